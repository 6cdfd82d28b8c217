//! The planar box (`shape = "box"`, `bodies::rectangle`): a uniform rectangle of half-width
//! `a` and half-height `b`, `I = m (a² + b²)/3`, turned by `θ`, striking with one corner.
//! Checked against an independent construction (the `rigid` shape with that inertia and the
//! corner turned by hand), and against identities: the default corner is the lowest one, a
//! square at 45° strikes straight below its centre, a half-turn gives the same problem, a
//! thin box is a rod, and an edge on the surface asks for the corner.

use impax::math::{Mat2, Vec2};
use impax::planar::bodies::{self, BodyImpact, BodyState, RigidBody, Side};
use impax::scenario::{BodySpec, PlanarScenario, Shape};

/// `|x − y| ≤ tol` entry by entry.
fn close_mat(x: Mat2, y: Mat2, tol: f64) -> bool {
    (x - y).iter().all(|d| d.abs() <= tol)
}

fn close_vec(x: Vec2, y: Vec2, tol: f64) -> bool {
    (x - y).iter().all(|d| d.abs() <= tol)
}

/// The corner `(s_a a, s_b b)` turned by `θ`, written out.
fn corner(a: f64, b: f64, theta: f64, sa: f64, sb: f64) -> Vec2 {
    let (s, c) = theta.sin_cos();
    Vec2::new(c * sa * a - s * sb * b, s * sa * a + c * sb * b)
}

fn box_spec(m: f64, half: [f64; 2], angle_deg: f64, corner: Option<[f64; 2]>) -> BodySpec {
    BodySpec {
        shape: "box".into(),
        mass: m,
        half_extents: Some(half),
        angle: Some(angle_deg),
        corner,
        velocity: Some([0.4, -1.3]),
        omega: Some(0.7),
        ..BodySpec::default()
    }
}

#[test]
fn box_is_the_rigid_body_with_its_inertia_and_corner() {
    let (m, a, b) = (1.7, 1.2, 0.45);
    let inertia = m * (a * a + b * b) / 3.0;
    let state = BodyState::new(0.4, -1.3, 0.7);
    for angle_deg in [-70.0, -20.0, 0.0, 15.0, 35.0, 80.0, 130.0] {
        for (sa, sb) in [(1.0, -1.0), (-1.0, -1.0), (1.0, 1.0), (-1.0, 1.0)] {
            let spec = box_spec(m, [a, b], angle_deg, Some([sa, sb]));
            let built = spec.build("body", Side::Below).unwrap();
            let r = corner(a, b, f64::to_radians(angle_deg), sa, sb);
            let rigid = RigidBody::new(m, inertia, r).unwrap();
            let (x, y) = (
                BodyImpact::on_fixed_surface(built.body, built.state),
                BodyImpact::on_fixed_surface(rigid, state),
            );
            assert!(
                close_mat(x.inverse_inertia(), y.inverse_inertia(), 1e-15),
                "{angle_deg}° corner ({sa}, {sb}): W {} vs {}",
                x.inverse_inertia(),
                y.inverse_inertia()
            );
            assert!(close_vec(x.contact_velocity(), y.contact_velocity(), 1e-15));
            assert_eq!(built.state, state);
            assert_eq!(built.body.inertia(), inertia);
        }
    }
}

#[test]
fn unturned_corner_below_the_centre_is_the_corner_itself() {
    // At θ = 0 with the corner (a, −b): r = (a, −b) exactly, and
    // W = [[1/m + b²/I, a b/I], [a b/I, 1/m + a²/I]].
    let (m, a, b) = (2.0, 1.5, 0.5);
    let i = m * (a * a + b * b) / 3.0;
    let body = bodies::rectangle(m, [a, b], 0.0, Some([1.0, -1.0]), Side::Below).unwrap();
    assert_eq!(body.contact(), Vec2::new(a, -b));
    let w = Mat2::new(
        1.0 / m + b * b / i,
        a * b / i,
        a * b / i,
        1.0 / m + a * a / i,
    );
    assert!(close_mat(body.inverse_inertia(), w, 1e-15));
    // As body B, met from above: the corner (a, b).
    let above = bodies::rectangle(m, [a, b], 0.0, Some([1.0, 1.0]), Side::Above).unwrap();
    assert_eq!(above.contact(), Vec2::new(a, b));
}

#[test]
fn default_corner_is_the_lowest_and_an_edge_asks_for_one() {
    let (m, a, b) = (1.0, 1.0, 0.4);
    for angle_deg in [5.0, 30.0, 60.0, 85.0, -40.0, 100.0, 200.0] {
        let theta = f64::to_radians(angle_deg);
        let chosen = bodies::rectangle(m, [a, b], theta, None, Side::Below).unwrap();
        let lowest = [(1.0, 1.0), (-1.0, 1.0), (-1.0, -1.0), (1.0, -1.0)]
            .map(|(sa, sb)| corner(a, b, theta, sa, sb))
            .into_iter()
            .min_by(|p, q| p.y.total_cmp(&q.y))
            .unwrap();
        assert!(close_vec(chosen.contact(), lowest, 1e-15), "{angle_deg}°");
        // The depth of the lowest corner is the rectangle's support: a |sin θ| + b |cos θ|.
        let depth = a * theta.sin().abs() + b * theta.cos().abs();
        assert!((chosen.contact().y + depth).abs() < 1e-15, "{angle_deg}°");
        let highest = bodies::rectangle(m, [a, b], theta, None, Side::Above).unwrap();
        assert!(close_vec(highest.contact(), -lowest, 1e-15), "{angle_deg}°");
    }
    // Flat on an edge (θ = 0, 90°): two corners are lowest.
    for angle_deg in [0.0, 90.0] {
        let e = box_spec(m, [a, b], angle_deg, None)
            .build("body", Side::Below)
            .unwrap_err();
        assert_eq!(e.field(), "body.corner", "{e}");
    }
    let e = box_spec(m, [a, b], 10.0, Some([1.0, 0.5]))
        .build("other", Side::Above)
        .unwrap_err();
    assert_eq!(e.to_string(), "other.corner: each entry must be +1 or -1");
}

#[test]
fn square_at_45_degrees_strikes_straight_below_its_centre() {
    let (m, a) = (1.3, 0.8);
    let body = bodies::rectangle(m, [a, a], f64::to_radians(45.0), None, Side::Below).unwrap();
    let r = body.contact();
    assert!(
        r.x.abs() < 1e-15 && (r.y + a * 2f64.sqrt()).abs() < 1e-15,
        "{r}"
    );
    // No coupling: W_tn = 0 and W_nn = 1/m.
    let w = body.inverse_inertia();
    assert!(
        w[(0, 1)].abs() < 1e-15 && (w[(1, 1)] - 1.0 / m).abs() < 1e-15,
        "{w}"
    );
}

#[test]
fn half_a_turn_gives_the_same_problem() {
    let (m, a, b) = (0.9, 1.1, 0.3);
    for angle_deg in [12.0, 47.0, 73.0] {
        let p = bodies::rectangle(m, [a, b], f64::to_radians(angle_deg), None, Side::Below);
        let q = bodies::rectangle(
            m,
            [a, b],
            f64::to_radians(angle_deg + 180.0),
            None,
            Side::Below,
        );
        let (p, q) = (p.unwrap(), q.unwrap());
        assert!(close_mat(p.inverse_inertia(), q.inverse_inertia(), 1e-14));
        assert!(close_vec(p.contact(), q.contact(), 1e-15));
    }
}

#[test]
fn a_thin_box_is_a_rod() {
    // b → 0: I → m a²/3 = m L²/12 with L = 2a, the lowest corner → the rod's lower end.
    let (m, l, b) = (1.4, 2.0, 1e-9);
    for angle_deg in [10.0, 50.0, 120.0] {
        let theta = f64::to_radians(angle_deg);
        let thin = bodies::rectangle(m, [l / 2.0, b], theta, None, Side::Below).unwrap();
        let rod = bodies::rod(m, l, theta, Side::Below).unwrap();
        assert!(
            close_vec(thin.contact(), rod.contact(), 2.0 * b),
            "{angle_deg}°"
        );
        assert!(close_mat(
            thin.inverse_inertia(),
            rod.inverse_inertia(),
            10.0 * b
        ));
    }
}

#[test]
fn box_scenario_files_and_their_errors() {
    let text = "friction = 0.5\nrestitution = 0.6\n[body]\nshape = \"box\"\nmass = 2.0\n\
                half_extents = [1.0, 0.5]\nangle_deg = 20\nvelocity = [0.3, -1.0]\nomega = 0.2\n";
    let s = PlanarScenario::from_toml(text).unwrap();
    let built = s.build().unwrap();
    assert_eq!(
        built.description(),
        "box m = 2, a = 1, b = 0.5, at 20°, v = (0.3, -1), ω = 0.2"
    );
    let r = corner(1.0, 0.5, f64::to_radians(20.0), -1.0, -1.0);
    assert!(close_vec(built.body.body.contact(), r, 1e-15));
    assert!(Shape::NAMES.contains(&"box"));
    for (edit, message) in [
        (
            text.replace("half_extents = [1.0, 0.5]\n", ""),
            "body.half_extents: required for shape `box`",
        ),
        (
            text.replace("angle_deg = 20", "angle_deg = 20\nradius = 1"),
            "body.radius: not a parameter of shape `box`",
        ),
        (
            text.replace("[1.0, 0.5]", "[1.0, -0.5]"),
            "body.half_extents[1]: -0.5 is out of range: must be > 0",
        ),
        (
            text.replace("angle_deg = 20", "angle_deg = 0"),
            "body.corner: an edge touches, not one corner: tilt the box or give `corner`",
        ),
        (
            text.replace("velocity = [0.3, -1.0]\nomega = 0.2", "speed = 1.0"),
            "body.speed: speed/alpha_deg/spin_ratio describe round bodies; give velocity and omega for shape `box`",
        ),
    ] {
        let e = PlanarScenario::from_toml(&edit).unwrap().build().unwrap_err();
        assert_eq!(e.to_string(), message);
    }
    // With the corner chosen, a box flat on its edge strikes with that corner.
    let flat = text.replace("angle_deg = 20", "angle_deg = 0\ncorner = [1, -1]");
    let built = PlanarScenario::from_toml(&flat).unwrap().build().unwrap();
    assert_eq!(built.body.body.contact(), Vec2::new(1.0, -0.5));
    assert!(built
        .description()
        .starts_with("box m = 2, a = 1, b = 0.5, at 0°, corner (1, -1)"));
}
