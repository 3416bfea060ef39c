"""MkDocs hook: the reproduction page's tables, generated from the same
functions ``thermobear demo`` writes ``reproduction.csv`` with, so the page
cannot drift from them.

``docs/reproduction.md`` holds the markers ``<!-- reproduction-counts -->``
(the counts line), ``<!-- reproduction-table -->`` (one row per seed figure
or table, its status following from its numbers),
``<!-- reproduction-numbers -->`` (one row per quoted number) and
``<!-- reproduction-claims -->`` (one row per claim in words). The number
table is the demo's own ``reproduction.parquet`` when the folder named by
``THERMOBEAR_DEMO_OUT`` has it (the gallery's demo run), else it is
computed. Figures link to the PNGs the gallery hook (``gallery.py``, listed
before this hook) adds to the site under ``gallery/img/``.
"""

from __future__ import annotations

import math
import os
from pathlib import Path

TABLE_MARKER = "<!-- reproduction-table -->"
COUNTS_MARKER = "<!-- reproduction-counts -->"
NUMBERS_MARKER = "<!-- reproduction-numbers -->"
CLAIMS_MARKER = "<!-- reproduction-claims -->"

_TABLE = None


def _cell(text) -> str:
    return " ".join(str(text).split()).replace("|", "\\|")


def _figure_cell(row) -> str:
    stem = row["figure"].rsplit("/", 1)[-1]
    if row["item"].lower().startswith("table"):
        return f"table `{stem}` (CSV, parquet)"
    uri = f"gallery/img/{row['figure']}.png"
    return f'[![{row["seed"]} {row["item"]}]({uri}){{ width="200" }}]({uri})<br>`{stem}`'


def _number(x) -> str:
    """A number as a reader takes it: thousands with separators, large and
    tiny ones in powers of ten, the rest to four significant digits."""
    if x is None or (isinstance(x, float) and not math.isfinite(x)):
        return "-"
    if abs(x) >= 1e6 or (0.0 < abs(x) < 1e-3):
        return f"{x:.3e}"
    if abs(x) >= 1000.0:
        return f"{x:,.0f}"
    return f"{x:.4g}"


def table_markdown(items) -> str:
    """The per-figure table in Markdown, one line per figure or table."""
    lines = [
        "| seed | item | paper | thermobear | numbers within | status | quoted | ours | reason | "
        "test |",
        "| --- | --- | --- | --- | --- | --- | --- | --- | --- | --- |",
    ]
    for r in items.iter_rows(named=True):
        within = (
            f"{r['within']} of {r['numbers']}"
            if r["numbers"]
            else (f"claims {r['claims_within']} of {r['claims']}" if r["claims"] else "-")
        )
        cells = [
            r["seed"], r["item"], _cell(r["paper"]), _figure_cell(r), within,
            f"**{r['status']}**", _cell(r["quoted"]), _cell(r["ours"]),
            _cell(r["reason"]) or "-", f"`{r['test']}`",
        ]  # fmt: skip
        lines.append("| " + " | ".join(cells) + " |")
    return "\n".join(lines)


def numbers_markdown(table, kind: str = "number") -> str:
    """One line per quoted number (or claim): the paper's value and how it
    was read, ours with its band, the error, the tolerance, the role."""
    import polars as pl

    t = table.filter(pl.col("kind") == kind)
    head = "number" if kind == "number" else "claim"
    lines = [
        f"| seed | item | {head} | quantity | condition | paper | read (precision) | ours | "
        "95 % band | error | tolerance | within | role | note |",
        "| --- | --- | --- | --- | --- | --- | --- | --- | --- | --- | --- | --- | --- | --- |",
    ]
    for r in t.iter_rows(named=True):
        cmp = "" if r["comparison"] == "=" else f"{r['comparison']} "
        band = (
            f"{_number(r['lower_95'])} .. {_number(r['upper_95'])}"
            if r["lower_95"] is not None and math.isfinite(r["lower_95"])
            else "-"
        )
        within = "-" if r["within"] is None else ("yes" if r["within"] else "**no**")
        if r["covered"] is not None and r["role"] == "checked":
            band += " (holds it)" if r["covered"] else " (misses it)"
        cells = [
            r["seed"], r["item"], f"`{r['id']}`", f"`{r['quantity']}`", _cell(r["condition"]),
            f"{cmp}{_number(r['paper_value'])} {r['unit']}", f"{r['read']} ({r['precision']:g})",
            _number(r["ours"]), band, _number(r["error"]), _cell(r["tolerance"]), within,
            r["role"], _cell(r["note"]),
        ]  # fmt: skip
        lines.append("| " + " | ".join(cells) + " |")
    return "\n".join(lines)


def _table():
    """The number table: the demo's, else computed (full grids)."""
    global _TABLE
    if _TABLE is None:
        import polars as pl

        env = os.environ.get("THERMOBEAR_DEMO_OUT")
        path = Path(env) / "reproduction.parquet" if env else None
        if path is not None and path.is_file():
            _TABLE = pl.read_parquet(path)
        else:
            from thermobear.studies.reproduction_table import numbers

            _TABLE = numbers()
    return _TABLE


def on_page_markdown(markdown, page, config, files):
    if page.file.src_uri != "reproduction.md":
        return markdown
    from thermobear.studies.reproduction_table import items, summary

    t = _table()
    return (
        markdown.replace(TABLE_MARKER, table_markdown(items(t)))
        .replace(COUNTS_MARKER, summary(t) + ".")
        .replace(NUMBERS_MARKER, numbers_markdown(t, "number"))
        .replace(CLAIMS_MARKER, numbers_markdown(t, "claim"))
    )
