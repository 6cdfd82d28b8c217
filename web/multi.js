// The explorer's view with several contacts: a built-in system struck at several contacts at
// once (the rod landing flat, Newton's cradle, the rocking block, ball–ball–wall) → the impax
// core (WebAssembly, impax.js: `impax_multi`) → every multi-contact law side by side in a
// table and in one animation per law of the bodies after the impact.
// Every number and every pose comes from the core; this file only lays out and draws. It uses
// explorer.js's helpers ($, signed, context, FONT, SMALL, GAIN), loaded before it.
"use strict";

(() => {
  // ---- parameters ------------------------------------------------------------------------

  // Slider ranges per system; the starting values are the core's defaults (info.multi_systems)
  // except those in START.
  const COEFFICIENTS = [
    { key: "restitution", label: "restitution e", unit: "every contact", min: 0, max: 1, step: 0.01 },
    { key: "friction", label: "friction μ", unit: "every contact", min: 0, max: 1.5, step: 0.005 },
  ];
  const SLIDERS = {
    "rod-flat": [
      { key: "vy", label: "v_y, centre", unit: "before (down < 0)", min: -5, max: 1, step: 0.05 },
      { key: "omega", label: "ω", unit: "rad/s before", min: -6, max: 6, step: 0.05 },
      ...COEFFICIENTS,
      { key: "vx", label: "v_x, centre", unit: "before", min: -2, max: 2, step: 0.05 },
      { key: "length", label: "length l", unit: "", min: 0.2, max: 3, step: 0.05 },
    ],
    cradle: [
      { key: "balls", label: "number of balls", unit: "touching", min: 2, max: 8, step: 1 },
      ...COEFFICIENTS,
      { key: "v0", label: "v₀, first ball", unit: "towards the others", min: 0.1, max: 3, step: 0.05 },
    ],
    "rocking-block": [
      { key: "omega", label: "ω about corner A", unit: "rad/s, < 0: B comes down", min: -5, max: -0.05, step: 0.05 },
      ...COEFFICIENTS,
      { key: "half_width", label: "half-width b", unit: "", min: 0.05, max: 1, step: 0.01 },
      { key: "half_height", label: "half-height h", unit: "", min: 0.1, max: 1.5, step: 0.01 },
    ],
    "ball-ball-wall": [
      { key: "angle_deg", label: "line of centres", unit: "° from the wall's normal", min: -80, max: 80, step: 0.5 },
      ...COEFFICIENTS,
      { key: "v0", label: "v₀, ball 2", unit: "towards the wall", min: 0.1, max: 3, step: 0.05 },
    ],
  };
  // A landing at 3 m/s with some spin: the rebound and the laws' differences show in the picture.
  const START = { "rod-flat": { vy: -3, omega: 2 } };

  const STYLE = {
    lcp: { colour: "#7f7f7f", dash: [1, 4] },
    sequential: { colour: "#1f77b4", dash: [8, 4] },
    lzb: { colour: "#2ca02c", dash: [] },
  };
  const BODY = "#1f5f99";

  // Screen timeline of the animation: the impact held, the motion after, the end held.
  const HOLD = 0.8, PLAY = 2.0, REST = 0.6;
  // The arrows at the impact: the distance a centre covers in this share of the window.
  const ARROW = 0.4;

  const mstate = { system: "cradle", values: {}, answer: null, info: null, updates: 0 };
  window.explorerMulti = mstate;

  function sliderId(key) { return `m-${key}`; }

  function buildSliders() {
    const box = $("multi-sliders");
    box.textContent = "";
    for (const p of SLIDERS[mstate.system]) {
      const wrap = document.createElement("div");
      wrap.className = "slider";
      const id = sliderId(p.key);
      wrap.innerHTML = `<div class="head"><label for="${id}">${p.label} <span class="unit">${p.unit}</span></label></div>`;
      const typed = document.createElement("input");
      Object.assign(typed, { type: "number", id: `${id}-value`, step: "any", className: "typed" });
      typed.setAttribute("aria-label", `${p.label}, exact value`);
      typed.addEventListener("change", () => {
        const x = Number(typed.value);
        if (typed.value.trim() === "" || !Number.isFinite(x)) { typed.value = String(mstate.values[p.key]); return; }
        mstate.values[p.key] = x;
        $(id).value = x;
        update();
      });
      wrap.firstChild.appendChild(typed);
      const input = document.createElement("input");
      Object.assign(input, { type: "range", id, min: p.min, max: p.max, step: p.step });
      input.value = mstate.values[p.key];
      input.addEventListener("input", () => {
        mstate.values[p.key] = Number(input.value);
        typed.value = String(mstate.values[p.key]);
        update();
      });
      wrap.appendChild(input);
      box.appendChild(wrap);
      typed.value = String(mstate.values[p.key]);
    }
  }

  function setSystem(name) {
    mstate.system = name;
    const d = mstate.info.multi_systems[name];
    mstate.values = { ...d.parameters, friction: d.friction, restitution: d.restitution, ...(START[name] || {}) };
    buildSliders();
    update();
  }

  function request() {
    const r = { system: mstate.system };
    for (const p of SLIDERS[mstate.system]) r[p.key] = mstate.values[p.key];
    return r;
  }

  // ---- the table: one column per law -----------------------------------------------------

  function verdictText(verdict) {
    switch (verdict) {
      case "energy-gained": return "ENERGY GAINED";
      case "inconsistent-assumption": return "inconsistent assumption";
      case "breakdown": return "BREAKDOWN";
      case "omitted": return "not computed";
      default: return "consistent";
    }
  }

  function swatch(law) {
    const st = STYLE[law] || { colour: "#444", dash: [2, 2] };
    return `<span class="swatch" style="border-top-color:${st.colour};border-top-style:${st.dash.length ? "dashed" : "solid"}"></span>`;
  }

  // The laws in the core's order, those left out included.
  function laws(a) {
    return mstate.info.multi_laws.map((law) =>
      a.results.find((r) => r.law === law) ||
      { law, verdict: "omitted", values: null, omitted: (a.omitted.find((o) => o.law === law) || {}).reason });
  }

  function renderTable(a) {
    const cols = laws(a);
    const table = $("multi-laws");
    table.tHead.innerHTML = "<tr><th class='text'>after the impact</th><th>before</th>" +
      cols.map((r) => `<th class="law" data-law="${r.law}">${swatch(r.law)}${r.law}</th>`).join("") + "</tr>";
    const body = table.tBodies[0];
    body.textContent = "";
    const before = (c) => {
      if (c.kind !== "velocity") return "";
      return signed(a.u_before[a.coordinates.indexOf(c.key)], 5);
    };
    const row = (key, label, cells, cls = "") => {
      const tr = document.createElement("tr");
      tr.dataset.key = key;
      tr.className = cls;
      tr.innerHTML = `<th class="text">${label}</th>` + cells.join("");
      body.appendChild(tr);
    };
    a.columns.forEach((c, i) => {
      const cells = cols.map((r) => {
        const x = r.values ? signed(r.values[i], 5) : "—";
        const gained = c.key === "dT" && r.verdict === "energy-gained" ? " gained" : "";
        return `<td class="num${gained}" data-law="${r.law}" data-key="${c.key}">${x}</td>`;
      });
      row(c.key, c.label, [`<td class="num before">${before(c)}</td>`, ...cells], c.kind);
    });
    a.contact_names.forEach((name, j) => {
      const cells = cols.map((r) => `<td class="text phases" data-law="${r.law}" data-key="phases${j + 1}">${r.contacts ? r.contacts[j].phase_summary : "—"}</td>`);
      row(`phases${j + 1}`, `phases ${name}`, ["<td></td>", ...cells], "phase");
    });
    const verdicts = cols.map((r) => `<td class="text verdict" data-law="${r.law}" data-verdict="${r.verdict}">${verdictText(r.verdict)}</td>`);
    row("verdict", "verdict", ["<td></td>", ...verdicts], "verdict-row");
    const notes = [`T⁻ = ${Number(a.energy_before.toPrecision(6))}; ΔT = T⁺ − T⁻; pₙ: the normal impulse at each contact; phases: each contact's regimes during the impact.`];
    for (const r of cols) {
      if (r.omitted) notes.push(`${r.law}: ${r.omitted.replace(/^law: /, "")}`);
      if (r.inconsistency) notes.push(`${r.law}: ${r.inconsistency.message}`);
      if (r.breakdown) notes.push(`${r.law}: breakdown: ${r.breakdown.message}`);
    }
    $("multi-notes").textContent = notes.join(" · ");
  }

  // ---- the animations: one canvas per law, one scale for all -----------------------------

  const anim = { start: 0, raf: 0, playing: true, t: 0 };

  function buildFigures(a) {
    const box = $("multi-anims");
    const want = mstate.info.multi_laws.join(",");
    if (box.dataset.laws !== want) {
      box.textContent = "";
      for (const law of mstate.info.multi_laws) {
        const fig = document.createElement("figure");
        fig.className = "anim";
        fig.dataset.law = law;
        fig.innerHTML = `<canvas aria-label="the bodies after the impact under ${law}"></canvas><figcaption></figcaption>`;
        box.appendChild(fig);
      }
      box.dataset.laws = want;
    }
    for (const fig of box.children) {
      const law = fig.dataset.law;
      const r = a.results.find((x) => x.law === law);
      const m = a.animation.motion[law];
      const cap = fig.querySelector("figcaption");
      if (!r) cap.innerHTML = `${swatch(law)}<b>${law}</b>: not computed for ${a.contact_names.length} contacts`;
      else if (!m) cap.innerHTML = `${swatch(law)}<b>${law}</b>: no velocities after (breakdown)`;
      else cap.innerHTML = `${swatch(law)}<b>${law}</b>: T⁺/T⁻ = ${r.energy_ratio.toFixed(5)}; ${m.end.text}`;
    }
  }

  // Extent of a body at a pose.
  function extent(body, [x, y, th]) {
    if (body.shape === "ball") return [[x - body.radius, y - body.radius], [x + body.radius, y + body.radius]];
    const pts = outline(body, [x, y, th]);
    return pts;
  }

  // The corners of a rod (its ends) or a block at a pose.
  function outline(body, [x, y, th]) {
    const c = Math.cos(th), s = Math.sin(th);
    const local = body.shape === "rod"
      ? [[-body.length / 2, 0], [body.length / 2, 0]]
      : [[-body.half_width, -body.half_height], [body.half_width, -body.half_height],
         [body.half_width, body.half_height], [-body.half_width, body.half_height]];
    return local.map(([px, py]) => [x + c * px - s * py, y + s * px + c * py]);
  }

  function bounds(a) {
    let xmin = Infinity, xmax = -Infinity, ymin = Infinity, ymax = -Infinity;
    const take = ([x, y]) => { xmin = Math.min(xmin, x); xmax = Math.max(xmax, x); ymin = Math.min(ymin, y); ymax = Math.max(ymax, y); };
    const bodies = a.scene.bodies;
    bodies.forEach((b) => extent(b, [...b.position, b.angle]).forEach(take));
    for (const m of Object.values(a.animation.motion)) {
      for (const f of m.poses) f.forEach((p, i) => extent(bodies[i], p).forEach(take));
    }
    // The arrows at the impact.
    const k = ARROW * a.animation.window;
    bodies.forEach((b, i) => {
      const [x, y] = b.position;
      take([x - k * b.velocity[0], y - k * b.velocity[1]]);
      for (const r of a.results) if (r.velocities_after) take([x + k * r.velocities_after[3 * i], y + k * r.velocities_after[3 * i + 1]]);
    });
    if (a.scene.layout === "floor") ymin = Math.min(ymin, 0);
    if (a.scene.layout === "wall") xmin = Math.min(xmin, 0);
    const pad = 0.06 * Math.max(xmax - xmin, ymax - ymin);
    return { xmin: xmin - pad, xmax: xmax + pad, ymin: ymin - pad, ymax: ymax + pad };
  }

  // The pose of every body of `law` at screen time `t` (frames interpolated).
  function posesAt(a, law, t) {
    const m = a.animation.motion[law];
    const poses = m.poses;
    const n = poses.length - 1;
    const f = Math.min(1, Math.max(0, (t - HOLD) / PLAY)) * n;
    const k = Math.min(n - 1, Math.floor(f)), w = f - k;
    return poses[k].map((p, i) => p.map((x, j) => x + w * (poses[k + 1][i][j] - x)));
  }

  function drawGround(ctx, a, X, Y, w, h) {
    ctx.strokeStyle = "#333";
    ctx.lineWidth = 2;
    if (a.scene.layout === "floor") {
      ctx.beginPath(); ctx.moveTo(4, Y(0)); ctx.lineTo(w - 4, Y(0)); ctx.stroke();
      ctx.lineWidth = 1;
      for (let x = 8; x < w - 4; x += 11) { ctx.beginPath(); ctx.moveTo(x, Y(0) + 1); ctx.lineTo(x - 7, Y(0) + 8); ctx.stroke(); }
    } else if (a.scene.layout === "wall") {
      ctx.beginPath(); ctx.moveTo(X(0), 4); ctx.lineTo(X(0), h - 4); ctx.stroke();
      ctx.lineWidth = 1;
      for (let y = 8; y < h - 4; y += 11) { ctx.beginPath(); ctx.moveTo(X(0) - 1, y); ctx.lineTo(X(0) - 8, y + 7); ctx.stroke(); }
    } else {
      ctx.strokeStyle = "#bbb"; ctx.lineWidth = 1; ctx.setLineDash([4, 4]);
      ctx.beginPath(); ctx.moveTo(4, Y(0)); ctx.lineTo(w - 4, Y(0)); ctx.stroke();
      ctx.setLineDash([]);
    }
  }

  function drawBody(ctx, body, pose, index, X, Y, s, ghost) {
    const [x, y, th] = pose;
    ctx.lineWidth = ghost ? 1 : 2;
    ctx.strokeStyle = ghost ? "#aaa" : BODY;
    ctx.fillStyle = ghost ? "rgba(0,0,0,0)" : "rgba(31,95,153,0.14)";
    ctx.setLineDash(ghost ? [3, 3] : []);
    if (body.shape === "ball") {
      ctx.beginPath(); ctx.arc(X(x), Y(y), body.radius * s, 0, 2 * Math.PI); ctx.fill(); ctx.stroke();
      if (!ghost) {
        // A radius that turns with the ball, and its number.
        ctx.beginPath(); ctx.moveTo(X(x), Y(y));
        ctx.lineTo(X(x + body.radius * Math.cos(th + Math.PI / 2)), Y(y + body.radius * Math.sin(th + Math.PI / 2))); ctx.stroke();
        ctx.fillStyle = "#123"; ctx.font = SMALL; ctx.textAlign = "center"; ctx.textBaseline = "middle";
        ctx.fillText(String(index + 1), X(x) + 0.45 * body.radius * s, Y(y) + 0.3 * body.radius * s);
      }
    } else if (body.shape === "rod") {
      const [[ax, ay], [bx, by]] = outline(body, pose);
      ctx.lineWidth = ghost ? 1.5 : 6; ctx.lineCap = "round";
      ctx.beginPath(); ctx.moveTo(X(ax), Y(ay)); ctx.lineTo(X(bx), Y(by)); ctx.stroke();
      ctx.lineCap = "butt";
      if (!ghost) labelCorners(ctx, [[ax, ay], [bx, by]], X, Y, -12, 8);
    } else {
      const pts = outline(body, pose);
      ctx.beginPath();
      pts.forEach(([px, py], k) => (k ? ctx.lineTo(X(px), Y(py)) : ctx.moveTo(X(px), Y(py))));
      ctx.closePath(); ctx.fill(); ctx.stroke();
      if (!ghost) labelCorners(ctx, pts.slice(0, 2), X, Y, -10, -9);
    }
    ctx.setLineDash([]);
  }

  // "A" and "B" beside the first two points, `dx` outwards (negative: inwards).
  function labelCorners(ctx, pts, X, Y, dy, dx) {
    ctx.fillStyle = "#123"; ctx.font = SMALL; ctx.textAlign = "center"; ctx.textBaseline = "middle";
    pts.forEach(([px, py], k) => ctx.fillText(k ? "B" : "A", X(px) + (k ? dx : -dx), Y(py) + dy));
  }

  function drawLaw(fig, a, box, t) {
    const law = fig.dataset.law;
    const canvas = fig.querySelector("canvas");
    const spanX = box.xmax - box.xmin, spanY = box.ymax - box.ymin;
    const aspect = Math.min(0.7, Math.max(0.34, spanY / spanX));
    const { ctx, w, h } = context(canvas, aspect);
    const s = Math.min(w / spanX, h / spanY);
    const X = (x) => w / 2 + (x - (box.xmin + box.xmax) / 2) * s;
    const Y = (y) => h / 2 - (y - (box.ymin + box.ymax) / 2) * s;
    drawGround(ctx, a, X, Y, w, h);
    const bodies = a.scene.bodies;
    bodies.forEach((b, i) => drawBody(ctx, b, [...b.position, b.angle], i, X, Y, s, true));
    if (!a.animation.motion[law]) {
      ctx.fillStyle = "#666"; ctx.font = FONT; ctx.textAlign = "center"; ctx.textBaseline = "middle";
      ctx.fillText("no motion: the law gives no result", w / 2, 18);
      return;
    }
    posesAt(a, law, t).forEach((p, i) => drawBody(ctx, bodies[i], p, i, X, Y, s, false));
    const r = a.results.find((x) => x.law === law);
    ctx.font = FONT; ctx.textAlign = "left"; ctx.textBaseline = "top";
    ctx.fillStyle = r.verdict === "energy-gained" ? GAIN : "#222";
    ctx.fillText(law, 8, 6);
    if (t < HOLD) {
      // At the impact: each centre's velocity before, arriving (black, thin), and after,
      // leaving (the law's colour), as the distance covered in ARROW of the window.
      const k = ARROW * a.animation.window;
      bodies.forEach((b, i) => {
        const [x, y] = b.position, v = b.velocity;
        const u = r.velocities_after.slice(3 * i, 3 * i + 2);
        arrow(ctx, X(x - k * v[0]), Y(y - k * v[1]), X(x), Y(y), "#111", 1.5);
        arrow(ctx, X(x), Y(y), X(x + k * u[0]), Y(y + k * u[1]), (STYLE[law] || {}).colour || "#444", 3.5);
      });
    }
  }

  // An arrow from (x0, y0) to (x1, y1), moved 3 px to its left (so that an arrow arriving
  // at a point and one leaving it backwards stay apart).
  function arrow(ctx, x0, y0, x1, y1, colour, width) {
    const len = Math.hypot(x1 - x0, y1 - y0);
    if (len < 2) return;
    const ux = (x1 - x0) / len, uy = (y1 - y0) / len, head = Math.min(4 + 2 * width, 0.4 * len);
    x0 += 3 * uy; x1 += 3 * uy; y0 -= 3 * ux; y1 -= 3 * ux;
    ctx.strokeStyle = colour; ctx.fillStyle = colour; ctx.lineWidth = width;
    ctx.beginPath(); ctx.moveTo(x0, y0); ctx.lineTo(x1 - ux * head, y1 - uy * head); ctx.stroke();
    ctx.beginPath(); ctx.moveTo(x1, y1);
    ctx.lineTo(x1 - ux * head - uy * head * 0.5, y1 - uy * head + ux * head * 0.5);
    ctx.lineTo(x1 - ux * head + uy * head * 0.5, y1 - uy * head - ux * head * 0.5);
    ctx.closePath(); ctx.fill();
  }

  function timeText(a, t) {
    const win = a.animation.window;
    const phys = Math.min(1, Math.max(0, (t - HOLD) / PLAY)) * win;
    const factor = PLAY / win;
    const pace = factor > 1.05 ? `slowed ×${factor.toPrecision(3)}` : factor < 0.95 ? `sped up ×${(1 / factor).toPrecision(3)}` : "real time";
    const where = a.scene.layout === "floor" ? `gravity ${a.scene.gravity} m/s² down` : "seen from above, no gravity in the plane";
    const stage = t < HOLD ? "the impact (arrows: velocity before, black; after, the law's colour)" : t < HOLD + PLAY ? "after the impact" : "end of the window";
    return `${stage}: t = ${phys.toFixed(3)} s of ${win.toPrecision(3)} s (${pace}; ${where})`;
  }

  function draw(t) {
    const a = mstate.answer;
    if (!a) return;
    anim.t = t;
    $("multi-clock").value = t / (HOLD + PLAY + REST);
    const box = bounds(a);
    for (const fig of $("multi-anims").children) drawLaw(fig, a, box, t);
    $("multi-time").textContent = timeText(a, t);
  }

  function frame(now) {
    anim.raf = 0;
    if (!anim.playing || $("several").hidden) return;
    draw(((now - anim.start) / 1000) % (HOLD + PLAY + REST));
    anim.raf = requestAnimationFrame(frame);
  }

  function startAnimation() {
    if (!anim.playing || $("several").hidden) { draw(anim.playing ? 0 : anim.t); return; }
    if (!anim.raf) anim.raf = requestAnimationFrame(frame);
  }

  function play(on) {
    anim.playing = on;
    $("multi-play").textContent = on ? "pause" : "play";
    anim.start = performance.now() - anim.t * 1000;
    startAnimation();
  }

  // ---- wiring ----------------------------------------------------------------------------

  function update() {
    const a = Impax.multi(request());
    const err = $("multi-error");
    if (a.error) {
      err.hidden = false;
      err.textContent = a.error;
      return;
    }
    err.hidden = true;
    mstate.answer = a;
    mstate.updates += 1;
    $("multi-scenario").textContent = a.scenario;
    const f = (x) => Number(x.toPrecision(6));
    const v = a.problem.v.map((c, j) => `${a.contact_names[j]} (${f(c.t)}, ${f(c.n)})`).join(", ");
    $("multi-problem").textContent = `contacts (v⁻ = (v_t, v_n)): ${v}; W ${2 * a.problem.contacts} × ${2 * a.problem.contacts} of rank ${a.problem.rank}`;
    renderTable(a);
    buildFigures(a);
    startAnimation();
    $("several").dataset.ready = "1";
    $("several").dataset.updates = String(mstate.updates);
  }

  async function init() {
    await Impax.load("impax_wasm.wasm");
    mstate.info = Impax.info();
    $("multi-system").value = mstate.system;
    $("multi-system").addEventListener("change", () => setSystem($("multi-system").value));
    $("multi-reset").addEventListener("click", () => setSystem(mstate.system));
    $("multi-play").addEventListener("click", () => play(!anim.playing));
    // The clock: dragging it pauses the animation at that time.
    $("multi-clock").addEventListener("input", () => {
      anim.t = Number($("multi-clock").value) * (HOLD + PLAY + REST);
      play(false);
    });
    let resize = 0;
    window.addEventListener("resize", () => { clearTimeout(resize); resize = setTimeout(() => draw(anim.t), 100); });
    setSystem(mstate.system);
  }

  Views.add({
    name: "several", tab: "tab-several", panel: "several", hash: "#several",
    shown: () => { if (mstate.info) startAnimation(); },
  });
  init().catch((e) => {
    $("multi-error").hidden = false;
    $("multi-error").textContent = `could not load the impax core: ${e.message}`;
  });
})();
