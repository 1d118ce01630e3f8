//! The expected syntax of each claim-file field, shown with a reading error: serde's own
//! message ("invalid type: map, expected a sequence") names neither the field nor the form
//! an author should write.

use serde::de::DeserializeOwned;

/// A reading error of one claim: the field at fault (when one is) and the message.
#[derive(Debug)]
pub(super) struct FieldError {
    pub field: Option<String>,
    pub message: String,
}

impl FieldError {
    /// An error no single field explains.
    pub fn whole(message: impl Into<String>) -> Self {
        FieldError {
            field: None,
            message: message.into(),
        }
    }

    /// The message followed by the field's expected form, if the field has one.
    pub fn with_syntax(&self) -> String {
        match self.field.as_deref().and_then(expected) {
            Some(form) => format!("{}; expected: {form}", self.message),
            None => self.message.clone(),
        }
    }
}

/// How a field is written, with an example (the claim format's reference is proofs/README.md).
pub(super) fn expected(field: &str) -> Option<&'static str> {
    Some(match field {
        "id" => r#"id = "000-ex4-x" (a string, unique in the file)"#,
        "source" => r#"source = "000_ef6a3958c7d702f5.txt 4)" (the text file and the printed label)"#,
        "statement" => r#"statement = 'the claim as printed' (a string)"#,
        "kind" => r#"kind = "identity" (a string: one of the kinds in proofs/README.md)"#,
        "expect" => r#"expect = "fails" (one of "proved", "proved_in_range", "verified", "fails")"#,
        "corrects" => r#"corrects = "000-ex4-y" (the id of the misprinted claim)"#,
        "note" => r#"note = "a remark" (a string)"#,
        "figure" => {
            r#"figure = "subdivision" (construction, subdivision, elevation, hodograph, hull, fit, conics or projection)"#
        }
        "uses" => r#"uses = ["000-9-intermediate"] (a list of claim ids)"#,
        "vars" => r#"vars = ["t"] or vars = ["s", "t"] (a list of parameter names)"#,
        "for" => {
            r#"for = ["n = 0..=10", "j = 0..=n"] or, for every n, for = ["n = 0.."] (a list of ranges, each a string)"#
        }
        "let" => r#"let = ["X = x0 + x1 - 2xh", "f(i) = i/(n+1)"] (a list of definitions, each a string)"#,
        "polygon" => r#"polygon = { name = "b", degree = "n" } (the degree a string)"#,
        "net" => r#"net = { name = "b", degree = ["m", "n"] } (two degrees, each a string)"#,
        "symbols" => r#"symbols = ["k", "l"] (a list of names)"#,
        "vectors" => r#"vectors = { x0 = 3, d0 = 3 } (each name = its dimension, an integer)"#,
        "curves" => r#"curves = { b = { points = [[0, 0], ["4/3", "-4/3"]], weights = [1, 2] } } (weights optional)"#,
        "surfaces" => r#"surfaces = { x = { net = [[[0, 0, 0], [0, 1, 0]], [[1, 0, 0], [1, 1, 1]]] } }"#,
        "lhs" | "rhs" => r#"lhs = "(1 - t)^2" and rhs = "B(0, 2, t)" (each a string), or chain = ["a", "b", "c"]"#,
        "chain" => r#"chain = ["a", "b", "c"] (a list of expressions, each a string)"#,
        "certificate" => r#"certificate = "R" or certificate = ["R1", "R2"] (WZ certificates, strings)"#,
        "induction" => r#"induction = "r" (a range variable)"#,
        "interval" => r#"interval = [0, 1] or interval = ["-1", "1/2"] (two exact numbers)"#,
        "points" => r#"points = [[0, 0], ["4/3", "-4/3"]] (a list of points, numbers as integers or strings)"#,
        "weights" => r#"weights = [1, "1/2", 1] (one exact number per point)"#,
        "power" | "on" | "premise" | "factor" | "expr" => r#"a string holding an expression, e.g. "(2t - 1)^2""#,
        "equation" => r#"equation = "4x^2 + 3y^2 - 10y + 3 = 0" (a string)"#,
        "param" => r#"param = "u" (a name)"#,
        "coords" => r#"coords = ["x", "y"] (a list of names)"#,
        "conic" => r#"conic = "ellipse" (ellipse, parabola or hyperbola)"#,
        "theorem" => r#"theorem = "subdivision" (a theorem's name, see proofs/README.md)"#,
        "degrees" => r#"degrees = "0..=10" (a string)"#,
        "steps" => r#"steps = 64 (an integer)"#,
        "k" | "l" | "delta2" => r#"k = "1/3" (an exact number: an integer or a string)"#,
        "relation" => r#"relation = ">=" or relation = ">""#,
        "claim" => r#"[[claim]] (double brackets: each claim is one table of an array of tables)"#,
        "text" => r#"[text] with file = "000_ef6a3958c7d702f5.txt" and title = "…""#,
        _ => return None,
    })
}

/// Reads `table` as `T`; an error names the field at fault: the one serde says is missing,
/// or the one whose removal changes the error (then that field's value is what was refused).
pub(super) fn read<T: DeserializeOwned>(table: toml::Table) -> Result<T, FieldError> {
    let message = match table.clone().try_into::<T>() {
        Ok(v) => return Ok(v),
        Err(e) => e.message().to_string(),
    };
    let missing = message
        .strip_prefix("missing field `")
        .and_then(|m| m.strip_suffix('`'))
        .map(str::to_string);
    let field = missing.or_else(|| {
        table.keys().find_map(|k| {
            let mut without = table.clone();
            without.remove(k);
            let other = without.try_into::<T>().err().map(|e| e.message().to_string());
            (other.as_deref() != Some(message.as_str())).then(|| k.clone())
        })
    });
    Err(FieldError { field, message })
}

/// The line (1-based, in the whole file) where `field` is set inside the claim that starts
/// at byte `start` and ends at byte `end` of `text`, if it is written there as `field = …`.
pub(super) fn field_line(text: &str, start: usize, end: usize, field: &str) -> Option<usize> {
    let (start, end) = (start.min(text.len()), end.min(text.len()));
    let before = text.get(..start)?.matches('\n').count();
    text.get(start..end)?.lines().enumerate().find_map(|(i, l)| {
        let rest = l.trim_start().strip_prefix(field)?;
        rest.trim_start().starts_with('=').then_some(before + i + 1)
    })
}
