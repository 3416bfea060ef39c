"""The seed B spindle demo study in quick mode: files written and the
paper-vs-thermobear table complete and self-consistent."""

from __future__ import annotations

import math
from pathlib import Path

import polars as pl
import pytest

from thermobear.studies.demo import STUDIES, study_function


def test_seed_b_spindle_study_quick(tmp_path: Path) -> None:
    fn = study_function(dict(STUDIES)["seed_b_spindle"])
    files = fn(tmp_path, True)
    assert all(f.exists() for f in files)
    assert any(f.name == "seed_b_fig04_transient.png" for f in files)
    t = pl.read_parquet(tmp_path / "paper_vs_thermobear_seed_b.parquet")
    assert t.columns == [
        "quantity",
        "condition",
        "paper_value",
        "paper_unit",
        "thermobear_value",
        "note",
    ]
    assert t.height >= 26
    assert all(math.isfinite(v) for v in t["thermobear_value"])
    assert all(len(n) > 10 for n in t["note"])

    def ours(q: str, cond: str) -> float:
        r = t.filter((pl.col("quantity") == q) & (pl.col("condition") == cond))
        return float(r["thermobear_value"][0])

    # Si3N4 balls expand less than steel balls (seed B Fig. 8).
    assert ours("radial thermal displacement, Si3N4 balls", "7009C, 18,000 rpm") < ours(
        "radial thermal displacement, steel balls", "7009C, 18,000 rpm"
    )
    # Compensation preload is k_s times the axial growth, k_s the spring rate
    # of the fitted spindle (pinned by seed B's 12.74 N at 18,000 rpm).
    from thermobear.studies.reproduce_seed_b import fitted_spindle

    k_s = fitted_spindle().spec.options["spring_rate_n_per_um"]
    for n in ("12000", "15000", "18000"):
        growth = ours("axial thermal growth", f"{n} rpm")
        assert ours("compensation preload", f"{n} rpm") == pytest.approx(k_s * growth, rel=1e-9)
