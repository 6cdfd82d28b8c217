"""Compare impax's robots with Pinocchio (pin 4.1.0) on the robots of example-robot-data 6.0.0.

Usage: python check.py            (impax is the installed Python package: validation/pinocchio/run.sh)

For each robot, with a fixed and with a floating base, at random states (base position and
orientation, every joint, every speed) and at several contact points — a link's frame origin
(`"LINK"`) or a point in it (`"LINK:x,y,z"`) — this compares:

* the mass matrix M(q) (`Mechanism.mass_matrix` against `pin.crba`);
* the contact point's Jacobian (`Mechanism.contact_jacobian`, rows x, y, z of the world,
  against `pin.getFrameJacobian(..., LOCAL_WORLD_ALIGNED)` of a frame added at the point);
* the contact-space W = J M⁻¹ Jᵀ and v⁻ = J u (`Mechanism.contact_problem`);
* the momentum balance M (u⁺ − u⁻) = Jᵀ p and ΔT = ½ u⁺ᵀ M u⁺ − ½ u⁻ᵀ M u⁻ with Pinocchio's
  M and J, for impax's u⁺ and p under `energetic` (`Mechanism.impact`).

Conventions. Pinocchio's free flyer: q = (x, y, z, qx, qy, qz, qw), v = (linear velocity of the
base origin, angular velocity), both in the base's local frame. impax: q = (x, y, z, qw, qx, qy,
qz), u = (base origin velocity, angular velocity), both in the world frame. So v = T u with
T = diag(Rᵀ, Rᵀ, P) (R the base orientation, P the joints' order), M_impax = Tᵀ M_pin T and
J_impax = J_pin T. Joints are matched by name; a continuous joint (Pinocchio's (cos θ, sin θ))
gets θ from impax's coordinate. Mimic joints are independent coordinates on both sides
(Pinocchio's URDF reader's default).

Deviations are relative to the largest entry of the quantity compared (of J u for v⁻, of Jᵀ p
for the momentum balance, of T⁻ for ΔT). Exit status 1 if any exceeds TOL = 1e-10, if a robot
of the required set cannot be read, or if the negative controls (M without the change of
velocity coordinates; the contact point moved by 1 mm) do not fail by far more than TOL.

After the required set, every other URDF file of example-robot-data is tried the same way (2
states, one contact): those impax reads are compared (and must agree), and those it cannot read
are listed with impax's reason.
"""

from __future__ import annotations

import math
import pathlib
import sys

import numpy as np
import pinocchio as pin

import impax

TOL = 1e-10
ROBOTS = pathlib.Path(sys.prefix) / "lib" / f"python{sys.version_info[0]}.{sys.version_info[1]}"
ROBOTS = ROBOTS / "site-packages" / "cmeel.prefix" / "share" / "example-robot-data" / "robots"

# label, path under ROBOTS, contacts (links, or points in a link's frame)
REQUIRED = [
    ("solo12", "solo_description/robots/solo12.urdf", ["FL_FOOT", "FR_FOOT", "HL_FOOT", "HR_FOOT:0.01,-0.02,0.005"]),
    ("ur5", "ur_description/urdf/ur5_robot.urdf", ["ee_link", "tool0", "wrist_3_link:0,0.1,0.05", "forearm_link:0.2,0,0.1"]),
    ("go2", "go2_description/urdf/go2.urdf", ["FL_foot", "RR_foot", "RL_calf:0,0,-0.1"]),
    ("anymal", "anymal_b_simple_description/robots/anymal.urdf", ["LF_FOOT", "RH_FOOT", "LH_SHANK:0.1,0,-0.2"]),
    ("anymal_c", "anymal_c_simple_description/urdf/anymal.urdf", ["LF_FOOT", "RH_FOOT"]),
    ("panda", "panda_description/urdf/panda.urdf", ["panda_hand_tcp", "panda_leftfinger:0,0.01,0.04", "panda_link4:0.05,0.05,0.1"]),
    ("talos_reduced", "talos_data/robots/talos_reduced.urdf", ["left_sole_link", "right_sole_link:0.1,0.05,0", "gripper_left_fingertip_1_link"]),
]
STATES = 12

# Why impax refuses a file, by a piece of its message.
WHY = [
    ("mimics an unknown joint", "the file's <mimic> names a joint it does not have (Pinocchio ignores <mimic> unless asked)"),
    ("missing field `filename`", "a <material> with a <texture/> without filename, which the URDF parser (urdf-rs) requires; impax never reads materials"),
    ("moves no mass", "a joint moves no mass, so M is singular; Pinocchio builds the model without factoring M"),
    ("positive semidefinite", "an inertia tensor with a negative eigenvalue (round-off in the file); Pinocchio does not check"),
    ("has no <link>", "an empty description (an unexpanded xacro stub)"),
]


def quat_matrix(w, x, y, z):
    return np.array(
        [
            [1 - 2 * (y * y + z * z), 2 * (x * y - w * z), 2 * (x * z + w * y)],
            [2 * (x * y + w * z), 1 - 2 * (x * x + z * z), 2 * (y * z - w * x)],
            [2 * (x * z - w * y), 2 * (y * z + w * x), 1 - 2 * (x * x + y * y)],
        ]
    )


class Pair:
    """One robot, one base, read by both: the maps between their coordinates."""

    def __init__(self, path: pathlib.Path, floating: bool):
        self.floating = floating
        self.imp = impax.mechanism(path, floating_base=floating)
        self.model = (
            pin.buildModelFromUrdf(str(path), pin.JointModelFreeFlyer()) if floating else pin.buildModelFromUrdf(str(path))
        )
        self.data = self.model.createData()
        coords, speeds = list(self.imp.coordinates), list(self.imp.speeds)
        first = 2 if floating else 1
        self.joints = []  # (pin idx_q, nq, pin idx_v, impax coordinate, impax speed)
        for j in range(first, self.model.njoints):
            jm, name = self.model.joints[j], self.model.names[j]
            if jm.nv != 1 or jm.nq not in (1, 2):
                raise ValueError(f"joint {name}: nq = {jm.nq}, nv = {jm.nv} not handled here")
            self.joints.append((jm.idx_q, jm.nq, jm.idx_v, coords.index(name), speeds.index(name)))
        base = 6 if floating else 0
        if len(self.joints) + base != len(speeds) or self.model.nv != len(speeds):
            raise ValueError(f"impax has {len(speeds)} speeds, Pinocchio {self.model.nv}")
        self.frames: dict[str, int] = {}

    def frame(self, contact: str) -> int:
        """A Pinocchio frame at impax's contact point (`LINK` or `LINK:x,y,z`)."""
        if contact not in self.frames:
            link, _, point = contact.partition(":")
            offset = np.array([float(x) for x in point.split(",")]) if point else np.zeros(3)
            body = self.model.frames[self.model.getFrameId(link, pin.FrameType.BODY)]
            placement = body.placement * pin.SE3(np.eye(3), offset)
            fid = self.model.addFrame(
                pin.Frame(f"impax {contact}", body.parentJoint, self.model.getFrameId(link, pin.FrameType.BODY), placement, pin.FrameType.OP_FRAME)
            )
            self.data = self.model.createData()
            self.frames[contact] = fid
        return self.frames[contact]

    def random_state(self, rng):
        n = len(self.imp.coordinates)
        q = np.empty(n)
        k = 0
        if self.floating:
            quat = rng.normal(size=4)
            q[:7] = np.concatenate([rng.uniform(-1, 1, 3), quat / np.linalg.norm(quat)])
            k = 7
        q[k:] = rng.uniform(-1.5, 1.5, n - k)
        u = rng.uniform(-2, 2, len(self.imp.speeds))
        return q, u

    def to_pin(self, q):
        """Pinocchio's q, and T with v_pin = T u_impax."""
        nv = self.model.nv
        qp = np.zeros(self.model.nq)
        t = np.zeros((nv, nv))
        if self.floating:
            w, x, y, z = q[3:7]
            qp[:7] = [*q[:3], x, y, z, w]
            r = quat_matrix(w, x, y, z)
            t[:3, :3] = r.T
            t[3:6, 3:6] = r.T
        for iq, nq, iv, ci, si in self.joints:
            if nq == 1:
                qp[iq] = q[ci]
            else:
                qp[iq : iq + 2] = [math.cos(q[ci]), math.sin(q[ci])]
            t[iv, si] = 1.0
        return qp, t

    def pin_quantities(self, q, contact):
        qp, t = self.to_pin(q)
        fid = self.frame(contact)
        pin.crba(self.model, self.data, qp)
        m = np.triu(self.data.M) + np.triu(self.data.M, 1).T
        pin.computeJointJacobians(self.model, self.data, qp)
        pin.updateFramePlacements(self.model, self.data)
        j = pin.getFrameJacobian(self.model, self.data, fid, pin.ReferenceFrame.LOCAL_WORLD_ALIGNED)[:3]
        return m, j, t


def rel(a, b, scale=None):
    a, b = np.asarray(a, float), np.asarray(b, float)
    s = np.abs(b).max() if scale is None else scale
    return float(np.abs(a - b).max() / max(s, 1e-300))


def compare(pair: Pair, contacts, states, rng, impacts=True):
    """The largest deviations over random states and contacts."""
    dev = dict.fromkeys(["M", "J", "W", "v", "balance", "dT"], 0.0)
    for _ in range(states):
        q, u = pair.random_state(rng)
        for contact in contacts:
            m_pin, j_pin, t = pair.pin_quantities(q, contact)
            m_imp = pair.imp.mass_matrix(q)
            j_imp = pair.imp.contact_jacobian(q, contact)
            dev["M"] = max(dev["M"], rel(m_imp, t.T @ m_pin @ t))
            dev["J"] = max(dev["J"], rel(j_imp, j_pin @ t))
            w_pin = j_pin @ np.linalg.solve(m_pin, j_pin.T)
            vp = t @ u
            v_pin = j_pin @ vp
            w_imp, v_imp = pair.imp.contact_problem(q, u, contact)
            dev["W"] = max(dev["W"], rel(w_imp, w_pin))
            scale = max(np.abs(v_pin).max(), 1e-3 * np.abs(j_pin).max() * np.abs(vp).max())
            dev["v"] = max(dev["v"], rel(v_imp, v_pin, scale))
            if not impacts:
                continue
            uu = u if v_pin[2] < 0 else -u
            rec = pair.imp.impact(q, uu, contact, friction=0.6, restitution=0.5, laws="energetic")
            (r,) = rec["results"]
            p = np.array([r["impulse"][k] for k in ("t1", "t2", "n")])
            before, after = t @ uu, t @ np.array(r["velocities_after"])
            jtp = j_pin.T @ p
            dev["balance"] = max(dev["balance"], rel(m_pin @ (after - before), jtp))
            t0 = 0.5 * before @ m_pin @ before
            d_t = 0.5 * after @ m_pin @ after - t0
            dev["dT"] = max(dev["dT"], abs(d_t - r["energy_change"]) / t0)
    return dev


def negative_controls(path):
    """Comparisons that must fail: M without the change of velocity coordinates, and the
    contact point moved by 1 mm."""
    pair = Pair(path, True)
    rng = np.random.default_rng(99)
    q, u = pair.random_state(rng)
    m_pin, j_pin, t = pair.pin_quantities(q, "FL_FOOT")
    naive = rel(pair.imp.mass_matrix(q), m_pin)
    _, j_moved, t = pair.pin_quantities(q, "FL_FOOT:0.001,0,0")
    moved = rel(pair.imp.contact_jacobian(q, "FL_FOOT"), j_moved @ t)
    return naive, moved


def main() -> int:
    print(f"impax {impax.__version__} against Pinocchio {pin.__version__} (example-robot-data 6.0.0 under {ROBOTS})")
    print(f"deviations relative to the largest entry; tolerance {TOL:g}\n")
    rng = np.random.default_rng(2026)
    failures = []
    header = f"{'robot':<15} {'base':<8} {'nv':>3} {'cases':>5}  {'M':>8} {'J':>8} {'W':>8} {'v⁻':>8} {'M Δu=Jᵀp':>10} {'ΔT':>8}"
    print(header)
    worst = dict.fromkeys(["M", "J", "W", "v", "balance", "dT"], 0.0)
    for label, rel_path, contacts in REQUIRED:
        for floating in (False, True):
            base = "floating" if floating else "fixed"
            try:
                pair = Pair(ROBOTS / rel_path, floating)
            except Exception as e:  # noqa: BLE001 — reported and failed
                print(f"{label:<15} {base:<8} not compared: {e}")
                failures.append(f"{label} ({base}): cannot be read: {e}")
                continue
            d = compare(pair, contacts, STATES, rng)
            cases = STATES * len(contacts)
            print(
                f"{label:<15} {base:<8} {pair.model.nv:>3} {cases:>5}  {d['M']:8.1e} {d['J']:8.1e} {d['W']:8.1e} "
                f"{d['v']:8.1e} {d['balance']:10.1e} {d['dT']:8.1e}"
            )
            for k, x in d.items():
                worst[k] = max(worst[k], x)
                if not x <= TOL:
                    failures.append(f"{label} ({base}): {k} deviates by {x:.2e}")
    print("\nlargest deviations over the required robots: " + ", ".join(f"{k} {x:.1e}" for k, x in worst.items()))

    naive, moved = negative_controls(ROBOTS / REQUIRED[0][1])
    print(f"negative controls (must fail): M without T: {naive:.1e}; contact moved 1 mm: {moved:.1e}")
    for what, x in [("M without T", naive), ("contact moved 1 mm", moved)]:
        if not x > 1e4 * TOL:
            failures.append(f"negative control {what}: only {x:.1e}, the comparison could not fail")

    print("\nevery other URDF file of example-robot-data (2 states, a floating base, the last link of the tree):")
    required = {p for _, p, _ in REQUIRED}
    unread = []
    compared = 0
    others = {k: (0.0, "") for k in ("M", "J", "W", "v")}
    for path in sorted(ROBOTS.rglob("*.urdf")):
        rel_path = str(path.relative_to(ROBOTS))
        if rel_path in required:
            continue
        try:
            pair = Pair(path, True)
        except Exception as e:  # noqa: BLE001 — listed with the reason
            message = str(e).splitlines()[0]
            why = next((w for k, w in WHY if k in message), "")
            try:
                nv = pin.buildModelFromUrdf(str(path), pin.JointModelFreeFlyer()).nv
                theirs = f"Pinocchio reads it (nv = {nv})"
            except Exception:  # noqa: BLE001
                theirs = "Pinocchio cannot read it either"
            unread.append((rel_path, f"{message}\n      {why + '; ' if why else ''}{theirs}"))
            continue
        model = pair.model
        leaf = max(
            (f for f in model.frames if f.type == pin.FrameType.BODY and f.name in pair.imp.contacts),
            key=lambda f: f.parentJoint,
        )
        d = compare(pair, [leaf.name + ":0.01,0.02,0.03"], 2, rng, impacts=False)
        compared += 1
        for k in others:
            if d[k] > others[k][0]:
                others[k] = (d[k], rel_path)
        bad = {k: x for k, x in d.items() if k in ("M", "J", "W", "v") and not x <= TOL}
        flag = "  DEVIATES" if bad else ""
        print(f"  {rel_path:<62} nv {model.nv:>3}  M {d['M']:.0e}  J {d['J']:.0e}  W {d['W']:.0e}  v {d['v']:.0e}{flag}")
        if bad:
            failures.append(f"{rel_path}: " + ", ".join(f"{k} {x:.1e}" for k, x in bad.items()))
    print("largest deviations over them: " + ", ".join(f"{k} {x:.1e} ({where})" for k, (x, where) in others.items()))
    print(f"{compared} more robots compared; {len(unread)} not compared:")
    for rel_path, why in unread:
        print(f"  {rel_path}: {why}")

    if failures:
        print("\nFAILED:\n  " + "\n  ".join(failures))
        return 1
    print("\nOK: impax's M, contact Jacobians, W, v⁻ and impacts agree with Pinocchio")
    return 0


if __name__ == "__main__":
    sys.exit(main())
