//! Certificates of proofs by symbolic expansion (`docs/certificates.md`, method `expansion`):
//! the goal written in real symbols only (a vector `v` of dimension d as the tuple
//! `(v_1, …, v_d)`), and per equality the variables and, per pair of entries, both sides
//! expanded as `numerator / denominator`, each a list of monomials with exact coefficients.
//!
//! The re-check expands the goal again with the kernel (`kernel::expand::expand`, then
//! `check_expanded`): that is the proof. Each listed `num / den` must be the kernel's
//! expansion of that side's entry as a rational function (the cross products agree); the
//! lists are there for other checkers and for readers.

use super::sampled::Goal;
use super::{array, contained, field, rational, Res};
use crate::verify::expansion::{in_coordinates, variables};
use crate::verify::kernel::check_expanded;
use crate::verify::kernel::expand::{expand, Expansion, Terms};
use crate::verify::kernel::poly::Poly;
use num_rational::BigRational;
use num_traits::Zero;
use serde_json::{json, Map, Value as Json};
use std::collections::BTreeMap;
use std::rc::Rc;

fn poly_json(p: &Terms) -> Json {
    Json::Array(p.iter().map(|(e, c)| json!([c.to_string(), e])).collect())
}

/// The goal and the `expansion` data of expanded equalities, or why they cannot be written.
pub(super) fn fields(eqs: &[Expansion], out: &mut Map<String, Json>) -> Res<()> {
    let mut symbols: BTreeMap<String, &str> = BTreeMap::new();
    let mut goal_eqs = Vec::new();
    let mut data_eqs = Vec::new();
    for e in eqs {
        let (layout, ints, (lhs, rhs)) = (&e.layout, &e.ints, &e.sides);
        let vars = variables(layout);
        let names = vars
            .iter()
            .map(|v| (v, "real"))
            .chain(ints.keys().map(|k| (k, "integer")));
        for (name, sort) in names {
            if *symbols.entry(name.clone()).or_insert(sort) != sort {
                return Err(format!("'{name}' is both an integer and a real symbol"));
            }
        }
        let known: Vec<String> = vars.iter().chain(ints.keys()).cloned().collect();
        let (l, r) = (in_coordinates(lhs, layout), in_coordinates(rhs, layout));
        for side in [&l, &r] {
            contained(side, &known, &[]).map_err(|why| format!("the goal uses {why}"))?;
        }
        goal_eqs.push(json!({"ints": super::ints_json(ints), "lhs": l.to_string(), "rhs": r.to_string()}));
        let entries: Vec<Json> = e
            .entries
            .iter()
            .map(|[ln, ld, rn, rd]| {
                json!({"lhs": {"num": poly_json(ln), "den": poly_json(ld)},
                       "rhs": {"num": poly_json(rn), "den": poly_json(rd)}})
            })
            .collect();
        data_eqs.push(json!({"vars": vars, "entries": entries}));
    }
    let symbols: Vec<Json> = symbols.iter().map(|(n, s)| json!({"name": n, "sort": s})).collect();
    out.insert(
        "goal".into(),
        json!({"relation": "=", "symbols": symbols, "equalities": goal_eqs}),
    );
    out.insert("expansion".into(), json!({ "equalities": data_eqs }));
    Ok(())
}

/// Largest exponent a listed term may have (the kernel's expansions stay within
/// `MAX_SYMBOLIC_DEGREE`; products of listed and expanded terms stay far below `u16::MAX`).
const MAX_EXPONENT: u64 = 4_096;

/// A listed polynomial: its terms (exponents, coefficient); a monomial listed twice or a zero
/// coefficient is refused.
fn read_poly(v: &Json, vars: usize, at: &str) -> Res<Terms> {
    let list = v.as_array().ok_or_else(|| format!("{at}: not a list of terms"))?;
    let mut terms = Vec::with_capacity(list.len());
    for (k, t) in list.iter().enumerate() {
        let at = format!("{at}[{k}]");
        let pair = t.as_array().filter(|p| p.len() == 2);
        let (c, e) = pair
            .map(|p| (&p[0], &p[1]))
            .ok_or_else(|| format!("{at}: not [coefficient, exponents]"))?;
        let c = c
            .as_str()
            .ok_or_else(|| format!("{at}: the coefficient is not a string"))?;
        let c = rational(c).map_err(|m| format!("{at}: {m}"))?;
        if c.is_zero() {
            return Err(format!("{at}: a zero coefficient"));
        }
        let e = e.as_array().filter(|e| e.len() == vars);
        let e = e.ok_or_else(|| format!("{at}: not one exponent per variable ({vars})"))?;
        let small = |x: &Json| x.as_u64().filter(|&x| x <= MAX_EXPONENT).map(|x| x as u16);
        let e: Option<Vec<u16>> = e.iter().map(small).collect();
        terms.push((
            e.ok_or_else(|| format!("{at}: an exponent is not an integer 0..={MAX_EXPONENT}"))?,
            c,
        ));
    }
    terms.sort();
    if terms.windows(2).any(|w| w[0].0 == w[1].0) {
        return Err(format!("{at}: a monomial is listed twice"));
    }
    Ok(terms)
}

/// The polynomial of `terms` over the variables `names`.
fn poly(names: &Rc<[String]>, terms: &Terms) -> Poly {
    let zero = Poly::constant(names, &BigRational::zero());
    terms.iter().fold(zero, |acc, (e, c)| {
        acc.sub(&Poly::constant(names, &-c).times_monomial(names, e))
    })
}

/// Re-checks an `expansion` certificate: the kernel expands each goal equality again in the
/// listed variables (they must be the goal's real symbols); the cleared difference of every
/// pair of entries must be zero, and each listed `num / den` equal to the kernel's expansion
/// of its side (`num · den' = num' · den`, the listed `den` not zero).
pub(super) fn recheck(cert: &Json, goal: &Goal, method: &str) -> Res<String> {
    let x = field(cert, "expansion", "certificate")?;
    let eqs = array(x, "equalities", "expansion")?;
    if eqs.len() != goal.equalities.len() {
        return Err(format!(
            "expansion.equalities: {} entries for {} goal equalities",
            eqs.len(),
            goal.equalities.len()
        ));
    }
    let mut expanded = Vec::with_capacity(eqs.len());
    let mut terms = 0;
    for (i, (eq, (ints, lhs, rhs, points))) in eqs.iter().zip(&goal.equalities).enumerate() {
        let at = format!("expansion.equalities[{i}]");
        if !points.is_empty() {
            return Err(format!("{at}: an expansion's goal lists no control points"));
        }
        let mut layout: Vec<(String, usize)> = Vec::new();
        for (j, v) in array(eq, "vars", &at)?.iter().enumerate() {
            let name = v.as_str().ok_or_else(|| format!("{at}.vars[{j}]: not a string"))?;
            if !goal.reals.iter().any(|r| r == name) {
                return Err(format!("{at}.vars[{j}]: '{name}' is not a real symbol of the goal"));
            }
            layout.push((name.to_string(), 0));
        }
        let e = expand(&layout, lhs, rhs, ints).map_err(|m| format!("equality {i}: {m}"))?;
        if e.difference().is_some() {
            return Err(format!(
                "equality {i}: the cleared difference of the sides is not the zero polynomial"
            ));
        }
        let listed = array(eq, "entries", &at)?;
        let kernel = &e.record.entries;
        let names: Rc<[String]> = layout.iter().map(|(v, _)| v.clone()).collect();
        if listed.len() != kernel.len() {
            return Err(format!(
                "{at}.entries: {} pairs of entries, the sides have {}",
                listed.len(),
                kernel.len()
            ));
        }
        for (k, (item, polys)) in listed.iter().zip(kernel).enumerate() {
            let (mut listed, mut own) = (Vec::with_capacity(4), Vec::with_capacity(4));
            for (p, (side, part)) in polys
                .iter()
                .zip([("lhs", "num"), ("lhs", "den"), ("rhs", "num"), ("rhs", "den")])
            {
                let where_ = format!("{at}.entries[{k}].{side}.{part}");
                let file = read_poly(field(field(item, side, &at)?, part, &where_)?, layout.len(), &where_)?;
                terms += file.len();
                listed.push(poly(&names, &file));
                own.push(poly(&names, p));
            }
            let at = |side: &str| format!("{at}.entries[{k}].{side}");
            if listed[1].is_zero() || listed[3].is_zero() {
                return Err(format!(
                    "{}: a listed denominator is the zero polynomial",
                    at("lhs or rhs")
                ));
            }
            for (side, i) in [("lhs", 0), ("rhs", 2)] {
                let cross = listed[i].mul(&own[i + 1]).sub(&own[i].mul(&listed[i + 1]));
                if !cross.is_zero() {
                    return Err(format!(
                        "{}: num/den is not the kernel's expansion of the {side} side",
                        at(side)
                    ));
                }
            }
        }
        expanded.push(e);
    }
    let proof = check_expanded(&expanded).ok_or("the kernel refuses the expansion")?;
    let derived = super::method_name(proof.method());
    if derived != method {
        return Err(format!("method: the file says {method}, the data is {derived}"));
    }
    Ok(format!(
        "{} equalities, expanded again exactly as rational functions: the cleared differences are 0, the {terms} listed terms agree",
        expanded.len()
    ))
}
