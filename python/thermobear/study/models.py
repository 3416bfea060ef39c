"""A calibrated model as the ``model`` input of a study's points.

The input accepts a [`CalibratedModel`][thermobear.CalibratedModel] (or a
[`Calibration`][thermobear.Calibration] / [`Diagnosis`][thermobear.Diagnosis]
by its model), the path of a saved model or its JSON text, and stores the
model's canonical JSON text: the study's description (and its hash) holds
the model itself, so another model is another study and a Dask worker
rebuilds the model from the description alone. The input column shows the
first 16 hex digits of the text's SHA-256 (the model's key); the points
find the model by that key. ``""`` is no model."""

from __future__ import annotations

import hashlib
import threading
from pathlib import Path
from typing import TYPE_CHECKING, Any

from ..errors import ConfigError

if TYPE_CHECKING:
    from ..diagnosis.calibrated import CalibratedModel

#: Models rebuilt in this process by their key: (text, model). The latest
#: ``_KEEP`` are kept.
_MODELS: dict[str, tuple[str, CalibratedModel]] = {}
_KEEP = 64
_LOCK = threading.Lock()  # a Dask worker runs tasks in several threads


def model_key(text: str) -> str:
    """The short key of a model's JSON text (what its column shows)."""
    return hashlib.sha256(text.encode()).hexdigest()[:16]


def model_shown(text: Any) -> str:
    """What the ``model`` column shows of a stored text: its key ('' for none)."""
    return model_key(str(text)) if text else ""


def _remember(text: str, model: CalibratedModel) -> str:
    key = model_key(text)
    with _LOCK:
        if len(_MODELS) >= _KEEP and key not in _MODELS:
            _MODELS.pop(next(iter(_MODELS)))
        _MODELS[key] = (text, model)
    return text


def _from_json(text: str) -> CalibratedModel:
    from ..diagnosis.calibrated import CalibratedModel

    return CalibratedModel.from_json(text)


def model_text(value: Any) -> str:
    """The stored form of a ``model`` input: a calibrated model (or a
    [`Calibration`][thermobear.Calibration] / [`Diagnosis`][thermobear.Diagnosis]
    by its model), the path of a saved model or its JSON text -> the
    model's canonical JSON text; None or '' -> '' (no model)."""
    if value is None or (isinstance(value, str) and not value.strip()):
        return ""
    inner = getattr(value, "model", None)
    if not hasattr(value, "to_json") and hasattr(inner, "to_json"):
        value = inner
    if hasattr(value, "to_json"):
        text = value.to_json()
        return text if model_key(text) in _MODELS else _remember(text, _from_json(text))
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
    model = _from_json(raw)
    return _remember(model.to_json(), model)


def model_of(key: str) -> CalibratedModel:
    """The model of a key shown in a ``model`` column (a model of a study
    built, or rebuilt, in this process)."""
    if key not in _MODELS:
        raise ConfigError(f"invalid model = {key!r}: not a model of this study")
    return _MODELS[key][1]


__all__ = ["model_key", "model_of", "model_shown", "model_text"]
