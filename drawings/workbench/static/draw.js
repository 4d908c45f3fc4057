// Drawing what the engine solved: the scheme at scale (its fixed pivots draggable), the
// velocity and acceleration plans of the position on the slider, and the results table.
// The page computes no mechanics: every coordinate it draws comes from the solution.
import {$, S, clear, el, f3, h, num, said, sym} from "./dom.js";
import {completeNow, edit} from "./solve.js";
import {drawCycle, drawForces} from "./views.js";
import {L, t, un} from "./words.js";

export const KIND = {absolute: "abs", relative: "rel", normal: "nrm", tangential: "tan", coriolis: "cor",
  sliding: "sld", closing: "cls"};

export function fit(svg, pts, pad) {
  let x0 = Infinity, y0 = Infinity, x1 = -Infinity, y1 = -Infinity;
  for (const [x, y] of pts) { x0 = Math.min(x0, x); x1 = Math.max(x1, x); y0 = Math.min(y0, -y); y1 = Math.max(y1, -y); }
  if (!isFinite(x0)) { x0 = -10; x1 = 10; y0 = -10; y1 = 10; }
  const w = Math.max(x1 - x0, 20), hh = Math.max(y1 - y0, 20), p = pad * Math.max(w, hh);
  svg.setAttribute("viewBox", [x0 - p, y0 - p, w + 2 * p, hh + 2 * p].map(f3).join(" "));
  svg.setAttribute("preserveAspectRatio", "xMidYMid meet");
  return Math.max(w, hh) * (1 + 2 * pad);
}
export function defs(svg) {
  const d = el(svg, "defs", {});
  const m = el(d, "marker", {id: svg.id + "-arr", viewBox: "0 0 10 10", refX: "10", refY: "5", markerWidth: "6",
    markerHeight: "6", orient: "auto-start-reverse", markerUnits: "strokeWidth"});
  el(m, "path", {d: "M0,1 L10,5 L0,9 z", class: "arrow"});
}
const mm = (p) => [p[0] * 1000, p[1] * 1000];
export function draw() {
  const pos = S.sol.positions[S.k];
  $("phi-out").textContent = "φ = " + num(pos.phi_deg) + "°  (" + (S.k + 1) + " " + t("of") + " " + S.sol.positions.length + ")";
  scheme(pos);
  if (S.sol.partial !== undefined && S.sol.partial !== S.k) { completeNow(); return; }  // its plans come with the rest
  const pl = pos.plans || {};
  plan($("vel"), pl.velocity, $("vel-scale"), "mm/(m/s)");
  plan($("acc"), pl.acceleration, $("acc-scale"), "mm/(m/s²)");
  table(pos);
  if (S.showForces && S.forces) drawForces();
  if (S.showCycle) drawCycle();
}
function sceneData() { return S.kind === "synthesis" && S.designedData ? S.designedData : S.data; }
function links() {
  const out = [];
  const L = sceneData().links || {};
  for (const id of Object.keys(L)) {
    const axis = Array.isArray(L[id].axis) ? L[id].axis : [];
    const extra = L[id].points && typeof L[id].points === "object" ? Object.keys(L[id].points) : [];
    out.push({id: id, axis: axis, names: axis.concat(extra)});
  }
  return out;
}
function scheme(pos) {
  const svg = $("scheme"); clear(svg);
  const P = (nm) => (pos.points[nm] ? mm(pos.points[nm].r) : null);
  const all = [];
  for (const q of S.sol.positions) for (const nm in q.points) all.push(mm(q.points[nm].r));
  const size = fit(svg, all, 0.08), u = size / 100;
  const D = sceneData();
  const frame = String(D.frame);
  const joints = Array.isArray(D.joints) ? D.joints : [];
  const unit = D.unit === "mm" ? 1 : 1000;
  for (const j of joints) {  // guides fixed to the frame: a long dashed line
    const g = j.guide;
    if (j.kind !== "P" || !g || String(g.link) !== frame) continue;
    let o = null;
    if (Array.isArray(g.through)) o = [g.through[0] * unit, g.through[1] * unit];
    else if (typeof g.through === "string") o = P(g.through);
    if (!o) continue;
    let a = typeof g.angle_deg === "number" ? g.angle_deg * Math.PI / 180 : null;
    if (a === null && typeof g.toward === "string" && P(g.toward)) { const t = P(g.toward); a = Math.atan2(t[1] - o[1], t[0] - o[0]); }
    if (a === null) continue;
    const R = size;
    el(svg, "line", {x1: f3(o[0] - R * Math.cos(a)), y1: f3(-(o[1] - R * Math.sin(a))), x2: f3(o[0] + R * Math.cos(a)),
      y2: f3(-(o[1] + R * Math.sin(a))), class: "guide", "stroke-width": f3(0.3 * u)});
  }
  for (const lk of links()) {
    if (lk.id === frame) continue;
    const pts = lk.names.map(P).filter((p) => p);
    if (pts.length < 2) continue;
    const d = pts.map((p, i) => (i ? "L" : "M") + f3(p[0]) + "," + f3(-p[1])).join(" ") + (pts.length > 2 ? " Z" : "");
    el(svg, "path", {d: d, class: "link", "stroke-width": f3(0.7 * u), "data-link": lk.id});
  }
  for (const j of joints) {  // sliders: a block along its guide
    if (j.kind !== "P" || !P(j.point)) continue;
    const p = P(j.point), g = j.guide || {};
    let a = 0;
    if (String(g.link) === frame && typeof g.angle_deg === "number") a = g.angle_deg;
    else if (g.link !== undefined && pos.links[String(g.link)]) a = pos.links[String(g.link)].theta * 180 / Math.PI;
    el(svg, "rect", {x: f3(p[0] - 5 * u), y: f3(-p[1] - 3 * u), width: f3(10 * u), height: f3(6 * u), class: "slider",
      "stroke-width": f3(0.5 * u), transform: "rotate(" + f3(-a) + " " + f3(p[0]) + " " + f3(-p[1]) + ")"});
  }
  const pivots = {};
  for (const j of joints) {
    if (j.kind === "R" && Array.isArray(j.links) && j.links.map(String).indexOf(frame) >= 0 && P(j.point)) {
      const p = P(j.point); pivots[j.point] = 1;
      el(svg, "path", {d: "M" + f3(p[0]) + "," + f3(-p[1]) + " l" + f3(-3 * u) + "," + f3(5 * u) + " h" + f3(6 * u) + " z",
        class: "ground", "stroke-width": f3(0.4 * u)});
    }
  }
  const axisNames = {};
  for (const lk of links()) for (const nm of lk.axis) axisNames[nm] = 1;
  for (const nm in pos.points) {
    const p = P(nm);
    const draggable = D === S.data && pivots[nm] && S.data.points && Array.isArray(S.data.points[nm]);
    if (axisNames[nm] || draggable) {
      const c = el(svg, "circle", {cx: f3(p[0]), cy: f3(-p[1]), r: f3((draggable ? 1.6 : 1.1) * u),
        class: draggable ? "pivot" : "joint", "stroke-width": f3(0.35 * u), "data-point": nm});
      if (draggable) dragPivot(svg, c, nm, unit);
    } else {
      el(svg, "circle", {cx: f3(p[0]), cy: f3(-p[1]), r: f3(0.6 * u), class: "dot", "data-point": nm});
    }
    el(svg, "text", {x: f3(p[0] + 2 * u), y: f3(-p[1] - 2 * u), "font-size": f3(3.2 * u), class: "label"}, nm);
  }
  $("scheme-scale").textContent = t("at_scale");
}
function dragPivot(svg, c, nm, unit) {
  c.addEventListener("pointerdown", (ev) => {
    ev.preventDefault();
    c.classList.add("drag");
    const ctm = svg.getScreenCTM().inverse();
    const at = (e) => { const q = new DOMPoint(e.clientX, e.clientY).matrixTransform(ctm); return [q.x, -q.y]; };
    let pending = null, released = false;
    document.body.dataset.drag = "on";
    const send = async () => {
      if (S.busy || !pending) return;
      S.busy = true;
      const v = pending; pending = null;
      await edit(["points", nm], [Math.round(v[0]) / unit, Math.round(v[1]) / unit], "points." + nm);
      S.busy = false;
      if (pending) send();
      else if (released) document.body.dataset.drag = "done";
    };
    const move = (e) => {
      const p = at(e);
      c.setAttribute("cx", f3(p[0])); c.setAttribute("cy", f3(-p[1]));
      pending = p; send();
    };
    // on the window: the scheme is drawn again after each solve and this circle goes with it
    const up = (e) => {
      window.removeEventListener("pointermove", move); window.removeEventListener("pointerup", up);
      released = true; c.classList.remove("drag");
      pending = at(e); send();
    };
    window.addEventListener("pointermove", move);
    window.addEventListener("pointerup", up);
  });
}
function plan(svg, p, cap, unit) {
  clear(svg); defs(svg);
  if (!p) { cap.textContent = t("not_asked"); return; }
  cap.textContent = scaleText(p.scale, unit);
  svg.dataset.scale = String(p.scale);
  const names = Object.keys(p.points);
  const size = fit(svg, names.map((k) => p.points[k]), 0.12), u = size / 100;
  for (const s of p.segments || []) {
    const a = p.points[s.from], b = p.points[s.to];
    if (!a || !b || Math.hypot(b[0] - a[0], b[1] - a[1]) < 1e-9) continue;
    el(svg, "line", {x1: f3(a[0]), y1: f3(-a[1]), x2: f3(b[0]), y2: f3(-b[1]), class: "seg " + (KIND[s.kind] || ""),
      "stroke-width": f3(0.5 * u), "marker-end": "url(#" + svg.id + "-arr)", "data-label": s.label});
  }
  // points on one spot (b on the pole at a dead centre) get one label "p_v, b, s4"
  const spots = [];
  for (const nm of names) {
    const q = p.points[nm];
    el(svg, "circle", {cx: f3(q[0]), cy: f3(-q[1]), r: f3(0.7 * u), class: "ppt", "data-name": nm});
    const g = spots.find((x) => Math.hypot(x.q[0] - q[0], x.q[1] - q[1]) <= 0.8 * u);
    if (g) g.names.push(nm); else spots.push({q: q, names: [nm]});
  }
  for (const g of spots) {
    el(svg, "text", {x: f3(g.q[0] + 1.5 * u), y: f3(-g.q[1] - 1.5 * u), "font-size": f3(4.5 * u), class: "label"},
      g.names.map(sym).join(", "));
  }
}
// A plan's scale as the scene's notation writes it in the page's language: μ in mm per unit,
// or (a Russian course's default) units per mm, or K.
const PER_MM = {"mm/(m/s)": "(m/s)/mm", "mm/(m/s²)": "(m/s²)/mm", "mm/N": "N/mm", "mm/m": "m/mm"};
export function scaleText(scale, unit) {
  const perMm = said("scale.per_mm", "0") === "1" && PER_MM[unit];
  return said("scale.symbol", "μ") + " = " + (perMm ? num(1 / scale) + " " + un(PER_MM[unit]) : num(scale) + " " + un(unit));
}
function table(pos) {
  const tb = $("table").tBodies[0]; clear(tb);
  for (const r of pos.readings || []) {
    const tr = h(tb, "tr");
    for (const x of [sym(r.quantity), sym(r.segment || ""), num(r.length_mm), num(r.value), num(r.exact), num(r.difference), un(r.unit)]) h(tr, "td", {}, String(x));
  }
  const bal = pos.balancing;
  if (bal && typeof bal === "object") {
    for (const k of Object.keys(bal)) {
      const v = bal[k];
      if (typeof v !== "number") continue;
      const tr = h(tb, "tr");
      for (const x of [sym("balancing." + k), "", "", "", num(v), "", ""]) h(tr, "td", {}, x);
    }
  }
  for (const id of Object.keys(pos.links)) {
    const lk = pos.links[id];
    if (lk.omega === undefined) continue;
    const tr = h(tb, "tr");
    for (const x of ["ω" + id + ", ε" + id, "", "", "", num(lk.omega) + (L.lang === "ru" ? "; " : ", ") + num(lk.eps === undefined ? NaN : lk.eps), "", un("rad/s, rad/s²")]) h(tr, "td", {}, x);
  }
}

