"""The rotor of a spindle laid out from its own description (the shaft,
bearing and motor dimensions), for [`thermobear.campbell`][thermobear.campbell],
[`thermobear.critical_speeds`][thermobear.critical_speeds] and
[`thermobear.vibration`][thermobear.vibration].

The layout follows the seed rotor (``src/rotor/presets.rs``), z from the tool
nose [m]: the front pair centre ``nose_length`` behind the nose, the motor
rotor centre ``front_span`` behind it, the rear pair centre ``rear_span``
further; each pair's two rows one bearing width apart about its centre. Shaft
steps: nose flange (outer diameter the front bore + 15 mm, taper bore 2/3 of
the front bore) up to the front seat; front seat (the front bore, two widths
long); motor seat (the front bore + 5 mm) up to the rear seat; rear seat (the
rear bore, two widths long); rear end 20 mm long (the rear bore - 5 mm). A
drawbar bore of 0.4 rear bores runs behind the nose. The motor rotor core
(its diameter and length, on the motor seat) and the seed's tool holder are
rigid disks.

A shaft described by its own segments (``Shaft.segments``) replaces these
steps: its steps from the nose, checked to reach past the rear pair and to
seat each pair on steps of its bore; the motor core sits on the largest
step under it.
"""

from __future__ import annotations

import json
from typing import Any

from ..errors import ConfigError

#: Steps of the layout [m]: nose flange over the front bore, motor seat over
#: the front bore, rear end under the rear bore, rear end length.
NOSE_STEP_M = 0.015
SEAT_STEP_M = 0.005
REAR_END_STEP_M = 0.005
REAR_END_LENGTH_M = 0.020


def _fail(key: str, value: float, why: str) -> ConfigError:
    return ConfigError(f"invalid {key} = {value:g}: {why}")


def rotor_layout(native: Any) -> dict[str, Any]:
    """The rotor of a native spindle (the keywords ``rotor=`` of the native
    rotor functions take): shaft steps, row positions, rotor core, bearings."""
    cfg = json.loads(native.config_json())
    p = cfg["params"]
    front, rear = p["front_bearing"], p["rear_bearing"]
    d_f, w_f = front["geometry"]["bore_m"], front["geometry"]["width_m"]
    d_r, w_r = rear["geometry"]["bore_m"], rear["geometry"]["width_m"]
    c_f = p["nose_length_m"]
    c_m = c_f + p["front_span_m"]
    c_r = c_m + p["rear_span_m"]
    if c_f < w_f:
        raise _fail(
            "shaft.nose_length_mm", c_f * 1e3, f"the front pair ({2e3 * w_f:g} mm wide) needs "
            f"at least {1e3 * w_f:g} mm between the nose and its centre for the rotor model",
        )  # fmt: skip
    half = p["rotor_length_m"] / 2.0
    core = (c_m - half, c_m + half)
    if core[0] < c_f + w_f or core[1] > c_r - w_r:
        raise _fail(
            "motor.rotor_length_mm", 2e3 * half,
            "the motor rotor core overlaps a bearing seat: lengthen the spans "
            "(shaft.front_span_mm, shaft.rear_span_mm) or shorten the core",
        )  # fmt: skip
    own = p.get("shaft_segments_m")
    if own:
        seats = [("front", c_f, w_f, d_f), ("rear", c_r, w_r, d_r)]
        steps, seat = _own_steps(own, seats, core)
    else:
        steps, seat = _derived_steps(c_f, w_f, d_f, c_r, w_r, d_r)
    if p["rotor_diameter_m"] <= seat:
        raise _fail(
            "motor.rotor_diameter_mm", p["rotor_diameter_m"] * 1e3,
            f"must exceed the motor seat on the shaft ({seat * 1e3:g} mm)",
        )  # fmt: skip
    return {
        "sections_m": [s for s in steps if s[0] > 0.0],
        "front_rows_m": [c_f - w_f / 2.0, c_f + w_f / 2.0],
        "rear_rows_m": [c_r - w_r / 2.0, c_r + w_r / 2.0],
        "core_span_m": core,
        "core_outer_diameter_m": p["rotor_diameter_m"],
        "core_inner_diameter_m": seat,
        "air_gap_m": p["air_gap_m"],
        "front_bearing_json": json.dumps(front),
        "rear_bearing_json": json.dumps(rear),
    }


def _derived_steps(
    c_f: float, w_f: float, d_f: float, c_r: float, w_r: float, d_r: float
) -> tuple[list[tuple[float, float, float]], float]:
    """The steps of the layout derived from the bores (module docstring)
    and the motor seat's diameter [m]."""
    seat, bore = d_f + SEAT_STEP_M, 0.4 * d_r
    steps = [
        (c_f - w_f, d_f + NOSE_STEP_M, 2.0 * d_f / 3.0),
        (2.0 * w_f, d_f, bore),
        ((c_r - w_r) - (c_f + w_f), seat, bore),
        (2.0 * w_r, d_r, bore),
        (REAR_END_LENGTH_M, d_r - REAR_END_STEP_M, bore),
    ]
    return steps, seat


#: Where a segment's error points in a description file.
SEGMENT_TABLE = "(in [spindle.shaft.segment])"

#: How far a seat's step may differ from its bearing's bore [m] (1 um).
SEAT_TOLERANCE_M = 1e-6


def _own_steps(
    segments: list[Any], seats: list[tuple[str, float, float, float]], core: tuple[float, float]
) -> tuple[list[tuple[float, float, float]], float]:
    """The user's shaft segments (length, outer, inner diameter [m] from the
    nose) as steps, checked: they reach past the rear pair, each pair's
    seat (its two rows, centre +- one width) lies on steps of its bore; the
    motor seat is the largest step under the core."""
    ends = [0.0]
    for length, _, _ in segments:
        ends.append(ends[-1] + length)
    name, c_r, w_r, _ = seats[-1]
    if ends[-1] < c_r + w_r - SEAT_TOLERANCE_M:
        raise _fail(
            "length_mm", segments[-1][0] * 1e3,
            f"the shaft's segments end {ends[-1] * 1e3:g} mm from the nose, before the "
            f"{name} pair's seat does ({(c_r + w_r) * 1e3:g} mm) {SEGMENT_TABLE}",
        )  # fmt: skip
    for name, c, w, bore in seats:
        for i, (_, outer, _) in enumerate(segments):
            overlap = min(ends[i + 1], c + w) - max(ends[i], c - w)
            if overlap > SEAT_TOLERANCE_M and abs(outer - bore) > SEAT_TOLERANCE_M:
                raise _fail(
                    "outer_diameter_mm", outer * 1e3,
                    f"shaft segment {i + 1} carries the {name} pair (bore {bore * 1e3:g} mm) "
                    f"between {(c - w) * 1e3:g} and {(c + w) * 1e3:g} mm from the nose: a "
                    f"bearing seat must have the bearing's bore {SEGMENT_TABLE}",
                )  # fmt: skip
    under = [seg[1] for i, seg in enumerate(segments)
             if min(ends[i + 1], core[1]) - max(ends[i], core[0]) > SEAT_TOLERANCE_M]  # fmt: skip
    return [tuple(seg) for seg in segments], max(under)
