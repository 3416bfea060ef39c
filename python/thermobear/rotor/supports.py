"""The spindle a rotor model runs on: its row material, preload and the
thermal raceway offsets of its bearings (the protocol [`thermobear.rotor`][thermobear.rotor]
reads)."""

from __future__ import annotations

from typing import Any, Callable, Optional, Sequence

import numpy as np
from numpy.typing import ArrayLike

from ..errors import ConfigError

#: Preset name -> row material of the four rows.
SPINDLE_PRESETS: dict[str, str] = {
    "seed-ceramic-spindle": "hybrid",
    "seed-steel-spindle": "steel",
}


_DEFAULT_PRELOAD_N = 400.0


def _resolve(spindle: Any) -> tuple[str, float, Optional[Callable[[float], dict[str, Any]]]]:
    """(row material, preload [N], offsets provider or None)."""
    if isinstance(spindle, str):
        name, preload, provider = spindle, _DEFAULT_PRELOAD_N, None
    else:
        preset = getattr(spindle, "rotor_preset_name", None)
        if preset is None:
            raise ConfigError(
                f"spindle={spindle!r}: pass a preset name {sorted(SPINDLE_PRESETS)} or an "
                "object with a rotor_preset_name attribute (see thermobear.rotor)"
            )
        name = preset
        preload = float(getattr(spindle, "preload_n", _DEFAULT_PRELOAD_N))
        provider = getattr(spindle, "raceway_offsets", None)
    if name not in SPINDLE_PRESETS:
        raise ConfigError(f"rotor_preset_name={name!r}: must be one of {sorted(SPINDLE_PRESETS)}")
    return SPINDLE_PRESETS[name], preload, provider


def _pair(value: Any, pair: str, speed: float) -> tuple[float, float]:
    try:
        radial, axial = (float(v) for v in value)
    except (TypeError, ValueError) as e:
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


def _speeds(speeds_rpm: Optional[ArrayLike], default: np.ndarray) -> np.ndarray:
    s = default if speeds_rpm is None else np.asarray(speeds_rpm, dtype=float).ravel()
    return np.ascontiguousarray(s, dtype=float)


def _effects(effects: Optional[Sequence[str]]) -> Optional[list[str]]:
    return None if effects is None else [str(e) for e in effects]
