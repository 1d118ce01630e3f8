//! Claim files written by an attacker or a careless user: deep expressions, control
//! characters, TeX's `^^` notation, colliding text names, statements that made the renderers
//! quadratic. Each gets a clear per-claim error or a safe rendering, never a crash, a spoofed
//! report line or a lost page.

use casteljau::html::{formula, render_pages};
use casteljau::verify::claims::{parse_file, ClaimFile};
use casteljau::verify::{prove_files, Verdict};
use std::path::Path;
use std::process::Command;
use std::time::Duration;

// CPU time, not wall time: the bounds are on the work, and a loaded machine stretches the wall.
#[path = "support/cpu.rs"]
mod cpu;
use cpu::{run_timed, thread_cpu};

fn claim(id: &str, lhs: &str, rhs: &str) -> String {
    format!(
        "[[claim]]\nid = \"{id}\"\nsource = \"x 1\"\nstatement = \"s\"\nkind = \"identity\"\nvars = [\"t\"]\nlhs = \"{lhs}\"\nrhs = \"{rhs}\"\n\n"
    )
}

fn file(text: &str) -> ClaimFile {
    parse_file(text, Path::new("hostile.toml")).unwrap()
}

fn chain(term: &str, op: &str, n: usize) -> String {
    vec![term; n].join(op)
}

#[test]
fn long_chains_are_a_per_claim_error_and_the_other_claims_keep_their_verdicts() {
    // 10,000 terms: the expression length limit (20,000 characters) admits them; the prover
    // threads' stacks did not (a stack overflow aborted the whole run).
    let mut text = claim("first", "(1+t)^2", "1 + 2t + t^2");
    for (k, (term, op)) in [("1", "+"), ("1", "-"), ("t", "*"), ("t", "/"), ("t", "")]
        .iter()
        .enumerate()
    {
        let lhs = if op.is_empty() {
            "t".repeat(10_000) // implicit products: 10,000 one-letter factors
        } else {
            chain(term, op, 10_000)
        };
        text.push_str(&claim(&format!("chain-{k}"), &lhs, "1"));
    }
    text.push_str(&claim("factorials", &format!("2{}", "!".repeat(10_000)), "2"));
    text.push_str(&claim("last", "(1-t)^2", "1 - 2t + t^2"));
    let f = file(&text);
    let report = prove_files(std::slice::from_ref(&f), &mut |_, _, _| {}).unwrap();
    let verdicts: Vec<(&str, Verdict)> = report.outcomes.iter().map(|o| (o.id.as_str(), o.verdict)).collect();
    assert_eq!(verdicts.first(), Some(&("first", Verdict::Proved)));
    assert_eq!(verdicts.last(), Some(&("last", Verdict::Proved)));
    for o in &report.outcomes[1..report.outcomes.len() - 1] {
        assert_eq!(o.verdict, Verdict::Error, "{}", o.id);
        assert!(o.certificate.contains("MAX_TREE_DEPTH"), "{}: {}", o.id, o.certificate);
    }
}

#[test]
fn chains_up_to_the_tree_depth_limit_are_proved_and_false_ones_fail() {
    let n = 512; // MAX_TREE_DEPTH: a chain of 512 terms is 512 levels deep
    let mut text = claim("sum", &chain("t", "+", n), &format!("{n}t"));
    text.push_str(&claim("difference", &chain("t", "-", n), &format!("{}t", 2 - n as i64)));
    text.push_str(&claim("false", &chain("t", "+", n), &format!("{}t", n + 1)));
    text.push_str(&claim("over", &chain("t", "+", n + 1), &format!("{}t", n + 1)));
    let mut with_let = claim("let", "f(f(t))", "255*(255*t)");
    with_let = with_let.replace("lhs =", &format!("let = [\"f(x) = {}\"]\nlhs =", chain("x", "+", 255)));
    text.push_str(&with_let);
    let report = prove_files(&[file(&text)], &mut |_, _, _| {}).unwrap();
    let v: Vec<Verdict> = report.outcomes.iter().map(|o| o.verdict).collect();
    assert_eq!(
        v,
        [
            Verdict::Proved,
            Verdict::Proved,
            Verdict::Fails,
            Verdict::Error,
            Verdict::Proved
        ]
    );
    // a definition put in place may not deepen the tree past the limit either
    let mut deeper = claim("deeper", "f(f(f(t)))", "255*(255*(255*t))");
    deeper = deeper.replace("lhs =", &format!("let = [\"f(x) = {}\"]\nlhs =", chain("x", "+", 255)));
    let report = prove_files(&[file(&deeper)], &mut |_, _, _| {}).unwrap();
    assert_eq!(report.outcomes[0].verdict, Verdict::Error);
    assert!(report.outcomes[0].certificate.contains("MAX_TREE_DEPTH"));
}

#[test]
fn a_derivative_too_large_to_build_is_refused() {
    // d²/dt² of a product of 256 factors: ~16 million nodes (1 GB) before it was bounded
    let text = claim("d2", &format!("diff({}, t, 2)", chain("t", "*", 256)), "256*255*t^254");
    let report = prove_files(&[file(&text)], &mut |_, _, _| {}).unwrap();
    assert_eq!(report.outcomes[0].verdict, Verdict::Error);
    assert!(
        report.outcomes[0].certificate.contains("MAX_DIFF_WORK"),
        "{}",
        report.outcomes[0].certificate
    );
}

#[test]
fn ids_with_anything_but_letters_digits_dash_underscore_and_dot_are_refused() {
    for bad in [
        "ok-1\\u001b[1A\\r[proved] ok-1",
        "a b",
        "a\\nb",
        "",
        "é",
        "a/b",
        "a\\u202eb",
    ] {
        let text = claim(bad, "t", "t");
        let err = parse_file(&text, Path::new("x.toml")).unwrap_err().to_string();
        assert!(err.contains("may hold only ASCII letters"), "{bad}: {err}");
        assert!(!err.chars().any(|c| c.is_control()), "{err:?}");
    }
    for good in ["000-1", "a_b.c", "X9"] {
        assert!(
            parse_file(&claim(good, "t", "t"), Path::new("x.toml")).is_ok(),
            "{good}"
        );
    }
}

#[test]
fn no_control_character_reaches_the_text_report() {
    let text = "[text]\nfile = \"x\\u001b[2J.txt\"\ntitle = \"t\\r\"\n\n".to_string()
        + &claim("c", "(1+t)^2", "1 + 3t + t^2")
            .replace("source = \"x 1\"", "source = \"x\\r[proved] c\"")
            .replace(
                "statement = \"s\"",
                "statement = \"a\\nb\\u202e\\u0007\"\nnote = \"\\u001b[8m\"",
            );
    let report = prove_files(&[file(&text)], &mut |_, _, _| {}).unwrap();
    assert_eq!(report.outcomes[0].verdict, Verdict::Fails);
    let out = report.to_text();
    assert!(
        out.chars().all(|c| c == '\n' || !(c.is_control() || c == '\u{202e}')),
        "{out:?}"
    );
    assert!(out.contains("=== x\\u{1b}[2J.txt ==="), "{out}");
    assert!(out.contains("    source:      x\\u{d}[proved] c\n"), "{out}");
    assert!(out.contains("    statement:   a\\u{a}b\\u{202e}\\u{7}\n"), "{out}");
    assert!(out.contains("[fails] c  !! MISMATCH: expected proved\n"), "{out}");
}

#[test]
fn distinct_texts_get_distinct_pages_and_never_the_index() {
    let files: Vec<ClaimFile> = ["index.txt", "a b.txt", "a_b.txt", "A_B.txt", "a_b-2.txt", "index", ""]
        .iter()
        .enumerate()
        .map(|(k, name)| {
            let text =
                format!("[text]\nfile = \"{name}\"\ntitle = \"t {name}\"\n\n") + &claim(&format!("c{k}"), "t", "t");
            parse_file(&text, Path::new(&format!("f{k}.toml"))).unwrap()
        })
        .collect();
    let report = prove_files(&files, &mut |_, _, _| {}).unwrap();
    let pages = render_pages(&report, &files).unwrap();
    assert_eq!(pages.len(), files.len() + 1);
    let mut names: Vec<String> = pages.iter().map(|(n, _)| n.to_lowercase()).collect();
    names.sort();
    names.dedup();
    assert_eq!(names.len(), pages.len(), "{names:?}");
    assert_eq!(pages.iter().filter(|(n, _)| n == "index.html").count(), 1);
    assert!(pages[0].1.contains("The texts' claims, checked exactly"));
    // every text's page is linked from the index and holds its claim
    for (k, (name, html)) in pages.iter().skip(1).enumerate() {
        assert!(pages[0].1.contains(&format!("href=\"{name}\"")), "{name}");
        assert!(html.contains(&format!("id=\"claim-c{k}\"")), "{name}");
    }
}

#[test]
fn statements_render_in_time_proportional_to_their_length() {
    for s in [
        "a_{".repeat(300_000),
        "a^(".repeat(300_000),
        format!("{}b{}", "a_{".repeat(100_000), "}".repeat(100_000)),
    ] {
        let start = thread_cpu();
        let html = formula(&s);
        let took = thread_cpu() - start;
        assert!(took < Duration::from_secs(1), "{took:?} of CPU");
        assert!(html.len() >= s.len());
    }
    // nested scripts still nest
    assert_eq!(formula("x_{a_{b}}^2"), "x<sub>a<sub>b</sub></sub><sup>2</sup>");
}

fn temp(name: &str, content: &str) -> std::path::PathBuf {
    let dir = std::env::temp_dir().join(format!("casteljau-hostile-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let path = dir.join(name);
    std::fs::write(&path, content).unwrap();
    path
}

fn latex_statement(path: &Path, id: &str) -> String {
    latex_statement_timed(path, id).0
}

/// The statement's LaTeX, and the CPU time the program took to write it.
fn latex_statement_timed(path: &Path, id: &str) -> (String, Duration) {
    let (out, took) = run_timed(Command::new(env!("CARGO_BIN_EXE_casteljau")).args([
        "--format",
        "latex",
        "prove",
        path.to_str().unwrap(),
        "--explain",
        id,
    ]));
    assert!(out.status.success(), "{}", String::from_utf8_lossy(&out.stderr));
    let text = String::from_utf8(out.stdout).unwrap();
    let line = text.lines().find(|l| l.starts_with("Statement: ")).unwrap();
    let statement = line["Statement: ".len()..].strip_suffix("\\\\").unwrap().to_string();
    (statement, took)
}

/// Control words LaTeX output of a statement may hold: only those the renderer writes.
const WRITTEN: &[&str] = &[
    "backslash",
    "sim",
    "textbackslash",
    "textasciitilde",
    "texttt",
    "mathrm",
    "dot",
    "mbox",
    "begin",
    "end",
    "hat",
    "textless",
    "textgreater",
    "textbar",
    "prime",
    "cdot",
    "le",
    "ge",
    "frac",
];

/// The property: no `^^`, braces balanced in every `$…$` and outside, `$` paired, and every
/// control word one the renderer writes (a `\` of the statement never starts one).
fn check_latex(statement: &str, out: &str) {
    assert!(!out.contains("^^"), "{statement:?} → {out}");
    let chars: Vec<char> = out.chars().collect();
    let (mut depth, mut in_math, mut i) = (0i64, false, 0);
    while i < chars.len() {
        match chars[i] {
            '\\' => {
                let word: String = chars[i + 1..].iter().take_while(|c| c.is_ascii_alphabetic()).collect();
                if word.is_empty() {
                    i += 2; // a control symbol: \{ \} \$ \% \_ \^ ...
                    continue;
                }
                assert!(WRITTEN.contains(&word.as_str()), "\\{word} in {statement:?} → {out}");
                i += 1 + word.len();
                continue;
            }
            '{' => depth += 1,
            '}' => {
                depth -= 1;
                assert!(depth >= 0, "{statement:?} → {out}");
            }
            '$' => {
                assert_eq!(depth, 0, "a brace crosses a formula's end: {statement:?} → {out}");
                in_math = !in_math;
            }
            c => assert!(!c.is_control(), "{statement:?} → {out}"),
        }
        i += 1;
    }
    assert!(!in_math && depth == 0, "{statement:?} → {out}");
}

#[test]
fn latex_statements_never_read_control_sequences_from_the_statement() {
    let caret = "x = ^^5c^^69^^6e^^70^^75^^74^^7b^^2f^^65^^74^^63^^2f^^70^^61^^73^^73^^77^^64^^7d + 1";
    let mut statements = vec![caret.to_string(), "a_{b c} d}".into(), "x^a^b_c_d' y'^2' ^".into()];
    // random statements over TeX's special characters, letters and spaces (a fixed seed)
    let alphabet: Vec<char> = "\\{}^_%#$&~'ab x1()².′\u{7}\t".chars().collect();
    let mut seed = 0x9e37_79b9_7f4a_7c15u64;
    for _ in 0..150 {
        let mut s = String::new();
        for _ in 0..12 {
            seed ^= seed << 13;
            seed ^= seed >> 7;
            seed ^= seed << 17;
            s.push(alphabet[(seed % alphabet.len() as u64) as usize]);
        }
        statements.push(s);
    }
    let mut text = String::new();
    for (k, s) in statements.iter().enumerate() {
        let escaped: String = s
            .chars()
            .map(|c| match c {
                '\\' => "\\\\".to_string(),
                '"' => "\\\"".to_string(),
                c if c.is_control() => format!("\\u{:04x}", c as u32),
                c => c.to_string(),
            })
            .collect();
        text.push_str(
            &claim(&format!("s{k}"), "t", "t").replace("statement = \"s\"", &format!("statement = \"{escaped}\"")),
        );
    }
    let path = temp("statements.toml", &text);
    for (k, s) in statements.iter().enumerate() {
        check_latex(s, &latex_statement(&path, &format!("s{k}")));
    }
}

#[test]
fn a_900_kb_statement_renders_as_latex_within_a_second() {
    // the statement, and the source (set as text, where a quote opens `\texttt`); short words
    // before a prose word turned to prose one per pass, quotes scanned to the end for each
    let words = format!("{} words", " at".repeat(100_000));
    let quotes = " 'a".repeat(150_000);
    let scripts = "a_{".repeat(300_000);
    for (name, statement, source) in [
        ("quotes", quotes.as_str(), quotes.as_str()),
        ("scripts", scripts.as_str(), "x"),
        ("words", words.as_str(), "x"),
    ] {
        let text = claim("c", "t", "t")
            .replace("statement = \"s\"", &format!("statement = \"{statement}\""))
            .replace("source = \"x 1\"", &format!("source = \"{source}\""));
        let path = temp(&format!("{name}.toml"), &text);
        let (out, took) = latex_statement_timed(&path, "c");
        assert!(took < Duration::from_secs(1), "{name}: {took:?} of CPU");
        assert!(!out.contains("^^"));
    }
}
