//! `Cubic::split_at` and lyon_geom's `CubicBezierSegment::split`, each out of line, so
//! that their machine code can be read side by side; the program checks that both give the
//! same halves, bit for bit, on a few curves.
//!
//! ```text
//! cargo build --release --example split_codegen
//! objdump -d --no-show-raw-insn -C target/release/examples/split_codegen \
//!     | awk '/<split_codegen::(casteljau|lyon)_split>:$/,/ret/'
//! ```

use casteljau::{Cubic, Point2, PointN};
use lyon_geom::{point, CubicBezierSegment};
use std::hint::black_box;

type Halves<C> = (C, C);

#[inline(never)]
fn casteljau_split(c: &Cubic<Point2<f64>>, t: f64) -> Halves<Cubic<Point2<f64>>> {
    c.split_at(&t)
}

#[inline(never)]
fn lyon_split(c: &CubicBezierSegment<f64>, t: f64) -> Halves<CubicBezierSegment<f64>> {
    c.split(t)
}

fn main() {
    let curves = [
        [[0.0, 0.0], [1.0, 2.0], [3.0, 2.5], [4.0, 0.5]],
        [[-1e300, 3.5], [2.0, -7.25], [1e-300, 0.1], [5.0, 1e10]],
    ];
    for points in curves {
        let ours = Cubic::new(points.map(PointN));
        let [a, b, c, d] = points.map(|[x, y]| point(x, y));
        let theirs = CubicBezierSegment {
            from: a,
            ctrl1: b,
            ctrl2: c,
            to: d,
        };
        for t in [0.3, 0.5, 1.0 / 3.0, 0.999] {
            let (l, r) = casteljau_split(black_box(&ours), black_box(t));
            let (ll, lr) = lyon_split(black_box(&theirs), black_box(t));
            for (half, lyon) in [(l, ll), (r, lr)] {
                let lyon = [lyon.from, lyon.ctrl1, lyon.ctrl2, lyon.to].map(|p| [p.x, p.y]);
                let ours = half.points().map(|p| p.0);
                assert_eq!(ours.map(|p| p.map(f64::to_bits)), lyon.map(|p| p.map(f64::to_bits)));
            }
        }
    }
    println!("Cubic::split_at and lyon's split agree bit for bit");
}
