"""The "from rig to prediction" demo study (quick mode), end to end: seed
A's 6208 measured on a rig with a hidden effect, diagnosed, its calibrated
model's stiffness band and the gear regimes on the calibrated bearings;
seed B's spindle calibrated on its measured temperatures against the
paper's values."""

from __future__ import annotations

import numpy as np
import polars as pl
import pytest

from thermobear.studies.demo import STUDIES
from thermobear.studies.rig_to_prediction import (
    HIDDEN,
    RIG_QUANTITIES,
    SEED_B_COLUMNS,
    rig_speeds_rpm,
    study_rig_to_prediction,
)


@pytest.fixture(scope="module")
def study(tmp_path_factory):
    out = tmp_path_factory.mktemp("rig_to_prediction")
    return out, study_rig_to_prediction(out, quick=True)


def _table(out, stem: str) -> pl.DataFrame:
    return pl.read_parquet(out / f"{stem}.parquet")


def test_the_study_is_in_the_demo_and_writes_tables_and_figures(study):
    out, files = study
    assert ("rig_to_prediction", "studies.rig_to_prediction:study_rig_to_prediction") in STUDIES
    assert all(f.exists() for f in files)
    names = {f.name for f in files}
    for stem in ("rig_measured", "rig_band", "stiffness_band", "regimes", "regime_boundaries",
                 "seed_b_band", "seed_b_paper"):  # fmt: skip
        assert f"rig_to_prediction_{stem}.parquet" in names
        assert f"rig_to_prediction_{stem}.csv" in names
    for stem in ("stiffness", "bifurcation", "rig_To", "seed_b_growth"):
        assert f"rig_to_prediction_{stem}.png" in names


def test_the_hidden_effect_is_named_with_an_interval_holding_the_truth(study):
    out, _ = study
    ((name, truth),) = HIDDEN.items()
    text = (out / "rig_to_prediction_summary.txt").read_text()
    assert f"verdict: missing effect {name}" in text
    cal = _table(out, "rig_to_prediction_rig_calibrated")
    assert cal["name"].to_list() == [name]
    assert cal["lower_95"][0] < truth < cal["upper_95"][0]
    # the rig measured what the module says, at its speeds
    m = _table(out, "rig_to_prediction_rig_measured")
    assert set(m["quantity"]) == set(RIG_QUANTITIES)
    assert np.array_equal(np.unique(m["speed_rpm"]), rig_speeds_rpm(True))


def test_the_band_at_the_measured_speeds_holds_the_truth(study):
    out, _ = study
    band = _table(out, "rig_to_prediction_rig_band")
    at = band.filter(pl.col("speed_rpm").is_in(rig_speeds_rpm(True).tolist()))
    assert at.height == len(rig_speeds_rpm(True)) * band["quantity"].n_unique()
    assert at["truth_inside"].all(), at.filter(~pl.col("truth_inside"))
    assert (at["upper"] > at["lower"]).all()
    # the prediction's value is the calibrated model's, not the truth's: the
    # bands are not centred on the truth by construction
    assert (at["value"] != at["truth"]).any()


def test_the_stiffness_band_widens_toward_the_top_speed(study):
    out, _ = study
    k = _table(out, "rig_to_prediction_stiffness_band").filter(
        pl.col("quantity") == "k_xx_n_per_m"
    ).sort("speed_rpm")  # fmt: skip
    assert k["speed_rpm"][0] == 6500.0 and k["speed_rpm"][-1] == 16500.0
    width = (k["upper"] - k["lower"]).to_numpy()
    assert np.all(np.diff(width) > 0.0), width
    assert width[-1] > 1.5 * width[0]
    assert k["truth_inside"].all()
    # the thermal stiffness falls with speed (centrifugal and thermal effects)
    assert np.all(np.diff(k["value"].to_numpy()) < 0.0)


def test_the_gear_regime_boundaries_have_intervals(study):
    out, _ = study
    b = _table(out, "rig_to_prediction_regime_boundaries")
    assert b.height > 0
    assert {"from_regime", "to_regime", "speed_rpm", "lower_rpm", "upper_rpm",
            "probability"} <= set(b.columns)  # fmt: skip
    assert (b["lower_rpm"] <= b["speed_rpm"]).all() and (b["speed_rpm"] <= b["upper_rpm"]).all()
    assert ((b["probability"] > 0.0) & (b["probability"] <= 1.0)).all()
    assert (b["from_regime"] != b["to_regime"]).all()


def test_the_seed_b_table_sets_the_papers_values_beside_the_band(study):
    out, _ = study
    t = _table(out, "rig_to_prediction_seed_b_paper")
    assert tuple(t.columns) == SEED_B_COLUMNS
    inside = (t["lower"] <= t["paper_value"]) & (t["paper_value"] <= t["upper"])
    assert t["inside"].to_list() == inside.to_list()
    # a plain reason exactly where the paper's value is outside the band
    assert ((t["reason"] == "") == t["inside"]).all()
    # the calibration used the measured temperatures only; the paper's own
    # simulation (growth, preload) is predicted, not fitted
    cal = t.filter(pl.col("calibrated_on"))
    assert set(cal["origin"]) == {"measured"}
    assert set(cal["quantity"]) == {"front_outer_ring_temperature_c",
                                    "rear_outer_ring_temperature_c"}  # fmt: skip
    growth = t.filter(pl.col("quantity") == "axial_growth_um").sort("speed_rpm")
    assert growth["speed_rpm"].to_list() == [12000.0, 15000.0, 18000.0]
    assert set(growth["origin"]) == {"simulated"}
