"""One gear sweep per sample of a calibrated bearing model: the gear system
on the bearings at a vector of calibrated values, and the regime labels
of sweeps that each take the RK4 steps their own speeds need (shared by
the in-process regime prediction and the ``regime_prediction`` study
kind)."""

from __future__ import annotations

from typing import TYPE_CHECKING, Any, Mapping

import numpy as np

from ..errors import ThermobearError

if TYPE_CHECKING:
    import polars


class BearingAt:
    """A calibrated model at one vector of its calibrated values: what
    ``GearSystem(bearings=...)`` (a bearing model) or ``GearSystem(...)``
    (a gear model) takes of a calibrated model (the hook
    ``_thermobear_model_``), for the spec at that vector."""

    def __init__(self, spec: Any) -> None:
        self.spec = spec

    def _thermobear_model_(self) -> tuple[Any, dict]:
        from ..diagnosis.calibrated import machine_options

        return machine_options(self.spec)


def regime_system(model: Any, theta: np.ndarray, gear: Any, gear_options: Mapping) -> Any:
    """The gear system of ``model`` at calibrated values ``theta``: a
    bearing model's bearings on their thermal stiffness schedule under
    ``gear``; a gear model's own pair with those inputs (its stiffness
    case unless ``gear_options`` names one)."""
    from ..gear.system import GearSystem

    spec = model.spec_at(theta) if len(theta) else model.spec
    if is_gear_spec(spec):
        return GearSystem(BearingAt(spec), **gear_options)
    return GearSystem(gear, bearings=BearingAt(spec), stiffness="thermal", **gear_options)


def is_gear_spec(spec: Any) -> bool:
    """Whether a model spec is a gear pair's (its conditions are a torque,
    a stiffness case and a direction)."""
    return hasattr(spec, "gear") and hasattr(spec, "system_options")


def sweep_labels(
    systems: Mapping[str, Any], speeds: np.ndarray, direction: str, sweep_options: Mapping
) -> tuple[dict[str, dict[float, str]], dict[str, str]]:
    """Sweep every system over ``speeds`` (``bifurcation_set``, in
    parallel), each with the RK4 steps its own speeds need (or the given
    ``steps_per_period``), so a system's labels do not depend on the others
    swept with it. Returns (case -> speed -> regime label, case -> the
    message of a sweep that failed at a speed)."""
    from ..gear.dynamics import bifurcation_set, sweep_steps

    opts = dict(sweep_options)
    given = opts.pop("steps_per_period", None)
    groups: dict[int, dict[str, Any]] = {}
    for case, system in systems.items():
        groups.setdefault(sweep_steps([system], speeds, given), {})[case] = system
    labels: dict[str, dict[float, str]] = {}
    failed: dict[str, str] = {}
    for steps, group in groups.items():
        try:
            pts = bifurcation_set(
                group, speeds, directions=(direction,), steps_per_period=steps, **opts
            )
        except ThermobearError as e:
            pts = _finished_cases(e, failed)
        labels.update(_labels_by_case(pts))
    return labels, failed


def _finished_cases(e: ThermobearError, failed: dict[str, str]) -> polars.DataFrame:
    """The rows of the sweeps that finished when others failed at a speed
    (the error's ``partial``); the failed ones' messages go to ``failed``.
    An error without a failed speed (an interrupt, bad settings) is raised."""
    import polars as pl

    from ..errors import Interrupted

    bad = getattr(e, "failed", None)
    if isinstance(e, Interrupted) or bad is None or not bad.height or "case" not in bad.columns:
        raise e
    for row in bad.iter_rows(named=True):
        failed.setdefault(str(row["case"]), f"sweep failed at {row['speed_rpm']:g} rpm: "
                                            f"{row['message']}")  # fmt: skip
    lost = set(failed) | set(e.not_run["case"].to_list())  # type: ignore[attr-defined]
    part: pl.DataFrame = e.partial  # type: ignore[attr-defined]
    return part.filter(~pl.col("case").is_in(sorted(lost)))


def _labels_by_case(pts: polars.DataFrame) -> dict[str, dict[float, str]]:
    """Each sweep's regime label by speed."""
    per = pts.select("case", "speed_rpm", "regime").unique(
        subset=["case", "speed_rpm"], keep="first", maintain_order=True
    )
    out: dict[str, dict[float, str]] = {}
    for case, v, reg in per.iter_rows():
        out.setdefault(str(case), {})[float(v)] = str(reg)
    return out
