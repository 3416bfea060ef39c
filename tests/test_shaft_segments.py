"""A spindle's shaft given as its own segments (``Shaft.segments``,
``[[spindle.shaft.segment]]``): the rotor model builds on them, the
derived layout written out as segments is the same rotor, a stiffer step
raises the critical speed, and a bad shaft is named with its line."""

from __future__ import annotations

import dataclasses

import numpy as np
import pytest

import thermobear as tb

EXAMPLE = "examples/own_spindle.toml"


@pytest.fixture(scope="module")
def spindle() -> tb.Spindle:
    return tb.Spindle.from_toml(EXAMPLE)


def _segments(sections_m) -> tuple:
    return tuple(
        tb.ShaftSegment(length_mm=1e3 * n, outer_diameter_mm=1e3 * o, bore_mm=1e3 * i)
        for n, o, i in sections_m
    )


def _with_shaft(spindle: tb.Spindle, segments: tuple) -> tb.Spindle:
    parts = dict(spindle.parts)
    parts["shaft"] = dataclasses.replace(parts["shaft"], segments=segments)
    parts["name"] = "own-shaft"
    return tb.Spindle(**parts)


def _first_critical_rpm(sp: tb.Spindle) -> float:
    c = tb.critical_speeds(sp, speeds_rpm=np.linspace(0.0, 90000.0, 10).tolist())
    return float(c["speed_rpm"].min())


def test_the_derived_layout_as_segments_is_the_same_rotor(spindle):
    """The derived steps written out as segments give the same beam model:
    the same sections (to a unit conversion), the same motor seat, the same
    critical speeds."""
    own = _with_shaft(spindle, _segments(spindle.rotor_layout["sections_m"]))
    a, b = spindle.rotor_layout, own.rotor_layout
    np.testing.assert_allclose(b["sections_m"], a["sections_m"], rtol=1e-14)
    assert b["core_inner_diameter_m"] == pytest.approx(a["core_inner_diameter_m"], rel=1e-14)
    assert _first_critical_rpm(own) == pytest.approx(_first_critical_rpm(spindle), rel=1e-9)
    # the thermal model lumps the shaft: the same thermal state
    t1 = tb.thermal_state(spindle, speed_rpm=12000.0).row(0, named=True)
    t2 = tb.thermal_state(own, speed_rpm=12000.0).row(0, named=True)
    assert t1["front_outer_ring_temperature_c"] == t2["front_outer_ring_temperature_c"]


def test_a_thicker_motor_seat_raises_the_first_critical_speed(spindle):
    """Bending stiffness grows like d^4 and mass like d^2: a thicker step
    between the pairs stiffens the rotor's first bending mode."""
    secs = [list(s) for s in spindle.rotor_layout["sections_m"]]
    base = _first_critical_rpm(_with_shaft(spindle, _segments(secs)))
    secs[2][1] *= 1.05  # the motor seat, under the core (rotor diameter 90 mm)
    assert _first_critical_rpm(_with_shaft(spindle, _segments(secs))) > base


def test_segments_round_trip_through_a_description_file(spindle, tmp_path):
    own = _with_shaft(spindle, _segments(spindle.rotor_layout["sections_m"]))
    text = own.to_toml()
    assert text.count("[[spindle.shaft.segment]]") == len(own.rotor_layout["sections_m"])
    back = tb.Spindle.from_toml(text)
    assert back.rotor_layout["sections_m"] == own.rotor_layout["sections_m"]
    assert back.to_toml() == text


def _file(tmp_path, spindle, edit) -> str:
    """The example's description with its derived shaft as segments, one
    value changed by ``edit`` (old, new) in the text; its path."""
    own = _with_shaft(spindle, _segments(spindle.rotor_layout["sections_m"]))
    text = own.to_toml()
    old, new = edit
    assert old in text
    path = tmp_path / "spindle.toml"
    path.write_text(text.replace(old, new, 1))
    return str(path)


def _line_of(path: str, needle: str) -> int:
    lines = open(path).read().splitlines()
    return next(i + 1 for i, line in enumerate(lines) if line.startswith(needle))


@pytest.mark.parametrize(
    "edit, key, words",
    [
        (("outer_diameter_mm = 70.0", "outer_diameter_mm = 72.0"), "outer_diameter_mm = 72.0",
         "front pair (bore 70 mm)"),
        (("length_mm = 20.0", "length_mm = -20.0"), "length_mm = -20.0", "length_mm"),
        (("bore_mm = 24.0", "bore_mm = 75.0"), "bore_mm = 75.0",
         "below the outer diameter"),
    ],
)  # fmt: skip
def test_a_bad_segment_is_named_with_its_line(spindle, tmp_path, edit, key, words):
    path = _file(tmp_path, spindle, edit)
    with pytest.raises(tb.ConfigError) as e:
        tb.Spindle.from_toml(path)
    msg = str(e.value)
    assert f"spindle.toml:{_line_of(path, key)}:" in msg and words in msg, msg


def test_segments_that_stop_before_the_rear_pair_are_named(spindle):
    secs = spindle.rotor_layout["sections_m"][:3]
    with pytest.raises(tb.ConfigError, match="before the rear pair's seat"):
        _with_shaft(spindle, _segments(secs))


def test_segments_key_and_non_tables_are_refused():
    base = '[spindle]\nname = "x"\n[spindle.shaft]\n'
    with pytest.raises(tb.ConfigError, match=r"\[\[spindle.shaft.segment\]\]"):
        tb.Spindle.from_toml(base + "segments = [1.0]\n")
    with pytest.raises(tb.ConfigError, match="segment"):
        tb.Spindle.from_toml(base + "segment = 3\n")
    with pytest.raises(tb.ConfigError, match="segments"):
        tb.Shaft(segments="thick")  # type: ignore[arg-type]
