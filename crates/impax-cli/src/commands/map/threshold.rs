//! For paper A's sphere swept over α and γ: the energy-gain boundary of Whittaker's rule
//! found by the engine on the grid, against the analytic threshold of paper A eq. 13 (and
//! the printed eqs. 14–15), as a report and as overlays of the `whittaker` panel.

use crate::output::plot::map::Overlay;
use crate::pipeline::space::Setup;
use crate::pipeline::template::{Field, Param};
use impax::analysis::{whittaker_sphere_thresholds, Axis};
use plotters::style::RGBColor;

/// Which grid axis is α and which is γ, when the scenario is paper A's sphere.
#[derive(Debug, Clone, Copy)]
pub(super) struct SeedAxes {
    /// Whether the first (x) axis is α (else it is γ).
    alpha_is_x: bool,
}

/// The axes of a map of paper A's sphere over α and γ (`None` for any other map).
pub(super) fn seed_axes(setup: &Setup) -> Option<SeedAxes> {
    if !setup.template.is_seed_sphere() {
        return None;
    }
    let a = Field::Body(Param::AlphaDeg);
    let g = Field::Body(Param::SpinRatio);
    match (setup.fields[0], setup.fields[1]) {
        (x, y) if x == a && y == g => Some(SeedAxes { alpha_is_x: true }),
        (x, y) if x == g && y == a => Some(SeedAxes { alpha_is_x: false }),
        _ => None,
    }
}

/// The engine's energy-gain boundary of Whittaker's rule against paper A eq. 13.
pub(super) struct Comparison {
    /// The comparison in words.
    pub(super) report: String,
    /// Engine boundary, lower and upper, as runs of (α, γ).
    engine: [Vec<Vec<(f64, f64)>>; 2],
    /// Eq. 13 thresholds γ*₋, γ*₊ as runs of (α, γ).
    analytic: [Vec<Vec<(f64, f64)>>; 2],
    /// The no-slip line γ = −sin α.
    no_slip: Vec<(f64, f64)>,
    /// Paper A's printed eqs. 14–15 points at α = 30° (only for the seed's e and f).
    printed: Vec<(f64, f64)>,
    alpha_is_x: bool,
}

impl Comparison {
    /// The overlays: the no-slip line on every panel, the boundaries on the `whittaker`
    /// panel (`panel`).
    pub(super) fn overlays(&self, panel: usize, panels: usize) -> Vec<Overlay> {
        let xy = |runs: &[Vec<(f64, f64)>]| -> Vec<Vec<(f64, f64)>> {
            runs.iter()
                .map(|r| {
                    r.iter()
                        .map(|&(a, g)| if self.alpha_is_x { (a, g) } else { (g, a) })
                        .collect()
                })
                .collect()
        };
        let mut v = Vec::new();
        for k in 0..panels {
            v.push(Overlay {
                panel: k,
                label: "no slip before the impact: γ = −sin α".into(),
                runs: xy(std::slice::from_ref(&self.no_slip)),
                colour: RGBColor(60, 60, 60),
                width: 1,
                dashed: true,
                markers: false,
            });
        }
        v.push(Overlay {
            panel,
            label: "whittaker: energy-gain boundary found by the engine on the grid".into(),
            runs: xy(&[self.engine[0].clone(), self.engine[1].clone()].concat()),
            colour: RGBColor(0, 0, 0),
            width: 4,
            dashed: false,
            markers: false,
        });
        v.push(Overlay {
            panel,
            label: "paper A eq. 13: ΔT = 0 (analytic γ*₊, γ*₋)".into(),
            runs: xy(&[self.analytic[0].clone(), self.analytic[1].clone()].concat()),
            colour: RGBColor(255, 215, 0),
            width: 2,
            dashed: true,
            markers: false,
        });
        if !self.printed.is_empty() {
            v.push(Overlay {
                panel,
                label: "paper A eqs. 14–15 as printed: γ = ±0.20 at α = 30°".into(),
                runs: xy(std::slice::from_ref(&self.printed)),
                colour: RGBColor(30, 90, 200),
                width: 2,
                dashed: false,
                markers: true,
            });
        }
        v
    }
}

/// Split points with NaN γ into runs.
fn runs(points: impl Iterator<Item = (f64, f64)>) -> Vec<Vec<(f64, f64)>> {
    let mut out = Vec::new();
    let mut cur = Vec::new();
    for (a, g) in points {
        if g.is_finite() {
            cur.push((a, g));
        } else if !cur.is_empty() {
            out.push(std::mem::take(&mut cur));
        }
    }
    if !cur.is_empty() {
        out.push(cur);
    }
    out
}

/// Compare the engine's boundary on the grid (`gain`: Whittaker gains energy, per cell) with
/// eq. 13.
pub(super) fn compare_threshold(
    setup: &Setup,
    ax: &Axis,
    ay: &Axis,
    axes: SeedAxes,
    gain: &[bool],
) -> Comparison {
    let (alpha_axis, gamma_axis) = if axes.alpha_is_x { (ax, ay) } else { (ay, ax) };
    let (f, e) = setup.template.coefficients();
    let (na, ng) = (alpha_axis.count(), gamma_axis.count());
    let ny = ay.count();
    let gained = |ia: u64, ig: u64| {
        let (ix, iy) = if axes.alpha_is_x { (ia, ig) } else { (ig, ia) };
        gain[(ix * ny + iy) as usize]
    };
    let step = if ng > 1 {
        (gamma_axis.stop() - gamma_axis.start()) / (ng - 1) as f64
    } else {
        f64::INFINITY
    };
    let (g0, g1) = (gamma_axis.start(), gamma_axis.stop());
    let mut engine = [Vec::new(), Vec::new()];
    let mut worst = [0.0f64; 2];
    let mut compared = [0u64; 2];
    let mut disagree = 0u64;
    for ia in 0..na {
        let alpha_deg = alpha_axis.value(ia);
        let t = whittaker_sphere_thresholds(alpha_deg.to_radians(), e, f);
        let cells: Vec<u64> = (0..ng).filter(|&ig| gained(ia, ig)).collect();
        // Outermost transitions: the midpoints between the first/last gaining cell and its
        // outer neighbour (none when the region reaches the edge of the grid).
        let lower = cells
            .first()
            .filter(|&&i| i > 0)
            .map(|&i| 0.5 * (gamma_axis.value(i - 1) + gamma_axis.value(i)));
        let upper = cells
            .last()
            .filter(|&&i| i + 1 < ng)
            .map(|&i| 0.5 * (gamma_axis.value(i) + gamma_axis.value(i + 1)));
        for (b, (found, exact)) in [(lower, t.lower), (upper, t.upper)].into_iter().enumerate() {
            engine[b].push((alpha_deg, found.unwrap_or(f64::NAN)));
            let inside = exact.filter(|&g| g > g0 + step && g < g1 - step);
            match (found, inside) {
                (Some(x), Some(y)) => {
                    worst[b] = worst[b].max((x - y).abs());
                    compared[b] += 1;
                }
                (None, Some(_)) => disagree += 1,
                (Some(x), None) if x > g0 + step && x < g1 - step => disagree += 1,
                _ => {}
            }
        }
    }
    // A finer analytic curve for drawing.
    let fine = 600u64.max(na);
    let curve = |b: usize| {
        runs((0..=fine).map(|i| {
            let a = alpha_axis.start()
                + (alpha_axis.stop() - alpha_axis.start()) * i as f64 / fine as f64;
            let t = whittaker_sphere_thresholds(a.to_radians(), e, f);
            let g = if b == 0 { t.lower } else { t.upper };
            (a, g.filter(|&g| g >= g0 && g <= g1).unwrap_or(f64::NAN))
        }))
    };
    let no_slip: Vec<(f64, f64)> = (0..=fine)
        .map(|i| {
            let a = alpha_axis.start()
                + (alpha_axis.stop() - alpha_axis.start()) * i as f64 / fine as f64;
            (a, -a.to_radians().sin())
        })
        .filter(|&(_, g)| g >= g0 && g <= g1)
        .collect();
    let seed_coefficients = f == 0.4 && e == 0.7;
    let printed = if seed_coefficients && alpha_axis.start() <= 30.0 && alpha_axis.stop() >= 30.0 {
        [0.20, -0.20]
            .into_iter()
            .filter(|&g| g >= g0 && g <= g1)
            .map(|g| (30.0, g))
            .collect()
    } else {
        Vec::new()
    };
    let mut report = if ng < 2 {
        "whittaker energy-gain boundary vs paper A eq. 13: not compared (the γ axis has a single value, no grid step)\n".to_string()
    } else {
        format!(
        "whittaker energy-gain boundary vs paper A eq. 13 (γ grid step {step:.6}): \
         max |engine − eq. 13| = {:.6} on the upper branch γ*₊ ({} α columns), {:.6} on the lower branch γ*₋ ({} α columns); \
         {disagree} columns where only one of them has a boundary inside the grid; \
         within half a grid step: {}\n",
        worst[1],
        compared[1],
        worst[0],
        compared[0],
        if worst[0] <= 0.5 * step * (1.0 + 1e-9) && worst[1] <= 0.5 * step * (1.0 + 1e-9) && disagree == 0 {
            "yes"
        } else {
            "NO"
        },
    )
    };
    let at30 = whittaker_sphere_thresholds(30f64.to_radians(), e, f);
    if seed_coefficients {
        report.push_str(&format!(
            "at α = 30°: eq. 13 gives γ*₊ = {:.6}, γ*₋ = {:.6}; paper A prints ±0.20 (eqs. 14–15)\n",
            at30.upper.unwrap_or(f64::NAN),
            at30.lower.unwrap_or(f64::NAN)
        ));
    }
    Comparison {
        report,
        engine: [
            runs(engine[0].iter().copied()),
            runs(engine[1].iter().copied()),
        ],
        analytic: [curve(0), curve(1)],
        no_slip,
        printed,
        alpha_is_x: axes.alpha_is_x,
    }
}
