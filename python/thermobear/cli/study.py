"""``thermobear study``: a design study described in TOML, computed in
chunks into a results directory (resumed when run again)."""

from __future__ import annotations

from pathlib import Path
from typing import Optional

from ..config import located_config_errors
from ..study import load_study


def run_study_file(
    path: Path,
    out: Path,
    scheduler: Optional[str] = None,
    progress: Optional[bool] = None,
    overwrite: bool = False,
    threads: Optional[int] = None,
    max_points: Optional[int] = None,
    max_steps: Optional[int] = None,
) -> str:
    """Run the study of a TOML file into ``out`` (``threads``: per chunk,
    on this machine; ``max_points``, ``max_steps``: in place of the file's
    caps on the grid's size); prints the study and its size first, returns
    the report line. A ``ConfigError`` about the file names it, the line
    and the key."""
    with located_config_errors(path):
        study = load_study(path, max_points=max_points, max_steps=max_steps)
    print(f"thermobear study: {study.summary()} into {out}", flush=True)
    try:
        study.run(
            out,
            engine=scheduler,
            progress=progress,
            overwrite=overwrite,
            collect=False,
            threads=threads,
        )
    except KeyboardInterrupt:
        if study.report is not None:
            study.report.interrupted = True
            print(f"thermobear study: {study.report}")
        raise
    return str(study.report)
