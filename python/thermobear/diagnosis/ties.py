"""Ties that still help: when the data cannot tell two or more candidates
apart, each member's own calibration -- value, 95 % interval, the gap left
after adding it alone (rms residual / sigma over all points and the
held-out ones, the chi^2 test of what is left) -- and the measurement, inside
the operating envelope, that separates it from the best member."""

from __future__ import annotations

import numpy as np

from .audit import gap_table
from .identifiability import suggest_measurement
from .statistics import _chi2, noise_p_value


def tie_members(rows: list, best: dict, margin: float) -> list[str]:
    """The rivals of the best passing row: every other named candidate
    (passing or not) whose delta-BIC is less than ``margin`` below the
    best's (a higher one included) -- except one whose calibrated value
    sits at a bound of its range (it claims the data only by leaning on
    its limit, so it is no rival) and the generic control."""
    return [
        row["candidate"]
        for row in rows
        if row["candidate"] != best["candidate"]
        and row.get("kind") != "control"
        and not row.get("at_bound", False)
        and best["delta_bic"] - row["delta_bic"] < margin
    ]


#: One-sided 95 % normal quantile: a lead the rival, were it the truth,
#: would give the best by chance more often than 5 % is no lead.
LEAD_Z = 1.645


def lead_z(gap: float, pred_best: np.ndarray, pred_rival: np.ndarray, s: np.ndarray) -> float:
    """The best candidate's lead over a rival, tested against the rival
    being the truth. With Gaussian errors of known sigma, the chi^2 lead
    chi^2_rival - chi^2_best has, if the rival were true, mean -D^2 and
    standard deviation 2 D, D = ||(p_best - p_rival) / s|| the distance of
    the two fits in sigma (the noise enters through 2 sum eps_i (p_best,i -
    p_rival,i) / s_i^2). Returns (gap + D^2) / (2 D), ``gap`` the delta-BIC
    lead (the chi^2 lead when both have one parameter); +inf when the fits
    coincide (then the delta-BIC margin alone decides)."""
    dist = float(np.linalg.norm((pred_best - pred_rival) / s))
    return float("inf") if dist <= 1e-12 else (gap + dist * dist) / (2.0 * dist)


def significant_rivals(rows, fits, best, data, exclude) -> list[str]:
    """Rivals beyond the delta-BIC margin that the best candidate does not
    beat significantly: a named candidate (not at a bound, delta-BIC > 0)
    whose delta-BIC lead the rival, were it the truth, would give the best
    by chance in more than 5 % of the data sets (``lead_z`` below
    ``LEAD_Z``). This matters only for fits less than 3.3 sigma apart,
    where the margin of 2 can be crossed by noise."""
    pb = fits[best["candidate"]]["pred"]
    out = []
    for row in rows:
        name = row["candidate"]
        if name == best["candidate"] or name in exclude or row.get("at_bound", False):
            continue
        if row["delta_bic"] <= 0.0 or name not in fits:
            continue
        gap = best["delta_bic"] - row["delta_bic"]
        if lead_z(gap, pb, fits[name]["pred"], data.s) < LEAD_Z:
            out.append(name)
    return out


def _member_row(name, row, fit, data, chi_now) -> tuple:
    r = data.residual(fit["pred"])
    chi = _chi2(r)
    held = data.held
    held_rms = float(np.sqrt(np.mean(r[held] ** 2))) if held.any() else float("nan")
    return (
        name,
        fit["value"],
        fit["lower_95"],
        fit["upper_95"],
        row["delta_bic"],
        float(np.sqrt(chi_now / data.n)),
        float(np.sqrt(chi / data.n)),
        held_rms,
        noise_p_value(chi, data.n),
    )


def tie_table(members, rows, fits, curves, search, envelope, suggest):
    """One row per tie member (the best first): ``value``, ``lower_95``,
    ``upper_95``, ``delta_bic``, ``rms_before_sigma`` and ``rms_after_sigma``
    (all points, the member added alone), ``heldout_rms_after_sigma``,
    ``p_noise`` (chi^2 test of the residual left: above 0.01, the member
    alone closes the gap to within noise) and where to measure to tell it
    from the best member (``separate_quantity``, ``separate_speed_rpm``,
    ``separate_axial_n``; empty for the best)."""
    import polars as pl

    d = search.data
    by_name = {row["candidate"]: row for row in rows}
    chi_now = _chi2(d.residual(search.pred))
    out = []
    fa = curves[members[0]].slope() / d.s
    for name in members:
        where = ("", float("nan"), float("nan"))
        if suggest and name != members[0]:
            fb = curves[name].slope() / d.s
            ca, cb = curves[members[0]].cand, curves[name].cand
            where = suggest_measurement(
                search.model, search.st, ca, cb, fa, fb, d.df, search.base_options, envelope
            )
        out.append(_member_row(name, by_name[name], fits[name], d, chi_now) + tuple(where))
    schema = {
        "candidate": pl.Utf8, "value": pl.Float64, "lower_95": pl.Float64,
        "upper_95": pl.Float64, "delta_bic": pl.Float64, "rms_before_sigma": pl.Float64,
        "rms_after_sigma": pl.Float64, "heldout_rms_after_sigma": pl.Float64,
        "p_noise": pl.Float64, "separate_quantity": pl.Utf8, "separate_speed_rpm": pl.Float64,
        "separate_axial_n": pl.Float64,
    }  # fmt: skip
    return pl.DataFrame(out, schema=schema, orient="row")


def tie_gap(members, fits, search):
    """The gap table (rms residual / sigma per quantity and speed band, all
    points) after each tie member alone, with a ``candidate`` column."""
    import polars as pl

    d = search.data
    r0 = d.residual(search.pred)
    everything = np.ones(d.n, dtype=bool)
    tables = [
        gap_table(d.df, r0, d.residual(fits[m]["pred"]), everything).with_columns(
            pl.lit(m).alias("candidate")
        )
        for m in members
    ]
    return pl.concat(tables)
