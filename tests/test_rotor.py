"""Spindle rotor dynamics from Python: Campbell diagram, vibration, spectrum,
the spindle protocol and the thermal seam."""

from __future__ import annotations

import numpy as np
import pytest

import thermobear as tb
from thermobear.errors import ConfigError


class ZeroOffsets:
    """Spindle protocol with zero thermal offsets: must equal uncoupled."""

    rotor_preset_name = "seed-ceramic-spindle"

    def raceway_offsets(self, speed_rpm: float) -> dict:
        return {"front": (0.0, 0.0), "rear": (0.0, 0.0)}


class HotFront:
    """Radial growth of the front rows only (thermal seam)."""

    rotor_preset_name = "seed-ceramic-spindle"
    preload_n = 400.0

    def raceway_offsets(self, speed_rpm: float) -> dict:
        return {"front": (6e-6, 0.0), "rear": (0.0, 0.0)}


def test_campbell_columns_whirl_split_and_hybrid_stiffer():
    # Gyroscopic splitting: at speed the lowest pair separates into a
    # backward branch below and a forward branch above; at rest they coincide.
    df = tb.campbell("seed-ceramic-spindle", speeds_rpm=[0.0, 30_000.0], modes=4)
    assert set(df.columns) >= {"speed_rpm", "mode", "frequency_hz", "whirl"}
    rest = df.filter(df["speed_rpm"] == 0.0)["frequency_hz"].to_numpy()
    fast = df.filter(df["speed_rpm"] == 30_000.0)
    assert abs(rest[1] - rest[0]) < 1e-3 * rest[0]
    f = fast["frequency_hz"].to_numpy()
    assert f[1] - f[0] > 1e-3 * f[0]
    assert fast["whirl"][0] == "backward"
    # Si3N4 balls: stiffer contacts -> higher first natural frequency (same preload).
    steel = tb.campbell("seed-steel-spindle", speeds_rpm=[0.0], modes=1)
    assert rest[0] > steel["frequency_hz"][0]


def test_vibration_grows_with_speed_and_zero_offsets_equal_uncoupled():
    # Below the first critical the unbalance force grows as speed^2 and the
    # response velocity roughly as speed^3: 18,000 rpm must exceed 6,000 rpm
    # by far more than the speed ratio.
    s = [6_000.0, 18_000.0]
    unc = tb.vibration("seed-ceramic-spindle", s, coupled=False)
    v = unc["velocity_rms_mm_s"].to_numpy()
    assert v[1] > 9.0 * v[0]
    assert np.allclose(unc["x1_mm_s"].to_numpy() / np.sqrt(2.0), v, rtol=1e-12)
    z = tb.vibration(ZeroOffsets(), s, coupled=True)
    assert z["velocity_rms_mm_s"].to_list() == unc["velocity_rms_mm_s"].to_list()
    assert z["coupled"].to_list() == [True, True]
    # Unbalance given as mass x radius scales the response linearly.
    a = tb.vibration("seed-ceramic-spindle", s, coupled=False, unbalance_g_mm=1.0)
    b = tb.vibration("seed-ceramic-spindle", s, coupled=False, unbalance_g_mm=3.0)
    assert np.allclose(b["x1_mm_s"].to_numpy(), 3.0 * a["x1_mm_s"].to_numpy(), rtol=1e-9)


def test_thermal_seam_changes_the_response_and_coupled_needs_offsets():
    hot = tb.campbell(HotFront(), speeds_rpm=[12_000.0], modes=1, coupled=True)
    cold = tb.campbell("seed-ceramic-spindle", speeds_rpm=[12_000.0], modes=1)
    # Radial growth at constant preload lowers the contact angle and raises
    # the radial stiffness of the front rows: the first mode rises.
    assert hot["frequency_hz"][0] > cold["frequency_hz"][0]
    with pytest.raises(ConfigError, match="thermal model"):
        tb.vibration("seed-ceramic-spindle", [12_000.0], coupled=True)
    with pytest.raises(ConfigError, match="rotor_preset_name"):
        tb.campbell("seed-brass-spindle")
    with pytest.raises(ConfigError, match="method"):
        tb.vibration("seed-steel-spindle", [1000.0], coupled=False, method="fourier")
    with pytest.raises(ConfigError, match="speeds_rpm"):
        tb.campbell("seed-steel-spindle", speeds_rpm=[float("nan")])
    with pytest.raises(ConfigError, match="speed_rpm"):
        tb.spectrum("seed-steel-spindle", speed_rpm=0.0, coupled=False)
    with pytest.raises(ConfigError, match="preload_n"):
        tb.campbell(type("S", (), {"rotor_preset_name": "seed-steel-spindle", "preload_n": -5.0})())
    with pytest.raises(ConfigError, match="front"):
        tb.vibration(
            type(
                "S",
                (),
                {
                    "rotor_preset_name": "seed-steel-spindle",
                    "raceway_offsets": lambda self, n: {"rear": (0, 0)},
                },
            )(),
            [1e3],
        )
    with pytest.raises(ConfigError, match="unbalance"):
        tb.vibration("seed-steel-spindle", [1000.0], False, unbalance_grade=2.5, unbalance_g_mm=1.0)


def test_spectrum_peak_is_the_rotation_frequency_and_time_matches_frequency():
    sp = tb.spectrum("seed-ceramic-spindle", speed_rpm=12_000.0, duration_s=0.05, coupled=False)
    f = sp["frequency_hz"].to_numpy()
    a = sp["velocity_mm_s"].to_numpy()
    k = int(np.argmax(a[1:])) + 1
    assert abs(f[k] - 200.0) <= f[1] - f[0]
    orders = tb.spectrum_orders("seed-ceramic-spindle", 12_000.0, 0.05, coupled=False)
    freq = tb.vibration("seed-ceramic-spindle", [12_000.0], coupled=False)
    # Nonlinear time response started in the linear steady state vs the
    # frequency-domain response: same 1X within 1 % (small amplitude).
    assert orders["velocity_mm_s"][0] == pytest.approx(freq["x1_mm_s"][0], rel=1e-2)
    # UMP (switchable effect) is a negative stiffness: it lowers the first mode.
    base = [e for e in tb._native.rotor_default_effects()]
    assert "unbalanced_magnetic_pull" not in base
    ump = tb.campbell(
        "seed-ceramic-spindle", [0.0], modes=1, effects=base + ["unbalanced_magnetic_pull"]
    )
    plain = tb.campbell("seed-ceramic-spindle", [0.0], modes=1)
    assert ump["frequency_hz"][0] < plain["frequency_hz"][0]


def test_critical_speeds_lie_on_the_1x_line_with_forward_above_backward():
    # A 1X critical speed is where a branch meets f = speed / 60; gyroscopic
    # stiffening raises the forward branch, so its crossing comes later.
    c = tb.critical_speeds("seed-ceramic-spindle", np.linspace(0.0, 120_000.0, 13), modes=2)
    assert c.height >= 2
    assert np.allclose(c["frequency_hz"].to_numpy(), c["speed_rpm"].to_numpy() / 60.0)
    fwd = c.filter(c["whirl"] == "forward")["speed_rpm"].to_numpy()
    bwd = c.filter(c["whirl"] == "backward")["speed_rpm"].to_numpy()
    assert fwd.size and bwd.size and fwd.min() > bwd.min()


def test_time_method_with_ball_forces_matches_frequency_method():
    # The nonlinear time response (ball forces, cage turning) at G2.5 is a
    # small-amplitude motion about the preloaded state: its 1X equals the
    # linear steady response within 1 %, and its RMS is 1X / sqrt 2 when
    # 2X and 3X are negligible. (Near 15,000 rpm the steel spindle's nose
    # 1X passes a near-cancellation of its static and inertial parts, where
    # relative differences are amplified: 1.4 % there; we test away from it.)
    s = [9_000.0, 18_000.0]
    t = tb.vibration("seed-steel-spindle", s, coupled=False, method="time", duration_s=0.04)
    f = tb.vibration("seed-steel-spindle", s, coupled=False)
    assert np.allclose(t["x1_mm_s"].to_numpy(), f["x1_mm_s"].to_numpy(), rtol=1e-2)
    assert np.all(t["x2_mm_s"].to_numpy() < 1e-3 * t["x1_mm_s"].to_numpy())
    assert np.allclose(
        t["velocity_rms_mm_s"].to_numpy(), t["x1_mm_s"].to_numpy() / np.sqrt(2.0), rtol=2e-2
    )


def test_spindle_thermal_coupling_reaches_the_rotor():
    """tb.vibration(coupled=True) on a tb.Spindle uses the raceway offsets of
    its coupled thermal steady state; with every thermal effect off the
    offsets vanish and the coupled result equals the uncoupled one exactly."""
    speeds = np.array([9000.0, 15000.0])
    sp = tb.Spindle.preset("seed-ceramic-spindle")
    iso = sp.with_options(effects=["centrifugal_force", "gyroscopic_moment"])
    off = iso.raceway_offsets(15000.0)
    assert all(v == 0.0 for pair in off.values() for v in pair)
    unc = tb.vibration(sp, speeds_rpm=speeds, coupled=False)
    cpl_iso = tb.vibration(iso, speeds_rpm=speeds, coupled=True)
    assert cpl_iso["velocity_rms_mm_s"].to_list() == unc["velocity_rms_mm_s"].to_list()
    hot = sp.raceway_offsets(15000.0)
    assert hot["front"][0] > 0.0  # inner parts run hotter: the groove centres close in
    cpl = tb.vibration(sp, speeds_rpm=speeds, coupled=True)
    assert cpl["velocity_rms_mm_s"].to_list() != unc["velocity_rms_mm_s"].to_list()
