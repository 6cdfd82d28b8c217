// The page's views, one shown at a time as tabs: each view registers its tab, its panel and
// its address (#several, #mechanism, #conserved; the first view has none), and is told when
// it is shown (to start its work the first time, to redraw canvases sized while hidden).
"use strict";

const Views = {
  list: [],

  // { name, tab, panel, hash, shown() }.
  add(view) {
    this.list.push(view);
    document.getElementById(view.tab).addEventListener("click", () => this.show(view.name));
  },

  show(name) {
    const view = this.list.find((v) => v.name === name) || this.list[0];
    for (const v of this.list) {
      const on = v === view;
      document.getElementById(v.panel).hidden = !on;
      document.getElementById(v.tab).setAttribute("aria-selected", String(on));
    }
    history.replaceState(null, "", view.hash || location.pathname + location.search);
    if (view.shown) view.shown();
  },

  // The view the address names (after every view's script has registered); on a change of
  // the address, the first view when it names none.
  start(changed) {
    const view = this.list.find((v) => v.hash && v.hash === location.hash);
    if (view) this.show(view.name);
    else if (changed) this.show(this.list[0].name);
  },
};

document.addEventListener("DOMContentLoaded", () => Views.start(false));
window.addEventListener("hashchange", () => Views.start(true));
