//! The series against many DOP853 steps over the same step, from loaded contacts and from
//! forces starting at zero; the rise of an event function inside a step.

use super::watched::{horner, rise};
use super::*;
use crate::multi::lzb::state::{Modes, Normal, StickSet, Tangent};
use crate::multi::MultiProblem;
use crate::numerics::dop853::dop853_step;

/// Two contacts (`W` positive definite, `w` its upper triangle), the first slipping, the
/// force exponent `eta`: the state after a step of the series from `y` in the normal
/// regimes `normal` against the same step in 400 DOP853 steps.
struct Case {
    w: [f64; 10],
    v: [f64; 4],
    normal: [Normal; 2],
    y: [f64; 8],
    eta: f64,
}

/// Both loaded, the second expanding.
const LOADED: Case = Case {
    w: [1.3, 0.2, 0.4, -0.1, 0.9, 0.3, 0.2, 1.1, 0.25, 1.0],
    v: [0.3, -1.0, -0.2, 0.4],
    normal: [Normal::Compression, Normal::Expansion],
    y: [0.05, 0.2, 0.3, 0.01, 0.0, 0.35, 0.25, 0.0],
    eta: 1.5,
};

fn agrees_with_runge_kutta(var: Var, x0: f64) {
    agrees(&LOADED, var, x0);
}

fn agrees(case: &Case, var: Var, x0: f64) {
    let p = MultiProblem::from_upper(2, &case.w, &case.v, &[0.4, 0.0], &[0.8, 0.6])
        .and_then(|p| p.with_exponent(case.eta))
        .unwrap();
    let setup = Setup::new(&p);
    let mut normal = [Normal::Off; 8];
    normal[..2].copy_from_slice(&case.normal);
    let modes = Modes {
        normal,
        tangent: [Tangent::Slip(1.0); 8],
        stick: StickSet::EMPTY,
    };
    let field = Field::new(&setup, &modes);
    let y = case.y;
    let mut ser = Series::<8>::new();
    assert!(ser.build(&setup, &field, var, x0, &y));
    let h = ser.h;
    assert!(h.abs() > 0.0 && h.is_finite());
    // (A step of a fair part of the path: in these units its scales are near one.)
    assert!(h.abs() > 0.01, "{h}");
    let f = |x: f64, y: &[f64; 8]| var.rhs::<8>(&setup, &field, x, y);
    let n = 400;
    let (mut x, mut z) = (x0, y);
    for _ in 0..n {
        let k1 = f(x, &z);
        z = dop853_step(&f, x, &z, &k1, h / n as f64).y;
        x += h / n as f64;
    }
    let end = ser.end();
    for i in 0..8 {
        let scale = setup.atol[i] / (0.1 * RTOL) + y[i].abs();
        assert!(
            (end[i] - z[i]).abs() <= 1e-11 * scale,
            "{var:?} component {i}: {} vs {}",
            end[i],
            z[i]
        );
    }
    // The dense output is the series itself: half the step is half the way there.
    let mid = ser.at(0.5);
    assert!(mid
        .iter()
        .zip(&y)
        .zip(&end)
        .all(|((m, a), b)| m.is_finite() && (m - a).abs() <= (b - a).abs() + 1e-12));
}

#[test]
fn a_step_in_time_agrees_with_runge_kutta() {
    agrees_with_runge_kutta(Var::Time, 0.0);
}

#[test]
fn a_step_in_the_start_variable_agrees_with_runge_kutta() {
    agrees_with_runge_kutta(Var::Root, 0.4);
}

#[test]
fn a_step_in_a_separation_variable_agrees_with_runge_kutta() {
    // σ = √s₁ at s₁ = 0.25, decreasing.
    let var = Var::Separation {
        contact: 1,
        entry: 0.5,
    };
    agrees_with_runge_kutta(var, 0.5);
}

#[test]
fn a_step_from_the_impacts_start_in_u_agrees_with_runge_kutta() {
    // Both contacts approaching, s = 0: each force starts as κ |v_n⁻|^η u^(2η)
    // (s_j = −v_nj⁻ u²), for Hertz's exponent and for η = 5/2.
    for eta in [1.5, 2.5] {
        let case = Case {
            v: [0.3, -1.0, -0.2, -0.6],
            normal: [Normal::Compression; 2],
            y: [0.0; 8],
            eta,
            ..LOADED
        };
        agrees(&case, Var::Root, 0.0);
    }
}

#[test]
fn the_start_in_z_agrees_with_runge_kutta() {
    // Both contacts approaching from s = 0: two steps of the series in z = τ^(η+1), each
    // against 2000 DOP853 steps over the same stretch of τ — the first from the start in
    // u = τ^(1/m) (where the path is smooth), the second in τ — for Hertz's exponent, a
    // linear spring, η = 5/2 and η = 5/4 (whose start in u is smooth only to order 9).
    for eta in [1.5, 1.0, 2.5, 1.25] {
        let p = MultiProblem::from_upper(
            2,
            &LOADED.w,
            &[0.3, -1.0, -0.2, -0.6],
            &[0.4, 0.0],
            &[0.8, 0.6],
        )
        .and_then(|p| p.with_exponent(eta))
        .unwrap();
        let setup = Setup::new(&p);
        let mut normal = [Normal::Off; 8];
        normal[..2].copy_from_slice(&[Normal::Compression; 2]);
        let modes = Modes {
            normal,
            tangent: [Tangent::Slip(1.0); 8],
            stick: StickSet::EMPTY,
        };
        let field = Field::new(&setup, &modes);
        let m = f64::from(setup.law.m);
        let mut ser = Series::<8>::new();
        let (mut z0, mut y) = (0.0, [0.0; 8]);
        for step in 0..2 {
            assert!(ser.build(&setup, &field, Var::Onset, z0, &y), "η = {eta}");
            // (A linear spring's force is analytic through s = 0, where the path's would be
            // cut: the step is kept to where both contacts are loaded.)
            while (0..2).any(|j| ser.end()[PER * j + S] <= 0.0) {
                ser.h *= 0.5;
            }
            let h = ser.h;
            assert!(h > 0.0 && h.is_finite());
            let (tau0, tau1) = (setup.law.onset_time(z0), setup.law.onset_time(z0 + h));
            // (The first step a fair part of the compression: in these units it lasts about
            // 1.)
            assert!(step > 0 || tau1 > 0.5, "η = {eta}: {tau1}");
            let (var, xa, xb) = if step == 0 {
                (Var::Root, 0.0, tau1.powf(1.0 / m))
            } else {
                (Var::Time, tau0, tau1)
            };
            let f = |x: f64, y: &[f64; 8]| var.rhs::<8>(&setup, &field, x, y);
            let n = 2000;
            let dx = (xb - xa) / n as f64;
            let (mut x, mut r) = (xa, y);
            for _ in 0..n {
                let k1 = f(x, &r);
                r = dop853_step(&f, x, &r, &k1, dx).y;
                x += dx;
            }
            let end = ser.end();
            for i in 0..8 {
                let scale = setup.atol[i] / (0.1 * RTOL) + end[i].abs();
                assert!(
                    (end[i] - r[i]).abs() <= 1e-11 * scale,
                    "η = {eta}, step {step}, component {i}: {} vs {}",
                    end[i],
                    r[i]
                );
            }
            (z0, y) = (z0 + h, end);
        }
    }
}

#[test]
fn a_step_from_a_contact_joining_agrees_with_runge_kutta() {
    // The second contact at s = 0 and v_n = 0, pushed into approach by the first's force
    // (dv_n2/dτ = (−0.2 + 0.1 · 0.4) F₁ < 0): s₂ ∝ τ², its force ∝ τ^(2η) — for Hertz's
    // exponent, a linear spring and η = 5/2.
    for eta in [1.5, 1.0, 2.5] {
        let case = Case {
            w: [1.3, 0.2, 0.4, -0.1, 0.9, 0.3, -0.2, 1.1, 0.25, 1.0],
            v: [0.3, -1.0, -0.2, 0.0],
            normal: [Normal::Compression; 2],
            y: [0.0, 0.0, 0.3, 0.0, 0.0, 0.0, 0.0, 0.0],
            eta,
        };
        agrees(&case, Var::Time, 0.0);
        if eta == 1.0 {
            // (A linear spring has no separation's variable.)
            continue;
        }
        // The same in a separation's variable, the first contact expanding to its
        // separation (σ decreasing: the force ∝ (−t)^(2η)): after an impulse p_n1 = 2,
        // where v_n1 = −1 + 0.9 · 2 and v_n2 = 0.4 − 0.2 · 2 = 0.
        let case = Case {
            v: [0.3, -1.0, -0.2, 0.4],
            normal: [Normal::Expansion, Normal::Compression],
            y: [0.0, 2.0, 0.3, 0.0, 0.0, 0.0, 0.0, 0.0],
            ..case
        };
        let var = Var::Separation {
            contact: 0,
            entry: 1.0,
        };
        agrees(&case, var, 0.3f64.sqrt());
    }
}

#[test]
fn a_rise_inside_the_step_is_found() {
    // q = −0.01 + t − t² on h = 1 rises from θ ≈ 0.0101 to 0.99 and ends below zero.
    let mut q = [0.0; ORDER + 1];
    q[0] = -0.01;
    q[1] = 1.0;
    q[2] = -1.0;
    assert_eq!(rise(&q, 1.0), Some(1.0 / 16.0));
    // A narrow bump between two samples: −1e-4 + (t − 0.53)² has its rise below zero…
    let mut q = [0.0; ORDER + 1];
    q[0] = -1e-4 - 0.53 * 0.53;
    q[1] = 2.0 * 0.53;
    q[2] = -1.0;
    // … (−(t − 0.53)² − 1e-4 never rises), while 1e-5 − (t − 0.53)² does, at its top.
    assert_eq!(rise(&q, 1.0), None);
    q[0] = 1e-5 - 0.53 * 0.53;
    let th = rise(&q, 1.0).expect("the bump");
    assert!((th - 0.53).abs() < 1e-6, "{th}");
    // Negative steps (a separation's variable) are the same polynomial in θ.
    q[1] = -q[1];
    let th = rise(&q, -1.0).expect("the bump");
    assert!((th - 0.53).abs() < 1e-6, "{th}");
    // A function that reaches zero at the step's end as a power, −c (1 − θ)³ (a separating
    // contact's stick-break function where it lands: its slope there is zero to
    // round-off), does not rise; a bump just before the end, 1e-6 − (θ − 0.97)², does.
    let c = 5.48e-5;
    let mut q = [0.0; ORDER + 1];
    let h: f64 = -0.0567;
    for (k, binom) in [1.0, -3.0, 3.0, -1.0].into_iter().enumerate() {
        q[k] = -c * binom / h.powi(k as i32);
    }
    assert_eq!(rise(&q, h), None);
    let mut q = [0.0; ORDER + 1];
    q[0] = 1e-6 - 0.97 * 0.97;
    q[1] = 2.0 * 0.97;
    q[2] = -1.0;
    let th = rise(&q, 1.0).expect("the bump at the end");
    assert!((th - 0.97).abs() < 1e-3 && horner(&q, th) > 0.0, "{th}");
}

/// Each watched function along a step, as the series' polynomial (`event_poly`), is the
/// function of the series' state there (`events::value`) — the same polynomial but for the
/// state's last order — and `locate` puts a crossing where the state's function is zero:
/// contact 0 compressing and slipping (then sticking), contact 1 expanding.
#[test]
fn the_watched_functions_are_polynomials_of_the_step() {
    use crate::multi::lzb::events;
    use crate::multi::lzb::friction::rebuild;
    let case = &LOADED;
    let p = MultiProblem::from_upper(2, &case.w, &case.v, &[0.4, 0.3], &[0.8, 0.6]).unwrap();
    let setup = Setup::new(&p);
    let mut normal = [Normal::Off; 8];
    normal[..2].copy_from_slice(&case.normal);
    let mut located = 0;
    for stick in [false, true] {
        let mut modes = Modes {
            normal,
            tangent: [Tangent::Slip(1.0); 8],
            stick: StickSet::EMPTY,
        };
        if stick {
            modes.tangent[0] = Tangent::Stick;
            rebuild(&setup, &mut modes);
        }
        let field = Field::new(&setup, &modes);
        let y = case.y;
        let mut ser = Series::<8>::new();
        assert!(ser.build(&setup, &field, Var::Time, 0.0, &y));
        let ev = field.eval::<8>(&setup, &y);
        let watch = events::watch(&setup, &modes, &y, &ev);
        let on_state = |watch: &events::Watch, i: usize, th: f64| {
            let z = ser.at(th);
            events::value(&setup, &modes, watch, i, &z, &field.eval::<8>(&setup, &z))
        };
        let poly = |watch: &events::Watch, i: usize, th: f64| {
            let (q, q2) = ser.event_poly(&setup, &modes, &field, watch, i).unwrap();
            let t = th * ser.h;
            let at = |q: &[f64; ORDER + 1]| q.iter().rev().fold(0.0, |v, c| v * t + c);
            q2.map_or(at(&q), |o| at(&q).max(at(&o)))
        };
        assert!(watch.n >= 4, "{:?}", &watch.list[..watch.n]);
        for i in 0..watch.n {
            for m in 0..=10 {
                let th = 0.1 * f64::from(m);
                let (a, b) = (poly(&watch, i, th), on_state(&watch, i, th));
                assert!(
                    (a - b).abs() <= 1e-12,
                    "{:?} at {th}: {a} vs {b}",
                    watch.list[i]
                );
            }
            // Offset so that the function crosses zero at θ = 0.37 where it increases
            // through the step; the crossing located on the polynomial is the state's.
            let g = |th: f64| on_state(&watch, i, th);
            let (g0, g1, g2) = (g(0.0), g(0.37), g(1.0));
            if !(g0 < g1 && g1 < g2) || (g2 - g0) < 1e-3 {
                continue;
            }
            let mut shifted = watch;
            shifted.offset[i] += g1;
            let ends = (on_state(&shifted, i, 0.0), on_state(&shifted, i, 1.0));
            let th = ser.locate(&setup, &modes, &field, &shifted, i, ends);
            assert!((th - 0.37).abs() <= 1e-9, "{:?}: {th}", watch.list[i]);
            assert!(
                on_state(&shifted, i, th).abs() <= 1e-13,
                "{:?}",
                watch.list[i]
            );
            located += 1;
        }
    }
    assert!(located >= 3, "{located}");
}
