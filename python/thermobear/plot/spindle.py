"""Spindle figures (seed B). Every function takes ``ax=None`` and returns
the Axes; re-exported by [`thermobear.plot`][thermobear.plot]."""

from __future__ import annotations

from typing import TYPE_CHECKING, Any, Optional, Sequence

from .axes import get_axes

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


def spindle_transient(
    df: Any, ax: Axes | None = None, *, columns: Optional[Sequence[str]] = None
) -> Axes:
    """Node temperatures against time (min) from [`thermobear.transient`][thermobear.transient]."""
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
        ax.plot(t, df[c].to_numpy(), label=c.removesuffix("_temperature_c").replace("_", " "))
    ax.set_xlabel("time [min]")
    ax.set_ylabel("temperature [°C]")
    ax.grid(True, alpha=0.3)
    ax.legend()
    return ax


def spindle_temperatures(
    df: Any,
    ax: Axes | None = None,
    *,
    x: str = "speed_rpm",
    columns: Optional[Sequence[str]] = None,
) -> Axes:
    """Steady temperatures against ``x`` (speed or preload) from stacked
    [`thermobear.thermal_state`][thermobear.thermal_state] rows."""
    ax = get_axes(ax)
    for c in columns if columns is not None else _BEARING_NODES:
        ax.plot(
            df[x].to_numpy(),
            df[c].to_numpy(),
            "o-",
            label=c.removesuffix("_temperature_c").replace("_", " "),
        )
    ax.set_xlabel(x.replace("_rpm", " [rpm]").replace("_n", " [N]"))
    ax.set_ylabel("temperature [°C]")
    ax.grid(True, alpha=0.3)
    ax.legend()
    return ax


def optimal_preload(grid: Any, ax: Axes | None = None) -> Axes:
    """Total radial displacement against preload, one line per speed, from
    [`thermobear.spindle_grid`][thermobear.spindle_grid]; the minimum of each line is marked."""
    import polars as pl

    ax = get_axes(ax)
    for n in sorted(set(grid["speed_rpm"].to_list())):
        g = grid.filter(pl.col("speed_rpm") == n).sort("preload_n")
        p = g["preload_n"].to_numpy()
        d = g["total_radial_displacement_um"].to_numpy()
        (line,) = ax.plot(p, d, "-", label=f"{n:.0f} rpm")
        i = int(d.argmin())
        ax.plot([p[i]], [d[i]], "o", color=line.get_color())
    ax.set_xlabel("preload [N]")
    ax.set_ylabel("total radial displacement [µm]")
    ax.grid(True, alpha=0.3)
    ax.legend()
    return ax


def compensation_preload(df: Any, ax: Axes | None = None) -> Axes:
    """Axial growth (um) and compensation preload (N) against speed from
    [`thermobear.compensation_preload`][thermobear.compensation_preload]."""
    ax = get_axes(ax)
    s = df["speed_rpm"].to_numpy()
    ax.bar(
        s,
        df["compensation_preload_n"].to_numpy(),
        width=0.3 * (s.max() - s.min() + 1) / max(len(s), 1),
    )
    for x, u, f in zip(
        s, df["axial_growth_um"].to_numpy(), df["compensation_preload_n"].to_numpy(), strict=False
    ):
        ax.annotate(f"{u:.1f} µm", (x, f), ha="center", va="bottom")
    ax.set_xlabel("speed [rpm]")
    ax.set_ylabel("compensation preload [N]")
    ax.grid(True, alpha=0.3)
    return ax
