"""UTC time handling. Inside the toolkit a time is float seconds since 1970-01-01T00:00:00Z.

Files carry ISO 8601 UTC strings (``2004-11-20T09:58:00Z``); arrays carry float64 seconds.
"""

from __future__ import annotations

from datetime import UTC, datetime

import numpy as np


def parse_utc(text: str) -> float:
    """ISO 8601 UTC text (``...Z``, ``+00:00`` or naive taken as UTC) to epoch seconds.

    Raises ``ValueError`` for text that is not a time or carries a non-UTC offset.
    """
    s = text.strip()
    if s.endswith(("Z", "z")):
        s = s[:-1] + "+00:00"
    dt = datetime.fromisoformat(s.replace(" ", "T", 1) if "T" not in s else s)
    if dt.tzinfo is None:
        dt = dt.replace(tzinfo=UTC)
    elif dt.utcoffset().total_seconds() != 0:
        raise ValueError(f"time {text!r} is not UTC")
    return dt.timestamp()


def format_utc(t_s: float, timespec: str = "milliseconds") -> str:
    """Epoch seconds to ISO 8601 UTC text ending in ``Z``."""
    dt = datetime.fromtimestamp(float(t_s), tz=UTC)
    return dt.isoformat(timespec=timespec).replace("+00:00", "Z")


def parse_utc_array(texts) -> np.ndarray:
    """A sequence of ISO 8601 UTC strings to a float64 array of epoch seconds."""
    return np.array([parse_utc(t) for t in texts], dtype=np.float64)
