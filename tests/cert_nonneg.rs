//! Certificates of the inequality `000-basis-nonneg` (a `>=` goal for every value, with each
//! live term's nonnegativity obligation) and of the `computation` facts `000-convex-hull` and
//! `000-affine`, which cite it and `000-partition-of-unity` as lemmas (`docs/certificates.md`):
//! the committed files are accepted, and tampered copies are refused.

use casteljau::verify::{check_certificate, check_certificate_texts, Recheck};
use serde_json::Value;
use std::path::PathBuf;

const DIR: &str = concat!(env!("CARGO_MANIFEST_DIR"), "/tests/certificates/texts");

fn committed(id: &str) -> Value {
    let text = std::fs::read_to_string(PathBuf::from(DIR).join(format!("{id}.json"))).unwrap();
    serde_json::from_str(&text).unwrap()
}

const NONNEG: &str = "000-basis-nonneg";
const UNITY: &str = "000-partition-of-unity";

/// `cert` checked together with the committed lemma files (`nonneg` in place of the committed
/// `000-basis-nonneg`, when given).
fn with_lemmas(cert: &Value, nonneg: Option<&Value>) -> Recheck {
    let lemma = nonneg.cloned().unwrap_or_else(|| committed(NONNEG));
    let texts = [cert.to_string(), lemma.to_string(), committed(UNITY).to_string()];
    let refs: Vec<&str> = texts.iter().map(String::as_str).collect();
    check_certificate_texts(&refs).remove(0)
}

fn refused(r: Recheck, label: &str) -> String {
    match r {
        Recheck::Refused(why) => why,
        other => panic!("{label}: not refused: {other:?}"),
    }
}

#[test]
fn the_three_files_are_accepted_with_their_lemmas() {
    let nonneg = committed(NONNEG);
    assert_eq!(nonneg["check"], "kernel");
    assert_eq!(nonneg["goal"]["relation"], ">=");
    match check_certificate(&nonneg.to_string()) {
        Recheck::Accepted(what) => assert!(what.contains("nonnegativity obligations are the file's"), "{what}"),
        other => panic!("{other:?}"),
    }
    for id in ["000-convex-hull", "000-affine"] {
        let cert = committed(id);
        assert_eq!(cert["check"], "kernel", "{id}");
        assert!(matches!(with_lemmas(&cert, None), Recheck::Accepted(_)), "{id}");
        // Alone, its lemmas' files are not given.
        match check_certificate(&cert.to_string()) {
            Recheck::NotChecked(why) => assert!(why.starts_with("rests on lemma"), "{why}"),
            other => panic!("{id}: {other:?}"),
        }
    }
}

/// Every string of the `nonnegative` data edited (digits, signs, names), one at a time.
fn data_mutants(cert: &Value) -> Vec<(String, Value)> {
    fn walk(v: &Value, path: &mut Vec<String>, out: &mut Vec<(Vec<String>, Value)>) {
        match v {
            Value::Object(o) => {
                for (k, x) in o {
                    path.push(k.clone());
                    walk(x, path, out);
                    path.pop();
                }
            }
            Value::Array(a) => {
                for (i, x) in a.iter().enumerate() {
                    path.push(i.to_string());
                    walk(x, path, out);
                    path.pop();
                }
            }
            Value::String(s) => {
                let mut edits = vec![format!("{s}0"), format!("-{s}"), s.replace('i', "n")];
                if let Some(k) = s.find(char::is_numeric) {
                    let d = s.as_bytes()[k] - b'0';
                    edits.push(format!("{}{}{}", &s[..k], (d + 1) % 10, &s[k + 1..]));
                }
                for e in edits.into_iter().filter(|e| e != s) {
                    out.push((path.clone(), Value::from(e)));
                }
            }
            _ => {}
        }
    }
    let mut edits = Vec::new();
    walk(&cert["pieces"]["nonnegative"], &mut vec![], &mut edits);
    edits
        .into_iter()
        .map(|(path, new)| {
            let mut m = cert.clone();
            let mut at = &mut m["pieces"]["nonnegative"];
            for k in &path {
                at = match at {
                    Value::Array(a) => &mut a[k.parse::<usize>().unwrap()],
                    Value::Object(o) => o.get_mut(k).unwrap(),
                    _ => unreachable!(),
                };
            }
            *at = new;
            (path.join("."), m)
        })
        .collect()
}

#[test]
fn tampered_inequality_certificates_are_refused() {
    let cert = committed(NONNEG);
    let mut named: Vec<(&str, Value)> = Vec::new();
    let mut m = cert.clone();
    m["goal"]["relation"] = Value::from("<=");
    named.push(("the inequality flipped", m));
    let mut m = cert.clone();
    m["goal"]["interval"]["to"] = Value::from("2");
    named.push(("the interval widened to [0, 2]", m));
    let mut m = cert.clone();
    m["goal"]["interval"]["from"] = Value::from("-1");
    named.push(("the interval widened to [-1, 1]", m));
    let mut m = cert.clone();
    m["goal"]["inequality"]["rhs"] = Value::from("1");
    named.push(("the right side 1", m));
    let mut m = cert.clone();
    m["goal"]["inequality"]["lhs"] = Value::from("B(i, n, t) - 1");
    named.push(("the left side less 1", m));
    let mut m = cert.clone();
    m["goal"]["for_all"][1]["to"] = Value::from("n + 1");
    named.push(("i past n (B is 0 there: a true goal, other pieces)", m));
    let mut m = cert.clone();
    m["pieces"]["nonnegative"][0]["terms"].as_array_mut().unwrap().clear();
    named.push(("the live terms dropped", m));
    let mut m = cert.clone();
    m["pieces"]["certificates"] = Value::from(vec!["1"]);
    named.push(("a WZ certificate added", m));
    let mut m = cert.clone();
    m["verdict"] = Value::from("proved_in_range");
    m["range"] = Value::from("n = 0..=3");
    named.push(("proved in range", m));
    // Each Bernstein coefficient with its sign changed (a zero made -1).
    let powers = cert["pieces"]["nonnegative"][0]["terms"][0]["powers"]
        .as_array()
        .unwrap();
    for (p, power) in powers.iter().enumerate() {
        for (k, c) in power["bernstein"].as_array().unwrap().iter().enumerate() {
            let c = c.as_str().unwrap();
            let flipped = if c == "0" { "-1".to_string() } else { format!("-{c}") };
            let mut m = cert.clone();
            m["pieces"]["nonnegative"][0]["terms"][0]["powers"][p]["bernstein"][k] = Value::from(flipped);
            named.push(("a Bernstein coefficient's sign changed", m));
        }
    }
    assert!(named.len() >= 13, "{}", named.len());
    for (label, m) in &named {
        let why = refused(check_certificate(&m.to_string()), label);
        assert!(!why.is_empty(), "{label}");
    }
    // On [0, 2] the kernel's own check refuses: (1 − t) has the Bernstein coefficients 1, −1.
    let why = refused(check_certificate(&named[1].1.to_string()), "widened");
    assert!(why.contains("not shown ≥ 0") || why.contains("fails"), "{why}");
    let all = data_mutants(&cert);
    assert!(all.len() >= 40, "{} data mutants", all.len());
    for (label, m) in all {
        refused(check_certificate(&m.to_string()), &label);
    }
}

#[test]
fn tampered_lemma_facts_are_refused() {
    let hull = committed("000-convex-hull");
    let affine = committed("000-affine");
    let mut cases: Vec<(&str, Value, Option<Value>)> = Vec::new();
    for cert in [&hull, &affine] {
        let mut m = cert.clone();
        m["lemmas"].as_array_mut().unwrap().pop();
        cases.push(("a lemma dropped", m, None));
        let mut m = cert.clone();
        m.as_object_mut().unwrap().remove("lemmas");
        cases.push(("the lemmas dropped", m, None));
        let mut m = cert.clone();
        m["computation"]["facts"][0]["sum_one"] = Value::from("000-basis-recursion");
        cases.push(("another claim as the sum lemma", m, None));
        let mut m = cert.clone();
        m["computation"]["facts"][0]["degrees"]["from"] = Value::from("-1");
        cases.push(("a negative degree", m, None));
        let mut m = cert.clone();
        m["computation"]["facts"][0]["degrees"]["to"] = Value::from("1000");
        cases.push(("a degree over the limit", m, None));
        let mut m = cert.clone();
        m["rests_on"] = Value::from(Vec::<String>::new());
        cases.push(("rests_on emptied", m, None));
        // The lemma's goal edited in the citing file (the lemma's file states another).
        let mut m = cert.clone();
        let last = m["lemmas"].as_array().unwrap().len() - 1;
        m["lemmas"][last]["goal"]["equalities"][0]["rhs"] = Value::from("2");
        cases.push(("the cited sum's goal edited", m, None));
    }
    let mut m = hull.clone();
    m["lemmas"][0]["goal"]["interval"]["to"] = Value::from("2");
    cases.push(("the cited interval widened", m, None));
    // The cited goal edited in both files: the lemma's file is then refused (its own proof).
    let mut lemma = committed(NONNEG);
    lemma["goal"]["interval"]["to"] = Value::from("2");
    let mut m = hull.clone();
    m["lemmas"][0]["goal"]["interval"]["to"] = Value::from("2");
    cases.push(("the lemma widened in both files", m, Some(lemma)));
    // A Bernstein coefficient of the lemma's file changed: the lemma is refused, so is its user.
    let mut lemma = committed(NONNEG);
    lemma["pieces"]["nonnegative"][0]["terms"][0]["powers"][0]["bernstein"][1] = Value::from("-1");
    cases.push(("the lemma's data tampered", hull.clone(), Some(lemma)));
    let mut m = hull.clone();
    m["computation"]["facts"][0]["computation"] = Value::from("affine_invariance");
    cases.push(("the hull read as the affine fact (rests on transform)", m, None));
    for (label, m, lemma) in &cases {
        refused(with_lemmas(m, lemma.as_ref()), label);
    }
}
