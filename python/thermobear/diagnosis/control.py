"""The generic control of the screening: an unknown smooth effect per
measured quantity, ``a x + b x^2`` with ``x`` the speed over the highest
measured speed (zero at standstill, like every speed-driven effect; two
parameters per quantity). It is never a verdict of its own: when it explains
the data as well as the best named candidate (its delta-BIC within the tie
margin of the named one's, or above), the data cannot tell the known effect
from an unknown one, and the verdict says so instead of naming it."""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

#: Parameters of the generic term of one quantity.
GENERIC_PARAMETERS = 2


@dataclass(frozen=True)
class GenericControl:
    """The generic control fitted to a residual: the quantities whose term
    lowers BIC (``quantities``), its total delta-BIC against the setting
    (the sum over those quantities), its parameter count, chi^2 after it
    and its prediction shift (value units) of every row."""

    quantities: tuple[str, ...]
    delta_bic: float
    n_parameters: int
    chi2: float
    shift: np.ndarray


def generic_control(data, pred: np.ndarray) -> GenericControl:
    """The generic smooth term fitted by linear least squares, quantity by
    quantity, to the residual of ``pred``; a quantity's term is kept when it
    lowers BIC (delta chi^2 > 2 ln n). The quantities act on disjoint rows,
    so the best combination is the union of the terms each worth keeping."""
    sp = data.cond["speed_rpm"].to_numpy()
    top = float(sp.max()) if sp.max() > 0 else 1.0
    x = sp / top
    r = data.residual(pred)
    n = data.n
    shift = np.zeros(n)
    kept, dbic = [], 0.0
    for q in sorted(set(data.quantity.tolist())):
        rows = data.quantity == q
        if rows.sum() <= GENERIC_PARAMETERS:
            continue
        a = np.column_stack([x[rows], x[rows] ** 2]) / data.s[rows, None]
        coef, *_ = np.linalg.lstsq(a, r[rows], rcond=None)
        gain = float(r[rows] @ r[rows] - np.sum((r[rows] - a @ coef) ** 2))
        d = gain - GENERIC_PARAMETERS * np.log(n)
        if d > 0.0:
            kept.append(q)
            dbic += d
            shift[rows] = np.column_stack([x[rows], x[rows] ** 2]) @ coef
    chi2 = float(np.sum((r - shift / data.s) ** 2))
    return GenericControl(tuple(kept), dbic, GENERIC_PARAMETERS * len(kept), chi2, shift)


def control_row(ctrl: GenericControl, chi_base: float) -> dict:
    """The control's row in the screening table (never passes: it is not a
    verdict)."""
    return {
        "candidate": "generic_control",
        "kind": "control",
        "side": "model",
        "value": float(len(ctrl.quantities)),
        "lower_95": None,
        "upper_95": None,
        "null": 0.0,
        "at_bound": False,
        "chi2": ctrl.chi2,
        "n_parameters": ctrl.n_parameters,
        "delta_bic": ctrl.delta_bic,
        "delta_aicc": None,
        "cv_chi2_before": chi_base,
        "cv_chi2_after": None,
        "heldout_chi2_before": None,
        "heldout_chi2_after": None,
        "passes": False,
    }


def control_matches(ctrl: GenericControl, best: dict, margin: float) -> bool:
    """Whether the generic control explains the data as well as the best
    named candidate: its delta-BIC no more than ``margin`` below."""
    return bool(ctrl.quantities) and ctrl.delta_bic >= best["delta_bic"] - margin
