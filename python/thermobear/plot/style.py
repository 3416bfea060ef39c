"""The one matplotlib style of the package's figures, and how to change it.

Every plot function draws inside [`style_context`][thermobear.plot.style.style_context]:
the package's rc settings (sized for a report: a 6 x 3.8 in figure, 10 pt
text, constrained layout so that no label is cut off) plus what the user set
with [`set_style`][thermobear.plot.set_style]. matplotlib is imported only
when a figure is drawn."""

from __future__ import annotations

import functools
import inspect
from contextlib import contextmanager
from typing import (
    TYPE_CHECKING,
    Any,
    Callable,
    Iterator,
    Mapping,
    Optional,
    ParamSpec,
    TypeVar,
    cast,
)

from ..errors import ConfigError

if TYPE_CHECKING:
    from matplotlib.axes import Axes
    from matplotlib.legend import Legend

__all__ = ["DEFAULT_STYLE", "place_legend", "set_style", "style_context", "styled"]

#: The package's matplotlib rc settings (a copy: change them with ``set_style``).
DEFAULT_STYLE: dict[str, Any] = {
    "figure.figsize": (6.0, 3.8),
    "figure.dpi": 100.0,
    "figure.constrained_layout.use": True,
    "font.size": 10.0,
    "axes.titlesize": 10.5,
    "axes.labelsize": 10.0,
    "xtick.labelsize": 9.0,
    "ytick.labelsize": 9.0,
    "legend.fontsize": 8.5,
    "legend.handlelength": 3.0,  # long enough to show a dashed line's dashes
    "legend.frameon": False,
    "axes.grid": True,
    "grid.alpha": 0.3,
    "grid.linewidth": 0.6,
    "lines.linewidth": 1.5,
    "lines.markersize": 4.0,
    "axes.spines.top": False,
    "axes.spines.right": False,
    "pdf.fonttype": 42,
    "ps.fonttype": 42,
}

_overrides: dict[str, Any] = {}
_state = {"defaults": True}


def set_style(
    rc: Optional[Mapping[str, Any]] = None, *, reset: bool = False, defaults: Optional[bool] = None
) -> dict[str, Any]:
    """Change the style every plot function of ``thermobear.plot`` draws in
    and return the style now in force (matplotlib rc settings).

    ``rc``: matplotlib rcParams (e.g. ``{"font.size": 12, "figure.figsize":
    (4, 3)}``) laid over the package's style, kept for every later figure.
    ``reset=True`` first drops what earlier calls set. ``defaults=False``
    leaves out the package's own settings, so that only ``rc`` and your
    matplotlib settings (``matplotlib.style.use``, a matplotlibrc) apply;
    ``defaults=True`` brings them back. An unknown rc name or a bad value
    raises [`ConfigError`][thermobear.ConfigError] naming it."""
    import matplotlib

    new = dict(rc or {})
    for key, value in new.items():
        try:
            matplotlib.RcParams({key: value})
        except (KeyError, ValueError, TypeError) as e:
            raise ConfigError(f"invalid rc[{key!r}] = {value!r}: {e}") from None
    if reset:
        _overrides.clear()
        _state["defaults"] = True
    if defaults is not None:
        _state["defaults"] = bool(defaults)
    _overrides.update(new)
    return current_style()


def current_style() -> dict[str, Any]:
    """The rc settings in force: the package's (unless turned off) under
    the user's."""
    base = dict(DEFAULT_STYLE) if _state["defaults"] else {}
    return {**base, **_overrides}


@contextmanager
def style_context() -> Iterator[None]:
    """Draw inside the package's style (``matplotlib.rc_context``)."""
    import matplotlib

    with matplotlib.rc_context(cast(Any, current_style())):
        yield


P = ParamSpec("P")
R = TypeVar("R")


#: Plot function -> the call that computes what it draws from a model
#: (named when a model is given in its place).
COMPUTED_BY: dict[str, str] = {
    "stiffness_curve": "tb.stiffness_curve(model, speeds_rpm, axial_n)",
    "stiffness_cases": "[tb.stiffness_curve(model, speeds_rpm, axial_n, mode=m) for m in modes]",
    "contact_angles": "tb.stiffness_curve(model, speeds_rpm, axial_n)",
    "ball_loads": "bearing.solve(axial_n, radial_n, speed_rpm=...)",
    "heat_vs_speed": "[tb.stiffness_curve(model, speeds_rpm, axial_n, mode='thermal'), ...]",
    "node_temperatures": "tb.stiffness_curve(model, speeds_rpm, axial_n, mode='thermal')",
    "thermal_deformations": "tb.stiffness_curve(model, speeds_rpm, axial_n, mode='thermal')",
    "spindle_temperatures": "pl.concat([tb.thermal_state(model, s) for s in speeds_rpm])",
    "spindle_transient": "tb.transient(model, speed_rpm=..., duration_s=...)",
    "optimal_preload": "tb.spindle_grid(model, speeds_rpm=..., preloads_n=...)",
    "compensation_preload": "tb.compensation_preload(model, speeds_rpm=...)",
    "campbell": "tb.campbell(model)",
    "spectrum": "tb.spectrum(model, speed_rpm)",
    "vibration": "[tb.vibration(model, speeds_rpm)]",
    "bifurcation": "tb.bifurcation(tb.GearSystem(model), speeds_rpm)",
    "regime_map": "tb.regime_map(tb.GearSystem(model), torques_n_m, speeds_rpm)",
    "prediction_band": "tb.predict(model, what, conditions)",
    "regime_probability": "tb.predict(model, 'regimes', conditions, gear=...)",
    "diagnosis_fit": "tb.diagnose(model, measured)",
    "diagnosis_residuals": "tb.diagnose(model, measured)",
}


def _is_model(obj: Any) -> bool:
    """Whether ``obj`` is a machine or a model (a bearing, spindle, gear
    pair or system, model spec, calibrated model) rather than a result."""
    from .. import _model_hook
    from ..bearing import Bearing
    from ..gear import GearPair, GearSystem
    from ..spindle import Spindle

    return (
        _model_hook.is_calibrated(obj)
        or isinstance(obj, (Bearing, Spindle, GearPair, GearSystem))
        or all(hasattr(obj, a) for a in ("candidate_list", "with_setting", "quantities"))
    )


def refuse_model(name: str, param: str, args: tuple[Any, ...]) -> None:
    """Raise [`ConfigError`][thermobear.ConfigError] when the first argument
    (``param``) of the plot function ``name`` (or an item of it) is a model
    rather than the result it draws, naming the call that computes that
    result."""
    if not args:
        return
    first = args[0]
    items = first if isinstance(first, (list, tuple)) else (first,)
    if not any(_is_model(x) for x in items):
        return
    how = COMPUTED_BY.get(name, "the call its docstring names")
    raise ConfigError(
        f"invalid {param} = {type(items[0]).__name__}: thermobear.plot.{name} draws a "
        f"result, not a model; compute it first and plot that: {how}"
    )


def styled(func: Callable[P, R]) -> Callable[P, R]:
    """Decorate a plot function: it draws inside ``style_context``, and a
    figure without a layout engine gets the style's (constrained) layout,
    so that small figures keep their labels whole. A model (a bearing, a
    spindle, a calibrated model ...) given where the function takes the
    result it draws raises [`ConfigError`][thermobear.ConfigError] naming the
    call that computes it (``refuse_model``)."""

    first = next(iter(inspect.signature(func).parameters), "")

    @functools.wraps(func)
    def wrapper(*args: P.args, **kwargs: P.kwargs) -> R:
        refuse_model(func.__name__, first, args)
        with style_context():
            result = func(*args, **kwargs)
            fit_layout(getattr(result, "figure", None))
            if hasattr(result, "xaxis"):
                wrap_labels(cast("Axes", result))
        return result

    return wrapper


def fit_layout(fig: Any) -> None:
    """Give a figure without a layout engine the constrained layout when
    the style asks for it and every Axes sits in a grid of subplots (Axes
    placed by hand with ``fig.add_axes`` stay where they are)."""
    import matplotlib

    if fig is None or not hasattr(fig, "get_layout_engine"):
        return
    if fig.get_layout_engine() is not None:
        return
    if not matplotlib.rcParams["figure.constrained_layout.use"]:
        return
    if all(a.get_subplotspec() is not None for a in fig.axes):
        fig.set_layout_engine("constrained")


#: Width of a character relative to the font size (a generous estimate
#: for sans-serif text, so that a wrapped label fits for certain).
_CHAR_WIDTH = 0.6

#: Widest share of its Axes' cell of the figure a legend beside it takes.
_LEGEND_SHARE = 0.4


def _length(text: str) -> float:
    """Rendered length of a line in characters (mathtext counts a third of
    its source: ``$k_{xx}$`` draws about three characters)."""
    parts = text.split("$")
    return sum(len(p) if i % 2 == 0 else len(p) / 3.0 for i, p in enumerate(parts))


def wrap_text(text: str, max_chars: float) -> str:
    """Break ``text`` at spaces outside mathtext into lines of at most
    ``max_chars`` characters where it can (a longer word keeps its line)."""
    if _length(text) <= max_chars or "\n" in text:
        return text
    words: list[str] = []
    math = False
    for w in text.split(" "):
        if math and words:
            words[-1] += " " + w
        else:
            words.append(w)
        math = math != (w.count("$") % 2 == 1)
    lines = [words[0]]
    for w in words[1:]:
        if _length(lines[-1] + " " + w) <= max_chars:
            lines[-1] += " " + w
        else:
            lines.append(w)
    return "\n".join(lines)


def _cell_points(ax: Axes) -> tuple[float, float]:
    """Width and height [pt] of the Axes' cell of its figure's grid (the
    whole figure for a single Axes or one placed by hand)."""
    fig = cast(Any, ax.figure)
    w, h = (72.0 * v for v in fig.get_size_inches())
    spec = ax.get_subplotspec()
    if spec is None:
        return w, h
    rows, cols = spec.get_gridspec().get_geometry()
    return w / cols, h / rows


def wrap_labels(ax: Axes) -> None:
    """Break an axis label or title longer than the room of its Axes' cell
    of the figure into lines, so that a small figure keeps it whole."""
    w, h = _cell_points(ax)
    for text, room in ((ax.xaxis.label, w), (ax.yaxis.label, h), (ax.title, w)):
        max_chars = 0.9 * room / (_CHAR_WIDTH * float(text.get_fontsize()))
        text.set_text(wrap_text(text.get_text(), max_chars))


def place_legend(ax: Axes, *, ncols: int = 1, **kwargs: Any) -> Legend | None:
    """A legend beside the Axes, to the right of its top corner, so that it
    never covers the data (constrained layout makes room for it); none when
    nothing is labelled. An entry wider than 40 % of the Axes' cell of
    the figure is broken into lines, and the font shrinks (to 6 pt at
    least) when the entries would be taller than the cell. ``kwargs`` go to
    ``Axes.legend``."""
    import matplotlib
    from matplotlib.font_manager import FontProperties

    handles, labels = ax.get_legend_handles_labels()
    if not handles:
        return None
    given = kwargs.pop("fontsize", matplotlib.rcParams["legend.fontsize"])
    size = float(FontProperties(size=given).get_size_in_points())
    width, height = _cell_points(ax)
    # the handle and its gap to the text, in characters
    rc = matplotlib.rcParams
    handle = (rc["legend.handlelength"] + rc["legend.handletextpad"]) / _CHAR_WIDTH
    for _ in range(4):  # a smaller font until the entries fit the cell's height (6 pt at least)
        max_chars = _LEGEND_SHARE * width / (_CHAR_WIDTH * size) - handle
        shown = [wrap_text(t, max(max_chars, 8.0)) for t in labels]
        lines = sum(t.count("\n") + 1 for t in shown)
        tall = (1.25 * lines + 0.6 * len(shown)) * size
        if tall <= 0.8 * height or size <= 6.0:
            break
        size = max(6.0, size * 0.8 * height / tall)
    right = 1.10 if ax.name == "polar" else 1.02
    opts: dict[str, Any] = dict(
        loc="upper left", bbox_to_anchor=(right, 1.0), borderaxespad=0.0, ncols=ncols,
        fontsize=size,
    )  # fmt: skip
    opts.update(kwargs)
    return ax.legend(handles, shown, **opts)


def artist_kwargs(defaults: Mapping[str, Any], kwargs: Mapping[str, Any]) -> dict[str, Any]:
    """The keyword arguments of an artist: the function's ``defaults``
    overridden by the caller's ``kwargs`` (so that ``color=`` or ``lw=``
    from the caller win without a duplicate-keyword error)."""
    return {**defaults, **kwargs}
