"""The discrepancy workflow on the seed B spindle:
SpindleModelSpec against direct model calls, a hidden thermal displacement
found from the baseline without it, the null case, seed B's measurements."""

from __future__ import annotations

import numpy as np
import polars as pl
import pytest

import thermobear as tb
from thermobear import diagnosis
from thermobear.diagnosis import SPINDLE_QUANTITIES, THERMAL_DISPLACEMENT_EFFECTS
from thermobear.errors import ConfigError, DataError
from thermobear.studies.diagnose_seed_b import (
    baseline_without_thermal_displacement,
    study_diagnose_seed_b,
)

SPEEDS = np.arange(6000.0, 18001.0, 2000.0)
QS = [
    "front_outer_ring_temperature_c",
    "rear_outer_ring_temperature_c",
    "velocity_rms_mm_s",
    "axial_growth_um",
]


@pytest.fixture(scope="module")
def spindle():
    return tb.Spindle.preset("seed-ceramic-spindle")


@pytest.fixture(scope="module")
def base(spindle):
    # one spec for the whole module: its cache holds every configuration
    return baseline_without_thermal_displacement(spindle)


def _conditions(quantities=QS):
    return pl.DataFrame(
        {
            "speed_rpm": np.repeat(SPEEDS, len(quantities)),
            "preload_n": 400.0,
            "quantity": list(quantities) * len(SPEEDS),
        }
    )


def _values(spec, cond):
    p = spec.predict(cond.rename({"preload_n": "axial_n"}))
    return np.array([p[q][i] for i, q in enumerate(cond["quantity"].to_list())])


def _sigma(cond, v):
    # thermocouples 0.5 K, vibrometer 5 %, axial growth probe 0.5 um
    q = cond["quantity"].to_list()
    return np.array(
        [0.05 * x if qq == "velocity_rms_mm_s" else 0.5 for qq, x in zip(q, v, strict=False)]
    )


def _measured(cond, v, sig, seed):
    rng = np.random.default_rng(seed)
    return cond.with_columns(
        pl.Series("value", v + rng.normal(size=len(v)) * sig), pl.Series("sigma", sig)
    )


def test_predictions_equal_direct_model_calls(spindle, base):
    coupled = base.with_setting(["thermal_displacement"])
    assert set(THERMAL_DISPLACEMENT_EFFECTS) <= set(coupled.effects)
    assert not set(THERMAL_DISPLACEMENT_EFFECTS) & set(base.effects)
    speeds = [9000.0, 15000.0]
    cond = pl.DataFrame({"speed_rpm": speeds, "axial_n": 400.0, "radial_n": 0.0})
    for spec, on in ((base, False), (coupled, True)):
        p = spec.predict(cond)
        for i, n in enumerate(speeds):
            row = spindle.thermal_state(n, effects=list(spec.effects))
            assert (
                p["front_outer_ring_temperature_c"][i] == row["front_outer_ring_temperature_c"][0]
            )
            assert p["rear_outer_ring_temperature_c"][i] == row["rear_outer_ring_temperature_c"][0]
            assert p["axial_growth_um"][i] == row["axial_growth_um"][0]
        direct = tb.vibration(
            spindle.with_options(effects=list(spec.effects)),
            speeds,
            coupled=on,
            effects=list(spec.effects),
        )
        np.testing.assert_allclose(
            p["velocity_rms_mm_s"], direct["velocity_rms_mm_s"].to_numpy(), rtol=1e-12
        )
    # the steady unbalance response is linear: twice the grade, twice the velocity
    g5 = coupled.with_setting(unbalance_grade=5.0).predict(cond)["velocity_rms_mm_s"]
    np.testing.assert_allclose(g5, 2.0 * coupled.predict(cond)["velocity_rms_mm_s"], rtol=1e-9)
    # without thermal expansion there is no thermal axial growth
    assert np.all(base.predict(cond)["axial_growth_um"] == 0.0)
    assert np.all(coupled.predict(cond)["axial_growth_um"] > 10.0)


def test_hidden_thermal_displacement_is_named_and_the_gap_shrinks(base):
    cond = _conditions()
    truth = _values(base.with_setting(["thermal_displacement"]), cond)
    sig = _sigma(cond, truth)
    named = 0
    for seed in range(5):
        d = tb.diagnose(base, _measured(cond, truth, sig, seed))
        names = [a["name"] for a in d.accepted] + d.tie
        named += "thermal_displacement" in names or any(
            n in THERMAL_DISPLACEMENT_EFFECTS for n in names
        )
        g = d.gap.group_by("quantity").agg(
            pl.col("rms_before_sigma").max(), pl.col("rms_after_sigma").max()
        )
        ag = g.filter(pl.col("quantity") == "axial_growth_um")
        # 100+ sigma before; within noise after
        assert ag["rms_before_sigma"][0] > 100.0
        assert ag["rms_after_sigma"][0] < 3.0
    assert named == 5
    # re-diagnosing new noise on the same conditions costs no model run
    runs = base.model_runs
    tb.diagnose(base, _measured(cond, truth, sig, 99))
    assert base.model_runs == runs


def test_null_case_names_nothing(base):
    cond = _conditions()
    v = _values(base, cond)
    sig = _sigma(cond, v)
    verdicts = [
        tb.diagnose(base, _measured(cond, v, sig, 100 + seed)).verdict for seed in range(10)
    ]
    # false discovery at most 1 in 10 (the acceptance rules aim at ~1 %)
    assert sum(v != "no missing effect supported" for v in verdicts) <= 1


def test_spec_carries_its_registry_and_bad_input_rejected(spindle, base):
    # the spindle's quantities and candidates come from the spec itself; the
    # bearing registry is untouched by a spindle diagnosis
    assert base.quantities is SPINDLE_QUANTITIES
    assert "front_outer_ring_temperature_c" not in diagnosis.QUANTITIES
    a = tb.spindle_candidates(base, ["velocity_rms_mm_s"])
    assert a.equals(tb.candidates(base, ["velocity_rms_mm_s"]))
    assert "sensor_offset:velocity_rms_mm_s" in a["name"].to_list()
    assert set(a["role"]) == {"effect", "calibration", "measurement"}
    with pytest.raises(ConfigError, match="quantity"):
        tb.candidates(base, ["outer_ring_temperature_c"])
    with pytest.raises(ConfigError, match="effect"):
        tb.SpindleModelSpec(spindle, effects=["no_such_effect"])
    with pytest.raises(ConfigError, match="option"):
        tb.SpindleModelSpec(spindle, lubricant="ATF")
    with pytest.raises(ConfigError, match="spin_friction"):
        tb.SpindleModelSpec(spindle, spin_friction_coefficient=-0.1)
    with pytest.raises(ConfigError, match="model"):
        tb.diagnose_spindle(tb.BearingModelSpec(tb.Bearing.preset("7008C")), _conditions())
    with pytest.raises(ConfigError, match="radial_n"):
        base.predict(pl.DataFrame({"speed_rpm": [9000.0], "axial_n": [400.0], "radial_n": [50.0]}))
    bad = _conditions().with_columns(
        pl.lit("outer_ring_temperature_c").alias("quantity"), value=30.0
    )
    with pytest.raises(DataError, match="quantity"):
        tb.load_spindle_measurements(bad)


def test_seed_b_table_matches_the_paper():
    m = tb.seed_b_measurements()
    got = {r["quantity"]: (r["speed_rpm"], r["value"]) for r in m.iter_rows(named=True)}
    # seed B, "Experimental results and analysis": Fig. 19a and Fig. 21
    assert got["front_outer_ring_temperature_c"] == (12000.0, 33.7)
    assert got["rear_outer_ring_temperature_c"] == (12000.0, 30.1)
    assert got["velocity_rms_mm_s"] == (18000.0, 18.92)
    assert (m["preload_n"] == 400.0).all()  # a spindle's preload keeps its name


def test_seed_b_study_quick(tmp_path):
    files = study_diagnose_seed_b(tmp_path, quick=True)
    assert all(f.exists() for f in files)
    text = (tmp_path / "diagnose_seed_b_verdict.txt").read_text()
    assert "verdict:" in text
    models = pl.read_csv(tmp_path / "diagnose_seed_b_models.csv")
    vib = models.filter(pl.col("quantity") == "velocity_rms_mm_s")
    # our G2.5 rotor is hundreds of times below the measured 18.92 mm/s; no
    # physical effect of the model closes that, only the measurement-side
    # runout of the vibrometer's track: 18.92 mm/s RMS at 18,000 rpm is
    # omega eps / sqrt 2 with eps = 14.2 um (inside its 0-50 um bounds)
    assert vib["measured_over_ours_without"][0] > 100.0
    assert "runout_um" in text and "14.2 µm" in text
    assert "unbalance_grade" not in text.split("held-out")[0].split("look-alikes")[0]


def test_without_axial_growth_thermal_displacement_is_only_a_look_alike(base):
    # temperatures and vibration only: thermal displacement raises the 18,000
    # rpm vibration by ~25 % (4 sigma at 5 %) and the temperatures by < 0.1 K,
    # much like a vibrometer scale error: the workflow must not name a wrong
    # physical effect, and it points at the measurement that separates them
    cond = _conditions(QS[:3])
    truth = _values(base.with_setting(["thermal_displacement"]), cond)
    sig = _sigma(cond, truth)
    found = 0
    for seed in range(5):
        d = tb.diagnose(base, _measured(cond, truth, sig, seed))
        model_side = [a["name"] for a in d.accepted if a["side"] == "model"]
        assert all(
            n == "thermal_displacement" or n in THERMAL_DISPLACEMENT_EFFECTS for n in model_side
        )
        found += "thermal_displacement" in model_side + d.tie
    assert found >= 2
    la = d.lookalikes.filter(
        (pl.col("a") == "thermal_displacement") & (pl.col("b") == "thermal_expansion_shaft")
    )
    assert la["suggest_quantity"][0] == "axial_growth_um"


def test_diagnose_accepts_a_spindle_model_directly():
    """tb.diagnose with a SpindleModelSpec uses the spec's own registry and
    gives the same result as tb.diagnose_spindle."""
    model = tb.SpindleModelSpec(
        tb.Spindle.preset("seed-ceramic-spindle"), effects=["centrifugal_force"]
    )
    data = tb.seed_b_measurements()
    a = tb.diagnose(model, data, holdout=None)
    b = tb.diagnose_spindle(model, data, holdout=None)
    assert a.verdict == b.verdict


def test_cli_diagnoses_seed_b_measurements_from_a_spindle_preset(tmp_path, capsys):
    import matplotlib

    matplotlib.use("Agg")
    from importlib.resources import files

    from thermobear.cli import main

    csv = files("thermobear") / "configs" / "seed_b_measurements.csv"
    out = tmp_path / "out"
    args = ["diagnose", str(csv), "--spindle", "seed-ceramic-spindle", "--out", str(out)]
    # two speeds: the default holdout (the highest speeds) is refused, as by the API
    assert main(args + ["--without", "thermal_displacement"]) == 1
    assert "holding out the highest speeds needs at least 3" in capsys.readouterr().err
    args += ["--holdout", "none"]
    assert main(args + ["--without", "thermal_displacement"]) == 0
    text = capsys.readouterr().out
    assert "verdict:" in text and (out / "diagnosis_gap.csv").exists()
    # the same as the Python call with the same baseline
    full = tb.SpindleModelSpec(tb.Spindle.preset("seed-ceramic-spindle"))
    base = tb.SpindleModelSpec(
        full.spindle, effects=[e for e in full.effects if e not in THERMAL_DISPLACEMENT_EFFECTS]
    )
    d = tb.diagnose(base, tb.seed_b_measurements(), holdout=None)
    assert d.verdict in text
    assert main(args + ["--without", "no_such_effect"]) == 1
    assert main(["diagnose", str(csv), "--spindle", "no-such-spindle"]) == 1
