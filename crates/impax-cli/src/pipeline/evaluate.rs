//! One chunk of a sweep: points → contact problems → every law through the batch API.

use crate::pipeline::space::Setup;
use impax::analysis::{for_each_brief, resolve_problems, ImpactSummary, Tally};
use impax::planar::bodies::BodyImpact;
use impax::planar::ContactProblem;
use impax::LawId;
use std::cell::RefCell;
use std::ops::Range;

/// The most laws a sweep has (every law once: those of [`LawId::ALL`] and `sequential`).
pub const MAX_LAWS: usize = LawId::ALL.len() + 1;

/// The first invalid point of a chunk: its index and why.
#[derive(Debug, Clone)]
pub struct Invalid {
    pub index: u64,
    pub reason: String,
}

/// What a chunk reports beside its own output.
#[derive(Debug, Clone, Default)]
pub struct ChunkNotes {
    /// Number of invalid points.
    pub invalid: u64,
    /// The first one.
    pub first_invalid: Option<Invalid>,
}

/// What a visitor sees of a valid point.
#[derive(Debug, Clone, Copy)]
pub struct PointView<'a> {
    /// The energy scale `T0` of the point.
    pub t0: f64,
    /// The impact (kept only when asked for: body outputs, `smith-centre`).
    pub impact: Option<&'a BodyImpact>,
}

/// Evaluate the points of `range` and call `visit(index, values, point, summaries)` for each
/// in order; `summaries[k]` is law `k` of `setup.laws` ([`ImpactSummary::INVALID`] for every
/// law when the point is invalid, and then `point` is `None`). `keep_impacts` keeps each
/// point's [`BodyImpact`] for the visitor (always kept when `smith-centre` is swept).
pub fn chunk(
    setup: &Setup,
    range: Range<u64>,
    keep_impacts: bool,
    mut visit: impl FnMut(u64, &[f64], Option<PointView<'_>>, &[ImpactSummary]),
) -> ChunkNotes {
    SCRATCH.with(|cell| {
        let mut scratch = cell.borrow_mut();
        let notes = fill(&mut scratch, setup, range.clone(), keep_impacts, true);
        resolve_all(&mut scratch, &setup.laws);
        scratch.visit(setup, range, &mut visit);
        notes
    })
}

/// Evaluate the points of `range` and tally each law (in the order of `setup.laws`):
/// the reduced output of a sweep, straight from the batch records.
pub fn tally(setup: &Setup, range: Range<u64>) -> (Vec<Tally>, ChunkNotes) {
    SCRATCH.with(|cell| {
        let mut scratch = cell.borrow_mut();
        let keep = setup.laws.iter().any(|l| l.needs_body());
        let notes = fill(&mut scratch, setup, range, keep, false);
        let (problems, t0s, impacts) = (&scratch.problems, &scratch.t0s, &scratch.impacts);
        let tallies = setup
            .laws
            .iter()
            .map(|&law| {
                let mut t = Tally::new();
                if law.needs_body() {
                    for ((imp, p), &t0) in impacts.iter().zip(problems).zip(t0s) {
                        t.add_resolution(&imp.resolve(law, p).map(|b| b.outcome), t0);
                    }
                } else {
                    // The batch, reduced on the fly: no record per impact, and only the
                    // brief of each outcome (verdict, phases, ΔT) is computed.
                    for_each_brief(law, problems, |j, r| t.add_brief(r, t0s[j]));
                }
                for _ in 0..notes.invalid {
                    t.add(&ImpactSummary::INVALID, 1.0);
                }
                t
            })
            .collect();
        (tallies, notes)
    })
}

/// Buffers reused from chunk to chunk on each thread: a fresh megabyte per chunk would cost
/// a page fault per 4 KiB (as much time as the impacts themselves).
#[derive(Default)]
struct Scratch {
    values: Vec<f64>,
    valid: Vec<bool>,
    problems: Vec<ContactProblem>,
    t0s: Vec<f64>,
    impacts: Vec<BodyImpact>,
    summaries: Vec<ImpactSummary>,
}

thread_local! {
    static SCRATCH: RefCell<Scratch> = RefCell::new(Scratch::default());
}

/// Build the chunk's problems (and, if asked, the impacts, values and validity).
/// `visits`: keep each point's values and validity for [`Scratch::visit`] (a tally needs
/// neither).
fn fill(
    scratch: &mut Scratch,
    setup: &Setup,
    range: Range<u64>,
    keep_impacts: bool,
    visits: bool,
) -> ChunkNotes {
    let laws = &setup.laws;
    let keep = keep_impacts || laws.iter().any(|l| l.needs_body());
    let mut notes = ChunkNotes::default();
    let mut template = setup.template.clone();
    let Scratch {
        values,
        valid,
        problems,
        t0s,
        impacts,
        summaries,
    } = scratch;
    values.clear();
    valid.clear();
    problems.clear();
    t0s.clear();
    impacts.clear();
    summaries.clear();
    // Only the fields whose values changed are set again (on a grid, the fast axis).
    setup
        .space
        .for_each_changed_in(range.clone(), |i, vals, changed| {
            if visits {
                values.extend_from_slice(vals);
            }
            for (f, &x) in setup.fields[changed..].iter().zip(&vals[changed..]) {
                template.set(*f, x);
            }
            let kept = if keep { Some(&mut *impacts) } else { None };
            match template.point_into(problems, t0s, kept) {
                Ok(()) => {
                    if visits {
                        valid.push(true)
                    }
                }
                Err(e) => {
                    if visits {
                        valid.push(false);
                    }
                    notes.invalid += 1;
                    if notes.first_invalid.is_none() {
                        notes.first_invalid = Some(Invalid {
                            index: i,
                            reason: e.to_string(),
                        });
                    }
                }
            }
        });
    notes
}

/// Resolve every law on the built problems through the batch API (law-major records:
/// `summaries[k * nv + j]` is law `k` on valid point `j`).
fn resolve_all(scratch: &mut Scratch, laws: &[LawId]) {
    let Scratch {
        problems,
        impacts,
        summaries,
        ..
    } = scratch;
    let nv = problems.len();
    summaries.clear();
    summaries.resize(laws.len() * nv, ImpactSummary::INVALID);
    for (k, &law) in laws.iter().enumerate() {
        let out = &mut summaries[k * nv..(k + 1) * nv];
        if law.needs_body() {
            for ((o, imp), p) in out.iter_mut().zip(impacts.iter()).zip(problems.iter()) {
                *o = match imp.resolve(law, p) {
                    Ok(b) => ImpactSummary::of(&b.outcome),
                    Err(_) => ImpactSummary::BREAKDOWN,
                };
            }
        } else {
            resolve_problems(law, problems, out).expect("one record per problem");
        }
    }
}

impl Scratch {
    /// Call the visitor for each point of the filled chunk, in order.
    fn visit(
        &self,
        setup: &Setup,
        range: Range<u64>,
        visit: &mut impl FnMut(u64, &[f64], Option<PointView<'_>>, &[ImpactSummary]),
    ) {
        let d = setup.fields.len();
        let laws = &setup.laws;
        let nv = self.problems.len();
        let (values, valid, t0s, impacts, summaries) = (
            &self.values,
            &self.valid,
            &self.t0s,
            &self.impacts,
            &self.summaries,
        );
        let mut row = [ImpactSummary::INVALID; MAX_LAWS];
        let invalid_row = [ImpactSummary::INVALID; MAX_LAWS];
        let mut j = 0;
        for (p, ok) in valid.iter().enumerate() {
            let vals = &values[p * d..(p + 1) * d];
            let index = range.start + p as u64;
            if *ok {
                for k in 0..laws.len() {
                    row[k] = summaries[k * nv + j];
                }
                let view = PointView {
                    t0: t0s[j],
                    impact: impacts.get(j),
                };
                visit(index, vals, Some(view), &row[..laws.len()]);
                j += 1;
            } else {
                visit(index, vals, None, &invalid_row[..laws.len()]);
            }
        }
    }
}
