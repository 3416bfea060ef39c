"""The gear-shaft-bearing system of seed A: mass, stiffness and damping
matrices, the bearing stiffness schedule against speed."""

from __future__ import annotations

import math
from pathlib import Path
from typing import TYPE_CHECKING, Any, Mapping, Optional, Union

import numpy as np
from numpy.typing import ArrayLike

from .. import _native
from .. import _validate as val
from .._deprecation import renamed_kwargs
from .._input_checks import check_gear_system
from .._types import BearingStiffnessPer, MeshDamping, StiffnessMode
from .pair import STIFFNESS_SPEEDS_RPM, GearPair, _config_error
from .tables import (
    MeshInput,
    backlash_half_um,
    bearing_count,
    mesh_period_samples,
    support_from_frame,
)

if TYPE_CHECKING:
    import polars

    from .._model_hook import CalibratedMachine


class GearSystem:
    """The 8-DOF helical pair on its bearings.

    ``gear``: a [`GearPair`][thermobear.GearPair], or a calibrated gear
    model (``thermobear.calibrate`` on a
    [`GearModelSpec`][thermobear.GearModelSpec]): its calibrated inputs
    (TE, mesh damping, backlash, mesh stiffness scale) are used and may not
    be given again with another value; its stiffness case, torque and
    bearings are the defaults of the arguments left out.

    Bearing support (A-52, ``diag(Kr, Kr, Ka)`` for pinion and gear):
    ``stiffness`` is ``"speed"`` (default: quasi-static stiffness at each
    speed, no thermal effects), ``"constant"`` (zero-speed stiffness of
    ``bearings`` under the seed loads), ``"thermal"`` (``stiffness_curve(mode=
    "thermal")``) or a frame with ``speed_rpm`` and the radial/axial
    stiffness [N/m]. The three computed cases give ONE bearing's stiffness;
    each shaft carries ``bearings_per_shaft`` (default 2, seed A Fig. 1)
    identical bearings in parallel, so the support is n x one bearing's. A
    frame must say what it holds: ``bearing_stiffness_per="bearing"``
    (``radial_stiffness_seed_n_per_m``, ``axial_stiffness_seed_n_per_m`` of one
    bearing, multiplied by ``bearings_per_shaft``) or ``"shaft"`` (the
    whole support of one shaft, used as given; ``bearings_per_shaft`` must
    then be left out). A frame with ``support_radial_stiffness_n_per_m``,
    ``support_axial_stiffness_n_per_m`` (as
    [`stiffness_schedule`][thermobear.GearSystem.stiffness_schedule]
    returns) is per shaft. Bearing loads follow |torque|: Fa = 2380.9
    |T|/100 + 300 N preload, Fr = 1189.9 |T|/100 N (seed A section 2.3).

    Backlash by name, at most one: ``half_backlash_um`` (b) or
    ``backlash_total_um`` (the total clearance 2b); default b = 50 um.
    ``backlash_um`` is a deprecated alias of ``backlash_total_um``
    (DeprecationWarning).

    Mesh inputs (see ``thermobear.gear.tables`` for the table format):
    ``mesh_stiffness_n_per_m`` (table with ``normal_stiffness_n_per_m`` or
    ``transverse_stiffness_n_per_m``, or a callable of ``mesh_phase``
    returning N/m along the normal deflection) replaces the computed
    ``mesh_model`` (``"potential-energy"`` default, or ``"iso"``);
    ``transmission_error_um`` (table with ``transmission_error_um`` or
    ``transmission_error_m``, or a callable returning um) replaces the
    first-harmonic TE of ``te_amplitude_um`` (default 2 um). Either is
    sampled once; the model interpolates the samples.
    ``mesh_stiffness_scale`` [-] (default 1) multiplies the mesh stiffness
    table, computed or given (a calibration input: seed A states no mesh
    stiffness values).

    ``torque_n_m``: input torque on the pinion [N m] (default the pair's;
    the older ``torque_nm`` is deprecated); negative
    is coast (the back flanks carry the load). ``mesh_damping``:
    ``"in-contact"`` (A-46 as printed, default) or ``"always"``.

    ``bearings`` may be a [`CalibratedModel`][thermobear.CalibratedModel]:
    its load scales act on the seed loads, its effects and thermal options
    on the ``"thermal"`` schedule.
    """

    @renamed_kwargs(torque_nm="torque_n_m")
    def __init__(
        self,
        gear: Union[GearPair, CalibratedMachine],
        bearings: Any = None,
        stiffness: Union[StiffnessMode, polars.DataFrame, Mapping[str, ArrayLike], None] = None,
        *,
        bearing_stiffness_per: Optional[BearingStiffnessPer] = None,
        bearings_per_shaft: Optional[int] = None,
        half_backlash_um: Optional[float] = None,
        backlash_total_um: Optional[float] = None,
        backlash_um: Optional[float] = None,
        mesh_damping_ratio: Optional[float] = None,
        mesh_damping: Optional[MeshDamping] = None,
        bearing_damping_ratio: Optional[float] = None,
        te_amplitude_um: Optional[float] = None,
        torque_n_m: Optional[float] = None,
        mesh_model: Optional[str] = None,
        table_points: int = 64,
        stiffness_speeds_rpm: Optional[ArrayLike] = None,
        mesh_stiffness_n_per_m: Optional[MeshInput] = None,
        transmission_error_um: Optional[MeshInput] = None,
        mesh_stiffness_scale: Optional[float] = None,
    ) -> None:
        from .._model_hook import scaled_load, unpack_model
        from ..bearing import Bearing

        given = {
            "half_backlash_um": half_backlash_um, "mesh_damping_ratio": mesh_damping_ratio,
            "mesh_damping": mesh_damping, "bearing_damping_ratio": bearing_damping_ratio,
            "te_amplitude_um": te_amplitude_um, "mesh_stiffness_scale": mesh_stiffness_scale,
        }  # fmt: skip
        gear, inp, defaults = _calibrated_gear(gear, given, backlash_total_um, backlash_um)
        bearings = defaults.get("bearings") if bearings is None else bearings
        stiffness = defaults.get("stiffness", "speed") if stiffness is None else stiffness
        torque_n_m = defaults.get("torque_n_m") if torque_n_m is None else torque_n_m
        bearings, calibrated = unpack_model(bearings)
        if not isinstance(gear, GearPair):
            raise _config_error(
                f"invalid gear = {gear!r}: must be a thermobear.GearPair or a calibrated gear model"
            )
        bearing = Bearing.preset("6208") if bearings is None else bearings
        torque = val.real(
            "torque_n_m", gear.geometry["input_torque_n_m"] if torque_n_m is None else torque_n_m
        )
        fa, fr = _native.seed_gear_bearing_loads(torque)
        if calibrated:  # the calibrated load scales act on the seed loads
            fa = scaled_load(calibrated, "axial_load_scale", fa)
            fr = scaled_load(calibrated, "radial_load_scale", fr)
        s, kr, ka = self._support(
            bearing, stiffness, bearing_stiffness_per, bearings_per_shaft, stiffness_speeds_rpm,
            (fa, fr), calibrated,
        )  # fmt: skip
        points = val.whole("table_points", table_points, 2)
        self.gear = gear
        self.bearing = bearing
        self.bearings_per_shaft = (
            None if bearing_stiffness_per == "shaft" else (bearing_count(bearings_per_shaft))
        )
        self.bearing_stiffness_per = "shaft" if bearing_stiffness_per == "shaft" else "bearing"
        self.bearing_loads_n = {"axial_n": fa, "radial_n": fr}
        self._s = _native.GearSystem(
            gear._g, [float(v) for v in s], [float(v) for v in kr], [float(v) for v in ka],
            **_checked_inputs(inp, backlash_total_um, backlash_um),
            torque_nm=torque, table_points=points,
            mesh_model=None if mesh_model is None else val.text("mesh_model", mesh_model),
            mesh_stiffness_n_per_m=self._stiffness_table(gear, mesh_stiffness_n_per_m, points),
            transmission_error_m=self._te_table(gear, transmission_error_um, points),
        )  # fmt: skip
        check_gear_system(gear.geometry, self.params)

    @classmethod
    def from_toml(cls, source: Union[str, Path]) -> "GearSystem":
        """A gear system from a ``[gear_system]`` description: a file path,
        TOML text or the name of a shipped file (``"seed-a-gear-system"``:
        seed A's pair on its 6208 bearings, as ``GearSystem(GearPair.preset(
        "seed-electric-drive"))`` builds it). An error names the file, the
        line and the key (see Gears and dynamics, "Description files")."""
        from ..config import located_config_errors
        from .description import parse_description, read_description

        path, text = read_description(source)
        with located_config_errors(path, text):
            return cls(**parse_description(text))

    def to_toml(self, path: Union[str, Path, None] = None) -> str:
        """The ``[gear_system]`` description of this system (written to
        ``path`` when given; the text is returned either way).
        ``from_toml`` of it gives this system to the last bit; a system the
        text would not give back (a stiffness frame, a bearing that is not
        a preset, a calibrated bearing model) raises
        [`ConfigError`][thermobear.ConfigError]."""
        from .description import to_toml

        return to_toml(self, GearSystem.from_toml, path)

    @staticmethod
    def _stiffness_table(gear: GearPair, given: Any, points: int) -> Optional[list[float]]:
        if given is None:
            return None
        cb = math.cos(math.radians(gear.geometry["helix_angle_deg"]))
        cols = {"normal_stiffness_n_per_m": 1.0, "transverse_stiffness_n_per_m": 1.0 / (cb * cb)}
        z = int(gear.geometry["pinion_teeth"])
        v = mesh_period_samples("mesh_stiffness_n_per_m", cols, 1.0, given, z, points)
        return [float(x) for x in v]

    @staticmethod
    def _te_table(gear: GearPair, given: Any, points: int) -> Optional[list[float]]:
        if given is None:
            return None
        cols = {"transmission_error_m": 1.0, "transmission_error_um": 1e-6}
        z = int(gear.geometry["pinion_teeth"])
        v = mesh_period_samples("transmission_error_um", cols, 1e-6, given, z, points)
        return [float(x) for x in v]

    def _support(
        self,
        bearing: Any,
        stiffness: Any,
        per: Optional[str],
        bearings_per_shaft: Optional[int],
        speeds: Optional[ArrayLike],
        loads: tuple[float, float],
        calibrated: Optional[dict[str, Any]] = None,
    ) -> tuple[Any, Any, Any]:
        """Support stiffness schedule of one shaft (speed, kr, ka);
        ``calibrated``: the options of a calibrated bearing model (its
        effects and thermal options act in the thermal case)."""
        from ..thermal import stiffness_curve

        if not isinstance(stiffness, str):
            self.stiffness_case = "user"
            return support_from_frame(stiffness, per, bearings_per_shaft)
        if stiffness not in ("constant", "speed", "thermal"):
            raise _config_error(
                f"invalid stiffness = {stiffness!r}: must be 'constant', 'speed', 'thermal' "
                "or a frame"
            )
        if per not in (None, "bearing"):
            raise _config_error(
                f"invalid bearing_stiffness_per = {per!r}: stiffness={stiffness!r} is computed "
                "for one bearing ('bearing'); 'shaft' applies to a frame only"
            )
        n = bearing_count(bearings_per_shaft)
        fa, fr = loads
        grid = np.asarray(STIFFNESS_SPEEDS_RPM if speeds is None else speeds, dtype=float)
        self.stiffness_case = stiffness
        options = _thermal_schedule_options(calibrated, stiffness)
        if stiffness != "thermal":
            return _native.gear_bearing_schedule(bearing._b, stiffness, list(grid), fa, fr, n)
        try:
            df = stiffness_curve(
                bearing, grid, axial_n=fa, radial_n=fr, mode="thermal", misalignment_rad=0.0,
                **options,
            )  # fmt: skip
        except Exception as e:  # the mode is added by the thermal module
            raise _config_error(
                "invalid stiffness = 'thermal': stiffness_curve(mode='thermal') is not "
                f"available here ({e}); pass a frame with speed_rpm, "
                "radial_stiffness_seed_n_per_m, axial_stiffness_seed_n_per_m instead"
            ) from e
        return support_from_frame(df, "bearing", n)

    @property
    def params(self) -> dict[str, float]:
        """Model numbers (mesh stiffness mean/min/max in N/m, normal
        direction; mesh damping N s/m; masses, radii, angles; torque in N m,
        negative for coast; ``te_amplitude_um``: the first-harmonic
        amplitude, or half the peak-to-peak of a TE table)."""
        p = dict(self._s.params())
        if "torque_nm" in p:
            p["torque_n_m"] = p.pop("torque_nm")
        return p

    @property
    def stiffness_schedule(self) -> polars.DataFrame:
        """Support stiffness of one shaft (all its bearings) against speed."""
        import polars as pl

        s, kr, ka = self._s.schedule()
        return pl.DataFrame(
            {
                "speed_rpm": np.asarray(s),
                "support_radial_stiffness_n_per_m": np.asarray(kr),
                "support_axial_stiffness_n_per_m": np.asarray(ka),
            }
        )

    def bearing_stiffness_at(self, speed_rpm: float) -> tuple[float, float]:
        """Support (radial, axial) stiffness [N/m] at a speed."""
        return tuple(self._s.bearing_stiffness_at(val.real("speed_rpm", speed_rpm, 0.0)))  # type: ignore[return-value]

    def mass_matrix_kg(self, speed_rpm: float = 10_000.0) -> np.ndarray:
        """Diagonal mass matrix of q = [x_p, y_p, z_p, x_g, y_g, z_g, u]
        (u = R_p theta_p - R_g theta_g, equivalent mass)."""
        return np.diag(self._s.mass_diagonal_kg(val.real("speed_rpm", speed_rpm, 0.0)))

    def stiffness_matrix_n_per_m(
        self, speed_rpm: float = 10_000.0, mesh_stiffness_n_per_m: Optional[float] = None
    ) -> np.ndarray:
        """Linear stiffness matrix in contact (default: mean mesh stiffness)."""
        k = (
            self.params["mesh_stiffness_mean_n_per_m"]
            if mesh_stiffness_n_per_m is None
            else mesh_stiffness_n_per_m
        )
        k = val.real("mesh_stiffness_n_per_m", k, 0.0, open_lo=True)
        return np.asarray(self._s.stiffness_matrix(val.real("speed_rpm", speed_rpm, 0.0), k))

    def natural_frequencies_hz(
        self, speed_rpm: float = 10_000.0, mesh_stiffness_n_per_m: Optional[float] = None
    ) -> np.ndarray:
        """Undamped natural frequencies in contact, ascending [Hz]."""
        k = (
            self.params["mesh_stiffness_mean_n_per_m"]
            if mesh_stiffness_n_per_m is None
            else mesh_stiffness_n_per_m
        )
        k = val.real("mesh_stiffness_n_per_m", k, 0.0, open_lo=True)
        n = val.real("speed_rpm", speed_rpm, 0.0)
        return np.asarray(self._s.natural_frequencies_hz(n, k))

    def static_state_m(self, speed_rpm: float = 10_000.0) -> np.ndarray:
        """Static equilibrium q = [x_p, y_p, z_p, x_g, y_g, z_g, u] (in m) in
        contact at the mean mesh stiffness and TE (back flank for coast)."""
        return np.asarray(self._s.static_state_m(val.real("speed_rpm", speed_rpm, 0.0)))

    def projection(self) -> np.ndarray:
        """Mesh-normal projection vector a of q (A-45)."""
        return np.asarray(self._s.projection())

    def mesh_tables(self) -> polars.DataFrame:
        """The mesh stiffness along the normal deflection and the static TE
        the model uses over one mesh period: ``mesh_phase`` (i / n),
        ``normal_stiffness_n_per_m``, ``transmission_error_um``,
        ``transmission_error_m``. Given back as ``mesh_stiffness_n_per_m=`` /
        ``transmission_error_um=`` it rebuilds the same model bit for bit.
        Tables given on different numbers of points keep their own samples:
        the phases are the union of both grids and each column is null
        where its table has no sample (drop the nulls of a column to give it
        back)."""
        import polars as pl

        t = {k: np.asarray(v) for k, v in self._s.mesh_tables().items()}
        nk, ne = len(t["normal_stiffness_n_per_m"]), len(t["transmission_error_m"])
        if nk == ne:
            return pl.DataFrame(t)
        grids = {"normal_stiffness_n_per_m": nk, "transmission_error_um": ne,
                 "transmission_error_m": ne}  # fmt: skip
        tables = [
            pl.DataFrame({"mesh_phase": np.arange(n) / n, col: t[col]}) for col, n in grids.items()
        ]
        out = pl.DataFrame({"mesh_phase": np.union1d(np.arange(nk) / nk, np.arange(ne) / ne)})
        for table in tables:
            out = out.join(table, on="mesh_phase", how="left")
        return out

    @property
    def mesh_model(self) -> str:
        """``"potential-energy"``, ``"iso"`` or ``"table"`` (user table)."""
        return str(self._s.mesh_model)

    def mesh_period_s(self, speed_rpm: float) -> float:
        """Mesh period 60 / (z_p n) [s]."""
        t = float(self._s.mesh_period_s(val.real("speed_rpm", speed_rpm, 0.0, open_lo=True)))
        return val.finite_result(t, {"speed_rpm": speed_rpm})

    def check_steps(self, speed_rpm: float, steps_per_period: int) -> None:
        """ConfigError if the RK4 step is too coarse at this speed."""
        n = val.real("speed_rpm", speed_rpm, 0.0, open_lo=True)
        self._s.check_steps(n, val.whole("steps_per_period", steps_per_period, 1))

    def __repr__(self) -> str:
        p = self.params
        return (
            f"GearSystem(stiffness={self.stiffness_case!r}, torque={p['torque_n_m']:.1f} N m, "
            f"k_m={p['mesh_stiffness_mean_n_per_m'] / 1e6:.0f} N/um, "
            f"2b={2 * p['half_backlash_um']:.0f} um, TE={p['te_amplitude_um']:.1f} um)"
        )


#: The inputs a calibrated gear model sets (a call may not change them).
CALIBRATED_GEAR_INPUTS = (
    "half_backlash_um",
    "mesh_damping_ratio",
    "mesh_damping",
    "bearing_damping_ratio",
    "te_amplitude_um",
    "mesh_stiffness_scale",
)


def _checked_inputs(
    inp: dict[str, Any], backlash_total_um: Optional[float], backlash_um: Optional[float]
) -> dict[str, Any]:
    """The native keywords of the gear pair's inputs, each checked (a named
    [`ConfigError`][thermobear.ConfigError]); the backlash by whichever
    name it was given."""
    return {
        "half_backlash_um": backlash_half_um(
            inp["half_backlash_um"], backlash_total_um, backlash_um, 50.0
        ),
        "mesh_damping_ratio": val.real("mesh_damping_ratio", inp["mesh_damping_ratio"], 0.0),
        "mesh_damping": val.choice("mesh_damping", inp["mesh_damping"], ("in-contact", "always")),
        "bearing_damping_ratio": val.real(
            "bearing_damping_ratio", inp["bearing_damping_ratio"], 0.0
        ),
        "te_amplitude_um": val.optional_real("te_amplitude_um", inp["te_amplitude_um"]),
        "mesh_stiffness_scale": val.real(
            "mesh_stiffness_scale", inp["mesh_stiffness_scale"], 0.0, open_lo=True
        ),
    }


#: The defaults of the inputs a calibrated gear model sets (None keeps a
#: TE table's or the native default: 2 um first-harmonic TE; backlash: 50 um).
_GEAR_INPUT_DEFAULTS: dict[str, Any] = {
    "half_backlash_um": None,
    "mesh_damping_ratio": 0.07,
    "mesh_damping": "in-contact",
    "bearing_damping_ratio": 0.02,
    "te_amplitude_um": None,
    "mesh_stiffness_scale": 1.0,
}


def _calibrated_gear(
    gear: Any, given: dict[str, Any], *backlash_aliases: Optional[float]
) -> tuple[Any, dict[str, Any], dict[str, Any]]:
    """``(pair, inputs, defaults)`` of ``gear``: a calibrated gear model
    gives its pair, the inputs it calibrated (a ``given`` value that
    differs raises [`ConfigError`][thermobear.ConfigError]: it would undo
    the calibration) and the defaults a call may change (stiffness case,
    torque, bearings); a pair gives itself, the ``given`` inputs with the
    documented defaults for those left out, and no defaults. A backlash
    given by another name (``backlash_aliases``) is refused for a model."""
    from .._model_hook import is_calibrated, unpack_model

    if not is_calibrated(gear):
        return gear, {k: d if given[k] is None else given[k]
                      for k, d in _GEAR_INPUT_DEFAULTS.items()}, {}  # fmt: skip
    pair, options = unpack_model(gear)
    defaults = dict(options.pop("_defaults", {}))
    fixed = {k: options[k] for k in CALIBRATED_GEAR_INPUTS if k in options}
    if not isinstance(pair, GearPair) or len(fixed) != len(CALIBRATED_GEAR_INPUTS):
        raise _config_error(
            f"invalid gear = {gear!r}: a calibrated model of a gear pair is needed here "
            "(a bearing model goes to bearings=)"
        )
    if any(b is not None for b in backlash_aliases):
        raise _config_error(
            "invalid backlash_total_um: the calibrated gear model sets half_backlash_um "
            f"= {fixed['half_backlash_um']!r}"
        )
    for k, v in given.items():
        if v is not None and v != fixed[k]:
            raise _config_error(
                f"invalid {k} = {v!r}: the calibrated gear model sets {k} = {fixed[k]!r}; "
                "giving it again would undo the calibration (use CalibratedModel.spec_at for "
                "a what-if)"
            )
    return pair, fixed, defaults or {"stiffness": "speed"}


def _thermal_schedule_options(
    calibrated: Optional[dict[str, Any]], stiffness: str
) -> dict[str, Any]:
    """The keywords of the thermal stiffness curve from a calibrated
    bearing model's options (none without one). The "speed" and "constant"
    schedules solve with every effect on and take no thermal option: a
    calibrated model with an effect switched off raises
    [`ConfigError`][thermobear.ConfigError] there (its thermal options
    would not act either; give ``stiffness="thermal"``)."""
    if not calibrated:
        return {}
    opts = {k: v for k, v in calibrated.items() if "load_scale" not in k}
    if stiffness == "thermal":
        return opts
    every = sorted(n for n, *_ in _native.effects())
    if sorted(opts.get("effects", every)) != every:
        raise _config_error(
            f"invalid stiffness = {stiffness!r}: the calibrated bearing model switches effects "
            "off, which only the thermal schedule honours; give stiffness='thermal'"
        )
    return {}
