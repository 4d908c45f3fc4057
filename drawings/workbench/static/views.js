// The right column's other views: the force polygons and the Zhukovsky lever of the position
// (asked for when shown), and the tables over the cycle as diagrams against φ.
import {$, S, api, clear, el, f3, h, num, said, where} from "./dom.js";
import {KIND, defs, fit, scaleText} from "./draw.js";
import {L, panelName, t, un} from "./words.js";

export async function loadForces() {
  if (!S.showForces || S.kind === "check" || !S.sol) return;
  const text = S.text;
  const r = await api("POST", "/api/forces" + (S.path ? "?" + where() : ""), text);
  if (text !== S.text) return;  // edited meanwhile: the next solve asks again
  S.forces = r.ok ? r.data : [];
  drawForces();
  document.body.dataset.forces = String(S.seq);
}
export function drawForces() {
  const box = $("force-panels"); clear(box);
  if (!S.forces || !S.forces.length) { h(box, "p", {}, t("no_forces")); return; }
  for (const pn of S.forces) {
    const lab = (lb) => ((pn.said || {})[L.lang] || {})[lb] || lb;  // the server's label in the page's language
    const fig = h(box, "figure", {"data-panel": pn.id});
    h(fig, "figcaption", {}, panelName(pn.name) + ", " + scaleText(pn.scale, pn.unit));
    const svg = el(fig, "svg", {id: "force-" + pn.id, role: "img", "data-scale": String(pn.scale)});
    defs(svg);
    const segs = pn.segments.map((g) => [g, g.track[S.k]]).filter((x) => x[1]);
    const pts = [];
    for (const [, t] of segs) pts.push([t[0], t[1]], [t[2], t[3]]);
    for (const nm in pn.points || {}) if (pn.points[nm][S.k]) pts.push(pn.points[nm][S.k]);
    const size = fit(svg, pts, 0.12), u = size / 100;
    for (const nm in pn.points || {}) {
      const q = pn.points[nm][S.k];
      if (!q) continue;
      el(svg, "circle", {cx: f3(q[0]), cy: f3(-q[1]), r: f3(0.7 * u), class: "ppt"});
      el(svg, "text", {x: f3(q[0] + 1.5 * u), y: f3(-q[1] + 4 * u), "font-size": f3(4 * u), class: "label"}, lab(nm));
    }
    for (const [g, t] of segs) {
      if (Math.hypot(t[2] - t[0], t[3] - t[1]) < 1e-9) continue;
      el(svg, "line", {x1: f3(t[0]), y1: f3(-t[1]), x2: f3(t[2]), y2: f3(-t[3]), class: "seg " + (g.kind === "force" ? "frc" : KIND[g.kind] || ""),
        "stroke-width": f3(0.5 * u), "marker-end": "url(#" + svg.id + "-arr)", "data-label": g.label});
      el(svg, "text", {x: f3((t[0] + t[2]) / 2 + u), y: f3(-(t[1] + t[3]) / 2 - u), "font-size": f3(3.6 * u), class: "label"}, lab(g.label));
    }
  }
}
export function showForces(on) { show(on ? "forces" : "plans"); }
export function show(view) {  // the right column: the plans, the forces, or the diagrams over the cycle
  S.showForces = view === "forces"; S.showCycle = view === "cycle";
  $("forces").hidden = !S.showForces; $("cycle").hidden = !S.showCycle;
  for (const f of document.querySelectorAll("#stage figure.plan")) f.hidden = view !== "plans";
  if (S.showForces) loadForces();
  if (S.showCycle) drawCycle();
}
function cycleRows() {
  const out = [];
  const tabs = S.sol && S.sol.cycle && Array.isArray(S.sol.cycle.tables) ? S.sol.cycle.tables : [];
  for (const tb of tabs) for (const r of tb.rows || []) out.push({table: tb, row: r});
  return out;
}
export function drawCycle() {
  const rows = cycleRows(), sel = $("cycle-row"), keep = sel.value;
  clear(sel);
  rows.forEach((x, i) => h(sel, "option", {value: String(i)}, said("cycle." + x.row.label, x.row.label) + (x.row.unit ? ", " + un(x.row.unit) : "")
    + " — " + said("cycle." + x.table.title, x.table.title)));
  const svg = $("cycle-chart"); clear(svg);
  const tb = $("cycle-table").tBodies[0]; clear(tb);
  if (!rows.length) return;
  sel.value = keep && Number(keep) < rows.length ? keep : "0";
  const {table, row} = rows[Number(sel.value)];
  const phis = table.phi_deg, vals = row.values.map((v) => (typeof v === "number" ? v : NaN));
  const ok = vals.filter((v) => isFinite(v));
  let lo = Math.min(0, ...ok), hi = Math.max(0, ...ok);
  if (hi - lo < 1e-12) { hi += 1; lo -= 1; }
  const W = 360, H = 160, x = (p) => 30 + (W - 40) * p / 360, y = (v) => H - 15 - (H - 30) * (v - lo) / (hi - lo);
  svg.setAttribute("viewBox", "0 0 " + W + " " + H);
  el(svg, "line", {x1: 30, y1: f3(y(0)), x2: W - 10, y2: f3(y(0)), class: "axis", "stroke-width": 0.6});
  el(svg, "line", {x1: 30, y1: 10, x2: 30, y2: H - 15, class: "axis", "stroke-width": 0.6});
  for (const p of [0, 90, 180, 270, 360]) el(svg, "text", {x: f3(x(p)), y: H - 3, "font-size": 8, "text-anchor": "middle", class: "label"}, p + "°");
  el(svg, "text", {x: 2, y: 14, "font-size": 8, class: "label"}, num(hi));
  el(svg, "text", {x: 2, y: H - 16, "font-size": 8, class: "label"}, num(lo));
  const d = phis.map((p, i) => (isFinite(vals[i]) ? (i && isFinite(vals[i - 1]) ? "L" : "M") + f3(x(p)) + "," + f3(y(vals[i])) : "")).join(" ");
  el(svg, "path", {d: d, class: "curve", "stroke-width": 1.2, "data-key": row.key});
  phis.forEach((p, i) => { if (isFinite(vals[i])) el(svg, "circle", {cx: f3(x(p)), cy: f3(y(vals[i])), r: 1.8, class: "ppt"}); });
  const cur = S.sol.positions[S.k].phi_deg;
  el(svg, "line", {x1: f3(x(cur)), y1: 10, x2: f3(x(cur)), y2: H - 15, class: "cursor", "stroke-width": 0.8});
  phis.forEach((p, i) => {
    const tr = h(tb, "tr", {class: Math.abs(p - cur) < 1e-9 ? "on" : ""});
    h(tr, "td", {}, "φ = " + num(p) + "°"); h(tr, "td", {}, num(vals[i]));
  });
}

