//! The `sampling` data of a certificate, serialized as it is written: its rows are most of a
//! sampled file's bytes, and building them as `serde_json::Value` maps first cost more than
//! writing them. The bytes are those of the same data as a `Value` (keys in sorted order).

use super::{rational_text, sqrt, Res};
use crate::verify::kernel::certificate::{Equality, Row};
use serde::ser::{SerializeMap, SerializeSeq, Serializer};
use serde::Serialize;
use serde_json::{json, Value as Json};

/// The `sampling` data of equalities whose values are numbers of the goal's field
/// (`radicand`; `None`: the rationals), each checked when the data is made.
pub(super) struct Sampling<'a> {
    eqs: &'a [Equality],
    radicand: Option<i64>,
}

impl<'a> Sampling<'a> {
    /// The data, or the first value that is not a number of the goal's field.
    pub(super) fn new(eqs: &'a [Equality], radicand: Option<i64>) -> Res<Sampling<'a>> {
        for v in eqs.iter().flat_map(|eq| &eq.rows).flat_map(|r| &r.value) {
            if !super::is_rational_text(v) {
                sqrt::value_json(v, radicand)?;
            }
        }
        Ok(Sampling { eqs, radicand })
    }
}

/// One value entry: its text when it is a rational (most are), else as [`sqrt::value_json`]
/// writes it (checked in [`Sampling::new`]).
struct Number<'a>(&'a str, Option<i64>);

impl Serialize for Number<'_> {
    fn serialize<S: Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        if self.1.is_none() || super::is_rational_text(self.0) {
            return s.serialize_str(self.0);
        }
        sqrt::value_json(self.0, self.1)
            .map_err(serde::ser::Error::custom)?
            .serialize(s)
    }
}

struct Values<'a>(&'a [String], Option<i64>);

impl Serialize for Values<'_> {
    fn serialize<S: Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        let mut seq = s.serialize_seq(Some(self.0.len()))?;
        for v in self.0 {
            seq.serialize_element(&Number(v, self.1))?;
        }
        seq.end()
    }
}

struct At<'a>(&'a Row);

impl Serialize for At<'_> {
    fn serialize<S: Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        let mut seq = s.serialize_seq(Some(self.0.at.len()))?;
        for x in &self.0.at {
            seq.serialize_element(&rational_text(x))?;
        }
        seq.end()
    }
}

/// A row: `at`, `lhs`, `polygon` (with control points), `rhs`, in that (sorted) order.
struct RowOut<'a>(&'a Row, bool, Option<i64>);

impl Serialize for RowOut<'_> {
    fn serialize<S: Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        let RowOut(row, polygon, radicand) = *self;
        let mut m = s.serialize_map(Some(3 + usize::from(polygon)))?;
        m.serialize_entry("at", &At(row))?;
        m.serialize_entry("lhs", &Values(&row.value, radicand))?;
        if polygon {
            m.serialize_entry("polygon", &row.basis)?;
        }
        m.serialize_entry("rhs", &Values(&row.value, radicand))?;
        m.end()
    }
}

struct Rows<'a>(&'a Equality, Option<i64>);

impl Serialize for Rows<'_> {
    fn serialize<S: Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        let polygon = !self.0.control_points.is_empty();
        let mut seq = s.serialize_seq(Some(self.0.rows.len()))?;
        for r in &self.0.rows {
            seq.serialize_element(&RowOut(r, polygon, self.1))?;
        }
        seq.end()
    }
}

struct EqualityOut<'a>(&'a Equality, Option<i64>);

impl Serialize for EqualityOut<'_> {
    fn serialize<S: Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        let params: Vec<Json> = self
            .0
            .params
            .iter()
            .map(|p| {
                json!({"name": p.name, "degree": p.degree, "lhs_degree": p.lhs_degree,
                       "rhs_degree": p.rhs_degree, "points": super::strings(&p.points)})
            })
            .collect();
        let mut m = s.serialize_map(Some(2))?;
        m.serialize_entry("params", &params)?;
        m.serialize_entry("values", &Rows(self.0, self.1))?;
        m.end()
    }
}

impl Serialize for Sampling<'_> {
    fn serialize<S: Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        struct Eqs<'b>(&'b Sampling<'b>);
        impl Serialize for Eqs<'_> {
            fn serialize<S: Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
                let mut seq = s.serialize_seq(Some(self.0.eqs.len()))?;
                for eq in self.0.eqs {
                    seq.serialize_element(&EqualityOut(eq, self.0.radicand))?;
                }
                seq.end()
            }
        }
        let mut m = s.serialize_map(Some(1))?;
        m.serialize_entry("equalities", &Eqs(self))?;
        m.end()
    }
}
