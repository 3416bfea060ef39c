"""The package's types are usable by a type checker.

One mypy run (configured in pyproject.toml: strict on the public API) checks
the package, ``examples/`` and every ```python block of the README and the
docs, plus a contract module below whose marked lines must fail: a misspelt
choice, a result used as the wrong type. stubtest checks the extension's
``_native.pyi`` against the compiled module.

The blocks of one Markdown file build on each other, as a reader runs them
(``tests/test_readme.py`` runs the README's in one namespace), so each file
becomes one module: its code blocks at their own line numbers, every other
line blank, so that an error names the Markdown file's line. A block that is
deliberately a fragment is left out by the comment
``<!-- typecheck: skip -->`` on the line before its fence.
"""

from __future__ import annotations

import re
import subprocess
import sys
import textwrap
from collections import defaultdict
from pathlib import Path

import pytest

pytest.importorskip("mypy")

ROOT = Path(__file__).resolve().parents[1]
SKIP_MARK = "<!-- typecheck: skip -->"
_FENCE = re.compile(r"^(\s*)```python\s*$")

#: Each line ending in ``# must fail`` must draw a checker error; the other
#: lines must pass. ``tb.bifurcation(..., direction="dwon")`` ran unnoticed
#: until the sweep reached the native code.
CONTRACT = """\
from __future__ import annotations

import matplotlib.axes
import numpy as np
import polars as pl

import thermobear as tb

b = tb.Bearing.preset("7008C")
speeds = np.linspace(6000.0, 12000.0, 4)  # numpy arrays are accepted where arrays are
curve: pl.DataFrame = tb.stiffness_curve(b, speeds, 500.0, 0.0)
ax: matplotlib.axes.Axes = tb.plot.stiffness_curve(curve)
tb.stiffness_curve(b, [6000.0, 9000.0], 500.0, 0.0, mode="thermal")
g = tb.GearPair.preset("seed-electric-drive")
gs = tb.GearSystem(g, stiffness="speed")
pts = tb.bifurcation(gs, speeds_rpm=range(6500, 6601, 50), direction="down")
tb.bifurcation(gs, speeds_rpm=range(6500, 6601, 50), direction="dwon")  # must fail
tb.stiffness_curve(b, speeds, 500.0, 0.0, mode="thermall")  # must fail
tb.GearSystem(g, stiffness="sped")  # must fail
tb.thermal_state(b, 6000.0, 500.0, 0.0, heat_model="skff")  # must fail
wrong: int = tb.stiffness_curve(b, speeds, 500.0, 0.0)  # must fail
not_axes: pl.DataFrame = tb.plot.stiffness_curve(curve)  # must fail
"""


def markdown_module(text: str) -> str | None:
    """The ```python blocks of a Markdown text as one module, each block at
    its own lines (dedented), every other line blank; None without blocks."""
    lines = text.split("\n")
    out = [""] * len(lines)
    found = False
    i = 0
    while i < len(lines):
        m = _FENCE.match(lines[i])
        if not m:
            i += 1
            continue
        j = i + 1
        while j < len(lines) and not lines[j].strip().startswith("```"):
            j += 1
        before = next((x.strip() for x in reversed(lines[:i]) if x.strip()), "")
        if before != SKIP_MARK:
            block = textwrap.dedent("\n".join(lines[i + 1 : j])).split("\n")
            out[i + 1 : j] = block
            found = True
        i = j + 1
    return "\n".join(out) + "\n" if found else None


def _markdown_files() -> list[Path]:
    return [ROOT / "README.md", *sorted((ROOT / "docs").rglob("*.md"))]


def _module_name(md: Path) -> str:
    rel = md.relative_to(ROOT).with_suffix("")
    return "md_" + re.sub(r"\W", "_", str(rel))


def _write_if_changed(path: Path, text: str) -> None:
    if not path.exists() or path.read_text() != text:
        path.write_text(text)


@pytest.fixture(scope="module")
def mypy_run(tmp_path_factory: pytest.TempPathFactory, request: pytest.FixtureRequest):
    """One mypy run over everything; the errors grouped by file.

    The generated modules keep one path from run to run (beside mypy's
    cache): mypy replays the errors of a module whose text it has seen
    under the path it saw it at, so a module written to a new temporary
    folder each run would have its errors reported for the old folder."""
    try:
        cache = request.config.cache.mkdir("mypy")  # type: ignore[union-attr]
        work = request.config.cache.mkdir("mypy-modules")  # type: ignore[union-attr]
    except AttributeError:  # the cache plugin is off: a fresh cache each run
        work = tmp_path_factory.mktemp("types")
        cache = work / "mypy-cache"
    sources: dict[str, Path] = {}  # module file -> the file its lines belong to
    for md in _markdown_files():
        code = markdown_module(md.read_text(encoding="utf-8"))
        if code is not None:
            f = work / f"{_module_name(md)}.py"
            _write_if_changed(f, code)
            sources[str(f)] = md
    contract = work / "typing_contract.py"
    _write_if_changed(contract, CONTRACT)
    examples = sorted((ROOT / "examples").glob("*.py"))
    cmd = [
        sys.executable, "-m", "mypy",
        "--config-file", str(ROOT / "pyproject.toml"),
        "--cache-dir", str(cache),
        "--no-error-summary", "--no-pretty", "--show-column-numbers",
        str(ROOT / "python" / "thermobear"),
        *map(str, examples), *sources, str(contract),
    ]  # fmt: skip
    run = subprocess.run(cmd, cwd=ROOT, capture_output=True, text=True, timeout=600)
    assert run.returncode in (0, 1), run.stdout + run.stderr  # 2: mypy itself failed
    errors: dict[str, list[str]] = defaultdict(list)
    for line in run.stdout.splitlines():
        m = re.match(r"^(.+?):(\d+):(\d+): error: (.*)$", line)
        if m:
            path = Path(m.group(1))
            path = path if path.is_absolute() else ROOT / path
            shown = sources.get(str(path), path)
            where = shown.relative_to(ROOT) if shown.is_relative_to(ROOT) else shown.name
            errors[str(path)].append(f"{where}:{m.group(2)}: {m.group(4)}")
    return errors, sources, contract


def _errors_under(errors: dict[str, list[str]], folder: Path) -> list[str]:
    return [e for path, es in errors.items() if Path(path).is_relative_to(folder) for e in es]


def test_the_package_type_checks(mypy_run):
    errors, _, _ = mypy_run
    found = _errors_under(errors, ROOT / "python")
    assert not found, "\n".join(found)


def test_the_examples_type_check(mypy_run):
    errors, _, _ = mypy_run
    found = _errors_under(errors, ROOT / "examples")
    assert not found, "\n".join(found)


def test_the_docs_code_blocks_type_check(mypy_run):
    errors, sources, _ = mypy_run
    assert any(md.name == "README.md" for md in sources.values())
    assert any("docs" in md.parts for md in sources.values())
    found = [e for f in sources for e in errors.get(f, [])]
    assert not found, "\n".join(found)


def test_misspelt_choices_and_misused_results_fail_the_checker(mypy_run):
    errors, _, contract = mypy_run
    got = errors.get(str(contract), [])
    failed = {int(e.split(":")[1]) for e in got}
    lines = CONTRACT.split("\n")
    must_fail = {n for n, line in enumerate(lines, 1) if line.endswith("# must fail")}
    assert len(must_fail) == 6
    missed = [lines[n - 1] for n in sorted(must_fail - failed)]
    assert not missed, "the checker accepted:\n" + "\n".join(missed)
    unexpected = [e for e in got if int(e.split(":")[1]) not in must_fail]
    assert not unexpected, "\n".join(unexpected)
    dwon = next(n for n, line in enumerate(lines, 1) if '"dwon"' in line)
    said = " ".join(e for e in got if int(e.split(":")[1]) == dwon)
    assert "dwon" in said and "direction" in said, said


def test_the_markdown_extractor_keeps_line_numbers_and_skips_fragments():
    text = "# t\n\n```python\nx = 1\n```\n\n<!-- typecheck: skip -->\n```python\ny = (\n```\n"
    mod = markdown_module(text)
    assert mod is not None
    assert mod.split("\n")[3] == "x = 1"
    assert "y = (" not in mod
    assert markdown_module("no code\n") is None


def test_the_native_stub_matches_the_extension():
    """stubtest: every name, parameter and default of ``_native.pyi`` against
    the compiled module (the allowlist holds only what it cannot check)."""
    cmd = [
        sys.executable, "-m", "mypy.stubtest", "thermobear._native",
        "--mypy-config-file", str(ROOT / "pyproject.toml"),
        "--allowlist", str(ROOT / "tests" / "stubtest_allowlist.txt"),
    ]  # fmt: skip
    run = subprocess.run(cmd, cwd=ROOT, capture_output=True, text=True, timeout=600)
    assert run.returncode == 0, run.stdout[-6000:] + run.stderr[-2000:]
