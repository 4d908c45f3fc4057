"""Sheets of many positions laid out as a course lays them out: one bordered block per
crank angle, in angle order, a block never split across sheets unless it cannot fit one.

A block is the panels of one position (scheme, plans, groups with polygons, crank, lever,
tables) packed inside a thin border under a heading "Положение 3, φ = 90°".  Blocks go on
the sheets one after another, each below or to the right of the previous one, so a
teacher reads the positions in order and finds one at a glance.
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass

import numpy as np

from drawings.paper.panel_frame import SLACK_MM, Panel
from drawings.paper.text import layout

Box = tuple[float, float, float, float]
HEAD = 8.0  # heading band of a block, mm
INSET = 3.0  # panels keep this far inside the border
HEAD_SIZE = 5.0


@dataclass(frozen=True, slots=True)
class Frame:
    """The border and heading of one position's block on a sheet."""

    phi: float
    box: Box
    heading: str
    notch: Box | None = None  # the corner the border goes round (the title block's)
    lead: Box | None = None  # the top-left corner it goes round (the plan of positions')

    def outline(self) -> list[tuple[float, float]]:
        """The border: the box, less the notch at its bottom-right corner and the lead at its
        top-left one."""
        x0, y0, x1, y1 = self.box
        right = [(x1, y0), (x1, y1)] if self.notch is None else [
            (x1, y0), (x1, self.notch[1]), (self.notch[0], self.notch[1]), (self.notch[0], y1)]
        left = [(x0, y1), (x0, y0)] if self.lead is None else [
            (x0, y1), (x0, self.lead[3]), (self.lead[2], self.lead[3]), (self.lead[2], y0)]
        return right + left

    @property
    def head_x(self) -> float:
        """Where the heading starts: the top edge's left end."""
        return self.box[0] if self.lead is None else self.lead[2]


@dataclass(slots=True)
class Block:
    """Panels placed relative to the block's top-left corner; ``framed`` blocks get a border."""

    panels: list[tuple[Panel, float, float]]
    width: float
    height: float
    phi: float | None
    heading: str = ""
    notch: Box | None = None  # block coordinates: the corner kept clear (the title block)
    lead: Box | None = None  # block coordinates: the top-left corner kept clear (the plan of positions)

    @property
    def framed(self) -> bool:
        return bool(self.heading)

    def boxes(self, x: float, y: float) -> list[Box]:
        """The rectangles the block covers at (x, y): its box less the notch and the lead, in
        bands from the top."""
        w, h = self.width, self.height
        n, ld = self.notch, self.lead
        ys = sorted({0.0, h} | ({n[1]} if n else set()) | ({ld[3]} if ld else set()))
        out: list[Box] = []
        for a, b in zip(ys[:-1], ys[1:], strict=True):
            x0 = ld[2] if ld is not None and b <= ld[3] + SLACK_MM else 0.0
            x1 = n[0] if n is not None and a >= n[1] - SLACK_MM else w
            if b - a > SLACK_MM and x1 - x0 > SLACK_MM:
                out.append((x + x0, y + a, x + x1, y + b))
        return out


def heading(phi: float, number: int | None, lang: str, part: int = 0) -> str:
    """``Положение 3, φ = 90°`` (``Position 3, φ = 90°``), ``(продолжение)`` on a second part."""
    from drawings.paper.common import angle

    at = f"φ = {angle(phi, lang)}°"
    word = "Положение" if lang == "ru" else "Position"
    text = f"{word} {number}, {at}" if number is not None else at
    if part:
        text += " (продолжение)" if lang == "ru" else " (continued)"
    return text


#: The blocks packed so far, by what determines them: the panels (each by identity; the
#: entry holds them, so no identity is reused while it is kept), the room, the spots' rule
#: and the heading in the font it is measured in.  The layout searches pack one position's
#: panels into the same widths again for every fit the other positions try.
_PACKED: dict[tuple, tuple[tuple[Panel, ...], Block, tuple[Panel, ...]]] = {}
_PACKED_MOST = 20000


def pack_block(panels: Sequence[Panel], width: float, height: float, gap: float,
               free_spots, title: str = "", notch: Box | None = None,
               lead: Box | None = None) -> tuple[Block, list[Panel]]:
    """:func:`_pack_block`, each packing made once (a fresh block returned every time)."""
    from drawings.paper.fonts import current

    key = (tuple(id(p) for p in panels), width, height, gap, free_spots, title, notch, lead, current())
    hit = _PACKED.get(key)
    if hit is None:
        if len(_PACKED) >= _PACKED_MOST:
            _PACKED.clear()
        made, left = _pack_block(panels, width, height, gap, free_spots, title, notch, lead)
        hit = _PACKED[key] = (tuple(panels), made, tuple(left))
    _, blk, rest = hit
    return (Block(list(blk.panels), blk.width, blk.height, blk.phi, blk.heading, blk.notch, blk.lead),
            list(rest))


def _pack_block(panels: Sequence[Panel], width: float, height: float, gap: float,
                free_spots, title: str = "", notch: Box | None = None,
                lead: Box | None = None) -> tuple[Block, list[Panel]]:
    """Panels in reading order inside a ``width`` × ``height`` block, each where it keeps the
    block's skyline lowest; returns the block (shrunk to its content) and what did not fit.
    ``notch`` (block coordinates, reaching the bottom-right corner) and ``lead`` (from the
    top-left corner; the heading starts right of it) are kept clear."""
    framed = bool(title)
    top = HEAD if framed else 0.0
    inset = INSET if framed else 0.0
    area = (inset, top + inset, width - inset, height - inset)
    taken: list[Box] = []
    if notch is not None:  # panels keep GAP from the notch's border, as from a panel
        taken.append((notch[0] - inset + gap, notch[1] - inset + gap, width + gap, height + gap))
    if lead is not None:  # and the inset from the border round the lead
        taken.append((-gap, -gap, lead[2] + inset - gap, lead[3] + inset - gap))
    placed: list[tuple[Panel, float, float]] = []
    rest: list[Panel] = []
    for p in panels:
        spots = free_spots(p.width, p.height, area, taken)
        if not len(spots):
            rest.append(p)
            continue
        X, Y = spots[:, 0], spots[:, 1]
        i = int(np.lexsort((X, Y, Y + p.height + 0.05 * X))[0])
        x, y = float(X[i]), float(Y[i])
        taken.append((x, y, x + p.width, y + p.height))
        placed.append((p, x, y))
    if not placed:
        return Block([], 0.0, 0.0, None, title), rest
    boxes = [(x, y, x + p.width, y + p.height) for p, x, y in placed]
    w = max(b[2] for b in boxes) + inset
    h = max(b[3] for b in boxes) + inset
    # the content runs under the lead: the heading starts right of it
    kept = None if lead is None or not any(b[0] < lead[2] for b in boxes) else (0.0, 0.0, lead[2], lead[3])
    if framed:
        w = max(w, (kept[2] if kept is not None else 0.0) + layout(title, 0, 0, HEAD_SIZE).box[2] + 2 * inset)
    cut = None
    if notch is not None and w > notch[0] and h > notch[1]:  # the content runs round the corner
        cut = (notch[0], notch[1], w, h)
    return Block(placed, w, h, placed[0][0].phi, title, cut, kept), rest


def place_block(block: Block, area: Box, taken: Sequence[Box], prev: Box | None, free_spots,
                gap: float) -> tuple[float, float] | None:
    """Where a block goes on a sheet: never above the previous block, nor left of it while
    wholly beside it (reading order), then the spot that keeps the skyline lowest."""
    spots = free_spots(block.width, block.height, area, taken)
    if not len(spots):
        return None
    X, Y = spots[:, 0], spots[:, 1]
    if prev is not None:
        ok = (Y >= prev[1] - SLACK_MM) & ((Y + block.height > prev[3] + SLACK_MM) | (X >= prev[2] + gap - SLACK_MM))
        X, Y = X[ok], Y[ok]
        if not len(X):
            return None
    i = int(np.lexsort((X, Y, Y + block.height + 0.05 * X))[0])
    return float(X[i]), float(Y[i])


def spread(blocks: list[tuple[Block, float, float]], area: Box, stays: Sequence[Box], gap: float,
           most: float = 1.5) -> list[tuple[Block, float, float]]:
    """Share a sheet's spare height between its bands of blocks: every block's top moves away
    from the area's top by one factor f (1 ≤ f ≤ ``most``), so nothing new overlaps and no
    position's block (a framed one) moves more than ``gap`` further from the one above it (a
    wider empty band between two positions reads as a sheet half drawn: the spare height stays
    below the last block)."""
    top = area[1]
    free = [(b, x, y) for b, x, y in blocks if y > top + SLACK_MM]
    if not free:
        return blocks
    most = min([most] + [1.0 + gap / (y - top) for b, _, y in free if b.framed])

    def ok(f: float) -> bool:
        for b, x, y in free:
            y2 = top + (y - top) * f
            box = (x, y2, x + b.width, y2 + b.height)
            if box[3] > area[3] + SLACK_MM:
                return False
            for s in stays:
                if box[0] < s[2] + gap - SLACK_MM and s[0] < box[2] + gap - SLACK_MM and \
                        box[1] < s[3] + gap - SLACK_MM and s[1] < box[3] + gap - SLACK_MM:
                    return False
        return True

    f = most
    while f > 1.0 and not ok(f):
        f = max(1.0, f - 0.02)
    if f <= 1.0 + SLACK_MM:
        return blocks
    return [(b, x, y if y <= top + SLACK_MM else top + (y - top) * f) for b, x, y in blocks]


def widths(area_w: float, panels: Sequence[Panel]) -> list[float]:
    """Block widths worth trying, widest first: fractions of the sheet's width, never
    narrower than the widest panel of the block."""
    widest = max((p.width for p in panels), default=0.0) + 2 * INSET
    out: list[float] = []
    for f in (1.0, 0.75, 2 / 3, 0.6, 0.5, 0.4, 1 / 3, 0.25):
        w = max(widest, area_w * f)
        if w <= area_w + SLACK_MM and all(abs(w - o) > 1.0 for o in out):
            out.append(w)
    return out or [area_w]


def frame_of(block: Block, x: float, y: float) -> Frame:
    assert block.phi is not None
    n, ld = block.notch, block.lead
    notch = None if n is None else (x + n[0], y + n[1], x + n[2], y + n[3])
    lead = None if ld is None else (x + ld[0], y + ld[1], x + ld[2], y + ld[3])
    return Frame(block.phi, (x, y, x + block.width, y + block.height), block.heading, notch, lead)
