"""Rotor dynamics of the seed B motorized spindle on bearing-solver rows.

Every function takes a ``spindle`` argument, either

* a preset name: ``"seed-ceramic-spindle"`` (7009C/7008C hybrid rows, Si3N4
  balls) or ``"seed-steel-spindle"`` (all-steel rows), back-to-back pairs
  under a 400 N constant-force preload (seed B's test), or
* any object following the **spindle protocol**:

  - ``rotor_preset_name: str`` — one of the two preset names above (the
    shaft, rotor core, tool holder and bearing positions of
    ``src/rotor/presets.rs``, every assumed dimension documented there);
  - optional ``preload_n: float`` — axial preload of each pair [N] (400 N);
  - optional ``raceway_offsets(speed_rpm: float) -> dict`` returning
    ``{"front": (radial_m, axial_m), "rear": (radial_m, axial_m)}``: the
    thermal groove-centre offsets u_Tr, u_Ta (A-38) of the front (7009C)
    and rear (7008C) pairs at that speed, from the spindle's thermal model.
    This is the seam of the thermal coupling: ``coupled=True`` calls it at
    every requested speed and solves the rows with those offsets; zero
    offsets reproduce the uncoupled model exactly.

The vibration is the x velocity of the tool nose (shaft end). Amplitudes of
1X/2X/3X and of the spectrum are single-sided peak amplitudes [mm/s].
"""

from __future__ import annotations

from typing import Any, Callable, Optional, Sequence

import numpy as np

from . import _native
from .errors import ConfigError

__all__ = [
    "SPINDLE_PRESETS",
    "campbell",
    "critical_speeds",
    "spectrum",
    "spectrum_orders",
    "vibration",
]

#: Preset name -> row material of the four rows.
SPINDLE_PRESETS: dict[str, str] = {
    "seed-ceramic-spindle": "hybrid",
    "seed-steel-spindle": "steel",
}

_DEFAULT_PRELOAD_N = 400.0


def _resolve(spindle: Any) -> tuple[str, float, Optional[Callable[[float], dict]]]:
    """(row material, preload [N], offsets provider or None)."""
    if isinstance(spindle, str):
        name, preload, provider = spindle, _DEFAULT_PRELOAD_N, None
    else:
        name = getattr(spindle, "rotor_preset_name", None)
        if name is None:
            raise ConfigError(
                f"spindle={spindle!r}: pass a preset name {sorted(SPINDLE_PRESETS)} or an "
                "object with a rotor_preset_name attribute (see thermobear.rotor)"
            )
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


def _offsets(spindle: Any, speeds: np.ndarray, coupled: bool) -> Optional[dict]:
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


def _speeds(speeds_rpm: Optional[Sequence[float]], default: np.ndarray) -> np.ndarray:
    s = default if speeds_rpm is None else np.asarray(speeds_rpm, dtype=float).ravel()
    return np.ascontiguousarray(s, dtype=float)


def _effects(effects: Optional[Sequence[str]]) -> Optional[list[str]]:
    return None if effects is None else [str(e) for e in effects]


def campbell(
    spindle: Any,
    speeds_rpm: Optional[Sequence[float]] = None,
    modes: int = 8,
    *,
    coupled: bool = False,
    effects: Optional[Sequence[str]] = None,
    progress: Optional[Callable[[int, int], None]] = None,
) -> "polars.DataFrame":  # noqa: F821
    """Campbell diagram: damped natural frequencies of the lowest ``modes``
    modes against speed, with the rows' stiffness solved at each speed.

    Columns ``speed_rpm, mode, frequency_hz, damping_ratio, whirl``
    (``forward``/``backward``/``undetermined``). Default speeds 0..30,000 rpm
    in 31 steps. ``effects`` (names of :func:`thermobear.effects`) go to the
    ball solver; ``"unbalanced_magnetic_pull"`` adds the UMP (off by default).
    """
    import polars as pl

    mat, preload, _ = _resolve(spindle)
    s = _speeds(speeds_rpm, np.linspace(0.0, 30_000.0, 31))
    d = _native.rotor_campbell(
        mat,
        preload,
        s,
        modes=int(modes),
        effects=_effects(effects),
        offsets=_offsets(spindle, s, coupled),
        progress=progress,
    )
    return pl.DataFrame(d)


def critical_speeds(
    spindle: Any,
    speeds_rpm: Optional[Sequence[float]] = None,
    modes: int = 8,
    *,
    harmonic: float = 1.0,
    coupled: bool = False,
    effects: Optional[Sequence[str]] = None,
) -> "polars.DataFrame":  # noqa: F821
    """Speeds where a Campbell branch crosses f = harmonic x speed / 60
    (linear interpolation on the speed grid). Columns ``speed_rpm,
    frequency_hz, branch, whirl``. Default grid 0..120,000 rpm (121
    speeds): the seed spindle on its preloaded rows is stiff, its first
    1X crossings lie above 60,000 rpm, far beyond its 30,000 rpm service
    speed."""
    import polars as pl

    mat, preload, _ = _resolve(spindle)
    s = _speeds(speeds_rpm, np.linspace(0.0, 120_000.0, 121))
    d = _native.rotor_critical_speeds(
        mat,
        preload,
        s,
        modes=int(modes),
        harmonic=float(harmonic),
        effects=_effects(effects),
        offsets=_offsets(spindle, s, coupled),
    )
    return pl.DataFrame(d)


def vibration(
    spindle: Any,
    speeds_rpm: Optional[Sequence[float]] = None,
    coupled: bool = True,
    unbalance_grade: Optional[float] = None,
    unbalance_g_mm: Optional[float] = None,
    method: str = "frequency",
    *,
    duration_s: float = 0.1,
    effects: Optional[Sequence[str]] = None,
    progress: Optional[Callable[[int, int], None]] = None,
) -> "polars.DataFrame":  # noqa: F821
    """Shaft-end (tool nose) vibration velocity against speed under a
    residual unbalance at the rotor core: ISO 21940 grade
    ``unbalance_grade`` [mm/s] at 30,000 rpm (default G2.5), or
    ``unbalance_g_mm`` [g mm].

    ``method="frequency"``: steady unbalance response with the linearised
    rows (only 1X; RMS = 1X / sqrt 2). ``method="time"``: time response of
    ``duration_s`` with the full nonlinear ball forces and the cage turning,
    from the linear steady state; RMS, peak and 1X/2X/3X of the record.

    Columns ``speed_rpm, velocity_rms_mm_s, velocity_peak_mm_s, x1_mm_s,
    x2_mm_s, x3_mm_s, coupled, unbalance_g_mm``. ``coupled=True`` needs a
    spindle with ``raceway_offsets`` (see the module doc); otherwise a
    ConfigError explains that the thermal model is missing.
    """
    import polars as pl

    mat, preload, _ = _resolve(spindle)
    s = _speeds(speeds_rpm, np.linspace(3_000.0, 30_000.0, 10))
    d = _native.rotor_vibration(
        mat,
        preload,
        s,
        unbalance_grade=unbalance_grade,
        unbalance_g_mm=unbalance_g_mm,
        method=method,
        duration_s=float(duration_s),
        effects=_effects(effects),
        offsets=_offsets(spindle, s, coupled),
        progress=progress,
    )
    u = d.pop("unbalance_g_mm")
    return pl.DataFrame(d).with_columns(
        pl.lit(bool(coupled)).alias("coupled"), pl.lit(float(u)).alias("unbalance_g_mm")
    )


def spectrum(
    spindle: Any,
    speed_rpm: float = 12_000.0,
    duration_s: float = 0.2,
    coupled: bool = True,
    *,
    nonlinear: bool = True,
    unbalance_grade: Optional[float] = None,
    unbalance_g_mm: Optional[float] = None,
    effects: Optional[Sequence[str]] = None,
) -> "polars.DataFrame":  # noqa: F821
    """Amplitude spectrum (Hann window) of the nose velocity from a time
    response at ``speed_rpm`` (nonlinear ball forces by default). Columns
    ``frequency_hz, velocity_mm_s``. The 1X/2X/3X amplitudes at the exact
    order frequencies, RMS and peak of the same record:
    :func:`spectrum_orders`."""
    import polars as pl

    d = _spectrum_native(
        spindle, speed_rpm, duration_s, coupled, nonlinear, unbalance_grade, unbalance_g_mm, effects
    )
    return pl.DataFrame({"frequency_hz": d["frequency_hz"], "velocity_mm_s": d["velocity_mm_s"]})


def spectrum_orders(
    spindle: Any,
    speed_rpm: float = 12_000.0,
    duration_s: float = 0.2,
    coupled: bool = True,
    *,
    nonlinear: bool = True,
    unbalance_grade: Optional[float] = None,
    unbalance_g_mm: Optional[float] = None,
    effects: Optional[Sequence[str]] = None,
) -> "polars.DataFrame":  # noqa: F821
    """1X, 2X, 3X of the same time response as :func:`spectrum`: columns
    ``order, frequency_hz, velocity_mm_s`` plus ``velocity_rms_mm_s`` and
    ``velocity_peak_mm_s`` of the record."""
    import polars as pl

    d = _spectrum_native(
        spindle, speed_rpm, duration_s, coupled, nonlinear, unbalance_grade, unbalance_g_mm, effects
    )
    f1 = float(speed_rpm) / 60.0
    return pl.DataFrame(
        {
            "order": [1, 2, 3],
            "frequency_hz": [f1, 2 * f1, 3 * f1],
            "velocity_mm_s": [d["x1_mm_s"], d["x2_mm_s"], d["x3_mm_s"]],
            "velocity_rms_mm_s": [d["velocity_rms_mm_s"]] * 3,
            "velocity_peak_mm_s": [d["velocity_peak_mm_s"]] * 3,
            "unbalance_g_mm": [d["unbalance_g_mm"]] * 3,
        }
    )


def _spectrum_native(
    spindle: Any,
    speed_rpm: float,
    duration_s: float,
    coupled: bool,
    nonlinear: bool,
    unbalance_grade: Optional[float],
    unbalance_g_mm: Optional[float],
    effects: Optional[Sequence[str]],
) -> dict:
    mat, preload, _ = _resolve(spindle)
    return _native.rotor_spectrum(
        mat,
        preload,
        float(speed_rpm),
        duration_s=float(duration_s),
        nonlinear=bool(nonlinear),
        unbalance_grade=unbalance_grade,
        unbalance_g_mm=unbalance_g_mm,
        effects=_effects(effects),
        offsets=_offsets(spindle, np.array([float(speed_rpm)]), coupled),
    )
