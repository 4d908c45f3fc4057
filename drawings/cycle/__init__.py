"""The cycle's sheets: kinematic diagrams, and the machine dynamics with the flywheel.

Added to a linkage's drawing when its outputs ask for ``diagrams`` or ``dynamics``
(:func:`extend`).  Every diagram carries its scale as the course writes it, the pole
distance of the graphical differentiation or integration, and the exact curve drawn thin
and dashed beside the graphical one.
"""

from __future__ import annotations

import dataclasses
import math
import re
from collections.abc import Sequence
from pathlib import Path

import numpy as np

from drawings.cycle.column import column_fits, phi_column
from drawings.cycle.cycle_plot import EXACT, GRAPH, Axes, loc, number, plot_panel, wide_table
from drawings.cycle.dynamics_diagrams import (
    a_panel,
    fly_table,
    i_panel,
    indicator_panels,
    m_panel,
    omega_panel,
    t_panel,
    w_panel,
)
from drawings.cycle.words import UNITS, tr
from drawings.paper.backend import Recording
from drawings.paper.common import fmt
from drawings.paper.fill import drawn_part
from drawings.paper.panel_frame import Panel
from drawings.paper.sheet import Sheet, SheetSpec, compose
from plans.cycle import spline
from plans.cycle.diagrams import Diagrams
from plans.cycle.dynamics import Dynamics
from plans.cycle.table import CycleTable, TableRow
from plans.scene.model import Scene
from plans.solution import Solution

# --------------------------------------------------------------------------- kinematic diagrams


def diagram_panels(dg: Diagrams, lang: str, first: int = 1) -> list[Panel]:
    """s, v, a of every subject, each with its pole, scale and error; positions numbered from
    ``first``."""
    out: list[Panel] = []
    L = dg.spec.length_mm
    phi0 = float(dg.nodes_deg[0])
    for g in dg.diagrams:
        rec = Recording()
        ax = Axes(rec, f"diagram-{g.name}", dg.mu_phi, phi0, lang, first)
        ys = g.values * g.scale
        ye = g.exact * g.scale
        ax.frame(L, float(min(ys.min(), ye.min())), float(max(ys.max(), ye.max())), g.name.replace("_", "_"))
        ax.positions(dg.nodes_deg[:-1])
        step = max(1, len(ye) // 240)  # a thin curve needs no more than a point per mm
        ax.curve(ax.x(g.exact_phi_deg[::step]), ye[::step], EXACT, f"diagram-{g.name}-exact")
        xs = ax.x(g.phi_deg)
        if g.quantity != "s":
            ax.pole(float(g.pole_mm or dg.pole_mm), ys, "P", "H_1" if g.quantity == "v" else "H_2")
        cx, cy = _closed(xs, ys, L)
        if g.quantity != "s":  # the draftsman's smooth curve through the found points
            cx, cy = spline.sample(cx, cy, spline.slopes(cx, cy), 6)
        ax.curve(cx, cy, GRAPH, f"diagram-{g.name}-graphical")
        ax.dots(xs, ys)
        how = tr(dg.spec.method, lang) if g.quantity != "s" else ""
        err = (f"{tr('error', lang)}: max {fmt(g.error_max_pct, 2, lang)} %, {_rms(lang)} {fmt(g.error_rms_pct, 2, lang)} %"
               if g.quantity != "s" else tr("exact_thin", lang))
        note = "; ".join(x for x in (how, err) if x)
        formula = g.scale_formula.replace(".", ",") if lang == "ru" else g.scale_formula
        scale = f"{formula}; μ_φ = {fmt(dg.mu_phi, 4, lang)} mm/rad"
        out.append(plot_panel(f"diagram-{g.name}", "diagram", f"{tr(g.quantity, lang)} {g.name}", rec, scale,
                              note, lang=lang))
    out += _ordinates_table(dg, lang, first)
    rows = [[g.name, number(g.error_max_pct, lang, 3), number(g.error_rms_pct, lang, 3),
             "—" if g.integral_error_max_pct is None else number(g.integral_error_max_pct, lang, 3)]
            for g in dg.diagrams]
    head = ["", "max", _rms(lang), "∫ max"]
    out.append(wide_table("diagram-errors", tr("errors", lang), head, rows, lang))
    return out


def _ordinates_table(dg: Diagrams, lang: str, first: int = 1) -> list[Panel]:
    """The diagrams over the positions: ordinate (mm) and value at each position, as the
    course tabulates them (the chord method's values sit between the positions)."""
    tables = []
    for subject in dict.fromkeys(g.subject for g in dg.diagrams):
        rows = []
        for g in dg.diagrams:
            if g.subject != subject:
                continue
            at = np.interp(dg.nodes_deg[:-1], g.phi_deg, g.values, period=360.0)
            u = UNITS.get(g.unit, (g.unit, g.unit))[0 if lang == "ru" else 1]
            rows.append(TableRow(f"{g.name}:mm", f"y({g.name})", "mm", tuple(float(x) for x in at * g.scale)))
            rows.append(TableRow(g.name, g.name, u, tuple(float(x) for x in at)))
        tables.append(CycleTable(f"{tr('ordinates', lang)} {subject}", tuple(float(x) for x in dg.nodes_deg[:-1]),
                                 tuple(rows)))
    return table_panels(tables, lang, "diagram", first=first)


def _closed(xs: np.ndarray, ys: np.ndarray, L: float) -> tuple[np.ndarray, np.ndarray]:
    """A periodic diagram joined over the whole axis: where its points stop short of 0 or L
    (the middles of the chords), the curve runs on to the value the cycle continues with."""
    if xs[0] > 1e-9:
        y0 = ys[-1] + (ys[0] - ys[-1]) * (L - xs[-1]) / (xs[0] + L - xs[-1]) if xs[-1] < L - 1e-9 else ys[-1]
        xs, ys = np.concatenate([[0.0], xs]), np.concatenate([[y0], ys])
    if xs[-1] < L - 1e-9:
        xs, ys = np.append(xs, L), np.append(ys, ys[0])
    return xs, ys


# --------------------------------------------------------------------------- dynamics


#: Each diagram of the cycle's dynamics alone, by its letter: M, A, T, I, W and ω (``w``).


def _rms(lang: str) -> str:
    """The root-mean-square error's short name: "ср. кв." on a Russian sheet."""
    return "ср. кв." if lang == "ru" else "rms"


def table_panels(tables: Sequence[CycleTable], lang: str, prefix: str,
                 titles: Sequence[str] | None = None, columns: int = 12, first: int = 1) -> list[Panel]:
    """Cycle tables as panels: positions as columns (numbered from ``first``), split in parts of
    ``columns`` when they are many."""
    out: list[Panel] = []
    for i, t in enumerate(tables):
        title = titles[i] if titles else t.title
        n = len(t.phi_deg)
        chunks = [range(0, n)] if n <= columns + 2 else [range(a, min(n, a + columns)) for a in range(0, n, columns)]
        for j, ks in enumerate(chunks):
            head = [tr("position", lang)] + [str(k + first) for k in ks]
            rows = [[tr("phi", lang)] + [number(t.phi_deg[k], lang, 6) for k in ks]]
            for r in t.rows:
                big = max([abs(v) for v in r.values if v is not None] + [0.0])
                # a dead centre's 1e-8 is a zero on paper
                cells = [None if r.values[k] is None else (0.0 if abs(r.values[k] or 0.0) <= 1e-5 * big
                                                          else r.values[k]) for k in ks]
                u = UNITS.get(r.unit, (r.unit, r.unit))[0 if lang == "ru" else 1]
                unit = f", {u}" if u and u != "1" else ""
                label = re.sub(r"_pr\b", "_пр", r.label) if lang == "ru" else r.label  # I_пр, M_пр
                rows.append([f"{label}{unit}"] + [number(c, lang, 4) for c in cells])
            out.append(wide_table(f"{prefix}-table-{i + 1}-{j + 1}", title, head, rows, lang))
    return out


def analogue_plans(plans: Sequence, lang: str, style: str, mu: float) -> list[Panel]:
    """The plans of velocity analogues at the table's positions (``Solution.analogue_plans``:
    velocity plans at μ_v = μ/|ω1|, each segment the analogue v/ω1 at μ, mm per m, the round
    scale written under the velocity one), drawn."""
    from drawings.plan_panel import plan_panel

    note = loc(f"{tr('analogues', lang)}: μ = {fmt(mu, 4, lang)} mm/m (ω_1 = 1)", lang)
    return [plan_panel(p, lang, style, pid=f"analogue-{k + 1}", note=note) for k, p in enumerate(plans)]


def dynamics_panels(d: Dynamics, tables: Sequence[CycleTable], lang: str, analogues: Sequence = (),
                    columns: int = 12, first: int = 1, w_size: float = 1.0, size: float = 1.0) -> list[Panel]:
    """The dynamics sheet's panels; ``w_size``: the energy–mass diagram's size against its
    readable one (smaller on a small sheet, larger where an A1 sheet has room); ``size``: the
    ω(φ) and indicator diagrams' against their A1 ones."""
    titles = [f"{tr('analogues', lang)}, μ = {fmt(d.scales.analogue, 4, lang)} mm/m (ω_1 = 1)",
              tr("Ipr", lang), f"{tr('Mpr', lang)}; {tr('sign', lang)}", tr("energy", lang)]
    plans = analogue_plans(analogues, lang, d.scene.scale_style, d.scales.analogue)  # none where the first sheet has them
    return ([m_panel(d, lang, first), a_panel(d, lang, first), t_panel(d, lang, first),
             i_panel(d, lang, first), w_panel(d, lang, first, w_size), omega_panel(d, lang, first, size),
             fly_table(d, lang)]
            + indicator_panels(d, lang, size) + table_panels(tables, lang, "dyn", titles, columns, first) + plans)


# --------------------------------------------------------------------------- the hook


def extend(sol: Solution | Scene, spec: SheetSpec, sheets: list[Sheet], scale_text: str | None = None,
           diagrams: bool = True, lay=None) -> list[Sheet]:
    """The drawing's sheets and, when the scene asks, the diagrams and dynamics sheets after them,
    numbered on from the last (a Scene is solved first, by plans.solve); ``diagrams=False``:
    the kinematic diagrams are already on the drawing's sheets (the course's kinematics sheet);
    ``lay(panels, spec)``: how the dynamics' panels are laid out (default: :func:`compose`)."""
    if not isinstance(sol, Solution):
        from plans.solution import solve

        sol = solve(sol)
    scene = sol.scene
    if not (scene.wants("diagrams") or scene.wants("dynamics")):
        return sheets
    lang = spec.language
    cr = sol.cycle
    extra: list[Sheet] = []
    if cr is not None and cr.diagrams is not None and diagrams:
        sub = dataclasses.replace(spec, subtitle=tr("diagrams", lang), pins=())
        extra += compose(fitting_diagrams(sol, cr.diagrams, spec), sub, scale_text, scene.path, render=False)
    if cr is not None and cr.dynamics is not None:
        sub = dataclasses.replace(spec, subtitle=tr("dynamics", lang), pins=())
        tabs = cr.tables[-4:]  # the dynamics' own: analogues, I_pr, M_pr, work and energy
        analogues: Sequence = () if scene.wants("velocity_plan") else sol.analogue_plans()  # else on the first sheet
        if analogues and spec.format in _GROWN:
            beside = analogue_plans(analogues, lang, scene.scale_style, cr.dynamics.scales.analogue)
            sheets, analogues = _plans_beside_positions(sheets, beside,
                                                        analogues, lay, scene.path)
        panels = fitting_dynamics(sol, cr.dynamics, tabs, sub, analogues)
        flat = lay is not None  # the course's set: its sheets laid flat

        def laid_out(ps: list[Panel], sp: SheetSpec) -> list[Sheet]:
            from drawings.paper.sheet import fits_empty

            ps = phi_column(ps, lambda p: fits_empty(p, sp.format, sp.orientation))  # one φ column
            return lay(ps, sp) if lay is not None else compose(ps, sp, scale_text, scene.path, render=False)
        laid = laid_out(panels, sub)
        if spec.format in _GROWN:
            laid = _fuller_dynamics(sol, panels, sub, laid_out, laid)
        elif flat:  # a last sheet left nearly empty: the diagrams on a shorter φ axis, if all then fit fewer
            axis = 240.0
            while len(laid) > 1 and min(map(_used, laid)) < 1 / 3 and axis > 160.0:
                axis -= 20.0
                fewer = laid_out(fitting_dynamics(sol, sol.dynamics_drawn(axis, 1.0), tabs, sub, analogues, axis),
                                 sub)
                if len(fewer) < len(laid):
                    laid = fewer
                    break
        extra += laid
    out = list(sheets) + extra
    for i, sh in enumerate(out):  # drawn here, numbered (the candidates laid out above are not)
        sh.number, sh.count = i + 1, len(out)
        sh.prims = []
        sh.render()
    return out


def _plans_beside_positions(sheets: list[Sheet], panels: list[Panel], analogues: Sequence, lay,
                            path: str) -> tuple[list[Sheet], Sequence]:
    """The plans of velocity analogues on the drawing's last sheet, beside the plan of
    positions, where that sheet holds no position's blocks and keeps them on one sheet (the
    kinematics sheet a course draws), laid out as the drawing lays it (``lay``, else
    :func:`compose`); then none are left for the dynamics sheet."""
    if not sheets:
        return sheets, analogues
    own = [p for p, _, _ in sheets[-1].placed]
    if any(p.phi is not None for p in own):
        return sheets, analogues
    spec = sheets[-1].spec
    laid = lay(own + panels, spec) if lay is not None else compose(own + panels, spec, None, path, render=False)
    if len(laid) > 1:
        return sheets, analogues
    return sheets[:-1] + laid, ()


#: The formats whose dynamics sheets take longer φ axes and taller diagrams where they have room.
_GROWN = ("A1", "A2")
#: The φ scales tried (mm per degree, round ones: a course writes μ_φ = 1 mm/°) and the
#: diagrams' heights (times the A1 ones).
_PER_DEG = (0.25, 0.4, 0.5, 1.0)
_HEIGHTS = (1.0, 1.25, 1.5, 2.0, 2.5)


def _fuller_dynamics(sol: Solution, base: Sequence[Panel], spec: SheetSpec, lay, laid: list[Sheet]) -> list[Sheet]:
    """The dynamics' sheets at the φ axis and diagram heights (round scales all, the
    energy–mass, ω(φ) and indicator diagrams as much larger) that keep the fewest sheets and
    leave the emptiest of them least empty; ``laid``, the A1 sizes' (``base``), where none does
    better.  Each axis is tried from the lowest diagrams up, until they take one more sheet;
    the tables and plans are ``base``'s, each diagram drawn once per size."""
    from functools import cache

    from drawings.paper.sheet import fits_empty

    d = sol.dynamics
    assert d is not None, "a scene with dynamics"
    lang, first = spec.language, spec.first_position
    best, key = laid, _key(laid, 240.0 * (1.5 if d.spec.cycle_deg == 720 else 1.0))
    per_360 = 1.5 if d.spec.cycle_deg == 720 else 1.0  # the engine's axis is given for 360°
    wit = cache(lambda size: w_panel(d, lang, first, size))
    ind = cache(lambda size: indicator_panels(d, lang, size))
    fixed = [p for p in base if p.pid == "dyn-flywheel"]
    rest = [p for p in base if p.kind != "dynamics" and p.pid != "dyn-flywheel"]  # tables, plans
    def fits(p: Panel) -> bool:
        return fits_empty(p, spec.format, spec.orientation)

    for length in _axes(d.spec.cycle_deg):
        fewest = None
        for h in _HEIGHTS:
            dh = sol.dynamics_drawn(length / per_360, h)
            column = [f(dh, lang, first) for f in (m_panel, a_panel, t_panel, i_panel)] + [omega_panel(dh, lang, first, h)]
            if not all(map(fits, column)) or not column_fits(column, fits):  # all in one φ column
                break
            # the energy–mass and indicator diagrams beside the column, as large again where there is room
            for side in [h] + [x for x in _HEIGHTS if x > h]:
                panels = column[:4] + [wit(min(side, 2.0)), column[4]] + fixed + ind(side) + rest
                if not all(map(fits, panels)):
                    break
                sheets = lay(panels, spec)
                if fewest is not None and len(sheets) > fewest:
                    break
                fewest = len(sheets) if fewest is None else fewest
                if _key(sheets, length) > key:
                    best, key = sheets, _key(sheets, length)
    return best


def _axes(cycle_deg: float) -> list[float]:
    """The φ axes tried (mm over the working cycle) at round scales in mm/°: a course sheet's
    is 180 mm to 360 mm long (to 540 mm over a four-stroke engine's two turns)."""
    top = 360.0 * (1.5 if cycle_deg == 720 else 1.0)
    return [cycle_deg * r for r in _PER_DEG if 180.0 <= cycle_deg * r <= top]


def _key(sheets: Sequence[Sheet], axis: float) -> tuple[int, bool, float, float, float]:
    """How good a set of sheets drawn at a φ axis of ``axis`` mm is: the fewest sheets first;
    then none of them more than a third empty; then the longer axis; then its emptiest sheet's
    part drawn (to 0.1 %), then all of them."""
    parts = [_used(sh) for sh in sheets]
    return -len(sheets), min(map(drawn_part, sheets)) >= 2 / 3, axis, round(min(parts), 3), sum(parts)


def fitting_diagrams(sol: Solution, dg: Diagrams, spec: SheetSpec) -> list[Panel]:
    """The kinematic diagrams as they fit the sheet: on a small one at a shorter φ axis (the
    scales μφ, μs... written on them the engine's at that length), not refused."""
    from drawings.paper.sheet import fits_empty

    panels = diagram_panels(dg, spec.language, spec.first_position)
    length = dg.spec.length_mm
    while not all(fits_empty(p, spec.format, spec.orientation) for p in panels) and length > 60.0:
        length = max(60.0, math.floor(length * 0.8 / 10.0) * 10.0)
        smaller = sol.diagrams_drawn(length)
        if smaller is None:
            break
        panels = diagram_panels(smaller, spec.language, spec.first_position)
    return panels


def _used(sheet: Sheet) -> float:
    """The part of a sheet's field (inside the frame) its panels cover (they do not overlap)."""
    from drawings.paper.sheet import usable

    a = usable(sheet.width, sheet.height)
    return sum(p.width * p.height for p, _, _ in sheet.placed) / ((a[2] - a[0]) * (a[3] - a[1]))


def fitting_dynamics(sol: Solution, d: Dynamics, tabs: Sequence[CycleTable], spec: SheetSpec,
                      analogues: Sequence = (), axis: float = 240.0) -> list[Panel]:
    """The dynamics sheet's panels as they fit the sheet: on a small one the φ axis of the
    diagrams is shortened (240 mm on A1 and A2, or ``axis``, the one ``d`` is drawn at) and
    their heights lowered until every diagram fits, not refused."""
    from drawings.paper.sheet import fits_empty

    panels = dynamics_panels(d, tabs, spec.language, analogues, first=spec.first_position)
    height = 1.0
    columns = 12
    w_size = 1.0
    while True:
        big = [p for p in panels if not fits_empty(p, spec.format, spec.orientation)]
        if big and columns > 3 and any(p.pid.startswith("dyn-table") for p in big):
            columns //= 2  # a table over the positions in more, narrower parts
        elif any(p.pid == "dyn-W" for p in big) and w_size > 0.3:
            w_size *= 0.8  # the energy–mass diagram at smaller round scales, its letters kept
        elif big and axis > 60.0:
            axis = max(60.0, math.floor(axis * 0.8 / 10.0) * 10.0)
            height = max(0.4, height * 0.85)
            d = sol.dynamics_drawn(axis, height)
        else:
            return panels
        panels = dynamics_panels(d, tabs, spec.language, analogues, columns, spec.first_position, w_size)


def diagrams_sheet_seconds(path: str | Path, repeat: int = 5) -> float:
    """Best time of the diagrams sheet of a scene to SVG text: engine, panels, layout, SVG."""
    import time

    from plans.kinematics.placing import load_scene
    from plans.solution import solve

    scene = load_scene(path)
    spec = dataclasses.replace(scene.sheet_for(), pins=())
    best = float("inf")
    for _ in range(max(1, repeat)):
        t = time.perf_counter()
        dia = solve(scene).diagrams
        assert dia is not None, f"{path} asks for no kinematic diagrams"
        sheets = compose(diagram_panels(dia, spec.language), spec, "", scene.path)
        for sh in sheets:
            sh.svg()
        best = min(best, time.perf_counter() - t)
    return best
