"""Joint calibration ([`calibrate`][thermobear.calibrate]): several data sets at once -- rigs
(each its own model spec), runs, load levels, quantities -- with parameters
shared by every set or one value per set; up to four candidates calibrated
together by bounded least squares on the models themselves, with
profile-likelihood intervals and an identifiability check.

Intervals: for each calibrated value, the range where the profile chi^2 (the
others re-calibrated at each trial value) stays within 3.84 phi of the
minimum, phi = max(1, chi^2 / (n - p)) (the reduced chi^2: the stated sigmas
are stretched when the fit says they are too small).

Identifiability: the Fisher information F = J^T J of the residual/sigma
against the parameters scaled to their bound spans, in correlation form
(unit diagonal). A parameter no data point moves (a zero diagonal), or with
a large share (|v| > 0.3) of an eigenvector whose eigenvalue is below 1e-6
of the largest (a combination the data cannot see: condition number above
1e6), or whose profile interval spans both bounds, is reported as not
identified."""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any, Optional, Protocol, Sequence

import numpy as np

from .. import _validate as val
from ..errors import ConfigError, ThermobearError
from ..plausibility import warn
from .calibrated import calibration_models
from .calibration import Calibration
from .measurements import prepare_measurements
from .protocol import as_spec
from .setting import _predict, _Setting
from .statistics import COND_MAX, fisher_identifiability

#: Most distinct candidates calibrated together.
MAX_JOINT = 4
#: The weighted residual of every point where the model fails at trial
#: values inside the bounds (a spindle's thermal runaway at the largest
#: friction): a misfit of a million sigmas, so the fit steps back from there.
FAILED_RESIDUAL = 1e6
_CHI2_95 = 3.841


@dataclass(frozen=True)
class _Slot:
    """One calibrated value: the candidate (per set, by set index) and the
    sets it acts on."""

    name: str
    label: str
    cands: dict  # set index -> Candidate

    @property
    def bounds(self) -> tuple[float, float]:
        c = next(iter(self.cands.values()))
        return c.lower, c.upper


def _sets(datasets) -> list[tuple[str, Any, Any]]:
    if not isinstance(datasets, (dict, list, tuple)):
        raise val.fail("datasets", datasets, "a list or dict of (model, measured) pairs")
    items = datasets.items() if isinstance(datasets, dict) else enumerate(datasets)
    out = []
    for label, pair in items:
        if not isinstance(pair, (tuple, list)) or len(pair) != 2:
            raise ConfigError(f"invalid datasets[{label!r}] = {pair!r}: give (model, measured)")
        out.append((str(label), as_spec(pair[0]), pair[1]))
    if not out:
        raise ConfigError("invalid datasets = []: give at least one (model, measured) pair")
    return out


def _slots(sets, data, parameters, per_set) -> list[_Slot]:
    """The calibrated values: a shared parameter is one slot over every set,
    a per-set one a slot per set."""
    names = list(dict.fromkeys(parameters))
    if not 1 <= len(names) <= MAX_JOINT:
        raise ConfigError(f"invalid parameters = {names}: give 1 to {MAX_JOINT} candidate names")
    for p in per_set:
        if p not in names:
            raise ConfigError(f"invalid per_set = {p!r}: not among parameters {names}")
    found = []
    for i, (label, spec, _) in enumerate(sets):
        pool = {c.name: c for c in spec.candidate_list(sorted(set(data[i].quantity.tolist())))}
        for n in names:
            c = pool.get(n)
            if c is None or c.kind != "parameter":
                raise ConfigError(
                    f"invalid parameter = {n!r} for data set {label!r}: not a calibratable "
                    "candidate of its model"
                )
        found.append(pool)
    slots = []
    for n in names:
        if n in per_set:
            slots += [_Slot(n, sets[i][0], {i: found[i][n]}) for i in range(len(sets))]
        else:
            slots.append(_Slot(n, "all", {i: found[i][n] for i in range(len(sets))}))
    return slots


class _Fittable(Protocol):
    """What ``_least_squares`` and ``_profile`` read of a problem: the
    bounds of the values and the residual/sigma against them."""

    lo: np.ndarray
    hi: np.ndarray

    def resid(self, theta: np.ndarray) -> np.ndarray: ...

    def chi2(self, theta: np.ndarray) -> float: ...


class _Problem:
    """The stacked residual of every set against the calibrated values."""

    def __init__(self, sets, data, slots):
        self.sets, self.data, self.slots = sets, data, slots
        self.lo = np.array([s.bounds[0] for s in slots])
        self.hi = np.array([s.bounds[1] for s in slots])
        self.null = np.array([next(iter(s.cands.values())).null for s in slots])

    def predict(self, theta) -> list[np.ndarray]:
        out = []
        for i, (_, spec, _) in enumerate(self.sets):
            st, opts = _Setting(), dict(spec.options)
            for s, v in zip(self.slots, theta, strict=True):
                if i in s.cands:
                    st = st.apply(s.cands[i], float(v), opts)
            d = self.data[i]
            out.append(_predict(spec, st, d.cond, d.quantity))
        return out

    def resid(self, theta) -> np.ndarray:
        try:
            pred = self.predict(theta)
        except ThermobearError:  # the model fails at these values (a thermal runaway)
            return np.full(sum(d.n for d in self.data), FAILED_RESIDUAL)
        return np.concatenate([(d.y - p) / d.s for d, p in zip(self.data, pred, strict=True)])

    def chi2(self, theta) -> float:
        r = self.resid(theta)
        return float(r @ r)


def _least_squares(prob: _Fittable, x0, free: np.ndarray, fixed: np.ndarray):
    """Bounded least squares over the ``free`` slots (the others at
    ``fixed``); returns (theta, chi^2, jacobian)."""
    from scipy.optimize import least_squares

    def full(x):
        t = fixed.copy()
        t[free] = x
        return t

    lo, hi = prob.lo[free], prob.hi[free]
    start = np.clip(x0[free], lo + 1e-9 * (hi - lo), hi - 1e-9 * (hi - lo))
    res = least_squares(
        lambda x: prob.resid(full(x)), start, bounds=(lo, hi), x_scale=hi - lo,
        diff_step=1e-5, max_nfev=80 * (1 + int(free.sum())),
    )  # fmt: skip
    return full(res.x), 2.0 * float(res.cost), res.jac


def _best_fit(prob: _Problem):
    """The least-chi^2 values from two starts (the baseline's values and
    the middle of the bounds)."""
    allfree = np.ones(len(prob.slots), dtype=bool)
    best = None
    for x0 in (prob.null, 0.5 * (prob.lo + prob.hi)):
        try:
            fit = _least_squares(prob, x0, allfree, x0.copy())
        except ThermobearError:
            continue
        if best is None or fit[1] < best[1]:
            best = fit
    if best is None:
        raise ThermobearError("joint calibration: the model fails at every start")
    return best


def _profile(prob: _Fittable, theta, chi_min, j, thr, halfwidth=None) -> tuple[float, float]:
    """The 95 % profile-likelihood interval of slot ``j``: the others
    re-calibrated at each trial value; an edge is the bound when the
    profile stays below the threshold up to it. ``halfwidth``: a guess of
    the interval's half width (e.g. 1.96 standard errors): the root is
    first bracketed 1.5 guesses out, which saves profile evaluations."""
    from scipy.optimize import brentq

    free = np.ones(len(theta), dtype=bool)
    free[j] = False

    def excess(t: float) -> float:
        fixed = theta.copy()
        fixed[j] = t
        if free.any():
            chi = _least_squares(prob, theta, free, fixed)[1]
        else:
            chi = prob.chi2(fixed)
        return chi - chi_min - thr

    edges = []
    tol = 1e-4 * (prob.hi[j] - prob.lo[j])
    for sign, bound in ((-1.0, prob.lo[j]), (1.0, prob.hi[j])):
        inner = theta[j]
        if halfwidth is not None and np.isfinite(halfwidth) and halfwidth > 0.0:
            guess = theta[j] + sign * 1.5 * halfwidth
            if (guess - bound) * sign < 0.0:  # strictly inside the bounds
                if excess(guess) > 0.0:
                    edges.append(float(brentq(excess, theta[j], guess, xtol=tol)))
                    continue
                inner = guess
        if abs(bound - inner) <= 1e-12 or excess(bound) <= 0.0:
            edges.append(float(bound))
            continue
        edges.append(float(brentq(excess, inner, bound, xtol=tol)))
    return edges[0], edges[1]


def _enough_points(names: list[str], n: int, p: int) -> None:
    """Refuse a fit of ``p`` values from fewer than ``p`` measured points."""
    if n < p:
        raise ConfigError(
            f"invalid parameters = {names!r}: {p} value(s) to calibrate from {n} measured "
            "point(s); a fit needs at least as many points as values (measure more, or "
            "calibrate fewer)"
        )


def _warn_ill_conditioned(names: list[str], cond: float) -> None:
    """Warn when the Fisher information's condition number passes ``COND_MAX``."""
    if not cond <= COND_MAX:
        warn(
            f"parameters = {names!r}: the fit is ill-conditioned (condition number {cond:.3g} "
            f"of the Fisher information, past {COND_MAX:g}): these data cannot pin every "
            "value; see the calibration's not_identified"
        )


def calibrate(
    datasets,
    parameters: Sequence[str],
    per_set: Sequence[str] = (),
    *,
    design_points: Optional[int] = None,
    refine_points: Optional[int] = None,
    refine_rounds: Optional[int] = None,
    penalty_rpm: Optional[float] = None,
    seed: int = 0,
    progress: Any = None,
) -> Calibration:
    """Calibrate up to four candidates (names from
    [`candidates`][thermobear.diagnosis.candidates.candidates] of
    each set's model: parameters, not switches) on several data sets at
    once. ``datasets``: a list or a dict (label -> pair) of ``(model,
    measured)`` pairs -- a model spec (one per rig; the same spec for runs or
    load levels of one rig; a [`Bearing`][thermobear.Bearing] or
    [`Spindle`][thermobear.Spindle] stands for its spec as configured) and anything
    [`load_measurements`][thermobear.load_measurements] reads;
    ``per_set``: the names calibrated with a value of their own in each set
    (e.g. a sensor offset per run), the others shared by all sets. Returns a
    [`Calibration`][thermobear.Calibration] (see the module docstring for the statistics).

    A gear pair ([`GearModelSpec`][thermobear.GearModelSpec], or a
    [`GearPair`][thermobear.GearPair] for its spec with the defaults) is
    calibrated on transition speeds of its bifurcation diagram by a design
    of experiments and its refinement, up to four inputs
    (``thermobear.diagnosis.gear_calibration``): ``design_points``,
    ``refine_points``, ``refine_rounds``, ``penalty_rpm``, ``seed`` and
    ``progress(done, total)`` set it (they apply to gear pairs only); the
    result's ``design`` holds every evaluated point."""
    sets = _sets(datasets)
    gear = [_is_gear(spec) for _, spec, _ in sets]
    if any(gear):
        if not all(gear):
            raise ConfigError("invalid datasets: a gear pair cannot share a calibration with "
                              "a bearing or spindle")  # fmt: skip
        if per_set:
            raise ConfigError(f"invalid per_set = {list(per_set)!r}: a gear calibration shares "
                              "every input")  # fmt: skip
        from .gear_calibration import calibrate_gear

        return calibrate_gear(
            sets, parameters, design_points=design_points, refine_points=refine_points,
            refine_rounds=refine_rounds, penalty_rpm=penalty_rpm, seed=seed, progress=progress,
        )  # fmt: skip
    for name, v in (("design_points", design_points), ("refine_points", refine_points),
                    ("refine_rounds", refine_rounds), ("penalty_rpm", penalty_rpm),
                    ("progress", progress)):  # fmt: skip
        if v is not None:
            raise ConfigError(f"invalid {name} = {v!r}: a setting of a gear pair's calibration")
    data = [prepare_measurements(m, spec.quantities, None) for _, spec, m in sets]
    names = val.names("parameters", parameters, one=True)
    slots = _slots(sets, data, names, val.names("per_set", per_set, one=True))
    n, p = sum(d.n for d in data), len(slots)
    _enough_points(names, n, p)
    prob = _Problem(sets, data, slots)
    chi_before = prob.chi2(prob.null)
    theta, chi_min, jac = _best_fit(prob)
    phi = max(1.0, chi_min / max(n - p, 1))
    cond, weak = fisher_identifiability(jac, prob.hi - prob.lo)
    _warn_ill_conditioned(names, cond)
    intervals = [_profile(prob, theta, chi_min, j, _CHI2_95 * phi) for j in range(p)]
    for j, (a, b) in enumerate(intervals):
        if a <= prob.lo[j] and b >= prob.hi[j]:
            weak.add(j)
    result = _result(prob, theta, intervals, weak, (chi_min, chi_before, n, phi, cond))
    models = calibration_models(prob, theta, jac, intervals, phi)
    result._models = {label: m for (label, _, _), m in zip(prob.sets, models, strict=True)}
    return result


def _is_gear(spec: Any) -> bool:
    from .gear_spec import GearModelSpec

    return isinstance(spec, GearModelSpec)


def _result(prob: _Problem, theta, intervals, weak, stats) -> Calibration:
    import polars as pl

    chi_min, chi_before, n, phi, cond = stats
    span = prob.hi - prob.lo
    rows = [
        (s.name, s.label, float(theta[j]), intervals[j][0], intervals[j][1],
         float(prob.lo[j]), float(prob.hi[j]), float(prob.null[j]),
         bool(min(theta[j] - prob.lo[j], prob.hi[j] - theta[j]) < 0.01 * span[j]),
         j not in weak)
        for j, s in enumerate(prob.slots)
    ]  # fmt: skip
    table = pl.DataFrame(
        rows,
        schema=["name", "set", "value", "lower_95", "upper_95", "lower", "upper", "null",
                "at_bound", "identified"],
        orient="row",
    )  # fmt: skip
    before, after = prob.predict(prob.null), prob.predict(theta)
    points = pl.concat(
        d.df.with_columns(
            pl.lit(label).alias("set"), pl.Series("model_before", b), pl.Series("model_after", a)
        )
        for (label, _, _), d, b, a in zip(prob.sets, prob.data, before, after, strict=True)
    )
    bad = sorted({f"{prob.slots[j].name}@{prob.slots[j].label}" for j in weak})
    notes = [f"not identified by these data: {', '.join(bad)}"] if bad else []
    return Calibration(table, chi_min, chi_before, n, phi, cond, bad, points, notes)
