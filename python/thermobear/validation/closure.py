"""What closes each gap: every screened candidate of a diagnosis, applied
alone at its calibrated value, and the largest |model - value| / sigma it
leaves per quantity (all points, held-out ones included)."""

from __future__ import annotations

from typing import TYPE_CHECKING, Any

import numpy as np

from ..diagnosis import Diagnosis
from ..diagnosis.candidates import candidate_pool
from ..diagnosis.measurements import load_measurements
from ..diagnosis.setting import _predict, _Setting

if TYPE_CHECKING:
    import polars


def closure_table(model: Any, measured: Any, d: Diagnosis) -> polars.DataFrame:
    """Rows ``candidate, value, quantity, max_abs_sigma`` for the baseline
    (candidate ``"baseline"``) and each candidate of the first screening
    round applied alone at its calibrated value; ``closes``: max <= 2."""
    import polars as pl

    df = load_measurements(measured, model.quantities)
    q = df["quantity"].to_numpy()
    y, s = df["value"].to_numpy(), df["sigma"].to_numpy()
    # a spindle's measurements keep their preload as ``preload_n``
    names = ("speed_rpm", "axial_n", "preload_n", "radial_n")
    cond = df.select([c for c in names if c in df.columns])
    pool = {c.name: c for c in candidate_pool(model, q, None)}
    rows = _rows("baseline", float("nan"), _predict(model, _Setting(), cond, q), y, s, q)
    table = d.screening[0] if d.screening else pl.DataFrame()
    for r in table.iter_rows(named=True) if table.height else ():
        c = pool.get(r.get("candidate", ""))
        if c is None or r.get("value") is None:  # a tie-only or unevaluated row
            continue
        st = _Setting().apply(c, float(r["value"]), dict(model.options))
        rows += _rows(c.name, float(r["value"]), _predict(model, st, cond, q), y, s, q)
    return pl.DataFrame(rows).with_columns((pl.col("max_abs_sigma") <= 2.0).alias("closes"))


def _rows(name: str, value: float, pred: np.ndarray, y: np.ndarray, s: np.ndarray, q: Any) -> list:
    out = []
    for qq in sorted(set(q.tolist())):
        m = q == qq
        out.append(
            {
                "candidate": name,
                "value": value,
                "quantity": qq,
                "max_abs_sigma": float(np.max(np.abs((pred[m] - y[m]) / s[m]))),
            }
        )
    return out


def unclosed(closure: polars.DataFrame) -> list[str]:
    """The quantities no single candidate brings within 2 sigma, each with
    the candidate that comes closest: "quantity (best: name, z sigma)"."""
    import polars as pl

    out = []
    for qq in sorted(set(closure["quantity"].to_list())):
        sub = closure.filter(pl.col("quantity") == qq).sort("max_abs_sigma")
        if not sub["closes"].any():
            out.append(f"{qq} (best: {sub['candidate'][0]}, {sub['max_abs_sigma'][0]:.3g} sigma)")
    return out
