// The form: every figure of the file with its unit (a row per value), the engine's errors
// beside the row they name.
import {$, S, clear, h} from "./dom.js";
import {edit} from "./solve.js";
import {refreshStructure, structure} from "./structure.js";
import {t, titleOf, un} from "./words.js";

const UNITS = {mass: "kg", inertia: "kg·m²", omega_rpm: "rpm", omega: "rad/s", resisting: "N or N·m",
  phi_ref_deg: "°", angle_deg: "°", positions: "", ratio: "", pressure: "Pa", diameter: "len"};
function unitOf(keys) {
  const last = String(keys[keys.length - 1]);
  if (S.kind === "check" && keys.indexOf("measured") >= 0) return "mm";
  if (S.kind === "check" && keys.indexOf("values") >= 0) return "SI";
  const u = S.data.unit || "m";
  if (keys[0] === "points" || ["length", "along", "across", "through", "offset", "diameter"].indexOf(last) >= 0) return u;
  if (/_deg$/.test(last)) return "°";
  if (keys[0] === "loads" && (last === "vector")) return "N";
  return UNITS[last] !== undefined ? UNITS[last] : "";
}
const SKIP = {format: 1, kind: 1, outputs: 1, title: 1, frame: 1, unit: 1, sheet: 1};
const IDS = {link: 1, links: 1, format: 1};  // link numbers name the structure: not a form's figure
export function form() {
  const f = $("form"); clear(f);
  const tt = S.data.title;
  $("doc-title").textContent = titleOf(tt, S.name);
  if (S.kind === "linkage") structure(f);
  const scalars = Object.keys(S.data).filter((k) => !SKIP[k] && typeof S.data[k] === "number");
  if (scalars.length) {  // a synthesis file's task: the stroke, K, the swing, λ at the top level
    const fs = h(f, "fieldset"); h(fs, "legend", {}, t("sections").task || "task");
    for (const k of scalars) row(fs, k, [k], [S.data[k]]);
  }
  for (const top of Object.keys(S.data)) {
    if (SKIP[top]) continue;
    const v = S.data[top];
    if (top === "links" && v && typeof v === "object") {
      for (const id of Object.keys(v)) section(f, t("link") + " " + id + (v[id].name ? " — " + v[id].name : ""), v[id], ["links", id]);
    } else if (top === "joints" && Array.isArray(v)) {
      v.forEach((j, i) => { if (j.guide && typeof j.guide === "object") section(f, t("guide") + " " + j.point, j.guide, ["joints", i, "guide"]); });
    } else if (v && typeof v === "object") {
      section(f, t("sections")[top] || top, v, [top]);
    }
  }
}
function section(f, title, obj, keys) {
  const fs = h(f, "fieldset"); h(fs, "legend", {}, title);
  walk(fs, obj, keys, "");
  if (!fs.querySelector(".row")) f.removeChild(fs);
}
function walk(fs, obj, keys, prefix) {
  if (Array.isArray(obj)) {
    obj.forEach((o, i) => {
      if (!o || typeof o !== "object") return;
      if (keys.length === 1) {  // a table per position: its own box, named by its angle
        const sub = h(fs, "fieldset");
        h(sub, "legend", {}, typeof o.phi_deg === "number" ? "φ = " + o.phi_deg + "°" : "#" + (i + 1));
        walk(sub, o, keys.concat([i]), "");
      } else walk(fs, o, keys.concat([i]), prefix + (i + 1) + ".");
    });
    return;
  }
  for (const key of Object.keys(obj)) {
    const v = obj[key], path = keys.concat([key]);
    if (IDS[key]) continue;
    if (typeof v === "number") row(fs, prefix + key, path, [v]);
    else if (Array.isArray(v) && v.length && v.length <= 3 && v.every((x) => typeof x === "number")) row(fs, prefix + key, path, v);
    else if (key === "sense" && typeof v === "string") row(fs, prefix + key, path, v, ["ccw", "cw"]);
    else if (S.kind === "check" && typeof v === "string" && keys.some((k) => k === "measured" || k === "values" || k === "scales"))
      row(fs, prefix + key, path, [v], null, true);  // a student's figure: blank, a number or "65 mm"
    else if (key === "kind" && keys[0] === "loads" && typeof v === "string") continue;
    else if (v && typeof v === "object") walk(fs, v, path, prefix + key + ".");
  }
}
function row(fs, label, keys, values, choices, text) {
  const id = keys.join(".");
  const r = h(fs, "div", {class: "row"});
  // a student's figure reads as its quantity ("v_A", "a_A.2"), its unit beside it
  const short = label.replace(/^(measured|values|written)\./, "").replace(/\.(mm|value)$/, "");
  h(r, "label", {for: "f-" + id + (choices ? "" : "-0"), title: id}, short);
  const box = h(r, "span", {class: "inputs"});
  if (choices) {
    const s = h(box, "select", {id: "f-" + id, "data-key": id});
    for (const c of choices) { const o = h(s, "option", {value: c}, c); if (c === values) o.selected = true; }
    s.addEventListener("change", () => edit(keys, s.value, id));
  } else {
    const inputs = values.map((x, i) => h(box, "input", {id: "f-" + id + "-" + i, "data-key": id, type: "text",
      inputmode: "decimal", value: String(x)}));
    const send = () => {
      if (text) {  // a number when it reads as one, else the text as typed ("" leaves it blank)
        const t = inputs[0].value.trim(), x = Number(t.replace(",", "."));
        edit(keys, t !== "" && isFinite(x) ? x : t, id);
        return;
      }
      const vals = inputs.map((e) => Number(e.value.replace(",", ".").trim()));
      if (inputs.some((e) => e.value.trim() === "") || vals.some((x) => !isFinite(x))) {
        mark(id, t("expected_number") + " " + JSON.stringify(inputs.map((e) => e.value).join(", ")));
        return;
      }
      edit(keys, values.length === 1 && !Array.isArray(valueAt(keys)) ? vals[0] : vals, id);
    };
    for (const e of inputs) e.addEventListener("change", send);  // on Enter or on leaving the field
  }
  h(r, "span", {class: "unit"}, un(unitOf(keys)));
  h(r, "span", {class: "err", id: "e-" + id});
}
export function refresh() {  // the form's values from the data (a dragged pivot), the focused field left alone
  refreshStructure();
  for (const e of document.querySelectorAll("#form input[data-key]")) {
    if (e === document.activeElement) continue;
    const v = valueAt(e.dataset.key.split(".")), i = Number(e.id.slice(e.id.lastIndexOf("-") + 1));
    const x = Array.isArray(v) ? v[i] : v;
    if (typeof x === "number" && Number(e.value) !== x) e.value = String(x);
  }
}
export function valueAt(keys) { let o = S.data; for (const k of keys) o = o == null ? undefined : o[k]; return o; }
export function mark(id, message) {
  for (const e of document.querySelectorAll("#form .err")) e.textContent = "";
  for (const e of document.querySelectorAll("#form input.bad")) e.classList.remove("bad");
  $("general-error").textContent = "";
  if (!message) return;
  let target = id ? $("e-" + id) : null;
  if (!target) $("general-error").textContent = message;
  else {
    target.textContent = message;
    for (const e of target.parentNode.querySelectorAll("input")) e.classList.add("bad");
  }
}

export function fieldId(field) {
  // "links.1.length" or "points.O" name a row; an array element or a sub-key names its row
  let f = String(field).replace(/\[(\d+)\]/g, ".$1");
  while (f) {
    if ($("e-" + f)) return f;
    const cut = f.lastIndexOf(".");
    if (cut < 0) break;
    f = f.slice(0, cut);
  }
  const prefix = String(field).replace(/\[(\d+)\]/g, ".$1") + ".";
  const e = Array.from(document.querySelectorAll("#form .err")).find((x) => x.id.slice(2).startsWith(prefix));
  return e ? e.id.slice(2) : null;
}

