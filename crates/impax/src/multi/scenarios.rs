//! The built-in systems struck at several contacts at once (their names are contracts of the
//! command line): `rod-flat`, `rocking-block`, `cradle`, `ball-ball-wall` (planar) and
//! `box-flat` (spatial).
//!
//! Each is a set of planar rigid bodies with generalized velocities `u` (per body `v_x`, `v_y`,
//! `ω`), a diagonal mass matrix and the contacts' rows `J` derived below from the velocity of a
//! body point, `v_P = v_G + ω ẑ × (P − G)` (theory §1, §6). A contact with a fixed surface of
//! normal `n` has the tangent `t = (n_y, −n_x)` (as [`crate::mechanism::Surface::tangent`]); a
//! contact between bodies A and B, with `n` the unit vector from A's centre to B's, measures
//! B's point relative to A's, so its impulse acts on B (and its opposite on A).
//!
//! | name | system | contacts | known answer |
//! |---|---|---|---|
//! | `rod-flat` | a uniform rod lying flat, landing | its two ends on the floor | symmetric landing: `u⁺ = (0, e |v_y|, 0)` |
//! | `rocking-block` | a uniform rectangle rocking about corner A as corner B strikes | A and B on the floor | Housner (1963): `ω⁺/ω⁻ = 1 − (3/2) sin²α`, `α = atan(b/h)`, for `e = 0` at B without slip |
//! | `cradle` | `N` equal balls in a row, touching, the first moving at `v0` | the `N − 1` ball–ball contacts | binary impacts: `(0, …, 0, v0)`; the LCP: not that |
//! | `ball-ball-wall` | a ball resting against a wall, struck by a second ball | wall–ball 1, ball 1–ball 2 | momentum along the wall and energy (e = 1, frictionless) |
//! | `box-flat` | a box lying flat (3D), landing and spinning about the vertical | its four lower corners on the floor | level at `e |v_z|`; `lcp`: `ω_z⁺ = max(ω_z⁻ − μ m (1 + e) |v_z| ρ / I_z, 0)`, `ρ = √(a² + b²)` |

use super::MultiImpact;
use crate::error::{Error, Num, Result};
use crate::mechanism::builtin::positive;
use nalgebra::DMatrix;

/// The names of the built-in multi-contact systems.
pub const NAMES: [&str; 5] = [
    "rod-flat",
    "rocking-block",
    "cradle",
    "ball-ball-wall",
    "box-flat",
];

/// A built-in system at the instant of its impact, with its default coefficients.
#[derive(Debug, Clone)]
pub struct MultiScenario {
    /// The built-in's name (one of [`NAMES`]).
    pub name: &'static str,
    /// One line saying what it is, with its parameters.
    pub description: String,
    /// The system at the impact.
    pub impact: MultiImpact,
    /// The default friction coefficient (every contact).
    pub friction: f64,
    /// The default coefficient of restitution (every contact).
    pub restitution: f64,
}

fn finite(field: &str, x: f64) -> Result<f64> {
    crate::error::finite(field, x)?;
    Ok(x)
}

/// Per-body coordinate names `x1, y1, theta1, …` (or `x, y, theta` for one body).
fn coordinates(bodies: usize) -> Vec<String> {
    let mut out = Vec::with_capacity(3 * bodies);
    for i in 1..=bodies {
        let s = if bodies == 1 {
            String::new()
        } else {
            i.to_string()
        };
        out.extend([format!("x{s}"), format!("y{s}"), format!("theta{s}")]);
    }
    out
}

/// `diag(m, m, I)` for each body.
fn mass_matrix(bodies: &[(f64, f64)]) -> DMatrix<f64> {
    let mut m = DMatrix::zeros(3 * bodies.len(), 3 * bodies.len());
    for (i, &(mass, inertia)) in bodies.iter().enumerate() {
        m[(3 * i, 3 * i)] = mass;
        m[(3 * i + 1, 3 * i + 1)] = mass;
        m[(3 * i + 2, 3 * i + 2)] = inertia;
    }
    m
}

/// Add to rows `(row, row + 1)` of `j` the contact-frame velocity of the point at `r` from
/// body `b`'s centre, times `sign`: `t·(v + ω ẑ × r)`, `n·(v + ω ẑ × r)`, with
/// `ẑ × r = (−r_y, r_x)`.
fn point_rows(j: &mut DMatrix<f64>, row: usize, b: usize, r: [f64; 2], n: [f64; 2], sign: f64) {
    let t = [n[1], -n[0]];
    let zr = [-r[1], r[0]];
    for (k, d) in [t, n].into_iter().enumerate() {
        j[(row + k, 3 * b)] += sign * d[0];
        j[(row + k, 3 * b + 1)] += sign * d[1];
        j[(row + k, 3 * b + 2)] += sign * (d[0] * zr[0] + d[1] * zr[1]);
    }
}

/// `rod-flat`: a uniform rod (mass `m`, length `l`, `I = m l²/12`) lying flat along `x`
/// on the floor, its centre moving at `(v_x, v_y)` and turning at `ω`; end A at `−l/2`,
/// end B at `+l/2`. Rows `J_A = [[1, 0, 0], [0, 1, −l/2]]`, `J_B = [[1, 0, 0], [0, 1, l/2]]`
/// (`v_n = v_y ∓ (l/2) ω`): four rows, three
/// degrees of freedom (the tangent rows coincide), so `W` has rank 3.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct RodFlat {
    /// Mass `m` (default 1).
    pub mass: f64,
    /// Length `l` (default 1).
    pub length: f64,
    /// The centre's horizontal velocity (default 0).
    pub vx: f64,
    /// The centre's vertical velocity (default −1: landing).
    pub vy: f64,
    /// The angular velocity (default 0).
    pub omega: f64,
}

impl Default for RodFlat {
    fn default() -> Self {
        Self {
            mass: 1.0,
            length: 1.0,
            vx: 0.0,
            vy: -1.0,
            omega: 0.0,
        }
    }
}

impl RodFlat {
    /// The system (default `μ = 0.5`, `e = 0.5`).
    ///
    /// # Errors
    /// `mass`, `length` not finite and positive; `vx`, `vy`, `omega` not finite.
    pub fn build(&self) -> Result<MultiScenario> {
        let m = positive("mass", self.mass)?;
        let l = positive("length", self.length)?;
        let u = [
            finite("vx", self.vx)?,
            finite("vy", self.vy)?,
            finite("omega", self.omega)?,
        ];
        let mut j = DMatrix::zeros(4, 3);
        let floor = [0.0, 1.0];
        point_rows(&mut j, 0, 0, [-0.5 * l, 0.0], floor, 1.0);
        point_rows(&mut j, 2, 0, [0.5 * l, 0.0], floor, 1.0);
        let impact = MultiImpact::new(
            coordinates(1),
            mass_matrix(&[(m, m * l * l / 12.0)]),
            vec!["end A".into(), "end B".into()],
            j,
            &u,
        )?;
        Ok(MultiScenario {
            name: "rod-flat",
            description: format!(
                "rod lying flat landing on both ends (m = {m}, l = {l}; v = ({}, {}), ω = {})",
                u[0], u[1], u[2]
            ),
            impact,
            friction: 0.5,
            restitution: 0.5,
        })
    }
}

/// `rocking-block`: a uniform rectangle (mass `m`, half-width `b`, half-height `h`,
/// `I = m (b² + h²)/3`) standing on the floor and rocking about its left corner A at the
/// angular velocity `ω < 0` (clockwise) as its right corner B strikes: the centre moves at
/// `ω ẑ × (b, h) = (−h ω, b ω)`, A is at rest, B comes down at `2 b |ω|`. Rows from the
/// corners at `(∓b, −h)` from the centre: `J_A = [[1, 0, h], [0, 1, −b]]`,
/// `J_B = [[1, 0, h], [0, 1, b]]`.
///
/// Housner (1963, *The behavior of inverted pendulum structures during earthquakes*, Bull.
/// Seismol. Soc. Am. 53): with a plastic impact at B (`e = 0`) and no slip, angular momentum
/// about B is conserved and the block goes on rocking about B with
/// `ω⁺/ω⁻ = 1 − (3/2) sin²α`, `α = atan(b/h)`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct RockingBlock {
    /// Mass `m` (default 1).
    pub mass: f64,
    /// Half-width `b` (default 0.2).
    pub half_width: f64,
    /// Half-height `h` (default 0.6).
    pub half_height: f64,
    /// The angular velocity about A before the impact, negative (default −1).
    pub omega: f64,
}

impl Default for RockingBlock {
    fn default() -> Self {
        Self {
            mass: 1.0,
            half_width: 0.2,
            half_height: 0.6,
            omega: -1.0,
        }
    }
}

impl RockingBlock {
    /// The system (default `μ = 1`, `e = 0`).
    ///
    /// # Errors
    /// `mass`, `half-width`, `half-height` not finite and positive; `omega` not finite and
    /// negative (B strikes only while the block turns clockwise about A).
    pub fn build(&self) -> Result<MultiScenario> {
        let m = positive("mass", self.mass)?;
        let b = positive("half-width", self.half_width)?;
        let h = positive("half-height", self.half_height)?;
        let w = finite("omega", self.omega)?;
        if w >= 0.0 {
            return Err(Error::OutOfRange {
                field: "omega".into(),
                value: w,
                reason: "must be negative: the block turns clockwise about its left corner A so that its right corner B strikes".into(),
            });
        }
        let mut j = DMatrix::zeros(4, 3);
        let floor = [0.0, 1.0];
        point_rows(&mut j, 0, 0, [-b, -h], floor, 1.0);
        point_rows(&mut j, 2, 0, [b, -h], floor, 1.0);
        let impact = MultiImpact::new(
            coordinates(1),
            mass_matrix(&[(m, m * (b * b + h * h) / 3.0)]),
            vec!["corner A".into(), "corner B".into()],
            j,
            &[-h * w, b * w, w],
        )?;
        Ok(MultiScenario {
            name: "rocking-block",
            description: format!(
                "block rocking about corner A as corner B strikes (m = {m}, half-width {b}, half-height {h}; ω = {w})"
            ),
            impact,
            friction: 1.0,
            restitution: 0.0,
        })
    }

    /// Housner's ratio `ω⁺/ω⁻ = 1 − (3/2) sin²α`, `α = atan(b/h)`: the block rocks on about
    /// B for a slender block (`b < √2 h`, a positive ratio); a squatter one cannot, and with
    /// `e = 0` comes to rest on both corners.
    pub fn housner_ratio(&self) -> f64 {
        let (b, h) = (self.half_width, self.half_height);
        1.0 - 1.5 * b * b / (b * b + h * h)
    }
}

/// `cradle`: `N` equal balls (solid spheres: mass `m`, radius `r`, `I = 2 m r²/5`) in a row
/// along `x`, touching, the first moving at `v0` towards the others. Contact `j` is between
/// balls `j` and `j + 1` (`n = x̂`, `t = −ŷ`): `v_n = v_x,j+1 − v_x,j`,
/// `v_t = −(v_y,j+1 − v_y,j) + r (ω_j + ω_j+1)`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Cradle {
    /// The number of balls `N ≥ 2` (default 3).
    pub balls: usize,
    /// Each ball's mass (default 1).
    pub mass: f64,
    /// Each ball's radius (default 0.5).
    pub radius: f64,
    /// The first ball's velocity (default 1).
    pub v0: f64,
}

impl Default for Cradle {
    fn default() -> Self {
        Self {
            balls: 3,
            mass: 1.0,
            radius: 0.5,
            v0: 1.0,
        }
    }
}

/// The most balls of a cradle.
pub const MAX_BALLS: usize = 100;

impl Cradle {
    /// The system (default `μ = 0`, `e = 1`).
    ///
    /// # Errors
    /// `balls` not in `2 ..= 100`; `mass`, `radius`, `v0` not finite and positive.
    pub fn build(&self) -> Result<MultiScenario> {
        let n = self.balls;
        if !(2..=MAX_BALLS).contains(&n) {
            return Err(Error::Invalid {
                field: "balls".into(),
                reason: format!("must be from 2 to {MAX_BALLS}, got {n}"),
            });
        }
        let m = positive("mass", self.mass)?;
        let r = positive("radius", self.radius)?;
        let v0 = positive("v0", self.v0)?;
        let mut j = DMatrix::zeros(2 * (n - 1), 3 * n);
        let along = [1.0, 0.0];
        for c in 0..n - 1 {
            point_rows(&mut j, 2 * c, c + 1, [-r, 0.0], along, 1.0);
            point_rows(&mut j, 2 * c, c, [r, 0.0], along, -1.0);
        }
        let mut u = vec![0.0; 3 * n];
        u[0] = v0;
        let impact = MultiImpact::new(
            coordinates(n),
            mass_matrix(&vec![(m, 0.4 * m * r * r); n]),
            (1..n).map(|i| format!("balls {i}–{}", i + 1)).collect(),
            j,
            &u,
        )?;
        Ok(MultiScenario {
            name: "cradle",
            description: format!(
                "Newton's cradle: {n} balls in a row touching, the first at v0 = {} (m = {}, r = {})",
                Num(v0),
                Num(m),
                Num(r)
            ),
            impact,
            friction: 0.0,
            restitution: 1.0,
        })
    }
}

/// `ball-ball-wall`: ball 1 (solid sphere: mass `m`, radius `r`) rests against a wall (the
/// line `x = 0`, normal `x̂`); ball 2 (the same) touches it with the line of centres at the
/// angle `θ` from `x̂` and moves at `v0` towards the wall (`−x̂`). Contact 1 (wall–ball 1):
/// `n = x̂`, `t = −ŷ`; contact 2 (ball 1–ball 2): `n = (cos θ, sin θ)`, `t = (sin θ, −cos θ)`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct BallBallWall {
    /// Each ball's mass (default 1).
    pub mass: f64,
    /// Each ball's radius (default 0.5).
    pub radius: f64,
    /// Ball 2's speed towards the wall (default 1).
    pub v0: f64,
    /// The angle of the line of centres from the wall's normal, degrees, in (−90, 90)
    /// (default 30).
    pub angle_deg: f64,
}

impl Default for BallBallWall {
    fn default() -> Self {
        Self {
            mass: 1.0,
            radius: 0.5,
            v0: 1.0,
            angle_deg: 30.0,
        }
    }
}

impl BallBallWall {
    /// The system (default `μ = 0`, `e = 1`).
    ///
    /// # Errors
    /// `mass`, `radius`, `v0` not finite and positive; `angle-deg` not in (−90, 90).
    pub fn build(&self) -> Result<MultiScenario> {
        let m = positive("mass", self.mass)?;
        let r = positive("radius", self.radius)?;
        let v0 = positive("v0", self.v0)?;
        let a = finite("angle-deg", self.angle_deg)?;
        if a.abs() >= 90.0 {
            return Err(Error::OutOfRange {
                field: "angle-deg".into(),
                value: a,
                reason: "must be in (−90, 90): ball 2 is on the side of ball 1 away from the wall"
                    .into(),
            });
        }
        let (s, c) = a.to_radians().sin_cos();
        let mut j = DMatrix::zeros(4, 6);
        point_rows(&mut j, 0, 0, [-r, 0.0], [1.0, 0.0], 1.0);
        let n = [c, s];
        point_rows(&mut j, 2, 1, [-r * c, -r * s], n, 1.0);
        point_rows(&mut j, 2, 0, [r * c, r * s], n, -1.0);
        let impact = MultiImpact::new(
            coordinates(2),
            mass_matrix(&[(m, 0.4 * m * r * r); 2]),
            vec!["wall–ball 1".into(), "ball 1–ball 2".into()],
            j,
            &[0.0, 0.0, 0.0, -v0, 0.0, 0.0],
        )?;
        Ok(MultiScenario {
            name: "ball-ball-wall",
            description: format!(
                "ball 1 against a wall struck by ball 2 at v0 = {}, centres at {}° from the wall's normal (m = {}, r = {})",
                Num(v0),
                Num(a),
                Num(m),
                Num(r)
            ),
            impact,
            friction: 0.0,
            restitution: 1.0,
        })
    }
}

/// `box-flat`: a uniform box (mass `m`, half-extents `a`, `b`, `c` along `x`, `y`, `z`;
/// `I = m diag(b² + c², a² + c², a² + b²)/3`) lying flat on the floor `z = 0`, its centre
/// moving at `(v_x, v_y, v_z)` and spinning about the vertical at `ω_z`; contacts at its four
/// lower corners `r = (±a, ±b, −c)` from the centre, frame `t1 = x̂`, `t2 = ŷ`, `n = ẑ`, rows
/// of `v + ω × r` (`u = (v, ω)`): twelve rows, six degrees of freedom, `W` of rank 6.
///
/// Landing without a horizontal velocity, every corner takes a quarter of
/// `m (1 + e) |v_z|` under `lcp` and the box leaves level at `e |v_z|`; the corners slip
/// round the vertical (each along `ω × r`, a different direction at each corner) and friction
/// takes `μ m (1 + e) |v_z| ρ` (`ρ = √(a² + b²)`) from the spin's angular momentum `I_z ω_z`,
/// or stops it.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct BoxFlat {
    /// Mass `m` (default 1).
    pub mass: f64,
    /// Half-extents `(a, b, c)` (default `(0.5, 0.3, 0.2)`).
    pub half_extents: [f64; 3],
    /// The centre's velocity (default `(0, 0, −1)`: landing).
    pub velocity: [f64; 3],
    /// The spin about the vertical `ω_z` (default 2).
    pub spin: f64,
}

impl Default for BoxFlat {
    fn default() -> Self {
        Self {
            mass: 1.0,
            half_extents: [0.5, 0.3, 0.2],
            velocity: [0.0, 0.0, -1.0],
            spin: 2.0,
        }
    }
}

impl BoxFlat {
    /// The corners' names, in order.
    pub const CORNERS: [&'static str; 4] = [
        "corner (+a, +b)",
        "corner (−a, +b)",
        "corner (−a, −b)",
        "corner (+a, −b)",
    ];

    /// The spatial system (default `μ = 0.3`, `e = 0.5`).
    ///
    /// # Errors
    /// `mass` and the half-extents (`half-extents`) not finite and positive; the velocity
    /// (`vx`, `vy`, `vz`) or the spin (`omega`) not finite.
    pub fn build(&self) -> Result<MultiScenario> {
        let m = positive("mass", self.mass)?;
        let [a, b, c] = self.half_extents;
        let (a, b, c) = (
            positive("half-extents", a)?,
            positive("half-extents", b)?,
            positive("half-extents", c)?,
        );
        let v = [
            finite("vx", self.velocity[0])?,
            finite("vy", self.velocity[1])?,
            finite("vz", self.velocity[2])?,
        ];
        let w = finite("omega", self.spin)?;
        let corners = [(a, b), (-a, b), (-a, -b), (a, -b)];
        let mut j = DMatrix::zeros(12, 6);
        for (k, &(x, y)) in corners.iter().enumerate() {
            let r = [x, y, -c];
            // v + ω × r: row `axis` has 1 at v_axis and (r × e_axis) at ω.
            for axis in 0..3 {
                j[(3 * k + axis, axis)] = 1.0;
                let mut e = [0.0; 3];
                e[axis] = 1.0;
                let cross = [
                    r[1] * e[2] - r[2] * e[1],
                    r[2] * e[0] - r[0] * e[2],
                    r[0] * e[1] - r[1] * e[0],
                ];
                for q in 0..3 {
                    j[(3 * k + axis, 3 + q)] = cross[q];
                }
            }
        }
        let inertia = [
            m * (b * b + c * c) / 3.0,
            m * (a * a + c * c) / 3.0,
            m * (a * a + b * b) / 3.0,
        ];
        let mass = DMatrix::from_diagonal(&nalgebra::DVector::from_vec(vec![
            m, m, m, inertia[0], inertia[1], inertia[2],
        ]));
        let impact = MultiImpact::spatial(
            ["x", "y", "z", "theta_x", "theta_y", "theta_z"]
                .map(String::from)
                .to_vec(),
            mass,
            Self::CORNERS.map(String::from).to_vec(),
            j,
            &[v[0], v[1], v[2], 0.0, 0.0, w],
        )?;
        Ok(MultiScenario {
            name: "box-flat",
            description: format!(
                "box lying flat landing on four corners (m = {m}, half-extents {a} × {b} × {c}; v = ({}, {}, {}), ω_z = {w})",
                v[0], v[1], v[2]
            ),
            impact,
            friction: 0.3,
            restitution: 0.5,
        })
    }
}
