"""Panels: one figure of the sheet each (scheme, plans, table, forces, lever).

A panel is drawn once, onto a :class:`Recording` in its own paper millimetres,
then normalised so its box (labels included) starts at (0, 0).  Layout only
moves panels; the recorded primitives are replayed onto the SVG backend.
"""

from __future__ import annotations

import cmath
import math
import re
from collections.abc import Sequence
from dataclasses import dataclass

from plans.kinematics.plan import Plan
from plans.units import DUST

from .backend import FILLED, HAIR, MAIN, THICK, THIN, Prim, Pt, Recording, Style, Transform
from .common import Placer, angle, arrow, dot, fmt, ident, phi_tag
from .i18n import tr
from .text import layout, point_label

TITLE_SIZE = 5.0
SCALE_SIZE = 3.5
LABEL_SIZE = 3.5
SMALL_SIZE = 2.5
PAD = 2.0


@dataclass(frozen=True, slots=True)
class Panel:
    """A finished figure: ``prims`` in panel mm with the box at (0, 0)–(width, height)."""

    pid: str  # "scheme-45", "velocity-45", ...
    kind: str  # positions | scheme | velocity | acceleration | table | group | polygon | crank | lever | legend
    phi: float | None
    prims: tuple[Prim, ...]
    width: float
    height: float
    title: str = ""
    quantity: str | None = None  # the scale this panel is drawn at: length, velocity, ...
    scale: float | None = None  # μ, mm per SI unit

    def at(self, x: float, y: float) -> list[Prim]:
        return [p.moved(x, y) for p in self.prims]

    def text_boxes(self) -> list[tuple[float, float, float, float]]:
        return [p.label.box for p in self.prims if p.op == "text" and p.label is not None]

    def svg(self, debug: bool = False) -> str:
        """The panel alone as an SVG document in true millimetres."""
        from .backend import replay
        from .svg import SvgBackend, document

        if not debug:
            return document(self.width, self.height, self.prims)
        be = SvgBackend(self.width, self.height, debug=debug)
        replay(self.prims, be)
        return be.tostring()

    def _repr_svg_(self) -> str:
        return self.svg()


def finish(pid: str, kind: str, phi: float | None, body: Recording, title: str,
           scale_line: str | None = None, note: str | None = None, quantity: str | None = None,
           scale: float | None = None) -> Panel:
    """Title (and scale) above the body, everything shifted to start at (0, 0); labels that a
    line of the finished figure crosses are moved clear of it (:func:`declutter`); a table's
    cells sit between its rules by construction and are not searched."""
    if kind not in ("table", "legend", "cycle-table"):
        from .declutter import declutter

        body = Recording(declutter(body.prims))
    x0, y0, x1, y1 = body.bbox()
    head = Recording()
    y = y0 - 2.5
    lines = []
    if note:
        lines.append((note, SCALE_SIZE, f"{pid}-note"))
    if scale_line:
        lines.append((scale_line, SCALE_SIZE, f"{pid}-scale"))
    for text, size, eid in reversed(lines):
        lab = layout(text, x0, y, size, "start", "bottom")
        head.text(lab, "scale" if eid.endswith("scale") else "note", eid)
        y = lab.box[1] - 1.2
    lab = layout(title, x0, y, TITLE_SIZE, "start", "bottom")
    head.text(lab, "title", f"{pid}-title")
    rec = Recording([Prim("begin", eid=pid, cls=f"panel {kind}")] + head.prims + body.prims + [Prim("end")])
    bx0, by0, bx1, by1 = rec.bbox()
    moved = rec.moved(PAD - bx0, PAD - by0)
    return Panel(pid, kind, phi, tuple(moved.prims), bx1 - bx0 + 2 * PAD, by1 - by0 + 2 * PAD, title,
                 quantity, scale)


# --------------------------------------------------------------------------- scales


_SCALE_UNITS = {
    "length": ("l", "mm/m", "m/mm"),
    "velocity": ("v", "mm/(m/s)", "(m/s)/mm"),
    "acceleration": ("a", "mm/(m/s^2)", "(m/s^2)/mm"),
    "force": ("F", "mm/N", "N/mm"),
}


def scale_text(quantity: str, mu: float, style: str, lang: str) -> str:
    """``μ_v = 6.667 mm/(m/s)``, ``μ_v = 0,15 (м/с)/мм`` or ``K_v = 0.15 (m/s)/mm``: the letter
    and the direction of the scene's notation in the sheet's language (plans.scene.notation)."""
    from plans.scene.notation import resolve

    sub, mu_unit, k_unit = _SCALE_UNITS[quantity]
    letter, per_mm, _ = resolve(style, lang)
    if per_mm:
        return f"{letter}_{sub} = {fmt(1.0 / mu, 4, lang)} {tr(k_unit, lang)}"
    return f"{letter}_{sub} = {fmt(mu, 4, lang)} {tr(mu_unit, lang)}"


def ratio_text(mu_l: float, lang: str = "en") -> str:
    """μl in mm/m as a drawing scale (GOST 2.302): 1000 -> ``1:1``, 250 -> ``1:4``,
    2000 -> ``2:1``, 400 -> ``1:2,5`` on a Russian sheet (``1:2.5`` in English)."""
    r = mu_l / 1000.0
    text = f"{r:.4g}:1" if r >= 1 else f"1:{1 / r:.4g}"
    return text.replace(".", ",") if lang == "ru" else text


STANDARD_RATIOS = (10.0, 5.0, 4.0, 2.5, 2.0, 1.0, 1 / 2, 1 / 2.5, 1 / 4, 1 / 5, 1 / 10, 1 / 15, 1 / 20,
                   1 / 25, 1 / 40, 1 / 50, 1 / 75, 1 / 100, 1 / 200, 1 / 500, 1 / 1000)


def auto_length_scale(size_m: float, target_mm: float = 230.0) -> float:
    """The largest standard drawing scale (GOST 2.302) that draws ``size_m`` within ``target_mm``."""
    for r in STANDARD_RATIOS:
        if size_m * 1000.0 * r <= target_mm:
            return 1000.0 * r
    return 1000.0 * STANDARD_RATIOS[-1]


# --------------------------------------------------------------------------- the kinematic scheme

BLOCK_L = 12.0
BLOCK_H = 7.0
JOINT_R = 1.6


@dataclass(frozen=True, slots=True)
class SchemeGeometry:
    """What the scheme needs from the kinematics at one position (world metres)."""

    points: dict[str, complex]  # every named point, global
    link_points: dict[int, dict[str, complex]]
    crank_omega: float
    crank_eps: float
    dead: tuple[str, ...]


def scheme_panel(scene, kin, k: int, mu_l: float, lang: str, strokes: dict[str, tuple[float, float]],
                 overlay=None) -> Panel:
    """The mechanism at position k at μl: links, joints, sliders, guides, frame, S points, ω1.

    ``overlay(rec, T, placer, pid)``, where given, draws more on the scheme (the instant
    centres) and returns the panel's (kind, title, note) in place of the scheme's."""
    phi = float(kin.phi_deg[k])
    pid = f"scheme-{phi_tag(phi)}" if overlay is None else f"centres-{phi_tag(phi)}"
    T = Transform(mu_l)
    frame = scene.frame
    rec = Recording()
    placer = Placer()

    def P(lid: int, name: str) -> complex:
        z = scene.frame_points[name] if lid == frame else scene.links[lid].points[name]
        return complex(kin.point_on(lid, z)[0][k])

    glob: dict[str, complex] = {}
    for name, z in scene.frame_points.items():
        glob[name] = z
    for lid in sorted(scene.links):
        for name in scene.links[lid].points:
            glob.setdefault(name, P(lid, name))
    centre_world = sum(glob.values()) / max(len(glob), 1)

    rec.begin(f"{pid}-guides", "guides")
    for jt in scene.joints:
        if jt.kind != "P" or jt.guide is None:
            continue
        g = jt.guide
        th = 0.0 if g.link == frame else float(kin.theta(g.link)[k])
        u = cmath.exp(1j * (th + g.angle))
        G = complex(kin.point_on(g.link, g.origin)[0][k]) if g.link != frame else g.origin
        pin = glob[jt.point]
        s_pin = ((pin - G) * u.conjugate()).real
        half = BLOCK_L / 2 / mu_l
        if g.link == frame:
            lo, hi = strokes.get(jt.name, (s_pin, s_pin))
            lo, hi = min(lo, s_pin) - half - 6 / mu_l, max(hi, s_pin) + half + 6 / mu_l
            a0, a1 = T.z(G + lo * u), T.z(G + hi * u)
            rec.line(a0, a1, Style(stroke="#333", width=0.18, dash=(6.0, 1.0, 1.0, 1.0), cls="axis"),
                     f"{pid}-axis-{ident(jt.point)}")
            side_w = cross(u, centre_world - G)
            nrm = -1j * u if side_w >= 0 else 1j * u  # away from the mechanism
            off = nrm * (BLOCK_H / 2 / mu_l)
            r0, r1 = T.z(G + lo * u + off), T.z(G + hi * u + off)
            rec.line(r0, r1, MAIN, f"{pid}-rail-{ident(jt.point)}")
            o = T.z(off)
            o0 = T.z(0j)
            ox, oy = o[0] - o0[0], o[1] - o0[1]
            dx, dy = r1[0] - r0[0], r1[1] - r0[1]
            side = 1 if (dy * ox - dx * oy) > 0 else -1
            rec.hatch(r0, r1, side, THIN, 3.0, 2.5, f"{pid}-hatch-{ident(jt.point)}")
            k2 = 2.5 / math.sqrt(2)
            L = math.hypot(dx, dy)
            hx, hy = (dy / L * side) * k2, (-dx / L * side) * k2
            placer.add_poly([r0, r1, (r1[0] + hx, r1[1] + hy), (r0[0] + hx, r0[1] + hy)])
            placer.add_line([a0, a1])
        else:
            carrier = scene.links[g.link]
            ss = [((P(g.link, n) - G) * u.conjugate()).real for n in carrier.points] + [s_pin]
            lo, hi = min(ss) - half - 4 / mu_l, max(ss) + half + 4 / mu_l
            a0, a1 = T.z(G + lo * u), T.z(G + hi * u)
            rec.line(a0, a1, THICK, f"{pid}-guide-{ident(jt.point)}")
            placer.add_line([a0, a1])
    rec.end()

    rec.begin(f"{pid}-links", "links")
    for lid in sorted(scene.links):
        kind, names = link_shape(scene, lid)
        link_outline(rec, placer, kind, [T.z(glob_of(P, lid, n)) for n in names], f"{pid}-link-{lid}")
    rec.end()

    rec.begin(f"{pid}-sliders", "sliders")
    for jt in scene.joints:
        if jt.kind != "P" or jt.guide is None:
            continue
        g = jt.guide
        th = 0.0 if g.link == frame else float(kin.theta(g.link)[k])
        ang = -(th + g.angle)  # paper angle
        c = T.z(glob[jt.point])
        ux, uy = math.cos(ang), math.sin(ang)
        hl, hh = BLOCK_L / 2, BLOCK_H / 2
        corners = [(c[0] + sx * hl * ux - sy * hh * uy, c[1] + sx * hl * uy + sy * hh * ux)
                   for sx, sy in ((-1, -1), (1, -1), (1, 1), (-1, 1))]
        rec.polygon(corners, Style(width=0.5, fill="#fff", cls="slider"), f"{pid}-slider-{ident(jt.point)}")
        placer.add_poly(corners)
    rec.end()

    rec.begin(f"{pid}-joints", "joints")
    drawn: set[str] = set()
    for jt in scene.joints:
        if jt.kind != "R" or jt.point in drawn:
            continue
        drawn.add(jt.point)
        c = T.z(glob[jt.point])
        if frame in jt.links:
            fixed_pivot(rec, c, f"{pid}-support-{ident(jt.point)}")
            placer.add_disc((c[0], c[1] + 4.0), 4.0)
        rec.circle(c, JOINT_R, Style(width=0.35, fill="#fff", cls="joint"), f"{pid}-joint-{ident(jt.point)}")
        placer.add_disc(c, JOINT_R + 0.3)
    rec.end()

    rec.begin(f"{pid}-centres", "centres")
    centres = []
    for lid in sorted(scene.links):
        link = scene.links[lid]
        for n in link.points:
            if n == link.centre or (n.startswith("S") and n not in drawn):
                centres.append(n)
                c = T.z(glob[n])
                rec.circle(c, 1.2, Style(width=0.25, fill="#fff", cls="centre"), f"{pid}-centre-{ident(n)}")
                rec.polygon(_quarter(c, 1.2, 0) + _quarter(c, 1.2, 2)[1:], Style(stroke=None, width=0,
                            fill="#000", cls="centre"))
                placer.add_disc(c, 1.4)
    rec.end()

    # ω1 (and ε1) arcs at the crank pivot
    d = scene.driver
    crank = scene.links[d.link]
    O = glob[d.pivot]
    A = glob[crank.axis[1]]
    c = T.z(O)
    th1 = cmath.phase(A - O)
    r_paper = min(12.0, max(7.0, 0.55 * abs(A - O) * mu_l))
    arcs = [("ω_1", d.sense, r_paper, "omega")]
    if d.eps != 0:
        arcs.append(("ε_1", 1 if d.eps > 0 else -1, r_paper + 4.0, "eps"))
    rec.begin(f"{pid}-arcs", "arcs")
    for text, sense, r, tag in arcs:
        w0 = th1 + sense * math.radians(35)
        w1 = th1 + sense * math.radians(125)
        a0p, a1p = T.angle(w0), T.angle(w1)
        rec.arc(c, r, a0p, a1p, Style(width=0.35, cls="arc"), f"{pid}-{tag}-arc")
        end = (c[0] + r * math.cos(a1p), c[1] + r * math.sin(a1p))
        tdir = -sense  # paper angle changes opposite to the world angle
        tx, ty = -math.sin(a1p) * tdir, math.cos(a1p) * tdir
        tip = (end[0] + tx * 3.2, end[1] + ty * 3.2)
        rec.polygon([tip, (end[0] - ty * 0.8, end[1] + tx * 0.8), (end[0] + ty * 0.8, end[1] - tx * 0.8)],
                    Style(stroke=None, width=0.0, fill="#000", cls="head"), f"{pid}-{tag}-head")
        mid = T.angle(th1 + sense * math.radians(80))
        anchor = (c[0] + (r + 0.5) * math.cos(mid), c[1] + (r + 0.5) * math.sin(mid))
        placer.add_line([(c[0] + r * math.cos(a0p + (a1p - a0p) * i / 8),
                          c[1] + r * math.sin(a0p + (a1p - a0p) * i / 8)) for i in range(9)])
        lab = placer.place(text, anchor, LABEL_SIZE, prefer=(math.cos(mid), math.sin(mid)))
        rec.text(lab, "label", f"{pid}-{tag}-label")
    rec.end()

    if any(len(g.links) == 4 for g in kin.structure.groups):  # class III: Assur's point S
        from .triad_marks import scheme_points

        scheme_points(rec, placer, T, scene, kin, k, pid, LABEL_SIZE)
    rec.begin(f"{pid}-labels", "labels")
    names = list(scene.frame_points) + [n for lid in sorted(scene.links) for n in scene.links[lid].points]
    seen: set[str] = set()
    for n in names:
        if n in seen:
            continue
        seen.add(n)
        c = T.z(glob[n])
        away = T.z(glob[n] - centre_world)
        o0 = T.z(0j)
        vx, vy = away[0] - o0[0], away[1] - o0[1]
        L = math.hypot(vx, vy) or 1.0
        lab = placer.place(point_label(n), c, LABEL_SIZE, prefer=(vx / L, vy / L), gap=2.0)
        rec.text(lab, "label", f"{pid}-label-{ident(n)}")
    rec.end()

    dead = _dead_points(scene, kin, k)
    title = f"{tr('scheme', lang)}, φ = {angle(phi, lang)}°"
    note = None
    if dead:
        note = f"{tr('dead', lang)} {', '.join(dead)}"
    kind = "scheme"
    if overlay is not None:
        kind, title, more = overlay(rec, T, placer, pid)
        note = "; ".join(x for x in (note, more) if x) or None
    return finish(pid, kind, phi, rec, title,
                  f"{scale_text('length', mu_l, scene.scale_style, lang)}  (M {ratio_text(mu_l, lang)})", note,
                  "length", mu_l)


def link_outline(rec: Recording, placer: Placer, kind: str, pts: list[Pt], eid: str) -> None:
    """A link as the textbook draws it: a thick bar, or a shaded plate for three or more
    points; its outline is kept clear of labels."""
    if kind == "line":
        rec.line(pts[0], pts[1], THICK, eid)
        placer.add_line(pts)
    elif kind == "polygon":
        rec.polygon(pts, Style(width=0.7, fill="#eeeeee", cls="link"), eid)
        placer.add_line(pts + [pts[0]])


def link_shape(scene, lid: int) -> tuple[str, list[str]]:
    """How a link is drawn: ``("line", [X, Y])`` from end to end of its collinear points, or
    ``("polygon", [...])`` through its pairs and other points (a rigid triangle, a plate);
    ``("none", [])`` for a one-point slider (drawn as its block).  Centres of mass (S...) do
    not shape the link."""
    link = scene.links[lid]
    names = [n for n in link.points if _is_joint_point(scene, lid, n) or not n.startswith("S")]
    for n in link.axis:
        if n not in names:
            names.insert(0, n)
    if len(names) < 2:
        # a one-pin link that carries a guide (a yoke): its body runs out to its centre of
        # mass, so S sits on the link it belongs to
        carrier = any(jt.guide is not None and jt.guide.link == lid for jt in scene.joints)
        far = [n for n in link.points if n not in names and names and abs(link.points[n] - link.points[names[0]]) > 0]
        if carrier and names and far:
            return "line", [names[0], max(far, key=lambda n: abs(link.points[n] - link.points[names[0]]))]
        return "none", []
    z = {n: link.points[n] for n in names}
    base = z[names[1]] - z[names[0]] if len(names) > 1 else 1.0
    size = max(abs(v - z[names[0]]) for v in z.values()) or 1.0
    u = base / abs(base) if abs(base) else 1.0
    rel = {n: (v - z[names[0]]) * u.conjugate() for n, v in z.items()}
    if all(abs(r.imag) <= DUST * size for r in rel.values()):
        lo = min(names, key=lambda n: rel[n].real)
        hi = max(names, key=lambda n: rel[n].real)
        return "line", [lo, hi]
    c = sum(z.values()) / len(z)
    order = sorted(names, key=lambda n: cmath.phase(z[n] - c))
    return "polygon", order


def glob_of(P, lid: int, name: str) -> complex:
    return P(lid, name)


def cross(a: complex, b: complex) -> float:
    return (a.conjugate() * b).imag


def _is_joint_point(scene, lid: int, name: str) -> bool:
    return any(lid in jt.links and jt.point == name for jt in scene.joints)


def _dead_points(scene, kin, k: int) -> list[str]:
    """Slider pins at rest at this position (dead centres), when velocities are known."""
    if kin.order < 1:
        return []
    d = scene.driver
    crank = scene.links[d.link]
    va = abs(complex(kin.point(crank.axis[1])[1][k]))
    out = []
    for jt in scene.joints:
        if jt.kind == "P" and jt.guide is not None and jt.guide.link == scene.frame:
            v = complex(kin.point(jt.point)[1][k])
            if abs(v) <= DUST * max(va, 1e-300):
                out.append(jt.point)
    return out


def fixed_pivot(rec: Recording, c: Pt, eid: str) -> None:
    """A fixed pivot: triangle to a hatched base, as the textbook draws the frame."""
    x, y = c
    rec.polyline([(x - 3.2, y + 5.5), (x, y), (x + 3.2, y + 5.5)], Style(width=0.5, cls="frame"), eid)
    rec.line((x - 5.5, y + 5.5), (x + 5.5, y + 5.5), Style(width=0.5, cls="frame"))
    rec.hatch((x - 5.5, y + 5.5), (x + 5.5, y + 5.5), -1, THIN, 2.0, 2.2)


def _quarter(c: Pt, r: float, q: int) -> list[Pt]:
    a0 = q * math.pi / 2
    return [c] + [(c[0] + r * math.cos(a0 + math.pi / 2 * i / 6), c[1] + r * math.sin(a0 + math.pi / 2 * i / 6))
                  for i in range(7)]


def strokes_over_cycle(sol) -> dict[str, tuple[float, float]]:
    """Travel of every slider pin along its fixed guide over one revolution (world m), every 5°
    (none where the mechanism does not turn a whole revolution)."""
    import numpy as np

    from plans.errors import PlansError

    scene = sol.scene
    try:
        rev = sol.revolution(73)
    except PlansError:
        return {}
    out = {}
    for jt in scene.joints:
        if jt.kind == "P" and jt.guide is not None and jt.guide.link == scene.frame:
            r = rev.point(jt.point)
            s = ((r - jt.guide.origin) * np.conj(jt.guide.direction)).real
            out[jt.name] = (float(s.min()), float(s.max()))
    return out


def cycle_size(sol) -> float:
    """Largest extent of the mechanism (world m) over a revolution (every 10°; the scene's own
    positions where it does not turn a whole one), for the auto scale."""
    import numpy as np

    from plans.errors import PlansError

    scene = sol.scene
    try:
        rev = sol.revolution(37)
        at = rev.point_on
    except PlansError:
        kin = sol.kinematics

        def at(lid, z):
            return kin.point_on(lid, z)[0]
    pts = [np.asarray(list(scene.frame_points.values()), dtype=complex)]
    for lid in scene.links:
        for z in scene.links[lid].points.values():
            pts.append(np.asarray(at(lid, z)))
    allp = np.concatenate([np.ravel(p) for p in pts])
    return float(max(np.ptp(allp.real), np.ptp(allp.imag), 1e-9))


# --------------------------------------------------------------------------- velocity / acceleration plans

VECTOR_STYLES: dict[str, Style] = {
    "absolute": Style(width=0.5, stroke="#000"),
    "relative": Style(width=0.35, stroke="#000"),
    "normal": Style(width=0.35, stroke="#1f4e9c", dash=(2.5, 1.0)),
    "tangential": Style(width=0.35, stroke="#1d6b36", dash=(5.0, 1.0, 1.0, 1.0)),
    "coriolis": Style(width=0.45, stroke="#b3261e"),
    "sliding": Style(width=0.35, stroke="#6a3d9a", dash=(1.2, 0.8)),
    "force": Style(width=0.5, stroke="#000"),
    "closing": Style(width=0.5, stroke="#b3261e"),
}
_LABELLED = ("normal", "tangential", "coriolis", "sliding")


def plan_panel(plan: Plan, lang: str, scale_style: str, pid: str | None = None) -> Panel:
    """A velocity or acceleration plan at true size (plan mm): pole, vectors, points, lines."""
    from plans.scene.notation import pole_label

    kind = plan.kind
    pid = pid or f"{kind}-{phi_tag(plan.phi_deg)}"
    T = Transform(1.0)
    rec = Recording()
    placer = Placer()
    xy = {p.name: T(*p.xy) for p in plan.points}
    xs = [p[0] for p in xy.values()]
    ys = [p[1] for p in xy.values()]
    m = 10.0
    box = (min(xs) - m, min(ys) - m, max(xs) + m, max(ys) + m)

    rec.begin(f"{pid}-lines", "construction")
    for i, cl in enumerate(plan.lines):
        p0 = T(*cl.point)
        d = T.direction(*cl.direction)
        seg = clip_line(p0, d, box)
        if seg is None:
            continue
        rec.line(seg[0], seg[1], Style(width=0.18, stroke="#666", cls="construction"), f"{pid}-line-{i}")
        placer.add_line(list(seg))
    rec.end()

    rec.begin(f"{pid}-vectors", "vectors")
    seg_geoms = []
    for s in plan.segments:
        a, b = xy[s.start], xy[s.end]
        st = VECTOR_STYLES.get(s.kind, VECTOR_STYLES["absolute"])
        arrow(rec, a, b, st, f"{pid}-{ident(s.label)}", f"vector {s.kind}")
        seg_geoms.append((s, a, b))
        placer.add_line([a, b])
    rec.end()

    rec.begin(f"{pid}-points", "points")
    groups: dict[str, list[str]] = {}
    for p in plan.points:
        root = p.coincides_with or p.name
        while True:
            nxt = next((q.coincides_with for q in plan.points if q.name == root and q.coincides_with), None)
            if nxt is None:
                break
            root = nxt
        groups.setdefault(root, []).append(p.name)
    for root in groups:
        dot(rec, xy[root], 0.6 if root == plan.pole else 0.5, f"{pid}-pt-{ident(root)}")
        placer.add_disc(xy[root], 0.7)
    rec.end()

    rec.begin(f"{pid}-labels", "labels")
    for root, names in groups.items():
        c = xy[root]
        vx = vy = 0.0
        for _s, a, b in seg_geoms:
            for here, there in ((a, b), (b, a)):
                if math.dist(here, c) < 1e-6 and math.dist(here, there) > 1e-6:
                    L = math.dist(here, there)
                    vx -= (there[0] - here[0]) / L
                    vy -= (there[1] - here[1]) / L
        L = math.hypot(vx, vy)
        prefer = (vx / L, vy / L) if L > 1e-9 else None
        text = ", ".join(point_label(pole_label(n, scale_style, lang)) for n in names)
        lab = placer.place(text, c, LABEL_SIZE, prefer=prefer, gap=0.8)
        rec.text(lab, "label", f"{pid}-label-{ident(root)}")
    for s, a, b in seg_geoms:
        if s.kind not in _LABELLED or s.length_mm < 4.0:
            continue
        mid = ((a[0] + b[0]) / 2, (a[1] + b[1]) / 2)
        L = math.dist(a, b)
        nx, ny = -(b[1] - a[1]) / L, (b[0] - a[0]) / L
        lab = placer.place(s.label, mid, SMALL_SIZE + 0.5, prefer=(nx, ny), gap=0.8)
        rec.text(lab, f"vector-label {s.kind}", f"{pid}-{ident(s.label)}-label",
                 fill=VECTOR_STYLES[s.kind].stroke or "#000")
    for i, cl in enumerate(plan.lines):
        p0 = T(*cl.point)
        seg = clip_line(p0, T.direction(*cl.direction), box)
        if seg is None or not cl.label:
            continue
        text = line_label(cl.label, lang)
        # label near the end farther from the pole
        end = max(seg, key=lambda q: math.hypot(*q))
        lab = placer.place(text, end, SMALL_SIZE, gap=0.6)
        rec.text(lab, "line-label", f"{pid}-line-{i}-label", fill="#444")
    rec.end()

    quantity = "velocity" if kind == "velocity" else "acceleration"
    title = f"{tr(kind, lang)}, φ = {angle(plan.phi_deg, lang)}°"
    return finish(pid, kind, plan.phi_deg, rec, title, scale_text(quantity, plan.scale, scale_style, lang),
                  quantity=quantity, scale=plan.scale)


_LINE_WORDS_RU = ((re.compile(r"guide of link (\w+)"), r"напр. звена \1"),
                  (re.compile(r"slot of link (\w+)"), r"кулисы \1"),
                  (re.compile(r"guide of (\w+)"), r"напр. \1"))


def line_label(label: str, lang: str) -> str:
    """A construction line's label in the sheet's language (``∥ guide of B`` -> ``∥ напр. B``)."""
    if lang != "ru":
        return label
    for rx, repl in _LINE_WORDS_RU:
        label = rx.sub(repl, label)
    return label


def clip_line(p: Pt, d: Pt, box: tuple[float, float, float, float]) -> tuple[Pt, Pt] | None:
    """The part of the line p + t·d inside ``box`` (Liang–Barsky)."""
    t0, t1 = -1e12, 1e12
    for pi, di, lo, hi in ((p[0], d[0], box[0], box[2]), (p[1], d[1], box[1], box[3])):
        if abs(di) < 1e-15:
            if pi < lo or pi > hi:
                return None
            continue
        a, b = (lo - pi) / di, (hi - pi) / di
        t0, t1 = max(t0, min(a, b)), min(t1, max(a, b))
    if t0 >= t1:
        return None
    return (p[0] + t0 * d[0], p[1] + t0 * d[1]), (p[0] + t1 * d[0], p[1] + t1 * d[1])


# --------------------------------------------------------------------------- results table

_QUANTITY_NAMES = {"omega": "ω", "eps": "ε"}
_UNITS = {"m/s": "m/s", "m/s^2": "m/s^2", "rad/s": "rad/s", "rad/s^2": "rad/s^2", "N": "N", "N*m": "N*m",
          "N·m": "N*m"}


def quantity_text(q: str) -> str:
    head, _, rest = q.partition("_")
    if head in _QUANTITY_NAMES and rest:
        return f"{_QUANTITY_NAMES[head]}_{rest}"
    return q


def table_panel(rows: Sequence, lang: str, scale_style: str, phi: float, pid: str | None = None,
                extra: Sequence[tuple[str, ...]] = (), title_key: str = "table",
                part: tuple[int, int, int] | None = None) -> Panel:
    """Per position: quantity, segment, mm, scale, value read, exact, unit, difference %.

    ``rows`` are readings (``plans.construction.Reading``-like); ``extra`` are ready rows of
    eight cells (the balancing force three ways).  ``part`` = (start, stop, n): only those
    rows, as the table's part n (:func:`drawings.table_parts.parts`).
    """
    from plans.scene.notation import pole_label, resolve

    pid = pid or f"table-{phi_tag(phi)}"
    if part is not None and part[2] > 1:
        pid = f"{pid}-{part[2]}"
    header: tuple[str, ...] = (tr("quantity", lang), tr("segment", lang), tr("mm", lang), tr("scale", lang),
              tr("read", lang), tr("exact", lang), tr("unit", lang), tr("diff", lang))
    body: list[tuple[str, tuple[str, ...]]] = []
    for r in rows:
        seg = " ".join(point_label(pole_label(t, scale_style, lang)) for t in r.segment.split()) if r.segment \
            else "—"
        mm = "—"
        if r.length_mm is not None:
            mm = fmt(_clean(r.length_mm, r.ref * (r.scale or 1.0)), 4, lang)
        if r.scale is None:
            sc = "—"
        elif resolve(scale_style, lang)[1]:  # units per mm
            sc = fmt(1.0 / r.scale, 4, lang)
        else:
            sc = fmt(r.scale, 4, lang)
        unit = tr(_UNITS.get(r.unit, r.unit), lang) if _UNITS.get(r.unit, r.unit) in _UNIT_KEYS else r.unit
        cells: tuple[str, ...] = (quantity_text(r.quantity), seg, mm, sc, fmt(_clean(r.value, r.ref), 5, lang),
                 fmt(_clean(r.exact, r.ref), 5, lang), unit, _diff_cell(r, unit, lang))
        body.append((ident(r.quantity), cells))
    for cells in extra:
        body.append((ident(cells[0]), tuple(cells)))
    if part is not None:
        body = body[part[0]:part[1]]
    size = SMALL_SIZE + 0.3
    from .fonts import metrics

    mtr = metrics()
    widths = [0.0] * len(header)
    for cells in [header] + [c for _, c in body]:
        for i, t in enumerate(cells):
            lab = layout(t, 0, 0, size)
            widths[i] = max(widths[i], lab.box[2] - lab.box[0] + 3.0)
    del mtr
    rh = size * 1.75
    rec = Recording()
    x_edges = [0.0]
    for w in widths:
        x_edges.append(x_edges[-1] + w)
    n = len(body) + 1
    H = n * rh
    rec.begin(f"{pid}-grid", "grid")
    rec.polygon([(0, 0), (x_edges[-1], 0), (x_edges[-1], H), (0, H)], Style(width=0.5, cls="grid"))
    for i in range(1, n):
        rec.line((0, i * rh), (x_edges[-1], i * rh), Style(width=0.5 if i == 1 else 0.18, cls="grid"))
    for x in x_edges[1:-1]:
        rec.line((x, 0), (x, H), Style(width=0.18, cls="grid"))
    rec.end()
    rec.begin(f"{pid}-cells", "cells")
    for i, t in enumerate(header):
        lab = layout(t, (x_edges[i] + x_edges[i + 1]) / 2, rh / 2, size, "middle", "middle")
        rec.text(lab, "th", f"{pid}-h{i}")
    used: dict[str, int] = {}
    for j, (rid, cells) in enumerate(body, start=1):
        used[rid] = used.get(rid, 0) + 1
        rid2 = rid if used[rid] == 1 else f"{rid}-{used[rid]}"
        rec.begin(f"{pid}-row-{rid2}", "row")
        for i, t in enumerate(cells):
            yc = j * rh + rh / 2
            if i == 0 or i == 1 or i == 6:
                lab = layout(t, x_edges[i] + 1.5, yc, size, "start", "middle")
            else:
                lab = layout(t, x_edges[i + 1] - 1.5, yc, size, "end", "middle")
            rec.text(lab, "td")
        rec.end()
    rec.end()
    title = f"{tr(title_key, lang)}, φ = {angle(phi, lang)}°"
    if part is not None and part[2] > 1:
        title += " " + tr("continued", lang)
    return finish(pid, "table", phi, rec, title)


_UNIT_KEYS = {"m/s", "m/s^2", "rad/s", "rad/s^2", "N", "N*m"}


def _diff_cell(r, unit: str, lang: str) -> str:
    """Δ as ``solve`` and the check report define it (:func:`plans.units.percent`), %; the
    absolute difference with its unit where the exact value is zero."""
    from plans.units import clean, percent

    pct = percent(r.value, r.exact, r.ref)
    if pct is None:
        return f"{fmt(clean(r.value - r.exact, r.ref), 3, lang)} {unit}"
    return f"{pct:+.2f}".replace(".", "," if lang == "ru" else ".").replace("+0,00", "0,00").replace(
        "+0.00", "0.00").replace("-0,00", "0,00").replace("-0.00", "0.00")


def _clean(v: float, ref: float) -> float:
    """Round-off noise of a vanishing quantity shown as 0."""
    return 0.0 if abs(v) <= DUST * max(abs(ref), 1e-300) else v


def single(prims: Sequence[Prim]) -> None:  # pragma: no cover - debugging aid
    for p in prims:
        print(p.op, p.eid, p.pts[:2])


__all__ = ["Panel", "scheme_panel", "plan_panel", "table_panel", "finish", "scale_text",
           "auto_length_scale", "strokes_over_cycle", "cycle_size", "VECTOR_STYLES", "HAIR", "FILLED"]
