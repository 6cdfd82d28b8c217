"""Compare impax's spatial `lcp` at several contacts with a real engine: PyBullet 3.2.6.

Usage: python check.py IMPAX_BINARY

Every case is one step of PyBullet's sequential-impulse solver with gravity off, position
correction off (no split impulse, contactERP = erp = frictionERP = 0), the restitution
threshold 0 and 2000 solver iterations, on a box lying flat on the plane z = 0 as it lands:
mass m, half-extents a, b, c, the box's inertia m (b² + c², a² + c², a² + b²)/3 set
explicitly, and its contact geometry four spheres of radius 1e-3 at the lower corners, so
that the engine has the four corner contacts `impax compare box-flat` has from the first
step (a Bullet box shape on a plane builds its four-point manifold over several steps). The
corners are placed 1e-5 into the plane: Bullet treats a contact at zero distance as a
speculative one and lowers the bounce by distance/Δt (0.01 here); at a small penetration
with ERP 0 the bounce is exactly −e v_n⁻. The box's restitution is e and the plane's 1
(Bullet multiplies them), its friction μ and the plane's 1 (multiplied too).
`impax compare box-flat --json` is run with the same numbers and the velocities after
(v, ω) compared.

* Landing level (v = (0, 0, v_z), no spin): the normal impulses alone; both agree on
  u⁺ = (0, 0, e |v_z|, 0, 0, 0).
* Sliding along an axis of the box (v = (v_x, 0, v_z) or (0, v_y, v_z), no spin): the box
  pitches but, by symmetry, does not yaw, so every corner slips the same way before and after;
  with Bullet's cone friction (enableConeFriction = 1) the exact cone's answer.
* Sliding obliquely, or spinning (ω_z ≠ 0): the box yaws and each corner slips its own way
  (a spin: along ω × r). Here Bullet
  is not the exact circular cone: with enableConeFriction = 1 its converged answer keeps
  more spin than `lcp` (less friction), with the default two-direction (pyramid) friction it
  keeps less (more friction). Both deviations are printed, for the record, not compared:
  they are the engine's friction model, which `impax` audits rather than copies.

Exit status 1 if a landing or sliding case deviates by more than TOL (1e-6), or a kind of
case is missing.
"""

import json
import math
import random
import subprocess
import sys

import pybullet as pb

TOL = 1e-6
ITERATIONS = 2000
RADIUS = 1e-3
SINK = 1e-5


def bullet(a, b, c, m, v, w, mu, e, cone=1):
    """The box's (v, ω) after one step of PyBullet."""
    pb.connect(pb.DIRECT)
    pb.setGravity(0, 0, 0)
    pb.setPhysicsEngineParameter(
        fixedTimeStep=1e-3,
        numSolverIterations=ITERATIONS,
        numSubSteps=0,
        useSplitImpulse=0,
        contactERP=0,
        erp=0,
        frictionERP=0,
        enableConeFriction=cone,
        restitutionVelocityThreshold=0,
        contactBreakingThreshold=0.01,
        solverResidualThreshold=0,
        deterministicOverlappingPairs=1,
    )
    plane = pb.createMultiBody(0, pb.createCollisionShape(pb.GEOM_PLANE))
    corners = [[x, y, -c + RADIUS] for x, y in ((a, b), (-a, b), (-a, -b), (a, -b))]
    shape = pb.createCollisionShapeArray(
        [pb.GEOM_SPHERE] * 4, radii=[RADIUS] * 4, collisionFramePositions=corners
    )
    box = pb.createMultiBody(m, shape, basePosition=[0, 0, c - SINK])
    inertia = [m * (b * b + c * c) / 3, m * (a * a + c * c) / 3, m * (a * a + b * b) / 3]
    pb.changeDynamics(
        box, -1, lateralFriction=mu, restitution=e, linearDamping=0, angularDamping=0,
        localInertiaDiagonal=inertia,
    )
    pb.changeDynamics(plane, -1, lateralFriction=1, restitution=1)
    pb.resetBaseVelocity(box, v, w)
    pb.performCollisionDetection()
    touching = len(pb.getContactPoints(box, plane))
    pb.stepSimulation()
    lin, ang = pb.getBaseVelocity(box)
    pb.disconnect()
    if touching != 4:
        raise SystemExit(f"the engine reports {touching} contacts, not 4")
    return list(lin) + list(ang)


def impax(binary, a, b, c, m, v, wz, mu, e):
    """`impax compare box-flat` under `lcp`: the velocities after (v, ω)."""
    args = [
        binary, "compare", "box-flat", "--law", "lcp", "--json",
        f"--half-extents={a!r},{b!r},{c!r}", f"--mass={m!r}",
        f"--vx={v[0]!r}", f"--vy={v[1]!r}", f"--vz={v[2]!r}", f"--omega={wz!r}",
        f"--friction={mu!r}", f"--restitution={e!r}",
    ]
    out = subprocess.run(args, capture_output=True, text=True, check=True)
    doc = json.loads(out.stdout)
    (r,) = doc["results"]
    return r["velocities_after"]


def main():
    binary = sys.argv[1]
    rng = random.Random(20261125)
    worst = 0.0
    counts = {"landing": 0, "sliding": 0}
    failures = []
    for kind in ("landing", "sliding"):
        for _ in range(40):
            a, b, c = (rng.uniform(0.1, 1.0) for _ in range(3))
            m = rng.uniform(0.2, 5.0)
            vz = -rng.uniform(0.2, 3.0)
            if kind == "landing":
                v = [0.0, 0.0, vz]
            else:
                # Along an axis of the box: by symmetry it does not yaw, and every corner
                # slips the same way before and after.
                s = rng.choice((-1.0, 1.0)) * rng.uniform(0.0, 2.0)
                v = [s, 0.0, vz] if rng.random() < 0.5 else [0.0, s, vz]
            mu, e = rng.uniform(0.0, 1.0), rng.uniform(0.0, 1.0)
            got = bullet(a, b, c, m, v, [0, 0, 0], mu, e)
            ref = impax(binary, a, b, c, m, v, 0.0, mu, e)
            scale = max(1.0, max(abs(x) for x in v))
            dev = max(abs(x - y) for x, y in zip(got, ref)) / scale
            worst = max(worst, dev)
            counts[kind] += 1
            if dev > TOL:
                failures.append((kind, a, b, c, m, v, mu, e, got, ref, dev))
    print(
        f"pybullet {pb.getAPIVersion()}: {counts['landing']} boxes landing level, "
        f"{counts['sliding']} sliding: largest deviation from impax lcp {worst:.2e} (tolerance {TOL:g})"
    )
    oblique = []
    for _ in range(10):
        a, b, c = (rng.uniform(0.1, 1.0) for _ in range(3))
        m, vz = rng.uniform(0.2, 5.0), -rng.uniform(0.2, 3.0)
        s, t = rng.uniform(0.5, 2.0), rng.uniform(0.2, 1.3)
        v = [s * math.cos(t), s * math.sin(t), vz]
        mu, e = rng.uniform(0.1, 1.0), rng.uniform(0.0, 1.0)
        ref = impax(binary, a, b, c, m, v, 0.0, mu, e)
        got = bullet(a, b, c, m, v, [0, 0, 0], mu, e)
        oblique.append(max(abs(x - y) for x, y in zip(got, ref)))
    print(
        "boxes sliding obliquely (they yaw, so the corners slip different ways): Bullet's cone "
        f"friction differs from lcp by {min(oblique):.1e} to {max(oblique):.1e} (not compared)"
    )
    spin = []
    for _ in range(10):
        a, b, c = (rng.uniform(0.1, 1.0) for _ in range(3))
        m, vz, wz = rng.uniform(0.2, 5.0), -rng.uniform(0.2, 3.0), rng.uniform(1.0, 10.0)
        mu, e = rng.uniform(0.05, 0.3), rng.uniform(0.0, 1.0)
        ref = impax(binary, a, b, c, m, [0, 0, vz], wz, mu, e)
        cone = bullet(a, b, c, m, [0, 0, vz], [0, 0, wz], mu, e, cone=1)
        pyramid = bullet(a, b, c, m, [0, 0, vz], [0, 0, wz], mu, e, cone=0)
        spin.append((wz, ref[5], cone[5], pyramid[5]))
    print("spinning boxes (ω_z before → after: impax lcp, Bullet cone friction, Bullet two-direction friction):")
    for wz, r, co, py in spin:
        print(f"  {wz:8.4f} → {r:8.4f}   cone {co:8.4f} ({co - r:+.4f})   two-direction {py:8.4f} ({py - r:+.4f})")
    for f in failures[:5]:
        print("DEVIATES:", f)
    sys.exit(1 if failures or min(counts.values()) == 0 else 0)


if __name__ == "__main__":
    main()
