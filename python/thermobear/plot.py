"""Figures. Every function takes ``ax=None`` (a new figure is made when
omitted) and returns the matplotlib Axes; matplotlib is imported lazily."""

from __future__ import annotations

from typing import Any, Optional, Sequence

import numpy as np

__all__ = [
    "ball_loads",
    "bifurcation",
    "contact_angles",
    "regime_map",
    "stiffness_cases",
    "stiffness_curve",
]


def _axes(ax: Any, polar: bool = False) -> Any:
    if ax is not None:
        return ax
    import matplotlib

    if matplotlib.get_backend().lower() not in ("agg",) and not _has_display():
        matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    fig = plt.figure(figsize=(6.4, 4.2))
    return fig.add_subplot(111, projection="polar" if polar else None)


def _has_display() -> bool:
    import os

    return bool(os.environ.get("DISPLAY") or os.environ.get("WAYLAND_DISPLAY"))


def stiffness_curve(df: Any, ax: Any = None, *, label: Optional[str] = None) -> Any:
    """Axial and radial stiffness (N/um) against speed from
    :func:`thermobear.stiffness_curve`."""
    ax = _axes(ax)
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
    ax = _axes(ax)
    for df, lab in zip(frames, labels):
        ax.plot(df["speed_rpm"].to_numpy(), df[column].to_numpy() / 1e6, label=lab)
    ax.set_xlabel("speed [rpm]")
    ax.set_ylabel(column.replace("_n_per_m", "").replace("_", " ") + " [N/µm]")
    ax.grid(True, alpha=0.3)
    ax.legend()
    return ax


def contact_angles(df: Any, ax: Any = None) -> Any:
    """Extreme inner and outer contact angles (deg) against speed."""
    ax = _axes(ax)
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
    ax = _axes(ax, polar=True)
    balls = solution.balls
    psi = np.radians(balls["azimuth_deg"].to_numpy())
    width = 2 * np.pi / max(len(psi), 1) * 0.4
    ax.bar(psi - width / 2, balls["inner_load_n"].to_numpy(), width=width, label="inner")
    ax.bar(psi + width / 2, balls["outer_load_n"].to_numpy(), width=width, label="outer")
    ax.set_title(f"ball loads [N] at {solution.speed_rpm:.0f} rpm")
    ax.legend(loc="lower right", fontsize="small")
    return ax


def bifurcation(
    pts: Any,
    ax: Any = None,
    *,
    y: str = "dte_um",
    s: float = 0.3,
    color: Optional[str] = None,
    label: Optional[str] = None,
) -> Any:
    """Bifurcation diagram: Poincare samples of ``y`` (default the dynamic
    transmission error in um) against ``speed_rpm``, one dot per sample, from
    :func:`thermobear.bifurcation`."""
    ax = _axes(ax)
    col = y if y in pts.columns else ("dte" if "dte" in pts.columns else y)
    ax.scatter(
        pts["speed_rpm"].to_numpy(),
        pts[col].to_numpy(),
        s=s,
        c=color or "k",
        marker=".",
        linewidths=0,
        label=label,
    )
    ax.set_xlabel("speed [rpm]")
    ax.set_ylabel(col.replace("_um", " [µm]").replace("_", " "))
    ax.grid(True, alpha=0.3)
    return ax


_REGIME_CODES = {"period-1": 1, "period-2": 2, "period-n": 3, "quasi-periodic": 4, "chaotic": 5}


def regime_map(
    df: Any, ax: Any = None, *, x: str = "speed_rpm", y: str = "torque_nm", regime: str = "regime"
) -> Any:
    """A map of motion regimes over two parameters (e.g. input torque x
    speed): period-1, period-2, higher period, quasi-periodic, chaotic."""
    from matplotlib.colors import BoundaryNorm, ListedColormap

    ax = _axes(ax)
    xs = np.unique(df[x].to_numpy())
    ys = np.unique(df[y].to_numpy())
    grid = np.full((len(ys), len(xs)), np.nan)
    xi = {v: i for i, v in enumerate(xs)}
    yi = {v: i for i, v in enumerate(ys)}
    for xv, yv, r in zip(df[x].to_numpy(), df[y].to_numpy(), df[regime].to_list()):
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


from .plot_diagnose import diagnosis_fit, diagnosis_residuals  # noqa: E402, F401
from .plot_rotor import campbell, spectrum, vibration  # noqa: E402,F401  (rotor figures)
from .plot_spindle import *  # noqa: E402,F401,F403
from .plot_thermal import heat_vs_speed, node_temperatures, thermal_deformations  # noqa: E402, F401
