"""Panels: one figure of the sheet each (scheme, plans, table, forces, lever).

A panel is drawn once, onto a :class:`Recording` in its own paper millimetres,
then normalised so its box (labels included) starts at (0, 0).  Layout only
moves panels; the recorded primitives are replayed onto the SVG backend.
"""

from __future__ import annotations

import math
import re
from collections.abc import Sequence

from drawings.linkage.scheme import (  # noqa: F401
    BLOCK_H,
    BLOCK_L,
    JOINT_R,
    SchemeGeometry,
    cross,
    cycle_size,
    fixed_pivot,
    glob_of,
    link_outline,
    link_shape,
    scheme_panel,
    strokes_over_cycle,
)
from drawings.paper.backend import FILLED, HAIR, Prim, Pt, Recording, Style, Transform
from drawings.paper.common import Placer, angle, arrow, dot, fmt, ident, phi_tag
from drawings.paper.i18n import tr

# the panel's frame and the scheme, importable from here as before
from drawings.paper.panel_frame import (  # noqa: F401
    LABEL_SIZE,
    PAD,
    SCALE_SIZE,
    SMALL_SIZE,
    STANDARD_RATIOS,
    TITLE_SIZE,
    Panel,
    auto_length_scale,
    finish,
    ratio_text,
    scale_text,
)
from drawings.paper.text import layout, point_label
from plans.kinematics.plan import Plan
from plans.units import DUST

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


def plan_panel(plan: Plan, lang: str, scale_style: str, pid: str | None = None) -> Panel:
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
    rows, as the table's part n (:func:`drawings.linkage.table_parts.parts`).
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
    from drawings.paper.fonts import metrics

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
