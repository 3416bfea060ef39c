"""Thermal figures (heat, node temperatures, thermal deformations against
speed or load). Every function takes ``ax=None`` and returns the Axes."""

from __future__ import annotations

from typing import TYPE_CHECKING, Any, Optional, Sequence

from .axes import get_axes
from .labels import axis_label, human_name
from .style import artist_kwargs, place_legend, styled

if TYPE_CHECKING:
    from matplotlib.axes import Axes

__all__ = ["heat_vs_speed", "node_temperatures", "thermal_deformations"]


@styled
def heat_vs_speed(
    frames: Sequence[Any],
    labels: Sequence[str],
    ax: Axes | None = None,
    *,
    column: str = "heat_w",
    x: str = "speed_rpm",
    **kwargs: Any,
) -> Axes:
    """Bearing heat [W] against speed for several cases (e.g. preloads),
    from [`thermobear.stiffness_curve`][thermobear.stiffness_curve] with ``mode="thermal"``;
    ``kwargs`` go to every line (``Axes.plot``)."""
    ax = get_axes(ax)
    for df, lab in zip(frames, labels, strict=False):
        style = {"marker": "o", "ms": 3, "label": lab}
        ax.plot(df[x].to_numpy(), df[column].to_numpy(), **artist_kwargs(style, kwargs))
    ax.set_xlabel(axis_label(x))
    ax.set_ylabel(axis_label(column))
    place_legend(ax)
    return ax


_NODES = (
    ("shaft_temperature_c", "shaft Ts"),
    ("inner_ring_temperature_c", "inner raceway Ti"),
    ("ball_temperature_c", "balls Tb"),
    ("outer_ring_temperature_c", "outer raceway To"),
    ("housing_temperature_c", "housing Th"),
)


@styled
def node_temperatures(
    df: Any,
    ax: Axes | None = None,
    *,
    x: str = "speed_rpm",
    xlabel: Optional[str] = None,
    **kwargs: Any,
) -> Axes:
    """Node temperatures [°C] against ``x`` (speed or a load column);
    ``kwargs`` go to every line (``Axes.plot``)."""
    ax = get_axes(ax)
    xs = df[x].to_numpy()
    for col, lab in _NODES:
        if col in df.columns:
            style = {"marker": "o", "ms": 3, "label": lab}
            ax.plot(xs, df[col].to_numpy(), **artist_kwargs(style, kwargs))
    ax.set_xlabel(xlabel or axis_label(x))
    ax.set_ylabel("temperature [°C]")
    place_legend(ax)
    return ax


@styled
def thermal_deformations(df: Any, ax: Axes | None = None, **kwargs: Any) -> Axes:
    """Radial and axial thermal offsets of the groove centres (A-38, ball
    growth included), the ball growth and the centrifugal ring expansion
    [µm] against speed; ``kwargs`` go to every line (``Axes.plot``)."""
    ax = get_axes(ax)
    s = df["speed_rpm"].to_numpy()
    for col, style in (
        ("radial_thermal_offset_um", "-"),
        ("axial_thermal_offset_um", "--"),
        ("ball_growth_um", ":"),
        ("centrifugal_expansion_um", "-."),
    ):
        if col in df.columns:
            ax.plot(
                s,
                df[col].to_numpy(),
                **artist_kwargs({"ls": style, "label": human_name(col)}, kwargs),
            )
    ax.axhline(0.0, color="k", lw=0.5)
    ax.set_xlabel(axis_label("speed_rpm"))
    ax.set_ylabel("displacement [µm]")
    place_legend(ax)
    return ax
