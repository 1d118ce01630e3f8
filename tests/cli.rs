//! The `casteljau` command through the built binary: outputs, JSON, exit statuses, errors.

use serde_json::{json, Value};
use std::process::{Command, Output};

fn casteljau(args: &[&str]) -> Output {
    Command::new(env!("CARGO_BIN_EXE_casteljau"))
        .args(args)
        .output()
        .expect("the casteljau binary runs")
}

/// Runs a command that must succeed; returns its stdout.
fn ok(args: &[&str]) -> String {
    let out = casteljau(args);
    assert!(
        out.status.success(),
        "{args:?} failed: {}",
        String::from_utf8_lossy(&out.stderr)
    );
    assert!(out.stderr.is_empty(), "{args:?} wrote to stderr");
    String::from_utf8(out.stdout).unwrap()
}

/// Runs a command that must fail with status 2 and one line on stderr; returns that line.
fn fails(args: &[&str]) -> String {
    let out = casteljau(args);
    assert_eq!(out.status.code(), Some(2), "{args:?} should exit 2");
    assert!(out.stdout.is_empty(), "{args:?} printed to stdout");
    let err = String::from_utf8(out.stderr).unwrap();
    assert!(!err.contains("panicked"), "{args:?} panicked: {err}");
    err
}

fn json_out(args: &[&str]) -> Value {
    serde_json::from_str(&ok(args)).unwrap()
}

// text 000, §1.3: the Bézier points of (-u² + 1, -u³ + u), -1 ≤ u ≤ 1
const CUBIC: &str = "0,0; 4/3,-4/3; 4/3,4/3; 0,0";

#[test]
fn eval_prints_exact_fractions() {
    assert_eq!(ok(&["eval", CUBIC, "--t", "1/3"]), "(8/9, -8/27)\n");
    // t = 1/2 is u = 0: the point (1, 0)
    assert_eq!(ok(&["eval", CUBIC, "--t", "0.5"]), "(1, 0)\n");
    // negative parameters and decimals, exactly
    assert_eq!(ok(&["eval", "0; 1; 3", "--t", "-1/2"]), "(-3/4)\n");
    assert_eq!(
        json_out(&["eval", CUBIC, "--t", "1/3", "--format", "json"]),
        json!({"ok": true, "point": ["8/9", "-8/27"]})
    );
}

#[test]
fn eval_scheme_prints_the_triangle() {
    let out = ok(&["eval", CUBIC, "--t", "1/3", "--scheme"]);
    assert!(out.starts_with("de Casteljau scheme (9) at t = 1/3\n"), "{out}");
    assert!(out.contains("b_0^1 = (4/9, -4/9)"), "{out}");
    assert!(out.contains("b_0^3 = (8/9, -8/27)"), "{out}");
    assert!(out.ends_with("b(1/3) = (8/9, -8/27)\n"), "{out}");
    let j = json_out(&["--format", "json", "eval", CUBIC, "--t", "1/3", "--scheme"]);
    assert_eq!(j["scheme"][3], json!([["8/9", "-8/27"]]));
    assert_eq!(j["scheme"][0][1], json!(["4/3", "-4/3"]));
}

#[test]
fn elevate_split_derivative() {
    assert_eq!(
        ok(&["elevate", "0,0; 1,2; 3,1", "--by", "2"]),
        "(0, 0); (1/2, 1); (7/6, 3/2); (2, 3/2); (3, 1)\n"
    );
    assert_eq!(
        ok(&["split", "0,0; 1,2; 3,1", "--t", "1/2"]),
        "left:  (0, 0); (1/2, 1); (5/4, 5/4)\nright: (5/4, 5/4); (2, 3/2); (3, 1)\n"
    );
    let j = json_out(&["split", "0; 1; 3", "--t", "1/2", "--format", "json"]);
    assert_eq!(
        j,
        json!({"ok": true, "left": [["0"], ["1/2"], ["5/4"]], "right": [["5/4"], ["2"], ["3"]]})
    );
    assert_eq!(ok(&["derivative", "0,0; 1,2; 3,1"]), "(2, 4); (4, -2)\n");
    assert_eq!(ok(&["derivative", "0,0; 1,2; 3,1", "--order", "2"]), "(2, -6)\n");
    assert_eq!(ok(&["derivative", "0,0; 1,2; 3,1", "--at", "1/2"]), "(3, 1)\n");
    assert_eq!(
        ok(&["derivative", "0,0; 1,2; 3,1", "--order", "3", "--at", "1/2"]),
        "(0, 0)\n"
    );
    // 4t − 4t² and 1 as a quadratic: the parabola's Bézier points
    assert_eq!(ok(&["to-bezier", "0,1; 4,0; -4,0"]), "(0, 1); (2, 1); (0, 1)\n");
}

#[test]
fn rational_conic_surface_fit() {
    // text 001, Example 3
    assert_eq!(
        ok(&["conic", "-1,1; 0,-1; 1,1", "--weights", "1, 1/2, 1"]),
        "type: ellipse\nimplicit: 4x^2 + 3y^2 - 10y + 3 = 0\n"
    );
    assert_eq!(
        json_out(&["conic", "-1,1; 0,-1; 1,1", "--weights", "1, 1, 1", "--format", "json"]),
        json!({"ok": true, "type": "parabola", "implicit": ["1", "0", "0", "0", "-1", "0"]})
    );
    assert_eq!(
        ok(&["eval", "1,0; 1,1; 0,1", "--weights", "1,1,2", "--t", "1/2"]),
        "(3/5, 4/5)\n"
    );
    assert_eq!(
        ok(&["surface", "0,0,0; 0,1,0 | 1,0,0; 1,1,1", "--u", "1/3", "--v", "3/4"]),
        "(1/3, 3/4, 1/4)\n"
    );
    let fit = [
        "fit", "--x0", "0,0,0", "--x1", "4,0,5", "--xh", "2,3/2,1", "--d0", "3,6,0", "--d1", "3,-6,12",
    ];
    assert_eq!(
        ok(&fit),
        "k = 1/3\nl = 1/3\npoints: (0, 0, 0); (1, 2, 0); (3, 2, 1); (4, 0, 5)\ndelta2 = 0\n"
    );
    let err = fails(&[
        "fit", "--x0", "0,0", "--x1", "1,0", "--xh", "0,1", "--d0", "1,0", "--d1", "2,0",
    ]);
    assert!(err.contains("parallel"), "{err}");
    let err = fails(&["conic", "-1,1; 0,-1; 1,1", "--weights", "1, 1/2"]);
    assert!(err.contains("2 weights for 3 control points"), "{err}");
    let err = fails(&["surface", "0,0 | 1,0; 1,1", "--u", "0", "--v", "0"]);
    assert!(err.contains("ragged"), "{err}");
}

#[test]
fn printed_points_are_valid_input() {
    let elevated = ok(&["elevate", CUBIC, "--by", "3"]);
    let a = ok(&["eval", elevated.trim(), "--t", "2/7"]);
    let b = ok(&["eval", CUBIC, "--t", "2/7"]);
    assert_eq!(a, b);
}

#[test]
fn bad_input_is_one_line_on_stderr_and_status_2() {
    let cases: &[(&[&str], &str)] = &[
        (&["eval", "0,0; 1", "--t", "1"], "dimension mismatch"),
        (&["eval", "0,0", "--t", "1/0"], "zero denominator"),
        (&["eval", "0,0", "--t", "abc"], "not a number"),
        (&["eval", "", "--t", "0"], "empty"),
        (&["eval", "0,x", "--t", "0"], "point 0: coordinate 1"),
        (&["eval", "0,0", "--t", "1e999999999"], "too large"),
        (
            &["elevate", "0,0", "--by", "1000000000000"],
            "degree after elevation is too large",
        ),
        (&["elevate", "0,0", "--by", "-1"], "non-negative integer"),
        (&["derivative", "0,0; 1,1", "--order", "2"], "order 2"),
        (&["to-bezier", "0,1; 4"], "dimension mismatch"),
        (&["prove", "/no/such/dir"], "no such file or directory"),
    ];
    for (args, needle) in cases {
        let err = fails(args);
        assert!(err.starts_with("casteljau: "), "{args:?}: {err}");
        assert_eq!(err.lines().count(), 1, "{args:?}: {err}");
        assert!(err.contains(needle), "{args:?}: {err:?} should mention {needle:?}");
    }
}

#[test]
fn usage_errors_exit_2_and_help_exits_0() {
    let out = casteljau(&["frobnicate"]);
    assert_eq!(out.status.code(), Some(2));
    let out = casteljau(&["eval", "0,0"]);
    assert_eq!(out.status.code(), Some(2), "missing --t");
    assert!(String::from_utf8_lossy(&out.stderr).contains("--t"));
    let out = casteljau(&["--help"]);
    assert_eq!(out.status.code(), Some(0));
    assert!(String::from_utf8_lossy(&out.stdout).contains("oracle"));
}

#[test]
fn prove_reports_and_sets_the_status() {
    // The real claim files: every verdict as expected, exit 0, the misprints listed.
    let out = casteljau(&["prove", "proofs", "--format", "json"]);
    assert_eq!(out.status.code(), Some(0), "{}", String::from_utf8_lossy(&out.stderr));
    let report: Value = serde_json::from_slice(&out.stdout).expect("prove --format json prints one JSON object");
    assert_eq!(report["summary"]["mismatches"].as_u64(), Some(0));
    let failing: Vec<&str> = report["summary"]["failing"]
        .as_array()
        .unwrap()
        .iter()
        .map(|v| v.as_str().unwrap())
        .collect();
    assert_eq!(failing, ["000-ex4-y", "003-two-stage", "004-8", "004-10"]);
    for claim in report["claims"].as_array().unwrap() {
        for field in ["id", "source", "statement", "verdict", "certificate", "expect"] {
            assert!(claim[field].is_string(), "claim without {field}: {claim}");
        }
        // Exactly one of four verdicts; a range exactly on proved_in_range.
        let verdict = claim["verdict"].as_str().unwrap();
        assert!(
            ["proved", "proved_in_range", "verified", "fails"].contains(&verdict),
            "{claim}"
        );
        assert_eq!(claim["range"].is_string(), verdict == "proved_in_range", "{claim}");
    }
    assert_eq!(report["summary"]["proved_in_range"].as_u64(), Some(17));
    // progress goes to stderr only on a terminal, never into a piped run
    assert!(out.stderr.is_empty());

    // A claim file whose claim does not get its expected verdict: exit 1, the mismatch named.
    let dir = std::env::temp_dir().join(format!("casteljau-cli-test-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    std::fs::write(
        dir.join("wrong.toml"),
        "[[claim]]\nid = \"wrong\"\nsource = \"test\"\nstatement = \"t^2 = t\"\nkind = \"identity\"\nlhs = \"t^2\"\nrhs = \"t\"\n",
    )
    .unwrap();
    let out = casteljau(&["prove", dir.to_str().unwrap()]);
    assert_eq!(out.status.code(), Some(1));
    let text = String::from_utf8_lossy(&out.stdout);
    assert!(text.contains("[fails] wrong") && text.contains("MISMATCH"), "{text}");
    assert!(text.contains("counterexample"), "{text}");

    // --explain: the step-by-step proof, and a clear error for an unknown id.
    let out = casteljau(&["prove", "--explain", "000-ex4-points"]);
    assert_eq!(out.status.code(), Some(0));
    let text = String::from_utf8_lossy(&out.stdout);
    assert!(text.contains("t = 1/3: both sides = (8/9, -8/27)"), "{text}");
    let err = fails(&["prove", dir.to_str().unwrap(), "--explain", "no-such-claim"]);
    assert!(err.contains("no-such-claim"), "{err}");
    // by default one screen (the argument, one worked case); --verbose adds the full log
    let fixture = "tests/support/subdivision_in_range.toml";
    let id = "lemma-1.3-proof-in-range";
    let short = ok(&["prove", fixture, "--explain", id]);
    // the proof on one screen, then its certificate file read back, folded
    let (proof, certificate) = short.split_once("\n\ncertificate file ").expect(&short);
    assert!(
        proof.lines().count() <= 40 && certificate.lines().count() <= 25,
        "{short}"
    );
    assert!(
        short.contains("why this suffices:") && !short.contains("\nsteps:"),
        "{short}"
    );
    let verbose = ok(&["prove", fixture, "--explain", id, "--verbose"]);
    assert!(verbose.contains("\nsteps:") && verbose.lines().count() > 1000);
    let latex = ok(&["--format", "latex", "prove", fixture, "--explain", id]);
    assert!(
        latex.contains("\\begin{array}{llll}") && latex.contains("\\paragraph{Claim"),
        "{latex}"
    );
    assert!(fails(&["prove", "--verbose"]).contains("--explain"));
    std::fs::remove_dir_all(&dir).unwrap();

    // No claim files at all is a usage error, not an empty success.
    let empty = std::env::temp_dir().join(format!("casteljau-cli-empty-{}", std::process::id()));
    std::fs::create_dir_all(&empty).unwrap();
    let err = fails(&["prove", empty.to_str().unwrap()]);
    assert!(err.contains("no claim files"), "{err}");
    std::fs::remove_dir_all(&empty).unwrap();
}

#[test]
fn prove_refuses_endless_empty_and_unbounded_claim_files() {
    // An endless file is refused before it is read whole; an empty one is not an empty success.
    // Devices are not claim files: refused before anything is read.
    for device in ["/dev/zero", "/dev/null"] {
        let err = fails(&["prove", device]);
        assert!(err.contains("not a regular file"), "{err}");
    }
    let dir = std::env::temp_dir().join(format!("casteljau-cli-bounds-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let empty = dir.join("empty.toml");
    std::fs::write(&empty, "").unwrap();
    let err = fails(&["prove", empty.to_str().unwrap()]);
    assert!(err.contains("no claims"), "{err}");
    // Unbounded work is refused at once, naming the limit.
    let big = dir.join("big.toml");
    std::fs::write(
        &big,
        "[[claim]]\nid = \"big\"\nsource = \"s\"\nstatement = \"s\"\nkind = \"identity\"\nlhs = \"((1+t)^4096)^24\"\nrhs = \"((1+t)^4096)^24\"\n",
    )
    .unwrap();
    // The claim is reported as undecided, with the limit as its one-line reason (exit 2).
    let out = casteljau(&["prove", big.to_str().unwrap()]);
    assert_eq!(out.status.code(), Some(2));
    let text = String::from_utf8(out.stdout).unwrap();
    let reason = text
        .lines()
        .find(|l| l.trim_start().starts_with("error:"))
        .unwrap_or_default();
    assert!(text.contains("[error] big") && reason.contains("MAX_WORK"), "{text}");
    // A range claim is reported with its scope, in text and JSON.
    let range = dir.join("range.toml");
    std::fs::write(
        &range,
        "[[claim]]\nid = \"r\"\nsource = \"s\"\nstatement = \"s\"\nkind = \"identity\"\nfor = [\"n = 0..=10\"]\nlhs = \"sum(i, 0, n, B(i, n, t))\"\nrhs = \"1 + C(n, 11)\"\n",
    )
    .unwrap();
    let text = ok(&["prove", range.to_str().unwrap()]);
    assert!(text.contains("[proved for n = 0..=10] r"), "{text}");
    let json = json_out(&["prove", range.to_str().unwrap(), "--format", "json"]);
    assert_eq!(json["claims"][0]["verdict"], "proved_in_range");
    assert_eq!(json["claims"][0]["range"], "n = 0..=10");
    assert_eq!(json["summary"]["proved_in_range"], 1);
    std::fs::remove_dir_all(&dir).unwrap();
}

#[test]
fn scheme_as_latex() {
    let out = ok(&["--format", "latex", "eval", "--scheme", "0,0; 1,1; 2,0", "--t", "1/2"]);
    assert_eq!(
        out,
        "\\[ t = \\frac{1}{2} \\]\n\\[\\begin{array}{lll}\n\
         b_{0} = \\left(0, 0\\right) \\\\\n\
         b_{1} = \\left(1, 1\\right) & b_{0}^{1} = \\left(\\frac{1}{2}, \\frac{1}{2}\\right) \\\\\n\
         b_{2} = \\left(2, 0\\right) & b_{1}^{1} = \\left(\\frac{3}{2}, \\frac{1}{2}\\right) & \
         b_{0}^{2} = \\left(1, \\frac{1}{2}\\right) \\\\\n\\end{array}\\]\n"
    );
    // negative fractions keep their sign outside \frac
    let neg = ok(&["--format", "latex", "eval", "--scheme", "0; -1", "--t", "1/3"]);
    assert!(neg.contains("b_{0}^{1} = -\\frac{1}{3}"), "{neg}");
    // LaTeX is only for the scheme and --explain
    assert!(fails(&["--format", "latex", "eval", "0,0; 1,1", "--t", "1/2"]).contains("--format latex"));
    assert!(fails(&["--format", "latex", "prove"]).contains("--format latex"));
}

/// Splits a documented command line on spaces outside quotes (`"…"` or `'…'`).
fn shell_words(cmd: &str) -> Vec<String> {
    let (mut words, mut cur, mut quote) = (Vec::new(), String::new(), None);
    for ch in cmd.chars() {
        match (ch, quote) {
            ('"' | '\'', None) => quote = Some(ch),
            (c, Some(q)) if c == q => quote = None,
            (' ', None) => {
                if !cur.is_empty() {
                    words.push(std::mem::take(&mut cur));
                }
            }
            _ => cur.push(ch),
        }
    }
    words.push(cur);
    words
}

/// What a documented command prints: stdout when it succeeds, its one stderr line when it
/// fails. Understands `casteljau ARGS`, `… | tail -N` and `echo 'LINE' | casteljau ARGS`.
fn documented_output(cmd: &str) -> String {
    let (mut cmd, mut tail) = (cmd, None);
    if let Some((head, n)) = cmd.rsplit_once(" | tail -") {
        (cmd, tail) = (head, Some(n.parse::<usize>().unwrap()));
    }
    let mut stdin = None;
    if let Some(rest) = cmd.strip_prefix("echo ") {
        let (line, rest) = rest.split_once(" | ").unwrap();
        stdin = Some(format!("{}\n", shell_words(line).concat()));
        cmd = rest;
    }
    let args = shell_words(cmd.strip_prefix("casteljau ").expect(cmd));
    let mut child = Command::new(env!("CARGO_BIN_EXE_casteljau"))
        .args(&args)
        .stdin(std::process::Stdio::piped())
        .stdout(std::process::Stdio::piped())
        .stderr(std::process::Stdio::piped())
        .spawn()
        .unwrap();
    {
        use std::io::Write as _;
        let mut pipe = child.stdin.take().unwrap();
        pipe.write_all(stdin.unwrap_or_default().as_bytes()).unwrap();
    }
    let out = child.wait_with_output().unwrap();
    // `prove` prints its report and exits 1 when a verdict is not the expected one (a false
    // `--identity` is documented that way)
    let reported = out.status.code() == Some(1) && args.first().is_some_and(|a| a == "prove");
    let text = if out.status.success() || reported {
        String::from_utf8(out.stdout).unwrap()
    } else {
        assert_eq!(out.status.code(), Some(2), "`{cmd}`");
        String::from_utf8(out.stderr).unwrap()
    };
    match tail {
        Some(n) => {
            let lines: Vec<&str> = text.lines().collect();
            lines[lines.len().saturating_sub(n)..]
                .iter()
                .map(|l| format!("{l}\n"))
                .collect()
        }
        None => text,
    }
}

/// Every `console` example of the README and of the guides in `docs/` is what the program
/// prints, byte for byte: each `$ casteljau …` line with the lines under it (up to the next
/// `$` line), and the oracle's example session with its requests and responses.
#[test]
fn readme_and_guide_examples_are_exact() {
    let root = env!("CARGO_MANIFEST_DIR");
    let mut docs = vec![std::path::PathBuf::from(format!("{root}/README.md"))];
    let mut guides: Vec<_> = std::fs::read_dir(format!("{root}/docs"))
        .unwrap()
        .map(|e| e.unwrap().path())
        .filter(|p| p.extension().is_some_and(|x| x == "md"))
        .collect();
    guides.sort();
    docs.extend(guides);
    let mut checked = 0;
    for doc in &docs {
        let text = std::fs::read_to_string(doc).unwrap();
        let name = doc.file_name().unwrap().to_string_lossy();
        for block in text.split("```console\n").skip(1) {
            let block = block.split("\n```").next().unwrap();
            let mut examples: Vec<(&str, String)> = Vec::new();
            for line in block.lines() {
                match line.strip_prefix("$ ") {
                    Some(cmd) => examples.push((cmd, String::new())),
                    None => {
                        let (_, expected) = examples.last_mut().expect("a console block starts with `$ `");
                        expected.push_str(line);
                        expected.push('\n');
                    }
                }
            }
            for (cmd, expected) in examples {
                if cmd.contains(" < ") {
                    continue; // the oracle session, checked below from its two blocks
                }
                assert_eq!(documented_output(cmd), expected, "{name}: `{cmd}`");
                checked += 1;
            }
        }
        if let Some(rest) = text.split("Requests (`session.jsonl`):\n\n```json\n").nth(1) {
            let requests = rest.split("```").next().unwrap();
            let responses = rest
                .split("Responses:\n\n```json\n")
                .nth(1)
                .unwrap()
                .split("```")
                .next()
                .unwrap();
            let mut child = Command::new(env!("CARGO_BIN_EXE_casteljau"))
                .arg("oracle")
                .stdin(std::process::Stdio::piped())
                .stdout(std::process::Stdio::piped())
                .spawn()
                .unwrap();
            {
                use std::io::Write as _;
                child.stdin.take().unwrap().write_all(requests.as_bytes()).unwrap();
            }
            let out = child.wait_with_output().unwrap();
            assert_eq!(
                String::from_utf8(out.stdout).unwrap(),
                responses,
                "{name}: the oracle session"
            );
            checked += 1;
        }
    }
    assert!(checked >= 25, "only {checked} documented examples found");
}

/// An installed binary proves the texts anywhere: without a path and without `proofs/` in
/// the working directory it uses the claims built into it, with the very same report;
/// `prove DIR` still reads only the user's files.
#[test]
fn prove_without_a_checkout_uses_the_builtin_claims() {
    let empty = std::env::temp_dir().join(format!("casteljau-cli-anywhere-{}", std::process::id()));
    std::fs::create_dir_all(&empty).unwrap();
    let run = |args: &[&str]| {
        Command::new(env!("CARGO_BIN_EXE_casteljau"))
            .args(args)
            .current_dir(&empty)
            .output()
            .unwrap()
    };
    let anywhere = run(&["prove"]);
    assert_eq!(
        anywhere.status.code(),
        Some(0),
        "{}",
        String::from_utf8_lossy(&anywhere.stderr)
    );
    let here = ok(&["prove"]);
    assert_eq!(String::from_utf8(anywhere.stdout).unwrap(), here);
    assert!(here.contains("total                           155"), "{here}");
    let explained = run(&["prove", "--explain", "004-8"]);
    assert!(String::from_utf8_lossy(&explained.stdout).contains("correction: 004-8-corrected"));
    // a path that is not there is an error, never a silent fallback to the built-in claims
    let missing = run(&["prove", "proofs"]);
    assert_eq!(missing.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&missing.stderr).contains("no such file or directory: proofs"));
    // a user's directory is read, and only it
    std::fs::write(
        empty.join("mine.toml"),
        "[[claim]]\nid = \"mine\"\nsource = \"s\"\nstatement = \"t(1-t) = t - t^2\"\nkind = \"identity\"\nlhs = \"t*(1-t)\"\nrhs = \"t - t^2\"\n",
    )
    .unwrap();
    let mine = run(&["prove", "."]);
    let text = String::from_utf8(mine.stdout).unwrap();
    assert!(text.contains("[proved] mine") && !text.contains("000-ex4-y"), "{text}");
    std::fs::remove_dir_all(&empty).unwrap();
}

#[test]
fn prove_refuses_a_fifo_at_once() {
    let dir = std::env::temp_dir().join(format!("casteljau-cli-fifo-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let fifo = dir.join("f.toml");
    let made = Command::new("mkfifo").arg(&fifo).status();
    if !made.is_ok_and(|s| s.success()) {
        eprintln!("no mkfifo here: nothing to test");
        return;
    }
    // with no writer, opening the FIFO would block forever: the command must not open it
    for target in [fifo.clone(), dir.clone()] {
        let mut child = Command::new(env!("CARGO_BIN_EXE_casteljau"))
            .arg("prove")
            .arg(&target)
            .stdout(std::process::Stdio::piped())
            .stderr(std::process::Stdio::piped())
            .spawn()
            .unwrap();
        let start = std::time::Instant::now();
        while child.try_wait().unwrap().is_none() {
            if start.elapsed() > std::time::Duration::from_secs(10) {
                child.kill().unwrap();
                panic!("prove {} blocked", target.display());
            }
            std::thread::sleep(std::time::Duration::from_millis(20));
        }
        let out = child.wait_with_output().unwrap();
        assert_eq!(out.status.code(), Some(2));
        let err = String::from_utf8(out.stderr).unwrap();
        assert_eq!(err.lines().count(), 1, "{err}");
        assert!(err.contains("not a regular file"), "{err}");
    }
    std::fs::remove_dir_all(&dir).unwrap();
}

#[test]
fn prove_html_checks_its_directory_before_proving() {
    let dir = std::env::temp_dir().join(format!("casteljau-cli-html-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let claims = dir.join("c.toml");
    std::fs::write(
        &claims,
        "[[claim]]\nid = \"c\"\nsource = \"s\"\nstatement = \"s\"\nkind = \"identity\"\nlhs = \"(1+t)^2\"\nrhs = \"1 + 2t + t^2\"\n",
    )
    .unwrap();
    let c = claims.to_str().unwrap();
    // a file where the directory should be
    let err = fails(&["prove", c, "--html", c]);
    assert!(err.contains("not a directory"), "{err}");
    let report = dir.join("report");
    let r = report.to_str().unwrap();
    ok_with_stderr(&["prove", c, "--html", r]);
    let index = std::fs::read_to_string(report.join("index.html")).unwrap();
    // an existing report is kept unless --force
    let err = fails(&["prove", c, "--html", r]);
    assert!(err.contains("--force"), "{err}");
    std::fs::write(report.join("index.html"), "mine").unwrap();
    let err = fails(&["prove", c, "--html", r]);
    assert!(err.contains("already exists"), "{err}");
    assert_eq!(std::fs::read_to_string(report.join("index.html")).unwrap(), "mine");
    ok_with_stderr(&["prove", c, "--html", r, "--force"]);
    assert_eq!(std::fs::read_to_string(report.join("index.html")).unwrap(), index);
    assert!(fails(&["prove", c, "--force"]).contains("--html"));
    std::fs::remove_dir_all(&dir).unwrap();
}

/// Runs a command that must succeed and may report on stderr; returns its stdout.
fn ok_with_stderr(args: &[&str]) -> String {
    let out = casteljau(args);
    assert!(
        out.status.success(),
        "{args:?} failed: {}",
        String::from_utf8_lossy(&out.stderr)
    );
    String::from_utf8(out.stdout).unwrap()
}

#[test]
fn format_is_honoured_or_refused() {
    let err = fails(&[
        "--format",
        "latex",
        "prove",
        "--explain",
        "000-lemma-1.3-proof",
        "--verbose",
    ]);
    assert!(err.contains("--verbose does not apply to --format latex"), "{err}");
    for format in ["json", "latex", "text"] {
        let err = fails(&["--format", format, "figure", "construction"]);
        assert!(err.contains("--format does not apply to `figure`"), "{err}");
    }
    assert!(ok(&["figure", "construction"]).starts_with("<svg"));
}

#[test]
fn an_undecided_claim_keeps_the_report_and_adds_one_stderr_line() {
    // exit 2: the report (every other claim's verdict) on stdout, one line on stderr naming
    // the claims not decided
    let dir = std::env::temp_dir().join(format!("casteljau-cli-undecided-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let path = dir.join("u.toml");
    std::fs::write(
        &path,
        "[[claim]]\nid = \"ok\"\nsource = \"s\"\nstatement = \"s\"\nkind = \"identity\"\nlhs = \"(1+t)^2\"\nrhs = \"1 + 2t + t^2\"\n\n\
         [[claim]]\nid = \"bad\"\nsource = \"s\"\nstatement = \"s\"\nkind = \"identity\"\nlhs = \"sqrt(2)*sqrt(3)*t\"\nrhs = \"sqrt(6)*t\"\n",
    )
    .unwrap();
    let out = casteljau(&["prove", path.to_str().unwrap()]);
    assert_eq!(out.status.code(), Some(2));
    let stdout = String::from_utf8(out.stdout).unwrap();
    assert!(
        stdout.contains("[proved] ok") && stdout.contains("[error] bad"),
        "{stdout}"
    );
    let stderr = String::from_utf8(out.stderr).unwrap();
    assert_eq!(
        stderr,
        "casteljau: 1 claim not decided (each with its reason in the report): bad\n"
    );
    std::fs::remove_dir_all(&dir).unwrap();
}
