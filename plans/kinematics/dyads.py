"""The construction of the velocity and acceleration plans, each dyad written once, over arrays.

What the draftsman does for each class-II Assur group (RRR, RRP, RPR, PRP, RPP) is one
function here, run over an array of cases at once: the positions of a cycle (the plans of
360 positions built together) or the drawings of a Monte Carlo.  The hand that draws is
a :class:`Pencil`:

* :class:`PerfectPencil` draws exactly: closed-form line intersections, the exact point
  where two construction lines are (nearly) parallel, :class:`plans.errors.Locked` where
  they are parallel and apart.  These are the plans (:mod:`plans.kinematics.construction`).
* a noisy pencil (:class:`plans.accuracy.draftsman.NoisyPencil`) marks, lays off, rules and
  reads with a pencil's and a protractor's error: the hand-drawing Monte Carlo.
* a linearised pencil (:class:`plans.check.tolerance.LinearisedPencil`) makes each drawing
  error alone and small, one case per error: the checker's tolerance propagation.

Angular velocities, normal and Coriolis components are read off the plan already drawn,
never taken from the exact analysis; the exact analysis gives only each reading's exact
value.  The protocol (the sentences of each step) is written only when asked for (one
position, for a printed or drawn plan).

Plan coordinates are complex numbers in plan mm, pole at 0.  A link's image is held as one
known image point plus its *similarity factor* f = (image of Y − image of X)/(Y − X):
μv·iω on the velocity plan, μa·(iε − ω²) on the acceleration plan.
"""

from __future__ import annotations

from collections.abc import Callable
from functools import partial
from typing import Any, Protocol

import numpy as np
from numpy.typing import NDArray

from plans.errors import Locked
from plans.kinematics.exact import Kinematics
from plans.kinematics.plan import Step
from plans.kinematics.structure import Group
from plans.lines import meet as intersection
from plans.phrases import Phrase, phrase
from plans.scene.model import Joint
from plans.tolerances import COINCIDE_REL, LOCK_SIN, NEAR_PARALLEL_SIN

C = NDArray[np.complex128]
R = NDArray[np.float64]
#: One construction line: a point it passes through and its unit direction (arrays).
Line = tuple[C, C]


def cross(a: Any, b: Any) -> Any:
    return (np.conjugate(a) * b).imag


def unit(z: Any) -> Any:
    """z / |z|, and 1 where z = 0."""
    mag = np.abs(z)
    if np.all(mag > 0):
        return z / mag
    return np.where(mag > 0, z / np.where(mag > 0, mag, 1.0), 1.0 + 0j)


class Scheme:
    """The scheme at the selected positions (the drawing of the mechanism the plans are
    built on), read from the exact positions, plus the exact rates for each reading."""

    def __init__(self, kin: Kinematics, ks: Any = slice(None)) -> None:
        self.kin = kin
        self.scene = kin.scene
        self.phi = np.asarray(kin.phi_deg, float)[ks]
        mo = kin.motion.items()
        self.r0 = {lid: np.asarray(m.r0)[ks] for lid, m in mo}
        self.rot = {lid: np.asarray(m.rot)[ks] for lid, m in mo}
        self.w = {lid: np.asarray(m.omega)[ks] for lid, m in mo if m.omega is not None}
        self.e = {lid: np.asarray(m.eps)[ks] for lid, m in mo if m.eps is not None}
        self.v0 = {lid: np.asarray(m.v0)[ks] for lid, m in mo if m.v0 is not None}
        self.a0 = {lid: np.asarray(m.a0)[ks] for lid, m in mo if m.a0 is not None}
        self.ks = ks
        self._pos: dict[tuple[int, str], C] = {}

    def local(self, link: int, name: str) -> complex:
        if link == self.scene.frame:
            return self.scene.frame_points[name]
        return self.scene.links[link].points[name]

    def pos(self, link: int, name: str) -> C:
        key = (link, name)
        got = self._pos.get(key)
        if got is None:
            got = self._pos[key] = self.r0[link] + self.rot[link] * self.local(link, name)
        return got

    def guide(self, jt: Joint) -> tuple[C, Any]:
        """Direction of a guide now, and the length it is transferred over on the scheme
        (0 for the frame's: drawn with the protractor alone)."""
        g = jt.guide
        assert g is not None
        link = self.scene.links.get(g.link)
        span = abs(link.length) if link is not None and link.length else 0.0
        return self.rot[g.link] * g.direction, span

    # exact rates of a point fixed to ``link`` at global position X
    def v(self, link: int, X: C) -> C:
        return self.v0[link] + 1j * self.w[link] * (X - self.r0[link])

    def a(self, link: int, X: C) -> C:
        return self.a0[link] + (1j * self.e[link] - self.w[link] ** 2) * (X - self.r0[link])

    def slide(self, jt: Joint) -> tuple[R, R]:
        sd, sdd = self.kin.slides[jt.name]
        sdd = np.zeros(np.shape(sd)) if sdd is None else sdd
        return np.asarray(sd)[self.ks], np.asarray(sdd)[self.ks]


class Pencil(Protocol):
    """The hand that draws.  Lengths in plan mm, directions as complex numbers; ``span``
    is the length (m) on the scheme a direction is transferred over (0: protractor alone)."""

    exact: bool

    def vector(self, length: Any, direction: Any, span: Any, out: str) -> C: ...  # a vector laid off to ``out``
    def line(self, direction: Any, span: Any) -> C: ...  # unit direction of a drawn line
    # a point found by similarity and marked; ``along()``: the image of the link it divides
    def mark(self, z: C, along: Any = None, joint: bool = False) -> C: ...
    def read(self, length: Any) -> Any: ...  # a length measured with the ruler

    def cut(self, b: Builder, l1: Line, l2: Line, out: str, exact_xy: C, group: Group,
            point: str) -> C: ...  # two lines intersected


class PerfectPencil:
    """Draws exactly; the draftsman's answer (the exact point) where two lines are parallel."""

    exact = True

    def vector(self, length: Any, direction: Any, span: Any, out: str) -> C:
        return length * unit(direction)

    def line(self, direction: Any, span: Any) -> C:
        return unit(direction)

    def mark(self, z: C, along: Any = None, joint: bool = False) -> C:
        return z

    def read(self, length: Any) -> Any:
        return length

    def cut(self, b: Builder, l1: Line, l2: Line, out: str, exact_xy: C, group: Group, point: str) -> C:
        (p1, d1), (p2, d2) = l1, l2
        s = cross(d1, d2)
        near = np.abs(s) <= NEAR_PARALLEL_SIN
        if near.any():
            extent = np.maximum.reduce([np.abs(p1), np.abs(p2), b.size, np.full(np.shape(s), 1e-300)])
            gap = np.abs(cross(d1, p2 - p1))
            locked = near & (np.abs(s) <= LOCK_SIN) & (gap > COINCIDE_REL * extent)
            if locked.any():
                k = int(np.argmax(locked))
                raise Locked(f"the lines {b.line_labels[-2]} and {b.line_labels[-1]} of the "
                             f"{b.kind} plan are parallel and apart",
                             group=f"{group.kind} {group.name}", point=point, phi_deg=float(b.snap.phi[k]))
            b.degenerate.append((out, near, np.abs(s)))
        if not near.any():
            return intersection(p1, d1, p2, d2, s)
        return np.where(near, exact_xy, intersection(p1, d1, p2, d2, np.where(near, 1.0, s)))


class Mixed(Exception):
    """A label that differs between the positions built together (build them one by one)."""


class Builder:
    """Accumulates one plan over all cases: points, segments, construction lines, readings
    (arrays) and, when asked, the protocol."""

    def __init__(self, snap: Scheme, kind: str, scale: float, pencil: Pencil, protocol: bool = False) -> None:
        self.snap, self.kind, self.mu, self.pencil, self.protocol = snap, kind, scale, pencil, protocol
        self.sym = "v" if kind == "velocity" else "a"
        self.unit = "m/s" if kind == "velocity" else "m/s^2"
        self.pole = "p_v" if kind == "velocity" else "p_a"
        n = np.size(snap.phi)
        self.zero = np.zeros(n, complex)
        self.pts: dict[str, C] = {self.pole: self.zero}
        self.order: list[str] = [self.pole]
        self.segments: list[tuple[str, str, str, str, R, R]] = []  # start, end, kind, label, mm, value
        self.lines: list[tuple[C, C, str]] = []
        self.line_labels: list[str] = []
        self.steps: list[Step] = []
        # quantity, segment, mm, scale, value, exact, unit, ref, drawn (read off the drawing, not a datum)
        self.readings: list[tuple[str, str | None, R | None, float | None, R, R, str, R, bool]] = []
        self.degenerate: list[tuple[str, Any, R]] = []
        self.factor: dict[int, C] = {snap.scene.frame: self.zero}
        self.anchor: dict[int, tuple[str, C]] = {snap.scene.frame: (self.pole, self.zero)}
        self.ref_pos: dict[int, C] = {snap.scene.frame: self.zero}
        self.labels: dict[tuple[int, str], str] = {}
        #: how each link's ω (ε) is read: (start, end, length) of a segment, or the link it turns with
        self.rate: dict[int, tuple[str, str, Any] | int] = {}
        self.rates: dict[int, R] = {}  # ω (ε) of each link as read off this plan
        self.ref: Any = 0.0  # the known vector's value: set when it is laid off
        self.size: Any = np.zeros(n)  # the plan's extent so far (mm from the pole)
        self._dust: tuple[Any, Any] | None = None

    @staticmethod
    def s(x: Any) -> Any:
        """One case's value, for the protocol's sentences."""
        a = np.ravel(x)
        return complex(a[0]) if np.iscomplexobj(a) else float(a[0])

    # -- points and images
    def add(self, label: str, xy: C) -> None:
        if label not in self.pts:
            self.order.append(label)
        self.pts[label] = xy
        self.size = np.maximum(self.size, np.abs(xy))

    def image(self, link: int, name: str) -> C:
        """Image of point ``name`` of ``link`` by the similarity theorem."""
        lab = self.labels.get((link, name))
        if lab is not None:
            return self.pts[lab]
        return self.image_at(link, self.snap.pos(link, name))

    def image_at(self, link: int, X: C) -> C:
        return self.anchor[link][1] + self.factor[link] * (X - self.ref_pos[link])

    def set_link(self, link: int, ref_label: str, ref_pos: C, factor: C) -> None:
        self.anchor[link] = (ref_label, self.pts[ref_label])
        self.ref_pos[link] = ref_pos
        self.factor[link] = factor

    def seg(self, start: str, end: str, kind: str, label: str, exact: Any) -> None:
        length = self.pencil.read(np.abs(self.pts[end] - self.pts[start]))
        # rounding dust at a dead centre (1e-15 of the plan) is read as zero, as on paper
        if self._dust is None or self._dust[0] is not self.ref:
            self._dust = (self.ref, COINCIDE_REL * np.maximum(self.ref * self.mu, 1e-300))
        dust = length <= self._dust[1]
        if dust.any():
            length = np.where(dust, 0.0, length)
        exact = np.abs(exact)
        small = exact <= 1e-12 * self.ref
        if np.any(small):
            exact = np.where(small, 0.0, exact)
        value = length / self.mu
        self.segments.append((start, end, kind, label, length, value))
        self.readings.append((label, f"{start} {end}", length, self.mu, value, exact, self.unit, self.ref, True))

    def step(self, op: str, inputs: tuple[str, ...], output: str, words: Callable[[], Phrase]) -> None:
        """A step of the protocol; its sentence is written only when a protocol is asked for."""
        if self.protocol:
            self.steps.append(Step.of(op, inputs, output, words()))

    def line(self, through: C, direction: Any, span: Any, label: str) -> Line:
        u = self.pencil.line(direction, span)
        self.lines.append((through, u, label))
        self.line_labels.append(label)
        return through, u

    def intersect(self, l1: Line, l2: Line, out: str, exact_xy: C, group: Group, point: str) -> C:
        return self.pencil.cut(self, l1, l2, out, exact_xy, group, point)


def lab(name: str) -> str:
    return name.lower()


# --------------------------------------------------------------------------- shared steps


def meet(b: Builder, g: Group, l1: Line, l2: Line, out: str, exact_xy: C, point: str,
         links: tuple[int, ...]) -> C:
    """The point ``out`` where two construction lines meet, labelled as ``point`` of ``links``."""
    xy = b.intersect(l1, l2, out, exact_xy, g, point)
    b.add(out, xy)
    for lk in links:
        b.labels[(lk, point)] = out
    return xy


def image_span(b: Builder, link: int) -> C:
    """The link's image between the two of its points drawn so far that lie farthest apart
    on the scheme (a point found by similarity divides it)."""
    snap = b.snap
    drawn = [snap.pos(link, name) for name in snap.scene.links[link].points
             if b.labels.get((link, name)) not in (None, b.pole) or name in snap.scene.frame_points]
    if link in b.ref_pos:  # the point the link's image is anchored at (a3 on the rocker)
        drawn.append(b.ref_pos[link])
    if len(drawn) < 2:
        return b.factor[link]
    ends = max(((x, y) for ix, x in enumerate(drawn) for y in drawn[ix + 1:]),
               key=lambda xy: float(np.abs(np.ravel(xy[1] - xy[0])[0])))
    return b.factor[link] * (ends[1] - ends[0])


def link_points(b: Builder, link: int) -> None:
    """Similarity theorem: images of the link's other named points."""
    snap = b.snap
    joints = {jt.point for jt in snap.scene.joints}
    for name in snap.scene.links[link].points:
        if (link, name) in b.labels:
            continue
        if name in snap.scene.frame_points:  # a pivot on the frame: its image is the pole
            b.labels[(link, name)] = b.pole
            continue
        lb = lab(name)
        if lb in b.pts:  # the same point through another link (a shared joint)
            b.labels[(link, name)] = lb
            continue
        X = snap.pos(link, name)
        xy = b.image(link, name)
        b.add(lb, b.pencil.mark(xy, lambda link=link: image_span(b, link), joint=name in joints))
        b.labels[(link, name)] = lb
        ref = b.anchor[link][0]
        b.step("similarity", (ref,), lb, partial(phrase, "similarity", lb=lb, link=link, name=name, ref=ref))
        exact = np.abs(snap.v(link, X)) if b.sym == "v" else np.abs(snap.a(link, X))
        b.seg(b.pole, lb, "absolute", f"{b.sym}_{name}", exact)


def read_rates(b: Builder) -> None:
    """ω (or ε) of every moving link read off the plan: a segment over the link's length
    at μ, with the sense the plan shows; a block turns with its guide; the crank's is given."""
    snap = b.snap
    d = snap.scene.driver
    n = np.size(snap.phi)
    b.rates[snap.scene.frame] = np.zeros(n)

    def rate(lid: int) -> R:
        if lid not in b.rates:
            how = b.rate.get(lid)
            if isinstance(how, tuple):
                start, end, length = how
                sense = np.sign(b.factor[lid].imag)
                b.rates[lid] = sense * b.pencil.read(np.abs(b.pts[end] - b.pts[start])) / (b.mu * length)
            elif how is not None:
                b.rates[lid] = rate(how)
            else:  # the crank: ω1 and ε1 are data
                b.rates[lid] = np.full(n, float(d.omega if b.sym == "v" else d.eps))
        return b.rates[lid]

    for lid in sorted(snap.scene.links):
        if lid not in b.factor:
            continue
        drawn = isinstance(b.rate.get(lid), tuple)
        value = rate(lid)
        exact = snap.w[lid] if b.sym == "v" else snap.e[lid]
        q, unit_ = (f"omega_{lid}", "rad/s") if b.sym == "v" else (f"eps_{lid}", "rad/s^2")
        link = snap.scene.links[lid]
        size = abs(link.length) if link.length else crank_length(snap)
        ref = b.ref / size
        value, exact = _dust(value, 1e-12 * ref), _dust(exact, 1e-12 * ref)
        b.readings.append((q, None, None, None, value, exact, unit_, ref, drawn))


def _dust(x: Any, floor: Any) -> Any:
    """x with what is not above ``floor`` read as zero."""
    small = np.abs(x) <= floor
    return np.where(small, 0.0, x) if small.any() else x


def crank_length(snap: Scheme) -> float:
    d = snap.scene.driver
    return abs(snap.scene.links[d.link].points[snap.scene.links[d.link].axis[1]])


def rel_seg(b: Builder, start: str, end: str, P: str, Q: str, exact: Any) -> None:
    if start == b.pole:  # relative to a fixed point: the absolute vector already drawn
        return
    b.seg(start, end, "relative", f"{b.sym}_{Q}{P}", exact)


def ensure(b: Builder, link: int, name: str, xy: C) -> str:
    """Make sure the image of a known point is labelled on the plan."""
    lb = b.labels.get((link, name))
    if lb is None:
        if link == b.snap.scene.frame:
            return b.pole
        lb = lab(name)
        if lb in b.pts:
            apart = np.abs(b.pts[lb] - xy) > COINCIDE_REL * np.maximum(1.0, np.abs(xy))
            if apart.any() and not apart.all() and b.pencil.exact:
                raise Mixed(lb)
            if apart.any():
                lb = f"{lb}{link}"
        b.add(lb, xy)
        b.labels[(link, name)] = lb
    return lb


def coincident(b: Builder, link: int, name: str, X: C) -> tuple[str, C]:
    """Image of the point of ``link`` that coincides with X now (e.g. B on a moving guide)."""
    if link == b.snap.scene.frame:
        return b.pole, b.zero
    lb = f"{lab(name)}{link}"
    xy = b.pencil.mark(b.image_at(link, X), lambda: image_span(b, link))
    b.add(lb, xy)
    b.step("similarity", (b.anchor[link][0],), lb,
           lambda: phrase("coincident", lb=lb, link=link, name=name))
    return lb, xy


def plans_of(snap: Scheme, mv: float, ma: float | None, pencil: Pencil,
             protocol: bool = False) -> tuple[Builder, Builder | None]:
    """Both plans over the cases of ``snap`` (the acceleration plan when ``ma`` is given)."""
    from plans.kinematics import accelerations, velocities

    vb = velocities.velocity_plan(snap, mv, pencil, protocol)
    ab = accelerations.acceleration_plan(snap, ma, vb, pencil, protocol) if ma is not None else None
    return vb, ab
