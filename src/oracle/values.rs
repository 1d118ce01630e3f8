//! Exact numbers, points and nets to and from JSON values: the oracle's encoding.
//!
//! A number is a JSON string in the text syntax of [`crate::parse_number`] (exact), or a
//! JSON number, which means exactly the `f64` it parses to (`0.1` is
//! `3602879701896397/36028797018963968`; integer literals that fit in 64 bits are those
//! integers). A point is an array of numbers, a list of points an array of points, a net an
//! array of rows of points. Exact results are written as strings in lowest terms, `"p/q"` or
//! `"p"`, with a positive denominator.

use crate::error::{Error, Result, MAX_DIMENSION};
use crate::input::{check_net, in_context, parse_count};
use crate::point::{common_dimension, Point};
use crate::scalar::{format_exact, parse_exact, Scalar};
use num_rational::BigRational;
use serde_json::Value;

/// An exact number from JSON: a string in the text syntax, or a JSON number taken as
/// exactly the `f64` it parses to (64-bit integer literals exactly).
///
/// ```
/// use casteljau::oracle::number_from_json;
/// use serde_json::json;
/// assert_eq!(number_from_json(&json!("1/3")).unwrap().to_string(), "1/3");
/// assert_eq!(number_from_json(&json!(0.5)).unwrap().to_string(), "1/2");
/// assert_eq!(number_from_json(&json!(0.1)).unwrap().to_string(), "3602879701896397/36028797018963968");
/// assert!(number_from_json(&json!("abc")).is_err());
/// ```
pub fn number_from_json(v: &Value) -> Result<BigRational> {
    match v {
        Value::String(s) => parse_exact(s),
        Value::Number(n) => json_number(n),
        other => Err(Error::Parse(format!(
            "expected a number (a JSON number or a string like \"1/3\"), got {}",
            describe(other)
        ))),
    }
}

/// A JSON number exactly: an integer as itself, any other number as exactly the f64 it
/// denotes.
pub fn json_number(n: &serde_json::Number) -> Result<BigRational> {
    if let Some(i) = n.as_i64() {
        Ok(BigRational::from_integer(i.into()))
    } else if let Some(u) = n.as_u64() {
        Ok(BigRational::from_integer(u.into()))
    } else {
        let x = n
            .as_f64()
            .ok_or_else(|| Error::Parse(format!("the JSON number {n} is not representable")))?;
        <BigRational as Scalar>::from_f64(x)
    }
}

/// A non-negative integer from JSON: a JSON integer or a string of digits.
pub fn count_from_json(v: &Value, what: &str) -> Result<usize> {
    match v {
        Value::Number(n) => match n.as_u64() {
            Some(u) => usize::try_from(u).map_err(|_| Error::TooLarge {
                what: "count",
                value: u.to_string(),
                limit: usize::MAX.to_string(),
            }),
            None => Err(Error::Parse(format!("{what} must be a non-negative integer, got {n}"))),
        },
        Value::String(s) => parse_count(s, what),
        other => Err(Error::Parse(format!(
            "{what} must be a non-negative integer, got {}",
            describe(other)
        ))),
    }
}

/// A point from a JSON array of numbers.
pub fn point_from_json(v: &Value) -> Result<Point<BigRational>> {
    let coords = v.as_array().ok_or_else(|| {
        Error::Parse(format!(
            "expected a point (an array of coordinates), got {}",
            describe(v)
        ))
    })?;
    if coords.len() > MAX_DIMENSION {
        return Err(Error::TooLarge {
            what: "dimension",
            value: coords.len().to_string(),
            limit: MAX_DIMENSION.to_string(),
        });
    }
    let coords = coords
        .iter()
        .enumerate()
        .map(|(k, c)| number_from_json(c).map_err(|e| in_context(&format!("coordinate {k}"), e)))
        .collect::<Result<Vec<_>>>()?;
    Point::new(coords)
}

/// Points from a JSON array of points, all of one dimension; at most `max` of them.
pub fn points_from_json(v: &Value, max: usize) -> Result<Vec<Point<BigRational>>> {
    let items = v.as_array().ok_or_else(|| {
        Error::Parse(format!(
            "expected an array of points (arrays of coordinates), got {}",
            describe(v)
        ))
    })?;
    if items.is_empty() {
        return Err(Error::Empty("a list of points"));
    }
    if items.len() > max {
        return Err(Error::TooLarge {
            what: "number of points",
            value: items.len().to_string(),
            limit: max.to_string(),
        });
    }
    let points = items
        .iter()
        .enumerate()
        .map(|(i, p)| point_from_json(p).map_err(|e| in_context(&format!("point {i}"), e)))
        .collect::<Result<Vec<_>>>()?;
    common_dimension(&points, "the list of points")?;
    Ok(points)
}

/// A rectangular control net from JSON: an array of rows, each an array of points; at most
/// `max` points per row and `max` rows.
pub fn net_from_json(v: &Value, max: usize) -> Result<Vec<Vec<Point<BigRational>>>> {
    let rows = v.as_array().ok_or_else(|| {
        Error::Parse(format!(
            "expected a net (an array of rows of points), got {}",
            describe(v)
        ))
    })?;
    if rows.len() > max {
        return Err(Error::TooLarge {
            what: "number of net rows",
            value: rows.len().to_string(),
            limit: max.to_string(),
        });
    }
    let rows = rows
        .iter()
        .enumerate()
        .map(|(i, r)| points_from_json(r, max).map_err(|e| in_context(&format!("row {i}"), e)))
        .collect::<Result<Vec<_>>>()?;
    check_net(&rows)?;
    Ok(rows)
}

/// Numbers from a JSON array.
pub fn numbers_from_json(v: &Value, max: usize) -> Result<Vec<BigRational>> {
    let items = v
        .as_array()
        .ok_or_else(|| Error::Parse(format!("expected an array of numbers, got {}", describe(v))))?;
    if items.len() > max {
        return Err(Error::TooLarge {
            what: "number of values",
            value: items.len().to_string(),
            limit: max.to_string(),
        });
    }
    items
        .iter()
        .enumerate()
        .map(|(i, c)| number_from_json(c).map_err(|e| in_context(&format!("number {i}"), e)))
        .collect()
}

/// A short description of a JSON value's type for error messages.
pub fn describe(v: &Value) -> String {
    match v {
        Value::Null => "null".into(),
        Value::Bool(b) => format!("the boolean {b}"),
        Value::Number(n) => format!("the number {n}"),
        Value::String(s) if s.chars().count() > 40 => format!("a string of {} characters", s.chars().count()),
        Value::String(s) => format!("the string {s:?}"),
        Value::Array(a) => format!("an array of {} items", a.len()),
        Value::Object(_) => "an object".into(),
    }
}

/// An exact number as JSON: a string in lowest terms, `"p/q"` or `"p"`.
pub fn number_to_json(r: &BigRational) -> Value {
    Value::String(format_exact(r))
}

/// A point as a JSON array of exact strings.
pub fn point_to_json(p: &Point<BigRational>) -> Value {
    Value::Array(p.coords().iter().map(number_to_json).collect())
}

/// Points as a JSON array of points.
pub fn points_to_json(points: &[Point<BigRational>]) -> Value {
    Value::Array(points.iter().map(point_to_json).collect())
}

/// An error for a size beyond its limit.
pub(super) fn too_large(what: &'static str, value: usize, limit: usize) -> crate::error::Error {
    crate::error::Error::TooLarge {
        what,
        value: value.to_string(),
        limit: limit.to_string(),
    }
}

/// A name from a request, cut to 40 characters for an error message.
pub(super) fn truncate(s: &str) -> String {
    if s.chars().count() > 40 {
        format!("{}…", s.chars().take(40).collect::<String>())
    } else {
        s.to_string()
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use serde_json::json;

    fn q(p: i64, d: i64) -> BigRational {
        BigRational::new(p.into(), d.into())
    }

    #[test]
    fn json_numbers_are_exact() {
        assert_eq!(number_from_json(&json!("-4/6")).unwrap(), q(-2, 3));
        assert_eq!(number_from_json(&json!("1e-3")).unwrap(), q(1, 1000));
        assert_eq!(number_from_json(&json!(-7)).unwrap(), q(-7, 1));
        assert_eq!(
            number_from_json(&json!(u64::MAX)).unwrap(),
            BigRational::from_integer(u64::MAX.into())
        );
        assert_eq!(number_from_json(&json!(0.375)).unwrap(), q(3, 8));
        let tenth = number_from_json(&json!(0.1)).unwrap();
        assert_eq!(tenth, <BigRational as Scalar>::from_f64(0.1).unwrap());
        assert_ne!(tenth, q(1, 10));
        for bad in [
            json!("1/0"),
            json!("abc"),
            json!("1e999999999"),
            json!(null),
            json!([1]),
            json!(true),
        ] {
            assert!(number_from_json(&bad).is_err(), "{bad}");
        }
    }

    #[test]
    fn json_structures_are_checked() {
        let pts = points_from_json(&json!([[0, 0], ["1/2", 1.5]]), 10).unwrap();
        assert_eq!(pts[1].coords(), &[q(1, 2), q(3, 2)]);
        let err = |v: Value| points_from_json(&v, 3).unwrap_err().to_string();
        assert!(err(json!([])).contains("empty"));
        assert!(err(json!([[0, 0], [1]])).contains("dimension mismatch"));
        assert!(err(json!([[]])).contains("at least one coordinate"));
        assert!(err(json!([[0], [1], [2], [3]])).contains("too large"));
        assert!(err(json!("0,0")).contains("array of points"));
        assert!(err(json!([[0, "x"]])).contains("point 0: coordinate 1"));
        let net = net_from_json(&json!([[[0, 0, 0], [1, 0, 1]], [[0, 1, 1], [1, 1, 0]]]), 10).unwrap();
        assert_eq!(net.len(), 2);
        assert!(net_from_json(&json!([[[0, 0]], [[0, 1], [1, 1]]]), 10)
            .unwrap_err()
            .to_string()
            .contains("ragged"));
        assert!(net_from_json(&json!([]), 10).is_err());
        assert_eq!(count_from_json(&json!(3), "by").unwrap(), 3);
        assert_eq!(count_from_json(&json!("3"), "by").unwrap(), 3);
        assert!(count_from_json(&json!(-3), "by").is_err());
        assert!(count_from_json(&json!(1.5), "by").is_err());
    }

    #[test]
    fn exact_results_are_strings_in_lowest_terms() {
        assert_eq!(number_to_json(&q(6, -4)), json!("-3/2"));
        assert_eq!(number_to_json(&q(4, 2)), json!("2"));
        let p = Point::new(vec![q(0, 1), q(-1, 3)]).unwrap();
        assert_eq!(points_to_json(&[p]), json!([["0", "-1/3"]]));
    }
}
