"""The drawing backend interface, the world-to-paper transform, and a recording backend.

Everything a renderer receives is in *paper millimetres*, x right, y down, as on
a sheet and in SVG.  World coordinates (metres of the mechanism, plan
millimetres with the pole at the origin) have y up; :class:`Transform` is the
only place the y axis is flipped.
"""

from __future__ import annotations

import math
from collections.abc import Iterable, Sequence
from dataclasses import dataclass, field
from typing import Protocol

from drawings.paper.text import Label, TextRun

Pt = tuple[float, float]


@dataclass(frozen=True, slots=True)
class Transform:
    """world -> paper: p = origin + scale · (x, −y)."""

    scale: float  # paper mm per world unit
    ox: float = 0.0
    oy: float = 0.0

    def __call__(self, x: float, y: float) -> Pt:
        return (self.ox + self.scale * x, self.oy - self.scale * y)

    def z(self, w: complex) -> Pt:
        """A complex world point."""
        return self(w.real, w.imag)

    def direction(self, dx: float, dy: float) -> Pt:
        """A world direction on paper (no translation, y flipped, unit length kept)."""
        return (dx, -dy)

    def angle(self, world_angle: float) -> float:
        """Paper angle (radians, y down) of a world angle (counter-clockwise)."""
        return -world_angle


#: A construction drawn at 1:1 in the panel's millimetres (y up, as the textbook draws it) put
#: on the paper (y down): the panels' one y-flip, ``PAPER(x, y)`` or ``PAPER.z(z)``.
PAPER = Transform(1.0)


@dataclass(frozen=True, slots=True)
class Style:
    stroke: str | None = "#000"
    width: float = 0.35  # mm
    fill: str | None = None
    dash: tuple[float, ...] = ()
    cls: str = ""


THICK = Style(width=0.7, cls="link")
MAIN = Style(width=0.5)
THIN = Style(width=0.25)
HAIR = Style(width=0.18, stroke="#555")
FILLED = Style(stroke=None, width=0.0, fill="#000")
#: A centre line (axis of a shaft, of symmetry): thin dash-dot.
CENTRE_LINE = Style(width=0.18, stroke="#333", dash=(6.0, 1.0, 1.0, 1.0), cls="axis")


class Backend(Protocol):
    def begin(self, gid: str, cls: str = "") -> None: ...
    def end(self) -> None: ...
    def line(self, p0: Pt, p1: Pt, style: Style, eid: str = "") -> None: ...
    def polyline(self, pts: Sequence[Pt], style: Style, eid: str = "") -> None: ...
    def polygon(self, pts: Sequence[Pt], style: Style, eid: str = "") -> None: ...
    def circle(self, c: Pt, r: float, style: Style, eid: str = "") -> None: ...
    def arc(self, c: Pt, r: float, a0: float, a1: float, style: Style, eid: str = "") -> None: ...
    def text(self, label: Label, cls: str = "", eid: str = "", fill: str = "#000") -> None: ...
    def hatch(self, p0: Pt, p1: Pt, side: int, style: Style, step: float = 2.5,
              length: float = 2.5, eid: str = "") -> None: ...


# --------------------------------------------------------------------------- recorded primitives


@dataclass(frozen=True, slots=True)
class Prim:
    """One drawn thing: ``op`` names the backend call; ``pts`` are its paper points."""

    op: str  # begin end line polyline polygon circle arc text hatch
    pts: tuple[Pt, ...] = ()
    style: Style | None = None
    r: float = 0.0
    a0: float = 0.0
    a1: float = 0.0
    label: Label | None = None
    eid: str = ""
    cls: str = ""
    side: int = 0
    step: float = 0.0
    length: float = 0.0
    fill: str = "#000"

    def moved(self, dx: float, dy: float) -> Prim:
        pts = tuple((x + dx, y + dy) for x, y in self.pts)
        lab = self.label
        if lab is not None:
            lab = Label(tuple(TextRun(t.x + dx, t.y + dy, t.text, t.size, t.font) for t in lab.runs),
                     (lab.box[0] + dx, lab.box[1] + dy, lab.box[2] + dx, lab.box[3] + dy), lab.plain)
        return Prim(self.op, pts, self.style, self.r, self.a0, self.a1, lab, self.eid, self.cls, self.side,
                    self.step, self.length, self.fill)

    def box(self) -> tuple[float, float, float, float] | None:
        """Paper bounding box including half the stroke width (None for group marks)."""
        if self.op in ("begin", "end"):
            return None
        if self.op == "text":
            assert self.label is not None
            return self.label.box
        hw = (self.style.width / 2 if self.style and self.style.stroke else 0.0)
        if self.op == "circle":
            (x, y), r = self.pts[0], self.r + hw
            return (x - r, y - r, x + r, y + r)
        pts = list(self.pts)
        if self.op == "arc":
            pts = arc_points(self.pts[0], self.r, self.a0, self.a1)
        if self.op == "hatch":
            pts = [p for seg in hatch_segments(self.pts[0], self.pts[1], self.side, self.step,
                                               self.length) for p in seg]
        xs = [p[0] for p in pts]
        ys = [p[1] for p in pts]
        return (min(xs) - hw, min(ys) - hw, max(xs) + hw, max(ys) + hw)


def arc_points(c: Pt, r: float, a0: float, a1: float, n: int = 24) -> list[Pt]:
    """Points along an arc from paper angle a0 to a1 (radians, y down)."""
    return [(c[0] + r * math.cos(a0 + (a1 - a0) * k / n), c[1] + r * math.sin(a0 + (a1 - a0) * k / n))
            for k in range(n + 1)]


#: The most strokes one hatched line gets (an A1 sheet's width at 0.4 mm): a guide of an
#: absurd length (a fuzzed file) is drawn, then refused as too big, without billions of strokes.
MAX_HATCH = 2000


def hatch_segments(p0: Pt, p1: Pt, side: int, step: float, length: float) -> list[tuple[Pt, Pt]]:
    """Short strokes at 45° along p0–p1 on ``side`` (+1 left of p0→p1 as seen on the sheet)."""
    dx, dy = p1[0] - p0[0], p1[1] - p0[1]
    L = math.hypot(dx, dy)
    if L == 0:
        return []
    ux, uy = dx / L, dy / L
    nx, ny = uy * side, -ux * side  # on a y-down sheet the left normal of (ux, uy) is (uy, −ux)
    k = length / math.sqrt(2)
    ex, ey = (nx - ux) * k, (ny - uy) * k
    count = max(1, int(min(L / step, MAX_HATCH)) + 1)
    if count > MAX_HATCH:  # a guide longer than any sheet: as many strokes as a sheet can show, spaced out
        step = L / (count - 1)
    gap = (L - (count - 1) * step) / 2
    out = []
    for i in range(count):
        t = gap + i * step
        x, y = p0[0] + ux * t, p0[1] + uy * t
        out.append(((x, y), (x + ex, y + ey)))
    return out


@dataclass(slots=True)
class Recording:
    """A backend that keeps what was drawn, for layout, tests and replay."""

    prims: list[Prim] = field(default_factory=list)

    def begin(self, gid: str, cls: str = "") -> None:
        self.prims.append(Prim("begin", eid=gid, cls=cls))

    def end(self) -> None:
        self.prims.append(Prim("end"))

    def line(self, p0: Pt, p1: Pt, style: Style, eid: str = "") -> None:
        self.prims.append(Prim("line", (p0, p1), style, eid=eid))

    def polyline(self, pts: Sequence[Pt], style: Style, eid: str = "") -> None:
        self.prims.append(Prim("polyline", tuple(pts), style, eid=eid))

    def polygon(self, pts: Sequence[Pt], style: Style, eid: str = "") -> None:
        self.prims.append(Prim("polygon", tuple(pts), style, eid=eid))

    def circle(self, c: Pt, r: float, style: Style, eid: str = "") -> None:
        self.prims.append(Prim("circle", (c,), style, r=r, eid=eid))

    def arc(self, c: Pt, r: float, a0: float, a1: float, style: Style, eid: str = "") -> None:
        self.prims.append(Prim("arc", (c,), style, r=r, a0=a0, a1=a1, eid=eid))

    def text(self, label: Label, cls: str = "", eid: str = "", fill: str = "#000") -> None:
        self.prims.append(Prim("text", (), None, label=label, eid=eid, cls=cls, fill=fill))

    def hatch(self, p0: Pt, p1: Pt, side: int, style: Style, step: float = 2.5,
              length: float = 2.5, eid: str = "") -> None:
        self.prims.append(Prim("hatch", (p0, p1), style, side=side, step=step, length=length, eid=eid))

    # ---- queries

    def bbox(self) -> tuple[float, float, float, float]:
        boxes = [b for b in (p.box() for p in self.prims) if b is not None]
        if not boxes:
            return (0.0, 0.0, 0.0, 0.0)
        return (min(b[0] for b in boxes), min(b[1] for b in boxes),
                max(b[2] for b in boxes), max(b[3] for b in boxes))

    def texts(self) -> list[Prim]:
        return [p for p in self.prims if p.op == "text"]

    def ops(self) -> dict[str, int]:
        out: dict[str, int] = {}
        for p in self.prims:
            out[p.op] = out.get(p.op, 0) + 1
        return out

    def by_id(self, eid: str) -> list[Prim]:
        return [p for p in self.prims if p.eid == eid]

    def moved(self, dx: float, dy: float) -> Recording:
        return Recording([p.moved(dx, dy) for p in self.prims])


def replay(prims: Iterable[Prim], backend: Backend) -> None:
    """Draw recorded primitives onto another backend."""
    for p in prims:
        op = p.op
        if op == "begin":
            backend.begin(p.eid, p.cls)
        elif op == "end":
            backend.end()
        elif op == "line":
            assert p.style is not None
            backend.line(p.pts[0], p.pts[1], p.style, p.eid)
        elif op == "polyline":
            assert p.style is not None
            backend.polyline(p.pts, p.style, p.eid)
        elif op == "polygon":
            assert p.style is not None
            backend.polygon(p.pts, p.style, p.eid)
        elif op == "circle":
            assert p.style is not None
            backend.circle(p.pts[0], p.r, p.style, p.eid)
        elif op == "arc":
            assert p.style is not None
            backend.arc(p.pts[0], p.r, p.a0, p.a1, p.style, p.eid)
        elif op == "text":
            assert p.label is not None
            backend.text(p.label, p.cls, p.eid, p.fill)
        elif op == "hatch":
            assert p.style is not None
            backend.hatch(p.pts[0], p.pts[1], p.side, p.style, p.step, p.length, p.eid)
        else:  # pragma: no cover
            raise ValueError(op)
