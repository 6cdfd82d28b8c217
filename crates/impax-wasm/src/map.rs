//! An energy map: one law over a grid of two parameters of a case, `ΔT/T0` and a class per
//! cell (paper A's γ–α map of the energy gain, or any two parameters).
//!
//! Request:
//!
//! ```json
//! {"scenario": {… a compare request …}, "law": "whittaker",
//!  "x": {"name": "spin_ratio", "min": -2, "max": 2, "count": 200},
//!  "y": {"name": "alpha_deg", "min": 0, "max": 89, "count": 200}}
//! ```
//!
//! Parameters: [`crate::case::BODY_PARAMETERS`] for a body, [`crate::case::MECHANISM_PARAMETERS`]
//! for a mechanism. Cell `(i, j)` (column `i` of `x`, row `j` of `y`, both from the minimum)
//! is at index `j · nx + i` and evaluated at `min + (max − min) k / (count − 1)`.
//!
//! Answer: `{"law", "x", "y", "counts": {class: n}, "range": [lo, hi] | null,
//! "first_invalid": text | null, "marker": [x, y] | null, "threshold": null | {"upper",
//! "lower"}}`; the cells are in the two arrays the caller passed. `marker` is the request's own
//! point; `threshold` is paper A eq. 13's boundary `γ*(α)` as lists of `[x, y]` polylines, for a
//! sphere with `whittaker` mapped over `spin_ratio` and `alpha_deg`.

use crate::case::{Case, Request, BODY_PARAMETERS, MECHANISM_PARAMETERS};
use impax::analysis::whittaker_sphere_thresholds;
use impax::mechanism::impact::MechanismImpact;
use impax::planar::bodies::{self, BodyImpact};
use impax::planar::Verdict;
use impax::scenario::{Shape, ShapeScalar};
use impax::LawId;
use serde::Deserialize;
use serde_json::{json, Value};

/// The most cells a map may have.
pub const MAX_CELLS: usize = 1_000_000;

/// The class of a map cell (the `u8` stored per cell).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
#[repr(u8)]
pub enum Class {
    /// `ΔT > 0`: energy gained (Kane's paradox).
    Gained = 0,
    /// `ΔT ≤ 0` and the law's assumptions hold.
    Lost = 1,
    /// `ΔT ≤ 0` but the law's own assumption is contradicted.
    Inconsistent = 2,
    /// The law gives no result (e.g. a negative normal impulse).
    Breakdown = 3,
    /// The point is not an impact (e.g. no approach).
    Invalid = 4,
}

impl Class {
    /// Stable names, in the order of the `u8` values.
    pub const NAMES: [&'static str; 5] = ["gained", "lost", "inconsistent", "breakdown", "invalid"];
}

/// One axis of a map.
#[derive(Debug, Clone, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct AxisSpec {
    /// A parameter name.
    pub name: String,
    /// First value.
    pub min: f64,
    /// Last value.
    pub max: f64,
    /// Number of values, 2 to 2000.
    pub count: usize,
}

impl AxisSpec {
    /// Value number `k`.
    pub fn at(&self, k: usize) -> f64 {
        self.min + (self.max - self.min) * k as f64 / (self.count - 1) as f64
    }

    fn check(&self, which: &str, known: &[&str]) -> Result<(), String> {
        if !known.contains(&self.name.as_str()) {
            return Err(format!(
                "{which}.name: unknown parameter `{}` (known: {})",
                self.name,
                known.join(", ")
            ));
        }
        if !(self.min.is_finite() && self.max.is_finite() && self.min < self.max) {
            return Err(format!(
                "{which}: need finite min < max, got {} to {}",
                self.min, self.max
            ));
        }
        if !(2..=2000).contains(&self.count) {
            return Err(format!(
                "{which}.count: must be 2 to 2000, got {}",
                self.count
            ));
        }
        Ok(())
    }
}

/// A map request.
#[derive(Debug, Clone, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct MapRequest {
    /// The case whose parameters are varied.
    pub scenario: Request,
    /// The law's id.
    pub law: String,
    /// Horizontal axis.
    pub x: AxisSpec,
    /// Vertical axis.
    pub y: AxisSpec,
}

/// Set parameter `name` of a request.
fn set(r: &mut Request, name: &str, value: f64) {
    match name {
        "friction" => r.friction = value,
        "restitution" => r.restitution = value,
        _ => {}
    }
    if let Some(b) = r.body.as_mut() {
        match name {
            "alpha_deg" => b.alpha = Some(value),
            "spin_ratio" => b.spin_ratio = Some(value),
            // A number of the body's shape, if its shape has it (the core's table).
            _ => {
                let shape = Shape::from_name(&b.shape);
                if let Some(s) = ShapeScalar::from_name(name) {
                    if shape.is_some_and(|shape| shape.has_scalar(s)) {
                        b.set_scalar(s, value);
                    }
                }
            }
        }
    }
    if let Some(m) = r.mechanism.as_mut() {
        match name {
            "angle1_deg" => m.angles_deg[0] = value,
            "angle2_deg" => m.angles_deg[1] = value,
            "rate1" => m.rates[0] = value,
            "rate2" => m.rates[1] = value,
            _ => {}
        }
    }
}

/// The value of parameter `name` of a request, if it has one.
fn get(r: &Request, name: &str) -> Option<f64> {
    match name {
        "friction" => return Some(r.friction),
        "restitution" => return Some(r.restitution),
        _ => {}
    }
    if let Some(b) = &r.body {
        return match name {
            "alpha_deg" => b.alpha,
            "spin_ratio" => b.spin_ratio,
            _ => ShapeScalar::from_name(name).and_then(|s| b.scalar(s)),
        };
    }
    if let Some(m) = &r.mechanism {
        return match name {
            "angle1_deg" => Some(m.angles_deg[0]),
            "angle2_deg" => Some(m.angles_deg[1]),
            "rate1" => Some(m.rates[0]),
            "rate2" => Some(m.rates[1]),
            _ => None,
        };
    }
    None
}

/// `(ΔT/T0, class)` of one body point; `Err` for an invalid point.
fn body_point(r: &Request, law: LawId, base: Option<&BodyImpact>) -> Result<(f64, Class), String> {
    let spec = r.body.as_ref().ok_or("request: no body")?;
    let impact = match base {
        // Only the motion changes: keep the body, set the state.
        Some(base) => {
            let alpha_deg = spec.alpha.unwrap_or(f64::NAN);
            if !(alpha_deg > -90.0 && alpha_deg < 90.0) {
                return Err(format!(
                    "alpha_deg: must be in (-90, 90) for the body to approach the surface, got {alpha_deg}"
                ));
            }
            let rho = base.body.0.contact().norm();
            let state = bodies::spin_state(
                spec.speed.unwrap_or(f64::NAN),
                alpha_deg.to_radians(),
                spec.spin_ratio.unwrap_or(f64::NAN),
                rho,
            )
            .map_err(|e| e.to_string())?;
            BodyImpact::on_fixed_surface(base.body.0, state)
        }
        None => match r.case()? {
            Case::Body(b) => b.impact,
            Case::Mechanism(_) => return Err("request: not a body".into()),
        },
    };
    let problem = impact
        .problem(r.friction, r.restitution)
        .map_err(|e| e.to_string())?;
    let before = impact.energy_before();
    let t0 = if before.translational > 0.0 {
        before.translational
    } else {
        before.total()
    };
    Ok(match impact.resolve(law, &problem) {
        Ok(b) => classify(b.outcome.verdict, b.outcome.energy_change / t0),
        Err(_) => (f64::NAN, Class::Breakdown),
    })
}

fn classify(v: Verdict, ratio: f64) -> (f64, Class) {
    let class = match v {
        Verdict::EnergyGained => Class::Gained,
        Verdict::Consistent => Class::Lost,
        Verdict::InconsistentAssumption => Class::Inconsistent,
    };
    (ratio, class)
}

fn mechanism_point(r: &Request, law: LawId) -> Result<(f64, Class), String> {
    let Case::Mechanism(case) = r.case()? else {
        return Err("request: not a mechanism".into());
    };
    let impact =
        MechanismImpact::new(&case.pendulum, &case.q, &case.u, 0).map_err(|e| e.to_string())?;
    let t0 = impact.energy_before();
    let problem = impact
        .problem(r.friction, r.restitution)
        .map_err(|e| e.to_string())?;
    Ok(match law.resolve(&problem) {
        Ok(o) => classify(o.verdict, o.energy_change / t0),
        Err(_) => (f64::NAN, Class::Breakdown),
    })
}

/// Compute a map: fill `values` and `classes` (`nx · ny` cells) and describe it.
///
/// # Errors
/// An unknown law or parameter, a bad axis, too many cells, or a base case that is itself
/// invalid.
pub fn compute(
    req: &MapRequest,
    values: &mut Vec<f32>,
    classes: &mut Vec<u8>,
) -> Result<Value, String> {
    let law: LawId = req.law.parse().map_err(|e: impax::Error| e.to_string())?;
    let base = req.scenario.case()?;
    let known: &[&str] = match &base {
        Case::Body(_) => &BODY_PARAMETERS,
        Case::Mechanism(_) => &MECHANISM_PARAMETERS,
    };
    if matches!(base, Case::Mechanism(_)) && law.needs_body() {
        return Err(format!("law: `{law}` needs a body, not a mechanism"));
    }
    req.x.check("x", known)?;
    req.y.check("y", known)?;
    if req.x.name == req.y.name {
        return Err(format!(
            "y.name: the same parameter as x (`{}`)",
            req.x.name
        ));
    }
    let (nx, ny) = (req.x.count, req.y.count);
    if nx * ny > MAX_CELLS {
        return Err(format!(
            "x.count × y.count: at most {MAX_CELLS} cells, got {}",
            nx * ny
        ));
    }
    values.clear();
    classes.clear();
    values.reserve(nx * ny);
    classes.reserve(nx * ny);
    // A body whose shape is not swept is built once.
    let fixed_body = match &base {
        Case::Body(b) if req.x.name != "angle_deg" && req.y.name != "angle_deg" => Some(b.impact),
        _ => None,
    };
    let mut counts = [0usize; 5];
    let (mut lo, mut hi) = (f64::INFINITY, f64::NEG_INFINITY);
    let mut first_invalid: Option<String> = None;
    let mut r = req.scenario.clone();
    for j in 0..ny {
        set(&mut r, &req.y.name, req.y.at(j));
        for i in 0..nx {
            set(&mut r, &req.x.name, req.x.at(i));
            let point = match &base {
                Case::Body(_) => body_point(&r, law, fixed_body.as_ref()),
                Case::Mechanism(_) => mechanism_point(&r, law),
            };
            let (ratio, class) = match point {
                Ok(p) => p,
                Err(e) => {
                    if first_invalid.is_none() {
                        first_invalid = Some(format!(
                            "{} = {}, {} = {}: {e}",
                            req.x.name,
                            req.x.at(i),
                            req.y.name,
                            req.y.at(j)
                        ));
                    }
                    (f64::NAN, Class::Invalid)
                }
            };
            if ratio.is_finite() {
                lo = lo.min(ratio);
                hi = hi.max(ratio);
            }
            counts[class as usize] += 1;
            values.push(ratio as f32);
            classes.push(class as u8);
        }
    }
    let threshold = threshold(req, &base, law);
    let marker = match (
        get(&req.scenario, &req.x.name),
        get(&req.scenario, &req.y.name),
    ) {
        (Some(x), Some(y)) => json!([x, y]),
        _ => Value::Null,
    };
    let mut count_map = serde_json::Map::new();
    for (k, name) in Class::NAMES.iter().enumerate() {
        count_map.insert((*name).into(), json!(counts[k]));
    }
    Ok(json!({
        "law": law.as_str(),
        "x": { "name": req.x.name, "min": req.x.min, "max": req.x.max, "count": nx },
        "y": { "name": req.y.name, "min": req.y.min, "max": req.y.max, "count": ny },
        "cells": nx * ny,
        "counts": count_map,
        "range": if lo <= hi { json!([lo, hi]) } else { Value::Null },
        "first_invalid": first_invalid,
        "marker": marker,
        "threshold": threshold,
    }))
}

/// Paper A eq. 13's boundary `γ*(α)` for a sphere under Whittaker's rule, in map
/// coordinates, when the map is over `spin_ratio` and `alpha_deg`.
fn threshold(req: &MapRequest, base: &Case, law: LawId) -> Value {
    let Case::Body(b) = base else {
        return Value::Null;
    };
    if b.shape != Shape::Sphere || law != LawId::Whittaker {
        return Value::Null;
    }
    let (alpha_axis, alpha_is_y) = match (req.x.name.as_str(), req.y.name.as_str()) {
        ("spin_ratio", "alpha_deg") => (&req.y, true),
        ("alpha_deg", "spin_ratio") => (&req.x, false),
        _ => return Value::Null,
    };
    let (e, mu) = (req.scenario.restitution, req.scenario.friction);
    // Polylines, broken where a root leaves its branch.
    let mut upper: Vec<Vec<Value>> = vec![Vec::new()];
    let mut lower: Vec<Vec<Value>> = vec![Vec::new()];
    let steps = 400;
    for k in 0..=steps {
        let alpha = alpha_axis.min + (alpha_axis.max - alpha_axis.min) * k as f64 / steps as f64;
        let t = if alpha > -90.0 && alpha < 90.0 {
            whittaker_sphere_thresholds(alpha.to_radians(), e, mu)
        } else {
            impax::analysis::SphereThresholds {
                upper: None,
                lower: None,
            }
        };
        for (root, lines) in [(t.upper, &mut upper), (t.lower, &mut lower)] {
            match root {
                Some(g) => lines.last_mut().expect("one line").push(if alpha_is_y {
                    json!([g, alpha])
                } else {
                    json!([alpha, g])
                }),
                None if !lines.last().expect("one line").is_empty() => lines.push(Vec::new()),
                None => {}
            }
        }
    }
    upper.retain(|l| l.len() > 1);
    lower.retain(|l| l.len() > 1);
    json!({ "upper": upper, "lower": lower })
}
