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
    seat, bore = d_f + SEAT_STEP_M, 0.4 * d_r
    if p["rotor_diameter_m"] <= seat:
        raise _fail(
            "motor.rotor_diameter_mm", p["rotor_diameter_m"] * 1e3,
            f"must exceed the motor seat on the shaft ({seat * 1e3:g} mm)",
        )  # fmt: skip
    steps = [
        (c_f - w_f, d_f + NOSE_STEP_M, 2.0 * d_f / 3.0),
        (2.0 * w_f, d_f, bore),
        ((c_r - w_r) - (c_f + w_f), seat, bore),
        (2.0 * w_r, d_r, bore),
        (REAR_END_LENGTH_M, d_r - REAR_END_STEP_M, bore),
    ]
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
