// The structure of a linkage scene, edited in the form: the frame's link and fixed pivots, the
// links and their points, the joints (R, and P with its guide), the driver, the groups'
// branches, the loads and what is asked for. Each change is an edit of the file made on the
// server (/api/edit: put, append, delete) and solved at once; what the engine cannot solve is
// its one-line error beside the row just used.
import {$, S, h} from "./dom.js";
import {change} from "./solve.js";
import {L, t} from "./words.js";

const OUTPUTS = ["positions", "velocity_plan", "acceleration_plan", "force_polygons", "lever"];
const number = (s) => Number(String(s).replace(",", ".").trim());
const isNum = (s) => String(s).trim() !== "" && isFinite(number(s));
// a number of the file as the page's language writes it (a decimal comma on a Russian page)
const shown = (x) => (L.lang === "ru" ? String(x).replace(".", ",") : String(x));
const label = (name) => t(name === "guide" ? "guide_of" : name) || name;

export function structure(f) {
  const D = S.data, links = D.links && typeof D.links === "object" ? D.links : {};
  const box = h(f, "details", {id: "structure"});
  box.open = S.structOpen !== undefined ? S.structOpen : Object.keys(links).length < 2;
  box.addEventListener("toggle", () => { S.structOpen = box.open; });
  h(box, "summary", {}, t("structure"));

  // the frame's link number
  const fr = h(box, "div", {class: "srow"});
  h(fr, "label", {for: "s-frame-link"}, t("frame_link"));
  const frame = h(fr, "input", {id: "s-frame-link", size: "3", value: D.frame === undefined ? "" : String(D.frame)});
  frame.addEventListener("change", () => {
    if (!isNum(frame.value)) { bad("frame", t("expected_number") + " " + JSON.stringify(frame.value)); return; }
    change({put: [[["frame"], number(frame.value)]]}, "s-frame", true);
  });
  h(fr, "span", {class: "err", id: "e-s-frame"});

  // the fixed pivots: [points]
  part(box, t("pivots"));
  const pts = D.points && typeof D.points === "object" ? D.points : {};
  for (const nm of Object.keys(pts)) item(box, pivotText(nm, pts[nm]), {delete: [["points", nm]]}, "pivot-" + nm);
  adder(box, "pivot", [["name", "O"], ["x", "0"], ["y", "0"]], (v) => {
    if (!v.name || !isNum(v.x) || !isNum(v.y)) return null;
    return {put: [[["points", v.name], [number(v.x), number(v.y)]]]};
  });

  // the links
  part(box, t("s_links"));
  for (const id of Object.keys(links)) {
    const lk = links[id], axis = Array.isArray(lk.axis) ? lk.axis.join("–") : "";
    item(box, id + (lk.name ? " " + lk.name : "") + ": " + axis + (lk.length !== undefined ? ", " + shown(lk.length) : ""),
      removeLink(id), "link-" + id);
  }
  let next = 1;
  while (links[String(next)] || next === D.frame) next++;
  adder(box, "link", [["id", String(next)], ["axis", "O A"], ["length", ""], ["name", ""]], (v) => {
    const axis = v.axis.split(/[\s,–-]+/).filter((x) => x);
    if (!isNum(v.id) || !axis.length || (axis.length > 1 && !isNum(v.length))) return null;
    if (links[String(number(v.id))] || number(v.id) === D.frame) return t("s_link") + " " + v.id + ": " + t("taken");
    const body = {};
    if (v.name) body.name = v.name;
    body.axis = axis;
    if (axis.length > 1) body.length = number(v.length);
    return {put: [[["links", String(number(v.id))], body]]};
  });

  // points on the links (centres of mass, coupler points), in the link's frame
  part(box, t("s_points"));
  for (const id of Object.keys(links)) {
    const lp = links[id].points && typeof links[id].points === "object" ? links[id].points : {};
    for (const nm of Object.keys(lp)) {
      const p = lp[nm], how = Object.keys(p || {}).map((k) => (t(k) || k) + " " + shown(p[k])).join(", ");
      item(box, id + ": " + nm + " (" + how + ")", {delete: [["links", id, "points", nm]]}, "lpoint-" + id + "-" + nm);
    }
  }
  adder(box, "lpoint", [["link", ""], ["name", "S2"], ["along", "0"], ["across", "0"]], (v) => {
    const lk = links[v.link];
    if (!lk || !v.name || !isNum(v.along) || !isNum(v.across)) return null;
    const at = {along: number(v.along), across: number(v.across)};
    if (lk.points && typeof lk.points === "object") return {put: [[["links", v.link, "points", v.name], at]]};
    return {put: [[["links", v.link, "points"], {[v.name]: at}]]};
  });

  // the joints: R at a point both links share; P, the point of one link along a guide of the other
  part(box, t("s_joints"));
  const joints = Array.isArray(D.joints) ? D.joints : [];
  joints.forEach((j, i) => {
    let text = j.kind + " " + [].concat(j.links).join("–") + " " + t("at") + " " + j.point;
    const g = j.guide;
    if (g && typeof g === "object") {
      const thr = Array.isArray(g.through) ? "(" + g.through.join(", ") + ")" : g.through;
      text += ", " + t("guide_of") + " " + g.link + (g.through !== undefined ? " " + t("through") + " " + thr : "")
        + (g.angle_deg !== undefined ? ", " + g.angle_deg + "°" : "") + (g.toward !== undefined ? " → " + g.toward : "");
    }
    item(box, text, {delete: [["joints", i]]}, "joint-" + i);
  });
  adder(box, "joint", [["kind", "R", ["R", "P"]], ["links", "4 1"], ["point", "O"], ["guide", ""], ["through", ""], ["angle", "0"]], (v) => {
    const ls = v.links.split(/[\s,–-]+/).filter((x) => x).map(number);
    if (ls.length !== 2 || ls.some((x) => !Number.isInteger(x)) || !v.point) return null;
    const body = {kind: v.kind, links: ls, point: v.point};
    if (v.kind === "P") {
      if (!isNum(v.guide) || !v.through || !isNum(v.angle)) return null;
      const thr = v.through.split(/[\s,]+/).filter((x) => x);
      body.guide = {link: number(v.guide), through: thr.length === 2 && thr.every(isNum) ? thr.map(number) : v.through,
        angle_deg: number(v.angle)};
    }
    return {append: [[["joints"], body]]};
  });

  // the driver
  part(box, t("s_driver"));
  const drv = D.driver && typeof D.driver === "object" ? D.driver : null;
  adder(box, "driver", [["link", drv ? String(drv.link) : "1"], ["rpm", drv && drv.omega_rpm !== undefined ? String(drv.omega_rpm) : "100"],
    ["positions", drv && drv.positions !== undefined ? String(drv.positions) : "12"]], (v) => {
    if (!isNum(v.link) || !isNum(v.rpm) || !isNum(v.positions)) return null;
    if (drv) return {put: [[["driver", "link"], number(v.link)], [["driver", "omega_rpm"], number(v.rpm)], [["driver", "positions"], number(v.positions)]]};
    return {put: [[["driver"], {link: number(v.link), omega_rpm: number(v.rpm), sense: "ccw", phi_ref_deg: 0, positions: number(v.positions)}]]};
  }, drv ? "✓" : "+");

  // the branches of the groups: which of the two assemblies
  part(box, t("s_branches"));
  const br = D.branches && typeof D.branches === "object" ? D.branches : {};
  for (const g of Object.keys(br)) item(box, g + " = " + br[g], {delete: [["branches", g]]}, "branch-" + g);
  adder(box, "branch", [["group", "2-3"], ["sign", "1", ["1", "-1"]]], (v) => (v.group ? {put: [[["branches", v.group], number(v.sign)]]} : null));

  // the loads: forces at points, moments resisting a link's rotation
  part(box, t("s_loads"));
  const loads = D.loads && typeof D.loads === "object" ? D.loads : {};
  for (const kind of ["force", "moment"]) {
    (Array.isArray(loads[kind]) ? loads[kind] : []).forEach((ld, i) => {
      const what = kind === "force" ? " " + t("at") + " " + ld.point + " [" + [].concat(ld.vector).join(", ") + "]" : " " + ld.resisting;
      item(box, t(kind) + " " + (ld.name || "") + " (" + t("s_link") + " " + ld.link + ")" + what, {delete: [["loads", kind, i]]}, kind + "-" + i);
    });
  }
  adder(box, "force", [["name", "F"], ["link", ""], ["point", ""], ["Fx", "0"], ["Fy", "0"]], (v) => {
    if (!v.name || !isNum(v.link) || !v.point || !isNum(v.Fx) || !isNum(v.Fy)) return null;
    return {append: [[["loads", "force"], {name: v.name, link: number(v.link), point: v.point, vector: [number(v.Fx), number(v.Fy)]}]]};
  });
  adder(box, "moment", [["name", "M"], ["link", ""], ["resisting", "0"]], (v) => {
    if (!v.name || !isNum(v.link) || !isNum(v.resisting)) return null;
    return {append: [[["loads", "moment"], {name: v.name, link: number(v.link), resisting: number(v.resisting)}]]};
  });

  // what the scene asks for
  const out = h(box, "div", {class: "srow outputs"});
  const asked = Array.isArray(D.outputs) ? D.outputs : [];
  for (const o of OUTPUTS) {
    const lb = h(out, "label");
    const c = h(lb, "input", {type: "checkbox", id: "s-out-" + o});
    c.checked = asked.indexOf(o) >= 0;
    lb.appendChild(document.createTextNode(" " + o));
    c.addEventListener("change", () => {
      const now = OUTPUTS.filter((x) => $("s-out-" + x).checked).concat(asked.filter((x) => OUTPUTS.indexOf(x) < 0));
      change({put: [[["outputs"], now]]}, "s-outputs", true);
    });
  }
  h(out, "span", {class: "err", id: "e-s-outputs"});
}

function part(box, title) { h(box, "h4", {}, title); }

const pivotText = (nm, xy) => nm + " = [" + [].concat(xy).join(", ") + "]";

// The pivots' coordinates as the data has them now (a pivot dragged), the rest left as it is.
export function refreshStructure() {
  const pts = S.data && S.data.points && typeof S.data.points === "object" ? S.data.points : {};
  for (const nm of Object.keys(pts)) {
    const e = document.querySelector("#structure [data-item='pivot-" + CSS.escape(nm) + "'] span");
    if (e) e.textContent = pivotText(nm, pts[nm]);
  }
}

function bad(id, message) {
  const e = $("e-s-" + id);
  if (e) e.textContent = message;
}

// One element of the structure with its ✕ (the ops remove it).
function item(box, text, ops, id) {
  const r = h(box, "div", {class: "sitem", "data-item": id});
  h(r, "span", {}, text);
  const x = h(r, "button", {type: "button", class: "del", title: t("remove"), id: "s-del-" + id}, "✕");
  x.addEventListener("click", () => change(ops, "s-" + id.split("-")[0], true));  // its error: at the adding row
}

// A row of inputs that adds an element: fields [name, default, choices?]; make(values) gives the
// ops, or null when a field is missing or not a number, or a line saying what is wrong.
function adder(box, id, fields, make, sign) {
  h(box, "div", {class: "hint"}, fields.map(([name]) => label(name)).join(" · "));
  const r = h(box, "div", {class: "srow add", "data-add": id});
  const inputs = {};
  for (const [name, value, choices] of fields) {
    if (choices) {
      const s = h(r, "select", {id: "s-" + id + "-" + name, title: name});
      for (const c of choices) h(s, "option", {value: c}, c);
      s.value = value;
      inputs[name] = s;
    } else {
      inputs[name] = h(r, "input", {id: "s-" + id + "-" + name, placeholder: label(name), title: label(name),
        value: value, size: String(Math.max(3, Math.min(8, (value || name).length + 1)))});
    }
  }
  const b = h(r, "button", {type: "button", id: "s-" + id + "-add", title: t("add")}, sign || "+");
  const err = h(r, "span", {class: "err", id: "e-s-" + id});
  b.addEventListener("click", () => {
    const v = {};
    for (const k in inputs) v[k] = inputs[k].value.trim();
    const ops = make(v);  // the edit, or null (a field missing), or what is wrong
    if (!ops || typeof ops === "string") { err.textContent = ops || t("empty_first"); return; }
    change(ops, "s-" + id, true);
  });
}

// A link removed with the joints that hold it and the loads on it (the scene stays whole).
function removeLink(id) {
  const D = S.data, del = [];
  const joints = Array.isArray(D.joints) ? D.joints : [];
  for (let i = joints.length - 1; i >= 0; i--) if ([].concat(joints[i].links).map(String).indexOf(id) >= 0) del.push(["joints", i]);
  const loads = D.loads && typeof D.loads === "object" ? D.loads : {};
  for (const kind of ["force", "moment", "gas"]) {
    const arr = Array.isArray(loads[kind]) ? loads[kind] : [];
    for (let i = arr.length - 1; i >= 0; i--) if (String(arr[i].link) === id) del.push(["loads", kind, i]);
  }
  del.push(["links", id]);
  return {delete: del};
}
