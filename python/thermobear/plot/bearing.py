"""Bearing figures: stiffness against speed, contact angles, ball loads."""

from __future__ import annotations

from typing import Any, Optional, Sequence

import numpy as np

from .axes import get_axes


def stiffness_curve(df: Any, ax: Any = None, *, label: Optional[str] = None) -> Any:
    """Axial and radial stiffness (N/um) against speed from
    :func:`thermobear.stiffness_curve`."""
    ax = get_axes(ax)
    s = df["speed_rpm"].to_numpy()
    tag = f" ({label})" if label else ""
    ax.plot(s, df["axial_stiffness_n_per_m"].to_numpy() / 1e6, "-", label="axial" + tag)
    ax.plot(s, df["radial_stiffness_n_per_m"].to_numpy() / 1e6, "--", label="radial" + tag)
    ax.set_xlabel("speed [rpm]")
    ax.set_ylabel("stiffness [N/µm]")
    ax.grid(True, alpha=0.3)
    ax.legend()
    return ax


def stiffness_cases(
    frames: Sequence[Any],
    labels: Sequence[str],
    ax: Any = None,
    *,
    column: str = "radial_stiffness_n_per_m",
) -> Any:
    """One stiffness column against speed for several cases (e.g. constant,
    speed, thermal)."""
    ax = get_axes(ax)
    for df, lab in zip(frames, labels, strict=False):
        ax.plot(df["speed_rpm"].to_numpy(), df[column].to_numpy() / 1e6, label=lab)
    ax.set_xlabel("speed [rpm]")
    ax.set_ylabel(column.replace("_n_per_m", "").replace("_", " ") + " [N/µm]")
    ax.grid(True, alpha=0.3)
    ax.legend()
    return ax


def contact_angles(df: Any, ax: Any = None) -> Any:
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


def ball_loads(solution: Any, ax: Any = None) -> Any:
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
