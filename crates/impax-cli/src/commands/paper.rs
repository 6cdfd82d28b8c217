//! `impax paper`: reproduction reports of the source papers.

use crate::cli::PaperArgs;
use crate::input::{CliError, CliResult};
use crate::output::fmt::Table;
use impax::paper::liu2012::{self, Agreement};
use serde_json::json;

const TITLE: &str =
    "Liu Yanzhu, On Kane's paradox of frictional impact, Mechanics in Engineering 2012(1): 91–94";

pub fn run(args: &PaperArgs, out: &mut Vec<u8>) -> CliResult<()> {
    if args.paper != "liu2012" {
        return Err(CliError::input(format!(
            "paper: unknown paper `{}` (known: liu2012)",
            args.paper
        )));
    }
    let rows = liu2012::report();
    let count = |a: Agreement| rows.iter().filter(|r| r.agreement == a).count();
    let text = if args.json {
        let doc = json!({
            "paper": "liu2012",
            "title": TITLE,
            "case": "sphere m = r = v0 = 1, α = 30°, e = 0.7, f = 0.4",
            "summary": {
                "agrees": count(Agreement::Agrees),
                "rounding": count(Agreement::Rounding),
                "differs": count(Agreement::Differs),
                "not_printed": count(Agreement::NotPrinted),
            },
            "rows": rows,
        });
        serde_json::to_string_pretty(&doc).map_err(CliError::failure)? + "\n"
    } else {
        let mut t = Table::new(&[
            ("#", true),
            ("id", false),
            ("quantity", false),
            ("printed", false),
            ("computed", false),
            ("verdict", false),
        ]);
        let mut notes = String::new();
        for (i, r) in rows.iter().enumerate() {
            let n = i + 1;
            t.row(vec![
                n.to_string(),
                r.id.to_string(),
                r.quantity.clone(),
                r.printed.clone(),
                r.computed.clone(),
                r.agreement.id().to_string(),
            ]);
            if !r.note.is_empty() {
                notes.push_str(&format!("[{n}] {}: {}\n", r.id, r.note));
            }
        }
        format!(
            "impax paper liu2012 — {TITLE}\ncase: sphere m = r = v0 = 1, α = 30°, e = 0.7, f = 0.4 (γ as stated); printed values beside impax's\n\n{}\nsummary: {} agree, {} rounding, {} differ, {} not printed (impax's exact result)\n\nnotes:\n{notes}",
            t.render(),
            count(Agreement::Agrees),
            count(Agreement::Rounding),
            count(Agreement::Differs),
            count(Agreement::NotPrinted),
        )
    };
    out.extend_from_slice(text.as_bytes());
    Ok(())
}
