//! The sweep of a map, in parallel: one value per cell and law (a class or a number), and
//! whether Whittaker's rule gains energy at each cell (for the comparison with eq. 13).

use super::cells::{sign_class, GAINED};
use super::What;
use crate::cli::MapArgs;
use crate::commands::sweep::CHUNK_POINTS;
use crate::input::{CliError, CliResult};
use crate::pipeline::columns::body_after;
use crate::pipeline::evaluate;
use crate::pipeline::progress::Progress;
use crate::pipeline::space::{self, Setup};
use impax::analysis::run_ordered;

/// What the sweep gives, per law (in the order of the setup's laws) and cell (in the grid's
/// order).
pub(super) struct Swept {
    /// The classes (sign or sequence maps).
    pub(super) cat: Vec<Vec<u8>>,
    /// The numbers (maps of a numeric column).
    pub(super) scal: Vec<Vec<f32>>,
    /// Whether `whittaker` gains energy, per cell (empty without `whittaker`).
    pub(super) gain: Vec<bool>,
}

/// Sweep the grid of `setup` for `what`; `whittaker` is the index of `whittaker` among the
/// laws, if it is one.
pub(super) fn sweep(
    args: &MapArgs,
    setup: &Setup,
    what: What,
    whittaker: Option<usize>,
) -> CliResult<Swept> {
    let nl = setup.laws.len();
    let total = setup.space.len();
    // Sweep: one value per cell and law, plus Whittaker's gain flags for the comparison.
    let mut cat: Vec<Vec<u8>> = vec![Vec::new(); nl];
    let mut scal: Vec<Vec<f32>> = vec![Vec::new(); nl];
    let mut gain: Vec<bool> = Vec::new();
    let progress = Progress::new(total, args.space.quiet);
    let quantity = what;
    let keep = matches!(what, What::Scalar(c) if c.needs_body());
    space::with_threads(args.space.threads, || {
        let r = run_ordered(
            total,
            CHUNK_POINTS,
            |range| {
                let n = (range.end - range.start) as usize;
                let mut c = vec![Vec::with_capacity(n); nl];
                let mut s = vec![Vec::with_capacity(n); nl];
                let mut g = Vec::with_capacity(n);
                evaluate::chunk(setup, range, keep, |_, _, point, sums| {
                    for (k, x) in sums.iter().enumerate() {
                        match quantity {
                            What::Sign => c[k].push(sign_class(x.status)),
                            What::Sequence => c[k].push(x.sequence as u8),
                            What::Scalar(col) => {
                                let body = if col.needs_body() {
                                    body_after(x, point)
                                } else {
                                    [f64::NAN; 3]
                                };
                                s[k].push(col.value(x, point, body) as f32)
                            }
                        }
                    }
                    if let Some(w) = whittaker {
                        g.push(sign_class(sums[w].status) == GAINED);
                    }
                });
                (n as u64, c, s, g)
            },
            |(n, c, s, g)| {
                for (dst, src) in cat.iter_mut().zip(c) {
                    dst.extend(src);
                }
                for (dst, src) in scal.iter_mut().zip(s) {
                    dst.extend(src);
                }
                gain.extend(g);
                progress.advance(n);
                Ok::<(), CliError>(())
            },
        );
        progress.finish("map", total, nl);
        r
    })??;
    Ok(Swept { cat, scal, gain })
}
