//! Draw a figure: de Casteljau's construction of a curve at `t`, from exact data, as SVG
//! (every point carries its exact value as a tooltip).
//!
//! `cargo run --example draw_figure -- construction.svg` (without a path: the SVG on stdout)

use casteljau::figure::construction;
use casteljau::{parse_exact, parse_points, BezierCurve, BigRational};

/// The SVG of the construction of b(1/3) for text 000's example 4).
fn svg() -> String {
    let points = parse_points("0,0; 4/3,-4/3; 4/3,4/3; 0,0").expect("points");
    let curve: BezierCurve<BigRational> = BezierCurve::new(points).expect("a curve");
    let t = parse_exact("1/3").expect("a number");
    construction(&curve, &t).and_then(|f| f.to_svg()).expect("a figure")
}

fn main() {
    let svg = svg();
    match std::env::args().nth(1) {
        Some(path) => {
            std::fs::write(&path, &svg).expect("a writable path");
            println!("wrote {path} ({} bytes)", svg.len());
        }
        None => print!("{svg}"),
    }
}

#[cfg(test)]
mod tests {
    #[test]
    fn the_figure_is_svg_with_the_exact_point() {
        let svg = super::svg();
        assert!(svg.starts_with("<svg") || svg.starts_with("<?xml"), "{}", &svg[..80]);
        // b(1/3) = (8/9, -8/27), exactly, in a tooltip
        assert!(svg.contains("8/9") && svg.contains("-8/27"), "no exact point");
    }
}
