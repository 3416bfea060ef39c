"""Step 3 of :func:`thermobear.diagnose`: each candidate added alone to
the baseline and calibrated within its bounds on the training points --
its prediction curve over a grid of values, the calibrated value, the 95 %
profile interval, BIC and the held-out chi^2."""

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


def _fit(curve: _Curve, y, s, train) -> dict:
    c = curve.cand
    if c.kind == "switch":
        r = (y - curve.preds[-1]) / s
        return {
            "value": 1.0,
            "chi2": _chi2(r[train]),
            "lower_95": None,
            "upper_95": None,
            "pred": curve.preds[-1],
            "at_bound": False,
            "excludes_null": True,
        }
    lo, hi = curve.values.min(), curve.values.max()
    grid = np.linspace(lo, hi, _DENSE)
    p = curve.at(grid)
    chi = np.sum(((y[train] - p[:, train]) / s[train]) ** 2, axis=1)
    i = int(np.argmin(chi))
    from scipy.optimize import minimize_scalar

    a, b = grid[max(i - 1, 0)], grid[min(i + 1, _DENSE - 1)]
    best_v, best_c = grid[i], chi[i]
    if b > a:
        res = minimize_scalar(
            lambda v: float(
                np.sum(((y[train] - curve.at(np.array([v]))[0][train]) / s[train]) ** 2)
            ),
            bounds=(a, b),
            method="bounded",
            options={"xatol": (hi - lo) * 1e-6},
        )
        if res.fun < best_c:
            best_v, best_c = float(res.x), float(res.fun)

    # contiguous 95 % profile interval around the best value; the edges are
    # refined by root finding on the interpolant (the dense grid is coarse)
    def excess(v: float) -> float:
        p1 = curve.at(np.array([v]))[0]
        return float(np.sum(((y[train] - p1[train]) / s[train]) ** 2)) - best_c - _CHI2_95

    lo95 = _profile_edge(excess, grid, chi, best_v, best_c, -1)
    hi95 = _profile_edge(excess, grid, chi, best_v, best_c, +1)
    tol = (hi - lo) * 0.01
    return {
        "value": float(best_v),
        "chi2": float(best_c),
        "lower_95": lo95,
        "upper_95": hi95,
        "pred": curve.at(np.array([best_v]))[0],
        "at_bound": bool(best_v <= lo + tol or best_v >= hi - tol),
        "excludes_null": bool(not (lo95 <= c.null <= hi95)),
    }


def _profile_edge(excess, grid, chi, best_v, best_c, direction) -> float:
    """Edge of the contiguous 95 % profile interval around ``best_v`` on one
    side: the nearest dense-grid point beyond which chi^2 exceeds the
    minimum by 3.84 brackets the root of ``excess`` with the last point
    inside (or ``best_v`` itself when the interval is narrower than the
    grid spacing); the interval reaches the bound when no point is outside."""
    from scipy.optimize import brentq

    out = chi > best_c + _CHI2_95
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


def screen(curves, data, chi_base, chi_held, delta_bic_min):
    """One screening round: each curve calibrated alone on the training
    points (:func:`_fit`) and scored against the baseline's training chi^2
    ``chi_base`` and held-out chi^2 ``chi_held``. A row passes with
    delta-BIC >= ``delta_bic_min``, the held-out chi^2 improved and (for a
    parameter) a 95 % interval inside the bounds that excludes the null
    value. Returns (rows, fits by name)."""
    rows, fits = [], {}
    for name, cu in curves.items():
        f = _fit(cu, data.y, data.s, data.train)
        fits[name] = f
        rows.append(_screen_row(cu.cand, f, data, chi_base, chi_held, delta_bic_min))
    return rows, fits


def _screen_row(c, f, data, chi_base, chi_held, delta_bic_min) -> dict:
    held = data.held
    rr = (data.y - f["pred"]) / data.s
    bic = f["chi2"] + np.log(data.n_train)
    held_after = _chi2(rr[held]) if held.any() else 0.0
    held_ok = (held_after < chi_held) if held.any() else True
    dbic = chi_base - bic
    interval_ok = c.kind == "switch" or (f["excludes_null"] and not f["at_bound"])
    return {
        "candidate": c.name,
        "kind": c.kind,
        "side": c.side,
        "value": f["value"],
        "lower_95": f["lower_95"],
        "upper_95": f["upper_95"],
        "null": c.null,
        "chi2_train": f["chi2"],
        "delta_bic": dbic,
        "heldout_chi2_before": chi_held,
        "heldout_chi2_after": held_after,
        "passes": bool(dbic >= delta_bic_min and held_ok and interval_ok),
    }


def screening_table(rows: list, rnd: int) -> Any:
    """The screening rows of round ``rnd`` (0-based) as a table, best
    delta-BIC first, with a ``round`` column (1-based)."""
    import polars as pl

    if not rows:
        return pl.DataFrame()
    table = pl.DataFrame(rows).sort("delta_bic", descending=True)
    return table.with_columns(pl.lit(rnd + 1).alias("round"))
