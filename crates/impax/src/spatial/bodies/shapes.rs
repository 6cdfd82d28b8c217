//! Spatial shapes: sphere, ellipsoid, cuboid corner, cylinder rim.

use super::rigid::RigidBody;
use crate::error::{finite, Error, Result};
use crate::math::{Mat3, Vec3};
use crate::planar::bodies::Side;
use nalgebra::UnitQuaternion;

fn positive(field: &str, x: f64) -> Result<f64> {
    finite(field, x)?;
    if x > 0.0 {
        Ok(x)
    } else {
        Err(Error::OutOfRange {
            field: field.into(),
            value: x,
            reason: "must be > 0".into(),
        })
    }
}

/// The world direction from the centre toward the contact: `−z` below, `+z` above.
fn toward(side: Side) -> Vec3 {
    match side {
        Side::Below => Vec3::new(0.0, 0.0, -1.0),
        Side::Above => Vec3::new(0.0, 0.0, 1.0),
    }
}

/// A solid sphere: `I = 2/5 m r² 1`, contact at `∓r z`. On a plane `W = (1/m) diag(7/2, 7/2, 1)`.
///
/// ```
/// use impax::planar::bodies::Side;
/// use impax::spatial::bodies::sphere;
/// let w = sphere(1.0, 1.0, Side::Below).unwrap().inverse_inertia();
/// assert!((w[(0, 0)] - 3.5).abs() < 1e-15 && (w[(2, 2)] - 1.0).abs() < 1e-15);
/// ```
pub fn sphere(mass: f64, radius: f64, side: Side) -> Result<RigidBody> {
    let r = positive("radius", radius)?;
    let m = positive("mass", mass)?;
    RigidBody::new(
        m,
        Mat3::identity() * (0.4 * m * r * r),
        UnitQuaternion::identity(),
        toward(side) * r,
    )
}

/// A uniform solid ellipsoid with semi-axes `(a, b, c)` along its body axes, oriented by
/// `orientation`: `I_body = m/5 diag(b² + c², a² + c², a² + b²)`. The contact is the point
/// whose outward normal is `∓z` (Liu 1997): with `M = R diag(a², b², c²) Rᵀ` and `d = ∓z`,
/// `r = M d / √(dᵀ M d)`.
pub fn ellipsoid(
    mass: f64,
    semi_axes: [f64; 3],
    orientation: UnitQuaternion<f64>,
    side: Side,
) -> Result<RigidBody> {
    let m = positive("mass", mass)?;
    let [a, b, c] = semi_axes;
    for (f, x) in [
        ("semi_axes[0]", a),
        ("semi_axes[1]", b),
        ("semi_axes[2]", c),
    ] {
        positive(f, x)?;
    }
    let rot = orientation.to_rotation_matrix();
    let mw = rot.matrix()
        * Mat3::from_diagonal(&Vec3::new(a * a, b * b, c * c))
        * rot.matrix().transpose();
    let d = toward(side);
    let r_world = mw * d / d.dot(&(mw * d)).sqrt();
    let inertia =
        Mat3::from_diagonal(&Vec3::new(b * b + c * c, a * a + c * c, a * a + b * b)) * (m / 5.0);
    RigidBody::new(m, inertia, orientation, rot.inverse() * r_world)
}

/// A uniform cuboid with half-extents `(a, b, c)`: `I_body = m/3 diag(b² + c², a² + c², a² + b²)`.
/// The contact is the corner `(±a, ±b, ±c)` given by `corner` (signs), or, if `None`, the
/// corner lowest along `∓z`; a tie (an edge or a face lowest) is an error asking for the
/// corner, since the contact would not be a single point.
pub fn cuboid(
    mass: f64,
    half_extents: [f64; 3],
    orientation: UnitQuaternion<f64>,
    corner: Option<[f64; 3]>,
    side: Side,
) -> Result<RigidBody> {
    let m = positive("mass", mass)?;
    let [a, b, c] = half_extents;
    for (f, x) in [
        ("half_extents[0]", a),
        ("half_extents[1]", b),
        ("half_extents[2]", c),
    ] {
        positive(f, x)?;
    }
    let rot = orientation.to_rotation_matrix();
    let d = toward(side);
    let corner = match corner {
        Some(sg) => {
            if sg.iter().any(|s| s.abs() != 1.0) {
                return Err(Error::Invalid {
                    field: "corner".into(),
                    reason: "each entry must be +1 or -1".into(),
                });
            }
            Vec3::new(sg[0] * a, sg[1] * b, sg[2] * c)
        }
        None => {
            let mut best = Vec3::zeros();
            let mut best_h = f64::NEG_INFINITY;
            let mut second_h = f64::NEG_INFINITY;
            for i in 0..8 {
                let v = Vec3::new(
                    if i & 1 == 0 { a } else { -a },
                    if i & 2 == 0 { b } else { -b },
                    if i & 4 == 0 { c } else { -c },
                );
                let h = (rot * v).dot(&d);
                if h > best_h {
                    second_h = best_h;
                    best_h = h;
                    best = v;
                } else if h > second_h {
                    second_h = h;
                }
            }
            if best_h - second_h <= 1e-12 * (a + b + c) {
                return Err(Error::Invalid {
                    field: "corner".into(),
                    reason:
                        "an edge or a face touches, not one corner: tilt the box or give `corner`"
                            .into(),
                });
            }
            best
        }
    };
    let inertia =
        Mat3::from_diagonal(&Vec3::new(b * b + c * c, a * a + c * c, a * a + b * b)) * (m / 3.0);
    RigidBody::new(m, inertia, orientation, corner)
}

/// A uniform solid cylinder of radius `r` and half-height `h` along its body `z` axis:
/// `I_body = diag(m(3r² + 4h²)/12, same, m r²/2)`. The contact is the rim point lowest
/// along `∓z`: `±h ẑ + r d⊥/|d⊥|` in the body frame, with `d⊥` the part of the direction
/// across the axis; an upright cylinder (face down) is an error.
pub fn cylinder(
    mass: f64,
    radius: f64,
    half_height: f64,
    orientation: UnitQuaternion<f64>,
    side: Side,
) -> Result<RigidBody> {
    let m = positive("mass", mass)?;
    let r = positive("radius", radius)?;
    let h = positive("half_height", half_height)?;
    let rot = orientation.to_rotation_matrix();
    let d_body = rot.inverse() * toward(side);
    let perp = Vec3::new(d_body.x, d_body.y, 0.0);
    let pn = perp.norm();
    if pn <= 1e-12 {
        return Err(Error::Invalid {
            field: "orientation".into(),
            reason: "the cylinder stands on a flat face: the contact is not a rim point; tilt it"
                .into(),
        });
    }
    if d_body.z.abs() <= 1e-12 {
        return Err(Error::Invalid {
            field: "orientation".into(),
            reason: "the cylinder lies on its side: a line touches, not a rim point; tilt it"
                .into(),
        });
    }
    let contact = Vec3::new(0.0, 0.0, h * d_body.z.signum()) + perp * (r / pn);
    let it = m * (3.0 * r * r + 4.0 * h * h) / 12.0;
    let inertia = Mat3::from_diagonal(&Vec3::new(it, it, 0.5 * m * r * r));
    RigidBody::new(m, inertia, orientation, contact)
}
