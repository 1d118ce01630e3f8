//! The claim file format (TOML), documented for authors in `proofs/README.md`.
//!
//! A file holds an optional `[text]` table and a list of `[[claim]]` tables. Every claim has
//! `id`, `source`, `statement`, `kind`, optional `expect` ("proved" by default, "verified",
//! "fails") and, for the correction of a misprint, `corrects = "<id>"`. The remaining fields
//! depend on the kind; unknown fields are errors, so a typo never silently drops data.

use super::claim_syntax::{field_line, read, FieldError};
use super::kernel::checked::Verdict;
use crate::error::{Error, Result};
use crate::figure::FigureKind;
use serde::Deserialize;
use std::collections::BTreeMap;
use std::path::{Path, PathBuf};

mod kind;
pub use kind::{
    BezierPoints, ConicType, Convergence, Fit, Identity, Implicit, Implies, Inequality, Kind, Relation, Sides, Theorem,
    Vanishes, WeightType, KINDS,
};

/// One claim file.
#[derive(Clone, Debug)]
pub struct ClaimFile {
    /// The text the claims come from.
    pub text: Option<TextInfo>,
    /// The claims, in order.
    pub claim: Vec<Claim>,
    /// Where it was loaded from (for a built-in file, its path in the repository).
    pub path: PathBuf,
    /// Built into the program (the texts' claims), not read from `path`.
    pub builtin: bool,
}

impl ClaimFile {
    /// Where its claims come from, for people: the path read, or that it is built in.
    pub fn origin(&self) -> String {
        match (self.builtin, self.path.file_name()) {
            (true, Some(name)) => format!("built into casteljau: {}", name.to_string_lossy()),
            _ => self.path.display().to_string(),
        }
    }
}

/// The `[text]` table.
#[derive(Clone, Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct TextInfo {
    /// The text file name, e.g. `000_ef6a3958c7d702f5.txt`.
    pub file: String,
    /// A short title.
    pub title: Option<String>,
}

/// A number written in a claim file: an integer or an exact expression string ("4/3", "2*sqrt(2)").
#[derive(Clone, Debug, Deserialize)]
#[serde(untagged)]
pub enum Number {
    /// An integer.
    Int(i64),
    /// An expression.
    Text(String),
    /// A float: refused (write it as a string to keep it exact).
    Float(f64),
}

impl Number {
    /// The expression text.
    pub fn text(&self) -> Result<String> {
        match self {
            Number::Int(n) => Ok(n.to_string()),
            Number::Text(s) => Ok(s.clone()),
            Number::Float(x) => Err(Error::Parse(format!(
                "the float {x} is not exact: write it as a string, e.g. \"0.25\" or \"1/4\""
            ))),
        }
    }
}

/// A polynomial or rational Bézier curve given by its control points (and weights).
#[derive(Clone, Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct CurveSpec {
    /// Control points, each a list of coordinates.
    pub points: Vec<Vec<Number>>,
    /// Weights (a rational curve) or none (a polynomial curve).
    pub weights: Option<Vec<Number>>,
}

/// A tensor-product Bézier surface given by its net `net[i][j]` = `b_{i,j}`.
#[derive(Clone, Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct SurfaceSpec {
    /// The control net, rows `i = 0..=m`, each with `j = 0..=n` points.
    pub net: Vec<Vec<Vec<Number>>>,
}

/// A symbolic control polygon `b_0..b_n` (`degree` names an integer range variable or is a number).
#[derive(Clone, Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct PolygonSpec {
    /// Its name in expressions (`b[j]`, `b(t)`, `b(i, r, t)`, `b'(t)`).
    pub name: String,
    /// The degree, an integer expression (`"n"`, `"3"`).
    pub degree: String,
}

/// A symbolic control net `b_{i,j}` of degree `(m, n)`.
#[derive(Clone, Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct NetSpec {
    /// Its name in expressions (`b[i, j]`, `b(u, v)`).
    pub name: String,
    /// The degrees `[m, n]`, integer expressions.
    pub degree: [String; 2],
}

/// An integer range of a claim, `n = 0..=10` or open `n = 0..`, parsed once when the claim
/// file is read; its bounds are integer expressions of earlier range variables.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct IntRange {
    /// The variable.
    pub var: String,
    /// The least value, an integer expression (`0`, `j`, `n-k`).
    pub from: String,
    /// The largest value, or `None` for an open range (every value from `from` on).
    pub to: Option<String>,
}

impl IntRange {
    /// Parses `n = 0..=10` or `n = 0..`.
    pub fn parse(text: &str) -> Result<Self> {
        let bad = || Error::Parse(format!("a range is written 'n = 0..=10' or 'n = 0..', not '{text}'"));
        let (var, rest) = text.split_once('=').ok_or_else(bad)?;
        let var = var.trim().to_string();
        if var.is_empty() || !var.chars().all(|c| c.is_alphanumeric() || c == '_') {
            return Err(bad());
        }
        let (from, to) = match rest.split_once("..=") {
            Some((a, b)) => (a.trim(), Some(b.trim().to_string())),
            None => (rest.trim().strip_suffix("..").ok_or_else(bad)?.trim(), None),
        };
        if from.is_empty() || to.as_deref() == Some("") {
            return Err(bad());
        }
        Ok(IntRange {
            var,
            from: from.to_string(),
            to,
        })
    }

    /// Whether the range is open (`n = 0..`).
    pub fn is_open(&self) -> bool {
        self.to.is_none()
    }
}

impl std::fmt::Display for IntRange {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match &self.to {
            Some(to) => write!(f, "{} = {}..={to}", self.var, self.from),
            None => write!(f, "{} = {}..", self.var, self.from),
        }
    }
}

impl<'de> Deserialize<'de> for IntRange {
    fn deserialize<D: serde::Deserializer<'de>>(d: D) -> std::result::Result<Self, D::Error> {
        let text = String::deserialize(d)?;
        IntRange::parse(&text).map_err(serde::de::Error::custom)
    }
}

/// What a claim declares for its expressions: parameters, integer ranges, definitions and
/// objects. Each kind takes the declarations listed by [`Kind::declares`]; any other is an error.
#[derive(Clone, Debug, Default, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Decls {
    /// Continuous parameters (default: the one-letter names t, s, u, v that occur).
    pub vars: Option<Vec<String>>,
    /// Integer ranges, in order (later bounds may use earlier variables).
    #[serde(rename = "for", default)]
    pub ranges: Vec<IntRange>,
    /// Definitions `"f(i) = …"`, in order (later ones may use earlier ones).
    #[serde(rename = "let", default)]
    pub defs: Vec<String>,
    /// A symbolic control polygon (identities affine in it are checked on a basis).
    pub polygon: Option<PolygonSpec>,
    /// A symbolic control net.
    pub net: Option<NetSpec>,
    /// Scalar unknowns for symbolic expansion.
    pub symbols: Option<Vec<String>>,
    /// Vector unknowns for symbolic expansion: name → dimension.
    pub vectors: Option<BTreeMap<String, usize>>,
    /// Concrete curves, by name.
    pub curves: Option<BTreeMap<String, CurveSpec>>,
    /// Concrete surfaces, by name.
    pub surfaces: Option<BTreeMap<String, SurfaceSpec>>,
}

/// The declaration fields, by their names in the file.
const DECLARATIONS: [&str; 9] = [
    "vars", "for", "let", "polygon", "net", "symbols", "vectors", "curves", "surfaces",
];

impl Decls {
    /// Whether a range is open (`n = 0..`): the claim is then proved for every value or not at
    /// all, never in a range.
    pub fn for_every(&self) -> bool {
        self.ranges.iter().any(IntRange::is_open)
    }

    /// Whether the claim is decided by symbolic expansion (it declares symbols or vectors).
    pub fn symbolic(&self) -> bool {
        self.symbols.is_some() || self.vectors.is_some()
    }

    /// The multi-letter names declared (kept whole by the parser).
    pub fn known_names(&self) -> Vec<String> {
        let mut out: Vec<String> = Vec::new();
        if let Some(p) = &self.polygon {
            out.push(p.name.clone());
        }
        if let Some(n) = &self.net {
            out.push(n.name.clone());
        }
        out.extend(self.symbols.iter().flatten().cloned());
        out.extend(self.vectors.iter().flat_map(|v| v.keys().cloned()));
        out.extend(self.curves.iter().flat_map(|c| c.keys().cloned()));
        out.extend(self.surfaces.iter().flat_map(|c| c.keys().cloned()));
        out.extend(self.vars.iter().flatten().cloned());
        out.extend(self.defs.iter().filter_map(|d| definition_name(d)));
        out
    }

    /// Every declared name with what declares it, in declaration order.
    pub fn declared(&self) -> Vec<(String, &'static str)> {
        let mut out: Vec<(String, &str)> = Vec::new();
        if let Some(p) = &self.polygon {
            out.push((p.name.clone(), "polygon"));
        }
        if let Some(n) = &self.net {
            out.push((n.name.clone(), "net"));
        }
        out.extend(self.symbols.iter().flatten().map(|s| (s.clone(), "symbol")));
        out.extend(
            self.vectors
                .iter()
                .flat_map(|v| v.keys().map(|k| (k.clone(), "vector"))),
        );
        out.extend(self.curves.iter().flat_map(|v| v.keys().map(|k| (k.clone(), "curve"))));
        out.extend(
            self.surfaces
                .iter()
                .flat_map(|v| v.keys().map(|k| (k.clone(), "surface"))),
        );
        out.extend(self.vars.iter().flatten().map(|s| (s.clone(), "parameter")));
        out.extend(self.ranges.iter().map(|r| (r.var.clone(), "range variable")));
        out.extend(
            self.defs
                .iter()
                .filter_map(|d| definition_name(d))
                .map(|n| (n, "definition")),
        );
        out
    }
}

/// The ranges with each open one closed after `extra` values past its first.
pub(crate) fn close_ranges(ranges: &[IntRange], extra: i64) -> Vec<IntRange> {
    ranges
        .iter()
        .map(|r| IntRange {
            to: Some(r.to.clone().unwrap_or_else(|| format!("({}) + {extra}", r.from))),
            ..r.clone()
        })
        .collect()
}

/// The name a definition `f(i) = …` defines.
fn definition_name(def: &str) -> Option<String> {
    let (head, _) = def.split_once('=')?;
    Some(head.split('(').next().unwrap_or("").trim().to_string())
}

/// The fields every claim has.
#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct Header {
    id: String,
    source: String,
    statement: String,
    kind: String,
    expect: Option<String>,
    corrects: Option<String>,
    note: Option<String>,
    figure: Option<String>,
    #[serde(default)]
    uses: Vec<String>,
}

const HEADER: [&str; 9] = [
    "id",
    "source",
    "statement",
    "kind",
    "expect",
    "corrects",
    "note",
    "figure",
    "uses",
];

/// One claim: what every claim has, its declarations and what its kind states
/// (see `proofs/README.md`).
#[derive(Clone, Debug)]
pub struct Claim {
    /// Unique id.
    pub id: String,
    /// Text file and printed label.
    pub source: String,
    /// The statement as printed.
    pub statement: String,
    /// The expected verdict, as written (`None`: the strongest the claim can get).
    pub expect: Option<Verdict>,
    /// The id of the misprinted claim this one corrects.
    pub corrects: Option<String>,
    /// A remark shown in the report.
    pub note: Option<String>,
    /// The figure that illustrates a general statement in the report (`figure = "subdivision"`):
    /// one of `casteljau figure`'s kinds, drawn on a text's example.
    pub figure: Option<FigureKind>,
    /// The claims it cites as lemmas (`uses = ["000-9-intermediate"]`): a library object is
    /// replaced by its formula in a proof for every value only through such a proved lemma.
    pub uses: Vec<String>,
    /// What its expressions may use.
    pub decls: Decls,
    /// What it states.
    pub kind: Kind,
}

impl Claim {
    /// Reads one `[[claim]]` table: the header, then the kind's own fields and the declarations
    /// it takes; any other field is an error naming it.
    pub(super) fn from_table(mut table: toml::Table) -> std::result::Result<Self, FieldError> {
        let id = table.get("id").and_then(|v| v.as_str()).map(str::to_string);
        if let Some(id) = &id {
            check_id(id).map_err(|e| FieldError {
                field: Some("id".into()),
                message: e,
            })?;
        }
        let in_claim = |e: FieldError| match &id {
            Some(id) => FieldError {
                message: format!("claim {id}: {}", e.message),
                ..e
            },
            None => e,
        };
        let mut head = toml::Table::new();
        let mut decls = toml::Table::new();
        for key in HEADER {
            if let Some(v) = table.remove(key) {
                head.insert(key.to_string(), v);
            }
        }
        for key in DECLARATIONS {
            if let Some(v) = table.remove(key) {
                decls.insert(key.to_string(), v);
            }
        }
        let head: Header = read(head).map_err(in_claim)?;
        let kind = Kind::from_table(&head.kind, table).map_err(|e| {
            in_claim(FieldError {
                message: format!("kind {}: {}", head.kind, e.message),
                ..e
            })
        })?;
        let allowed = kind.declares();
        if let Some(k) = decls.keys().find(|k| !allowed.contains(&k.as_str())) {
            return Err(in_claim(FieldError::whole(format!(
                "the field '{k}' does not belong to kind {} (its declarations: {})",
                head.kind,
                if allowed.is_empty() {
                    "none".to_string()
                } else {
                    allowed.join(", ")
                }
            ))));
        }
        let decls: Decls = read(decls).map_err(in_claim)?;
        let expect = match head.expect.as_deref() {
            None => None,
            Some(name) if name != "error" && Verdict::from_name(name).is_some() => Verdict::from_name(name),
            Some(other) => {
                return Err(in_claim(FieldError {
                    field: Some("expect".into()),
                    message: format!("expect must be one of the verdicts, not \"{other}\""),
                }))
            }
        };
        let figure = match head.figure.as_deref() {
            None => None,
            Some(name) => Some(name.parse::<FigureKind>().map_err(|_| {
                in_claim(FieldError {
                    field: Some("figure".into()),
                    message: format!(
                        "figure must be one of {}, not \"{name}\"",
                        FigureKind::ALL.map(|k| k.name()).join(", ")
                    ),
                })
            })?),
        };
        Ok(Claim {
            id: head.id,
            source: head.source,
            statement: head.statement,
            expect,
            corrects: head.corrects,
            note: head.note,
            figure,
            uses: head.uses,
            decls,
            kind,
        })
    }

    /// Whether a range is open (`n = 0..`): the claim is then proved for every value or not at
    /// all, never in a range.
    pub fn for_every(&self) -> bool {
        self.decls.for_every()
    }

    /// Whether the claim is checked over finite integer ranges (`for`, or a theorem's
    /// `degrees`): then the strongest verdict it can get is `proved_in_range`.
    pub fn has_ranges(&self) -> bool {
        !self.decls.ranges.is_empty() || matches!(self.kind, Kind::Theorem(_))
    }

    /// The expected verdict: `expect`, or by default the strongest verdict the claim can get
    /// (`proved_in_range` for a claim over ranges, `proved` otherwise).
    pub fn expected(&self) -> Verdict {
        match self.expect {
            None => Verdict::strongest(self.has_ranges() && !self.for_every()),
            Some(v) => v,
        }
    }
}

/// A claim id names the claim in every report, in links (`#claim-ID`) and on the command line
/// (`--explain ID`): ASCII letters, digits, `-`, `_` and `.` only, so that it prints as itself
/// (no control character can redraw a report line) and its anchor is its own.
fn check_id(id: &str) -> std::result::Result<(), String> {
    let allowed = |c: char| c.is_ascii_alphanumeric() || matches!(c, '-' | '_' | '.');
    if id.is_empty() || !id.chars().all(allowed) {
        return Err(format!(
            "the id \"{}\" may hold only ASCII letters, digits, '-', '_' and '.' (and not be empty)",
            id.escape_debug()
        ));
    }
    Ok(())
}

/// The raw file, before its claims are read by kind.
#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct RawFile {
    text: Option<TextInfo>,
    #[serde(default)]
    claim: Vec<toml::Spanned<toml::Table>>,
}

/// Parses one claim file's text.
pub fn parse_file(text: &str, path: &Path) -> Result<ClaimFile> {
    let raw: RawFile = toml::from_str(text).map_err(|e| {
        let at = e
            .span()
            .map(|s| text[..s.start.min(text.len())].matches('\n').count() + 1);
        // `[claim]` (one table) for `[[claim]]` is the mistake serde words as "expected a sequence"
        let single = toml::from_str::<toml::Table>(text).is_ok_and(|t| t.get("claim").is_some_and(|c| c.is_table()));
        match (single, at) {
            (true, Some(at)) => Error::Parse(format!(
                "{}:{at}: [claim] is a single table; expected: {}",
                path.display(),
                super::claim_syntax::expected("claim").unwrap_or_default()
            )),
            _ => Error::Parse(format!("{}: {}", path.display(), e.to_string().trim())),
        }
    })?;
    if raw.claim.is_empty() {
        return Err(Error::Parse(format!(
            "{}: no claims (a claim file lists [[claim]] tables; see proofs/README.md)",
            path.display()
        )));
    }
    let line = |at: usize| text[..at.min(text.len())].matches('\n').count() + 1;
    let claims = raw
        .claim
        .into_iter()
        .map(|t| {
            let span = t.span();
            Claim::from_table(t.into_inner()).map_err(|e| {
                let at = e
                    .field
                    .as_deref()
                    .and_then(|f| field_line(text, span.start, span.end, f));
                Error::Parse(match at {
                    Some(at) => format!("{}:{at}: {}", path.display(), e.with_syntax()),
                    None => format!(
                        "{}: the claim at line {}: {}",
                        path.display(),
                        line(span.start),
                        e.with_syntax()
                    ),
                })
            })
        })
        .collect::<Result<Vec<_>>>()?;
    let f = ClaimFile {
        text: raw.text,
        claim: claims,
        path: path.to_path_buf(),
        builtin: false,
    };
    let mut seen = std::collections::BTreeSet::new();
    for c in &f.claim {
        if !seen.insert(c.id.clone()) {
            return Err(Error::Parse(format!(
                "{}: duplicate claim id '{}'",
                path.display(),
                c.id
            )));
        }
    }
    for c in &f.claim {
        if let Some(target) = &c.corrects {
            if !seen.contains(target) {
                return Err(Error::Parse(format!(
                    "{}: claim {} corrects '{}', which is not in the file",
                    path.display(),
                    c.id,
                    target.escape_debug()
                )));
            }
        }
    }
    Ok(f)
}

/// Largest claim file accepted, in bytes (checked while reading: a larger file, or an endless
/// one like `/dev/zero`, is refused without being read whole).
pub const MAX_CLAIM_FILE_BYTES: u64 = 1 << 20;

/// Loads one claim file.
pub fn load_file(path: &Path) -> Result<ClaimFile> {
    use std::io::Read as _;
    let cannot = |e: std::io::Error| Error::Domain(format!("cannot read claim file {}: {e}", path.display()));
    let file = std::fs::File::open(path).map_err(cannot)?;
    let mut bytes = Vec::new();
    file.take(MAX_CLAIM_FILE_BYTES + 1)
        .read_to_end(&mut bytes)
        .map_err(cannot)?;
    if bytes.len() as u64 > MAX_CLAIM_FILE_BYTES {
        return Err(Error::TooLarge {
            what: "claim file",
            value: format!("{} (more than {MAX_CLAIM_FILE_BYTES} bytes)", path.display()),
            limit: format!("{MAX_CLAIM_FILE_BYTES} bytes"),
        });
    }
    let text = String::from_utf8(bytes)
        .map_err(|_| Error::Parse(format!("{}: a claim file must be UTF-8 text", path.display())))?;
    parse_file(&text, path)
}

/// The four reference texts' claim files, built into the library (`proofs/` of the
/// repository), so that an installed `casteljau prove` needs no checkout. Each keeps its
/// repository path, so reports and explanations read the same as from `proofs/`.
const BUILTIN: [(&str, &str); 4] = [
    (
        "proofs/000_ef6a3958c7d702f5.toml",
        include_str!("../../proofs/000_ef6a3958c7d702f5.toml"),
    ),
    (
        "proofs/001_d6775559ddbdd5b2.toml",
        include_str!("../../proofs/001_d6775559ddbdd5b2.toml"),
    ),
    (
        "proofs/003_bd67d8bed055bcf9.toml",
        include_str!("../../proofs/003_bd67d8bed055bcf9.toml"),
    ),
    (
        "proofs/004_658c519a4aef48a5.toml",
        include_str!("../../proofs/004_658c519a4aef48a5.toml"),
    ),
];

/// The texts' claim files as built into the library, in name order (the same files as
/// `proofs/` in the repository).
pub fn builtin_files() -> Result<Vec<ClaimFile>> {
    BUILTIN
        .iter()
        .map(|(path, text)| parse_file(text, Path::new(path)).map(|f| ClaimFile { builtin: true, ..f }))
        .collect()
}

/// Loads every `.toml` file given, or found directly in a given directory (sorted by name).
pub fn load_paths(paths: &[PathBuf]) -> Result<Vec<ClaimFile>> {
    let mut files = Vec::new();
    for p in paths {
        if p.is_dir() {
            let mut entries: Vec<PathBuf> = std::fs::read_dir(p)
                .map_err(|e| Error::Domain(format!("cannot read directory {}: {e}", p.display())))?
                .filter_map(|e| e.ok().map(|e| e.path()))
                .filter(|q| q.extension().is_some_and(|x| x == "toml"))
                .collect();
            entries.sort();
            for q in entries {
                files.push(load_file(&q)?);
            }
        } else if p.exists() {
            files.push(load_file(p)?);
        } else {
            return Err(Error::Domain(format!(
                "no such claim file or directory: {}",
                p.display()
            )));
        }
    }
    if files.is_empty() {
        return Err(Error::Domain("no claim files found (expected .toml files)".into()));
    }
    Ok(files)
}

/// An identity claim `1 = 1` with `body` appended (declarations for a test).
#[cfg(test)]
pub(crate) fn test_claim(body: &str) -> Claim {
    parse_file(
        &format!("[[claim]]\nid = \"x\"\nsource = \"s\"\nstatement = \"s\"\nkind = \"identity\"\nlhs = \"1\"\nrhs = \"1\"\n{body}"),
        Path::new("t.toml"),
    )
    .unwrap()
    .claim
    .remove(0)
}
