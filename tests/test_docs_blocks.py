"""Every code block of the docs runs as written.

Each page of ``docs/`` is run the way a reader runs it: its blocks in
order, in one fresh scratch folder (the test's ``tmp_path``, also the
working directory), its Python blocks sharing one namespace. What a block
is follows from its fence, and the pages keep to these conventions:

``python``
    Run with ``exec``; what it prints is kept for an output block after it.
``bash``, ``console``, ``sh``
    Command lines (a trailing backslash continues a line, ``#`` starts a
    comment, a ``$`` prompt is dropped, ``&&`` chains are split). A command
    starting with ``thermobear`` or ``python[3] -m thermobear`` is run as
    ``[sys.executable, "-m", "thermobear", ...]`` in the scratch folder and
    must exit with status 0; what it prints is kept for an output block.
    Any other command (installing, building, the Rust toolchain) is not
    run: it must be in ``NOT_RUN_COMMANDS`` below, which says why.
``toml``, ``csv`` with ``title="NAME"``
    A file the reader writes: its text is saved as ``NAME`` in the scratch
    folder, for the blocks after it to read (the docs site shows the name
    above the block). The page shows it before the first block that reads
    it. A ``toml`` or ``csv`` block without a title is a fragment and must
    be in ``NOT_RUN_BLOCKS``.
``text`` after a paragraph ending in "prints" (or "prints:")
    The output of the block before it. The real output must match it:
    lines are compared with their whitespace collapsed and blank lines
    dropped; a line ``...`` stands for any number of lines, and ``...``
    inside a line for any text. There is no other tolerance: every number
    shown is compared as printed, so a page that shows a number it does
    not want checked writes ``...`` in its place. Any other ``text`` block
    is an illustration and must be in ``NOT_RUN_BLOCKS``. (Output is not
    shown in a comment after ``print``: a comment is not checked.)
``rust``
    Compiled and run as doctests by ``cargo test --doc``: ``src/lib.rs``
    includes ``docs/rust.md`` into the crate's documentation (for doctests
    only), and the crate package ships the file; both are checked here.

Files a page reads but does not write are downloads: a Markdown link to a
file under ``docs/examples/`` is copied into the scratch folder before the
page runs, as the reader saves it.

``thermobear demo`` takes most of a minute and several pages show it: a
``demo`` command with the same arguments in a folder with the same files is
run once per test session, and later pages get a copy of the files it
wrote and of what it printed.

Every page runs in CI. ``PAGE_SECONDS`` holds the time each page took on
two shared cores; a page over ``SLOW_S`` carries ``slow`` in its test id,
so ``-k "not slow"`` leaves those out of a quick local run.
"""

from __future__ import annotations

import contextlib
import hashlib
import io
import os
import re
import shlex
import shutil
import subprocess
import sys
import time
from dataclasses import dataclass, field
from pathlib import Path

import matplotlib
import polars as pl
import pytest

matplotlib.use("Agg")

ROOT = Path(__file__).resolve().parents[1]
DOCS = ROOT / "docs"
EXAMPLES = DOCS / "examples"

SHELL = {"bash", "console", "sh"}
FILES = {"toml", "csv"}

#: Commands that are not run: (page, the command's words joined by single
#: spaces) -> why. The test runs the package as installed; installing and
#: building it, the wheels and the docs site are CI steps of their own
#: (.ci/run runs the README's quick start, which holds the same commands).
NOT_RUN_COMMANDS: dict[tuple[str, str], str] = {
    ("getting-started.md", "python3 -m pip install ."): "installs this checkout: the package "
    "under test",
    (
        "getting-started.md",
        "python3 -m pip install "
        "thermobear-0.1.0-cp311-abi3-manylinux2014_x86_64.manylinux_2_17_x86_64.whl",
    ): "a built wheel: CI builds it and installs it in a fresh environment",
    ("getting-started.md", "bash scripts/test.sh"): "every test, this one included",
    ("index.md", "python3 -m pip install ."): "installs this checkout: the package under test",
    ("index.md", "bash scripts/test.sh"): "every test, this one included",
    ("index.md", "python3 -m pip install .[docs]"): "the docs extras: CI installs them to build "
    "the site",
    ("index.md", "mkdocs build --strict"): "builds this site: a CI step of its own",
    ("how-to/study.md", "pip install thermobear[dask]"): "an extra: the test extras hold Dask",
    ("rust.md", "cargo doc --open"): "opens a browser; CI builds the crate's docs",
    ("rust.md", "cargo test"): "the crate's tests, the doctests of this page among them: "
    "scripts/test.sh runs them",
    ("rust.md", "cargo bench"): "minutes of benchmark timing; CI compiles the benches",
}

#: Blocks that are not run: (page, a piece of the block's text) -> why.
NOT_RUN_BLOCKS: dict[tuple[str, str], str] = {
    ("rust.md", "[dependencies]\nthermobear = { path"): "a fragment of the reader's own Cargo.toml",
    ("how-to/study.md", "results/thermal-grid/manifest.json"): "the layout of a study's folder, "
    "a description beside each file",
    ("cli.md", "thermobear: error: system.toml:19"): "error messages for broken files the "
    "page does not show",
}

#: Seconds per page with a block to run, measured on two cores shared with
#: other jobs (load average 5-8): idle cores take less.
PAGE_SECONDS: dict[str, float] = {
    "cli.md": 383.0,  # thermobear demo in three formats at 300 dpi; a diagnosis, a calibration
    "getting-started.md": 210.0,  # thermobear demo; the Python blocks take 8 s
    "index.md": 154.0,  # thermobear demo (a copy when getting-started.md ran it first)
    "how-to/diagnose.md": 38.0,  # a bearing and a spindle diagnosis, in Python and as commands
    "how-to/study.md": 23.0,  # a 144-point thermal grid, then on a local Dask cluster
    "api/plotting.md": 14.0,  # a calibration, then its prediction
    "how-to/rig-to-prediction.md": 5.4,
    "reproduction.md": 0.1,
    "concepts/conventions.md": 0.0,
    "concepts/limits.md": 0.0,
}
SLOW_S = 20.0


@dataclass(frozen=True)
class Block:
    lang: str
    title: str | None
    code: str
    line: int  # of the opening fence, 1-based
    before: str  # the last line of prose before the fence


_OPEN = re.compile(r"^(?P<indent>[ \t]*)```(?P<lang>[\w+-]*)(?P<attrs>[^`]*)$")
_TITLE = re.compile(r'title="([^"]+)"')


def blocks(text: str) -> list[Block]:
    """The fenced blocks of a Markdown text, in order."""
    lines = text.split("\n")
    out: list[Block] = []
    i = 0
    while i < len(lines):
        m = _OPEN.match(lines[i])
        if not m:
            i += 1
            continue
        indent = m["indent"]
        j = i + 1
        while j < len(lines) and lines[j].strip() != "```":
            j += 1
        assert j < len(lines), f"line {i + 1}: a fence that is never closed"
        body = [ln[len(indent) :] if ln.startswith(indent) else ln for ln in lines[i + 1 : j]]
        before = next((x.strip() for x in reversed(lines[:i]) if x.strip()), "")
        title = _TITLE.search(m["attrs"])
        out.append(
            Block(
                lang=m["lang"],
                title=title[1] if title else None,
                code="\n".join(body) + "\n",
                line=i + 1,
                before=before,
            )
        )
        i = j + 1
    return out


def commands(code: str) -> list[list[str]]:
    """The commands of a shell block, each as its words."""
    out: list[list[str]] = []
    for line in code.replace("\\\n", " ").split("\n"):
        words = shlex.split(re.sub(r"^\s*\$ ", "", line), comments=True)
        cmd: list[str] = []
        for w in [*words, "&&"]:
            if w != "&&":
                cmd.append(w)
            elif cmd:
                out.append(cmd)
                cmd = []
    return out


def thermobear_args(cmd: list[str]) -> list[str] | None:
    """The arguments of a thermobear command; None for any other command."""
    if cmd[0] == "thermobear":
        return cmd[1:]
    if cmd[0] in ("python", "python3") and cmd[1:3] == ["-m", "thermobear"]:
        return cmd[3:]
    return None


@dataclass
class Step:
    block: Block
    kind: str  # python, commands, file, output, rust or not run
    commands: list[list[str]] = field(default_factory=list)  # thermobear arguments


def plan(page: Path) -> tuple[list[Step], set[tuple[str, str]]]:
    """What running a page does with each block, and the ``NOT_RUN_*`` keys
    it used. A block or command that neither runs nor is listed fails."""
    name = page.relative_to(DOCS).as_posix()
    steps: list[Step] = []
    used: set[tuple[str, str]] = set()
    for b in blocks(page.read_text(encoding="utf-8")):
        where = f"{name}:{b.line}"
        if b.lang == "python":
            steps.append(Step(b, "python"))
        elif b.lang in SHELL:
            run = []
            for cmd in commands(b.code):
                args = thermobear_args(cmd)
                if args is None:
                    key = (name, " ".join(cmd))
                    assert key in NOT_RUN_COMMANDS, (
                        f"{where}: the command {key[1]!r} is neither thermobear "
                        "nor in NOT_RUN_COMMANDS"
                    )
                    used.add(key)
                else:
                    run.append(args)
            steps.append(Step(b, "commands" if run else "not run", run))
        elif b.lang in FILES and b.title:
            steps.append(Step(b, "file"))
        elif b.lang == "text" and re.search(r"\bprints:?$", b.before, re.I):
            assert steps and steps[-1].kind in ("python", "commands"), (
                f"{where}: an output block after no block that runs"
            )
            steps.append(Step(b, "output"))
        elif b.lang == "rust":
            steps.append(Step(b, "rust"))
        else:
            keys = [k for k in NOT_RUN_BLOCKS if k[0] == name and k[1] in b.code]
            assert keys, (
                f"{where}: a {b.lang or 'plain'} block neither runs nor is in NOT_RUN_BLOCKS"
            )
            used.update(keys)
            steps.append(Step(b, "not run"))
    return steps, used


def downloads(page: Path) -> list[Path]:
    """The files under docs/examples/ the page links to."""
    text = page.read_text(encoding="utf-8")
    found = []
    for link in re.findall(r"\]\(([^)\s#]+)\)", text):
        target = (page.parent / link).resolve()
        if EXAMPLES in target.parents:
            assert target.is_file(), f"{page.name}: a link to {link}, which does not exist"
            found.append(target)
    return found


def matches(expected: str, actual: str) -> bool:
    """Whether real output matches an output block (see the module's
    docstring)."""

    def lines(s: str) -> list[str]:
        return [" ".join(ln.split()) for ln in s.split("\n") if ln.strip()]

    pattern = "".join(
        r"(?:[^\n]*\n)*?" if ln == "..." else ".*?".join(map(re.escape, ln.split("..."))) + r"\n"
        for ln in lines(expected)
    )
    return re.fullmatch(pattern, "".join(ln + "\n" for ln in lines(actual))) is not None


def _snapshot(folder: Path) -> dict[str, str]:
    return {
        p.relative_to(folder).as_posix(): hashlib.sha256(p.read_bytes()).hexdigest()
        for p in sorted(folder.rglob("*"))
        if p.is_file()
    }


#: (arguments, the folder's files before) -> (the folder, the files the
#: demo wrote, what it printed); see the module's docstring.
_DEMO_RUNS: dict[tuple[tuple[str, ...], tuple], tuple[Path, list[str], str]] = {}


def run_thermobear(args: list[str], folder: Path) -> str:
    """Run a thermobear command in ``folder``; what it printed."""
    key = (tuple(args), tuple(sorted(_snapshot(folder).items())))
    if args[:1] == ["demo"] and key in _DEMO_RUNS:
        first, written, printed = _DEMO_RUNS[key]
        for rel in written:
            (folder / rel).parent.mkdir(parents=True, exist_ok=True)
            shutil.copy2(first / rel, folder / rel)
        return printed
    before = dict(key[1])
    run = subprocess.run(
        [sys.executable, "-m", "thermobear", *args],
        cwd=folder,
        env={**os.environ, "MPLBACKEND": "Agg"},
        capture_output=True,
        text=True,
        timeout=1800,
    )
    assert run.returncode == 0, (
        f"thermobear {shlex.join(args)}: exit status {run.returncode}\n{run.stderr[-3000:]}"
    )
    if args[:1] == ["demo"]:
        written = [rel for rel, h in _snapshot(folder).items() if before.get(rel) != h]
        _DEMO_RUNS[key] = (folder, written, run.stdout)
    return run.stdout


def run_page(page: Path, folder: Path) -> tuple[dict[str, int], dict[int, float]]:
    """Run a page's blocks in ``folder``, the working directory: how many
    blocks of each kind, and the seconds each block took, by its line."""
    name = page.relative_to(DOCS).as_posix()
    steps, _ = plan(page)
    for f in downloads(page):
        shutil.copy(f, folder / f.name)
    namespace: dict = {"__name__": "__main__"}
    counts: dict[str, int] = {}
    seconds: dict[int, float] = {}
    printed = ""
    for step in steps:
        b = step.block
        where = f"{name}:{b.line}"
        t0 = time.perf_counter()
        if step.kind == "python":
            out = io.StringIO()
            with contextlib.redirect_stdout(out):
                exec(compile(b.code, where, "exec"), namespace)
            printed = out.getvalue()
        elif step.kind == "commands":
            printed = "".join(run_thermobear(args, folder) for args in step.commands)
        elif step.kind == "file":
            assert b.title
            (folder / b.title).parent.mkdir(parents=True, exist_ok=True)
            (folder / b.title).write_text(b.code, encoding="utf-8")
        elif step.kind == "output":
            assert matches(b.code, printed), (
                f"{where}: the page shows\n{b.code}\nbut the block before it printed\n{printed}"
            )
        counts[step.kind] = counts.get(step.kind, 0) + 1
        seconds[b.line] = time.perf_counter() - t0
    return counts, seconds


PAGES = sorted(DOCS.rglob("*.md"))


def _param(page: Path):
    name = page.relative_to(DOCS).as_posix()
    slow = PAGE_SECONDS.get(name, 0.0) > SLOW_S
    return pytest.param(page, id=f"{name}-slow" if slow else name)


@pytest.mark.parametrize("page", [_param(p) for p in PAGES])
def test_the_page_runs_as_written(page: Path, tmp_path: Path, monkeypatch: pytest.MonkeyPatch):
    monkeypatch.chdir(tmp_path)  # what the blocks write lands in the scratch folder
    counts, seconds = run_page(page, tmp_path)
    print(page.relative_to(DOCS), counts, f"{sum(seconds.values()):.1f} s")


def test_every_block_runs_or_is_listed_with_its_reason():
    used: set[tuple[str, str]] = set()
    kinds: set[str] = set()
    for page in PAGES:
        steps, keys = plan(page)
        used |= keys
        kinds |= {s.kind for s in steps}
    assert {"python", "commands", "file", "output", "rust"} <= kinds
    stale = (set(NOT_RUN_COMMANDS) | set(NOT_RUN_BLOCKS)) - used
    assert not stale, f"entries that match no block any more: {sorted(stale)}"
    names = {p.relative_to(DOCS).as_posix() for p in PAGES}
    assert set(PAGE_SECONDS) <= names, set(PAGE_SECONDS) - names


def test_the_rust_page_is_compiled_as_doctests():
    rust = [b for b in blocks((DOCS / "rust.md").read_text(encoding="utf-8")) if b.lang == "rust"]
    assert rust and all("fn main()" in b.code for b in rust)
    lib = (ROOT / "src" / "lib.rs").read_text(encoding="utf-8")
    assert re.search(r'#\[cfg\(doctest\)\]\s*#\[doc = include_str!\("\.\./docs/rust\.md"\)\]', lib)
    cargo = (ROOT / "Cargo.toml").read_text(encoding="utf-8")
    include = re.search(r"^include = \[(.*?)\]", cargo, re.S | re.M)
    assert include and '"/docs/rust.md"' in include[1], "the crate package must ship docs/rust.md"


def test_the_downloads_are_the_files_the_pages_show():
    diagnose = {
        b.title: b.code for b in blocks((DOCS / "how-to/diagnose.md").read_text()) if b.title
    }
    for name in ("measured.csv", "system.toml"):
        assert (EXAMPLES / name).read_text(encoding="utf-8") == diagnose[name], name
    runs = pl.read_csv(EXAMPLES / "runs.csv")
    for run in ("a", "b"):
        one = pl.read_csv(EXAMPLES / f"run_{run}.csv")
        assert runs.filter(pl.col("run") == run).drop("run").equals(one), run
    linked = {f for page in PAGES for f in downloads(page)}
    assert linked == set(EXAMPLES.iterdir()), "a file under docs/examples/ no page links to"


def test_output_blocks_match_as_documented():
    out = "verdict: x = 0.01874\n  a   b\n\ngap 4.75 -> 1.45\n(note)\n"
    assert matches("verdict: x = 0.01874\na b\ngap 4.75 -> 1.45\n(note)", out)
    assert matches("verdict: x = ...\n...\n(note)", out)
    assert matches("verdict: x = 0.01874\n...\ngap 4.75 -> ...\n...", out)
    assert not matches("verdict: x = 0.0187\n...", out)  # numbers as printed
    assert not matches("verdict: x = 0.01874\na b", out)  # the rest needs a "..." line
    assert not matches("gap 4.75 -> 1.45\n...", out)


def test_commands_are_read_as_a_reader_types_them():
    code = (
        "# a comment\n$ thermobear diagnose m.csv \\\n    --out d/   # trailing\n"
        'python3 -m pip install ".[docs]" && python -m thermobear demo --quick\n'
    )
    cmds = commands(code)
    assert cmds == [
        ["thermobear", "diagnose", "m.csv", "--out", "d/"],
        ["python3", "-m", "pip", "install", ".[docs]"],
        ["python", "-m", "thermobear", "demo", "--quick"],
    ]
    assert [thermobear_args(c) for c in cmds] == [
        ["diagnose", "m.csv", "--out", "d/"],
        None,
        ["demo", "--quick"],
    ]
