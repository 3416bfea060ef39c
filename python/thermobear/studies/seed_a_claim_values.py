"""Ours for each of seed A's claims in words (``papers/seed_a_claims.csv``):
the quantity a claim row names, at its condition, under a bearing model,
and the difference or ratio against its reference.

A condition is the 6208 at ``speed_rpm`` under ``preload_n`` plus, at
``torque_n_m``, the gear's bearing forces of seed A section 2.3 scaled
with the torque (2380.9 N axial and 1189.9 N radial at 100 N m); its case
is the coupled thermal state (``stiffness`` "thermal" or empty) or the
quasi-statics without thermal effects (``"speed"``). A reference
``"axial_n=0"`` / ``"radial_n=0"`` removes the gear's axial / radial force
and keeps the preload; ``"quantity=<name>"`` is another quantity at the
same condition. Every condition is solved once per model
(``ClaimPoints``).
"""

from __future__ import annotations

from dataclasses import dataclass, replace
from typing import Any, Callable

import numpy as np

from ..errors import ConfigError
from .seed_a_thermal import LOAD_AXIAL_N, LOAD_RADIAL_N

#: The torque at which seed A states its bearing forces [N m].
SEED_TORQUE_N_M = 100.0

#: The node of each node-temperature quantity (``ThermalState.temperature_c``).
NODE_OF = {
    f"{n}_temperature_c": n
    for n in ("shaft", "inner_contact", "inner_ring", "ball", "outer_ring", "outer_contact",
              "housing")
}  # fmt: skip


@dataclass(frozen=True)
class Condition:
    """One operating point of a claim: speed [rpm], preload [N], input
    torque [N m], the case ("thermal" or "speed") and whether the gear's
    axial and radial forces act."""

    speed_rpm: float
    preload_n: float
    torque_n_m: float
    case: str = "thermal"
    gear_axial: bool = True
    gear_radial: bool = True

    def loads_n(self) -> tuple[float, float]:
        """(axial, radial) bearing load [N]: the preload plus the gear's forces."""
        scale = self.torque_n_m / SEED_TORQUE_N_M
        axial = self.preload_n + (LOAD_AXIAL_N * scale if self.gear_axial else 0.0)
        radial = LOAD_RADIAL_N * scale if self.gear_radial else 0.0
        return axial, radial

    def moved(self, key: str, value: str) -> Condition:
        """The condition with one of its settings changed (a reference)."""
        if key == "stiffness":
            return replace(self, case=_case(value))
        try:
            number = float(value)
        except ValueError:
            number = float("nan")
        if key in ("speed_rpm", "preload_n", "torque_n_m") and number == number:
            changes: dict[str, Any] = {key: number}
            return replace(self, **changes)
        if key in ("axial_n", "radial_n") and number == 0.0:
            off: dict[str, Any] = {"gear_" + key[:-2]: False}
            return replace(self, **off)
        raise ConfigError(
            f"invalid reference = '{key}={value}': speed_rpm, preload_n, torque_n_m, stiffness, "
            "axial_n=0, radial_n=0 or quantity=<name>"
        )


def _case(stiffness: str) -> str:
    s = (stiffness or "thermal").strip()
    if s not in ("thermal", "speed"):
        raise ConfigError(f"invalid stiffness = {stiffness!r}: 'thermal', 'speed' or empty")
    return s


def condition_of(row: dict) -> Condition:
    """A claim row's own condition."""
    return Condition(
        float(row["speed_rpm"]),
        float(row["preload_n"] or 0.0),
        float(row["torque_n_m"] or 0.0),
        _case(row["stiffness"]),
    )


def _solution_values(sol: Any) -> dict[str, float]:
    """The mechanical quantities of a bearing solution."""
    balls = sol.balls
    return {
        "radial_stiffness_seed_n_per_m": sol.radial_stiffness_seed_n_per_m,
        "axial_stiffness_seed_n_per_m": sol.axial_stiffness_seed_n_per_m,
        "k_xx_n_per_m": sol.k_xx_n_per_m,
        "k_zz_n_per_m": sol.k_zz_n_per_m,
        "radial_displacement_um": sol.radial_displacement_um,
        "axial_displacement_um": sol.axial_displacement_um,
        "outer_contact_angle_deg": float(balls["outer_contact_angle_deg"].mean()),
        "inner_contact_angle_deg": float(balls["inner_contact_angle_deg"].mean()),
        "outer_load_max_n": float(balls["outer_load_n"].max()),
        "inner_load_max_n": float(balls["inner_load_n"].max()),
    }


def thermal_values(state: Any) -> dict[str, float]:
    """Every claim quantity of a coupled thermal state: node temperatures,
    heat, the deformations of Fig. 10 (the combined ones as
    ``seed_a_thermal.fig10_parts`` adds them) and the solution's
    stiffness, contact angles and loads."""
    d = state.deformations
    out = _solution_values(state.solution)
    out |= {q: state.temperature_c(n) for q, n in NODE_OF.items()}
    out |= {k: float(d[k]) for k in ("radial_thermal_offset_um", "axial_thermal_offset_um",
                                       "centrifugal_expansion_um")}  # fmt: skip
    out["heat_w"] = state.total_heat_w
    out["axial_combined_um"] = out["axial_displacement_um"] + out["axial_thermal_offset_um"]
    out["radial_combined_um"] = (
        out["radial_displacement_um"] + out["centrifugal_expansion_um"]
        + out["radial_thermal_offset_um"]
    )  # fmt: skip
    return out


class ClaimPoints:
    """The claim quantities of a bearing ``model`` (a
    [`CalibratedModel`][thermobear.CalibratedModel] of a bearing), each
    condition solved once."""

    def __init__(self, model: Any) -> None:
        self.model = model
        self._cache: dict[tuple, dict[str, float]] = {}

    def values(self, cond: Condition) -> dict[str, float]:
        """Every quantity at ``cond``."""
        fa, fr = cond.loads_n()
        key = (cond.case, cond.speed_rpm, fa, fr)
        if key not in self._cache:
            self._cache[key] = self._solve(cond.case, cond.speed_rpm, fa, fr)
        return self._cache[key]

    def _solve(self, case: str, speed_rpm: float, axial_n: float, radial_n: float) -> dict:
        from ..thermal import thermal_state

        if case == "thermal":
            return thermal_values(thermal_state(self.model, speed_rpm, axial_n, radial_n))
        bearing, options = self.model.model()
        sol = bearing.solve(
            axial_n=axial_n, radial_n=radial_n, speed_rpm=speed_rpm, effects=options["effects"]
        )
        return _solution_values(sol)

    def value(self, quantity: str, cond: Condition) -> float:
        """One quantity at ``cond``; a ConfigError names one the case lacks."""
        got = self.values(cond)
        if quantity not in got:
            raise ConfigError(
                f"invalid quantity = {quantity!r} ({cond.case} case): known: {', '.join(got)}"
            )
        return float(got[quantity])


def _reference(row: dict) -> tuple[str, str]:
    ref = str(row["reference"]).strip()
    if "=" not in ref:
        raise ConfigError(f"invalid reference = {ref!r} ({row['id']}): 'key=value'")
    key, value = ref.split("=", 1)
    return key.strip(), value.strip()


def half_sweep_rise_ratio(points: ClaimPoints, row: dict) -> float:
    """The rise of ``variant`` over the upper half of the speed sweep from
    the reference speed to the row's over its rise over the lower half."""
    cond = condition_of(row)
    lo = float(_reference(row)[1])
    mid = 0.5 * (lo + cond.speed_rpm)
    q = str(row["variant"])
    t = [points.value(q, replace(cond, speed_rpm=s)) for s in (lo, mid, cond.speed_rpm)]
    return (t[2] - t[1]) / (t[1] - t[0])


def axial_to_radial_rise_ratio(points: ClaimPoints, row: dict) -> float:
    """The rise of ``variant`` as the gear's axial force comes on over its
    rise as the radial force comes on (the other force and the preload
    held)."""
    cond = condition_of(row)
    q = str(row["variant"])
    full = points.value(q, cond)
    axial = full - points.value(q, replace(cond, gear_axial=False))
    radial = full - points.value(q, replace(cond, gear_radial=False))
    return axial / radial


def tooth_pairs_in_mesh(points_per_cycle: int = 400) -> int:
    """The fewest tooth pairs of seed A's pair (Table 3) in mesh at once
    over a mesh period: one pair's stiffness over its path through the mesh
    (``GearPair.tooth_pair_stiffness``), the pairs one mesh period apart
    counted where it is positive."""
    from ..gear import GearPair

    one = GearPair.preset("seed-electric-drive").tooth_pair_stiffness(points=points_per_cycle * 8)
    x = one["mesh_cycles"].to_numpy()
    k = one["transverse_stiffness_n_per_m"].to_numpy()
    phase = (np.arange(points_per_cycle) + 0.5) / points_per_cycle
    shifts = np.arange(int(np.ceil(x[-1])) + 1)
    at = phase[:, None] + shifts[None, :]
    inside = (at > x[0]) & (at < x[-1])
    positive = np.interp(at, x, k, left=0.0, right=0.0) > 0.0
    return int((inside & positive).sum(axis=1).min())


#: Derived quantities: name -> our value of a row.
DERIVED: dict[str, Callable[[ClaimPoints, dict], float]] = {
    "half_sweep_rise_ratio": half_sweep_rise_ratio,
    "axial_to_radial_rise_ratio": axial_to_radial_rise_ratio,
    "tooth_pairs_in_mesh": lambda points, row: float(tooth_pairs_in_mesh()),
}


def claim_value(points: ClaimPoints, row: dict) -> float:
    """Ours for one claim row: the quantity at its condition, or its
    difference or ratio against the reference (variant ``"size"``: a ratio
    of magnitudes)."""
    q = str(row["quantity"])
    if q in DERIVED:
        return float(DERIVED[q](points, row))
    cond = condition_of(row)
    ours = points.value(q, cond)
    if row["relation"] == "value":
        return ours
    key, value = _reference(row)
    if key == "quantity":
        ref = points.value(value, cond)
    else:
        ref = points.value(q, cond.moved(key, value))
    if row["relation"] == "difference":
        return ours - ref
    if row["relation"] == "ratio":
        return abs(ours) / abs(ref) if row["variant"] == "size" else ours / ref
    raise ConfigError(f"invalid relation = {row['relation']!r} ({row['id']}): not for a claim")


def basis_of(row: dict) -> str:
    """What ours is for a row, in a few words."""
    q = str(row["quantity"])
    if q == "tooth_pairs_in_mesh":
        return "fewest pairs in mesh from one pair's stiffness path (Table 3 pair)"
    if _case(row["stiffness"]) == "speed":
        return "quasi-statics without thermal effects, the seed A bearing model"
    return "coupled thermal state of the seed A bearing model (jet, fitted housing)"
