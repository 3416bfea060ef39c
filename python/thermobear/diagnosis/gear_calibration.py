"""Calibrating a gear pair against its bifurcation diagram:
[`thermobear.calibrate`][thermobear.calibrate] on a
[`GearModelSpec`][thermobear.GearModelSpec].

A transition speed jumps when an input crosses a bifurcation, so the
chi^2 of the measured transition speeds is a discontinuous, many-valleyed
function of the inputs, on which least squares stalls. The calibration
instead:

1. evaluates a scrambled Sobol design of ``design_points`` points over the
   inputs' bounds (plus the baseline's values): a coarse map of the chi^2;
2. refines around the best point with a second design of
   ``refine_points`` in a box an eighth of each bound span wide on either
   side (clipped to the bounds), repeated ``refine_rounds`` times around the
   best point so far, each box half as wide as the last;
3. explores the region within the 95 % threshold (below): a design of
   ``refine_points`` in the extent of the points inside it, widened by half
   that extent on either side, until a round no longer widens the extent
   by a tenth (at most three rounds), so that the interval read off the
   design spans the region rather than the few points the refinement
   happened to put in it;
4. takes the least chi^2 of all evaluated points as the estimate.

The residual of a row is (measured - model) / sigma, sigma the stated one
combined with the model's own resolution (a transition is located to one
step of the sweep's speed grid: a uniform error of standard deviation
step / sqrt(12)); a row the model has
no such transition for, or one further off than ``penalty_rpm``, counts as
``penalty_rpm`` off: a capped (robust) chi^2, so that one transition the
model lacks does not outweigh all the others.

Intervals: phi = max(1, chi^2_min / (n - p)) stretches the stated sigmas
when the fit says they are too small (as [`calibrate`][thermobear.calibrate]
does for smooth models). Read off the design, the region within 3.84 phi
of the minimum (a profile-likelihood region) is resolved only at the
evaluated points, and a rough chi^2 breaks it into islands; so the chi^2's
trend near the estimate is fitted too: a quadratic bowl by least squares
over the points of the first refinement box (``_bowl``), whose curvature
gives a covariance 2 phi H^-1 (phi from the bowl's own least value). The
95 % interval of each input spans both the range of the evaluated points
within the threshold and the estimate +- 1.96 of the bowl's standard
deviation, within the bounds; an input whose interval spans nine tenths of
its bounds is reported as not identified. The covariance (which feeds the
sampled bands of [`predict`][thermobear.predict.band.predict]) is the
bowl's (without cross terms where the full surface is no bowl); where there
is no bowl at all (too few points), that of the evaluated points weighted
by exp(-(chi^2 - chi^2_min) / (2 phi)), each standard deviation at least
the range of the points inside over 3.92, and the interval spans the
estimate +- 1.96 of its standard deviation as well.

Every evaluated point is kept (``Calibration.design``: the inputs, chi^2
and stage), so the map the estimate came from can be drawn and checked.
"""

from __future__ import annotations

from typing import Any, Callable, Optional, Sequence

import numpy as np

from .. import _validate as val
from ..errors import ConfigError
from .calibration import Calibration

_CHI2_95 = 3.841

#: Default design sizes: the coarse Sobol design and each refinement.
DESIGN_POINTS = 128
REFINE_POINTS = 32
REFINE_ROUNDS = 2
#: A transition the model lacks, or one further off than this, counts as
#: this far off [rpm].
PENALTY_RPM = 3000.0
#: Half width of a refinement box, as a fraction of each bound span.
REFINE_HALF_WIDTH = 1.0 / 8.0
#: Most rounds exploring the region within the 95 % threshold.
EXPLORE_ROUNDS = 3


class _GearData:
    """One data set: its spec, checked measurements, conditions."""

    def __init__(self, label: str, spec: Any, measured: Any) -> None:
        from .gear_spec import GEAR_CONDITIONS, GEAR_QUANTITIES
        from .measurements import load_measurements

        df = load_measurements(measured, GEAR_QUANTITIES)
        self.label, self.spec, self.df = label, spec, df
        self.cond = df.select(list(GEAR_CONDITIONS))
        self.quantity = df["quantity"].to_numpy()
        self.y = df["value"].to_numpy()
        # the model locates a transition only to its sweep's grid: a uniform
        # error over one step (sd step / sqrt(12)) adds to the stated sigma
        grid = np.diff(spec.sweep_speeds(self.cond))
        step = float(np.median(grid)) if grid.size else 0.0
        self.s = np.hypot(df["sigma"].to_numpy(), step / np.sqrt(12.0))

    def predict(self, values: dict[str, float]) -> np.ndarray:
        got = self.spec.with_setting(**values).predict(self.cond)
        out = np.empty(len(self.y))
        for q in np.unique(self.quantity):
            rows = self.quantity == q
            out[rows] = got[q][rows]
        return out

    def residual(self, pred: np.ndarray, penalty_rpm: float) -> np.ndarray:
        off = np.where(np.isfinite(pred), np.abs(self.y - pred), penalty_rpm)
        sign = np.where(np.isfinite(pred), np.sign(self.y - pred), 1.0)
        return sign * np.minimum(off, penalty_rpm) / self.s


def calibrate_gear(
    sets: Sequence[tuple[str, Any, Any]],
    parameters: Sequence[str],
    *,
    design_points: Optional[int] = None,
    refine_points: Optional[int] = None,
    refine_rounds: Optional[int] = None,
    penalty_rpm: Optional[float] = None,
    seed: int = 0,
    progress: Optional[Callable[[int, int], Any]] = None,
) -> Calibration:
    """The calibration of ``parameters`` (names of
    ``thermobear.diagnosis.gear_spec.GEAR_PARAMETERS``, shared by every set)
    on the transition speeds of ``sets`` ((label, gear spec, measured)
    triples): see the module docstring. ``progress(done, total)`` after
    each evaluated point; Ctrl-C stops between points (and inside a sweep)."""
    n_design = val.whole("design_points", DESIGN_POINTS if design_points is None else
                         design_points, 1, 100_000)  # fmt: skip
    n_refine = val.whole("refine_points", REFINE_POINTS if refine_points is None else
                         refine_points, 0, 100_000)  # fmt: skip
    rounds = val.whole("refine_rounds", REFINE_ROUNDS if refine_rounds is None else
                       refine_rounds, 0, 100)  # fmt: skip
    penalty = val.real("penalty_rpm", PENALTY_RPM if penalty_rpm is None else penalty_rpm,
                       0.0, open_lo=True)  # fmt: skip
    seed = val.whole("seed", seed, 0, None)
    data = [_GearData(label, spec, m) for label, spec, m in sets]
    names = list(dict.fromkeys(val.names("parameters", parameters, one=True)))
    cands = _candidates(data[0].spec, names)
    lo = np.array([c.lower for c in cands])
    hi = np.array([c.upper for c in cands])
    null = np.clip(np.array([c.null for c in cands]), lo, hi)
    run = _Design(data, names, penalty, 1 + n_design + rounds * n_refine, progress)
    run.evaluate(null, "baseline")
    for x in _sobol(lo, hi, n_design, seed):
        run.evaluate(x, "design")
    for k in range(rounds):
        half = REFINE_HALF_WIDTH * (hi - lo) / (2.0**k)
        best = run.best()[0]
        for x in _sobol(np.maximum(lo, best - half), np.minimum(hi, best + half), n_refine,
                        seed + 1 + k):  # fmt: skip
            run.evaluate(x, f"refine {k + 1}")
    for k in range(EXPLORE_ROUNDS if n_refine else 0):
        box = _region_box(run, lo, hi)
        if box is None:
            break
        for x in _sobol(box[0], box[1], n_refine, seed + 100 + k):
            run.evaluate(x, f"explore {k + 1}")
    return _result(run, cands, lo, hi, null, (n_design, n_refine, rounds))


def _region_box(run: _Design, lo: np.ndarray, hi: np.ndarray) -> Optional[tuple]:
    """The box to explore next around the points within the 95 %
    threshold: their extent widened by half of it (at least a 64th of each
    bound span) on either side, within the bounds; None when the last
    exploration did not widen the extent by a tenth in any input."""
    thetas = np.array([p[0] for p in run.points])
    chis = np.array([p[1] for p in run.points])
    chi_min = float(chis.min())
    n = sum(len(d.y) for d in run.data)
    phi = max(1.0, chi_min / max(n - len(run.names), 1))
    inside = thetas[chis <= chi_min + _CHI2_95 * phi]
    a, b = inside.min(axis=0), inside.max(axis=0)
    if run.extent is not None:
        grown = ((run.extent[0] - a) + (b - run.extent[1])) > 0.1 * np.maximum(
            run.extent[1] - run.extent[0], (hi - lo) / 64.0
        )
        if not grown.any():
            return None
    run.extent = (a, b)
    w = np.maximum(b - a, (hi - lo) / 64.0)
    return np.maximum(lo, a - 0.5 * w), np.minimum(hi, b + 0.5 * w)


class _Design:
    """The evaluated points of a gear calibration: each a vector of the
    inputs with its chi^2 and stage."""

    def __init__(self, data: list, names: list, penalty: float, total: int, progress: Any):
        self.data, self.names, self.penalty = data, names, penalty
        self.total, self.progress = total, progress
        self.points: list[tuple[np.ndarray, float, str]] = []
        #: The extent of the points within the 95 % threshold at the last
        #: exploration (lower and upper corner), None before the first.
        self.extent: Optional[tuple[np.ndarray, np.ndarray]] = None

    def values(self, theta: np.ndarray) -> dict[str, float]:
        return dict(zip(self.names, (float(x) for x in theta), strict=True))

    def evaluate(self, theta: np.ndarray, stage: str) -> float:
        v = self.values(theta)
        r = np.concatenate([d.residual(d.predict(v), self.penalty) for d in self.data])
        chi = float(r @ r)
        self.points.append((np.array(theta, dtype=float), chi, stage))
        if self.progress is not None:
            self.progress(len(self.points), self.total)
        return chi

    def best(self) -> tuple[np.ndarray, float]:
        i = int(np.argmin([p[1] for p in self.points]))
        return self.points[i][0], self.points[i][1]


def _result(run: _Design, cands: list, lo: np.ndarray, hi: np.ndarray, null: np.ndarray,
            sizes: tuple[int, int, int]) -> Calibration:  # fmt: skip
    """The calibration of a finished design: estimate, intervals,
    covariance, the points before and after, the models."""
    import polars as pl

    from .calibrated import CalibratedModel, _Step, provenance

    names, data = run.names, run.data
    thetas = np.array([p[0] for p in run.points])
    chis = np.array([p[1] for p in run.points])
    theta, chi_min = run.best()
    n, p = sum(len(d.y) for d in data), len(names)
    phi = max(1.0, chi_min / max(n - p, 1))
    inside = chis <= chi_min + _CHI2_95 * phi
    intervals = [(float(thetas[inside, j].min()), float(thetas[inside, j].max())) for j in range(p)]
    bowl = _bowl(thetas, chis, theta, lo, hi, n - p)
    cov = bowl if bowl is not None else _weighted_covariance(thetas, chis, chi_min, phi, intervals)
    # the bowl's width (or the design's weighted spread) beside the points inside
    sd = np.sqrt(np.diag(cov))
    intervals = [(float(max(lo[j], min(a, theta[j] - 1.96 * sd[j]))),
                  float(min(hi[j], max(b, theta[j] + 1.96 * sd[j]))))
                 for j, (a, b) in enumerate(intervals)]  # fmt: skip
    weak = [nm for j, nm in enumerate(names) if intervals[j][1] - intervals[j][0]
            >= 0.9 * (hi[j] - lo[j])]  # fmt: skip
    table = pl.DataFrame(
        [(nm, "all", float(theta[j]), intervals[j][0], intervals[j][1], float(lo[j]),
          float(hi[j]), float(null[j]),
          bool(min(theta[j] - lo[j], hi[j] - theta[j]) < 0.01 * (hi[j] - lo[j])),
          nm not in weak)
         for j, nm in enumerate(names)],
        schema=["name", "set", "value", "lower_95", "upper_95", "lower", "upper", "null",
                "at_bound", "identified"],
        orient="row",
    )  # fmt: skip
    points = pl.concat(
        d.df.with_columns(pl.lit(d.label).alias("set"),
                          pl.Series("model_before", d.predict(run.values(null))),
                          pl.Series("model_after", d.predict(run.values(theta))))
        for d in data
    )  # fmt: skip
    n_design, n_refine, rounds = sizes
    notes = [
        f"design of experiments: {len(run.points)} evaluated points ({n_design} coarse, "
        f"{rounds} x {n_refine} refining, then exploring the region within the 95 % threshold); "
        f"{int(inside.sum())} within it",
        "the chi^2 of transition speeds is rough: the intervals are local (the bowl around the "
        "estimate and the points inside the threshold); islands elsewhere that the design did "
        "not find may fit as well",
    ]
    notes += [f"not identified by these data: {', '.join(weak)}"] if weak else []
    chi_before = run.points[0][1]
    result = Calibration(table, chi_min, chi_before, n, phi, float("nan"), weak, points, notes)
    prov = provenance([d.label for d in data], [d.df for d in data], "gear calibration")
    steps = [_Step(nm, c) for nm, c in zip(names, cands, strict=True)]
    result._models = {
        d.label: CalibratedModel("calibration", f"{', '.join(names)} on {d.label}", d.spec,
                                 steps, theta, cov, intervals, provenance=prov)
        for d in data
    }  # fmt: skip
    result.design = pl.DataFrame(
        {**{nm: thetas[:, j] for j, nm in enumerate(names)}, "chi2": chis,
         "stage": [q[2] for q in run.points], "within_95": inside},
    )  # fmt: skip
    return result


def transition_chi2(
    spec: Any, measured: Any, values: dict[str, float], penalty_rpm: float = PENALTY_RPM
) -> float:
    """The chi^2 a gear calibration minimises, of ``measured`` (a gear
    measurement table) for ``spec`` with the inputs ``values``: the capped
    residuals of the module docstring, sigma with the sweep grid's
    resolution."""
    d = _GearData("", spec, measured)
    r = d.residual(d.predict(values), penalty_rpm)
    return float(r @ r)


def _candidates(spec: Any, names: list[str]) -> list[Any]:
    from .gear_spec import GEAR_PARAMETERS

    pool = {c.name: c for c in spec.candidate_list()}
    out = []
    for nm in names:
        if nm not in pool:
            raise ConfigError(
                f"invalid parameter = {nm!r}: a gear pair's calibratable inputs are "
                f"{', '.join(GEAR_PARAMETERS)}"
            )
        out.append(pool[nm])
    if not names:
        raise ConfigError("invalid parameters = []: name at least one input")
    return out


def _sobol(lo: np.ndarray, hi: np.ndarray, n: int, seed: int) -> np.ndarray:
    """``n`` scrambled Sobol points in the box [lo, hi] (reproducible by
    ``seed``)."""
    from scipy.stats import qmc

    if n == 0:
        return np.zeros((0, len(lo)))
    u = qmc.Sobol(len(lo), scramble=True, seed=seed).random(n)
    return lo + u * (hi - lo)


def _bowl(
    thetas: np.ndarray, chis: np.ndarray, best: np.ndarray, lo: np.ndarray, hi: np.ndarray,
    dof: int,
) -> Optional[np.ndarray]:  # fmt: skip
    """The covariance of the chi^2 bowl around the estimate: a quadratic
    surface c + g'u + u'Hu/2 fitted by least squares to the evaluated
    points within the first refinement box (u the inputs' offsets over
    their bound spans; a box twice as wide when that gives no bowl), its
    curvature giving ``2 phi H^-1`` with phi = max(1, the bowl's least
    value / ``dof``): the trend of a rough chi^2 under its roughness, which
    the few points inside the threshold resolve poorly. Where the full
    surface is no bowl (H not positive definite), a surface without the
    cross terms (each input's own curvature); an input curving the wrong
    way there gets the variance of a uniform spread over its bounds (the
    data do not hold it near the estimate). None when too few points lie in
    the box."""
    span = hi - lo
    u = (thetas - best) / span
    p = len(best)
    for half in (REFINE_HALF_WIDTH, 2.0 * REFINE_HALF_WIDTH):
        near = np.all(np.abs(u) <= half, axis=1)
        for cross in (True, False):
            pairs = np.triu_indices(p) if cross else (np.arange(p), np.arange(p))
            if near.sum() < 2 * (1 + p + len(pairs[0])):
                continue
            got = _quadratic_bowl(u[near], chis[near], pairs, dof, strict=cross)
            if got is not None:
                return got * np.outer(span, span)
    return None


def _quadratic_bowl(
    x: np.ndarray, chis: np.ndarray, pairs: tuple, dof: int, strict: bool
) -> Optional[np.ndarray]:
    """``2 phi H^-1`` of the quadratic least-squares surface through
    (``x``, ``chis``) with the curvature terms ``pairs`` (index pairs of
    H); ``strict``: None unless H is positive definite; else (a diagonal
    H) an input with a curvature that is not positive gets the variance of
    a uniform spread over the unit span, 1/12."""
    p = x.shape[1]
    quad = np.stack(
        [x[:, i] * x[:, j] * (0.5 if i == j else 1.0) for i, j in zip(*pairs, strict=True)],
        axis=1,
    )
    design = np.hstack([np.ones((len(x), 1)), x, quad])
    coef, *_ = np.linalg.lstsq(design, chis, rcond=None)
    h = np.zeros((p, p))
    h[pairs] = coef[1 + p :]
    h = h + np.triu(h, 1).T
    g = coef[1 : 1 + p]
    if strict:
        try:
            np.linalg.cholesky(h)
        except np.linalg.LinAlgError:
            return None
        u0 = -np.linalg.solve(h, g)
        floor = float(coef[0] + g @ u0 + 0.5 * u0 @ h @ u0)
        return 2.0 * max(1.0, floor / max(dof, 1)) * np.linalg.inv(h)
    d = np.diag(h)
    ok = d > 0.0
    u0 = np.where(ok, -g / np.where(ok, d, 1.0), 0.0)
    floor = float(coef[0] + g @ u0 + 0.5 * np.sum(d * u0 * u0 * ok))
    phi = max(1.0, floor / max(dof, 1))
    return np.diag(np.where(ok, 2.0 * phi / np.where(ok, d, 1.0), 1.0 / 12.0))


def _weighted_covariance(
    thetas: np.ndarray, chis: np.ndarray, chi_min: float, phi: float,
    intervals: Sequence[tuple[float, float]],
) -> np.ndarray:  # fmt: skip
    """The covariance of the evaluated points weighted by their likelihood
    at the stretched sigmas, each standard deviation at least (upper -
    lower) / 3.92 of its 95 % interval (the correlations kept)."""
    w = np.exp(-(chis - chi_min) / (2.0 * phi))
    w = w / w.sum()
    d = thetas - w @ thetas
    cov = (d * w[:, None]).T @ d
    sd = np.sqrt(np.clip(np.diag(cov), 0.0, None))
    safe = np.where(sd > 0.0, sd, 1.0)
    corr = np.where(np.outer(sd > 0.0, sd > 0.0), cov / np.outer(safe, safe), 0.0)
    np.fill_diagonal(corr, 1.0)
    floor = np.array([(b - a) / 3.92 for a, b in intervals])
    sd = np.maximum(sd, floor)
    return corr * np.outer(sd, sd)


__all__ = ["calibrate_gear", "transition_chi2"]
