"""Which way the 6208's radial stiffness goes with speed, and at which
loads that turns (seed A Fig. 11).

Seed A says its radial stiffness "slowly improves" with speed at 100 N m.
Two measures answer differently: seed A's series formula (A-39 to A-42,
``radial_stiffness_seed_n_per_m``: per ball the inner and outer contact
stiffnesses projected by cos^2 of their contact angles, in series) and
the full tangent stiffness ``k_xx_n_per_m`` (which also carries how the
contact angles turn under the load). With speed the centrifugal force
loads the outer contacts and flattens their angle (the outer term
stiffens) while it unloads the inner contacts and steepens theirs (the
inner term softens); which change wins depends on the loads. The trend
here is the relative change from 6500 to 16,500 rpm (the paper's range),
and ``sign_changes`` finds the axial loads at which it changes sign.

The seed formula is computed two ways: the native column, and
``seed_radial_stiffness_from_balls_n_per_m`` from the solved ball set
(per contact the Hertz tangent stiffness 1.5 Q / delta, A-1).
"""

from __future__ import annotations

from typing import Any, Callable, Sequence

import numpy as np

from ..errors import ConfigError

#: The speeds a trend compares: seed A's Fig. 11 range [rpm].
SPEED_RANGE_RPM = (6500.0, 16500.0)

#: The stiffness measures a trend can be taken of.
MEASURES = ("radial_stiffness_seed_n_per_m", "k_xx_n_per_m", "seed_from_balls")


def projected_contact_stiffness_n_per_m(balls: Any) -> dict[str, np.ndarray]:
    """Per ball, the tangent stiffness k = 1.5 Q / delta (A-1) of the inner
    and of the outer contact times cos^2 of its contact angle (A-42), from
    a solved ball set (``BearingSolution.balls``): side -> array [N/m]."""
    k = {}
    for side in ("inner", "outer"):
        q = balls[f"{side}_load_n"].to_numpy()
        d = balls[f"{side}_deflection_um"].to_numpy() * 1e-6
        if np.any(d <= 0.0):
            raise ConfigError(f"invalid ball set: a {side} contact without deflection")
        cos = np.cos(np.radians(balls[f"{side}_contact_angle_deg"].to_numpy()))
        k[side] = 1.5 * q / d * cos**2
    return k


def seed_radial_stiffness_from_balls_n_per_m(balls: Any) -> float:
    """Seed A's radial stiffness (A-39 to A-42) from a solved ball set: per
    ball the projected inner and outer contact stiffnesses
    (``projected_contact_stiffness_n_per_m``) in series, summed with the
    weight cos^2 of the ball's azimuth [N/m]."""
    k = projected_contact_stiffness_n_per_m(balls)
    weight = np.cos(np.radians(balls["azimuth_deg"].to_numpy())) ** 2
    return float(np.sum(k["inner"] * k["outer"] / (k["inner"] + k["outer"]) * weight))


def radial_stiffness_n_per_m(
    model: Any, speed_rpm: float, axial_n: float, radial_n: float, measure: str, thermal: bool
) -> float:
    """One radial stiffness of a bearing ``model`` (a
    [`CalibratedModel`][thermobear.CalibratedModel] of a bearing) at a
    point: ``measure`` one of ``MEASURES``; ``thermal``: in the coupled
    thermal state, else by the quasi-statics without thermal effects."""
    from ..thermal import thermal_state

    if measure not in MEASURES:
        raise ConfigError(f"invalid measure = {measure!r}: one of {MEASURES}")
    if thermal:
        sol = thermal_state(model, speed_rpm, axial_n, radial_n).solution
    else:
        bearing, options = model.model()
        sol = bearing.solve(
            axial_n=axial_n, radial_n=radial_n, speed_rpm=speed_rpm, effects=options["effects"]
        )
    if measure == "seed_from_balls":
        return seed_radial_stiffness_from_balls_n_per_m(sol.balls)
    return float(getattr(sol, measure))


def speed_trend(model: Any, axial_n: float, radial_n: float, measure: str, thermal: bool) -> float:
    """The relative change of a radial stiffness from 6500 to 16,500 rpm
    (positive: it rises with speed)."""
    lo, hi = (
        radial_stiffness_n_per_m(model, s, axial_n, radial_n, measure, thermal)
        for s in SPEED_RANGE_RPM
    )
    return hi / lo - 1.0


def sign_changes(
    trend: Callable[[float], float], loads_n: Sequence[float], tol_n: float = 0.5
) -> list[tuple[float, str]]:
    """Every load of the grid ``loads_n`` (ascending) between two of whose
    points ``trend`` changes sign, located by bisection to ``tol_n`` [N]:
    (load, "rising to falling" or "falling to rising" as the load grows)."""
    grid = np.asarray(loads_n, dtype=float)
    if grid.size < 2 or np.any(np.diff(grid) <= 0.0):
        raise ConfigError("invalid loads_n: two or more ascending loads")
    signs = [trend(float(x)) > 0.0 for x in grid]
    out = []
    for i in range(grid.size - 1):
        if signs[i] == signs[i + 1]:
            continue
        lo, hi = float(grid[i]), float(grid[i + 1])
        while hi - lo > tol_n:
            mid = 0.5 * (lo + hi)
            lo, hi = (mid, hi) if (trend(mid) > 0.0) == signs[i] else (lo, mid)
        out.append((0.5 * (lo + hi), "rising to falling" if signs[i] else "falling to rising"))
    return out


#: The axial loads the turning table scans [N]: 20 N to 4 kN.
SCAN_AXIAL_N = tuple(np.r_[np.arange(20.0, 800.0, 40.0), np.arange(800.0, 4001.0, 200.0)])


def turning_table(model: Any, radial_loads_n: Sequence[float] = (0.0, 1189.9)) -> Any:
    """For each radial load (``radial_n``), ``measure`` (seed formula,
    k_xx) and ``case`` ("speed": without thermal effects, "thermal"): the
    axial loads at which the trend with speed changes sign over
    ``SCAN_AXIAL_N`` (``sign_changes``, text with the direction), the last
    of them (``axial_n``, null when none) and the trend at the lightest and
    heaviest scanned load (``trend_lightest``, ``trend_heaviest``: relative
    changes from 6500 to 16,500 rpm)."""
    import polars as pl

    rows = []
    for fr in radial_loads_n:
        for measure in ("radial_stiffness_seed_n_per_m", "k_xx_n_per_m"):
            for thermal in (False, True):
                trend = _trend_of(model, float(fr), measure, thermal)
                changes = sign_changes(trend, SCAN_AXIAL_N)
                rows.append({
                    "radial_n": float(fr), "measure": measure,
                    "case": "thermal" if thermal else "speed",
                    "sign_changes": ", ".join(f"{x:.0f} N ({d})" for x, d in changes),
                    "axial_n": changes[-1][0] if changes else None,
                    "trend_lightest": trend(SCAN_AXIAL_N[0]),
                    "trend_heaviest": trend(SCAN_AXIAL_N[-1]),
                })  # fmt: skip
    return pl.DataFrame(rows, schema_overrides={"axial_n": pl.Float64})


def _trend_of(model: Any, radial_n: float, measure: str, thermal: bool) -> Callable[[float], float]:
    """The speed trend as a function of the axial load alone."""

    def trend(axial_n: float) -> float:
        return speed_trend(model, axial_n, radial_n, measure, thermal)

    return trend
