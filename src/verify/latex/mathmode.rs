//! What makes a formula read as mathematics: `a/b` as `\frac{a}{b}`, the parentheses that
//! pair with the formula's own kept in it, `^(r)` as a superscript; each within bounds that
//! keep the math well-formed and the work per character bounded.

use super::Part;

/// The longest operand of a fraction `\frac` is written for, in characters: a longer one keeps
/// its `/` (and the work per `/` stays bounded).
pub(super) const MAX_OPERAND: usize = 40;

/// `a/b` in a formula already in math mode as `\frac{a}{b}`: each operand a number or name
/// (`3`, `dt`), a call (`C(n+1,i)`), a parenthesised group (its parentheses dropped) and an
/// optional `!`. Anything else (`b_i/2`, an operand with unbalanced braces, spaces around the
/// `/`) keeps the `/`. Braces stay balanced: each operand is balanced on its own.
pub(super) fn fractions(m: &str) -> String {
    if !m.contains('/') {
        return m.to_string();
    }
    let c: Vec<char> = m.chars().collect();
    let mut out: Vec<char> = Vec::with_capacity(c.len());
    let mut i = 0;
    while i < c.len() {
        if c[i] == '/' {
            if let (Some(start), Some(end)) = (left_operand(&out), right_operand(&c, i + 1)) {
                let left: String = strip_group(&out[start..]).iter().collect();
                let right: String = strip_group(&c[i + 1..end]).iter().collect();
                out.truncate(start);
                out.extend(format!("\\frac{{{left}}}{{{right}}}").chars());
                i = end;
                continue;
            }
        }
        out.push(c[i]);
        i += 1;
    }
    out.into_iter().collect()
}

/// Whether an operand's braces balance and it holds nothing that ends math mode.
fn fit_operand(o: &[char]) -> bool {
    let mut depth = 0i64;
    let mut k = 0;
    while k < o.len() {
        match o[k] {
            '\\' => k += 1,
            '{' => depth += 1,
            '}' => {
                depth -= 1;
                if depth < 0 {
                    return false;
                }
            }
            '$' => return false,
            _ => {}
        }
        k += 1;
    }
    depth == 0 && !o.is_empty() && o.len() <= MAX_OPERAND
}

/// `(…)` without its parentheses when the operand is just that group.
fn strip_group(o: &[char]) -> &[char] {
    if o.len() >= 2 && o[0] == '(' && o[o.len() - 1] == ')' {
        let mut depth = 0;
        for (k, &ch) in o.iter().enumerate() {
            match ch {
                '(' => depth += 1,
                ')' => {
                    depth -= 1;
                    if depth == 0 && k + 1 < o.len() {
                        return o;
                    }
                }
                _ => {}
            }
        }
        return &o[1..o.len() - 1];
    }
    o
}

/// Where the operand before a `/` starts in `out`, if it is one `fractions` writes.
fn left_operand(out: &[char]) -> Option<usize> {
    let mut k = out.len();
    if k > 0 && out[k - 1] == '!' {
        k -= 1;
    }
    if k > 0 && out[k - 1] == ')' {
        let mut depth = 0;
        let mut j = k;
        loop {
            if j == 0 || k - j > MAX_OPERAND {
                return None;
            }
            j -= 1;
            match out[j] {
                ')' => depth += 1,
                '(' => {
                    depth -= 1;
                    if depth == 0 {
                        break;
                    }
                }
                _ => {}
            }
        }
        k = j;
    }
    while k > 0 && out[k - 1].is_ascii_alphanumeric() && out.len() - k < MAX_OPERAND {
        k -= 1;
    }
    // not the end of a control word (`\infty`), of a longer word, a script's argument or nothing
    let before_ok =
        k == 0 || !(matches!(out[k - 1], '\\' | '_' | '^' | '{' | '}') || out[k - 1].is_ascii_alphanumeric());
    let empty = out[k..].iter().all(|&c| c == '!');
    (before_ok && !empty && fit_operand(&out[k..])).then_some(k)
}

/// Where the operand after a `/` at `j` ends in `c`, if it is one `fractions` writes.
fn right_operand(c: &[char], j: usize) -> Option<usize> {
    let mut k = j;
    while k < c.len() && c[k].is_ascii_alphanumeric() && k - j < MAX_OPERAND {
        k += 1;
    }
    if k < c.len() && c[k] == '(' {
        let mut depth = 0;
        loop {
            if k >= c.len() || k - j > MAX_OPERAND {
                return None;
            }
            match c[k] {
                '(' => depth += 1,
                ')' => {
                    depth -= 1;
                    if depth == 0 {
                        k += 1;
                        break;
                    }
                }
                _ => {}
            }
            k += 1;
        }
    }
    if k < c.len() && c[k] == '!' {
        k += 1;
    }
    // a script after the operand would attach to the fraction
    let scripted = k < c.len() && matches!(c[k], '_' | '^' | '\'');
    (k > j && !scripted && fit_operand(&c[j..k])).then_some(k)
}

/// A formula takes the parentheses its own parentheses pair with from the prose beside it:
/// `(2t−1)³` and `B_i(t)` are formulas as a whole, not `(` and `2t−1)³` (`$B_i(t$)`).
pub(super) fn balance_parentheses(parts: &mut [(Part, String)]) {
    for k in 0..parts.len() {
        if parts[k].0 != Part::Math {
            continue;
        }
        // parentheses closed before any opens, and opened but not closed
        let (mut unopened, mut unclosed) = (0usize, 0usize);
        for c in parts[k].1.chars() {
            match c {
                '(' => unclosed += 1,
                ')' if unclosed > 0 => unclosed -= 1,
                ')' => unopened += 1,
                _ => {}
            }
        }
        if unopened > 0 && k > 0 && parts[k - 1].0 == Part::Prose {
            let prev = &mut parts[k - 1].1;
            let take = prev.chars().rev().take_while(|&c| c == '(').count().min(unopened);
            let moved = "(".repeat(take);
            prev.truncate(prev.len() - take);
            parts[k].1.insert_str(0, &moved);
        }
        if unclosed > 0 && k + 1 < parts.len() && parts[k + 1].0 == Part::Prose {
            let next = &mut parts[k + 1].1;
            let take = next.chars().take_while(|&c| c == ')').count().min(unclosed);
            next.drain(..take);
            let moved = ")".repeat(take);
            parts[k].1.push_str(&moved);
        }
    }
}

/// The length of `(…)` at `i` (parentheses included) when it holds only letters, digits,
/// spaces, `+`, `-`, `−` and `,`: a superscript such as `^(r)`, `^(n+1)`.
pub(super) fn paren_script_len(chars: &[char], i: usize) -> Option<usize> {
    let inner = chars[i + 1..]
        .iter()
        .take(MAX_OPERAND)
        .take_while(|c| c.is_ascii_alphanumeric() || matches!(c, ' ' | '+' | '-' | '−' | ','))
        .count();
    (inner > 0 && chars.get(i + 1 + inner) == Some(&')')).then_some(inner + 2)
}

#[cfg(test)]
mod tests {
    use super::super::{statement, text};

    #[test]
    fn fractions_superscripts_in_parentheses_and_claim_expressions() {
        // fractions, the texts' `^(r)` superscripts, expressions of a claim file as formulas
        assert_eq!(
            statement("b_i^(1) = i/(n+1) b_{i−1}"),
            "$b_i^{(1)} = \\frac{i}{n+1} b_{i-1}$"
        );
        assert_eq!(statement("n!/(n−k)! x"), "$\\frac{n!}{(n-k)!} x$");
        assert_eq!(statement("C(n,i)/C(n+1,i) b_i"), "$\\frac{C(n,i)}{C(n+1,i)} b_i$");
        // a `/` whose operand is scripted, spaced or too long stays
        assert_eq!(statement("b_i/2 + x / y"), "$b_i/2 + x / y$");
        let long = format!("x = {}/2", "7".repeat(50));
        assert_eq!(statement(&long), format!("${long}$"));
        assert_eq!(text("'4/3*B(1, 3, t)' = '1'"), "$\\frac{4}{3}\\cdot B(1, 3, t)$ = $1$");
    }
}
