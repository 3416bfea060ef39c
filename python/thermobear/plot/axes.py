"""The Axes a figure draws into: the given one, or a new figure's, made in
the package's style (the Agg backend when there is no display)."""

from __future__ import annotations

from typing import TYPE_CHECKING

if TYPE_CHECKING:
    from matplotlib.axes import Axes


def get_axes(ax: Axes | None, polar: bool = False) -> Axes:
    """``ax`` (its figure gets the style's layout when it has none: see
    ``thermobear.plot.style.fit_layout``), or a new figure's Axes."""
    if ax is not None:
        from .style import fit_layout

        fit_layout(ax.figure)
        return ax
    import matplotlib

    if matplotlib.get_backend().lower() not in ("agg",) and not _has_display():
        matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    from .style import style_context

    with style_context():  # size, fonts and layout of the package's style
        fig = plt.figure()
        return fig.add_subplot(111, projection="polar" if polar else None)


def _has_display() -> bool:
    import os

    return bool(os.environ.get("DISPLAY") or os.environ.get("WAYLAND_DISPLAY"))
