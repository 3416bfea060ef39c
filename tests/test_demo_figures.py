"""Every figure the demo writes follows the package's one style for a
report: its axis labels, titles and legend entries name quantities in words
(never a column name such as ``radial_stiffness_n_per_m``; symbols only as
mathtext), no legend covers the data area of any Axes of its figure, and no
file name reads a newton metre as "nm" (nanometre). The figures are checked
as the demo saves them (quick demo, every study), so a new study figure is
checked without being listed here."""

from __future__ import annotations

import re
from pathlib import Path
from typing import Any

import matplotlib

matplotlib.use("Agg")

import pytest
from matplotlib.figure import Figure

from thermobear.glossary import GLOSSARY
from thermobear.studies.demo import run_demo


def _without_math(text: str) -> str:
    return re.sub(r"\$[^$]*\$", "", text)


def _overlaps(fig: Figure) -> list[str]:
    """Legends (of an Axes or of the figure) whose box overlaps the data
    area of an Axes of the figure (colorbars and empty Axes aside)."""
    fig.canvas.draw()
    r = fig.canvas.get_renderer()
    legends = [a.get_legend() for a in fig.axes] + list(fig.legends)
    data_axes = [a for a in fig.axes if a.has_data() and not hasattr(a, "_colorbar")]
    bad = []
    for legend in (g for g in legends if g is not None and g.get_visible()):
        box = legend.get_window_extent(r)
        for a in data_axes:
            if box.overlaps(a.get_window_extent(r)):
                bad.append(f"legend over the axes {a.get_title() or a.get_ylabel()!r}")
    return bad


def _texts(fig: Figure) -> list[str]:
    """Axis labels, titles and legend entries of every Axes, the
    figure's suptitle and figure legends."""
    texts = []
    for a in fig.axes:
        texts += [a.get_xlabel(), a.get_ylabel(), a.get_title()]
        if a.get_legend() is not None:
            texts += [t.get_text() for t in a.get_legend().get_texts()]
    for legend in fig.legends:
        texts += [t.get_text() for t in legend.get_texts()]
    if getattr(fig, "_suptitle", None) is not None:
        texts.append(fig._suptitle.get_text())
    return [t for t in texts if t]


@pytest.fixture(scope="module")
def demo_figures(tmp_path_factory) -> dict[str, dict[str, Any]]:
    """The quick demo, every figure inspected when it is first saved:
    stem -> its texts and the legends over data."""
    seen: dict[str, dict[str, Any]] = {}
    real = Figure.savefig

    def savefig(fig: Figure, fname: Any, *args: Any, **kwargs: Any) -> Any:
        stem = Path(str(fname)).stem
        if stem not in seen:
            seen[stem] = {"texts": _texts(fig), "overlaps": _overlaps(fig)}
        return real(fig, fname, *args, **kwargs)

    out = tmp_path_factory.mktemp("demo_figures")
    with pytest.MonkeyPatch.context() as mp:
        mp.setattr(Figure, "savefig", savefig)
        run_demo(out, quick=True)
    files = [p for p in out.rglob("*") if p.is_file()]
    headers = [p.read_text().split("\n", 1)[0] for p in files if p.suffix == ".csv"]
    columns = {c.strip('"') for h in headers for c in h.split(",")}
    seen["__files__"] = {"names": [p.name for p in files], "columns": sorted(columns)}
    return seen


def _figures(demo_figures: dict[str, dict[str, Any]]) -> dict[str, dict[str, Any]]:
    return {k: v for k, v in demo_figures.items() if k != "__files__"}


def test_the_demo_figures_were_inspected(demo_figures):
    figures = _figures(demo_figures)
    assert len(figures) >= 40, sorted(figures)
    pngs = {n[:-4] for n in demo_figures["__files__"]["names"] if n.endswith(".png")}
    assert pngs == set(figures)


def test_no_label_or_legend_entry_is_a_column_name(demo_figures):
    bad = []
    for stem, fig in _figures(demo_figures).items():
        for text in fig["texts"]:
            plain = _without_math(text)
            if "_" in plain or plain.strip() in GLOSSARY:
                bad.append((stem, text))
    assert bad == []


def test_no_legend_covers_the_data(demo_figures):
    bad = {stem: fig["overlaps"] for stem, fig in _figures(demo_figures).items() if fig["overlaps"]}
    assert bad == {}


#: "nm" as a token of a name ("_100nm_", "torque_nm"): it reads as nanometre.
_NM_IN_NAME = re.compile(r"(^|[0-9_])nm([0-9_.]|$)")


def test_no_name_reads_a_newton_metre_as_nanometre(demo_figures):
    """A torque is "_n_m" in every file name and table column ("_100_n_m_")
    and "N m" on a figure, never "nm"."""
    files = demo_figures["__files__"]
    bad = [n for n in files["names"] + files["columns"] if _NM_IN_NAME.search(n)]
    for stem, fig in _figures(demo_figures).items():
        bad += [f"{stem}: {t}" for t in fig["texts"] if re.search(r"[0-9 ]nm\b|\bNm\b", t)]
    assert bad == []
