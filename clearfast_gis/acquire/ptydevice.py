"""Simulated serial devices on pseudo-terminals, with the faults of a field set-up.

A device simulator is a protocol engine (:class:`DeviceEngine`: bytes in with ``feed``, bytes
due now out with ``pending_output``) served by :class:`PtyDevice` on the master side of a
pseudo-terminal. A driver opens the slave side by name exactly as it opens ``/dev/ttyUSB0``,
so tests and dry runs use the real driver code and pyserial. The device can also sit behind a
stable symbolic link (as udev's ``/dev/serial/by-id/...`` links), which lets it be unplugged
and plugged back: :meth:`PtyDevice.unplug` closes the pseudo-terminal (a driver reading it gets
an I/O error, as from a pulled USB adapter) and removes the link; :meth:`PtyDevice.replug`
makes a new pseudo-terminal and points the link at it. :attr:`PtyDevice.mute` drops the
device's output (a hung instrument) and :meth:`PtyDevice.inject` sends raw bytes (line noise,
a wrong baud rate).

Bytes the device sends while nobody reads are lost once the terminal's input queue is full,
as on a serial line with nothing connected.
"""

from __future__ import annotations

import contextlib
import os
import select
import threading
import tty
from collections.abc import Iterator
from pathlib import Path
from typing import Protocol


class DeviceEngine(Protocol):
    """The protocol side of a simulated instrument."""

    def feed(self, data: bytes) -> None:
        """Take bytes sent by the driver."""
        ...

    def pending_output(self) -> bytes:
        """Bytes due to be sent now."""
        ...


@contextlib.contextmanager
def pty_pair() -> Iterator[tuple[int, str]]:
    """A pseudo-terminal in raw mode: yields (master fd, slave device name).

    The instrument side reads and writes the master fd; the driver opens the slave name with
    ``serial.Serial``. Both ends are closed on exit.
    """
    master, slave = _open_pty()
    try:
        yield master, os.ttyname(slave)
    finally:
        _close(master, slave)


def _open_pty() -> tuple[int, int]:
    master, slave = os.openpty()
    tty.setraw(slave)
    tty.setraw(master)
    return master, slave


def _close(*fds: int) -> None:
    for fd in fds:
        with contextlib.suppress(OSError):
            os.close(fd)


class PtyDevice:
    """Serves a :class:`DeviceEngine` on a pseudo-terminal in a thread.

    Parameters
    ----------
    engine : DeviceEngine
        The instrument's protocol engine.
    link : path, optional
        A symbolic link kept pointing at the current pseudo-terminal (replaced atomically);
        drivers should open the link, which survives :meth:`unplug` / :meth:`replug`.
    poll_s : float
        Longest wait for input before the engine's output is checked, seconds.
    name : str
        Thread name suffix.

    Attributes
    ----------
    mute : bool
        When True the device's output is discarded (the engine still runs).
    dropped_bytes : int
        Output lost because nobody read it (or the device was unplugged or mute).
    """

    def __init__(self, engine: DeviceEngine, link: str | os.PathLike | None = None,
                 poll_s: float = 0.002, name: str = "device") -> None:
        self.engine = engine
        self.link = None if link is None else Path(link)
        self.poll_s = float(poll_s)
        self.name = name
        self.mute = False
        self.dropped_bytes = 0
        self._fds: tuple[int, int] | None = None
        self._slave_name = ""
        self._lock = threading.Lock()
        self._stop = threading.Event()
        self._thread: threading.Thread | None = None

    # -- the terminal -----------------------------------------------------------------------

    @property
    def path(self) -> str:
        """What a driver opens: the link if there is one, else the slave device name."""
        return str(self.link) if self.link is not None else self._slave_name

    @property
    def plugged(self) -> bool:
        """True while the pseudo-terminal exists."""
        return self._fds is not None

    def _plug(self) -> None:
        master, slave = _open_pty()
        os.set_blocking(master, False)
        name = os.ttyname(slave)
        with self._lock:
            self._fds = (master, slave)
            self._slave_name = name
        if self.link is not None:
            self.link.parent.mkdir(parents=True, exist_ok=True)
            tmp = self.link.with_name(f".{self.link.name}.{os.getpid()}.tmp")
            with contextlib.suppress(FileNotFoundError):
                tmp.unlink()
            os.symlink(name, tmp)
            os.replace(tmp, self.link)

    def unplug(self) -> None:
        """Close the pseudo-terminal (readers get an I/O error) and remove the link."""
        with self._lock:
            fds, self._fds = self._fds, None
        if self.link is not None:
            with contextlib.suppress(FileNotFoundError):
                self.link.unlink()
        if fds is not None:
            _close(*fds)

    def replug(self) -> None:
        """A new pseudo-terminal behind the link (after :meth:`unplug`)."""
        if self._fds is None:
            self._plug()

    def inject(self, data: bytes) -> None:
        """Send raw bytes now (line noise), whatever the engine is saying."""
        self._send(bytes(data))

    def _send(self, data: bytes) -> None:
        with self._lock:
            fds = self._fds
            if fds is None or self.mute:
                self.dropped_bytes += len(data)
                return
            try:
                n = os.write(fds[0], data)
            except (BlockingIOError, OSError):
                n = 0
            self.dropped_bytes += len(data) - n

    # -- serving ----------------------------------------------------------------------------

    def start(self) -> PtyDevice:
        """Create the pseudo-terminal (and link) and start serving; returns self."""
        self._plug()
        self._thread = threading.Thread(target=self._serve, daemon=True,
                                        name=f"clearfast-sim-{self.name}")
        self._thread.start()
        return self

    def _serve(self) -> None:
        while not self._stop.is_set():
            data = b""
            with self._lock:  # unplug() waits, so the fd cannot be closed and reused meanwhile
                fds = self._fds
                if fds is not None:
                    with contextlib.suppress(OSError):
                        ready, _, _ = select.select([fds[0]], [], [], self.poll_s)
                        data = os.read(fds[0], 4096) if ready else b""
            if fds is None:
                self._stop.wait(self.poll_s)
            if data:
                self.engine.feed(data)
            out = self.engine.pending_output()
            if out:
                self._send(out)

    def stop(self) -> None:
        """Stop serving, close the pseudo-terminal and remove the link."""
        self._stop.set()
        if self._thread is not None:
            self._thread.join(timeout=2.0)
        self.unplug()

    def __enter__(self) -> PtyDevice:
        return self if self._thread is not None else self.start()

    def __exit__(self, *exc: object) -> None:
        self.stop()
