"""Step 4 of [`thermobear.diagnose`][thermobear.diagnose]: acceptance -- the best passing
candidate, a tie set of rivals, the accepted record, and the joint refit
of every accepted parameter."""

from __future__ import annotations

from typing import Callable, Optional

import numpy as np

from ..errors import ThermobearError
from .candidates import Candidate
from .joint import _CHI2_95, _profile
from .setting import _predict, _Setting
from .statistics import fisher_identifiability
from .ties import tie_members


class _RefitProblem:
    """The refit as ``_profile`` reads a problem: bounds and
    the residual/sigma of the training points against the parameters."""

    def __init__(
        self, resid: Callable[[np.ndarray], np.ndarray], lo: np.ndarray, hi: np.ndarray
    ) -> None:
        self.resid, self.lo, self.hi = resid, lo, hi

    def chi2(self, theta: np.ndarray) -> float:
        r = self.resid(theta)
        return float(r @ r)


def joint_refit(model, cands, accepted, cond, quantity, y, s, train, base_options):
    """Re-calibrate every accepted continuous parameter together (bounded
    least squares on the model itself, not the interpolant) once two or more
    are accepted: an effect calibrated alone absorbs part of the next one.
    Intervals: 95 % profile likelihood, as [`calibrate`][thermobear.calibrate] gives
    them -- the values of one parameter where the chi^2, the others
    re-calibrated at each trial value, stays within 3.84 phi of the minimum
    (phi = max(1, reduced chi^2)); ``identified``: False for a parameter the
    Fisher information does not identify
    (``fisher_identifiability``) or whose interval spans
    both bounds. Updates ``accepted`` in place; returns (setting,
    prediction) or None."""
    from scipy.optimize import least_squares

    idx = [i for i, c in enumerate(cands) if c.kind == "parameter"]
    if len(idx) < 2:
        return None

    def setting(theta):
        st = _Setting((), (), ())
        vals = {i: t for i, t in zip(idx, theta, strict=False)}
        for i, c in enumerate(cands):
            st = st.apply(c, float(vals.get(i, accepted[i]["value"])), base_options)
        return st

    def resid(theta):
        return ((y - _predict(model, setting(theta), cond, quantity)) / s)[train]

    x0 = np.array([accepted[i]["value"] for i in idx])
    lo = np.array([cands[i].lower for i in idx])
    hi = np.array([cands[i].upper for i in idx])
    try:
        res = least_squares(
            resid,
            np.clip(x0, lo, hi),
            bounds=(lo, hi),
            diff_step=1e-4,
            x_scale=hi - lo,
            max_nfev=60,
        )
        chi_min = 2.0 * float(res.cost)
        phi = max(1.0, chi_min / max(int(train.sum()) - len(idx), 1))
        prob = _RefitProblem(resid, lo, hi)
        # the linearised interval (J^T J)^-1 brackets the profile's edges
        se = np.sqrt(np.clip(np.diag(np.linalg.pinv(res.jac.T @ res.jac)), 0.0, None) * phi)
        intervals = [
            _profile(prob, res.x, chi_min, k, _CHI2_95 * phi, 1.96 * se[k]) for k in range(len(idx))
        ]
    except (ThermobearError, ValueError, np.linalg.LinAlgError):
        return None
    _, weak = fisher_identifiability(res.jac, hi - lo)
    for k, i in enumerate(idx):
        a, b = intervals[k]
        accepted[i].update(
            value=float(res.x[k]),
            lower_95=float(a),
            upper_95=float(b),
            joint=True,
            identified=k not in weak and not (a <= lo[k] and b >= hi[k]),
        )
    st = setting(res.x)
    return st, _predict(model, st, cond, quantity)


def select(rows: list, tie_delta_bic: float) -> tuple[Optional[dict], list]:
    """The best passing screening row (largest delta-BIC; None when no row
    passes) and its rivals (``tie_members``): every other named
    candidate -- passing or not -- whose delta-BIC is less than
    ``tie_delta_bic`` below the best's (a higher one included), unless it
    sits at a bound of its range; they make a tie set."""
    passing = [row for row in rows if row["passes"]]
    if not passing:
        return None, []
    best = max(passing, key=lambda row: row["delta_bic"])
    return best, tie_members(rows, best, tie_delta_bic)


def accepted_record(c: Candidate, best: dict, rnd: int) -> dict:
    """The record of an accepted candidate (``Diagnosis.accepted``) from
    its screening row in round ``rnd`` (0-based)."""
    return {
        "name": c.name,
        "side": c.side,
        "role": c.role,
        "parameter": c.parameter,
        "null": c.null,
        "unit": c.unit,
        "value": best["value"],
        "lower_95": best["lower_95"],
        "upper_95": best["upper_95"],
        "delta_bic": best["delta_bic"],
        "round": rnd + 1,
    }
