"""The engine's unbalanced inertia forces and moments over a turn of the crank: each order's
resultant (the closing vectors of the polygons turning k times as fast as the crank) as
diagrams over the crank angle α, stacked in one α column at one round μ_α, each at its own
round scale written beside it, and their sum (the shaking force or moment of the harmonic
series) with the exact one of the kinetostatics drawn thin and dashed beside it.

A resultant's part in the vertical plane (the real part of the engine plane: the vertical
force, the moment of the vertical forces) is drawn solid, its part in the horizontal plane
dashed; an inline engine's reciprocating forces have none.
"""

from __future__ import annotations

import math

import numpy as np

from drawings.balancing.balancing_paper import TURN_DEG_PER_MM, diagram_scale
from drawings.cycle.cycle_plot import EXACT, Axes
from drawings.linkage.panels import SMALL_SIZE, Panel, finish
from drawings.paper.backend import THIN, Recording, Style
from drawings.paper.common import fmt
from drawings.paper.i18n import lookup
from drawings.paper.text import layout
from plans.balancing.analysis import KINDS, Balance, Resultant
from plans.balancing.exact import ExactCheck
from plans.tolerances import CLOSED_REL

_W: dict[str, tuple[str, str]] = {
    "force": ("Неуравновешенные силы инерции за оборот кривошипа",
              "Unbalanced inertia forces over a turn of the crank"),
    "moment": ("Неуравновешенные моменты сил инерции за оборот кривошипа",
               "Unbalanced moments of the inertia forces over a turn of the crank"),
    "planes": ("сплошная — в вертикальной плоскости, штриховая — в горизонтальной",
               "solid: in the vertical plane, dashed: in the horizontal plane"),
    "rotating": ("вращающиеся массы", "rotating masses"),
    "first_order": ("ПДМ I порядка", "reciprocating, first order"),
    "second_order": ("ПДМ II порядка", "reciprocating, second order"),
    "sum": ("сумма порядков", "the orders summed"),
    "exact": ("тонкая штриховая — точно (кинетостатика)", "thin dashed: exact (kinetostatics)"),
    "N": ("Н", "N"),
    "N*m": ("Н·м", "N·m"),
    "per_mm": ("мм", "mm"),
}
_SUB = {"rotating": "r", "first_order": "I", "second_order": "II", "sum": "Σ"}
VERTICAL = Style(width=0.5, cls="turn-vertical")
HORIZONTAL = Style(width=0.4, dash=(3.0, 1.5), cls="turn-horizontal")
ROW_MM = 22.0  # a diagram's largest ordinate at the A1 size, mm
SAMPLES = 721  # α every half degree over the turn

_t = lookup(_W)


def turn_panels(b: Balance, chk: ExactCheck | None, lang: str, size: float = 1.0,
                deg_per_mm: float = TURN_DEG_PER_MM) -> list[Panel]:
    """One panel per quantity (force, moment) with an unbalanced order left: its diagrams over
    a turn, ``size`` times the A1 heights, at μ_α = ``deg_per_mm`` (a round one); the sum's
    row where more than one order is left or ``chk`` has the exact one (then drawn beside it,
    even where every order closes)."""
    out = []
    alpha = np.linspace(0.0, 2 * math.pi, SAMPLES)
    for quantity, res in (("force", b.forces), ("moment", b.moments)):
        rows = [(kind, _values(res[kind], alpha)) for kind in KINDS if res[kind].amplitude > 0]
        exact = None
        if chk is not None and (chk.max_exact if quantity == "force" else chk.max_moment) > 0:
            exact = (chk.alpha, chk.exact if quantity == "force" else chk.moment_exact)
        if not rows and exact is None:
            continue  # balanced, and by the exact check too
        if len(rows) != 1 or exact is not None:  # where every order closes: the series' truncation alone
            rows.append(("sum", sum((v for _, v in rows), np.zeros(SAMPLES, complex))))
        out.append(_panel(quantity, rows, alpha, exact, lang, size, deg_per_mm))
    return out


def _values(R: Resultant, alpha: np.ndarray) -> np.ndarray:
    """The resultant over the turn in N (N·m): real part in the vertical plane, imaginary in
    the horizontal."""
    return np.asarray(R.at(alpha), dtype=complex)


def _panel(quantity: str, rows: list[tuple[str, np.ndarray]], alpha: np.ndarray,
           exact: tuple[np.ndarray, np.ndarray] | None, lang: str, size: float, deg_per_mm: float) -> Panel:
    pid = f"turn-{quantity}"
    letter = "R" if quantity == "force" else "M"
    unit = _t("N*m" if quantity == "moment" else "N", lang)
    rec = Recording()
    mu_phi = 180.0 / math.pi / deg_per_mm  # mm per rad
    length = 360.0 / deg_per_mm
    y = 0.0
    dashed = False
    for kind, v in rows:
        big = float(np.max(np.abs(v)))
        if kind == "sum" and exact is not None:
            big = max(big, float(np.max(np.abs(exact[1]))))
        k = diagram_scale(big, ROW_MM * size)  # units per mm
        parts = [(np.real(v), VERTICAL, "vertical")]
        if float(np.max(np.abs(np.imag(v)))) > CLOSED_REL * big:
            parts.append((np.imag(v), HORIZONTAL, "horizontal"))
            dashed = True
        h = big / k
        y += h + 12.0  # the row's scale line above its y axis
        sub = Recording()
        name = f"{letter}_{{{_SUB[kind]}}}"
        ax = Axes(sub, f"{pid}-{kind}", mu_phi, 0.0, lang)
        ax.frame(length, -h, h, name, "α")
        for deg in range(0, 361, 30):
            x = float(ax.x(deg))
            sub.line((x, -1.2), (x, 1.2), THIN)
            if deg % 90 == 0 and deg:
                sub.text(layout(f"{deg}°", x, 2.0, SMALL_SIZE, "middle", "top"), "tick")
        for vals, style, side in parts:
            ax.curve(ax.x(np.degrees(alpha)), vals / k, style, f"{pid}-{kind}-{side}")
        if kind == "sum" and exact is not None:  # the exact one over the same turn, closed at 360°
            xs = np.append(ax.x(np.degrees(exact[0])), length)
            for side, vals in (("vertical", np.real(exact[1])), ("horizontal", np.imag(exact[1]))):
                if side == "vertical" or len(parts) > 1:
                    ax.curve(xs, np.append(vals, vals[0]) / k, EXACT, f"{pid}-exact-{side}")
        head = f"{name} ({_t(kind, lang)}): μ_{letter} = {fmt(k, 4, lang)} {unit}/{_t('per_mm', lang)}"
        sub.text(layout(head, 6.0, -h - 7.0, SMALL_SIZE + 0.5, "start", "bottom"), "scale",
                 f"{pid}-{kind}-scale")
        rec.prims.extend(sub.moved(0.0, y).prims)
        y += h + 6.0
    scale = f"μ_α = {fmt(deg_per_mm, 3, lang)}°/{_t('per_mm', lang)}"
    notes = ([_t("planes", lang)] if dashed else []) + ([_t("exact", lang)] if exact is not None else [])
    return finish(pid, "diagram", None, rec, _t(quantity, lang), scale, "; ".join(notes) or None)
