"""Figures of a prediction with uncertainty (from
[`thermobear.predict`][thermobear.predict.band.predict]): a quantity against speed with
its shaded band, each explanation's curve and the measured points; the
probability of each gear regime against speed. Every function takes
``ax=None`` and returns the Axes."""

from __future__ import annotations

from typing import TYPE_CHECKING, Any, Optional

import numpy as np

from ..errors import ConfigError
from ..predict.band import ENVELOPE, MIXTURE
from .axes import get_axes
from .gear import layer_example, regime_color, regime_layer, regime_order
from .labels import axis_label
from .style import artist_kwargs, place_legend, styled

if TYPE_CHECKING:
    import polars
    from matplotlib.axes import Axes

__all__ = ["prediction_band", "regime_probability"]


#: How a unit of a prediction frame is shown: (factor, shown unit). A
#: stiffness reads in N/um, as engineers quote it.
_SHOWN_UNITS = {"N/m": (1e-6, "N/µm"), "C": (1.0, "°C"), "um": (1.0, "µm"), "1": (1.0, "")}

_LOADS = ("axial_n", "radial_n", "preload_n")


def shown_unit(unit: str) -> tuple[float, str]:
    """The factor from a frame's ``unit`` to the unit a figure shows, and
    that unit's label."""
    return _SHOWN_UNITS.get(unit, (1.0, unit))


def quantity_label(quantity: str, unit: str) -> str:
    """An axis label: the quantity in words and the unit shown, e.g.
    "outer ring temperature [°C]" ("radial stiffness $k_{xx}$ [N/µm]" for
    an entry of the stiffness matrix)."""
    _, shown = shown_unit(unit)
    return axis_label(quantity, shown)


def _quantity_rows(pred: polars.DataFrame, quantity: str) -> polars.DataFrame:
    """The rows of ``quantity`` at one load condition, sorted by speed;
    [`ConfigError`][thermobear.ConfigError] for a quantity the frame lacks
    or a frame of several load conditions."""
    import polars as pl

    have = pred["quantity"].unique(maintain_order=True).to_list()
    if quantity not in have:
        raise ConfigError(f"invalid quantity = {quantity!r}: the prediction holds {have}")
    rows = pred.filter(pl.col("quantity") == quantity).sort("speed_rpm")
    for c in _LOADS:
        if c in rows.columns and rows[c].n_unique() > 1:
            raise ConfigError(
                f"invalid pred: it holds several {c} ({sorted(rows[c].unique().to_list())}); "
                f"filter it to one, e.g. pred.filter(pl.col({c!r}) == ...)"
            )
    keys = ["speed_rpm", "member"] if "member" in rows.columns else ["speed_rpm"]
    if rows.select(keys).is_duplicated().any():
        raise ConfigError(
            f"invalid quantity = {quantity!r}: several rows per speed (a regime prediction: "
            "draw it with regime_probability)"
        )
    return rows


def _measured_rows(measured: polars.DataFrame, rows: polars.DataFrame) -> polars.DataFrame:
    """The measured rows at the prediction's load condition (every
    quantity: their speeds are the measured range)."""
    keep = np.ones(measured.height, dtype=bool)
    for c in _LOADS:
        if c in measured.columns and c in rows.columns and rows.height:
            keep &= np.isclose(measured[c].to_numpy().astype(float), float(rows[c][0]))
    return measured.filter(keep)


def _draw_measured(
    ax: Axes, measured: polars.DataFrame, rows: polars.DataFrame, quantity: str, k: float
) -> None:
    """The measured speed range shaded (what lies outside it is
    extrapolated) and the measured points of ``quantity`` with their
    sigma as error bars."""
    import polars as pl

    m = _measured_rows(measured, rows)
    if m.height == 0:
        return
    sp = m["speed_rpm"].to_numpy().astype(float)
    if sp.max() > sp.min():
        ax.axvspan(sp.min(), sp.max(), color="0.9", lw=0, zorder=0, label="measured speeds")
    else:
        ax.axvline(sp[0], color="0.6", lw=1.0, ls=":", zorder=0, label="measured speed")
    pts = m.filter(pl.col("quantity") == quantity).sort("speed_rpm")
    if pts.height:
        err = pts["sigma"].to_numpy() * k if "sigma" in pts.columns else None
        ax.errorbar(pts["speed_rpm"].to_numpy(), pts["value"].to_numpy() * k, yerr=err,
                    fmt="o", color="k", ms=4, capsize=2, zorder=4,
                    label="measured (± sigma)")  # fmt: skip


@styled
def prediction_band(
    pred: polars.DataFrame,
    quantity: str,
    measured: Optional[polars.DataFrame] = None,
    ax: Axes | None = None,
    **kwargs: Any,
) -> Axes:
    """One predicted ``quantity`` against speed with its band.

    ``pred``: a frame of [`thermobear.predict`][thermobear.predict.band.predict] (columns
    ``speed_rpm``, ``quantity``, ``value``, ``lower``, ``upper``, ``unit``,
    ``member``, ``method``) at one load condition. A single model: its value
    as a line and the band between ``lower`` and ``upper`` shaded. Several
    members (a tie, "unresolved"): each member's value as a line and the
    combined band shaded (the weighed mixture's, or the envelope's when the
    frame was made with ``band="envelope"``). ``measured``: a tidy measurement table
    (``speed_rpm``, ``quantity``, ``value``, ``sigma``; as from
    [`thermobear.load_measurements`][thermobear.load_measurements]): its
    points of ``quantity`` with error bars of one sigma, and the range of
    its speeds shaded grey, so that what lies outside is seen to be
    extrapolated. The axis shows the unit of the frame's ``unit`` column (a
    stiffness in N/µm). ``kwargs`` go to the value lines (``Axes.plot``)."""
    import polars as pl

    ax = get_axes(ax)
    rows = _quantity_rows(pred, quantity)
    if "member" not in rows.columns:
        rows = rows.with_columns(pl.lit("").alias("member"))
    unit = str(rows["unit"][0]) if "unit" in rows.columns else "1"
    k, _ = shown_unit(unit)
    labels = rows["member"].unique(maintain_order=True).to_list()
    combined = next((m for m in (MIXTURE, ENVELOPE) if m in labels), None)
    members = [m for m in labels if m not in (MIXTURE, ENVELOPE)]
    several = len(members) > 1 or combined is not None
    band = rows.filter(pl.col("member") == combined) if combined is not None else rows
    if several and combined is None:
        band = rows.group_by("speed_rpm").agg(pl.col("lower").min(), pl.col("upper").max())
    band = band.sort("speed_rpm")
    method = str(rows["method"][0]) if "method" in rows.columns and not several else ""
    what = {"delta": "band (delta method)", "sampling": "band (sampled)"}.get(method, "band")
    if several:
        what = (
            "band of the explanations' weighed mixture"
            if combined == MIXTURE
            else "envelope of the explanations' bands"
        )
    ax.fill_between(band["speed_rpm"].to_numpy(), band["lower"].to_numpy() * k,
                    band["upper"].to_numpy() * k, color="tab:blue", alpha=0.25, lw=0,
                    zorder=2, label=what)  # fmt: skip
    for i, m in enumerate(members):
        own = rows.filter(pl.col("member") == m)
        color = f"C{i + 1}" if several else "tab:blue"
        line = {"color": color, "lw": 1.6, "zorder": 3, "label": m if several else "prediction"}
        ax.plot(own["speed_rpm"].to_numpy(), own["value"].to_numpy() * k,
                **artist_kwargs(line, kwargs))  # fmt: skip
    if measured is not None:
        _draw_measured(ax, measured, rows, quantity, k)
    ax.set_xlabel(axis_label("speed_rpm"))
    ax.set_ylabel(quantity_label(quantity, unit))
    place_legend(ax)
    return ax


def _regime_grid(
    pred: polars.DataFrame, member: Optional[str]
) -> tuple[np.ndarray, list[str], np.ndarray]:
    """Speeds, regimes (in their order) and the probability of each regime
    at each speed (regimes x speeds): the rows of ``member``, or, without
    one, the equal-weight mixture of the members' probabilities."""
    import polars as pl

    df = pred
    if "quantity" in df.columns:
        df = df.filter(pl.col("quantity") == "regime_probability")
    if "member" in df.columns:
        df = df.filter(~pl.col("member").is_in([ENVELOPE, MIXTURE]))
        if member is not None:
            df = df.filter(pl.col("member") == member)
    if df.height == 0:
        of = "" if member is None else f" of member {member!r}"
        raise ConfigError(
            f"invalid pred: no regime_probability rows{of} (thermobear.predict(model, 'regimes'))"
        )
    n = df["member"].n_unique() if "member" in df.columns else 1
    speeds = np.unique(df["speed_rpm"].to_numpy().astype(float))
    shown = [_grouped(str(r)) for r in df["regime"].to_list()]
    regimes = sorted(set(shown), key=lambda r: regime_order(_example(r)))
    grid = np.zeros((len(regimes), len(speeds)))
    ri = {r: i for i, r in enumerate(regimes)}
    si = np.searchsorted(speeds, df["speed_rpm"].to_numpy().astype(float))
    for r, s, v in zip(shown, si, df["value"].to_numpy(), strict=True):
        grid[ri[r], s] += float(v) / n
    return speeds, regimes, grid


def _grouped(regime: str) -> str:
    """A regime's layer (``thermobear.plot.gear.regime_layer``)."""
    return regime_layer(regime)


def _example(layer: str) -> str:
    """A regime of a layer (for its order and colour)."""
    return layer_example(layer)


@styled
def regime_probability(
    pred: polars.DataFrame, ax: Axes | None = None, *, member: Optional[str] = None, **kwargs: Any
) -> Axes:
    """The probability of each gear regime against speed, stacked (the
    stack reaches 1 at every speed), from the regime prediction of
    [`thermobear.predict`][thermobear.predict.band.predict] (``what="regimes"``; columns
    ``speed_rpm``, ``regime``, ``value`` and optionally ``quantity`` and
    ``member``). Each speed's probabilities hold half-way to its
    neighbours (steps: the regimes are labels of the swept speeds). Under
    several members (explanations) the figure shows their equal-weight
    mixture, or the one named by ``member``. As in
    [`regime_map`][thermobear.plot.regime_map], the periods of 3 or more
    share one layer, "period-n (n ≥ 3)", and the colours are the same.
    ``kwargs`` go to the stack (``Axes.stackplot``)."""
    ax = get_axes(ax)
    speeds, regimes, grid = _regime_grid(pred, member)
    colors = [regime_color(_example(r)) for r in regimes]
    stack = {"labels": regimes, "colors": colors, "alpha": 0.85, "lw": 0, "step": "mid"}
    ax.stackplot(speeds, grid, **artist_kwargs(stack, kwargs))
    ax.set_xlim(speeds.min(), speeds.max() if speeds.max() > speeds.min() else speeds.min() + 1)
    ax.set_ylim(0.0, 1.0)
    ax.set_xlabel(axis_label("speed_rpm"))
    ax.set_ylabel("probability of the regime")
    place_legend(ax)
    return ax
