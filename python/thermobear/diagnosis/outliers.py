"""The robust outlier audit of [`thermobear.diagnose`][thermobear.diagnose]: single points
that no smooth model of their series can reach.

The rule, on the residual (value - model) / sigma of the best-fit setting:
a *series* is one quantity at one load and run, ordered by speed. Within a
series of at least 5 points, each point's residual is compared with a
straight line in speed fitted to the series (the best fit has taken the
curvature out; a line keeps the leverage of the end points low), as
the standardized leave-one-out deviation ``t = e / sqrt(1 - h)`` (``e``
the least-squares residual, ``h`` the leverage: the deviation from the
trend of the *other* points, in units of its own standard deviation at
unit sigma). The robust scale of a quantity is ``s = max(1, 1.4826 MAD(t))``
over all its series (a median, so one gross point does not inflate it). A
point is an outlier when both

* ``|t| > 5 s`` (far outside the scatter of its series about a smooth
  trend), and
* its residual, taken from the series' median, exceeds 3 times that of
  each of its speed neighbours (a single point, not the end of a steep but
  smooth rise).

Points are removed one at a time (the worst first, the trend refitted)
and at most a quarter of a series is flagged."""

from __future__ import annotations

import numpy as np

#: Thresholds of the rule (see the module docstring).
Z_OUTLIER = 5.0
NEIGHBOUR_RATIO = 3.0
MAD_TO_SIGMA = 1.4826  # 1 / Phi^-1(3/4): MAD of a normal sample -> its sigma


def _series(df) -> list[np.ndarray]:
    """Row indices of each series (quantity, load, run), sorted by speed."""
    keys = list(
        zip(
            df["quantity"].to_list(),
            df["axial_n"].to_list(),
            df["radial_n"].to_list(),
            df["run"].to_list(),
            strict=False,
        )
    )
    sp = df["speed_rpm"].to_numpy()
    out = []
    for k in sorted(set(keys)):
        rows = np.array([i for i, kk in enumerate(keys) if kk == k])
        out.append(rows[np.argsort(sp[rows], kind="stable")])
    return out


def loo_deviation(x: np.ndarray, r: np.ndarray) -> np.ndarray:
    """Standardized leave-one-out deviation of each point from a straight
    line in ``x`` through the others; zeros for fewer than four points."""
    n = len(r)
    if n < 4:
        return np.zeros(n)
    span = x.max() - x.min()
    u = (x - x.min()) / span if span > 0 else np.zeros(n)
    a = np.vander(u, 2)
    q, _ = np.linalg.qr(a)
    h = np.sum(q * q, axis=1)
    e = r - q @ (q.T @ r)
    return e / np.sqrt(np.clip(1.0 - h, 1e-12, None))


def _robust_scale(t: np.ndarray) -> float:
    if t.size == 0:
        return 1.0
    return max(1.0, MAD_TO_SIGMA * float(np.median(np.abs(t - np.median(t)))))


def _single_point(r: np.ndarray, j: int) -> bool:
    """Whether point ``j`` of a series stands alone: its residual from the
    series median beyond NEIGHBOUR_RATIO times each speed neighbour's."""
    d = np.abs(r - np.median(r))
    nb = [k for k in (j - 1, j + 1) if 0 <= k < len(r)]
    return all(d[j] > NEIGHBOUR_RATIO * d[k] for k in nb)


def _worst(x: np.ndarray, r: np.ndarray, pool: np.ndarray) -> tuple[int, float]:
    """The point of a series farthest from the trend of the others and its
    robust z: its leave-one-out deviation over the robust scale of the
    other points' deviations, recomputed without it (so that a gross point
    does not inflate the scale it is judged by), pooled with ``pool`` (the
    deviations of the quantity's other series); (-1, 0) when it does not
    stand alone."""
    t = loo_deviation(x, r)
    j = int(np.argmax(np.abs(t)))
    rest = np.arange(len(r)) != j
    z = t[j] / _robust_scale(np.concatenate([loo_deviation(x[rest], r[rest]), pool]))
    return (j, float(z)) if _single_point(r, j) else (-1, 0.0)


def flag_outliers(df, r: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """(mask of the outliers, robust z of the flagged rows, 0 elsewhere) by
    the rule of the module docstring, on the residual ``r`` (in sigma) of
    the rows of the tidy table ``df``."""
    sp = df["speed_rpm"].to_numpy().astype(float)
    q = df["quantity"].to_numpy()
    series = _series(df)
    t_all = np.zeros(len(r))
    for rows in series:
        t_all[rows] = loo_deviation(sp[rows], r[rows])
    flagged = np.zeros(len(r), dtype=bool)
    z = np.zeros(len(r))
    for rows in series:
        pool = t_all[(q == q[rows[0]]) & ~np.isin(np.arange(len(r)), rows)]
        live = rows.copy()
        for _ in range(len(rows) // 4):
            if len(live) < 5:  # the trend of the others needs four points
                break
            j, zj = _worst(sp[live], r[live], pool)
            if j < 0 or abs(zj) <= Z_OUTLIER:
                break
            flagged[live[j]] = True
            z[live[j]] = zj
            live = np.delete(live, j)
    return flagged, z


def outlier_table(df, flagged: np.ndarray, z: np.ndarray, pred: np.ndarray):
    """The flagged rows: quantity, condition, value, model and robust z."""
    import polars as pl

    rows = df.with_columns(pl.Series("model", pred), pl.Series("robust_z", z)).filter(flagged)
    return rows.select(
        ["quantity", "speed_rpm", "axial_n", "radial_n", "run", "value", "model", "robust_z"]
    )


def outlier_words(table) -> str:
    """The outliers in words for the verdict."""
    parts = [
        f"{r['quantity']} at {r['speed_rpm']:.0f} rpm, {r['axial_n']:.0f} N"
        + (f", run {r['run']}" if r["run"] != "1" else "")
        + f" ({r['robust_z']:+.1f} robust sigma)"
        for r in table.iter_rows(named=True)
    ]
    n = len(parts)
    return f"{n} outlier{'s' if n > 1 else ''} left out: " + "; ".join(parts)
