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
async function fetched(url, busy, name) {
  status(busy);
  const s = stem("scene");
  const r = await api("POST", url + (url.indexOf("?") < 0 ? "?" : "&") + "path=" + encodeURIComponent(s + ".toml"), S.text);
  if (!r.ok) { status(r.data.error, true); return false; }
  download(r.data, name(s, r.data));
  status(t("ready"));
  return true;
}

export function sheets(fmt) {
  return fetched("/api/draw?format=" + fmt, t("drawing") + " " + fmt.toUpperCase() + "…",
    (s, blob) => s + (blob.type === "application/zip" ? "-" + fmt + ".zip" : "." + fmt));
}

export function demo() { return fetched("/api/demo", t("building"), (s) => s + ".html"); }

export async function note() {
  if (await fetched("/api/note?language=" + L.lang, t("writing_note"), (s) => s + ".docx")) {
    document.body.dataset.note = String(Number(document.body.dataset.note || 0) + 1);
  }
}

export function json() {
  if (S.sol) download(new Blob([JSON.stringify(S.sol, null, 2)], {type: "application/json"}), stem("scene") + ".json");
}
