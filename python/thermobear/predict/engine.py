"""A calibrated model in a [`Study`][thermobear.Study]: the ``prediction``
kind of point, and the sampled band computed through the study engine
(this machine, or a Dask cluster: ``predict(..., engine=...)``).

A ``prediction`` point is a calibrated model's outputs (every quantity of
its ``what``; the others null) at one operating condition and one vector of
its calibrated values: ``sample`` 0 is the estimate, ``sample`` k (1 ..
``samples``) the k-th scrambled Sobol point of ``seed``, exactly as
[`predict`][thermobear.predict.band.predict] draws them. The ``model``
input is stored as the model's saved JSON text, so the study's description
(and its hash) holds the model itself: another model is another study, and a
Dask worker rebuilds the model from the description alone. Its column shows
the first 16 hex digits of the text's SHA-256.

The points of one model and one sample are computed together, in one call
of the model spec's ``predict`` over their conditions; every condition is
solved on its own, so a point's outputs do not depend on the chunking."""

from __future__ import annotations

import threading
from typing import TYPE_CHECKING, Any, Mapping, Optional, Sequence

import numpy as np

from .. import errors
from ..diagnosis.calibrated import CalibratedModel
from ..diagnosis.protocol import MODEL_KINDS
from ..errors import ConfigError, ThermobearError
from ..study import Study
from ..study.kinds import Kind, Param, _grouped, _one_of, register_kind
from ..study.models import model_of, model_shown, model_text
from .conditions import WHATS, condition_columns, is_spindle, quantities_for
from .uncertainty import parameters_of, sampled_quantiles, sobol_points

if TYPE_CHECKING:
    import polars

_KEEP = 64
_LOCK = threading.Lock()  # a Dask worker runs tasks in several threads

#: Sobol points by (model key, member, samples, seed); the latest ``_KEEP``.
_POINTS: dict[tuple[str, str, int, int], np.ndarray] = {}


def _member_of(model: CalibratedModel, member: str) -> CalibratedModel:
    if not member:
        return model
    for m in model.members:
        if m.label == member:
            return m
    known = ", ".join(repr(m.label) for m in model.members) or "none (not a tie)"
    raise ConfigError(f"invalid member = {member!r}: the model's members: {known}")


def sample_values(
    model: CalibratedModel, key: tuple[str, str, int, int], sample: int
) -> np.ndarray:
    """The calibrated values of ``sample``: 0 the estimates, k the k-th of
    the ``samples`` Sobol points of ``seed`` (``key``: model key, member,
    samples, seed)."""
    samples = key[2]
    if sample > samples:
        raise ConfigError(f"invalid sample = {sample}: 0 (the estimate) .. samples = {samples}")
    if sample == 0:
        return np.asarray(model.values, dtype=float)
    points = _POINTS.get(key)
    if points is None:
        points = sobol_points(parameters_of(model), samples, key[3])
        with _LOCK:
            if len(_POINTS) >= _KEEP:
                _POINTS.pop(next(iter(_POINTS)))
            _POINTS[key] = points
    return points[sample - 1]


def _conditions(spec: Any, rows: polars.DataFrame) -> polars.DataFrame:
    """The rows' operating conditions as the spec reads them."""
    import polars as pl

    if is_spindle(spec):
        if (rows["axial_n"] != 0.0).any():
            raise ConfigError("invalid axial_n: a spindle model's condition is preload_n")
        pre = rows["preload_n"].fill_null(float(spec.spindle.preload_n))
        return pl.DataFrame({"speed_rpm": rows["speed_rpm"], "preload_n": pre})
    if rows["preload_n"].is_not_null().any():
        raise ConfigError(
            "invalid preload_n: a bearing model's conditions are axial_n and radial_n"
        )
    return rows.select(condition_columns(spec))


def _sample_of(keys: dict, kind_name: str) -> tuple[Any, np.ndarray]:
    """The calibrated model (or tie member) of a prediction point and its
    calibrated values at the point's sample (empty: no calibrated value)."""
    if not keys["model"]:
        raise ConfigError(f"invalid model = '': a {kind_name} study needs a model")
    cm = _member_of(model_of(keys["model"]), keys["member"])
    at = (keys["model"], keys["member"], keys["samples"], keys["seed"])
    return cm, sample_values(cm, at, keys["sample"])


def _run_prediction(kind: Kind, inputs: Any, threads: Optional[int]) -> Any:
    import polars as pl

    def solve(keys: dict, rows: Any) -> Any:
        cm, theta = _sample_of(keys, "prediction")
        spec = cm.spec_at(theta) if theta.size else cm.spec
        got = spec.predict(_conditions(spec, rows))
        out = {q: np.asarray(got[q], dtype=float) for q in quantities_for(spec, keys["what"])}
        return pl.DataFrame(out).with_columns(pl.lit(True).alias("ok"))

    return _grouped(kind, inputs, solve)


def _at_least(name: str, least: int) -> Any:
    def check(value: Any) -> None:
        if value < least:
            raise ConfigError(f"invalid {name} = {value!r}: must be >= {least}")

    return check


def _outputs() -> tuple[tuple[str, str], ...]:
    names = dict.fromkeys(q for _, _, quantities in MODEL_KINDS.values() for q in quantities)
    return tuple((q, "Float64") for q in names)


PREDICTION = Kind(
    "prediction",
    "a calibrated model's outputs at a condition and a sample of its calibrated values",
    (
        Param(
            "model",
            str,
            "",
            "calibrated model: the object, its saved JSON file or text (column: SHA-256 key)",
            convert=model_text,
            show=model_shown,
        ),
        Param("member", str, "", "member (explanation) label of a tie; '' the model itself"),
        Param("what", str, "measured", "quantities, as predict's", check=_one_of("what", *WHATS)),
        Param("samples", int, 64, "Sobol samples drawn", check=_at_least("samples", 1)),
        Param("seed", int, 0, "seed of the scrambled Sobol points", check=_at_least("seed", 0)),
        Param("sample", int, 0, "0: the estimate; k: Sobol point k", check=_at_least("sample", 0)),
        Param("speed_rpm", float, 0.0, "shaft speed [rpm]", per_point=True),
        Param("axial_n", float, 0.0, "axial load of a bearing model [N]", per_point=True),
        Param("radial_n", float, 0.0, "radial load of a bearing model [N]", per_point=True),
        Param("preload_n", float, None, "preload of a spindle model [N]", per_point=True),
    ),
    _outputs(),
    _run_prediction,
)  # fmt: skip

register_kind(PREDICTION)


# -- gear regimes of a sample: the regime_prediction kind ------------------------


def _canonical(value: Any, name: str) -> str:
    """A JSON-able mapping (arrays as lists) or its JSON text -> canonical JSON text."""
    import json

    try:
        raw = json.loads(value) if isinstance(value, str) else value
        if isinstance(raw, Mapping):
            raw = {str(k): np.asarray(v).tolist() if np.ndim(v) else v for k, v in raw.items()}
        elif isinstance(raw, (list, tuple, np.ndarray)):
            raw = [float(v) for v in np.asarray(raw, dtype=float).ravel()]
        return json.dumps(raw, sort_keys=True, allow_nan=False)
    except (TypeError, ValueError) as e:
        raise ConfigError(f"invalid {name} = {value!r}: not JSON-able ({e})") from None


#: Gear pairs' saved JSON texts by their key (what the ``gear`` column shows).
_GEARS: dict[str, str] = {}


def gear_text(value: Any) -> str:
    """A gear pair input: a preset name as it is, a ``GearPair`` (or its
    saved JSON text) as the JSON text of its saved state, remembered by
    its key."""
    import json

    if isinstance(value, str) and not value.lstrip().startswith("{"):
        return value
    native = getattr(value, "_g", None)
    if native is None and not isinstance(value, str):
        raise ConfigError(f"invalid gear = {value!r}: a thermobear.GearPair or a preset name")
    text = value if native is None else json.dumps(native.__reduce__()[1][0], sort_keys=True)
    with _LOCK:
        _GEARS[model_shown(text)] = text
    return text


def _check_gear(text: Any) -> None:
    from ..gear import GearPair

    if not str(text).lstrip().startswith("{") and text not in GearPair.preset_names():
        known = ", ".join(GearPair.preset_names())
        raise ConfigError(f"invalid gear = {text!r}: unknown; known: {known}")


def gear_of(shown: str) -> Any:
    """The ``GearPair`` of a ``gear`` column value (a preset name or the
    key of a remembered saved state)."""
    import json

    from .. import _native
    from ..gear import GearPair

    if shown in _GEARS:
        return GearPair(_native._restore(json.loads(_GEARS[shown])))
    return GearPair.preset(shown)


def _run_regimes(kind: Kind, inputs: Any, threads: Optional[int]) -> Any:
    import json

    import polars as pl

    from . import sweeps

    def solve(keys: dict, rows: Any) -> Any:
        cm, theta = _sample_of(keys, "regime_prediction")
        options = json.loads(keys["gear_options"])
        system = sweeps.regime_system(cm, theta, gear_of(keys["gear"]), options)
        sweep = np.asarray(json.loads(keys["speeds_rpm"]), dtype=float)
        labels, failed = sweeps.sweep_labels(
            {"0": system}, sweep, keys["direction"], json.loads(keys["sweep_options"])
        )
        if failed:
            raise ThermobearError(failed["0"])
        got = [labels["0"].get(float(v)) for v in rows["speed_rpm"]]
        bad = [g is None for g in got]
        return pl.DataFrame({
            "regime": got, "ok": [not b for b in bad],
            "error_kind": ["ConfigError" if b else None for b in bad],
            "error": ["invalid speed_rpm: not a speed of speeds_rpm" if b else None for b in bad],
        })  # fmt: skip

    return _grouped(kind, inputs, solve)


def _shared(name: str) -> Param:
    return PREDICTION.param(name)


REGIME_PREDICTION = Kind(
    "regime_prediction",
    "the gear regime at a speed of the sweep on a calibrated bearing model at a sample of its "
    "calibrated values",
    (
        *(_shared(n) for n in ("model", "member", "samples", "seed", "sample")),
        Param("gear", str, "seed-electric-drive", "gear pair: a preset name, or a GearPair "
              "(stored as its saved JSON)", convert=gear_text, check=_check_gear,
              show=lambda t: model_shown(t) if str(t).startswith("{") else t),
        Param("gear_options", str, "{}", "GearSystem keywords (JSON; the bearings are the "
              "model's, on the thermal schedule)", convert=lambda v: _canonical(v, "gear_options")),
        Param("sweep_options", str, "{}", "bifurcation_set keywords (JSON)",
              convert=lambda v: _canonical(v, "sweep_options")),
        Param("direction", str, "down", "sweep direction",
              check=_one_of("direction", "down", "up", "independent")),
        Param("speeds_rpm", str, "[]", "the sweep's speeds [rpm] (JSON list)",
              convert=lambda v: _canonical(v, "speeds_rpm")),
        Param("speed_rpm", float, 0.0, "pinion speed, one of speeds_rpm [rpm]", per_point=True),
    ),
    (("regime", "String"),),
    _run_regimes,
)  # fmt: skip

register_kind(REGIME_PREDICTION)


# -- the sampled band through the study engine -----------------------------------


def _what_of(spec: Any, quantities: Sequence[str]) -> str:
    """The ``what`` with the fewest quantities that holds ``quantities``."""
    fits = []
    for w in WHATS:
        try:
            got = quantities_for(spec, w)
        except ConfigError:
            continue
        if set(quantities) <= set(got):
            fits.append((len(got), w))
    return min(fits)[1] if fits else "measured"


def band_study(
    model: Any, cond: polars.DataFrame, quantities: Sequence[str], samples: int, seed: int
) -> Study:
    """The study of a sampled band: ``sample`` 0 .. ``samples`` (outermost)
    times the conditions (the product of each column's values: a superset
    when ``cond`` is not a full product), one chunk per sample."""
    if not hasattr(model, "to_json"):
        raise ConfigError(
            f"invalid model = {type(model).__name__}: the study engine needs a CalibratedModel "
            "(it travels as its saved form)"
        )
    dims: dict[str, Any] = {"sample": list(range(samples + 1))}
    for c in cond.columns:
        dims[c] = cond[c].unique(maintain_order=True).to_list()
    fixed = {"model": model, "what": _what_of(model.spec, quantities), "samples": samples,
             "seed": seed}  # fmt: skip
    per_sample = int(np.prod([len(v) for k, v in dims.items() if k != "sample"]))
    # the study is the prediction's own (its size is the samples asked for):
    # no grid cap of the Study's, which a predict caller could not raise
    size = per_sample * (samples + 1)
    return Study("prediction", dims, fixed, chunk_size=per_sample, max_points=max(size, 1))


def _raise_row(kind: Optional[str], message: Optional[str]) -> None:
    cls = getattr(errors, str(kind), ThermobearError)
    if not (isinstance(cls, type) and issubclass(cls, ThermobearError)):
        cls = ThermobearError
    raise cls(str(message))


def study_band(
    model: Any,
    cond: polars.DataFrame,
    quantities: Sequence[str],
    level: float,
    samples: int,
    seed: int,
    engine: Any,
) -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray]:
    """As ``sampling_band`` (value at the estimates, the quantile band, the
    sample standard deviation; quantity-major), every sample a chunk of a
    ``prediction`` study on ``engine`` ("local": this machine; a
    ``dask.distributed.Client`` or a scheduler address)."""
    study = band_study(model, cond, quantities, samples, seed)
    df = study.run(engine=None if engine == "local" else engine, progress=False)
    cols = list(cond.columns)
    got = cond.with_row_index("_row").join(df, on=cols, how="left").sort("sample", "_row")
    n, s = cond.height, samples + 1
    y = np.stack([got[q].to_numpy().reshape(s, n) for q in quantities], axis=1).reshape(s, -1)
    ok: np.ndarray = np.asarray(got["ok"].to_numpy().reshape(s, n).all(axis=1))
    if not ok[0]:
        bad = got.filter(~got["ok"]).row(0, named=True)
        _raise_row(bad["error_kind"], bad["error"])
    runs = [y[k] for k in range(1, s) if ok[k]]
    return sampled_quantiles(y[0], runs, int(s - 1 - len(runs)), level)


def check_engine(engine: Any) -> None:
    """``engine`` of [`predict`][thermobear.predict.band.predict]: None
    (in-process), "local", a ``dask.distributed.Client`` (checked by the
    study) or a scheduler address (``"tcp://host:port"``)."""
    if isinstance(engine, str) and engine != "local" and ":" not in engine:
        raise ConfigError(
            f"invalid engine = {engine!r}: give None (in-process), 'local' (the study engine "
            "on this machine), a dask.distributed.Client or a scheduler address"
        )


def study_labels(
    model: Any,
    sample_ids: Sequence[int],
    order: np.ndarray,
    run: tuple[Any, dict, dict, str],
    samples: int,
    seed: int,
    engine: Any,
) -> list[Any]:
    """The regime labels of samples ``sample_ids`` of ``model`` (0: the
    estimate) as a ``regime_prediction`` study on ``engine``, one chunk per
    sample's sweep over ``order`` (``run``: gear, gear options, sweep
    options, direction): per sample its labels by speed (a dict) or the
    message of its failure (a str)."""
    if not hasattr(model, "to_json"):
        raise ConfigError(
            f"invalid model = {type(model).__name__}: the study engine needs a CalibratedModel "
            "(it travels as its saved form)"
        )
    gear, gear_options, sweep_options, direction = run
    fixed = {"model": model, "samples": samples, "seed": seed, "gear": gear,
             "gear_options": gear_options, "sweep_options": sweep_options,
             "direction": direction, "speeds_rpm": order}  # fmt: skip
    dims = {"sample": list(sample_ids), "speed_rpm": order.tolist()}
    size = max(len(dims["sample"]) * len(order), 1)  # the prediction's own: no grid cap
    study = Study("regime_prediction", dims, fixed, chunk_size=len(order), max_points=size)
    df = study.run(engine=None if engine == "local" else engine, progress=False)
    out: list[Any] = []
    for (_,), rows in df.group_by(["sample"], maintain_order=True):
        if rows["ok"].all():
            out.append(dict(zip(rows["speed_rpm"].to_list(), rows["regime"].to_list(),
                                strict=True)))  # fmt: skip
        else:
            bad = rows.filter(~rows["ok"]).row(0, named=True)
            out.append(f"{bad['error_kind']}: {bad['error']}")
    return out


__all__ = [
    "PREDICTION", "REGIME_PREDICTION", "band_study", "check_engine", "model_text",
    "study_band", "study_labels",
]  # fmt: skip
