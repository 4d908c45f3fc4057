"""Small drawing helpers shared by the panels: vectors, ids, numbers, label placement."""

from __future__ import annotations

import math
import re
from collections.abc import Sequence
from dataclasses import dataclass, field

import numpy as np
import shapely

from drawings.paper.backend import FILLED, Backend, Prim, Pt, Recording, Style
from drawings.paper.declutter import clip_segments
from drawings.paper.text import Label, layout

HEAD_LEN = 3.5  # mm, arrowhead length on the sheet
HEAD_HALF = 0.65  # mm, half width

_GREEK_IDS = {"τ": "tau", "μ": "mu", "ω": "omega", "ε": "eps", "φ": "phi", "Φ": "Phi", "Σ": "Sum"}


def ident(text: str) -> str:
    """A stable XML id fragment: ``a_BA^τ`` -> ``a_BA-tau``."""
    s = "".join(_GREEK_IDS.get(ch, ch) for ch in text)
    s = s.replace("^", "-").replace(" ", "_").replace("@", "-")
    return re.sub(r"[^A-Za-z0-9_.-]", "", s)


def phi_tag(phi: float) -> str:
    """Crank angle in ids: 45 -> ``45``, 22.5 -> ``22.5``, -30 -> ``m30``."""
    s = f"{phi:.6g}"
    return s.replace("-", "m")


def fmt(v: float, sig: int = 4, lang: str = "en") -> str:
    """A number as written on the sheet: ``sig`` significant digits, decimal comma in Russian."""
    if abs(v) < 1e-9:
        v = 0.0
    if v == 0 or not math.isfinite(v):
        s = "0" if v == 0 else str(v)
    else:
        mag = math.floor(math.log10(abs(v)))
        dec = max(0, sig - 1 - mag)
        s = f"{v:.{dec}f}"
        if "." in s:
            s = s.rstrip("0").rstrip(".")
        if s in ("-0", ""):
            s = "0"
    return s.replace(".", ",") if lang == "ru" else s


def degrees360(a: float) -> float:
    """Radians as degrees in [0, 360), round-off at 360 shown as 0."""
    d = round(math.degrees(a) % 360.0, 6)
    return 0.0 if d >= 360.0 else d


def angle(phi: float, lang: str = "en") -> str:
    """A crank angle, degrees, the same in a block's heading and in its panels' titles
    (181,851° in both, not 181,9° under 181,851°)."""
    return fmt(phi, 6, lang)


def arrow(b: Backend, p0: Pt, p1: Pt, style: Style, eid: str, cls: str,
          head: float = HEAD_LEN, half: float = HEAD_HALF) -> None:
    """A vector from p0 to p1 (paper mm) as a group: the shaft ``line`` starts exactly at p0,
    the filled head ``polygon`` has its first point exactly at p1 (measure between them)."""
    dx, dy = p1[0] - p0[0], p1[1] - p0[1]
    L = math.hypot(dx, dy)
    b.begin(eid, cls)
    if L < 1e-6:
        b.line(p0, p0, style)
        b.end()
        return
    ux, uy = dx / L, dy / L
    h = min(head, 0.45 * L)
    w = half * h / head
    base = (p1[0] - ux * h, p1[1] - uy * h)
    shaft_end = (p1[0] - ux * h * 0.7, p1[1] - uy * h * 0.7)
    b.line(p0, shaft_end, style)
    fill = Style(stroke=None, width=0.0, fill=style.stroke or "#000", cls="head")
    b.polygon([p1, (base[0] - uy * w, base[1] + ux * w), (base[0] + uy * w, base[1] - ux * w)], fill)
    b.end()


def dot(b: Backend, c: Pt, r: float = 0.55, eid: str = "") -> None:
    b.circle(c, r, FILLED, eid)


def coincident_positions(points: Sequence[tuple[float, float]]) -> list[list[int]]:
    """The positions whose sheet points fall in one 0.3 mm cell (they share one mark and one
    label, "1, 11"), each group in order of position, the groups in order of first position."""
    groups: dict[tuple[float, float], list[int]] = {}
    for k, p in enumerate(points):
        key = (round(p[0] / 0.3) * 0.3, round(p[1] / 0.3) * 0.3)
        groups.setdefault(key, []).append(k)
    return list(groups.values())


def box_poly(box: tuple[float, float, float, float], pad: float = 0.0) -> shapely.Geometry:
    return shapely.box(box[0] - pad, box[1] - pad, box[2] + pad, box[3] + pad)


@dataclass(slots=True)
class Placer:
    """Greedy label placement: candidates around an anchor on growing rings, scored by the
    length of lines they cover and the symbols they touch; placed labels are never covered.

    Plain numpy on boxes and segments (no geometry objects per candidate): a sheet places
    a few hundred labels in a few milliseconds."""

    segments: list[tuple[float, float, float, float]] = field(default_factory=list)
    discs: list[tuple[float, float, float]] = field(default_factory=list)
    polys: list[list[Pt]] = field(default_factory=list)
    boxes: list[tuple[float, float, float, float]] = field(default_factory=list)  # placed labels
    bounds: tuple[float, float, float, float] | None = None  # keep labels inside (soft)

    def add_line(self, pts: Sequence[Pt]) -> None:
        for p, q in zip(pts[:-1], pts[1:], strict=False):
            if p != q:
                self.segments.append((p[0], p[1], q[0], q[1]))

    def add_poly(self, pts: Sequence[Pt]) -> None:
        """An area labels should stay out of (a slider block, a hatched band)."""
        self.add_line(list(pts) + [pts[0]])
        self.polys.append(list(pts))

    def add_disc(self, c: Pt, r: float) -> None:
        self.discs.append((c[0], c[1], r))

    def add_box(self, box: tuple[float, float, float, float]) -> None:
        self.boxes.append(box)

    @property
    def labels(self) -> list[tuple[float, float, float, float]]:
        return self.boxes

    def _costs(self, bx: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        """(soft cost, clash with a placed label) of candidate boxes bx (k×4)."""
        k = len(bx)
        cost = np.zeros(k)
        clash: np.ndarray = np.zeros(k, dtype=bool)
        x0, y0, x1, y1 = (bx[:, i:i + 1] for i in range(4))
        if self.boxes:
            L = np.asarray(self.boxes)
            clash = np.asarray(((x0 < L[:, 2]) & (L[:, 0] < x1) & (y0 < L[:, 3]) & (L[:, 1] < y1)).any(axis=1))
        S = np.asarray(self.segments) if self.segments else np.zeros((0, 4))
        if len(S):
            # only the segments whose boxes meet the candidates' region
            lo_x, lo_y, hi_x, hi_y = bx[:, 0].min(), bx[:, 1].min(), bx[:, 2].max(), bx[:, 3].max()
            near = ((np.minimum(S[:, 0], S[:, 2]) <= hi_x) & (np.maximum(S[:, 0], S[:, 2]) >= lo_x)
                    & (np.minimum(S[:, 1], S[:, 3]) <= hi_y) & (np.maximum(S[:, 1], S[:, 3]) >= lo_y))
            S = S[near]
        if len(S):
            inside, t0, t1 = clip_segments(S, bx)
            dx, dy = S[:, 2] - S[:, 0], S[:, 3] - S[:, 1]
            length = np.where(inside, (t1 - t0) * np.hypot(dx, dy), 0.0)
            cost += (inside * 3.0 + length).sum(axis=1)
        if self.discs:
            D = np.asarray(self.discs)
            cx = np.clip(D[:, 0], x0, x1)
            cy = np.clip(D[:, 1], y0, y1)
            hit = np.hypot(cx - D[:, 0], cy - D[:, 1]) < D[:, 2]
            cost += hit.sum(axis=1) * 8.0
        mx, my = (bx[:, 0] + bx[:, 2]) / 2, (bx[:, 1] + bx[:, 3]) / 2
        for poly in self.polys:
            px = [p[0] for p in poly]
            py = [p[1] for p in poly]
            if min(px) <= mx.max() and max(px) >= mx.min() and min(py) <= my.max() and max(py) >= my.min():
                cost += _inside(poly, mx, my) * 20.0
        if self.bounds is not None:
            b = self.bounds
            out = (bx[:, 0] < b[0]) | (bx[:, 1] < b[1]) | (bx[:, 2] > b[2]) | (bx[:, 3] > b[3])
            cost += out * 50.0
        return cost, clash

    def place(self, text: str, anchor: Pt, size: float, prefer: tuple[float, float] | None = None,
              gap: float = 1.0, hard_only: bool = False) -> Label:
        """Best of 16 positions around ``anchor`` on rings moving outwards; ``prefer`` is a
        paper direction to favour.  Labels never overlap labels already placed (the rings
        keep growing until a free spot is found)."""
        lab0 = layout(text, 0.0, 0.0, size, "middle", "middle")
        bx0, by0, bx1, by1 = lab0.box
        w, h = bx1 - bx0, by1 - by0
        ang = 2 * np.pi * np.arange(16) / 16
        cx, cy = np.cos(ang), np.sin(ang)
        pref = 0.0 if prefer is None else 1.5 * (1.0 - (cx * prefer[0] + cy * prefer[1]))
        best = None
        rings = (0.0, 2.0, 5.0, 9.0, 14.0, 20.0, 28.0, 40.0, 60.0)
        for ring, extra in enumerate(rings):
            dist = gap + extra
            x = anchor[0] + cx * (dist + w / 2 * np.sqrt(np.abs(cx)))
            y = anchor[1] + cy * (dist + h / 2 * np.sqrt(np.abs(cy)))
            boxes = np.stack([x + bx0 - 0.3, y + by0 - 0.3, x + bx1 + 0.3, y + by1 + 0.3], axis=1)
            soft, clash = self._costs(boxes)
            if hard_only:
                soft = np.zeros_like(soft)
            cost = soft + pref + (min(ring, 3) * 4.0 + max(0, ring - 3) * 10.0) + clash * 1000.0
            i = int(np.argmin(cost))
            if best is None or cost[i] < best[0] - 1e-9:
                best = (float(cost[i]), bool(clash[i]), float(x[i]), float(y[i]))
            if not best[1] and (best[0] < 1.0 + ring * 4.0 or ring >= 3):
                break
        assert best is not None
        lab = layout(text, best[2], best[3], size, "middle", "middle")
        self.boxes.append(lab.box)
        return lab


def _inside(poly: Sequence[Pt], x: np.ndarray, y: np.ndarray) -> np.ndarray:
    """Points (x, y) inside a polygon (even–odd rule)."""
    res = np.zeros(len(x), dtype=bool)
    n = len(poly)
    for i in range(n):
        (ax, ay), (bx, by) = poly[i], poly[(i + 1) % n]
        if ay == by:
            continue
        cond = (ay > y) != (by > y)
        xi = ax + (y - ay) * (bx - ax) / (by - ay)
        res ^= cond & (x < xi)
    return res


def label_boxes(prims: Sequence[Prim]) -> list[tuple[float, float, float, float]]:
    return [p.label.box for p in prims if p.op == "text" and p.label is not None]


def rec_bbox(rec: Recording) -> tuple[float, float, float, float]:
    return rec.bbox()
