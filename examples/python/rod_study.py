"""How often does Whittaker's rule gain energy when a rod strikes the ground?

A small study with impax's Python bindings: N random rods (uniform, m = 1, L = 1) strike a
fixed surface with their lower end — the rod at an angle θ ∈ (5°, 175°) from the surface, its
centre moving at speed 1 in a direction d ∈ (−60°, 60°) from the downward normal, spinning at
ω ∈ (−3, 3) rad/s, with μ ∈ (0, 1) and e ∈ (0, 1) — and we count the impacts whose kinetic
energy rises under `whittaker` (Newton restitution with Coulomb friction on the total
impulses, paper A eq. 7: Kane's paradox). States whose contact point is not approaching the
surface are no impacts (`invalid`) and are left out of the fraction.

The same sweep runs twice: in this process (`impax.study.run`) and on a Dask cluster
(`impax.dask.sweep`: a LocalCluster of worker processes, or a running cluster given by its
scheduler's address); the counts must be identical.

    python examples/python/rod_study.py                      # 10⁶ rods, local and a 2-worker LocalCluster
    python examples/python/rod_study.py --n 100000000 --address tcp://SCHEDULER:8786
"""

from __future__ import annotations

import argparse
import math

import numpy as np

import impax
import impax.study as study

RANGES = {
    "angle": (math.radians(5), math.radians(175)),
    "direction": (math.radians(-60), math.radians(60)),
    "omega": (-3.0, 3.0),
    "friction": (0.0, 1.0),
    "restitution": (0.0, 1.0),
}


def report(title: str, r: study.SweepResult) -> None:
    s = r.summary
    where = f"{r.workers} Dask workers" if r.workers else "this process"
    print(f"{title} ({where}, {r.chunks} chunks): {r.points:,} rods in {r.seconds:.2f} s = {r.throughput / 1e6:.2f} M impacts/s")
    print(
        f"  impacts {s.valid:,} (not approaching: {s.count('invalid'):,}); "
        f"energy gained {s.energy_gained:,} = {100 * s.energy_gain_fraction:.3f} % of impacts; "
        f"breakdown (negative normal impulse) {s.count('breakdown'):,}; "
        f"inconsistent assumption {s.count('inconsistent-assumption'):,}"
    )


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--n", type=int, default=1_000_000, help="number of random rods (default 10⁶)")
    ap.add_argument("--seed", type=int, default=1)
    ap.add_argument("--law", default="whittaker")
    ap.add_argument("--chunk", type=int, default=1 << 18, help="points per chunk (per Dask task)")
    ap.add_argument("--workers", type=int, default=2, help="LocalCluster worker processes")
    ap.add_argument("--address", help="scheduler address of a running Dask cluster (instead of a LocalCluster)")
    ap.add_argument("--no-dask", action="store_true", help="run only in this process")
    args = ap.parse_args()

    space = study.RandomSample("rod", args.n, RANGES, fixed={"speed": 1.0, "mass": 1.0, "length": 1.0}, seed=args.seed)
    local = study.run(space, args.law, chunk_size=args.chunk)
    report(f"{args.law}, local", local)
    if args.no_dask:
        return

    import impax.dask

    if args.address:
        remote = impax.dask.sweep(space, args.law, chunk_size=args.chunk, client=args.address)
    else:
        from distributed import LocalCluster

        with LocalCluster(
            n_workers=args.workers, threads_per_worker=1, processes=True, dashboard_address=None, silence_logs=40
        ) as cluster:
            remote = impax.dask.sweep(space, args.law, chunk_size=args.chunk, client=cluster.scheduler_address, threads=1)
    report(f"{args.law}, Dask", remote)
    same = np.array_equal(remote.summary.counts, local.summary.counts)
    print(f"  identical to the local run: {'yes' if same else 'NO'}")
    if not same:
        raise SystemExit(1)


if __name__ == "__main__":
    main()
