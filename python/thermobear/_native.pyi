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
def thermal_state(
    bearing: Bearing,
    speed_rpm: float,
    axial_n: float,
    radial_n: float,
    effects: Optional[Sequence[str]] = None,
    lubricant: str = "e-drive ATF",
    lubrication_factor_f0: float = 1.0,
    spin_friction: float = 0.06,
    oil_air_temperature_c: float = 28.0,
    ambient_temperature_c: float = 26.0,
    housing_material: Optional[Material] = None,
    raceway_control: str = "outer",
    misalignment_rad: Optional[float] = 0.0,
) -> dict[str, Any]: ...
def thermal_stiffness_curve(
    bearing: Bearing,
    speeds_rpm: npt.NDArray[np.float64],
    axial_n: float,
    radial_n: float,
    effects: Optional[Sequence[str]] = None,
    lubricant: str = "e-drive ATF",
    lubrication_factor_f0: float = 1.0,
    spin_friction: float = 0.06,
    oil_air_temperature_c: float = 28.0,
    ambient_temperature_c: float = 26.0,
    housing_material: Optional[Material] = None,
    raceway_control: str = "outer",
    misalignment_rad: Optional[float] = 0.0,
    progress: Optional[Callable[[int, int], None]] = None,
) -> dict[str, npt.NDArray[np.float64]]: ...
def seed_a_network_links(
    bearing: Bearing,
    speed_rpm: float,
    lubricant: str = "e-drive ATF",
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
    lubricant: str = "e-drive ATF",
    oil_air_temperature_c: float = 28.0,
    ambient_temperature_c: float = 26.0,
    housing_material: Optional[Material] = None,
) -> dict[str, Any]: ...
