// The workbench page: the scene's data as a form, every edit sent to the server (the TOML is
// edited there, keeping comments and order), solved there, and drawn here.
import {checkRun} from "./check.js";
import {$, S, api, status} from "./dom.js";
import {draw} from "./draw.js";
import {demo, json, note, save, sheets} from "./files.js";
import {form} from "./form.js";
import {gallery, open, openFile} from "./gallery.js";
import {undo} from "./solve.js";
import {drawCycle, show, showForces} from "./views.js";
import {L, setLanguage, t, translate} from "./words.js";

$("form").addEventListener("submit", (e) => e.preventDefault());  // Enter sends a field, never the form
$("to-gallery").addEventListener("click", () => { history.replaceState(null, "", "#"); gallery(); });
$("save").addEventListener("click", save);
$("undo").addEventListener("click", undo);
for (const b of document.querySelectorAll("#downloads button[data-format]")) b.addEventListener("click", () => sheets(b.dataset.format));
$("dl-json").addEventListener("click", json);
$("dl-demo").addEventListener("click", demo);
$("dl-note").addEventListener("click", note);
$("new-check").addEventListener("click", async () => {
  if (!S.path) { status(t("save_first"), true); return; }
  const r = await api("GET", "/api/template?path=" + encodeURIComponent(S.path));
  if (!r.ok) { status(r.data.error, true); return; }
  showForces(false);
  open(null, r.data.path, r.data.text, r.data.data, r.data.kind);
});
$("open-designed").addEventListener("click", () => {
  if (!S.designed) return;
  const stem = (S.path || S.name || "design").replace(/\.toml$/, "").replace(/.*\//, "");
  showForces(false);
  open(null, stem + "_scene.toml", S.designed);
});
$("show-forces").addEventListener("click", () => showForces(true));
$("show-plans").addEventListener("click", () => showForces(false));
$("show-plans2").addEventListener("click", () => show("plans"));
$("show-cycle").addEventListener("click", () => show("cycle"));
$("cycle-row").addEventListener("change", drawCycle);
$("phi").addEventListener("input", () => { S.k = Number($("phi").value); if (S.sol && S.kind !== "check") draw(); });
$("lang").addEventListener("click", () => {
  setLanguage(L.lang === "ru" ? "en" : "ru");
  if (!$("gallery").hidden) gallery(); else if (S.data) { form(); if (S.sol && S.kind !== "check") draw(); else if (S.sol) checkRun(); }
});
translate();
const m = /^#file=(.+)$/.exec(location.hash);
if (m) openFile(decodeURIComponent(m[1])); else gallery();
