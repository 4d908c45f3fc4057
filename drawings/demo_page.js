"use strict";
(function () {
  const L = JSON.parse(document.getElementById("lesson").textContent);
  const T = JSON.parse(document.getElementById("words").textContent);
  const NS = "http://www.w3.org/2000/svg";
  const $ = (id) => document.getElementById(id);
  const KIND = {absolute: "abs", relative: "rel", normal: "nrm", tangential: "tan", coriolis: "cor",
    sliding: "sld", force: "frc", closing: "cls"};

  function el(parent, tag, attrs, text) {
    const e = document.createElementNS(NS, tag);
    for (const k in attrs) e.setAttribute(k, attrs[k]);
    if (text !== undefined) e.textContent = text;
    parent.appendChild(e);
    return e;
  }
  const f3 = (x) => (Math.round(x * 1000) / 1000).toString();
  // numbers and words as the page's language writes them (decimal comma, F_ур, Н)
  const nf = (x, digits) => String(Number(x.toPrecision(digits))).replace(".", T.decimal);
  const fixed = (x, digits) => x.toFixed(digits).replace(".", T.decimal);
  const lab = (s) => String(s).replace(/\b[FMI]_(bal|pr)\b/g, (m) => T.labels[m] || m)
    .replace(/\b([FM])f(?=\d)/g, (m) => T.labels[m] || m).replace(/Phi/g, "Φ");  // Ff56: a pair's friction
  const unit = (u) => T.units[u] || u;
  const pt = (nm) => (T.points || {})[nm] || nm;  // a plan's pole as the page's language names it (p, π)
  function fit(svg, boxes, pad) {
    let x0 = Infinity, y0 = Infinity, x1 = -Infinity, y1 = -Infinity;
    for (const [x, y] of boxes) { x0 = Math.min(x0, x); x1 = Math.max(x1, x); y0 = Math.min(y0, -y); y1 = Math.max(y1, -y); }
    if (!isFinite(x0)) { x0 = -10; x1 = 10; y0 = -10; y1 = 10; }
    const w = Math.max(x1 - x0, 20), h = Math.max(y1 - y0, 20);
    const cx = (x0 + x1) / 2, cy = (y0 + y1) / 2;
    svg.setAttribute("viewBox", [cx - w / 2 - pad, cy - h / 2 - pad, w + 2 * pad, h + 2 * pad].map(f3).join(" "));
    return Math.max(w, h) + 2 * pad;
  }
  function clear(svg) { while (svg.lastChild) svg.removeChild(svg.lastChild); }
  // Points drawn on one spot (b on the pole at a dead centre, a ≡ c ≡ s4 when a rod only
  // translates) get one label "a, c, s4", as a draftsman writes them, not letters on letters.
  function spots(entries, tol) {
    const out = [];
    for (const [nm, p, hi] of entries) {
      const g = out.find((x) => Math.hypot(x.p[0] - p[0], x.p[1] - p[1]) <= tol);
      if (g) { g.names.push(nm); g.hi = g.hi || hi; } else out.push({names: [nm], p: p, hi: hi});
    }
    return out;
  }
  function defs(svg) {
    const d = el(svg, "defs", {});
    for (const [id, cls] of [["arr", "arrow"], ["arr-hi", "arrow hi"], ["arr-bad", "arrow bad"]]) {
      const m = el(d, "marker", {id: svg.id + "-" + id, viewBox: "0 0 10 10", refX: "10", refY: "5",
        markerWidth: "6", markerHeight: "6", orient: "auto-start-reverse", markerUnits: "strokeWidth"});
      el(m, "path", {d: "M0,1 L10,5 L0,9 z", class: cls});
    }
  }

  // ---------------------------------------------------------------- the scheme
  function lerp(a, b, f) { return [a[0] + (b[0] - a[0]) * f, a[1] + (b[1] - a[1]) * f]; }
  function at(track, t) {
    const n = track.length;
    if (n === 1) return track[0];
    const i = Math.floor(t) % n, f = t - Math.floor(t);
    return lerp(track[i], track[(i + 1) % n], f);
  }
  function angleAt(track, t) {
    const n = track.length;
    if (n === 1) return track[0];
    const i = Math.floor(t) % n, f = t - Math.floor(t);
    let a = track[i], b = track[(i + 1) % n];
    while (b - a > 180) b -= 360;
    while (a - b > 180) b += 360;
    return a + (b - a) * f;
  }
  function drawScheme(svg, S, t, marks, links, size, arms) {
    clear(svg);
    defs(svg);
    const u = size / 100;
    const P = (nm) => at(S.points[nm], t);
    for (const g of S.guides) {
      el(svg, "line", {x1: f3(g.from[0]), y1: f3(-g.from[1]), x2: f3(g.to[0]), y2: f3(-g.to[1]), class: "guide",
        "stroke-width": f3(0.3 * u)});
    }
    for (const lk of S.links) {
      const pts = lk.points.map(P);
      if (pts.length < 2) continue;
      const hi = links.indexOf(lk.id) >= 0;
      const d = pts.map((p, k) => (k ? "L" : "M") + f3(p[0]) + "," + f3(-p[1])).join(" ") + (pts.length > 2 ? " Z" : "");
      el(svg, "path", {d: d, class: "link" + (hi ? " hi" : ""), "stroke-width": f3((hi ? 1.1 : 0.7) * u),
        "data-link": lk.id});
    }
    for (const s of S.sliders) {
      const p = P(s.point), a = angleAt(s.angle_deg, t);
      const hi = links.indexOf(s.link) >= 0;
      el(svg, "rect", {x: f3(p[0] - 5 * u), y: f3(-p[1] - 3 * u), width: f3(10 * u), height: f3(6 * u),
        class: "slider" + (hi ? " hi" : ""), "stroke-width": f3(0.6 * u),
        transform: "rotate(" + f3(-a) + " " + f3(p[0]) + " " + f3(-p[1]) + ")"});
    }
    for (const nm of S.frame_points) {
      const p = P(nm);
      el(svg, "path", {d: "M" + f3(p[0]) + "," + f3(-p[1]) + " l" + f3(-3 * u) + "," + f3(5 * u) + " h" + f3(6 * u) + " z",
        class: "ground", "stroke-width": f3(0.4 * u)});
    }
    for (const nm in S.points) {
      const p = P(nm), hi = marks.indexOf(nm) >= 0;
      el(svg, "circle", {id: svg.id + "-joint-" + nm, cx: f3(p[0]), cy: f3(-p[1]), r: f3((hi ? 1.8 : 1.1) * u),
        class: "joint" + (hi ? " hi" : ""), "stroke-width": f3(0.35 * u)});
      el(svg, "text", {x: f3(p[0] + 2 * u), y: f3(-p[1] - 2 * u), "font-size": f3(4 * u), class: "label" + (hi ? " hi" : "")}, nm);
    }
    // a moment equation: each known force's line and its arm h from the point the moments are about
    for (const a of arms || []) {
      if (Math.hypot(a.foot[0] - a.at[0], a.foot[1] - a.at[1]) > 0.2 * u) {
        el(svg, "line", {x1: f3(a.at[0]), y1: f3(-a.at[1]), x2: f3(a.foot[0]), y2: f3(-a.foot[1]), class: "fline",
          "stroke-width": f3(0.3 * u)});
      }
      el(svg, "line", {x1: f3(a.about[0]), y1: f3(-a.about[1]), x2: f3(a.foot[0]), y2: f3(-a.foot[1]), class: "arm",
        "stroke-width": f3(0.6 * u), "data-arm": a.label});
      el(svg, "circle", {cx: f3(a.foot[0]), cy: f3(-a.foot[1]), r: f3(0.7 * u), class: "armfoot"});
      // the label just past the foot, along the arm: arms from one point part their labels
      const dx = a.foot[0] - a.about[0], dy = a.foot[1] - a.about[1], d = Math.hypot(dx, dy) || 1;
      const m = [a.foot[0] + 2.5 * u * dx / d, a.foot[1] + 2.5 * u * dy / d];
      el(svg, "text", {x: f3(m[0]), y: f3(-m[1]), "font-size": f3(3.6 * u), class: "armlabel",
        "text-anchor": dx < 0 ? "end" : "start", "dominant-baseline": "middle"}, lab("h_" + a.label));
    }
  }
  function schemeBox(S, withArms) {
    const pts = [];
    for (const nm in S.points) for (const p of S.points[nm]) pts.push(p);
    for (const g of S.guides) pts.push(g.from, g.to);
    if (withArms) for (const s of L.steps) for (const a of s.arms || []) pts.push(a.foot);  // an arm may reach past the links
    return pts;
  }

  // ---------------------------------------------------------------- a plan, step by step
  function drawPanel(svg, panel, upto, fresh, mistake) {
    clear(svg);
    defs(svg);
    const pts = Object.values(panel.points);
    if (mistake) for (const k in mistake.moved) pts.push(mistake.moved[k]);
    const size = fit(svg, pts, 12);
    const u = size / 100;
    const shown = upto.points, segs = upto.segments, lines = upto.lines;
    for (const k of lines) {
      const ln = panel.lines[k], R = size * 1.5;
      const hi = fresh.lines.indexOf(k) >= 0;
      el(svg, "line", {x1: f3(ln.point[0] - R * ln.dir[0]), y1: f3(-(ln.point[1] - R * ln.dir[1])),
        x2: f3(ln.point[0] + R * ln.dir[0]), y2: f3(-(ln.point[1] + R * ln.dir[1])),
        class: "cline" + (hi ? " hi" : ""), "stroke-width": f3(0.25 * u), "data-line": k});
    }
    for (const k of segs) {
      const s = panel.segments[k], a = panel.points[s.from], b = panel.points[s.to];
      const hi = fresh.segments.indexOf(k) >= 0;
      const bad = mistake && mistake.highlight && mistake.highlight.indexOf(s.label) >= 0;
      if (Math.hypot(b[0] - a[0], b[1] - a[1]) < 1e-6) continue;
      el(svg, "line", {x1: f3(a[0]), y1: f3(-a[1]), x2: f3(b[0]), y2: f3(-b[1]),
        class: "seg " + (KIND[s.kind] || "abs") + (hi ? " hi" : "") + (bad ? " bad" : ""),
        "stroke-width": f3((hi ? 0.9 : 0.6) * u), "marker-end": "url(#" + svg.id + (bad ? "-arr-bad" : hi ? "-arr-hi" : "-arr") + ")",
        "data-seg": s.label});
      const m = [(a[0] + b[0]) / 2, (a[1] + b[1]) / 2];
      el(svg, "text", {x: f3(m[0] + 1.5 * u), y: f3(-m[1] - 1.5 * u), "font-size": f3(3.2 * u), class: "seglabel"}, lab(s.label));
    }
    const named = [];
    for (const nm of shown) {
      if (nm.endsWith(">")) continue;  // a force's tip on the lever: its arrow and label say it
      const p = panel.points[nm], hi = fresh.points.indexOf(nm) >= 0;
      el(svg, "circle", {cx: f3(p[0]), cy: f3(-p[1]), r: f3((hi ? 1.4 : 0.9) * u), class: "pt" + (hi ? " hi" : ""),
        "data-point": nm});
      named.push([nm, p, hi]);
    }
    for (const g of spots(named, 1.5 * u)) {
      el(svg, "text", {x: f3(g.p[0] + 1.8 * u), y: f3(-g.p[1] + 4.2 * u), "font-size": f3(4 * u),
        class: "label" + (g.hi ? " hi" : "")}, g.names.map(pt).join(", "));
    }
    if (mistake) {
      for (const nm in mistake.moved) {
        const w = mistake.moved[nm], r = mistake.right[nm] || w;
        el(svg, "line", {x1: f3(r[0]), y1: f3(-r[1]), x2: f3(w[0]), y2: f3(-w[1]), class: "wrong",
          "stroke-width": f3(0.5 * u), "marker-end": "url(#" + svg.id + "-arr-bad)"});
        el(svg, "circle", {cx: f3(w[0]), cy: f3(-w[1]), r: f3(1.6 * u), class: "wrongpt", "stroke-width": f3(0.4 * u),
          "data-wrong": nm});
        el(svg, "text", {x: f3(w[0] + 2 * u), y: f3(-w[1] - 2 * u), "font-size": f3(4 * u), class: "label bad"}, nm + "′");
      }
    }
  }

  // ---------------------------------------------------------------- step-by-step state
  let cur = 0;
  const steps = L.steps;
  const panelsById = {};
  for (const p of L.panels) panelsById[p.id] = p;
  const schemeSize = fit($("scheme"), schemeBox(L.scheme, true), 12);
  let mistakeOn = null;

  function revealed(n) {
    const pid = steps[n].panel, acc = {points: [panelsById[pid].pole], segments: [], lines: []};
    for (let k = 0; k <= n; k++) {
      if (steps[k].panel !== pid) continue;
      acc.points.push(...steps[k].points);
      acc.segments.push(...steps[k].segments);
      acc.lines.push(...steps[k].lines);
    }
    return acc;
  }
  function panelTitle(p) {
    if (p.id === "crank") return T.panel_titles.crank;
    return (T.panel_titles[p.kind] || p.title) + (p.id.startsWith("group") ? " " + p.id.slice(6) : "");
  }
  function tabs() {
    const bar = $("tabs");
    bar.textContent = "";
    for (const p of L.panels) {
      const first = steps.findIndex((s) => s.panel === p.id);
      const b = document.createElement("button");
      b.textContent = panelTitle(p);
      b.className = steps[cur].panel === p.id ? "tab on" : "tab";
      b.onclick = () => go(first);
      bar.appendChild(b);
    }
  }
  function go(n) {
    cur = Math.max(0, Math.min(steps.length - 1, n));
    const s = steps[cur], panel = panelsById[s.panel];
    const m = mistakeOn && mistakeOn.panel === s.panel ? mistakeOn : null;
    drawPanel($("panel"), panel, revealed(cur), s, m);
    drawScheme($("scheme"), L.scheme, 0, s.scheme, s.links, schemeSize, s.arms);
    $("counter").textContent = (cur + 1) + " / " + steps.length;
    $("step-text").textContent = lab(s.text);
    $("panel-title").textContent = panelTitle(panel) + ", μ = " + nf(panel.scale, 4) + " " + unit(panel.unit);
    $("back").disabled = cur === 0;
    $("next").disabled = cur === steps.length - 1;
    document.body.dataset.step = String(cur);
    tabs();
  }
  function mistakesBox() {
    const box = $("mistakes");
    if (!L.mistakes.length) { box.hidden = true; return; }
    for (const m of L.mistakes) {
      const row = document.createElement("label");
      const cb = document.createElement("input");
      cb.type = "checkbox";
      cb.id = "mistake-" + m.id;
      cb.onchange = () => {
        for (const o of box.querySelectorAll("input")) if (o !== cb) o.checked = false;
        mistakeOn = cb.checked ? m : null;
        $("mistake-text").textContent = cb.checked ? lab(m.text) : "";
        if (cb.checked) {
          let last = -1;
          steps.forEach((s, k) => { if (s.panel === m.panel) last = k; });
          go(last);
        } else go(cur);
      };
      row.appendChild(cb);
      row.appendChild(document.createTextNode(" " + (T.mistakes[m.id] || m.title)));
      box.appendChild(row);
    }
  }

  // ---------------------------------------------------------------- the cycle
  const C = L.cycle, N = C.phi_deg.length;
  let t = 0, playing = false, last = 0;
  const cycSize = fit($("cyc-scheme"), schemeBox(C.scheme), 10);
  $("cyc-scheme").dataset.muL = String(C.scheme.mu_l);
  $("cyc-vel").parentNode.hidden = !C.velocity;
  $("cyc-acc").parentNode.hidden = !C.acceleration;
  {  // the panels the scene has share the row (no empty column where a plan is not asked for)
    const n = 1 + !!C.velocity + !!C.acceleration;
    if (n < 3) $("cyc-scheme").parentNode.parentNode.classList.add(n === 2 ? "two" : "one");
  }
  makeCharts();
  // A plan's longest vector changes manyfold over a turn (a quick return's peak): each frame
  // fills its panel, like the force polygons, with a scale bar of a round value.
  function drawCyclePlan(svg, images, mu, un, pole) {
    clear(svg);
    defs(svg);
    const pts = [[0, 0]];
    for (const nm in images) pts.push(at(images[nm], t));
    const box = square(svg, pts), u = box[2] / 100;
    for (const lk of C.scheme.links) {
      const pts = lk.points.map((nm) => images[nm.toLowerCase()]).filter((x) => x).map((tr) => at(tr, t));
      if (pts.length < 2) continue;
      const d = pts.map((p, k) => (k ? "L" : "M") + f3(p[0]) + "," + f3(-p[1])).join(" ") + (pts.length > 2 ? " Z" : "");
      el(svg, "path", {d: d, class: "seg rel", "stroke-width": f3(0.4 * u), fill: "none"});
    }
    const named = [];
    for (const nm in images) {
      const p = at(images[nm], t);
      if (Math.hypot(p[0], p[1]) > 1e-6) {
        el(svg, "line", {id: svg.id + "-" + nm, x1: "0", y1: "0", x2: f3(p[0]), y2: f3(-p[1]), class: "seg abs",
          "stroke-width": f3(0.5 * u),
          "marker-end": "url(#" + svg.id + "-arr)"});
      }
      named.push([nm, p, false]);
    }
    for (const g of spots(named, 1.5 * u)) {
      el(svg, "text", {x: f3(g.p[0] + 1.5 * u), y: f3(-g.p[1] - 1.5 * u), "font-size": f3(4.5 * u), class: "label"},
        g.names.join(", "));
    }
    el(svg, "circle", {cx: "0", cy: "0", r: f3(1.2 * u), class: "pt"});
    el(svg, "text", {x: f3(-6 * u), y: f3(5 * u), "font-size": f3(4.5 * u), class: "label"}, pt(pole));
    scaleBar(svg, box, mu, u, un);
  }
  function interp(xs, ys, x) {
    const n = xs.length;
    if (x <= xs[0]) return ys[0];
    if (x >= xs[n - 1]) return ys[n - 1];
    let lo = 0, hi = n - 1;
    while (hi - lo > 1) { const m = (lo + hi) >> 1; if (xs[m] <= x) lo = m; else hi = m; }
    const f = (x - xs[lo]) / (xs[hi] - xs[lo] || 1);
    return ys[lo] + (ys[hi] - ys[lo]) * f;
  }
  function makeCharts() {
    const box = $("cyc-charts");
    (C.charts || []).forEach((ch, k) => {
      const fig = document.createElement("figure");
      const cap = document.createElement("figcaption");
      cap.textContent = lab(ch.label) + ", " + unit(ch.unit);
      fig.appendChild(cap);
      const svg = document.createElementNS(NS, "svg");
      svg.id = "chart-" + k;
      svg.setAttribute("class", "chart");
      fig.appendChild(svg);
      box.appendChild(fig);
    });
  }
  function drawCharts() {
    const phi = (((t % N) + N) % N) * (360 / N);
    (C.charts || []).forEach((ch, k) => {
      const svg = $("chart-" + k);
      clear(svg);
      const W = 200, H = 60, xs = ch.phi_deg, ys = ch.values, x0 = xs[0];
      let lo = Math.min(0, ...ys), hi = Math.max(0, ...ys);
      if (ch.nodes) { lo = Math.min(lo, ...ch.nodes); hi = Math.max(hi, ...ch.nodes); }
      if (hi - lo < 1e-12 * Math.max(1, Math.abs(hi))) hi = lo + 1;
      svg.setAttribute("viewBox", "-4 -9 " + (W + 8) + " " + (H + 14));
      const X = (p) => ((p - x0) / 360) * W, Y = (v) => H - ((v - lo) / (hi - lo)) * H;
      el(svg, "line", {x1: "0", y1: f3(Y(0)), x2: String(W), y2: f3(Y(0)), class: "axis", "stroke-width": "0.3"});
      el(svg, "path", {d: ys.map((v, i) => (i ? "L" : "M") + f3(X(xs[i])) + "," + f3(Y(v))).join(" "),
        class: "curve", "stroke-width": "0.6", fill: "none"});
      if (ch.nodes) ch.nodes.forEach((v, i) => {
        el(svg, "circle", {cx: f3(X(ch.nodes_deg[i])), cy: f3(Y(v)), r: "1.1", class: "node"});
      });
      let p = phi;
      while (p < x0) p += 360;
      while (p >= x0 + 360) p -= 360;
      const v = interp(xs, ys, p);
      el(svg, "line", {id: "cursor-" + k, x1: f3(X(p)), y1: "0", x2: f3(X(p)), y2: String(H), class: "cursor",
        "stroke-width": "0.6"});
      el(svg, "circle", {cx: f3(X(p)), cy: f3(Y(v)), r: "1.4", class: "pt hi"});
      el(svg, "text", {x: "1", y: "-3", "font-size": "5.5", class: "label", "data-value": String(v)},
        lab(ch.label) + "(" + fixed(p, 1) + "°) = " + nf(v, 5) + " " + unit(ch.unit));
    });
  }
  // ---------------------------------------------------------------- forces over the cycle
  const F = C.forces || [];
  function segAt(track) {
    const i = Math.floor(t) % N, f = t - Math.floor(t), a = track[i], b = track[(i + 1) % N];
    if (a && b) return [a[0] + (b[0] - a[0]) * f, a[1] + (b[1] - a[1]) * f, a[2] + (b[2] - a[2]) * f, a[3] + (b[3] - a[3]) * f];
    return f < 0.5 ? a || b : b || a;
  }
  function ptAt(track) {
    const i = Math.floor(t) % N, f = t - Math.floor(t), a = track[i], b = track[(i + 1) % N];
    if (a && b) return lerp(a, b, f);
    return f < 0.5 ? a || b : b || a;
  }
  function makeForces() {
    const box = $("cyc-forces");
    for (const fp of F) {
      const fig = document.createElement("figure");
      const cap = document.createElement("figcaption");
      cap.textContent = panelTitle(fp) + ", μ = " + nf(fp.scale, 4) + " " + unit(fp.unit);
      fig.appendChild(cap);
      const svg = document.createElementNS(NS, "svg");
      svg.id = "cyc-f-" + fp.id;
      svg.setAttribute("role", "img");
      svg.dataset.mu = String(fp.scale);
      if (fp.force_scale) svg.dataset.muF = String(fp.force_scale);
      fig.appendChild(svg);
      box.appendChild(fig);
    }
    box.hidden = !F.length;
  }
  // A polygon's forces change tenfold over a turn (the gas force): each frame is shown
  // filling its square panel, with a scale bar of a round force saying how big it is.
  function square(svg, pts) {
    let x0 = 0, y0 = 0, x1 = 0, y1 = 0;
    for (const [x, y] of pts) { x0 = Math.min(x0, x); x1 = Math.max(x1, x); y0 = Math.min(y0, -y); y1 = Math.max(y1, -y); }
    const side = Math.max(x1 - x0, y1 - y0, 1e-3) * 1.3, cx = (x0 + x1) / 2, cy = (y0 + y1) / 2;
    // a strip under the drawing holds the scale bar (CSS keeps the panel at this aspect)
    svg.setAttribute("viewBox", [cx - side / 2, cy - side / 2, side, side * 1.12].map(f3).join(" "));
    return [cx - side / 2, cy - side / 2, side];
  }
  function scaleBar(svg, box, mu, u, un = "N") {
    const want = 0.25 * box[2] / mu;  // a quarter of the panel, in newtons
    const k = Math.pow(10, Math.floor(Math.log10(want)));
    const F0 = [5, 2, 1].map((m) => m * k).find((x) => x <= want) || k;
    const x = box[0] + 0.04 * box[2], y = box[1] + box[2] * 1.09;
    el(svg, "line", {x1: f3(x), y1: f3(y), x2: f3(x + F0 * mu), y2: f3(y), class: "seg", "stroke-width": f3(0.6 * u),
      "data-bar": String(F0)});
    el(svg, "text", {x: f3(x), y: f3(y - 1.5 * u), "font-size": f3(4.5 * u), class: "label"},
      nf(F0, 6) + " " + unit(un));
  }
  function drawForces() {
    for (const fp of F) {
      const svg = $("cyc-f-" + fp.id);
      clear(svg);
      defs(svg);
      const P = {}, E = fp.segments.map((s) => segAt(s.track)), pts = [[0, 0]];
      for (const nm in fp.points || {}) { P[nm] = ptAt(fp.points[nm]); if (P[nm]) pts.push(P[nm]); }
      let mu = fp.force_scale || fp.scale;
      if (fp.points) {  // the lever's arrows: the longest a third of the lever, whatever the turn
        let reach = 0, longest = 0;
        for (const nm in P) if (P[nm]) reach = Math.max(reach, Math.hypot(P[nm][0], P[nm][1]));
        for (const e of E) if (e) longest = Math.max(longest, Math.hypot(e[2] - e[0], e[3] - e[1]));
        const g = longest > 0 && reach > 0 ? reach / 3 / longest : 1;
        E.forEach((e, k) => { if (e) E[k] = [e[0], e[1], e[0] + (e[2] - e[0]) * g, e[1] + (e[3] - e[1]) * g]; });
        mu *= g;
      }
      for (const e of E) if (e) pts.push([e[0], e[1]], [e[2], e[3]]);
      const box = square(svg, pts), u = box[2] / 100;
      if (fp.points) {  // the lever: the turned velocity plan, its links as a rigid figure
        for (const lk of C.scheme.links) {
          const pts = lk.points.map((nm) => P[nm.toLowerCase()] || (C.scheme.frame_points.indexOf(nm) >= 0 ? [0, 0] : null))
            .filter((x) => x);
          if (pts.length < 2) continue;
          const d = pts.map((p, k) => (k ? "L" : "M") + f3(p[0]) + "," + f3(-p[1])).join(" ") + (pts.length > 2 ? " Z" : "");
          el(svg, "path", {d: d, class: "lever", "stroke-width": f3(0.5 * u)});
        }
        const named = [];
        for (const nm in P) {
          const p = P[nm];
          if (!p) continue;
          el(svg, "circle", {id: svg.id + "-pt-" + nm, cx: f3(p[0]), cy: f3(-p[1]), r: f3(0.9 * u), class: "pt"});
          named.push([nm, p, false]);
        }
        for (const g of spots(named, 1.5 * u)) {
          el(svg, "text", {x: f3(g.p[0] - 5.5 * u), y: f3(-g.p[1] - 1.5 * u), "font-size": f3(5.5 * u), class: "label"},
            g.names.join(", "));
        }
      }
      fp.segments.forEach((s, k) => {
        const e = E[k];
        if (!e || Math.hypot(e[2] - e[0], e[3] - e[1]) < 1e-6) return;
        el(svg, "line", {id: svg.id + "-seg-" + k, x1: f3(e[0]), y1: f3(-e[1]), x2: f3(e[2]), y2: f3(-e[3]),
          class: "seg " + (KIND[s.kind] || "abs"), "stroke-width": f3(0.8 * u), "marker-end": "url(#" + svg.id + "-arr)",
          "data-seg": s.label});
        const lx = fp.points ? e[2] : (e[0] + e[2]) / 2, ly = fp.points ? e[3] : (e[1] + e[3]) / 2;
        el(svg, "text", {x: f3(lx + 1.2 * u), y: f3(-ly - 1.2 * u), "font-size": f3(5 * u), class: "seglabel"}, lab(s.label));
      });
      el(svg, "circle", {cx: "0", cy: "0", r: f3(1.1 * u), class: "pt"});
      el(svg, "text", {x: f3(-6 * u), y: f3(5.5 * u), "font-size": f3(5.5 * u), class: "label"}, fp.points ? "p" : "o");
      scaleBar(svg, box, mu, u);
    }
  }
  makeForces();

  function drawCycle() {
    drawScheme($("cyc-scheme"), C.scheme, t, [], [], cycSize);
    if (C.velocity) drawCyclePlan($("cyc-vel"), C.velocity, C.mu_v, "m/s", "p_v");
    if (C.acceleration) drawCyclePlan($("cyc-acc"), C.acceleration, C.mu_a, "m/s²", "p_a");
    drawCharts();
    drawForces();
    const phi = ((Math.floor(t) % N) + (t - Math.floor(t))) * (360 / N);
    $("phi-out").textContent = "φ = " + fixed(phi, 1) + "°";
    $("phi").value = String(t);
  }
  function frame(now) {
    if (!playing) return;
    const dt = Math.min(0.1, (now - last) / 1000);
    last = now;
    t = (t + dt * N / 6) % N;  // one turn in six seconds
    drawCycle();
    requestAnimationFrame(frame);
  }
  function play(on) {
    playing = on;
    $("play").textContent = on ? T.pause : T.play;
    if (on) { last = performance.now(); requestAnimationFrame(frame); }
  }

  // ---------------------------------------------------------------- wiring
  function mode(which) {
    $("steps-view").hidden = which !== "steps";
    $("cycle-view").hidden = which !== "cycle";
    $("mode-steps").className = which === "steps" ? "on" : "";
    $("mode-cycle").className = which === "cycle" ? "on" : "";
    if (which === "cycle") drawCycle(); else play(false);
  }
  $("next").onclick = () => go(cur + 1);
  $("back").onclick = () => go(cur - 1);
  $("mode-steps").onclick = () => mode("steps");
  $("mode-cycle").onclick = () => mode("cycle");
  $("phi").max = String(N);
  $("phi").oninput = () => { t = Math.min(parseFloat($("phi").value), N - 1e-9); drawCycle(); };
  $("play").onclick = () => play(!playing);
  document.addEventListener("keydown", (e) => {
    if (e.target && e.target.tagName === "INPUT" && e.target.type === "range") return;
    if (!$("steps-view").hidden) {
      if (e.key === "ArrowRight" || e.key === "PageDown" || e.key === " ") { go(cur + 1); e.preventDefault(); }
      if (e.key === "ArrowLeft" || e.key === "PageUp") { go(cur - 1); e.preventDefault(); }
      if (e.key === "Home") go(0);
      if (e.key === "End") go(steps.length - 1);
    } else {
      if (e.key === "ArrowRight") { t = (t + 1) % N; drawCycle(); }
      if (e.key === "ArrowLeft") { t = (t - 1 + N) % N; drawCycle(); }
      if (e.key === " ") { play(!playing); e.preventDefault(); }
    }
  });
  mistakesBox();
  if (steps.length) go(0);
  else { $("mode-steps").disabled = true; mode("cycle"); }  // a scene that asks for positions only
  window.plansDemo = {go: go, step: () => cur, steps: steps.length, setPhi: (x) => { t = x; drawCycle(); }, mode: mode};
  document.body.dataset.readyMs = String(Math.round(performance.now()));  // since navigation began
  document.body.dataset.ready = "1";
})();
