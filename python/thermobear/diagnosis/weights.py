"""Weights of the explanations of a tie or an "unresolved" verdict by how
well each predicts points it was not fitted to.

Each member's leave-one-out log predictive density of every measured point.
A member's fit is linear in the data once linearised: its calibrated
values' hat matrix ``H`` (the weighted least-squares projection at the
estimate), then its discrepancy term (a Gaussian process, posterior mean
``S e`` of the residuals ``e``) on what they leave, together the smoother
``L = H + S (I - H)``. For any linear smoother whose leave-one-out fit is
its fit with the left-out value replaced by its own prediction -- least
squares and Gaussian-process regression both are -- the left-out residual
is ``e_i / (1 - L_ii)`` and its predictive variance ``sigma_i^2 / (1 -
L_ii)`` (Hastie, Tibshirani and Friedman, *The Elements of Statistical
Learning*, eq. 7.52; Rasmussen and Williams, *Gaussian Processes for
Machine Learning*, eqs. 5.10-5.12, which are the same identity); a point
held out of the process's training takes its posterior variance on top. The
combination of the two parts is a linearisation: the process is fitted to
the residuals of the full fit, and its hyperparameters are held.

The weights are pseudo-BMA+ weights of these densities (Yao, Vehtari,
Simpson and Gelman, "Using stacking to average Bayesian predictive
distributions", Bayesian Analysis 13, 2018, section 3.2): each member's
summed leave-one-out log density ``elpd_k`` turned into a weight
``exp(elpd_k) / sum_j exp(elpd_j)``, averaged over Bayesian-bootstrap
replicates of the points so that a lead that rests on a few points counts
for less. Stacking (the same paper's optimal mixture weights) was the other
choice; on the tens of points of a rig it puts all the weight on one member
for leads of one or two nats -- too sure for a reading an engineer acts
on.

"""

from __future__ import annotations

from typing import Any

import numpy as np

#: The largest leverage used (a point that alone pins a value would give
#: an infinite leave-one-out variance).
MAX_LEVERAGE = 0.99

#: Bayesian-bootstrap replicates of the pseudo-BMA+ weights, and their
#: seed (the weights are deterministic).
BOOTSTRAP_DRAWS = 2000
BOOTSTRAP_SEED = 20180901


def loo_log_density(r: Any, jac: Any, data: Any, fitted: Any = None) -> np.ndarray:
    """The leave-one-out log predictive density of each point of ``data``
    under one member: ``r``, ``jac`` its weighted residuals (residual /
    sigma) at the estimate and their Jacobian against its calibrated
    values, ``fitted`` its discrepancy term (``fit_discrepancy``) or None;
    its hat matrix and the term's smoother combined (``member_smoother``),
    then ``smoother_loo``."""
    s = np.asarray(data.s, dtype=float)
    e = np.asarray(r, dtype=float) * s
    smooth, extra = gaussian_process_smoother(fitted, data) if fitted else (None, None)
    lev = member_smoother(hat_matrix(jac, s), smooth)
    d, var = smoother_loo(e if smooth is None else e - smooth @ e, lev, s)
    if extra is not None:
        var = var + extra
    return _normal_log_density(d, np.zeros_like(d), var)


def hat_matrix(jac: Any, sigma: Any) -> np.ndarray:
    """The hat matrix ``H`` of a weighted linear least-squares fit in the
    measured units: ``jac`` the Jacobian of the weighted residuals
    (residual / sigma) against the calibrated values, ``sigma`` the
    measurements' standard deviations; ``H = S_w A (A^T A)^+ A^T S_w^-1``,
    ``A`` = ``jac``, ``S_w`` = diag(sigma) (zero without values)."""
    s = np.asarray(sigma, dtype=float)
    a = np.asarray(jac, dtype=float).reshape(s.size, -1)
    if not a.shape[1]:
        return np.zeros((s.size, s.size))
    hw = a @ np.linalg.pinv(a.T @ a) @ a.T
    return s[:, None] * hw / s[None, :]


def gaussian_process_smoother(fitted: dict, data: Any) -> tuple[np.ndarray, np.ndarray]:
    """The linear smoother of a fitted discrepancy term on ``data``'s rows
    (``S``: the term's posterior mean at every row is ``S e``, ``e`` the
    residuals; ``S = K_f K^-1`` on a quantity's training rows, ``K_f``
    the term's covariance and ``K`` that plus the noise, ``k*^T K^-1`` on
    its held-out rows) and, per row, the term's posterior variance where
    the row is held out (0 elsewhere)."""
    from .discrepancy import Hyperparameters, kernel_matrix, prior_variance

    n = data.n
    smooth, extra = np.zeros((n, n)), np.zeros(n)
    train = data.train if data.held.any() else np.ones(n, dtype=bool)
    speeds = data.cond["speed_rpm"].to_numpy()
    top = float(fitted["speed_scale_rpm"])
    for q, term in (fitted.get("terms") or {}).items():
        rows = np.flatnonzero(train & (data.quantity == q))
        if rows.size != len(term["residuals"]):
            continue  # not the rows the term was fitted on
        x = speeds[rows] / top
        sig = np.asarray(data.s, dtype=float)[rows]
        hp = Hyperparameters(
            float(term["amplitude"]), float(term["length_scale"]), float(term["speed_power"])
        )
        kf = kernel_matrix(x, x, hp, fitted["kernel"])
        kinv = np.linalg.inv(kf + np.diag(sig * sig))
        smooth[np.ix_(rows, rows)] = kf @ kinv
        held = np.flatnonzero(~train & (data.quantity == q))
        if held.size:
            ks = kernel_matrix(speeds[held] / top, x, hp, fitted["kernel"])
            smooth[np.ix_(held, rows)] = ks @ kinv
            post = prior_variance(speeds[held] / top, hp) - np.sum((ks @ kinv) * ks, axis=1)
            extra[held] = np.clip(post, 0.0, None)
    return smooth, extra


def member_smoother(hat: np.ndarray, smooth: Any = None) -> np.ndarray:
    """The smoother of a member's whole fit: its calibrated values' hat
    matrix ``H``, then its discrepancy term's smoother ``S`` on what they
    leave: ``L = H + S (I - H)``."""
    if smooth is None:
        return hat
    return hat + smooth @ (np.eye(hat.shape[0]) - hat)


def smoother_loo(resid: Any, smoother: Any, sigma: Any) -> tuple[np.ndarray, np.ndarray]:
    """The leave-one-out residuals and predictive variances of a linear
    smoother ``L`` (fitted values ``L y``) with residuals ``resid`` = ``(I
    - L) y``: ``resid_i / (1 - L_ii)`` and ``sigma_i^2 / (1 - L_ii)`` (the
    leave-one-out identity of linear least squares -- Hastie, Tibshirani
    and Friedman, eq. 7.52 -- and of Gaussian-process regression --
    Rasmussen and Williams, eqs. 5.10-5.12 -- in one form)."""
    lii = np.clip(np.diag(np.asarray(smoother, dtype=float)), 0.0, MAX_LEVERAGE)
    s = np.asarray(sigma, dtype=float)
    return np.asarray(resid, dtype=float) / (1.0 - lii), s * s / (1.0 - lii)


def _normal_log_density(x: np.ndarray, mean: np.ndarray, var: np.ndarray) -> np.ndarray:
    return -0.5 * np.log(2.0 * np.pi * var) - 0.5 * (x - mean) ** 2 / var


def pseudo_bma_weights(log_density: Any, draws: int = BOOTSTRAP_DRAWS) -> np.ndarray:
    """The pseudo-BMA+ weights of members whose pointwise log predictive
    densities are the columns of ``log_density`` (points x members): the
    mean over ``draws`` Bayesian-bootstrap replicates (Dirichlet(1, ..., 1)
    weights ``a`` on the points, seed ``BOOTSTRAP_SEED``: deterministic) of
    ``softmax_k(n sum_i a_i lpd_ik)``. With the same difference at every
    point it is the plain pseudo-BMA ``softmax_k(sum_i lpd_ik)``."""
    lpd = np.asarray(log_density, dtype=float)
    n, k = lpd.shape
    if k == 1:
        return np.ones(1)
    a = np.random.default_rng(BOOTSTRAP_SEED).dirichlet(np.ones(n), size=draws)
    z = n * (a @ lpd)
    z -= z.max(axis=1, keepdims=True)
    e = np.exp(z)
    return np.mean(e / e.sum(axis=1, keepdims=True), axis=0)


def short_label(label: str) -> str:
    """A member's label without its tag ("named: ", "tie member 2: " ...)."""
    out = str(label)
    for tag in ("named: ", "alternative: ", "generic_control: "):
        out = out.replace(tag, "")
    if out.startswith("tie member "):
        out = out.split(": ", 1)[-1]
    return out


#: The weight from which a member is called favoured.
FAVOURED = 0.5


def weights_words(model: Any) -> str:
    """How strongly the weights favour one member, in words: "favoured:
    <member> (weight 0.93); <other> cannot be ruled out (weight 0.07)" --
    an other member below 0.01 is "ruled out by prediction"; "" for a
    model without weighed members."""
    members = [m for m in getattr(model, "members", ()) if m.weight is not None]
    if len(members) < 2:
        return ""
    order = sorted(members, key=lambda m: -float(m.weight))
    best = order[0]
    head = "favoured" if float(best.weight) >= FAVOURED else "most weight"
    parts = [f"{head}: {short_label(best.label)} (weight {float(best.weight):.2f})"]
    for m in order[1:]:
        w = float(m.weight)
        what = "ruled out by prediction" if w < 0.01 else "cannot be ruled out"
        parts.append(f"{short_label(m.label)} {what} (weight {w:.2f})")
    return "; ".join(parts)
