//! Input validation and robustness.
//!
//! * Every invalid input to `ContactProblem::new` / `from_entries` / `with_coefficients`, to
//!   the body constructors (`RigidBody::new`, `sphere`, `disc`, `rod`, `ellipse`,
//!   `spin_state`), to `BodyImpact::problem` and to `LawId::from_str` returns the right
//!   `impax::Error` variant, naming the offending field, and its message starts with that
//!   field.
//! * Valid but extreme problems (entries of `W` from 1e-150 to 1e150, nearly singular `W`,
//!   `μ = 2`, `e = 0` or 1, `v_t = 0`, tiny and huge velocities) never make a law panic; an
//!   outcome is finite with `p_n ≥ 0`, and each Darboux–Keller outcome meets its own
//!   termination rule.

use impax::math::{Mat2, Vec2};
use impax::planar::bodies::{
    disc, ellipse, rod, sphere, spin_state, BodyImpact, BodyState, RigidBody, Side,
};
use impax::planar::ContactProblem;
use impax::{Error, LawId};
use std::panic::{catch_unwind, AssertUnwindSafe};

const NAN: f64 = f64::NAN;
const INF: f64 = f64::INFINITY;

/// Assert that `r` is an error of the variant `kind` naming `name`, and that the message
/// starts with the field.
fn expect_err<T: std::fmt::Debug>(r: Result<T, Error>, kind: &str, name: &str) {
    let e = match r {
        Ok(v) => panic!("expected {kind} on `{name}`, got Ok({v:?})"),
        Err(e) => e,
    };
    let got = match &e {
        Error::NotFinite { .. } => "NotFinite",
        Error::OutOfRange { .. } => "OutOfRange",
        Error::NotSymmetric { .. } => "NotSymmetric",
        Error::NotPositiveDefinite { .. } => "NotPositiveDefinite",
        Error::NotApproaching { .. } => "NotApproaching",
        Error::UnknownLaw { .. } => "UnknownLaw",
        Error::Invalid { .. } => "Invalid",
        _ => "other",
    };
    assert_eq!(got, kind, "wrong variant for `{name}`: {e:?}");
    assert_eq!(e.field(), name, "wrong field: {e:?}");
    let msg = e.to_string();
    assert!(
        msg.starts_with(&format!("{name}:")),
        "message `{msg}` does not start with `{name}:`"
    );
}

fn problem(w: [f64; 4], v: [f64; 2], mu: f64, e: f64) -> Result<ContactProblem, Error> {
    ContactProblem::new(
        Mat2::new(w[0], w[1], w[2], w[3]),
        Vec2::new(v[0], v[1]),
        mu,
        e,
    )
}

const W: [f64; 4] = [2.0, 0.5, 0.5, 1.5];
const V: [f64; 2] = [0.3, -1.0];

#[test]
fn a_valid_problem_is_accepted_as_given() {
    let p = problem(W, V, 0.3, 0.5).unwrap();
    assert_eq!((p.wtt(), p.wtn(), p.wnn()), (2.0, 0.5, 1.5));
    assert_eq!(p.velocity(), Vec2::new(0.3, -1.0));
    assert_eq!((p.friction(), p.restitution()), (0.3, 0.5));
    // Boundary values that are allowed.
    for (mu, e) in [(0.0, 0.0), (0.0, 1.0), (2.0, 1.0), (1e6, 0.5)] {
        assert!(problem(W, V, mu, e).is_ok(), "μ = {mu}, e = {e}");
    }
    // Asymmetry at the level of round-off is accepted (and averaged).
    let p = problem([2.0, 0.5, 0.5 + 1e-16, 1.5], V, 0.3, 0.5).unwrap();
    assert!((p.wtn() - 0.5).abs() < 1e-15);
}

#[test]
fn non_finite_entries_are_named() {
    for bad in [NAN, INF, -INF] {
        for (i, name) in ["w[t,t]", "w[t,n]", "w[n,t]", "w[n,n]"].iter().enumerate() {
            let mut w = W;
            w[i] = bad;
            expect_err(problem(w, V, 0.3, 0.5), "NotFinite", name);
        }
        expect_err(problem(W, [bad, -1.0], 0.3, 0.5), "NotFinite", "v[t]");
        expect_err(problem(W, [0.3, bad], 0.3, 0.5), "NotFinite", "v[n]");
        expect_err(problem(W, V, bad, 0.5), "NotFinite", "friction");
        expect_err(problem(W, V, 0.3, bad), "NotFinite", "restitution");
    }
    // The value is reported.
    match problem(W, V, 0.3, INF) {
        Err(Error::NotFinite { value, .. }) => assert_eq!(value, INF),
        other => panic!("{other:?}"),
    }
}

#[test]
fn w_must_be_symmetric() {
    expect_err(
        problem([2.0, 0.5, 0.4, 1.5], V, 0.3, 0.5),
        "NotSymmetric",
        "w",
    );
    expect_err(
        problem([2.0, 0.5, -0.5, 1.5], V, 0.3, 0.5),
        "NotSymmetric",
        "w",
    );
    expect_err(
        problem([2.0, 1e-9, 0.0, 1.5], V, 0.3, 0.5),
        "NotSymmetric",
        "w",
    );
    match problem([2.0, 0.5, 0.4, 1.5], V, 0.3, 0.5) {
        Err(Error::NotSymmetric { upper, lower, .. }) => assert_eq!((upper, lower), (0.5, 0.4)),
        other => panic!("{other:?}"),
    }
}

#[test]
fn w_must_be_positive_definite() {
    let cases: [[f64; 4]; 9] = [
        [-2.0, 0.5, 0.5, 1.5],                // negative W_tt
        [0.0, 0.0, 0.0, 1.5],                 // zero W_tt
        [2.0, 0.5, 0.5, -1.5],                // negative W_nn
        [2.0, 0.0, 0.0, 0.0],                 // zero W_nn
        [-1.0, 0.0, 0.0, -1.0],               // negative definite
        [1.0, 1.0, 1.0, 1.0],                 // det = 0
        [1.0, 2.0, 2.0, 1.0],                 // det < 0 (indefinite)
        [4.0, -3.0, -3.0, 2.0],               // det < 0 with positive diagonal
        [1.0, 1.0 - 1e-15, 1.0 - 1e-15, 1.0], // det at round-off level
    ];
    for w in cases {
        expect_err(problem(w, V, 0.3, 0.5), "NotPositiveDefinite", "w");
        expect_err(
            ContactProblem::from_entries(w[0], w[1], w[3], V[0], V[1], 0.3, 0.5),
            "NotPositiveDefinite",
            "w",
        );
    }
}

#[test]
fn contact_must_approach() {
    for vn in [0.0, -0.0, 1e-300, 1.0] {
        expect_err(problem(W, [0.3, vn], 0.3, 0.5), "NotApproaching", "v");
    }
    match problem(W, [0.3, 2.0], 0.3, 0.5) {
        Err(Error::NotApproaching { value, .. }) => assert_eq!(value, 2.0),
        other => panic!("{other:?}"),
    }
}

#[test]
fn coefficients_must_be_in_range() {
    for mu in [-1e-300, -0.1, -1e300] {
        expect_err(problem(W, V, mu, 0.5), "OutOfRange", "friction");
    }
    for e in [-1e-12, -0.5, 1.0 + 1e-12, 1.5, 1e300] {
        expect_err(problem(W, V, 0.3, e), "OutOfRange", "restitution");
    }
    // `with_coefficients` re-validates.
    let p = problem(W, V, 0.3, 0.5).unwrap();
    expect_err(p.with_coefficients(-0.3, 0.5), "OutOfRange", "friction");
    expect_err(p.with_coefficients(0.3, 1.1), "OutOfRange", "restitution");
    expect_err(p.with_coefficients(NAN, 0.5), "NotFinite", "friction");
    assert!(p.with_coefficients(0.0, 1.0).is_ok());
}

#[test]
fn the_first_problem_found_is_reported() {
    // A NaN entry is reported before asymmetry, asymmetry before definiteness, and the
    // matrix before the velocity and the coefficients.
    expect_err(
        problem([NAN, 0.5, 0.4, -1.0], [0.3, 1.0], -1.0, 2.0),
        "NotFinite",
        "w[t,t]",
    );
    expect_err(
        problem([-2.0, 0.5, 0.4, 1.5], V, 0.3, 0.5),
        "NotSymmetric",
        "w",
    );
    expect_err(
        problem([-2.0, 0.5, 0.5, 1.5], [0.3, 1.0], -1.0, 2.0),
        "NotPositiveDefinite",
        "w",
    );
    expect_err(problem(W, [0.3, 1.0], -1.0, 2.0), "NotApproaching", "v");
    expect_err(problem(W, V, -1.0, 2.0), "OutOfRange", "friction");
}

#[test]
fn unknown_law_ids_are_rejected() {
    for law in LawId::ALL {
        assert_eq!(law.as_str().parse::<LawId>().unwrap(), law);
    }
    for bad in ["", "Newton", "kane", "smith_centre", "two phase"] {
        match bad.parse::<LawId>() {
            Err(Error::UnknownLaw { id, known }) => {
                assert_eq!(id, bad);
                for law in LawId::ALL {
                    assert!(known.contains(law.as_str()), "{known}");
                }
            }
            other => panic!("`{bad}`: {other:?}"),
        }
    }
}

#[test]
fn rigid_body_validation() {
    let r = Vec2::new(0.1, -1.0);
    for bad in [0.0, -1.0] {
        expect_err(RigidBody::new(bad, 1.0, r), "OutOfRange", "mass");
        expect_err(RigidBody::new(1.0, bad, r), "OutOfRange", "inertia");
    }
    for bad in [NAN, INF, -INF] {
        expect_err(RigidBody::new(bad, 1.0, r), "NotFinite", "mass");
        expect_err(RigidBody::new(1.0, bad, r), "NotFinite", "inertia");
        expect_err(
            RigidBody::new(1.0, 1.0, Vec2::new(bad, -1.0)),
            "NotFinite",
            "contact[t]",
        );
        expect_err(
            RigidBody::new(1.0, 1.0, Vec2::new(0.1, bad)),
            "NotFinite",
            "contact[n]",
        );
    }
    let b = RigidBody::new(2.0, 0.5, r).unwrap();
    assert_eq!((b.mass(), b.inertia(), b.contact()), (2.0, 0.5, r));
}

#[test]
fn shape_validation() {
    for ctor in [sphere, disc] {
        for bad in [0.0, -1.0] {
            expect_err(ctor(1.0, bad, Side::Below), "OutOfRange", "radius");
            expect_err(ctor(bad, 1.0, Side::Below), "OutOfRange", "mass");
        }
        for bad in [NAN, INF] {
            expect_err(ctor(1.0, bad, Side::Below), "NotFinite", "radius");
            expect_err(ctor(bad, 1.0, Side::Below), "NotFinite", "mass");
        }
        assert!(ctor(1.0, 1.0, Side::Above).is_ok());
    }
    let angle = 0.7;
    for bad in [0.0, -2.0] {
        expect_err(rod(1.0, bad, angle, Side::Below), "OutOfRange", "length");
        expect_err(rod(bad, 1.0, angle, Side::Below), "OutOfRange", "mass");
    }
    for bad in [0.0, -0.1, std::f64::consts::PI, 4.0] {
        expect_err(rod(1.0, 1.0, bad, Side::Below), "OutOfRange", "angle");
    }
    expect_err(rod(1.0, NAN, angle, Side::Below), "NotFinite", "length");
    expect_err(rod(1.0, 1.0, NAN, Side::Below), "NotFinite", "angle");
    expect_err(rod(NAN, 1.0, angle, Side::Below), "NotFinite", "mass");
    for bad in [0.0, -1.0] {
        expect_err(
            ellipse(1.0, bad, 1.0, angle, Side::Below),
            "OutOfRange",
            "semi-axis-a",
        );
        expect_err(
            ellipse(1.0, 1.0, bad, angle, Side::Below),
            "OutOfRange",
            "semi-axis-b",
        );
        expect_err(
            ellipse(bad, 1.0, 1.0, angle, Side::Below),
            "OutOfRange",
            "mass",
        );
    }
    expect_err(
        ellipse(1.0, INF, 1.0, angle, Side::Below),
        "NotFinite",
        "semi-axis-a",
    );
    expect_err(
        ellipse(1.0, 1.0, NAN, angle, Side::Below),
        "NotFinite",
        "semi-axis-b",
    );
    expect_err(
        ellipse(1.0, 1.0, 1.0, NAN, Side::Below),
        "NotFinite",
        "angle",
    );
    for bad in [NAN, INF] {
        expect_err(spin_state(bad, 0.5, 0.0, 1.0), "NotFinite", "speed");
        expect_err(spin_state(1.0, bad, 0.0, 1.0), "NotFinite", "alpha");
        expect_err(spin_state(1.0, 0.5, bad, 1.0), "NotFinite", "spin-ratio");
        expect_err(spin_state(1.0, 0.5, 0.0, bad), "NotFinite", "radius");
    }
    expect_err(spin_state(1.0, 0.5, 0.0, 0.0), "OutOfRange", "radius");
    expect_err(spin_state(1.0, 0.5, 0.0, -1.0), "OutOfRange", "radius");
}

#[test]
fn impacts_validate_through_the_problem() {
    let body = sphere(1.0, 1.0, Side::Below).unwrap();
    // Moving away from the surface.
    let leaving = BodyImpact::on_fixed_surface(body, BodyState::new(0.5, 1.0, 0.0));
    expect_err(leaving.problem(0.3, 0.5), "NotApproaching", "v");
    // Resting contact (v_n = 0) is not an impact either.
    let resting = BodyImpact::on_fixed_surface(body, BodyState::new(0.5, 0.0, 3.0));
    expect_err(resting.problem(0.3, 0.5), "NotApproaching", "v");
    let hitting = BodyImpact::on_fixed_surface(body, BodyState::new(0.5, -1.0, 0.0));
    expect_err(hitting.problem(-0.3, 0.5), "OutOfRange", "friction");
    expect_err(hitting.problem(0.3, 1.5), "OutOfRange", "restitution");
    expect_err(hitting.problem(0.3, NAN), "NotFinite", "restitution");
    // Two bodies: B moving down faster than A means separation.
    let other = sphere(1.0, 1.0, Side::Above).unwrap();
    let apart = BodyImpact::between(
        body,
        BodyState::new(0.0, -1.0, 0.0),
        other,
        BodyState::new(0.0, -2.0, 0.0),
    );
    expect_err(apart.problem(0.3, 0.5), "NotApproaching", "v");
    let closing = BodyImpact::between(
        body,
        BodyState::new(0.0, -1.0, 0.0),
        other,
        BodyState::new(0.0, 0.5, 0.0),
    );
    assert!(closing.problem(0.3, 0.5).is_ok());
}

// ---------------------------------------------------------------------------------------
// Robustness on extreme but valid problems

/// Check one outcome for finiteness and, for the Darboux–Keller laws, its termination rule.
fn check_outcome(p: &ContactProblem, law: LawId) -> Result<(), String> {
    let res = catch_unwind(AssertUnwindSafe(|| law.resolve(p)))
        .map_err(|_| format!("{law} panicked on {p:?}"))?;
    let Ok(o) = res else { return Ok(()) };
    let finite = [
        o.impulse.x,
        o.impulse.y,
        o.velocity_after.x,
        o.velocity_after.y,
        o.energy_change,
        o.work.compression,
        o.work.restitution,
        o.work.friction,
    ]
    .iter()
    .all(|x| x.is_finite());
    if !finite {
        return Err(format!("{law}: non-finite outcome {o:?} for {p:?}"));
    }
    if o.impulse.y < 0.0 {
        return Err(format!("{law}: p_n = {} < 0 for {p:?}", o.impulse.y));
    }
    if law.is_darboux_keller() {
        let e = p.restitution();
        let vn = p.velocity().y;
        let Some(pc) = o.compression_impulse else {
            return Err(format!("{law}: no compression impulse for {p:?}"));
        };
        let rel = |x: f64, y: f64| (x - y).abs() <= 1e-9 * x.abs().max(y.abs());
        let ok = match law {
            LawId::Newton => {
                // v_n⁺ = −e v_n⁻, to round-off of v⁻ + W p.
                let scale =
                    vn.abs() + (p.wtn() * o.impulse.x).abs() + (p.wnn() * o.impulse.y).abs();
                (o.velocity_after.y + e * vn).abs() <= 1e-9 * scale
            }
            LawId::Poisson => rel(o.impulse.y, (1.0 + e) * pc),
            _ => {
                let scale = o.work.compression.abs();
                (o.work.restitution + e * e * o.work.compression).abs() <= 1e-9 * scale
            }
        };
        if !ok || pc.is_nan() || pc <= 0.0 || pc > o.impulse.y * (1.0 + 1e-12) {
            return Err(format!("{law}: termination rule not met: {o:?} for {p:?}"));
        }
    }
    Ok(())
}

#[test]
fn no_law_panics_on_extreme_valid_problems() {
    let scales = [1e-150, 1e-30, 1e-8, 1.0, 1e8, 1e30, 1e150];
    // (W_tt, W_tn, W_nn) shapes, multiplied by a scale.
    let shapes = [
        (1.0, 0.0, 1.0),
        (3.5, 0.0, 1.0),
        (1.0, 0.99, 1.0),
        (1.0, -0.99, 1.0),
        (1.0, 1.0 - 1e-6, 1.0),
        (1.0, -(1.0 - 1e-6), 1.0),
        (1e-6, 0.5e-3, 1.0),
        (1.0, 0.5e-3, 1e-6),
        (100.0, 0.3, 0.01),
    ];
    let velocities = [
        (0.0, -1.0),
        (1.0, -1.0),
        (-1.0, -1.0),
        (1e-300, -1.0),
        (1e6, -1e-6),
        (-1e-6, -1e6),
        (1e100, -1e100),
        (1e-100, -1e-100),
    ];
    let coefficients = [
        (0.0, 0.0),
        (0.0, 1.0),
        (2.0, 0.0),
        (2.0, 1.0),
        (0.5, 0.5),
        (1e-12, 0.7),
    ];
    let mut checked = 0;
    let mut rejected = 0;
    let mut failures = Vec::new();
    for s in scales {
        for (a, b, c) in shapes {
            for (vt, vn) in velocities {
                for (mu, e) in coefficients {
                    let Ok(p) = ContactProblem::from_entries(s * a, s * b, s * c, vt, vn, mu, e)
                    else {
                        rejected += 1;
                        continue;
                    };
                    // Some extremes are legitimately out of floating-point range (p ≈ v/W
                    // overflows); only problems whose impulse scale is representable count.
                    let lambda_min = s * (a * c - b * b) / (a + c);
                    let v = vn.abs().max(vt.abs());
                    let representable = v / lambda_min < 1e250 && v * v / lambda_min < 1e250;
                    let p2 = p.mirrored();
                    for law in LawId::CONTACT_SPACE {
                        for q in [&p, &p2] {
                            checked += 1;
                            if let Err(msg) = check_outcome(q, law) {
                                if representable || msg.contains("panicked") {
                                    failures.push(msg);
                                }
                            }
                        }
                    }
                }
            }
        }
    }
    println!("{checked} law runs, {rejected} problems rejected by validation");
    assert!(checked > 10_000);
    assert!(
        failures.is_empty(),
        "{} failures, e.g.:\n{}",
        failures.len(),
        failures
            .iter()
            .take(100)
            .cloned()
            .collect::<Vec<_>>()
            .join("\n")
    );
}
