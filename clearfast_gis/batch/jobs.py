"""One survey of a batch: where its products go, and its conversion as one task.

A task never raises: whatever goes wrong with one survey becomes that survey's ``failed``
status and one-line error, so the other surveys of the batch go on.
"""

from __future__ import annotations

import os
import socket
import time
from collections.abc import Callable, Sequence
from dataclasses import asdict, dataclass
from pathlib import Path

from clearfast_gis.errors import ClearfastError

Emit = Callable[[dict], None]
"""Receiver of progress events (``{"event": ..., "survey": ..., ...}``)."""


@dataclass(frozen=True)
class SurveyJob:
    """A survey to convert and its products folder.

    Attributes
    ----------
    name : str
        The survey folder's name, also the products folder's name under the output folder.
    survey : str
        Absolute path of the survey folder.
    products : str
        Absolute path of the products folder (``OUTDIR/<name>``).
    """

    name: str
    survey: str
    products: str


@dataclass(frozen=True)
class SurveyResult:
    """Outcome of one survey.

    Attributes
    ----------
    name : str
        Survey folder name.
    status : {"ok", "failed"}
    anomalies : int or None
        Suspects written (None when failed).
    seconds : float
        Wall time of the conversion, seconds.
    error : str or None
        One-line error of a failed survey (``file: field: problem``).
    products : str
        Products folder.
    worker : str
        ``host:pid`` of the process that ran it.
    """

    name: str
    status: str
    anomalies: int | None
    seconds: float
    error: str | None
    products: str
    worker: str

    def as_dict(self) -> dict:
        """Plain dict (JSON lines, summary)."""
        return asdict(self)


def plan_jobs(surveys: Sequence[str | os.PathLike], outdir: str | os.PathLike
              ) -> list[SurveyJob]:
    """One job per survey folder, products in ``outdir/<survey folder name>``.

    Raises
    ------
    ClearfastError
        Exit status 2: two surveys share a folder name (their products would collide).
    """
    out = Path(outdir).resolve()
    jobs: list[SurveyJob] = []
    seen: dict[str, str] = {}
    for s in surveys:
        path = Path(s).resolve()
        name = path.name
        if name in seen:
            raise ClearfastError(f"two surveys named {name!r} ({seen[name]} and {path}) would "
                                 "write the same products folder", str(s), exit_code=2)
        seen[name] = str(path)
        jobs.append(SurveyJob(name, str(path), str(out / name)))
    return jobs


def worker_id() -> str:
    """``host:pid`` of this process."""
    return f"{socket.gethostname()}:{os.getpid()}"


def count_suspects(products: str | os.PathLike) -> int:
    """Number of features of the ``suspects`` layer of ``products/anomalies.gpkg``."""
    import pyogrio

    info = pyogrio.read_info(Path(products) / "anomalies.gpkg", layer="suspects")
    return int(info["features"])


def convert_survey(job: SurveyJob, options=None, resume: bool = True,
                   emit: Emit | None = None) -> SurveyResult:
    """Run the whole chain on one survey; never raises.

    Parameters
    ----------
    job : SurveyJob
    options : clearfast_gis.pipeline.ProcessOptions, optional
    resume : bool
        Continue an interrupted run of the same survey in the same products folder.
    emit : callable, optional
        Receives a ``start`` event when the work begins.

    Returns
    -------
    SurveyResult
    """
    from clearfast_gis.pipeline import process_survey

    who = worker_id()
    if emit is not None:
        emit({"event": "start", "survey": job.name, "worker": who})
    t0 = time.perf_counter()
    try:
        process_survey(job.survey, job.products, options, resume=resume)
        n = count_suspects(job.products)
    except ClearfastError as exc:
        return SurveyResult(job.name, "failed", None, time.perf_counter() - t0,
                            exc.one_line(), job.products, who)
    except Exception as exc:  # one survey's bug must not stop the batch
        line = " ".join(str(exc).split()) or type(exc).__name__
        return SurveyResult(job.name, "failed", None, time.perf_counter() - t0,
                            f"internal error: {type(exc).__name__}: {line}", job.products, who)
    return SurveyResult(job.name, "ok", n, time.perf_counter() - t0, None, job.products, who)
