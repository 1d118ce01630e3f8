// casteljau's interactive figures: the page's state (control points, t, r, w, n) is read from
// the JSON in <script id="state">, every value shown is computed here in exact rational
// arithmetic (BigInt fractions) and written into elements with stable ids and a `data-exact`
// attribute holding the value as the oracle prints it (compact JSON of lowest-terms strings),
// so that a browser test can compare the page with `casteljau oracle` byte for byte.
// Drawing alone uses floats: pixels need no more.
"use strict";

// ---------------------------------------------------------------------------------------------
// Exact fractions

function gcd(a, b) {
  a = a < 0n ? -a : a;
  b = b < 0n ? -b : b;
  while (b !== 0n) [a, b] = [b, a % b];
  return a;
}

// A rational in lowest terms with a positive denominator, so that equal values print equally.
class Fraction {
  constructor(n, d = 1n) {
    if (d === 0n) throw new Error("zero denominator");
    if (d < 0n) [n, d] = [-n, -d];
    const g = gcd(n, d);
    this.n = g > 1n ? n / g : n;
    this.d = g > 1n ? d / g : d;
  }
  // "p/q", "p" or "-p/q", as the oracle writes numbers
  static parse(s) {
    const m = /^(-?\d+)(?:\/(\d+))?$/.exec(s);
    if (!m) throw new Error("not a fraction: " + s);
    return new Fraction(BigInt(m[1]), m[2] === undefined ? 1n : BigInt(m[2]));
  }
  static of(k) { return new Fraction(BigInt(k)); }
  add(o) { return new Fraction(this.n * o.d + o.n * this.d, this.d * o.d); }
  sub(o) { return new Fraction(this.n * o.d - o.n * this.d, this.d * o.d); }
  mul(o) { return new Fraction(this.n * o.n, this.d * o.d); }
  div(o) { return new Fraction(this.n * o.d, this.d * o.n); }
  isZero() { return this.n === 0n; }
  sign() { return this.n > 0n ? 1 : this.n < 0n ? -1 : 0; }
  cmp(o) { return this.sub(o).sign(); }
  toString() { return this.d === 1n ? this.n.toString() : this.n + "/" + this.d; }
  toNumber() { return Number(this.n) / Number(this.d); }
}

const ZERO = Fraction.of(0);
const ONE = Fraction.of(1);

// ---------------------------------------------------------------------------------------------
// The algorithms, on points as arrays of Fractions

const lerp = (a, b, t) => a.map((x, k) => ONE.sub(t).mul(x).add(t.mul(b[k])));

// The whole scheme: levels[r][i] = b_i^r(t).
function scheme(points, t) {
  const levels = [points];
  for (let r = 1; r < points.length; r++) {
    const prev = levels[r - 1];
    levels.push(prev.slice(1).map((p, i) => lerp(prev[i], p, t)));
  }
  return levels;
}

function split(points, t) {
  const lv = scheme(points, t), n = points.length - 1;
  return { left: lv.map((row) => row[0]), right: lv.map((_, j) => lv[n - j][j]) };
}

// One degree up: b'_i = i/(n+1) b_{i-1} + (1 - i/(n+1)) b_i. The elevated polygon of a degree
// is unique, so r single steps give exactly the oracle's `elevate` by r.
function elevate(points, r) {
  for (let s = 0; s < r; s++) {
    const m = Fraction.of(points.length);
    const out = [points[0]];
    for (let i = 1; i < points.length; i++) {
      const a = new Fraction(BigInt(i)).div(m);
      out.push(lerp(points[i], points[i - 1], a));
    }
    out.push(points[points.length - 1]);
    points = out;
  }
  return points;
}

// The hodograph's control points n (b_{i+1} - b_i).
function hodograph(points) {
  const n = Fraction.of(points.length - 1);
  return points.slice(1).map((p, i) => p.map((x, k) => n.mul(x.sub(points[i][k]))));
}

const evalAt = (points, t) => scheme(points, t)[points.length - 1][0];

// The rational curve's point: de Casteljau on (w p, w), then one division.
function rationalEval(points, weights, t) {
  const h = evalAt(points.map((p, i) => [...p.map((x) => x.mul(weights[i])), weights[i]]), t);
  const w = h[h.length - 1];
  return h.slice(0, -1).map((x) => x.div(w));
}

function binomial(n, k) {
  let c = 1n;
  for (let j = 1; j <= k; j++) c = (c * BigInt(n - k + j)) / BigInt(j);
  return c;
}

function bernstein(n, t) {
  const out = [];
  for (let i = 0; i <= n; i++) {
    let v = new Fraction(binomial(n, i));
    for (let j = 0; j < i; j++) v = v.mul(t);
    for (let j = i; j < n; j++) v = v.mul(ONE.sub(t));
    out.push(v);
  }
  return out;
}

// (B - A) × (C - A): twice the signed area of the triangle ABC.
const cross = (a, b, c) => b[0].sub(a[0]).mul(c[1].sub(a[1])).sub(b[1].sub(a[1]).mul(c[0].sub(a[0])));

// The conic carrying the arc: with barycentric coordinates τ_i ∝ w_i B_i(t) in the triangle of
// the control points, τ_1² w_0 w_2 = 4 w_1² τ_0 τ_2. Each τ_i is a linear form L_i(x, y) (over
// the doubled area), so w_0 w_2 L_1² − 4 w_1² L_0 L_2 = 0, scaled to coprime integers with the
// first non-zero coefficient positive, as the oracle writes it.
function conic(points, weights) {
  const [p0, p1, p2] = points;
  if (cross(p0, p1, p2).isZero()) return { type: "degenerate (collinear control points)", implicit: null };
  const linear = (f) => {
    const c = f([ZERO, ZERO]);
    return [f([ONE, ZERO]).sub(c), f([ZERO, ONE]).sub(c), c];
  };
  const l0 = linear((x) => cross(x, p1, p2));
  const l1 = linear((x) => cross(p0, x, p2));
  const l2 = linear((x) => cross(p0, p1, x));
  // [A, B, C, D, E, F] of the product of two linear forms
  const product = ([a1, b1, c1], [a2, b2, c2]) => [
    a1.mul(a2), a1.mul(b2).add(a2.mul(b1)), b1.mul(b2), a1.mul(c2).add(a2.mul(c1)), b1.mul(c2).add(b2.mul(c1)), c1.mul(c2),
  ];
  const [w0, w1, w2] = weights;
  const s = w0.mul(w2), u = Fraction.of(4).mul(w1).mul(w1);
  const q11 = product(l1, l1), q02 = product(l0, l2);
  const coeffs = q11.map((x, k) => s.mul(x).sub(u.mul(q02[k])));
  let den = 1n;
  for (const c of coeffs) den = (den / gcd(den, c.d)) * c.d;
  let ints = coeffs.map((c) => (c.n * den) / c.d);
  const g = ints.reduce((a, b) => gcd(a, b), 0n);
  const first = ints.find((x) => x !== 0n);
  const f = first < 0n ? -g : g;
  ints = ints.map((x) => x / f);
  const excess = w1.mul(w1).sub(w0.mul(w2)).sign();
  const type = excess < 0 ? "ellipse" : excess === 0 ? "parabola" : "hyperbola";
  return { type, implicit: ints.map(String) };
}

// ---------------------------------------------------------------------------------------------
// Showing values: `data-exact` is the oracle's JSON, the text the same numbers for people

const json = (v) => JSON.stringify(v);
const pointStrings = (p) => p.map(String);
const pointText = (p) => "(" + p.map(String).join(", ") + ")";
const listText = (ps) => ps.map(pointText).join("; ");
const SUB = "₀₁₂₃₄₅₆₇₈₉";
const SUP = "⁰¹²³⁴⁵⁶⁷⁸⁹";
const digits = (k, set) => String(k).split("").map((c) => set[+c]).join("");

function setValue(id, exact, text) {
  const el = document.getElementById(id);
  el.dataset.exact = exact;
  el.textContent = text;
}

// ---------------------------------------------------------------------------------------------
// The page

const state = JSON.parse(document.getElementById("state").textContent);
const kind = state.kind;
const pts = (state.points || []).map((p) => p.map(Fraction.parse));
const ts = state.ts.map(Fraction.parse);
let ti = state.ts.indexOf(state.t);
// elevation has no parameter t
const hasT = ts.length > 0;
const ws = (state.ws || []).map(Fraction.parse);
let wi = state.ws ? state.ws.indexOf(state.w) : 0;
let r = state.r || 1;
let n = state.n || 3;
const grid = BigInt(state.grid || 6);

// The values each figure shows, computed from the current state: [id, exact, text] triples.
function values() {
  const t = ts[ti];
  const out = hasT ? [["t-value", json(String(t)), String(t)]] : [];
  pts.forEach((p, i) => out.push(["p-" + i, json(pointStrings(p)), "b" + digits(i, SUB) + " = " + pointText(p)]));
  if (kind === "construction") {
    scheme(pts, t).forEach((row, lv) =>
      row.forEach((p, i) =>
        out.push([`b-${lv}-${i}`, json(pointStrings(p)), `b${digits(i, SUB)}${digits(lv, SUP)}(t) = ${pointText(p)}`])
      )
    );
  } else if (kind === "subdivision") {
    const { left, right } = split(pts, t);
    out.push(["left", json(left.map(pointStrings)), listText(left)]);
    out.push(["right", json(right.map(pointStrings)), listText(right)]);
  } else if (kind === "elevation") {
    const e = elevate(pts, r);
    out.push(["r-value", json(String(r)), String(r)]);
    out.push(["elevated", json(e.map(pointStrings)), listText(e)]);
  } else if (kind === "hodograph") {
    const h = hodograph(pts);
    out.push(["point", json(pointStrings(evalAt(pts, t))), pointText(evalAt(pts, t))]);
    out.push(["hodograph", json(h.map(pointStrings)), listText(h)]);
    const v = evalAt(h, t);
    out.push(["vector", json(pointStrings(v)), pointText(v)]);
  } else if (kind === "conics") {
    const weights = [ONE, ws[wi], ONE];
    const x = rationalEval(pts, weights, t);
    const c = conic(pts, weights);
    out.push(["w-value", json(String(ws[wi])), String(ws[wi])]);
    out.push(["point", json(pointStrings(x)), pointText(x)]);
    out.push(["type", json(c.type), c.type]);
    out.push(["implicit", json(c.implicit), c.implicit ? equation(c.implicit) : "none (collinear control points)"]);
  } else if (kind === "bernstein") {
    const b = bernstein(n, t);
    out.push(["n-value", json(String(n)), String(n)]);
    out.push(["basis", json(b.map(String)), b.map((v, i) => `B${digits(i, SUB)}${digits(n, SUP)} = ${v}`).join(", ")]);
  }
  return out;
}

// A x² + B xy + C y² + D x + E y + F = 0, terms with a zero coefficient left out
function equation(k) {
  const terms = ["x²", "xy", "y²", "x", "y", ""];
  let s = "";
  k.forEach((c, i) => {
    if (c === "0") return;
    const neg = c.startsWith("-"), a = neg ? c.slice(1) : c;
    const coef = a === "1" && terms[i] ? "" : a;
    s += (s ? (neg ? " − " : " + ") : neg ? "−" : "") + coef + terms[i];
  });
  return (s || "0") + " = 0";
}

// ---------------------------------------------------------------------------------------------
// Drawing

const SVG = "http://www.w3.org/2000/svg";
const svg = document.getElementById("canvas");
const W = 600, H = 400, PAD = 36;
let view; // math → pixel: x ↦ ox + s x, y ↦ oy − s y

// The view is fixed from the starting points (with room to drag), so the picture does not
// jump while a point moves.
function setView(box) {
  let [x0, y0, x1, y1] = box;
  const span = Math.max(x1 - x0, y1 - y0, 1);
  const m = span * 0.25;
  [x0, y0, x1, y1] = [x0 - m, y0 - m, x1 + m, y1 + m];
  const s = Math.min((W - 2 * PAD) / (x1 - x0), (H - 2 * PAD) / (y1 - y0));
  view = { s, ox: W / 2 - (s * (x0 + x1)) / 2, oy: H / 2 + (s * (y0 + y1)) / 2, x0, y0, x1, y1 };
}
const px = (p) => [view.ox + view.s * p[0], view.oy - view.s * p[1]];
const toFloat = (p) => p.map((x) => x.toNumber());

function el(name, attrs, parent = svg) {
  const e = document.createElementNS(SVG, name);
  for (const [k, v] of Object.entries(attrs)) e.setAttribute(k, v);
  parent.appendChild(e);
  return e;
}
// A label beside a point (pixel offset dx, dy); at 18 units (the stylesheet) it is 11 px on a 390 px phone.
function label(p, text, dx = 0, dy = -12, anchor = "middle", parent = svg) {
  const e = el("text", { x: p[0] + dx, y: p[1] + dy, class: "label", "text-anchor": anchor }, parent);
  e.textContent = text;
  return e;
}
const polyline = (ps, cls) => el("polyline", { points: ps.map((p) => px(p).join(",")).join(" "), class: cls });
const dot = (p, cls, rad = 4) => el("circle", { cx: px(p)[0], cy: px(p)[1], r: rad, class: cls });

// Float samples of the curve for its line only.
function curveSamples(points, weights) {
  const f = points.map(toFloat), w = weights ? weights.map((x) => x.toNumber()) : f.map(() => 1);
  const out = [];
  for (let k = 0; k <= 128; k++) {
    const t = k / 128;
    let h = f.map((p, i) => [...p.map((x) => x * w[i]), w[i]]);
    while (h.length > 1) h = h.slice(1).map((q, i) => q.map((x, c) => (1 - t) * h[i][c] + t * x));
    out.push(h[0].slice(0, -1).map((x) => x / h[0][h[0].length - 1]));
  }
  return out;
}

function drawCurve() {
  const t = ts[ti];
  const tf = toFloat;
  polyline(pts.map(tf), "polygon");
  if (kind === "conics") {
    const w = ws[wi];
    // the rest of the conic: the same arc with −w₁ (dashed)
    polyline(curveSamples(pts, [ONE, ZERO.sub(w), ONE]), "rest");
    polyline(curveSamples(pts, [ONE, w, ONE]), "curve");
    const x = px(tf(rationalEval(pts, [ONE, w, ONE], t)));
    dot(tf(rationalEval(pts, [ONE, w, ONE], t)), "at", 5);
    label(x, "x(t)", 10, 18, "start");
  } else {
    polyline(curveSamples(pts), "curve");
  }
  if (kind === "construction") {
    scheme(pts, t).forEach((row, lv) => {
      if (lv === 0) return;
      if (row.length > 1) polyline(row.map(tf), "level level" + (lv % 4));
      row.forEach((p) => dot(tf(p), lv === pts.length - 1 ? "at" : "inner", lv === pts.length - 1 ? 5 : 3));
    });
    label(px(tf(evalAt(pts, t))), "b(t)", 10, 18, "start");
  } else if (kind === "subdivision") {
    const { left, right } = split(pts, t);
    polyline(left.map(tf), "left");
    polyline(right.map(tf), "right");
    left.concat(right).forEach((p) => dot(tf(p), "inner", 3));
    dot(tf(left[left.length - 1]), "at", 5);
    label(px(tf(left[left.length - 1])), "b(t)", 10, 18, "start");
  } else if (kind === "elevation") {
    const e = elevate(pts, r).map(tf);
    polyline(e, "elevated");
    e.forEach((p) => dot(p, "inner", 3));
  } else if (kind === "hodograph") {
    const b = tf(evalAt(pts, t)), h = hodograph(pts);
    // the tangent b′(t)/n drawn at b(t): the side of the scheme's last segment
    const v = tf(evalAt(h, t)).map((x) => x / (pts.length - 1));
    polyline([b, [b[0] + v[0], b[1] + v[1]]], "tangent");
    dot(b, "at", 5);
    label(px(b), "b(t)", 10, 18, "start");
    label(px([b[0] + v[0], b[1] + v[1]]), "b′(t)/n", 8, -8, "start");
  }
  // control points labelled outwards, away from the polygon's centre
  const fs = pts.map(tf);
  const cx = fs.reduce((a, p) => a + p[0], 0) / fs.length, cy = fs.reduce((a, p) => a + p[1], 0) / fs.length;
  const seen = new Set();
  fs.forEach((p, i) => {
    const key = p.join();
    const [ax, ay] = px(p), [bx, by] = px([cx, cy]);
    const len = Math.hypot(ax - bx, ay - by) || 1;
    // coinciding points share one label
    const names = fs.map((q, j) => (q.join() === key ? "b" + digits(j, SUB) : null)).filter(Boolean);
    const [ux, uy] = [(ax - bx) / len, (ay - by) / len];
    const anchor = Math.abs(ux) < 0.4 ? "middle" : ux > 0 ? "start" : "end";
    if (!seen.has(key)) label([ax, ay], names.join(" = "), 14 * ux, 14 * uy + 6 + (uy > 0.4 ? 8 : 0), anchor);
    seen.add(key);
  });
  pts.forEach((p, i) => {
    const c = dot(tf(p), "handle", 7);
    c.dataset.index = i;
    c.id = "handle-" + i;
  });
}

// The hodograph in its own panel, around the origin; rescaled to its points each time.
function drawHodograph() {
  const hs = document.getElementById("hodo");
  hs.replaceChildren();
  const h = hodograph(pts).map(toFloat);
  const all = h.concat([[0, 0]]);
  const xs = all.map((p) => p[0]), ys = all.map((p) => p[1]);
  const span = Math.max(Math.max(...xs) - Math.min(...xs), Math.max(...ys) - Math.min(...ys), 1e-9);
  const s = 240 / span, cx = (Math.max(...xs) + Math.min(...xs)) / 2, cy = (Math.max(...ys) + Math.min(...ys)) / 2;
  const q = (p) => [150 + s * (p[0] - cx), 150 - s * (p[1] - cy)];
  const add = (name, attrs) => el(name, attrs, hs);
  add("polyline", { points: h.map((p) => q(p).join(",")).join(" "), class: "polygon" });
  add("polyline", { points: curveSamples(hodograph(pts)).map((p) => q(p).join(",")).join(" "), class: "curve" });
  const v = q(toFloat(evalAt(hodograph(pts), ts[ti])));
  add("polyline", { points: q([0, 0]).join(",") + " " + v.join(","), class: "tangent" });
  add("circle", { cx: q([0, 0])[0], cy: q([0, 0])[1], r: 3, class: "inner" });
  add("circle", { cx: v[0], cy: v[1], r: 5, class: "at" });
  label(q([0, 0]), "0", -8, 16, "end", hs);
  label(v, "b′(t)", 8, -8, "start", hs);
}

// The basis on [0, 1] × [0, 1], the values at t marked, and a handle that drags t.
function drawBasis() {
  const t = ts[ti].toNumber();
  const q = (x, y) => [PAD + (W - 2 * PAD) * x, H - PAD - (H - 2 * PAD) * y];
  el("polyline", { points: [q(0, 1), q(0, 0), q(1, 0)].map((p) => p.join(",")).join(" "), class: "axes" });
  label(q(0, 0), "0", -8, 16, "end");
  label(q(1, 0), "1", 0, 20);
  label(q(0, 1), "1", -8, 5, "end");
  for (let i = 0; i <= n; i++) {
    const line = [];
    for (let k = 0; k <= 100; k++) {
      const x = k / 100;
      line.push(q(x, Number(binomial(n, i)) * x ** i * (1 - x) ** (n - i)).join(","));
    }
    el("polyline", { points: line.join(" "), class: "basis level" + (i % 4) });
    // named at its maximum, t = i/n
    const top = q(i / n, Number(binomial(n, i)) * (i / n) ** i * (1 - i / n) ** (n - i));
    label(top, "B" + digits(i, SUB) + digits(n, SUP), i === 0 ? 10 : i === n ? -10 : 0, -8, i === 0 ? "start" : i === n ? "end" : "middle");
  }
  el("polyline", { points: q(t, 0).join(",") + " " + q(t, 1).join(","), class: "tangent" });
  label(q(t, 1), "t = " + ts[ti], 0, -8);
  bernstein(n, ts[ti]).forEach((v) => {
    const [x, y] = q(t, v.toNumber());
    el("circle", { cx: x, cy: y, r: 4, class: "at" });
  });
  const [hx, hy] = q(t, 0);
  const c = el("circle", { cx: hx, cy: hy, r: 8, class: "handle", id: "t-handle" });
  c.dataset.index = "t";
}

function render() {
  for (const [id, exact, text] of values()) setValue(id, exact, text);
  svg.replaceChildren();
  if (kind === "bernstein") drawBasis();
  else drawCurve();
  if (kind === "hodograph") drawHodograph();
  if (hasT) document.getElementById("t-slider").value = ti;
  const now = { t: hasT ? String(ts[ti]) : "", r: String(r), w: ws.length ? String(ws[wi]) : "", n: String(n) };
  for (const e of document.querySelectorAll(".now")) e.textContent = now[e.dataset.of];
}

// ---------------------------------------------------------------------------------------------
// Dragging: a handle follows the pointer, snapped to the grid 1/grid (t to the nearest listed
// rational), and stays inside the view.

function svgPoint(ev) {
  const m = svg.getScreenCTM().inverse();
  return [m.a * ev.clientX + m.c * ev.clientY + m.e, m.b * ev.clientX + m.d * ev.clientY + m.f];
}

function snap(x, lo, hi) {
  const k = Math.round(Math.min(Math.max(x, lo), hi) * Number(grid));
  return new Fraction(BigInt(k), grid);
}

function nearestT(x) {
  let best = 0;
  ts.forEach((v, i) => {
    if (Math.abs(v.toNumber() - x) < Math.abs(ts[best].toNumber() - x)) best = i;
  });
  return best;
}

let dragging = null;
svg.addEventListener("pointerdown", (ev) => {
  const target = ev.target.closest(".handle");
  if (!target) return;
  dragging = target.dataset.index;
  svg.setPointerCapture(ev.pointerId);
  ev.preventDefault();
});
svg.addEventListener("pointermove", (ev) => {
  if (dragging === null) return;
  const [x, y] = svgPoint(ev);
  if (dragging === "t") {
    ti = nearestT((x - PAD) / (W - 2 * PAD));
  } else {
    const mx = (x - view.ox) / view.s, my = (view.oy - y) / view.s;
    pts[+dragging] = [snap(mx, view.x0, view.x1), snap(my, view.y0, view.y1)];
  }
  render();
});
const stop = () => (dragging = null);
svg.addEventListener("pointerup", stop);
svg.addEventListener("pointercancel", stop);

function slider(id, set) {
  const s = document.getElementById(id);
  if (s) s.addEventListener("input", () => { set(+s.value); render(); });
}
slider("t-slider", (v) => (ti = v));
slider("r-slider", (v) => (r = v));
slider("w-slider", (v) => (wi = v));
slider("n-slider", (v) => (n = v));

// For the browser test: where a point of the figure is on the screen (client pixels), and the
// region a control point can be dragged in.
function svgToClient(sx, sy) {
  const m = svg.getScreenCTM();
  return [m.a * sx + m.c * sy + m.e, m.b * sx + m.d * sy + m.f];
}
window.casteljau = {
  toClient: (x, y) => svgToClient(...px([x, y])),
  tToClient: (t) => svgToClient(PAD + (W - 2 * PAD) * t, H - PAD),
  grid: Number(grid),
  view: () => view,
};

// The values the page was written with are the engine's (casteljau's Rust, exact); the page
// recomputes them here and says whether the two agree before anything moves.
const written = new Map([...document.querySelectorAll("[data-exact]")].map((e) => [e.id, e.dataset.exact]));
const start = values();
const agree = start.every(([id, exact]) => written.get(id) === exact) && start.length === written.size;
const check = document.getElementById("engine-check");
check.textContent = agree
  ? "The values computed in this page agree exactly with casteljau's engine at the start."
  : "The values computed in this page differ from casteljau's engine: please report this page.";
check.dataset.agree = agree;
if (kind !== "bernstein") {
  let fs = pts.map(toFloat);
  // an ellipse is shown whole at the start
  if (kind === "conics" && ws[wi].cmp(ONE) < 0) fs = fs.concat(curveSamples(pts, [ONE, ZERO.sub(ws[wi]), ONE]));
  setView([Math.min(...fs.map((p) => p[0])), Math.min(...fs.map((p) => p[1])), Math.max(...fs.map((p) => p[0])), Math.max(...fs.map((p) => p[1]))]);
}
render();
