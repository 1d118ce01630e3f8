// The interactive figures in a real browser (run by scripts/browser_test.sh, which installs
// Chromium and playwright-core). For each figure: load the page (file://, network refused),
// move its sliders with the keyboard and drag its handles with the mouse to random positions,
// read every value the page shows (`data-exact` and the text), and compare them byte for byte
// with `casteljau oracle`'s answers for the same points and t; check that no element is
// wider than the viewport at 1280 and 390 px; take a screenshot at both widths.
//
// node scripts/browser_test.mjs --bin target/release/casteljau --pw DIR [--positions 60]
//      [--seed 1] [--shots docs/screenshots] [--chromium /usr/bin/chromium]
import { spawn, execFileSync } from "node:child_process";
import { createRequire } from "node:module";
import { mkdtempSync, rmSync, mkdirSync } from "node:fs";
import { tmpdir } from "node:os";
import { join, resolve } from "node:path";
import { createInterface } from "node:readline";

const args = Object.fromEntries(
  process.argv.slice(2).reduce((acc, a, i, all) => (a.startsWith("--") ? [...acc, [a.slice(2), all[i + 1]]] : acc), [])
);
const bin = resolve(args.bin || "target/release/casteljau");
const positions = +(args.positions || 60);
const shots = args.shots ? resolve(args.shots) : null;
const { chromium } = createRequire(resolve(args.pw) + "/")("playwright-core");
const KINDS = ["construction", "subdivision", "elevation", "hodograph", "conics", "bernstein"];

// A seeded generator (mulberry32), so that a failure can be replayed with its --seed.
let seed = +(args.seed || 1) >>> 0;
function random() {
  seed = (seed + 0x6d2b79f5) >>> 0;
  let x = seed;
  x = Math.imul(x ^ (x >>> 15), x | 1);
  x ^= x + Math.imul(x ^ (x >>> 7), x | 61);
  return ((x ^ (x >>> 14)) >>> 0) / 4294967296;
}
const randInt = (lo, hi) => lo + Math.floor(random() * (hi - lo + 1));

// ---------------------------------------------------------------------------------------------
// The oracle: one process, one JSON line per request, answers in order.

const oracle = spawn(bin, ["oracle"], { stdio: ["pipe", "pipe", "inherit"] });
const waiting = [];
createInterface({ input: oracle.stdout }).on("line", (line) => waiting.shift()(line));
function ask(request) {
  return new Promise((res) => {
    waiting.push((line) => {
      const answer = JSON.parse(line);
      if (!answer.ok) throw new Error(`oracle refused ${JSON.stringify(request)}: ${answer.error}`);
      res(answer);
    });
    oracle.stdin.write(JSON.stringify(request) + "\n");
  });
}

// ---------------------------------------------------------------------------------------------
// What the page should show, formatted here independently of the page's script.

const SUB = "₀₁₂₃₄₅₆₇₈₉", SUP = "⁰¹²³⁴⁵⁶⁷⁸⁹";
const digits = (k, set) => String(k).split("").map((c) => set[+c]).join("");
const pointText = (p) => "(" + p.join(", ") + ")";
const listText = (ps) => ps.map(pointText).join("; ");
function equation(k) {
  const terms = ["x²", "xy", "y²", "x", "y", ""];
  let s = "";
  k.forEach((c, i) => {
    if (c === "0") return;
    const neg = c.startsWith("-"), a = neg ? c.slice(1) : c;
    s += (s ? (neg ? " − " : " + ") : neg ? "−" : "") + (a === "1" && terms[i] ? "" : a) + terms[i];
  });
  return (s || "0") + " = 0";
}
const gcd = (a, b) => (b === 0n ? (a < 0n ? -a : a) : gcd(b, a % b));
function fraction(k, g) {
  const d = gcd(BigInt(k), BigInt(g));
  const [n, m] = [BigInt(k) / d, BigInt(g) / d];
  return m === 1n ? String(n) : `${n}/${m}`;
}

// The values the sliders move over (src/html/interactive.rs): t over the fractions in [0, 1]
// with denominators up to 12, the middle weight over WEIGHTS.
const FAREY = [...new Set([...Array(12)].flatMap((_, q) => [...Array(q + 2)].map((_, p) => p / (q + 1))))]
  .sort((a, b) => a - b)
  .map((x) => {
    for (let q = 1; ; q++) if (Math.abs(x * q - Math.round(x * q)) < 1e-9) return fraction(Math.round(x * q), q);
  });
const FAREY_VALUES = FAREY.map((f) => f.split("/").reduce((a, b) => a / b));
const WEIGHTS = ["1/8", "1/6", "1/5", "1/4", "1/3", "2/5", "1/2", "3/5", "2/3", "3/4", "4/5", "1", "5/4", "4/3", "3/2",
  "5/3", "2", "5/2", "3", "4", "5", "6", "8"];

// The expected `id → [exact, text]` for the state the page shows (its points, t, r, w, n).
async function expected(kind, shown) {
  const out = new Map();
  const put = (id, value, text) => out.set(id, [JSON.stringify(value), text]);
  const points = Object.keys(shown).filter((id) => /^p-\d+$/.test(id)).sort((a, b) => a.slice(2) - b.slice(2))
    .map((id) => JSON.parse(shown[id][0]));
  points.forEach((p, i) => put("p-" + i, p, `b${digits(i, SUB)} = ${pointText(p)}`));
  const t = shown["t-value"] && JSON.parse(shown["t-value"][0]);
  if (t !== undefined) put("t-value", t, t);
  if (kind === "construction") {
    for (let r = 0; r < points.length; r++)
      for (let i = 0; i + r < points.length; i++) {
        const a = await ask({ op: "eval", points: points.slice(i, i + r + 1), t });
        put(`b-${r}-${i}`, a.point, `b${digits(i, SUB)}${digits(r, SUP)}(t) = ${pointText(a.point)}`);
      }
  } else if (kind === "subdivision") {
    const a = await ask({ op: "split", points, t });
    put("left", a.left, listText(a.left));
    put("right", a.right, listText(a.right));
  } else if (kind === "elevation") {
    const r = JSON.parse(shown["r-value"][0]);
    const a = await ask({ op: "elevate", points, by: r });
    put("r-value", r, r);
    put("elevated", a.points, listText(a.points));
  } else if (kind === "hodograph") {
    const b = await ask({ op: "eval", points, t });
    const h = await ask({ op: "derivative", points, order: 1 });
    const v = await ask({ op: "derivative", points, order: 1, t });
    put("point", b.point, pointText(b.point));
    put("hodograph", h.points, listText(h.points));
    put("vector", v.vector, pointText(v.vector));
  } else if (kind === "conics") {
    const w = JSON.parse(shown["w-value"][0]);
    const weights = ["1", w, "1"];
    const x = await ask({ op: "rational_eval", points, weights, t });
    const c = await ask({ op: "conic", points, weights });
    put("w-value", w, w);
    put("point", x.point, pointText(x.point));
    put("type", c.type, c.type);
    put("implicit", c.implicit, c.implicit ? equation(c.implicit) : "none (collinear control points)");
  } else if (kind === "bernstein") {
    // B_i^n(t) are the coordinates of the point at t of the curve with control points e_0 … e_n
    const n = +JSON.parse(shown["n-value"][0]);
    const unit = [...Array(n + 1)].map((_, i) => [...Array(n + 1)].map((_, j) => (i === j ? "1" : "0")));
    const a = await ask({ op: "eval", points: unit, t });
    put("n-value", String(n), String(n));
    put("basis", a.point, a.point.map((v, i) => `B${digits(i, SUB)}${digits(n, SUP)} = ${v}`).join(", "));
  }
  return out;
}

// ---------------------------------------------------------------------------------------------
// Driving the page like a reader

const shownValues = (page) =>
  page.$$eval("[data-exact]", (els) => Object.fromEntries(els.map((e) => [e.id, [e.dataset.exact, e.textContent]])));

// Moves a range input to `index` with the arrow keys, as a keyboard user would.
async function slide(page, id, index) {
  const el = page.locator("#" + id);
  const now = +(await el.inputValue());
  await el.focus();
  const key = index > now ? "ArrowRight" : "ArrowLeft";
  for (let k = 0; k < Math.abs(index - now); k++) await page.keyboard.press(key);
  const after = +(await el.inputValue());
  if (after !== index) throw new Error(`#${id} is at ${after} after the keys, not ${index}`);
}

async function sliderRange(page, id) {
  return page.$eval("#" + id, (e) => [+e.min, +e.max]);
}

// Drags the handle whose centre is at client (x0, y0) to (x1, y1) with the mouse.
async function drag(page, [x0, y0], [x1, y1]) {
  await page.mouse.move(x0, y0);
  await page.mouse.down();
  await page.mouse.move((x0 + x1) / 2, (y0 + y1) / 2, { steps: 3 });
  await page.mouse.move(x1, y1, { steps: 3 });
  await page.mouse.up();
}

// Handles the mouse can grab: those on top at their own centre (a point dragged onto another
// hides it).
const grabbable = (page) =>
  page.$$eval(".handle", (hs) =>
    hs.map((h) => {
      const b = h.getBoundingClientRect();
      const [x, y] = [b.left + b.width / 2, b.top + b.height / 2];
      return { id: h.id, index: h.dataset.index, x, y, top: document.elementFromPoint(x, y) === h };
    }).filter((h) => h.top)
  );

// One random position: the sliders moved, a handle dragged to a random grid point. Returns the
// values the test expects the page to show for the parts it set itself.
async function move(page, kind) {
  const want = {};
  const ts = await page.$("#t-slider");
  if (ts && !(kind === "bernstein" && random() < 0.5)) {
    const [lo, hi] = await sliderRange(page, "t-slider");
    const k = randInt(lo, hi);
    await slide(page, "t-slider", k);
    want["t-value"] = JSON.stringify(FAREY[k]);
  }
  for (const [id, shown, value] of [["r-slider", "r-value", String], ["w-slider", "w-value", (k) => WEIGHTS[k]],
    ["n-slider", "n-value", String]]) {
    if (await page.$("#" + id)) {
      const [lo, hi] = await sliderRange(page, id);
      const k = randInt(lo, hi);
      await slide(page, id, k);
      want[shown] = JSON.stringify(value(k));
    }
  }
  const handles = await grabbable(page);
  const h = handles[randInt(0, handles.length - 1)];
  if (kind === "bernstein") {
    // the t handle on the axis: dropped over a random place, it snaps to the nearest listed t
    const t = random();
    const target = await page.evaluate((t) => window.casteljau.tToClient(t), t);
    await drag(page, [h.x, h.y], target);
    const nearest = FAREY_VALUES.reduce((best, v, i) => (Math.abs(v - t) < Math.abs(FAREY_VALUES[best] - t) ? i : best), 0);
    want["t-value"] = JSON.stringify(FAREY[nearest]);
    return want;
  }
  const { grid, view } = await page.evaluate(() => ({ grid: window.casteljau.grid, view: window.casteljau.view() }));
  const kx = randInt(Math.ceil(view.x0 * grid), Math.floor(view.x1 * grid));
  const ky = randInt(Math.ceil(view.y0 * grid), Math.floor(view.y1 * grid));
  const target = await page.evaluate(([x, y]) => window.casteljau.toClient(x, y), [kx / grid, ky / grid]);
  await drag(page, [h.x, h.y], target);
  want["p-" + h.index] = JSON.stringify([fraction(kx, grid), fraction(ky, grid)]);
  return want;
}

async function overflow(page) {
  return page.evaluate(() => {
    const w = window.innerWidth;
    // what is drawn inside an <svg> is clipped to it: the <svg> itself must fit
    const wide = [...document.querySelectorAll("body *")]
      .filter((e) => !e.parentElement.closest("svg"))
      .filter((e) => e.getBoundingClientRect().right > w + 0.5)
      .map((e) => e.tagName + (e.id ? "#" + e.id : ""));
    return { scroll: document.documentElement.scrollWidth, width: w, wide };
  });
}

let failures = 0;
function fail(message) {
  failures++;
  console.error("FAIL " + message);
}

async function compare(page, kind, label, want = {}) {
  const shown = await shownValues(page);
  for (const [id, exact] of Object.entries(want))
    if (shown[id]?.[0] !== exact) fail(`${kind} ${label}: ${id} is ${shown[id]?.[0]} after the drag, not ${exact}`);
  const exp = await expected(kind, shown);
  for (const [id, [exact, text]] of exp) {
    if (!shown[id]) fail(`${kind} ${label}: no element #${id}`);
    else if (shown[id][0] !== exact) fail(`${kind} ${label}: #${id} data-exact ${shown[id][0]} ≠ oracle ${exact}`);
    else if (shown[id][1] !== text) fail(`${kind} ${label}: #${id} text "${shown[id][1]}" ≠ "${text}"`);
  }
  for (const id of Object.keys(shown)) if (!exp.has(id)) fail(`${kind} ${label}: #${id} was not checked`);
  const o = await overflow(page);
  if (o.scroll > o.width || o.wide.length) fail(`${kind} ${label}: wider than ${o.width} px: ${o.scroll} px, ${o.wide.join(" ")}`);
  return exp.size;
}

// ---------------------------------------------------------------------------------------------

const pages = mkdtempSync(join(tmpdir(), "casteljau-pages-"));
const profile = mkdtempSync(join(tmpdir(), "casteljau-chromium-"));
for (const kind of KINDS) execFileSync(bin, ["figure", kind, "--interactive", "-o", join(pages, kind + ".html")]);
if (shots) mkdirSync(shots, { recursive: true });

const context = await chromium.launchPersistentContext(profile, {
  executablePath: args.chromium || "/usr/bin/chromium",
  headless: true,
  args: ["--no-sandbox", "--disable-gpu", "--disable-quic", "--no-first-run", "--disable-background-networking",
    "--disable-component-update", "--disable-sync"],
  viewport: { width: 1280, height: 800 },
});
// a self-contained page asks for nothing but itself
const offline = [];
await context.route("**/*", (route) => {
  const url = route.request().url();
  if (url.startsWith("file:")) return route.continue();
  offline.push(url);
  return route.abort();
});

const phone = { width: 390, height: 844 }, desktop = { width: 1280, height: 800 };
const summary = [];
try {
  for (const kind of KINDS) {
    const page = await context.newPage();
    page.setDefaultTimeout(10000);
    const errors = [];
    page.on("pageerror", (e) => errors.push(String(e)));
    await page.setViewportSize(phone);
    await page.goto("file://" + join(pages, kind + ".html"));
    const agree = await page.$eval("#engine-check", (e) => e.dataset.agree);
    if (agree !== "true") fail(`${kind}: the page's values at the start differ from the engine's`);
    await compare(page, kind, "start (390 px)");
    if (shots) await page.screenshot({ path: join(shots, `${kind}-390.png`) });
    await page.setViewportSize(desktop);
    await compare(page, kind, "start (1280 px)");
    if (shots) await page.screenshot({ path: join(shots, `${kind}-1280.png`) });
    let values = 0;
    try {
      for (let k = 1; k <= positions; k++) {
        // the last third at phone width: the drags and the overflow check there too
        if (k === Math.floor((2 * positions) / 3) + 1) await page.setViewportSize(phone);
        const want = await move(page, kind);
        values += await compare(page, kind, `position ${k}`, want);
      }
    } catch (e) {
      // a page whose script failed cannot be driven: one failure, then the next figure
      fail(`${kind}: ${e.message.split("\n")[0]}`);
    }
    if (errors.length) fail(`${kind}: script errors: ${errors.join("; ")}`);
    summary.push(`${kind}: ${positions} positions, ${values} values equal to the oracle's`);
    await page.close();
  }
} finally {
  await context.close();
  oracle.stdin.end();
  rmSync(profile, { recursive: true, force: true });
  rmSync(pages, { recursive: true, force: true });
}
if (offline.length) fail(`requests beyond the page: ${offline.join(" ")}`);
console.log(summary.join("\n"));
console.log(failures ? `browser test: ${failures} failures` : "browser test: every value equal to the oracle's, no overflow");
process.exit(failures ? 1 : 0);
