//! The request of the view with several contacts, checked and built by the core: a planar
//! built-in of [`impax::multi::scenarios`] by name, its parameters under the names of
//! `impax compare NAME`'s flags (`_` for `-`), μ and e; and the scene the page draws.
//!
//! ```json
//! {"system": "cradle", "balls": 3, "v0": 1, "friction": 0, "restitution": 1}
//! ```
//!
//! | system | parameters (defaults: the core's) | the scene |
//! |---|---|---|
//! | `rod-flat` | `mass`, `length`, `vx`, `vy`, `omega` | the rod lying on the floor `y = 0`, its centre at the origin |
//! | `rocking-block` | `mass`, `half_width`, `half_height`, `omega` | the block upright on the floor, its centre at `(0, h)` |
//! | `cradle` | `balls`, `mass`, `radius`, `v0` | the balls along `y = 0`, ball `i` (from 0) at `x = 2 r i` |
//! | `ball-ball-wall` | `mass`, `radius`, `v0`, `angle_deg` | the wall `x = 0`, ball 1 at `(r, 0)`, ball 2 at `(r, 0) + 2 r (cos θ, sin θ)` |
//!
//! `friction` and `restitution` are those of every contact (the system's defaults when
//! left out). A parameter the system does not take, a value out of range or a system with
//! no contact approaching is an error naming the field.

use impax::mechanism::builtin::{Block, BuiltIn, Rod, STANDARD_GRAVITY};
use impax::multi::scenarios::{BallBallWall, Cradle, RockingBlock, RodFlat};
use impax::multi::MultiScenario;
use serde::Deserialize;
use serde_json::{json, Value};

/// The systems the view offers: the planar built-ins of [`impax::multi::scenarios`].
pub const SYSTEMS: [&str; 4] = ["rod-flat", "rocking-block", "cradle", "ball-ball-wall"];

/// The parameters each system takes (besides `friction` and `restitution`).
pub fn parameters(system: &str) -> &'static [&'static str] {
    match system {
        "rod-flat" => &["mass", "length", "vx", "vy", "omega"],
        "rocking-block" => &["mass", "half_width", "half_height", "omega"],
        "cradle" => &["balls", "mass", "radius", "v0"],
        _ => &["mass", "radius", "v0", "angle_deg"],
    }
}

/// A request: the system and those of its parameters that differ from the defaults.
#[derive(Debug, Clone, Default, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct MultiRequest {
    /// One of [`SYSTEMS`].
    pub system: String,
    /// Coulomb friction μ ≥ 0 at every contact.
    pub friction: Option<f64>,
    /// Restitution e ∈ [0, 1] at every contact.
    pub restitution: Option<f64>,
    /// The mass (of each ball).
    pub mass: Option<f64>,
    /// `rod-flat`: the rod's length.
    pub length: Option<f64>,
    /// `rod-flat`: the centre's horizontal velocity.
    pub vx: Option<f64>,
    /// `rod-flat`: the centre's vertical velocity.
    pub vy: Option<f64>,
    /// `rod-flat`: the angular velocity; `rocking-block`: the angular velocity about corner A
    /// (negative).
    pub omega: Option<f64>,
    /// `cradle`: the number of balls (a whole number).
    pub balls: Option<f64>,
    /// `cradle`, `ball-ball-wall`: each ball's radius.
    pub radius: Option<f64>,
    /// `cradle`: the first ball's velocity; `ball-ball-wall`: ball 2's speed.
    pub v0: Option<f64>,
    /// `rocking-block`: the half-width b.
    pub half_width: Option<f64>,
    /// `rocking-block`: the half-height h.
    pub half_height: Option<f64>,
    /// `ball-ball-wall`: the line of centres from the wall's normal, degrees.
    pub angle_deg: Option<f64>,
}

/// What surrounds the bodies.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Layout {
    /// The floor `y = 0`, gravity along `−y` (rod, block).
    Floor,
    /// A row on a horizontal table seen from above (the cradle): no gravity in the plane.
    Row,
    /// The wall `x = 0` on a horizontal table seen from above (ball–ball–wall).
    Wall,
}

impl Layout {
    /// `floor`, `row` or `wall`.
    pub fn id(self) -> &'static str {
        match self {
            Layout::Floor => "floor",
            Layout::Row => "row",
            Layout::Wall => "wall",
        }
    }
}

/// A body's outline as the page draws it.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Outline {
    /// A rod along its angle.
    Rod {
        /// Its length.
        length: f64,
    },
    /// A rectangle, upright at angle 0.
    Block {
        /// Half of its width.
        half_width: f64,
        /// Half of its height.
        half_height: f64,
    },
    /// A ball.
    Ball {
        /// Its radius.
        radius: f64,
    },
}

impl Outline {
    fn to_json(self) -> Value {
        match self {
            Outline::Rod { length } => json!({ "shape": "rod", "length": length }),
            Outline::Block {
                half_width,
                half_height,
            } => json!({ "shape": "block", "half_width": half_width, "half_height": half_height }),
            Outline::Ball { radius } => json!({ "shape": "ball", "radius": radius }),
        }
    }
}

/// A checked request: the core's system and the scene at the impact.
#[derive(Debug, Clone)]
pub struct System {
    /// The core's built-in.
    pub scenario: MultiScenario,
    /// μ at every contact.
    pub friction: f64,
    /// e at every contact.
    pub restitution: f64,
    /// What surrounds the bodies.
    pub layout: Layout,
    /// Each body's outline.
    pub outlines: Vec<Outline>,
    /// The configuration at the impact, `(x, y, θ)` per body, in the scene's frame.
    pub q: Vec<f64>,
    /// The mechanism whose motion after the impact the core simulates (rod, block: gravity,
    /// the floor, contacts that stay closed); `None` for the balls, which move freely.
    pub mechanism: Option<BuiltIn>,
}

/// The core's error as one line, its field as the request spells it (`half-width` →
/// `half_width`).
pub fn named(e: impax::Error) -> String {
    let text = e.to_string();
    let field = e.field();
    if field.contains('-') {
        if let Some(rest) = text.strip_prefix(field) {
            return format!("{}{rest}", field.replace('-', "_"));
        }
    }
    text
}

impl MultiRequest {
    /// The numbers given, by name.
    fn given(&self) -> [(&'static str, Option<f64>); 11] {
        [
            ("mass", self.mass),
            ("length", self.length),
            ("vx", self.vx),
            ("vy", self.vy),
            ("omega", self.omega),
            ("balls", self.balls),
            ("radius", self.radius),
            ("v0", self.v0),
            ("half_width", self.half_width),
            ("half_height", self.half_height),
            ("angle_deg", self.angle_deg),
        ]
    }

    /// Check the request and build the system.
    ///
    /// # Errors
    /// One line naming the field: an unknown system, a parameter the system does not take, a
    /// value out of range (the core's checks).
    pub fn system(&self) -> Result<System, String> {
        let name = self.system.as_str();
        if !SYSTEMS.contains(&name) {
            return Err(format!(
                "system: unknown system `{name}` (known: {})",
                SYSTEMS.join(", ")
            ));
        }
        let takes = parameters(name);
        for (key, value) in self.given() {
            if value.is_some() && !takes.contains(&key) {
                return Err(format!(
                    "{key}: not a parameter of `{name}` (it takes {})",
                    takes.join(", ")
                ));
            }
        }
        let (scenario, layout, outlines, q, mechanism) = match name {
            "rod-flat" => self.rod()?,
            "rocking-block" => self.block()?,
            "cradle" => self.cradle()?,
            _ => self.ball_ball_wall()?,
        };
        Ok(System {
            friction: self.friction.unwrap_or(scenario.friction),
            restitution: self.restitution.unwrap_or(scenario.restitution),
            scenario,
            layout,
            outlines,
            q,
            mechanism,
        })
    }

    fn rod(&self) -> Result<Built, String> {
        let d = RodFlat::default();
        let rod = RodFlat {
            mass: self.mass.unwrap_or(d.mass),
            length: self.length.unwrap_or(d.length),
            vx: self.vx.unwrap_or(d.vx),
            vy: self.vy.unwrap_or(d.vy),
            omega: self.omega.unwrap_or(d.omega),
        };
        let scenario = rod.build().map_err(named)?;
        let mechanism = Rod::new(rod.mass, rod.length, STANDARD_GRAVITY, 0.0).map_err(named)?;
        Ok((
            scenario,
            Layout::Floor,
            vec![Outline::Rod { length: rod.length }],
            vec![0.0; 3],
            Some(BuiltIn::Rod(mechanism)),
        ))
    }

    fn block(&self) -> Result<Built, String> {
        let d = RockingBlock::default();
        let block = RockingBlock {
            mass: self.mass.unwrap_or(d.mass),
            half_width: self.half_width.unwrap_or(d.half_width),
            half_height: self.half_height.unwrap_or(d.half_height),
            omega: self.omega.unwrap_or(d.omega),
        };
        let scenario = block.build().map_err(named)?;
        let (b, h) = (block.half_width, block.half_height);
        let mechanism = Block::new(block.mass, b, h, STANDARD_GRAVITY, 0.0).map_err(named)?;
        Ok((
            scenario,
            Layout::Floor,
            vec![Outline::Block {
                half_width: b,
                half_height: h,
            }],
            vec![0.0, h, 0.0],
            Some(BuiltIn::Block(mechanism)),
        ))
    }

    fn cradle(&self) -> Result<Built, String> {
        let d = Cradle::default();
        let balls = match self.balls {
            None => d.balls,
            Some(x) if x.fract() == 0.0 && (0.0..=1e9).contains(&x) => x as usize,
            Some(x) => return Err(format!("balls: must be a whole number, got {x}")),
        };
        let cradle = Cradle {
            balls,
            mass: self.mass.unwrap_or(d.mass),
            radius: self.radius.unwrap_or(d.radius),
            v0: self.v0.unwrap_or(d.v0),
        };
        let scenario = cradle.build().map_err(named)?;
        let r = cradle.radius;
        let q = (0..balls)
            .flat_map(|i| [2.0 * r * i as f64, 0.0, 0.0])
            .collect();
        Ok((
            scenario,
            Layout::Row,
            vec![Outline::Ball { radius: r }; balls],
            q,
            None,
        ))
    }

    fn ball_ball_wall(&self) -> Result<Built, String> {
        let d = BallBallWall::default();
        let system = BallBallWall {
            mass: self.mass.unwrap_or(d.mass),
            radius: self.radius.unwrap_or(d.radius),
            v0: self.v0.unwrap_or(d.v0),
            angle_deg: self.angle_deg.unwrap_or(d.angle_deg),
        };
        let scenario = system.build().map_err(named)?;
        let r = system.radius;
        let (s, c) = system.angle_deg.to_radians().sin_cos();
        Ok((
            scenario,
            Layout::Wall,
            vec![Outline::Ball { radius: r }; 2],
            vec![r, 0.0, 0.0, r + 2.0 * r * c, 2.0 * r * s, 0.0],
            None,
        ))
    }
}

/// A built system: the core's, its layout, outlines, configuration and mechanism.
type Built = (
    MultiScenario,
    Layout,
    Vec<Outline>,
    Vec<f64>,
    Option<BuiltIn>,
);

impl System {
    /// The scene as JSON: `layout`, `gravity` (along `−y`, 0 without a floor) and per body
    /// its outline (`shape`: `rod` with `length`, `block` with `half_width`, `half_height`,
    /// `ball` with `radius`), `position` `[x, y]` and `angle` at the impact, and `velocity`
    /// `[v_x, v_y, ω]` before it.
    pub fn scene_json(&self) -> Value {
        let u = self.scenario.impact.velocities_before();
        let bodies: Vec<Value> = self
            .outlines
            .iter()
            .enumerate()
            .map(|(i, o)| {
                let mut b = o.to_json();
                let m = b.as_object_mut().expect("an object");
                let q = &self.q[3 * i..3 * i + 3];
                m.insert("position".into(), json!([q[0], q[1]]));
                m.insert("angle".into(), json!(q[2]));
                let v = &u[3 * i..3 * i + 3];
                m.insert(
                    "velocity".into(),
                    json!(v.iter().map(|&x| crate::report::num(x)).collect::<Vec<_>>()),
                );
                b
            })
            .collect();
        json!({
            "layout": self.layout.id(),
            "gravity": if self.layout == Layout::Floor { STANDARD_GRAVITY } else { 0.0 },
            "bodies": bodies,
        })
    }
}

/// Each system's parameters with the core's defaults, and its default μ and e:
/// `{name: {"parameters": {key: value}, "friction", "restitution", "description"}}`.
pub fn systems_json() -> Value {
    let mut out = serde_json::Map::new();
    for name in SYSTEMS {
        let request = MultiRequest {
            system: name.into(),
            ..MultiRequest::default()
        };
        let Ok(s) = request.system() else { continue };
        let defaults: Vec<(&str, f64)> = match name {
            "rod-flat" => {
                let d = RodFlat::default();
                vec![
                    ("mass", d.mass),
                    ("length", d.length),
                    ("vx", d.vx),
                    ("vy", d.vy),
                    ("omega", d.omega),
                ]
            }
            "rocking-block" => {
                let d = RockingBlock::default();
                vec![
                    ("mass", d.mass),
                    ("half_width", d.half_width),
                    ("half_height", d.half_height),
                    ("omega", d.omega),
                ]
            }
            "cradle" => {
                let d = Cradle::default();
                vec![
                    ("balls", d.balls as f64),
                    ("mass", d.mass),
                    ("radius", d.radius),
                    ("v0", d.v0),
                ]
            }
            _ => {
                let d = BallBallWall::default();
                vec![
                    ("mass", d.mass),
                    ("radius", d.radius),
                    ("v0", d.v0),
                    ("angle_deg", d.angle_deg),
                ]
            }
        };
        let parameters: serde_json::Map<String, Value> = defaults
            .into_iter()
            .map(|(k, v)| (k.into(), json!(v)))
            .collect();
        out.insert(
            name.into(),
            json!({
                "parameters": parameters,
                "friction": s.friction,
                "restitution": s.restitution,
                "description": s.scenario.description,
            }),
        );
    }
    out.into()
}
