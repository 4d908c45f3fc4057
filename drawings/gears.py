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

from drawings.gears_sliding import sliding_panel
from drawings.gears_train import (
    AXIS,
    LABEL,
    SMALL,
    grid,
    magnification,
    magnifications,
    rays_panel,
    scheme_panel,
    speeds_panel,
    synthesis_panel,
    tr,
    unit_word,
    velocity_panel,
)
from drawings.linkage.panels import Panel, finish, ratio_text
from drawings.paper.backend import HAIR, MAIN, PAPER, THICK, THIN, Recording, Style
from drawings.paper.common import Placer, arrow, dot, fmt
from drawings.paper.fonts import choose, drawing
from drawings.paper.sheet import Sheet, SheetSpec, compose, fits_empty, sheet_spec, usable
from drawings.paper.text import layout
from plans.errors import InputError, Said
from plans.gears.meshing import Meshing
from plans.gears.model import GearFile
from plans.gears.solution import GearsSolution, solve_file
from plans.gears.solve import GearSolution

DASHED = Style(stroke="#000", width=0.25, dash=(3.0, 1.5), cls="working")
ACTIVE = Style(width=1.2, cls="active")


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
    W, H = mg.window, mg.half_height
    # the field: W either side of P, and in height H (a field asked for, mg.reach), else only
    # as far as the teeth go (plus 12 mm)
    near = [z for dw in mg.wheels for z in dw.outline if abs(z.real) <= W]
    ylo = -H if mg.reach else max(-H, min(min(z.imag for z in near) - 12.0, -12.0))
    yhi = H if mg.reach else min(H, max(max(z.imag for z in near) + 12.0, 12.0))
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
    rec = grid(rows, "results")
    return finish("results", "table", None, rec, tr("results", lang))


def train_panels(sol: GearSolution, lang: str, f: float, pairs: bool) -> list[Panel]:
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
    spec = sheet_spec(gf.raw, gf.path, gf.title or tr("title", "ru" if language != "en" else "en"),
                      format=format, orientation=orientation, language=language, font=font)
    choose(spec.font, gf.path, font)
    lang = spec.language
    from drawings.paper.fill import fullest_on_one_sheet

    if not gs.meshings and not train_panels(sol, lang, 1.0, True):
        raise InputError(Said("dg_nothing_draw_meshes"), file=gf.path, field="meshes")
    fs = magnifications(sol) if sol.plan is not None else [1.0]
    f = magnification(sol, spec) if sol.plan is not None else 1.0
    if not gs.meshings:  # the train alone, as large as its sheet holds
        trains = {g: train_panels(sol, lang, g, True) for g in fs if g >= f}
        made = {id(t[0]): g for g, t in trains.items()}

        def scale(panels: Sequence[Panel]) -> str:
            return ratio_text(sol.plan.mu_l * made[id(panels[0])]) if sol.plan is not None else ""

        alone = fullest_on_one_sheet(([t] for t in trains.values()), spec, gf.path, scale)
        panels, sheets = alone if alone is not None else (trains[f], compose(trains[f], spec, scale(trains[f]), gf.path))
        return GearDrawing(gf, sol, None, spec, tuple(panels), tuple(sheets))
    # a sheet for each meshing drawn, its field as large as the sheet holds: the meshing with
    # its specific sliding, the pairs' table on the first, the train (laid out alone, moved
    # on as one piece) on the last
    train = train_panels(sol, lang, f, False)
    tscale = ratio_text(sol.plan.mu_l * f) if sol.plan is not None else ""
    out: list[Sheet] = []
    every: list[Panel] = []
    for i, mg in enumerate(gs.meshings):
        rest = [sliding_panel(mg, lang)] + ([results_panel(sol, lang)] if i == 0 else [])
        after = [(train, tscale)] if i == len(gs.meshings) - 1 and train else []
        panels, sheets = meshing_sheet(gs, i, rest, after, spec, lang)
        every += panels + [p for ps, _ in after for p in ps]
        out += sheets
    for n, sh in enumerate(out):
        sh.number, sh.count = n + 1, len(out)
        sh.prims = []
        sh.render()
    return GearDrawing(gf, sol, gs.meshings[0], spec, tuple(every), tuple(out))


FIELD_STEP = 10.0  # mm: the meshing's field is grown in these steps


def field_sizes(mg: Meshing, spec: SheetSpec) -> tuple[list[float], list[float]]:
    """The meshing's field's half-widths and half-heights about P worth trying on a sheet,
    smallest first: from the least that shows its teeth and line of action up to the sheet's
    field, no farther than the wheels reach (their largest circles and 12 mm)."""
    x0, y0, x1, y1 = usable(*spec.size)
    reach_x = max(max(dw.radii.values()) for dw in mg.wheels) + 12.0
    reach_lo = max(max(dw.radii.values()) - dw.centre.imag for dw in mg.wheels) + 12.0
    reach_hi = max(max(dw.radii.values()) + dw.centre.imag for dw in mg.wheels) + 12.0
    wmax = min((x1 - x0) / 2 - 2.0, reach_x)
    hmax = min((y1 - y0) / 2 - 18.0, max(reach_lo, reach_hi))
    ws = [mg.window + FIELD_STEP * j for j in range(int((wmax - mg.window) // FIELD_STEP) + 1)]
    low = 0.5 * mg.window  # a field lower than it is wide, where the sheet has no more height
    hs = [low + FIELD_STEP * j for j in range(int((hmax - low) // FIELD_STEP) + 1)]
    return ws, hs


def meshing_sheet(gs: GearsSolution, i: int, rest: list[Panel], after: list[tuple[list[Panel], str]],
                  spec: SheetSpec, lang: str) -> tuple[list[Panel], list[Sheet]]:
    """The ``i``-th meshing's sheet: its field the largest of :func:`field_sizes` whose panel,
    with ``rest`` and then each set of ``after`` laid out alone and moved on, keeps one sheet
    (tried first as a box of the panel's size, then drawn); else the least field, on as many
    sheets as it takes."""
    from drawings.paper.merge import merged

    mg = gs.meshings[i]
    scale = ratio_text(mg.k * 1000.0)

    gf_path = gs.file.path
    later = [s for g, t in after for s in compose(g, spec, t, gf_path)]  # laid out once, moved on

    def laid(first: Panel) -> list[Sheet]:
        return merged(compose([first] + rest, spec, scale, gf_path) + later)

    def fits(field: tuple[float, float]) -> bool:
        """A box of the panel's size (the field, the contact ratio's line under it, the title
        above) with the rest keeps one sheet."""
        box = Panel(f"meshing-{i}", "meshing", None, (), 2 * field[0] + 5.0, 2 * field[1] + 27.0, "")
        return fits_empty(box, spec.format, spec.orientation) and len(laid(box)) == 1

    ws, hs = field_sizes(mg, spec)
    found: list[tuple[float, float]] = []
    for h in reversed(hs):  # for each height the widest field that fits, found by halving
        lo, hi = -1, len(ws) - 1
        while lo < hi:
            mid = (lo + hi + 1) // 2
            if fits((ws[mid], h)):
                lo = mid
            else:
                hi = mid - 1
        if lo >= 0:
            found.append((ws[lo], h))
    for field in sorted(found, key=lambda f: (-f[0] * f[1], -f[0])):
        drawn = meshing_panel(gs.meshing_in(i, field), lang)
        sheets = laid(drawn)
        if len(sheets) == 1:
            return [drawn] + rest, sheets
    drawn = meshing_panel(mg, lang)
    return [drawn] + rest, laid(drawn)
