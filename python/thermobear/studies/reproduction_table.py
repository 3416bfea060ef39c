"""The reproduction table gathered from the seed rows
(``reproduction_seed_a``, ``reproduction_seed_b``): as a DataFrame, the
counts per seed, the summary line and the files ``thermobear demo``
writes."""

from __future__ import annotations

from dataclasses import fields
from pathlib import Path
from typing import Any

from .reproduction import Row
from .reproduction_seed_a import ROWS as ROWS_A
from .reproduction_seed_b import ROWS as ROWS_B


def all_rows() -> tuple[Row, ...]:
    """Seed A's rows, then seed B's."""
    return tuple(ROWS_A) + tuple(ROWS_B)


def table(rows: tuple[Row, ...] | None = None) -> Any:
    """The rows as a polars DataFrame, one column per field."""
    import polars as pl

    rows = all_rows() if rows is None else rows
    names = [f.name for f in fields(Row)]
    return pl.DataFrame(
        {n: [getattr(r, n) for r in rows] for n in names}, schema={n: pl.Utf8 for n in names}
    )


def counts(rows: tuple[Row, ...] | None = None) -> dict[str, tuple[int, int]]:
    """Per seed: (rows reproduced or explained, rows). A row is explained
    when it is not reproduced but carries its reason and its test."""
    rows = all_rows() if rows is None else rows
    out: dict[str, tuple[int, int]] = {}
    for seed in ("A", "B"):
        mine = [r for r in rows if r.seed == seed]
        ok = [r for r in mine if r.status == "reproduced" or (r.reason.strip() and r.test)]
        out[seed] = (len(ok), len(mine))
    return out


def summary(rows: tuple[Row, ...] | None = None) -> str:
    """``"seed A: N of M results reproduced or explained; seed B: ..."``."""
    c = counts(rows)
    return "; ".join(
        f"seed {s}: {n} of {m} results reproduced or explained" for s, (n, m) in c.items()
    )


def write_reproduction(out: Path) -> list[Path]:
    """Write ``reproduction.csv`` / ``.parquet`` into ``out``, print the
    summary line and return the files."""
    from .output import write_table

    files = write_table(table(), out, "reproduction")
    print(f"  reproduction: {summary()}", flush=True)
    return files
