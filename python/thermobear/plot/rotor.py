"""Rotor-dynamics figures: Campbell diagram, vibration velocity against
speed, spectrum. Every function takes ``ax=None`` and returns the Axes
(matplotlib imported lazily through ``thermobear.plot.axes.get_axes``)."""

from __future__ import annotations

from typing import TYPE_CHECKING, Any, Optional, Sequence

import numpy as np
from numpy.typing import ArrayLike

from .axes import get_axes

if TYPE_CHECKING:
    from matplotlib.axes import Axes

__all__ = ["campbell", "vibration", "spectrum"]


def campbell(df: Any, ax: Axes | None = None, *, orders: ArrayLike = (1.0,)) -> Axes:
    """Natural frequencies against speed from [`thermobear.campbell`][thermobear.campbell]
    (forward whirl solid, backward dashed) with the excitation lines
    f = order x speed / 60."""
    ax = get_axes(ax)
    speed = df["speed_rpm"].to_numpy()
    modes = df["mode"].to_numpy()
    freq = df["frequency_hz"].to_numpy()
    whirl = np.asarray(df["whirl"].to_list())
    for k in np.unique(modes):
        sel = modes == k
        fw = sel & (whirl == "forward")
        bw = sel & (whirl == "backward")
        ax.plot(speed[sel], freq[sel], "-", color="0.8", lw=0.8)
        ax.plot(speed[fw], freq[fw], "o", ms=2.5, color="C0", label="forward" if k == 0 else None)
        ax.plot(speed[bw], freq[bw], "s", ms=2.5, color="C3", label="backward" if k == 0 else None)
    s = np.array([speed.min(), speed.max()])
    for o in np.ravel(orders):
        ax.plot(s, o * s / 60.0, "k--", lw=1.0, label=f"{o:g}X")
    ax.set_xlabel("speed [rpm]")
    ax.set_ylabel("natural frequency [Hz]")
    ax.grid(True, alpha=0.3)
    ax.legend(fontsize="small")
    return ax


def vibration(
    frames: Sequence[Any],
    labels: Sequence[str],
    ax: Axes | None = None,
    *,
    column: str = "velocity_rms_mm_s",
    log: bool = True,
) -> Axes:
    """Vibration velocity against speed from [`thermobear.vibration`][thermobear.vibration],
    one line per frame."""
    ax = get_axes(ax)
    for df, lab in zip(frames, labels, strict=False):
        ax.plot(df["speed_rpm"].to_numpy(), df[column].to_numpy(), "o-", ms=3, label=lab)
    ax.set_xlabel("speed [rpm]")
    ax.set_ylabel(column.replace("_mm_s", " [mm/s]").replace("_", " "))
    if log:
        ax.set_yscale("log")
    ax.grid(True, which="both", alpha=0.3)
    ax.legend(fontsize="small")
    return ax


def spectrum(
    df: Any,
    ax: Axes | None = None,
    *,
    speed_rpm: Optional[float] = None,
    max_frequency_hz: Optional[float] = None,
) -> Axes:
    """Velocity amplitude spectrum from [`thermobear.spectrum`][thermobear.spectrum]; with
    ``speed_rpm`` the 1X/2X/3X frequencies are marked."""
    ax = get_axes(ax)
    f = df["frequency_hz"].to_numpy()
    a = df["velocity_mm_s"].to_numpy()
    top = max_frequency_hz if max_frequency_hz is not None else f.max()
    sel = f <= top
    ax.semilogy(f[sel], np.maximum(a[sel], 1e-12), lw=0.8)
    if speed_rpm is not None:
        for k in (1, 2, 3):
            ax.axvline(k * speed_rpm / 60.0, color="C3", ls=":", lw=0.8)
    ax.set_xlabel("frequency [Hz]")
    ax.set_ylabel("velocity amplitude [mm/s]")
    ax.grid(True, which="both", alpha=0.3)
    return ax
