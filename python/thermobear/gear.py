"""Helical gear pair nonlinear dynamics (seed A, PHYSICS.md section 7).

* :class:`GearPair`: geometry, contact ratios, ISO 6336-1 stiffness, the
  time-varying mesh stiffness (potential-energy method), typo checks of
  paper-style tables.
* :class:`GearSystem`: the 8-DOF model (A-43 .. A-52; the two rotations
  reduced to the relative mesh coordinate, 7 DOF) with the computed mesh
  stiffness (normal direction, ``k_t / cos^2(beta)``) and the bearings'
  support stiffness against speed (``"constant"``, ``"speed"``,
  ``"thermal"`` or a user frame). Two bearings per shaft act in parallel.
* :func:`bifurcation`, :func:`bifurcation_set`, :func:`regimes`,
  :func:`regime_map`, :func:`largest_lyapunov`.

Every value the seed omits has a documented default (:func:`gear_defaults`):
total backlash 100 um (half backlash b = 50 um), mesh damping ratio 0.07
acting only while the teeth touch (A-46 as printed; ``mesh_damping="always"``
for the PHYSICS.md form), bearing damping ratio 0.02, first-harmonic
transmission error 2 um.
"""

from __future__ import annotations

from typing import Any, Callable, Mapping, Optional, Sequence, Union

import numpy as np

from . import _native

__all__ = [
    "GearPair",
    "GearSystem",
    "bifurcation",
    "bifurcation_set",
    "gear_defaults",
    "largest_lyapunov",
    "regime_map",
    "regimes",
]

#: Speeds at which the "speed" and "thermal" bearing stiffness is solved
#: (linear interpolation in between, constant beyond the ends) [rpm].
STIFFNESS_SPEEDS_RPM = np.arange(1000.0, 20000.0 + 1.0, 250.0)

Progress = Optional[Callable[[int, int], Any]]


def _config_error(msg: str) -> Exception:
    from .errors import ConfigError

    return ConfigError(msg)


class GearPair:
    """A helical gear pair. ``GearPair.preset("seed-electric-drive")`` is seed
    A's first pair (Table 3, typos corrected); :meth:`from_table` takes a
    paper-style table (E in MPa, density in t/mm^3, inertia in t mm^2) and
    refuses typos, naming the likely intended value."""

    def __init__(self, native: Any) -> None:
        self._g = native

    @classmethod
    def preset(cls, name: str) -> "GearPair":
        return cls(_native.GearPair.preset(name))

    @staticmethod
    def preset_names() -> list[str]:
        return list(_native.GearPair.preset_names())

    @classmethod
    def from_table(
        cls,
        *,
        pinion_teeth: int,
        gear_teeth: int,
        normal_module_mm: float,
        normal_pressure_angle_deg: float,
        helix_angle_deg: float,
        face_width_mm: float,
        youngs_modulus_mpa: float,
        poisson_ratio: float,
        density_t_per_mm3: float,
        mass_kg: Sequence[float],
        polar_inertia_t_mm2: Sequence[float],
        input_torque_nm: float,
        profile_shift_coeff: Sequence[float] = (0.0, 0.0),
        addendum_coeff: float = 1.0,
        dedendum_coeff: float = 1.25,
    ) -> "GearPair":
        return cls(
            _native.GearPair.from_table(
                int(pinion_teeth),
                int(gear_teeth),
                float(normal_module_mm),
                float(normal_pressure_angle_deg),
                float(helix_angle_deg),
                float(face_width_mm),
                float(youngs_modulus_mpa),
                float(poisson_ratio),
                float(density_t_per_mm3),
                (float(mass_kg[0]), float(mass_kg[1])),
                (float(polar_inertia_t_mm2[0]), float(polar_inertia_t_mm2[1])),
                float(input_torque_nm),
                (float(profile_shift_coeff[0]), float(profile_shift_coeff[1])),
                float(addendum_coeff),
                float(dedendum_coeff),
            )
        )

    @property
    def geometry(self) -> dict[str, float]:
        """Derived geometry (mm, deg) and the contact ratios."""
        return dict(self._g.geometry())

    @property
    def transverse_contact_ratio(self) -> float:
        return self.geometry["transverse_contact_ratio"]

    @property
    def overlap_ratio(self) -> float:
        return self.geometry["overlap_ratio"]

    @property
    def iso_stiffness(self) -> dict[str, float]:
        """ISO 6336-1 Method B: c' (``single_n_per_mm_um``), c_gamma_alpha,
        c_gamma_beta [N/(mm um)] and totals over the face width [N/m]."""
        return dict(self._g.iso_stiffness())

    def mesh_stiffness(
        self, points: int = 64, model: str = "potential-energy"
    ) -> "polars.DataFrame":  # noqa: F821
        """k_m over one mesh period: ``mesh_phase``,
        ``transverse_stiffness_n_per_m`` (along the transverse line of action,
        comparable with ISO's c_gamma b) and ``normal_stiffness_n_per_m`` (for
        the normal deflection of A-45, what the dynamics use)."""
        import polars as pl

        cols = self._g.mesh_stiffness(int(points), model)
        return pl.DataFrame({k: np.asarray(v) for k, v in cols.items()})

    @property
    def typo_warnings(self) -> "polars.DataFrame":  # noqa: F821
        """The source table's suspicious values with the likely intended ones
        (for the preset: seed A Table 3 as printed)."""
        import polars as pl

        rows = self._g.typo_warnings()
        return pl.DataFrame(
            {
                "field": [r["field"] for r in rows],
                "given": [float(r["given"]) for r in rows],
                "likely_intended": [float(r["likely_intended"]) for r in rows],
                "reason": [r["reason"] for r in rows],
            },
            schema={
                "field": pl.Utf8,
                "given": pl.Float64,
                "likely_intended": pl.Float64,
                "reason": pl.Utf8,
            },
        )

    def mesh_frequency_hz(self, speed_rpm: float) -> float:
        return float(self._g.mesh_frequency_hz(float(speed_rpm)))

    def __repr__(self) -> str:
        return repr(self._g)


def gear_defaults() -> "polars.DataFrame":  # noqa: F821
    """The values seed A does not give, with the defaults used and why."""
    import polars as pl

    d = _native.gear_defaults()
    rows = [
        ("backlash_um", 2.0 * d["half_backlash_um"], "total clearance 2b; b = 50 um (not in A)"),
        ("mesh_damping_ratio", d["mesh_damping_ratio"], "usual 0.03-0.17 range (not in A)"),
        ("mesh_damping", None, "in-contact only (A-46 as printed); 'always' offered"),
        ("bearing_damping_ratio", d["bearing_damping_ratio"], "on body mass (not in A)"),
        ("te_amplitude_um", d["te_amplitude_um"], "first mesh harmonic (not in A)"),
        ("bearings_per_shaft", d["bearings_per_shaft"], "A Fig. 1; in parallel"),
        ("mesh_table_points", d["table_points"], "k_m and e samples per mesh period"),
    ]
    return pl.DataFrame(
        {
            "parameter": [r[0] for r in rows],
            "value": [r[1] for r in rows],
            "note": [r[2] for r in rows],
        }
    )


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
        from .bearing import Bearing, stiffness_curve

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


def _speeds(speeds_rpm: Sequence[float]) -> np.ndarray:
    s = np.ascontiguousarray(np.asarray(speeds_rpm, dtype=float).ravel())
    if s.size == 0:
        raise _config_error("invalid speeds_rpm = []: give at least one speed")
    return s


def _check_system(system: Any) -> None:
    if not isinstance(system, GearSystem):
        raise _config_error(f"invalid system = {system!r}: must be a thermobear.GearSystem")


def _points_frame(
    cols: Mapping[str, Any], direction: str, case: Optional[str]
) -> "polars.DataFrame":  # noqa: F821
    import polars as pl

    counts = np.asarray(cols["poincare_count"])
    per_speed = {
        "speed_rpm": np.asarray(cols["speed_rpm"]),
        "regime": list(cols["regime"]),
        "period": np.asarray(cols["period"]),
        "impact": list(cols["impact"]),
        "lyapunov_per_period": list(cols["lyapunov_per_period"]),
        "dte_min_um": np.asarray(cols["dte_min_um"]),
        "dte_max_um": np.asarray(cols["dte_max_um"]),
        "jump_after": list(cols["jump_after"]),
    }
    speed_df = pl.DataFrame(per_speed, schema_overrides={"lyapunov_per_period": pl.Float64})
    idx = np.repeat(np.arange(len(counts)), counts)
    df = speed_df[idx].with_columns(pl.Series("dte_um", np.asarray(cols["poincare_dte_um"])))
    df = df.with_columns(pl.lit(direction).alias("direction"))
    if case is not None:
        df = df.with_columns(pl.lit(case).alias("case"))
    first = ["speed_rpm", "dte_um"]
    return df.select(first + [c for c in df.columns if c not in first])


def bifurcation(
    system: GearSystem,
    speeds_rpm: Sequence[float],
    direction: str = "up",
    transient_periods: int = 300,
    record_periods: int = 100,
    steps_per_period: int = 64,
    *,
    lyapunov_periods: int = 100,
    progress: Progress = None,
) -> "polars.DataFrame":  # noqa: F821
    """Speed sweep (A Figs. 14-15): ``"up"``/``"down"`` carry the state from
    speed to speed (continuation), ``"independent"`` starts every speed from
    the static state (parallel). One row per Poincare sample (once per mesh
    period): ``speed_rpm``, ``dte_um`` (dynamic transmission error
    ``delta_n - e`` along the mesh normal), and per-speed ``regime``
    (period-n / quasi-periodic / chaotic), ``period``, ``impact``
    (no-impact / single-sided / double-sided), ``lyapunov_per_period``
    (non-periodic speeds), ``dte_min_um``, ``dte_max_um``, ``jump_after``
    (amplitude jump to the next speed), ``direction``.
    GIL released; Ctrl-C interrupts; ``progress(done, total)``."""
    _check_system(system)
    cols = _native.bifurcation(
        system._s,
        _speeds(speeds_rpm),
        direction,
        int(transient_periods),
        int(record_periods),
        int(steps_per_period),
        int(lyapunov_periods),
        progress,
    )
    return _points_frame(cols, direction, None)


def bifurcation_set(
    systems: Mapping[str, GearSystem],
    speeds_rpm: Sequence[float],
    directions: Sequence[str] = ("up", "down"),
    transient_periods: int = 300,
    record_periods: int = 100,
    steps_per_period: int = 64,
    *,
    lyapunov_periods: int = 100,
    progress: Progress = None,
) -> "polars.DataFrame":  # noqa: F821
    """Every (case, direction) sweep over the same speeds in parallel
    (lock-step batches); the :func:`bifurcation` columns plus ``case``."""
    import polars as pl

    if not systems:
        raise _config_error("invalid systems = {}: give at least one")
    jobs = [(name, sys, d) for name, sys in systems.items() for d in directions]
    for _, sys, _ in jobs:
        _check_system(sys)
    res = _native.bifurcation_many(
        [j[1]._s for j in jobs],
        [j[2] for j in jobs],
        _speeds(speeds_rpm),
        int(transient_periods),
        int(record_periods),
        int(steps_per_period),
        int(lyapunov_periods),
        progress,
    )
    return pl.concat([_points_frame(c, d, name) for (name, _, d), c in zip(jobs, res)])


def _per_speed_from_points(pts: Any, rel_tol: float = 1e-3, max_period: int = 16) -> Any:
    """Per-speed regime from bare Poincare samples: the smallest n with
    x[k+n] = x[k] (within rel_tol of the diagram's range) for all k."""
    import polars as pl

    span = float(pts["dte_um"].max() - pts["dte_um"].min()) or 1.0
    rows = []
    for (speed,), g in pts.group_by(["speed_rpm"], maintain_order=True):
        x = g["dte_um"].to_numpy()
        period = 0
        for n in range(1, min(max_period, len(x) - 1) + 1):
            if np.all(np.abs(x[n:] - x[:-n]) <= rel_tol * span):
                period = n
                break
        rows.append((speed, f"period-{period}" if period else "non-periodic", period))
    return pl.DataFrame(
        {
            "speed_rpm": [r[0] for r in rows],
            "regime": [r[1] for r in rows],
            "period": [r[2] for r in rows],
        }
    )


def regimes(pts: Any) -> "polars.DataFrame":  # noqa: F821
    """Collapse a :func:`bifurcation` frame into speed ranges of one regime:
    ``speed_from_rpm``, ``speed_to_rpm``, ``regime``, ``period``, ``impact``,
    ``speeds`` (count), ``jump_at_end`` (amplitude jump to the next range),
    per ``case``/``direction`` when present. A frame with only ``speed_rpm``
    and ``dte_um`` is classified by the period of its samples."""
    import polars as pl

    if "speed_rpm" not in pts.columns:
        raise _config_error("invalid pts = frame without 'speed_rpm'")
    keys = [k for k in ("case", "direction") if k in pts.columns]
    if "regime" in pts.columns:
        cols = ["speed_rpm", "regime"] + [
            c for c in ("period", "impact", "jump_after") if c in pts.columns
        ]
        per = pts.select(keys + cols).unique(
            subset=keys + ["speed_rpm"], keep="first", maintain_order=True
        )
    else:
        if "dte_um" not in pts.columns:
            raise _config_error("invalid pts = frame without 'regime' or 'dte_um'")
        parts = []
        groups = pts.group_by(keys, maintain_order=True) if keys else [((), pts)]
        for key, g in groups:
            p = _per_speed_from_points(g)
            for k, v in zip(keys, key if isinstance(key, tuple) else (key,)):
                p = p.with_columns(pl.lit(v).alias(k))
            parts.append(p)
        per = pl.concat(parts)
    if "period" not in per.columns:
        per = per.with_columns(pl.lit(0).alias("period"))
    if "impact" not in per.columns:
        per = per.with_columns(pl.lit("unknown").alias("impact"))
    if "jump_after" not in per.columns:
        per = per.with_columns(pl.lit(False).alias("jump_after"))
    out = []
    groups = per.group_by(keys, maintain_order=True) if keys else [((), per)]
    for key, g in groups:
        g = g.sort("speed_rpm")
        s = g["speed_rpm"].to_numpy()
        reg = g["regime"].to_list()
        per_n = g["period"].to_list()
        imp = g["impact"].to_list()
        jump = g["jump_after"].to_list()
        start = 0
        for i in range(len(s)):
            last = i == len(s) - 1
            if last or jump[i] or reg[i + 1] != reg[i] or imp[i + 1] != imp[i]:
                row = dict(zip(keys, key if isinstance(key, tuple) else (key,)))
                row.update(
                    speed_from_rpm=float(s[start]),
                    speed_to_rpm=float(s[i]),
                    regime=reg[i],
                    period=int(per_n[i]),
                    impact=imp[i],
                    speeds=i - start + 1,
                    jump_at_end=bool(jump[i]) and not last,
                )
                out.append(row)
                start = i + 1
    return pl.DataFrame(out)


def regime_map(
    system: GearSystem,
    torques_nm: Sequence[float],
    speeds_rpm: Sequence[float],
    te_scales: Sequence[float] = (1.0,),
    transient_periods: int = 300,
    record_periods: int = 100,
    steps_per_period: int = 64,
    *,
    lyapunov_periods: int = 100,
    progress: Progress = None,
) -> "polars.DataFrame":  # noqa: F821
    """Motion regime over input torque x speed (x TE scale), every cell from
    its static state: ``torque_nm``, ``te_scale``, ``te_amplitude_um``,
    ``speed_rpm``, ``regime``, ``period``, ``impact``, ``amplitude_um``,
    ``mean_dte_um``. The bearing stiffness schedule stays the system's."""
    import polars as pl

    _check_system(system)
    torques = [float(t) for t in np.asarray(torques_nm, dtype=float).ravel()]
    scales = [float(e) for e in np.asarray(te_scales, dtype=float).ravel()]
    cols = _native.regime_map(
        system._s,
        torques,
        scales,
        _speeds(speeds_rpm),
        int(transient_periods),
        int(record_periods),
        int(steps_per_period),
        int(lyapunov_periods),
        progress,
    )
    df = pl.DataFrame(
        {k: (np.asarray(v) if not isinstance(v, list) else v) for k, v in cols.items()}
    )
    te = system.params["te_amplitude_um"]
    return df.with_columns((pl.col("te_scale") * te).alias("te_amplitude_um"))


def largest_lyapunov(
    system_or_name: Union[str, GearSystem],
    speed_rpm: Optional[float] = None,
    *,
    time: Optional[float] = None,
    step: Optional[float] = None,
    transient_time: Optional[float] = None,
    method: str = "benettin",
    periods: int = 200,
    transient_periods: int = 300,
    steps_per_period: int = 64,
) -> float:
    """Largest Lyapunov exponent per unit time.

    Reference systems by name: ``"lorenz"`` (sigma 10, rho 28, beta 8/3;
    published 0.9056) and ``"duffing-ueda"`` (x'' + 0.05 x' + x^3 = 7.5 cos t;
    about 0.10), ``method="benettin"`` or ``"variational"``. For a
    :class:`GearSystem` give ``speed_rpm``; the exponent is in 1/s (Benettin,
    renormalised once per mesh period)."""
    if isinstance(system_or_name, str):
        return float(
            _native.largest_lyapunov_reference(system_or_name, time, step, transient_time, method)
        )
    _check_system(system_or_name)
    if speed_rpm is None:
        raise _config_error("invalid speed_rpm = None: a gear system needs a speed")
    return float(
        _native.largest_lyapunov_gear(
            system_or_name._s,
            float(speed_rpm),
            int(periods),
            int(transient_periods),
            int(steps_per_period),
        )
    )
