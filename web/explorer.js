// The explorer page: sliders → a request → the impax core (WebAssembly, impax.js) → the
// table, the energy bars, Routh's diagram, the energy-gain map and the animation.
// Every number shown comes from the core; this file only lays out and draws.
"use strict";

// ---- parameters --------------------------------------------------------------------------

const MOTION = [
  { key: "alpha_deg", label: "approach angle α", unit: "° from the normal", min: -89, max: 89, step: 0.5, value: 30 },
  { key: "spin_ratio", label: "spin ratio γ = ω₀ρ/v₀", unit: "ρ: centre to contact", min: -2, max: 2, step: 0.001, value: 0 },
  { key: "speed", label: "approach speed v₀", unit: "length/time", min: 0.1, max: 5, step: 0.1, value: 1 },
];
const COEFFICIENTS = [
  { key: "friction", label: "friction μ", unit: "Coulomb", min: 0, max: 1.5, step: 0.005, value: 0.4 },
  { key: "restitution", label: "restitution e", unit: "", min: 0, max: 1, step: 0.01, value: 0.7 },
];
const MASS = { key: "mass", label: "mass m", unit: "", min: 0.1, max: 5, step: 0.1, value: 1 };
// Slider presets of the shapes (keys: the core's names of their numbers, info.shape_parameters).
const SHAPE_PARAMETERS = {
  sphere: [MASS, { key: "radius", label: "radius r", unit: "length", min: 0.1, max: 3, step: 0.05, value: 1 }],
  disc: [MASS, { key: "radius", label: "radius r", unit: "length", min: 0.1, max: 3, step: 0.05, value: 1 }],
  rod: [MASS,
    { key: "length", label: "length L", unit: "length", min: 0.2, max: 4, step: 0.05, value: 2 },
    { key: "angle_deg", label: "angle to the surface", unit: "°", min: 5, max: 175, step: 0.5, value: 50 }],
  ellipse: [MASS,
    { key: "semi_axis_a", label: "semi-axis a", unit: "length", min: 0.2, max: 3, step: 0.05, value: 2 },
    { key: "semi_axis_b", label: "semi-axis b", unit: "length", min: 0.2, max: 3, step: 0.05, value: 1 },
    { key: "angle_deg", label: "angle of a to the surface", unit: "°", min: -90, max: 90, step: 0.5, value: 20 }],
  rigid: [MASS,
    { key: "inertia", label: "moment of inertia I", unit: "about the centre", min: 0.05, max: 5, step: 0.05, value: 0.5 },
    { key: "contact_t", label: "contact point r_t", unit: "from the centre", min: -2, max: 2, step: 0.05, value: 0.3 },
    { key: "contact_n", label: "contact point r_n", unit: "below the centre", min: -2, max: -0.05, step: 0.05, value: -1 }],
};
// The sliders of a shape with no preset, by what its number measures (the core's quantity).
const QUANTITY_SLIDERS = {
  length: { unit: "length", min: 0.1, max: 3, step: 0.05, value: 1 },
  angle: { unit: "° from the surface", min: -90, max: 90, step: 0.5, value: 20 },
  inertia: { unit: "about the centre", min: 0.05, max: 5, step: 0.05, value: 0.5 },
  offset: { unit: "from the centre", min: -2, max: 2, step: 0.05, value: 0 },
};
const PENDULUM = [
  { key: "angle1_deg", label: "θ₁ (rod 1)", unit: "° from the downward vertical", min: -85, max: 85, step: 0.5, value: 30 },
  { key: "angle2_deg", label: "θ₂ (rod 2)", unit: "° from the downward vertical", min: -85, max: 85, step: 0.5, value: 0 },
  { key: "rate1", label: "θ̇₁", unit: "rad/s", min: -5, max: 5, step: 0.05, value: -1 },
  { key: "rate2", label: "θ̇₂", unit: "rad/s", min: -5, max: 5, step: 0.05, value: 2 },
  { key: "friction", label: "friction μ", unit: "Coulomb", min: 0, max: 1.5, step: 0.005, value: 0.5 },
  { key: "restitution", label: "restitution e", unit: "", min: 0, max: 1, step: 0.01, value: 0.5 },
  { key: "m1", label: "mass m₁", unit: "", min: 0.1, max: 5, step: 0.1, value: 1 },
  { key: "m2", label: "mass m₂", unit: "", min: 0.1, max: 5, step: 0.1, value: 1 },
  { key: "l1", label: "length l₁", unit: "", min: 0.1, max: 3, step: 0.05, value: 1 },
  { key: "l2", label: "length l₂", unit: "", min: 0.1, max: 3, step: 0.05, value: 1 },
];
// Short element ids for the sliders the page is driven by.
const SLIDER_IDS = { alpha_deg: "alpha", spin_ratio: "gamma", friction: "mu", restitution: "e" };

const AXIS_LABELS = {
  alpha_deg: "approach angle α (°)",
  spin_ratio: "spin ratio γ = ω₀ρ/v₀ (–)",
  friction: "friction coefficient μ (–)",
  restitution: "restitution e (–)",
  angle_deg: "body angle to the surface (°)",
  angle1_deg: "θ₁ from the vertical (°)",
  angle2_deg: "θ₂ from the vertical (°)",
  rate1: "θ̇₁ before (rad/s)",
  rate2: "θ̇₂ before (rad/s)",
};
const AXIS_RANGES = {
  alpha_deg: [0, 89], spin_ratio: [-2, 2], friction: [0, 1.5], restitution: [0, 1],
  angle_deg: [5, 175], angle1_deg: [-80, 80], angle2_deg: [-80, 80], rate1: [-5, 5], rate2: [-5, 5],
};

// A colour, a dash pattern and a width per law, so that paths and rows stay apart in greyscale.
const LAW_STYLE = {
  whittaker: { colour: "#d62728", dash: [] },
  "two-phase": { colour: "#ff7f0e", dash: [10, 5] },
  smith: { colour: "#9467bd", dash: [3, 4] },
  "smith-centre": { colour: "#e377c2", dash: [12, 4, 3, 4] },
  brach: { colour: "#8c564b", dash: [16, 6] },
  newton: { colour: "#1f77b4", dash: [] },
  poisson: { colour: "#17becf", dash: [6, 3] },
  energetic: { colour: "#2ca02c", dash: [] },
  lcp: { colour: "#7f7f7f", dash: [1, 4] },
};
const styleOf = (law) => LAW_STYLE[law] || { colour: "#444", dash: [2, 2] };

const GAIN = "#c62828";
const LOSS = "#4a7bb0";

// ---- state -------------------------------------------------------------------------------

const state = {
  kind: "sphere",
  values: {},
  law: "whittaker",
  info: null,
  compare: null,
  map: null,
  mapKey: "",
  mapTimer: 0,
  timings: [],
};
window.explorer = state;

const $ = (id) => document.getElementById(id);

function shapeParameters(kind) {
  if (SHAPE_PARAMETERS[kind]) return SHAPE_PARAMETERS[kind];
  const generic = (p) => ({ key: p.name, label: p.label, ...QUANTITY_SLIDERS[p.quantity] });
  return [MASS, ...state.info.shape_parameters[kind].map(generic)];
}

function parametersOf(kind) {
  if (kind === "double-pendulum") return PENDULUM;
  return [MOTION[0], MOTION[1], ...COEFFICIENTS, ...shapeParameters(kind), MOTION[2]];
}

function buildSliders() {
  const box = $("sliders");
  box.textContent = "";
  for (const p of parametersOf(state.kind)) {
    if (!(p.key in state.values)) state.values[p.key] = p.value;
    const wrap = document.createElement("div");
    wrap.className = "slider";
    const id = SLIDER_IDS[p.key] || `p-${p.key}`;
    wrap.innerHTML = `<div class="head"><label for="${id}">${p.label} <span class="unit">${p.unit}</span></label></div>`;
    // The exact value, typed (it may leave the slider's range: the core then says what is wrong).
    const typed = document.createElement("input");
    Object.assign(typed, { type: "number", id: `${id}-value`, step: "any", className: "typed" });
    typed.setAttribute("aria-label", `${p.label}, exact value`);
    typed.addEventListener("change", () => {
      const x = Number(typed.value);
      if (typed.value.trim() === "" || !Number.isFinite(x)) { showValue(p.key); return; }
      state.values[p.key] = x;
      $(id).value = x;
      update();
    });
    wrap.firstChild.appendChild(typed);
    const input = document.createElement("input");
    Object.assign(input, { type: "range", id, min: p.min, max: p.max, step: p.step });
    input.value = state.values[p.key];
    input.dataset.key = p.key;
    input.addEventListener("input", () => {
      state.values[p.key] = Number(input.value);
      showValue(p.key);
      update();
    });
    wrap.appendChild(input);
    box.appendChild(wrap);
    showValue(p.key);
  }
}

function showValue(key) {
  const id = SLIDER_IDS[key] || `p-${key}`;
  const out = $(`${id}-value`);
  if (out) out.value = String(state.values[key]);
}

function setParameter(key, value) {
  const id = SLIDER_IDS[key] || `p-${key}`;
  const input = $(id);
  if (!input) return;
  input.value = value;
  state.values[key] = Number(input.value);
  showValue(key);
}

function request() {
  const v = state.values;
  if (state.kind === "double-pendulum") {
    return {
      friction: v.friction, restitution: v.restitution,
      mechanism: {
        name: "double-pendulum", masses: [v.m1, v.m2], lengths: [v.l1, v.l2],
        angles_deg: [v.angle1_deg, v.angle2_deg], rates: [v.rate1, v.rate2],
      },
    };
  }
  const body = { shape: state.kind, mass: v.mass, speed: v.speed, alpha_deg: v.alpha_deg, spin_ratio: v.spin_ratio };
  // The shape's numbers where the core's table puts them (`semi_axis_a` → `semi_axes[0]`).
  for (const p of state.info.shape_parameters[state.kind]) {
    if (p.index === null) body[p.key] = v[p.name];
    else (body[p.key] ||= [])[p.index] = v[p.name];
  }
  return { friction: v.friction, restitution: v.restitution, body };
}

// ---- formatting --------------------------------------------------------------------------

// As `impax compare`'s table: a sign and `digits` decimals; −0 as +0.
function signed(x, digits) {
  if (x === null || x === undefined) return "—";
  const s = Math.abs(x).toFixed(digits);
  const zero = Number(s) === 0;
  return (x < 0 && !zero ? "−" : "+") + s;
}

function verdictText(r) {
  switch (r.verdict) {
    case "energy-gained":
      return r.inconsistency ? "ENERGY GAINED (Kane's paradox); inconsistent assumption" : "ENERGY GAINED (Kane's paradox)";
    case "inconsistent-assumption": return "inconsistent assumption";
    case "breakdown": return "BREAKDOWN";
    default: return "consistent";
  }
}

function tick(x) {
  const a = Math.abs(x);
  if (a === 0) return "0";
  if (a >= 1e4 || a < 1e-3) return x.toExponential(1);
  return String(Number(x.toPrecision(4))).replace("-", "−");
}

function niceTicks(lo, hi, count) {
  const span = hi - lo;
  if (!(span > 0)) return [lo];
  const raw = span / count;
  const mag = Math.pow(10, Math.floor(Math.log10(raw)));
  const step = [1, 2, 2.5, 5, 10].map((m) => m * mag).find((s) => s >= raw) || raw;
  const out = [];
  for (let t = Math.ceil(lo / step - 1e-9) * step; t <= hi + 1e-9 * span; t += step) out.push(Math.abs(t) < 1e-12 * step ? 0 : t);
  return out;
}

// ---- canvases ----------------------------------------------------------------------------

const FONT = '13px system-ui, -apple-system, "Segoe UI", "DejaVu Sans", sans-serif';
const SMALL = '12px system-ui, -apple-system, "Segoe UI", "DejaVu Sans", sans-serif';

// Size a canvas to its displayed width (× device pixels) and return a context in CSS pixels.
function context(canvas, aspect) {
  const w = Math.max(300, canvas.clientWidth || 600);
  const h = Math.round(w * aspect);
  const dpr = window.devicePixelRatio || 1;
  if (canvas.width !== Math.round(w * dpr) || canvas.height !== Math.round(h * dpr)) {
    canvas.width = Math.round(w * dpr);
    canvas.height = Math.round(h * dpr);
  }
  const ctx = canvas.getContext("2d");
  ctx.setTransform(dpr, 0, 0, dpr, 0, 0);
  ctx.clearRect(0, 0, w, h);
  ctx.fillStyle = "#fff";
  ctx.fillRect(0, 0, w, h);
  ctx.font = FONT;
  return { ctx, w, h };
}

// Diagonal hatching over `colour`: the gain stays visible in greyscale.
function hatch(ctx, colour, background) {
  const c = document.createElement("canvas");
  c.width = c.height = 8;
  const g = c.getContext("2d");
  g.fillStyle = background;
  g.fillRect(0, 0, 8, 8);
  g.strokeStyle = colour;
  g.lineWidth = 2;
  g.beginPath();
  g.moveTo(0, 8); g.lineTo(8, 0);
  g.moveTo(-2, 2); g.lineTo(2, -2);
  g.moveTo(6, 10); g.lineTo(10, 6);
  g.stroke();
  return ctx.createPattern(c, "repeat");
}

// A frame with axes: returns the mapping from data to pixels.
function axes(ctx, box, xr, yr, xLabel, yLabel, grid = true) {
  const { x0, y0, w, h } = box;
  const X = (x) => x0 + ((x - xr[0]) / (xr[1] - xr[0])) * w;
  const Y = (y) => y0 + h - ((y - yr[0]) / (yr[1] - yr[0])) * h;
  ctx.save();
  ctx.font = SMALL;
  ctx.fillStyle = "#222";
  ctx.strokeStyle = "#e2e2e2";
  ctx.lineWidth = 1;
  ctx.textAlign = "center";
  ctx.textBaseline = "top";
  for (const t of niceTicks(xr[0], xr[1], Math.max(3, Math.floor(w / 80)))) {
    if (grid) { ctx.beginPath(); ctx.moveTo(X(t), y0); ctx.lineTo(X(t), y0 + h); ctx.stroke(); }
    ctx.fillText(tick(t), X(t), y0 + h + 4);
  }
  ctx.textAlign = "right";
  ctx.textBaseline = "middle";
  for (const t of niceTicks(yr[0], yr[1], Math.max(3, Math.floor(h / 50)))) {
    if (grid) { ctx.beginPath(); ctx.moveTo(x0, Y(t)); ctx.lineTo(x0 + w, Y(t)); ctx.stroke(); }
    ctx.fillText(tick(t), x0 - 5, Y(t));
  }
  ctx.strokeStyle = "#777";
  ctx.strokeRect(x0, y0, w, h);
  ctx.font = FONT;
  ctx.textAlign = "center";
  ctx.textBaseline = "bottom";
  ctx.fillText(xLabel, x0 + w / 2, y0 + h + 36);
  ctx.save();
  ctx.translate(x0 - 44, y0 + h / 2);
  ctx.rotate(-Math.PI / 2);
  ctx.textBaseline = "bottom";
  ctx.fillText(yLabel, 0, 0);
  ctx.restore();
  ctx.restore();
  return { X, Y };
}

// ---- the table ---------------------------------------------------------------------------

function renderTable(r) {
  const head = $("laws").tHead;
  const cols = r.columns;
  head.innerHTML = "<tr><th class='text'>law</th>" + cols.map((c) => `<th>${c.label}</th>`).join("") +
    "<th class='text'>phases (regime@p<sub>n</sub> at its end)</th><th class='text'>verdict</th></tr>";
  const body = $("laws").tBodies[0];
  body.textContent = "";
  const notes = [];
  for (const res of r.results) {
    const tr = document.createElement("tr");
    tr.dataset.law = res.law;
    tr.dataset.verdict = res.verdict;
    tr.className = (res.verdict === "energy-gained" ? "gained" : res.verdict === "breakdown" ? "breakdown" : "") +
      (res.law === state.law ? " selected" : "");
    const st = styleOf(res.law);
    let html = `<td class="law text"><span class="swatch" style="border-top-color:${st.colour};border-top-style:${st.dash.length ? "dashed" : "solid"}"></span>${res.law}</td>`;
    cols.forEach((c, i) => {
      const x = res.values ? res.values[i] : null;
      html += `<td class="num ${c.key}" data-col="${c.key}">${res.values ? signed(x, 5) : "—"}</td>`;
    });
    const phases = res.phases.map((p) => `${p.kind}@${p.ends_at.toFixed(4)}`).join(" → ") || "—";
    html += `<td class="text phases">${phases}</td><td class="text verdict" data-verdict="${res.verdict}">${verdictText(res)}</td>`;
    tr.innerHTML = html;
    tr.addEventListener("click", () => selectLaw(res.law));
    body.appendChild(tr);
    if (res.inconsistency) notes.push(`${res.law}: ${res.inconsistency.message}`);
    if (res.breakdown) notes.push(`${res.law}: breakdown: ${res.breakdown.message}`);
  }
  const t0 = r.kind === "body" ? "T0 = ½ m v₀² (translational kinetic energy before)" : "T⁻ = kinetic energy before";
  $("notes").textContent = `ΔT/T0 with ${t0}. ` + notes.join(" · ");
}

function selectLaw(law) {
  state.law = law;
  $("law").value = law;
  for (const tr of $("laws").tBodies[0].rows) tr.classList.toggle("selected", tr.dataset.law === law);
  drawRouth();
  scheduleMap(true);
  startAnimation();
}

// ---- energy bars -------------------------------------------------------------------------

function drawBars() {
  const r = state.compare;
  const rows = r.results;
  const canvas = $("bars");
  const rowH = 26;
  const width = Math.max(300, canvas.clientWidth || 600);
  const { ctx, w } = context(canvas, (rows.length * rowH + 84) / width);
  const values = rows.filter((x) => x.energy).map((x) => x.energy_change_ratio);
  let lo = Math.min(0, ...values), hi = Math.max(0, ...values);
  // Room on both sides of the zero line, for the labels and for the eye.
  lo = Math.min(lo, -0.45 * hi); hi = Math.max(hi, -0.45 * lo);
  const span = Math.max(hi - lo, 1e-9);
  lo -= 0.04 * span; hi += 0.04 * span;
  const box = { x0: 112, y0: 10, w: w - 112 - 110, h: rows.length * rowH };
  const X = (x) => box.x0 + ((x - lo) / (hi - lo)) * box.w;
  ctx.font = SMALL;
  ctx.strokeStyle = "#eee";
  ctx.fillStyle = "#222";
  ctx.textAlign = "center";
  ctx.textBaseline = "top";
  for (const t of niceTicks(lo, hi, 6)) {
    ctx.beginPath(); ctx.moveTo(X(t), box.y0); ctx.lineTo(X(t), box.y0 + box.h); ctx.stroke();
    ctx.fillText(tick(t), X(t), box.y0 + box.h + 4);
  }
  const gainFill = hatch(ctx, GAIN, "#f7c6c0");
  rows.forEach((res, i) => {
    const yc = box.y0 + i * rowH + rowH / 2;
    ctx.font = FONT;
    ctx.textAlign = "right";
    ctx.textBaseline = "middle";
    ctx.fillStyle = res.law === state.law ? "#000" : "#333";
    ctx.fillText(res.law, box.x0 - 8, yc);
    if (!res.energy) {
      ctx.textAlign = "left";
      ctx.fillStyle = "#666";
      ctx.fillText("breakdown: no result", X(0) + 6, yc);
      return;
    }
    const v = res.energy_change_ratio;
    const a = X(Math.min(0, v)), b = X(Math.max(0, v));
    ctx.fillStyle = v > 0 ? gainFill : LOSS;
    ctx.fillRect(a, yc - 9, Math.max(b - a, 1), 18);
    ctx.strokeStyle = v > 0 ? GAIN : "#2c5582";
    ctx.lineWidth = v > 0 ? 2 : 1;
    ctx.strokeRect(a, yc - 9, Math.max(b - a, 1), 18);
    // The value beside the bar, on the side of the zero line the bar does not take.
    ctx.font = SMALL;
    ctx.fillStyle = v > 0 ? GAIN : "#222";
    ctx.textAlign = "left";
    ctx.fillText(signed(v, 4) + (v > 0 ? " gained" : ""), v > 0 ? b + 5 : X(0) + 5, yc);
  });
  // The zero line.
  ctx.strokeStyle = "#000";
  ctx.lineWidth = 2;
  ctx.beginPath(); ctx.moveTo(X(0), box.y0 - 4); ctx.lineTo(X(0), box.y0 + box.h + 2); ctx.stroke();
  ctx.font = FONT;
  ctx.fillStyle = "#222";
  ctx.textAlign = "center";
  ctx.textBaseline = "bottom";
  const label = state.compare.kind === "body" ? "ΔT / T0: change of kinetic energy (T0 = ½ m v₀²)" : "ΔT / T⁻: change of kinetic energy";
  ctx.fillText(label, box.x0 + box.w / 2, box.y0 + box.h + 38);
  ctx.font = SMALL;
  ctx.textAlign = "right";
  ctx.fillStyle = "#444";
  ctx.fillText("◀ energy lost", X(0) - 6, box.y0 + box.h + 56);
  ctx.textAlign = "left";
  ctx.fillStyle = GAIN;
  ctx.fillText("energy gained (hatched) ▶", X(0) + 6, box.y0 + box.h + 56);
}

// ---- Routh's diagram ---------------------------------------------------------------------

// The part of the line u x + v y = c inside the rectangle.
function clipLine(u, v, c, xr, yr) {
  const pts = [];
  if (v !== 0) for (const x of xr) { const y = (c - u * x) / v; if (y >= yr[0] && y <= yr[1]) pts.push([x, y]); }
  if (u !== 0) for (const y of yr) { const x = (c - v * y) / u; if (x >= xr[0] && x <= xr[1]) pts.push([x, y]); }
  pts.sort((p, q) => p[0] - q[0] || p[1] - q[1]);
  return pts.length >= 2 ? [pts[0], pts[pts.length - 1]] : null;
}

function drawRouth() {
  const r = state.compare;
  if (!r) return;
  const { ctx, w, h } = context($("routh"), 0.62);
  const paths = r.results.filter((x) => x.path && x.path.length);
  let xmin = 0, xmax = 0, ymax = 0;
  for (const p of paths) for (const [x, y] of p.path) { xmin = Math.min(xmin, x); xmax = Math.max(xmax, x); ymax = Math.max(ymax, y); }
  const newton = r.routh.lines.find((l) => l.id === "newton");
  if (newton && newton.coef[1] > 0) ymax = Math.max(ymax, newton.coef[2] / newton.coef[1]);
  ymax = Math.max(ymax, 1e-9) * 1.12;
  const spanX = Math.max(xmax - xmin, 0.3 * ymax);
  const xr = [xmin - 0.15 * spanX, xmax + 0.15 * spanX];
  const yr = [-0.03 * ymax, ymax];
  const legendW = 200;
  const box = { x0: 64, y0: 10, w: w - 64 - legendW - 16, h: h - 10 - 54 };
  const unit = "mass × velocity";
  const { X, Y } = axes(ctx, box, xr, yr, `tangential impulse p_t (${unit})`, `normal impulse p_n (${unit})`);
  ctx.save();
  ctx.beginPath(); ctx.rect(box.x0, box.y0, box.w, box.h); ctx.clip();
  // The friction cone.
  const mu = r.routh.friction;
  ctx.strokeStyle = "#999"; ctx.lineWidth = 1; ctx.setLineDash([6, 5]);
  ctx.beginPath(); ctx.moveTo(X(-mu * yr[1]), Y(yr[1])); ctx.lineTo(X(0), Y(0)); ctx.lineTo(X(mu * yr[1]), Y(yr[1])); ctx.stroke();
  const lineStyle = { stick: ["#00897b", [], 2], compression: ["#555", [], 2], newton: ["#555", [9, 5], 1.5] };
  for (const l of r.routh.lines) {
    const seg = clipLine(l.coef[0], l.coef[1], l.coef[2], xr, yr);
    if (!seg) continue;
    const [c, d, lw] = lineStyle[l.id] || ["#777", [2, 2], 1];
    ctx.strokeStyle = c; ctx.setLineDash(d); ctx.lineWidth = lw;
    ctx.beginPath(); ctx.moveTo(X(seg[0][0]), Y(seg[0][1])); ctx.lineTo(X(seg[1][0]), Y(seg[1][1])); ctx.stroke();
  }
  // Paths: earlier laws wider, so that coinciding paths stay visible; the selected law on top.
  const order = paths.map((p, i) => [p, i]).sort((a, b) => (a[0].law === state.law) - (b[0].law === state.law));
  const n = paths.length;
  for (const [p, i] of order) {
    const st = styleOf(p.law);
    const selected = p.law === state.law;
    ctx.strokeStyle = st.colour;
    ctx.setLineDash(st.dash);
    ctx.lineWidth = selected ? 5 : 1.5 + (4 * (n - 1 - i)) / Math.max(n - 1, 1);
    ctx.beginPath();
    p.path.forEach(([x, y], k) => (k ? ctx.lineTo(X(x), Y(y)) : ctx.moveTo(X(x), Y(y))));
    ctx.stroke();
    ctx.setLineDash([]);
    const [ex, ey] = p.path[p.path.length - 1];
    ctx.fillStyle = st.colour; ctx.strokeStyle = "#000"; ctx.lineWidth = 1;
    ctx.beginPath(); ctx.arc(X(ex), Y(ey), selected ? 6 : 4.5, 0, 2 * Math.PI); ctx.fill(); ctx.stroke();
    for (const [x, y] of p.path.slice(1, -1)) {
      ctx.beginPath(); ctx.moveTo(X(x), Y(y) - 6); ctx.lineTo(X(x) - 5, Y(y) + 4); ctx.lineTo(X(x) + 5, Y(y) + 4); ctx.closePath(); ctx.fill(); ctx.stroke();
    }
  }
  ctx.restore();
  // Legend.
  ctx.font = SMALL;
  ctx.textBaseline = "middle";
  ctx.textAlign = "left";
  let ly = box.y0 + 8;
  const lx = box.x0 + box.w + 14;
  const item = (draw, text) => { draw(lx, ly); ctx.fillStyle = "#222"; ctx.fillText(text, lx + 30, ly); ly += 17; };
  for (const p of paths) {
    const st = styleOf(p.law);
    item((x, y) => { ctx.strokeStyle = st.colour; ctx.setLineDash(st.dash); ctx.lineWidth = p.law === state.law ? 4 : 2.5; ctx.beginPath(); ctx.moveTo(x, y); ctx.lineTo(x + 24, y); ctx.stroke(); ctx.setLineDash([]); }, p.law);
  }
  ly += 4;
  const lineItem = (c, d, lw, text) => item((x, y) => { ctx.strokeStyle = c; ctx.setLineDash(d); ctx.lineWidth = lw; ctx.beginPath(); ctx.moveTo(x, y); ctx.lineTo(x + 24, y); ctx.stroke(); ctx.setLineDash([]); }, text);
  lineItem("#00897b", [], 2, "sticking: v_t = 0");
  lineItem("#555", [], 2, "max. compression: v_n = 0");
  lineItem("#555", [9, 5], 1.5, "Newton: v_n = −e v_n⁻");
  lineItem("#999", [6, 5], 1, `friction cone (μ = ${mu})`);
  item((x, y) => { ctx.fillStyle = "#888"; ctx.beginPath(); ctx.arc(x + 12, y, 4.5, 0, 2 * Math.PI); ctx.fill(); }, "end of the impact");
  item((x, y) => { ctx.fillStyle = "#888"; ctx.beginPath(); ctx.moveTo(x + 12, y - 6); ctx.lineTo(x + 7, y + 4); ctx.lineTo(x + 17, y + 4); ctx.closePath(); ctx.fill(); }, "end of the first phase");
}

// ---- the map -----------------------------------------------------------------------------

function mapParameters() {
  const known = state.info.map_parameters[state.kind === "double-pendulum" ? "mechanism" : "body"];
  return known.filter((k) => k in state.values);
}

function fillAxisSelect(select, chosen) {
  select.textContent = "";
  for (const k of mapParameters()) {
    const o = document.createElement("option");
    o.value = k; o.textContent = k;
    select.appendChild(o);
  }
  select.value = chosen;
}

function setMapAxes(x, y) {
  fillAxisSelect($("map-x"), x);
  fillAxisSelect($("map-y"), y);
  $("map-x-min").value = AXIS_RANGES[x][0]; $("map-x-max").value = AXIS_RANGES[x][1];
  $("map-y-min").value = AXIS_RANGES[y][0]; $("map-y-max").value = AXIS_RANGES[y][1];
  if (state.kind === "ellipse") {
    for (const a of ["x", "y"]) if ($(`map-${a}`).value === "angle_deg") { $(`map-${a}-min`).value = -90; $(`map-${a}-max`).value = 90; }
  }
}

function mapRequest() {
  const n = Number($("map-n").value);
  return {
    scenario: request(), law: state.law,
    x: { name: $("map-x").value, min: Number($("map-x-min").value), max: Number($("map-x-max").value), count: n },
    y: { name: $("map-y").value, min: Number($("map-y-min").value), max: Number($("map-y-max").value), count: n },
  };
}

// The map's own key: the request without the two swept values (moving along them only moves
// the marker).
function mapKey(req) {
  const copy = JSON.parse(JSON.stringify(req));
  for (const a of [req.x.name, req.y.name]) {
    if (a in copy.scenario) delete copy.scenario[a];
    for (const part of ["body", "mechanism"]) if (copy.scenario[part]) delete copy.scenario[part][a];
    if (copy.scenario.mechanism) {
      const m = copy.scenario.mechanism, i = { angle1_deg: 0, angle2_deg: 1, rate1: 0, rate2: 1 }[a];
      if (i !== undefined) (a.startsWith("angle") ? m.angles_deg : m.rates)[i] = null;
    }
  }
  return JSON.stringify(copy);
}

// Recompute the map after the current event; a slow map (the double pendulum's) waits until
// the slider rests for 150 ms, so that the table keeps following the drag.
function scheduleMap(force) {
  if (force) state.mapKey = "";
  clearTimeout(state.mapTimer);
  const slow = state.map && state.map.ms > 40;
  state.mapTimer = setTimeout(computeMap, slow ? 150 : 0);
}

function computeMap() {
  const req = mapRequest();
  const key = mapKey(req);
  if (key === state.mapKey && state.map) {
    state.map.answer.marker = markerOf(req);
    drawMap();
    return;
  }
  const t = performance.now();
  const m = Impax.map(req);
  const ms = performance.now() - t;
  if (m.answer.error) {
    $("map-info").textContent = `map: ${m.answer.error}`;
    return;
  }
  m.ms = ms;
  state.map = m;
  state.mapKey = key;
  state.timings.push(ms);
  const canvas = $("map");
  canvas.dataset.ms = ms.toFixed(2);
  canvas.dataset.cells = String(m.answer.cells);
  canvas.dataset.gained = String(m.answer.counts.gained);
  drawMap();
}

function markerOf(req) {
  const get = (name) => {
    if (name === "friction" || name === "restitution") return req.scenario[name];
    if (req.scenario.body) return req.scenario.body[name];
    const m = req.scenario.mechanism;
    return { angle1_deg: m.angles_deg[0], angle2_deg: m.angles_deg[1], rate1: m.rates[0], rate2: m.rates[1] }[name];
  };
  return [get(req.x.name), get(req.y.name)];
}

function lossColour(t) {
  // Light to dark blue as the loss grows (t in [0, 1]).
  const a = [222, 235, 247], b = [8, 48, 107];
  return a.map((c, i) => Math.round(c + (b[i] - c) * Math.min(1, Math.max(0, t))));
}
function gainColour(t) {
  const a = [253, 208, 162], b = [165, 15, 21];
  return a.map((c, i) => Math.round(c + (b[i] - c) * Math.min(1, Math.max(0, t))));
}

function drawMap() {
  const m = state.map;
  if (!m) return;
  const a = m.answer;
  const { ctx, w, h } = context($("map"), 0.62);
  const nx = a.x.count, ny = a.y.count;
  const range = a.range || [0, 0];
  const lo = Math.min(range[0], -1e-12), hi = Math.max(range[1], 1e-12);
  // Cells → an image, row 0 (lowest y) at the bottom.
  const img = new ImageData(nx, ny);
  const mask = new ImageData(nx, ny);
  for (let j = 0; j < ny; j++) {
    for (let i = 0; i < nx; i++) {
      const k = j * nx + i, p = ((ny - 1 - j) * nx + i) * 4;
      const c = m.classes[k], v = m.values[k];
      let rgb;
      if (c === 3) rgb = [90, 90, 90];
      else if (c === 4) rgb = [238, 238, 238];
      else if (v > 0) { rgb = gainColour(v / hi); mask.data[p + 3] = 255; }
      else rgb = lossColour(v / lo);
      img.data.set([rgb[0], rgb[1], rgb[2], 255], p);
    }
  }
  const box = { x0: 70, y0: 10, w: w - 70 - 120, h: h - 10 - 60 };
  const cellCanvas = (data) => { const c = document.createElement("canvas"); c.width = nx; c.height = ny; c.getContext("2d").putImageData(data, 0, 0); return c; };
  ctx.imageSmoothingEnabled = false;
  ctx.drawImage(cellCanvas(img), box.x0, box.y0, box.w, box.h);
  // Hatch the gain cells: a hatch layer kept only where the mask is set.
  const layer = document.createElement("canvas");
  layer.width = Math.ceil(box.w); layer.height = Math.ceil(box.h);
  const lc = layer.getContext("2d");
  lc.fillStyle = hatch(lc, "rgba(60,0,0,0.55)", "rgba(0,0,0,0)");
  lc.fillRect(0, 0, layer.width, layer.height);
  lc.globalCompositeOperation = "destination-in";
  lc.imageSmoothingEnabled = false;
  lc.drawImage(cellCanvas(mask), 0, 0, layer.width, layer.height);
  ctx.drawImage(layer, box.x0, box.y0);
  const xr = [a.x.min, a.x.max], yr = [a.y.min, a.y.max];
  const { X, Y } = axes(ctx, box, xr, yr, AXIS_LABELS[a.x.name] || a.x.name, AXIS_LABELS[a.y.name] || a.y.name, false);
  ctx.save();
  ctx.beginPath(); ctx.rect(box.x0, box.y0, box.w, box.h); ctx.clip();
  // Paper A eq. 13's threshold (sphere, Whittaker).
  if (a.threshold) {
    for (const line of [...a.threshold.upper, ...a.threshold.lower]) {
      for (const [c, lw, d] of [["#fff", 4, []], ["#000", 1.8, [7, 4]]]) {
        ctx.strokeStyle = c; ctx.lineWidth = lw; ctx.setLineDash(d);
        ctx.beginPath();
        line.forEach(([x, y], k) => (k ? ctx.lineTo(X(x), Y(y)) : ctx.moveTo(X(x), Y(y))));
        ctx.stroke();
      }
    }
    ctx.setLineDash([]);
  }
  // The current point.
  const mk = a.marker;
  if (mk && mk[0] !== undefined) {
    const px = X(mk[0]), py = Y(mk[1]);
    for (const [c, lw] of [["#fff", 4], ["#000", 1.8]]) {
      ctx.strokeStyle = c; ctx.lineWidth = lw;
      ctx.beginPath(); ctx.arc(px, py, 7, 0, 2 * Math.PI);
      ctx.moveTo(px - 13, py); ctx.lineTo(px - 7, py); ctx.moveTo(px + 7, py); ctx.lineTo(px + 13, py);
      ctx.moveTo(px, py - 13); ctx.lineTo(px, py - 7); ctx.moveTo(px, py + 7); ctx.lineTo(px, py + 13);
      ctx.stroke();
    }
  }
  ctx.restore();
  drawColourBar(ctx, { x0: box.x0 + box.w + 18, y0: box.y0 + 16, w: 16, h: box.h - 70 }, lo, hi);
  const c = a.counts;
  const share = (100 * c.gained) / a.cells;
  $("map-info").innerHTML =
    `<b>${a.law}</b>: ${a.cells.toLocaleString("en")} impacts computed in <b id="map-ms">${m.ms.toFixed(1)} ms</b> (WebAssembly); ` +
    `energy gained in ${share.toFixed(1)} % of the cells (hatched)` +
    (c.breakdown ? `, breakdown in ${c.breakdown}` : "") + (c.invalid ? `, ${c.invalid} invalid (no impact)` : "") +
    (a.range ? `; ΔT/T0 from ${tick(a.range[0])} to ${tick(a.range[1])}` : "") +
    (a.threshold ? ". Dashed: paper A eq. 13's threshold γ*(α)." : ".") +
    " Circle: the sliders' point.";
}

function drawColourBar(ctx, box, lo, hi) {
  const { x0, y0, w, h } = box;
  const Y = (v) => y0 + h - ((v - lo) / (hi - lo)) * h;
  const steps = Math.ceil(h);
  for (let s = 0; s < steps; s++) {
    const v = lo + ((hi - lo) * (s + 0.5)) / steps;
    const rgb = v > 0 ? gainColour(v / hi) : lossColour(v / lo);
    ctx.fillStyle = `rgb(${rgb})`;
    ctx.fillRect(x0, y0 + h - (s + 1) * (h / steps), w, h / steps + 0.5);
  }
  if (hi > 0) {
    ctx.fillStyle = hatch(ctx, "rgba(60,0,0,0.55)", "rgba(0,0,0,0)");
    ctx.fillRect(x0, Y(hi), w, Y(0) - Y(hi));
  }
  ctx.strokeStyle = "#555"; ctx.lineWidth = 1; ctx.strokeRect(x0, y0, w, h);
  ctx.font = SMALL; ctx.fillStyle = "#222"; ctx.textAlign = "left"; ctx.textBaseline = "middle";
  for (const t of niceTicks(lo, hi, 6)) {
    ctx.beginPath(); ctx.moveTo(x0 + w, Y(t)); ctx.lineTo(x0 + w + 4, Y(t)); ctx.stroke();
    ctx.fillText(tick(t), x0 + w + 6, Y(t));
  }
  ctx.lineWidth = 2; ctx.strokeStyle = "#000";
  ctx.beginPath(); ctx.moveTo(x0 - 3, Y(0)); ctx.lineTo(x0 + w + 3, Y(0)); ctx.stroke();
  ctx.textAlign = "left"; ctx.textBaseline = "bottom"; ctx.font = SMALL;
  ctx.fillText("ΔT/T0", x0 - 4, y0 - 3);
  ctx.textBaseline = "top";
  const legend = [["rgb(90,90,90)", "breakdown"], ["rgb(238,238,238)", "no impact"]];
  legend.forEach(([c, t], i) => {
    const y = y0 + h + 10 + i * 18;
    ctx.fillStyle = c; ctx.fillRect(x0, y, w, 12); ctx.strokeStyle = "#777"; ctx.lineWidth = 1; ctx.strokeRect(x0, y, w, 12);
    ctx.fillStyle = "#222"; ctx.fillText(t, x0 + w + 6, y);
  });
}

function mapClick(ev) {
  const a = state.map && state.map.answer;
  if (!a) return;
  const rect = $("map").getBoundingClientRect();
  const w = rect.width, h = Math.round(w * 0.62);
  const box = { x0: 70, y0: 10, w: w - 70 - 120, h: h - 10 - 60 };
  const fx = (ev.clientX - rect.left - box.x0) / box.w, fy = 1 - (ev.clientY - rect.top - box.y0) / box.h;
  if (fx < 0 || fx > 1 || fy < 0 || fy > 1) return;
  setParameter(a.x.name, a.x.min + fx * (a.x.max - a.x.min));
  setParameter(a.y.name, a.y.min + fy * (a.y.max - a.y.min));
  update();
}

// ---- the animation -----------------------------------------------------------------------

const anim = { start: 0, raf: 0, playing: true };

function startAnimation() {
  const r = state.compare;
  if (!r) return;
  $("anim-law").textContent = r.animation.after[state.law] ? `law: ${state.law}` : `${state.law}: no result (breakdown)`;
  anim.start = performance.now();
  if (!anim.raf && anim.playing) anim.raf = requestAnimationFrame(frame);
  if (!anim.playing) drawAnimation(2.9);
}

function frame(now) {
  anim.raf = 0;
  if (!anim.playing) return;
  const t = (Math.max(0, now - anim.start) / 1000) % 3.2;
  drawAnimation(t);
  if (anim.playing) anim.raf = requestAnimationFrame(frame);
}

// Extent of one body at a pose.
function bodyPoints(shape, pose) {
  const [x, y, th] = pose;
  if (shape.kind === "circle") return [[x - shape.radius, y - shape.radius], [x + shape.radius, y + shape.radius]];
  if (shape.kind === "segment") {
    const d = shape.direction + th, c = Math.cos(d) * shape.half_length, s = Math.sin(d) * shape.half_length;
    return [[x - c, y - s], [x + c, y + s]];
  }
  const r = shape.kind === "ellipse" ? Math.max(shape.a, shape.b) : Math.max(Math.hypot(...shape.contact), shape.gyration);
  return [[x - r, y - r], [x + r, y + r]];
}

function drawBody(ctx, shape, pose, X, Y, s, colour) {
  const [x, y, th] = pose;
  ctx.strokeStyle = colour; ctx.fillStyle = colour; ctx.lineWidth = 2.5;
  if (shape.kind === "circle") {
    ctx.fillStyle = "rgba(31,95,153,0.12)";
    ctx.beginPath(); ctx.arc(X(x), Y(y), shape.radius * s, 0, 2 * Math.PI); ctx.fill(); ctx.stroke();
    // A radius that turns with the body (it points to the contact at the impact).
    const d = -Math.PI / 2 + th;
    ctx.beginPath(); ctx.moveTo(X(x), Y(y)); ctx.lineTo(X(x + shape.radius * Math.cos(d)), Y(y + shape.radius * Math.sin(d))); ctx.stroke();
  } else if (shape.kind === "segment") {
    const d = shape.direction + th, c = Math.cos(d) * shape.half_length, sn = Math.sin(d) * shape.half_length;
    ctx.lineWidth = 6; ctx.lineCap = "round";
    ctx.beginPath(); ctx.moveTo(X(x - c), Y(y - sn)); ctx.lineTo(X(x + c), Y(y + sn)); ctx.stroke();
    ctx.lineCap = "butt";
  } else if (shape.kind === "ellipse") {
    ctx.fillStyle = "rgba(31,95,153,0.12)";
    ctx.beginPath(); ctx.ellipse(X(x), Y(y), shape.a * s, shape.b * s, -(shape.direction + th), 0, 2 * Math.PI); ctx.fill(); ctx.stroke();
  } else {
    const [ct, cn] = shape.contact, c = Math.cos(th), sn = Math.sin(th);
    ctx.setLineDash([5, 4]); ctx.lineWidth = 1.5;
    ctx.beginPath(); ctx.arc(X(x), Y(y), shape.gyration * s, 0, 2 * Math.PI); ctx.stroke();
    ctx.setLineDash([]); ctx.lineWidth = 3;
    ctx.beginPath(); ctx.moveTo(X(x), Y(y)); ctx.lineTo(X(x + c * ct - sn * cn), Y(y + sn * ct + c * cn)); ctx.stroke();
  }
  ctx.fillStyle = "#000";
  ctx.beginPath(); ctx.arc(X(x), Y(y), 3, 0, 2 * Math.PI); ctx.fill();
}

function drawAnimation(t) {
  const r = state.compare;
  if (!r) return;
  const { ctx, w, h } = context($("anim"), 0.62);
  const A = r.animation;
  const after = A.after[state.law];
  const frames = [...A.before, ...(after || [])];
  let xmin = Infinity, xmax = -Infinity, ymin = 0, ymax = -Infinity;
  for (const f of frames) f.forEach((pose, b) => { for (const [x, y] of bodyPoints(A.shapes[b], pose)) { xmin = Math.min(xmin, x); xmax = Math.max(xmax, x); ymin = Math.min(ymin, y); ymax = Math.max(ymax, y); } });
  for (const [x, y] of A.pins) { xmin = Math.min(xmin, x); xmax = Math.max(xmax, x); ymax = Math.max(ymax, y); }
  const pad = 40, bottom = 46;
  const s = Math.min((w - 2 * pad) / Math.max(xmax - xmin, 1e-9), (h - pad - bottom) / Math.max(ymax - ymin, 1e-9));
  const cx = (xmin + xmax) / 2;
  const X = (x) => w / 2 + (x - cx) * s;
  const Y = (y) => h - bottom - (y - ymin) * s;
  // The floor.
  ctx.strokeStyle = "#333"; ctx.lineWidth = 2;
  ctx.beginPath(); ctx.moveTo(10, Y(0)); ctx.lineTo(w - 10, Y(0)); ctx.stroke();
  ctx.lineWidth = 1;
  for (let x = 14; x < w - 10; x += 12) { ctx.beginPath(); ctx.moveTo(x, Y(0) + 1); ctx.lineTo(x - 8, Y(0) + 9); ctx.stroke(); }
  // Timeline: approach 1.3 s, impact 0.3 s, rebound 1.3 s, rest.
  const n = A.before.length - 1;
  let pose, label;
  if (t < 1.3) { pose = A.before[Math.min(n, Math.round((t / 1.3) * n))]; label = "before the impact"; }
  else if (t < 1.6 || !after) { pose = A.before[n]; label = after ? "impact" : "no result: the law breaks down"; }
  else { const m = after.length - 1; pose = after[Math.min(m, Math.round(((t - 1.6) / 1.3) * m))]; label = `after the impact: ${state.law}`; }
  // Trails of the centres.
  ctx.fillStyle = "#bbb";
  for (const f of A.before) for (const [x, y] of f) { ctx.beginPath(); ctx.arc(X(x), Y(y), 1.5, 0, 2 * Math.PI); ctx.fill(); }
  if (after) { ctx.fillStyle = styleOf(state.law).colour; for (const f of after) for (const [x, y] of f) { ctx.beginPath(); ctx.arc(X(x), Y(y), 1.5, 0, 2 * Math.PI); ctx.fill(); } }
  for (const [x, y] of A.pins) {
    ctx.fillStyle = "#333";
    ctx.beginPath(); ctx.moveTo(X(x), Y(y)); ctx.lineTo(X(x) - 9, Y(y) + 12); ctx.lineTo(X(x) + 9, Y(y) + 12); ctx.closePath(); ctx.fill();
  }
  pose.forEach((p, b) => drawBody(ctx, A.shapes[b], p, X, Y, s, "#1f5f99"));
  ctx.fillStyle = "#c62828";
  ctx.beginPath(); ctx.arc(X(0), Y(0), 4, 0, 2 * Math.PI); ctx.fill();
  ctx.font = FONT; ctx.fillStyle = "#222"; ctx.textAlign = "left"; ctx.textBaseline = "top";
  ctx.fillText(label, 12, 8);
  const res = r.results.find((x) => x.law === state.law);
  if (res && res.energy) {
    ctx.fillStyle = res.energy_change_ratio > 0 ? GAIN : "#222";
    ctx.fillText(`ΔT/T0 = ${signed(res.energy_change_ratio, 4)}${res.energy_change_ratio > 0 ? " (energy gained)" : ""}`, 12, 26);
  }
  ctx.font = SMALL; ctx.fillStyle = "#555"; ctx.textBaseline = "bottom";
  ctx.fillText("grey dots: centre before; coloured dots: after; red dot: contact point", 12, h - 6);
}

// ---- wiring ------------------------------------------------------------------------------

function update() {
  const r = Impax.compare(request());
  const err = $("error");
  if (r.error) {
    err.hidden = false;
    err.textContent = r.error;
    return;
  }
  err.hidden = true;
  state.compare = r;
  $("scenario").textContent = r.scenario;
  const p = r.problem, f = (x) => Number(x.toPrecision(6));
  $("problem").textContent = `W = [[${f(p.w[0][0])}, ${f(p.w[0][1])}], [${f(p.w[1][0])}, ${f(p.w[1][1])}]], v⁻ = (${f(p.v.t)}, ${f(p.v.n)})` +
    thresholdText(r.threshold);
  renderTable(r);
  drawBars();
  drawRouth();
  scheduleMap(false);
  startAnimation();
  document.body.dataset.ready = "1";
}

// Paper A eq. 13 for the sphere: where Whittaker's rule gains energy along γ.
function thresholdText(t) {
  if (!t) return "";
  const g = (x) => x.toFixed(6).replace("-", "−");
  if (t.upper === null && t.lower === null) return "; Whittaker's rule gains energy at no γ here (paper A eq. 13)";
  const edge = `−sin α = ${g(t.edge)}`;
  const range = t.upper !== null && t.lower !== null ? `γ*₋ = ${g(t.lower)} < γ < γ*₊ = ${g(t.upper)} (not at γ = ${edge}: no slip)`
    : t.upper !== null ? `${edge} < γ < γ*₊ = ${g(t.upper)}` : `γ*₋ = ${g(t.lower)} < γ < ${edge}`;
  return `; Whittaker's rule gains energy for ${range} (paper A eq. 13)`;
}

function setKind(kind) {
  state.kind = kind;
  state.values = {};
  state.mapKey = "";
  state.map = null;
  buildSliders();
  const laws = kind === "double-pendulum" ? state.info.mechanism_laws : state.info.laws;
  const sel = $("law");
  sel.textContent = "";
  for (const l of laws) { const o = document.createElement("option"); o.value = l; o.textContent = l; sel.appendChild(o); }
  if (!laws.includes(state.law)) state.law = "whittaker";
  sel.value = state.law;
  if (kind === "double-pendulum") setMapAxes("friction", "restitution");
  else setMapAxes("spin_ratio", "alpha_deg");
  $("map-n").value = kind === "double-pendulum" ? "100" : "200";
  update();
}

async function main() {
  try {
    await Impax.load("impax_wasm.wasm");
  } catch (e) {
    $("error").hidden = false;
    $("error").textContent = `could not load the impax core: ${e.message}`;
    return;
  }
  state.info = Impax.info();
  // Shapes of the core the page lists no option for yet (a shape added to the core's table).
  const select = $("shape"), listed = [...select.options].map((o) => o.value);
  for (const name of state.info.shapes.filter((n) => !listed.includes(n))) {
    const o = document.createElement("option");
    o.value = name; o.textContent = name;
    select.insertBefore(o, select.querySelector('option[value="double-pendulum"]'));
  }
  $("shape").addEventListener("change", () => setKind($("shape").value));
  $("reset").addEventListener("click", () => { $("shape").value = "sphere"; state.law = "whittaker"; setKind("sphere"); });
  $("law").addEventListener("change", () => selectLaw($("law").value));
  for (const id of ["map-x", "map-y"]) {
    $(id).addEventListener("change", () => {
      const a = id.slice(4), name = $(id).value;
      $(`map-${a}-min`).value = AXIS_RANGES[name][0];
      $(`map-${a}-max`).value = AXIS_RANGES[name][1];
      scheduleMap(true);
    });
  }
  for (const id of ["map-x-min", "map-x-max", "map-y-min", "map-y-max", "map-n"]) $(id).addEventListener("change", () => scheduleMap(true));
  $("map").addEventListener("click", mapClick);
  $("play").addEventListener("click", () => {
    anim.playing = !anim.playing;
    $("play").textContent = anim.playing ? "pause" : "play";
    startAnimation();
  });
  let resize = 0;
  window.addEventListener("resize", () => { clearTimeout(resize); resize = setTimeout(() => { drawBars(); drawRouth(); drawMap(); }, 100); });
  setKind("sphere");
}

Views.add({
  name: "one", tab: "tab-one", panel: "one-contact", hash: "",
  // The canvases were sized while hidden: redraw them at their width.
  shown: () => window.dispatchEvent(new Event("resize")),
});
main();
