"""Design studies: batch entry points equal single calls bit for bit, a study
is the same whatever the chunking, the engine or an interruption, failed
points are rows, the grid file names its bad keys."""

from __future__ import annotations

import json

import numpy as np
import polars as pl
import pytest
from polars.testing import assert_frame_equal

import thermobear as tb
from thermobear.study.kinds import kinds_table

# -- batch entry points ------------------------------------------------------------


def test_solve_many_equals_single_solves_bit_for_bit():
    b = tb.Bearing.preset("7008C")
    pts = pl.DataFrame(
        {
            "speed_rpm": [0.0, 6000.0, 12000.0, 18000.0, 12000.0],
            "axial_n": [400.0, 400.0, 800.0, 300.0, -5.0],
            "radial_n": [0.0, 200.0, 500.0, 100.0, 0.0],
            "case": ["a", "b", "c", "d", "e"],
        }
    )
    df = b.solve_many(pts, threads=2)
    assert df["case"].to_list() == pts["case"].to_list()  # carried through
    for row in df.head(4).iter_rows(named=True):
        s = b.solve(axial_n=row["axial_n"], radial_n=row["radial_n"], speed_rpm=row["speed_rpm"])
        balls = s.balls
        assert row["axial_stiffness_seed_n_per_m"] == s.axial_stiffness_seed_n_per_m
        assert row["radial_stiffness_seed_n_per_m"] == s.radial_stiffness_seed_n_per_m
        assert row["k_zz_n_per_m"] == s.stiffness[2, 2]
        assert row["axial_displacement_um"] == s.displacement[2] * 1e6
        assert row["inner_contact_angle_max_deg"] == balls["inner_contact_angle_deg"].max()
        assert row["outer_load_max_n"] == balls["outer_load_n"].max()
        assert row["iterations"] == s.iterations and row["residual"] == s.residual
        assert row["ok"] and row["error"] is None
    # The bad point is a row with its error, nulls, and nothing raised.
    bad = df.row(4, named=True)
    assert not bad["ok"] and bad["error_kind"] == "ConfigError"
    assert "axial_n" in bad["error"] and bad["axial_stiffness_seed_n_per_m"] is None
    with pytest.raises(tb.ConfigError, match="axial_n"):
        b.solve(axial_n=-5.0, speed_rpm=12000.0)


def test_solve_many_does_not_depend_on_threads_and_physics_holds():
    b = tb.Bearing.preset("7008C")
    speeds = np.linspace(5000.0, 20000.0, 7)
    pts = {"speed_rpm": np.concatenate([speeds, 2 * speeds]), "axial_n": 600.0}
    one, two = b.solve_many(pts, threads=1), b.solve_many(pts, threads=2)
    assert_frame_equal(one, two)
    # Ball centrifugal force m dm omega_c^2 / 2 (A-16): the force ratio is the
    # square of the cage-speed ratio, and doubling the shaft speed about
    # doubles the cage speed (the contact angles shift it by a few percent).
    fc, cage = one["centrifugal_force_n"].to_numpy(), one["cage_speed_rpm"].to_numpy()
    np.testing.assert_allclose(fc[7:] / fc[:7], (cage[7:] / cage[:7]) ** 2, rtol=1e-9)
    assert np.all(np.abs(cage[7:] / cage[:7] - 2.0) < 0.05)
    # At speed the outer contact angle falls below the inner one (A-16).
    assert (one["outer_contact_angle_max_deg"] < one["inner_contact_angle_min_deg"]).all()


def test_solve_many_reports_progress_and_stops_on_ctrl_c():
    import signal
    import time

    b = tb.Bearing.preset("7008C")
    calls = []
    pts = {"speed_rpm": np.linspace(3000.0, 15000.0, 500), "axial_n": 500.0}
    b.solve_many(pts, progress=lambda done, total: calls.append((done, total)))
    assert calls[-1] == (500, 500) and all(t == 500 for _, t in calls)
    assert [d for d, _ in calls] == sorted(d for d, _ in calls)
    # A real interrupt (SIGINT's handler on an OS timer) 0.2 s into a batch
    # of about 10 s of work stops it well before the end.
    many = {"speed_rpm": np.linspace(3000.0, 15000.0, 250_000), "axial_n": 500.0}
    previous = signal.signal(signal.SIGALRM, signal.default_int_handler)
    try:
        signal.setitimer(signal.ITIMER_REAL, 0.2)
        t0 = time.perf_counter()
        with pytest.raises(KeyboardInterrupt):
            b.solve_many(many)
        assert time.perf_counter() - t0 < 3.0
    finally:
        signal.setitimer(signal.ITIMER_REAL, 0.0)
        signal.signal(signal.SIGALRM, previous)


def test_thermal_state_many_equals_thermal_state_and_keeps_a_runaway_row():
    b = tb.Bearing.preset("6208")
    pts = {"speed_rpm": [4000.0, 9000.0, 200_000.0], "axial_n": 300.0, "radial_n": 500.0}
    df = tb.thermal_state_many(b, pts, lubricant="ISO VG 32")
    for row in df.head(2).iter_rows(named=True):
        s = tb.thermal_state(b, row["speed_rpm"], 300.0, 500.0, lubricant="ISO VG 32")
        assert row["heat_w"] == s.total_heat_w
        assert row["ball_temperature_c"] == s.temperature_c("Tb")
        assert row["radial_stiffness_seed_n_per_m"] == s.solution.radial_stiffness_seed_n_per_m
        assert row["thermal_iterations"] == s.iterations
    # Heat grows with speed (Palmgren load and viscous moments times speed).
    assert df["heat_w"][1] > df["heat_w"][0]
    runaway = df.row(2, named=True)
    assert runaway["error_kind"] == "ThermalRunawayError" and "lubricant" in runaway["error"]
    assert runaway["heat_w"] is None


# -- studies on this machine ------------------------------------------------------


def _thermal_study(chunk_size: int = 4) -> tb.Study:
    return tb.Study(
        "thermal",
        {"bearing": ["6208", "7008C"], "speed_rpm": [3000, 9000, 200_000], "axial_n": [300, 600]},
        {"radial_n": 200.0, "lubricant": "ISO VG 32"},
        chunk_size=chunk_size,
    )


def test_study_rows_are_the_grid_in_order_with_inputs_and_outputs():
    s = _thermal_study()
    df = s.run(progress=False)
    assert df.height == 12 == len(s) and df["point"].to_list() == list(range(12))
    # First dimension outermost.
    assert df["bearing"].to_list()[:6] == ["6208"] * 6
    assert df["speed_rpm"].to_list()[:6] == [3000.0, 3000.0, 9000.0, 9000.0, 200_000.0, 200_000.0]
    assert set(df["lubricant"]) == {"ISO VG 32"} and set(df["housing_material"]) == {"aluminium"}
    # The 6208 runs away far beyond its speed limit: rows with the error.
    bad = df.filter(~pl.col("ok"))
    assert bad.select("bearing", "speed_rpm").unique().rows() == [("6208", 200_000.0)]
    assert set(bad["error_kind"]) == {"ThermalRunawayError"}
    assert s.report.failed_points == 2 and s.report.computed == 3 and s.report.reused == 0
    # The same as the batch call of one bearing.
    one = tb.thermal_state_many(
        tb.Bearing.preset("7008C"),
        df.filter(pl.col("bearing") == "7008C").select("speed_rpm", "axial_n", "radial_n"),
        lubricant="ISO VG 32",
    )
    assert df.filter(pl.col("bearing") == "7008C")["heat_w"].to_list() == one["heat_w"].to_list()


def test_a_model_the_solver_rejects_is_an_error_row_of_its_points_only():
    s = tb.Study(
        "thermal", {"spin_friction_coefficient": [0.06, -1.0], "speed_rpm": [5000.0, 8000.0]}
    )
    df = s.run(progress=False)
    assert df["ok"].to_list() == [True, True, False, False]
    bad = df.filter(~pl.col("ok"))
    assert set(bad["error_kind"]) == {"ConfigError"} and "spin_friction" in bad["error"][0]
    good = tb.thermal_state_many(tb.Bearing.preset("7008C"), {"speed_rpm": [5000.0, 8000.0]})
    assert df["heat_w"].head(2).to_list() == good["heat_w"].to_list()


def test_a_study_pickles():
    import pickle

    s = tb.Study("spindle", {"speed_rpm": [8000.0, 9000.0]}, {"preload_kind": "spring"})
    t = pickle.loads(pickle.dumps(s))
    assert t.grid_hash == s.grid_hash and t.chunk_size == s.chunk_size
    assert_frame_equal(t.points(), s.points())


def test_heat_model_and_lubrication_are_dimensions():
    s = tb.Study(
        "thermal", {"heat_model": ["palmgren", "skf"]}, {"speed_rpm": 8000.0, "axial_n": 400}
    )
    df = s.run(progress=False)
    b = tb.Bearing.preset("7008C")
    for row in df.iter_rows(named=True):
        single = tb.thermal_state(b, 8000.0, 400.0, 0.0, heat_model=row["heat_model"])
        assert row["heat_w"] == single.total_heat_w
    assert df["heat_w"][0] != df["heat_w"][1]
    with pytest.raises(tb.ConfigError, match="lubrication = treacle"):
        tb.Study("thermal", {"lubrication": ["oil-mist", "treacle"]})
    oil_air = tb.Study("thermal", {"lubrication": ["oil-air"]}, {"speed_rpm": 8000.0})
    assert oil_air.run(progress=False)["ok"].all()


def test_chunking_does_not_change_results():
    a = _thermal_study(chunk_size=1).run(progress=False)
    b = _thermal_study(chunk_size=100).run(progress=False)
    assert_frame_equal(a, b)


def test_preload_adds_to_the_axial_load():
    a = tb.Study("bearing", {"speed_rpm": [8000, 16000]}, {"axial_n": 100, "preload_n": 400})
    b = tb.Study("bearing", {"speed_rpm": [8000, 16000]}, {"axial_n": 500})
    cols = ["axial_stiffness_seed_n_per_m", "axial_displacement_um", "inner_load_max_n"]
    assert_frame_equal(a.run(progress=False).select(cols), b.run(progress=False).select(cols))


def test_interrupted_study_resumes_with_only_the_missing_chunks(tmp_path):
    s = _thermal_study(chunk_size=2)  # 6 chunks
    seen = []

    def stop_after_two(index, frame):
        seen.append(index)
        if len(seen) == 2:
            raise KeyboardInterrupt

    with pytest.raises(KeyboardInterrupt):
        s.run(tmp_path, progress=False, on_chunk=stop_after_two)
    assert s.report.interrupted and s.report.computed == 2
    assert len(list((tmp_path / "chunks").glob("chunk-*.parquet"))) == 2
    again = _thermal_study(chunk_size=2)
    df = again.run(tmp_path, progress=False)
    assert (again.report.computed, again.report.reused) == (4, 2)
    assert_frame_equal(df, _thermal_study().run(progress=False))
    third = _thermal_study(chunk_size=2)
    assert_frame_equal(third.run(tmp_path, progress=False), df)
    assert (third.report.computed, third.report.reused) == (0, 6)
    assert third.report.failed_points == 2  # the 6208's runaway rows, read back
    assert _thermal_study(chunk_size=2).run(tmp_path, collect=False, progress=False) is None
    manifest = json.loads((tmp_path / "manifest.json").read_text())
    assert manifest["grid_hash"] == s.grid_hash and manifest["n_chunks"] == 6
    assert not list(tmp_path.rglob("*.tmp"))  # written by rename only


def test_ctrl_c_keeps_finished_chunks_and_the_rerun_computes_the_rest(tmp_path):
    """A real interrupt: SIGALRM with SIGINT's handler, delivered by the OS
    0.3 s into the run (inside a native batch call or between chunks)."""
    import signal

    def study() -> tb.Study:
        grid = {
            "speed_rpm": {"start": 2000, "stop": 20000, "num": 50},
            "axial_n": range(200, 1000, 20),
        }
        return tb.Study("thermal", grid, chunk_size=50)  # 2000 points, 40 chunks

    s = study()
    previous = signal.signal(signal.SIGALRM, signal.default_int_handler)
    try:
        signal.setitimer(signal.ITIMER_REAL, 0.3)
        with pytest.raises(KeyboardInterrupt):
            s.run(tmp_path, progress=False)
    finally:
        signal.setitimer(signal.ITIMER_REAL, 0.0)
        signal.signal(signal.SIGALRM, previous)
    kept = len(list((tmp_path / "chunks").glob("chunk-*.parquet")))
    assert kept == s.report.computed < 40 and s.report.interrupted
    assert not list(tmp_path.rglob("*.tmp"))
    again = study()
    df = again.run(tmp_path, progress=False)
    assert (again.report.computed, again.report.reused) == (40 - kept, kept)
    assert df["point"].to_list() == list(range(2000)) and df["ok"].all()


def test_another_grid_is_not_mixed_into_old_results(tmp_path):
    _thermal_study(chunk_size=6).run(tmp_path, progress=False)
    other = tb.Study("thermal", {"speed_rpm": [3000, 4000]}, chunk_size=6)
    assert other.grid_hash != _thermal_study(chunk_size=6).grid_hash
    with pytest.raises(tb.ConfigError, match="another grid"):
        other.run(tmp_path, progress=False)
    df = other.run(tmp_path, progress=False, overwrite=True)
    assert df.height == 2 and other.report.computed == 1
    # Changing the chunking changes the hash too (chunks would not line up).
    assert tb.Study("thermal", {"speed_rpm": [3000, 4000]}, chunk_size=1).grid_hash != (
        other.grid_hash
    )


def test_spindle_and_gear_points():
    sp = tb.Study("spindle", {"speed_rpm": [9000.0]}, {"preload_n": 250.0}).run(progress=False)
    direct = tb.Spindle.preset("seed-ceramic-spindle").thermal_state(9000.0, preload_n=250.0)
    assert sp["front_ball_temperature_c"][0] == direct["front_ball_temperature_c"][0]
    assert sp["operating_preload_n"][0] == direct["operating_preload_n"][0]
    g = tb.Study(
        "gear",
        {"speed_rpm": [3000.0], "te_amplitude_um": [2.0]},
        {"torque_n_m": 100.0, "transient_periods": 60, "record_periods": 20},
    ).run(progress=False)
    system = tb.GearSystem(tb.GearPair.preset("seed-electric-drive"), torque_n_m=100.0)
    cell = tb.regime_map(system, [100.0], [3000.0], [1.0], 60, 20)  # the same default steps
    assert g["regime"][0] == cell["regime"][0] and g["amplitude_um"][0] == cell["amplitude_um"][0]
    # Too few steps per period at a low speed: the point's error, not the study's.
    low = tb.Study("gear", {"speed_rpm": [3000.0]}, {"steps_per_period": 16}).run(progress=False)
    assert low["error_kind"][0] == "ConfigError" and "steps_per_period" in low["error"][0]


def test_a_dask_task_rebuilds_the_same_chunk_from_the_description():
    # What a worker receives is the JSON-able description, not the objects.
    from thermobear.study.engine import compute, compute_on_worker

    for s in (
        tb.Study("spindle", {"speed_rpm": [8000.0]}, chunk_size=1),
        tb.Study("thermal", {"speed_rpm": [5000.0, 7000.0]}, {"lubricant": "ISO VG 68"}),
    ):
        spec = json.loads(json.dumps(s.grid.spec()))
        assert_frame_equal(
            compute_on_worker(spec, s.chunk_size, 0), compute(s.grid, s.chunk_size, 0, 1)
        )


# -- grids and the TOML file -------------------------------------------------------


def test_grid_values_ranges_and_errors():
    s = tb.Study(
        "bearing",
        {"speed_rpm": {"start": 1000, "stop": 2000, "step": 250}, "axial_n": range(100, 301, 100)},
    )
    pts = s.points()
    assert sorted(set(pts["speed_rpm"])) == [1000.0, 1250.0, 1500.0, 1750.0, 2000.0]
    assert pts.height == 15
    assert tb.Study("bearing", {"speed_rpm": {"start": 0, "stop": 1, "num": 3}}).n_points == 3
    with pytest.raises(tb.ConfigError, match="'speed'"):
        tb.Study("bearing", {"speed": [1.0]})
    with pytest.raises(tb.ConfigError, match="bearing = '6209'"):
        tb.Study("bearing", {"bearing": ["6208", "6209"]})
    with pytest.raises(tb.ConfigError, match="grid.axial_n"):
        tb.Study("bearing", {"axial_n": [1.0, float("nan")]})
    with pytest.raises(tb.ConfigError, match="'nmu'"):
        tb.Study("bearing", {"speed_rpm": {"start": 0, "stop": 1, "nmu": 3}})
    with pytest.raises(tb.ConfigError, match="lubricant"):
        tb.Study("thermal", {"lubricant": ["ISO VG 46"]})
    with pytest.raises(tb.ConfigError, match="kind = 'rotor'"):
        tb.Study("rotor", {})
    table = kinds_table()
    kinds = {"bearing", "thermal", "spindle", "gear", "prediction", "regime_prediction"}
    assert kinds == set(table["kind"])


@pytest.mark.parametrize(
    "text, key, where",
    [
        ("[study]\nkind='bearing'\n[grids]\nspeed_rpm=[1.0]\n", "'grids'", "top level"),
        ("[study]\nkind='bearing'\nchunks=3\n", "'chunks'", "[study]"),
        ("[study]\nkind='bearing'\n[grid]\nspeed=[1.0]\n", "'speed'", "[grid]"),
        ("[study]\nkind='thermal'\n[fixed]\nlubricant_name='x'\n", "'lubricant_name'", "[fixed]"),
        (
            "[study]\nkind='bearing'\n[grid]\nspeed_rpm={start=0, stop=1, nun=2}\n",
            "'nun'",
            "grid.speed_rpm",
        ),
    ],
)
def test_toml_errors_name_the_key_and_its_table(text, key, where):
    with pytest.raises(tb.ConfigError) as e:
        tb.load_study(text)
    assert key in str(e.value) and where in str(e.value)


def test_the_example_grid_file_loads():
    from importlib import resources

    text = resources.files("thermobear.configs").joinpath("study_thermal_grid.toml").read_text()
    s = tb.load_study(text)
    assert s.kind == "thermal" and s.n_points == 288 and s.chunk_size == 48


# -- progress, the command line, the optional Dask ---------------------------------


def test_progress_bar_only_when_asked_or_interactive(capsys):
    s = tb.Study("bearing", {"speed_rpm": [6000.0, 7000.0]}, chunk_size=1)
    s.run()  # stderr is not a terminal under pytest: silent
    s.run(progress=False)
    assert capsys.readouterr().err == ""
    s.run(progress=True)
    err = capsys.readouterr().err
    assert "bearing study" in err and "2/2" in err


def test_command_line_study_resumes(tmp_path, capsys):
    from thermobear.cli.main import main

    grid = tmp_path / "grid.toml"
    grid.write_text(
        "[study]\nkind = 'bearing'\nchunk_size = 2\n"
        "[grid]\nspeed_rpm = {start = 4000, stop = 12000, num = 5}\naxial_n = [300]\n"
    )
    out = tmp_path / "results"
    assert main(["study", str(grid), "--out", str(out), "--no-progress"]) == 0
    assert "3 computed, 0 reused" in capsys.readouterr().out
    assert main(["study", str(grid), "--out", str(out), "--no-progress"]) == 0
    assert "0 computed, 3 reused" in capsys.readouterr().out
    assert pl.scan_parquet(out / "chunks" / "*.parquet").collect().height == 5
    grid.write_text("[study]\nkind = 'bearing'\n[grid]\nspeeds = [1.0]\n")
    assert main(["study", str(grid), "--out", str(out)]) == 1  # a config error
    assert "'speeds'" in capsys.readouterr().err


def test_without_dask_the_engine_names_the_extra(monkeypatch):
    import sys

    for name in ("dask", "dask.distributed"):
        monkeypatch.setitem(sys.modules, name, None)  # import raises ImportError
    s = tb.Study("bearing", {"speed_rpm": [6000.0]})
    with pytest.raises(tb.ConfigError, match=r'pip install "thermobear\[dask\]"'):
        s.run(engine="tcp://127.0.0.1:8786", progress=False)
    assert s.run(progress=False).height == 1  # the local engine needs no Dask


# -- a calibrated model in place of a preset ------------------------------------------


def _calibrated(spec) -> tb.CalibratedModel:
    """A model at a spec's settings (no calibrated values: cheap to build)."""
    return tb.CalibratedModel("nothing", "baseline", spec, [], [], np.zeros((0, 0)))


def _bearing_model(preset: str = "7008C", oil_fraction: float = 0.01) -> tb.CalibratedModel:
    """A bearing with a churning loss and a 10 % axial load scale."""
    spec = tb.BearingModelSpec(tb.Bearing.preset(preset))
    return _calibrated(spec.with_setting(churning_oil_fraction=oil_fraction, axial_load_scale=1.1))


def test_a_thermal_study_of_a_calibrated_model_is_its_thermal_state():
    m = _bearing_model()
    speeds = [6000.0, 12000.0]
    df = tb.Study("thermal", {"speed_rpm": speeds}, {"model": m, "axial_n": 300.0}).run(
        progress=False
    )
    nodes = ("shaft", "inner_ring", "ball", "outer_ring", "housing")
    for i, s in enumerate(speeds):
        st = tb.thermal_state(m, s, 300.0, 0.0)  # the load scale and oil fraction act
        for n in nodes:
            assert df[f"{n}_temperature_c"][i] == st.temperature_c(n), n
        assert df["heat_w"][i] == st.total_heat_w and df["churning_heat_w"][i] > 0.0
    preset = tb.Study("thermal", {"speed_rpm": speeds}, {"axial_n": 300.0}).run(progress=False)
    assert (preset["churning_heat_w"] == 0.0).all()
    assert df["model"][0] == df["model"][1] != preset["model"][0] == ""
    # A setting off its default must agree with the calibrated one: the
    # point that contradicts it is its own error row, naming both values.
    rows = tb.Study(
        "thermal",
        {"churning_oil_fraction": [0.01, 0.0]},
        {"model": m, "speed_rpm": 6000.0, "axial_n": 300.0},
    ).run(progress=False)
    assert rows["ok"].to_list() == [True, False] and rows["error_kind"][1] == "ConfigError"
    assert "churning_oil_fraction = 0.0" in rows["error"][1] and "= 0.01" in rows["error"][1]
    assert rows["outer_ring_temperature_c"][0] == df["outer_ring_temperature_c"][0]
    other = tb.Study("thermal", {"speed_rpm": [6000.0]}, {"model": m, "bearing": "6208"})
    assert "bearing = '6208'" in other.run(progress=False)["error"][0]


def test_the_grid_hash_follows_the_model_and_a_worker_rebuilds_it(tmp_path):
    from thermobear.study import models
    from thermobear.study.engine import compute, compute_on_worker

    m = _bearing_model()
    path = m.save(tmp_path / "model.json")

    def study(model) -> tb.Study:
        return tb.Study("thermal", {"speed_rpm": [6000.0, 9000.0]}, {"model": model})

    same = {study(x).grid_hash for x in (m, path, str(path), m.to_json())}
    assert len(same) == 1
    assert study(_bearing_model(oil_fraction=0.02)).grid_hash not in same
    assert tb.Study("thermal", {"speed_rpm": [6000.0, 9000.0]}).grid_hash not in same
    s = study(m)
    spec = json.loads(json.dumps(s.grid.spec()))
    local = compute(s.grid, s.chunk_size, 0, 1)
    models._MODELS.clear()  # a fresh worker: the model comes from the description
    assert_frame_equal(compute_on_worker(spec, s.chunk_size, 0), local)
    assert local["ok"].all()


def test_a_spindle_study_of_a_calibrated_model_is_its_thermal_state():
    sp = tb.Spindle.preset("seed-ceramic-spindle")
    spec = tb.SpindleModelSpec.of_model(sp).with_setting(spin_friction_coefficient=0.08)
    m = _calibrated(spec.with_setting(preload_scale=0.9))
    speeds = [9000.0, 12000.0]
    df = tb.Study("spindle", {"speed_rpm": speeds}, {"model": m, "preload_n": 250.0}).run(
        progress=False
    )
    col = "front_outer_ring_temperature_c"
    for i, s in enumerate(speeds):
        st = tb.thermal_state(m, s, preload_n=250.0)
        for c in (col, "operating_preload_n", "k_xx_n_per_m", "axial_growth_um"):
            assert df[c][i] == st[c][0], c
        assert df[col][i] != sp.thermal_state(s, preload_n=250.0)[col][0]
    wrong = tb.Study("spindle", {"speed_rpm": [9000.0]}, {"model": _bearing_model()})
    assert "a spindle point takes a model of a spindle" in wrong.run(progress=False)["error"][0]


def test_a_gear_point_of_a_calibrated_model_has_its_thermal_support():
    m = _bearing_model("6208")
    fixed = {"model": m, "torque_n_m": 100.0, "transient_periods": 60, "record_periods": 20}
    g = tb.Study("gear", {"speed_rpm": [3000.0]}, fixed).run(progress=False)
    gear = tb.GearPair.preset("seed-electric-drive")
    system = tb.GearSystem(gear, bearings=m, stiffness="thermal", torque_n_m=100.0)
    cell = tb.regime_map(system, [100.0], [3000.0], [1.0], 60, 20)
    assert g["ok"][0] and g["regime"][0] == cell["regime"][0]
    assert g["amplitude_um"][0] == cell["amplitude_um"][0]
    assert g["mean_dte_um"][0] == cell["mean_dte_um"][0]
    plain = tb.regime_map(tb.GearSystem(gear, torque_n_m=100.0), [100.0], [3000.0], [1.0], 60, 20)
    assert g["mean_dte_um"][0] != plain["mean_dte_um"][0]  # another support
    constant = tb.Study("gear", {"speed_rpm": [3000.0]}, {**fixed, "stiffness": "constant"})
    err = constant.run(progress=False)["error"][0]
    assert "stiffness = 'constant'" in err and "stiffness = 'thermal'" in err
