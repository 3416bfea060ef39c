"""The reproduction table: one row per result figure and table of both seed
studies, each with a counterpart the demo writes, a status, a reason where
it differs and an existing test; the docs page and the README agree with it."""

from __future__ import annotations

import ast
import re
from pathlib import Path

import polars as pl
import pytest

from thermobear.errors import ConfigError
from thermobear.studies.demo import STUDIES, study_function
from thermobear.studies.reproduction import STATUSES, Row
from thermobear.studies.reproduction_table import all_rows, counts, summary, table

ROOT = Path(__file__).resolve().parents[1]

#: Seed A (Liu, Liu & Hu, Sensors 2021, 21, 309): the result figures 6, 8,
#: 10, 11, 13, 14, 15 and the parameter tables 1-3 the model uses; Figs.
#: 1-5, 7, 9, 12 are drawings.
SEED_A = {"Fig. 6", "Fig. 8", "Fig. 10", "Fig. 11", "Fig. 13", "Fig. 14", "Fig. 15"} | {
    "Table 1",
    "Table 2",
    "Table 3",
}
#: Seed B: result figures 2-6, 8, 12-17, 19-21 and its tables with results
#: or parameters the model reproduces.
SEED_B_FIGURES = {f"Fig. {n}" for n in (2, 3, 4, 5, 6, 8, 12, 13, 14, 15, 16, 17, 19, 20, 21)}


def _number(item: str) -> str:
    """``"Fig. 12 (400 N)"`` -> ``"Fig. 12"``: a row may split a figure."""
    m = re.match(r"(Fig\.|Table) \d+", item)
    assert m, item
    return m.group(0)


def test_one_row_per_result_figure_and_table_of_both_seeds():
    rows = all_rows()
    a = {_number(r.item) for r in rows if r.seed == "A"}
    b = {_number(r.item) for r in rows if r.seed == "B"}
    assert a == SEED_A
    assert b >= SEED_B_FIGURES and b - SEED_B_FIGURES <= {f"Table {n}" for n in range(1, 6)}
    keys = [(r.seed, r.item) for r in rows]
    assert len(keys) == len(set(keys))  # no item twice


def test_every_row_has_a_status_and_a_reason_when_not_reproduced():
    for r in all_rows():
        assert r.status in STATUSES, r
        if r.status != "reproduced":
            assert len(r.reason.split()) >= 8, (r.seed, r.item)
        assert r.quoted.strip() and r.ours.strip() and r.paper.strip()
    with pytest.raises(ConfigError, match="reason"):
        Row("A", "Fig. 6", "p", "s/f", "q", "o", "differs", "", "t::x")
    with pytest.raises(ConfigError, match="status"):
        Row("A", "Fig. 6", "p", "s/f", "q", "o", "roughly", "r", "t::x")  # type: ignore[arg-type]


def _test_names(path: Path) -> set[str]:
    tree = ast.parse(path.read_text())
    return {n.name for n in ast.walk(tree) if isinstance(n, ast.FunctionDef)}


def test_every_rows_test_node_exists():
    for r in all_rows():
        file, _, name = r.test.partition("::")
        path = ROOT / file
        assert path.is_file(), (r.item, r.test)
        assert name.split("[")[0] in _test_names(path), (r.item, r.test)


@pytest.fixture(scope="module")
def demo_files(tmp_path_factory) -> set[str]:
    """Every file the quick demo studies named by the rows write, as
    ``"<study>/<name>"``."""
    out = tmp_path_factory.mktemp("demo")
    studies = dict(STUDIES)
    needed = sorted({r.figure.split("/")[0] for r in all_rows()})
    for name in needed:
        assert name in studies, name
        study_function(studies[name])(out / name, True)
    return {str(p.relative_to(out)) for p in out.rglob("*") if p.is_file()}


def test_every_row_has_its_figure_or_table_in_the_demo_output(demo_files):
    missing = []
    for r in all_rows():
        kind = ("csv", "parquet") if r.item.startswith("Table") else ("png",)
        if not all(f"{r.figure}.{ext}" in demo_files for ext in kind):
            missing.append((r.seed, r.item, r.figure))
    assert missing == []
    # Each new seed A counterpart names its seed figure in its file name.
    for r in all_rows():
        if r.seed == "A" and r.item.startswith("Fig."):
            num = _number(r.item).split()[1]
            assert f"seed_a_fig{num}" in r.figure, r.figure


def test_table_and_summary(tmp_path, capsys):
    from thermobear.studies.reproduction_table import write_reproduction

    files = write_reproduction(tmp_path)
    assert {f.name for f in files} == {"reproduction.csv", "reproduction.parquet"}
    df = pl.read_parquet(tmp_path / "reproduction.parquet")
    assert df.equals(table()) and df.height == len(all_rows())
    assert summary() in capsys.readouterr().out
    n, m = counts()["A"]
    assert summary().startswith(f"seed A: {n} of {m} results reproduced or explained")


def test_readme_gives_the_counts_of_the_rows():
    text = " ".join((ROOT / "README.md").read_text().split())
    found = re.findall(r"seed ([AB]): (\d+) of (\d+) results reproduced or explained", text)
    assert {s: (int(n), int(m)) for s, n, m in found} == counts()


def test_docs_page_is_generated_from_the_rows():
    import importlib.util

    page = " ".join((ROOT / "docs" / "reproduction.md").read_text().split())
    assert "<!-- reproduction-table -->" in page and "<!-- reproduction-counts -->" in page
    nav = (ROOT / "mkdocs.yml").read_text()
    assert "reproduction.md" in nav and "docs/hooks/reproduction.py" in nav
    spec = importlib.util.spec_from_file_location("hook", ROOT / "docs/hooks/reproduction.py")
    assert spec and spec.loader
    hook = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(hook)
    md = hook.table_markdown(all_rows())
    assert md.count("\n") == len(all_rows()) + 1
    for r in all_rows():
        assert f"| {r.seed} | {r.item} |" in md and r.test in md
    # The period-1 section quotes the evidence pinned by the Fig. 14 row's test.
    fig14 = next(r for r in all_rows() if r.seed == "A" and r.item == "Fig. 14")
    for number in ("4748 N", "5.3 µm", "1.5 µm", "3.8 µm", "25 N m", "30 N m", "6.8 %"):
        assert number in fig14.ours + " " + fig14.reason, number
        assert number in page, number
