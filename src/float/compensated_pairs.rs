//! Compensated de Casteljau for `t ∈ [0, 1]` two nodes at a time: the operations of
//! `compensated_triangle` (the same ones, in the same order, so the same bits; with FMA the
//! error of each node's sum by FastTwoSum on the addends ordered by magnitude, the same
//! exact error as its TwoSum) on pairs of floats, which the compiler maps to the two lanes of an SSE2 register on the default
//! x86-64 target. Nodes `i` and `i + 1` of a level read the values `[x_i, x_{i+1}]` and
//! `[x_{i+1}, x_{i+2}]`: the pair loaded for the next step, shifted by one. A level of `len`
//! nodes takes `⌈len/2⌉` steps; an odd level's last step computes one value too many, in
//! the buffers' padding. With FMA (and so AVX), a cubic runs on values held in registers
//! instead, its first level's three nodes in one step of four lanes. FMA is chosen at run
//! time where the CPU has it (`multiversion`), with the same bits as without.
//!
//! Three things make it cheaper than the node-by-node loop, none of them changing a bit:
//!
//! - **No range check per node.** Dekker's product error is exact (and equal to
//!   [`super::two_product`]'s) when nothing in it overflows or rounds below `2^−1022`. For
//!   `t ∈ [0, 1]` both factors `s = fl(1 − t)` and `t` lie in `[0, 1]` and `s + t ≤ 1 + u`,
//!   so a level grows the largest magnitude by at most `(1 + u)³`: from `Σ|b_i| ≤ 2^994`
//!   every value stays below `2^995`, where splitting and the partial products are finite.
//!   Below, a granularity argument replaces the check: if every value of a level is an
//!   integer multiple of `2^F`, then `s·x` is a multiple of `2^(F + e_s)` (`e_s` the ulp
//!   exponent of `s`), and so is its rounded value (rounding to a coarser grid keeps the
//!   multiple, to a finer one it is exact); likewise for `t` and for the sum. So the
//!   values of level `r` are multiples of `2^(F_0 + r·L)`, `L` the smaller ulp exponent of
//!   the nonzero factors (`≤ −52`), `F_0` the finest ulp exponent of the inputs. Every
//!   partial product of Dekker's error of `k·x` is then a multiple of
//!   `2^(F_0 + r·L + L)`, so while that is at least `2^−1074` no operation in it rounds
//!   below the normal range, and the error is exact. The loop counts the levels this
//!   covers; when they run out it takes the finest ulp exponent of the values at hand and
//!   counts again, and gives up (`None`, the caller's checked triangle then runs) only
//!   when not one more level is covered.
//! - **A two-operation split.** Each value `x` is split as `x_h = x` with the last 26 bits
//!   of its significand cleared (27 significant bits) and `x_l = x − x_h` (exact, at most
//!   26 bits, `|x_l| < 2^(e−26)` for `2^e ≤ |x|`): a mask and a subtraction instead of
//!   Veltkamp's four operations. With the factor `k` split by Veltkamp (`k_h` of 26 bits,
//!   `k_l` of at most 26 bits, `|k_l| ≤ 2^(e_k−26)`, both multiples of `2^(e_k−52)`),
//!   Dekker's `((k_h x_h − p) + k_h x_l + k_l x_h) + k_l x_l` stays exact at every step
//!   (`X = k·x`, `p = fl(X)`, `E = e_k + e`, `|X| < 2^(E+2)`, values normal by the
//!   argument above): the four products have at most 53 bits; `k_h x_h − p` is a multiple
//!   of `2^(E−52)` below `2^(E−23)`; adding `k_h x_l` gives `(X − p) − k_l x`, a multiple
//!   of `2^(E−77)` below `2^(E−25) + 2^(E−51)`; adding `k_l x_h` gives `(X − p) − k_l x_l`,
//!   a multiple of `2^(E−78)` below `2^(E−50)`; each fits in 53 bits, and the last sum is
//!   `X − p` itself, a float. So the error is the exact one, as with Veltkamp's split.
//! - **The first level's low parts are zeros**: `(w + s·0) + t·0` is `w + 0` for
//!   `s, t ≥ 0`, one addition instead of four operations.
//!
//! The bound is one expression with constants per degree ([`UnitBound`]).

use super::casteljau::{gamma_computed, next_up, ETA, UNIT_ROUNDOFF};
use super::eft::{fast_two_sum, split, MAX_SPLIT};
use multiversion::multiversion;
use multiversion::target::target_cfg_f;
use std::ops::{Add, Mul, Sub};

/// Up to this degree (exclusive) the pairs run on the stack with tabulated bound constants.
const MAX_DEGREE: usize = super::STACK_COEFFICIENTS;

/// Whether `t` and the degree of `b` are in this module's domain: `t ∈ [0, 1]`, degrees 1
/// to 63.
#[inline(always)]
fn in_domain(b: &[f64], t: f64) -> bool {
    (0.0..=1.0).contains(&t) && (2..=MAX_DEGREE).contains(&b.len())
}

/// `(res, e)` of [`super::compensated_de_casteljau`] for `t ∈ [0, 1]` and degrees 1 to 63;
/// `None` elsewhere and when a value may leave the range where the products' errors are
/// exact without a check (the caller then runs its checked triangle: the same bits).
/// TwoProduct by a fused multiply-add where the CPU has one, chosen at run time.
#[inline]
pub(super) fn compensated_in_unit_interval(b: &[f64], t: f64) -> Option<(f64, f64)> {
    if !in_domain(b, t) {
        return None;
    }
    // a cubic, the common case, on its own version: without the other degrees' code the
    // call saves no registers and sets up no stack
    let (res, bound) = if b.len() == 4 {
        best_cubic(b, t)
    } else {
        best_triangle(b, t)
    };
    (!bound.is_nan()).then_some((res, bound))
}

/// [`compensated_in_unit_interval`] by the fused multiply-add's formulas (`FMA`) or by
/// Dekker's product, whatever the CPU has (without the instruction, each `f64::mul_add` is a
/// call to the C library's correctly rounded `fma`: slow, and the same bits).
pub(super) fn compensated_in_unit_interval_by<const FMA: bool>(b: &[f64], t: f64) -> Option<(f64, f64)> {
    if !in_domain(b, t) {
        return None;
    }
    triangle::<FMA>(b, t)
}

/// [`triangle`] compiled twice, for the build's target and for x86-64 with AVX and FMA, the
/// second taken where the CPU has them (the FMA formulas); where the build's target has FMA
/// already there is one version and no choice at run time. A declined triangle comes back
/// as a NaN bound (a bound the triangle gives is finite): two floats return in registers,
/// an `Option` of them through memory, which the call cannot inline away.
#[multiversion(targets("x86_64+avx+fma"))]
fn best_triangle(b: &[f64], t: f64) -> (f64, f64) {
    let parts = if target_cfg_f!(target_feature = "fma") {
        triangle::<true>(b, t)
    } else {
        triangle::<false>(b, t)
    };
    parts.unwrap_or((f64::NAN, f64::NAN))
}

/// [`best_triangle`] for a cubic (`b.len() == 4`).
#[multiversion(targets("x86_64+avx+fma"))]
fn best_cubic(b: &[f64], t: f64) -> (f64, f64) {
    let parts = if target_cfg_f!(target_feature = "fma") {
        cubic_triangle::<true>(b, t)
    } else {
        cubic_triangle::<false>(b, t)
    };
    parts.unwrap_or((f64::NAN, f64::NAN))
}

/// [`triangle`] for a cubic.
#[inline(always)]
fn cubic_triangle<const FMA: bool>(b: &[f64], t: f64) -> Option<(f64, f64)> {
    let factors = Factors::<Pair, FMA>::new(t);
    let (hi, lo, abs) = if FMA {
        cubic(&factors, b)
    } else {
        unrolled::<4, 6, FMA>(&factors, b)
    }?;
    let res = hi + lo;
    Some((res, UnitBound::of(3, abs, res)))
}

/// The compensated triangle of `b` at `t` (in the domain) and its bound, TwoProduct by
/// fused multiply-adds (`FMA`) or by Dekker's product: the same bits.
#[inline(always)]
fn triangle<const FMA: bool>(b: &[f64], t: f64) -> Option<(f64, f64)> {
    let n = b.len() - 1;
    let factors = Factors::<Pair, FMA>::new(t);
    let (hi, lo, abs) = match b.len() {
        2 => unrolled::<2, 4, FMA>(&factors, b),
        3 => unrolled::<3, 6, FMA>(&factors, b),
        4 if FMA => cubic(&factors, b),
        4 => unrolled::<4, 6, FMA>(&factors, b),
        5 => unrolled::<5, 8, FMA>(&factors, b),
        len if len + 2 <= 8 => looped::<8, FMA>(&factors, b),
        len if len + 2 <= 16 => looped::<16, FMA>(&factors, b),
        len if len + 2 <= 32 => looped::<32, FMA>(&factors, b),
        _ => looped::<{ MAX_DEGREE + 2 }, FMA>(&factors, b),
    }?;
    let res = hi + lo;
    Some((res, UnitBound::of(n, abs, res)))
}

/// Floats operated on lane by lane: one node of the triangle per lane.
trait Lanes: Copy + Add<Output = Self> + Sub<Output = Self> + Mul<Output = Self> {
    fn splat(x: f64) -> Self;
    fn map(self, f: impl Fn(f64) -> f64) -> Self;
    /// Lane 0 (every lane of a splat value).
    fn first(self) -> f64;
    /// `k·self − p` in each lane, rounded once.
    fn fused(self, k: Self, p: Self) -> Self;
    /// `(larger, smaller)` in magnitude, lane by lane.
    fn ordered(self, o: Self) -> (Self, Self);
}

/// `(larger, smaller)` of `a`, `b` in magnitude (`a` on a tie).
#[inline(always)]
fn ordered(a: f64, b: f64) -> (f64, f64) {
    if a.abs() >= b.abs() {
        (a, b)
    } else {
        (b, a)
    }
}

/// `k·x − p` rounded once: the exact error of `p = fl(k·x)` when `p` is that product.
#[inline(always)]
fn fused(x: f64, k: f64, p: f64) -> f64 {
    k.mul_add(x, -p)
}

/// Two floats, operated on lane by lane, written out lane by lane: loops over the lanes
/// compiled to more instructions, partly scalar (measured: `git log -p -- docs/performance.md`).
#[derive(Clone, Copy)]
struct Pair([f64; 2]);

impl Lanes for Pair {
    #[inline(always)]
    fn splat(x: f64) -> Self {
        Pair([x, x])
    }

    #[inline(always)]
    fn map(self, f: impl Fn(f64) -> f64) -> Self {
        Pair([f(self.0[0]), f(self.0[1])])
    }

    #[inline(always)]
    fn first(self) -> f64 {
        self.0[0]
    }

    #[inline(always)]
    fn fused(self, k: Self, p: Self) -> Self {
        Pair([fused(self.0[0], k.0[0], p.0[0]), fused(self.0[1], k.0[1], p.0[1])])
    }

    #[inline(always)]
    fn ordered(self, o: Self) -> (Self, Self) {
        let ((a0, b0), (a1, b1)) = (ordered(self.0[0], o.0[0]), ordered(self.0[1], o.0[1]));
        (Pair([a0, a1]), Pair([b0, b1]))
    }
}

impl Pair {
    #[inline(always)]
    fn load(b: &[f64], i: usize) -> Self {
        Pair([b[i], b[i + 1]])
    }

    #[inline(always)]
    fn store(self, b: &mut [f64], i: usize) {
        b[i] = self.0[0];
        b[i + 1] = self.0[1];
    }

    /// `[self₁, next₀]`: the pair one position further along.
    #[inline(always)]
    fn shifted(self, next: Pair) -> Self {
        Pair([self.0[1], next.0[0]])
    }
}

impl Add for Pair {
    type Output = Pair;
    #[inline(always)]
    fn add(self, o: Pair) -> Pair {
        Pair([self.0[0] + o.0[0], self.0[1] + o.0[1]])
    }
}

impl Sub for Pair {
    type Output = Pair;
    #[inline(always)]
    fn sub(self, o: Pair) -> Pair {
        Pair([self.0[0] - o.0[0], self.0[1] - o.0[1]])
    }
}

impl Mul for Pair {
    type Output = Pair;
    #[inline(always)]
    fn mul(self, o: Pair) -> Pair {
        Pair([self.0[0] * o.0[0], self.0[1] * o.0[1]])
    }
}

/// `W` floats, operated on lane by lane: the cubic's levels with FMA (four lanes are an
/// AVX register). Written with `array::from_fn`, which compiled to the faster cubic there;
/// the two-lane levels keep [`Pair`].
#[derive(Clone, Copy)]
struct Wide<const W: usize>([f64; W]);

impl<const W: usize> Lanes for Wide<W> {
    #[inline(always)]
    fn splat(x: f64) -> Self {
        Wide([x; W])
    }

    #[inline(always)]
    fn map(self, f: impl Fn(f64) -> f64) -> Self {
        Wide(self.0.map(f))
    }

    #[inline(always)]
    fn first(self) -> f64 {
        self.0[0]
    }

    #[inline(always)]
    fn fused(self, k: Self, p: Self) -> Self {
        Wide(std::array::from_fn(|j| fused(self.0[j], k.0[j], p.0[j])))
    }

    #[inline(always)]
    fn ordered(self, o: Self) -> (Self, Self) {
        let pairs: [(f64, f64); W] = std::array::from_fn(|j| ordered(self.0[j], o.0[j]));
        (Wide(pairs.map(|p| p.0)), Wide(pairs.map(|p| p.1)))
    }
}

impl<const W: usize> Wide<W> {
    /// The `V` lanes from lane `i` on.
    #[inline(always)]
    fn part<const V: usize>(self, i: usize) -> Wide<V> {
        Wide(std::array::from_fn(|j| self.0[i + j]))
    }

    /// `[self₁, …, self_{W−1}, self₀]`: each lane's right neighbour (the last lane's is not
    /// one).
    #[inline(always)]
    fn rotated(self) -> Self {
        Wide(std::array::from_fn(|j| self.0[(j + 1) % W]))
    }
}

/// The three operations of [`Wide`], lane by lane.
macro_rules! wide_operation {
    ($trait:ident, $method:ident, $op:tt) => {
        impl<const W: usize> $trait for Wide<W> {
            type Output = Self;
            #[inline(always)]
            fn $method(self, o: Self) -> Self {
                Wide(std::array::from_fn(|j| self.0[j] $op o.0[j]))
            }
        }
    };
}

wide_operation!(Add, add, +);
wide_operation!(Sub, sub, -);
wide_operation!(Mul, mul, *);

/// A factor of every product (`s` or `t`) in every lane, split by Veltkamp for Dekker's
/// product; its errors by fused multiply-adds when `FMA` (the halves then go unused).
#[derive(Clone, Copy)]
struct Factor<V, const FMA: bool> {
    value: V,
    halves: (V, V),
}

impl<V: Lanes, const FMA: bool> Factor<V, FMA> {
    #[inline(always)]
    fn new(k: f64) -> Self {
        let (h, l) = split(k);
        Factor {
            value: V::splat(k),
            halves: (V::splat(h), V::splat(l)),
        }
    }

    /// The exact error `k·x − p` of `p = fl(k·x)` (in the range the module documentation
    /// gives): Dekker's product on the two-operation split of `x`, or one fused
    /// multiply-add.
    #[inline(always)]
    fn error(&self, x: V, p: V) -> V {
        if FMA {
            return x.fused(self.value, p);
        }
        /// All but the last 26 bits of a float's significand.
        const HIGH_27_BITS: u64 = !((1 << 26) - 1);
        let (kh, kl) = self.halves;
        let xh = x.map(|v| f64::from_bits(v.to_bits() & HIGH_27_BITS));
        let xl = x - xh;
        ((kh * xh - p) + kh * xl + kl * xh) + kl * xl
    }
}

/// What every node needs: `s = fl(1 − t)` and its error `ρ`, `t`, the factor `s' ≥ 1 − t`
/// of the `|b_i|` triangle, and the ulp exponent `L` of the granularity argument.
struct Factors<V, const FMA: bool> {
    s: Factor<V, FMA>,
    t: Factor<V, FMA>,
    rho: V,
    s_abs: V,
    /// `−L ≥ 52`: how much a level may refine the grid of the values (in exponent).
    refinement: i64,
}

impl<V: Lanes, const FMA: bool> Factors<V, FMA> {
    #[inline(always)]
    fn new(t: f64) -> Self {
        // `|1| ≥ |t|` for `t ∈ [0, 1]`: FastTwoSum's error is exact, the one `one_minus` gives
        let (s, rho) = fast_two_sum(1.0, -t);
        // a zero factor's products are zeros, on every grid
        let exponent = |k: f64| if k == 0.0 { 0 } else { -ulp_exponent(k) };
        Factors {
            s: Factor::new(s),
            t: Factor::new(t),
            rho: V::splat(rho),
            s_abs: V::splat(next_up(s + rho.abs())),
            // with FMA no grid is kept ([`Factors::level_budget`]): any refinement will do
            refinement: if FMA {
                52
            } else {
                exponent(s).max(exponent(t)).min(1074)
            },
        }
    }

    /// The same factors in the lanes of `U`.
    #[inline(always)]
    fn widen<U: Lanes>(&self) -> Factors<U, FMA> {
        let widen = |f: &Factor<V, FMA>| Factor {
            value: U::splat(f.value.first()),
            halves: (U::splat(f.halves.0.first()), U::splat(f.halves.1.first())),
        };
        Factors {
            s: widen(&self.s),
            t: widen(&self.t),
            rho: U::splat(self.rho.first()),
            s_abs: U::splat(self.s_abs.first()),
            refinement: self.refinement,
        }
    }

    /// The levels that may multiply values that are multiples of `2^finest`, as a budget:
    /// a level is covered while the budget is at least [`Factors::refinement`], and spends
    /// that much (so `⌊budget / refinement⌋` levels, without dividing).
    #[inline(always)]
    fn level_budget(&self, finest: i64) -> i64 {
        if FMA {
            // a fused multiply-add is the reference itself
            return i64::MAX / 2;
        }
        finest + 1074
    }
}

/// The ulp exponent of a float: `e − 52` for `2^e ≤ |x| < 2^(e+1)`, `−1074` below `2^−1022`.
#[inline(always)]
fn ulp_exponent(x: f64) -> i64 {
    let biased = ((x.to_bits() >> 52) & 0x7ff) as i64;
    biased.max(1) - 1075
}

/// The finest ulp exponent of the nonzero `values` (`i64::MAX / 4` when all are zero: a
/// zero is a multiple of every power of two).
fn finest_ulp_exponent(values: &[f64]) -> i64 {
    let least = values
        .iter()
        .map(|x| x.abs())
        .filter(|x| *x != 0.0)
        .fold(f64::INFINITY, f64::min);
    if least == f64::INFINITY {
        i64::MAX / 4
    } else {
        ulp_exponent(least)
    }
}

/// `Σ|b_i|` may not exceed this for the triangle to stay below `2^995` ([`MAX_SPLIT`]).
const MAX_ABS_SUM: f64 = MAX_SPLIT / 2.0;

/// Whether a computed `Σ|b_i|` lets the triangle run unchecked: at most [`MAX_ABS_SUM`], and
/// not NaN (a NaN coefficient makes the sum NaN, which every comparison refuses).
#[inline(always)]
fn abs_sum_in_range(sum: f64) -> bool {
    sum <= MAX_ABS_SUM
}

/// Copies `b` into `hi` and `|b_i|` into `abs` (both as long as `b`), and gives the finest
/// ulp exponent of the `b_i`; `None` when `Σ|b_i|` exceeds [`MAX_ABS_SUM`] or is not finite
/// (or NaN).
#[inline(always)]
fn scan(b: &[f64], hi: &mut [f64], abs: &mut [f64]) -> Option<i64> {
    // in two lanes: their sum bounds the largest |b_i| in any order, and a NaN stays NaN
    // (the least value needs no care for NaN: the sum then refuses)
    let smaller = |x: f64, y: f64| if x < y { x } else { y };
    let (mut sum, mut least) = (Pair::splat(0.0), Pair::splat(f64::INFINITY));
    let mut pairs = b.chunks_exact(2);
    let mut copies = hi.chunks_exact_mut(2);
    let mut out = abs.chunks_exact_mut(2);
    for ((x, h), o) in (&mut pairs).zip(&mut copies).zip(&mut out) {
        let x = Pair([x[0], x[1]]);
        x.store(h, 0);
        let a = x.map(f64::abs);
        a.store(o, 0);
        sum = sum + a;
        least = Pair([smaller(a.0[0], least.0[0]), smaller(a.0[1], least.0[1])]);
    }
    let (mut sum, mut least) = (sum.0[0] + sum.0[1], smaller(least.0[0], least.0[1]));
    if let ([x], [h], [o]) = (pairs.remainder(), copies.into_remainder(), out.into_remainder()) {
        *h = *x;
        *o = x.abs();
        sum += *o;
        least = smaller(*o, least);
    }
    if !abs_sum_in_range(sum) {
        return None;
    }
    // a zero coefficient says nothing of the grid: look at the others
    Some(if least == 0.0 {
        finest_ulp_exponent(b)
    } else {
        ulp_exponent(least)
    })
}

/// One level in place: `len` nodes from `hi, lo, abs[0..=len]`, two per step; the buffers
/// hold `len + 3` values at least (the last step reads one pair past the level).
#[inline(always)]
fn level<const FIRST: bool, const FMA: bool>(
    f: &Factors<Pair, FMA>,
    hi: &mut [f64],
    lo: &mut [f64],
    abs: &mut [f64],
    len: usize,
) {
    let (mut a, mut a_lo) = (Pair::load(hi, 0), Pair::load(lo, 0));
    let mut i = 0;
    while i < len {
        let (c, c_lo) = (Pair::load(hi, i + 2), Pair::load(lo, i + 2));
        let (sum, low) = node::<FIRST, _, FMA>(f, a, a_lo, a.shifted(c), a_lo.shifted(c_lo));
        sum.store(hi, i);
        low.store(lo, i);
        (a, a_lo) = (c, c_lo);
        i += 2;
    }
    // the |b_i| triangle's level on its own: fewer values held across the steps above
    let mut a_abs = Pair::load(abs, 0);
    let mut i = 0;
    while i < len {
        let c_abs = Pair::load(abs, i + 2);
        abs_node(f, a_abs, a_abs.shifted(c_abs)).store(abs, i);
        a_abs = c_abs;
        i += 2;
    }
}

/// Nodes of the triangle, one per lane: from the values `a` and their right neighbours `b`
/// (high parts) and `a_lo`, `b_lo` (low parts, zeros on the first level), the new high
/// and low parts.
#[inline(always)]
fn node<const FIRST: bool, V: Lanes, const FMA: bool>(f: &Factors<V, FMA>, a: V, a_lo: V, b: V, b_lo: V) -> (V, V) {
    let (s, t) = (f.s.value, f.t.value);
    let p1 = s * a;
    let e1 = f.s.error(a, p1);
    let p2 = t * b;
    let e2 = f.t.error(b, p2);
    let sum = p1 + p2;
    let e3 = if FMA {
        // FastTwoSum on the addends ordered by magnitude: the same exact error as Knuth's
        // TwoSum (so the same bits, +0 when it is 0 in both), two dependent operations
        // after the sum instead of four; the blend that orders them needs AVX
        let (big, small) = p1.ordered(p2);
        (big - sum) + small
    } else {
        let bb = sum - p1;
        (p1 - (sum - bb)) + (p2 - bb)
    };
    let w = e1 + e2 + e3 + f.rho * a;
    let low = if FIRST {
        w + V::splat(0.0)
    } else {
        w + s * a_lo + t * b_lo
    };
    (sum, low)
}

/// Nodes of the `|b_i|` triangle, one per lane.
#[inline(always)]
fn abs_node<V: Lanes, const FMA: bool>(f: &Factors<V, FMA>, a: V, b: V) -> V {
    f.s_abs * a + f.t.value * b
}

/// A cubic's triangle on values held in registers, where fused multiply-adds give the
/// products' errors (no grid to keep: [`Factors::level_budget`]), with the check of `Σ|b_i|`
/// that [`scan`] makes: the first level's three nodes in one step of four lanes (an AVX
/// register), the second's two in one of two, the last alone. Values are never stored and
/// read back at another width, which stalls the read. The same nodes as [`unrolled`], so
/// the same bits. Only with FMA: without AVX four lanes are two SSE2 registers, and this form was slower there than [`unrolled`] (measured: `git log -p -- docs/performance.md`).
#[inline(always)]
fn cubic<const FMA: bool>(f: &Factors<Pair, FMA>, b: &[f64]) -> Option<(f64, f64, f64)> {
    let x = Wide::<4>([b[0], b[1], b[2], b[3]]);
    let abs = x.map(f64::abs);
    let sum = (abs.0[0] + abs.0[1]) + (abs.0[2] + abs.0[3]);
    if !abs_sum_in_range(sum) {
        return None;
    }
    let (four, two, one) = (f.widen(), f.widen(), f.widen());
    let zero = Wide::splat(0.0);
    // lane 3 of the first level is not a node: it is never read
    let (hi, lo) = node::<true, _, FMA>(&four, x, zero, x.rotated(), zero);
    let abs = abs_node(&four, abs, abs.rotated());
    let (hi, lo) = node::<false, Wide<2>, FMA>(&two, hi.part(0), lo.part(0), hi.part(1), lo.part(1));
    let abs = abs_node(&two, abs.part(0), abs.part(1));
    let (hi, lo) = node::<false, Wide<1>, FMA>(&one, hi.part(0), lo.part(0), hi.part(1), lo.part(1));
    let abs = abs_node(&one, abs.part(0), abs.part(1));
    Some((hi.0[0], lo.0[0], abs.0[0]))
}

/// The triangle on `b` in buffers of `N ≥ len + 2` values: `(hi, lo, the |b_i| triangle)`.
#[inline(always)]
fn looped<const N: usize, const FMA: bool>(f: &Factors<Pair, FMA>, b: &[f64]) -> Option<(f64, f64, f64)> {
    let len = b.len();
    let (mut hi, mut lo, mut abs) = ([0.0; N], [0.0; N], [0.0; N]);
    let mut budget = f.level_budget(scan(b, &mut hi[..len], &mut abs[..len])?);
    for level_len in (1..len).rev() {
        if budget < f.refinement {
            budget = f.level_budget(finest_ulp_exponent(&hi[..=level_len]));
            if budget < f.refinement {
                return None;
            }
        }
        if level_len == len - 1 {
            level::<true, FMA>(f, &mut hi, &mut lo, &mut abs, level_len);
        } else {
            level::<false, FMA>(f, &mut hi, &mut lo, &mut abs, level_len);
        }
        budget -= f.refinement;
    }
    Some((hi[0], lo[0], abs[0]))
}

/// [`looped`] for `LEN` coefficients known at compile time (unrolled, in registers), with
/// one range check up front.
#[inline(always)]
fn unrolled<const LEN: usize, const N: usize, const FMA: bool>(
    f: &Factors<Pair, FMA>,
    b: &[f64],
) -> Option<(f64, f64, f64)> {
    let (mut hi, mut lo, mut abs) = ([0.0; N], [0.0; N], [0.0; N]);
    if f.level_budget(scan(b, &mut hi[..LEN], &mut abs[..LEN])?) < (LEN as i64 - 1) * f.refinement {
        return None;
    }
    level::<true, FMA>(f, &mut hi, &mut lo, &mut abs, LEN - 1);
    for len in (1..LEN - 1).rev() {
        level::<false, FMA>(f, &mut hi, &mut lo, &mut abs, len);
    }
    Some((hi[0], lo[0], abs[0]))
}

/// The bound of compensated de Casteljau for `t ∈ [0, 1]` as one expression,
/// `e = fl(fl(fl(β_n·A) + fl(α·|res|)) + δ_n)`, from the float triangle `A` on `|b_i|`
/// (factors `s' ≥ 1 − t` and `t`). Why it holds, with `Σ = Σ|b_i|B_i^n(t)`:
///
/// - the `|b_i|` triangle rounds nonnegative values only: `Σ ≤ (1 + γ_{2n})A + U₁`, with
///   `U₁ = (n(n+1)/2 + 1)·2^−1074` (the underflow term of `abs_sum_rounded_up`, for a
///   level growth within `1 + 2^−48`, as `s' + t` is);
/// - compensated de Casteljau: `|res − p| ≤ u|p| + 2γ_{3n}²Σ + U₃`, `U₃ = (3n(n+1)/2 + 1)
///   ·2^−1074` (`compensated_underflow`, same growth), and `|p| ≤ |res| + |res − p|`, so
///   `|res − p| ≤ α'|res| + β'_n A + δ'_n` with `α' = u/(1 − u)`,
///   `β'_n = 2γ_{3n}²(1 + γ_{2n})/(1 − u)`, `δ'_n = (2γ_{3n}²U₁ + U₃)/(1 − u)`;
/// - each rounding to nearest of nonnegative values is at least the exact value over
///   `1 + u`, less `2^−1075` for a product that lands among subnormals (a sum of floats is
///   exact there), so `e ≥ β A/(1+u)³ + α|res|/(1+u)³ + δ/(1+u) − 2^−1074`, which is at
///   least the bound above for `β ≥ β'_n(1+u)³`, `α ≥ α'(1+u)³`, `δ ≥ (δ'_n + 2^−1074)(1+u)`:
///   the constants below, rounded up at each step, with `(1 + u)³/(1 − u) ≤ 1 + 8u`.
struct UnitBound;

impl UnitBound {
    /// `α = u(1 + 8u)`, a float.
    const ALPHA: f64 = UNIT_ROUNDOFF * (1.0 + 8.0 * UNIT_ROUNDOFF);

    #[inline(always)]
    fn of(n: usize, abs_triangle: f64, res: f64) -> f64 {
        let (beta, delta) = BOUND_CONSTANTS[n];
        beta * abs_triangle + Self::ALPHA * res.abs() + delta
    }

    /// `(β_n, δ_n)`, each operation rounded up.
    const fn constants(n: usize) -> (f64, f64) {
        const fn mul_up(a: f64, b: f64) -> f64 {
            next_up(a * b)
        }
        const fn add_up(a: f64, b: f64) -> f64 {
            next_up(a + b)
        }
        let g = gamma_computed(3 * n);
        let two_g2 = mul_up(2.0 * g, g);
        let margin = 1.0 + 8.0 * UNIT_ROUNDOFF;
        let beta = mul_up(mul_up(two_g2, add_up(1.0, gamma_computed(2 * n))), margin);
        let nodes = (n * (n + 1) / 2) as u64;
        let (u1, u3) = (f64::from_bits(nodes + 1), f64::from_bits(3 * nodes + 1));
        let delta = mul_up(add_up(add_up(mul_up(two_g2, u1), u3), ETA), margin);
        (beta, delta)
    }
}

/// [`UnitBound::constants`] for every degree below [`MAX_DEGREE`], at compile time.
static BOUND_CONSTANTS: [(f64, f64); MAX_DEGREE] = {
    let mut table = [(0.0, 0.0); MAX_DEGREE];
    let mut n = 1;
    while n < MAX_DEGREE {
        table[n] = UnitBound::constants(n);
        n += 1;
    }
    table
};
