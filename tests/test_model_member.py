"""A calibrated model with several members (a tie, an "unresolved" verdict)
passed where one machine is expected: ``member=`` picks the explanation;
without it the first is used and an ``AmbiguousModelWarning`` names them
all."""

from __future__ import annotations

import inspect
import warnings

import numpy as np
import pytest

import thermobear as tb
from thermobear import diagnosis as D
from thermobear._model_hook import member_of, unpack_model
from thermobear.diagnosis.calibrated import CalibratedModel, _Step


@pytest.fixture(scope="module")
def tie() -> CalibratedModel:
    base = D.BearingModelSpec(tb.Bearing.preset("7008C"))
    pool = {c.name: c for c in base.candidate_list()}
    members = [
        CalibratedModel("named", f"tie member {i}: {n}", base, [_Step(n, pool[n])], [v],
                        np.zeros((1, 1)))
        for i, (n, v) in enumerate([("extra_heat_w", 30.0), ("lubrication_factor_f0", 3.0)], 1)
    ]  # fmt: skip
    m0 = members[0]
    return CalibratedModel("tie", "tie", base, m0._steps, m0.values, m0.covariance, members=members)


def _quiet(fn, *args, **kwargs):
    with warnings.catch_warnings():
        warnings.simplefilter("error", tb.AmbiguousModelWarning)
        return fn(*args, **kwargs)


def test_member_by_index_label_or_name_reaches_the_call(tie):
    heat = [
        _quiet(tb.thermal_state, tie, 8000.0, 300.0, member=m).total_heat_w
        for m in (0, 1, "tie member 2: lubrication_factor_f0", "lubrication_factor_f0", -1)
    ]
    direct = [tb.thermal_state(m, 8000.0, 300.0).total_heat_w for m in tie.members]
    assert heat == [direct[0], direct[1], direct[1], direct[1], direct[1]]
    assert direct[0] != direct[1]  # the members are different machines
    curve = _quiet(tb.stiffness_curve, tie, [4000.0], 300.0, 0.0, mode="thermal", member=1)
    same = tb.stiffness_curve(tie.members[1], [4000.0], 300.0, 0.0, mode="thermal")
    assert curve.equals(same)


def test_without_member_the_first_is_used_and_a_warning_names_them(tie):
    with pytest.warns(tb.AmbiguousModelWarning) as got:
        state = tb.thermal_state(tie, 8000.0, 300.0)
    msg = str(got[0].message)
    assert "tie member 1: extra_heat_w" in msg and "tie member 2: lubrication_factor_f0" in msg
    assert "member 0" in msg and "member=" in msg
    assert got[0].filename == __file__  # points at the caller's line
    assert state.total_heat_w == tb.thermal_state(tie.members[0], 8000.0, 300.0).total_heat_w


def test_a_member_that_is_not_there_is_a_config_error(tie):
    for bad in (2, "nope", 1.0, True):
        with pytest.raises(tb.ConfigError, match=r"invalid member = .*tie member 1"):
            tb.thermal_state(tie, 8000.0, 300.0, member=bad)
    with pytest.raises(tb.ConfigError, match="invalid member = 0: the model has no members"):
        tb.thermal_state(tie.members[0], 8000.0, 300.0, member=0)
    bearing = tb.Bearing.preset("7008C")
    with pytest.raises(tb.ConfigError, match="invalid member = 1: only a calibrated model"):
        tb.thermal_state(bearing, 8000.0, 300.0, member=1)
    with pytest.raises(tb.ConfigError, match="invalid member"):
        unpack_model(bearing, member=0)


def test_the_hook_shows_the_keyword_and_the_helpers_agree(tie):
    assert "member" in inspect.signature(tb.thermal_state).parameters
    assert "member" in inspect.signature(tb.transient).parameters
    assert _quiet(member_of, tie, "extra_heat_w") is tie.members[0]
    assert member_of(tie.members[1]) is tie.members[1]
    machine, options = _quiet(unpack_model, tie, 1)
    assert options["lubrication_factor_f0"] == 3.0
