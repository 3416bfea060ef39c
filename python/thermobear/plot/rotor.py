"""Rotor-dynamics figures: Campbell diagram, vibration velocity against
speed, spectrum. Every function takes ``ax=None`` and returns the Axes
(matplotlib imported lazily through ``thermobear.plot.axes.get_axes``)."""

from __future__ import annotations

from typing import TYPE_CHECKING, Any, Optional, Sequence

import numpy as np
from numpy.typing import ArrayLike

from .axes import get_axes
from .labels import axis_label
from .style import artist_kwargs, place_legend, styled

if TYPE_CHECKING:
    from matplotlib.axes import Axes

__all__ = ["campbell", "vibration", "spectrum"]


@styled
def campbell(df: Any, ax: Axes | None = None, *, orders: ArrayLike = (1.0,), **kwargs: Any) -> Axes:
    """Natural frequencies against speed from [`thermobear.campbell`][thermobear.campbell]
    (forward whirl circles, backward squares) with the excitation lines
    f = order x speed / 60. ``kwargs`` go to the whirl markers
    (``Axes.plot``)."""
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
        for sel_w, mk, c, lab in (
            (fw, "o", "C0", "forward whirl"),
            (bw, "s", "C3", "backward whirl"),
        ):
            style = {
                "ls": "none",
                "marker": mk,
                "ms": 2.5,
                "color": c,
                "label": lab if k == 0 else None,
            }
            ax.plot(speed[sel_w], freq[sel_w], **artist_kwargs(style, kwargs))
    s = np.array([speed.min(), speed.max()])
    for o in np.ravel(orders):
        ax.plot(s, o * s / 60.0, "k--", lw=1.0, label=f"excitation {o:g}X")
    ax.set_xlabel(axis_label("speed_rpm"))
    ax.set_ylabel("natural frequency [Hz]")
    place_legend(ax)
    return ax


@styled
def vibration(
    frames: Sequence[Any],
    labels: Sequence[str],
    ax: Axes | None = None,
    *,
    column: str = "velocity_rms_mm_s",
    log: bool = True,
    **kwargs: Any,
) -> Axes:
    """Vibration velocity against speed from [`thermobear.vibration`][thermobear.vibration],
    one line per frame; ``kwargs`` go to every line (``Axes.plot``)."""
    ax = get_axes(ax)
    for df, lab in zip(frames, labels, strict=False):
        style = {"marker": "o", "ms": 3, "label": lab}
        ax.plot(df["speed_rpm"].to_numpy(), df[column].to_numpy(), **artist_kwargs(style, kwargs))
    ax.set_xlabel(axis_label("speed_rpm"))
    ax.set_ylabel(axis_label(column))
    if log:
        ax.set_yscale("log")
    ax.grid(True, which="minor", alpha=0.15)
    place_legend(ax)
    return ax


@styled
def spectrum(
    df: Any,
    ax: Axes | None = None,
    *,
    speed_rpm: Optional[float] = None,
    max_frequency_hz: Optional[float] = None,
    **kwargs: Any,
) -> Axes:
    """Velocity amplitude spectrum from [`thermobear.spectrum`][thermobear.spectrum]; with
    ``speed_rpm`` the 1X/2X/3X frequencies are marked. ``kwargs`` go to the
    spectrum line (``Axes.semilogy``)."""
    ax = get_axes(ax)
    f = df["frequency_hz"].to_numpy()
    a = df["velocity_mm_s"].to_numpy()
    top = max_frequency_hz if max_frequency_hz is not None else f.max()
    sel = f <= top
    ax.semilogy(f[sel], np.maximum(a[sel], 1e-12), **artist_kwargs({"lw": 0.8}, kwargs))
    if speed_rpm is not None:
        for k in (1, 2, 3):
            lab = "1X, 2X, 3X of the speed" if k == 1 else None
            ax.axvline(k * speed_rpm / 60.0, color="C3", ls=":", lw=0.8, label=lab)
    ax.set_xlabel(axis_label("frequency_hz"))
    ax.set_ylabel("velocity amplitude [mm/s]")
    place_legend(ax)
    return ax
