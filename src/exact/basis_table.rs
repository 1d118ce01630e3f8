//! [`BernsteinTable`]: Bernstein values at sample parameters, computed once and shared.
//!
//! A polynomial identity of degree ≤ d holds iff it holds at d + 1 distinct points. At the
//! integers `t = 0, 1, …, d` every Bernstein value `B_j^n(k) = C(n,j) kʲ (1−k)^(n−j)` is an
//! integer — no fraction, no gcd; at a rational `t = p/q` the values share the denominator
//! `qⁿ`. A proof engine checks many claims at the same few parameters, so the rows are
//! cached: a table is `Sync`, held across claims and read by parallel workers (a read lock
//! per lookup; a row is computed outside any lock and shared as an [`Arc`]). Evaluators on
//! machine words read the rows as [`SmallRational`]s ([`BernsteinTable::at_small`]), through a
//! per-thread memo of the last few rows, which spares the lock and the hash.
//!
//! Limits: a row's degree is at most [`MAX_TABLE_DEGREE`] and its estimated size at most
//! [`MAX_ROW_BITS`] (larger requests are [`Error::TooLarge`]); the table keeps at most
//! [`MAX_TABLE_BITS`] bits of integers and hands out rows computed beyond that budget
//! without keeping them, so memory stays bounded whatever the claims ask.
//!
//! ```
//! use casteljau::{BernsteinTable, BigInt, BigRational, Scalar};
//! let table = BernsteinTable::shared();
//! // B_j^3(2) = C(3,j) 2^j (-1)^(3-j): -1, 6, -12, 8
//! let row = table.at_integer(3, 2).unwrap();
//! assert_eq!(row[..], [(-1).into(), 6.into(), (-12).into(), BigInt::from(8)]);
//! // at t = 1/3, over the denominator 3^3 = 27
//! let third = BigRational::from_ratio(1, 3).unwrap();
//! let row = table.at_rational(3, &third).unwrap();
//! assert_eq!(row.denominator(), &BigInt::from(27));
//! assert_eq!(row.value(1), &BigRational::from_ratio(4, 9).unwrap());
//! assert_eq!(table.bernstein(1, 3, &third).unwrap(), casteljau::bernstein(1, 3, &third).unwrap());
//! ```

use super::SmallRational;
use crate::error::{Error, Result};
use num_bigint::BigInt;
use num_rational::BigRational;
use num_traits::{One, Zero};
use std::cell::RefCell;
use std::collections::HashMap;
use std::hash::Hash;
use std::sync::{Arc, OnceLock, RwLock};

/// Largest degree of a cached Bernstein row (the proof engine's exponent limit).
pub const MAX_TABLE_DEGREE: usize = 4_096;

/// Largest size of one row, estimated before computing it: `(n + 1)` entries of at most
/// `n (1 + max(bits(a), bits(b)))` bits for `C(n,j) aʲ b^(n−j)` (64 MiB of integers).
pub const MAX_ROW_BITS: u64 = 1 << 29;

/// Largest number of integer bits a [`BernsteinTable`] keeps (32 MiB); rows computed past
/// it are returned but not kept.
pub const MAX_TABLE_BITS: u64 = 1 << 28;

/// The Bernstein values `B_0^n(t), …, B_n^n(t)` at a rational `t = p/q`: integer
/// numerators over the common denominator `qⁿ`, and the reduced values.
#[derive(Clone, Debug, PartialEq)]
pub struct RationalBasisRow {
    numerators: Vec<BigInt>,
    denominator: BigInt,
    values: Vec<BigRational>,
}

impl RationalBasisRow {
    /// `C(n,j) pʲ (q−p)^(n−j)`, `j = 0..=n`.
    pub fn numerators(&self) -> &[BigInt] {
        &self.numerators
    }

    /// `qⁿ`.
    pub fn denominator(&self) -> &BigInt {
        &self.denominator
    }

    /// `B_j^n(t)` reduced, `j = 0..=n`.
    pub fn values(&self) -> &[BigRational] {
        &self.values
    }

    /// `B_j^n(t)`; `j ≤ n` (panics otherwise, like slice indexing).
    pub fn value(&self, j: usize) -> &BigRational {
        &self.values[j]
    }

    /// The degree `n`.
    pub fn degree(&self) -> usize {
        self.values.len() - 1
    }
}

/// One cache: rows by key, and the bits they hold.
struct Cache<K, V> {
    rows: RwLock<(HashMap<K, Arc<V>>, u64)>,
}

impl<K: Eq + Hash + Clone, V> Cache<K, V> {
    fn new() -> Self {
        Cache {
            rows: RwLock::new((HashMap::new(), 0)),
        }
    }

    /// The row for `key`, computing it (outside the lock) with `make` on a miss.
    fn get_or(&self, key: &K, make: impl FnOnce() -> (V, u64)) -> Arc<V> {
        if let Some(row) = self.rows.read().unwrap_or_else(|e| e.into_inner()).0.get(key) {
            return Arc::clone(row);
        }
        let (row, bits) = make();
        let row = Arc::new(row);
        let mut guard = self.rows.write().unwrap_or_else(|e| e.into_inner());
        let (map, used) = &mut *guard;
        if let Some(existing) = map.get(key) {
            // Another thread computed it meanwhile: share theirs, so equal keys give one row.
            return Arc::clone(existing);
        }
        if *used + bits <= MAX_TABLE_BITS {
            *used += bits;
            map.insert(key.clone(), Arc::clone(&row));
        }
        row
    }

    /// The row for `key` if it is kept.
    fn get(&self, key: &K) -> Option<Arc<V>> {
        self.rows
            .read()
            .unwrap_or_else(|e| e.into_inner())
            .0
            .get(key)
            .map(Arc::clone)
    }

    fn len(&self) -> usize {
        self.rows.read().unwrap_or_else(|e| e.into_inner()).0.len()
    }
}

/// Cached binomial rows and Bernstein rows at integer and rational parameters. See the
/// [module documentation](self).
pub struct BernsteinTable {
    binomials: Cache<usize, Vec<BigInt>>,
    integer: Cache<(usize, i64), Vec<BigInt>>,
    rational: Cache<RationalKey, RationalBasisRow>,
    small: Cache<RationalKey, Vec<SmallRational>>,
}

/// The key of a rational row: degree and `t`, as words when they fit (no allocation and no
/// continued-fraction hash of a [`BigRational`] per lookup).
#[derive(Clone, PartialEq, Eq, Hash)]
enum RationalKey {
    Words(usize, i64, i64),
    Big(usize, BigInt, BigInt),
}

impl RationalKey {
    fn new(n: usize, t: &BigRational) -> Self {
        match (i64::try_from(t.numer()), i64::try_from(t.denom())) {
            (Ok(p), Ok(q)) => RationalKey::Words(n, p, q),
            _ => RationalKey::Big(n, t.numer().clone(), t.denom().clone()),
        }
    }
}

impl RationalKey {
    fn of_small(n: usize, t: &SmallRational) -> Self {
        match t.as_words() {
            Some((p, q)) => RationalKey::Words(n, p, q),
            None => RationalKey::new(n, &BigRational::from(t)),
        }
    }
}

/// How many small rows each thread keeps at hand.
const RECENT_SMALL: usize = 4;

thread_local! {
    /// The small rows this thread read last. A formula reads `B(0..=n, n, t)` at one `t`, often
    /// beside one or two other degrees, so most lookups need neither the lock (a cache line
    /// shared by every worker) nor a hash. A row is a function of `(n, t)` alone, so the
    /// same memo serves every table.
    static RECENT: RefCell<Vec<(RationalKey, Arc<Vec<SmallRational>>)>> = const { RefCell::new(Vec::new()) };
}

fn recent_small(key: &RationalKey) -> Option<Arc<Vec<SmallRational>>> {
    RECENT.with(|r| {
        r.borrow()
            .iter()
            .find(|(k, _)| k == key)
            .map(|(_, row)| Arc::clone(row))
    })
}

fn remember_small(key: RationalKey, row: &Arc<Vec<SmallRational>>) {
    RECENT.with(|r| {
        let mut r = r.borrow_mut();
        if r.len() == RECENT_SMALL {
            r.remove(0);
        }
        r.push((key, Arc::clone(row)));
    });
}

impl Default for BernsteinTable {
    fn default() -> Self {
        Self::new()
    }
}

impl std::fmt::Debug for BernsteinTable {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(
            f,
            "BernsteinTable {{ binomial rows: {}, integer rows: {}, rational rows: {} }}",
            self.binomials.len(),
            self.integer.len(),
            self.rational.len()
        )
    }
}

fn check_table_degree(n: usize) -> Result<()> {
    if n > MAX_TABLE_DEGREE {
        return Err(Error::TooLarge {
            what: "degree of a cached Bernstein row",
            value: n.to_string(),
            limit: MAX_TABLE_DEGREE.to_string(),
        });
    }
    Ok(())
}

/// Checks the size estimate of a row `C(n,j) aʲ b^(n−j)` against [`MAX_ROW_BITS`].
fn check_row_size(n: usize, a: &BigInt, b: &BigInt) -> Result<()> {
    let n = n as u128;
    let estimate = (n + 1) * n * (1 + a.bits().max(b.bits()) as u128);
    if estimate > MAX_ROW_BITS as u128 {
        return Err(Error::TooLarge {
            what: "size of a Bernstein row (bits, estimated)",
            value: estimate.to_string(),
            limit: MAX_ROW_BITS.to_string(),
        });
    }
    Ok(())
}

fn bits(row: &[BigInt]) -> u64 {
    row.iter().map(|x| x.bits() + 64).sum()
}

/// `C(n,j) aʲ b^(n−j)` for `j = 0..=n`, from a binomial row.
fn bernstein_products(binomials: &[BigInt], a: &BigInt, b: &BigInt) -> Vec<BigInt> {
    let n = binomials.len() - 1;
    // b^(n−j) from the top down, then aʲ from the bottom up.
    let mut b_powers = Vec::with_capacity(n + 1);
    let mut acc = BigInt::one();
    for _ in 0..=n {
        b_powers.push(acc.clone());
        acc *= b;
    }
    let mut a_power = BigInt::one();
    let mut row = Vec::with_capacity(n + 1);
    for (j, c) in binomials.iter().enumerate() {
        row.push(c * &a_power * &b_powers[n - j]);
        a_power *= a;
    }
    row
}

impl BernsteinTable {
    /// An empty table.
    pub fn new() -> Self {
        BernsteinTable {
            binomials: Cache::new(),
            integer: Cache::new(),
            rational: Cache::new(),
            small: Cache::new(),
        }
    }

    /// One table for the whole process, for callers that do not keep their own.
    pub fn shared() -> &'static BernsteinTable {
        static SHARED: OnceLock<BernsteinTable> = OnceLock::new();
        SHARED.get_or_init(BernsteinTable::new)
    }

    /// `C(n, 0), …, C(n, n)`.
    pub fn binomials(&self, n: usize) -> Result<Arc<Vec<BigInt>>> {
        check_table_degree(n)?;
        Ok(self.binomials.get_or(&n, || {
            let row = crate::bernstein::binomial_row(n);
            let b = bits(&row);
            (row, b)
        }))
    }

    /// `B_j^n(k) = C(n,j) kʲ (1−k)^(n−j)`, `j = 0..=n`: integers.
    pub fn at_integer(&self, n: usize, k: i64) -> Result<Arc<Vec<BigInt>>> {
        check_table_degree(n)?;
        let (a, b) = (BigInt::from(k), BigInt::one() - k);
        check_row_size(n, &a, &b)?;
        let binomials = self.binomials(n)?;
        Ok(self.integer.get_or(&(n, k), || {
            let row = bernstein_products(&binomials, &a, &b);
            let b = bits(&row);
            (row, b)
        }))
    }

    /// The rows at `t = 0, 1, …, d`: the sample points of a degree-`d` check.
    pub fn at_integers(&self, n: usize, d: usize) -> Result<Vec<Arc<Vec<BigInt>>>> {
        (0..=d as i64).map(|k| self.at_integer(n, k)).collect()
    }

    /// `B_j^n(t)`, `j = 0..=n`, at a rational `t`, over the common denominator `qⁿ`.
    pub fn at_rational(&self, n: usize, t: &BigRational) -> Result<Arc<RationalBasisRow>> {
        check_table_degree(n)?;
        let (p, q) = (t.numer(), t.denom());
        let s = q - p;
        check_row_size(n, p, &s)?;
        let binomials = self.binomials(n)?;
        Ok(self.rational.get_or(&RationalKey::new(n, t), || {
            let numerators = bernstein_products(&binomials, p, &s);
            let denominator = num_traits::pow(q.clone(), n);
            let values = numerators
                .iter()
                .map(|x| BigRational::new(x.clone(), denominator.clone()))
                .collect::<Vec<_>>();
            let b = 2 * bits(&numerators) + values.iter().map(|v| v.denom().bits() + 64).sum::<u64>();
            (
                RationalBasisRow {
                    numerators,
                    denominator,
                    values,
                },
                b,
            )
        }))
    }

    /// The row of [`Self::at_rational`] as [`SmallRational`]s, for evaluators on machine
    /// words: a lookup costs no conversion and no allocation.
    pub fn at_small(&self, n: usize, t: &SmallRational) -> Result<Arc<Vec<SmallRational>>> {
        let key = RationalKey::of_small(n, t);
        if let Some(row) = recent_small(&key) {
            return Ok(row);
        }
        let row = self.small_row(n, t, &key)?;
        // Only rows on words: their size is bounded by the degree limit (64 KiB), so the
        // memo never pins big rows the table itself declined to keep.
        if row.iter().all(SmallRational::is_small) {
            remember_small(key, &row);
        }
        Ok(row)
    }

    fn small_row(&self, n: usize, t: &SmallRational, key: &RationalKey) -> Result<Arc<Vec<SmallRational>>> {
        if let Some(row) = self.small.get(key) {
            return Ok(row);
        }
        let row = self.at_rational(n, &BigRational::from(t))?;
        Ok(self.small.get_or(key, || {
            let values: Vec<SmallRational> = row.values().iter().map(SmallRational::from).collect();
            let b = values
                .iter()
                .map(|v| {
                    if v.is_small() {
                        128
                    } else {
                        64 + 2 * BigRational::from(v).denom().bits()
                    }
                })
                .sum();
            (values, b)
        }))
    }

    /// `B_i^n(t)` with the convention of the formulas: zero outside `0 ≤ i ≤ n`; a negative
    /// `n` is an error.
    pub fn bernstein(&self, i: i64, n: i64, t: &BigRational) -> Result<BigRational> {
        let degree = usize::try_from(n).map_err(|_| Error::Domain(format!("Bernstein degree {n} is negative")))?;
        if i < 0 || i > n {
            return Ok(BigRational::zero());
        }
        Ok(self.at_rational(degree, t)?.value(i as usize).clone())
    }

    /// `B_i^n(k)` at an integer `k`; zero outside `0 ≤ i ≤ n`.
    pub fn bernstein_at_integer(&self, i: usize, n: usize, k: i64) -> Result<BigInt> {
        if i > n {
            return Ok(BigInt::zero());
        }
        Ok(self.at_integer(n, k)?[i].clone())
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::scalar::{Ring, Scalar};

    #[test]
    fn rows_match_the_formula_and_are_shared() {
        let table = BernsteinTable::new();
        for n in 0..8usize {
            for k in -3..=5i64 {
                let row = table.at_integer(n, k).unwrap();
                for (j, b) in row.iter().enumerate() {
                    let expect = crate::bernstein::bernstein(j, n, &BigRational::from_i64(k)).unwrap();
                    assert_eq!(BigRational::from_integer(b.clone()), expect, "B_{j}^{n}({k})");
                }
                assert!(Arc::ptr_eq(&row, &table.at_integer(n, k).unwrap()));
            }
        }
        let t = BigRational::from_ratio(-2, 7).unwrap();
        let row = table.at_rational(5, &t).unwrap();
        assert_eq!(row.degree(), 5);
        for j in 0..=5 {
            assert_eq!(row.value(j), &crate::bernstein::bernstein(j, 5, &t).unwrap());
            assert_eq!(
                row.value(j),
                &BigRational::new(row.numerators()[j].clone(), row.denominator().clone())
            );
        }
        assert_eq!(table.bernstein(6, 5, &t).unwrap(), BigRational::from_i64(0));
        assert_eq!(table.bernstein(-1, 5, &t).unwrap(), BigRational::from_i64(0));
        assert!(table.bernstein(0, -1, &t).is_err());
        assert!(matches!(
            table.at_integer(MAX_TABLE_DEGREE + 1, 1),
            Err(Error::TooLarge { .. })
        ));
        assert!(format!("{table:?}").contains("rational rows: 1"));
    }

    #[test]
    fn small_rows_are_the_rational_rows_as_words() {
        let table = BernsteinTable::new();
        for (p, q) in [(0, 1), (1, 3), (-2, 7), (5, 4)] {
            let t = BigRational::from_ratio(p, q).unwrap();
            let small = SmallRational::from(&t);
            for n in [0usize, 1, 5, 40] {
                let row = table.at_small(n, &small).unwrap();
                let values: Vec<SmallRational> = table
                    .at_rational(n, &t)
                    .unwrap()
                    .values()
                    .iter()
                    .map(SmallRational::from)
                    .collect();
                assert_eq!(*row, values, "n = {n}, t = {t}");
                assert!(Arc::ptr_eq(&row, &table.at_small(n, &small).unwrap()));
            }
        }
        // A parameter past machine words is a big key, still exact.
        let t = BigRational::new(1.into(), num_traits::pow(BigInt::from(3), 50));
        let row = table.at_small(3, &SmallRational::from(&t)).unwrap();
        assert_eq!(BigRational::from(&row[3]), &t * &t * &t);
        assert!(!row[3].is_small());
    }

    #[test]
    fn parallel_readers_see_one_row() {
        let table = BernsteinTable::new();
        let rows: Vec<_> = std::thread::scope(|scope| {
            let handles: Vec<_> = (0..4)
                .map(|_| scope.spawn(|| table.at_integer(40, 7).unwrap()))
                .collect();
            handles.into_iter().map(|h| h.join().unwrap()).collect()
        });
        assert!(rows.windows(2).all(|w| w[0] == w[1]));
    }
}
