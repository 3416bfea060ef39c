"""Transition speeds of a gear pair read off its bifurcation diagram: where
the low-speed period-1 motion ends, where the amplitude jumps, where
period-2 motion is seen, where irregular (chaos-like) motion starts and
ends, and the periodic windows inside it.

A transition speed is a measurement of a gear system as a temperature is
of a bearing: published bifurcation diagrams are described by exactly
these numbers ("period-2 at 12,840 r/min", "chaos in 11,750-12,460
r/min"). This module turns a sweep ([`bifurcation`][thermobear.bifurcation]
or [`bifurcation_set`][thermobear.bifurcation_set]) into the same numbers.

Each speed of a sweep gets a class from its regime label:

* ``"P1"``: period-1;
* ``"Pn"``: period-2 to period-4 (a diagram shows 2 to 4 distinct points);
* ``"C"``: irregular: chaotic, quasi-periodic, or a period of
  ``IRREGULAR_PERIOD`` mesh periods or more, which a diagram shows as a
  cloud no reader tells from chaos.

A single speed whose class differs from both neighbours (which agree) takes
their class (at an end of the sweep: from the next two), and a run of
regular motion shorter than ``MIN_WINDOW_SPEEDS`` inside irregular motion
is part of it: one grid point of another class is not a range a reader
would quote (``smoothed``). Then, for the speeds in ascending order (the
transition speeds of a diagram are read along the speed axis, in either
sweep direction):

* ``period1_end_speed_rpm``: the midpoint between the last speed of the
  low-speed period-1 range and the next one (a sweep that is not period-1
  at its lowest speed has none; one that is period-1 throughout has none);
* ``jump_speed_rpm``: each amplitude jump (``jump_after``) at the midpoint
  between the speed and the next one in sweep order;
* ``period2_speed_rpm``: every speed whose motion is period-2;
* ``multiperiod_end_speed_rpm``: the upper end (midpoint to the next
  speed) of each range of class ``"Pn"``;
* ``chaos_speed_rpm``: every speed of class ``"C"``;
* ``chaos_start_speed_rpm`` / ``chaos_end_speed_rpm``: the lower / upper
  end of each range of class ``"C"`` (midpoints; a range reaching the
  sweep's end has that end at the sweep's end);
* ``window_start_speed_rpm`` / ``window_end_speed_rpm``: the lower / upper
  end of each range of regular motion (``"P1"`` or ``"Pn"``) with
  irregular motion below it, and above it or reaching the sweep's top
  speed (a periodic window in chaos).

The model value of a quoted transition is the event of its quantity
nearest to the quoted speed, over the sweeps its condition names (a
stiffness case and a direction, or ``"any"`` of them); a bound (``"<="``:
"below 7500 r/min in all three cases") takes, for each sweep, its lowest
event and then the highest of those (the bound holds in every sweep when
this is below it). A sweep with no such event gives NaN.
"""

from __future__ import annotations

from typing import TYPE_CHECKING, Any, Mapping, Sequence

import numpy as np

if TYPE_CHECKING:
    import polars

#: The transition quantities, each with what it is.
TRANSITIONS: dict[str, str] = {
    "period1_end_speed_rpm": "end of the low-speed period-1 motion",
    "jump_speed_rpm": "a jump of the transmission-error amplitude",
    "period2_speed_rpm": "a speed of period-2 motion",
    "multiperiod_end_speed_rpm": "upper end of a range of period-2 to period-4 motion",
    "chaos_speed_rpm": "a speed of irregular (chaos-like) motion",
    "chaos_start_speed_rpm": "lower end of a range of irregular motion",
    "chaos_end_speed_rpm": "upper end of a range of irregular motion",
    "window_start_speed_rpm": "lower end of a periodic window in irregular motion",
    "window_end_speed_rpm": "upper end of a periodic window in irregular motion",
}

#: Periods (in mesh periods) from which a periodic orbit counts as
#: irregular: a bifurcation diagram shows 5 or more points per speed as a
#: cloud.
IRREGULAR_PERIOD = 5

#: The fewest speeds of a periodic window in irregular motion: fewer are
#: part of the cloud (at a 50 rpm grid, 150 rpm; the narrowest window a
#: paper quotes is about 200 rpm wide).
MIN_WINDOW_SPEEDS = 3

#: Stiffness case and direction wildcards of a quoted condition.
ANY = "any"

_IRREGULAR_REGIMES = ("chaotic", "quasi-periodic")


def speed_class(regime: str, period: int) -> str:
    """``"P1"``, ``"Pn"`` (period 2-4) or ``"C"`` (irregular) of one
    speed's regime label and period (see the module docstring)."""
    if regime in _IRREGULAR_REGIMES or period <= 0 or period >= IRREGULAR_PERIOD:
        return "C"
    return "P1" if period == 1 else "Pn"


def smoothed(classes: Sequence[str], min_window: int = 1) -> list[str]:
    """``classes`` read as a diagram is read: every single entry that
    differs from both of its neighbours (which agree) takes their class; an
    end entry that differs from the next two (which agree) takes theirs;
    then every run of regular motion (``"P1"``/``"Pn"``) shorter than
    ``min_window`` entries with irregular motion on both sides is part of
    that irregular range (a periodic point or two inside chaos is part of
    the cloud, not a window)."""
    src = list(classes)
    c = list(classes)
    n = len(c)
    for i in range(1, n - 1):
        if src[i - 1] == src[i + 1] != src[i]:
            c[i] = src[i - 1]
    if n >= 3 and src[1] == src[2] != src[0]:
        c[0] = src[1]
    if n >= 3 and src[-2] == src[-3] != src[-1]:
        c[-1] = src[-2]
    if min_window > 1:
        arr = np.array(c)
        for i, j in _runs(arr != "C"):
            if i > 0 and j < n - 1 and j - i + 1 < min_window:
                c[i : j + 1] = ["C"] * (j - i + 1)
    return c


def _runs(mask: np.ndarray) -> list[tuple[int, int]]:
    """(first, last) index of each run of True."""
    out = []
    i, n = 0, len(mask)
    while i < n:
        if mask[i]:
            j = i
            while j + 1 < n and mask[j + 1]:
                j += 1
            out.append((i, j))
            i = j + 1
        else:
            i += 1
    return out


def sweep_events(
    speeds_rpm: Any, regimes: Sequence[str], periods: Any, jumps: Any, direction: str
) -> dict[str, np.ndarray]:
    """The transition events of one sweep: ``speeds_rpm`` ascending with
    each speed's regime label, period and ``jump_after`` flag (the jump to
    the next speed in sweep order ``direction``)."""
    sp = np.asarray(speeds_rpm, dtype=float)
    per = np.asarray(periods, dtype=int)
    jmp = np.asarray(jumps, dtype=bool)
    n = len(sp)

    def mid(a: Any, b: Any) -> float:
        return float(0.5 * (sp[int(a)] + sp[int(b)]))

    classes = [speed_class(r, p) for r, p in zip(regimes, per, strict=True)]
    c = np.array(smoothed(classes, MIN_WINDOW_SPEEDS))
    ev: dict[str, list[float]] = {q: [] for q in TRANSITIONS}
    step = -1 if direction == "down" else 1
    for k in np.nonzero(jmp)[0]:
        if 0 <= k + step < n:
            ev["jump_speed_rpm"].append(mid(k, k + step))
    ev["period2_speed_rpm"] = sp[per == 2].tolist()
    ev["chaos_speed_rpm"] = sp[c == "C"].tolist()
    not_p1 = np.nonzero(c != "P1")[0]
    if len(not_p1) and not_p1[0] > 0:
        ev["period1_end_speed_rpm"].append(mid(not_p1[0] - 1, not_p1[0]))
    for _i, j in _runs(c == "Pn"):
        ev["multiperiod_end_speed_rpm"].append(mid(j, j + 1) if j < n - 1 else sp[j])
    for i, j in _runs(c == "C"):
        ev["chaos_start_speed_rpm"].append(mid(i - 1, i) if i > 0 else sp[0])
        ev["chaos_end_speed_rpm"].append(mid(j, j + 1) if j < n - 1 else sp[j])
    for i, j in _runs(c != "C"):
        if i > 0:  # irregular below; above: irregular, or the sweep's top
            ev["window_start_speed_rpm"].append(mid(i - 1, i))
            ev["window_end_speed_rpm"].append(mid(j, j + 1) if j < n - 1 else sp[j])
    return {q: np.asarray(v, dtype=float) for q, v in ev.items()}


def transition_events(pts: polars.DataFrame) -> dict[tuple[str, str], dict[str, np.ndarray]]:
    """The events of every sweep of a bifurcation frame (one per ``case``
    and ``direction``; a frame of one sweep is case ``""``): (case,
    direction) -> quantity -> event speeds [rpm]."""
    import polars as pl

    keys = [k for k in ("case", "direction") if k in pts.columns]
    per = pts.group_by([*keys, "speed_rpm"], maintain_order=True).agg(
        pl.col("regime").first(), pl.col("period").first(), pl.col("jump_after").first()
    )
    out: dict[tuple[str, str], dict[str, np.ndarray]] = {}
    groups = per.group_by(keys, maintain_order=True) if keys else [((), per)]
    for key, g in groups:
        k = dict(zip(keys, key if isinstance(key, tuple) else (key,), strict=True))
        g = g.sort("speed_rpm")
        d = str(k.get("direction", "up"))
        out[(str(k.get("case", "")), d)] = sweep_events(
            g["speed_rpm"].to_numpy(), g["regime"].to_list(), g["period"].to_numpy(),
            g["jump_after"].to_numpy(), d,
        )  # fmt: skip
    return out


def matching_sweeps(
    events: Mapping[tuple[str, str], Any], case: str, direction: str
) -> list[tuple[str, str]]:
    """The sweeps a condition names: ``case`` and ``direction`` each a
    value or ``"any"``."""
    return [
        k
        for k in events
        if (case == ANY or k[0] == case) and (direction == ANY or k[1] == direction)
    ]


def model_value(
    events: Mapping[tuple[str, str], Mapping[str, np.ndarray]],
    quantity: str,
    near_rpm: float,
    case: str = ANY,
    direction: str = ANY,
    comparison: str = "=",
) -> float:
    """The model's value of a quoted transition (see the module
    docstring): the event of ``quantity`` nearest to ``near_rpm`` over the
    sweeps of ``case`` and ``direction``, or for a bound ``"<="`` the
    highest of the sweeps' lowest events (``">="``: the lowest of their
    highest); NaN when a sweep it needs has no such event."""
    keys = matching_sweeps(events, case, direction)
    if not keys:
        return float("nan")
    if comparison in ("<=", ">="):
        per_sweep = []
        for k in keys:
            v = events[k][quantity]
            if v.size == 0:
                return float("nan")
            per_sweep.append(v.min() if comparison == "<=" else v.max())
        return float(max(per_sweep) if comparison == "<=" else min(per_sweep))
    allv = np.concatenate([events[k][quantity] for k in keys])
    if allv.size == 0:
        return float("nan")
    return float(allv[np.argmin(np.abs(allv - near_rpm))])
