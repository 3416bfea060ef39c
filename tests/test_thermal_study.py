"""The seed A thermal demo study (quick mode) writes its tables and figures."""

import polars as pl

from thermobear.studies.demo import STUDIES, study_function
from thermobear.studies.seed_a_thermal import study_seed_a_thermal


def test_seed_a_thermal_study(tmp_path):
    assert study_function(dict(STUDIES)["seed_a_thermal"]) is study_seed_a_thermal
    files = study_seed_a_thermal(tmp_path, quick=True)
    assert all(f.exists() for f in files)
    t = pl.read_parquet(tmp_path / "paper_vs_thermobear_seed_a.parquet")
    assert {"quantity", "condition", "paper_value", "paper_unit", "thermobear_value"} <= set(
        t.columns
    )
    # Table 1: Pd = 0.04 mm gives a0 = 14.8351 deg (seed A).
    row = t.filter(pl.col("quantity") == "free contact angle")
    assert abs(float(row["thermobear_value"][0]) - 14.8351) < 5e-4
    # Heat and node temperatures rise with speed at every preload (Fig. 6, 8a).
    heat = pl.read_parquet(tmp_path / "seed_a_heat_vs_speed.parquet")
    for _, g in heat.group_by(["case", "preload_n"]):
        assert g.sort("speed_rpm")["heat_w"].diff().drop_nulls().min() > 0
