"""Statistics shared by the steps: chi^2, speed bands, the residual's shape
against speed (AIC), cosine similarity, the chi^2 test, identifiability
from the Fisher information."""

from __future__ import annotations

import numpy as np


def _chi2(r: np.ndarray) -> float:
    return float(np.sum(r * r))


def _speed_bands(speed: np.ndarray, n_bands: int = 3) -> np.ndarray:
    lo, hi = float(speed.min()), float(speed.max())
    if hi <= lo:
        return np.array(["all"] * len(speed), dtype=object)
    edges = np.linspace(lo, hi, n_bands + 1)
    idx = np.clip(np.searchsorted(edges, speed, side="right") - 1, 0, n_bands - 1)
    names = [f"{edges[i]:.0f}-{edges[i + 1]:.0f} rpm" for i in range(n_bands)]
    return np.array([names[i] for i in idx], dtype=object)


def _band_key(band: str) -> float:
    return float(band.split("-")[0]) if band != "all" else 0.0


def residual_shape(speed: np.ndarray, r: np.ndarray) -> tuple[str, dict[str, float]]:
    """Shape of a residual (in sigma) against speed, chosen by AIC among
    none (k=0), offset (1), slope (2: 1, x), growth (3: 1, x, x^2 with
    x the speed scaled to [-1, 1]) and local feature (offset + the one point
    that helps most; k=3: the chosen location counts as a parameter)."""
    x = speed.astype(float)
    span = x.max() - x.min()
    x = (x - x.min()) / span * 2.0 - 1.0 if span > 0 else np.zeros_like(x)
    n = len(r)
    aic = {"none": _chi2(r)}
    bases = {"offset": [np.ones(n)], "slope": [np.ones(n), x], "growth": [np.ones(n), x, x * x]}
    for name, cols in bases.items():
        if n <= len(cols):
            continue
        a = np.column_stack(cols)
        coef, *_ = np.linalg.lstsq(a, r, rcond=None)
        aic[name] = _chi2(r - a @ coef) + 2.0 * len(cols)
    if n > 3:
        best = np.inf
        for i in range(n):
            e = np.zeros(n)
            e[i] = 1.0
            a = np.column_stack([np.ones(n), e])
            coef, *_ = np.linalg.lstsq(a, r, rcond=None)
            best = min(best, _chi2(r - a @ coef))
        aic["local feature"] = best + 6.0
    return min(aic, key=aic.__getitem__), aic


def _cosine(a: np.ndarray, b: np.ndarray) -> float:
    na, nb = np.linalg.norm(a), np.linalg.norm(b)
    if na == 0 or nb == 0:
        return 0.0
    return float(a @ b / (na * nb))


def noise_p_value(chi2: float, n: int) -> float:
    """Probability that pure noise (``n`` points of unit sigma) gives a
    chi^2 at least ``chi2``: the chi^2 test of a residual."""
    from scipy.stats import chi2 as chi2_dist

    return float(chi2_dist.sf(chi2, n))


#: Fisher information condition number (correlation form) above which a
#: combination of parameters counts as not identified.
COND_MAX = 1e6


def fisher_identifiability(jac: np.ndarray, spans: np.ndarray) -> tuple[float, set]:
    """Identifiability from the Jacobian of residual/sigma against the
    parameters: the Fisher information J^T J with the parameters scaled by
    their bound ``spans``, in correlation form (unit diagonal). Returns its
    condition number and the indices it does not identify: a parameter no
    point moves (zero diagonal), or one with a large share (|v| > 0.3) of
    an eigenvector whose eigenvalue is below 1/``COND_MAX`` of the
    largest."""
    js = jac * spans[None, :]
    f = js.T @ js
    dg = np.diag(f)
    weak = set(np.flatnonzero(dg <= 1e-12 * max(float(dg.max()), 1e-300)).tolist())
    ok = np.array([i not in weak for i in range(len(dg))])
    if ok.sum() == 0:
        return float("inf"), weak
    sub = f[np.ix_(ok, ok)]
    corr = sub / np.sqrt(np.outer(np.diag(sub), np.diag(sub)))
    w, v = np.linalg.eigh(corr)
    cond = float(w[-1] / max(w[0], 1e-300))
    idx = np.flatnonzero(ok)
    for k in np.flatnonzero(w < w[-1] / COND_MAX):
        weak |= set(idx[np.abs(v[:, k]) > 0.3].tolist())
    return cond, weak
