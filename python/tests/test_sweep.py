"""The sweep example: threads and a Dask LocalCluster (2 workers) give exactly the serial run."""

import json

import pytest

from cablenav import sweep
from conftest import ROOT

BASE = json.loads((ROOT / "static" / "scenarios" / "cdpr7-box.json").read_text())


@pytest.fixture(scope="module")
def designs():
    return sweep.layouts(BASE, 240, spread=0.4, seed=7)


@pytest.fixture(scope="module")
def serial(designs):
    return sweep.run_serial(designs)


def test_layouts_are_reproducible_and_varied(designs):
    assert designs == sweep.layouts(BASE, 240, spread=0.4, seed=7)
    assert designs[0]["robot"] == BASE["robot"]
    anchors = {json.dumps([c["base"] for c in d["robot"]["cables"]]) for d in designs}
    assert len(anchors) == 240


def test_serial_results_are_meaningful(serial):
    assert [r["name"] for r in serial[:2]] == ["layout-0000", "layout-0001"]
    assert all(0.0 <= r["score"] <= 1.0 for r in serial)
    assert set(serial[0]["trajectories"]) == {t["name"] for t in BASE["trajectories"]}
    # The layouts differ in what they allow: not every design scores the same.
    assert len({round(r["score"], 9) for r in serial}) > 10
    ranked = sweep.rank(serial)
    assert ranked[0][0] == max(r["score"] for r in serial)


def test_threads_equal_serial(designs, serial):
    assert sweep.run_threads(designs, workers=2) == serial


def test_dask_local_cluster_equals_serial(designs, serial):
    distributed = pytest.importorskip("dask.distributed")
    with distributed.LocalCluster(n_workers=2, threads_per_worker=1, processes=True, dashboard_address=None) as cluster:
        with distributed.Client(cluster) as client:
            assert len(client.scheduler_info()["workers"]) == 2
            assert sweep.run_dask(designs, client) == serial


def test_command_line(capsys):
    sweep.main([str(ROOT / "static" / "scenarios" / "cdpr7-box.json"), "--designs", "30", "--workers", "2", "--top", "3"])
    out = capsys.readouterr().out
    assert out.startswith("30 designs × 2 trajectories verified exactly")
    assert out.count("layout-") == 3
