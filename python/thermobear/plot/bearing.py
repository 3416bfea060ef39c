"""Bearing figures: stiffness against speed, contact angles, ball loads."""

from __future__ import annotations

from typing import TYPE_CHECKING, Any, Optional, Sequence

import numpy as np

from .axes import get_axes
from .labels import axis_label, human_name
from .style import artist_kwargs, place_legend, styled

if TYPE_CHECKING:
    from matplotlib.axes import Axes


@styled
def stiffness_curve(
    df: Any,
    ax: Axes | None = None,
    *,
    label: Optional[str] = None,
    seed: bool = True,
    **kwargs: Any,
) -> Axes:
    """Radial and axial stiffness (N/µm) against speed from
    [`thermobear.stiffness_curve`][thermobear.stiffness_curve]: the entries ``k_xx`` and ``k_zz`` of
    the full tangent stiffness (solid), and with ``seed=True`` beside them
    seed A's simplified series formula (dashed, same colour). ``kwargs``
    go to every line (``Axes.plot``: ``color``, ``lw``, ``rasterized`` ...)."""
    ax = get_axes(ax)
    s = df["speed_rpm"].to_numpy()
    tag = f" ({label})" if label else ""
    for full, simple, name in (
        ("k_xx_n_per_m", "radial_stiffness_seed_n_per_m", "radial $k_{xx}$"),
        ("k_zz_n_per_m", "axial_stiffness_seed_n_per_m", "axial $k_{zz}$"),
    ):
        (line,) = ax.plot(
            s, df[full].to_numpy() / 1e6, **artist_kwargs({"label": name + tag}, kwargs)
        )
        if seed and simple in df.columns:
            lab = name.split()[0] + ", seed formula" + tag
            dashed = {"color": line.get_color(), "ls": "--", "label": lab}
            ax.plot(s, df[simple].to_numpy() / 1e6, **artist_kwargs(dashed, kwargs))
    ax.set_xlabel(axis_label("speed_rpm"))
    ax.set_ylabel("stiffness [N/µm]")
    place_legend(ax)
    return ax


@styled
def stiffness_cases(
    frames: Sequence[Any],
    labels: Sequence[str],
    ax: Axes | None = None,
    *,
    column: str = "k_xx_n_per_m",
    seed_column: str | None = None,
    **kwargs: Any,
) -> Axes:
    """One stiffness column against speed for several cases (e.g. constant,
    speed, thermal); default the radial entry ``k_xx`` of the full
    stiffness (``"radial_stiffness_seed_n_per_m"`` for seed A's formula).
    With ``seed_column`` (e.g. ``"radial_stiffness_seed_n_per_m"``) that
    column is drawn dashed beside each case, in the case's colour.
    ``kwargs`` go to every line (``Axes.plot``)."""
    ax = get_axes(ax)
    for df, lab in zip(frames, labels, strict=False):
        s = df["speed_rpm"].to_numpy()
        (line,) = ax.plot(s, df[column].to_numpy() / 1e6, **artist_kwargs({"label": lab}, kwargs))
        if seed_column is not None:
            dashed = {"color": line.get_color(), "ls": "--", "lw": 1.0}
            ax.plot(s, df[seed_column].to_numpy() / 1e6, **artist_kwargs(dashed, kwargs))
    if seed_column is not None:  # one legend entry for the dashed lines of every case
        ax.plot([], [], color="0.3", ls="--", lw=1.0, label=f"dashed: {human_name(seed_column)}")
    ax.set_xlabel(axis_label("speed_rpm"))
    ax.set_ylabel(axis_label(column, "N/µm"))
    place_legend(ax)
    return ax


@styled
def contact_angles(df: Any, ax: Axes | None = None, **kwargs: Any) -> Axes:
    """Extreme inner and outer contact angles (°) against speed; ``kwargs``
    go to every line (``Axes.plot``)."""
    ax = get_axes(ax)
    s = df["speed_rpm"].to_numpy()
    for col, style in (
        ("inner_contact_angle_max_deg", "-"),
        ("outer_contact_angle_max_deg", "--"),
    ):
        if col in df.columns:
            ax.plot(
                s,
                df[col].to_numpy(),
                **artist_kwargs({"ls": style, "label": human_name(col)}, kwargs),
            )
    ax.set_xlabel(axis_label("speed_rpm"))
    ax.set_ylabel("contact angle [°]")
    place_legend(ax)
    return ax


@styled
def ball_loads(solution: Any, ax: Axes | None = None, **kwargs: Any) -> Axes:
    """Inner and outer contact loads of every ball around the bearing
    (polar; azimuth 0 = direction of the radial load); ``kwargs`` go to
    both bar sets (``Axes.bar``)."""
    ax = get_axes(ax, polar=True)
    balls = solution.balls
    psi = np.radians(balls["azimuth_deg"].to_numpy())
    width = 2 * np.pi / max(len(psi), 1) * 0.4
    for shift, col, lab in (
        (-0.5, "inner_load_n", "inner raceway"),
        (0.5, "outer_load_n", "outer raceway"),
    ):
        ax.bar(
            psi + shift * width,
            balls[col].to_numpy(),
            **artist_kwargs({"width": width, "label": lab}, kwargs),
        )
    ax.set_title(f"ball contact loads [N] at {solution.speed_rpm:.0f} rpm")
    place_legend(ax)
    return ax
