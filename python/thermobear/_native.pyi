"""Type stubs of the Rust extension module ``thermobear._native``.

SI inside; every argument name carries its unit. Arrays are float64 numpy.
"""

from typing import Any, Callable, Optional, Sequence

import numpy as np
import numpy.typing as npt

__version__: str

class ThermobearError(Exception): ...
class ConfigError(ThermobearError): ...
class ConvergenceError(ThermobearError): ...
class ThermalRunawayError(ConvergenceError): ...
class DataError(ThermobearError): ...

class Material:
    def __init__(
        self,
        name: str,
        youngs_modulus_gpa: float,
        poisson_ratio: float,
        density_kg_m3: float,
        thermal_expansion_per_k: float,
        conductivity_w_mk: float,
        specific_heat_j_kgk: float,
    ) -> None: ...
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

class Bearing:
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
    def from_toml(text: str) -> Bearing: ...
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
        moment_nmm: float,
        speed_rpm: float,
        effects: Optional[Sequence[str]] = None,
        raceway_control: str = "outer",
        misalignment_rad: Optional[float] = 0.0,
    ) -> dict: ...

def effects() -> list[tuple[str, str]]: ...
def check_config(text: str) -> list[str]: ...
def stiffness_curve(
    bearing: Bearing,
    speeds_rpm: npt.NDArray[np.float64],
    axial_n: float,
    radial_n: float,
    moment_nmm: float,
    effects: Optional[Sequence[str]] = None,
    raceway_control: str = "outer",
    misalignment_rad: Optional[float] = 0.0,
    progress: Optional[Callable[[int, int], None]] = None,
) -> dict[str, npt.NDArray[np.float64]]: ...

class Spindle:
    @staticmethod
    def preset(name: str) -> Spindle: ...
    @staticmethod
    def preset_names() -> list[str]: ...
    def with_options(
        self,
        preload_n: float | None = None,
        preload_kind: str | None = None,
        spring_rate_n_per_um: float | None = None,
        radial_load_n: float | None = None,
        effects: list[str] | None = None,
        spin_friction: float | None = None,
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
    def isothermal(self, speed_rpm: float) -> tuple[dict[str, Any], dict[str, Any]]: ...
    def transient(
        self,
        speed_rpm: float,
        duration_s: float,
        dt_s: float = 5.0,
        record_every: int = 1,
        initial_c: float | None = None,
        mechanics_update_k: float = 0.05,
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
