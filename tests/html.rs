//! The HTML report as a reader sees it: every page is well-formed, offline and printable;
//! every claim is there with its statement, verdict, certificate and figure; misprints sit
//! beside their corrections; the index's table is the report's summary.

use casteljau::html::interactive::{interactive_file, INTERACTIVE_KINDS};
use casteljau::html::{claim_anchor, page_name, render_pages, verdict_text};
use casteljau::verify::claims::{load_paths, Kind};
use casteljau::verify::{prove_paths, Report, Verdict};
use std::path::PathBuf;
use std::process::Command;
use std::sync::OnceLock;

fn proofs() -> Vec<PathBuf> {
    vec![PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("proofs")]
}

/// The report of the real claim files and its pages (computed once for all tests).
fn fixture() -> &'static (Report, Vec<(String, String)>) {
    static CELL: OnceLock<(Report, Vec<(String, String)>)> = OnceLock::new();
    CELL.get_or_init(|| {
        let report = prove_paths(&proofs(), &mut |_, _, _| {}).unwrap();
        let files = load_paths(&proofs()).unwrap();
        let pages = render_pages(&report, &files).unwrap();
        (report, pages)
    })
}

fn page(name: &str) -> &'static str {
    &fixture()
        .1
        .iter()
        .find(|(n, _)| n == name)
        .unwrap_or_else(|| panic!("no page {name}"))
        .1
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

#[test]
fn every_page_is_well_formed_offline_and_printable() {
    let (report, pages) = fixture();
    assert_eq!(pages[0].0, "index.html");
    assert_eq!(pages.len(), 1 + report.summaries().len());
    for (name, html) in pages {
        let doc = parse(html);
        assert_eq!(doc.root_element().tag_name().name(), "html", "{name}");
        assert!(html.starts_with("<!DOCTYPE html>"), "{name}");
        assert!(html.contains("@media print"), "{name}: no print stylesheet");
        for n in doc.descendants().filter(|n| n.is_element()) {
            assert_ne!(n.tag_name().name(), "script", "{name}: a script");
            assert_ne!(n.tag_name().name(), "link", "{name}: an external resource");
            for a in ["href", "src"] {
                if let Some(v) = n.attribute(a) {
                    assert!(!v.contains("://"), "{name}: {a}=\"{v}\" leaves the report");
                    let target = v.split('#').next().unwrap();
                    // or one of the interactive figures written beside the pages
                    let interactive = target
                        .strip_prefix("interactive/")
                        .is_some_and(|f| INTERACTIVE_KINDS.iter().any(|k| interactive_file(*k) == f));
                    assert!(
                        target.is_empty() || pages.iter().any(|(p, _)| p == target) || interactive,
                        "{name}: broken link {v}"
                    );
                }
            }
        }
        // every in-page anchor exists
        for n in doc.descendants().filter(|n| n.has_tag_name("a")) {
            let href = n.attribute("href").unwrap_or("");
            let (file, frag) = href.split_once('#').unwrap_or((href, ""));
            if frag.is_empty() {
                continue;
            }
            let target_page = if file.is_empty() { html.as_str() } else { page(file) };
            assert!(
                target_page.contains(&format!("id=\"{frag}\"")),
                "{name}: the anchor {href} points nowhere"
            );
        }
    }
}

#[test]
fn every_claim_is_on_its_page_with_statement_verdict_and_certificate() {
    let (report, _) = fixture();
    for o in &report.outcomes {
        let html = page(&page_name(&o.text));
        let doc = parse(html);
        let section = doc
            .descendants()
            .find(|n| n.has_tag_name("section") && n.attribute("data-claim") == Some(o.id.as_str()))
            .unwrap_or_else(|| panic!("claim {} missing from {}", o.id, page_name(&o.text)));
        assert_eq!(section.attribute("id"), Some(claim_anchor(&o.id).as_str()));
        let vt = verdict_text(o);
        assert!(has_class(&section, vt.class), "{}", o.id);
        let statement = section.descendants().find(|n| has_class(n, "statement")).unwrap();
        assert_eq!(statement.attribute("title"), Some(o.statement.as_str()), "{}", o.id);
        // the rendered statement keeps every character but the script markers; a `_` inside a
        // library name is a character (`elevate_by`), not a subscript
        let plain: String = o.statement.chars().filter(|c| !"_^{}".contains(*c)).collect();
        let rendered = text_of(&statement);
        assert_eq!(rendered.replace('_', ""), plain, "{}", o.id);
        if o.id == "000-8-library" {
            assert!(
                rendered.contains("BezierCurve::elevate_by vs elevate_steps"),
                "{rendered}"
            );
        }
        let cert = section.descendants().find(|n| has_class(n, "certificate")).unwrap();
        assert_eq!(text_of(&cert), o.certificate, "{}", o.id);
        assert!(text_of(&section).contains(&vt.scope), "{}", o.id);
        let note = section.descendants().find(|n| has_class(n, "range-bound"));
        assert_eq!(note.map(|n| text_of(&n)), o.range_bound.clone(), "{}", o.id);
    }
}

#[test]
fn misprints_are_highlighted_beside_their_corrections() {
    let (report, _) = fixture();
    let misprints: Vec<_> = report.outcomes.iter().filter(|o| o.expect == Verdict::Fails).collect();
    assert!(misprints.len() >= 4);
    for m in misprints {
        let doc = parse(page(&page_name(&m.text)));
        let section = doc
            .descendants()
            .find(|n| n.attribute("data-claim") == Some(m.id.as_str()))
            .unwrap();
        assert!(has_class(&section, "misprint"), "{}", m.id);
        let fix = report
            .outcomes
            .iter()
            .find(|o| o.corrects.as_deref() == Some(m.id.as_str()))
            .unwrap();
        let banner = section
            .descendants()
            .find(|n| has_class(n, "misprint") && n.has_tag_name("p"))
            .unwrap();
        assert!(
            banner
                .descendants()
                .any(|a| a.attribute("href") == Some(format!("#{}", claim_anchor(&fix.id)).as_str())),
            "{}: no link to its correction",
            m.id
        );
        let fixed = doc
            .descendants()
            .find(|n| n.attribute("data-claim") == Some(fix.id.as_str()))
            .unwrap();
        assert!(has_class(&fixed, "correction"), "{}", fix.id);
        // and the index lists it
        assert!(page("index.html").contains(&format!("#{}\">{}</a>", claim_anchor(&m.id), m.id)));
    }
}

#[test]
fn every_claim_with_a_geometric_object_has_its_figure() {
    let (report, _) = fixture();
    let files = load_paths(&proofs()).unwrap();
    let mut with_figure = 0;
    for f in &files {
        let text = f.text.as_ref().map(|t| t.file.clone()).unwrap();
        let doc = parse(page(&page_name(&text)));
        for c in &f.claim {
            let geometric = c.decls.curves.is_some()
                || c.decls.surfaces.is_some()
                || matches!(c.kind, Kind::BezierPoints(_))
                || matches!(&c.kind, Kind::Theorem(t) if !["partition_of_unity", "identity_4", "affine_invariance"].contains(&t.theorem.as_str()));
            let section = doc
                .descendants()
                .find(|n| n.attribute("data-claim") == Some(c.id.as_str()))
                .unwrap();
            let svg = section.descendants().find(|n| n.has_tag_name("svg"));
            let reference = section.descendants().find(|n| has_class(n, "figref"));
            if let Some(r) = reference {
                // "the same as for X above": X's section has the figure
                let href = r.descendants().find_map(|a| a.attribute("href")).unwrap();
                let target = doc
                    .descendants()
                    .find(|n| n.attribute("id") == Some(&href[1..]))
                    .unwrap();
                assert!(target.descendants().any(|n| n.has_tag_name("svg")), "{}", c.id);
            }
            if geometric {
                assert!(svg.is_some() || reference.is_some(), "claim {} has no figure", c.id);
            }
            if let Some(svg) = svg {
                with_figure += 1;
                // the inline SVG is a figure of its own: a title and drawn shapes
                assert!(svg.children().any(|n| n.has_tag_name("title")));
                assert!(
                    svg.descendants().filter(|n| n.has_tag_name("path")).count() >= 2,
                    "{}",
                    c.id
                );
            }
        }
    }
    assert!(with_figure >= 15, "only {with_figure} figures");
    assert!(report.outcomes.len() > with_figure);
}

#[test]
fn the_index_table_is_the_reports_summary() {
    let (report, _) = fixture();
    let doc = parse(page("index.html"));
    let table = doc.descendants().find(|n| has_class(n, "summary")).unwrap();
    let rows: Vec<Vec<String>> = table
        .children()
        .filter(|n| n.has_tag_name("tr"))
        .map(|tr| {
            tr.children()
                .filter(|n| n.is_element())
                .map(|td| text_of(&td))
                .collect()
        })
        .collect();
    let sums = report.summaries();
    assert_eq!(rows.len(), 1 + sums.len() + 1);
    for (row, s) in rows[1..].iter().zip(&sums) {
        assert_eq!(row[0], s.text);
        let numbers = [s.claims, s.proved, s.proved_in_range, s.verified, s.fails];
        for (cell, n) in row[2..7].iter().zip(numbers) {
            assert_eq!(cell, &n.to_string(), "{}", s.text);
        }
        assert_eq!(row[7], format!("{}/{}", s.as_expected, s.claims));
    }
    assert_eq!(rows.last().unwrap()[2], report.outcomes.len().to_string());
}

#[test]
fn prove_html_writes_the_report() {
    let dir = std::env::temp_dir().join(format!("casteljau-html-{}", std::process::id()));
    let run = Command::new(env!("CARGO_BIN_EXE_casteljau"))
        .current_dir(env!("CARGO_MANIFEST_DIR"))
        .args(["prove", "--html"])
        .arg(&dir)
        .output()
        .unwrap();
    assert!(run.status.success(), "{}", String::from_utf8_lossy(&run.stderr));
    let mut names: Vec<String> = std::fs::read_dir(&dir)
        .unwrap()
        .map(|e| e.unwrap().file_name().to_string_lossy().into_owned())
        .collect();
    names.sort();
    assert_eq!(
        names,
        [
            "000_ef6a3958c7d702f5.html",
            "001_d6775559ddbdd5b2.html",
            "003_bd67d8bed055bcf9.html",
            "004_658c519a4aef48a5.html",
            "index.html",
            "interactive"
        ]
    );
    // the text report on stdout is unchanged by --html
    assert!(String::from_utf8_lossy(&run.stdout).contains("=== summary ==="));
    std::fs::remove_dir_all(&dir).unwrap();
}

#[test]
fn the_handout_has_statements_misprints_corrections_and_figures_but_no_ids_or_commands() {
    let (report, _) = fixture();
    let files = load_paths(&proofs()).unwrap();
    let pages = casteljau::html::render_handout(report, &files).unwrap();
    assert_eq!(pages.len(), report.summaries().len() + 1);
    for (name, html) in &pages {
        let doc = parse(html);
        let text = text_of(&doc.root_element());
        for o in &report.outcomes {
            assert!(!text.contains(&o.id), "{name} names the claim {}", o.id);
        }
        // outside the figures (the hull figure's title names its "certificate weights")
        let prose: String = doc
            .descendants()
            .filter(|n| n.is_text() && !n.ancestors().any(|a| a.has_tag_name("svg")))
            .filter_map(|n| n.text())
            .collect();
        for word in ["--", "certificate", "proofs/"] {
            assert!(!prose.contains(word), "{name} holds '{word}'");
        }
    }
    for m in report.outcomes.iter().filter(|o| o.expect == Verdict::Fails) {
        let html = &pages.iter().find(|(n, _)| *n == page_name(&m.text)).unwrap().1;
        let doc = parse(html);
        let item = doc
            .descendants()
            .find(|n| {
                has_class(n, "printed") && text_of(n).replace('_', "") == m.statement.replace(['_', '^', '{', '}'], "")
            })
            .unwrap_or_else(|| panic!("misprint {} not struck through", m.id));
        let section = item.parent().unwrap();
        assert!(text_of(&section).contains("As printed this is false"), "{}", m.id);
        if let Some(fix) = report
            .outcomes
            .iter()
            .find(|c| c.corrects.as_deref() == Some(m.id.as_str()))
        {
            let correct = section.descendants().find(|n| has_class(n, "correction")).unwrap();
            assert!(text_of(&correct).contains("Correct:"), "{}", fix.id);
        }
    }
    let text000 = &pages.iter().find(|(n, _)| n.starts_with("000_")).unwrap().1;
    assert!(
        text000.matches("<svg ").count() >= 5,
        "text 000's handout has few figures"
    );
    assert!(
        text000.contains("both sides = "),
        "no worked case in text 000's handout"
    );
}
