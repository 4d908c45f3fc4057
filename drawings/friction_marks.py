"""Friction on a free body: each pin's friction circle with the reaction's line tangent to
it, each slide's total reaction leaning from the normal by the friction angle, and the
efficiency rows of the results table."""

from __future__ import annotations

import math
from typing import Any

from .backend import Recording, Style, Transform
from .common import Placer, fmt

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
            lab = placer.place(label(rc) + "Σ", tip, 2.2, gap=0.8)
            rec.text(lab, "label", eid + "-label", fill=TOTAL.stroke or "#000")


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
    rows = [
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
