"""Step 6 of [`thermobear.diagnose`][thermobear.diagnose]: the gap before and after under
each explanation the verdict names, on every measured point.

The explanations: the accepted candidates together (or none: the
baseline); under a tie, each member added alone to what was accepted
before (and the generic control when it ties too); under "unresolved", the
known effects the data cannot tell from an unknown one, and that unknown
smooth term (the generic control: the posterior mean of the Gaussian-process
discrepancy that ``thermobear.predict`` adds). Each is calibrated on the
training points only -- never on the held-out points -- and predicts every
point: on a training point the "after" is a fit, on a held-out point an
extrapolation."""

from __future__ import annotations

from typing import Any, Sequence

import numpy as np

from .acceptance import joint_refit
from .audit import gap_table
from .candidates import Candidate
from .control import GenericControl
from .discrepancy import discrepancy_at, fit_discrepancy
from .measurements import MeasuredData
from .screening import _curve, _fit
from .setting import _predict, _Setting
from .statistics import _band_key


def calibrated_without_heldout(
    s: Any, cands: Sequence[Candidate], target: MeasuredData
) -> np.ndarray:
    """The candidates ``cands`` calibrated on the training points of the
    search's data (``s.data``; each alone in order, then together) and their
    prediction of every row of ``target``. Without held-out points the
    training points are all the points."""
    d = s.data
    train = d.train if d.held.any() else np.ones(d.n, dtype=bool)
    st, records = _Setting(), []
    for c in cands:
        cu = _curve(s.model, st, c, d.cond, d.quantity, s.base_options)
        value = 1.0 if cu is None or c.kind == "switch" else _fit(cu, d.y, d.s, train)["value"]
        st = st.apply(c, value, s.base_options)
        records.append({"value": value})
    joint = joint_refit(
        s.model, list(cands), records, d.cond, d.quantity, d.y, d.s, train, s.base_options
    )
    st = joint[0] if joint is not None else st
    return _predict(s.model, st, target.cond, target.quantity)


def explanations(s: Any) -> list[tuple[str, Any]]:
    """The explanations the verdict names: (label, candidates) for named
    effects, (label, GenericControl) for the unknown smooth one."""
    if s.unresolved is not None:
        ctrl = s.unresolved[2]
        names = " + ".join(c.name for c in s.withdrawn)
        return [(f"known: {names}", list(s.withdrawn)), (f"unknown: {ctrl.label}", ctrl)]
    if s.tie:
        by_name = {c.name: c for c in s.pool}
        out: list[tuple[str, Any]] = []
        for m in s.tie:
            if m == "generic_control" and s.tie_control is not None:
                out.append((f"tie: unknown: {s.tie_control.label}", s.tie_control))
            elif m in by_name:
                out.append((f"tie: {m}", list(s.accepted_cands) + [by_name[m]]))
        return out
    label = " + ".join(c.name for c in s.accepted_cands) or "nothing accepted (baseline)"
    return [(label, list(s.accepted_cands))]


def _control_prediction(s: Any, ctrl: GenericControl, reference: Sequence[Candidate]) -> np.ndarray:
    """The unknown smooth term on the residual of the ``reference``
    candidates (themselves calibrated without the held-out points), and its
    prediction of every kept row: the posterior mean of the model-discrepancy
    term ``thermobear.predict`` adds (a Gaussian process in speed per
    quantity, ``fit_discrepancy``) fitted on the training points only. A
    quantity with too few training speeds for a term keeps the reference."""
    d = s.data
    ref = calibrated_without_heldout(s, reference, d)
    train = d.train if d.held.any() else np.ones(d.n, dtype=bool)
    speeds = d.cond["speed_rpm"].to_numpy()
    gp = fit_discrepancy(speeds[train], d.quantity[train], (d.y - ref)[train], d.s[train])
    shift = np.zeros(d.n)
    for q in gp["terms"]:
        rows = d.quantity == q
        got = discrepancy_at(gp, q, speeds[rows])
        if got is not None:
            shift[rows] = got[0]
    return ref + shift


def explained_predictions(s: Any) -> list[tuple[str, np.ndarray]]:
    """(label, prediction of every kept row) for every explanation
    (``explanations``), each calibrated without the held-out points."""
    d = s.data
    out = []
    for label, what in explanations(s):
        if isinstance(what, GenericControl):
            reference = [] if s.unresolved is not None else list(s.accepted_cands)
            out.append((label, _control_prediction(s, what, reference)))
        else:
            out.append((label, calibrated_without_heldout(s, what, d)))
    return out


def explained_points(s: Any, preds: list[tuple[str, np.ndarray]]) -> Any:
    """The kept points once per explanation: the measured rows with
    ``explanation``, ``model_after`` (the explanation calibrated without
    the held-out points) and ``heldout``."""
    import polars as pl

    d = s.data
    return pl.concat(
        [
            d.df.with_columns(
                pl.lit(label).alias("explanation"),
                pl.Series("model_after", pred),
                pl.Series("heldout", d.held),
            )
            for label, pred in preds
        ]
    )


def explained_gap(s: Any, pred0: np.ndarray, preds: list[tuple[str, np.ndarray]]) -> Any:
    """The gap table under every explanation (``explained_predictions``)
    on every kept point: ``explanation``, ``quantity``, ``speed_band``,
    ``heldout``, ``n``, ``rms_before_sigma`` (the baseline),
    ``rms_after_sigma`` (the explanation calibrated without the held-out
    points)."""
    import polars as pl

    d = s.data
    r0 = d.residual(pred0)
    tables = []
    for i, (label, pred) in enumerate(preds):
        r1 = d.residual(pred)
        for held in (False, True):
            mask = d.held == held
            if not mask.any():
                continue
            t = gap_table(d.df, r0, r1, mask)
            tables.append(
                t.with_columns(
                    pl.lit(label).alias("explanation"),
                    pl.lit(i).alias("_order"),
                    pl.lit(held).alias("heldout"),
                    pl.col("speed_band").map_elements(_band_key, pl.Float64).alias("_band"),
                )
            )
    cols = ["explanation", "quantity", "speed_band", "heldout", "n"]
    cols += ["rms_before_sigma", "rms_after_sigma"]
    out = pl.concat(tables).sort("_order", "quantity", "_band", "heldout", maintain_order=True)
    return out.select(cols)
