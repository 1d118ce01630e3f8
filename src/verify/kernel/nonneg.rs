//! Certificates of inequalities for every value (`docs/certificates.md`, "Inequalities for
//! every value") and of the two `computation` theorems that rest on cited lemmas (the convex
//! hull and the affine invariance of text 000), kept typed: the goal `lhs ≥ rhs` over integer
//! ranges and an interval, and the nonnegativity obligation of every live term on every piece
//! of the domain, as [`super::bernstein::check_nonneg_pieces`] discharged it (which factor, and
//! why it is ≥ 0: the Bernstein coefficients of each polynomial factor on the interval).

use super::checked::Method;
use super::{Proof, Trusted};
use num_rational::BigRational;
use num_traits::{Signed, Zero};

/// The goal of a for-every inequality: `lhs ≥ rhs` at every integer point of the ranges and
/// every value of the one real symbol in the interval.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct NonnegGoal {
    /// The real symbol (the interval's).
    pub real: String,
    /// The integer ranges: variable, least value, largest value (`None`: open).
    pub for_all: Vec<(String, String, Option<String>)>,
    /// The left side, as it prints.
    pub lhs: String,
    /// The right side, as it prints.
    pub rhs: String,
    /// The interval `[a, b]` of the real symbol.
    pub interval: (BigRational, BigRational),
}

/// Why one factor of a live term is ≥ 0 on the interval.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Why {
    /// A positive constant base (any exponent).
    PositiveConstant,
    /// A coefficient affine in the integers, ≥ 0 on the piece.
    AffineOnPiece,
    /// A polynomial coefficient with positive coefficients in variables ≥ 0.
    PositiveMonomials,
    /// A polynomial in the real symbol whose Bernstein coefficients are ≥ 0.
    Bernstein,
    /// A base whose Bernstein coefficients are ≥ 0 with both end ones > 0 (> 0 on the
    /// interval: any exponent).
    BernsteinPositive,
    /// A base whose Bernstein coefficients are ≥ 0, with an exponent ≥ 0 on the piece.
    ExponentNonneg,
}

impl Why {
    /// The name a certificate writes.
    pub fn name(self) -> &'static str {
        match self {
            Why::PositiveConstant => "positive_constant",
            Why::AffineOnPiece => "affine_on_piece",
            Why::PositiveMonomials => "positive_monomials",
            Why::Bernstein => "bernstein",
            Why::BernsteinPositive => "bernstein_positive",
            Why::ExponentNonneg => "exponent_nonneg",
        }
    }

    /// Whether these Bernstein coefficients show what the reason says (none are needed for
    /// the reasons that are not Bernstein's).
    fn holds_for(self, c: &[BigRational]) -> bool {
        let nonneg = !c.is_empty() && c.iter().all(|x| !x.is_negative());
        match self {
            Why::Bernstein | Why::ExponentNonneg => nonneg,
            Why::BernsteinPositive => {
                nonneg && c.first().is_some_and(Signed::is_positive) && c.last().is_some_and(Signed::is_positive)
            }
            Why::PositiveConstant | Why::AffineOnPiece | Why::PositiveMonomials => c.is_empty(),
        }
    }
}

/// One factor of a live term shown ≥ 0.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Factor {
    /// The factor (a coefficient, or a power's base), as it prints.
    pub factor: String,
    /// A power's exponent (`None` for the coefficient).
    pub exponent: Option<String>,
    /// Why it is ≥ 0.
    pub why: Why,
    /// For a Bernstein reason: the polynomial's coefficients in the Bernstein basis of its
    /// degree on the whole interval (empty otherwise).
    pub bernstein: Vec<BigRational>,
}

/// One live term on a piece: its coefficient, factorials (of arguments ≥ 0 on the piece) and
/// powers, each factor with its reason.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct LiveTerm {
    /// The term, as it prints.
    pub term: String,
    /// Its coefficient.
    pub coefficient: Factor,
    /// Its factorials, `(a)!` or `1/(a)!`.
    pub factorials: Vec<String>,
    /// Its powers.
    pub powers: Vec<Factor>,
}

/// One piece of the domain and its live terms.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Piece {
    /// The piece, as the conditions on the integers that define it.
    pub region: String,
    /// Its live terms.
    pub terms: Vec<LiveTerm>,
}

/// A for-every inequality's goal and the obligations the kernel discharged for it.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Nonneg {
    /// The goal.
    pub goal: NonnegGoal,
    /// Every piece of the domain with its live terms.
    pub pieces: Vec<Piece>,
}

/// Whether every recorded factor's Bernstein coefficients show its reason: the record a file
/// lists is compared with the kernel's own derivation by the caller, and is checked here to
/// prove what it says (no negative coefficient of a factor shown ≥ 0 by them).
pub fn check_record(pieces: &[Piece]) -> bool {
    !pieces.is_empty()
        && pieces.iter().all(|p| {
            p.terms.iter().all(|t| {
                std::iter::once(&t.coefficient)
                    .chain(&t.powers)
                    .all(|f| f.why.holds_for(&f.bernstein))
            })
        })
}

/// The goal `B(i, n, t) ≥ 0` for `n ≥ 0`, `0 ≤ i ≤ n`, `t ∈ [0, 1]` (the convex hull's first
/// lemma).
pub fn basis_nonneg_goal() -> NonnegGoal {
    NonnegGoal {
        real: "t".into(),
        for_all: vec![
            ("n".into(), "0".into(), None),
            ("i".into(), "0".into(), Some("n".into())),
        ],
        lhs: "B(i, n, t)".into(),
        rhs: "0".into(),
        interval: (BigRational::zero(), BigRational::from_integer(1.into())),
    }
}

/// The members of the chain `Σ_{i=0}^{n} B(i, n, t) = 1` (the lemma both theorems cite), for
/// every real `t` and every `n ≥ 0`.
pub const UNITY_MEMBERS: [&str; 2] = ["sum(i, 0, n, B(i, n, t))", "1"];

/// The goal `Σ_{i=0}^{n} B(i, n, t) = 1` for every real `t` and `n ≥ n₀` with `n₀ ≤ lo`: the
/// chain's members, the real symbols and the range `(n, n₀, open)`.
pub struct Unity<'a> {
    /// The chain's members.
    pub members: &'a [String],
    /// The real symbols.
    pub reals: &'a [String],
    /// The integer ranges.
    pub for_all: &'a [(String, String, Option<String>)],
}

fn is_unity(u: &Unity<'_>, lo: i64) -> bool {
    let from_ok = |f: &str| f.parse::<i64>().is_ok_and(|f| f <= lo);
    u.members == UNITY_MEMBERS
        && u.reals == ["t"]
        && matches!(u.for_all, [(n, from, None)] if n == "n" && from_ok(from))
}

/// The convex hull property for `n = lo..=hi`: `b(t) = Σ_i B_i^n(t) b_i` (the curve in the
/// Bernstein form the library evaluates, `bernstein_all`) with `B_i^n(t) ≥ 0` on `[0, 1]` and
/// `Σ_i B_i^n(t) = 1` — the two cited lemmas' goals, exactly these, for every `n ≥ 0` — is a
/// convex combination of the control points. The lemmas themselves are proved in their own
/// files (checked by the caller).
pub fn check_convex_combination(lo: i64, hi: i64, nonneg: &NonnegGoal, unity: &Unity<'_>) -> Option<Proof> {
    (0 <= lo && lo <= hi && *nonneg == basis_nonneg_goal() && is_unity(unity, lo))
        .then(|| Proof::new(Method::Computation, &[Trusted::BernsteinAll]))
}

/// Affine invariance for `n = lo..=hi`: `Φ(p) = A p + c` and the curve `Σ_i b_i B_i^n(t)`, so
/// `Φ(Σ b_i B_i) = Σ (A b_i) B_i + c = Σ (A b_i + c) B_i` by linearity and the cited lemma
/// `Σ_i B_i^n(t) = 1` (its goal, exactly, for every `n ≥ n₀ ≤ lo`); `transformed`: the
/// library's `transform` maps each control point by `Φ` on every basis input the caller ran.
pub fn check_affine_invariance(lo: i64, hi: i64, unity: &Unity<'_>, transformed: bool) -> Option<Proof> {
    (0 <= lo && lo <= hi && transformed && is_unity(unity, lo))
        .then(|| Proof::new(Method::Computation, &[Trusted::Transform]))
}

#[cfg(test)]
mod tests {
    use super::*;

    fn q(n: i64) -> BigRational {
        BigRational::from_integer(n.into())
    }

    fn goal() -> NonnegGoal {
        basis_nonneg_goal()
    }

    #[test]
    fn records_and_lemma_goals_are_checked() {
        let factor = |why, c: Vec<i64>| Factor {
            factor: "t".into(),
            exponent: Some("i".into()),
            why,
            bernstein: c.into_iter().map(q).collect(),
        };
        let piece = |f: Factor| Piece {
            region: "n ≥ 0".into(),
            terms: vec![LiveTerm {
                term: "t^(i)".into(),
                coefficient: factor(Why::PositiveConstant, vec![]),
                factorials: vec![],
                powers: vec![f],
            }],
        };
        assert!(check_record(&[piece(factor(Why::ExponentNonneg, vec![0, 1]))]));
        assert!(!check_record(&[piece(factor(Why::ExponentNonneg, vec![0, -1]))]));
        assert!(!check_record(&[piece(factor(Why::BernsteinPositive, vec![0, 1]))]));
        assert!(!check_record(&[piece(factor(Why::ExponentNonneg, vec![]))]));
        assert!(!check_record(&[]));
        let (members, reals) = (
            vec!["sum(i, 0, n, B(i, n, t))".to_string(), "1".into()],
            vec!["t".to_string()],
        );
        let for_all = vec![("n".to_string(), "0".to_string(), None)];
        let unity = Unity {
            members: &members,
            reals: &reals,
            for_all: &for_all,
        };
        assert!(check_convex_combination(0, 8, &goal(), &unity).is_some());
        let mut wide = goal();
        wide.interval.1 = q(2);
        assert!(check_convex_combination(0, 8, &wide, &unity).is_none());
        let late = vec![("n".to_string(), "1".to_string(), None)];
        let later = Unity {
            for_all: &late,
            ..unity
        };
        assert!(check_convex_combination(0, 8, &goal(), &later).is_none());
        assert!(check_affine_invariance(0, 8, &unity, true).is_some());
        assert!(check_affine_invariance(0, 8, &unity, false).is_none());
    }
}
