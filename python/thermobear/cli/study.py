"""``thermobear study``: a design study described in TOML, computed in
chunks into a results directory (resumed when run again)."""

from __future__ import annotations

from pathlib import Path
from typing import Optional

from ..study import load_study


def run_study_file(
    path: Path,
    out: Path,
    scheduler: Optional[str] = None,
    progress: Optional[bool] = None,
    overwrite: bool = False,
) -> str:
    """Run the study of a TOML file into ``out``; returns the report line."""
    study = load_study(path)
    try:
        study.run(out, engine=scheduler, progress=progress, overwrite=overwrite, collect=False)
    except KeyboardInterrupt:
        if study.report is not None:
            study.report.interrupted = True
            print(f"thermobear study: {study.report}")
        raise
    return str(study.report)
