//! Certificates as files (`docs/certificates.md`, `docs/certificate.schema.json`): each
//! claim's verdict written as JSON with the data the kernel checked, and such files re-checked
//! by the kernel alone, with no claim file and no search.
//!
//! Reading a file (JSON, the goal's expression text) is elaboration, trusted like the claim
//! parser; the obligations are decided by `kernel::certificate`.

use super::kernel;
use super::kernel::certificate::{Data, Equality, Param, Refutation};
use super::kernel::checked::{Method, Verdict};
use super::kernel::expr::Expr;
use super::parse::parse;
use super::report::{ClaimOutcome, Report};
use crate::error::{Error, Result};
use num_rational::BigRational;
use num_traits::ToPrimitive;
use serde_json::{json, Map, Value as Json};
use std::collections::BTreeMap;
use std::io::Write;
use std::path::{Path, PathBuf};
use std::str::FromStr;

mod computation;
mod convergence;
mod expansion;
mod hyper;
mod layout;
mod links;
mod nonneg;
mod polygon;
mod rows;
mod sampled;

use rows::Sampling;
use sampled::{read_goal, recheck_fails, recheck_proof};
mod sqrt;

/// The `format` field of every certificate.
pub const FORMAT: &str = "casteljau-certificate";
/// The format's version.
pub const VERSION: u64 = 1;
/// Largest certificate file `check` reads.
pub const MAX_FILE_BYTES: u64 = 4 << 20;
/// Most certificate files `check` reads from one directory.
pub const MAX_FILES: usize = 10_000;

/// Whether a re-checkable goal may call `name`: a built-in function that needs no claim
/// object (a `match`: written-out sides call `B` many times).
fn builtin(name: &str) -> bool {
    matches!(
        name,
        "B" | "C"
            | "binom"
            | "dot"
            | "comp"
            | "det"
            | "inv"
            | "transpose"
            | "rows"
            | "cols"
            | "integral"
            | "__dB"
            | "__dpow"
            | "delta"
    )
}

/// The method's name in a certificate.
fn method_name(m: Method) -> &'static str {
    match m {
        Method::Sampling { .. } => "sampling",
        Method::Evaluation => "evaluation",
        Method::Expansion => "expansion",
        Method::Pieces => "pieces",
        Method::Wz => "wz",
        Method::Telescoping => "telescoping",
        Method::StatedRecurrence => "stated_recurrence",
        Method::Induction => "induction",
        Method::Bernstein => "bernstein",
        Method::Beta => "beta",
        Method::Computation => "computation",
    }
}

// ---------------------------------------------------------------------------------------
// Writing

/// The symbols of equalities, with their sorts; an error if a name has both.
fn symbols(eqs: &[&Equality]) -> std::result::Result<BTreeMap<String, &'static str>, String> {
    let mut out: BTreeMap<String, &'static str> = BTreeMap::new();
    for eq in eqs {
        let names = eq.ints.keys().map(|k| (k, "integer"));
        let points = eq.control_points.iter().map(|(n, _)| (n, polygon::SORT));
        for (name, sort) in names.chain(eq.params.iter().map(|p| (&p.name, "real"))).chain(points) {
            if *out.entry(name.clone()).or_insert(sort) != sort {
                return Err(format!("'{name}' is both an integer and a real symbol"));
            }
        }
    }
    Ok(out)
}

/// Why a goal's text cannot be re-checked alone (it names a claim object, a control point
/// not among `points`, a name that is not a symbol, a `sqrt` that is not of one square-free
/// integer constant, or does not print back to itself).
fn not_self_contained(text: &str, known: &[String], points: &[&String]) -> Option<String> {
    self_contained(text, known, points).err()
}

/// A goal's text parsed, when it can be re-checked alone (see [`not_self_contained`]).
fn self_contained(text: &str, known: &[String], points: &[&String]) -> std::result::Result<Expr, String> {
    let e = parse(text, known).map_err(|err| format!("'{text}' does not parse back ({err})"))?;
    if e.to_string() != text {
        return Err(format!("'{text}' does not print back to itself"));
    }
    contained(&e, known, points)?;
    Ok(e)
}

/// Why an expression cannot be re-checked alone (a claim object, a control point not among
/// `points`, a name that is not a symbol, a `sqrt` that is not of one square-free integer
/// constant), or the radicand of its `sqrt` (`None`: there is none). Its printed text parses
/// back to it (`tests` of the printer: `expr_tests.rs`).
pub(super) fn contained(e: &Expr, known: &[String], points: &[&String]) -> std::result::Result<Option<i64>, String> {
    let mut bad: Option<String> = None;
    e.visit(&mut |x| match x {
        Expr::Index(name, _) if !points.contains(&name) => {
            bad.get_or_insert(format!("the control points {name}[…]"));
        }
        Expr::Call(name, _) if name != "sqrt" && !builtin(name) => {
            bad.get_or_insert(format!("the claim's object {name}(…)"));
        }
        _ => {}
    });
    if bad.is_none() {
        if let Some(v) = e.free_vars().into_iter().find(|v| !known.contains(v)) {
            bad = Some(format!("the claim's object {v}"));
        }
    }
    if let Some(why) = bad {
        return Err(why);
    }
    sqrt::radicand([e])
}

fn rational_entries(values: &[String]) -> bool {
    values.iter().all(|v| rational(v).is_ok())
}

fn ints_json(ints: &BTreeMap<String, i64>) -> Json {
    Json::Object(ints.iter().map(|(k, v)| (k.clone(), json!(v.to_string()))).collect())
}

fn strings(v: &[BigRational]) -> Vec<String> {
    v.iter().map(rational_text).collect()
}

/// `r.to_string()`, formatted from machine words when numerator and denominator fit (most
/// sampled values do; num-bigint's decimal conversion is the slow part of writing them).
fn rational_text(r: &BigRational) -> String {
    match (r.numer().to_i64(), r.denom().to_i64()) {
        (Some(p), Some(1)) => p.to_string(),
        (Some(p), Some(q)) => format!("{p}/{q}"),
        _ => r.to_string(),
    }
}

/// The goal of equalities and its field's radicand (`None`: the rationals), or why it
/// cannot be re-checked alone.
fn goal<'e>(eqs: Vec<&'e Equality>) -> std::result::Result<(Goal<'e>, Option<i64>), String> {
    let syms = symbols(&eqs)?;
    let known: Vec<String> = syms.keys().cloned().collect();
    let mut radicand = None;
    for eq in &eqs {
        if eq.polygons != eq.control_points.len() + 1 {
            return Err("the basis polygons are not the zero and the unit ones".into());
        }
        let points: Vec<&String> = eq.control_points.iter().map(|(n, _)| n).collect();
        for side in [&eq.lhs, &eq.rhs] {
            let d = contained(side, &known, &points).map_err(|why| format!("the goal uses {why}"))?;
            radicand = sqrt::same_field(radicand, d)?;
        }
    }
    Ok((Goal { symbols: syms, eqs }, radicand))
}

/// A goal of equalities as it is written: `{"equalities": […], "relation": "=", "symbols":
/// […]}`, each side printed straight into the file (a side written out can be long).
struct Goal<'e> {
    symbols: BTreeMap<String, &'static str>,
    eqs: Vec<&'e Equality>,
}

impl serde::Serialize for Goal<'_> {
    fn serialize<S: serde::Serializer>(&self, s: S) -> std::result::Result<S::Ok, S::Error> {
        use serde::ser::{SerializeMap, SerializeSeq};
        struct Side<'a>(&'a Expr);
        impl serde::Serialize for Side<'_> {
            fn serialize<S: serde::Serializer>(&self, s: S) -> std::result::Result<S::Ok, S::Error> {
                s.collect_str(self.0)
            }
        }
        struct Eq<'a>(&'a Equality);
        impl serde::Serialize for Eq<'_> {
            fn serialize<S: serde::Serializer>(&self, s: S) -> std::result::Result<S::Ok, S::Error> {
                let eq = self.0;
                let points = !eq.control_points.is_empty();
                let mut m = s.serialize_map(Some(3 + usize::from(points)))?;
                if points {
                    m.serialize_entry("control_points", &polygon::points_json(&eq.control_points))?;
                }
                m.serialize_entry("ints", &ints_json(&eq.ints))?;
                m.serialize_entry("lhs", &Side(&eq.lhs))?;
                m.serialize_entry("rhs", &Side(&eq.rhs))?;
                m.end()
            }
        }
        struct Eqs<'a>(&'a [&'a Equality]);
        impl serde::Serialize for Eqs<'_> {
            fn serialize<S: serde::Serializer>(&self, s: S) -> std::result::Result<S::Ok, S::Error> {
                let mut seq = s.serialize_seq(Some(self.0.len()))?;
                for eq in self.0 {
                    seq.serialize_element(&Eq(eq))?;
                }
                seq.end()
            }
        }
        let symbols: Vec<Json> = self
            .symbols
            .iter()
            .map(|(n, s)| json!({"name": n, "sort": s}))
            .collect();
        let mut m = s.serialize_map(Some(3))?;
        m.serialize_entry("equalities", &Eqs(&self.eqs))?;
        m.serialize_entry("relation", "=")?;
        m.serialize_entry("symbols", &symbols)?;
        m.end()
    }
}

fn refutation_json(r: &Refutation) -> Json {
    let at: Map<String, Json> = r.at.iter().map(|(k, v)| (k.clone(), json!(v.to_string()))).collect();
    let mut out = json!({"equality": 0, "at": at, "lhs": r.lhs, "rhs": r.rhs});
    if !r.equality.control_points.is_empty() {
        out["polygon"] = json!(r.basis);
    }
    if let Some((_, value)) = &r.premise {
        out["premise"] = json!(value);
    }
    out
}

/// A sampled proof's `goal` and `sampling` data, serialized as they are written (the others'
/// data is in the certificate's map).
type Direct<'o> = Option<(Goal<'o>, Sampling<'o>)>;

/// The data part of a certificate: `check: kernel` with the goal and the method's data, or
/// `check: none` with the reason.
fn data_fields<'o>(o: &'o ClaimOutcome, out: &mut Map<String, Json>) -> std::result::Result<Direct<'o>, String> {
    let method = o.method.map_or("a check", method_name);
    match (&o.data, o.verdict) {
        (_, Verdict::Error) => Err("not decided (an error verdict): nothing to re-check".into()),
        (_, Verdict::Verified) => convergence::fields(&o.computed, out).map(|()| None),
        (Data::Sampled(eqs), Verdict::Proved | Verdict::ProvedInRange) => {
            // A range variable written into the expressions (not an integer symbol) leaves
            // a checker no way to see that the goal covers the range.
            let named = o
                .range
                .iter()
                .flat_map(|r| r.split([',', ';']))
                .filter_map(|p| p.split_once('='));
            for (v, _) in named {
                if eqs.iter().any(|eq| !eq.ints.contains_key(v.trim())) {
                    return Err(format!(
                        "the range's {} is not an integer symbol of every equality",
                        v.trim()
                    ));
                }
            }
            let (goal, radicand) = goal(eqs.iter().collect())?;
            let sampling = Sampling::new(eqs, radicand)?;
            Ok(Some((goal, sampling)))
        }
        (Data::Nonneg(n), Verdict::Proved) => nonneg::fields(n, out).map(|()| None),
        (Data::Symbolic(s), Verdict::Proved) => {
            let (goal, data, lemmas) = hyper::fields(s);
            out.insert("goal".into(), goal);
            out.insert("pieces".into(), data);
            if !lemmas.is_empty() {
                out.insert("lemmas".into(), Json::Array(lemmas));
            }
            Ok(None)
        }
        (Data::Expanded(eqs), Verdict::Proved | Verdict::ProvedInRange) => expansion::fields(eqs, out).map(|()| None),
        (_, Verdict::Proved | Verdict::ProvedInRange) if matches!(o.method, Some(Method::Computation)) => {
            computation::fields(&o.computed, out).map(|()| None)
        }
        (Data::Refuted(r), Verdict::Fails) => {
            let premise_value = r.premise.iter().flat_map(|(_, v)| v);
            if !rational_entries(&r.lhs) || !rational_entries(&r.rhs) || premise_value.clone().any(|v| rational(v).is_err()) {
                return Err("the values are not rational (a square root)".into());
            }
            let mut eq = r.equality.clone();
            // The counterexample's parameters are the goal's real symbols.
            eq.params =
                r.at.iter()
                    .map(|(name, _)| Param {
                        name: name.clone(),
                        degree: 0,
                        lhs_degree: String::new(),
                        rhs_degree: String::new(),
                        points: Vec::new(),
                    })
                    .collect();
            let (goal, radicand) = goal(vec![&eq])?;
            let mut goal = serde_json::to_value(&goal).map_err(|e| e.to_string())?;
            if radicand.is_some() {
                return Err("a counterexample's goal with sqrt: its values are not written in this version (not done)".into());
            }
            if let Some((premise, _)) = &r.premise {
                let known: Vec<String> = r.at.iter().map(|(k, _)| k.clone()).collect();
                if let Some(why) = not_self_contained(premise, &known, &[]) {
                    return Err(format!("the premise uses {why}"));
                }
                goal["equalities"][0]["premise"] = json!(premise);
            }
            out.insert("goal".into(), goal);
            out.insert("fails".into(), refutation_json(r));
            Ok(None)
        }
        (_, Verdict::Fails) => Err(format!(
            "the counterexample was found by {method}, whose data this version does not record (not done)"
        )),
        (_, Verdict::Proved) if matches!(o.method, Some(Method::Pieces | Method::Wz)) => Err(format!(
            "method {method}: its goal is written only for an identity whose cited lemmas have written goals, or an inequality whose factors' Bernstein coefficients on the whole interval show it (not done: the others)"
        )),
        _ => Err(format!(
            "method {method}: this version records no data for it (not done)"
        )),
    }
}

/// The certificate of one claim's outcome.
pub fn certificate(o: &ClaimOutcome) -> Json {
    let (mut out, direct) = certificate_parts(o);
    if let Some((goal, sampling)) = direct {
        match (serde_json::to_value(&goal), serde_json::to_value(&sampling)) {
            (Ok(g), Ok(v)) => {
                out.insert("goal".into(), g);
                out.insert("sampling".into(), v);
            }
            // not reached: `Sampling::new` checked every value
            (Err(e), _) | (_, Err(e)) => {
                out.insert("check".into(), json!("none"));
                out.insert("reason".into(), json!(e.to_string()));
            }
        }
    }
    Json::Object(out)
}

/// A certificate's fields, but for a sampled proof's goal and data (serialized as written).
fn certificate_parts(o: &ClaimOutcome) -> (Map<String, Json>, Direct<'_>) {
    let mut out = Map::new();
    out.insert("format".into(), json!(FORMAT));
    out.insert("version".into(), json!(VERSION));
    out.insert("id".into(), json!(o.id));
    out.insert("source".into(), json!(o.source));
    out.insert("statement".into(), json!(o.statement));
    out.insert("verdict".into(), json!(o.verdict.as_str()));
    out.insert("method".into(), json!(o.method.map(method_name)));
    let rests: Vec<&str> = o.rests_on.iter().flatten().map(|t| t.name()).collect();
    out.insert("rests_on".into(), json!(rests));
    out.insert("range".into(), json!(o.range));
    out.insert("summary".into(), json!(o.certificate));
    let mut data = Map::new();
    // The data the kernel recorded, written as it is: `prove --check` and `casteljau check`
    // re-read it (re-reading every file here would cost as much as checking them all).
    match data_fields(o, &mut data) {
        Ok(direct) => {
            out.insert("check".into(), json!("kernel"));
            out.extend(data);
            (out, direct)
        }
        Err(reason) => {
            out.insert("check".into(), json!("none"));
            out.insert("reason".into(), json!(reason));
            (out, None)
        }
    }
}

/// A certificate as it is written: its fields in sorted order (as a `Value` map prints them),
/// with a sampled proof's `goal` and `sampling` in their places.
struct Written<'a>(Map<String, Json>, Direct<'a>);

impl serde::Serialize for Written<'_> {
    fn serialize<S: serde::Serializer>(&self, s: S) -> std::result::Result<S::Ok, S::Error> {
        use serde::ser::SerializeMap;
        enum Entry<'b> {
            Goal(&'b Goal<'b>),
            Sampling(&'b Sampling<'b>),
        }
        impl serde::Serialize for Entry<'_> {
            fn serialize<S: serde::Serializer>(&self, s: S) -> std::result::Result<S::Ok, S::Error> {
                match self {
                    Entry::Goal(g) => g.serialize(s),
                    Entry::Sampling(d) => d.serialize(s),
                }
            }
        }
        // in key order
        let direct = match &self.1 {
            Some((goal, sampling)) => vec![("goal", Entry::Goal(goal)), ("sampling", Entry::Sampling(sampling))],
            None => Vec::new(),
        };
        let mut m = s.serialize_map(Some(self.0.len() + direct.len()))?;
        let mut direct = direct.into_iter().peekable();
        for (k, v) in &self.0 {
            while let Some((key, entry)) = direct.next_if(|(key, _)| k.as_str() > *key) {
                m.serialize_entry(key, &entry)?;
            }
            m.serialize_entry(k, v)?;
        }
        for (key, entry) in direct {
            m.serialize_entry(key, &entry)?;
        }
        m.end()
    }
}

/// A certificate's text as its file holds it ([`layout`]), with the final newline.
pub(super) fn file_text(cert: &Json) -> String {
    let mut out = Vec::new();
    let mut json = serde_json::Serializer::with_formatter(&mut out, layout::Layout::new());
    // A `Value` of strings, numbers, lists and maps serializes into memory without error.
    let _ = serde::Serialize::serialize(cert, &mut json);
    out.push(b'\n');
    String::from_utf8_lossy(&out).into_owned()
}

/// A file name for a claim id: its letters, digits, `-`, `_` and `.`, others as `_`.
pub(super) fn file_name(id: &str) -> String {
    let safe: String = id
        .chars()
        .map(|c| {
            if c.is_ascii_alphanumeric() || "-_.".contains(c) {
                c
            } else {
                '_'
            }
        })
        .collect();
    format!("{safe}.json")
}

/// Writes one certificate per claim of `report` into `dir` (created if missing), as
/// `<id>.json`; returns how many. Two claims whose ids give the same file name are an error.
pub fn write_certificates(report: &Report, dir: &Path) -> Result<usize> {
    let io = |e: std::io::Error| Error::Parse(format!("cannot write certificates to {}: {e}", dir.display()));
    std::fs::create_dir_all(dir).map_err(io)?;
    let mut seen = std::collections::BTreeSet::new();
    for o in &report.outcomes {
        let name = file_name(&o.id);
        if !seen.insert(name.clone()) {
            return Err(Error::Parse(format!(
                "two claims write the certificate {name} (ids must be unique across the claim files)"
            )));
        }
        // Written as it serializes: no copy of the text (a certificate can be megabytes).
        // A larger buffer than the default 8 KiB: a sampled file is written in fewer system calls.
        let mut file = std::io::BufWriter::with_capacity(1 << 16, std::fs::File::create(dir.join(name)).map_err(io)?);
        let (fields, direct) = certificate_parts(o);
        let mut json = serde_json::Serializer::with_formatter(&mut file, layout::Layout::new());
        serde::Serialize::serialize(&Written(fields, direct), &mut json).map_err(|e| io(e.into()))?;
        file.write_all(b"\n").and_then(|()| file.flush()).map_err(io)?;
    }
    Ok(report.outcomes.len())
}

// ---------------------------------------------------------------------------------------
// Re-checking

/// What re-checking one certificate found.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum Recheck {
    /// The kernel re-checked the data: it proves (or refutes) the goal. What was checked.
    Accepted(String),
    /// The file carries no data to re-check (`check: none`); its reason.
    NotChecked(String),
    /// The data does not establish the verdict: the first failing obligation.
    Refused(String),
}

type Res<T> = std::result::Result<T, String>;

fn field<'a>(v: &'a Json, key: &str, at: &str) -> Res<&'a Json> {
    v.get(key).ok_or_else(|| format!("{at}: no field '{key}'"))
}

fn string<'a>(v: &'a Json, key: &str, at: &str) -> Res<&'a str> {
    field(v, key, at)?
        .as_str()
        .ok_or_else(|| format!("{at}.{key}: not a string"))
}

fn array<'a>(v: &'a Json, key: &str, at: &str) -> Res<&'a Vec<Json>> {
    field(v, key, at)?
        .as_array()
        .ok_or_else(|| format!("{at}.{key}: not a list"))
}

/// An exact rational written `p` or `p/q`, reduced, q > 1.
fn rational(text: &str) -> Res<BigRational> {
    if let Some(r) = small_rational_text(text) {
        return Ok(r);
    }
    rational_big(text)
}

/// `rational(text)` when `text` is `p` or `p/q` in lowest terms with both in an `i64` (the
/// common case), without num-bigint's parsing and printing back; `None` sends every other
/// text (bigger numbers, and every text not so written) to [`rational_big`], which decides.
fn small_rational_text(text: &str) -> Option<BigRational> {
    small_parts(text).map(|(p, q)| BigRational::new_raw(p.into(), q.into()))
}

/// `p` and `q` (1 for an integer) of a text [`small_rational_text`] reads.
fn small_parts(text: &str) -> Option<(i64, i64)> {
    // Canonical decimal of an i64: digits with no leading zero, "-" only before a nonzero.
    fn int(s: &str, signed: bool) -> Option<i64> {
        let digits = if signed { s.strip_prefix('-').unwrap_or(s) } else { s };
        let ok = !digits.is_empty()
            && digits.len() <= 18
            && digits.bytes().all(|b| b.is_ascii_digit())
            && (digits == "0" || !digits.starts_with('0'))
            && !(s.starts_with('-') && digits == "0");
        if !ok {
            return None;
        }
        s.parse().ok()
    }
    match text.split_once('/') {
        None => int(text, true).map(|p| (p, 1)),
        Some((p, q)) => {
            let (p, q) = (int(p, true)?, int(q, false)?);
            (q > 1 && num_integer::Integer::gcd(&p, &q) == 1).then_some((p, q))
        }
    }
}

/// Whether [`rational`] reads `text`, without building the number when it is small.
fn is_rational_text(text: &str) -> bool {
    small_parts(text).is_some() || rational_big(text).is_ok()
}

fn rational_big(text: &str) -> Res<BigRational> {
    let r = BigRational::from_str(text).map_err(|_| format!("'{text}' is not an exact rational p/q"))?;
    if r.to_string() != text {
        return Err(format!("'{text}' is not written in lowest terms as p/q"));
    }
    Ok(r)
}

fn rationals(v: &Json, at: &str) -> Res<Vec<BigRational>> {
    let list = v.as_array().ok_or_else(|| format!("{at}: not a list"))?;
    list.iter()
        .enumerate()
        .map(|(i, x)| {
            x.as_str()
                .ok_or_else(|| format!("{at}[{i}]: not a string"))
                .and_then(rational)
                .map_err(|e| format!("{at}[{i}]: {e}"))
        })
        .collect()
}

/// Re-checks a certificate; `known`: the kernel's data it was just written from, if it was.
fn recheck(cert: &Json) -> Res<Option<String>> {
    if string(cert, "format", "certificate")? != FORMAT {
        return Err(format!("format: not '{FORMAT}'"));
    }
    let version = field(cert, "version", "certificate")?.as_u64();
    if version != Some(VERSION) {
        return Err(format!("version: this program reads version {VERSION}"));
    }
    let verdict = string(cert, "verdict", "certificate")?;
    let verdict = Verdict::from_name(verdict).ok_or_else(|| format!("verdict: '{verdict}' is not a verdict"))?;
    match string(cert, "check", "certificate")? {
        "none" => return Ok(None),
        "kernel" => {}
        other => return Err(format!("check: '{other}' is not kernel or none")),
    }
    let range = field(cert, "range", "certificate")?;
    if range.is_null() == (verdict == Verdict::ProvedInRange) {
        return Err("range: given exactly when the verdict is proved_in_range".into());
    }
    let method = field(cert, "method", "certificate")?.as_str().unwrap_or("none");
    if cert.get("pieces").is_some() {
        if verdict != Verdict::Proved {
            return Err("verdict: pieces data proves a goal for every value (proved)".into());
        }
        if nonneg::is_inequality(cert) {
            return nonneg::recheck(cert, method).map(Some);
        }
        return hyper::recheck(cert, method).map(Some);
    }
    match verdict {
        Verdict::Verified if cert.get("convergence").is_some() => return convergence::recheck(cert).map(Some),
        // A computation's facts have no goal: read before the goal is.
        Verdict::Proved | Verdict::ProvedInRange if cert.get("computation").is_some() => {
            return computation::recheck(cert, method).map(Some)
        }
        _ => {}
    }
    let goal = read_goal(cert)?;
    if verdict != Verdict::Fails && goal.premises.iter().any(Option::is_some) {
        return Err("goal: a premise is defined only for a counterexample in this version".into());
    }
    match verdict {
        Verdict::Proved | Verdict::ProvedInRange if cert.get("expansion").is_some() => {
            expansion::recheck(cert, &goal, method).map(Some)
        }
        Verdict::Proved | Verdict::ProvedInRange => recheck_proof(cert, &goal, method).map(Some),
        Verdict::Fails => recheck_fails(cert, &goal).map(Some),
        other => Err(format!("verdict {}: no kernel data is defined for it", other.as_str())),
    }
}

/// Re-checks one certificate's text with the kernel alone: its JSON value and the result, a
/// proof citing lemmas accepted here with their goals assumed.
fn check_alone(text: &str) -> (links::Link, Recheck) {
    let cert: Json = match serde_json::from_str(text) {
        Ok(v) => v,
        Err(e) => return (links::Link::of(None), Recheck::Refused(format!("not JSON: {e}"))),
    };
    let r = match recheck(&cert) {
        Ok(Some(what)) => Recheck::Accepted(what),
        Ok(None) => Recheck::NotChecked(
            cert.get("reason")
                .and_then(Json::as_str)
                .unwrap_or("no reason given")
                .to_string(),
        ),
        Err(obligation) => Recheck::Refused(obligation),
    };
    (links::Link::of(Some(&cert)), r)
}

/// Re-checks certificate texts together with the kernel: each file alone, then the lemmas
/// each cites resolved among them (a file citing a lemma is accepted only when the lemma's
/// file is among `texts`, is accepted and states the goal it assumes; no cycle).
pub fn check_certificate_texts(texts: &[&str]) -> Vec<Recheck> {
    let (links, alone): (Vec<_>, Vec<_>) = texts.iter().map(|t| check_alone(t)).unzip();
    links::resolve(&links, alone)
}

/// The ids of the lemmas a certificate's proof cites (none when its list cannot be read: the
/// re-check then refuses it).
pub(crate) fn cited_lemmas(cert: &Json) -> Vec<String> {
    hyper::lemmas(cert).map_or_else(|_| Vec::new(), |l| l.into_iter().map(|(id, _)| id).collect())
}

/// Re-checks one certificate's text with the kernel alone (a proof citing a lemma is "not
/// re-checked": the lemma's file is not given).
pub fn check_certificate(text: &str) -> Recheck {
    check_certificate_texts(&[text]).remove(0)
}

/// Re-checks certificate files: each path a file, or a directory whose `.json` files are read
/// in name order. An unreadable path, a file over [`MAX_FILE_BYTES`] or a directory over
/// [`MAX_FILES`] files is an error.
pub fn check_certificates(paths: &[PathBuf]) -> Result<Vec<(PathBuf, Recheck)>> {
    let io = |p: &Path, e: std::io::Error| Error::Parse(format!("cannot read {}: {e}", p.display()));
    let mut files = Vec::new();
    for p in paths {
        if p.is_dir() {
            let mut found: Vec<PathBuf> = std::fs::read_dir(p)
                .map_err(|e| io(p, e))?
                .filter_map(|e| e.ok().map(|e| e.path()))
                .filter(|f| f.extension().is_some_and(|x| x == "json"))
                .take(MAX_FILES + 1)
                .collect();
            if found.len() > MAX_FILES {
                return Err(Error::TooLarge {
                    what: "certificate directory",
                    value: format!("more than {MAX_FILES} files in {}", p.display()),
                    limit: format!("{MAX_FILES} files"),
                });
            }
            found.sort();
            files.extend(found);
        } else {
            files.push(p.clone());
        }
    }
    let (mut links, mut alone) = (Vec::with_capacity(files.len()), Vec::with_capacity(files.len()));
    for f in &files {
        let size = std::fs::metadata(f).map_err(|e| io(f, e))?.len();
        if size > MAX_FILE_BYTES {
            return Err(Error::TooLarge {
                what: "certificate file",
                value: format!("{} bytes in {}", size, f.display()),
                limit: format!("{MAX_FILE_BYTES} bytes"),
            });
        }
        let (link, r) = check_alone(&std::fs::read_to_string(f).map_err(|e| io(f, e))?);
        links.push(link);
        alone.push(r);
    }
    Ok(files.into_iter().zip(links::resolve(&links, alone)).collect())
}
