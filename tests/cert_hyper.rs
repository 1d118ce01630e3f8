//! Certificates of for-every proofs (`pieces` data, methods `pieces` and `wz`,
//! `docs/certificates.md`): tampered copies of the texts' certificates are refused by
//! `casteljau check`, or, where a mutant is still accepted, `prove` proves its changed goal
//! as a claim over the same ranges (with its polygon or net).

use casteljau::verify::{check_certificate, check_certificate_texts, claims, prove_files, Recheck, Verdict};
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
        // An inequality's goal (`>=`) has its own test: tests/cert_nonneg.rs.
        .filter(|(_, v)| v.get("pieces").is_some() && v["goal"]["relation"] == "=")
        .collect()
}

/// The committed certificate of claim `id`.
fn committed_file(id: &str) -> Value {
    let text = std::fs::read_to_string(PathBuf::from(DIR).join(format!("{id}.json"))).unwrap();
    serde_json::from_str(&text).unwrap()
}

/// The ids of the lemmas a certificate cites.
fn lemma_ids(cert: &Value) -> Vec<String> {
    cert.get("lemmas")
        .and_then(Value::as_array)
        .map(|l| l.iter().map(|x| x["id"].as_str().unwrap().to_string()).collect())
        .unwrap_or_default()
}

/// The committed files of the lemmas `cert` cites, and of theirs.
fn lemma_files(cert: &Value) -> Vec<Value> {
    let mut out: Vec<Value> = Vec::new();
    let mut todo = lemma_ids(cert);
    while let Some(id) = todo.pop() {
        if out.iter().any(|f| f["id"] == id.as_str()) {
            continue;
        }
        let f = committed_file(&id);
        todo.extend(lemma_ids(&f));
        out.push(f);
    }
    out
}

/// `cert` re-checked together with the committed files of its lemmas.
fn check_with_lemmas(cert: &Value) -> Recheck {
    let mut texts = vec![cert.to_string()];
    texts.extend(lemma_files(cert).iter().map(Value::to_string));
    let refs: Vec<&str> = texts.iter().map(String::as_str).collect();
    check_certificate_texts(&refs).remove(0)
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
    for (k, lemma) in cert
        .get("lemmas")
        .and_then(Value::as_array)
        .into_iter()
        .flatten()
        .enumerate()
    {
        for i in 0..lemma["goal"]["equalities"].as_array().unwrap().len() {
            edit("lemma goal side", &format!("/lemmas/{k}/goal/equalities/{i}/lhs"), cert);
            edit("lemma goal side", &format!("/lemmas/{k}/goal/equalities/{i}/rhs"), cert);
        }
        for i in 0..lemma["goal"]["for_all"].as_array().unwrap().len() {
            edit("lemma range end", &format!("/lemmas/{k}/goal/for_all/{i}/from"), cert);
            edit("lemma range end", &format!("/lemmas/{k}/goal/for_all/{i}/to"), cert);
        }
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
    let cited = cert.get("lemmas").and_then(Value::as_array).map_or(0, Vec::len);
    for k in 0..cited {
        let mut m = cert.clone();
        m["lemmas"].as_array_mut().unwrap().remove(k);
        out.push(("a lemma dropped".into(), m));
    }
    // The induction variable changed to each other range symbol, or dropped; a proof by
    // pieces made an induction on its first range symbol.
    let ranges: Vec<String> = cert["goal"]["for_all"]
        .as_array()
        .unwrap()
        .iter()
        .map(|r| r["name"].as_str().unwrap().to_string())
        .collect();
    match cert["pieces"].get("induction").and_then(Value::as_str) {
        Some(var) => {
            for other in ranges.iter().filter(|r| *r != var) {
                let mut m = cert.clone();
                m["pieces"]["induction"] = Value::from(other.as_str());
                out.push(("induction variable".into(), m));
            }
            let mut m = cert.clone();
            m["pieces"].as_object_mut().unwrap().remove("induction");
            out.push(("induction dropped".into(), m));
        }
        None => {
            let mut m = cert.clone();
            m["pieces"]["induction"] = Value::from(ranges[0].as_str());
            out.push(("induction added".into(), m));
        }
    }
    let mut m = cert.clone();
    m["verdict"] = Value::from("proved_in_range");
    m["range"] = Value::from("n = 0..=3");
    out.push(("verdict".into(), m));
    out
}

/// A claim file's `[[claim]]` stating the goal of certificate `m` as claim `id`, proved as
/// `m` says (its WZ certificates, induction variable and lemmas).
fn claim_toml(id: &str, m: &Value) -> String {
    let g = &m["goal"];
    let q = |s: &str| format!("{s:?}");
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
        "[[claim]]\nid = \"{id}\"\nsource = \"test\"\nstatement = \"mutant\"\nkind = \"identity\"\nfor = [{}]\nvars = [{}]\nchain = [{}]\n",
        ranges.join(", "),
        reals.join(", "),
        chain.join(", ")
    );
    if !certs.is_empty() {
        toml.push_str(&format!("certificate = [{}]\n", certs.join(", ")));
    }
    if let Some(var) = m["pieces"].get("induction").and_then(Value::as_str) {
        toml.push_str(&format!("induction = \"{var}\"\n"));
    }
    let uses: Vec<String> = lemma_ids(m).iter().map(|l| q(l)).collect();
    if !uses.is_empty() {
        toml.push_str(&format!("uses = [{}]\n", uses.join(", ")));
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
    toml
}

/// The verdict `prove` gives a mutant's goal as a claim over the same ranges (citing the
/// committed lemmas, stated from their files), and its one-line certificate (or reason).
fn proved(m: &Value) -> (Verdict, String) {
    let mut toml = String::new();
    for lemma in lemma_files(m).iter().rev() {
        toml.push_str(&claim_toml(lemma["id"].as_str().unwrap(), lemma));
    }
    toml.push_str(&claim_toml("mutant", m));
    let path = std::env::temp_dir().join(format!("casteljau-mutant-{}.toml", std::process::id()));
    std::fs::write(&path, toml).unwrap();
    let verdict = match claims::load_paths(std::slice::from_ref(&path)) {
        Ok(files) => {
            let report = prove_files(&files, &mut |_, _, _| {}).unwrap();
            let o = report.outcomes.iter().find(|o| o.id == "mutant").unwrap();
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
    let mut citing = 0;
    for (path, cert) in &all {
        let r = check_with_lemmas(cert);
        assert!(matches!(r, Recheck::Accepted(_)), "{}: {r:?}", path.display());
        // Alone, a proof citing a lemma is not re-checked: the lemma's file is not given.
        if let Some(id) = lemma_ids(cert).first() {
            citing += 1;
            match check_certificate(&cert.to_string()) {
                Recheck::NotChecked(why) => {
                    assert_eq!(why, format!("rests on lemma {id}, whose file was not given"))
                }
                other => panic!("{}: {other:?}", path.display()),
            }
        }
    }
    assert_eq!(citing, 10, "the certificates citing lemmas");
}

#[test]
fn tampered_pieces_certificates_are_refused_or_prove_a_true_goal() {
    let (mut total, mut refused, mut still_true) = (0, 0, 0);
    let mut kinds = std::collections::BTreeMap::new();
    for (path, cert) in committed() {
        for (label, m) in mutants(&cert) {
            total += 1;
            match check_with_lemmas(&m) {
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

#[test]
fn a_lemma_reference_must_name_a_file_given_accepted_with_the_same_goal_and_no_cycle() {
    let cert = committed_file("000-1");
    let lemma = committed_file("000-9-intermediate");
    let check = |texts: &[&Value]| {
        let t: Vec<String> = texts.iter().map(|v| v.to_string()).collect();
        let refs: Vec<&str> = t.iter().map(String::as_str).collect();
        check_certificate_texts(&refs)
    };
    assert!(matches!(&check(&[&cert, &lemma])[0], Recheck::Accepted(_)));
    // The listed goal differs from the lemma file's (the lemma's range widened).
    let mut other = cert.clone();
    other["lemmas"][0]["goal"]["for_all"][1]["to"] = Value::from("n + 1");
    match &check(&[&other, &lemma])[0] {
        Recheck::Refused(why) => assert!(why.contains("states another goal"), "{why}"),
        r => panic!("{r:?}"),
    }
    // The lemma file's goal edited (its own data kept): the lemma refused, and so the proof.
    let mut bad = lemma.clone();
    bad["goal"]["equalities"][0]["rhs"] = Value::from("sum(j, 0, r, b[i + j]*B(j, r, t)) + 1");
    let mut cites_bad = cert.clone();
    cites_bad["lemmas"][0]["goal"] = bad["goal"].clone();
    match &check(&[&cites_bad, &bad])[..] {
        [Recheck::Refused(why), Recheck::Refused(_)] => assert!(why.contains("which is refused"), "{why}"),
        r => panic!("{r:?}"),
    }
    // A missing lemma: not re-checked, never accepted.
    let mut missing = cert.clone();
    missing["lemmas"][0]["id"] = Value::from("000-no-such-lemma");
    match &check(&[&missing, &lemma])[0] {
        Recheck::NotChecked(why) => assert_eq!(why, "rests on lemma 000-no-such-lemma, whose file was not given"),
        r => panic!("{r:?}"),
    }
    // Two files stating the lemma.
    match &check(&[&cert, &lemma, &lemma])[0] {
        Recheck::Refused(why) => assert!(why.contains("2 files state it"), "{why}"),
        r => panic!("{r:?}"),
    }
    // A cycle: the induction also cites the proof that cites it (a lemma it never applies, so
    // each file alone is accepted); both are refused, the cycle named.
    let mut cyclic = lemma.clone();
    let derivative = committed_file("000-derivative-proof");
    cyclic["lemmas"] = serde_json::json!([{"id": "000-derivative-proof", "goal": derivative["goal"]}]);
    let closed = committed_file("000-delta-closed-form");
    let mut derivative_cites = derivative.clone();
    derivative_cites["lemmas"][0]["goal"] = cyclic["goal"].clone();
    let r = check(&[&derivative_cites, &cyclic, &closed]);
    for x in &r[..2] {
        match x {
            Recheck::Refused(why) => assert!(
                why.contains("the lemmas form a cycle: ") && why.contains("000-derivative-proof → 000-9-intermediate")
                    || why.contains("000-9-intermediate → 000-derivative-proof"),
                "{why}"
            ),
            r => panic!("{r:?}"),
        }
    }
    assert!(matches!(r[2], Recheck::Accepted(_)), "{:?}", r[2]);
}
