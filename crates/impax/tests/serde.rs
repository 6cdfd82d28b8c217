//! The feature `serde`: every serialized type reads back equal to what was written, bit for
//! bit, through JSON text and through `serde_json::Value`, on the real results of every law —
//! planar, spatial, with several contacts, and on bodies — and on every breakdown; ids are
//! written as the ids the command line prints; a problem read back is validated as a built
//! one; the JSON the book shows (`docs/src/library.md`) is the library's.
//!
//! `cargo test -p impax --features serde --test serde`

use impax::law::{Breakdown, BreakdownReason, Inconsistency, Verdict, WorkSplit};
use impax::math::{Mat2, Vec2, Vec3};
use impax::multi::{MultiDetail, MultiProblem};
use impax::planar::bodies::{sphere, spin_state, BodyImpact, Side};
use impax::planar::{ContactProblem, LawDetail, Phases};
use impax::scenario::{PlanarScenario, SEED_TOML};
use impax::spatial;
use impax::spatial::bodies::BodyState;
use impax::LawId;
use serde::de::DeserializeOwned;
use serde::Serialize;
use serde_json::{json, Value};
use std::collections::BTreeSet;
use std::fmt::Debug;

/// Write `x` as JSON text and as a `Value`, read both back, and check that each equals `x`
/// bit for bit (the `Debug` form shows every `f64` to its last bit, and the sign of zero).
/// Returns the written `Value`.
fn round_trip<T: Serialize + DeserializeOwned + PartialEq + Debug>(x: &T) -> Value {
    let text = serde_json::to_string(x).expect("serializes");
    let back: T = serde_json::from_str(&text).unwrap_or_else(|e| panic!("{e}: {text}"));
    assert_eq!(&back, x, "{text}");
    assert_eq!(format!("{back:?}"), format!("{x:?}"), "{text}");
    let value = serde_json::to_value(x).expect("serializes");
    let back: T = serde_json::from_value(value.clone()).unwrap_or_else(|e| panic!("{e}: {text}"));
    assert_eq!(format!("{back:?}"), format!("{x:?}"), "{text}");
    value
}

/// The `"id"` of a tagged value (empty without one).
fn id_of(v: &Value) -> String {
    v["id"].as_str().unwrap_or_default().to_string()
}

/// What the tests met, to check that they covered every variant.
#[derive(Default)]
struct Seen {
    details: BTreeSet<String>,
    inconsistencies: BTreeSet<String>,
    breakdowns: BTreeSet<String>,
    verdicts: BTreeSet<String>,
}

impl Seen {
    fn record(&mut self, v: &Value) {
        if let Some(id) = v["detail"]["id"].as_str() {
            self.details.insert(id.to_string());
        }
        if let Some(id) = v["inconsistency"]["id"].as_str() {
            self.inconsistencies.insert(id.to_string());
        }
        if let Some(id) = v["verdict"].as_str() {
            self.verdicts.insert(id.to_string());
        }
    }

    fn breakdown(&mut self, b: &Breakdown) {
        let v = round_trip(b);
        assert_eq!(v["law"], b.law.as_str());
        assert_eq!(v["reason"]["id"], b.reason.id());
        self.breakdowns.insert(b.reason.id().to_string());
    }
}

/// Planar problems over couplings, angles of approach, friction and restitution: slip, stick,
/// reversal, a two-phase switch, Brach's cap, `lcp`'s candidates, breakdowns.
fn planar_problems() -> Vec<ContactProblem> {
    let mut out = Vec::new();
    for (a, b, c) in [
        (3.5, 0.0, 1.0),
        (2.0, 1.2, 1.0),
        (1.0, -0.9, 1.0),
        (4.0, 2.5, 2.0),
    ] {
        for deg in [0.0f64, 20.0, 45.0, 70.0, 85.0, -30.0] {
            for mu in [0.0, 0.2, 0.6, 2.0] {
                for e in [0.0, 0.5, 1.0] {
                    let r = deg.to_radians();
                    let w = Mat2::new(a, b, b, c);
                    let v = Vec2::new(r.sin(), -r.cos());
                    out.push(ContactProblem::new(w, v, mu, e).expect("valid"));
                }
            }
        }
    }
    out
}

#[test]
fn law_ids_are_written_as_their_ids() {
    for law in LawId::ALL.into_iter().chain(LawId::MULTI_CONTACT) {
        let v = round_trip(&law);
        assert_eq!(v, json!(law.as_str()));
    }
    let e = serde_json::from_str::<LawId>("\"kane\"").unwrap_err();
    assert!(e.to_string().contains("unknown impact law `kane`"), "{e}");
    for verdict in [
        Verdict::Consistent,
        Verdict::EnergyGained,
        Verdict::InconsistentAssumption,
    ] {
        assert_eq!(round_trip(&verdict), json!(verdict.id()));
    }
}

#[test]
fn every_inconsistency_and_breakdown_reason_is_tagged_by_its_id() {
    for i in [
        Inconsistency::SlipReversed { slip_after: -0.25 },
        Inconsistency::ReversalDidNotHappen { slip_after: 0.125 },
        Inconsistency::MultipleSolutions { count: 3 },
        Inconsistency::StillApproaching {
            normal_velocity: -1e-3,
        },
    ] {
        assert_eq!(round_trip(&i)["id"], i.id());
    }
    for reason in [
        BreakdownReason::NegativeNormalImpulse { denominator: -0.5 },
        BreakdownReason::NoConsistentSplit {
            switch_impulse: 0.3,
            total_impulse: 0.2,
        },
        BreakdownReason::NoEtaRoot,
        BreakdownReason::NoSeparation,
        BreakdownReason::PlanarOnly,
        BreakdownReason::NeedsBody,
        BreakdownReason::NoSolution,
        BreakdownReason::Overflow,
        BreakdownReason::TooManyImpacts { limit: 10 },
        BreakdownReason::TooManyContacts {
            contacts: 5,
            limit: 4,
        },
        BreakdownReason::TooManySteps { limit: 100 },
        BreakdownReason::Jammed { stored: 0.5 },
    ] {
        assert_eq!(round_trip(&reason)["id"], reason.id());
        round_trip(&Breakdown {
            law: LawId::Lzb,
            reason,
        });
    }
    let w = WorkSplit {
        compression: -0.5,
        restitution: 0.25,
        friction: -0.125,
    };
    assert_eq!(
        round_trip(&w),
        json!({"compression": -0.5, "restitution": 0.25, "friction": -0.125})
    );
}

#[test]
fn planar_outcomes_of_every_law_round_trip() {
    let mut seen = Seen::default();
    let laws: Vec<LawId> = LawId::ALL
        .into_iter()
        .chain([LawId::Sequential, LawId::Lzb])
        .collect();
    for p in planar_problems() {
        round_trip(&p);
        for &law in &laws {
            let r = law.resolve(&p);
            round_trip(&r);
            match r {
                Ok(o) => {
                    let v = round_trip(&o);
                    seen.record(&v);
                    assert_eq!(v["law"], law.as_str());
                    assert_eq!(v["verdict"], o.verdict.id());
                    assert_eq!(
                        v["phases"].as_array().expect("a list").len(),
                        o.phases.len()
                    );
                    round_trip(&o.phases);
                    round_trip(&o.detail);
                    round_trip(&impax::planar::OutcomeBrief::of(&o));
                    for phase in o.phases.as_slice() {
                        round_trip(phase);
                        round_trip(&phase.kind);
                    }
                }
                Err(b) => seen.breakdown(&b),
            }
        }
    }
    // smith-centre on bodies, and every law's body outcome (one body, two bodies).
    let seed = PlanarScenario::from_toml(SEED_TOML)
        .unwrap()
        .build()
        .unwrap();
    let two = PlanarScenario::from_toml(
        "friction = 0.5\nrestitution = 0.6\n[body]\nshape = \"rod\"\nmass = 1.0\nlength = 2.0\n\
         angle_deg = 40.0\nvelocity = [0.8, -1.0]\nomega = 0.5\n[other]\nshape = \"disc\"\n\
         mass = 2.0\nradius = 1.0\nvelocity = [0.0, 0.0]\nomega = 0.0\n",
    )
    .unwrap()
    .build()
    .unwrap();
    for (impact, mu, e) in [(seed.impact, 0.4, 0.7), (two.impact, 0.5, 0.6)] {
        let p = impact.problem(mu, e).unwrap();
        for law in LawId::ALL {
            match impact.resolve(law, &p) {
                Ok(o) => seen.record(&round_trip(&o)["outcome"]),
                Err(b) => seen.breakdown(&b),
            }
        }
    }
    for gamma in [-3.0, -0.5, 0.0, 1.0] {
        let body = sphere(1.0, 1.0, Side::Below).unwrap();
        let impact = BodyImpact::on_fixed_surface(body, spin_state(1.0, 0.5, gamma, 1.0).unwrap());
        let p = impact.problem(0.4, 0.7).unwrap();
        let o = impact.resolve(LawId::SmithCentre, &p).unwrap();
        seen.record(&round_trip(&o)["outcome"]);
    }
    let details: Vec<&str> = seen.details.iter().map(String::as_str).collect();
    assert_eq!(
        details,
        [
            "brach",
            "darboux-keller",
            "lcp",
            "none",
            "smith",
            "two-phase"
        ]
    );
    assert!(seen.inconsistencies.contains("slip-reversed"));
    assert!(seen.inconsistencies.contains("reversal-did-not-happen"));
    assert!(seen.verdicts.contains("energy-gained"));
    assert!(
        seen.breakdowns.contains("needs-body"),
        "{:?}",
        seen.breakdowns
    );
    assert!(seen.breakdowns.len() >= 2, "{:?}", seen.breakdowns);
}

#[test]
fn spatial_outcomes_of_every_law_round_trip() {
    let mut seen = Seen::default();
    let laws: Vec<LawId> = LawId::SPATIAL
        .into_iter()
        .chain([LawId::Sequential, LawId::Lzb, LawId::TwoPhase])
        .collect();
    let mut kinds = BTreeSet::new();
    for w in [
        [3.5, 0.0, 0.0, 3.5, 0.0, 1.0],
        [2.0, 0.3, 0.8, 1.5, -0.4, 1.0],
        [1.2008, 0.7592, 0.4034, 1.4497, 0.2240, 1.1040],
    ] {
        for v in [
            [0.5, 0.0, -0.866],
            [0.3, -0.4, -1.0],
            [0.0, 0.0, -1.0],
            [-0.3176, -0.9221, -0.1423],
        ] {
            for (mu, e) in [(0.0, 0.5), (0.3, 0.7), (1.0, 1.0), (19.5, 1.0)] {
                let p = spatial::ContactProblem::from_upper(w, v, mu, e).unwrap();
                round_trip(&p);
                for &law in &laws {
                    let r = law.resolve(&p);
                    round_trip(&r);
                    match r {
                        Ok(o) => {
                            let v = round_trip(&o);
                            seen.record(&v);
                            round_trip(&o.phases);
                            for phase in o.phases.as_slice() {
                                kinds.insert(id_of(&round_trip(&phase.kind)));
                            }
                            if let spatial::LawDetail::DarbouxKeller { .. } = o.detail {
                                assert!(v["detail"]["steps"].is_u64());
                            }
                        }
                        Err(b) => seen.breakdown(&b),
                    }
                }
            }
        }
    }
    let details: Vec<&str> = seen.details.iter().map(String::as_str).collect();
    assert_eq!(details, ["brach", "darboux-keller", "lcp", "none"]);
    assert!(
        kinds.contains("slip") && kinds.contains("stick"),
        "{kinds:?}"
    );
    assert!(
        seen.breakdowns.contains("planar-only"),
        "{:?}",
        seen.breakdowns
    );
    // On bodies: a spinning sphere on a plane.
    let body = impax::spatial::bodies::sphere(1.0, 0.5, Side::Below).unwrap();
    let state = BodyState::new(Vec3::new(0.5, 0.2, -1.0), Vec3::new(1.0, -2.0, 0.3));
    let impact = impax::spatial::bodies::BodyImpact::on_fixed_surface(body, state);
    let p = impact.problem(0.3, 0.6).unwrap();
    for law in LawId::SPATIAL {
        round_trip(&impact.resolve(law, &p).unwrap());
    }
}

#[test]
fn outcomes_at_several_contacts_round_trip() {
    let mut seen = Seen::default();
    let mut details = BTreeSet::new();
    // Three balls in a row, the first moving (a cradle), and a rod landing on both ends.
    let cradle = MultiProblem::from_upper(
        2,
        &[2.0, 0.0, 1.4, 0.0, 2.0, 0.0, -1.0, 2.0, 0.0, 2.0],
        &[0.0, -1.0, 0.0, 0.0],
        &[0.0, 0.3],
        &[1.0, 0.5],
    )
    .unwrap();
    let rod = MultiProblem::from_upper(
        2,
        &[1.0, 0.0, 1.0, 0.0, 4.0, 0.0, -2.0, 1.0, 0.0, 4.0],
        &[0.3, -1.0, 0.3, -1.0],
        &[0.5],
        &[0.5],
    )
    .unwrap()
    .with_stiffness(&[1.0, 2.0])
    .unwrap()
    .with_exponent(1.0)
    .unwrap();
    for p in [cradle, rod] {
        let v = round_trip(&p);
        assert_eq!(v["w"].as_array().unwrap().len(), 4);
        for law in LawId::MULTI_CONTACT {
            match law.resolve(&p).unwrap() {
                Ok(o) => {
                    let v = round_trip(&o);
                    seen.record(&v);
                    details.insert(id_of(&v["detail"]));
                    if let MultiDetail::Lcp { solutions } = &o.detail {
                        round_trip(solutions);
                    }
                }
                Err(b) => seen.breakdown(&b),
            }
        }
    }
    // One contact: every contact-space law, its own detail carried over.
    for p in planar_problems().iter().step_by(7) {
        let multi = MultiProblem::from_contact(p).unwrap();
        round_trip(&multi);
        for law in LawId::CONTACT_SPACE {
            match law.resolve(&multi).unwrap() {
                Ok(o) => {
                    let v = round_trip(&o);
                    details.insert(id_of(&v["detail"]));
                }
                Err(b) => seen.breakdown(&b),
            }
        }
    }
    for id in ["lcp", "sequential", "lzb", "one-contact"] {
        assert!(details.contains(id), "{details:?}");
    }
}

#[test]
fn a_problem_read_back_is_validated() {
    let p = ContactProblem::from_entries(3.5, 0.0, 1.0, 0.5, -0.866, 0.4, 0.7).unwrap();
    assert_eq!(
        round_trip(&p),
        json!({"w": [[3.5, 0.0], [0.0, 1.0]], "v": [0.5, -0.866], "friction": 0.4, "restitution": 0.7})
    );
    let read = |text: &str| {
        serde_json::from_str::<ContactProblem>(text)
            .unwrap_err()
            .to_string()
    };
    let e = read(
        r#"{"w": [[3.5, 0.0], [0.0, 1.0]], "v": [0.5, 0.2], "friction": 0.4, "restitution": 0.7}"#,
    );
    assert!(e.starts_with("v: "), "{e}");
    let e = read(
        r#"{"w": [[1.0, 2.0], [2.0, 1.0]], "v": [0.5, -1.0], "friction": 0.4, "restitution": 0.7}"#,
    );
    assert!(e.starts_with("w: "), "{e}");
    let e = read(
        r#"{"w": [[1.0, 0.0], [0.0, 1.0]], "v": [0.5, -1.0], "friction": 0.4, "restitution": 1.5}"#,
    );
    assert!(e.starts_with("restitution: "), "{e}");
    let e = read(r#"{"w": [[1.0, 0.0], [0.0, 1.0]], "v": [0.5, -1.0], "friction": 0.4, "e": 0.5}"#);
    assert!(e.contains("unknown field `e`"), "{e}");
    let e = serde_json::from_str::<spatial::ContactProblem>(
        r#"{"w": [[1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]], "v": [0.5, 0.0, -1.0], "friction": -0.1, "restitution": 0.5}"#,
    )
    .unwrap_err()
    .to_string();
    assert!(e.starts_with("friction: "), "{e}");
    let e = serde_json::from_str::<MultiProblem>(
        r#"{"w": [[1.0, 0.0], [0.0]], "v": [0.0, -1.0], "friction": [0.1], "restitution": [0.5], "stiffness": [1.0], "exponent": 1.5}"#,
    )
    .unwrap_err()
    .to_string();
    assert!(e.starts_with("w: "), "{e}");
    let e = serde_json::from_str::<MultiProblem>(
        r#"{"w": [[1.0, 0.0], [0.0, 1.0]], "v": [0.0, -1.0], "friction": [0.1], "restitution": [0.5], "stiffness": [1.0], "exponent": 0.0}"#,
    )
    .unwrap_err()
    .to_string();
    assert!(e.starts_with("exponent: "), "{e}");
}

#[test]
fn phase_lists_are_read_within_their_capacity() {
    let slip = json!({"kind": {"slip": "positive"}, "ends_at": 0.25});
    let stick = json!({"kind": "stick", "ends_at": 0.5});
    let two: Phases = serde_json::from_value(json!([slip, stick])).unwrap();
    assert_eq!(two.summary(), "slip+ → stick");
    assert!(serde_json::from_value::<Phases>(json!([slip, stick, slip])).is_err());
    assert!(serde_json::from_value::<Phases>(json!([slip, slip])).is_err());
    let three = json!({"kind": {"id": "stick"}, "ends_at": 0.5});
    assert!(serde_json::from_value::<spatial::Phases>(json!([three, three, three])).is_err());
    let detail: LawDetail = serde_json::from_value(json!({"id": "none"})).unwrap();
    assert_eq!(detail, LawDetail::None);
}

#[test]
fn the_scenario_round_trips() {
    let s = PlanarScenario::from_toml(SEED_TOML).unwrap();
    round_trip(&s);
    let two = PlanarScenario::from_toml(
        "friction = 0.5\nrestitution = 0.6\nlaws = [\"whittaker\", \"lcp\"]\n[body]\n\
         shape = \"ellipse\"\nmass = 1.0\nsemi_axes = [2.0, 1.0]\nangle_deg = 20.0\n\
         velocity = [0.8, -1.0]\nomega = 0.5\n[other]\nshape = \"rigid\"\nmass = 2.0\n\
         inertia = 0.5\ncontact = [0.3, 1.0]\nvelocity = [0.0, 0.0]\nomega = 0.0\n",
    )
    .unwrap();
    let v = round_trip(&two);
    assert_eq!(v["other"]["shape"], "rigid");
    // What is written reads back through the same reader as the files, to the same build.
    let built = serde_json::from_value::<PlanarScenario>(v)
        .unwrap()
        .build()
        .unwrap();
    assert_eq!(built.impact, two.build().unwrap().impact);
    round_trip(&built.body.scale);
    round_trip(&built.body.state);
}

#[test]
fn the_book_shows_the_librarys_json() {
    let page = std::fs::read_to_string(concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/../../docs/src/library.md"
    ))
    .unwrap();
    let section = &page[page.find("## Serde").expect("the section")..];
    let start = section.find("```json\n").expect("a JSON block") + "```json\n".len();
    let shown: Value =
        serde_json::from_str(&section[start..][..section[start..].find("```").unwrap()])
            .expect("valid JSON");
    let a = 30f64.to_radians();
    let p = ContactProblem::from_entries(3.5, 0.0, 1.0, a.sin(), -a.cos(), 0.4, 0.7).unwrap();
    let o = LawId::TwoPhase.resolve(&p).unwrap();
    assert_eq!(serde_json::to_value(o).unwrap(), shown);
}

/// Spatial problems with several contacts and their outcomes: `box-flat` spinning and
/// sliding, under `lcp` and `sequential`.
#[test]
fn spatial_outcomes_at_several_contacts_round_trip() {
    use impax::multi::scenarios::BoxFlat;
    use impax::multi::spatial;
    let mut details = BTreeSet::new();
    for (spin, vx, mu, e) in [
        (2.0, 0.0, 0.3, 0.5),
        (6.0, 0.4, 0.1, 0.8),
        (0.0, 0.0, 0.0, 1.0),
    ] {
        let sc = BoxFlat {
            spin,
            velocity: [vx, 0.0, -1.0],
            ..BoxFlat::default()
        }
        .build()
        .unwrap();
        let p = sc.impact.spatial_problem(&[mu], &[e]).unwrap();
        let v = round_trip(&p);
        assert_eq!(v["w"].as_array().unwrap().len(), 12);
        for law in [LawId::Lcp, LawId::Sequential] {
            let out = spatial::resolve(law, &p).unwrap().unwrap();
            let v = round_trip(&out);
            assert_eq!(v["law"], law.as_str());
            details.insert(id_of(&v["detail"]));
        }
    }
    assert_eq!(
        details,
        ["lcp", "sequential"]
            .map(String::from)
            .into_iter()
            .collect()
    );
}
