//! Each claim's certificate file read back for people, in the HTML report and after
//! `--explain`: the tables show the file's own values, "re-checked by the kernel" appears
//! exactly when the kernel accepts the file, any other file says why not, a method's data
//! that has no layout of its own is still shown, and nothing in a certificate reaches a page
//! unescaped.

use casteljau::html::{certificate_html, render_pages, render_pages_linking};
use casteljau::verify::claims::{load_paths, parse_file};
use casteljau::verify::{
    explain_files, prove_files, prove_paths, read_back, readable, readable_among, write_certificates, ExplainStyle,
    Report, Status, Verdict,
};
use serde_json::{json, Value};
use std::path::{Path, PathBuf};
use std::sync::OnceLock;

fn proofs() -> Vec<PathBuf> {
    vec![PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("proofs")]
}

/// The report of the real claim files and its pages, each certificate embedded.
fn fixture() -> &'static (Report, Vec<(String, String)>) {
    static CELL: OnceLock<(Report, Vec<(String, String)>)> = OnceLock::new();
    CELL.get_or_init(|| {
        let report = prove_paths(&proofs(), &mut |_, _, _| {}).unwrap();
        let pages = render_pages(&report, &load_paths(&proofs()).unwrap()).unwrap();
        (report, pages)
    })
}

fn parse(html: &str) -> roxmltree::Document<'_> {
    let opts = roxmltree::ParsingOptions {
        allow_dtd: true,
        ..Default::default()
    };
    roxmltree::Document::parse_with_options(html, opts).unwrap_or_else(|e| panic!("not well-formed: {e}"))
}

fn has_class(n: &roxmltree::Node, class: &str) -> bool {
    n.attribute("class")
        .is_some_and(|c| c.split_whitespace().any(|x| x == class))
}

fn text_of(n: &roxmltree::Node) -> String {
    n.descendants()
        .filter(|d| d.is_text())
        .map(|d| d.text().unwrap_or(""))
        .collect()
}

/// The certificate block of claim `id` on its page, as `(page, block)` (the page parsed).
fn with_block<T>(id: &str, f: impl FnOnce(roxmltree::Node) -> T) -> T {
    let (_, pages) = fixture();
    let (_, html) = pages
        .iter()
        .find(|(_, h)| h.contains(&format!("data-claim=\"{id}\"")))
        .unwrap_or_else(|| panic!("no page has claim {id}"));
    let doc = parse(html);
    let section = doc
        .descendants()
        .find(|n| n.attribute("data-claim") == Some(id))
        .unwrap();
    let block = section
        .descendants()
        .find(|n| n.has_tag_name("details") && has_class(n, "certfile"))
        .unwrap_or_else(|| panic!("claim {id} has no certificate block"));
    f(block)
}

/// The certificate of claim `id` as `prove --certificates` writes it.
fn certificate_file(id: &str) -> Value {
    let (report, _) = fixture();
    let o = report.outcomes.iter().find(|o| o.id == id).unwrap();
    serde_json::from_str(&readable(o).json).unwrap()
}

/// A value as the tables show it: one value alone, several as `(a, b)`.
fn shown(v: &Value) -> String {
    let items: Vec<&str> = v.as_array().unwrap().iter().map(|x| x.as_str().unwrap()).collect();
    if items.len() == 1 {
        items[0].to_string()
    } else {
        format!("({})", items.join(", "))
    }
}

fn rows(table: roxmltree::Node) -> Vec<Vec<String>> {
    table
        .children()
        .filter(|r| r.has_tag_name("tr"))
        .map(|r| r.children().filter(|c| c.is_element()).map(|c| text_of(&c)).collect())
        .collect()
}

#[test]
fn the_file_read_back_is_the_file_written() {
    let (report, _) = fixture();
    let dir = std::env::temp_dir().join(format!("casteljau-view-{}", std::process::id()));
    write_certificates(report, &dir).unwrap();
    for o in &report.outcomes {
        let r = readable(o);
        let written = std::fs::read_to_string(dir.join(&r.file)).unwrap();
        assert_eq!(r.json, written, "{}", o.id);
    }
    std::fs::remove_dir_all(&dir).unwrap();
}

#[test]
fn a_sampling_table_shows_the_certificates_values() {
    let cert = certificate_file("000-ex4-points");
    assert_eq!(cert["check"], "kernel");
    let eq = &cert["sampling"]["equalities"][0];
    let names: Vec<&str> = eq["params"]
        .as_array()
        .unwrap()
        .iter()
        .map(|p| p["name"].as_str().unwrap())
        .collect();
    let mut want = vec![names.iter().map(|n| n.to_string()).collect::<Vec<_>>()];
    want[0].extend(["left side".to_string(), "right side".to_string()]);
    for row in eq["values"].as_array().unwrap() {
        let mut cells: Vec<String> = row["at"]
            .as_array()
            .unwrap()
            .iter()
            .map(|x| x.as_str().unwrap().to_string())
            .collect();
        cells.push(shown(&row["lhs"]));
        cells.push(shown(&row["rhs"]));
        want.push(cells);
    }
    assert!(want.len() > 2, "{want:?}");
    with_block("000-ex4-points", |block| {
        assert!(has_class(&block, "kernel"));
        let summary = block.children().find(|n| n.has_tag_name("summary")).unwrap();
        assert!(text_of(&summary).contains("re-checked by the kernel"));
        let tables: Vec<Vec<Vec<String>>> = block
            .descendants()
            .filter(|n| n.has_tag_name("table"))
            .map(rows)
            .collect();
        assert!(
            tables.contains(&want),
            "no table equals the certificate's values: {tables:?}"
        );
        // the degree bound of each variable, with its points, as the file gives it
        let p = &eq["params"][0];
        let points: Vec<&str> = p["points"]
            .as_array()
            .unwrap()
            .iter()
            .map(|x| x.as_str().unwrap())
            .collect();
        let bound = vec![
            p["name"].as_str().unwrap().to_string(),
            p["degree"].to_string(),
            p["lhs_degree"].as_str().unwrap().to_string(),
            p["rhs_degree"].as_str().unwrap().to_string(),
            points.join(", "),
        ];
        assert!(tables.iter().any(|t| t.contains(&bound)), "{tables:?}");
        // the file itself, embedded and folded
        let json = block
            .descendants()
            .find(|n| n.has_tag_name("details") && has_class(n, "json"))
            .unwrap();
        let pre = json.descendants().find(|n| n.has_tag_name("pre")).unwrap();
        assert_eq!(serde_json::from_str::<Value>(&text_of(&pre)).unwrap(), cert);
    });
}

#[test]
fn a_counterexample_shows_the_point_and_both_sides() {
    let cert = certificate_file("000-ex4-y");
    assert_eq!(cert["verdict"], "fails");
    assert_eq!(cert["check"], "kernel");
    let f = &cert["fails"];
    let at: Vec<String> = f["at"]
        .as_object()
        .unwrap()
        .iter()
        .map(|(k, v)| format!("{k} = {}", v.as_str().unwrap()))
        .collect();
    with_block("000-ex4-y", |block| {
        assert!(has_class(&block, "kernel"));
        let lines: Vec<(String, String)> = block
            .descendants()
            .filter(|n| n.has_tag_name("dt"))
            .map(|dt| {
                let dd = dt.next_sibling_element().unwrap();
                (text_of(&dt), text_of(&dd))
            })
            .collect();
        for want in [
            ("at".to_string(), at.join(", ")),
            ("left side".to_string(), shown(&f["lhs"])),
            ("right side".to_string(), shown(&f["rhs"])),
        ] {
            assert!(lines.contains(&want), "{want:?} not in {lines:?}");
        }
        assert_ne!(shown(&f["lhs"]), shown(&f["rhs"]));
    });
}

#[test]
fn re_checked_exactly_when_the_kernel_accepts_the_file_else_the_reason() {
    let (report, _) = fixture();
    let (mut kernel, mut none) = (0, 0);
    for o in &report.outcomes {
        let r = readable(o);
        let cert: Value = serde_json::from_str(&r.json).unwrap();
        let accepted = matches!(
            casteljau::verify::check_certificate(&r.json),
            casteljau::verify::Recheck::Accepted(_)
        );
        match &r.status {
            Status::Rechecked(_) => {
                assert!(accepted && cert["check"] == "kernel", "{}", o.id);
                kernel += 1;
            }
            Status::NotRechecked(why) if cert.get("lemmas").is_some() => {
                // A proof citing lemmas read back alone: the lemmas' files are not given.
                assert!(!accepted && cert["check"] == "kernel", "{}", o.id);
                assert!(
                    why.starts_with("rests on lemma ") && why.ends_with(", whose file was not given"),
                    "{why}"
                );
                none += 1;
            }
            Status::NotRechecked(why) => {
                assert!(!accepted, "{}", o.id);
                assert_eq!(cert["check"], "none", "{}", o.id);
                assert_eq!(why, cert["reason"].as_str().unwrap(), "{}", o.id);
                none += 1;
                with_block(&o.id, |block| {
                    assert!(has_class(&block, "none"));
                    let text = text_of(&block);
                    assert!(text.contains("not re-checked") && !text.contains("re-checked by the kernel"));
                    assert!(text.contains(why.as_str()), "{}: the reason is not shown", o.id);
                });
            }
        }
    }
    assert!(kernel > 0 && none > 0, "{kernel} re-checked, {none} not");
}

/// A proof citing lemmas is re-checked with the lemmas' certificates of the same run, as
/// `check DIR` does: in the report's page and by `readable_among`; without them it is not.
#[test]
fn a_proof_citing_lemmas_is_re_checked_with_their_certificates() {
    let (report, _) = fixture();
    let mut citing = 0;
    for o in &report.outcomes {
        let alone = readable(o);
        let cert: Value = serde_json::from_str(&alone.json).unwrap();
        if cert.get("lemmas").is_none() {
            continue;
        }
        citing += 1;
        match readable_among(o, &report.outcomes).status {
            Status::Rechecked(what) => assert!(what.contains("its lemmas "), "{}: {what}", o.id),
            other => panic!("{}: {other:?}", o.id),
        }
        // the lemmas are found among the others, not assumed: without them, not re-checked
        let others: Vec<_> = report.outcomes.iter().filter(|c| c.id == o.id).cloned().collect();
        assert!(
            matches!(readable_among(o, &others).status, Status::NotRechecked(_)),
            "{}",
            o.id
        );
        assert!(matches!(alone.status, Status::NotRechecked(_)), "{}", o.id);
        with_block(&o.id, |block| {
            let text = text_of(&block);
            assert!(
                text.contains("re-checked by the kernel") && !text.contains("not re-checked"),
                "{}: {text}",
                o.id
            );
        });
    }
    assert!(citing >= 10, "{citing} proofs citing lemmas");
}

#[test]
fn a_tampered_certificate_is_not_shown_as_re_checked() {
    let mut cert = certificate_file("000-ex4-points");
    cert["sampling"]["equalities"][0]["values"][1]["lhs"][0] = json!("9/7");
    let r = read_back(&cert, "000-ex4-points.json");
    match &r.status {
        Status::NotRechecked(why) => assert!(why.starts_with("the kernel refuses it: "), "{why}"),
        other => panic!("a tampered file shown as {other:?}"),
    }
    let html = certificate_html(&r, None);
    assert!(!html.contains("re-checked by the kernel"), "{html}");
    assert!(html.contains("9/7"));
    // a file that claims a check it does not have
    let mut cert = certificate_file("000-ex4-y");
    cert["fails"]["lhs"] = json!(["0"]);
    assert!(matches!(read_back(&cert, "x.json").status, Status::NotRechecked(_)));
}

#[test]
fn a_method_without_a_layout_of_its_own_is_shown_generically() {
    let rows: Vec<Value> = (0..130)
        .map(|k| json!({"n": k.to_string(), "value": format!("{k}/7")}))
        .collect();
    let cert = json!({
        "format": "casteljau-certificate", "version": 1, "id": "x", "verdict": "proved",
        "method": "wz", "check": "kernel",
        "goal": {"relation": "=", "symbols": [{"name": "n", "sort": "integer"}],
                 "equalities": [{"ints": {}, "lhs": "sum(k, 0, n, binom(n, k))", "rhs": "2^n",
                                 "for": "n >= 0"}]},
        "wz": {"R": "-1/2*k/(-k + n + 1)", "pieces": [{"when": "n >= 1", "obligation": "F(n+1,k) - F(n,k) = G(n,k+1) - G(n,k)"}],
               "base": rows, "note": "<script>alert(1)</script>"}
    });
    let r = read_back(&cert, "x.json");
    // the kernel has no such data in this version: not re-checked, and why
    assert!(matches!(&r.status, Status::NotRechecked(_)), "{:?}", r.status);
    let text = r.to_text(false);
    for want in [
        "R: -1/2*k/(-k + n + 1)",
        "sum(k, 0, n, binom(n, k)) = 2^n",
        "for: n >= 0",
        "when",
        "n >= 1",
        "… 118 more rows (in the file)",
        "0/7",
        "11/7",
    ] {
        assert!(text.contains(want), "{want:?} not in\n{text}");
    }
    assert!(!text.contains("12/7"), "a folded row is shown:\n{text}");
    let html = certificate_html(&r, None);
    parse(&format!("<div>{html}</div>"));
    assert!(!html.contains("<script"), "{html}");
    assert!(html.contains("&lt;script&gt;alert(1)&lt;/script&gt;"));
    assert!(html.contains("<table class=\"cert\">") && html.contains("… 118 more rows"));
}

#[test]
fn with_a_certificate_directory_the_report_links_each_file() {
    let (report, _) = fixture();
    let pages = render_pages_linking(report, &load_paths(&proofs()).unwrap(), Some("../certs/")).unwrap();
    let page = &pages
        .iter()
        .find(|(_, h)| h.contains("data-claim=\"000-ex4-points\""))
        .unwrap()
        .1;
    assert!(page.contains("<a href=\"../certs/000-ex4-points.json\">000-ex4-points.json</a>"));
    assert!(
        !page.contains("<details class=\"json\">"),
        "linked files are not embedded too"
    );
    parse(page);
}

#[test]
fn a_hostile_statement_is_escaped_in_the_certificate_block() {
    let text = r#"
[text]
file = "x.txt"
title = "t"

[[claim]]
id = "hostile"
source = "x 1"
statement = "</pre></details><script>alert('x')</script> & (1+t)^2 = 1 + 2t + t^2"
kind = "identity"
vars = ["t"]
lhs = "(1+t)^2"
rhs = "1 + 2*t + t^2"
"#;
    let file = parse_file(text, Path::new("x.toml")).unwrap();
    let files = vec![file];
    let report = prove_files(&files, &mut |_, _, _| {}).unwrap();
    assert!(report.outcomes[0].verdict == Verdict::Proved);
    let pages = render_pages(&report, &files).unwrap();
    for (name, html) in &pages {
        assert!(!html.contains("<script"), "{name}: a script got through");
        parse(html);
    }
    let page = &pages[1].1;
    assert!(page.contains("&lt;/pre&gt;&lt;/details&gt;&lt;script&gt;alert(&#39;x&#39;)&lt;/script&gt; &amp;"));
    let r = readable(&report.outcomes[0]);
    assert!(matches!(r.status, Status::Rechecked(_)), "{:?}", r.status);
}

#[test]
fn explain_ends_with_the_certificate_file() {
    let files = load_paths(&proofs()).unwrap();
    let text = explain_files(&files, "000-ex4-points", ExplainStyle::Short).unwrap();
    let (before, cert) = text.split_once("\n\ncertificate file ").unwrap();
    assert!(before.contains("why this suffices:") && before.ends_with("--explain 000-ex4-points --verbose"));
    assert!(
        cert.starts_with("000-ex4-points.json: re-checked by the kernel: "),
        "{cert}"
    );
    assert!(cert.contains("1/3  (8/9, -8/27)  (8/9, -8/27)"), "{cert}");
    // by default folded to one screen; --verbose as the report shows it
    let short = explain_files(&files, "000-4-library", ExplainStyle::Short).unwrap();
    let verbose = explain_files(&files, "000-4-library", ExplainStyle::Verbose).unwrap();
    let (_, short) = short.split_once("\n\ncertificate file ").unwrap();
    let (_, verbose) = verbose.split_once("\n\ncertificate file ").unwrap();
    assert!(short.contains("… 65 more equalities (in the file)"), "{short}");
    assert!(short.contains("… 63 more rows (in the file)"), "{short}");
    assert!(verbose.contains("… 60 more equalities (in the file)"), "{verbose}");
    assert!(short.lines().count() < 80 && verbose.lines().count() > short.lines().count());
    let latex = explain_files(&files, "000-ex4-points", ExplainStyle::Latex).unwrap();
    assert!(!latex.contains("certificate file"));
    // a theorem's certificate citing a lemma its claim does not `use`: the lemma is decided too
    let affine = explain_files(&files, "000-affine", ExplainStyle::Short).unwrap();
    assert!(
        affine.contains("\n\ncertificate file 000-affine.json: re-checked by the kernel: ")
            && affine.contains("000-partition-of-unity re-checked in their own files"),
        "{affine}"
    );
}
