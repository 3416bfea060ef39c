"""Step 3 of [`thermobear.diagnose`][thermobear.diagnose]: each candidate added alone to
the baseline and calibrated within its bounds on all the points -- its
prediction curve over a grid of values, the calibrated value, the 95 %
profile-likelihood interval, BIC and AICc, the cross-validated chi^2 (folds
of operating cells) and, reported apart, the extrapolation check (held-out
top speeds or runs)."""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any, Optional

import numpy as np

from .candidates import Candidate
from .setting import _predict
from .statistics import _chi2

_GRID = 13  # parameter values evaluated per candidate (cubic interpolant between)


_DENSE = 601


_CHI2_95 = 3.841  # chi^2(1) 95 % quantile: profile interval

#: A calibrated value within this fraction of the span from a bound sits
#: at the bound (the dense grid's spacing is 1/600 of the span).
_AT_BOUND = 2e-3


@dataclass
class _Curve:
    """Predictions of the measured rows against one candidate's parameter."""

    cand: Candidate
    values: np.ndarray  # parameter values with a model evaluation
    preds: np.ndarray  # (len(values), n_rows)

    def _spline(self) -> Any:
        if not hasattr(self, "_cs"):
            from scipy.interpolate import CubicSpline

            self._cs = CubicSpline(self.values, self.preds, axis=0)
        return self._cs

    def at(self, v: np.ndarray) -> np.ndarray:
        if self.cand.kind == "switch":
            idx = np.clip(np.rint(v), 0, 1).astype(int)
            return self.preds[idx]
        return self._spline()(v)

    def slope(self) -> np.ndarray:
        """d prediction / d parameter at the null value (switch: on - off)."""
        if self.cand.kind == "switch":
            return self.preds[-1] - self.preds[0]
        return self._spline()(self.cand.null, 1)


def _grid_with_null(grid: np.ndarray, null: float) -> np.ndarray:
    """The grid with the null value put on it: a grid point within a tiny
    fraction of the span of the null is replaced by it (two abscissae that
    differ only by rounding would break the interpolant)."""
    tol = 1e-6 * (grid[-1] - grid[0])
    keep = grid[np.abs(grid - null) > tol]
    return np.unique(np.concatenate([keep, [null]]))


def _curve(model, st, c, cond, quantity, base_options) -> Optional[_Curve]:
    from ..errors import ThermobearError

    if c.kind == "switch":
        vals = np.array([0.0, 1.0])
    elif c.lower > 0.0 and c.upper >= 20.0 * c.lower:
        # A positive scale over decades: the response goes like 1/scale
        # (a conductance), so a geometric grid keeps the interpolant accurate
        # at the low end.
        vals = _grid_with_null(np.geomspace(c.lower, c.upper, _GRID), c.null)
    else:
        vals = _grid_with_null(np.linspace(c.lower, c.upper, _GRID), c.null)
    good, preds = [], []
    for v in vals:
        try:
            preds.append(_predict(model, st.apply(c, float(v), base_options), cond, quantity))
            good.append(v)
        except ThermobearError:
            continue
    if c.kind == "switch" and len(good) < 2 or c.kind != "switch" and len(good) < 4:
        return None
    return _Curve(c, np.asarray(good), np.asarray(preds))


def _dense(curve: _Curve) -> tuple[np.ndarray, np.ndarray]:
    """The dense parameter grid over the curve's values and the
    interpolated predictions on it (``(_DENSE, n_rows)``)."""
    grid = np.linspace(curve.values.min(), curve.values.max(), _DENSE)
    return grid, curve.at(grid)


def _switch_fit(curve: _Curve, y, s, mask) -> dict:
    r = (y - curve.preds[-1]) / s
    return {
        "value": 1.0,
        "chi2": _chi2(r[mask]),
        "lower_95": None,
        "upper_95": None,
        "pred": curve.preds[-1],
        "at_bound": False,
        "excludes_null": True,
        "phi": 1.0,
    }


def _fit(curve: _Curve, y, s, mask, dense=None) -> dict:
    """The candidate calibrated on the rows of ``mask``: the least chi^2
    over its bounds (dense grid, then bounded refinement on the
    interpolant) and its 95 % profile-likelihood interval: the values whose
    chi^2 exceeds the minimum by less than 3.84 phi, phi = max(1, reduced
    chi^2 of the fit) -- the interval widens when the residual left is
    larger than the stated sigma explain (the stated sigma too small, or
    structure the candidate does not explain)."""
    c = curve.cand
    if c.kind == "switch":
        return _switch_fit(curve, y, s, mask)
    grid, p = dense if dense is not None else _dense(curve)
    lo, hi = grid[0], grid[-1]
    chi = np.sum(((y[mask] - p[:, mask]) / s[mask]) ** 2, axis=1)
    i = int(np.argmin(chi))

    def chi_at(v: float) -> float:
        return float(np.sum(((y[mask] - curve.at(np.array([v]))[0][mask]) / s[mask]) ** 2))

    best_v, best_c = _refine(chi_at, grid, i, chi[i], (hi - lo) * 1e-6)
    phi = max(1.0, best_c / max(int(mask.sum()) - 1, 1))
    thr = _CHI2_95 * phi

    def excess(v: float) -> float:
        return chi_at(v) - best_c - thr

    lo95 = _profile_edge(excess, grid, chi, best_v, best_c, -1, thr)
    hi95 = _profile_edge(excess, grid, chi, best_v, best_c, +1, thr)
    tol = (hi - lo) * _AT_BOUND
    return {
        "value": float(best_v),
        "chi2": float(best_c),
        "lower_95": lo95,
        "upper_95": hi95,
        "pred": curve.at(np.array([best_v]))[0],
        "at_bound": bool(best_v <= lo + tol or best_v >= hi - tol),
        "excludes_null": bool(not (lo95 <= c.null <= hi95)),
        "phi": phi,
    }


def _refine(chi_at, grid, i, chi_i, xatol) -> tuple[float, float]:
    """Bounded scalar minimisation of ``chi_at`` between the dense-grid
    neighbours of its best grid point ``i``."""
    from scipy.optimize import minimize_scalar

    a, b = grid[max(i - 1, 0)], grid[min(i + 1, len(grid) - 1)]
    best_v, best_c = float(grid[i]), float(chi_i)
    if b > a:
        res = minimize_scalar(chi_at, bounds=(a, b), method="bounded", options={"xatol": xatol})
        if res.fun < best_c:
            best_v, best_c = float(res.x), float(res.fun)
    return best_v, best_c


def _sq_residuals(curve: _Curve, y, s, dense=None) -> np.ndarray:
    """Squared residuals (in sigma) of every row at every dense-grid value."""
    _, p = dense if dense is not None else _dense(curve)
    return ((y - p) / s) ** 2


def cv_chi2(curve: _Curve, y, s, folds, dense=None, r2=None) -> tuple[float, int]:
    """Cross-validated chi^2 of a candidate and the number of folds that
    test it: for each fold, the parameter calibrated on the other folds
    (dense-grid minimum) predicts the fold; the sum over the folds. A fold
    tests the candidate only when the candidate moves both its training
    and its held-out points; an untested fold keeps the setting's chi^2
    (the null value's). A switch has no parameter: its chi^2, every fold."""
    if curve.cand.kind == "switch":
        return _chi2((y - curve.preds[-1]) / s), len(np.unique(folds))
    _, p = dense if dense is not None else _dense(curve)
    r2 = _sq_residuals(curve, y, s, dense) if r2 is None else r2
    r2_null = ((y - curve.at(np.array([curve.cand.null]))[0]) / s) ** 2
    moves = np.ptp(p, axis=0) / s > 1e-9
    total, tested = 0.0, 0
    for f in np.unique(folds):
        held = folds == f
        train = ~held
        if moves[train].any() and moves[held].any():
            i = int(np.argmin(r2[:, train].sum(axis=1)))
            total += float(r2[i, held].sum())
            tested += 1
        else:
            total += float(r2_null[held].sum())
    return total, tested


def extrapolation_chi2(curve: _Curve, y, s, train, dense=None, r2=None) -> float:
    """Chi^2 on the held-out points (``~train``) of the candidate
    calibrated on the training points only (dense-grid minimum)."""
    held = ~train
    if curve.cand.kind == "switch":
        return _chi2(((y - curve.preds[-1]) / s)[held])
    r2 = _sq_residuals(curve, y, s, dense) if r2 is None else r2
    i = int(np.argmin(r2[:, train].sum(axis=1)))
    return float(r2[i, held].sum())


def _profile_edge(excess, grid, chi, best_v, best_c, direction, thr=_CHI2_95) -> float:
    """Edge of the contiguous 95 % profile interval around ``best_v`` on one
    side: the nearest dense-grid point beyond which chi^2 exceeds the
    minimum by ``thr`` (3.84 phi) brackets the root of ``excess`` with the last point
    inside (or ``best_v`` itself when the interval is narrower than the
    grid spacing); the interval reaches the bound when no point is outside."""
    from scipy.optimize import brentq

    out = chi > best_c + thr
    side = grid < best_v if direction < 0 else grid > best_v
    idx = np.flatnonzero(out & side)
    if idx.size == 0:
        return float(grid[0] if direction < 0 else grid[-1])
    j = int(idx[-1] if direction < 0 else idx[0])
    inner = grid[j + 1] if direction < 0 else grid[j - 1]
    inner = max(inner, best_v) if direction > 0 else min(inner, best_v)
    a, b = (grid[j], inner) if direction < 0 else (inner, grid[j])
    fa, fb = excess(a), excess(b)
    if fa * fb > 0.0:  # rounding at the bracket: the grid point is the edge
        return float(grid[j])
    return float(brentq(excess, a, b))


def candidate_curves(model, st, pool, data, base_options):
    """Each candidate of ``pool`` evaluated around the setting ``st``:
    (curves by name, names not evaluable, notes). A candidate whose model
    fails on too many grid values, or which moves no measured quantity
    (slope below 1e-9 sigma), is dropped."""
    curves, dropped, notes = {}, [], []
    for c in pool:
        cu = _curve(model, st, c, data.cond, data.quantity, base_options)
        if cu is None:
            dropped.append(c.name)
            continue
        if np.max(np.abs(cu.slope() / data.s)) < 1e-9:
            dropped.append(c.name)
            notes.append(f"{c.name}: no effect on the measured quantities")
            continue
        curves[c.name] = cu
    return curves, dropped, notes


def screen(curves, data, chi_base, chi_held, delta_bic_min, k_accepted: int = 0):
    """One screening round: each curve calibrated alone on all the points
    (``_fit``) and scored against the current setting's chi^2
    ``chi_base`` (all points) and held-out chi^2 ``chi_held``; ``k_accepted``
    parameters are in the setting already (for AICc). A row passes with
    delta-BIC >= ``delta_bic_min``, a lower cross-validated chi^2 than the
    setting's (``cv_chi2``) and (for a parameter) a 95 % interval inside
    the bounds that excludes the null value. The extrapolation check
    (calibrated without the held-out points, ``extrapolation_chi2``) is
    reported, not required. Returns (rows, fits by name)."""
    rows, fits = [], {}
    everything = np.ones(data.n, dtype=bool)
    for name, cu in curves.items():
        dense = r2 = None
        if cu.cand.kind != "switch":
            dense = _dense(cu)
            r2 = _sq_residuals(cu, data.y, data.s, dense)
        f = _fit(cu, data.y, data.s, everything, dense)
        f["cv_chi2"], f["cv_folds"] = cv_chi2(cu, data.y, data.s, data.folds, dense, r2)
        f["held_chi2"] = (
            extrapolation_chi2(cu, data.y, data.s, data.train, dense, r2)
            if data.held.any()
            else 0.0
        )
        fits[name] = f
        rows.append(_screen_row(cu.cand, f, data, chi_base, chi_held, delta_bic_min, k_accepted))
    return rows, fits


def aicc_penalty(k: int, n: int) -> float:
    """AICc's penalty of ``k`` parameters on ``n`` points: 2k + 2k(k+1)/(n-k-1)
    (infinite when n <= k + 1)."""
    return 2.0 * k + (2.0 * k * (k + 1) / (n - k - 1) if n > k + 1 else np.inf)


def _screen_row(c, f, data, chi_base, chi_held, delta_bic_min, k_accepted=0) -> dict:
    n, k = data.n, 1  # a switch counts as one parameter (a model choice), like a value
    dbic = chi_base - f["chi2"] - k * np.log(n)
    daicc = chi_base - f["chi2"] + aicc_penalty(k_accepted, n) - aicc_penalty(k_accepted + k, n)
    interval_ok = c.kind == "switch" or (f["excludes_null"] and not f["at_bound"])
    # no fold can test a candidate whose effect sits in one operating cell:
    # the cross-validation has nothing to say, BIC and the interval decide
    cv_ok = f["cv_chi2"] < chi_base or f["cv_folds"] == 0
    return {
        "candidate": c.name,
        "kind": c.kind,
        "side": c.side,
        "value": f["value"],
        "lower_95": f["lower_95"],
        "upper_95": f["upper_95"],
        "null": c.null,
        "at_bound": f["at_bound"],
        "chi2": f["chi2"],
        "n_parameters": k,
        "delta_bic": dbic,
        "delta_aicc": daicc,
        "cv_chi2_before": chi_base,
        "cv_chi2_after": f["cv_chi2"],
        "cv_folds": f["cv_folds"],
        "heldout_chi2_before": chi_held,
        "heldout_chi2_after": f["held_chi2"],
        "passes": bool(dbic >= delta_bic_min and cv_ok and interval_ok),
    }


def screening_table(rows: list, rnd: int) -> Any:
    """The screening rows of round ``rnd`` (0-based) as a table, best
    delta-BIC first, with a ``round`` column (1-based)."""
    import polars as pl

    if not rows:
        return pl.DataFrame()
    floats = (
        "value", "lower_95", "upper_95", "null", "chi2", "delta_bic", "delta_aicc",
        "cv_chi2_before", "cv_chi2_after", "heldout_chi2_before", "heldout_chi2_after",
    )  # fmt: skip
    table = pl.DataFrame(rows).with_columns(
        [pl.col(c).cast(pl.Float64) for c in floats if c in rows[0]]
    )
    table = table.sort("delta_bic", descending=True)
    return table.with_columns(pl.lit(rnd + 1).alias("round"))
