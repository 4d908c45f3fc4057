"""The largest of several drawings of a set of figures that one sheet still holds: a sheet of
few panels (a cam, a synthesis, a gear pair) is drawn at the largest round scales that keep
it one sheet, not left two thirds empty at the A1 lengths."""

from __future__ import annotations

from collections.abc import Callable, Iterable, Sequence

import shapely

from drawings.paper.panel_frame import SLACK_MM, Panel
from drawings.paper.sheet import Sheet, SheetSpec, compose, fits_empty, title_box, usable


def drawn_part(sheet: Sheet) -> float:
    """The part of a sheet's field (inside the frame, less the title block, both from the
    sheet's size) its panels' boxes cover: the union of the boxes, so a box's overlap or its
    part outside the field is not counted twice.  Every fill measure of the sheets and the
    tests is this one."""
    return boxes_part(sheet.width, sheet.height, [(x, y, x + p.width, y + p.height) for p, x, y in sheet.placed])


def boxes_part(W: float, H: float, boxes: Iterable[tuple[float, float, float, float]]) -> float:
    """The part of a W × H sheet's field the union of ``boxes`` (x0, y0, x1, y1) covers."""
    field = shapely.box(*usable(W, H)).difference(shapely.box(*title_box(W, H)))
    return float(shapely.union_all([shapely.box(*b) for b in boxes]).intersection(field).area / field.area)


def fullest_on_one_sheet(groups: Iterable[Iterable[Sequence[Panel]]], spec: SheetSpec, path: str,
                         scale: Callable[[Sequence[Panel]], str | None]
                         ) -> tuple[list[Panel], list[Sheet]] | None:
    """Of the first group (the largest main figure first) with a candidate whose panels all go
    on one sheet of ``spec``, the candidate that covers most of it (the first of equals), laid
    out; None when no candidate does.  ``scale`` writes the title block's Scale cell."""
    W, H = spec.size
    x0, y0, x1, y1 = usable(W, H)
    t0, s0, t1, s1 = title_box(W, H)
    room = (x1 - x0) * (y1 - y0) - (t1 - t0) * (s1 - s0)
    # the field drawn_part measures against: what no candidate's part can exceed its area over
    field = (x1 - x0) * (y1 - y0) - max(0.0, min(t1, x1) - max(t0, x0)) * max(0.0, min(s1, y1) - max(s0, y0))
    for group in groups:
        best: tuple[float, list[Panel], list[Sheet]] | None = None
        for panels in group:
            area = sum(p.width * p.height for p in panels)
            if area > room or not all(fits_empty(p, spec.format, spec.orientation) for p in panels):
                continue  # more than the sheet holds: not worth laying out
            if best is not None and area / field <= best[0] + SLACK_MM:
                continue  # covering no more than the fullest so far even laid out without overlap
            sheets = compose(panels, spec, scale(panels), path)
            if len(sheets) == 1:
                part = drawn_part(sheets[0])
                if best is None or part > best[0] + SLACK_MM:
                    best = (part, list(panels), sheets)
        if best is not None:
            return best[1], best[2]
    return None


def fullest_of_chains(groups: Iterable[Iterable[Sequence[Sequence[Panel]]]], spec: SheetSpec, path: str,
                      scale: Callable[[Sequence[Panel]], str | None]
                      ) -> tuple[list[Panel], list[Sheet]] | None:
    """:func:`fullest_on_one_sheet` of candidates in chains: each chain runs from the smallest
    to the largest drawing of one set of figures, and a candidate of a chain that goes on one
    sheet is taken for one whose smaller ones do too, so each chain is bisected for its
    largest that does (a handful of layouts, not one per candidate)."""
    W, H = spec.size
    x0, y0, x1, y1 = usable(W, H)
    t0, s0, t1, s1 = title_box(W, H)
    field = (x1 - x0) * (y1 - y0) - max(0.0, min(t1, x1) - max(t0, x0)) * max(0.0, min(s1, y1) - max(s0, y0))

    def area(panels: Sequence[Panel]) -> float:
        return sum(p.width * p.height for p in panels)

    def one_sheet(panels: Sequence[Panel]) -> list[Sheet] | None:
        if area(panels) > field or not all(fits_empty(p, spec.format, spec.orientation) for p in panels):
            return None
        sheets = compose(panels, spec, scale(panels), path)
        return sheets if len(sheets) == 1 else None

    for group in groups:
        best: tuple[float, list[Panel], list[Sheet]] | None = None
        for chain in group:
            if not chain or (best is not None and area(chain[-1]) / field <= best[0] + SLACK_MM):
                continue  # its largest covers no more than the fullest so far even laid out without overlap
            lo, hi = 0, len(chain) - 1
            found: tuple[int, list[Sheet]] | None = None
            while lo <= hi:
                mid = (lo + hi) // 2
                sheets = one_sheet(chain[mid])
                if sheets is None:
                    hi = mid - 1
                else:
                    found, lo = (mid, sheets), mid + 1
            if found is not None:
                part = drawn_part(found[1][0])
                if best is None or part > best[0] + SLACK_MM:
                    best = (part, list(chain[found[0]]), found[1])
        if best is not None:
            return best[1], best[2]
    return None
