// The explorer's view "Your mechanism": a mechanism file pasted or picked from
// examples/mechanisms/ (embedded in the module) → the impax core (WebAssembly, impax.js:
// `impax_mechanism`) → every law side by side on the impact of the contact that strikes, as
// `impax compare FILE --json`. The state q, u and μ, e start at the file's own and can be
// changed; a file that does not read is one line of error saying where.
// Every number comes from the core; this file only lays out and draws. It uses explorer.js's
// helpers ($, signed), loaded before it.
"use strict";

(() => {
  const mech = { info: null, answer: null, updates: 0, q: null, u: null, friction: null, restitution: null, started: false };
  window.explorerMechanism = mech;

  const VERDICTS = {
    "energy-gained": "ENERGY GAINED",
    "inconsistent-assumption": "inconsistent assumption",
    breakdown: "BREAKDOWN",
    consistent: "consistent",
  };
  const COEFFICIENTS = [
    { key: "friction", label: "friction μ", min: 0, max: 1.5, step: 0.005 },
    { key: "restitution", label: "restitution e", min: 0, max: 1, step: 0.01 },
  ];

  // ---- requests --------------------------------------------------------------------------

  function request() {
    const r = { file: $("mech-file").value };
    for (const k of ["q", "u", "friction", "restitution"]) if (mech[k] !== null) r[k] = mech[k];
    return r;
  }

  // A new file: its own state and coefficients.
  function fromFile() {
    mech.q = mech.u = mech.friction = mech.restitution = null;
    update();
  }

  function update() {
    const a = Impax.mechanism(request());
    const err = $("mech-error");
    mech.updates += 1;
    $("mechanism").dataset.updates = String(mech.updates);
    if (a.error) {
      err.hidden = false;
      err.textContent = a.error;
      $("mech-results").classList.add("stale");
      return;
    }
    err.hidden = true;
    $("mech-results").classList.remove("stale");
    mech.answer = a;
    // What the core used: the file's state unless the page gave one.
    mech.q = a.q; mech.u = a.u_before; mech.friction = a.friction; mech.restitution = a.restitution;
    buildState(a);
    $("mech-scenario").textContent = a.scenario;
    $("mech-problem").textContent = problemText(a);
    renderTable(a);
    $("mechanism").dataset.ready = "1";
  }

  // ---- the state and the coefficients ----------------------------------------------------

  // One typed input per entry of q and u, named as the core names them.
  function buildState(a) {
    const box = $("mech-state");
    const want = JSON.stringify([a.coordinates, a.speeds]);
    if (box.dataset.names !== want) {
      box.textContent = "";
      for (const [key, names, title] of [["q", a.coordinates, "q (coordinates, SI: rad, m)"], ["u", a.speeds, "u (velocities before, rad/s, m/s)"]]) {
        const group = document.createElement("fieldset");
        group.className = "state";
        group.innerHTML = `<legend>${title}</legend>`;
        names.forEach((name, i) => {
          const id = `mech-${key}-${i}`;
          const row = document.createElement("div");
          row.className = "entry";
          row.innerHTML = `<label for="${id}">${name}</label>`;
          const input = document.createElement("input");
          Object.assign(input, { type: "number", id, step: "any", className: "typed" });
          input.dataset.name = name;
          input.addEventListener("change", () => {
            const x = Number(input.value);
            if (input.value.trim() === "" || !Number.isFinite(x)) { input.value = String(mech[key][i]); return; }
            mech[key] = mech[key].slice();
            mech[key][i] = x;
            update();
          });
          row.appendChild(input);
          group.appendChild(row);
        });
        box.appendChild(group);
      }
      box.dataset.names = want;
    }
    a.coordinates.forEach((_, i) => { $(`mech-q-${i}`).value = String(a.q[i]); });
    a.speeds.forEach((_, i) => { $(`mech-u-${i}`).value = String(a.u_before[i]); });
    for (const c of COEFFICIENTS) {
      $(`mech-${c.key}`).value = a[c.key];
      $(`mech-${c.key}-value`).value = String(a[c.key]);
    }
  }

  function buildCoefficients() {
    const box = $("mech-coefficients");
    for (const c of COEFFICIENTS) {
      const id = `mech-${c.key}`;
      const wrap = document.createElement("div");
      wrap.className = "slider";
      wrap.innerHTML = `<div class="head"><label for="${id}">${c.label} <span class="unit">default: the file's, else 0.5</span></label></div>`;
      const typed = document.createElement("input");
      Object.assign(typed, { type: "number", id: `${id}-value`, step: "any", className: "typed" });
      typed.setAttribute("aria-label", `${c.label}, exact value`);
      typed.addEventListener("change", () => {
        const x = Number(typed.value);
        if (typed.value.trim() === "" || !Number.isFinite(x)) { typed.value = String(mech[c.key]); return; }
        mech[c.key] = x;
        update();
      });
      wrap.firstChild.appendChild(typed);
      const input = document.createElement("input");
      Object.assign(input, { type: "range", id, min: c.min, max: c.max, step: c.step });
      input.addEventListener("input", () => {
        mech[c.key] = Number(input.value);
        typed.value = input.value;
        update();
      });
      wrap.appendChild(input);
      box.appendChild(wrap);
    }
  }

  // ---- the table: one column per law -----------------------------------------------------

  function problemText(a) {
    const f = (x) => Number(x.toPrecision(6));
    const p = a.problem;
    const w = p.w.map((row) => `[${row.map(f).join(", ")}]`).join(", ");
    const v = a.space === "3d" ? `(${f(p.v.t1)}, ${f(p.v.t2)}, ${f(p.v.n)})` : `(${f(p.v.t)}, ${f(p.v.n)})`;
    return `contact “${a.contact}” strikes (gap ${f(a.gap)}): W = J M⁻¹ Jᵀ = [${w}], v⁻ = ${v}; T⁻ = ${f(a.energy_before)}`;
  }

  function renderTable(a) {
    const table = $("mech-laws");
    const laws = a.results;
    table.tHead.innerHTML = "<tr><th class='text'>after the impact</th><th>before</th>" +
      laws.map((r) => `<th class="law" data-law="${r.law}">${r.law}</th>`).join("") + "</tr>";
    const body = table.tBodies[0];
    body.textContent = "";
    const row = (key, cls, label, cells) => {
      const tr = document.createElement("tr");
      tr.dataset.key = key;
      tr.className = cls;
      tr.innerHTML = `<th class="text">${label}</th>` + cells.join("");
      body.appendChild(tr);
    };
    a.rows.forEach((c, i) => {
      const cells = laws.map((r) => {
        const x = r.values ? signed(r.values[i], 5) : "—";
        const gained = c.key === "dT" && r.verdict === "energy-gained" ? " gained" : "";
        return `<td class="num${gained}" data-law="${r.law}" data-key="${c.key}">${x}</td>`;
      });
      const before = c.before === null ? "" : signed(c.before, 5);
      row(c.key, c.kind, c.label, [`<td class="num before">${before}</td>`, ...cells]);
    });
    row("phases", "phase", "phases", ["<td></td>", ...laws.map((r) =>
      `<td class="text phases" data-law="${r.law}" data-key="phases">${r.phase_summary || "—"}</td>`)]);
    row("verdict", "verdict-row", "verdict", ["<td></td>", ...laws.map((r) =>
      `<td class="text verdict" data-law="${r.law}" data-verdict="${r.verdict}">${VERDICTS[r.verdict] || r.verdict}</td>`)]);
    const notes = [`${a.space === "3d" ? "In space: t1, t2 along the floor's x and y, n = z" : "In the plane: t along the floor, n up"}; ΔT = T⁺ − T⁻; phases: the regimes during the impact${a.space === "3d" ? "" : " (regime@pₙ at its end)"}.`];
    for (const r of laws) {
      if (r.inconsistency) notes.push(`${r.law}: ${r.inconsistency.message}`);
      if (r.breakdown) notes.push(`${r.law}: breakdown: ${r.breakdown.message}`);
    }
    $("mech-notes").textContent = notes.join(" · ");
  }

  // ---- wiring ----------------------------------------------------------------------------

  function loadExample(name) {
    const f = mech.info.mechanism_files.find((x) => x.name === name);
    $("mech-file").value = f.text;
    fromFile();
  }

  async function start() {
    if (mech.started) return;
    mech.started = true;
    try {
      await Impax.load("impax_wasm.wasm");
    } catch (e) {
      $("mech-error").hidden = false;
      $("mech-error").textContent = `could not load the impax core: ${e.message}`;
      return;
    }
    mech.info = Impax.info();
    const select = $("mech-example");
    for (const f of mech.info.mechanism_files) {
      const o = document.createElement("option");
      o.value = f.name; o.textContent = f.name;
      select.appendChild(o);
    }
    select.addEventListener("change", () => loadExample(select.value));
    buildCoefficients();
    // Typing: the file's own state again, once the typing pauses.
    let typing = 0;
    $("mech-file").addEventListener("input", () => {
      clearTimeout(typing);
      select.value = "";
      typing = setTimeout(fromFile, 250);
    });
    $("mech-reset").addEventListener("click", fromFile);
    select.value = mech.info.mechanism_files[0].name;
    loadExample(select.value);
  }

  Views.add({ name: "mechanism", tab: "tab-mechanism", panel: "mechanism", hash: "#mechanism", shown: start });
})();
