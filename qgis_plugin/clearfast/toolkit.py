"""Find and run the clearfast toolkit's command line, streaming its progress into Processing.

The command is run as an argument list (never through a shell). ``--progress json`` lines
(``{"event": ..., "stage": ..., "fraction": ...}``) drive the feedback's progress bar; other
lines go to the log. The run polls ``feedback.isCanceled()`` and ends the child process (and its
own children) when the user cancels.
"""

from __future__ import annotations

import importlib.util
import json
import os
import queue
import shlex
import shutil
import signal
import subprocess
import sys
import threading
import time
from dataclasses import dataclass, field

ENV_VAR = "CLEARFAST_COMMAND"
SETTINGS_KEY = "clearfast/toolkit_command"

INSTALL_HELP = (
    "The clearfast toolkit was not found. Install it into a Python 3.11 (or newer) environment "
    "with `python3 -m pip install clearfast-gis` (from a source checkout: "
    "`scripts/bootstrap.sh`), then put its `clearfast` command on PATH, or set the environment "
    "variable CLEARFAST_COMMAND (or the QGIS setting clearfast/toolkit_command) to it, e.g. "
    "/home/me/clearfast/.venv/bin/clearfast. Opening products needs only QGIS."
)


class ToolkitMissing(Exception):
    """The toolkit's command line cannot be found."""


class ToolkitFailed(Exception):
    """The toolkit ran and failed; the message is its one-line error."""


class ToolkitCancelled(Exception):
    """The user cancelled the run; the child process was ended."""


@dataclass
class RunResult:
    """Outcome of :func:`run_toolkit`."""

    returncode: int
    stdout: str
    stderr: str
    events: list = field(default_factory=list)


def _configured() -> str:
    text = os.environ.get(ENV_VAR, "").strip()
    if text:
        return text
    try:
        from qgis.core import QgsSettings

        return str(QgsSettings().value(SETTINGS_KEY, "") or "").strip()
    except ImportError:
        return ""


def toolkit_command() -> list[str]:
    """The command prefix that runs ``clearfast``.

    Order: ``CLEARFAST_COMMAND`` (environment), the QGIS setting ``clearfast/toolkit_command``
    (both split like a shell would, but run without one), ``clearfast`` on PATH, then
    ``python3 -m clearfast_gis.cli.main`` when QGIS's own Python can import the toolkit.

    Raises
    ------
    ToolkitMissing
        With installation instructions.
    """
    text = _configured()
    if text:
        argv = shlex.split(text, posix=os.name != "nt")
        if not argv or shutil.which(argv[0]) is None and not os.path.isfile(argv[0]):
            raise ToolkitMissing(f"{ENV_VAR} / {SETTINGS_KEY} names {text!r}, which does not "
                                 f"exist. {INSTALL_HELP}")
        return argv
    exe = shutil.which("clearfast")
    if exe:
        return [exe]
    if importlib.util.find_spec("clearfast_gis") is not None:
        base = os.path.basename(sys.executable).lower()
        python = sys.executable if base.startswith("python") else shutil.which("python3")
        if python:
            return [python, "-m", "clearfast_gis.cli.main"]
    raise ToolkitMissing(INSTALL_HELP)


def toolkit_available() -> tuple[bool, str]:
    """(True, "") when the toolkit can be run, else (False, how to install it)."""
    try:
        toolkit_command()
    except ToolkitMissing as exc:
        return False, str(exc)
    return True, ""


def _reader(stream, tag: str, out: queue.Queue) -> None:
    for line in iter(stream.readline, ""):
        out.put((tag, line.rstrip("\r\n")))
    stream.close()
    out.put((tag, None))


def _end_process(proc: subprocess.Popen, grace_s: float = 5.0) -> None:
    try:
        if os.name == "posix":
            os.killpg(proc.pid, signal.SIGTERM)
        else:
            proc.terminate()
        proc.wait(grace_s)
    except (ProcessLookupError, subprocess.TimeoutExpired):
        if proc.poll() is None:
            if os.name == "posix":
                os.killpg(proc.pid, signal.SIGKILL)
            else:
                proc.kill()
            proc.wait()


def handle_line(line: str, feedback, events: list) -> None:
    """Send one stdout line of the toolkit to ``feedback`` (progress, messages or log)."""
    text = line.strip()
    if not text:
        return
    obj = None
    if text.startswith("{"):
        try:
            obj = json.loads(text)
        except ValueError:
            obj = None
    if not isinstance(obj, dict) or "event" not in obj:
        feedback.pushConsoleInfo(line)
        return
    events.append(obj)
    event = obj.get("event")
    if event == "stage":  # a stage of the processing chain begins: its name and label
        feedback.setProgressText(f"{obj.get('stage', '')}: {obj.get('label', '')}")
        feedback.pushInfo(f"{obj.get('stage', '')}: {obj.get('label', '')}")
    if event == "start":
        what = " / ".join(str(obj[k]) for k in ("stage", "step") if obj.get(k))
        feedback.setProgressText(what)
        feedback.pushInfo(f"{what}: {obj.get('total', '?')} steps")
    if event in ("start", "progress", "end") and isinstance(obj.get("fraction"), (int, float)):
        feedback.setProgress(max(0.0, min(100.0, 100.0 * float(obj["fraction"]))))
    elif event == "message":
        feedback.pushInfo(str(obj.get("message", "")))


def run_toolkit(args: list[str], feedback, cwd: str | None = None, poll_s: float = 0.1,
                command: list[str] | None = None) -> RunResult:
    """Run ``clearfast ARGS`` and stream its output into ``feedback``.

    Parameters
    ----------
    args : list of str
        Arguments after the command, e.g. ``["export", folder, "--mine-action", "-o", out]``.
    feedback : QgsProcessingFeedback
        Receives progress, messages and the log; polled for cancellation.
    cwd : str, optional
        Working folder of the child.
    poll_s : float
        Polling period for output and cancellation, seconds.
    command : list of str, optional
        Command prefix; default :func:`toolkit_command`.

    Returns
    -------
    RunResult
        Also for a non-zero exit status (the caller decides what it means).

    Raises
    ------
    ToolkitMissing, ToolkitCancelled
    """
    argv = [*(command or toolkit_command()), *args]
    feedback.pushCommandInfo(" ".join(shlex.quote(a) for a in argv))
    env = dict(os.environ, PYTHONUNBUFFERED="1")
    proc = subprocess.Popen(
        argv, stdout=subprocess.PIPE, stderr=subprocess.PIPE, stdin=subprocess.DEVNULL,
        text=True, encoding="utf-8", errors="replace", bufsize=1, cwd=cwd, env=env,
        start_new_session=(os.name == "posix"),
    )
    lines: queue.Queue = queue.Queue()
    threads = [threading.Thread(target=_reader, args=(proc.stdout, "out", lines), daemon=True),
               threading.Thread(target=_reader, args=(proc.stderr, "err", lines), daemon=True)]
    for t in threads:
        t.start()
    out, err, events = [], [], []
    open_streams = 2
    cancelled = False
    while open_streams:
        if feedback.isCanceled() and not cancelled:
            cancelled = True
            feedback.pushInfo("Cancelling: ending the toolkit run…")
            _end_process(proc)
        try:
            tag, line = lines.get(timeout=poll_s)
        except queue.Empty:
            continue
        if line is None:
            open_streams -= 1
        elif tag == "out":
            out.append(line)
            handle_line(line, feedback, events)
        else:
            err.append(line)
            if line.strip():
                feedback.pushConsoleInfo(line)
    start = time.monotonic()
    while proc.poll() is None and time.monotonic() - start < 30:
        if feedback.isCanceled() and not cancelled:
            cancelled = True
            _end_process(proc)
        time.sleep(poll_s)
    if proc.poll() is None:
        _end_process(proc)
    if cancelled:
        raise ToolkitCancelled("cancelled by the user; the toolkit run was stopped")
    return RunResult(proc.returncode, "\n".join(out), "\n".join(err), events)


_DEFAULTS: dict[tuple[str, ...], dict] = {}


def toolkit_defaults(timeout_s: float = 60.0) -> dict:
    """The toolkit's processing defaults (``clearfast options --json``, its ``process``
    object: parameter name -> default), asked once per toolkit command and kept.

    The plugin defines no defaults of its own; it shows the toolkit's. Returns an empty dict
    when the toolkit is missing or does not answer (an algorithm then cannot run anyway).
    """
    try:
        command = tuple(toolkit_command())
    except ToolkitMissing:
        return {}
    if command not in _DEFAULTS:
        doc = {}
        try:
            proc = subprocess.run([*command, "options", "--json"], capture_output=True,
                                  text=True, timeout=timeout_s, stdin=subprocess.DEVNULL)
            lines = [s for s in proc.stdout.splitlines() if s.startswith("{")]
            doc = json.loads(lines[-1]) if proc.returncode == 0 and lines else {}
        except (OSError, subprocess.TimeoutExpired, ValueError):
            doc = {}
        process = doc.get("process") if isinstance(doc, dict) else None
        _DEFAULTS[command] = dict(process) if isinstance(process, dict) else {}
    return dict(_DEFAULTS[command])


def error_line(result: RunResult) -> str:
    """The toolkit's one-line error (last non-empty stderr line) or the exit status."""
    for line in reversed(result.stderr.splitlines()):
        if line.strip():
            return line.strip()
    return f"the toolkit exited with status {result.returncode}"
