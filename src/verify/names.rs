//! Which names a claim may declare.
//!
//! A declared name
//! (definition, polygon, net, symbol, vector, curve, surface, parameter, range variable) may
//! not be a built-in function or a library operation: `let = ["B(i, n, t) = 0"]` would turn a
//! claim about Bernstein polynomials into a claim about something else.

use super::claims::Claim;
use super::kernel::expr::FUNCTIONS;
use super::methods::{NetMethod, PolygonMethod};
use crate::error::{Error, Result};

/// Names the parser and evaluator give a meaning of their own (besides [`FUNCTIONS`] and the
/// polygon and net operations).
const INTERNAL: &[&str] = &["__dB", "__dpow"];

/// Whether `name` is reserved: a built-in function, a library operation, or internal.
pub fn is_reserved(name: &str) -> bool {
    FUNCTIONS.contains(&name)
        || PolygonMethod::parse(name).is_some()
        || NetMethod::parse(name).is_some()
        || INTERNAL.contains(&name)
}

/// No declared name is reserved, reads as a surface's partial, or is declared twice.
pub fn check_declarations(c: &Claim) -> Result<()> {
    let declared = c.decls.declared();
    let surfaces: Vec<&str> = declared
        .iter()
        .filter(|(_, what)| *what == "surface" || *what == "net")
        .map(|(n, _)| n.as_str())
        .collect();
    for (k, (name, what)) in declared.iter().enumerate() {
        // `x_uv` is the notation for a partial of the surface `x`: a name of that form
        // would be read as a derivative (or hide one).
        if let Some((base, _, _)) = super::kernel::expr::split_partial(name) {
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
            let err = check_declarations(&claim(&format!(
                "kind = \"identity\"\nlhs = \"1\"\nrhs = \"1\"\n{decl}"
            )))
            .unwrap_err()
            .to_string();
            assert!(err.contains("shadow"), "{decl}: {err}");
        }
        let err = check_declarations(&claim(
            "kind = \"identity\"\nlhs = \"1\"\nrhs = \"1\"\nsymbols = [\"k\"]\nlet = [\"k = 2\"]",
        ))
        .unwrap_err()
        .to_string();
        assert!(err.contains("declared twice"), "{err}");
    }
}

/// The ids nearest to `id` by edit distance (at most three, and only close ones: within a
/// third of the length, at least 2), for a "did you mean" after an unknown id.
pub fn nearest<'a>(id: &str, ids: impl Iterator<Item = &'a str>) -> Vec<String> {
    let within = (id.chars().count() / 3).max(2);
    let mut scored: Vec<(usize, &str)> = ids
        .map(|c| (edit_distance(id, c), c))
        .filter(|(d, _)| *d <= within)
        .collect();
    scored.sort();
    let best = scored.first().map(|(d, _)| *d);
    scored
        .into_iter()
        .filter(|(d, _)| Some(*d) == best)
        .take(3)
        .map(|(_, c)| c.to_string())
        .collect()
}

/// Levenshtein distance between two strings, by characters.
fn edit_distance(a: &str, b: &str) -> usize {
    let b: Vec<char> = b.chars().collect();
    let mut row: Vec<usize> = (0..=b.len()).collect();
    for (i, ca) in a.chars().enumerate() {
        let mut diag = row[0];
        row[0] = i + 1;
        for (j, cb) in b.iter().enumerate() {
            let next = (row[j + 1] + 1).min(row[j] + 1).min(diag + usize::from(ca != *cb));
            diag = row[j + 1];
            row[j + 1] = next;
        }
    }
    row[b.len()]
}

#[cfg(test)]
mod nearest_tests {
    use super::{edit_distance, nearest};

    #[test]
    fn the_nearest_ids_are_suggested_and_far_ones_are_not() {
        assert_eq!(edit_distance("004-08", "004-8"), 1);
        assert_eq!(edit_distance("kitten", "sitting"), 3);
        let ids = ["004-8", "004-8-corrected", "004-10", "000-ex4-y"];
        assert_eq!(nearest("004-08", ids.iter().copied()), ["004-8"]);
        assert_eq!(nearest("004-9", ids.iter().copied()), ["004-8"]);
        assert!(nearest("zzzzzzzzzz", ids.iter().copied()).is_empty());
    }
}
