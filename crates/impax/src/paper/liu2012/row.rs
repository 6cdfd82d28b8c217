//! The rows of the report: how a printed number, formula or statement is set beside the
//! engine's value, and how numbers are shown.

use super::{Agreement, Row};

/// Relative tolerance for "the printed formula equals the engine".
pub(super) const FORMULA_TOL: f64 = 1e-9;

/// `(value, decimals)` of a printed decimal number.
pub(super) fn parse_printed(printed: &str) -> Option<(f64, usize)> {
    let s = printed.trim().replace('−', "-");
    let value: f64 = s.parse().ok()?;
    let decimals = s.split_once('.').map_or(0, |(_, frac)| frac.len());
    Some((value, decimals))
}

/// `x` with `d` decimals, without a sign on zero.
pub(super) fn fmt(x: f64, d: usize) -> String {
    let s = format!("{x:.d$}");
    if s.chars().all(|c| matches!(c, '-' | '0' | '.')) {
        s.trim_start_matches('-').to_string()
    } else {
        s
    }
}

/// Six decimals (formula rows and notes).
pub(super) fn f6(x: f64) -> String {
    fmt(x, 6)
}

/// Signed, six decimals (`+0.177779`).
pub(super) fn s6(x: f64) -> String {
    if x > 0.0 {
        format!("+{}", f6(x))
    } else {
        f6(x)
    }
}

/// A row comparing a number with a printed number. `printed_number` is the number as
/// printed; `printed` the fuller text shown (often the same).
pub(super) fn number(
    id: &'static str,
    quantity: String,
    printed: &str,
    printed_number: &str,
    value: f64,
    why: impl FnOnce() -> String,
) -> Row {
    let decimals = parse_printed(printed_number).map_or(3, |(_, d)| d);
    let agreement = Agreement::of(printed_number, value);
    Row {
        id,
        quantity,
        printed: printed.to_string(),
        computed: fmt(value, (decimals + 3).min(6)),
        computed_value: Some(value),
        agreement,
        note: if agreement == Agreement::Agrees {
            String::new()
        } else {
            why()
        },
    }
}

/// A row comparing a printed formula, evaluated at the seed, with the engine.
pub(super) fn formula(
    id: &'static str,
    quantity: String,
    printed: &str,
    from_formula: f64,
    engine: f64,
) -> Row {
    let agrees = (from_formula - engine).abs() <= FORMULA_TOL * engine.abs().max(1.0);
    Row {
        id,
        quantity,
        printed: printed.to_string(),
        computed: f6(engine),
        computed_value: Some(engine),
        agreement: if agrees {
            Agreement::Agrees
        } else {
            Agreement::Differs
        },
        note: if agrees {
            String::new()
        } else {
            format!(
                "the printed formula gives {}, the engine {}",
                f6(from_formula),
                f6(engine)
            )
        },
    }
}

/// A row checking a printed statement (inequality, condition, conclusion).
pub(super) fn statement(
    id: &'static str,
    quantity: String,
    printed: &str,
    computed: String,
    value: Option<f64>,
    holds: bool,
    why: impl FnOnce() -> String,
) -> Row {
    Row {
        id,
        quantity,
        printed: printed.to_string(),
        computed,
        computed_value: value,
        agreement: if holds {
            Agreement::Agrees
        } else {
            Agreement::Differs
        },
        note: if holds { String::new() } else { why() },
    }
}

/// A row with impax's own result, not printed in the paper.
pub(super) fn reference(
    quantity: String,
    computed: String,
    value: Option<f64>,
    note: String,
) -> Row {
    Row {
        id: "exact",
        quantity,
        printed: "—".to_string(),
        computed,
        computed_value: value,
        agreement: Agreement::NotPrinted,
        note,
    }
}
