"""Candidates: what could explain a gap between a baseline and the
measurements -- an effect the baseline leaves out, a miscalibrated input,
a sensor offset on the measurement side. :class:`Candidate` records, the
bearing's candidate list and the candidate table (:func:`candidates`)."""

from __future__ import annotations

from dataclasses import dataclass
from typing import Optional, Sequence

import numpy as np

from ..errors import ConfigError
from .measurements import QUANTITIES
from .protocol import ModelSpec
from .registry import _HOUSING_MATERIALS, _PARAMETERS, _THERMAL_DEFAULTS, NOT_IN_BEARING


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


def _candidate_list(model: Optional[ModelSpec], quantities: Sequence[str] = ()) -> list[Candidate]:
    from .. import _native

    base_eff = set(model.effects) if model is not None else set()
    opts = model.options if model is not None else _THERMAL_DEFAULTS
    temps = tuple(q for q in QUANTITIES if q.startswith("temperature_c"))
    mech = tuple(q for q in QUANTITIES if not q.startswith("temperature_c"))
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
    for name, opt, unit, lo, hi, is_off, role, desc in _PARAMETERS:
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
    for mat in _HOUSING_MATERIALS:
        if mat != str(opts["housing_material"]):
            name = f"housing_material:{mat}"
            out.append(
                Candidate(
                    name,
                    "switch",
                    "model",
                    "housing_is_" + mat.replace("-", "_"),
                    "1",
                    0.0,
                    1.0,
                    0.0,
                    f"housing conductance/expansion of {mat}",
                    temps + mech,
                    option="housing_material",
                    role="calibration",
                )
            )
    out += sensor_offset_candidates(quantities, QUANTITIES)
    return out


def sensor_offset_candidates(quantities: Sequence[str], table: dict) -> list:
    """The measurement-side decoys: a constant offset per measured quantity
    (+-10 typical sigma, or +-20 % for relative quantities); ``table`` maps a
    quantity to its registry row (typical sigma at [3], relative flag at [4])."""
    out = []
    for q in quantities:
        typ, rel = table[q][3], table[q][4]
        unit = "K" if q.startswith("temperature_c") else q.rsplit("_", 1)[-1]
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
) -> "polars.DataFrame":  # noqa: F821
    """The candidate registry against a baseline: ``name``, ``kind``
    ("switch" or "parameter"), ``role`` ("effect": a physical term the
    baseline leaves out; "calibration": a baseline input whose value may be
    off; "measurement": a sensor-offset decoy, one per measured quantity in
    ``quantities``), ``side`` ("model" or "measurement"), ``parameter``,
    ``unit``, ``lower``, ``upper`` (physical bounds), ``default`` (the null
    value: the baseline's), ``description``, ``affects``. Without ``model``
    the baseline is the default :func:`thermobear.thermal_state` options
    with no effect switched on (every effect is listed)."""
    import polars as pl

    table = QUANTITIES if model is None else model.quantities
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


def candidate_pool(model: ModelSpec, quantity: np.ndarray, names: Optional[Sequence[str]]) -> list:
    """The candidates to screen against ``model``: its candidate list with
    a sensor-offset decoy per measured quantity (``quantity``: the quantity
    of each measured row), restricted to ``names`` when given (every name
    must be a known candidate)."""
    pool = model.candidate_list(sorted(set(quantity.tolist())))
    if names is None:
        return pool
    known = {c.name for c in pool}
    for n in names:
        if n not in known:
            raise ConfigError(f"invalid candidate = {n!r}: known: {', '.join(sorted(known))}")
    return [c for c in pool if c.name in set(names)]


def split_evaluable(pool: list) -> tuple[list, list[str]]:
    """(the candidates the model can evaluate, the names of those that act
    only outside it: spindle or rotor effects against a single bearing)."""
    outside = [c.name for c in pool if c.affects == (NOT_IN_BEARING,)]
    return [c for c in pool if c.name not in outside], outside
