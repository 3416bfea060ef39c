"""One name per quantity: every public parameter, result property and frame
column that carries a unit is in the glossary, the glossary and its docs
page agree, and the names of older releases still work and warn."""

from __future__ import annotations

import inspect
import re
import warnings
from pathlib import Path

import numpy as np
import polars as pl
import pytest

import thermobear as tb
from thermobear.glossary import GLOSSARY, UNIT_SUFFIXES

DOCS = Path(__file__).resolve().parents[1] / "docs" / "glossary.md"

#: Names that end in a unit token by accident. ``zero_one_k`` is the
#: (dimensionless) K statistic of the 0-1 test for chaos, not a kelvin.
NOT_QUANTITIES = {"zero_one_k"}


def has_unit(name: str) -> bool:
    """Whether a name ends in a unit token (``axial_n``, ``speed_rpm`` ...)."""
    return any(name.endswith(s) and len(name) > len(s) for s in UNIT_SUFFIXES)


def not_in_glossary(names) -> list[str]:
    return sorted({n for n in names if has_unit(n) and n not in NOT_QUANTITIES} - set(GLOSSARY))


# -- the glossary itself ------------------------------------------------------


def test_glossary_frame_matches_the_mapping():
    df = tb.glossary()
    assert df.columns == ["name", "unit", "symbol", "description"]
    assert df.height == len(GLOSSARY)
    assert df["name"].n_unique() == df.height
    row = df.filter(pl.col("name") == "outer_ring_temperature_c").row(0, named=True)
    assert (row["unit"], row["symbol"]) == ("C", "To")


def test_docs_page_is_the_same_table():
    rows = {}
    for line in DOCS.read_text().splitlines():
        m = re.match(r"^\| `([a-z0-9_]+)` \| (.*?) \| (.*?) \| (.*?) \|$", line)
        if m:
            rows[m.group(1)] = (m.group(2), m.group(3), m.group(4))
    assert rows == {k: tuple(v) for k, v in GLOSSARY.items()}


def test_every_glossary_name_ends_in_its_unit():
    unit_of_suffix = {
        "_w_per_m2_k": "W/(m^2 K)",
        "_cm3_per_min": "cm^3/min",
        "_cm3_per_h": "cm^3/h",
        "_l_per_min": "l/min",
        "_m_per_s": "m/s",
        "_n_m_per_rad": "N m/rad",
        "_mm_rpm": "mm rpm",
        "_mpa": "MPa",
        "_n_per_rad": "N/rad",
        "_n_per_um": "N/um",
        "_n_per_m": "N/m",
        "_mm_s": "mm/s",
        "_n_m": "N m",
        "_cst": "mm^2/s",
        "_rpm": "rpm",
        "_deg": "deg",
        "_rad": "rad",
        "_hz": "Hz",
        "_mm": "mm",
        "_um": "um",
        "_n": "N",
        "_m": "m",
        "_c": "C",
        "_k": "K",
        "_w": "W",
        "_s": "s",
    }
    for name, entry in GLOSSARY.items():
        suffix = next((s for s in UNIT_SUFFIXES if name.endswith(s)), None)
        if suffix is None:  # a dimensionless coefficient or a rate
            assert entry.unit in ("1", "1/s"), name
            continue
        if (name.endswith("_per_s") and suffix == "_s") or name == "unbalance_g_mm":
            assert entry.unit in ("1/s", "g mm"), name
            continue
        assert entry.unit == unit_of_suffix[suffix], (name, entry.unit)


def test_one_description_one_unit():
    by_description: dict[str, set[str]] = {}
    for entry in GLOSSARY.values():
        by_description.setdefault(entry.description, set()).add(entry.unit)
    assert {d: u for d, u in by_description.items() if len(u) > 1} == {}


def test_no_retired_unit_tokens_in_the_glossary():
    for name in GLOSSARY:
        assert not re.search(r"_nmm?(_|$)", name), name


# -- the public surface ---------------------------------------------------------


def _public_callables():
    for name in tb.__all__:
        obj = getattr(tb, name)
        if inspect.ismodule(obj):
            continue
        if inspect.isclass(obj):
            for attr, member in vars(obj).items():
                if attr.startswith("_") and attr != "__init__":
                    continue
                fn = member.__func__ if isinstance(member, (classmethod, staticmethod)) else member
                if callable(fn):
                    yield f"{name}.{attr}", fn
        elif callable(obj):
            yield name, obj


def test_every_parameter_with_a_unit_is_in_the_glossary():
    missing = {}
    for qualname, fn in _public_callables():
        try:
            params = inspect.signature(fn).parameters
        except (TypeError, ValueError):
            continue
        bad = not_in_glossary(params)
        if bad:
            missing[qualname] = bad
    assert missing == {}


def test_every_result_property_with_a_unit_is_in_the_glossary():
    missing = {}
    for name in tb.__all__:
        obj = getattr(tb, name)
        if inspect.isclass(obj):
            props = [
                a
                for a, m in inspect.getmembers(obj)
                if isinstance(m, property) and not (m.__doc__ or "").startswith("Deprecated")
            ]
            bad = not_in_glossary(props)
            if bad:
                missing[name] = bad
    assert missing == {}


# -- the frames the main producers return ---------------------------------------


@pytest.fixture(scope="module")
def bearing():
    return tb.Bearing.preset("7009C")


@pytest.fixture(scope="module")
def spindle():
    return tb.Spindle.preset("seed-ceramic-spindle")


def _frames(bearing, spindle):
    speeds = [6000.0, 12000.0]
    yield "balls", bearing.solve(axial_n=500.0, radial_n=200.0, speed_rpm=12000.0).balls
    for mode in ("constant", "speed", "thermal"):
        yield (
            f"stiffness_curve[{mode}]",
            tb.stiffness_curve(bearing, speeds, axial_n=500.0, radial_n=200.0, mode=mode),
        )
    th = tb.thermal_state(bearing, speed_rpm=12000.0, axial_n=500.0)
    yield "temperatures", th.temperatures
    yield "heat", th.heat
    yield "deformations", pl.DataFrame({k: [v] for k, v in th.deformations.items()})
    yield "solve_many", bearing.solve_many({"axial_n": [500.0], "speed_rpm": [1000.0]})
    yield "spindle thermal_state", tb.thermal_state(spindle, speed_rpm=12000.0)
    yield "transient", tb.transient(spindle, speed_rpm=12000.0, duration_s=20.0, dt_s=10.0)
    yield (
        "optimal_preload",
        tb.optimal_preload(spindle, speeds_rpm=[12000.0], preloads_n=[200.0, 400.0]),
    )
    yield "vibration", tb.vibration(spindle, [12000.0])
    yield "seed_b_measurements", tb.seed_b_measurements()
    gear = tb.GearSystem(tb.GearPair.preset("seed-electric-drive"), stiffness="constant")
    yield (
        "bifurcation",
        tb.bifurcation(
            gear,
            [4000.0, 5000.0],
            transient_periods=20,
            record_periods=10,
            steps_per_period=128,
        ),
    )


def test_every_frame_column_with_a_unit_is_in_the_glossary(bearing, spindle):
    missing = {}
    with warnings.catch_warnings():
        warnings.simplefilter("error", DeprecationWarning)  # no producer uses an old name
        for label, df in _frames(bearing, spindle):
            bad = not_in_glossary(df.columns)
            if bad:
                missing[label] = bad
    assert missing == {}


def test_the_temperature_of_a_node_has_one_name(bearing, spindle):
    th = tb.thermal_state(bearing, speed_rpm=12000.0, axial_n=500.0)
    t = th.temperatures
    assert t.columns == ["node", "symbol", "temperature_c"]
    row = t.filter(pl.col("node") == "outer_ring").row(0, named=True)
    assert row["symbol"] == "To"
    assert th.temperature_c("outer_ring") == th.temperature_c("To") == row["temperature_c"]
    curve = tb.stiffness_curve(bearing, [12000.0], axial_n=500.0, mode="thermal")
    assert curve["outer_ring_temperature_c"][0] == pytest.approx(row["temperature_c"], abs=1e-6)
    sp = tb.thermal_state(spindle, speed_rpm=12000.0)
    assert set(spindle.node_names) >= {"front_outer_ring", "rotor", "cooling_water"}
    for node in spindle.node_names:
        assert f"{node}_temperature_c" in sp.columns


def test_displacements_are_in_micrometres(bearing):
    s = bearing.solve(axial_n=500.0, radial_n=200.0)
    q = s.displacement
    assert s.radial_displacement_um == pytest.approx(np.hypot(q[0], q[1]) * 1e6)
    assert s.axial_displacement_um == pytest.approx(q[2] * 1e6)
    c = tb.stiffness_curve(bearing, [0.0], axial_n=500.0, radial_n=200.0)
    assert c["radial_displacement_um"][0] == pytest.approx(s.radial_displacement_um, rel=1e-9)


def test_seed_and_full_stiffness_are_told_apart(bearing):
    s = bearing.solve(axial_n=500.0, radial_n=200.0, speed_rpm=12000.0)
    assert s.k_xx_n_per_m == s.stiffness[0, 0]
    c = tb.stiffness_curve(bearing, [12000.0], axial_n=500.0, radial_n=200.0)
    assert c["k_xx_n_per_m"][0] == pytest.approx(s.k_xx_n_per_m, rel=1e-9)
    assert c["radial_stiffness_seed_n_per_m"][0] == pytest.approx(
        s.radial_stiffness_seed_n_per_m, rel=1e-9
    )
    assert "radial_stiffness_n_per_m" not in c.columns


def test_one_spin_friction_default():
    from thermobear.thermal.state import DEFAULT_SPIN_FRICTION_COEFFICIENT

    spindle = tb.Spindle.preset("seed-ceramic-spindle")
    assert spindle.assumptions["spin_friction_coefficient"] == DEFAULT_SPIN_FRICTION_COEFFICIENT
    for fn in (tb.isothermal_heat, tb.thermal_state_many):
        default = inspect.signature(fn).parameters["spin_friction_coefficient"].default
        assert default == DEFAULT_SPIN_FRICTION_COEFFICIENT


# -- older names: still working, with a warning naming the new one --------------


def test_moment_nmm_is_converted_and_warns(bearing):
    new = bearing.solve(axial_n=500.0, moment_n_m=2.0, misalignment_rad=None)
    with pytest.warns(DeprecationWarning, match="use `moment_n_m`"):
        old = bearing.solve(axial_n=500.0, moment_nmm=2000.0, misalignment_rad=None)
    np.testing.assert_allclose(old.displacement, new.displacement, rtol=1e-12)
    with pytest.raises(tb.ConfigError, match="moment_n_m"):
        bearing.solve(moment_nmm=1.0, moment_n_m=1.0)


def test_mm_displacement_properties_warn(bearing):
    s = bearing.solve(axial_n=500.0)
    with pytest.warns(DeprecationWarning, match="axial_displacement_um"):
        mm = s.axial_displacement_mm
    assert mm * 1000.0 == pytest.approx(s.axial_displacement_um)


def test_spin_friction_keyword_warns(bearing):
    new = tb.isothermal_heat(
        bearing, 12000.0, 500.0, oil_temperature_c=40.0, spin_friction_coefficient=0.08
    )
    with pytest.warns(DeprecationWarning, match="spin_friction_coefficient"):
        old = tb.isothermal_heat(
            bearing, 12000.0, 500.0, oil_temperature_c=40.0, spin_friction=0.08
        )
    assert old.total_heat_w == new.total_heat_w


def test_torque_nm_warns():
    pair = tb.GearPair.preset("seed-electric-drive")
    with pytest.warns(DeprecationWarning, match="torque_n_m"):
        old = tb.GearSystem(pair, torque_nm=-30.0)
    assert old.params["torque_n_m"] == -30.0


def test_old_quantity_names_and_preload_column_warn():
    new = tb.seed_b_measurements()
    old = new.rename({"preload_n": "axial_n"}).with_columns(
        pl.col("quantity").replace(
            {
                "front_outer_ring_temperature_c": "temperature_c:front_outer",
                "rear_outer_ring_temperature_c": "rear_outer_ring_temperature_c",
            }
        )
    )
    with pytest.warns(DeprecationWarning) as record:
        back = tb.load_measurements(old, model="spindle")
    text = " ".join(str(w.message) for w in record)
    assert "front_outer_ring_temperature_c" in text and "preload_n" in text
    assert back.equals(new)
