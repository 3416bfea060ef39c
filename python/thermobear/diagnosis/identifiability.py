"""Step 2 of [`thermobear.diagnose`][thermobear.diagnose]: identifiability. Each candidate's
fingerprint, pairwise cosine similarity, look-alike pairs and the extra
measurement that tells two look-alikes apart."""

from __future__ import annotations

import numpy as np

from .setting import _predict_all
from .statistics import _cosine


def envelope_grid(df, envelope=None):
    """Operating points to consider for an extra measurement: 8 speeds over
    the measured speed range (or ``envelope["speed_rpm"]`` = (lo, hi), a
    range the user declares reachable) at each measured load (or at the
    ends of ``envelope["axial_n"]`` = (lo, hi)) -- never outside the range
    the data or the user vouch for."""
    import polars as pl

    env = envelope or {}
    sp = df["speed_rpm"].to_numpy()
    lo, hi = env.get("speed_rpm", (float(sp.min()), float(sp.max())))
    speeds = np.linspace(float(lo), float(hi), 8)
    if "axial_n" in env:
        r0 = float(df["radial_n"][0])
        loads = [(float(a), r0) for a in sorted(set(map(float, env["axial_n"])))]
    else:
        pairs = zip(df["axial_n"].to_list(), df["radial_n"].to_list(), strict=False)
        loads = sorted(set(pairs))
    return pl.DataFrame(
        {
            "speed_rpm": np.tile(speeds, len(loads)),
            "axial_n": np.repeat([a for a, _ in loads], len(speeds)),
            "radial_n": np.repeat([r for _, r in loads], len(speeds)),
        }
    )


def _response(model, st, c, cond, base_options) -> dict:
    """d prediction / d parameter of every supported quantity at ``cond``
    (a switch: on - off)."""
    step = 1.0 if c.kind == "switch" else 0.05 * (c.upper - c.lower)
    v0 = 0.0 if c.kind == "switch" else c.null
    v1 = v0 + step if v0 + step <= c.upper else v0 - step
    p0 = _predict_all(model, st.apply(c, v0, base_options), cond)
    p1 = _predict_all(model, st.apply(c, v1, base_options), cond)
    return {q: (p1[q] - p0[q]) / (v1 - v0) for q in model.quantities}


def suggest_measurement(model, st, ca, cb, fa, fb, df, base_options, envelope=None):
    """Quantity, speed and axial load where two look-alike fingerprints (b
    scaled to match a on the measured rows) differ most, over all supported
    quantities inside the operating envelope (``envelope_grid``), in
    units of the typical uncertainty: (quantity, speed_rpm, axial_n); three
    Nones when no quantity separates them (a failed prediction)."""
    from ..errors import ThermobearError

    cond = envelope_grid(df, envelope)
    try:
        ra = _response(model, st, ca, cond, base_options)
        rb = _response(model, st, cb, cond, base_options)
    except ThermobearError:
        return None, None, None
    scale = float(fa @ fb / (fb @ fb)) if fb @ fb > 0 else 0.0
    best = -1.0
    where: tuple[str | None, float | None, float | None] = (None, None, None)
    table = model.quantities
    every = _predict_all(model, st, cond)
    for q in table:
        typ, rel = table[q][3], table[q][4]
        base = every[q]
        sig = np.abs(base) * typ if rel else np.full(cond.height, typ)
        d = np.abs(ra[q] - scale * rb[q]) / np.maximum(sig, 1e-300)
        i = int(np.argmax(d))
        if d[i] > best:
            best, where = float(d[i]), (q, float(cond["speed_rpm"][i]), float(cond["axial_n"][i]))
    return where


def identifiability(
    model, st, curves, data, base_options, lookalike_cosine, suggest, envelope=None
):
    """Fingerprints of the candidates around the setting ``st`` (each
    curve's slope over sigma on the measured rows): the pairwise cosine
    table (``a``, ``b``, ``cosine``) and the look-alike pairs (|cos| >
    ``lookalike_cosine``) with the quantity and speed that separate them
    best inside the operating envelope (``suggest_measurement``, when
    ``suggest``; null ``suggest_*`` columns when not asked for or none
    separates them)."""
    import polars as pl

    fp = {n: cu.slope() / data.s for n, cu in curves.items()}
    names = list(fp)
    pairs, la = [], []
    for i, a in enumerate(names):
        for b in names[i + 1 :]:
            cs = _cosine(fp[a], fp[b])
            pairs.append((a, b, cs))
            if abs(cs) > lookalike_cosine:
                where: tuple = (None, None, None)
                if suggest:
                    ca, cb = curves[a].cand, curves[b].cand
                    where = suggest_measurement(
                        model, st, ca, cb, fp[a], fp[b], data.df, base_options, envelope
                    )
                la.append((a, b, cs, *where))
    fingerprints = pl.DataFrame(pairs, schema=["a", "b", "cosine"], orient="row")
    lookalikes = pl.DataFrame(
        la,
        schema={
            "a": pl.Utf8,
            "b": pl.Utf8,
            "cosine": pl.Float64,
            "suggest_quantity": pl.Utf8,
            "suggest_speed_rpm": pl.Float64,
            "suggest_axial_n": pl.Float64,
        },
        orient="row",
    )
    return fingerprints, lookalikes
