//! One claim's work budget, drawn from while the claim is checked.
//!
//! The exact evaluations of a claim are counted before it starts (`sampling::MAX_WORK`, which
//! theorem claims share), but the searches behind an open range (the WZ ansatz, creative
//! telescoping, the pieces of a symbolic proof) cannot know their work in advance: each has a
//! limit of its own, and together they draw from one [`Budget`] per proof, so a claim that
//! runs several searches in turn still ends within one budget. The budget is a value passed
//! down with the proof (in [`Symbols`](super::hyper::Symbols), which every search receives),
//! never a global: claims are checked in parallel, each with its own.
//!
//! Its unit is a 10¹²th of the whole budget (fine enough that rounding each draw up never
//! matters): each search draws its work in its own units, scaled by the limit it already has
//! ([`Budget::draw`]), so one search alone may spend what its own limit allows, and two
//! searches of one claim share it.

use crate::error::{Error, Result};
use std::cell::Cell;

/// The units of one claim's whole budget.
pub const CLAIM_BUDGET: u128 = 1_000_000_000_000;

/// What lowers a claim's work, said with every spent budget.
const HOW_TO_LOWER: &str = "lower the degrees, the number of integer symbols or the size of the numbers";

/// A claim's work budget: what is left of [`CLAIM_BUDGET`], drawn from as the work is done
/// (a new one is full).
#[derive(Debug, Default)]
pub struct Budget {
    spent: Cell<u128>,
}

impl Budget {
    /// Draws `work` units of a search whose own limit is `limit` units (so `limit` units are
    /// the whole claim's budget), or an error naming `what` and the budget when the claim's
    /// budget is spent. Work is rounded up: a draw is never free.
    pub fn draw(&self, what: &'static str, work: u128, limit: u128) -> Result<()> {
        let units = work.saturating_mul(CLAIM_BUDGET).div_ceil(limit.max(1));
        let spent = self.spent.get().saturating_add(units);
        self.spent.set(spent);
        if spent > CLAIM_BUDGET {
            return Err(Error::TooLarge {
                what,
                value: "more than the claim's budget".into(),
                limit: format!("CLAIM_BUDGET = {CLAIM_BUDGET} units per claim, shared by its searches: {HOW_TO_LOWER}"),
            });
        }
        Ok(())
    }

    /// The units spent so far.
    #[cfg(test)]
    fn spent(&self) -> u128 {
        self.spent.get()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn searches_share_one_budget() {
        let b = Budget::default();
        // Half of one search's limit, then half of another's: the budget is just spent.
        b.draw("first", 50, 100).unwrap();
        b.draw("second", 500, 1000).unwrap();
        assert_eq!(b.spent(), CLAIM_BUDGET);
        let err = b.draw("third", 1, 1_000_000_000).unwrap_err().to_string();
        assert!(err.contains("third") && err.contains("CLAIM_BUDGET"), "{err}");
    }

    #[test]
    fn a_draw_is_never_free_and_never_overflows() {
        let b = Budget::default();
        b.draw("tiny", 1, u128::MAX).unwrap();
        assert_eq!(b.spent(), 1);
        assert!(b.draw("huge", u128::MAX, 1).is_err());
        assert!(b.draw("again", u128::MAX, 1).is_err());
    }
}
