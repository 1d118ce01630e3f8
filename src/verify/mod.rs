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
//! assert_eq!(out.verdict(), Verdict::Proved);
//! assert!(out.certificate.contains("degree ≤ 3 in t"));
//! ```

// The modules, bottom up: each imports only modules named before it in this list (checked
// by `tests/layers.rs`).
//
// - the trusted `kernel`: verdicts, methods, outcomes, the one door to `proved`, and what
//   the checks compute with: expression trees, the algebras and the evaluator, rational
//   functions, hypergeometric terms, domain pieces, Beta integrals, the work budget (it imports
//   nothing of verify outside `kernel/`);
// - `outcome`: a claim's result as the reports read it (a proof from the kernel, or a verdict
//   that needs none);
// - the data: `claim_syntax` (each field's expected form, for errors), `claims` (the claim
//   file format), `one_line` (the claim of `prove --identity`);
// - expressions: `parse`, `rewrite` (definitions, substitution, `diff`), `methods` (library
//   operations callable in expressions);
// - searches: `ansatz` (WZ certificates), `telescope` (recurrences by creative telescoping);
// - a claim's context: `objects`, `inline`, `context`, `names`, `lemma` (library objects by
//   their definitions and by lemmas; `inline` writes concrete ones out for certificates);
// - provers: `sampling` (degree bounds and exact evaluation), `expansion` (symbolic expansion,
//   `implies`), `identity` (the identity goal), `translate`, `recurrence` and `symbolic` (for
//   every n), `theorems`, `inequality`;
// - the kinds and the scope of a verdict: `kinds`, `scope`;
// - the reports: `argue`, `latex`, `report`;
// - certificates as files: `certify` (written from the kernel's data, re-checked by the kernel);
//   `readable` (a certificate file laid out for people: `--explain`, the HTML report).
mod ansatz;
mod argue;
mod certify;
mod claim_syntax;
pub mod claims;
mod context;
mod expansion;
mod identity;
mod inequality;
mod inline;
mod kernel;
mod kinds;
mod latex;
mod lemma;
mod methods;
mod names;
mod objects;
mod one_line;
mod outcome;
mod parse;
mod readable;
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

pub use certify::{check_certificate, check_certificate_texts, check_certificates, write_certificates, Recheck};
pub use kernel::checked::{Evaluation, Method, Step, StepKind, Verdict};
pub use kernel::{Proof, Trusted};
pub use kinds::check_claim;
pub use one_line::identity_file;
pub use outcome::Checked;
pub use readable::{read_back, readable, readable_among, Block, Readable, Status};
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
    prove_files_keeping(files, progress, true)
}

/// The verdicts of [`prove_files`] without the work only certificate files need (the sampled
/// sides written out without the claim's objects): the same verdicts, methods, texts and JSON
/// report, checked on the same evidence. The outcomes' data then records each sampled side as
/// the claim writes it, so it is not for [`write_certificates`], the HTML report or `explain`
/// (they take [`prove_files`]).
pub fn prove_files_without_certificates(
    files: &[claims::ClaimFile],
    progress: &mut dyn FnMut(usize, usize, &str),
) -> Result<Report> {
    prove_files_keeping(files, progress, false)
}

fn prove_files_keeping(
    files: &[claims::ClaimFile],
    progress: &mut dyn FnMut(usize, usize, &str),
    certify: bool,
) -> Result<Report> {
    let jobs: Vec<Job<'_>> = files.iter().flat_map(|f| f.claim.iter().map(move |c| (f, c))).collect();
    let decided = decide(&jobs, progress, certify);
    let outcomes = jobs
        .iter()
        .zip(decided)
        .map(|(&(f, c), d)| outcome(f, c, d.checked, d.range_bound))
        .collect();
    Ok(Report { outcomes })
}

type Job<'a> = (&'a claims::ClaimFile, &'a claims::Claim);

/// A claim decided, with what is read from its one elaboration: the note on its scope and,
/// for a claim proved for every value, the lemma it states (for the claims citing it).
struct Decided {
    checked: Checked,
    range_bound: Option<String>,
    lemma: Option<Result<lemma::Lemma>>,
}

/// Checks one claim (elaborated once, in [`kinds::check_citing`]) with the lemmas it cites.
/// `certify`: see [`kinds::check_citing`].
fn decide_one(
    claim: &claims::Claim,
    lemmas: &Result<Vec<lemma::Lemma>>,
    detail: bool,
    certify: bool,
) -> Result<Decided> {
    let (checked, ctx) = kinds::check_citing(claim, lemmas, detail, certify)?;
    let range_bound = scope::range_bound_in(claim, &ctx, checked.verdict());
    let lemma = (checked.verdict() == Verdict::Proved && claim.for_every()).then(|| {
        let mut lemma = lemma::Lemma::from_claim(claim, &ctx)?;
        // The goal the claim's own certificate writes, for the certificates citing it.
        if let kernel::certificate::Data::Symbolic(goal) = checked.data() {
            lemma.statement = Some(Box::new(symbolic::written::statement(goal)));
        }
        Ok(lemma)
    });
    Ok(Decided {
        checked,
        range_bound,
        lemma,
    })
}

/// Every claim of `jobs` checked, the cited ones first (see [`prove_files`]).
fn decide(jobs: &[Job<'_>], progress: &mut dyn FnMut(usize, usize, &str), certify: bool) -> Vec<Decided> {
    use rayon::prelude::*;
    let total = jobs.len();
    let rounds = citation_rounds(jobs);
    let mut decided: Vec<Option<Decided>> = (0..total).map(|_| None).collect();
    let mut done = 0;
    for round in rounds {
        // Each round's claims cite only claims decided in earlier rounds.
        let jobs = &jobs;
        let decided_so_far = &decided;
        let round = &round;
        let check = |&(index, ref cited): &(usize, Result<Vec<usize>>)| {
            let lemmas = cited.clone().and_then(|cited| lemmas_of(jobs, decided_so_far, &cited));
            // A claim that cannot be decided is reported as such; it never hides the others.
            let decided = decide_one(jobs[index].1, &lemmas, false, certify).unwrap_or_else(|e| Decided {
                checked: Checked::error(e.to_string()),
                range_bound: None,
                lemma: None,
            });
            (index, decided)
        };
        if rayon::current_thread_index().is_some() {
            // Called from a worker of the pool (a caller's parallel loop): no thread of the pool
            // may wait for the others, so the round runs on the pool and reports at its end.
            let results: Vec<(usize, Decided)> = round.par_iter().map(check).collect();
            for (index, checked) in results {
                done += 1;
                progress(done, total, &jobs[index].1.id);
                decided[index] = Some(checked);
            }
            continue;
        }
        let (done_tx, done_rx) = std::sync::mpsc::channel::<usize>();
        let results: Vec<(usize, Decided)> = std::thread::scope(|scope| {
            let worker = scope.spawn(move || {
                round
                    .par_iter()
                    .map_with(done_tx, |done_tx, job| {
                        let out = check(job);
                        // The receiver lives until every claim is done; a send cannot fail.
                        let _ = done_tx.send(out.0);
                        out
                    })
                    .collect()
            });
            // Completions arrive in any order; count them here so `done` rises by one each time.
            for index in done_rx.iter() {
                done += 1;
                progress(done, total, &jobs[index].1.id);
            }
            worker.join().unwrap_or_else(|panic| std::panic::resume_unwind(panic))
        });
        for (index, checked) in results {
            decided[index] = Some(checked);
        }
    }
    decided
        .into_iter()
        .map(|c| c.expect("every claim is in a round"))
        .collect()
}

/// The claims in rounds: a claim comes after every claim it cites (`uses`), each with the
/// indices of the claims it cites, or why they cannot be cited (an unknown id, a cycle).
fn citation_rounds(jobs: &[Job<'_>]) -> Vec<Vec<(usize, Result<Vec<usize>>)>> {
    let index_of = |id: &str| jobs.iter().position(|(_, c)| c.id == id);
    // depth[k]: the round of claim k, or the reason it has none.
    let mut depth: Vec<Option<std::result::Result<usize, String>>> = vec![None; jobs.len()];
    fn round_of(
        k: usize,
        jobs: &[Job<'_>],
        index_of: &dyn Fn(&str) -> Option<usize>,
        depth: &mut Vec<Option<std::result::Result<usize, String>>>,
        path: &mut Vec<usize>,
    ) -> std::result::Result<usize, String> {
        if let Some(d) = &depth[k] {
            return d.clone();
        }
        if let Some(at) = path.iter().position(|&p| p == k) {
            let cycle: Vec<&str> = path[at..].iter().chain([&k]).map(|&p| jobs[p].1.id.as_str()).collect();
            return Err(format!("the citations form a cycle: {}", cycle.join(" → ")));
        }
        path.push(k);
        let mut d = Ok(0);
        for id in &jobs[k].1.uses {
            let cited = match index_of(id) {
                None => Err(format!("it cites {id}, which is not a claim of the files checked")),
                Some(c) => round_of(c, jobs, index_of, depth, path).map_err(|e| format!("it cites {id}: {e}")),
            };
            d = match (d, cited) {
                (Ok(a), Ok(b)) => Ok(a.max(b + 1)),
                (Err(e), _) | (_, Err(e)) => Err(e),
            };
        }
        path.pop();
        depth[k] = Some(d.clone());
        d
    }
    for k in 0..jobs.len() {
        round_of(k, jobs, &index_of, &mut depth, &mut Vec::new()).ok();
    }
    let mut rounds: Vec<Vec<(usize, Result<Vec<usize>>)>> = Vec::new();
    for (k, d) in depth.into_iter().enumerate() {
        let (r, cited) = match d.expect("every claim has a depth") {
            Ok(r) => (r, Ok(jobs[k].1.uses.iter().filter_map(|id| index_of(id)).collect())),
            Err(e) => (0, Err(Error::Domain(format!("claim {}: {e}", jobs[k].1.id)))),
        };
        if rounds.len() <= r {
            rounds.resize_with(r + 1, Vec::new);
        }
        rounds[r].push((k, cited));
    }
    rounds
}

/// The lemmas of the cited claims, each proved for every value; otherwise why not.
fn lemmas_of(jobs: &[Job<'_>], decided: &[Option<Decided>], cited: &[usize]) -> Result<Vec<lemma::Lemma>> {
    cited
        .iter()
        .map(|&k| {
            let claim = jobs[k].1;
            let d = decided[k].as_ref();
            match d.map(|d| d.checked.verdict()) {
                Some(Verdict::Proved) if claim.for_every() => d
                    .and_then(|d| d.lemma.clone())
                    .unwrap_or_else(|| Err(Error::Domain(format!("the lemma of {} was not read", claim.id)))),
                Some(v) => Err(Error::Domain(format!(
                    "it cites {}, which is {} and not proved for every value (a lemma must be; a claim resting on a lemma proved in a range is at most proved in that range)",
                    claim.id,
                    v.as_str()
                ))),
                None => Err(Error::Domain(format!("{} is not decided before the claims citing it", claim.id))),
            }
        })
        .collect()
}

fn outcome(
    f: &claims::ClaimFile,
    c: &claims::Claim,
    mut checked: Checked,
    range_bound: Option<String>,
) -> ClaimOutcome {
    let proof = checked.proof();
    let (verdict, range) = (checked.verdict(), checked.range().map(str::to_string));
    let (method, rests_on) = (proof.map(kernel::Proof::method), proof.map(|p| p.rests_on().to_vec()));
    // moved, not copied: a certificate's data holds every sampled side written out
    let computed = std::mem::take(&mut checked.computed);
    let certificate = std::mem::take(&mut checked.certificate);
    ClaimOutcome {
        id: c.id.clone(),
        source: c.source.clone(),
        statement: c.statement.clone(),
        verdict,
        range,
        method,
        rests_on,
        data: checked.into_data(),
        computed,
        certificate,
        expect: c.expected(),
        file: f.path.display().to_string(),
        text: text_name(f),
        corrects: c.corrects.clone(),
        note: c.note.clone(),
        range_bound,
    }
}

/// One claim checked with its steps, after the claims it cites (and theirs), and the note on
/// its scope; with the outcomes of the claims it cites (and theirs), whose certificates its
/// own is re-checked with.
fn explained(
    files: &[claims::ClaimFile],
    claim: &claims::Claim,
) -> Result<(Checked, Option<String>, Vec<ClaimOutcome>)> {
    if claim.uses.is_empty() {
        return decide_one(claim, &Ok(Vec::new()), true, true).map(|d| (d.checked, d.range_bound, Vec::new()));
    }
    let all: Vec<Job<'_>> = files.iter().flat_map(|f| f.claim.iter().map(move |c| (f, c))).collect();
    let mut wanted: Vec<&str> = claim.uses.iter().map(String::as_str).collect();
    let mut k = 0;
    while k < wanted.len() {
        if let Some((_, c)) = all.iter().find(|(_, c)| c.id == wanted[k]) {
            for id in &c.uses {
                if !wanted.contains(&id.as_str()) && *id != claim.id {
                    wanted.push(id);
                }
            }
        }
        k += 1;
    }
    let mut jobs: Vec<Job<'_>> = all
        .iter()
        .copied()
        .filter(|(_, c)| wanted.contains(&c.id.as_str()))
        .collect();
    jobs.push(
        all.iter()
            .copied()
            .find(|(_, c)| c.id == claim.id)
            .expect("the claim is in its files"),
    );
    let rounds = citation_rounds(&jobs);
    let cited = rounds
        .iter()
        .flatten()
        .find(|(k, _)| *k == jobs.len() - 1)
        .map(|(_, cited)| cited.clone())
        .expect("every claim is in a round");
    let decided: Vec<Option<Decided>> = decide(&jobs[..jobs.len() - 1], &mut |_, _, _| {}, true)
        .into_iter()
        .map(Some)
        .collect();
    let lemmas = cited.and_then(|cited| lemmas_of(&jobs, &decided, &cited));
    let d = decide_one(claim, &lemmas, true, true)?;
    // As `prove --certificates` writes them (checked without steps), for the re-check.
    let outcomes = jobs
        .iter()
        .zip(decided)
        .filter_map(|(&(f, c), d)| d.map(|d| outcome(f, c, d.checked, d.range_bound)))
        .collect();
    Ok((d.checked, d.range_bound, outcomes))
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

/// The worked case of claim `id` as a reader of the texts wants it (the handout): exact
/// evaluations and the scheme (9), or the counterexample; no proof internals.
pub fn worked_case_lines(files: &[claims::ClaimFile], id: &str) -> Result<Vec<String>> {
    for f in files {
        if let Some(c) = f.claim.iter().find(|c| c.id == id) {
            let (checked, _, _) = explained(files, c).map_err(|e| in_claim(f, id, e))?;
            return Ok(report::worked_lines(c, &checked));
        }
    }
    Err(Error::Domain(format!(
        "no claim with id '{id}' in the given claim files"
    )))
}

/// `cited` and the outcomes of the lemmas `o`'s certificate cites that `cited` lacks, and
/// theirs: a theorem's certificate may cite lemmas its claim does not `use` (the convex hull,
/// the affine invariance), decided here as [`explained`] decides a claim's own.
fn with_certificate_lemmas(
    files: &[claims::ClaimFile],
    o: &ClaimOutcome,
    mut cited: Vec<ClaimOutcome>,
) -> Result<Vec<ClaimOutcome>> {
    let mut wanted = certify::cited_lemmas(&certify::certificate(o));
    while let Some(id) = wanted.pop() {
        if id == o.id || cited.iter().any(|c| c.id == id) {
            continue;
        }
        for f in files {
            for c in f.claim.iter().filter(|c| c.id == id) {
                let (checked, range_bound, more) = explained(files, c).map_err(|e| in_claim(f, &id, e))?;
                let lemma = outcome(f, c, checked, range_bound);
                wanted.extend(certify::cited_lemmas(&certify::certificate(&lemma)));
                cited.extend(
                    more.into_iter()
                        .filter(|m| !cited.iter().any(|c| c.id == m.id))
                        .collect::<Vec<_>>(),
                );
                cited.push(lemma);
            }
        }
    }
    Ok(cited)
}

/// The proof of claim `id`, searched in claim files already loaded; see [`explain`].
pub fn explain_files(files: &[claims::ClaimFile], id: &str, style: ExplainStyle) -> Result<String> {
    for f in files {
        if let Some(c) = f.claim.iter().find(|c| c.id == id) {
            let (checked, range_bound, cited) = explained(files, c).map_err(|e| in_claim(f, id, e))?;
            let text = report::explain_text(f, c, &checked, range_bound.as_deref(), style);
            if style == ExplainStyle::Latex {
                // a LaTeX fragment for a handout: the certificate's tables are for the screen
                return Ok(text);
            }
            let brief = style == ExplainStyle::Short;
            let o = outcome(f, c, checked, range_bound);
            let cited = with_certificate_lemmas(files, &o, cited)?;
            let certificate = readable_among(&o, &cited).to_text(brief);
            return Ok(format!("{}\n\n{certificate}", text.trim_end()));
        }
    }
    let ids = files.iter().flat_map(|f| f.claim.iter().map(|c| c.id.as_str()));
    let near = names::nearest(id, ids);
    Err(Error::Domain(if near.is_empty() {
        format!("no claim with id '{id}' in the given claim files")
    } else {
        format!(
            "no claim with id '{id}' in the given claim files (did you mean {}?)",
            near.join(", ")
        )
    }))
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Every claim of the texts is elaborated once ([`context::Ctx::new`]): its check on every
    /// route, the note on its scope and its lemma all take that one context (the cases of a
    /// claim are derived from it without parsing its definitions again). The claims are
    /// decided here one after the other on this thread, in the rounds `prove` uses.
    #[test]
    fn every_claim_of_the_texts_is_elaborated_once() {
        let files = claims::builtin_files().unwrap();
        let jobs: Vec<Job<'_>> = files.iter().flat_map(|f| f.claim.iter().map(move |c| (f, c))).collect();
        let mut decided: Vec<Option<Decided>> = (0..jobs.len()).map(|_| None).collect();
        let (mut counted, mut in_range, mut cited) = (0, 0, 0);
        for round in citation_rounds(&jobs) {
            for (index, uses) in round {
                let claim = jobs[index].1;
                let lemmas = uses.and_then(|uses| lemmas_of(&jobs, &decided, &uses));
                cited += usize::from(lemmas.as_ref().is_ok_and(|l| !l.is_empty()));
                let before = context::elaborations();
                let d = decide_one(claim, &lemmas, false, true).unwrap_or_else(|e| panic!("{}: {e}", claim.id));
                let n = context::elaborations() - before;
                assert_eq!(n, 1, "claim {} is elaborated {n} times", claim.id);
                in_range += usize::from(d.range_bound.is_some());
                decided[index] = Some(d);
                counted += 1;
            }
        }
        assert_eq!(counted, jobs.len());
        // The routes that derive contexts were taken: notes on the scope, lemmas cited.
        assert!(
            in_range > 10 && cited > 0,
            "{in_range} notes, {cited} claims citing lemmas"
        );
    }
}
