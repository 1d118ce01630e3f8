//! The `casteljau` command: prove the texts' claims, compute on exact data, serve the oracle.
//!
//! Exit status: 0 on success, 1 when `prove` finds a verdict other than the expected one,
//! 2 for usage errors, bad input and I/O errors (one clear line on stderr, never a panic: a
//! message of several lines, such as a TOML error with its snippet, is joined with ` | `).

use casteljau::figure::FigureRequest;
use casteljau::float::nearest_f64;
use casteljau::oracle::{self, check_weight_count, Answer, FloatMethod, Op};
use casteljau::verify::{check_certificates, write_certificates, Recheck};
use casteljau::verify::{
    claims, explain_files, identity_file, prove_files, prove_files_without_certificates, ExplainStyle, Verdict,
};
use casteljau::CubicFitData;
use casteljau::{parse_count, parse_net, parse_number, parse_numbers, parse_point, parse_points};
use casteljau::{BezierCurve, BezierSurface, BigRational, Error, Point, RationalBezierCurve};
use clap::{Parser, Subcommand, ValueEnum};
use serde_json::{json, Value};
use std::io::{self, IsTerminal, Write};
use std::path::{Path, PathBuf};

// A folder of the binary's own modules (outside the library's layers).
#[path = "main/prove.rs"]
mod prove;
use prove::{prove, recheck_status, recheck_summary, Reports};
use std::process::ExitCode;

#[derive(Parser)]
#[command(
    name = "casteljau",
    version,
    about = "Exact Bézier geometry: prove the texts' claims, compute with exact fractions, serve an oracle",
    after_help = "Numbers are exact: 3, -4/3, 0.25, 1e-3. Points: \"0,0; 4/3,-4/3; 4/3,4/3; 0,0\". \
                  Nets: rows separated by '|'.\nExit status: 0 ok, 1 a claim did not get its expected verdict, \
                  2 bad usage or input."
)]
struct Cli {
    /// Output format (default text; `figure` writes SVG or, with --interactive, HTML, and takes none).
    #[arg(long, global = true, value_enum)]
    format: Option<Format>,
    #[command(subcommand)]
    command: Command,
}

#[derive(Clone, Copy, PartialEq, Eq, ValueEnum)]
enum Format {
    /// Exact fractions for people.
    Text,
    /// One JSON object, the same fields as the oracle's answer.
    Json,
    /// A LaTeX fragment (`eval --scheme` and `prove --explain` only).
    Latex,
}

#[derive(Clone, Copy, PartialEq, Eq, ValueEnum)]
enum MethodArg {
    /// Plain de Casteljau, with its a priori and running bounds.
    DeCasteljau,
    /// Compensated de Casteljau (about twice the working precision), with its bound.
    Compensated,
    /// Interval arithmetic: an enclosure of the exact value.
    Interval,
}

#[derive(Subcommand)]
enum Command {
    /// Check every claim in the claim files (default: proofs/, else the texts' claims built in); exit 1 on a mismatch.
    Prove {
        /// Claim files or directories (default: proofs/ when present, else the four texts' claims built into the program).
        paths: Vec<PathBuf>,
        /// Print the proof of one claim instead: the argument and one worked case (with --identity, no ID).
        #[arg(long, value_name = "ID", num_args = 0..=1, default_missing_value = "")]
        explain: Option<String>,
        /// Check one identity instead of claim files: "lhs = rhs", read as a claim file's lhs and rhs.
        #[arg(long, value_name = "LHS = RHS", conflicts_with_all = ["paths", "html"], allow_hyphen_values = true)]
        identity: Option<String>,
        /// With --identity: an integer range, "n = 0..=10" or "n = 0.." (every n); repeatable.
        #[arg(long = "for", value_name = "RANGE", requires = "identity")]
        ranges: Vec<String>,
        /// With --identity: the continuous parameters, e.g. "t,u" (default: the free one-letter names).
        #[arg(long, value_name = "NAMES", requires = "identity", value_delimiter = ',')]
        vars: Option<Vec<String>>,
        /// With --explain: also the full log of every checked case (text and JSON only).
        #[arg(long, requires = "explain")]
        verbose: bool,
        /// Also write a static HTML report (index, one page per text, figures) into DIR.
        #[arg(long, value_name = "DIR", conflicts_with = "explain")]
        html: Option<PathBuf>,
        /// Also write a students' handout into DIR (statements, worked cases, figures, misprints; no ids).
        #[arg(long, value_name = "DIR", conflicts_with_all = ["explain", "identity"])]
        handout: Option<PathBuf>,
        /// With --html or --handout: overwrite an existing report (DIR/index.html).
        #[arg(long)]
        force: bool,
        /// Also write one certificate per claim into DIR, as DIR/<id>.json (docs/certificates.md).
        #[arg(long, value_name = "DIR", conflicts_with = "explain")]
        certificates: Option<PathBuf>,
        /// With --certificates: re-check the written certificates with the kernel (a self-test).
        #[arg(long, requires = "certificates")]
        check: bool,
    },
    /// Re-check certificate files (or directories of them) with the kernel alone; exit 1 if one is refused.
    Check {
        /// Certificate files, or directories whose .json files are read.
        #[arg(required = true)]
        paths: Vec<PathBuf>,
    },
    /// Evaluate b(t) exactly by de Casteljau's algorithm (a rational curve with --weights).
    Eval {
        /// Control points, e.g. "0,0; 4/3,-4/3; 4/3,4/3; 0,0".
        #[arg(allow_hyphen_values = true)]
        points: String,
        /// The parameter.
        #[arg(long, allow_hyphen_values = true)]
        t: String,
        /// Print the whole triangular scheme (9) (polynomial curves).
        #[arg(long, conflicts_with = "weights")]
        scheme: bool,
        /// Weights of a rational curve, one per control point, e.g. "1, 1/2, 1".
        #[arg(long, allow_hyphen_values = true)]
        weights: Option<String>,
        /// Evaluate in f64 (every number read as its nearest f64) and judge the result exactly.
        #[arg(long = "f64", conflicts_with_all = ["scheme", "weights"])]
        float: bool,
        /// The f64 evaluator (with --f64; default compensated).
        #[arg(long, value_enum, requires = "float")]
        method: Option<MethodArg>,
    },
    /// The type and implicit equation of the conic through a rational quadratic arc.
    Conic {
        /// Three planar control points.
        #[arg(allow_hyphen_values = true)]
        points: String,
        /// Their weights, e.g. "1, 1/2, 1".
        #[arg(long, allow_hyphen_values = true)]
        weights: String,
    },
    /// Evaluate a tensor-product surface b(u, v) exactly.
    Surface {
        /// The control net: rows i = 0..m separated by '|', each row the points j = 0..n.
        #[arg(allow_hyphen_values = true)]
        net: String,
        /// The parameter u (along the rows' index i).
        #[arg(long, allow_hyphen_values = true)]
        u: String,
        /// The parameter v (along a row, index j).
        #[arg(long, allow_hyphen_values = true)]
        v: String,
    },
    /// Text 004's cubic fit from x(0), x(1), x(1/2), x'(0), x'(1).
    Fit {
        /// x(0).
        #[arg(long, allow_hyphen_values = true)]
        x0: String,
        /// x(1).
        #[arg(long, allow_hyphen_values = true)]
        x1: String,
        /// x(1/2).
        #[arg(long, allow_hyphen_values = true)]
        xh: String,
        /// x'(0).
        #[arg(long, allow_hyphen_values = true)]
        d0: String,
        /// x'(1).
        #[arg(long, allow_hyphen_values = true)]
        d1: String,
    },
    /// Elevate the degree by r (formula (8)).
    Elevate {
        /// Control points.
        #[arg(allow_hyphen_values = true)]
        points: String,
        /// Number of elevation steps r.
        #[arg(long, value_name = "R", allow_hyphen_values = true)]
        by: String,
    },
    /// Subdivide at t: the control points of both pieces.
    Split {
        /// Control points.
        #[arg(allow_hyphen_values = true)]
        points: String,
        /// The parameter.
        #[arg(long, allow_hyphen_values = true)]
        t: String,
    },
    /// The control points of the k-th derivative curve (with n!/(n-k)!), or its vector at t.
    Derivative {
        /// Control points.
        #[arg(allow_hyphen_values = true)]
        points: String,
        /// The order k.
        #[arg(long, value_name = "K", default_value = "1", allow_hyphen_values = true)]
        order: String,
        /// Print the derivative vector at this parameter instead.
        #[arg(long, value_name = "T", allow_hyphen_values = true)]
        at: Option<String>,
    },
    /// Bézier points of the polynomial curve a_0 + a_1 t + … + a_n t^n on [0, 1].
    ToBezier {
        /// The coefficient vectors a_0; a_1; …; a_n, e.g. "0,1; 4,0; -4,0".
        #[arg(allow_hyphen_values = true)]
        power: String,
    },
    /// Serve exact answers to JSON requests, one per line on stdin (see docs).
    Oracle,
    /// Draw a figure from exact data as SVG (defaults: the texts' examples).
    #[command(
        after_help = "Figures: construction, subdivision (--t), elevation (--steps), hodograph, \
                            hull (--point), conics (--weights: middle weights), net (--iso), enneper, \
                            fit (--weights: a rational curve's weights), bernstein (--degree, --t), projection.\nInput: control points \
                            \"0,0; 1,2; 3,0\", or a net with rows separated by '|'."
    )]
    Figure {
        /// construction, subdivision, elevation, hodograph, hull, conics, net, enneper, fit,
        /// bernstein or projection.
        what: String,
        /// Control points or a control net (default: the texts' example).
        #[arg(allow_hyphen_values = true)]
        input: Option<String>,
        /// The parameter (construction, subdivision; default 1/2; bernstein: 1/3).
        #[arg(long, allow_hyphen_values = true)]
        t: Option<String>,
        /// Elevation steps, e.g. "1, 2, 4, 8" (elevation).
        #[arg(long)]
        steps: Option<String>,
        /// The point whose hull weights are drawn (hull; default b(1/3)).
        #[arg(long, allow_hyphen_values = true)]
        point: Option<String>,
        /// Middle weights (conics) or a rational curve's weights (fit).
        #[arg(long, allow_hyphen_values = true)]
        weights: Option<String>,
        /// Iso-curves per direction (net; default 4).
        #[arg(long)]
        iso: Option<String>,
        /// The degree of the basis (bernstein; default 3).
        #[arg(long)]
        degree: Option<String>,
        /// Write the SVG here (default: standard output).
        #[arg(short, long, value_name = "FILE")]
        output: Option<PathBuf>,
        /// Write one self-contained HTML page instead, with draggable points and sliders (construction,
        /// subdivision, elevation, hodograph, conics, bernstein).
        #[arg(long)]
        interactive: bool,
    },
}

fn main() -> ExitCode {
    let cli = match Cli::try_parse() {
        Ok(cli) => cli,
        // clap prints help and version to stdout with status 0; a usage error is one line
        Err(e) if !e.use_stderr() => e.exit(),
        Err(e) => {
            let text = e.render().to_string();
            // the first paragraph is the message (a list of missing arguments follows it)
            let message: Vec<&str> = text
                .lines()
                .take_while(|l| !l.trim().is_empty())
                .map(str::trim)
                .collect();
            let message = message.join(" ");
            eprintln!(
                "casteljau: {} (see casteljau --help)",
                message.trim_start_matches("error: ")
            );
            return ExitCode::from(2);
        }
    };
    match std::panic::catch_unwind(|| run(cli)) {
        Ok(Ok(code)) => code,
        Ok(Err(message)) => {
            // one line, whatever the message holds (a TOML snippet, an input with a newline)
            let one_line: Vec<&str> = message
                .lines()
                .map(str::trim_end)
                .filter(|l| !l.trim().is_empty())
                .collect();
            eprintln!("casteljau: {}", one_line.join(" | "));
            ExitCode::from(2)
        }
        Err(_) => {
            eprintln!("casteljau: internal error (a bug in casteljau: please report the command line)");
            ExitCode::from(2)
        }
    }
}

/// Runs one command; `Err` is the one-line message for stderr (exit status 2).
fn run(cli: Cli) -> Result<ExitCode, String> {
    let format = cli.format.unwrap_or(Format::Text);
    let e = |e: Error| e.to_string();
    match cli.command {
        Command::Prove {
            paths,
            explain: id,
            identity,
            ranges,
            vars,
            verbose,
            html,
            handout,
            force,
            certificates,
            check,
        } => {
            if force && html.is_none() && handout.is_none() {
                return Err("--force applies only with --html or --handout".into());
            }
            prove(
                &paths,
                identity.map(|i| (i, ranges, vars)),
                id.as_deref(),
                verbose,
                Reports {
                    html: html.as_deref(),
                    handout: handout.as_deref(),
                    force,
                    certificates: certificates.as_deref(),
                    check,
                },
                format,
            )
        }
        Command::Figure {
            what,
            input,
            t,
            steps,
            point,
            weights,
            iso,
            degree,
            output: out,
            interactive,
        } => {
            if cli.format.is_some() {
                return Err("--format does not apply to `figure` (it writes SVG, or HTML with --interactive)".into());
            }
            let request = FigureRequest {
                kind: what.parse().map_err(e)?,
                input,
                t,
                steps,
                point,
                weights,
                iso,
                degree,
            };
            let svg = if interactive {
                casteljau::html::interactive::interactive_page(&request).map_err(e)?
            } else {
                request.figure().and_then(|f| f.to_svg()).map_err(e)?
            };
            match out {
                Some(path) => {
                    std::fs::write(&path, svg).map_err(|err| format!("cannot write {}: {err}", path.display()))?
                }
                None => output(&svg)?,
            }
            Ok(ExitCode::SUCCESS)
        }
        Command::Check { paths } => {
            if matches!(format, Format::Latex) {
                return Err("--format latex does not apply to `check`".into());
            }
            let checked = check_certificates(&paths).map_err(e)?;
            let (line, refused) = recheck_summary(&checked);
            match format {
                Format::Json => {
                    let files: Vec<Value> = checked
                        .iter()
                        .map(|(path, r)| {
                            let (status, detail) = recheck_status(r);
                            json!({"file": path.display().to_string(), "status": status, "detail": detail})
                        })
                        .collect();
                    output(&format!("{}\n", json!({"files": files, "summary": line})))?;
                }
                _ => {
                    let mut text = String::new();
                    for (path, r) in &checked {
                        let (status, detail) = recheck_status(r);
                        text.push_str(&format!("{}: {status}: {detail}\n", path.display()));
                    }
                    text.push_str(&line);
                    text.push('\n');
                    output(&text)?;
                }
            }
            Ok(if refused > 0 {
                ExitCode::from(1)
            } else {
                ExitCode::SUCCESS
            })
        }
        Command::Oracle => {
            let output = io::BufWriter::with_capacity(oracle::READ_CHUNK_BYTES, io::stdout().lock());
            match oracle::serve(io::stdin().lock(), output) {
                Ok(()) => Ok(ExitCode::SUCCESS),
                // the client closed its end: nobody is left to answer
                Err(err) if err.kind() == io::ErrorKind::BrokenPipe => Ok(ExitCode::SUCCESS),
                Err(err) => Err(format!("oracle: {err}")),
            }
        }
        Command::Eval {
            points,
            t,
            weights: Some(weights),
            ..
        } => {
            let op = Op::RationalEval {
                curve: rational_arg(&points, &weights)?,
                t: number_arg("--t", &t)?,
                approx: None,
            };
            emit(&op.run().map_err(e)?, format, None)
        }
        Command::Eval {
            points,
            t,
            float: true,
            method,
            ..
        } => {
            let nearest = |x: &BigRational| {
                BigRational::from_float(nearest_f64(x)).ok_or_else(|| format!("{x} is beyond the f64 range"))
            };
            let curve = curve_arg(&points)?;
            let curve = BezierCurve::new(
                curve
                    .points()
                    .iter()
                    .map(|p| Point::new(p.coords().iter().map(nearest).collect::<Result<_, _>>()?).map_err(e))
                    .collect::<Result<_, _>>()?,
            )
            .map_err(e)?;
            let op = Op::FloatEval {
                curve,
                t: nearest(&number_arg("--t", &t)?)?,
                method: match method.unwrap_or(MethodArg::Compensated) {
                    MethodArg::DeCasteljau => FloatMethod::DeCasteljau,
                    MethodArg::Compensated => FloatMethod::Compensated,
                    MethodArg::Interval => FloatMethod::Interval,
                },
            };
            emit(&op.run().map_err(e)?, format, None)
        }
        Command::Conic { points, weights } => {
            let op = Op::Conic {
                curve: rational_arg(&points, &weights)?,
            };
            emit(&op.run().map_err(e)?, format, None)
        }
        Command::Surface { net, u, v } => {
            let net = parse_net(&net).map_err(|err| format!("control net: {err}"))?;
            let op = Op::SurfaceEval {
                surface: BezierSurface::new(net).map_err(|err| format!("control net: {err}"))?,
                u: number_arg("--u", &u)?,
                v: number_arg("--v", &v)?,
                approx: None,
            };
            emit(&op.run().map_err(e)?, format, None)
        }
        Command::Fit { x0, x1, xh, d0, d1 } => {
            let data = CubicFitData::new(
                point_arg("--x0", &x0)?,
                point_arg("--x1", &x1)?,
                point_arg("--xh", &xh)?,
                point_arg("--d0", &d0)?,
                point_arg("--d1", &d1)?,
            )
            .map_err(e)?;
            emit(&Op::FitCubic { data }.run().map_err(e)?, format, None)
        }
        Command::Eval { points, t, scheme, .. } => {
            let curve = curve_arg(&points)?;
            let t = number_arg("--t", &t)?;
            let op = Op::Eval {
                curve: curve.clone(),
                t: t.clone(),
                approx: None,
            };
            let answer = op.run().map_err(e)?;
            if !scheme {
                return emit(&answer, format, None);
            }
            // the scheme is the whole triangle of exact lerps (this also bounds the printed size)
            casteljau::oracle::check_scheme_work(&curve, &t).map_err(|err| format!("--scheme: {err}"))?;
            let scheme = curve.scheme(&t);
            match format {
                Format::Text => {
                    output(&format!("{scheme}b({}) = {}\n", t, answer.to_text()))?;
                    Ok(ExitCode::SUCCESS)
                }
                Format::Latex => {
                    output(&scheme.to_latex())?;
                    Ok(ExitCode::SUCCESS)
                }
                Format::Json => {
                    let columns: Vec<Value> = scheme
                        .columns
                        .iter()
                        .map(|c| casteljau::oracle::points_to_json(c))
                        .collect();
                    emit(&answer, format, Some(("scheme", Value::Array(columns))))
                }
            }
        }
        Command::Elevate { points, by } => {
            let op = Op::Elevate {
                curve: curve_arg(&points)?,
                by: parse_count(&by, "--by").map_err(e)?,
            };
            emit(&op.run().map_err(e)?, format, None)
        }
        Command::Split { points, t } => {
            let op = Op::Split {
                curve: curve_arg(&points)?,
                t: number_arg("--t", &t)?,
            };
            emit(&op.run().map_err(e)?, format, None)
        }
        Command::Derivative { points, order, at } => {
            let op = Op::Derivative {
                curve: curve_arg(&points)?,
                order: parse_count(&order, "--order").map_err(e)?,
                at: at.as_deref().map(|t| number_arg("--at", t)).transpose()?,
            };
            emit(&op.run().map_err(e)?, format, None)
        }
        Command::ToBezier { power } => {
            let coeffs = parse_points(&power).map_err(|err| format!("coefficients: {err}"))?;
            let dim = coeffs[0].dim();
            let op = Op::ToBezier {
                power: (0..dim)
                    .map(|k| coeffs.iter().map(|a| a.coords()[k].clone()).collect())
                    .collect(),
            };
            emit(&op.run().map_err(e)?, format, None)
        }
    }
}

fn curve_arg(text: &str) -> Result<BezierCurve<BigRational>, String> {
    let points = parse_points(text).map_err(|e| format!("control points: {e}"))?;
    BezierCurve::new(points).map_err(|e| format!("control points: {e}"))
}

fn rational_arg(points: &str, weights: &str) -> Result<RationalBezierCurve<BigRational>, String> {
    let points = parse_points(points).map_err(|e| format!("control points: {e}"))?;
    let weights = parse_numbers(weights).map_err(|e| format!("--weights: {e}"))?;
    check_weight_count(points.len(), weights.len()).map_err(|e| format!("--weights: {e}"))?;
    RationalBezierCurve::new(points, weights).map_err(|e| e.to_string())
}

fn point_arg(flag: &str, text: &str) -> Result<Point<BigRational>, String> {
    parse_point(text).map_err(|e| format!("{flag}: {e}"))
}

fn number_arg(flag: &str, text: &str) -> Result<BigRational, String> {
    parse_number(text).map_err(|e| format!("{flag}: {e}"))
}

const LATEX_ONLY: &str = "--format latex is for `eval --scheme` and `prove --explain` only";

/// Prints an answer as text, or as the oracle's JSON object (plus an `extra` field).
fn emit(answer: &Answer, format: Format, extra: Option<(&str, Value)>) -> Result<ExitCode, String> {
    match format {
        Format::Latex => return Err(LATEX_ONLY.into()),
        Format::Text => output(&format!("{}\n", answer.to_text()))?,
        Format::Json => {
            let mut m = answer.to_json();
            m.insert("ok".into(), json!(true));
            if let Some((k, v)) = extra {
                m.insert(k.into(), v);
            }
            output(&format!("{}\n", Value::Object(m)))?;
        }
    }
    Ok(ExitCode::SUCCESS)
}

/// Writes to stdout. `println!` would panic when the reader has gone (`casteljau … | head`);
/// a closed pipe just means nobody wants the rest, so the command ends quietly.
fn output(text: &str) -> Result<(), String> {
    let mut out = io::stdout().lock();
    match out.write_all(text.as_bytes()).and_then(|()| out.flush()) {
        Ok(()) => Ok(()),
        Err(e) if e.kind() == io::ErrorKind::BrokenPipe => std::process::exit(0),
        Err(e) => Err(format!("cannot write the output: {e}")),
    }
}
