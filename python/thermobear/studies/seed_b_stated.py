"""Seed B's spindle as stated beside the spindle fitted to the paper's own
numbers: the front bearing's ball, inner- and outer-ring temperatures and
the axial growth against speed, at the stated 400 N preload, with the
paper's quoted values (Figs. 5 and 17).

"As stated" is the preset (``Spindle.preset("seed-ceramic-spindle")``:
every input the paper leaves out at its documented default); "fitted" is
``reproduce_seed_b.fitted_spindle()``."""

from __future__ import annotations

from pathlib import Path
from typing import Any

from .output import save_figure, write_table

#: Speeds of the comparison [rpm].
SPEEDS_RPM = (6_000.0, 12_000.0, 18_000.0)
#: The columns compared, with their labels.
COLUMNS = (
    ("front_ball_temperature_c", "ball"),
    ("front_inner_ring_temperature_c", "inner ring"),
    ("front_outer_ring_temperature_c", "outer ring"),
)


def stated_vs_fitted() -> Any:
    """One row per speed and version ("stated", "fitted"): the compared
    temperatures and the axial growth."""
    import polars as pl

    from ..spindle import Spindle
    from .reproduce_seed_b import fitted_spindle

    versions = {
        "stated": Spindle.preset("seed-ceramic-spindle"),
        "fitted": fitted_spindle().model()[0],
    }
    rows = []
    for name, sp in versions.items():
        for n in SPEEDS_RPM:
            s = sp.thermal_state(speed_rpm=n).row(0, named=True)
            rows.append({"version": name, "speed_rpm": n, "axial_growth_um": s["axial_growth_um"],
                         **{c: s[c] for c, _ in COLUMNS}})  # fmt: skip
    return pl.DataFrame(rows)


def study_stated_vs_fitted(out: Path) -> list[Path]:
    """The table and its figure: temperatures against speed, stated dashed,
    fitted solid, the paper's Fig. 5 values at 18,000 rpm as markers."""
    import matplotlib.pyplot as plt
    import polars as pl

    from ..plot.style import place_legend
    from .paper_numbers import quotes

    df = stated_vs_fitted()
    files = write_table(df, out, "seed_b_stated_vs_fitted")
    q = quotes("B").filter(pl.col("item") == "Fig. 5", pl.col("relation") == "value")
    _fig, ax = plt.subplots(figsize=(6.4, 4.2), layout="constrained")
    for k, (col, label) in enumerate(COLUMNS):
        for name, style in (("stated", "--"), ("fitted", "-")):
            sub = df.filter(pl.col("version") == name)
            ax.plot(sub["speed_rpm"], sub[col], style, color=f"C{k}", label=f"{label}, {name}")
        paper = q.filter(pl.col("quantity") == col)
        ax.plot(paper["speed_rpm"], paper["value"], "s", color=f"C{k}", label=f"{label}, seed B")
    ax.set_xlabel("speed [rpm]")
    ax.set_ylabel("front bearing temperature [°C]")
    ax.set_title("Seed B Fig. 5: spindle as stated and as fitted")
    place_legend(ax)
    files.append(save_figure(ax, out, "seed_b_stated_vs_fitted"))
    return files
