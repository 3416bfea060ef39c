"""Materials, bearing construction, Hertz contact and the error hierarchy."""

import math

import pytest

import thermobear as tb


def test_error_hierarchy():
    assert issubclass(tb.ConfigError, tb.ThermobearError)
    assert issubclass(tb.ConvergenceError, tb.ThermobearError)
    assert issubclass(tb.ThermalRunawayError, tb.ConvergenceError)
    assert issubclass(tb.DataError, tb.ThermobearError)


def test_seed_a_free_contact_angle():
    # Seed A Table 1: Pd = 0.04 mm with f_i 0.52, f_o 0.53, D 12 mm -> 14.8351 deg.
    g = tb.Bearing.preset("6208").geometry
    assert g["free_contact_angle_deg"] == pytest.approx(14.8351, abs=1e-3)
    assert g["ball_count"] == 9


def test_presets_and_material_classes():
    for name in tb.Bearing.preset_names():
        b = tb.Bearing.preset(name)
        assert b.name == name
    assert tb.Bearing.preset("7009C-hybrid").material_class == "hybrid"
    assert tb.Bearing.preset("7009C").material_class == "steel"
    assert tb.Bearing.preset("7008C-ceramic").material_class == "ceramic"


def test_material_override_and_custom():
    soft = tb.Material("soft", base="52100", youngs_modulus_gpa=150.0)
    assert soft.youngs_modulus_gpa == pytest.approx(150.0)
    assert soft.poisson_ratio == pytest.approx(tb.Material.preset("52100").poisson_ratio)
    b_soft = tb.Bearing.deep_groove(
        ball_count=9,
        ball_diameter_mm=12,
        pitch_diameter_mm=60,
        inner_conformity=0.52,
        outer_conformity=0.53,
        diametral_clearance_mm=0.04,
        bore_mm=40,
        outer_diameter_mm=80,
        width_mm=18,
        ring_material=soft,
        ball_material=soft,
    )
    b = tb.Bearing.preset("6208")
    # Hertz: K scales with E' (same geometry), so a softer material has a smaller K.
    k_soft = b_soft.contact("inner", 15.0)["load_deflection_constant_n_per_m1_5"]
    k = b.contact("inner", 15.0)["load_deflection_constant_n_per_m1_5"]
    e_ratio = (
        b_soft.contact("inner", 15.0)["reduced_modulus_pa"]
        / b.contact("inner", 15.0)["reduced_modulus_pa"]
    )
    assert k_soft / k == pytest.approx(e_ratio, rel=1e-12)
    with pytest.raises(tb.ConfigError, match="youngs_modulus_gpa"):
        tb.Material("bad", base="52100", youngs_modulus_gpa=-1.0)
    with pytest.raises(tb.ConfigError, match="hardness"):
        tb.Material("bad", base="52100", hardness=60)


def test_hertz_exact_vs_hamrock_brewe_and_load_law():
    b = tb.Bearing.preset("6208")
    for raceway in ("inner", "outer"):
        exact = b.contact(raceway, 20.0, 800.0)
        approx = b.contact(raceway, 20.0, 800.0, exact=False)
        assert approx["ellipticity"] == pytest.approx(exact["ellipticity"], rel=0.03)
        # Q = K delta^1.5 and dQ/d delta = 1.5 K^(2/3) Q^(1/3) 
        k = exact["load_deflection_constant_n_per_m1_5"]
        assert k * exact["deflection_m"] ** 1.5 == pytest.approx(800.0, rel=1e-10)
        assert exact["contact_stiffness_n_per_m"] == pytest.approx(
            1.5 * k ** (2 / 3) * 800.0 ** (1 / 3), rel=1e-10
        )
        # p0 = 3 Q / (2 pi a b)
        p0 = 1.5 * 800.0 / (math.pi * exact["semi_major_m"] * exact["semi_minor_m"])
        assert exact["max_pressure_pa"] == pytest.approx(p0, rel=1e-12)
    # The inner contact is more conforming across, less in rolling: higher pressure.
    assert (
        b.contact("inner", 20.0, 800.0)["max_pressure_pa"]
        > b.contact("outer", 20.0, 800.0)["max_pressure_pa"]
    )


@pytest.mark.parametrize(
    "kwargs, field",
    [
        (dict(inner_conformity=0.5), "inner_conformity"),
        (dict(outer_conformity=0.49), "outer_conformity"),
        (dict(ball_diameter_mm=25.0), "ball_diameter_mm"),
        (dict(diametral_clearance_mm=-0.01), "diametral_clearance_mm"),
        (dict(ball_diameter_mm=float("nan")), "ball_diameter_mm"),
        (dict(ball_count=40), "ball_count"),
        (dict(ball_count=1), "ball_count"),
    ],
)
def test_bad_geometry_names_field(kwargs, field):
    base = dict(
        ball_count=9,
        ball_diameter_mm=12,
        pitch_diameter_mm=60,
        inner_conformity=0.52,
        outer_conformity=0.53,
        diametral_clearance_mm=0.04,
        bore_mm=40,
        outer_diameter_mm=80,
        width_mm=18,
    )
    base.update(kwargs)
    with pytest.raises(tb.ConfigError, match=field):
        tb.Bearing.deep_groove(**base)


def test_config_rejects_unknown_keys_by_name():
    with pytest.raises(tb.ConfigError, match="ball_diameter"):
        tb.Bearing.from_toml('[bearing]\npreset = "6208"\nball_diameter = 12.0\n')
    with pytest.raises(tb.ConfigError, match="warp_drive"):
        tb.load_config('[model]\neffects = ["warp_drive"]\n')


def test_seed_configs_ship_inside_the_package():
    names = tb.seed_config_names()
    assert "seed_a_6208" in names and "seed_b_7009c" in names
    b = tb.Bearing.from_toml(tb.seed_config("seed_a_6208"))
    assert b.name == "6208"


def test_effects_registry():
    df = tb.effects()
    assert {"centrifugal_force", "gyroscopic_moment", "ring_centrifugal_expansion"} <= set(
        df["name"]
    )
