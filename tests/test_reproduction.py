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
from thermobear.studies.paper_numbers import counts, quotes
from thermobear.studies.reproduction import STATUSES, Row
from thermobear.studies.reproduction_table import (
    NUMBER_COLUMNS,
    all_rows,
    figure_of,
    items,
    numbers,
    summary,
)

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


@pytest.fixture(scope="module")
def number_table():
    """The full reproduction table, numbers and claims (as the demo and
    the docs page build it)."""
    return numbers()


def test_table_and_summary(tmp_path, capsys, number_table):
    from thermobear.studies.reproduction_table import write_reproduction

    files = write_reproduction(tmp_path, table=number_table)
    assert {f.name for f in files} == {
        "reproduction.csv", "reproduction.parquet", "reproduction_items.csv",
        "reproduction_items.parquet",
    }  # fmt: skip
    df = pl.read_parquet(tmp_path / "reproduction.parquet")
    assert df.equals(number_table)
    assert tuple(df.columns) == NUMBER_COLUMNS
    # one row per quoted number and per claim, each evaluated
    q = quotes(kind=None)
    assert df.height == q.height and set(df["id"]) == set(q["id"])
    assert summary(number_table) in capsys.readouterr().out
    per_item = pl.read_parquet(tmp_path / "reproduction_items.parquet")
    assert per_item.height == len(all_rows())


def test_a_figures_status_follows_from_its_numbers(number_table):
    it = items(number_table)
    for r in it.iter_rows(named=True):
        if r["numbers"]:
            sub = number_table.filter(
                (pl.col("seed") == r["seed"]) & (pl.col("kind") == "number")
                & pl.col("item").map_elements(figure_of, return_dtype=pl.Utf8).eq(r["item"])
            )  # fmt: skip
            comparable = sub.filter(pl.col("within").is_not_null())
            n_in = int(comparable["within"].sum())
            assert r["within"] == n_in
            if comparable.height and n_in == comparable.height:
                assert r["status"] == "reproduced", r["item"]
            elif n_in == 0 and comparable.height:
                assert r["status"] == "differs", r["item"]


def test_what_the_reproduction_reaches(number_table):
    """Seed A: at least 80 % of its numbers within tolerance, fitted and
    held out alike, and at least half of the held-out ones inside their
    95 % band. Seed B reaches 36 of 63 (the goal of 80 % is not met; the
    page gives each miss its evidence): this pins it against regressions.
    Every quoted number is evaluated (ours or "not comparable")."""
    a = counts(number_table, "A")
    assert a["all"][0] >= 0.8 * a["all"][1] and a["checked"][0] >= 0.8 * a["checked"][1], a
    assert a["checked in band"][0] >= 0.5 * a["checked in band"][1], a
    b = counts(number_table, "B")
    assert b["all"][0] >= 36 and b["all"][1] + b["not comparable"][1] == 67, b
    assert number_table["ours"].is_nan().sum() == 0  # no NaN placeholder: null


def test_readme_gives_the_counts_of_the_table(number_table):
    text = " ".join((ROOT / "README.md").read_text().split())
    for seed in ("A", "B"):
        c = counts(number_table, seed)
        n, m = c["all"]
        want = f"seed {seed}: {n} of {m} numbers within tolerance"
        assert want in text, want


def test_docs_page_is_generated_from_the_table(number_table):
    import importlib.util

    page = " ".join((ROOT / "docs" / "reproduction.md").read_text().split())
    for marker in ("table", "counts", "numbers", "claims"):
        assert f"<!-- reproduction-{marker} -->" in page, marker
    nav = (ROOT / "mkdocs.yml").read_text()
    assert "reproduction.md" in nav and "docs/hooks/reproduction.py" in nav
    spec = importlib.util.spec_from_file_location("hook", ROOT / "docs/hooks/reproduction.py")
    assert spec and spec.loader
    hook = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(hook)
    md = hook.table_markdown(items(number_table))
    assert md.count("\n") == len(all_rows()) + 1
    for r in all_rows():
        assert f"| {r.seed} | {r.item} |" in md and r.test in md
    nums = hook.numbers_markdown(number_table, "number")
    claims = hook.numbers_markdown(number_table, "claim")
    kinds = number_table["kind"].to_list()
    assert nums.count("\n") == kinds.count("number") + 1
    assert claims.count("\n") == kinds.count("claim") + 1
    for i in number_table["id"]:
        assert f"`{i}`" in nums + claims


def test_the_reproduction_page_code_runs_as_written(tmp_path, monkeypatch):
    monkeypatch.chdir(tmp_path)
    text = (ROOT / "docs" / "reproduction.md").read_text()
    blocks = re.findall(r"```python\n(.*?)```", text, re.S)
    assert blocks
    namespace: dict = {}
    for code in blocks:
        exec(compile(code, "reproduction.md", "exec"), namespace)
    assert namespace["thermal"].stiffness_case == "thermal"
    assert namespace["thermal"].params["te_amplitude_um"] == pytest.approx(
        float(namespace["model"].values[0])
    )
