"""Where the studies write: tables as parquet + CSV, figures in the formats
asked for (PNG by default; PDF and SVG as vector files), all through
``write_table`` and ``save_figure``."""

from __future__ import annotations

from contextlib import contextmanager
from contextvars import ContextVar
from pathlib import Path
from typing import Any, Iterator, Optional, Sequence

from ..errors import ConfigError

#: The figure formats ``save_figure`` writes.
FIGURE_FORMATS: tuple[str, ...] = ("png", "pdf", "svg")

#: The resolution of a PNG figure (and of the rasterized parts of a vector
#: one) unless the demo is told otherwise [dots per inch].
DEFAULT_DPI = 200.0

#: (formats, dpi) of the figures written now (``figure_options``).
_OPTIONS: ContextVar[tuple[tuple[str, ...], float]] = ContextVar(
    "figure_options", default=(("png",), DEFAULT_DPI)
)


def write_table(df: Any, out: Path, stem: str, *, csv: bool = True) -> list[Path]:
    """Write a polars DataFrame as parquet and (``csv=True``) CSV; large
    point sets (Poincare sections) are written as parquet only."""
    out.mkdir(parents=True, exist_ok=True)
    pq = out / f"{stem}.parquet"
    df.write_parquet(pq)
    if not csv:
        return [pq]
    df.write_csv(out / f"{stem}.csv")
    return [pq, out / f"{stem}.csv"]


def parse_formats(formats: str | Sequence[str]) -> tuple[str, ...]:
    """Figure formats from a comma list (``"png,pdf,svg"``) or a sequence,
    in their order, each once; [`ConfigError`][thermobear.ConfigError]
    naming a format that is not one of ``FIGURE_FORMATS`` or an empty list."""
    items = formats.split(",") if isinstance(formats, str) else list(formats)
    out: list[str] = []
    for f in (str(x).strip().lower().lstrip(".") for x in items):
        if f not in FIGURE_FORMATS:
            raise ConfigError(
                f"invalid format = {f!r}: one of {', '.join(FIGURE_FORMATS)} (a comma list)"
            )
        if f not in out:
            out.append(f)
    if not out:
        raise ConfigError(f"invalid format = {formats!r}: name at least one of {FIGURE_FORMATS}")
    return tuple(out)


def check_dpi(dpi: float | str) -> float:
    """The resolution as a float; [`ConfigError`][thermobear.ConfigError]
    unless it is finite and within 10 to 2400 dpi."""
    try:
        value = float(dpi)
    except (TypeError, ValueError):
        raise ConfigError(f"invalid dpi = {dpi!r}: a number of dots per inch") from None
    if not 10.0 <= value <= 2400.0:
        raise ConfigError(f"invalid dpi = {dpi!r}: between 10 and 2400 dots per inch")
    return value


@contextmanager
def figure_options(
    formats: str | Sequence[str] = ("png",), dpi: float = DEFAULT_DPI
) -> Iterator[tuple[tuple[str, ...], float]]:
    """Within the block, ``save_figure`` writes every figure in ``formats``
    at ``dpi`` (checked: ``parse_formats``, ``check_dpi``)."""
    token = _OPTIONS.set((parse_formats(formats), check_dpi(dpi)))
    try:
        yield _OPTIONS.get()
    finally:
        _OPTIONS.reset(token)


def save_figure(
    ax: Any,
    out: Path,
    stem: str,
    *,
    formats: Optional[str | Sequence[str]] = None,
    dpi: Optional[float] = None,
) -> Path:
    """Write the figure of ``ax`` as ``out/<stem>.<ext>`` for each format
    (default: those of the enclosing ``figure_options``, else PNG at 200
    dpi), close it and return the path of the first format. A figure
    without a layout engine (made outside the package's style) gets a tight
    layout first; vector files carry no date, so that they repeat byte for
    byte."""
    import matplotlib
    import matplotlib.pyplot as plt

    fmts, res = _OPTIONS.get()
    fmts = parse_formats(formats) if formats is not None else fmts
    res = check_dpi(dpi) if dpi is not None else res
    out.mkdir(parents=True, exist_ok=True)
    fig = ax.figure
    fig = getattr(fig, "figure", fig)  # a SubFigure's root figure
    if fig.get_layout_engine() is None:
        fig.tight_layout()
    meta = {"pdf": {"CreationDate": None}, "svg": {"Date": None}}
    paths = [out / f"{stem}.{ext}" for ext in fmts]
    with matplotlib.rc_context({"svg.hashsalt": "thermobear"}):
        for path, ext in zip(paths, fmts, strict=True):
            fig.savefig(path, dpi=res, format=ext, metadata=meta.get(ext))
    plt.close(fig)
    return paths[0]
