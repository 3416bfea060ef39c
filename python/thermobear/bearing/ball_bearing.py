"""Ball bearings: construction, solving, stiffness.

Every length a user passes or reads carries its unit in the name
(``ball_diameter_mm``, ``axial_displacement_um``); forces are N, moments
N m (``_n_m``); ``stiffness`` matrices are SI.

Displacements follow ISO/TS 16281: they are measured from the concentric
position with the groove curvature centres in one plane, so taking up the
clearance is part of the displacement (a deep-groove bearing with clearance
moves axially by about ``A sin(alpha0)`` before it carries any load).
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import TYPE_CHECKING, Any, Optional, Sequence

import numpy as np
from numpy.typing import ArrayLike

from .. import _native, plausibility
from .. import _validate as v
from .._deprecation import renamed_kwargs, warn_renamed
from .._limits import cap_threads
from .._names import renamed_columns
from .._types import RacewayControl
from ..errors import ConfigError, ConvergenceError
from .material import Material, _native_material

if TYPE_CHECKING:
    import polars


def _effects_arg(effects: Optional[Sequence[str]]) -> Optional[list[str]]:
    if effects is None:
        return None
    if isinstance(effects, str):
        return [effects]
    try:
        names = list(effects)
    except TypeError:
        raise v.fail("effects", effects, "a name or a list of effect names") from None
    return [v.text("effects", e) for e in names]


#: The raceway-control choices.
_CONTROLS = ("outer", "inner")


def _dim(name: str, mm: Any) -> float:
    """A length of a bearing in mm: finite and above zero."""
    return v.real(name, mm, 0.0, open_lo=True)


class Bearing:
    """A ball bearing (deep-groove or angular-contact).

    Build with ``preset`` (``"6208"``, ``"7008C"``, ``"7009C"``, each also
    ``-hybrid`` with Si3N4 balls and ``-ceramic``),
    [`deep_groove`][thermobear.bearing.ball_bearing.Bearing.deep_groove],
    [`angular_contact`][thermobear.bearing.ball_bearing.Bearing.angular_contact] or
    [`from_toml`][thermobear.bearing.ball_bearing.Bearing.from_toml].
    """

    def __init__(self, native: Any) -> None:
        self._b = native
        self._provenance: dict[str, str] = {}

    # -- construction -------------------------------------------------
    @classmethod
    def preset(cls, name: str) -> "Bearing":
        """A built-in bearing by its name, one of
        `Bearing.preset_names()`, or a catalogue
        bearing by its standard designation (``"6208-2RS1"``, ``"7014CE/HCP4A"``,
        ``"HCB7009C-T-P4S"``; what is read: How-to "Bearings by designation").
        [`provenance`][thermobear.Bearing.provenance] says where each value
        comes from."""
        from . import catalogue

        if not isinstance(name, str):
            known = ", ".join(_native.Bearing.preset_names())
            raise v.fail("name", name, f"a bearing preset name (a string): one of {known}")
        try:
            b = cls(_native.Bearing.preset(name))
        except ConfigError:
            des = catalogue.parse_designation(name)  # a ConfigError with a guess
            kw, provenance = catalogue.catalogue_geometry(des)
            build = cls.deep_groove if des.bearing_type == catalogue.DEEP else cls.angular_contact
            b = build(**kw, name=des.text)
        else:
            provenance = catalogue.preset_provenance(name, b.bearing_type)
        b._provenance = provenance
        return b

    @staticmethod
    def preset_names() -> list[str]:
        return list(_native.Bearing.preset_names())

    @classmethod
    def deep_groove(
        cls,
        *,
        ball_count: int,
        ball_diameter_mm: float,
        pitch_diameter_mm: float,
        inner_conformity: float,
        outer_conformity: float,
        diametral_clearance_mm: float,
        bore_mm: float,
        outer_diameter_mm: float,
        width_mm: float,
        ring_material: Any = None,
        ball_material: Any = None,
        name: Optional[str] = None,
    ) -> "Bearing":
        """A deep-groove bearing; the free contact angle follows from the
        clearance, cos(alpha0) = 1 - Pd / (2 (f_i + f_o - 1) D)."""
        return cls._checked(
            _native.Bearing.deep_groove(
                v.whole("ball_count", ball_count, 1, 10_000),
                _dim("ball_diameter_mm", ball_diameter_mm),
                _dim("pitch_diameter_mm", pitch_diameter_mm),
                v.real("inner_conformity", inner_conformity, 0.5, open_lo=True),
                v.real("outer_conformity", outer_conformity, 0.5, open_lo=True),
                v.real("diametral_clearance_mm", diametral_clearance_mm, 0.0),
                _dim("bore_mm", bore_mm),
                _dim("outer_diameter_mm", outer_diameter_mm),
                _dim("width_mm", width_mm),
                _native_material(ring_material),
                _native_material(ball_material),
                name,
            )
        )

    @classmethod
    def angular_contact(
        cls,
        *,
        ball_count: int,
        ball_diameter_mm: float,
        pitch_diameter_mm: float,
        inner_conformity: float,
        outer_conformity: float,
        free_contact_angle_deg: float,
        bore_mm: float,
        outer_diameter_mm: float,
        width_mm: float,
        ring_material: Any = None,
        ball_material: Any = None,
        name: Optional[str] = None,
    ) -> "Bearing":
        """An angular-contact bearing from its free contact angle."""
        return cls._checked(
            _native.Bearing.angular_contact(
                v.whole("ball_count", ball_count, 1, 10_000),
                _dim("ball_diameter_mm", ball_diameter_mm),
                _dim("pitch_diameter_mm", pitch_diameter_mm),
                v.real("inner_conformity", inner_conformity, 0.5, open_lo=True),
                v.real("outer_conformity", outer_conformity, 0.5, open_lo=True),
                v.real("free_contact_angle_deg", free_contact_angle_deg, 0.0, 90.0),
                _dim("bore_mm", bore_mm),
                _dim("outer_diameter_mm", outer_diameter_mm),
                _dim("width_mm", width_mm),
                _native_material(ring_material),
                _native_material(ball_material),
                name,
            )
        )

    @classmethod
    def from_toml(cls, path_or_text: str) -> "Bearing":
        """The ``[bearing]`` of a system description file or text; its
        ``preset`` takes a built-in preset or a catalogue designation (as
        [`preset`][thermobear.Bearing.preset]), explicit keys override it."""
        from ..config import catalogue_bearings, load_config

        text = load_config(path_or_text)
        return cls._checked(_native.Bearing.from_toml(text, catalogue_bearings(text)))

    @classmethod
    def _checked(cls, native: Any) -> "Bearing":
        """A bearing built from the user's dimensions, its plausibility
        checked (``thermobear._input_checks``; the presets need none)."""
        from .._input_checks import check_bearing_geometry

        check_bearing_geometry(native.geometry(), native.bearing_type)
        return cls(native)

    # -- properties ---------------------------------------------------
    @property
    def name(self) -> str:
        return self._b.name

    @property
    def bearing_type(self) -> str:
        return self._b.bearing_type

    @property
    def material_class(self) -> str:
        """``"steel"``, ``"hybrid"`` (Si3N4 balls) or ``"ceramic"``."""
        return self._b.material_class

    @property
    def geometry(self) -> dict[str, float]:
        """Geometry in mm and degrees."""
        return dict(self._b.geometry())

    @property
    def provenance(self) -> dict[str, str]:
        """Where each value of a preset or catalogue bearing comes from:
        field -> ``"catalogue ISO 15: ..."``, ``"published: <source>"``,
        ``"estimated: <rule>"``, ``"designation: ..."`` or ``"default: ..."``
        (empty for a bearing built from dimensions given to a constructor)."""
        return dict(getattr(self, "_provenance", {}))

    def summary(self) -> str:
        """The bearing in a few lines: type, materials, dimensions and
        internal geometry, and a note naming every estimated value."""
        from .catalogue import summary_lines

        return "\n".join(summary_lines(self.name, self.bearing_type, self.material_class,
                                       self.geometry, self.provenance))  # fmt: skip

    @property
    def ring_material(self) -> Material:
        m = Material.__new__(Material)
        m._m = self._b.ring_material
        return m

    @property
    def ball_material(self) -> Material:
        m = Material.__new__(Material)
        m._m = self._b.ball_material
        return m

    def contact(
        self, raceway: str, contact_angle_deg: float, load_n: float = 1000.0, exact: bool = True
    ) -> dict[str, float]:
        """Hertz contact of one ball on the ``"inner"``/``"outer"`` raceway
        (exact ellipticity, or Hamrock-Brewe closed forms with ``exact=False``)."""
        out = dict(
            self._b.contact(
                v.choice("raceway", raceway, ("inner", "outer")),
                v.real("contact_angle_deg", contact_angle_deg, -90.0, 90.0),
                v.real("load_n", load_n, 0.0),
                v.flag("exact", exact),
            )
        )
        a_mm = out["semi_major_m"] * 1e3  # NaN or inf past overflow: refused as well
        if not a_mm <= self.geometry["ball_diameter_mm"]:
            raise v.fail(
                "load_n",
                load_n,
                f"a load whose contact ellipse fits the ball (semi-major axis {a_mm:.3g} mm "
                f"against a {self.geometry['ball_diameter_mm']:g} mm ball: Hertz theory fails)",
            )
        return out

    # -- solving -------------------------------------------------------
    @renamed_kwargs(moment_nmm=("moment_n_m", lambda v: float(v) / 1000.0))
    def solve(
        self,
        axial_n: float = 0.0,
        radial_n: float = 0.0,
        moment_n_m: float = 0.0,
        speed_rpm: float = 0.0,
        *,
        effects: Optional[Sequence[str]] = None,
        raceway_control: RacewayControl = "outer",
        misalignment_rad: Optional[float] = 0.0,
    ) -> BearingSolution:
        """Solve the bearing under an axial force, a radial force (along x)
        and a tilting moment (about y) at an inner-ring speed.

        At ``speed_rpm=0`` this is the static (Hertz) solve; above it the
        Jones-Harris quasi-static model with the named ``effects`` (default:
        all; see [`thermobear.effects`][thermobear.effects]), with outer- (default) or
        inner-``raceway_control``.

        The inner ring's tilt is held at ``misalignment_rad`` (default 0: the
        ISO/TS 16281 practice of a ring held by shaft and housing; the moment
        needed to hold it is a reaction). With ``misalignment_rad=None`` the
        tilt is free and solved so that the bearing carries ``moment_n_m``
        (N m; the older ``moment_nmm`` in N mm is deprecated and converted)."""
        loads = {
            "axial_n": v.real("axial_n", axial_n),
            "radial_n": v.real("radial_n", radial_n),
            "moment_n_m": v.real("moment_n_m", moment_n_m),
            "speed_rpm": v.real("speed_rpm", speed_rpm, 0.0),
        }
        tilt = self._tilt(misalignment_rad)
        try:
            raw = self._b.solve(
                *loads.values(),
                _effects_arg(effects),
                v.choice("raceway_control", raceway_control, _CONTROLS),
                tilt,
            )
        except ConvergenceError as e:
            v.name_inputs(e, {**loads, "misalignment_rad": tilt})
            raise
        plausibility.check_solution(self, raw, loads, tilt)
        return BearingSolution(raw)

    def solve_many(
        self,
        points: Any,
        *,
        effects: Optional[Sequence[str]] = None,
        raceway_control: RacewayControl = "outer",
        misalignment_rad: Optional[float] = 0.0,
        threads: Optional[int] = None,
        progress: Any = None,
    ) -> polars.DataFrame:
        """Solve many operating points in one native call (rayon threads,
        GIL released, Ctrl-C within 50 ms), each exactly as [`solve`][thermobear.Bearing.solve]
        would (bit for bit).

        ``points``: a polars DataFrame (or a mapping of columns) with any of
        ``axial_n``, ``radial_n``, ``moment_n_m``, ``speed_rpm`` (absent: 0;
        an older ``moment_nmm`` column in N mm is converted, with a warning);
        other columns are carried through. Options as in [`solve`][thermobear.Bearing.solve], for
        every point; ``threads`` (default: all cores) and
        ``progress(done, total)``.

        Returns the input columns followed by one row of outputs per point:
        ``axial_stiffness_seed_n_per_m``, ``radial_stiffness_seed_n_per_m``
        (seed A's series formula), ``k_xx_n_per_m``, ``k_zz_n_per_m``,
        ``k_ryry_n_m_per_rad`` (diagonal of
        the tangent stiffness), ``axial_displacement_um``,
        ``radial_displacement_um``, ``tilt_rad``, inner/outer contact angle
        max/min (``_deg``), ``inner_load_max_n``, ``outer_load_max_n``,
        ``centrifugal_force_n``, ``cage_speed_rpm``, ``residual``,
        ``iterations``, then ``ok``, ``error_kind`` and ``error``: a point that
        fails (bad input, no convergence) is a row with its error and null
        outputs; nothing is raised for it."""
        from .batch import column_array, join_inputs, operating_frame, result_frame

        names = ("axial_n", "radial_n", "moment_n_m", "speed_rpm")
        frame = operating_frame(_moment_in_n_m(points), names)
        arrays = [column_array(frame, c) for c in names]
        options = dict(
            effects=_effects_arg(effects),
            raceway_control=v.choice("raceway_control", raceway_control, _CONTROLS),
            misalignment_rad=self._tilt(misalignment_rad),
        )
        raw = _native.solve_many(
            self._b,
            arrays[0],
            arrays[1],
            arrays[2] * 1000.0,  # the native call takes N mm
            arrays[3],
            **options,
            threads=cap_threads(threads),
            progress=v.optional_callback("progress", progress),
        )
        plausibility.check_speeds(arrays[3], self._pitch_mm(), None)
        # a row whose contact reaches past the groove is a failed row, as in solve
        points = dict(zip(names, arrays, strict=True))
        past = plausibility.rows_past_the_groove(self, raw, points, options)
        for i, message in past.items():
            raw["ok"][i], raw["error_kind"][i], raw["error"][i] = False, "ConfigError", message
        return join_inputs(frame, result_frame(raw))

    def ring_forces(
        self,
        displacement: ArrayLike,
        speed_rpm: float = 0.0,
        *,
        effects: Optional[Sequence[str]] = None,
        raceway_control: RacewayControl = "outer",
    ) -> tuple[np.ndarray, np.ndarray]:
        """The forward map used inside time integration: for a prescribed
        inner-ring displacement ``[dx, dy, dz (m), theta_x, theta_y (rad)]``
        return the reaction of the balls on the inner ring
        ``[Fx, Fy, Fz (N), Mx, My (N m)]`` and the tangent stiffness
        ``-d(reaction)/d(displacement)`` (5x5, SI)."""
        q = [float(x) for x in v.reals("displacement", displacement)]
        if len(q) != 5:
            raise v.fail("displacement", q, "5 values [dx, dy, dz, tx, ty]")
        raw = self._b.ring_forces(
            q,
            v.real("speed_rpm", speed_rpm, 0.0),
            _effects_arg(effects),
            v.choice("raceway_control", raceway_control, _CONTROLS),
        )
        return np.asarray(raw["reaction"]), np.asarray(raw["stiffness_matrix"])

    def _pitch_mm(self) -> float:
        """The pitch diameter in mm (for the speed factor n dm)."""
        return plausibility._geometry(self)["pitch_diameter_mm"]

    def _tilt(self, misalignment_rad: Any) -> Optional[float]:
        """``misalignment_rad`` checked: a number or None, within the groove
        (warned past the plausibility limit)."""
        tilt = v.optional_real("misalignment_rad", misalignment_rad)
        if tilt:
            plausibility.check_misalignment(tilt, plausibility._geometry(self))
        return tilt

    def thermal_state(
        self,
        speed_rpm: float,
        axial_n: Optional[float] = None,
        radial_n: Optional[float] = None,
        **options: Any,
    ) -> Any:
        """The coupled thermal steady state of this bearing: the same
        computation as [`thermobear.thermal_state`][thermobear.thermal_state] (options as there);
        returns a [`ThermalState`][thermobear.ThermalState]."""
        return _task("thermal_state")(self, speed_rpm, axial_n, radial_n, **options)

    def thermal_state_many(self, points: Any, **options: Any) -> polars.DataFrame:
        """The coupled thermal steady state at many operating points: the
        same computation as [`thermobear.thermal_state_many`][thermobear.thermal_state_many] (points
        and options as there; one row per point, failed points as rows with
        their error)."""
        return _task("thermal_state_many")(self, points, **options)

    def __repr__(self) -> str:
        return repr(self._b)


def _moment_in_n_m(points: Any) -> Any:
    """``points`` with an older ``moment_nmm`` column (N mm) as ``moment_n_m``."""
    import polars as pl

    if not isinstance(points, (pl.DataFrame, dict)):
        return points  # operating_frame says what it takes
    cols = points.columns if isinstance(points, pl.DataFrame) else list(points)
    if "moment_nmm" not in cols:
        return points
    if "moment_n_m" in cols:
        from ..errors import ConfigError

        raise ConfigError("invalid points = both moment_nmm and moment_n_m: give moment_n_m")
    warn_renamed("moment_nmm", "moment_n_m", stacklevel=3, what="value in N m, not N mm")
    if isinstance(points, pl.DataFrame):
        return points.with_columns((pl.col("moment_nmm") / 1000.0).alias("moment_n_m")).drop(
            "moment_nmm"
        )
    out = {k: v for k, v in points.items() if k != "moment_nmm"}
    out["moment_n_m"] = np.asarray(points["moment_nmm"], dtype=float) / 1000.0
    return out


#: Tasks of a bearing computed by a higher layer (the thermal model) and
#: offered here as methods: name -> function(bearing, ...). The module that
#: computes a task registers it (``register_task``) when it is imported,
#: which ``import thermobear`` always does.
_TASKS: dict[str, Any] = {}


def register_task(name: str, function: Any) -> None:
    """Offer ``function(bearing, ...)`` as the [`Bearing`][thermobear.Bearing] method ``name``."""
    _TASKS[name] = function


def _task(name: str) -> Any:
    if name not in _TASKS:  # only when thermobear.thermal was never imported
        from ..errors import ConfigError

        raise ConfigError(f"invalid task = {name!r}: import thermobear first")
    return _TASKS[name]


@dataclass(frozen=True)
class BearingSolution:
    """A solved bearing. SI inside ``raw``; displacements in um."""

    raw: dict[str, Any]

    @property
    def displacement(self) -> np.ndarray:
        """Inner-ring displacement [dx, dy, dz (m), theta_x, theta_y (rad)]."""
        return np.asarray(self.raw["displacement"])

    @property
    def axial_displacement_um(self) -> float:
        """Axial displacement of the inner ring [um]."""
        return float(self.displacement[2] * 1e6)

    @property
    def radial_displacement_um(self) -> float:
        """Radial displacement of the inner ring [um]."""
        return float(np.hypot(self.displacement[0], self.displacement[1]) * 1e6)

    @property
    def axial_displacement_mm(self) -> float:
        """Deprecated: [`axial_displacement_um`][thermobear.BearingSolution.axial_displacement_um]
        in mm."""
        warn_renamed("axial_displacement_mm", "axial_displacement_um", what="value in um")
        return self.axial_displacement_um / 1000.0

    @property
    def radial_displacement_mm(self) -> float:
        """Deprecated: [`radial_displacement_um`][thermobear.BearingSolution.radial_displacement_um]
        in mm."""
        warn_renamed("radial_displacement_mm", "radial_displacement_um", what="value in um")
        return self.radial_displacement_um / 1000.0

    @property
    def tilt_rad(self) -> float:
        return float(np.hypot(self.displacement[3], self.displacement[4]))

    @property
    def applied_load(self) -> np.ndarray:
        """[Fx, Fy, Fz (N), Mx, My (N m)] on the inner ring (moments are the
        reactions when the tilt is held)."""
        return np.asarray(self.raw["applied_load"])

    @property
    def stiffness(self) -> np.ndarray:
        """5x5 stiffness matrix d(F)/d(q), q = [dx, dy, dz, theta_x, theta_y],
        F = [Fx, Fy, Fz, Mx, My]; SI (N/m, N/rad, N m/m, N m/rad)."""
        return np.asarray(self.raw["stiffness_matrix"])

    @property
    def axial_stiffness_seed_n_per_m(self) -> float:
        """Seed A eq. 39-40 axial stiffness: the simplified series formula
        (the complete one is [`k_zz_n_per_m`][thermobear.BearingSolution.k_zz_n_per_m])."""
        return float(self.raw["axial_stiffness_n_per_m"])

    @property
    def radial_stiffness_seed_n_per_m(self) -> float:
        """Seed A eq. 41-42 radial stiffness: the simplified series formula
        (the complete one is [`k_xx_n_per_m`][thermobear.BearingSolution.k_xx_n_per_m])."""
        return float(self.raw["radial_stiffness_n_per_m"])

    @property
    def k_xx_n_per_m(self) -> float:
        """Radial entry of the full 5x5 tangent [`stiffness`][thermobear.BearingSolution.stiffness]
        [N/m]."""
        return float(self.stiffness[0, 0])

    @property
    def k_zz_n_per_m(self) -> float:
        """Axial entry of the full 5x5 tangent [`stiffness`][thermobear.BearingSolution.stiffness]
        [N/m]."""
        return float(self.stiffness[2, 2])

    @property
    def axial_stiffness_n_per_m(self) -> float:
        """Deprecated:
        [`axial_stiffness_seed_n_per_m`][thermobear.BearingSolution.axial_stiffness_seed_n_per_m]."""
        warn_renamed("axial_stiffness_n_per_m", "axial_stiffness_seed_n_per_m")
        return self.axial_stiffness_seed_n_per_m

    @property
    def radial_stiffness_n_per_m(self) -> float:
        """Deprecated:
        [`radial_stiffness_seed_n_per_m`][thermobear.BearingSolution.radial_stiffness_seed_n_per_m]."""
        warn_renamed("radial_stiffness_n_per_m", "radial_stiffness_seed_n_per_m")
        return self.radial_stiffness_seed_n_per_m

    @property
    def speed_rpm(self) -> float:
        return float(self.raw["speed_rpm"])

    @property
    def iterations(self) -> int:
        return int(self.raw["iterations"])

    @property
    def residual(self) -> float:
        return float(self.raw["residual"])

    @property
    def balls(self) -> polars.DataFrame:
        """Per ball: azimuth, loads, contact angles, deflections, kinematics."""
        import polars as pl

        return pl.DataFrame(renamed_columns(dict(self.raw["balls"])))

    def __repr__(self) -> str:
        return (
            f"BearingSolution({self.speed_rpm:g} rpm, axial {self.axial_displacement_um:.3g} um, "
            f"radial {self.radial_displacement_um:.3g} um, k_xx {self.k_xx_n_per_m:.3g} N/m)"
        )

    def summary(self) -> str:
        """The solved state in a few lines: speed, load, displacements,
        tilt, stiffness (full 5x5 diagonal and the seed formula),
        convergence."""
        f = self.applied_load
        return "\n".join(
            [
                f"bearing solution at {self.speed_rpm:g} rpm",
                f"  load: axial {f[2]:.4g} N, radial {float(np.hypot(f[0], f[1])):.4g} N, "
                f"moment {float(np.hypot(f[3], f[4])):.4g} N m",
                f"  displacement: axial {self.axial_displacement_um:.4g} um, radial "
                f"{self.radial_displacement_um:.4g} um, tilt {self.tilt_rad:.3g} rad",
                f"  stiffness (5x5): k_xx {self.k_xx_n_per_m:.4g} N/m, k_zz "
                f"{self.k_zz_n_per_m:.4g} N/m",
                f"  stiffness (seed formula): radial {self.radial_stiffness_seed_n_per_m:.4g} "
                f"N/m, axial {self.axial_stiffness_seed_n_per_m:.4g} N/m",
                f"  converged in {self.iterations} iterations, residual {self.residual:.3g}",
            ]
        )
