"""The gear sheets: the meshing of one pair (profiles, circles, line of action, the active
part, the contact ratio read off the drawing, the zones of single and double contact) and
the train (its unfolded scheme, the velocity plan of linear velocities and the ray diagram
of angular velocities), from :mod:`plans.gears`."""

from __future__ import annotations

import math
from collections.abc import Sequence
from dataclasses import dataclass
from pathlib import Path

import numpy as np
import shapely

from drawings.linkage.panels import Panel, finish, ratio_text
from drawings.paper.backend import HAIR, MAIN, PAPER, THICK, THIN, Recording, Style
from drawings.paper.common import Placer, arrow, dot, fmt
from drawings.paper.fonts import choose, drawing
from drawings.paper.i18n import lookup
from drawings.paper.i18n import tr as words
from drawings.paper.panel_frame import ruled_grid
from drawings.paper.sheet import Sheet, SheetSpec, compose, fits_empty, sheet_spec
from drawings.paper.text import layout
from plans.errors import InputError, Said
from plans.gears.meshing import Meshing
from plans.gears.model import GearFile
from plans.gears.solution import GearsSolution, solve_file
from plans.gears.solve import GearSolution
from plans.language import SHEET_WORDS

AXIS = Style(stroke="#000", width=0.25, dash=(8.0, 1.5, 1.0, 1.5), cls="axis")
DASHED = Style(stroke="#000", width=0.25, dash=(3.0, 1.5), cls="working")
ACTIVE = Style(width=1.2, cls="active")
LABEL = 3.5
SMALL = 2.5

_WORDS = {
    "meshing": ("Картина зацепления", "Meshing of the pair"),
    "results": ("Геометрия зубчатых передач", "Geometry of the pairs"),
    "scheme": ("Схема механизма (развёрнутая)", "Scheme of the train (unfolded)"),
    "vplan": ("План линейных скоростей", "Plan of linear velocities"),
    "rays": ("План угловых скоростей", "Plan of angular velocities"),
    "speeds": ("Частоты вращения", "Speeds"),
    "synthesis": ("Подбор чисел зубьев 2K-H", "Numbers of teeth of the 2K-H train"),
    "double": ("двухпарное", "double"),
    "single": ("однопарное", "single"),
    "exact": ("точно", "exact"),
    "drawn": ("по чертежу", "drawn"),
    "shaft": ("Вал", "Shaft"),
    "willis": ("n, об/мин (Виллис)", "n, rpm (Willis)"),
    "plan": ("n, об/мин (план)", "n, rpm (plan)"),
    "quantity": ("Величина", "Quantity"),
    "pair": ("Пара", "Pair"),
    "gear": ("колесо", "gear"),
    "title": ("Зубчатая передача", "Gear train"),
}


tr = lookup(_WORDS)


def unit_word(unit: str, lang: str) -> str:
    """The file's length unit as the sheet writes it: мм on a Russian sheet."""
    return words(f"unit_{unit}", lang) if f"unit_{unit}" in SHEET_WORDS else unit


@dataclass(frozen=True)
class GearDrawing:
    """Everything drawn for a gear file: the solution, the meshing, the panels and sheets."""

    file: GearFile
    solution: GearSolution
    meshing: Meshing | None
    spec: SheetSpec
    panels: tuple[Panel, ...]
    sheets: tuple[Sheet, ...]

    def _repr_svg_(self) -> str:
        return self.sheets[0].svg()


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
    # the field: W either side of P, and in height only as far as the teeth go (plus 12 mm)
    near = [z for dw in mg.wheels for z in dw.outline if abs(z.real) <= W]
    ylo = max(-W, min(min(z.imag for z in near) - 12.0, -12.0))
    yhi = min(W, max(max(z.imag for z in near) + 12.0, 12.0))
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
        else:  # inside the field, below the arrow's head, ending at the edge
            right = at.real > 0
            placed = layout(text, *PAPER(at.real + (-2.0 if right else 2.0), at.imag - 5.0), LABEL,
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


def _grid(rows: Sequence[Sequence[str]], pid: str) -> Recording:
    """A ruled table, first row the header."""
    size = SMALL + 0.3
    ncol = max(len(r) for r in rows)
    widths = [0.0] * ncol
    for r in rows:
        for i, t in enumerate(r):
            lab = layout(t, 0, 0, size)
            widths[i] = max(widths[i], lab.box[2] - lab.box[0] + 3.0)
    xs = [0.0]
    for w in widths:
        xs.append(xs[-1] + w)
    rh = size * 1.75
    rec = Recording()
    ruled_grid(rec, pid, xs, len(rows), rh)
    for j, r in enumerate(rows):
        for i, t in enumerate(r):
            anchor, x = ("start", xs[i] + 1.5) if i == 0 else ("middle", (xs[i] + xs[i + 1]) / 2)
            rec.text(layout(t, x, (j + 0.5) * rh, size, anchor, "middle"), "cell", f"{pid}-c{j}-{i}")
    return rec


def results_panel(sol: GearSolution, lang: str) -> Panel:
    gf = sol.file
    k = gf.to_unit
    head = [tr("quantity", lang)]
    cols = []
    for p in sol.pairs:
        for w in p.wheels:
            head.append(f"{p.gears[0]}–{p.gears[1]}: {w.name}")
            cols.append((p, w))

    def f(v: float, d: int = 4) -> str:
        s = f"{v:.{d}f}"
        return s.replace(".", ",") if lang == "ru" else s

    rows = [head]
    spec = [
        ("z", lambda p, w: str(w.z)),
        ("x", lambda p, w: f(w.x, 5)),
        ("α_w, °", lambda p, w: f(math.degrees(p.alpha_w), 4)),
        (f"a_w, {unit_word(gf.unit, lang)}", lambda p, w: f(p.a_w * k, 3)),
        ("y", lambda p, w: f(p.y, 5)),
        ("Δy", lambda p, w: f(p.delta_y, 5)),
        ("r", lambda p, w: f(w.pitch * k, 3)),
        ("r_b", lambda p, w: f(w.base * k, 3)),
        ("r_a", lambda p, w: f(w.tip * k, 3)),
        ("r_f", lambda p, w: f(w.root * k, 3)),
        ("r_w", lambda p, w: f(w.working * k, 3)),
        ("α_a, °", lambda p, w: f(math.degrees(w.tip_angle), 3)),
        ("s", lambda p, w: f(w.thickness * k, 3)),
        ("s_a", lambda p, w: f(w.tip_thickness * k, 3)),
        ("s_a/m", lambda p, w: f(w.tip_thickness / p.m, 3)),
        ("ε", lambda p, w: f(p.contact_ratio, 4)),
    ]
    for name, fn in spec:
        rows.append([name] + [fn(p, w) for p, w in cols])
    rec = _grid(rows, "results")
    return finish("results", "table", None, rec, tr("results", lang))


GAP = 26.0  # mm between the gears' columns on the unfolded scheme
TICK = 2.0  # mm, half the width of a gear's symbol (its face) along the shaft
BEARING = (6.0, 2.5)  # mm, a radial bearing's length along the shaft and its half height
FRAME = Style(width=0.25)  # the frame's hatching (drawn with the class "hatch")


def _bearing(rec: Recording, x: float, y: float, eid: str, fixed: bool = True) -> None:
    """GOST 2.770 radial bearing on the frame: two short lines along the shaft above and below
    it, the frame's hatching behind them (``fixed``), or alone where it sits on a carrier."""
    L, hh = BEARING
    for side in (-1, 1):
        yy = y + side * hh
        rec.line((x - L / 2, yy), (x + L / 2, yy), MAIN, f"{eid}{'-top' if side < 0 else '-bottom'}")
        if fixed:
            rec.line((x, yy), (x, yy + side * 1.5), MAIN)
            rec.hatch((x - L / 2, yy + side * 1.5), (x + L / 2, yy + side * 1.5), -side, FRAME, 1.5, 1.5)


def _rigid(rec: Recording, x: float, y: float, eid: str) -> None:
    """GOST 2.770 fixed (keyed) joint of a part on its shaft: a cross on the shaft."""
    d = 1.3
    rec.line((x - d, y - d), (x + d, y + d), MAIN, f"{eid}-a")
    rec.line((x - d, y + d), (x + d, y - d), MAIN, f"{eid}-b")


def scheme_panel(sol: GearSolution, lang: str, f: float = 1.0) -> Panel:
    """The unfolded train in GOST 2.770 symbols: every shaft a thick line on its axis, held in
    radial bearings on the frame; every gear a line of its working diameter with its face
    ticks, fixed on its shaft by a cross (a planet turning free on the carrier's pin);
    a ring gear's teeth inward; a held shaft's gear hatched to the frame; the carrier H a
    thick bracket from its shaft to the planets' pins.  ``f`` magnifies the engine's μ_l."""
    plan = sol.plan
    assert plan is not None
    gf = sol.file
    mu = plan.mu_l * f / 1000.0  # paper mm per mm
    rec = Recording()
    col: dict[str, float] = {}
    x = GAP
    for p in sol.pairs:
        for w in p.wheels:
            if w.name not in col:
                col[w.name] = x
                x += GAP
    radii: dict[str, float] = {}
    for p in sol.pairs:
        for w in p.wheels:
            radii[w.name] = w.working * 1e3 * mu

    def Y(shaft: str) -> float:
        return -plan.axes[shaft] * 1e3 * mu

    carriers = {n for n, s in gf.shafts.items() if any(t.carrier == n for t in gf.shafts.values())}
    held = {n for n, s in gf.shafts.items() if s.speed_rpm == 0 and s.carrier is None}
    x_end = x
    # shafts: the centre line, the thick shaft over its gears, a bearing at each end
    for n, s in gf.shafts.items():
        y = Y(n)
        on = [col[g] for g, gg in gf.gears.items() if gg.shaft == n and g in col]
        if s.carrier is None:
            rec.line((0.0, y), (x_end + 6.0, y), AXIS, f"axis-{n}")
        if not on:
            continue
        lo, hi = min(on), max(on)
        if s.carrier is None and n not in held:
            lo, hi = min(lo, 6.0), hi + 8.0
            rec.line((lo, y), (hi, y), THICK, f"shaft-{n}")
            _bearing(rec, lo + BEARING[0] / 2 + 1.0, y, f"bearing-{n}-0")
            if n not in carriers:
                _bearing(rec, hi - BEARING[0] / 2 - 1.0, y, f"bearing-{n}-1")
        elif s.carrier is not None:  # a planet's pin on the carrier
            rec.line((lo - 4.0, y), (x_end + 4.0, y), THICK, f"shaft-{n}")
    for name, cx in col.items():
        g = gf.gears[name]
        y = Y(g.shaft)
        r = radii[name]
        top, bottom = y - r, y + r
        rec.line((cx, top), (cx, bottom), THICK, f"gear-{name}")
        for yy in (top, bottom):  # the face: the teeth's width along the shaft
            rec.line((cx - TICK, yy), (cx + TICK, yy), THICK, f"gear-{name}-face{'t' if yy == top else 'b'}")
        if g.internal:  # a ring: its rim outward, the teeth inward
            for side, yy in ((-1, top), (1, bottom)):
                rec.line((cx, yy), (cx, yy + side * 3.0), THICK, f"gear-{name}-ring{side}")
        if g.shaft in held:  # held: fixed to the frame
            for side, yy in ((-1, top), (1, bottom)):
                edge = yy + side * (3.0 if g.internal else 0.0)
                rec.hatch((cx - 3.0, edge), (cx + 3.0, edge), -side, FRAME, 1.5, 1.5)
        elif gf.shafts[g.shaft].carrier is not None:
            _bearing(rec, cx, y, f"pin-bearing-{name}", fixed=False)
        else:
            _rigid(rec, cx, y, f"fix-{name}")
        rec.text(layout(name, cx + TICK + 1.0, top - 1.5, LABEL, "start", "bottom"), "label", f"label-gear-{name}")
    for n in sorted(carriers):  # carriers: a bracket from the central axis to each planet pin
        planets = [q for q, t in gf.shafts.items() if t.carrier == n]
        y0 = Y(n)
        xc = x_end + 4.0
        for q in planets:
            rec.polyline([(xc, Y(q)), (xc, y0)], THICK, f"carrier-{n}-{q}")
        rec.line((xc, y0), (xc + 14.0, y0), THICK, f"shaft-{n}")
        _bearing(rec, xc + 9.0, y0, f"bearing-{n}")
        rec.text(layout(n, xc + 2.0, y0 - 2.5, LABEL, "start", "bottom"), "label", f"label-carrier-{n}")
    return finish("train-scheme", "train-scheme", None, rec, tr("scheme", lang),
                  f"μ_l = {fmt(plan.mu_l * f, 4, lang)} {'мм/м' if lang == 'ru' else 'mm/m'}")


def velocity_panel(sol: GearSolution, lang: str, f: float = 1.0) -> Panel:
    """The plan of linear velocities beside the scheme (its heights the scheme's), each
    shaft's line through its known points; ``f`` magnifies the engine's plan (μ × f)."""
    plan = sol.plan
    assert plan is not None
    rec = Recording()
    placer = Placer()
    ys = [pt[1] * f for ln in plan.lines.values() for _, pt in ln.points] + \
        [y * plan.mu_l * f for y in plan.axes.values()]
    y0, y1 = min(ys) - 8.0, max(ys) + 8.0
    rec.line((0.0, -y0), (0.0, -y1), AXIS, "radial-line")
    done: set[str] = set()
    for n, ln in plan.lines.items():
        pts = [(nm, (q[0] * f, q[1] * f)) for nm, q in ln.points]
        if len({round(p[1], 6) for _, p in pts}) < 2:
            pts.append(("", (ln.p1[0] * f, ln.p1[1] * f)))
        lo = min(pts, key=lambda t: t[1][1])[1]
        hi = max(pts, key=lambda t: t[1][1])[1]
        rec.line(_pt(complex(*lo)), _pt(complex(*hi)), MAIN, f"line-{n}")
        placer.add_line([_pt(complex(*lo)), _pt(complex(*hi))])
        mid = ((lo[0] + hi[0]) / 2, (lo[1] + hi[1]) / 2)
        rec.text(placer.place(n, _pt(complex(*mid)), LABEL, (1.0, 0.0)), "label", f"label-line-{n}")
        for name, (vx, vy) in pts:
            if not name or name in done:
                continue
            done.add(name)
            if abs(vx) > 1e-6:
                arrow(rec, (0.0, -vy), (vx, -vy), THIN, f"v-{name}", "vector")
            dot(rec, (vx, -vy), 0.6, f"pt-{name}")
            rec.text(placer.place(name, (vx, -vy), SMALL + 0.5, (1.0, -0.5)), "label", f"label-{name}")
    txt = f"μ_v = {fmt(plan.mu_v * f, 4, lang)} {'мм/(м/с)' if lang == 'ru' else 'mm/(m/s)'}"
    return finish("velocity-plan", "velocity-plan", None, rec, tr("vplan", lang), txt)


def rays_panel(sol: GearSolution, lang: str, f: float = 1.0) -> Panel:
    """The plan of angular velocities: rays from the pole O_ω parallel to the shafts' lines cut
    the reference line at h; ``f`` magnifies it (h and the intercepts; μ_ω × f)."""
    plan = sol.plan
    assert plan is not None
    rec = Recording()
    placer = Placer()
    h = plan.h * f
    xs = [ln.intercept * f for ln in plan.lines.values()] + [0.0]
    lo, hi = min(xs) - 10.0, max(xs) + 10.0
    rec.line(PAPER(lo, h), PAPER(hi, h), MAIN, "reference-line")
    dot(rec, (0.0, 0.0), 0.8, "pole")
    rec.text(layout("O_ω", 2.0, 3.5, LABEL, "start", "middle"), "label", "label-pole")
    rec.line((0.0, 0.0), PAPER(0.0, h + 4.0), AXIS, "pole-normal")
    placer.add_line([PAPER(lo, h), PAPER(hi, h)])
    for n, ln in plan.lines.items():
        rec.line((0.0, 0.0), (ln.intercept * f, -h), THIN, f"ray-{n}")
        placer.add_line([(0.0, 0.0), (ln.intercept * f, -h)])
        dot(rec, (ln.intercept * f, -h), 0.6, f"omega-{n}")
    for n, ln in plan.lines.items():
        rec.text(placer.place(f"ω_{n}", (ln.intercept * f, -h), SMALL + 0.5, (0.0, -1.0)), "label",
                 f"label-omega-{n}")
    rec.text(layout(f"h = {fmt(h, 3, lang)}", 2.0, -h / 2, SMALL, "start", "middle"), "note", "pole-distance")
    txt = f"μ_ω = {fmt(plan.mu_omega * f, 4, lang)} {'мм/(рад/с)' if lang == 'ru' else 'mm/(rad/s)'}"
    return finish("ray-diagram", "ray-diagram", None, rec, tr("rays", lang), txt)


def speeds_panel(sol: GearSolution, lang: str) -> Panel:
    assert sol.omega is not None and sol.plan is not None
    rows = [[tr("shaft", lang), tr("willis", lang), tr("plan", lang), "ω, " + ("рад/с" if lang == "ru" else "rad/s")]]
    for n, w in sol.omega.items():
        wp = sol.plan.lines[n].omega
        rows.append([n, fmt(w * 30 / math.pi, 7, lang), fmt(wp * 30 / math.pi, 7, lang), fmt(w, 6, lang)])
    return finish("speeds", "table", None, _grid(rows, "speeds"), tr("speeds", lang))


def synthesis_panel(sol: GearSolution, lang: str) -> Panel:
    t = sol.synthesis
    assert t is not None
    ok = t.conditions(sol.file.ha)
    rows = [["z_1", "z_2", "z_3", "k", "i_{1H}"] + [words(c, lang) for c in ok],
            [str(t.z1), str(t.z2), str(t.z3), str(t.planets), fmt(t.ratio, 5, lang)] +
            ["+" if v else "−" for v in ok.values()]]
    return finish("synthesis", "table", None, _grid(rows, "synthesis"), tr("synthesis", lang))


def magnifications(sol: GearSolution) -> list[float]:
    """How much larger than the engine's plan the train's scheme and velocity plan may be
    drawn, largest first: the factors of 10, 5, 4, 2.5, 2 that keep μ_l and μ_v round, and 1.
    The plan of angular velocities keeps its h: μ_ω = h·μ_v/μ_l does not change."""
    from plans.kinematics.scales import is_round

    plan = sol.plan
    assert plan is not None
    return [f for f in (10.0, 5.0, 4.0, 2.5, 2.0) if is_round(plan.mu_l * f) and is_round(plan.mu_v * f)] + [1.0]


def magnification(sol: GearSolution, spec: SheetSpec) -> float:
    """How much larger than the engine's plan the train's scheme and velocity plan are drawn at
    least: the largest of 10, 5, 4, 2.5, 2, 1 that keeps μ_l and μ_v round, the scheme and the
    plan within half the sheet's height (the engine's plan fits any sheet at 1); larger where
    the sheet it goes on has room.  The plan of
    angular velocities keeps its h: μ_ω = h·μ_v/μ_l does not change."""
    from plans.kinematics.scales import is_round

    plan = sol.plan
    assert plan is not None
    gears = sol.file.gears
    ys = [pt[1] for ln in plan.lines.values() for _, pt in ln.points]
    for p in sol.pairs:
        for w in p.wheels:  # the scheme: every gear's working circle about its axis
            y, r = plan.axes[gears[w.name].shaft] * plan.mu_l, w.working * plan.mu_l
            ys += [y - r, y + r]
    tall = (max(ys) - min(ys)) if ys else 1.0
    wide = max([abs(pt[0]) for ln in plan.lines.values() for _, pt in ln.points] + [1.0])
    W, H = spec.size
    for f in (10.0, 5.0, 4.0, 2.5, 2.0):
        if is_round(plan.mu_l * f) and is_round(plan.mu_v * f) and tall * f <= 0.5 * H and wide * f <= 0.3 * W:
            return f
    return 1.0


def _train(sol: GearSolution, lang: str, f: float, pairs: bool) -> list[Panel]:
    """The train's panels with its scheme and plan magnified ``f`` times (and the pairs' table
    where no meshing sheet holds it)."""
    train: list[Panel] = []
    if sol.plan is not None:
        train += [scheme_panel(sol, lang, f), velocity_panel(sol, lang, f), rays_panel(sol, lang),
                  speeds_panel(sol, lang)]
    if sol.synthesis is not None:
        train.append(synthesis_panel(sol, lang))
    if pairs and sol.pairs:
        train.append(results_panel(sol, lang))
    return train


@drawing
def draw(source: GearsSolution | GearFile | str | Path, *, format: str | None = None,
         orientation: str | None = None, language: str | None = None, font: str | None = None) -> GearDrawing:
    """The meshing sheet (when the file has an external pair) and the train sheet (when it
    gives speeds): of a solved gear file (``plans.solve``), or of a file or its path, solved here."""
    gs = source if isinstance(source, GearsSolution) else solve_file(source)
    gf = gs.file
    sol = gs.solution
    from plans.language import choose as run_language

    spec = sheet_spec(gf.raw, gf.path, gf.title or tr("title", run_language(language, gf.raw)),
                      format=format, orientation=orientation, language=language, font=font)
    choose(spec.font, gf.path, font)
    lang = spec.language
    from drawings.gears_sliding import sliding_panel
    from drawings.paper.fill import fullest_on_one_sheet

    drawings = list(gs.meshings)
    mesh: list[Panel] = []  # each meshing with its specific sliding, then the pairs' table
    for one in drawings:
        mesh += [meshing_panel(one, lang), sliding_panel(one, lang)]
    if drawings:
        mesh.append(results_panel(sol, lang))
    mesh_scale = "; ".join(dict.fromkeys(ratio_text(one.k * 1000.0, lang) for one in drawings))
    mg = drawings[0] if drawings else None
    fs = magnifications(sol) if sol.plan is not None else [1.0]

    def train_scale(f: float) -> str:
        return ratio_text(sol.plan.mu_l * f, lang) if sol.plan is not None else ""

    if not mesh and not _train(sol, lang, 1.0, True):
        raise InputError(Said("dg_nothing_draw_meshes"),
                         file=gf.path, field="meshes")
    trains = {f: _train(sol, lang, f, mg is None) for f in fs}
    made = {id(t[0]): f for f, t in trains.items() if t}  # a train's first panel -> its magnification

    def scale(panels: Sequence[Panel]) -> str:  # the Scale cell: the meshings', the train's
        f = next((made[id(p)] for p in panels if id(p) in made), None)
        ms = mesh_scale if any(p.kind == "meshing" for p in panels) else ""
        return "; ".join(t for t in (ms, train_scale(f) if f is not None else "") if t)

    # the meshings and the train on one sheet, the train as large as that leaves room for
    least = magnification(sol, spec) if sol.plan is not None else 1.0
    from drawings.paper.merge import merged

    groups: list[tuple[list[Panel], str]] = []
    sheets: list[Sheet] = []
    for f in fs if mesh else ():  # largest first: the train laid out alone, moved on as one piece
        if f < least or not trains[f] or not all(fits_empty(p, spec.format, spec.orientation) for p in trains[f]):
            continue
        sets = [(mesh, mesh_scale), (trains[f], scale(trains[f]))]
        laid = merged([s for g, t in sets for s in compose(g, spec, t, gf.path)])
        if len(laid) == 1:
            groups, sheets = sets, laid
            break
    if not sheets:  # a sheet of the meshings, then the train's as large as its own sheet holds
        if mesh:
            groups.append((mesh, mesh_scale))
        alone = fullest_on_one_sheet(([trains[f]] for f in fs if trains[f] and f >= least), spec, gf.path, scale)
        train = alone[0] if alone is not None else trains[fs[-1]]
        if train:
            groups.append((train, scale(train)))
        for panels, text in groups:
            sheets.extend(compose(panels, spec, text, gf.path))
        sheets = merged(sheets)  # the train on the meshing sheet where it fits; one numbering
    panels_all = tuple(p for g, _ in groups for p in g)
    return GearDrawing(gf, sol, mg, spec, panels_all, tuple(sheets))
