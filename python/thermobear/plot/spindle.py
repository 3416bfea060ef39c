"""Spindle figures (seed B). Every function takes ``ax=None`` and returns
the Axes; re-exported by :mod:`thermobear.plot`."""

from __future__ import annotations

from typing import Any, Optional, Sequence

from .axes import get_axes

__all__ = [
    "compensation_preload",
    "optimal_preload",
    "spindle_temperatures",
    "spindle_transient",
]

_BEARING_NODES = ("front_balls_c", "front_inner_c", "front_outer_c")


def spindle_transient(df: Any, ax: Any = None, *, columns: Optional[Sequence[str]] = None) -> Any:
    """Node temperatures against time (min) from :func:`thermobear.transient`."""
    ax = get_axes(ax)
    cols = list(columns) if columns is not None else [*_BEARING_NODES, "rotor_c", "stator_c"]
    t = df["time_s"].to_numpy() / 60.0
    for c in cols:
        ax.plot(t, df[c].to_numpy(), label=c.removesuffix("_c").replace("_", " "))
    ax.set_xlabel("time [min]")
    ax.set_ylabel("temperature [°C]")
    ax.grid(True, alpha=0.3)
    ax.legend()
    return ax


def spindle_temperatures(
    df: Any, ax: Any = None, *, x: str = "speed_rpm", columns: Optional[Sequence[str]] = None
) -> Any:
    """Steady temperatures against ``x`` (speed or preload) from stacked
    :func:`thermobear.thermal_state` rows."""
    ax = get_axes(ax)
    for c in columns if columns is not None else _BEARING_NODES:
        ax.plot(
            df[x].to_numpy(), df[c].to_numpy(), "o-", label=c.removesuffix("_c").replace("_", " ")
        )
    ax.set_xlabel(x.replace("_rpm", " [rpm]").replace("_n", " [N]"))
    ax.set_ylabel("temperature [°C]")
    ax.grid(True, alpha=0.3)
    ax.legend()
    return ax


def optimal_preload(grid: Any, ax: Any = None) -> Any:
    """Total radial displacement against preload, one line per speed, from
    :func:`thermobear.spindle_grid`; the minimum of each line is marked."""
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


def compensation_preload(df: Any, ax: Any = None) -> Any:
    """Axial growth (um) and compensation preload (N) against speed from
    :func:`thermobear.compensation_preload`."""
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
