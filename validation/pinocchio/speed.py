"""How fast impax strikes solo12's foot, beside Pinocchio on the same model and states.

Usage: python speed.py [--states N] [--repeats R]

Prints figures only (nothing here is asserted: times depend on the machine and its load).
Each figure is the median over R repeats of the time per state, over N random states of solo12
with a floating base (18 speeds), the foot FL_FOOT approaching the floor:

* Pinocchio: `crba` + `computeFrameJacobian` (LOCAL_WORLD_ALIGNED) + `cholesky.decompose`
  + three `cholesky.solve` (M⁻¹ Jᵀ, for W = J M⁻¹ Jᵀ), one Python call each; and `crba`
  alone, which bounds what one call costs through the binding;
* impax `contact_problem(q, u, contact)`: the same quantities (M, J, its factorisation, W and
  v⁻ = J u) in one Python call;
* impax `impact(q, u, contact, laws="energetic")`: state → u⁺ (and the whole record, a
  dict), one Python call;
* impax `impact_batch(Q, U, contact, law="energetic", threads=1)`: state → u⁺ for N states in
  one call on one thread (no Python per state), the time divided by N.

The ratios compare impax's batch (the whole impact, Darboux–Keller integration included) and
its one-call W with Pinocchio's dynamics alone.
"""

from __future__ import annotations

import argparse
import pathlib
import statistics
import sys
import time

import numpy as np
import pinocchio as pin

import impax

ROBOTS = pathlib.Path(sys.prefix) / "lib" / f"python{sys.version_info[0]}.{sys.version_info[1]}"
SOLO12 = ROBOTS / "site-packages" / "cmeel.prefix" / "share" / "example-robot-data" / "robots" / "solo_description" / "robots" / "solo12.urdf"
FOOT = "FL_FOOT"


def states(m, n, rng):
    q = np.concatenate(
        [rng.uniform(-1, 1, (n, 2)), rng.uniform(0.1, 0.5, (n, 1)), rng.normal(size=(n, 4)), rng.uniform(-1.5, 1.5, (n, 12))],
        axis=1,
    )
    q[:, 3:7] /= np.linalg.norm(q[:, 3:7], axis=1, keepdims=True)
    u = rng.uniform(-2, 2, (n, 18))
    for i in range(n):
        if m.contact_problem(q[i], u[i], FOOT)[1][2] > 0:
            u[i] = -u[i]
    return q, u


def median_per_state(run, n, repeats):
    times = []
    for _ in range(repeats):
        t0 = time.perf_counter()
        run()
        times.append((time.perf_counter() - t0) / n)
    return statistics.median(times)


def main() -> None:
    ap = argparse.ArgumentParser()
    ap.add_argument("--states", type=int, default=2000)
    ap.add_argument("--repeats", type=int, default=7)
    args = ap.parse_args()
    n, repeats = args.states, args.repeats

    m = impax.mechanism(SOLO12, floating_base=True)
    q, u = states(m, n, np.random.default_rng(1))
    model = pin.buildModelFromUrdf(str(SOLO12), pin.JointModelFreeFlyer())
    data = model.createData()
    fid = model.getFrameId(FOOT, pin.FrameType.BODY)
    qp = np.concatenate([q[:, :3], q[:, 4:7], q[:, 3:4], q[:, 7:]], axis=1)  # quaternion (x, y, z, w)
    lwa = pin.ReferenceFrame.LOCAL_WORLD_ALIGNED

    def pinocchio():
        for i in range(n):
            pin.crba(model, data, qp[i])
            pin.cholesky.decompose(model, data)
            j = pin.computeFrameJacobian(model, data, qp[i], fid, lwa)
            for r in range(3):
                pin.cholesky.solve(model, data, j[r])

    def crba_alone():
        for i in range(n):
            pin.crba(model, data, qp[i])

    def problem():
        for i in range(n):
            m.contact_problem(q[i], u[i], FOOT)

    def single():
        for i in range(n):
            m.impact(q[i], u[i], FOOT, friction=0.5, restitution=0.5, laws="energetic")

    def batch():
        m.impact_batch(q, u, FOOT, 0.5, 0.5, "energetic", threads=1)

    rows = [
        ("Pinocchio crba + frame Jacobian + Cholesky (M⁻¹Jᵀ), Python calls", median_per_state(pinocchio, n, repeats)),
        ("Pinocchio crba alone (one Python call: its C++ cost and one call's overhead)", median_per_state(crba_alone, n, repeats)),
        ("impax contact_problem: W, v⁻ (one Python call)", median_per_state(problem, n, repeats)),
        ("impax impact, energetic: state → u⁺ and the record (one Python call)", median_per_state(single, n, repeats)),
        ("impax impact_batch, energetic: state → u⁺ (one thread, per state)", median_per_state(batch, n, repeats)),
    ]
    print(f"solo12, floating base (18 speeds), {FOOT} striking; {n} random states, median of {repeats} repeats")
    print(f"impax {impax.__version__}, Pinocchio {pin.__version__}")
    for label, t in rows:
        print(f"  {label:<80} {t * 1e6:8.2f} µs")
    base = rows[0][1]
    print(f"  ratio impax batch impact / Pinocchio dynamics: {rows[4][1] / base:.2f}")
    print(f"  ratio impax contact_problem / Pinocchio dynamics (both one state per Python call): {rows[2][1] / base:.2f}")


if __name__ == "__main__":
    main()
