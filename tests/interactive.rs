//! The interactive figures' starting state: every exact value written into the page (its
//! `data-exact` attribute) equals the oracle's answer for the page's own points and t, byte for
//! byte — the same comparison scripts/browser_test.sh makes in a browser after each move.
//! Also: the page is self-contained, bad requests are clear errors, and the report links the
//! pages it writes.

use casteljau::figure::{FigureKind, FigureRequest};
use casteljau::html::interactive::{interactive_page, INTERACTIVE_KINDS};
use casteljau::oracle::handle_line;
use serde_json::{json, Value};
use std::collections::BTreeMap;
use std::process::Command;

fn unescape(s: &str) -> String {
    s.replace("&quot;", "\"")
        .replace("&#39;", "'")
        .replace("&lt;", "<")
        .replace("&gt;", ">")
        .replace("&amp;", "&")
}

/// `id → (data-exact, text)` of every value element of a page.
fn shown(page: &str) -> BTreeMap<String, (String, String)> {
    let mut out = BTreeMap::new();
    for piece in page.split("<dd id=\"").skip(1) {
        let (id, rest) = piece.split_once('"').unwrap();
        let rest = rest.strip_prefix(" data-exact=\"").unwrap();
        let (exact, rest) = rest.split_once('"').unwrap();
        let text = rest.strip_prefix('>').unwrap().split_once("</dd>").unwrap().0;
        out.insert(id.to_string(), (unescape(exact), unescape(text)));
    }
    out
}

/// The page's starting state (the JSON its script reads).
fn state(page: &str) -> Value {
    let json = page
        .split_once("<script type=\"application/json\" id=\"state\">")
        .unwrap()
        .1
        .split_once("</script>")
        .unwrap()
        .0;
    serde_json::from_str(json).unwrap()
}

fn ask(request: Value) -> Value {
    let answer: Value = serde_json::from_str(&handle_line(&request.to_string())).unwrap();
    assert_eq!(answer["ok"], true, "{request}: {answer}");
    answer
}

/// The oracle's answers for the page's points and t, as `id → data-exact`.
fn expected(page: &str) -> BTreeMap<String, String> {
    let s = state(page);
    let points: Vec<Value> = s["points"].as_array().unwrap().clone();
    let t = s["t"].clone();
    let mut out = BTreeMap::new();
    let mut put = |id: String, v: &Value| out.insert(id, v.to_string());
    for (i, p) in points.iter().enumerate() {
        put(format!("p-{i}"), p);
    }
    let kind = s["kind"].as_str().unwrap();
    if kind != "elevation" {
        put("t-value".into(), &t);
    }
    match kind {
        "construction" => {
            for r in 0..points.len() {
                for i in 0..points.len() - r {
                    let a = ask(json!({"op": "eval", "points": &points[i..=i + r], "t": t}));
                    put(format!("b-{r}-{i}"), &a["point"]);
                }
            }
        }
        "subdivision" => {
            let a = ask(json!({"op": "split", "points": points, "t": t}));
            put("left".into(), &a["left"]);
            put("right".into(), &a["right"]);
        }
        "elevation" => {
            let r = s["r"].as_u64().unwrap();
            let a = ask(json!({"op": "elevate", "points": points, "by": r}));
            put("r-value".into(), &json!(r.to_string()));
            put("elevated".into(), &a["points"]);
        }
        "hodograph" => {
            put(
                "point".into(),
                &ask(json!({"op": "eval", "points": points, "t": t}))["point"],
            );
            let h = ask(json!({"op": "derivative", "points": points, "order": 1}));
            put("hodograph".into(), &h["points"]);
            let v = ask(json!({"op": "derivative", "points": points, "order": 1, "t": t}));
            put("vector".into(), &v["vector"]);
        }
        "conics" => {
            let weights = json!(["1", s["w"], "1"]);
            let x = ask(json!({"op": "rational_eval", "points": points, "weights": weights, "t": t}));
            let c = ask(json!({"op": "conic", "points": points, "weights": weights}));
            put("w-value".into(), &s["w"]);
            put("point".into(), &x["point"]);
            put("type".into(), &c["type"]);
            put("implicit".into(), &c["implicit"]);
        }
        "bernstein" => {
            let n = s["n"].as_u64().unwrap() as usize;
            let unit: Vec<Vec<&str>> = (0..=n)
                .map(|i| (0..=n).map(|j| if i == j { "1" } else { "0" }).collect())
                .collect();
            let a = ask(json!({"op": "eval", "points": unit, "t": t}));
            put("n-value".into(), &json!(n.to_string()));
            put("basis".into(), &a["point"]);
        }
        k => panic!("unknown kind {k}"),
    }
    out
}

fn request(kind: FigureKind, input: Option<&str>, opts: &[(&str, &str)]) -> FigureRequest {
    let mut r = FigureRequest::new(kind);
    r.input = input.map(String::from);
    for (k, v) in opts {
        let v = Some(v.to_string());
        match *k {
            "t" => r.t = v,
            "steps" => r.steps = v,
            "weights" => r.weights = v,
            "degree" => r.degree = v,
            "point" => r.point = v,
            _ => unreachable!(),
        }
    }
    r
}

fn check(page: &str) -> usize {
    let shown = shown(page);
    let expected = expected(page);
    let got: BTreeMap<String, String> = shown.iter().map(|(k, (e, _))| (k.clone(), e.clone())).collect();
    assert_eq!(got, expected);
    expected.len()
}

#[test]
fn the_starting_values_are_the_oracles() {
    for kind in INTERACTIVE_KINDS {
        let page = interactive_page(&FigureRequest::new(kind)).unwrap();
        assert!(check(&page) >= 3, "{}", kind.name());
    }
    // other data: degree 5 with big-ish fractions, t off the Farey list, every option
    let cases: Vec<FigureRequest> = vec![
        request(
            FigureKind::Construction,
            Some("0,0; 1/7,3; -2,5/3; 4,4; 5,-1; 6,0"),
            &[("t", "13/17")],
        ),
        request(FigureKind::Subdivision, Some("-3,1/2; 1,9; 4,-2"), &[("t", "0")]),
        request(FigureKind::Elevation, Some("0,0; 1,2; 3,2; 4,0"), &[("steps", "16")]),
        request(FigureKind::Hodograph, Some("0,0; 2,3"), &[("t", "1")]),
        request(
            FigureKind::Conics,
            Some("0,0; 1,1; 2,0"),
            &[("t", "2/5"), ("weights", "7/3")],
        ),
        request(FigureKind::Conics, Some("0,0; 1,1; 2,2"), &[("weights", "1")]),
        request(FigureKind::Bernstein, None, &[("t", "5/7"), ("degree", "10")]),
    ];
    for r in &cases {
        let page = interactive_page(r).unwrap();
        check(&page);
        // the starting t is on the slider, and the slider starts at it
        let s = state(&page);
        if let Some(t) = r.t.as_deref() {
            assert_eq!(s["t"], t);
            let index = s["ts"].as_array().unwrap().iter().position(|x| x == t).unwrap();
            assert!(page.contains(&format!(
                "id=\"t-slider\" min=\"0\" max=\"{}\" step=\"1\" value=\"{index}\"",
                s["ts"].as_array().unwrap().len() - 1
            )));
        }
    }
    // the collinear conic has no equation, and says so
    let page = interactive_page(&cases[5]).unwrap();
    assert_eq!(shown(&page)["implicit"].0, "null");
    assert_eq!(shown(&page)["type"].0, "\"degenerate (collinear control points)\"");
}

#[test]
fn the_text_shows_the_same_numbers() {
    let page = interactive_page(&FigureRequest::new(FigureKind::Construction)).unwrap();
    let s = shown(&page);
    assert_eq!(s["b-3-0"].1, "b₀³(t) = (1, 0)");
    assert_eq!(s["b-1-0"].1, "b₀¹(t) = (2/3, -2/3)");
    let page = interactive_page(&FigureRequest::new(FigureKind::Conics)).unwrap();
    assert_eq!(shown(&page)["implicit"].1, "4x² + 3y² − 10y + 3 = 0");
    let page = interactive_page(&FigureRequest::new(FigureKind::Bernstein)).unwrap();
    assert_eq!(shown(&page)["basis"].1, "B₀³ = 8/27, B₁³ = 4/9, B₂³ = 2/9, B₃³ = 1/27");
}

#[test]
fn a_page_is_self_contained() {
    for kind in INTERACTIVE_KINDS {
        let page = interactive_page(&FigureRequest::new(kind)).unwrap();
        // the only URL is the SVG namespace, a name and not a fetch
        assert_eq!(
            page.matches("://").count(),
            page.matches("http://www.w3.org/2000/svg").count()
        );
        for fetch in ["<link", " src=", "import(", "fetch(", "XMLHttpRequest", "@import"] {
            assert!(!page.contains(fetch), "{}: {fetch}", kind.name());
        }
        assert!(page.starts_with("<!DOCTYPE html>") && page.contains("name=\"viewport\""));
    }
}

#[test]
fn bad_requests_are_clear_errors() {
    let err = |r: FigureRequest| interactive_page(&r).unwrap_err().to_string();
    assert!(err(FigureRequest::new(FigureKind::Hull)).contains("`figure hull` has no interactive version"));
    assert!(err(request(FigureKind::Construction, None, &[("t", "3/2")])).contains("outside [0, 1]"));
    assert!(err(request(FigureKind::Construction, None, &[("t", "-1/2")])).contains("outside [0, 1]"));
    assert!(err(request(FigureKind::Construction, None, &[("steps", "2")])).contains("--steps does not apply"));
    assert!(err(request(FigureKind::Elevation, None, &[("t", "1/2")])).contains("--t does not apply"));
    assert!(err(request(FigureKind::Elevation, None, &[("steps", "17")])).contains("outside 1..=16"));
    assert!(err(request(FigureKind::Elevation, None, &[("steps", "0")])).contains("outside 1..=16"));
    assert!(err(request(FigureKind::Bernstein, None, &[("degree", "11")])).contains("outside 1..=10"));
    assert!(err(request(FigureKind::Bernstein, Some("0,0; 1,1"), &[])).contains("takes no control points"));
    assert!(err(request(FigureKind::Conics, None, &[("weights", "-1")])).contains("must be positive"));
    assert!(err(request(FigureKind::Conics, None, &[("weights", "0")])).contains("must be positive"));
    assert!(err(request(FigureKind::Conics, Some("0,0; 1,1; 2,0; 3,3"), &[])).contains("three control points"));
    assert!(err(request(FigureKind::Construction, Some("0,0,0; 1,1,1"), &[])).contains("planar"));
    assert!(err(request(FigureKind::Construction, Some("0,0"), &[])).contains("2 to 10 control points"));
    let eleven = ["0,0"; 11].join("; ");
    assert!(err(request(FigureKind::Construction, Some(&eleven), &[])).contains("2 to 10 control points"));
    let big = format!("0,0; 1,{}", "9".repeat(30));
    assert!(err(request(FigureKind::Construction, Some(&big), &[])).contains("64 bits"));
    assert!(err(request(
        FigureKind::Construction,
        None,
        &[("t", "1/36893488147419103233")]
    ))
    .contains("64 bits"));
    // and through the command: exit status 2, one line on stderr, nothing on stdout
    let out = Command::new(env!("CARGO_BIN_EXE_casteljau"))
        .args(["figure", "net", "--interactive"])
        .output()
        .unwrap();
    assert_eq!(out.status.code(), Some(2));
    assert!(out.stdout.is_empty());
    assert_eq!(String::from_utf8_lossy(&out.stderr).lines().count(), 1);
}

#[test]
fn the_command_writes_the_page() {
    let out = Command::new(env!("CARGO_BIN_EXE_casteljau"))
        .args(["figure", "subdivision", "0,0; 1,2; 3,0", "--t", "1/3", "--interactive"])
        .output()
        .unwrap();
    assert!(out.status.success(), "{}", String::from_utf8_lossy(&out.stderr));
    let page = String::from_utf8(out.stdout).unwrap();
    check(&page);
    assert_eq!(shown(&page)["left"].0, r#"[["0","0"],["1/3","2/3"],["7/9","8/9"]]"#);
}

#[test]
fn the_report_links_the_pages_it_writes() {
    let dir = std::env::temp_dir().join(format!("casteljau-interactive-{}", std::process::id()));
    let run = Command::new(env!("CARGO_BIN_EXE_casteljau"))
        .current_dir(env!("CARGO_MANIFEST_DIR"))
        .args(["prove", "--html"])
        .arg(&dir)
        .output()
        .unwrap();
    assert!(run.status.success(), "{}", String::from_utf8_lossy(&run.stderr));
    let mut linked = 0;
    for entry in std::fs::read_dir(&dir).unwrap() {
        let path = entry.unwrap().path();
        if path.extension().is_some_and(|e| e == "html") {
            let html = std::fs::read_to_string(&path).unwrap();
            for piece in html.split("href=\"interactive/").skip(1) {
                let file = piece.split_once('"').unwrap().0;
                assert!(
                    dir.join("interactive").join(file).is_file(),
                    "{}: {file}",
                    path.display()
                );
                linked += 1;
            }
        }
    }
    assert!(linked >= 4, "only {linked} links to interactive figures");
    for kind in INTERACTIVE_KINDS {
        let page = std::fs::read_to_string(dir.join("interactive").join(format!("{}.html", kind.name()))).unwrap();
        check(&page);
    }
    std::fs::remove_dir_all(&dir).unwrap();
}
