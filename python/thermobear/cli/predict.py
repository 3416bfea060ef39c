"""``thermobear predict``: a saved calibrated model's prediction with its
uncertainty band at the speeds and loads given on the command line; the
frame of [`thermobear.predict`][thermobear.predict.band.predict] written as
parquet and CSV, and one band figure
([`thermobear.plot.prediction_band`][thermobear.plot.prediction_band]) per
quantity and load condition."""

from __future__ import annotations

import argparse
import math
from pathlib import Path
from typing import TYPE_CHECKING, Any, Optional, Sequence, Union

from .. import _validate as val
from ..errors import ConfigError

if TYPE_CHECKING:
    import polars

#: What ``thermobear predict --what`` predicts (the ``what`` of
#: ``thermobear.predict`` without the gear regimes).
WHATS: tuple[str, ...] = ("measured", "stiffness", "temperatures", "growth", "vibration")

#: The stem of the prediction table and of its figures.
STEM = "prediction"


class UsageError(Exception):
    """A command-line usage error found after parsing (an option that does
    not fit the model given): exit status 2, one line on stderr."""


# ------------------------------------------------------------------ arguments


def _number_list(text: str, what: str) -> list[float]:
    """A comma list of finite numbers >= 0 (``what`` names them in the error)."""
    out: list[float] = []
    for t in (s.strip() for s in text.split(",")):
        try:
            x = float(t)
        except ValueError:
            raise argparse.ArgumentTypeError(f"invalid {what} = {t!r}: not a number") from None
        if not math.isfinite(x) or x < 0.0:
            raise argparse.ArgumentTypeError(f"invalid {what} = {t}: a finite number >= 0")
        out.append(x)
    return out


def speeds_arg(text: str) -> list[float]:
    """``--speeds``: a comma list of speeds [rpm]."""
    return _number_list(text, "speed_rpm")


def preloads_arg(text: str) -> list[float]:
    """``--preloads``: a comma list of a spindle's preloads [N]."""
    return _number_list(text, "preload_n")


def loads_arg(text: str) -> tuple[float, float]:
    """``--loads``: ``AXIAL_N[,RADIAL_N]`` of a bearing (radial 0 when left out)."""
    values = _number_list(text, "load_n")
    if len(values) > 2:
        raise argparse.ArgumentTypeError(
            f"invalid loads = {text!r}: AXIAL_N or AXIAL_N,RADIAL_N (repeat --loads for more)"
        )
    return (values[0], values[1] if len(values) == 2 else 0.0)


def what_arg(text: str) -> str:
    """``--what``: one of ``WHATS`` (a close misspelling is named)."""
    t = text.strip()
    if t not in WHATS:
        raise argparse.ArgumentTypeError(
            f"invalid what = {t!r}: one of {', '.join(WHATS)}{val.did_you_mean(t, WHATS)}"
        )
    return t


def band_arg(text: str) -> str:
    """``--band``: a reading of the members' combined band."""
    t = text.strip()
    known = combined_labels()
    if t not in known:
        raise argparse.ArgumentTypeError(
            f"invalid band = {t!r}: one of {', '.join(known)}{val.did_you_mean(t, known)}"
        )
    return t


def level_arg(text: str) -> float:
    """``--level``: the band's probability, in [0.5, 0.999] (``check_level``)."""
    from ..predict.uncertainty import check_level

    try:
        return float(check_level(float(text)))
    except (ValueError, ConfigError) as e:
        rule = str(e) if isinstance(e, ConfigError) else f"invalid level = {text!r}: not a number"
        raise argparse.ArgumentTypeError(rule) from None


def add_arguments(p: argparse.ArgumentParser, figure_options: Any) -> None:
    """The arguments of ``thermobear predict`` (``figure_options``: adds the
    ``--format`` and ``--dpi`` the drawing subcommands share)."""
    p.add_argument(
        "model",
        help="a saved calibrated model (.json; calibrated_model.json of thermobear calibrate "
        "or diagnose --out)",
    )
    p.add_argument(
        "--what", type=what_arg, default="measured", metavar="WHAT",
        help=f"what to predict: {', '.join(WHATS)} (default: %(default)s)",
    )  # fmt: skip
    p.add_argument(
        "--speeds", type=speeds_arg, required=True, metavar="RPM[,RPM...]",
        help="the speeds in rpm (a comma list)",
    )  # fmt: skip
    loads = p.add_mutually_exclusive_group()
    loads.add_argument(
        "--loads", type=loads_arg, action="append", metavar="AXIAL_N[,RADIAL_N]",
        help="a bearing model's load condition in N (radial 0 when left out; repeatable)",
    )  # fmt: skip
    loads.add_argument(
        "--preloads", type=preloads_arg, action="extend", metavar="N[,N...]",
        help="a spindle model's preloads in N (a comma list; repeatable)",
    )  # fmt: skip
    p.add_argument(
        "--level", type=level_arg, default=0.95, metavar="P",
        help="probability of the band, in [0.5, 0.999] (default: %(default)s)",
    )  # fmt: skip
    p.add_argument(
        "--member", default=None, metavar="LABEL",
        help="of a tie or an unresolved verdict, only this explanation's rows (or the combined "
        f"rows: {', '.join(combined_labels())})",
    )  # fmt: skip
    p.add_argument(
        "--band", type=band_arg, default=None, metavar="READING",
        help="of a tie or an unresolved verdict, how the members' bands combine: "
        f"{', '.join(combined_labels())} (default: {default_band()})",
    )  # fmt: skip
    figure_options(p)
    p.add_argument(
        "--out", required=True, help="folder for prediction.parquet, prediction.csv and figures"
    )


# ------------------------------------------------------------------ the command


def load_model(path: Path) -> Any:
    """The calibrated model saved at ``path``; a ``ConfigError`` about its
    content names the file."""
    from ..diagnosis import CalibratedModel

    try:
        return CalibratedModel.load(path)
    except ConfigError as e:  # the load names the path already
        raise ConfigError(str(e) if str(path) in str(e) else f"{path}: {e}") from None


def prediction_conditions(
    model: Any,
    speeds_rpm: Sequence[float],
    loads_n: Optional[Sequence[tuple[float, float]]] = None,
    preloads_n: Optional[Sequence[float]] = None,
) -> dict[str, Any]:
    """The conditions dict of [`thermobear.predict`][thermobear.predict.band.predict]:
    every speed at each load condition -- a bearing's ``loads_n`` (axial,
    radial) or a spindle's ``preloads_n``. ``UsageError`` when the options
    do not fit the model (``--loads`` for a spindle ...)."""
    from ..predict.conditions import condition_columns

    cols = condition_columns(model.spec)
    if cols == ("speed_rpm", "preload_n"):
        if loads_n:
            raise UsageError("--loads is for a bearing model; this is a spindle: give --preloads")
        if not preloads_n:
            raise UsageError("a spindle model needs --preloads N[,N...]")
        return {"speeds_rpm": list(speeds_rpm), "preload_n": list(preloads_n)}
    if cols == ("speed_rpm", "axial_n", "radial_n"):
        if preloads_n:
            raise UsageError("--preloads is for a spindle model; this is a bearing: give --loads")
        if not loads_n:
            raise UsageError("a bearing model needs --loads AXIAL_N[,RADIAL_N]")
        return {"speeds_rpm": list(speeds_rpm), "loads": [tuple(x) for x in loads_n]}
    raise ConfigError(
        f"invalid model = {type(model.spec).__name__}: thermobear predict takes a bearing or "
        "a spindle model"
    )


def check_what(model: Any, what: str) -> None:
    """``UsageError`` when the model predicts none of the quantities of
    ``--what`` (``--what vibration`` for a bearing model)."""
    from ..predict.conditions import quantities_for

    try:
        quantities_for(model.spec, what)
    except ConfigError as e:
        raise UsageError(f"--what {what}: {e}") from None


def combined_labels() -> tuple[str, ...]:
    """The ``member`` labels of the rows that combine the members' bands
    (one per reading of ``thermobear.predict``'s ``band``)."""
    from ..predict import band

    return tuple(getattr(band, "BANDS", (band.ENVELOPE,)))


def default_band() -> str:
    """The reading of the combined band ``thermobear.predict`` uses by default."""
    import inspect

    from ..predict import predict

    given = inspect.signature(predict).parameters.get("band")
    return str(given.default) if given is not None else combined_labels()[0]


def member_labels(model: Any) -> list[str]:
    """The ``member`` labels of the model's prediction rows: each
    explanation's and those of the combined rows (none for a single
    model)."""
    labels = [str(m.label) for m in getattr(model, "members", ()) or ()]
    return labels + list(combined_labels()) if labels else []


def check_member(model: Any, member: str, band: Optional[str] = None) -> None:
    """Refuse a ``--member`` the model has not (a close one is named), or
    combined rows that another ``--band`` reading than the one given."""
    if band is not None and member in combined_labels() and member != band:
        raise ConfigError(
            f"invalid member = {member!r}: with --band {band} the combined rows are {band!r}"
        )
    labels = member_labels(model)
    if not labels:
        raise ConfigError(
            f"invalid member = {member!r}: the model is a single explanation (kind "
            f"{model.kind!r}); leave out --member"
        )
    if member not in labels:
        raise ConfigError(
            f"invalid member = {member!r}: the model's members are "
            f"{', '.join(repr(x) for x in labels)}{val.did_you_mean(member, labels)}"
        )


def _load_suffix(row: dict[str, Any]) -> str:
    """A file-name part of a load condition: ``axial_300n_radial_0n``,
    ``preload_400n``."""
    parts = [f"{k[:-2]}_{v:g}n" for k, v in row.items()]
    return "_".join(parts).replace(".", "p")


def band_figures(
    pred: polars.DataFrame, out: Path, formats: Sequence[str], dpi: float
) -> list[Path]:
    """One band figure per quantity and load condition of ``pred``, written
    in each of ``formats`` (``prediction_<quantity>``, with the load
    condition in the name when there are several)."""
    import polars as pl

    from .. import plot
    from ..studies.output import save_figure

    loads = [c for c in ("axial_n", "radial_n", "preload_n") if c in pred.columns]
    levels = pred.select(loads).unique(maintain_order=True).rows(named=True) if loads else [{}]
    files: list[Path] = []
    for q in pred["quantity"].unique(maintain_order=True).to_list():
        for level in levels:
            rows = pred.filter(pl.col("quantity") == q)
            for k, v in level.items():
                rows = rows.filter(pl.col(k) == v)
            stem = f"{STEM}_{q}" + (f"_{_load_suffix(level)}" if len(levels) > 1 else "")
            ax = plot.prediction_band(rows, q)
            if len(levels) > 1:
                ax.set_title(", ".join(f"{k[:-2]} {v:g} N" for k, v in level.items()))
            save_figure(ax, out, stem, formats=formats, dpi=dpi)
            files += [out / f"{stem}.{ext}" for ext in formats]
    return files


def predict_files(
    model_path: Union[str, Path],
    what: str,
    speeds_rpm: Sequence[float],
    out: Path,
    *,
    loads_n: Optional[Sequence[tuple[float, float]]] = None,
    preloads_n: Optional[Sequence[float]] = None,
    level: float = 0.95,
    member: Optional[str] = None,
    band: Optional[str] = None,
    formats: Sequence[str] = ("png",),
    dpi: float = 200.0,
) -> tuple[polars.DataFrame, list[Path]]:
    """``thermobear predict``: the prediction of the calibrated model saved
    at ``model_path`` (what [`thermobear.predict`][thermobear.predict.band.predict]
    returns for ``what`` at every speed of ``speeds_rpm`` under each load
    condition: ``loads_n``, (axial_n, radial_n) pairs of a bearing, or
    ``preloads_n`` of a spindle; band at probability ``level``; ``band``:
    how a tie's members combine, None for ``thermobear.predict``'s default,
    or the reading ``member`` names), only the rows of ``member`` when
    given; written into ``out`` as
    ``prediction.parquet`` and ``prediction.csv`` with the band figures.
    Returns the frame and the files written."""
    from ..predict import predict
    from ..studies.output import write_table

    model = load_model(Path(model_path))
    conditions = prediction_conditions(model, speeds_rpm, loads_n, preloads_n)
    check_what(model, what)
    options: dict[str, Any] = {"level": level}
    if member is not None:
        check_member(model, member, band)
        if member in combined_labels():
            band = member
    if band is not None:
        options["band"] = band
    pred = predict(model, what, conditions, **options)  # type: ignore[arg-type]
    if member is not None:
        import polars as pl

        pred = pred.filter(pl.col("member") == member)
    files = write_table(pred, out, STEM)
    files += band_figures(pred, out, formats, dpi)
    return pred, files
