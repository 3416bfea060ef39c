"""Seed B's reproduction rows: each counterpart figure of the ceramic
motorized-spindle study shows what its seed figure shows (trend, ordering of
the curves), and the paper's quoted numbers are met within a stated
tolerance or differ for the reason the row states (the numbers quoted in
each test come from the seed B study's text; the quick demo's grids).
"""

from __future__ import annotations

import ast
from pathlib import Path

import numpy as np
import polars as pl
import pytest

from thermobear.studies.reproduction import STATUSES
from thermobear.studies.reproduction_seed_b import ROWS
from thermobear.studies.seed_b_spindle import study_seed_b_spindle
from thermobear.studies.seed_b_vibration import study_seed_b_vibration

#: Result figures and tables of seed B (drawings exempt: Figs. 1, 7, 9-11, 18).
SEED_B_ITEMS = {f"Fig. {n}" for n in (2, 3, 4, 5, 6, 8, 12, 13, 14, 15, 16, 17, 19, 20, 21)}
SEED_B_ITEMS |= {"Table 1", "Table 2", "Table 3"}


@pytest.fixture(scope="module")
def demo(tmp_path_factory: pytest.TempPathFactory) -> Path:
    out = tmp_path_factory.mktemp("seed_b_demo")
    study_seed_b_spindle(out / "seed_b_spindle", True)
    study_seed_b_vibration(out / "seed_b_vibration", True)
    return out


def _read(demo: Path, stem: str) -> pl.DataFrame:
    return pl.read_parquet(demo / "seed_b_spindle" / f"{stem}.parquet")


@pytest.fixture(scope="module")
def mech(demo: Path) -> pl.DataFrame:
    return _read(demo, "seed_b_contact_and_stiffness").sort("preload_n", "speed_rpm")


def _at(df: pl.DataFrame, col: str, **where: float) -> float:
    for k, v in where.items():
        df = df.filter(pl.col(k) == v)
    assert df.height == 1, where
    return float(df[col][0])


def _series(df: pl.DataFrame, col: str, **where: float) -> np.ndarray:
    for k, v in where.items():
        df = df.filter(pl.col(k) == v)
    return df[col].to_numpy()


# -- the table itself -------------------------------------------------------


def test_rows_cover_every_result_figure_once_with_existing_counterparts(demo: Path) -> None:
    assert [r.item for r in ROWS if r.item in SEED_B_ITEMS] == [r.item for r in ROWS]
    assert {r.item for r in ROWS} == SEED_B_ITEMS and len(ROWS) == len(SEED_B_ITEMS)
    tests = {
        n.name
        for n in ast.parse(Path(__file__).read_text()).body
        if isinstance(n, ast.FunctionDef) and n.name.startswith("test_")
    }
    for r in ROWS:
        assert r.seed == "B" and r.status in STATUSES
        assert r.status == "reproduced" or len(r.reason) > 40, r.item
        found = list(demo.glob(f"{r.figure}.*"))
        assert found, f"{r.item}: no demo file {r.figure}"
        kind, number = r.item.replace(".", "").lower().split()
        assert f"_{kind}{int(number):02d}_" in r.figure or f"_{kind}{number}_" in r.figure
        path, name = r.test.split("::")
        assert path == "tests/test_reproduction_seed_b.py" and name in tests, r.test


# -- thermal results --------------------------------------------------------


def test_fig02_convection_coefficients(demo: Path) -> None:
    """Coefficients rise nonlinearly with speed; bearing-air above shaft
    end-air; the water jacket and natural convection do not depend on speed."""
    h = _read(demo, "seed_b_fig02_convection_coefficients").sort("speed_rpm")
    bearing = _series(h.filter(pl.col("link") == "front_inner-oil"), "film_coefficient_w_per_m2_k")
    nose = _series(h.filter(pl.col("link") == "nose-air"), "film_coefficient_w_per_m2_k")
    for v in (bearing, nose):
        assert np.all(np.diff(v) > 0) and np.all(np.diff(v, 2) < 0)  # rising, concave
    assert np.all(bearing > 10.0 * nose)
    # laminar films: h ~ n^0.5, so doubling the speed multiplies h by sqrt(2)
    n = _series(h.filter(pl.col("link") == "nose-air"), "speed_rpm")
    i6, i12 = int(np.flatnonzero(n == 6000.0)[0]), int(np.flatnonzero(n == 12000.0)[0])
    assert bearing[i12] / bearing[i6] == pytest.approx(np.sqrt(2.0), rel=1e-9)
    for link in ("sleeve-water", "housing_front-air"):
        v = _series(h.filter(pl.col("link") == link), "film_coefficient_w_per_m2_k")
        assert np.ptp(v) == 0.0


def test_convection_coefficients_follow_their_laws() -> None:
    """Natural convection h = C dT^0.25 (16 K doubles h against 1 K); forced
    films do not depend on the temperature difference; a negative difference
    is a ConfigError naming it."""
    import thermobear as tb

    sp = tb.Spindle.preset("seed-ceramic-spindle")
    h1, h16 = (
        sp.convection_coefficients([9000.0], temperature_difference_k=dt).sort("link")
        for dt in (1.0, 16.0)
    )
    ratio = dict(
        zip(
            h1["link"],
            (h16["film_coefficient_w_per_m2_k"] / h1["film_coefficient_w_per_m2_k"]).to_list(),
            strict=True,
        )
    )
    assert ratio["housing_front-air"] == pytest.approx(2.0, rel=1e-12)
    assert ratio["front_inner-oil"] == pytest.approx(1.0, rel=1e-12)
    with pytest.raises(tb.ConfigError, match="temperature_difference_k"):
        sp.convection_coefficients([9000.0], temperature_difference_k=-1.0)


def test_table1_convection_12000rpm(demo: Path) -> None:
    """One coefficient per boundary at 12,000 rpm, equal to Fig. 2's."""
    t = _read(demo, "seed_b_table1_convection_12000rpm")
    h = _read(demo, "seed_b_fig02_convection_coefficients").filter(pl.col("speed_rpm") == 12000.0)
    assert t["link"].to_list() == h["link"].to_list() and t["link"].n_unique() == t.height
    assert t["film_coefficient_w_per_m2_k"].to_list() == h["film_coefficient_w_per_m2_k"].to_list()
    assert all(len(b) > 5 for b in t["boundary"])


def test_tables2_3_parameters(demo: Path) -> None:
    """The assumed parameters stand in for the lost tables: the 7009C/7008C
    presets' catalogue envelopes and the conditions the text states."""
    b = _read(demo, "seed_b_table2_bearing_parameters")
    rows = {r["bearing"]: r for r in b.iter_rows(named=True)}
    f, r = rows["7009C-hybrid"], rows["7008C-hybrid"]
    assert (f["bore_mm"], f["outer_diameter_mm"], f["width_mm"]) == (45.0, 75.0, 16.0)
    assert (r["bore_mm"], r["outer_diameter_mm"], r["width_mm"]) == (40.0, 68.0, 15.0)
    assert f["free_contact_angle_deg"] == pytest.approx(15.0)
    p = dict(_read(demo, "seed_b_table3_spindle_parameters").iter_rows())
    assert float(p["water_flow_l_min"]) == 10.0 and float(p["ambient_temperature_c"]) == 25.0
    assert float(p["water_temperature_c"]) == 18.0 and float(p["preload_n"]) == 400.0


def test_fig03_temperature_field(demo: Path) -> None:
    """Balls hottest of the bearing parts, stator below rotor, the sleeve by
    the cooling jacket the coolest; as in seed B the balls are the hottest
    nodes of the spindle (the fitted heat puts the bearing friction above
    the motor losses). Seed B has the front bearing above the rear; with
    the load friction its Fig. 6 asks for, the smaller rear bearing makes
    nearly the front's heat: the front outer ring stays above the rear, the
    balls of both sets come within 1 K (the row's reason)."""
    f = _read(demo, "seed_b_fig03_temperature_field")
    t = dict(zip(f["node"], f["temperature_c"], strict=True))
    for side in ("front", "rear"):
        assert t[f"{side}_ball"] > t[f"{side}_inner_ring"] > t[f"{side}_outer_ring"]
    assert t["front_outer_ring"] > t["rear_outer_ring"]
    assert abs(t["front_ball"] - t["rear_ball"]) < 1.0
    assert t["stator"] < t["rotor"]
    assert min(t.values()) == t["sleeve"]
    assert max(t.values()) == max(t["front_ball"], t["rear_ball"])
    state = _read(demo, "seed_b_steady_vs_speed").filter(pl.col("speed_rpm") == 12000.0)
    assert t["rotor"] == pytest.approx(float(state["rotor_temperature_c"][0]), abs=0.0)


def test_fig04_transient(demo: Path) -> None:
    """Temperatures rise ever more slowly; near-steady after 5-25 min
    (seed B: about 21 min; ours about 9 min, the row's reason); the rear
    outer ring follows below the front, the rear balls and inner ring
    within 1 K of the front's (Fig. 3's reason)."""
    tr = _read(demo, "seed_b_transient_12000rpm")
    t = tr["time_s"].to_numpy() / 60.0
    for side in ("front", "rear"):
        v = tr[f"{side}_inner_ring_temperature_c"].to_numpy()
        # the quick demo's 5 s step rings for the first step or two
        assert np.all(np.diff(v[t >= 1.0]) >= -1e-9)
        rise = (v - v[0]) / (v[-1] - v[0])
        t95 = t[np.argmax(rise >= 0.95)]
        assert 5.0 <= t95 <= 25.0, (side, t95)
        assert (v[np.argmax(t >= 5.0)] - v[0]) > 0.5 * (v[-1] - v[0])  # slowing rise
    end = tr.row(-1, named=True)
    assert end["front_outer_ring_temperature_c"] > end["rear_outer_ring_temperature_c"]
    for part in ("ball", "inner_ring"):
        assert abs(end[f"front_{part}_temperature_c"] - end[f"rear_{part}_temperature_c"]) < 1.0


def test_fig05_temperatures_vs_speed(demo: Path) -> None:
    """Ball > inner > outer ring; the front outer ring above the rear with a
    gap that grows with speed, the balls of both sets within 0.5 K (seed B:
    front above rear, Fig. 3's reason); at 18,000 rpm the front inner ring
    and ball within seed B's 3 K of its 49.8 and 64.8 C, the outer ring
    below its 38.9 C by less than 6 K: the heat fitted to these and Fig. 6's
    500 N ball cannot meet all four (the row's reason)."""
    s = _read(demo, "seed_b_steady_vs_speed").sort("speed_rpm")
    for side in ("front", "rear"):
        b, i, o = (
            s[f"{side}_{p}_temperature_c"].to_numpy() for p in ("ball", "inner_ring", "outer_ring")
        )
        assert np.all(i > o)
        assert np.all((b > i)[1:]) and (side == "rear" or b[0] > i[0])  # rear: from 12,000 rpm
        assert np.all(np.diff(b) > 0) and np.all(np.diff(o) > 0)
        assert (b - i)[-1] > (b - i)[0]
    gap = s["front_outer_ring_temperature_c"].to_numpy()
    gap = gap - s["rear_outer_ring_temperature_c"].to_numpy()
    assert np.all(gap > 0) and gap[-1] > gap[0]
    balls = s["front_ball_temperature_c"].to_numpy() - s["rear_ball_temperature_c"].to_numpy()
    assert np.all(np.abs(balls) < 0.5)
    hi = s.row(-1, named=True)
    assert hi["front_inner_ring_temperature_c"] == pytest.approx(49.8, abs=3.0)
    assert hi["front_ball_temperature_c"] == pytest.approx(64.8, abs=3.0)
    assert 0.0 < 38.9 - hi["front_outer_ring_temperature_c"] < 6.0


def test_fig06_ball_temperature_vs_preload(mech: pl.DataFrame) -> None:
    """Ball temperature rises with preload at every speed, more at high
    speed; the rise from 300 to 500 N at 18,000 rpm, carried by the fitted
    load friction, is between 40 % of seed B's 17.1 K and all of it (with
    Harris' table f1 it was under a tenth; the row's reason)."""
    rises = []
    for n in (6000.0, 12000.0, 18000.0):
        v = _series(mech, "front_ball_temperature_c", speed_rpm=n)
        assert np.all(np.diff(v) > 0)
        rises.append(v[-1] - v[0])
    assert rises[-1] > rises[0]
    assert 0.4 * 17.1 < rises[-1] < 17.1


def test_fig08_thermal_displacement(demo: Path) -> None:
    """Radial thermal displacement rises with speed, steel balls above
    Si3N4 at both bearings (seed B: 16.68 against 8.2 um at 18,000 rpm; ours
    smaller, the ratio kept above 1.4); the axial groove-centre offset is
    negative and smaller than the radial (the row's reason)."""
    d = _read(demo, "seed_b_thermal_displacement").sort("speed_rpm")
    for col in ("thermal_radial_displacement_um", "rear_thermal_radial_displacement_um"):
        cer = d.filter(pl.col("balls") == "Si3N4")[col].to_numpy()
        steel = d.filter(pl.col("balls") == "steel")[col].to_numpy()
        assert np.all(np.diff(cer) > 0) and np.all(np.diff(steel) > 0)
        assert np.all(steel > cer)
        assert steel[-1] / cer[-1] > 1.4
    hi = d.filter((pl.col("balls") == "Si3N4") & (pl.col("speed_rpm") == 18000.0)).row(
        0, named=True
    )
    assert hi["thermal_radial_displacement_um"] < 8.2
    for side in ("front", "rear"):
        ax = d[f"{side}_axial_thermal_displacement_um"].to_numpy()
        assert np.all(ax < 0) and np.all(
            np.abs(ax) < d["thermal_radial_displacement_um"].to_numpy()
        )


# -- bearing mechanics ----------------------------------------------------------


def test_fig12_radial_stiffness(mech: pl.DataFrame) -> None:
    """Stiffness rises with preload; uncoupled it falls with speed (seed B
    Fig. 12a); the thermal state stiffens every point and offsets the
    centrifugal softening in part at 300 N and wholly at 500 N, where the
    coupled stiffness rises with speed as in seed B's Fig. 12b; the largest
    per-bearing value within 10 % of seed B's 2.74e8 (read as N/m)."""
    for col in ("k_xx_isothermal_n_per_m", "k_xx_n_per_m"):
        for n in (6000.0, 12000.0, 18000.0):
            assert np.all(np.diff(_series(mech, col, speed_rpm=n)) > 0)
    for p in (300.0, 400.0, 500.0):
        iso = _series(mech, "k_xx_isothermal_n_per_m", preload_n=p)
        cpl = _series(mech, "k_xx_n_per_m", preload_n=p)
        assert np.all(np.diff(iso) < 0)
        assert cpl[-1] - cpl[0] > iso[-1] - iso[0]
    cpl = _series(mech, "k_xx_n_per_m", preload_n=500.0)
    assert cpl[-1] > cpl[0]
    assert np.all(mech["k_xx_n_per_m"].to_numpy() > mech["k_xx_isothermal_n_per_m"].to_numpy())
    assert float(mech["k_xx_n_per_m"].max()) / 2.0 == pytest.approx(2.74e8, rel=0.10)


def test_fig13_contact_angles(mech: pl.DataFrame) -> None:
    """(a) Uncoupled, the inner angle rises and the outer falls with speed
    (centrifugal force); seed B's 300 N numbers match ours with inner and
    outer exchanged, within 1 deg; the changes shrink with preload. (b) The
    thermal state lowers both angles at 400 N; with it the outer angle falls
    from 6,000 to 18,000 rpm by seed B's 2.68 deg (printed for the inner,
    read exchanged) within a quarter."""
    inner = _series(mech, "inner_contact_angle_isothermal_deg", preload_n=300.0)
    outer = _series(mech, "outer_contact_angle_isothermal_deg", preload_n=300.0)
    assert np.all(np.diff(inner) > 0) and np.all(np.diff(outer) < 0)
    assert outer[0] == pytest.approx(15.54, abs=1.0) and outer[-1] == pytest.approx(13.31, abs=1.0)
    assert inner[0] == pytest.approx(16.13, abs=1.0) and inner[-1] == pytest.approx(18.69, abs=1.0)
    in5 = _series(mech, "inner_contact_angle_isothermal_deg", preload_n=500.0)
    out5 = _series(mech, "outer_contact_angle_isothermal_deg", preload_n=500.0)
    assert in5[-1] - in5[0] < inner[-1] - inner[0]
    assert out5[0] - out5[-1] < outer[0] - outer[-1]
    m4 = mech.filter(pl.col("preload_n") == 400.0)
    for side in ("inner", "outer"):
        coupled = m4[f"{side}_contact_angle_deg"].to_numpy()
        assert np.all(coupled < m4[f"{side}_contact_angle_isothermal_deg"].to_numpy())
    drop = _at(m4, "outer_contact_angle_deg", speed_rpm=6000.0) - _at(
        m4, "outer_contact_angle_deg", speed_rpm=18000.0
    )
    assert drop == pytest.approx(2.68, rel=0.25)


def test_fig14_contact_loads(mech: pl.DataFrame) -> None:
    """Loads rise with preload; uncoupled, the outer load rises and the inner
    falls with speed; outer above inner; at 18,000 rpm the 500 N outer load
    within 20 % of seed B's 104.35 N and its ratio to 300 N within 0.1 of
    1.57; the thermal state raises the 400 N outer load (seed B: +10.78 N)."""
    for side in ("outer", "inner"):
        for n in (6000.0, 18000.0):
            assert np.all(np.diff(_series(mech, f"{side}_load_max_isothermal_n", speed_rpm=n)) > 0)
    for p in (300.0, 400.0, 500.0):
        out_iso = _series(mech, "outer_load_max_isothermal_n", preload_n=p)
        in_iso = _series(mech, "inner_load_max_isothermal_n", preload_n=p)
        assert np.all(np.diff(out_iso) > 0) and np.all(np.diff(in_iso) < 0)
        assert np.all(out_iso > in_iso)
        assert np.all(
            _series(mech, "outer_load_max_n", preload_n=p)
            > _series(mech, "inner_load_max_n", preload_n=p)
        )
    o5 = _at(mech, "outer_load_max_isothermal_n", speed_rpm=18000.0, preload_n=500.0)
    o3 = _at(mech, "outer_load_max_isothermal_n", speed_rpm=18000.0, preload_n=300.0)
    assert o5 == pytest.approx(104.35, rel=0.2) and o5 / o3 == pytest.approx(1.57, abs=0.1)
    extra = _at(mech, "outer_load_max_n", speed_rpm=18000.0, preload_n=400.0) - _at(
        mech, "outer_load_max_isothermal_n", speed_rpm=18000.0, preload_n=400.0
    )
    assert 10.78 <= extra <= 3.0 * 10.78


def test_fig15_radial_displacement(mech: pl.DataFrame, demo: Path) -> None:
    """(a) Radial thermal displacement rises with speed and preload, below
    seed B's 9.84 um; (b) at 12,000 rpm the displacement without thermal
    displacement falls with preload and flattens, near seed B's 2 um."""
    for p in (300.0, 400.0, 500.0):
        assert np.all(np.diff(_series(mech, "thermal_radial_displacement_um", preload_n=p)) > 0)
    for n in (6000.0, 12000.0, 18000.0):
        assert np.all(np.diff(_series(mech, "thermal_radial_displacement_um", speed_rpm=n)) > 0)
    assert float(mech["thermal_radial_displacement_um"].max()) < 9.84
    scan = (
        _read(demo, "seed_b_preload_scan").filter(pl.col("speed_rpm") == 12000.0).sort("preload_n")
    )
    p = scan["preload_n"].to_numpy()
    u = scan["mechanical_radial_displacement_um"].to_numpy()
    assert np.all(np.diff(u) < 0)
    slope = np.diff(u) / np.diff(p)
    assert abs(slope[-1]) < abs(slope[0]) / 4.0
    assert float(u[p >= 460.0][0]) == pytest.approx(2.0, abs=1.0)


def test_fig16_optimal_preload(demo: Path) -> None:
    """The preload of least total displacement exists inside the scan at each
    speed and the least displacement grows with speed (seed B: 6.5 um at
    12,000 rpm, 1.56 x at 18,000); ours rises with speed where seed B's falls
    from 400 to 390 N (the row's reason)."""
    best = _read(demo, "seed_b_optimal_preload").sort("speed_rpm")
    d = best["min_radial_displacement_um"].to_numpy()
    assert np.all(np.diff(d) > 0)
    assert d[0] == pytest.approx(6.5, abs=2.0)
    assert 1.0 < d[-1] / d[0] < 1.56
    opt = best["optimal_preload_n"].to_numpy()
    assert np.all(np.diff(opt) >= 0) and opt[-1] > 390.0


def test_fig17_compensation(demo: Path) -> None:
    """Axial growth and compensation preload rise with speed; the preload is
    the fitted spring rate times the growth; from the room temperature our
    growth rises less from 12,000 to 18,000 rpm than seed B's, which doubles
    (the row's reason)."""
    c = _read(demo, "seed_b_compensation_preload").sort("speed_rpm")
    u = c["axial_growth_um"].to_numpy()
    f = c["compensation_preload_n"].to_numpy()
    rate = c["spring_rate_n_per_um"].to_numpy()
    assert np.all(np.diff(u) > 0)
    assert f == pytest.approx(rate * u, rel=1e-6)
    assert 1.0 < u[-1] / u[0] < 0.8 * 35.38 / 17.92


def test_fig19_outer_ring_vs_measurement(demo: Path) -> None:
    """Front outer ring above rear at every speed and in time; the rear
    within two sensor sigmas (1 K) of the measured 30.1 C, the front 2-4 K
    below the measured 33.7 C at 12,000 rpm (the row's reason)."""
    s = _read(demo, "seed_b_steady_vs_speed")
    front, rear = (s[f"{k}_outer_ring_temperature_c"].to_numpy() for k in ("front", "rear"))
    assert np.all(front > rear)
    tr = _read(demo, "seed_b_transient_12000rpm")
    at20 = tr.filter(pl.col("time_s") >= 20 * 60.0).row(0, named=True)
    assert at20["front_outer_ring_temperature_c"] > at20["rear_outer_ring_temperature_c"]
    assert at20["rear_outer_ring_temperature_c"] == pytest.approx(30.1, abs=1.0)
    assert 2.0 < 33.7 - at20["front_outer_ring_temperature_c"] < 4.0
    assert (demo / "seed_b_spindle" / "seed_b_fig19_outer_ring_vs_measurement.png").exists()


# -- vibration ------------------------------------------------------------------


def test_fig20_spectrum(demo: Path) -> None:
    """1X dominates the spectrum, far above 2X and 3X (seed B: 7.53 against
    0.398 and 0.708 mm/s); the unbalance pinned by seed B's 1X gives its
    level within 15 % (the time record's window and the uncoupled rows against
    the fit's steady coupled response), but no 2X or 3X of seed B's size (the
    row's reason). With the unbalanced magnetic pull, the cause seed B gives
    for its measured spectrum, 1X and 2X both grow."""
    v = "seed_b_vibration"
    o = pl.read_parquet(demo / v / "seed_b_spectrum_orders_12000rpm.parquet")
    u = pl.read_parquet(demo / v / "seed_b_spectrum_orders_12000rpm_magnetic_pull.parquet")
    x = o["velocity_mm_s"].to_numpy()
    y = u["velocity_mm_s"].to_numpy()
    assert x[0] > 100.0 * max(x[1], x[2])
    assert x[0] == pytest.approx(7.53, rel=0.15)
    assert max(x[1], x[2]) < 0.398 / 100.0
    assert y[0] > x[0] and y[1] > 2.0 * x[1]


def test_fig21_vibration_vs_speed(demo: Path) -> None:
    """Velocity rises with speed; the thermally coupled spindle vibrates
    more than the uncoupled (seed B at 18,000 rpm: 18.78 against 16.10 mm/s,
    +17 %); with the unbalance pinned by the 12,000 rpm 1X amplitude, the
    coupled 18,000 rpm level is seed B's within 25 % (an unbalance response
    grows as n^3 below the first critical speed)."""
    t = pl.read_parquet(demo / "seed_b_vibration" / "seed_b_vibration_vs_speed.parquet")
    unc = t.filter(pl.col("case") == "seed-ceramic-spindle: uncoupled").sort("speed_rpm")
    cpl = t.filter(pl.col("case") == "seed-ceramic-spindle: thermally coupled").sort("speed_rpm")
    for d in (unc, cpl):
        assert np.all(np.diff(d["velocity_rms_mm_s"].to_numpy()) > 0)
    ratio = cpl["velocity_rms_mm_s"][-1] / unc["velocity_rms_mm_s"][-1]
    assert 1.0 < ratio < 2.0
    assert cpl["velocity_rms_mm_s"][-1] == pytest.approx(18.78, rel=0.25)
