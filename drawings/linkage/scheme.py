"""The kinematic scheme of a position: links, joints, sliders, guides, the frame's pivots,
the centres of mass and ω1, at a standard drawing scale; the strokes and the size of the
mechanism over the cycle that fix the scheme's scale and the sliders' dead points."""

from __future__ import annotations

import cmath
import math
from dataclasses import dataclass

from drawings.paper.backend import MAIN, THICK, THIN, Pt, Recording, Style, Transform
from drawings.paper.common import Placer, angle, ident, phi_tag
from drawings.paper.i18n import tr
from drawings.paper.panel_frame import (
    LABEL_SIZE,
    Panel,
    finish,
    ratio_text,
    scale_text,
)
from drawings.paper.text import point_label
from plans.units import DUST

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
        from drawings.linkage.triad_marks import scheme_points

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
