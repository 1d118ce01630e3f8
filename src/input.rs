//! Reading exact geometry from text, and writing exact points back as text.
//!
//! The `casteljau` command, its figures and the JSON-lines oracle share these readers, so a
//! number, point or net means the same thing everywhere.
//!
//! The syntax is described on [`parse_points`].
//!
//! The JSON forms of the same numbers, points and nets are the oracle's
//! (`casteljau::oracle::number_from_json` and its neighbours).

use crate::error::{Error, Result, MAX_DIMENSION};
use crate::point::{common_dimension, Point};
use crate::scalar::parse_exact;
use num_rational::BigRational;

/// Wraps an error with the place in the input where it happened.
pub fn in_context(ctx: &str, e: Error) -> Error {
    match e {
        Error::Parse(m) => Error::Parse(format!("{ctx}: {m}")),
        other => Error::Parse(format!("{ctx}: {other}")),
    }
}

/// Parses one exact number (see [`parse_exact`]; the whole syntax is on [`parse_points`]).
///
/// ```
/// use casteljau::parse_number;
/// assert_eq!(parse_number("-4/6").unwrap().to_string(), "-2/3");
/// assert!(parse_number("1/0").is_err());
/// ```
pub fn parse_number(text: &str) -> Result<BigRational> {
    parse_exact(text)
}

/// Parses a non-negative integer count such as an elevation `r` or a derivative order.
pub fn parse_count(text: &str, what: &str) -> Result<usize> {
    let s = text.trim();
    if s.is_empty() || !s.bytes().all(|b| b.is_ascii_digit()) {
        return Err(Error::Parse(format!(
            "{what} must be a non-negative integer, got '{text}'"
        )));
    }
    s.parse::<usize>().map_err(|_| Error::TooLarge {
        what: "count",
        value: s.to_string(),
        limit: usize::MAX.to_string(),
    })
}

/// Parses one point: coordinates separated by `,`, optionally in parentheses.
///
/// ```
/// use casteljau::parse_point;
/// let p = parse_point("(4/3, -0.5)").unwrap();
/// assert_eq!(p.to_string(), "(4/3, -1/2)");
/// ```
pub fn parse_point(text: &str) -> Result<Point<BigRational>> {
    let s = text.trim();
    let inner = match (s.strip_prefix('('), s.ends_with(')')) {
        (Some(rest), true) => &rest[..rest.len() - 1],
        (None, false) => s,
        _ => return Err(Error::Parse(format!("unbalanced parentheses in point '{s}'"))),
    };
    if inner.trim().is_empty() {
        return Err(Error::Parse(
            "empty point (write its coordinates separated by ',')".into(),
        ));
    }
    let parts: Vec<&str> = inner.split(',').collect();
    if parts.len() > MAX_DIMENSION {
        return Err(Error::TooLarge {
            what: "dimension",
            value: parts.len().to_string(),
            limit: MAX_DIMENSION.to_string(),
        });
    }
    let coords = parts
        .iter()
        .enumerate()
        .map(|(k, c)| parse_exact(c).map_err(|e| in_context(&format!("coordinate {k}"), e)))
        .collect::<Result<Vec<_>>>()?;
    Point::new(coords)
}

/// Parses points separated by `;`, all of one dimension.
///
/// # Text syntax (command line, figures)
///
/// | what      | syntax                                   | example                              |
/// |-----------|------------------------------------------|--------------------------------------|
/// | number    | integer, `p/q`, decimal, exponent        | `-3`, `4/3`, `0.25`, `1e-3`          |
/// | point     | coordinates separated by `,`, optional `( )` | `4/3,-4/3` or `(4/3, -4/3)`      |
/// | points    | points separated by `;`                  | `0,0; 4/3,-4/3; 4/3,4/3; 0,0`        |
/// | net       | rows separated by `\|`, each row points  | `0,0,0; 1,0,1 \| 0,1,1; 1,1,0`       |
/// | numbers   | numbers separated by `,` (or `;`)        | `1, 1/2, 1`                          |
///
/// Whitespace around any item is ignored. Every number is exact (see
/// [`parse_exact`]): `0.1` is `1/10`. A net row `i` holds the points `b_{i0}, …, b_{in}`;
/// rows are `i = 0..m`. Printed points (`(4/3, -4/3); (0, 0)`) are valid input again.
///
/// ```
/// use casteljau::parse_points;
/// let pts = parse_points("0,0; 4/3,-4/3; 4/3,4/3; 0,0").unwrap();
/// assert_eq!(pts.len(), 4);
/// assert!(parse_points("0,0; 1").is_err()); // mixed dimensions
/// ```
pub fn parse_points(text: &str) -> Result<Vec<Point<BigRational>>> {
    if text.trim().is_empty() {
        return Err(Error::Empty("a list of points"));
    }
    let points = text
        .split(';')
        .enumerate()
        .map(|(i, p)| parse_point(p).map_err(|e| in_context(&format!("point {i}"), e)))
        .collect::<Result<Vec<_>>>()?;
    common_dimension(&points, "the list of points")?;
    Ok(points)
}

/// Parses a control net: rows separated by `|`, each row points separated by `;`.
/// All rows must have the same number of points, all points the same dimension.
///
/// ```
/// use casteljau::parse_net;
/// let net = parse_net("0,0,0; 1,0,1 | 0,1,1; 1,1,0").unwrap();
/// assert_eq!((net.len(), net[0].len()), (2, 2));
/// assert!(parse_net("0,0; 1,0 | 0,1").is_err()); // ragged
/// ```
pub fn parse_net(text: &str) -> Result<Vec<Vec<Point<BigRational>>>> {
    let rows = text
        .split('|')
        .enumerate()
        .map(|(i, r)| parse_points(r).map_err(|e| in_context(&format!("row {i}"), e)))
        .collect::<Result<Vec<_>>>()?;
    check_net(&rows)?;
    Ok(rows)
}

/// Parses numbers separated by `,` or `;` (for example weights `1, 1/2, 1`).
pub fn parse_numbers(text: &str) -> Result<Vec<BigRational>> {
    if text.trim().is_empty() {
        return Err(Error::Empty("a list of numbers"));
    }
    text.split([',', ';'])
        .enumerate()
        .map(|(i, c)| parse_exact(c).map_err(|e| in_context(&format!("number {i}"), e)))
        .collect()
}

/// Checks that a net is rectangular (every row as long as the first) and of one dimension.
pub fn check_net(rows: &[Vec<Point<BigRational>>]) -> Result<()> {
    let first = rows.first().ok_or(Error::Empty("a control net"))?;
    let cols = first.len();
    if cols == 0 {
        return Err(Error::Empty("a control net row"));
    }
    for (i, row) in rows.iter().enumerate() {
        if row.len() != cols {
            return Err(Error::Parse(format!(
                "ragged net: row 0 has {cols} points but row {i} has {}",
                row.len()
            )));
        }
    }
    let all: Vec<Point<BigRational>> = rows.iter().flatten().cloned().collect();
    common_dimension(&all, "a control net")?;
    Ok(())
}

/// Points as text that [`parse_points`] reads back: `(0, 0); (4/3, -4/3)`.
pub fn format_points(points: &[Point<BigRational>]) -> String {
    crate::point::PointList(points).to_string()
}

#[cfg(test)]
mod tests {
    use super::*;

    fn q(p: i64, d: i64) -> BigRational {
        BigRational::new(p.into(), d.into())
    }

    #[test]
    fn parses_the_text_syntax() {
        let pts = parse_points(" 0,0; 4/3,-4/3 ;(4/3, 4/3); 0 , 0 ").unwrap();
        assert_eq!(pts.len(), 4);
        assert_eq!(pts[1].coords(), &[q(4, 3), q(-4, 3)]);
        assert_eq!(pts[2].coords(), &[q(4, 3), q(4, 3)]);
        let w = parse_numbers("1, 1/2, 1").unwrap();
        assert_eq!(w, vec![q(1, 1), q(1, 2), q(1, 1)]);
        let net = parse_net("0,0,0; 1,0,1; 2,0,0 | 0,1,1; 1,1,0; 2,1,1").unwrap();
        assert_eq!(net.len(), 2);
        assert_eq!(net[1][2].coords(), &[q(2, 1), q(1, 1), q(1, 1)]);
        assert_eq!(parse_count(" 12 ", "r").unwrap(), 12);
    }

    #[test]
    fn printed_points_parse_back() {
        let pts = parse_points("1/3,-2; 0.5,7").unwrap();
        let text = format_points(&pts);
        assert_eq!(text, "(1/3, -2); (1/2, 7)");
        assert_eq!(parse_points(&text).unwrap(), pts);
    }

    #[test]
    fn text_errors_say_where() {
        let msg = |s: &str| parse_points(s).unwrap_err().to_string();
        assert!(
            msg("0,0; 1,abc").contains("point 1: coordinate 1"),
            "{}",
            msg("0,0; 1,abc")
        );
        assert!(msg("0,0; 1/0,1").contains("zero denominator"));
        assert!(msg("0,0; 1,2,3").contains("dimension mismatch"));
        assert!(msg("0,0;;1,1").contains("point 1: empty point"));
        assert!(msg("").contains("empty"));
        assert!(msg("(0,0").contains("parentheses"));
        assert!(parse_net("0,0 | 1,1; 2,2").unwrap_err().to_string().contains("ragged"));
        assert!(parse_net("0,0 | ").unwrap_err().to_string().contains("row 1"));
        assert!(parse_count("-1", "r").is_err());
        assert!(parse_count("99999999999999999999999", "r").is_err());
        assert!(parse_numbers("1,,2").is_err());
    }
}
