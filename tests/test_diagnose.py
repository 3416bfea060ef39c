"""The discrepancy workflow on synthetic measurements in which the effect is
hidden: data made by the full model with a known setting plus Gaussian
noise, diagnosed from a baseline that lacks it. Rates over fixed seeds (the
model runs once per configuration; the seeds only change the noise)."""

from __future__ import annotations

import numpy as np
import polars as pl
import pytest

import thermobear as tb
from thermobear import diagnosis as D

SPEEDS_RPM = np.linspace(2000.0, 18000.0, 10)
QUANTITIES = [
    "outer_ring_temperature_c",
    "inner_ring_temperature_c",
    "ball_temperature_c",
    "radial_stiffness_seed_n_per_m",
    "heat_w",  # separates churning from spin friction (the suggested extra measurement)
]
SIGMA_K = 0.3  # thermocouple noise [K] (high SNR)
SIGMA_REL = 0.01  # stiffness noise, relative


@pytest.fixture(scope="module")
def full_effects() -> list[str]:
    return [e for e in tb.effects("switch")["name"].to_list() if e != "unbalanced_magnetic_pull"]


@pytest.fixture(scope="module")
def bearing() -> tb.Bearing:
    return tb.Bearing.preset("7008C")


@pytest.fixture(scope="module")
def baseline(bearing, full_effects) -> D.BearingModelSpec:
    return D.BearingModelSpec(bearing, effects=full_effects)


def _conditions() -> pl.DataFrame:
    n = len(QUANTITIES)
    return pl.DataFrame(
        {
            "speed_rpm": np.repeat(SPEEDS_RPM, n),
            "axial_n": 300.0,
            "radial_n": 0.0,
            "quantity": QUANTITIES * len(SPEEDS_RPM),
        }
    )


def _measured(truth: D.BearingModelSpec, seed: int, extra=None) -> pl.DataFrame:
    cond = _conditions()
    allq = truth.predict(cond)
    q = cond["quantity"].to_list()
    val = np.array([allq[qq][i] for i, qq in enumerate(q)])
    sig = np.array(
        [
            SIGMA_K if qq.endswith("temperature_c") else SIGMA_REL * v
            for qq, v in zip(q, val, strict=False)
        ]
    )
    if extra is not None:
        val = val + extra(cond, sig)
    rng = np.random.default_rng(seed)
    noisy = val + rng.normal(size=len(val)) * sig
    return cond.with_columns(pl.Series("value", noisy), pl.Series("sigma", sig))


# ---------------------------------------------------------------- data checks


def test_load_measurements_checks_columns_quantities_values_units():
    good = pl.DataFrame(
        {
            "speed_rpm": [1000.0, 2000.0],
            "preload_n": [300.0, 300.0],
            "quantity": ["outer_ring_temperature_c"] * 2,
            "value": [30.0, 31.0],
        }
    )
    df = tb.load_measurements(good)
    assert df["axial_n"].to_list() == [300.0, 300.0]  # preload_n is the axial load
    assert df["radial_n"].to_list() == [0.0, 0.0]
    assert np.allclose(df["sigma"], 0.5)  # typical thermocouple uncertainty
    with pytest.raises(tb.DataError, match="value"):
        tb.load_measurements(good.drop("value"))
    with pytest.raises(tb.DataError, match="axial_n"):
        tb.load_measurements(good.drop("preload_n"))
    with pytest.raises(tb.DataError, match="quantity = 'temperature_c:Tx'"):
        tb.load_measurements(good.with_columns(pl.lit("temperature_c:Tx").alias("quantity")))
    with pytest.raises(tb.DataError, match="NaN"):
        tb.load_measurements(good.with_columns(pl.Series("value", [30.0, float("nan")])))
    with pytest.raises(tb.DataError, match="not numeric"):
        tb.load_measurements(good.with_columns(pl.Series("value", ["30", "warm"])))
    with pytest.raises(tb.DataError, match="kelvin"):
        tb.load_measurements(good.with_columns(pl.Series("value", [303.15, 304.15])))
    with pytest.raises(tb.DataError, match="N/um|plausible"):
        tb.load_measurements(
            good.with_columns(
                pl.lit("radial_stiffness_seed_n_per_m").alias("quantity"),
                pl.Series("value", [180.0, 175.0]),
            )
        )
    with pytest.raises(tb.DataError, match="sigma"):
        tb.load_measurements(good.with_columns(pl.lit(0.0).alias("sigma")))


def test_candidate_registry_bounds_contain_the_null(baseline):
    c = tb.candidates(baseline, ["outer_ring_temperature_c"])
    assert set(c["kind"].unique()) == {"switch", "parameter"}
    assert (c["lower"] <= c["default"]).all() and (c["default"] <= c["upper"]).all()
    names = c["name"].to_list()
    assert "lubrication_factor_f0" in names and "sensor_offset:outer_ring_temperature_c" in names
    # effects already in the baseline are not candidates; all of them without a model
    assert "spin_friction" not in c.filter(pl.col("kind") == "switch")["name"].to_list()
    every = tb.candidates()
    assert set(tb.effects()["name"]) <= set(every["name"])
    assert every["name"].n_unique() == every.height  # a verdict names one candidate


def test_residual_shape_by_aic():
    rng = np.random.default_rng(0)
    x = np.linspace(1000.0, 9000.0, 12)
    picks = [D.residual_shape(x, rng.normal(size=12))[0] for _ in range(50)]
    # white noise: AIC prefers "none" (it admits a 1-parameter shape with
    # P(chi2_1 > 2) = 16 %, so not always)
    assert picks.count("none") >= 25
    assert picks.count("none") > max(picks.count(k) for k in ("offset", "slope", "growth"))
    ramp = 8.0 * (x - x.min()) / np.ptp(x) + rng.normal(size=12) * 0.3
    assert D.residual_shape(x, ramp)[0] == "slope"
    assert D.residual_shape(x, 6.0 + rng.normal(size=12) * 0.3)[0] == "offset"


# ---------------------------------------------------------------- rates


def _discovery(d) -> bool:
    return d.verdict != "no missing effect supported"


def test_null_case_false_discovery_at_most_5_percent_over_100_seeds(baseline):
    found = [_discovery(tb.diagnose(baseline, _measured(baseline, seed))) for seed in range(100)]
    assert np.mean(found) <= 0.05


def test_hidden_churning_loss_named_at_high_snr_and_gap_shrinks(baseline):
    f0_true = 1.3
    truth = baseline.with_setting(lubrication_factor_f0=f0_true)
    named = covered = 0
    for seed in range(100):
        d = tb.diagnose(baseline, _measured(truth, 1000 + seed))
        if [a["name"] for a in d.accepted] == ["lubrication_factor_f0"] and not d.tie:
            named += 1
            a = d.accepted[0]
            covered += a["lower_95"] <= f0_true <= a["upper_95"]
            # Pooled per quantity over its speed bands (a band of 2-3 points
            # is too few to judge alone): where the gap is signal, it halves.
            gap = (
                d.gap.group_by("quantity")
                .agg(
                    ((pl.col("n") * pl.col("rms_before_sigma") ** 2).sum() / pl.col("n").sum())
                    .sqrt()
                    .alias("before"),
                    ((pl.col("n") * pl.col("rms_after_sigma") ** 2).sum() / pl.col("n").sum())
                    .sqrt()
                    .alias("after"),
                )
                .filter(pl.col("before") > 3.0)
            )
            assert gap.height >= 3
            assert (gap["after"] < 0.5 * gap["before"]).all()
    assert named >= 90
    assert covered >= 0.85 * named  # 95 % profile intervals


def test_sensor_offset_decoy_is_not_a_physical_effect(baseline):
    def offset(cond, sig):
        return np.where(cond["quantity"].to_numpy() == "outer_ring_temperature_c", 2.0, 0.0)

    physical = sensor = 0
    for seed in range(40):
        d = tb.diagnose(baseline, _measured(baseline, 2000 + seed, offset))
        physical += any(a["side"] == "model" for a in d.accepted)
        sensor += [a["name"] for a in d.accepted] == ["sensor_offset:outer_ring_temperature_c"]
    assert physical <= 2
    assert sensor >= 36


def test_hidden_spin_friction_switch_named(bearing, full_effects, baseline):
    # The test hides an effect of a stated strength, independent of the
    # package's default coefficient (which may change): spin friction at
    # mu_s = 0.06 in the truth, and the same coefficient in the baseline,
    # which only lacks the switch (switching it on restores the truth).
    mu_s = 0.06
    truth = baseline.with_setting(spin_friction_coefficient=mu_s)
    no_spin = [e for e in full_effects if e != "spin_friction"]
    base = D.BearingModelSpec(bearing, effects=no_spin, spin_friction_coefficient=mu_s)
    ds = [tb.diagnose(base, _measured(truth, 3000 + s)) for s in range(20)]
    named = sum([a["name"] for a in d.accepted] == ["spin_friction"] for d in ds)
    # spin friction and churning are look-alikes (cosine ~0.99): a tie that
    # contains the true effect is honest, a wrong single name is not; so is
    # "unresolved" (spin friction heat, like an unknown heat source
    # with a smooth speed law, the carrier control: spin friction's own law
    # fits better than the carrier's by more than 3.84 in chi^2 only in about
    # half the seeds, so the rest are "unresolved", spin friction listed)
    tied = sum("spin_friction" in d.tie + [a["name"] for a in d.unresolved] for d in ds)
    wrong = sum(bool(d.accepted) and d.accepted[0]["name"] != "spin_friction" for d in ds)
    assert named >= 5 and named + tied >= 19 and wrong <= 1


def test_effect_outside_registry_is_reported_as_unexplained(baseline):
    def wave(cond, sig):
        x = (cond["speed_rpm"].to_numpy() - 2000.0) / 16000.0
        tb_rows = cond["quantity"].to_numpy() == "ball_temperature_c"
        return np.where(tb_rows, 4.0 * sig * np.sin(2.0 * np.pi * 1.5 * x), 0.0)

    verdicts = [
        tb.diagnose(baseline, _measured(baseline, 4000 + s, wave)).verdict for s in range(20)
    ]
    assert sum(v.startswith("structured residual") for v in verdicts) >= 18


# ---------------------------------------------------------------- outputs


def test_diagnosis_tables_plots_and_cli(tmp_path, baseline):
    import matplotlib

    matplotlib.use("Agg")
    truth = baseline.with_setting(lubrication_factor_f0=1.5)
    meas = _measured(truth, 7)
    d = tb.diagnose(baseline, meas)
    assert (
        d.audit.filter(pl.col("quantity") == "ball_temperature_c")["mean_residual_sigma"].min() > 3
    )
    assert "lubrication_factor_f0" in d.summary()
    ax = tb.plot.diagnosis_fit(d, "ball_temperature_c")
    assert ax.get_ylabel() == "ball temperature [°C]"
    assert tb.plot.diagnosis_residuals(d) is not None
    # the command line: seed B configuration (default effects = all) on its own data
    from thermobear.cli import main

    toml = tmp_path / "system.toml"
    toml.write_text(tb.seed_config("seed_b_7009c"))
    spec, _ = D.model_from_toml(toml)
    truth_b = spec.with_setting(lubrication_factor_f0=1.5)
    csv = tmp_path / "measured.csv"
    _measured(truth_b, 8).drop("axial_n").write_csv(csv)  # loads from [operating]
    out = tmp_path / "out"
    assert main(["diagnose", str(csv), "--model", str(toml), "--out", str(out)]) == 0
    assert (out / "diagnosis_gap.csv").exists() and (out / "diagnosis_residuals.png").exists()
    bad = tmp_path / "bad.csv"
    pl.DataFrame({"speed_rpm": [1.0], "quantity": ["x"], "value": [1.0]}).write_csv(bad)
    assert main(["diagnose", str(bad), "--model", str(toml)]) == 1  # a data error


def test_two_effects_at_once_named_and_jointly_calibrated(baseline):
    """A churning loss and a sensor offset on To together: both are
    accepted over two rounds, then calibrated jointly (the f0 of round 1
    absorbed part of the offset); the joint interval covers the truth."""

    def offset(cond, sig):
        return np.where(cond["quantity"].to_numpy() == "outer_ring_temperature_c", 2.0, 0.0)

    truth = baseline.with_setting(lubrication_factor_f0=1.3)
    both = covered = 0
    for seed in range(10):
        d = tb.diagnose(baseline, _measured(truth, 6000 + seed, offset))
        names = [a["name"] for a in d.accepted]
        if sorted(names) == ["lubrication_factor_f0", "sensor_offset:outer_ring_temperature_c"]:
            both += 1
            f0 = d.accepted[names.index("lubrication_factor_f0")]
            off = d.accepted[names.index("sensor_offset:outer_ring_temperature_c")]
            covered += f0["lower_95"] <= 1.3 <= f0["upper_95"] and (
                off["lower_95"] <= 2.0 <= off["upper_95"]
            )
    assert both >= 9
    assert covered >= 7


def test_holdout_by_run_and_lookalikes(baseline):
    meas = _measured(baseline.with_setting(lubrication_factor_f0=1.5), 11)
    runs = np.where(np.arange(meas.height) % 2 == 0, "a", "b")
    meas = meas.with_columns(pl.Series("run", runs))
    d = tb.diagnose(baseline, meas, holdout=["b"])
    assert d.points.filter(pl.col("heldout"))["run"].unique().to_list() == ["b"]
    assert [a["name"] for a in d.accepted] == ["lubrication_factor_f0"]
    with pytest.raises(tb.DataError, match="run"):
        tb.diagnose(baseline, meas, holdout=["c"])
    # cast iron and steel housings: both iron alloys, conductivity and
    # expansion close -> look-alike fingerprints (cosine > 0.99)
    la = d.lookalikes.filter(
        (pl.col("a") == "housing_material:cast-iron")
        & (pl.col("b") == "housing_material:shaft-steel")
    )
    assert la.height == 1 and la["cosine"][0] > 0.99
    assert la["suggest_quantity"][0] in D.QUANTITIES
    cos = d.fingerprints["cosine"].to_numpy()
    assert np.all(np.abs(cos) <= 1.0 + 1e-12)


# ------------------------------------------------------ calibration inputs


def _rate(baseline, truth, name, seed0, n=100):
    """Seeds where ``name`` is the single accepted candidate, or is in a
    reported tie; and seeds with a wrong single name."""
    named = tied = wrong = 0
    for seed in range(n):
        d = tb.diagnose(baseline, _measured(truth, seed0 + seed))
        names = [a["name"] for a in d.accepted]
        if names == [name] and not d.tie:
            named += 1
        elif name in d.tie or (name in names and d.tie):
            tied += 1
        elif names and names[0] != name:
            wrong += 1
    return named, tied, wrong


def test_hidden_extra_bearing_heat_named_at_high_snr(baseline):
    """Seed B's explanation of its hotter bearings: friction of a magnetic
    pull the model does not apply, i.e. heat at the bearing the baseline
    leaves out (15 W here)."""
    truth = baseline.with_setting(extra_heat_w=15.0)
    named, tied, wrong = _rate(baseline, truth, "extra_heat_w", 8000)
    assert named + tied >= 90 and wrong <= 5, (named, tied, wrong)


def test_hidden_housing_conductance_named_at_high_snr(baseline):
    """A housing that sheds its heat three times better than the bare
    natural-convection cylinder assumed (fins, air flow or conduction into
    the machine frame): cooler, at nearly unchanged friction heat. (At
    scale 0.6 the change is within ~2 sigma; the oil-air temperature offset
    is its documented look-alike at low SNR.)"""
    truth = baseline.with_setting(housing_conductance_scale=3.0)
    named, tied, wrong = _rate(baseline, truth, "housing_conductance_scale", 9000)
    assert named + tied >= 90 and wrong <= 5, (named, tied, wrong)


def test_calibration_inputs_reach_the_thermal_model(bearing):
    base = tb.thermal_state(bearing, 12000.0, 300.0)
    same = tb.thermal_state(
        bearing, 12000.0, 300.0, extra_heat_w=0.0, housing_conductance_scale=1.0
    )
    assert same.temperature_c("Tb") == base.temperature_c("Tb")  # defaults = baseline
    hot = tb.thermal_state(bearing, 12000.0, 300.0, extra_heat_w=20.0)
    h = hot.heat
    assert h.filter(pl.col("source") == "extra")["heat_w"][0] == 20.0
    # heat balance: every source, the extra one included, leaves the network
    assert hot.boundary_flows["heat_w"].sum() == pytest.approx(h["heat_w"].sum(), rel=1e-6)
    assert hot.temperature_c("Tb") > base.temperature_c("Tb")
    cool = tb.thermal_state(bearing, 12000.0, 300.0, housing_conductance_scale=3.0)
    assert cool.temperature_c("Th") < base.temperature_c("Th")
    with pytest.raises(tb.ConfigError, match="extra_heat_w"):
        tb.thermal_state(bearing, 12000.0, 300.0, extra_heat_w=-1.0)
    with pytest.raises(tb.ConfigError, match="housing_conductance_scale"):
        tb.stiffness_curve(
            bearing, [6000.0], axial_n=300.0, mode="thermal", housing_conductance_scale=0.0
        )
    c = tb.candidates()
    for name in ("extra_heat_w", "housing_conductance_scale"):
        row = c.filter(pl.col("name") == name)
        assert row["kind"][0] == "parameter" and row["lower"][0] <= row["default"][0]


def test_model_section_carries_the_calibration_inputs():
    text = tb.seed_config("seed_b_7009c")
    assert "[model]" in text
    text = text.replace(
        "[model]", "[model]\nextra_heat_w = 7.5\nhousing_conductance_scale = 2.0", 1
    )
    spec, _ = D.model_from_toml(text)
    assert spec.options["extra_heat_w"] == 7.5
    assert spec.options["housing_conductance_scale"] == 2.0
    with pytest.raises(tb.ThermobearError, match="extra_heat"):
        D.model_from_toml(text.replace("extra_heat_w =", "extra_heat ="))
