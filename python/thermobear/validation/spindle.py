"""The spindle sets (seed B's quoted numbers): the seed ceramic spindle with
every effect on except the magnetic pull (an assumption about the motor,
off by default in the registry), diagnosed with :func:`thermobear.diagnose`
on the set's points with the runs of ``[calibration] holdout_runs`` held
out; the closure table says what closes each quantity's gap."""

from __future__ import annotations

import time

from ..diagnosis import SpindleModelSpec, diagnose
from ..spindle import Spindle
from .closure import closure_table, unclosed
from .result import SetResult
from .sets import points_frame


def seed_b_baseline(preset: str = "seed-ceramic-spindle") -> SpindleModelSpec:
    """The spindle baseline of the seed B sets: every effect except
    ``unbalanced_magnetic_pull``."""
    from .. import _native

    eff = [n for n, *_ in _native.effects() if n != "unbalanced_magnetic_pull"]
    return SpindleModelSpec(Spindle.preset(preset), effects=eff)


def run_spindle(data: dict) -> SetResult:
    """Validate a spindle set (module doc)."""
    import polars as pl

    t0 = time.perf_counter()
    pts = points_frame(data)
    measured = pts.select("speed_rpm", "preload_n", "quantity", "value", "sigma", "run")
    model = seed_b_baseline(data["geometry"]["spindle_preset"])
    held = list(data.get("calibration", {}).get("holdout_runs", []))
    d = diagnose(model, measured, holdout=held or None)
    closure = closure_table(model, measured, d)
    pool = {c.name: c for c in model.candidate_list(sorted(set(pts["quantity"].to_list())))}
    cal = [
        {
            "name": a["name"],
            "value": float(a["value"]),
            "lower": pool[a["name"]].lower,
            "upper": pool[a["name"]].upper,
            "unit": a["unit"],
        }
        for a in d.accepted
    ]
    p = d.points
    frame = p.select("quantity", "value", "sigma", "model_before", "model_after", "heldout")
    frame = frame.with_columns(
        pl.format("{}@{} rpm", p["quantity"], p["speed_rpm"].cast(pl.Int64)).alias("label"),
        pts["origin"].alias("origin"),
    )
    res = SetResult(
        data["name"],
        data["title"],
        data["source"]["citation"],
        frame,
        d.verdict,
        cal,
        holdout="held out (not used for calibration): runs " + ", ".join(held),
        tables={
            "closure": closure,
            "screening": d.screening[0] if d.screening else None,
            "reference": reference_table(data, model),
        },
        notes=list(d.notes) + [d.summary()],
    )
    gaps = unclosed(closure)
    if not res.passes:
        res.missing = (
            "no single candidate closes these quantities' gaps within 2 sigma: " + "; ".join(gaps)
            if gaps
            else "the accepted calibration leaves held-out points above 2 sigma"
        )
    res.seconds = time.perf_counter() - t0
    return res


def reference_table(data: dict, model: SpindleModelSpec) -> "polars.DataFrame":  # noqa: F821
    """The set's ``[[reference]]`` values (the paper's model, not
    measurements) beside the baseline's value of the named
    :meth:`thermobear.Spindle.thermal_state` column; not calibrated."""
    import polars as pl

    rows = []
    for r in data.get("reference", []):
        sp = model.configured(float(r["preload_n"]))
        got = float(sp.thermal_state(float(r["speed_rpm"]))[r["column"]][0])
        rows.append(
            {"reference": r["name"], "paper": float(r["value"]), "thermobear": got,
             "ratio": got / float(r["value"])}
        )  # fmt: skip
    return pl.DataFrame(rows) if rows else pl.DataFrame()
