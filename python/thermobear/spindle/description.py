"""A spindle from its parts: the ``[spindle]`` description (TOML or the
dataclasses of ``parts``) mapped onto the native spindle configuration,
and back.

One path builds every described spindle: the ``seed-ceramic-spindle``
configuration (``Spindle.config_json`` of the native preset) with the
described values put in, handed to ``_native.Spindle.from_config``, which
checks every field by name. The way back reads the configuration of a
native spindle into parts, so ``to_toml`` -> ``from_toml`` gives the same
configuration to the last bit: a value in the description is converted
between its unit and SI by shifting its shortest decimal digits, and the
value written is one that converts back exactly.
"""

from __future__ import annotations

import copy
import json
import math
import re
import tomllib
from decimal import Decimal
from functools import lru_cache
from pathlib import Path
from typing import Any, Mapping, Optional

from .. import _native
from .. import _validate as val
from .._toml_text import toml_value
from ..errors import ConfigError
from .parts import (
    PART_TYPES,
    SUPPLY_KEYS,
    BearingSet,
    Housing,
    Lubrication,
    MagneticPull,
    Motor,
    Preload,
    Shaft,
    ShaftSegment,
)

#: The preset whose configuration fills what a description leaves out.
BASE_PRESET = "seed-ceramic-spindle"
PULL_EFFECT = "unbalanced_magnetic_pull"
#: Keys of the ``[spindle]`` table itself.
TOP_KEYS = ("name", "effects")
BEARING_TABLES = ("front", "rear")
#: Package folder of the preset description files.
SPINDLE_FILES = "thermobear.configs"


# -- exact unit conversion ------------------------------------------------------
def to_si(value: float, exponent: int) -> float:
    """``value`` times 10**exponent, its shortest decimal shifted (exact),
    then rounded once to the nearest float."""
    return float(Decimal(repr(float(value))).scaleb(exponent))


def from_si(value: float, exponent: int) -> float:
    """The value in the description's unit that ``to_si`` takes back to
    ``value`` exactly (the nearest such float to the plain conversion)."""
    first = float(Decimal(repr(float(value))).scaleb(-exponent))
    up = down = first
    for _ in range(64):
        for cand in (up, down):
            if to_si(cand, exponent) == value:
                return cand
        up, down = math.nextafter(up, math.inf), math.nextafter(down, -math.inf)
    return first


@lru_cache(maxsize=1)
def _base_json() -> str:
    return str(_native.Spindle.preset(BASE_PRESET).config_json())


def base_config() -> dict[str, Any]:
    """The configuration of ``BASE_PRESET`` as a dict (a fresh copy)."""
    return copy.deepcopy(json.loads(_base_json()))


# -- parts -> native -------------------------------------------------------------
def _bearing_set(value: Any, which: str) -> BearingSet:
    if value is None:
        return BearingSet("7009C-hybrid" if which == "front" else "7008C-hybrid")
    if isinstance(value, BearingSet):
        return value
    return BearingSet(value)


def _part(value: Any, kind: type, name: str) -> Any:
    if value is None:
        return kind()
    if not isinstance(value, kind):
        raise val.fail(name, value, f"None or a thermobear.{kind.__name__}")
    return value


def build_native(
    name: Optional[str],
    front: Any = None,
    rear: Any = None,
    effects: Any = None,
    **parts: Any,
) -> Any:
    """The native spindle of a description (parts None: their defaults)."""
    name = "custom" if name is None else val.text("name", name)
    f, r = _bearing_set(front, "front"), _bearing_set(rear, "rear")
    p = {k: _part(parts.get(k), t, k) for k, t in PART_TYPES.items()}
    cfg = base_config()
    _put_params(cfg["params"], p)
    pre: Preload = p["preload"]
    if pre.kind == "spring":
        rate = cfg["preload"].get("Spring", {}).get("rate_n_per_m")
        if pre.spring_rate_n_per_um is not None:
            rate = to_si(pre.spring_rate_n_per_um, 6)
        cfg["preload"] = {"Spring": {"force_n": pre.preload_n, "rate_n_per_m": rate}}
    else:
        cfg["preload"] = {"Rigid": {"force_n": pre.preload_n}}
    cfg["params"]["preload_n"] = pre.preload_n
    housing: Housing = p["housing"]
    cfg["assembly_temperature_c"] = (
        housing.ambient_temperature_c
        if housing.assembly_temperature_c is None
        else housing.assembly_temperature_c
    )
    cfg["radial_load_n"] = p["tool"].radial_load_n
    lub: Lubrication = p["lubrication"]
    cfg["spin_friction_coefficient"] = lub.spin_friction_coefficient
    motor: Motor = p["motor"]
    cfg["effects"] = _effects(cfg["effects"], effects, motor.magnetic_pull)
    if motor.magnetic_pull is not None:
        _put_pull(cfg["magnetic_pull"], motor.magnetic_pull)
    elif motor != Motor() or p["shaft"] != Shaft():
        # no pull table: the seed's air-gap data (kept, off) belong to the
        # seed's motor on the seed's shaft; another machine has none
        cfg["magnetic_pull"] = None
    try:
        native = _native.Spindle.from_config(
            json.dumps(cfg),
            name,
            front_bearing=f.bearing._b,
            rear_bearing=r.bearing._b,
            lubricant=lub.lubricant,
            heat=_heat(lub),
        )
    except ConfigError as e:
        raise _described_error(e) from None
    if p["shaft"].segments:  # the rotor's own shaft: checked now, not at first use
        from .rotor_layout import rotor_layout

        rotor_layout(native)
    return native


_NATIVE_ERROR = re.compile(r"^invalid (\w+) = ([^:]+): (.*)$", re.S)


def _described_error(error: ConfigError) -> ConfigError:
    """A native error about a configuration field, named as the description
    names it (key, value in its unit, and its table)."""
    m = _NATIVE_ERROR.match(str(error))
    by_field = {k: (part, field, exp) for k, part, field, exp in PARAM_FIELDS}
    if m is None or m.group(1) not in by_field:
        return error
    part, field, exponent = by_field[m.group(1)]
    try:
        shown = f"{from_si(float(m.group(2)), exponent):g}"
    except ValueError:
        shown = m.group(2)
    return type(error)(f"invalid {field} = {shown}: {m.group(3)} (in [spindle.{part}])")


#: (config field, part, part field, power of ten from the part's unit to SI).
PARAM_FIELDS: tuple[tuple[str, str, str, int], ...] = (
    ("front_span_m", "shaft", "front_span_mm", -3),
    ("rear_span_m", "shaft", "rear_span_mm", -3),
    ("nose_length_m", "shaft", "nose_length_mm", -3),
    ("sleeve_outer_diameter_m", "housing", "sleeve_outer_diameter_mm", -3),
    ("front_housing_length_m", "housing", "front_housing_length_mm", -3),
    ("rear_housing_length_m", "housing", "rear_housing_length_mm", -3),
    ("stator_contact_w_m2k", "housing", "stator_contact_w_per_m2_k", 0),
    ("ambient_temperature_c", "housing", "ambient_temperature_c", 0),
    ("rotor_diameter_m", "motor", "rotor_diameter_mm", -3),
    ("rotor_length_m", "motor", "rotor_length_mm", -3),
    ("air_gap_m", "motor", "air_gap_mm", -3),
    ("stator_outer_diameter_m", "motor", "stator_outer_diameter_mm", -3),
    ("stator_copper_w", "motor", "stator_copper_loss_w", 0),
    ("stator_iron_w", "motor", "stator_iron_loss_w", 0),
    ("rotor_copper_w", "motor", "rotor_copper_loss_w", 0),
    ("rotor_mechanical_w", "motor", "windage_loss_w", 0),
    ("loss_reference_rpm", "motor", "loss_reference_speed_rpm", 0),
    ("water_flow_l_min", "cooling", "jacket_flow_l_per_min", 0),
    ("water_temperature_c", "cooling", "water_temperature_c", 0),
    ("channel_width_m", "cooling", "channel_width_mm", -3),
    ("channel_height_m", "cooling", "channel_height_mm", -3),
    ("jacket_wetted_fraction", "cooling", "jacket_wetted_fraction", 0),
    ("oil_air_temperature_c", "lubrication", "oil_air_temperature_c", 0),
)

#: (pull field, MagneticPull field, power of ten to SI); the core position
#: is on the pull's holder.
PULL_FIELDS: tuple[tuple[str, str, int], ...] = (
    ("rotor_radius_m", "core_radius_mm", -3),
    ("core_length_m", "core_length_mm", -3),
    ("air_gap_m", "air_gap_mm", -3),
    ("flux_density_t", "flux_density_t", 0),
    ("static_eccentricity_m", "static_eccentricity_um", -6),
    ("reduction_factor", "reduction_factor", 0),
)


def _put_params(params: dict[str, Any], parts: dict[str, Any]) -> None:
    for key, part, field, exponent in PARAM_FIELDS:
        params[key] = to_si(getattr(parts[part], field), exponent)
    params["outer_ring_contact_w_m2k"] = parts["housing"].outer_ring_contact_w_per_m2_k
    segments = parts["shaft"].segments
    params["shaft_segments_m"] = [
        [to_si(g.length_mm, -3), to_si(g.outer_diameter_mm, -3), to_si(g.bore_mm, -3)]
        for g in segments
    ] or None


def _put_pull(holder: dict[str, Any], pull: MagneticPull) -> None:
    if pull.core_from_front_pair_mm is not None:
        holder["core_from_front_pair_m"] = to_si(pull.core_from_front_pair_mm, -3)
    for key, field, exponent in PULL_FIELDS:
        value = getattr(pull, field)
        if value is not None:
            holder["pull"][key] = to_si(value, exponent)
    holder["pull"]["enabled"] = True


def _effects(base: list[str], effects: Any, pull: Optional[MagneticPull]) -> list[str]:
    """The effect names: ``effects`` (None: the preset's), the magnetic
    pull on exactly when the motor describes it."""
    from ..bearing.ball_bearing import _effects_arg

    names = list(base) if effects is None else list(_effects_arg(effects) or [])
    if pull is None and PULL_EFFECT in names and effects is not None:
        raise ConfigError(
            f"invalid effects = {PULL_EFFECT}: the pull needs the motor's magnetic_pull "
            "(a [spindle.motor.magnetic_pull] table)"
        )
    names = [n for n in names if n != PULL_EFFECT]
    return names + [PULL_EFFECT] if pull is not None else names


def _heat(lub: Lubrication) -> dict[str, Any]:
    """The native heat settings of ``lub`` (as ``Spindle.with_options``)."""
    from ..thermal.oil_supply import supply_dict

    heat: dict[str, Any] = {
        "heat_model": lub.heat_model,
        "lubrication": lub.method,
        "lubrication_factor_f0": lub.lubrication_factor_f0,
        "load_friction_scale": lub.load_friction_scale,
        "churning_oil_fraction": lub.churning_oil_fraction,
        "sliding_friction_ehl": lub.sliding_friction_ehl,
        "replenishment_krs": lub.replenishment_krs,
        "seal_moment_n_m": lub.seal_moment_n_m,
    }
    supply = {k: getattr(lub, k) for k in SUPPLY_KEYS}
    if any(v is not None for v in supply.values()):
        if lub.churning_oil_fraction not in (None, 0.0):
            raise ConfigError(
                f"invalid churning_oil_fraction = {lub.churning_oil_fraction:g}: with an oil "
                "supply the drag follows the supply; leave the fraction out"
            )
        heat["churning_oil_fraction"] = None
    heat["skf_series"] = None
    heat["oil_supply"] = supply_dict(supply)
    return heat


# -- native -> parts -------------------------------------------------------------
def _preset_bearing_name(bearing: dict[str, Any], which: str) -> str:
    """The preset name of a configured bearing; a bearing that is not a
    preset to the last bit cannot be named in a file."""
    from ..bearing import Bearing

    name = str(bearing.get("name"))
    try:
        env = Bearing.preset(name)._b.__reduce__()[1][0]
    except ConfigError:
        env = None
    if env is not None and json.loads(env["data"]) == bearing:
        return name
    raise ConfigError(
        f"invalid {which} bearing = {name!r}: not a bearing preset; a description file names "
        "its bearings by preset (build this spindle in Python with a thermobear.Bearing)"
    )


def _bearing_of(bearing: dict[str, Any], which: str, named: bool) -> Any:
    """A configured bearing as its preset name; with ``named`` False, a
    bearing that is no preset (balls scaled by a calibration, a bearing
    built in Python) as a [`Bearing`][thermobear.Bearing] rebuilt from its
    stored data."""
    from ..bearing import Bearing

    try:
        return _preset_bearing_name(bearing, which)
    except ConfigError:
        if named:
            raise
    rebuild, (envelope,) = Bearing.preset(BASE_BEARING)._b.__reduce__()
    return Bearing(rebuild({**envelope, "data": json.dumps(bearing)}))


#: A preset whose stored envelope carries a rebuilt bearing's data.
BASE_BEARING = "7009C"


#: The spindle inputs of an extra heat at the front set (no part holds them).
EXTRA_HEAT_KEYS = (
    "extra_heat_w",
    "unknown_heat_linear_w",
    "unknown_heat_quadratic_w",
    "unknown_heat_reference_rpm",
)


def _no_extra_heat(cfg: dict[str, Any]) -> None:
    """A spindle with an extra heat at its front set (a calibrated
    member's unknown heat source) has no description: refused by name, so
    that a file never drops it silently."""
    for k in EXTRA_HEAT_KEYS[:3]:  # the heat and the law's coefficients
        v = float(cfg.get(k) or 0.0)
        if v != 0.0:
            raise ConfigError(
                f"invalid {k} = {v:g}: a spindle with an extra heat at its front bearing set "
                "(an unknown heat source) has no description file or parts; describe the "
                "spindle without it and give the heat to the call (Spindle.with_options)"
            )


def describe(native: Any, named: bool = True) -> dict[str, Any]:
    """The description (``Spindle`` keywords -> parts) of a native spindle;
    ``named``: bearings by preset name only (a description file's rule),
    else a bearing that is no preset comes back as a ``Bearing``."""
    cfg = json.loads(native.config_json())
    a = dict(native.assumptions())
    _no_extra_heat(cfg)
    params = cfg["params"]
    values: dict[str, dict[str, Any]] = {k: {} for k in PART_TYPES}
    for key, part, field, exponent in PARAM_FIELDS:
        values[part][field] = from_si(params[key], exponent)
    kind, data = next(iter(cfg["preload"].items()))
    values["preload"].update(kind=kind.lower(), preload_n=data["force_n"])
    if kind == "Spring":
        values["preload"]["spring_rate_n_per_um"] = from_si(data["rate_n_per_m"], 6)
    values["housing"]["assembly_temperature_c"] = cfg["assembly_temperature_c"]
    values["housing"]["outer_ring_contact_w_per_m2_k"] = params.get("outer_ring_contact_w_m2k")
    values["tool"]["radial_load_n"] = cfg["radial_load_n"]
    values["shaft"]["segments"] = tuple(
        ShaftSegment(*(from_si(x, -3) for x in seg)) for seg in params.get("shaft_segments_m") or ()
    )
    lub = values["lubrication"]
    lub.update(
        method=a["lubrication"], lubricant=params["lubricant"]["name"],
        lubrication_factor_f0=params["lubrication_factor_f0"],
        churning_oil_fraction=cfg["churning_oil_fraction"], heat_model=a["heat_model"],
        spin_friction_coefficient=cfg["spin_friction_coefficient"],
        load_friction_scale=cfg.get("load_friction_scale", 1.0),
        sliding_friction_ehl=cfg["skf"]["mu_ehl"],
        replenishment_krs=cfg["skf"]["replenishment_krs"],
        seal_moment_n_m=cfg["skf"]["seal_moment_n_m"],
    )  # fmt: skip
    supply = {k: a[k] for k in SUPPLY_KEYS if k in a}
    if supply:  # the drag follows the supply, not a fixed fraction
        lub.update(supply, churning_oil_fraction=None)
    effects = list(cfg["effects"])
    if PULL_EFFECT in effects:
        values["motor"]["magnetic_pull"] = _describe_pull(cfg["magnetic_pull"])
    out: dict[str, Any] = {"name": native.name}
    out.update({k: PART_TYPES[k](**v) for k, v in values.items()})
    for which in BEARING_TABLES:
        out[which] = _bearing_of(params[f"{which}_bearing"], which, named)
    base = [e for e in json.loads(_base_json())["effects"] if e != PULL_EFFECT]
    if sorted(e for e in effects if e != PULL_EFFECT) != sorted(base):
        out["effects"] = [e for e in effects if e != PULL_EFFECT]
    return out


def _describe_pull(holder: dict[str, Any]) -> MagneticPull:
    values = {"core_from_front_pair_mm": from_si(holder["core_from_front_pair_m"], -3)}
    for key, field, exponent in PULL_FIELDS:
        values[field] = from_si(holder["pull"][key], exponent)
    return MagneticPull(**values)


# -- TOML ------------------------------------------------------------------------
def _table(header: str, items: Mapping[str, Any], array: bool = False) -> list[str]:
    lines = [f"[[{header}]]" if array else f"[{header}]"]
    lines += [f"{k} = {toml_value(v)}" for k, v in items.items() if v is not None]
    return lines + [""]


def to_toml(native: Any) -> str:
    """The ``[spindle]`` description file of a native spindle."""
    d = describe(native)
    top = {"name": d["name"], "effects": d.get("effects")}
    lines = ["# A thermobear spindle description (thermobear.Spindle.from_toml).", ""]
    lines += _table("spindle", top)
    shaft = dict(vars(d["shaft"]))
    segments = shaft.pop("segments")
    lines += _table("spindle.shaft", shaft)
    for seg in segments:
        lines += _table("spindle.shaft.segment", vars(seg), array=True)
    for which in BEARING_TABLES:
        lines += _table(f"spindle.{which}", {"bearing": d[which], "arrangement": "DB", "rows": 2})
    motor = dict(vars(d["motor"]))
    pull = motor.pop("magnetic_pull")
    for key in ("preload", "housing"):
        lines += _table(f"spindle.{key}", vars(d[key]))
    lines += _table("spindle.motor", motor)
    if pull is not None:
        lines += _table("spindle.motor.magnetic_pull", vars(pull))
    for key in ("cooling", "lubrication", "tool"):
        lines += _table(f"spindle.{key}", vars(d[key]))
    return "\n".join(lines).rstrip() + "\n"


def _spindle_file(name: str) -> Optional[str]:
    """The text of the shipped description of preset ``name`` (None when
    ``name`` is not a preset)."""
    from importlib import resources

    if name.lower() not in _native.Spindle.preset_names():
        return None
    return resources.files(SPINDLE_FILES).joinpath("spindles", name.lower() + ".toml").read_text()


def read_description(source: str | Path) -> tuple[Optional[Path], str]:
    """(path or None, TOML text) of a preset name, a path or TOML text."""
    from ..config import read_text_file

    text = str(source)
    if isinstance(source, str) and (shipped := _spindle_file(text)) is not None:
        return None, shipped
    if isinstance(source, Path) or ("\n" not in text and "=" not in text):
        return Path(text), read_text_file(Path(text))
    return None, text


def parse_description(text: str) -> dict[str, Any]:
    """The ``Spindle`` keywords of a ``[spindle]`` description's TOML text
    (errors name the table and key; ``located_config_errors`` adds the
    line)."""
    doc = tomllib.loads(text)
    unknown = [k for k in doc if k != "spindle"]
    if "spindle" not in doc or not isinstance(doc["spindle"], dict):
        raise ConfigError("invalid key = spindle: a spindle description needs a [spindle] table")
    if unknown:
        raise ConfigError(f"invalid key = {unknown[0]!r}: a spindle description has [spindle] only")
    sp = doc["spindle"]
    known = (*TOP_KEYS, *BEARING_TABLES, *PART_TYPES)
    for key in sp:
        if key not in known:
            raise ConfigError(f"invalid key = {key!r}: unknown in [spindle]; known: "
                              + ", ".join(known) + val.did_you_mean(key, known))  # fmt: skip
    out: dict[str, Any] = {k: sp[k] for k in TOP_KEYS if k in sp}
    for which in BEARING_TABLES:
        if which in sp:
            out[which] = _located(f"spindle.{which}", BearingSet, _table_of(sp, which))
    for key, kind in PART_TYPES.items():
        if key in sp:
            table = dict(_table_of(sp, key))
            if key == "motor" and "magnetic_pull" in table:
                pull = _table_of(table, "magnetic_pull", "spindle.motor")
                table["magnetic_pull"] = _located("spindle.motor.magnetic_pull", MagneticPull, pull)
            if key == "shaft":
                table = _shaft_table(table)
            out[key] = _located(f"spindle.{key}", kind, table)
    return out


def _shaft_table(table: dict[str, Any]) -> dict[str, Any]:
    """The ``[spindle.shaft]`` keywords with its ``[[spindle.shaft.segment]]``
    tables read as ``segments`` (a ``segments`` key itself is unknown)."""
    out = dict(table)
    if "segments" in out:
        raise ConfigError(
            "invalid key = 'segments': unknown in [spindle.shaft]; give each step as a "
            "[[spindle.shaft.segment]] table"
        )
    segs = out.pop("segment", [])
    if not isinstance(segs, list) or not all(isinstance(g, dict) for g in segs):
        raise ConfigError(
            "invalid key = 'segment': must be tables [[spindle.shaft.segment]] in [spindle.shaft]"
        )
    out["segments"] = tuple(_located("spindle.shaft.segment", ShaftSegment, g) for g in segs)
    return out


def _table_of(parent: dict[str, Any], key: str, where: str = "spindle") -> dict[str, Any]:
    value = parent[key]
    if not isinstance(value, dict):
        raise ConfigError(f"invalid key = {key!r}: must be a table [{where}.{key}] in [{where}]")
    return value


def _located(table: str, kind: type, values: dict[str, Any]) -> Any:
    """``kind(**values)`` with an unknown key or a bad value named with its
    table (``in [table]``: the TOML error locator finds its line)."""
    from dataclasses import fields

    known = [f.name for f in fields(kind)]
    from dataclasses import MISSING

    for f in fields(kind):
        if f.default is MISSING and f.name not in values:
            raise ConfigError(f"invalid key = {f.name!r}: missing in [{table}]")
    for key in values:
        if key not in known:
            raise ConfigError(f"invalid key = {key!r}: unknown in [{table}]; known: "
                              + ", ".join(known) + val.did_you_mean(key, known))  # fmt: skip
    try:
        return kind(**values)
    except ConfigError as e:
        if "in [" in str(e):
            raise
        raise type(e)(f"{e} (in [{table}])") from None
