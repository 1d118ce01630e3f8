//! `casteljau prove` and `casteljau check`: the claim files read, decided and reported; the
//! certificate files re-checked.

use super::*;

/// Every path names a claim file or a directory of them: anything else (a FIFO, a device)
/// could block or never end, so it is refused before anything is read.
fn check_claim_paths(paths: &[PathBuf]) -> Result<(), String> {
    for path in paths {
        let meta = std::fs::metadata(path).map_err(|err| match err.kind() {
            io::ErrorKind::NotFound => format!(
                "no such file or directory: {} (give claim files or directories)",
                path.display()
            ),
            _ => format!("cannot read {}: {err}", path.display()),
        })?;
        if !meta.is_file() && !meta.is_dir() {
            return Err(format!(
                "{} is not a regular file or a directory (give claim files or directories)",
                path.display()
            ));
        }
        if meta.is_dir() {
            // the `.toml` entries `prove` reads from a directory must be regular files too
            let entries = std::fs::read_dir(path).map_err(|err| format!("cannot read {}: {err}", path.display()))?;
            for entry in entries.filter_map(|e| e.ok().map(|e| e.path())) {
                let special = entry.extension().is_some_and(|x| x == "toml")
                    && std::fs::metadata(&entry).is_ok_and(|m| !m.is_file() && !m.is_dir());
                if special {
                    return Err(format!(
                        "{} is not a regular file (claim files must be regular files)",
                        entry.display()
                    ));
                }
            }
        }
    }
    Ok(())
}

/// Checks the report directory before any claim is proved: it is created (so an unwritable
/// place fails at once), and an existing report is only replaced with `--force`.
fn prepare_report_dir(flag: &str, dir: &Path, force: bool) -> Result<(), String> {
    if dir.exists() && !dir.is_dir() {
        return Err(format!("{flag}: {} exists and is not a directory", dir.display()));
    }
    let index = dir.join("index.html");
    if index.exists() && !force {
        return Err(format!(
            "{flag}: {} already exists (add --force to overwrite the report)",
            index.display()
        ));
    }
    std::fs::create_dir_all(dir).map_err(|err| format!("{flag}: cannot create {}: {err}", dir.display()))
}

/// The HTML a `prove` run also writes: the report and the handout, each into its directory.
pub(crate) struct Reports<'a> {
    pub(crate) html: Option<&'a Path>,
    pub(crate) handout: Option<&'a Path>,
    pub(crate) force: bool,
    pub(crate) certificates: Option<&'a Path>,
    pub(crate) check: bool,
}

/// The `--identity` check: the identity, its `--for` ranges and its `--vars`.
type OneLine = (String, Vec<String>, Option<Vec<String>>);

pub(crate) fn prove(
    paths: &[PathBuf],
    identity: Option<OneLine>,
    id: Option<&str>,
    verbose: bool,
    reports: Reports<'_>,
    format: Format,
) -> Result<ExitCode, String> {
    check_claim_paths(paths)?;
    let files = match &identity {
        Some((lhs_rhs, ranges, vars)) => {
            let vars: Option<Vec<String>> = vars.as_ref().map(|v| v.iter().map(|s| s.trim().to_string()).collect());
            vec![identity_file(lhs_rhs, ranges, vars.as_deref()).map_err(|e| e.to_string())?]
        }
        None => claim_files(paths)?,
    };
    let id = match id {
        Some("") if identity.is_some() => Some("identity"),
        Some("") => return Err("--explain needs a claim id (only --identity has one claim)".into()),
        other => other,
    };
    if let Some(id) = id {
        let style = match (format, verbose) {
            (Format::Latex, true) => {
                return Err("--verbose does not apply to --format latex (the LaTeX proof has no case log)".into())
            }
            (Format::Latex, false) => ExplainStyle::Latex,
            (_, true) => ExplainStyle::Verbose,
            (_, false) => ExplainStyle::Short,
        };
        let text = explain_files(&files, id, style).map_err(|e| e.to_string())?;
        match format {
            Format::Text | Format::Latex => output(&format!("{}\n", text.trim_end()))?,
            Format::Json => output(&format!("{}\n", json!({"id": id, "explanation": text})))?,
        }
        return Ok(ExitCode::SUCCESS);
    }
    if matches!(format, Format::Latex) {
        return Err(LATEX_ONLY.into());
    }
    if let (Some(a), Some(b)) = (reports.html, reports.handout) {
        if a == b {
            return Err("--html and --handout need two different directories".into());
        }
    }
    if let Some(dir) = reports.html {
        prepare_report_dir("--html", dir, reports.force)?;
    }
    if let Some(dir) = reports.handout {
        prepare_report_dir("--handout", dir, reports.force)?;
    }
    let show_progress = io::stderr().is_terminal();
    let mut progress = |done: usize, total: usize, claim: &str| {
        if show_progress {
            // one line, redrawn in place: carriage return, then clear to the end of the line
            let mut err = io::stderr().lock();
            let _ = write!(err, "\r\x1b[2K[{done}/{total}] {claim}");
            let _ = err.flush();
        }
    };
    // The HTML report shows each claim's certificate; the handout reads only verdicts.
    let report = if reports.certificates.is_some() || reports.html.is_some() {
        prove_files(&files, &mut progress)
    } else {
        prove_files_without_certificates(&files, &mut progress)
    };
    if show_progress {
        eprint!("\r\x1b[2K");
    }
    let report = report.map_err(|e| e.to_string())?;
    if let Some(dir) = reports.html {
        if let Some(certs) = reports.certificates {
            // the report links each claim's file there (written below)
            std::fs::create_dir_all(certs)
                .map_err(|e| format!("--certificates: cannot create {}: {e}", certs.display()))?;
        }
        let written =
            casteljau::html::write_report(&report, &files, dir, reports.certificates).map_err(|e| e.to_string())?;
        eprintln!(
            "casteljau: wrote the HTML report ({written} pages) to {}",
            dir.join("index.html").display()
        );
    }
    if let Some(dir) = reports.handout {
        let written = casteljau::html::write_handout(&report, &files, dir).map_err(|e| e.to_string())?;
        eprintln!(
            "casteljau: wrote the handout ({written} pages) to {}",
            dir.join("index.html").display()
        );
    }
    let mut refused = 0;
    if let Some(dir) = reports.certificates {
        let written = write_certificates(&report, dir).map_err(|e| e.to_string())?;
        eprintln!("casteljau: wrote {written} certificates to {}", dir.display());
        if reports.check {
            let checked = check_certificates(&[dir.to_path_buf()]).map_err(|e| e.to_string())?;
            for (path, r) in &checked {
                if let Recheck::Refused(why) = r {
                    eprintln!("casteljau: {}: REFUSED: {why}", path.display());
                }
            }
            let (line, bad) = recheck_summary(&checked);
            refused = bad;
            eprintln!("casteljau: --check: {line}");
        }
    }
    match format {
        Format::Text if identity.is_some() => output(&report.claims_text())?,
        Format::Text => output(&report.to_text())?,
        Format::Json => output(&format!("{}\n", report.to_json()))?,
        Format::Latex => return Err(LATEX_ONLY.into()),
    }
    let undecided: Vec<&str> = report
        .outcomes
        .iter()
        .filter(|o| o.verdict == Verdict::Error)
        .map(|o| o.id.as_str())
        .collect();
    Ok(if !undecided.is_empty() {
        // the report above keeps every other claim's verdict; the status line names the others
        eprintln!(
            "casteljau: {} claim{} not decided (each with its reason in the report): {}",
            undecided.len(),
            if undecided.len() == 1 { "" } else { "s" },
            undecided.join(", ")
        );
        ExitCode::from(2)
    } else if report.mismatches() > 0 || refused > 0 {
        ExitCode::from(1)
    } else {
        ExitCode::SUCCESS
    })
}

/// A re-check's status word and detail, as `check` prints them.
pub(crate) fn recheck_status(r: &Recheck) -> (&'static str, &str) {
    match r {
        Recheck::Accepted(what) => ("re-checked by the kernel", what),
        Recheck::NotChecked(why) => ("not re-checked", why),
        Recheck::Refused(why) => ("REFUSED", why),
    }
}

/// The one-line summary of re-checked certificates, and how many were refused.
pub(crate) fn recheck_summary(checked: &[(PathBuf, Recheck)]) -> (String, usize) {
    let count = |f: fn(&Recheck) -> bool| checked.iter().filter(|(_, r)| f(r)).count();
    let accepted = count(|r| matches!(r, Recheck::Accepted(_)));
    let none = count(|r| matches!(r, Recheck::NotChecked(_)));
    let refused = count(|r| matches!(r, Recheck::Refused(_)));
    (
        format!(
            "{} certificates: {accepted} re-checked by the kernel, {none} not re-checked (no data for their method), {refused} refused",
            checked.len()
        ),
        refused,
    )
}

/// The claim files `prove` reads: those given; without any, `proofs/` when the working
/// directory has one (a checkout), else the four texts' claims built into the program (an
/// installed binary run anywhere).
fn claim_files(paths: &[PathBuf]) -> Result<Vec<claims::ClaimFile>, String> {
    let default = Path::new("proofs");
    let loaded = if !paths.is_empty() {
        claims::load_paths(paths)
    } else if default.is_dir() {
        claims::load_paths(&[default.to_path_buf()])
    } else {
        claims::builtin_files()
    };
    loaded.map_err(|e| e.to_string())
}
