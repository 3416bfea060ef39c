"""The result of [`calibrate`][thermobear.calibrate]: [`Calibration`][thermobear.Calibration]
(the calibrated values with their intervals, the fit before and after, the
points and, for a gear pair, the evaluated design), shared by the smooth
joint calibration (``thermobear.diagnosis.joint``) and the gear pair's
(``thermobear.diagnosis.gear_calibration``)."""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import TYPE_CHECKING, Any

from ..errors import ConfigError

if TYPE_CHECKING:
    from .calibrated import CalibratedModel


@dataclass
class Calibration:
    """Result of [`calibrate`][thermobear.calibrate]. ``parameters``: one row per calibrated
    value (``name``, ``set``: the data-set label or "all" when shared,
    ``value``, ``lower_95``, ``upper_95``, ``lower``, ``upper`` (bounds),
    ``null`` (the baseline's), ``at_bound``, ``identified``); ``chi2`` and
    ``n`` of the fit, ``phi`` (interval stretch), ``condition_number`` of
    the Fisher information in correlation form, ``not_identified`` (names),
    ``points``: every measured row with ``set``, ``model_before`` and
    ``model_after``."""

    parameters: Any
    chi2: float
    chi2_before: float
    n: int
    phi: float
    condition_number: float
    not_identified: list
    points: Any
    notes: list = field(default_factory=list)
    _models: dict = field(default_factory=dict, repr=False, compare=False)
    #: A gear pair's calibration: every evaluated point of its design
    #: (the inputs, ``chi2``, ``stage``, ``within_95``); None otherwise.
    design: Any = field(default=None, repr=False, compare=False)

    @property
    def model(self) -> CalibratedModel:
        """The calibrated model of the first data set (see
        [`model_for`][thermobear.Calibration.model_for]): a
        [`CalibratedModel`][thermobear.CalibratedModel]."""
        if not self._models:
            raise ConfigError("invalid calibration: it carries no calibrated model")
        return next(iter(self._models.values()))

    def model_for(self, set_label: str) -> CalibratedModel:
        """The calibrated model of data set ``set_label``: its spec with the
        values that act on it (the shared ones and its own per-set ones)."""
        if str(set_label) in self._models:
            return self._models[str(set_label)]
        raise ConfigError(f"invalid set_label = {set_label!r}: not a data set of this calibration")

    def summary(self) -> str:
        """The calibration in a few lines: each value with its 95 % profile
        interval and bounds (flagged at a bound or not identified), the fit
        before and after, the interval stretch and the notes."""
        lines = [
            f"calibration of {self.parameters.height} value(s) on {self.n} points: chi^2 "
            f"{self.chi2_before:.4g} -> {self.chi2:.4g} (phi {self.phi:.3g}, condition number "
            f"{self.condition_number:.3g})"
        ]
        for r in self.parameters.iter_rows(named=True):
            flags = ([" at its bound"] if r["at_bound"] else []) + (
                [" not identified"] if not r["identified"] else []
            )
            lines.append(
                f"  {r['name']} [{r['set']}] = {r['value']:.4g}  95 % [{r['lower_95']:.4g}, "
                f"{r['upper_95']:.4g}]  bounds [{r['lower']:.4g}, {r['upper']:.4g}], null "
                f"{r['null']:.4g}{''.join(flags)}"
            )
        lines += [f"note: {n}" for n in self.notes]
        return "\n".join(lines)

    def __repr__(self) -> str:
        values = ", ".join(
            f"{r['name']}={r['value']:.4g}" for r in self.parameters.iter_rows(named=True)
        )
        return f"Calibration({values}; chi2 {self.chi2_before:.4g} -> {self.chi2:.4g}, n={self.n})"
