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

from drawings.cycle.cycle_plot import EXACT, GRAPH, Axes, number, plot_panel, wide_table
from drawings.paper.backend import HAIR, MAIN, THIN, Recording, Style
from drawings.paper.common import fmt
from drawings.paper.i18n import lookup
from drawings.paper.panel_frame import Panel
from drawings.paper.sheet import Sheet, SheetSpec, compose
from drawings.paper.text import layout
from plans.cycle import spline
from plans.cycle.diagrams import Diagrams
from plans.cycle.dynamics import Dynamics
from plans.cycle.table import CycleTable, TableRow
from plans.scene.model import Scene
from plans.solution import Solution

WORDS: dict[str, tuple[str, str]] = {
    "diagrams": ("Кинематические диаграммы", "Kinematic diagrams"),
    "dynamics": ("Динамика машины. Маховик", "Machine dynamics. Flywheel"),
    "s": ("Диаграмма перемещений", "Displacement diagram"),
    "v": ("Диаграмма скоростей", "Velocity diagram"),
    "a": ("Диаграмма ускорений", "Acceleration diagram"),
    "chords": ("метод хорд", "chord method"),
    "tangents": ("метод касательных", "tangent method"),
    "exact_thin": ("тонкая штриховая — точная кривая", "thin dashed: exact curve"),
    "error": ("погрешность", "error"),
    "errors": ("Погрешность графических диаграмм, % размаха", "Error of the graphical diagrams, % of range"),
    "M": ("Приведённый момент сил M_пр(φ)", "Reduced moment of forces M_pr(φ)"),
    "A": ("Работы A_c(φ), A_д(φ)", "Work A_c(φ), A_d(φ)"),
    "T": ("Изменение кинетической энергии ΔT(φ)", "Change of kinetic energy ΔT(φ)"),
    "I": ("Приведённый момент инерции I_пр(φ)", "Reduced moment of inertia I_pr(φ)"),
    "W": ("Диаграмма энергомасс (Виттенбауэр)", "Energy–mass diagram (Wittenbauer)"),
    "w": ("Угловая скорость кривошипа ω(φ)", "Angular velocity of the crank ω(φ)"),
    "fly": ("Маховик", "Flywheel"),
    "sign": ("M_пр > 0: нагрузки движут кривошип", "M_pr > 0: the loads drive the crank"),
    "method": ("Метод", "Method"),
    "inertia": ("I_м, кг·м²", "I_fw, kg·m²"),
    "achieved": ("δ достигнутое", "δ achieved"),
    "diff": ("Δ к точному, %", "vs exact, %"),
    "graphical": ("Виттенбауэр", "Wittenbauer"),
    "merkalov": ("Мерцалов", "Merkalov"),
    "exact": ("точно", "exact"),
    "position": ("№ положения", "Position"),
    "phi": ("φ, °", "φ, deg"),
    "analogues": ("Аналоги скоростей", "Velocity analogues"),
    "Ipr": ("Приведённый момент инерции, кг·м²", "Reduced moment of inertia, kg·m²"),
    "Mpr": ("Приведённый момент сил, Н·м", "Reduced moment of forces, N·m"),
    "plans": ("Планы по положениям", "Plans over the positions"),
    "ordinates": ("Ординаты диаграмм по положениям:", "Ordinates of the diagrams over the positions:"),
    "energy": ("Работы и кинетическая энергия, Дж", "Work and kinetic energy, J"),
    "with_graphical": ("с маховиком по Виттенбауэру", "with the Wittenbauer flywheel"),
    "with_exact": ("с точным маховиком", "with the exact flywheel"),
    "indicator": ("Индикаторная диаграмма", "Indicator diagram"),
    "intake": ("впуск", "intake"),
    "compression": ("сжатие", "compression"),
    "expansion": ("расширение", "expansion"),
    "exhaust": ("выпуск", "exhaust"),
    "down": ("ход к валу", "toward the crank"),
    "up": ("ход от вала", "away from the crank"),
    "fires": ("воспламенение при φ", "ignition at φ"),
}


_UNITS = {"N*m": ("Н·м", "N·m"), "kg*m^2": ("кг·м²", "kg·m²"), "m": ("м", "m"), "mm": ("мм", "mm"),
          "J": ("Дж", "J"), "N": ("Н", "N"), "m/s": ("м/с", "m/s"), "m/s^2": ("м/с²", "m/s²"),
          "rad/s": ("рад/с", "rad/s"), "rad/s^2": ("рад/с²", "rad/s²"), "deg": ("°", "°")}


tr = lookup(WORDS)


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
            u = _UNITS.get(g.unit, (g.unit, g.unit))[0 if lang == "ru" else 1]
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


def _m_panel(d: Dynamics, lang: str, first: int = 1) -> Panel:
    s = d.scales
    t = d.table
    rec = Recording()
    ax = Axes(rec, "dyn-M", s.phi, float(t.phi_deg[0]), lang, first)
    rad = np.radians(t.phi_deg - t.phi_deg[0])
    xs_s, ys_s = spline.sample(rad, t.M_pr, spline.slopes(rad, t.M_pr), 8)
    ye = d.exact.M_pr * s.M
    L = math.radians(d.spec.cycle_deg) * s.phi  # the whole working cycle
    ax.frame(L, float(min(ye.min(), t.M_pr.min() * s.M)), float(max(ye.max(), t.M_pr.max() * s.M)), "M_пр" if lang == "ru" else "M_pr")
    ax.positions(t.phi_deg[:-1])
    ax.curve(ax.x(d.exact.phi_deg), ye, EXACT)
    ax.curve(xs_s * s.phi, ys_s * s.M, GRAPH, "dyn-M-graphical")
    ax.dots(ax.x(t.phi_deg), t.M_pr * s.M)
    # the mean ordinate of each interval, projected onto the axis, and the pole's rays to it
    means = spline.interval_integrals(rad, t.M_pr, spline.slopes(rad, t.M_pr)) / np.diff(rad)
    for k, m in enumerate(means):
        x0, x1 = rad[k] * s.phi, rad[k + 1] * s.phi
        rec.line((x0, -m * s.M), (x1, -m * s.M), HAIR)
    ax.pole(s.H, means * s.M)
    ax.hline(-d.M_driving * s.M, 0.0, L, Style(width=0.35, dash=(4, 1.5)), f"−M_д = {fmt(-d.M_driving, 4, lang)}"
             if lang == "ru" else f"−M_d = {fmt(-d.M_driving, 4, lang)}")
    scale = f"μ_M = {fmt(s.M, 4, lang)} mm/(N·m); μ_φ = {fmt(s.phi, 4, lang)} mm/rad; H = {fmt(s.H, 3, lang)} mm"
    return plot_panel("dyn-M", "dynamics", tr("M", lang), rec, scale, tr("sign", lang), lang=lang)


def _a_panel(d: Dynamics, lang: str, first: int = 1) -> Panel:
    s = d.scales
    t = d.table
    rec = Recording()
    ax = Axes(rec, "dyn-A", s.phi, float(t.phi_deg[0]), lang, first)
    L = math.radians(d.spec.cycle_deg) * s.phi  # the whole working cycle
    ya = np.concatenate([d.A_c, d.A_d]) * s.A
    ax.frame(L, float(ya.min()), float(ya.max()), "A")
    ax.positions(t.phi_deg[:-1])
    ex_A = d.A_c_exact * s.A
    ax.curve(ax.x(d.exact.phi_deg), ex_A, EXACT)
    rad = np.radians(t.phi_deg - t.phi_deg[0])
    xs, ys = spline.sample(rad, d.A_c, spline.slopes(rad, d.A_c), 8)
    ax.curve(xs * s.phi, ys * s.A, GRAPH, "dyn-A-c")
    ax.dots(ax.x(t.phi_deg), d.A_c * s.A)
    rec.line((0.0, 0.0), (L, -d.A_d[-1] * s.A), MAIN, "dyn-A-d")
    end_c = "A_c" if lang != "ru" else "A_с"
    rec.text(layout(end_c, L + 1.5, -d.A_c[-1] * s.A, 2.5, "start", "middle"), "note")
    rec.text(layout("A_д" if lang == "ru" else "A_d", L + 1.5, -d.A_d[-1] * s.A, 2.5, "start", "middle"), "note")
    scale = f"μ_A = μ_M·μ_φ/H = {fmt(s.A, 4, lang)} mm/J"
    return plot_panel("dyn-A", "dynamics", tr("A", lang), rec, scale, tr("exact_thin", lang), lang=lang)


def _t_panel(d: Dynamics, lang: str, first: int = 1) -> Panel:
    s = d.scales
    t = d.table
    rec = Recording()
    ax = Axes(rec, "dyn-T", s.phi, float(t.phi_deg[0]), lang, first)
    L = math.radians(d.spec.cycle_deg) * s.phi  # the whole working cycle
    ye = d.dT_exact * s.A
    ax.frame(L, float(min(ye.min(), d.dT.min() * s.A)), float(max(ye.max(), d.dT.max() * s.A)), "ΔT")
    ax.positions(t.phi_deg[:-1])
    ax.curve(ax.x(d.exact.phi_deg), ye, EXACT)
    rad = np.radians(t.phi_deg - t.phi_deg[0])
    xs, ys = spline.sample(rad, d.dT, spline.slopes(rad, d.dT), 8)
    ax.curve(xs * s.phi, ys * s.A, GRAPH, "dyn-T-graphical")
    ax.dots(ax.x(t.phi_deg), d.dT * s.A)
    scale = f"μ_T = μ_A = {fmt(s.A, 4, lang)} mm/J; ΔT = A_c + A_d" if lang != "ru" else \
        f"μ_T = μ_A = {fmt(s.A, 4, lang)} мм/Дж; ΔT = A_с + A_д"
    return plot_panel("dyn-T", "dynamics", tr("T", lang), rec, scale, lang=lang)


def _i_panel(d: Dynamics, lang: str, first: int = 1) -> Panel:
    s = d.scales
    t = d.table
    rec = Recording()
    ax = Axes(rec, "dyn-I", s.phi, float(t.phi_deg[0]), lang, first)
    L = math.radians(d.spec.cycle_deg) * s.phi  # the whole working cycle
    ye = d.exact.I_pr * s.I
    ax.frame(L, 0.0, float(ye.max()), "I_пр" if lang == "ru" else "I_pr")
    ax.positions(t.phi_deg[:-1])
    ax.curve(ax.x(d.exact.phi_deg), ye, EXACT)
    rad = np.radians(t.phi_deg - t.phi_deg[0])
    xs, ys = spline.sample(rad, t.I_pr, spline.slopes(rad, t.I_pr), 8)
    ax.curve(xs * s.phi, ys * s.I, GRAPH, "dyn-I-graphical")
    ax.dots(ax.x(t.phi_deg), t.I_pr * s.I)
    scale = f"μ_I = {fmt(s.I, 4, lang)} mm/(kg·m²)"
    return plot_panel("dyn-I", "dynamics", tr("I", lang), rec, scale, lang=lang)


W_WIDTH_MM = 150.0  # the energy–mass diagram's I_pr extent from I = 0
W_HEIGHT_MM = 110.0  # ... and its ΔT extent with k and l


def _w_panel(d: Dynamics, lang: str, first: int = 1, size: float = 1.0) -> Panel:
    """ΔT against I_pr from I = 0: the closed curve, the tangents at ψ_max, ψ_min, k and l; at
    its own round scales (the curve about W_WIDTH_MM × W_HEIGHT_MM, readable; ``size`` times
    that on a small sheet, its letters the same), every position numbered (coincident ones
    share a label: "1, 13")."""
    from drawings.paper.common import Placer, coincident_positions
    from plans.kinematics.scales import round_scale

    w = d.wittenbauer
    rec = Recording()
    placer = Placer()
    t = d.table
    span = float(max(np.max(w.dT), w.k, w.l, 0.0) - min(np.min(w.dT), w.k, w.l, 0.0))
    mu_T = round_scale(span, W_HEIGHT_MM * size) if span > 0 else d.scales.A
    top_I = float(np.max(w.I))
    mu_I = round_scale(top_I, W_WIDTH_MM * size) if top_I > 0 else d.scales.I
    X = w.I * mu_I
    Y = w.dT * mu_T
    x_hi = float(X.max()) + 8.0
    k_mm, l_mm = w.k * mu_T, w.l * mu_T
    lo = float(min(Y.min(), k_mm, l_mm))
    hi = float(max(Y.max(), k_mm, l_mm))
    ax = Axes(rec, "dyn-W", 1.0, 0.0, lang)
    ax.frame(x_hi, lo, hi, "ΔT", "I_пр" if lang == "ru" else "I_pr")
    curve = [(float(a), float(-b)) for a, b in zip(X, Y, strict=True)]
    rec.polyline(curve, GRAPH, "dyn-W-curve")
    placer.add_line(curve)
    placer.add_line([(0.0, 0.0), (x_hi + 8.0, 0.0)])
    for name, b, slope, touch in (("k", w.k, w.slope_max, w.touch_max), ("l", w.l, w.slope_min, w.touch_min)):
        tan = slope * mu_T / mu_I  # on paper
        x1 = float(X[touch]) + 6.0
        rec.line((0.0, -b * mu_T), (x1, -(b * mu_T + tan * x1)), THIN, f"dyn-W-tangent-{name}")
        placer.add_line([(0.0, -b * mu_T), (x1, -(b * mu_T + tan * x1))])
        rec.circle((0.0, -b * mu_T), 0.6, Style(stroke=None, width=0, fill="#000"))
        rec.text(layout(name, -1.5, -b * mu_T, 3.5, "end", "middle"), "point")
    pts = [(float(t.I_pr[k] * mu_I), float(-d.dT[k] * mu_T)) for k in range(len(t.phi_deg) - 1)]
    for p in pts:
        rec.circle(p, 0.6, Style(stroke=None, width=0, fill="#000"))
        placer.add_disc(p, 0.8)
    cx = sum(p[0] for p in pts) / max(len(pts), 1)
    cy = sum(p[1] for p in pts) / max(len(pts), 1)
    for ks in coincident_positions(pts):
        p = pts[ks[0]]
        away = (p[0] - cx, p[1] - cy)
        L = math.hypot(*away) or 1.0
        lab = placer.place(", ".join(str(k + first) for k in ks), p, 2.5, prefer=(away[0] / L, away[1] / L),
                           gap=0.8)
        rec.text(lab, "tick", f"dyn-W-n-{ks[0] + first}")
    kl = (w.k - w.l) * mu_T
    fw = d.flywheel
    scale = (f"μ_T = {fmt(mu_T, 4, lang)} mm/J; μ_I = {fmt(mu_I, 4, lang)} mm/(kg·m²); "
             f"tg ψ = (μ_T/μ_I)·ω_{{m}}²(1 ± δ)/2")
    note = (f"kl = {fmt(kl, 4, lang)} mm; I_fw = kl/(μ_T·ω_{{m}}²·δ) = {fmt(fw.inertia_graphical, 4, lang)} kg·m²; "
            f"ω_m = {fmt(fw.omega_mean, 4, lang)} rad/s, δ = {fmt(fw.delta, 4, lang)}")
    return plot_panel("dyn-W", "dynamics", tr("W", lang), rec, scale, note, lang=lang)


def _omega_panel(d: Dynamics, lang: str, first: int = 1) -> Panel:
    """ω(φ) by exact integration of the motion, magnified about ω_m."""
    s = d.scales
    fw = d.flywheel
    rec = Recording()
    ax = Axes(rec, "dyn-w", s.phi, float(d.exact.phi_deg[0]), lang, first)
    L = math.radians(d.spec.cycle_deg) * s.phi  # the whole working cycle
    span = max(float(np.ptp(d.omega)), float(np.ptp(d.omega_exact)), 1e-300)
    mu_w = 40.0 / span
    y_g = (d.omega - fw.omega_mean) * mu_w
    y_e = (d.omega_exact - fw.omega_mean) * mu_w
    ax.frame(L, float(min(y_g.min(), y_e.min())), float(max(y_g.max(), y_e.max())), "ω − ω_m")
    ax.positions(d.table.phi_deg[:-1])
    ax.curve(ax.x(d.exact.phi_deg), y_e, EXACT, "dyn-w-exact")
    ax.curve(ax.x(d.exact.phi_deg), y_g, GRAPH, "dyn-w-graphical")
    half = fw.delta * fw.omega_mean / 2 * mu_w
    for y, lab in ((half, "ω_max"), (-half, "ω_min")):
        ax.hline(y, 0.0, L, Style(width=0.2, dash=(3, 1.5)), lab)
    scale = f"μ_ω = {fmt(mu_w, 4, lang)} mm/(rad/s); ω_m = {fmt(fw.omega_mean, 5, lang)} rad/s"
    note = (f"{tr('with_graphical', lang)}: δ = {fmt(fw.delta_achieved, 4, lang)}; "
            f"{tr('with_exact', lang)} ({tr('exact_thin', lang).split(' — ')[0]}): δ = "
            f"{fmt(fw.delta_achieved_exact, 4, lang)}")
    return plot_panel("dyn-w", "dynamics", tr("w", lang), rec, scale, note, lang=lang)


#: Each diagram of the cycle's dynamics alone, by its letter: M, A, T, I, W and ω (``w``).
DYNAMICS_DIAGRAMS = {"M": _m_panel, "A": _a_panel, "T": _t_panel, "I": _i_panel, "W": _w_panel, "w": _omega_panel}


def _fly_table(d: Dynamics, lang: str) -> Panel:
    fw = d.flywheel
    ex = fw.inertia_exact

    def pct(i: float) -> str:
        return number(100 * (i - ex) / ex, lang, 3) if ex else "—"

    rows = [[tr("graphical", lang), number(fw.inertia_graphical, lang, 5), number(fw.delta_achieved, lang, 4),
             pct(fw.inertia_graphical)],
            [tr("merkalov", lang), number(fw.inertia_merkalov, lang, 5), number(fw.delta_achieved_merkalov, lang, 4),
             pct(fw.inertia_merkalov)],
            [tr("exact", lang), number(ex, lang, 5), number(fw.delta_achieved_exact, lang, 4), "0"]]
    head = [tr("method", lang), tr("inertia", lang), tr("achieved", lang), tr("diff", lang)]
    note = (f"M_д = {fmt(d.M_driving, 4, lang)} Н·м (точно {fmt(d.M_driving_exact, 4, lang)})" if lang == "ru" else
            f"M_d = {fmt(d.M_driving, 4, lang)} N·m (exact {fmt(d.M_driving_exact, 4, lang)})")
    return wide_table("dyn-flywheel", f"{tr('fly', lang)}: δ = {fmt(fw.delta, 4, lang)}", head, rows, lang, note)


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
                u = _UNITS.get(r.unit, (r.unit, r.unit))[0 if lang == "ru" else 1]
                unit = f", {u}" if u and u != "1" else ""
                label = re.sub(r"_pr\b", "_пр", r.label) if lang == "ru" else r.label  # I_пр, M_пр
                rows.append([f"{label}{unit}"] + [number(c, lang, 4) for c in cells])
            out.append(wide_table(f"{prefix}-table-{i + 1}-{j + 1}", title, head, rows, lang))
    return out


def indicator_panels(d: Dynamics, lang: str) -> list[Panel]:
    """Each cylinder's indicator diagram as given: the pressure against the piston's travel
    from the outer dead centre, one line per stroke (the working stroke drawn main), with its
    ignition where it fires (found when the scene's loads were read)."""
    out = []
    loads = d.scene.loads
    assert loads is not None, "a scene with dynamics holds its [loads]"
    for k, gl in enumerate(loads.gas):
        if not gl.diagram or gl.stroke <= 0:
            continue
        H_mm = gl.stroke * 1000
        p_top = max(float(np.max(np.abs(p))) for _, p in gl.diagram.values()) or 1.0
        mu_s = 100.0 / H_mm
        mu_p = nice_scale_mm(p_top, 60.0)
        rec = Recording()
        ax = Axes(rec, f"ind-{k}", 1.0, 0.0, lang)
        lows = [float(np.min(p)) for _, p in gl.diagram.values()]
        ax.frame(100.0, min(lows + [0.0]) * mu_p, p_top * mu_p, "p", "s")
        for side, (ts, ps) in gl.diagram.items():
            style = MAIN if side in ("expansion", "down") else (THIN if side in ("compression", "up") else
                                                                Style(width=0.25, dash=(3, 1.5)))
            pts = [(float(t * 1000 * mu_s), float(-p * mu_p)) for t, p in zip(ts, ps, strict=True)]
            rec.polyline(pts, style, f"ind-{k}-{side}")
            # each stroke named at its own place along the travel, the low ones below their line
            at = {"expansion": 0.3, "down": 0.3, "compression": 0.12, "up": 0.12, "exhaust": 0.55,
                  "intake": 0.8}[side]
            x = at * 100.0
            y = -float(np.interp(at * gl.stroke, ts, ps)) * mu_p
            below = side == "intake"
            rec.text(layout(tr(side, lang), x + 1.0, y + (1.5 if below else -1.0), 2.5, "start",
                            "top" if below else "bottom"), "note")
        scale = (f"μ_s = {fmt(mu_s, 4, lang)} mm/mm (H = {fmt(H_mm, 4, lang)} mm); "
                 f"μ_p = {fmt(mu_p * 1e6, 4, lang)} mm/MPa")
        note = None
        if gl.ignition is not None:
            note = f"{tr('fires', lang)} = {fmt(gl.ignition, 5, lang)}°"
        out.append(plot_panel(f"ind-{k}", "dynamics", f"{tr('indicator', lang)} {gl.name}", rec, scale, note,
                              lang=lang))
    return out


def nice_scale_mm(top: float, target_mm: float) -> float:
    """mm per unit drawing ``top`` at about ``target_mm``."""
    from plans.kinematics.construction import nice_scale

    return nice_scale(top, target_mm)


def analogue_plans(plans: Sequence, lang: str, style: str) -> list[Panel]:
    """The plans of velocity analogues at the table's positions (``Solution.analogue_plans``:
    velocity plans at μ_v = μ/|ω1|, each segment the analogue v/ω1 at μ, mm per m), drawn."""
    from drawings.plan_panel import plan_panel

    return [plan_panel(p, lang, style, pid=f"analogue-{k + 1}") for k, p in enumerate(plans)]


def dynamics_panels(d: Dynamics, tables: Sequence[CycleTable], lang: str, analogues: Sequence = (),
                    columns: int = 12, first: int = 1, w_size: float = 1.0) -> list[Panel]:
    """The dynamics sheet's panels; ``w_size``: the energy–mass diagram's size against its
    readable one (smaller on a small sheet)."""
    titles = [f"{tr('analogues', lang)}, μ = {fmt(d.scales.analogue, 4, lang)} mm/m (ω_1 = 1)",
              tr("Ipr", lang), f"{tr('Mpr', lang)}; {tr('sign', lang)}", tr("energy", lang)]
    plans = analogue_plans(analogues, lang, d.scene.scale_style)  # none where the first sheet has the plans
    return ([_m_panel(d, lang, first), _a_panel(d, lang, first), _t_panel(d, lang, first),
             _i_panel(d, lang, first), _w_panel(d, lang, first, w_size), _omega_panel(d, lang, first), _fly_table(d, lang)]
            + indicator_panels(d, lang) + table_panels(tables, lang, "dyn", titles, columns, first) + plans)


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
        extra += compose(fitting_diagrams(sol, cr.diagrams, spec), sub, scale_text, scene.path)
    if cr is not None and cr.dynamics is not None:
        sub = dataclasses.replace(spec, subtitle=tr("dynamics", lang), pins=())
        tabs = cr.tables[-4:]  # the dynamics' own: analogues, I_pr, M_pr, work and energy
        analogues = () if scene.wants("velocity_plan") else sol.analogue_plans()  # else on the first sheet
        panels = _fitting_dynamics(sol, cr.dynamics, tabs, sub, analogues)
        if lay is None:
            extra += compose(panels, sub, scale_text, scene.path)
        else:  # a last sheet left nearly empty: the diagrams on a shorter φ axis, if all then fit fewer
            laid = lay(panels, sub)
            axis = 240.0
            while len(laid) > 1 and min(map(_used, laid)) < 1 / 3 and axis > 160.0:
                axis -= 20.0
                fewer = lay(_fitting_dynamics(sol, sol.dynamics_drawn(axis, 1.0), tabs, sub, analogues, axis), sub)
                if len(fewer) < len(laid):
                    laid = fewer
                    break
            extra += laid
    out = list(sheets) + extra
    for i, sh in enumerate(out):
        sh.number, sh.count = i + 1, len(out)
        sh.prims = []
        sh.render()
    return out


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


def _fitting_dynamics(sol: Solution, d: Dynamics, tabs: Sequence[CycleTable], spec: SheetSpec,
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
