//! A claim's certificate file in the report ([`crate::verify::readable`]): whether the kernel
//! re-checks it, its goal and its method's data as tables and lines, and the file itself —
//! linked when the report is written with `--certificates DIR`, otherwise embedded in a folded
//! `<details>` (up to [`MAX_EMBEDDED_BYTES`]; a larger file is named, with the command that
//! writes it).

use crate::figure::svg::esc;
use crate::verify::{Block, Readable, Status};
use std::fmt::Write as _;
use std::path::{Component, Path};

/// The largest certificate file embedded in a page when no certificate directory is linked.
pub const MAX_EMBEDDED_BYTES: usize = 32 * 1024;

/// The certificate block of one claim; `json_dir` is the URL of the certificate directory
/// relative to the page (ending in `/`), when the report links one.
pub fn certificate_html(r: &Readable, json_dir: Option<&str>) -> String {
    let mut s = String::new();
    let (class, word, detail) = match &r.status {
        Status::Rechecked(what) => ("kernel", "re-checked by the kernel", what),
        Status::NotRechecked(why) => ("none", "not re-checked", why),
    };
    let _ = writeln!(
        s,
        "<details class=\"certfile {class}\" open=\"open\">\n<summary>certificate file \
         <span class=\"file\">{}</span>: <strong class=\"recheck\">{word}</strong></summary>",
        esc(&r.file)
    );
    let _ = writeln!(s, "<p class=\"recheck-detail\">{}</p>", esc(detail));
    if let Some(m) = &r.method {
        let _ = writeln!(s, "<p class=\"cert-method\">method: <code>{}</code></p>", esc(m));
    }
    if !r.goal.is_empty() {
        s.push_str("<div class=\"cert-goal\">\n<h3>goal</h3>\n");
        blocks_html(&mut s, &r.goal, 4);
        s.push_str("</div>\n");
    }
    blocks_html(&mut s, &r.data, 3);
    match json_dir {
        Some(dir) => {
            let _ = writeln!(
                s,
                "<p class=\"json\">The file: <a href=\"{}{}\">{}</a> (JSON, docs/certificates.md); \
                 <code>casteljau check</code> re-reads it.</p>",
                esc(dir),
                esc(&r.file),
                esc(&r.file)
            );
        }
        None if r.json.len() <= MAX_EMBEDDED_BYTES => {
            let _ = writeln!(
                s,
                "<details class=\"json\"><summary>the file {} ({} bytes of JSON, as <code>prove --certificates DIR</code> \
                 writes it)</summary>\n<pre>{}</pre>\n</details>",
                esc(&r.file),
                r.json.len(),
                esc(r.json.trim_end())
            );
        }
        None => {
            let _ = writeln!(
                s,
                "<p class=\"json\">The file {} ({} bytes of JSON) is too large to embed: \
                 <code>prove --html DIR --certificates DIR2</code> writes it and links it here.</p>",
                esc(&r.file),
                r.json.len()
            );
        }
    }
    s.push_str("</details>\n");
    s
}

fn blocks_html(s: &mut String, blocks: &[Block], level: usize) {
    for b in blocks {
        match b {
            Block::Lines(lines) => {
                s.push_str("<dl class=\"kv\">\n");
                for (k, v) in lines {
                    let _ = writeln!(s, "<dt>{}</dt><dd class=\"math\">{}</dd>", esc(k), esc(v));
                }
                s.push_str("</dl>\n");
            }
            Block::Table { columns, rows, more } => {
                s.push_str("<div class=\"scroll\"><table class=\"cert\">\n<tr>");
                for c in columns {
                    let _ = write!(s, "<th>{}</th>", esc(c));
                }
                s.push_str("</tr>\n");
                for r in rows {
                    s.push_str("<tr>");
                    for c in r {
                        let _ = write!(s, "<td>{}</td>", esc(c));
                    }
                    s.push_str("</tr>\n");
                }
                s.push_str("</table></div>\n");
                if *more > 0 {
                    let _ = writeln!(s, "<p class=\"more\">… {more} more rows (in the file)</p>");
                }
            }
            Block::Group { title, blocks } => {
                let h = level.min(6);
                let _ = writeln!(s, "<div class=\"cert-group\">\n<h{h}>{}</h{h}>", esc(title));
                blocks_html(s, blocks, level + 1);
                s.push_str("</div>\n");
            }
            Block::More(n, what) => {
                let _ = writeln!(s, "<p class=\"more\">… {n} more {} (in the file)</p>", esc(what));
            }
        }
    }
}

/// The URL of directory `to` seen from a page in directory `from` (both existing), ending in
/// `/`, each path segment percent-encoded; `None` when either cannot be resolved.
pub fn relative_url(from: &Path, to: &Path) -> Option<String> {
    let (from, to) = (from.canonicalize().ok()?, to.canonicalize().ok()?);
    let (a, b): (Vec<Component>, Vec<Component>) = (from.components().collect(), to.components().collect());
    let common = a.iter().zip(&b).take_while(|(x, y)| x == y).count();
    if common == 0 {
        return None;
    }
    let mut url = "../".repeat(a.len() - common);
    for c in &b[common..] {
        let segment = c.as_os_str().to_str()?;
        url.push_str(&percent(segment));
        url.push('/');
    }
    if url.is_empty() {
        url.push_str("./");
    }
    Some(url)
}

/// A path segment with every byte but the unreserved ones (RFC 3986) percent-encoded.
fn percent(segment: &str) -> String {
    segment
        .bytes()
        .map(|b| {
            if b.is_ascii_alphanumeric() || b"-._~".contains(&b) {
                (b as char).to_string()
            } else {
                format!("%{b:02X}")
            }
        })
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn relative_urls_between_directories() {
        let base = std::env::temp_dir().join(format!("casteljau-rel-{}", std::process::id()));
        let (report, certs, same) = (base.join("report"), base.join("my certs"), base.join("report/c"));
        for d in [&report, &certs, &same] {
            std::fs::create_dir_all(d).unwrap();
        }
        assert_eq!(relative_url(&report, &certs).as_deref(), Some("../my%20certs/"));
        assert_eq!(relative_url(&report, &same).as_deref(), Some("c/"));
        assert_eq!(relative_url(&report, &report).as_deref(), Some("./"));
        assert_eq!(relative_url(&report, &base.join("missing")), None);
        std::fs::remove_dir_all(&base).unwrap();
    }
}
