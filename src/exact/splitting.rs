//! The exact Bernstein sum of one coordinate on big integers, by binary splitting (and a
//! surface's double sum, its columns' sums combined the same way: `net_sum`).
//!
//! With `t = a/b`, `s = b − a` and coordinates `x_i = c_i / d_i`,
//!
//! ```text
//! b(t) = Σ_i C(n,i) aⁱ s^(n−i) c_i/d_i  /  bⁿ.
//! ```
//!
//! The nested (Horner) sum of [`super::fraction_free`] multiplies an accumulator that grows
//! to the size of the result by the next term `n` times: `n` products of a big number by a
//! small one, `O(n · N)` word operations for a result of `N` words, and its inputs over one
//! common denominator are each as long as that denominator. Here the sum is split in halves
//! down to single terms and the halves are combined with a few products of balanced
//! operands, where Karatsuba's and Toom-3's multiplication pay (dashu-int's, see
//! [`ProductTree`]): `O(M(N) log n)`.
//!
//! A node `[lo, hi)` holds `T, P, Q, D` with
//!
//! ```text
//! Σ_{i=lo}^{hi−1} (Π_{k=lo}^{i} p(k)/q(k)) · c_i/d_i · a^(i−lo) s^(hi−1−i) = T / (Q D),
//! ```
//!
//! `p(k)/q(k) = (n−k+1)/k` the ratio of consecutive binomials (`p(0) = q(0) = 1`),
//! `P = Π p(k)`, `Q = Π q(k)` and `D = Π d_i` over the node; two halves `l`, `r` combine as
//!
//! ```text
//! T = T_l · s^len(r) Q_r D_r + T_r · a^len(l) P_l D_l,   P = P_l P_r,  Q = Q_l Q_r,  D = D_l D_r.
//! ```
//!
//! At the root `Q = n!` divides `T` exactly, leaving `b(t) = N / (D bⁿ)`.
//!
//! **Denominators.** Unrelated denominators (the general case: 30-digit fractions from
//! different sources) are kept as the product `D`, which is then as long as their lcm and
//! costs no gcd at all. Denominators that share most of their factors (decimals, floats,
//! one denominator for the whole curve) would make that product far longer than their
//! lcm `L`: when `L` stays short, the numerators are put over `L` instead and `D = 1`.
//!
//! **The one reduction.** `N / (D bⁿ)` is brought to lowest terms without a gcd of two long
//! numbers: the remainders `N mod d_i` come down the product tree of the `d_i` (a remainder
//! tree), each gives `h_i = gcd(N, d_i)` on short numbers, and `gcd(N, D) = gcd(N, Π h_i)`
//! ([`super::gcd::gcd_with_product`]), where `Π h_i` is short (usually a few small primes);
//! `bⁿ` is skipped whole when `gcd(N mod b, b) = 1`. Factors of two words or more, 3,000
//! to 24,000 bits in all, give their `h_i` by Hensel's remainders instead
//! ([`super::hensel::gcd_with_factors`]); a product of a few factors (up to degree 31),
//! unless they are long, is reduced by one gcd (`tree_reduces`).

use crate::exact::gcd::{self, Part};
use crate::exact::hensel;
use dashu_int::{IBig, UBig};
use num_bigint::{BigInt, Sign};
use num_integer::Integer;
use num_rational::BigRational;
use num_traits::{One, ToPrimitive, Zero};
use std::collections::BTreeMap;

/// The products of the denominators over the nodes of the splitting tree, in pre-order: the
/// node of `[lo, hi)` with index `i` has its left child at `i + 1` and its right child at
/// `i + 2 (mid − lo)` (a subtree of `m` leaves has `2m − 1` nodes).
///
/// The products and the divisions of the remainder tree run on dashu-int's integers: its
/// products take 0.5 to 0.65 times num-bigint's from 12 words on (a 100-word square 3.9
/// against 6.1 µs, 270 words 18.7 against 29.2 µs), its remainders of long numbers 0.7 times
/// (270 words by 135: 15.7 against 23.1 µs; 2026-12-05, `exact_grid`'s machine, quiet).
pub(crate) struct ProductTree {
    nodes: Vec<UBig>,
    /// The factors and their product as num-bigint's, for the callers.
    factors: Vec<BigInt>,
    product: BigInt,
}

/// The split point of `[lo, hi)`, the same in every tree of this module.
fn middle(lo: usize, hi: usize) -> usize {
    lo + (hi - lo) / 2
}

impl ProductTree {
    /// The tree of `factors` (at least one, all positive).
    pub(crate) fn new(factors: &[&BigInt]) -> Self {
        let mut nodes = vec![UBig::ZERO; 2 * factors.len() - 1];
        fn build(nodes: &mut [UBig], factors: &[&BigInt], lo: usize, hi: usize, id: usize) {
            if hi - lo == 1 {
                nodes[id] = gcd::to_dashu(factors[lo].magnitude());
                return;
            }
            let mid = middle(lo, hi);
            let (left, right) = (id + 1, id + 2 * (mid - lo));
            build(nodes, factors, lo, mid, left);
            build(nodes, factors, mid, hi, right);
            nodes[id] = &nodes[left] * &nodes[right];
        }
        build(&mut nodes, factors, 0, factors.len(), 0);
        let product = BigInt::from_biguint(Sign::Plus, gcd::from_words(nodes[0].as_words()));
        ProductTree {
            nodes,
            factors: factors.iter().map(|&f| f.clone()).collect(),
            product,
        }
    }

    /// The product of all factors.
    pub(crate) fn product(&self) -> &BigInt {
        &self.product
    }

    /// `x mod f` for every factor `f`, in order, nonnegative (a remainder tree).
    pub(crate) fn remainders(&self, x: &BigInt) -> Vec<BigInt> {
        let mut out = vec![BigInt::zero(); self.factors.len()];
        fn down(nodes: &[UBig], out: &mut [BigInt], x: UBig, lo: usize, hi: usize, id: usize) {
            let r = x % &nodes[id];
            if hi - lo == 1 {
                out[lo] = BigInt::from_biguint(Sign::Plus, gcd::from_words(r.as_words()));
                return;
            }
            let mid = middle(lo, hi);
            down(nodes, out, r.clone(), lo, mid, id + 1);
            down(nodes, out, r, mid, hi, id + 2 * (mid - lo));
        }
        let top = gcd::to_dashu(x.magnitude()) % &self.nodes[0];
        // x mod f = f − (|x| mod f) for a negative x and a nonzero remainder.
        let top = if x.sign() == Sign::Minus && top != UBig::ZERO {
            &self.nodes[0] - top
        } else {
            top
        };
        down(&self.nodes, &mut out, top, 0, self.factors.len(), 0);
        out
    }
}

/// The powers `base^m` for every length `m` of a node of the splitting tree of `n + 1`
/// terms, each the product of its two halves' powers.
fn node_powers(base: &BigInt, terms: usize) -> BTreeMap<usize, IBig> {
    let mut lengths = Vec::new();
    let mut level = vec![terms];
    while !level.is_empty() {
        lengths.extend(&level);
        let mut next: Vec<usize> = level
            .iter()
            .filter(|&&m| m > 1)
            .flat_map(|&m| [m / 2, m - m / 2])
            .collect();
        next.sort_unstable();
        next.dedup();
        level = next;
    }
    lengths.sort_unstable();
    lengths.dedup();
    let mut powers = BTreeMap::new();
    for m in lengths {
        let value = if m == 1 {
            gcd::to_ibig(base)
        } else {
            &powers[&(m / 2)] * &powers[&(m - m / 2)]
        };
        powers.insert(m, value);
    }
    powers
}

/// One node's `T, P, Q` (its `D` is in the [`ProductTree`]).
struct Node {
    t: IBig,
    p: IBig,
    q: IBig,
}

/// What the splitting of one coordinate reads.
struct Sum<'a> {
    n: usize,
    numerators: &'a [IBig],
    denominators: Option<&'a ProductTree>,
    a_powers: &'a BTreeMap<usize, IBig>,
    s_powers: &'a BTreeMap<usize, IBig>,
}

impl Sum<'_> {
    fn node(&self, lo: usize, hi: usize, id: usize) -> Node {
        if hi - lo == 1 {
            let (p, q) = if lo == 0 {
                (IBig::ONE, IBig::ONE)
            } else {
                (IBig::from(self.n - lo + 1), IBig::from(lo))
            };
            return Node {
                t: &p * &self.numerators[lo],
                p,
                q,
            };
        }
        let mid = middle(lo, hi);
        let (left_id, right_id) = (id + 1, id + 2 * (mid - lo));
        let left = self.node(lo, mid, left_id);
        let right = self.node(mid, hi, right_id);
        // The cofactors first, so that each product with a T is of balanced operands.
        let mut right_factor = &self.s_powers[&(hi - mid)] * &right.q;
        let mut left_factor = &self.a_powers[&(mid - lo)] * &left.p;
        if let Some(tree) = self.denominators {
            right_factor *= &tree.nodes[right_id];
            left_factor *= &tree.nodes[left_id];
        }
        Node {
            t: left.t * right_factor + right.t * left_factor,
            p: left.p * right.p,
            q: left.q * right.q,
        }
    }
}

/// `T` with `Σ_i C(n,i) aⁱ s^(n−i) N_i / D_i = T / Π D_i`, `s = b − a`, for the numerators
/// `N_i` over the factors `D_i` of `denominators` (all 1 when `None`), by binary splitting
/// (on dashu-int's integers, as [`ProductTree`]).
pub(crate) fn sum_over(numerators: &[BigInt], denominators: Option<&ProductTree>, a: &BigInt, b: &BigInt) -> BigInt {
    let n = numerators.len() - 1;
    let s = b - a;
    let numerators: Vec<IBig> = numerators.iter().map(gcd::to_ibig).collect();
    let sum = Sum {
        n,
        numerators: &numerators,
        denominators,
        a_powers: &node_powers(a, n + 1),
        s_powers: &node_powers(&s, n + 1),
    };
    let root = sum.node(0, n + 1, 0);
    // Q = n! divides T (see the module documentation).
    gcd::from_ibig(&(root.t / root.q))
}

/// `b'(t)` of one coordinate, `n ≥ 1`, as one binary-splitting sum over the product `D` of
/// the denominators: with `n C(n−1,i−1) = i C(n,i)` and `n C(n−1,i) = (n−i) C(n,i)`,
///
/// ```text
/// bⁿ⁻¹ b'(t) = Σ_i C(n,i) a^(i−1) s^(n−1−i) (i s − (n−i) a) c_i/d_i = T / (a s D),
/// ```
///
/// `T` the sum of this module with the numerators `c_i (i s − (n−i) a)`; `a s` divides `T`
/// (every term has a factor `a s`). `None` at `t = 0` or `1` (`a s = 0`), and when the
/// denominators share most of their factors (see [`short_common_denominator`]): their
/// product would then be far longer than their lcm, and the caller's sum over the lcm is
/// shorter.
pub(crate) fn first_derivative_sum(values: &[&BigRational], a: &BigInt, b: &BigInt) -> Option<BigRational> {
    let n = values.len() - 1;
    let s = b - a;
    if a.is_zero() || s.is_zero() || short_common_denominator(values).is_some() {
        return None;
    }
    let denominators: Vec<&BigInt> = values.iter().map(|v| v.denom()).collect();
    let numerators: Vec<BigInt> = values
        .iter()
        .enumerate()
        .map(|(i, v)| v.numer() * (&s * i - a * (n - i)))
        .collect();
    let tree = ProductTree::new(&denominators);
    let num = sum_over(&numerators, Some(&tree), a, b) / (a * &s);
    Some(reduce_over(num, Some(&tree), &[(b, n - 1)]))
}

/// One coordinate of a surface's point `b(u, v)`, `net[i][j]` the values of the net: each
/// column `j` summed at `u` over a common denominator `L_j` (unreduced): the product of its
/// denominators when they are unrelated, else their lcm; then those columns at `v` by
/// binary splitting over `Π L_j`, and one reduction against the short factors of all the
/// `L_j` and `q_u^m q_v^n`.
pub(crate) fn net_sum(net: &[Vec<&BigRational>], u: &BigRational, v: &BigRational) -> BigRational {
    let (m, n) = (net.len() - 1, net[0].len() - 1);
    let (mut columns, mut lcms, mut factors) = (Vec::with_capacity(n + 1), Vec::with_capacity(n + 1), Vec::new());
    for j in 0..=n {
        let values: Vec<&BigRational> = net.iter().map(|row| row[j]).collect();
        // Unrelated denominators: the column over their product, as `bernstein_sum` does
        // (no lcm to compute, and each numerator stays as short as its input).
        if short_common_denominator(&values).is_none() {
            let denominators: Vec<&BigInt> = values.iter().map(|v| v.denom()).collect();
            let numerators: Vec<BigInt> = values.iter().map(|v| v.numer().clone()).collect();
            let tree = ProductTree::new(&denominators);
            columns.push(sum_over(&numerators, Some(&tree), u.numer(), u.denom()));
            factors.extend(denominators.into_iter().cloned());
            lcms.push(tree.product().clone());
            continue;
        }
        let (numerators, tree) = over_lcm(&values);
        columns.push(sum_over(&numerators, None, u.numer(), u.denom()));
        match tree {
            Some(tree) => {
                factors.extend(tree.factors.iter().cloned());
                lcms.push(tree.product().clone());
            }
            None => lcms.push(BigInt::one()),
        }
    }
    let outer = ProductTree::new(&lcms.iter().collect::<Vec<_>>());
    let num = sum_over(&columns, Some(&outer), v.numer(), v.denom());
    let fine = (!factors.is_empty()).then(|| ProductTree::new(&factors.iter().collect::<Vec<_>>()));
    reduce_over(num, fine.as_ref(), &[(v.denom(), n), (u.denom(), m)])
}

/// `Σ_i C(n,i) aⁱ s^(n−i) x_i / bⁿ` for `x_i = values[i]`, `t = a/b`, `s = b − a`, in lowest
/// terms (see the [module documentation](self)).
pub(crate) fn bernstein_sum(values: &[&BigRational], a: &BigInt, b: &BigInt) -> BigRational {
    let n = values.len() - 1;
    let run = |numerators: &[BigInt], denominators: Option<&ProductTree>| sum_over(numerators, denominators, a, b);
    match short_common_denominator(values) {
        Some(common) => {
            let numerators: Vec<BigInt> = values
                .iter()
                .map(|v| {
                    if v.denom().is_one() {
                        v.numer() * &common
                    } else {
                        v.numer() * (&common / v.denom())
                    }
                })
                .collect();
            let num = run(&numerators, None);
            gcd::reduce(num, &[Part::Power(b, n), Part::Number(&common)])
        }
        None => {
            let denominators: Vec<&BigInt> = values.iter().map(|v| v.denom()).collect();
            let tree = ProductTree::new(&denominators);
            let numerators: Vec<BigInt> = values.iter().map(|v| v.numer().clone()).collect();
            let num = run(&numerators, Some(&tree));
            reduce_over(num, Some(&tree), &[(b, n)])
        }
    }
}

/// The lcm of the denominators as a product tree of short factors, `f_i = d_i / gcd(L, d_i)`
/// with `L` the lcm of the denominators before `d_i` (factors 1 left out): their product is
/// the lcm, and a reduction against it needs only the remainders modulo the factors
/// ([`reduce_over`]). `None` when every denominator is 1.
pub(crate) fn lcm_tree<'a>(denominators: impl Iterator<Item = &'a BigInt>) -> Option<ProductTree> {
    let mut lcm = BigInt::one();
    let mut factors = Vec::new();
    for d in denominators {
        if d.is_one() {
            continue;
        }
        let g = gcd::gcd_int(&lcm, d);
        let f = if g.is_one() { d.clone() } else { d / g };
        if !f.is_one() {
            lcm *= &f;
            factors.push(f);
        }
    }
    if factors.is_empty() {
        return None;
    }
    Some(ProductTree::new(&factors.iter().collect::<Vec<_>>()))
}

/// The lcm of the denominators when it stays short (at most twice the longest one plus two
/// words): denominators that share their factors. `None` as soon as it grows past that.
fn short_common_denominator(values: &[&BigRational]) -> Option<BigInt> {
    let longest = values.iter().map(|v| v.denom().bits()).max().unwrap_or(1);
    let limit = 2 * longest + 128;
    let mut common = BigInt::one();
    for v in values {
        if v.denom().is_one() || v.denom() == &common {
            continue;
        }
        common = gcd::lcm_int(&common, v.denom());
        if common.bits() > limit {
            return None;
        }
    }
    Some(common)
}

/// The numerators of `values` over the lcm of their denominators, and that lcm as a
/// [`lcm_tree`] (`None` when it is 1).
pub(crate) fn over_lcm(values: &[&BigRational]) -> (Vec<BigInt>, Option<ProductTree>) {
    let tree = lcm_tree(values.iter().map(|v| v.denom()));
    let numerators = match &tree {
        None => values.iter().map(|v| v.numer().clone()).collect(),
        Some(tree) => values
            .iter()
            .map(|v| {
                if v.denom().is_one() {
                    v.numer() * tree.product()
                } else {
                    v.numer() * (tree.product() / v.denom())
                }
            })
            .collect(),
    };
    (numerators, tree)
}

/// Up to this many factors, [`reduce_over`] takes one gcd (`gcd::gcd_int`) of the
/// numerator and their product instead of the remainder tree: at degree 20 (about 2,100
/// bits of product) that ran about 10% fewer instructions than the tree's divisions and leaf
/// gcds (callgrind on `derivative_at` and `eval` of the `exact_big` case, with the
/// single-word Lehmer gcd); the tree's divisions are quasi-linear, so it wins on long
/// products.
const SMALL_TREE_LEAVES: usize = 32;

/// Whether [`reduce_over`] takes the remainder tree: past [`SMALL_TREE_LEAVES`] factors, or
/// when the product has more than 7,500 bits in factors of 400 bits or more on average.
/// Measured (2026-12-05, eval at t = 1/3 of planar curves, one gcd against the tree,
/// alternating runs): the tree took 12% less time for 11 factors of 1,000 bits (300-digit
/// denominators, degree 10), 7% less for 21 of 500 bits, 4.5% less for 8 of 1,000 bits,
/// 2% less for 13 of 500 bits (6,500 bits in all), 1% less for 26 of 333 bits, and 3.5%
/// more for 21 of 333 bits; at 6 factors of 1,000 bits the two were equal.
fn tree_reduces(tree: &ProductTree) -> bool {
    let (leaves, bits) = (tree.factors.len() as u64, tree.product.bits());
    leaves > SMALL_TREE_LEAVES as u64 || (bits > 7_500 && bits >= 400 * leaves)
}

/// Whether the tree's factors are long enough for [`hensel::factor_gcds`] ([`hensel::pays`]).
fn by_factors(tree: &ProductTree) -> bool {
    hensel::pays(tree.factors.len(), tree.product.bits())
}

/// `num / (Π tree's factors · Π bᵉ)` in lowest terms, each `b > 0`: by [`gcd::reduce`]
/// part by part, the tree's factors as their product when they are few, else their gcd
/// with `num` found first, factor by factor ([`by_factors`]) or by the remainder tree.
pub(crate) fn reduce_over(num: BigInt, tree: Option<&ProductTree>, powers: &[(&BigInt, usize)]) -> BigRational {
    let powers = powers.iter().map(|&(b, e)| Part::Power(b, e));
    let tree = match tree {
        Some(tree) if (by_factors(tree) || tree_reduces(tree)) && !num.is_zero() => tree,
        few => {
            let product = few.map(|tree| Part::Number(tree.product()));
            return gcd::reduce(num, &product.into_iter().chain(powers).collect::<Vec<_>>());
        }
    };
    let g = if by_factors(tree) {
        hensel::gcd_with_factors(&num, &tree.factors)
    } else {
        // Every gcd(num, d_i); their product has the primes num shares with Π d_i.
        gcd::gcd_with_product(&num, &tree_gcds(tree, &num))
    };
    let (num, den) = if g.is_one() {
        (num, tree.product().clone())
    } else {
        (num.div_floor(&g), tree.product().div_floor(&g))
    };
    // What is left of num is prime to den: the powers against it alone.
    let (num, power_den) = gcd::reduce(num, &powers.collect::<Vec<_>>()).into_raw();
    BigRational::new_raw(num, power_den * den)
}

/// The gcds `gcd(num, d_i) ≠ 1` of `num` with the tree's factors, by the remainder tree: at
/// the cost of about one division of `num` by `Π d_i`.
fn tree_gcds(tree: &ProductTree, num: &BigInt) -> Vec<BigInt> {
    let remainders = tree.remainders(num);
    let leaves = &tree.factors[..];
    // Double words (30-digit denominators): the word gcds interleaved.
    let words = gcd::paired_gcds(remainders.iter().zip(leaves).map(|(r, f)| {
        let (r, f) = (r.to_u128()?, f.to_u128()?);
        (r != 0).then_some((r, f))
    }));
    remainders
        .iter()
        .zip(leaves)
        .zip(words)
        .map(|((r, f), word)| {
            if word != 0 {
                BigInt::from(word)
            } else {
                gcd::gcd_int(r, f)
            }
        })
        .filter(|h| !h.is_one())
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;
    use proptest::prelude::*;

    fn integer(limbs: &[u64], negative: bool) -> BigInt {
        let magnitude = gcd::from_words(limbs);
        BigInt::from_biguint(if negative { Sign::Minus } else { Sign::Plus }, magnitude)
    }

    proptest! {
        /// The remainder tree (on dashu-int's copies) against `mod_floor` for every factor:
        /// numbers of either sign, shorter and longer than the product, factors of 1 to 6
        /// words and 1.
        #[test]
        fn remainders_are_mod_floor(
            x in (proptest::collection::vec(any::<u64>(), 0..60), any::<bool>()),
            factors in proptest::collection::vec(proptest::collection::vec(any::<u64>(), 0..6), 1..40),
        ) {
            let x = integer(&x.0, x.1);
            let factors: Vec<BigInt> = factors.iter().map(|f| integer(f, false).max(BigInt::one())).collect();
            let tree = ProductTree::new(&factors.iter().collect::<Vec<_>>());
            let want: Vec<BigInt> = factors.iter().map(|f| x.mod_floor(f)).collect();
            prop_assert_eq!(tree.remainders(&x), want);
        }

        /// `reduce_over` in lowest terms by each of its ways (one gcd, the remainder tree,
        /// Hensel's remainders by factor): factors of 1 to 14 words sharing a part with
        /// each other and with the numerator, powers of two, and a power of a base.
        #[test]
        fn reduce_over_is_lowest_terms(
            x in (proptest::collection::vec(any::<u64>(), 1..40), any::<bool>()),
            factors in proptest::collection::vec((proptest::collection::vec(any::<u64>(), 1..15), 0u32..130, any::<bool>()), 1..40),
            common in proptest::collection::vec(any::<u64>(), 0..3),
            (base, e) in (1u64..1000, 0usize..5),
        ) {
            let common = integer(&common, false).max(BigInt::one());
            let num = integer(&x.0, x.1) * &common * BigInt::from(6u8);
            prop_assume!(!num.is_zero());
            let factors: Vec<BigInt> = factors
                .iter()
                .map(|(f, twos, shared)| {
                    let f = integer(f, false).max(BigInt::one()) << twos;
                    if *shared { f * &common } else { f }
                })
                .collect();
            let tree = ProductTree::new(&factors.iter().collect::<Vec<_>>());
            let base = BigInt::from(base);
            let want = BigRational::new(num.clone(), tree.product() * num_traits::pow(base.clone(), e));
            // num-rational's `==` compares values: the parts, for lowest terms.
            let got = reduce_over(num, Some(&tree), &[(&base, e)]);
            prop_assert_eq!((got.numer(), got.denom()), (want.numer(), want.denom()));
        }
    }

    /// One case of each way `reduce_over` can take, so that the proptest's draws do not
    /// decide whether a way is tested: 3 factors of 20 words (Hensel's), 50 of 10 words (the
    /// tree), 2 of 3 words (one gcd); the factors share a 200-bit prime-rich part and
    /// powers of two with each other and the numerator.
    #[test]
    fn reduce_over_takes_each_way() {
        let word = |i: u64| 0x9E37_79B9_7F4A_7C15u64.wrapping_mul(i + 1) | 1;
        let shared = integer(&[word(90), word(91), word(92)], false) >> 12u32;
        for (count, words, hensel_way) in [(3usize, 20usize, true), (50, 10, false), (2, 3, false)] {
            let factors: Vec<BigInt> = (0..count)
                .map(|k| {
                    let limbs: Vec<u64> = (0..words).map(|i| word((k * 31 + i) as u64)).collect();
                    (integer(&limbs, false) << (k % 3)) * if k % 2 == 0 { shared.clone() } else { BigInt::one() }
                })
                .collect();
            let tree = ProductTree::new(&factors.iter().collect::<Vec<_>>());
            assert_eq!(by_factors(&tree), hensel_way, "{count} factors of {words} words");
            let limbs: Vec<u64> = (0..count * words).map(|i| word(i as u64 + 7)).collect();
            let num = integer(&limbs, true) * &shared * BigInt::from(4u8);
            let want = BigRational::new(num.clone(), tree.product().clone());
            assert_ne!(want.denom(), tree.product(), "the case reduces");
            let got = reduce_over(num, Some(&tree), &[]);
            assert_eq!((got.numer(), got.denom()), (want.numer(), want.denom()));
        }
    }
}
