"""`impax.mechanism(path_or_text, ...)`: mechanism files (planar and `space = "3d"`) and URDF
robots read once and evaluated at any state.

* the double-pendulum example file equals the built-in under its relative angles (W, v⁻,
  M, every law's impulse, ΔT and u⁺) to 1e-12;
* solo12 (floating base, 18 speeds) and ur5 (fixed base): W = J M⁻¹ Jᵀ and v⁻ = J u from
  the exposed M and J; the normal row of J against a finite difference of the contact's
  height along u (the quaternion advanced by the world angular velocity); the momentum
  balance M (u⁺ − u⁻) = Jᵀ p; ΔT from contact space and from the speeds; on random states;
* `energetic` gains no energy on 2,000 random solo12 foot impacts over four pairs (μ, e);
* `impact` returns the document of `impax compare ... --json`, equal key for key and number
  for number (solo12, the 3D arm file, the double-pendulum file);
* `impact_batch` rows equal `impact`'s numbers bit for bit, for any thread count;
* bad input raises `ValueError` naming the field.
"""

from __future__ import annotations

import math

import numpy as np
import pytest

import impax
from conftest import ROOT, num

URDF = ROOT / "crates" / "impax" / "tests" / "data" / "urdf"
SOLO12 = URDF / "solo12.urdf"
UR5 = URDF / "ur5_robot.urdf"
EXAMPLES = ROOT / "examples" / "mechanisms"
FEET = ("FL_FOOT", "FR_FOOT", "HL_FOOT", "HR_FOOT")


@pytest.fixture(scope="module")
def solo():
    return impax.mechanism(SOLO12, floating_base=True)


def random_quaternion(rng):
    q = rng.normal(size=4)
    return q / np.linalg.norm(q)


def solo_state(rng, m, contact):
    """A random floating-base state of solo12 whose contact approaches the floor."""
    q = np.concatenate([rng.uniform(-1, 1, 2), [rng.uniform(0.1, 0.5)], random_quaternion(rng), rng.uniform(-2, 2, 12)])
    u = rng.uniform(-2, 2, 18)
    _, v = m.contact_problem(q, u, contact)
    return q, (u if v[2] < 0 else -u)


def advance(q, u, h, floating):
    """q moved by h along u: positions and joints by h·u, the quaternion (w, x, y, z) turned
    by the world angular velocity u[3:6] (q ← exp(h ω / 2) ⊗ q)."""
    if not floating:
        return q + h * u
    out = q.copy()
    out[:3] += h * u[:3]
    w = u[3:6]
    angle = np.linalg.norm(w) * h
    axis = w / np.linalg.norm(w) if np.linalg.norm(w) > 0 else np.zeros(3)
    r = np.concatenate([[math.cos(angle / 2)], math.sin(angle / 2) * axis])
    a, b = r, q[3:7]
    out[3:7] = [
        a[0] * b[0] - a[1:] @ b[1:],
        *(a[0] * b[1:] + b[0] * a[1:] + np.cross(a[1:], b[1:])),
    ]
    out[7:] += h * u[6:]
    return out


def test_double_pendulum_file_equals_builtin():
    f = impax.mechanism(EXAMPLES / "double-pendulum.toml")
    assert (f.name, f.space, f.coordinates, f.contacts) == (
        "double-pendulum",
        "2d",
        ["theta1", "theta2"],
        ("tip of rod 2", "elbow"),
    )
    q0, u0 = f.default_state()
    assert np.allclose(q0, [math.radians(30), -math.radians(30)]) and np.allclose(u0, [-1, 3])
    rng = np.random.default_rng(3)
    # Relative angles: θ2(abs) = q1 + q2, so θ = T q with T = [[1, 0], [1, 1]].
    t = np.array([[1.0, 0.0], [1.0, 1.0]])
    for _ in range(10):
        a = rng.uniform(-1.2, 1.2, 2)
        w = rng.uniform(-3, 3, 2)
        q, u = np.linalg.solve(t, a), np.linalg.solve(t, w)
        if f.contact_problem(q, u, "tip of rod 2")[1][1] >= 0:
            w, u = -w, -u
        b = impax.mechanism("double-pendulum", angles=list(a), rates=list(w))
        wf, vf = f.contact_problem(q, u, "tip of rod 2", 0.5, 0.5)
        assert np.allclose(wf, b.w, rtol=0, atol=1e-12) and np.allclose(vf, b.v, rtol=0, atol=1e-12)
        m = f.mass_matrix(q)
        assert m.shape == (2, 2) and np.allclose(m, m.T, rtol=0, atol=1e-15)
        assert abs(0.5 * u @ m @ u - b.energy_before) <= 1e-12 * b.energy_before
        j = f.contact_jacobian(q, "tip of rod 2")
        assert np.allclose(j @ np.linalg.solve(m, j.T), wf, rtol=0, atol=1e-12)
        rec = f.impact(q, u, "tip of rod 2")
        assert rec["contact"] == "tip of rod 2" and rec["coordinates"] == ["theta1", "theta2"]
        assert abs(rec["energy_before"] - b.energy_before) <= 1e-12 * b.energy_before
        assert [r["law"] for r in rec["results"]] == list(impax.CONTACT_SPACE_LAWS)
        for r in rec["results"]:
            ref = b.resolve(r["law"])
            assert r["verdict"] == ref.verdict, r["law"]
            if ref.verdict == "breakdown":
                assert r["velocities_after"] is None
                continue
            assert np.allclose([r["impulse"]["t"], r["impulse"]["n"]], ref.impulse, rtol=1e-12, atol=1e-12)
            assert abs(r["energy_change"] - ref.energy_change) <= 1e-12 * max(1, abs(ref.energy_change))
            assert np.allclose(t @ np.array(r["velocities_after"]), ref.velocities_after, rtol=1e-12, atol=1e-12)


def test_planar_file_record_equals_cli(cli):
    path = EXAMPLES / "double-pendulum.toml"
    f = impax.mechanism(path)
    q, u = np.array([0.7, -0.2]), np.array([-1.5, 2.5])
    ref = cli.json("compare", str(path), "--q=" + ",".join(map(num, q)), "--u=" + ",".join(map(num, u)))
    assert f.impact(q, u) == ref


def test_solo12_names_and_shapes(solo):
    assert solo.name == "solo" and solo.space == "3d"
    assert solo.coordinates[:7] == ["x", "y", "z", "qw", "qx", "qy", "qz"]
    assert solo.speeds[:6] == ("vx", "vy", "vz", "wx", "wy", "wz")
    assert len(solo.coordinates) == 19 and len(solo.speeds) == 18
    assert set(FEET) <= set(solo.contacts) and solo.mimic_joints == ()
    q = solo.neutral()
    assert q.shape == (19,) and q[3] == 1.0
    assert solo.mass_matrix(q).shape == (18, 18)
    assert solo.contact_jacobian(q, "FL_FOOT").shape == (3, 18)
    fixed = impax.mechanism(str(SOLO12))
    assert fixed.coordinates == solo.coordinates[7:]
    assert impax.mechanism(SOLO12.read_text(), floating_base=True).coordinates == solo.coordinates


@pytest.mark.parametrize("robot", ["solo12", "ur5"])
def test_jacobian_against_finite_differences(robot):
    """The normal row of J is the rate of the contact's height along u: the floor is put at
    a fixed height (so `gap` is the height above it) and q advanced by ±h along u."""
    floating = robot == "solo12"
    m = impax.mechanism(SOLO12 if floating else UR5, floating_base=floating, floor=-5.0)
    rng = np.random.default_rng(21)
    contacts = ["FL_FOOT", "HR_FOOT:0.01,-0.02,0.03"] if floating else ["ee_link", "wrist_2_link:0.05,0,0.1"]
    for contact in contacts:
        for _ in range(5):
            n = len(m.speeds)
            if floating:
                q = np.concatenate([rng.uniform(-1, 1, 3), random_quaternion(rng), rng.uniform(-2, 2, 12)])
            else:
                q = rng.uniform(-3, 3, n)
            u = rng.uniform(-2, 2, n)
            h = 1e-6
            rate = (m.gap(advance(q, u, h, floating), contact) - m.gap(advance(q, u, -h, floating), contact)) / (2 * h)
            jn = m.contact_jacobian(q, contact)[2]
            assert abs(jn @ u - rate) <= 1e-7 * max(1, abs(rate)), (contact, jn @ u, rate)


def test_solo12_momentum_balance_and_energy(solo):
    rng = np.random.default_rng(12)
    for i in range(12):
        contact = FEET[i % 4] + (":0,0,-0.01" if i % 2 else "")
        q, u = solo_state(rng, solo, contact)
        m = solo.mass_matrix(q)
        assert np.abs(m - m.T).max() <= 1e-14 * np.abs(m).max() and np.linalg.eigvalsh(m).min() > 0
        j = solo.contact_jacobian(q, contact)
        w, v = solo.contact_problem(q, u, contact, 0.7, 0.5)
        scale = np.abs(w).max()
        assert np.abs(w - j @ np.linalg.solve(m, j.T)).max() <= 1e-10 * scale
        assert np.abs(v - j @ u).max() <= 1e-12 * max(1, np.abs(j @ u).max())
        rec = solo.impact(q, u, contact=contact, friction=0.7, restitution=0.5)
        t_before = 0.5 * u @ m @ u
        assert abs(rec["energy_before"] - t_before) <= 1e-12 * t_before
        assert len(rec["results"]) == len(impax.SPATIAL_LAWS)
        for r in rec["results"]:
            if r["verdict"] == "breakdown":
                continue
            after = np.array(r["velocities_after"])
            p = np.array([r["impulse"][k] for k in ("t1", "t2", "n")])
            lhs, rhs = m @ (after - u), j.T @ p
            assert np.abs(lhs - rhs).max() <= 1e-10 * max(1, np.abs(rhs).max()), r["law"]
            de = r["energy_change"]
            for other in (r["energy_change_from_velocities"], 0.5 * after @ m @ after - t_before):
                assert abs(other - de) <= 1e-9 * max(1e-3, t_before), (r["law"], other, de)
            va = [r["velocity_after"][k] for k in ("t1", "t2", "n")]
            assert np.allclose(va, v + w @ p, rtol=1e-10, atol=1e-10)
            assert np.allclose(va, j @ after, rtol=1e-10, atol=1e-10)
            if r["law"] == "energetic":
                assert de <= 1e-12 * t_before


def test_ur5_fixed_base_momentum_balance():
    ur5 = impax.mechanism(UR5, contact="ee_link")
    assert ur5.coordinates == [
        "shoulder_pan_joint",
        "shoulder_lift_joint",
        "elbow_joint",
        "wrist_1_joint",
        "wrist_2_joint",
        "wrist_3_joint",
    ]
    rng = np.random.default_rng(4)
    for _ in range(10):
        q, u = rng.uniform(-3, 3, 6), rng.uniform(-2, 2, 6)
        j = ur5.contact_jacobian(q)
        if j[2] @ u >= 0:
            u = -u
        m = ur5.mass_matrix(q)
        rec = ur5.impact(q, u, friction=0.3, restitution=0.6)
        for r in rec["results"]:
            if r["verdict"] == "breakdown":
                continue
            p = np.array([r["impulse"][k] for k in ("t1", "t2", "n")])
            du = np.array(r["velocities_after"]) - u
            assert np.abs(m @ du - j.T @ p).max() <= 1e-10 * max(1, np.abs(j.T @ p).max()), r["law"]


def test_energetic_never_gains_energy(solo):
    rng = np.random.default_rng(2026)
    n = 500
    q = np.concatenate(
        [rng.uniform(-1, 1, (n, 2)), rng.uniform(0.1, 0.5, (n, 1)), rng.normal(size=(n, 4)), rng.uniform(-2, 2, (n, 12))],
        axis=1,
    )
    q[:, 3:7] /= np.linalg.norm(q[:, 3:7], axis=1, keepdims=True)
    u = rng.uniform(-3, 3, (n, 18))
    # Every state approaching: u reversed where the foot would leave the floor.
    vn = np.array([solo.contact_problem(q[i], u[i], "HL_FOOT")[1][2] for i in range(n)])
    u[vn > 0] *= -1
    valid = 0
    for friction, restitution in [(0.0, 1.0), (0.3, 0.5), (0.9, 0.0), (2.5, 0.9)]:
        b = solo.impact_batch(q, u, "HL_FOOT", friction, restitution, "energetic", on_invalid="mark")
        status = np.array(impax.STATUSES)[b["status"]]
        ok = status != "invalid"
        valid += ok.sum()
        assert set(status[ok]) <= {"consistent"}, set(status[ok])
        assert np.all(b["energy_change"][ok] <= 1e-12 * b["energy_before"][ok])
        # ΔT from the speeds with the exposed mass matrix, on a few rows.
        for i in np.flatnonzero(ok)[:5]:
            m = solo.mass_matrix(q[i])
            after = b["velocities_after"][i]
            from_speeds = 0.5 * after @ m @ after - 0.5 * u[i] @ m @ u[i]
            assert abs(from_speeds - b["energy_change"][i]) <= 1e-9 * b["energy_before"][i]
            if restitution == 1.0 and friction == 0.0:
                assert abs(b["energy_change"][i]) <= 1e-9 * b["energy_before"][i]
    assert valid == 4 * n


def test_solo12_record_equals_cli(cli, solo):
    rng = np.random.default_rng(5)
    q, u = solo_state(rng, solo, "HR_FOOT")
    ref = cli.json(
        "compare",
        str(SOLO12),
        "--floating-base",
        "--contact=HR_FOOT",
        "--q=" + ",".join(num(x) for x in q),
        "--u=" + ",".join(num(x) for x in u),
        "--friction=0.6",
        "--restitution=0.4",
    )
    rec = solo.impact(q, u, "HR_FOOT", friction=0.6, restitution=0.4)
    assert rec == ref
    assert set(rec) >= {"mechanism", "coordinates", "q", "u_before", "contact", "gap", "problem", "energy_before", "results"}
    w, v = solo.contact_problem(q, u, "HR_FOOT")
    assert w.tolist() == ref["problem"]["w"]
    assert v.tolist() == [ref["problem"]["v"][k] for k in ("t1", "t2", "n")]
    assert solo.gap(q, "HR_FOOT") == 0.0 == rec["gap"]
    lifted = impax.mechanism(SOLO12, floating_base=True, floor=-1.0)
    assert lifted.gap(q, "HR_FOOT") > 0


def test_arm_file_record_equals_cli(cli):
    path = EXAMPLES / "arm-3d.toml"
    arm = impax.mechanism(path)
    assert (arm.name, arm.space, arm.coordinates, arm.contacts) == ("arm-3d", "3d", ["hinge x", "hinge y", "elbow"], ("tip",))
    q, u = arm.default_state()
    assert arm.impact(q, u) == cli.json("compare", str(path))
    q2, u2 = q + 0.1, u * 1.5
    ref = cli.json("compare", str(path), "--q=" + ",".join(map(num, q2)), "--u=" + ",".join(map(num, u2)), "--law=energetic,lcp")
    assert arm.impact(q2, u2, laws=["energetic", "lcp"]) == ref


@pytest.mark.parametrize("law", ["energetic", "lcp", "whittaker"])
def test_batch_rows_equal_single_calls(solo, law):
    rng = np.random.default_rng(7)
    states = [solo_state(rng, solo, "FR_FOOT") for _ in range(30)]
    q = np.array([s[0] for s in states])
    u = np.array([s[1] for s in states])
    u[4] = -u[4]  # a separating contact: invalid
    with pytest.raises(ValueError, match=r"^row 4: v: the normal contact velocity must be negative"):
        solo.impact_batch(q, u, "FR_FOOT", 0.5, 0.5, law)
    b = solo.impact_batch(q, u, "FR_FOOT", 0.5, 0.5, law, on_invalid="mark")
    one = solo.impact_batch(q, u, "FR_FOOT", 0.5, 0.5, law, on_invalid="mark", threads=1)
    for k in b:
        if k != "law":
            assert np.array_equal(b[k], one[k], equal_nan=True), k
    assert b["velocities_after"].shape == (30, 18) and b["impulse"].shape == (30, 3)
    for i in range(30):
        status = impax.STATUSES[b["status"][i]]
        if i == 4:
            assert status == "invalid" and np.all(np.isnan(b["velocities_after"][i]))
            continue
        rec = solo.impact(q[i], u[i], "FR_FOOT", 0.5, 0.5, laws=law)
        (r,) = rec["results"]
        assert status == r["verdict"]
        assert b["energy_before"][i] == rec["energy_before"]
        if r["verdict"] == "breakdown":
            assert np.all(np.isnan(b["impulse"][i]))
            continue
        assert b["velocities_after"][i].tolist() == r["velocities_after"]
        assert b["impulse"][i].tolist() == [r["impulse"][k] for k in ("t1", "t2", "n")]
        assert b["velocity_after"][i].tolist() == [r["velocity_after"][k] for k in ("t1", "t2", "n")]
        assert b["energy_change"][i] == r["energy_change"]


def test_planar_batch_equals_single_calls():
    f = impax.mechanism(EXAMPLES / "double-pendulum.toml")
    rng = np.random.default_rng(9)
    q = rng.uniform(-1, 1, (20, 2))
    u = rng.uniform(-3, 3, (20, 2))
    b = f.impact_batch(q, u, "tip of rod 2", law="energetic", on_invalid="mark")
    assert b["impulse"].shape == (20, 2)
    seen = 0
    for i in range(20):
        status = impax.STATUSES[b["status"][i]]
        try:
            rec = f.impact(q[i], u[i], "tip of rod 2", laws="energetic")
        except ValueError:
            assert status == "invalid"
            continue
        seen += 1
        (r,) = rec["results"]
        assert status == r["verdict"]
        assert b["velocities_after"][i].tolist() == r["velocities_after"]
        assert b["impulse"][i].tolist() == [r["impulse"]["t"], r["impulse"]["n"]]
    assert seen >= 5


def test_errors_name_the_field(solo):
    q, u = solo.neutral(), np.zeros(18)
    u[2] = -1.0
    cases = [
        (lambda: solo.impact(q[:5], u, "FL_FOOT"), r"^q: needs 19 numbers"),
        (lambda: solo.impact(q, np.append(u, 0), "FL_FOOT"), r"^u: needs 18 numbers"),
        (lambda: solo.impact(q, np.where(np.arange(18) == 3, np.nan, u), "FL_FOOT"), r"^u\[3\] \(wx\)"),
        (lambda: solo.impact(np.where(np.arange(19) == 3, 2.0, q), u, "FL_FOOT"), r"^q\[3\.\.7\] \(qw, qx, qy, qz\)"),
        (lambda: solo.impact(q, u), r"^contact: which link strikes"),
        (lambda: solo.impact(q, u, "TOE"), r'^contact\[TOE\]: unknown link "TOE"'),
        (lambda: solo.impact(q, u, "FL_FOOT:1,2"), r"^contact: "),
        (lambda: solo.impact(q, u, "FL_FOOT", friction=-1), r"^friction: "),
        (lambda: solo.impact(q, u, "FL_FOOT", restitution=2), r"^restitution: "),
        (lambda: solo.impact(q, u, "FL_FOOT", laws="smith"), r"^law: `smith` is defined for planar impacts only"),
        (lambda: solo.impact(q, u, "FL_FOOT", laws=["nope"]), r"^law: "),
        (lambda: solo.impact(q, -u, "FL_FOOT"), r"^v: the normal contact velocity must be negative"),
        (lambda: solo.mass_matrix(q[:-1]), r"^q: needs 19 numbers"),
        (lambda: solo.contact_jacobian(q), r"^contact: which link strikes"),
        (lambda: solo.impact_batch(q, u, "FL_FOOT"), r"^q: expected shape \(N, 19\)"),
        (lambda: solo.impact_batch(q[None], u[None, :5], "FL_FOOT"), r"^u: expected shape \(1, 18\)"),
        (lambda: solo.impact_batch(q[None], u[None], "FL_FOOT", on_invalid="skip"), r"^on_invalid: "),
        (lambda: solo.impact_batch(q[None], u[None], "FL_FOOT", law="smith"), r"^law: `smith` is defined for planar"),
        (lambda: impax.mechanism(SOLO12, masses=[1.0]), r"^masses: a parameter of the built-in mechanisms"),
        (lambda: impax.mechanism(SOLO12, floating_base=True, contact="TOE"), r'^contact\[TOE\]: unknown link'),
        (lambda: impax.mechanism(SOLO12, floor=math.inf), r"^floor: "),
        (lambda: impax.mechanism(SOLO12, gravity=-1.0), r"^gravity: "),
        (lambda: impax.mechanism("double-pendulum", floor=0.0), r"^floor: not a parameter of a built-in"),
        (lambda: impax.mechanism(EXAMPLES / "arm-3d.toml", floating_base=True), r"^floating_base: "),
        (lambda: impax.mechanism(EXAMPLES / "arm-3d.toml", contact="knee"), r"^contact: `knee` is not a contact of `arm-3d`"),
        (lambda: impax.mechanism("missing/robot.urdf"), r"^mechanism: cannot read `missing/robot.urdf`"),
        (lambda: impax.mechanism("<robot name='x'><link name='a'/><joint/></robot>"), r"^urdf: "),
        (lambda: impax.mechanism("[[body]]\nname = 1\n"), r"^mechanism: 2:8: invalid type"),
        (lambda: impax.mechanism(EXAMPLES / "double-pendulum.toml").impact([0, 0], [1, 1], "knee"), r"^contact: `knee` is not a contact"),
        (lambda: impax.mechanism(EXAMPLES / "double-pendulum.toml").impact([0, 0, 0], [1, 1]), r"^q: "),
    ]
    for call, pattern in cases:
        with pytest.raises(ValueError, match=pattern):
            call()
    with pytest.raises(ValueError, match=r"^mechanism: unknown mechanism `pendulum`"):
        impax.mechanism("pendulum")
    with pytest.raises(TypeError, match=r"^mechanism: expected a built-in's name"):
        impax.mechanism(42)
