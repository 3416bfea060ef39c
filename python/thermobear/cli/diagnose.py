"""``thermobear diagnose``: a measurement file against a baseline (a bearing
system description or a spindle preset), the tables and figures written."""

from __future__ import annotations

from pathlib import Path
from typing import Any, Optional, Sequence, Union

from .. import _validate as val
from .. import plot
from ..config import located_config_errors
from ..diagnosis import BearingModelSpec, Diagnosis, SpindleModelSpec, diagnose, model_from_toml
from ..errors import ConfigError
from ..spindle import Spindle
from ..studies.output import save_figure, write_table
from .data import located_data_errors, read_measurements

#: ``holdout`` of ``diagnose_files`` that picks the highest speeds when
#: the data hold three or more distinct speeds, and no hold-out otherwise.
AUTO_HOLDOUT = "auto"

#: The file of the diagnosis' calibrated model in the ``--out`` folder.
MODEL_FILE = "calibrated_model.json"

#: The Python advice of ``Diagnosis.summary`` and its command-line form.
_PYTHON_VERBOSE = "summary(verbose=True)"
_CLI_VERBOSE = "rerun with --verbose"


def cli_summary(d: Diagnosis, verbose: bool = False) -> str:
    """The diagnosis' summary as the command line prints it: its advice
    to see more given as the option (``--verbose``), not the Python call."""
    return str(d.summary(verbose=verbose)).replace(_PYTHON_VERBOSE, _CLI_VERBOSE)


def spindle_preset(name: str) -> Spindle:
    """The spindle preset ``name`` (``--spindle``); a ``ConfigError`` that
    lists the presets and names a close one."""
    known = Spindle.preset_names()
    if name not in known:
        raise ConfigError(
            f"invalid spindle = {name!r}: not a spindle preset (known: {', '.join(known)})"
            f"{val.did_you_mean(name, known)}"
        )
    return Spindle.preset(name)


def baseline(
    system: Union[str, Path, None], spindle: Optional[str], without: Sequence[str] = ()
) -> tuple[Any, Optional[dict]]:
    """The baseline model spec -- of a bearing system description
    (``system``, TOML) or of a spindle preset (``spindle``) -- with the
    effects in ``without`` switched off, and the description's
    ``[operating]`` table (None for a spindle). A ``ConfigError`` about the
    description names its file, line and key."""
    if system is not None and spindle is not None:
        raise ConfigError("invalid baseline: give a system description (--model) or --spindle")
    if spindle is not None:
        full = SpindleModelSpec(spindle_preset(spindle))
        known = [*full._known, "thermal_displacement"]
        for w in without:
            if w not in known:
                raise ConfigError(
                    f"invalid without = {w!r}: not an effect of the baseline "
                    f"({', '.join(known)}){val.did_you_mean(w, known)}"
                )
        drop = set(full._expand(list(without))) if without else set()
        return SpindleModelSpec(
            full.spindle, effects=[e for e in full.effects if e not in drop]
        ), None
    if system is None:
        raise ConfigError("invalid baseline: give a system description (--model) or --spindle")
    with located_config_errors(system):
        full_b, op = model_from_toml(system)
        for w in without:
            if w not in full_b.effects:
                raise ConfigError(
                    f"invalid without = {w!r}: not an effect of the baseline "
                    f"({', '.join(full_b.effects)}){val.did_you_mean(w, full_b.effects)}"
                )
        effects = [e for e in full_b.effects if e not in set(without)]
        return BearingModelSpec(full_b.bearing, effects=effects, **full_b.options), op


def with_operating_loads(df: Any, op: Optional[dict]) -> Any:
    """Measurements of a bearing with the loads of the system description's
    ``[operating]`` table where the file gives none."""
    import polars as pl

    if op is None:
        return df
    if "axial_n" not in df.columns and "preload_n" not in df.columns:
        df = df.with_columns(pl.lit(float(op.get("axial_n", 0.0))).alias("axial_n"))
    if "radial_n" not in df.columns:
        df = df.with_columns(pl.lit(float(op.get("radial_n", 0.0))).alias("radial_n"))
    return df


def diagnose_files(
    measured: Union[str, Path],
    system: Union[str, Path, None] = None,
    out: Optional[Path] = None,
    *,
    spindle: Optional[str] = None,
    without: Sequence[str] = (),
    candidates: Optional[Sequence[str]] = None,
    holdout: Union[str, float, Sequence[str], None] = "highest_speeds",
) -> tuple[Diagnosis, list[Path]]:
    """``thermobear diagnose``: diagnose a measurement file (CSV lines
    starting with ``#`` are comments) against a baseline -- a bearing system
    description (``system``, TOML) or a spindle preset (``spindle``, e.g.
    "seed-ceramic-spindle") -- with the effects in ``without`` (names, or
    "thermal_displacement" for a spindle) switched off; ``candidates`` and
    ``holdout`` as [`thermobear.diagnose`][thermobear.diagnose] takes them, with its default
    (``"auto"`` as well: the highest speeds with three or more distinct speeds,
    else none); write
    tables (gap, audit, screening, points) and figures into ``out`` when
    given, with the diagnosis' calibrated model (``calibrated_model.json``,
    [`CalibratedModel.load`][thermobear.CalibratedModel.load] reads it back,
    ``thermobear predict`` takes it)."""
    import polars as pl

    spec, op = baseline(system, spindle, without)
    p = Path(measured)
    df = with_operating_loads(read_measurements(p), op)
    if isinstance(holdout, str) and holdout == AUTO_HOLDOUT:
        n_speeds = df["speed_rpm"].n_unique() if "speed_rpm" in df.columns else 0
        holdout = "highest_speeds" if n_speeds >= 3 else None
    with located_data_errors(p):
        d = diagnose(
            spec, df, candidates=None if candidates is None else list(candidates), holdout=holdout
        )
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
        files.append(d.model.save(out / MODEL_FILE))
    return d, files
