"""A velocity or acceleration plan on paper: the panel of a :class:`plans.kinematics.plan.Plan`
at true size (pole, vectors, points, construction lines, labels), and the vector styles
every polygon on a sheet shares.

Drawn by the linkage's sheets (:mod:`drawings.linkage`, which imports these names from
:mod:`drawings.linkage.panels` as before), the checker's marked sheet and the cycle's
dynamics sheet (the plans of velocity analogues): below the rooms of those sheets, so the
cycle's drawings need not import the linkage's, whose sheet set includes the cycle's.
"""

from __future__ import annotations

import math
import re

from drawings.paper.backend import Pt, Recording, Style, Transform
from drawings.paper.common import Placer, angle, arrow, dot, ident, phi_tag
from drawings.paper.i18n import tr
from drawings.paper.panel_frame import LABEL_SIZE, SMALL_SIZE, Panel, finish, scale_text
from drawings.paper.text import point_label
from plans.kinematics.plan import Plan

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


def on_paper(plan: Plan, margin: float
             ) -> tuple[Transform, Recording, Placer, dict[str, Pt], tuple[float, float, float, float]]:
    """A plan drawn at true size: its transform, a recording and a label placer, its points
    on the paper and the box ``margin`` mm around them (the construction lines clipped to it)."""
    T = Transform(1.0)
    xy = {p.name: T(*p.xy) for p in plan.points}
    xs = [p[0] for p in xy.values()]
    ys = [p[1] for p in xy.values()]
    return T, Recording(), Placer(), xy, (min(xs) - margin, min(ys) - margin, max(xs) + margin, max(ys) + margin)


def plan_panel(plan: Plan, lang: str, scale_style: str, pid: str | None = None, note: str | None = None) -> Panel:
    """A velocity or acceleration plan at true size (plan mm): pole, vectors, points, lines."""
    from plans.scene.notation import pole_label

    kind = plan.kind
    pid = pid or f"{kind}-{phi_tag(plan.phi_deg)}"
    T, rec, placer, xy, box = on_paper(plan, 10.0)

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
                  note, quantity=quantity, scale=plan.scale)


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
