"""Step 2 of :func:`thermobear.diagnose`: identifiability. Each candidate's
fingerprint, pairwise cosine similarity, look-alike pairs and the extra
measurement that tells two look-alikes apart."""

from __future__ import annotations

import numpy as np

from .setting import _predict
from .statistics import _cosine


def suggest_measurement(model, st, ca, cb, fa, fb, df, base_options):
    """Quantity and speed where two look-alike fingerprints (b scaled to
    match a on the measured rows) differ most, over all supported
    quantities on a speed grid, in units of the typical uncertainty."""
    import polars as pl

    sp = df["speed_rpm"].to_numpy()
    grid = np.linspace(sp.min(), sp.max() * 1.25, 8)
    cond = pl.DataFrame(
        {
            "speed_rpm": grid,
            "axial_n": [float(df["axial_n"][0])] * 8,
            "radial_n": [float(df["radial_n"][0])] * 8,
        }
    )

    table = model.quantities

    def response(c):
        step = 1.0 if c.kind == "switch" else 0.05 * (c.upper - c.lower)
        v0 = 0.0 if c.kind == "switch" else c.null
        v1 = v0 + step if v0 + step <= c.upper else v0 - step
        out = {}
        for q in table:
            qa = np.array([q] * len(grid))
            p0 = _predict(model, st.apply(c, v0, base_options), cond, qa)
            p1 = _predict(model, st.apply(c, v1, base_options), cond, qa)
            out[q] = (p1 - p0) / (v1 - v0)
        return out

    from ..errors import ThermobearError

    try:
        ra, rb = response(ca), response(cb)
    except ThermobearError:
        return "", float("nan")
    scale = float(fa @ fb / (fb @ fb)) if fb @ fb > 0 else 0.0
    best, where = -1.0, ("", float("nan"))
    for q in table:
        typ, rel = table[q][3], table[q][4]
        base = _predict(model, st, cond, np.array([q] * len(grid)))
        sig = np.abs(base) * typ if rel else np.full(len(grid), typ)
        d = np.abs(ra[q] - scale * rb[q]) / np.maximum(sig, 1e-300)
        i = int(np.argmax(d))
        if d[i] > best:
            best, where = float(d[i]), (q, float(grid[i]))
    return where


def identifiability(model, st, curves, data, base_options, lookalike_cosine, suggest):
    """Fingerprints of the candidates around the setting ``st`` (each
    curve's slope over sigma on the measured rows): the pairwise cosine
    table (``a``, ``b``, ``cosine``) and the look-alike pairs (|cos| >
    ``lookalike_cosine``) with the quantity and speed that separate them
    best (:func:`suggest_measurement`, when ``suggest``)."""
    import polars as pl

    fp = {n: cu.slope() / data.s for n, cu in curves.items()}
    names = list(fp)
    pairs, la = [], []
    for i, a in enumerate(names):
        for b in names[i + 1 :]:
            cs = _cosine(fp[a], fp[b])
            pairs.append((a, b, cs))
            if abs(cs) > lookalike_cosine:
                q, v = ("", float("nan"))
                if suggest:
                    ca, cb = curves[a].cand, curves[b].cand
                    q, v = suggest_measurement(
                        model, st, ca, cb, fp[a], fp[b], data.df, base_options
                    )
                la.append((a, b, cs, q, v))
    fingerprints = pl.DataFrame(pairs, schema=["a", "b", "cosine"], orient="row")
    lookalikes = pl.DataFrame(
        la,
        schema={
            "a": pl.Utf8,
            "b": pl.Utf8,
            "cosine": pl.Float64,
            "suggest_quantity": pl.Utf8,
            "suggest_speed_rpm": pl.Float64,
        },
        orient="row",
    )
    return fingerprints, lookalikes
