//! Certificates of for-every proofs on the pieces of a domain (methods `pieces` and `wz`,
//! `docs/certificates.md`): the goal over integer ranges (`for_all`), with its polygon or net,
//! and the WZ certificates `R` of its symbolic sums. The kernel's obligations are built from
//! the goal by the translation into hypergeometric terms, the same on writing and on
//! re-checking, so the re-check translates the goal again and runs the same kernel checks.

use super::super::kernel::certificate::Symbolic;
use super::super::symbolic::written::prove_written;
use super::{array, field, method_name, string, Res};
use serde_json::{json, Value as Json};

/// The goal and the data of a written for-every proof.
pub(super) fn fields(s: &Symbolic) -> (Json, Json) {
    let mut symbols: Vec<Json> = s.reals.iter().map(|n| json!({"name": n, "sort": "real"})).collect();
    symbols.extend(s.for_all.iter().map(|(n, ..)| json!({"name": n, "sort": "integer"})));
    let for_all: Vec<Json> = s
        .for_all
        .iter()
        .map(|(n, from, to)| json!({"name": n, "from": from, "to": to}))
        .collect();
    let equalities: Vec<Json> = s
        .members
        .windows(2)
        .map(|p| json!({"lhs": p[0], "rhs": p[1]}))
        .collect();
    let mut goal = json!({"relation": "=", "symbols": symbols, "for_all": for_all, "equalities": equalities});
    if let Some((name, degree)) = &s.polygon {
        goal["polygon"] = json!({"name": name, "degree": degree});
    }
    if let Some((name, degree)) = &s.net {
        goal["net"] = json!({"name": name, "degree": degree});
    }
    (goal, json!({"certificates": s.certificates}))
}

/// An optional `{"name", "degree"}` object of the goal.
fn object<'a>(g: &'a Json, key: &str) -> Res<Option<(String, &'a Json)>> {
    match g.get(key) {
        None => Ok(None),
        Some(o) => {
            let at = format!("goal.{key}");
            Ok(Some((string(o, "name", &at)?.to_string(), field(o, "degree", &at)?)))
        }
    }
}

/// Reads a written goal back (see [`fields`]).
fn read(cert: &Json) -> Res<Symbolic> {
    let g = field(cert, "goal", "certificate")?;
    if string(g, "relation", "goal")? != "=" {
        return Err("goal.relation: only '=' is defined".into());
    }
    let (mut reals, mut ints) = (Vec::new(), Vec::new());
    for (i, s) in array(g, "symbols", "goal")?.iter().enumerate() {
        let at = format!("goal.symbols[{i}]");
        let name = string(s, "name", &at)?.to_string();
        if reals.contains(&name) || ints.contains(&name) {
            return Err(format!("{at}: '{name}' is declared twice"));
        }
        match string(s, "sort", &at)? {
            "real" => reals.push(name),
            "integer" => ints.push(name),
            other => return Err(format!("{at}.sort: '{other}' is not real or integer")),
        }
    }
    let mut for_all = Vec::new();
    for (i, r) in array(g, "for_all", "goal")?.iter().enumerate() {
        let at = format!("goal.for_all[{i}]");
        let name = string(r, "name", &at)?.to_string();
        if ints.get(i) != Some(&name) {
            return Err(format!("{at}: '{name}' is not the integer symbol {i} of the goal"));
        }
        let to = match field(r, "to", &at)? {
            Json::Null => None,
            _ => Some(string(r, "to", &at)?.to_string()),
        };
        for_all.push((name, string(r, "from", &at)?.to_string(), to));
    }
    if for_all.len() != ints.len() || !for_all.iter().any(|r| r.2.is_none()) {
        return Err("goal.for_all: one range per integer symbol, at least one open (to: null)".into());
    }
    let polygon = match object(g, "polygon")? {
        Some((name, d)) => Some((name, d.as_str().ok_or("goal.polygon.degree: not a string")?.to_string())),
        None => None,
    };
    let net = match object(g, "net")? {
        Some((name, d)) => {
            let d: Vec<&str> = d.as_array().into_iter().flatten().filter_map(Json::as_str).collect();
            match d[..] {
                [m, n] => Some((name, [m.to_string(), n.to_string()])),
                _ => return Err("goal.net.degree: not two strings".into()),
            }
        }
        None => None,
    };
    let mut members: Vec<String> = Vec::new();
    for (i, eq) in array(g, "equalities", "goal")?.iter().enumerate() {
        let at = format!("goal.equalities[{i}]");
        let (l, r) = (string(eq, "lhs", &at)?, string(eq, "rhs", &at)?);
        match members.last() {
            None => members.push(l.to_string()),
            Some(last) if last != l => {
                return Err(format!("{at}.lhs: not the right side of the equality before (a chain)"))
            }
            Some(_) => {}
        }
        members.push(r.to_string());
    }
    if members.is_empty() {
        return Err("goal.equalities: none".into());
    }
    let p = field(cert, "pieces", "certificate")?;
    let certificates = array(p, "certificates", "pieces")?
        .iter()
        .enumerate()
        .map(|(i, c)| {
            c.as_str()
                .map(str::to_string)
                .ok_or_else(|| format!("pieces.certificates[{i}]: not a string"))
        })
        .collect::<Res<_>>()?;
    Ok(Symbolic {
        reals,
        for_all,
        polygon,
        net,
        members,
        certificates,
    })
}

/// Re-checks a written for-every proof: the goal translated again and every obligation proved
/// by the kernel, by the method the file names.
pub(super) fn recheck(cert: &Json, method: &str) -> Res<String> {
    let goal = read(cert)?;
    let (derived, obligations) = prove_written(&goal).map_err(|e| format!("the goal's obligations: {e}"))?;
    if method_name(derived) != method {
        return Err(format!(
            "method: the file says {method}, the kernel's proof is {}",
            method_name(derived)
        ));
    }
    Ok(format!(
        "for every value of the open ranges: the goal translated again, {obligations} kernel checks passed ({})",
        derived.text()
    ))
}
