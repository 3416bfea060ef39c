"""The result of [`thermobear.diagnose`][thermobear.diagnose]:
[`Diagnosis`][thermobear.Diagnosis]."""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import Any

from .verdict import _unit


@dataclass
class Diagnosis:
    """Result of [`diagnose`][thermobear.diagnose] (tables are polars DataFrames).

    ``audit``: residual per quantity and speed band of the baseline
    (``n``, ``mean_residual_sigma``, ``rms_residual_sigma``) with the
    quantity's residual ``shape``; ``fingerprints``: pairwise cosine
    similarity of the candidates' fingerprints; ``lookalikes``: pairs with
    |cos| > 0.95 and the extra measurement (quantity, speed) that separates
    them best; ``screening``: one table per round (candidate, calibrated
    value, 95 % interval, delta_bic, held-out chi^2, passes); ``accepted``:
    the accepted candidates with value and interval; ``tie``: names of a
    tie set; ``verdict``: text; ``gap``: held-out rms residual/sigma per
    quantity and speed band before and after (after: the accepted
    candidates calibrated without the held-out points, an extrapolation);
    ``points``: the measured rows with ``model_before``, ``model_after``
    (calibrated on all points), ``model_extrapolated`` (calibrated without
    the held-out ones), ``heldout``, ``outlier``;
    ``ties``: one row per tie member (its value, interval, the gap after it
    alone, where to measure to separate it); ``tie_gap``: the gap table
    after each member; ``outliers``: the points the robust audit left out;
    ``unresolved``: the candidates the rounds would have accepted when the
    generic control explains the data as well (then ``accepted`` is empty),
    and, marked ``alternative``, the other first-round candidates that
    explain the data as well as the control."""

    audit: Any
    fingerprints: Any
    lookalikes: Any
    screening: list
    accepted: list
    tie: list
    verdict: str
    gap: Any
    points: Any
    not_evaluable: list = field(default_factory=list)
    notes: list = field(default_factory=list)
    ties: Any = None
    tie_gap: Any = None
    outliers: Any = None
    unresolved: list = field(default_factory=list)

    def summary(self) -> str:
        lines = [f"verdict: {self.verdict}"]
        for a in self.accepted:
            interval = (
                f" [{a['lower_95']:.4g}, {a['upper_95']:.4g}]{_unit(a['unit'])}"
                if a["lower_95"] is not None
                else " (switched on)"
            )
            lines.append(
                f"  accepted {a['name']}: {a['parameter']} = {a['value']:.4g}{interval}, "
                f"delta-BIC {a['delta_bic']:.1f}"
            )
        if self.tie:
            lines.append("  tie set: " + ", ".join(self.tie))
        lines += self._tie_lines()
        for row in self.lookalikes.iter_rows(named=True):
            lines.append(
                f"  look-alikes {row['a']} ~ {row['b']} (cos {row['cosine']:.3f}): measure "
                f"{row['suggest_quantity']} at {row['suggest_speed_rpm']:.0f} rpm"
            )
        lines.append("held-out gap (rms residual / sigma):")
        for row in self.gap.iter_rows(named=True):
            lines.append(
                f"  {row['quantity']:28s} {row['speed_band']:18s} n={row['n']:3d} "
                f"before {row['rms_before_sigma']:8.2f}  after {row['rms_after_sigma']:8.2f}"
            )
        lines += [f"note: {n}" for n in self.notes]
        return "\n".join(lines)

    def _tie_lines(self) -> list[str]:
        if self.ties is None:
            return []
        out = []
        for r in self.ties.iter_rows(named=True):
            iv = "" if r["lower_95"] is None else f" [{r['lower_95']:.4g}, {r['upper_95']:.4g}]"
            sep = (
                f"; tell from {self.ties['candidate'][0]} by {r['separate_quantity']} at "
                f"{r['separate_speed_rpm']:.0f} rpm, {r['separate_axial_n']:.0f} N"
                if r["separate_quantity"]
                else ""
            )
            out.append(
                f"  tie member {r['candidate']}: {r['value']:.4g}{iv}, rms/sigma "
                f"{r['rms_before_sigma']:.2f} -> {r['rms_after_sigma']:.2f} "
                f"(p_noise {r['p_noise']:.2g}){sep}"
            )
        return out

    def __repr__(self) -> str:
        return f"Diagnosis(verdict={self.verdict!r})"
