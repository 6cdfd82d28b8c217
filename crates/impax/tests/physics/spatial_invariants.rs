//! Invariant slip directions and the resumption direction (theory §2, "Spatial").
//!
//! With `g(ŝ) = w_tn − μ W_tt ŝ`, a slip direction `ŝ = (cos φ, sin φ)` is invariant when
//! `f(φ) = ŝ × g(ŝ) = 0`; it is centripetal when `ŝ·g < 0`, centrifugal when `ŝ·g > 0`.
//! Everything here is recomputed by the test from `W` (no library formula):
//!
//! * `invariant_rays` on 4,000 random problems (`μ ∈ [0, 2]`, about 8 % `μ = 0`):
//!   every ray has `|f(φ)| ≤ 1e-12 (|w_tn| + μ |W_tt|)`, `φ ∈ [0, 2π)`, the right type and
//!   rate `ŝ·g`; the number of rays equals the number of sign changes of `f` on a dense scan
//!   of 20,000 angles, and every root bisected on the scan lies within `1e-8` rad of a ray
//!   (problems whose scan has a near-double root, `|f| < 1e-9` scale at a local minimum of
//!   `|f|` with no sign change, are counted and skipped: they are not generic);
//! * special structures: isotropic `W_tt` with `w_tn = 0` gives `All` (no swirl);
//!   `w_tn = 0` with anisotropic `W_tt` gives the four eigen-directions, all centripetal;
//!   `μ = 0` gives the two rays `±ŵ_tn` (centrifugal along `+ŵ_tn`);
//! * `sticking_ratio = −W_tt⁻¹ w_tn` (2×2 inverse by hand);
//! * `resumption_direction` on the same problems: when `|W_tt⁻¹ w_tn| > μ` it returns
//!   `(ŝ, λ')` with `|ŝ| = 1`, `λ' > 0`, `|(λ'I + μW_tt) ŝ − w_tn| ≤ 1e-12` of the size of
//!   the terms, `λ'` equal to the test's own bisection root of `|(λ'I + μW_tt)⁻¹ w_tn| = 1`
//!   to 1e-10, and `ŝ` is the one and only centrifugal invariant ray; when
//!   `|W_tt⁻¹ w_tn| < μ` it returns `None` and there is no centrifugal ray (cases within
//!   1e-9 of the boundary are skipped).

use impax::math::SplitMix64;
use impax::spatial::{
    invariant_rays, resumption_direction, sticking_ratio, ContactProblem, InvariantRays, RayKind,
};
use std::f64::consts::{PI, TAU};

const PROBLEMS: usize = 3_000;
const SCAN: usize = 4_096;

/// The tangential data of a problem: `W_tt`, `w_tn`, `μ`.
#[derive(Debug, Clone, Copy)]
struct Field {
    a: [[f64; 2]; 2],
    w: [f64; 2],
    mu: f64,
}

impl Field {
    fn of(p: &ContactProblem) -> Self {
        let m = p.w();
        Field {
            a: [[m[(0, 0)], m[(0, 1)]], [m[(1, 0)], m[(1, 1)]]],
            w: [m[(0, 2)], m[(1, 2)]],
            mu: p.friction(),
        }
    }
    fn g(&self, s: [f64; 2]) -> [f64; 2] {
        [
            self.w[0] - self.mu * (self.a[0][0] * s[0] + self.a[0][1] * s[1]),
            self.w[1] - self.mu * (self.a[1][0] * s[0] + self.a[1][1] * s[1]),
        ]
    }
    /// `(f, q) = (ŝ × g, ŝ·g)` at angle `φ`.
    fn fq(&self, phi: f64) -> (f64, f64) {
        let s = [phi.cos(), phi.sin()];
        let g = self.g(s);
        (s[0] * g[1] - s[1] * g[0], s[0] * g[0] + s[1] * g[1])
    }
    fn scale(&self) -> f64 {
        let a = &self.a;
        self.w[0].hypot(self.w[1])
            + self.mu
                * (a[0][0] * a[0][0] + a[1][1] * a[1][1] + a[0][1] * a[0][1] + a[1][0] * a[1][0])
                    .sqrt()
    }
    /// `W_tt⁻¹ w_tn`.
    fn att_inv_w(&self) -> [f64; 2] {
        let a = &self.a;
        let det = a[0][0] * a[1][1] - a[0][1] * a[1][0];
        [
            (a[1][1] * self.w[0] - a[0][1] * self.w[1]) / det,
            (-a[1][0] * self.w[0] + a[0][0] * self.w[1]) / det,
        ]
    }
    /// `|(λI + μW_tt)⁻¹ w_tn|`.
    fn shifted_norm(&self, l: f64) -> f64 {
        let m = [
            [l + self.mu * self.a[0][0], self.mu * self.a[0][1]],
            [self.mu * self.a[1][0], l + self.mu * self.a[1][1]],
        ];
        let det = m[0][0] * m[1][1] - m[0][1] * m[1][0];
        let x = [
            (m[1][1] * self.w[0] - m[0][1] * self.w[1]) / det,
            (-m[1][0] * self.w[0] + m[0][0] * self.w[1]) / det,
        ];
        x[0].hypot(x[1])
    }
    /// The root `λ' > 0` of `|(λ'I + μW_tt)⁻¹ w_tn| = 1`, by bisection.
    fn resumption_rate(&self) -> f64 {
        let (mut lo, mut hi) = (0.0f64, self.w[0].hypot(self.w[1]));
        loop {
            let mid = 0.5 * (lo + hi);
            if mid <= lo || mid >= hi {
                return hi;
            }
            if self.shifted_norm(mid) > 1.0 {
                lo = mid;
            } else {
                hi = mid;
            }
        }
    }
}

/// A random problem: `W_tt = R diag(d1, d2) Rᵀ`, `w_tn = ρ √w_nn W_tt^{1/2} û`.
fn random_problem(rng: &mut SplitMix64) -> ContactProblem {
    let d1 = rng.decades(-1.0, 1.0);
    let d2 = d1 * rng.decades(0.0, 2.0);
    let th = rng.range(0.0, PI);
    let (s, c) = th.sin_cos();
    let a00 = c * c * d1 + s * s * d2;
    let a01 = c * s * (d1 - d2);
    let a11 = s * s * d1 + c * c * d2;
    let (r1, r2) = (d1.sqrt(), d2.sqrt());
    let h00 = c * c * r1 + s * s * r2;
    let h01 = c * s * (r1 - r2);
    let h11 = s * s * r1 + c * c * r2;
    let wnn = rng.decades(-1.0, 1.0);
    let rho = rng.range(0.0, 0.999);
    let (uy, ux) = rng.range(0.0, TAU).sin_cos();
    let k = rho * wnn.sqrt();
    let w = [k * (h00 * ux + h01 * uy), k * (h01 * ux + h11 * uy)];
    let u = rng.unit();
    let mu = if u < 0.08 {
        0.0
    } else if u < 0.5 {
        // Around the stick limit |W_tt⁻¹ w_tn|, so that both sides are well represented.
        let det = a00 * a11 - a01 * a01;
        let l = ((a11 * w[0] - a01 * w[1]) / det).hypot((-a01 * w[0] + a00 * w[1]) / det);
        (l * rng.decades(-0.5, 0.5)).min(2.0)
    } else {
        rng.range(0.0, 2.0)
    };
    ContactProblem::from_upper([a00, a01, w[0], a11, w[1], wnn], [0.3, -0.2, -1.0], mu, 0.5)
        .expect("valid by construction")
}

fn angle_gap(a: f64, b: f64) -> f64 {
    let d = (a - b).rem_euclid(TAU);
    d.min(TAU - d)
}

#[test]
fn invariant_rays_are_the_roots_of_f_found_by_a_dense_scan() {
    let mut rng = SplitMix64(0x1A7A_21A7_0000_0004);
    let mut failures = Vec::new();
    let (mut skipped, mut checked, mut rays_seen) = (0usize, 0usize, [0usize; 5]);
    let mut worst_f = 0.0f64;
    for case in 0..PROBLEMS {
        let p = random_problem(&mut rng);
        let fd = Field::of(&p);
        let scale = fd.scale();
        let rays = match invariant_rays(&p) {
            InvariantRays::All => {
                failures.push(format!("case {case}: All for a generic problem {p:?}"));
                continue;
            }
            r => r,
        };
        let rays = rays.as_slice();
        rays_seen[rays.len()] += 1;
        for r in rays {
            let (f, q) = fd.fq(r.angle);
            worst_f = worst_f.max(f.abs() / scale);
            let kind = if q < 0.0 {
                RayKind::Centripetal
            } else {
                RayKind::Centrifugal
            };
            if f.abs() > 1e-12 * scale
                || f.is_nan()
                || !(0.0..TAU).contains(&r.angle)
                || (q.abs() > 1e-12 * scale && r.kind != kind)
                || (r.rate - q).abs() > 1e-12 * scale
            {
                failures.push(format!(
                    "case {case}: ray {r:?} has f = {f:e}, ŝ·g = {q:e} (scale {scale:e}): {p:?}"
                ));
            }
        }
        // Dense scan of f.
        let vals: Vec<f64> = (0..SCAN)
            .map(|i| fd.fq(TAU * i as f64 / SCAN as f64).0)
            .collect();
        let mut roots = Vec::new();
        let mut near_double = false;
        for i in 0..SCAN {
            let (fa, fb) = (vals[i], vals[(i + 1) % SCAN]);
            let (a, b) = (
                TAU * i as f64 / SCAN as f64,
                TAU * (i + 1) as f64 / SCAN as f64,
            );
            if (fa < 0.0) != (fb < 0.0) {
                let up = fa < 0.0;
                let (mut lo, mut hi) = (a, b);
                loop {
                    let mid = 0.5 * (lo + hi);
                    if mid <= lo || mid >= hi {
                        break;
                    }
                    let fm = fd.fq(mid).0;
                    if (fm >= 0.0) == up {
                        hi = mid;
                    } else {
                        lo = mid;
                    }
                }
                roots.push(hi);
            } else {
                let fp = vals[(i + SCAN - 1) % SCAN];
                if fa.abs() <= fp.abs() && fa.abs() <= fb.abs() && fa.abs() < 1e-9 * scale {
                    near_double = true;
                }
            }
        }
        if near_double {
            skipped += 1;
            continue;
        }
        checked += 1;
        if roots.len() != rays.len() {
            failures.push(format!(
                "case {case}: {} rays {:?} but {} sign changes at {roots:?}: {p:?}",
                rays.len(),
                rays.iter().map(|r| r.angle).collect::<Vec<_>>(),
                roots.len()
            ));
            continue;
        }
        for x in &roots {
            if !rays.iter().any(|r| angle_gap(r.angle, *x) <= 1e-8) {
                failures.push(format!(
                    "case {case}: scan root {x} has no ray: {rays:?}: {p:?}"
                ));
            }
        }
    }
    eprintln!(
        "invariant rays: {checked} problems checked, {skipped} near-double skipped; \
         problems with 0/1/2/3/4 rays: {rays_seen:?}; largest |f(ray)|/scale {worst_f:.2e}"
    );
    for f in failures.iter().take(10) {
        eprintln!("FAIL {f}");
    }
    assert!(
        failures.is_empty(),
        "{} failures, first: {}",
        failures.len(),
        failures[0]
    );
    assert!(skipped * 100 <= PROBLEMS, "too many skipped: {skipped}");
    assert!(
        rays_seen[4] >= 200 && rays_seen[2] >= 200,
        "ray counts {rays_seen:?}"
    );
}

#[test]
fn special_structures_have_the_expected_rays() {
    // Isotropic W_tt, w_tn = 0 (a sphere): every direction is invariant.
    let p = ContactProblem::from_upper([3.5, 0.0, 0.0, 3.5, 0.0, 1.0], [0.5, 0.2, -1.0], 0.4, 0.5)
        .unwrap();
    assert_eq!(invariant_rays(&p), InvariantRays::All);
    // w_tn = 0, anisotropic: the eigen-directions of W_tt, all centripetal.
    let th: f64 = 0.3;
    let (s, c) = th.sin_cos();
    let (d1, d2) = (1.0, 4.0);
    let p = ContactProblem::from_upper(
        [
            c * c * d1 + s * s * d2,
            c * s * (d1 - d2),
            0.0,
            s * s * d1 + c * c * d2,
            0.0,
            1.0,
        ],
        [0.5, 0.2, -1.0],
        0.7,
        0.5,
    )
    .unwrap();
    let rays = invariant_rays(&p);
    let rays = rays.as_slice();
    assert_eq!(rays.len(), 4, "{rays:?}");
    for (r, want) in rays.iter().zip([th, th + PI / 2.0, th + PI, th + 1.5 * PI]) {
        assert!(angle_gap(r.angle, want) <= 1e-12, "{r:?} vs {want}");
        assert_eq!(r.kind, RayKind::Centripetal, "{r:?}");
        let d = if angle_gap(r.angle, th) < 1.0 || angle_gap(r.angle, th + PI) < 1.0 {
            d1
        } else {
            d2
        };
        assert!(
            (r.rate + 0.7 * d).abs() <= 1e-12,
            "{r:?}: rate vs −μ d = {}",
            -0.7 * d
        );
    }
    // μ = 0: the rays ±ŵ_tn, centrifugal along +ŵ_tn.
    let p = ContactProblem::from_upper([2.0, 0.3, 0.3, 1.0, 0.4, 1.0], [0.5, 0.2, -1.0], 0.0, 0.5)
        .unwrap();
    let rays = invariant_rays(&p);
    let rays = rays.as_slice();
    assert_eq!(rays.len(), 2, "{rays:?}");
    let phi = 0.4f64.atan2(0.3);
    for r in rays {
        if angle_gap(r.angle, phi) <= 1e-12 {
            assert_eq!(r.kind, RayKind::Centrifugal);
            assert!((r.rate - 0.5).abs() <= 1e-14);
        } else {
            assert!(angle_gap(r.angle, phi + PI) <= 1e-12, "{r:?}");
            assert_eq!(r.kind, RayKind::Centripetal);
        }
    }
}

#[test]
fn sticking_ratio_is_minus_the_inverse_tangential_block_times_the_coupling() {
    let mut rng = SplitMix64(0x0005_71C4);
    for _ in 0..PROBLEMS {
        let p = random_problem(&mut rng);
        let fd = Field::of(&p);
        let l = fd.att_inv_w();
        let got = sticking_ratio(&p);
        let n = l[0].hypot(l[1]);
        assert!(
            (got.x + l[0]).hypot(got.y + l[1]) <= 1e-12 * n,
            "{got:?} vs −{l:?} for {p:?}"
        );
    }
}

#[test]
fn resumption_direction_solves_the_shifted_system_and_is_the_centrifugal_ray() {
    let mut rng = SplitMix64(0x002E_50AE);
    let mut failures = Vec::new();
    let (mut some, mut none, mut skipped) = (0usize, 0usize, 0usize);
    let mut worst = 0.0f64;
    for case in 0..PROBLEMS {
        let p = random_problem(&mut rng);
        let fd = Field::of(&p);
        let l = fd.att_inv_w();
        let ln = l[0].hypot(l[1]);
        let rays = invariant_rays(&p);
        let centrifugal: Vec<f64> = rays
            .as_slice()
            .iter()
            .filter(|r| r.kind == RayKind::Centrifugal)
            .map(|r| r.angle)
            .collect();
        let got = resumption_direction(&p);
        if (ln - fd.mu).abs() <= 1e-9 * ln.max(fd.mu) {
            skipped += 1;
            continue;
        }
        if ln > fd.mu {
            some += 1;
            let Some((s, lam)) = got else {
                failures.push(format!(
                    "case {case}: None although |W_tt⁻¹ w_tn| = {ln} > μ = {}: {p:?}",
                    fd.mu
                ));
                continue;
            };
            let want = fd.resumption_rate();
            let a = &fd.a;
            let r = [
                (lam + fd.mu * a[0][0]) * s.x + fd.mu * a[0][1] * s.y - fd.w[0],
                fd.mu * a[1][0] * s.x + (lam + fd.mu * a[1][1]) * s.y - fd.w[1],
            ];
            let res = r[0].hypot(r[1]) / (fd.scale() + lam);
            worst = worst.max(res);
            if !((s.norm() - 1.0).abs() <= 1e-14
                && lam > 0.0
                && res <= 1e-12
                && (lam - want).abs() <= 1e-10 * want)
            {
                failures.push(format!(
                    "case {case}: ŝ = {s:?} (|ŝ| − 1 = {:e}), λ' = {lam} (bisection {want}), \
                     residual {res:e}: {p:?}",
                    s.norm() - 1.0
                ));
            }
            let phi = s.y.atan2(s.x);
            if centrifugal.len() != 1 || angle_gap(centrifugal[0], phi) > 1e-8 {
                failures.push(format!(
                    "case {case}: resumption at {phi} but centrifugal rays {centrifugal:?}: {p:?}"
                ));
            }
        } else {
            none += 1;
            if got.is_some() || !centrifugal.is_empty() {
                failures.push(format!(
                    "case {case}: |W_tt⁻¹ w_tn| = {ln} < μ = {} but resumption {got:?}, \
                     centrifugal rays {centrifugal:?}: {p:?}",
                    fd.mu
                ));
            }
        }
    }
    eprintln!(
        "resumption: {some} with |W_tt⁻¹ w_tn| > μ, {none} below, {skipped} at the limit; \
         largest relative residual {worst:.2e}"
    );
    for f in failures.iter().take(10) {
        eprintln!("FAIL {f}");
    }
    assert!(
        failures.is_empty(),
        "{} failures, first: {}",
        failures.len(),
        failures[0]
    );
    assert!(some >= 500 && none >= 500, "{some} / {none}");
}
