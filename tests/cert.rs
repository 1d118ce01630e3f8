//! Certificates as data (`docs/certificates.md`): the texts' certificates in
//! `tests/certificates/texts/` are what `prove --certificates` writes today, the kernel
//! re-checks every re-checkable one, and tampered copies are refused — or, where a mutant
//! still proves its (changed) goal, the search proves that goal too.

use casteljau::verify::{
    check_certificate, check_certificate_texts, claims, identity_file, prove_files, write_certificates, Recheck,
    Verdict,
};
use serde_json::Value;
use std::path::{Path, PathBuf};

const DIR: &str = concat!(env!("CARGO_MANIFEST_DIR"), "/tests/certificates/texts");

fn committed() -> Vec<(PathBuf, String)> {
    let mut files: Vec<PathBuf> = std::fs::read_dir(DIR)
        .unwrap()
        .map(|e| e.unwrap().path())
        .filter(|p| p.extension().is_some_and(|x| x == "json"))
        .collect();
    files.sort();
    files
        .into_iter()
        .map(|p| (p.clone(), std::fs::read_to_string(p).unwrap()))
        .collect()
}

#[test]
fn the_committed_certificates_are_what_prove_writes() {
    let proofs = Path::new(env!("CARGO_MANIFEST_DIR")).join("proofs");
    let files = claims::load_paths(&[proofs]).unwrap();
    let report = prove_files(&files, &mut |_, _, _| {}).unwrap();
    let out = std::env::temp_dir().join(format!("casteljau-cert-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&out);
    assert_eq!(write_certificates(&report, &out).unwrap(), 155);
    let written = std::fs::read_dir(&out).unwrap().count();
    assert_eq!(written, 155, "one file per claim");
    for (path, text) in committed() {
        let name = path.file_name().unwrap();
        let fresh = std::fs::read_to_string(out.join(name)).unwrap();
        assert!(
            fresh == text,
            "{} is stale: run prove --certificates tests/certificates/texts",
            name.to_string_lossy()
        );
    }
    assert_eq!(committed().len(), 155);
    std::fs::remove_dir_all(&out).unwrap();
}

#[test]
fn every_recheckable_certificate_is_accepted_and_the_others_say_why() {
    let (mut accepted, mut none) = (0, 0);
    // Checked together, as `casteljau check DIR` does: a proof citing a lemma needs its file.
    let all = committed();
    let texts: Vec<&str> = all.iter().map(|(_, t)| t.as_str()).collect();
    for ((path, text), r) in all.iter().zip(check_certificate_texts(&texts)) {
        let cert: Value = serde_json::from_str(text).unwrap();
        match cert["check"].as_str().unwrap() {
            "kernel" => {
                assert!(matches!(r, Recheck::Accepted(_)), "{}: {r:?}", path.display());
                accepted += 1;
            }
            _ => {
                assert!(
                    matches!(r, Recheck::NotChecked(ref why) if !why.is_empty()),
                    "{}: {r:?}",
                    path.display()
                );
                none += 1;
            }
        }
    }
    assert_eq!((accepted, none), (155, 0));
}

/// Where a mutant changes the file.
fn is_rational(s: &str) -> bool {
    let body = s.strip_prefix('-').unwrap_or(s);
    !body.is_empty()
        && body.split('/').count() <= 2
        && body
            .split('/')
            .all(|p| !p.is_empty() && p.bytes().all(|b| b.is_ascii_digit()))
}

fn bump_rational(s: &str) -> Vec<String> {
    let (num, den) = s.split_once('/').unwrap_or((s, "1"));
    let n: i128 = num.parse().unwrap();
    let d: i128 = den.parse().unwrap();
    let mut out = vec![if d == 1 {
        format!("{}", n + 1)
    } else {
        format!("{}/{d}", n + d)
    }];
    if n != 0 {
        out.push(if d == 1 {
            format!("{}", -n)
        } else {
            format!("{}/{d}", -n)
        });
    }
    out
}

/// Every digit run of an expression incremented, one at a time, and its first sign flipped.
fn edit_expression(s: &str) -> Vec<String> {
    let bytes = s.as_bytes();
    let mut out = Vec::new();
    let mut i = 0;
    while i < bytes.len() {
        if bytes[i].is_ascii_digit() {
            let start = i;
            while i < bytes.len() && bytes[i].is_ascii_digit() {
                i += 1;
            }
            let n: u64 = s[start..i].parse().unwrap();
            out.push(format!("{}{}{}", &s[..start], n + 1, &s[i..]));
        } else {
            i += 1;
        }
    }
    for (from, to) in [(" + ", " - "), (" - ", " + ")] {
        if let Some(k) = s.find(from) {
            out.push(format!("{}{to}{}", &s[..k], &s[k + from.len()..]));
        }
    }
    out
}

/// Most mutants of the numbers of one file (spread evenly over its leaves): the largest file
/// has 4,356 grid points.
const PER_FILE: usize = 250;

/// The mutants of one certificate: the numbers of its data, its degree bounds, its integer
/// cases, each goal expression edited (its data kept), each equality's sides swapped, a row
/// dropped; an expansion's coefficients and exponents, its variables and its two sides' data
/// exchanged, a term dropped; a computation's inputs, its equation and its result (at most
/// [`PER_FILE`] edits of leaves, and five equalities, per file).
fn mutants(cert: &Value) -> Vec<(String, Value)> {
    // (path, replacement) pairs, built before any copy of the file is made.
    fn walk(v: &Value, path: &mut Vec<String>, edits: &mut Vec<(Vec<String>, Value)>) {
        let key = path.last().map(String::as_str).unwrap_or("");
        let mut set = |new: Value| edits.push((path.clone(), new));
        match v {
            Value::Object(o) => {
                for (k, x) in o {
                    path.push(k.clone());
                    walk(x, path, edits);
                    path.pop();
                }
            }
            Value::Array(a) => {
                for (i, x) in a.iter().enumerate() {
                    path.push(i.to_string());
                    walk(x, path, edits);
                    path.pop();
                }
            }
            Value::Number(n) => {
                let n = n.as_u64().unwrap();
                set(Value::from(n + 1));
                if n > 0 {
                    set(Value::from(n - 1));
                }
            }
            Value::String(s)
                if (key == "lhs" || key == "rhs" || key == "premise")
                    && (path[0] == "goal" || path[0] == "computation") =>
            {
                for e in edit_expression(s) {
                    set(Value::from(e));
                }
            }
            Value::String(s) if key == "kind" => {
                for other in ["ellipse", "parabola", "hyperbola", "degenerate"] {
                    if other != s {
                        set(Value::from(other));
                    }
                }
            }
            Value::String(s) if key == "lhs_degree" || key == "rhs_degree" => {
                let (num, rest) = s
                    .split_once('/')
                    .map_or((s.as_str(), String::new()), |(a, b)| (a, format!("/{b}")));
                let n: u64 = num.parse().unwrap();
                set(Value::from(format!("{}{rest}", n + 1)));
            }
            Value::String(s) if is_rational(s) => {
                for b in bump_rational(s) {
                    set(Value::from(b));
                }
            }
            _ => {}
        }
    }
    let mut edits = Vec::new();
    for part in ["goal", "sampling", "fails", "expansion", "computation", "convergence"] {
        if let Some(v) = cert.get(part) {
            walk(v, &mut vec![part.to_string()], &mut edits);
        }
    }
    let step = edits.len().div_ceil(PER_FILE).max(1);
    let mut out: Vec<(String, Value)> = edits
        .into_iter()
        .step_by(step)
        .map(|(path, new)| {
            let mut m = cert.clone();
            let mut at = &mut m;
            for k in &path {
                at = match at {
                    Value::Array(a) => &mut a[k.parse::<usize>().unwrap()],
                    Value::Object(o) => o.get_mut(k).unwrap(),
                    _ => unreachable!(),
                };
            }
            *at = new;
            let label: Vec<&str> = path
                .iter()
                .map(|k| if k.parse::<usize>().is_ok() { "#" } else { k })
                .collect();
            (label.join("."), m)
        })
        .collect();
    // A computation's certificate has no goal (its facts are edited above).
    let eqs = cert["goal"]["equalities"].as_array().map_or(0, Vec::len);
    for i in 0..eqs.min(5) {
        let mut m = cert.clone();
        let eq = &mut m["goal"]["equalities"][i];
        let (l, r) = (eq["lhs"].clone(), eq["rhs"].clone());
        eq["lhs"] = r;
        eq["rhs"] = l;
        out.push(("swapped sides".into(), m));
        if let Some(points) = cert["goal"]["equalities"][i]["control_points"]
            .as_array()
            .filter(|p| p.len() >= 2)
        {
            let mut m = cert.clone();
            m["goal"]["equalities"][i]["control_points"] = Value::from(points[..points.len() - 1].to_vec());
            out.push(("a control point dropped".into(), m));
            let mut m = cert.clone();
            m["goal"]["equalities"][i]["control_points"]
                .as_array_mut()
                .unwrap()
                .swap(0, 1);
            out.push(("two control points swapped".into(), m));
        }
        if let Some(vars) = cert["expansion"]["equalities"][i]["vars"].as_array() {
            // The variables exchanged, the two sides' data exchanged, a term dropped.
            let x = &cert["expansion"]["equalities"][i];
            let mut m = cert.clone();
            let mut v = vars.clone();
            v.reverse();
            m["expansion"]["equalities"][i]["vars"] = Value::from(v);
            out.push(("variables exchanged".into(), m));
            let mut m = cert.clone();
            let entry = &mut m["expansion"]["equalities"][i]["entries"][0];
            (entry["lhs"], entry["rhs"]) = (x["entries"][0]["rhs"].clone(), x["entries"][0]["lhs"].clone());
            out.push(("data sides exchanged".into(), m));
            let mut m = cert.clone();
            m["expansion"]["equalities"][i]["entries"][0]["lhs"]["num"]
                .as_array_mut()
                .unwrap()
                .pop();
            out.push(("a term dropped".into(), m));
        }
        if let Some(rows) = cert["sampling"]["equalities"][i]["values"].as_array() {
            let mut m = cert.clone();
            m["sampling"]["equalities"][i]["values"]
                .as_array_mut()
                .unwrap()
                .remove(rows.len() - 1);
            out.push(("a row dropped".into(), m));
        }
    }
    out
}

/// The search's verdict on an equality with control points: a claim file declaring the
/// polygon or net of the listed points (an unlisted point is 0 in both).
fn searched_on_points(eq: &Value, reals: &[String]) -> Verdict {
    let points = eq["control_points"].as_array().unwrap();
    let name = points[0]["name"].as_str().unwrap();
    let index = |p: &Value| -> Vec<i64> {
        p["index"]
            .as_array()
            .unwrap()
            .iter()
            .map(|i| i.as_i64().unwrap())
            .collect()
    };
    let top: Vec<i64> = (0..index(&points[0]).len())
        .map(|k| points.iter().map(|p| index(p)[k]).max().unwrap())
        .collect();
    let decl = match top.as_slice() {
        [n] => format!("polygon = {{ name = \"{name}\", degree = \"{n}\" }}"),
        [m, n] => format!("net = {{ name = \"{name}\", degree = [\"{m}\", \"{n}\"] }}"),
        _ => return Verdict::Error,
    };
    let ranges: Vec<String> = eq["ints"]
        .as_object()
        .unwrap()
        .iter()
        .map(|(k, v)| format!("\"{k} = {0}..={0}\"", v.as_str().unwrap()))
        .collect();
    let text = format!(
        "[text]\nfile = \"mutant.txt\"\ntitle = \"mutant\"\n\n[[claim]]\nid = \"mutant\"\nsource = \"mutant\"\nstatement = \"mutant\"\nkind = \"identity\"\n{decl}\nvars = {:?}\nfor = [{}]\nlhs = {:?}\nrhs = {:?}\n",
        reals,
        ranges.join(", "),
        eq["lhs"].as_str().unwrap(),
        eq["rhs"].as_str().unwrap()
    );
    let dir = std::env::temp_dir().join(format!("casteljau-mutant-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let path = dir.join("mutant.toml");
    std::fs::write(&path, text).unwrap();
    let verdict = match claims::load_paths(&[path]) {
        Ok(files) => prove_files(&files, &mut |_, _, _| {}).unwrap().outcomes[0].verdict,
        Err(_) => Verdict::Error,
    };
    std::fs::remove_dir_all(&dir).unwrap();
    verdict
}

/// The search's verdict on one equality of a goal, at its integer case.
fn searched(eq: &Value, reals: &[String]) -> Verdict {
    if eq.get("control_points").is_some() {
        return searched_on_points(eq, reals);
    }
    let ranges: Vec<String> = eq["ints"]
        .as_object()
        .unwrap()
        .iter()
        .map(|(k, v)| format!("{k} = {0}..={0}", v.as_str().unwrap()))
        .collect();
    let identity = format!("{} = {}", eq["lhs"].as_str().unwrap(), eq["rhs"].as_str().unwrap());
    let file = match identity_file(&identity, &ranges, Some(reals)) {
        Ok(f) => f,
        Err(_) => return Verdict::Error,
    };
    prove_files(&[file], &mut |_, _, _| {}).unwrap().outcomes[0].verdict
}

/// The search's verdict on one equality of an expansion goal: its real symbols declared as a
/// claim's `symbols`, so that the search expands it symbolically (a grid over ten or more
/// parameters of a rational function is not what the search does).
fn expanded(eq: &Value, reals: &[String]) -> Verdict {
    assert!(
        eq["ints"].as_object().unwrap().is_empty(),
        "no integer cases in the texts' expansions"
    );
    let q = |v: &Value| serde_json::to_string(v).unwrap();
    let text = format!(
        "[[claim]]\nid = \"mutant\"\nsource = \"test\"\nstatement = \"mutant\"\nkind = \"identity\"\nsymbols = {}\nlhs = {}\nrhs = {}\n",
        q(&Value::from(reals.to_vec())),
        q(&eq["lhs"]),
        q(&eq["rhs"])
    );
    let file = match claims::parse_file(&text, Path::new("mutant.toml")) {
        Ok(f) => f,
        Err(_) => return Verdict::Error,
    };
    prove_files(&[file], &mut |_, _, _| {}).unwrap().outcomes[0].verdict
}

#[test]
fn tampered_certificates_are_refused_or_prove_a_true_goal() {
    let (mut total, mut refused, mut still_true) = (0, 0, 0);
    let mut kinds = std::collections::BTreeMap::new();
    for (path, text) in committed() {
        let cert: Value = serde_json::from_str(&text).unwrap();
        // The for-every certificates (`pieces` data) have their own test: tests/cert_hyper.rs;
        // the facts citing lemmas theirs: tests/cert_nonneg.rs.
        if cert["check"] != "kernel" || cert.get("pieces").is_some() || cert.get("lemmas").is_some() {
            continue;
        }
        for (label, m) in mutants(&cert) {
            total += 1;
            if std::env::var("CERT_DEBUG").is_ok() {
                eprintln!("{} {total}", path.display());
            }
            match check_certificate(&m.to_string()) {
                Recheck::Refused(why) => {
                    assert!(why.contains(':') || !why.is_empty());
                    refused += 1;
                }
                Recheck::NotChecked(why) => panic!("{}: a mutant not checked: {why}", path.display()),
                // Every distance of bounded evidence is computed again: only an edited control
                // point whose curve has the same distances (the maximum taken elsewhere) may pass,
                // and then the evidence is true of the edited curve.
                Recheck::Accepted(what) if m["verdict"] == "verified" => {
                    assert!(
                        label.contains("points"),
                        "{}: an accepted mutant of bounded evidence ({label}): {what}",
                        path.display()
                    );
                    still_true += 1;
                    *kinds.entry("evidence of an edited curve".to_string()).or_insert(0) += 1;
                }
                Recheck::Accepted(_) if m["method"] == "computation" => {
                    // The named library computation, run again on the mutant's inputs, gives its
                    // result: what the proof rests on agrees (a fact, not an identity to search).
                    still_true += 1;
                    *kinds.entry("computation input".to_string()).or_insert(0) += 1;
                }
                Recheck::Accepted(_) => {
                    // The mutant still proves (or refutes) its goal: the search must agree.
                    let reals: Vec<String> = m["goal"]["symbols"]
                        .as_array()
                        .unwrap()
                        .iter()
                        .filter(|s| s["sort"] == "real")
                        .map(|s| s["name"].as_str().unwrap().to_string())
                        .collect();
                    let eqs = m["goal"]["equalities"].as_array().unwrap();
                    if m["verdict"] == "fails" {
                        let k = m["fails"]["equality"].as_u64().unwrap() as usize;
                        // An implication's equation (17 coordinates) is searched symbolically; the
                        // premise holds at the counterexample, re-checked above.
                        let v = if eqs[k].get("premise").is_some() {
                            expanded(&eqs[k], &reals)
                        } else {
                            searched(&eqs[k], &reals)
                        };
                        assert_eq!(v, Verdict::Fails, "{}: {m}", path.display());
                    } else {
                        for eq in eqs {
                            let v = if m["method"] == "expansion" {
                                expanded(eq, &reals)
                            } else {
                                searched(eq, &reals)
                            };
                            assert!(
                                v == Verdict::Proved || v == Verdict::ProvedInRange,
                                "{}: an accepted mutant whose goal the search does not prove ({v:?}): {m}",
                                path.display()
                            );
                        }
                    }
                    still_true += 1;
                    *kinds.entry(label).or_insert(0) += 1;
                }
            }
        }
    }
    eprintln!("accepted mutants by kind: {kinds:?}");
    eprintln!("tampering: {total} mutants, {refused} refused, {still_true} accepted with a goal the search proves");
    assert!(total >= 2_000, "{total} mutants");
    assert_eq!(total, refused + still_true);
}

#[test]
fn bad_files_are_refused_with_a_reason_not_a_panic() {
    for text in [
        "",
        "{",
        "[]",
        "{\"format\": 1}",
        "{\"format\": \"casteljau-certificate\", \"version\": 2}",
    ] {
        assert!(matches!(check_certificate(text), Recheck::Refused(_)), "{text}");
    }
    let (_, good) = committed()
        .into_iter()
        .find(|(p, _)| p.ends_with("000-ex4-x.json"))
        .unwrap();
    let mut cert: Value = serde_json::from_str(&good).unwrap();
    cert["goal"]["equalities"][0]["lhs"] = Value::from("b(t)");
    match check_certificate(&cert.to_string()) {
        Recheck::Refused(why) => assert!(why.contains("equality 0"), "{why}"),
        other => panic!("{other:?}"),
    }
}

/// The five files of text 001's example 2 (values in Q(√2)): accepted, and the edits that
/// matter for a field Q(√d) refused with their reason: a coefficient of √2 or the radicand of
/// a value, a sample point, the degree bound, the sides swapped, `sqrt(2)` made `sqrt(3)` in
/// one place (two fields) or `sqrt(8)` everywhere (not square-free), or `sqrt(t)`.
#[test]
fn goals_in_q_sqrt_d_are_rechecked_and_their_mutants_refused() {
    let files = [
        "001-ex2",
        "001-ex2-hyperbola",
        "001-proj-ex2-p",
        "001-proj-ex2-x",
        "001-proj-ex2-hyperbola",
    ];
    let refused = |m: &Value, label: &str, reason: &str| match check_certificate(&m.to_string()) {
        Recheck::Refused(why) => assert!(why.contains(reason), "{label}: {why}"),
        other => panic!("{label}: a mutant not refused: {other:?}"),
    };
    let mut irrational_values = 0;
    for name in files {
        let (_, text) = committed()
            .into_iter()
            .find(|(p, _)| p.ends_with(format!("{name}.json")))
            .unwrap();
        let cert: Value = serde_json::from_str(&text).unwrap();
        assert_eq!(cert["check"], "kernel", "{name}");
        match check_certificate(&text) {
            Recheck::Accepted(what) => assert!(what.contains("in Q(√2)"), "{name}: {what}"),
            other => panic!("{name}: {other:?}"),
        }
        let eq = &cert["sampling"]["equalities"][0];
        let rows = eq["values"].as_array().unwrap();
        // A value a + b√2: its b changed, its radicand changed (to a square-free 3, to 8).
        if let Some((k, j)) = (0..rows.len())
            .flat_map(|k| (0..rows[k]["lhs"].as_array().unwrap().len()).map(move |j| (k, j)))
            .find(|&(k, j)| rows[k]["lhs"][j].is_object())
        {
            irrational_values += 1;
            let path = |m: &mut Value, side: &str, key: &str, v: &str| {
                m["sampling"]["equalities"][0]["values"][k][side][j][key] = Value::from(v);
            };
            let b = rows[k]["lhs"][j]["irrational"].as_str().unwrap();
            let mut m = cert.clone();
            path(&mut m, "lhs", "irrational", &format!("{b}1"));
            refused(&m, &format!("{name}: the coefficient of √2"), "the left side is");
            let mut m = cert.clone();
            path(&mut m, "rhs", "radicand", "3");
            refused(&m, &format!("{name}: the radicand 3"), "the goal is in Q(√2)");
            let mut m = cert.clone();
            path(&mut m, "lhs", "radicand", "8");
            refused(&m, &format!("{name}: the radicand 8"), "not square-free");
        }
        let mut m = cert.clone();
        m["sampling"]["equalities"][0]["values"][0]["lhs"][0] = Value::from("1/1000");
        refused(&m, &format!("{name}: a value"), "the left side is");
        let mut m = cert.clone();
        m["sampling"]["equalities"][0]["params"][0]["points"][0] = Value::from("1/1000");
        refused(&m, &format!("{name}: a sample point"), "the grid's point");
        let mut m = cert.clone();
        let d = eq["params"][0]["degree"].as_u64().unwrap();
        m["sampling"]["equalities"][0]["params"][0]["degree"] = Value::from(d - 1);
        refused(&m, &format!("{name}: the degree bound"), "degree bound");
        let g = &cert["goal"]["equalities"][0];
        let mut m = cert.clone();
        (m["goal"]["equalities"][0]["lhs"], m["goal"]["equalities"][0]["rhs"]) = (g["rhs"].clone(), g["lhs"].clone());
        let p = &eq["params"][0];
        if p["lhs_degree"] == p["rhs_degree"] {
            // The same equality read the other way: its data proves it (the search agrees).
            assert!(
                matches!(check_certificate(&m.to_string()), Recheck::Accepted(_)),
                "{name}"
            );
        } else {
            refused(&m, &format!("{name}: the sides swapped"), "degree bound");
        }
        let side = if g["lhs"].as_str().unwrap().contains("sqrt(2)") {
            "lhs"
        } else {
            "rhs"
        };
        let text = g[side].as_str().unwrap();
        let mut m = cert.clone();
        m["goal"]["equalities"][0][side] = Value::from(text.replace("sqrt(2)", "sqrt(8)"));
        refused(&m, &format!("{name}: sqrt(8)"), "not square-free");
        let mut m = cert.clone();
        m["goal"]["equalities"][0][side] = Value::from(text.replace("sqrt(2)", "sqrt(t)"));
        refused(&m, &format!("{name}: sqrt(t)"), "not an integer d ≥ 2");
        let mut m = cert.clone();
        m["goal"]["equalities"][0][side] = Value::from(text.replacen("sqrt(2)", "sqrt(3)", 1));
        let two_fields = text.matches("sqrt(2)").count() > 1
            || g[if side == "lhs" { "rhs" } else { "lhs" }]
                .as_str()
                .unwrap()
                .contains("sqrt(2)");
        refused(
            &m,
            &format!("{name}: sqrt(3) once"),
            if two_fields {
                "mixes sqrt(3) and sqrt(2)"
            } else {
                "equality 0"
            },
        );
    }
    assert_eq!(irrational_values, 3, "001-ex2 and 001-proj-ex2-x list values a + b√2");
}
