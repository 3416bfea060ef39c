"""Spindle inputs that a study may not know: the ball size, the axial
length of the shaft between the bearing sets and the motor losses, changed
on a [`Spindle`][thermobear.Spindle] through its stored configuration
(rebuilt and checked by the same constructor as a preset).

[`with_dimensions`][thermobear.spindle.dimensions.with_dimensions] returns a
new spindle; each change is a factor on the preset's value (1 keeps it):

* ``ball_diameter_scale``: every ball of both pairs, and with it the
  diametral clearance, so the free contact angle stays the same
  (cos alpha_0 = 1 - P_d / (2 (f_i + f_o - 1) D)); the ball mass, its
  centrifugal force, the Hertz contacts and the ball surface of the
  thermal network follow.
* ``span_scale``: the axial layout between the bearing sets -- front and
  rear spans, the rotor core's length and position -- so the length over
  which the shaft grows against the housing (the spans' sum) and the
  lever of the nose load change together.
* ``motor_loss_scale``: the four motor losses (stator copper and iron,
  rotor copper and windage) alike.

And one value: ``outer_ring_contact_w_per_m2_k``, the thermal contact
conductance of the outer rings' seats in the housing (None keeps the
spindle's own; see [`Housing`][thermobear.Housing]).
"""

from __future__ import annotations

import json
import math
from typing import Any, Optional

from ..errors import ConfigError

#: The bearing rows of a spindle configuration.
_ROWS = ("front_bearing", "rear_bearing")
#: Axial lengths of the layout between the bearing sets [m].
_AXIAL = ("front_span_m", "rear_span_m", "rotor_length_m")
#: The motor losses [W].
_LOSSES = ("stator_copper_w", "stator_iron_w", "rotor_copper_w", "rotor_mechanical_w")


def _factor(name: str, value: Any) -> float:
    """A scale factor: a finite number > 0 (``ConfigError`` naming it)."""
    try:
        v = float(value)
    except (TypeError, ValueError):
        raise ConfigError(f"invalid {name} = {value!r}: a finite factor > 0") from None
    if not (math.isfinite(v) and v > 0.0):
        raise ConfigError(f"invalid {name} = {value!r}: a finite factor > 0")
    return v


def scaled_balls(params: dict[str, Any], scale: float) -> dict[str, Any]:
    """``params`` (a spindle's ``config.params``) with every ball diameter
    and diametral clearance times ``scale``."""
    out = dict(params)
    for row in _ROWS:
        bearing = dict(out[row])
        g = dict(bearing["geometry"])
        g["ball_diameter_m"] = g["ball_diameter_m"] * scale
        g["diametral_clearance_m"] = g["diametral_clearance_m"] * scale
        bearing["geometry"] = g
        out[row] = bearing
    return out


def scaled_layout(config: dict[str, Any], scale: float) -> dict[str, Any]:
    """``config`` (a spindle's ``config``) with the axial layout between
    the bearing sets times ``scale``: spans, rotor core length and the
    magnetic-pull core's length and position."""
    out = dict(config)
    params = dict(out["params"])
    for k in _AXIAL:
        params[k] = params[k] * scale
    out["params"] = params
    pull = out.get("magnetic_pull")
    if pull:
        pull = dict(pull)
        pull["core_from_front_pair_m"] = pull["core_from_front_pair_m"] * scale
        inner = dict(pull["pull"])
        for k in ("position_m", "core_length_m"):
            inner[k] = inner[k] * scale
        pull["pull"] = inner
        out["magnetic_pull"] = pull
    return out


def scaled_losses(params: dict[str, Any], scale: float) -> dict[str, Any]:
    """``params`` with the four motor losses times ``scale``."""
    return {**params, **{k: params[k] * scale for k in _LOSSES}}


def with_dimensions(
    spindle: Any,
    *,
    ball_diameter_scale: float = 1.0,
    span_scale: float = 1.0,
    motor_loss_scale: float = 1.0,
    outer_ring_contact_w_per_m2_k: Optional[float] = None,
) -> Any:
    """A copy of ``spindle`` with its balls, axial layout and motor losses
    scaled (module doc); every other setting kept. A factor of 1 changes
    nothing; an impossible result (a ball too large for its rings, a rotor
    longer than the spans allow) is refused by the spindle's own checks."""
    from .. import _native
    from .spindle import Spindle

    if not isinstance(spindle, Spindle):
        raise ConfigError(f"invalid spindle = {spindle!r}: give a thermobear.Spindle")
    balls = _factor("ball_diameter_scale", ball_diameter_scale)
    span = _factor("span_scale", span_scale)
    losses = _factor("motor_loss_scale", motor_loss_scale)
    seat = None
    if outer_ring_contact_w_per_m2_k is not None:
        seat = _factor("outer_ring_contact_w_per_m2_k", outer_ring_contact_w_per_m2_k)
    if balls == span == losses == 1.0 and seat is None:
        return spindle
    state = dict(spindle._native.__reduce__()[1][0])
    data = json.loads(state["data"])
    config = scaled_layout(data["config"], span)
    config["params"] = scaled_losses(scaled_balls(config["params"], balls), losses)
    if seat is not None:
        config["params"]["outer_ring_contact_w_m2k"] = seat
    data["config"] = config
    state["data"] = json.dumps(data)
    return Spindle(_native._restore(state))


def _config(spindle: Any) -> dict[str, Any]:
    """A spindle's stored configuration (its ``config``)."""
    return json.loads(spindle._native.__reduce__()[1][0]["data"])["config"]


def row_geometries(spindle: Any) -> dict[str, dict[str, Any]]:
    """The geometry of the spindle's front and rear bearing rows as stored
    (after any ``with_dimensions``): bearing name -> ball count, ball
    diameter and mass, pitch diameter, conformities, clearance, free
    contact angle and envelope (mm, g, deg)."""
    out = {}
    for row in _ROWS:
        b = _config(spindle)["params"][row]
        g = b["geometry"]
        d_m = g["ball_diameter_m"]
        out[b["name"]] = {
            "ball_count": float(g["ball_count"]),
            "ball_diameter_mm": d_m * 1e3,
            "ball_mass_g": b["ball"]["density_kg_m3"] * math.pi * d_m**3 / 6.0 * 1e3,
            "bore_mm": g["bore_m"] * 1e3,
            "diametral_clearance_mm": g["diametral_clearance_m"] * 1e3,
            "free_contact_angle_deg": math.degrees(g["free_contact_angle_rad"]),
            "inner_conformity": g["inner_conformity"],
            "outer_conformity": g["outer_conformity"],
            "outer_diameter_mm": g["outer_diameter_m"] * 1e3,
            "pitch_diameter_mm": g["pitch_diameter_m"] * 1e3,
            "width_mm": g["width_m"] * 1e3,
        }
    return out
