//! What each kind of claim states: one struct of its own fields per kind, and [`Kind`], the
//! kinds by name with the declarations each takes (`claim_kinds!`).

use super::super::claim_syntax::{read, FieldError};
use super::{Number, DECLARATIONS};
use serde::Deserialize;

/// The two sides of an identity, or a chain `a = b = c = …` (consecutive members equal).
#[derive(Clone, Debug)]
pub enum Sides {
    /// `lhs = rhs`.
    Pair(String, String),
    /// `chain = [a, b, c, …]`.
    Chain(Vec<String>),
}

impl Sides {
    /// The members in order (two for a pair).
    pub fn members(&self) -> Vec<String> {
        match self {
            Sides::Pair(l, r) => vec![l.clone(), r.clone()],
            Sides::Chain(c) => c.clone(),
        }
    }
}

/// `kind = "identity"`: `lhs = rhs`, or every step of `chain`.
#[derive(Clone, Debug, Deserialize)]
#[serde(try_from = "IdentityFields")]
pub struct Identity {
    /// The sides.
    pub sides: Sides,
    /// With open ranges: WZ certificates `R`, one per sum with a symbolic bound (innermost first).
    pub certificates: Vec<String>,
    /// With open ranges: proved by induction on this range variable (`induction = "r"`), the
    /// library objects unfolded by their defining recursion.
    pub induction: Option<String>,
}

/// An identity's fields as written.
#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct IdentityFields {
    lhs: Option<String>,
    rhs: Option<String>,
    chain: Option<Vec<String>>,
    #[serde(default, deserialize_with = "one_or_many")]
    certificate: Vec<String>,
    induction: Option<String>,
}

fn one_or_many<'de, D: serde::Deserializer<'de>>(d: D) -> std::result::Result<Vec<String>, D::Error> {
    Certificates::deserialize(d)
        .map(Certificates::into_list)
        .map_err(|_| serde::de::Error::custom("certificate must be a string or a list of strings"))
}

impl TryFrom<IdentityFields> for Identity {
    type Error = String;
    fn try_from(f: IdentityFields) -> std::result::Result<Self, String> {
        let sides = match (f.lhs, f.rhs, f.chain) {
            (Some(l), Some(r), None) => Sides::Pair(l, r),
            (None, None, Some(c)) => Sides::Chain(c),
            _ => return Err(r#"an identity needs either lhs and rhs, or chain; expected: lhs = "(1 - t)^2" and rhs = "B(0, 2, t)", or chain = ["a", "b", "c"]"#.into()),
        };
        Ok(Identity {
            sides,
            certificates: f.certificate,
            induction: f.induction,
        })
    }
}

/// `kind = "implicit"`: the curve `on` satisfies `equation` for every parameter.
#[derive(Clone, Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Implicit {
    /// The curve, a tuple expression in `t` (or a curve call like `x(t)`).
    pub on: String,
    /// The equation `A = B` (or an expression meaning `= 0`).
    pub equation: String,
    /// The coordinate names the equation uses (default `x, y, z`).
    pub coords: Option<Vec<String>>,
}

impl Implicit {
    /// The coordinate names.
    pub fn coordinates(&self) -> Vec<String> {
        self.coords
            .clone()
            .unwrap_or_else(|| vec!["x".into(), "y".into(), "z".into()])
    }
}

/// `kind = "bezier_points"`: the Bézier points of a power-basis curve on `[a, b]`.
#[derive(Clone, Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct BezierPoints {
    /// The curve in the power basis, a tuple expression in `param`.
    pub power: String,
    /// Its parameter name (default `u`).
    pub param: Option<String>,
    /// The parameter interval `[a, b]`.
    pub interval: [Number; 2],
    /// The claimed Bézier points.
    pub points: Vec<Vec<Number>>,
}

impl BezierPoints {
    /// The parameter's name.
    pub fn parameter(&self) -> String {
        self.param.clone().unwrap_or_else(|| "u".into())
    }
}

/// `kind = "conic_type"`: the conic `equation` is the printed `conic`.
#[derive(Clone, Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct ConicType {
    /// The conic, an equation of degree 2 in x, y.
    pub equation: String,
    /// The printed type ("ellipse", "parabola", "hyperbola").
    pub conic: String,
}

/// `kind = "weight_type"`: a rational quadratic's weights give the printed conic type.
#[derive(Clone, Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct WeightType {
    /// The printed type.
    pub conic: String,
}

/// `kind = "implies"`: `equation` follows from `premise` by `equation = factor · premise`.
#[derive(Clone, Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Implies {
    /// The premise (an expression meaning `= 0`, or `A = B`).
    pub premise: String,
    /// The conclusion, an equation.
    pub equation: String,
    /// The factor with `conclusion = factor · premise` identically.
    pub factor: String,
}

/// `kind = "theorem"`: a general theorem of the texts for every degree in `degrees`.
#[derive(Clone, Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Theorem {
    /// Which theorem.
    pub theorem: String,
    /// The degrees checked, `"0..=10"` (the default).
    pub degrees: Option<String>,
}

/// `kind = "convergence"`: Theorem 1.2, bounded evidence.
#[derive(Clone, Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Convergence {
    /// The largest number of elevation steps (default 64).
    pub steps: Option<usize>,
}

/// `kind = "fit"`: text 004's cubic fit of a concrete curve.
#[derive(Clone, Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Fit {
    /// The printed (or stated) tangent length `k`, if any.
    pub k: Option<Number>,
    /// The printed tangent length `l`, if any.
    pub l: Option<Number>,
    /// The printed `δ²`, if any.
    pub delta2: Option<Number>,
}

/// Whether an inequality is strict.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Deserialize)]
pub enum Relation {
    /// `lhs ≥ rhs`.
    #[default]
    #[serde(rename = ">=", alias = "≥")]
    AtLeast,
    /// `lhs > rhs`.
    #[serde(rename = ">")]
    Greater,
}

/// `kind = "inequality"`: `lhs ≥ rhs` (or `>`) on an interval.
#[derive(Clone, Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Inequality {
    /// The left side.
    pub lhs: String,
    /// The right side (default 0).
    pub rhs: Option<String>,
    /// `">="` (default) or `">"`.
    #[serde(default)]
    pub relation: Relation,
    /// The parameter interval `[a, b]`.
    pub interval: Option<[Number; 2]>,
}

/// `kind = "vanishes"`: `expr = 0` for every value of the variables and ranges.
#[derive(Clone, Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Vanishes {
    /// The expression.
    pub expr: String,
}

impl Vanishes {
    /// The identity `expr = 0`.
    pub fn identity(&self) -> Identity {
        Identity {
            sides: Sides::Pair(self.expr.clone(), "0".into()),
            certificates: Vec::new(),
            induction: None,
        }
    }
}

/// Writes [`Kind`] (one variant per kind, with the kind's own fields), [`KINDS`], the
/// kind's name and declarations and the reading of its fields: a new kind is one line here,
/// its struct, and its lowering in `kinds::check_kind`.
macro_rules! claim_kinds {
    ($( $(#[$doc:meta])* $variant:ident $(($fields:ty))? = $name:literal, declares $declares:expr; )*) => {
        /// What a claim states, one variant per kind, with the kind's own fields.
        #[derive(Clone, Debug)]
        pub enum Kind {
            $( $(#[$doc])* $variant $(($fields))?, )*
        }

        /// The kinds by their names in the file.
        pub const KINDS: &[&str] = &[$($name),*];

        impl Kind {
            /// The kind's name in the file.
            pub fn name(&self) -> &'static str {
                match self {
                    $( Kind::$variant { .. } => $name, )*
                }
            }

            /// The declarations ([`Decls`](super::Decls)) the kind takes.
            pub fn declares(&self) -> &'static [&'static str] {
                match self {
                    $( Kind::$variant { .. } => $declares, )*
                }
            }

            /// The kind named `kind`, from its own fields (unknown fields refused).
            pub(super) fn from_table(kind: &str, own: toml::Table) -> std::result::Result<Self, FieldError> {
                match kind {
                    $( $name => claim_kinds!(@read $variant $(($fields))?, own), )*
                    other => Err(FieldError {
                        field: Some("kind".into()),
                        message: format!("unknown kind '{other}' ({})", KINDS.join(", ")),
                    }),
                }
            }
        }
    };
    (@read $variant:ident ($fields:ty), $own:expr) => {
        read::<$fields>($own).map(Kind::$variant)
    };
    (@read $variant:ident, $own:expr) => {
        read::<Empty>($own).map(|_| Kind::$variant)
    };
}

claim_kinds! {
    /// `identity`.
    Identity(Identity) = "identity", declares &DECLARATIONS;
    /// `implicit`.
    Implicit(Implicit) = "implicit", declares &["vars", "for", "let", "polygon", "net", "curves", "surfaces"];
    /// `bezier_points`.
    BezierPoints(BezierPoints) = "bezier_points", declares &["let"];
    /// `conic_type`.
    ConicType(ConicType) = "conic_type", declares &["let"];
    /// `weight_type` (of the curve in `curves`).
    WeightType(WeightType) = "weight_type", declares &["curves"];
    /// `enneper` (the surface in `surfaces` is Enneper's surface).
    Enneper = "enneper", declares &["surfaces"];
    /// `implies`.
    Implies(Implies) = "implies", declares &["symbols", "vectors", "let"];
    /// `theorem`.
    Theorem(Theorem) = "theorem", declares &[];
    /// `convergence` (of the curve in `curves`).
    Convergence(Convergence) = "convergence", declares &["curves"];
    /// `fit` (of the curve in `curves`).
    Fit(Fit) = "fit", declares &["curves"];
    /// `inequality`.
    Inequality(Inequality) = "inequality", declares &["vars", "for", "let"];
    /// `vanishes`.
    Vanishes(Vanishes) = "vanishes", declares &DECLARATIONS;
}

impl Kind {
    /// The identity the kind states, for the kinds that state one (the every-n route and the
    /// range-bound note take it).
    pub fn identity(&self) -> Option<std::borrow::Cow<'_, Identity>> {
        match self {
            Kind::Identity(i) => Some(std::borrow::Cow::Borrowed(i)),
            Kind::Vanishes(v) => Some(std::borrow::Cow::Owned(v.identity())),
            _ => None,
        }
    }

    /// The kind's expression fields as the explanation shows them, in order.
    pub fn shown_fields(&self) -> Vec<(&'static str, &str)> {
        match self {
            Kind::Identity(Identity {
                sides: Sides::Pair(l, r),
                ..
            }) => vec![("lhs", l), ("rhs", r)],
            Kind::Inequality(i) => {
                let mut v = vec![("lhs", i.lhs.as_str())];
                v.extend(i.rhs.as_deref().map(|r| ("rhs", r)));
                v
            }
            Kind::Implicit(i) => vec![("on", &i.on), ("equation", &i.equation)],
            Kind::ConicType(c) => vec![("equation", &c.equation)],
            Kind::Implies(i) => vec![
                ("equation", &i.equation),
                ("premise", &i.premise),
                ("factor", &i.factor),
            ],
            Kind::BezierPoints(b) => vec![("power", &b.power)],
            Kind::Vanishes(v) => vec![("expr", &v.expr)],
            _ => Vec::new(),
        }
    }
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct Empty {}

/// One certificate or a list of them.
#[derive(Clone, Debug, Deserialize)]
#[serde(untagged)]
enum Certificates {
    One(String),
    Many(Vec<String>),
}

impl Certificates {
    fn into_list(self) -> Vec<String> {
        match self {
            Certificates::One(s) => vec![s],
            Certificates::Many(v) => v,
        }
    }
}
