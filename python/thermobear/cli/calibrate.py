"""``thermobear calibrate``: named parameters of a baseline (a bearing
system description or a spindle preset) calibrated on one or more
measurement files, the estimates, their 95 % intervals and the summary
written."""

from __future__ import annotations

import json
import math
from pathlib import Path
from typing import Any, Optional, Sequence, Union

from .._native import __version__
from ..diagnosis import calibrate
from ..diagnosis.measurements import prepare_measurements
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
