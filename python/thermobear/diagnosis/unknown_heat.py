"""The unknown term of an "unresolved" verdict shaped by physics: an
unknown heat source at the bearing (at a spindle's front bearing set) with
its own speed law,

    H(n) = max(0, a x + b x^2),    x = n / n_ref,

``a`` = ``unknown_heat_linear_w``, ``b`` = ``unknown_heat_quadratic_w``
[W], ``n_ref`` = ``unknown_heat_reference_rpm`` (the highest measured
speed). It is the carrier control of the screening
(``thermobear.diagnosis.control``: the same two-parameter law acting on
the extra-heat input) made a model of its own: the heat enters the
bearing's heat balance like the rolling heat, so it moves every
temperature, the thermal expansions, the contact loads and the stiffness
-- a member that predicts every quantity the model predicts, with a band
from its two fitted coefficients, and that extrapolates as heat does. A
heat source cannot take heat away: the law is clipped at zero (the
bearing model refuses a negative extra heat). What the heat cannot
explain is left to the Gaussian-process discrepancy fitted on top of it.

Everything here is a small function of plain numbers and the model spec
protocol; the fit is bounded least squares on the weighted residuals."""

from __future__ import annotations

from typing import Any, Sequence

import numpy as np

from ..thermal.heat_law import HEAT_LAW_OPTIONS, has_heat_law, heat_law_w
from .candidates import Candidate

#: The options of the unknown heat source's speed law (see the module
#: docstring): linear and quadratic coefficients [W], reference speed [rpm];
#: the thermal entry points take them as keywords (``thermobear.thermal.heat_law``).
UNKNOWN_HEAT_OPTIONS = HEAT_LAW_OPTIONS

#: Bounds of each coefficient [W]: twice the range of the registry's
#: constant extra heat (0-100 W) either way; the clipped law then spans
#: 0-400 W at the reference speed.
COEFFICIENT_BOUNDS = (-200.0, 200.0)

#: The upper bound of the reference speed [rpm] (a bound, not a limit of
#: the law: far above any rolling bearing's speed).
MAX_REFERENCE_RPM = 1e6


#: Whether options hold a non-zero law; the law's heat [W] at given speeds.
has_unknown_heat = has_heat_law
unknown_heat_w = heat_law_w


def supports_unknown_heat(spec: Any) -> bool:
    """Whether a model spec carries the unknown heat source: a bearing
    spec (its thermal options take the law) or a spindle spec (the law's
    heat goes to the front bearing set, ``extra_heat_w`` of the spindle)."""
    if hasattr(spec, "bearing") and hasattr(spec, "thermal_options"):
        return True
    return hasattr(spec, "configured") and all(k in spec.options for k in HEAT_LAW_OPTIONS)


def unknown_heat_candidates(quantities: Sequence[str]) -> tuple[Candidate, Candidate, Candidate]:
    """The two coefficients (calibrated) and the reference speed (held) as
    candidates, ``quantities`` the ones the heat affects."""
    lo, hi = COEFFICIENT_BOUNDS
    aff = tuple(quantities)
    lin = Candidate(
        "unknown_heat_linear_w", "parameter", "model", "unknown_heat_linear_w", "W", lo, hi,
        0.0, "unknown heat source: linear coefficient of its speed law", aff,
        option="unknown_heat_linear_w", role="effect",
    )  # fmt: skip
    quad = Candidate(
        "unknown_heat_quadratic_w", "parameter", "model", "unknown_heat_quadratic_w", "W", lo,
        hi, 0.0, "unknown heat source: quadratic coefficient of its speed law", aff,
        option="unknown_heat_quadratic_w", role="effect",
    )  # fmt: skip
    ref = Candidate(
        "unknown_heat_reference_rpm", "parameter", "model", "unknown_heat_reference_rpm", "rpm",
        0.0, MAX_REFERENCE_RPM, 0.0, "unknown heat source: reference speed of its speed law", aff,
        option="unknown_heat_reference_rpm", role="calibration",
    )  # fmt: skip
    return lin, quad, ref


def fit_unknown_heat(
    base: Any, setting: Any, data: Any
) -> tuple[tuple[Candidate, Candidate, Candidate], float, np.ndarray, float]:
    """The unknown heat law fitted to ``data`` on top of ``setting`` (the
    fixed steps' ``_Setting``): bounded least squares of the weighted
    residuals in the two coefficients, the reference speed the highest
    measured one. Returns the candidates (linear, quadratic, reference),
    the reference speed [rpm], the coefficients [W] and the chi^2 left."""
    from scipy.optimize import least_squares

    from .setting import _predict

    ref = float(np.max(data.cond["speed_rpm"].to_numpy()))
    cands = unknown_heat_candidates(tuple(base.quantities))
    lin, quad, rc = cands
    opts = dict(base.options)
    at_ref = setting.apply(rc, ref, opts)

    def resid(v: np.ndarray) -> np.ndarray:
        st = at_ref.apply(lin, float(v[0]), opts).apply(quad, float(v[1]), opts)
        return data.residual(_predict(base, st, data.cond, data.quantity))

    lo, hi = COEFFICIENT_BOUNDS
    x0 = np.clip(_linear_start(resid), lo + 1e-9, hi - 1e-9)
    res = least_squares(
        resid, x0, bounds=([lo, lo], [hi, hi]), diff_step=1e-3, x_scale=[10.0, 10.0],
        xtol=1e-8, ftol=1e-10, max_nfev=60,
    )  # fmt: skip
    chi2 = float(np.sum(res.fun**2))
    return cands, ref, np.asarray(res.x, dtype=float), chi2


def _linear_start(resid: Any) -> np.ndarray:
    """A start from one Gauss-Newton step at a small positive law (the
    clip at zero makes the law flat below it)."""
    x = np.array([1.0, 1.0])
    r0 = resid(x)
    jac = np.empty((r0.size, 2))
    for j in range(2):
        e = x.copy()
        e[j] += 1.0
        jac[:, j] = (resid(e) - r0) / 1.0
    step, *_ = np.linalg.lstsq(jac, -r0, rcond=None)
    return x + step
