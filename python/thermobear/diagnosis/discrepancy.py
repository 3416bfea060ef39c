"""The unknown smooth term of an "unresolved" verdict as a model discrepancy
(the discrepancy function of Kennedy and O'Hagan's calibration): a
zero-mean Gaussian process in speed, one per measured quantity, fitted to
the residual ``measured - model`` on the training points.

The input is the speed over the highest training speed, ``x = n / n_top``
(the generic control's own variable). The covariance of the unknown term
between two speeds is ``a^2 (x x')^p k(|x - x'| / l)``, ``k`` the squared
exponential ``exp(-d^2 / 2)`` or the Matern 5/2 ``(1 + sqrt5 d + 5 d^2 / 3)
exp(-sqrt5 d)``: the prior standard deviation ``a x^p`` grows with speed
as a speed-driven effect does (zero at standstill for ``p > 0``; ``p = 0``
a term of the same size at every speed). Each measured value adds its own
noise ``sigma^2``. With
``K`` the training points' covariance plus ``diag(sigma^2)``, ``r`` their
residuals and ``k*`` the covariance of a new speed with them:

* mean ``m(x*) = k*^T K^-1 r`` (it passes through the residuals as far as
  their sigmas allow);
* variance ``v(x*) = a^2 x*^(2p) - k*^T K^-1 k*`` (about zero at a well
  measured speed, back to the prior ``a^2 x*^(2p)`` far from every
  measured one).

The amplitude ``a``, the length scale ``l`` and the speed power ``p``
maximise the marginal likelihood ``log p(r) = -r^T K^-1 r / 2 - log|K| / 2
- n log(2 pi) / 2`` within bounds (``hyperparameter_bounds``): ``l``
between half the smallest spacing of the measured speeds and
``MAX_LENGTH_SCALE``, so the term never correlates farther than the
measured range and its band widens beyond it instead of continuing a
trend; ``p`` from 0 to ``MAX_SPEED_POWER``.

Everything here is a small pure function of plain arrays; the fitted term
is a plain dict (JSON), the form a ``CalibratedModel`` saves."""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any, Literal, Optional, Sequence

import numpy as np

from ..errors import ConfigError

Kernel = Literal["squared_exponential", "matern52"]
KERNELS: tuple[str, ...] = ("squared_exponential", "matern52")

#: The kernel of the discrepancy a diagnosis fits: Matern 5/2 (twice
#: differentiable paths; less sure of itself between and beyond the
#: measured speeds than the squared exponential's infinitely smooth ones).
DEFAULT_KERNEL: Kernel = "matern52"

#: The longest length scale allowed, in units of the highest training
#: speed: the unknown term may correlate over the measured range, no
#: farther (a longer scale would extrapolate the trend as a polynomial).
MAX_LENGTH_SCALE = 1.0

#: The highest speed power ``p`` of the prior standard deviation: the
#: steepest speed law among the bearing's losses (drag and churning power
#: ~ n^3).
MAX_SPEED_POWER = 3.0

#: The fewest distinct training speeds a quantity needs for its term.
MIN_SPEEDS = 3

#: Starts of the bounded optimiser: length scales (fractions of the allowed
#: range, in logarithms) by speed powers. The likelihood can have several
#: maxima; the best of all wins.
_STARTS = tuple((f, p) for f in (0.15, 0.5, 0.85) for p in (0.5, 1.5, 2.5))


@dataclass(frozen=True)
class Hyperparameters:
    """Amplitude ``a`` (the quantity's unit), length scale ``l`` (units of
    the speed scale) and speed power ``p`` of the kernel."""

    amplitude: float
    length_scale: float
    speed_power: float = 0.0


def kernel_matrix(
    x1: Any, x2: Any, hp: Hyperparameters, kernel: Kernel = DEFAULT_KERNEL
) -> np.ndarray:
    """The covariance ``a^2 (x1_i x2_j)^p k(|x1_i - x2_j| / l)`` of the
    unknown term (see the module docstring)."""
    a = np.asarray(x1, dtype=float).reshape(-1, 1)
    b = np.asarray(x2, dtype=float).reshape(1, -1)
    d = np.abs(a - b) / float(hp.length_scale)
    if kernel == "squared_exponential":
        k = np.exp(-0.5 * d * d)
    elif kernel == "matern52":
        s5 = np.sqrt(5.0) * d
        k = (1.0 + s5 + s5 * s5 / 3.0) * np.exp(-s5)
    else:
        raise ConfigError(f"invalid kernel = {kernel!r}: one of {', '.join(KERNELS)}")
    p = float(hp.speed_power)
    return float(hp.amplitude) ** 2 * (np.abs(a) ** p) * (np.abs(b) ** p) * k


def prior_variance(x: Any, hp: Hyperparameters) -> np.ndarray:
    """The prior variance ``a^2 x^(2p)`` of the unknown term at ``x``."""
    xv = np.abs(np.asarray(x, dtype=float).ravel())
    return float(hp.amplitude) ** 2 * xv ** (2.0 * float(hp.speed_power))


def _factor(x: np.ndarray, sigma: np.ndarray, hp: Hyperparameters, kernel: Kernel) -> np.ndarray:
    """The Cholesky factor of the training covariance plus noise."""
    k = kernel_matrix(x, x, hp, kernel)
    k[np.diag_indices_from(k)] += sigma * sigma
    return np.linalg.cholesky(k)


def _arrays(*values: Any) -> list[np.ndarray]:
    return [np.asarray(v, dtype=float).ravel() for v in values]


def log_marginal_likelihood(
    x: Any, r: Any, sigma: Any, hp: Hyperparameters, kernel: Kernel = DEFAULT_KERNEL
) -> float:
    """``log p(r | a, l, p)`` of the residuals ``r`` at ``x`` with noise
    ``sigma`` (Rasmussen and Williams, eq. 2.30); -inf when the covariance
    is not positive definite."""
    xv, rv, sv = _arrays(x, r, sigma)
    try:
        chol = _factor(xv, sv, hp, kernel)
    except np.linalg.LinAlgError:
        return -np.inf
    alpha = np.linalg.solve(chol.T, np.linalg.solve(chol, rv))
    logdet = 2.0 * float(np.sum(np.log(np.diag(chol))))
    return float(-0.5 * rv @ alpha - 0.5 * logdet - 0.5 * rv.size * np.log(2.0 * np.pi))


def hyperparameter_bounds(x: Any, r: Any, sigma: Any) -> list[tuple[float, float]]:
    """[(amplitude low, high), (length low, high), (power low, high)]: the
    amplitude from 1e-6 to 100 times the larger of the largest residual and
    the smallest sigma; the length scale from half the smallest spacing of
    the distinct speeds (never below 0.01) to ``MAX_LENGTH_SCALE``; the
    speed power from 0 to ``MAX_SPEED_POWER``."""
    xv, rv, sv = _arrays(x, r, sigma)
    xu = np.unique(xv)
    scale = max(float(np.max(np.abs(rv))), float(np.min(sv)))
    gap = float(np.min(np.diff(xu))) if xu.size > 1 else MAX_LENGTH_SCALE
    lo = min(max(0.5 * gap, 0.01), 0.5 * MAX_LENGTH_SCALE)
    return [(1e-6 * scale, 1e2 * scale), (lo, MAX_LENGTH_SCALE), (0.0, MAX_SPEED_POWER)]


def fit_hyperparameters(
    x: Any, r: Any, sigma: Any, kernel: Kernel = DEFAULT_KERNEL
) -> tuple[Hyperparameters, float]:
    """The hyperparameters at the maximum of the marginal likelihood within
    ``hyperparameter_bounds`` and that maximum: L-BFGS-B in log amplitude,
    log length scale and power, from several starts (the best wins)."""
    from scipy.optimize import minimize

    xv, rv, sv = _arrays(x, r, sigma)
    (alo, ahi), (llo, lhi), pb = hyperparameter_bounds(xv, rv, sv)
    bounds = [(np.log(alo), np.log(ahi)), (np.log(llo), np.log(lhi)), pb]
    a0 = float(np.log(np.clip(max(float(np.std(rv)), float(np.min(sv))), alo, ahi)))

    def nll(q: np.ndarray) -> float:
        hp = Hyperparameters(float(np.exp(q[0])), float(np.exp(q[1])), float(q[2]))
        v = -log_marginal_likelihood(xv, rv, sv, hp, kernel)
        return v if np.isfinite(v) else 1e300

    best_f, best_q = np.inf, np.zeros(3)
    for f, p in _STARTS:
        start = np.array([a0, bounds[1][0] + f * (bounds[1][1] - bounds[1][0]), p])
        res = minimize(nll, start, method="L-BFGS-B", bounds=bounds)
        if float(res.fun) < best_f:
            best_f, best_q = float(res.fun), np.asarray(res.x, dtype=float)
    hp = Hyperparameters(float(np.exp(best_q[0])), float(np.exp(best_q[1])), float(best_q[2]))
    return hp, -best_f


def posterior(
    x: Any, r: Any, sigma: Any, hp: Hyperparameters, x_new: Any,
    kernel: Kernel = DEFAULT_KERNEL,
) -> tuple[np.ndarray, np.ndarray]:  # fmt: skip
    """The posterior mean and variance of the unknown term at ``x_new``
    given the residuals ``r`` at ``x`` with noise ``sigma`` (Rasmussen and
    Williams, eqs. 2.25-2.26; the variance of the term itself, without a
    new measurement's noise)."""
    xv, rv, sv = _arrays(x, r, sigma)
    xs = np.asarray(x_new, dtype=float).ravel()
    chol = _factor(xv, sv, hp, kernel)
    alpha = np.linalg.solve(chol.T, np.linalg.solve(chol, rv))
    ks = kernel_matrix(xv, xs, hp, kernel)
    w = np.linalg.solve(chol, ks)
    mean = ks.T @ alpha
    var = prior_variance(xs, hp) - np.sum(w * w, axis=0)
    return mean, np.clip(var, 0.0, None)


def fit_discrepancy(
    speeds_rpm: Any, quantity: Sequence[str], residual: Any, sigma: Any,
    kernel: Kernel = DEFAULT_KERNEL,
) -> dict:  # fmt: skip
    """The discrepancy term of every quantity with at least ``MIN_SPEEDS``
    distinct speeds among the rows (the training points): ``{"kernel",
    "speed_scale_rpm" (the highest speed), "terms": {quantity: {"amplitude",
    "length_scale" (in units of the speed scale), "speed_power",
    "log_marginal_likelihood", "speeds_rpm", "residuals", "sigmas"}}}`` --
    plain numbers, JSON as it is. ``residual``: measured - model, in the
    quantity's unit; ``sigma``: the measurements' standard deviations."""
    if kernel not in KERNELS:
        raise ConfigError(f"invalid kernel = {kernel!r}: one of {', '.join(KERNELS)}")
    sp, r, s = _arrays(speeds_rpm, residual, sigma)
    q = np.asarray(quantity, dtype=object).ravel()
    if not (sp.size == r.size == s.size == q.size) or np.any(~(s > 0.0)):
        raise ConfigError("invalid residuals: speeds, quantities, residuals and sigmas of one "
                          "length, sigmas > 0")  # fmt: skip
    top = float(sp.max()) if sp.size and sp.max() > 0.0 else 1.0
    terms: dict[str, dict] = {}
    for name in dict.fromkeys(q.tolist()):
        rows = q == name
        if np.unique(sp[rows]).size < MIN_SPEEDS:
            continue
        hp, lml = fit_hyperparameters(sp[rows] / top, r[rows], s[rows], kernel)
        terms[str(name)] = {
            "amplitude": hp.amplitude, "length_scale": hp.length_scale,
            "speed_power": hp.speed_power, "log_marginal_likelihood": lml,
            "speeds_rpm": sp[rows].tolist(), "residuals": r[rows].tolist(),
            "sigmas": s[rows].tolist(),
        }  # fmt: skip
    return {"kernel": kernel, "speed_scale_rpm": top, "terms": terms}


def discrepancy_at(
    fitted: dict, quantity: str, speeds_rpm: Any
) -> Optional[tuple[np.ndarray, np.ndarray]]:
    """(mean, variance) of the fitted term (``fit_discrepancy``) of
    ``quantity`` at ``speeds_rpm``, or None when the quantity has none."""
    term = (fitted.get("terms") or {}).get(quantity)
    if term is None:
        return None
    top = float(fitted["speed_scale_rpm"])
    x = np.asarray(term["speeds_rpm"], dtype=float) / top
    xs = np.asarray(speeds_rpm, dtype=float).ravel() / top
    hp = Hyperparameters(
        float(term["amplitude"]), float(term["length_scale"]), float(term["speed_power"])
    )
    return posterior(x, term["residuals"], term["sigmas"], hp, xs, fitted["kernel"])
