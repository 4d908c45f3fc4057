"""Diagrams over the crank angle and wide tables: the figures of the cycle's sheets.

A diagram is drawn in its own paper millimetres: the origin of the axes at (0, 0), the
ordinate up (paper y = −y).  Curves come in SI with their scale μ (mm per unit); the
abscissa is the crank angle at μ_φ (mm per rad) from the first position.
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from dataclasses import dataclass

import numpy as np

from drawings.paper.backend import FILLED, HAIR, MAIN, PAPER, THIN, Recording, Style
from drawings.paper.common import arrow, fmt
from drawings.paper.panel_frame import SMALL_SIZE, Panel, finish, ruled_grid
from drawings.paper.text import column_edges, layout

EXACT = Style(width=0.2, stroke="#777", dash=(1.5, 0.8), cls="exact")
GRAPH = Style(width=0.5, cls="graphical")
AXIS = Style(width=0.35, cls="axis")
TICK = 2.5  # mm, size of the position numbers


@dataclass
class Axes:
    """A diagram under construction: x = μ_φ·(φ − φ0) mm, y = μ·value mm (up)."""

    rec: Recording
    pid: str
    mu_phi: float
    phi0_deg: float
    lang: str
    first: int = 1  # the first position's number ([sheet] first_position)

    def x(self, phi_deg: float | np.ndarray) -> np.ndarray:
        return self.mu_phi * np.radians(np.asarray(phi_deg, float) - self.phi0_deg)

    def pts(self, xs: np.ndarray, ys: np.ndarray) -> list[tuple[float, float]]:
        return [(float(a), float(-b)) for a, b in zip(xs, ys, strict=True)]

    def frame(self, length: float, y_lo: float, y_hi: float, y_name: str, x_name: str = "φ") -> None:
        """The two axes with arrows; names at their ends."""
        y_lo, y_hi = min(y_lo, 0.0) - 4.0, max(y_hi, 0.0) + 6.0
        arrow(self.rec, (0.0, 0.0), (length + 8.0, 0.0), AXIS, f"{self.pid}-xaxis", "axis")
        arrow(self.rec, PAPER(0.0, y_lo), PAPER(0.0, y_hi), AXIS, f"{self.pid}-yaxis", "axis")
        self.rec.text(layout(x_name, length + 9.5, 0.0, 3.5, "start", "middle"), "axis-name")
        self.rec.text(layout(y_name, *PAPER(1.5, y_hi), 3.5, "start", "top"), "axis-name")

    def positions(self, phis_deg: Sequence[float] | np.ndarray, numbers: bool = True) -> None:
        """Ticks at the positions, numbered from ``first`` as the plans number them (1..N by
        default, as the course's tables do; a number that would touch the previous one is left out)."""
        last = -1e9
        for k, phi in enumerate(phis_deg):
            x = float(self.x(phi))
            self.rec.line((x, -1.2), (x, 1.2), THIN)
            if numbers and x - last >= 4.5:
                self.rec.text(layout(str(k + self.first), x, 2.0, TICK, "middle", "top"), "tick")
                last = x

    def curve(self, xs: np.ndarray, ys: np.ndarray, style: Style, eid: str = "") -> None:
        """A curve through its points, a dense one (the exact grid's thousands) kept at two
        points per mm of the axis: no line on paper needs more."""
        xs, ys = np.asarray(xs, float), np.asarray(ys, float)
        step = int(len(xs) // max(2.0 * float(np.ptp(xs)), 1.0)) if len(xs) > 2 else 1
        if step > 1:
            keep = np.unique(np.append(np.arange(0, len(xs), step), len(xs) - 1))
            xs, ys = xs[keep], ys[keep]
        self.rec.polyline(self.pts(xs, ys), style, eid)

    def dots(self, xs: np.ndarray, ys: np.ndarray) -> None:
        for a, b in zip(xs, ys, strict=True):
            self.rec.circle((float(a), float(-b)), 0.5, FILLED)

    def hline(self, y: float, x0: float, x1: float, style: Style, label: str = "", eid: str = "") -> None:
        self.rec.line(PAPER(x0, y), PAPER(x1, y), style, eid)
        if label:
            self.rec.text(layout(label, *PAPER(x1 + 1.5, y), 2.5, "start", "middle"), "note")

    def pole(self, H: float, ordinates: Sequence[float] | np.ndarray, name: str = "P", hname: str = "H") -> None:
        """The pole at H mm left of the origin and its rays to the ordinates on the y axis."""
        self.rec.begin(f"{self.pid}-pole", "pole")
        for y in ordinates:
            self.rec.line((-H, 0.0), (0.0, -float(y)), HAIR)
        self.rec.circle((-H, 0.0), 0.7, FILLED)
        self.rec.text(layout(name, -H, 1.8, 3.0, "middle", "top"), "pole-name")
        self.rec.line((-H, 6.5), (0.0, 6.5), THIN)
        for xx in (-H, 0.0):
            self.rec.line((xx, 5.5), (xx, 7.5), THIN)
        self.rec.text(layout(f"{hname} = {fmt(H, 3, self.lang)}", -H / 2, 7.3, 2.5, "middle", "top"), "note")
        self.rec.end()


def phi_axis(mu_phi: float, cycle_deg: float) -> tuple[float, float | None]:
    """The φ axis of a diagram at ``mu_phi`` (mm per rad) over ``cycle_deg``: its length in mm
    and the scale in mm per degree where that is a round one (1 mm/°, 0.5 mm/°: the unit the
    course writes), else None; the length then the round scale times the cycle exactly."""
    from plans.kinematics.scales import round_scale
    from plans.tolerances import ROUND_OFF_REL

    per_deg = mu_phi * math.pi / 180.0
    r = round_scale(1.0, per_deg) if per_deg > 0 else 0.0  # the round μ nearest below
    if r > 0 and abs(r - per_deg) <= ROUND_OFF_REL * per_deg:
        return r * cycle_deg, r
    return math.radians(cycle_deg) * mu_phi, None


def phi_scale(mu_phi: float, cycle_deg: float, lang: str) -> str:
    """μ_φ as the scale line writes it: in mm/° where that is round, else in mm/rad."""
    per_deg = phi_axis(mu_phi, cycle_deg)[1]
    if per_deg is not None:
        return f"μ_φ = {fmt(per_deg, 4, lang)} mm/°"
    return f"μ_φ = {fmt(mu_phi, 4, lang)} mm/rad"


#: Units and symbols of the scale lines in Russian (longest first).
_RU = (("mm/mm", "мм/мм"), ("mm/MPa", "мм/МПа"), ("mm/(m/s^2)", "мм/(м/с²)"), ("mm/(rad/s^2)", "мм/(рад/с²)"), ("mm/(m/s)", "мм/(м/с)"),
       ("mm/(rad/s)", "мм/(рад/с)"), ("mm/(N·m)", "мм/(Н·м)"), ("mm/(kg·m²)", "мм/(кг·м²)"), ("mm/rad", "мм/рад"), ("mm/°", "мм/°"),
       ("mm/J", "мм/Дж"), ("mm/m", "мм/м"), ("kg·m²", "кг·м²"), ("rad/s", "рад/с"), ("N·m", "Н·м"),
       (" mm", " мм"), ("I_fw", "I_м"), ("A_d", "A_д"), ("A_c", "A_с"), ("M_d", "M_д"), ("(exact", "(точно"))


def loc(text: str | None, lang: str) -> str | None:
    """A scale line or note in the sheet's language (numbers are already written for it)."""
    if text is None or lang != "ru":
        return text
    for en, ru in _RU:
        text = text.replace(en, ru)
    return text


def plot_panel(pid: str, kind: str, title: str, rec: Recording, scale_line: str, note: str | None = None,
               lang: str = "en") -> Panel:
    return finish(pid, kind, None, rec, title, loc(scale_line, lang), loc(note, lang))


def wide_table(pid: str, title: str, header: Sequence[str], rows: Sequence[Sequence[str]], lang: str,
               note: str | None = None) -> Panel:
    """A table with the quantities as rows and the positions as columns (seed 004's layout)."""
    size = SMALL_SIZE + 0.3
    edges = column_edges([list(header)] + [list(r) for r in rows], size)
    rh = size * 1.75
    n = len(rows) + 1
    rec = Recording()
    ruled_grid(rec, pid, edges, n, rh, thick_column=1)  # the quantities' names ruled off
    rec.begin(f"{pid}-cells", "cells")
    for j, cells in enumerate([list(header)] + [list(r) for r in rows]):
        yc = j * rh + rh / 2
        for i, t in enumerate(cells):
            if i == 0:
                rec.text(layout(t, edges[0] + 1.5, yc, size, "start", "middle"), "th" if j == 0 else "td")
            else:
                rec.text(layout(t, edges[i + 1] - 1.5, yc, size, "end", "middle"), "th" if j == 0 else "td")
    rec.end()
    return finish(pid, "cycle-table", None, rec, loc(title, lang) or title, None, loc(note, lang))


def number(v: float | None, lang: str, sig: int = 4) -> str:
    if v is None or not math.isfinite(v):
        return "—"
    return fmt(v, sig, lang) if abs(v) < 1e5 else f"{v:.3e}".replace(".", "," if lang == "ru" else ".")


__all__ = ["Axes", "phi_axis", "phi_scale", "EXACT", "GRAPH", "MAIN", "plot_panel", "wide_table", "number"]
