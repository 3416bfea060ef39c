"""The README's Python examples run as written."""

import re
from pathlib import Path

import matplotlib

matplotlib.use("Agg")


def test_readme_python_blocks_run(tmp_path, monkeypatch):
    monkeypatch.chdir(tmp_path)  # files the examples write land in a scratch folder
    text = (Path(__file__).resolve().parents[1] / "README.md").read_text()
    blocks = re.findall(r"```python\n(.*?)```", text, re.S)
    assert blocks
    namespace: dict = {}  # blocks build on each other, as a reader runs them
    for code in blocks:
        exec(compile(code, "README.md", "exec"), namespace)


def test_docs_hold_no_control_characters():
    # A formula once reached the docs through a non-raw Python string: "\frac",
    # "\text" and "\approx" became a form feed, a tab and a bell, and the page
    # showed "rac", "ext" and "pprox". Markdown and TeX never need these bytes.
    root = Path(__file__).resolve().parents[1]
    files = [root / "README.md", root / "CHANGELOG.md", *sorted((root / "docs").rglob("*.md"))]
    for f in files:
        text = f.read_text(encoding="utf-8")
        bad = [
            (n, repr(ch))
            for n, line in enumerate(text.split("\n"), 1)
            for ch in line
            if ch in "\x07\x08\x0b\x0c"
        ]
        assert not bad, (f.name, bad[:5])
        tabs = [n for n, line in enumerate(text.split("\n"), 1) if "\t" in line and "$" in line]
        assert not tabs, (f.name, "a tab inside a formula line", tabs[:5])
