"""Spindle figures (seed B). Every function takes ``ax=None`` and returns
the Axes; re-exported by [`thermobear.plot`][thermobear.plot]."""

from __future__ import annotations

from typing import TYPE_CHECKING, Any, Optional, Sequence

from .axes import get_axes
from .labels import axis_label, human_name
from .style import artist_kwargs, place_legend, styled

if TYPE_CHECKING:
    from matplotlib.axes import Axes

__all__ = [
    "compensation_preload",
    "optimal_preload",
    "spindle_temperatures",
    "spindle_transient",
]

_BEARING_NODES = (
    "front_ball_temperature_c",
    "front_inner_ring_temperature_c",
    "front_outer_ring_temperature_c",
)


def _node(column: str) -> str:
    """A temperature column's node in words: "front bearing ball"."""
    return human_name(column).removesuffix(" temperature")


@styled
def spindle_transient(
    df: Any, ax: Axes | None = None, *, columns: Optional[Sequence[str]] = None, **kwargs: Any
) -> Axes:
    """Node temperatures against time (min) from [`thermobear.transient`][thermobear.transient];
    the legend stands beside the axes. ``kwargs`` go to every line
    (``Axes.plot``)."""
    ax = get_axes(ax)
    cols = (
        list(columns)
        if columns is not None
        else [
            *_BEARING_NODES,
            "rotor_temperature_c",
            "stator_temperature_c",
        ]
    )
    t = df["time_s"].to_numpy() / 60.0
    for c in cols:
        ax.plot(t, df[c].to_numpy(), **artist_kwargs({"label": _node(c)}, kwargs))
    ax.set_xlabel("time [min]")
    ax.set_ylabel("temperature [°C]")
    place_legend(ax)
    return ax


@styled
def spindle_temperatures(
    df: Any,
    ax: Axes | None = None,
    *,
    x: str = "speed_rpm",
    columns: Optional[Sequence[str]] = None,
    **kwargs: Any,
) -> Axes:
    """Steady temperatures against ``x`` (speed or preload) from stacked
    [`thermobear.thermal_state`][thermobear.thermal_state] rows; ``kwargs``
    go to every line (``Axes.plot``)."""
    ax = get_axes(ax)
    for c in columns if columns is not None else _BEARING_NODES:
        style = {"marker": "o", "label": _node(c)}
        ax.plot(df[x].to_numpy(), df[c].to_numpy(), **artist_kwargs(style, kwargs))
    ax.set_xlabel(axis_label(x))
    ax.set_ylabel("temperature [°C]")
    place_legend(ax)
    return ax


@styled
def optimal_preload(grid: Any, ax: Axes | None = None, **kwargs: Any) -> Axes:
    """Total radial displacement against preload, one line per speed, from
    [`thermobear.spindle_grid`][thermobear.spindle_grid]; the minimum of each line is marked.
    ``kwargs`` go to every line (``Axes.plot``)."""
    import polars as pl

    ax = get_axes(ax)
    for n in sorted(set(grid["speed_rpm"].to_list())):
        g = grid.filter(pl.col("speed_rpm") == n).sort("preload_n")
        p = g["preload_n"].to_numpy()
        d = g["total_radial_displacement_um"].to_numpy()
        (line,) = ax.plot(p, d, **artist_kwargs({"label": f"{n:,.0f} rpm"}, kwargs))
        i = int(d.argmin())
        ax.plot([p[i]], [d[i]], "o", color=line.get_color(), mfc="white")
    ax.plot([], [], "o", color="0.3", mfc="white", label="least displacement")
    ax.set_xlabel(axis_label("preload_n"))
    ax.set_ylabel(axis_label("total_radial_displacement_um"))
    place_legend(ax)
    return ax


@styled
def compensation_preload(df: Any, ax: Axes | None = None, **kwargs: Any) -> Axes:
    """Axial growth (µm, above each bar) and compensation preload (N, the
    bars) against speed from
    [`thermobear.compensation_preload`][thermobear.compensation_preload];
    ``kwargs`` go to the bars (``Axes.bar``)."""
    ax = get_axes(ax)
    s = df["speed_rpm"].to_numpy()
    width = 0.3 * (s.max() - s.min() + 1) / max(len(s), 1)
    ax.bar(s, df["compensation_preload_n"].to_numpy(), **artist_kwargs({"width": width}, kwargs))
    for x, u, f in zip(
        s, df["axial_growth_um"].to_numpy(), df["compensation_preload_n"].to_numpy(), strict=False
    ):
        ax.annotate(f"{u:.1f} µm", (x, f), xytext=(0, 2), textcoords="offset points",
                    ha="center", va="bottom", fontsize="small")  # fmt: skip
    ax.margins(y=0.15)
    ax.set_xlabel(axis_label("speed_rpm"))
    ax.set_ylabel(axis_label("compensation_preload_n"))
    return ax
