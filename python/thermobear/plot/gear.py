"""Gear dynamics figures: bifurcation diagrams and regime maps."""

from __future__ import annotations

from typing import TYPE_CHECKING, Any, Optional

import numpy as np

from .axes import get_axes

if TYPE_CHECKING:
    from matplotlib.axes import Axes


def bifurcation(
    pts: Any,
    ax: Axes | None = None,
    *,
    y: str = "dte_um",
    s: float = 0.3,
    color: Optional[str] = None,
    label: Optional[str] = None,
    unsettled_color: Optional[str] = "tab:orange",
) -> Axes:
    """Bifurcation diagram: Poincare samples of ``y`` (default the dynamic
    transmission error in um) against ``speed_rpm``, one dot per sample, from
    [`thermobear.bifurcation`][thermobear.bifurcation]. Speeds whose transient did not settle
    (``settled`` False: provisional labels) are drawn in ``unsettled_color``
    (``None``: like the others)."""
    ax = get_axes(ax)
    col = y if y in pts.columns else ("dte" if "dte" in pts.columns else y)
    x, v = pts["speed_rpm"].to_numpy(), pts[col].to_numpy()
    odd = np.zeros(len(x), dtype=bool)
    if unsettled_color is not None and "settled" in pts.columns:
        odd = ~pts["settled"].to_numpy().astype(bool)
    kw: dict[str, Any] = dict(s=s, marker=".", linewidths=0)
    ax.scatter(x[~odd], v[~odd], c=color or "k", label=label, **kw)
    if odd.any():
        ax.scatter(x[odd], v[odd], c=unsettled_color, label="not settled", **kw)
    ax.set_xlabel("speed [rpm]")
    ax.set_ylabel(col.replace("_um", " [µm]").replace("_", " "))
    ax.grid(True, alpha=0.3)
    return ax


_REGIME_CODES = {"period-1": 1, "period-2": 2, "period-n": 3, "quasi-periodic": 4, "chaotic": 5}


def regime_map(
    df: Any,
    ax: Axes | None = None,
    *,
    x: str = "speed_rpm",
    y: str = "torque_n_m",
    regime: str = "regime",
) -> Axes:
    """A map of motion regimes over two parameters (e.g. input torque x
    speed): period-1, period-2, higher period, quasi-periodic, chaotic."""
    from matplotlib.colors import BoundaryNorm, ListedColormap

    ax = get_axes(ax)
    xs = np.unique(df[x].to_numpy())
    ys = np.unique(df[y].to_numpy())
    grid = np.full((len(ys), len(xs)), np.nan)
    xi = {v: i for i, v in enumerate(xs)}
    yi = {v: i for i, v in enumerate(ys)}
    for xv, yv, r in zip(df[x].to_numpy(), df[y].to_numpy(), df[regime].to_list(), strict=False):
        code = _REGIME_CODES.get(r)
        if code is None and isinstance(r, str) and r.startswith("period-"):
            code = 3
        grid[yi[yv], xi[xv]] = code if code is not None else np.nan
    cmap = ListedColormap(["#4c72b0", "#55a868", "#c4ad66", "#8172b2", "#c44e52"])
    norm = BoundaryNorm([0.5, 1.5, 2.5, 3.5, 4.5, 5.5], cmap.N)
    mesh = ax.pcolormesh(xs, ys, grid, cmap=cmap, norm=norm, shading="nearest")
    cb = ax.figure.colorbar(mesh, ax=ax, ticks=[1, 2, 3, 4, 5])
    cb.ax.set_yticklabels(["period-1", "period-2", "period-n", "quasi-per.", "chaos"])
    ax.set_xlabel(x.replace("_", " "))
    ax.set_ylabel(y.replace("_", " "))
    return ax
