"""The kinds of point a study computes: their inputs (with units and
defaults) and how a chunk of points is computed.

Every kind maps a frame of input rows to a frame of outputs with the same
number of rows, a fixed schema, and ``ok``, ``error_kind``, ``error``: a
point that fails (no convergence, thermal runaway, a setting the model
rejects) is a row with its error and null outputs, never an exception.

* ``bearing``: the quasi-static solve at speed
([`Bearing.solve_many`][thermobear.Bearing.solve_many]);
* ``thermal``: the coupled thermal state of one bearing
  ([`thermobear.thermal_state`][thermobear.thermal_state], batched);
* ``spindle``: the coupled steady state of a spindle
  ([`Spindle.thermal_state`][thermobear.Spindle.thermal_state]);
* ``gear``: the motion regime of the gear system at a speed
  ([`thermobear.regime_map`][thermobear.regime_map] of one cell);
* ``prediction``: a calibrated model's outputs at a condition and a sample
  of its calibrated values (defined, and registered with
  ``register_kind``, by ``thermobear.predict.engine``).

``thermal``, ``spindle`` and ``gear`` take an optional ``model``: a
calibrated model (stored as its JSON text, ``study.models``) in place of
the bearing or spindle preset, its calibrated options applied as
``thermal_state`` applies them (a setting at the kind's default takes the
calibrated value; another one must agree, or the point is a ConfigError).
"""

from __future__ import annotations

from concurrent.futures import ThreadPoolExecutor
from dataclasses import dataclass
from typing import Any, Callable, Optional

from .._limits import available_cores, cap_threads
from .._model_hook import merge_options, scaled_load
from .._types import StiffnessMode, StudyKind
from ..errors import ConfigError, ThermobearError
from ..thermal.state import DEFAULT_SPIN_FRICTION_COEFFICIENT, HEAT_MODEL_OPTIONS
from .models import model_of, model_shown, model_text

Runner = Callable[["Kind", Any, Optional[int]], Any]


@dataclass(frozen=True)
class Param:
    """One input of a kind: a grid dimension or a fixed setting."""

    name: str
    type: type
    default: Any
    doc: str
    #: A column of the native batch call (speed, loads); the other inputs
    #: define the model, and points are grouped by them.
    per_point: bool = False
    #: Checks a value (raises ConfigError), e.g. a preset name.
    check: Optional[Callable[[Any], None]] = None
    #: Turns a given value into the one the study stores and hashes (e.g. a
    #: calibrated model, or the path of its file, into its JSON text); given
    #: that stored value again it returns it unchanged.
    convert: Optional[Callable[[Any], Any]] = None
    #: What the input column shows of a stored value (e.g. a short hash of
    #: a model's JSON text instead of the text in every row).
    show: Optional[Callable[[Any], Any]] = None


@dataclass(frozen=True)
class Kind:
    """A kind of point: its inputs, its outputs (name -> polars dtype name)
    and the function that computes a chunk."""

    name: StudyKind
    doc: str
    params: tuple[Param, ...]
    outputs: tuple[tuple[str, str], ...]
    run: Runner

    def param(self, name: str) -> Param:
        for p in self.params:
            if p.name == name:
                return p
        known = ", ".join(p.name for p in self.params)
        raise ConfigError(
            f"invalid key = {name!r}: not an input of a {self.name} point; known: {known}"
        )

    def compute(self, inputs: Any, threads: Optional[int] = None) -> Any:
        """Outputs of the input rows (fixed schema, same height)."""
        import polars as pl

        out = self.run(self, inputs, threads)
        schema = {n: getattr(pl, t) for n, t in self.outputs}
        schema.update(ok=pl.Boolean, error_kind=pl.String, error=pl.String)
        missing = [c for c in schema if c not in out.columns]
        out = out.with_columns(pl.lit(None).alias(c) for c in missing)
        return out.select(pl.col(c).cast(t) for c, t in schema.items())


# -- checks of names --------------------------------------------------------


def _choice(names: Callable[[], list[str]], what: str) -> Callable[[Any], None]:
    def check(value: Any) -> None:
        known = names()
        if value not in known:
            raise ConfigError(f"invalid {what} = {value!r}: unknown; known: {', '.join(known)}")

    return check


def _bearing_names() -> list[str]:
    from ..bearing import Bearing

    return Bearing.preset_names()


def _material_names() -> list[str]:
    from ..bearing import Material

    return Material.preset_names()


def _spindle_names() -> list[str]:
    from ..spindle import Spindle

    return Spindle.preset_names()


def _gear_names() -> list[str]:
    from ..gear import GearPair

    return GearPair.preset_names()


def _check_lubricant(name: Any) -> None:
    # The network of any bearing names the lubricant's data; the native
    # side rejects an unknown preset with the known ones listed.
    from .. import _native
    from ..bearing import Bearing

    _native.seed_a_network_links(Bearing.preset("6208")._b, 0.0, lubricant=str(name))


def _check_lubrication(name: Any) -> None:
    from .. import _native

    _native.lubrication_defaults(str(name), "angular_contact")


def _one_of(what: str, *values: str) -> Callable[[Any], None]:
    return _choice(lambda: list(values), what)


# -- shared helpers -------------------------------------------------------------


def _error_row(e: BaseException) -> dict:
    return {"ok": False, "error_kind": type(e).__name__, "error": str(e)}


def _solve_rows(solve: Callable[[dict, Any], Any], keys: list[str], rows: Any) -> Any:
    """``solve(model, rows)`` for rows of one model; its ThermobearError
    becomes every row's error."""
    import polars as pl

    try:
        return solve({k: rows[k][0] for k in keys}, rows)
    except ThermobearError as e:
        err = _error_row(e)
        return pl.DataFrame({k: [v] * rows.height for k, v in err.items()})


def _grouped(kind: Kind, inputs: Any, solve: Callable[[dict, Any], Any]) -> Any:
    """Group the rows by the model inputs, ``solve(model, rows)`` each group
    and put the rows back in input order."""
    import polars as pl

    keys = [p.name for p in kind.params if not p.per_point]
    if all(inputs[k].n_unique() == 1 for k in keys):  # one model: no regrouping
        return _solve_rows(solve, keys, inputs)
    frame = inputs.with_row_index("_row")
    parts = [
        _solve_rows(solve, keys, rows).with_columns(rows["_row"])
        for _, rows in frame.group_by(keys, maintain_order=True)
    ]
    return pl.concat(parts, how="diagonal_relaxed").sort("_row").drop("_row")


def _row_map(inputs: Any, threads: Optional[int], point: Callable[[dict], dict]) -> Any:
    """``point(row) -> outputs`` over the rows in a thread pool (the native
    calls release the GIL); a ThermobearError becomes the row's error."""
    import polars as pl

    def safe(row: dict) -> dict:
        try:
            return {**point(row), "ok": True, "error_kind": None, "error": None}
        except ThermobearError as e:
            return _error_row(e)

    rows = inputs.to_dicts()
    workers = max(1, min(len(rows), cap_threads(threads) or available_cores()))
    pool = ThreadPoolExecutor(max_workers=workers)
    try:
        out = list(pool.map(safe, rows))
    except BaseException:
        # Ctrl-C (or an error): drop the rows not started, wait only for the
        # ones running (each a short native call).
        pool.shutdown(wait=True, cancel_futures=True)
        raise
    pool.shutdown(wait=True)
    return pl.DataFrame(out, infer_schema_length=None)


_BEARING_OUTPUTS = (
    ("axial_stiffness_seed_n_per_m", "Float64"),
    ("radial_stiffness_seed_n_per_m", "Float64"),
    ("k_xx_n_per_m", "Float64"),
    ("k_zz_n_per_m", "Float64"),
    ("k_ryry_n_m_per_rad", "Float64"),
    ("axial_displacement_um", "Float64"),
    ("radial_displacement_um", "Float64"),
    ("tilt_rad", "Float64"),
    ("inner_contact_angle_max_deg", "Float64"),
    ("inner_contact_angle_min_deg", "Float64"),
    ("outer_contact_angle_max_deg", "Float64"),
    ("outer_contact_angle_min_deg", "Float64"),
    ("inner_load_max_n", "Float64"),
    ("outer_load_max_n", "Float64"),
    ("centrifugal_force_n", "Float64"),
    ("cage_speed_rpm", "Float64"),
    ("residual", "Float64"),
    ("iterations", "Int64"),
)

_LOADS = (
    Param("speed_rpm", float, 0.0, "inner-ring (shaft) speed [rpm]", per_point=True),
    Param("axial_n", float, 0.0, "external axial load [N]", per_point=True),
    Param("preload_n", float, 0.0, "axial preload [N], added to axial_n", per_point=True),
    Param("radial_n", float, 0.0, "radial load [N]", per_point=True),
)


def _loads(rows: Any) -> dict:
    import polars as pl

    return {
        "speed_rpm": rows["speed_rpm"],
        "axial_n": rows.select(pl.col("axial_n") + pl.col("preload_n")).to_series(),
        "radial_n": rows["radial_n"],
    }


def _bearing_of(name: str) -> Any:
    from ..bearing import Bearing

    return Bearing.preset(str(name))


# -- a calibrated model in place of a preset ------------------------------------------


def _model_param(preset: str) -> Param:
    """The optional ``model`` input of a kind whose ``preset`` input it replaces."""
    return Param(
        "model",
        str,
        "",
        f"calibrated model (the object, its saved JSON file or text; column: SHA-256 key): "
        f"replaces the {preset} preset, its calibrated options apply; '' none",
        convert=model_text,
        show=model_shown,
    )


def _calibrated(kind: Kind, key: str, preset: str, name: str) -> tuple[Any, dict[str, Any]]:
    """``(machine, options)`` of the calibrated model of a ``model`` key
    (``CalibratedModel.model``). The ``preset`` input it replaces must be
    left at its default, and the model's machine must be that kind's."""
    from ..bearing import Bearing

    default = kind.param(preset).default
    if name != default:
        raise ConfigError(
            f"invalid {preset} = {name!r}: the calibrated model replaces the {preset} preset; "
            f"leave {preset} at its default {default!r} when model is given"
        )
    machine, options = model_of(key).model()
    if (preset == "spindle") == isinstance(machine, Bearing):
        raise ConfigError(
            f"invalid model = {key!r}: a model of a {type(machine).__name__}; "
            f"a {kind.name} point takes a model of a {preset}"
        )
    return machine, dict(options)


def _given(kind: Kind, settings: dict[str, Any]) -> dict[str, Any]:
    """The settings not at the kind's default: those a calibrated option
    must agree with (a setting at its default takes the calibrated value)."""
    return {k: v for k, v in settings.items() if v is not None and v != kind.param(k).default}


# -- bearing ----------------------------------------------------------------------


def _run_bearing(kind: Kind, inputs: Any, threads: Optional[int]) -> Any:
    import polars as pl

    def solve(model: dict, rows: Any) -> Any:
        out = _bearing_of(model["bearing"]).solve_many(
            pl.DataFrame(_loads(rows)),
            raceway_control=model["raceway_control"],
            misalignment_rad=model["misalignment_rad"],
            threads=threads,
        )
        return out.drop("speed_rpm", "axial_n", "radial_n")

    return _grouped(kind, inputs, solve)


BEARING = Kind(
    "bearing",
    "quasi-static solve of one bearing at speed (ring tilt held at misalignment_rad)",
    (
        Param(
            "bearing",
            str,
            "7008C",
            "bearing preset (thermobear presets)",
            check=_choice(_bearing_names, "bearing"),
        ),
        *_LOADS,
        Param(
            "raceway_control",
            str,
            "outer",
            "'outer' or 'inner'",
            check=_one_of("raceway_control", "outer", "inner"),
        ),
        Param("misalignment_rad", float, 0.0, "inner-ring tilt, held [rad]"),
    ),
    _BEARING_OUTPUTS,
    _run_bearing,
)


# -- thermal ----------------------------------------------------------------------

_THERMAL_OUTPUTS = _BEARING_OUTPUTS + (
    ("shaft_temperature_c", "Float64"),
    ("inner_ring_temperature_c", "Float64"),
    ("ball_temperature_c", "Float64"),
    ("outer_ring_temperature_c", "Float64"),
    ("housing_temperature_c", "Float64"),
    ("oil_temperature_c", "Float64"),
    ("viscosity_cst", "Float64"),
    ("heat_w", "Float64"),
    ("load_heat_w", "Float64"),
    ("viscous_heat_w", "Float64"),
    ("spin_heat_w", "Float64"),
    ("churning_heat_w", "Float64"),
    ("radial_thermal_offset_um", "Float64"),
    ("axial_thermal_offset_um", "Float64"),
    ("ball_growth_um", "Float64"),
    ("centrifugal_expansion_um", "Float64"),
    ("thermal_residual_k", "Float64"),
    ("thermal_iterations", "Int64"),
)


def _run_thermal(kind: Kind, inputs: Any, threads: Optional[int]) -> Any:
    import polars as pl

    from ..thermal import thermal_state_many

    def solve(model: dict, rows: Any) -> Any:
        settings = {k: v for k, v in model.items() if k not in ("bearing", "model")}
        loads = _loads(rows)
        if model["model"]:
            bearing, settings, loads = _thermal_model(kind, model, settings, loads)
        else:
            bearing = _bearing_of(model["bearing"])
        out = thermal_state_many(bearing, pl.DataFrame(loads), threads=threads, **settings)
        return out.drop("speed_rpm", "axial_n", "radial_n")

    return _grouped(kind, inputs, solve)


def _thermal_model(
    kind: Kind, model: dict, settings: dict[str, Any], loads: dict
) -> tuple[Any, dict[str, Any], dict]:
    """A thermal point of a calibrated model: its bearing, the settings
    with its options (as ``thermal_state`` takes them from the model: a
    setting off its default must agree) and the loads scaled as the
    calibration applied them to the stated ones (``preload_n`` included)."""
    import polars as pl

    bearing, options = _calibrated(kind, model["model"], "bearing", model["bearing"])
    accepted = {p.name for p in kind.params} | {"effects"} | set(HEAT_MODEL_OPTIONS)
    merged = {**settings, **merge_options(options, _given(kind, settings), accepted)}
    for scale, arg in (("axial_load_scale", "axial_n"), ("radial_load_scale", "radial_n")):
        stated = loads[arg].cast(pl.Float64).to_list()
        loads[arg] = pl.Series(arg, [scaled_load(options, scale, x) for x in stated], pl.Float64)
    return bearing, merged, loads


THERMAL = Kind(
    "thermal",
    "coupled thermal steady state of one bearing in the seed A network",
    (
        Param("bearing", str, "7008C", "bearing preset", check=_choice(_bearing_names, "bearing")),
        _model_param("bearing"),
        *_LOADS,
        Param("lubricant", str, "e-drive ATF", "lubricant preset", check=_check_lubricant),
        Param(
            "housing_material",
            str,
            "aluminium",
            "material preset of the housing",
            check=_choice(_material_names, "housing_material"),
        ),
        # Default None: what the model takes without it (f0 = 1 or the
        # lubrication method's; no drag heat or the method's oil fraction).
        Param("lubrication_factor_f0", float, None, "Palmgren f0 [-]"),
        Param(
            "spin_friction_coefficient",
            float,
            DEFAULT_SPIN_FRICTION_COEFFICIENT,
            "spin friction coefficient [-]",
        ),
        Param("oil_air_temperature_c", float, 28.0, "oil-air supply temperature [C]"),
        Param("ambient_temperature_c", float, 26.0, "ambient temperature [C]"),
        Param(
            "raceway_control",
            str,
            "outer",
            "'outer' or 'inner'",
            check=_one_of("raceway_control", "outer", "inner"),
        ),
        Param("misalignment_rad", float, 0.0, "inner-ring tilt, held [rad]"),
        Param("extra_heat_w", float, 0.0, "heat beyond the modelled friction [W]"),
        Param("housing_conductance_scale", float, 1.0, "scale of the housing convection [-]"),
        Param("churning_oil_fraction", float, None, "oil volume fraction of the oil-air mix [-]"),
        Param(
            "heat_model",
            str,
            "palmgren",
            "'palmgren' or 'skf' friction heat",
            check=_one_of("heat_model", "palmgren", "skf"),
        ),
        Param(
            "lubrication",
            str,
            None,
            "lubrication method (sets f0 and oil fraction)",
            check=_check_lubrication,
        ),
    ),
    _THERMAL_OUTPUTS,
    _run_thermal,
)


# -- spindle ----------------------------------------------------------------------

_SPINDLE_NODES = (
    "front_shaft",
    "rotor",
    "rear_shaft",
    "stator",
    "front_inner_ring",
    "front_ball",
    "front_outer_ring",
    "rear_inner_ring",
    "rear_ball",
    "rear_outer_ring",
    "front_housing",
    "sleeve",
    "rear_housing",
)
_SPINDLE_OUTPUTS = tuple((f"{n}_temperature_c", "Float64") for n in _SPINDLE_NODES) + (
    ("operating_preload_n", "Float64"),
    ("rear_operating_preload_n", "Float64"),
    ("spring_compression_um", "Float64"),
    ("radial_displacement_um", "Float64"),
    ("inner_contact_angle_deg", "Float64"),
    ("outer_contact_angle_deg", "Float64"),
    ("inner_load_max_n", "Float64"),
    ("outer_load_max_n", "Float64"),
    ("k_xx_n_per_m", "Float64"),
    ("k_zz_n_per_m", "Float64"),
    ("front_bearing_heat_w", "Float64"),
    ("bearing_heat_w", "Float64"),
    ("motor_losses_w", "Float64"),
    ("total_heat_w", "Float64"),
    ("axial_growth_um", "Float64"),
    ("thermal_radial_displacement_um", "Float64"),
    ("ball_growth_um", "Float64"),
    ("iterations", "Int64"),
)


_SPINDLE_SETTINGS = (
    "preload_n",
    "radial_n",
    "preload_kind",
    "spring_rate_n_per_um",
    "spin_friction_coefficient",
)


def _spindle_base(kind: Kind, name: str, key: str) -> tuple[Any, dict[str, Any]]:
    """``(spindle, options)``: the preset, or a calibrated model's spindle
    and options."""
    from ..spindle import Spindle

    return _calibrated(kind, key, "spindle", name) if key else (Spindle.preset(name), {})


def _run_spindle(kind: Kind, inputs: Any, threads: Optional[int]) -> Any:
    bases: dict[tuple[str, str], Any] = {}
    for name, key in inputs.select("spindle", "model").unique(maintain_order=True).iter_rows():
        try:  # built once, before the threads
            bases[(name, key)] = _spindle_base(kind, name, key)
        except ThermobearError as e:
            bases[(name, key)] = (type(e), str(e))

    def point(row: dict) -> dict:
        base, options = bases[(row["spindle"], row["model"])]
        if isinstance(base, type):
            raise base(options)
        # As thermal_state takes a calibrated model: its options must agree
        # with the settings given, its preload scale acts on preload_n.
        given = {k: row[k] for k in _SPINDLE_SETTINGS if row[k] is not None}
        s = merge_options(options, given, {"effects", *_SPINDLE_SETTINGS})
        sp = base.with_options(
            preload_n=s.get("preload_n"),
            preload_kind=s.get("preload_kind"),
            spring_rate_n_per_um=s.get("spring_rate_n_per_um"),
            radial_load_n=s.get("radial_n"),
            effects=s.get("effects"),
            spin_friction_coefficient=s.get("spin_friction_coefficient"),
        )
        state = sp.thermal_state(row["speed_rpm"]).row(0, named=True)
        return {k: state[k] for k, _ in _SPINDLE_OUTPUTS if k in state}

    return _row_map(inputs, threads, point)


SPINDLE = Kind(
    "spindle",
    "coupled thermal steady state of a motorized spindle (two bearing pairs)",
    (
        Param(
            "spindle",
            str,
            "seed-ceramic-spindle",
            "spindle preset",
            check=_choice(_spindle_names, "spindle"),
        ),
        _model_param("spindle"),
        Param("speed_rpm", float, 10_000.0, "shaft speed [rpm]"),
        # Default None: the preset's own value (null in the table).
        Param("preload_n", float, None, "preload force [N]"),
        Param("radial_n", float, None, "radial load at the nose [N]"),
        Param(
            "preload_kind",
            str,
            None,
            "'rigid' or 'spring'",
            check=_one_of("preload_kind", "rigid", "spring"),
        ),
        Param("spring_rate_n_per_um", float, None, "preload spring rate [N/um]"),
        Param("spin_friction_coefficient", float, None, "spin friction coefficient [-]"),
    ),
    _SPINDLE_OUTPUTS,
    _run_spindle,
)


# -- gear ---------------------------------------------------------------------------


def _gear_bearings(kind: Kind, row: dict) -> tuple[Any, StiffnessMode]:
    """The shafts' bearings and stiffness model of a gear point: the
    preset, or a calibrated model with the ``"thermal"`` stiffness (its
    options act on that schedule; ``"speed"``, the default, becomes it)."""
    from ..bearing import Bearing

    if not row["model"]:
        return Bearing.preset(row["bearing"]), row["stiffness"]
    _calibrated(kind, row["model"], "bearing", row["bearing"])
    if row["stiffness"] not in ("speed", "thermal"):
        raise ConfigError(
            f"invalid stiffness = {row['stiffness']!r}: the calibrated model sets "
            "stiffness = 'thermal' (its options act on the thermal stiffness schedule)"
        )
    return model_of(row["model"]), "thermal"


def _run_gear(kind: Kind, inputs: Any, threads: Optional[int]) -> Any:
    from ..gear import GearPair, GearSystem, regime_map

    def point(row: dict) -> dict:
        bearings, stiffness = _gear_bearings(kind, row)
        system = GearSystem(
            GearPair.preset(row["gear"]),
            bearings,
            stiffness,
            backlash_total_um=row["backlash_total_um"],
            mesh_damping_ratio=row["mesh_damping_ratio"],
            te_amplitude_um=row["te_amplitude_um"],
            torque_n_m=row["torque_n_m"],
        )
        cell = regime_map(
            system,
            [row["torque_n_m"]],
            [row["speed_rpm"]],
            [1.0],
            transient_periods=row["transient_periods"],
            record_periods=row["record_periods"],
            steps_per_period=row["steps_per_period"],
        ).row(0, named=True)
        return {k: cell[k] for k, _ in _GEAR_OUTPUTS}

    return _row_map(inputs, threads, point)


_GEAR_OUTPUTS = (
    ("regime", "String"),
    ("period", "Int64"),
    ("impact", "String"),
    ("amplitude_um", "Float64"),
    ("mean_dte_um", "Float64"),
    ("lyapunov_per_s", "Float64"),
    ("settled", "Boolean"),
)

GEAR = Kind(
    "gear",
    "motion regime of the gear system at a speed (every cell from its static state)",
    (
        Param(
            "gear",
            str,
            "seed-electric-drive",
            "gear pair preset",
            check=_choice(_gear_names, "gear"),
        ),
        Param(
            "bearing",
            str,
            "6208",
            "bearing preset of the shafts",
            check=_choice(_bearing_names, "bearing"),
        ),
        _model_param("bearing"),
        Param(
            "stiffness",
            str,
            "speed",
            "bearing stiffness model: 'speed' (as tb.GearSystem), 'constant' or 'thermal' "
            "(a model's: 'thermal')",
            check=_one_of("stiffness", "constant", "speed", "thermal"),
        ),
        Param("speed_rpm", float, 3000.0, "pinion speed [rpm]"),
        Param("torque_n_m", float, 100.0, "input torque [N m]"),
        Param("te_amplitude_um", float, 2.0, "transmission error amplitude [um]"),
        Param("backlash_total_um", float, 100.0, "total backlash 2b [um]"),
        Param("mesh_damping_ratio", float, 0.07, "mesh damping ratio [-]"),
        Param("transient_periods", int, 300, "mesh periods discarded"),
        Param("record_periods", int, 100, "mesh periods recorded"),
        # Default None: as tb.bifurcation -- 64, or the fewest the point's
        # speed needs; a given number is checked before the point runs.
        Param(
            "steps_per_period",
            int,
            None,
            "RK4 steps per mesh period (null: 64, or the fewest the speed needs)",
        ),
    ),
    _GEAR_OUTPUTS,
    _run_gear,
)

KINDS: dict[str, Kind] = {k.name: k for k in (BEARING, THERMAL, SPINDLE, GEAR)}


def register_kind(kind: Kind) -> None:
    """Add a kind of point defined by a higher layer (the ``prediction``
    kind of ``thermobear.predict``: a calibrated model's outputs); a kind
    of that name is replaced."""
    KINDS[kind.name] = kind


def kind_of(name: str) -> Kind:
    if not isinstance(name, str) or name not in KINDS:
        raise ConfigError(f"invalid kind = {name!r}: known: {', '.join(KINDS)}")
    return KINDS[name]


def kinds_table() -> Any:
    """Every kind's inputs: ``kind``, ``input``, ``type``, ``default``, ``doc``."""
    import polars as pl

    rows = [
        {
            "kind": k.name,
            "input": p.name,
            "type": p.type.__name__,
            "default": "(the model's own)" if p.default is None else str(p.default),
            "doc": p.doc,
        }
        for k in KINDS.values()
        for p in k.params
    ]
    return pl.DataFrame(rows)
