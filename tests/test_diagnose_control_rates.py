"""The generic control against the named candidates on the real bearing
model (the candidate list): "a heat source that no registry term models was
named as churning, with a tight interval".

Case: a 7008C angular-contact bearing at 400 N axial preload, 7 speeds
(3000-18000 rpm), 4 quantities (outer, inner and ball temperatures, heat),
the typical sigmas. Hidden: an extra heat source growing like n^1.5 (a
seal rub, say) that no candidate models -- the registry's extra heat is
constant in speed, Palmgren's f0 scales a viscous moment ~ (nu n)^(2/3)
whose heat grows like n^(5/3) at a fixed viscosity.

Asserted: the source is worth more than 3 sigma at the top speed, yet the
noiseless truth lies within 1 sigma (chi^2 < 1 over all 28 points) of a
miscalibrated f0 and of the carrier control (an unknown heat source with a
free quadratic speed law): the data cannot tell the shapes apart, so
"unresolved" (or a tie with the unknown smooth effect) is the right
answer, and a known name is given in at most 2 of 20 seeds (the rule
allows about 2 % per data set, see ``control.CARRIER_LEAD``). A real f0
error of 3 sigma at the top speed is named, tied or unresolved with f0
listed in >= 90 % of the seeds, another single name in <= 1; and the null
case gives at most 5 false discoveries in 100 seeds."""

from __future__ import annotations

import numpy as np
import polars as pl

import thermobear as tb
from thermobear import diagnosis as D

SPEEDS = np.linspace(3000.0, 18000.0, 7)
QUANTITIES = [
    "outer_ring_temperature_c",
    "inner_ring_temperature_c",
    "ball_temperature_c",
    "heat_w",
]
_CACHE: dict = {}


def _base():
    if "base" not in _CACHE:
        _CACHE["base"] = D.BearingModelSpec(tb.Bearing.preset("7008C"))
    return _CACHE["base"]


def _conditions() -> pl.DataFrame:
    rows = [(s, 400.0, 0.0, q) for s in SPEEDS for q in QUANTITIES]
    return pl.DataFrame(rows, schema=["speed_rpm", "axial_n", "radial_n", "quantity"], orient="row")


def _values(model_at_speed) -> np.ndarray:
    """The predicted value of every row, the model chosen per speed."""
    cond = _conditions()
    out = np.empty(cond.height)
    for s in SPEEDS:
        rows = (cond["speed_rpm"] == s).to_numpy()
        pred = model_at_speed(s).predict(cond.filter(rows))
        out[rows] = [pred[q][i] for i, q in enumerate(cond.filter(rows)["quantity"])]
    return out


def _seal_source(s: float):
    """25 W at the top speed, growing like n^1.5."""
    return _base().with_setting(extra_heat_w=float(25.0 * (s / SPEEDS.max()) ** 1.5))


def _table(values, sigma, seed=None) -> pl.DataFrame:
    noise = 0.0 if seed is None else np.random.default_rng(seed).normal(size=len(values))
    return _conditions().with_columns(
        pl.Series("value", values + noise * sigma), pl.Series("sigma", sigma)
    )


def _sigma(values) -> np.ndarray:
    return D.typical_sigma(_base().quantities, _conditions()["quantity"].to_list(), values)


def _top_speed_sigma(values, sigma) -> float:
    top = _conditions()["speed_rpm"].to_numpy() == SPEEDS.max()
    base = _values(lambda s: _base())
    return float(np.max(np.abs(values - base)[top] / sigma[top]))


def test_the_n15_source_is_indistinguishable_from_f0_on_these_data():
    """Noiseless truth: f0 calibrated to it, and the carrier control,
    each leave chi^2 < 1 -- both fits lie within 1 sigma of the truth (so
    within 2 sigma of each other): no noise realisation can tell them
    apart reliably."""
    values = _values(_seal_source)
    sigma = _sigma(values)
    assert _top_speed_sigma(values, sigma) > 3.0
    d = tb.diagnose(
        _base(), _table(values, sigma), ["lubrication_factor_f0", "extra_heat_w"],
        suggest=False, outliers=False,
    )  # fmt: skip
    table = d.screening[0]
    f0 = table.filter(pl.col("candidate") == "lubrication_factor_f0")["chi2"][0]
    ctrl = table.filter(pl.col("candidate") == "generic_control")["chi2"][0]
    assert f0 < 1.0 and ctrl < 1.0, (f0, ctrl)
    assert d.verdict.startswith("unresolved"), d.verdict


def test_a_hidden_n15_heat_source_is_not_named_as_a_known_term():
    values = _values(_seal_source)
    sigma = _sigma(values)
    named = 0
    for seed in range(20):
        d = tb.diagnose(_base(), _table(values, sigma, seed), suggest=False)
        named += bool(d.accepted)
        unknown_in_tie = "generic_control" in d.tie
        assert d.accepted or d.unresolved or unknown_in_tie or "structured" in d.verdict, d.verdict
    assert named <= 2


def _outcome(d, name) -> str:
    if [a["name"] for a in d.accepted] == [name]:
        return "right"
    if name in d.tie or name in [a["name"] for a in d.unresolved]:
        return "tie"
    return "wrong" if d.accepted else "other"


def test_a_real_f0_error_is_named_or_unresolved_with_f0_listed():
    """f0 moved so that the largest change at the top speed is 3 sigma
    (heat grows linearly in f0 at a fixed speed, to within the viscosity's
    feedback)."""
    step = _values(lambda s: _base().with_setting(lubrication_factor_f0=1.1))
    one = _top_speed_sigma(step, _sigma(step))
    f0 = 1.0 + 0.1 * 3.0 / one
    values = _values(lambda s: _base().with_setting(lubrication_factor_f0=f0))
    sigma = _sigma(values)
    assert 2.9 < _top_speed_sigma(values, sigma) < 3.3
    out = [
        _outcome(tb.diagnose(_base(), _table(values, sigma, 100 + s), suggest=False),
                 "lubrication_factor_f0")
        for s in range(20)
    ]  # fmt: skip
    assert out.count("right") + out.count("tie") >= 18, out
    assert out.count("wrong") <= 1, out


def test_null_false_discoveries_on_the_same_design():
    values = _values(lambda s: _base())
    sigma = _sigma(values)
    found = sum(
        tb.diagnose(_base(), _table(values, sigma, 1000 + s), suggest=False).verdict
        != "no missing effect supported"
        for s in range(100)
    )
    assert found <= 5


def test_the_carrier_rule_on_its_threshold():
    """``matching_control``: a carrier control matches a named set unless
    the named chi^2 is lower than the carrier's by more than 3.84 (plus one
    per named parameter beyond the carrier's two); BIC's charge for the
    carrier's extra parameter is not counted in the named set's favour."""
    from thermobear.diagnosis.control import carrier_control, matching_control
    from thermobear.diagnosis.measurements import prepare_measurements

    values = _values(lambda s: _base())
    sigma = _sigma(values)
    d = prepare_measurements(_table(values, sigma, 7), _base().quantities, None)
    x = d.cond["speed_rpm"].to_numpy() / SPEEDS.max()
    slope = np.where(d.quantity == "heat_w", 1.0, 0.4)  # value per W of the source
    pred0 = d.y - slope * (8.0 * x + 18.0 * x**2)  # the source: ~26 W at the top speed
    carriers = {"extra_heat_w": slope}
    chi_c = carrier_control(d, pred0, "extra_heat_w", slope).chi2
    assert matching_control(d, pred0, chi_c - 3.8, 1, carriers) is not None
    assert matching_control(d, pred0, chi_c - 3.9, 1, carriers) is None
    assert matching_control(d, pred0, chi_c - 4.8, 3, carriers) is not None
    assert matching_control(d, pred0, chi_c - 4.9, 3, carriers) is None
    assert matching_control(d, pred0, chi_c - 3.9, 1, {}) is None  # no carrier


def test_the_carrier_lead_threshold_bounds_false_naming():
    """Were the carrier's family the truth, the named set's chi^2 lead
    over it exceeds 3.84 in at most about 2 % of data sets, whatever the
    distance D between the truth and the named family and however the named
    direction leans out of the carrier's plane (linear models, 28 points,
    Gaussian noise: Monte-Carlo over the geometry)."""
    rng = np.random.default_rng(0)
    n, worst = 28, 0.0
    e = np.eye(n)
    for dist in (0.0, 0.5, 1.0, 2.0, 3.0):
        for lean in (0.0, 0.3, 0.8, np.pi / 2):
            u = np.cos(lean) * e[0] + np.sin(lean) * e[2]  # the named direction
            y = dist * e[1] + rng.normal(size=(20_000, n))  # truth in the carrier plane (e0, e1)
            chi_carrier = np.sum(y[:, 2:] ** 2, axis=1)
            chi_named = np.sum(y**2, axis=1) - (y @ u) ** 2
            worst = max(worst, float(np.mean(chi_carrier - chi_named > 3.841)))
    assert 0.005 < worst < 0.025, worst
