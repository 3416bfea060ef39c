"""Forced response of the spindle rotor to its unbalance: vibration
velocity and displacement against speed, the spectrum and its orders."""

from __future__ import annotations

from typing import TYPE_CHECKING, Any, Callable, Optional, Sequence

import numpy as np
from numpy.typing import ArrayLike

from .. import _native
from .. import _validate as val
from .._model_hook import takes_calibrated
from .._partial import speed_frames
from .._types import ResponseMethod, VibrationModel
from ..errors import ThermobearError
from .supports import _effects, _offsets, _resolve, _rotor, _speeds, _time_record

if TYPE_CHECKING:
    import polars


@takes_calibrated()
def vibration(
    spindle: Any,
    speeds_rpm: Optional[ArrayLike] = None,
    coupled: bool = True,
    unbalance_grade: Optional[float] = None,
    unbalance_g_mm: Optional[float] = None,
    method: ResponseMethod = "frequency",
    *,
    duration_s: float = 0.1,
    effects: Optional[Sequence[str]] = None,
    progress: Optional[Callable[[int, int], None]] = None,
    model: VibrationModel = "rotor",
) -> polars.DataFrame:
    """Shaft-end (tool nose) vibration velocity against speed under a
    residual unbalance at the rotor core: ISO 21940 grade
    ``unbalance_grade`` [mm/s] at 30,000 rpm (default G2.5), or
    ``unbalance_g_mm`` [g mm].

    ``model="seed-b"``: seed B's own model instead of the rotor's forced
    response -- the velocity omega x (bearing radial displacement + radial
    thermal displacement) of
    [`thermobear.rotor.displacement_vibration`][thermobear.rotor.displacement_vibration]
    (its assumptions are listed there); ``spindle`` must then be a
    [`thermobear.Spindle`][thermobear.Spindle] or a preset name, and the unbalance,
    ``method`` and ``effects`` arguments do not apply.

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

    coupled = val.flag("coupled", coupled)
    if val.choice("model", model, ("rotor", "seed-b")) == "seed-b":
        from .displacement import displacement_vibration

        return displacement_vibration(spindle, speeds_rpm, coupled).with_columns(
            pl.lit(coupled).alias("coupled")
        )
    mat, preload, _ = _resolve(spindle)
    s = _speeds(speeds_rpm, np.linspace(3_000.0, 30_000.0, 10))
    method = val.choice("method", method, ("frequency", "time"))
    unbalance = _unbalance(unbalance_grade, unbalance_g_mm)
    duration_s = _time_record(float(s.max()), duration_s) if method == "time" else 0.1

    def frame(d: Any, _speeds_done: Any = None) -> polars.DataFrame:
        d = dict(d)
        u = d.pop("unbalance_g_mm")
        return pl.DataFrame(d).with_columns(
            pl.lit(bool(coupled)).alias("coupled"), pl.lit(float(u)).alias("unbalance_g_mm")
        )

    try:
        d = _native.rotor_vibration(
            mat,
            preload,
            s,
            unbalance_grade=unbalance[0],
            unbalance_g_mm=unbalance[1],
            method=method,
            duration_s=duration_s,
            effects=_effects(effects),
            offsets=_offsets(spindle, s, coupled),
            rotor=_rotor(spindle),
            progress=progress,
        )
    except ThermobearError as e:
        speed_frames(e, s, frame)
        raise
    return frame(d)


@takes_calibrated()
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
) -> polars.DataFrame:
    """Amplitude spectrum (Hann window) of the nose velocity from a time
    response at ``speed_rpm`` (nonlinear ball forces by default). Columns
    ``frequency_hz, velocity_mm_s``. The 1X/2X/3X amplitudes at the exact
    order frequencies, RMS and peak of the same record:
    [`spectrum_orders`][thermobear.spectrum_orders]."""
    import polars as pl

    d = _spectrum_native(
        spindle, speed_rpm, duration_s, coupled, nonlinear, unbalance_grade, unbalance_g_mm, effects
    )
    return pl.DataFrame({"frequency_hz": d["frequency_hz"], "velocity_mm_s": d["velocity_mm_s"]})


@takes_calibrated()
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
) -> polars.DataFrame:
    """1X, 2X, 3X of the same time response as [`spectrum`][thermobear.spectrum]: columns
    ``order, frequency_hz, velocity_mm_s`` plus ``velocity_rms_mm_s`` and
    ``velocity_peak_mm_s`` of the record."""
    import polars as pl

    d = _spectrum_native(
        spindle, speed_rpm, duration_s, coupled, nonlinear, unbalance_grade, unbalance_g_mm, effects
    )
    f1 = val.real("speed_rpm", speed_rpm) / 60.0  # checked in _spectrum_native
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
) -> dict[str, Any]:
    mat, preload, _ = _resolve(spindle)
    n = val.real("speed_rpm", speed_rpm, 0.0, open_lo=True)
    grade, g_mm = _unbalance(unbalance_grade, unbalance_g_mm)
    return _native.rotor_spectrum(
        mat,
        preload,
        n,
        duration_s=_time_record(n, duration_s),
        nonlinear=val.flag("nonlinear", nonlinear),
        unbalance_grade=grade,
        unbalance_g_mm=g_mm,
        effects=_effects(effects),
        offsets=_offsets(spindle, np.array([n]), val.flag("coupled", coupled)),
        rotor=_rotor(spindle),
    )


#: The coarsest balance quality grade of ISO 21940-11 (G 4000 [mm/s]), and the
#: unbalance [g mm] above it on the seed spindle's rotor (G 4000 is 7,841 g mm
#: there, rounded up): the largest residual unbalances the model accepts.
_MAX_GRADE = 4000.0
_MAX_G_MM = 1.0e4


def _unbalance(grade: Any, g_mm: Any) -> tuple[Optional[float], Optional[float]]:
    """The residual unbalance arguments: each None or a finite number in
    [0, the coarsest ISO 21940-11 grade] (a grade [mm/s], a mass times
    radius [g mm])."""
    return (
        val.optional_real("unbalance_grade", grade, 0.0, _MAX_GRADE),
        val.optional_real("unbalance_g_mm", g_mm, 0.0, _MAX_G_MM),
    )
