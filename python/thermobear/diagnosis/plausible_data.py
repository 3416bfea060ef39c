"""Measured data that look wrong, and what a diagnosis says when no known
effect fits.

Checks of a measurement table ([`load_measurements`][thermobear.load_measurements];
every rule with its reason on the docs page "Limits"):

* a stiffness (``*_n_per_m``) whose every value is at most
  ``STIFFNESS_N_PER_UM_MAX`` (1e4) looks like N/um: a
  [`DataError`][thermobear.DataError] (no rolling bearing or spindle is
  that soft; the same stiffness in N/um is 1..1e4);
* a displacement (``*_displacement*_um``, ``*_growth*_um``) whose every
  value is below ``DISPLACEMENT_MM_MAX_UM`` (0.2 um) in magnitude, not all 0,
  looks like mm: a [`PlausibilityWarning`][thermobear.PlausibilityWarning];
* a heat of 0 at a speed above 0: a warning (a turning bearing makes
  friction heat: a missing reading written as 0?);
* every row at one speed (those of quantities measured at rest left
  out): a note of the diagnosis (no speed law can be fitted from one
  speed; a calibration at one speed is fine);
* a change quantity (``thermobear.diagnosis.relative``) whose reading at
  its reference speed is more than 3 sigma from 0: a warning (the probe's
  zero is not among the rows).

(A temperature given in kelvin is refused by the loader itself.)

When the best named fit of a diagnosis leaves the residual far above noise
(the chi^2 test's p-value below ``UNEXPLAINED_P_VALUE``, 1e-6), its verdict
says "not explained by any known effect" (``unexplained_words``) and names
the causes it can check:

* a quantity shifted by a constant (``constant_shifts``): its own residual
  after the best fit is far above noise and a constant takes away at least
  ``SHIFT_SHARE`` (90 %) of its chi^2 -- a sensor tare, or a displacement
  probe zeroed at a reference speed, whose relative quantity is then named;
* speeds that look like rad/s (``speeds_look_like_rad_s``)."""

from __future__ import annotations

from typing import TYPE_CHECKING, Any, Collection, Optional, Sequence

import numpy as np

from ..errors import DataError
from .relative import CHANGE_FOR, CHANGE_OF, reference_speeds
from .statistics import noise_p_value

if TYPE_CHECKING:
    import polars

#: The largest value [N/m] of a stiffness column whose every value is this
#: low or lower that is refused as N/um.
STIFFNESS_N_PER_UM_MAX = 1e4

#: Below this magnitude [um] in every row, a displacement looks like mm.
DISPLACEMENT_MM_MAX_UM = 0.2

#: How many sigma a change quantity may read away from 0 at its reference
#: speed before a warning.
ZERO_SIGMA = 3.0

#: The p-value of the chi^2 test of the best named fit below which a
#: diagnosis says "not explained by any known effect" and looks for a cause.
UNEXPLAINED_P_VALUE = 1e-6

#: The least share of a quantity's chi^2 a constant must take away for the
#: quantity to count as shifted by a constant.
SHIFT_SHARE = 0.9

#: Speeds look like rad/s only when every one is below this [the unit given].
RAD_S_MAX = 2000.0
#: ... and each, times 30 / pi, lies within this many rpm of a multiple of
#: ``RPM_STEP`` (an integer rad/s is within 30 / (2 pi) = 4.8 rpm of the
#: round rpm it was converted from).
RPM_TOLERANCE = 5.0
RPM_STEP = 100.0


def _warn(message: str) -> None:
    from ..plausibility import warn

    warn(message)


def _is_displacement(q: str) -> bool:
    return q.endswith("_um") and ("displacement" in q or "growth" in q)


def check_units(df: polars.DataFrame, table: dict) -> None:
    """The unit checks of a measurement table's quantities that come
    before the plausible ranges: a stiffness in N/um is a DataError, a
    displacement in mm a warning."""
    import polars as pl

    for q in df["quantity"].unique(maintain_order=True).to_list():
        if q not in table:
            continue
        v = df.filter(pl.col("quantity") == q)["value"].to_numpy()
        if q.endswith("_n_per_m") and np.all(v > 0.0) and np.all(v <= STIFFNESS_N_PER_UM_MAX):
            raise DataError(
                f"invalid value = {v[0]:g} for {q}: every value is {STIFFNESS_N_PER_UM_MAX:g} "
                "N/m or less, which looks like N/um (a bearing's stiffness is about 1e6..1e10 "
                "N/m); give N/m (multiply by 1e6)"
            )
        big = float(np.max(np.abs(v)))
        if _is_displacement(q) and 0.0 < big < DISPLACEMENT_MM_MAX_UM:
            _warn(
                f"every value of {q} is below {DISPLACEMENT_MM_MAX_UM:g} um in magnitude "
                f"(largest {big:g}): given in mm? {q} is in um (multiply mm by 1000)"
            )


def check_readings(df: polars.DataFrame, static: Collection[str] = ()) -> None:
    """Warnings on a checked measurement table: a heat of 0 at speed, a
    change quantity away from 0 at its reference speed. (A table at one
    speed is no mistake for a calibration; the diagnosis, which compares
    speed laws, says so in its notes: ``one_speed_note``.)"""
    q = df["quantity"].to_numpy().astype(str)
    sp = df["speed_rpm"].to_numpy()
    v = df["value"].to_numpy()
    zero_heat = (q == "heat_w") & (v == 0.0) & (sp > 0.0)
    if zero_heat.any():
        i = int(np.argmax(zero_heat))
        _warn(
            f"heat_w = 0 at speed_rpm = {sp[i]:g} (row {i}): a turning bearing makes friction "
            "heat; a missing reading written as 0?"
        )
    if not np.isin(q, list(CHANGE_OF)).any():
        return
    ref = reference_speeds(df)
    s = df["sigma"].to_numpy()
    off = np.isfinite(ref) & (sp == ref) & (np.abs(v) > ZERO_SIGMA * s)
    if off.any():
        i = int(np.argmax(off))
        _warn(
            f"{q[i]} reads {v[i]:g} at speed_rpm = {sp[i]:g}, its reference speed (the lowest "
            f"measured), not 0 (more than {ZERO_SIGMA:g} sigma): a change quantity is relative "
            "to its lowest speed; give the row where the probe was zeroed (value 0)"
        )


def one_speed_note(df: polars.DataFrame, static: Collection[str] = ()) -> Optional[str]:
    """The diagnosis note when every row (the ``static`` quantities' left
    out) is at one speed, else None."""
    q = df["quantity"].to_numpy().astype(str)
    sp = df["speed_rpm"].to_numpy()
    moving = ~np.isin(q, list(static))
    if moving.sum() > 1 and np.unique(sp[moving]).size == 1:
        return (
            f"every row is at speed_rpm = {sp[moving][0]:g}: effects that differ in how they "
            "grow with speed cannot be told apart from one speed"
        )
    return None


def speeds_look_like_rad_s(speeds: Any) -> bool:
    """Whether measured speeds look like rad/s rather than rpm: at least
    two distinct speeds, every one below ``RAD_S_MAX``, not every one a
    multiple of 10 (round rpm settings are), and each, times 30 / pi
    (rad/s -> rpm), within ``RPM_TOLERANCE`` of a multiple of
    ``RPM_STEP`` (the round rpm a rad/s value is usually converted from:
    314 rad/s is 2998.5 rpm)."""
    sp = np.unique(np.asarray(speeds, dtype=float))
    sp = sp[sp > 0.0]
    if sp.size < 2 or np.any(sp >= RAD_S_MAX):
        return False
    if np.all(np.abs(sp / 10.0 - np.round(sp / 10.0)) < 1e-9):
        return False
    rpm = sp * 30.0 / np.pi
    return bool(np.all(np.abs(rpm - RPM_STEP * np.round(rpm / RPM_STEP)) <= RPM_TOLERANCE))


def constant_shifts(data: Any, pred: np.ndarray) -> list[dict]:
    """The measured quantities that look shifted by a constant after the
    fit ``pred`` (of ``data``, a ``MeasuredData``): at two distinct speeds
    or more, their own residual far above noise (p < ``UNEXPLAINED_P_VALUE``)
    and a constant (the sigma-weighted mean of value - prediction) taking
    away at least ``SHIFT_SHARE`` of its chi^2. Each: ``quantity``,
    ``offset`` (in the quantity's unit), ``share`` of its chi^2 the
    constant takes, ``zero_speed_rpm`` (the lowest speed, when every
    reading there is within 3 sigma of 0: a probe zeroed there), and
    ``change`` (its relative quantity, "" without one)."""
    out = []
    r = data.residual(pred)
    speeds = data.cond["speed_rpm"].to_numpy()
    for q in dict.fromkeys(data.quantity.tolist()):
        rows = data.quantity == q
        if np.unique(speeds[rows]).size < 2:
            continue
        rq = r[rows]
        chi = float(rq @ rq)
        if noise_p_value(chi, int(rows.sum())) >= UNEXPLAINED_P_VALUE:
            continue
        w = 1.0 / data.s[rows] ** 2
        offset = float(np.sum(w * (data.y[rows] - pred[rows])) / np.sum(w))
        left = rq - offset / data.s[rows]
        share = 1.0 - float(left @ left) / chi
        if share < SHIFT_SHARE:
            continue
        low = speeds[rows] == speeds[rows].min()
        zeroed = bool(np.all(np.abs(data.y[rows][low]) <= ZERO_SIGMA * data.s[rows][low]))
        out.append(
            {
                "quantity": str(q),
                "offset": offset,
                "share": share,
                "zero_speed_rpm": float(speeds[rows].min()) if zeroed else None,
                "change": CHANGE_FOR.get(str(q), ""),
            }
        )
    return out


def _unit(q: str) -> str:
    from ..glossary import GLOSSARY, SUFFIX_UNITS, UNIT_SUFFIXES

    if q in GLOSSARY:
        return GLOSSARY[q].unit
    return next((SUFFIX_UNITS[s] for s in UNIT_SUFFIXES if q.endswith(s)), "")


def shift_words(shift: dict, registry: Optional[dict] = None) -> str:
    """One constant shift (``constant_shifts``) and what to do about it."""
    q, unit = shift["quantity"], _unit(shift["quantity"])
    words = (
        f"{q} looks shifted by a constant ({shift['offset']:+.4g} {unit} takes away "
        f"{100.0 * shift['share']:.0f} % of its chi^2)"
    )
    change = shift["change"]
    usable = change and (registry is None or change in registry)
    if shift["zero_speed_rpm"] is not None and usable:
        return (
            f"{words}; it reads about 0 at {shift['zero_speed_rpm']:g} rpm: a displacement probe "
            f"zeroed at that speed? give it as the relative quantity {change} (its change from "
            "the lowest speed)"
        )
    if usable:
        return f"{words}: a probe zeroed at a reference speed? give it as {change}, or a tare"
    return f"{words}: a sensor tare or offset larger than the offset decoy's bounds?"


def rad_s_words(speeds: Any) -> str:
    """The hint that the speeds look like rad/s, with two of them converted."""
    sp = np.unique(np.asarray(speeds, dtype=float))
    shown = ", ".join(f"{x:g} -> {x * 30.0 / np.pi:.0f} rpm" for x in (sp[0], sp[-1]))
    return (
        f"speed_rpm looks like rad/s (every speed below {RAD_S_MAX:g}; as rad/s they are round "
        f"rpm: {shown}); give speed_rpm in rpm (multiply rad/s by 30/pi)"
    )


def best_named_chi2(data: Any, pred: np.ndarray, screening: Sequence[Any]) -> float:
    """The chi^2 of the best named fit: the setting the rounds reached
    (``pred``) or any candidate a round screened (the generic control, an
    unknown effect, left out), whichever is lower."""
    r = data.residual(pred)
    best = float(r @ r)
    for table in screening:
        if table is None or table.is_empty() or "chi2" not in table.columns:
            continue
        named = table
        if "kind" in table.columns:
            named = table.filter(table["kind"] != "control")
        got = named["chi2"].drop_nulls().drop_nans()
        if got.len():
            best = min(best, float(got.min()))
    return best


def unexplained_words(
    data: Any, pred: np.ndarray, screening: Sequence[Any], registry: Optional[dict] = None
) -> str:
    """The verdict's words when the best named fit (``best_named_chi2``)
    fails the chi^2 test at ``UNEXPLAINED_P_VALUE``: "not explained by any
    known effect", the fit's chi^2 and the causes found (constant shifts,
    speeds in rad/s); "" when the fit passes."""
    chi = best_named_chi2(data, pred, screening)
    p = noise_p_value(chi, data.n)
    if p >= UNEXPLAINED_P_VALUE:
        return ""
    pv = f"p = {p:.2g}" if p > 0.0 else "p < 1e-300"
    words = (
        f"not explained by any known effect (the best named fit leaves chi^2 {chi:.4g} on "
        f"{data.n} points, {pv})"
    )
    causes = [shift_words(s, registry) for s in constant_shifts(data, pred)]
    if speeds_look_like_rad_s(data.cond["speed_rpm"].to_numpy()):
        causes.append(rad_s_words(data.cond["speed_rpm"].to_numpy()))
    if causes:
        words += "; likely cause: " + "; ".join(causes)
    return words
