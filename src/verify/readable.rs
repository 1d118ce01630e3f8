//! A certificate file read back for people (`--explain`, the HTML report): its goal, its
//! method's data as tables and `key: value` lines, and whether the kernel re-checks it.
//!
//! Everything is read from the certificate's JSON value ([`certificate`]), never from the
//! prover's internals, so what a reader sees is what `casteljau check` reads. Two parts have a
//! layout of their own (`sampling`: the degree bounds and the table of exact values; `fails`:
//! the counterexample); every other method's data is laid out generically (an array of
//! objects with the same keys is a table, an object a group of lines), so a method that gains
//! data in a later version is shown without a change here. Long lists are folded with a
//! count; the JSON keeps them whole.

use super::certify::{certificate, check_certificate_texts, cited_lemmas, file_name, file_text, Recheck};
use super::report::ClaimOutcome;
use serde_json::{Map, Value as Json};

/// Rows of a table shown before the rest are folded into a count.
pub const MAX_ROWS: usize = 12;
/// Items of a list (equalities, groups) shown before the rest are folded into a count.
pub const MAX_ITEMS: usize = 6;
/// Values of a list of numbers or strings shown on one line.
const MAX_VALUES: usize = 24;
/// Characters of one value shown (a longer one is cut, saying how much is left out).
const MAX_CHARS: usize = 400;

/// The fields every certificate has (docs/certificates.md); the others are the method's data.
const COMMON: &[&str] = &[
    "format",
    "version",
    "id",
    "source",
    "statement",
    "verdict",
    "method",
    "rests_on",
    "range",
    "summary",
    "check",
    "reason",
    "goal",
];

/// Whether the kernel re-checks the certificate as written.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum Status {
    /// `check: kernel`, and re-reading the file is accepted: what was re-checked.
    Rechecked(String),
    /// Not re-checked: the file's reason (`check: none`), or why re-reading it is refused.
    NotRechecked(String),
}

/// One part of a readable certificate.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum Block {
    /// `key: value` lines.
    Lines(Vec<(String, String)>),
    /// A table: its column heads, the rows shown, and how many rows are folded.
    Table {
        /// The column heads.
        columns: Vec<String>,
        /// The rows shown, each a cell per column.
        rows: Vec<Vec<String>>,
        /// How many rows are folded (left out here, whole in the file).
        more: usize,
    },
    /// A titled group of blocks.
    Group {
        /// What the group holds.
        title: String,
        /// Its blocks.
        blocks: Vec<Block>,
    },
    /// Items folded into a count: how many, and of what ("equalities").
    More(usize, String),
}

/// A certificate as a reader sees it.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Readable {
    /// Whether the kernel re-checks it.
    pub status: Status,
    /// The method named by the file (`sampling`, `wz`, …), if any.
    pub method: Option<String>,
    /// The goal: its symbols and equalities (empty for `check: none`).
    pub goal: Vec<Block>,
    /// The method's data, or the counterexample.
    pub data: Vec<Block>,
    /// The file's name as `prove --certificates DIR` writes it in DIR.
    pub file: String,
    /// The file's text, exactly as `prove --certificates` writes it.
    pub json: String,
}

/// The certificate of a claim's outcome, read back for people.
/// A proof citing lemmas is re-checked alone, so it shows "not re-checked" (see
/// [`readable_among`]).
pub fn readable(o: &ClaimOutcome) -> Readable {
    read_back(&certificate(o), &file_name(&o.id))
}

/// The certificate of a claim's outcome, read back for people and re-checked together with
/// the certificates of the lemmas it cites, and theirs, found by id among `others` (as
/// `casteljau check DIR` re-checks the files `prove --certificates DIR` writes in one run).
pub fn readable_among(o: &ClaimOutcome, others: &[ClaimOutcome]) -> Readable {
    let cert = certificate(o);
    let mut lemmas: Vec<Json> = Vec::new();
    let mut seen: Vec<String> = vec![o.id.clone()];
    let mut wanted = cited_lemmas(&cert);
    while let Some(id) = wanted.pop() {
        if seen.contains(&id) {
            continue;
        }
        // Every claim of that id: two files stating one lemma are refused, as by `check`.
        for other in others.iter().filter(|c| c.id == id) {
            let c = certificate(other);
            wanted.extend(cited_lemmas(&c));
            lemmas.push(c);
        }
        seen.push(id);
    }
    read_back_with(&cert, &file_name(&o.id), &lemmas)
}

/// A certificate's JSON value read back for people; `file` is its file's name. The kernel
/// re-reads the value's text as `casteljau check` reads a file: a value that is not a
/// certificate, or whose data does not prove its goal, is shown as not re-checked.
pub fn read_back(cert: &Json, file: &str) -> Readable {
    read_back_with(cert, file, &[])
}

/// [`read_back`], the kernel re-checking `cert` together with the certificates `lemmas` (the
/// lemmas it cites resolved among them).
fn read_back_with(cert: &Json, file: &str, lemmas: &[Json]) -> Readable {
    let json = file_text(cert);
    let texts: Vec<String> = lemmas.iter().map(file_text).collect();
    let all: Vec<&str> = std::iter::once(json.as_str())
        .chain(texts.iter().map(String::as_str))
        .collect();
    let status = match check_certificate_texts(&all).swap_remove(0) {
        Recheck::Accepted(what) if cert.get("check").and_then(Json::as_str) == Some("kernel") => {
            Status::Rechecked(clean(&what))
        }
        Recheck::Accepted(_) => Status::NotRechecked("the file does not say check: kernel".into()),
        Recheck::NotChecked(why) => Status::NotRechecked(clean(&why)),
        Recheck::Refused(why) => Status::NotRechecked(format!("the kernel refuses it: {}", clean(&why))),
    };
    let goal = cert.get("goal").map(goal_blocks).unwrap_or_default();
    let equalities = goal_equalities(cert);
    let mut data = Vec::new();
    if let Some(obj) = cert.as_object() {
        for (key, value) in obj.iter().filter(|(k, _)| !COMMON.contains(&k.as_str())) {
            data.push(match key.as_str() {
                "sampling" => sampling(value, &equalities),
                "fails" => fails(value, &equalities),
                _ => generic(key, value),
            });
        }
    }
    Readable {
        status,
        method: cert.get("method").and_then(Json::as_str).map(clean),
        goal,
        data,
        file: clean(file),
        json,
    }
}

/// A string fit to print: control characters (terminal escapes, bidi controls) shown as
/// U+FFFD, and at most [`MAX_CHARS`] characters.
fn clean(text: &str) -> String {
    let mut out: String = text
        .chars()
        .take(MAX_CHARS)
        .map(|c| {
            if c.is_control() || ('\u{202a}'..='\u{202e}').contains(&c) || ('\u{2066}'..='\u{2069}').contains(&c) {
                '\u{fffd}'
            } else {
                c
            }
        })
        .collect();
    let total = text.chars().count();
    if total > MAX_CHARS {
        out.push_str(&format!(" … ({} more characters)", total - MAX_CHARS));
    }
    out
}

/// A scalar or a list of scalars on one line; `None` for anything nested.
fn flat(v: &Json) -> Option<String> {
    match v {
        Json::Null => Some("—".into()),
        Json::Bool(b) => Some(b.to_string()),
        Json::Number(n) => Some(n.to_string()),
        Json::String(s) => Some(clean(s)),
        Json::Array(items) => {
            let shown: Option<Vec<String>> = items.iter().take(MAX_VALUES).map(scalar).collect();
            let mut line = shown?.join(", ");
            if items[items.len().min(MAX_VALUES)..].iter().any(|x| scalar(x).is_none()) {
                return None;
            }
            if items.len() > MAX_VALUES {
                line.push_str(&format!(", … ({} more)", items.len() - MAX_VALUES));
            }
            Some(line)
        }
        Json::Object(o) => quadratic(o),
    }
}

/// A number `a + b√d` written `{"rational": a, "irrational": b, "radicand": d}` (strings),
/// shown as `a + b√d` (`b√d` when `a` is 0); `None` for any other object.
fn quadratic(o: &Map<String, Json>) -> Option<String> {
    if o.len() != 3 {
        return None;
    }
    let part = |k: &str| o.get(k).and_then(Json::as_str).map(clean);
    let (a, b, d) = (part("rational")?, part("irrational")?, part("radicand")?);
    let root = match b.as_str() {
        "1" => format!("√{d}"),
        "-1" => format!("-√{d}"),
        _ => format!("{b}√{d}"),
    };
    Some(match (a.as_str(), root.strip_prefix('-')) {
        ("0", _) => root,
        (_, Some(positive)) => format!("{a} - {positive}"),
        (_, None) => format!("{a} + {root}"),
    })
}

fn scalar(v: &Json) -> Option<String> {
    match v {
        Json::Array(_) => None,
        other => flat(other),
    }
}

/// A vector of exact values: one value alone, several as `(a, b, c)`.
fn vector(v: &Json) -> String {
    match v.as_array() {
        Some(items) if items.len() == 1 => flat(&items[0]).unwrap_or_default(),
        Some(_) => format!("({})", flat(v).unwrap_or_default()),
        None => flat(v).unwrap_or_default(),
    }
}

/// The goal's equalities as `lhs = rhs` with their integer values (`n = 3, j = 1`).
fn goal_equalities(cert: &Json) -> Vec<(String, String)> {
    let list = cert.pointer("/goal/equalities").and_then(Json::as_array);
    list.into_iter()
        .flatten()
        .map(|eq| {
            let side = |k: &str| eq.get(k).and_then(Json::as_str).map(clean).unwrap_or_default();
            (format!("{} = {}", side("lhs"), side("rhs")), ints(eq))
        })
        .collect()
}

fn ints(eq: &Json) -> String {
    let obj = eq.get("ints").and_then(Json::as_object);
    let pairs: Vec<String> = obj
        .into_iter()
        .flatten()
        .map(|(k, v)| format!("{} = {}", clean(k), flat(v).unwrap_or_default()))
        .collect();
    pairs.join(", ")
}

/// The goal: its symbols, then each distinct `lhs = rhs` with the integer values it is
/// stated for (a table when there are several).
fn goal_blocks(goal: &Json) -> Vec<Block> {
    let mut lines = Vec::new();
    let symbols: Vec<String> = goal
        .get("symbols")
        .and_then(Json::as_array)
        .into_iter()
        .flatten()
        .map(|s| {
            let get = |k: &str| s.get(k).and_then(Json::as_str).map(clean).unwrap_or_default();
            format!("{} ({})", get("name"), get("sort"))
        })
        .collect();
    if !symbols.is_empty() {
        lines.push(("symbols".to_string(), symbols.join(", ")));
    }
    let mut blocks = Vec::new();
    if !lines.is_empty() {
        blocks.push(Block::Lines(lines));
    }
    // An inequality's goal (`>=`, `<=`): its sides and the interval of its real symbol.
    if let Some(ineq) = goal.get("inequality") {
        let side = |k: &str| ineq.get(k).and_then(Json::as_str).map(clean).unwrap_or_default();
        let rel = if goal.get("relation").and_then(Json::as_str) == Some("<=") {
            "≤"
        } else {
            "≥"
        };
        let mut lines = vec![(
            "inequality".to_string(),
            format!("{} {rel} {}", side("lhs"), side("rhs")),
        )];
        if let Some(iv) = goal.get("interval") {
            let get = |k: &str| iv.get(k).and_then(Json::as_str).map(clean).unwrap_or_default();
            lines.push((
                "for".to_string(),
                format!("{} in [{}, {}]", get("name"), get("from"), get("to")),
            ));
        }
        blocks.push(Block::Lines(lines));
    }
    // Equalities with the same sides differ only in their integers: one line and a table.
    let eqs: Vec<&Json> = goal
        .get("equalities")
        .and_then(Json::as_array)
        .into_iter()
        .flatten()
        .collect();
    let mut groups: Vec<(String, Vec<&Json>)> = Vec::new();
    for eq in eqs {
        let side = |k: &str| eq.get(k).and_then(Json::as_str).map(clean).unwrap_or_default();
        let text = format!("{} = {}", side("lhs"), side("rhs"));
        match groups.iter_mut().find(|(t, _)| *t == text) {
            Some((_, members)) => members.push(eq),
            None => groups.push((text, vec![eq])),
        }
    }
    let folded = groups.len().saturating_sub(MAX_ITEMS);
    for (text, members) in groups.into_iter().take(MAX_ITEMS) {
        let cases: Vec<&Map<String, Json>> = members
            .iter()
            .filter_map(|m| m.get("ints").and_then(Json::as_object))
            .filter(|o| !o.is_empty())
            .collect();
        let mut lines = vec![("equality".to_string(), text)];
        if members.len() == 1 && cases.len() == 1 {
            lines.push(("with".into(), ints(members[0])));
        }
        // keys a later version adds to an equality (ranges, conditions) shown as they are
        for (k, v) in members[0].as_object().into_iter().flatten() {
            if !["lhs", "rhs", "ints"].contains(&k.as_str()) {
                lines.push((clean(k), flat(v).unwrap_or_else(|| clean(&v.to_string()))));
            }
        }
        blocks.push(Block::Lines(lines));
        if members.len() > 1 && !cases.is_empty() {
            blocks.push(Block::Group {
                title: format!("stated for these {} integer values (one equality each)", members.len()),
                blocks: vec![table_of(&cases)],
            });
        }
    }
    if folded > 0 {
        blocks.push(Block::More(folded, "equalities".into()));
    }
    blocks
}

/// A table of objects: the union of their keys as columns, in first-seen order.
fn table_of(objs: &[&Map<String, Json>]) -> Block {
    let mut columns: Vec<String> = Vec::new();
    for o in objs {
        for k in o.keys() {
            if !columns.contains(k) {
                columns.push(k.clone());
            }
        }
    }
    let rows = objs
        .iter()
        .take(MAX_ROWS)
        .map(|o| {
            columns
                .iter()
                .map(|c| {
                    o.get(c)
                        .map(|v| flat(v).unwrap_or_else(|| clean(&v.to_string())))
                        .unwrap_or_default()
                })
                .collect()
        })
        .collect();
    Block::Table {
        columns: columns.iter().map(|c| clean(c)).collect(),
        rows,
        more: objs.len().saturating_sub(MAX_ROWS),
    }
}

/// The sampling data: per equality, the degree bound in each variable with its points, and
/// the table of both sides' exact values at each point of the grid.
fn sampling(value: &Json, goal: &[(String, String)]) -> Block {
    let eqs = value.get("equalities").and_then(Json::as_array);
    let Some(eqs) = eqs else {
        return generic("sampling", value);
    };
    let mut blocks = Vec::new();
    for (i, eq) in eqs.iter().enumerate().take(MAX_ITEMS) {
        let params: Vec<&Json> = eq
            .get("params")
            .and_then(Json::as_array)
            .into_iter()
            .flatten()
            .collect();
        let names: Vec<String> = params
            .iter()
            .map(|p| p.get("name").and_then(Json::as_str).map(clean).unwrap_or_default())
            .collect();
        let mut inner = Vec::new();
        if !params.is_empty() {
            let rows: Vec<Vec<String>> = params
                .iter()
                .map(|p| {
                    let get = |k: &str| p.get(k).map(|v| flat(v).unwrap_or_default()).unwrap_or_default();
                    vec![
                        get("name"),
                        get("degree"),
                        get("lhs_degree"),
                        get("rhs_degree"),
                        get("points"),
                    ]
                })
                .collect();
            inner.push(Block::Group {
                title: "the degree bound in each variable (of each side), and its points".into(),
                blocks: vec![Block::Table {
                    columns: ["variable", "degree ≤", "left side", "right side", "points"]
                        .map(String::from)
                        .to_vec(),
                    rows,
                    more: 0,
                }],
            });
        }
        let values: Vec<&Json> = eq
            .get("values")
            .and_then(Json::as_array)
            .into_iter()
            .flatten()
            .collect();
        let mut columns = names.clone();
        columns.extend(["left side".to_string(), "right side".to_string()]);
        let rows = values
            .iter()
            .take(MAX_ROWS)
            .map(|row| {
                let mut cells: Vec<String> = row
                    .get("at")
                    .and_then(Json::as_array)
                    .into_iter()
                    .flatten()
                    .map(|x| flat(x).unwrap_or_default())
                    .collect();
                cells.resize(names.len(), String::new());
                cells.push(row.get("lhs").map(vector).unwrap_or_default());
                cells.push(row.get("rhs").map(vector).unwrap_or_default());
                cells
            })
            .collect();
        inner.push(Block::Group {
            title: "both sides' exact values at the points".into(),
            blocks: vec![Block::Table {
                columns,
                rows,
                more: values.len().saturating_sub(MAX_ROWS),
            }],
        });
        // the goal above prints each equality; its integers say which one this is
        let title = match goal.get(i) {
            Some((_, ints)) if !ints.is_empty() => format!("equality {} of the goal, with {ints}", i + 1),
            _ => format!("equality {} of the goal", i + 1),
        };
        blocks.push(Block::Group { title, blocks: inner });
    }
    if eqs.len() > MAX_ITEMS {
        blocks.push(Block::More(eqs.len() - MAX_ITEMS, "equalities".into()));
    }
    Block::Group {
        title: "sampling: each equality's degree bound, and both sides' exact values at the points".into(),
        blocks,
    }
}

/// The counterexample: the equality, the point (and basis polygon), the premise's value,
/// both sides' exact values.
fn fails(value: &Json, goal: &[(String, String)]) -> Block {
    let mut lines = Vec::new();
    let k = value.get("equality").and_then(Json::as_u64);
    if let Some((text, ints)) = k.and_then(|k| usize::try_from(k).ok()).and_then(|k| goal.get(k)) {
        if goal.len() > 1 {
            lines.push(("equality".to_string(), text.clone()));
        }
        if !ints.is_empty() {
            lines.push(("with".to_string(), ints.clone()));
        }
    }
    if let Some(at) = value.get("at").and_then(Json::as_object) {
        let point: Vec<String> = at
            .iter()
            .map(|(n, v)| format!("{} = {}", clean(n), flat(v).unwrap_or_default()))
            .collect();
        lines.push(("at".to_string(), point.join(", ")));
    }
    // On control points: which basis polygon; for an implication: the premise's value (0).
    if let Some(p) = value.get("polygon").and_then(Json::as_u64) {
        let which = match p {
            0 => "0 (every listed control point 0)".to_string(),
            p => format!("{p} (listed control point {p} is 1, the others 0)"),
        };
        lines.push(("basis polygon".to_string(), which));
    }
    if let Some(p) = value.get("premise") {
        lines.push(("premise".to_string(), vector(p)));
    }
    lines.push((
        "left side".to_string(),
        value.get("lhs").map(vector).unwrap_or_default(),
    ));
    lines.push((
        "right side".to_string(),
        value.get("rhs").map(vector).unwrap_or_default(),
    ));
    Block::Group {
        title: "counterexample".into(),
        blocks: vec![Block::Lines(lines)],
    }
}

/// Any JSON value under a key, laid out for reading.
fn generic(key: &str, value: &Json) -> Block {
    let title = clean(key);
    if let Some(line) = flat(value) {
        return Block::Lines(vec![(title, line)]);
    }
    Block::Group {
        title,
        blocks: contents(value),
    }
}

/// The inside of an object or a list: its flat fields as lines, lists of alike objects as
/// tables, the rest as groups.
fn contents(value: &Json) -> Vec<Block> {
    match value {
        Json::Object(obj) => {
            let mut lines = Vec::new();
            let mut blocks = Vec::new();
            for (k, v) in obj {
                match flat(v) {
                    Some(line) => lines.push((clean(k), line)),
                    None => blocks.push(generic(k, v)),
                }
            }
            if !lines.is_empty() {
                blocks.insert(0, Block::Lines(lines));
            }
            blocks
        }
        Json::Array(items) => {
            let objs: Vec<&Map<String, Json>> = items.iter().filter_map(Json::as_object).collect();
            let alike = objs.len() == items.len()
                && objs.iter().all(|o| o.keys().eq(objs[0].keys()))
                && objs.iter().all(|o| o.values().all(|v| flat(v).is_some()));
            if alike {
                return vec![table_of(&objs)];
            }
            let mut blocks: Vec<Block> = items
                .iter()
                .take(MAX_ITEMS)
                .enumerate()
                .map(|(i, v)| generic(&format!("[{}]", i + 1), v))
                .collect();
            if items.len() > MAX_ITEMS {
                blocks.push(Block::More(items.len() - MAX_ITEMS, "items".into()));
            }
            blocks
        }
        other => vec![Block::Lines(vec![(String::new(), flat(other).unwrap_or_default())])],
    }
}

impl Status {
    /// The status in words: "re-checked by the kernel: …" or "not re-checked: …".
    pub fn text(&self) -> String {
        match self {
            Status::Rechecked(what) => format!("re-checked by the kernel: {what}"),
            Status::NotRechecked(why) => format!("not re-checked: {why}"),
        }
    }
}

/// Rows of a table and groups of a list that `--explain` shows by default (one screen);
/// `--verbose` shows what the HTML report shows.
const BRIEF: (usize, usize) = (3, 1);

impl Readable {
    /// The certificate as plain text (`--explain`): indented lines, tables in aligned columns;
    /// `brief` folds tables after 3 rows, groups of groups after the first (the data's
    /// equalities) and the goal after its first equality; else as the report does.
    pub fn to_text(&self, brief: bool) -> String {
        let limits = if brief { BRIEF } else { (usize::MAX, usize::MAX) };
        let mut out = format!("certificate file {}: {}\n", self.file, self.status.text());
        if let Some(m) = &self.method {
            out.push_str(&format!("  method: {m}\n"));
        }
        if !self.goal.is_empty() {
            out.push_str("  goal:\n");
            // the goal whole (its equalities are what the data below is about); brief: its
            // first two equalities, the rest counted
            let goal = if brief {
                brief_goal(&self.goal)
            } else {
                self.goal.clone()
            };
            text_blocks(&mut out, &goal, 4, (limits.0, usize::MAX));
        }
        text_blocks(&mut out, &self.data, 2, limits);
        out.push_str(&format!(
            "  the file: `prove --certificates DIR` writes it as DIR/{}, `casteljau check` re-reads it\n",
            self.file
        ));
        out
    }
}

/// The goal's blocks up to its second equality, the equalities after it counted.
fn brief_goal(goal: &[Block]) -> Vec<Block> {
    let is_equality = |b: &Block| matches!(b, Block::Lines(l) if l.first().is_some_and(|(k, _)| k == "equality"));
    let mut shown = Vec::new();
    let (mut seen, mut folded) = (0, 0);
    for b in goal {
        if is_equality(b) {
            seen += 1;
        }
        match b {
            Block::More(n, _) => folded += n,
            _ if seen > 1 => folded += usize::from(is_equality(b)),
            _ => shown.push(b.clone()),
        }
    }
    if folded > 0 {
        shown.push(Block::More(folded, "equalities".into()));
    }
    shown
}

/// Blocks as indented text, showing at most `rows` rows of a table and `groups` groups of a
/// list (the rest counted, with the list's own count of folded items).
fn text_blocks(out: &mut String, blocks: &[Block], indent: usize, (max_rows, max_groups): (usize, usize)) {
    let pad = " ".repeat(indent);
    let (mut groups, mut folded, mut noun) = (0, 0, "groups".to_string());
    for b in blocks {
        match b {
            Block::Lines(lines) => {
                for (k, v) in lines {
                    if k.is_empty() {
                        out.push_str(&format!("{pad}{v}\n"));
                    } else {
                        out.push_str(&format!("{pad}{k}: {v}\n"));
                    }
                }
            }
            Block::Table { columns, rows, more } => {
                let shown = &rows[..rows.len().min(max_rows)];
                let more = more + (rows.len() - shown.len());
                let width = |k: usize| {
                    shown
                        .iter()
                        .map(|r| r.get(k).map_or(0, |c| c.chars().count()))
                        .chain([columns[k].chars().count()])
                        .max()
                        .unwrap_or(0)
                };
                let widths: Vec<usize> = (0..columns.len()).map(width).collect();
                let line = |cells: &[String]| {
                    let padded: Vec<String> = cells
                        .iter()
                        .zip(&widths)
                        .map(|(c, w)| format!("{c}{}", " ".repeat(w.saturating_sub(c.chars().count()))))
                        .collect();
                    format!("{pad}{}\n", padded.join("  ").trim_end())
                };
                out.push_str(&line(columns));
                for r in shown {
                    out.push_str(&line(r));
                }
                if more > 0 {
                    out.push_str(&format!("{pad}… {more} more rows (in the file)\n"));
                }
            }
            Block::Group { title, blocks } => {
                // a group of tables only (a bound's table, the values' table) is never folded:
                // its rows are
                let leaf = !blocks.iter().any(|b| matches!(b, Block::Group { .. }));
                groups += usize::from(!leaf);
                if !leaf && groups > max_groups {
                    folded += 1;
                    continue;
                }
                out.push_str(&format!("{pad}{title}:\n"));
                text_blocks(out, blocks, indent + 2, (max_rows, max_groups));
            }
            Block::More(n, what) => {
                folded += n;
                noun.clone_from(what);
            }
        }
    }
    if folded > 0 {
        out.push_str(&format!("{pad}… {folded} more {noun} (in the file)\n"));
    }
}
