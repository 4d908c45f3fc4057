"""Packing rectangles on sheets: the panels of one position into its block, the blocks one
after another onto the sheets.

A block is packed several ways (in reading order, tallest first, widest first, largest
first; each into a range of widths, bottom-left on a skyline); every shape that no other
beats in both width and height is kept, so the sheet can take the one that fits the room
left on it (beside the plan of positions, under the previous block).  Blocks go in angle
order: each one where it keeps the sheet's skyline lowest, never above the previous one,
else on the next sheet.
"""

from __future__ import annotations

from collections.abc import Callable, Sequence
from dataclasses import dataclass
from functools import partial

import numpy as np

from drawings.paper.blocks import Block, heading, pack_block, place_block
from drawings.paper.panel_frame import SLACK_MM, Panel

Box = tuple[float, float, float, float]
Spots = Callable[[float, float, Box, Sequence[Box]], np.ndarray]

#: A band of a sheet lower than this (mm) is not worth starting a part of a block in.
MIN_BAND = 40.0
#: Fractions of the sheet's width a block is packed into.
FRACTIONS = (1.0, 0.9, 0.8, 0.75, 2 / 3, 0.6, 0.55, 0.5, 0.45, 0.4, 0.35, 1 / 3, 0.3, 0.25)


def _unique(a: np.ndarray) -> np.ndarray:
    """The distinct values of ``a`` in order: ``np.unique``'s own sort and comparison,
    without the import of numpy.ma that ``np.unique`` costs."""
    a = np.sort(a)
    keep = np.ones(a.shape, dtype=bool)
    keep[1:] = a[1:] != a[:-1]
    return a[keep]


def free_spots(gap: float) -> Spots:
    """The free top-left corners of a w × h box among ``taken`` (k×2, may be empty): where
    the box touches the area's edges or sits ``gap`` from a box already there."""

    def spots(w: float, h: float, area: Box, taken: Sequence[Box]) -> np.ndarray:
        T = np.asarray(taken, dtype=float).reshape(-1, 4)
        xs = _unique(np.concatenate([[area[0], area[2] - w], T[:, 2] + gap, T[:, 0] - gap - w]))
        ys = _unique(np.concatenate([[area[1], area[3] - h], T[:, 3] + gap, T[:, 1] - gap - h]))
        xs = xs[(xs >= area[0] - SLACK_MM) & (xs + w <= area[2] + SLACK_MM)]
        ys = ys[(ys >= area[1] - SLACK_MM) & (ys + h <= area[3] + SLACK_MM)]
        if not len(xs) or not len(ys):
            return np.zeros((0, 2))
        X, Y = (a.ravel() for a in np.meshgrid(xs, ys))
        if len(T):
            g = gap - SLACK_MM
            hit = ((X[:, None] < T[None, :, 2] + g) & (T[None, :, 0] - g < X[:, None] + w)
                   & (Y[:, None] < T[None, :, 3] + g) & (T[None, :, 1] - g < Y[:, None] + h)).any(axis=1)
            X, Y = X[~hit], Y[~hit]
        return np.stack([X, Y], axis=1)

    return spots


def _orders(panels: Sequence[Panel]) -> list[list[Panel]]:
    """Reading order first (it wins a tie), then the classic orders of rectangle packing
    (tallest, widest, largest first), the first panel (the scheme) still first."""
    base = list(panels)
    out = [base]
    for key in (lambda p: -p.height, lambda p: -p.width, lambda p: -p.width * p.height):
        o = base[:1] + sorted(base[1:], key=key)
        if all(o != x for x in out):
            out.append(o)
    return out


def _pareto(blocks: list[Block]) -> list[Block]:
    """Shapes no other shape beats in both width and height (within 1 mm), smallest area first;
    of shapes alike, the first tried (reading order)."""
    keep: list[Block] = []
    for b in blocks:
        if any(k.width <= b.width + 1.0 and k.height <= b.height + 1.0 for k in keep):
            continue
        keep = [k for k in keep if not (b.width <= k.width + 1.0 and b.height <= k.height + 1.0)]
        keep.append(b)
    return sorted(keep, key=lambda b: (b.width * b.height, b.width))


def shapes(panels: Sequence[Panel], area_w: float, limit: Callable[[float], float], gap: float,
           spots: Spots, title: str, extra: Sequence[float] = ()) -> tuple[list[Block], list[Panel]]:
    """Every useful shape of the block of ``panels`` (each order packed into each width):
    all the Pareto shapes when some shape holds every panel, else the one holding the most
    (and the panels left for the next part)."""
    from drawings.paper.blocks import INSET

    widest = max((p.width for p in panels), default=0.0) + 2 * INSET
    one_row = sum(p.width for p in panels) + gap * (len(panels) - 1) + 2 * INSET  # wider packs alike
    ws: list[float] = []
    for w in [area_w * f for f in FRACTIONS] + list(extra):
        w = min(max(widest, w), max(widest, one_row))
        if w <= area_w + SLACK_MM and all(abs(w - o) > 1.0 for o in ws):
            ws.append(w)
    whole: list[Block] = []
    reading: list[Block] = []  # the shapes that keep the reading order
    part: tuple[Block, list[Panel]] | None = None
    for i, order in enumerate(_orders(panels)):
        last: tuple[Block, list[Panel], float] | None = None
        for w in sorted(ws or [area_w], reverse=True):
            if last is not None and not last[1] and last[0].width <= w - 1.0 and last[2] == limit(w):
                continue  # the wider pack did not use this width: the same pack again
            blk, rest = pack_block(order, w, limit(w), gap, spots, title)
            last = (blk, rest, limit(w))
            if not rest:
                (reading if i == 0 else whole).append(blk)
            elif i == 0 and (part is None or len(rest) < len(part[1])):  # parts keep the reading order
                part = (blk, rest)
    # another order only where it is clearly tighter (5 % both ways) than every reading shape
    whole = [b for b in whole if not any(r.width <= 1.05 * b.width + 1.0 and r.height <= 1.05 * b.height + 1.0
                                         for r in reading)]
    if reading or whole:
        return _pareto(reading + whole), []
    assert part is not None
    return [part[0]], part[1]


@dataclass(frozen=True, slots=True)
class Flow:
    """The panels of a position too many for one sheet: they flow over the sheets in parts
    ("continued"), each part filling the room left on its sheet."""

    panels: tuple[Panel, ...]
    titles: Callable[[int], str]  # the heading of part n


@dataclass(frozen=True, slots=True)
class Whole:
    """A position's block in every shape worth trying.  On the small formats (A3, A4), where
    no shape fits the room left on a sheet with much of it still free, its panels flow
    instead (continued on the next sheet): the sheet is not given up.  On A1 and A2 a position stays
    whole on one sheet."""

    shapes: list[Block]
    flow: Flow | None
    panels: tuple[Panel, ...] = ()  # its panels and heading, packed again round the title block
    title: str = ""


#: A sheet with more of its area free than this takes the first part of a block that does
#: not fit it whole, rather than being left behind (formats where positions flow).
FREE_TO_FLOW = 0.3


def blocks_of(groups: list[list[Panel]], area: Box, lang: str, numbers: dict[float, int],
              limit: Callable[[float], float], gap: float, spots: Spots,
              single: Sequence[str], keep_whole: bool = True) -> list[Whole | Flow]:
    """Each group as a block in every shape worth trying, or as a :class:`Flow` when it
    cannot fit one sheet; drawing-wide panels (``single`` kinds) stand alone.  With
    ``keep_whole`` a block that fits one sheet never flows."""
    aw = area[2] - area[0]
    # room beside a drawing-wide panel (the plan of positions) is a width worth trying
    extra = [aw - p.width - gap for grp in groups for p in grp if p.kind in single and p.width < aw]
    out: list[Whole | Flow] = []
    for grp in groups:
        phi = grp[0].phi
        if grp[0].kind in single or phi is None:
            out.extend(Whole([Block([(p, 0.0, 0.0)], p.width, p.height, p.phi)], None) for p in grp)
            continue
        found, left = shapes(grp, aw, limit, gap, spots, heading(phi, numbers.get(phi), lang), extra)
        flow = Flow(tuple(grp), partial(heading, phi, numbers.get(phi), lang))
        out.append(flow if left else Whole(found, None if keep_whole or len(grp) == 1 else flow, tuple(grp),
                                           heading(phi, numbers.get(phi), lang)))
    return out


def _part(flow: Flow, rest: list[Panel], n: int, area: Box, taken: Sequence[Box], prev: Box | None,
          gap: float, spots: Spots) -> tuple[Block, list[Panel], float, float] | None:
    """The next part of a flow on a sheet: packed into the band below everything on it or
    into the room right of the previous block, whichever holds more panels."""
    tb = taken[0]
    others = taken[1:]
    regions = [(area[0], area[1] if not others else max(t[3] for t in others) + gap)]
    if prev is not None:
        x0, y0 = prev[2] + gap, prev[1]
        room = (x0, y0, area[2], area[3])
        if not any(t[0] < room[2] and room[0] < t[2] and t[1] < room[3] and room[1] < t[3] for t in others):
            regions.append((x0, y0))
    best = None
    for x0, y0 in regions:
        if area[3] - y0 < MIN_BAND:
            continue
        full = area[2] - x0
        tries: list[tuple[float, float, Box | None]] = []
        for f in FRACTIONS:
            w = full * f
            h = area[3] - y0 if x0 + w <= tb[0] - gap + SLACK_MM else tb[1] - gap - y0
            tries.append((w, h, None))
        if tb[0] - gap > x0 + MIN_BAND and tb[1] - gap > y0 + MIN_BAND:  # the whole room, round the title block
            tries.append((full, area[3] - y0, (tb[0] - gap / 2 - x0, tb[1] - gap / 2 - y0, full, area[3] - y0)))
        for w, h, notch in tries:
            if h < MIN_BAND or w < 2 * MIN_BAND:
                continue
            blk, left = pack_block(rest, w, h, gap, spots, flow.titles(n), notch)
            if not blk.panels:
                continue
            cost = (len(left), y0, blk.width * blk.height)
            if best is None or cost < best[0]:
                best = (cost, blk, left, x0, y0)
    if best is None:
        return None
    return best[1], best[2], best[3], best[4]


def round_corner(item: Whole, area: Box, taken: Sequence[Box], gap: float,
                 spots: Spots) -> tuple[Block, float, float] | None:
    """The block of ``item`` packed into all the room below everything on a sheet (``taken``:
    the title block first), its border going round the title block's corner (an L), and where
    it goes; None when that room does not hold it whole in any order (:func:`_orders`)."""
    tb, others = taken[0], taken[1:]
    x0 = area[0]
    y0 = max(t[3] for t in others) + gap if others else area[1]
    if tb[1] - gap < y0 + MIN_BAND or tb[0] - gap < x0 + MIN_BAND:
        return None
    w, h = area[2] - x0, area[3] - y0
    notch = (tb[0] - gap / 2 - x0, tb[1] - gap / 2 - y0, w, h)
    for order in _orders(item.panels):  # the reading order where it holds them all
        blk, left = pack_block(order, w, h, gap, spots, item.title, notch)
        if not left:
            return blk, x0, y0
    return None


def _free(area: Box, taken: Sequence[Box]) -> float:
    """The fraction of a sheet's area no box covers (the boxes do not overlap)."""
    whole = (area[2] - area[0]) * (area[3] - area[1])
    return 1.0 - sum((t[2] - t[0]) * (t[3] - t[1]) for t in taken) / whole


def place_blocks(blks: list[Whole | Flow], taken: list[list[Box]], area: Box, gap: float,
                 spots: Spots, corner: bool = False
                 ) -> tuple[list[list[tuple[Block, float, float]]], list[list[Box]]]:
    """Blocks one after another on the sheets (pinned panels already there): each in the
    shape and spot that keep the current sheet's skyline lowest (a shape that leaves room
    for the next block wins), else (with ``corner``) in all the room below the rest going
    round the title block's corner (:func:`round_corner`), else on the next sheet; a block
    that fits no room left on a sheet with much of it free flows over it and the next in
    parts.  Returns the blocks per sheet and every sheet's taken boxes."""
    tks = [list(t) for t in taken]
    out: list[list[tuple[Block, float, float]]] = [[] for _ in tks]
    tb = tks[0][0]
    cur = 0
    prev: Box | None = None

    def next_sheet() -> None:
        nonlocal cur, prev
        cur, prev = cur + 1, None
        if cur == len(tks):
            tks.append([tb])
            out.append([])

    def flow(f: Flow) -> None:
        nonlocal prev
        rest, part = list(f.panels), 0
        while rest:
            got = _part(f, rest, part, area, tks[cur], prev, gap, spots)
            if got is None and not out[cur] and len(tks[cur]) == 1:  # too big for a frame: alone
                p = rest[0]
                got = Block([(p, 0.0, 0.0)], p.width, p.height, p.phi), rest[1:], area[0], area[1]
            if got is None:
                next_sheet()
                continue
            b, rest, x, y = got
            box = (x, y, x + b.width, y + b.height)
            tks[cur].append(box)
            out[cur].append((b, x, y))
            prev, part = box, part + 1
            if rest:  # the part took what this sheet had for it: the next part, the next sheet
                next_sheet()

    for n, item in enumerate(blks):
        if isinstance(item, Flow):
            flow(item)
            continue
        options = item.shapes
        after_item = blks[n + 1] if n + 1 < len(blks) else None
        after = after_item.shapes if isinstance(after_item, Whole) else []
        flowed = False
        while True:
            best = None
            for b in options:
                spot = place_block(b, area, tks[cur], prev, spots, gap)
                if spot is None:
                    continue
                box = (spot[0], spot[1], spot[0] + b.width, spot[1] + b.height)
                room = any(place_block(c, area, tks[cur] + [box], box, spots, gap) is not None for c in after)
                cost = (not room, spot[1] + b.height + 0.05 * spot[0], b.width * b.height, spot[1], spot[0])
                if best is None or cost < best[0]:
                    best = (cost, b, spot)
            if best is not None:
                break
            got = round_corner(item, area, tks[cur], gap, spots) if corner and item.panels else None
            if got is not None:
                best = ((False, 0.0, 0.0, 0.0, 0.0), got[0], (got[1], got[2]))
                break
            if not out[cur] and len(tks[cur]) == 1:  # pragma: no cover - blocks fit an empty sheet
                raise ValueError(f"a block of {options[0].width:.0f}×{options[0].height:.0f} mm does not fit")
            if item.flow is not None and _free(area, tks[cur]) > FREE_TO_FLOW:
                flow(item.flow)
                flowed = True
                break
            next_sheet()
        if flowed:
            continue
        assert best is not None
        _, b, spot = best
        box = (spot[0], spot[1], spot[0] + b.width, spot[1] + b.height)
        tks[cur].append(box)
        out[cur].append((b, spot[0], spot[1]))
        prev = box
    while len(out) > 1 and not out[-1] and len(tks[-1]) == 1:
        out.pop()
        tks.pop()
    return out, tks


def place_note(w: float, h: float, area: Box, tks: list[list[Box]], gap: float, spots: Spots) -> tuple[int, float, float]:
    """Where a note (the legend) goes once the blocks are down: above the title block of the
    first sheet with room, else the free spot nearest that corner; a new sheet if none has room."""
    for s, taken in enumerate(tks):
        found = spots(w, h, area, taken)
        if not len(found):
            continue
        tb = taken[0]
        X, Y = found[:, 0], found[:, 1]
        far = np.hypot(tb[2] - (X + w), tb[1] - gap - (Y + h))  # from the corner above the title block
        i = int(np.lexsort((X, Y, np.round(far, 6)))[0])
        return s, float(X[i]), float(Y[i])
    return len(tks), area[2] - w, tks[0][0][1] - gap - h
