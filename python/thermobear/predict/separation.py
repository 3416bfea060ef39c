"""[`separating_measurement`][thermobear.separating_measurement]: where to
measure next to tell the members of a tie (or the named effect and the
unknown smooth term of "unresolved") apart."""

from __future__ import annotations

from typing import TYPE_CHECKING, Any, Mapping, Optional, Sequence, Union

import numpy as np

from ..errors import ConfigError
from .band import ModelOutputs, discrepancy_part
from .conditions import What, condition_columns, condition_frame, quantities_for, unit_of_quantity
from .model_input import as_calibrated
from .uncertainty import delta_band, parameters_of

if TYPE_CHECKING:
    import polars


def separating_measurement(
    model: Any,
    envelope_conditions: Any,
    sigma: Union[float, Mapping[str, float], None] = None,
    what: What = "measured",
) -> polars.DataFrame:
    """The condition and quantity where the members of a tie (or of
    "unresolved") differ most, relative to the measurement's sigma, within
    the operating envelope the user declares.

    ``envelope_conditions``: the candidate conditions (as
    [`predict`][thermobear.predict.band.predict] takes them: a frame, or a dict of
    ``speeds_rpm`` and loads -- a grid over the envelope); ``sigma``: the
    measurement's standard deviation in the quantity's unit (a number for
    every quantity, a dict quantity -> sigma (only those quantities are
    considered), or None for each quantity's
    typical sigma; a relative typical sigma is taken of the larger
    prediction).

    Each member is predicted with its band, as
    [`predict`][thermobear.predict.band.predict] gives it: the value and a
    standard deviation -- the calibrated values' by the delta method, and
    for the unknown smooth term of "unresolved" its model-discrepancy
    term's posterior mean and standard deviation, which grow away from the
    measured speeds. The separation of two members at a condition is

        |value_a - value_b| / sqrt(sigma^2 + sd_a^2 + sd_b^2)

    the difference of their predictions in standard deviations of what a
    measurement there would show under either: a difference the members'
    own uncertainty could produce separates them no better than one within
    the measurement's noise. (Far from the measured speeds the unknown
    term's band swamps any difference: the best condition is where the
    predictions have drifted apart while the band is still narrow.)

    Returns one row: the condition columns, ``quantity``, ``member_a``,
    ``member_b`` (the pair that separates most), ``value_a``, ``value_b``,
    ``sd_a``, ``sd_b`` (their standard deviations), ``unit``, ``sigma`` and
    ``separation``."""
    import polars as pl

    cm = as_calibrated(model)
    sigma = _checked_sigma(sigma)
    members = tuple(getattr(cm, "members", ()) or ())
    if len(members) < 2:
        raise ConfigError(
            f"invalid model: kind {getattr(cm, 'kind', '?')!r} with {len(members)} member(s); a "
            "separating measurement needs two explanations or more (a tie or unresolved)"
        )
    cond = condition_frame(cm.spec, envelope_conditions)
    quantities = quantities_for(cm.spec, what)
    if isinstance(sigma, Mapping):  # the quantities the user can measure
        quantities = [q for q in quantities if q in sigma]
        if not quantities:
            raise ConfigError(f"invalid sigma = {dict(sigma)!r}: no quantity of what = {what!r}")
    preds = [member_moments(m, cond, quantities) for m in members]
    sep, a, b, i, sig = _most_separated(cm.spec, quantities, cond.height, sigma, preds)
    row = cond.row(i % cond.height, named=True)
    q = quantities[i // cond.height]
    return pl.DataFrame(
        [{
            **row, "quantity": q, "member_a": str(members[a].label),
            "member_b": str(members[b].label), "value_a": float(preds[a][0][i]),
            "value_b": float(preds[b][0][i]), "sd_a": float(preds[a][1][i]),
            "sd_b": float(preds[b][1][i]), "unit": unit_of_quantity(q), "sigma": sig,
            "separation": sep,
        }]
    ).select([*condition_columns(cm.spec), "quantity", "member_a", "member_b", "value_a",
              "value_b", "sd_a", "sd_b", "unit", "sigma", "separation"])  # fmt: skip


def _checked_sigma(sigma: Any) -> Union[float, dict[str, float], None]:
    """``sigma`` checked: None, a finite number > 0, or a dict quantity ->
    such a number."""
    from .. import _validate as val

    if sigma is None:
        return None
    if isinstance(sigma, Mapping):
        return {
            val.text("sigma key", q): val.real(f"sigma[{q!r}]", v, 0.0, open_lo=True)
            for q, v in sigma.items()
        }
    return val.real("sigma", sigma, 0.0, open_lo=True)


def member_moments(
    model: Any, cond: polars.DataFrame, quantities: Sequence[str]
) -> tuple[np.ndarray, np.ndarray]:
    """(value, standard deviation) of a member's every output
    (quantity-major): the delta method on its calibrated values, plus its
    model-discrepancy term when it carries one (``discrepancy_part``)."""
    f = ModelOutputs(model, cond, quantities)
    par = parameters_of(model)
    value, _, _, sd = delta_band(f, par, 1.0)
    term = discrepancy_part(model, cond, quantities)
    if term is None:
        return value, sd
    return value + term[0], np.sqrt(sd * sd + term[1])


def _most_separated(
    spec: Any, quantities: list[str], n: int, sigma: Optional[Any],
    preds: Sequence[tuple[np.ndarray, np.ndarray]],
) -> tuple[float, int, int, int, float]:  # fmt: skip
    """(separation, member a, member b, output index, sigma there) of the
    pair and output that separate most (see ``separating_measurement``)."""
    best = (-1.0, 0, 0, 0, 0.0)
    for a in range(len(preds)):
        for b in range(a + 1, len(preds)):
            (va, sa), (vb, sb) = preds[a], preds[b]
            s = _sigmas(spec, quantities, n, sigma, np.maximum(np.abs(va), np.abs(vb)))
            ratio = np.abs(va - vb) / np.sqrt(s * s + sa * sa + sb * sb)
            i = int(np.argmax(ratio))
            if ratio[i] > best[0]:
                best = (float(ratio[i]), a, b, i, float(s[i]))
    return best


def _sigmas(
    spec: Any, quantities: list[str], n: int, sigma: Optional[Any], big: np.ndarray
) -> np.ndarray:
    """The measurement sigma of every output (quantity-major)."""
    out = np.empty(len(quantities) * n)
    for k, q in enumerate(quantities):
        rows = slice(k * n, (k + 1) * n)
        if sigma is None:
            *_, typical, relative = spec.quantities[q]
            out[rows] = typical * big[rows] if relative else np.full(n, typical)
        elif isinstance(sigma, Mapping):
            out[rows] = float(sigma[q])
        else:
            out[rows] = float(sigma)
    if not np.all(np.isfinite(out)) or np.any(out <= 0.0):
        raise ConfigError(f"invalid sigma = {sigma!r}: positive and finite")
    return out
