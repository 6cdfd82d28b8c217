"""Several contacts at once from Python: `impax.resolve(..., contacts=K)` gives the command
line's `impax resolve --contacts K --json` numbers, Newton's cradle and the rod landing flat
reproduce their known answers, and bad input raises `ValueError` naming the argument."""

from __future__ import annotations

import numpy as np
import pytest

import impax

CRADLE_W = [[2, 0, 0, 0], [0, 2, 0, -1], [0, 0, 2, 0], [0, -1, 0, 2]]
ROD_UPPER = [1, 0, 1, 0, 4, 0, -2, 1, 0, 4]


def test_cradle_lcp_and_sequential():
    lcp = impax.resolve(CRADLE_W, [0, -1, 0, 0], 0.0, 1.0, "lcp", contacts=2)
    assert lcp.law == "lcp" and lcp.verdict == "consistent"
    assert lcp.impulses[0][1] == pytest.approx(4 / 3, abs=1e-12)
    assert lcp.impulses[1][1] == pytest.approx(2 / 3, abs=1e-12)
    assert abs(lcp.energy_change) < 1e-12
    assert len(lcp.detail["solutions"]) == 1
    seq = impax.resolve(CRADLE_W, [[0, -1], [0, 0]], 0.0, 1.0, "sequential", contacts=2)
    assert [i["contact"] for i in seq.detail["impacts"]] == [1, 2]
    assert seq.velocities_after[1][1] == pytest.approx(1.0, abs=1e-15)


def test_rod_flat_agrees_with_the_cli(cli):
    for law in ("lcp", "sequential"):
        ref = cli.json(
            "resolve",
            "--contacts=2",
            "--w=" + ",".join(str(x) for x in ROD_UPPER),
            "--v=0.3,-1,0.3,-1",
            "--friction=0.2,0.4",
            "--restitution=0.6",
            f"--law={law}",
        )
        out = impax.resolve(ROD_UPPER, [0.3, -1, 0.3, -1], [0.2, 0.4], 0.6, law, contacts=2)
        assert out.verdict == ref["verdict"]
        assert out.energy_change == pytest.approx(ref["energy_change"], rel=1e-13)
        for py, c in zip(out.contacts, ref["contacts"]):
            assert py["impulse"] == pytest.approx((c["impulse"]["t"], c["impulse"]["n"]), abs=1e-13)
            assert py["velocity_after"] == pytest.approx(
                (c["velocity_after"]["t"], c["velocity_after"]["n"]), abs=1e-13
            )
            assert [k for k, _ in py["phases"]] == [p["kind"] for p in c["phases"]]
            for key in ("compression", "restitution", "friction"):
                assert py["work"][key] == pytest.approx(c["work"][key], abs=1e-13)


def test_one_contact_is_the_one_contact_law():
    one = impax.resolve([3.5, 0.4, 1.2], [0.5, -0.866], 0.3, 0.7, "energetic")
    many = impax.resolve(np.array([3.5, 0.4, 1.2]), [0.5, -0.866], 0.3, 0.7, "energetic", contacts=1)
    assert many.impulses[0] == pytest.approx(one.impulse, rel=1e-13)
    assert many.energy_change == pytest.approx(one.energy_change, rel=1e-13)
    assert "lcp" in impax.MULTI_CONTACT_LAWS and "sequential" in impax.MULTI_CONTACT_LAWS


@pytest.mark.parametrize(
    "kwargs, field",
    [
        (dict(w=ROD_UPPER[:9], v=[0, -1, 0, -1]), "w"),
        (dict(w=ROD_UPPER, v=[0, -1, 0]), "v"),
        (dict(w=ROD_UPPER, v=[0.3, -1, 0, -1]), "v"),
        (dict(w=ROD_UPPER, v=[0, -1, 0, -1], law="smith"), "law"),
        (dict(w=ROD_UPPER, v=[0, -1, 0, -1], friction=[0.5, 0.5, 0.5]), "friction"),
        (dict(w=ROD_UPPER, v=[0, -1, 0, -1], restitution=[0.5, 1.5]), "restitution[2]"),
        (dict(w=ROD_UPPER, v=[0, -1, 0, -1], contacts=0), "contacts"),
        (dict(w=ROD_UPPER, v=[0, -1, 0, -1], law="lzb", stiffness=[1, -2]), "stiffness[2]"),
        (dict(w=ROD_UPPER, v=[0, -1, 0, -1], law="lzb", stiffness=[1, 2, 3]), "stiffness"),
        (dict(w=ROD_UPPER, v=[0, -1, 0, -1], law="lzb", stiffness=float("nan")), "stiffness"),
        (dict(w=ROD_UPPER, v=[0, -1, 0, -1], law="lzb", exponent=0.0), "exponent"),
        (dict(w=ROD_UPPER, v=[0, -1, 0, -1], law="lzb", exponent=10**400), "exponent"),
    ],
)
def test_bad_input_names_the_argument(kwargs, field):
    args = dict(friction=0.5, restitution=0.5, law="lcp", contacts=2)
    args.update(kwargs)
    with pytest.raises(ValueError, match=field.replace("[", r"\[").replace("]", r"\]")):
        impax.resolve(args.pop("w"), args.pop("v"), args.pop("friction"), args.pop("restitution"), args.pop("law"), **args)


def test_several_coefficients_need_contacts():
    with pytest.raises(ValueError, match="friction"):
        impax.resolve([3.5, 0.4, 1.2], [0.5, -0.866], [0.3, 0.3], 0.7)


def test_lzb_force_law_agrees_with_the_cli(cli):
    """`stiffness=` and `exponent=` are `--stiffness` and `--exponent`."""
    ref = cli.json(
        "resolve",
        "--contacts=2",
        "--w=" + ",".join(str(x) for x in ROD_UPPER),
        "--v=0.3,-1,0.3,-1",
        "--friction=0.2",
        "--restitution=0.6",
        "--stiffness=1,4",
        "--exponent=1",
        "--law=lzb",
    )
    out = impax.resolve(
        ROD_UPPER, [0.3, -1, 0.3, -1], 0.2, 0.6, "lzb", contacts=2, stiffness=[1, 4], exponent=1.0
    )
    assert out.energy_change == pytest.approx(ref["energy_change"], rel=1e-13)
    for py, c in zip(out.contacts, ref["contacts"]):
        assert py["impulse"] == pytest.approx((c["impulse"]["t"], c["impulse"]["n"]), abs=1e-13)
    # Only the stiffnesses' ratios matter.
    a = impax.resolve(ROD_UPPER, [0.3, -1, 0.3, -1], 0.2, 0.6, "lzb", contacts=2, stiffness=2.5)
    b = impax.resolve(ROD_UPPER, [0.3, -1, 0.3, -1], 0.2, 0.6, "lzb", contacts=2)
    for x, y in zip(a.velocities_after, b.velocities_after):
        assert x == pytest.approx(y, abs=1e-10)


def test_force_law_needs_contacts():
    for kwargs, field in ((dict(stiffness=2.0), "stiffness"), (dict(exponent=1.0), "exponent")):
        with pytest.raises(ValueError, match=field):
            impax.resolve([3.5, 0.4, 1.2], [0.5, -0.866], 0.3, 0.7, **kwargs)


# A cradle of three unit point masses in 3D (normals last), frictionless, e = 1.
CRADLE3_UPPER = [2, 0, 0, 0, 0, 0, 2, 0, 0, 0, 0, 2, 0, 0, -1, 2, 0, 0, 2, 0, 2]


def test_spatial_contacts_agree_with_the_cli(cli):
    """A 3K × 3K W makes the problem spatial, as on the command line."""
    for law in ("lcp", "sequential"):
        ref = cli.json(
            "resolve",
            "--contacts=2",
            "--w=" + ",".join(str(x) for x in CRADLE3_UPPER),
            "--v=0.2,0.1,-1,0,0,0",
            "--friction=0.3",
            "--restitution=0.8",
            f"--law={law}",
        )
        out = impax.resolve(CRADLE3_UPPER, [[0.2, 0.1, -1], [0, 0, 0]], 0.3, 0.8, law, contacts=2)
        assert out.verdict == ref["verdict"]
        assert out.energy_change == pytest.approx(ref["energy_change"], rel=1e-13, abs=1e-15)
        for py, c in zip(out.contacts, ref["contacts"]):
            i = c["impulse"]
            assert py["impulse"] == pytest.approx((i["t1"], i["t2"], i["n"]), abs=1e-13)
            assert [k for k, _ in py["phases"]] == [p["kind"] for p in c["phases"]]
    lcp = impax.resolve(np.array(CRADLE3_UPPER, float), [0, 0, -1, 0, 0, 0], 0.0, 1.0, "lcp", contacts=2)
    assert lcp.impulses[0] == pytest.approx((0, 0, 4 / 3), abs=1e-12)
    with pytest.raises(ValueError, match="v"):
        impax.resolve(CRADLE3_UPPER, [0, 0, -1, 0, 0], 0.0, 1.0, "lcp", contacts=2)
    with pytest.raises(ValueError, match="law"):
        impax.resolve(CRADLE3_UPPER, [0, 0, -1, 0, 0, 0], 0.0, 1.0, "newton", contacts=2)


def test_batch_with_contacts_is_resolve_row_by_row():
    """`resolve_batch(..., contacts=K)` row i is `resolve(..., contacts=K)` on row i, planar
    and spatial, for every multi-contact law."""
    rng = np.random.default_rng(7)
    for d in (2, 3):
        k, n = 2, 40
        m = d * k
        ws, vs = [], []
        while len(ws) < n:
            j = rng.uniform(-1, 1, (m, m + 1))
            minv = np.diag(1 / rng.uniform(0.3, 3, m + 1))
            u = rng.uniform(-1, 1, m + 1)
            v = j @ u
            if min(v[d - 1 :: d]) >= 0:
                continue
            ws.append(j @ minv @ j.T)
            vs.append(v)
        w, v = np.array(ws), np.array(vs)
        mu = rng.uniform(0, 1, (n, k))
        e = rng.uniform(0, 1, n)
        laws = ("lcp", "sequential", "lzb")
        for law in laws:
            r = impax.resolve_batch(w, v, mu, e, law, contacts=k)
            assert r["impulse"].shape == (n, k, d)
            for i in range(n):
                one = impax.resolve(w[i], v[i], list(mu[i]), e[i], law, contacts=k)
                assert impax.STATUSES[r["status"][i]] == one.verdict
                if one.verdict != "breakdown":
                    assert np.allclose(r["impulse"][i], np.array(one.impulses), rtol=0, atol=1e-14)
                    assert r["energy_change"][i] == one.energy_change


def test_batch_with_contacts_names_bad_input():
    w = np.array([ROD_UPPER, ROD_UPPER], float)
    v = np.array([[0, -1, 0, -1], [0, -1, 0.5, -1]], float)
    with pytest.raises(ValueError, match="row 1: v"):
        impax.resolve_batch(w, v, 0.3, 0.5, "lcp", contacts=2)
    r = impax.resolve_batch(w, v, 0.3, 0.5, "lcp", contacts=2, on_invalid="mark")
    assert [impax.STATUSES[s] for s in r["status"]] == ["consistent", "invalid"]
    with pytest.raises(ValueError, match="w"):
        impax.resolve_batch(w[:, :9], v, 0.3, 0.5, "lcp", contacts=2)
    with pytest.raises(ValueError, match="friction"):
        impax.resolve_batch(w, v, [0.3, 0.3, 0.3], 0.5, "lcp", contacts=2)
