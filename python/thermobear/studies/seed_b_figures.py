"""Drawing helpers shared by the seed B counterpart figures: multi-panel
figures, one line per front/rear bearing or per case, and the human names of
the spindle's bearing parts."""

from __future__ import annotations

from typing import Any, Sequence

#: Bearing parts of the spindle's thermal network: column stem -> human name.
PARTS: tuple[tuple[str, str], ...] = (
    ("ball", "ball"),
    ("inner_ring", "inner ring"),
    ("outer_ring", "outer ring"),
)

#: Line style of each bearing set (front solid, rear dashed).
SETS: tuple[tuple[str, str], ...] = (("front", "-"), ("rear", "--"))

#: One colour per preload of the seed B grids (300, 400, 500 N).
PRELOAD_COLOURS = {300.0: "tab:blue", 400.0: "tab:orange", 500.0: "tab:green"}


def panels(
    n: int, ncols: int | None = None, size_in: tuple[float, float] = (5.2, 4.0)
) -> list[Any]:
    """``n`` Axes in one new figure, ``ncols`` per row (default: all in one
    row), each about ``size_in`` inches (the Agg backend when there is no
    display, as every thermobear plot)."""
    from ..plot.axes import get_axes

    first = get_axes(None)
    if n == 1:
        return [first]
    fig: Any = first.figure
    ncols = n if ncols is None else ncols
    nrows = -(-n // ncols)
    fig.set_size_inches(size_in[0] * ncols, size_in[1] * nrows)
    first.remove()
    return [fig.add_subplot(nrows, ncols, i + 1) for i in range(n)]


def legend_outside(ax: Any, fontsize: float = 7) -> None:
    """The legend to the right of the Axes, clear of the data (the
    package's ``place_legend``; its font shrinks further on a small
    panel)."""
    from ..plot.style import place_legend

    place_legend(ax, fontsize=fontsize)


def finish(ax: Any, xlabel: str, ylabel: str, title: str = "", legend: bool = True) -> Any:
    """Axis labels, a light grid, the title and a legend beside the Axes,
    clear of the data (the package's ``place_legend``). A label with an
    underscore and no space is a column or glossary name, shown as its
    quantity and unit (``axis_label``: "speed_rpm" -> "speed [rpm]")."""
    from matplotlib.ticker import MaxNLocator

    ax.set_xlabel(_label(xlabel))
    ax.set_ylabel(_label(ylabel))
    if ax.get_xscale() == "linear":  # at most 6 ticks: 5-digit speeds stay apart on a narrow panel
        ax.xaxis.set_major_locator(MaxNLocator(nbins=5, steps=[1, 2, 2.5, 3, 5, 10]))
    ax.grid(True, alpha=0.3)
    if title:
        ax.set_title(title, fontsize=10)
    if legend:
        legend_outside(ax, 8)
    return ax


def _label(text: str) -> str:
    """A column or glossary name as "quantity [unit]"; other text as is."""
    from ..plot.labels import axis_label

    return axis_label(text) if "_" in text and " " not in text else text


def front_rear_lines(
    ax: Any,
    df: Any,
    x: str,
    columns: Sequence[tuple[str, str]],
    scale: float = 1.0,
    marker: str = "o",
) -> None:
    """Per ``(column stem, label)``: the front column (solid) and the rear
    one (dashed) against ``x``, in one colour per stem; ``scale`` multiplies
    the values. A stem is the column without its ``front_``/``rear_`` prefix."""
    xs = df[x].to_numpy()
    for i, (stem, label) in enumerate(columns):
        colour = f"C{i}"
        for side, style in SETS:
            col = f"{side}_{stem}"
            if col in df.columns:
                ax.plot(
                    xs,
                    df[col].to_numpy() * scale,
                    linestyle=style,
                    marker=marker,
                    markersize=3,
                    color=colour,
                    label=f"{side} {label}",
                )
