//! Colours: one per law, categorical palettes for the sign and sequence maps, and colour
//! maps for scalar heatmaps (viridis; a blue–white–red diverging map centred on zero).

use impax::LawId;
use plotters::style::RGBColor;

/// A fixed colour per law (the same in every picture).
pub fn law(law: LawId) -> RGBColor {
    match law {
        LawId::Whittaker => RGBColor(214, 39, 40),
        LawId::TwoPhase => RGBColor(255, 127, 14),
        LawId::Smith => RGBColor(148, 103, 189),
        LawId::SmithCentre => RGBColor(227, 119, 194),
        LawId::Brach => RGBColor(140, 86, 75),
        LawId::Newton => RGBColor(31, 119, 180),
        LawId::Poisson => RGBColor(23, 190, 207),
        LawId::Energetic => RGBColor(44, 160, 44),
        LawId::Lcp => RGBColor(127, 127, 127),
        LawId::Sequential => RGBColor(188, 189, 34),
        LawId::Lzb => RGBColor(0, 0, 0),
    }
}

/// Linear interpolation between colour stops `(t, r, g, b)`, `t` ascending in `[0, 1]`.
fn ramp(stops: &[(f64, u8, u8, u8)], t: f64) -> RGBColor {
    let t = if t.is_nan() { 0.0 } else { t.clamp(0.0, 1.0) };
    for w in stops.windows(2) {
        let (a, b) = (w[0], w[1]);
        if t <= b.0 {
            let u = if b.0 > a.0 {
                (t - a.0) / (b.0 - a.0)
            } else {
                0.0
            };
            let mix = |x: u8, y: u8| (x as f64 + (y as f64 - x as f64) * u).round() as u8;
            return RGBColor(mix(a.1, b.1), mix(a.2, b.2), mix(a.3, b.3));
        }
    }
    let l = stops[stops.len() - 1];
    RGBColor(l.1, l.2, l.3)
}

/// Viridis (sampled at nine stops), `t ∈ [0, 1]`.
pub fn viridis(t: f64) -> RGBColor {
    ramp(
        &[
            (0.0, 68, 1, 84),
            (0.125, 71, 44, 122),
            (0.25, 59, 81, 139),
            (0.375, 44, 113, 142),
            (0.5, 33, 144, 141),
            (0.625, 39, 173, 129),
            (0.75, 92, 200, 99),
            (0.875, 170, 220, 50),
            (1.0, 253, 231, 37),
        ],
        t,
    )
}

/// Blue–white–red (ColorBrewer RdBu, reversed), `t ∈ [0, 1]`, white at ½.
pub fn diverging(t: f64) -> RGBColor {
    ramp(
        &[
            (0.0, 5, 48, 97),
            (0.15, 33, 102, 172),
            (0.3, 103, 169, 207),
            (0.42, 209, 229, 240),
            (0.5, 247, 247, 247),
            (0.58, 253, 219, 199),
            (0.7, 239, 138, 98),
            (0.85, 178, 24, 43),
            (1.0, 103, 0, 31),
        ],
        t,
    )
}

/// Colour of cells without a value (breakdown or invalid point) in scalar maps.
pub const NO_VALUE: RGBColor = RGBColor(200, 200, 200);
