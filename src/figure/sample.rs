//! Drawing samples: the exact control data rounded once to `f64`, then evaluated in `f64`.
//!
//! A drawn curve only needs pixels, and exact samples cost a whole exact de Casteljau
//! scheme each (seconds for a few hundred samples of a degree-64 curve). De Casteljau's
//! algorithm in `f64` takes convex combinations for `0 ≤ t ≤ 1`, so each sample is within a
//! few ulps (relative to the largest control coordinate, times the degree) of the exact
//! point of the rounded control data: many orders of magnitude below a pixel of a drawing a
//! few hundred pixels wide. Every value printed on a figure stays exact; only these
//! polylines are approximations.

/// `b(k/count)` for `k = 0..=count` of the curve with these (drawn, planar) control points.
pub(crate) fn polynomial(points: &[[f64; 2]], count: usize) -> Vec<[f64; 2]> {
    let weights = vec![1.0; points.len()];
    rational(points, &weights, count)
}

/// `Σ w_i b_i B_i(t) / Σ w_i B_i(t)` at `t = k/count` for `k = 0..=count`, by de Casteljau
/// on the homogeneous points `(w x, w y, w)`.
pub(crate) fn rational(points: &[[f64; 2]], weights: &[f64], count: usize) -> Vec<[f64; 2]> {
    let homogeneous: Vec<[f64; 3]> = points
        .iter()
        .zip(weights)
        .map(|(p, &w)| [w * p[0], w * p[1], w])
        .collect();
    let mut work = homogeneous.clone();
    (0..=count)
        .map(|k| {
            let t = k as f64 / count.max(1) as f64;
            work.copy_from_slice(&homogeneous);
            let [x, y, w] = reduce(&mut work, t);
            [x / w, y / w]
        })
        .collect()
}

/// The control points of the iso-curve at `s` of a drawn net: each column (`along_rows`:
/// each row) reduced at `s` by de Casteljau.
pub(crate) fn iso(net: &[Vec<[f64; 2]>], s: f64, along_rows: bool) -> Vec<[f64; 2]> {
    let lift = |p: &[f64; 2]| [p[0], p[1], 1.0];
    let mut out = Vec::new();
    if along_rows {
        for row in net {
            let mut work: Vec<[f64; 3]> = row.iter().map(lift).collect();
            let [x, y, _] = reduce(&mut work, s);
            out.push([x, y]);
        }
    } else {
        for j in 0..net.first().map_or(0, Vec::len) {
            let mut work: Vec<[f64; 3]> = net.iter().map(|row| lift(&row[j])).collect();
            let [x, y, _] = reduce(&mut work, s);
            out.push([x, y]);
        }
    }
    out
}

/// De Casteljau's algorithm in place: the point at `t` (the first entry at the end).
fn reduce(work: &mut [[f64; 3]], t: f64) -> [f64; 3] {
    let s = 1.0 - t;
    for r in 1..work.len() {
        for i in 0..work.len() - r {
            let (a, b) = (work[i], work[i + 1]);
            work[i] = [s * a[0] + t * b[0], s * a[1] + t * b[1], s * a[2] + t * b[2]];
        }
    }
    work[0]
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn samples_match_the_exact_curve_to_rounding() {
        // b(t) = (2t(1 − t)·2 + t², …) of the quadratic (0,0), (1,2), (2,0): x = 2t, y = 4t(1 − t)
        let pts = [[0.0, 0.0], [1.0, 2.0], [2.0, 0.0]];
        for (k, p) in polynomial(&pts, 8).iter().enumerate() {
            let t = k as f64 / 8.0;
            assert_eq!(*p, [2.0 * t, 4.0 * t * (1.0 - t)]);
        }
        // (1,0), (1,1), (0,1) with weights 1, 3, 2 at t = 1/2: (7/9, 8/9)
        let got = rational(&[[1.0, 0.0], [1.0, 1.0], [0.0, 1.0]], &[1.0, 3.0, 2.0], 2)[1];
        assert!(
            (got[0] - 7.0 / 9.0).abs() < 1e-15 && (got[1] - 8.0 / 9.0).abs() < 1e-15,
            "{got:?}"
        );
    }

    #[test]
    fn iso_curves_reduce_rows_or_columns() {
        let net = vec![vec![[0.0, 0.0], [1.0, 0.0]], vec![[0.0, 2.0], [1.0, 4.0]]];
        assert_eq!(iso(&net, 0.5, true), vec![[0.5, 0.0], [0.5, 3.0]]);
        assert_eq!(iso(&net, 0.5, false), vec![[0.0, 1.0], [1.0, 2.0]]);
    }
}
