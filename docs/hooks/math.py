"""MkDocs hook: render every equation to MathML when the site is built.

``pymdownx.arithmatex`` (generic mode) leaves each equation as TeX wrapped in
``<span class="arithmatex">\\(...\\)</span>`` (inline) or
``<div class="arithmatex">\\[...\\]</div>`` (display). This hook replaces the
TeX with MathML from the pure-Python ``latex2mathml`` package, so the built
pages need no JavaScript renderer and no network: every current browser draws
MathML itself. The hook runs on page content, so equations in docstrings
rendered by mkdocstrings are converted too.

An equation that cannot be converted stops the build with its page and TeX,
rather than reaching a reader as raw TeX.
"""

from __future__ import annotations

import html
import re

from latex2mathml.converter import convert
from mkdocs.exceptions import PluginError

#: One arithmatex block: its tag, and the TeX with its delimiters.
_ARITHMATEX = re.compile(
    r'<(?P<tag>span|div) class="arithmatex">(?P<tex>.*?)</(?P=tag)>',
    re.DOTALL,
)
_DELIMITERS = {
    ("\\(", "\\)"): "inline",
    ("\\[", "\\]"): "block",
    ("$$", "$$"): "block",
    ("$", "$"): "inline",
}
# latex2mathml lays ``aligned`` out as one run of symbols; ``align*`` becomes
# the right/left column table that ``aligned`` means inside an equation.
_ALIGNED = re.compile(r"\\(begin|end)\{aligned\}")


def tex_to_mathml(tex: str, display: str) -> str:
    """MathML for one equation (TeX without delimiters); ``display`` is
    ``"inline"`` or ``"block"``."""
    return convert(_ALIGNED.sub(r"\\\1{align*}", tex.strip()), display=display)


def _strip_delimiters(tex: str, tag: str) -> tuple[str, str]:
    for (left, right), display in _DELIMITERS.items():
        if tex.startswith(left) and tex.endswith(right) and len(tex) >= len(left) + len(right):
            return tex[len(left) : len(tex) - len(right)], display
    # No delimiters: the element says which kind of equation it is.
    return tex, "block" if tag == "div" else "inline"


def on_page_content(html_text: str, page, **kwargs) -> str:
    """Replace every arithmatex equation of the page with MathML."""

    def render(match: re.Match[str]) -> str:
        tag = match.group("tag")
        tex, display = _strip_delimiters(html.unescape(match.group("tex")).strip(), tag)
        try:
            mathml = tex_to_mathml(tex, display)
        except Exception as exc:  # noqa: BLE001 - any failure must stop the build
            raise PluginError(
                f"{page.file.src_uri}: cannot render the equation {tex!r} as MathML: {exc}"
            ) from exc
        return f'<{tag} class="arithmatex">{mathml}</{tag}>'

    return _ARITHMATEX.sub(render, html_text)
