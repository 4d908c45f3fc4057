"""The gear train's panels: its unfolded scheme in GOST 2.770 symbols, the plan of linear
velocities beside it at its heights and the plan of angular velocities (Smirnov's method,
from :mod:`plans.gears.train`), the speeds and the 2K-H synthesis tables; and what every
gear panel shares (styles, words, the ruled table)."""

from __future__ import annotations

import math
from collections.abc import Sequence
from dataclasses import dataclass

from drawings.linkage.panels import Panel, finish
from drawings.paper.backend import MAIN, PAPER, THICK, THIN, Recording, Style
from drawings.paper.common import Placer, arrow, dot, fmt
from drawings.paper.i18n import lookup
from drawings.paper.i18n import tr as words
from drawings.paper.panel_frame import ruled_grid
from drawings.paper.sheet import SheetSpec
from drawings.paper.text import layout
from plans.gears.solve import GearSolution
from plans.kinematics.scales import is_round, round_down, round_scale, round_up
from plans.language import SHEET_WORDS

AXIS = Style(stroke="#000", width=0.25, dash=(8.0, 1.5, 1.0, 1.5), cls="axis")
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


def grid(rows: Sequence[Sequence[str]], pid: str) -> Recording:
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


def velocity_panel(sol: GearSolution, lang: str, f: float = 1.0, g: float = 1.0) -> Panel:
    """The plan of linear velocities beside the scheme (its heights the scheme's), each
    shaft's line through its known points; ``f`` magnifies the engine's plan (μ_l and μ_v × f),
    ``g`` its velocities once more (μ_v × f·g: its own round scale)."""
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
        pts = [(nm, (q[0] * f * g, q[1] * f)) for nm, q in ln.points]
        if len({round(p[1], 6) for _, p in pts}) < 2:
            pts.append(("", (ln.p1[0] * f * g, ln.p1[1] * f)))
        lo = min(pts, key=lambda t: t[1][1])[1]
        hi = max(pts, key=lambda t: t[1][1])[1]
        rec.line(PAPER.z(complex(*lo)), PAPER.z(complex(*hi)), MAIN, f"line-{n}")
        placer.add_line([PAPER.z(complex(*lo)), PAPER.z(complex(*hi))])
        mid = ((lo[0] + hi[0]) / 2, (lo[1] + hi[1]) / 2)
        rec.text(placer.place(n, PAPER.z(complex(*mid)), LABEL, (1.0, 0.0)), "label", f"label-line-{n}")
        for name, (vx, vy) in pts:
            if not name or name in done:
                continue
            done.add(name)
            if abs(vx) > 1e-6:
                arrow(rec, (0.0, -vy), (vx, -vy), THIN, f"v-{name}", "vector")
            dot(rec, (vx, -vy), 0.6, f"pt-{name}")
            rec.text(placer.place(name, (vx, -vy), SMALL + 0.5, (1.0, -0.5)), "label", f"label-{name}")
    txt = f"μ_v = {fmt(plan.mu_v * f * g, 4, lang)} {'мм/(м/с)' if lang == 'ru' else 'mm/(m/s)'}"
    return finish("velocity-plan", "velocity-plan", None, rec, tr("vplan", lang), txt)


def rays_panel(sol: GearSolution, lang: str, f: float = 1.0, g: float = 1.0) -> Panel:
    """The plan of angular velocities: rays from the pole O_ω parallel to the shafts' lines cut
    the reference line at h; ``f`` magnifies it (h and the intercepts; μ_ω × f), ``g`` the
    intercepts alone, as a plan of velocities drawn at μ_v × g turns its lines (μ_ω × f·g)."""
    plan = sol.plan
    assert plan is not None
    rec = Recording()
    placer = Placer()
    h = plan.h * f
    xs = [ln.intercept * f * g for ln in plan.lines.values()] + [0.0]
    lo, hi = min(xs) - 10.0, max(xs) + 10.0
    rec.line(PAPER(lo, h), PAPER(hi, h), MAIN, "reference-line")
    dot(rec, (0.0, 0.0), 0.8, "pole")
    rec.text(layout("O_ω", 2.0, 3.5, LABEL, "start", "middle"), "label", "label-pole")
    rec.line((0.0, 0.0), PAPER(0.0, h + 4.0), AXIS, "pole-normal")
    placer.add_line([PAPER(lo, h), PAPER(hi, h)])
    for n, ln in plan.lines.items():
        rec.line((0.0, 0.0), (ln.intercept * f * g, -h), THIN, f"ray-{n}")
        placer.add_line([(0.0, 0.0), (ln.intercept * f * g, -h)])
        dot(rec, (ln.intercept * f * g, -h), 0.6, f"omega-{n}")
    for n, ln in plan.lines.items():
        rec.text(placer.place(f"ω_{n}", (ln.intercept * f * g, -h), SMALL + 0.5, (0.0, -1.0)), "label",
                 f"label-omega-{n}")
    rec.text(layout(f"h = {fmt(h, 3, lang)}", 2.0, -h / 2, SMALL, "start", "middle"), "note", "pole-distance")
    txt = f"μ_ω = {fmt(plan.mu_omega * f * g, 4, lang)} {'мм/(рад/с)' if lang == 'ru' else 'mm/(rad/s)'}"
    return finish("ray-diagram", "ray-diagram", None, rec, tr("rays", lang), txt)


def speeds_panel(sol: GearSolution, lang: str) -> Panel:
    assert sol.omega is not None and sol.plan is not None
    rows = [[tr("shaft", lang), tr("willis", lang), tr("plan", lang), "ω, " + ("рад/с" if lang == "ru" else "rad/s")]]
    for n, w in sol.omega.items():
        wp = sol.plan.lines[n].omega
        rows.append([n, fmt(w * 30 / math.pi, 7, lang), fmt(wp * 30 / math.pi, 7, lang), fmt(w, 6, lang)])
    return finish("speeds", "table", None, grid(rows, "speeds"), tr("speeds", lang))


def synthesis_panel(sol: GearSolution, lang: str) -> Panel:
    t = sol.synthesis
    assert t is not None
    ok = t.conditions(sol.file.ha)
    rows = [["z_1", "z_2", "z_3", "k", "i_{1H}"] + [words(c, lang) for c in ok],
            [str(t.z1), str(t.z2), str(t.z3), str(t.planets), fmt(t.ratio, 5, lang)] +
            ["+" if v else "−" for v in ok.values()]]
    return finish("synthesis", "table", None, grid(rows, "synthesis"), tr("synthesis", lang))


def magnifications(sol: GearSolution) -> list[float]:
    """How much larger than the engine's plan the train's scheme (and the heights of its plan of
    velocities) may be drawn, largest first: the factors of 10, 5, 4, 2.5, 2 that keep μ_l
    round, and 1.  The velocities take their own round scale (:func:`train_scales`)."""
    plan = sol.plan
    assert plan is not None
    return [f for f in (10.0, 5.0, 4.0, 2.5, 2.0) if is_round(plan.mu_l * f)] + [1.0]


def extent(sol: GearSolution) -> tuple[float, float]:
    """The scheme's height (every gear's working circle about its axis) and the plan's widest
    velocity at the engine's scales, mm."""
    plan = sol.plan
    assert plan is not None
    gears = sol.file.gears
    ys = [pt[1] for ln in plan.lines.values() for _, pt in ln.points]
    for p in sol.pairs:
        for w in p.wheels:
            y, r = plan.axes[gears[w.name].shaft] * plan.mu_l, w.working * plan.mu_l
            ys += [y - r, y + r]
    tall = (max(ys) - min(ys)) if ys else 1.0
    wide = max([abs(pt[0]) for ln in plan.lines.values() for _, pt in ln.points] + [1.0])
    return tall, wide


def magnification(sol: GearSolution, spec: SheetSpec) -> float:
    """The largest of :func:`magnifications` that keeps the scheme and the plan within half the
    sheet's height and the plan within 0.3 of its width (1, the engine's plan, fits any)."""
    tall, wide = extent(sol)
    W, H = spec.size
    return next(f for f in magnifications(sol) if f == 1.0 or (tall * f <= 0.5 * H and wide * f <= 0.3 * W))


@dataclass(frozen=True)
class TrainScales:
    """The train's drawings each at its own round scale, as factors of the engine's plan: the
    scheme and the plan's heights μ_l × f, the plan's velocities μ_v × f·g, the plan of angular
    velocities μ_ω × q·g (its rays parallel to the plan's lines: h × q, intercepts × q·g)."""

    f: float
    g: float
    q: float


def train_scales(sol: GearSolution, f: float) -> list[TrainScales]:
    """The plans of velocities worth drawing beside the scheme at magnification ``f``, the
    shortest first: μ_v round, from the round scale just below the engine's × f up to a plan
    1.2 times as wide as the scheme is tall (three at most); each with the plan of angular
    velocities at the least round μ_ω that keeps its pole as far from the reference line as
    the engine's (h = μ_ω μ_l/μ_v), and at the largest that draws it within the plan of
    velocities' width and the scheme's height (as wide as the two side by side, about)."""
    plan = sol.plan
    assert plan is not None
    tall, wide = extent(sol)
    mus: list[float] = []
    mu = round_down(plan.mu_v * f)
    while len(mus) < 3 and (not mus or wide * mu / plan.mu_v <= 1.2 * tall * f):
        mus.append(mu)
        mu = round_up(mu * 1.01)  # the next round scale
    xs = [ln.intercept for ln in plan.lines.values()] + [0.0]
    spread = (max(xs) - min(xs)) / plan.mu_omega  # rad/s from the least ω (or 0) to the largest
    out = []
    for mu_v in mus:
        g = mu_v / (plan.mu_v * f)
        # the pole no nearer the reference line than the engine's h: h = μ_ω μ_l / μ_v
        least = round_up(plan.h * mu_v / (plan.mu_l * f))
        wider = round_scale(spread, wide * mu_v / plan.mu_v + tall * f)
        for mu_w in dict.fromkeys((least, max(least, wider))):
            out.append(TrainScales(f, g, mu_w / (plan.mu_omega * g)))
    return out


def train_figures(sol: GearSolution, lang: str, s: TrainScales) -> list[Panel]:
    """The train's figures at the scales ``s``: its scheme, plan of velocities beside it and
    plan of angular velocities (none without a plan)."""
    if sol.plan is None:
        return []
    return [scheme_panel(sol, lang, s.f), velocity_panel(sol, lang, s.f, s.g), rays_panel(sol, lang, s.q, s.g)]


def train_tables(sol: GearSolution, lang: str) -> list[Panel]:
    """The train's tables: the speeds (by Willis and off the plan), the 2K-H synthesis."""
    return ([speeds_panel(sol, lang)] if sol.plan is not None else []) + \
        ([synthesis_panel(sol, lang)] if sol.synthesis is not None else [])


def train_panels(sol: GearSolution, lang: str, s: TrainScales) -> list[Panel]:
    """The train's figures and tables."""
    return train_figures(sol, lang, s) + train_tables(sol, lang)
