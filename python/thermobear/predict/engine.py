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

import hashlib
import threading
from pathlib import Path
from typing import TYPE_CHECKING, Any, Optional, Sequence

import numpy as np

from .. import errors
from ..diagnosis.calibrated import CalibratedModel
from ..diagnosis.protocol import MODEL_KINDS
from ..errors import ConfigError, ThermobearError
from ..study import Study
from ..study.kinds import Kind, Param, _grouped, _one_of, register_kind
from .conditions import WHATS, condition_columns, is_spindle, quantities_for
from .uncertainty import parameters_of, sampled_quantiles, sobol_points

if TYPE_CHECKING:
    import polars

#: Models rebuilt in this process by the key of their JSON text (the first
#: 16 hex digits of its SHA-256): (text, model). The latest ``_KEEP`` are kept.
_MODELS: dict[str, tuple[str, CalibratedModel]] = {}
_KEEP = 64
_LOCK = threading.Lock()  # a Dask worker runs tasks in several threads

#: Sobol points by (model key, member, samples, seed).
_POINTS: dict[tuple[str, str, int, int], np.ndarray] = {}


def model_key(text: str) -> str:
    """The short key of a model's JSON text (what its column shows)."""
    return hashlib.sha256(text.encode()).hexdigest()[:16]


def _remember(text: str, model: CalibratedModel) -> str:
    key = model_key(text)
    with _LOCK:
        if len(_MODELS) >= _KEEP and key not in _MODELS:
            _MODELS.pop(next(iter(_MODELS)))
        _MODELS[key] = (text, model)
    return text


def model_text(value: Any) -> str:
    """The stored form of a ``model`` input: a calibrated model (or a
    [`Calibration`][thermobear.Calibration] / [`Diagnosis`][thermobear.Diagnosis]
    by its model), the path of a saved model or its JSON text -> the
    model's canonical JSON text."""
    inner = getattr(value, "model", None)
    if not hasattr(value, "to_json") and hasattr(inner, "to_json"):
        value = inner
    if hasattr(value, "to_json"):
        text = value.to_json()
        return (
            text if model_key(text) in _MODELS else _remember(text, CalibratedModel.from_json(text))
        )
    if isinstance(value, Path) or (isinstance(value, str) and not value.lstrip().startswith("{")):
        try:
            raw = Path(value).read_text()
        except OSError as e:
            raise ConfigError(f"invalid model = {str(value)!r}: cannot read: {e}") from None
    elif isinstance(value, str):
        raw = value
    else:
        raise ConfigError(
            f"invalid model = {type(value).__name__}: give a calibrated model, the path of its "
            "saved file or its JSON text"
        )
    if model_key(raw) in _MODELS:
        return raw
    model = CalibratedModel.from_json(raw)
    return _remember(model.to_json(), model)


def _model_of(key: str) -> CalibratedModel:
    if key not in _MODELS:
        raise ConfigError(f"invalid model = {key!r}: not a model of this study")
    return _MODELS[key][1]


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


def _run_prediction(kind: Kind, inputs: Any, threads: Optional[int]) -> Any:
    import polars as pl

    def solve(keys: dict, rows: Any) -> Any:
        if not keys["model"]:
            raise ConfigError("invalid model = '': a prediction study needs a model")
        cm = _member_of(_model_of(keys["model"]), keys["member"])
        at = (keys["model"], keys["member"], keys["samples"], keys["seed"])
        theta = sample_values(cm, at, keys["sample"])
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
            show=lambda text: model_key(str(text)) if text else "",
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
    return Study("prediction", dims, fixed, chunk_size=per_sample)


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


__all__ = ["PREDICTION", "band_study", "check_engine", "model_text", "study_band"]
