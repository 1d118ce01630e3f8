//! Certificates of for-every proofs on the pieces of a domain (methods `pieces` and `wz`,
//! `docs/certificates.md`): the goal over integer ranges (`for_all`), with its polygon or net,
//! and the WZ certificates `R` of its symbolic sums. The kernel's obligations are built from
//! the goal by the translation into hypergeometric terms, the same on writing and on
//! re-checking, so the re-check translates the goal again and runs the same kernel checks.

use super::super::kernel::certificate::Symbolic;
use super::super::symbolic::written::prove_written;
use super::{array, field, method_name, string, Res};
use serde_json::{json, Value as Json};

/// The goal, the data and the cited lemmas (`[{"id", "goal"}]`, empty when none) of a written
/// for-every proof.
pub(super) fn fields(s: &Symbolic) -> (Json, Json, Vec<Json>) {
    let lemmas = s
        .lemmas
        .iter()
        .map(|(id, g)| json!({"id": id, "goal": goal_json(g)}))
        .collect();
    let mut data = json!({"certificates": s.certificates});
    if let Some(var) = &s.induction {
        data["induction"] = json!(var);
    }
    (goal_json(s), data, lemmas)
}

/// The goal of a written for-every proof (its statement, no proof data).
pub(super) fn goal_json(s: &Symbolic) -> Json {
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
    goal
}

/// An optional `{"name", "degree"}` object of the goal.
fn object<'a>(g: &'a Json, key: &str, whole: &str) -> Res<Option<(String, &'a Json)>> {
    match g.get(key) {
        None => Ok(None),
        Some(o) => {
            let at = format!("{whole}.{key}");
            Ok(Some((string(o, "name", &at)?.to_string(), field(o, "degree", &at)?)))
        }
    }
}

/// Reads a written goal back with its data (see [`fields`]).
fn read(cert: &Json) -> Res<Symbolic> {
    let mut goal = read_goal(field(cert, "goal", "certificate")?, "goal")?;
    let p = field(cert, "pieces", "certificate")?;
    goal.certificates = array(p, "certificates", "pieces")?
        .iter()
        .enumerate()
        .map(|(i, c)| {
            c.as_str()
                .map(str::to_string)
                .ok_or_else(|| format!("pieces.certificates[{i}]: not a string"))
        })
        .collect::<Res<_>>()?;
    goal.induction = match p.get("induction") {
        None => None,
        Some(_) => Some(string(p, "induction", "pieces")?.to_string()),
    };
    goal.lemmas = lemmas(cert)?
        .into_iter()
        .enumerate()
        .map(|(i, (id, g))| Ok((id, read_goal(g, &format!("lemmas[{i}].goal"))?)))
        .collect::<Res<_>>()?;
    Ok(goal)
}

/// The lemmas a certificate cites: each id and goal as written (`[]` without the field).
pub(super) fn lemmas(cert: &Json) -> Res<Vec<(String, &Json)>> {
    let Some(list) = cert.get("lemmas") else {
        return Ok(Vec::new());
    };
    let list = list.as_array().ok_or("lemmas: not a list")?;
    let mut out: Vec<(String, &Json)> = Vec::new();
    for (i, l) in list.iter().enumerate() {
        let at = format!("lemmas[{i}]");
        let id = string(l, "id", &at)?.to_string();
        if out.iter().any(|(seen, _)| *seen == id) {
            return Err(format!("{at}: lemma {id} is listed twice"));
        }
        out.push((id, field(l, "goal", &at)?));
    }
    Ok(out)
}

/// A written goal's symbols, the real ones and the integer ones in order (each declared once).
pub(super) fn read_symbols(g: &Json, whole: &str) -> Res<(Vec<String>, Vec<String>)> {
    let (mut reals, mut ints) = (Vec::new(), Vec::new());
    for (i, s) in array(g, "symbols", whole)?.iter().enumerate() {
        let at = format!("{whole}.symbols[{i}]");
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
    Ok((reals, ints))
}

/// A written goal's integer ranges, one per integer symbol in `ints`' order, at least one open:
/// each `(name, from, to)` (`to: None` for an open range).
pub(super) fn read_for_all(g: &Json, whole: &str, ints: &[String]) -> Res<Vec<(String, String, Option<String>)>> {
    let mut for_all = Vec::new();
    for (i, r) in array(g, "for_all", whole)?.iter().enumerate() {
        let at = format!("{whole}.for_all[{i}]");
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
        return Err(format!(
            "{whole}.for_all: one range per integer symbol, at least one open (to: null)"
        ));
    }
    Ok(for_all)
}

/// Reads a written goal (its statement) back; `whole` names it in errors.
pub(super) fn read_goal(g: &Json, whole: &str) -> Res<Symbolic> {
    if string(g, "relation", whole)? != "=" {
        return Err(format!("{whole}.relation: only '=' is defined"));
    }
    let (reals, ints) = read_symbols(g, whole)?;
    let for_all = read_for_all(g, whole, &ints)?;
    let polygon = match object(g, "polygon", whole)? {
        Some((name, d)) => Some((
            name,
            d.as_str()
                .ok_or_else(|| format!("{whole}.polygon.degree: not a string"))?
                .to_string(),
        )),
        None => None,
    };
    let net = match object(g, "net", whole)? {
        Some((name, d)) => {
            let d: Vec<&str> = d.as_array().into_iter().flatten().filter_map(Json::as_str).collect();
            match d[..] {
                [m, n] => Some((name, [m.to_string(), n.to_string()])),
                _ => return Err(format!("{whole}.net.degree: not two strings")),
            }
        }
        None => None,
    };
    let mut members: Vec<String> = Vec::new();
    for (i, eq) in array(g, "equalities", whole)?.iter().enumerate() {
        let at = format!("{whole}.equalities[{i}]");
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
        return Err(format!("{whole}.equalities: none"));
    }
    Ok(Symbolic {
        reals,
        for_all,
        polygon,
        net,
        members,
        certificates: Vec::new(),
        lemmas: Vec::new(),
        induction: None,
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
