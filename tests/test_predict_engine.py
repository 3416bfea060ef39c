"""A sampled band through the study engine (``predict(..., engine=...)``)
and the ``prediction`` study kind: a calibrated model in a Study.

The model: a 7008C at 300 / 600 N whose Palmgren f0 and extra heat are
calibrated (estimates and covariance given directly: the engine's job is
to run the samples, not to calibrate). Its model run is a few speeds of
the thermal stiffness curve, a few hundredths of a second."""

from __future__ import annotations

import pickle

import numpy as np
import polars as pl
import pytest
from polars.testing import assert_frame_equal

import thermobear as tb
from thermobear import diagnosis as D
from thermobear.diagnosis.calibrated import CalibratedModel, _Step
from thermobear.predict.uncertainty import parameters_of, sobol_points

NAMES = ("lubrication_factor_f0", "extra_heat_w")
COND = {"speeds_rpm": [3000.0, 9000.0, 15000.0], "axial_n": [300.0, 600.0]}
TO = "outer_ring_temperature_c"


def _model(values=(1.6, 5.0), label="f0 and extra heat") -> CalibratedModel:
    base = D.BearingModelSpec(tb.Bearing.preset("7008C"))
    pool = {c.name: c for c in base.candidate_list()}
    cov = [[0.04, 0.05], [0.05, 1.0]]
    steps = [_Step(n, pool[n]) for n in NAMES]
    return CalibratedModel("calibration", label, base, steps, list(values), cov)


@pytest.fixture(scope="module")
def model() -> CalibratedModel:
    return _model()


def test_the_local_engine_gives_the_in_process_band_bit_for_bit(model):
    here = tb.predict(model, "temperatures", COND, method="sampling", samples=12, seed=4)
    there = tb.predict(
        model, "temperatures", COND, method="sampling", samples=12, seed=4, engine="local"
    )
    assert_frame_equal(there, here)
    assert (here["upper"] - here["lower"] > 0.0).all()
    # the default (no engine) is the in-process loop, and a delta band ignores the engine
    delta = tb.predict(model, "temperatures", COND, method="delta")
    assert_frame_equal(tb.predict(model, "temperatures", COND, engine="local"), delta)


def test_conditions_that_are_not_a_product_and_the_members_of_a_tie(model):
    """Load pairs (300 N, 0) and (600 N, 200 N): the study computes the
    product of the columns' values and picks the pairs; each member of a
    tie is its own study; the bands equal the in-process ones."""
    cond = {"speeds_rpm": [4000.0, 12000.0], "loads": [(300.0, 0.0), (600.0, 200.0)]}
    other = _model((1.2, 8.0), "tie member 2")
    tie = CalibratedModel(
        "tie", "tie", model.spec, [], [], np.zeros((0, 0)), members=[model, other]
    )
    kw = dict(method="sampling", samples=8, seed=1)
    here = tb.predict(tie, "stiffness", cond, band="envelope", **kw)
    there = tb.predict(tie, "stiffness", cond, engine="local", band="envelope", **kw)
    assert_frame_equal(there, here)
    assert set(there["member"]) == {model.label, "tie member 2", "envelope"}
    assert there.filter(pl.col("member") == "envelope").height == 4 * 4


def test_a_band_on_a_dask_cluster_equals_the_local_one(model):
    distributed = pytest.importorskip("dask.distributed")
    here = tb.predict(model, "temperatures", COND, method="sampling", samples=8, seed=2)
    with distributed.LocalCluster(
        n_workers=1, processes=False, threads_per_worker=2, dashboard_address=":0"
    ) as cluster:
        with distributed.Client(cluster) as client:
            there = tb.predict(
                model, "temperatures", COND, method="sampling", samples=8, seed=2, engine=client
            )
    assert_frame_equal(there, here)


def test_a_prediction_study_holds_the_model_and_its_hash_follows_it(model, tmp_path):
    path = model.save(tmp_path / "model.json")
    grid = {"sample": [0, 1, 2], "speed_rpm": [5000.0, 10000.0]}
    fixed = {"what": "temperatures", "samples": 2, "axial_n": 300.0}
    by_object = tb.Study("prediction", grid, {**fixed, "model": model})
    by_path = tb.Study("prediction", grid, {**fixed, "model": str(path)})
    by_text = tb.Study("prediction", grid, {**fixed, "model": path.read_text()})
    assert by_object.grid_hash == by_path.grid_hash == by_text.grid_hash
    assert by_object.manifest()["study"]["fixed"]["model"] == model.to_json()
    changed = tb.Study("prediction", grid, {**fixed, "model": _model((1.6, 5.5))})
    assert changed.grid_hash != by_object.grid_hash
    assert pickle.loads(pickle.dumps(by_path)).grid_hash == by_object.grid_hash

    df = by_path.run(tmp_path / "out", progress=False)
    assert df.height == 6 and df["ok"].all()
    assert df["model"].n_unique() == 1 and len(df["model"][0]) == 16
    # sample 0 is the estimate: the spec's own prediction
    at = df.filter(pl.col("sample") == 0).sort("speed_rpm")
    cond = pl.DataFrame({"speed_rpm": [5000.0, 10000.0], "axial_n": 300.0, "radial_n": 0.0})
    np.testing.assert_array_equal(at[TO].to_numpy(), model.spec.predict(cond)[TO])
    # a sample moves the model; quantities outside ``what`` stay null
    assert not np.array_equal(df.filter(pl.col("sample") == 1)[TO].to_numpy(), at[TO].to_numpy())
    assert df["k_xx_n_per_m"].null_count() == 6
    # the same study from TOML with the model's path resumes the stored one
    toml = (
        '[study]\nkind = "prediction"\n[grid]\nsample = [0, 1, 2]\n'
        "speed_rpm = [5000.0, 10000.0]\n"
        f'[fixed]\nmodel = "{path}"\nwhat = "temperatures"\nsamples = 2\naxial_n = 300.0\n'
    )
    again = tb.load_study(toml)
    assert_frame_equal(again.run(tmp_path / "out", progress=False), df)
    assert (again.report.computed, again.report.reused) == (0, 1)


def test_bad_points_are_error_rows_and_bad_inputs_name_the_field(model, tmp_path):
    s = tb.Study(
        "prediction",
        {"sample": [0, 3], "member": ["", "nobody"]},
        {"model": model, "samples": 2, "speed_rpm": 5000.0, "axial_n": 300.0},
    )
    df = s.run(progress=False)
    assert df["ok"].to_list() == [True, False, False, False]
    assert "member = 'nobody'" in df["error"][1] and "sample = 3" in df["error"][2]
    preload = tb.Study("prediction", {"preload_n": [100.0]}, {"model": model}).run(progress=False)
    assert not preload["ok"][0] and "preload_n" in preload["error"][0]
    with pytest.raises(tb.ConfigError, match="model"):
        tb.Study("prediction", {}, {"model": str(tmp_path / "missing.json")})
    with pytest.raises(tb.ConfigError, match="samples"):
        tb.Study("prediction", {}, {"model": model, "samples": 0})
    with pytest.raises(tb.ConfigError, match="engine"):
        tb.predict(model, "temperatures", COND, method="sampling", engine="threads")
    with pytest.raises(tb.ConfigError, match="engine"):
        tb.predict(model, "temperatures", COND, method="sampling", engine=3)


def test_a_prediction_study_without_a_model_says_so():
    df = tb.Study("prediction", {"speed_rpm": [1000.0]}).run(progress=False)
    assert not df["ok"][0] and "model" in df["error"][0]


# -- gear regimes on the study engine ------------------------------------------------

REGIME_SPEEDS_RPM = np.linspace(9000.0, 16000.0, 15)
REGIME_ARGS = dict(gear_options={"torque_n_m": 20.0, "te_amplitude_um": 5.0}, samples=8, seed=0)


@pytest.fixture(scope="module")
def hot_bearing() -> CalibratedModel:
    """A 6208 whose extra friction heat (20 +- 10 W) moves its thermal
    stiffness and so where the seed gear pair leaves chaos."""
    base = D.BearingModelSpec(tb.Bearing.preset("6208"))
    step = _Step("extra_heat_w", {c.name: c for c in base.candidate_list()}["extra_heat_w"])
    return CalibratedModel("calibration", "", base, [step], [20.0], [[100.0]])


def _regimes(model, **kw) -> pl.DataFrame:
    cond = {"speeds_rpm": REGIME_SPEEDS_RPM}
    return tb.predict(model, "regimes", cond, **REGIME_ARGS, **kw)


@pytest.fixture(scope="module")
def regimes_here(hot_bearing) -> pl.DataFrame:
    return _regimes(hot_bearing)


def test_regimes_on_the_local_engine_equal_the_in_process_ones(hot_bearing, regimes_here):
    there = _regimes(hot_bearing, engine="local")
    assert_frame_equal(there, regimes_here)
    assert_frame_equal(tb.regime_boundaries(there), tb.regime_boundaries(regimes_here))
    # the samples disagree somewhere: the test compares real probabilities
    p = regimes_here.filter(pl.col("quantity") == "regime_probability")
    assert ((p["value"] > 0.0) & (p["value"] < 1.0)).any()
    assert tb.regime_boundaries(regimes_here).height >= 2


def test_regimes_on_a_dask_cluster_equal_the_in_process_ones(hot_bearing, regimes_here):
    distributed = pytest.importorskip("dask.distributed")
    with distributed.LocalCluster(
        n_workers=1, processes=False, threads_per_worker=2, dashboard_address=":0"
    ) as cluster:
        with distributed.Client(cluster) as client:
            there = _regimes(hot_bearing, engine=client)
    assert_frame_equal(there, regimes_here)


def test_a_regime_prediction_study_sweeps_one_sample_per_chunk(hot_bearing):
    """A point is the regime at one speed of the sample's whole sweep: sample
    0 (the estimate) is the plain down sweep of the calibrated model."""
    order = REGIME_SPEEDS_RPM[::-1]
    opts = REGIME_ARGS["gear_options"]
    fixed = {"model": hot_bearing, "gear_options": opts, "speeds_rpm": order}
    s = tb.Study("regime_prediction", {"sample": [0], "speed_rpm": order}, fixed)
    df = s.run(progress=False)
    assert df["ok"].all() and df["gear"][0] == "seed-electric-drive"
    gear = tb.GearPair.preset("seed-electric-drive")
    system = tb.GearSystem(gear, bearings=hot_bearing, stiffness="thermal", **opts)
    plain = tb.bifurcation(system, REGIME_SPEEDS_RPM, direction="down")
    want = plain.unique("speed_rpm", keep="first", maintain_order=True)
    assert df["regime"].to_list() == want["regime"].to_list()
    # a speed outside the sweep is an error row; an unknown gear pair is refused
    odd = tb.Study("regime_prediction", {"speed_rpm": [order[0], 9100.0]}, fixed)
    assert odd.run(progress=False)["ok"].to_list() == [True, False]
    with pytest.raises(tb.ConfigError, match="gear = 'no-such-pair'"):
        tb.Study("regime_prediction", {}, {**fixed, "gear": "no-such-pair"})


@pytest.mark.parametrize("engine", [None, "local"])
def test_a_failing_regime_sample_is_left_out_and_counted(hot_bearing, monkeypatch, engine):
    """The gear system of the hottest sample fails: of 16 samples (1 in 16
    fails) it is left out of the shares; of 8 (1 in 8, over 10 %) the
    prediction is refused, naming the count."""
    from thermobear.predict import sweeps

    real, hottest = sweeps.regime_system, {}

    def failing(model, theta, gear, options):
        if len(theta) and theta[0] >= hottest["w"]:
            raise tb.ConvergenceError("thermal stiffness did not converge")
        return real(model, theta, gear, options)

    monkeypatch.setattr(sweeps, "regime_system", failing)
    cond = {"speeds_rpm": REGIME_SPEEDS_RPM[::2]}
    opts = {"gear_options": REGIME_ARGS["gear_options"], "seed": 0, "engine": engine}
    for samples in (16, 8):
        hottest["w"] = sobol_points(parameters_of(hot_bearing), samples, 0)[:, 0].max()
        if samples == 8:
            with pytest.raises(tb.ThermobearError, match="failed at 1 of 8 samples"):
                tb.predict(hot_bearing, "regimes", cond, samples=samples, **opts)
            continue
        p = tb.predict(hot_bearing, "regimes", cond, samples=samples, **opts).filter(
            pl.col("quantity") == "regime_probability"
        )
        k = p["value"].to_numpy() * 15.0  # shares of the 15 samples left
        assert np.allclose(k, np.round(k)) and not np.allclose(k, np.round(k * 16 / 15) * 15 / 16)
