//! The checks of a contact-space problem with `K` contacts, planar (`d = 2`) or spatial
//! (`d = 3`): one implementation for [`super::MultiProblem`] and
//! [`super::spatial::MultiProblem3`].

use super::problem::{RANGE_TOL, RANK_TOL};
use crate::error::{Error, Num, Result};
use crate::math::{exact_unit_factor, Units};
use nalgebra::{DMatrix, DVector};

/// Relative tolerance on the asymmetry of `W` accepted as round-off (as for one contact).
const SYMMETRY_TOL: f64 = 1e-12;

/// The components of one contact, tangent(s) first, normal last.
pub(crate) const fn components(d: usize) -> &'static [&'static str] {
    if d == 2 {
        &["t", "n"]
    } else {
        &["t1", "t2", "n"]
    }
}

/// The name of row or column `i` of a `dK × dK` `W`: planar `t1, n1, t2, …`; spatial
/// `t1_1, t2_1, n_1, t1_2, …` (contacts counted from 1).
pub(crate) fn row_name(d: usize, i: usize) -> String {
    let c = components(d)[i % d];
    if d == 2 {
        format!("{c}{}", i / d + 1)
    } else {
        format!("{c}_{}", i / d + 1)
    }
}

/// The field of component `i` of `v⁻`: `v[n,2]` is the second contact's normal velocity.
pub(crate) fn velocity_name(d: usize, i: usize) -> String {
    format!("v[{},{}]", components(d)[i % d], i / d + 1)
}

/// The per-contact coefficients: one value for every contact or one per contact, each finite
/// and in range; the field `name` (or `name[j]`, counted from 1, with one value per contact).
pub(crate) fn coefficients(
    name: &str,
    values: &[f64],
    k: usize,
    check: impl Fn(f64) -> Option<&'static str>,
) -> Result<Vec<f64>> {
    if values.len() != 1 && values.len() != k {
        return Err(Error::Invalid {
            field: name.into(),
            reason: format!(
                "expected 1 value (every contact) or {k} (one per contact), got {}",
                values.len()
            ),
        });
    }
    let field = |j: usize| {
        if values.len() == 1 {
            name.to_string()
        } else {
            format!("{name}[{}]", j + 1)
        }
    };
    for (j, &x) in values.iter().enumerate() {
        crate::error::finite_named(|| field(j), x)?;
        if let Some(reason) = check(x) {
            return Err(Error::OutOfRange {
                field: field(j),
                value: x,
                reason: reason.into(),
            });
        }
    }
    Ok((0..k)
        .map(|j| values[if values.len() == 1 { 0 } else { j }])
        .collect())
}

/// The stiffness ratios `κ_j` of `lzb`: one value for every contact or `K`, each positive and
/// finite (field `stiffness`, `stiffness[j]`).
pub(crate) fn stiffnesses(values: &[f64], k: usize) -> Result<Vec<f64>> {
    coefficients("stiffness", values, k, |x| {
        (x <= 0.0).then_some("a stiffness must be > 0")
    })
}

/// The exponent `η` of `lzb`'s force law: finite and `> 0` (field `exponent`).
pub(crate) fn exponent(eta: f64) -> Result<f64> {
    crate::error::finite("exponent", eta)?;
    if eta <= 0.0 {
        return Err(Error::OutOfRange {
            field: "exponent".into(),
            value: eta,
            reason: "the exponent of the force law must be > 0".into(),
        });
    }
    Ok(eta)
}

/// `W` from its upper triangle, row by row (`dK (dK + 1) / 2` numbers).
pub(crate) fn from_upper_triangle(
    d: usize,
    contacts: usize,
    upper: &[f64],
) -> Result<DMatrix<f64>> {
    let n = d * contacts;
    let expected = n * (n + 1) / 2;
    if contacts == 0 || upper.len() != expected {
        return Err(Error::Invalid {
            field: "w".into(),
            reason: if contacts == 0 {
                "at least one contact is needed".into()
            } else {
                format!(
                    "expected {expected} numbers (the upper triangle of the {n} × {n} W, row by row), got {}",
                    upper.len()
                )
            },
        });
    }
    let mut w = DMatrix::zeros(n, n);
    let mut it = upper.iter();
    for i in 0..n {
        for j in i..n {
            let x = *it.next().expect("counted above");
            w[(i, j)] = x;
            w[(j, i)] = x;
        }
    }
    Ok(w)
}

/// A problem that passed every check: what both problem types keep.
#[derive(Debug, Clone, PartialEq)]
pub(crate) struct Checked {
    pub k: usize,
    /// `W` as given (symmetrised).
    pub w: DMatrix<f64>,
    /// `v⁻` as given (its round-off outside the range of a singular `W` removed).
    pub v: DVector<f64>,
    pub mu: Vec<f64>,
    pub e: Vec<f64>,
    pub rank: usize,
    pub approach_energy: f64,
    /// The canonical units: velocities times `units.a`, `W` times `units.b` (powers of two).
    pub units: Units,
    /// `W` and `v⁻` in the canonical units, where the laws work.
    pub ws: DMatrix<f64>,
    pub vs: DVector<f64>,
}

/// Check a problem of `d` components per contact (the docs of [`super::MultiProblem`] list
/// the checks); `own_block(w, j)` checks contact `j`'s own `d × d` block of `W`.
pub(crate) fn check(
    d: usize,
    w: DMatrix<f64>,
    v: &[f64],
    friction: &[f64],
    restitution: &[f64],
    own_block: impl Fn(&DMatrix<f64>, usize) -> Result<()>,
) -> Result<Checked> {
    let n = w.nrows();
    let what = if d == 2 {
        "tangent and normal"
    } else {
        "two tangents and normal"
    };
    if n == 0 || !n.is_multiple_of(d) || w.ncols() != n {
        return Err(Error::Invalid {
            field: "w".into(),
            reason: format!(
                "must be {d}K × {d}K for K ≥ 1 contacts ({what} of each), got {} × {}",
                w.nrows(),
                w.ncols()
            ),
        });
    }
    let k = n / d;
    if v.len() != n {
        return Err(Error::Invalid {
            field: "v".into(),
            reason: format!(
                "expected {n} numbers ({what} of each of {k} contacts), got {}",
                v.len()
            ),
        });
    }
    let w = symmetric(d, w)?;
    for j in 0..k {
        own_block(&w, j).map_err(|e| match e {
            Error::NotPositiveDefinite { reason, .. } => Error::NotPositiveDefinite {
                field: "w".into(),
                reason: format!("contact {}'s own block: {reason}", j + 1),
            },
            other => other,
        })?;
    }
    for (i, &x) in v.iter().enumerate() {
        crate::error::finite_named(|| velocity_name(d, i), x)?;
    }
    let mu = coefficients("friction", friction, k, crate::error::friction_out_of_range)?;
    let e = coefficients("restitution", restitution, k, |x| {
        (!(0.0..=1.0).contains(&x)).then_some("the coefficient of restitution must be in [0, 1]")
    })?;
    let least = (0..k)
        .map(|j| v[d * j + d - 1])
        .fold(f64::INFINITY, f64::min);
    if least >= 0.0 {
        return Err(Error::NotApproaching {
            field: "v".into(),
            value: least,
        });
    }
    spectrum(d, k, w, v, mu, e)
}

/// Every entry finite and `W` symmetric to round-off (the mean of the two off-diagonal
/// entries kept).
fn symmetric(d: usize, mut w: DMatrix<f64>) -> Result<DMatrix<f64>> {
    let n = w.nrows();
    for i in 0..n {
        for j in 0..n {
            crate::error::finite_named(
                || format!("w[{},{}]", row_name(d, i), row_name(d, j)),
                w[(i, j)],
            )?;
        }
    }
    let scale = w.amax().max(f64::MIN_POSITIVE);
    for i in 0..n {
        for j in i + 1..n {
            let (upper, lower) = (w[(i, j)], w[(j, i)]);
            if (upper - lower).abs() > SYMMETRY_TOL * scale {
                return Err(Error::Invalid {
                    field: "w".into(),
                    reason: format!(
                        "must be symmetric, but w[{},{}] = {} differs from w[{},{}] = {}",
                        row_name(d, i),
                        row_name(d, j),
                        Num(upper),
                        row_name(d, j),
                        row_name(d, i),
                        Num(lower)
                    ),
                });
            }
            let mean = 0.5 * upper + 0.5 * lower;
            w[(i, j)] = mean;
            w[(j, i)] = mean;
        }
    }
    Ok(w)
}

/// The canonical units, the rank of `W` (positive semidefinite), `v⁻` in its range and the
/// approach energy `½ v⁻ᵀ W⁺ v⁻`.
fn spectrum(
    d: usize,
    k: usize,
    w: DMatrix<f64>,
    v: &[f64],
    mu: Vec<f64>,
    e: Vec<f64>,
) -> Result<Checked> {
    let n = d * k;
    // Canonical units (powers of two, exact): the largest |v| and diagonal entry of W in
    // [1, 2).
    let vmax = v.iter().fold(0.0f64, |m, x| m.max(x.abs()));
    let dmax = (0..n).fold(0.0f64, |m, i| m.max(w[(i, i)]));
    let units = Units {
        a: exact_unit_factor(vmax, v),
        b: exact_unit_factor(dmax, w.as_slice()),
    };
    let ws = &w * units.b;
    let mut vs = DVector::from_column_slice(v) * units.a;
    let eig = ws
        .clone()
        .try_symmetric_eigen(f64::EPSILON, 10_000)
        .ok_or_else(|| Error::Invalid {
            field: "w".into(),
            reason: "its eigenvalues could not be computed".into(),
        })?;
    let lmax = eig.eigenvalues.max();
    let lmin = eig.eigenvalues.min();
    if lmin < -RANK_TOL * lmax {
        return Err(Error::Invalid {
            field: "w".into(),
            reason: format!(
                "must be positive semidefinite, but its smallest eigenvalue is {} of its largest",
                Num(lmin / lmax)
            ),
        });
    }
    let zero = |l: f64| l.abs() <= RANK_TOL * lmax;
    let rank = eig.eigenvalues.iter().filter(|&&l| !zero(l)).count();
    if rank < n {
        // v⁻ must be a velocity J u: in the range of W = J M⁻¹ Jᵀ.
        let norm = vs.norm();
        let mut outside = DVector::zeros(n);
        for (c, &l) in eig.eigenvalues.iter().enumerate() {
            if zero(l) {
                let u = eig.eigenvectors.column(c);
                outside += u * u.dot(&vs);
            }
        }
        let part = outside.norm() / norm;
        if part > RANGE_TOL {
            return Err(Error::Invalid {
                field: "v".into(),
                reason: format!(
                    "not a velocity the contacts can have: W is singular (rank {rank} of {n}: the contacts are redundant) and v has a component of {} of |v| outside its range (a velocity J u of the bodies has none)",
                    Num(part)
                ),
            });
        }
        // Below round-off of the eigenvectors themselves, v⁻ is kept exactly as given.
        if part > 64.0 * f64::EPSILON {
            vs -= outside;
        }
    }
    let mut energy = 0.0;
    for (c, &l) in eig.eigenvalues.iter().enumerate() {
        if !zero(l) {
            let x = eig.eigenvectors.column(c).dot(&vs);
            energy += 0.5 * x * x / l;
        }
    }
    let approach_energy = units.work(energy);
    crate::error::representable_energy(approach_energy, vmax)?;
    let v = if vs.as_slice() != (DVector::from_column_slice(v) * units.a).as_slice() {
        vs.map(|x| units.velocity(x))
    } else {
        DVector::from_column_slice(v)
    };
    Ok(Checked {
        k,
        w,
        v,
        mu,
        e,
        rank,
        approach_energy,
        units,
        ws,
        vs,
    })
}
