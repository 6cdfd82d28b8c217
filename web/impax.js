// The loader of the impax core compiled to WebAssembly: fetch the module, instantiate it
// (it imports nothing), and call its C-ABI exports with JSON text in linear memory.
// See crates/impax-wasm/src/lib.rs for the interface.
"use strict";

const Impax = {
  exports: null,
  loading: null,

  // Load the module once: the page's views share it (a second call gets the same promise).
  load(url) {
    if (!this.loading) this.loading = this.instantiate(url);
    return this.loading;
  },

  async instantiate(url) {
    let bytes;
    try {
      const response = await fetch(url);
      if (!response.ok) throw new Error(`${url}: HTTP ${response.status}`);
      bytes = await response.arrayBuffer();
    } catch (e) {
      // A page opened from the disk (file://) may not fetch: use the base64 copy that
      // `impax explore` writes beside the page.
      bytes = await this.embedded(e);
    }
    const { instance } = await WebAssembly.instantiate(bytes, {});
    this.exports = instance.exports;
    return this;
  },

  embedded(cause) {
    return new Promise((resolve, reject) => {
      const script = document.createElement("script");
      script.src = "impax_wasm.js";
      script.onload = () => {
        const text = atob(window.IMPAX_WASM_BASE64);
        const bytes = new Uint8Array(text.length);
        for (let i = 0; i < text.length; i++) bytes[i] = text.charCodeAt(i);
        resolve(bytes.buffer);
      };
      script.onerror = () => reject(new Error(`${cause.message}; impax_wasm.js not found either`));
      document.head.appendChild(script);
    });
  },

  // The answer of the last call, parsed.
  answer(ptr) {
    const len = this.exports.impax_output_len();
    const text = new TextDecoder().decode(new Uint8Array(this.exports.memory.buffer, ptr, len));
    return JSON.parse(text);
  },

  call(name, request) {
    const text = new TextEncoder().encode(JSON.stringify(request));
    const ptr = this.exports.impax_alloc(text.length);
    new Uint8Array(this.exports.memory.buffer, ptr, text.length).set(text);
    return this.answer(this.exports[name](ptr, text.length));
  },

  info() {
    return this.answer(this.exports.impax_info());
  },

  compare(request) {
    return this.call("impax_compare", request);
  },

  // Every multi-contact law on a built-in system struck at several contacts.
  multi(request) {
    return this.call("impax_multi", request);
  },

  // Every law on the impact of a mechanism file's striking contact.
  mechanism(request) {
    return this.call("impax_mechanism", request);
  },

  // The quantities the tracker reports along a built-in's free motion.
  conserved(request) {
    return this.call("impax_conserved", request);
  },

  // An energy map: the description, and copies of the cells (ΔT/T0 as f32, class as u8).
  map(request) {
    const answer = this.call("impax_map", request);
    if (answer.error) return { answer };
    const n = answer.cells;
    const buffer = this.exports.memory.buffer;
    const values = new Float32Array(buffer, this.exports.impax_map_values(), n).slice();
    const classes = new Uint8Array(buffer, this.exports.impax_map_classes(), n).slice();
    return { answer, values, classes };
  },
};
