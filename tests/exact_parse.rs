//! Reading `p/q`: the machine-word path (both integers of at most 38 digits) against
//! num-rational's own reduction of the same integers, with `==` and in lowest terms, across
//! the 38/39-digit boundary, signs on either side, zeros, leading zeros and whitespace; and
//! its errors the general path's.

use casteljau::{parse_exact, BigInt, BigRational, Error};
use proptest::prelude::*;
use std::str::FromStr;

/// Digit strings of 1 to 45 digits (both sides of the 38-digit word limit), sometimes
/// with leading zeros.
fn digits() -> impl Strategy<Value = String> {
    (proptest::collection::vec(0u8..10, 1..=45), 0usize..3).prop_map(|(d, zeros)| {
        let mut s = "0".repeat(zeros);
        s.extend(d.iter().map(|&x| char::from(b'0' + x)));
        s
    })
}

fn sign() -> impl Strategy<Value = &'static str> {
    prop_oneof![Just(""), Just("-"), Just("+")]
}

fn naive(p: &str, q: &str) -> BigRational {
    BigRational::new(BigInt::from_str(p).unwrap(), BigInt::from_str(q).unwrap())
}

proptest! {
    #[test]
    fn fractions_read_as_num_rational_reduces_them(
        (sp, p) in (sign(), digits()),
        (sq, q) in (sign(), digits()),
        spaces in any::<bool>(),
    ) {
        let text = if spaces { format!(" {sp}{p} / {sq}{q} ") } else { format!("{sp}{p}/{sq}{q}") };
        let zero_den = q.bytes().all(|b| b == b'0');
        match parse_exact(&text) {
            Ok(r) => {
                prop_assert!(!zero_den);
                let expected = naive(&format!("{sp}{p}"), &format!("{sq}{q}"));
                prop_assert_eq!(format!("{r:?}"), format!("{expected:?}"));
                prop_assert_eq!(r, expected);
            }
            Err(e) => prop_assert!(zero_den && matches!(e, Error::DivisionByZero(_)), "{e}"),
        }
    }

    /// Common factors of every size, so that the reduction has work to do.
    #[test]
    fn shared_factors_are_divided_out(a in 1u128..10u128.pow(12), b in 1u128..10u128.pow(12), g in 1u128..10u128.pow(14)) {
        let (p, q) = ((a * g).to_string(), (b * g).to_string());
        let r = parse_exact(&format!("{p}/{q}")).unwrap();
        prop_assert_eq!(format!("{r:?}"), format!("{:?}", naive(&p, &q)));
    }
}

#[test]
fn edges_of_the_word_path() {
    let max38 = "9".repeat(38);
    for (text, expected) in [
        ("0/5", naive("0", "1")),
        ("-0/-7", naive("0", "1")),
        ("-4/-6", naive("2", "3")),
        ("4/-6", naive("-2", "3")),
        (&format!("{max38}/3") as &str, naive(&max38, "3")),
        (&format!("-{max38}/{max38}"), naive("-1", "1")),
    ] {
        assert_eq!(parse_exact(text).unwrap(), expected, "{text}");
    }
    for bad in ["1/0", "-1/-000", "1/", "/2", "1/2/3", "+/1", "1/ -", "1.5/0", "1/x"] {
        assert!(parse_exact(bad).is_err(), "{bad}");
    }
    // Decimals and exponents on either side still take the general path.
    assert_eq!(parse_exact("1.5/3").unwrap(), naive("1", "2"));
    assert_eq!(parse_exact("1/2e1").unwrap(), naive("1", "20"));
}
