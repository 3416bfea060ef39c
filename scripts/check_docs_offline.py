#!/usr/bin/env python3
"""Load pages of the built docs site in headless Chromium with the network off.

Fails (exit 1) when a page, after its scripts have run, still shows

* an equation as raw TeX: ``\\(``, ``\\[`` or ``$$`` in the visible text, an
  ``arithmatex`` element with no rendered math inside, or a MathML
  ``<merror>`` / MathJax error element;
* a Sphinx role such as ``:func:`` or ``:class:`` in the visible text (a
  cross-reference that was never resolved);

or when any page of the site loads a script, stylesheet, font, image or frame
from another host (it would be missing offline).

The network is off for Chromium in two ways at once: it runs in a fresh
network namespace (``unshare -n``) where it can, and every host name resolves
to nothing and every request goes to a proxy on a closed local port.

Usage::

    python3 scripts/check_docs_offline.py --site DIR [--page concepts/physics/ ...]
    python3 scripts/check_docs_offline.py            # builds the site first

Exit codes: 0 every page is clean, 1 a page is not, 2 Chromium (or MkDocs,
when the site is built here) is missing or the pages could not be loaded.
"""

from __future__ import annotations

import argparse
import os
import re
import shutil
import subprocess
import sys
import tempfile
import time
from concurrent.futures import ThreadPoolExecutor
from html.parser import HTMLParser
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]

#: Pages loaded by default: every page with equations and one API page of
#: each kind (docstrings with cross-references and equations).
DEFAULT_PAGES = (
    "index.html",
    "getting-started/index.html",
    "concepts/physics/index.html",
    "concepts/conventions/index.html",
    "concepts/spindle-rotor/index.html",
    "concepts/diagnosis/index.html",
    "concepts/validation/index.html",
    "how-to/diagnose/index.html",
    "api/diagnosis/index.html",
    "api/thermal/index.html",
    "api/spindle/index.html",
)

#: Sphinx/reST roles that mean an unresolved cross-reference when shown.
ROLES = re.compile(r":(?:py:)?(?:func|class|meth|attr|mod|data|exc|obj|const|ref|doc|term|any):`")
#: TeX delimiters that mean an equation was never rendered.
RAW_TEX = re.compile(r"\\\(|\\\)|\\\[|\\\]|\$\$")

_SKIP = {"script", "style", "noscript", "template", "head", "svg"}
_VOID = {
    "area", "base", "br", "col", "embed", "hr", "img", "input", "link", "meta",
    "param", "source", "track", "wbr",
}  # fmt: skip


class _PageText(HTMLParser):
    """The visible text of a page, and what its math elements hold."""

    def __init__(self) -> None:
        super().__init__(convert_charrefs=True)
        self.stack: list[str] = []
        self.prose: list[str] = []  # text outside <pre>, inline code marked with `
        self.math_elements = 0  # rendered math: <math> or MathJax containers
        self.errors: list[str] = []
        self._arithmatex: list[dict] = []  # open arithmatex elements

    def _hidden(self) -> bool:
        return any(t in _SKIP for t in self.stack)

    def handle_starttag(self, tag: str, attrs: list[tuple[str, str | None]]) -> None:
        a = dict(attrs)
        classes = (a.get("class") or "").split()
        if tag == "merror" or tag == "mjx-merror" or "MathJax_Error" in classes:
            self.errors.append(f"a math element failed to render (<{tag}>)")
        if a.get("data-mjx-error"):
            self.errors.append(f"MathJax error: {a['data-mjx-error']}")
        if tag in ("math", "mjx-container"):
            self.math_elements += 1
            for open_ in self._arithmatex:
                open_["rendered"] = True
        if tag in _VOID:
            return
        self.stack.append(tag)
        if "arithmatex" in classes:
            self._arithmatex.append({"depth": len(self.stack), "rendered": False, "text": []})
        if tag == "code" and "pre" not in self.stack:
            self.prose.append("`")

    def handle_startendtag(self, tag: str, attrs: list[tuple[str, str | None]]) -> None:
        if tag not in _VOID:
            self.handle_starttag(tag, attrs)
            self.handle_endtag(tag)
        else:
            self.handle_starttag(tag, attrs)

    def handle_endtag(self, tag: str) -> None:
        if tag in _VOID or tag not in self.stack:
            return
        while self.stack:
            top = self.stack.pop()
            if self._arithmatex and self._arithmatex[-1]["depth"] > len(self.stack):
                done = self._arithmatex.pop()
                if not done["rendered"]:
                    tex = " ".join("".join(done["text"]).split())
                    self.errors.append(f"equation left as raw TeX: {tex[:80]!r}")
            if top == "code" and "pre" not in self.stack:
                self.prose.append("`")
            if top == tag:
                break

    def handle_data(self, data: str) -> None:
        if self._hidden():
            return
        for open_ in self._arithmatex:
            open_["text"].append(data)
        if "pre" not in self.stack:
            self.prose.append(data)


def check_dom(dom: str) -> list[str]:
    """The problems a reader would see on one page, given its DOM after its
    scripts ran. Empty when the page is clean."""
    page = _PageText()
    page.feed(dom)
    page.close()
    problems = list(page.errors)
    text = "".join(page.prose)
    # Inline code may quote TeX or roles on purpose: look at prose only for
    # TeX, and at prose with inline code marked for roles (``:func:`x` `` in
    # a docstring renders as ":func:" followed by inline code).
    prose_only = re.sub(r"`[^`]*`", " ", text)
    for m in RAW_TEX.finditer(prose_only):
        ctx = " ".join(prose_only[max(0, m.start() - 40) : m.end() + 40].split())
        problems.append(f"raw TeX delimiter {m.group()!r} in the text: ...{ctx}...")
    for m in ROLES.finditer(text):
        ctx = " ".join(text[max(0, m.start() - 30) : m.end() + 40].split())
        problems.append(f"raw role {m.group()[:-1]!r} in the text: ...{ctx}...")
    return problems


_EXTERNAL = re.compile(
    r"<(?:script|link|img|iframe|source|audio|video)\b[^>]*?\b(?:src|href)\s*=\s*"
    r"[\"']((?:https?:)?//[^\"']+)[\"']",
    re.IGNORECASE,
)


def external_resources(site: Path) -> list[str]:
    """Resources that pages of the site load from another host (links a
    reader may follow are fine; ``<link rel=preconnect>`` loads nothing but
    is reported too, since it only appears beside something that does)."""
    found = []
    for html in sorted(site.rglob("*.html")):
        for m in _EXTERNAL.finditer(html.read_text(encoding="utf-8", errors="replace")):
            found.append(f"{html.relative_to(site)}: loads {m.group(1)}")
    for css in sorted(site.rglob("*.css")):
        text = css.read_text(encoding="utf-8", errors="replace")
        for m in re.finditer(r"url\(\s*[\"']?((?:https?:)?//[^)\"']+)", text):
            found.append(f"{css.relative_to(site)}: loads {m.group(1)}")
    return found


def find_chromium() -> str | None:
    """The Chromium (or Chrome) executable, or None."""
    env = os.environ.get("CHROMIUM")
    if env:
        return env if shutil.which(env) else None
    for name in ("chromium", "chromium-browser", "google-chrome", "google-chrome-stable"):
        path = shutil.which(name)
        if path:
            return path
    return None


def _can_unshare() -> bool:
    if not hasattr(os, "geteuid") or os.geteuid() != 0 or not shutil.which("unshare"):
        return False
    return subprocess.run(["unshare", "-n", "true"], capture_output=True).returncode == 0


def dump_dom(chromium: str, url: str, *, budget_ms: int = 4000, timeout_s: float = 60.0) -> str:
    """The DOM of ``url`` after its scripts ran for ``budget_ms`` of virtual
    time, loaded by headless Chromium with no network."""
    with tempfile.TemporaryDirectory(prefix="thermobear-chromium-") as profile:
        cmd = [
            chromium,
            "--headless",
            "--no-sandbox",
            "--disable-gpu",
            "--disable-dev-shm-usage",
            "--no-first-run",
            "--no-default-browser-check",
            "--disable-extensions",
            "--disable-background-networking",
            "--disable-component-update",
            "--disable-sync",
            "--metrics-recording-only",
            f"--user-data-dir={profile}",
            # No name resolves and every request goes to a closed port.
            "--host-resolver-rules=MAP * ~NOTFOUND",
            "--proxy-server=http://127.0.0.1:9",
            "--allow-file-access-from-files",
            f"--virtual-time-budget={budget_ms}",
            "--dump-dom",
            url,
        ]
        if _can_unshare():
            cmd = ["unshare", "-n", *cmd]
        proc = subprocess.run(cmd, capture_output=True, text=True, timeout=timeout_s)
    if proc.returncode != 0 or "<html" not in proc.stdout.lower():
        raise RuntimeError(
            f"chromium could not load {url} (exit {proc.returncode}): {proc.stderr[-800:]}"
        )
    return proc.stdout


def build_site(dest: Path, demo_out: Path | None = None) -> None:
    """``mkdocs build --strict`` of this repository into ``dest``. Without
    ``demo_out`` (and no ``THERMOBEAR_DEMO_OUT``) the gallery gets one figure
    only, which is all the pages checked here need."""
    env = dict(os.environ, NO_MKDOCS_2_WARNING="1")
    with tempfile.TemporaryDirectory(prefix="thermobear-docs-demo-") as tmp:
        if demo_out is None and not env.get("THERMOBEAR_DEMO_OUT"):
            fig = Path(tmp) / "seed_a_thermal"
            fig.mkdir()
            shutil.copy(ROOT / "docs/images/seed_a_radial_stiffness_three_cases.png", fig)
            demo_out = Path(tmp)
        if demo_out is not None:
            env["THERMOBEAR_DEMO_OUT"] = str(demo_out)
        subprocess.run(
            [sys.executable, "-m", "mkdocs", "build", "--strict", "--quiet", "-d", str(dest)],
            cwd=ROOT,
            env=env,
            check=True,
        )


def check_site(
    site: Path, pages: tuple[str, ...] | list[str] = DEFAULT_PAGES, chromium: str | None = None
) -> dict[str, list[str]]:
    """Problems per page (and under ``"(site)"`` for off-site resources);
    only pages with problems appear."""
    chromium = chromium or find_chromium()
    if chromium is None:
        raise FileNotFoundError("no chromium executable found")
    problems: dict[str, list[str]] = {}
    external = external_resources(site)
    if external:
        problems["(site)"] = external
    urls = {}
    for page in pages:
        path = site / page
        if path.is_dir():
            path = path / "index.html"
        if path.is_file():
            urls[page] = path.resolve().as_uri()
        else:
            problems[page] = [f"no such page in the built site: {path}"]
    # Two browsers at a time: each is mostly waiting on its own start-up.
    with ThreadPoolExecutor(max_workers=2) as pool:
        loaded = pool.map(lambda u: dump_dom(chromium, u), urls.values())
        doms = dict(zip(urls, loaded, strict=True))
    for page, dom in doms.items():
        found = check_dom(dom)
        if found:
            problems[page] = found
    return problems


def main(argv: list[str] | None = None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--site", type=Path, help="the built site (default: build it now)")
    ap.add_argument(
        "--page",
        action="append",
        help="a page of the site, relative to it (repeatable; default: the pages with "
        "equations and three API pages)",
    )
    args = ap.parse_args(argv)
    chromium = find_chromium()
    if chromium is None:
        print("check_docs_offline: no chromium found (apt-get install chromium)", file=sys.stderr)
        return 2
    pages = args.page or list(DEFAULT_PAGES)
    t0 = time.monotonic()
    with tempfile.TemporaryDirectory(prefix="thermobear-site-") as tmp:
        site = args.site
        if site is None:
            site = Path(tmp) / "site"
            try:
                build_site(site)
            except (subprocess.CalledProcessError, FileNotFoundError) as e:
                print(f"check_docs_offline: the site did not build: {e}", file=sys.stderr)
                return 2
        try:
            problems = check_site(site, pages, chromium)
        except (RuntimeError, subprocess.TimeoutExpired) as e:
            print(f"check_docs_offline: {e}", file=sys.stderr)
            return 2
    for page, found in problems.items():
        print(f"{page}:")
        for p in found:
            print(f"  {p}")
    n_bad = len(problems)
    print(
        f"check_docs_offline: {len(pages)} pages loaded offline in "
        f"{time.monotonic() - t0:.1f} s; {n_bad} with problems"
    )
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())
