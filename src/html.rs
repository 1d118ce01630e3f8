//! The static HTML report of a `prove` run, for reading on screen and handing out on paper.
//!
//! [`write_report`] writes `index.html` (what the verdicts mean, the summary table, the
//! misprints found) and one page per text with every claim: its statement as printed, the
//! verdict and its scope, the certificate or counterexample, misprints highlighted beside their
//! corrections, and the figure the claim is about ([`claim_figure`]), inlined as SVG. Pages
//! are self-contained (styles inline, no scripts, no network) and well-formed XML, and carry a
//! print stylesheet.

mod claim_figure;
mod handout;
pub mod interactive;
mod pages;
mod report;
mod statement;
mod verdict;

pub use claim_figure::{claim_figure, ClaimFigure};
pub use handout::{render_handout, write_handout};
pub use pages::{claim_anchor, page_name, page_names};
pub use statement::formula;
pub use verdict::{verdict_text, VerdictText};

use crate::error::Result;
use crate::verify::claims::ClaimFile;
use crate::verify::{ClaimOutcome, Report};
use pages::{text_titles, write_pages};
use report::{index_page, text_page};
use std::path::Path;

/// Writes the report into `dir` (created if needed): `index.html` and one page per text.
/// Returns the number of pages written.
pub fn write_report(report: &Report, files: &[ClaimFile], dir: &Path) -> Result<usize> {
    let pages = render_pages(report, files)?;
    write_pages(dir, "report", &pages)?;
    interactive::write_pages(dir)?;
    Ok(pages.len())
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
