"""The documentation: every public name has an API entry, docstrings use
cross-references the docs site resolves (no Sphinx roles), no file cites a
tracker number, and the built site reads offline in a headless browser
(skipped where Chromium or MkDocs is missing)."""

from __future__ import annotations

import importlib
import importlib.util
import inspect
import re
import sys
from pathlib import Path

import pytest

import thermobear

ROOT = Path(__file__).resolve().parents[1]
API = ROOT / "docs" / "api"
ENTRY = re.compile(r"^:::\s+([\w.]+)\s*$", re.MULTILINE)


def _resolve(path: str) -> object:
    """The object a dotted path names: the longest importable module, then
    attributes."""
    parts = path.split(".")
    for i in range(len(parts), 0, -1):
        try:
            obj: object = importlib.import_module(".".join(parts[:i]))
        except ImportError:
            continue
        for attr in parts[i:]:
            obj = getattr(obj, attr)
        return obj
    raise ImportError(path)


def _api_entries() -> dict[str, list[str]]:
    """``::: path`` entries of docs/api/*.md: path -> pages."""
    entries: dict[str, list[str]] = {}
    for page in sorted(API.glob("*.md")):
        for path in ENTRY.findall(page.read_text(encoding="utf-8")):
            entries.setdefault(path, []).append(page.name)
    return entries


def test_api_entries_resolve():
    entries = _api_entries()
    assert len(entries) > 30, entries
    unresolved = []
    for path in entries:
        try:
            _resolve(path)
        except (ImportError, AttributeError) as e:
            unresolved.append(f"{path}: {e}")
    assert not unresolved, unresolved


def test_every_public_name_has_an_api_entry():
    """Each name of ``thermobear.__all__`` is documented: an entry
    ``::: thermobear.NAME``, or an entry of the same object under its
    defining module (where the documentation tool would otherwise resolve
    the name to a module of the same name)."""
    entries = _api_entries()
    documented = {id(_resolve(p)) for p in entries}
    missing = [
        name
        for name in thermobear.__all__
        if f"thermobear.{name}" not in entries
        and id(inspect.unwrap(getattr(thermobear, name))) not in documented
    ]
    assert not missing, f"no API entry in docs/api/*.md for: {missing}"


def test_a_name_is_documented_once():
    """Two entries of one object give two anchors for one name, and
    cross-references to it become ambiguous."""
    twice = {p: pages for p, pages in _api_entries().items() if len(pages) > 1}
    assert not twice, twice


ROLE = re.compile(r":(?:py:)?(?:func|class|meth|attr|mod|data|exc|obj|const):`")


def test_no_sphinx_roles_in_the_package():
    """The docs site renders docstrings as Markdown: a Sphinx role would
    show as literal text. Cross-references are ``[`name`][thermobear.name]``."""
    found = [
        f"{path.relative_to(ROOT)}:{n}: {line.strip()}"
        for path in sorted((ROOT / "python" / "thermobear").rglob("*.py*"))
        if path.suffix in (".py", ".pyi")
        for n, line in enumerate(path.read_text(encoding="utf-8").splitlines(), 1)
        if ROLE.search(line)
    ]
    assert not found, "\n".join(found)


# A tracker citation: the word for an issue or pull request with a number,
# or a bare number sign with digits (not an anchor such as "#8-data-notes",
# an HTML entity or a colour).
TRACKER = re.compile(
    r"\b(?:issues?|tickets?|bugs?|PRs?|pull requests?)\s*#?\s*\d+\b"
    r"|(?<![\w&/#])#\d{1,4}(?![\w-])",
    re.IGNORECASE,
)
SCANNED = ("python", "src", "tests", "docs", "benches", "examples", "validation", "scripts", ".ci")
TEXT = {".py", ".pyi", ".rs", ".md", ".toml", ".txt", ".sh", ".yml", ".yaml", ".cfg", ".csv", ""}
TOP_FILES = ("README.md", "CHANGELOG.md", "Cargo.toml", "pyproject.toml", "mkdocs.yml")


def _tracker_citations(text: str) -> list[str]:
    return [m.group(0) for m in TRACKER.finditer(text)]


def test_the_tracker_pattern():
    # Built from parts, so that this file cites no number itself.
    cited = (
        "workflow (issue " + "6)",
        "issue " + "12 item 8",
        "see issues " + "3",
        "fixed in #" + "12 ",
        "(#" + "4)",
        "PR #" + "7",
    )
    for text in cited:
        assert _tracker_citations(text), text
    fine = (
        "the [§8](#8-data-notes) notes",
        "&#8212;",
        "color #1f77b4 and #000000",
        "this issues a warning for 3 points",
        "seed A (A-12), eq. 6.40",
    )
    for text in fine:
        assert not _tracker_citations(text), text


def test_no_file_cites_a_tracker_number():
    """Code and docs name the capability, never a tracker number: "the
    discrepancy workflow", not a number a reader of the package cannot
    look up."""
    files = [ROOT / f for f in TOP_FILES if (ROOT / f).is_file()]
    for d in SCANNED:
        files += [
            p
            for p in sorted((ROOT / d).rglob("*"))
            if p.is_file() and p.suffix in TEXT and "__pycache__" not in p.parts
        ]
    found = []
    for path in files:
        try:
            text = path.read_text(encoding="utf-8")
        except UnicodeDecodeError:
            continue
        for n, line in enumerate(text.splitlines(), 1):
            for cite in _tracker_citations(line):
                found.append(f"{path.relative_to(ROOT)}:{n}: {cite!r} in {line.strip()[:80]!r}")
    assert not found, "\n".join(found)


def _checker():
    spec = importlib.util.spec_from_file_location(
        "check_docs_offline", ROOT / "scripts" / "check_docs_offline.py"
    )
    mod = importlib.util.module_from_spec(spec)
    sys.modules[spec.name] = mod
    spec.loader.exec_module(mod)
    return mod


def test_the_offline_check_sees_raw_math_and_roles():
    """The page check itself, on hand-made DOMs: raw TeX, an unrendered
    arithmatex element, a MathML error and a raw role are each caught; a
    rendered page is clean."""
    check = _checker().check_dom
    clean = (
        "<html><body><p>An angle <span class='arithmatex'><math><mi>α</mi></math></span>"
        " and <code>\\(x\\)</code> quoted as code.</p><pre>:func:`x`</pre></body></html>"
    )
    assert check(clean) == []
    assert check("<html><body><p>raw \\(\\alpha_0\\) here</p></body></html>")
    assert check("<html><body><div class='arithmatex'>\\[x\\]</div></body></html>")
    assert check("<html><body><p>$$ x $$</p></body></html>")
    assert check("<html><body><p><math><merror><mtext>x</mtext></merror></math></p></body></html>")
    assert check("<html><body><p>see :func:<code>diagnose</code></p></body></html>")


def test_docs_render_offline_in_a_headless_browser(tmp_path):
    """Build the site (``mkdocs build --strict``), load pages with equations
    and API pages in headless Chromium with the network off, and find no raw
    TeX, no failed equation, no raw role and nothing loaded from off-site."""
    mod = _checker()
    chromium = mod.find_chromium()
    if chromium is None:
        pytest.skip("no chromium (apt-get install chromium)")
    for package in ("mkdocs", "mkdocstrings", "material", "latex2mathml"):
        if importlib.util.find_spec(package) is None:
            pytest.skip(f"the docs extra is not installed (no {package}): pip install '.[docs]'")
    site = tmp_path / "site"
    mod.build_site(site)
    problems = mod.check_site(site, mod.DEFAULT_PAGES, chromium)
    assert not problems, problems
