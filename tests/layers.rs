//! `src/verify/` has no import circle: each module imports only the modules named before it
//! in the list at the top of `src/verify/mod.rs`.

use std::collections::BTreeSet;

const DIR: &str = concat!(env!("CARGO_MANIFEST_DIR"), "/src/verify");

/// The module names in the order the list in `mod.rs` names them (backquoted names).
fn layer_order() -> Vec<String> {
    let text = std::fs::read_to_string(format!("{DIR}/mod.rs")).unwrap();
    let mut out = Vec::new();
    for line in text
        .lines()
        .take_while(|l| l.starts_with("//") || l.is_empty() || !l.starts_with("pub mod"))
    {
        if !line.starts_with("// ") {
            continue;
        }
        for (k, piece) in line.split('`').enumerate() {
            let known = std::path::Path::new(&format!("{DIR}/{piece}.rs")).exists();
            if k % 2 == 1 && known && !out.contains(&piece.to_string()) {
                out.push(piece.to_string());
            }
        }
    }
    out
}

/// The sibling modules a file uses (`super::name`), outside comments and its tests.
fn imports(module: &str, modules: &[String]) -> BTreeSet<String> {
    let text = std::fs::read_to_string(format!("{DIR}/{module}.rs")).unwrap();
    let code: String = text
        .split("#[cfg(test)]")
        .next()
        .unwrap()
        .lines()
        .map(|l| l.split("//").next().unwrap())
        .collect::<Vec<_>>()
        .join("\n");
    let mut out = BTreeSet::new();
    for m in modules {
        let used = code.contains(&format!("super::{m}::"))
            || code.contains(&format!("super::{m};"))
            || code.contains(&format!("super::{{{m},"))
            || code.contains(&format!(", {m}}};"))
            || code.contains(&format!("super::{{{m}}}"));
        if used && m != module {
            out.insert(m.clone());
        }
    }
    out
}

#[test]
fn every_verify_module_imports_only_modules_below_it() {
    let order = layer_order();
    let files: BTreeSet<String> = std::fs::read_dir(DIR)
        .unwrap()
        .filter_map(|e| e.ok()?.file_name().into_string().ok())
        .filter_map(|n| n.strip_suffix(".rs").map(str::to_string))
        .filter(|n| n != "mod")
        // test-only modules (`#[cfg(test)]`) may use any layer
        .filter(|n| !n.ends_with("_tests"))
        .collect();
    let listed: BTreeSet<String> = order.iter().cloned().collect();
    assert_eq!(listed, files, "the list in mod.rs names every module once");
    for (k, m) in order.iter().enumerate() {
        for used in imports(m, &order) {
            let at = order.iter().position(|x| *x == used).unwrap();
            assert!(at < k, "{m} imports {used}, which the list puts above it");
        }
    }
}

#[test]
fn the_check_sees_an_upward_import() {
    // `kinds` uses `symbolic`: read the other way round, that is an upward import.
    let order = layer_order();
    assert!(imports("kinds", &order).contains("symbolic"));
    let (k, s) = (
        order.iter().position(|x| x == "kinds").unwrap(),
        order.iter().position(|x| x == "symbolic").unwrap(),
    );
    assert!(s < k);
}
