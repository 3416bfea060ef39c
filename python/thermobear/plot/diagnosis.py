"""Figures of a [`Diagnosis`][thermobear.Diagnosis]: measured against
the model before and after the accepted effects, and the residual in sigma
against speed. Every function takes ``ax=None`` and returns the Axes."""

from __future__ import annotations

from typing import TYPE_CHECKING, Any, Optional

import numpy as np

from .axes import get_axes
from .labels import axis_label, human_name, name_unit
from .style import artist_kwargs, place_legend, styled

if TYPE_CHECKING:
    from matplotlib.axes import Axes

__all__ = ["diagnosis_fit", "diagnosis_residuals"]


@styled
def diagnosis_fit(
    diagnosis: Any, quantity: Optional[str] = None, ax: Axes | None = None, **kwargs: Any
) -> Axes:
    """Measured values (error bars: sigma; open markers: held out) and the
    model before/after against speed for one ``quantity`` (default: the
    first measured one; a stiffness in N/µm). ``kwargs`` go to the two model lines
    (``Axes.plot``)."""
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
    k, unit = (1e-6, "N/µm") if name_unit(str(q)) == "N/m" else (1.0, None)  # as engineers quote it
    for m, face, lab in (
        (~held, None, "measured (training)"),
        (held, "none", "measured (held out)"),
    ):
        if m.any():
            ax.errorbar(
                sp[m],
                d["value"].to_numpy()[m] * k,
                yerr=d["sigma"].to_numpy()[m] * k,
                fmt="o",
                mfc=face,
                color="k",
                ms=4,
                capsize=2,
                label=lab,
            )
    for col, ls, c, lab in (
        ("model_before", "--", "tab:red", "model before the effects"),
        ("model_after", "-", "tab:blue", "model after the effects"),
    ):
        ax.plot(
            sp, d[col].to_numpy() * k, **artist_kwargs({"ls": ls, "color": c, "label": lab}, kwargs)
        )
    ax.set_xlabel(axis_label("speed_rpm"))
    ax.set_ylabel(axis_label(str(q), unit))
    place_legend(ax)
    return ax


@styled
def diagnosis_residuals(diagnosis: Any, ax: Axes | None = None, **kwargs: Any) -> Axes:
    """Residual / sigma against speed for every measured quantity, before
    (crosses) and after (dots) the accepted effects; the band +-2 shaded.
    ``kwargs`` go to the markers (``Axes.plot``)."""
    ax = get_axes(ax)
    pts = diagnosis.points
    q = pts["quantity"].to_numpy()
    sp = pts["speed_rpm"].to_numpy()
    s = pts["sigma"].to_numpy()
    y = pts["value"].to_numpy()
    for i, qq in enumerate(sorted(set(q.tolist()))):
        m = q == qq
        c = f"C{i % 10}"
        before = {"ls": "none", "marker": "x", "color": c, "alpha": 0.6}
        after = {"ls": "none", "marker": "o", "ms": 3, "color": c, "label": human_name(qq)}
        ax.plot(
            sp[m],
            (y[m] - pts["model_before"].to_numpy()[m]) / s[m],
            **artist_kwargs(before, kwargs),
        )
        ax.plot(
            sp[m], (y[m] - pts["model_after"].to_numpy()[m]) / s[m], **artist_kwargs(after, kwargs)
        )
    ax.axhspan(-2.0, 2.0, color="0.85", zorder=0)
    ax.axhline(0.0, color="k", lw=0.8)
    ax.set_xlabel(axis_label("speed_rpm"))
    ax.set_ylabel("residual / σ (× before, ● after)")
    place_legend(ax)
    if np.isfinite(sp).all():
        ax.set_xlim(sp.min() - 0.03 * np.ptp(sp) - 1, sp.max() + 0.03 * np.ptp(sp) + 1)
    return ax
