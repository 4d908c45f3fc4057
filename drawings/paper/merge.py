"""Two short sets on one sheet: a sheet's panels, kept as they were laid out, moved onto the
free room of the sheet before it when they fit there.

A gear file's meshing sheet and its train sheet, a cam's profile and its diagrams: each laid
out alone they leave two A1 sheets mostly empty.  The later set keeps its own arrangement (the
plan of velocities beside the train's scheme, at the scheme's heights) and moves as one piece.
"""

from __future__ import annotations

import dataclasses
from collections.abc import Sequence

from drawings.paper.packing import free_spots
from drawings.paper.sheet import GAP, Sheet, usable

Box = tuple[float, float, float, float]


def _extent(sh: Sheet) -> Box:
    """The box round every panel and block border of a sheet."""
    boxes = [(x, y, x + p.width, y + p.height) for p, x, y in sh.placed] + [f.box for f in sh.frames]
    return (min(b[0] for b in boxes), min(b[1] for b in boxes), max(b[2] for b in boxes), max(b[3] for b in boxes))


def _taken(sh: Sheet) -> list[Box]:
    return [sh.title_box] + [(x, y, x + p.width, y + p.height) for p, x, y in sh.placed] + [f.box for f in sh.frames]


def moved_onto(prev: Sheet, sh: Sheet) -> tuple[float, float] | None:
    """Where :func:`merged` moves ``sh``'s panels, as laid out, onto ``prev``'s free room (the
    uppermost free spot, then the leftmost): the shift, or None where they do not fit (or
    ``sh`` has none, or a block's border runs round a corner)."""
    if not sh.placed or any(f.notch is not None or f.lead is not None for f in sh.frames):
        return None
    x0, y0, x1, y1 = _extent(sh)
    spots = free_spots(GAP)(x1 - x0, y1 - y0, usable(prev.width, prev.height), _taken(prev))
    if not len(spots):
        return None
    i = min(range(len(spots)), key=lambda k: (round(float(spots[k][1]), 6), float(spots[k][0])))
    return float(spots[i][0]) - x0, float(spots[i][1]) - y0


def merged(sheets: Sequence[Sheet], scale_texts: Sequence[str | None] | None = None) -> list[Sheet]:
    """``sheets`` with each one's panels moved onto the sheet before it where they fit there as
    laid out (the uppermost free spot, then the leftmost); renumbered.  ``scale_texts``: each
    sheet's Scale cell (a merged sheet's joins its sets' different ones with "; ")."""
    texts = list(scale_texts) if scale_texts is not None else [sh.scale_text for sh in sheets]
    out: list[Sheet] = []
    out_texts: list[list[str | None]] = []
    for sh, text in zip(sheets, texts, strict=True):
        shift = moved_onto(out[-1], sh) if out else None
        if shift is not None:
            prev, (dx, dy) = out[-1], shift
            prev.placed.extend((p, x + dx, y + dy) for p, x, y in sh.placed)
            prev.frames.extend(dataclasses.replace(f, box=(f.box[0] + dx, f.box[1] + dy, f.box[2] + dx,
                                                           f.box[3] + dy)) for f in sh.frames)
            out_texts[-1].append(text)
            continue
        out.append(sh)
        out_texts.append([text])
    for n, (sh, ts) in enumerate(zip(out, out_texts, strict=True)):
        if len(ts) > 1:  # None (the sheet's main image's) only where every set said None
            known = [t for t in ts if t is not None]
            sh.scale_text = "; ".join(dict.fromkeys(t for t in known if t)) if known else None
        sh.number, sh.count = n + 1, len(out)
        sh.prims = []
        sh.render()
    return out
