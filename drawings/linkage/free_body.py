"""A link drawn free, as the course draws a group or the crank apart: its links and slots at
μl, each load and reaction an arrow at μF from its point (too short ones lengthened and
marked), each couple an arc, the points named; the forces' labels as the textbook writes them."""

from __future__ import annotations

import cmath
import math
import re
from collections.abc import Sequence

import numpy as np

from drawings.linkage.panels import (
    BLOCK_L,
    JOINT_R,
    LABEL_SIZE,
    SMALL_SIZE,
    link_outline,
    link_shape,
)
from drawings.paper.backend import Pt, Recording, Style, Transform
from drawings.paper.common import Placer, arrow, dot, ident
from drawings.paper.text import point_label
from plans.forces.shared import nice_scale
from plans.units import DUST

LOAD = Style(width=0.45, stroke="#000")
REACTION = Style(width=0.45, stroke="#b3261e")
ARM = Style(width=0.18, stroke="#555", dash=(1.5, 1.0))
FBD_ARROW_MM = 32.0
MIN_ARROW_MM = 4.0  # a force drawn shorter than this at μF is lengthened and marked †
COUPLE_STEP_MM = 3.5  # the next couple at a point already holding one: a larger arc

_NAME = re.compile(r"^(Phi|M_Phi|[A-Z])(\d+)(.*)$")
_FRICTION = re.compile(r"^([MF])f(\d+)$")


def force_label(label: str, lang: str = "en") -> str:
    """``F21^τ`` -> ``F_21^τ``, ``Phi2`` -> ``Φ_2``, ``M_Phi2'`` -> ``M_Φ2'``, ``F_bal`` -> ``F_ур`` (ru)."""
    if label == "F_bal":
        return "F_ур" if lang == "ru" else "F_bal"
    f = _FRICTION.match(label)
    if f:  # a friction couple or force of a pair: M_f21, F_f36
        return f"{f.group(1)}_{{f{f.group(2)}}}"
    if label.startswith("M_Phi"):
        return "M_{Φ" + label[5:].rstrip("'") + "}" + "'" * (len(label) - len(label.rstrip("'")))
    m = _NAME.match(label)
    if m:
        head = "Φ" if m.group(1) == "Phi" else m.group(1)
        return f"{head}_{m.group(2)}{m.group(3)}"
    return label.replace("Phi", "Φ")




def fbd_scale(values: Sequence[complex], cycle: float = 0.0, factor: float = 1.0) -> float:
    """μF of a free body: round, its longest force FBD_ARROW_MM at most; forces that are zero
    up to round-off against the cycle's largest (``cycle``) take the cycle's scale."""
    longest = max((abs(v) for v in values), default=0.0)
    if longest <= DUST * cycle:
        longest = cycle
    return nice_scale(longest, FBD_ARROW_MM * factor)


def largest_of(arrays) -> float:
    return max((float(np.max(np.abs(a))) for a in arrays), default=0.0)


def moment_arc(rec: Recording, placer: Placer, c: tuple[float, float], M: float, label: str,
                eid: str, r: float = 6.0, taken: dict[tuple[float, float], int] | None = None) -> None:
    """A couple as an arc with a filled head, counter-clockwise for M > 0; the couples drawn at
    one point (``taken`` counts them) spread apart: each next one on a larger arc, on the
    other side of the point."""
    if M == 0:
        return
    i = 0
    if taken is not None:
        key = (round(c[0], 3), round(c[1], 3))
        i = taken.get(key, 0)
        taken[key] = i + 1
    r += COUPLE_STEP_MM * i
    sense = 1 if M > 0 else -1

    def crosses(start: float) -> bool:  # the arc (and its head) over a label already placed
        ts = np.radians(np.linspace(start, start - sense * 125, 24))
        xs, ys = c[0] + r * np.cos(ts), c[1] + r * np.sin(ts)
        return any(bool(np.any((xs > b[0]) & (xs < b[2]) & (ys > b[1]) & (ys < b[3]))) for b in placer.boxes)

    first = 200 + 180 * (i % 2)
    start = next((a for a in (first, first + 90, first + 180, first + 270) if not crosses(a)), first)
    a0, a1 = math.radians(start), math.radians(start - sense * 110)  # paper angles (y down: ccw is −)
    rec.arc(c, r, a0, a1, Style(width=0.35, stroke="#1f4e9c", cls="moment"), eid)
    end = (c[0] + r * math.cos(a1), c[1] + r * math.sin(a1))
    t = -sense
    tx, ty = -math.sin(a1) * t, math.cos(a1) * t
    tip = (end[0] + tx * 3.0, end[1] + ty * 3.0)
    rec.polygon([tip, (end[0] - ty * 0.8, end[1] + tx * 0.8), (end[0] + ty * 0.8, end[1] - tx * 0.8)],
                Style(stroke=None, width=0, fill="#1f4e9c", cls="head"))
    mid = (a0 + a1) / 2
    lab = placer.place(label, (c[0] + (r + 1) * math.cos(mid), c[1] + (r + 1) * math.sin(mid)), SMALL_SIZE + 0.5,
                       prefer=(math.cos(mid), math.sin(mid)))
    rec.text(lab, "label", f"{eid}-label", fill="#1f4e9c")


def legible(p0: Pt, p1: Pt) -> tuple[Pt, bool]:
    """The head of a vector drawn from p0: at least MIN_ARROW_MM long (True when lengthened,
    so that the drawing marks it as not to scale); a zero vector stays zero."""
    L = math.dist(p0, p1)
    if 0 < L < MIN_ARROW_MM:
        return (p0[0] + (p1[0] - p0[0]) * MIN_ARROW_MM / L, p0[1] + (p1[1] - p0[1]) * MIN_ARROW_MM / L), True
    return p1, False


def short_note(lang: str) -> str:
    """The note under a panel's title that explains the † of the lengthened vectors."""
    return (f"† короче {MIN_ARROW_MM:g} мм в масштабе μF: показаны не в масштабе" if lang == "ru"
            else f"† shorter than {MIN_ARROW_MM:g} mm at μF: drawn not to scale")


def short_mark(lang: str) -> str:
    """The same, brief, on a free body's scale line (no line more under its title)."""
    return (f"† — {MIN_ARROW_MM:g} мм, не в масштабе" if lang == "ru"
            else f"†: {MIN_ARROW_MM:g} mm, not to scale")


def force_at(rec: Recording, placer: Placer, T: Transform, r: complex, F: complex, mu_f: float,
              label: str, style: Style, eid: str) -> bool:
    """A force drawn from its point of application, labelled at its head; one too short to
    see at μF is drawn MIN_ARROW_MM long and its label marked † (returns True then)."""
    if abs(F) * mu_f <= DUST * FBD_ARROW_MM:  # zero up to round-off: nothing to draw
        return False
    p0 = T.z(r)
    d = F * mu_f
    p1, short = legible(p0, (p0[0] + d.real, p0[1] - d.imag))
    if short:
        label += "†"
    arrow(rec, p0, p1, style, eid, "force " + ("reaction" if style is REACTION else "load"))
    placer.add_line([p0, p1])
    L = math.dist(p0, p1) or 1.0
    lab = placer.place(label, p1, SMALL_SIZE + 0.5, prefer=((p1[0] - p0[0]) / L, (p1[1] - p0[1]) / L), gap=0.8)
    rec.text(lab, "label", f"{eid}-label", fill=style.stroke or "#000")
    return short


def draw_links(rec: Recording, placer: Placer, scene, kin, k: int, links: Sequence[int], T: Transform,
                pid: str) -> dict[str, complex]:
    """Links (thick), slider blocks, joint circles and point labels; returns the points drawn."""
    pts: dict[str, complex] = {}
    for lid in links:
        link = scene.links[lid]
        for n, z in link.points.items():
            pts.setdefault(n, complex(kin.point_on(lid, z)[0][k]))
        kind, names = link_shape(scene, lid)
        link_outline(rec, placer, kind, [T.z(pts[n]) for n in names], f"{pid}-link-{lid}")
    for jt in scene.joints:  # a slot of the group's own link: drawn whole, through its block
        if jt.kind == "P" and jt.guide is not None and jt.guide.link in links and jt.slider in links \
                and jt.guide.link != scene.frame and jt.point in pts:
            draw_slot(rec, placer, scene, kin, k, jt, pts, T, pid)
    for jt in scene.joints:
        if not (set(jt.links) & set(links)) or jt.point not in pts:
            continue
        c = T.z(pts[jt.point])
        if jt.kind == "P" and jt.guide is not None and jt.slider in links:
            g = jt.guide
            th = 0.0 if g.link == scene.frame else float(kin.theta(g.link)[k])
            ang = -(th + g.angle)
            ux, uy = math.cos(ang), math.sin(ang)
            corners = [(c[0] + sx * 6 * ux - sy * 3.5 * uy, c[1] + sx * 6 * uy + sy * 3.5 * ux)
                       for sx, sy in ((-1, -1), (1, -1), (1, 1), (-1, 1))]
            rec.polygon(corners, Style(width=0.5, fill="#fff", cls="slider"), f"{pid}-slider-{ident(jt.point)}")
            placer.add_poly(corners)
            # the guide the group is cut from: a thin dash-dot line
            a0 = (c[0] - 14 * ux, c[1] - 14 * uy)
            a1 = (c[0] + 14 * ux, c[1] + 14 * uy)
            rec.line(a0, a1, Style(width=0.18, stroke="#333", dash=(6.0, 1.0, 1.0, 1.0), cls="axis"))
    done: set[str] = set()
    for jt in scene.joints:
        if jt.kind == "R" and (set(jt.links) & set(links)) and jt.point in pts and jt.point not in done:
            done.add(jt.point)
            c = T.z(pts[jt.point])
            rec.circle(c, JOINT_R, Style(width=0.35, fill="#fff", cls="joint"), f"{pid}-joint-{ident(jt.point)}")
            placer.add_disc(c, JOINT_R + 0.3)
    return pts


def draw_slot(rec: Recording, placer: Placer, scene, kin, k: int, jt, pts: dict[str, complex], T: Transform,
          pid: str) -> None:
    """The slot of a moving guide (a coulisse) as a thick line along the guide from the
    carrier's farthest points through the slider's pin and past its block, so that the block
    sits on its link as on the scheme."""
    g = jt.guide
    u = cmath.exp(1j * (float(kin.theta(g.link)[k]) + g.angle))
    G = complex(kin.point_on(g.link, g.origin)[0][k])
    carrier = scene.links[g.link]
    ss = [((complex(kin.point_on(g.link, z)[0][k]) - G) * u.conjugate()).real for n, z in carrier.points.items()
          if not n.startswith("S")] + [((pts[jt.point] - G) * u.conjugate()).real]
    over = (BLOCK_L / 2 + 4.0) / T.scale  # past the block's ends on the paper
    a0, a1 = T.z(G + (min(ss) - over) * u), T.z(G + (max(ss) + over) * u)
    rec.line(a0, a1, Style(width=0.7, stroke="#000", cls="slot"), f"{pid}-slot-{ident(jt.point)}")
    placer.add_line([a0, a1])


def label_points(rec: Recording, placer: Placer, pts: dict[str, complex], T: Transform, pid: str) -> None:
    cx = sum(pts.values()) / max(len(pts), 1)
    for n, z in pts.items():
        c = T.z(z)
        away = z - cx
        L = abs(away) or 1.0
        if n.startswith("S"):
            rec.circle(c, 1.0, Style(width=0.25, fill="#fff", cls="centre"))
            dot(rec, c, 0.4)
        lab = placer.place(point_label(n), c, LABEL_SIZE, prefer=(away.real / L, -away.imag / L), gap=1.8)
        rec.text(lab, "label", f"{pid}-label-{ident(n)}")
