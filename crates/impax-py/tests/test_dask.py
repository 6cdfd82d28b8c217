"""Sweeps on Dask: a LocalCluster with 2 worker processes gives results identical to the
single-process batch (counts, maps, Parquet partitions), through a Client and through the
scheduler's address alike."""

from __future__ import annotations

import numpy as np
import pytest

import impax
import impax.dask

import distributed

RANGES = {
    "angle": (0.05, 3.09),
    "direction": (-1.2, 1.2),
    "omega": (-3.0, 3.0),
    "friction": (0.0, 2.0),
    "restitution": (0.0, 1.0),
}


@pytest.fixture(scope="module")
def cluster():
    with distributed.LocalCluster(
        n_workers=2, threads_per_worker=1, processes=True, dashboard_address=None, silence_logs=40
    ) as c:
        yield c


def test_local_cluster_equals_single_process_batch(cluster, tmp_path):
    space = impax.study.RandomSample("rod", 150_000, RANGES, seed=7)
    w, v, f, e = space.problems()
    ref = impax.resolve_batch(w, v, f, e, "whittaker", on_invalid="mark")
    counts = np.bincount(ref["status"], minlength=len(impax.STATUSES))
    with distributed.Client(cluster) as client:
        r = impax.dask.sweep(space, "whittaker", chunk_size=1 << 14, client=client, map="energy_change", threads=1)
    assert r.workers == 2 and r.chunks == 10
    assert np.array_equal(r.summary.counts, counts)
    assert np.array_equal(r.map, ref["energy_change"], equal_nan=True)
    # Some points separate (invalid), some gain energy, some break down: all counted.
    assert r.summary.count("invalid") > 0 and r.summary.energy_gained > 0 and r.summary.count("breakdown") > 0
    assert r.summary.energy_gain_fraction == ref["energy_gained"].sum() / (ref["status"] != 4).sum()
    # The same through the scheduler's address (as for a remote cluster), with Parquet output.
    pq = pytest.importorskip("pyarrow.parquet")
    out = tmp_path / "parts"
    r2 = impax.dask.sweep(
        space, "whittaker", chunk_size=1 << 15, client=cluster.scheduler_address, map="status", parquet=str(out), threads=1
    )
    assert np.array_equal(r2.map, ref["status"])
    assert np.array_equal(r2.summary.counts, counts)
    assert [p.rsplit("/", 1)[1] for p in r2.files] == [f"part-{k:06d}.parquet" for k in range(5)]
    table = pq.ParquetDataset(r2.files).read() if hasattr(pq, "ParquetDataset") else None
    import pyarrow as pa

    table = pa.concat_tables([pq.read_table(p) for p in r2.files])
    assert table.num_rows == len(space)
    assert np.array_equal(table["energy_change"].to_numpy(), ref["energy_change"], equal_nan=True)
    assert np.array_equal(table["p_n"].to_numpy(), ref["impulse"][:, 1], equal_nan=True)
    assert np.array_equal(table["angle"].to_numpy(), space.params(0, len(space))["angle"])
    assert table["status"].to_pylist()[:50] == [impax.STATUSES[s] for s in ref["status"][:50]]


def test_grid_map_on_cluster_equals_local_run(cluster):
    grid = impax.study.Grid(
        "sphere",
        {"alpha": np.radians(np.linspace(0, 89, 90)), "spin_ratio": np.linspace(-3, 3, 121)},
        fixed={"friction": 0.4, "restitution": 0.7},
    )
    local = impax.study.run(grid, "whittaker", chunk_size=1000, map="energy_gained")
    with distributed.Client(cluster) as client:
        remote = impax.dask.sweep(grid, "whittaker", chunk_size=777, client=client, map="energy_gained")
        # With a default client, client=None uses it.
        default = impax.dask.sweep(grid, "whittaker", chunk_size=5000, map="energy_gained")
    assert remote.map.shape == (90, 121)
    assert np.array_equal(remote.map, local.map) and np.array_equal(default.map, local.map)
    assert np.array_equal(remote.summary.counts, local.summary.counts)
    # The map is paper A's: at α = 30° Whittaker gains energy for −1.2058 < γ < 0.2058 (eq. 13).
    gamma = np.linspace(-3, 3, 121)
    row = remote.map[30]
    assert np.array_equal(row, (gamma > -1.2058) & (gamma < 0.2058) & (np.abs(gamma + 0.5) > 1e-9))


def test_sweep_without_cluster_runs_in_process():
    space = impax.study.RandomSample("rod", 10_000, RANGES, seed=1)
    a = impax.dask.sweep(space, "energetic", chunk_size=3000)
    b = impax.study.run(space, "energetic", chunk_size=4096)
    assert a.workers == 0 and np.array_equal(a.summary.counts, b.summary.counts)
    assert a.summary.energy_gained == 0
