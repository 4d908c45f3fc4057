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

from plans.errors import InputError
from plans.gears.meshing import Meshing
from plans.gears.model import GearFile
from plans.gears.solution import GearsSolution, solve_file
from plans.gears.solve import GearSolution

from .backend import HAIR, MAIN, PAPER, THICK, THIN, Recording, Style
from .common import Placer, arrow, dot, fmt
from .i18n import lookup
from .panels import Panel, finish, ratio_text
from .sheet import Sheet, SheetSpec, compose, sheet_spec
from .text import layout

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
    return finish(f"meshing-{g1}-{g2}", "meshing", None, rec, title, f"M {ratio_text(mg.k * 1000.0)}")


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
    H = rh * len(rows)
    rec = Recording()
    rec.begin(f"{pid}-grid", "grid")
    rec.polygon([(0, 0), (xs[-1], 0), (xs[-1], H), (0, H)], Style(width=0.5, cls="grid"))
    for i in range(1, len(rows)):
        rec.line((0, i * rh), (xs[-1], i * rh), Style(width=0.5 if i == 1 else 0.18, cls="grid"))
    for x in xs[1:-1]:
        rec.line((x, 0), (x, H), Style(width=0.18, cls="grid"))
    rec.end()
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
        (f"a_w, {gf.unit}", lambda p, w: f(p.a_w * k, 3)),
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


def scheme_panel(sol: GearSolution, lang: str) -> Panel:
    """The unfolded train: every gear a bar of its working diameter on its axis, side by side."""
    plan = sol.plan
    assert plan is not None
    gf = sol.file
    mu = plan.mu_l / 1000.0  # paper mm per mm
    rec = Recording()
    col: dict[str, float] = {}
    x = 0.0
    for p in sol.pairs:
        for w in p.wheels:
            if w.name not in col:
                col[w.name] = x
                x += 12.0
    radii: dict[str, float] = {}
    for p in sol.pairs:
        for w in p.wheels:
            radii[w.name] = w.working * 1e3 * mu
    for name, cx in col.items():
        g = gf.gears[name]
        y = plan.axes[g.shaft] * 1e3 * mu
        r = radii[name]
        rec.line(PAPER(cx, y - r), PAPER(cx, y + r), THICK, f"gear-{name}")
        if g.internal:
            for side in (-1, 1):
                rec.line(PAPER(cx, y + side * r), PAPER(cx - 4.0, y + side * r), THICK,
                         f"gear-{name}-ring{side}")
        rec.line(PAPER(cx - 3.0, y), PAPER(cx + 3.0, y), MAIN, f"axis-{name}")
        rec.text(layout(name, *PAPER(cx + 1.5, y + r + 2.0), LABEL, "start", "bottom"), "label", f"label-gear-{name}")
    for n, s in gf.shafts.items():
        y = plan.axes[n] * 1e3 * mu
        if s.carrier is None:
            rec.line(PAPER(-8.0, y), PAPER(x + 2.0, y), AXIS, f"shaft-{n}")
    for n in gf.shafts:  # carriers: a bracket from the central axis to each planet axis
        planets = [q for q, t in gf.shafts.items() if t.carrier == n]
        if planets:
            y0 = plan.axes[n] * 1e3 * mu
            xc = x + 4.0
            for q in planets:
                yq = plan.axes[q] * 1e3 * mu
                rec.polyline([PAPER(x - 6.0, yq), PAPER(xc, yq), PAPER(xc, y0), PAPER(xc + 6.0, y0)], MAIN, f"carrier-{n}-{q}")
            rec.text(layout(n, *PAPER(xc + 2.0, y0 + 2.0), LABEL, "start", "bottom"), "label", f"label-carrier-{n}")
    return finish("train-scheme", "train-scheme", None, rec, tr("scheme", lang),
                  f"μ_l = {fmt(plan.mu_l, 4, lang)} {'мм/м' if lang == 'ru' else 'mm/m'}")


def velocity_panel(sol: GearSolution, lang: str) -> Panel:
    plan = sol.plan
    assert plan is not None
    rec = Recording()
    placer = Placer()
    ys = [pt[1] for ln in plan.lines.values() for _, pt in ln.points] + [y * plan.mu_l for y in plan.axes.values()]
    y0, y1 = min(ys) - 8.0, max(ys) + 8.0
    rec.line(PAPER(0.0, y0), PAPER(0.0, y1), AXIS, "radial-line")
    xs = [pt[0] for ln in plan.lines.values() for _, pt in ln.points]
    span = (min(xs + [0.0]) - 10.0, max(xs + [0.0]) + 10.0)
    done: set[str] = set()
    for n, ln in plan.lines.items():
        pts = list(ln.points)
        if len({round(p[1], 6) for _, p in pts}) < 2:
            pts.append(("", ln.p1))
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
                arrow(rec, PAPER(0.0, vy), PAPER(vx, vy), THIN, f"v-{name}", "vector")
            dot(rec, PAPER(vx, vy), 0.6, f"pt-{name}")
            rec.text(placer.place(name, PAPER(vx, vy), SMALL + 0.5, (1.0, -0.5)), "label", f"label-{name}")
    del span
    txt = f"μ_v = {fmt(plan.mu_v, 4, lang)} {'мм/(м/с)' if lang == 'ru' else 'mm/(m/s)'}"
    return finish("velocity-plan", "velocity-plan", None, rec, tr("vplan", lang), txt)


def rays_panel(sol: GearSolution, lang: str) -> Panel:
    plan = sol.plan
    assert plan is not None
    rec = Recording()
    placer = Placer()
    h = plan.h
    xs = [ln.intercept for ln in plan.lines.values()] + [0.0]
    lo, hi = min(xs) - 10.0, max(xs) + 10.0
    rec.line(PAPER(lo, h), PAPER(hi, h), MAIN, "reference-line")
    dot(rec, (0.0, 0.0), 0.8, "pole")
    rec.text(layout("O_ω", 2.0, 3.5, LABEL, "start", "middle"), "label", "label-pole")
    rec.line((0.0, 0.0), PAPER(0.0, h + 4.0), AXIS, "pole-normal")
    placer.add_line([PAPER(lo, h), PAPER(hi, h)])
    for n, ln in plan.lines.items():
        rec.line((0.0, 0.0), PAPER(ln.intercept, h), THIN, f"ray-{n}")
        placer.add_line([(0.0, 0.0), PAPER(ln.intercept, h)])
        dot(rec, PAPER(ln.intercept, h), 0.6, f"omega-{n}")
    for n, ln in plan.lines.items():
        rec.text(placer.place(f"ω_{n}", PAPER(ln.intercept, h), SMALL + 0.5, (0.0, -1.0)), "label", f"label-omega-{n}")
    rec.text(layout(f"h = {fmt(h, 3, lang)}", *PAPER(2.0, h / 2), SMALL, "start", "middle"), "note", "pole-distance")
    txt = f"μ_ω = {fmt(plan.mu_omega, 4, lang)} {'мм/(рад/с)' if lang == 'ru' else 'mm/(rad/s)'}"
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
    rows = [["z_1", "z_2", "z_3", "k", "i_{1H}"] + list(ok),
            [str(t.z1), str(t.z2), str(t.z3), str(t.planets), fmt(t.ratio, 5, lang)] +
            ["+" if v else "−" for v in ok.values()]]
    return finish("synthesis", "table", None, _grid(rows, "synthesis"), tr("synthesis", lang))


def draw(source: GearsSolution | GearFile | str | Path, *, format: str | None = None,
         orientation: str | None = None, language: str | None = None) -> GearDrawing:
    """The meshing sheet (when the file has an external pair) and the train sheet (when it
    gives speeds): of a solved gear file (``plans.solve``), or of a file or its path, solved here."""
    gs = source if isinstance(source, GearsSolution) else solve_file(source)
    gf = gs.file
    sol = gs.solution
    spec = sheet_spec(gf.raw, gf.path, gf.title or tr("title", "ru" if language != "en" else "en"),
                      format=format, orientation=orientation, language=language)
    lang = spec.language
    groups: list[tuple[list[Panel], str]] = []
    drawings = list(gs.meshings)
    if drawings:  # the meshings and the table of the pairs share sheets as they fit
        scales = list(dict.fromkeys(ratio_text(one.k * 1000.0) for one in drawings))
        groups.append(([meshing_panel(one, lang) for one in drawings] + [results_panel(sol, lang)],
                       "; ".join(scales)))
    mg = drawings[0] if drawings else None
    train: list[Panel] = []
    if sol.plan is not None:
        train += [scheme_panel(sol, lang), velocity_panel(sol, lang), rays_panel(sol, lang), speeds_panel(sol, lang)]
    if sol.synthesis is not None:
        train.append(synthesis_panel(sol, lang))
    if mg is None and sol.pairs:
        train.append(results_panel(sol, lang))
    if train:
        groups.append((train, ratio_text(sol.plan.mu_l) if sol.plan is not None else ""))
    if not groups:
        raise InputError("nothing to draw: expected [[meshes]] or [[shafts]] with speeds",
                         file=gf.path, field="meshes")
    sheets: list[Sheet] = []
    for panels, scale in groups:
        sheets.extend(compose(panels, spec, scale, gf.path))
    for i, sh in enumerate(sheets):  # one numbering across the meshing and train sheets
        sh.number, sh.count = i + 1, len(sheets)
        sh.render()
    panels_all = tuple(p for g, _ in groups for p in g)
    return GearDrawing(gf, sol, mg, spec, panels_all, tuple(sheets))
