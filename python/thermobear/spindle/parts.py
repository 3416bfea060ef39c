"""The parts of a spindle description: one small dataclass per part, the
same keys as the tables of a ``[spindle]`` description file (see
[`Spindle.from_toml`][thermobear.Spindle.from_toml]).

Every default is the value of the ``seed-ceramic-spindle`` preset; a field
left at ``None`` takes the preset's (or, where said, the lubrication
method's) value. Each field is checked when the part is built: a bad value
is a [`ConfigError`][thermobear.ConfigError] that names it.
"""

from __future__ import annotations

from dataclasses import dataclass, fields
from typing import Any, Optional

from .. import _validate as val
from ..errors import ConfigError

#: The pair arrangements of rolling-bearing practice; the model has DB only.
ARRANGEMENTS = ("DB", "DF", "DT")


def _check_reals(part: Any, rules: dict[str, tuple[float, float, bool]]) -> None:
    """Check the real fields of ``part`` named in ``rules`` (lo, hi,
    open_lo); None passes for a field whose default is None."""
    for name, (lo, hi, open_lo) in rules.items():
        value = getattr(part, name)
        if value is None and _optional(part, name):
            continue
        object.__setattr__(part, name, val.real(name, value, lo, hi, open_lo=open_lo))


def _optional(part: Any, name: str) -> bool:
    """Whether the field ``name`` of ``part`` takes None."""
    return any(f.name == name and "Optional" in str(f.type) for f in fields(part))


POS = (0.0, val.INF, True)  # > 0
NONNEG = (0.0, val.INF, False)  # >= 0
ANY = (-val.INF, val.INF, False)


@dataclass(frozen=True)
class ShaftSegment:
    """One cylindrical step of the shaft: ``length_mm`` long, of outer
    diameter ``outer_diameter_mm`` and bore ``bore_mm`` (0: solid)."""

    length_mm: float
    outer_diameter_mm: float
    bore_mm: float = 0.0

    def __post_init__(self) -> None:
        _check_reals(self, {"length_mm": POS, "outer_diameter_mm": POS,
                            "bore_mm": NONNEG})  # fmt: skip
        if self.bore_mm >= self.outer_diameter_mm:
            raise val.fail("bore_mm", self.bore_mm,
                           f"below the outer diameter ({self.outer_diameter_mm:g} mm)")  # fmt: skip


@dataclass(frozen=True)
class Shaft:
    """The shaft as the model has it: the rotor centre ``front_span_mm``
    behind the front pair centre and ``rear_span_mm`` ahead of the rear pair
    centre, the nose (tool side) ``nose_length_mm`` in front of the front
    pair; its journals have the bearings' bores. ``segments``: the shaft's
    own steps from the nose, in order
    ([`ShaftSegment`][thermobear.ShaftSegment]s; empty: a
    layout derived from the bores and spans); the rotor model builds its
    beam elements from them, each bearing row seated on a step of its bore
    (the thermal network lumps the shaft either way)."""

    front_span_mm: float = 120.0
    rear_span_mm: float = 120.0
    nose_length_mm: float = 60.0
    segments: tuple[ShaftSegment, ...] = ()

    def __post_init__(self) -> None:
        _check_reals(self, {"front_span_mm": POS, "rear_span_mm": POS, "nose_length_mm": NONNEG})
        segs = self.segments
        if isinstance(segs, (str, bytes)) or not hasattr(segs, "__iter__"):
            raise val.fail("segments", segs, "a sequence of thermobear.spindle.ShaftSegment")
        out = []
        for i, seg in enumerate(segs):
            if not isinstance(seg, ShaftSegment):
                raise val.fail(f"segments[{i}]", seg, "a thermobear.spindle.ShaftSegment")
            out.append(seg)
        object.__setattr__(self, "segments", tuple(out))


@dataclass(frozen=True)
class BearingSet:
    """The bearings at one end: ``bearing`` a preset name
    ([`Bearing.preset`][thermobear.Bearing.preset]) or a
    [`Bearing`][thermobear.Bearing] (angular-contact), ``rows`` of them in
    ``arrangement``. The model has matched pairs back to back: ``"DB"``,
    two rows, adjacent (spacing = bearing width). Face to face (``"DF"``),
    tandem (``"DT"``) and sets of other row counts are refused as not
    modelled."""

    bearing: Any
    arrangement: str = "DB"
    rows: int = 2

    def __post_init__(self) -> None:
        from ..bearing import Bearing

        b = self.bearing
        if isinstance(b, str):
            b = Bearing.preset(b)
        elif not isinstance(b, Bearing):
            raise val.fail("bearing", b, "a bearing preset name or a thermobear.Bearing")
        if b.bearing_type != "angular-contact":
            raise ConfigError(
                f"invalid bearing = {b.name!r}: a spindle set of {b.bearing_type} bearings is "
                "not modelled; the spindle model has angular-contact pairs"
            )
        object.__setattr__(self, "bearing", b)
        arrangement = val.text("arrangement", self.arrangement).upper()
        if arrangement not in ARRANGEMENTS:
            raise val.fail("arrangement", self.arrangement, "DB" + val.did_you_mean(
                arrangement, ARRANGEMENTS))  # fmt: skip
        if arrangement != "DB":
            raise ConfigError(
                f"invalid arrangement = {self.arrangement}: not modelled; the spindle model has "
                "back-to-back (DB) pairs only"
            )
        object.__setattr__(self, "arrangement", arrangement)
        rows = val.whole("rows", self.rows, 1)
        if rows != 2:
            raise ConfigError(
                f"invalid rows = {rows}: not modelled; the spindle model has two rows per set "
                "(a matched pair), no single rows or tandem sets"
            )
        object.__setattr__(self, "rows", rows)


@dataclass(frozen=True)
class Preload:
    """Preload per bearing, the same for both sets: ``"spring"`` (a spring
    pack of ``spring_rate_n_per_um``; None: seed B's 6.45 N / 17.92 um) or
    ``"rigid"`` (fixed positions; no rate)."""

    kind: str = "spring"
    preload_n: float = 400.0
    spring_rate_n_per_um: Optional[float] = None

    def __post_init__(self) -> None:
        object.__setattr__(self, "kind", val.choice("kind", self.kind, ("spring", "rigid")))
        _check_reals(self, {"preload_n": POS, "spring_rate_n_per_um": NONNEG})
        if self.kind == "rigid" and self.spring_rate_n_per_um is not None:
            raise ConfigError(
                f"invalid spring_rate_n_per_um = {self.spring_rate_n_per_um:g}: a rigid preload "
                'has no spring; give kind = "spring" or leave the rate out'
            )


@dataclass(frozen=True)
class Housing:
    """The steel housing: the sleeve around the stator (outside diameter
    ``sleeve_outer_diameter_mm``, shrink-fit contact conductance
    ``stator_contact_w_per_m2_k`` to the stator), the bearing-seat housings
    at each end (``outer_ring_contact_w_per_m2_k``: the thermal contact
    conductance of the outer rings' seats, about 10^3-10^4 for a loose fit
    with an oil film; None: perfect contact), the ambient air around it and
    the temperature at which the spindle was assembled (zero thermal
    offsets; None: the ambient)."""

    sleeve_outer_diameter_mm: float = 180.0
    front_housing_length_mm: float = 60.0
    rear_housing_length_mm: float = 50.0
    stator_contact_w_per_m2_k: float = 1000.0
    ambient_temperature_c: float = 25.0
    assembly_temperature_c: Optional[float] = None
    outer_ring_contact_w_per_m2_k: Optional[float] = None

    def __post_init__(self) -> None:
        _check_reals(self, {
            "sleeve_outer_diameter_mm": POS, "front_housing_length_mm": POS,
            "rear_housing_length_mm": POS, "stator_contact_w_per_m2_k": POS,
            "ambient_temperature_c": ANY, "assembly_temperature_c": ANY,
            "outer_ring_contact_w_per_m2_k": POS,
        })  # fmt: skip


@dataclass(frozen=True)
class MagneticPull:
    """The static unbalanced magnetic pull of the rotor core on the shaft
    (given: the pull acts). None takes the seed rotor's data: core centre
    midway between the pairs, core radius 34.7 mm, length 120 mm, air gap
    0.3 mm, 0.55 T RMS, static eccentricity 10 % of the gap."""

    core_from_front_pair_mm: Optional[float] = None
    core_radius_mm: Optional[float] = None
    core_length_mm: Optional[float] = None
    air_gap_mm: Optional[float] = None
    flux_density_t: Optional[float] = None
    static_eccentricity_um: Optional[float] = None
    reduction_factor: Optional[float] = None

    def __post_init__(self) -> None:
        _check_reals(self, {
            "core_from_front_pair_mm": ANY, "core_radius_mm": POS, "core_length_mm": POS,
            "air_gap_mm": POS, "flux_density_t": NONNEG, "static_eccentricity_um": ANY,
            "reduction_factor": (0.0, 1.0, False),
        })  # fmt: skip


@dataclass(frozen=True)
class Motor:
    """The built-in motor, centred ``front_span_mm`` behind the front pair
    (see [`Shaft`][thermobear.Shaft]): rotor and stator core, air gap, and
    its losses at ``loss_reference_speed_rpm`` (copper constant, iron
    scaling with speed^1.5, windage with speed^2). ``magnetic_pull``: the
    pull on the shaft (None: none)."""

    rotor_diameter_mm: float = 79.4
    rotor_length_mm: float = 150.0
    air_gap_mm: float = 0.3
    stator_outer_diameter_mm: float = 140.0
    stator_copper_loss_w: float = 250.0
    stator_iron_loss_w: float = 200.0
    rotor_copper_loss_w: float = 100.0
    windage_loss_w: float = 50.0
    loss_reference_speed_rpm: float = 12000.0
    magnetic_pull: Optional[MagneticPull] = None

    def __post_init__(self) -> None:
        _check_reals(self, {
            "rotor_diameter_mm": POS, "rotor_length_mm": POS, "air_gap_mm": POS,
            "stator_outer_diameter_mm": POS, "stator_copper_loss_w": NONNEG,
            "stator_iron_loss_w": NONNEG, "rotor_copper_loss_w": NONNEG,
            "windage_loss_w": NONNEG, "loss_reference_speed_rpm": POS,
        })  # fmt: skip
        pull = self.magnetic_pull
        if pull is not None and not isinstance(pull, MagneticPull):
            raise val.fail("magnetic_pull", pull, "None or a thermobear.MagneticPull")


@dataclass(frozen=True)
class Cooling:
    """The water jacket around the stator sleeve: flow, inlet temperature
    (a boundary), a rectangular channel and the wetted fraction of the
    stator-sleeve interface."""

    jacket_flow_l_per_min: float = 10.0
    water_temperature_c: float = 18.0
    channel_width_mm: float = 10.0
    channel_height_mm: float = 5.0
    jacket_wetted_fraction: float = 0.5

    def __post_init__(self) -> None:
        _check_reals(self, {
            "jacket_flow_l_per_min": POS, "water_temperature_c": ANY, "channel_width_mm": POS,
            "channel_height_mm": POS, "jacket_wetted_fraction": (0.0, 1.0, True),
        })  # fmt: skip


#: Oil-supply keys of [`Lubrication`] (as ``Spindle.with_options``).
SUPPLY_KEYS = (
    "oil_flow_cm3_per_min",
    "jet_count",
    "jet_velocity_m_per_s",
    "oil_volume_cm3_per_h",
    "air_flow_l_per_min",
    "oil_level_mm",
    "grease_fill_fraction",
    "oil_flow_scale",
    "cavity_fraction_speed_exponent",
)


@dataclass(frozen=True)
class Lubrication:
    """Lubrication of the bearings and the heat model: ``method``
    ("oil-air", "grease", "oil-mist", "jet", "oil-bath"), ``lubricant``
    (a preset oil: "ISO VG 32", "ISO VG 68", "e-drive ATF"), the Palmgren
    factor and the ball-drag oil fraction (the preset's 1.0 and 0; None:
    the method's defaults; with an oil supply the fraction follows the
    supply: leave it at 0 or None), the
    oil-air supply temperature (a boundary), ``heat_model`` ("palmgren",
    "skf"), the spin friction coefficient, the factor on Palmgren's
    load-friction factor f1 (``load_friction_scale``, 1: Harris'
    constants), the SKF-model settings and the oil supply (as
    [`Spindle.with_options`][thermobear.Spindle.with_options]; None: none)."""

    method: str = "oil-air"
    lubricant: str = "ISO VG 32"
    lubrication_factor_f0: Optional[float] = 1.0
    churning_oil_fraction: Optional[float] = 0.0
    oil_air_temperature_c: float = 25.0
    heat_model: str = "palmgren"
    spin_friction_coefficient: float = 0.05
    load_friction_scale: float = 1.0
    sliding_friction_ehl: Optional[float] = None
    replenishment_krs: Optional[float] = None
    seal_moment_n_m: float = 0.0
    oil_flow_cm3_per_min: Optional[float] = None
    jet_count: Optional[int] = None
    jet_velocity_m_per_s: Optional[float] = None
    oil_volume_cm3_per_h: Optional[float] = None
    air_flow_l_per_min: Optional[float] = None
    oil_level_mm: Optional[float] = None
    grease_fill_fraction: Optional[float] = None
    oil_flow_scale: Optional[float] = None
    cavity_fraction_speed_exponent: Optional[float] = None

    def __post_init__(self) -> None:
        for name in ("method", "lubricant", "heat_model"):
            val.text(name, getattr(self, name))
        object.__setattr__(self, "heat_model", val.choice(
            "heat_model", self.heat_model, ("palmgren", "skf")))  # fmt: skip
        _check_reals(self, {
            "lubrication_factor_f0": NONNEG, "churning_oil_fraction": (0.0, 1.0, False),
            "oil_air_temperature_c": ANY, "spin_friction_coefficient": NONNEG,
            "load_friction_scale": NONNEG, "sliding_friction_ehl": NONNEG,
            "replenishment_krs": NONNEG,
            "seal_moment_n_m": NONNEG, "oil_flow_cm3_per_min": NONNEG,
            "jet_velocity_m_per_s": NONNEG, "oil_volume_cm3_per_h": NONNEG,
            "air_flow_l_per_min": NONNEG, "oil_level_mm": NONNEG,
            "grease_fill_fraction": (0.0, 1.0, False), "oil_flow_scale": NONNEG,
            "cavity_fraction_speed_exponent": ANY,
        })  # fmt: skip
        if self.jet_count is not None:
            object.__setattr__(self, "jet_count", val.whole("jet_count", self.jet_count, 1))


@dataclass(frozen=True)
class ToolLoad:
    """The working (tool-side) radial load at the spindle nose, ``nose_length_mm``
    in front of the front pair; it is shared by the pairs by the lever rule."""

    radial_load_n: float = 0.0

    def __post_init__(self) -> None:
        _check_reals(self, {"radial_load_n": ANY})


#: Part of each table of a ``[spindle]`` description.
PART_TYPES: dict[str, type] = {
    "shaft": Shaft,
    "preload": Preload,
    "housing": Housing,
    "motor": Motor,
    "cooling": Cooling,
    "lubrication": Lubrication,
    "tool": ToolLoad,
}
