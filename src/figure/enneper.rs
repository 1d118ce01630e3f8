//! Enneper's surface as a bicubic net (text 003, Example 5).

use super::net::draw_net;
use super::svg::Figure;
use crate::error::Result;
use crate::point::AffineMap;
use crate::scalar::Scalar;
use crate::surface::{enneper_net, BezierSurface};

/// The net of text 003 Ex. 5, computed by the library: `3 · E` on `[−2, 2]²`, i.e.
/// `3 · enneper_net(2)` (the 16 printed points).
pub fn text003_example5<T: Scalar>() -> Result<BezierSurface<T>> {
    enneper_net(&T::from_i64(2))?.transform(&AffineMap::scaling(3, &T::from_i64(3)))
}

/// The figure of an Enneper net: [`super::net()`] with three iso-curves each way shaded by
/// depth (the surface folds over itself, and depth tells its sheets apart), noting whether
/// the net is exactly text 003's Example 5.
pub fn enneper<T: Scalar>(surface: &BezierSurface<T>) -> Result<Figure> {
    let mut fig = draw_net(surface, 3, "Enneper's surface from a bicubic net", true)?;
    let example = text003_example5::<T>()?;
    if *surface == example {
        fig.note(None, "this net is exactly 3 · E(4s − 2, 4t − 2) with E(u, v) = (u − u³/3 + uv², v − v³/3 + vu², u² − v²): text 003 Ex. 5");
    }
    let matches = surface.enneper_matches().unwrap_or_default();
    for m in matches {
        fig.note(
            None,
            format!(
                "library match: x(s, t) = {} · E({}, {}){}",
                m.lambda,
                affine(&m.alpha, "s", &m.beta),
                affine(&m.gamma, "t", &m.delta),
                if m.swapped { " (parameters swapped)" } else { "" }
            ),
        );
    }
    Ok(fig)
}

/// `a·x + b` written as `4s − 2`.
fn affine<T: Scalar>(a: &T, x: &str, b: &T) -> String {
    if b.is_zero() {
        format!("{a}{x}")
    } else if *b < T::zero() {
        format!("{a}{x} − {}", b.neg_ref())
    } else {
        format!("{a}{x} + {b}")
    }
}
