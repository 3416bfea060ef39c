"""A gear system as a description file: the ``[gear_system]`` TOML table
and back.

``[gear_system]`` holds the keywords of
[`GearSystem`][thermobear.GearSystem] by their own names (the bearings by
preset name or designation, the stiffness case, backlash, TE, damping,
torque, mesh model); ``[gear_system.gear]`` holds those of
[`GearPair.from_table`][thermobear.GearPair.from_table] (teeth, module,
angles, face width, material, masses, inertias); the optional tables
``[gear_system.mesh_stiffness_n_per_m]`` and
``[gear_system.transmission_error_um]`` hold one mesh period as columns
(``mesh_phase`` and the value column). Each value is checked here under
the name it has in the file; an error says ``invalid <key> = <value>:
... (in [<table>])`` so that ``config.located_config_errors`` can add the
file and line.

The way back reads the native state of a system (its SI values) and
writes each in the description's unit as the shortest decimal that the
core's own conversion (``x * 1e-3`` for mm, ``x * pi / 180`` for degrees,
...) takes back to the same float, so ``to_toml`` -> ``from_toml`` gives
the same system to the last bit; ``to_toml`` rebuilds the system from the
text it wrote and refuses one the text would not give back (a calibrated
bearing model, a stiffness frame, a bearing that is no preset).

This module does not import ``system`` (``GearSystem`` calls it), so the
system is passed in and the rebuild is the caller's ``from_toml``.
"""

from __future__ import annotations

import json
import math
import re
import tomllib
from importlib import resources
from pathlib import Path
from typing import Any, Callable, Mapping, Optional, Union

import numpy as np

from .. import _validate as val
from .._toml_text import toml_value
from ..errors import ConfigError
from .pair import MAX_MESH_POINTS, STIFFNESS_SPEEDS_RPM, GearPair
from .tables import mesh_period_samples

#: The top table and the gear pair's table.
TOP = "gear_system"
GEAR = "gear_system.gear"
#: Package folder of the shipped description files (``configs/gears``).
GEAR_FILES = "thermobear.configs"
GEAR_FOLDER = "gears"
#: The fewest teeth the core accepts on either gear (``MIN_TEETH`` of the
#: Rust gear geometry).
MIN_TEETH = 6
STIFFNESS_CASES = ("constant", "speed", "thermal")
MESH_MODELS = ("potential-energy", "iso")
MESH_DAMPING = ("in-contact", "always")

#: Key -> the comment ``to_toml`` writes beside it (unit; meaning).
NOTES: dict[str, str] = {
    "bearings": "bearing on each shaft: a preset name or a catalogue designation",
    "stiffness": "support stiffness: constant, speed (quasi-static) or thermal",
    "bearings_per_shaft": "identical bearings per shaft, in parallel",
    "stiffness_speeds_rpm": "rpm; speeds where the support stiffness is solved",
    "torque_n_m": "N m; input torque on the pinion (negative: coast)",
    "half_backlash_um": "um; half the backlash b (the clearance is 2b)",
    "backlash_total_um": "um; the whole backlash 2b",
    "te_amplitude_um": "um; amplitude of the first-harmonic static transmission error",
    "mesh_damping_ratio": "1; viscous damping ratio of the mesh",
    "mesh_damping": "in-contact (only while teeth touch) or always",
    "bearing_damping_ratio": "1; damping ratio of the bearing supports",
    "mesh_model": "mesh stiffness: potential-energy or iso",
    "table_points": "samples per mesh period of the stiffness and TE tables",
    "mesh_stiffness_scale": "1; factor on the mesh stiffness",
    "pinion_teeth": "teeth of the pinion (the driving gear)",
    "gear_teeth": "teeth of the driven gear",
    "normal_module_mm": "mm; normal module",
    "normal_pressure_angle_deg": "deg; normal pressure angle, in (0, 45]",
    "helix_angle_deg": "deg; helix angle, in [0, 45)",
    "face_width_mm": "mm; face width",
    "profile_shift_coeff": "1; profile shift x, [pinion, gear]",
    "addendum_coeff": "1; basic-rack addendum over the module",
    "dedendum_coeff": "1; basic-rack dedendum over the module",
    "youngs_modulus_mpa": "MPa; Young's modulus of both gears",
    "poisson_ratio": "1; Poisson's ratio of both gears",
    "density_t_per_mm3": "t/mm^3; density (7.8e-9 t/mm^3 is 7800 kg/m^3)",
    "mass_kg": "kg; masses, [pinion, gear]",
    "polar_inertia_t_mm2": "t mm^2; polar inertias, [pinion, gear] (1 t mm^2 = 1e-3 kg m^2)",
    "input_torque_n_m": "N m; the pair's own input torque (torque_n_m above acts)",
    "mesh_phase": "1; fraction of one mesh period",
    "normal_stiffness_n_per_m": "N/m; mesh stiffness along the normal deflection",
    "transverse_stiffness_n_per_m": "N/m; mesh stiffness in the transverse plane",
    "transmission_error_um": "um; static transmission error",
}

#: The mesh-period tables: name -> the value columns it may hold and their
#: factor to the SI the core takes.
TABLES: dict[str, dict[str, float]] = {
    "mesh_stiffness_n_per_m": {
        "normal_stiffness_n_per_m": 1.0,
        "transverse_stiffness_n_per_m": 1.0,
    },
    "transmission_error_um": {"transmission_error_um": 1e-6},
}
PHASE = "mesh_phase"


# -- checks of single values -----------------------------------------------------
def _real(lo: float = -math.inf, *, open_lo: bool = False) -> Callable[[str, Any], float]:
    return lambda name, v: val.real(name, v, lo, open_lo=open_lo)


def _choice(options: tuple[str, ...]) -> Callable[[str, Any], Any]:
    return lambda name, v: val.choice(name, v, options)


def _interval(lo: float, hi: float, shown: str) -> Callable[[str, Any], float]:
    """A real strictly inside (lo, hi) or on an end that ``shown`` closes."""

    def check(name: str, v: Any) -> float:
        x = val.real(name, v)
        inside = (lo < x or (shown[0] == "[" and x == lo)) and (
            x < hi or (shown[-1] == "]" and x == hi)
        )
        if not inside:
            raise val.fail(name, v, f"a finite number in {shown}")
        return x

    return check


def _teeth(name: str, v: Any) -> int:
    n = val.whole(name, v, 0, None)
    if not MIN_TEETH <= n <= 100_000:
        raise val.fail(name, v, f"a whole number >= {MIN_TEETH} (and at most 100000)")
    return n


def _speeds(name: str, v: Any) -> list[float]:
    s = val.reals(name, v, 0.0)
    if np.any(s <= 0.0) or np.any(np.diff(s) <= 0.0):
        raise val.fail(name, v, "positive speeds, strictly ascending")
    return [float(x) for x in s]


#: Key of ``[gear_system]`` -> its check (returns the value to pass on).
SYSTEM_CHECKS: dict[str, Callable[[str, Any], Any]] = {
    "bearings": val.text,
    "stiffness": _choice(STIFFNESS_CASES),
    "bearings_per_shaft": lambda name, v: val.whole(name, v, 1),
    "stiffness_speeds_rpm": _speeds,
    "torque_n_m": _real(),
    "half_backlash_um": _real(0.0, open_lo=True),
    "backlash_total_um": _real(0.0, open_lo=True),
    "te_amplitude_um": _real(),
    "mesh_damping_ratio": _real(0.0),
    "mesh_damping": _choice(MESH_DAMPING),
    "bearing_damping_ratio": _real(0.0),
    "mesh_model": _choice(MESH_MODELS),
    "table_points": lambda name, v: val.whole(name, v, 2, MAX_MESH_POINTS),
    "mesh_stiffness_scale": _real(0.0, open_lo=True),
}

#: Key of ``[gear_system.gear]`` -> its check; the ranges are the core's.
GEAR_CHECKS: dict[str, Callable[[str, Any], Any]] = {
    "pinion_teeth": _teeth,
    "gear_teeth": _teeth,
    "normal_module_mm": _real(0.0, open_lo=True),
    "normal_pressure_angle_deg": _interval(0.0, 45.0, "(0, 45]"),
    "helix_angle_deg": _interval(0.0, 45.0, "[0, 45)"),
    "face_width_mm": _real(0.0, open_lo=True),
    "profile_shift_coeff": val.pair,
    "addendum_coeff": _interval(0.5, 1.5, "[0.5, 1.5]"),
    "dedendum_coeff": _interval(0.0, 2.0, "(0, 2]"),
    "youngs_modulus_mpa": _real(0.0, open_lo=True),
    "poisson_ratio": _interval(0.0, 0.5, "(0, 0.5)"),
    "density_t_per_mm3": _real(0.0, open_lo=True),
    "mass_kg": lambda name, v: val.pair(name, v, 0.0),
    "polar_inertia_t_mm2": lambda name, v: val.pair(name, v, 0.0),
    "input_torque_n_m": _real(),
}
#: The keys ``GearPair.from_table`` needs (the others have its defaults).
GEAR_REQUIRED = tuple(
    k for k in GEAR_CHECKS if k not in ("profile_shift_coeff", "addendum_coeff", "dedendum_coeff")
)


def _checked(table: str, check: Callable[[str, Any], Any], key: str, value: Any) -> Any:
    """``check(key, value)`` with an error naming its table."""
    try:
        return check(key, value)
    except ConfigError as e:
        raise type(e)(f"{e} (in [{table}])") from None


def _known(table: str, given: Mapping[str, Any], known: tuple[str, ...]) -> None:
    """Refuse an unknown key (a sub-table by its header, so that its line
    is found) with the closest known one."""
    for key, value in given.items():
        if key in known:
            continue
        hint = f"; known: {', '.join(known)}" + val.did_you_mean(key, known)
        if isinstance(value, dict):
            raise ConfigError(f"invalid key = {table}.{key}: an unknown table{hint}")
        raise ConfigError(f"invalid key = {key!r}: unknown in [{table}]{hint}")


def _sub_table(parent: Mapping[str, Any], key: str) -> dict[str, Any]:
    value = parent[key]
    if not isinstance(value, dict):
        raise ConfigError(f"invalid key = {key!r}: must be a table [{TOP}.{key}] in [{TOP}]")
    return value


# -- TOML -> GearSystem keywords ---------------------------------------------------
def parse_description(text: str) -> dict[str, Any]:
    """The ``GearSystem`` keywords of a ``[gear_system]`` description's TOML
    text (the pair and the bearing built): every value checked, an error
    naming its key and table."""
    doc = tomllib.loads(text)
    for key in doc:
        if key != TOP:
            raise ConfigError(
                f"invalid key = {key!r}: a gear system description has [{TOP}] only"
                + val.did_you_mean(key, [TOP])
            )
    if not isinstance(doc.get(TOP), dict):
        raise ConfigError(f"invalid key = {TOP}: a gear system description needs a [{TOP}] table")
    top = doc[TOP]
    _known(TOP, top, (*SYSTEM_CHECKS, "gear", *TABLES))
    if "gear" not in top:
        raise ConfigError(f"invalid {TOP} = table without [{GEAR}]: the gear pair is needed")
    if "half_backlash_um" in top and "backlash_total_um" in top:
        raise ConfigError(
            f"invalid backlash_total_um = {top['backlash_total_um']!r}: give half_backlash_um "
            f"(b) or backlash_total_um (2b), not both (in [{TOP}])"
        )
    out: dict[str, Any] = {"gear": gear_pair(_sub_table(top, "gear"))}
    for key, check in SYSTEM_CHECKS.items():
        if key in top and not isinstance(top[key], dict):
            out[key] = _checked(TOP, check, key, top[key])
        elif key in top:
            raise ConfigError(f"invalid key = {key!r}: a value, not a table (in [{TOP}])")
    out["bearings"] = _bearing(out.get("bearings", "6208"))
    z = int(out["gear"].geometry["pinion_teeth"])
    points = int(out.get("table_points", 64))
    for name in TABLES:
        if name in top:
            out[name] = mesh_table(name, _sub_table(top, name), z, points)
    return out


def gear_pair(table: Mapping[str, Any]) -> GearPair:
    """The pair of ``[gear_system.gear]`` (``GearPair.from_table``)."""
    _known(GEAR, table, tuple(GEAR_CHECKS))
    for key in GEAR_REQUIRED:
        if key not in table:
            raise ConfigError(f"invalid {GEAR} = table without {key!r}: the pair needs it")
    values = {k: _checked(GEAR, GEAR_CHECKS[k], k, v) for k, v in table.items()}
    if values.get("dedendum_coeff", 1.25) < values.get("addendum_coeff", 1.0):
        raise ConfigError(
            f"invalid dedendum_coeff = {values.get('dedendum_coeff', 1.25):g}: must be at least "
            f"the addendum_coeff (in [{GEAR}])"
        )
    try:
        return GearPair.from_table(**values)
    except ConfigError as e:
        raise _gear_error(e, values) from None


def _gear_error(error: ConfigError, values: Mapping[str, Any]) -> ConfigError:
    """A core error about the pair, named by the description's key: the
    pinion's and gear's values are the entries of one pair key, and the
    angles are given in degrees."""
    m = re.match(r"^invalid (\w+) = ([^:]+): (.*)$", str(error), re.S)
    if m is None:
        return type(error)(f"invalid {GEAR} = table: {error}")
    name, shown, why = m.groups()
    for prefix in ("pinion_", "gear_"):
        base = name[len(prefix) :]
        if name.startswith(prefix) and base in GEAR_CHECKS:
            which = 0 if prefix == "pinion_" else 1
            return type(error)(f"invalid {base}[{which}] = {shown}: {why} (in [{GEAR}])")
    if name.endswith("_rad") and name[:-4] + "_deg" in GEAR_CHECKS:
        key = name[:-4] + "_deg"
        return type(error)(f"invalid {key} = {values[key]:g}: {why} (in [{GEAR}])")
    if name in GEAR_CHECKS:
        return type(error)(f"invalid {name} = {shown}: {why} (in [{GEAR}])")
    return type(error)(f"invalid {GEAR} = table: {error}")


def _bearing(name: str) -> Any:
    from ..bearing import Bearing

    try:
        return Bearing.preset(name)
    except ConfigError as e:
        hint = val.did_you_mean(name, Bearing.preset_names())
        raise type(e)(
            f"invalid bearings = {name!r}: not a bearing preset or designation{hint} "
            f"(in [{TOP}]; {e})"
        ) from None


def mesh_table(name: str, table: Mapping[str, Any], pinion_teeth: int, points: int) -> Any:
    """The columns of a mesh-period table (``mesh_phase`` and one value
    column), checked as the gear system will use them."""
    where = f"{TOP}.{name}"
    _known(where, table, (PHASE, *TABLES[name]))
    values = [c for c in TABLES[name] if c in table]
    if PHASE not in table or len(values) != 1:
        raise ConfigError(
            f"invalid {where} = table with {sorted(table)}: give {PHASE} and one of "
            + ", ".join(TABLES[name])
        )
    cols = {c: _checked(where, val.reals, c, table[c]).tolist() for c in (PHASE, values[0])}
    try:
        mesh_period_samples(name, TABLES[name], 1.0, cols, pinion_teeth, points)
    except ConfigError as e:
        raise type(e)(f"invalid {PHASE} = table: {e} (in [{where}])") from None
    return cols


def read_description(source: Union[str, Path]) -> tuple[Optional[Path], str]:
    """(path or None, TOML text) of a shipped file's name, a path or TOML
    text."""
    from ..config import read_text_file

    text = str(source)
    if isinstance(source, str) and "\n" not in text and text in shipped_names():
        return None, shipped_text(text)
    if isinstance(source, Path) or ("\n" not in text and "=" not in text):
        return Path(text), read_text_file(Path(text))
    return None, text


def shipped_names() -> list[str]:
    """Names of the shipped gear system descriptions (``configs/gears``)."""
    folder = resources.files(GEAR_FILES).joinpath(GEAR_FOLDER)
    if not folder.is_dir():
        return []
    return sorted(p.name[:-5] for p in folder.iterdir() if p.name.endswith(".toml"))


def shipped_text(name: str) -> str:
    """The text of a shipped gear system description."""
    return resources.files(GEAR_FILES).joinpath(GEAR_FOLDER, name + ".toml").read_text()


# -- GearSystem -> TOML ----------------------------------------------------------
def _state(native: Any) -> dict[str, Any]:
    """The saved state of a native object (its exact SI values)."""
    return dict(json.loads(native.__reduce__()[1][0]["data"]))


def in_unit(si: float, to_si: Callable[[float], float], name: str) -> float:
    """The shortest decimal ``x`` with ``to_si(x) == si`` (the value a
    description writes for an SI value the core holds)."""
    guess = si / to_si(1.0)
    for digits in range(1, 18):
        x = float(f"{guess:.{digits}g}")
        if to_si(x) == si:
            return x
    up = down = guess
    for _ in range(64):
        for x in (up, down):
            if to_si(x) == si:
                return x
        up, down = math.nextafter(up, math.inf), math.nextafter(down, -math.inf)
    raise ConfigError(f"invalid {name} = {si!r}: no value in the description's unit gives it back")


def _times(factor: float) -> Callable[[float], float]:
    return lambda x: x * factor


def describe_gear(pair: GearPair) -> dict[str, Any]:
    """The ``[gear_system.gear]`` values of a pair."""
    s = _state(pair._g)["spec"]
    wheels = s["wheels"]
    if any(w["tip_alteration_coeff"] != 0.0 or w["bore_radius_m"] is not None for w in wheels):
        raise ConfigError(
            f"invalid gear = {pair!r}: a tip alteration or a bore is not part of a description"
        )
    inertia = [in_unit(w["polar_inertia_kg_m2"], _times(1e-3), "polar_inertia") for w in wheels]
    return {
        "pinion_teeth": int(wheels[0]["teeth"]),
        "gear_teeth": int(wheels[1]["teeth"]),
        "normal_module_mm": in_unit(s["normal_module_m"], _times(1e-3), "normal_module_mm"),
        "normal_pressure_angle_deg": in_unit(
            s["normal_pressure_angle_rad"], math.radians, "normal_pressure_angle_deg"
        ),
        "helix_angle_deg": in_unit(s["helix_angle_rad"], math.radians, "helix_angle_deg"),
        "face_width_mm": in_unit(s["face_width_m"], _times(1e-3), "face_width_mm"),
        "profile_shift_coeff": [float(w["profile_shift_coeff"]) for w in wheels],
        "addendum_coeff": float(s["addendum_coeff"]),
        "dedendum_coeff": float(s["dedendum_coeff"]),
        "youngs_modulus_mpa": in_unit(s["youngs_modulus_pa"], _times(1e6), "youngs_modulus_mpa"),
        "poisson_ratio": float(s["poisson_ratio"]),
        "density_t_per_mm3": in_unit(s["density_kg_m3"], _times(1e12), "density_t_per_mm3"),
        "mass_kg": [float(w["mass_kg"]) for w in wheels],
        "polar_inertia_t_mm2": inertia,
        "input_torque_n_m": float(s["input_torque_n_m"]),
    }


def _bearing_name(bearing: Any) -> str:
    """The preset name (or designation) of a bearing that it rebuilds to
    the last bit; a ConfigError for any other bearing."""
    from ..bearing import Bearing

    name = str(getattr(bearing, "name", ""))
    try:
        same = _state(Bearing.preset(name)._b) == _state(bearing._b)
    except ConfigError:
        same = False
    if not same:
        raise ConfigError(
            f"invalid bearings = {name!r}: not a bearing preset or designation; a description "
            "names its bearings by preset (build this system in Python with the Bearing)"
        )
    return name


def describe(system: Any) -> dict[str, dict[str, Any]]:
    """The description of a gear system: table name -> its values."""
    if system.stiffness_case not in STIFFNESS_CASES:
        raise ConfigError(
            f"invalid stiffness = {system.stiffness_case!r}: a description holds a computed "
            f"case ({', '.join(STIFFNESS_CASES)}); a stiffness frame cannot be written"
        )
    st = _state(system._s)
    top: dict[str, Any] = {
        "bearings": _bearing_name(system.bearing),
        "stiffness": system.stiffness_case,
        "bearings_per_shaft": system.bearings_per_shaft,
    }
    speeds = [float(row[0]) for row in st["schedule"]]
    if system.stiffness_case != "constant" and speeds != STIFFNESS_SPEEDS_RPM.tolist():
        top["stiffness_speeds_rpm"] = speeds
    top["torque_n_m"] = float(st["spec"]["input_torque_n_m"])
    top["half_backlash_um"] = in_unit(st["half_backlash_m"], _times(1e-6), "half_backlash_um")
    if st["transmission_error_m"] is None:
        top["te_amplitude_um"] = in_unit(st["te_amplitude_m"], _times(1e-6), "te_amplitude_um")
    for key in ("mesh_damping_ratio", "mesh_damping", "bearing_damping_ratio"):
        top[key] = st[key]
    if st["mesh_stiffness_n_per_m"] is None:
        top["mesh_model"] = st["mesh_model"]
    top["table_points"] = int(st["table_points"])
    top["mesh_stiffness_scale"] = float(st["mesh_stiffness_scale"])
    out = {TOP: top, GEAR: describe_gear(system.gear)}
    k, e = st["mesh_stiffness_n_per_m"], st["transmission_error_m"]
    if k is not None:
        out[f"{TOP}.mesh_stiffness_n_per_m"] = _period("normal_stiffness_n_per_m", k, 1.0)
    if e is not None:
        out[f"{TOP}.transmission_error_um"] = _period("transmission_error_um", e, 1e-6)
    return out


def _period(column: str, si: list[float], factor: float) -> dict[str, Any]:
    n = len(si)
    values = [in_unit(float(v), _times(factor), column) for v in si]
    return {PHASE: [i / n for i in range(n)], column: values}


def render(tables: Mapping[str, Mapping[str, Any]]) -> str:
    """The TOML text of a description (a comment with unit and meaning
    beside every key)."""
    lines = ["# A thermobear gear system description (thermobear.GearSystem.from_toml).", ""]
    for header, items in tables.items():
        lines.append(f"[{header}]")
        for key, value in items.items():
            if value is None:
                continue
            text = toml_value(value, per_line=4)
            note = f"  # {NOTES[key]}" if key in NOTES else ""
            if "\n" in text:  # the comment on the opening line of the array
                first, rest = text.split("\n", 1)
                lines.append(f"{key} = {first}{note}\n{rest}")
            else:
                lines.append(f"{key} = {text}{note}")
        lines.append("")
    return "\n".join(lines).rstrip() + "\n"


def _differences(a: Any, b: Any) -> list[str]:
    """What of gear system ``b`` differs from ``a`` (empty when the same)."""
    sa, sb = _state(a._s), _state(b._s)
    out = [k for k in sa if sa[k] != sb.get(k)]
    if _state(a.gear._g)["spec"] != _state(b.gear._g)["spec"]:
        out.append("gear")
    for attr in ("stiffness_case", "bearings_per_shaft", "bearing_stiffness_per"):
        if getattr(a, attr) != getattr(b, attr):
            out.append(attr)
    return out


def to_toml(system: Any, rebuild: Callable[[str], Any], path: Union[str, Path, None] = None) -> str:
    """The description of ``system``, checked by building the system again
    from it (``rebuild``: ``GearSystem.from_toml``); written to ``path``
    when given."""
    text = render(describe(system))
    differ = _differences(system, rebuild(text))
    if differ:
        raise ConfigError(
            f"invalid gear system = {system!r}: its description would not give it back "
            f"({', '.join(differ)} differ: a calibrated bearing model's load scales or "
            "options are not part of a description)"
        )
    if path is not None:
        try:
            Path(path).write_text(text, encoding="utf-8")
        except OSError as e:
            raise ConfigError(f"{path}: cannot write: {e.strerror or e}") from None
    return text
