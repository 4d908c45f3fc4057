"""The V engine's banks on the balancing sheet: each bank's polygon of its own cylinders on
its own phase diagram (cranks measured from the bank's axis), its closing vector (the
bank's resultant along its axis), and the banks combined: the path of the resultant's tip
over a turn (a circle, a line or an ellipse) with its largest vector.
"""

from __future__ import annotations

import cmath
import math

import numpy as np

from drawings.balancing.balancing_paper import engine_paper, polygon_scale
from drawings.linkage.panels import SMALL_SIZE, VECTOR_STYLES, Panel, finish
from drawings.paper.backend import CENTRE_LINE, HAIR, Recording, Style
from drawings.paper.common import Placer, arrow, degrees360, dot, fmt
from drawings.paper.i18n import lookup
from drawings.paper.text import layout
from plans.balancing.analysis import Balance
from plans.balancing.banks import Bank, BankPolygon, Locus

_W: dict[str, tuple[str, str]] = {
    "force": ("Силы инерции ПДМ {k} порядка по рядам", "Reciprocating forces, order {k}, bank by bank"),
    "moment": ("Повёрнутые моменты ПДМ {k} порядка по рядам", "Turned moments, order {k}, bank by bank"),
    "bank": ("ряд {n}: ось {g}°", "bank {n}: axis {g}°"),
    "sum": ("сумма рядов", "banks combined"),
    "zero": ("уравновешено", "balanced"),
    "circle": ("окружность", "circle"),
    "line": ("отрезок", "line"),
    "ellipse": ("эллипс", "ellipse"),
    "with": ("вращается с кривошипом", "turns with the crank"),
    "against": ("вращается против кривошипа", "turns against the crank"),
    "N": ("Н", "N"),
    "N*m": ("Н·м", "N·m"),
}
BANK_AXIS = Style(width=0.25, stroke="#6a3d9a", dash=(4, 1.5))
LOCUS = Style(width=0.35, stroke="#1f4e9c")
LOCUS_MM = 32.0  # the largest combined vector on the sheet, mm
ROMAN = {1: "I", 2: "II"}


_word = lookup(_W)


def _w(key: str, lang: str, **kw: object) -> str:
    return _word(key, lang).format(**kw)


def bank_panels(b: Balance, lang: str, size: float = 1.0) -> list[Panel]:
    """One panel per quantity and order, for an engine with more than one bank; the moment
    panels only where some cylinder has an arm; ``size`` times the A1 sizes."""
    if len(b.banks.banks) < 2:
        return []
    out = []
    for quantity in ("force", "moment"):
        for kind in ("first_order", "second_order"):
            polys = [(bk, (bk.forces if quantity == "force" else bk.moments)[kind]) for bk in b.banks.banks]
            if all(p.scale_ref == 0.0 for _, p in polys):
                continue
            loci = b.banks.forces if quantity == "force" else b.banks.moments
            out.append(_panel(quantity, kind, polys, loci[kind], b.banks.banks, lang, size))
    return out


def _path(p: BankPolygon) -> list[complex]:
    pts = [0j]
    for _, a, pi, li in p.rows:
        pts.append(pts[-1] + pi * li * cmath.exp(1j * a))
    return pts


def _panel(quantity: str, kind: str, polys: list[tuple[Bank, BankPolygon]], L: Locus,
           banks: tuple[Bank, ...], lang: str, size: float = 1.0) -> Panel:
    k = 1 if kind == "first_order" else 2
    pid = f"banks-{quantity}-{kind}"
    rec = Recording()
    placer = Placer()
    paths = [_path(p) for _, p in polys]
    extent = max(max(abs(a - c) for a in pts for c in pts) for pts in paths)
    s = polygon_scale(extent, size / 2.0)  # the bank polygons at about half the polygon panels' size, round too
    sym = ("r" if quantity == "force" else "m") + f"_{ROMAN[k]}"
    unit = _w("N*m" if quantity == "moment" else "N", lang)
    x_off = 0.0
    for (bank, poly), pts in zip(polys, paths, strict=True):
        tag = f"{pid}-{bank.number}"
        xs = [engine_paper(z, s)[0] for z in pts]
        o = (x_off - min(xs), 0.0)
        # the bank's axis: the phase diagram's reference (up), cranks measured from it
        top = min([engine_paper(z, s, o)[1] for z in pts] + [o[1] - 10.0])
        rec.line((o[0], o[1] + 6.0), (o[0], top - 6.0), BANK_AXIS, f"{tag}-axis")
        placer.add_line([(o[0], o[1] + 6.0), (o[0], top - 6.0)])
        dot(rec, o, 0.6, f"{tag}-pole")
        for (cyl, _, _, _), a, c in zip(poly.rows, pts[:-1], pts[1:], strict=True):
            pa, pc = engine_paper(a, s, o), engine_paper(c, s, o)
            if abs(c - a) * s < 0.05:
                continue
            arrow(rec, pa, pc, VECTOR_STYLES["force"], f"{tag}-v{cyl}", "vector force")
            placer.add_line([pa, pc])
        for (cyl, _, _, _), a, c in zip(poly.rows, pts[:-1], pts[1:], strict=True):
            pa, pc = engine_paper(a, s, o), engine_paper(c, s, o)
            if abs(c - a) * s < 0.05:
                continue
            d = math.dist(pa, pc)
            lab = placer.place(str(cyl), ((pa[0] + pc[0]) / 2, (pa[1] + pc[1]) / 2), SMALL_SIZE + 0.5,
                               prefer=(-(pc[1] - pa[1]) / d, (pc[0] - pa[0]) / d), gap=0.8)
            rec.text(lab, "label", f"{tag}-v{cyl}-label")
        end = engine_paper(pts[-1], s, o)
        if poly.closed:
            text = f"{sym}^{{({bank.number})}} = 0"
        else:
            arrow(rec, o, end, VECTOR_STYLES["closing"], f"{tag}-closing", "vector closing")
            placer.add_line([o, end])
            text = f"{sym}^{{({bank.number})}} = {fmt(abs(poly.closing), 4, lang)}, {fmt(degrees360(poly.phase), 4, lang)}°"
        d = max(math.dist(o, end), 1e-9)
        # the side opposite the cylinder numbers (a one-cylinder bank's closing vector is its vector)
        away = ((end[1] - o[1]) / d, -(end[0] - o[0]) / d)
        lab = placer.place(text, ((o[0] + end[0]) / 2, (o[1] + end[1]) / 2), SMALL_SIZE + 0.5, prefer=away,
                           gap=1.5)
        rec.text(lab, "closing-label", f"{tag}-closing-label", fill=VECTOR_STYLES["closing"].stroke or "#000")
        names = ", ".join(c.name for c in bank.cylinders)
        bottom = max([engine_paper(z, s, o)[1] for z in pts] + [o[1] + 6.0]) + 3.0  # below the axis line too
        head = layout(f"{_w('bank', lang, n=bank.number, g=fmt(degrees360(bank.axis), 4, lang))} ({names})",
                      o[0], bottom, SMALL_SIZE, "start", "top")
        rec.text(head, "note", f"{tag}-name")
        amp = layout(f"{sym.upper()}^{{({bank.number})}} = {fmt(poly.amplitude, 5, lang)} {unit}", o[0],
                     head.box[3] + 1.0, SMALL_SIZE, "start", "top")
        rec.text(amp, "note", f"{tag}-amplitude")
        x_off = rec.bbox()[2] + 12.0
    _locus(rec, pid, L, banks, x_off + LOCUS_MM * size, unit, sym, lang, LOCUS_MM * size)
    title = _w(quantity, lang, k=ROMAN[k])
    scale = f"μ = {fmt(s, 4, lang)} {'мм/ед.' if lang == 'ru' else 'mm/unit'}; " \
            f"{'ед.' if lang == 'ru' else 'unit'} = {fmt(polys[0][1].unit, 5, lang)} {unit}"
    return finish(pid, "polygon", None, rec, title, scale)


def _locus(rec: Recording, pid: str, L: Locus, banks: tuple[Bank, ...], xc: float, unit: str, sym: str,
           lang: str, R: float = LOCUS_MM) -> None:
    """The banks' axes through one centre and the path of the combined vector's tip, its
    largest vector ``R`` mm long."""
    o = (xc, 0.0)
    for bank in banks:
        a, c = engine_paper(bank.direction, R + 6.0, o), engine_paper(-bank.direction, R + 6.0, o)
        rec.line(c, a, BANK_AXIS, f"{pid}-sum-axis-{bank.number}")
        rec.text(layout(str(bank.number), a[0], a[1] - 0.8, SMALL_SIZE, "middle", "bottom"), "label",
                 f"{pid}-sum-axis-{bank.number}-label", fill=BANK_AXIS.stroke or "#000")
    rec.line((o[0], o[1] + R + 6.0), (o[0], o[1] - R - 6.0), CENTRE_LINE, f"{pid}-sum-vertical")
    text = f"{sym.upper()}: {_w(L.shape, lang)}"
    if L.shape != "zero":
        s = R / L.maximum
        alpha = np.linspace(0.0, 2 * np.pi / L.order, 181)
        pts = [engine_paper(complex(z), s, o) for z in L.at(alpha)]
        if L.shape == "circle":
            rec.circle(o, L.maximum * s, LOCUS, f"{pid}-sum-locus")
        else:
            rec.polyline(pts, LOCUS, f"{pid}-sum-locus")
        tip = engine_paper(cmath.exp(1j * L.direction) * L.maximum, s, o)
        arrow(rec, o, tip, VECTOR_STYLES["closing"], f"{pid}-sum-max", "vector closing")
        text += (f", max = {fmt(L.maximum, 5, lang)} {unit} ({fmt(degrees360(L.direction), 4, lang)}°), "
                 f"min = {fmt(L.minimum, 5, lang)} {unit}")
        if L.sense in ("with", "against"):
            text += f"; {_w(L.sense, lang)}"
    else:
        rec.circle(o, 0.8, HAIR, f"{pid}-sum-zero")
    rec.text(layout(_w("sum", lang), o[0] - R - 6.0, o[1] - R - 8.0, SMALL_SIZE + 0.5, "start", "bottom"),
             "note", f"{pid}-sum-name")
    rec.text(layout(text, o[0] - R - 6.0, o[1] + R + 8.0, SMALL_SIZE, "start", "top"), "note",
             f"{pid}-sum-values")
