//! The de Casteljau scheme (9) of one parameter, as the text prints it and as LaTeX.

use crate::point::Point;
use crate::scalar::Scalar;
use std::fmt;

/// The triangular de Casteljau scheme (9) at one parameter: `column(r)[i] = b_i^r(t)`.
#[derive(Clone, Debug, PartialEq)]
pub struct DeCasteljauScheme<T> {
    /// The parameter.
    pub t: T,
    /// `columns[r][i] = b_i^r(t)`, `r = 0..=n`, `i = 0..=n-r`.
    pub columns: Vec<Vec<Point<T>>>,
}

impl<T: Scalar> DeCasteljauScheme<T> {
    /// The degree of the curve.
    pub fn degree(&self) -> usize {
        self.columns.len() - 1
    }

    /// `b_i^r(t)`.
    pub fn get(&self, r: usize, i: usize) -> Option<&Point<T>> {
        self.columns.get(r)?.get(i)
    }

    /// The point of the curve, `b_0^n(t)`.
    pub fn point(&self) -> &Point<T> {
        &self.columns[self.degree()][0]
    }
}

impl<T: Scalar + fmt::Display> DeCasteljauScheme<T> {
    /// The triangle (9) as a LaTeX `array` (math mode), row `k` holding `b_k, …, b_0^k(t)`;
    /// fractions as `\frac`, a one-coordinate point as its number.
    pub fn to_latex(&self) -> String {
        let n = self.columns.len() - 1;
        let num = |x: &T| {
            let s = x.to_string();
            match s.split_once('/') {
                Some((a, b)) => match a.strip_prefix('-') {
                    Some(a) => format!("-\\frac{{{a}}}{{{b}}}"),
                    None => format!("\\frac{{{a}}}{{{b}}}"),
                },
                None => s,
            }
        };
        let mut out = format!(
            "\\[ t = {} \\]\n\\[\\begin{{array}}{{{}}}\n",
            num(&self.t),
            "l".repeat(n + 1)
        );
        for k in 0..=n {
            let mut cells = Vec::new();
            for r in 0..=k {
                let i = k - r;
                let label = if r == 0 {
                    format!("b_{{{i}}}")
                } else {
                    format!("b_{{{i}}}^{{{r}}}")
                };
                let p = &self.columns[r][i];
                let coords: Vec<String> = p.coords().iter().map(num).collect();
                let value = if coords.len() == 1 {
                    coords[0].clone()
                } else {
                    format!("\\left({}\\right)", coords.join(", "))
                };
                cells.push(format!("{label} = {value}"));
            }
            out.push_str(&format!("{} \\\\\n", cells.join(" & ")));
        }
        out.push_str("\\end{array}\\]\n");
        out
    }
}

/// Prints the scheme as the text's triangle (9): row `k` holds `b_k, b_{k-1}^1(t), …, b_0^k(t)`.
impl<T: fmt::Display> fmt::Display for DeCasteljauScheme<T> {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let n = self.columns.len() - 1;
        writeln!(f, "de Casteljau scheme (9) at t = {}", self.t)?;
        for k in 0..=n {
            let mut cells = Vec::new();
            for r in 0..=k {
                let i = k - r;
                let label = if r == 0 { format!("b_{i}") } else { format!("b_{i}^{r}") };
                cells.push(format!("{label} = {}", self.columns[r][i]));
            }
            writeln!(f, "  {}", cells.join("   "))?;
        }
        Ok(())
    }
}
