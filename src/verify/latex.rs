//! `--explain` as a LaTeX fragment that `pdflatex` compiles: ASCII only, formulas in math
//! mode (`\dot{x}`, `-`, `\sum`), code in `\texttt`, and the Japanese of the texts inside
//! `CJK` environments (the only non-ASCII bytes; the document loads `CJKutf8`).

use super::argue::{
    argument, cases, certificate_case, misprint_lines, sample_evaluations, verdict_text, worked_case, worked_scheme,
    worked_sum,
};
use super::claims::{Claim, ClaimFile};
use super::outcome::Checked;
use std::fmt::Write as _;

mod mathmode;
use mathmode::{balance_parentheses, fractions, paren_script_len};

/// The first line of every fragment: what the document around it must load.
pub const PREAMBLE_NOTE: &str =
    "% casteljau --explain: needs \\usepackage{CJKutf8} (Japanese statements; Debian: latex-cjk-japanese)";

/// Japanese (and full-width) characters: set in a `CJK` environment, never in math.
fn is_cjk(ch: char) -> bool {
    matches!(ch as u32,
        0x3000..=0x303F   // CJK punctuation
        | 0x3040..=0x30FF // hiragana, katakana
        | 0x3400..=0x4DBF | 0x4E00..=0x9FFF // ideographs
        | 0xFF00..=0xFFEF) // full-width forms
}

/// A non-ASCII character in math mode; `None` for one that has no math form.
fn math_symbol(ch: char) -> Option<&'static str> {
    Some(match ch {
        '−' | '–' => "-",
        '·' | '⋅' => "\\cdot ",
        '×' => "\\times ",
        '≤' => "\\le ",
        '≥' => "\\ge ",
        '≠' => "\\ne ",
        '≈' => "\\approx ",
        '≡' => "\\equiv ",
        '±' => "\\pm ",
        '→' => "\\to ",
        '⇒' => "\\Rightarrow ",
        '⇔' => "\\Leftrightarrow ",
        '∈' => "\\in ",
        '∞' => "\\infty ",
        '∂' => "\\partial ",
        '∇' => "\\nabla ",
        '∘' => "\\circ ",
        '∫' => "\\int ",
        '√' => "\\surd ",
        '…' | '⋯' => "\\ldots ",
        '′' => "'",
        '″' => "''",
        '‖' => "\\| ",
        '⟨' => "\\langle ",
        '⟩' => "\\rangle ",
        'Σ' => "\\sum ",
        'Δ' => "\\Delta ",
        'Φ' => "\\Phi ",
        'Ψ' => "\\Psi ",
        'Ω' => "\\Omega ",
        'Γ' => "\\Gamma ",
        'Π' => "\\prod ",
        'α' => "\\alpha ",
        'β' => "\\beta ",
        'γ' => "\\gamma ",
        'δ' => "\\delta ",
        'ε' => "\\varepsilon ",
        'θ' => "\\theta ",
        'κ' => "\\kappa ",
        'λ' => "\\lambda ",
        'μ' => "\\mu ",
        'π' => "\\pi ",
        'σ' => "\\sigma ",
        'τ' => "\\tau ",
        'φ' => "\\varphi ",
        'ω' => "\\omega ",
        '⁰' => "^{0}",
        '¹' => "^{1}",
        '²' => "^{2}",
        '³' => "^{3}",
        '⁴' => "^{4}",
        '⁵' => "^{5}",
        '⁶' => "^{6}",
        '⁷' => "^{7}",
        '⁸' => "^{8}",
        '⁹' => "^{9}",
        'ⁿ' => "^{n}",
        'ᵀ' => "^{T}",
        '⁻' => "^{-}",
        '₀' => "_{0}",
        '₁' => "_{1}",
        '₂' => "_{2}",
        '₃' => "_{3}",
        '₄' => "_{4}",
        '₅' => "_{5}",
        '₆' => "_{6}",
        '₇' => "_{7}",
        '₈' => "_{8}",
        '₉' => "_{9}",
        'ᵢ' => "_{i}",
        'ⱼ' => "_{j}",
        'ₙ' => "_{n}",
        'ẋ' => "\\dot{x}",
        'ẍ' => "\\ddot{x}",
        'ẏ' => "\\dot{y}",
        _ => return None,
    })
}

/// A non-ASCII character in text mode: accented letters, quotes, else its math form.
fn text_symbol(ch: char) -> Option<String> {
    let accent = |a: &str, c: char| format!("\\{a}{{{c}}}");
    Some(match ch {
        'é' => accent("'", 'e'),
        'è' => accent("`", 'e'),
        'ü' => accent("\"", 'u'),
        'ö' => accent("\"", 'o'),
        'ä' => accent("\"", 'a'),
        '§' => "\\S{}".into(),
        '—' => "---".into(),
        '–' => "--".into(),
        '‘' => "`".into(),
        '’' => "'".into(),
        '“' => "``".into(),
        '”' => "''".into(),
        ' ' => "~".into(),
        _ => format!("${}$", math_symbol(ch)?.trim_end()),
    })
}

/// ASCII text with TeX's special characters escaped.
fn escape_ascii(ch: char, out: &mut String) {
    match ch {
        _ if ch.is_ascii_control() => out.push_str(&unknown(ch)),
        '\\' => out.push_str("\\textbackslash{}"),
        '{' | '}' | '_' | '#' | '&' | '%' | '$' => {
            out.push('\\');
            out.push(ch);
        }
        '^' => out.push_str("\\^{}"),
        '~' => out.push_str("\\textasciitilde{}"),
        '<' => out.push_str("\\textless{}"),
        '>' => out.push_str("\\textgreater{}"),
        '|' => out.push_str("\\textbar{}"),
        _ => out.push(ch),
    }
}

/// A character no table knows, written so that the fragment stays ASCII and the gap is seen.
fn unknown(ch: char) -> String {
    format!("[U+{:04X}]", ch as u32)
}

/// Text: prose escaped, `code` and 'expressions' in `\texttt`, symbols as inline math,
/// Japanese in `CJK` environments.
pub fn text(t: &str) -> String {
    let mut out = String::new();
    let chars: Vec<char> = t.chars().collect();
    // where the next backquote, and the next quote that closes (not before a letter or
    // digit), are at or after each index: each opening one finds its end at once
    let mut next_tick = vec![None; chars.len() + 1];
    let mut next_close = vec![None; chars.len() + 1];
    for k in (0..chars.len()).rev() {
        next_tick[k] = if chars[k] == '`' { Some(k) } else { next_tick[k + 1] };
        let closes = chars[k] == '\'' && chars.get(k + 1).is_none_or(|n| !n.is_alphanumeric());
        next_close[k] = if closes { Some(k) } else { next_close[k + 1] };
    }
    let mut i = 0;
    while i < chars.len() {
        let ch = chars[i];
        let code_end = match ch {
            '`' => next_tick[i + 1].map(|k| k - i - 1),
            // an opening quote: not inside a word (the claim's), closed before a space or the end
            '\'' if i == 0 || !chars[i - 1].is_alphanumeric() => next_close[i + 1].map(|k| k - i - 1),
            _ => None,
        };
        if let Some(len) = code_end.filter(|&len| len > 0) {
            let inner: String = chars[i + 1..i + 1 + len].iter().collect();
            if is_expression(&inner) {
                // an expression of a claim file (`4/3*B(1, 3, t)`): a formula, `*` a dot
                let _ = write!(out, "${}$", fractions(&formula(&inner.replace('*', "·"))));
            } else {
                let _ = write!(out, "\\texttt{{{}}}", plain(&inner));
            }
            i += len + 2;
            continue;
        }
        if is_cjk(ch) {
            let run: String = chars[i..].iter().take_while(|&&c| is_cjk(c)).collect();
            i += run.chars().count();
            let _ = write!(out, "\\begin{{CJK}}{{UTF8}}{{min}}{run}\\end{{CJK}}");
            continue;
        }
        match (ch, chars.get(i + 1)) {
            // a minus sign before a number, not a hyphen; `--` not an en dash
            ('-', Some(d)) if d.is_ascii_digit() && (i == 0 || !chars[i - 1].is_alphanumeric()) => out.push_str("$-$"),
            ('-', Some('-')) => out.push_str("-{}"),
            _ => push_text_char(ch, &mut out),
        }
        i += 1;
    }
    out
}

/// Whether quoted text is an expression (set as a formula) rather than a name or code (set
/// in `\texttt`): it has an operator or a call, and no library path or identifier.
fn is_expression(t: &str) -> bool {
    let chars: Vec<char> = t.chars().collect();
    let operator = t.contains(['=', '+', '*', '/', '^', '<', '>']) || t.contains("(");
    let code = t.contains("::")
        || (0..chars.len()).any(|k| {
            chars[k].is_ascii_alphabetic() && identifier_len(&chars, k, word_at(&chars, k), &word(&chars, k)).is_some()
        });
    let number = t.chars().all(|c| c.is_ascii_digit() || c == '-') && t.chars().any(|c| c.is_ascii_digit());
    (operator || number) && !code && !t.contains(['`', '\\', '$', '%', '#', '&', '~'])
}

fn word_at(chars: &[char], k: usize) -> usize {
    chars[k..].iter().take_while(|c| c.is_ascii_alphabetic()).count()
}

fn word(chars: &[char], k: usize) -> String {
    chars[k..k + word_at(chars, k)].iter().collect()
}

fn push_text_char(ch: char, out: &mut String) {
    if ch.is_ascii() {
        escape_ascii(ch, out);
    } else if let Some(s) = text_symbol(ch) {
        out.push_str(&s);
    } else if is_cjk(ch) {
        let _ = write!(out, "\\begin{{CJK}}{{UTF8}}{{min}}{ch}\\end{{CJK}}");
    } else {
        out.push_str(&unknown(ch));
    }
}

/// Text without `code` detection (the inside of `\texttt`, file names, ids).
fn plain(t: &str) -> String {
    let mut out = String::new();
    for ch in t.chars() {
        push_text_char(ch, &mut out);
    }
    out.replace("--", "-{}-")
}

/// Names that stay in a formula although they are words, when used as functions (`sum(`,
/// `max_i`); elsewhere (`and sum to 1`) they are words.
const MATH_NAMES: &[&str] = &[
    "sin", "cos", "tan", "exp", "log", "det", "max", "min", "dot", "diff", "inv", "sqrt", "rows", "sum", "lim", "deg",
];
/// Short English words that a formula never contains as a product of variables.
const SHORT_WORDS: &[&str] = &[
    "is", "of", "an", "at", "on", "to", "be", "in", "by", "if", "or", "as", "so", "we", "it", "de", "vs", "up",
];
/// Abbreviations whose dots and letters are prose.
const ABBREVIATIONS: &[&str] = &["e.g.", "i.e."];

#[derive(Clone, Copy, PartialEq, Eq)]
enum Part {
    Math,
    Prose,
    Japanese,
    /// A library name such as `BezierCurve::elevate_by`: set in `\texttt`.
    Code,
    /// Spaces and punctuation: math between two formula parts, prose otherwise.
    Neutral,
    /// A short word (`at`, `a`) whose neighbours decide: prose beside prose.
    ShortWord {
        both_sides: bool,
    },
    /// A `-` between two letters: a hyphen after a prose word, a minus otherwise.
    Dash,
}

/// Letters of words, including the accented ones of names such as Bézier.
fn is_word_char(ch: char) -> bool {
    ch.is_ascii_alphabetic() || matches!(ch, 'é' | 'è' | 'ü' | 'ö' | 'ä')
}

/// The length of an identifier starting at `i` (`elevate_by`, `BezierCurve::split_at`): a
/// word of three or more letters, not a math name, continued by `_` or `::` and a letter.
fn identifier_len(chars: &[char], i: usize, word_len: usize, word: &str) -> Option<usize> {
    if word_len < 3 || MATH_NAMES.contains(&word) {
        return None;
    }
    let rest = &chars[i + word_len..];
    let continues = match rest {
        ['_', c, ..] | [':', ':', c, ..] => c.is_ascii_alphabetic(),
        _ => false,
    };
    if !continues {
        return None;
    }
    let mut len = word_len;
    while let Some(&c) = chars.get(i + len) {
        let double_colon = c == ':' && chars.get(i + len + 1) == Some(&':');
        if double_colon {
            len += 2;
        } else if c.is_ascii_alphanumeric() || c == '_' {
            len += 1;
        } else {
            break;
        }
    }
    Some(len)
}

/// A statement split into parts, each word decided by itself where it can be.
fn split_statement(chars: &[char]) -> Vec<(Part, String)> {
    let mut parts: Vec<(Part, String)> = Vec::new();
    let mut i = 0;
    let boundary_before = |i: usize| i == 0 || matches!(chars[i - 1], ' ' | '(');
    let boundary_after = |k: usize| chars.get(k).is_none_or(|c| matches!(c, ' ' | ')' | ',' | ':' | ';'));
    while i < chars.len() {
        let ch = chars[i];
        let abbreviation = ABBREVIATIONS
            .iter()
            .find(|a| chars[i..].iter().take(a.len()).copied().eq(a.chars()) && boundary_before(i));
        let (part, len) = if let Some(a) = abbreviation {
            (Part::Prose, a.len())
        } else if is_cjk(ch) {
            (Part::Japanese, chars[i..].iter().take_while(|&&c| is_cjk(c)).count())
        } else if is_word_char(ch) {
            let len = chars[i..].iter().take_while(|&&c| is_word_char(c)).count();
            let word: String = chars[i..i + len].iter().collect();
            let scripted = i > 0 && matches!(chars[i - 1], '_' | '^');
            let called = chars.get(i + len).is_some_and(|c| matches!(c, '(' | '_' | '^' | '{'));
            // between spaces (the old rule) a listed short word is prose; after `(` or before
            // `)` its neighbours decide
            let spaced = (i == 0 || chars[i - 1] == ' ') && chars.get(i + len).is_none_or(|c| *c == ' ');
            let bounded = boundary_before(i) && boundary_after(i + len);
            if let Some(id_len) = identifier_len(chars, i, len, &word).filter(|_| !scripted) {
                (Part::Code, id_len)
            } else if scripted {
                (Part::Math, len)
            } else if MATH_NAMES.contains(&word.as_str()) {
                (if called { Part::Math } else { Part::Prose }, len)
            } else if len >= 3 || (spaced && SHORT_WORDS.contains(&word.as_str())) {
                (Part::Prose, len)
            } else if bounded && SHORT_WORDS.contains(&word.as_str()) {
                (Part::ShortWord { both_sides: false }, len)
            } else if bounded && word == "a" {
                (Part::ShortWord { both_sides: true }, len)
            } else {
                (Part::Math, len)
            }
        } else if ch == '-' && i > 0 && is_word_char(chars[i - 1]) && chars.get(i + 1).is_some_and(|&c| is_word_char(c))
        {
            (Part::Dash, 1)
        } else if matches!(ch, ' ' | ',' | ';' | ':' | '.' | '(' | ')') {
            (Part::Neutral, 1)
        } else {
            (Part::Math, 1)
        };
        let piece: String = chars[i..i + len].iter().collect();
        match parts.last_mut() {
            Some((p, s)) if *p == part && matches!(part, Part::Math | Part::Japanese | Part::Neutral) => {
                s.push_str(&piece)
            }
            _ => parts.push((part, piece)),
        }
        i += len;
    }
    parts
}

/// Decides the short words, dashes and neutral parts from their neighbours.
fn resolve_parts(mut parts: Vec<(Part, String)>) -> Vec<(Part, String)> {
    // the nearest part on each side that is not neutral (neutral parts stay neutral here)
    let mut before = vec![None; parts.len()];
    let mut after = vec![None; parts.len()];
    let mut last = None;
    for (k, (p, _)) in parts.iter().enumerate() {
        before[k] = last;
        if *p != Part::Neutral {
            last = Some(k);
        }
    }
    last = None;
    for (k, (p, _)) in parts.iter().enumerate().rev() {
        after[k] = last;
        if *p != Part::Neutral {
            last = Some(k);
        }
    }
    // short words: prose beside prose (one side, or both for `a`), spreading along a phrase;
    // a word that turns to prose is the only news for its two neighbours, so each is looked
    // at again only then (the fixed point of the rule, in time linear in the parts)
    let mut todo: Vec<usize> = (0..parts.len()).collect();
    while let Some(k) = todo.pop() {
        if let Part::ShortWord { both_sides } = parts[k].0 {
            let prose = |j: Option<usize>| j.is_some_and(|j: usize| parts[j].0 == Part::Prose);
            let (b, a) = (prose(before[k]), prose(after[k]));
            if (both_sides && b && a) || (!both_sides && (b || a)) {
                parts[k].0 = Part::Prose;
                todo.extend(before[k].into_iter().chain(after[k]));
            }
        }
    }
    for k in 0..parts.len() {
        parts[k].0 = match parts[k].0 {
            Part::ShortWord { .. } => Part::Math,
            Part::Dash if k > 0 && parts[k - 1].0 == Part::Prose => Part::Prose,
            Part::Dash => Part::Math,
            p => p,
        };
    }
    // neutral parts between two formula parts belong to the formula
    for k in 0..parts.len() {
        if parts[k].0 == Part::Neutral {
            let math = |j: Option<usize>| j.and_then(|j| parts.get(j)).is_some_and(|p| p.0 == Part::Math);
            parts[k].0 = if math(k.checked_sub(1)) && math(Some(k + 1)) {
                Part::Math
            } else {
                Part::Prose
            };
        }
    }
    let mut merged: Vec<(Part, String)> = Vec::new();
    for (p, s) in parts {
        match merged.last_mut() {
            Some((q, m)) if *q == p && p != Part::Code => m.push_str(&s),
            _ => merged.push((p, s)),
        }
    }
    balance_parentheses(&mut merged);
    merged.retain(|(_, s)| !s.is_empty());
    merged
}

/// A statement as printed: its formulas in math mode (`$…$`), its words as text, library
/// names in `\texttt`, its Japanese in `CJK` environments.
pub fn statement(t: &str) -> String {
    let chars: Vec<char> = t.chars().collect();
    let mut out = String::new();
    for (p, s) in resolve_parts(split_statement(&chars)) {
        match p {
            Part::Japanese => {
                let _ = write!(out, "\\begin{{CJK}}{{UTF8}}{{min}}{s}\\end{{CJK}}");
            }
            Part::Math => {
                let lead = s.len() - s.trim_start().len();
                let trail = s.len() - s.trim_end().len();
                out.push_str(&" ".repeat(lead.min(1)));
                let _ = write!(out, "${}$", fractions(&formula(s.trim())));
                out.push_str(&" ".repeat(trail.min(1)));
            }
            Part::Code => {
                let _ = write!(out, "\\texttt{{{}}}", plain(&s));
            }
            _ => out.push_str(&plain(&s)),
        }
    }
    out
}

/// A run of superscript (subscript) characters at `i` (`⁻¹` is `^{-1}`): its mark, the group's
/// inside and its length.
fn script_run(chars: &[char], i: usize) -> Option<(char, String, usize)> {
    let script = |c: char| math_symbol(c).filter(|m| m.len() == 4 && (m.starts_with("^{") || m.starts_with("_{")));
    let mark = script(chars[i])?.chars().next()?;
    let mut inner = String::new();
    let mut len = 0;
    while let Some(m) = chars
        .get(i + len)
        .and_then(|&c| script(c))
        .filter(|m| m.starts_with(mark))
    {
        inner.push_str(&m[2..3]);
        len += 1;
    }
    Some((mark, inner, len))
}

/// One atom of a formula at `i` in math mode and its length: `x` with a combining dot as
/// `\dot{x}`, a math name as `\mathrm{sum}`, one character; `None` for what is not an atom by
/// itself (scripts, primes, braces, spaces).
fn atom(chars: &[char], i: usize) -> Option<(String, usize)> {
    let ch = chars[i];
    if ch.is_alphanumeric() && chars.get(i + 1) == Some(&'\u{307}') {
        let mut inner = String::new();
        push_math_char(ch, &mut inner);
        return Some((format!("\\dot{{{inner}}}"), 2));
    }
    if let Some(name) = MATH_NAMES.iter().find(|n| {
        let end = i + n.len();
        chars.get(i..end).is_some_and(|w| w.iter().copied().eq(n.chars()))
            && chars.get(end).is_none_or(|c| !c.is_ascii_alphabetic())
            && (i == 0 || !chars[i - 1].is_ascii_alphabetic())
    }) {
        return Some((format!("\\mathrm{{{name}}}"), name.len()));
    }
    if matches!(ch, '^' | '_' | '{' | '}' | '\'' | '′' | '″' | ' ') || script_run(chars, i).is_some() {
        return None;
    }
    let mut out = String::new();
    push_math_char(ch, &mut out);
    Some((out, 1))
}

/// The scripts already on the current base inside one group of a formula, so that a second
/// one starts a new (empty) base instead of TeX's "double superscript" error.
#[derive(Clone, Copy, Default)]
struct Scripts {
    sup: bool,
    sub: bool,
    /// The last thing written was a prime, which a `^` or another prime joins.
    after_prime: bool,
}

impl Scripts {
    /// Before a script `mark` (`^` or `_`; a prime is a `^`): `{}` when the base has one.
    fn before(&mut self, mark: char, out: &mut String) {
        let taken = if mark == '^' {
            self.sup && !self.after_prime
        } else {
            self.sub
        };
        if taken {
            out.push_str("{}");
            *self = Scripts::default();
        }
        if mark == '^' {
            self.sup = true;
        } else {
            self.sub = true;
        }
        self.after_prime = false;
    }
}

/// A formula's characters in math mode: `_`, `^` and braces kept (the statements use TeX's
/// notation), Unicode symbols mapped, `x` with a combining dot as `\dot{x}`.
///
/// Whatever the statement holds, the result is well-formed math that reads no control sequence
/// from it: a brace without its partner in the formula is written `\{` or `\}`, every script
/// has an argument (a letter, a digit or a group: never a second `^`, so TeX's `^^5c` notation
/// for `\` cannot occur), and a second script on one base starts an empty base `{}`.
fn formula(t: &str) -> String {
    let chars: Vec<char> = t.chars().collect();
    let mut partner = vec![None; chars.len()];
    let mut stack = Vec::new();
    for (k, &c) in chars.iter().enumerate() {
        if c == '{' {
            stack.push(k);
        } else if c == '}' {
            if let Some(o) = stack.pop() {
                partner[o] = Some(k);
                partner[k] = Some(o);
            }
        }
    }
    let mut out = String::new();
    // the scripts of the base in each open group, innermost last
    let mut groups = vec![Scripts::default()];
    let mut i = 0;
    while i < chars.len() {
        let ch = chars[i];
        let top = groups.last_mut().expect("the formula's own group is never closed");
        if let Some((mark, inner, len)) = script_run(&chars, i) {
            top.before(mark, &mut out);
            let _ = write!(out, "{mark}{{{inner}}}");
            i += len;
            continue;
        }
        match ch {
            '^' | '_' => {
                top.before(ch, &mut out);
                out.push(ch);
                i += 1;
                match chars.get(i) {
                    // the texts' `b_i^(r)`: a superscript in parentheses, of simple characters
                    Some('(') if ch == '^' && paren_script_len(&chars, i).is_some() => {
                        let len = paren_script_len(&chars, i).expect("checked");
                        out.push('{');
                        for &c in &chars[i..i + len] {
                            push_math_char(c, &mut out);
                        }
                        out.push('}');
                        i += len;
                    }
                    Some('{') if partner[i].is_some() => {
                        out.push('{');
                        groups.push(Scripts::default());
                        i += 1;
                    }
                    Some(_) if atom(&chars, i).is_some() => {
                        let (a, len) = atom(&chars, i).expect("checked");
                        if len == 1 && chars[i].is_ascii_alphanumeric() {
                            out.push_str(&a);
                        } else {
                            let _ = write!(out, "{{{a}}}");
                        }
                        i += len;
                    }
                    _ => out.push_str("{}"),
                }
            }
            '\'' | '′' | '″' => {
                if !top.after_prime {
                    top.before('^', &mut out);
                }
                out.push_str(if ch == '″' { "''" } else { "'" });
                top.after_prime = true;
                i += 1;
            }
            '{' if partner[i].is_some() => {
                out.push('{');
                groups.push(Scripts::default());
                i += 1;
            }
            '}' if partner[i].is_some() => {
                out.push('}');
                groups.pop();
                i += 1;
                // the group is the base of what follows, unless it was a script's argument
                let script_argument = partner[i - 1].is_some_and(|o| o > 0 && matches!(chars[o - 1], '^' | '_'));
                let top = groups.last_mut().expect("the formula's own group is never closed");
                if !script_argument {
                    *top = Scripts::default();
                }
                top.after_prime = false;
            }
            '{' | '}' => {
                let _ = write!(out, "\\{ch}");
                *top = Scripts::default();
                i += 1;
            }
            ' ' => {
                out.push(' ');
                top.after_prime = false;
                i += 1;
            }
            _ => {
                let (a, len) = atom(&chars, i).unwrap_or_else(|| (unknown(ch), 1));
                out.push_str(&a);
                *top = Scripts::default();
                i += len;
            }
        }
    }
    out
}

fn push_math_char(ch: char, out: &mut String) {
    match ch {
        // `formula` writes scripts and braces itself; alone they are symbols
        '_' | '{' | '}' => {
            out.push('\\');
            out.push(ch);
        }
        '^' => out.push_str("\\hat{}"),
        '\\' => out.push_str("\\backslash "),
        '#' | '&' | '%' | '$' => {
            out.push('\\');
            out.push(ch);
        }
        '~' => out.push_str("\\sim "),
        _ if ch.is_ascii_control() => out.push_str(&unknown(ch)),
        _ if ch.is_ascii() => out.push(ch),
        _ => match math_symbol(ch) {
            Some(s) => out.push_str(s),
            None if is_cjk(ch) => {
                let _ = write!(out, "\\mbox{{\\begin{{CJK}}{{UTF8}}{{min}}{ch}\\end{{CJK}}}}");
            }
            None => match text_symbol(ch) {
                Some(s) => {
                    let _ = write!(out, "\\mbox{{{s}}}");
                }
                None => out.push_str(&unknown(ch)),
            },
        },
    }
}

/// The short proof as a LaTeX fragment: the claim, its verdict, the argument, one worked case
/// and the scheme (9) as an `array` of exact fractions.
pub(super) fn explain(f: &ClaimFile, c: &Claim, checked: &Checked, range_bound: Option<&str>) -> String {
    let mut s = String::new();
    let _ = writeln!(s, "{PREAMBLE_NOTE}");
    // the claim file on the heading's line may break after its folder (a long id and path
    // overfill the line otherwise); the source on its own line, as in the text output
    let path = plain(&f.origin()).replace('/', "/\\allowbreak ");
    let _ = writeln!(
        s,
        "\\paragraph{{Claim \\texttt{{{}}}}} (\\texttt{{{path}}})\\\\",
        plain(&c.id)
    );
    let _ = writeln!(s, "Source: {}\\\\", text(&c.source));
    let _ = writeln!(s, "Statement: {}\\\\", statement(&c.statement));
    let _ = writeln!(
        s,
        "Verdict: \\textbf{{{}}}\\\\",
        text(&verdict_text(checked.verdict(), checked.range()))
    );
    let label = if checked.verdict() == super::kernel::checked::Verdict::Fails {
        "Counterexample"
    } else {
        "Certificate"
    };
    let _ = writeln!(s, "{label}: {}\n", text(&checked.certificate));
    for line in misprint_lines(f, c) {
        // the correction by name; the command that shows it is for the terminal
        let line = line.split(" (see --explain").next().unwrap_or(&line);
        let (key, value) = line.split_once(':').unwrap_or(("", line));
        let _ = writeln!(s, "\\noindent {}: {}\n", text(key.trim()), text(value.trim()));
    }
    if let Some(r) = range_bound {
        let _ = writeln!(s, "\\noindent Range-bound: {}\n", text(r));
    }
    let _ = writeln!(
        s,
        "\\noindent Why this suffices: {}\n",
        text(&argument(c, checked).join(" "))
    );
    let all = cases(&checked.steps);
    let case = worked_case(&all);
    let evals = case.map(|c| sample_evaluations(c, 4)).unwrap_or_default();
    let (header, lines): (String, Vec<String>) = match case {
        Some(case) => (
            case.header.line(),
            if evals.is_empty() {
                case.lines.iter().take(4).map(|l| l.line()).collect()
            } else {
                evals.iter().map(|e| e.to_string()).collect()
            },
        ),
        None => {
            let (h, l) = certificate_case(checked);
            (h.to_string(), l.into_iter().map(String::from).collect())
        }
    };
    let _ = writeln!(s, "\\noindent Worked case: {}", text(&header));
    if !lines.is_empty() {
        let _ = writeln!(s, "\\begin{{itemize}}");
        for l in &lines {
            let _ = writeln!(s, "\\item {}", text(l));
        }
        let _ = writeln!(s, "\\end{{itemize}}");
    }
    if let Some(scheme) = worked_scheme(c, checked, evals.first().copied()) {
        let mut array = scheme.to_latex();
        if scheme.degree() >= 4 {
            // five or more columns of points (the widest: 3-d, degree 4) overfill the text width
            // at TeX's 5 pt column padding; 2 pt keeps them inside and the columns apart
            array = array.replacen("\\[\\begin{array}", "\\[\\arraycolsep=2pt\\begin{array}", 1);
        }
        s.push_str(&array);
        if let Some(sum) = evals.first().and_then(|e| worked_sum(c, &scheme, e)) {
            let _ = writeln!(s, "{}", text(&sum));
        }
    }
    s
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn formulas_are_math_and_everything_is_ascii_outside_cjk() {
        // a formula keeps the parenthesis that closes its own before Japanese text
        assert_eq!(
            statement("−3/4 ẋ(0)·ẋ(0) k = X·x(0) を得る"),
            "$-\\frac{3}{4} \\dot{x}(0)\\cdot \\dot{x}(0) k = X\\cdot x(0)$ \\begin{CJK}{UTF8}{min}を得る\\end{CJK}"
        );
        assert_eq!(statement("x\u{307} ≤ Σ b_i"), "$\\dot{x} \\le  \\sum  b_i$");
        assert_eq!(statement("gives k = l = 3/10"), "gives $k = l = \\frac{3}{10}$");
        assert_eq!(
            text("`delta` and 'b(t)' ≤ 1, the claim's"),
            "\\texttt{delta} and $b(t)$ $\\le$ 1, the claim's"
        );
        assert_eq!(text("b_0^n {x} 100%"), "b\\_0\\^{}n \\{x\\} 100\\%");
        assert_eq!(text("see --explain x: -32, b-1"), "see -{}-explain x: $-$32, b-1");
        assert_eq!(statement("(from (7) = 0)"), "(from $(7) = 0$)");
        assert_eq!(statement("M⁻¹ xᵀ₁₂"), "$M^{-1} x^{T}_{12}$");
        // library names are code, not a word with a subscript
        assert_eq!(statement("elevate_by, once"), "\\texttt{elevate\\_by}, once");
        assert_eq!(
            statement("(BezierCurve::split_at)"),
            "(\\texttt{BezierCurve::split\\_at})"
        );
        // words beside formulas: short words after `(`, `sum` not called, hyphens, names
        assert_eq!(statement("x = 1 (at the corner)"), "$x = 1$ (at the corner)");
        assert_eq!(statement("B_i(t) and sum to 1"), "$B_i(t)$ and sum to $1$");
        assert_eq!(statement("sum(i, 0, n, b)"), "$\\mathrm{sum}(i, 0, n, b)$");
        assert_eq!(statement("non-zero weights, n-k"), "non-zero weights, $n-k$");
        assert_eq!(statement("the Bézier points"), "the B\\'{e}zier points");
        assert_eq!(statement("as a curve, a(t)"), "as a curve, $a(t)$");
        assert_eq!(statement("e.g. x(t) = t"), "e.g. $x(t) = t$");
        assert_eq!(text("§2"), "\\S{}2");
        assert_eq!(text("✓"), "[U+2713]");
        assert_eq!(text("Bézier 曲線"), "B\\'{e}zier \\begin{CJK}{UTF8}{min}曲線\\end{CJK}");
    }
}
