"""Candidates: what could explain a gap between a baseline and the
measurements -- an effect the baseline leaves out, a miscalibrated input,
a sensor offset on the measurement side. ``Candidate`` records, the
bearing's candidate list and the candidate table
([`candidates`][thermobear.diagnosis.candidates.candidates])."""

from __future__ import annotations

from dataclasses import dataclass
from typing import TYPE_CHECKING, Any, Optional, Protocol, Sequence

import numpy as np
from numpy.typing import ArrayLike

from ..errors import ConfigError
from .measurements import QUANTITIES
from .protocol import ModelSpec, as_spec
from .registry import (
    _HOUSING_MATERIALS,
    _PARAMETERS,
    _THERMAL_DEFAULTS,
    FLOW_KEYWORDS,
    HEAT_MODELS,
    LOAD_SCALE_BOUNDS,
    NOT_IN_BEARING,
    SKF_PARAMETERS,
    SUPPLY_PARAMETERS,
)

if TYPE_CHECKING:
    import polars


class _BearingBaseline(Protocol):
    """What the candidate list reads of a bearing baseline (a
    ``BearingModelSpec``; named structurally so this module, which the spec
    imports, does not import it back)."""

    effects: tuple[str, ...]
    options: dict[str, Any]
    bearing: Any


@dataclass(frozen=True)
class Candidate:
    name: str
    kind: str  # "switch" | "parameter"
    side: str  # "model" | "measurement"
    parameter: str
    unit: str
    lower: float
    upper: float
    null: float
    description: str
    affects: tuple[str, ...]
    option: str = ""
    offset: bool = False
    quantity: str = ""
    effect: str = ""
    #: "effect" (a physical term the baseline leaves out), "calibration" (a
    #: baseline input whose value may be off) or "measurement" (a decoy on
    #: the measurement side)
    role: str = "effect"
    relative: bool = False  # measurement offsets: relative (x (1 + v)) or additive


def _candidate_list(
    model: Optional[_BearingBaseline], quantities: Sequence[str] = ()
) -> list[Candidate]:
    from .. import _native

    base_eff = set(model.effects) if model is not None else set()
    opts = model.options if model is not None else _THERMAL_DEFAULTS
    temps = tuple(q for q in QUANTITIES if q.endswith("temperature_c"))
    mech = tuple(q for q in QUANTITIES if not q.endswith("temperature_c"))
    out = []
    for name, desc, models in _native.effects():
        if name in base_eff:
            continue
        affects = tuple(QUANTITIES) if "bearing" in models else (NOT_IN_BEARING,)
        out.append(
            Candidate(
                name,
                "switch",
                "model",
                f"{name}_on",
                "1",
                0.0,
                1.0,
                0.0,
                desc,
                affects,
                effect=name,
            )
        )
    lub_bounds = _lubrication_bounds(model)
    for name, opt, unit, lo, hi, is_off, role, desc in _PARAMETERS:
        lo, hi = lub_bounds.get(opt, (lo, hi))
        if opts[opt] is None:  # the fixed drag fraction under an oil supply
            continue
        base = float(opts[opt])
        if is_off:
            null, lo_, hi_ = 0.0, lo, hi
        else:
            null, lo_, hi_ = base, min(lo, base), max(hi, base)
        out.append(
            Candidate(
                name,
                "parameter",
                "model",
                f"{name}" if is_off else f"{opt}",
                unit,
                lo_,
                hi_,
                null,
                desc,
                tuple(QUANTITIES),
                option=opt,
                offset=is_off,
                role=role,
            )
        )
    out += _housing_candidates(str(opts["housing_material"]), temps + mech)
    out += heat_model_candidates(opts, tuple(QUANTITIES))
    out += supply_candidates(opts, tuple(QUANTITIES))
    out += sensor_offset_candidates(quantities, QUANTITIES)
    out += sensor_gain_candidates(quantities, QUANTITIES)
    return out


def _housing_candidates(baseline_material: str, affects: tuple) -> list[Candidate]:
    """The other housing materials as switches (a baseline input)."""
    return [
        Candidate(
            f"housing_material:{mat}",
            "switch",
            "model",
            "housing_is_" + mat.replace("-", "_"),
            "1",
            0.0,
            1.0,
            0.0,
            f"housing conductance/expansion of {mat}",
            affects,
            option="housing_material",
            role="calibration",
        )
        for mat in _HOUSING_MATERIALS
        if mat != baseline_material
    ]


def supply_candidates(opts: dict, affects: tuple) -> list[Candidate]:
    """The oil-supply inputs (``SUPPLY_PARAMETERS``: flow scale, speed
    exponent of the cavity fraction) when the baseline states a jet,
    oil-air or oil-mist flow (``FLOW_KEYWORDS``); none otherwise. The null
    is the baseline's value (default 1, Parker's correlation as published)."""
    if all(opts.get(k) is None for k in FLOW_KEYWORDS):
        return []
    return [
        _calibration_candidate(
            opt, unit, lo, hi, default if opts.get(opt) is None else float(opts[opt]), desc, affects
        )
        for opt, unit, lo, hi, default, desc in SUPPLY_PARAMETERS
    ]


def _calibration_candidate(
    opt: str, unit: str, lo: float, hi: float, null: float, desc: str, affects: tuple
) -> Candidate:
    """A model option calibrated within ``[lo, hi]`` (widened to hold its
    null, the baseline's value)."""
    return Candidate(
        opt,
        "parameter",
        "model",
        opt,
        unit,
        min(lo, null),
        max(hi, null),
        null,
        desc,
        affects,
        option=opt,
        role="calibration",
    )  # fmt: skip


def _lubrication_bounds(model: Optional[_BearingBaseline]) -> dict:
    """f0 and drag oil-fraction bounds of the baseline's lubrication method
    (none without one): option -> (lower, upper)."""
    from .. import _native

    if model is None:
        return {}
    lub = model.options.get("lubrication")
    if lub is None:
        return {}
    d = _native.lubrication_defaults(str(lub), model.bearing.bearing_type.replace("-", "_"))
    return {
        "lubrication_factor_f0": tuple(d["f0_bounds"]),
        "churning_oil_fraction": tuple(d["oil_fraction_bounds"]),
    }


def heat_model_candidates(opts: dict, affects: tuple, skf_inputs: bool = True) -> list[Candidate]:
    """The other heat models (docs/concepts/physics.md §9) as switches
    (role "effect": a heat model the baseline leaves out) and, when the
    baseline uses the SKF-style model, its calibratable inputs (mu_EHL,
    K_rs; bounds and sources in ``SKF_PARAMETERS``) unless
    ``skf_inputs`` is false (a model without those options)."""
    base = str(opts.get("heat_model", "palmgren"))
    out = [
        Candidate(
            f"heat_model:{hm}",
            "switch",
            "model",
            f"heat_model_is_{hm}",
            "1",
            0.0,
            1.0,
            0.0,
            desc,
            affects,
            option="heat_model",
            role="effect",
        )  # fmt: skip
        for hm, desc in HEAT_MODELS.items()
        if hm != base
    ]
    if base == "skf" and skf_inputs:
        for opt, unit, lo, hi, desc in SKF_PARAMETERS:
            out.append(
                _calibration_candidate(opt, unit, lo, hi, _skf_null(opts, opt), desc, affects)
            )
    return out


def _skf_null(opts: dict, opt: str) -> float:
    """The baseline's value of an SKF input (its default when not set)."""
    from .. import _native

    if opts.get(opt) is not None:
        return float(opts[opt])
    if opt == "sliding_friction_ehl":
        return float(_native.skf_sliding_friction_ehl(str(opts.get("lubricant", "e-drive ATF"))))
    d = _native.lubrication_defaults(str(opts.get("lubrication") or "oil-air"), "angular_contact")
    return float(d["replenishment_krs"])


#: Sensor gain bounds (relative): thermocouples +-2 % of the reading in C
#: (IEC 60584-1 class 2 allows 0.75 % of the reading; an uncalibrated
#: acquisition chain's gain adds about as much again -- our assumption);
#: other absolute quantities (displacement probes, contact angles) +-10 %
#: (a non-contact probe's sensitivity depends on the target material and
#: is off by 5-10 % unless calibrated on it).
SENSOR_GAIN_BOUNDS = {"temperature": 0.02, "other": 0.10}


def sensor_gain_candidates(quantities: Sequence[str], table: dict) -> list:
    """The measurement-side gain errors: the reading times (1 + g), one
    per measured quantity (sensor) whose uncertainty is absolute (for
    relative-sigma quantities the relative ``sensor_offset`` already is a
    gain). Bounds: ``SENSOR_GAIN_BOUNDS``."""
    out = []
    for q in quantities:
        if table[q][4]:
            continue
        b = SENSOR_GAIN_BOUNDS["temperature" if q.endswith("temperature_c") else "other"]
        out.append(
            Candidate(
                f"sensor_gain:{q}",
                "parameter",
                "measurement",
                "relative_gain",
                "1",
                -b,
                b,
                0.0,
                f"sensor gain error on {q}",
                (q,),
                offset=True,
                quantity=q,
                role="measurement",
                relative=True,
            )  # fmt: skip
        )
    return out


def load_level_candidates(
    option: str, levels: ArrayLike, quantities: tuple, what: str, min_levels: int = 2
) -> list[Candidate]:
    """One load-scale candidate per non-zero load level
    (``{option}@{level:g}``, bounds ``LOAD_SCALE_BOUNDS``, null 1) when
    there are ``min_levels`` or more: a load cell or preload setting off at
    one level only (with one level it is the global scale)."""
    lv = sorted({float(v) for v in np.ravel(levels) if float(v) != 0.0})
    if len(lv) < min_levels:
        return []
    lo, hi = LOAD_SCALE_BOUNDS
    return [
        Candidate(
            f"{option}@{v:g}",
            "parameter",
            "model",
            f"{option}@{v:g}",
            "1",
            lo,
            hi,
            1.0,
            f"{what} of the {v:g} N level differs from the stated one by a factor",
            quantities,
            option=f"{option}@{v:g}",
            role="calibration",
        )  # fmt: skip
        for v in lv
    ]


def sensor_offset_candidates(quantities: Sequence[str], table: dict) -> list:
    """The measurement-side decoys: a constant offset per measured quantity
    (+-10 typical sigma, or +-20 % for relative quantities); ``table`` maps a
    quantity to its registry row (typical sigma at [3], relative flag at [4])."""
    out = []
    for q in quantities:
        typ, rel = table[q][3], table[q][4]
        unit = "K" if q.endswith("temperature_c") else q.rsplit("_", 1)[-1]
        bound = 10.0 * typ if not rel else 0.2
        out.append(
            Candidate(
                f"sensor_offset:{q}",
                "parameter",
                "measurement",
                "offset" if not rel else "relative_offset",
                "1" if rel else unit,
                -bound,
                bound,
                0.0,
                f"decoy: constant sensor offset on {q}",
                (q,),
                offset=True,
                quantity=q,
                role="measurement",
                relative=bool(rel),
            )
        )
    return out


def candidates(
    model: Optional[ModelSpec] = None, quantities: Sequence[str] = ()
) -> polars.DataFrame:
    """The candidate registry against a baseline: ``name``, ``kind``
    ("switch" or "parameter"), ``role`` ("effect": a physical term the
    baseline leaves out; "calibration": a baseline input whose value may be
    off; "measurement": a sensor-offset decoy, one per measured quantity in
    ``quantities``), ``side`` ("model" or "measurement"), ``parameter``,
    ``unit``, ``lower``, ``upper`` (physical bounds), ``default`` (the null
    value: the baseline's), ``description``, ``affects``. ``model``: a
    model spec (bearing or spindle), or a [`Bearing`][thermobear.Bearing] or
    [`Spindle`][thermobear.Spindle] taken as configured. Without ``model``
    the baseline is a bearing with the default
    [`thermobear.thermal_state`][thermobear.thermal_state] options and no effect switched on
    (every effect is listed)."""
    import polars as pl

    from .. import _validate as val

    model = None if model is None else as_spec(model)
    table = QUANTITIES if model is None else model.quantities
    quantities = val.names("quantities", quantities, one=True)
    for q in quantities:
        if q not in table:
            raise ConfigError(f"invalid quantity = {q!r}: known: {', '.join(table)}")
    cs = _candidate_list(None, quantities) if model is None else model.candidate_list(quantities)
    return pl.DataFrame(
        {
            "name": [c.name for c in cs],
            "kind": [c.kind for c in cs],
            "role": [c.role for c in cs],
            "side": [c.side for c in cs],
            "parameter": [c.parameter for c in cs],
            "unit": [c.unit for c in cs],
            "lower": [c.lower for c in cs],
            "upper": [c.upper for c in cs],
            "default": [c.null for c in cs],
            "description": [c.description for c in cs],
            "affects": [", ".join(c.affects) for c in cs],
        }
    )


def candidate_pool(
    model: ModelSpec,
    quantity: np.ndarray,
    names: Optional[Sequence[str]],
    conditions: Any = None,
) -> list:
    """The candidates to screen against ``model``: its candidate list with
    a sensor-offset decoy per measured quantity (``quantity``: the quantity
    of each measured row), restricted to ``names`` when given (every name
    must be a known candidate). With the measured ``conditions`` (a frame
    with ``axial_n`` / ``radial_n``) and a model that has
    ``level_candidates(conditions)``, one load-scale candidate per load
    level is added."""
    pool = model.candidate_list(sorted(set(quantity.tolist())))
    if hasattr(model, "level_candidates"):
        pool += model.level_candidates(*_levels(conditions, names))
    if names is None:
        return pool
    known = {c.name for c in pool}
    for n in names:
        if n not in known:
            from .._validate import did_you_mean

            raise ConfigError(
                f"invalid candidate = {n!r}: known: {', '.join(sorted(known))}"
                + did_you_mean(n, sorted(known))
            )
    return [c for c in pool if c.name in set(names)]


def _levels(conditions: Any, names: Optional[Sequence[str]]) -> tuple[Any, int]:
    """The load levels to build per-level candidates for and the fewest
    levels that make them: the measured ``conditions`` (two or more levels),
    else the levels named in ``names`` (``<option>@<N>``; any number)."""
    import polars as pl

    if conditions is not None:
        return conditions, 2
    ax, ra = [0.0], [0.0]
    for n in names or ():
        opt, _, level = str(n).partition("@")
        if level and opt in ("axial_load_scale", "preload_scale"):
            ax.append(float(level))
        elif level and opt == "radial_load_scale":
            ra.append(float(level))
    rows = max(len(ax), len(ra))
    return pl.DataFrame(
        {"axial_n": ax + [0.0] * (rows - len(ax)), "radial_n": ra + [0.0] * (rows - len(ra))}
    ), 1


def split_evaluable(pool: list) -> tuple[list, list[str]]:
    """(the candidates the model can evaluate, the names of those that act
    only outside it: spindle or rotor effects against a single bearing)."""
    outside = [c.name for c in pool if c.affects == (NOT_IN_BEARING,)]
    return [c for c in pool if c.name not in outside], outside
