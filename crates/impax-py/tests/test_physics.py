"""Physics of the batch results, not only plumbing: the identities of contact space hold row
by row (theory §1, §5), the exact laws never gain energy with `energetic`, special cases
collapse as they must, and a batch equals the single-problem path and itself across thread
counts."""

from __future__ import annotations

import math

import numpy as np
import pytest

import impax
from conftest import random_planar, random_spatial

PLANAR = list(impax.CONTACT_SPACE_LAWS)


def resolved(r):
    return np.isin(r["status"], [0, 1, 2])


@pytest.mark.parametrize("law", PLANAR)
def test_contact_space_identities(law):
    w, v, f, e = random_planar(np.random.default_rng(11), 20_000)
    r = impax.resolve_batch(w, v, f, e, law)
    ok = resolved(r)
    assert ok.mean() > 0.9
    p, va = r["impulse"][ok], r["velocity_after"][ok]
    a, b, c = w[ok, 0], w[ok, 1], w[ok, 2]
    v0 = v[ok]
    scale = np.abs(v0).max(axis=1) + np.abs(va).max(axis=1)
    # v⁺ = v⁻ + W p
    assert np.all(np.abs(va[:, 0] - (v0[:, 0] + a * p[:, 0] + b * p[:, 1])) <= 1e-12 * scale * (1 + np.abs(p).max(axis=1) * (a + c)))
    assert np.all(np.abs(va[:, 1] - (v0[:, 1] + b * p[:, 0] + c * p[:, 1])) <= 1e-12 * scale * (1 + np.abs(p).max(axis=1) * (a + c)))
    # ΔT = v⁻·p + ½ pᵀ W p = W_c + W_r + W_t
    dt = (v0 * p).sum(axis=1) + 0.5 * (a * p[:, 0] ** 2 + 2 * b * p[:, 0] * p[:, 1] + c * p[:, 1] ** 2)
    energy_scale = (np.abs(v0) * np.abs(p)).sum(axis=1) + (np.abs(va) * np.abs(p)).sum(axis=1)
    assert np.all(np.abs(r["energy_change"][ok] - dt) <= 1e-12 * energy_scale)
    works = r["work_compression"][ok] + r["work_restitution"][ok] + r["work_friction"][ok]
    assert np.all(np.abs(r["energy_change"][ok] - works) <= 1e-11 * energy_scale)
    # p_n ≥ 0 and the impact ends separating: v_n⁺ ≥ 0 (to round-off).
    assert np.all(p[:, 1] >= 0)
    assert np.all(va[:, 1] >= -1e-12 * scale)
    # Breakdowns carry no numbers; resolved rows carry no NaN.
    assert not np.isnan(r["energy_change"][ok]).any()
    assert np.isnan(r["energy_change"][~ok]).all()
    assert np.array_equal(r["energy_gained"], impax.STATUSES.index("energy-gained") == r["status"])


def test_energetic_never_gains_energy_whittaker_does():
    w, v, f, e = random_planar(np.random.default_rng(12), 200_000)
    en = impax.resolve_batch(w, v, f, e, "energetic")
    assert not en["energy_gained"].any()
    assert np.all(en["work_friction"][resolved(en)] <= 0)
    wh = impax.resolve_batch(w, v, f, e, "whittaker")
    assert wh["energy_gained"].mean() > 0.01  # Kane's paradox is common, not exotic


def test_frictionless_every_law_gives_the_same_normal_impulse():
    w, v, _, e = random_planar(np.random.default_rng(13), 5_000)
    expected = -(1 + e) * v[:, 1] / w[:, 2]
    for law in PLANAR:
        r = impax.resolve_batch(w, v, 0.0, e, law)
        assert np.all(resolved(r))
        assert np.allclose(r["impulse"][:, 1], expected, rtol=1e-12, atol=0)
        assert np.all(r["impulse"][:, 0] == 0)


def test_no_coupling_makes_newton_poisson_energetic_agree():
    w, v, f, e = random_planar(np.random.default_rng(14), 5_000)
    w[:, 1] = 0.0
    rs = [impax.resolve_batch(w, v, f, e, law) for law in ("newton", "poisson", "energetic")]
    for r in rs[1:]:
        assert np.allclose(r["impulse"], rs[0]["impulse"], rtol=1e-12, atol=1e-15)


def test_energetic_at_zero_restitution_ends_at_compression():
    w, v, f, _ = random_planar(np.random.default_rng(15), 5_000)
    r = impax.resolve_batch(w, v, f, 0.0, "energetic")
    assert np.allclose(r["impulse"][:, 1], r["compression_impulse"], rtol=1e-12, atol=0)


def test_mirror_symmetry():
    w, v, f, e = random_planar(np.random.default_rng(16), 5_000)
    wm, vm = w * [1, -1, 1], v * [-1, 1]
    for law in PLANAR:
        a = impax.resolve_batch(w, v, f, e, law)
        b = impax.resolve_batch(wm, vm, f, e, law)
        assert np.array_equal(a["status"], b["status"])
        ok = resolved(a)
        assert np.allclose(a["impulse"][ok] * [-1, 1], b["impulse"][ok], rtol=1e-12, atol=1e-14)


@pytest.mark.parametrize("law", PLANAR)
def test_batch_rows_equal_single_resolve_bit_for_bit(law):
    w, v, f, e = random_planar(np.random.default_rng(17), 300)
    r = impax.resolve_batch(w, v, f, e, law)
    for i in range(len(w)):
        o = impax.resolve(w[i], v[i], f[i], e[i], law)
        if o.verdict == "breakdown":
            assert impax.STATUSES[r["status"][i]] == "breakdown"
            assert o.impulse is None and o.energy_change is None
            continue
        assert impax.STATUSES[r["status"][i]] == o.verdict
        assert tuple(r["impulse"][i]) == o.impulse
        assert tuple(r["velocity_after"][i]) == o.velocity_after
        assert r["energy_change"][i] == o.energy_change
        assert r["work_friction"][i] == o.work["friction"]
        kinds = [p["kind"] for p in o.phases]
        seq = impax.SEQUENCES[r["sequence"][i]]
        if len(kinds) == 1:
            assert seq == {"stick": "stick", "no-slip": "no-slip"}.get(kinds[0], "slip")
        else:
            assert seq == ("slip-stick" if kinds[1] == "stick" else "slip-reverse")


def test_deterministic_across_thread_counts_and_chunks():
    w, v, f, e = random_planar(np.random.default_rng(18), 100_003)
    a = impax.resolve_batch(w, v, f, e, "energetic", threads=1)
    b = impax.resolve_batch(w, v, f, e, "energetic", threads=3)
    c = impax.resolve_batch(w, v, f, e, "energetic")
    for k in a:
        if k != "law":
            assert np.array_equal(a[k], b[k], equal_nan=True) and np.array_equal(a[k], c[k], equal_nan=True)
    part = impax.resolve_batch(w[50_000:], v[50_000:], f[50_000:], e[50_000:], "energetic")
    assert np.array_equal(part["impulse"], a["impulse"][50_000:], equal_nan=True)


def test_spatial_batch_embeds_planar():
    w, v, f, e = random_planar(np.random.default_rng(19), 2_000)
    w3 = np.stack([w[:, 0], np.zeros(len(w)), w[:, 1], np.full(len(w), 2.0), np.zeros(len(w)), w[:, 2]], axis=1)
    v3 = np.stack([v[:, 0], np.zeros(len(w)), v[:, 1]], axis=1)
    for law in impax.SPATIAL_LAWS:
        p2 = impax.resolve_batch(w, v, f, e, law)
        p3 = impax.resolve_batch(w3, v3, f, e, law)
        assert np.array_equal(p2["status"], p3["status"])
        ok = resolved(p2)
        assert np.allclose(p3["impulse"][ok][:, [0, 2]], p2["impulse"][ok], rtol=1e-10, atol=1e-12)
        assert np.all(np.abs(p3["impulse"][ok][:, 1]) <= 1e-12)


def test_spatial_energetic_never_gains():
    w, v, f, e = random_spatial(np.random.default_rng(20), 3_000)
    r = impax.resolve_batch(w, v, f, e, "energetic")
    assert np.all(resolved(r))
    assert not r["energy_gained"].any()
    assert np.all(r["energy_change"] <= 1e-12 * (np.abs(v) ** 2).sum(axis=1) * 10)


def test_scenario_helpers_equal_the_bodies():
    rng = np.random.default_rng(21)
    angle, speed, direction, omega = rng.uniform(0.1, 3.0, 50), rng.uniform(0.5, 2, 50), rng.uniform(-1, 1, 50), rng.uniform(-2, 2, 50)
    w, v, f, e = impax.study.rod_problems(angle, speed, direction, omega, mass=2.0, length=1.5, friction=0.3)
    for i in range(50):
        vx, vy = speed[i] * math.sin(direction[i]), -speed[i] * math.cos(direction[i])
        try:
            body = impax.rod(2.0, 1.5, angle[i], velocity=(vx, vy), omega=omega[i], friction=0.3)
        except ValueError:
            assert v[i, 1] >= 0  # not approaching: the body refuses, the batch marks it
            continue
        bw = body.w
        assert np.array_equal(w[i], [bw[0, 0], bw[0, 1], bw[1, 1]])
        assert tuple(v[i]) == body.v
    alpha, gamma = np.radians(np.linspace(0, 80, 9)), np.linspace(-2, 2, 9)
    w, v, f, e = impax.study.sphere_problems(alpha, gamma)
    for i in range(9):
        body = impax.sphere(alpha=alpha[i], spin_ratio=gamma[i])
        assert tuple(v[i]) == body.v and np.array_equal(w[i], body.w.ravel()[[0, 1, 3]])
    # γ = −sin α: no slip before, exactly (round-off is not a slip direction).
    w, v, f, e = impax.study.sphere_problems(np.radians(30), -math.sin(math.radians(30)))
    assert v[0, 0] == 0.0


def test_seed_grid_matches_paper_a_threshold():
    """On the seed's sphere, Whittaker gains energy exactly between the two roots of paper A
    eq. 13 (γ*₊ = 0.205811 at α = 30°): the batch's sign flips there."""
    gamma = np.array([0.2058, 0.2059])
    w, v, f, e = impax.study.sphere_problems(np.radians(30.0), gamma)
    r = impax.resolve_batch(w, v, f, e, "whittaker")
    assert r["energy_gained"].tolist() == [True, False]
