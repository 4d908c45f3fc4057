"""Panels: one figure of the sheet each (scheme, plans, table, forces, lever).

A panel is drawn once, onto a :class:`Recording` in its own paper millimetres,
then normalised so its box (labels included) starts at (0, 0).  Layout only
moves panels; the recorded primitives are replayed onto the SVG backend.
"""

from __future__ import annotations

from collections.abc import Sequence

from drawings.linkage.scheme import (  # noqa: F401
    BLOCK_H,
    BLOCK_L,
    JOINT_R,
    SchemeGeometry,
    cross,
    cycle_size,
    fixed_pivot,
    glob_of,
    link_outline,
    link_shape,
    scheme_panel,
    strokes_over_cycle,
)
from drawings.paper.backend import FILLED, HAIR, Prim, Recording
from drawings.paper.common import angle, fmt, ident, phi_tag
from drawings.paper.i18n import tr

# the panel's frame and the scheme, importable from here as before
from drawings.paper.panel_frame import (  # noqa: F401
    LABEL_SIZE,
    PAD,
    SCALE_SIZE,
    SMALL_SIZE,
    STANDARD_RATIOS,
    TITLE_SIZE,
    Panel,
    auto_length_scale,
    finish,
    ratio_text,
    ruled_grid,
    scale_text,
)
from drawings.paper.text import layout, point_label
from drawings.plan_panel import (  # noqa: F401  (the plans' panel, importable from here as before)
    VECTOR_STYLES,
    clip_line,
    line_label,
    on_paper,
    plan_panel,
)
from plans.units import DUST

# --------------------------------------------------------------------------- results table

_QUANTITY_NAMES = {"omega": "ω", "eps": "ε"}
_UNITS = {"m/s": "m/s", "m/s^2": "m/s^2", "rad/s": "rad/s", "rad/s^2": "rad/s^2", "N": "N", "N*m": "N*m",
          "N·m": "N*m"}


def quantity_text(q: str) -> str:
    head, _, rest = q.partition("_")
    if head in _QUANTITY_NAMES and rest:
        return f"{_QUANTITY_NAMES[head]}_{rest}"
    return q


def table_panel(rows: Sequence, lang: str, scale_style: str, phi: float, pid: str | None = None,
                extra: Sequence[tuple[str, ...]] = (), title_key: str = "table",
                part: tuple[int, int, int] | None = None) -> Panel:
    """Per position: quantity, segment, mm, scale, value read, exact, unit, difference %.

    ``rows`` are readings (``plans.construction.Reading``-like); ``extra`` are ready rows of
    eight cells (the balancing force three ways).  ``part`` = (start, stop, n): only those
    rows, as the table's part n (:func:`drawings.linkage.table_parts.parts`).
    """
    from plans.scene.notation import pole_label, resolve

    pid = pid or f"table-{phi_tag(phi)}"
    if part is not None and part[2] > 1:
        pid = f"{pid}-{part[2]}"
    header: tuple[str, ...] = (tr("quantity", lang), tr("segment", lang), tr("mm", lang), tr("scale", lang),
              tr("read", lang), tr("exact", lang), tr("unit", lang), tr("diff", lang))
    body: list[tuple[str, tuple[str, ...]]] = []
    for r in rows:
        seg = " ".join(point_label(pole_label(t, scale_style, lang)) for t in r.segment.split()) if r.segment \
            else "—"
        mm = "—"
        if r.length_mm is not None:
            mm = fmt(_clean(r.length_mm, r.ref * (r.scale or 1.0)), 4, lang)
        if r.scale is None:
            sc = "—"
        elif resolve(scale_style, lang)[1]:  # units per mm
            sc = fmt(1.0 / r.scale, 4, lang)
        else:
            sc = fmt(r.scale, 4, lang)
        unit = tr(_UNITS.get(r.unit, r.unit), lang) if _UNITS.get(r.unit, r.unit) in _UNIT_KEYS else r.unit
        cells: tuple[str, ...] = (quantity_text(r.quantity), seg, mm, sc, fmt(_clean(r.value, r.ref), 5, lang),
                 fmt(_clean(r.exact, r.ref), 5, lang), unit, _diff_cell(r, unit, lang))
        body.append((ident(r.quantity), cells))
    for cells in extra:
        body.append((ident(cells[0]), tuple(cells)))
    if part is not None:
        body = body[part[0]:part[1]]
    size = SMALL_SIZE + 0.3
    from drawings.paper.fonts import metrics

    mtr = metrics()
    widths = [0.0] * len(header)
    for cells in [header] + [c for _, c in body]:
        for i, t in enumerate(cells):
            lab = layout(t, 0, 0, size)
            widths[i] = max(widths[i], lab.box[2] - lab.box[0] + 3.0)
    del mtr
    rh = size * 1.75
    rec = Recording()
    x_edges = [0.0]
    for w in widths:
        x_edges.append(x_edges[-1] + w)
    ruled_grid(rec, pid, x_edges, len(body) + 1, rh)
    rec.begin(f"{pid}-cells", "cells")
    for i, t in enumerate(header):
        lab = layout(t, (x_edges[i] + x_edges[i + 1]) / 2, rh / 2, size, "middle", "middle")
        rec.text(lab, "th", f"{pid}-h{i}")
    used: dict[str, int] = {}
    for j, (rid, cells) in enumerate(body, start=1):
        used[rid] = used.get(rid, 0) + 1
        rid2 = rid if used[rid] == 1 else f"{rid}-{used[rid]}"
        rec.begin(f"{pid}-row-{rid2}", "row")
        for i, t in enumerate(cells):
            yc = j * rh + rh / 2
            if i == 0 or i == 1 or i == 6:
                lab = layout(t, x_edges[i] + 1.5, yc, size, "start", "middle")
            else:
                lab = layout(t, x_edges[i + 1] - 1.5, yc, size, "end", "middle")
            rec.text(lab, "td")
        rec.end()
    rec.end()
    title = f"{tr(title_key, lang)}, φ = {angle(phi, lang)}°"
    if part is not None and part[2] > 1:
        title += " " + tr("continued", lang)
    return finish(pid, "table", phi, rec, title)


_UNIT_KEYS = {"m/s", "m/s^2", "rad/s", "rad/s^2", "N", "N*m"}


def _diff_cell(r, unit: str, lang: str) -> str:
    """Δ as ``solve`` and the check report define it (:func:`plans.units.percent`), %; the
    absolute difference with its unit where the exact value is zero."""
    from plans.units import clean, percent

    pct = percent(r.value, r.exact, r.ref)
    if pct is None:
        return f"{fmt(clean(r.value - r.exact, r.ref), 3, lang)} {unit}"
    return f"{pct:+.2f}".replace(".", "," if lang == "ru" else ".").replace("+0,00", "0,00").replace(
        "+0.00", "0.00").replace("-0,00", "0,00").replace("-0.00", "0.00")


def _clean(v: float, ref: float) -> float:
    """Round-off noise of a vanishing quantity shown as 0."""
    return 0.0 if abs(v) <= DUST * max(abs(ref), 1e-300) else v


def single(prims: Sequence[Prim]) -> None:  # pragma: no cover - debugging aid
    for p in prims:
        print(p.op, p.eid, p.pts[:2])


__all__ = ["Panel", "scheme_panel", "plan_panel", "table_panel", "finish", "scale_text",
           "auto_length_scale", "strokes_over_cycle", "cycle_size", "VECTOR_STYLES", "HAIR", "FILLED"]
