"""The meshing of one pair as the gear sheet draws it: profiles, circles, the line of action,
the active part, the contact ratio read off the drawing, the zones of single and double
contact, over the field :mod:`plans.gears.meshing` constructed."""

from __future__ import annotations

import math
from collections.abc import Sequence

import numpy as np
import shapely

from drawings.gears_train import AXIS, LABEL, SMALL, tr
from drawings.linkage.panels import Panel, finish, ratio_text
from drawings.paper.backend import HAIR, MAIN, PAPER, THICK, THIN, Recording, Style
from drawings.paper.common import Placer, arrow, dot, fmt
from drawings.paper.text import layout
from plans.gears.meshing import Meshing

DASHED = Style(stroke="#000", width=0.25, dash=(3.0, 1.5), cls="working")
ACTIVE = Style(width=1.2, cls="active")


def _pt(z: complex) -> tuple[float, float]:
    """Construction mm (y up) -> panel paper mm (y down)."""
    return PAPER.z(z)


def _clipped(rec: Recording, pts: Sequence[complex], box: shapely.Geometry, style: Style, eid: str) -> None:
    line = shapely.LineString([(z.real, z.imag) for z in pts])
    part = line.intersection(box)
    geoms = [g for g in getattr(part, "geoms", [part]) if not g.is_empty and g.geom_type == "LineString"]
    for i, g in enumerate(geoms):
        rec.polyline([PAPER(x, y) for x, y in g.coords], style, f"{eid}-{i}" if i else eid)


def _on_field(z: complex, box: shapely.Geometry) -> tuple[complex, bool]:
    """``z`` and True inside the field, else where the ray from P toward it leaves the field."""
    if shapely.contains_xy(box, z.real, z.imag):
        return z, True
    part = shapely.LineString([(0.0, 0.0), (z.real, z.imag)]).intersection(box)
    x, y = max(shapely.get_coordinates(part), key=lambda c: math.hypot(*c))
    return complex(x, y), False


def _circle(O: complex, r: float, n: int = 720) -> list[complex]:
    return [O + r * complex(math.cos(t), math.sin(t)) for t in np.linspace(0, 2 * math.pi, n + 1)]


def meshing_panel(mg: Meshing, lang: str) -> Panel:
    """The pair at its enlargement, clipped to a square field about P (one figure drawn in
    the order a draftsman draws it: circles, teeth, centres, line of action, zones,
    construction, readings; hence its length)."""
    W = mg.window
    # the field: W either side of P, its rows where a field was asked for, else W above and
    # below P but only as far as the teeth go (plus 12 mm)
    near = [z for dw in mg.wheels for z in dw.outline if abs(z.real) <= W]
    ylo, yhi = mg.rows or (max(-W, min(min(z.imag for z in near) - 12.0, -12.0)),
                           min(W, max(max(z.imag for z in near) + 12.0, 12.0)))
    box = shapely.box(-W, ylo, W, yhi)
    rec = Recording()
    placer = Placer()
    p = mg.pair
    styles = {"pitch": AXIS, "base": THIN, "tip": THIN, "root": THIN, "working": DASHED}
    for dw in mg.wheels:
        rec.begin(f"wheel-{dw.name}", "wheel")
        for key, st in styles.items():
            if key == "working" and abs(dw.radii["working"] - dw.radii["pitch"]) < 0.05:
                continue
            _clipped(rec, _circle(dw.centre, dw.radii[key]), box, st, f"wheel-{dw.name}-{key}")
        _clipped(rec, list(dw.outline), box, THICK, f"wheel-{dw.name}-teeth")
        rec.end()
    # centre line O1O2 and the centres
    rec.begin("centres", "centres")
    ys = [dw.centre.imag for dw in mg.wheels]
    lo = max(min(ys) - 8, ylo)
    hi = min(max(ys + [30.0]) + 8, yhi)
    rec.line(PAPER(0.0, lo), PAPER(0.0, hi), AXIS, "centre-line")
    for i, dw in enumerate(mg.wheels):
        O = dw.centre
        sign = -1 if O.imag < 0 else 1
        name = f"O_{dw.name}"
        if ylo <= O.imag <= yhi:
            dot(rec, _pt(O), 0.9, f"centre-{dw.name}")
            rec.text(placer.place(name, _pt(O), LABEL, (1.0, 0.0)), "label", f"label-O{dw.name}")
        else:  # the centre is off the field: say where it is
            y = ylo if sign < 0 else yhi
            arrow(rec, PAPER(0.0, y - sign * 12), PAPER(0.0, y), THIN, f"to-O{dw.name}", "pointer")
            txt = f"{name}: {fmt(abs(O.imag), 4, lang)} мм" if lang == "ru" else f"{name}: {fmt(abs(O.imag), 4)} mm"
            rec.text(layout(txt, *PAPER(3.0, y - sign * (6 + 5 * i)), SMALL, "start", "middle"), "label",
                     f"label-O{dw.name}")
    rec.end()
    # line of action, the active part, the zones
    rec.begin("line-of-action", "line-of-action")
    u = (mg.N2 - mg.N1) / abs(mg.N2 - mg.N1)
    along = [((z - mg.N1) * u.conjugate()).real for z in (mg.N1, mg.N2, mg.B1, mg.B2)]
    _clipped(rec, [mg.N1 + (min(along) - 12) * u, mg.N1 + (max(along) + 12) * u], box, MAIN, "N1N2")
    rec.line(_pt(mg.B1), _pt(mg.B2), ACTIVE, "B1B2")
    nrm = 1j * u
    (d1a, d1b), (sa, sb), (d2a, d2b) = mg.zones()  # complex points on N1N2
    for i, (a, b) in enumerate(((d1a, d1b), (d2a, d2b))):
        for off in (3.0, 4.4):
            rec.line(_pt(a + off * nrm), _pt(b + off * nrm), THIN, f"zone-double-{i}-{off:g}")
    if abs(sb - sa) > 1e-6:
        rec.line(_pt(sa + 3.7 * nrm), _pt(sb + 3.7 * nrm), THIN, "zone-single")
    for i, z in enumerate((d1b, d2a)):
        rec.line(_pt(z - 2 * nrm), _pt(z + 6 * nrm), THIN, f"zone-tick-{i}")
    rec.end()
    # a tangency point N off the field (an internal pair's N2 lies far out): an arrow at the
    # field's edge toward it, labelled with its distance from P
    shown = {name: _on_field(z, box) for name, z in (("N_1", mg.N1), ("N_2", mg.N2), ("B_1", mg.B1),
                                                     ("B_2", mg.B2), ("P", 0j))}
    for name, (z, inside) in shown.items():
        if inside:
            dot(rec, _pt(z), 0.8, f"point-{name.replace('_', '')}")
            placer.add_disc(_pt(z), 1.0)
        else:
            arrow(rec, _pt(z - 10 * u * (1 if (z.conjugate() * u).real > 0 else -1)), _pt(z), THIN,
                  f"to-{name.replace('_', '')}", "pointer")
    placer.add_line([_pt(shown["N_1"][0]), _pt(shown["N_2"][0])])
    for name, z, pref in (("N_1", mg.N1, (-1.0, 0.0)), ("N_2", mg.N2, (1.0, 0.0)), ("B_1", mg.B1, (-1.0, 0.3)),
                          ("B_2", mg.B2, (1.0, -0.3)), ("P", 0j, (1.0, 0.4))):
        at, inside = shown[name]
        text = name if inside else (f"{name}: {fmt(abs(z), 4, lang)} " + ("мм" if lang == "ru" else "mm"))
        if inside:
            placed = placer.place(text, _pt(at), LABEL, pref)
        else:  # inside the field, below the arrow's head (above it on the bottom edge), ending at the edge
            right = at.real > 0
            dy = 5.0 if at.imag < ylo + 6.0 else -5.0
            placed = layout(text, *PAPER(at.real + (-2.0 if right else 2.0), at.imag + dy), LABEL,
                            "end" if right else "start", "middle")
        rec.text(placed, "label", f"label-{name.replace('_', '')}")
    mid_d = (d1a + d1b) / 2 - 14 * nrm
    rec.text(layout(tr("double", lang), *_pt(mid_d), SMALL, "middle", "middle"), "note", "zone-double-label")
    if abs(sb - sa) > 1e-6:
        mid_s = (sa + sb) / 2 - 14 * nrm
        rec.text(layout(tr("single", lang), *_pt(mid_s), SMALL, "middle", "middle"), "note", "zone-single-label")
    # the draftsman's construction of gear 1's flank through P
    rec.begin("involute-construction", "construction")
    for i, (T, q) in enumerate(mg.construction):
        rec.line(_pt(T), _pt(q), HAIR, f"tangent-{i}")
        dot(rec, _pt(T), 0.45, f"tangent-point-{i}")
        dot(rec, _pt(q), 0.45, f"laid-off-{i}")
    rec.end()
    # the pressure angle at P
    rec.text(layout(f"α_w = {fmt(math.degrees(p.alpha_w), 5, lang)}°", *PAPER(-W + 4.0, yhi - 8.0), LABEL, "start", "middle"),
             "note", "alpha-w")
    eps = (f"ε = B_{{1}}B_{{2}}/p_{{b}} = {fmt(mg.b1b2, 4, lang)}/{fmt(mg.p_b, 4, lang)} = "
           f"{fmt(mg.contact_ratio_drawn, 3, lang)} ({tr('drawn', lang)}); "
           f"ε = {fmt(p.contact_ratio, 5, lang)} ({tr('exact', lang)})")
    rec.text(layout(eps, *PAPER(-W, ylo - 6.0), LABEL, "start", "middle"), "note", "contact-ratio")
    rec.polygon([PAPER(-W, yhi), PAPER(W, yhi), PAPER(W, ylo), PAPER(-W, ylo)], Style(stroke="#999", width=0.18, cls="field"), "field")
    g1, g2 = p.gears
    title = f"{tr('meshing', lang)} {g1}–{g2}"
    return finish(f"meshing-{g1}-{g2}", "meshing", None, rec, title, f"M {ratio_text(mg.k * 1000.0, lang)}")
