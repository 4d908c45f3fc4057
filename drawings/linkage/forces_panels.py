"""Force panels: each Assur group cut free with its loads and reactions, its force
polygon, the initial link with the balancing load and its polygon, the Zhukovsky
lever, and a table of the forces read off the polygons.

Reads the frozen results of :mod:`plans.forces` and :mod:`plans.lever`.
"""

from __future__ import annotations

import cmath
import math
import re
from collections.abc import Callable, Sequence
from functools import wraps
from typing import Any

import numpy as np

# the free bodies' pieces, importable from here as before
from drawings.linkage.free_body import (  # noqa: F401
    ARM,
    COUPLE_STEP_MM,
    FBD_ARROW_MM,
    LOAD,
    MIN_ARROW_MM,
    REACTION,
    draw_links,
    draw_slot,
    fbd_scale,
    force_at,
    force_label,
    label_points,
    largest_of,
    legible,
    moment_arc,
    short_mark,
    short_note,
)
from drawings.linkage.friction_marks import (
    efficiency_panels,
    efficiency_rows,
    friction_marks,
    friction_points,
)
from drawings.linkage.panels import (
    LABEL_SIZE,
    SMALL_SIZE,
    VECTOR_STYLES,
    Panel,
    clip_line,
    finish,
    on_paper,
    scale_text,
    table_panel,
)
from drawings.paper.backend import Pt, Recording, Style, Transform
from drawings.paper.common import Placer, angle, arrow, dot, fmt, ident, phi_tag
from drawings.paper.i18n import tr
from drawings.paper.text import point_label
from plans.kinematics.plan import Plan
from plans.kinematics.scales import fit
from plans.units import DUST

_MADE: dict[tuple, tuple[tuple, Panel]] = {}
_MADE_MOST = 4000


def _once(make: Callable[..., Panel]) -> Callable[..., Panel]:
    """``make`` drawing each panel once: the layout searches build a position's panels again
    at every fit the other parts try, its plans and solution the same objects.  The key: the
    numbers and words as they are, any other argument (a plan, a solution: not changed once
    solved) by identity (the entry holds it, so no identity is reused while it is kept), and
    the font the labels are measured in."""
    from drawings.paper.fonts import current

    def key(a: Any) -> Any:
        if a is None or isinstance(a, (str, int, float)):
            return a
        if isinstance(a, tuple) and all(isinstance(x, (str, int, float)) for x in a):
            return ("tuple", *a)  # a table's part
        return ("id", id(a))

    @wraps(make)
    def once(*args: Any) -> Panel:
        k = (make.__name__, current(), *map(key, args))
        hit = _MADE.get(k)
        if hit is None:
            if len(_MADE) >= _MADE_MOST:
                _MADE.clear()
            hit = _MADE[k] = (args, make(*args))
        return hit[1]

    return once


def build(sol, spec, ks: Sequence[int], plans_at: dict[int, Any], mu_l: float) -> dict:
    """Panels per position k, and ("table", k) -> extra rows for the results table."""
    if sol.forces is None:
        return {}
    scene, kin = sol.scene, sol.kinematics
    fa, lv = sol.forces
    lang, style = spec.language, scene.scale_style

    def want(kind: str) -> bool:
        return spec.panels is None or kind in spec.panels

    out: dict[Any, Any] = {}
    for k in ks:
        phi = float(kin.phi_deg[k])
        panels: list[Panel] = []
        polys = sol.force_polygons(k) if scene.wants("force_polygons") else ()
        by_group = {fp.group: fp for fp in polys}
        if scene.wants("force_polygons"):
            for gf in reversed(fa.groups):  # attachment order: nearest the crank first
                if want("group"):
                    panels.append(group_panel(scene, kin, gf, k, mu_l, lang, style, fa.friction))
                    fp = by_group.get(gf.group.name)
                    if fp is not None:
                        panels.append(polygon_panel(fp.plan, lang, style,
                                                    f"polygon-{ident(gf.group.name)}-{phi_tag(phi)}",
                                                    f"{tr('group_polygon', lang)} {gf.group.name}"))
            if want("crank"):
                panels.append(crank_panel(scene, kin, fa, k, mu_l, lang, style))
                fp = by_group.get(str(fa.crank.link))
                if fp is not None:
                    panels.append(polygon_panel(fp.plan, lang, style, f"polygon-crank-{phi_tag(phi)}",
                                                tr("crank_polygon", lang)))
        if scene.wants("lever") and want("lever") and bool(lv.valid[k]):
            vplan = plans_at[k].velocity if k in plans_at else None
            panels.append(lever_panel(sol, k, vplan, lang, style))
        if want("table") and polys:
            from drawings.linkage.table_parts import parts

            def table(part: tuple[int, int, int] | None, polys: Any = polys, phi: float = phi) -> Panel:
                return forces_table(polys, lang, style, phi, part)

            panels.extend(parts(table, spec))
        out[k] = panels
        out[("table", k)] = balancing_rows(sol, k, lang) + efficiency_rows(fa, k, lang)
    if fa.friction is not None and want("table"):  # η(φ) and its table go with the tables
        out["efficiency"] = efficiency_panels(sol.efficiency, fa, lang, min(1.0, spec.fit))
    return out


@_once
def group_panel(scene, kin, gf, k: int, mu_l: float, lang: str, style: str, friction: Any = None) -> Panel:
    """The group cut free (appendices 4–5): loads at their points, the unknown reactions
    at the outer pairs (τ and n components at a revolute), arms h of the moment equations."""
    g = gf.group
    phi = float(kin.phi_deg[k])
    pid = f"group-{ident(g.name)}-{phi_tag(phi)}"
    T = Transform(mu_l)
    rec = Recording()
    placer = Placer()
    pts = draw_links(rec, placer, scene, kin, k, g.links, T, pid)
    triad = hasattr(gf, "S")  # class III: loads per link, three outer reactions, Assur's point
    loads = [f for fs in gf.loads for f in fs] if triad else list(gf.loads_i) + list(gf.loads_j)
    moments = [m for ms in gf.moments for m in ms] if triad else list(gf.moments_i) + list(gf.moments_j)
    if triad:
        from drawings.linkage.triad_marks import special_point

        special_point(rec, placer, T, gf, k, pts, pid, LABEL_SIZE, kin)
    reacts = []
    couples: list[tuple[str, float, str]] = []
    for rc in (gf.reactions[:3] if triad else (gf.reactions[0], gf.reactions[2])):
        name = rc.name(scene.fij)
        if rc.tau is not None and rc.e_tau is not None and rc.n is not None and rc.e_n is not None:
            reacts.append((complex(rc.r[k]), complex(rc.tau[k] * rc.e_tau[k]), f"{name}^τ"))
            reacts.append((complex(rc.r[k]), complex(rc.n[k] * rc.e_n[k]), f"{name}^n"))
        else:
            at = complex(rc.r[k])
            if rc.guide is not None and float(rc.N[k]) != 0:
                off = float(rc.offset[k])
                if abs(off) * mu_l <= 40.0:  # the resultant's point, when it lies by the slider
                    at = at + off * complex(rc.guide[k])
                elif float(rc.M[k]) != 0:  # else N at the pin plus the pair's couple
                    couples.append((rc.point, float(rc.M[k]), "M" + name[1:]))
            reacts.append((at, complex(rc.F[k]), name))
    values = [complex(f.F[k]) for f in loads] + [v for _, v, _ in reacts]
    mu_f = fbd_scale(values, largest_of([f.F for f in loads] + [rc.F for rc in gf.reactions]), fit(scene))
    # arms of the moment equations
    for (eq, label), arm in gf.arms.items():
        h = float(arm[k])
        f = next((x for x in loads if x.label == label), None)
        m = re.match(r"M_(\w+)\(", eq)
        if f is None or m is None or m.group(1) not in pts or h * mu_l < 1.0:
            continue
        P = pts[m.group(1)]
        F = complex(f.F[k])
        if F == 0:
            continue
        u = F / abs(F)
        r = complex(f.r[k])
        foot = r + ((P - r) * u.conjugate()).real * u
        rec.line(T.z(P), T.z(foot), ARM, f"{pid}-arm-{ident(label)}")
        rec.line(T.z(r), T.z(foot), Style(width=0.18, stroke="#777", dash=(4.0, 1.0, 1.0, 1.0)))
        mid = T.z((P + foot) / 2)
        sub = re.sub(r"[_^{}]", "", force_label(label, lang))  # one level of script: h_{Φ2}, not h_{Φ_2}
        lab = placer.place(f"h_{{{sub}}}", mid, SMALL_SIZE, gap=0.6)
        rec.text(lab, "label arm", f"{pid}-arm-{ident(label)}-label", fill="#555")
    short = False
    for f in loads:
        short |= force_at(rec, placer, T, complex(f.r[k]), complex(f.F[k]), mu_f, force_label(f.label, lang),
                           LOAD, f"{pid}-{ident(f.label)}")
    for at, F, name in reacts:
        short |= force_at(rec, placer, T, at, F, mu_f, force_label(name, lang), REACTION, f"{pid}-{ident(name)}")
    at_pin = friction_points(friction)  # a friction couple is drawn at its pair's pin
    taken: dict[tuple[float, float], int] = {}
    for m in moments:
        link = scene.links[m.link]
        centre = link.centre or next((n for n in link.points if n.startswith("S")), link.axis[0])
        centre = at_pin.get(m.label, centre) if at_pin.get(m.label) in pts else centre
        moment_arc(rec, placer, T.z(pts[centre]), float(m.M[k]), force_label(m.label, lang),
                    f"{pid}-{ident(m.label)}", taken=taken)
    for point, M, name in couples:
        moment_arc(rec, placer, T.z(pts[point]), M, force_label(name, lang), f"{pid}-{ident(name)}", r=8.0,
                    taken=taken)
    friction_marks(rec, placer, T, friction, gf.reactions, k, mu_l, mu_f, pid,
                   lambda rc: force_label(rc.name(scene.fij), lang))
    label_points(rec, placer, pts, T, pid)
    title = f"{tr('group', lang)} {g.name} ({g.kind}), φ = {angle(phi, lang)}°"
    sc = f"{scale_text('length', mu_l, style, lang)};  {scale_text('force', mu_f, style, lang)}"
    if short:
        sc += ";  " + short_mark(lang)
    return finish(pid, "group", phi, rec, title, sc, quantity="length", scale=mu_l)


@_once
def crank_panel(scene, kin, fa, k: int, mu_l: float, lang: str, style: str) -> Panel:
    """The initial link with the reactions of the groups, its own loads, the balancing
    load and the frame's reaction (appendix 6)."""
    c = fa.crank
    phi = float(kin.phi_deg[k])
    pid = f"crank-{phi_tag(phi)}"
    T = Transform(mu_l)
    rec = Recording()
    placer = Placer()
    pts = draw_links(rec, placer, scene, kin, k, [c.link], T, pid)
    bal = complex(c.F_bal[k] * c.e_bal[k]) if c.kind == "force" else 0j
    values = [complex(f.F[k]) for f in c.loads] + [bal, complex(c.frame.F[k])]
    mu_f = fbd_scale(values, largest_of([f.F for f in c.loads] + [c.frame.F]), fit(scene))
    short = False
    for f in c.loads:
        short |= force_at(rec, placer, T, complex(f.r[k]), complex(f.F[k]), mu_f, force_label(f.label, lang),
                           LOAD, f"{pid}-{ident(f.label)}")
    taken: dict[tuple[float, float], int] = {}
    if c.kind == "force":
        short |= force_at(rec, placer, T, complex(c.r_point[k]), bal, mu_f, force_label("F_bal", lang),
                           REACTION, f"{pid}-F_bal")
    else:
        moment_arc(rec, placer, T.z(pts[scene.driver.pivot]), float(c.M_bal[k]),
                    "M_ур" if lang == "ru" else "M_bal", f"{pid}-M_bal", r=8.0, taken=taken)
    for m in c.moments:
        moment_arc(rec, placer, T.z(pts[c.point]), float(m.M[k]), force_label(m.label, lang),
                    f"{pid}-{ident(m.label)}", taken=taken)
    name = c.frame.name(scene.fij)
    short |= force_at(rec, placer, T, complex(c.frame.r[k]), complex(c.frame.F[k]), mu_f,
                       force_label(name, lang), REACTION, f"{pid}-{ident(name)}")
    friction_marks(rec, placer, T, fa.friction, (c.frame,), k, mu_l, mu_f, pid,
                   lambda rc: force_label(rc.name(scene.fij), lang))
    label_points(rec, placer, pts, T, pid)
    title = f"{tr('crank', lang)} {c.link}, φ = {angle(phi, lang)}°"
    sc = f"{scale_text('length', mu_l, style, lang)};  {scale_text('force', mu_f, style, lang)}"
    if short:
        sc += ";  " + short_mark(lang)
    return finish(pid, "crank", phi, rec, title, sc, quantity="length", scale=mu_l)


# --------------------------------------------------------------------------- polygons and lever


@_once
def polygon_panel(plan: Plan, lang: str, style: str, pid: str, title: str) -> Panel:
    """A force polygon head to tail (plan mm, true size): known forces black, the closing
    reactions red, the two construction lines that closed it thin; every vector labelled."""
    T, rec, placer, xy, box = on_paper(plan, 8.0)
    for i, cl in enumerate(plan.lines):
        seg = clip_line(T(*cl.point), T.direction(*cl.direction), box)
        if seg is not None:
            rec.line(seg[0], seg[1], Style(width=0.18, stroke="#666", cls="construction"), f"{pid}-line-{i}")
            placer.add_line(list(seg))
    geoms = []
    used: dict[str, int] = {}
    laid: list[tuple[Pt, Pt]] = []
    for s in plan.segments:
        a, b = xy[s.start], xy[s.end]
        k = sum(_collinear_overlap(a, b, c, d) for c, d in laid)
        laid.append((a, b))
        if k and s.length_mm > 1e-6:  # on a line already drawn: beside it, so each one shows
            L = math.dist(a, b)
            nx, ny = -(b[1] - a[1]) / L * SIDE_MM * k, (b[0] - a[0]) / L * SIDE_MM * k
            a, b = (a[0] + nx, a[1] + ny), (b[0] + nx, b[1] + ny)
        st = VECTOR_STYLES["closing" if s.kind == "closing" else "force"]
        eid = f"{pid}-{ident(s.label)}"
        used[eid] = used.get(eid, 0) + 1
        if used[eid] > 1:
            eid = f"{eid}-{used[eid]}"
        arrow(rec, a, b, st, eid, f"vector {s.kind}")
        placer.add_line([a, b])
        geoms.append((s, a, b, eid))
    for p in plan.points:
        if p.coincides_with is None:
            dot(rec, xy[p.name], 0.45)
            placer.add_disc(xy[p.name], 0.6)
    xs, ys = [q[0] for q in xy.values()], [q[1] for q in xy.values()]
    centre = (sum(xs) / len(xs), sum(ys) / len(ys)) if xs else (0.0, 0.0)
    for p in plan.points:  # the vertices lettered as the tables cite them ("o a", "a b")
        if p.coincides_with is not None or p.name.endswith(">"):
            continue
        v = xy[p.name]
        names = [q.name for q in plan.points if q.name == p.name or q.coincides_with == p.name]
        away = (v[0] - centre[0], v[1] - centre[1])
        L = math.hypot(*away) or 1.0
        lab = placer.place(", ".join(point_label(n) for n in names), v, LABEL_SIZE - 0.5,
                           prefer=(away[0] / L, away[1] / L), gap=0.8)
        rec.text(lab, "label", f"{pid}-label-{ident(p.name)}")
    for s, a, b, eid in geoms:
        if s.length_mm < 1e-6:
            continue
        mid = ((a[0] + b[0]) / 2, (a[1] + b[1]) / 2)
        L = math.dist(a, b)
        nx, ny = -(b[1] - a[1]) / L, (b[0] - a[0]) / L
        st = VECTOR_STYLES["closing" if s.kind == "closing" else "force"]
        lab = placer.place(force_label(s.label, lang), mid, SMALL_SIZE + 0.5, prefer=(nx, ny), gap=0.8)
        rec.text(lab, "vector-label", f"{eid}-label", fill=st.stroke or "#000")
    return finish(pid, "polygon", plan.phi_deg, rec, f"{title}, φ = {angle(plan.phi_deg, lang)}°",
                  scale_text("force", plan.scale, style, lang), quantity="force", scale=plan.scale)


SIDE_MM = 1.2  # offset of a force drawn on a line another force already covers


def _collinear_overlap(a: Pt, b: Pt, c: Pt, d: Pt) -> bool:
    """Segments ab and cd on one line (within 1 mm) sharing more than 0.5 mm of it."""
    L = math.dist(a, b)
    if L < 1e-6 or math.dist(c, d) < 1e-6:
        return False
    ux, uy = (b[0] - a[0]) / L, (b[1] - a[1]) / L
    off = [abs((q[0] - a[0]) * uy - (q[1] - a[1]) * ux) for q in (c, d)]
    if max(off) > 1.0:
        return False
    t = sorted(((q[0] - a[0]) * ux + (q[1] - a[1]) * uy) for q in (c, d))
    return min(L, t[1]) - max(0.0, t[0]) > 0.5


@_once
def lever_panel(sol, k: int, vplan: Plan | None, lang: str, style: str) -> Panel:
    """The velocity plan turned 90° as a rigid lever about the pole, every force at the image of
    its point parallel to itself, the arms h from the pole, and the balancing force."""
    lv = sol.lever
    plan = sol.lever_plan(k)
    phi = plan.phi_deg
    pid = f"lever-{phi_tag(phi)}"
    T = Transform(1.0)
    rec = Recording()
    placer = Placer()
    xy = {p.name: T(*p.xy) for p in plan.points}
    images = [p.name for p in plan.points if not p.name.endswith(">")]  # ordered: stable output
    if vplan is not None:  # every point's image, loaded or not: the plan turned, at the lever's μv
        rot = lv.turn * 1j * lv.scale / vplan.scale
        for vp in vplan.points:
            if vp.name != vplan.pole and vp.name not in xy:
                w = rot * complex(*vp.xy)
                xy[vp.name] = T(w.real, w.imag)
                images.append(vp.name)
    # the lever itself: the plan's vectors turned
    if vplan is not None:
        for vs in vplan.segments:
            na = "p" if vs.start == vplan.pole else vs.start
            nb = "p" if vs.end == vplan.pole else vs.end
            if na in xy and nb in xy and vs.kind in ("absolute", "relative") and xy[na] != xy[nb]:
                rec.line(xy[na], xy[nb], Style(width=0.5, stroke="#000", cls="lever"),
                         f"{pid}-bar-{ident(na)}-{ident(nb)}")
                placer.add_line([xy[na], xy[nb]])
    segs = [s for s in plan.segments if s.kind == "force"]
    mu_f = (segs[0].length_mm / segs[0].value) if segs and segs[0].value else 1.0
    c = lv.fa.crank
    bal_vecs: list[tuple[str, tuple[Pt, Pt]]] = []
    if c.kind == "force":
        F = complex(lv.by_lever[k]) * complex(c.e_bal[k])
        wb = complex(lv.w_bal[k])
        bal_vecs.append((force_label("F_bal", lang), (T(wb.real, wb.imag), T((wb + F * mu_f).real,
                                                                             (wb + F * mu_f).imag))))
    elif bool(lv.valid[k]):  # a balancing moment as its force pair: F = M/l_OA ⟂ OA at a, −F at p
        rA = complex(c.r_point[k])
        rO = complex(lv.fa.kin.point(lv.fa.scene.driver.pivot, c.link)[0][k])
        M = float(c.M_bal[k])
        if abs(rA - rO) > 0 and M != 0:
            F = 1j * (rA - rO) * M / abs(rA - rO) ** 2
            wb = complex(lv.w_bal[k])
            name = "M_ур" if lang == "ru" else "M_bal"
            for pair, at, fv in ((f"{name}'", wb, F), (f"{name}''", 0j, -F)):
                bal_vecs.append((pair, (T(at.real, at.imag), T((at + fv * mu_f).real, (at + fv * mu_f).imag))))
    short = False
    arrows: list[tuple[str, str, Pt, Pt, Style, str]] = []
    for s in segs:
        arrows.append((f"{pid}-{ident(s.label)}", force_label(s.label, lang), xy[s.start], xy[s.end], LOAD,
                       "vector force"))
    for i, (pair, (p0, p1)) in enumerate(bal_vecs):
        arrows.append((f"{pid}-F_bal" if i == 0 else f"{pid}-F_bal-{i}", pair, p0, p1, REACTION, "vector closing"))
    drawn: list[tuple[str, str, Pt, Pt, Style, str]] = []
    for eid, text, p0, p1, st, cls in arrows:  # too short to see at μF: a minimum length, marked †
        p1, lengthened = legible(p0, p1)
        if lengthened:
            text, short = text + "†", True
        drawn.append((eid, text, p0, p1, st, cls))
    pole = xy["p"]
    for i, cl in enumerate(plan.lines):
        z0 = complex(*cl.point)
        u = complex(*cl.direction)
        foot = z0 + ((0j - z0) * u.conjugate()).real * u
        if abs(foot) > 1.0:
            ft = T(foot.real, foot.imag)
            rec.line(pole, ft, ARM, f"{pid}-arm-{i}")
            rec.line(T(*cl.point), ft, Style(width=0.18, stroke="#888", dash=(4.0, 1.0, 1.0, 1.0)))
    for eid, _text, p0, p1, st, cls in drawn:
        if p0 != p1:
            arrow(rec, p0, p1, st, eid, cls)
            placer.add_line([p0, p1])
    for n in images:
        dot(rec, xy[n], 0.5)
        placer.add_disc(xy[n], 0.6)
    seen: set[tuple[float, float]] = set()
    for n in sorted(images, key=lambda x: (x != "p", x)):
        key = (round(xy[n][0], 6), round(xy[n][1], 6))
        if key in seen:
            continue
        same = [m for m in sorted(images) if (round(xy[m][0], 6), round(xy[m][1], 6)) == key]
        seen.add(key)
        lab = placer.place(", ".join(point_label(m) for m in same), xy[n], LABEL_SIZE, gap=0.8)
        rec.text(lab, "label", f"{pid}-label-{ident(n)}")
    for eid, text, p0, p1, st, _cls in drawn:
        if p0 == p1:
            continue
        L = math.dist(p0, p1) or 1.0
        vl = placer.place(text, p1, SMALL_SIZE + 0.5, prefer=((p1[0] - p0[0]) / L, (p1[1] - p0[1]) / L), gap=0.6)
        rec.text(vl, "vector-label", f"{eid}-label", fill=st.stroke if st is REACTION and st.stroke else "#000")
    turn = ("90° " + ("против часовой" if lv.turn > 0 else "по часовой")) if lang == "ru" else (
        "turned 90° " + ("ccw" if lv.turn > 0 else "cw"))
    title = f"{tr('lever', lang)}, φ = {angle(phi, lang)}° ({turn})"
    sc = f"{scale_text('velocity', lv.scale, style, lang)};  {scale_text('force', mu_f, style, lang)}"
    note = short_note(lang) if short else None
    return finish(pid, "lever", phi, rec, title, sc, note=note, quantity="velocity", scale=lv.scale)


# --------------------------------------------------------------------------- tables


class _Row:
    """A reading-like row for :func:`table_panel`."""

    __slots__ = ("quantity", "segment", "length_mm", "scale", "value", "exact", "unit", "ref", "relative")

    def __init__(self, quantity: str, segment: str | None, length_mm: float | None, scale: float | None,
                 value: float, exact: float, unit: str, ref: float) -> None:
        self.quantity, self.segment, self.length_mm, self.scale = quantity, segment, length_mm, scale
        self.value, self.exact, self.unit, self.ref = value, exact, unit, ref
        den = max(abs(exact), ref)
        self.relative = abs(value - exact) / den if den > 0 else 0.0


@_once
def forces_table(polys, lang: str, style: str, phi: float, part: tuple[int, int, int] | None = None) -> Panel:
    """Every polygon vector: segment, mm, μF, value read to the ruler, exact, difference."""
    rows = []
    whole = max((s.value for fp in polys for s in fp.plan.segments), default=0.0)
    for fp in polys:
        ref = max((s.value for s in fp.plan.segments), default=0.0)
        if ref <= DUST * whole:
            # a polygon of round-off only (the crank's in a dead position): its forces are
            # zero against the position's, not -100 % against each other
            ref = whole
        for s in fp.plan.segments:
            rows.append(_Row(force_label(s.label, lang), f"{s.start} {s.end}", s.length_mm, fp.scale,
                             fp.reading(s.label), s.value, "N", ref))
    title_pid = f"forces-table-{phi_tag(phi)}"
    p = table_panel(rows, lang, style, phi, pid=title_pid, title_key="forces_table", part=part)
    return p


def balancing_rows(sol, k: int, lang: str) -> list[tuple[str, ...]]:
    """The balancing load three ways (kinetostatics, lever, power) and δ, as table rows."""
    lv = sol.lever
    rows = sol.force_rows(k)[-4:]
    keys = ("by_groups", "by_lever", "by_power")
    force = lv.fa.crank.kind == "force"
    letter = "F" if force else "M"
    name = f"{letter}_ур" if lang == "ru" else f"{letter}_bal"
    out: list[tuple[str, ...]] = []
    for key, r in zip(keys, rows[:3], strict=False):
        unit = "Н" if (lang == "ru" and r.unit == "N") else ("Н·м" if lang == "ru" and r.unit == "N·m" else r.unit)
        read = "—" if r.drawing is None else fmt(r.drawing, 5, lang)
        d = r.difference
        diff = "—" if d is None else f"{d:+.2f}".replace("+0.00", "0.00").replace("-0.00", "0.00")
        if lang == "ru":
            diff = diff.replace(".", ",")
        out.append((f"{name} ({tr(key, lang)})", "—", "—", "—", read, fmt(r.exact, 5, lang), unit, diff))
    delta = rows[3]
    if delta.drawing is not None and np.isfinite(delta.drawing):
        out.append((f"δ = ({letter}_lev − {letter}_kin)/{letter}_kin, %" if lang == "en"
                    else f"δ = ({letter}_рыч − {letter}_кин)/{letter}_кин, %",
                    "—", "—", "—", fmt(delta.drawing, 3, lang), fmt(delta.exact, 3, lang), "%", "—"))
    return out


__all__ = ["build", "group_panel", "crank_panel", "polygon_panel", "lever_panel", "forces_table",
           "balancing_rows", "force_label", "cmath"]
