"""Validation against published data: each shipped set
(``thermobear/validation/data/*.toml``: source, geometry, conditions,
points with their sigma) is modelled with thermobear's models, diagnosed
with [`thermobear.diagnose`][thermobear.diagnose], one or more inputs calibrated on part of
the points and the error reported on the points held out.

* ``seed_b_spindle`` -- seed B's measured outer-ring temperatures and
  vibration, its own model's axial growth and compensation preload
  (``thermobear.validation.spindle``);
* ``seed_b_vibration`` -- seed B's measured 18.92 mm/s: unbalance, runout
  or thermal displacement? (``thermobear.validation.vibration``);
* ``fag_b70c_rigidity`` -- FAG catalogue axial rigidity and lift-off force
  of spindle-bearing pairs (``thermobear.validation.catalogue``);
* ``ntn_ultage_rigidity`` -- NTN catalogue radial and axial rigidity of 95
  spindle-bearing pairs of two series and two contact angles
  (``thermobear.validation.catalogue``);
* ``skf_reference_speed_62`` -- SKF catalogue reference speeds of 27
  deep-groove bearings as a heat balance under the ISO 15312 reference
  conditions: which heat model reproduces the published friction heat?
  (``thermobear.validation.reference_speed``);
* ``skf_reference_speed_60``, ``skf_reference_speed_63`` -- the same
  catalogue's 60 and 63 series, references the heat model was not tuned to:
  every candidate keeps its value calibrated on the 62 series, every bearing
  is held out.

[`validate`][thermobear.validate] runs them and writes the report
(``thermobear.validation.report``).
"""

from __future__ import annotations

from pathlib import Path
from typing import Optional, Sequence

from .result import SetResult
from .sets import load_set, set_names

__all__ = ["SetResult", "load_set", "run_set", "set_names", "validate"]


def run_set(name: str) -> SetResult:
    """Validate one shipped set by name (see [`set_names`][thermobear.validation.set_names])."""
    from .catalogue import run_catalogue
    from .reference_speed import run_reference_speed
    from .spindle import run_spindle
    from .vibration import run_vibration

    data = load_set(name)
    other = data.get("calibration", {}).get("calibration_set")
    if data["kind"] == "reference_speed" and other:
        return run_reference_speed(data, load_set(str(other)))
    runner = {
        "spindle": run_spindle,
        "spindle_vibration": run_vibration,
        "bearing_catalogue": run_catalogue,
        "reference_speed": run_reference_speed,
    }[data["kind"]]
    return runner(data)


def validate(sets: Optional[Sequence[str]] = None, out: Optional[Path] = None) -> list[SetResult]:
    """Run the named validation sets (default: all shipped ones) and, with
    ``out``, write ``validation.md`` and a figure per set there. Each
    [`SetResult`][thermobear.validation.SetResult] carries baseline error, verdict, calibrated
    parameters, held-out error after calibration and, when a set does not
    pass, what is missing."""
    names = list(set_names() if not sets else sets)
    for n in names:
        load_set(n)  # a bad name fails before any model runs
    results = [run_set(n) for n in names]
    if out is not None:
        from .report import write_report

        write_report(results, Path(out))
    return results
