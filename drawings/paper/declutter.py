"""Labels clear of every line: a last pass over a finished figure.

Labels are placed while a figure is drawn, and a line or arrow drawn later may run through
one.  Once the figure is complete, every label that a line crosses, or that touches another
label, is moved the least distance (rings of 1–16 mm, 16 directions) to where nothing crosses
it; a label with no such spot nearby stays where it was.
"""

from __future__ import annotations

import math

import numpy as np

from drawings.paper.backend import Prim, arc_points
from drawings.paper.text import Label, TextRun

SHRINK = 0.25  # a line grazing a label's box by less than this does not cross it, mm
RINGS = (1.0, 2.0, 3.0, 4.5, 6.0, 7.5, 9.0, 11.0, 13.5, 16.0)
_KEEP = ("title", "scale", "note", "heading", "cell", "table", "tb-text")  # never moved


def _segments(prims: list[Prim]) -> np.ndarray:
    out: list[tuple[float, float, float, float]] = []
    for p in prims:
        if p.op in ("line", "polyline"):
            pts = list(p.pts)
        elif p.op == "polygon":
            pts = list(p.pts) + list(p.pts[:1])
        elif p.op == "circle":
            pts = arc_points(p.pts[0], p.r, 0.0, 2 * math.pi, 24)
        elif p.op == "arc":
            pts = arc_points(p.pts[0], p.r, p.a0, p.a1)
        else:
            continue
        for a, b in zip(pts[:-1], pts[1:], strict=False):
            if a != b:
                out.append((a[0], a[1], b[0], b[1]))
    return np.asarray(out, dtype=float).reshape(-1, 4)


def clip_segments(S: np.ndarray, bx: np.ndarray) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Liang–Barsky clip of every segment of S (m×4) by every box of bx (k×4): (k×m) whether
    the segment runs through the box, and the parameters t0, t1 of the part inside."""
    k = len(bx)
    x0, y0, x1, y1 = (bx[:, i:i + 1] for i in range(4))
    sx, sy = S[:, 0], S[:, 1]
    dx, dy = S[:, 2] - sx, S[:, 3] - sy
    t0 = np.zeros((k, len(S)))
    t1 = np.ones((k, len(S)))
    ok = np.ones((k, len(S)), dtype=bool)
    with np.errstate(divide="ignore", invalid="ignore"):
        for p, q in ((-dx, sx - x0), (dx, x1 - sx), (-dy, sy - y0), (dy, y1 - sy)):
            r = q / p  # p: one per segment, broadcast over the boxes by each operation
            ok &= ~((p == 0) & (q < 0))
            t0 = np.where(p < 0, np.maximum(t0, r), t0)
            t1 = np.where(p > 0, np.minimum(t1, r), t1)
    return ok & (t1 > t0), t0, t1


def _crossed(S: np.ndarray, bx: np.ndarray, ext: np.ndarray | None = None) -> np.ndarray:
    """For candidate boxes bx (k×4): does any segment of S run through the box (Liang–Barsky)?
    ``ext``: the segments' extents (min x, min y, max x, max y; m×4), to clip only those that
    reach the candidates' region (one wholly beside every box crosses none: the clip's
    rounding keeps it out too)."""
    k = len(bx)
    if not len(S) or not k:
        return np.zeros(k, dtype=bool)
    if ext is not None:
        S = S[(ext[:, 0] <= bx[:, 2].max()) & (ext[:, 2] >= bx[:, 0].min())
              & (ext[:, 1] <= bx[:, 3].max()) & (ext[:, 3] >= bx[:, 1].min())]
        if not len(S):
            return np.zeros(k, dtype=bool)
    return np.asarray(clip_segments(S, bx)[0].any(axis=1))


def _clash(boxes: np.ndarray, bx: np.ndarray) -> np.ndarray:
    if not len(boxes):
        return np.zeros(len(bx), dtype=bool)
    x0, y0, x1, y1 = (bx[:, i:i + 1] for i in range(4))
    B = boxes
    return np.asarray(((x0 < B[:, 2]) & (B[:, 0] < x1) & (y0 < B[:, 3]) & (B[:, 1] < y1)).any(axis=1))


def _moved(p: Prim, dx: float, dy: float) -> Prim:
    lab = p.label
    assert lab is not None
    runs = tuple(TextRun(t.x + dx, t.y + dy, t.text, t.size, t.font) for t in lab.runs)
    box = (lab.box[0] + dx, lab.box[1] + dy, lab.box[2] + dx, lab.box[3] + dy)
    return Prim(p.op, p.pts, p.style, p.r, p.a0, p.a1, Label(runs, box, lab.plain), p.eid, p.cls, p.side,
                p.step, p.length, p.fill)


def declutter(prims: list[Prim]) -> list[Prim]:
    """``prims`` with every crossed label moved to the nearest spot no line crosses."""
    S = _segments(prims)
    idx = [i for i, p in enumerate(prims) if p.op == "text" and p.label is not None
           and not any(k in p.cls.split() for k in _KEEP)]
    if not idx:
        return prims
    out = list(prims)
    ext = np.concatenate([np.minimum(S[:, :2], S[:, 2:]), np.maximum(S[:, :2], S[:, 2:])], axis=1)
    boxes = np.array([list(p.label.box) for p in (prims[i] for i in idx) if p.label is not None], dtype=float)
    ang = 2 * np.pi * np.arange(16) / 16
    cx, cy = np.cos(ang), np.sin(ang)
    g = SHRINK
    for j, i in enumerate(idx):
        b = boxes[j]
        inner = np.array([[b[0] + g, b[1] + g, b[2] - g, b[3] - g]])
        others = np.delete(boxes, j, axis=0)
        if b[2] - b[0] <= 2 * g or b[3] - b[1] <= 2 * g:
            continue
        if not _crossed(S, inner, ext)[0] and not _clash(others, b[None, :])[0]:
            continue
        for r in RINGS:
            dx, dy = r * cx, r * cy
            cand = np.stack([b[0] + g + dx, b[1] + g + dy, b[2] - g + dx, b[3] - g + dy], axis=1)
            full = np.stack([b[0] + dx, b[1] + dy, b[2] + dx, b[3] + dy], axis=1)
            free = ~_crossed(S, cand, ext) & ~_clash(others, full)
            if free.any():
                m = int(np.argmax(free))
                out[i] = _moved(prims[i], float(dx[m]), float(dy[m]))
                boxes[j] = (b[0] + dx[m], b[1] + dy[m], b[2] + dx[m], b[3] + dy[m])
                break
    return out


__all__ = ["declutter"]
