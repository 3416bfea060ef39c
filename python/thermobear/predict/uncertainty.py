"""Parameter uncertainty of a prediction: the delta method (linearised:
central finite differences, variance g^T C g) and quasi-random sampling
(scrambled Sobol points through the normal of the estimates, clipped to the
bounds, empirical quantiles).

A calibrated value the data do not identify (non-finite variance) is given
the variance of a uniform distribution over its bounds, (upper - lower)^2 /
12, uncorrelated with the others: the bounds are then all that is known of
it."""

from __future__ import annotations

import warnings
from dataclasses import dataclass
from typing import Any, Callable

import numpy as np

from ..errors import ConfigError, DataError, ThermobearError

#: Finite-difference step of the delta method, in standard deviations of
#: each calibrated value: small enough for the slope at the estimate, large
#: enough to stay far above the solver's convergence tolerance.
DELTA_STEP_STD = 0.1

#: The most sample runs that may fail (e.g. thermal runaway at an extreme
#: sample) before a sampled band is refused, as a fraction of the samples.
MAX_FAILED_FRACTION = 0.1


@dataclass(frozen=True)
class Parameters:
    """The calibrated values of a model: names, estimates, covariance and
    bounds (lower, upper)."""

    names: tuple[str, ...]
    values: np.ndarray
    covariance: np.ndarray
    lower: np.ndarray
    upper: np.ndarray

    @property
    def std(self) -> np.ndarray:
        return np.sqrt(np.clip(np.diag(self.covariance), 0.0, None))

    def root(self) -> np.ndarray:
        """A square root ``L`` of the covariance (``L L^T = C``): the
        Cholesky factor, or the symmetric root when C is singular."""
        c = self.covariance
        try:
            return np.linalg.cholesky(c)
        except np.linalg.LinAlgError:
            w, v = np.linalg.eigh(0.5 * (c + c.T))
            return v * np.sqrt(np.clip(w, 0.0, None))


def parameters_of(model: Any) -> Parameters:
    """The calibrated values of a calibrated model (``names``, ``values``,
    ``covariance`` and the bounds of ``intervals``)."""
    names = tuple(str(n) for n in getattr(model, "names", ()))
    p = len(names)
    values = np.asarray(getattr(model, "values", np.zeros(0)), dtype=float).reshape(p)
    cov = np.asarray(getattr(model, "covariance", np.zeros((0, 0))), dtype=float).reshape(p, p)
    lower, upper = _bounds(model, names)
    cov = cov.copy()
    for j in range(p):
        if not np.isfinite(cov[j, j]):
            span = upper[j] - lower[j]
            if not np.isfinite(span):
                raise DataError(
                    f"invalid covariance of {names[j]}: not finite and the value has no bounds"
                )
            cov[j, :] = 0.0
            cov[:, j] = 0.0
            cov[j, j] = span * span / 12.0
    if not np.all(np.isfinite(cov)):
        raise DataError("invalid covariance: non-finite entries")
    return Parameters(names, values, 0.5 * (cov + cov.T), lower, upper)


def _bounds(model: Any, names: tuple[str, ...]) -> tuple[np.ndarray, np.ndarray]:
    lo = np.full(len(names), -np.inf)
    hi = np.full(len(names), np.inf)
    table = getattr(model, "intervals", None)
    if table is None or not names or "lower" not in getattr(table, "columns", ()):
        return lo, hi
    by_name = {str(r["name"]): r for r in table.iter_rows(named=True)}
    for j, n in enumerate(names):
        r = by_name.get(n)
        if r is not None and r["lower"] is not None and r["upper"] is not None:
            lo[j], hi[j] = float(r["lower"]), float(r["upper"])
    return lo, hi


Outputs = Callable[[np.ndarray], np.ndarray]


def delta_band(
    f: Outputs, par: Parameters, z: float
) -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray]:
    """Value, lower and upper bound and standard deviation of every output
    of ``f`` by the delta method: the gradient by central differences of
    ``DELTA_STEP_STD`` standard deviations (one-sided at a bound), variance
    g^T C g, band value +- z sd."""
    theta = par.values
    y0 = f(theta)
    grad = np.zeros((len(theta), y0.size))
    for j, s in enumerate(par.std):
        if s == 0.0:
            continue
        h = DELTA_STEP_STD * s
        up = min(h, par.upper[j] - theta[j])
        dn = min(h, theta[j] - par.lower[j])
        yp = f(_moved(theta, j, up)) if up > 0.0 else y0
        ym = f(_moved(theta, j, -dn)) if dn > 0.0 else y0
        width = max(up, 0.0) + max(dn, 0.0)
        if width > 0.0:
            grad[j] = (yp - ym) / width
    var = np.einsum("im,ij,jm->m", grad, par.covariance, grad)
    sd = np.sqrt(np.clip(var, 0.0, None))
    return y0, y0 - z * sd, y0 + z * sd, sd


def _moved(theta: np.ndarray, j: int, step: float) -> np.ndarray:
    t = theta.copy()
    t[j] += step
    return t


def sobol_points(par: Parameters, samples: int, seed: int) -> np.ndarray:
    """``samples`` parameter vectors: scrambled Sobol points (seeded) mapped
    through the normal of the estimates (``norm.ppf``, then the covariance
    root), clipped to the bounds; shape (samples, p)."""
    from scipy.stats import norm, qmc

    p = len(par.values)
    if p == 0:
        return np.zeros((samples, 0))
    sobol = qmc.Sobol(d=p, scramble=True, rng=np.random.default_rng(seed))
    with warnings.catch_warnings():  # a sample count not a power of 2 is fine here
        warnings.simplefilter("ignore", UserWarning)
        u = sobol.random(samples)
    z = norm.ppf(np.clip(u, 1e-12, 1.0 - 1e-12))
    theta = par.values + z @ par.root().T
    return np.clip(theta, par.lower, par.upper)


def sampling_band(
    f: Outputs, par: Parameters, level: float, samples: int, seed: int
) -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray]:
    """Value (at the estimates), lower and upper bound (the empirical
    quantiles (1 -+ level) / 2 over the Sobol samples) and the sample
    standard deviation of every output of ``f``."""
    y0 = f(par.values)
    runs, failed = [], 0
    for theta in sobol_points(par, samples, seed):
        try:
            runs.append(f(theta))
        except ThermobearError:
            failed += 1
    return sampled_quantiles(y0, runs, failed, level)


def sampled_quantiles(
    y0: np.ndarray, runs: list, failed: int, level: float
) -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray]:
    """``y0`` and the quantile band and standard deviation of the sample
    ``runs`` (``failed`` more samples failed; too many refuse the band)."""
    samples = len(runs) + failed
    if failed > MAX_FAILED_FRACTION * samples or len(runs) < 2:
        raise ThermobearError(
            f"sampled band: the model failed at {failed} of {samples} samples of the "
            "calibrated values; use method='delta' or check the calibration"
        )
    y = np.vstack(runs)
    a = 0.5 * (1.0 - level)
    if np.isnan(y).any():  # an output some samples lack (a gear's transition)
        with warnings.catch_warnings():
            warnings.simplefilter("ignore", RuntimeWarning)
            lower, upper = np.nanquantile(y, [a, 1.0 - a], axis=0)
            return y0, lower, upper, np.nanstd(y, axis=0, ddof=1)
    lower, upper = np.quantile(y, [a, 1.0 - a], axis=0)
    return y0, lower, upper, y.std(axis=0, ddof=1)


#: The band probabilities a prediction accepts (docs page "Limits"): below
#: 0.5 a band holds less than half the outcomes and is no uncertainty band;
#: above 0.999 its edges are the far tails, which neither the linearised
#: (delta) band nor a sampled band of a few thousand runs resolves.
LEVEL_RANGE = (0.5, 0.999)


def check_level(level: float) -> float:
    """``level`` as a float in ``LEVEL_RANGE``, [0.5, 0.999]."""
    from .. import _validate

    lo, hi = LEVEL_RANGE
    lv = _validate.real("level", level, 0.0, 1.0, open_lo=True)
    if not lo <= lv <= hi:
        raise ConfigError(
            f"invalid level = {level!r}: a probability in [{lo:g}, {hi:g}], e.g. 0.95 (a band "
            "below 0.5 is no uncertainty band; above 0.999 its far tails are not resolved)"
        )
    return lv
