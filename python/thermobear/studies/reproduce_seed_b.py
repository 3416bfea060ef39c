"""Seed B reproduced from its own numbers: the inputs its text leaves out
pinned by the numbers it quotes, with thermobear's calibration, and every
other quoted number predicted with its 95 % band.

Seed B's spindle and bearing tables are lost from its text, so the spindle
preset carries assumptions. The rows of ``papers/seed_b_quotes.csv`` with
``role`` "fitted" pin them, stage by stage (``STAGES``, each one
[`thermobear.calibrate`][thermobear.calibrate] of up to four inputs on the
data sets of the settings its rows hold at; two rounds, each stage at the
others' latest values):

1. the ball size (``ball_diameter_scale``) from Fig. 14a's excess of the
   outer over the inner contact load, 14.15 N at 18,000 rpm and 500 N --
   the balls' centrifugal force, so their mass (the outer load itself,
   104.35 N, also depends on the ball count, which the lost table would
   state: it is checked, not fitted);
2. the heat and the shaft length between the sets
   (``lubrication_factor_f0``, ``load_friction_scale``,
   ``motor_loss_scale``, ``span_scale``) together from Fig. 5's ball,
   inner and outer ring at 18,000 rpm and 400 N (64.8 / 49.8 / 38.9 C),
   Fig. 6's ball at 500 N (74.2 C) and Fig. 17's axial growth at the same
   18,000 rpm (35.38 um): the viscous heat sets the level, the load
   friction (a factor on Palmgren's f1) the rise with preload, and the
   growth is the shaft's temperature over its length, so the four are
   pinned jointly (fitted one after the other they trade along the
   growth). Fig. 17's 12,000 rpm growth (17.92 um) is a prediction: from
   the room temperature no heat balance halves the growth between 18,000
   and 12,000 rpm as seed B's does, so the two growths together would pin
   a shape, not a length;
3. the preload spring (``spring_rate_n_per_um``) from Fig. 17's
   compensation preload at 18,000 rpm (12.74 N, beside its growth);
4. the working radial load at the nose (``radial_load_n``) from Fig. 15b's
   radial displacement without thermal displacement, "about 2 um" above
   460 N at 12,000 rpm;
5. the rotor's unbalance (``unbalance_g_mm``) from Fig. 20a's 1X velocity
   amplitude, 7.53 mm/s at 12,000 rpm.

The calibrated values, with the stages' covariances side by side, make one
[`CalibratedModel`][thermobear.CalibratedModel] per setting (``SETTINGS``
of ``seed_b_numbers``: Si3N4 or steel balls, with or without the thermal
displacement, with or without the nose load), shipped as JSON in
``thermobear.studies.papers`` (``MODEL_FILES``), with the band of every
row (``BANDS_FILE``): the delta method of
[`thermobear.predict`][thermobear.predict.band.predict] at 95 %.

Get the fitted spindle in one line::

    model = thermobear.studies.reproduce_seed_b.fitted_spindle()

(a calibrated model: ``thermobear.vibration``, ``thermobear.transient`` and
``thermobear.predict`` take it in place of the spindle; ``model.model()[0]``
is the configured [`Spindle`][thermobear.Spindle]).
[`fit`][thermobear.studies.reproduce_seed_b.fit] redoes every calibration
(minutes); [`evaluate`][thermobear.studies.reproduce_seed_b.evaluate] reads
the shipped models and computes ours for every row in seconds.
"""

from __future__ import annotations

import functools
import time
from dataclasses import dataclass
from pathlib import Path
from typing import TYPE_CHECKING, Any, Mapping, Optional, Sequence

import numpy as np

from ..errors import ConfigError
from .seed_b_numbers import SETTINGS, SeedBNumbers, setting_label, spec_quantity

if TYPE_CHECKING:
    import polars

#: The package holding the shipped models and bands.
PAPERS = "thermobear.studies.papers"

#: The shipped model of each setting (``seed_b_numbers.SETTINGS``).
MODEL_FILES: dict[str, str] = {
    "ceramic": "seed_b_spindle_model.json",
    "ceramic uncoupled": "seed_b_spindle_uncoupled_model.json",
    "ceramic loaded": "seed_b_spindle_loaded_model.json",
    "ceramic loaded uncoupled": "seed_b_spindle_loaded_uncoupled_model.json",
    "steel": "seed_b_steel_spindle_model.json",
}

#: The band table: ``id``, ``ours``, ``lower``, ``upper``, ``basis``, one
#: row per quoted number, at the shipped models' estimates.
BANDS_FILE = "seed_b_bands.csv"

#: The probability of the bands.
LEVEL = 0.95

#: The oil-air supply of seed B's test (5 mL/h of oil; the air flow is not
#: stated). The spindle keeps the preset's constant-force spring preload,
#: 400 N, its rate calibrated.
SUPPLY: dict[str, Any] = {"oil_volume_cm3_per_h": 5.0}

#: Each unstated input declared in the baseline, at the preset's value
#: (the null of its candidate): the factors 1, f0 1 (the preset's), the
#: nose load the earlier study assumed (500 N), an unbalance of 5 g mm
#: (about ISO G2.5 on this rotor).
NULLS: dict[str, float] = {
    "ball_diameter_scale": 1.0,
    "span_scale": 1.0,
    "motor_loss_scale": 1.0,
    "lubrication_factor_f0": 1.0,
    "load_friction_scale": 1.0,
    "unbalance_g_mm": 5.0,
}
NOSE_LOAD_NULL_N = 500.0


@dataclass(frozen=True)
class Stage:
    """One calibration: its ``parameters`` (candidate names) and the
    fitted ``rows`` (quote ids) that pin them."""

    name: str
    parameters: tuple[str, ...]
    rows: tuple[str, ...]


STAGES: tuple[Stage, ...] = (
    Stage("ball size", ("ball_diameter_scale",), ("B14-outer-inner",)),
    Stage(
        "heat and shaft length",
        ("lubrication_factor_f0", "load_friction_scale", "motor_loss_scale", "span_scale"),
        ("B05-ball", "B05-inner", "B05-outer", "B06-ball-500", "B17-growth-18000"),
    ),
    Stage("spring", ("spring_rate_n_per_um",), ("B17-comp-18000",)),
    Stage("nose load", ("radial_load_n",), ("B15-flat",)),
    Stage("unbalance", ("unbalance_g_mm",), ("B20-a1",)),
)

#: Rounds over the stages (each stage at the others' latest values).
ROUNDS = 2


# -- the baseline -------------------------------------------------------------


def baseline_spindle(variant: str = "ceramic") -> Any:
    """The seed B spindle as the text states it: hybrid (``"ceramic"``) or
    steel 7009C/7008C pairs, spring preload 400 N, oil-air 5 mL/h."""
    from ..spindle import Spindle

    if variant not in ("ceramic", "steel"):
        raise ConfigError(f"invalid variant = {variant!r}: 'ceramic' or 'steel'")
    sp = Spindle.preset(f"seed-{variant}-spindle")
    return sp.with_options(preload_kind="spring", **SUPPLY)


def baseline_spec(setting: str, values: Optional[Mapping[str, float]] = None) -> Any:
    """The spindle model spec of ``setting`` with every unstated input
    declared (at the preset's value, or at ``values``) -- the nose load
    only where the setting carries it."""
    from ..diagnosis.spindle_spec import THERMAL_DISPLACEMENT_EFFECTS, SpindleModelSpec

    s = _setting(setting)
    sp = baseline_spindle(s.variant)
    effects = [e for e in sp._native.effects if s.coupled or e not in THERMAL_DISPLACEMENT_EFFECTS]
    declared: dict[str, Any] = dict(NULLS)
    if s.loaded:
        declared["radial_load_n"] = NOSE_LOAD_NULL_N
    spec = SpindleModelSpec(sp, effects=effects, **declared)
    own: dict[str, Any] = {k: float(v) for k, v in (values or {}).items() if k in spec.options}
    if not s.loaded:
        own.pop("radial_load_n", None)
    return spec.with_setting(**own) if own else spec


def _setting(label: str) -> Any:
    if label not in SETTINGS:
        raise ConfigError(f"invalid setting = {label!r}: one of {', '.join(SETTINGS)}")
    return SETTINGS[label]


# -- the fitted rows as measurements ------------------------------------------


def _quotes() -> Any:
    from .paper_numbers import quotes

    return quotes("B")


def fitted_rows(q: Any, ids: Sequence[str]) -> Any:
    """The rows ``ids`` of the quotes ``q``; each must be a fitted row (a
    checked row never enters a fit: ``ConfigError`` naming it)."""
    import polars as pl

    rows = q.filter(pl.col("id").is_in(list(ids)))
    missing = sorted(set(ids) - set(rows["id"].to_list()))
    if missing:
        raise ConfigError(f"invalid stage rows: {missing} not among the quotes")
    held = rows.filter(pl.col("role") != "fitted")["id"].to_list()
    if held:
        raise ConfigError(f"invalid stage rows: {held} are checked rows; only fitted rows pin")
    return rows


#: Differences the spindle model has as a quantity of its own: (quantity,
#: reference) -> model quantity.
DIFFERENCE_QUANTITIES = {
    ("outer_load_max_n", "quantity=inner_load_max_n"): "outer_inner_load_difference_n",
}


def measurements(rows: Any) -> dict[str, Any]:
    """The rows as measured tables per setting (``speed_rpm``,
    ``preload_n``, ``quantity``, ``value``, ``sigma``, ``run`` = the row's
    id): a value, or a difference the model has as a quantity (the outer
    minus the inner contact load). Sigma: the reading precision
    (``paper_numbers.sigma_of``)."""
    import polars as pl

    from .paper_numbers import sigma_of

    out: dict[str, list] = {}
    for r in rows.iter_rows(named=True):
        label = setting_label(r)
        q, factor = spec_quantity(r)
        value, sigma = float(r["value"]), sigma_of(r["precision"])
        if r["relation"] == "difference":
            q = DIFFERENCE_QUANTITIES.get((q, str(r["reference"])), "")
        if not q or r["comparison"] != "=" or r["relation"] not in ("value", "difference"):
            raise ConfigError(
                f"invalid fitted row {r['id']!r}: a value, or a difference the model has as a "
                "quantity (DIFFERENCE_QUANTITIES)"
            )
        out.setdefault(label, []).append(
            (float(r["speed_rpm"]), float(r["preload_n"]), q, value / factor, sigma / factor,
             str(r["id"]))
        )  # fmt: skip
    cols = ["speed_rpm", "preload_n", "quantity", "value", "sigma", "run"]
    return {k: pl.DataFrame(v, schema=cols, orient="row") for k, v in out.items()}


def restated_rows(q: Any, fitted: Sequence[str]) -> list[str]:
    """The difference rows whose both ends are fitted values (the text's
    own difference of two fitted numbers: no prediction)."""
    vals = {
        (r["quantity"], r["speed_rpm"], r["preload_n"], setting_label(r))
        for r in q.iter_rows(named=True)
        if r["id"] in set(fitted) and r["relation"] == "value"
    }
    out = []
    for r in q.iter_rows(named=True):
        if r["relation"] != "difference":
            continue
        key, _, v = str(r["reference"]).partition("=")
        end = dict(r)
        end[key] = v if key in ("quantity", "coupling") else float(v)
        this = (r["quantity"], r["speed_rpm"], r["preload_n"], setting_label(r))
        other = (end["quantity"], end["speed_rpm"], end["preload_n"], setting_label(end))
        if this in vals and other in vals:
            out.append(str(r["id"]))
    return out


def pinning_rows(q: Optional[Any] = None) -> list[str]:
    """Every row the fit reads or restates: the stages' rows and the
    differences of two of them."""
    q = _quotes() if q is None else q
    staged = list(dict.fromkeys(i for st in STAGES for i in st.rows))
    return staged + [i for i in restated_rows(q, staged) if i not in staged]


# -- the calibration ------------------------------------------------------------


def calibrate_stage(stage: Stage, q: Any, values: Mapping[str, float]) -> Any:
    """One stage: [`thermobear.calibrate`][thermobear.calibrate] of its
    parameters on its fitted rows, every other input at ``values``; the
    data sets are the settings its rows hold at."""
    from ..diagnosis import calibrate

    data = measurements(fitted_rows(q, stage.rows))
    sets = {label: (baseline_spec(label, values), m) for label, m in data.items()}
    return calibrate(sets, list(stage.parameters))


def _stage_values(cal: Any) -> dict[str, float]:
    return {r["name"]: float(r["value"]) for r in cal.parameters.iter_rows(named=True)}


def fit_stages(
    q: Optional[Any] = None, rounds: int = ROUNDS, progress: Any = None
) -> tuple[dict[str, float], list[tuple[Stage, Any]]]:
    """Every stage, ``rounds`` times: (the calibrated values, the last
    round's calibration of each stage)."""
    q = _quotes() if q is None else q
    values: dict[str, float] = {}
    last: list[tuple[Stage, Any]] = []
    for k in range(rounds):
        last = []
        for stage in STAGES:
            cal = calibrate_stage(stage, q, values)
            values.update(_stage_values(cal))
            last.append((stage, cal))
            if progress is not None:
                progress(k, stage, cal)
    return values, last


def combined_models(stages: Sequence[tuple[Stage, Any]], q: Any) -> dict[str, Any]:
    """One calibrated model per setting: every stage's values (in stage
    order), their covariances side by side (each stage's own, at the
    others' values), the profile intervals; provenance names the fitted
    rows."""
    from ..diagnosis.calibrated import CalibratedModel, _Step, provenance

    names, values, profile, blocks = [], [], [], []
    for _, cal in stages:
        for r in cal.parameters.iter_rows(named=True):
            names.append(str(r["name"]))
            values.append(float(r["value"]))
            profile.append((float(r["lower_95"]), float(r["upper_95"])))
        blocks.append(_stage_covariance(cal))
    cov = _block_diagonal(blocks)
    tables = [d.drop("run") for _, cal in stages for d in [cal.points]]
    prov = provenance([st.name for st, _ in stages], tables, "staged calibration")
    prov["quotes"] = pinning_rows(q)
    prov["stages"] = [
        {"name": st.name, "parameters": list(st.parameters), "quotes": list(st.rows),
         "chi2": float(cal.chi2), "n_points": int(cal.n), "phi": float(cal.phi)}
        for st, cal in stages
    ]  # fmt: skip
    fitted = dict(zip(names, values, strict=True))
    out = {}
    for label in SETTINGS:
        base = baseline_spec(label)
        pool = {c.name: c for c in base.candidate_list()}
        steps = [_Step(n, pool.get(n)) for n in names]
        out[label] = CalibratedModel(
            "calibration", f"seed B spindle, {label}: {len(names)} inputs from the quoted numbers",
            base, steps, [fitted[n] for n in names], cov, profile, provenance=prov,
        )  # fmt: skip
    return out


def _stage_covariance(cal: Any) -> np.ndarray:
    """A stage's linearised covariance, a value its data do not identify
    marked unknown (infinite variance, no correlation): a band then takes
    the uniform variance over its bounds (``thermobear.predict``'s rule)
    rather than the zero a flat direction of the fit would give it."""
    cov = np.array(cal.model.covariance, dtype=float)
    for j, ok in enumerate(cal.parameters["identified"].to_list()):
        if not ok:
            cov[j, :] = 0.0
            cov[:, j] = 0.0
            cov[j, j] = np.inf
    return cov


def _block_diagonal(blocks: Sequence[np.ndarray]) -> np.ndarray:
    n = sum(b.shape[0] for b in blocks)
    out = np.zeros((n, n))
    i = 0
    for b in blocks:
        k = b.shape[0]
        out[i : i + k, i : i + k] = b
        i += k
    return out


def specs_at(models: Mapping[str, Any], theta: Optional[np.ndarray] = None) -> dict[str, Any]:
    """Each setting's spec at the calibrated values (or at ``theta``)."""
    return {k: (m.spec if theta is None else m.spec_at(theta)) for k, m in models.items()}


# -- bands ------------------------------------------------------------------------


#: Rows whose number jumps with the inputs (the argmin of a scan, the
#: first time a record crosses a level): no smooth band.
_NOT_SMOOTH = ("optimal_preload_n", "settling_time_s")


def _is_plain(r: Mapping[str, Any]) -> bool:
    """Whether a row is a model quantity at its own condition (its band
    straight from [`thermobear.predict`][thermobear.predict.band.predict])."""
    from ..diagnosis.spindle_spec import SPINDLE_QUANTITIES

    q, factor = spec_quantity(r)
    return (
        r["relation"] == "value" and q in SPINDLE_QUANTITIES and factor == 1.0
        and str(r["item"]) != "Fig. 16" and r["speed_rpm"] is not None
    )  # fmt: skip


def predicted_band(model: Any, rows: Any) -> dict[str, tuple[float, float, float]]:
    """[`thermobear.predict`][thermobear.predict.band.predict] of ``model``
    at the rows' conditions: id -> (value, lower, upper) at 95 %."""
    import polars as pl

    from ..predict import predict

    cond = rows.select("speed_rpm", "preload_n").unique(maintain_order=True)
    band = predict(model, "measured", conditions=cond, level=LEVEL, method="delta")
    out = {}
    for r in rows.iter_rows(named=True):
        q, _ = spec_quantity(r)
        b = band.filter(
            (pl.col("quantity") == q)
            & (pl.col("speed_rpm") == r["speed_rpm"])
            & (pl.col("preload_n") == r["preload_n"])
        ).row(0, named=True)
        out[str(r["id"])] = (float(b["value"]), float(b["lower"]), float(b["upper"]))
    return out


def derived_band(models: Mapping[str, Any], rows: Any) -> dict[str, tuple[float, float, float]]:
    """The delta-method band (as [`thermobear.predict`][thermobear.predict.band.predict]'s:
    central differences of a tenth of a standard deviation, variance g^T C g)
    of the rows whose number is derived from several model values:
    id -> (value, lower, upper) at 95 %; a row whose number jumps with the
    inputs (``_NOT_SMOOTH``) has no band (NaN)."""
    from scipy.stats import norm

    from ..predict.uncertainty import delta_band, parameters_of
    from .seed_b_numbers import numbers

    par = parameters_of(models["ceramic"])

    def f(theta: np.ndarray) -> np.ndarray:
        return numbers(rows, specs_at(models, theta))

    z = float(norm.ppf(0.5 + 0.5 * LEVEL))
    value, lower, upper, _ = delta_band(f, par, z)
    out = {}
    for k, r in enumerate(rows.iter_rows(named=True)):
        flat = str(r["quantity"]) in _NOT_SMOOTH or not np.isfinite(value[k])
        lo, hi = (np.nan, np.nan) if flat else (lower[k], upper[k])
        out[str(r["id"])] = (float(value[k]), float(lo), float(hi))
    return out


def band_table(models: Mapping[str, Any], q: Any) -> Any:
    """Every row's ours and 95 % band at the models' estimates (``id``,
    ``ours``, ``lower``, ``upper``, ``basis``)."""
    import polars as pl

    plain = q.filter(pl.Series([_is_plain(r) for r in q.iter_rows(named=True)], dtype=pl.Boolean))
    got: dict[str, tuple[float, float, float]] = {}
    for label in SETTINGS:
        mine = plain.filter(
            pl.Series([setting_label(r) == label for r in plain.iter_rows(named=True)])
        )
        if mine.height:
            got |= predicted_band(models[label], mine)
    rest = q.filter(~pl.col("id").is_in(list(got)))
    got |= derived_band(models, rest)
    ids = q["id"].to_list()
    return pl.DataFrame(
        {
            "id": ids,
            "ours": [got[i][0] for i in ids],
            "lower": [got[i][1] for i in ids],
            "upper": [got[i][2] for i in ids],
            "basis": [basis(r) for r in q.iter_rows(named=True)],
        }
    )


# -- what ours is ------------------------------------------------------------------


def basis(r: Mapping[str, Any]) -> str:
    """What ours is for a row, in a few words."""
    from .seed_b_numbers import NOT_COMPARABLE

    if r["id"] in NOT_COMPARABLE:
        return "not comparable: the measured curve is not given"
    label = setting_label(r)
    q, rel = str(r["quantity"]), str(r["relation"])
    words = {
        "settling_time_s": "slowest front part at 95 % of its rise, transient at 12,000 rpm",
        "optimal_preload_n": "preload of least total radial displacement, 300-500 N scan",
        "frequency_hz": "harmonic of the shaft speed",
        "k_xx_n_per_m": "radial stiffness of one bearing: half the front pair's k_xx",
        "velocity_amplitude_mm_s": "nose velocity spectrum line, fitted unbalance",
        "velocity_rms_mm_s": "rotor's unbalance response RMS, fitted unbalance",
        "total_radial_displacement_um": "mechanical (uncoupled) + radial thermal displacement",
    }
    text = words.get(q, q.replace("_", " "))
    if str(r["item"]) == "Fig. 16" and q == "total_radial_displacement_um":
        text = "least total radial displacement over the 300-500 N scan"
    if rel.startswith("model_error"):
        text = f"measurement minus ours ({q.replace('_', ' ')})"
    if rel == "ratio" and q.endswith("_contact_angle_deg"):
        text = "ratio of the 6,000-18,000 rpm angle changes"
    return f"{text}; fitted model, {label}"


# -- files ---------------------------------------------------------------------------


def _papers_dir() -> Path:
    """The folder of the models: a refit's while one is in force and holds
    them (``paper_numbers.refitted``), else the shipped one."""
    from .paper_numbers import papers_file

    return Path(str(papers_file(BANDS_FILE))).parent


def fit(quick: bool = False, out: Optional[Path] = None) -> dict:
    """Redo every calibration from the fitted rows only (``STAGES``, one
    round when ``quick``), write the models (``MODEL_FILES``) and the band
    table (``BANDS_FILE``) into ``out`` (default: the package's papers
    folder) and return ``values``, ``intervals`` (one row per input:
    value, 95 % profile interval, bounds, stage), ``files`` and
    ``seconds``."""
    import polars as pl

    t0 = time.perf_counter()
    q = _quotes()
    values, stages = fit_stages(q, 1 if quick else ROUNDS)
    models = combined_models(stages, q)
    folder = _papers_dir() if out is None else Path(out)
    folder.mkdir(parents=True, exist_ok=True)
    files = [models[k].save(folder / name) for k, name in MODEL_FILES.items()]
    bands = band_table(models, q)
    bands.write_csv(folder / BANDS_FILE, float_precision=None)
    files.append(folder / BANDS_FILE)
    rows = [
        {**r, "stage": st.name}
        for st, cal in stages
        for r in cal.parameters.select(
            "name", "value", "lower_95", "upper_95", "lower", "upper", "at_bound"
        ).iter_rows(named=True)
    ]
    models_cache_clear()
    return {
        "values": values,
        "intervals": pl.DataFrame(rows),
        "files": files,
        "seconds": time.perf_counter() - t0,
    }


@functools.lru_cache(maxsize=None)
def _models_at(folder: str) -> dict[str, Any]:
    from ..diagnosis import CalibratedModel

    return {k: CalibratedModel.load(Path(folder) / name) for k, name in MODEL_FILES.items()}


def models_cache_clear() -> None:
    """Forget the loaded models (after a refit)."""
    _models_at.cache_clear()


def fitted_models(folder: Optional[Path] = None) -> dict[str, Any]:
    """The shipped calibrated models, one per setting (``MODEL_FILES``)."""
    return _models_at(str(_papers_dir() if folder is None else Path(folder)))


def fitted_spindle(variant: str = "ceramic", coupled: bool = True) -> Any:
    """Seed B's spindle with every input its text leaves out pinned from
    its quoted numbers: the shipped [`CalibratedModel`][thermobear.CalibratedModel]
    (hybrid ``"ceramic"`` or ``"steel"`` balls; ``coupled``: with the
    thermal displacement). It stands for the spindle in downstream calls
    (``thermobear.vibration(model, ...)``, ``thermobear.predict(model,
    ...)``); ``model.model()[0]`` is the configured
    [`Spindle`][thermobear.Spindle]."""
    label = variant if coupled else f"{variant} uncoupled"
    models = fitted_models()
    if label not in models:
        raise ConfigError(f"invalid variant/coupled = {variant!r}/{coupled}: no such model")
    return models[label]


def shipped_bands(folder: Optional[Path] = None) -> polars.DataFrame:
    """The shipped band table (``BANDS_FILE``)."""
    import polars as pl

    path = (_papers_dir() if folder is None else Path(folder)) / BANDS_FILE
    return pl.read_csv(path, schema_overrides={"lower": pl.Float64, "upper": pl.Float64})


def evaluate(quotes: Any, quick: bool = False) -> polars.DataFrame:
    """Ours for every seed B row of ``quotes`` (the number rows; others are
    left to other evaluators): computed from the shipped models (``quick``:
    a coarser preload scan, shorter transient and spectrum records), with
    the shipped 95 % band. Columns ``id``, ``ours``, ``lower``, ``upper``,
    ``basis``."""
    import polars as pl

    q = quotes.filter(pl.col("seed") == "B")
    if "kind" in q.columns:
        q = q.filter(pl.col("kind") == "number")
    bands = {r["id"]: r for r in shipped_bands().iter_rows(named=True)}
    q = q.filter(pl.col("id").is_in(list(bands)))
    models = fitted_models()
    f1 = _simulated_f1_hz(q)
    ev = SeedBNumbers(specs_at(models), quick, f1)
    ids = q["id"].to_list()
    return pl.DataFrame(
        {
            "id": ids,
            "ours": [ev.row(r) for r in q.iter_rows(named=True)],
            "lower": [bands[i]["lower"] for i in ids],
            "upper": [bands[i]["upper"] for i in ids],
            "basis": [bands[i]["basis"] for i in ids],
        },
        schema={"id": pl.Utf8, "ours": pl.Float64, "lower": pl.Float64, "upper": pl.Float64,
                "basis": pl.Utf8},
    )  # fmt: skip


def _simulated_f1_hz(q: Any) -> float:
    """Seed B's simulated 1X frequency (Fig. 20a) from the quotes."""
    import polars as pl

    f = q.filter(pl.col("id") == "B20-f1")
    return float(f["value"][0]) if f.height else 196.6
