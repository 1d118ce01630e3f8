//! The claim file format (TOML), documented for authors in `proofs/README.md`.
//!
//! A file holds an optional `[text]` table and a list of `[[claim]]` tables. Every claim has
//! `id`, `source`, `statement`, `kind`, optional `expect` ("proved" by default, "verified",
//! "fails") and, for the correction of a misprint, `corrects = "<id>"`. The remaining fields
//! depend on the kind; unknown fields are errors, so a typo never silently drops data.

use super::Verdict;
use crate::error::{Error, Result};
use serde::Deserialize;
use std::collections::BTreeMap;
use std::path::{Path, PathBuf};

/// One claim file.
#[derive(Clone, Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct ClaimFile {
    /// The text the claims come from.
    pub text: Option<TextInfo>,
    /// The claims, in order.
    #[serde(default)]
    pub claim: Vec<Claim>,
    /// Where it was loaded from (filled in by [`load_file`]).
    #[serde(skip)]
    pub path: PathBuf,
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

/// One claim (fields by kind; see `proofs/README.md`).
#[derive(Clone, Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Claim {
    /// Unique id.
    pub id: String,
    /// Text file and printed label.
    pub source: String,
    /// The statement as printed.
    pub statement: String,
    /// The kind of check.
    pub kind: String,
    /// The expected verdict ("proved" when absent).
    pub expect: Option<String>,
    /// The id of the misprinted claim this one corrects.
    pub corrects: Option<String>,
    /// A remark shown in the report.
    pub note: Option<String>,

    /// identity: left side.
    pub lhs: Option<String>,
    /// identity: right side.
    pub rhs: Option<String>,
    /// identity: a chain `a = b = c = …` (consecutive members are claimed equal).
    pub chain: Option<Vec<String>>,
    /// implicit / implies / conic: an equation `A = B` (or an expression meaning `= 0`).
    pub equation: Option<String>,
    /// implicit: the curve, a tuple expression in `t` (or a curve call like `x(t)`).
    pub on: Option<String>,
    /// implicit: the coordinate names the equation uses (default `x, y, z`).
    pub coords: Option<Vec<String>>,
    /// implies: the premise (an expression meaning `= 0`, or `A = B`).
    pub premise: Option<String>,
    /// implies: the factor with `conclusion = factor · premise` identically.
    pub factor: Option<String>,
    /// bezier_points: the curve in the power basis, a tuple expression in `param`.
    pub power: Option<String>,
    /// bezier_points: its parameter name (default `u`).
    pub param: Option<String>,
    /// bezier_points: the parameter interval `[a, b]`.
    pub interval: Option<[Number; 2]>,
    /// bezier_points: the claimed Bézier points.
    pub points: Option<Vec<Vec<Number>>>,
    /// conic_type / weight_type: the printed type ("ellipse", "parabola", "hyperbola").
    pub conic: Option<String>,

    /// Continuous parameters (default: the one-letter names t, s, u, v that occur).
    pub vars: Option<Vec<String>>,
    /// Integer ranges `"n = 0..=10"`, in order.
    #[serde(rename = "for")]
    pub ranges: Option<Vec<String>>,
    /// Definitions `"f(i) = …"`, in order (later ones may use earlier ones).
    #[serde(rename = "let")]
    pub defs: Option<Vec<String>>,
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

    /// theorem / convergence: which one.
    pub theorem: Option<String>,
    /// theorem: the degrees checked, `"0..=10"`.
    pub degrees: Option<String>,
    /// convergence: the largest number of elevation steps.
    pub steps: Option<usize>,

    /// identity with open ranges: WZ certificates `R`, one per sum with a symbolic bound
    /// (innermost first); a single string or a list.
    pub certificate: Option<Certificates>,
    /// inequality: `">="` (default) or `">"`.
    pub relation: Option<String>,

    /// fit: the printed (or stated) tangent length `k` of text 004's cubic, if any.
    pub k: Option<Number>,
    /// fit: the printed tangent length `l`, if any.
    pub l: Option<Number>,
    /// fit: the printed `δ²`, if any.
    pub delta2: Option<Number>,
}

/// One certificate or a list of them.
#[derive(Clone, Debug, Deserialize)]
#[serde(untagged)]
pub enum Certificates {
    /// One certificate.
    One(String),
    /// Several, in order.
    Many(Vec<String>),
}

impl Claim {
    /// The certificates, in order.
    pub fn certificates(&self) -> Vec<String> {
        match &self.certificate {
            None => Vec::new(),
            Some(Certificates::One(s)) => vec![s.clone()],
            Some(Certificates::Many(v)) => v.clone(),
        }
    }

    /// Whether a range is open (`n = 0..`): the claim is then proved for every value or not at
    /// all, never in a range.
    pub fn for_every(&self) -> bool {
        super::symbolic::is_for_every(self)
    }

    /// Whether the claim is checked over finite integer ranges (`for`, or a theorem's
    /// `degrees`): then the strongest verdict it can get is `proved_in_range`.
    pub fn has_ranges(&self) -> bool {
        self.ranges.as_ref().is_some_and(|r| !r.is_empty()) || self.kind == "theorem"
    }

    /// The expected verdict: `expect`, or by default the strongest verdict the claim can get
    /// (`proved_in_range` for a claim over ranges, `proved` otherwise).
    pub fn expected(&self) -> Result<Verdict> {
        match self.expect.as_deref() {
            None if self.has_ranges() && !self.for_every() => Ok(Verdict::ProvedInRange),
            None | Some("proved") => Ok(Verdict::Proved),
            Some("proved_in_range") => Ok(Verdict::ProvedInRange),
            Some("verified") => Ok(Verdict::Verified),
            Some("fails") => Ok(Verdict::Fails),
            Some(other) => Err(Error::Parse(format!(
                "claim {}: expect must be \"proved\", \"proved_in_range\", \"verified\" or \"fails\", not \"{other}\"",
                self.id
            ))),
        }
    }

    /// The multi-letter names the claim declares (kept whole by the parser).
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
        for d in self.defs.iter().flatten() {
            if let Some((head, _)) = d.split_once('=') {
                let name = head.split('(').next().unwrap_or("").trim();
                out.push(name.to_string());
            }
        }
        out
    }

    /// A required text field, or a clear error.
    pub fn need<'a>(&self, field: &'a Option<String>, name: &str) -> Result<&'a str> {
        field.as_deref().ok_or_else(|| {
            Error::Parse(format!(
                "claim {} (kind {}) needs the field '{name}'",
                self.id, self.kind
            ))
        })
    }
}

/// Parses one claim file's text.
pub fn parse_file(text: &str, path: &Path) -> Result<ClaimFile> {
    let mut f: ClaimFile =
        toml::from_str(text).map_err(|e| Error::Parse(format!("{}: {}", path.display(), e.to_string().trim())))?;
    f.path = path.to_path_buf();
    if f.claim.is_empty() {
        return Err(Error::Parse(format!(
            "{}: no claims (a claim file lists [[claim]] tables; see proofs/README.md)",
            path.display()
        )));
    }
    let mut seen = std::collections::BTreeSet::new();
    for c in &f.claim {
        if !seen.insert(c.id.clone()) {
            return Err(Error::Parse(format!(
                "{}: duplicate claim id '{}'",
                path.display(),
                c.id
            )));
        }
        c.expected()?;
    }
    for c in &f.claim {
        if let Some(target) = &c.corrects {
            if !seen.contains(target) {
                return Err(Error::Parse(format!(
                    "{}: claim {} corrects '{target}', which is not in the file",
                    path.display(),
                    c.id
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
        .map(|(path, text)| parse_file(text, Path::new(path)))
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
