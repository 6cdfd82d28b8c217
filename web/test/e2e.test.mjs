// End-to-end test of the explorer page in a real browser (Debian's chromium, headless),
// against the numbers of the `impax` command line.
//
//   IMPAX_BIN=target/release/impax node --test web/test/e2e.test.mjs
//
// Environment: IMPAX_BIN (the binary, required), CHROMIUM (default /usr/bin/chromium),
// SCREENSHOT (default target/explorer.png beside the repository root; the book's picture
// docs/src/img/explorer.png is refreshed with SCREENSHOT=docs/src/img/explorer.png),
// MULTI_SCREENSHOT (the view with several contacts, default target/explorer-multi.png; the
// book's docs/src/img/explorer-multi.png), MECHANISM_SCREENSHOT and CONSERVED_SCREENSHOT (the
// views "Your mechanism" and "Conserved quantities", default target/explorer-mechanism.png and
// target/explorer-conserved.png; the book's docs/src/img/explorer-{mechanism,conserved}.png).
import { test, before, after } from "node:test";
import assert from "node:assert/strict";
import { spawn, execFileSync } from "node:child_process";
import fs from "node:fs";
import net from "node:net";
import os from "node:os";
import path from "node:path";
import { fileURLToPath, pathToFileURL } from "node:url";
import { chromium } from "playwright-core";

const here = path.dirname(fileURLToPath(import.meta.url));
const root = path.resolve(here, "../..");
const IMPAX = process.env.IMPAX_BIN && path.resolve(process.env.IMPAX_BIN);
const CHROMIUM = process.env.CHROMIUM || "/usr/bin/chromium";
const SCREENSHOT = process.env.SCREENSHOT || path.join(root, "target/explorer.png");
const MULTI_SCREENSHOT = process.env.MULTI_SCREENSHOT || path.join(root, "target/explorer-multi.png");
const MECHANISM_SCREENSHOT = process.env.MECHANISM_SCREENSHOT || path.join(root, "target/explorer-mechanism.png");
const CONSERVED_SCREENSHOT = process.env.CONSERVED_SCREENSHOT || path.join(root, "target/explorer-conserved.png");
const FLAGS = ["--headless", "--no-sandbox", "--disable-gpu", "--no-first-run",
  "--disable-background-networking", "--disable-component-update", "--disable-sync"];

let server, url, browser, page;
const errors = [];

function impax(...args) {
  return JSON.parse(execFileSync(IMPAX, args, { encoding: "utf8", cwd: root }));
}

// The one-line error of a command that fails (exit 2), without its `error: `.
function impaxError(...args) {
  try {
    execFileSync(IMPAX, args, { encoding: "utf8", cwd: root, stdio: ["ignore", "pipe", "pipe"] });
  } catch (e) {
    assert.equal(e.status, 2, `${args.join(" ")}: exit status`);
    return e.stderr.trim().replace(/^error: /, "");
  }
  assert.fail(`${args.join(" ")} succeeded`);
}

function freePort() {
  return new Promise((resolve, reject) => {
    const s = net.createServer();
    s.once("error", reject);
    s.listen(0, "127.0.0.1", () => { const { port } = s.address(); s.close(() => resolve(port)); });
  });
}

before(async () => {
  assert.ok(IMPAX, "set IMPAX_BIN to the impax binary");
  const port = await freePort();
  server = spawn(IMPAX, ["explore", "--port", String(port)], { stdio: ["ignore", "pipe", "pipe"] });
  url = await new Promise((resolve, reject) => {
    let text = "";
    const timer = setTimeout(() => reject(new Error(`impax explore printed no URL: ${text}`)), 10000);
    server.stdout.on("data", (d) => {
      text += d;
      const m = text.match(/http:\/\/127\.0\.0\.1:\d+\//);
      if (m) { clearTimeout(timer); resolve(m[0]); }
    });
    server.on("exit", (code) => reject(new Error(`impax explore exited with ${code}`)));
  });
  browser = await chromium.launch({ executablePath: CHROMIUM, args: FLAGS });
  page = await browser.newPage({ viewport: { width: 1366, height: 768 } });
  page.on("pageerror", (e) => errors.push(e.message));
  page.on("console", (m) => { if (m.type() === "error") errors.push(m.text()); });
  await page.goto(url);
  await page.waitForSelector('body[data-ready="1"]', { timeout: 20000 });
  await page.waitForFunction(() => document.getElementById("map").dataset.ms, null, { timeout: 20000 });
});

after(async () => {
  if (browser) await browser.close();
  if (server) server.kill();
});

// The number a table cell shows (the page writes − for minus).
const shown = (text) => Number(text.trim().replace("−", "-").replace("+", ""));

async function cell(law, col) {
  return page.$eval(`#laws tr[data-law="${law}"] td[data-col="${col}"]`, (td) => td.textContent);
}
async function verdict(law) {
  return page.$eval(`#laws tr[data-law="${law}"] td.verdict`, (td) => td.dataset.verdict);
}

async function setSlider(id, value) {
  await page.$eval(`#${id}`, (el, v) => {
    el.value = v;
    el.dispatchEvent(new Event("input", { bubbles: true }));
  }, String(value));
}

// The table against `impax compare --json` to the digits shown (5 decimals).
async function checkTable(json, columns) {
  assert.ok(json.results.length >= 7);
  for (const r of json.results) {
    const row = await page.$(`#laws tr[data-law="${r.law}"]`);
    assert.ok(row, `the page lists law ${r.law}`);
    assert.equal(await verdict(r.law), r.verdict, `${r.law}: verdict`);
    if (r.verdict === "breakdown") continue;
    for (const [col, value] of Object.entries(columns(r))) {
      const text = await cell(r.law, col);
      assert.ok(Math.abs(shown(text) - value) <= 0.5e-5 + 1e-12,
        `${r.law} ${col}: page shows ${text}, impax compare --json gives ${value}`);
      assert.equal(shown(text).toFixed(5), (Math.abs(value) < 0.5e-5 ? 0 : value).toFixed(5).replace("-0.00000", "0.00000"));
    }
    const phases = await page.$eval(`#laws tr[data-law="${r.law}"] td.phases`, (td) => td.textContent);
    assert.equal(phases, r.phases.map((p) => `${p.kind}@${p.ends_at.toFixed(4)}`).join(" → "), `${r.law}: phases`);
  }
}

const bodyColumns = (r) => ({
  vx: r.body_velocity_after.vx,
  vy: r.body_velocity_after.vy,
  omega: r.body_velocity_after.omega, // r = v0 = 1
  vt: r.contact_velocity_after.t,
  dT: r.energy_change_ratio,
});

// Paper A eq. 13 (Whittaker's ΔT/T0 for the sphere, positive slip branch), solved for γ:
// ΔT/T0 = (sin α − k)² + (e² + 5/2 f² (1+e)²) cos² α − 1 − 2 f γ (1+e) cos α, k = f (1+e) cos α.
function whittakerThreshold(alphaDeg, e, f) {
  const a = (alphaDeg * Math.PI) / 180, s = Math.sin(a), c = Math.cos(a), k = f * (1 + e) * c;
  const free = (s - k) ** 2 + (e * e + 2.5 * f * f * (1 + e) ** 2) * c * c - 1;
  return free / (2 * f * (1 + e) * c);
}

test("impax explore serves the page and the module (application/wasm)", async () => {
  const res = await fetch(url + "impax_wasm.wasm");
  assert.equal(res.status, 200);
  assert.equal(res.headers.get("content-type"), "application/wasm");
  const bytes = Buffer.from(await res.arrayBuffer());
  assert.ok(bytes.equals(fs.readFileSync(path.join(root, "web/impax_wasm.wasm"))), "the served module is web/impax_wasm.wasm");
  assert.equal((await fetch(url + "nope")).status, 404);
  assert.deepEqual(errors, []);
});

test("the table shows the seed's case with the numbers of impax compare --json", async () => {
  const json = impax("compare", "--json");
  await checkTable(json, bodyColumns);
  assert.ok(shown(await cell("whittaker", "dT")) > 0, "Whittaker gains energy (Kane's paradox)");
  assert.ok(shown(await cell("energetic", "dT")) < 0, "the energetic law loses energy");
  assert.equal(await verdict("whittaker"), "energy-gained");
  const problem = await page.$eval("#problem", (p) => p.textContent);
  assert.match(problem, /γ\*₋ = −1\.205811 < γ < γ\*₊ = 0\.205811/);
});

test("moving γ past Whittaker's threshold (paper A eq. 13) flips the verdict", async () => {
  const g = whittakerThreshold(30, 0.7, 0.4);
  assert.ok(Math.abs(g - 0.205811) < 1e-6, `γ* = ${g}`);
  const below = Math.floor(g * 1000) / 1000, above = Math.ceil(g * 1000) / 1000; // 0.205, 0.206
  await setSlider("gamma", below);
  assert.equal(await verdict("whittaker"), "energy-gained");
  assert.ok(shown(await cell("whittaker", "dT")) > 0);
  await setSlider("gamma", above);
  assert.notEqual(await verdict("whittaker"), "energy-gained");
  assert.ok(shown(await cell("whittaker", "dT")) <= 0);
  // The same numbers as the command line at that spin.
  await checkTable(impax("compare", "--json", "--spin-ratio", String(above)), bodyColumns);
  await setSlider("gamma", 0);
});

test("the table follows a slider while it is dragged", async () => {
  const box = await page.$eval("#alpha", (el) => { const r = el.getBoundingClientRect(); return { x: r.x, y: r.y, w: r.width, h: r.height }; });
  const seen = new Set();
  await page.mouse.move(box.x + box.w * 0.6, box.y + box.h / 2);
  await page.mouse.down();
  for (let k = 0; k <= 8; k++) {
    await page.mouse.move(box.x + box.w * (0.6 + 0.03 * k), box.y + box.h / 2);
    seen.add(await cell("whittaker", "dT"));
  }
  await page.mouse.up();
  assert.ok(seen.size >= 6, `the table changed while dragging (${seen.size} distinct values)`);
  await setSlider("alpha", 30);
  assert.equal(await cell("whittaker", "dT"), "+0.24240");
});

test("a value typed beside a slider is used exactly, and an impossible one is a clear error", async () => {
  await page.fill("#gamma-value", "0.2058");
  await page.press("#gamma-value", "Enter");
  await page.waitForFunction(() => document.getElementById("gamma-value").value === "0.2058");
  const json = impax("compare", "--json", "--spin-ratio", "0.2058");
  await checkTable(json, bodyColumns);
  await page.fill("#e-value", "1.5");
  await page.press("#e-value", "Enter");
  const message = await page.$eval("#error", (e) => (e.hidden ? "" : e.textContent));
  assert.match(message, /^restitution: 1\.5 is out of range/);
  assert.ok(!(await page.content()).includes("NaN"));
  for (const [id, v] of [["e-value", "0.7"], ["gamma-value", "0"]]) {
    await page.fill(`#${id}`, v);
    await page.press(`#${id}`, "Enter");
  }
  assert.equal(await page.$eval("#error", (e) => e.hidden), true);
  assert.equal(await cell("whittaker", "dT"), "+0.24240");
});

test("the energy-gain map is computed in the page and matches paper A eq. 13", async () => {
  await page.selectOption("#law", "whittaker");
  await page.waitForFunction(() => document.getElementById("map").dataset.cells === "40000");
  // Each change of μ recomputes the 200 × 200 map in WebAssembly.
  const times = [];
  for (const mu of [0.41, 0.42, 0.43, 0.44, 0.45, 0.4]) {
    const last = await page.$eval("#map", (c) => c.dataset.ms + c.dataset.gained);
    await setSlider("mu", mu);
    await page.waitForFunction((l) => { const c = document.getElementById("map"); return c.dataset.ms + c.dataset.gained !== l; }, last);
    times.push(Number(await page.$eval("#map", (c) => c.dataset.ms)));
  }
  times.sort((a, b) => a - b);
  const median = times[Math.floor(times.length / 2)];
  console.log(`map 200 × 200 (40,000 impacts, whittaker) recomputed in ${times.map((t) => t.toFixed(1)).join(", ")} ms; median ${median.toFixed(1)} ms`);
  assert.ok(median < 1000, `the map takes ${median} ms`);
  // Energy gained in the cells eq. 13 says, up to cells on the boundary.
  let expected = 0, boundary = 0;
  for (let j = 0; j < 200; j++) {
    const alpha = (89 * j) / 199, g = whittakerThreshold(alpha, 0.7, 0.4), edge = -Math.sin((alpha * Math.PI) / 180);
    for (let i = 0; i < 200; i++) {
      const gamma = -2 + (4 * i) / 199;
      if (gamma > edge && gamma < g) expected++;
      if (Math.abs(gamma - g) < 1e-9) boundary++;
    }
  }
  // The lower branch (γ < −sin α) of eq. 13.
  for (let j = 0; j < 200; j++) {
    const alpha = (89 * j) / 199, a = (alpha * Math.PI) / 180, s = Math.sin(a), c = Math.cos(a);
    const k = 0.4 * 1.7 * c, free = (s + k) ** 2 + (0.49 + 2.5 * 0.16 * 2.89) * c * c - 1;
    const lower = -free / (2 * 0.4 * 1.7 * c);
    for (let i = 0; i < 200; i++) {
      const gamma = -2 + (4 * i) / 199;
      if (gamma < -s && gamma > lower) expected++;
    }
  }
  const gained = Number(await page.$eval("#map", (c) => c.dataset.gained));
  assert.ok(Math.abs(gained - expected) <= Math.max(boundary, 2), `map: ${gained} cells gain energy, eq. 13: ${expected}`);
  // Drawn: warm (gain) and blue (loss) pixels in the canvas.
  const [warm, blue] = await page.$eval("#map", (c) => {
    const d = c.getContext("2d").getImageData(0, 0, c.width, c.height).data;
    let w = 0, b = 0;
    for (let i = 0; i < d.length; i += 4) {
      if (d[i] > 150 && d[i + 2] < 120 && d[i] - d[i + 2] > 60) w++;
      if (d[i + 2] > 150 && d[i + 2] - d[i] > 60) b++;
    }
    return [w, b];
  });
  assert.ok(warm > 2000 && blue > 2000, `map pixels: ${warm} warm, ${blue} blue`);
});

test("every shape of the core's table is offered and resolved (a shape with no preset gets sliders from the core)", async () => {
  const shapes = await page.evaluate(() => window.explorer.info.shapes);
  const offered = await page.$$eval("#shape option", (os) => os.map((o) => o.value));
  for (const s of shapes) assert.ok(offered.includes(s), `the page offers ${s}`);
  for (const s of shapes) {
    await page.selectOption("#shape", s);
    await page.waitForFunction((k) => window.explorer.kind === k && window.explorer.compare, s);
    const message = await page.$eval("#error", (e) => (e.hidden ? "" : e.textContent));
    assert.equal(message, "", `${s}: ${message}`);
    const scenario = await page.$eval("#scenario", (e) => e.textContent);
    assert.ok(scenario.startsWith(s === "rigid" ? "rigid body" : s), `${s}: ${scenario}`);
    // Every number of the shape has a slider, named as the core names it.
    const numbers = await page.evaluate((k) => window.explorer.info.shape_parameters[k].map((p) => p.name), s);
    for (const n of numbers) assert.ok(await page.$(`#p-${n}`), `${s}: a slider for ${n}`);
  }
  assert.ok(!(await page.content()).includes("NaN"));
  await page.click("#reset");
  await page.waitForFunction(() => document.querySelector('#laws tr[data-law="whittaker"] td[data-col="dT"]')?.textContent === "+0.24240");
});

test("Kane's double pendulum: the page agrees with impax compare double-pendulum --json", async () => {
  await page.selectOption("#shape", "double-pendulum");
  await page.waitForSelector('#laws tr[data-law="whittaker"]');
  const json = impax("compare", "double-pendulum", "--json");
  await checkTable(json, (r) => ({
    u1: r.velocities_after[0],
    u2: r.velocities_after[1],
    vt: r.contact_velocity_after.t,
    vn: r.contact_velocity_after.n,
    ratio: r.energy_ratio,
  }));
  assert.equal(await cell("whittaker", "ratio"), "+1.26087");
  // A configuration that cannot strike (both rods vertical: W is singular) is an error, not NaN.
  await setSlider("p-angle1_deg", 0);
  await setSlider("p-angle2_deg", 0);
  const message = await page.$eval("#error", (e) => (e.hidden ? "" : e.textContent));
  assert.match(message, /positive definite|approach/);
  assert.ok(!(await page.content()).includes("NaN"));
  await page.click("#reset");
  await page.waitForFunction(() => document.querySelector('#laws tr[data-law="whittaker"] td[data-col="dT"]')?.textContent === "+0.24240");
});

// ---- the view with several contacts ------------------------------------------------------

async function multiCell(law, key) {
  return page.$eval(`#multi-laws td[data-law="${law}"][data-key="${key}"]`, (td) => td.textContent);
}

// Set a slider of the view and wait for the page to answer it.
async function setMultiSlider(key, value) {
  const before = await page.$eval("#several", (s) => s.dataset.updates);
  await page.$eval(`#m-${key}`, (el, v) => {
    el.value = v;
    el.dispatchEvent(new Event("input", { bubbles: true }));
  }, String(value));
  await page.waitForFunction((b) => document.getElementById("several").dataset.updates !== b, before);
}

// The table against `impax compare NAME --json`, to the five decimals shown, for every law.
async function checkMultiTable(json) {
  const a = await page.evaluate(() => window.explorerMulti.answer);
  assert.deepEqual(a.results.map((r) => r.law), json.results.map((r) => r.law));
  for (const r of json.results) {
    assert.equal(await page.$eval(`#multi-laws td.verdict[data-law="${r.law}"]`, (td) => td.dataset.verdict), r.verdict, `${r.law}: verdict`);
    const expected = { dT: r.energy_change, ratio: r.energy_ratio };
    for (const c of a.columns) {
      if (c.kind === "velocity") expected[c.key] = r.velocities_after[json.coordinates.indexOf(c.key)];
    }
    r.contacts.forEach((ct, j) => { expected[`pn${j + 1}`] = ct.impulse.n; });
    assert.equal(Object.keys(expected).length, a.columns.length);
    for (const [key, value] of Object.entries(expected)) {
      const text = await multiCell(r.law, key);
      assert.equal(shown(text).toFixed(5), (Math.abs(value) < 0.5e-5 ? 0 : value).toFixed(5).replace("-0.00000", "0.00000"),
        `${r.law} ${key}: page shows ${text}, impax compare --json gives ${value}`);
    }
  }
}

// How many pixels of a law's canvas are not white.
async function inked(law) {
  return page.$eval(`#multi-anims figure[data-law="${law}"] canvas`, (c) => {
    const d = c.getContext("2d").getImageData(0, 0, c.width, c.height).data;
    let n = 0;
    for (let i = 0; i < d.length; i += 4) if (d[i] < 200 || d[i + 1] < 200 || d[i + 2] < 200) n++;
    return n;
  });
}

async function pixels(law) {
  return page.$eval(`#multi-anims figure[data-law="${law}"] canvas`, (c) => c.toDataURL());
}

async function setClock(fraction) {
  await page.$eval("#multi-clock", (el, v) => { el.value = v; el.dispatchEvent(new Event("input", { bubbles: true })); }, String(fraction));
}

test("several contacts: Newton's cradle under every multi-contact law, as impax compare cradle --json", async () => {
  await page.click("#tab-several");
  await page.waitForSelector('#several[data-ready="1"]', { timeout: 20000 });
  assert.equal(await page.$eval("#one-contact", (m) => m.hidden), true);
  assert.equal(await page.$eval("#multi-system", (s) => s.value), "cradle");
  const laws = await page.$$eval("#multi-laws thead th.law", (ths) => ths.map((th) => th.dataset.law));
  assert.deepEqual(laws, ["lcp", "sequential", "lzb"]);
  // The LCP's cradle: (−1/3, 2/3, 2/3) v0; binary impacts: (0, 0, v0).
  assert.equal(await multiCell("lcp", "x1"), "−0.33333");
  assert.equal(await multiCell("lcp", "x2"), "+0.66667");
  assert.equal(await multiCell("sequential", "x3"), "+1.00000");
  await checkMultiTable(impax("compare", "cradle", "--json"));
  // One animation per law, drawn.
  for (const law of laws) assert.ok((await inked(law)) > 500, `${law}: the canvas is drawn`);
  // The clock moves the balls: lcp's first ball goes back, sequential's stays.
  await setClock(0.05);
  const [lcpAt0, seqAt0] = [await pixels("lcp"), await pixels("sequential")];
  await setClock(0.8);
  assert.notEqual(await pixels("lcp"), lcpAt0, "lcp's balls move");
  assert.notEqual(await pixels("sequential"), seqAt0, "the last ball moves under sequential");
  assert.equal(await page.$eval("#multi-play", (b) => b.textContent), "play");
  await page.click("#multi-play");
  assert.equal(await page.$eval("#multi-play", (b) => b.textContent), "pause");
});

test("several contacts: a slider changes the numbers (balls, then e), as impax compare cradle does", async () => {
  await setMultiSlider("balls", 4);
  assert.notEqual(await multiCell("lcp", "x1"), "−0.33333");
  assert.ok(await page.$('#multi-laws td[data-law="lcp"][data-key="x4"]'), "a fourth ball's column");
  await checkMultiTable(impax("compare", "cradle", "--balls", "4", "--json"));
  const before = await multiCell("sequential", "ratio");
  await setMultiSlider("restitution", 0.5);
  assert.notEqual(await multiCell("sequential", "ratio"), before);
  await checkMultiTable(impax("compare", "cradle", "--balls", "4", "--restitution", "0.5", "--json"));
  // Eight balls: seven contacts, beyond lcp's six: its column says so.
  await setMultiSlider("balls", 8);
  assert.equal(await page.$eval('#multi-laws td.verdict[data-law="lcp"]', (td) => td.dataset.verdict), "omitted");
  assert.match(await page.$eval("#multi-notes", (p) => p.textContent), /lcp: .*at most 6 contacts/);
  assert.ok((await inked("sequential")) > 500);
  await page.click("#multi-reset");
  await page.waitForFunction(() => document.querySelector('#multi-laws td[data-law="lcp"][data-key="x1"]')?.textContent === "−0.33333");
});

test("several contacts: the rod landing flat and the rocking block, and a rod that does not land is an error", async () => {
  await page.selectOption("#multi-system", "rod-flat");
  await page.waitForFunction(() => window.explorerMulti.answer.system === "rod-flat");
  const vy = await page.$eval("#m-vy", (el) => el.value), omega = await page.$eval("#m-omega", (el) => el.value);
  await checkMultiTable(impax("compare", "rod-flat", "--vy", vy, "--omega", omega, "--json"));
  const end = await page.$eval('#multi-anims figure[data-law="lcp"] figcaption', (f) => f.textContent);
  assert.match(end, /strikes the floor at t = /);
  await setMultiSlider("omega", 0);
  await setMultiSlider("vy", -2);
  await checkMultiTable(impax("compare", "rod-flat", "--vy", "-2", "--omega", "0", "--json"));
  // Landing level: lcp and lzb give (0, e |v_y|, 0).
  assert.equal(await multiCell("lcp", "y"), "+1.00000");
  assert.equal(await multiCell("lzb", "y"), "+1.00000");
  await page.$eval("#m-vy", (el) => { el.value = "0.5"; el.dispatchEvent(new Event("input", { bubbles: true })); });
  assert.match(await page.$eval("#multi-error", (e) => (e.hidden ? "" : e.textContent)), /^vy, omega: no end of the rod comes down/);
  await page.selectOption("#multi-system", "rocking-block");
  await page.waitForFunction(() => window.explorerMulti.answer.system === "rocking-block");
  assert.equal(await page.$eval("#multi-error", (e) => e.hidden), true);
  await checkMultiTable(impax("compare", "rocking-block", "--json"));
  // Housner: ω⁺/ω⁻ = 1 − (3/2) sin²α = 0.85 for b = 0.2, h = 0.6.
  assert.equal(await multiCell("lcp", "theta"), "−0.85000");
  await page.selectOption("#multi-system", "ball-ball-wall");
  await page.waitForFunction(() => window.explorerMulti.answer.system === "ball-ball-wall");
  await checkMultiTable(impax("compare", "ball-ball-wall", "--json"));
  const [sw, iw] = await page.evaluate(() => [document.documentElement.scrollWidth, window.innerWidth]);
  assert.ok(sw <= iw, `no horizontal scrolling (${sw} > ${iw})`);
  assert.ok(!(await page.content()).includes("NaN"));
  // The screenshot of the view: the cradle 1.2 s after the impact.
  await page.selectOption("#multi-system", "cradle");
  await page.waitForFunction(() => window.explorerMulti.answer.system === "cradle");
  await setClock(0.6);
  fs.mkdirSync(path.dirname(MULTI_SCREENSHOT), { recursive: true });
  await page.screenshot({ path: MULTI_SCREENSHOT, fullPage: true });
  await page.click("#tab-one");
  assert.equal(await page.$eval("#several", (m) => m.hidden), true);
  assert.equal(await cell("whittaker", "dT"), "+0.24240");
  assert.deepEqual(errors, []);
});

// ---- the view "Your mechanism" -----------------------------------------------------------

const DOUBLE_PENDULUM = "examples/mechanisms/double-pendulum.toml";
const ARM = "examples/mechanisms/arm-3d.toml";

// Do something in the view and wait for the page to answer it.
async function mechUpdate(action) {
  const before = await page.$eval("#mechanism", (m) => m.dataset.updates);
  await action();
  await page.waitForFunction((b) => document.getElementById("mechanism").dataset.updates !== b, before, { timeout: 5000 });
}

async function mechError() {
  return page.$eval("#mech-error", (e) => (e.hidden ? "" : e.textContent));
}

// The file in the text area, as if typed (the page reads it once the typing pauses).
async function typeFile(text) {
  await mechUpdate(() => page.$eval("#mech-file", (el, t) => {
    el.value = t;
    el.dispatchEvent(new Event("input", { bubbles: true }));
  }, text));
}

// The table against `impax compare FILE --json`, to the five decimals shown, for every law:
// the generalized velocities after, the contact velocity after, the impulse, ΔT and T⁺/T⁻.
async function checkMechanismTable(json) {
  const a = await page.evaluate(() => window.explorerMechanism.answer);
  assert.deepEqual(a.results.map((r) => r.law), json.results.map((r) => r.law));
  const spatial = a.space === "3d";
  const speeds = spatial ? json.speeds : json.coordinates;
  for (const r of json.results) {
    assert.equal(await page.$eval(`#mech-laws td.verdict[data-law="${r.law}"]`, (td) => td.dataset.verdict), r.verdict, `${r.law}: verdict`);
    if (r.verdict === "breakdown") continue;
    const expected = { dT: r.energy_change, ratio: r.energy_ratio };
    speeds.forEach((name, i) => { expected[name] = r.velocities_after[i]; });
    if (spatial) {
      Object.assign(expected, { vt1: r.velocity_after.t1, vt2: r.velocity_after.t2, vn: r.velocity_after.n,
        pt1: r.impulse.t1, pt2: r.impulse.t2, pn: r.impulse.n });
    } else {
      Object.assign(expected, { vt: r.contact_velocity_after.t, vn: r.contact_velocity_after.n, pt: r.impulse.t, pn: r.impulse.n });
    }
    assert.equal(Object.keys(expected).length, a.rows.length, "one row per number");
    for (const [key, value] of Object.entries(expected)) {
      const text = await page.$eval(`#mech-laws td[data-law="${r.law}"][data-key="${key}"]`, (td) => td.textContent);
      assert.equal(shown(text).toFixed(5), (Math.abs(value) < 0.5e-5 ? 0 : value).toFixed(5).replace("-0.00000", "0.00000"),
        `${r.law} ${key}: page shows ${text}, impax compare --json gives ${value}`);
    }
  }
}

test("your mechanism: Kane & Levinson's double pendulum from its file, as impax compare FILE --json", async () => {
  await page.click("#tab-mechanism");
  await page.waitForSelector('#mechanism[data-ready="1"]', { timeout: 20000 });
  assert.equal(await page.evaluate(() => location.hash), "#mechanism");
  assert.equal(await page.$eval("#one-contact", (m) => m.hidden), true);
  assert.equal(await page.$eval("#mech-example", (s) => s.value), "double-pendulum.toml");
  assert.equal(await page.$eval("#mech-file", (t) => t.value), fs.readFileSync(path.join(root, DOUBLE_PENDULUM), "utf8"));
  // The state is the file's.
  assert.equal(await page.$eval("#mech-q-0", (i) => i.value), "0.5235987755982988");
  assert.equal(await page.$eval("#mech-u-1", (i) => i.value), "3");
  const json = impax("compare", DOUBLE_PENDULUM, "--json");
  await checkMechanismTable(json);
  // Kane's paradox: Whittaker's rule gains 26 % of the energy.
  assert.equal(await page.$eval('#mech-laws td[data-law="whittaker"][data-key="ratio"]', (td) => td.textContent), "+1.26087");
  assert.equal(await page.$eval('#mech-laws td.verdict[data-law="whittaker"]', (td) => td.dataset.verdict), "energy-gained");
  assert.ok(!(await page.content()).includes("NaN"));
});

test("your mechanism: the state and the coefficients typed in are used, as impax compare FILE --u … --friction …", async () => {
  await mechUpdate(async () => { await page.fill("#mech-u-1", "2.5"); await page.press("#mech-u-1", "Enter"); });
  await mechUpdate(async () => { await page.fill("#mech-friction-value", "0.3"); await page.press("#mech-friction-value", "Enter"); });
  await checkMechanismTable(impax("compare", DOUBLE_PENDULUM, "--u=-1,2.5", "--friction", "0.3", "--json"));
  // A state that cannot strike (both rods hanging straight down: W is singular) is the
  // command line's error.
  for (const i of [0, 1]) await mechUpdate(async () => { await page.fill(`#mech-q-${i}`, "0"); await page.press(`#mech-q-${i}`, "Enter"); });
  assert.equal(await mechError(), impaxError("compare", DOUBLE_PENDULUM, "--q=0,0"));
  assert.match(await mechError(), /^w: must be positive definite/);
  assert.ok(!(await page.content()).includes("NaN"));
  await mechUpdate(() => page.click("#mech-reset"));
  assert.equal(await mechError(), "");
  await checkMechanismTable(impax("compare", DOUBLE_PENDULUM, "--json"));
});

test("your mechanism: a broken file is one line naming its field as the command line does, never a crash", async () => {
  const text = fs.readFileSync(path.join(root, DOUBLE_PENDULUM), "utf8");
  const bad = text.replace('parent = "rod 1"', 'parent = "rod 3"');
  const file = path.join(os.tmpdir(), `impax-e2e-${process.pid}.toml`);
  fs.writeFileSync(file, bad);
  const cli = impaxError("compare", file, "--json");
  fs.rmSync(file);
  assert.equal(cli, "joint[theta2].parent: `rod 3` is not a body of the file");
  await typeFile(bad);
  assert.equal(await mechError(), `line 36: ${cli}`);
  assert.equal(await page.$eval("#mech-example", (s) => s.value), "", "the menu no longer names an example");
  // The TOML reader's line and column; a body without its mass.
  await typeFile(text.replace("mass = 1.0", "mas = 1.0"));
  assert.match(await mechError(), /^line 16, column 1: unknown field `mas`/);
  await typeFile(text.replace("mass = 1.0", "mass = -1.0"));
  assert.match(await mechError(), /^line 16: body\[rod 1\]\.mass: /);
  await typeFile("");
  assert.notEqual(await mechError(), "");
  assert.ok(!(await page.content()).includes("NaN"));
  assert.deepEqual(errors, []);
  await mechUpdate(() => page.selectOption("#mech-example", "double-pendulum.toml"));
  assert.equal(await mechError(), "");
  await checkMechanismTable(impax("compare", DOUBLE_PENDULUM, "--json"));
});

test("your mechanism: every example of examples/mechanisms/ answers; the arm in space as impax compare FILE --json", async () => {
  const files = await page.$$eval("#mech-example option", (os) => os.map((o) => o.value).filter((v) => v));
  assert.deepEqual([...files].sort(), fs.readdirSync(path.join(root, "examples/mechanisms")).filter((f) => f.endsWith(".toml")).sort());
  // Numbers written as # (the last digit of a velocity may differ between the builds).
  const words = (m) => m.replace(/-?\d[\d.e+-]*/g, "#");
  for (const f of files) {
    await mechUpdate(() => page.selectOption("#mech-example", f));
    const message = await mechError();
    let cli = null;
    try { cli = impax("compare", `examples/mechanisms/${f}`, "--json"); } catch { /* the error below */ }
    if (cli) {
      assert.equal(message, "", f);
      await checkMechanismTable(cli);
    } else if (/has no contact point to strike/.test(impaxError("compare", `examples/mechanisms/${f}`))) {
      // A planar file without a contact point: the command line suggests `impax conserved`.
      assert.match(message, /^contact: `[^`]+` has no contact point to strike/, f);
    } else {
      // The command line's message (the hopper is thrown upwards: its foot does not approach).
      assert.equal(words(message), words(impaxError("compare", `examples/mechanisms/${f}`)), f);
    }
  }
  await mechUpdate(() => page.selectOption("#mech-example", "arm-3d.toml"));
  assert.equal(await page.evaluate(() => window.explorerMechanism.answer.space), "3d");
  await checkMechanismTable(impax("compare", ARM, "--json"));
  const [sw, iw] = await page.evaluate(() => [document.documentElement.scrollWidth, window.innerWidth]);
  assert.ok(sw <= iw, `no horizontal scrolling (${sw} > ${iw})`);
  // The screenshot of the view: Kane & Levinson's pendulum.
  await mechUpdate(() => page.selectOption("#mech-example", "double-pendulum.toml"));
  fs.mkdirSync(path.dirname(MECHANISM_SCREENSHOT), { recursive: true });
  await page.screenshot({ path: MECHANISM_SCREENSHOT, fullPage: true });
  assert.deepEqual(errors, []);
});

// ---- the view of conserved quantities ----------------------------------------------------

// The number the table shows (conserved.js's fmt).
const sixDigits = (x) => (x === 0 ? "0" : Math.abs(x) >= 1e5 || Math.abs(x) < 1e-3 ? x.toExponential(5) : x.toPrecision(6)).replace("-", "−");

async function consUpdate(action) {
  const before = await page.$eval("#conserved", (m) => m.dataset.updates);
  await action();
  await page.waitForFunction((b) => document.getElementById("conserved").dataset.updates !== b, before, { timeout: 10000 });
}

// The page's quantities against `impax conserved NAME --json`: the same quantities, the same
// verdicts, the initial and final values to the six digits shown, and the relative change of
// a quantity that is not conserved to 1e-6 (a conserved one's is rounding noise, which
// differs between the native and the WebAssembly build).
async function checkConserved(json) {
  const a = await page.evaluate(() => window.explorerConserved.answer);
  assert.deepEqual(a.quantities.map((q) => q.name), json.quantities.map((q) => q.name));
  assert.deepEqual(a.cyclic, json.cyclic);
  for (const q of json.quantities) {
    const row = `#cons-table tr[data-name="${q.name}"]`;
    const mine = a.quantities.find((x) => x.name === q.name);
    assert.equal(mine.conserved, q.conserved, `${q.name}: conserved`);
    assert.equal(await page.$eval(`${row} td.verdict`, (td) => td.dataset.verdict), q.conserved ? "conserved" : "not-conserved", q.name);
    assert.equal(await page.$eval(`${row} td[data-col="initial"]`, (td) => td.textContent), sixDigits(q.initial), `${q.name}: initial`);
    assert.equal(await page.$eval(`${row} td[data-col="final"]`, (td) => td.textContent), sixDigits(q.final), `${q.name}: final`);
    if (!q.conserved) {
      assert.ok(Math.abs(mine.relative_deviation - q.relative_deviation) <= 1e-6 * q.relative_deviation, `${q.name}: relative change`);
    }
    assert.equal(mine.values.length, json.samples, `${q.name}: a value per sample`);
  }
}

async function inkedCanvas(selector) {
  return page.$eval(selector, (c) => {
    const d = c.getContext("2d").getImageData(0, 0, c.width, c.height).data;
    let n = 0;
    for (let i = 0; i < d.length; i += 4) if (d[i] < 200 || d[i + 1] < 200 || d[i + 2] < 200) n++;
    return n;
  });
}

test("conserved quantities: the ring-pendulum of paper B, as impax conserved ring-pendulum --json", async () => {
  await page.click("#tab-conserved");
  await page.waitForSelector('#conserved[data-ready="1"]', { timeout: 20000 });
  assert.equal(await page.evaluate(() => location.hash), "#conserved");
  assert.equal(await page.$eval("#mechanism", (m) => m.hidden), true);
  const json = impax("conserved", "ring-pendulum", "--json");
  await checkConserved(json);
  // Paper B: x is cyclic, p_x is conserved and the horizontal momentum P_x is not; the energy
  // and the boost's Noether charge are conserved.
  const verdict = (name) => page.$eval(`#cons-table tr[data-name="${name}"] td.verdict`, (td) => td.textContent);
  assert.equal(await verdict("p_x"), "conserved");
  assert.equal(await verdict("P_x"), "NOT conserved");
  assert.equal(await verdict("energy"), "conserved");
  assert.equal(await verdict("boost x"), "conserved");
  // One plot per quantity, drawn; the motion drawn, and moved by the clock.
  const plots = await page.$$eval("#cons-plots figure", (fs) => fs.map((f) => f.dataset.name));
  assert.deepEqual(plots, json.quantities.map((q) => q.name));
  for (const name of plots) assert.ok((await inkedCanvas(`#cons-plots figure[data-name="${name}"] canvas`)) > 500, `${name}: the plot is drawn`);
  await page.$eval("#cons-clock", (el) => { el.value = "0.1"; el.dispatchEvent(new Event("input", { bubbles: true })); });
  const at = await page.$eval("#cons-anim", (c) => c.toDataURL());
  assert.ok((await inkedCanvas("#cons-anim")) > 500);
  await page.$eval("#cons-clock", (el) => { el.value = "0.4"; el.dispatchEvent(new Event("input", { bubbles: true })); });
  assert.notEqual(await page.$eval("#cons-anim", (c) => c.toDataURL()), at, "the ring rolls");
  assert.equal(await page.$eval("#cons-play", (b) => b.textContent), "play");
  assert.ok(!(await page.content()).includes("NaN"));
});

test("conserved quantities: a slider changes the motion, as impax conserved --rates …; the cart's P_x is conserved", async () => {
  await consUpdate(() => page.$eval("#c-phidot", (el) => { el.value = "1"; el.dispatchEvent(new Event("input", { bubbles: true })); }));
  await checkConserved(impax("conserved", "ring-pendulum", "--rates", "0.5,1", "--json"));
  // An impossible value is the core's error, naming its field.
  await consUpdate(async () => { await page.fill("#c-radius-value", "0"); await page.press("#c-radius-value", "Enter"); });
  assert.match(await page.$eval("#cons-error", (e) => (e.hidden ? "" : e.textContent)), /^radius: 0 is out of range/);
  assert.ok(!(await page.content()).includes("NaN"));
  await consUpdate(() => page.click("#cons-reset"));
  assert.equal(await page.$eval("#cons-error", (e) => e.hidden), true);
  await consUpdate(() => page.selectOption("#cons-system", "cart-pendulum"));
  const cart = impax("conserved", "cart-pendulum", "--json");
  await checkConserved(cart);
  assert.equal(await page.$eval('#cons-table tr[data-name="P_x"] td.verdict', (td) => td.textContent), "conserved");
  await consUpdate(() => page.selectOption("#cons-system", "ring-pendulum"));
  await checkConserved(impax("conserved", "ring-pendulum", "--json"));
  const [sw, iw] = await page.evaluate(() => [document.documentElement.scrollWidth, window.innerWidth]);
  assert.ok(sw <= iw, `no horizontal scrolling (${sw} > ${iw})`);
  // The screenshot of the view, 1.2 s into the motion.
  await page.$eval("#cons-clock", (el) => { el.value = "0.12"; el.dispatchEvent(new Event("input", { bubbles: true })); });
  fs.mkdirSync(path.dirname(CONSERVED_SCREENSHOT), { recursive: true });
  await page.screenshot({ path: CONSERVED_SCREENSHOT, fullPage: true });
  await page.click("#tab-one");
  assert.equal(await page.$eval("#conserved", (m) => m.hidden), true);
  assert.equal(await page.evaluate(() => location.hash), "");
  assert.equal(await cell("whittaker", "dT"), "+0.24240");
  assert.deepEqual(errors, []);
});

test("the folder written by --out works offline (file://) and the page fits a laptop screen", async () => {
  const dir = fs.mkdtempSync(path.join(os.tmpdir(), "impax-explorer-"));
  execFileSync(IMPAX, ["explore", "--out", dir]);
  const offline = await browser.newPage({ viewport: { width: 1920, height: 1080 } });
  await offline.goto(pathToFileURL(path.join(dir, "index.html")).href);
  await offline.waitForSelector('body[data-ready="1"]', { timeout: 20000 });
  assert.equal(await offline.$eval('#laws tr[data-law="whittaker"] td[data-col="dT"]', (td) => td.textContent), "+0.24240");
  await offline.click("#tab-several");
  await offline.waitForSelector('#several[data-ready="1"]', { timeout: 20000 });
  assert.equal(await offline.$eval('#multi-laws td[data-law="lcp"][data-key="x1"]', (td) => td.textContent), "−0.33333");
  // An address ending in #mechanism or #conserved opens that view, and so does changing the
  // address of the open page.
  const direct = await browser.newPage({ viewport: { width: 1366, height: 768 } });
  await direct.goto(pathToFileURL(path.join(dir, "index.html")).href + "#mechanism");
  await direct.waitForSelector('#mechanism[data-ready="1"]', { timeout: 20000 });
  assert.equal(await direct.$eval("#one-contact", (m) => m.hidden), true);
  assert.equal(await direct.$eval('#mech-laws td[data-law="whittaker"][data-key="ratio"]', (td) => td.textContent), "+1.26087");
  await direct.evaluate(() => { location.hash = "#conserved"; });
  await direct.waitForSelector('#conserved[data-ready="1"]', { timeout: 20000 });
  assert.equal(await direct.$eval("#mechanism", (m) => m.hidden), true);
  assert.equal(await direct.$eval('#cons-table tr[data-name="P_x"] td.verdict', (td) => td.textContent), "NOT conserved");
  await direct.close();
  await offline.click("#tab-one");
  for (const p of [offline, page]) {
    const [sw, iw] = await p.evaluate(() => [document.documentElement.scrollWidth, window.innerWidth]);
    assert.ok(sw <= iw, `no horizontal scrolling (${sw} > ${iw})`);
  }
  await offline.close();
  fs.rmSync(dir, { recursive: true });
  // The screenshot of the seed's case, the rebound of Whittaker's rule.
  await page.$eval("#play", (b) => b.click());
  await page.waitForTimeout(200);
  fs.mkdirSync(path.dirname(SCREENSHOT), { recursive: true });
  await page.screenshot({ path: SCREENSHOT, fullPage: true });
  assert.deepEqual(errors, []);
});
