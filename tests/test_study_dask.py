"""A study on a Dask cluster (two worker processes, one thread each) gives
the local result bit for bit, resumes like a local one, and reports
progress as the chunks complete."""

from __future__ import annotations

import pytest
from polars.testing import assert_frame_equal

import thermobear as tb

distributed = pytest.importorskip("dask.distributed")


@pytest.fixture(scope="module")
def cluster():
    with distributed.LocalCluster(
        n_workers=2, processes=True, threads_per_worker=1, dashboard_address=":0"
    ) as c:
        yield c


def _study() -> tb.Study:
    return tb.Study(
        "thermal",
        {
            "bearing": ["6208", "7008C-hybrid"],
            "speed_rpm": {"start": 3000, "stop": 15000, "num": 4},
            "axial_n": [300, 700],
            "housing_material": ["aluminium", "cast-iron"],
        },
        {"radial_n": 250.0},
        chunk_size=4,
    )


def test_cluster_equals_local_bit_for_bit(cluster, tmp_path, capsys):
    local = _study().run(progress=False)
    with distributed.Client(cluster) as client:
        s = _study()
        remote = s.run(tmp_path, engine=client, progress=True)
    assert_frame_equal(remote, local)
    assert (s.report.computed, s.report.reused) == (8, 0)
    err = capsys.readouterr().err
    assert "thermal study" in err and "32/32" in err


def test_cluster_by_address_resumes_an_interrupted_study(cluster, tmp_path):
    done = []

    def stop(index, frame):
        done.append(index)
        if len(done) == 3:
            raise KeyboardInterrupt

    s = _study()
    with pytest.raises(KeyboardInterrupt):
        s.run(tmp_path, engine=cluster.scheduler_address, progress=False, on_chunk=stop)
    assert s.report.computed == 3
    again = _study()
    df = again.run(tmp_path, engine=cluster.scheduler_address, progress=False)
    assert (again.report.computed, again.report.reused) == (5, 3)
    assert_frame_equal(df, _study().run(progress=False))
