//! The report's and the handout's files: each text's page name, claim anchors, the texts'
//! titles, the claim an outcome came from, and writing the pages out.

use crate::error::{Error, Result};
use crate::verify::claims::{Claim, ClaimFile};
use crate::verify::ClaimOutcome;
use std::collections::BTreeMap;
use std::path::Path;

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

/// Writes `pages` (`(file name, HTML)`) into `dir`, created if needed; `what` names the
/// directory in errors.
pub(crate) fn write_pages(dir: &Path, what: &str, pages: &[(String, String)]) -> Result<()> {
    std::fs::create_dir_all(dir)
        .map_err(|e| Error::Domain(format!("cannot create the {what} directory {}: {e}", dir.display())))?;
    for (name, html) in pages {
        let path = dir.join(name);
        std::fs::write(&path, html).map_err(|e| Error::Domain(format!("cannot write {}: {e}", path.display())))?;
    }
    Ok(())
}

/// Each text's title by its file name (empty where the claim file gives none).
pub(crate) fn text_titles(files: &[ClaimFile]) -> BTreeMap<String, String> {
    files
        .iter()
        .filter_map(|f| {
            f.text
                .as_ref()
                .map(|t| (t.file.clone(), t.title.clone().unwrap_or_default()))
        })
        .collect()
}

/// The claim an outcome came from.
pub(crate) fn find_claim<'a>(files: &'a [ClaimFile], o: &ClaimOutcome) -> Option<&'a Claim> {
    files
        .iter()
        .filter(|f| f.path.display().to_string() == o.file)
        .flat_map(|f| &f.claim)
        .find(|c| c.id == o.id)
}
