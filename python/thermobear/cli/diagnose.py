"""``thermobear diagnose``: a measurement file against a baseline (a bearing
system description or a spindle preset), the tables and figures written."""

from __future__ import annotations

from pathlib import Path
from typing import Any, Optional, Sequence, Union

from .. import plot
from ..diagnosis import BearingModelSpec, Diagnosis, SpindleModelSpec, diagnose, model_from_toml
from ..errors import ConfigError, DataError
from ..spindle import Spindle
from ..studies.output import save_figure, write_table


def diagnose_files(
    measured: Union[str, Path],
    system: Union[str, Path, None] = None,
    out: Optional[Path] = None,
    *,
    spindle: Optional[str] = None,
    without: Sequence[str] = (),
) -> tuple[Diagnosis, list[Path]]:
    """``thermobear diagnose``: diagnose a measurement file (CSV lines
    starting with ``#`` are comments) against a baseline -- a bearing system
    description (``system``, TOML) or a spindle preset (``spindle``, e.g.
    "seed-ceramic-spindle") -- with the effects in ``without`` (names, or
    "thermal_displacement" for a spindle) switched off; write tables (gap,
    audit, screening, points) and figures into ``out`` when given."""
    import polars as pl

    if (system is None) == (spindle is None):
        raise ConfigError("invalid baseline: give a system description (--model) or --spindle")
    p = Path(measured)
    try:
        df = pl.read_parquet(p) if p.suffix == ".parquet" else pl.read_csv(p, comment_prefix="#")
    except Exception as e:  # noqa: BLE001
        raise DataError(f"invalid measurements = {p}: cannot read: {e}") from None
    if spindle is not None:
        full = SpindleModelSpec(Spindle.preset(spindle))
        drop = set(full._expand(list(without))) if without else set()
        spec: Any = SpindleModelSpec(
            full.spindle, effects=[e for e in full.effects if e not in drop]
        )
    else:
        spec, op = model_from_toml(system)
        for w in without:
            if w not in spec.effects:
                raise ConfigError(
                    f"invalid without = {w!r}: not an effect of the baseline "
                    f"({', '.join(spec.effects)})"
                )
        spec = BearingModelSpec(
            spec.bearing, effects=[e for e in spec.effects if e not in set(without)], **spec.options
        )
        if "axial_n" not in df.columns and "preload_n" not in df.columns:
            df = df.with_columns(pl.lit(float(op.get("axial_n", 0.0))).alias("axial_n"))
        if "radial_n" not in df.columns:
            df = df.with_columns(pl.lit(float(op.get("radial_n", 0.0))).alias("radial_n"))
    n_speeds = df["speed_rpm"].n_unique() if "speed_rpm" in df.columns else 0
    d = diagnose(spec, df, holdout="highest_speeds" if n_speeds >= 3 else None)
    files: list[Path] = []
    if out is not None:
        files += write_table(d.gap, out, "diagnosis_gap")
        files += write_table(d.audit, out, "diagnosis_audit")
        files += write_table(pl.concat(d.screening, how="diagonal"), out, "diagnosis_screening")
        files += write_table(d.points, out, "diagnosis_points")
        for name, table in (("diagnosis_ties", d.ties), ("diagnosis_outliers", d.outliers)):
            if table is not None and table.height:
                files += write_table(table, out, name)
        for i, q in enumerate(sorted(set(d.points["quantity"].to_list()))):
            files.append(save_figure(plot.diagnosis_fit(d, q), out, f"diagnosis_fit_{i}"))
        files.append(save_figure(plot.diagnosis_residuals(d), out, "diagnosis_residuals"))
    return d, files
