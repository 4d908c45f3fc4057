"""The synthesis sheet: the construction (the extreme positions, the overlap angle θ, the
circle on whose arc the chord subtends θ and the chosen pivot, the position of the least
transmission angle) and the table of the design (given, found, measured back)."""

from __future__ import annotations

import cmath
import math
from dataclasses import dataclass
from pathlib import Path

import numpy as np

from drawings.linkage.panels import STANDARD_RATIOS, Panel, finish, ratio_text
from drawings.paper.backend import CENTRE_LINE, HAIR, MAIN, THICK, THIN, Pt, Recording, Style
from drawings.paper.common import dot, fmt
from drawings.paper.fonts import choose, drawing
from drawings.paper.i18n import lookup
from drawings.paper.sheet import GAP, TB_H, Sheet, SheetSpec, compose, sheet_spec, usable
from drawings.paper.text import layout
from plans.synthesis.design import Design, choice_text, stroke_of
from plans.synthesis.model import Task
from plans.synthesis.proof import Coulisse, FourBar, Slider
from plans.synthesis.solution import DesignSolution, solve_task

SMALL = 2.5
LABEL = 3.5
CONSTRUCT = Style(width=0.25, stroke="#1f5fbf")
CIRCLE = Style(width=0.25, stroke="#1f5fbf", dash=(6.0, 1.5, 1.0, 1.5))
AXIS = CENTRE_LINE
WORST = Style(width=0.35, stroke="#c00000", dash=(3.0, 1.2))
FAR = Style(width=0.5, stroke="#555")

WORDS = {
    "construction": ("Крайние положения, угол перекрытия θ", "Extreme positions, overlap angle θ"),
    "table": ("Задано, найдено, проверено", "Given, found, measured back"),
    "quantity": ("Величина", "Quantity"),
    "given": ("Задано", "Given"),
    "found": ("Найдено", "Found"),
    "measured": ("Проверено по механизму", "Measured back"),
    "motion": ("Перемещение выходного звена и его аналог скорости за оборот кривошипа",
               "The output's travel and its velocity analogue over a crank turn"),
    "gamma": ("Угол передачи за оборот кривошипа", "The transmission angle over a crank turn"),
    "working": ("рабочий ход", "working stroke"),
    "return": ("холостой ход", "return stroke"),
}
_w = lookup(WORDS)


@dataclass(frozen=True)
class Drawing:
    design: Design
    spec: SheetSpec
    panels: tuple[Panel, ...]
    sheets: tuple[Sheet, ...]


def _scale(size_m: float, target_mm: float) -> float:
    """The largest standard scale (paper mm per m) drawing ``size_m`` within ``target_mm``."""
    for r in STANDARD_RATIOS:
        if r * 1000.0 * size_m <= target_mm:
            return r * 1000.0
    return STANDARD_RATIOS[-1] * 1000.0


def _text(rec: Recording, s: str, p: Pt, size: float = LABEL, anchor: str = "start", valign: str = "middle",
          eid: str = "", fill: str = "#000") -> None:
    rec.text(layout(s, p[0], p[1], size, anchor, valign), "label", eid, fill=fill)


def _links(d: Design, p: dict[str, complex]) -> list[tuple[str, str]]:
    if d.model == "v_engine":
        return [("O", "A"), ("A", "B"), ("A", "C")]
    if d.model in ("crank_rocker", "three_positions"):
        return [("O", "A"), ("A", "B"), ("D", "B")]
    if d.model == "coulisse":
        return [("O", "A"), ("C", "D"), ("D", "E")]
    return [("O", "A"), ("A", "B")]


def construction_panel(ds: DesignSolution, lang: str, target: float, mu: float | None = None) -> Panel:
    """The construction at the largest standard scale drawing it within ``target`` mm (or at
    ``mu``, paper mm per m)."""
    d = ds.design
    t = d.task
    m0 = d.measured[0]
    fixed = {"O": 0j, **{k: v for k, v in d.points.items() if k in ("D", "C")}}
    pos1 = {**fixed, **ds.joints(m0.phi_start)}
    pos2 = {**fixed, **ds.joints(m0.phi_end)}
    worst = {**fixed, **ds.joints(m0.phi_gamma)}
    pts = list(pos1.values()) + list(pos2.values()) + list(worst.values())
    xs = [z.real for z in pts]
    ys = [z.imag for z in pts]
    box = (min(xs), min(ys), max(xs), max(ys))
    span = max(box[2] - box[0], box[3] - box[1], 1e-9)
    circ = d.circle
    if circ is not None and circ[1] < 1.2 * span:  # the circle whole when it is not far bigger
        c, R = circ
        box = (min(box[0], c.real - R), min(box[1], c.imag - R), max(box[2], c.real + R), max(box[3], c.imag + R))
        span = max(box[2] - box[0], box[3] - box[1])
    if mu is None:
        mu = _scale(span * 1.15, target)
    rec = Recording()

    def P(z: complex) -> Pt:
        return (mu * z.real, -mu * z.imag)

    pad = 0.06 * span
    lo = complex(box[0] - pad, box[1] - pad)
    hi = complex(box[2] + pad, box[3] + pad)
    # the construction's circle (the part within the drawing when it is large) and its centre
    if circ is not None:
        c, R = circ
        n = 720
        run: list[Pt] = []
        for k in range(n + 1):
            z = c + R * cmath.exp(2j * math.pi * k / n)
            if lo.real <= z.real <= hi.real and lo.imag <= z.imag <= hi.imag:
                run.append(P(z))
            elif run:
                if len(run) > 1:
                    rec.polyline(run, CIRCLE, "construction-circle")
                run = []
        if len(run) > 1:
            rec.polyline(run, CIRCLE, "construction-circle")
        if lo.real <= c.real <= hi.real and lo.imag <= c.imag <= hi.imag:
            dot(rec, P(c), 0.5, "circle-centre")
            _text(rec, "O₁", (P(c)[0] + 1.5, P(c)[1] + 1.5), SMALL, valign="top")
    # the guides and the crank's circle
    l1 = d.lengths["crank"]
    rec.circle(P(0j), mu * l1, HAIR, "crank-circle")
    for i, m in enumerate(d.mechs):
        if isinstance(m, Slider | Coulisse):
            g0, u = m.G0, m.u
            s = [((z - g0) * u.conjugate()).real for z in (lo, hi, complex(lo.real, hi.imag), complex(hi.real, lo.imag))]
            rec.line(P(g0 + min(s) * u), P(g0 + max(s) * u), AXIS, f"guide-{i}")
    # the extreme positions: the links thick, the far one grey; the points labelled ′ and ″
    # (a V-engine: each cylinder's own)
    sets: list[tuple[dict[str, complex], dict[str, complex], list[tuple[str, str]], tuple[str, ...] | None]] = [
        (pos1, pos2, _links(d, pos1), None)]
    if d.model == "v_engine":
        m1 = d.measured[1]
        sets = [(pos1, pos2, [("O", "A"), ("A", "B")], ("A", "B")),
                ({**fixed, **ds.joints(m1.phi_start)}, {**fixed, **ds.joints(m1.phi_end)},
                 [("O", "A"), ("A", "C")], ("C",))]
    for i, (p1, p2, links, names) in enumerate(sets):
        for pos, style, mark in ((p1, THICK, "′"), (p2, FAR, "″")):
            for a, b in links:
                rec.line(P(pos[a]), P(pos[b]), style, f"link-{a}{b}-{i}{'1' if mark == '′' else '2'}")
            for name, z in pos.items():
                if name in fixed or (names is not None and name not in names):
                    continue
                dot(rec, P(z), 0.6)
                _text(rec, f"{name}{mark}", (P(z)[0] + 1.8, P(z)[1] - 1.8), LABEL, valign="bottom")
    for name, z in fixed.items():
        if name != "O":  # the frame's line between the pivots
            rec.line(P(0j), P(z), THIN, f"frame-O{name}")
        dot(rec, P(z), 0.9, f"pivot-{name}")
        # beside the pivot, not below it: the pivot C is the construction's lowest point
        _text(rec, name, (P(z)[0] - 2.0, P(z)[1] + 1.0), LABEL, "end", "middle", eid=f"label-{name}")
    # the overlap angle θ at the crank's pivot: the rays to the output's extreme points
    out_pt = {"central": "B", "offset": "B", "v_engine": "B", "crank_rocker": "B", "three_positions": "B",
              "coulisse": "A"}[d.model]
    z1, z2 = pos1[out_pt], pos2[out_pt]
    if d.model == "v_engine":
        rec.line(P(z1), P(z2), CONSTRUCT, "stroke-C")
        q1, q2 = sets[1][0]["C"], sets[1][1]["C"]
        rec.line(P(q1), P(q2), CONSTRUCT, "stroke-C")
    if d.model == "coulisse":  # the coulisse at its extremes (tangent to the crank circle)
        C = d.points["C"]
        for z in (z1, z2):
            rec.line(P(C), P(C + (z - C) * (d.lengths["coulisse"] / abs(z - C))), CONSTRUCT)
        _angle(rec, P, C, z1, z2, 0.35 * abs(z1 - C),
               f"ψ = θ = {fmt(math.degrees(m0.swing or 0.0), 4, lang)}°", "psi")
        for z in (z1, z2):  # the crank at the extremes: ⟂ the coulisse
            rec.line(P(0j), P(z), CONSTRUCT, "crank-extreme")
    else:
        a1, a2 = cmath.phase(z1), cmath.phase(z2)
        if t.theta > 1e-9:
            for z in (z1, z2):
                rec.line(P(0j), P(z), CONSTRUCT, "ray")
            _angle(rec, P, 0j, z1, z2, 0.45 * min(abs(z1), abs(z2)), f"θ = {fmt(math.degrees(t.theta), 4, lang)}°",
                   "theta")
        del a1, a2
        if isinstance(d.mechs[0], FourBar):
            D = d.points["D"]
            rec.line(P(z1), P(z2), CONSTRUCT, "chord")
            _angle(rec, P, D, z1, z2, 0.3 * d.lengths["rocker"], f"ψ = {fmt(math.degrees(m0.swing or 0.0), 4, lang)}°",
                   "psi")
        else:
            rec.line(P(z1), P(z2), CONSTRUCT, "stroke")
            mid = (z1 + z2) / 2
            H = m0.stroke or 0.0
            _text(rec, f"H = {fmt(H / t.scale, 4, lang)}", (P(mid)[0], P(mid)[1] + 7.5), SMALL, "middle", "top")
    if d.model == "offset":  # the offset e: the pivot's perpendicular to the guide
        s0 = d.mechs[0]
        foot = s0.G0 + ((0j - s0.G0) * s0.u.conjugate()).real * s0.u
        rec.line(P(0j), P(foot), THIN, "offset")
        half = P(foot / 2)
        _text(rec, f"e = {fmt(d.lengths['offset'] / t.scale, 4, lang)}", (half[0] - 1.5, half[1]), SMALL, "end",
              eid="label-offset")
    # the position of the least transmission angle, dashed red, with γ_min at its joint
    for a, b in _links(d, worst):
        rec.line(P(worst[a]), P(worst[b]), WORST, f"worst-{a}{b}")
    jpt = {"central": "B", "offset": "B", "v_engine": "B", "crank_rocker": "B", "three_positions": "B",
           "coulisse": "E"}[d.model]
    g = min(x.gamma_min for x in d.measured)
    q = P(worst[jpt])
    _gamma_arc(rec, P, d, worst, jpt)
    _text(rec, f"γmin = {fmt(math.degrees(g), 4, lang)}°", (q[0] + 2.0, q[1] + 2.5), LABEL, valign="top",
          eid="gamma-min", fill="#c00000")
    # three positions: the given positions of the crank and the rocker
    if d.model == "three_positions":
        for k in (1, 2, 3):
            A, B = d.points[f"A{k}"], d.points[f"B{k}"]
            rec.line(P(0j), P(A), CONSTRUCT, f"given-crank-{k}")
            rec.line(P(d.points["D"]), P(B), CONSTRUCT, f"given-rocker-{k}")
            _text(rec, str(k), (P(B)[0] + 1.2, P(B)[1] - 1.2), SMALL, valign="bottom")
    note = f"{ratio_text(mu, lang)}; " + ("штрих — положение γmin" if lang == "ru" else "dashed red: the position of γmin")
    return finish("construction", "synthesis-construction", None, rec, _w("construction", lang), note=note,
                  quantity="length", scale=mu)


def _gamma_arc(rec: Recording, P, d: Design, pos: dict[str, complex], jpt: str) -> None:
    """The least transmission angle as an arc at its joint: between the coupler and the rocker
    (the acute one), or between the rod and the normal to the slider's guide."""
    J = pos[jpt]
    m = d.mechs[0]
    if isinstance(m, FourBar):
        a, b = pos["A"] - J, J - pos["D"]  # the rocker produced beyond B
        if (a.conjugate() * b).real < 0:
            b = -b
    elif isinstance(m, Slider):
        a = pos["A"] - J
        n = 1j * m.u
        b = n if (a.conjugate() * n).real > 0 else -n
    elif m.l4 > 0:  # the coulisse's RRP ram: the rod against the guide's normal
        a = pos["D"] - J
        n = 1j * m.u
        b = n if (a.conjugate() * n).real > 0 else -n
    else:
        return
    r = 0.25 * abs(a)
    n_ = 24
    t0, t1 = cmath.phase(a), cmath.phase(a) + math.remainder(cmath.phase(b) - cmath.phase(a), 2 * math.pi)
    rec.polyline([P(J + r * cmath.exp(1j * (t0 + (t1 - t0) * k / n_))) for k in range(n_ + 1)], WORST, "gamma-arc")
    rec.line(P(J), P(J + 1.3 * r * b / abs(b)), Style(width=0.18, stroke="#c00000"), "gamma-ray")


def _angle(rec: Recording, P, c: complex, z1: complex, z2: complex, r: float, label: str, eid: str,
           reflex: bool = False) -> None:
    """An arc at ``c`` between the rays to z1 and z2 (the smaller angle, or the larger), labelled."""
    a1, a2 = cmath.phase(z1 - c), cmath.phase(z2 - c)
    d = math.remainder(a2 - a1, 2 * math.pi)
    if reflex:
        d = d - math.copysign(2 * math.pi, d)
    n = 40
    pts = [P(c + r * cmath.exp(1j * (a1 + d * k / n))) for k in range(n + 1)]
    rec.polyline(pts, THIN, f"arc-{eid}")
    mid = P(c + (r + 0.0) * cmath.exp(1j * (a1 + d / 2)))
    _text(rec, label, (mid[0] + 1.0, mid[1]), LABEL, "start", "middle", eid=f"label-{eid}")


def _rows(ds: DesignSolution, lang: str) -> list[tuple[str, str, str, str]]:
    d = ds.design
    t = d.task
    u = {"mm": "мм", "cm": "см", "m": "м"}.get(t.unit, t.unit) if lang == "ru" else t.unit
    L = t.scale
    m = d.measured[0]
    ru = lang == "ru"

    def n(x: float, sig: int = 6) -> str:
        return fmt(x, sig, lang)

    def ln(x: float) -> str:
        return f"{n(x / L)} {u}"

    def deg(x: float, sig: int = 6) -> str:
        return f"{n(math.degrees(x), sig)}°"

    rows: list[tuple[str, str, str, str]] = []
    if d.model != "three_positions":
        rows.append(("K", n(t.K), f"θ = {deg(t.theta)}", n(m.K, 10)))
    else:
        rows.append(("K", "—", "—", n(m.K, 10)))
    if m.stroke is not None:
        given = ln(stroke_of(t)) if t.stroke is not None or t.mean_speed is not None else "—"
        rows.append(("H", given, "—", f"{n(m.stroke / L, 10)} {u}"))
    if m.swing is not None:
        given = deg(t.swing) if t.swing is not None and d.model == "crank_rocker" else "—"
        found = deg(t.theta) if d.model == "coulisse" else "—"
        rows.append(("ψ", given, found, f"{n(math.degrees(m.swing), 10)}°"))
    names = {"crank": ("l1 (OA)", "кривошип l1 (OA)"), "rod": ("l2 (AB)" if d.model != "coulisse" else "DE", "шатун")
             , "offset": ("e", "e"), "coupler": ("l2 (AB)", "шатун l2 (AB)"), "rocker": ("l3 (DB)", "коромысло l3 (DB)"),
             "frame": ("l0 (OD)", "стойка l0 (OD)"), "centre_distance": ("l0 (OC)", "l0 (OC)"),
             "coulisse": ("CD", "кулиса CD"), "guide_height": ("h", "h")}
    given_keys = {"offset": t.offset, "rocker": t.rocker, "frame": t.frame, "centre_distance": t.centre_distance,
                  "guide_height": t.guide_height, "rod": t.rod}
    for k, v in d.lengths.items():
        label = names.get(k, (k, k))[1 if ru else 0]
        if k == "rod" and d.model != "coulisse":
            label = "шатун l2 (AB)" if ru else "l2 (AB)"
        if k == "rod" and d.model == "coulisse":
            label = "шатун DE" if ru else "rod DE"
        g = given_keys.get(k)
        rows.append((label, ln(g) if g is not None else "—", ln(v) if g is None else "—", "—"))
    if d.model in ("central", "offset", "v_engine"):
        lam = d.lengths["crank"] / d.lengths["rod"]
        rows.append(("λ = l1/l2", n(t.lam) if t.lam is not None else "—", n(lam) if t.lam is None else "—", "—"))
    g = min(x.gamma_min for x in d.measured)
    if t.mechanism != "crank_rocker":
        given = deg(t.pressure_angle_max) if t.pressure_angle_max is not None else "—"
        rows.append(("ϑmax" if not ru else "ϑmax (угол давления)", given, "—", deg(math.pi / 2 - g)))
    given = deg(t.gamma_min) if t.gamma_min is not None else "—"
    rows.append(("γmin", given, "—", deg(g)))
    rows.append(("условие Грасгофа / полный оборот" if ru else "full turn, one branch",
                 "—", "—", "да" if ru else "yes"))
    if d.model == "three_positions":
        assert t.positions is not None
        for i, ((phi, psi), measured) in enumerate(zip(t.positions, ds.rocker_angles, strict=True), 1):
            rows.append((f"φ{i} → ψ{i}", f"{deg(phi)} → {deg(psi)}", "—", deg(measured, 10)))
    return rows


def table_panel(ds: DesignSolution, lang: str) -> Panel:
    d = ds.design
    rows = [(_w("quantity", lang), _w("given", lang), _w("found", lang), _w("measured", lang)), *_rows(ds, lang)]
    widths = [40.0, 34.0, 34.0, 44.0]
    h = 7.0
    rec = Recording()
    x = [0.0]
    for width in widths:
        x.append(x[-1] + width)
    for i, row in enumerate(rows):
        y = i * h
        for j, cell in enumerate(row):
            _text(rec, cell, (x[j] + 1.5, y + h / 2), SMALL, eid=f"cell-{i}-{j}")
        rec.line((0, y), (x[-1], y), MAIN if i <= 1 else HAIR)
    rec.line((0, len(rows) * h), (x[-1], len(rows) * h), MAIN)
    for xx in x:
        rec.line((xx, 0), (xx, len(rows) * h), MAIN if xx in (0.0, x[-1]) else HAIR)
    if d.choice:  # how the free choice was made, wrapped under the table
        words = (("выбор: " if lang == "ru" else "chosen: ") + choice_text(d.choice, lang)).split()
        room = int(x[-1] / (SMALL * 0.55))
        wrapped = [""]
        for w in words:
            if wrapped[-1] and len(wrapped[-1]) + 1 + len(w) > room:
                wrapped.append(w)
            else:
                wrapped[-1] = f"{wrapped[-1]} {w}".strip()
        for i, line in enumerate(wrapped):
            _text(rec, line, (0.0, len(rows) * h + 4.0 + 4.0 * i), SMALL, eid=f"choice-{i}")
    return finish("design-table", "table", None, rec, _w("table", lang))


def _output(d: Design, i: int, phi: float) -> tuple[float, float]:
    """Mechanism ``i``'s output at the crank angle ``phi`` as far as it has gone from where
    its working stroke starts (the slider's or the ram's travel in m, the rocker's swing in
    rad) and its velocity analogue along the working stroke (d/dφ of it, + while it goes out)."""
    m, mo = d.mechs[i], d.measured[i]
    if isinstance(m, FourBar):
        q, q0, q1, dq = m.psi(phi), m.psi(mo.phi_start), m.psi(mo.phi_end), m.dpsi(phi)
        gone, way = math.remainder(q - q0, 2 * math.pi), math.remainder(q1 - q0, 2 * math.pi)
    else:
        q, q0, q1, dq = m.s(phi), m.s(mo.phi_start), m.s(mo.phi_end), m.ds(phi)
        gone, way = q - q0, q1 - q0
    sign = 1.0 if way >= 0 else -1.0
    return sign * gone, sign * d.task.sense * dq  # d/d(turn) = sense·d/dφ


def motion_panel(ds: DesignSolution, lang: str, mu_phi: float, g: float = 1.0, tall: float = 1.0) -> Panel:
    """The designed mechanism over one crank turn from the start of its working stroke (the
    crank's turn at ``mu_phi`` mm per degree): the output's travel, the working and the return
    strokes' angles read off it (their ratio is K) and its velocity analogue (its zeros are
    the extreme positions): what the construction promised, seen over the whole turn.  ``tall`` lengthens the ordinates
    (their round scales the larger ones it allows) where the sheet has room."""
    from drawings.cycle.cycle_plot import Axes
    from plans.kinematics.scales import round_scale

    d, t = ds.design, ds.task
    m0 = d.measured[0]
    n = 361
    turn = [360.0 * k / (n - 1) for k in range(n)]  # degrees of the crank's turn
    phis = [m0.phi_start + t.sense * math.radians(x) for x in turn]
    rocker = isinstance(d.mechs[0], FourBar)
    u = {"mm": "мм", "cm": "см", "m": "м"}.get(t.unit, t.unit) if lang == "ru" else t.unit
    mm = "мм" if lang == "ru" else "mm"
    rad = "рад" if lang == "ru" else "rad"
    names = ["ψ"] if rocker else (["B", "C"] if d.model == "v_engine" else ["E"] if d.model == "coulisse" else ["B"])
    outs = [[_output(d, i, p) for p in phis] for i in range(len(names))]
    conv = math.degrees(1.0) if rocker else 1.0 / t.scale  # to degrees, or to the file's unit
    top = max(q for c in outs for q, _ in c) * conv or 1.0
    fast = max(abs(v) for c in outs for _, v in c) * conv or 1.0
    mu_q = round_scale(top, 80.0 * g * tall)  # mm per degree or per the file's unit
    mu_v = round_scale(fast, 40.0 * g * tall)  # mm per (degree or unit) per rad
    L = 360.0 * mu_phi
    k_phi = mu_phi * 180.0 / math.pi  # mm per rad of the crank's turn
    x_end = math.degrees(((m0.phi_end - m0.phi_start) * t.sense) % (2 * math.pi))
    rec = Recording()
    ax = Axes(rec, "motion-s", k_phi, 0.0, lang)
    xs = ax.x(np.asarray(turn))
    q_name, v_name = ("ψ", "dψ/dφ") if rocker else (("s", "ds/dφ") if len(names) == 1 else ("s_B, s_C", "ds/dφ"))
    ax.frame(L, 0.0, top * mu_q, q_name)
    for i, (name, c) in enumerate(zip(names, outs, strict=True)):
        ys = np.array([q * conv * mu_q for q, _ in c])
        ax.curve(xs, ys, MAIN if i == 0 else FAR, f"output-{i}")
        if len(names) > 1:
            k = max(range(n), key=lambda j: ys[j])
            _text(rec, f"s_{name}", (float(xs[k]) + 1.5, -ys[k] - 1.5), SMALL, valign="bottom")
    for a, b, key in ((0.0, x_end, "working"), (x_end, 360.0, "return")):
        _text(rec, f"{_w(key, lang)} {fmt(b - a, 5, lang)}°", ((a + b) / 2 * mu_phi, 5.0), SMALL, "middle", "top",
              eid=f"stroke-{key}")
    # the velocity analogue: zero at the extreme positions, + on the working stroke
    vrec = Recording()
    vax = Axes(vrec, "motion-v", k_phi, 0.0, lang)
    vax.frame(L, -fast * mu_v, fast * mu_v, v_name)
    for i, c in enumerate(outs):
        vax.curve(xs, np.array([v * conv * mu_v for _, v in c]), MAIN if i == 0 else FAR, f"analogue-{i}")
    for x in (0.0, x_end, 360.0):
        dot(vrec, (x * mu_phi, 0.0), 0.6)
    y_v = 16.0 + fast * mu_v + 6.0
    rec.prims.extend(vrec.moved(0.0, y_v).prims)
    for x in (0.0, x_end, 360.0):  # the extreme positions through both diagrams
        rec.line((x * mu_phi, -top * mu_q - 4.0), (x * mu_phi, y_v + fast * mu_v),
                 Style(width=0.18, stroke="#555", dash=(2.0, 1.0)))
    q_unit = "°" if rocker else u
    scale = (f"μ_φ = {fmt(mu_phi, 3, lang)} {mm}/°; μ_{'ψ' if rocker else 's'} = {fmt(mu_q, 3, lang)} {mm}/{q_unit}; "
             f"μ′ = {fmt(mu_v, 3, lang)} {mm}/({q_unit}/{rad})")
    note = f"K = {fmt(x_end, 5, lang)}°/{fmt(360.0 - x_end, 5, lang)}° = {fmt(m0.K, 6, lang)}"
    return finish("output-motion", "synthesis-motion", None, rec, _w("motion", lang), scale, note)


def gamma_panel(ds: DesignSolution, lang: str, mu_phi: float, g: float = 1.0, tall: float = 1.0) -> Panel:
    """The transmission angle γ over one crank turn from the start of the working stroke (at
    ``mu_phi`` mm per degree of the turn), γmin on it and the permissible one."""
    from drawings.cycle.cycle_plot import Axes
    from plans.kinematics.scales import round_scale

    d, t = ds.design, ds.task
    m0 = d.measured[0]
    n = 361
    turn = [360.0 * k / (n - 1) for k in range(n)]
    phis = [m0.phi_start + t.sense * math.radians(x) for x in turn]
    mu_g = round_scale(90.0, 90.0 * g * tall)  # mm per degree of γ
    L = 360.0 * mu_phi
    rec = Recording()
    ax = Axes(rec, "motion-g", mu_phi * 180.0 / math.pi, 0.0, lang)
    xs = ax.x(np.asarray(turn))
    ax.frame(L, 0.0, 90.0 * mu_g, "γ")
    gam = [min(m.gamma(p) for m in d.mechs) for p in phis]
    ax.curve(xs, np.degrees(gam) * mu_g, MAIN, "gamma")
    allowed = t.gamma_min if t.gamma_min is not None else (
        math.pi / 2 - t.pressure_angle_max if t.pressure_angle_max is not None else None)
    if allowed is not None:
        ax.hline(math.degrees(allowed) * mu_g, 0.0, L, WORST, f"[γ] = {fmt(math.degrees(allowed), 4, lang)}°")
    g_min = min(x.gamma_min for x in d.measured)
    k = min(range(n), key=lambda j: gam[j])
    dot(rec, (float(xs[k]), -math.degrees(g_min) * mu_g), 0.6, "gamma-min-dot")
    _text(rec, f"γmin = {fmt(math.degrees(g_min), 4, lang)}°", (float(xs[k]) + 1.5, -math.degrees(g_min) * mu_g + 2.0),
          SMALL, valign="top", eid="gamma-min-reading", fill="#c00000")
    x_end = math.degrees(((m0.phi_end - m0.phi_start) * t.sense) % (2 * math.pi))
    for x in (0.0, x_end, 360.0):  # the extreme positions
        rec.line((x * mu_phi, -90.0 * mu_g - 4.0), (x * mu_phi, 0.0), Style(width=0.18, stroke="#555", dash=(2.0, 1.0)))
    mm = "мм" if lang == "ru" else "mm"
    scale = f"μ_φ = {fmt(mu_phi, 3, lang)} {mm}/°; μ_γ = {fmt(mu_g, 3, lang)} {mm}/°"
    return finish("transmission", "synthesis-motion", None, rec, _w("gamma", lang), scale)


def _largest(ds: DesignSolution, spec: SheetSpec) -> list[Panel]:
    """The construction at the largest standard scale (and the diagrams over the turn at the
    longest round φ axis) that keep the sheet one sheet; else at the old lengths."""
    from drawings.paper.fill import fullest_on_one_sheet

    W, H = spec.size
    x0, y0, x1, y1 = usable(W, H)
    g = min(W / 841.0, H / 594.0)
    lang = spec.language
    table = table_panel(ds, lang)
    longest = max(x1 - x0, y1 - y0)
    top = construction_panel(ds, lang, longest).scale or 1000.0
    mus = [r * 1000.0 for r in STANDARD_RATIOS if r * 1000.0 <= top * (1 + 1e-9)]
    axes = [a for a in (2.0, 1.0, 0.5, 0.25) if a <= max(2 * g, 0.25) * (1 + 1e-9)]

    def candidates(mu: float):
        c = construction_panel(ds, lang, longest, mu)
        for a in axes:
            gammas = [gamma_panel(ds, lang, a, g, tall) for tall in (2.0, 1.0)]
            for tall in (2.0, 1.5, 1.0):
                motion = motion_panel(ds, lang, a, g, tall)
                for gamma in gammas:
                    yield [c, table, motion, gamma]

    found = fullest_on_one_sheet((candidates(mu) for mu in mus), spec, ds.task.path,
                                 lambda ps: ratio_text(ps[0].scale or 1000.0, lang))
    if found is not None:
        return found[0]
    wide = (x1 - x0) > (y1 - y0)
    target = min((x1 - x0) * (0.62 if wide else 0.95), (y1 - y0) - TB_H - GAP - 30.0 - (0 if wide else 90.0))
    return [construction_panel(ds, lang, target), table]


def build_panels(ds: DesignSolution, spec: SheetSpec) -> list[Panel]:
    return _largest(ds, spec)


@drawing
def draw(source: DesignSolution | Task | str | Path, *, format: str | None = None,
         orientation: str | None = None, language: str | None = None, font: str | None = None) -> Drawing:
    """The synthesis sheet of a designed task (``plans.solve``), or of a task or its file,
    designed here."""
    ds = source if isinstance(source, DesignSolution) else solve_task(source)
    t = ds.task
    d = ds.design
    raw = t.raw if "sheet" in t.raw else {"sheet": t.task.get("sheet", {})}
    from plans.language import choose as run_language

    lang = run_language(language, raw)
    title = t.raw.get("title", t.title)
    if isinstance(title, dict):
        title = title.get(lang) or t.title
    spec = sheet_spec(raw, t.path, str(title), format=format, orientation=orientation, language=language,
                      font=font)
    choose(spec.font, t.path, font)
    panels = build_panels(ds, spec)
    sheets = compose(panels, spec, ratio_text(panels[0].scale or 1000.0, spec.language), t.path)
    return Drawing(d, spec, tuple(panels), tuple(sheets))
