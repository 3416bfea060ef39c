"""Ball bearings: construction, solving, stiffness.

Every length a user passes or reads carries its unit in the name
(``ball_diameter_mm``, ``axial_displacement_mm``); forces are N, moments
N mm where the name says ``_nmm``; ``stiffness`` matrices are SI.

Displacements follow ISO/TS 16281: they are measured from the concentric
position with the groove curvature centres in one plane, so taking up the
clearance is part of the displacement (a deep-groove bearing with clearance
moves axially by about ``A sin(alpha0)`` before it carries any load).
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any, Optional, Sequence

import numpy as np

from .. import _native
from .material import Material, _native_material


def _effects_arg(effects: Optional[Sequence[str]]) -> Optional[list[str]]:
    if effects is None:
        return None
    if isinstance(effects, str):
        return [effects]
    return [str(e) for e in effects]


class Bearing:
    """A ball bearing (deep-groove or angular-contact).

    Build with :meth:`preset` (``"6208"``, ``"7008C"``, ``"7009C"``, each also
    ``-hybrid`` with Si3N4 balls and ``-ceramic``), :meth:`deep_groove`,
    :meth:`angular_contact` or :meth:`from_toml`.
    """

    def __init__(self, native: Any) -> None:
        self._b = native

    # -- construction -------------------------------------------------
    @classmethod
    def preset(cls, name: str) -> "Bearing":
        return cls(_native.Bearing.preset(name))

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
        return cls(
            _native.Bearing.deep_groove(
                int(ball_count),
                float(ball_diameter_mm),
                float(pitch_diameter_mm),
                float(inner_conformity),
                float(outer_conformity),
                float(diametral_clearance_mm),
                float(bore_mm),
                float(outer_diameter_mm),
                float(width_mm),
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
        return cls(
            _native.Bearing.angular_contact(
                int(ball_count),
                float(ball_diameter_mm),
                float(pitch_diameter_mm),
                float(inner_conformity),
                float(outer_conformity),
                float(free_contact_angle_deg),
                float(bore_mm),
                float(outer_diameter_mm),
                float(width_mm),
                _native_material(ring_material),
                _native_material(ball_material),
                name,
            )
        )

    @classmethod
    def from_toml(cls, path_or_text: str) -> "Bearing":
        """The ``[bearing]`` of a system description file or text."""
        from ..config import load_config

        return cls(_native.Bearing.from_toml(load_config(path_or_text)))

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
        return dict(self._b.contact(raceway, float(contact_angle_deg), float(load_n), bool(exact)))

    # -- solving -------------------------------------------------------
    def solve(
        self,
        axial_n: float = 0.0,
        radial_n: float = 0.0,
        moment_nmm: float = 0.0,
        speed_rpm: float = 0.0,
        *,
        effects: Optional[Sequence[str]] = None,
        raceway_control: str = "outer",
        misalignment_rad: Optional[float] = 0.0,
    ) -> BearingSolution:
        """Solve the bearing under an axial force, a radial force (along x)
        and a tilting moment (about y) at an inner-ring speed.

        At ``speed_rpm=0`` this is the static (Hertz) solve; above it the
        Jones-Harris quasi-static model with the named ``effects`` (default:
        all; see :func:`thermobear.effects`), with outer- (default) or
        inner-``raceway_control``.

        The inner ring's tilt is held at ``misalignment_rad`` (default 0: the
        ISO/TS 16281 practice of a ring held by shaft and housing; the moment
        needed to hold it is a reaction). With ``misalignment_rad=None`` the
        tilt is free and solved so that the bearing carries ``moment_nmm``."""
        raw = self._b.solve(
            float(axial_n),
            float(radial_n),
            float(moment_nmm),
            float(speed_rpm),
            _effects_arg(effects),
            raceway_control,
            None if misalignment_rad is None else float(misalignment_rad),
        )
        return BearingSolution(raw)

    def solve_many(
        self,
        points: Any,
        *,
        effects: Optional[Sequence[str]] = None,
        raceway_control: str = "outer",
        misalignment_rad: Optional[float] = 0.0,
        threads: Optional[int] = None,
        progress: Any = None,
    ) -> "polars.DataFrame":  # noqa: F821
        """Solve many operating points in one native call (rayon threads,
        GIL released, Ctrl-C within 50 ms), each exactly as :meth:`solve`
        would (bit for bit).

        ``points``: a polars DataFrame (or a mapping of columns) with any of
        ``axial_n``, ``radial_n``, ``moment_nmm``, ``speed_rpm`` (absent: 0);
        other columns are carried through. Options as in :meth:`solve`, for
        every point; ``threads`` (default: all cores) and
        ``progress(done, total)``.

        Returns the input columns followed by one row of outputs per point:
        ``axial_stiffness_n_per_m``, ``radial_stiffness_n_per_m`` (seed A),
        ``k_xx_n_per_m``, ``k_zz_n_per_m``, ``k_ryry_nm_per_rad`` (diagonal of
        the tangent stiffness), ``axial_displacement_um``,
        ``radial_displacement_um``, ``tilt_rad``, inner/outer contact angle
        max/min (``_deg``), ``inner_load_max_n``, ``outer_load_max_n``,
        ``centrifugal_force_n``, ``cage_speed_rpm``, ``residual``,
        ``iterations``, then ``ok``, ``error_kind`` and ``error``: a point that
        fails (bad input, no convergence) is a row with its error and null
        outputs; nothing is raised for it."""
        from .batch import column_array, join_inputs, operating_frame, result_frame

        names = ("axial_n", "radial_n", "moment_nmm", "speed_rpm")
        frame = operating_frame(points, names)
        raw = _native.solve_many(
            self._b,
            *(column_array(frame, c) for c in names),
            effects=_effects_arg(effects),
            raceway_control=raceway_control,
            misalignment_rad=None if misalignment_rad is None else float(misalignment_rad),
            threads=None if threads is None else int(threads),
            progress=progress,
        )
        return join_inputs(frame, result_frame(raw))

    def ring_forces(
        self,
        displacement: Sequence[float],
        speed_rpm: float = 0.0,
        *,
        effects: Optional[Sequence[str]] = None,
        raceway_control: str = "outer",
    ) -> tuple[np.ndarray, np.ndarray]:
        """The forward map used inside time integration: for a prescribed
        inner-ring displacement ``[dx, dy, dz (m), theta_x, theta_y (rad)]``
        return the reaction of the balls on the inner ring
        ``[Fx, Fy, Fz (N), Mx, My (N m)]`` and the tangent stiffness
        ``-d(reaction)/d(displacement)`` (5x5, SI)."""
        q = [float(v) for v in np.asarray(displacement, dtype=float).ravel()]
        if len(q) != 5:
            from ..errors import ConfigError

            raise ConfigError(f"invalid displacement = {q}: needs 5 values [dx, dy, dz, tx, ty]")
        raw = self._b.ring_forces(q, float(speed_rpm), _effects_arg(effects), raceway_control)
        return np.asarray(raw["reaction_n_nm"]), np.asarray(raw["stiffness_matrix"])

    def __repr__(self) -> str:
        return repr(self._b)


@dataclass(frozen=True)
class BearingSolution:
    """A solved bearing. SI inside ``raw``; convenience properties in mm."""

    raw: dict

    @property
    def displacement(self) -> np.ndarray:
        """Inner-ring displacement [dx, dy, dz (m), theta_x, theta_y (rad)]."""
        return np.asarray(self.raw["displacement"])

    @property
    def axial_displacement_mm(self) -> float:
        return float(self.displacement[2] * 1e3)

    @property
    def radial_displacement_mm(self) -> float:
        return float(np.hypot(self.displacement[0], self.displacement[1]) * 1e3)

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
    def axial_stiffness_n_per_m(self) -> float:
        """Seed A eq. 39-40 axial stiffness."""
        return float(self.raw["axial_stiffness_n_per_m"])

    @property
    def radial_stiffness_n_per_m(self) -> float:
        """Seed A eq. 41-42 radial stiffness."""
        return float(self.raw["radial_stiffness_n_per_m"])

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
    def balls(self) -> "polars.DataFrame":  # noqa: F821
        """Per ball: azimuth, loads, contact angles, deflections, kinematics."""
        import polars as pl

        return pl.DataFrame({k: np.asarray(v) for k, v in self.raw["balls"].items()})
