"""Seed A's thermal figures (Figs. 6, 8, 10, 11, 13) from what the paper
says, and the bearing inputs it leaves out pinned by it.

Seed A quotes no number for these figures: only trends and orderings in
words, written as bounds in ``papers/seed_a_claims.csv``. It leaves out
the housing material, the thermal network's coefficients and dimensions
(its Table 2 gives formulas only) and prints the bearing steel's
expansion coefficient as 1.36e-7 1/K, a hundred times too small for any
steel (1.36e-5 is the nearer reading; AISI 52100 is 1.25e-5).

``fit()`` pins them from the fitted claims (Figs. 8 and 10) by the
calibration for bounds of ``thermobear.diagnosis.bounds``: every option
-- the steel's expansion (both readings), the housing material (the
bearing spec's baseline and its ``housing_material:<mat>`` candidates)
and the housing-to-air conductance scale (its candidate's bounds, in
half-decade levels) -- is scored by the fitted claims it meets and by how
far it misses the others; the checked claims (Figs. 6, 11, 13) never enter.
The chosen setup is a [`CalibratedModel`][thermobear.CalibratedModel]
written to ``papers/seed_a_bearing_model.json`` with the claims' ids in
its provenance; ``seed_a_bearing_model()`` loads it::

    model = seed_a_bearing_model()
    tb.thermal_state(model, 6500.0, 2680.9, 1189.9)
    tb.GearSystem(tb.GearPair.preset("seed-electric-drive"), bearings=model,
                  stiffness="thermal")

``evaluate(quotes, quick)`` gives ours for every claim row of seed A.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from importlib import resources
from pathlib import Path
from typing import TYPE_CHECKING, Any, Optional, Sequence

import numpy as np

from ..errors import ConfigError
from .seed_a_thermal import MODEL_FILE, SUPPLY, seed_a_bearing_model

if TYPE_CHECKING:
    import polars

    from ..bearing import Bearing
    from ..diagnosis.bearing_spec import BearingModelSpec
    from ..diagnosis.bounds import OptionScore
    from ..diagnosis.calibrated import CalibratedModel, ModelKind

#: Readings of Table 1's printed expansion coefficient 1.36e-7 1/K [1/K],
#: the paper's own (its nearer reading) first, then AISI 52100's.
STEEL_EXPANSION_READINGS_PER_K = (1.36e-5, 1.25e-5)

#: Levels of the housing conductance scale per decade of its bounds.
CONDUCTANCE_LEVELS_PER_DECADE = 2


@dataclass(frozen=True)
class BearingOption:
    """One value of each input the claims choose: the steel's expansion
    coefficient [1/K], the housing material and the housing-to-air
    conductance scale [1]."""

    steel_expansion_per_k: float
    housing_material: str
    housing_conductance_scale: float

    @property
    def label(self) -> str:
        return (
            f"steel {self.steel_expansion_per_k:.3g} 1/K, {self.housing_material} housing, "
            f"housing conductance x{self.housing_conductance_scale:.3g}"
        )


def bearing_6208(steel_expansion_per_k: float) -> Bearing:
    """Seed A's 6208 (Table 1; the preset's geometry) with rings and balls
    of 52100 steel expanding ``steel_expansion_per_k`` [1/K] (the preset
    itself at 52100's own coefficient)."""
    from ..bearing import Bearing, Material

    preset = Bearing.preset("6208")
    steel = preset.ring_material
    if steel_expansion_per_k == steel.thermal_expansion_per_k:
        return preset
    if not 0.0 < steel_expansion_per_k < 1e-3:
        raise ConfigError(
            f"invalid steel_expansion_per_k = {steel_expansion_per_k!r}: a positive 1/K value"
        )
    mat = Material(
        f"{steel.name}, expansion {steel_expansion_per_k:.3g}", base=steel.name,
        thermal_expansion_per_k=steel_expansion_per_k,
    )  # fmt: skip
    g = preset.geometry
    keys = ("pitch_diameter_mm", "inner_conformity", "outer_conformity", "diametral_clearance_mm",
            "bore_mm", "outer_diameter_mm", "width_mm", "ball_diameter_mm")  # fmt: skip
    return Bearing.deep_groove(
        ball_count=int(g["ball_count"]), **{k: g[k] for k in keys}, ring_material=mat,
        ball_material=mat, name=preset.name,
    )  # fmt: skip


def base_spec(steel_expansion_per_k: float) -> BearingModelSpec:
    """The baseline model of an option: ``bearing_6208`` with the thermal
    study's oil jet (``seed_a_thermal.SUPPLY``) and the spec's defaults."""
    from ..diagnosis.bearing_spec import BearingModelSpec

    return BearingModelSpec(bearing_6208(steel_expansion_per_k), **SUPPLY)


def option_model(
    option: BearingOption, label: Optional[str] = None, provenance: Optional[dict] = None
) -> CalibratedModel:
    """The bearing model of ``option``: its baseline with the housing
    material switch and the conductance scale applied as the bearing
    spec's own candidates (held at the chosen values)."""
    from ..diagnosis.calibrated import CalibratedModel, _Step

    base = base_spec(option.steel_expansion_per_k)
    cands = {c.name: c for c in base.candidate_list()}
    steps = []
    if option.housing_material != base.options["housing_material"]:
        name = f"housing_material:{option.housing_material}"
        steps.append(_Step(name, cands[name], 1.0))
    scale = cands["housing_conductance_scale"]
    if option.housing_conductance_scale != scale.null:
        steps.append(_Step(scale.name, scale, float(option.housing_conductance_scale)))
    kind: ModelKind = "named" if steps else "nothing"
    return CalibratedModel(
        kind, label or option.label, base, steps, [], np.zeros((0, 0)), provenance=provenance
    )


def conductance_levels(lower: float, upper: float, per_decade: int) -> list[float]:
    """Log-spaced levels from ``lower`` to ``upper`` (both kept),
    ``per_decade`` per decade."""
    n = int(round(math.log10(upper / lower) * per_decade))
    return [float(x) for x in np.logspace(math.log10(lower), math.log10(upper), n + 1)]


def bearing_options(quick: bool = False) -> list[BearingOption]:
    """Every option the claims choose among: each steel reading, the
    baseline's housing and each ``housing_material:<mat>`` candidate, the
    conductance scale's levels over its candidate bounds (half-decades;
    whole decades when ``quick``), in order of preference."""
    base = base_spec(STEEL_EXPANSION_READINGS_PER_K[0])
    cands = base.candidate_list()
    housings = [base.options["housing_material"]] + [
        c.name.split(":", 1)[1] for c in cands if c.name.startswith("housing_material:")
    ]
    scale = next(c for c in cands if c.name == "housing_conductance_scale")
    per_decade = 1 if quick else CONDUCTANCE_LEVELS_PER_DECADE
    levels = conductance_levels(scale.lower, scale.upper, per_decade)
    levels.sort(key=lambda s: (abs(math.log10(s / scale.null)), s))  # nearest the null first
    return [
        BearingOption(a, h, s) for a in STEEL_EXPANSION_READINGS_PER_K for h in housings
        for s in levels
    ]  # fmt: skip


def claim_rows(quotes: Any, role: Optional[str] = None) -> list[dict]:
    """Seed A's claim rows of ``quotes`` (of ``role`` when given)."""
    import polars as pl

    q = quotes.filter(pl.col("seed") == "A")
    if "kind" in q.columns:
        q = q.filter(pl.col("kind") == "claim")
    else:
        q = q.filter(pl.col("read").str.starts_with("text (in words)"))
    if role is not None:
        q = q.filter(pl.col("role") == role)
    return list(q.iter_rows(named=True))


def claim_values(model: Any, rows: Sequence[dict]) -> dict[str, float]:
    """Ours for each claim row under a bearing ``model``: id -> value."""
    from .seed_a_claim_values import ClaimPoints, claim_value

    points = ClaimPoints(model)
    return {r["id"]: claim_value(points, r) for r in rows}


def _claims(rows: Sequence[dict]) -> list:
    from ..diagnosis.bounds import Claim
    from .paper_numbers import tolerance_abs

    return [
        Claim(
            r["id"], r["comparison"], float(r["value"]),
            tolerance_abs(r["tolerance"], r["value"]), float(r["precision"]),
        )
        for r in rows
    ]  # fmt: skip


def choose_bearing(quotes: Any = None, quick: bool = False) -> tuple[BearingOption, list]:
    """The option the fitted claims choose and every option's score
    (``thermobear.diagnosis.bounds``); only the fitted rows of ``quotes``
    (default: seed A's claims) are read."""
    from ..diagnosis.bounds import choose, score_option
    from .paper_numbers import quotes as read_quotes

    rows = claim_rows(read_quotes("A", kind="claim") if quotes is None else quotes, "fitted")
    if not rows:
        raise ConfigError("invalid quotes: no fitted claim of seed A")
    claims = _claims(rows)
    options = bearing_options(quick)
    scores = [score_option(o.label, claims, claim_values(option_model(o), rows)) for o in options]
    best = choose(scores, [o.label for o in options])
    return next(o for o in options if o.label == best.label), scores


def _provenance(rows: list[dict], checked: list[str], scores: list, chosen: OptionScore) -> dict:
    import polars as pl

    from ..diagnosis.bounds import best_group, score_table
    from ..diagnosis.calibrated import provenance

    tied = [s.label for s in best_group(scores)]
    verdict = (
        f"chosen among {len(scores)} options by {len(rows)} fitted claims: {chosen.count} met, "
        f"{chosen.shortfall_precisions:.1f} reading precisions short on the others; "
        f"{len(tied)} option(s) the claims cannot tell apart, the first in the order of "
        "preference taken"
    )
    frame = pl.DataFrame(rows).select("id", "quantity", "relation", "reference", "comparison",
                                      "value", "tolerance", "precision")  # fmt: skip
    prov = provenance([r["id"] for r in rows], [frame], verdict)
    table = score_table(scores, chosen)
    return prov | {"held_out": checked, "options": table.to_dicts(), "tied": tied}


def fit(quick: bool = False, write: bool = True, out_dir: Optional[Path] = None) -> CalibratedModel:
    """Redo the choice from the fitted claims and (``write``) write
    ``seed_a_bearing_model.json`` into ``out_dir`` (default: the package's
    ``papers`` folder, the shipped file); returns the model."""
    from .paper_numbers import quotes as read_quotes

    q = read_quotes("A", kind="claim")
    option, scores = choose_bearing(q, quick)
    chosen = next(s for s in scores if s.label == option.label)
    rows = claim_rows(q, "fitted")
    checked = [r["id"] for r in claim_rows(q, "checked")]
    label = f"seed A 6208, chosen by its claims: {option.label}"
    model = option_model(option, label, _provenance(rows, checked, scores, chosen))
    if write:
        shipped = Path(str(resources.files("thermobear.studies.papers")))
        model.save((shipped if out_dir is None else Path(out_dir)) / MODEL_FILE)
    return model


def evaluate(quotes: Any, quick: bool = False) -> polars.DataFrame:
    """Ours for every claim row of seed A in ``quotes`` (the number rows are
    the gear study's) under the shipped bearing model: ``id``, ``ours``,
    ``lower``, ``upper`` (NaN: a choice among options carries no band) and
    ``basis``. The same in ``quick`` (the points are few and fast)."""
    import polars as pl

    from .seed_a_claim_values import basis_of

    rows = claim_rows(quotes)
    ours = claim_values(seed_a_bearing_model(), rows)
    return pl.DataFrame(
        {
            "id": [r["id"] for r in rows],
            "ours": [float(ours[r["id"]]) for r in rows],
            "lower": [math.nan] * len(rows),
            "upper": [math.nan] * len(rows),
            "basis": [basis_of(r) for r in rows],
        },
        schema={"id": pl.Utf8, "ours": pl.Float64, "lower": pl.Float64, "upper": pl.Float64,
                "basis": pl.Utf8},
    )  # fmt: skip
