"""Seed A's gear pair calibrated on its own bifurcation diagrams.

Seed A quotes 45 transition speeds of its 100 N m bifurcation diagrams
(Figs. 14-15 and the conclusions; ``papers/seed_a_quotes.csv``) and states
no transmission error, mesh damping, backlash or mesh stiffness value. The
fitted rows (the constant- and speed-dependent-stiffness cases, both sweep
directions) pin those four inputs with the project's gear calibration
([`thermobear.calibrate`][thermobear.calibrate] on a
[`GearModelSpec`][thermobear.GearModelSpec]: a design of experiments and
its refinement); the thermal case and the numbers whose case the text does
not name are held out and predicted, each with its 95 % band from the
calibrated inputs' uncertainty (sampled).

``fit()`` redoes the calibration and the bands and writes the shipped
files (``papers/seed_a_gear_model.json``, ``papers/seed_a_gear_bands.csv``);
``fitted_gear_model()`` loads the shipped model: one line away from the
stated preset::

    model = fitted_gear_model()                       # the calibrated pair
    system = tb.GearSystem(model, stiffness="thermal")  # its thermal case

``evaluate(quotes, quick)`` gives ours for every seed A number row (the
reproduction table).
"""

from __future__ import annotations

from pathlib import Path
from typing import TYPE_CHECKING, Any, Optional

import numpy as np

if TYPE_CHECKING:
    import polars

    from ..diagnosis.calibrated import CalibratedModel

#: The speed grid of every seed A sweep (the paper's 6500-16,500 rpm) [rpm].
SPEEDS_RPM = np.arange(6500.0, 16500.0 + 1.0, 50.0)
#: Seed A's input torque for Figs. 14-15 [N m].
TORQUE_N_M = 100.0
#: The inputs calibrated: seed A states none of them.
PARAMETERS = ("te_amplitude_um", "mesh_damping_ratio", "half_backlash_um", "mesh_stiffness_scale")
#: Samples of the calibrated inputs behind each band.
BAND_SAMPLES = 32
#: Refinement rounds of the calibration (each box half as wide as the last).
REFINE_ROUNDS = 3
#: Points of the calibration's coarse design: four inputs on a rough
#: chi^2 (the gear calibration's default is 128).
DESIGN_POINTS = 256

MODEL_FILE = "seed_a_gear_model.json"
BANDS_FILE = "seed_a_gear_bands.csv"
SHIFTS_FILE = "seed_a_thermal_shifts.csv"


def _papers_file(name: str) -> Any:
    from .paper_numbers import papers_file

    return papers_file(name)


def measurements(role: Optional[str] = "fitted") -> polars.DataFrame:
    """Seed A's transition speeds as a gear measurement table
    ([`load_measurements`][thermobear.load_measurements] reads it): the
    number rows of ``role`` ("fitted", "checked", or None for both) that
    are plain values, ``sigma`` their reading precision, ``run`` their id."""
    import polars as pl

    from .paper_numbers import measurement_rows, quotes

    rows = measurement_rows(quotes("A"), role)
    return rows.select(
        "speed_rpm", "torque_n_m", "stiffness", "direction", "quantity", "value",
        pl.col("precision").alias("sigma"), pl.col("id").alias("run"),
    )  # fmt: skip


def bearing_model() -> Any:
    """The seed A bearing the thermal case stands on: the calibrated
    bearing model pinned by seed A's thermal claims
    (``seed_a_thermal.seed_a_bearing_model``: the 6208 with its oil jet,
    the chosen housing and steel)."""
    from .seed_a_thermal import seed_a_bearing_model

    return seed_a_bearing_model()


def base_spec(speeds_rpm: Any = None) -> Any:
    """The stated model: seed A's pair at 100 N m with the documented
    defaults for what the paper leaves out, its thermal case on
    ``bearing_model()``, swept over ``speeds_rpm`` (default
    ``SPEEDS_RPM``)."""
    from ..diagnosis.gear_spec import GearModelSpec
    from ..gear import GearPair

    grid = SPEEDS_RPM if speeds_rpm is None else np.asarray(speeds_rpm, dtype=float)
    return GearModelSpec(
        GearPair.preset("seed-electric-drive"), torque_n_m=TORQUE_N_M, stiffness="thermal",
        bearings=bearing_model(), sweep_speeds_rpm=grid.tolist(),
    )  # fmt: skip


def fitted_gear_model() -> CalibratedModel:
    """The calibrated seed A gear model shipped with thermobear (see
    ``fit``): ``tb.GearSystem(fitted_gear_model(), stiffness="thermal")``,
    ``tb.bifurcation(fitted_gear_model(), speeds)``."""
    from ..diagnosis.calibrated import CalibratedModel

    return CalibratedModel.from_json(_papers_file(MODEL_FILE).read_text())


def calibrate_inputs(
    measured: Any, spec: Any = None, *, design_points: Optional[int] = None,
    refine_points: Optional[int] = None, seed: int = 0, progress: Any = None,
) -> Any:  # fmt: skip
    """The calibration of ``PARAMETERS`` on ``measured`` (a gear
    measurement table) with the gear calibration's defaults, on ``spec``
    (default ``base_spec()``)."""
    from ..diagnosis.joint import calibrate

    spec = base_spec() if spec is None else spec
    return calibrate(
        {"seed A 100 N m": (spec, measured)}, list(PARAMETERS),
        design_points=DESIGN_POINTS if design_points is None else design_points,
        refine_points=refine_points, refine_rounds=REFINE_ROUNDS, seed=seed, progress=progress,
    )  # fmt: skip


def _conditions(rows: Any) -> Any:
    return rows.select("speed_rpm", "torque_n_m", "stiffness", "direction", "comparison")


def _ours(spec: Any, rows: Any) -> np.ndarray:
    got = spec.predict(_conditions(rows))
    q = rows["quantity"].to_list()
    return np.array([got[name][i] for i, name in enumerate(q)], dtype=float)


def bands(model: Any, rows: Any, samples: int = BAND_SAMPLES, seed: int = 0) -> polars.DataFrame:
    """The 95 % band of every row's transition speed from the calibrated
    inputs' uncertainty, by [`predict`][thermobear.predict.band.predict]
    (``samples`` scrambled Sobol points of their normal, clipped to the
    bounds, each swept): columns ``id``, ``value`` (at the estimate),
    ``lower``, ``upper``."""
    import polars as pl

    from ..predict.band import predict

    cond = _conditions(rows)
    got = predict(model, "measured", cond, method="sampling", samples=samples, seed=seed)
    keys = ["speed_rpm", "torque_n_m", "stiffness", "direction", "comparison", "quantity"]
    picked = rows.select("id", *keys).join(
        got.select(*keys, "value", "lower", "upper"), on=keys, how="left", nulls_equal=True
    )
    return picked.select("id", "value", "lower", "upper").with_columns(
        pl.col(c).fill_nan(None) for c in ("value", "lower", "upper")
    )


def thermal_pairs(q: Any) -> polars.DataFrame:
    """The paper's thermal shifts: every transition the text quotes for
    both the speed-dependent and the thermal stiffness case, in the same
    sweep direction and of the same quantity, paired in speed order
    (``speed_id``, ``thermal_id``, the quantity, the direction and the
    paper's shift, thermal minus speed case)."""
    import polars as pl

    rows = _number_rows(q).filter(pl.col("comparison") == "=")
    out = []
    for (quantity, d), g in rows.group_by(["quantity", "direction"], maintain_order=True):
        sp = g.filter(pl.col("stiffness") == "speed").sort("value")
        th = g.filter(pl.col("stiffness") == "thermal").sort("value")
        for a, b in zip(sp.iter_rows(named=True), th.iter_rows(named=True), strict=False):
            out.append((a["id"], b["id"], quantity, d, b["value"] - a["value"]))
    return pl.DataFrame(
        out, schema=["speed_id", "thermal_id", "quantity", "direction", "paper_shift_rpm"],
        orient="row",
    )  # fmt: skip


def thermal_shifts(
    model: Any, q: Any, samples: int = BAND_SAMPLES, seed: int = 0, spec: Any = None
) -> polars.DataFrame:
    """Seed A's question, answered: how far thermal deformation of the
    bearings moves each transition the paper quotes for both cases, with
    the calibrated inputs. Per pair of ``thermal_pairs``: ours (the thermal
    case's event nearest the thermal quote minus the speed case's nearest
    the speed quote, at the estimate) and its 95 % interval over
    ``samples`` Sobol points of the calibrated inputs (those of the bands;
    ``samples_with_both``: samples that have both events)."""
    import polars as pl

    from ..predict.uncertainty import parameters_of, sobol_points

    pairs = thermal_pairs(q)
    rows = _number_rows(q)
    index = {i: k for k, i in enumerate(rows["id"].to_list())}
    a = np.array([index[i] for i in pairs["speed_id"]], dtype=int)
    b = np.array([index[i] for i in pairs["thermal_id"]], dtype=int)
    base = model.spec if spec is None else spec
    est = _ours(base, rows)
    thetas = sobol_points(parameters_of(model), samples, seed)
    runs = np.array([_ours(base.with_setting(**_values(model, t)), rows) for t in thetas])
    d = runs[:, b] - runs[:, a]
    ok = np.isfinite(d)
    lo, hi = np.full(len(a), np.nan), np.full(len(a), np.nan)
    for k in range(len(a)):
        v = d[ok[:, k], k]
        if v.size >= samples // 2:
            lo[k], hi[k] = np.quantile(v, [0.025, 0.975])
    return pairs.with_columns(
        pl.Series("shift_rpm", est[b] - est[a]).fill_nan(None),
        pl.Series("lower_rpm", lo).fill_nan(None),
        pl.Series("upper_rpm", hi).fill_nan(None),
        pl.Series("samples_with_both", ok.sum(axis=0)),
    )


def _values(model: Any, theta: np.ndarray) -> dict[str, float]:
    return dict(zip(model.names, (float(x) for x in theta), strict=True))


def fit(out_dir: Optional[Path] = None, progress: Any = None) -> dict[str, Any]:
    """Redo the calibration on the fitted rows only, the bands of every
    row and the thermal shifts; write ``MODEL_FILE``, ``BANDS_FILE`` and
    ``SHIFTS_FILE`` into ``out_dir`` (default: the package's ``papers``
    folder). Several minutes on two cores."""
    from importlib import resources

    from .paper_numbers import quotes

    shipped = Path(str(resources.files("thermobear.studies.papers")))
    out = shipped if out_dir is None else Path(out_dir)
    measured = measurements("fitted")
    cal = calibrate_inputs(measured, progress=progress)
    model = cal.model
    model.provenance["quotes"] = measured["run"].to_list()
    model.provenance["chi2"] = float(cal.chi2)
    model.save(out / MODEL_FILE)
    q = quotes("A")
    b = bands(model, _number_rows(q))
    b.write_csv(out / BANDS_FILE)
    shifts = thermal_shifts(model, q)
    shifts.write_csv(out / SHIFTS_FILE)
    return {"calibration": cal, "model": model, "bands": b, "shifts": shifts}


def shipped_shifts() -> polars.DataFrame:
    """The thermal shifts shipped with the calibrated model (see ``fit``)."""
    import polars as pl

    with _papers_file(SHIFTS_FILE).open("rb") as f:
        return pl.read_csv(f)


def _number_rows(q: Any) -> Any:
    import polars as pl

    from ..gear.transitions import TRANSITIONS

    return q.filter(pl.col("quantity").is_in(list(TRANSITIONS)))


def evaluate(q: Any, quick: bool = False) -> polars.DataFrame:
    """Ours for every seed A transition row of ``q``: the shipped
    calibrated model's transition nearest the quoted speed, on the grid it
    was calibrated on (also in ``quick``: a transition is read to its grid),
    and the shipped 95 % band."""
    import polars as pl

    rows = _number_rows(q)
    if rows.height == 0:
        return pl.DataFrame(schema={"id": pl.Utf8, "ours": pl.Float64, "lower": pl.Float64,
                                    "upper": pl.Float64, "basis": pl.Utf8})  # fmt: skip
    model = fitted_gear_model()
    ours = _ours(model.spec, rows)  # on the calibration's own grid, quick or not
    with _papers_file(BANDS_FILE).open("rb") as f:
        shipped = pl.read_csv(f)
    basis = [
        f"calibrated gear pair ({role}), {_stiffness_text(s)}, {d} sweep"
        for role, s, d in zip(rows["role"], rows["stiffness"], rows["direction"], strict=True)
    ]
    got = pl.DataFrame({"id": rows["id"], "ours": ours, "basis": basis})
    return got.join(shipped.select("id", "lower", "upper"), on="id", how="left").select(
        "id", "ours", "lower", "upper", "basis"
    )


def _stiffness_text(case: str) -> str:
    return "nearest of the three stiffness cases" if case == "any" else f"{case} stiffness"
