"""Every public plot function of ``thermobear.plot`` makes a figure fit for
a report: it returns its Axes, draws into a given one, passes its
``**kwargs`` on to its artists, writes PDF and SVG, names quantities in
words with their units (never a column name), keeps its legend off the data
and its labels inside a small figure. The functions are enumerated from
``thermobear.plot.__all__`` (those that return an Axes), so a new one fails
here until it is given inputs in ``CASES``. The inputs are real results of
the package at a few points (a bearing, a spindle, a rotor, a gear sweep, a
diagnosis); the regime probabilities are those of the real sweep's labels.
Also: the style can be changed and reset, the bifurcation diagram colours
each speed by its regime and marks the changes, and the demo writes every
figure in each requested format."""

from __future__ import annotations

import inspect
import re
from pathlib import Path
from typing import Any, Callable

import matplotlib

matplotlib.use("Agg")

import matplotlib.pyplot as plt
import numpy as np
import polars as pl
import pytest
from matplotlib.collections import Collection
from matplotlib.colors import to_hex
from matplotlib.lines import Line2D
from matplotlib.patches import Patch

import thermobear as tb
from thermobear import diagnosis as D
from thermobear.glossary import GLOSSARY
from thermobear.plot.gear import regime_color, regime_layer
from thermobear.plot.labels import axis_label
from thermobear.studies import demo
from thermobear.studies.output import figure_options, parse_formats, save_figure


def _returns_axes(f: Any) -> bool:
    return callable(f) and str(inspect.signature(f).return_annotation).endswith("Axes")


#: Every public plot function (returns an Axes).
PLOT_FUNCTIONS = sorted(n for n in tb.plot.__all__ if _returns_axes(getattr(tb.plot, n)))

Case = tuple[tuple[Any, ...], dict[str, Any]]


@pytest.fixture(scope="module")
def gear_points() -> pl.DataFrame:
    """A real up-sweep of the seed gear pair at a light torque: period-1,
    then quasi-periodic, then chaotic."""
    system = tb.GearSystem(
        tb.GearPair.preset("seed-electric-drive"), torque_n_m=20.0, te_amplitude_um=10.0
    )
    return tb.bifurcation(system, np.linspace(6000.0, 20000.0, 15), "up", 100, 40, 64)


@pytest.fixture(scope="module")
def diagnosis() -> Any:
    """A diagnosis of synthetic outer-ring temperatures and stiffnesses whose
    Palmgren factor differs from the baseline's."""
    base = D.BearingModelSpec(tb.Bearing.preset("7008C"))
    quantities = ["outer_ring_temperature_c"] * 4 + ["radial_stiffness_seed_n_per_m"] * 4
    cond = pl.DataFrame(
        {"speed_rpm": [3000.0, 6000.0, 9000.0, 12000.0] * 2, "axial_n": 300.0, "radial_n": 0.0,
         "quantity": quantities}
    )  # fmt: skip
    meas = D.synthetic_measurements(base.with_setting(lubrication_factor_f0=1.6), cond, 0.3, 0)
    return tb.diagnose(base, meas, candidates=["lubrication_factor_f0"])


def _regime_probabilities(points: pl.DataFrame) -> pl.DataFrame:
    per = points.unique("speed_rpm", keep="first", maintain_order=True)
    return per.select(
        "speed_rpm", "regime", pl.lit("regime_probability").alias("quantity"),
        pl.lit(1.0).alias("value"),
    )  # fmt: skip


@pytest.fixture(scope="module")
def cases(gear_points: pl.DataFrame, diagnosis: Any) -> dict[str, Case]:
    """Arguments of every plot function, from real results."""
    bearing = tb.Bearing.preset("7008C")
    speeds = [4000.0, 8000.0, 12000.0]
    curve = tb.stiffness_curve(bearing, speeds, 300.0, 0.0)
    thermal = tb.stiffness_curve(bearing, speeds, 300.0, 0.0, mode="thermal")
    spindle = tb.Spindle.preset("seed-ceramic-spindle")
    states = pl.concat([spindle.thermal_state(speed_rpm=n) for n in (6000.0, 12000.0)])
    rotor = "seed-ceramic-spindle"
    rmap = tb.regime_map(
        tb.GearSystem(tb.GearPair.preset("seed-electric-drive"), te_amplitude_um=10.0),
        [10.0, 20.0], [8000.0, 12000.0, 16000.0], transient_periods=50, record_periods=20,
    )  # fmt: skip
    pred = tb.predict(diagnosis.model, "temperatures", {"speeds_rpm": speeds, "axial_n": 300.0})
    return {
        "ball_loads": ((bearing.solve(axial_n=300.0, radial_n=400.0, speed_rpm=8000.0),), {}),
        "bifurcation": ((gear_points,), {"mark_transitions": True}),
        "campbell": ((tb.campbell(rotor, [0.0, 15000.0, 30000.0], modes=4),), {}),
        "compensation_preload": (
            (
                tb.compensation_preload(
                    spindle, speeds_rpm=[12000.0, 18000.0], spring_rate_n_per_um=0.36
                ),
            ),
            {},
        ),
        "contact_angles": ((curve,), {}),
        "diagnosis_fit": ((diagnosis, "radial_stiffness_seed_n_per_m"), {}),
        "diagnosis_residuals": ((diagnosis,), {}),
        "heat_vs_speed": (([thermal], ["300 N preload"]), {}),
        "node_temperatures": ((thermal,), {}),
        "optimal_preload": (
            (
                tb.spindle_grid(
                    spindle,
                    speeds_rpm=[12000.0, 18000.0],
                    preloads_n=[200.0, 400.0, 600.0],
                    radial_loads_n=[500.0],
                ),
            ),
            {},
        ),
        "prediction_band": ((pred, "outer_ring_temperature_c"), {}),
        "regime_map": ((rmap,), {}),
        "regime_probability": ((_regime_probabilities(gear_points),), {}),
        "spectrum": ((tb.spectrum(rotor, 12000.0, 0.02, coupled=False),), {"speed_rpm": 12000.0}),
        "spindle_temperatures": ((states,), {}),
        "spindle_transient": (
            (tb.transient(spindle, speed_rpm=12000.0, duration_s=300.0, dt_s=2.0),),
            {},
        ),
        "stiffness_cases": (
            ([curve, thermal], ["speed", "thermal"]),
            {"seed_column": "radial_stiffness_seed_n_per_m"},
        ),
        "stiffness_curve": ((curve,), {}),
        "thermal_deformations": ((thermal,), {}),
        "vibration": (
            (
                [tb.vibration(rotor, [6000.0, 12000.0], coupled=False, unbalance_grade=2.5)],
                ["uncoupled"],
            ),
            {},
        ),
    }


def _draw(cases: dict[str, Case], name: str, **extra: Any) -> Any:
    args, kwargs = cases[name]
    f: Callable[..., Any] = getattr(tb.plot, name)
    return f(*args, **{**kwargs, **extra})


@pytest.fixture(autouse=True)
def _close_figures():
    yield
    plt.close("all")


def test_every_plot_function_has_a_case(cases):
    assert len(PLOT_FUNCTIONS) >= 20
    assert sorted(cases) == PLOT_FUNCTIONS


@pytest.mark.parametrize("name", PLOT_FUNCTIONS)
def test_returns_its_axes_and_draws_into_a_given_one(cases, name):
    from matplotlib.axes import Axes

    new = _draw(cases, name)
    assert isinstance(new, Axes) and new.has_data()
    polar = name == "ball_loads"
    fig = plt.figure()
    given = fig.add_subplot(111, projection="polar" if polar else None)
    assert _draw(cases, name, ax=given) is given
    assert given.has_data() and len(fig.axes) >= 1 and given.figure is fig


def _artists(ax: Any) -> list[Any]:
    return [a for a in ax.get_children() if isinstance(a, (Line2D, Collection, Patch))]


@pytest.mark.parametrize("name", PLOT_FUNCTIONS)
def test_kwargs_reach_the_artists(cases, name):
    ax = _draw(cases, name, rasterized=True, gid="tb-kwarg")
    marked = [a for a in _artists(ax) if a.get_gid() == "tb-kwarg"]
    assert marked and all(a.get_rasterized() for a in marked)
    if name in ("regime_map", "regime_probability"):
        return  # a mesh or a stack of regime colours: a single colour has no meaning
    ax = _draw(cases, name, color="#123456")
    seen = set()
    for a in _artists(ax):
        if isinstance(a, Line2D):
            seen.add(to_hex(a.get_color()))
        elif isinstance(a, Collection) and len(a.get_facecolor()):
            seen.add(to_hex(a.get_facecolor()[0]))
        elif isinstance(a, Patch):
            seen.add(to_hex(a.get_facecolor()))
    assert "#123456" in seen


@pytest.mark.parametrize("name", PLOT_FUNCTIONS)
def test_writes_pdf_and_svg(cases, name, tmp_path):
    fig = _draw(cases, name).figure
    for ext, magic in (("pdf", b"%PDF-"), ("svg", b"<svg")):
        path = tmp_path / f"{name}.{ext}"
        fig.savefig(path)
        head = path.read_bytes()[:400]
        assert head.startswith(magic) if ext == "pdf" else magic in head, (name, ext)
        assert path.stat().st_size > 1000


def _without_math(text: str) -> str:
    return re.sub(r"\$[^$]*\$", "", text)


def _texts(ax: Any) -> tuple[list[str], list[str]]:
    """Axis labels and titles of the figure (colorbars included), and the
    legend entries."""
    labels, entries = [], []
    for a in ax.figure.axes:
        labels += [a.get_xlabel(), a.get_ylabel(), a.get_title()]
        legend = a.get_legend()
        if legend is not None:
            entries += [t.get_text() for t in legend.get_texts()]
    return [t for t in labels if t], entries


@pytest.mark.parametrize("name", PLOT_FUNCTIONS)
def test_labels_are_words_with_units_never_column_names(cases, name):
    ax = _draw(cases, name)
    labels, entries = _texts(ax)
    for text in labels + entries:
        assert "_" not in _without_math(text), (name, text)
    for text in (ax.get_xlabel(), ax.get_ylabel()):
        if text:  # a physical quantity has its unit in brackets; a ratio says what it is
            assert re.search(r"\[[^\]]+\]", text) or re.search(r"probability|σ", text), text
    if name != "regime_probability":  # a stack fills its axes: its legend stands beside them
        assert ax.get_legend() is not None or name in ("regime_map", "compensation_preload")


def test_regime_map_axes_read_speed_and_torque(cases):
    ax = _draw(cases, "regime_map")
    assert (ax.get_xlabel(), ax.get_ylabel()) == ("speed [rpm]", "torque [N m]")


@pytest.mark.parametrize("name", PLOT_FUNCTIONS)
def test_legend_stands_beside_the_data(cases, name):
    ax = _draw(cases, name)
    legend = ax.get_legend()
    if legend is None:
        return
    r = ax.figure.canvas.get_renderer()
    ax.figure.canvas.draw()
    assert not legend.get_window_extent(r).overlaps(ax.get_window_extent(r)), name


@pytest.mark.parametrize("name", PLOT_FUNCTIONS)
def test_small_figure_keeps_its_labels_whole(cases, name):
    fig = plt.figure(figsize=(3.0, 2.0))  # outside the package's style: no layout engine
    ax = fig.add_subplot(111, projection="polar" if name == "ball_loads" else None)
    _draw(cases, name, ax=ax)
    ax.set_title("a title")
    fig.canvas.draw()
    r = fig.canvas.get_renderer()
    box = fig.bbox
    for a in fig.axes:
        tight = a.get_tightbbox(r)
        assert tight.x0 >= box.x0 - 1 and tight.y0 >= box.y0 - 1, (name, tight, box)
        assert tight.x1 <= box.x1 + 1 and tight.y1 <= box.y1 + 1, (name, tight, box)
    assert ax.get_position().width > 0.15 and ax.get_position().height > 0.15, name


def test_axis_labels_of_the_glossary_read_as_words_with_units():
    assert axis_label("speed_rpm") == "speed [rpm]"
    assert axis_label("torque_n_m") == "torque [N m]"
    assert axis_label("ball_temperature_c") == "ball temperature [°C]"
    assert axis_label("dte_um") == "dynamic transmission error [µm]"
    assert axis_label("radial_stiffness_n_per_m") == "radial stiffness [N/m]"
    assert axis_label("k_xx_n_per_m", "N/µm") == "radial stiffness $k_{xx}$ [N/µm]"
    for name, entry in GLOSSARY.items():
        text = axis_label(name)
        assert "_" not in _without_math(text), name
        assert ("[" in text) == (entry.unit != "1"), name


def test_style_is_the_package_style_until_changed(cases):
    ax = _draw(cases, "stiffness_curve")
    assert ax.xaxis.label.get_fontsize() == 10.0
    assert tuple(ax.figure.get_size_inches()) == (6.0, 3.8)
    assert ax.figure.get_layout_engine() is not None  # constrained: nothing clipped
    try:
        style = tb.plot.set_style({"font.size": 13.0, "axes.labelsize": 13.0})
        assert style["axes.labelsize"] == 13.0 and style["figure.figsize"] == (6.0, 3.8)
        assert _draw(cases, "stiffness_curve").xaxis.label.get_fontsize() == 13.0
        tb.plot.set_style(defaults=False)  # only the user's own settings and matplotlib's
        assert tuple(_draw(cases, "stiffness_curve").figure.get_size_inches()) == tuple(
            matplotlib.rcParams["figure.figsize"]
        )
        with pytest.raises(tb.ConfigError, match="font.sise"):
            tb.plot.set_style({"font.sise": 3})
        with pytest.raises(tb.ConfigError, match="lines.linewidth"):
            tb.plot.set_style({"lines.linewidth": "thick"})
    finally:
        tb.plot.set_style(reset=True)
    assert _draw(cases, "stiffness_curve").xaxis.label.get_fontsize() == 10.0
    assert matplotlib.rcParams["font.size"] == matplotlib.rcParamsDefault["font.size"]


def test_bifurcation_colours_each_speed_by_its_regime_and_marks_changes(gear_points):
    per = gear_points.unique("speed_rpm", keep="first", maintain_order=True)
    regimes = per["regime"].to_list()
    assert {"period-1", "quasi-periodic", "chaotic"} <= set(regimes)  # the sweep's three regimes
    jumped = per.with_row_index().filter(pl.col("regime") == "chaotic")["index"][1]
    pts = gear_points.with_columns(
        (pl.col("speed_rpm") == per["speed_rpm"][jumped]).alias("jump_after")
    )
    ax = tb.plot.bifurcation(pts, mark_transitions=True)
    layers = sorted({regime_layer(r) for r in regimes})
    by_label = {c.get_label(): c for c in ax.collections}
    assert sorted(by_label) == layers
    speeds = gear_points["speed_rpm"].to_numpy()
    for layer, c in by_label.items():
        assert to_hex(c.get_facecolor()[0]) == to_hex(regime_color(layer))
        inside = np.isin(c.get_offsets()[:, 0], per.filter(pl.col("regime") == layer)["speed_rpm"])
        assert inside.all()
    assert sum(len(c.get_offsets()) for c in ax.collections) == len(speeds)
    s = per["speed_rpm"].to_numpy()
    changes = [0.5 * (s[i] + s[i + 1]) for i in range(len(s) - 1) if regimes[i] != regimes[i + 1]]
    vlines = [ln for ln in ax.get_lines() if ln.get_linestyle() == "--"]
    assert sorted(ln.get_xdata()[0] for ln in vlines) == sorted(changes) and changes
    (jump,) = [ln for ln in ax.get_lines() if ln.get_linestyle() == ":"]
    assert jump.get_xdata()[0] == 0.5 * (s[jumped] + s[jumped + 1])
    entries = [t.get_text() for t in ax.get_legend().get_texts()]
    assert set(layers) | {"regime change", "amplitude jump"} == set(entries)
    assert not tb.plot.bifurcation(pts).get_lines()  # without marks by default


def _png_dpi(path: Path) -> float:
    from PIL import Image

    with Image.open(path) as im:
        return float(im.info["dpi"][0])


def test_save_figure_writes_every_format_under_its_stem(tmp_path, cases):
    ax = _draw(cases, "stiffness_curve")
    with figure_options("png,pdf,svg", dpi=150):
        first = save_figure(ax, tmp_path, "seed_x_fig1_stiffness")
    assert first == tmp_path / "seed_x_fig1_stiffness.png"
    assert abs(_png_dpi(first) - 150.0) < 0.5
    assert (tmp_path / "seed_x_fig1_stiffness.pdf").read_bytes().startswith(b"%PDF-")
    assert b"<svg" in (tmp_path / "seed_x_fig1_stiffness.svg").read_bytes()[:400]
    # the default outside the options: PNG alone, 200 dpi; vector files repeat byte for byte
    assert save_figure(_draw(cases, "stiffness_curve"), tmp_path / "d", "f").suffix == ".png"
    assert abs(_png_dpi(tmp_path / "d" / "f.png") - 200.0) < 0.5
    again = [save_figure(_draw(cases, "stiffness_curve"), tmp_path / k, "f", formats="svg,pdf")
             for k in ("a", "b")]  # fmt: skip
    for ext in ("svg", "pdf"):
        a, b = ((tmp_path / k / f"f.{ext}").read_bytes() for k in ("a", "b"))
        assert a == b, ext
    assert again[0].suffix == ".svg"
    assert parse_formats(" PNG, svg,png ") == ("png", "svg")
    with pytest.raises(tb.ConfigError, match="format = 'jpg'"):
        parse_formats("png,jpg")
    with pytest.raises(tb.ConfigError, match="dpi"):
        with figure_options("png", dpi=0):
            pass


def test_demo_writes_each_requested_format(tmp_path, monkeypatch, capsys):
    from thermobear.cli import main

    one = [s for s in demo.STUDIES if s[0] == "seed_a_bearing"]
    monkeypatch.setattr(demo, "STUDIES", one)
    args = ["demo", "--out", str(tmp_path), "--quick", "--format", "png,pdf,svg", "--dpi", "150"]
    assert main(args) == 0
    pngs = sorted(p.stem for p in tmp_path.rglob("*.png"))
    assert pngs and "seed_a_ball_loads" in pngs
    for ext in ("pdf", "svg"):
        assert sorted(p.stem for p in tmp_path.rglob(f"*.{ext}")) == pngs
    assert all(abs(_png_dpi(p) - 150.0) < 0.5 for p in tmp_path.rglob("*.png"))
    capsys.readouterr()
    assert main(["demo", "--out", str(tmp_path / "x"), "--format", "png,tiff"]) == 2
    assert "tiff" in capsys.readouterr().err
