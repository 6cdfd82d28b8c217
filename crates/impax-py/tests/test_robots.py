"""`impax.mechanism(path_or_text, ...)`: mechanism files (planar and `space = "3d"`) and URDF
robots read once and evaluated at any state.

* the double-pendulum example file equals the built-in under its relative angles (W, v⁻, every
  law's impulse, ΔT and u⁺) to 1e-12;
* solo12 with a floating base: W = J M⁻¹ Jᵀ and v⁻ = J u from the mass matrix and the
  Jacobian, the momentum balance M (u⁺ − u⁻) = Jᵀ p, ΔT from the contact space and from the
  speeds, on random states;
* the records equal `impax compare ... --json`'s (solo12, the 3D arm file);
* `impact_batch` rows equal `impact` on each row, bit for bit, for any thread count;
* bad input raises `ValueError` naming the field.
"""

from __future__ import annotations

import math

import numpy as np
import pytest

import impax
from conftest import ROOT, assert_close, num

SOLO12 = ROOT / "crates" / "impax" / "tests" / "data" / "urdf" / "solo12.urdf"
EXAMPLES = ROOT / "examples" / "mechanisms"
FEET = ("FL_FOOT", "FR_FOOT", "HL_FOOT", "HR_FOOT")


@pytest.fixture(scope="module")
def solo():
    return impax.mechanism(SOLO12, floating_base=True)


def solo_state(rng, m, contact):
    """A random floating-base state of solo12 whose contact approaches the floor."""
    q = np.concatenate([rng.uniform(-1, 1, 2), [rng.uniform(0.1, 0.5)], rng.normal(size=4), rng.uniform(-2, 2, 12)])
    q[3:7] /= np.linalg.norm(q[3:7])
    u = rng.uniform(-2, 2, 18)
    _, v = m.contact_problem(q, u, contact)
    return q, (u if v[2] < 0 else -u)


def test_double_pendulum_file_equals_builtin():
    f = impax.mechanism(EXAMPLES / "double-pendulum.toml")
    assert (f.name, f.space, f.coordinates, f.contacts) == (
        "double-pendulum",
        "2d",
        ("theta1", "theta2"),
        ("tip of rod 2", "elbow"),
    )
    q0, u0 = f.default_state()
    assert np.allclose(q0, [math.radians(30), -math.radians(30)]) and np.allclose(u0, [-1, 3])
    rng = np.random.default_rng(3)
    for _ in range(10):
        a = rng.uniform(-1.2, 1.2, 2)
        w = rng.uniform(-3, 3, 2)
        # Relative angles: θ2(abs) = q1 + q2, so θ = T q with T = [[1, 0], [1, 1]].
        t = np.array([[1.0, 0.0], [1.0, 1.0]])
        q, u = np.linalg.solve(t, a), np.linalg.solve(t, w)
        if f.contact_problem(q, u, "tip of rod 2")[1][1] >= 0:
            w, u = -w, -u
        b = impax.mechanism("double-pendulum", angles=list(a), rates=list(w))
        wf, vf = f.contact_problem(q, u, "tip of rod 2", 0.5, 0.5)
        assert np.allclose(wf, b.w, rtol=0, atol=1e-12) and np.allclose(vf, b.v, rtol=0, atol=1e-12)
        m = f.mass_matrix(q)
        assert m.shape == (2, 2) and np.allclose(m, m.T, rtol=0, atol=1e-15)
        assert abs(0.5 * u @ m @ u - b.energy_before) <= 1e-12 * b.energy_before
        records = f.impact(q, u, "tip of rod 2")
        assert [r.law for r in records] == list(impax.CONTACT_SPACE_LAWS)
        for r in records:
            ref = b.resolve(r.law)
            assert r.verdict == ref.verdict, r.law
            if ref.verdict == "breakdown":
                continue
            assert np.allclose(r.impulse, ref.impulse, rtol=1e-12, atol=1e-12)
            assert abs(r.energy_change - ref.energy_change) <= 1e-12 * max(1, abs(ref.energy_change))
            assert np.allclose(t @ np.array(r.velocities_after), ref.velocities_after, rtol=1e-12, atol=1e-12)
            assert abs(r.energy_before - ref.energy_before) <= 1e-12 * ref.energy_before


def test_solo12_names_and_shapes(solo):
    assert solo.name == "solo" and solo.space == "3d"
    assert solo.coordinates[:7] == ("x", "y", "z", "qw", "qx", "qy", "qz")
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


def test_solo12_momentum_balance_and_energy(solo):
    rng = np.random.default_rng(12)
    for i in range(12):
        contact = FEET[i % 4] + (":0,0,-0.01" if i % 2 else "")
        q, u = solo_state(rng, solo, contact)
        m = solo.mass_matrix(q)
        j = solo.contact_jacobian(q, contact)
        w, v = solo.contact_problem(q, u, contact, 0.7, 0.5)
        scale = np.abs(w).max()
        assert np.abs(w - j @ np.linalg.solve(m, j.T)).max() <= 1e-10 * scale
        assert np.abs(v - j @ u).max() <= 1e-12 * max(1, np.abs(j @ u).max())
        for r in solo.impact(q, u, contact=contact, friction=0.7, restitution=0.5):
            if r.verdict == "breakdown":
                continue
            du = np.array(r.velocities_after) - u
            p = np.array(r.impulse)
            lhs, rhs = m @ du, j.T @ p
            assert np.abs(lhs - rhs).max() <= 1e-10 * max(1, np.abs(rhs).max()), r.law
            t_after = 0.5 * np.array(r.velocities_after) @ m @ np.array(r.velocities_after)
            t_before = 0.5 * u @ m @ u
            assert abs(r.energy_before - t_before) <= 1e-12 * t_before
            de = r.energy_change
            for other in (r.energy_change_from_velocities, t_after - t_before):
                assert abs(other - de) <= 1e-9 * max(1e-3, t_before), (r.law, other, de)
            assert np.allclose(r.velocity_after, v + w @ p, rtol=1e-10, atol=1e-10)
            if r.law == "energetic":
                assert de <= 1e-12 * t_before


def test_solo12_records_equal_cli(cli, solo):
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
    records = solo.impact(q, u, "HR_FOOT", friction=0.6, restitution=0.4)
    assert [r.law for r in records] == [r["law"] for r in ref["results"]]
    for r, e in zip(records, ref["results"]):
        assert_close(r.to_dict(), e, r.law, tol=1e-10)
    w, v = solo.contact_problem(q, u, "HR_FOOT")
    assert_close(w.tolist(), ref["problem"]["w"], tol=1e-12)
    assert_close(dict(zip(("t1", "t2", "n"), v.tolist())), ref["problem"]["v"], tol=1e-12)
    assert solo.gap(q, "HR_FOOT") == 0.0
    lifted = impax.mechanism(SOLO12, floating_base=True, floor=-1.0)
    assert lifted.gap(q, "HR_FOOT") > 0


def test_arm_file_equals_cli(cli):
    path = EXAMPLES / "arm-3d.toml"
    arm = impax.mechanism(path)
    assert (arm.name, arm.space, arm.coordinates, arm.contacts) == ("arm-3d", "3d", ("hinge x", "hinge y", "elbow"), ("tip",))
    ref = cli.json("compare", str(path))
    q, u = arm.default_state()
    records = arm.impact(q, u)
    assert [r.law for r in records] == [r["law"] for r in ref["results"]]
    for r, e in zip(records, ref["results"]):
        assert_close(r.to_dict(), e, r.law, tol=1e-10)
        if r.law == "energetic":
            assert r.hodograph is not None and r.invariant_rays is not None


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
        (r,) = solo.impact(q[i], u[i], "FR_FOOT", 0.5, 0.5, laws=law)
        assert status == r.verdict
        assert b["energy_before"][i] == r.energy_before
        if r.verdict == "breakdown":
            assert np.all(np.isnan(b["impulse"][i]))
            continue
        assert np.array_equal(b["velocities_after"][i], r.velocities_after)
        assert np.array_equal(b["impulse"][i], r.impulse)
        assert np.array_equal(b["velocity_after"][i], r.velocity_after)
        assert b["energy_change"][i] == r.energy_change


def test_planar_batch_equals_single_calls():
    f = impax.mechanism(EXAMPLES / "double-pendulum.toml")
    rng = np.random.default_rng(9)
    q = rng.uniform(-1, 1, (20, 2))
    u = rng.uniform(-3, 3, (20, 2))
    b = f.impact_batch(q, u, "tip of rod 2", law="energetic", on_invalid="mark")
    assert b["impulse"].shape == (20, 2)
    for i in range(20):
        status = impax.STATUSES[b["status"][i]]
        try:
            (r,) = f.impact(q[i], u[i], "tip of rod 2", laws="energetic")
        except ValueError:
            assert status == "invalid"
            continue
        assert status == r.verdict
        assert np.array_equal(b["velocities_after"][i], r.velocities_after)
        assert np.array_equal(b["impulse"][i], r.impulse)


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
        (lambda: solo.impact_batch(q, u, "FL_FOOT"), r"^q: expected shape \(N, 19\)"),
        (lambda: solo.impact_batch(q[None], u[None, :5], "FL_FOOT"), r"^u: expected shape \(1, 18\)"),
        (lambda: solo.impact_batch(q[None], u[None], "FL_FOOT", on_invalid="skip"), r"^on_invalid: "),
        (lambda: impax.mechanism(SOLO12, masses=[1.0]), r"^masses: a parameter of the built-in mechanisms"),
        (lambda: impax.mechanism(SOLO12, floating_base=True, contact="TOE"), r'^contact\[TOE\]: unknown link'),
        (lambda: impax.mechanism("double-pendulum", floor=0.0), r"^floor: not a parameter of a built-in"),
        (lambda: impax.mechanism(EXAMPLES / "arm-3d.toml", floating_base=True), r"^floating_base: "),
        (lambda: impax.mechanism(EXAMPLES / "arm-3d.toml", contact="knee"), r"^contact: `knee` is not a contact of `arm-3d`"),
        (lambda: impax.mechanism("missing/robot.urdf"), r"^mechanism: cannot read `missing/robot.urdf`"),
        (lambda: impax.mechanism("<robot name='x'><link name='a'/><joint/></robot>"), r"^urdf: "),
        (lambda: impax.mechanism("[[body]]\nname = 1\n"), r"^mechanism: 2:8: invalid type"),
        (lambda: impax.mechanism(EXAMPLES / "double-pendulum.toml").impact([0, 0], [1, 1], "knee"), r"^contact: `knee` is not a contact"),
    ]
    for call, pattern in cases:
        with pytest.raises(ValueError, match=pattern):
            call()
    with pytest.raises(ValueError, match=r"^mechanism: unknown mechanism `pendulum`"):
        impax.mechanism("pendulum")
    with pytest.raises(TypeError, match=r"^mechanism: expected a built-in's name"):
        impax.mechanism(42)
