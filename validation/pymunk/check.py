"""Validate impax's `lcp` law against a real engine: pymunk 7.3.1 (Chipmunk 2).

Usage: python check.py IMPAX_BINARY

Every case is one collision step of pymunk with gravity off, position correction off
(collision_slop = 0, collision_bias = 1, joint error_bias = 1, max_bias = 0) and 5000 solver
iterations, so the engine lands on the fixed point of its velocity-level iteration. The
contact geometry (the contact point on the rod and the body poses) is read from the
engine's arbiter before the solve; W = J M⁻¹ Jᵀ and v⁻ are computed here by hand from it,
`impax resolve --law lcp --json` is called with them, and the post-impact velocities are
compared (body velocities vx, vy, ω for the rod; θ̇1, θ̇2 for the double pendulum).

* Rod drops: a uniform rod onto a static segment, over angles, velocities, spins, μ and e
  (sticking, slipping, reversing and energy-gaining cases are counted and each required).
* Double pendulum: two uniform rods on pymunk pivot joints, the tip of rod 2 striking a floor;
  the mass matrix is derived by hand (M11 = m1 l1²/3 + m2 l1², M12 = m2 l1 l2 cos(θ1−θ2)/2,
  M22 = m2 l2²/3), and `impax compare double-pendulum` (mass matrix by automatic
  differentiation) is checked too.
* Negative control: on the reversing and energy-gaining rods, the exact laws `newton` and
  `energetic` must differ from the engine by far more than the tolerance, or this
  comparison could not fail.

Exit status 1 if any case deviates by more than TOL (1e-6), or a required kind of case or
the negative control is missing. The largest deviation is printed.
"""

import json
import math
import subprocess
import sys

import pymunk

TOL = 1e-6
DT = 1e-7
PENETRATION = 1e-9
ITERATIONS = 5000


def impax_resolve(binary, w, v, mu, e, law):
    """`impax resolve` for one planar problem; the JSON entry."""
    args = [
        binary,
        "resolve",
        "--w",
        ",".join(repr(float(x)) for x in w),
        "--v",
        ",".join(repr(float(x)) for x in v),
        "--friction",
        repr(float(mu)),
        "--restitution",
        repr(float(e)),
        "--law",
        law,
        "--json",
    ]
    out = subprocess.run(args, capture_output=True, text=True)
    if out.returncode != 0:
        raise RuntimeError(f"impax failed ({out.returncode}): {out.stderr.strip()} for {args}")
    return json.loads(out.stdout)


def quiet_space():
    space = pymunk.Space()
    space.gravity = (0.0, 0.0)
    space.iterations = ITERATIONS
    space.collision_slop = 0.0
    space.collision_bias = 1.0  # 1 − bias^dt = 0: no position correction
    space.damping = 1.0
    return space


def floor(space, surface_y):
    """A static segment whose top surface is y = surface_y (radius 0.1, friction and
    elasticity 1 so that the rod's own values are the products Chipmunk uses)."""
    seg = pymunk.Segment(
        space.static_body, (-100.0, surface_y - 0.1), (100.0, surface_y - 0.1), 0.1
    )
    seg.elasticity = 1.0
    seg.friction = 1.0
    seg.collision_type = 2
    space.add(seg)


def watch(space, bodies):
    """Record the contact point and body states before the solve."""
    seen = {}

    def pre(arb, _space, _data):
        cps = arb.contact_point_set
        seen["count"] = len(cps.points)
        seen["normal"] = (cps.normal.x, cps.normal.y)
        seen["point"] = (cps.points[0].point_a.x, cps.points[0].point_a.y)
        seen["states"] = [
            (b.position.x, b.position.y, b.angle, b.velocity.x, b.velocity.y, b.angular_velocity)
            for b in bodies
        ]

    space.on_collision(1, 2, pre_solve=pre)
    return seen


def rod_drop(angle_deg, vx, vy, omega, mu, e, length=1.0, mass=1.0):
    """One collision of a uniform rod (lower end first) with the floor y = 0."""
    space = quiet_space()
    inertia = mass * length * length / 12.0
    body = pymunk.Body(mass, inertia)
    th = math.radians(angle_deg)
    # Chipmunk integrates positions before it detects collisions: start the rod so that
    # its lower end is PENETRATION below the floor after that first position update.
    th1 = th + omega * DT
    body.position = (0.0, -PENETRATION - vy * DT + 0.5 * length * math.sin(th1))
    body.angle = th
    body.velocity = (vx, vy)
    body.angular_velocity = omega
    shape = pymunk.Segment(body, (-0.5 * length, 0.0), (0.5 * length, 0.0), 0.0)
    shape.elasticity = e
    shape.friction = mu
    shape.collision_type = 1
    space.add(body, shape)
    floor(space, 0.0)
    seen = watch(space, [body])
    space.step(DT)
    if seen.get("count") != 1 or abs(seen["normal"][0]) > 1e-12 or seen["normal"][1] > -0.999999:
        raise RuntimeError(f"unexpected contact {seen} for rod {angle_deg}°")
    x, y, _a, ux, uy, w = seen["states"][0]
    rt, rn = seen["point"][0] - x, seen["point"][1] - y
    wm = (
        1.0 / mass + rn * rn / inertia,
        -rt * rn / inertia,
        1.0 / mass + rt * rt / inertia,
    )
    v = (ux - w * rn, uy + w * rt)
    before = (ux, uy, w)
    after = (body.velocity.x, body.velocity.y, body.angular_velocity)

    def apply(p):
        pt, pn = p["t"], p["n"]
        return (ux + pt / mass, uy + pn / mass, w + (rt * pn - rn * pt) / inertia)

    def energy(s):
        return 0.5 * mass * (s[0] ** 2 + s[1] ** 2) + 0.5 * inertia * s[2] ** 2

    return wm, v, before, after, apply, energy


def double_pendulum(t1_deg, t2_deg, u1, u2, mu, e, m=(1.0, 1.0), l=(1.0, 1.0)):
    """One collision of a double pendulum's tip with a floor, through pymunk pivot joints."""
    space = quiet_space()
    (m1, m2), (l1, l2) = m, l
    t1, t2 = math.radians(t1_deg), math.radians(t2_deg)
    rods = []
    for mass, length, theta, centre, vel, rate in (
        (m1, l1, t1, (0.5 * l1 * math.sin(t1), -0.5 * l1 * math.cos(t1)),
         (0.5 * l1 * math.cos(t1) * u1, 0.5 * l1 * math.sin(t1) * u1), u1),
        (m2, l2, t2,
         (l1 * math.sin(t1) + 0.5 * l2 * math.sin(t2), -l1 * math.cos(t1) - 0.5 * l2 * math.cos(t2)),
         (l1 * math.cos(t1) * u1 + 0.5 * l2 * math.cos(t2) * u2,
          l1 * math.sin(t1) * u1 + 0.5 * l2 * math.sin(t2) * u2), u2),
    ):
        b = pymunk.Body(mass, mass * length * length / 12.0)
        # Chipmunk moves every body by its own velocity before it detects the collision;
        # start one step back so that the pose it then sees is the given one, where the
        # velocities satisfy the joints (J(q) u depends on q: a pose advanced with
        # velocities fixed would violate them by O(dt)).
        b.position = (centre[0] - vel[0] * DT, centre[1] - vel[1] * DT)
        b.angle = theta - 0.5 * math.pi - rate * DT  # +x axis from the pivot down the rod
        b.velocity = vel
        b.angular_velocity = rate
        s = pymunk.Segment(b, (-0.5 * length, 0.0), (0.5 * length, 0.0), 0.0)
        s.elasticity = e
        s.friction = mu
        s.filter = pymunk.ShapeFilter(group=1)  # the rods do not collide with each other
        s.collision_type = 1
        space.add(b, s)
        rods.append(b)
    j1 = pymunk.PivotJoint(space.static_body, rods[0], (0.0, 0.0), (-0.5 * l1, 0.0))
    j2 = pymunk.PivotJoint(rods[0], rods[1], (0.5 * l1, 0.0), (-0.5 * l2, 0.0))
    for j in (j1, j2):
        j.error_bias = 1.0
        j.max_bias = 0.0
        j.collide_bodies = False
        space.add(j)
    # The floor just above the tip at the given pose.
    floor(space, -l1 * math.cos(t1) - l2 * math.cos(t2) + PENETRATION)
    seen = watch(space, rods)
    space.step(DT)
    if seen.get("count") != 1 or seen["normal"][1] > -0.999999:
        raise RuntimeError(f"unexpected contact {seen} for the double pendulum")
    # The angles the engine sees (after its position update).
    th1 = seen["states"][0][2] + 0.5 * math.pi
    th2 = seen["states"][1][2] + 0.5 * math.pi
    w1, w2 = seen["states"][0][5], seen["states"][1][5]
    # Hand-derived mass matrix and tip Jacobian (rows: t = x, n = y).
    a = m1 * l1 * l1 / 3.0 + m2 * l1 * l1
    b = 0.5 * m2 * l1 * l2 * math.cos(th1 - th2)
    c = m2 * l2 * l2 / 3.0
    det = a * c - b * b
    minv = ((c / det, -b / det), (-b / det, a / det))
    jac = ((l1 * math.cos(th1), l2 * math.cos(th2)), (l1 * math.sin(th1), l2 * math.sin(th2)))
    mj = [[sum(minv[i][k] * jac[r][k] for k in range(2)) for r in range(2)] for i in range(2)]
    wfull = [[sum(jac[r][i] * mj[i][s] for i in range(2)) for s in range(2)] for r in range(2)]
    wm = (wfull[0][0], 0.5 * (wfull[0][1] + wfull[1][0]), wfull[1][1])
    v = (jac[0][0] * w1 + jac[0][1] * w2, jac[1][0] * w1 + jac[1][1] * w2)
    before = (w1, w2)
    after = (rods[0].angular_velocity, rods[1].angular_velocity)

    def apply(p):
        f = (p["t"], p["n"])
        q = [sum(jac[r][i] * f[r] for r in range(2)) for i in range(2)]
        return (w1 + minv[0][0] * q[0] + minv[0][1] * q[1], w2 + minv[1][0] * q[0] + minv[1][1] * q[1])

    def energy(s):
        return 0.5 * (a * s[0] ** 2 + 2 * b * s[0] * s[1] + c * s[1] ** 2)

    return wm, v, before, after, apply, energy, (math.degrees(th1), math.degrees(th2))


def rod_cases():
    """Deterministic rod drops: (angle°, vx, vy, ω, μ, e)."""
    cases = [(50.0, 0.5, -1.0, 0.0, 0.8, 1.0)]  # the audit's rod (impax audit rod): T⁺/T⁻ ≈ 1.18
    angles = [10.0, 25.0, 40.0, 50.0, 65.0, 80.0]
    motions = [(0.5, -1.0, 0.0), (-0.7, -1.0, 0.0), (1.5, -0.5, 0.0), (0.2, -2.0, 3.0),
               (0.0, -1.0, -2.0)]
    frictions = [0.0, 0.2, 0.5, 0.8, 1.5]
    restitutions = [0.0, 0.5, 1.0]
    k = 0
    for a in angles:
        for mo in motions:
            for i in range(3):
                mu = frictions[(k + i) % len(frictions)]
                e = restitutions[(k + 2 * i) % len(restitutions)]
                cases.append((a, mo[0], mo[1], mo[2], mu, e))
            k += 1
    # Low friction, a small slip towards the side the rod's rotation drives the contact
    # back from: the final slip reverses (the engine's friction then opposes the final
    # slip, unlike the Darboux–Keller laws whose friction follows the slip through the halt).
    for a in (30.0, 45.0, 60.0, 75.0):
        for vx in (0.3, 0.1):
            for mu, e in ((0.1, 1.0), (0.3, 0.5)):
                cases.append((a, vx, -1.0, 0.0, mu, e))
    return cases


def main():
    binary = sys.argv[1]
    worst = 0.0
    worst_case = None
    kinds = {"stick": 0, "slip": 0, "reversing": 0, "energy-gaining": 0}
    control = {"newton": math.inf, "energetic": math.inf}
    failures = 0
    rods = rod_cases()
    for case in rods:
        angle, vx, vy, omega, mu, e = case
        wm, v, before, after, apply, energy = rod_drop(angle, vx, vy, omega, mu, e)
        out = impax_resolve(binary, wm, v, mu, e, "lcp")
        want = apply(out["impulse"])
        dev = max(abs(x - y) for x, y in zip(after, want)) / max(1.0, max(map(abs, before)))
        kind = out["phases"][0]["kind"]
        if kind == "stick":
            kinds["stick"] += 1
        elif mu > 0:
            kinds["slip"] += 1
            if (kind == "slip+") != (v[0] > 0) and v[0] != 0:
                kinds["reversing"] += 1
        gain = energy(after) / energy(before)
        if out["verdict"] == "energy-gained":
            kinds["energy-gaining"] += 1
        if dev > worst:
            worst, worst_case = dev, f"rod {case}"
        if dev > TOL:
            failures += 1
            print(f"FAIL rod {case}: deviation {dev:.3e}")
        reversing = kind.startswith("slip") and mu > 0 and v[0] != 0 and (kind == "slip+") != (v[0] > 0)
        # Negative control: the exact laws against the engine where they must differ.
        for law, where in (("newton", reversing), ("energetic", out["verdict"] == "energy-gained")):
            if where:
                o = impax_resolve(binary, wm, v, mu, e, law)
                d = max(abs(x - y) for x, y in zip(after, apply(o["impulse"])))
                control[law] = min(control[law], d)
        if case == rods[0]:
            print(f"the audit's rod (50°, μ = 0.8, e = 1, v = (0.5, −1)): pymunk T⁺/T⁻ = {gain:.6f}, "
                  f"impax lcp {energy(want) / energy(before):.6f}")
    print(f"rod drops: {len(rods)} cases — {kinds['stick']} stick, {kinds['slip']} slip "
          f"({kinds['reversing']} reversing), {kinds['energy-gaining']} energy-gaining")

    pend = [
        (30.0, 0.0, -1.0, 2.0, 0.5, 0.5),  # Kane & Levinson's state
        (30.0, 0.0, -1.0, 2.0, 1.0, 1.0),
        (20.0, -35.0, -1.0, 2.5, 0.3, 0.8),
        (45.0, 20.0, 0.5, -3.0, 0.8, 0.0),
        (-30.0, 10.0, 1.0, -2.0, 0.2, 0.6),
        (60.0, 30.0, -2.0, 0.5, 1.5, 1.0),
    ]
    pend_worst = 0.0
    for case in pend:
        t1, t2, u1, u2, mu, e = case
        wm, v, before, after, apply, energy, seen_deg = double_pendulum(t1, t2, u1, u2, mu, e)
        out = impax_resolve(binary, wm, v, mu, e, "lcp")
        want = apply(out["impulse"])
        dev = max(abs(x - y) for x, y in zip(after, want)) / max(1.0, max(map(abs, before)))
        # The same impact through impax's own mechanism (mass matrix by automatic
        # differentiation) at the angles the engine saw.
        cmd = [binary, "compare", "double-pendulum", "--angles-deg",
               f"{seen_deg[0]!r},{seen_deg[1]!r}", "--rates", f"{before[0]!r},{before[1]!r}",
               "--friction", repr(mu), "--restitution", repr(e), "--law", "lcp", "--json"]
        res = subprocess.run(cmd, capture_output=True, text=True)
        if res.returncode != 0:
            raise RuntimeError(f"impax failed: {res.stderr.strip()} for {cmd}")
        mech = json.loads(res.stdout)["results"][0]["velocities_after"]
        dev = max(dev, max(abs(x - y) for x, y in zip(after, mech)) / max(1.0, max(map(abs, before))))
        pend_worst = max(pend_worst, dev)
        if dev > worst:
            worst, worst_case = dev, f"double pendulum {case}"
        if dev > TOL:
            failures += 1
            print(f"FAIL double pendulum {case}: deviation {dev:.3e}")
        print(f"double pendulum {case}: {out['phases'][0]['kind']}, "
              f"T⁺/T⁻ = {energy(after) / energy(before):.6f}, deviation {dev:.2e}")

    print(f"negative control: newton differs from the engine by at least {control['newton']:.3e} on every "
          f"reversing rod, energetic by at least {control['energetic']:.3e} on every energy-gaining one")
    print(f"largest deviation pymunk vs impax lcp: {worst:.3e} ({worst_case}); "
          f"double pendulum {pend_worst:.3e}; {len(rods) + len(pend)} cases, tolerance {TOL:g}")
    missing = [k for k, n in kinds.items() if n < 5]
    if missing:
        print(f"FAIL: fewer than 5 {', '.join(missing)} cases")
        failures += 1
    if not all(100 * TOL < c < math.inf for c in control.values()):
        print("FAIL: the negative control does not separate the laws")
        failures += 1
    if failures:
        print(f"{failures} failure(s)")
        return 1
    print("pymunk agrees with impax lcp")
    return 0


if __name__ == "__main__":
    sys.exit(main())
