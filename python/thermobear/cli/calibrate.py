"""``thermobear calibrate``: named parameters of a baseline (a bearing
system description or a spindle preset) calibrated on one or more
measurement files, the estimates, their 95 % intervals and the summary
written."""

from __future__ import annotations

import json
import math
from pathlib import Path
from typing import Any, Optional, Sequence, Union

from .. import _validate as val
from .._native import __version__
from ..diagnosis import calibrate
from ..diagnosis.measurements import prepare_measurements
from ..errors import ConfigError
from .data import located_data_errors, read_measurements
from .diagnose import baseline, with_operating_loads

#: Scalars of a ``Calibration`` written to calibration.json.
_STATS = ("chi2", "chi2_before", "n", "phi", "condition_number")


def _json_number(x: Any) -> Any:
    """A JSON-safe number: floats as they are, non-finite ones as None."""
    if isinstance(x, float) and not math.isfinite(x):
        return None
    return x


def calibration_summary(cal: Any) -> str:
    """The calibration's own ``summary()``, or a plain one: a line per
    calibrated value with its 95 % interval, the fit and the notes."""
    own = getattr(cal, "summary", None)
    if callable(own):
        return str(own())
    lines = [f"calibration: chi2 {cal.chi2_before:.4g} -> {cal.chi2:.4g} on {cal.n} points"]
    for r in cal.parameters.iter_rows(named=True):
        flag = "" if r["identified"] else "  (not identified)"
        lines.append(
            f"  {r['name']} [{r['set']}] = {r['value']:.6g}  "
            f"(95 %: {r['lower_95']:.6g} .. {r['upper_95']:.6g}){flag}"
        )
    lines += [f"  note: {n}" for n in cal.notes]
    return "\n".join(lines)


def calibratable(spec: Any) -> list[Any]:
    """The candidates of a baseline spec that ``calibrate --parameters``
    accepts: those of kind "parameter" against every quantity it predicts
    (so every sensor offset and gain term)."""
    return [c for c in spec.candidate_list(sorted(spec.quantities)) if c.kind == "parameter"]


def check_parameters(spec: Any, names: Sequence[str]) -> None:
    """Refuse a name of ``--parameters`` (or ``--per-set``) that the
    baseline cannot calibrate, naming a close one."""
    known = [c.name for c in calibratable(spec)]
    for n in names:
        if n not in known:
            raise ConfigError(
                f"invalid parameters = {n!r}: not a calibratable parameter of the baseline"
                f"{val.did_you_mean(n, known)} (thermobear effects --parameters lists them)"
            )


def parameter_baselines(
    system: Union[str, Path, None] = None, spindle: Optional[str] = None
) -> list[tuple[str, Any]]:
    """The baselines whose calibratable names ``thermobear effects
    --parameters`` lists, each with its spec: the system description
    ``system`` or the spindle preset ``spindle`` when given, else a bearing
    (``--model``: the default bearing baseline) and each spindle preset
    (``--spindle``)."""
    from ..bearing import Bearing
    from ..diagnosis import BearingModelSpec, SpindleModelSpec
    from ..spindle import Spindle

    if system is not None or spindle is not None:
        spec, _ = baseline(system, spindle)
        return [("--model" if system is not None else "--spindle", spec)]
    out: list[tuple[str, Any]] = [("--model", BearingModelSpec(Bearing.preset("7008C")))]
    out += [("--spindle", SpindleModelSpec(Spindle.preset(n))) for n in Spindle.preset_names()]
    return out


def parameter_lines(
    system: Union[str, Path, None] = None, spindle: Optional[str] = None
) -> list[str]:
    """``thermobear effects --parameters``: one line per name
    ``thermobear calibrate --parameters`` accepts -- name, the baseline
    options that take it (``--model``, ``--spindle``), bounds with the unit,
    description -- for the baselines of ``parameter_baselines``, in the
    order of the first baseline that has it."""
    rows: dict[str, tuple[Any, list[str]]] = {}
    for label, spec in parameter_baselines(system, spindle):
        for c in calibratable(spec):
            rows.setdefault(c.name, (c, []))[1].append(label)
    lines = []
    for name, (c, where) in rows.items():
        base = ", ".join(dict.fromkeys(where))
        bounds = f"{c.lower:g}..{c.upper:g} {c.unit}"
        lines.append(f"{name:44s} {base:18s} {bounds:20s} {c.description}")
    return lines


def _labels(files: Sequence[Path]) -> list[str]:
    """A set label per file: its stem, made unique with a number."""
    out: list[str] = []
    for f in files:
        label, k = f.stem, 2
        while label in out:
            label, k = f"{f.stem}_{k}", k + 1
        out.append(label)
    return out


def calibrate_files(
    measured: Sequence[Union[str, Path]],
    parameters: Sequence[str],
    out: Path,
    system: Union[str, Path, None] = None,
    *,
    spindle: Optional[str] = None,
    without: Sequence[str] = (),
    per_set: Sequence[str] = (),
) -> tuple[Any, list[Path]]:
    """``thermobear calibrate``: calibrate ``parameters`` (candidate names,
    as [`thermobear.calibrate`][thermobear.calibrate] takes them; ``per_set``: those with a
    value of their own per file) of a baseline -- a bearing system
    description (``system``) or a spindle preset (``spindle``), with the
    effects in ``without`` switched off -- on the measurement files
    ``measured`` (one data set each, labelled by the file's stem). Writes
    into ``out``: ``calibration_parameters`` (parquet + CSV: name, set,
    value, lower_95, upper_95, bounds, null, at_bound, identified),
    ``calibration_points`` (every measured point with the model before
    and after), ``calibration.json`` (the same estimates and the fit
    statistics), ``calibration_summary.txt`` and ``calibrated_model.json``
    (the calibrated model of the first file,
    [`CalibratedModel.load`][thermobear.CalibratedModel.load] reads it back). Returns the
    [`Calibration`][thermobear.Calibration] and the files written."""
    from ..studies.output import write_table

    spec, op = baseline(system, spindle, without)
    check_parameters(spec, [*parameters, *per_set])
    paths = [Path(m) for m in measured]
    labels = _labels(paths)
    sets: dict[str, tuple[Any, Any]] = {}
    for label, p in zip(labels, paths, strict=True):
        df = with_operating_loads(read_measurements(p), op)
        with located_data_errors(p):  # each file checked on its own: errors name it
            prepare_measurements(df, spec.quantities, None)
        sets[label] = (spec, df)
    with located_data_errors(paths[0] if len(paths) == 1 else None):
        cal = calibrate(sets, list(parameters), per_set=list(per_set))
    summary = calibration_summary(cal)
    files = write_table(cal.parameters, out, "calibration_parameters")
    files += write_table(cal.points, out, "calibration_points")
    doc = {
        "thermobear_version": __version__,
        "baseline": {"system": None if system is None else str(system), "spindle": spindle},
        "without": list(without),
        "sets": {label: str(p) for label, p in zip(labels, paths, strict=True)},
        "parameters": [
            {k: _json_number(v) for k, v in row.items()}
            for row in cal.parameters.iter_rows(named=True)
        ],
        **{k: _json_number(float(getattr(cal, k))) for k in _STATS},
        "not_identified": list(cal.not_identified),
        "notes": list(cal.notes),
        "summary": summary,
    }
    doc["n"] = int(cal.n)
    js = out / "calibration.json"
    js.write_text(json.dumps(doc, indent=2, allow_nan=False) + "\n")
    txt = out / "calibration_summary.txt"
    txt.write_text(summary + "\n")
    model = cal.model.save(out / "calibrated_model.json")
    return cal, files + [js, txt, model]
