"""The specific sliding of a drawn pair: λ1 and λ2 along the line of action, laid off under
the meshing at its enlargement (the diagram's abscissa is N1N2 as drawn), the active part
B1B2 marked and the greatest values at its ends, where the course reads them."""

from __future__ import annotations

import math

import numpy as np

from drawings.linkage.panels import Panel, finish
from drawings.paper.backend import HAIR, MAIN, THIN, Recording, Style
from drawings.paper.common import dot, fmt
from drawings.paper.i18n import lookup
from drawings.paper.text import layout
from plans.gears.meshing import Meshing
from plans.kinematics.scales import round_scale

SMALL = 2.5
LABEL = 3.5
FLOOR = -2.0  # λ is drawn down to this (it runs to −∞ at N1 and at N2)
WORDS = {"sliding": ("Диаграммы удельных скольжений", "Specific sliding")}
_w = lookup(WORDS)


def sliding(rho1: np.ndarray, g: float, u: float, internal: bool) -> tuple[np.ndarray, np.ndarray]:
    """λ1 and λ2 where the contact is ρ1 from N1 along the line of action (N1N2 = g, u = z2/z1):
    λ1 = 1 − ρ2/(u ρ1), λ2 = 1 − u ρ1/ρ2, with ρ2 = g − ρ1 (ρ1 + g for a ring)."""
    rho2 = rho1 + g if internal else g - rho1
    with np.errstate(divide="ignore", invalid="ignore"):
        return 1.0 - rho2 / (u * rho1), 1.0 - u * rho1 / rho2


def sliding_panel(mg: Meshing, lang: str, height: float = 40.0) -> Panel:
    """λ1, λ2 against the contact's place on N1N2 at the meshing's enlargement (mm from N1),
    λ at a round scale with 1 about ``height`` mm above the axis; B1, P, B2 marked."""
    p = mg.pair
    k = mg.k * 1e3  # paper mm per m
    w1, w2 = p.wheels
    u = w2.z / w1.z
    g = p.g
    end = p.rho_end * 1.15 if p.internal else g
    rho = np.linspace(end * 1e-3, end * (1 - 1e-3) if not p.internal else end, 600)
    l1, l2 = sliding(rho, g, u, p.internal)
    mu = round_scale(1.0, height)  # mm per unit of λ
    rec = Recording()
    x = rho * k
    L = end * k
    rec.line((0.0, 0.0), (L + 6.0, 0.0), THIN, "axis")
    rec.text(layout("N_1", 0.0, 2.0, LABEL, "middle", "top"), "label", "label-N1")
    if not p.internal:
        rec.text(layout("N_2", L, 2.0, LABEL, "middle", "top"), "label", "label-N2")
    rec.line((0.0, -mu * 1.1), (0.0, -mu * FLOOR), THIN, "lambda-axis")
    rec.text(layout("λ", -1.5, -mu * 1.1, LABEL, "end", "top"), "label", "label-lambda")
    rec.line((-2.0, -mu), (L, -mu), Style(width=0.13, stroke="#888", dash=(1.0, 1.0)), "one")
    rec.text(layout("1", -2.5, -mu, SMALL, "end", "middle"), "label", "label-one")
    for name, lam, style in (("1", l1, MAIN), ("2", l2, Style(width=0.5, dash=(4.0, 1.5)))):
        ok = np.isfinite(lam) & (lam >= FLOOR)
        runs = np.split(np.arange(len(lam)), np.flatnonzero(np.diff(ok.astype(int))) + 1)
        for i, run in enumerate(r for r in runs if ok[r[0]]):
            rec.polyline([(float(x[j]), float(-mu * lam[j])) for j in run], style, f"lambda{name}-{i}")
        j = int(np.nanargmax(np.where(ok, lam, -np.inf)))  # its top, near N2 (λ1) or N1 (λ2)
        right = x[j] > L / 2
        rec.text(layout(f"λ_{name}", float(x[j]) + (-1.5 if right else 4.0), float(-mu * lam[j]) - 1.5, LABEL,
                        "end" if right else "start", "bottom"), "label", f"label-lambda{name}")
    # the active part B1B2 and P, with the greatest |λ| at its ends
    marks = (("B_1", p.rho_start), ("P", p.rho_p), ("B_2", p.rho_end))
    for name, r in marks:
        xr = r * k
        rec.line((xr, -mu * 1.1), (xr, -mu * FLOOR), HAIR, f"at-{name.replace('_', '')}")
        dot(rec, (xr, 0.0), 0.5)
        rec.text(layout(name, xr + 1.0, -mu * FLOOR + 1.5, LABEL, "start", "top"), "label",
                 f"label-at-{name.replace('_', '')}")
    rec.line((p.rho_start * k, 0.0), (p.rho_end * k, 0.0), Style(width=1.2), "active")
    s1, s2 = p.sliding
    mm = "мм" if lang == "ru" else "mm"
    note = (f"μ_λ = {fmt(mu, 3, lang)} {mm}; |λ_{{1}}|max = {fmt(s1, 4, lang)} (B_{{1}}), "
            f"|λ_{{2}}|max = {fmt(s2, 4, lang)} (B_{{2}})") if math.isfinite(s1) and math.isfinite(s2) else \
        f"μ_λ = {fmt(mu, 3, lang)} {mm}"
    g1, g2 = p.gears
    return finish(f"sliding-{g1}-{g2}", "sliding", None, rec, f"{_w('sliding', lang)} {g1}–{g2}", note)
