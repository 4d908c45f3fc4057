// What every part of the page shares: the state of the file shown, the server's API, and the
// few helpers that make elements.
import {L, t} from "./words.js";

export const NS = "http://www.w3.org/2000/svg";
export const $ = (id) => document.getElementById(id);

// The file shown: its path (null while unsaved), name, TOML text, data, kind, solution, the
// position on the slider; seq/shown order the answers (an older one never replaces a newer).
export const S = {path: null, name: null, text: "", data: null, kind: null, sol: null, k: 0, last: null, seq: 0,
  shown: 0, busy: false, forces: null, showForces: false, showCycle: false, designed: null, designedData: null,
  undo: []};

export const f3 = (x) => (Math.round(x * 1000) / 1000).toString();
// a figure shown (never one typed back into a field): a decimal comma on a Russian page
export const num = (x) => (x === undefined || x === null ? "" : Number.isNaN(Number(x)) ? "—"
  : L.lang === "ru" ? Number(x.toPrecision(5)).toString().replace(".", ",") : Number(x.toPrecision(5)).toString());
// a key of the solution (omega_1, p_a, a segment "p_v a") as the page's language writes it
// (the server's symbols: ω1, π or p_a as the scene's notation says)
export const said = (key, fallback) => (((S.sol && S.sol.symbols) || {})[L.lang] || {})[key] || fallback;
export const sym = (nm) => String(nm).split(" ").map((w) => (((S.sol && S.sol.symbols) || {})[L.lang] || {})[w] || w).join(" ");
export const stem = (fallback) => (S.path || S.name || fallback).replace(/\.toml$/, "");
export const where = () => (S.path ? "path=" + encodeURIComponent(S.path) : "");

export function status(text, bad) { const s = $("status"); s.textContent = text; s.className = bad ? "bad" : ""; }

export async function api(method, url, body, type) {
  const opt = {method: method, headers: {}};
  if (body !== undefined) { opt.body = body; opt.headers["Content-Type"] = type || "text/plain; charset=utf-8"; }
  let r;
  try { r = await fetch(url, opt); } catch (e) { return {ok: false, status: 0, data: {error: t("no_answer")}}; }
  const ct = r.headers.get("Content-Type") || "";
  const data = ct.startsWith("application/json") ? await r.json() : await r.blob();
  if (data && data.errors && data.errors[L.lang]) data.error = data.errors[L.lang];  // the engine's line in the page's language
  return {ok: r.ok, status: r.status, data: data};
}

export function el(parent, tag, attrs, text) {  // an SVG element
  const e = document.createElementNS(NS, tag);
  for (const k in attrs) e.setAttribute(k, attrs[k]);
  if (text !== undefined) e.textContent = text;
  parent.appendChild(e);
  return e;
}

export function h(parent, tag, attrs, text) {  // an HTML element
  const e = document.createElement(tag);
  for (const k in attrs || {}) e.setAttribute(k, attrs[k]);
  if (text !== undefined) e.textContent = text;
  if (parent) parent.appendChild(e);
  return e;
}

export function clear(x) { while (x.lastChild) x.removeChild(x.lastChild); }

export function download(blob, name) {
  const a = h(document.body, "a", {href: URL.createObjectURL(blob), download: name});
  a.click();
  setTimeout(() => { URL.revokeObjectURL(a.href); a.remove(); }, 1000);
}
