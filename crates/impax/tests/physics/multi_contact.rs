//! Several contacts at once (`impax::multi`): `lcp` and `sequential`, checked against
//! independent derivations, not against their own code.
//!
//! * `K = 1`: `lcp` is the one-contact `lcp` and `sequential` is `energetic`, to 1e-13, on
//!   random problems;
//! * decoupled contacts (block-diagonal `W`): each contact is its own one-contact law;
//! * Newton's cradle (three equal balls touching, `e = 1`, frictionless; `W = J M⁻¹ Jᵀ`
//!   derived here from the balls): `lcp` gives `(−1/3, 2/3, 2/3) v0`, `sequential`
//!   `(0, 0, 1) v0`, both conserving momentum and energy;
//! * a rod lying flat landing on both ends (four contact rows, rank-3 `W`, derived here):
//!   `lcp` gives the body `(0, e |v_y|, 0)` for every `e` and `μ`, `sequential` for `e = 0` and
//!   `e = 1` (for `0 < e < 1` the first end struck makes it rotate: the order matters); a
//!   sliding landing keeps the momentum balance `Σ p_t = −μ Σ p_n`;
//! * on random problems (`K = 2 … 4`, `W = J M⁻¹ Jᵀ` of random bodies, singular ones
//!   included): every `lcp` solution satisfies the conditions to 1e-12; the solutions equal
//!   those of an independent enumeration (every combination of modes solved through the
//!   pseudo-inverse of the full `2K × 2K` system, from the eigenvalues of `AᵀA`); every converged projected
//!   Gauss–Seidel run (the engines' iteration) ends on one of them, and on the only one without
//!   friction;
//! * `sequential` never gains energy (20,000 random problems) and no law's `consistent`
//!   result leaves a contact approaching;
//! * errors name their field; the one-contact laws are refused with two contacts.

use crate::support::{
    body_after, contact_space, cradle_jacobian, dump, flat, kinetic, random_multi, random_one,
    rod_jacobian, Random,
};
use impax::math::{SplitMix64, Vec2};
use impax::multi::{lcp, sequential, ContactPhaseKind, MultiDetail, MultiOutcome, MultiProblem};
use impax::planar::{ContactProblem, Verdict};
use impax::LawId;
use nalgebra::{DMatrix, DVector};

fn both(p: &MultiProblem) -> [MultiOutcome; 2] {
    [
        lcp::resolve(p).expect("lcp"),
        sequential::resolve(p).expect("sequential"),
    ]
}

// ---------------------------------------------------------------------------------------
// K = 1

/// `|x − y|` relative to `scale` below `tol`.
fn close(x: f64, y: f64, scale: f64, tol: f64) -> bool {
    (x - y).abs() <= tol * scale
}

#[test]
fn one_contact_lcp_is_the_planar_lcp_and_sequential_is_energetic() {
    let mut rng = SplitMix64(0x6d75_6c74);
    let mut worst = [0.0f64; 2];
    for _ in 0..20_000 {
        let one = random_one(&mut rng);
        let multi = MultiProblem::from_contact(&one).expect("one contact");
        for (n, (law, reference)) in [
            (LawId::Lcp, LawId::Lcp),
            (LawId::Sequential, LawId::Energetic),
        ]
        .into_iter()
        .enumerate()
        {
            let r = reference.resolve(&one).expect("reference");
            let m = law.resolve(&multi).expect("valid").expect("outcome");
            assert_eq!(m.law, law);
            let c = &m.contacts[0];
            let pscale = r.impulse.norm();
            let vscale = one.velocity().norm() + r.velocity_after.norm();
            let escale = pscale * vscale;
            let d = [
                (c.impulse - r.impulse).norm() / pscale,
                (c.velocity_after - r.velocity_after).norm() / vscale,
                (m.energy_change - r.energy_change).abs() / escale,
                (c.work.compression - r.work.compression).abs() / escale,
                (c.work.restitution - r.work.restitution).abs() / escale,
                (c.work.friction - r.work.friction).abs() / escale,
            ]
            .into_iter()
            .fold(0.0, f64::max);
            worst[n] = worst[n].max(d);
            assert!(d < 1e-13, "{law}: {d:e} from {reference} on {one:?}");
            assert_eq!(m.verdict, r.verdict, "{law} on {one:?}");
            if law == LawId::Sequential {
                let phases: Vec<_> = r
                    .phases
                    .as_slice()
                    .iter()
                    .map(|p| (ContactPhaseKind::from(p.kind), p.ends_at))
                    .collect();
                let mine: Vec<_> = c.phases.iter().map(|p| (p.kind, p.ends_at)).collect();
                assert_eq!(mine, phases);
            }
        }
    }
    println!(
        "K = 1: lcp within {:.1e} of the planar lcp, sequential within {:.1e} of energetic",
        worst[0], worst[1]
    );
}

#[test]
fn one_contact_laws_through_resolve_with_one_contact() {
    let mut rng = SplitMix64(5);
    for _ in 0..2000 {
        let one = random_one(&mut rng);
        let multi = MultiProblem::from_contact(&one).unwrap();
        // (`lcp` is the enumeration of `impax::multi::lcp`, compared above to round-off.)
        for law in LawId::CONTACT_SPACE
            .into_iter()
            .filter(|l| *l != LawId::Lcp)
        {
            let r = law.resolve(&one);
            let m = law.resolve(&multi).expect("one contact: every law");
            match (r, m) {
                (Ok(r), Ok(m)) => {
                    assert_eq!(m.contacts[0].impulse, r.impulse);
                    assert_eq!(m.energy_change, r.energy_change);
                    assert_eq!(m.verdict, r.verdict);
                }
                (Err(a), Err(b)) => assert_eq!(a, b),
                (r, m) => panic!("{law}: {r:?} vs {m:?}"),
            }
        }
    }
}

// ---------------------------------------------------------------------------------------
// Decoupled contacts

#[test]
fn decoupled_contacts_are_their_own_one_contact_problems() {
    let mut rng = SplitMix64(0xdec0);
    for trial in 0..3000 {
        let k = 2 + trial % 3;
        let ones: Vec<ContactProblem> = (0..k).map(|_| random_one(&mut rng)).collect();
        let multi = crate::support::block_diagonal(&ones);
        let [l, s] = both(&multi);
        for (j, one) in ones.iter().enumerate() {
            for (out, law) in [(&l, LawId::Lcp), (&s, LawId::Energetic)] {
                let r = law.resolve(one).unwrap();
                let c = &out.contacts[j];
                let pscale = r.impulse.norm();
                let vscale = one.velocity().norm() + r.velocity_after.norm();
                assert!(
                    (c.impulse - r.impulse).norm() <= 1e-12 * pscale,
                    "{law} contact {j}: {:?} vs {:?}",
                    c.impulse,
                    r.impulse
                );
                assert!((c.velocity_after - r.velocity_after).norm() <= 1e-12 * vscale);
            }
        }
        let sum: f64 = ones
            .iter()
            .map(|p| LawId::Energetic.resolve(p).unwrap().energy_change)
            .sum();
        assert!(close(s.energy_change, sum, sum.abs(), 1e-12));
        // One solution: the conditions separate.
        let MultiDetail::Lcp { solutions } = &l.detail else {
            panic!()
        };
        assert_eq!(solutions.len(), 1);
    }
}

#[test]
fn a_separating_decoupled_contact_stays_off() {
    // Contact 2 separates (v_n = +0.5) and is not coupled to contact 1.
    let p = MultiProblem::from_upper(
        2,
        &[2.0, 0.5, 0.0, 0.0, 1.5, 0.0, 0.0, 3.0, 0.2, 1.0],
        &[0.3, -1.0, -0.4, 0.5],
        &[0.3],
        &[0.5],
    )
    .unwrap();
    for o in both(&p) {
        let c = &o.contacts[1];
        assert_eq!(c.impulse, Vec2::zeros());
        assert_eq!(c.velocity_after, Vec2::new(-0.4, 0.5));
        assert_eq!(c.phases[0].kind, ContactPhaseKind::Off);
    }
}

// ---------------------------------------------------------------------------------------
// Newton's cradle

#[test]
fn newtons_cradle() {
    let (m, r, v0) = (1.3, 0.2, 0.7);
    let i = 0.4 * m * r * r;
    let masses = [m, m, i, m, m, i, m, m, i];
    let j = cradle_jacobian(r);
    let u = DVector::from_column_slice(&[v0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0]);
    let (w, v) = contact_space(&j, &masses, &u);
    // The normals: W_nn = 2/m, coupled by −1/m; ball 1 closing at v0.
    assert!((w[(1, 1)] - 2.0 / m).abs() < 1e-15 && (w[(1, 3)] + 1.0 / m).abs() < 1e-15);
    assert_eq!(v, vec![0.0, -v0, 0.0, 0.0]);
    let p = MultiProblem::new(w, &v, &[0.0], &[1.0]).unwrap();
    let [l, s] = both(&p);
    let t0 = kinetic(&masses, &u);
    for (o, expected) in [
        (&l, [-1.0 / 3.0, 2.0 / 3.0, 2.0 / 3.0]),
        (&s, [0.0, 0.0, 1.0]),
    ] {
        let ua = body_after(&j, &masses, &u, o);
        for b in 0..3 {
            assert!(
                (ua[3 * b] - expected[b] * v0).abs() < 1e-14,
                "{}: ball {} at {}",
                o.law,
                b + 1,
                ua[3 * b]
            );
            assert!(ua[3 * b + 1].abs() < 1e-15 && ua[3 * b + 2].abs() < 1e-15);
        }
        let momentum: f64 = (0..3).map(|b| m * ua[3 * b]).sum();
        assert!((momentum - m * v0).abs() < 1e-14);
        let t1 = kinetic(&masses, &ua);
        assert!((t1 - t0).abs() < 1e-14 * t0);
        assert!(o.energy_change.abs() < 1e-14 * t0);
        assert!((o.energy_change - (t1 - t0)).abs() < 1e-14 * t0);
        assert_eq!(o.verdict, Verdict::Consistent);
    }
    let MultiDetail::Sequential { impacts } = &s.detail else {
        panic!()
    };
    assert_eq!(
        impacts.iter().map(|b| b.contact).collect::<Vec<_>>(),
        vec![0, 1]
    );
    let MultiDetail::Lcp { solutions } = &l.detail else {
        panic!()
    };
    assert_eq!(solutions.len(), 1);
}

// ---------------------------------------------------------------------------------------
// A rod lying flat

#[test]
fn rod_landing_flat() {
    let (m, l) = (2.5, 0.8);
    let masses = [m, m, m * l * l / 12.0];
    let j = rod_jacobian(l);
    for vy in [-1.0, -3.7] {
        let u = DVector::from_column_slice(&[0.0, vy, 0.0]);
        let (w, v) = contact_space(&j, &masses, &u);
        for e in [0.0, 0.3, 0.8, 1.0] {
            for mu in [0.0, 0.2, 1.0] {
                let p = MultiProblem::new(w.clone(), &v, &[mu], &[e]).unwrap();
                assert_eq!(p.rank(), 3);
                let mut laws = vec![lcp::resolve(&p).unwrap()];
                if e == 0.0 || e == 1.0 {
                    laws.push(sequential::resolve(&p).unwrap());
                }
                for o in &laws {
                    let ua = body_after(&j, &masses, &u, o);
                    let expected = [0.0, e * vy.abs(), 0.0];
                    for k in 0..3 {
                        assert!(
                            (ua[k] - expected[k]).abs() < 1e-9 * vy.abs(),
                            "{} e = {e}, μ = {mu}: {ua:?}",
                            o.law
                        );
                    }
                    assert_ne!(o.verdict, Verdict::EnergyGained);
                }
                if e > 0.0 && e < 1.0 {
                    // The binary impacts break the symmetry: the rod leaves rotating.
                    let ua = body_after(&j, &masses, &u, &sequential::resolve(&p).unwrap());
                    assert!(ua[2].abs() > 1e-3 * vy.abs() / l, "{ua:?}");
                }
                // lcp: one solution, the normal impulses (1 + e) m |v_y| / 2 each, the
                // tangential ones the least-norm split (zero).
                let o = &laws[0];
                let MultiDetail::Lcp { solutions } = &o.detail else {
                    panic!()
                };
                assert_eq!(solutions.len(), 1);
                for c in &o.contacts {
                    assert!(
                        (c.impulse.y - 0.5 * (1.0 + e) * m * vy.abs()).abs() < 1e-12 * m * vy.abs()
                    );
                    assert!(c.impulse.x.abs() < 1e-12 * m * vy.abs());
                }
            }
        }
    }
}

#[test]
fn rod_landing_flat_while_sliding() {
    // v_x ≠ 0: enough friction stops the slide (stick), less lets it slide with
    // Σ p_t = −μ Σ p_n (the cone at both ends: the tangential split is not unique).
    let (m, l) = (1.0, 1.0);
    let masses = [m, m, m * l * l / 12.0];
    let j = rod_jacobian(l);
    let (vx, vy, e) = (0.5, -1.0, 0.5);
    let u = DVector::from_column_slice(&[vx, vy, 0.0]);
    let (w, v) = contact_space(&j, &masses, &u);
    for mu in [0.1, 0.2, 1.0 / 3.0, 0.5, 2.0] {
        let p = MultiProblem::new(w.clone(), &v, &[mu], &[e]).unwrap();
        let o = lcp::resolve(&p).unwrap();
        let ua = body_after(&j, &masses, &u, &o);
        let total_n = (1.0 + e) * m * vy.abs();
        let vx_after = (vx - mu * total_n / m).max(0.0);
        assert!((ua[0] - vx_after).abs() < 1e-12, "μ = {mu}: {ua:?}");
        assert!(
            (ua[1] - e * vy.abs()).abs() < 1e-12 && ua[2].abs() < 1e-12,
            "μ = {mu}: {ua:?}"
        );
        let pt: f64 = o.contacts.iter().map(|c| c.impulse.x).sum();
        assert!((pt + m * (vx - vx_after)).abs() < 1e-12);
        for c in &o.contacts {
            assert!(c.impulse.x.abs() <= mu * c.impulse.y * (1.0 + 1e-12));
        }
        let MultiDetail::Lcp { solutions } = &o.detail else {
            panic!()
        };
        assert_eq!(solutions.len(), 1, "μ = {mu}");
    }
}

// ---------------------------------------------------------------------------------------
// Random problems: W = J M⁻¹ Jᵀ of random bodies (singular when the contacts outnumber the
// degrees of freedom), v = J u.

/// The largest violation of the conditions by the impulses `p` (with `v⁺ = v⁻ + W p`
/// recomputed here), relative to the impulse and velocity scales, and whether the contact
/// regimes reported agree with it.
fn violation(r: &Random, p: &DVector<f64>) -> f64 {
    let k = r.problem.contacts();
    let va = &r.v + &r.w * p;
    let pscale = p.amax().max(1e-300);
    let vscale = (0..2 * k)
        .map(|i| {
            r.v[i].abs()
                + (0..2 * k)
                    .map(|c| r.w[(i, c)].abs() * p[c].abs())
                    .sum::<f64>()
        })
        .fold(0.0, f64::max);
    let mut worst = 0.0f64;
    for c in 0..k {
        let (pt, pn, vt, vn) = (p[2 * c], p[2 * c + 1], va[2 * c], va[2 * c + 1]);
        let gap = vn - r.b[c];
        worst = worst
            .max(-pn / pscale)
            .max(-gap / vscale)
            .max((pn / pscale) * (gap.abs() / vscale))
            .max((pt.abs() - r.mu[c] * pn) / pscale);
        // Stick, or friction on the cone against the slip after.
        let on_cone = (pt.abs() - r.mu[c] * pn).abs() / pscale;
        let stick = vt.abs() / vscale;
        let against = (pt * vt).max(0.0) / (pscale * vscale);
        worst = worst.max(stick.min(on_cone.max(against)));
    }
    worst
}

#[test]
fn lcp_solutions_satisfy_the_conditions_on_random_problems() {
    let mut rng = SplitMix64(0x1c92);
    let (mut worst, mut several, mut singular, mut offs, mut wedged) = (0.0f64, 0, 0, 0, 0);
    for trial in 0..20_000 {
        let k = 2 + trial % 3;
        let r = random_multi(&mut rng, k);
        if r.problem.rank() < 2 * k {
            singular += 1;
        }
        let o = match lcp::resolve(&r.problem) {
            Ok(o) => o,
            Err(b) => {
                // No solution exists when redundant contacts wedge: impulses inside the
                // friction cones that exert no net force (Jᵀ p = 0) at contacts with a
                // positive Newton target (Anitescu & Potra's solvability condition fails).
                // Only with a singular W, friction, and restitution.
                assert_eq!(b.reason.id(), "no-solution");
                assert!(r.problem.rank() < 2 * k, "{b}: {}", dump(&r));
                assert!(r.mu.iter().any(|m| *m > 0.0) && r.b.iter().any(|b| *b > 0.0));
                let e = vec![0.0; k];
                let plastic = MultiProblem::new(r.w.clone(), r.v.as_slice(), &r.mu, &e).unwrap();
                assert!(lcp::resolve(&plastic).is_ok(), "e = 0 has a solution");
                wedged += 1;
                continue;
            }
        };
        let MultiDetail::Lcp { solutions } = &o.detail else {
            panic!()
        };
        if solutions.len() > 1 {
            several += 1;
            assert!(matches!(
                o.verdict,
                Verdict::EnergyGained | Verdict::InconsistentAssumption
            ));
        }
        for s in solutions {
            let d = violation(&r, &flat(&s.impulses));
            worst = worst.max(d);
            assert!(d < 1e-12, "violation {d:e} on {:?}", r.problem);
            // The reported velocities are v⁻ + W p.
            let va = &r.v + &r.w * flat(&s.impulses);
            let scale = r.v.amax() + (&r.w.abs() * flat(&s.impulses).abs()).amax();
            assert!((flat(&s.velocities_after) - va).amax() <= 1e-12 * scale);
            offs += s
                .regimes
                .iter()
                .filter(|x| **x == ContactPhaseKind::Off)
                .count();
            // ΔT identity.
            let dt = r.problem.energy_change(&s.impulses);
            assert!((dt - s.energy_change).abs() <= 1e-12 * scale * flat(&s.impulses).amax());
        }
        // The result is the least kinetic energy after.
        assert_eq!(o.energy_change, solutions[0].energy_change);
        assert!(solutions
            .windows(2)
            .all(|w| w[0].energy_change <= w[1].energy_change));
    }
    println!("lcp: 20000 random problems ({singular} with singular W), {several} with several solutions, {offs} contacts off, {wedged} wedged (no solution); worst violation {worst:.1e}");
    assert!(singular > 3000 && offs > 1000);
}

/// The conditions solved independently: every combination of modes as one 2K × 2K linear
/// system (identity rows for the impulses a mode fixes, rows of W for the velocities) through
/// its pseudo-inverse, the inequalities checked to `tol`.
#[allow(clippy::needless_range_loop)] // c indexes the contacts' modes, rows and coefficients
fn independent_solutions(r: &Random, tol: f64) -> Vec<DVector<f64>> {
    let k = r.problem.contacts();
    let n = 2 * k;
    let mut out: Vec<DVector<f64>> = Vec::new();
    let radix: Vec<usize> = r.mu.iter().map(|m| if *m > 0.0 { 4 } else { 2 }).collect();
    let total: usize = radix.iter().product();
    for mut code in 0..total {
        let mut modes = vec![0usize; k];
        for c in 0..k {
            modes[c] = code % radix[c];
            code /= radix[c];
            if radix[c] == 2 && modes[c] == 1 {
                modes[c] = 4; // frictionless: off or free
            }
        }
        let mut a = DMatrix::zeros(n, n);
        let mut rhs = DVector::zeros(n);
        for c in 0..k {
            let (t, nn) = (2 * c, 2 * c + 1);
            match modes[c] {
                0 => {
                    a[(t, t)] = 1.0;
                    a[(nn, nn)] = 1.0;
                }
                1 => {
                    a.set_row(t, &r.w.row(t));
                    rhs[t] = -r.v[t];
                }
                2 | 3 => {
                    let s = if modes[c] == 2 { 1.0 } else { -1.0 };
                    a[(t, t)] = 1.0;
                    a[(t, nn)] = s * r.mu[c];
                }
                _ => a[(t, t)] = 1.0,
            }
            if modes[c] != 0 {
                a.set_row(nn, &r.w.row(nn));
                rhs[nn] = r.b[c] - r.v[nn];
            }
        }
        // Nonsingular: LU with full pivoting. Singular: least squares, least norm,
        // p = Σ v_k (v_k·Aᵀr)/λ_k over the eigenpairs of AᵀA. (Not nalgebra's SVD, which
        // recomposes some of these matrices only to 3e-3.)
        let ata = a.transpose() * &a;
        let atr = a.transpose() * &rhs;
        let eig = ata.symmetric_eigen();
        let lmax = eig.eigenvalues.max();
        let lu = (eig.eigenvalues.min() > 1e-14 * lmax)
            .then(|| a.clone().full_piv_lu().solve(&rhs))
            .flatten();
        let p = if let Some(p) = lu {
            p
        } else {
            let mut p = DVector::zeros(n);
            for c in 0..n {
                let l = eig.eigenvalues[c];
                if l > 1e-14 * lmax {
                    let vk = eig.eigenvectors.column(c);
                    p += vk * (vk.dot(&atr) / l);
                }
            }
            p
        };
        let va = &r.v + &r.w * &p;
        let pscale = p.amax().max(1e-300);
        let vscale = r.v.amax() + (&r.w.abs() * p.abs()).amax();
        if (&a * &p - &rhs).amax() > tol * (vscale + pscale) {
            continue;
        }
        let mut ok = true;
        for c in 0..k {
            let (pt, pn, vt, vn) = (p[2 * c], p[2 * c + 1], va[2 * c], va[2 * c + 1]);
            ok &= match modes[c] {
                0 => vn >= r.b[c] - tol * vscale,
                1 => pn >= -tol * pscale && pt.abs() <= r.mu[c] * pn + tol * pscale,
                2 => pn >= -tol * pscale && vt >= -tol * vscale,
                3 => pn >= -tol * pscale && vt <= tol * vscale,
                _ => pn >= -tol * pscale,
            };
        }
        // Distinct beyond 1e-9 of the velocities' own size (not of |W| |p|: an
        // ill-conditioned W has solutions with large impulses whose velocities are exact
        // to round-off all the same).
        let own = r.v.amax() + va.amax();
        if ok && !out.iter().any(|x| (x - &va).amax() <= 1e-9 * own) {
            out.push(va);
        }
    }
    out
}

#[test]
fn lcp_matches_an_independent_enumeration() {
    let mut rng = SplitMix64(0xe4e);
    let mut several = 0;
    for trial in 0..3000 {
        let k = 2 + trial % 3;
        let r = random_multi(&mut rng, k);
        let mine: Vec<DVector<f64>> = lcp::solutions(&r.problem)
            .iter()
            .map(|s| flat(&s.velocities_after))
            .collect();
        let scale = r.v.amax() + mine.iter().map(|x| x.amax()).fold(0.0, f64::max);
        let strict = independent_solutions(&r, 1e-10);
        let loose = independent_solutions(&r, 1e-7);
        for x in &strict {
            assert!(
                mine.iter().any(|m| (m - x).amax() <= 1e-7 * scale),
                "independent solution {x:?} missing from {mine:?} ({})",
                dump(&r)
            );
        }
        for m in &mine {
            assert!(
                loose.iter().any(|x| (m - x).amax() <= 1e-7 * scale),
                "solution {m:?} not found independently ({loose:?}; {})",
                dump(&r)
            );
        }
        if mine.len() > 1 {
            several += 1;
        }
    }
    println!("lcp = independent enumeration on 3000 problems ({several} with several solutions)");
}

/// Projected Gauss–Seidel, the engines' iteration: each contact in turn, its normal impulse
/// projected on `p_n ≥ 0` towards `v_n⁺ = b`, its tangential impulse on the cone towards
/// `v_t⁺ = 0`. `None` if it has not converged after `sweeps`.
fn pgs(r: &Random, sweeps: usize) -> Option<DVector<f64>> {
    let k = r.problem.contacts();
    let mut p: DVector<f64> = DVector::zeros(2 * k);
    let mut v = r.v.clone();
    let scale = r.v.amax();
    for _ in 0..sweeps {
        let mut change = 0.0f64;
        for c in 0..k {
            let (t, n) = (2 * c, 2 * c + 1);
            let pn = (p[n] - (v[n] - r.b[c]) / r.w[(n, n)]).max(0.0);
            let dn = pn - p[n];
            p[n] = pn;
            v += r.w.column(n) * dn;
            let pt = (p[t] - v[t] / r.w[(t, t)]).clamp(-r.mu[c] * p[n], r.mu[c] * p[n]);
            let dt = pt - p[t];
            p[t] = pt;
            v += r.w.column(t) * dt;
            change = change
                .max((r.w.column(n) * dn).amax())
                .max((r.w.column(t) * dt).amax());
        }
        if change <= 1e-15 * scale {
            return Some(v);
        }
    }
    None
}

#[test]
fn converged_projected_gauss_seidel_ends_on_an_lcp_solution() {
    let mut rng = SplitMix64(0x96a);
    let (mut converged, mut frictionless) = (0, 0);
    for trial in 0..3000 {
        let k = 2 + trial % 3;
        let mut r = random_multi(&mut rng, k);
        if trial % 2 == 0 {
            // Frictionless: one solution in velocities, which PGS reaches.
            r.mu = vec![0.0; k];
            let e: Vec<f64> = (0..k).map(|c| r.problem.restitution(c)).collect();
            r.problem = MultiProblem::new(r.w.clone(), r.v.as_slice(), &r.mu, &e).unwrap();
        }
        let mine = lcp::solutions(&r.problem);
        let Some(v) = pgs(&r, 200_000) else {
            // Frictionless with a positive definite W: Gauss–Seidel on a strictly convex
            // problem, which converges (slowly, or not to 1e-15, when W is singular).
            assert!(
                trial % 2 == 1 || r.problem.rank() < 2 * k,
                "frictionless PGS did not converge: {}",
                dump(&r)
            );
            continue;
        };
        converged += 1;
        let scale = r.v.amax() + v.amax();
        if trial % 2 == 0 {
            frictionless += 1;
            assert_eq!(mine.len(), 1, "frictionless: one solution, {mine:?}");
        }
        assert!(
            mine.iter()
                .any(|s| (flat(&s.velocities_after) - &v).amax() <= 1e-8 * scale),
            "PGS ended at {v:?}, not among {:?}",
            mine.iter()
                .map(|s| flat(&s.velocities_after))
                .collect::<Vec<_>>()
        );
    }
    println!("PGS converged on {converged} of 3000 problems ({frictionless} frictionless), each on an lcp solution");
}

// ---------------------------------------------------------------------------------------
// Energy and approach

#[test]
fn sequential_never_gains_energy_and_no_consistent_result_approaches() {
    let mut rng = SplitMix64(0x5e9);
    let (mut impacts, mut most, mut breakdowns) = (0usize, 0usize, 0);
    // Sequences cut at 10⁴ binary impacts: with W positive definite, with W singular.
    let mut unsettled = [0usize; 2];
    let mut verdicts = [0usize; 3];
    for trial in 0..20_000 {
        let k = 2 + trial % 3;
        let r = random_multi(&mut rng, k);
        for law in [LawId::Lcp, LawId::Sequential] {
            let o = match law.resolve(&r.problem).unwrap() {
                Ok(o) => o,
                Err(b) => {
                    // lcp: no solution when redundant contacts wedge (above). sequential:
                    // a sequence that does not settle within its bound.
                    match law {
                        LawId::Lcp => {
                            assert!(r.problem.rank() < 2 * k, "{b}: {}", dump(&r));
                            breakdowns += 1;
                        }
                        _ => {
                            assert_eq!(b.reason.id(), "too-many-impacts");
                            unsettled[usize::from(r.problem.rank() < 2 * k)] += 1;
                        }
                    }
                    continue;
                }
            };
            let p = flat(&o.impulses());
            let scale = r.v.amax() + (&r.w.abs() * p.abs()).amax();
            if o.verdict == Verdict::Consistent {
                for c in &o.contacts {
                    assert!(
                        c.velocity_after.y >= -1e-9 * scale,
                        "{law} consistent and approaching: {:?}",
                        r.problem
                    );
                }
            }
            if law == LawId::Sequential {
                assert_ne!(o.verdict, Verdict::EnergyGained, "{:?}", r.problem);
                assert!(o.energy_change <= 1e-13 * scale * p.amax());
                // Works sum to ΔT; ΔT from the body velocities (exact identity).
                let total: f64 = o.contacts.iter().map(|c| c.work.total()).sum();
                assert!((total - o.energy_change).abs() <= 1e-10 * scale * p.amax());
                let dt = r.problem.energy_change(&o.impulses());
                assert!((dt - o.energy_change).abs() <= 1e-10 * scale * p.amax());
                let MultiDetail::Sequential { impacts: list } = &o.detail else {
                    panic!()
                };
                impacts += list.len();
                most = most.max(list.len());
                verdicts[match o.verdict {
                    Verdict::Consistent => 0,
                    Verdict::EnergyGained => 1,
                    Verdict::InconsistentAssumption => 2,
                }] += 1;
            }
        }
    }
    println!("sequential: 20000 problems, {impacts} binary impacts (at most {most} in one), verdicts {verdicts:?}, {unsettled:?} cut at 10⁴ impacts (W positive definite, singular); lcp: {breakdowns} without solution");
    assert_eq!(verdicts[1], 0);
    assert!(unsettled[0] + unsettled[1] < 100, "{unsettled:?}");
}

// ---------------------------------------------------------------------------------------
// Errors

#[test]
fn errors_name_their_field() {
    let rod = [1.0, 0.0, 1.0, 0.0, 4.0, 0.0, -2.0, 1.0, 0.0, 4.0];
    let v = [0.0, -1.0, 0.0, -1.0];
    let field = |r: impax::Result<MultiProblem>| r.unwrap_err().field().to_string();
    let mut w = rod;
    w[4] = f64::NAN;
    assert_eq!(
        field(MultiProblem::from_upper(2, &w, &v, &[0.5], &[0.5])),
        "w[n1,n1]"
    );
    assert_eq!(
        field(MultiProblem::from_upper(2, &rod[..9], &v, &[0.5], &[0.5])),
        "w"
    );
    // Indefinite: the ends coupled by −5 > √(4·4).
    let mut w = rod;
    w[6] = -5.0;
    let e = MultiProblem::from_upper(2, &w, &v, &[0.5], &[0.5]).unwrap_err();
    assert_eq!(e.field(), "w");
    assert!(e.to_string().contains("semidefinite"), "{e}");
    // A contact's own block not positive definite.
    let mut w = rod;
    w[1] = 2.0;
    let e = MultiProblem::from_upper(2, &w, &v, &[0.5], &[0.5]).unwrap_err();
    assert!(e.to_string().contains("contact 1's own block"), "{e}");
    // Not J u for the rod (v_t1 ≠ v_t2).
    let e = MultiProblem::from_upper(2, &rod, &[0.3, -1.0, 0.0, -1.0], &[0.5], &[0.5]).unwrap_err();
    assert_eq!(e.field(), "v");
    assert!(e.to_string().contains("rank 3 of 4"), "{e}");
    assert_eq!(
        field(MultiProblem::from_upper(
            2,
            &rod,
            &[0.0, -1.0, 0.0, f64::NAN],
            &[0.5],
            &[0.5]
        )),
        "v[n,2]"
    );
    assert_eq!(
        field(MultiProblem::from_upper(
            2,
            &rod,
            &[0.0, 1.0, 0.0, 1.0],
            &[0.5],
            &[0.5]
        )),
        "v"
    );
    assert_eq!(
        field(MultiProblem::from_upper(2, &rod, &v, &[0.5, -0.1], &[0.5])),
        "friction[2]"
    );
    assert_eq!(
        field(MultiProblem::from_upper(2, &rod, &v, &[-0.5], &[0.5])),
        "friction"
    );
    assert_eq!(
        field(MultiProblem::from_upper(2, &rod, &v, &[0.5], &[0.5, 1.5])),
        "restitution[2]"
    );
    assert_eq!(
        field(MultiProblem::from_upper(
            2,
            &rod,
            &v,
            &[0.5],
            &[0.5, 0.5, 0.5]
        )),
        "restitution"
    );
    // The laws.
    let p = MultiProblem::from_upper(2, &rod, &v, &[0.5], &[0.5]).unwrap();
    for law in LawId::ALL.into_iter().filter(|l| !l.is_multi_contact()) {
        let e = law.resolve(&p).unwrap_err();
        assert_eq!(e.field(), "law");
        assert!(e.to_string().contains(law.as_str()), "{e}");
    }
    let k = 7;
    let mut w = DMatrix::identity(2 * k, 2 * k);
    w[(1, 3)] = 0.1;
    w[(3, 1)] = 0.1;
    let mut v = vec![0.0; 2 * k];
    v[1] = -1.0;
    let p = MultiProblem::new(w, &v, &[0.3], &[0.5]).unwrap();
    let e = LawId::Lcp.resolve(&p).unwrap_err();
    assert!(e.to_string().contains("at most 6"), "{e}");
    assert_eq!(
        lcp::resolve(&p).unwrap_err().reason.id(),
        "too-many-contacts"
    );
    assert!(LawId::Sequential.resolve(&p).unwrap().is_ok());
}

#[test]
fn sequential_is_energetic_for_one_contact_everywhere() {
    use impax::spatial;
    let p = ContactProblem::from_entries(2.0, 0.5, 1.5, 0.3, -1.0, 0.3, 0.5).unwrap();
    let (s, e) = (
        LawId::Sequential.resolve(&p).unwrap(),
        LawId::Energetic.resolve(&p).unwrap(),
    );
    assert_eq!(s.law, LawId::Sequential);
    assert_eq!(s.impulse, e.impulse);
    let p3 = spatial::ContactProblem::from_upper(
        [2.0, 0.3, 0.1, 1.5, 0.2, 1.0],
        [0.5, 0.2, -1.0],
        0.5,
        0.6,
    )
    .unwrap();
    let (s, e) = (
        LawId::Sequential.resolve(&p3).unwrap(),
        LawId::Energetic.resolve(&p3).unwrap(),
    );
    assert_eq!(s.law, LawId::Sequential);
    assert_eq!(s.impulse, e.impulse);
    assert_eq!("sequential".parse::<LawId>().unwrap(), LawId::Sequential);
    assert!(!LawId::ALL.contains(&LawId::Sequential));
}
