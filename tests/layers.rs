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

/// The top-level items of a `use` tree's braces, `inner` starting after the `{`: `a`, `b::{c,
/// d}` of `{a, b::{c, d}}`.
fn brace_items(inner: &str) -> Vec<String> {
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
}

/// The first path segment of each item of a `use` tree's braces or a path: `a`, `b` of
/// `{a, b::c}`.
fn heads(rest: &str) -> Vec<String> {
    let ident = |s: &str| -> String { s.chars().take_while(|c| c.is_alphanumeric() || *c == '_').collect() };
    if let Some(inner) = rest.strip_prefix('{') {
        brace_items(inner)
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

// ---------------------------------------------------------------------------------------
// The core files of `src/` (all but `verify/`, `html`, `figure/`, `oracle/`, `main.rs`): no
// import circle. Each file imports only files named before it in the list under "Layers" in
// `src/lib.rs`. A file's imports are the paths it names (`crate::…`, `super::…`, `self::…`,
// a child module's name in a `use`), each resolved to the file that defines the item: through
// the re-exports (`pub use`) of the modules on the way, which are not imports themselves, as
// `mod` declarations are not.
// ---------------------------------------------------------------------------------------

/// The parts of `src/` outside the core.
const NOT_CORE: [&str; 6] = ["verify", "html", "figure", "oracle", "main", "lib"];

/// A module's path from the crate root, `["exact", "gcd"]` for `src/exact/gcd.rs`.
type Module = Vec<String>;

/// The module of a file under `src/`: `src/a/b.rs` and `src/a/b/mod.rs` are `a/b`.
fn module_of(path: &Path) -> Module {
    let rel = path.strip_prefix(SRC).unwrap().with_extension("");
    let mut m: Module = rel
        .components()
        .map(|c| c.as_os_str().to_string_lossy().into_owned())
        .collect();
    if m.last().is_some_and(|x| x == "mod") {
        m.pop();
    }
    if m == ["lib"] {
        m.clear();
    }
    m
}

/// Every module of the crate, with its file.
fn crate_modules() -> std::collections::BTreeMap<Module, PathBuf> {
    rust_files(Path::new(SRC))
        .into_iter()
        .map(|f| (module_of(&f), f))
        .collect()
}

/// The paths of a `use` tree starting at `rest` (`a::{b, c::d}` is `a::b` and `a::c::d`;
/// a glob's last segment is empty).
fn use_paths(rest: &str) -> Vec<Vec<String>> {
    let rest = rest.trim_start();
    if let Some(inner) = rest.strip_prefix('{') {
        return brace_items(inner)
            .iter()
            .filter(|i| !i.trim().is_empty())
            .flat_map(|i| use_paths(i))
            .collect();
    }
    let head: String = rest.chars().take_while(|c| c.is_alphanumeric() || *c == '_').collect();
    match rest[head.len()..].strip_prefix("::") {
        Some(tail) => use_paths(tail)
            .into_iter()
            .map(|mut p| {
                p.insert(0, head.clone());
                p
            })
            .collect(),
        None => vec![vec![head]],
    }
}

/// `path` (`crate::`, `super::`, `self::` or a child's name, already split off) from module
/// `m` as a path from the crate root.
fn absolute(m: &Module, prefix: &str, path: Vec<String>) -> Vec<String> {
    let mut base: Vec<String> = match prefix {
        "crate" => Vec::new(),
        "self" => m.clone(),
        _ => {
            let ups = prefix.matches("super").count();
            m[..m.len().saturating_sub(ups)].to_vec()
        }
    };
    base.extend(path);
    base
}

/// Every place in `code` where a path starts: `crate::`, `$crate::`, `self::`, or a chain of
/// `super::`, with the text after it.
fn path_starts(code: &str) -> Vec<(String, &str)> {
    let mut out = Vec::new();
    let bytes = code.as_bytes();
    let mut at = 0;
    while at < code.len() {
        let rest = &code[at..];
        let boundary =
            at == 0 || !(bytes[at - 1].is_ascii_alphanumeric() || bytes[at - 1] == b'_' || bytes[at - 1] == b':');
        if boundary {
            for word in ["crate::", "self::"] {
                if let Some(tail) = rest.strip_prefix(word) {
                    out.push((word.trim_end_matches("::").to_string(), tail));
                }
            }
            if rest.starts_with("super::") {
                let mut end = 0;
                while rest[end..].starts_with("super::") {
                    end += "super::".len();
                }
                out.push((rest[..end].to_string(), &rest[end..]));
                at += end;
                continue;
            }
        }
        at += rest.chars().next().unwrap().len_utf8();
    }
    out
}

/// The code of a file without its `pub use` re-exports and `mod` declarations.
fn without_declarations(code: &str) -> String {
    let mut out = String::new();
    let mut rest = code;
    loop {
        let next = ["pub use ", "pub(crate) use ", "pub(super) use "]
            .iter()
            .filter_map(|w| rest.find(w))
            .min();
        match next {
            Some(k) => {
                out.push_str(&rest[..k]);
                let end = rest[k..].find(';').map_or(rest.len(), |e| k + e + 1);
                rest = &rest[end..];
            }
            None => {
                out.push_str(rest);
                break;
            }
        }
    }
    out.lines()
        .filter(|l| {
            let t = l.trim_start();
            let t = t
                .strip_prefix("pub(crate) ")
                .or_else(|| t.strip_prefix("pub "))
                .unwrap_or(t);
            !(t.starts_with("mod ") && t.trim_end().ends_with(';'))
        })
        .collect::<Vec<_>>()
        .join("\n")
}

/// The re-exports of each module: name → the absolute path it stands for.
fn reexports(
    modules: &std::collections::BTreeMap<Module, PathBuf>,
) -> std::collections::BTreeMap<Module, std::collections::BTreeMap<String, Vec<String>>> {
    let mut out = std::collections::BTreeMap::new();
    for (m, f) in modules {
        let code = code_of(f);
        let table: &mut std::collections::BTreeMap<String, Vec<String>> = out.entry(m.clone()).or_default();
        for w in ["pub use ", "pub(crate) use ", "pub(super) use "] {
            for (k, _) in code.match_indices(w) {
                for mut p in use_paths(&code[k + w.len()..]) {
                    if p.is_empty() || p[0].is_empty() {
                        continue;
                    }
                    let first = p.remove(0);
                    let abs = match first.as_str() {
                        "crate" | "self" => absolute(m, &first, p),
                        "super" => absolute(m, "super", p),
                        child => {
                            let mut c = m.clone();
                            c.push(child.to_string());
                            if !modules.contains_key(&c) {
                                continue;
                            }
                            c.extend(p);
                            c
                        }
                    };
                    if let Some(name) = abs.last().filter(|n| !n.is_empty()) {
                        table.insert(name.clone(), abs.clone());
                    }
                }
            }
        }
    }
    out
}

/// The module whose file defines what `path` names: the deepest module on the path, through
/// re-exports.
fn resolve(
    path: &[String],
    modules: &std::collections::BTreeMap<Module, PathBuf>,
    reexports: &std::collections::BTreeMap<Module, std::collections::BTreeMap<String, Vec<String>>>,
    depth: usize,
) -> Module {
    let mut cur: Module = Vec::new();
    for s in path {
        let mut next = cur.clone();
        next.push(s.clone());
        if modules.contains_key(&next) {
            cur = next;
            continue;
        }
        if let Some(target) = reexports.get(&cur).and_then(|t| t.get(s)) {
            if depth < 8 && target.as_slice() != path {
                return resolve(target, modules, reexports, depth + 1);
            }
        }
        break;
    }
    cur
}

/// The core modules each core module imports.
fn core_imports() -> std::collections::BTreeMap<String, BTreeSet<String>> {
    let modules = crate_modules();
    let reexports = reexports(&modules);
    let name = |m: &Module| m.join("/");
    let is_core = |m: &Module| !m.is_empty() && !NOT_CORE.contains(&m[0].as_str());
    let mut out = std::collections::BTreeMap::new();
    for (m, f) in &modules {
        let file = f.file_name().unwrap().to_string_lossy();
        if !is_core(m) || file == "tests.rs" || file.ends_with("_tests.rs") {
            continue;
        }
        let code = without_declarations(&code_of(f));
        let mut targets = BTreeSet::new();
        for (prefix, rest) in path_starts(&code) {
            for p in use_paths(rest) {
                targets.insert(resolve(&absolute(m, &prefix, p), &modules, &reexports, 0));
            }
        }
        // `use child::…` in a module with a folder
        for (k, _) in code.match_indices("use ") {
            for mut p in use_paths(&code[k + 4..]) {
                let mut child = m.clone();
                child.push(p.remove(0));
                if modules.contains_key(&child) {
                    child.extend(p);
                    targets.insert(resolve(&child, &modules, &reexports, 0));
                }
            }
        }
        let used: BTreeSet<String> = targets.iter().filter(|t| is_core(t) && *t != m).map(name).collect();
        out.insert(name(m), used);
    }
    out
}

/// The core files in the order of the list under "Layers" in `src/lib.rs`.
fn core_layer_order() -> Vec<String> {
    let text = std::fs::read_to_string(format!("{SRC}/lib.rs")).unwrap();
    let start = text.find("//! ## Layers").expect("lib.rs documents the layers");
    let mut out = Vec::new();
    for line in text[start..]
        .lines()
        .skip(1)
        .take_while(|l| !l.starts_with("//! ## ") && l.starts_with("//!"))
    {
        for (k, piece) in line.split('`').enumerate() {
            let is_name = !piece.is_empty() && piece.chars().all(|c| c.is_alphanumeric() || c == '_' || c == '/');
            if k % 2 == 1 && is_name && !out.contains(&piece.to_string()) {
                out.push(piece.to_string());
            }
        }
    }
    out
}

/// The imports that go up the list (or to a file the list does not name): empty when
/// every file imports only files below it, so that there is no circle.
fn upward_imports(order: &[String], imports: &std::collections::BTreeMap<String, BTreeSet<String>>) -> Vec<String> {
    let mut out = Vec::new();
    for (m, used) in imports {
        let at = order.iter().position(|x| x == m);
        for u in used {
            let below = match (at, order.iter().position(|x| x == u)) {
                (Some(a), Some(b)) => b < a,
                _ => false,
            };
            if !below {
                out.push(format!("{m} imports {u}"));
            }
        }
    }
    out
}

#[test]
fn every_core_file_imports_only_files_below_it() {
    let order = core_layer_order();
    let imports = core_imports();
    // the list names every core file (its other backquoted words name no core file)
    let files: BTreeSet<String> = imports.keys().cloned().collect();
    let order: Vec<String> = order.into_iter().filter(|n| files.contains(n)).collect();
    let listed: BTreeSet<String> = order.iter().cloned().collect();
    assert_eq!(listed, files, "the list in lib.rs names every core file");
    let up = upward_imports(&order, &imports);
    assert!(up.is_empty(), "imports against the layers of lib.rs: {up:#?}");
}

#[test]
fn the_core_check_sees_imports_and_circles() {
    let imports = core_imports();
    // a path through a re-export reaches the defining file: `scalar` names
    // `crate::exact::{fraction_free, …}`, `surface` `crate::point::Point` (in `coords`)
    assert!(
        imports["scalar"].contains("exact/fraction_free"),
        "{:?}",
        imports["scalar"]
    );
    assert!(imports["surface"].contains("coords"));
    assert!(imports["curve/exact"].contains("curve"), "super:: paths");
    assert!(
        !imports["exact/fraction_free"].contains("curve"),
        "the kernels import no curve"
    );
    // a circle: whatever the order, one of its imports goes up
    let circle: std::collections::BTreeMap<String, BTreeSet<String>> = [
        ("a".to_string(), BTreeSet::from(["b".to_string()])),
        ("b".to_string(), BTreeSet::from(["a".to_string()])),
    ]
    .into();
    for order in [["a", "b"], ["b", "a"]] {
        let order: Vec<String> = order.iter().map(|s| s.to_string()).collect();
        assert_eq!(upward_imports(&order, &circle).len(), 1);
    }
    assert_eq!(use_paths("{a, b::{c, d}, e::*}; x").len(), 4);
}

#[test]
fn no_type_identity_in_the_core() {
    // The kernel choice is by trait methods: no `Any`, no `TypeId` in the core files.
    let core = core_imports();
    for (m, path) in crate_modules() {
        if !core.contains_key(&m.join("/")) {
            continue;
        }
        let code = code_of(&path);
        for word in ["TypeId", "dyn Any", "std::any"] {
            assert!(!code.contains(word), "{} uses {word}", path.display());
        }
    }
}
