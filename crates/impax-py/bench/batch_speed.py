"""Benchmark: `resolve_batch` on 10⁶ problems against a Python loop over `resolve`.

Prints figures; asserts nothing about time (the machines are shared: a timed assertion fails
under load — it was a test, `tests/test_speed.py`, until it did). Run it with the Python of
the test stage's environment, after `bash scripts/test.d/30-python.sh` has installed the
wheel::

    .venv-ci/bin/python crates/impax-py/bench/batch_speed.py [--n 1000000] [--sample 20000] [--law energetic] [--runs 3]

The loop is the one a user writes to get the same numbers: one `impax.resolve` call per row of
the same numpy arrays, reading what the batch returns for that row (impulse, velocity after,
energy change, work split, compression impulse, verdict, phases). It is timed on a sample of
rows and extrapolated per problem. The timings are interleaved and the best of several runs of
each is kept, so that a burst of load elsewhere slows both alike. Besides the wall-clock
speed-up it prints the single-threaded one and an estimate for free cores (per-core ratio ×
cores × 0.85, a parallel efficiency below rayon's on two free cores), since on a loaded
machine the batch may not get its cores while the loop needs only one.
"""

from __future__ import annotations

import argparse
import os
import time

import numpy as np

import impax


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--n", type=int, default=1_000_000, help="problems in the batch")
    parser.add_argument("--sample", type=int, default=20_000, help="rows timed in the loop")
    parser.add_argument("--law", default="energetic")
    parser.add_argument("--runs", type=int, default=3, help="interleaved runs; the best is kept")
    args = parser.parse_args()
    n, sample, law = args.n, min(args.sample, args.n), args.law

    space = impax.study.RandomSample(
        "rod",
        n,
        {"angle": (0.1, 3.0), "direction": (-1.0, 1.0), "omega": (-1.0, 1.0), "friction": (0.0, 1.0), "restitution": (0.0, 1.0)},
        seed=5,
    )
    w, v, f, e = space.problems()
    rows = np.random.default_rng(0).choice(n, sample, replace=False)
    ws, vs, fs, es = w[rows], v[rows], f[rows], e[rows]

    def loop() -> float:
        t = time.perf_counter()
        out = []
        for i in range(sample):
            o = impax.resolve(ws[i], vs[i], fs[i], es[i], law)
            out.append((o.impulse, o.velocity_after, o.energy_change, o.work, o.compression_impulse, o.verdict, o.phases))
        return (time.perf_counter() - t) / sample

    def batch(threads: int | None = None) -> float:
        t = time.perf_counter()
        impax.resolve_batch(w, v, f, e, law, threads=threads)
        return (time.perf_counter() - t) / n

    per_row_batch, per_row_loop, one_thread = float("inf"), float("inf"), float("inf")
    for _ in range(args.runs):
        per_row_batch = min(per_row_batch, batch())
        per_row_loop = min(per_row_loop, loop())
        one_thread = min(one_thread, batch(threads=1))
    cores = len(os.sched_getaffinity(0)) if hasattr(os, "sched_getaffinity") else os.cpu_count()
    speedup = per_row_loop / per_row_batch
    per_core = per_row_loop / one_thread
    print(
        f"resolve_batch ({law}, {n} rod impacts): {1e-6 / per_row_batch:.1f} M/s "
        f"({per_row_batch * 1e9:.0f} ns per problem; 1 thread {1e-6 / one_thread:.1f} M/s; {cores} cores)\n"
        f"loop over resolve ({sample} rows): {per_row_loop * 1e6:.2f} µs per problem\n"
        f"speed-up: {speedup:.0f}× wall clock, {per_core:.0f}× per core, ≈ {per_core * cores * 0.85:.0f}× with the cores free"
    )


if __name__ == "__main__":
    main()
