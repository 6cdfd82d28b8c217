//! The serialized forms of the types that keep an invariant (feature `serde`).
//!
//! A problem is written as plain data — `W` row by row, `v⁻`, the coefficients — and read
//! back through its validating constructor, so that a deserialized problem is as checked as a
//! built one (the error names the field, as [`crate::Error`] does). A phase sequence is
//! written as the list of its phases and read back phase by phase, within its capacity.

use crate::math::{Mat2, Mat3, Vec2, Vec3};
use crate::multi::MultiProblem;
use crate::planar::{ContactProblem, Phase, Phases};
use crate::spatial;
use nalgebra::DMatrix;
use serde::de::Error as _;
use serde::{Deserialize, Deserializer, Serialize, Serializer};

/// A planar problem as written: `W` by rows, `v⁻ = (v_t, v_n)`, `μ`, `e`.
#[derive(Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
struct ContactProblemForm {
    w: [[f64; 2]; 2],
    v: Vec2,
    friction: f64,
    restitution: f64,
}

impl Serialize for ContactProblem {
    fn serialize<S: Serializer>(&self, serializer: S) -> Result<S::Ok, S::Error> {
        ContactProblemForm {
            w: [[self.wtt(), self.wtn()], [self.wtn(), self.wnn()]],
            v: self.velocity(),
            friction: self.friction(),
            restitution: self.restitution(),
        }
        .serialize(serializer)
    }
}

impl<'de> Deserialize<'de> for ContactProblem {
    fn deserialize<D: Deserializer<'de>>(deserializer: D) -> Result<Self, D::Error> {
        let f = ContactProblemForm::deserialize(deserializer)?;
        let w = Mat2::new(f.w[0][0], f.w[0][1], f.w[1][0], f.w[1][1]);
        ContactProblem::new(w, f.v, f.friction, f.restitution).map_err(D::Error::custom)
    }
}

/// A spatial problem as written: `W` by rows, `v⁻ = (v_t1, v_t2, v_n)`, `μ`, `e`.
#[derive(Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
struct ContactProblem3Form {
    w: [[f64; 3]; 3],
    v: Vec3,
    friction: f64,
    restitution: f64,
}

impl Serialize for spatial::ContactProblem {
    fn serialize<S: Serializer>(&self, serializer: S) -> Result<S::Ok, S::Error> {
        let w = self.w();
        ContactProblem3Form {
            w: [0, 1, 2].map(|i| [0, 1, 2].map(|j| w[(i, j)])),
            v: self.velocity(),
            friction: self.friction(),
            restitution: self.restitution(),
        }
        .serialize(serializer)
    }
}

impl<'de> Deserialize<'de> for spatial::ContactProblem {
    fn deserialize<D: Deserializer<'de>>(deserializer: D) -> Result<Self, D::Error> {
        let f = ContactProblem3Form::deserialize(deserializer)?;
        let w = Mat3::from_fn(|i, j| f.w[i][j]);
        spatial::ContactProblem::new(w, f.v, f.friction, f.restitution).map_err(D::Error::custom)
    }
}

/// A problem with several contacts as written: `W` by rows (`2K × 2K`, contact-major), `v⁻`
/// (`2K` numbers), and per contact `μ`, `e` and the stiffness ratio of `lzb`, with `lzb`'s
/// exponent.
#[derive(Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
struct MultiProblemForm {
    w: Vec<Vec<f64>>,
    v: Vec<f64>,
    friction: Vec<f64>,
    restitution: Vec<f64>,
    stiffness: Vec<f64>,
    exponent: f64,
}

/// The serde impls of a problem type with several contacts (planar and spatial share the
/// form; the spatial `W` is `3K × 3K`).
macro_rules! multi_form {
    ($ty:ty) => {
        impl Serialize for $ty {
            fn serialize<S: Serializer>(&self, serializer: S) -> Result<S::Ok, S::Error> {
                let k = self.contacts();
                let w = self.w();
                MultiProblemForm {
                    w: w.row_iter().map(|r| r.iter().copied().collect()).collect(),
                    v: self.velocity().iter().copied().collect(),
                    friction: (0..k).map(|j| self.friction(j)).collect(),
                    restitution: (0..k).map(|j| self.restitution(j)).collect(),
                    stiffness: (0..k).map(|j| self.stiffness(j)).collect(),
                    exponent: self.exponent(),
                }
                .serialize(serializer)
            }
        }

        impl<'de> Deserialize<'de> for $ty {
            fn deserialize<D: Deserializer<'de>>(deserializer: D) -> Result<Self, D::Error> {
                let f = MultiProblemForm::deserialize(deserializer)?;
                let n = f.w.len();
                if let Some(row) = f.w.iter().find(|r| r.len() != n) {
                    return Err(D::Error::custom(format!(
                        "w: every row must have {n} entries (W is square), one has {}",
                        row.len()
                    )));
                }
                let w = DMatrix::from_fn(n, n, |i, j| f.w[i][j]);
                <$ty>::new(w, &f.v, &f.friction, &f.restitution)
                    .and_then(|p| p.with_stiffness(&f.stiffness))
                    .and_then(|p| p.with_exponent(f.exponent))
                    .map_err(D::Error::custom)
            }
        }
    };
}

multi_form!(MultiProblem);
multi_form!(crate::multi::spatial::MultiProblem);

impl Serialize for Phases {
    fn serialize<S: Serializer>(&self, serializer: S) -> Result<S::Ok, S::Error> {
        serializer.collect_seq(self.as_slice())
    }
}

impl<'de> Deserialize<'de> for Phases {
    /// At most [`Phases::CAPACITY`] phases, no two in a row of the same kind (a law's phase
    /// ends where its regime changes).
    fn deserialize<D: Deserializer<'de>>(deserializer: D) -> Result<Self, D::Error> {
        let list = Vec::<Phase>::deserialize(deserializer)?;
        if list.len() > Phases::CAPACITY {
            return Err(D::Error::custom(format!(
                "phases: at most {} phases, got {}",
                Phases::CAPACITY,
                list.len()
            )));
        }
        if list.windows(2).any(|w| w[0].kind == w[1].kind) {
            return Err(D::Error::custom(
                "phases: two phases in a row of the same kind",
            ));
        }
        let mut phases = Phases::new();
        for p in list {
            phases.push(p.kind, p.ends_at);
        }
        Ok(phases)
    }
}

impl Serialize for spatial::Phases {
    fn serialize<S: Serializer>(&self, serializer: S) -> Result<S::Ok, S::Error> {
        serializer.collect_seq(self.as_slice())
    }
}

impl<'de> Deserialize<'de> for spatial::Phases {
    /// At most two phases (slip, then stick or resumed slip).
    fn deserialize<D: Deserializer<'de>>(deserializer: D) -> Result<Self, D::Error> {
        let list = Vec::<spatial::Phase>::deserialize(deserializer)?;
        if list.len() > 2 {
            return Err(D::Error::custom(format!(
                "phases: at most 2 phases, got {}",
                list.len()
            )));
        }
        let mut phases = spatial::Phases::new();
        for p in list {
            phases.push(p.kind, p.ends_at);
        }
        Ok(phases)
    }
}
