//! A priori bounds for the float algorithms of the operations other than evaluation:
//! subdivision (de Casteljau's triangle, convex or lerp form), degree elevation, the
//! derivative's control points by differences, and the power-to-Bézier conversion.
//!
//! Each function returns, per output coefficient, a [`OpBound`]: the absolute bound on the
//! named algorithm's error for these float inputs (exact: the inputs are the floats given)
//! and the sum of absolute values `S` it is `γ_k` times (the condition numerator). The
//! derivations are in `docs/float-bounds.md`; `tests/float_ops.rs` checks every bound on the
//! 10,000 edge cases of `tests/float_edges.rs` against a plain float implementation of each
//! algorithm.

use super::casteljau::{
    a_priori_index, abs_factors, abs_sum_rounded_up, add_up, gamma, level_growth, mul_up, next_up, underflow_term, ETA,
};
use super::eft::two_sum;
use super::methods::binomials;

/// One output coefficient's a priori bound.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct OpBound {
    /// `|computed − exact| ≤ bound` (an `f64` at least the exact bound; `+∞` when none).
    pub bound: f64,
    /// The sum of absolute values `S` the bound is `γ_k` times (at least the exact sum).
    pub sum: f64,
}

/// The float algorithm of a subdivision: de Casteljau's triangle in one of its forms.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum SplitForm {
    /// `fl(fl(s·a) + fl(t·b))`, `s = fl(1 − t)` (bounded as [`super::a_priori_bound`]).
    Convex,
    /// `fl(a + fl(t·fl(b − a)))` (bounded as [`super::lerp_bound`]).
    Lerp,
}

/// The bounds of a float subdivision at `t` of one coordinate's coefficients `b`: `(left,
/// right)`, `n + 1` each. The left half's point `j` is the triangle's node at level `j`
/// over `b_0..b_j`, the right half's point `k` the node at level `n − k` over `b_k..b_n`:
/// each is a de Casteljau evaluation of that sub-curve, so its bound is the evaluation
/// bound of the sub-curve, bit for bit. One triangle on `|b_i|` gives all the sums.
pub fn split_bounds(b: &[f64], t: f64, form: SplitForm) -> (Vec<OpBound>, Vec<OpBound>) {
    let n = b.len() - 1;
    let mut buf: Vec<f64> = b.iter().map(|x| x.abs()).collect();
    let mut left = vec![0.0; n + 1];
    let mut right = vec![0.0; n + 1];
    left[0] = buf[0];
    right[n] = buf[n];
    let (s_abs, t_abs) = abs_factors(t);
    let (wa, wb) = match form {
        SplitForm::Convex => (s_abs, t_abs),
        SplitForm::Lerp => {
            let (s, rho) = two_sum(1.0, -t);
            (add_up(add_up(s.abs(), rho.abs()), t.abs()), t.abs())
        }
    };
    for r in 1..=n {
        let len = n - r + 1;
        match form {
            // the very triangle of `abs_bernstein_sum`, one level at a time
            SplitForm::Convex => {
                for i in 0..len {
                    buf[i] = s_abs * buf[i] + t_abs * buf[i + 1];
                }
            }
            SplitForm::Lerp => {
                for i in 0..len {
                    buf[i] = add_up(mul_up(wa, buf[i]), mul_up(wb, buf[i + 1]));
                }
            }
        }
        left[r] = buf[0];
        right[n - r] = buf[n - r];
    }
    let bound = |j: usize, node: f64| -> OpBound {
        if j == 0 {
            return OpBound { bound: 0.0, sum: node };
        }
        match form {
            SplitForm::Convex => {
                let sum = abs_sum_rounded_up(node, j, s_abs, t_abs);
                OpBound {
                    bound: add_up(
                        mul_up(gamma(a_priori_index(j, t)), sum),
                        underflow_term(j, 1.0, level_growth(t)),
                    ),
                    sum,
                }
            }
            SplitForm::Lerp => OpBound {
                bound: add_up(mul_up(gamma(4 * j), node), underflow_term(j, 1.0, add_up(wa, wb))),
                sum: node,
            },
        }
    };
    let left = left.iter().enumerate().map(|(j, s)| bound(j, *s)).collect();
    let right = right.iter().enumerate().map(|(k, s)| bound(n - k, *s)).collect();
    (left, right)
}

/// The bounds of elevating the degree of `b` by `by`, one step at a time, each step
/// `c_i = α_i b_{i−1} + β_i b_i` (`α_i = i/(m+1)`, `β_i = (m+1−i)/(m+1)`, `m` the degree
/// before the step, `c_0 = b_0`, `c_{m+1} = b_m` copied) computed as
/// `fl(fl(α̂_i·b_{i−1}) + fl(β̂_i·b_i))` with `α̂_i`, `β̂_i` the rounded quotients, or as
/// `fl(fl(fl(i·b_{i−1}) + fl((m+1−i)·b_i)) / (m+1))`: three roundings per path and step,
/// `γ_{3r} Σ_j E_ij |b_j| + r·2^−1074·(1 + 10^−9)`, `E` the elevation matrix.
pub fn elevate_bounds(b: &[f64], by: usize) -> Vec<OpBound> {
    let mut sums: Vec<f64> = b.iter().map(|x| x.abs()).collect();
    for _ in 0..by {
        let m = sums.len() - 1;
        let mut next = Vec::with_capacity(m + 2);
        next.push(sums[0]);
        for i in 1..=m {
            // α, β rounded up: every step of the sum at least the exact one
            let alpha = next_up(i as f64 / (m + 1) as f64);
            let beta = next_up((m + 1 - i) as f64 / (m + 1) as f64);
            next.push(add_up(mul_up(alpha, sums[i - 1]), mul_up(beta, sums[i])));
        }
        next.push(sums[m]);
        sums = next;
    }
    let g = gamma(3 * by);
    let under = mul_up(next_up(by as f64 * (1.0 + 1e-9)), ETA);
    let last = sums.len() - 1;
    sums.iter()
        .enumerate()
        .map(|(i, s)| OpBound {
            bound: if i == 0 || i == last || by == 0 {
                0.0
            } else {
                add_up(mul_up(g, *s), under)
            },
            sum: *s,
        })
        .collect()
}

/// The bounds of the control points of the `order`-th derivative of `b` computed by
/// differences: `order` rounds of `d_i ← fl((m − l + 1)·fl(d_{i+1} − d_i))`, `m` the degree.
/// The first round errs relative to its own exact result (a difference of floats is rounded
/// once, and never underflows; neither does a product by a whole number), so the bound is
/// `γ_{2k} · (m−1)!/(m−k)! · Σ_j C(k−1, j) |m (b_{i+j+1} − b_{i+j})|`.
pub fn derivative_bounds(b: &[f64], order: usize) -> Vec<OpBound> {
    let m = b.len() - 1;
    if order == 0 {
        return b
            .iter()
            .map(|x| OpBound {
                bound: 0.0,
                sum: x.abs(),
            })
            .collect();
    }
    if order > m {
        return Vec::new();
    }
    // |b_{j+1} − b_j| is within half an ulp of the rounded difference: next_up covers it
    let mut sums: Vec<f64> = b
        .windows(2)
        .map(|w| mul_up(m as f64, next_up((w[1] - w[0]).abs())))
        .collect();
    for l in 2..=order {
        let factor = (m - l + 1) as f64;
        for i in 0..sums.len() - 1 {
            sums[i] = mul_up(factor, add_up(sums[i], sums[i + 1]));
        }
        sums.pop();
    }
    let g = gamma(2 * order);
    sums.iter()
        .map(|s| OpBound {
            bound: mul_up(g, *s),
            sum: *s,
        })
        .collect()
}

/// Highest degree whose power-to-Bézier weights stay normal floats (`1/C(n, j) ≥ 2^−1000`).
pub const TO_BEZIER_MAX_DEGREE: usize = 1000;

/// The bounds of converting power-basis coefficients (per coordinate `coords[k]`, the
/// coefficients of `t^0..t^n`) to Bézier points by `b_i = Σ_{j ≤ i} fl(w_ij · a_j)` summed
/// in any order, `w_ij = fl(Ĉ(i, j)/Ĉ(n, j))` with `Ĉ` the correctly rounded binomials
/// ([`binomials`]): `γ_{i+4} Σ_j w_ij |a_j| + (i + 1)·2^−1075·(1 + 10^−9)`, per coordinate.
/// `+∞` above [`TO_BEZIER_MAX_DEGREE`] (the weights would leave the normal range).
pub fn to_bezier_bounds(coords: &[Vec<f64>]) -> Vec<Vec<OpBound>> {
    let n = coords.first().map_or(0, |a| a.len().saturating_sub(1));
    if n > TO_BEZIER_MAX_DEGREE {
        let none = OpBound {
            bound: f64::INFINITY,
            sum: f64::INFINITY,
        };
        return coords.iter().map(|_| vec![none; n + 1]).collect();
    }
    let cn = binomials(n);
    // ŵ = w(1 + θ₃), so w ≤ ŵ(1 + 2γ₃) ≤ ŵ(1 + 4γ₃) rounded
    let widen = 1.0 + 4.0 * gamma(3);
    let mut out: Vec<Vec<OpBound>> = coords.iter().map(|_| Vec::with_capacity(n + 1)).collect();
    for i in 0..=n {
        let ci = binomials(i);
        let w: Vec<f64> = (0..=i).map(|j| mul_up(ci[j] / cn[j], widen)).collect();
        let under = mul_up(next_up((i + 1) as f64 * 0.5 * (1.0 + 1e-9)), ETA);
        for (a, out) in coords.iter().zip(out.iter_mut()) {
            let sum = w.iter().zip(a).fold(0.0, |s, (w, a)| add_up(s, mul_up(*w, a.abs())));
            out.push(OpBound {
                bound: add_up(mul_up(gamma(i + 4), sum), under),
                sum,
            });
        }
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::float::{a_priori_bound, lerp_bound};

    #[test]
    fn split_bounds_are_the_evaluation_bounds_of_the_sub_curves_bit_for_bit() {
        let b = [0.1, -3.5, 2e-300, 7.25, -1e10, 5e-324, 0.3];
        let n = b.len() - 1;
        for t in [0.0, 0.1, 0.5, 0.7, 1.0, 1e-300, 1.0 / 3.0] {
            let (l, r) = split_bounds(&b, t, SplitForm::Convex);
            let (ll, lr) = split_bounds(&b, t, SplitForm::Lerp);
            for j in 0..=n {
                assert_eq!(l[j].bound, a_priori_bound(&b[..=j], t), "left {j} at {t}");
                assert_eq!(r[j].bound, a_priori_bound(&b[j..], t), "right {j} at {t}");
                assert_eq!(ll[j].bound, lerp_bound(&b[..=j], t), "lerp left {j} at {t}");
                assert_eq!(lr[j].bound, lerp_bound(&b[j..], t), "lerp right {j} at {t}");
            }
        }
    }

    #[test]
    fn copied_points_have_no_error_and_the_others_some_bound() {
        let e = elevate_bounds(&[1.0, -2.0, 3.0], 2);
        assert_eq!(e.len(), 5);
        assert_eq!((e[0].bound, e[4].bound), (0.0, 0.0));
        assert!(e[2].bound > 0.0 && e[2].bound < 1e-14, "{e:?}");
        let d = derivative_bounds(&[1.0, -2.0, 3.0], 1);
        assert_eq!(d.len(), 2);
        // the differences are exact: γ₂·|2·(−3)|
        assert!(
            d[0].bound >= 6.0 * 2.0 * 1.1e-16 && d[0].bound < 6.0 * 2.0 * 1.2e-16,
            "{d:?}"
        );
        assert!(derivative_bounds(&[1.0], 2).is_empty());
        let p = to_bezier_bounds(&[vec![1.0, 2.0, 3.0]]).remove(0);
        assert_eq!(p.len(), 3);
        assert!(p[2].sum >= 6.0, "{p:?}");
    }
}
