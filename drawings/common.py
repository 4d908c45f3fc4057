"""Small drawing helpers shared by the panels: vectors, ids, numbers, label placement."""

from __future__ import annotations

import math
import re
from collections.abc import Sequence
from dataclasses import dataclass, field

import shapely

from .backend import FILLED, Backend, Prim, Pt, Recording, Style
from .text import Label, layout

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


def box_poly(box: tuple[float, float, float, float], pad: float = 0.0) -> shapely.Geometry:
    return shapely.box(box[0] - pad, box[1] - pad, box[2] + pad, box[3] + pad)


@dataclass(slots=True)
class Placer:
    """Greedy label placement: candidates around an anchor, scored by what they cover."""

    obstacles: list[shapely.Geometry] = field(default_factory=list)  # lines, symbols (soft)
    labels: list[shapely.Geometry] = field(default_factory=list)  # placed label boxes (hard)
    bounds: tuple[float, float, float, float] | None = None  # keep labels inside (soft)

    def add_line(self, pts: Sequence[Pt]) -> None:
        if len(pts) >= 2 and any(pts[i] != pts[0] for i in range(1, len(pts))):
            self.obstacles.append(shapely.LineString(pts))

    def add_disc(self, c: Pt, r: float) -> None:
        self.obstacles.append(shapely.Point(c).buffer(r, 8))

    def add_box(self, box: tuple[float, float, float, float]) -> None:
        self.labels.append(box_poly(box))

    def place(self, text: str, anchor: Pt, size: float, prefer: tuple[float, float] | None = None,
              gap: float = 1.0, hard_only: bool = False) -> Label:
        """Best of 16 positions around ``anchor``; ``prefer`` is a paper direction to favour."""
        best: tuple[float, Label] | None = None
        lab0 = layout(text, 0.0, 0.0, size, "middle", "middle")
        w = lab0.box[2] - lab0.box[0]
        h = lab0.box[3] - lab0.box[1]
        lab_tree = shapely.STRtree(self.labels) if self.labels else None
        obs_tree = shapely.STRtree(self.obstacles) if self.obstacles else None
        for ring, dist in enumerate((gap, gap + 2.0, gap + 5.0)):
            for k in range(16):
                ang = 2 * math.pi * k / 16
                cx, cy = math.cos(ang), math.sin(ang)
                # centre the box so that its nearest edge is ``dist`` from the anchor
                rx = dist + w / 2 * abs(cx) ** 0.5
                ry = dist + h / 2 * abs(cy) ** 0.5
                x = anchor[0] + cx * rx
                y = anchor[1] + cy * ry
                lab = layout(text, x, y, size, "middle", "middle")
                poly = box_poly(lab.box, 0.3)
                cost = ring * 4.0
                if lab_tree is not None:
                    hits = lab_tree.query(poly, predicate="intersects")
                    cost += 1000.0 * len(hits)
                if obs_tree is not None and not hard_only:
                    for i in obs_tree.query(poly, predicate="intersects"):
                        g = self.obstacles[int(i)]
                        inter = g.intersection(poly)
                        cost += 3.0 + (inter.length if g.geom_type == "LineString" else 5.0 * inter.area)
                if prefer is not None:
                    cost += 1.5 * (1.0 - (cx * prefer[0] + cy * prefer[1]))
                if self.bounds is not None:
                    bx = self.bounds
                    if lab.box[0] < bx[0] or lab.box[1] < bx[1] or lab.box[2] > bx[2] or lab.box[3] > bx[3]:
                        cost += 50.0
                if best is None or cost < best[0] - 1e-9:
                    best = (cost, lab)
            if best is not None and best[0] < 1.0 + ring * 4.0:
                break
        assert best is not None
        self.labels.append(box_poly(best[1].box))
        return best[1]


def label_boxes(prims: Sequence[Prim]) -> list[tuple[float, float, float, float]]:
    return [p.label.box for p in prims if p.op == "text" and p.label is not None]


def rec_bbox(rec: Recording) -> tuple[float, float, float, float]:
    return rec.bbox()
