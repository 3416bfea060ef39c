"""Thermal figures (heat, node temperatures, thermal deformations against
speed or load). Every function takes ``ax=None`` and returns the Axes."""

from __future__ import annotations

from typing import TYPE_CHECKING, Any, Optional, Sequence

from .axes import get_axes

if TYPE_CHECKING:
    from matplotlib.axes import Axes

__all__ = ["heat_vs_speed", "node_temperatures", "thermal_deformations"]


def heat_vs_speed(
    frames: Sequence[Any],
    labels: Sequence[str],
    ax: Axes | None = None,
    *,
    column: str = "heat_w",
    x: str = "speed_rpm",
) -> Axes:
    """Bearing heat [W] against speed for several cases (e.g. preloads),
    from [`thermobear.stiffness_curve`][thermobear.stiffness_curve] with ``mode="thermal"``."""
    ax = get_axes(ax)
    for df, lab in zip(frames, labels, strict=False):
        ax.plot(df[x].to_numpy(), df[column].to_numpy(), "o-", ms=3, label=lab)
    ax.set_xlabel("speed [rpm]" if x == "speed_rpm" else x)
    ax.set_ylabel("heat [W]")
    ax.grid(True, alpha=0.3)
    ax.legend()
    return ax


_NODES = (
    ("shaft_temperature_c", "shaft Ts"),
    ("inner_ring_temperature_c", "inner raceway Ti"),
    ("ball_temperature_c", "balls Tb"),
    ("outer_ring_temperature_c", "outer raceway To"),
    ("housing_temperature_c", "housing Th"),
)


def node_temperatures(
    df: Any, ax: Axes | None = None, *, x: str = "speed_rpm", xlabel: Optional[str] = None
) -> Axes:
    """Node temperatures [C] against ``x`` (speed or a load column)."""
    ax = get_axes(ax)
    xs = df[x].to_numpy()
    for col, lab in _NODES:
        if col in df.columns:
            ax.plot(xs, df[col].to_numpy(), "o-", ms=3, label=lab)
    ax.set_xlabel(xlabel or ("speed [rpm]" if x == "speed_rpm" else x))
    ax.set_ylabel("temperature [°C]")
    ax.grid(True, alpha=0.3)
    ax.legend(fontsize="small")
    return ax


def thermal_deformations(df: Any, ax: Axes | None = None) -> Axes:
    """Radial and axial thermal offsets of the groove centres (A-38, ball
    growth included), the ball growth and the centrifugal ring expansion
    [um] against speed."""
    ax = get_axes(ax)
    s = df["speed_rpm"].to_numpy()
    for col, style, lab in (
        ("radial_thermal_offset_um", "-", "radial thermal offset u_Tr"),
        ("axial_thermal_offset_um", "--", "axial thermal offset u_Ta"),
        ("ball_growth_um", ":", "ball diameter growth"),
        ("centrifugal_expansion_um", "-.", "centrifugal ring expansion"),
    ):
        if col in df.columns:
            ax.plot(s, df[col].to_numpy(), style, label=lab)
    ax.axhline(0.0, color="k", lw=0.5)
    ax.set_xlabel("speed [rpm]")
    ax.set_ylabel("displacement [µm]")
    ax.grid(True, alpha=0.3)
    ax.legend(fontsize="small")
    return ax
