//! Which fields belong to which claim kind, and which names a claim may declare.
//!
//! A field that does not belong to the claim's kind is an error naming the field (it would
//! otherwise be ignored, and the claim would say less than its author wrote). A declared name
//! (definition, polygon, net, symbol, vector, curve, surface, parameter, range variable) may
//! not be a built-in function or a library operation: `let = ["B(i, n, t) = 0"]` would turn a
//! claim about Bernstein polynomials into a claim about something else.

use super::claims::Claim;
use super::expr::FUNCTIONS;
use super::methods::{NetMethod, PolygonMethod};
use crate::error::{Error, Result};

/// The fields every kind has.
const COMMON: &[&str] = &["id", "source", "statement", "kind", "expect", "corrects", "note"];

/// The fields of each kind (besides [`COMMON`]).
pub const KIND_FIELDS: &[(&str, &[&str])] = &[
    (
        "identity",
        &[
            "lhs",
            "rhs",
            "chain",
            "vars",
            "for",
            "let",
            "polygon",
            "net",
            "symbols",
            "vectors",
            "curves",
            "surfaces",
            "certificate",
        ],
    ),
    (
        "implicit",
        &[
            "on", "equation", "coords", "vars", "for", "let", "polygon", "net", "curves", "surfaces",
        ],
    ),
    ("bezier_points", &["power", "param", "interval", "points", "let"]),
    ("conic_type", &["equation", "conic", "let"]),
    ("weight_type", &["curves", "conic"]),
    ("enneper", &["surfaces"]),
    (
        "implies",
        &["premise", "equation", "factor", "symbols", "vectors", "let"],
    ),
    ("theorem", &["theorem", "degrees"]),
    ("convergence", &["curves", "steps"]),
    ("fit", &["curves", "k", "l", "delta2"]),
    (
        "inequality",
        &["lhs", "rhs", "relation", "interval", "vars", "for", "let"],
    ),
];

/// Names the parser and evaluator give a meaning of their own (besides [`FUNCTIONS`] and the
/// polygon and net operations).
const INTERNAL: &[&str] = &["__dB", "__dpow"];

/// The fields the claim sets, by their names in the file.
fn present(c: &Claim) -> Vec<&'static str> {
    let mut out = Vec::new();
    let mut add = |set: bool, name: &'static str| {
        if set {
            out.push(name);
        }
    };
    add(c.lhs.is_some(), "lhs");
    add(c.rhs.is_some(), "rhs");
    add(c.chain.is_some(), "chain");
    add(c.equation.is_some(), "equation");
    add(c.on.is_some(), "on");
    add(c.coords.is_some(), "coords");
    add(c.premise.is_some(), "premise");
    add(c.factor.is_some(), "factor");
    add(c.power.is_some(), "power");
    add(c.param.is_some(), "param");
    add(c.interval.is_some(), "interval");
    add(c.points.is_some(), "points");
    add(c.conic.is_some(), "conic");
    add(c.vars.is_some(), "vars");
    add(c.ranges.is_some(), "for");
    add(c.defs.is_some(), "let");
    add(c.polygon.is_some(), "polygon");
    add(c.net.is_some(), "net");
    add(c.symbols.is_some(), "symbols");
    add(c.vectors.is_some(), "vectors");
    add(c.curves.is_some(), "curves");
    add(c.surfaces.is_some(), "surfaces");
    add(c.theorem.is_some(), "theorem");
    add(c.degrees.is_some(), "degrees");
    add(c.steps.is_some(), "steps");
    add(c.k.is_some(), "k");
    add(c.l.is_some(), "l");
    add(c.delta2.is_some(), "delta2");
    add(c.certificate.is_some(), "certificate");
    add(c.relation.is_some(), "relation");
    out
}

/// Whether `name` is reserved: a built-in function, a library operation, or internal.
pub fn is_reserved(name: &str) -> bool {
    FUNCTIONS.contains(&name)
        || PolygonMethod::parse(name).is_some()
        || NetMethod::parse(name).is_some()
        || INTERNAL.contains(&name)
}

/// Every field belongs to the claim's kind, and no declared name is reserved or declared twice.
pub fn check_fields(c: &Claim) -> Result<()> {
    let Some((_, fields)) = KIND_FIELDS.iter().find(|(k, _)| *k == c.kind) else {
        return Err(Error::Parse(format!(
            "claim {}: unknown kind '{}' ({})",
            c.id,
            c.kind,
            KIND_FIELDS.iter().map(|k| k.0).collect::<Vec<_>>().join(", ")
        )));
    };
    for f in present(c) {
        if !fields.contains(&f) && !COMMON.contains(&f) {
            return Err(Error::Parse(format!(
                "claim {}: the field '{f}' does not belong to kind {} (its fields: {})",
                c.id,
                c.kind,
                fields.join(", ")
            )));
        }
    }
    let mut declared: Vec<(String, &str)> = Vec::new();
    if let Some(p) = &c.polygon {
        declared.push((p.name.clone(), "polygon"));
    }
    if let Some(n) = &c.net {
        declared.push((n.name.clone(), "net"));
    }
    declared.extend(c.symbols.iter().flatten().map(|s| (s.clone(), "symbol")));
    declared.extend(c.vectors.iter().flat_map(|v| v.keys().map(|k| (k.clone(), "vector"))));
    declared.extend(c.curves.iter().flat_map(|v| v.keys().map(|k| (k.clone(), "curve"))));
    declared.extend(c.surfaces.iter().flat_map(|v| v.keys().map(|k| (k.clone(), "surface"))));
    declared.extend(c.vars.iter().flatten().map(|s| (s.clone(), "parameter")));
    for r in c.ranges.iter().flatten() {
        if let Some((v, _)) = r.split_once('=') {
            declared.push((v.trim().to_string(), "range variable"));
        }
    }
    for d in c.defs.iter().flatten() {
        if let Some((head, _)) = d.split_once('=') {
            let name = head.split('(').next().unwrap_or("").trim();
            declared.push((name.to_string(), "definition"));
        }
    }
    let surfaces: Vec<&str> = declared
        .iter()
        .filter(|(_, what)| *what == "surface" || *what == "net")
        .map(|(n, _)| n.as_str())
        .collect();
    for (k, (name, what)) in declared.iter().enumerate() {
        // `x_uv` is the notation for a partial of the surface `x`: a name of that form
        // would be read as a derivative (or hide one).
        if let Some((base, _, _)) = super::expr::split_partial(name) {
            if surfaces.contains(&name.as_str()) || surfaces.contains(&base) {
                return Err(Error::Parse(format!(
                    "claim {}: the {what} '{name}' reads as a partial derivative ({base}_u, {base}_uv, … are the partials of a surface {base}); choose another name",
                    c.id
                )));
            }
        }
        if is_reserved(name) {
            return Err(Error::Parse(format!(
                "claim {}: the {what} '{name}' would shadow a built-in function or library operation of the same name; choose another name",
                c.id
            )));
        }
        if let Some((_, other)) = declared[..k].iter().find(|(n, _)| n == name) {
            return Err(Error::Parse(format!(
                "claim {}: '{name}' is declared twice (as a {other} and as a {what})",
                c.id
            )));
        }
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::super::claims::parse_file;
    use super::*;
    use std::path::Path;

    fn claim(body: &str) -> Claim {
        let f = parse_file(
            &format!("[[claim]]\nid = \"x\"\nsource = \"s\"\nstatement = \"s\"\n{body}"),
            Path::new("t.toml"),
        )
        .unwrap();
        f.claim[0].clone()
    }

    #[test]
    fn a_field_of_another_kind_is_named() {
        let err = check_fields(&claim(
            "kind = \"theorem\"\ntheorem = \"derivative\"\nlet = [\"B = 0\"]",
        ))
        .unwrap_err()
        .to_string();
        assert!(err.contains("'let' does not belong to kind theorem"), "{err}");
        let err = check_fields(&claim(
            "kind = \"conic_type\"\nequation = \"x = y\"\nconic = \"parabola\"\nlhs = \"1\"",
        ))
        .unwrap_err()
        .to_string();
        assert!(err.contains("'lhs'"), "{err}");
        assert!(check_fields(&claim("kind = \"identity\"\nlhs = \"t\"\nrhs = \"t\"")).is_ok());
    }

    #[test]
    fn built_ins_and_library_names_cannot_be_shadowed() {
        for decl in [
            "let = [\"B(i, n, t) = 0\"]",
            "let = [\"C = 2\"]",
            "let = [\"sum(a, b, c, d) = 0\"]",
            "symbols = [\"elev\"]",
            "polygon = { name = \"bsum\", degree = \"2\" }",
            "for = [\"sqrt = 0..=2\"]",
            "vars = [\"diff\"]",
        ] {
            let err = check_fields(&claim(&format!(
                "kind = \"identity\"\nlhs = \"1\"\nrhs = \"1\"\n{decl}"
            )))
            .unwrap_err()
            .to_string();
            assert!(err.contains("shadow"), "{decl}: {err}");
        }
        let err = check_fields(&claim(
            "kind = \"identity\"\nlhs = \"1\"\nrhs = \"1\"\nsymbols = [\"k\"]\nlet = [\"k = 2\"]",
        ))
        .unwrap_err()
        .to_string();
        assert!(err.contains("declared twice"), "{err}");
    }
}
