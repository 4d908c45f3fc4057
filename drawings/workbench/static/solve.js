// An edit sent to the server (the TOML is edited there, its comments and order kept) and the
// scene solved: a linkage's edit and its solve come back in one answer (/api/edit?solve=1).
import {checkRun} from "./check.js";
import {$, S, api, num, status, where} from "./dom.js";
import {draw} from "./draw.js";
import {fieldId, form, mark, refresh} from "./form.js";
import {loadForces} from "./views.js";
import {t} from "./words.js";

// A figure of the form changed: keys is its key path in the file, id its row.
export function edit(keys, value, id) { return change({set: [[keys, value]]}, id, false); }

// Any edit ({set, put, append, delete}: see /api/edit); rebuild: the structure changed, the
// form is made again; from: the text to edit (an earlier one, taken back), else the file's.
// True when the file was changed.
export async function change(ops, id, rebuild, from) {
  S.last = id;
  const before = S.text;
  if (later !== null) { clearTimeout(later); later = null; }  // the next answer brings its own
  const together = S.kind === "linkage";
  const seq = together ? ++S.seq : 0, t0 = performance.now();
  if (together) status(t("solving"));
  // at: the position on the slider comes whole, the others after it is drawn (complete())
  const url = "/api/edit" + (together ? "?solve=1&steps=0&view=page&at=" + S.k + (S.path ? "&" + where() : "") : "");
  const r = await api("POST", url, JSON.stringify(Object.assign({text: from === undefined ? S.text : from, set: []}, ops)),
    "application/json");
  if (!r.ok || !r.data.data) {
    if (together && seq >= S.shown) { S.shown = seq; document.body.dataset.solved = String(seq); }
    mark((r.data.field && fieldId(r.data.field)) || id, r.data.error);
    status(t("not_changed"), true);
    return false;
  }
  if (from === undefined && r.data.text !== before) {
    S.undo.push(before);
    if (S.undo.length > UNDO_MAX) S.undo.shift();
  }
  $("undo").disabled = !S.undo.length;
  S.text = r.data.text; S.data = r.data.data;
  if (rebuild) form(); else refresh();
  $("doc-path").textContent = (S.path || t("not_saved")) + " •";
  if (!together) await solve();
  else present(seq, r.data.solution ? {ok: true, data: r.data.solution} : {ok: false, data: r.data.solve_error}, t0);
  return true;
}

// Files the page edits and exports but does not draw (their sheets and note are downloads).
const UNDRAWN = {gears: 1, cam: 1, engine: 1};

// The file as it was before the last change (the form made again, the scene solved again:
// a text solved before is answered from the server's store).
const UNDO_MAX = 100;
export async function undo() {
  if (!S.undo.length) return;
  await change({}, null, true, S.undo.pop());
  $("undo").disabled = !S.undo.length;
}

export async function solve() {
  if (S.kind === "check") return checkRun();
  if (UNDRAWN[S.kind]) {
    S.shown = ++S.seq;
    mark(null);
    status(t("ready"));
    document.body.dataset.solved = String(S.seq);
    return;
  }
  const seq = ++S.seq;
  const t0 = performance.now();
  status(t("solving"));
  let text = S.text;
  if (S.kind === "synthesis") {  // designed first (plans design), then its scene solved and drawn
    const d = await api("POST", "/api/design" + (S.path ? "?" + where() : ""), S.text);
    if (!d.ok) { present(seq, d, t0); return; }
    S.designed = d.data.scene; S.designedData = d.data.data;
    $("general-error").textContent = "";
    $("design-summary").textContent = designSummary(d.data.design);
    text = d.data.scene;
  }
  // steps=0: the construction protocol's text is left out (the page draws, it reads no protocol)
  const r = await api("POST", "/api/solve?steps=0&view=page" + (S.path && S.kind !== "synthesis" ? "&" + where() : ""), text);
  present(seq, r, t0);
}

// The answer of solve number seq drawn (an older answer after a newer one is dropped).
function present(seq, r, t0) {
  if (seq < S.shown) return;
  S.shown = seq;
  if (!r.ok) {
    // the field the engine names, else the field just edited (a construction names its group)
    mark((r.data.field && fieldId(r.data.field)) || S.last, r.data.error);
    status(t("error"), true);
    document.body.dataset.solved = String(seq);
    return;
  }
  mark(null);
  S.sol = r.data;
  const n = S.sol.positions.length;
  $("phi").max = String(Math.max(n - 1, 0));
  if (S.k >= n) S.k = 0;
  $("phi").value = String(S.k);
  draw();
  status(t("solved") + " " + Math.round(performance.now() - t0) + " " + t("ms"));
  if (S.showForces) loadForces();
  document.body.dataset.solved = String(seq);
  if (S.sol.partial !== undefined) later = setTimeout(() => complete(seq, S.text), REST_AFTER_MS);
}

// The other positions of a partial answer, asked for once its own position is drawn and no
// edit follows at once (typing, dragging: only the position on the slider is written), or
// as soon as the slider moves (the server has the scene solved already: it only writes them).
const REST_AFTER_MS = 150;
let later = null, asked = null;
export function completeNow() {
  if (later !== null) { clearTimeout(later); later = null; }
  complete(S.shown, S.text);
}
async function complete(seq, text) {
  later = null;
  if (S.text !== text || S.shown !== seq || !S.sol || S.sol.partial === undefined || asked === text) return;
  asked = text;
  const r = await api("POST", "/api/solve?steps=0&view=page" + (S.path ? "&" + where() : ""), text);
  asked = null;
  if (S.text !== text || S.shown !== seq || !S.sol || S.sol.partial === undefined) return;
  if (!r.ok) {  // the rest without an answer: the engine's line, as for the first
    mark((r.data.field && fieldId(r.data.field)) || S.last, r.data.error);
    status(t("error"), true);
    return;
  }
  const k = S.sol.partial;
  S.sol = r.data;
  if (S.k !== k || S.showCycle) draw();
  document.body.dataset.complete = String(seq);
}

function designSummary(D) {
  const parts = [];
  for (const k in D.lengths || {}) parts.push((t("lengths")[k] || k) + " = " + num(D.lengths[k]));
  if (D.K_measured !== undefined) parts.push("K = " + num(D.K_measured));
  if (D.stroke_measured !== undefined) parts.push("H = " + num(D.stroke_measured));
  if (D.swing_measured_deg !== undefined) parts.push("ψ = " + num(D.swing_measured_deg) + "°");
  if (D.gamma_min_deg !== undefined) parts.push("γmin = " + num(D.gamma_min_deg) + "°");
  return parts.join(", ");
}
