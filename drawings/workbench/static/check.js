// The check mode: a student's figures per position checked live against the engine.
import {$, S, api, clear, h, num, status} from "./dom.js";
import {fieldId, mark} from "./form.js";
import {L, t, un} from "./words.js";

export async function checkRun() {
  const seq = ++S.seq;
  status(t("checking"));
  const where = S.path || S.name;  // an unsaved check file finds its scene from the name it will have
  const r = await api("POST", "/api/check?names=1&language=" + L.lang + (where ? "&path=" + encodeURIComponent(where) : ""), S.text);
  if (seq < S.shown) return;
  S.shown = seq;
  for (const e of document.querySelectorAll(".row.pass, .row.fail")) e.classList.remove("pass", "fail");
  const tb = $("check-table").tBodies[0];
  if (!r.ok) {
    mark((r.data.field && fieldId(r.data.field)) || S.last, r.data.error);
    $("check-error").textContent = r.data.error;
    status("error", true);
    document.body.dataset.solved = String(seq);
    return;
  }
  mark(null); $("check-error").textContent = "";
  S.sol = r.data;
  const R = r.data, sm = R.summary || {};
  $("check-summary").textContent = (R.student ? R.student + ": " : "") + sm.passed + " " + t("of") + " " + sm.items +
    " " + t("figures_within") + ", " + sm.failed + " " + t("figures_off") + (R.mark !== null && R.mark !== undefined ? "; " + t("mark") + " " + num(R.mark) : "");
  const ul = $("check-causes"); clear(ul);
  // the cause's kind as the program names it on an English page; a Russian one has its sentence alone
  for (const c of R.causes || []) h(ul, "li", {}, L.lang === "ru" ? c.detail : c.kind.replace(/_/g, " ") + ": " + c.detail);
  const name = (q) => (R.names && R.names[q]) || q;
  clear(tb);
  for (const it of R.items || []) {
    const tr = h(tb, "tr", {class: it.verdict, "data-field": it.field || ""});
    for (const x of [num(it.phi_deg), name(it.quantity), it.where || "", num(it.student), num(it.exact), num(it.error_pct),
      num(it.tolerance_pct), it.verdict === "pass" ? t("within") : t("off")]) h(tr, "td", {}, String(x));
    const id = it.field && fieldId(it.field);
    const row = id && $("e-" + id) && $("e-" + id).parentNode;
    if (row) {
      if (!row.classList.contains("fail")) row.classList.add(it.verdict === "pass" ? "pass" : "fail");
      if (it.verdict !== "pass") { row.classList.remove("pass"); row.title = name(it.quantity) + ": " + t("exact") + " " + num(it.exact) + " " + un(it.unit); }
    }
  }
  status(t("checked"));
  document.body.dataset.solved = String(seq);
}

