"""Seed B's bearing-mechanics results drawn from thermobear's spindle model:
radial dynamic stiffness (Fig. 12), contact angles (Fig. 13), contact loads
(Fig. 14) and radial displacements (Fig. 15) of the front bearing against
speed and preload, each uncoupled (no thermal effects) and thermally coupled.

The frames come solved from ``study_seed_b_spindle``: ``mech`` holds the
coupled steady state of every speed and preload with the uncoupled values
beside (``*_isothermal_*`` columns), ``scan`` the preload scan under the
working radial load. Nothing is solved here.
"""

from __future__ import annotations

from pathlib import Path
from typing import Any

from ..plot.labels import axis_label
from .output import save_figure
from .seed_b_figures import PRELOAD_COLOURS, finish, legend_outside, panels


def _by_preload(
    ax: Any, mech: Any, column: str, style: str, label: str, scale: float = 1.0
) -> None:
    """One line per preload of ``column`` against speed."""
    import polars as pl

    for p in sorted(set(mech["preload_n"].to_list())):
        d = mech.filter(pl.col("preload_n") == p).sort("speed_rpm")
        ax.plot(
            d["speed_rpm"].to_numpy(),
            d[column].to_numpy() * scale,
            linestyle=style,
            marker="o",
            markersize=3,
            color=PRELOAD_COLOURS.get(p),
            label=f"{label}{p:.0f} N",
        )


def radial_stiffness(mech: Any, out: Path) -> Path:
    """Fig. 12: radial stiffness k_xx of the front pair against speed for
    each preload, (a) uncoupled and (b) thermally coupled."""
    axes = panels(2)
    for ax, col, panel in (
        (axes[0], "k_xx_isothermal_n_per_m", "(a) uncoupled"),
        (axes[1], "k_xx_n_per_m", "(b) with thermal displacement"),
    ):
        _by_preload(ax, mech, col, "-", "", 1e-6)
        finish(ax, "speed_rpm", axis_label("k_xx_n_per_m", "N/µm"), panel)
    lo = min(a.get_ylim()[0] for a in axes)
    hi = max(a.get_ylim()[1] for a in axes)
    for a in axes:
        a.set_ylim(lo, hi)
    axes[0].figure.suptitle("Seed B Fig. 12: radial dynamic stiffness of the front pair")
    return save_figure(axes[0], out, "seed_b_fig12_radial_stiffness")


def contact_angles(mech: Any, out: Path, preload_n: float = 400.0) -> Path:
    """Fig. 13: (a) inner (solid) and outer (dashed) contact angles against
    speed for each preload, uncoupled; (b) at ``preload_n`` uncoupled
    against thermally coupled."""
    import polars as pl

    ax_a, ax_b = panels(2)
    _by_preload(ax_a, mech, "inner_contact_angle_isothermal_deg", "-", "inner, ")
    _by_preload(ax_a, mech, "outer_contact_angle_isothermal_deg", "--", "outer, ")
    d = mech.filter(pl.col("preload_n") == preload_n).sort("speed_rpm")
    s = d["speed_rpm"].to_numpy()
    for side, colour in (("inner", "C3"), ("outer", "C4")):
        ax_b.plot(
            s,
            d[f"{side}_contact_angle_isothermal_deg"].to_numpy(),
            "o--",
            color=colour,
            markersize=3,
            label=f"{side}, uncoupled",
        )
        ax_b.plot(
            s,
            d[f"{side}_contact_angle_deg"].to_numpy(),
            "o-",
            color=colour,
            markersize=3,
            label=f"{side}, with thermal displacement",
        )
    finish(ax_a, "speed_rpm", "contact angle [°]", "(a) uncoupled, by preload", legend=False)
    legend_outside(ax_a)
    finish(ax_b, "speed_rpm", "contact angle [°]", f"(b) {preload_n:.0f} N", legend=False)
    legend_outside(ax_b)
    ax_a.figure.suptitle("Seed B Fig. 13: contact angles of the front bearing")
    return save_figure(ax_a, out, "seed_b_fig13_contact_angles")


def contact_loads(mech: Any, out: Path, preload_n: float = 400.0) -> Path:
    """Fig. 14: largest contact loads of the front bearing against speed:
    (a) outer and inner by preload, uncoupled; (b) at ``preload_n`` uncoupled
    against coupled; (c) outer and (d) inner by preload, coupled (solid)
    against uncoupled (dashed)."""
    import polars as pl

    ax_a, ax_b, ax_c, ax_d = panels(4, ncols=2)
    _by_preload(ax_a, mech, "outer_load_max_isothermal_n", "-", "outer, ")
    _by_preload(ax_a, mech, "inner_load_max_isothermal_n", "--", "inner, ")
    d = mech.filter(pl.col("preload_n") == preload_n).sort("speed_rpm")
    s = d["speed_rpm"].to_numpy()
    for side, colour in (("outer", "C3"), ("inner", "C4")):
        ax_b.plot(
            s,
            d[f"{side}_load_max_isothermal_n"].to_numpy(),
            "o--",
            color=colour,
            markersize=3,
            label=f"{side}, uncoupled",
        )
        ax_b.plot(
            s,
            d[f"{side}_load_max_n"].to_numpy(),
            "o-",
            color=colour,
            markersize=3,
            label=f"{side}, with thermal displacement",
        )
    for ax, side in ((ax_c, "outer"), (ax_d, "inner")):
        _by_preload(ax, mech, f"{side}_load_max_n", "-", "coupled, ")
        _by_preload(ax, mech, f"{side}_load_max_isothermal_n", "--", "uncoupled, ")
    titles = (
        "(a) uncoupled, by preload",
        f"(b) {preload_n:.0f} N",
        "(c) outer ring",
        "(d) inner ring",
    )
    for ax, title in zip((ax_a, ax_b, ax_c, ax_d), titles, strict=True):
        finish(ax, "speed_rpm", "largest contact load [N]", title, legend=False)
        legend_outside(ax)
    ax_a.figure.suptitle("Seed B Fig. 14: contact loads of the front bearing")
    return save_figure(ax_a, out, "seed_b_fig14_contact_loads")


def radial_displacement(mech: Any, scan: Any, out: Path, speed_rpm: float = 12_000.0) -> Path:
    """Fig. 15: (a) radial thermal displacement of the front bearing against
    speed for each preload; (b) radial displacement under the working load
    without thermal displacement against preload at ``speed_rpm``."""
    import polars as pl

    ax_a, ax_b = panels(2)
    _by_preload(ax_a, mech, "thermal_radial_displacement_um", "-", "")
    finish(ax_a, "speed_rpm", "radial thermal displacement [µm]", "(a) by preload")
    d = scan.filter(pl.col("speed_rpm") == speed_rpm).sort("preload_n")
    ax_b.plot(
        d["preload_n"].to_numpy(),
        d["mechanical_radial_displacement_um"].to_numpy(),
        "o-",
        markersize=3,
        color="C3",
        label=f"{speed_rpm:,.0f} rpm, no thermal displacement",
    )
    finish(ax_b, "preload_n", "radial displacement [µm]", f"(b) {speed_rpm:,.0f} rpm")
    ax_a.figure.suptitle("Seed B Fig. 15: radial displacement of the front bearing")
    return save_figure(ax_a, out, "seed_b_fig15_radial_displacement")
