//! What a cell shows: the classes of the sign of ΔT and of the phase sequence with their
//! colours, or a number on a colour scale.

use super::What;
use crate::output::plot::map::Cells;
use impax::analysis::{Sequence, Status};
use impax::planar::Verdict;
use plotters::style::RGBColor;

/// Sign classes.
pub(super) const GAINED: u8 = 0;
pub(super) const LOST: u8 = 1;
pub(super) const BREAKDOWN: u8 = 2;
pub(super) const INVALID: u8 = 3;

/// The sign classes: label and colour.
fn sign_classes() -> Vec<(String, RGBColor)> {
    vec![
        (
            "ΔT > 0: energy gained (Kane's paradox)".into(),
            RGBColor(215, 48, 39),
        ),
        ("ΔT ≤ 0: energy lost".into(), RGBColor(171, 210, 230)),
        ("breakdown of the law".into(), RGBColor(80, 80, 80)),
        ("invalid point".into(), RGBColor(245, 245, 245)),
    ]
}

/// The phase-sequence classes, in the order of [`Sequence::ALL`]: label and colour.
fn sequence_classes() -> Vec<(String, RGBColor)> {
    Sequence::ALL
        .iter()
        .map(|s| {
            let (label, c) = match s {
                Sequence::Slip => ("slip throughout", RGBColor(253, 174, 97)),
                Sequence::SlipStick => ("slip → stick", RGBColor(102, 189, 99)),
                Sequence::SlipReverse => ("slip → reversed slip", RGBColor(152, 78, 163)),
                Sequence::Stick => ("stick throughout", RGBColor(55, 126, 184)),
                Sequence::NoSlip => ("no slip, no friction", RGBColor(255, 255, 153)),
                Sequence::None => ("none (breakdown or invalid)", RGBColor(150, 150, 150)),
            };
            (label.to_string(), c)
        })
        .collect()
}

/// The sign class of a point's status.
pub(super) fn sign_class(status: Status) -> u8 {
    match status {
        Status::Resolved(Verdict::EnergyGained) => GAINED,
        Status::Resolved(_) => LOST,
        Status::Breakdown => BREAKDOWN,
        Status::Invalid => INVALID,
    }
}

/// The cells of the map: the classes (`cat`, per law and point) or the numbers (`scal`) of
/// the sweep, as `what` asks.
pub(super) fn cells(what: What, cat: Vec<Vec<u8>>, scal: Vec<Vec<f32>>) -> Cells {
    match what {
        What::Sign => Cells::Categories {
            data: cat,
            classes: sign_classes(),
        },
        What::Sequence => Cells::Categories {
            data: cat,
            classes: sequence_classes(),
        },
        What::Scalar(col) => {
            let (mut lo, mut hi) = (f64::INFINITY, f64::NEG_INFINITY);
            for v in scal
                .iter()
                .flatten()
                .map(|&v| v as f64)
                .filter(|v| v.is_finite())
            {
                lo = lo.min(v);
                hi = hi.max(v);
            }
            if !lo.is_finite() {
                (lo, hi) = (0.0, 1.0);
            }
            Cells::Scalar {
                data: scal,
                label: col.label().to_string(),
                lo,
                hi,
                diverging: lo < 0.0 && hi > 0.0,
            }
        }
    }
}
