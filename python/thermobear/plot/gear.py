"""Gear dynamics figures: bifurcation diagrams and regime maps."""

from __future__ import annotations

from typing import TYPE_CHECKING, Any, Optional

import numpy as np

from .axes import get_axes
from .labels import axis_label
from .style import artist_kwargs, place_legend, styled

if TYPE_CHECKING:
    from matplotlib.axes import Axes


@styled
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
    by_regime: bool = True,
    mark_transitions: bool = False,
    **kwargs: Any,
) -> Axes:
    """Bifurcation diagram: Poincare samples of ``y`` (default the dynamic
    transmission error in µm) against ``speed_rpm``, one dot per sample, from
    [`thermobear.bifurcation`][thermobear.bifurcation]. With a ``regime``
    column and ``by_regime=True`` (and no ``color``) each speed's dots take
    the colour of its regime (period-1, period-2, period-n (n ≥ 3),
    quasi-periodic, chaotic: the colours of [`regime_map`][thermobear.plot.regime_map]),
    one legend entry per regime. Speeds whose transient did not settle
    (``settled`` False: provisional labels) are drawn in ``unsettled_color``
    (``None``: like the others). ``kwargs`` go to every scatter
    (``Axes.scatter``); above 20,000 dots they are rasterized unless
    ``rasterized`` is given, so that PDF and SVG files stay small.

    ``mark_transitions=True`` marks, between consecutive speeds of the
    sweep, each change of the regime label (a dashed line in the colour of
    the regime entered) and each amplitude jump the sweep flagged
    (``jump_after``: a dotted black line).

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
    kw = artist_kwargs(
        {"s": s, "marker": ".", "linewidths": 0, "rasterized": len(x) > 20_000}, kwargs
    )
    regimes = pts["regime"].to_list() if by_regime and color is None and "regime" in pts else None
    _samples(ax, x[~odd], v[~odd], None if regimes is None else list(np.array(regimes)[~odd]),
             artist_kwargs({"c": color or "k", "label": label}, kw))  # fmt: skip
    if odd.any():
        ax.scatter(
            x[odd], v[odd], **artist_kwargs({"c": unsettled_color, "label": "not settled"}, kw)
        )
    ax.set_xlabel(axis_label("speed_rpm"))
    ax.set_ylabel(axis_label(col, "µm" if col == "dte" else None))
    if mark_transitions:
        mark_regime_changes(ax, pts)
    if boundaries is not None and "probability" in boundaries.columns:
        boundaries = boundaries.filter(boundaries["probability"] >= min_probability)
    if boundaries is not None and len(boundaries) > 0:
        boundary_spans(ax, boundaries, float(np.ptp(x)) if len(x) else 0.0)
    place_legend(ax, markerscale=max(1.0, 6.0 / max(s, 1e-3) ** 0.5))
    return ax


def _samples(ax: Axes, x: Any, v: Any, regimes: Optional[list[Any]], kw: dict[str, Any]) -> None:
    """The Poincare samples: one scatter in ``kw``'s colour, or with
    ``regimes`` one per regime layer in its colour and named after it."""
    if regimes is None:
        ax.scatter(x, v, **kw)
        return
    layers = np.array([regime_layer(str(r)) for r in regimes], dtype=object)
    for layer in sorted(set(layers.tolist()), key=lambda r: regime_order(layer_example(r))):
        m = layers == layer
        own = {"c": regime_color(layer_example(layer)), "label": layer}
        ax.scatter(x[m], v[m], **{**kw, **own})


def mark_regime_changes(ax: Axes, points: Any) -> None:
    """Between consecutive speeds of each sweep (in its order): a dashed
    line where the regime label changes, in the colour of the regime
    entered, and a dotted black line where the sweep flagged an amplitude
    jump (``jump_after``); one legend entry each."""
    keys = [c for c in ("speed_rpm", "regime", "jump_after") if c in points.columns]
    if "regime" not in keys and "jump_after" not in keys:
        return
    groups = [points]
    if "direction" in points.columns and points["direction"].n_unique() > 1:
        groups = [g for _, g in points.group_by("direction", maintain_order=True)]
    seen: set[str] = set()
    for g in groups:
        per = g.select(keys).unique("speed_rpm", keep="first", maintain_order=True)
        sp = per["speed_rpm"].to_numpy()
        reg = per["regime"].to_list() if "regime" in keys else [None] * len(sp)
        jump = per["jump_after"].to_list() if "jump_after" in keys else [False] * len(sp)
        for i in range(len(sp) - 1):
            at = 0.5 * (sp[i] + sp[i + 1])
            if reg[i] != reg[i + 1]:
                lab = None if "change" in seen else "regime change"
                seen.add("change")
                ax.axvline(
                    at, color=regime_color(str(reg[i + 1])), ls="--", lw=0.9, zorder=1, label=lab
                )
            if jump[i]:
                lab = None if "jump" in seen else "amplitude jump"
                seen.add("jump")
                ax.axvline(at, color="k", ls=":", lw=1.1, zorder=1, label=lab)


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
    place_legend(ax)


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


#: The layer of every period of 3 or more (as in ``regime_map``).
HIGHER_PERIODS = "period-n (n ≥ 3)"


def regime_layer(regime: str) -> str:
    """A regime's layer in a figure: its own for period-1, period-2 and
    the non-periodic regimes, one layer for all higher periods."""
    kind, period, _ = regime_order(regime)
    return HIGHER_PERIODS if kind == 0 and period >= 3 else regime


def layer_example(layer: str) -> str:
    """A regime of a layer (for its order and colour)."""
    return "period-3" if layer == HIGHER_PERIODS else layer


def short_regime(label: Any) -> str:
    """A short form of a regime label for a figure: "P1", "P2", "QP", "chaos"."""
    s = str(label)
    if s.startswith("period-"):
        return "P" + s[7:]
    return {"quasi-periodic": "QP", "chaotic": "chaos"}.get(s, s)


_REGIME_CODES = {"period-1": 1, "period-2": 2, "period-n": 3, "quasi-periodic": 4, "chaotic": 5}


@styled
def regime_map(
    df: Any,
    ax: Axes | None = None,
    *,
    x: str = "speed_rpm",
    y: str = "torque_n_m",
    regime: str = "regime",
    **kwargs: Any,
) -> Axes:
    """A map of motion regimes over two parameters (e.g. input torque x
    speed): period-1, period-2, higher period, quasi-periodic, chaotic.
    ``kwargs`` go to the mesh (``Axes.pcolormesh``, e.g. ``rasterized``)."""
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
    mesh = ax.pcolormesh(
        xs, ys, grid, **artist_kwargs({"cmap": cmap, "norm": norm, "shading": "nearest"}, kwargs)
    )
    cb = ax.figure.colorbar(mesh, ax=ax, ticks=[1, 2, 3, 4, 5])
    cb.ax.set_yticklabels(["period-1", "period-2", "period-n (n ≥ 3)", "quasi-periodic", "chaotic"])
    ax.set_xlabel(axis_label(x))
    ax.set_ylabel(axis_label(y))
    ax.grid(False)
    return ax
