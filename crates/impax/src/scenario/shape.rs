//! The planar body shapes: their names, the parameters each takes, and the numbers of them a
//! sweep can set by name — the one table every front end reads (the command line, the sweeps,
//! the Python bindings, the explorer). [`BodySpec`](super::BodySpec) builds the bodies.

use crate::error::{Error, Result};
use std::fmt;
use std::str::FromStr;

/// A planar body shape, by the name a scenario gives it (`shape = "rod"`).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
#[non_exhaustive]
pub enum Shape {
    /// A solid sphere (`radius`).
    Sphere,
    /// A uniform disc (`radius`).
    Disc,
    /// A uniform thin rod (`length`, `angle_deg`).
    Rod,
    /// A uniform elliptical disc (`semi_axes`, optional `angle_deg`).
    Ellipse,
    /// Any planar rigid body (`inertia`, `contact`).
    Rigid,
    /// A uniform rectangle striking with one corner (`half_extents`, optional `angle_deg` and
    /// `corner`).
    Box,
}

/// Whether a shape needs a parameter or may go without it (its default then applies).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum Need {
    /// The shape needs it.
    Required,
    /// The shape takes it and has a default.
    Optional,
}

impl Shape {
    /// Every shape, in the order of [`Shape::NAMES`].
    pub const ALL: [Shape; 6] = [
        Shape::Sphere,
        Shape::Disc,
        Shape::Rod,
        Shape::Ellipse,
        Shape::Rigid,
        Shape::Box,
    ];

    /// The names of [`Shape::ALL`], as scenarios spell them.
    pub const NAMES: [&'static str; 6] = ["sphere", "disc", "rod", "ellipse", "rigid", "box"];

    /// The name, e.g. `"rod"`.
    pub fn name(self) -> &'static str {
        match self {
            Shape::Sphere => "sphere",
            Shape::Disc => "disc",
            Shape::Rod => "rod",
            Shape::Ellipse => "ellipse",
            Shape::Rigid => "rigid",
            Shape::Box => "box",
        }
    }

    /// The shape of a name, if it is one of [`Shape::NAMES`].
    pub fn from_name(name: &str) -> Option<Self> {
        Self::ALL.into_iter().find(|s| s.name() == name)
    }

    /// The shape of a name, or an error naming `field` and listing the known shapes:
    /// `body.shape: unknown shape `cube` (known: sphere, disc, rod, ellipse, rigid)`.
    ///
    /// # Errors
    /// [`Error::Invalid`] for a name not in [`Shape::NAMES`].
    pub fn parse(name: &str, field: &str) -> Result<Self> {
        Self::from_name(name).ok_or_else(|| Error::Invalid {
            field: field.into(),
            reason: format!("unknown shape `{name}` (known: {})", Self::NAMES.join(", ")),
        })
    }

    /// The parameters the shape takes, with whether it needs them.
    pub fn parameters(self) -> &'static [(ShapeParam, Need)] {
        use Need::{Optional, Required};
        match self {
            Shape::Sphere | Shape::Disc => &[(ShapeParam::Radius, Required)],
            Shape::Rod => &[
                (ShapeParam::Length, Required),
                (ShapeParam::Angle, Required),
            ],
            Shape::Ellipse => &[
                (ShapeParam::SemiAxes, Required),
                (ShapeParam::Angle, Optional),
            ],
            Shape::Rigid => &[
                (ShapeParam::Inertia, Required),
                (ShapeParam::Contact, Required),
            ],
            Shape::Box => &[
                (ShapeParam::HalfExtents, Required),
                (ShapeParam::Angle, Optional),
                (ShapeParam::Corner, Optional),
            ],
        }
    }

    /// Whether the shape takes the parameter, and how.
    pub fn takes(self, p: ShapeParam) -> Option<Need> {
        self.parameters()
            .iter()
            .find(|(q, _)| *q == p)
            .map(|&(_, need)| need)
    }

    /// Whether a sweep may set the number `s` of this shape.
    pub fn has_scalar(self, s: ShapeScalar) -> bool {
        self.takes(s.param().0).is_some()
    }

    /// A round body (sphere, disc): its motion may be given as paper A's `v0, α, γ`, and its
    /// tables are normalised by `v0` and `r`.
    pub fn is_round(self) -> bool {
        matches!(self, Shape::Sphere | Shape::Disc)
    }
}

impl fmt::Display for Shape {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.name())
    }
}

impl FromStr for Shape {
    type Err = Error;

    /// As [`Shape::parse`] with the field `shape`.
    fn from_str(name: &str) -> Result<Self> {
        Self::parse(name, "shape")
    }
}

/// How the angles of a body are written: in degrees (scenario files, the command line, the
/// explorer: the keys `angle_deg`, `alpha_deg`) or in radians (the Python bindings: `angle`,
/// `alpha`). Keys in errors, descriptions and ranges follow it.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Default)]
pub enum AngleUnit {
    /// Degrees (`angle_deg = 50`).
    #[default]
    Degrees,
    /// Radians (`angle=0.87`).
    Radians,
}

impl AngleUnit {
    /// The angle in radians.
    pub fn to_radians(self, x: f64) -> f64 {
        match self {
            AngleUnit::Degrees => x.to_radians(),
            AngleUnit::Radians => x,
        }
    }

    /// A right angle in this unit (90 or π/2).
    pub fn right_angle(self) -> f64 {
        match self {
            AngleUnit::Degrees => 90.0,
            AngleUnit::Radians => std::f64::consts::FRAC_PI_2,
        }
    }

    /// The angle as descriptions show it: `50°`, `0.87 rad`.
    pub fn show(self, x: f64) -> String {
        match self {
            AngleUnit::Degrees => format!("{x}°"),
            AngleUnit::Radians => format!("{x} rad"),
        }
    }

    /// The open interval of approach angles, as messages write it.
    pub(crate) fn approach_interval(self) -> &'static str {
        match self {
            AngleUnit::Degrees => "(-90, 90)",
            AngleUnit::Radians => "(-π/2, π/2)",
        }
    }

    /// The key of the approach angle `α`: `alpha_deg` or `alpha`.
    pub fn alpha_key(self) -> &'static str {
        match self {
            AngleUnit::Degrees => "alpha_deg",
            AngleUnit::Radians => "alpha",
        }
    }
}

/// A parameter of a shape, as a scenario's key names it.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
#[non_exhaustive]
pub enum ShapeParam {
    /// `radius` (sphere, disc).
    Radius,
    /// `length` (rod).
    Length,
    /// `semi_axes = [a, b]` (ellipse).
    SemiAxes,
    /// `inertia`, the central moment of inertia (rigid).
    Inertia,
    /// `contact = [r_t, r_n]`, the contact point from the centre of mass (rigid).
    Contact,
    /// `angle_deg` (or `angle` in radians): the body's angle from the surface (rod; ellipse,
    /// its `a` axis; box, its `a` side).
    Angle,
    /// `half_extents = [a, b]`: half-width and half-height (box).
    HalfExtents,
    /// `corner = [s_a, s_b]`: the signs (`±1`) of the corner that strikes, in the body's frame
    /// (box; default: the lowest corner).
    Corner,
}

impl ShapeParam {
    /// Every shape parameter, in the order errors list them.
    pub const ALL: [ShapeParam; 8] = [
        ShapeParam::Radius,
        ShapeParam::Length,
        ShapeParam::SemiAxes,
        ShapeParam::Inertia,
        ShapeParam::Contact,
        ShapeParam::Angle,
        ShapeParam::HalfExtents,
        ShapeParam::Corner,
    ];

    /// The key, with angles in `unit`: `radius`, `semi_axes`, `angle_deg` or `angle`.
    pub fn key(self, unit: AngleUnit) -> &'static str {
        match (self, unit) {
            (ShapeParam::Radius, _) => "radius",
            (ShapeParam::Length, _) => "length",
            (ShapeParam::SemiAxes, _) => "semi_axes",
            (ShapeParam::Inertia, _) => "inertia",
            (ShapeParam::Contact, _) => "contact",
            (ShapeParam::Angle, AngleUnit::Degrees) => "angle_deg",
            (ShapeParam::Angle, AngleUnit::Radians) => "angle",
            (ShapeParam::HalfExtents, _) => "half_extents",
            (ShapeParam::Corner, _) => "corner",
        }
    }

    /// How many numbers it holds (1, or 2 for a pair such as `semi_axes`).
    pub fn count(self) -> usize {
        match self {
            ShapeParam::SemiAxes
            | ShapeParam::Contact
            | ShapeParam::HalfExtents
            | ShapeParam::Corner => 2,
            _ => 1,
        }
    }

    /// The parameter of a key spelled with angles in `unit`, or an error naming the key and
    /// listing the known ones.
    ///
    /// # Errors
    /// [`Error::Invalid`] for a key of no shape.
    pub fn parse(key: &str, unit: AngleUnit) -> Result<Self> {
        Self::ALL
            .into_iter()
            .find(|p| p.key(unit) == key)
            .ok_or_else(|| Error::Invalid {
                field: key.into(),
                reason: format!(
                    "not a parameter of any shape (known: {})",
                    Self::ALL.map(|p| p.key(unit)).join(", ")
                ),
            })
    }
}

/// One number of a shape's parameters that a sweep can set by name (the angle in degrees).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
#[non_exhaustive]
pub enum ShapeScalar {
    /// `radius`.
    Radius,
    /// `length`.
    Length,
    /// `angle_deg`.
    AngleDeg,
    /// `semi_axis_a`: `semi_axes[0]`.
    SemiAxisA,
    /// `semi_axis_b`: `semi_axes[1]`.
    SemiAxisB,
    /// `inertia`.
    Inertia,
    /// `contact_t`: `contact[0]`.
    ContactT,
    /// `contact_n`: `contact[1]`.
    ContactN,
    /// `half_extent_a`: `half_extents[0]`.
    HalfExtentA,
    /// `half_extent_b`: `half_extents[1]`.
    HalfExtentB,
}

impl ShapeScalar {
    /// Every one, in the order field lists show them.
    pub const ALL: [ShapeScalar; 10] = [
        ShapeScalar::Radius,
        ShapeScalar::Length,
        ShapeScalar::AngleDeg,
        ShapeScalar::SemiAxisA,
        ShapeScalar::SemiAxisB,
        ShapeScalar::Inertia,
        ShapeScalar::ContactT,
        ShapeScalar::ContactN,
        ShapeScalar::HalfExtentA,
        ShapeScalar::HalfExtentB,
    ];

    /// The name, e.g. `semi_axis_a` (the command line writes `semi-axis-a`).
    pub fn name(self) -> &'static str {
        match self {
            ShapeScalar::Radius => "radius",
            ShapeScalar::Length => "length",
            ShapeScalar::AngleDeg => "angle_deg",
            ShapeScalar::SemiAxisA => "semi_axis_a",
            ShapeScalar::SemiAxisB => "semi_axis_b",
            ShapeScalar::Inertia => "inertia",
            ShapeScalar::ContactT => "contact_t",
            ShapeScalar::ContactN => "contact_n",
            ShapeScalar::HalfExtentA => "half_extent_a",
            ShapeScalar::HalfExtentB => "half_extent_b",
        }
    }

    /// The scalar of a name (`_` or `-` between words).
    pub fn from_name(name: &str) -> Option<Self> {
        let name = name.replace('-', "_");
        Self::ALL.into_iter().find(|s| s.name() == name)
    }

    /// An axis label with units, e.g. `semi-axis a`.
    pub fn label(self) -> &'static str {
        match self {
            ShapeScalar::Radius => "radius r",
            ShapeScalar::Length => "length L",
            ShapeScalar::AngleDeg => "angle θ from the surface (deg)",
            ShapeScalar::SemiAxisA => "semi-axis a",
            ShapeScalar::SemiAxisB => "semi-axis b",
            ShapeScalar::Inertia => "moment of inertia I",
            ShapeScalar::ContactT => "contact offset r_t",
            ShapeScalar::ContactN => "contact offset r_n",
            ShapeScalar::HalfExtentA => "half-width a",
            ShapeScalar::HalfExtentB => "half-height b",
        }
    }

    /// The parameter it is a number of, and its index there.
    pub fn param(self) -> (ShapeParam, usize) {
        match self {
            ShapeScalar::Radius => (ShapeParam::Radius, 0),
            ShapeScalar::Length => (ShapeParam::Length, 0),
            ShapeScalar::AngleDeg => (ShapeParam::Angle, 0),
            ShapeScalar::SemiAxisA => (ShapeParam::SemiAxes, 0),
            ShapeScalar::SemiAxisB => (ShapeParam::SemiAxes, 1),
            ShapeScalar::Inertia => (ShapeParam::Inertia, 0),
            ShapeScalar::ContactT => (ShapeParam::Contact, 0),
            ShapeScalar::ContactN => (ShapeParam::Contact, 1),
            ShapeScalar::HalfExtentA => (ShapeParam::HalfExtents, 0),
            ShapeScalar::HalfExtentB => (ShapeParam::HalfExtents, 1),
        }
    }

    /// What it measures.
    pub fn quantity(self) -> Quantity {
        match self {
            ShapeScalar::Radius
            | ShapeScalar::Length
            | ShapeScalar::SemiAxisA
            | ShapeScalar::SemiAxisB
            | ShapeScalar::HalfExtentA
            | ShapeScalar::HalfExtentB => Quantity::Length,
            ShapeScalar::AngleDeg => Quantity::Angle,
            ShapeScalar::Inertia => Quantity::Inertia,
            ShapeScalar::ContactT | ShapeScalar::ContactN => Quantity::Offset,
        }
    }

    /// Whether its values must be `> 0` (lengths, the moment of inertia); the others take any
    /// finite value the body's builder accepts.
    pub fn positive(self) -> bool {
        matches!(
            self,
            ShapeScalar::Radius
                | ShapeScalar::Length
                | ShapeScalar::SemiAxisA
                | ShapeScalar::SemiAxisB
                | ShapeScalar::Inertia
                | ShapeScalar::HalfExtentA
                | ShapeScalar::HalfExtentB
        )
    }
}

/// What a shape's number measures: front ends that offer values of it (the explorer's
/// sliders) choose their ranges by it.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
#[non_exhaustive]
pub enum Quantity {
    /// A length (`> 0`).
    Length,
    /// An angle from the surface, in degrees.
    Angle,
    /// A moment of inertia (`> 0`).
    Inertia,
    /// A coordinate of a point from the centre of mass (any sign).
    Offset,
}

impl Quantity {
    /// `length`, `angle`, `inertia` or `offset`.
    pub fn name(self) -> &'static str {
        match self {
            Quantity::Length => "length",
            Quantity::Angle => "angle",
            Quantity::Inertia => "inertia",
            Quantity::Offset => "offset",
        }
    }
}
