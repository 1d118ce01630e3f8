//! The report's pages: the index (what the verdicts mean, the summary, the misprints) and one
//! page per text with every claim's section.

use super::certificate::certificate_html;
use super::claim_figure::{claim_figure, topic};
use super::interactive;
use super::pages::{claim_anchor, find_claim};
use super::statement::formula;
use super::verdict::{verdict_text, verdict_words};
use crate::error::Result;
use crate::figure::svg::esc;
use crate::verify::claims::{Claim, ClaimFile};
use crate::verify::{readable_among, ClaimOutcome, Report, TextSummary, Verdict};
use std::collections::BTreeMap;
use std::fmt::Write as _;

const STYLE: &str = r#"
:root { --proved: #1e7b34; --proved-in-range: #2f6f9f; --verified: #9a6700; --fails: #b42318; --ink: #1d1d1f; --muted: #5f6368; --rule: #d0d4d9; }
* { box-sizing: border-box; }
body { font-family: "DejaVu Sans", "Noto Sans", "Noto Sans CJK JP", Arial, sans-serif; color: var(--ink); line-height: 1.45;
       max-width: 62rem; margin: 0 auto; padding: 1.2rem 1.5rem 3rem; font-size: 15px; }
h1 { font-size: 1.6rem; margin: 0.3rem 0 0.2rem; overflow-wrap: anywhere; }
h2 { font-size: 1.05rem; margin: 0 0 0.4rem; display: flex; flex-wrap: wrap; gap: 0.5rem; align-items: baseline; }
a { color: #1a56a8; }
.crumbs { margin: 0; font-size: 0.9rem; color: var(--muted); }
.lead { color: var(--muted); margin-top: 0.2rem; }
table { border-collapse: collapse; margin: 0.8rem 0 1.2rem; width: 100%; }
th, td { border-bottom: 1px solid var(--rule); padding: 0.35rem 0.6rem; text-align: left; vertical-align: top; }
th { background: #f3f5f7; }
table.misprints td:first-child { white-space: nowrap; }
/* the titles are short Japanese phrases: one line each, never one character per line */
table.summary td:nth-child(2), table.summary th:nth-child(2) { white-space: nowrap; }
td.n { text-align: right; font-variant-numeric: tabular-nums; }
tr.total td { font-weight: bold; border-top: 2px solid var(--ink); }
.chip { display: inline-block; white-space: nowrap; border-radius: 0.7rem; padding: 0 0.55rem; font-size: 0.8rem; font-weight: bold;
        color: #fff; text-transform: uppercase; letter-spacing: 0.03em; }
.chip.proved { background: var(--proved); } .chip.proved-in-range { background: var(--proved-in-range); } .chip.verified { background: var(--verified); } .chip.fails { background: var(--fails); }
.chip.mismatch { background: #000; }
.claim { border: 1px solid var(--rule); border-left: 6px solid var(--proved); border-radius: 4px; padding: 0.8rem 1rem;
         margin: 1rem 0; }
.claim.verified { border-left-color: var(--verified); } .claim.proved-in-range { border-left-color: var(--proved-in-range); }
.claim.fails { border-left-color: var(--fails); }
.claim.misprint { background: #fff5f4; }
.claim.correction { background: #f3fbf4; }
.claim .id { font-family: "DejaVu Sans Mono", monospace; font-size: 0.95rem; white-space: nowrap; }
.claim .source { color: var(--muted); font-weight: normal; font-size: 0.9rem; }
.statement { font-size: 1.1rem; margin: 0.3rem 0 0.5rem; padding: 0.4rem 0.7rem; background: #f7f7f9; border-radius: 3px; }
.scope { margin: 0.2rem 0; font-size: 0.92rem; }
.banner { margin: 0.4rem 0; padding: 0.4rem 0.7rem; border-radius: 3px; font-size: 0.95rem; }
.banner.misprint { background: #fde2df; border: 1px solid #f4a79d; }
.banner.correction { background: #dcf2e0; border: 1px solid #9bd3a6; }
.banner.mismatch { background: #000; color: #fff; }
dl { margin: 0.4rem 0 0; display: grid; grid-template-columns: max-content minmax(0, 1fr); gap: 0.25rem 0.8rem; }
dt { color: var(--muted); font-size: 0.88rem; }
dd { margin: 0; }
pre { margin: 0; white-space: pre-wrap; overflow-wrap: anywhere; font-family: "DejaVu Sans Mono", monospace; font-size: 0.85rem; }
.printonly { display: none; }
figure { margin: 0.7rem 0 0; }
figure svg { width: 100%; max-width: 100%; height: auto; border: 1px solid var(--rule); }
figcaption { color: var(--muted); font-size: 0.85rem; }
nav.toc { columns: 2; font-size: 0.88rem; margin: 0.5rem 0 1rem; }
nav.toc a { text-decoration: none; }
nav.toc div { break-inside: avoid; }
/* the certificate file read back: tables scroll sideways inside the claim, never the page */
details.certfile { margin: 0.6rem 0 0; border-top: 1px dashed var(--rule); padding-top: 0.4rem; }
details.certfile > summary { cursor: pointer; font-size: 0.92rem; }
details.certfile.kernel .recheck { color: var(--proved); } details.certfile.none .recheck { color: var(--muted); }
details.certfile .file, details.certfile code { font-family: "DejaVu Sans Mono", monospace; font-size: 0.85rem; }
.recheck-detail, .cert-method, p.more, p.json { margin: 0.2rem 0; font-size: 0.88rem; color: var(--muted); }
details.certfile h3, details.certfile h4, details.certfile h5, details.certfile h6 { font-size: 0.9rem; margin: 0.5rem 0 0.2rem; }
dd.math { font-family: "DejaVu Sans Mono", monospace; font-size: 0.85rem; overflow-wrap: anywhere; }
.cert-group { margin-left: 0.6rem; }
div.scroll { max-width: 100%; overflow-x: auto; }
table.cert { width: auto; margin: 0.2rem 0 0.4rem; font-family: "DejaVu Sans Mono", monospace; font-size: 0.82rem; }
table.cert td, table.cert th { padding: 0.1rem 0.6rem 0.1rem 0; white-space: nowrap; }
details.json pre { max-height: 24rem; overflow: auto; background: #f7f7f9; padding: 0.4rem; }
footer { margin-top: 2rem; color: var(--muted); font-size: 0.85rem; }
@media (max-width: 640px) {
  /* a phone: the summary's rows stacked, each count with its name; figures scroll sideways at
     560 px or more, so that their 13 px labels show at 9.5 px or more */
  body { padding: 0.6rem 0.7rem 2rem; font-size: 14px; }
  h1 { font-size: 1.25rem; }
  nav.toc { columns: 1; }
  table.summary, table.summary tbody, table.summary tr, table.summary td { display: block; }
  table.summary tr:first-child { display: none; }
  table.summary tr { border-bottom: 1px solid var(--rule); padding: 0.3rem 0; }
  table.summary td { border: none; padding: 0.05rem 0.3rem; white-space: normal; }
  table.summary td:nth-child(2) { white-space: normal; }
  table.summary td.n { display: inline-block; text-align: left; }
  table.summary td.n::before { content: attr(data-label) " "; color: var(--muted); }
  table.misprints, table.misprints tbody, table.misprints tr, table.misprints td { display: block; }
  table.misprints tr:first-child { display: none; }
  table.misprints tr { border-bottom: 1px solid var(--rule); padding: 0.3rem 0; }
  table.misprints td { border: none; padding: 0.05rem 0.3rem; }
  table.misprints td:nth-child(2)::before { content: "as printed: "; color: var(--muted); }
  table.misprints td:nth-child(3)::before { content: "correction: "; color: var(--muted); }
  table.misprints a, nav.toc a { white-space: nowrap; }
  dl { grid-template-columns: 1fr; }
  figure { overflow-x: auto; }
  figure svg { min-width: 560px; }
}
@media print {
  /* A4, compact text; a claim or a figure is never split across pages */
  @page { size: A4; margin: 8mm 10mm; }
  body { max-width: none; padding: 0; font-size: 8.5pt; line-height: 1.25; }
  /* the certificate file read back is for the screen (text 000 keeps to 14 printed pages) */
  nav.toc, .noprint, details.certfile { display: none; }
  a { color: inherit; text-decoration: none; }
  h1 { font-size: 14pt; } h2 { font-size: 10pt; margin-bottom: 0.15rem; }
  table { margin: 0.4rem 0 0.8rem; } th, td { padding: 0.15rem 0.4rem; }
  /* a claim may break across pages; its figure (below its text) never does */
  .claim { border-color: #999; padding: 0.25rem 0.5rem; margin: 0.3rem 0; }
  .scope.proved { display: none; } .printonly { display: block; }
  .statement { font-size: 9pt; margin: 0.1rem 0 0.2rem; padding: 0.1rem 0.4rem; }
  .scope, .banner, dt { font-size: 8pt; } .banner { margin: 0.2rem 0; padding: 0.2rem 0.5rem; }
  dl { gap: 0.1rem 0.6rem; margin-top: 0.2rem; }
  pre { font-size: 7pt; }
  figure { break-inside: avoid; page-break-inside: avoid; margin-top: 0.3rem; }
  p.interactive { display: none; }
  /* figures at most 145 mm high, their labels and legends at 16 px so that they print at 9 pt or
     more (labels are placed for this size: figure/place.rs); a legend line made longer by the
     larger font runs on past the drawing's right edge */
  figure svg { max-height: 145mm; border: none; font-size: 16px; overflow: visible; }
  figure svg text[font-size="13"] { font-size: 16px; }
  figcaption { font-size: 8.5pt; }
  .chip { color: #000 !important; background: none !important; border: 1.5px solid #000; }
  .claim.misprint, .claim.correction, .statement { background: none; }
  .banner.misprint { border: 2px solid #000; background: none; }
  .banner.correction { border: 1px dashed #000; background: none; }
  h2 { break-after: avoid; }
}
"#;

fn head(title: &str) -> String {
    format!(
        "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\"/>\n\
         <meta name=\"viewport\" content=\"width=device-width, initial-scale=1\"/>\n\
         <title>{}</title>\n<style>{STYLE}</style>\n</head>\n<body>\n",
        esc(title)
    )
}

const FOOT: &str = "<footer>Written by <code>casteljau prove --html</code>. Every verdict is decided in exact \
                    arithmetic; figures are computed exactly and drawn at the end (hover a point for its exact \
                    value).</footer>\n</body>\n</html>\n";

pub(super) fn index_page(
    report: &Report,
    sums: &[TextSummary],
    titles: &BTreeMap<String, String>,
    pages: &BTreeMap<String, String>,
) -> String {
    let mut s = head("casteljau: the texts' claims, checked exactly");
    s.push_str("<header>\n<h1>The texts' claims, checked exactly</h1>\n");
    let _ = writeln!(
        s,
        "<p class=\"lead\">{} claims from {} texts. Each claim is printed as the text states it, with a verdict \
         decided in exact arithmetic and what the verdict rests on.</p>\n</header>",
        report.outcomes.len(),
        sums.len()
    );
    s.push_str("<h2>What the verdicts mean</h2>\n<table>\n");
    for v in Verdict::SHOWN {
        let vt = verdict_words(v, None);
        let _ = writeln!(
            s,
            "<tr><td><span class=\"chip {}\">{}</span></td><td>{}</td></tr>",
            vt.class,
            vt.label,
            esc(&vt.scope)
        );
    }
    s.push_str("</table>\n<h2>Summary</h2>\n<table class=\"summary\">\n");
    s.push_str(
        "<tr><th>text</th><th>title</th><th>claims</th><th>proved</th><th>proved in range</th><th>verified</th><th>fails</th><th>as expected</th></tr>\n",
    );
    let mut total = [0usize; 6];
    for sum in sums {
        let title = titles.get(&sum.text).map(String::as_str).unwrap_or("");
        let _ = writeln!(
            s,
            "<tr><td><a href=\"{}\">{}</a></td><td>{}</td><td class=\"n\" data-label=\"claims\">{}</td>\
             <td class=\"n\" data-label=\"proved\">{}</td><td class=\"n\" data-label=\"proved in range\">{}</td>\
             <td class=\"n\" data-label=\"verified\">{}</td><td class=\"n\" data-label=\"fails\">{}</td>\
             <td class=\"n\" data-label=\"as expected\">{}/{}</td></tr>",
            pages[&sum.text],
            esc(&sum.text),
            esc(title),
            sum.claims,
            sum.proved,
            sum.proved_in_range,
            sum.verified,
            sum.fails,
            sum.as_expected,
            sum.claims
        );
        for (t, v) in total.iter_mut().zip([
            sum.claims,
            sum.proved,
            sum.proved_in_range,
            sum.verified,
            sum.fails,
            sum.as_expected,
        ]) {
            *t += v;
        }
    }
    let _ = writeln!(
        s,
        "<tr class=\"total\"><td>total</td><td></td><td class=\"n\" data-label=\"claims\">{}</td>\
         <td class=\"n\" data-label=\"proved\">{}</td><td class=\"n\" data-label=\"proved in range\">{}</td>\
         <td class=\"n\" data-label=\"verified\">{}</td><td class=\"n\" data-label=\"fails\">{}</td>\
         <td class=\"n\" data-label=\"as expected\">{}/{}</td></tr>\n</table>",
        total[0], total[1], total[2], total[3], total[4], total[5], total[0]
    );
    let mismatches = report.mismatches();
    if mismatches == 0 {
        s.push_str("<p>Every verdict is the one the claim files expect.</p>\n");
    } else {
        let _ = writeln!(
            s,
            "<p class=\"banner mismatch\">{mismatches} verdicts differ from what the claim files expect.</p>"
        );
    }
    let misprints: Vec<&ClaimOutcome> = report
        .outcomes
        .iter()
        .filter(|o| o.verdict == Verdict::Fails && o.expect == Verdict::Fails)
        .collect();
    if !misprints.is_empty() {
        s.push_str("<h2>Misprints found</h2>\n<table class=\"misprints\">\n<tr><th>claim</th><th>as printed</th><th>correction</th></tr>\n");
        for m in misprints {
            let fix = report
                .outcomes
                .iter()
                .find(|o| o.corrects.as_deref() == Some(m.id.as_str()));
            let page = &pages[&m.text];
            let fix_html = match fix {
                Some(f) => format!(
                    "<a href=\"{page}#{}\">{}</a>: {} <span class=\"chip {}\">{}</span>",
                    claim_anchor(&f.id),
                    esc(&f.id),
                    formula(&f.statement),
                    verdict_text(f).class,
                    verdict_text(f).label
                ),
                None => "—".into(),
            };
            let _ = writeln!(
                s,
                "<tr><td><a href=\"{page}#{}\">{}</a></td><td>{}</td><td>{fix_html}</td></tr>",
                claim_anchor(&m.id),
                esc(&m.id),
                formula(&m.statement)
            );
        }
        s.push_str("</table>\n");
    }
    s.push_str(FOOT);
    s
}

pub(super) fn text_page(
    sum: &TextSummary,
    title: &str,
    outcomes: &[&ClaimOutcome],
    report: &Report,
    files: &[ClaimFile],
    json_dir: Option<&str>,
) -> Result<String> {
    let heading = if title.is_empty() {
        sum.text.clone()
    } else {
        format!("{} — {title}", sum.text)
    };
    let mut s = head(&heading);
    let _ = writeln!(
        s,
        "<header>\n<p class=\"crumbs noprint\"><a href=\"index.html\">← all texts</a></p>\n<h1>{}</h1>\n\
         <p class=\"lead\">{} claims: {} proved, {} proved in range, {} verified, {} fail{}.</p>\n</header>",
        esc(&heading),
        sum.claims,
        sum.proved,
        sum.proved_in_range,
        sum.verified,
        sum.fails,
        if sum.mismatches == 0 {
            "; every verdict as the claim file expects".to_string()
        } else {
            format!("; {} NOT as expected", sum.mismatches)
        }
    );
    // the print leaves out each proof's scope line (the same words every time): said once here
    if let Some(vt) = Verdict::SHOWN
        .into_iter()
        .map(|v| verdict_words(v, None))
        .find(|vt| vt.class == "proved")
    {
        let _ = writeln!(
            s,
            "<p class=\"scope printonly\"><strong>{}</strong>, on every claim marked so: {}.</p>",
            vt.label,
            esc(&vt.scope)
        );
    }
    s.push_str("<nav class=\"toc\">\n");
    for o in outcomes {
        let vt = verdict_text(o);
        let _ = writeln!(
            s,
            "<div><span class=\"chip {}\">{}</span> <a href=\"#{}\">{}</a></div>",
            vt.class,
            vt.label,
            claim_anchor(&o.id),
            esc(&o.id)
        );
    }
    s.push_str("</nav>\n<main>\n");
    // a figure drawn once is referred to by later claims on the same data
    let mut drawn: Vec<(String, String)> = Vec::new();
    for o in outcomes {
        claim_section(&mut s, o, outcomes, report, find_claim(files, o), json_dir, &mut drawn)?;
    }
    s.push_str("</main>\n");
    s.push_str(FOOT);
    Ok(s)
}

fn claim_section(
    s: &mut String,
    o: &ClaimOutcome,
    all: &[&ClaimOutcome],
    report: &Report,
    claim: Option<&Claim>,
    json_dir: Option<&str>,
    drawn: &mut Vec<(String, String)>,
) -> Result<()> {
    let vt = verdict_text(o);
    let misprint = o.verdict == Verdict::Fails && o.expect == Verdict::Fails;
    let correction_of = o.corrects.as_ref();
    let corrected_by = all.iter().find(|c| c.corrects.as_deref() == Some(o.id.as_str()));
    let mut classes = vec!["claim", vt.class];
    if misprint {
        classes.push("misprint");
    }
    if correction_of.is_some() {
        classes.push("correction");
    }
    let _ = writeln!(
        s,
        "<section class=\"{}\" id=\"{}\" data-claim=\"{}\">",
        classes.join(" "),
        claim_anchor(&o.id),
        esc(&o.id)
    );
    let _ = writeln!(
        s,
        "<h2><span class=\"chip {}\">{}</span> <span class=\"id\">{}</span> <span class=\"source\">{}</span></h2>",
        vt.class,
        vt.label,
        esc(&o.id),
        esc(&o.source)
    );
    let _ = writeln!(
        s,
        "<p class=\"statement\" lang=\"ja\" title=\"{}\">{}</p>",
        esc(&o.statement),
        formula(&o.statement)
    );
    if o.verdict != o.expect {
        let _ = writeln!(
            s,
            "<p class=\"banner mismatch\">MISMATCH: the claim file expects “{}”, the check says “{}”.</p>",
            o.expect.as_str(),
            o.verdict.as_str()
        );
    }
    if misprint {
        let fix = match corrected_by {
            Some(c) => format!(
                " Corrected in <a href=\"#{}\">{}</a>: {}",
                claim_anchor(&c.id),
                esc(&c.id),
                formula(&c.statement)
            ),
            None => String::new(),
        };
        let _ = writeln!(
            s,
            "<p class=\"banner misprint\"><strong>Misprint.</strong> As printed the statement is false (the \
             counterexample is below).{fix}</p>"
        );
    }
    if let Some(target) = correction_of {
        let printed = all
            .iter()
            .find(|c| &c.id == target)
            .map(|c| format!(" (printed: {})", formula(&c.statement)))
            .unwrap_or_default();
        let _ = writeln!(
            s,
            "<p class=\"banner correction\"><strong>Correction</strong> of the misprint \
             <a href=\"#{}\">{}</a>{printed}.</p>",
            claim_anchor(target),
            esc(target)
        );
    }
    let _ = writeln!(
        s,
        "<p class=\"scope {}\"><strong>{}</strong>: {}</p>",
        vt.class,
        vt.label,
        esc(&vt.scope)
    );
    s.push_str("<dl>\n");
    let label = if o.verdict == Verdict::Fails {
        "counterexample"
    } else {
        "certificate"
    };
    let _ = writeln!(
        s,
        "<dt>{label}</dt><dd><pre class=\"certificate\">{}</pre></dd>",
        esc(&o.certificate)
    );
    if let Some(m) = o.method_text() {
        let _ = writeln!(s, "<dt>method</dt><dd class=\"method\">{}</dd>", esc(&m));
    }
    if let Some(n) = &o.note {
        let _ = writeln!(s, "<dt>note</dt><dd>{}</dd>", formula(n));
    }
    if let Some(r) = &o.range_bound {
        let _ = writeln!(s, "<dt>range-bound</dt><dd class=\"range-bound\">{}</dd>", esc(r));
    }
    let _ = writeln!(s, "<dt>expected</dt><dd>{}</dd>", o.expect.as_str());
    s.push_str("</dl>\n");
    // re-checked with the certificates of the lemmas it cites, as `check DIR` does
    s.push_str(&certificate_html(&readable_among(o, &report.outcomes), json_dir));
    if let Some(c) = claim {
        match claim_figure(c) {
            Ok(Some(cf)) => {
                let svg = cf.figure.to_svg()?;
                let key = svg.clone();
                match drawn.iter().find(|(k, _)| *k == key) {
                    Some((_, first)) => {
                        let _ = writeln!(
                            s,
                            "<p class=\"figref\">Figure: the same as for <a href=\"#{}\">{}</a> above ({}).</p>",
                            claim_anchor(first),
                            esc(first),
                            esc(&cf.caption)
                        );
                    }
                    None => {
                        let _ = writeln!(
                            s,
                            "<figure class=\"{}\">\n{}<figcaption>{}</figcaption>\n</figure>",
                            if cf.own_data { "own" } else { "illustration" },
                            svg.trim_end()
                                .replacen("<svg ", &format!("<svg id=\"fig-{}\" ", claim_anchor(&o.id)), 1),
                            esc(&cf.caption)
                        );
                        if let Some(link) = topic(c).filter(|_| !cf.own_data).and_then(interactive::link) {
                            s.push_str(&link);
                        }
                        drawn.push((key, o.id.clone()));
                    }
                }
            }
            Ok(None) => {}
            Err(e) => {
                let _ = writeln!(
                    s,
                    "<p class=\"banner mismatch\">The figure could not be drawn: {}</p>",
                    esc(&e.to_string())
                );
            }
        }
    }
    s.push_str("</section>\n");
    Ok(())
}
