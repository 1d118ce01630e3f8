//! `src/verify/` has no import circle: each module (a file, or a folder with its files) imports
//! only the modules named before it in the list at the top of `src/verify/mod.rs`. The trusted
//! `kernel/` imports nothing of `verify` outside itself and of the crate only number types, and
//! only it makes a `proved` verdict.

use std::collections::BTreeSet;
use std::path::{Path, PathBuf};

const SRC: &str = concat!(env!("CARGO_MANIFEST_DIR"), "/src");
const DIR: &str = concat!(env!("CARGO_MANIFEST_DIR"), "/src/verify");

/// Whether `name` (an identifier) is a module of `verify`: `name.rs` or `name/mod.rs`.
fn is_module(name: &str) -> bool {
    !name.is_empty()
        && name.chars().all(|c| c.is_alphanumeric() || c == '_')
        && (Path::new(&format!("{DIR}/{name}.rs")).exists() || Path::new(&format!("{DIR}/{name}/mod.rs")).exists())
}

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
            if k % 2 == 1 && is_module(piece) && !out.contains(&piece.to_string()) {
                out.push(piece.to_string());
            }
        }
    }
    out
}

/// Every `.rs` file under `dir`, recursively.
fn rust_files(dir: &Path) -> Vec<PathBuf> {
    let mut out = Vec::new();
    for e in std::fs::read_dir(dir).unwrap() {
        let p = e.unwrap().path();
        if p.is_dir() {
            out.extend(rust_files(&p));
        } else if p.extension().is_some_and(|x| x == "rs") {
            out.push(p);
        }
    }
    out.sort();
    out
}

/// The files of module `m`: `m.rs`, `m/mod.rs` and every file under `m/`.
fn module_files(m: &str) -> Vec<PathBuf> {
    let mut out: Vec<PathBuf> = vec![PathBuf::from(format!("{DIR}/{m}.rs"))];
    let folder = PathBuf::from(format!("{DIR}/{m}"));
    if folder.is_dir() {
        out.extend(rust_files(&folder));
    }
    out.retain(|p| p.exists());
    out
}

/// A file's code outside comments and its tests.
fn code_of(path: &Path) -> String {
    let text = std::fs::read_to_string(path).unwrap();
    text.split("#[cfg(test)]")
        .next()
        .unwrap()
        .lines()
        .map(|l| l.split("//").next().unwrap())
        .collect::<Vec<_>>()
        .join("\n")
}

/// How many `super::` lead from `path` to `verify`: 1 for `verify/m.rs` and `verify/m/mod.rs`,
/// 2 for `verify/m/x.rs`, and so on.
fn supers_to_verify(path: &Path) -> usize {
    let rel = path.strip_prefix(DIR).unwrap();
    let n = rel.components().count();
    if rel.file_name().is_some_and(|f| f == "mod.rs") {
        n - 1
    } else {
        n
    }
}

/// The first path segment of each item of a `use` tree's braces or a path: `a`, `b` of
/// `{a, b::c}`.
fn heads(rest: &str) -> Vec<String> {
    let ident = |s: &str| -> String { s.chars().take_while(|c| c.is_alphanumeric() || *c == '_').collect() };
    if let Some(inner) = rest.strip_prefix('{') {
        let mut depth = 0;
        let mut items = vec![String::new()];
        for c in inner.chars() {
            match c {
                '{' => depth += 1,
                '}' if depth == 0 => break,
                '}' => depth -= 1,
                ',' if depth == 0 => {
                    items.push(String::new());
                    continue;
                }
                _ => {}
            }
            items.last_mut().unwrap().push(c);
        }
        items
            .iter()
            .map(|i| ident(i.trim()))
            .filter(|i| !i.is_empty())
            .collect()
    } else {
        vec![ident(rest)]
    }
}

/// The modules of `verify` a file names: by `super::` chains that reach `verify`, and by
/// `crate::verify::`.
fn verify_paths(path: &Path) -> BTreeSet<String> {
    let code = code_of(path);
    let up = supers_to_verify(path);
    let mut out = BTreeSet::new();
    let mut at = 0;
    while let Some(k) = code[at..].find("super::") {
        let start = at + k;
        let mut end = start;
        let mut count = 0;
        while code[end..].starts_with("super::") {
            end += "super::".len();
            count += 1;
        }
        if count == up {
            out.extend(heads(&code[end..]));
        }
        at = end;
    }
    for (k, _) in code.match_indices("crate::verify::") {
        out.extend(heads(&code[k + "crate::verify::".len()..]));
    }
    out
}

/// The sibling modules module `m` uses.
fn imports(m: &str, modules: &[String]) -> BTreeSet<String> {
    module_files(m)
        .iter()
        .flat_map(|f| verify_paths(f))
        .filter(|x| x != m && modules.contains(x))
        .collect()
}

#[test]
fn every_verify_module_imports_only_modules_below_it() {
    let order = layer_order();
    let files: BTreeSet<String> = std::fs::read_dir(DIR)
        .unwrap()
        .filter_map(|e| {
            let e = e.ok()?;
            let name = e.file_name().into_string().ok()?;
            if e.path().is_dir() {
                // a folder is a module of its own only with a `mod.rs` (else it holds the
                // submodules of `name.rs`)
                return e.path().join("mod.rs").exists().then_some(name);
            }
            name.strip_suffix(".rs").map(str::to_string)
        })
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

#[test]
fn the_check_reads_subfolders_and_super_super_paths() {
    // `symbolic/induction.rs` reaches `lemma` by `super::super::lemma`.
    let induction = PathBuf::from(format!("{DIR}/symbolic/induction.rs"));
    assert_eq!(supers_to_verify(&induction), 2);
    assert!(verify_paths(&induction).contains("lemma"));
    assert!(imports("symbolic", &layer_order()).contains("lemma"));
    assert_eq!(heads("{a, b::{c, d}, e}; x"), ["a", "b", "e"]);
}

#[test]
fn the_kernel_is_the_bottom_and_imports_nothing_of_verify() {
    let order = layer_order();
    assert_eq!(order.first().map(String::as_str), Some("kernel"));
    let files = module_files("kernel");
    assert!(files.len() >= 2, "{files:?}");
    for f in &files {
        let outside: Vec<String> = verify_paths(f)
            .into_iter()
            .filter(|m| is_module(m) && m != "kernel")
            .collect();
        assert!(outside.is_empty(), "{} imports {outside:?} of verify", f.display());
        // Of the crate, only the number code the kernel computes with: the scalar types,
        // `exact/`, `quadratic`, and `bernstein` (binomials) and `linalg` (dot products), which
        // import nothing of `verify` either.
        let code = code_of(f);
        for (k, _) in code.match_indices("crate::") {
            let head = heads(&code[k + "crate::".len()..]);
            for h in head {
                assert!(
                    ["scalar", "exact", "quadratic", "bernstein", "linalg", "error"].contains(&h.as_str()),
                    "{} uses crate::{h}",
                    f.display()
                );
            }
        }
    }
}

/// The lines outside `src/verify/kernel/` that name `Verdict::Proved` (or `ProvedInRange`)
/// other than to read a verdict: a match arm's pattern or an `==` / `!=` comparison.
fn verdict_makers(text: &str) -> Vec<String> {
    let mut out = Vec::new();
    for line in text.lines() {
        let code = line.split("//").next().unwrap();
        for (k, _) in code.match_indices("Verdict::Proved") {
            let (before, after) = (code[..k].trim_end(), &code[k..]);
            let read = after.contains("=>")
                || before.ends_with("==")
                || before.ends_with("!=")
                || after
                    .trim_start_matches(|c: char| c.is_alphanumeric() || c == ':' || c == '_')
                    .trim_start()
                    .starts_with(['=', '!']);
            if !read {
                out.push(line.trim().to_string());
            }
        }
    }
    out
}

#[test]
fn only_the_kernel_makes_a_proved_verdict() {
    let kernel = PathBuf::from(format!("{DIR}/kernel"));
    let mut makers = Vec::new();
    for f in rust_files(Path::new(SRC)) {
        if f.starts_with(&kernel) {
            continue;
        }
        let text = std::fs::read_to_string(&f).unwrap();
        makers.extend(
            verdict_makers(&text)
                .into_iter()
                .map(|l| format!("{}: {l}", f.display())),
        );
    }
    assert!(makers.is_empty(), "{makers:#?}");
}

#[test]
fn the_verdict_check_sees_a_construction() {
    assert_eq!(
        verdict_makers("let c = Checked::new(Verdict::Proved, cert);\nif v == Verdict::Proved {}"),
        ["let c = Checked::new(Verdict::Proved, cert);"]
    );
    assert!(verdict_makers("    Verdict::ProvedInRange => 1,\nx != Verdict::ProvedInRange").is_empty());
    assert_eq!(verdict_makers("out.verdict = Verdict::ProvedInRange;").len(), 1);
}
