"use strict";
// The workbench page: the scene's data as a form, every edit sent to the server (the TOML is
// edited there, keeping comments and order), solved there, and drawn here. The page computes
// no mechanics: every coordinate it draws comes from /api/solve.
(function () {
  const NS = "http://www.w3.org/2000/svg";
  const $ = (id) => document.getElementById(id);
  const S = {path: null, name: null, text: "", data: null, sol: null, k: 0, last: null, seq: 0, shown: 0,
    busy: false, again: null};
  const KIND = {absolute: "abs", relative: "rel", normal: "nrm", tangential: "tan", coriolis: "cor",
    sliding: "sld", closing: "cls"};
  const f3 = (x) => (Math.round(x * 1000) / 1000).toString();
  const num = (x) => (x === undefined || x === null ? "" : Number(x.toPrecision(5)).toString());

  // ------------------------------------------------------------------ the page's language
  const WORDS = {
    en: {gallery: "the gallery", workbench: "workbench", save: "Save", page: "Page", check: "Check…",
      page_tip: "the demonstration page (plans demo)", check_tip: "a blank check file for this scene: type in a student's figures",
      start: "Start from a course mechanism", files_of: "Files of", scheme: "Scheme", velocity_plan: "Velocity plan",
      acceleration_plan: "Acceleration plan", forces: "Forces ▸", forces_tip: "the force polygons and the Zhukovsky lever",
      cycle: "Cycle ▸", cycle_tip: "the tables over the cycle as diagrams", cycle_title: "Over the cycle",
      open_designed: "Open the designed scene", designed: "Designed:",
      plans: "◂ Plans", forces_title: "Force polygons and the Zhukovsky lever", quantity: "quantity", segment: "segment",
      mm: "mm", read: "read", exact: "exact", difference: "difference", unit: "unit", where: "where", student: "student",
      error_pct: "error, %", tolerance_pct: "tolerance, %", verdict: "verdict", create: "Create",
      no_files: "No TOML files yet: create one above and save it.", not_saved: "(not saved)", solving: "solving…",
      solved: "solved in", error: "error", not_changed: "not changed", saved: "saved", checking: "checking…",
      checked: "checked", within: "✓ within", off: "✗ off", of: "of", figures_within: "figures within tolerance",
      figures_off: "off", mark: "mark", link: "link", guide: "guide at", at_scale: "(at scale, lengths in mm)",
      not_asked: "(not asked for)", balancing: "balancing", expected_number: "expected a number, got",
      no_answer: "the server does not answer", drawing: "drawing", ready: "ready", building: "building the page…",
      save_first: "save the scene first: a check file names its scene's file", name_needed: "a file name is needed",
      no_forces: "The scene asks for no force analysis (outputs: force_polygons, lever).",
      kinds: {linkage: "linkages", engine: "engines", gears: "gears", cam: "cams", check: "check files", synthesis: "synthesis"},
      sections: {task: "task"}},
    ru: {gallery: "галерея", workbench: "верстак", save: "Сохранить", page: "Страница", check: "Проверка…",
      page_tip: "демонстрационная страница (plans demo)", check_tip: "пустой файл проверки для этой схемы: введите цифры студента",
      start: "Начать с механизма курса", files_of: "Файлы папки", scheme: "Схема", velocity_plan: "План скоростей",
      acceleration_plan: "План ускорений", forces: "Силы ▸", forces_tip: "планы сил и рычаг Жуковского",
      cycle: "Цикл ▸", cycle_tip: "таблицы за цикл в виде диаграмм", cycle_title: "За цикл",
      open_designed: "Открыть спроектированную схему", designed: "Спроектировано:",
      plans: "◂ Планы", forces_title: "Планы сил и рычаг Жуковского", quantity: "величина", segment: "отрезок",
      mm: "мм", read: "по плану", exact: "точно", difference: "разность", unit: "ед.", where: "где", student: "студент",
      error_pct: "ошибка, %", tolerance_pct: "допуск, %", verdict: "итог", create: "Создать",
      no_files: "Файлов TOML пока нет: создайте схему выше и сохраните её.", not_saved: "(не сохранён)",
      solving: "расчёт…", solved: "рассчитано за", error: "ошибка", not_changed: "не изменено", saved: "сохранён",
      checking: "проверка…", checked: "проверено", within: "✓ в допуске", off: "✗ вне допуска", of: "из",
      figures_within: "величин в допуске", figures_off: "вне допуска", mark: "оценка", link: "звено", guide: "направляющая",
      at_scale: "(в масштабе, длины в мм)", not_asked: "(не запрошен)", balancing: "уравновешивающая",
      expected_number: "ожидалось число, введено", no_answer: "сервер не отвечает", drawing: "чертёж", ready: "готов",
      building: "строится страница…", save_first: "сначала сохраните схему: файл проверки ссылается на её файл",
      name_needed: "нужно имя файла", no_forces: "Силовой расчёт в схеме не запрошен (outputs: force_polygons, lever).",
      kinds: {linkage: "механизмы", engine: "двигатели", gears: "зубчатые передачи", cam: "кулачки", check: "файлы проверки", synthesis: "проектирование"},
      sections: {points: "точки стойки", driver: "начальное звено", loads: "нагрузки", branches: "сборки",
        positions: "положения", scales: "масштабы", tolerance: "допуски", cycle: "цикл", dynamics: "динамика",
        task: "задание"}},
  };
  let LANG = localStorage.getItem("plans-lang") || ((navigator.language || "").startsWith("ru") ? "ru" : "en");
  const t = (k) => (WORDS[LANG][k] !== undefined ? WORDS[LANG][k] : WORDS.en[k]);
  function translate() {
    document.documentElement.lang = LANG;
    for (const e of document.querySelectorAll("[data-t]")) e.textContent = t(e.dataset.t);
    for (const e of document.querySelectorAll("[data-t-title]")) e.title = t(e.dataset.tTitle);
    $("lang").textContent = LANG === "ru" ? "EN" : "RU";
  }
  const RU_UNITS = {"mm": "мм", "m": "м", "kg": "кг", "kg·m²": "кг·м²", "rpm": "об/мин", "rad/s": "рад/с",
    "N or N·m": "Н или Н·м", "N": "Н", "N·m": "Н·м", "Pa": "Па", "SI": "СИ", "m/s": "м/с", "m/s^2": "м/с²",
    "m/s²": "м/с²", "rad/s²": "рад/с²", "mm/N": "мм/Н", "mm/(m/s)": "мм/(м/с)", "mm/(m/s²)": "мм/(м/с²)",
    "rad/s, rad/s²": "рад/с, рад/с²"};
  const un = (u) => (LANG === "ru" && RU_UNITS[u] ? RU_UNITS[u] : u);
  const panelName = (nm) => (LANG !== "ru" ? nm : nm === "crank" ? "начальное звено" : nm === "lever" ? "рычаг Жуковского"
    : nm.replace(/^group /, "группа "));
  const titleOf = (tt, fallback) => (typeof tt === "string" ? tt : (tt && (tt[LANG] || tt.ru || tt.en)) || fallback);

  function status(text, bad) { const s = $("status"); s.textContent = text; s.className = bad ? "bad" : ""; }
  async function api(method, url, body, type) {
    const opt = {method: method, headers: {}};
    if (body !== undefined) { opt.body = body; opt.headers["Content-Type"] = type || "text/plain; charset=utf-8"; }
    let r;
    try { r = await fetch(url, opt); } catch (e) { return {ok: false, status: 0, data: {error: t("no_answer")}}; }
    const ct = r.headers.get("Content-Type") || "";
    const data = ct.startsWith("application/json") ? await r.json() : await r.blob();
    return {ok: r.ok, status: r.status, data: data};
  }
  function el(parent, tag, attrs, text) {
    const e = document.createElementNS(NS, tag);
    for (const k in attrs) e.setAttribute(k, attrs[k]);
    if (text !== undefined) e.textContent = text;
    parent.appendChild(e);
    return e;
  }
  function h(parent, tag, attrs, text) {
    const e = document.createElement(tag);
    for (const k in attrs || {}) e.setAttribute(k, attrs[k]);
    if (text !== undefined) e.textContent = text;
    if (parent) parent.appendChild(e);
    return e;
  }
  function clear(x) { while (x.lastChild) x.removeChild(x.lastChild); }

  // ------------------------------------------------------------------ the gallery
  async function gallery() {
    $("gallery").hidden = false; $("editor").hidden = true;
    $("save-box").hidden = true; $("downloads").hidden = true;
    $("doc-title").textContent = t("workbench"); $("doc-path").textContent = "";
    const [sm, fl] = await Promise.all([api("GET", "/api/samples"), api("GET", "/api/files")]);
    const cards = $("samples"); clear(cards);
    for (const s of sm.ok ? sm.data : []) {
      const c = h(cards, "div", {class: "card", "data-sample": s.name});
      h(c, "b", {}, titleOf(s.titles, s.title)); h(c, "small", {}, s.name + ".toml");
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
  async function openFile(path) {
    const r = await api("GET", "/api/file?path=" + encodeURIComponent(path));
    if (!r.ok) { status(r.data.error, true); return; }
    open(path, path, r.data.text, r.data.data, r.data.kind);
  }
  async function open(path, name, text, data, kind) {
    S.path = path; S.name = name; S.text = text; S.k = 0; S.sol = null; S.forces = null;
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

  // ------------------------------------------------------------------ the form
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
  function form() {
    const f = $("form"); clear(f);
    const tt = S.data.title;
    $("doc-title").textContent = titleOf(tt, S.name);
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
  function refresh() {  // the form's values from the data (a dragged pivot), the focused field left alone
    for (const e of document.querySelectorAll("#form input[data-key]")) {
      if (e === document.activeElement) continue;
      const v = valueAt(e.dataset.key.split(".")), i = Number(e.id.slice(e.id.lastIndexOf("-") + 1));
      const x = Array.isArray(v) ? v[i] : v;
      if (typeof x === "number" && Number(e.value) !== x) e.value = String(x);
    }
  }
  function valueAt(keys) { let o = S.data; for (const k of keys) o = o == null ? undefined : o[k]; return o; }
  function mark(id, message) {
    for (const e of document.querySelectorAll(".row .err")) e.textContent = "";
    for (const e of document.querySelectorAll(".row input.bad")) e.classList.remove("bad");
    $("general-error").textContent = "";
    if (!message) return;
    let target = id ? $("e-" + id) : null;
    if (!target) $("general-error").textContent = message;
    else {
      target.textContent = message;
      for (const e of target.parentNode.querySelectorAll("input")) e.classList.add("bad");
    }
  }

  // ------------------------------------------------------------------ edit, solve
  async function edit(keys, value, id) {
    S.last = id;
    const r = await api("POST", "/api/edit", JSON.stringify({text: S.text, set: [[keys, value]]}), "application/json");
    if (!r.ok) { mark(r.data.field || id, r.data.error); status(t("not_changed"), true); return; }
    S.text = r.data.text; S.data = r.data.data;
    refresh();
    $("doc-path").textContent = (S.path || t("not_saved")) + " •";
    await solve();
  }
  async function solve() {
    if (S.kind === "check") return checkRun();
    const seq = ++S.seq;
    const t0 = performance.now();
    status(t("solving"));
    let text = S.text;
    if (S.kind === "synthesis") {  // designed first (plans design), then its scene solved and drawn
      const d = await api("POST", "/api/design" + (S.path ? "?path=" + encodeURIComponent(S.path) : ""), S.text);
      if (d.ok) {
        S.designed = d.data.scene; S.designedData = d.data.data;
        $("general-error").textContent = "";
        $("design-summary").textContent = designSummary(d.data.design);
        text = d.data.scene;
      } else text = null;
      if (!d.ok) {
        if (seq < S.shown) return;
        S.shown = seq;
        mark((d.data.field && fieldId(d.data.field)) || S.last, d.data.error);
        status(t("error"), true);
        document.body.dataset.solved = String(seq);
        return;
      }
    }
    // steps=0: the construction protocol's text is left out (the page draws, it reads no protocol)
    const r = await api("POST", "/api/solve?steps=0" + (S.path && S.kind !== "synthesis" ? "&path=" + encodeURIComponent(S.path) : ""), text);
    if (seq < S.shown) return;  // an older answer after a newer one: keep the newer
    S.shown = seq;
    if (!r.ok) {
      // the field the engine names, else the field just edited (a construction names its group)
      const field = r.data.field && fieldId(r.data.field);
      mark(field || S.last, r.data.error);
      status("error", true);
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
    status(t("solved") + " " + Math.round(performance.now() - t0) + " ms");
    if (S.showForces) loadForces();
    document.body.dataset.solved = String(seq);
  }
  function designSummary(D) {
    const parts = [];
    for (const k in D.lengths || {}) parts.push(k + " = " + num(D.lengths[k]));
    if (D.K_measured !== undefined) parts.push("K = " + num(D.K_measured));
    if (D.stroke_measured !== undefined) parts.push("H = " + num(D.stroke_measured));
    if (D.swing_measured_deg !== undefined) parts.push("ψ = " + num(D.swing_measured_deg) + "°");
    if (D.gamma_min_deg !== undefined) parts.push("γmin = " + num(D.gamma_min_deg) + "°");
    return parts.join(", ");
  }
  function fieldId(field) {
    // "links.1.length" or "points.O" name a row; an array element or a sub-key names its row
    let f = String(field).replace(/\[(\d+)\]/g, ".$1");
    while (f) {
      if ($("e-" + f)) return f;
      const cut = f.lastIndexOf(".");
      if (cut < 0) break;
      f = f.slice(0, cut);
    }
    const prefix = String(field).replace(/\[(\d+)\]/g, ".$1") + ".";
    const e = Array.from(document.querySelectorAll(".row .err")).find((x) => x.id.slice(2).startsWith(prefix));
    return e ? e.id.slice(2) : null;
  }

  // ------------------------------------------------------------------ the check mode
  async function checkRun() {
    const seq = ++S.seq;
    status(t("checking"));
    const where = S.path || S.name;  // an unsaved check file finds its scene from the name it will have
    const r = await api("POST", "/api/check" + (where ? "?path=" + encodeURIComponent(where) : ""), S.text);
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
    for (const c of R.causes || []) h(ul, "li", {}, c.kind.replace(/_/g, " ") + ": " + c.detail);
    clear(tb);
    for (const it of R.items || []) {
      const tr = h(tb, "tr", {class: it.verdict, "data-field": it.field || ""});
      for (const x of [num(it.phi_deg), it.quantity, it.where || "", num(it.student), num(it.exact), num(it.error_pct),
        num(it.tolerance_pct), it.verdict === "pass" ? t("within") : t("off")]) h(tr, "td", {}, String(x));
      const id = it.field && fieldId(it.field);
      const row = id && $("e-" + id) && $("e-" + id).parentNode;
      if (row) {
        if (!row.classList.contains("fail")) row.classList.add(it.verdict === "pass" ? "pass" : "fail");
        if (it.verdict !== "pass") { row.classList.remove("pass"); row.title = it.quantity + ": exact " + num(it.exact) + " " + it.unit; }
      }
    }
    status(t("checked"));
    document.body.dataset.solved = String(seq);
  }

  // ------------------------------------------------------------------ drawing
  function fit(svg, pts, pad) {
    let x0 = Infinity, y0 = Infinity, x1 = -Infinity, y1 = -Infinity;
    for (const [x, y] of pts) { x0 = Math.min(x0, x); x1 = Math.max(x1, x); y0 = Math.min(y0, -y); y1 = Math.max(y1, -y); }
    if (!isFinite(x0)) { x0 = -10; x1 = 10; y0 = -10; y1 = 10; }
    const w = Math.max(x1 - x0, 20), hh = Math.max(y1 - y0, 20), p = pad * Math.max(w, hh);
    svg.setAttribute("viewBox", [x0 - p, y0 - p, w + 2 * p, hh + 2 * p].map(f3).join(" "));
    svg.setAttribute("preserveAspectRatio", "xMidYMid meet");
    return Math.max(w, hh) * (1 + 2 * pad);
  }
  function defs(svg) {
    const d = el(svg, "defs", {});
    const m = el(d, "marker", {id: svg.id + "-arr", viewBox: "0 0 10 10", refX: "10", refY: "5", markerWidth: "6",
      markerHeight: "6", orient: "auto-start-reverse", markerUnits: "strokeWidth"});
    el(m, "path", {d: "M0,1 L10,5 L0,9 z", class: "arrow"});
  }
  const mm = (p) => [p[0] * 1000, p[1] * 1000];
  function draw() {
    const pos = S.sol.positions[S.k];
    $("phi-out").textContent = "φ = " + num(pos.phi_deg) + "°  (" + (S.k + 1) + " " + t("of") + " " + S.sol.positions.length + ")";
    scheme(pos);
    const pl = pos.plans || {};
    plan($("vel"), pl.velocity, $("vel-scale"), "mm/(m/s)");
    plan($("acc"), pl.acceleration, $("acc-scale"), "mm/(m/s²)");
    table(pos);
    if (S.showForces && S.forces) drawForces();
    if (S.showCycle) drawCycle();
  }
  function sceneData() { return S.kind === "synthesis" && S.designedData ? S.designedData : S.data; }
  function links() {
    const out = [];
    const L = sceneData().links || {};
    for (const id of Object.keys(L)) {
      const axis = Array.isArray(L[id].axis) ? L[id].axis : [];
      const extra = L[id].points && typeof L[id].points === "object" ? Object.keys(L[id].points) : [];
      out.push({id: id, axis: axis, names: axis.concat(extra)});
    }
    return out;
  }
  function scheme(pos) {
    const svg = $("scheme"); clear(svg);
    const P = (nm) => (pos.points[nm] ? mm(pos.points[nm].r) : null);
    const all = [];
    for (const q of S.sol.positions) for (const nm in q.points) all.push(mm(q.points[nm].r));
    const size = fit(svg, all, 0.08), u = size / 100;
    const D = sceneData();
    const frame = String(D.frame);
    const joints = Array.isArray(D.joints) ? D.joints : [];
    const unit = D.unit === "mm" ? 1 : 1000;
    for (const j of joints) {  // guides fixed to the frame: a long dashed line
      const g = j.guide;
      if (j.kind !== "P" || !g || String(g.link) !== frame) continue;
      let o = null;
      if (Array.isArray(g.through)) o = [g.through[0] * unit, g.through[1] * unit];
      else if (typeof g.through === "string") o = P(g.through);
      if (!o) continue;
      let a = typeof g.angle_deg === "number" ? g.angle_deg * Math.PI / 180 : null;
      if (a === null && typeof g.toward === "string" && P(g.toward)) { const t = P(g.toward); a = Math.atan2(t[1] - o[1], t[0] - o[0]); }
      if (a === null) continue;
      const R = size;
      el(svg, "line", {x1: f3(o[0] - R * Math.cos(a)), y1: f3(-(o[1] - R * Math.sin(a))), x2: f3(o[0] + R * Math.cos(a)),
        y2: f3(-(o[1] + R * Math.sin(a))), class: "guide", "stroke-width": f3(0.3 * u)});
    }
    for (const lk of links()) {
      if (lk.id === frame) continue;
      const pts = lk.names.map(P).filter((p) => p);
      if (pts.length < 2) continue;
      const d = pts.map((p, i) => (i ? "L" : "M") + f3(p[0]) + "," + f3(-p[1])).join(" ") + (pts.length > 2 ? " Z" : "");
      el(svg, "path", {d: d, class: "link", "stroke-width": f3(0.7 * u), "data-link": lk.id});
    }
    for (const j of joints) {  // sliders: a block along its guide
      if (j.kind !== "P" || !P(j.point)) continue;
      const p = P(j.point), g = j.guide || {};
      let a = 0;
      if (String(g.link) === frame && typeof g.angle_deg === "number") a = g.angle_deg;
      else if (g.link !== undefined && pos.links[String(g.link)]) a = pos.links[String(g.link)].theta * 180 / Math.PI;
      el(svg, "rect", {x: f3(p[0] - 5 * u), y: f3(-p[1] - 3 * u), width: f3(10 * u), height: f3(6 * u), class: "slider",
        "stroke-width": f3(0.5 * u), transform: "rotate(" + f3(-a) + " " + f3(p[0]) + " " + f3(-p[1]) + ")"});
    }
    const pivots = {};
    for (const j of joints) {
      if (j.kind === "R" && Array.isArray(j.links) && j.links.map(String).indexOf(frame) >= 0 && P(j.point)) {
        const p = P(j.point); pivots[j.point] = 1;
        el(svg, "path", {d: "M" + f3(p[0]) + "," + f3(-p[1]) + " l" + f3(-3 * u) + "," + f3(5 * u) + " h" + f3(6 * u) + " z",
          class: "ground", "stroke-width": f3(0.4 * u)});
      }
    }
    const axisNames = {};
    for (const lk of links()) for (const nm of lk.axis) axisNames[nm] = 1;
    for (const nm in pos.points) {
      const p = P(nm);
      const draggable = D === S.data && pivots[nm] && S.data.points && Array.isArray(S.data.points[nm]);
      if (axisNames[nm] || draggable) {
        const c = el(svg, "circle", {cx: f3(p[0]), cy: f3(-p[1]), r: f3((draggable ? 1.6 : 1.1) * u),
          class: draggable ? "pivot" : "joint", "stroke-width": f3(0.35 * u), "data-point": nm});
        if (draggable) dragPivot(svg, c, nm, unit);
      } else {
        el(svg, "circle", {cx: f3(p[0]), cy: f3(-p[1]), r: f3(0.6 * u), class: "dot", "data-point": nm});
      }
      el(svg, "text", {x: f3(p[0] + 2 * u), y: f3(-p[1] - 2 * u), "font-size": f3(3.2 * u), class: "label"}, nm);
    }
    $("scheme-scale").textContent = t("at_scale");
  }
  function dragPivot(svg, c, nm, unit) {
    c.addEventListener("pointerdown", (ev) => {
      ev.preventDefault();
      c.classList.add("drag");
      const ctm = svg.getScreenCTM().inverse();
      const at = (e) => { const q = new DOMPoint(e.clientX, e.clientY).matrixTransform(ctm); return [q.x, -q.y]; };
      let pending = null, released = false;
      document.body.dataset.drag = "on";
      const send = async () => {
        if (S.busy || !pending) return;
        S.busy = true;
        const v = pending; pending = null;
        await edit(["points", nm], [Math.round(v[0]) / unit, Math.round(v[1]) / unit], "points." + nm);
        S.busy = false;
        if (pending) send();
        else if (released) document.body.dataset.drag = "done";
      };
      const move = (e) => {
        const p = at(e);
        c.setAttribute("cx", f3(p[0])); c.setAttribute("cy", f3(-p[1]));
        pending = p; send();
      };
      // on the window: the scheme is drawn again after each solve and this circle goes with it
      const up = (e) => {
        window.removeEventListener("pointermove", move); window.removeEventListener("pointerup", up);
        released = true; c.classList.remove("drag");
        pending = at(e); send();
      };
      window.addEventListener("pointermove", move);
      window.addEventListener("pointerup", up);
    });
  }
  function plan(svg, p, cap, unit) {
    clear(svg); defs(svg);
    if (!p) { cap.textContent = t("not_asked"); return; }
    cap.textContent = "μ = " + num(p.scale) + " " + un(unit);
    svg.dataset.scale = String(p.scale);
    const names = Object.keys(p.points);
    const size = fit(svg, names.map((k) => p.points[k]), 0.12), u = size / 100;
    for (const s of p.segments || []) {
      const a = p.points[s.from], b = p.points[s.to];
      if (!a || !b || Math.hypot(b[0] - a[0], b[1] - a[1]) < 1e-9) continue;
      el(svg, "line", {x1: f3(a[0]), y1: f3(-a[1]), x2: f3(b[0]), y2: f3(-b[1]), class: "seg " + (KIND[s.kind] || ""),
        "stroke-width": f3(0.5 * u), "marker-end": "url(#" + svg.id + "-arr)", "data-label": s.label});
    }
    // points on one spot (b on the pole at a dead centre) get one label "p_v, b, s4"
    const spots = [];
    for (const nm of names) {
      const q = p.points[nm];
      el(svg, "circle", {cx: f3(q[0]), cy: f3(-q[1]), r: f3(0.7 * u), class: "ppt", "data-name": nm});
      const g = spots.find((x) => Math.hypot(x.q[0] - q[0], x.q[1] - q[1]) <= 0.8 * u);
      if (g) g.names.push(nm); else spots.push({q: q, names: [nm]});
    }
    for (const g of spots) {
      el(svg, "text", {x: f3(g.q[0] + 1.5 * u), y: f3(-g.q[1] - 1.5 * u), "font-size": f3(4.5 * u), class: "label"},
        g.names.join(", "));
    }
  }
  // ------------------------------------------------------------------ forces (on demand)
  async function loadForces() {
    if (!S.showForces || S.kind === "check" || !S.sol) return;
    const text = S.text;
    const r = await api("POST", "/api/forces" + (S.path ? "?path=" + encodeURIComponent(S.path) : ""), text);
    if (text !== S.text) return;  // edited meanwhile: the next solve asks again
    S.forces = r.ok ? r.data : [];
    drawForces();
    document.body.dataset.forces = String(S.seq);
  }
  function drawForces() {
    const box = $("force-panels"); clear(box);
    if (!S.forces || !S.forces.length) { h(box, "p", {}, t("no_forces")); return; }
    for (const pn of S.forces) {
      const fig = h(box, "figure", {"data-panel": pn.id});
      h(fig, "figcaption", {}, panelName(pn.name) + ", μ = " + num(pn.scale) + " " + un(pn.unit));
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
        el(svg, "text", {x: f3(q[0] + 1.5 * u), y: f3(-q[1] + 4 * u), "font-size": f3(4 * u), class: "label"}, nm);
      }
      for (const [g, t] of segs) {
        if (Math.hypot(t[2] - t[0], t[3] - t[1]) < 1e-9) continue;
        el(svg, "line", {x1: f3(t[0]), y1: f3(-t[1]), x2: f3(t[2]), y2: f3(-t[3]), class: "seg " + (g.kind === "force" ? "frc" : KIND[g.kind] || ""),
          "stroke-width": f3(0.5 * u), "marker-end": "url(#" + svg.id + "-arr)", "data-label": g.label});
        el(svg, "text", {x: f3((t[0] + t[2]) / 2 + u), y: f3(-(t[1] + t[3]) / 2 - u), "font-size": f3(3.6 * u), class: "label"}, g.label);
      }
    }
  }
  function showForces(on) { show(on ? "forces" : "plans"); }
  function show(view) {  // the right column: the plans, the forces, or the diagrams over the cycle
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
  function drawCycle() {
    const rows = cycleRows(), sel = $("cycle-row"), keep = sel.value;
    clear(sel);
    rows.forEach((x, i) => h(sel, "option", {value: String(i)}, x.row.label + (x.row.unit ? ", " + un(x.row.unit) : "") + " — " + x.table.title));
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

  function table(pos) {
    const tb = $("table").tBodies[0]; clear(tb);
    for (const r of pos.readings || []) {
      const tr = h(tb, "tr");
      for (const x of [r.quantity, r.segment || "", num(r.length_mm), num(r.value), num(r.exact), num(r.difference), un(r.unit)]) h(tr, "td", {}, String(x));
    }
    const bal = pos.balancing;
    if (bal && typeof bal === "object") {
      for (const k of Object.keys(bal)) {
        const v = bal[k];
        if (typeof v !== "number") continue;
        const tr = h(tb, "tr");
        for (const x of [t("balancing") + " " + k, "", "", "", num(v), "", ""]) h(tr, "td", {}, x);
      }
    }
    for (const id of Object.keys(pos.links)) {
      const lk = pos.links[id];
      if (lk.omega === undefined) continue;
      const tr = h(tb, "tr");
      for (const x of ["ω" + id + ", ε" + id, "", "", "", num(lk.omega) + ", " + num(lk.eps === undefined ? NaN : lk.eps), "", un("rad/s, rad/s²")]) h(tr, "td", {}, x);
    }
  }

  // ------------------------------------------------------------------ save, downloads
  async function save() {
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
  function download(blob, name) {
    const a = h(document.body, "a", {href: URL.createObjectURL(blob), download: name});
    a.click();
    setTimeout(() => { URL.revokeObjectURL(a.href); a.remove(); }, 1000);
  }
  async function sheets(fmt) {
    status(t("drawing") + " " + fmt.toUpperCase() + "…");
    const stem = (S.path || S.name || "scene").replace(/\.toml$/, "");
    const r = await api("POST", "/api/draw?format=" + fmt + "&path=" + encodeURIComponent(stem + ".toml"), S.text);
    if (!r.ok) { status(r.data.error, true); return; }
    download(r.data, stem + (r.data.type === "application/zip" ? "-" + fmt + ".zip" : "." + fmt));
    status(fmt.toUpperCase() + " " + t("ready"));
  }

  $("to-gallery").addEventListener("click", () => { history.replaceState(null, "", "#"); gallery(); });
  $("save").addEventListener("click", save);
  for (const b of document.querySelectorAll("#downloads button[data-format]")) b.addEventListener("click", () => sheets(b.dataset.format));
  $("dl-json").addEventListener("click", () => {
    if (S.sol) download(new Blob([JSON.stringify(S.sol, null, 2)], {type: "application/json"}),
      (S.path || S.name || "scene").replace(/\.toml$/, "") + ".json");
  });
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
  $("dl-demo").addEventListener("click", async () => {
    status(t("building"));
    const stem = (S.path || S.name || "scene").replace(/\.toml$/, "");
    const r = await api("POST", "/api/demo?path=" + encodeURIComponent(stem + ".toml"), S.text);
    if (!r.ok) { status(r.data.error, true); return; }
    download(r.data, stem + ".html");
    status(t("ready"));
  });
  $("phi").addEventListener("input", () => { S.k = Number($("phi").value); if (S.sol && S.kind !== "check") draw(); });
  $("lang").addEventListener("click", () => {
    LANG = LANG === "ru" ? "en" : "ru";
    localStorage.setItem("plans-lang", LANG);
    translate();
    if (!$("gallery").hidden) gallery(); else if (S.data) { form(); if (S.sol && S.kind !== "check") draw(); else if (S.sol) checkRun(); }
  });
  translate();
  const m = /^#file=(.+)$/.exec(location.hash);
  if (m) openFile(decodeURIComponent(m[1])); else gallery();
})();
