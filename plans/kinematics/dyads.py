"""The construction of the velocity and acceleration plans, each dyad written once, over arrays.

What the draftsman does for each class-II Assur group (RRR, RRP, RPR, PRP, RPP) is one
function here, run over an array of cases at once: the positions of a cycle (the plans of
360 positions built together) or the drawings of a Monte Carlo.  One position drawn
exactly runs the same functions on Python numbers (a :class:`Scheme` of one position:
numpy's cost per call would be all of its cost; see :mod:`plans.kinematics.cases`).
The hand that draws is a :class:`Pencil`:

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
from typing import TYPE_CHECKING, Any, Protocol

import numpy as np

from plans.errors import Locked, Said
from plans.kinematics.cases import Arrays, Numbers, cross, unit
from plans.kinematics.exact import Kinematics
from plans.kinematics.plan import Step
from plans.kinematics.structure import Group
from plans.phrases import Phrase, phrase
from plans.scene.model import Joint
from plans.tolerances import COINCIDE_REL, EXACT_ZERO_REL, LOCK_SIN, NEAR_PARALLEL_SIN
from plans.units import clean

#: Values over the cases: numpy arrays (complex plane vectors, real lengths and rates), or
#: Python ``complex`` and ``float`` at one position (see :mod:`plans.kinematics.cases`).
if TYPE_CHECKING:  # numpy.typing only for the checker: it costs a command's start a millisecond
    from numpy.typing import NDArray

    C = NDArray[np.complex128] | Any
    R = NDArray[np.float64] | Any
    #: One construction line: a point it passes through and its unit direction.
    Line = tuple[C, C]

__all__ = ["Builder", "Mixed", "Pencil", "PerfectPencil", "Scheme", "cross", "unit"]

_FIELDS = ("rot", "r0", "omega", "v0", "eps", "a0")


class Scheme:
    """The scheme at the selected positions (the drawing of the mechanism the plans are
    built on), read from the exact positions, plus the exact rates for each reading.

    ``ks`` selects positions of ``kin`` (a slice or a list: every value an array over them);
    one position as an ``int`` holds Python numbers instead (:attr:`xp` is
    :class:`plans.kinematics.cases.Numbers`): one position pays no numpy call per step."""

    def __init__(self, kin: Kinematics, ks: Any = slice(None)) -> None:
        self.kin = kin
        self.scene = kin.scene
        self.ks = ks
        self.one = type(ks) is int
        self.xp: type[Arrays] | type[Numbers] = Numbers if self.one else Arrays
        self._pos: dict[tuple[int, str], C] = {}
        self._slides: dict[str, tuple[Any, Any]] = {}
        self.joint_points = {jt.point for jt in kin.scene.joints}
        self._rated: list[tuple[int, float, str, str]] | None = None
        if self.one:
            self._numbers(kin, ks)
            return
        self.phi = np.asarray(kin.phi_deg, float)[ks]
        mo = kin.motion.items()
        self.r0 = {lid: np.asarray(m.r0)[ks] for lid, m in mo}
        self.rot = {lid: np.asarray(m.rot)[ks] for lid, m in mo}
        self.w = {lid: np.asarray(m.omega)[ks] for lid, m in mo if m.omega is not None}
        self.e = {lid: np.asarray(m.eps)[ks] for lid, m in mo if m.eps is not None}
        self.v0 = {lid: np.asarray(m.v0)[ks] for lid, m in mo if m.v0 is not None}
        self.a0 = {lid: np.asarray(m.a0)[ks] for lid, m in mo if m.a0 is not None}

    def _numbers(self, kin: Kinematics, k: int) -> None:
        """Position ``k`` as Python numbers (a motion held as numbers stays numbers)."""
        self.phi = float(kin.phi_deg[k])
        R0, ROT, W, E, V0, A0 = self.r0, self.rot, self.w, self.e, self.v0, self.a0 = {}, {}, {}, {}, {}, {}
        nd = np.ndarray
        for lid, m in kin.motion.items():
            raw = getattr(m, "raw", None)
            rot, r0, w, v0, e, a0 = raw() if raw is not None else [getattr(m, f) for f in _FIELDS]
            ROT[lid] = rot.item(k) if type(rot) is nd else rot
            R0[lid] = r0.item(k) if type(r0) is nd else r0
            if w is not None:
                W[lid] = w.item(k) if type(w) is nd else w
            if v0 is not None:
                V0[lid] = v0.item(k) if type(v0) is nd else v0
            if e is not None:
                E[lid] = e.item(k) if type(e) is nd else e
            if a0 is not None:
                A0[lid] = a0.item(k) if type(a0) is nd else a0

    def phi_at(self, k: int) -> float:
        """The crank angle of case ``k`` (degrees)."""
        return self.phi if self.one else float(self.phi[k])

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

    def rated(self) -> list[tuple[int, float, str, str]]:
        """Each link whose ω and ε are read: (link, the length they are referred to, the
        names of its ω and ε readings), by link number."""
        if self._rated is None:
            crank = crank_length(self)
            self._rated = [(lid, abs(link.length or crank), f"omega_{lid}", f"eps_{lid}")
                           for lid, link in sorted(self.scene.links.items())]
        return self._rated

    # exact rates of a point fixed to ``link`` at global position X
    def v(self, link: int, X: C) -> C:
        return self.v0[link] + 1j * self.w[link] * (X - self.r0[link])

    def a(self, link: int, X: C) -> C:
        w = self.w[link]
        return self.a0[link] + (1j * self.e[link] - w * w) * (X - self.r0[link])

    def slide(self, jt: Joint) -> tuple[R, R]:
        got = self._slides.get(jt.name)
        if got is None:
            sd, sdd = self.kin.slides[jt.name]
            if self.one:
                k = self.ks
                got = (float(sd[k]), 0.0 if sdd is None else float(sdd[k]))
            else:
                sdd = np.zeros(np.shape(sd)) if sdd is None else sdd
                got = (np.asarray(sd)[self.ks], np.asarray(sdd)[self.ks])
            self._slides[jt.name] = got
        return got


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
        xp = b.xp
        (p1, d1), (p2, d2) = l1, l2
        s = cross(d1, d2)
        sin = abs(s)
        if b.one and sin > NEAR_PARALLEL_SIN:
            return p1 + cross(p2 - p1, d2) / s * d1
        near = sin <= NEAR_PARALLEL_SIN
        if not xp.any(near):
            return p1 + cross(p2 - p1, d2) / s * d1
        if xp.scalar:
            extent = max(abs(p1), abs(p2), b.size, 1e-300)
        else:
            extent = np.maximum.reduce([np.abs(p1), np.abs(p2), b.size, np.full(np.shape(s), 1e-300)])
        gap = abs(cross(d1, p2 - p1))
        locked = near & (sin <= LOCK_SIN) & (gap > COINCIDE_REL * extent)
        if xp.any(locked):
            raise Locked(Said("kd_lines_kind_plan", v=b.line_labels[-2], v2=b.line_labels[-1], kind=b.kind), group=f"{group.kind} {group.name}",
                         point=point, phi_deg=b.snap.phi_at(xp.argmax(locked)))
        b.degenerate.append((out, near, sin))
        t = cross(p2 - p1, d2) / xp.where(near, 1.0, s)
        return xp.where(near, exact_xy, p1 + t * d1)


class Mixed(Exception):
    """A label that differs between the positions built together (build them one by one)."""


class Builder:
    """Accumulates one plan over all cases: points, segments, construction lines, readings
    (arrays) and, when asked, the protocol."""

    def __init__(self, snap: Scheme, kind: str, scale: float, pencil: Pencil, protocol: bool = False) -> None:
        self.snap, self.kind, self.mu, self.pencil, self.protocol = snap, kind, scale, pencil, protocol
        # Python numbers at one position drawn exactly; arrays wherever a pencil draws many cases
        xp = self.xp = snap.xp if isinstance(pencil, PerfectPencil) else Arrays
        self.one = xp.scalar  # one position in Python numbers, the perfect pencil
        self.sym = "v" if kind == "velocity" else "a"
        self.unit = "m/s" if kind == "velocity" else "m/s^2"
        self.pole = "p_v" if kind == "velocity" else "p_a"
        n = 1 if snap.one else np.size(snap.phi)
        self.zero = xp.zeros(n, complex)
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
        self.size: Any = xp.zeros(n)  # the plan's extent so far (mm from the pole)
        self._dust: tuple[Any, Any] | None = None
        attach = getattr(pencil, "attach", None)
        if attach is not None:  # a pencil that makes a student's slip looks at the plan it draws
            attach(self)

    def s(self, x: Any) -> Any:
        """One case's value, for the protocol's sentences."""
        return self.xp.first(x)

    # -- points and images
    def add(self, label: str, xy: C) -> None:
        if label not in self.pts:
            self.order.append(label)
        self.pts[label] = xy
        if self.one:
            r = abs(xy)
            if r > self.size:
                self.size = r
        else:
            self.size = np.maximum(self.size, abs(xy))

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
        ref, dust = self.ref, self._dust
        # rounding dust at a dead centre (1e-15 of the plan) is read as zero, as on paper
        if dust is None or dust[0] is not ref:
            dust = self._dust = (ref, COINCIDE_REL * self.xp.maximum(ref * self.mu, 1e-300))
        exact = abs(exact)
        if self.one:  # the same reading in Python numbers (the perfect pencil reads what is drawn)
            length = abs(self.pts[end] - self.pts[start])
            if length <= dust[1]:
                length = 0.0
            if exact <= EXACT_ZERO_REL * ref:
                exact = 0.0
        else:
            xp = self.xp
            length = self.pencil.read(abs(self.pts[end] - self.pts[start]))
            small = length <= dust[1]
            if xp.any(small):
                length = np.where(small, 0.0, length)
            small = exact <= EXACT_ZERO_REL * ref
            if xp.any(small):
                exact = np.where(small, 0.0, exact)
        value = length / self.mu
        self.segments.append((start, end, kind, label, length, value))
        self.readings.append((label, f"{start} {end}", length, self.mu, value, exact, self.unit, ref, True))

    def step(self, op: str, inputs: tuple[str, ...], output: str, words: Callable[[], Phrase]) -> None:
        """A step of the protocol; its sentence is written only when a protocol is asked for."""
        if self.protocol:
            self.steps.append(Step.of(op, inputs, output, words()))

    def line(self, through: C, direction: Any, span: Any, label: str) -> Line:
        u = self.pencil.line(direction, span)
        self.lines.append((through, u, label))
        self.line_labels.append(label)
        return through, u


def lab(name: str) -> str:
    return name.lower()


# --------------------------------------------------------------------------- shared steps


def meet(b: Builder, g: Group, l1: Line, l2: Line, out: str, exact_xy: C, point: str,
         links: tuple[int, ...]) -> C:
    """The point ``out`` where two construction lines meet, labelled as ``point`` of ``links``."""
    xy = b.pencil.cut(b, l1, l2, out, exact_xy, g, point)
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
               key=lambda xy: abs(b.s(xy[1] - xy[0])))
    return b.factor[link] * (ends[1] - ends[0])


def link_points(b: Builder, link: int) -> None:
    """Similarity theorem: images of the link's other named points."""
    snap = b.snap
    joints = snap.joint_points
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
        b.add(lb, xy if b.one else b.pencil.mark(xy, lambda link=link: image_span(b, link), joint=name in joints))
        b.labels[(link, name)] = lb
        if b.protocol:
            ref = b.anchor[link][0]
            b.step("similarity", (ref,), lb, partial(phrase, "similarity", lb=lb, link=link, name=name, ref=ref))
        exact = abs(snap.v(link, X)) if b.sym == "v" else abs(snap.a(link, X))
        b.seg(b.pole, lb, "absolute", f"{b.sym}_{name}", exact)


def read_rates(b: Builder) -> None:
    """ω (or ε) of every moving link read off the plan: a segment over the link's length
    at μ, with the sense the plan shows; a block turns with its guide; the crank's is given."""
    snap = b.snap
    d = snap.scene.driver
    xp = b.xp
    n = 1 if snap.one else np.size(snap.phi)
    b.rates[snap.scene.frame] = xp.zeros(n)

    def rate(lid: int) -> R:
        if lid not in b.rates:
            how = b.rate.get(lid)
            if isinstance(how, tuple):
                start, end, length = how
                sense = xp.sign(b.factor[lid].imag)
                b.rates[lid] = sense * b.pencil.read(abs(b.pts[end] - b.pts[start])) / (b.mu * length)
            elif how is not None:
                b.rates[lid] = rate(how)
            else:  # the crank: ω1 and ε1 are data
                b.rates[lid] = xp.full(n, float(d.omega if b.sym == "v" else d.eps))
        return b.rates[lid]

    velocity = b.sym == "v"
    exacts = snap.w if velocity else snap.e
    unit_ = "rad/s" if velocity else "rad/s^2"
    for lid, size, omega, eps in snap.rated():
        if lid not in b.factor:
            continue
        drawn = isinstance(b.rate.get(lid), tuple)
        value = rate(lid)
        exact = exacts[lid]
        q = omega if velocity else eps
        ref = b.ref / size
        if b.one:
            floor = EXACT_ZERO_REL * ref
            value = 0.0 if abs(value) <= floor else value
            exact = 0.0 if abs(exact) <= floor else exact
        else:
            value, exact = _dust(value, EXACT_ZERO_REL * ref), _dust(exact, EXACT_ZERO_REL * ref)
        b.readings.append((q, None, None, None, value, exact, unit_, ref, drawn))


def _dust(x: Any, floor: Any) -> Any:
    """x with what is not above ``floor`` read as zero (arrays)."""
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
            xp = b.xp
            apart = abs(b.pts[lb] - xy) > COINCIDE_REL * xp.maximum(1.0, abs(xy))
            if xp.any(apart) and not xp.all(apart) and b.pencil.exact:
                raise Mixed(lb)
            if xp.any(apart):
                lb = f"{lb}{link}"
        b.add(lb, xy)
        b.labels[(link, name)] = lb
    return lb


def coincident(b: Builder, link: int, name: str, X: C) -> tuple[str, C]:
    """Image of the point of ``link`` that coincides with X now (e.g. B on a moving guide)."""
    if link == b.snap.scene.frame:
        return b.pole, b.zero
    lb = f"{lab(name)}{link}"
    xy = b.image_at(link, X)
    if not b.one:
        xy = b.pencil.mark(xy, lambda: image_span(b, link))
    b.add(lb, xy)
    b.step("similarity", (b.anchor[link][0],), lb,
           lambda: phrase("coincident", lb=lb, link=link, name=name))
    return lb, xy


def lay_normal(b: Builder, vr: Any, link: int, frm: str, frm_xy: np.ndarray, P: np.ndarray,
            X: np.ndarray, Pn: str, Xn: str) -> tuple[str, np.ndarray]:
    """Lay off a_XP^n = ω²·l toward P from the image of P on the acceleration plan; ω read off
    the velocity plan (``vr.omega``)."""
    w = vr.omega(link)
    ln = abs(P - X)
    lb = f"n_{Xn}{Pn}"
    vec = b.pencil.vector(b.mu * w * w * ln, P - X, ln, lb)
    b.add(lb, frm_xy + vec)
    b.step("lay off", (frm,), lb, lambda: phrase(
        "a_normal", X=Xn, P=Pn, v=clean(abs(b.s(w * ln)), b.s(vr.vb.ref)), l=b.s(ln), an=clean(b.s(w * w * ln), b.s(b.ref)),
        mm=abs(b.s(vec)), frm=frm))
    b.seg(frm, lb, "normal", f"a_{Xn}{Pn}^n", b.snap.w[link] ** 2 * ln)
    return lb, frm_xy + vec


def lay_coriolis(b: Builder, vr: Any, guide_link: int, v_rel: np.ndarray, frm: str, frm_xy: np.ndarray,
                 label: str, exact: np.ndarray) -> tuple[str, np.ndarray]:
    """Lay off a^k = 2 ω × v_rel (v_rel turned 90° in the sense of ω) from ``frm``; ω and
    v_rel are read off the velocity plan."""
    w = vr.omega(guide_link)
    muv = vr.vb.mu
    v_read = b.pencil.read(abs(v_rel) * muv) / muv
    lb = f"k_{label}"
    vec = b.pencil.vector(b.mu * 2 * abs(w) * v_read, 1j * b.xp.sign(w) * v_rel, 0.0, lb)
    b.add(lb, frm_xy + vec)
    b.step("lay off", (frm,), lb, lambda: phrase(
        "a_coriolis", label=label, g=guide_link, w=clean(abs(b.s(w)), abs(b.snap.scene.driver.omega)), v=clean(abs(b.s(v_rel)), b.s(vr.vb.ref)),
        ak=clean(abs(b.s(2 * w * v_rel)), b.s(b.ref)), mm=abs(b.s(vec))))
    b.seg(frm, lb, "coriolis", f"a^k_{label}", exact)
    return lb, frm_xy + vec
