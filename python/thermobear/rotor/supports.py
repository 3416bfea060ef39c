"""The spindle a rotor model runs on: its row material, preload and the
thermal raceway offsets of its bearings (the protocol [`thermobear.rotor`][thermobear.rotor]
reads)."""

from __future__ import annotations

from typing import Any, Callable, Optional, Sequence

import numpy as np
from numpy.typing import ArrayLike

from .. import _validate as val
from ..errors import ConfigError

#: Preset name -> row material of the four rows.
SPINDLE_PRESETS: dict[str, str] = {
    "seed-ceramic-spindle": "hybrid",
    "seed-steel-spindle": "steel",
}


_DEFAULT_PRELOAD_N = 400.0


def _rotor(spindle: Any) -> Optional[dict[str, Any]]:
    """The spindle's own rotor (its ``rotor_layout``), None: a seed rotor."""
    return None if isinstance(spindle, str) else getattr(spindle, "rotor_layout", None)


def _resolve(spindle: Any) -> tuple[str, float, Optional[Callable[[float], dict[str, Any]]]]:
    """(row material, preload [N], offsets provider or None); the material
    is not used by a spindle with its own rotor (``_rotor``)."""
    if isinstance(spindle, str):
        name, preload, provider = spindle, _DEFAULT_PRELOAD_N, None
    elif _rotor(spindle) is not None:
        name = "seed-steel-spindle"
        preload = val.real("preload_n", getattr(spindle, "preload_n", _DEFAULT_PRELOAD_N), 0.0)
        provider = getattr(spindle, "raceway_offsets", None)
    else:
        preset = getattr(spindle, "rotor_preset_name", None)
        if preset is None:
            raise ConfigError(
                f"spindle={spindle!r}: pass a preset name {sorted(SPINDLE_PRESETS)} or an "
                "object with a rotor_preset_name attribute (see thermobear.rotor)"
            )
        name = preset
        preload = val.real("preload_n", getattr(spindle, "preload_n", _DEFAULT_PRELOAD_N), 0.0)
        provider = getattr(spindle, "raceway_offsets", None)
    if not isinstance(name, str) or name not in SPINDLE_PRESETS:
        raise ConfigError(f"rotor_preset_name={name!r}: must be one of {sorted(SPINDLE_PRESETS)}")
    return SPINDLE_PRESETS[name], preload, provider


def _pair(value: Any, pair: str, speed: float) -> tuple[float, float]:
    try:
        radial, axial = (float(v) for v in value)
    except (TypeError, ValueError, OverflowError) as e:
        raise ConfigError(
            f"raceway_offsets({speed})[{pair!r}]={value!r}: must be (radial_m, axial_m)"
        ) from e
    if not (np.isfinite(radial) and np.isfinite(axial)):
        raise ConfigError(f"raceway_offsets({speed})[{pair!r}]={value!r}: must be finite")
    return radial, axial


def _offsets(spindle: Any, speeds: np.ndarray, coupled: bool) -> Optional[dict[str, Any]]:
    """The offsets dict for the native call (None: uncoupled)."""
    if not coupled:
        return None
    _, _, provider = _resolve(spindle)
    if provider is None:
        raise ConfigError(
            f"coupled=True: spindle={spindle!r} has no raceway_offsets(speed_rpm); the "
            "thermally coupled vibration needs the spindle's thermal model to supply the "
            "raceway offsets (spindle protocol in thermobear.rotor). Use coupled=False for "
            "the uncoupled model."
        )
    cols: dict[str, list[float]] = {
        k: [] for k in ("front_radial_m", "front_axial_m", "rear_radial_m", "rear_axial_m")
    }
    grid = np.unique(speeds)
    for n in grid:
        o = provider(float(n))
        for pair in ("front", "rear"):
            if pair not in o:
                raise ConfigError(f"raceway_offsets({n})={o!r}: missing key {pair!r}")
            r, a = _pair(o[pair], pair, float(n))
            cols[f"{pair}_radial_m"].append(r)
            cols[f"{pair}_axial_m"].append(a)
    return {"speed_rpm": [float(n) for n in grid], **cols}


def _speeds(
    speeds_rpm: Optional[ArrayLike], default: np.ndarray, *, positive: bool = False
) -> np.ndarray:
    """The speeds [rpm] (``default`` when None): finite, >= 0 (> 0 with ``positive``)."""
    s = default if speeds_rpm is None else val.reals("speeds_rpm", speeds_rpm, 0.0)
    if positive and s.min() <= 0.0:
        raise val.fail("speeds_rpm", speeds_rpm, "finite speeds > 0 rpm")
    return np.ascontiguousarray(s, dtype=float)


def _effects(effects: Optional[Sequence[str]]) -> Optional[list[str]]:
    return val.optional_names("effects", effects, one=True)


#: Time steps per revolution of the rotor's time response, and the most a
#: run may take (the native integrator's cap: ``src/rotor/spindle_vibration.rs``,
#: ``src/rotor/transient.rs``).
STEPS_PER_REVOLUTION = 64
MAX_TIME_STEPS = 10_000_000


def _time_record(speed_rpm: float, duration_s: Any) -> float:
    """``duration_s`` checked for a time response at ``speed_rpm``: > 0,
    and no more than ``MAX_TIME_STEPS`` steps of 1/64 revolution."""
    d = val.real("duration_s", duration_s, 0.0, open_lo=True)
    steps = d * speed_rpm / 60.0 * STEPS_PER_REVOLUTION
    if steps > MAX_TIME_STEPS:
        raise ConfigError(
            f"invalid duration_s = {d:g} at speed_rpm = {speed_rpm:g}: the time response takes "
            f"{steps:.3g} steps of 1/{STEPS_PER_REVOLUTION} revolution, more than the "
            f"{MAX_TIME_STEPS} a run may take; use duration_s <= "
            f"{MAX_TIME_STEPS * 60.0 / STEPS_PER_REVOLUTION / speed_rpm:.3g} s"
        )
    return d
