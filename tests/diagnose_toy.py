"""A closed-form test rig for the statistics of ``thermobear.diagnose``
(no solver: every prediction is a formula, so hundreds of seeds run in
seconds and the truth is known exactly).

With n = speed / 10^4 rpm and F = axial load / 1000 N:

* heat = f0 x 40 n^(2/3) + 15 F n + extra heat + 30 c_drag n^3 [W];
* Ti = ambient + 0.25 heat + 1.5 n [C]; To = ambient + 0.15 heat [C];
* axial stiffness = 1e8 (1 + F)^(1/3) (1 - 0.1 n^2 with centrifugal
  softening) [N/m].

Candidates: the switch ``centrifugal``, the parameters ``drag_coefficient``
(c_drag 0-2, baseline 0), ``lubrication_factor_f0`` (0.5-3, baseline 1),
``extra_heat_w`` (0-100 W) and ``ambient_temperature_offset_k`` (-10..20 K),
and a sensor offset per measured quantity."""

from __future__ import annotations

import numpy as np
import polars as pl

import thermobear as tb
from thermobear.diagnosis import Candidate, ModelSpec, sensor_offset_candidates

Q = {
    "heat_w": ("heat_w", 1.0, (0.0, 1e5), 0.02, True),
    "inner_ring_temperature_c": ("ti", 1.0, (-60.0, 250.0), 0.5, False),
    "outer_ring_temperature_c": ("to", 1.0, (-60.0, 250.0), 0.5, False),
    "axial_stiffness_seed_n_per_m": ("ka", 1.0, (1e5, 1e11), 0.02, True),
}


class Rig(ModelSpec):
    """The closed-form rig of the module docstring."""

    quantities = Q

    def __init__(self, effects=(), **options):
        self.effects = tuple(sorted(effects))
        base = {"lubrication_factor_f0": 1.0, "extra_heat_w": 0.0, "ambient_temperature_c": 25.0}
        self.options = {**base, "drag_coefficient": 0.0, **options}
        self._cache = {}

    def with_setting(self, add_effects=(), **options):
        new = Rig(set(self.effects) | set(add_effects), **{**self.options, **options})
        new._cache = self._cache
        return new

    def predict(self, conditions):
        n = conditions["speed_rpm"].to_numpy() / 1e4
        f = conditions["axial_n"].to_numpy() / 1e3
        o = self.options
        heat = o["lubrication_factor_f0"] * 40.0 * n ** (2.0 / 3.0) + 15.0 * f * n
        heat = heat + o["extra_heat_w"] + 30.0 * o["drag_coefficient"] * n**3
        amb = o["ambient_temperature_c"]
        ka = 1e8 * (1.0 + f) ** (1.0 / 3.0)
        if "centrifugal" in self.effects:
            ka = ka * (1.0 - 0.1 * n**2)
        self._cache[self._key()] = True
        return {
            "heat_w": heat,
            "inner_ring_temperature_c": amb + 0.25 * heat + 1.5 * n,
            "outer_ring_temperature_c": amb + 0.15 * heat,
            "axial_stiffness_seed_n_per_m": ka,
        }

    def candidate_list(self, quantities=()):
        allq = tuple(Q)
        out = [
            Candidate(e, "switch", "model", f"{e}_on", "1", 0.0, 1.0, 0.0, e, allq, effect=e)
            for e in ("centrifugal",)
            if e not in self.effects
        ]
        out += [
            Candidate("drag_coefficient", "parameter", "model", "drag_coefficient", "1", 0.0,
                      2.0, 0.0, "ball drag ~ n^3", allq, option="drag_coefficient"),
            Candidate("lubrication_factor_f0", "parameter", "model", "lubrication_factor_f0",
                      "1", 0.5, 3.0, 1.0, "f0", allq, option="lubrication_factor_f0",
                      role="calibration"),
            Candidate("extra_heat_w", "parameter", "model", "extra_heat_w", "W", 0.0, 100.0,
                      0.0, "extra heat", allq, option="extra_heat_w"),
            Candidate("ambient_temperature_offset_k", "parameter", "model",
                      "ambient_temperature_offset_k", "K", -10.0, 20.0, 0.0, "ambient",
                      allq, option="ambient_temperature_c", offset=True, role="calibration"),
        ]  # fmt: skip
        return out + sensor_offset_candidates(quantities, Q)


def conditions(speeds, loads=(300.0,), quantities=tuple(Q), runs=("1",)) -> pl.DataFrame:
    """Every quantity at every speed, load and run."""
    rows = [(s, a, 0.0, q, r) for r in runs for a in loads for s in speeds for q in quantities]
    return pl.DataFrame(
        rows, schema=["speed_rpm", "axial_n", "radial_n", "quantity", "run"], orient="row"
    )


def measured(truth, cond, seed, noise=1.0, sigma_scale=1.0):
    """The truth plus Gaussian noise of ``noise`` x the typical sigma; the
    ``sigma`` column states ``sigma_scale`` x the true noise sigma."""
    df = tb.diagnosis.synthetic_measurements(truth, cond, noise=noise, seed=seed)
    return df.with_columns(pl.col("sigma") * sigma_scale)


def top_speed_sigma(truth, base, cond) -> float:
    """The largest |truth - baseline| / typical sigma at the top speed."""
    pt, pb = truth.predict(cond), base.predict(cond)
    q = cond["quantity"].to_list()
    top = cond["speed_rpm"].to_numpy() == cond["speed_rpm"].max()
    best = 0.0
    for i in np.flatnonzero(top):
        typ, rel = Q[q[i]][3], Q[q[i]][4]
        sig = typ * abs(pb[q[i]][i]) if rel else typ
        best = max(best, abs(pt[q[i]][i] - pb[q[i]][i]) / sig)
    return best
