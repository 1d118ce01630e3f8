//! Answers as text for people (the command line).

use super::Answer;
use crate::input::format_points;
use num_bigint::BigInt;
use num_traits::Signed;

impl Answer {
    /// The answer as text for people, in exact fractions; lists of points are written so
    /// that [`crate::parse_points`] reads them back.
    pub fn to_text(&self) -> String {
        match self {
            Answer::Point { point, .. } | Answer::JudgedPoint { point, .. } => point.to_string(),
            Answer::FloatEval(f) => {
                let list = |items: Vec<String>| items.join(", ");
                let mut text = format!(
                    "method: {}\nvalue: {}\nexact: {}\nulps: {}\nerror_ulps: {}\nbound_ulps: {}\nwithin_bound: {}",
                    f.method.as_str(),
                    list(f.values.iter().map(|v| format!("{v:?}")).collect()),
                    f.point,
                    list(f.errors.iter().map(|e| e.ulps.to_string()).collect()),
                    list(f.errors.iter().map(|e| format!("{:?}", e.error_ulps)).collect()),
                    list(f.bound.iter().map(|b| format!("{:?}", b.bound_ulps)).collect()),
                    list(f.bound.iter().map(|b| b.within.to_string()).collect()),
                );
                if let Some(r) = &f.running {
                    text.push_str(&format!(
                        "\nrunning_bound_ulps: {}",
                        list(r.iter().map(|b| format!("{:?}", b.bound_ulps)).collect())
                    ));
                }
                if let Some(e) = &f.enclosure {
                    text.push_str(&format!(
                        "\ninterval: {}",
                        list(e.iter().map(|(lo, hi, _)| format!("[{lo:?}, {hi:?}]")).collect())
                    ));
                }
                text
            }
            Answer::Points(p) => format_points(p),
            Answer::Judged(j) => j.exact.to_text(),
            Answer::Results(r) => r.iter().map(Answer::to_text).collect::<Vec<_>>().join("\n"),
            Answer::Vector(v) => v.to_string(),
            Answer::Split { left, right } => {
                format!("left:  {}\nright: {}", format_points(left), format_points(right))
            }
            Answer::Conic { kind, implicit } => match implicit {
                Some(k) => format!("type: {}\nimplicit: {} = 0", kind.as_str(), conic_polynomial(k)),
                None => format!(
                    "type: {}\nimplicit: none (no unique conic through collinear points)",
                    kind.as_str()
                ),
            },
            Answer::Fit(fit) => {
                let mut text = format!(
                    "k = {}\nl = {}\npoints: {}\ndelta2 = {}",
                    fit.k,
                    fit.l,
                    format_points(fit.curve.points()),
                    fit.delta2
                );
                for w in &fit.warnings {
                    text.push_str(&format!("\nwarning: {w}"));
                }
                text
            }
        }
    }
}

/// `A x^2 + B xy + C y^2 + D x + E y + F` with zero terms left out and signs folded in,
/// e.g. `4x^2 + 3y^2 - 10y + 3`.
pub fn conic_polynomial(k: &[BigInt; 6]) -> String {
    const MONOMIALS: [&str; 6] = ["x^2", "xy", "y^2", "x", "y", ""];
    let mut out = String::new();
    for (c, mono) in k.iter().zip(MONOMIALS) {
        if num_traits::Zero::is_zero(c) {
            continue;
        }
        let negative = c.is_negative();
        let magnitude = c.abs();
        let digits = if num_traits::One::is_one(&magnitude) && !mono.is_empty() {
            String::new()
        } else {
            magnitude.to_string()
        };
        match (out.is_empty(), negative) {
            (true, true) => out.push('-'),
            (true, false) => {}
            (false, true) => out.push_str(" - "),
            (false, false) => out.push_str(" + "),
        }
        out.push_str(&digits);
        out.push_str(mono);
    }
    if out.is_empty() {
        out.push('0');
    }
    out
}
