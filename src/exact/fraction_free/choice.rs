//! Which kernel of the fraction-free module runs past machine words, by measured sizes.

use num_bigint::BigInt;
use num_rational::BigRational;

/// The size below which the nested sum over the lcm of the denominators beats binary
/// splitting on big integers, as `Σ bits(d_i) + 2 n bits(q)` (see [`nested_wins`]).
///
/// Measured (2026-12-05, `examples`-side prototype against the library's eval, interleaved,
/// planar curves of the `exact_grid.py` grid): the nested sum won at 5 digits up to degree
/// 50 at `t = 1/3` (size 1,067: 37 µs against 49 µs), at degrees 3 and 5 with a 20-digit
/// `t` (464, 762) and at 30 digits at degree 3 (412, 796) and 5 at `t = 1/3` (620); it lost
/// at 30 digits, degree 5 with a 20-digit `t` (1,260: 17 µs against 14 µs) and from degree
/// 20 at 30 digits (2,100 and up: twice as slow), and tied at 5 digits, degree 20 with a
/// 20-digit `t` (2,997). In the grid's own run afterwards (docs/performance.md) the
/// 30-digit degree-5 cell at `t = 1/3` (620) was 9% slower nested, within the spread.
const NESTED_BITS: u64 = 1100;

/// Whether one coordinate's Bernstein sum is cheaper nested (Horner) over the lcm of its
/// denominators than by binary splitting: when that lcm and the powers of `q` stay short
/// the nested sum's steps are products by short numbers and its reduction one gcd, where
/// binary splitting builds a tree of products and reduces through their remainders.
pub(super) fn nested_wins(values: &[&BigRational], q: &BigInt) -> bool {
    let n = values.len() as u64 - 1;
    let denominators: u64 = values.iter().map(|v| v.denom().bits()).sum();
    denominators + 2 * n * q.bits() <= NESTED_BITS
}

/// Whether a surface whose net overflows machine words is cheaper row by row (each row's
/// sum at `v` reduced, then the column of those at `u`) than by `splitting::net_sum` (all
/// the net's denominators in one product, one reduction): when a row's denominators and
/// `v`'s are single words and its nested sum wins ([`nested_wins`]), its reduced point is
/// short and often within machine words.
///
/// Measured (2026-12-05, interleaved, nets of the `exact_grid.py` grid, u = v = 1/3): row
/// by row took 10 µs against 21 µs for 5-digit nets of degree (3, 3), 23 against 62 at
/// (5, 5), 563 against 695 at (20, 20) and 5.0 ms against 6.0 ms at (50, 50); with 30-digit
/// denominators it lost at (3, 3) and (5, 5) (61 against 43 µs, 161 against 136), and with
/// a 20-digit parameter at 5 digits (1.8 ms against 0.9 ms at (20, 20)), which
/// [`nested_wins`] already refuses.
///
/// In the grid itself, 5-digit nets with a 20-digit parameter at (3, 3) and (5, 5), which
/// pass [`nested_wins`], took 30.5 µs against 27.5 µs and 79.5 against 77.4 row by row:
/// the parameter's denominator must be a word too.
pub(super) fn rows_first(row: &[&BigRational], v: &BigRational) -> bool {
    v.denom().bits() <= 64 && row.iter().all(|x| x.denom().bits() <= 64) && nested_wins(row, v.denom())
}

/// The shortest mean denominator, in bits, for which a subdivision is split pair by pair.
const PAIRS_MIN_BITS: u64 = 30;

/// Whether one coordinate's subdivision past machine words is cheaper pair by pair on
/// reduced fractions (`split::split_coordinate`) than over the lcm of its denominators:
/// with long denominators and a low degree, the lcm is as long as all of them together and
/// each of the `2n − 1` outputs is reduced by a gcd with all of it, where a pair's gcds are
/// of one or two neighbours' denominators; with short ones, or many, or a long `t` (whose
/// powers both kernels carry, the pairs in every value of the triangle), the lcm wins.
///
/// The rule, with `D` the mean bits of the denominators and `Q` those of `t`'s: pairs up to
/// degree 6 while `n Q ≤ 6 D`, and at degrees 7 and 8 while `D ≥ 800` and `n Q ≤ D`, never
/// below 30 bits. Measured (2026-12-05, both kernels on the `exact_grid.py` grid's planar
/// curves, one after the other, 2 shared cores): pairs won at 30, 100 and 300 digits (`D` =
/// 100, 333, 1000) up to degree 6 with `t = 1/3` and a 20-digit `t` (by 10% to 45%: 30
/// digits, cubic, 22.4 µs against 17.3 µs), with a 100-digit `t` at 100 digits to degree 4
/// and at 300 to degree 6; they lost with a 100-digit `t` at 15 to 30 digits (30 digits,
/// cubic: 42 µs against 40; degree 6: 200 against 159), at 100 digits from degree 6 and at
/// degree 8 with a 20-digit `t` (480 against 440 µs), and everywhere at degree 10 but 300
/// digits with a short `t` (a tie). At 300 digits, degree 8, pairs won with a short `t`
/// (1.92 ms against 2.33) and lost with a 100-digit one (2.75 against 2.57).
pub(super) fn pairs_win(values: &[&BigRational], q: &BigInt) -> bool {
    let n = values.len() as u64 - 1;
    let mean = values.iter().map(|v| v.denom().bits()).sum::<u64>() / (n + 1);
    let reach = n * q.bits();
    mean >= PAIRS_MIN_BITS
        && match n {
            1..=6 => reach <= 6 * mean,
            7..=8 => mean >= 800 && reach <= mean,
            _ => false,
        }
}
