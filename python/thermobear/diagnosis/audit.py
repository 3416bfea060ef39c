"""Step 1 and 6 of [`thermobear.diagnose`][thermobear.diagnose]: the residual audit per
quantity and speed band (mean and rms residual/sigma, the residual's
shape) and the held-out gap before/after."""

from __future__ import annotations

import numpy as np

from .statistics import _band_key, _speed_bands, residual_shape


def gap_table(df, r0, r1, mask):
    import polars as pl

    bands = _speed_bands(df["speed_rpm"].to_numpy())
    q = df["quantity"].to_numpy()
    rows = []
    for qq in sorted(set(q[mask].tolist())):
        for b in sorted(set(bands[mask & (q == qq)].tolist()), key=_band_key):
            m = mask & (q == qq) & (bands == b)
            rows.append(
                (
                    qq,
                    b,
                    int(m.sum()),
                    float(np.sqrt(np.mean(r0[m] ** 2))),
                    float(np.sqrt(np.mean(r1[m] ** 2))),
                )
            )
    return pl.DataFrame(
        rows,
        schema=["quantity", "speed_band", "n", "rms_before_sigma", "rms_after_sigma"],
        orient="row",
    )


def audit(df, r):
    import polars as pl

    sp, q = df["speed_rpm"].to_numpy(), df["quantity"].to_numpy()
    bands = _speed_bands(sp)
    rows = []
    for qq in sorted(set(q.tolist())):
        mq = q == qq
        shape, _ = residual_shape(sp[mq], r[mq])
        for b in sorted(set(bands[mq].tolist()), key=_band_key):
            m = mq & (bands == b)
            rows.append(
                (
                    qq,
                    b,
                    int(m.sum()),
                    float(np.mean(r[m])),
                    float(np.sqrt(np.mean(r[m] ** 2))),
                    shape,
                )
            )
    return pl.DataFrame(
        rows,
        schema=[
            "quantity",
            "speed_band",
            "n",
            "mean_residual_sigma",
            "rms_residual_sigma",
            "shape",
        ],
        orient="row",
    )
