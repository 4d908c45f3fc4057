"""Packing rectangles on sheets: the panels of one position into its block, the blocks one
after another onto the sheets.

A block is packed several ways (in reading order, tallest first, widest first, largest
first; each into a range of widths, bottom-left on a skyline); every shape that no other
beats in both width and height is kept, so the sheet can take the one that fits the room
left on it (beside the plan of positions, under the previous block).  Blocks go in angle
order: each one where it keeps the sheet's skyline lowest, never above the previous one,
else (where the sheet asks for it) packed into the whole room left, its border running round
the title block's corner and the plan of positions (:func:`round_corners`), else on the next
sheet.
"""

from __future__ import annotations

from collections.abc import Callable, Sequence
from dataclasses import dataclass
from functools import cache, partial

import numpy as np

from drawings.paper.blocks import Block, heading, pack_block, place_block
from drawings.paper.panel_frame import SLACK_MM, Panel

Box = tuple[float, float, float, float]
Spots = Callable[[float, float, Box, Sequence[Box]], np.ndarray]

#: A band of a sheet lower than this (mm) is not worth starting a part of a block in.
MIN_BAND = 40.0
#: The least step (mm) of a border going round the title block's corner worth drawing.
MIN_STEP = 10.0
#: Fractions of the sheet's width a block is packed into.
FRACTIONS = (1.0, 0.9, 0.8, 0.75, 2 / 3, 0.6, 0.55, 0.5, 0.45, 0.4, 0.35, 1 / 3, 0.3, 0.25)


def _unique(a: np.ndarray) -> np.ndarray:
    """The distinct values of ``a`` in order: ``np.unique``'s own sort and comparison,
    without the import of numpy.ma that ``np.unique`` costs."""
    a = np.sort(a)
    keep = np.ones(a.shape, dtype=bool)
    keep[1:] = a[1:] != a[:-1]
    return a[keep]


@cache  # one rule per gap: the packings made with it are kept by it (blocks.pack_block)
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
        X, Y = np.tile(xs, len(ys)), np.repeat(ys, len(xs))  # np.meshgrid's order, without its cost
        if len(T):
            # a corner (x, y) is taken where a box overlaps the box's columns at x and its rows
            # at y: each compared once per column and per row, not once per corner
            g = gap - SLACK_MM
            hx = (xs[:, None] < T[None, :, 2] + g) & (T[None, :, 0] - g < xs[:, None] + w)
            hy = (ys[:, None] < T[None, :, 3] + g) & (T[None, :, 1] - g < ys[:, None] + h)
            free = ~(hy[:, None, :] & hx[None, :, :]).any(axis=2).ravel()
            X, Y = X[free], Y[free]
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
    panels: tuple[Panel, ...] = ()  # in reading order, for a block packed round corners
    title: str = ""


#: A sheet with more of its area free than this takes the first part of a block that does
#: not fit it whole, rather than being left behind (formats where positions flow).
FREE_TO_FLOW = 0.3


def blocks_of(groups: list[list[Panel]], area: Box, lang: str, numbers: dict[float, int],
              limit: Callable[[float], float], gap: float, spots: Spots,
              single: Sequence[str], keep_whole: bool = True, tb: Box | None = None) -> list[Whole | Flow]:
    """Each group as a block in every shape worth trying, or as a :class:`Flow` when it
    cannot fit one sheet; drawing-wide panels (``single`` kinds) stand alone.  With
    ``keep_whole`` a block that fits one sheet never flows: not even one that fits it only
    round the title block ``tb`` (no shapes then: :func:`round_corners` places it)."""
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
        whole = Whole([] if left else found, None if keep_whole or len(grp) == 1 else flow, tuple(grp),
                      flow.titles(0))
        if left and keep_whole and tb is not None and round_corners(whole, area, [tb], None, gap, spots):
            left = []  # whole on a sheet of its own, round the title block
        out.append(flow if left else whole)
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


def _rooms(area: Box, taken: Sequence[Box], prev: Box | None, gap: float,
           note: tuple[float, float] | None = None, lone: bool = False) -> list[tuple[float, float, Box | None]]:
    """The rooms left on a sheet that reach its bottom-right corner (round the title block),
    as (x0, y0, lead): the band below everything on it, the room right of the previous block,
    and, where the previous block is a ``lone`` panel (the plan of positions) at the left
    edge, the room from its top down the sheet's whole width with that panel kept clear in
    the room's top-left corner (``lead``, in the room's coordinates, the border ``gap``/2
    from the panel), there with room for a ``note`` (w, h: the legend) under it or without."""
    tb, others = taken[0], taken[1:]

    def clear(room: Box, but: Box | None = None) -> bool:
        return not any(t != but and t[0] < room[2] - SLACK_MM and room[0] < t[2] - SLACK_MM
                       and t[1] < room[3] - SLACK_MM and room[1] < t[3] - SLACK_MM for t in others)

    out: list[tuple[float, float, Box | None]] = [
        (area[0], area[1] if not others else max(t[3] for t in others) + gap, None)]
    if prev is not None:
        if clear((prev[2] + gap, prev[1], area[2], area[3])):
            out.append((prev[2] + gap, prev[1], None))
        if lone and prev[0] <= area[0] + SLACK_MM and clear((area[0], prev[1], area[2], area[3]), prev):
            lead = (0.0, 0.0, prev[2] + gap / 2 - area[0], prev[3] + gap / 2 - prev[1])
            out.append((area[0], prev[1], lead))
            if note is not None:  # room for the legend under the plan of positions, gap from the border
                out.append((area[0], prev[1], (0.0, 0.0, max(lead[2], note[0] + gap),
                                               prev[3] + 2 * gap + note[1] - prev[1])))
    return [(x0, y0, lead) for x0, y0, lead in out
            if tb[0] - gap > x0 + MIN_BAND and tb[1] - gap > y0 + MIN_BAND]


def round_corners(item: Whole, area: Box, taken: Sequence[Box], prev: Box | None, gap: float,
                  spots: Spots, note: tuple[float, float] | None = None,
                  lone: bool = False) -> tuple[Block, float, float] | None:
    """A position's block packed whole into a room left on a sheet, its border running round
    the title block's corner (and round the plan of positions above-left of it, ``lone``:
    :func:`_rooms`) where the block's rectangles find no room: the block that leaves room
    for a ``note`` (w, h: the legend still to go on this sheet), then has no step in its
    border lower than :data:`MIN_STEP`, then keeps the reading order (else moves least of
    it: the panels it leaves out, earlier), then ends highest (the least area of equals),
    or None where no room holds all its panels."""
    if not item.panels:
        return None
    tb = taken[0]
    reading = list(item.panels)
    best = None
    for x0, y0, lead in _rooms(area, taken, prev, gap, note, lone):
        w, h = area[2] - x0, area[3] - y0
        notch = (tb[0] - gap / 2 - x0, tb[1] - gap / 2 - y0, w, h)
        # the reading order; then it with the panels it leaves out moved earlier; then the others
        tries = [(0, reading)]
        first, out = pack_block(reading, w, h, gap, spots, item.title, notch, lead)
        if out:
            rest = [p for p in reading if p not in out]
            tries += [(1, rest[:k] + out + rest[k:]) for k in range(1, len(rest))]
        tries += [(2, o) for o in _orders(reading)[1:]]
        for rank, order in tries:
            blk, left = (first, out) if rank == 0 else pack_block(order, w, h, gap, spots, item.title, notch, lead)
            if left or (lead is not None and blk.lead is None):  # all under the lead's right: the room beside it
                continue
            crowded = note is not None and not len(spots(*note, area, [*taken, *blk.boxes(x0, y0)]))
            # a border stepping down a few mm beside the title block reads as a slip of the pen
            step = blk.notch is not None and blk.height - blk.notch[1] < MIN_STEP
            cost = (crowded, step, rank, y0 + blk.height, blk.width * blk.height)
            if best is None or cost < best[0]:
                best = (cost, blk, x0, y0)
    return None if best is None else (best[1], best[2], best[3])


def _free(area: Box, taken: Sequence[Box]) -> float:
    """The fraction of a sheet's area no box covers (the boxes do not overlap)."""
    whole = (area[2] - area[0]) * (area[3] - area[1])
    return 1.0 - sum((t[2] - t[0]) * (t[3] - t[1]) for t in taken) / whole


def place_blocks(blks: list[Whole | Flow], taken: list[list[Box]], area: Box, gap: float,
                 spots: Spots, note: tuple[float, float] | None = None, corners: bool = False
                 ) -> tuple[list[list[tuple[Block, float, float]]], list[list[Box]]]:
    """Blocks one after another on the sheets (pinned panels already there): each in the
    shape and spot that keep the current sheet's skyline lowest (a shape that leaves room
    for the next block wins), else (with ``corners``) round the corners of the room left
    (:func:`round_corners`, leaving room for the ``note`` to come where no earlier sheet
    has it), else on the next sheet; a block that fits no room left on a sheet with much of
    it free flows over it and the next in parts.  Returns the blocks per sheet and every
    sheet's taken boxes (a block's as the rectangles inside its border)."""
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
        rounded = None
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
            if corners:
                housed = note is None or any(len(spots(*note, area, t)) for t in tks[:cur])
                lone = bool(out[cur]) and not out[cur][-1][0].framed  # after the plan of positions
                rounded = round_corners(item, area, tks[cur], prev, gap, spots, None if housed else note, lone)
                if rounded is not None:
                    break
            if not out[cur] and len(tks[cur]) == 1:  # pragma: no cover - blocks fit an empty sheet
                raise ValueError(f"a block of {len(item.panels) or 1} panels does not fit")
            if item.flow is not None and _free(area, tks[cur]) > FREE_TO_FLOW:
                flow(item.flow)
                flowed = True
                break
            next_sheet()
        if flowed:
            continue
        if best is None:
            assert rounded is not None
            b, spot = rounded[0], (rounded[1], rounded[2])
        else:
            _, b, spot = best
        tks[cur].extend(b.boxes(*spot))
        out[cur].append((b, spot[0], spot[1]))
        prev = (spot[0], spot[1], spot[0] + b.width, spot[1] + b.height)
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
