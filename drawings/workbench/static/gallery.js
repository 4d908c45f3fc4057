// The gallery (the course's mechanisms and the folder's files) and opening a file in the editor.
import {$, S, api, clear, h, status} from "./dom.js";
import {form} from "./form.js";
import {solve} from "./solve.js";
import {t, titleOf} from "./words.js";

export async function gallery() {
  $("gallery").hidden = false; $("editor").hidden = true;
  $("save-box").hidden = true; $("downloads").hidden = true;
  $("doc-title").textContent = t("workbench"); $("doc-path").textContent = "";
  const [sm, fl] = await Promise.all([api("GET", "/api/samples"), api("GET", "/api/files")]);
  const cards = $("samples"); clear(cards);
  for (const s of sm.ok ? sm.data : []) {
    const c = h(cards, "div", {class: "card", "data-sample": s.name});
    h(c, "b", {}, s.name === "new" ? t("new_scene") : titleOf(s.titles, s.title));
    h(c, "small", {}, s.name === "new" ? t("new_tip") : s.name + ".toml");
    h(c, "button", {}, t("create")).addEventListener("click", () => open(null, s.name + ".toml", s.text));
  }
  const folder = $("folder"); clear(folder);
  if (fl.ok) {
    $("folder-name").textContent = fl.data.folder;
    const kinds = Object.keys(fl.data.files).sort();
    if (!kinds.length) h(folder, "p", {}, t("no_files"));
    for (const kind of kinds) {
      h(folder, "h3", {}, t("kinds")[kind] || kind);
      const ul = h(folder, "ul");
      for (const f of fl.data.files[kind]) {
        const li = h(ul, "li");
        const a = h(li, "a", {"data-path": f.path}, f.path);
        a.addEventListener("click", () => openFile(f.path));
        h(li, "span", {}, " — " + titleOf(f.titles, f.title));
      }
    }
  }
  document.body.dataset.ready = "gallery";
}
export async function openFile(path) {
  const r = await api("GET", "/api/file?path=" + encodeURIComponent(path));
  if (!r.ok) { status(r.data.error, true); return; }
  open(path, path, r.data.text, r.data.data, r.data.kind);
}
export async function open(path, name, text, data, kind) {
  S.path = path; S.name = name; S.text = text; S.k = 0; S.sol = null; S.forces = null; S.structOpen = undefined;
  S.undo = []; $("undo").disabled = true;
  if (!data) {
    const r = await api("POST", "/api/edit", JSON.stringify({text: text, set: []}), "application/json");
    if (!r.ok) { status(r.data.error, true); return; }
    data = r.data.data; kind = r.data.kind;
  }
  S.data = data; S.kind = kind || "linkage";
  $("checkview").hidden = S.kind !== "check"; $("stage").hidden = S.kind === "check";
  $("gallery").hidden = true; $("editor").hidden = false;
  $("save-box").hidden = false; $("downloads").hidden = false;
  $("dl-demo").hidden = S.kind !== "linkage"; $("new-check").hidden = S.kind !== "linkage";
  $("dl-note").hidden = !NOTE_KINDS[S.kind];
  $("dl-json").hidden = S.kind !== "linkage" && S.kind !== "check" && S.kind !== "synthesis";
  $("design-box").hidden = S.kind !== "synthesis"; S.designed = null; S.designedData = null;
  $("design-summary").textContent = "";
  for (const b of document.querySelectorAll("#downloads button[data-format]")) b.hidden = S.kind === "check";
  $("save-path").value = path || name;
  $("doc-path").textContent = path || t("not_saved");
  if (path) history.replaceState(null, "", "#file=" + encodeURIComponent(path));
  else history.replaceState(null, "", "#");
  form();
  await solve();
}

// The kinds of file the explanatory note (plans note) takes.
const NOTE_KINDS = {linkage: 1, gears: 1, cam: 1, engine: 1};
