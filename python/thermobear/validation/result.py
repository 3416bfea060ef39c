"""The outcome of validating one set: [`SetResult`][thermobear.validation.result.SetResult]."""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import Any


@dataclass
class SetResult:
    """One validation set against thermobear's models.

    ``points``: polars frame, one row per published point (``label``,
    ``quantity``, ``value``, ``sigma``, ``model_before``, ``model_after``:
    the model calibrated on the points not held out only, ``heldout``: not
    used for calibration, and where the set states it ``origin``: measured
    or simulated); ``verdict``: the diagnosis' verdict (or why none was
    run); ``calibrated``: dicts ``name, value, lower, upper, unit``;
    ``missing``: a plain statement of what the models lack when the set does
    not pass (empty when it passes); ``tables``: further named frames for
    the report; ``notes``: lines for the report; ``heldout_by_explanation``:
    when the verdict names more than one explanation (a tie, "unresolved"),
    the worst held-out |model - value| / sigma under each, every one
    calibrated without the held-out points."""

    name: str
    title: str
    source: str
    points: Any
    verdict: str
    calibrated: list = field(default_factory=list)
    holdout: str = ""
    missing: str = ""
    tables: dict = field(default_factory=dict)
    notes: list = field(default_factory=list)
    seconds: float = 0.0
    heldout_by_explanation: dict = field(default_factory=dict)

    def _z(self, col: str, held: bool) -> Any:
        import numpy as np

        p = self.points.filter(self.points["heldout"]) if held else self.points
        return np.abs((p[col].to_numpy() - p["value"].to_numpy()) / p["sigma"].to_numpy())

    @property
    def baseline_max_sigma(self) -> float:
        """Largest |model - value| / sigma of the baseline over all points."""
        z = self._z("model_before", False)
        return float(z.max()) if z.size else 0.0

    @property
    def heldout_max_sigma_after(self) -> float:
        """Largest |model - value| / sigma on the held-out points of the
        model calibrated without them (NaN without held-out points); under
        several explanations, the worst of them."""
        if self.heldout_by_explanation:
            return float(max(self.heldout_by_explanation.values()))
        z = self._z("model_after", True)
        return float(z.max()) if z.size else float("nan")

    @property
    def parameters_in_bounds(self) -> bool:
        return all(c["lower"] <= c["value"] <= c["upper"] for c in self.calibrated)

    @property
    def passes(self) -> bool:
        """Held-out error after calibration within 2 sigma, parameters inside
        their bounds."""
        z = self.heldout_max_sigma_after
        return bool(z == z and z <= 2.0 and self.parameters_in_bounds)

    def summary(self) -> str:
        """The set's outcome in a few lines: pass or not, baseline and
        held-out errors, the verdict, the calibrated values, what is
        missing, the notes."""
        lines = [
            f"{self.name}: {'passes' if self.passes else 'does not pass'} ({self.title})",
            f"  {self.points.height} points; baseline max |model - value| / sigma "
            f"{self.baseline_max_sigma:.3g}; held-out, calibrated without them, "
            f"{self.heldout_max_sigma_after:.3g}",
            f"  verdict: {self.verdict}",
        ]
        lines += [
            f"  held-out under {k}: {v:.3g} sigma" for k, v in self.heldout_by_explanation.items()
        ]
        for c in self.calibrated:
            lines.append(
                f"  calibrated {c['name']} = {c['value']:.4g} {c.get('unit', '')} "
                f"[{c['lower']:.4g}, {c['upper']:.4g}]".rstrip()
            )
        if self.missing:
            lines.append(f"  missing: {self.missing}")
        lines += [f"note: {n}" for n in self.notes]
        return "\n".join(lines)

    def __repr__(self) -> str:
        state = "passes" if self.passes else "does not pass"
        return f"SetResult({self.name!r}, {self.points.height} points, {state})"
