"""Figures of a [`Diagnosis`][thermobear.Diagnosis]: measured against
the model before and after the accepted effects, and the residual in sigma
against speed. Every function takes ``ax=None`` and returns the Axes."""

from __future__ import annotations

from typing import TYPE_CHECKING, Any, Optional

import numpy as np

from .axes import get_axes

if TYPE_CHECKING:
    from matplotlib.axes import Axes

__all__ = ["diagnosis_fit", "diagnosis_residuals"]


def diagnosis_fit(diagnosis: Any, quantity: Optional[str] = None, ax: Axes | None = None) -> Axes:
    """Measured values (error bars: sigma; open markers: held out) and the
    model before/after against speed for one ``quantity`` (default: the
    first measured one)."""
    import polars as pl

    ax = get_axes(ax)
    pts = diagnosis.points
    q = quantity if quantity is not None else pts["quantity"][0]
    d = pts.filter(pl.col("quantity") == q).sort("speed_rpm")
    if d.height == 0:
        from ..errors import ConfigError

        raise ConfigError(f"invalid quantity = {q!r}: not in the measured data")
    sp = d["speed_rpm"].to_numpy()
    held = d["heldout"].to_numpy()
    for m, face, lab in (
        (~held, None, "measured (training)"),
        (held, "none", "measured (held out)"),
    ):
        if m.any():
            ax.errorbar(
                sp[m],
                d["value"].to_numpy()[m],
                yerr=d["sigma"].to_numpy()[m],
                fmt="o",
                mfc=face,
                color="k",
                ms=4,
                capsize=2,
                label=lab,
            )
    ax.plot(sp, d["model_before"].to_numpy(), "--", color="tab:red", label="model before")
    ax.plot(sp, d["model_after"].to_numpy(), "-", color="tab:blue", label="model after")
    ax.set_xlabel("speed [rpm]")
    ax.set_ylabel(q)
    ax.grid(True, alpha=0.3)
    ax.legend(fontsize=8)
    return ax


def diagnosis_residuals(diagnosis: Any, ax: Axes | None = None) -> Axes:
    """Residual / sigma against speed for every measured quantity, before
    (crosses) and after (dots) the accepted effects; the band +-2 shaded."""
    ax = get_axes(ax)
    pts = diagnosis.points
    q = pts["quantity"].to_numpy()
    sp = pts["speed_rpm"].to_numpy()
    s = pts["sigma"].to_numpy()
    y = pts["value"].to_numpy()
    for i, qq in enumerate(sorted(set(q.tolist()))):
        m = q == qq
        c = f"C{i % 10}"
        ax.plot(sp[m], (y[m] - pts["model_before"].to_numpy()[m]) / s[m], "x", color=c, alpha=0.6)
        ax.plot(
            sp[m], (y[m] - pts["model_after"].to_numpy()[m]) / s[m], "o", ms=3, color=c, label=qq
        )
    ax.axhspan(-2.0, 2.0, color="0.85", zorder=0)
    ax.axhline(0.0, color="k", lw=0.8)
    ax.set_xlabel("speed [rpm]")
    ax.set_ylabel("residual / sigma (x before, o after)")
    ax.grid(True, alpha=0.3)
    ax.legend(fontsize=7)
    if np.isfinite(sp).all():
        ax.set_xlim(sp.min() - 0.03 * np.ptp(sp) - 1, sp.max() + 0.03 * np.ptp(sp) + 1)
    return ax
