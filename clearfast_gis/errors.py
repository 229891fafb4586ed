"""Errors that the command line reports as one line, never as a traceback."""

from __future__ import annotations

from os import PathLike


class ClearfastError(Exception):
    """A problem with an input or an output, reported as ``file: field: message``.

    Parameters
    ----------
    message : str
        What is wrong, in plain words.
    path : str or PathLike, optional
        The file (or folder) concerned.
    field : str, optional
        The field, column, line or record inside the file, e.g. ``camera.resolution`` or
        ``line 12``.
    exit_code : int
        Exit status for the command line (1 = invalid input or failed run, 2 = usage error).
    """

    def __init__(
        self,
        message: str,
        path: str | PathLike | None = None,
        field: str | None = None,
        exit_code: int = 1,
    ) -> None:
        self.message = message
        self.path = None if path is None else str(path)
        self.field = field
        self.exit_code = exit_code
        super().__init__(self.one_line())

    def one_line(self) -> str:
        """The message as one line: ``path: field: message``."""
        parts = [p for p in (self.path, self.field) if p]
        text = " ".join(self.message.split())
        return ": ".join([*parts, text])


class InvalidInput(ClearfastError):
    """An input file that is missing, unreadable or does not follow its format."""


class OutputError(ClearfastError):
    """A product that cannot be written (permissions, disk full, ...)."""


def more_problems(n_problems: int, hint: str = "") -> str:
    """Suffix for a one-line error that shows the first of ``n_problems`` problems.

    >>> more_problems(1), more_problems(2), more_problems(3, "run clearfast validate")
    ('', ' (and 1 more problem)', ' (and 2 more problems: run clearfast validate)')
    """
    if n_problems <= 1:
        return ""
    rest = n_problems - 1
    return f" (and {rest} more problem{'s' if rest > 1 else ''}{': ' + hint if hint else ''})"
