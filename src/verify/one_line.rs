//! One identity from the command line (`casteljau prove --identity "lhs = rhs"`), made into
//! the claim a claim file with the same fields would give, by the same reading.

use super::claims::{Claim, ClaimFile};
use crate::error::{Error, Result};
use std::path::PathBuf;

/// The claim `casteljau prove --identity` checks: `lhs = rhs` (or a chain `a = b = c`) with
/// its `for` ranges and `vars`, read exactly as the same fields of a claim file (id `identity`).
///
/// ```
/// use casteljau::verify::{identity_file, prove_files, Verdict};
/// let file = identity_file("sum(k, 0, n, C(n, k)) = 2^n", &["n = 0..".to_string()], None).unwrap();
/// let report = prove_files(&[file], &mut |_, _, _| {}).unwrap();
/// assert_eq!(report.outcomes[0].verdict, Verdict::Proved);
/// // a false identity fails with an exact counterexample
/// let file = identity_file("t^2 = t", &[], None).unwrap();
/// let report = prove_files(&[file], &mut |_, _, _| {}).unwrap();
/// assert_eq!(report.outcomes[0].verdict, Verdict::Fails);
/// // what is not an identity is refused with the expected form
/// assert!(identity_file("t <= 1", &[], None).is_err());
/// ```
pub fn identity_file(identity: &str, ranges: &[String], vars: Option<&[String]>) -> Result<ClaimFile> {
    let members = identity_members(identity)?;
    let strings = |v: &[String]| toml::Value::Array(v.iter().cloned().map(toml::Value::String).collect());
    let mut statement = identity.trim().to_string();
    if !ranges.is_empty() {
        statement = format!("{statement}, for {}", ranges.join(", "));
    }
    let mut t = toml::Table::new();
    for (k, v) in [("id", "identity"), ("source", "command line"), ("kind", "identity")] {
        t.insert(k.into(), toml::Value::String(v.into()));
    }
    t.insert("statement".into(), toml::Value::String(statement));
    match members.as_slice() {
        [l, r] => {
            t.insert("lhs".into(), toml::Value::String(l.clone()));
            t.insert("rhs".into(), toml::Value::String(r.clone()));
        }
        chain => _ = t.insert("chain".into(), strings(chain)),
    }
    if !ranges.is_empty() {
        t.insert("for".into(), strings(ranges));
    }
    if let Some(vars) = vars {
        t.insert("vars".into(), strings(vars));
    }
    let claim = Claim::from_table(t).map_err(|e| Error::Parse(format!("--identity: {}", e.with_syntax())))?;
    Ok(ClaimFile {
        text: None,
        claim: vec![claim],
        path: PathBuf::from("command line"),
        builtin: false,
    })
}

/// The members of `a = b` or `a = b = c`, split at each `=` outside brackets; `==`, `<=`,
/// `>=` and `!=` are refused (an inequality is a claim file's `kind = "inequality"`).
fn identity_members(identity: &str) -> Result<Vec<String>> {
    let bad = |why: &str| {
        Error::Parse(format!(
            "--identity: {why}; expected: \"lhs = rhs\", e.g. \"sum(k, 0, n, C(n, k)) = 2^n\""
        ))
    };
    let (mut members, mut depth, mut from) = (Vec::new(), 0i32, 0);
    let bytes = identity.as_bytes();
    for (i, &b) in bytes.iter().enumerate() {
        match b {
            b'(' | b'[' => depth += 1,
            b')' | b']' => depth -= 1,
            b'=' if depth == 0 => {
                let prev = i.checked_sub(1).map(|j| bytes[j]);
                if matches!(prev, Some(b'<' | b'>' | b'!' | b'=')) || bytes.get(i + 1) == Some(&b'=') {
                    return Err(bad(
                        "only '=' is an identity's relation (an inequality needs a claim file)",
                    ));
                }
                members.push(identity[from..i].trim().to_string());
                from = i + 1;
            }
            _ => {}
        }
    }
    members.push(identity[from..].trim().to_string());
    if members.len() < 2 {
        return Err(bad("no '=' between two sides"));
    }
    if members.iter().any(String::is_empty) {
        return Err(bad("a side is empty"));
    }
    Ok(members)
}
