"""A setting: the baseline plus applied candidates (effects switched on,
options replaced, sensor offsets), and the prediction of every measured row
under it."""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any

import numpy as np

from .candidates import Candidate
from .protocol import ModelSpec


@dataclass(frozen=True)
class _Setting:
    effects: tuple[str, ...] = ()
    options: tuple[tuple[str, Any], ...] = ()
    offsets: tuple[tuple[str, float, bool], ...] = ()  # (quantity, value, relative)

    def apply(self, c: Candidate, value: float, base_options: dict) -> "_Setting":
        opts = dict(self.options)
        if c.side == "measurement":
            return _Setting(
                self.effects, self.options, self.offsets + ((c.quantity, value, c.relative),)
            )
        if c.kind == "switch":
            if c.effect:
                return (
                    _Setting(
                        tuple(sorted(set(self.effects) | {c.effect})), self.options, self.offsets
                    )
                    if value >= 0.5
                    else self
                )
            if value < 0.5:
                return self
            opts[c.option] = c.name.split(":", 1)[1]
        else:
            # a per-level option (load scale of one level) may be new to the
            # baseline, and an unset one (None) takes its default: the
            # candidate's null value
            if c.offset:
                cur = opts.get(c.option, base_options.get(c.option))
                opts[c.option] = (c.null if cur is None else float(cur)) + value
            else:
                opts[c.option] = value
        return _Setting(self.effects, tuple(sorted(opts.items())), self.offsets)


def _predict_all(model: ModelSpec, st: _Setting, cond: Any) -> dict[str, np.ndarray]:
    """Every quantity of the model at each row of ``cond`` under a setting
    (sensor offsets applied): one model run for them all."""
    m = model.with_setting(st.effects, **dict(st.options))
    allq = m.predict(cond)
    out = {q: np.asarray(allq[q], dtype=float) for q in model.quantities}
    for q, v, rel in st.offsets:
        out[q] = out[q] * (1.0 + v) if rel else out[q] + v
    return out


def _predict(model: ModelSpec, st: _Setting, cond: Any, quantity: np.ndarray) -> np.ndarray:
    """Prediction of each measured row (its own quantity) under a setting."""
    m = model.with_setting(st.effects, **dict(st.options))
    allq = m.predict(cond)
    y = np.empty(len(quantity))
    for q in np.unique(quantity):
        rows = quantity == q
        y[rows] = allq[q][rows]
    for q, v, rel in st.offsets:
        rows = quantity == q
        y[rows] = y[rows] * (1.0 + v) if rel else y[rows] + v
    return y
