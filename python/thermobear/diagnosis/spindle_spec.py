"""The discrepancy workflow of [`thermobear.diagnosis`][thermobear.diagnosis] on a motorized
spindle (seed B): [`SpindleModelSpec`][thermobear.SpindleModelSpec] is the spindle's model
in the protocol [`thermobear.diagnose`][thermobear.diagnose] uses (``predict(conditions)``
over every supported quantity, ``with_setting(effects, **options)`` sharing
one cache, ``options``, ``effects``), with its own quantity and candidate
registry; [`thermobear.diagnose`][thermobear.diagnose], given this spec or a
[`Spindle`][thermobear.Spindle], runs the unchanged screening, acceptance and
gap machinery of [`thermobear.diagnosis`][thermobear.diagnosis] with that registry.

Quantities (``SPINDLE_QUANTITIES``): outer-ring (and other node)
temperatures of the front and rear bearings from
[`thermobear.Spindle.thermal_state`][thermobear.Spindle.thermal_state], the
axial thermal growth, and the shaft-end vibration velocity RMS from
[`thermobear.vibration`][thermobear.vibration], coupled
(thermal raceway offsets, A-38) exactly when a thermal-expansion effect is
on. Conditions: ``speed_rpm`` and ``preload_n`` (stored as ``axial_n`` by
[`thermobear.load_measurements`][thermobear.load_measurements]; a spindle's
axial load is its preload).

Candidates: every effect the baseline leaves off as a switch, plus
``thermal_displacement`` (the five thermal-expansion effects together:
seed B's "model with thermal displacement"), the spin friction coefficient,
the preload kind (rigid <-> constant-force spring), the spring rate when the
preload is a spring, the rotor's residual unbalance grade (G0.4-G6.3), a
preload scale (0.7-1.3, and one per preload level when the data have
several), the shaft runout a non-contact vibration probe sees (0-50 um),
the other heat model, for a spindle whose oil supply states a flow the
supply's flow scale and cavity-fraction speed exponent, and per measured
quantity a sensor offset and (for absolute-sigma quantities) a sensor gain.
"""

from __future__ import annotations

from importlib import resources
from typing import TYPE_CHECKING, Any, Optional, Sequence, Union

import numpy as np

from .._validate import did_you_mean
from ..errors import ConfigError, ThermobearError
from ..spindle.description import PULL_EFFECT
from ..spindle.spindle import MAX_EXTRA_HEAT_W, Spindle, _state_row
from ..thermal.heat_law import HEAT_LAW_OPTIONS, pop_heat_law
from ..thermal.oil_supply import SUPPLY_OPTIONS
from .candidates import (
    Candidate,
    heat_model_candidates,
    load_level_candidates,
    sensor_gain_candidates,
    sensor_offset_candidates,
    supply_candidates,
)
from .candidates import candidates as _candidate_table
from .measurements import PRELOAD_REGISTRIES, load_measurements
from .protocol import ModelSpec, register_kind
from .registry import supply_given
from .relative import with_changes
from .result import Diagnosis
from .screening import _GRID
from .workflow import diagnose

if TYPE_CHECKING:
    import polars

__all__ = [
    "SPINDLE_QUANTITIES",
    "THERMAL_DISPLACEMENT_EFFECTS",
    "SpindleModelSpec",
    "diagnose_spindle",
    "load_spindle_measurements",
    "seed_b_measurements",
    "spindle_candidates",
]

#: The thermal-expansion effects whose raceway offsets (A-38) make up seed
#: B's "thermal displacement"; switching all of them off is the paper's
#: uncoupled model.
THERMAL_DISPLACEMENT_EFFECTS: tuple[str, ...] = (
    "thermal_expansion_balls",
    "thermal_expansion_housing",
    "thermal_expansion_inner_ring",
    "thermal_expansion_outer_ring",
    "thermal_expansion_shaft",
)
_GROUP = "thermal_displacement"

_T_RANGE = (-60.0, 250.0)
#: name: (model column, scale, plausible range, typical sigma, relative?) --
#: the layout of ``thermobear.diagnosis.QUANTITIES``. Thermocouples
#: +-0.5 K; laser-Doppler vibrometer velocity 5 % (the Polytec OFV-505 of
#: seed B's test; 5 % is our assumption for the whole chain, the paper gives
#: none); axial growth 0.5 um (capacitive probe, assumed); operating
#: preload of the front pair 2 % (a load washer or strain-gauged spacer in
#: the preload path, assumed).
SPINDLE_QUANTITIES: dict[str, tuple[str, float, tuple[float, float], float, bool]] = {
    "front_outer_ring_temperature_c": ("front_outer_ring_temperature_c", 1.0, _T_RANGE, 0.5, False),
    "rear_outer_ring_temperature_c": ("rear_outer_ring_temperature_c", 1.0, _T_RANGE, 0.5, False),
    "front_inner_ring_temperature_c": ("front_inner_ring_temperature_c", 1.0, _T_RANGE, 0.5, False),
    "rear_inner_ring_temperature_c": ("rear_inner_ring_temperature_c", 1.0, _T_RANGE, 0.5, False),
    "front_housing_temperature_c": ("front_housing_temperature_c", 1.0, _T_RANGE, 0.5, False),
    "rear_housing_temperature_c": ("rear_housing_temperature_c", 1.0, _T_RANGE, 0.5, False),
    "axial_growth_um": ("axial_growth_um", 1.0, (-1e4, 1e4), 0.5, False),
    "operating_preload_n": ("operating_preload_n", 1.0, (0.0, 1e5), 0.02, True),
    "velocity_rms_mm_s": ("velocity_rms_mm_s", 1.0, (0.0, 1e3), 0.05, True),
    # What a simulation study reports beside the rig's sensors (seed B
    # Figs. 5-20); the sigmas are assumed, as above: a thermocouple in a
    # ball pocket 0.5 K, a displacement probe 0.2 um (its thermal part 0.5
    # um: the difference of two expansions), a contact load 2 %, a contact
    # angle 0.2 deg, a radial stiffness 5 %, the 1X line of a velocity
    # spectrum 5 %; the outer minus the inner contact load (the balls'
    # centrifugal force) 3 N, two loads of 2 % of about 100 N each; the
    # compensation preload 0.5 N (absolute: it is zero without a spring).
    "front_ball_temperature_c": ("front_ball_temperature_c", 1.0, _T_RANGE, 0.5, False),
    "thermal_radial_displacement_um": (
        "thermal_radial_displacement_um", 1.0, (-1e3, 1e3), 0.5, False,
    ),
    "radial_displacement_um": ("radial_displacement_um", 1.0, (0.0, 1e3), 0.2, False),
    "total_radial_displacement_um": (
        "total_radial_displacement_um", 1.0, (0.0, 1e3), 0.5, False,
    ),
    "inner_load_max_n": ("inner_load_max_n", 1.0, (0.0, 1e4), 0.02, True),
    "outer_load_max_n": ("outer_load_max_n", 1.0, (0.0, 1e4), 0.02, True),
    "outer_inner_load_difference_n": (
        "outer_inner_load_difference_n", 1.0, (-1e4, 1e4), 3.0, False,
    ),
    "inner_contact_angle_deg": ("inner_contact_angle_deg", 1.0, (0.0, 90.0), 0.2, False),
    "outer_contact_angle_deg": ("outer_contact_angle_deg", 1.0, (0.0, 90.0), 0.2, False),
    "k_xx_n_per_m": ("k_xx_n_per_m", 1.0, (0.0, 1e11), 0.05, True),
    "compensation_preload_n": ("compensation_preload_n", 1.0, (-1e4, 1e4), 0.5, False),
    "x1_mm_s": ("x1_mm_s", 1.0, (0.0, 1e3), 0.05, True),
    # probes zeroed at a reference speed: the change of axial_growth_um and
    # radial_displacement_um from there (thermobear.diagnosis.relative)
    "axial_growth_change_um": ("axial_growth_um", 1.0, (-1e4, 1e4), 0.5, False),
    "radial_displacement_change_um": ("radial_displacement_um", 1.0, (-1e3, 1e3), 0.2, False),
}  # fmt: skip
_VIB = "velocity_rms_mm_s"
#: The quantities of the rotor's forced response (computed on first access).
_ROTOR = (_VIB, "x1_mm_s")
#: The quantities computed only when asked for: the rotor's, and the total
#: radial displacement (it needs the uncoupled state beside the coupled one).
_LAZY = (*_ROTOR, "total_radial_displacement_um")
PRELOAD_REGISTRIES.append(SPINDLE_QUANTITIES)  # spindle data state a preload_n

#: Options of the spindle model and their bounds as candidates. Spin
#: friction coefficient 0-0.3 as in thermobear.diagnosis (boundary to dry
#: contact); spring rate 0.05-3 N/um brackets seed B's 0.36 N/um disc
#: springs by an order of magnitude each way (assumed range).
_SPIN_BOUNDS = (0.0, 0.3)
_SPRING_BOUNDS = (0.05, 3.0)
#: Residual unbalance grade of the rotor [mm/s]: ISO 21940-11 balance
#: quality grades from G0.4 (precision grinding spindles) to G6.3 (the
#: coarsest grade the standard's table suggests for machine-tool parts and
#: electric motors); a rotor outside this range is not a finished spindle.
_UNBALANCE_BOUNDS = (0.4, 6.3)
#: Shaft runout seen by a non-contact vibration probe [um]: 0-50 um (a
#: precision spindle nose runs within a few um; a tool-holder taper or a
#: probe track on an unground shaft section reaches tens of um -- ISO 10791-1
#: tolerances for spindle nose run-out are 3-10 um, 50 um is a generous
#: upper end for a measuring track that is not the nose).
RUNOUT_BOUNDS_UM = (0.0, 50.0)
#: Preload scale: the preload set by spring length or spacers is off by a
#: factor (same bounds as the bearing's load scales).
PRELOAD_SCALE_BOUNDS = (0.7, 1.3)
#: Inputs a study may not know, calibratable once declared: each is an
#: option that defaults to None (the spindle's own value, not a
#: candidate); given a number it is applied and becomes a candidate with
#: that value as its null. Bounds (assumed ranges, each stated here):
#:
#: * ``ball_diameter_scale`` 0.8-1.15 on the preset's balls (7009C: 8.73
#:   mm): 7.0-10.0 mm, the balls of the 15 mm ring section of a 45 x 75 mm
#:   bearing between the thinnest and the thickest rings a ground race
#:   keeps (0.45-0.65 of the section);
#: * ``span_scale`` 0.5-1.5 on the axial layout between the sets (the
#:   preset's 240 mm): 120-360 mm, a motor core of 75-225 mm between
#:   two pairs;
#: * ``motor_loss_scale`` 0.25-3 on the preset's 600 W at 12,000 rpm:
#:   150-1800 W, 1.5-18 % of the 10 kW the preset assumes;
#: * ``lubrication_factor_f0``: the bounds of the spindle's lubrication
#:   method (``thermobear.lubrication_defaults``: oil-air 0.85-3.4, half
#:   and twice Palmgren's table value);
#: * ``load_friction_scale`` 0.25-25 on Palmgren's load-friction factor
#:   f1 (Harris' z = 0.001 for angular-contact bearings): from a quarter of
#:   the table value to the load friction of an unlubricated contact
#:   (f1 P1 dm with f1 about 0.006 at the seed preloads);
#: * ``outer_ring_contact_w_per_m2_k`` 300-30,000 W/(m^2 K): the contact
#:   conductance of a loose outer-ring seat, from a dry clearance fit to
#:   an oil-filled tight one (Yovanovich's gap and contact conductances);
#: * ``radial_load_n`` 0-3000 N at the nose: from a free-running spindle
#:   to a heavy cut on a 45 mm front bearing (a fifth of its static rating);
#: * ``unbalance_g_mm`` 0-10,000 g mm: the whole range the rotor model
#:   accepts, as a simulation's excitation, not a balance grade (G2.5 is
#:   about 5 g mm on this rotor, G4000 about 7,800 g mm).
UNSTATED_BOUNDS: dict[str, tuple[float, float]] = {
    "ball_diameter_scale": (0.8, 1.15),
    "span_scale": (0.5, 1.5),
    "motor_loss_scale": (0.25, 3.0),
    "load_friction_scale": (0.25, 25.0),
    "outer_ring_contact_w_per_m2_k": (300.0, 3.0e4),
    "radial_load_n": (0.0, 3000.0),
    "unbalance_g_mm": (0.0, 1.0e4),
}
#: The declarable inputs that change the spindle's stored dimensions.
_DIMENSIONS = (
    "ball_diameter_scale",
    "span_scale",
    "motor_loss_scale",
    "outer_ring_contact_w_per_m2_k",
)
UNSTATED_INPUTS = (
    *_DIMENSIONS,
    "lubrication_factor_f0",
    "load_friction_scale",
    "radial_load_n",
    "unbalance_g_mm",
)
_OPTIONS = (
    "spin_friction_coefficient",
    "preload_kind",
    "spring_rate_n_per_um",
    "unbalance_grade",
    "preload_scale",
    "runout_um",
    "heat_model",
    "lubrication",
    "churning_oil_fraction",
    "extra_heat_w",
    *HEAT_LAW_OPTIONS,
    *SUPPLY_OPTIONS,
    *UNSTATED_INPUTS,
)
#: Options that act only on the vibration quantity (not the thermal state).
_VIBRATION_ONLY = ("unbalance_grade", "runout_um", "unbalance_g_mm")


class SpindleModelSpec(ModelSpec):
    """The baseline model of a spindle: a [`Spindle`][thermobear.Spindle],
    ``effects`` (names, or ``"thermal_displacement"`` for the five
    thermal-expansion effects; None = every effect) and options
    ``spin_friction_coefficient``, ``preload_kind`` ("rigid" or "spring"),
    ``spring_rate_n_per_um`` and ``unbalance_grade`` (ISO 21940 grade of the
    rotor, mm/s; default G2.5) -- each defaults to the spindle's own --,
    ``preload_scale`` (the stated preload times this; per level
    ``preload_scale@<N>``), ``runout_um`` (shaft runout seen by the
    vibration probe, default 0), ``heat_model``, ``lubrication``,
    ``churning_oil_fraction`` and the oil-supply keywords such as
    ``oil_volume_cm3_per_h``, ``oil_flow_scale`` (docs/concepts/physics.md
    §9). The spindle's own oil supply is the default: its drag follows the
    supply as in [`Spindle.thermal_state`][thermobear.Spindle.thermal_state];
    a lubrication method or a fixed ``churning_oil_fraction`` given without
    supply keywords replaces it, as in
    [`Spindle.with_options`][thermobear.Spindle.with_options].

    Inputs a study does not know (``UNSTATED_INPUTS``; each None by default,
    the spindle's own value): ``ball_diameter_scale``, ``span_scale`` and
    ``motor_loss_scale`` (factors on the spindle's balls, axial layout and
    motor losses, [`with_dimensions`][thermobear.spindle.dimensions.with_dimensions]),
    ``outer_ring_contact_w_per_m2_k`` (the contact conductance of the
    outer rings' seats),
    ``lubrication_factor_f0``, ``load_friction_scale`` (a factor on
    Palmgren's load-friction factor f1), ``radial_load_n`` (the working load at the
    nose) and ``unbalance_g_mm`` (the rotor's unbalance as mass times
    radius, in place of ``unbalance_grade``). Given a number, each is
    applied and listed as a calibration candidate (bounds:
    ``UNSTATED_BOUNDS``).

    Each configuration, preload and speed is solved once (cached, shared by
    the copies of [`with_setting`][thermobear.SpindleModelSpec.with_setting])."""

    #: The quantities this model predicts (``SPINDLE_QUANTITIES``).
    quantities = SPINDLE_QUANTITIES

    def candidate_list(self, quantities: Sequence[str] = ()) -> list[Candidate]:
        """The spindle's candidates against this baseline, with a
        sensor-offset decoy per measured quantity in ``quantities``."""
        return _spindle_candidate_list(self, quantities)

    def __init__(self, spindle: Any, effects: Optional[Sequence[str]] = None, **options: Any):
        from .. import _native

        if not isinstance(spindle, Spindle):
            raise ConfigError(f"invalid spindle = {spindle!r}: give a thermobear.Spindle")
        _check_option_names(options)
        self.spindle = spindle
        self._known = tuple(n for n, *_ in _native.effects())
        every = [n for n in self._known if n != PULL_EFFECT or _has_pull_data(spindle)]
        self.effects = self._expand(every if effects is None else effects)
        defaults = {
            "spin_friction_coefficient": _default_spin_friction(spindle),
            "preload_kind": spindle.preload_kind,
            "spring_rate_n_per_um": spindle.spring_rate_n_per_um,
            "unbalance_grade": 2.5,
            "preload_scale": 1.0,
            "runout_um": 0.0,
            "heat_model": str(spindle.assumptions.get("heat_model", "palmgren")),
            "lubrication": None,
            "extra_heat_w": float(spindle.assumptions.get("extra_heat_w", 0.0)),
            **{k: float(spindle.assumptions.get(k, 0.0)) for k in HEAT_LAW_OPTIONS},
            **_own_drag(spindle),
            **dict.fromkeys(UNSTATED_INPUTS),
        }
        self.options = _merged_options(defaults, options)
        _check_options(self.options)
        self._cache: dict = {}

    @classmethod
    def of_model(cls, spindle: Any) -> "SpindleModelSpec":
        """The spec of a [`Spindle`][thermobear.Spindle] as configured: its own
        effects ([`with_options`][thermobear.Spindle.with_options]), the spindle's
        options."""
        if not isinstance(spindle, Spindle):
            raise ConfigError(f"invalid spindle = {spindle!r}: give a thermobear.Spindle")
        return cls(spindle, effects=list(spindle._native.effects))

    def _expand(self, effects: Sequence[str]) -> tuple[str, ...]:
        out: set[str] = set()
        for e in effects:
            e = str(e)
            if e == _GROUP:
                out |= set(THERMAL_DISPLACEMENT_EFFECTS)
            elif e in self._known:
                out.add(e)
            else:
                raise ConfigError(
                    f"invalid effect = {e!r}: known: {', '.join(self._known)}, {_GROUP}"
                )
        return tuple(sorted(out))

    def with_setting(self, add_effects: Sequence[str] = (), **options: Any) -> "SpindleModelSpec":
        """A copy with effects added and options replaced (shares the cache)."""
        new = object.__new__(SpindleModelSpec)
        new.spindle = self.spindle
        new._known = self._known
        new.effects = new._expand(list(self.effects) + list(add_effects))
        _check_option_names(options)
        new.options = _merged_options(self.options, options)
        _check_options(new.options)
        new._cache = self._cache
        return new

    def effective_preload_n(self, preload_n: float) -> float:
        """The preload the model applies for a stated ``preload_n`` [N]:
        times ``preload_scale`` and the level's ``preload_scale@<N>``."""
        o = self.options
        level = float(o.get(f"preload_scale@{float(preload_n):g}", 1.0))
        return float(preload_n) * float(o["preload_scale"]) * level

    def _thermal_key(self) -> tuple:
        """Options that change the thermal state (not the vibration-only
        ones, not the preload scales: those enter as the effective preload);
        computed once per spec (its options do not change after it is
        built)."""
        got = self.__dict__.get("_tkey")
        if got is None or got[0] is not self.options:
            key = tuple(
                sorted(
                    (k, str(v))
                    for k, v in self.options.items()
                    if k not in _VIBRATION_ONLY and not k.startswith("preload_scale")
                )
            )
            got = (self.options, key)
            self.__dict__["_tkey"] = got
        return got[1]

    def level_candidates(
        self,
        conditions: polars.DataFrame,
        min_levels: int = 2,
    ) -> list[Candidate]:
        """One preload-scale candidate per preload level of ``conditions``
        (``min_levels`` or more levels)."""
        col = "axial_n" if "axial_n" in conditions.columns else "preload_n"
        levels = conditions[col].to_list()
        return load_level_candidates(
            "preload_scale", levels, tuple(SPINDLE_QUANTITIES), "preload", min_levels
        )

    @property
    def coupled(self) -> bool:
        """Whether the vibration uses the thermal raceway offsets (any
        thermal-expansion effect on)."""
        return bool(set(self.effects) & set(THERMAL_DISPLACEMENT_EFFECTS))

    def configured(self, preload_n: float) -> Spindle:
        """The [`Spindle`][thermobear.Spindle] of this configuration at a
        stated preload (scaled by
        [`effective_preload_n`][thermobear.SpindleModelSpec.effective_preload_n]);
        the drag settings not set (None) stay the spindle's own; the extra
        heat at the front set and the unknown heat source's speed law
        (``unknown_heat_*``) are the spindle's inputs of those names."""
        o = self.options
        # the spindle's own spring rate is kept as stored (N/um -> N/m is not
        # exact to the last bit); another one is set
        rate = o["spring_rate_n_per_um"]
        spring = o["preload_kind"] == "spring" and rate != self.spindle.spring_rate_n_per_um
        drag = ("lubrication", "churning_oil_fraction", "lubrication_factor_f0",
                "load_friction_scale", *SUPPLY_OPTIONS)  # fmt: skip
        radial = o["radial_load_n"]
        return self._dimensioned().with_options(
            preload_n=self.effective_preload_n(preload_n),
            preload_kind=o["preload_kind"],
            spring_rate_n_per_um=float(rate) if spring else None,
            radial_load_n=None if radial is None else float(radial),
            effects=list(self.effects),
            spin_friction_coefficient=float(o["spin_friction_coefficient"]),
            heat_model=str(o["heat_model"]),
            extra_heat_w=float(o["extra_heat_w"]),
            **{k: float(o[k]) for k in HEAT_LAW_OPTIONS},
            **{k: o[k] for k in drag if o[k] is not None},
        )

    def _dimensioned(self) -> Spindle:
        """The spindle with the declared dimension factors applied (once
        per set of factors, shared by the copies)."""
        from ..spindle.dimensions import with_dimensions

        scales = {k: self.options[k] for k in _DIMENSIONS if self.options[k] is not None}
        if not scales:
            return self.spindle
        key = ("dimensions", tuple(sorted(scales.items())))
        if key not in self._cache:
            self._cache[key] = with_dimensions(self.spindle, **scales)
        return self._cache[key]

    def _state(self, preload_n: float, speed_rpm: float) -> dict:
        key = ("state", self.effects, self._thermal_key(), self.effective_preload_n(preload_n),
               speed_rpm)  # fmt: skip
        if key not in self._cache:
            sp = self.configured(preload_n)
            try:
                d = sp._native.steady_state(float(speed_rpm))
            except ThermobearError as e:  # a failing configuration fails every time
                self._cache[key] = e
                raise
            offsets = {
                "front": tuple(float(v) for v in d["front_raceway_offsets_m"]),
                "rear": tuple(float(v) for v in d["rear_raceway_offsets_m"]),
            }
            row = _state_row(d, sp)
            row["compensation_preload_n"] = self._compensation_n(row["axial_growth_um"])
            row["outer_inner_load_difference_n"] = row["outer_load_max_n"] - row["inner_load_max_n"]
            self._cache[key] = (row, offsets)
        res = self._cache[key]
        if isinstance(res, ThermobearError):
            raise res
        return res

    def _compensation_n(self, axial_growth_um: float) -> float:
        """The preload the axial growth adds through the spring, k_s u (0
        for a rigid preload or with ``preload_change_from_axial_growth``
        off), as [`compensation_preload`][thermobear.compensation_preload]."""
        o = self.options
        if o["preload_kind"] != "spring" or "preload_change_from_axial_growth" not in self.effects:
            return 0.0
        return float(o["spring_rate_n_per_um"]) * float(axial_growth_um)

    def mechanical(self) -> SpindleModelSpec:
        """The same configuration without thermal displacement (the five
        thermal-expansion effects off): seed B's uncoupled model (made once
        per spec)."""
        got = self.__dict__.get("_mechanical")
        if got is not None and got.options is self.options:
            return got
        new = object.__new__(SpindleModelSpec)
        new.spindle, new._known, new.options, new._cache = (
            self.spindle, self._known, self.options, self._cache,
        )  # fmt: skip
        new.effects = tuple(e for e in self.effects if e not in THERMAL_DISPLACEMENT_EFFECTS)
        self.__dict__["_mechanical"] = new
        return new

    def _row(self, preload_n: float, speed_rpm: float) -> dict:
        """The state row with seed B's total radial displacement (eq. 22):
        the radial displacement without thermal displacement (this
        configuration uncoupled, same speed and preload) plus the radial
        thermal displacement of this state."""
        row, _ = self._state(preload_n, speed_rpm)
        if "total_radial_displacement_um" not in row:
            cold = row if not self.coupled else self.mechanical()._state(preload_n, speed_rpm)[0]
            row["total_radial_displacement_um"] = abs(cold["radial_displacement_um"]) + (
                row["thermal_radial_displacement_um"] if self.coupled else 0.0
            )
        return row

    def unbalance(self) -> dict[str, Optional[float]]:
        """The rotor's unbalance as [`thermobear.vibration`][thermobear.vibration]
        takes it: ``unbalance_g_mm`` when declared, else ``unbalance_grade``."""
        g_mm = self.options["unbalance_g_mm"]
        if g_mm is not None:
            return {"unbalance_grade": None, "unbalance_g_mm": float(g_mm)}
        return {"unbalance_grade": float(self.options["unbalance_grade"]), "unbalance_g_mm": None}

    def _vibration(self, preload_n: float, speeds: np.ndarray) -> dict[str, np.ndarray]:
        from ..rotor import vibration

        unbalance = self.unbalance()
        key = ("vibration", self.effects, self._thermal_key(), tuple(sorted(unbalance.items())),
               self.effective_preload_n(preload_n), tuple(speeds.tolist()))  # fmt: skip
        if key not in self._cache:
            rotor = _RotorView(self, preload_n)
            try:
                df = vibration(
                    rotor,
                    speeds,
                    coupled=self.coupled,
                    effects=list(self.effects),
                    unbalance_grade=unbalance["unbalance_grade"],
                    unbalance_g_mm=unbalance["unbalance_g_mm"],
                )
            except ThermobearError as e:
                self._cache[key] = e
                raise
            self._cache[key] = {_VIB: df[_VIB].to_numpy(), "x1_mm_s": df["x1_mm_s"].to_numpy()}
        res = self._cache[key]
        if isinstance(res, ThermobearError):
            raise res
        return res

    def predict(self, conditions: polars.DataFrame) -> dict[str, np.ndarray]:
        """Every quantity of ``SPINDLE_QUANTITIES`` at each row of
        ``conditions`` (``speed_rpm`` and ``axial_n`` or ``preload_n``):
        name -> array. The vibration and the total radial displacement (which
        needs the uncoupled state too) are computed only when asked for (the
        returned mapping evaluates them on first access)."""
        sp = conditions["speed_rpm"].to_numpy().astype(float)
        radial = (
            conditions["radial_n"].to_numpy().astype(float)
            if "radial_n" in conditions.columns
            else np.zeros(0)
        )
        if np.any(radial != 0.0):
            r = float(radial[radial != 0.0][0])
            raise ConfigError(
                f"invalid radial_n = {r}: a spindle's radial load is a setting of the "
                "Spindle (with_options(radial_load_n=...)), not a measured condition"
            )
        col = "axial_n" if "axial_n" in conditions.columns else "preload_n"
        pre = conditions[col].to_numpy().astype(float)
        cells, inverse = np.unique(np.stack([pre, sp], axis=1), axis=0, return_inverse=True)
        at = inverse.reshape(-1)

        def column(states: list[dict], q: str) -> np.ndarray:
            c, s = SPINDLE_QUANTITIES[q][0], SPINDLE_QUANTITIES[q][1]
            return (np.array([st[c] for st in states], dtype=float) * s)[at]

        states = [self._state(float(p), float(v))[0] for p, v in cells]
        out = {q: column(states, q) for q in SPINDLE_QUANTITIES if q not in _LAZY}

        def lazy(q: str) -> np.ndarray:
            if q in _ROTOR:
                return self._vibration_rows(q, sp, pre)
            return column([self._row(float(p), float(v)) for p, v in cells], q)

        return with_changes(_Predictions(out, lazy), conditions, self.predict)

    def _vibration_rows(self, quantity: str, sp: np.ndarray, pre: np.ndarray) -> np.ndarray:
        """The rotor's ``quantity`` (velocity RMS, or the 1X amplitude) at
        each row; the probe's runout adds to both as a 1X line."""
        y = np.empty(len(sp))
        for p in sorted(set(pre.tolist())):
            rows = np.flatnonzero(pre == p)
            speeds = np.unique(sp[rows])
            v = self._vibration(p, speeds)[quantity]
            y[rows] = v[np.searchsorted(speeds, sp[rows])]
        runout = float(self.options["runout_um"])
        if quantity == _VIB:
            return runout_velocity_rms_mm_s(y, sp, runout)
        return np.sqrt(2.0) * runout_velocity_rms_mm_s(y / np.sqrt(2.0), sp, runout)

    def __repr__(self) -> str:
        return f"SpindleModelSpec({self.spindle!r}, effects={list(self.effects)})"


register_kind("spindle", Spindle, SpindleModelSpec, SPINDLE_QUANTITIES)


def runout_velocity_rms_mm_s(velocity_rms_mm_s: Any, speed_rpm: Any, runout_um: float) -> Any:
    """The velocity RMS a non-contact probe reads [mm/s] when the shaft
    track it looks at runs out by ``runout_um`` (peak, um): the track's
    once-per-revolution motion eps sin(omega t) reads as a 1X velocity of
    amplitude omega eps (RMS omega eps / sqrt 2), added to the vibration
    in quadrature (its phase to the unbalance response is not known; the
    expected power of two 1X components of unrelated phase is the sum)."""
    v = np.asarray(velocity_rms_mm_s, dtype=float)
    if runout_um == 0.0:
        return v
    omega = 2.0 * np.pi * np.asarray(speed_rpm, dtype=float) / 60.0
    r = omega * runout_um * 1e-3 / np.sqrt(2.0)  # um * rad/s -> mm/s
    return np.sqrt(v * v + r * r)


class _Predictions(dict):
    """The predictions; the lazy columns (``_LAZY``) are computed on first
    access."""

    def __init__(self, values: dict, vibration: Any) -> None:
        super().__init__(values)
        self._vibration = vibration

    def __missing__(self, key: str) -> np.ndarray:
        if key not in _LAZY:
            raise KeyError(key)
        self[key] = self._vibration(key)
        return self[key]


class _RotorView:
    """The spindle protocol of [`thermobear.rotor`][thermobear.rotor] for one configuration,
    reading the raceway offsets from the spec's cached steady states."""

    def __init__(self, spec: SpindleModelSpec, preload_n: float) -> None:
        self._spec = spec
        self.preload_n = float(preload_n)
        self.rotor_layout = spec.spindle.rotor_layout
        if self.rotor_layout is None:
            self.rotor_preset_name = spec.spindle.rotor_preset_name

    def raceway_offsets(self, speed_rpm: float) -> dict:
        return self._spec._state(self.preload_n, float(speed_rpm))[1]


def _default_spin_friction(spindle: Spindle) -> float:
    a = spindle.assumptions
    if "spin_friction_coefficient" in a:
        return float(a["spin_friction_coefficient"])
    raise ConfigError(f"invalid spindle = {spindle!r}: no spin friction coefficient in assumptions")


def _own_drag(spindle: Spindle) -> dict:
    """The spindle's drag settings as spec options: its oil supply as the
    supply keywords that give it back (None where not stated), or, without
    a supply, its fixed cavity oil fraction."""
    a = spindle.assumptions
    own = {k: a.get(k) for k in SUPPLY_OPTIONS}
    fixed = None if supply_given(own) else float(a.get("churning_oil_fraction", 0.0))
    return {"churning_oil_fraction": fixed, **own}


def _merged_options(base: dict, options: dict) -> dict:
    """``base`` with ``options`` replaced, the drag kept to one source as
    [`Spindle.with_options`][thermobear.Spindle.with_options] does: supply
    keywords given leave the fixed fraction unset; a lubrication method
    or a fixed fraction given without them drops the base's supply (the
    method's drag, or the fixed fraction)."""
    out = {**base, **options}
    if supply_given(options):
        if "churning_oil_fraction" not in options:
            out["churning_oil_fraction"] = None
    elif any(options.get(k) is not None for k in ("lubrication", "churning_oil_fraction")):
        out.update(dict.fromkeys(SUPPLY_OPTIONS))
        if "churning_oil_fraction" not in options:  # the method's own fraction
            out["churning_oil_fraction"] = None
    return out


def _check_option_names(options: dict) -> None:
    from .registry import current_option_names

    current_option_names(options)
    for k in options:
        if k in _OPTIONS or k.split("@", 1)[0] == "preload_scale" and "@" in k:
            continue
        raise ConfigError(
            f"invalid option = {k!r}: known: {', '.join(_OPTIONS)}" + did_you_mean(k, _OPTIONS)
        )


def _check_options(o: dict) -> None:
    mu = o["spin_friction_coefficient"]
    if not (isinstance(mu, (int, float)) and np.isfinite(mu) and mu >= 0.0):
        raise ConfigError(f"invalid spin_friction_coefficient = {mu!r}: a finite coefficient >= 0")
    if o["preload_kind"] not in ("rigid", "spring"):
        raise ConfigError(f"invalid preload_kind = {o['preload_kind']!r}: 'rigid' or 'spring'")
    k = o["spring_rate_n_per_um"]
    if o["preload_kind"] == "spring" and not (k is not None and np.isfinite(k) and k > 0):
        raise ConfigError(f"invalid spring_rate_n_per_um = {k!r}: a spring needs a rate > 0")
    g = o["unbalance_grade"]
    if not (np.isfinite(g) and g > 0):
        raise ConfigError(f"invalid unbalance_grade = {g!r}: a grade > 0 mm/s")
    e = o["runout_um"]
    if not (np.isfinite(e) and e >= 0):
        raise ConfigError(f"invalid runout_um = {e!r}: a runout >= 0 um")
    x = o["churning_oil_fraction"]
    if x is not None and supply_given(o):
        raise ConfigError(
            f"invalid churning_oil_fraction = {x!r}: a fixed cavity oil fraction overrides "
            "the oil supply given; give one or the other"
        )
    for k in UNSTATED_INPUTS:
        _check_unstated(k, o[k])
    q = o["extra_heat_w"]
    if not (isinstance(q, (int, float)) and np.isfinite(q) and 0.0 <= q <= MAX_EXTRA_HEAT_W):
        raise ConfigError(
            f"invalid extra_heat_w = {q!r}: a heat in [0, {MAX_EXTRA_HEAT_W:g}] W at the front set"
        )
    pop_heat_law({k: o[k] for k in HEAT_LAW_OPTIONS})


def _has_pull_data(spindle: Spindle) -> bool:
    """Whether ``spindle`` carries the motor's air-gap data (a spindle
    described without a magnetic-pull table has none, so "every effect"
    leaves the pull out)."""
    return "magnetic_pull_static_n" in spindle.assumptions


def _check_unstated(name: str, value: Any) -> None:
    """An unstated input: None, or a finite number (> 0 for the factors
    and f0, >= 0 for the unbalance; the nose load may point either way)."""
    if value is None:
        return
    ok = isinstance(value, (int, float)) and not isinstance(value, bool) and np.isfinite(value)
    if ok and name in (*_DIMENSIONS, "lubrication_factor_f0", "load_friction_scale"):
        ok = value > 0.0
    elif ok and name == "unbalance_g_mm":
        ok = value >= 0.0
    if not ok:
        raise ConfigError(
            f"invalid {name} = {value!r}: None or a finite number (see UNSTATED_BOUNDS)"
        )


# --------------------------------------------------------------------------
# candidates


def _spindle_candidate_list(
    model: Optional[SpindleModelSpec], quantities: Sequence[str] = ()
) -> list[Candidate]:
    """The spindle's candidates (same ``thermobear.diagnosis.Candidate``
    records as the bearing registry)."""

    if model is None:
        model = SpindleModelSpec(Spindle.preset("seed-ceramic-spindle"), effects=[])
    base = set(model.effects)
    opts = model.options
    allq = tuple(SPINDLE_QUANTITIES)
    out = _switch_candidates(base, allq)
    out += _spin_friction_candidates(opts, allq)
    out += _preload_candidates(opts, allq)
    out += _unbalance_candidates(opts)
    out += _preload_scale_and_runout_candidates(opts, allq)
    out += _unstated_candidates(model, allq)
    out.append(_extra_heat_candidate(opts, allq))
    out += heat_model_candidates(opts, allq, skf_inputs=False)
    out += supply_candidates(opts, allq)
    out += sensor_offset_candidates(quantities, SPINDLE_QUANTITIES)
    out += sensor_gain_candidates(quantities, SPINDLE_QUANTITIES)
    return out


def _preload_scale_and_runout_candidates(opts: dict, allq: tuple) -> list[Candidate]:
    """The preload set off by a factor (a baseline input) and the shaft
    runout a non-contact vibration probe sees (measurement side; it acts
    through the model's vibration, so it is a model option)."""
    scale = _calibrated_input(
        "preload_scale", "preload_scale", "1", opts["preload_scale"], PRELOAD_SCALE_BOUNDS,
        "preload differs from the stated one by a factor", allq,
    )  # fmt: skip
    runout = Candidate(
        "runout_um", "parameter", "model", "runout_um", "um", RUNOUT_BOUNDS_UM[0],
        max(RUNOUT_BOUNDS_UM[1], float(opts["runout_um"])), float(opts["runout_um"]),
        "shaft runout seen by the non-contact vibration probe: 1X velocity omega x runout",
        (_VIB,), option="runout_um", role="measurement",
    )  # fmt: skip
    return [scale, runout]


#: Bounds of the spindle's extra heat at the front set [W]: twice the
#: single bearing's (0-100 W), one such heat per front bearing.
EXTRA_HEAT_BOUNDS_W = (0.0, 200.0)


def _extra_heat_candidate(opts: dict, allq: tuple) -> Candidate:
    """An extra heat at the front bearing set, split like rolling heat
    (the spindle's carrier of the unknown heat source, as ``extra_heat_w``
    is the bearing's)."""
    lo, hi = EXTRA_HEAT_BOUNDS_W
    null = float(opts["extra_heat_w"])
    return Candidate(
        "extra_heat_w", "parameter", "model", "extra_heat_w", "W", lo, max(hi, null), null,
        "extra heat at the front bearing set (e.g. magnetic-pull friction), split like "
        "rolling heat", allq, option="extra_heat_w", role="effect",
    )  # fmt: skip


#: What each unstated input is, for its candidate.
_UNSTATED_TEXT = {
    "ball_diameter_scale": ("1", "ball diameter of both pairs as a factor on the spindle's"),
    "span_scale": ("1", "axial layout between the bearing sets (spans, rotor core) as a factor"),
    "motor_loss_scale": ("1", "motor losses (stator and rotor) as a factor on the spindle's"),
    "lubrication_factor_f0": ("1", "Palmgren lubrication factor f0 of the viscous moment"),
    "load_friction_scale": (
        "1",
        "Palmgren load-friction factor f1 as a factor on Harris' table value",
    ),
    "outer_ring_contact_w_per_m2_k": (
        "W/(m^2 K)",
        "thermal contact conductance of the outer rings' seats in the housing",
    ),
    "radial_load_n": ("N", "working radial load at the spindle nose"),
    "unbalance_g_mm": ("g mm", "rotor unbalance (mass x radius) exciting the vibration"),
}


def _unstated_candidates(model: SpindleModelSpec, allq: tuple) -> list[Candidate]:
    """A calibration candidate for each declared unstated input (an option
    given a number; bounds ``UNSTATED_BOUNDS``, f0 those of the spindle's
    lubrication method). The unbalance acts on the rotor's quantities only,
    the nose load on every quantity but those."""
    out = []
    for name in UNSTATED_INPUTS:
        value = model.options[name]
        if value is None:
            continue
        unit, desc = _UNSTATED_TEXT[name]
        bounds = UNSTATED_BOUNDS.get(name) or _f0_bounds(model.spindle)
        affects = _ROTOR if name == "unbalance_g_mm" else allq
        if name == "radial_load_n":
            affects = tuple(q for q in allq if q not in _ROTOR)
        out.append(_calibrated_input(name, name, unit, float(value), bounds, desc, affects))
    return out


def _f0_bounds(spindle: Spindle) -> tuple[float, float]:
    """The f0 bounds of the spindle's lubrication method (oil-air when it
    states none)."""
    from .. import _native

    method = str(spindle.assumptions.get("lubrication") or "oil-air")
    return tuple(_native.lubrication_defaults(method, "angular_contact")["f0_bounds"])


def _switch_candidates(base: set, allq: tuple) -> list[Candidate]:
    """``thermal_displacement`` (when two or more of its effects are off)
    and every effect the baseline leaves off."""
    from .. import _native

    out: list[Candidate] = []
    missing = [e for e in THERMAL_DISPLACEMENT_EFFECTS if e not in base]
    if len(missing) > 1:
        out.append(
            Candidate(
                _GROUP,
                "switch",
                "model",
                f"{_GROUP}_on",
                "1",
                0.0,
                1.0,
                0.0,
                "thermal growth of shaft, rings, balls and housing together (A-38): "
                "seed B's coupled model",
                allq,
                effect=_GROUP,
            )
        )
    for name, desc, *_ in _native.effects():
        if name in base:
            continue
        out.append(
            Candidate(
                name, "switch", "model", f"{name}_on", "1", 0.0, 1.0, 0.0, desc, allq, effect=name
            )
        )
    return out


def _calibrated_input(
    name: str, option: str, unit: str, value: float, bounds: tuple, desc: str, quantities: tuple
) -> Candidate:
    """A baseline input calibrated over its bounds (widened to hold the
    baseline value, which is snapped onto the screening grid)."""
    v = _on_grid(float(value), *bounds)
    return Candidate(
        name,
        "parameter",
        "model",
        option,
        unit,
        min(bounds[0], v),
        max(bounds[1], v),
        v,
        desc,
        quantities,
        option=option,
        role="calibration",
    )


def _spin_friction_candidates(opts: dict, allq: tuple) -> list[Candidate]:
    """The spin friction coefficient, a baseline input."""
    desc = "spin friction coefficient mu_s (acts with the spin_friction effect on)"
    return [
        _calibrated_input(
            "spin_friction_coefficient",
            "spin_friction_coefficient",
            "1",
            opts["spin_friction_coefficient"],
            _SPIN_BOUNDS,
            desc,
            allq,
        )
    ]


def _preload_candidates(opts: dict, allq: tuple) -> list[Candidate]:
    """The other preload kind (rigid <-> spring) and, for a spring, its rate."""
    out: list[Candidate] = []
    other = "rigid" if opts["preload_kind"] == "spring" else "spring"
    if other == "rigid" or opts["spring_rate_n_per_um"] is not None:
        out.append(
            Candidate(
                f"preload_kind:{other}",
                "switch",
                "model",
                f"preload_is_{other}",
                "1",
                0.0,
                1.0,
                0.0,
                f"preload by {'fixed position' if other == 'rigid' else 'constant-force spring'}",
                allq,
                option="preload_kind",
                role="calibration",
            )
        )
    if opts["preload_kind"] == "spring":
        desc = "preload spring rate (thermal growth changes the preload by rate x growth)"
        out.append(
            _calibrated_input(
                "spring_rate_n_per_um",
                "spring_rate_n_per_um",
                "N/um",
                opts["spring_rate_n_per_um"],
                _SPRING_BOUNDS,
                desc,
                allq,
            )
        )
    return out


def _unbalance_candidates(opts: dict) -> list[Candidate]:
    """The rotor's residual unbalance grade (acts on the vibration only)."""
    desc = "residual unbalance of the rotor (ISO 21940 grade at 30,000 rpm)"
    return [
        _calibrated_input(
            "unbalance_grade",
            "unbalance_grade",
            "mm/s",
            opts["unbalance_grade"],
            _UNBALANCE_BOUNDS,
            desc,
            (_VIB,),
        )
    ]


def _on_grid(null: float, lo: float, hi: float) -> float:
    """The null value, snapped onto the screening grid of
    [`thermobear.diagnosis`][thermobear.diagnosis] (``linspace(lo, hi, _GRID)`` plus the null)
    when it lies within rounding of a grid point: 0.05 and
    ``linspace(0, 0.3, 13)[2]`` differ in the last bit, and two abscissae an
    ulp apart make the cubic interpolant of the predictions meaningless."""
    lo, hi = min(lo, null), max(hi, null)
    grid = np.linspace(lo, hi, _GRID)
    i = int(np.argmin(np.abs(grid - null)))
    return float(grid[i]) if abs(grid[i] - null) <= 1e-9 * (hi - lo) else null


def spindle_candidates(
    model: Optional[SpindleModelSpec] = None, quantities: Sequence[str] = ()
) -> "polars.DataFrame":  # noqa: F821
    """Deprecated: [`thermobear.candidates`][thermobear.diagnosis.candidates.candidates] takes a
    spindle spec or a [`Spindle`][thermobear.Spindle]. Without ``model`` the baseline is the
    seed ceramic spindle with every effect off."""
    from .._deprecation import warn_renamed

    warn_renamed("spindle_candidates", "candidates", what="it takes a spindle model")
    if model is None:
        model = SpindleModelSpec(Spindle.preset("seed-ceramic-spindle"), effects=[])
    return _candidate_table(model, quantities)


def load_spindle_measurements(data: Any) -> "polars.DataFrame":  # noqa: F821
    """Deprecated: [`thermobear.load_measurements`][thermobear.load_measurements] recognises spindle
    data by their quantities (or takes ``model=``)."""
    from .._deprecation import warn_renamed

    warn_renamed("load_spindle_measurements", "load_measurements", what="it reads spindle data")
    return load_measurements(data, SPINDLE_QUANTITIES)


def diagnose_spindle(
    model: SpindleModelSpec,
    measured: Any,
    candidates: Optional[Sequence[str]] = None,
    holdout: Union[str, float, Sequence[str], None] = "highest_speeds",
    **options: Any,
) -> Diagnosis:
    """Deprecated: [`thermobear.diagnose`][thermobear.diagnose] takes a spindle spec or a
    [`Spindle`][thermobear.Spindle]."""
    from .._deprecation import warn_renamed

    warn_renamed("diagnose_spindle", "diagnose", what="it takes a spindle model")
    if not isinstance(model, (SpindleModelSpec, Spindle)):
        raise ConfigError(f"invalid model = {model!r}: give a thermobear.SpindleModelSpec")
    return diagnose(model, measured, candidates, holdout, **options)


def seed_b_measurements() -> polars.DataFrame:
    """Seed B's reported measurements (configs/seed_b_measurements.csv; the
    sources are in the file) as a checked tidy table."""
    path = resources.files("thermobear.configs").joinpath("seed_b_measurements.csv")
    with resources.as_file(path) as p:
        return load_measurements(p, SPINDLE_QUANTITIES)
