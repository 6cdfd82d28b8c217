// The explorer's view of conserved quantities (paper B): the built-in ring-pendulum (or the
// cart-pendulum, the contrast) moving freely → the impax core (WebAssembly, impax.js:
// `impax_conserved`, the tracker of `impax conserved`) → every quantity it reports over time
// with its verdict, as a table and small time plots, and the motion itself.
// Every number and every pose comes from the core; this file only lays out and draws. It uses
// explorer.js's helpers ($, context, tick, niceTicks, FONT, SMALL, GAIN), loaded before it.
"use strict";

(() => {
  // Slider ranges; the starting values are the core's defaults (info.conserved_systems).
  const COMMON = [
    { key: "bob", label: "bob mass m", unit: "point mass", min: 0.1, max: 5, step: 0.05 },
    { key: "length", label: "arm l", unit: "m", min: 0.1, max: 3, step: 0.05 },
    { key: "phi", label: "φ₀", unit: "° from the downward vertical", min: -179, max: 179, step: 1 },
    { key: "xdot", label: "ẋ₀", unit: "m/s, the carrier", min: -3, max: 3, step: 0.05 },
    { key: "phidot", label: "φ̇₀", unit: "rad/s", min: -8, max: 8, step: 0.05 },
    { key: "duration", label: "duration", unit: "s of motion", min: 1, max: 30, step: 0.5 },
  ];
  const SLIDERS = {
    "ring-pendulum": [
      { key: "carrier", label: "ring mass M", unit: "thin ring, I = M R²", min: 0.1, max: 5, step: 0.05 },
      { key: "radius", label: "ring radius R", unit: "m", min: 0.1, max: 3, step: 0.05 },
      ...COMMON,
    ],
    "cart-pendulum": [
      { key: "carrier", label: "cart mass M", unit: "slides freely", min: 0.1, max: 5, step: 0.05 },
      ...COMMON,
    ],
  };
  const DURATION = 10;
  const VERDICT_CLASS = { conserved: "kept", "NOT conserved": "lost" };
  const BODY = "#1f5f99";

  const cons = { system: "ring-pendulum", values: {}, info: null, answer: null, updates: 0, started: false, plots: [] };
  window.explorerConserved = cons;

  // ---- parameters ------------------------------------------------------------------------

  function defaults(name) {
    const d = cons.info.conserved_systems[name];
    return {
      carrier: d.masses[0], bob: d.masses[1], length: d.lengths[0], radius: d.radius,
      phi: d.angles_deg[0], xdot: d.rates[0], phidot: d.rates[1], duration: DURATION,
    };
  }

  function request() {
    const v = cons.values;
    const r = {
      mechanism: cons.system, masses: [v.carrier, v.bob], lengths: [v.length],
      angles_deg: [v.phi], rates: [v.xdot, v.phidot], duration: v.duration,
    };
    if (cons.system === "ring-pendulum") r.radius = v.radius;
    return r;
  }

  function buildSliders() {
    const box = $("cons-sliders");
    box.textContent = "";
    for (const p of SLIDERS[cons.system]) {
      const id = `c-${p.key}`;
      const wrap = document.createElement("div");
      wrap.className = "slider";
      wrap.innerHTML = `<div class="head"><label for="${id}">${p.label} <span class="unit">${p.unit}</span></label></div>`;
      const typed = document.createElement("input");
      Object.assign(typed, { type: "number", id: `${id}-value`, step: "any", className: "typed" });
      typed.setAttribute("aria-label", `${p.label}, exact value`);
      typed.addEventListener("change", () => {
        const x = Number(typed.value);
        if (typed.value.trim() === "" || !Number.isFinite(x)) { typed.value = String(cons.values[p.key]); return; }
        cons.values[p.key] = x;
        $(id).value = x;
        update();
      });
      wrap.firstChild.appendChild(typed);
      const input = document.createElement("input");
      Object.assign(input, { type: "range", id, min: p.min, max: p.max, step: p.step });
      input.value = cons.values[p.key];
      input.addEventListener("input", () => {
        cons.values[p.key] = Number(input.value);
        typed.value = input.value;
        update();
      });
      wrap.appendChild(input);
      box.appendChild(wrap);
      typed.value = String(cons.values[p.key]);
    }
  }

  function setSystem(name) {
    cons.system = name;
    cons.values = defaults(name);
    buildSliders();
    update();
  }

  // ---- the table -------------------------------------------------------------------------

  const fmt = (x) => (x === 0 ? "0" : Math.abs(x) >= 1e5 || Math.abs(x) < 1e-3 ? x.toExponential(5) : x.toPrecision(6)).replace("-", "−");
  const sci = (x) => (x === 0 ? "0" : x.toExponential(1).replace("-", "−"));

  function renderTable(a) {
    const body = $("cons-table").tBodies[0];
    body.textContent = "";
    for (const q of a.quantities) {
      const tr = document.createElement("tr");
      tr.dataset.name = q.name;
      tr.className = VERDICT_CLASS[q.verdict] || "lost";
      tr.innerHTML = `<th class="text">${q.name}</th><td class="text">${q.description}</td>` +
        `<td class="num" data-col="initial">${fmt(q.initial)}</td><td class="num" data-col="final">${fmt(q.final)}</td>` +
        `<td class="num" data-col="relative">${sci(q.relative_deviation)}</td>` +
        `<td class="text verdict" data-verdict="${q.conserved ? "conserved" : "not-conserved"}">${q.verdict}</td>`;
      body.appendChild(tr);
    }
    const steps = `${a.steps.accepted} steps (${a.steps.rejected} rejected)`;
    $("cons-notes").textContent = `Dormand–Prince 5(4) at relative tolerance ${sci(a.tolerances.relative)}, ${steps}, ${a.samples} samples over ${a.duration} s. ` +
      `Relative: the largest deviation from the initial value over the magnitude of the quantity's terms; conserved when at most ${a.tolerance}. ` +
      `Cyclic coordinates (∂L/∂q ≡ 0): ${a.cyclic.length ? a.cyclic.join(", ") : "none"}.`;
  }

  // ---- the time plots: one per quantity, drawn once per answer, the cursor on top --------

  function buildPlots(a) {
    const box = $("cons-plots");
    const want = a.quantities.map((q) => q.name).join("|");
    if (box.dataset.names !== want) {
      box.textContent = "";
      for (const q of a.quantities) {
        const fig = document.createElement("figure");
        fig.className = "plot";
        fig.dataset.name = q.name;
        fig.innerHTML = `<canvas aria-label="${q.name} over time"></canvas><figcaption></figcaption>`;
        box.appendChild(fig);
      }
      box.dataset.names = want;
    }
    cons.plots = [...box.children].map((fig, i) => {
      const q = a.quantities[i];
      fig.className = `plot ${VERDICT_CLASS[q.verdict] || "lost"}`;
      fig.querySelector("figcaption").innerHTML = `<b>${q.name}</b> <span class="verdict">${q.verdict}</span><br>${q.description}; largest change ${sci(q.largest_deviation)} (relative ${sci(q.relative_deviation)})`;
      return { fig, image: renderPlot(fig.querySelector("canvas"), a, q) };
    });
  }

  // The y range: the values' span, or (a quantity that does not move on the scale of its
  // terms) 2 % of its magnitude about its mean, so that a conserved quantity draws flat.
  function yRange(q) {
    let lo = Math.min(...q.values), hi = Math.max(...q.values);
    const least = 0.02 * Math.max(q.magnitude, Math.abs(q.initial), 1e-300);
    if (hi - lo < least) { const mid = (lo + hi) / 2; lo = mid - least / 2; hi = mid + least / 2; }
    const pad = 0.08 * (hi - lo);
    return [lo - pad, hi + pad];
  }

  function plotBox(w, h) {
    return { x0: 52, y0: 8, w: w - 60, h: h - 8 - 22 };
  }

  function renderPlot(canvas, a, q) {
    const { ctx, w, h } = context(canvas, 0.42);
    const box = plotBox(w, h);
    const [lo, hi] = yRange(q);
    const t1 = a.times[a.times.length - 1];
    const X = (t) => box.x0 + (t / t1) * box.w;
    const Y = (y) => box.y0 + box.h - ((y - lo) / (hi - lo)) * box.h;
    ctx.font = SMALL; ctx.fillStyle = "#333"; ctx.strokeStyle = "#e4e4e4"; ctx.lineWidth = 1;
    ctx.textAlign = "right"; ctx.textBaseline = "middle";
    for (const t of niceTicks(lo, hi, 3)) {
      ctx.beginPath(); ctx.moveTo(box.x0, Y(t)); ctx.lineTo(box.x0 + box.w, Y(t)); ctx.stroke();
      ctx.fillText(tick(t), box.x0 - 4, Y(t));
    }
    ctx.textAlign = "center"; ctx.textBaseline = "top";
    // The axis' name at its right end, where no tick label is written.
    for (const t of niceTicks(0, t1, 5)) if (X(t) < box.x0 + box.w - 30) ctx.fillText(tick(t), X(t), box.y0 + box.h + 4);
    ctx.textAlign = "right";
    ctx.fillText("t (s)", box.x0 + box.w, box.y0 + box.h + 4);
    ctx.strokeStyle = "#888"; ctx.strokeRect(box.x0, box.y0, box.w, box.h);
    // The initial value, dashed; the quantity, in the verdict's colour.
    ctx.setLineDash([4, 3]); ctx.strokeStyle = "#999";
    ctx.beginPath(); ctx.moveTo(box.x0, Y(q.initial)); ctx.lineTo(box.x0 + box.w, Y(q.initial)); ctx.stroke();
    ctx.setLineDash([]);
    ctx.strokeStyle = q.conserved ? BODY : GAIN; ctx.lineWidth = 2;
    ctx.beginPath();
    q.values.forEach((v, k) => (k ? ctx.lineTo(X(a.times[k]), Y(v)) : ctx.moveTo(X(a.times[k]), Y(v))));
    ctx.stroke();
    // Keep the picture for the cursor's redraws.
    const copy = document.createElement("canvas");
    copy.width = canvas.width; copy.height = canvas.height;
    copy.getContext("2d").drawImage(canvas, 0, 0);
    return { copy, box, t1 };
  }

  function drawCursors(t) {
    for (const { fig, image } of cons.plots) {
      const canvas = fig.querySelector("canvas");
      const ctx = canvas.getContext("2d");
      const dpr = window.devicePixelRatio || 1;
      ctx.setTransform(1, 0, 0, 1, 0, 0);
      ctx.drawImage(image.copy, 0, 0);
      ctx.setTransform(dpr, 0, 0, dpr, 0, 0);
      const x = image.box.x0 + (t / image.t1) * image.box.w;
      ctx.strokeStyle = "#000"; ctx.lineWidth = 1;
      ctx.beginPath(); ctx.moveTo(x, image.box.y0); ctx.lineTo(x, image.box.y0 + image.box.h); ctx.stroke();
    }
  }

  // ---- the motion ------------------------------------------------------------------------

  const anim = { start: 0, raf: 0, playing: true, t: 0 };

  // The pose of every body at time t (samples interpolated).
  function posesAt(a, t) {
    const n = a.times.length - 1;
    const f = Math.min(1, Math.max(0, t / a.times[n])) * n;
    const k = Math.min(n - 1, Math.floor(f)), w = f - k;
    return a.poses[k].map((p, i) => p.map((x, j) => x + w * (a.poses[k + 1][i][j] - x)));
  }

  function drawMotion(t) {
    const a = cons.answer;
    if (!a || !a.scene) return;
    const { ctx, w, h } = context($("cons-anim"), 0.36);
    const sc = a.scene, ring = sc.bodies[0].shape === "ring";
    const r = ring ? sc.bodies[0].radius : 0.12 * sc.length;
    const size = r + sc.length;
    const poses = posesAt(a, t);
    const [cx] = poses[0];
    // The camera follows the carrier; the floor's marks stay in the world.
    const top = (ring ? r : 0) + sc.length, bottom = Math.min(-0.25 * size, (ring ? r : 0) - sc.length);
    const s = Math.min(w / (5 * size), (h - 24) / (top - bottom + 0.3 * size));
    const X = (x) => w / 2 + (x - cx) * s;
    const Y = (y) => h - 22 - (y - bottom) * s;
    ctx.strokeStyle = "#333"; ctx.lineWidth = 2;
    const floorY = ring ? sc.floor : -0.17 * sc.length;
    ctx.beginPath(); ctx.moveTo(0, Y(floorY)); ctx.lineTo(w, Y(floorY)); ctx.stroke();
    const step = niceTicks(0, w / s, 8)[1] || 1;
    ctx.font = SMALL; ctx.fillStyle = "#555"; ctx.textAlign = "center"; ctx.textBaseline = "top"; ctx.lineWidth = 1;
    for (let m = Math.floor((cx - w / s) / step) * step; m <= cx + w / s; m += step) {
      ctx.beginPath(); ctx.moveTo(X(m), Y(floorY)); ctx.lineTo(X(m), Y(floorY) + 6); ctx.stroke();
      ctx.fillText(`${tick(m)} m`, X(m), Y(floorY) + 7);
    }
    // The bob's path over the last second.
    ctx.fillStyle = "rgba(198,40,40,0.35)";
    for (let k = 0; k < 60; k++) {
      const tk = t - (k * 1) / 60;
      if (tk < 0) break;
      const [bx, by] = posesAt(a, tk)[1];
      ctx.beginPath(); ctx.arc(X(bx), Y(by), 1.6, 0, 2 * Math.PI); ctx.fill();
    }
    const [x0, y0, th0] = poses[0], [bx, by] = poses[1];
    ctx.strokeStyle = BODY; ctx.lineWidth = 3;
    if (ring) {
      ctx.beginPath(); ctx.arc(X(x0), Y(y0), r * s, 0, 2 * Math.PI); ctx.stroke();
      // Three spokes turning with the ring (its angle −x/R: rolling without slip).
      ctx.lineWidth = 1.5;
      for (let k = 0; k < 3; k++) {
        const ang = th0 + (2 * Math.PI * k) / 3;
        ctx.beginPath(); ctx.moveTo(X(x0), Y(y0)); ctx.lineTo(X(x0 + r * Math.cos(ang)), Y(y0 + r * Math.sin(ang))); ctx.stroke();
      }
    } else {
      const half = 0.35 * sc.length, tall = 0.12 * sc.length;
      ctx.fillStyle = "rgba(31,95,153,0.15)";
      ctx.fillRect(X(x0 - half), Y(y0 + tall), 2 * half * s, 2 * tall * s);
      ctx.strokeRect(X(x0 - half), Y(y0 + tall), 2 * half * s, 2 * tall * s);
    }
    ctx.strokeStyle = "#333"; ctx.lineWidth = 2;
    ctx.beginPath(); ctx.moveTo(X(x0), Y(y0)); ctx.lineTo(X(bx), Y(by)); ctx.stroke();
    ctx.fillStyle = "#c62828";
    ctx.beginPath(); ctx.arc(X(bx), Y(by), Math.max(5, 0.07 * size * s), 0, 2 * Math.PI); ctx.fill();
    ctx.fillStyle = "#000";
    ctx.beginPath(); ctx.arc(X(x0), Y(y0), 3, 0, 2 * Math.PI); ctx.fill();
    ctx.font = FONT; ctx.fillStyle = "#222"; ctx.textAlign = "left"; ctx.textBaseline = "top";
    ctx.fillText(`t = ${t.toFixed(2)} s`, 8, 6);
  }

  function draw(t) {
    const a = cons.answer;
    if (!a) return;
    anim.t = t;
    $("cons-clock").value = t / a.duration;
    drawMotion(t);
    drawCursors(t);
  }

  function frame(now) {
    anim.raf = 0;
    if (!anim.playing || $("conserved").hidden || !cons.answer) return;
    draw(((now - anim.start) / 1000) % cons.answer.duration);
    anim.raf = requestAnimationFrame(frame);
  }

  function startAnimation() {
    if (!anim.playing || $("conserved").hidden) { draw(anim.t); return; }
    anim.start = performance.now() - anim.t * 1000;
    if (!anim.raf) anim.raf = requestAnimationFrame(frame);
  }

  function play(on) {
    anim.playing = on;
    $("cons-play").textContent = on ? "pause" : "play";
    startAnimation();
  }

  // ---- wiring ----------------------------------------------------------------------------

  function update() {
    const a = Impax.conserved(request());
    const err = $("cons-error");
    cons.updates += 1;
    $("conserved").dataset.updates = String(cons.updates);
    if (a.error) {
      err.hidden = false;
      err.textContent = a.error;
      $("cons-results").classList.add("stale");
      return;
    }
    err.hidden = true;
    $("cons-results").classList.remove("stale");
    cons.answer = a;
    anim.t = Math.min(anim.t, a.duration);
    $("cons-scenario").textContent = a.scenario;
    renderTable(a);
    buildPlots(a);
    startAnimation();
    $("conserved").dataset.ready = "1";
  }

  async function start() {
    if (cons.started) { if (cons.answer) { buildPlots(cons.answer); startAnimation(); } return; }
    cons.started = true;
    try {
      await Impax.load("impax_wasm.wasm");
    } catch (e) {
      $("cons-error").hidden = false;
      $("cons-error").textContent = `could not load the impax core: ${e.message}`;
      return;
    }
    cons.info = Impax.info();
    $("cons-system").value = cons.system;
    $("cons-system").addEventListener("change", () => setSystem($("cons-system").value));
    $("cons-reset").addEventListener("click", () => setSystem(cons.system));
    $("cons-play").addEventListener("click", () => play(!anim.playing));
    $("cons-clock").addEventListener("input", () => {
      anim.t = Number($("cons-clock").value) * cons.answer.duration;
      play(false);
    });
    let resize = 0;
    window.addEventListener("resize", () => {
      clearTimeout(resize);
      resize = setTimeout(() => { if (cons.answer && !$("conserved").hidden) { buildPlots(cons.answer); draw(anim.t); } }, 100);
    });
    setSystem(cons.system);
  }

  Views.add({ name: "conserved", tab: "tab-conserved", panel: "conserved", hash: "#conserved", shown: start });
})();
