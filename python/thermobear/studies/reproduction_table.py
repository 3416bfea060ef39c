"""The reproduction table, number by number: every number the seed papers
quote (``paper_numbers.quotes``) beside ours, with its error, tolerance,
role (fitted or checked) and band; every claim they state in words the
same way; and per figure or table (the rows of ``reproduction_seed_a`` and
``reproduction_seed_b``: what the paper shows, thermobear's counterpart,
the reason wherever it differs) a status that follows from its numbers.

``thermobear demo`` writes ``reproduction.csv`` / ``.parquet`` (the
numbers and claims) and ``reproduction_items.csv`` / ``.parquet`` (per
figure), and prints the counts; the documentation's reproduction page is
generated from the same functions."""

from __future__ import annotations

import re
from dataclasses import fields
from pathlib import Path
from typing import Any, Optional

from .paper_numbers import (
    SEEDS,
    condition_text,
    counts,
    evaluate,
    item_status,
    number_table,
    quotes,
)
from .paper_numbers import summary as number_summary
from .reproduction import Row
from .reproduction_seed_a import ROWS as ROWS_A
from .reproduction_seed_b import ROWS as ROWS_B

#: The columns of ``reproduction.csv``, in order.
NUMBER_COLUMNS = (
    "seed", "item", "id", "kind", "quantity", "condition", "paper_value", "unit",
    "comparison", "read", "precision", "ours", "error", "tolerance", "within", "role",
    "lower_95", "upper_95", "covered", "basis", "note",
)  # fmt: skip


def all_rows() -> tuple[Row, ...]:
    """Seed A's per-figure rows, then seed B's."""
    return tuple(ROWS_A) + tuple(ROWS_B)


def figure_of(item: str) -> str:
    """The figure or table a number's item belongs to: ``"Fig. 14a"`` ->
    ``"Fig. 14"``; the conclusions stay themselves."""
    m = re.match(r"(Fig\.|Table) \d+", item)
    return m.group(0) if m else item


def numbers(quick: bool = False, seeds: tuple[str, ...] = SEEDS) -> Any:
    """The number table of ``seeds`` (numbers and claims), one row each,
    with ours: the columns of ``NUMBER_COLUMNS``."""
    import polars as pl

    frames = []
    for s in seeds:
        q = quotes(s, kind=None)
        t = number_table(q, evaluate(s, quick, q))
        frames.append(t)
    t = pl.concat(frames, how="diagonal_relaxed")
    cond = [condition_text(r) for r in t.iter_rows(named=True)]
    # a value ours does not have (not comparable, no band) is null, never NaN
    return t.with_columns(
        pl.Series("condition", cond, dtype=pl.Utf8),
        pl.col("value").alias("paper_value"),
        pl.col("lower").fill_nan(None).alias("lower_95"),
        pl.col("upper").fill_nan(None).alias("upper_95"),
        pl.col("ours").fill_nan(None),
        pl.col("error").fill_nan(None),
    ).select(NUMBER_COLUMNS)


def items(table: Any) -> Any:
    """Per figure or table: the row's texts with ``numbers``, ``claims``,
    ``within`` (numbers within tolerance), ``claims_within`` and
    ``status``: from the numbers where the item quotes any (see
    ``paper_numbers.item_status``), else from its claims, else the row's
    own (a parameter table)."""
    import polars as pl

    t = table.with_columns(
        pl.col("item").map_elements(figure_of, return_dtype=pl.Utf8).alias("figure_item")
    )
    nums = item_status(t.filter(pl.col("kind") == "number").drop("item").rename(
        {"figure_item": "item"}))  # fmt: skip
    clm = item_status(t.filter(pl.col("kind") == "claim").drop("item").rename(
        {"figure_item": "item"}))  # fmt: skip
    by_n = {(r["seed"], r["item"]): r for r in nums.iter_rows(named=True)}
    by_c = {(r["seed"], r["item"]): r for r in clm.iter_rows(named=True)}
    out = []
    for row in all_rows():
        key = (row.seed, figure_of(row.item))
        n, c = by_n.get(key), by_c.get(key)
        status = (n or c or {}).get("status") or row.status
        if n is not None and n["status"] == "not comparable" and c is not None:
            status = c["status"]
        d = {f.name: getattr(row, f.name) for f in fields(Row)}
        d.update(
            status=status,
            numbers=0 if n is None else int(n["numbers"]),
            within=0 if n is None else int(n["within_tolerance"]),
            claims=0 if c is None else int(c["numbers"]),
            claims_within=0 if c is None else int(c["within_tolerance"]),
        )
        out.append(d)
    return pl.DataFrame(out)


def summary(table: Any) -> str:
    """The counts line: per seed, numbers within tolerance of all
    comparable numbers, fitted and checked apart, checked ones inside their
    band, and the claims."""
    parts = []
    for s in SEEDS:
        line = number_summary(table, (s,))
        c = counts(table, s, "claim")
        if c["all"][1]:
            line += f"; claims {c['all'][0]} of {c['all'][1]}"
        parts.append(line)
    return "; ".join(parts)


def write_reproduction(out: Path, quick: bool = False, table: Optional[Any] = None) -> list[Path]:
    """Write ``reproduction.csv``/``.parquet`` (numbers and claims) and
    ``reproduction_items.csv``/``.parquet`` (per figure) into ``out``,
    print the counts and return the files."""
    from .output import write_table

    t = numbers(quick) if table is None else table
    files = write_table(t, out, "reproduction")
    files += write_table(items(t), out, "reproduction_items")
    print(f"  reproduction: {summary(t)}", flush=True)
    return files
