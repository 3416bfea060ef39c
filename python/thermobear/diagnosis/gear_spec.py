"""The gear pair as a model to calibrate: [`GearModelSpec`][thermobear.GearModelSpec].

Its measured quantities are transition speeds of the pair's bifurcation
diagram (``thermobear.gear.transitions``: the end of the low-speed
period-1 motion, amplitude jumps, period-2 speeds, ranges of irregular
motion and the periodic windows in them), each at a condition: the input
torque ``torque_n_m``, the bearing ``stiffness`` case ("constant",
"speed", "thermal" or "any") and the sweep ``direction`` ("up", "down" or
"any"); the row's ``speed_rpm`` is where the transition was read, and the
model's value is its own event of that quantity nearest to it.

Its calibratable inputs are what a paper on gear dynamics often leaves
out: the first-harmonic static transmission error ``te_amplitude_um``,
the mesh damping ratio ``mesh_damping_ratio``, the half backlash
``half_backlash_um`` and a factor on the mesh stiffness
``mesh_stiffness_scale``. Transition speeds jump when an input crosses a
bifurcation, so they are calibrated by a design of experiments and a
local refinement ([`thermobear.calibrate`][thermobear.calibrate] on a gear
spec; ``thermobear.diagnosis.gear_calibration``), not by least squares.

Each configuration's sweeps (every stiffness case, torque and direction the
conditions name, all in one parallel
[`bifurcation_set`][thermobear.bifurcation_set]) run once and are cached.
"""

from __future__ import annotations

import json
from typing import TYPE_CHECKING, Any, Optional, Sequence

import numpy as np

from ..errors import ConfigError
from .candidates import Candidate
from .measurements import GEAR_REGISTRIES
from .protocol import ModelSpec, register_kind

if TYPE_CHECKING:
    import polars

#: Stiffness cases and directions a gear measurement may name.
STIFFNESS_CASES = ("constant", "speed", "thermal", "any")
DIRECTIONS = ("up", "down", "any")

#: The condition columns of a gear measurement (besides ``quantity``,
#: ``value``, ``sigma``, ``run``).
GEAR_CONDITIONS = ("speed_rpm", "torque_n_m", "stiffness", "direction")

#: Typical reading uncertainty of a transition speed read off a diagram
#: [rpm] (used when a table gives no sigma): 50 rpm, a tenth of the
#: 500 rpm ticks of a typical speed axis (assumed).
TYPICAL_SIGMA_RPM = 50.0


def _registry() -> dict[str, tuple[str, float, tuple[float, float], float, bool]]:
    from ..gear.transitions import TRANSITIONS

    return {q: (q, 1.0, (0.0, 1e6), TYPICAL_SIGMA_RPM, False) for q in TRANSITIONS}


#: name: (model column, scale, plausible range, typical sigma, relative?),
#: the layout of ``thermobear.diagnosis.QUANTITIES``.
GEAR_QUANTITIES: dict[str, tuple[str, float, tuple[float, float], float, bool]] = _registry()
GEAR_REGISTRIES.append(GEAR_QUANTITIES)

#: The calibratable inputs: option -> (lower, upper, unit, description).
#: Bounds: first-harmonic static TE 0.5-60 um (ground automotive gears
#: reach 1-10 um, ISO 1328 grades 4-8 allow profile and pitch deviations of
#: that order; 60 um lies beyond any gear in service, so a calibration at
#: the top says the data ask for more than a real gear); mesh damping ratio
#: 0.01-0.20 (measured gear-mesh damping is 0.03-0.17, Kahraman & Singh,
#: J. Sound Vib. 146 (1991)); half backlash 5-150 um (normal backlash of
#: 1-3 mm module gears is 0.03-0.2 mm, ISO/TR 10064-2); mesh stiffness
#: factor 0.4-1.5 (ISO 6336-1 and numerical mesh stiffnesses of one pair
#: differ by tens of per cent).
GEAR_PARAMETERS: dict[str, tuple[float, float, str, str]] = {
    "te_amplitude_um": (0.5, 60.0, "um", "first-harmonic static transmission error"),
    "mesh_damping_ratio": (0.01, 0.20, "-", "mesh damping ratio"),
    "half_backlash_um": (5.0, 150.0, "um", "half backlash"),
    "mesh_stiffness_scale": (0.4, 1.5, "-", "factor on the mesh stiffness"),
}

#: Defaults of the options (the documented defaults of ``GearSystem``; the
#: sweep grid, None, follows the measured speeds).
_DEFAULTS: dict[str, Any] = {
    "te_amplitude_um": 2.0,
    "mesh_damping_ratio": 0.07,
    "half_backlash_um": 50.0,
    "mesh_stiffness_scale": 1.0,
    "bearing_damping_ratio": 0.02,
    "mesh_damping": "in-contact",
    "torque_n_m": None,
    "stiffness": "speed",
    "bearings": None,
    "sweep_speeds_rpm": None,
    "sweep_step_rpm": 50.0,
    "sweep_options": None,
}

#: Options that are GearSystem keywords as they are.
_SYSTEM_OPTIONS = (
    "te_amplitude_um",
    "mesh_damping_ratio",
    "half_backlash_um",
    "mesh_stiffness_scale",
    "bearing_damping_ratio",
    "mesh_damping",
)


class GearModelSpec(ModelSpec):
    """The baseline model of a gear pair on its bearings, for calibrating
    the pair's unstated inputs on transition speeds.

    ``gear``: a [`GearPair`][thermobear.GearPair]. Options (keywords; all
    JSON-serialisable, so a calibrated model saves them):
    ``te_amplitude_um``, ``mesh_damping_ratio``, ``half_backlash_um``,
    ``mesh_stiffness_scale``, ``bearing_damping_ratio``, ``mesh_damping``
    (as [`GearSystem`][thermobear.GearSystem]); ``torque_n_m`` (None: the
    pair's; a measured row's own torque wins); ``stiffness`` (the case
    [`GearSystem`][thermobear.GearSystem] and
    [`bifurcation`][thermobear.bifurcation] use for a calibrated model when
    none is named; default "speed"); ``bearings`` (None: the 6208 preset;
    a bearing preset name, or the saved JSON text of a calibrated bearing
    model, whose thermal options the "thermal" case uses);
    ``sweep_speeds_rpm`` (the sweep's speeds; None: the measured speeds'
    range widened by 10 % each way on a grid of ``sweep_step_rpm``, default
    50 rpm); ``sweep_options`` (keywords of
    [`bifurcation_set`][thermobear.bifurcation_set], a dict).

    ``predict(conditions)``: every transition quantity at each row of
    ``conditions`` (``speed_rpm``, ``torque_n_m``, ``stiffness``,
    ``direction``; an optional ``comparison`` column for bounds)."""

    quantities = GEAR_QUANTITIES
    #: The columns of a condition row.
    conditions = GEAR_CONDITIONS

    def __init__(self, gear: Any, effects: Optional[Sequence[str]] = None, **options: Any):
        from ..gear.pair import GearPair

        if not isinstance(gear, GearPair):
            raise ConfigError(f"invalid gear = {gear!r}: give a thermobear.GearPair")
        if effects:
            raise ConfigError(
                f"invalid effects = {list(effects)!r}: a gear model has no switchable effects"
            )
        self.gear = gear
        self.effects = ()
        self.options = _checked_options({**_DEFAULTS, **options})
        self._cache: dict = {}

    @classmethod
    def of_model(cls, gear: Any) -> "GearModelSpec":
        """The spec of a [`GearPair`][thermobear.GearPair] with the documented defaults."""
        return cls(gear)

    def with_setting(self, add_effects: Sequence[str] = (), **options: Any) -> "GearModelSpec":
        """A copy with options replaced (shares the cache); a gear model has
        no effects to add."""
        if add_effects:
            raise ConfigError(
                f"invalid effects = {list(add_effects)!r}: a gear model has no switchable effects"
            )
        new = object.__new__(GearModelSpec)
        new.gear = self.gear
        new.effects = ()
        new.options = _checked_options({**self.options, **options})
        new._cache = self._cache
        return new

    def system_options(self) -> dict[str, Any]:
        """The [`GearSystem`][thermobear.GearSystem] keywords of the options
        (what a calibrated gear model passes on)."""
        o = self.options
        out = {k: o[k] for k in _SYSTEM_OPTIONS}
        if o["torque_n_m"] is not None:
            out["torque_n_m"] = float(o["torque_n_m"])
        return out

    def bearing_model(self) -> Any:
        """The bearings: None (the system's default 6208), a
        [`Bearing`][thermobear.Bearing] preset, or a calibrated bearing
        model (from its saved JSON text)."""
        b = self.options["bearings"]
        if b is None:
            return None
        if str(b).lstrip().startswith("{"):
            from .calibrated import CalibratedModel

            return CalibratedModel.from_json(str(b))
        from ..bearing import Bearing

        return Bearing.preset(str(b))

    def system(self, stiffness: Optional[str] = None, torque_n_m: Optional[float] = None) -> Any:
        """The [`GearSystem`][thermobear.GearSystem] of this setting in
        bearing-stiffness case ``stiffness`` (default the ``stiffness``
        option) at ``torque_n_m`` (default the option's, else the pair's)."""
        from ..gear.system import GearSystem

        opts = self.system_options()
        if torque_n_m is not None:
            opts["torque_n_m"] = float(torque_n_m)
        case: Any = self.options["stiffness"] if stiffness is None else stiffness
        return GearSystem(self.gear, bearings=self.bearing_model(), stiffness=case, **opts)

    def torque_of(self, torque_n_m: Optional[float]) -> float:
        """The torque of a condition row [N m]: its own, else the
        ``torque_n_m`` option, else the pair's."""
        if torque_n_m is not None:
            return float(torque_n_m)
        if self.options["torque_n_m"] is not None:
            return float(self.options["torque_n_m"])
        return float(self.gear.geometry["input_torque_n_m"])

    def sweep_speeds(self, conditions: polars.DataFrame) -> np.ndarray:
        """The speeds the sweeps run over (see the class docstring)."""
        given = self.options["sweep_speeds_rpm"]
        if given is not None:
            return np.asarray(given, dtype=float)
        sp = conditions["speed_rpm"].to_numpy()
        step = float(self.options["sweep_step_rpm"])
        lo = max(step, np.floor(0.9 * sp.min() / step) * step)
        hi = np.ceil(1.1 * sp.max() / step) * step
        return np.arange(lo, hi + 0.5 * step, step)

    def events(self, conditions: polars.DataFrame) -> dict:
        """The transition events of every sweep the conditions name:
        (case, torque, direction) -> quantity -> speeds (cached by setting,
        sweeps and speeds)."""
        from ..gear.dynamics import bifurcation_set
        from ..gear.transitions import transition_events

        speeds = self.sweep_speeds(conditions)
        cases = _named(conditions["stiffness"].to_list(), ("constant", "speed", "thermal"))
        directions = _named(conditions["direction"].to_list(), ("up", "down"))
        torques = sorted({self.torque_of(t) for t in conditions["torque_n_m"].to_list()})
        key = (
            tuple(sorted((k, json.dumps(v, sort_keys=True)) for k, v in self.options.items())),
            tuple(cases), tuple(directions), tuple(torques), tuple(speeds.tolist()),
        )  # fmt: skip
        if key not in self._cache:
            systems = {
                f"{c}@{t:g}": self.system(stiffness=c, torque_n_m=t) for c in cases for t in torques
            }
            pts = bifurcation_set(
                systems, speeds, directions=tuple(directions),
                **(self.options["sweep_options"] or {}),
            )  # fmt: skip
            self._cache[key] = transition_events(pts)
        return self._cache[key]

    def predict(self, conditions: polars.DataFrame) -> dict[str, np.ndarray]:
        """Every transition quantity at each row of ``conditions``: the
        model's event nearest to the row's ``speed_rpm`` over the sweeps of
        its stiffness case, torque and direction (a bound row: see
        ``thermobear.gear.transitions.model_value``); NaN where the model
        has no such event."""
        from ..gear.transitions import model_value

        ev = self.events(conditions)
        comp = (
            conditions["comparison"].to_list()
            if "comparison" in conditions.columns
            else ["="] * conditions.height
        )
        out = {q: np.full(conditions.height, np.nan) for q in GEAR_QUANTITIES}
        rows = zip(
            conditions["speed_rpm"].to_list(), conditions["torque_n_m"].to_list(),
            conditions["stiffness"].to_list(), conditions["direction"].to_list(), comp,
            strict=True,
        )  # fmt: skip
        for i, (s, t, case, d, cmp) in enumerate(rows):
            tq = self.torque_of(t)
            sub = {(c.split("@")[0], dd): e for (c, dd), e in ev.items()
                   if float(c.split("@")[1]) == tq}  # fmt: skip
            for q in GEAR_QUANTITIES:
                out[q][i] = model_value(sub, q, float(s), case, d, cmp)
        return out

    def candidate_list(self, quantities: Sequence[str] = ()) -> list[Candidate]:
        """The calibratable inputs as parameter candidates (their null: the
        current option values)."""
        out = []
        for name, (lo, hi, unit, desc) in GEAR_PARAMETERS.items():
            out.append(
                Candidate(
                    name=name, kind="parameter", side="model", parameter=name, unit=unit,
                    lower=lo, upper=hi, null=float(self.options[name]),
                    description=f"{desc} (not stated)", affects=tuple(GEAR_QUANTITIES),
                    option=name, role="calibration",
                )
            )  # fmt: skip
        return out

    def __repr__(self) -> str:
        shown = {k: self.options[k] for k in GEAR_PARAMETERS}
        return f"GearModelSpec({self.gear!r}, {shown})"


def _named(values: Sequence[Any], every: tuple[str, ...]) -> list[str]:
    """The cases (or directions) the rows name, ``"any"`` standing for all."""
    got = set()
    for v in values:
        got |= set(every) if v == "any" else {str(v)}
    return [v for v in every if v in got]


def _checked_options(o: dict) -> dict:
    """The options with named errors for unknown names and bad values."""
    from .. import _validate as val

    unknown = sorted(set(o) - set(_DEFAULTS))
    if unknown:
        raise ConfigError(
            f"invalid option = {unknown[0]!r}: a gear model's options are {', '.join(_DEFAULTS)}"
            + val.did_you_mean(unknown[0], _DEFAULTS)
        )
    for name in GEAR_PARAMETERS:
        o[name] = val.real(name, o[name], 0.0, open_lo=name != "te_amplitude_um")
    o["bearing_damping_ratio"] = val.real("bearing_damping_ratio", o["bearing_damping_ratio"], 0.0)
    o["mesh_damping"] = val.choice("mesh_damping", o["mesh_damping"], ("in-contact", "always"))
    if o["torque_n_m"] is not None:
        o["torque_n_m"] = val.real("torque_n_m", o["torque_n_m"])
    o["stiffness"] = val.choice("stiffness", o["stiffness"], ("constant", "speed", "thermal"))
    o["sweep_step_rpm"] = val.real("sweep_step_rpm", o["sweep_step_rpm"], 0.0, open_lo=True)
    if o["sweep_speeds_rpm"] is not None:
        o["sweep_speeds_rpm"] = val.reals("sweep_speeds_rpm", o["sweep_speeds_rpm"], 0.0).tolist()
    if o["sweep_options"] is not None and not isinstance(o["sweep_options"], dict):
        raise ConfigError(f"invalid sweep_options = {o['sweep_options']!r}: a dict")
    if o["bearings"] is not None and not isinstance(o["bearings"], str):
        text = getattr(o["bearings"], "to_json", None)
        if text is None:
            raise ConfigError(
                f"invalid bearings = {o['bearings']!r}: a bearing preset name or a calibrated "
                "bearing model"
            )
        o["bearings"] = text()
    return o


def _register() -> None:
    from ..gear.pair import GearPair

    register_kind("gear", GearPair, GearModelSpec, GEAR_QUANTITIES)


_register()
