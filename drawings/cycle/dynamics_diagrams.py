"""The machine-dynamics diagrams of a course's dynamics sheet: M_пр(φ), A(φ), ΔT(φ), I_пр(φ),
the energy–mass (Wittenbauer) diagram, ω(φ), the flywheel's table and the indicator diagrams,
each a panel at round scales (``size`` times the A1 extents where a sheet has room)."""

from __future__ import annotations

import math

import numpy as np

from drawings.cycle.cycle_plot import (
    EXACT,
    GRAPH,
    Axes,
    number,
    phi_axis,
    phi_scale,
    plot_panel,
    wide_table,
)
from drawings.cycle.words import tr
from drawings.paper.backend import HAIR, MAIN, THIN, Recording, Style
from drawings.paper.common import fmt
from drawings.paper.panel_frame import Panel
from drawings.paper.text import layout
from plans.cycle import spline
from plans.cycle.dynamics import Dynamics


def m_panel(d: Dynamics, lang: str, first: int = 1) -> Panel:
    s = d.scales
    t = d.table
    rec = Recording()
    ax = Axes(rec, "dyn-M", s.phi, float(t.phi_deg[0]), lang, first)
    rad = np.radians(t.phi_deg - t.phi_deg[0])
    xs_s, ys_s = spline.sample(rad, t.M_pr, spline.slopes(rad, t.M_pr), 8)
    ye = d.exact.M_pr * s.M
    L = phi_axis(s.phi, d.spec.cycle_deg)[0]  # the whole working cycle, at μ_φ as written
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
    scale = f"μ_M = {fmt(s.M, 4, lang)} mm/(N·m); {phi_scale(s.phi, d.spec.cycle_deg, lang)}; H = {fmt(s.H, 3, lang)} mm"
    return plot_panel("dyn-M", "dynamics", tr("M", lang), rec, scale, tr("sign", lang), lang=lang)


def a_panel(d: Dynamics, lang: str, first: int = 1) -> Panel:
    s = d.scales
    t = d.table
    rec = Recording()
    ax = Axes(rec, "dyn-A", s.phi, float(t.phi_deg[0]), lang, first)
    L = phi_axis(s.phi, d.spec.cycle_deg)[0]  # the whole working cycle, at μ_φ as written
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
    # μ_φ written in mm/° enters the formula times 180/π (mm/rad)
    per_deg = phi_axis(s.phi, d.spec.cycle_deg)[1] is not None
    scale = f"μ_A = {'(180/π)·' if per_deg else ''}μ_M·μ_φ/H = {fmt(s.A, 4, lang)} mm/J"
    return plot_panel("dyn-A", "dynamics", tr("A", lang), rec, scale, tr("exact_thin", lang), lang=lang)


def t_panel(d: Dynamics, lang: str, first: int = 1) -> Panel:
    s = d.scales
    t = d.table
    rec = Recording()
    ax = Axes(rec, "dyn-T", s.phi, float(t.phi_deg[0]), lang, first)
    L = phi_axis(s.phi, d.spec.cycle_deg)[0]  # the whole working cycle, at μ_φ as written
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


def i_panel(d: Dynamics, lang: str, first: int = 1) -> Panel:
    s = d.scales
    t = d.table
    rec = Recording()
    ax = Axes(rec, "dyn-I", s.phi, float(t.phi_deg[0]), lang, first)
    L = phi_axis(s.phi, d.spec.cycle_deg)[0]  # the whole working cycle, at μ_φ as written
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


def w_panel(d: Dynamics, lang: str, first: int = 1, size: float = 1.0) -> Panel:
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


def omega_panel(d: Dynamics, lang: str, first: int = 1, size: float = 1.0) -> Panel:
    """ω(φ) by exact integration of the motion, magnified about ω_m at a round μ_ω (its swing
    about 40 mm, ``size`` times that where the sheet has room)."""
    from plans.kinematics.scales import round_scale

    s = d.scales
    fw = d.flywheel
    rec = Recording()
    ax = Axes(rec, "dyn-w", s.phi, float(d.exact.phi_deg[0]), lang, first)
    L = phi_axis(s.phi, d.spec.cycle_deg)[0]  # the whole working cycle, at μ_φ as written
    span = max(float(np.ptp(d.omega)), float(np.ptp(d.omega_exact)), 1e-300)
    mu_w = round_scale(span, 40.0 * size)
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


DYNAMICS_DIAGRAMS = {"M": m_panel, "A": a_panel, "T": t_panel, "I": i_panel, "W": w_panel, "w": omega_panel}


def fly_table(d: Dynamics, lang: str) -> Panel:
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


def indicator_panels(d: Dynamics, lang: str, size: float = 1.0) -> list[Panel]:
    """Each cylinder's indicator diagram as given: the pressure against the piston's travel
    from the outer dead centre, one line per stroke (the working stroke drawn main), with its
    ignition where it fires (found when the scene's loads were read); at round scales, the
    stroke about 100 mm long and the pressure 60 mm high (``size`` times that where the sheet
    has room)."""
    from plans.kinematics.scales import round_scale

    out = []
    loads = d.scene.loads
    assert loads is not None, "a scene with dynamics holds its [loads]"
    for k, gl in enumerate(loads.gas):
        if not gl.diagram or gl.stroke <= 0:
            continue
        H_mm = gl.stroke * 1000
        p_top = max(float(np.max(np.abs(p))) for _, p in gl.diagram.values()) or 1.0
        mu_s = round_scale(H_mm, 100.0 * size)
        width = H_mm * mu_s
        mu_p = nice_scale_mm(p_top, 60.0 * size)
        rec = Recording()
        ax = Axes(rec, f"ind-{k}", 1.0, 0.0, lang)
        lows = [float(np.min(p)) for _, p in gl.diagram.values()]
        ax.frame(width, min(lows + [0.0]) * mu_p, p_top * mu_p, "p", "s")
        for side, (ts, ps) in gl.diagram.items():
            style = MAIN if side in ("expansion", "down") else (THIN if side in ("compression", "up") else
                                                                Style(width=0.25, dash=(3, 1.5)))
            pts = [(float(t * 1000 * mu_s), float(-p * mu_p)) for t, p in zip(ts, ps, strict=True)]
            rec.polyline(pts, style, f"ind-{k}-{side}")
            # each stroke named at its own place along the travel, the low ones below their line
            at = {"expansion": 0.3, "down": 0.3, "compression": 0.12, "up": 0.12, "exhaust": 0.55,
                  "intake": 0.8}[side]
            x = at * width
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
