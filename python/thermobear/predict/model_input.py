"""What a prediction is given: the calibrated model behind a
``Calibration`` or ``Diagnosis`` and the conditions it was calibrated at."""

from __future__ import annotations

from typing import Any

from ..errors import ConfigError


def as_calibrated(model: Any) -> Any:
    """The calibrated model of ``model``: a ``CalibratedModel`` (anything
    with ``spec_at``) as it is, a [`Calibration`][thermobear.Calibration]
    or [`Diagnosis`][thermobear.Diagnosis] by its ``model``."""
    if hasattr(model, "spec_at") and hasattr(model, "spec"):
        return model
    inner = getattr(model, "model", None)
    if inner is not None and hasattr(inner, "spec_at"):
        return inner
    raise ConfigError(
        f"invalid model = {type(model).__name__}: give a calibrated model (Calibration.model, "
        "Diagnosis.model)"
    )


def measured_conditions(model: Any) -> Any:
    """The conditions the calibrated model was calibrated at, when it
    carries them (a ``conditions`` frame or the ``points`` of its
    calibration), else None."""
    for attr in ("conditions", "points"):
        df = getattr(model, attr, None)
        if df is not None and hasattr(df, "columns") and "speed_rpm" in df.columns:
            return df
    prov = getattr(model, "provenance", None) or {}
    got = prov.get("conditions") if isinstance(prov, dict) else None
    return got if got is not None and hasattr(got, "columns") else None
