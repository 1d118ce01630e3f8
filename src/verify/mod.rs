//! Exact proofs of the texts' claims: claim files, verdicts with certificates, reports.
//!
//! A claim file (TOML, documented in `proofs/README.md`) lists what a text prints — formulas,
//! examples, properties, each step of a derivation — as expressions written as in a book
//! (`(2t-1)/(t^2-t+1)`, `4x^2+3y^2-10y+3`, `B(i, n, t)`, `sum(r, j, n, …)`). Each claim gets a
//! verdict decided in exact arithmetic only:
//!
//! - **proved**: the finite check is a proof. A polynomial identity of degree ≤ d (the bound is
//!   *derived* from the expressions by the degree-bound algebra, never guessed) is checked exactly at d+1
//!   distinct parameters; rational functions by their cleared numerators at points where no
//!   denominator vanishes; identities affine in the control points on the zero and unit
//!   polygons; two parameters on a grid; claims about arbitrary vectors by exact symbolic
//!   expansion (rational functions).
//! - **proved_in_range**: every case of the claim's finite integer ranges (`for`, a theorem's
//!   `degrees`) proved as above; the ranges are reported with the verdict. Never "proved".
//! - **verified**: bounded evidence for a statement about a limit, saying exactly what was checked.
//! - **fails**: an exact counterexample (the parameters and both sides' values).
//!
//! ```
//! use casteljau::verify::{check_claim, claims::parse_file, Verdict};
//! let file = parse_file(r#"
//! [[claim]]
//! id = "ex"
//! source = "000 4)"
//! statement = "-(2t-1)^2+1 = 4/3 B_1^3(t) + 4/3 B_2^3(t)"
//! kind = "identity"
//! lhs = "-(2t-1)^2 + 1"
//! rhs = "4/3 B(1,3,t) + 4/3 B(2,3,t)"
//! "#, std::path::Path::new("x.toml")).unwrap();
//! let out = check_claim(&file.claim[0], false).unwrap();
//! assert_eq!(out.verdict, Verdict::Proved);
//! assert!(out.certificate.contains("degree ≤ 3 in t"));
//! ```

// The modules, bottom up: each imports only modules named before it in this list (checked
// by `tests/layers.rs`).
//
// - the work `budget` a proof's searches share (it imports nothing of verify);
// - the data: `expr` (expression trees), `checked` (verdicts, methods, outcomes), `claims`
//   (the claim file format);
// - expressions: `alg` (the algebras evaluated in), `poly` (rational functions), `parse`,
//   `rewrite` (definitions, substitution, `diff`), `eval` (the evaluator), `methods` (library
//   operations callable in expressions);
// - hypergeometric terms: `hyper`, `pieces` (zero on every piece of a domain), `ansatz`,
//   `telescope` (recurrences by creative telescoping), `beta` (integrals over [0, 1]);
// - a claim's context: `objects`, `context`, `names`;
// - provers: `sampling` (degree bounds and exact evaluation), `expansion` (symbolic expansion,
//   `implies`), `identity` (the identity goal), `translate`, `recurrence` and `symbolic` (for
//   every n), `theorems`, `inequality`;
// - the kinds and the scope of a verdict: `kinds`, `scope`;
// - the reports: `argue`, `latex`, `report`.
mod alg;
mod ansatz;
mod argue;
mod beta;
mod budget;
mod checked;
pub mod claims;
mod context;
mod eval;
mod expansion;
mod expr;
mod hyper;
mod identity;
mod inequality;
mod kinds;
mod latex;
mod methods;
mod names;
mod objects;
mod parse;
mod pieces;
mod poly;
mod recurrence;
mod report;
mod rewrite;
mod sampling;
mod scope;
mod symbolic;
mod telescope;
mod theorems;
mod translate;

use crate::error::{Error, Result};
use std::path::PathBuf;

pub use checked::{Checked, Evaluation, Method, Step, StepKind, Verdict};
pub use kinds::check_claim;
pub use report::{ClaimOutcome, ExplainStyle, Report, TextSummary};
pub use scope::{range_bound, PROVABLE};
pub use theorems::elevation_bound;

pub(crate) use objects::curve_from_spec;

#[cfg(test)]
mod expr_tests;

/// Loads every claim file under `paths` (files, or directories whose `.toml` files are read in
/// name order) and checks every claim; `progress(done, total, id)` is called after each claim,
/// on the calling thread, with `done` counting completed claims. Claims are independent and
/// checked in parallel (rayon); the report keeps file order. A claim that cannot be decided (a
/// malformed expression, a limit reached) gets [`Verdict::Error`] with its one-line reason, and
/// every other claim is still checked; a file that cannot be read or parsed is an error.
pub fn prove_paths(paths: &[PathBuf], progress: &mut dyn FnMut(usize, usize, &str)) -> Result<Report> {
    prove_files(&claims::load_paths(paths)?, progress)
}

/// Checks every claim of claim files already loaded (e.g. [`claims::builtin_files`]), as
/// [`prove_paths`] does.
pub fn prove_files(files: &[claims::ClaimFile], progress: &mut dyn FnMut(usize, usize, &str)) -> Result<Report> {
    use rayon::prelude::*;
    let jobs: Vec<(&claims::ClaimFile, &claims::Claim)> =
        files.iter().flat_map(|f| f.claim.iter().map(move |c| (f, c))).collect();
    let total = jobs.len();
    let (done_tx, done_rx) = std::sync::mpsc::channel::<usize>();
    let jobs = &jobs;
    let results: Vec<Result<ClaimOutcome>> = std::thread::scope(|scope| {
        let worker = scope.spawn(move || {
            jobs.par_iter()
                .enumerate()
                .map_with(done_tx, |done_tx, (index, &(f, c))| {
                    let outcome = check_one(f, c);
                    // The receiver lives until every claim is done; a send cannot fail.
                    let _ = done_tx.send(index);
                    outcome
                })
                .collect()
        });
        // Completions arrive in any order; count them here so `done` rises by one each time.
        for (done, index) in done_rx.iter().enumerate() {
            progress(done + 1, total, &jobs[index].1.id);
        }
        worker.join().unwrap_or_else(|panic| std::panic::resume_unwind(panic))
    });
    let outcomes = results.into_iter().collect::<Result<Vec<_>>>()?;
    Ok(Report { outcomes })
}

fn check_one(f: &claims::ClaimFile, c: &claims::Claim) -> Result<ClaimOutcome> {
    // A claim that cannot be decided is reported as such; it never hides the others.
    let checked = kinds::check_claim(c, false).unwrap_or_else(|e| checked::Checked::new(Verdict::Error, e.to_string()));
    let range_bound = scope::range_bound(c, checked.verdict);
    Ok(ClaimOutcome {
        id: c.id.clone(),
        source: c.source.clone(),
        statement: c.statement.clone(),
        verdict: checked.verdict,
        range: checked.range,
        certificate: checked.certificate,
        expect: c.expected(),
        file: f.path.display().to_string(),
        text: text_name(f),
        corrects: c.corrects.clone(),
        note: c.note.clone(),
        range_bound,
    })
}

fn text_name(f: &claims::ClaimFile) -> String {
    match &f.text {
        Some(t) => t.file.clone(),
        None => f
            .path
            .file_stem()
            .map(|s| s.to_string_lossy().into_owned())
            .unwrap_or_default(),
    }
}

fn in_claim(f: &claims::ClaimFile, id: &str, e: Error) -> Error {
    Error::Domain(format!("{}: claim {id}: {e}", f.path.display()))
}

/// The proof of claim `id` (searched in `paths`), in exact fractions: the argument (what is
/// checked, why it suffices), one worked case with the de Casteljau scheme (9) that goes with it,
/// and with [`ExplainStyle::Verbose`] every checked case.
pub fn explain(paths: &[PathBuf], id: &str, style: ExplainStyle) -> Result<String> {
    explain_files(&claims::load_paths(paths)?, id, style)
}

/// The proof of claim `id`, searched in claim files already loaded; see [`explain`].
pub fn explain_files(files: &[claims::ClaimFile], id: &str, style: ExplainStyle) -> Result<String> {
    for f in files {
        if let Some(c) = f.claim.iter().find(|c| c.id == id) {
            let checked = kinds::check_claim(c, true).map_err(|e| in_claim(f, id, e))?;
            let range_bound = scope::range_bound(c, checked.verdict);
            return Ok(report::explain_text(f, c, &checked, range_bound.as_deref(), style));
        }
    }
    Err(Error::Domain(format!(
        "no claim with id '{id}' in the given claim files"
    )))
}
