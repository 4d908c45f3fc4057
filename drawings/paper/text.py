"""Labels with subscripts and superscripts, laid out into positioned runs.

Notation (the one plan objects use): ``v_BA``, ``a_BA^n``, ``a^k_A3A2``, ``p_v``,
``F_12``, ``μ_v``; a script runs over letters and digits, or over ``{...}``.
A subscript and a superscript after the same base are stacked, as the textbook
writes a^n_BA.  Layout is done here, once, with measured widths: every run gets
its own x, y, so no renderer has to understand baseline shifts.
"""

from __future__ import annotations

import re
from collections.abc import Sequence
from dataclasses import dataclass
from functools import lru_cache

from drawings.paper.fonts import FAMILIES, FONT_FAMILY, current, metrics, pieces

SCRIPT_SIZE = 0.7
#: GOST 2.304: letters at least 2.5 mm (:data:`drawings.paper.panel_frame.SMALL_SIZE`); an index is written
#: a size smaller, never below the standard's smallest size, 1.8 mm.
SCRIPT_MIN = 1.8
SUB_SHIFT = 0.28  # of the base size, downwards on paper
SUP_SHIFT = -0.42


@dataclass(frozen=True, slots=True)
class TextRun:
    x: float  # paper mm, left end of the run's baseline
    y: float  # baseline
    text: str
    size: float  # font size, mm
    font: str = ""  # the run's family where it is not the sheet's default (DejaVu Sans): "osifont"


@dataclass(frozen=True, slots=True)
class Label:
    runs: tuple[TextRun, ...]
    box: tuple[float, float, float, float]  # x0, y0, x1, y1 (paper mm, y down)
    plain: str  # the text without markup, for search and tests


#: Characters DejaVu Sans lacks, drawn with the nearest glyph it has.
GLYPH_FALLBACK = str.maketrans({"⟂": "⊥"})

_POINT = re.compile(r"^([A-Za-z]+)(\d+)$")


def point_label(name: str) -> str:
    """``S2`` -> ``S_2``, ``a3`` -> ``a_3``; names with markup pass through."""
    m = _POINT.match(name)
    return f"{m.group(1)}_{m.group(2)}" if m else name


def parse(label: str) -> list[tuple[str, str]]:
    """Split markup into (text, role) pieces, role in base/sub/sup."""
    label = label.translate(GLYPH_FALLBACK)
    out: list[tuple[str, str]] = []
    i, n = 0, len(label)
    base: list[str] = []
    while i < n:
        ch = label[i]
        if ch in "_^" and i + 1 < n:
            if base:
                out.append(("".join(base), "base"))
                base = []
            role = "sub" if ch == "_" else "sup"
            if label[i + 1] == "{":
                j = label.find("}", i + 2)
                j = n if j < 0 else j
                out.append((label[i + 2:j], role))
                i = j + 1
            else:
                j = i + 1
                while j < n and (label[j].isalnum()):
                    j += 1
                out.append((label[i + 1:j], role))
                i = j
            continue
        base.append(ch)
        i += 1
    if base:
        out.append(("".join(base), "base"))
    return [p for p in out if p[0]]


def plain(label: str) -> str:
    return "".join(t for t, _ in parse(label))


def layout(label: str, x: float, y: float, size: float, anchor: str = "start",
           valign: str = "baseline") -> Label:
    """Runs of ``label`` with the anchor point at (x, y).

    anchor: start | middle | end; valign: baseline | middle (of the capitals) | top | bottom.
    """
    lab = _layout0(label, size, anchor, valign, current())
    if x == 0.0 and y == 0.0:
        return lab
    return Label(tuple(TextRun(r.x + x, r.y + y, r.text, r.size, r.font) for r in lab.runs),
                 (lab.box[0] + x, lab.box[1] + y, lab.box[2] + x, lab.box[3] + y), lab.plain)


@lru_cache(maxsize=4096)
def _layout0(label: str, size: float, anchor: str, valign: str, font: str = "dejavu") -> Label:
    """The layout at the origin in ``font`` (cached: labels repeat across panels and positions).
    Each piece is written in runs of one family each (:func:`drawings.paper.fonts.pieces`),
    each measured in its own family."""
    x = y = 0.0
    m = metrics(FAMILIES[font])
    parts = parse(label)
    runs: list[tuple[float, float, str, float, str]] = []  # dx, dy, text, size, family

    def put(x0: float, dy: float, text: str, s: float) -> float:
        """The piece's runs from ``x0``; the x where it ends."""
        for t, fam in pieces(text, font):
            runs.append((x0, dy, t, s, fam))
            x0 += metrics(fam or FONT_FAMILY).width(t, s)
        return x0

    cx = 0.0
    script_x = None  # x where the current script cluster began
    script_end = 0.0
    top, bottom = -m.ascent * size, m.descent * size
    for text, role in parts:
        if role == "base":
            if script_x is not None:
                cx = script_end
                script_x = None
            cx = put(cx, 0.0, text, size)
            continue
        s = max(size * SCRIPT_SIZE, min(SCRIPT_MIN, size))
        if script_x is None:
            script_x = cx
            script_end = cx
        dy = SUB_SHIFT * size if role == "sub" else SUP_SHIFT * size
        script_end = max(script_end, put(script_x, dy, text, s))
        top = min(top, dy - m.ascent * s)
        bottom = max(bottom, dy + m.descent * s)
    if script_x is not None:
        cx = script_end
    width = cx
    ox = {"start": 0.0, "middle": -width / 2, "end": -width}[anchor]
    cap = m.cap * size
    oy = {"baseline": 0.0, "middle": cap / 2, "top": -top, "bottom": -bottom}[valign]
    bx, by = x + ox, y + oy
    out = tuple(TextRun(bx + dx, by + dy, t, s, f) for dx, dy, t, s, f in runs)
    return Label(out, (bx, by + top, bx + width, by + bottom), "".join(p[0] for p in parts))


def wrap(text: str, width: float, size: float) -> list[str]:
    """Words of ``text`` in greedy lines no wider than ``width`` mm, measured as drawn."""
    lines: list[str] = []
    cur = ""
    for w in text.split():
        trial = f"{cur} {w}".strip()
        lab = layout(trial, 0, 0, size)
        if cur and lab.box[2] - lab.box[0] > width:
            lines.append(cur)
            cur = w
        else:
            cur = trial
    if cur:
        lines.append(cur)
    return lines


def column_edges(rows: Sequence[Sequence[str]], size: float, pad: float = 3.0) -> list[float]:
    """The x of a ruled table's column edges, 0 first: each column as wide as its widest cell
    written at ``size``, plus ``pad`` mm of margin."""
    widths = [0.0] * (len(rows[0]) if rows else 0)  # the header's columns
    for cells in rows:
        for i, t in enumerate(cells):
            box = layout(t, 0, 0, size).box
            widths[i] = max(widths[i], box[2] - box[0] + pad)
    edges = [0.0]
    for w in widths:
        edges.append(edges[-1] + w)
    return edges
