//! Certificates of for-every proofs (`pieces` data, methods `pieces` and `wz`,
//! `docs/certificates.md`): tampered copies of the texts' certificates are refused by
//! `casteljau check`, or, where a mutant is still accepted, `prove` proves its changed goal
//! as a claim over the same ranges (with its polygon or net).

use casteljau::verify::{check_certificate, claims, prove_files, Recheck, Verdict};
use serde_json::Value;
use std::path::PathBuf;

const DIR: &str = concat!(env!("CARGO_MANIFEST_DIR"), "/tests/certificates/texts");

/// The texts' certificates with `pieces` data.
fn committed() -> Vec<(PathBuf, Value)> {
    let mut files: Vec<PathBuf> = std::fs::read_dir(DIR)
        .unwrap()
        .map(|e| e.unwrap().path())
        .filter(|p| p.extension().is_some_and(|x| x == "json"))
        .collect();
    files.sort();
    files
        .into_iter()
        .map(|p| {
            let v: Value = serde_json::from_str(&std::fs::read_to_string(&p).unwrap()).unwrap();
            (p, v)
        })
        .filter(|(_, v)| v.get("pieces").is_some())
        .collect()
}

/// Every digit run incremented and decremented, one at a time; each ` + ` and ` - ` flipped;
/// each one-letter integer name replaced by another one.
fn edits(s: &str) -> Vec<String> {
    let b = s.as_bytes();
    let mut out = Vec::new();
    let mut i = 0;
    while i < b.len() {
        if b[i].is_ascii_digit() {
            let start = i;
            while i < b.len() && b[i].is_ascii_digit() {
                i += 1;
            }
            let n: u64 = s[start..i].parse().unwrap();
            out.push(format!("{}{}{}", &s[..start], n + 1, &s[i..]));
            if n > 0 {
                out.push(format!("{}{}{}", &s[..start], n - 1, &s[i..]));
            }
        } else {
            i += 1;
        }
    }
    for (from, to) in [(" + ", " - "), (" - ", " + ")] {
        for (k, _) in s.match_indices(from) {
            out.push(format!("{}{to}{}", &s[..k], &s[k + from.len()..]));
        }
    }
    if !s.is_empty() && !s.starts_with('-') {
        out.push(format!("-({s})"));
    }
    out.push(format!("{s} + 1"));
    out
}

/// The mutants of one certificate: its goal's expressions, range ends, polygon or net
/// degrees and WZ certificates edited (the rest kept), sides swapped, the method changed, a
/// certificate dropped or added, a range closed.
fn mutants(cert: &Value) -> Vec<(String, Value)> {
    let mut out = Vec::new();
    let mut edit = |label: &str, ptr: &str, cert: &Value| {
        if let Some(Value::String(s)) = cert.pointer(ptr) {
            for e in edits(s) {
                let mut m = cert.clone();
                *m.pointer_mut(ptr).unwrap() = Value::from(e);
                out.push((label.to_string(), m));
            }
        }
    };
    let eqs = cert["goal"]["equalities"].as_array().unwrap().len();
    for i in 0..eqs {
        // A chain's shared member edited on both sides of it keeps the chain: edit each
        // equality's ends; the left end of a later one edits the chain (refused as no chain).
        edit("goal side", &format!("/goal/equalities/{i}/lhs"), cert);
        edit("goal side", &format!("/goal/equalities/{i}/rhs"), cert);
    }
    for i in 0..cert["goal"]["for_all"].as_array().unwrap().len() {
        edit("range end", &format!("/goal/for_all/{i}/from"), cert);
        edit("range end", &format!("/goal/for_all/{i}/to"), cert);
    }
    edit("polygon degree", "/goal/polygon/degree", cert);
    edit("net degree", "/goal/net/degree/0", cert);
    edit("net degree", "/goal/net/degree/1", cert);
    for i in 0..cert["pieces"]["certificates"].as_array().unwrap().len() {
        edit("certificate R", &format!("/pieces/certificates/{i}"), cert);
    }
    for i in 0..eqs {
        let mut m = cert.clone();
        let eq = &mut m["goal"]["equalities"][i];
        let (l, r) = (eq["lhs"].clone(), eq["rhs"].clone());
        eq["lhs"] = r;
        eq["rhs"] = l;
        out.push(("swapped sides".into(), m));
    }
    let mut m = cert.clone();
    m["method"] = Value::from(if cert["method"] == "wz" { "pieces" } else { "wz" });
    out.push(("method".into(), m));
    let mut m = cert.clone();
    if m["pieces"]["certificates"].as_array_mut().unwrap().pop().is_some() {
        out.push(("a certificate dropped".into(), m));
    } else {
        m["pieces"]["certificates"] = serde_json::json!(["1"]);
        out.push(("a certificate added".into(), m));
    }
    let mut m = cert.clone();
    m["goal"]["for_all"][0]["to"] = Value::from("5");
    out.push(("a range closed".into(), m));
    let mut m = cert.clone();
    m["verdict"] = Value::from("proved_in_range");
    m["range"] = Value::from("n = 0..=3");
    out.push(("verdict".into(), m));
    out
}

/// The verdict `prove` gives a mutant's goal as a claim over the same ranges, and its
/// one-line certificate (or reason).
fn proved(m: &Value) -> (Verdict, String) {
    let g = &m["goal"];
    let q = |s: &str| format!("'{s}'");
    let ranges: Vec<String> = g["for_all"]
        .as_array()
        .unwrap()
        .iter()
        .map(|r| match r["to"].as_str() {
            Some(to) => q(&format!(
                "{} = {}..={to}",
                r["name"].as_str().unwrap(),
                r["from"].as_str().unwrap()
            )),
            None => q(&format!(
                "{} = {}..",
                r["name"].as_str().unwrap(),
                r["from"].as_str().unwrap()
            )),
        })
        .collect();
    let reals: Vec<String> = g["symbols"]
        .as_array()
        .unwrap()
        .iter()
        .filter(|s| s["sort"] == "real")
        .map(|s| q(s["name"].as_str().unwrap()))
        .collect();
    let eqs = g["equalities"].as_array().unwrap();
    let mut chain: Vec<String> = vec![q(eqs[0]["lhs"].as_str().unwrap())];
    chain.extend(eqs.iter().map(|e| q(e["rhs"].as_str().unwrap())));
    let certs: Vec<String> = m["pieces"]["certificates"]
        .as_array()
        .unwrap()
        .iter()
        .map(|c| q(c.as_str().unwrap()))
        .collect();
    let mut toml = format!(
        "[[claim]]\nid = \"mutant\"\nsource = \"test\"\nstatement = \"mutant\"\nkind = \"identity\"\nfor = [{}]\nvars = [{}]\nchain = [{}]\n",
        ranges.join(", "),
        reals.join(", "),
        chain.join(", ")
    );
    if !certs.is_empty() {
        toml.push_str(&format!("certificate = [{}]\n", certs.join(", ")));
    }
    if let Some(p) = g.get("polygon") {
        toml.push_str(&format!(
            "polygon = {{ name = \"{}\", degree = \"{}\" }}\n",
            p["name"].as_str().unwrap(),
            p["degree"].as_str().unwrap()
        ));
    }
    if let Some(n) = g.get("net") {
        toml.push_str(&format!(
            "net = {{ name = \"{}\", degree = [\"{}\", \"{}\"] }}\n",
            n["name"].as_str().unwrap(),
            n["degree"][0].as_str().unwrap(),
            n["degree"][1].as_str().unwrap()
        ));
    }
    let path = std::env::temp_dir().join(format!("casteljau-mutant-{}.toml", std::process::id()));
    std::fs::write(&path, toml).unwrap();
    let verdict = match claims::load_paths(std::slice::from_ref(&path)) {
        Ok(files) => {
            let o = &prove_files(&files, &mut |_, _, _| {}).unwrap().outcomes[0];
            (o.verdict, o.certificate.clone())
        }
        Err(e) => (Verdict::Error, e.to_string()),
    };
    std::fs::remove_file(&path).unwrap();
    verdict
}

#[test]
fn every_pieces_certificate_is_accepted() {
    let all = committed();
    assert!(all.len() >= 26, "{} pieces certificates", all.len());
    for (path, cert) in &all {
        let r = check_certificate(&cert.to_string());
        assert!(matches!(r, Recheck::Accepted(_)), "{}: {r:?}", path.display());
    }
}

#[test]
fn tampered_pieces_certificates_are_refused_or_prove_a_true_goal() {
    let (mut total, mut refused, mut still_true) = (0, 0, 0);
    let mut kinds = std::collections::BTreeMap::new();
    for (path, cert) in committed() {
        for (label, m) in mutants(&cert) {
            total += 1;
            match check_certificate(&m.to_string()) {
                Recheck::Refused(why) => {
                    assert!(!why.is_empty());
                    refused += 1;
                }
                Recheck::NotChecked(why) => panic!("{}: a mutant not checked: {why}", path.display()),
                Recheck::Accepted(_) => {
                    // A range made empty at some values (`j = 1..=n` at n = 0) is true there
                    // with nothing to prove; `prove` refuses such a claim as saying nothing.
                    let (v, why) = proved(&m);
                    assert!(
                        v == Verdict::Proved || (v == Verdict::Error && why.contains("empty")),
                        "{}: an accepted mutant ({label}) whose goal prove does not prove ({v:?}, {why}): {m}",
                        path.display()
                    );
                    still_true += 1;
                    *kinds.entry(label).or_insert(0) += 1;
                }
            }
        }
    }
    eprintln!("accepted mutants by kind: {kinds:?}");
    eprintln!("tampering (pieces): {total} mutants, {refused} refused, {still_true} accepted with a goal prove proves");
    assert!(total >= 1_000, "{total} mutants");
    assert_eq!(total, refused + still_true);
}

#[test]
fn an_edited_goal_with_its_data_kept_is_refused() {
    let (_, mut cert) = committed()
        .into_iter()
        .find(|(p, _)| p.ends_with("000-partition-of-unity.json"))
        .unwrap();
    cert["goal"]["equalities"][0]["rhs"] = Value::from("2");
    match check_certificate(&cert.to_string()) {
        Recheck::Refused(why) => assert!(why.contains("obligations"), "{why}"),
        other => panic!("{other:?}"),
    }
}
