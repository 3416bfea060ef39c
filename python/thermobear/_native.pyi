"""Type stubs of the Rust extension module ``thermobear._native``.

SI inside; every argument name carries its unit. Arrays are float64 numpy.
"""

from typing import Any, Callable, Optional, Sequence, final

import numpy as np
import numpy.typing as npt

__version__: str

#: Rebuild a native object from the versioned state of ``__reduce__``
#: (``{"format": "thermobear", "version": 1, "kind": ..., "data": <JSON>}``);
#: an unknown format, version or kind raises ConfigError.
_restore: Callable[[dict[str, Any]], Any]

class ThermobearError(Exception): ...
class ConfigError(ThermobearError): ...
class ConvergenceError(ThermobearError): ...
class ThermalRunawayError(ConvergenceError): ...
class DataError(ThermobearError): ...

class Interrupted(ThermobearError):
    done: int
    total: int

class ThreadsWarning(RuntimeWarning): ...

def available_cores() -> int:
    """The number of cores a ``threads`` argument is capped to."""

@final  # a native class: Python cannot subclass it
class Material:
    def __reduce__(self) -> tuple[Callable[[dict[str, Any]], Any], tuple[dict[str, Any]]]:
        """Pickle support: ``(_restore, ({format, version, kind, data},))``."""
    def __new__(
        cls,
        name: str,
        youngs_modulus_gpa: float,
        poisson_ratio: float,
        density_kg_m3: float,
        thermal_expansion_per_k: float,
        conductivity_w_mk: float,
        specific_heat_j_kgk: float,
    ) -> Material: ...
    @staticmethod
    def preset(name: str) -> Material: ...
    @staticmethod
    def preset_names() -> list[str]: ...
    @property
    def name(self) -> str: ...
    @property
    def youngs_modulus_gpa(self) -> float: ...
    @property
    def poisson_ratio(self) -> float: ...
    @property
    def density_kg_m3(self) -> float: ...
    @property
    def thermal_expansion_per_k(self) -> float: ...
    @property
    def conductivity_w_mk(self) -> float: ...
    @property
    def specific_heat_j_kgk(self) -> float: ...

@final  # a native class: Python cannot subclass it
class Bearing:
    def __reduce__(self) -> tuple[Callable[[dict[str, Any]], Any], tuple[dict[str, Any]]]:
        """Pickle support: ``(_restore, ({format, version, kind, data},))``."""
    @staticmethod
    def preset(name: str) -> Bearing: ...
    @staticmethod
    def preset_names() -> list[str]: ...
    @staticmethod
    def deep_groove(
        ball_count: int,
        ball_diameter_mm: float,
        pitch_diameter_mm: float,
        inner_conformity: float,
        outer_conformity: float,
        diametral_clearance_mm: float,
        bore_mm: float,
        outer_diameter_mm: float,
        width_mm: float,
        ring_material: Optional[Material] = None,
        ball_material: Optional[Material] = None,
        name: Optional[str] = None,
    ) -> Bearing: ...
    @staticmethod
    def angular_contact(
        ball_count: int,
        ball_diameter_mm: float,
        pitch_diameter_mm: float,
        inner_conformity: float,
        outer_conformity: float,
        free_contact_angle_deg: float,
        bore_mm: float,
        outer_diameter_mm: float,
        width_mm: float,
        ring_material: Optional[Material] = None,
        ball_material: Optional[Material] = None,
        name: Optional[str] = None,
    ) -> Bearing: ...
    @staticmethod
    def from_toml(text: str, catalogue: Optional[dict[str, Bearing]] = None) -> Bearing: ...
    @property
    def name(self) -> str: ...
    @property
    def bearing_type(self) -> str: ...
    @property
    def material_class(self) -> str: ...
    @property
    def ring_material(self) -> Material: ...
    @property
    def ball_material(self) -> Material: ...
    def geometry(self) -> dict[str, float]: ...
    def contact(
        self, raceway: str, contact_angle_deg: float, load_n: float = 1000.0, exact: bool = True
    ) -> dict[str, float]: ...
    def solve(
        self,
        axial_n: float,
        radial_n: float,
        moment_n_m: float,
        speed_rpm: float,
        effects: Optional[Sequence[str]] = None,
        raceway_control: str = "outer",
        misalignment_rad: Optional[float] = ...,  # 0.0
    ) -> dict: ...
    def ring_forces(
        self,
        displacement: Sequence[float],
        speed_rpm: float,
        effects: Optional[Sequence[str]] = None,
        raceway_control: str = "outer",
    ) -> dict: ...

def effects() -> list[tuple[str, str, list[str]]]: ...
def check_config(text: str, catalogue: Optional[dict[str, Bearing]] = None) -> list[str]: ...
def stiffness_curve(
    bearing: Bearing,
    speeds_rpm: npt.NDArray[np.float64],
    axial_n: float,
    radial_n: float,
    moment_n_m: float,
    effects: Optional[Sequence[str]] = None,
    raceway_control: str = "outer",
    misalignment_rad: Optional[float] = ...,  # 0.0
    progress: Optional[Callable[[int, int], None]] = None,
) -> dict[str, npt.NDArray[np.float64]]: ...

# ---- batch entry points (src/python/batch.rs): one row per point, errors per row ----

def solve_many(
    bearing: Bearing,
    axial_n: npt.NDArray[np.float64],
    radial_n: npt.NDArray[np.float64],
    moment_n_m: npt.NDArray[np.float64],
    speed_rpm: npt.NDArray[np.float64],
    effects: Optional[Sequence[str]] = None,
    raceway_control: str = "outer",
    misalignment_rad: Optional[float] = ...,  # 0.0
    threads: Optional[int] = None,
    progress: Optional[Callable[[int, int], None]] = None,
) -> dict[str, Any]:
    """Output arrays (NaN/0 where a point failed), ``ok`` (bool array),
    ``error_kind`` and ``error`` (lists of str or None)."""

# ---- the core's default solver options (src/python/defaults.rs) ----
def default_solve_options() -> dict[str, Any]:
    """``SolveOptions::default()`` of the Rust core (tilt held level)."""

def solve_with_default_options(
    bearing: Bearing,
    axial_n: float,
    radial_n: float,
    moment_n_m: float,
    speed_rpm: float,
) -> dict[str, Any]:
    """One point solved with the core's default options untouched."""

# ---- helical gear pair dynamics (src/python/gear.rs) ----

@final  # a native class: Python cannot subclass it
class GearPair:
    def __reduce__(self) -> tuple[Callable[[dict[str, Any]], Any], tuple[dict[str, Any]]]:
        """Pickle support: ``(_restore, ({format, version, kind, data},))``."""
    @staticmethod
    def preset(name: str) -> GearPair: ...
    @staticmethod
    def preset_names() -> list[str]: ...
    @staticmethod
    def from_table(
        pinion_teeth: int,
        gear_teeth: int,
        normal_module_mm: float,
        normal_pressure_angle_deg: float,
        helix_angle_deg: float,
        face_width_mm: float,
        youngs_modulus_mpa: float,
        poisson_ratio: float,
        density_t_per_mm3: float,
        mass_kg: tuple[float, float],
        polar_inertia_t_mm2: tuple[float, float],
        input_torque_nm: float,
        profile_shift_coeff: tuple[float, float] = ...,  # (0.0, 0.0)
        addendum_coeff: float = 1.0,
        dedendum_coeff: float = 1.25,
    ) -> GearPair: ...
    def typo_warnings(self) -> list[dict]: ...
    def geometry(self) -> dict[str, float]: ...
    def iso_stiffness(self) -> dict[str, float]: ...
    def mesh_stiffness(
        self, points: int = 64, model: str = "potential-energy"
    ) -> dict[str, npt.NDArray[np.float64]]: ...
    def tooth_pair_stiffness(
        self, points: int = 256, model: str = "potential-energy"
    ) -> dict[str, npt.NDArray[np.float64]]: ...
    def mesh_frequency_hz(self, speed_rpm: float) -> float: ...

@final  # a native class: Python cannot subclass it
class GearSystem:
    def __reduce__(self) -> tuple[Callable[[dict[str, Any]], Any], tuple[dict[str, Any]]]:
        """Pickle support: ``(_restore, ({format, version, kind, data},))``."""
    def __new__(
        cls,
        gear: GearPair,
        speeds_rpm: Sequence[float],
        radial_stiffness_n_per_m: Sequence[float],
        axial_stiffness_n_per_m: Sequence[float],
        *,
        half_backlash_um: float = 50.0,
        mesh_damping_ratio: float = 0.07,
        mesh_damping: str = "in-contact",
        bearing_damping_ratio: float = 0.02,
        te_amplitude_um: Optional[float] = None,
        torque_nm: Optional[float] = None,
        table_points: int = 64,
        mesh_model: Optional[str] = None,
        mesh_stiffness_n_per_m: Optional[Sequence[float]] = None,
        transmission_error_m: Optional[Sequence[float]] = None,
        mesh_stiffness_scale: float = 1.0,
    ) -> GearSystem:
        """Support stiffness per shaft against speed; optional uniform mesh
        tables over one mesh period (phases i / n): normal mesh stiffness
        [N/m] instead of ``mesh_model``, TE [m] instead of
        ``te_amplitude_um`` (default 2 um); ``mesh_stiffness_scale``
        multiplies the mesh stiffness table. Negative ``torque_nm``: coast."""
    @property
    def mesh_model(self) -> str: ...
    def params(self) -> dict[str, float]: ...
    def schedule(self) -> tuple[list[float], list[float], list[float]]: ...
    def bearing_stiffness_at(self, speed_rpm: float) -> tuple[float, float]: ...
    def mass_diagonal_kg(self, speed_rpm: float) -> list[float]: ...
    def stiffness_matrix(
        self, speed_rpm: float, mesh_stiffness_n_per_m: float
    ) -> list[list[float]]: ...
    def natural_frequencies_hz(
        self, speed_rpm: float, mesh_stiffness_n_per_m: float
    ) -> list[float]: ...
    def projection(self) -> list[float]: ...
    def static_state_m(self, speed_rpm: float) -> list[float]: ...
    def mesh_period_s(self, speed_rpm: float) -> float: ...
    def check_steps(self, speed_rpm: float, steps_per_period: int) -> None: ...
    def mesh_tables(self) -> dict[str, npt.NDArray[np.float64]]:
        """``mesh_phase``, ``normal_stiffness_n_per_m``,
        ``transmission_error_um``, ``transmission_error_m``."""

def bifurcation(
    system: GearSystem,
    speeds_rpm: npt.NDArray[np.float64],
    direction: str = "up",
    transient_periods: int = 300,
    record_periods: int = 100,
    steps_per_period: int = 64,
    lyapunov_periods: int = 100,
    progress: Optional[Callable[[int, int], None]] = None,
    settings: Optional[dict[str, Any]] = None,
) -> dict:
    """Per-speed columns in sweep order plus the flat Poincare samples.
    ``settings``: classifier settings by name (max_transient_periods,
    max_period, period_rel_tol, converging_ratio, lyapunov_block_periods,
    lyapunov_max_periods, lyapunov_sigmas,
    lyapunov_threshold_per_mesh_period, zero_one_threshold,
    jump_rel_amplitude, jump_trend_factor, jump_window_speeds); speeds
    strictly ascending."""

def bifurcation_many(
    systems: Sequence[GearSystem],
    directions: Sequence[str],
    speeds_rpm: npt.NDArray[np.float64],
    transient_periods: int = 300,
    record_periods: int = 100,
    steps_per_period: int = 64,
    lyapunov_periods: int = 100,
    progress: Optional[Callable[[int, int], None]] = None,
    settings: Optional[dict[str, Any]] = None,
) -> list[dict]: ...
def regime_map(
    system: GearSystem,
    torques_nm: Sequence[float],
    te_scales: Sequence[float],
    speeds_rpm: npt.NDArray[np.float64],
    transient_periods: int = 300,
    record_periods: int = 100,
    steps_per_period: int = 64,
    lyapunov_periods: int = 100,
    progress: Optional[Callable[[int, int], None]] = None,
    settings: Optional[dict[str, Any]] = None,
) -> dict: ...
def largest_lyapunov_reference(
    name: str,
    time: Optional[float] = None,
    step: Optional[float] = None,
    transient_time: Optional[float] = None,
    method: str = "benettin",
) -> float: ...
def largest_lyapunov_gear(
    system: GearSystem,
    speed_rpm: float,
    periods: int = 200,
    transient_periods: int = 300,
    steps_per_period: int = 64,
    block_periods: int = 10,
) -> dict[str, float]:
    """``lyapunov_per_s``, ``lyapunov_stderr_per_s``,
    ``lyapunov_per_mesh_period``, ``lyapunov_stderr_per_mesh_period``,
    ``blocks``, ``mesh_period_s``."""

def gear_bearing_schedule(
    bearing: Bearing,
    case: str,
    speeds_rpm: Sequence[float],
    axial_n: float,
    radial_n: float,
    bearings_per_shaft: int = 2,
) -> tuple[list[float], list[float], list[float]]: ...
def seed_gear_bearing_loads(torque_nm: float) -> tuple[float, float]: ...
def gear_defaults() -> dict[str, float]: ...
def rotor_campbell(
    row_material: str,
    preload_n: float,
    speeds_rpm: npt.NDArray[np.float64],
    modes: int = 8,
    effects: Optional[Sequence[str]] = None,
    offsets: Optional[dict[str, list[float]]] = None,
    progress: Optional[Callable[[int, int], None]] = None,
    rotor: Optional[dict[str, Any]] = None,
) -> dict[str, Any]: ...
def rotor_critical_speeds(
    row_material: str,
    preload_n: float,
    speeds_rpm: npt.NDArray[np.float64],
    modes: int = 8,
    harmonic: float = 1.0,
    effects: Optional[Sequence[str]] = None,
    offsets: Optional[dict[str, list[float]]] = None,
    rotor: Optional[dict[str, Any]] = None,
) -> dict[str, Any]: ...
def rotor_vibration(
    row_material: str,
    preload_n: float,
    speeds_rpm: npt.NDArray[np.float64],
    unbalance_grade: Optional[float] = None,
    unbalance_g_mm: Optional[float] = None,
    method: str = "frequency",
    duration_s: float = 0.1,
    effects: Optional[Sequence[str]] = None,
    offsets: Optional[dict[str, list[float]]] = None,
    progress: Optional[Callable[[int, int], None]] = None,
    rotor: Optional[dict[str, Any]] = None,
) -> dict[str, Any]: ...
def rotor_spectrum(
    row_material: str,
    preload_n: float,
    speed_rpm: float,
    duration_s: float = 0.2,
    nonlinear: bool = True,
    unbalance_grade: Optional[float] = None,
    unbalance_g_mm: Optional[float] = None,
    effects: Optional[Sequence[str]] = None,
    offsets: Optional[dict[str, list[float]]] = None,
    rotor: Optional[dict[str, Any]] = None,
) -> dict[str, Any]: ...
def rotor_default_effects() -> list[str]: ...

@final  # a native class: Python cannot subclass it
class Spindle:
    def __reduce__(self) -> tuple[Callable[[dict[str, Any]], Any], tuple[dict[str, Any]]]:
        """Pickle support: ``(_restore, ({format, version, kind, data},))``."""
    @staticmethod
    def preset(name: str) -> Spindle: ...
    @staticmethod
    def preset_names() -> list[str]: ...
    @staticmethod
    def from_config(
        config_json: str,
        name: str,
        front_bearing: Bearing | None = None,
        rear_bearing: Bearing | None = None,
        lubricant: str | None = None,
        heat: dict[str, Any] | None = None,
    ) -> Spindle: ...
    def config_json(self) -> str: ...
    def with_options(
        self,
        preload_n: float | None = None,
        preload_kind: str | None = None,
        spring_rate_n_per_um: float | None = None,
        radial_load_n: float | None = None,
        effects: list[str] | None = None,
        spin_friction: float | None = None,
        heat: dict[str, Any] | None = None,
    ) -> Spindle: ...
    @property
    def name(self) -> str: ...
    @property
    def preload_n(self) -> float: ...
    @property
    def preload_kind(self) -> str: ...
    @property
    def spring_rate_n_per_um(self) -> float | None: ...
    @property
    def radial_load_n(self) -> float: ...
    @property
    def node_names(self) -> list[str]: ...
    @property
    def effects(self) -> list[str]: ...
    def assumptions(self) -> dict[str, Any]: ...
    def steady_state(self, speed_rpm: float) -> dict[str, Any]: ...
    def convection_coefficients(
        self,
        speeds_rpm: Sequence[float],
        temperature_difference_k: float = 10.0,
        temperatures_c: Sequence[Sequence[float]] | None = None,
    ) -> tuple[list[str], npt.NDArray[np.float64]]: ...
    def isothermal(self, speed_rpm: float) -> tuple[dict[str, Any], dict[str, Any]]: ...
    def transient(
        self,
        speed_rpm: float,
        duration_s: float,
        dt_s: float = 5.0,
        record_every: int = 1,
        initial_c: float | None = None,
        mechanics_update_k: float = 0.05,
        progress: Callable[[int, int], Any] | None = None,
    ) -> dict[str, Any]: ...
    def grid(
        self,
        speeds_rpm: list[float],
        preloads_n: list[float],
        radial_loads_n: list[float],
        progress: Callable[[int, int], Any] | None = None,
    ) -> dict[str, list[float]]: ...
    def compensation(
        self,
        speeds_rpm: list[float],
        spring_rate_n_per_um: float,
        progress: Callable[[int, int], Any] | None = None,
    ) -> dict[str, list[float]]: ...

# ``settings`` of the three coupled-bearing calls below: a dict with every
# keyword of ``thermobear.thermal_state`` except ``effects`` (lubricant,
# lubrication_factor_f0, spin_friction, oil_air_temperature_c,
# ambient_temperature_c, housing_material, raceway_control,
# misalignment_rad, extra_heat_w, housing_conductance_scale,
# churning_oil_fraction, heat_model, lubrication, skf_series,
# sliding_friction_ehl, replenishment_krs, seal_moment_n_m, and
# ``oil_supply``: a dict with every key of
# ``thermobear.thermal.oil_supply.SUPPLY_OPTIONS``, None where not given), as
# ``thermobear.thermal.state._model_kwargs`` builds it. Every heat result
# carries the heat split rolling_heat_w, sliding_heat_w, spin_heat_w,
# drag_heat_w, ring_cage_churning_heat_w, seal_heat_w, extra_heat_w (they sum
# to the total) and cavity_oil_fraction.
def thermal_state(
    bearing: Bearing,
    speed_rpm: float,
    axial_n: float,
    radial_n: float,
    effects: Optional[Sequence[str]],
    settings: dict[str, Any],
) -> dict[str, Any]: ...
def isothermal_heat(
    bearing: Bearing,
    speed_rpm: float,
    axial_n: float,
    radial_n: float,
    oil_temperature_c: float,
    effects: Optional[Sequence[str]],
    settings: dict[str, Any],
) -> dict[str, Any]:
    """Heat rows of [`thermal_state`][thermobear.thermal_state] (no nodes, boundaries or
    deformations) with the oil held at ``oil_temperature_c``, on the
    isothermal bearing state (``solution``)."""

def thermal_stiffness_curve(
    bearing: Bearing,
    speeds_rpm: npt.NDArray[np.float64],
    axial_n: float,
    radial_n: float,
    effects: Optional[Sequence[str]],
    settings: dict[str, Any],
    progress: Optional[Callable[[int, int], None]] = None,
) -> dict[str, npt.NDArray[np.float64]]: ...
def thermal_state_many(
    bearing: Bearing,
    speed_rpm: npt.NDArray[np.float64],
    axial_n: npt.NDArray[np.float64],
    radial_n: npt.NDArray[np.float64],
    effects: Optional[Sequence[str]],
    settings: dict[str, Any],
    threads: Optional[int] = None,
    progress: Optional[Callable[[int, int], None]] = None,
) -> dict[str, Any]:
    """Columns of ``solve_many`` plus temperatures, heat and thermal
    offsets per point; ``ok``, ``error_kind``, ``error``."""

def lubrication_defaults(lubrication: str, bearing_type: str) -> dict[str, Any]: ...
def skf_sliding_friction_ehl(lubricant: str) -> float: ...
def seed_a_network_links(
    bearing: Bearing,
    speed_rpm: float,
    lubricant: str = ...,  # "e-drive ATF"
    oil_air_temperature_c: float = 28.0,
    ambient_temperature_c: float = 26.0,
    housing_material: Optional[Material] = None,
) -> dict[str, Any]: ...
def seed_a_steady_temperatures(
    bearing: Bearing,
    speed_rpm: float,
    inner_ring_w: float,
    balls_w: float,
    outer_ring_w: float,
    lubricant: str = ...,  # "e-drive ATF"
    oil_air_temperature_c: float = 28.0,
    ambient_temperature_c: float = 26.0,
    housing_material: Optional[Material] = None,
) -> dict[str, Any]: ...
