//! The static HTML report of a `prove` run, for reading on screen and handing out on paper.
//!
//! [`write_report`] writes `index.html` (what the verdicts mean, the summary table, the
//! misprints found) and one page per text with every claim: its statement as printed, the
//! verdict and its scope, the certificate or counterexample, misprints highlighted beside their
//! corrections, the certificate file read back ([`certificate`]: re-checked by the kernel or
//! why not, its data as tables, the JSON linked or embedded), and the figure the claim is about
//! ([`claim_figure`]), inlined as SVG. Pages
//! are self-contained (styles inline, no scripts, no network) and well-formed XML, and carry a
//! print stylesheet.

mod certificate;
mod claim_figure;
mod handout;
pub mod interactive;
mod pages;
mod report;
mod statement;
mod verdict;

pub use certificate::{certificate_html, relative_url, MAX_EMBEDDED_BYTES};
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
/// With `certificates` (the directory `prove --certificates` writes, existing), each claim links
/// its certificate file there; otherwise the file is embedded in its page. Returns the number
/// of pages written.
pub fn write_report(report: &Report, files: &[ClaimFile], dir: &Path, certificates: Option<&Path>) -> Result<usize> {
    std::fs::create_dir_all(dir).map_err(|e| {
        crate::error::Error::Domain(format!("cannot create the report directory {}: {e}", dir.display()))
    })?;
    let json_dir = match certificates {
        Some(c) => Some(relative_url(dir, c).ok_or_else(|| {
            crate::error::Error::Domain(format!(
                "cannot link the certificates in {} from the report in {}",
                c.display(),
                dir.display()
            ))
        })?),
        None => None,
    };
    let pages = render_pages_linking(report, files, json_dir.as_deref())?;
    write_pages(dir, "report", &pages)?;
    interactive::write_pages(dir)?;
    Ok(pages.len())
}

/// The pages as `(file name, HTML)`, `index.html` first, each claim's certificate file
/// embedded in its page.
pub fn render_pages(report: &Report, files: &[ClaimFile]) -> Result<Vec<(String, String)>> {
    render_pages_linking(report, files, None)
}

/// The pages as [`render_pages`] gives them, each claim's certificate file linked in
/// `json_dir` (a URL relative to the report's pages, ending in `/`) when given.
pub fn render_pages_linking(
    report: &Report,
    files: &[ClaimFile],
    json_dir: Option<&str>,
) -> Result<Vec<(String, String)>> {
    let sums = report.summaries();
    let titles = text_titles(files);
    let names = page_names(sums.iter().map(|s| s.text.as_str()));
    let mut pages = vec![("index.html".to_string(), index_page(report, &sums, &titles, &names))];
    for sum in &sums {
        let outcomes: Vec<&ClaimOutcome> = report.outcomes.iter().filter(|o| o.text == sum.text).collect();
        let title = titles.get(&sum.text).cloned().unwrap_or_default();
        pages.push((
            names[&sum.text].clone(),
            text_page(sum, &title, &outcomes, report, files, json_dir)?,
        ));
    }
    Ok(pages)
}
