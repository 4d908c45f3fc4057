"""The benchmark's plot: error against run time per position, log-log (``bench.svg``).

Drawn with the sheets' backend (:class:`drawings.paper.svg.SvgBackend`, paper millimetres, fixed
number formatting), so the same records give the same bytes.  ``plans bench`` writes it
when the renderer is installed: :func:`add_plot` hands the command the plot to write.
"""

from __future__ import annotations

import argparse
import math
from collections.abc import Mapping, Sequence
from typing import Any

from drawings.paper.backend import Style
from drawings.paper.svg import SvgBackend
from drawings.paper.text import layout
from plans.accuracy.oracles import Record

#: Method -> colour of its points.
COLOURS = {"exact": "#1f77b4", "construction": "#d62728", "newton": "#2ca02c",
           "newton tol sweep": "#98df8a", "finite differences": "#ff7f0e", "pylinkage": "#9467bd",
           "mechanism": "#8c564b"}
# paper (mm): width, height, margins left, right, top, bottom
_W, _H, _ML, _MR, _MT, _MB = 180.0, 115.0, 20.0, 46.0, 8.0, 14.0
_FONT = 2.8
_GRID = Style(stroke="#ddd", width=0.2)
_FRAME = Style(width=0.3)
_HAND = Style(stroke="#555", width=0.3, dash=(1.5, 1.0))


def _decades(lo: float, hi: float) -> tuple[int, int]:
    a, b = math.floor(math.log10(lo)), math.ceil(math.log10(hi))
    return a, max(b, a + 1)


def svg_plot(records: Sequence[Record], draftsman: Mapping[str, float] | None = None) -> str:
    """Log-log error against run time per position (one point per record) with the hand
    drawing's p95 errors as dashed levels; SVG text, deterministic."""
    pts = sorted((r.time_per_position, max(r.error, 1e-17), r.method) for r in records
                 if r.method in COLOURS and math.isfinite(r.time_per_position) and r.time_per_position > 0
                 and math.isfinite(r.error) and not r.scene.startswith("chain") and r.note != "is the oracle")
    hand = sorted((draftsman or {}).items(), key=lambda kv: kv[1])
    ys = [p[1] for p in pts] + [v for _, v in hand]
    x0, x1 = _decades(min((p[0] for p in pts), default=1e-7), max((p[0] for p in pts), default=1e-2))
    y0, y1 = _decades(min(ys, default=1e-16), max(ys, default=1.0))
    left, right, top, bottom = _ML, _W - _MR, _MT, _H - _MB

    def X(v: float) -> float:
        return left + (math.log10(v) - x0) / (x1 - x0) * (right - left)

    def Y(v: float) -> float:
        return top + (y1 - math.log10(v)) / (y1 - y0) * (bottom - top)

    b = SvgBackend(_W, _H, title="error against run time per position")
    b.begin("grid")
    for e in range(x0, x1 + 1):
        x = X(10.0**e)
        b.line((x, top), (x, bottom), _GRID)
        b.text(layout(f"10^{{{e}}}", x, bottom + 4.5, _FONT, anchor="middle"))
    for e in range(y0, y1 + 1, max(1, (y1 - y0) // 10)):
        y = Y(10.0**e)
        b.line((left, y), (right, y), _GRID)
        b.text(layout(f"10^{{{e}}}", left - 1.5, y + 1.0, _FONT, anchor="end"))
    b.polygon([(left, top), (right, top), (right, bottom), (left, bottom)], _FRAME)
    b.text(layout("run time per position (s)", (left + right) / 2, _H - 2.5, _FONT, anchor="middle"))
    b.text(layout("error (relative to the known vector)", left, top - 2.5, _FONT))
    b.end()
    b.begin("points")
    for tp, err, m in pts:
        b.circle((X(tp), Y(err)), 0.9, Style(stroke=None, width=0.0, fill=COLOURS[m]))
    b.end()
    b.begin("hand-drawing")
    for k, (label, val) in enumerate(hand):
        y = Y(val)
        b.line((left, y), (right, y), _HAND)
        dy = 3.5 if k == 0 else -1.0  # the lowest line's label below it, the others above
        b.text(layout(label, left + 1.5, y + dy, _FONT * 0.9), fill="#555")
    b.end()
    b.begin("legend")
    for k, m in enumerate(sorted({p[2] for p in pts})):
        y = top + 3.5 + 4.5 * k
        b.circle((right + 4.0, y), 1.0, Style(stroke=None, width=0.0, fill=COLOURS[m]))
        b.text(layout(m, right + 6.5, y + 1.0, _FONT))
    b.end()
    return b.tostring() + "\n"


def plot(result: Mapping[str, Any]) -> str:
    """``bench.svg`` of a benchmark result (the JSON-ready dictionary of ``run_bench``)."""
    return svg_plot([Record.from_json(r) for r in result["records"]], result.get("draftsman_lines"))


def add_plot(parser: argparse.ArgumentParser) -> None:
    """Give ``plans bench`` the plot to write beside bench.md and bench.json."""
    parser.set_defaults(plots={"bench.svg": plot})
