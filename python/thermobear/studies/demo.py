"""``thermobear demo``: the seed studies, written as tables (parquet + CSV)
and figures (PNG, and PDF or SVG when asked) into an output folder.

Each study is a function ``study_*(out: Path, quick: bool) -> list[Path]``.
"""

from __future__ import annotations

import time
from pathlib import Path
from typing import Callable, Sequence

from .output import DEFAULT_DPI, figure_options

# Each study: (name, "module:function") inside thermobear, imported when run.
STUDIES: list[tuple[str, str]] = [
    ("seed_a_bearing", "studies.seed_a_bearing:study_seed_a_bearing"),
    ("seed_b_bearing", "studies.seed_b_bearing:study_seed_b_bearing"),
    ("seed_a_gear", "studies.seed_a_gear:study_seed_a_gear"),
    ("seed_b_vibration", "studies.seed_b_vibration:study_seed_b_vibration"),
    ("seed_b_spindle", "studies.seed_b_spindle:study_seed_b_spindle"),
    ("seed_a_thermal", "studies.seed_a_thermal:study_seed_a_thermal"),
    ("diagnose_synthetic", "studies.diagnose_synthetic:study_diagnose"),
    ("diagnose_seed_b", "studies.diagnose_seed_b:study_diagnose_seed_b"),
    ("rig_to_prediction", "studies.rig_to_prediction:study_rig_to_prediction"),
]


def refit_papers(folder: Path, quick: bool = False) -> list[Path]:
    """Redo the calibrations that pin the seed papers' unstated inputs from
    their fitted numbers, writing the models (and their bands) into
    ``folder``: seed A's bearing (its claims), then its gear pair (on that
    bearing), then seed B's spindle. Returns the files written."""
    from .paper_numbers import refitted
    from .reproduce_seed_a_gear import fit as fit_gear
    from .reproduce_seed_a_thermal import fit as fit_bearing
    from .reproduce_seed_b import fit as fit_spindle

    with refitted(folder):
        fit_bearing(quick, out_dir=folder)
        fit_gear(out_dir=folder)
        fit_spindle(quick, out=folder)
    return sorted(p for p in Path(folder).iterdir() if p.is_file())


def study_function(spec: str) -> Callable[[Path, bool], list[Path]]:
    """Resolve a ``"module:function"`` study reference."""
    import importlib

    module, func = spec.split(":")
    return getattr(importlib.import_module(f"thermobear.{module}"), func)


def run_demo(
    out: Path,
    quick: bool = False,
    *,
    formats: str | Sequence[str] = ("png",),
    dpi: float = DEFAULT_DPI,
    refit: bool = False,
) -> Path:
    """Run every study into ``out`` and return it; every figure is written
    in each of ``formats`` (``"png"``, ``"pdf"``, ``"svg"``; a comma list or
    a sequence) as ``<stem>.<format>``, a PNG at ``dpi``, all in the
    package's style (``thermobear.plot.set_style`` changes it). ``refit``:
    first redo every calibration that pins the seed papers' unstated inputs
    (minutes; ``refit_papers``) into ``out/papers`` and use those models
    instead of the shipped ones."""
    from contextlib import ExitStack

    from ..plot.style import style_context
    from .paper_numbers import refitted

    # every figure, the studies' own ones too, in the package's style
    with figure_options(formats, dpi), style_context(), ExitStack() as stack:
        out.mkdir(parents=True, exist_ok=True)
        if refit:
            folder = stack.enter_context(refitted(out / "papers"))
            t0 = time.perf_counter()
            refit_papers(folder, quick)
            print(f"  refit: {folder} in {time.perf_counter() - t0:.1f} s", flush=True)
        for name, spec in STUDIES:
            t0 = time.perf_counter()
            files = study_function(spec)(out / name, quick)
            print(f"  {name}: {len(files)} files in {time.perf_counter() - t0:.1f} s", flush=True)
        from .reproduction_table import write_reproduction

        t0 = time.perf_counter()
        files = write_reproduction(out, quick)  # the number table, per figure, the counts
        print(f"  reproduction: {len(files)} files in {time.perf_counter() - t0:.1f} s", flush=True)
    return out
