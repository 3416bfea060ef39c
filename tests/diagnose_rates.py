"""Shared helpers of the diagnosis rate tests on the real models: the
outcome of one diagnosis for a hidden candidate, its 95 % interval, the
size of an effect at the top speed, and the run over seeds."""

from __future__ import annotations

from typing import Callable

import numpy as np
import polars as pl

import thermobear as tb
from thermobear import diagnosis as D


def outcome(d, name) -> str:
    """ "right" (``name`` alone accepted), "tie" (in the tie set or the
    unresolved list), "wrong" (another name accepted) or "silent"."""
    names = [a["name"] for a in d.accepted]
    if names == [name]:
        return "right"
    if name in d.tie or name in [a["name"] for a in d.unresolved]:
        return "tie"
    return "wrong" if names else "silent"


def interval(d, name):
    """The 95 % interval of ``name`` as accepted, as a tie member or as an
    unresolved candidate; None when it has none."""
    for a in d.accepted + d.unresolved:
        if a["name"] == name:
            return a["lower_95"], a["upper_95"]
    if d.ties is not None and name in d.ties["candidate"].to_list():
        row = d.ties.filter(pl.col("candidate") == name).row(0, named=True)
        return row["lower_95"], row["upper_95"]
    return None


def top_speed_sigma_real(truth, base, cond) -> float:
    """The largest |truth - baseline| / typical sigma at the top speed."""
    pt, pb = truth.predict(cond), base.predict(cond)
    q = cond["quantity"].to_list()
    top = cond["speed_rpm"].to_numpy() == cond["speed_rpm"].max()
    sig = D.typical_sigma(base.quantities, q, np.array([pb[qq][i] for i, qq in enumerate(q)]))
    return max(abs(pt[q[i]][i] - pb[q[i]][i]) / sig[i] for i in np.flatnonzero(top))


def hidden_runs(base, measured: Callable[[int], pl.DataFrame], name, value, seeds):
    """Diagnose ``base`` against ``measured(seed)`` for every seed: (the
    outcomes for ``name``, how many of its intervals cover ``value``, how
    many intervals there were)."""
    out, covered, n = [], 0, 0
    for s in seeds:
        d = tb.diagnose(base, measured(s), suggest=False)
        out.append(outcome(d, name))
        iv = interval(d, name)
        if iv is not None:
            n += 1
            covered += iv[0] <= value <= iv[1]
    return out, covered, n
