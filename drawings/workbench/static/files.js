// Saving the file and the downloads: the sheets (SVG, PDF, DXF), the JSON, the demonstration
// page and the explanatory note, each as its own command writes it.
import {$, S, api, download, status, stem} from "./dom.js";
import {L, t} from "./words.js";

export async function save() {
  const path = $("save-path").value.trim();
  if (!path) { status(t("name_needed"), true); return; }
  const r = await api("PUT", "/api/file?path=" + encodeURIComponent(path), S.text);
  if (!r.ok) { status(r.data.error, true); return; }
  S.path = r.data.path;
  $("doc-path").textContent = S.path;
  history.replaceState(null, "", "#file=" + encodeURIComponent(S.path));
  status(t("saved") + " " + S.path);
  document.body.dataset.saved = S.path;
}

// POST the file's text to url (its name passed as ?path=) and download the answer as name.
async function fetched(url, busy, name, json) {
  status(busy);
  const s = stem("scene");
  const r = await api("POST", url + (url.indexOf("?") < 0 ? "?" : "&") + "path=" + encodeURIComponent(S.path || s + ".toml"), S.text);
  if (!r.ok) { status(r.data.error, true); return false; }
  const blob = json ? new Blob([JSON.stringify(r.data, null, 2)], {type: "application/json"}) : r.data;
  download(blob, name(s, blob));
  status(t("ready"));
  return true;
}

export function sheets(fmt) {
  return fetched("/api/draw?format=" + fmt, t("drawing") + " " + fmt.toUpperCase() + "…",
    (s, blob) => s + (blob.type === "application/zip" ? "-" + fmt + ".zip" : "." + fmt));
}

export function demo() { return fetched("/api/demo?language=" + L.lang, t("building"), (s) => s + ".html"); }

export async function note() {
  if (await fetched("/api/note?language=" + L.lang, t("writing_note"), (s) => s + ".docx")) {
    document.body.dataset.note = String(Number(document.body.dataset.note || 0) + 1);
  }
}

// The whole JSON of plans solve (the page keeps only what it draws).
export function json() {
  const url = S.kind === "check" ? "/api/check" : S.kind === "synthesis" ? "/api/design" : "/api/solve";
  return fetched(url, t("solving"), (s) => s + ".json", true);
}
