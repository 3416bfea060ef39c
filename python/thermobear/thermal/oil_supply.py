"""The oil supply as a model input (docs/concepts/physics.md §9, "Oil
supply, cavity oil fraction and drag").

The supply keywords of every thermal call (``thermal_state``,
``isothermal_heat``, ``stiffness_curve(mode="thermal")``, the spindle),
by lubrication method:

* ``"jet"``: ``oil_flow_cm3_per_min`` (total oil flow into the bearing),
  ``jet_count`` (default 1), ``jet_velocity_m_per_s`` (when known);
* ``"oil-air"`` and ``"oil-mist"``: ``oil_volume_cm3_per_h`` and
  ``air_flow_l_per_min``;
* ``"oil-bath"``: ``oil_level_mm``, the static oil level above the lowest
  point of the lowest ball (None: the middle of the lowest ball, the
  ISO 15312 reference level);
* ``"grease"``: ``grease_fill_fraction`` (default 0.3);
* the two calibratable tunings: ``oil_flow_scale`` (default 1) and
  ``cavity_fraction_speed_exponent`` (default 1, Parker's).

Giving any of them switches the drag from the method's fixed cavity oil
fraction to the supply model: the cavity oil fraction follows the supply
and the speed (Parker's jet correlation; the SKF bath drag for an oil
bath). ``lubrication="oil-bath"`` uses the supply model at the reference
level even without a keyword. ``churning_oil_fraction`` is the explicit
override: given with a supply keyword it is refused (one or the other);
given alone, the fixed fraction is used as before. A jet, oil-air or
oil-mist method without its flow keeps the method's fixed fraction (no
published default flow).
"""

from __future__ import annotations

from typing import Any

from ..errors import ConfigError

#: Supply keywords and their defaults (None: not given).
SUPPLY_OPTIONS: dict[str, Any] = {
    "oil_flow_cm3_per_min": None,
    "jet_count": None,
    "jet_velocity_m_per_s": None,
    "oil_volume_cm3_per_h": None,
    "air_flow_l_per_min": None,
    "oil_level_mm": None,
    "grease_fill_fraction": None,
    "oil_flow_scale": None,
    "cavity_fraction_speed_exponent": None,
}


#: Lubrication methods whose drag follows the supply model even without a
#: supply keyword (``lubrication="oil-bath"``: the SKF bath drag at the
#: reference level); a model spec leaves their fixed fraction unset too.
SUPPLY_WITHOUT_KEYWORDS: tuple[str, ...] = ("oil-bath",)


def _number(name: str, value: Any) -> Any:
    if value is None:
        return None
    if name == "jet_count":
        if isinstance(value, bool) or not float(value).is_integer() or value < 1:
            raise ConfigError(f"invalid jet_count = {value!r}: a whole number >= 1")
        return int(value)
    try:
        x = float(value)
    except (TypeError, ValueError):
        raise ConfigError(f"invalid {name} = {value!r}: a number") from None
    if x != x or x < 0.0:
        raise ConfigError(f"invalid {name} = {value!r}: a number >= 0")
    return x


def supply_dict(options: dict[str, Any]) -> dict[str, Any]:
    """Every supply keyword of the heat ``options`` checked as a number
    (None where not given); the native side checks that they belong to
    the lubrication method and resolves the supply."""
    return {k: _number(k, options.get(k)) for k in SUPPLY_OPTIONS}
