//! Which kernel of the fraction-free module runs past machine words, by measured sizes.

use num_bigint::BigInt;
use num_rational::BigRational;

/// Bounds of the fraction-form nested sum (`horner`, on words of any length) against binary
/// splitting, with `share = n bits(q)` (the parameter's part of every number) and `size =
/// Σ bits(d_i) + 2 share` (about the length of its last numbers): the degree at most
/// `HORNER_DEGREE`, the size at most `HORNER_BITS`, and the share at most
/// `HORNER_PARAMETER_BITS`, or any share up to degree `HORNER_ANY_SHARE_DEGREE`, or a share
/// up to `HORNER_WIDE_SHARE` with denominators of `HORNER_WIDE_SHARE_DENOMINATORS` bits in
/// all: a long `t` makes every coefficient `C(n,i) pⁱ` long, and the nested sum's steps
/// multiply the denominators so far by it.
///
/// Measured (2026-12-06, `exact_grid.py`, planar curves, the `eval` cells of digits 5 to
/// 300, degrees 3 to 200, the three kinds of `t`, either kernel forced, two runs each,
/// alternating): the nested sum won at every cell of degree 3 and 5 (300 digits, degree 5,
/// 100-digit `t`: 130 against 138 µs, size 9,300, share 1,665); at `t = 1/3` it won at 5
/// digits to degree 200 (94 against 187 µs, size 4,200), at 30 digits to degree 50 (89–94
/// against 138 µs, size 5,300) and at 100 digits, degree 20 (138 against 145 µs, size
/// 7,000), tied at 30 digits, degree 100 (312 against 336–358 µs, size 10,500), and lost
/// at 30 digits, degree 200 (1.14–1.20 against 0.88–0.97 ms, size 20,000), 100 digits,
/// degree 50 (670 against 535 µs) and 300 digits, degree 20 (890 against 615 µs). With a
/// 20-digit `t` at degree 20 it won at 5 digits (18 against 28 µs: share 1,340, 360 bits
/// of denominators) and lost at 30 (56 against 52 µs: 2,100 bits) and 100 (206 against
/// 169 µs); with a 20-digit `t` at degree 50 (share 3,350) and a 100-digit one from degree
/// 20 (share 6,660) it lost or tied everywhere.
const HORNER_PARAMETER_BITS: u64 = 1000;
const HORNER_DEGREE: u64 = 200;
const HORNER_BITS: u64 = 10_000;
const HORNER_ANY_SHARE_DEGREE: u64 = 5;
const HORNER_WIDE_SHARE: u64 = 1500;
const HORNER_WIDE_SHARE_DENOMINATORS: u64 = 1000;

/// Whether one coordinate's Bernstein sum on big integers is cheaper nested on a fraction
/// than by binary splitting: its steps are products by short factors and cost the length of
/// the numbers so far, a total quadratic in the degree, where binary splitting builds a
/// tree of balanced products (see [`HORNER_BITS`]).
pub(super) fn horner_wins(values: &[&BigRational], q: &BigInt) -> bool {
    let n = values.len() as u64 - 1;
    let denominators: u64 = values.iter().map(|v| v.denom().bits()).sum();
    let share = n * q.bits();
    n <= HORNER_DEGREE
        && denominators + 2 * share <= HORNER_BITS
        && (share <= HORNER_PARAMETER_BITS
            || n <= HORNER_ANY_SHARE_DEGREE
            || (share <= HORNER_WIDE_SHARE && denominators <= HORNER_WIDE_SHARE_DENOMINATORS))
}

/// Whether a word kernel is bound to overflow: the denominators that differ from their
/// neighbour, longer than `limit` bits together (160 for a curve's point, whose integers
/// are also multiplied by powers of `t`; 64 for the derivative curve, whose word kernel puts
/// the whole curve over one denominator and reduces each output by a gcd of double words,
/// where the pairwise kernel took 1.6 to 1.9 µs against 2.3 to 2.6 µs for a cubic of
/// 5-digit fractions, 2026-12-05). Their lcm could still be short (shared
/// factors), but the word kernel would first compute gcds and products until it overflows,
/// and the big-integer kernels keep equal neighbours' denominators once.
pub(super) fn words_hopeless(values: &[&BigRational], limit: u64) -> bool {
    let mut bits = values[0].denom().bits() - 1;
    for pair in values.windows(2) {
        if !super::horner::equal(pair[1].denom(), pair[0].denom()) {
            bits += pair[1].denom().bits() - 1;
        }
    }
    bits > limit
}

/// Whether the product of the powers `qⁿ`, a factor of every word kernel's final
/// denominator, is past `i128` for certain (`q ≥ 2^(bits − 1)`): the word kernel would run
/// its sums until they overflow. A 5-digit cubic at a 20-digit `t` (67 bits) spent 8% of
/// its time on the words' lcms (docs/performance.md, "Word tiers that cannot fit").
pub(super) fn powers_overflow(powers: &[(usize, &BigInt)]) -> bool {
    let bits = powers
        .iter()
        .map(|&(n, q)| (n as u64).saturating_mul(q.bits().saturating_sub(1)))
        .fold(0u64, u64::saturating_add);
    bits >= 127
}

/// Whether a surface whose net overflows machine words is cheaper row by row (each row's
/// sum at `v` reduced, then the column of those at `u`) than by `splitting::net_sum` (all
/// the net's denominators in one product, one reduction): when a row's denominators and
/// `v`'s are single words and its nested sum wins ([`horner_wins`]), its reduced point is
/// short and often within machine words.
///
/// Measured (2026-12-05, interleaved, nets of the `exact_grid.py` grid, u = v = 1/3): row
/// by row took 10 µs against 21 µs for 5-digit nets of degree (3, 3), 23 against 62 at
/// (5, 5), 563 against 695 at (20, 20) and 5.0 ms against 6.0 ms at (50, 50); with 30-digit
/// denominators it lost at (3, 3) and (5, 5) (61 against 43 µs, 161 against 136), and with
/// a 20-digit parameter at 5 digits (1.8 ms against 0.9 ms at (20, 20)), which
/// [`horner_wins`] already refuses.
///
/// In the grid itself, 5-digit nets with a 20-digit parameter at (3, 3) and (5, 5), which
/// pass [`horner_wins`], took 30.5 µs against 27.5 µs and 79.5 against 77.4 row by row:
/// the parameter's denominator must be a word too.
pub(super) fn rows_first(row: &[&BigRational], v: &BigRational) -> bool {
    v.denom().bits() <= 64 && row.iter().all(|x| x.denom().bits() <= 64) && horner_wins(row, v.denom())
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

#[cfg(test)]
mod tests {
    use super::*;
    use num_traits::{One, Pow};
    use proptest::prelude::*;

    proptest! {
        /// The skip is sound: whenever it is taken, the powers' product alone is past
        /// `i128::MAX` (at least 2^127), so the word kernel could not have succeeded.
        #[test]
        fn skipped_powers_do_not_fit_words(
            (a, shift_a, n) in (1u128.., 0u32..100, 0usize..12),
            (b, shift_b, m) in (1u128.., 0u32..100, 0usize..12),
        ) {
            let q = |x: u128, shift: u32| -> BigInt { ((BigInt::from(x) << shift) >> 64u32).max(BigInt::one()) };
            let (qa, qb) = (q(a, shift_a), q(b, shift_b));
            if powers_overflow(&[(n, &qa), (m, &qb)]) {
                let product = Pow::pow(&qa, n as u32) * Pow::pow(&qb, m as u32);
                prop_assert!(product.bits() >= 128, "{qa}^{n} {qb}^{m}");
            }
        }
    }

    #[test]
    fn powers_at_the_edge() {
        let two = |k: u32| BigInt::one() << k;
        // 2^63 squared is 2^126: fits, not skipped; one more bit or one more factor is past.
        assert!(!powers_overflow(&[(2, &two(63))]));
        assert!(powers_overflow(&[(2, &two(64))]));
        assert!(powers_overflow(&[(2, &two(63)), (1, &two(1))]));
        assert!(!powers_overflow(&[(1000, &BigInt::one())]));
    }
}
