"""Bearing figures: stiffness against speed, contact angles, ball loads."""

from __future__ import annotations

from typing import TYPE_CHECKING, Any, Optional, Sequence

import numpy as np

from .axes import get_axes

if TYPE_CHECKING:
    from matplotlib.axes import Axes


def stiffness_curve(
    df: Any, ax: Axes | None = None, *, label: Optional[str] = None, seed: bool = True
) -> Axes:
    """Radial and axial stiffness (N/um) against speed from
    [`thermobear.stiffness_curve`][thermobear.stiffness_curve]: the entries ``k_xx`` and ``k_zz`` of
    the full tangent stiffness (solid), and with ``seed=True`` beside them
    seed A's simplified series formula (dashed, same colour)."""
    ax = get_axes(ax)
    s = df["speed_rpm"].to_numpy()
    tag = f" ({label})" if label else ""
    for full, simple, name in (
        ("k_xx_n_per_m", "radial_stiffness_seed_n_per_m", "radial k_xx"),
        ("k_zz_n_per_m", "axial_stiffness_seed_n_per_m", "axial k_zz"),
    ):
        (line,) = ax.plot(s, df[full].to_numpy() / 1e6, "-", label=name + tag)
        if seed and simple in df.columns:
            ax.plot(
                s,
                df[simple].to_numpy() / 1e6,
                "--",
                color=line.get_color(),
                label=name.split()[0] + " (seed formula)" + tag,
            )
    ax.set_xlabel("speed [rpm]")
    ax.set_ylabel("stiffness [N/µm]")
    ax.grid(True, alpha=0.3)
    ax.legend()
    return ax


def stiffness_cases(
    frames: Sequence[Any],
    labels: Sequence[str],
    ax: Axes | None = None,
    *,
    column: str = "k_xx_n_per_m",
    seed_column: str | None = None,
) -> Axes:
    """One stiffness column against speed for several cases (e.g. constant,
    speed, thermal); default the radial entry ``k_xx`` of the full
    stiffness (``"radial_stiffness_seed_n_per_m"`` for seed A's formula).
    With ``seed_column`` (e.g. ``"radial_stiffness_seed_n_per_m"``) that
    column is drawn dashed beside each case, in the case's colour."""
    ax = get_axes(ax)
    for df, lab in zip(frames, labels, strict=False):
        s = df["speed_rpm"].to_numpy()
        (line,) = ax.plot(s, df[column].to_numpy() / 1e6, label=lab)
        if seed_column is not None:
            ax.plot(s, df[seed_column].to_numpy() / 1e6, "--", color=line.get_color(), lw=1.0)
    ax.set_xlabel("speed [rpm]")
    label = column.replace("_n_per_m", "").replace("_", " ") + " [N/µm]"
    if seed_column is not None:
        label += "; dashed: seed series formula"
    ax.set_ylabel(label)
    ax.grid(True, alpha=0.3)
    ax.legend()
    return ax


def contact_angles(df: Any, ax: Axes | None = None) -> Axes:
    """Extreme inner and outer contact angles (deg) against speed."""
    ax = get_axes(ax)
    s = df["speed_rpm"].to_numpy()
    for col, style in (
        ("inner_contact_angle_max_deg", "-"),
        ("outer_contact_angle_max_deg", "--"),
    ):
        if col in df.columns:
            ax.plot(s, df[col].to_numpy(), style, label=col.split("_")[0] + " (max)")
    ax.set_xlabel("speed [rpm]")
    ax.set_ylabel("contact angle [deg]")
    ax.grid(True, alpha=0.3)
    ax.legend()
    return ax


def ball_loads(solution: Any, ax: Axes | None = None) -> Axes:
    """Inner and outer contact loads of every ball around the bearing
    (polar; azimuth 0 = direction of the radial load)."""
    ax = get_axes(ax, polar=True)
    balls = solution.balls
    psi = np.radians(balls["azimuth_deg"].to_numpy())
    width = 2 * np.pi / max(len(psi), 1) * 0.4
    ax.bar(psi - width / 2, balls["inner_load_n"].to_numpy(), width=width, label="inner")
    ax.bar(psi + width / 2, balls["outer_load_n"].to_numpy(), width=width, label="outer")
    ax.set_title(f"ball loads [N] at {solution.speed_rpm:.0f} rpm")
    ax.legend(loc="lower right", fontsize="small")
    return ax
