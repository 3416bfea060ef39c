"""The seed papers' numbers as data: every value in the reproduction table
equals the number printed in the paper (a fixture of the quotes with their
line of origin), the files are well formed, at least a third of each
paper's numbers are held out, and a held-out number never enters a fit."""

from __future__ import annotations

import csv
import os
from pathlib import Path

import numpy as np
import polars as pl
import pytest

import thermobear as tb
from thermobear.studies import paper_numbers as pn
from thermobear.studies import reproduce_seed_a_gear as gear

ROOT = Path(__file__).resolve().parents[1]
FIXTURE = ROOT / "tests" / "data" / "seed_quotes.csv"
#: The papers' text extractions, where a developer checkout has them
#: beside the repository (CI does); the fixture's excerpts are checked
#: against their lines there.
SEEDS_DIR = Path(os.environ.get("THERMOBEAR_SEEDS_DIR", ROOT.parent / "shared" / "seeds"))
SEED_FILES = {"A": "000_4169de416354dfd4.txt", "B": "001_13a65964c3217843.txt"}


def _fixture() -> list[dict]:
    with FIXTURE.open() as f:
        return list(csv.DictReader(line for line in f if not line.startswith("#")))


def test_every_paper_value_equals_its_quote():
    fix = {r["id"]: r for r in _fixture()}
    q = pn.quotes()
    assert set(q["id"]) == set(fix), set(q["id"]) ^ set(fix)
    for r in q.iter_rows(named=True):
        f = fix[r["id"]]
        assert f["seed"] == r["seed"]
        assert r["value"] == pytest.approx(float(f["value"]), rel=1e-12), r["id"]
        # the number as printed is in the excerpt, and its digits give the value
        assert f["printed"] in f["excerpt"], r["id"]


@pytest.mark.skipif(not SEEDS_DIR.is_dir(), reason="the seed texts are not beside this checkout")
def test_every_excerpt_is_on_its_line_of_the_paper():
    texts = {s: (SEEDS_DIR / n).read_text().splitlines() for s, n in SEED_FILES.items()}
    for f in _fixture():
        line = texts[f["seed"]][int(f["line"]) - 1]
        assert f["excerpt"] in line, (f["id"], f["line"])


def test_quote_files_are_well_formed_and_a_third_is_held_out():
    for seed in pn.SEEDS:
        q = pn.quotes(seed)
        assert q.height >= 40, seed
        checked = q.filter(pl.col("role") == "checked").height
        assert checked >= q.height / 3, (seed, checked, q.height)
        assert (q["precision"] > 0).all()
        for r in q.iter_rows(named=True):
            assert pn.tolerance_abs(r["tolerance"], r["value"]) > 0, r["id"]
            assert r["note"].strip(), r["id"]


def test_bad_quote_rows_are_refused():
    df = pn.quotes("A").head(1).drop("kind").with_columns(pl.all().cast(pl.Utf8))
    with pytest.raises(tb.ConfigError, match="relation"):
        pn._checked(df.with_columns(pl.lit("sum").alias("relation")), "x.csv")
    with pytest.raises(tb.ConfigError, match="role"):
        pn._checked(df.with_columns(pl.lit("maybe").alias("role")), "x.csv")
    with pytest.raises(tb.ConfigError, match="tolerance"):
        pn.tolerance_abs("about 5", 10.0)
    assert pn.tolerance_abs("25%", -8.0) == pytest.approx(2.0)


def test_number_table_within_bounds_and_band():
    q = pn.quotes("A").filter(pl.col("id").is_in(["A14-c-p1", "A15-x-jump", "AC-t-cs"]))
    ev = pl.DataFrame(
        {"id": ["A14-c-p1", "A15-x-jump", "AC-t-cs"], "ours": [10_500.0, 7_000.0, float("nan")],
         "lower": [9_000.0, 6_900.0, float("nan")], "upper": [9_600.0, 7_100.0, float("nan")],
         "basis": ["", "", ""]},
    )  # fmt: skip
    t = pn.number_table(q, ev)
    row = {r["id"]: r for r in t.iter_rows(named=True)}
    assert row["A14-c-p1"]["within"] is True  # 856 rpm off, tolerance 1000
    assert row["A14-c-p1"]["covered"] is False  # 9644 outside 9000 .. 9600
    assert row["A15-x-jump"]["within"] is True and row["A15-x-jump"]["covered"] is None  # a bound
    assert row["AC-t-cs"]["within"] is None  # not comparable
    c = pn.counts(t, "A")
    assert c["all"] == (2, 2) and c["not comparable"] == (0, 1)


# -- the held-out rule --------------------------------------------------------------


def test_a_checked_number_never_enters_the_gear_fit(monkeypatch):
    fitted = gear.measurements("fitted")
    q = pn.quotes("A")
    checked_ids = set(q.filter(pl.col("role") == "checked")["id"])
    assert checked_ids and not checked_ids & set(fitted["run"])
    # every fitted plain value is in the fit
    plain = pn.measurement_rows(q, "fitted")
    assert set(fitted["run"]) == set(plain["id"])
    # the shipped model names exactly these rows as its data
    model = gear.fitted_gear_model()
    assert set(model.provenance["quotes"]) == set(fitted["run"])
    assert model.provenance["n_points"] == fitted.height
    # moving every checked number far away changes nothing the fit sees
    real = pn.quotes

    def moved(seed=None, kind="number"):
        df = real(seed, kind)
        return df.with_columns(
            pl.when(pl.col("role") == "checked").then(pl.col("value") + 5000.0)
            .otherwise(pl.col("value")).alias("value"),
            pl.when(pl.col("role") == "checked").then(pl.col("speed_rpm") + 5000.0)
            .otherwise(pl.col("speed_rpm")).alias("speed_rpm"),
        )  # fmt: skip

    checked_before = gear.measurements("checked")
    monkeypatch.setattr(pn, "quotes", moved)
    assert gear.measurements("fitted").equals(fitted)
    # (the checked rows did move: the patch acts)
    assert not gear.measurements("checked").equals(checked_before)


def test_the_shipped_fit_is_the_calibration_of_the_fitted_rows():
    """The shipped model is reproducible from the fitted rows alone: its
    chi^2 recomputed at its own values is the one its calibration reached,
    below the stated inputs' chi^2; its intervals hold its values."""
    from thermobear.diagnosis.gear_calibration import transition_chi2

    model = gear.fitted_gear_model()
    assert list(model.names) == list(gear.PARAMETERS)
    fitted = gear.measurements("fitted")
    values = dict(zip(model.names, model.values.tolist(), strict=True))
    chi2 = transition_chi2(model.spec, fitted, values)
    assert chi2 == pytest.approx(model.provenance["chi2"], rel=1e-9)
    stated = {"te_amplitude_um": 2.0, "mesh_damping_ratio": 0.07, "half_backlash_um": 50.0,
              "mesh_stiffness_scale": 1.0}  # fmt: skip
    assert transition_chi2(model.spec, fitted, stated) > 10.0 * chi2
    for r in model.intervals.iter_rows(named=True):
        assert r["lower"] <= r["lower_95"] <= r["value"] <= r["upper_95"] <= r["upper"], r
    cov = model.covariance
    assert np.all(np.linalg.eigvalsh(cov) >= -1e-12 * np.abs(cov).max())


def test_refitted_models_take_precedence_while_in_force(tmp_path):
    """``thermobear demo --refit`` writes its models into a folder and
    reads them from there (``paper_numbers.refitted``); outside the block,
    and for a file the folder lacks, the shipped one is read."""
    shipped = gear.fitted_gear_model()
    other = shipped.spec_at({"te_amplitude_um": 10.0})
    from thermobear.diagnosis.calibrated import CalibratedModel

    moved = CalibratedModel("calibration", "moved", shipped._base, shipped._steps,
                            [10.0, *shipped.values[1:]], shipped.covariance, shipped._profile,
                            provenance=shipped.provenance)  # fmt: skip
    moved.save(tmp_path / gear.MODEL_FILE)
    with pn.refitted(tmp_path):
        got = gear.fitted_gear_model()
        assert got.values[0] == 10.0 and got == moved
        # the bands were not refitted here: the shipped ones are read
        assert str(pn.papers_file(gear.BANDS_FILE)).endswith(gear.BANDS_FILE)
        assert not str(pn.papers_file(gear.BANDS_FILE)).startswith(str(tmp_path))
    assert gear.fitted_gear_model() == shipped
    assert other.options["te_amplitude_um"] == 10.0
