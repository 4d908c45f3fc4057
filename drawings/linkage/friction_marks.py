"""Friction on a free body: each pin's friction circle with the reaction's line tangent to
it, each slide's total reaction leaning from the normal by the friction angle, and the
efficiency rows of the results table."""

from __future__ import annotations

import math
from typing import Any

from drawings.paper.backend import Recording, Style, Transform
from drawings.paper.common import Placer, fmt
from plans.kinematics.scales import round_down

CIRCLE = Style(width=0.25, stroke="#6a3d9a", dash=(1.2, 0.8), cls="friction-circle")
TANGENT = Style(width=0.3, stroke="#6a3d9a", dash=(5.0, 1.0, 1.0, 1.0), cls="friction-line")
TOTAL = Style(width=0.45, stroke="#6a3d9a", cls="friction-total")
#: A friction circle is a fraction of a millimetre at drawing scale: drawn at least this big (mm).
SHOWN_RADIUS = 2.5
TANGENT_MM = 14.0


def friction_marks(rec: Recording, placer: Placer, T: Transform, fr: Any, reactions: Any, k: int,
                   mu_l: float, mu_f: float, pid: str, label: Any) -> None:
    """Draw the friction of the pairs among ``reactions`` (Reaction objects) at position k."""
    if fr is None:
        return
    by_joint = {p.friction.joint.name: p for p in fr.pairs}
    for rc in reactions:
        p = by_joint.get(rc.joint.name)
        if p is None:
            continue
        F = complex(rc.F[k])
        c = T.z(complex(rc.r[k]))
        eid = f"{pid}-friction-{p.label}"
        if rc.guide is None:
            rho_mm = max(p.friction.rho * mu_l, SHOWN_RADIUS)
            rec.circle(c, rho_mm, CIRCLE, eid + "-circle")
            s = float(p.sense[k])
            if F == 0 or s == 0:  # no line: a zero reaction, or the sense undetermined (either side)
                continue
            u = F / abs(F)
            # the couple on ``on`` is −s·ρ|F|: the line of F shifted so its moment about the pin is that
            d = -1j * u * (-s)  # unit offset on the sheet's model axes
            mid = (c[0] + rho_mm * d.real, c[1] - rho_mm * d.imag)
            a = (mid[0] - TANGENT_MM * u.real, mid[1] + TANGENT_MM * u.imag)
            b = (mid[0] + TANGENT_MM * u.real, mid[1] - TANGENT_MM * u.imag)
            rec.line(a, b, TANGENT, eid + "-line")
            placer.add_line([a, b])
        else:
            s = float(p.sense[k])
            total = F - s * float(p.load[k]) * complex(rc.guide[k])  # N plus the friction on ``on``
            if total == 0:
                continue
            d = total * mu_f
            tip = (c[0] + d.real, c[1] - d.imag)
            rec.line(c, tip, TOTAL, eid + "-total")
            placer.add_line([c, tip])
            lab = placer.place(label(rc) + "Σ", tip, 2.5, gap=0.8)  # GOST 2.304: 2.5 mm at least
            rec.text(lab, "label", eid + "-label", fill=TOTAL.stroke or "#000")


def friction_points(fr: Any) -> dict[str, str]:
    """The pin of each friction couple by its label (both links' labels)."""
    if fr is None:
        return {}
    out = {}
    for p in fr.pairs:
        if p.reaction.guide is None:
            for lab in p.labels(fr.frictionless.scene):
                out[lab] = p.friction.joint.point
    return out


def efficiency_rows(fa: Any, k: int, lang: str) -> list[tuple[str, ...]]:
    """η, the balancing load without and with friction, and the approximations, as table rows."""
    fr = fa.friction
    if fr is None:
        return []
    ru = lang == "ru"
    force = fa.crank.kind == "force"
    unit = ("Н" if force else "Н·м") if ru else ("N" if force else "N·m")
    letter = "F" if force else "M"
    name = f"{letter}_ур" if ru else f"{letter}_bal"
    eta = float(fr.efficiency[k])
    dash = "—"
    rows: list[tuple[str, ...]] = [
        (f"{name} ({'без трения' if ru else 'no friction'})", dash, dash, dash, dash,
         fmt(float(fr.frictionless.balancing[k]), 5, lang), unit, dash),
        (f"{name} ({'с трением' if ru else 'with friction'})", dash, dash, dash, dash,
         fmt(float(fa.balancing[k]), 5, lang) if fr.converged[k] else dash, unit, dash),
        ("η", dash, dash, dash, dash, dash if math.isnan(eta) else fmt(eta, 4, lang), dash, dash),
        ("приближений" if ru else "approximations", dash, dash, dash, dash, str(int(fr.iterations[k])),
         dash, dash),
    ]
    for p in fr.undetermined(k):
        what = "направление не определено" if ru else "sense undetermined"
        rows.append((f"{p.label}: {what}", dash, dash, dash, dash, "≤ " + fmt(float(p.limit[k]), 4, lang),
                     ("Н·м" if ru else "N·m") if p.reaction.guide is None else unit.split("·")[0], dash))
    for name_ in fr.self_locking(k):
        rows.append((("самоторможение: " if ru else "self-locking: ") + name_, dash, dash, dash, dash, dash,
                     dash, dash))
    return rows


def efficiency_panels(eff: dict[str, Any] | None, fa: Any, lang: str, size: float = 1.0) -> list[Any]:
    """The diagram η(φ) over the turn with the cycle's η (``eff``: the solution's
    ``efficiency``), and the table of the positions: F_bal without and with friction, the
    power lost and η.  ``size``: the diagram's length and height as a fraction of A1's (the
    paper's fit)."""
    from drawings.cycle.cycle_plot import GRAPH, Axes, number, plot_panel, wide_table

    fr = fa.friction
    if eff is None or fr is None or fa.n < 2:
        return []
    import numpy as np

    ru = lang == "ru"
    phis = np.asarray(eff["phi_deg"], float)
    eta = np.asarray(fr.efficiency, float)
    rec = Recording()
    mu_phi = 180.0 * size / (2 * math.pi)  # the turn 180 mm long on A1
    finite = eta[np.isfinite(eta)]
    big = float(np.max(np.abs(finite))) if finite.size else 1.0
    # mm per unit of η: round (1, 2, 2.5, 4, 5 × 10^k) as every scale of the sheet, the curve within 60 mm
    mu_eta = round_down(min(50.0, 60.0 / max(big, 1e-9)) * size)
    ax = Axes(rec, "friction-eta", mu_phi, float(phis[0]), lang)
    lo = float(min(finite.min(), 0.0)) * mu_eta if finite.size else 0.0
    hi = float(max(finite.max(), 1.0)) * mu_eta if finite.size else mu_eta
    L = 2 * math.pi * mu_phi
    ax.frame(L, lo, hi, "η")
    ax.positions(phis)
    # the curve through the positions (and on to the turn's end: η repeats), broken where undefined
    phis = np.append(phis, phis[0] + 360.0)
    eta = np.append(eta, eta[0])
    xs = ax.x(phis)
    run: list[int] = []
    for k in list(range(len(phis))) + [-1]:
        if k >= 0 and np.isfinite(eta[k]):
            run.append(k)
            continue
        if len(run) > 1:
            ax.curve(xs[run], eta[run] * mu_eta, GRAPH, f"friction-eta-curve-{run[0]}")
        run = []
    ok = np.isfinite(eta)
    ax.dots(xs[ok], eta[ok] * mu_eta)
    ax.hline(mu_eta, 0.0, L, Style(width=0.18, stroke="#777", dash=(1.5, 0.8)), "η = 1")
    if eff.get("cycle") is not None:
        c = float(eff["cycle"])
        ax.hline(c * mu_eta, 0.0, L, Style(width=0.35, dash=(4, 1.5)),
                 ("η_ц = " if ru else "η_cycle = ") + fmt(c, 3, lang))
    scale = f"μ_η = {fmt(mu_eta, 3, lang)} mm; μ_φ = {fmt(mu_phi, 4, lang)} mm/rad"
    title = "КПД по положениям η(φ)" if ru else "Efficiency over the turn η(φ)"
    note = ("η = F_ур,0/F_ур (кривошип ведущий), F_ур/F_ур,0 (ведомый)" if ru
            else "η = F_bal,0/F_bal (driving crank), F_bal/F_bal,0 (driven)")
    panels = [plot_panel("friction-eta", "dynamics", title, rec, scale, note, lang=lang)]
    force = fa.crank.kind == "force"
    unit = ("Н" if force else "Н·м") if ru else ("N" if force else "N·m")
    sym = ("F_ур" if ru else "F_bal") if force else ("M_ур" if ru else "M_bal")
    header = ["", *(str(k + 1) for k in range(len(phis) - 1))]
    rows = [
        ["φ, °", *(number(float(p), lang, 4) for p in phis[:-1])],
        [f"{sym},0, {unit}", *(number(float(b), lang) for b in fr.frictionless.balancing)],
        [f"{sym}, {unit}", *(number(float(b), lang) if fr.converged[k] else "—" for k, b in enumerate(fa.balancing))],
        [("ΣP_тр, Вт" if ru else "ΣP_f, W"), *(number(float(x), lang) for x in fr.losses)],
        ["η", *(number(float(x), lang, 3) if np.isfinite(x) else "—" for x in eta[:-1])],
    ]
    cyc = eff.get("cycle")
    note2 = None if cyc is None else (
        f"{'η цикла' if ru else 'cycle η'} = A_{'пс' if ru else 'useful'}/A_{'дв' if ru else 'driving'} = "
        f"{fmt(eff['A_useful'], 4, lang)}/{fmt(eff['A_driving'], 4, lang)} = {fmt(cyc, 3, lang)}")
    panels.append(wide_table("friction-table", "КПД и потери на трение" if ru else "Efficiency and friction losses",
                             header, rows, lang, note2))
    return panels
