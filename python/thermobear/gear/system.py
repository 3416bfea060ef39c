"""The gear-shaft-bearing system of seed A: mass, stiffness and damping
matrices, the bearing stiffness schedule against speed."""

from __future__ import annotations

from typing import Any, Optional, Sequence, Union

import numpy as np

from .. import _native
from .pair import STIFFNESS_SPEEDS_RPM, GearPair, _config_error


def _schedule_from_frame(df: Any, n: int) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    for col in ("speed_rpm", "radial_stiffness_n_per_m", "axial_stiffness_n_per_m"):
        if col not in getattr(df, "columns", ()):
            raise _config_error(
                f"invalid stiffness = frame without {col!r}: need speed_rpm, "
                "radial_stiffness_n_per_m, axial_stiffness_n_per_m (per bearing)"
            )
    s = np.asarray(df["speed_rpm"], dtype=float)
    order = np.argsort(s, kind="stable")
    kr = np.asarray(df["radial_stiffness_n_per_m"], dtype=float)[order] * n
    ka = np.asarray(df["axial_stiffness_n_per_m"], dtype=float)[order] * n
    return s[order], kr, ka


class GearSystem:
    """The 8-DOF helical pair on its bearings.

    ``stiffness``: ``"constant"`` (zero-speed stiffness of ``bearings`` under
    the seed loads), ``"speed"`` (quasi-static stiffness at each speed, no
    thermal effects), ``"thermal"`` (from ``stiffness_curve(mode="thermal")``
    when the bearing module offers it) or a frame with ``speed_rpm``,
    ``radial_stiffness_n_per_m``, ``axial_stiffness_n_per_m`` of ONE bearing.
    Each shaft carries ``bearings_per_shaft`` (default 2) identical bearings
    in parallel: support stiffness = n x one bearing's (A-52, ``diag(Kr, Kr,
    Ka)`` for pinion and gear). Bearing loads follow the torque: Fa = 2380.9
    T/100 + 300 N preload, Fr = 1189.9 T/100 N (seed A section 2.3).

    ``backlash_um`` is the total clearance 2b. ``mesh_damping``:
    ``"in-contact"`` (A-46 as printed, default) or ``"always"``.
    """

    def __init__(
        self,
        gear: GearPair,
        bearings: Any = None,
        stiffness: Union[str, Any] = "constant",
        *,
        bearings_per_shaft: int = 2,
        backlash_um: float = 100.0,
        mesh_damping_ratio: float = 0.07,
        mesh_damping: str = "in-contact",
        bearing_damping_ratio: float = 0.02,
        te_amplitude_um: float = 2.0,
        torque_nm: Optional[float] = None,
        mesh_model: str = "potential-energy",
        table_points: int = 64,
        stiffness_speeds_rpm: Optional[Sequence[float]] = None,
    ) -> None:
        from ..bearing import Bearing
        from ..thermal import stiffness_curve

        if not isinstance(gear, GearPair):
            raise _config_error(f"invalid gear = {gear!r}: must be a thermobear.GearPair")
        if isinstance(bearings_per_shaft, bool) or int(bearings_per_shaft) < 1:
            raise _config_error(f"invalid bearings_per_shaft = {bearings_per_shaft!r}: at least 1")
        n = int(bearings_per_shaft)
        bearing = Bearing.preset("6208") if bearings is None else bearings
        torque = float(gear.geometry["input_torque_nm"] if torque_nm is None else torque_nm)
        fa, fr = _native.seed_gear_bearing_loads(torque)
        grid = np.asarray(
            STIFFNESS_SPEEDS_RPM if stiffness_speeds_rpm is None else stiffness_speeds_rpm,
            dtype=float,
        )
        if isinstance(stiffness, str):
            if stiffness in ("constant", "speed"):
                s, kr, ka = _native.gear_bearing_schedule(
                    bearing._b, stiffness, list(grid), fa, fr, n
                )
            elif stiffness == "thermal":
                try:
                    df = stiffness_curve(
                        bearing, grid, axial_n=fa, radial_n=fr, mode="thermal", misalignment_rad=0.0
                    )
                except Exception as e:  # the mode is added by the thermal module
                    raise _config_error(
                        "invalid stiffness = 'thermal': stiffness_curve(mode='thermal') is not "
                        f"available here ({e}); pass a frame with speed_rpm, "
                        "radial_stiffness_n_per_m, axial_stiffness_n_per_m instead"
                    ) from e
                s, kr, ka = _schedule_from_frame(df, n)
            else:
                raise _config_error(
                    f"invalid stiffness = {stiffness!r}: must be 'constant', 'speed', 'thermal' "
                    "or a frame"
                )
            self.stiffness_case = stiffness
        else:
            s, kr, ka = _schedule_from_frame(stiffness, n)
            self.stiffness_case = "user"
        self.gear = gear
        self.bearing = bearing
        self.bearings_per_shaft = n
        self.bearing_loads_n = {"axial_n": fa, "radial_n": fr}
        self._s = _native.GearSystem(
            gear._g,
            [float(v) for v in s],
            [float(v) for v in kr],
            [float(v) for v in ka],
            half_backlash_um=0.5 * float(backlash_um),
            mesh_damping_ratio=float(mesh_damping_ratio),
            mesh_damping=mesh_damping,
            bearing_damping_ratio=float(bearing_damping_ratio),
            te_amplitude_um=float(te_amplitude_um),
            torque_nm=torque,
            table_points=int(table_points),
            mesh_model=mesh_model,
        )

    @property
    def params(self) -> dict[str, float]:
        """Model numbers (mesh stiffness mean/min/max in N/m, normal
        direction; mesh damping N s/m; masses, radii, angles)."""
        return dict(self._s.params())

    @property
    def stiffness_schedule(self) -> "polars.DataFrame":  # noqa: F821
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
        return tuple(self._s.bearing_stiffness_at(float(speed_rpm)))  # type: ignore[return-value]

    def mass_matrix_kg(self, speed_rpm: float = 10_000.0) -> np.ndarray:
        """Diagonal mass matrix of q = [x_p, y_p, z_p, x_g, y_g, z_g, u]
        (u = R_p theta_p - R_g theta_g, equivalent mass)."""
        return np.diag(self._s.mass_diagonal_kg(float(speed_rpm)))

    def stiffness_matrix_n_per_m(
        self, speed_rpm: float = 10_000.0, mesh_stiffness_n_per_m: Optional[float] = None
    ) -> np.ndarray:
        """Linear stiffness matrix in contact (default: mean mesh stiffness)."""
        k = (
            self.params["mesh_stiffness_mean_n_per_m"]
            if mesh_stiffness_n_per_m is None
            else mesh_stiffness_n_per_m
        )
        return np.asarray(self._s.stiffness_matrix(float(speed_rpm), float(k)))

    def natural_frequencies_hz(
        self, speed_rpm: float = 10_000.0, mesh_stiffness_n_per_m: Optional[float] = None
    ) -> np.ndarray:
        """Undamped natural frequencies in contact, ascending [Hz]."""
        k = (
            self.params["mesh_stiffness_mean_n_per_m"]
            if mesh_stiffness_n_per_m is None
            else mesh_stiffness_n_per_m
        )
        return np.asarray(self._s.natural_frequencies_hz(float(speed_rpm), float(k)))

    def projection(self) -> np.ndarray:
        """Mesh-normal projection vector a of q (A-45)."""
        return np.asarray(self._s.projection())

    def mesh_tables(self) -> "polars.DataFrame":  # noqa: F821
        """k_m (normal) and the static TE the model uses over one mesh period."""
        import polars as pl

        return pl.DataFrame({k: np.asarray(v) for k, v in self._s.mesh_tables().items()})

    def mesh_period_s(self, speed_rpm: float) -> float:
        return float(self._s.mesh_period_s(float(speed_rpm)))

    def check_steps(self, speed_rpm: float, steps_per_period: int) -> None:
        """ConfigError if the RK4 step is too coarse at this speed."""
        self._s.check_steps(float(speed_rpm), int(steps_per_period))

    def __repr__(self) -> str:
        p = self.params
        return (
            f"GearSystem(stiffness={self.stiffness_case!r}, torque={p['torque_nm']:.1f} N m, "
            f"k_m={p['mesh_stiffness_mean_n_per_m'] / 1e6:.0f} N/um, "
            f"2b={2 * p['half_backlash_um']:.0f} um, TE={p['te_amplitude_um']:.1f} um)"
        )
