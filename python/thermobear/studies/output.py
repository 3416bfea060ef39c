"""Where the studies write: tables as parquet + CSV, figures as PNG."""

from __future__ import annotations

from pathlib import Path
from typing import Any


def write_table(df: Any, out: Path, stem: str) -> list[Path]:
    """Write a polars DataFrame as parquet and CSV."""
    out.mkdir(parents=True, exist_ok=True)
    pq, csv = out / f"{stem}.parquet", out / f"{stem}.csv"
    df.write_parquet(pq)
    df.write_csv(csv)
    return [pq, csv]


def save_figure(ax: Any, out: Path, stem: str) -> Path:
    import matplotlib.pyplot as plt

    out.mkdir(parents=True, exist_ok=True)
    fig = ax.figure
    fig.tight_layout()
    path = out / f"{stem}.png"
    fig.savefig(path, dpi=120)
    plt.close(fig)
    return path
