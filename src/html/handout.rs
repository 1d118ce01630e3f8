//! The students' handout of a `prove` run (`prove --handout DIR`): per text, its statements as
//! printed, one worked case in exact fractions, the figure, and each misprint with its
//! correction. No claim ids, verdict certificates, proof methods or command-line text: what a
//! teacher hands out, not how the program checked it. Printed on A4, a statement's block may
//! break across pages; only a figure is kept whole.

use super::claim_figure::claim_figure;
use super::pages::{find_claim, page_names, text_titles, write_pages};
use super::statement::formula;
use crate::error::Result;
use crate::figure::svg::esc;
use crate::verify::claims::ClaimFile;
use crate::verify::{ClaimOutcome, Report, TextSummary, Verdict};
use std::fmt::Write as _;
use std::path::Path;

const STYLE: &str = r#"
* { box-sizing: border-box; }
body { font-family: "DejaVu Sans", "Noto Sans", "Noto Sans CJK JP", Arial, sans-serif; color: #1d1d1f; line-height: 1.4;
       max-width: 52rem; margin: 0 auto; padding: 1rem 1.2rem 2rem; font-size: 15px; overflow-wrap: break-word; }
h1 { font-size: 1.4rem; margin: 0.2rem 0; }
h2 { font-size: 0.95rem; margin: 0.9rem 0 0.2rem; color: #5f6368; font-weight: normal; }
.lead { color: #5f6368; margin: 0.2rem 0 0.6rem; }
.statement { font-size: 1.05rem; margin: 0.15rem 0; }
.misprint .statement.printed { text-decoration: line-through; text-decoration-color: #b42318; }
.label { font-weight: bold; font-size: 0.85rem; }
.scope { font-size: 0.85rem; color: #5f6368; margin: 0.1rem 0; }
.note { font-size: 0.9rem; margin: 0.1rem 0; }
pre { margin: 0.2rem 0 0 1rem; white-space: pre-wrap; overflow-wrap: anywhere; font-family: "DejaVu Sans Mono", monospace;
      font-size: 0.8rem; }
figure { margin: 0.3rem 0 0; }
figure svg { width: 100%; max-width: 100%; height: auto; }
@media (max-width: 640px) {
  /* a phone: figures scroll sideways at 560 px or more, their 13 px labels at 9.5 px or more */
  body { padding: 0.6rem 0.7rem 2rem; font-size: 14px; }
  figure { overflow-x: auto; }
  figure svg { min-width: 560px; }
}
figcaption { color: #5f6368; font-size: 0.8rem; }
ul { padding-left: 1.2rem; }
@media print {
  @page { size: A4; margin: 10mm 12mm; }
  body { max-width: none; padding: 0; font-size: 9.5pt; line-height: 1.3; }
  a { color: inherit; text-decoration: none; }
  h1 { font-size: 13pt; } h2 { font-size: 8.5pt; margin: 0.45rem 0 0.05rem; break-after: avoid; }
  .statement { font-size: 10pt; }
  pre { font-size: 7.5pt; }
  /* a figure follows its text and is never split; at most 85 mm high, so that the text
     before a figure that moves to the next page leaves its page more than 60% filled */
  figure { break-inside: avoid; page-break-inside: avoid; }
  figure svg { max-height: 85mm; width: auto; max-width: 100%; font-size: 14px; overflow: visible; }
  figure svg text[font-size="13"] { font-size: 14px; }
  figcaption { font-size: 7.5pt; }
}
"#;

fn head(title: &str) -> String {
    format!(
        "<!DOCTYPE html>\n<html lang=\"ja\">\n<head>\n<meta charset=\"utf-8\"/>\n\
         <meta name=\"viewport\" content=\"width=device-width, initial-scale=1\"/>\n\
         <title>{}</title>\n<style>{STYLE}</style>\n</head>\n<body>\n",
        esc(title)
    )
}

const FOOT: &str = "</body>\n</html>\n";

/// Whether a claim is about this program's library rather than the text (its statement
/// names a library function): not for the handout.
fn about_the_library(o: &ClaimOutcome) -> bool {
    ["library", "BezierCurve", "::", "elevate_"]
        .iter()
        .any(|w| o.statement.contains(w))
}

/// The printed label of a claim's source, without the text's file name (`000_….txt 4)` → `4)`).
fn label(o: &ClaimOutcome) -> &str {
    match o.source.strip_prefix(o.text.as_str()) {
        Some(rest) => rest.trim(),
        None => o.source.as_str(),
    }
}

/// A counterexample as a reader wants it: the point and the two sides' values, without the
/// claim file's own expressions (`at x = 1: the premise 'diff(D2, k)' = 0 holds, but … gives
/// left side = -32, right side = 22` → `at x = 1: left side = -32, right side = 22`).
fn counterexample(certificate: &str) -> String {
    if !certificate.contains('\'') {
        return certificate.to_string();
    }
    let point = certificate
        .strip_prefix("at ")
        .and_then(|rest| rest.split_once(": "))
        .map(|(p, _)| p);
    match (point, certificate.find("left side =")) {
        (Some(point), Some(k)) => format!("at {point}: {}", &certificate[k..]),
        _ => certificate.to_string(),
    }
}

/// Writes the handout into `dir` (created if needed): `index.html` and one page per text.
/// Returns the number of pages written.
pub fn write_handout(report: &Report, files: &[ClaimFile], dir: &Path) -> Result<usize> {
    let pages = render_handout(report, files)?;
    write_pages(dir, "handout", &pages)?;
    Ok(pages.len())
}

/// The handout's pages as `(file name, HTML)`, `index.html` first.
pub fn render_handout(report: &Report, files: &[ClaimFile]) -> Result<Vec<(String, String)>> {
    let sums = report.summaries();
    let titles = text_titles(files);
    let names = page_names(sums.iter().map(|s| s.text.as_str()));
    let mut index = head("Handout: the texts' statements, checked exactly");
    index.push_str("<h1>The texts' statements, checked exactly</h1>\n<ul>\n");
    for sum in &sums {
        let title = titles.get(&sum.text).cloned().unwrap_or_default();
        let _ = writeln!(
            index,
            "<li><a href=\"{}\">{}</a> {}</li>",
            names[&sum.text],
            esc(&heading_of(&sum.text)),
            esc(&title)
        );
    }
    index.push_str("</ul>\n");
    index.push_str(FOOT);
    let mut pages = vec![("index.html".to_string(), index)];
    for sum in &sums {
        let outcomes: Vec<&ClaimOutcome> = report.outcomes.iter().filter(|o| o.text == sum.text).collect();
        let title = titles.get(&sum.text).cloned().unwrap_or_default();
        pages.push((names[&sum.text].clone(), text_handout(sum, &title, &outcomes, files)?));
    }
    Ok(pages)
}

/// `000_ef6a3958c7d702f5.txt` → `Text 000`; another name stays as it is.
fn heading_of(text: &str) -> String {
    match text.split_once('_') {
        Some((n, _)) if !n.is_empty() && n.chars().all(|c| c.is_ascii_digit()) => format!("Text {n}"),
        _ => text.to_string(),
    }
}

fn text_handout(sum: &TextSummary, title: &str, outcomes: &[&ClaimOutcome], files: &[ClaimFile]) -> Result<String> {
    let heading = if title.is_empty() {
        heading_of(&sum.text)
    } else {
        format!("{} — {title}", heading_of(&sum.text))
    };
    let mut s = head(&heading);
    let _ = writeln!(
        s,
        "<h1>{}</h1>\n<p class=\"lead\">Each statement as the text prints it, checked in exact arithmetic: it holds \
         for every value of its variables unless a line under it says otherwise. Misprints are struck through and \
         followed by their correction. Worked cases and figures use exact fractions.</p>",
        esc(&heading)
    );
    let mut drawn: Vec<String> = Vec::new();
    for o in outcomes {
        // a correction is shown under its misprint; claims about the library are not the text's
        if o.corrects.is_some() || about_the_library(o) {
            continue;
        }
        let misprint = o.verdict == Verdict::Fails && o.expect == Verdict::Fails;
        let fix = outcomes.iter().find(|c| c.corrects.as_deref() == Some(o.id.as_str()));
        let _ = writeln!(
            s,
            "<section class=\"item{}\">\n<h2>{}</h2>",
            if misprint { " misprint" } else { "" },
            esc(label(o))
        );
        if misprint {
            let _ = writeln!(
                s,
                "<p class=\"statement printed\" lang=\"ja\">{}</p>\n<p class=\"note\"><span class=\"label\">Misprint.</span> \
                 As printed this is false: {}.{}</p>",
                formula(&o.statement),
                esc(&counterexample(&o.certificate)),
                o.note
                    .as_deref()
                    .map(|n| format!(" {}", formula(n.trim_start_matches("misprint: "))))
                    .unwrap_or_default()
            );
            if let Some(fix) = fix {
                let _ = writeln!(
                    s,
                    "<p class=\"statement correction\" lang=\"ja\"><span class=\"label\">Correct:</span> {}</p>",
                    formula(&fix.statement)
                );
            }
        } else {
            let _ = writeln!(s, "<p class=\"statement\" lang=\"ja\">{}</p>", formula(&o.statement));
            match o.verdict {
                Verdict::ProvedInRange => {
                    let _ = writeln!(
                        s,
                        "<p class=\"scope\">Checked for {} (every case), not beyond.</p>",
                        esc(o.range.as_deref().unwrap_or("the stated finite ranges"))
                    );
                }
                Verdict::Verified => {
                    let _ = writeln!(s, "<p class=\"scope\">Checked on examples, not proved.</p>");
                }
                Verdict::Fails | Verdict::Error => {
                    let _ = writeln!(s, "<p class=\"scope\">Not confirmed: see the full report.</p>");
                }
                Verdict::Proved => {}
            }
        }
        // the worked case of the statement that holds: the correction's for a misprint
        let worked_id = match (misprint, fix) {
            (true, Some(f)) => f.id.as_str(),
            _ => o.id.as_str(),
        };
        let lines = crate::verify::worked_case_lines(files, worked_id).unwrap_or_default();
        if !lines.is_empty() {
            let _ = writeln!(
                s,
                "<p class=\"note\"><span class=\"label\">Worked case.</span></p>\n<pre>{}</pre>",
                esc(&lines.join("\n"))
            );
        }
        if let Some(claim) = find_claim(files, o) {
            if let Ok(Some(cf)) = claim_figure(claim) {
                let svg = cf.figure.to_svg()?;
                if !drawn.contains(&svg) {
                    let _ = writeln!(
                        s,
                        "<figure>\n{}<figcaption>{}</figcaption>\n</figure>",
                        svg.trim_end(),
                        esc(&cf.caption)
                    );
                    drawn.push(svg);
                }
            }
        }
        s.push_str("</section>\n");
    }
    s.push_str(FOOT);
    Ok(s)
}
