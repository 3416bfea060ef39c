"""An extra heat at the bearing with its own speed law,

    H(n) = max(0, a x + b x^2),    x = n / n_ref,

``a`` = ``unknown_heat_linear_w``, ``b`` = ``unknown_heat_quadratic_w``
[W], ``n_ref`` = ``unknown_heat_reference_rpm`` [rpm]. It is the heat of
the diagnosis' unknown heat source (a member of an "unresolved" model:
``thermobear.diagnosis.unknown_heat``), and the thermal entry points take
it as keywords so that such a member stands for its bearing in
[`thermal_state`][thermobear.thermal_state], ``thermal_state_many``,
``thermal_stiffness_curve`` and ``isothermal_heat`` as it does in the
prediction: at each speed the law's heat is added to ``extra_heat_w``
(split like rolling heat). A heat source cannot take heat away, hence the
clip at zero."""

from __future__ import annotations

from typing import Any

import numpy as np

from .. import _validate as val

#: The keywords of the law: linear and quadratic coefficients [W],
#: reference speed [rpm].
HEAT_LAW_OPTIONS = (
    "unknown_heat_linear_w",
    "unknown_heat_quadratic_w",
    "unknown_heat_reference_rpm",
)


def has_heat_law(options: dict[str, Any]) -> bool:
    """Whether ``options`` hold a non-zero law."""
    return any(float(options.get(k) or 0.0) != 0.0 for k in HEAT_LAW_OPTIONS[:2])


def heat_law_w(options: dict[str, Any], speeds_rpm: Any) -> np.ndarray:
    """The law's heat [W] at ``speeds_rpm`` (zero without a reference
    speed)."""
    n = np.asarray(speeds_rpm, dtype=float)
    a = float(options.get("unknown_heat_linear_w") or 0.0)
    b = float(options.get("unknown_heat_quadratic_w") or 0.0)
    ref = float(options.get("unknown_heat_reference_rpm") or 0.0)
    x = n / ref if ref > 0.0 else np.zeros_like(n)
    return np.clip(a * x + b * x * x, 0.0, None)


def pop_heat_law(kwargs: dict[str, Any]) -> dict[str, float]:
    """The law's keywords taken out of a call's ``kwargs``, checked
    (finite; the reference speed > 0 when a coefficient is not zero)."""
    law = {k: kwargs.pop(k) for k in HEAT_LAW_OPTIONS if k in kwargs}
    out = {k: val.real(k, v) for k, v in law.items() if v is not None}
    if has_heat_law(out):
        ref = out.get("unknown_heat_reference_rpm")
        if ref is None or ref <= 0.0:
            raise val.fail(
                "unknown_heat_reference_rpm", ref,
                "a speed > 0 [rpm]: the law's coefficients are the heat at x = n / n_ref",
            )  # fmt: skip
    return out


def plus_heat_law(extra_heat_w: Any, law: dict[str, float], speed_rpm: Any) -> Any:
    """``extra_heat_w`` with the law's heat at ``speed_rpm`` added (both
    checked), or ``extra_heat_w`` as given without a law."""
    if not has_heat_law(law):
        return extra_heat_w
    at = val.real("speed_rpm", speed_rpm, 0.0)
    return val.real("extra_heat_w", extra_heat_w) + float(heat_law_w(law, at))
