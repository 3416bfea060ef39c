"""Seed B's thermal results drawn from thermobear's spindle model: the
convection coefficients against speed (Fig. 2, Table 1), the temperature
field (Fig. 3), transient and steady temperatures of the front and rear
bearings (Figs. 4-6), the radial and axial thermal displacement (Fig. 8) and
the outer-ring temperature against the measurement (Fig. 19).

Every function takes frames the seed B spindle study has already solved
(``study_seed_b_spindle``) and only draws and writes; only the convection
coefficients are computed here (a cheap evaluation of the network's laws).
"""

from __future__ import annotations

from pathlib import Path
from typing import Any

import numpy as np

from .output import save_figure, write_table
from .seed_b_figures import PARTS, finish, front_rear_lines, legend_outside, panels

#: Human names of the spindle network's convection links (seed B Fig. 2 and
#: Table 1 name the boundaries by the surfaces they join).
CONVECTION_LINKS: dict[str, str] = {
    "front_inner-oil": "front bearing - oil-air",
    "rear_inner-oil": "rear bearing - oil-air",
    "rotor-stator_gap": "rotor - stator air gap",
    "nose-air": "shaft end - air",
    "housing_front-air": "housing - air (natural)",
    "sleeve-water": "cooling jacket - water",
}


def convection(sp: Any, out: Path, speeds_rpm: Any) -> tuple[list[Path], Any]:
    """Fig. 2 (film coefficient against speed, one line per boundary) and
    Table 1 (the coefficients at 12,000 rpm). Natural convection at a 10 K
    difference."""
    import polars as pl

    h = sp.convection_coefficients(speeds_rpm, temperature_difference_k=10.0)
    h = h.filter(pl.col("link").is_in(list(CONVECTION_LINKS))).with_columns(
        pl.col("link").replace_strict(CONVECTION_LINKS).alias("boundary")
    )
    files = write_table(h, out, "seed_b_fig02_convection_coefficients")
    ax = panels(1)[0]
    for link, name in CONVECTION_LINKS.items():
        d = h.filter(pl.col("link") == link).sort("speed_rpm")
        style = "--" if link.startswith("rear") else "-"
        ax.plot(
            d["speed_rpm"].to_numpy(),
            d["film_coefficient_w_per_m2_k"].to_numpy(),
            linestyle=style,
            label=name,
        )
    ax.set_yscale("log")
    finish(
        ax,
        "speed_rpm",
        "film coefficient h [W/(m² K)]",
        "Seed B Fig. 2: convection coefficients against speed",
    )
    legend_outside(ax, 8)
    files.append(save_figure(ax, out, "seed_b_fig02_convection_coefficients"))
    at12 = h.filter(pl.col("speed_rpm") == 12_000.0).select(
        "boundary", "link", "film_coefficient_w_per_m2_k"
    )
    files += write_table(at12, out, "seed_b_table1_convection_12000rpm")
    return files, h


#: Node -> (axial start, axial end, inner radius, outer radius) as names of
#: the dimensions in ``_layout`` (the drawing's cross-section, mm).
def _layout(sp: Any) -> dict[str, tuple[float, float, float, float]]:
    """Where each node of the spindle network sits on a half cross-section
    (axial position from the front pair's centre towards the rear, radius from
    the axis) [mm], from the preset's dimensions. The stator outside diameter
    (140 mm) and the housing lengths (60 / 50 mm) are the preset's values
    that ``Spindle.assumptions`` does not list."""
    from ..bearing import Bearing

    a = sp.assumptions
    fb, rb = (Bearing.preset(a[k]).geometry for k in ("front_bearing", "rear_bearing"))
    zr = a["front_span_mm"]  # rotor centre
    zb = zr + a["rear_span_mm"]  # rear pair centre
    half_rotor, rr = 0.5 * a["rotor_length_mm"], 0.5 * a["rotor_diameter_mm"]
    rs, rst = 0.5 * a["sleeve_outer_diameter_mm"], 70.0

    def rings(g: dict, z: float) -> dict[str, tuple[float, float, float, float]]:
        w, d = g["width_mm"], g["pitch_diameter_mm"]
        ball = g["ball_diameter_mm"]
        return {
            "inner_ring": (z - w, z + w, 0.5 * g["bore_mm"], 0.5 * (d - ball)),
            "ball": (z - w, z + w, 0.5 * (d - ball), 0.5 * (d + ball)),
            "outer_ring": (z - w, z + w, 0.5 * (d + ball), 0.5 * g["outer_diameter_mm"]),
            "housing": (z - 30.0, z + 30.0, 0.5 * g["outer_diameter_mm"], rs),
        }

    lay = {f"front_{k}": v for k, v in rings(fb, 0.0).items()}
    lay.update({f"rear_{k}": v for k, v in rings(rb, zb).items()})
    lay["front_shaft"] = (-a["nose_length_mm"], zr - half_rotor, 0.0, 0.5 * fb["bore_mm"])
    lay["rear_shaft"] = (zr + half_rotor, zb + rb["width_mm"], 0.0, 0.5 * rb["bore_mm"])
    lay["rotor"] = (zr - half_rotor, zr + half_rotor, 0.0, rr)
    lay["stator"] = (zr - half_rotor, zr + half_rotor, rr + 0.3, rst)
    lay["sleeve"] = (30.0, zb - 30.0, rst, rs)
    return lay


def temperature_field(sp: Any, state: Any, out: Path, title: str) -> list[Path]:
    """Fig. 3 counterpart: each node of the thermal network drawn as the
    region of the half cross-section it lumps, coloured by its temperature
    (one temperature per region: a lumped network, not an FE field)."""
    import matplotlib as mpl
    import polars as pl
    from matplotlib.patches import Rectangle

    lay = _layout(sp)
    temps = {n: float(state[f"{n}_temperature_c"][0]) for n in lay}
    frame = pl.DataFrame(
        {
            "node": list(lay),
            "temperature_c": [temps[n] for n in lay],
            "axial_position_mm": [0.5 * (v[0] + v[1]) for v in lay.values()],
            "radial_position_mm": [0.5 * (v[2] + v[3]) for v in lay.values()],
        }
    )
    files = write_table(frame, out, "seed_b_fig03_temperature_field")
    ax = panels(1)[0]
    ax.figure.set_size_inches(8.0, 3.6)
    norm = mpl.colors.Normalize(min(temps.values()), max(temps.values()))
    cmap = mpl.colormaps["inferno"]
    for n, (z0, z1, r0, r1) in lay.items():
        ax.add_patch(
            Rectangle((z0, r0), z1 - z0, r1 - r0, facecolor=cmap(norm(temps[n])), edgecolor="k")
        )
        if r1 - r0 > 6.0 or n.endswith("ball"):
            light = norm(temps[n]) < 0.55
            ax.text(
                0.5 * (z0 + z1),
                0.5 * (r0 + r1),
                f"{temps[n]:.1f}",
                ha="center",
                va="center",
                fontsize=6,
                color="w" if light else "k",
            )
    ax.set_xlim(min(v[0] for v in lay.values()) - 5, max(v[1] for v in lay.values()) + 5)
    ax.set_ylim(0.0, max(v[3] for v in lay.values()) + 5)
    ax.set_aspect("equal")
    ax.figure.colorbar(mpl.cm.ScalarMappable(norm=norm, cmap=cmap), ax=ax, label="temperature [°C]")
    finish(ax, "axial position from the front pair [mm]", "radius [mm]", title, legend=False)
    files.append(save_figure(ax, out, "seed_b_fig03_temperature_field"))
    return files


def transient_front_rear(tr: Any, out: Path, title: str) -> Path:
    """Fig. 4: ball, inner- and outer-ring temperatures of the front (solid)
    and rear (dashed) bearings against time."""
    ax = panels(1)[0]
    t = tr.with_columns((tr["time_s"] / 60.0).alias("time_min"))
    cols = [(f"{stem}_temperature_c", name) for stem, name in PARTS]
    front_rear_lines(ax, t, "time_min", cols, marker="")
    finish(ax, "time [min]", "temperature [°C]", title)
    return save_figure(ax, out, "seed_b_fig04_transient")


def steady_front_rear(vs_speed: Any, out: Path, title: str) -> Path:
    """Fig. 5: steady temperatures of the front and rear bearings' parts
    against speed."""
    ax = panels(1)[0]
    cols = [(f"{stem}_temperature_c", name) for stem, name in PARTS]
    front_rear_lines(ax, vs_speed.sort("speed_rpm"), "speed_rpm", cols)
    finish(ax, "speed_rpm", "temperature [°C]", title)
    return save_figure(ax, out, "seed_b_fig05_temperatures_vs_speed")


def ball_vs_preload(mech: Any, out: Path) -> Path:
    """Fig. 6: front and rear ball temperature against preload, one colour
    per speed."""
    import polars as pl

    ax = panels(1)[0]
    for i, n in enumerate(sorted(set(mech["speed_rpm"].to_list()))):
        d = mech.filter(pl.col("speed_rpm") == n).sort("preload_n")
        for side, style in (("front", "-"), ("rear", "--")):
            ax.plot(
                d["preload_n"].to_numpy(),
                d[f"{side}_ball_temperature_c"].to_numpy(),
                linestyle=style,
                marker="o",
                markersize=3,
                color=f"C{i}",
                label=f"{side}, {n:,.0f} rpm",
            )
    finish(
        ax,
        "preload_n",
        "ball temperature [°C]",
        "Seed B Fig. 6: ball temperature against preload",
    )
    legend_outside(ax)
    return save_figure(ax, out, "seed_b_fig06_ball_temperature_vs_preload")


def thermal_displacement(disp: Any, out: Path) -> Path:
    """Fig. 8a/b: radial and axial thermal displacement of the front (solid)
    and rear (dashed) bearings against speed, Si3N4 against steel balls."""
    import polars as pl

    axes = panels(2)
    for ax, panel, cols, ylabel in (
        (
            axes[0],
            "a",
            ("thermal_radial_displacement_um", "rear_thermal_radial_displacement_um"),
            "radial thermal displacement [µm]",
        ),
        (
            axes[1],
            "b",
            ("front_axial_thermal_displacement_um", "rear_axial_thermal_displacement_um"),
            "axial groove-centre offset [µm]",
        ),
    ):
        for i, balls in enumerate(("Si3N4", "steel")):
            d = disp.filter(pl.col("balls") == balls).sort("speed_rpm")
            for col, (side, style) in zip(cols, (("front", "-"), ("rear", "--")), strict=True):
                ax.plot(
                    d["speed_rpm"].to_numpy(),
                    d[col].to_numpy(),
                    linestyle=style,
                    marker="o",
                    markersize=3,
                    color=f"C{i}",
                    label=f"{side}, {balls} balls",
                )
        ax.axhline(0.0, color="0.5", linewidth=0.8)
        finish(ax, "speed_rpm", ylabel, f"({panel})", legend=panel == "a")
    axes[0].figure.suptitle("Seed B Fig. 8: thermal displacement of the front and rear bearings")
    return save_figure(axes[0], out, "seed_b_fig08_thermal_displacement")


def outer_ring_vs_measurement(tr: Any, vs_speed: Any, measured: Any, out: Path) -> list[Path]:
    """Fig. 19a/b: simulated outer-ring temperatures of the front and rear
    bearings against time at 12,000 rpm and against speed, with the measured
    values seed B quotes (20-min maxima at 12,000 rpm, 0.5 K sensor sigma)."""
    import polars as pl

    files: list[Path] = []
    ax_a, ax_b = panels(2)
    t = tr.with_columns((tr["time_s"] / 60.0).alias("time_min"))
    col = [("outer_ring_temperature_c", "outer ring, simulated")]
    front_rear_lines(ax_a, t, "time_min", col, marker="")
    front_rear_lines(ax_b, vs_speed.sort("speed_rpm"), "speed_rpm", col)
    for i, side in enumerate(("front", "rear")):
        m = measured.filter(pl.col("quantity") == f"{side}_outer_ring_temperature_c")
        for ax, x in ((ax_a, np.full(m.height, 20.0)), (ax_b, m["speed_rpm"].to_numpy())):
            ax.errorbar(
                x,
                m["value"].to_numpy(),
                yerr=m["sigma"].to_numpy(),
                fmt="s",
                color="C0",
                mfc="w" if i else "C0",
                label=f"{side}, measured",
            )
    finish(ax_a, "time [min]", "outer-ring temperature [°C]", "Fig. 19a: 12,000 rpm")
    finish(ax_b, "speed_rpm", "outer-ring temperature [°C]", "Fig. 19b: against speed")
    ax_a.figure.suptitle("Seed B Fig. 19: outer-ring temperature, simulation and experiment")
    files.append(save_figure(ax_a, out, "seed_b_fig19_outer_ring_vs_measurement"))
    return files
