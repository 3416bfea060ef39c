"""A helical gear pair: geometry, ISO 6336 and time-varying mesh stiffness,
the default parameters."""

from __future__ import annotations

from typing import TYPE_CHECKING, Any

import numpy as np
from numpy.typing import ArrayLike

from .. import _native
from .. import _validate as val
from .._deprecation import renamed_kwargs
from .._types import MeshModel

if TYPE_CHECKING:
    import polars

#: Speeds at which the "speed" and "thermal" bearing stiffness is solved
#: (linear interpolation in between, constant beyond the ends) [rpm].
STIFFNESS_SPEEDS_RPM = np.arange(1000.0, 20000.0 + 1.0, 250.0)

#: The most points of a mesh-stiffness curve (a million per mesh period is
#: already far finer than any tooth profile).
MAX_MESH_POINTS = 1_000_000


def _config_error(msg: str) -> Exception:
    from ..errors import ConfigError

    return ConfigError(msg)


class GearPair:
    """A helical gear pair. ``GearPair.preset("seed-electric-drive")`` is seed
    A's first pair (Table 3, typos corrected); ``from_table`` takes a
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
    @renamed_kwargs(input_torque_nm="input_torque_n_m")
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
        mass_kg: ArrayLike,
        polar_inertia_t_mm2: ArrayLike,
        input_torque_n_m: float,
        profile_shift_coeff: ArrayLike = (0.0, 0.0),
        addendum_coeff: float = 1.0,
        dedendum_coeff: float = 1.25,
    ) -> "GearPair":
        # the angles in the model's own ranges, named in degrees
        helix = val.real("helix_angle_deg", helix_angle_deg)
        if not 0.0 <= helix < 45.0:
            raise val.fail("helix_angle_deg", helix, "a finite number in [0, 45)")
        return cls(
            _native.GearPair.from_table(
                val.whole("pinion_teeth", pinion_teeth, 1),
                val.whole("gear_teeth", gear_teeth, 1),
                val.real("normal_module_mm", normal_module_mm, 0.0, open_lo=True),
                val.real(
                    "normal_pressure_angle_deg", normal_pressure_angle_deg, 0.0, 45.0, open_lo=True
                ),
                helix,
                val.real("face_width_mm", face_width_mm, 0.0, open_lo=True),
                val.real("youngs_modulus_mpa", youngs_modulus_mpa, 0.0, open_lo=True),
                val.real("poisson_ratio", poisson_ratio, -1.0, 0.5),
                val.real("density_t_per_mm3", density_t_per_mm3, 0.0, open_lo=True),
                val.pair("mass_kg", mass_kg),  # signs: the native check names the gear
                val.pair("polar_inertia_t_mm2", polar_inertia_t_mm2),
                val.real("input_torque_n_m", input_torque_n_m),
                val.pair("profile_shift_coeff", profile_shift_coeff),
                val.real("addendum_coeff", addendum_coeff, 0.0),
                val.real("dedendum_coeff", dedendum_coeff, 0.0),
            )
        )

    @property
    def geometry(self) -> dict[str, float]:
        """Derived geometry (mm, deg), the contact ratios and the input
        torque ``input_torque_n_m`` [N m]."""
        g = dict(self._g.geometry())
        if "input_torque_nm" in g:
            g["input_torque_n_m"] = g.pop("input_torque_nm")
        return g

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
        self, points: int = 64, model: MeshModel = "potential-energy"
    ) -> polars.DataFrame:
        """k_m over one mesh period: ``mesh_phase``,
        ``transverse_stiffness_n_per_m`` (along the transverse line of action,
        comparable with ISO's c_gamma b) and ``normal_stiffness_n_per_m`` (for
        the normal deflection of A-45, what the dynamics use)."""
        import polars as pl

        n = val.whole("points", points, 2, MAX_MESH_POINTS)
        cols = self._g.mesh_stiffness(n, val.text("model", model))
        return pl.DataFrame({k: np.asarray(v) for k, v in cols.items()})

    def tooth_pair_stiffness(
        self, points: int = 256, model: MeshModel = "potential-energy"
    ) -> polars.DataFrame:
        """One tooth pair's stiffness over its whole engagement, as its
        contact enters the path of contact (approach), crosses the pitch point
        and leaves (recess): ``mesh_cycles`` (roll from entering, in mesh
        periods; the engagement lasts eps_alpha + eps_beta of them),
        ``transverse_stiffness_n_per_m`` and ``normal_stiffness_n_per_m``.
        Shifted by whole mesh periods and summed over the pairs in mesh it
        gives [`mesh_stiffness`][thermobear.GearPair.mesh_stiffness]."""
        import polars as pl

        cols = self._g.tooth_pair_stiffness(int(points), model)
        return pl.DataFrame({k: np.asarray(v) for k, v in cols.items()})

    @property
    def typo_warnings(self) -> polars.DataFrame:
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
        f = float(self._g.mesh_frequency_hz(val.real("speed_rpm", speed_rpm, 0.0)))
        return val.finite_result(f, {"speed_rpm": speed_rpm})

    def __repr__(self) -> str:
        return repr(self._g)


def gear_defaults() -> polars.DataFrame:
    """The values seed A does not give, with the defaults used and why."""
    import polars as pl

    d = _native.gear_defaults()
    rows = [
        ("half_backlash_um", d["half_backlash_um"], "half backlash b (not in A)"),
        ("backlash_total_um", 2.0 * d["half_backlash_um"], "total clearance 2b (not in A)"),
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
