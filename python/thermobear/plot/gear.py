"""Gear dynamics figures: bifurcation diagrams and regime maps."""

from __future__ import annotations

from typing import TYPE_CHECKING, Any, Optional

import numpy as np

from .axes import get_axes

if TYPE_CHECKING:
    from matplotlib.axes import Axes


def bifurcation(
    points: Any,
    boundaries: Any = None,
    ax: Axes | None = None,
    *,
    y: str = "dte_um",
    s: float = 0.3,
    color: Optional[str] = None,
    label: Optional[str] = None,
    unsettled_color: Optional[str] = "tab:orange",
    min_probability: float = 0.5,
) -> Axes:
    """Bifurcation diagram: Poincare samples of ``y`` (default the dynamic
    transmission error in um) against ``speed_rpm``, one dot per sample, from
    [`thermobear.bifurcation`][thermobear.bifurcation]. Speeds whose transient did not settle
    (``settled`` False: provisional labels) are drawn in ``unsettled_color``
    (``None``: like the others).

    ``boundaries``: the regime changes with their intervals, from
    ``thermobear.regime_boundaries`` (columns
    ``from_regime``, ``to_regime``, ``speed_rpm``, ``lower_rpm``,
    ``upper_rpm``, ``probability``): each is drawn as a shaded vertical span
    over [``lower_rpm``, ``upper_rpm``] in the colour of the regime entered,
    a dashed line at ``speed_rpm`` and a label "from -> to" (with the share
    of samples that change when below 1). Only the changes at least
    ``min_probability`` of the samples show are marked (default: most)."""
    if ax is None and boundaries is not None and hasattr(boundaries, "add_patch"):
        ax, boundaries = boundaries, None  # an older call: bifurcation(points, ax)
    ax = get_axes(ax)
    pts = points
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
    if boundaries is not None and "probability" in boundaries.columns:
        boundaries = boundaries.filter(boundaries["probability"] >= min_probability)
    if boundaries is not None and len(boundaries) > 0:
        boundary_spans(ax, boundaries, float(np.ptp(x)) if len(x) else 0.0)
    return ax


#: The ``gid`` of the shaded span of each regime change a figure marks.
BOUNDARY_GID = "regime-boundary"


def boundary_spans(ax: Axes, boundaries: Any, width_rpm: float = 0.0) -> None:
    """Shade each regime change's interval [``lower_rpm``, ``upper_rpm``]
    (``gid`` ``"regime-boundary"``), a dashed line at its ``speed_rpm``
    and a label at the top of the axes (naming the member when the frame
    holds several; a label closer than 3 % of ``width_rpm`` to the one
    before it goes lower down); one legend entry for them all."""
    from matplotlib.transforms import blended_transform_factory

    trans = blended_transform_factory(ax.transData, ax.transAxes)
    several = "member" in boundaries.columns and boundaries["member"].n_unique() > 1
    last = {0.98: -np.inf, 0.6: -np.inf}  # label height -> speed of its last label
    for i, b in enumerate(boundaries.sort("speed_rpm").iter_rows(named=True)):
        c = regime_color(str(b["to_regime"]))
        lab = "regime change: interval (colour: regime entered)" if i == 0 else None
        lo, hi, at = float(b["lower_rpm"]), float(b["upper_rpm"]), float(b["speed_rpm"])
        ax.axvspan(lo, hi, color=c, alpha=0.22, lw=0, zorder=0, gid=BOUNDARY_GID, label=lab)
        ax.axvline(at, color=c, ls="--", lw=0.9, zorder=1)
        text = f"{short_regime(b['from_regime'])} \u2192 {short_regime(b['to_regime'])}"
        p = b.get("probability")
        if p is not None and np.isfinite(p) and p < 0.995:
            text += f" (p {p:.2f})"
        if several:
            text += f" [{b['member']}]"
        y = 0.98 if at - last[0.98] >= 0.03 * width_rpm else min(last, key=lambda h: last[h])
        last[y] = at
        ax.text(at, y, text, transform=trans, rotation=90, ha="right", va="top", fontsize=7,
                color="0.15")  # fmt: skip
    ax.legend(fontsize=8, loc="lower left")


_REGIME_COLORS = {"period-1": "#4c72b0", "period-2": "#55a868", "quasi-periodic": "#8172b2",
                  "chaotic": "#c44e52"}  # fmt: skip
_HIGHER_PERIOD_COLORS = ("#c4ad66", "#dd8452", "#937860", "#da8bc3")


def regime_order(label: str) -> tuple[int, int, str]:
    """Sort key of a regime label: period-1, period-2, ... period-n,
    quasi-periodic, chaotic, then any other label alphabetically."""
    if label.startswith("period-") and label[7:].isdigit():
        return (0, int(label[7:]), label)
    return ({"quasi-periodic": 1, "chaotic": 2}.get(label, 3), 0, label)


def regime_color(label: str) -> str:
    """The colour of a regime label (as in [`regime_map`][thermobear.plot.regime_map]
    for period-1, period-2, quasi-periodic and chaotic; higher periods in
    turn from a warm palette; grey for any other label)."""
    if label in _REGIME_COLORS:
        return _REGIME_COLORS[label]
    kind, period, _ = regime_order(label)
    if kind == 0:
        return _HIGHER_PERIOD_COLORS[(period - 3) % len(_HIGHER_PERIOD_COLORS)]
    return "0.6"


def short_regime(label: Any) -> str:
    """A short form of a regime label for a figure: "P1", "P2", "QP", "chaos"."""
    s = str(label)
    if s.startswith("period-"):
        return "P" + s[7:]
    return {"quasi-periodic": "QP", "chaotic": "chaos"}.get(s, s)


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
