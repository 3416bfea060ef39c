"""The warning tier against the makers' own ratings: a speed factor a
catalogue rates a bearing for is not "past what real machines do".

SKF's reference speeds (ISO 15312 conditions: an oil bath) of the 60, 62 and
63 series are the rows of the shipped ``skf_reference_speed_*`` validation
sets (SKF General Catalogue 6000, 2006, bearing tables pp. 302-317)."""

from __future__ import annotations

import tomllib
import warnings
from importlib import resources

import pytest

import thermobear as tb

SETS = ("skf_reference_speed_60", "skf_reference_speed_62", "skf_reference_speed_63")


def _rows(name: str) -> tuple[str, list[dict]]:
    text = resources.files("thermobear.validation.data").joinpath(f"{name}.toml").read_text("utf-8")
    data = tomllib.loads(text)
    return data["conditions"]["lubrication"], data["bearings"]


def _ndm_mm_rpm(row: dict) -> float:
    """n dm of a catalogue row: reference speed times the pitch diameter,
    (bore + outside diameter) / 2 as the validation sets take it."""
    return row["reference_speed_rpm"] * 0.5 * (row["bore_mm"] + row["outer_diameter_mm"])


def test_the_oil_bath_limit_is_the_highest_catalogue_oil_bath_rating():
    """Every catalogue reference speed lies within the oil-bath limit, and
    the limit is no more than 1 % above the highest of them (the 6000 at
    67,000 rpm on an 18 mm pitch diameter: 1.206e6 mm rpm): it is the
    catalogue's figure, not a guess well above it."""
    ndm = []
    for name in SETS:
        lubrication, rows = _rows(name)
        assert lubrication == "oil-bath"
        ndm += [_ndm_mm_rpm(r) for r in rows]
    limit = tb.get_limits().max_ndm_mm_rpm("oil-bath")
    assert max(ndm) == pytest.approx(1.206e6)
    assert max(ndm) <= limit <= 1.01 * max(ndm)
    # the ratings sit near one n dm for every size (1.0-1.21 million): the
    # catalogue's oil-bath practice, far above the former 0.5 million limit
    assert min(ndm) > 1.0e6


def test_a_catalogue_reference_speed_solves_without_a_plausibility_warning():
    """The 6000 at its reference speed in an oil bath: the maker's rating."""
    b = tb.Bearing.deep_groove(
        ball_count=7, ball_diameter_mm=4.7625, pitch_diameter_mm=18.0, inner_conformity=0.515,
        outer_conformity=0.525, bore_mm=10.0, outer_diameter_mm=26.0, width_mm=8.0,
        diametral_clearance_mm=0.0075,
    )  # fmt: skip
    with warnings.catch_warnings():
        warnings.simplefilter("error", tb.PlausibilityWarning)
        tb.isothermal_heat(
            b, speed_rpm=67000.0, radial_n=98.0, oil_temperature_c=70.0, lubrication="oil-bath"
        )
    with pytest.warns(tb.PlausibilityWarning, match="oil-bath"):  # 10 % past the rating
        tb.isothermal_heat(
            b, speed_rpm=1.1 * 67000.0, radial_n=98.0, oil_temperature_c=70.0,
            lubrication="oil-bath",
        )  # fmt: skip


def test_validate_runs_the_catalogue_sets_without_plausibility_warnings():
    """``thermobear validate`` on the catalogue sets: no warning fires on a
    catalogue point (the CLI runs the same ``validate``)."""
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        results = tb.validate(list(SETS))
    assert len(results) == len(SETS)
    plaus = [str(w.message) for w in caught if issubclass(w.category, tb.PlausibilityWarning)]
    assert plaus == []
