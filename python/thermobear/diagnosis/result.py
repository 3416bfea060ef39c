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
    them best (``suggest_quantity``, ``suggest_speed_rpm``,
    ``suggest_axial_n``: null when no suggestion was asked for or none
    separates them); ``screening``: one table per round (candidate, calibrated
    value, 95 % interval, delta_bic, held-out chi^2, passes); ``accepted``:
    the accepted candidates with value and interval; ``tie``: names of a
    tie set; ``verdict``: text; ``gap``: rms residual/sigma on every
    measured point (outliers left out) by ``explanation``, ``quantity``,
    ``speed_band`` and ``heldout``, before (the baseline) and after each
    explanation the verdict names -- the accepted candidates (none: the
    baseline), each tie member, or under "unresolved" the known effects and
    the unknown smooth term -- every one calibrated without the held-out
    points (on those an extrapolation); ``explained``: the kept points once
    per explanation with its ``model_after``; ``points``: the measured rows
    with ``model_before``, ``model_after`` (the accepted setting
    calibrated on all points; under "unresolved" nothing is accepted: the
    baseline), ``model_extrapolated`` (the accepted setting calibrated
    without the held-out ones), ``heldout``, ``outlier``;
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
    explained: Any = None
    _model: Any = field(default=None, repr=False, compare=False)

    @property
    def model(self) -> Any:
        """The calibrated model of the verdict: a
        [`CalibratedModel`][thermobear.CalibratedModel] with the accepted
        candidates at their values (kind "named"), the baseline (kind
        "nothing"), or one member per explanation (kind "tie", or
        "unresolved" with the generic smooth control as a member)."""
        from ..errors import ConfigError

        if self._model is None:
            raise ConfigError("invalid diagnosis: it carries no calibrated model")
        return self._model

    def _named(self) -> list[str]:
        """The candidates the verdict names: accepted, tie members and the
        known effects of "unresolved"."""
        names = [a["name"] for a in self.accepted] + [a["name"] for a in self.unresolved]
        return list(dict.fromkeys(names + [t for t in self.tie if t != "generic_control"]))

    def summary(self, verbose: bool = False) -> str:
        """The verdict, the gap per explanation and the look-alikes of the
        named candidates with the measurement that separates them (one
        screen); ``verbose``: also every other look-alike pair, the gap
        table row by row and the notes."""
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
        named = set(self._named())
        others = 0
        for row in self.lookalikes.iter_rows(named=True):
            if not verbose and not {row["a"], row["b"]} & named:
                others += 1
                continue
            where = (
                "no separating measurement found"
                if row["suggest_speed_rpm"] is None
                else f"measure {row['suggest_quantity']} at {row['suggest_speed_rpm']:.0f} rpm"
            )
            lines.append(
                f"  look-alikes {row['a']} ~ {row['b']} (cos {row['cosine']:.3f}): {where}"
            )
        lines += gap_lines(self.gap, verbose)
        if verbose:
            lines += [f"note: {n}" for n in self.notes]
        elif others or self.notes:
            lines.append(
                f"({others} look-alike pair(s) of other candidates and {len(self.notes)} "
                "note(s): summary(verbose=True))"
            )
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


def gap_lines(gap: Any, verbose: bool = False) -> list[str]:
    """The gap table in words: under each explanation, one line per
    quantity with "before -> after" per speed band (held-out bands marked
    ``*``); ``verbose``: one line per row."""
    lines = ["gap, rms residual / sigma before -> after (* held out: extrapolated):"]
    if gap is None or gap.height == 0:
        return lines
    if not gap["heldout"].any():
        lines[0] = "gap, rms residual / sigma before -> after (no held-out points):"
    for (label,), sub in gap.group_by("explanation", maintain_order=True):
        lines.append(f"  under {label}:")
        if verbose:
            lines += [
                f"    {r['quantity']:28s} {r['speed_band']:18s}{'*' if r['heldout'] else ' '} "
                f"n={r['n']:3d} before {r['rms_before_sigma']:8.2f}  after "
                f"{r['rms_after_sigma']:8.2f}"
                for r in sub.iter_rows(named=True)
            ]
            continue
        for (q,), rows in sub.group_by("quantity", maintain_order=True):
            cells = [
                f"{r['speed_band'].replace(' rpm', '')}{'*' if r['heldout'] else ''} "
                f"{r['rms_before_sigma']:.3g} -> {r['rms_after_sigma']:.3g}"
                for r in rows.iter_rows(named=True)
            ]
            lines.append(f"    {q}: " + "; ".join(cells))
    return lines
