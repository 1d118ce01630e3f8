//! The static HTML report of a `prove` run, for reading on screen and handing out on paper.
//!
//! [`write_report`] writes `index.html` (what the verdicts mean, the summary table, the
//! misprints found) and one page per text with every claim: its statement as printed, the
//! verdict and its scope, the certificate or counterexample, misprints highlighted beside their
//! corrections, and the figure the claim is about ([`claim_figure`]), inlined as SVG. Pages
//! are self-contained (styles inline, no scripts, no network) and well-formed XML, and carry a
//! print stylesheet.

use crate::error::{Error, Result};
use crate::figure::FigureKind;
use crate::figure::{self, svg::esc, AnyCurve, Figure};
use crate::point::Point;
use crate::quadratic::QuadraticIrrational;
use crate::rational::RationalBezierCurve;
use crate::scalar::{Ring, Scalar};
use crate::surface::BezierSurface;
use crate::verify::claims::{Claim, ClaimFile, Kind, Number, SurfaceSpec};
use crate::verify::{ClaimOutcome, Report, TextSummary, Verdict};
use crate::BezierCurve;
use std::collections::BTreeMap;
use std::fmt::Write as _;
use std::path::Path;

mod handout;
pub mod interactive;
mod statement;
pub use handout::{render_handout, write_handout};
pub use statement::formula;

/// The exact scalar of claim figures: claim files may write `2*sqrt(2)`.
type Q = QuadraticIrrational;

/// How a verdict reads in the report: a CSS class, its word, and what it covers.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct VerdictText {
    /// `proved`, `verified` or `fails` (a CSS class).
    pub class: &'static str,
    /// The word shown.
    pub label: &'static str,
    /// What the verdict covers, in one sentence.
    pub scope: String,
}

/// The one place that turns a verdict into words.
pub fn verdict_text(outcome: &ClaimOutcome) -> VerdictText {
    verdict_words(outcome.verdict, outcome.range.as_deref())
}

/// The words for a verdict; `range` is the finite range a `proved_in_range` covers.
fn verdict_words(verdict: Verdict, range: Option<&str>) -> VerdictText {
    match verdict {
        Verdict::Proved => VerdictText {
            class: "proved",
            label: "proved",
            scope: "for every value of every variable of the statement; the certificate says why the finite check is a proof"
                .into(),
        },
        Verdict::ProvedInRange => VerdictText {
            class: "proved-in-range",
            label: "proved in range",
            scope: match range {
                Some(r) => format!("every case of {r} proved; not a proof beyond that range"),
                None => "every case of the stated finite ranges proved; not a proof beyond them".into(),
            },
        },
        Verdict::Verified => VerdictText {
            class: "verified",
            label: "verified",
            scope: "bounded evidence, not a proof: the certificate says exactly what was checked".into(),
        },
        Verdict::Fails => VerdictText {
            class: "fails",
            label: "fails",
            scope: "false as stated: the certificate is an exact counterexample".into(),
        },
        Verdict::Error => VerdictText {
            class: "error",
            label: "error",
            scope: "not decided: the reason says which limit or form stopped the check".into(),
        },
    }
}

/// A figure for a claim, with a caption saying what it shows.
#[derive(Clone, Debug)]
pub struct ClaimFigure {
    /// The figure.
    pub figure: Figure,
    /// Whether it draws the claim's own data (`false`: an illustration on a text's example).
    pub own_data: bool,
    /// One line under the figure.
    pub caption: String,
}

/// The page of a text: `000_ef6a3958c7d702f5.txt` → `000_ef6a3958c7d702f5.html` (at most 100
/// characters before `.html`; [`page_names`] gives each text of a report a page of its own).
pub fn page_name(text: &str) -> String {
    let stem = text.strip_suffix(".txt").unwrap_or(text);
    let safe: String = stem
        .chars()
        .take(100)
        .map(|c| {
            if c.is_ascii_alphanumeric() || c == '-' || c == '_' {
                c
            } else {
                '_'
            }
        })
        .collect();
    if safe.is_empty() {
        return "text.html".into();
    }
    format!("{safe}.html")
}

/// The page of each text, in the order given: its [`page_name`], unless `index.html` or an
/// earlier text has that name (compared without case, as a case-insensitive file system
/// would), then the name with `-2`, `-3`, … added. So N texts get N pages and none is the index.
pub fn page_names<'a>(texts: impl IntoIterator<Item = &'a str>) -> BTreeMap<String, String> {
    let mut used = std::collections::BTreeSet::from(["index.html".to_string()]);
    let mut pages = BTreeMap::new();
    for text in texts {
        if pages.contains_key(text) {
            continue;
        }
        let base = page_name(text);
        let stem = base.strip_suffix(".html").unwrap_or(&base);
        let mut name = base.clone();
        let mut k = 2;
        while used.contains(&name.to_lowercase()) {
            name = format!("{stem}-{k}.html");
            k += 1;
        }
        used.insert(name.to_lowercase());
        pages.insert(text.to_string(), name);
    }
    pages
}

/// The anchor of a claim on its page.
pub fn claim_anchor(id: &str) -> String {
    let safe: String = id
        .chars()
        .map(|c| {
            if c.is_ascii_alphanumeric() || c == '-' || c == '_' || c == '.' {
                c
            } else {
                '_'
            }
        })
        .collect();
    format!("claim-{safe}")
}

/// Writes the report into `dir` (created if needed): `index.html` and one page per text.
/// Returns the number of pages written.
pub fn write_report(report: &Report, files: &[ClaimFile], dir: &Path) -> Result<usize> {
    let pages = render_pages(report, files)?;
    write_pages(dir, "report", &pages)?;
    interactive::write_pages(dir)?;
    Ok(pages.len())
}

/// Writes `pages` (`(file name, HTML)`) into `dir`, created if needed; `what` names the
/// directory in errors.
fn write_pages(dir: &Path, what: &str, pages: &[(String, String)]) -> Result<()> {
    std::fs::create_dir_all(dir)
        .map_err(|e| Error::Domain(format!("cannot create the {what} directory {}: {e}", dir.display())))?;
    for (name, html) in pages {
        let path = dir.join(name);
        std::fs::write(&path, html).map_err(|e| Error::Domain(format!("cannot write {}: {e}", path.display())))?;
    }
    Ok(())
}

/// Each text's title by its file name (empty where the claim file gives none).
fn text_titles(files: &[ClaimFile]) -> BTreeMap<String, String> {
    files
        .iter()
        .filter_map(|f| {
            f.text
                .as_ref()
                .map(|t| (t.file.clone(), t.title.clone().unwrap_or_default()))
        })
        .collect()
}

/// The pages as `(file name, HTML)`, `index.html` first.
pub fn render_pages(report: &Report, files: &[ClaimFile]) -> Result<Vec<(String, String)>> {
    let sums = report.summaries();
    let titles = text_titles(files);
    let names = page_names(sums.iter().map(|s| s.text.as_str()));
    let mut pages = vec![("index.html".to_string(), index_page(report, &sums, &titles, &names))];
    for sum in &sums {
        let outcomes: Vec<&ClaimOutcome> = report.outcomes.iter().filter(|o| o.text == sum.text).collect();
        let title = titles.get(&sum.text).cloned().unwrap_or_default();
        pages.push((names[&sum.text].clone(), text_page(sum, &title, &outcomes, files)?));
    }
    Ok(pages)
}

/// The claim an outcome came from.
fn find_claim<'a>(files: &'a [ClaimFile], o: &ClaimOutcome) -> Option<&'a Claim> {
    files
        .iter()
        .filter(|f| f.path.display().to_string() == o.file)
        .flat_map(|f| &f.claim)
        .find(|c| c.id == o.id)
}

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
dl { margin: 0.4rem 0 0; display: grid; grid-template-columns: max-content 1fr; gap: 0.25rem 0.8rem; }
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
  nav.toc, .noprint { display: none; }
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

fn index_page(
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

fn text_page(sum: &TextSummary, title: &str, outcomes: &[&ClaimOutcome], files: &[ClaimFile]) -> Result<String> {
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
        claim_section(&mut s, o, outcomes, find_claim(files, o), &mut drawn)?;
    }
    s.push_str("</main>\n");
    s.push_str(FOOT);
    Ok(s)
}

fn claim_section(
    s: &mut String,
    o: &ClaimOutcome,
    all: &[&ClaimOutcome],
    claim: Option<&Claim>,
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

fn number(n: &Number) -> Result<Q> {
    Q::parse(&n.text()?)
}

fn points(rows: &[Vec<Number>]) -> Result<Vec<Point<Q>>> {
    rows.iter()
        .map(|p| Point::new(p.iter().map(number).collect::<Result<Vec<_>>>()?))
        .collect()
}

fn surface_of(spec: &SurfaceSpec) -> Result<BezierSurface<Q>> {
    BezierSurface::new(spec.net.iter().map(|row| points(row)).collect::<Result<_>>()?)
}

fn q(p: i64, d: i64) -> Q {
    Q::from_ratio(p, d).expect("nonzero denominator")
}

/// Text 000's example 4), the curve the illustrations of general statements are drawn on.
fn example_curve() -> Result<BezierCurve<Q>> {
    BezierCurve::new(vec![
        Point::new(vec![q(0, 1), q(0, 1)])?,
        Point::new(vec![q(4, 3), q(-4, 3)])?,
        Point::new(vec![q(4, 3), q(4, 3)])?,
        Point::new(vec![q(0, 1), q(0, 1)])?,
    ])
}

const ON_EXAMPLE: &str = "illustration on text 000's example 4), b = (0, 0), (4/3, −4/3), (4/3, 4/3), (0, 0)";

/// Which illustration a general statement about curves gets: the claim's `figure`, or its
/// theorem's.
fn topic(c: &Claim) -> Option<FigureKind> {
    if let Kind::Theorem(t) = &c.kind {
        return match t.theorem.as_str() {
            "de_casteljau_bernstein" => Some(FigureKind::Construction),
            "subdivision" => Some(FigureKind::Subdivision),
            "elevation_7" | "elevation_8" => Some(FigureKind::Elevation),
            "derivative" | "derivative_k" | "endpoint_tangent" | "tangent_at_t0" => Some(FigureKind::Hodograph),
            "convex_hull" => Some(FigureKind::Hull),
            _ => None,
        };
    }
    c.figure
}

fn illustrate(t: FigureKind) -> Result<Figure> {
    let c = example_curve()?;
    let half = q(1, 2);
    match t {
        FigureKind::Construction => figure::construction(&c, &half),
        FigureKind::Subdivision => figure::subdivision(&c, &q(1, 3)),
        FigureKind::Elevation => figure::elevation(&c, &[1, 2, 4, 8, 16]),
        FigureKind::Hodograph => figure::hodograph(&c),
        FigureKind::Hull => figure::hull(&c, &c.eval(&q(1, 3))),
        FigureKind::Conics => {
            let rows = crate::input::parse_points(figure::DEFAULT_CONIC_POLYGON)?;
            let pts = rows
                .iter()
                .map(|p| p.try_map(|x| Ok(Q::rational(x.clone()))))
                .collect::<Result<Vec<_>>>()?;
            figure::conics(&pts, &q(1, 1), &q(1, 1), &[q(1, 2), q(1, 1), q(2, 1)])
        }
        FigureKind::Projection => figure::conic_projection(&BezierCurve::new(
            crate::input::parse_points(figure::DEFAULT_PARABOLA)?
                .iter()
                .map(|p| p.try_map(|x| Ok(Q::rational(x.clone()))))
                .collect::<Result<_>>()?,
        )?),
        FigureKind::Fit => {
            let rows = crate::input::parse_points(figure::DEFAULT_FIT_CURVE)?;
            let pts = rows
                .iter()
                .map(|p| p.try_map(|x| Ok(Q::rational(x.clone()))))
                .collect::<Result<Vec<_>>>()?;
            figure::fit(&AnyCurve::Polynomial(BezierCurve::new(pts)?))
        }
        // the others on the figure command's own defaults (its texts' examples)
        FigureKind::Net | FigureKind::Enneper | FigureKind::Bernstein => figure::FigureRequest::new(t).figure(),
    }
}

/// The figure a claim is about: the claim's own curves or surfaces when it has them (a
/// conic arc family for a rational quadratic, the fit for a `fit` claim, the net with
/// iso-curves for a surface, Enneper's net, the elevation for Theorem 1.2, the construction
/// for a polynomial curve), otherwise an illustration of the statement's topic on a text's
/// example (by its theorem, or the claim file's `figure`). `None` for claims with no geometric
/// object (scalar identities, text 004's vector algebra).
pub fn claim_figure(c: &Claim) -> Result<Option<ClaimFigure>> {
    let own = |figure: Figure, caption: String| {
        Ok(Some(ClaimFigure {
            figure,
            own_data: true,
            caption,
        }))
    };
    if let Some(surfaces) = &c.decls.surfaces {
        if let Some((name, spec)) = surfaces.iter().next() {
            let surface = surface_of(spec)?;
            if matches!(c.kind, Kind::Enneper) {
                return own(
                    figure::enneper(&surface)?,
                    format!("the claim's net {name}, with iso-curves"),
                );
            }
            return own(
                figure::net(&surface, 4, &format!("The net of {name}"))?,
                format!("the claim's net {name}: iso-curves and boundary curves"),
            );
        }
    }
    if let Some(curves) = &c.decls.curves {
        let objs: Vec<(&String, AnyCurve<Q>)> = curves
            .iter()
            .map(|(n, spec)| Ok((n, crate::verify::curve_from_spec::<Q>(spec)?)))
            .collect::<Result<_>>()?;
        if matches!(c.kind, Kind::Fit(_)) {
            if let Some((name, x)) = objs.first() {
                return own(figure::fit(x)?, format!("text 004's fit of the claim's curve {name}"));
            }
        }
        if matches!(c.kind, Kind::Convergence(_)) {
            if let Some((name, AnyCurve::Polynomial(b))) =
                objs.iter().find(|(_, o)| matches!(o, AnyCurve::Polynomial(_)))
            {
                return own(
                    figure::elevation(b, &[1, 2, 4, 8, 16])?,
                    format!("the claim's curve {name} elevated r = 1, 2, 4, 8, 16 times"),
                );
            }
        }
        // a planar rational quadratic: the family of arcs of its polygon
        let conic = objs.iter().find_map(|(name, o)| match o {
            AnyCurve::Rational(r) if r.dim() == 2 && r.degree() == 2 => Some((name, r.clone())),
            _ => None,
        });
        // a homogeneous quadratic in space: the rational arc it projects to
        let conic = match conic {
            Some(found) => Some(found),
            None => objs.iter().find_map(|(name, o)| match o {
                AnyCurve::Polynomial(p) if p.dim() == 3 && p.degree() == 2 => {
                    RationalBezierCurve::from_homogeneous(p).ok().map(|r| (name, r))
                }
                _ => None,
            }),
        };
        if let Some((name, arc)) = conic {
            let w = arc.weights();
            let mut middles = vec![w[1].clone()];
            if w[0] == Q::one() && w[2] == Q::one() {
                for m in [q(1, 2), q(1, 1), q(2, 1)] {
                    if !middles.contains(&m) {
                        middles.push(m);
                    }
                }
            }
            middles.sort_by(|a, b| a.partial_cmp(b).unwrap_or(std::cmp::Ordering::Equal));
            return own(
                figure::conics(arc.points(), &w[0], &w[2], &middles)?,
                format!(
                    "the claim's arc {name} (w₁ = {}) among arcs of its control polygon",
                    w[1]
                ),
            );
        }
        if let Some((name, AnyCurve::Polynomial(b))) = objs.iter().find(|(_, o)| matches!(o, AnyCurve::Polynomial(_))) {
            return own(
                figure::construction(b, &q(1, 2))?,
                format!("the claim's curve {name}: de Casteljau's construction at t = 1/2"),
            );
        }
    }
    if let Kind::BezierPoints(claimed) = &c.kind {
        {
            let b = BezierCurve::new(points(&claimed.points)?)?;
            return own(
                figure::construction(&b, &q(1, 2))?,
                "the claimed Bézier points and their curve, constructed at t = 1/2".into(),
            );
        }
    }
    if let Some(t) = topic(c) {
        let caption = match t {
            FigureKind::Fit => "illustration of text 004's method on our worked example x(t) = (t, 1 + t², t⁴)",
            FigureKind::Conics => "illustration on the control polygon of text 001's Ex. 3 and Ex. 4, w₀ = w₂ = 1",
            FigureKind::Projection => "illustration on the parabola of text 001's Ex. 1 of the proof of (10)",
            FigureKind::Net => "illustration on text 003's Ex. 2 net (degree (2, 2))",
            FigureKind::Enneper => "illustration on Enneper's net of text 003's Ex. 5",
            FigureKind::Bernstein => "the Bernstein basis of degree 3, with its values at t = 1/3",
            _ => ON_EXAMPLE,
        };
        return Ok(Some(ClaimFigure {
            figure: illustrate(t)?,
            own_data: false,
            caption: caption.into(),
        }));
    }
    if let Some(net) = &c.decls.net {
        // a symbolic net: illustrated on text 003's nets
        let (spec, what) = if net.degree == ["1", "1"] {
            (
                "0,0,0; 0,1,0 | 1,0,0; 1,1,1",
                "illustration on text 003's bilinear patch (a hyperbolic paraboloid)",
            )
        } else {
            (
                figure::DEFAULT_NET,
                "illustration on text 003's Ex. 2 net (degree (2, 2))",
            )
        };
        let rows = crate::input::parse_net(spec)?;
        let surface: BezierSurface<Q> = BezierSurface::new(
            rows.iter()
                .map(|r| {
                    r.iter()
                        .map(|p| p.try_map(|x| Ok(Q::rational(x.clone()))))
                        .collect::<Result<Vec<_>>>()
                })
                .collect::<Result<_>>()?,
        )?;
        return Ok(Some(ClaimFigure {
            figure: figure::net(&surface, 4, "A tensor-product net")?,
            own_data: false,
            caption: what.into(),
        }));
    }
    Ok(None)
}
