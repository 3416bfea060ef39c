"""MkDocs hook: the reproduction page's table, generated from the rows in
``thermobear.studies.reproduction`` so the page cannot drift from them.

``docs/reproduction.md`` holds the marker ``<!-- reproduction-table -->``
(and ``<!-- reproduction-counts -->``); this hook replaces them with one
table row per seed figure or table and the counts. Figures link to the PNGs
the gallery hook (``gallery.py``, listed before this hook) adds to the site
under ``gallery/img/``.
"""

from __future__ import annotations

TABLE_MARKER = "<!-- reproduction-table -->"
COUNTS_MARKER = "<!-- reproduction-counts -->"


def _cell(text: str) -> str:
    return " ".join(text.split()).replace("|", "\\|")


def _figure_cell(row) -> str:
    stem = row.figure.rsplit("/", 1)[-1]
    if row.item.lower().startswith("table"):
        return f"table `{stem}` (CSV, parquet)"
    uri = f"gallery/img/{row.figure}.png"
    return f'[![{row.seed} {row.item}]({uri}){{ width="200" }}]({uri})<br>`{stem}`'


def table_markdown(rows) -> str:
    """The reproduction table in Markdown, one line per row."""
    lines = [
        "| seed | item | paper | thermobear | quoted | ours | status | reason | test |",
        "| --- | --- | --- | --- | --- | --- | --- | --- | --- |",
    ]
    for r in rows:
        cells = [
            r.seed,
            r.item,
            _cell(r.paper),
            _figure_cell(r),
            _cell(r.quoted),
            _cell(r.ours),
            f"**{r.status}**",
            _cell(r.reason) or "-",
            f"`{r.test}`",
        ]
        lines.append("| " + " | ".join(cells) + " |")
    return "\n".join(lines)


def on_page_markdown(markdown, page, config, files):
    if page.file.src_uri != "reproduction.md":
        return markdown
    from thermobear.studies.reproduction_table import all_rows, summary

    rows = all_rows()
    return markdown.replace(TABLE_MARKER, table_markdown(rows)).replace(
        COUNTS_MARKER, summary(rows) + "."
    )
