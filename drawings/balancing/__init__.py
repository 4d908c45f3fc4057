"""The engine-balancing sheet (seed 002): crankshaft scheme, phase diagrams of the first and
second order, polygons of the inertia forces and of the turned moments with their closing
vectors, the analytic table beside each polygon, counterweights and results.

Reads the frozen results of :mod:`plans.balancing`; lays them out with the panel and sheet
machinery of the linkage sheets (:mod:`drawings.linkage.panels`, :mod:`drawings.paper.sheet`).
"""

from __future__ import annotations

import cmath
import math
from collections.abc import Sequence
from dataclasses import dataclass
from functools import partial
from pathlib import Path

from drawings.balancing.balancing_paper import diagram_scale, engine_paper, polygon_scale
from drawings.linkage.panels import LABEL_SIZE, SMALL_SIZE, VECTOR_STYLES, Panel, finish
from drawings.paper.backend import CENTRE_LINE, HAIR, MAIN, Recording, Style
from drawings.paper.common import Placer, arrow, degrees360, dot, fmt
from drawings.paper.fonts import choose, drawing, metrics
from drawings.paper.i18n import lookup
from drawings.paper.panel_frame import auto_length_scale, ratio_text, ruled_grid
from drawings.paper.sheet import Sheet, SheetSpec, compose, sheet_spec
from drawings.paper.text import column_edges, layout
from plans.balancing.analysis import KINDS, Balance, Polygon, Resultant
from plans.balancing.engine import Engine
from plans.balancing.exact import ExactCheck
from plans.balancing.solution import EngineSolution, solve_engine

_W: dict[str, tuple[str, str]] = {
    "shaft": ("Схема коленчатого вала", "Crankshaft"),
    "scale": ("М", "Scale"),
    "phase1": ("Фазовая диаграмма I порядка", "Phase diagram, first order"),
    "phase2": ("Фазовая диаграмма II порядка", "Phase diagram, second order"),
    "force-rotating": ("Силы инерции вращающихся масс", "Inertia forces of the rotating masses"),
    "force-first_order": ("Силы инерции ПДМ I порядка", "Reciprocating inertia forces, first order"),
    "force-second_order": ("Силы инерции ПДМ II порядка", "Reciprocating inertia forces, second order"),
    "moment-rotating": ("Повёрнутые моменты вращающихся масс", "Turned moments of the rotating masses"),
    "moment-first_order": ("Повёрнутые моменты сил ПДМ I порядка", "Turned moments, first order"),
    "moment-second_order": ("Повёрнутые моменты сил ПДМ II порядка", "Turned moments, second order"),
    "forward": ("прямое вращение", "turning with the crank"),
    "backward": ("обратное вращение", "turning against the crank"),
    "table": ("Таблица", "Table"),
    "closed": ("многоугольник замкнут", "the polygon closes"),
    "results": ("Неуравновешенные силы и моменты", "Unbalanced forces and moments"),
    "cw": ("Противовесы", "Counterweights"),
    "quantity": ("Величина", "Quantity"),
    "amplitude": ("Амплитуда", "Amplitude"),
    "dimless": ("Безразм.", "Dimensionless"),
    "phase": ("Фаза, °", "Phase, °"),
    "unit": ("Ед.", "Unit"),
    "for": ("Для", "For"),
    "plane": ("Плоскость z, м", "Plane z, m"),
    "mr": ("m·r, кг·м", "m·r, kg·m"),
    "kgm_mm": ("кг·м/мм", "kg·m/mm"),
    "mass": ("m, кг", "m, kg"),
    "radius": ("r, м", "r, m"),
    "angle": ("Угол, °", "Angle, °"),
    "none": ("не нужны", "none needed"),
    "exact": ("Проверка кинетостатикой", "Check by kinetostatics"),
    "ref": ("плоскость приведения", "reference plane"),
    "tdc": ("ВМТ", "TDC"),
    "rotating": ("вращ.", "rotating"),
    "first_order": ("ПДМ I", "recipr. I"),
    "second_order": ("ПДМ II", "recipr. II"),
    "N": ("Н", "N"),
    "N*m": ("Н·м", "N·m"),
    "err": ("ошибка ряда", "truncation error"),
    "actual": ("действительный", "actual"),
    "cw_first": ("силы и моменты ПДМ I порядка противовесом не уравновешиваются (балансирные валы)",
                 "first-order reciprocating forces and moments: not by a counterweight (balancing shafts)"),
    "cw_second": ("силы и моменты ПДМ II порядка противовесом не уравновешиваются (валы с 2ω)",
                  "second-order reciprocating forces and moments: not by a counterweight (shafts at 2ω)"),
}
_SYM = {("force", "rotating"): "r_r", ("force", "first_order"): "r_I", ("force", "second_order"): "r_{II}",
        ("moment", "rotating"): "m_r", ("moment", "first_order"): "m_I", ("moment", "second_order"): "m_{II}"}
_ABS = {("force", "rotating"): "R_r", ("force", "first_order"): "R_I", ("force", "second_order"): "R_{II}",
        ("moment", "rotating"): "M_r", ("moment", "first_order"): "M_I", ("moment", "second_order"): "M_{II}"}
CLOSING = VECTOR_STYLES["closing"]
ACTUAL = Style(width=0.35, stroke="#b3261e", dash=(2.5, 1.2))
AXIS = CENTRE_LINE
STAR_R = 50.0  # radius of a phase diagram, mm


_t = lookup(_W)


@dataclass(frozen=True)
class BalancingDrawing:
    """Everything drawn for one engine."""

    engine: Engine
    balance: Balance
    spec: SheetSpec
    panels: tuple[Panel, ...]
    sheets: tuple[Sheet, ...]

    def _repr_svg_(self) -> str:
        return self.sheets[0].svg()


@drawing
def draw(source: EngineSolution | Engine | str | Path, *, format: str | None = None,
         orientation: str | None = None, language: str | None = None, font: str | None = None) -> BalancingDrawing:
    """The sheets of a solved engine (``plans.solve``), or of an engine or its file, solved here."""
    es = source if isinstance(source, EngineSolution) else solve_engine(source)
    engine = es.engine
    spec = sheet_spec(engine.raw, engine.path, engine.title, format=format, orientation=orientation,
                      language=language, font=font)
    choose(spec.font, engine.path, font)
    metrics()
    b = es.balance
    if spec.format in GROWN:  # where an A1 sheet has room: the figures larger, at round scales
        panels, sheets = _grown(es, spec)
    else:
        panels = build_panels(es, spec.language)
        sheets = compose(panels, spec, "", engine.path)
    return BalancingDrawing(engine, b, spec, tuple(panels), tuple(sheets))


#: The formats whose balancing sheets take larger figures where they have room, and the sizes
#: tried (times the A1 ones: the polygons' round scales, the phase diagrams, the crankshaft).
GROWN = ("A1", "A2")
SIZES = (1.0, 1.1, 1.25, 1.4, 1.5, 1.75, 2.0, 2.25, 2.5)
#: The diagrams over a turn: their heights (times the A1 ones, the lowest first) and μ_α, °/mm.
TURNS = tuple((h, d) for d in (2.0, 1.0) for h in (0.5, 0.75, 1.0, 1.5, 2.0, 2.5, 3.0, 4.0))


def _grown(es: EngineSolution, spec: SheetSpec) -> tuple[list[Panel], list[Sheet]]:
    """The panels at the sizes that keep the fewest sheets and leave the emptiest least empty
    (:mod:`drawings.balancing.balancing_growth`)."""
    from drawings.balancing.balancing_banks import bank_panels
    from drawings.balancing.balancing_growth import Group, fullest
    from drawings.balancing.balancing_turn import turn_panels

    b, e, lang = es.balance, es.engine, spec.language
    groups = [Group(lambda s: [shaft_panel(e, lang, s)], SIZES),
              Group(lambda s: [phase_panel(e, 1, lang, s), phase_panel(e, 2, lang, s)], SIZES)]
    for res in (b.forces, b.moments):
        groups += [Group(partial(_one_polygon, res[kind], lang), SIZES) for kind in KINDS]
    groups += [Group(lambda s: bank_panels(b, lang, s), SIZES),
               Group(lambda t: turn_panels(b, es.exact, lang, *t), TURNS, joint=False),
               Group(lambda _: [results_panel(b, es.exact, lang)], (1.0,)),
               Group(lambda s: [counterweights_panel(b, lang, s)], SIZES)]
    return fullest(groups, spec, e.path)


def _one_polygon(R: Resultant, lang: str, size: float) -> list[Panel]:
    return [polygon_panel(R, lang, size)]


def build_panels(es: EngineSolution, lang: str, size: float = 1.0) -> list[Panel]:
    """The sheet's panels, their figures ``size`` times the A1 ones (the tables as they are)."""
    b = es.balance
    e = b.engine
    panels = [shaft_panel(e, lang, size), phase_panel(e, 1, lang, size), phase_panel(e, 2, lang, size)]
    for _quantity, res in (("force", b.forces), ("moment", b.moments)):
        for kind in KINDS:
            R = res[kind]
            panels.append(polygon_panel(R, lang, size))
    from drawings.balancing.balancing_banks import bank_panels
    from drawings.balancing.balancing_turn import turn_panels

    panels += bank_panels(b, lang, size)
    panels += turn_panels(b, es.exact, lang, *TURNS[0])  # the lowest: they fit an A3 sheet
    panels.append(results_panel(b, es.exact, lang))
    panels.append(counterweights_panel(b, lang, size))
    return panels


# --------------------------------------------------------------------------- scheme and phase diagrams


def shaft_panel(e: Engine, lang: str, size: float = 1.0) -> Panel:
    """The crankshaft from the side: the axis, each crank as its projection on the vertical
    plane at its z, the cylinder numbers, the reference plane and the arms l_i."""
    zs = [c.z for c in e.cylinders] + [e.reference_z]
    span = max(max(zs) - min(zs), e.r)
    # mm per m: one drawing scale (GOST 2.302), the shaft within 260 mm and a throw's 2r within 70
    s_z = s_r = min(auto_length_scale(span, 260.0 * size), auto_length_scale(2 * e.r, 70.0 * size))
    # cylinder 1 on the left, whichever way z runs
    sign = 1.0 if e.cylinders[0].z <= e.cylinders[-1].z else -1.0
    z0 = min(zs) if sign > 0 else max(zs)
    rec = Recording()
    x = [sign * (c.z - z0) * s_z for c in e.cylinders]
    lo, hi = -8.0, (max(zs) - min(zs)) * s_z + 8.0
    rec.line((lo, 0.0), (hi, 0.0), AXIS, "shaft-axis")
    for c, xc in zip(e.cylinders, x, strict=True):
        y = -s_r * e.r * math.cos(c.crank)
        rec.polyline([(xc - 3, 0.0), (xc - 3, y), (xc + 3, y), (xc + 3, 0.0)], MAIN, f"shaft-crank-{c.number}")
        dot(rec, (xc, y), 0.8)
    names: dict[float, list[str]] = {}  # cylinders in one plane (a V engine) share a label
    for c, xc in zip(e.cylinders, x, strict=True):
        names.setdefault(round(xc, 6), []).append(f"{c.name}: {fmt(degrees360(c.crank), 4, lang)}°")
    for xc, texts in names.items():
        lab = layout(", ".join(texts), xc, -s_r * e.r - 4.0, SMALL_SIZE + 0.5, "middle", "bottom")
        rec.text(lab, "label", f"shaft-label-{xc:g}")
    xr = sign * (e.reference_z - z0) * s_z
    rec.line((xr, -s_r * e.r - 2), (xr, s_r * e.r + 6), Style(width=0.25, stroke="#1f4e9c", dash=(3, 1.5)),
             "shaft-ref")
    rec.text(layout(_t("ref", lang), xr + 1.0, s_r * e.r + 6, SMALL_SIZE, "start", "top"), "note", "shaft-ref-label")
    arms: dict[float, list[int]] = {}
    for c, xc in zip(e.cylinders, x, strict=True):
        arms.setdefault(round(xc, 6), []).append(c.number)
    for c, xc in zip(e.cylinders, x, strict=True):
        if arms[round(xc, 6)][0] != c.number:
            continue
        l_dim = (c.z - e.reference_z) / e.arm_unit
        rec.text(layout(f"l_{c.number} = {fmt(l_dim, 3, lang)}", xc, s_r * e.r + 2.0, SMALL_SIZE, "middle", "top"),
                 "note", f"shaft-arm-{c.number}")
    note = f"r = {fmt(e.r * 1000, 4, lang)} мм, λ = {fmt(e.lam, 3, lang)}, ω = {fmt(e.omega, 4, lang)} рад/с" \
        if lang == "ru" else f"r = {fmt(e.r * 1000, 4)} mm, λ = {fmt(e.lam, 3)}, ω = {fmt(e.omega, 4)} rad/s"
    return finish("shaft", "scheme", None, rec, _t("shaft", lang), f"{_t('scale', lang)} {ratio_text(s_z, lang)}",
                  note)


def phase_panel(e: Engine, order: int, lang: str, size: float = 1.0) -> Panel:
    """The star of cranks at k·β_i (and the banks' axes of a V engine), its radius ``size``
    times STAR_R."""
    pid = f"phase-{order}"
    rec = Recording()
    placer = Placer()
    R = STAR_R * size
    rec.line((0.0, R + 6), (0.0, -R - 6), AXIS, f"{pid}-vertical")
    rec.text(layout(_t("tdc", lang), 0.0, -R - 7, SMALL_SIZE, "middle", "bottom"), "note", f"{pid}-tdc")
    placer.add_line([(0.0, R + 6), (0.0, -R - 6)])
    if not e.is_inline:
        for g in sorted({round(c.bank, 12) for c in e.cylinders}):
            a, b = engine_paper(cmath.exp(1j * g), R + 8), engine_paper(-cmath.exp(1j * g), 8.0)
            rec.line(b, a, Style(width=0.25, stroke="#6a3d9a", dash=(4, 1.5)), f"{pid}-bank-{math.degrees(g):g}")
            placer.add_line([b, a])
            who = ", ".join(c.name for c in e.cylinders if abs(c.bank - g) < 1e-9)
            lab = placer.place(who, a, SMALL_SIZE + 0.3, prefer=(a[0] / (R + 8), a[1] / (R + 8)), gap=0.8)
            rec.text(lab, "label", f"{pid}-bank-label-{math.degrees(g):g}", fill="#6a3d9a")
    rec.circle((0.0, 0.0), R, HAIR, f"{pid}-circle")
    tips: dict[int, list[str]] = {}
    for c in e.cylinders:
        ang = order * c.crank
        key = round(math.degrees(ang) % 360.0 * 1e6)
        tips.setdefault(key, []).append(c.name)
    for key, names in sorted(tips.items()):
        ang = math.radians(key / 1e6)
        tip = engine_paper(cmath.exp(1j * ang), R)
        rec.line((0.0, 0.0), tip, Style(width=0.5), f"{pid}-crank-{names[0]}")
        placer.add_line([(0.0, 0.0), tip])
        dot(rec, tip, 0.7)
        lab = placer.place(", ".join(names), tip, LABEL_SIZE, prefer=(tip[0] / R, tip[1] / R), gap=1.2)
        rec.text(lab, "label", f"{pid}-label-{names[0]}")
    # the sense of rotation
    rec.arc((0.0, 0.0), R * 0.45, -math.radians(100), -math.radians(150), Style(width=0.3), f"{pid}-omega")
    a1 = -math.radians(150)
    end = (R * 0.45 * math.cos(a1), R * 0.45 * math.sin(a1))
    tx, ty = math.sin(a1), -math.cos(a1)
    rec.polygon([(end[0] - tx * 2.4, end[1] - ty * 2.4), (end[0] - ty * 0.7, end[1] + tx * 0.7),
                 (end[0] + ty * 0.7, end[1] - tx * 0.7)], Style(stroke=None, width=0, fill="#000"))
    lab = placer.place("ω" if order == 1 else "2ω", (-R * 0.45 * 0.94, -R * 0.45 * 0.94), SMALL_SIZE + 0.5,
                       prefer=(-0.7, -0.7), gap=1.0)
    rec.text(lab, "label", f"{pid}-omega-label")
    return finish(pid, "phase", None, rec, _t(f"phase{order}", lang))


# --------------------------------------------------------------------------- polygons


def _path(poly: Polygon) -> list[complex]:
    pts = [0j]
    for r in poly.rows:
        pts.append(pts[-1] + r.vector)
    return pts


def polygon_panel(R: Resultant, lang: str, size: float = 1.0) -> Panel:
    """The vectors p_i (or p_i l_i) head to tail and the closing vector, one polygon per
    rotating part (forward and backward side by side for a V engine)."""
    pid = f"polygon-{R.quantity}-{R.kind}"
    rec = Recording()
    placer = Placer()
    paths = [_path(p) for p in R.polygons]
    extent = max(max(abs(a - b) for a in pts for b in pts) for pts in paths)
    s = polygon_scale(extent, size)
    x_off = 0.0
    sym = _SYM[(R.quantity, R.kind)]
    for poly, pts in zip(R.polygons, paths, strict=True):
        xs = [engine_paper(z, s)[0] for z in pts]
        o = (x_off - min(xs), 0.0)
        tag = f"{pid}-{poly.branch}" if poly.branch else pid
        dot(rec, o, 0.6, f"{tag}-pole")
        for r, a, b in zip(poly.rows, pts[:-1], pts[1:], strict=True):
            pa, pb = engine_paper(a, s, o), engine_paper(b, s, o)
            if abs(b - a) * s < 0.05:
                continue
            arrow(rec, pa, pb, VECTOR_STYLES["force"], f"{tag}-v{r.cylinder}", "vector force")
            placer.add_line([pa, pb])
        for r, a, b in zip(poly.rows, pts[:-1], pts[1:], strict=True):
            pa, pb = engine_paper(a, s, o), engine_paper(b, s, o)
            if abs(b - a) * s < 0.05:
                continue
            mid = ((pa[0] + pb[0]) / 2, (pa[1] + pb[1]) / 2)
            L = math.dist(pa, pb)
            nx, ny = -(pb[1] - pa[1]) / L, (pb[0] - pa[0]) / L
            lab = placer.place(str(r.cylinder), mid, SMALL_SIZE + 0.5, prefer=(nx, ny), gap=0.8)
            rec.text(lab, "label", f"{tag}-v{r.cylinder}-label")
        end = engine_paper(pts[-1], s, o)
        sub = "" if not poly.branch else ("^+" if poly.branch == "forward" else "^−")
        if poly.closed:
            text = f"{sym}{sub} = 0"
        else:
            z = poly.closing
            arrow(rec, o, end, CLOSING, f"{tag}-closing", "vector closing")
            placer.add_line([o, end])
            text = f"{sym}{sub} = {fmt(abs(z), 4, lang)}, {fmt(degrees360(math.atan2(z.imag, z.real)), 4, lang)}°"
        lab = placer.place(text, ((o[0] + end[0]) / 2, (o[1] + end[1]) / 2), SMALL_SIZE + 0.6, gap=1.5)
        rec.text(lab, "closing-label", f"{tag}-closing-label", fill=CLOSING.stroke or "#000")
        if R.quantity == "moment" and not poly.closed:
            # the seed's last step: the turned closing vector turned back 90° clockwise is the moment
            act = engine_paper(pts[-1] * -1j, s, o)
            arrow(rec, o, act, ACTUAL, f"{tag}-actual", "vector actual")
            placer.add_line([o, act])
            lab = placer.place(f"{sym}{sub} ({_t('actual', lang)})", act, SMALL_SIZE + 0.3, gap=1.0)
            rec.text(lab, "note", f"{tag}-actual-label", fill=ACTUAL.stroke or "#000")
        if poly.branch:
            lab = layout(_t(poly.branch, lang), o[0], -s * 0 + 6.0 + max(engine_paper(z, s, o)[1] for z in pts),
                         SMALL_SIZE, "start", "top")
            rec.text(lab, "note", f"{tag}-branch")
        x0, _, x1, _ = rec.bbox()
        x_off = x1 + 12.0
    x_tab = rec.bbox()[2] + 10.0
    y_tab = rec.bbox()[1]
    for poly in R.polygons:
        tab = table_recording(R, poly, lang)
        bx = tab.bbox()
        moved = tab.moved(x_tab - bx[0], y_tab - bx[1])
        rec.prims.extend(moved.prims)
        y_tab += bx[3] - bx[1] + 5.0
    unit = "N*m" if R.quantity == "moment" else "N"
    amp = f"{_ABS[(R.quantity, R.kind)]} = {fmt(R.amplitude, 5, lang)} {_t(unit, lang)}"
    if R.amplitude > 0:
        amp += f", φ = {fmt(degrees360(R.phase), 4, lang)}°"
    scale = f"μ = {fmt(s, 4, lang)} {'мм/ед.' if lang == 'ru' else 'mm/unit'}; " \
            f"{'ед.' if lang == 'ru' else 'unit'} = {fmt(R.polygons[0].unit, 5, lang)} {_t(unit, lang)}"
    return finish(pid, "polygon", None, rec, _t(f"{R.quantity}-{R.kind}", lang), scale, amp)


# --------------------------------------------------------------------------- tables


def grid_panel(pid: str, title: str, header: Sequence[str], rows: Sequence[Sequence[str]],
               note: str | None = None, left: int = 1) -> Panel:
    """A ruled table as a panel of its own."""
    return finish(pid, "table", None, grid_recording(pid, header, rows, left), title, note)


def grid_recording(pid: str, header: Sequence[str], rows: Sequence[Sequence[str]], left: int = 1,
                   caption: str | None = None) -> Recording:
    """A ruled table: header row, body rows; the first ``left`` columns left-aligned."""
    size = 3.5
    xe = column_edges([list(header)] + [list(r) for r in rows], size)
    rh = size * 1.75
    n = len(rows) + 1
    rec = Recording()
    ruled_grid(rec, pid, xe, n, rh, thick_rows=(1, n - 1) if n > 2 else ())  # the sums' row ruled too
    rec.begin(f"{pid}-cells", "cells")
    for j, cells in enumerate([list(header)] + [list(r) for r in rows]):
        yc = j * rh + rh / 2
        for i, t in enumerate(cells):
            if j == 0:
                lab = layout(t, (xe[i] + xe[i + 1]) / 2, yc, size, "middle", "middle")
            elif i < left:
                lab = layout(t, xe[i] + 1.5, yc, size, "start", "middle")
            else:
                lab = layout(t, xe[i + 1] - 1.5, yc, size, "end", "middle")
            rec.text(lab, "th" if j == 0 else "td")
    rec.end()
    if caption:
        rec.text(layout(caption, 0.0, -1.2, SMALL_SIZE + 0.3, "start", "bottom"), "note", f"{pid}-caption")
    return rec


def table_recording(R: Resultant, poly: Polygon, lang: str) -> Recording:
    """The seed's analytic table beside its polygon: β_i, cos β_i, sin β_i, p_i, (l_i,)
    p_i l_i cos β_i, p_i l_i sin β_i and the sums (the closing vector's projections), and
    each vector in N (N·m) with the closing vector's length in the last row."""
    moment = R.quantity == "moment"
    b = "β" if poly.order == 1 else "2β"
    head = ["№", f"{b}_i, °", f"cos {b}_i", f"sin {b}_i", "p_i"]
    head += ["l_i", f"p_i l_i cos {b}_i", f"p_i l_i sin {b}_i"] if moment else [f"p_i cos {b}_i", f"p_i sin {b}_i"]
    unit = _t("N*m" if moment else "N", lang)
    head.append(f"{'M_i' if moment else 'P_i'}, {unit}")
    rows = []
    for r in poly.rows:
        c, s = math.cos(r.angle), math.sin(r.angle)
        cells = [str(r.cylinder), fmt(degrees360(r.angle), 4, lang), fmt(c, 3, lang), fmt(s, 3, lang),
                 fmt(r.p, 3, lang)]
        if moment:
            cells.append(fmt(r.l, 3, lang))
        cells += [fmt(r.p * r.l * c, 3, lang), fmt(r.p * r.l * s, 3, lang), fmt(r.p * r.l * poly.unit, 5, lang)]
        rows.append(cells)
    z = poly.closing
    total = 0.0 if poly.closed else abs(z) * poly.unit
    rows.append(["Σ"] + [""] * (len(head) - 4) + [fmt(z.real, 3, lang), fmt(z.imag, 3, lang), fmt(total, 5, lang)])
    tag = f"-{poly.branch}" if poly.branch else ""
    caption = None if not poly.branch else _t(poly.branch, lang)
    return grid_recording(f"table-{R.quantity}-{R.kind}{tag}", head, rows, caption=caption)


def results_panel(b: Balance, chk: ExactCheck | None, lang: str) -> Panel:
    head = [_t("quantity", lang), _t("dimless", lang), _t("amplitude", lang), _t("unit", lang), _t("phase", lang)]
    rows = []
    for quantity, res in (("force", b.forces), ("moment", b.moments)):
        for kind in KINDS:
            R = res[kind]
            unit = "N*m" if quantity == "moment" else "N"
            rows.append([_ABS[(quantity, kind)], fmt(R.dimensionless, 4, lang), fmt(R.amplitude, 5, lang),
                         _t(unit, lang), fmt(degrees360(R.phase), 4, lang) if R.amplitude > 0 else "—"])
    note = None
    if chk is not None:
        note = (f"{_t('exact', lang)}: max |R| = {fmt(chk.max_exact, 5, lang)} {_t('N', lang)}, "
                f"{_t('err', lang)} {fmt(chk.max_error, 3, lang)} {_t('N', lang)}; "
                f"max |M| = {fmt(chk.max_moment, 5, lang)} {_t('N*m', lang)}, "
                f"{_t('err', lang)} {fmt(chk.max_moment_error, 3, lang)} {_t('N*m', lang)}")
    return grid_panel("results", _t("results", lang), head, rows, note)


def counterweights_panel(b: Balance, lang: str, size: float = 1.0) -> Panel:
    head = [_t("for", lang), _t("plane", lang), _t("mr", lang), _t("mass", lang), _t("radius", lang),
            _t("angle", lang)]
    rows = [[_t(c.of, lang), fmt(c.plane_z, 4, lang), fmt(c.mass_radius, 4, lang), fmt(c.mass, 4, lang),
             fmt(c.radius, 4, lang), fmt(degrees360(c.angle), 4, lang)] for c in b.counterweights]
    if not rows:
        return grid_panel("counterweights", _t("cw", lang), head, [[_t("none", lang), "—", "—", "—", "—", "—"]],
                          _cw_note(b, lang))
    # an end view: crank 1 up, each counterweight's m·r as a vector at its angle, at a round scale
    rec = Recording()
    placer = Placer()
    big = max(c.mass_radius for c in b.counterweights)
    k_mr = diagram_scale(big, 22.0 * size)  # kg·m per mm
    Rr = big / k_mr
    rec.circle((0.0, 0.0), Rr, HAIR, "cw-circle")
    rec.line((0.0, 0.0), (0.0, -Rr), Style(width=0.7), "cw-crank1")
    placer.add_line([(0.0, 0.0), (0.0, -Rr)])
    rec.text(placer.place("1", (0.0, -Rr), LABEL_SIZE, prefer=(0.0, -1.0), gap=0.8), "label", "cw-crank1-label")
    for k, c in enumerate(b.counterweights):
        tip = engine_paper(cmath.exp(1j * c.angle) * c.mass_radius, 1.0 / k_mr)
        style = CLOSING if c.of == "rotating" else Style(width=0.5, stroke="#1f4e9c")
        arrow(rec, (0.0, 0.0), tip, style, f"cw-{k}", "vector counterweight")
        placer.add_line([(0.0, 0.0), tip])
        lab = placer.place(f"{_t(c.of, lang)}, z = {fmt(c.plane_z, 4, lang)}", tip, SMALL_SIZE + 0.3, gap=1.0)
        rec.text(lab, "label", f"cw-{k}-label", fill=style.stroke or "#000")
    tab = grid_recording("cw-table", head, rows)
    x0 = rec.bbox()[2] + 10.0
    y0 = rec.bbox()[1]
    bx = tab.bbox()
    rec.prims.extend(tab.moved(x0 - bx[0], y0 - bx[1]).prims)
    scale = f"μ_{{mr}} = {fmt(k_mr, 4, lang)} {_t('kgm_mm', lang)}"
    return finish("counterweights", "table", None, rec, _t("cw", lang), scale, _cw_note(b, lang))


def _cw_note(b: Balance, lang: str) -> str | None:
    """What a counterweight cannot take, in the sheet's language."""
    out = []
    for t in b.notes:
        key = "cw_first" if t.startswith("first-order") else "cw_second" if t.startswith("second-order") else ""
        out.append(_t(key, lang) if key else t)
    return "; ".join(out) or None
