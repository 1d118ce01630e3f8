//! Statements as HTML: the texts' `_x`, `^{…}` notation as subscripts and superscripts.

use crate::figure::svg::esc;
use std::fmt::Write as _;

/// Math names whose `_` starts a subscript although they are words (`lim_{r→∞}`).
const SCRIPTED_NAMES: &[&str] = &["lim", "max", "min", "sum", "sup", "inf", "det", "deg"];

/// Whether the `_` at `i` joins a library name (`elevate_by`, `BezierCurve::split_at`):
/// after a word of three or more letters that is not a math name (`from`: where the group
/// being read starts).
fn in_identifier(chars: &[char], from: usize, i: usize) -> bool {
    let word: String = chars[from..i]
        .iter()
        .rev()
        .take_while(|c| c.is_ascii_alphanumeric())
        .collect();
    let word: String = word.chars().rev().collect();
    word.chars().filter(|c| c.is_ascii_alphabetic()).count() >= 3 && !SCRIPTED_NAMES.contains(&word.as_str())
}

/// For each `open` of `chars`, the index of the `shut` that closes it (by nesting); one pass.
fn partners(chars: &[char], open: char, shut: char) -> Vec<Option<usize>> {
    let mut out = vec![None; chars.len()];
    let mut stack = Vec::new();
    for (k, &c) in chars.iter().enumerate() {
        if c == open {
            stack.push(k);
        } else if c == shut {
            if let Some(o) = stack.pop() {
                out[o] = Some(k);
            }
        }
    }
    out
}

/// A statement as HTML: `_x`, `_{…}` become subscripts and `^x`, `^{…}`, `^(…)` superscripts
/// (the texts' and claim files' notation); a `_` inside a library name
/// (`split_at`) stays; everything else is escaped text.
///
/// One pass with the brackets matched beforehand, and the open scripts on a stack rather than
/// in recursion: a long or deeply nested statement takes time in proportion to its length.
pub fn formula(text: &str) -> String {
    let chars: Vec<char> = text.chars().collect();
    let braces = partners(&chars, '{', '}');
    let parens = partners(&chars, '(', ')');
    let mut out = String::new();
    // the scripts open around `i`: (where the group starts, where it ends, where reading goes
    // on after it, its tag)
    let mut open: Vec<(usize, usize, usize, &str)> = Vec::new();
    let (mut from, mut end) = (0, chars.len());
    let mut i = 0;
    loop {
        if i >= end {
            let Some((_, _, next, tag)) = open.pop() else {
                break;
            };
            let _ = write!(out, "</{tag}>");
            i = next;
            (from, end) = open.last().map_or((0, chars.len()), |&(f, e, _, _)| (f, e));
            continue;
        }
        let c = chars[i];
        let literal = c == '_' && in_identifier(&chars, from, i);
        if (c == '_' || c == '^') && !literal && i + 1 < end && i > from && !chars[i - 1].is_whitespace() {
            let tag = if c == '_' { "sub" } else { "sup" };
            let start = i + 1;
            // the script's group: its first index, its end, and where reading goes on after it
            let group = match chars[start] {
                '{' => braces[start].filter(|&k| k < end).map(|k| (start + 1, k, k + 1)),
                '(' => parens[start]
                    .filter(|&k| k < end && k - start <= 8)
                    .map(|k| (start, k + 1, k + 1)),
                d if d.is_ascii_digit() => {
                    let stop = chars[start..end]
                        .iter()
                        .position(|c| !c.is_ascii_digit())
                        .map_or(end, |k| start + k);
                    Some((start, stop, stop))
                }
                l if l.is_alphabetic() => Some((start, start + 1, start + 1)),
                _ => None,
            };
            if let Some((first, stop, next)) = group.filter(|&(first, stop, _)| stop > first) {
                let _ = write!(out, "<{tag}>");
                open.push((first, stop, next, tag));
                (from, end) = (first, stop);
                i = first;
                continue;
            }
        }
        out.push_str(&esc(&c.to_string()));
        i += 1;
    }
    out
}
