"""Velocity and acceleration plans built as a draftsman builds them.

On the scheme drawn at the crank angle, the draftsman lays off the known
vectors from the pole, draws the two construction lines of each Assur group
(⟂ a link, ∥ a guide) through known plan points and intersects them (shapely
does the intersection), then finds further points by the similarity theorem.
Angular velocities, normal and Coriolis components are read off the plan
already drawn, never taken from the exact analysis; the exact analysis
(:mod:`plans.kinematics`) is used only to report each reading's error and as
the draftsman's answer where two construction lines are (nearly) parallel.

Plan coordinates are complex numbers in plan mm, pole at 0.  A link's image is
held as one known image point plus its *similarity factor*
f = (image of Y − image of X)/(Y − X): μv·iω on the velocity plan,
μa·(iε − ω²) on the acceleration plan.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import shapely

from plans.errors import Locked
from plans.kinematics.exact import Kinematics
from plans.kinematics.plan import ConstructionLine, Plan, PlanPoint, Segment, Step
from plans.kinematics.structure import Group
from plans.scene.model import Joint
from plans.tolerances import COINCIDE_REL, LOCK_SIN, NEAR_PARALLEL_SIN
from plans.units import clean, percent

_NICE = (1.0, 2.0, 2.5, 4.0, 5.0)  # round both ways: μ and K = 1/μ


def nice_scale(longest: float, target_mm: float = 100.0, mantissas: tuple[float, ...] = _NICE) -> float:
    """μ (mm per unit) with K = 1/μ a round number, so that ``longest`` is drawn as
    the longest vector not above ``target_mm`` (75–100 mm): how a draftsman picks it."""
    if not (longest > 0 and math.isfinite(longest)):
        return 1.0
    k_min = longest / target_mm  # K may not be smaller than this
    e = math.floor(math.log10(k_min))
    for m in mantissas + (10.0,):
        K = m * 10.0**e
        if K >= k_min * (1 - 1e-12):
            return 1.0 / K
    return 1.0 / (10.0 ** (e + 1))  # pragma: no cover


def cross(a: complex, b: complex) -> float:
    return (a.conjugate() * b).imag


@dataclass(frozen=True, slots=True)
class Reading:
    """A value read off a plan next to the exact value."""

    quantity: str  # "v_B", "omega_2", "a_BA^n", ...
    segment: str | None  # segment read ("p_v b") or None for derived values
    length_mm: float | None
    scale: float | None
    value: float  # read off the drawing (signed for ω, ε)
    exact: float
    unit: str
    ref: float  # size of the plan in this unit (the known vector), floor for relative errors

    @property
    def difference(self) -> float:
        return clean(self.value - self.exact, max(abs(self.exact), self.ref))

    @property
    def percent(self) -> float | None:
        """Signed difference, % of max(|exact|, ref); None where the exact value is zero."""
        return percent(self.value, self.exact, self.ref)

    @property
    def relative(self) -> float:
        """|difference| / max(|exact|, ref): a vanishing quantity (b on the pole) is
        compared with the size of the plan it is read from, not with zero."""
        den = max(abs(self.exact), self.ref)
        return abs(self.difference) / den if den > 0 else 0.0

    def to_json(self) -> dict:
        return {"quantity": self.quantity, "segment": self.segment, "length_mm": self.length_mm,
                "scale": self.scale, "value": self.value, "exact": self.exact, "unit": self.unit,
                "difference": self.difference, "relative": self.relative}


@dataclass(frozen=True, slots=True)
class PositionPlans:
    phi_deg: float
    velocity: Plan | None
    acceleration: Plan | None
    readings: tuple[Reading, ...]


# --------------------------------------------------------------------------- snapshot


class _Snapshot:
    """The scheme at one crank angle, read from the exact positions (the drawing of
    the mechanism the plans are built on), plus exact rates for the error report."""

    def __init__(self, kin: Kinematics, k: int) -> None:
        self.kin = kin
        self.scene = kin.scene
        self.k = k
        self.phi = float(kin.phi_deg[k])
        self.r0 = {lid: complex(m.r0[k]) for lid, m in kin.motion.items()}
        self.rot = {lid: complex(m.rot[k]) for lid, m in kin.motion.items()}
        self.w = {lid: float(m.omega[k]) for lid, m in kin.motion.items() if m.omega is not None}
        self.e = {lid: float(m.eps[k]) for lid, m in kin.motion.items() if m.eps is not None}
        self.v0 = {lid: complex(m.v0[k]) for lid, m in kin.motion.items() if m.v0 is not None}
        self.a0 = {lid: complex(m.a0[k]) for lid, m in kin.motion.items() if m.a0 is not None}

    def local(self, link: int, name: str) -> complex:
        if link == self.scene.frame:
            return self.scene.frame_points[name]
        return self.scene.links[link].points[name]

    def pos(self, link: int, name: str) -> complex:
        return self.r0[link] + self.rot[link] * self.local(link, name)

    def guide(self, jt: Joint) -> tuple[complex, complex]:
        g = jt.guide
        assert g is not None
        return self.r0[g.link] + self.rot[g.link] * g.origin, self.rot[g.link] * g.direction

    # exact rates of a point fixed to ``link`` at global position X
    def v(self, link: int, X: complex) -> complex:
        return self.v0[link] + 1j * self.w[link] * (X - self.r0[link])

    def a(self, link: int, X: complex) -> complex:
        return self.a0[link] + (1j * self.e[link] - self.w[link] ** 2) * (X - self.r0[link])

    def slide(self, jt: Joint) -> tuple[float, float | None]:
        sd, sdd = self.kin.slides[jt.name]
        return float(sd[self.k]), (None if sdd is None else float(sdd[self.k]))


# --------------------------------------------------------------------------- builder


class _Builder:
    """Accumulates one plan: points, segments, construction lines, protocol."""

    def __init__(self, snap: _Snapshot, kind: str, scale: float) -> None:
        self.snap = snap
        self.kind = kind
        self.mu = scale
        self.sym = "v" if kind == "velocity" else "a"
        self.unit = "m/s" if kind == "velocity" else "m/s^2"
        self.pole = "p_v" if kind == "velocity" else "p_a"
        self.pts: dict[str, complex] = {self.pole: 0j}
        self.order: list[str] = [self.pole]
        self.segments: list[Segment] = []
        self.lines: list[ConstructionLine] = []
        self.steps: list[Step] = []
        self.readings: list[Reading] = []
        self.degenerate: list[str] = []
        self.factor: dict[int, complex] = {snap.scene.frame: 0j}
        self.anchor: dict[int, tuple[str, complex]] = {snap.scene.frame: (self.pole, 0j)}
        self.labels: dict[tuple[int, str], str] = {}
        self.ref = 0.0  # the known vector's value: set when it is laid off
        self.size = 0.0  # the plan's extent so far (mm from the pole)

    # -- points and images
    def add(self, label: str, xy: complex) -> None:
        if label not in self.pts:
            self.order.append(label)
        self.pts[label] = xy
        self.size = max(self.size, abs(xy))

    def image(self, link: int, name: str) -> complex:
        """Image of point ``name`` of ``link`` by the similarity theorem."""
        lab = self.labels.get((link, name))
        if lab is not None:
            return self.pts[lab]
        ref, ref_xy = self.anchor[link]
        X = self.snap.pos(link, name)
        R = self.ref_pos[link]
        return ref_xy + self.factor[link] * (X - R)

    def image_at(self, link: int, X: complex) -> complex:
        ref, ref_xy = self.anchor[link]
        return ref_xy + self.factor[link] * (X - self.ref_pos[link])

    def set_link(self, link: int, ref_label: str, ref_pos: complex, factor: complex) -> None:
        self.anchor[link] = (ref_label, self.pts[ref_label])
        self.ref_pos[link] = ref_pos
        self.factor[link] = factor

    ref_pos: dict[int, complex]

    def seg(self, start: str, end: str, kind: str, label: str, exact: float) -> None:
        d = self.pts[end] - self.pts[start]
        length = abs(d)
        value = length / self.mu
        # rounding dust at a dead centre (1e-15 of the plan) is read as zero, as on paper
        if length <= COINCIDE_REL * max(self.ref * self.mu, 1e-300):
            length = value = 0.0
        if abs(exact) <= 1e-12 * self.ref:
            exact = 0.0
        self.segments.append(Segment(start, end, kind, label, length, value))
        self.readings.append(Reading(label, f"{start} {end}", length, self.mu, value, exact, self.unit,
                                     self.ref))

    def step(self, op: str, inputs: tuple[str, ...], output: str, text: str) -> None:
        self.steps.append(Step(op, inputs, output, text))

    def line(self, through: complex, direction: complex, label: str) -> tuple[complex, complex]:
        u = direction / abs(direction)
        self.lines.append(ConstructionLine((through.real, through.imag), (u.real, u.imag), label))
        return through, u

    def intersect(self, l1: tuple[complex, complex], l2: tuple[complex, complex], out: str,
                  exact_xy: complex, group: Group, point: str) -> complex:
        """Intersection of two construction lines, by shapely; the draftsman's answer
        (the exact point) where they are parallel or nearly so."""
        (p1, d1), (p2, d2) = l1, l2
        s = cross(d1, d2)
        extent = max(abs(p1), abs(p2), self.size, 1e-300)
        if abs(s) <= NEAR_PARALLEL_SIN:
            gap = abs(cross(d1, p2 - p1))
            if abs(s) <= LOCK_SIN and gap > COINCIDE_REL * extent:
                raise Locked(f"the lines {self.lines[-2].label} and {self.lines[-1].label} of the "
                             f"{self.kind} plan are parallel and apart",
                             group=f"{group.kind} {group.name}", point=point, phi_deg=self.snap.phi)
            self.degenerate.append(f"{out}: construction lines parallel within {abs(s):.1e} rad; "
                                   f"the exact point is taken")
            return exact_xy
        reach = 2.0 * (abs(p1 - p2) + extent) / abs(s) + extent
        ends = [(p1 - reach * d1, p1 + reach * d1), (p2 - reach * d2, p2 + reach * d2)]
        a, b = shapely.linestrings([[(z.real, z.imag) for z in pair] for pair in ends])
        x = shapely.intersection(a, b)
        if x.is_empty or x.geom_type != "Point":  # pragma: no cover - guarded by the test above
            self.degenerate.append(f"{out}: no single intersection; the exact point is taken")
            return exact_xy
        return complex(x.x, x.y)

    def finish(self) -> Plan:
        extent = max((abs(z) for z in self.pts.values()), default=0.0)
        tol = COINCIDE_REL * max(extent, 1e-300)
        points = []
        seen: list[str] = []
        for name in self.order:
            xy = self.pts[name]
            same = next((o for o in seen if abs(self.pts[o] - xy) <= tol), None)
            points.append(PlanPoint(name, (float(xy.real), float(xy.imag)), same))
            if same is None:
                seen.append(name)
            elif name != self.pole:
                self.step("coincide", (same,), name, f"{name} coincides with {same}")
        return Plan(kind=self.kind, phi_deg=self.snap.phi, scale=self.mu, pole=self.pole,
                    points=tuple(points), segments=tuple(self.segments), lines=tuple(self.lines),
                    steps=tuple(self.steps), degenerate=tuple(self.degenerate))


def _lab(name: str) -> str:
    return name.lower()


# --------------------------------------------------------------------------- plans


def build(kin: Kinematics, k: int, *, velocity_scale: float | None = None,
          acceleration_scale: float | None = None) -> PositionPlans:
    """Both plans at position ``k`` (as far as the scene asks and the kinematics reaches)."""
    snap = _Snapshot(kin, k)
    scene = kin.scene
    want_v = scene.wants("velocity_plan") and kin.order >= 1
    want_a = scene.wants("acceleration_plan") and kin.order >= 2
    if not want_v:
        return PositionPlans(snap.phi, None, None, ())
    mv = velocity_scale or scene.scales.get("velocity") or default_scales(kin)[0]
    vb = _velocity(snap, mv)
    vplan = vb.finish()
    readings = list(vb.readings)
    aplan = None
    if want_a:
        ma = acceleration_scale or scene.scales.get("acceleration") or default_scales(kin)[1]
        ab = _acceleration(snap, ma, vb)
        aplan = ab.finish()
        readings += ab.readings
    return PositionPlans(snap.phi, vplan, aplan, tuple(readings))


def default_scales(kin: Kinematics) -> tuple[float, float]:
    """μv and μa as the course picks them: the crank pin's vector (the known one)
    drawn 50–100 mm at a round scale (or as ``[scales]`` says), the same at every position."""
    from plans.kinematics.scales import common_scales

    return common_scales(kin)


def _velocity(snap: _Snapshot, mu: float) -> _Builder:
    b = _Builder(snap, "velocity", mu)
    b.ref_pos = {snap.scene.frame: 0j}
    d = snap.scene.driver
    crank = snap.scene.links[d.link]
    O, A_name = d.pivot, crank.axis[1]
    Opos, Apos = snap.pos(d.link, O), snap.pos(d.link, A_name)
    w1 = d.omega
    a_xy = mu * 1j * w1 * (Apos - Opos)
    b.add(_lab(A_name), a_xy)
    b.ref = abs(a_xy) / mu
    b.labels[(d.link, A_name)] = _lab(A_name)
    b.labels[(d.link, O)] = b.pole
    b.step("lay off", (b.pole,), _lab(A_name),
           f"v_{A_name} = ω1·l_{O}{A_name} = {abs(w1):.6g}·{abs(Apos - Opos):.6g} = "
           f"{abs(w1 * (Apos - Opos)):.6g} m/s; lay off {b.pole}{_lab(A_name)} = {abs(a_xy):.3f} mm "
           f"⟂ {O}{A_name} in the sense of ω1 (μv = {mu:.6g} mm/(m/s))")
    b.set_link(d.link, _lab(A_name), Apos, mu * 1j * w1)
    b.seg(b.pole, _lab(A_name), "absolute", f"v_{A_name}", abs(snap.v(d.link, Apos)))
    _link_points(b, d.link)
    for g in snap.kin.structure.groups:
        _VEL[g.kind](b, g)
        for lid in g.links:
            _link_points(b, lid)
    _omegas(b)
    return b


def _link_points(b: _Builder, link: int) -> None:
    """Similarity theorem: images of the link's other named points."""
    snap = b.snap
    sym = b.sym
    for name in snap.scene.links[link].points:
        if (link, name) in b.labels:
            continue
        if name in snap.scene.frame_points:  # a pivot on the frame: its image is the pole
            b.labels[(link, name)] = b.pole
            continue
        lab = _lab(name)
        if lab in b.pts:  # the same point through another link (a shared joint)
            b.labels[(link, name)] = lab
            continue
        X = snap.pos(link, name)
        xy = b.image(link, name)
        b.add(lab, xy)
        b.labels[(link, name)] = lab
        ref = b.anchor[link][0]
        b.step("similarity", (ref,), lab,
               f"{lab}: similarity theorem on link {link} ({name} of link {link} from {ref})")
        exact = abs(snap.v(link, X)) if sym == "v" else abs(snap.a(link, X))
        b.seg(b.pole, lab, "absolute", f"{sym}_{name}", exact)


def _omegas(b: _Builder) -> None:
    """ω (or ε) of every moving link read off the plan: from the similarity factor."""
    snap = b.snap
    for lid in sorted(snap.scene.links):
        if lid not in b.factor:
            continue
        f = b.factor[lid]
        if b.sym == "v":  # f = μv·iω
            value, exact, q, unit = f.imag / b.mu, snap.w[lid], f"omega_{lid}", "rad/s"
        else:  # f = μa·(iε − ω²)
            value, exact, q, unit = f.imag / b.mu, snap.e[lid], f"eps_{lid}", "rad/s^2"
        link = snap.scene.links[lid]
        size = abs(link.length) if link.length else _crank_length(snap)
        ref = b.ref / size
        value = 0.0 if abs(value) <= 1e-12 * ref else value
        exact = 0.0 if abs(exact) <= 1e-12 * ref else exact
        b.readings.append(Reading(q, None, None, None, value, exact, unit, ref))


def _crank_length(snap: _Snapshot) -> float:
    d = snap.scene.driver
    return abs(snap.scene.links[d.link].points[snap.scene.links[d.link].axis[1]])


def _exact_v(b: _Builder, link: int, X: complex) -> complex:
    return b.mu * b.snap.v(link, X)


def _rel_seg(b: _Builder, start: str, end: str, P: str, Q: str, exact: float) -> None:
    if start == b.pole:  # relative to a fixed point: the absolute vector already drawn
        return
    b.seg(start, end, "relative", f"{b.sym}_{Q}{P}", exact)


# -- velocity, one function per dyad kind ---------------------------------------------


def _v_rrr(b: _Builder, g: Group) -> None:
    snap = b.snap
    i, j = g.links
    j1, j2, j3 = g.joints
    p, q = g.known
    P1, B, P3 = snap.pos(p, j1.point), snap.pos(i, j2.point), snap.pos(q, j3.point)
    x1, x3 = b.image(p, j1.point), b.image(q, j3.point)
    n1 = _ensure(b, p, j1.point, x1)
    n3 = _ensure(b, q, j3.point, x3)
    L1 = b.line(x1, 1j * (B - P1), f"⟂ {j1.point}{j2.point}")
    L3 = b.line(x3, 1j * (B - P3), f"⟂ {j3.point}{j2.point}")
    out = _lab(j2.point)
    xb = b.intersect(L1, L3, out, _exact_v(b, i, B), g, j2.point)
    b.add(out, xb)
    b.labels[(i, j2.point)] = b.labels[(j, j2.point)] = out
    b.step("intersect", (n1, n3), out,
           f"v_{j2.point} = v_{j1.point} + v_{j2.point}{j1.point} = v_{j3.point} + v_{j2.point}{j3.point}: "
           f"line through {n1} ⟂ {j1.point}{j2.point}, line through {n3} ⟂ {j3.point}{j2.point}; "
           f"they meet at {out}")
    b.set_link(i, out, B, (xb - x1) / (B - P1))
    b.set_link(j, out, B, (xb - x3) / (B - P3))
    b.seg(b.pole, out, "absolute", f"v_{j2.point}", abs(snap.v(i, B)))
    _rel_seg(b, n1, out, j1.point, j2.point, abs(snap.v(i, B) - snap.v(p, P1)))
    _rel_seg(b, n3, out, j3.point, j2.point, abs(snap.v(j, B) - snap.v(q, P3)))


def _ensure(b: _Builder, link: int, name: str, xy: complex) -> str:
    """Make sure the image of a known point is labelled on the plan."""
    lab = b.labels.get((link, name))
    if lab is None:
        lab = _lab(name) if link != b.snap.scene.frame else b.pole
        if link == b.snap.scene.frame:
            return b.pole
        if lab in b.pts and abs(b.pts[lab] - xy) > COINCIDE_REL * max(1.0, abs(xy)):
            lab = f"{lab}{link}"
        b.add(lab, xy)
        b.labels[(link, name)] = lab
    return lab


def _coincident(b: _Builder, link: int, name: str, X: complex) -> tuple[str, complex]:
    """Image of the point of ``link`` that coincides with X now (e.g. B on a moving guide)."""
    if link == b.snap.scene.frame:
        return b.pole, 0j
    lab = f"{_lab(name)}{link}"
    xy = b.image_at(link, X)
    b.add(lab, xy)
    b.step("similarity", (b.anchor[link][0],), lab,
           f"{lab}: image of the point of link {link} under {name} (similarity theorem)")
    return lab, xy


def _v_rrp(b: _Builder, g: Group) -> None:
    snap = b.snap
    i, j = g.links
    j1, j2, j3 = g.joints
    p, q = g.known
    P1, B = snap.pos(p, j1.point), snap.pos(i, j2.point)
    _, u = snap.guide(j3)
    x1 = b.image(p, j1.point)
    n1 = _ensure(b, p, j1.point, x1)
    nq, xq = _coincident(b, q, j2.point, B)
    L1 = b.line(x1, 1j * (B - P1), f"⟂ {j1.point}{j2.point}")
    L3 = b.line(xq, u, f"∥ guide of {j2.point}")
    out = _lab(j2.point)
    xb = b.intersect(L1, L3, out, _exact_v(b, i, B), g, j2.point)
    b.add(out, xb)
    b.labels[(i, j2.point)] = b.labels[(j, j2.point)] = out
    b.step("intersect", (n1, nq), out,
           f"v_{j2.point} = v_{j1.point} + v_{j2.point}{j1.point}, v_{j2.point}{j1.point} ⟂ {j1.point}{j2.point}, "
           f"v_{j2.point} ∥ guide: line through {n1} ⟂ {j1.point}{j2.point}, line through {nq} ∥ guide; "
           f"they meet at {out}")
    b.set_link(i, out, B, (xb - x1) / (B - P1))
    b.set_link(j, out, B, b.factor[q])
    b.seg(b.pole, out, "absolute", f"v_{j2.point}", abs(snap.v(i, B)))
    _rel_seg(b, n1, out, j1.point, j2.point, abs(snap.v(i, B) - snap.v(p, P1)))
    if q != snap.scene.frame:
        sd, _ = snap.slide(j3)
        b.seg(nq, out, "sliding", f"v_{j2.point}{j}{j2.point}{q}", abs(sd))


def _v_rpr(b: _Builder, g: Group) -> None:
    snap = b.snap
    i, j = g.links
    j1, j2, j3 = g.joints
    p, q = g.known
    A, Cq = snap.pos(p, j1.point), snap.pos(q, j3.point)
    _, u = _slot(snap, g)
    xa, xc = b.image(p, j1.point), b.image(q, j3.point)
    na = _ensure(b, p, j1.point, xa)
    nc = _ensure(b, q, j3.point, xc)
    L1 = b.line(xc, 1j * (A - Cq), f"⟂ {j3.point}{j1.point}")
    L2 = b.line(xa, u, f"∥ slot of link {j}")
    out = f"{_lab(j1.point)}{j}"
    x3 = b.intersect(L1, L2, out, _exact_v(b, j, A), g, j1.point)
    b.add(out, x3)
    b.step("intersect", (nc, na), out,
           f"v_{j1.point}{j} = v_{j3.point} + v_{j1.point}{j}{j3.point} (⟂ {j3.point}{j1.point}) = "
           f"v_{j1.point}{i} + v_{j1.point}{j}{j1.point}{i} (∥ slot): they meet at {out}")
    f = (x3 - xc) / (A - Cq)
    b.set_link(j, out, A, f)
    b.set_link(i, na, A, f)
    b.labels[(i, j1.point)] = na
    b.seg(b.pole, out, "absolute", f"v_{j1.point}{j}", abs(snap.v(j, A)))
    _rel_seg(b, nc, out, j3.point, f"{j1.point}{j}", abs(snap.v(j, A) - snap.v(q, Cq)))
    sd, _ = snap.slide(j2)
    b.seg(out, na, "sliding", f"v_{j1.point}{i}{j1.point}{j}", abs(sd))


def _slot(snap: _Snapshot, g: Group) -> tuple[complex, complex]:
    """Global line of the slot carried by j (for RPR/RPP), from j's placed pose."""
    return snap.guide(g.joints[1])


def _v_prp(b: _Builder, g: Group) -> None:
    snap = b.snap
    i, j = g.links
    j1, j2, j3 = g.joints
    p, q = g.known
    B = snap.pos(i, j2.point)
    _, u1 = snap.guide(j1)
    _, u3 = snap.guide(j3)
    n1, x1 = _coincident(b, p, j2.point, B)
    n3, x3 = _coincident(b, q, j2.point, B)
    L1 = b.line(x1, u1, f"∥ guide of link {i}")
    L3 = b.line(x3, u3, f"∥ guide of link {j}")
    out = _lab(j2.point)
    xb = b.intersect(L1, L3, out, _exact_v(b, i, B), g, j2.point)
    b.add(out, xb)
    b.labels[(i, j2.point)] = b.labels[(j, j2.point)] = out
    b.step("intersect", (n1, n3), out,
           f"v_{j2.point} = v_{j2.point}{p} + v_rel ∥ guide of {i} = v_{j2.point}{q} + v_rel ∥ guide of {j}: "
           f"they meet at {out}")
    b.set_link(i, out, B, b.factor[p])
    b.set_link(j, out, B, b.factor[q])
    b.seg(b.pole, out, "absolute", f"v_{j2.point}", abs(snap.v(i, B)))
    sd1, _ = snap.slide(j1)
    sd3, _ = snap.slide(j3)
    if n1 != b.pole:
        b.seg(n1, out, "sliding", f"v_{j2.point}{i}{j2.point}{p}", abs(sd1))
    if n3 != b.pole:
        b.seg(n3, out, "sliding", f"v_{j2.point}{j}{j2.point}{q}", abs(sd3))


def _v_rpp(b: _Builder, g: Group) -> None:
    snap = b.snap
    i, j = g.links
    j1, j2, j3 = g.joints
    p, q = g.known
    A = snap.pos(p, j1.point)
    _, u2 = _slot(snap, g)
    _, u3 = snap.guide(j3)
    xa = b.image(p, j1.point)
    na = _ensure(b, p, j1.point, xa)
    nq, xq = _coincident(b, q, j1.point, A)
    L3 = b.line(xq, u3, f"∥ guide of link {j}")
    L2 = b.line(xa, u2, f"∥ slot of link {j}")
    out = f"{_lab(j1.point)}{j}"
    xj = b.intersect(L3, L2, out, _exact_v(b, j, A), g, j1.point)
    b.add(out, xj)
    b.step("intersect", (nq, na), out,
           f"v_{j1.point}{j} = v_{j1.point}{q} + v_rel ∥ guide = v_{j1.point}{i} + v_rel ∥ slot: "
           f"they meet at {out}")
    b.set_link(j, out, A, b.factor[q])
    b.set_link(i, na, A, b.factor[q])
    b.labels[(i, j1.point)] = na
    b.seg(b.pole, out, "absolute", f"v_{j1.point}{j}", abs(snap.v(j, A)))
    sd2, _ = snap.slide(j2)
    sd3, _ = snap.slide(j3)
    b.seg(out, na, "sliding", f"v_{j1.point}{i}{j1.point}{j}", abs(sd2))
    if nq != b.pole:
        b.seg(nq, out, "sliding", f"v_{j1.point}{j}{j1.point}{q}", abs(sd3))


_VEL = {"RRR": _v_rrr, "RRP": _v_rrp, "RPR": _v_rpr, "PRP": _v_prp, "RPP": _v_rpp}


# --------------------------------------------------------------------------- acceleration


class _VelReader:
    """What the acceleration plan takes from the velocity plan already drawn."""

    def __init__(self, vb: _Builder) -> None:
        self.vb = vb

    def omega(self, link: int) -> float:
        return self.vb.factor[link].imag / self.vb.mu

    def rel(self, a: str, b: str) -> complex:
        """Velocity vector from plan point a to plan point b, in m/s."""
        return (self.vb.pts[b] - self.vb.pts[a]) / self.vb.mu


def _acceleration(snap: _Snapshot, mu: float, vb: _Builder) -> _Builder:
    b = _Builder(snap, "acceleration", mu)
    b.ref_pos = {snap.scene.frame: 0j}
    vr = _VelReader(vb)
    d = snap.scene.driver
    crank = snap.scene.links[d.link]
    O, A_name = d.pivot, crank.axis[1]
    Opos, Apos = snap.pos(d.link, O), snap.pos(d.link, A_name)
    w1, e1 = d.omega, d.eps
    an = mu * (w1**2) * (Opos - Apos)
    at = mu * 1j * e1 * (Apos - Opos)
    a_lab = _lab(A_name)
    l1 = abs(Apos - Opos)
    if e1 != 0.0:
        b.add(f"n_{A_name}{O}", an)
        b.step("lay off", (b.pole,), f"n_{A_name}{O}",
               f"a_{A_name}^n = ω1²·l_{O}{A_name} = {w1**2 * l1:.6g} m/s²: {abs(an):.3f} mm from {A_name} "
               f"toward {O} (μa = {mu:.6g} mm/(m/s²))")
        b.add(a_lab, an + at)
        b.step("lay off", (f"n_{A_name}{O}",), a_lab,
               f"a_{A_name}^τ = ε1·l_{O}{A_name} = {abs(e1) * l1:.6g} m/s²: {abs(at):.3f} mm ⟂ {O}{A_name}")
        b.seg(b.pole, f"n_{A_name}{O}", "normal", f"a_{A_name}{O}^n", w1**2 * l1)
        b.seg(f"n_{A_name}{O}", a_lab, "tangential", f"a_{A_name}{O}^τ", abs(e1) * l1)
    else:
        b.add(a_lab, an)
        b.step("lay off", (b.pole,), a_lab,
               f"a_{A_name} = a_{A_name}^n = ω1²·l_{O}{A_name} = {w1**2 * l1:.6g} m/s² (ε1 = 0): "
               f"{abs(an):.3f} mm from {A_name} toward {O} (μa = {mu:.6g} mm/(m/s²))")
    b.labels[(d.link, A_name)] = a_lab
    b.labels[(d.link, O)] = b.pole
    b.ref = abs(an + at) / mu
    b.set_link(d.link, a_lab, Apos, mu * (1j * e1 - w1**2))
    b.seg(b.pole, a_lab, "absolute", f"a_{A_name}", abs(snap.a(d.link, Apos)))
    _link_points(b, d.link)
    for g in snap.kin.structure.groups:
        _ACC[g.kind](b, g, vr)
        for lid in g.links:
            _link_points(b, lid)
    _omegas(b)
    return b


def _normal(b: _Builder, vr: _VelReader, link: int, frm: str, frm_xy: complex, P: complex, X: complex,
            Pn: str, Xn: str) -> tuple[str, complex]:
    """Lay off a_XP^n = ω²·l toward P from the image of P; ω read off the velocity plan."""
    w = vr.omega(link)
    vec = b.mu * w * w * (P - X)
    lab = f"n_{Xn}{Pn}"
    b.add(lab, frm_xy + vec)
    l = abs(P - X)
    b.step("lay off", (frm,), lab,
           f"a_{Xn}{Pn}^n = v_{Xn}{Pn}²/l_{Pn}{Xn} = {clean(w * w * l, b.ref):.6g} m/s²: {abs(vec):.3f} mm from {frm} "
           f"parallel to {Xn}{Pn}, from {Xn} toward {Pn}")
    b.seg(frm, lab, "normal", f"a_{Xn}{Pn}^n", b.snap.w[link] ** 2 * l)
    return lab, frm_xy + vec


def _coriolis(b: _Builder, vr: _VelReader, guide_link: int, v_rel: complex, frm: str, frm_xy: complex,
              label: str, exact: float) -> tuple[str, complex]:
    """Lay off a^k = 2 ω × v_rel (v_rel turned 90° in the sense of ω) from ``frm``."""
    w = vr.omega(guide_link)
    vec = b.mu * 2 * w * 1j * v_rel
    lab = f"k_{label}"
    b.add(lab, frm_xy + vec)
    b.step("lay off", (frm,), lab,
           f"a^k_{label} = 2·ω{guide_link}·v_r = {clean(abs(2 * w * v_rel), b.ref):.6g} m/s²: {abs(vec):.3f} mm, "
           f"v_r turned 90° in the sense of ω{guide_link}")
    b.seg(frm, lab, "coriolis", f"a^k_{label}", exact)
    return lab, frm_xy + vec


def _a_rrr(b: _Builder, g: Group, vr: _VelReader) -> None:
    snap = b.snap
    i, j = g.links
    j1, j2, j3 = g.joints
    p, q = g.known
    P1, B, P3 = snap.pos(p, j1.point), snap.pos(i, j2.point), snap.pos(q, j3.point)
    x1, x3 = b.image(p, j1.point), b.image(q, j3.point)
    n1 = _ensure(b, p, j1.point, x1)
    n3 = _ensure(b, q, j3.point, x3)
    m1, y1 = _normal(b, vr, i, n1, x1, P1, B, j1.point, j2.point)
    m3, y3 = _normal(b, vr, j, n3, x3, P3, B, j3.point, j2.point)
    L1 = b.line(y1, 1j * (B - P1), f"⟂ {j1.point}{j2.point}")
    L3 = b.line(y3, 1j * (B - P3), f"⟂ {j3.point}{j2.point}")
    out = _lab(j2.point)
    xb = b.intersect(L1, L3, out, b.mu * snap.a(i, B), g, j2.point)
    b.add(out, xb)
    b.labels[(i, j2.point)] = b.labels[(j, j2.point)] = out
    b.step("intersect", (m1, m3), out,
           f"a_{j2.point}{j1.point}^τ ⟂ {j1.point}{j2.point} through {m1} and a_{j2.point}{j3.point}^τ ⟂ "
           f"{j3.point}{j2.point} through {m3} meet at {out}")
    b.set_link(i, out, B, (xb - x1) / (B - P1))
    b.set_link(j, out, B, (xb - x3) / (B - P3))
    b.seg(m1, out, "tangential", f"a_{j2.point}{j1.point}^τ", abs(snap.e[i]) * abs(B - P1))
    b.seg(m3, out, "tangential", f"a_{j2.point}{j3.point}^τ", abs(snap.e[j]) * abs(B - P3))
    b.seg(b.pole, out, "absolute", f"a_{j2.point}", abs(snap.a(i, B)))


def _a_rrp(b: _Builder, g: Group, vr: _VelReader) -> None:
    snap = b.snap
    i, j = g.links
    j1, j2, j3 = g.joints
    p, q = g.known
    P1, B = snap.pos(p, j1.point), snap.pos(i, j2.point)
    _, u = snap.guide(j3)
    x1 = b.image(p, j1.point)
    n1 = _ensure(b, p, j1.point, x1)
    m1, y1 = _normal(b, vr, i, n1, x1, P1, B, j1.point, j2.point)
    nq, xq = _coincident(b, q, j2.point, B)
    start, start_xy = nq, xq
    if q != snap.scene.frame:
        vname = f"{_lab(j2.point)}{q}"
        v_rel = vr.rel(vname, _lab(j2.point))
        sd, _ = snap.slide(j3)
        start, start_xy = _coriolis(b, vr, q, v_rel, nq, xq, f"{j2.point}{j}{j2.point}{q}",
                                    abs(2 * snap.w[q] * sd))
    L1 = b.line(y1, 1j * (B - P1), f"⟂ {j1.point}{j2.point}")
    L3 = b.line(start_xy, u, f"∥ guide of {j2.point}")
    out = _lab(j2.point)
    xb = b.intersect(L1, L3, out, b.mu * snap.a(i, B), g, j2.point)
    b.add(out, xb)
    b.labels[(i, j2.point)] = b.labels[(j, j2.point)] = out
    b.step("intersect", (m1, start), out,
           f"line through {m1} ⟂ {j1.point}{j2.point} (a_{j2.point}{j1.point}^τ) and line through {start} "
           f"∥ guide meet at {out}")
    b.set_link(i, out, B, (xb - x1) / (B - P1))
    b.set_link(j, out, B, b.factor[q])
    b.seg(m1, out, "tangential", f"a_{j2.point}{j1.point}^τ", abs(snap.e[i]) * abs(B - P1))
    b.seg(b.pole, out, "absolute", f"a_{j2.point}", abs(snap.a(i, B)))
    if q != snap.scene.frame:
        _, sdd = snap.slide(j3)
        b.seg(start, out, "sliding", f"a^r_{j2.point}{j}{j2.point}{q}", abs(sdd or 0.0))


def _a_rpr(b: _Builder, g: Group, vr: _VelReader) -> None:
    snap = b.snap
    i, j = g.links
    j1, j2, j3 = g.joints
    p, q = g.known
    A, Cq = snap.pos(p, j1.point), snap.pos(q, j3.point)
    _, u = _slot(snap, g)
    xa, xc = b.image(p, j1.point), b.image(q, j3.point)
    na = _ensure(b, p, j1.point, xa)
    nc = _ensure(b, q, j3.point, xc)
    An = f"{j1.point}{j}"
    mc, yc = _normal(b, vr, j, nc, xc, Cq, A, j3.point, An)
    # a_A3 = a_A2 + a^k_A3A2 + a^r_A3A2, v_A3A2 read from the velocity plan (a2 -> a3)
    v_rel = vr.rel(_lab(j1.point), f"{_lab(j1.point)}{j}")
    sd, sdd = snap.slide(j2)
    mk, yk = _coriolis(b, vr, j, v_rel, na, xa, f"{j1.point}{j}{j1.point}{i}", abs(2 * snap.w[j] * sd))
    L1 = b.line(yc, 1j * (A - Cq), f"⟂ {j3.point}{j1.point}")
    L2 = b.line(yk, u, f"∥ slot of link {j}")
    out = f"{_lab(j1.point)}{j}"
    x3 = b.intersect(L1, L2, out, b.mu * snap.a(j, A), g, j1.point)
    b.add(out, x3)
    b.step("intersect", (mc, mk), out,
           f"a_{An}{j3.point}^τ ⟂ {j3.point}{j1.point} through {mc} and a^r ∥ slot through {mk} meet at {out}")
    f = (x3 - xc) / (A - Cq)
    b.set_link(j, out, A, f)
    b.set_link(i, na, A, f)
    b.labels[(i, j1.point)] = na
    b.seg(mc, out, "tangential", f"a_{An}{j3.point}^τ", abs(snap.e[j]) * abs(A - Cq))
    b.seg(mk, out, "sliding", f"a^r_{j1.point}{j}{j1.point}{i}", abs(sdd or 0.0))
    b.seg(b.pole, out, "absolute", f"a_{An}", abs(snap.a(j, A)))


def _a_prp(b: _Builder, g: Group, vr: _VelReader) -> None:
    snap = b.snap
    i, j = g.links
    j1, j2, j3 = g.joints
    p, q = g.known
    B = snap.pos(i, j2.point)
    _, u1 = snap.guide(j1)
    _, u3 = snap.guide(j3)
    out = _lab(j2.point)
    ends = []
    for jt, carrier, link in ((j1, p, i), (j3, q, j)):
        nm, xy = _coincident(b, carrier, j2.point, B)
        if carrier != snap.scene.frame:
            v_rel = vr.rel(f"{_lab(j2.point)}{carrier}", out)
            sd, _ = snap.slide(jt)
            nm, xy = _coriolis(b, vr, carrier, v_rel, nm, xy, f"{j2.point}{link}{j2.point}{carrier}",
                               abs(2 * snap.w[carrier] * sd))
        ends.append((nm, xy))
    L1 = b.line(ends[0][1], u1, f"∥ guide of link {i}")
    L3 = b.line(ends[1][1], u3, f"∥ guide of link {j}")
    xb = b.intersect(L1, L3, out, b.mu * snap.a(i, B), g, j2.point)
    b.add(out, xb)
    b.labels[(i, j2.point)] = b.labels[(j, j2.point)] = out
    b.step("intersect", (ends[0][0], ends[1][0]), out,
           f"line through {ends[0][0]} ∥ guide of link {i} and line through {ends[1][0]} ∥ guide of link {j} "
           f"meet at {out}")
    b.set_link(i, out, B, b.factor[p])
    b.set_link(j, out, B, b.factor[q])
    b.seg(b.pole, out, "absolute", f"a_{j2.point}", abs(snap.a(i, B)))
    for (nm, _), jt, carrier, link in ((ends[0], j1, p, i), (ends[1], j3, q, j)):
        if nm != b.pole:
            _, sdd = snap.slide(jt)
            b.seg(nm, out, "sliding", f"a^r_{j2.point}{link}{j2.point}{carrier}", abs(sdd or 0.0))


def _a_rpp(b: _Builder, g: Group, vr: _VelReader) -> None:
    snap = b.snap
    i, j = g.links
    j1, j2, j3 = g.joints
    p, q = g.known
    A = snap.pos(p, j1.point)
    _, u2 = _slot(snap, g)
    _, u3 = snap.guide(j3)
    xa = b.image(p, j1.point)
    na = _ensure(b, p, j1.point, xa)
    out = f"{_lab(j1.point)}{j}"
    nq, xq = _coincident(b, q, j1.point, A)
    s3, y3 = nq, xq
    if q != snap.scene.frame:
        v_rel = vr.rel(f"{_lab(j1.point)}{q}", out)
        sd3, _ = snap.slide(j3)
        s3, y3 = _coriolis(b, vr, q, v_rel, nq, xq, f"{j1.point}{j}{j1.point}{q}", abs(2 * snap.w[q] * sd3))
    # a_Aj = a_Ai + a^k_AjAi + a^r_AjAi, v_AjAi from the velocity plan (a -> aj)
    v_rel2 = vr.rel(_lab(j1.point), out)
    sd2, sdd2 = snap.slide(j2)
    s2, y2 = na, xa
    if q != snap.scene.frame or snap.w.get(j, 0.0) != 0.0:
        s2, y2 = _coriolis(b, vr, j, v_rel2, na, xa, f"{j1.point}{j}{j1.point}{i}", abs(2 * snap.w[j] * sd2))
    L3 = b.line(y3, u3, f"∥ guide of link {j}")
    L2 = b.line(y2, u2, f"∥ slot of link {j}")
    xj = b.intersect(L3, L2, out, b.mu * snap.a(j, A), g, j1.point)
    b.add(out, xj)
    b.step("intersect", (s3, s2), out,
           f"line through {s3} ∥ guide of link {j} and line through {s2} ∥ slot meet at {out}")
    b.set_link(j, out, A, b.factor[q])
    b.set_link(i, na, A, b.factor[q])
    b.labels[(i, j1.point)] = na
    b.seg(b.pole, out, "absolute", f"a_{j1.point}{j}", abs(snap.a(j, A)))
    b.seg(s2, out, "sliding", f"a^r_{j1.point}{j}{j1.point}{i}", abs(sdd2 or 0.0))


_ACC = {"RRR": _a_rrr, "RRP": _a_rrp, "RPR": _a_rpr, "PRP": _a_prp, "RPP": _a_rpp}


def build_all(kin: Kinematics) -> list[PositionPlans]:
    """Plans at every position of the scene: one round scale for all, a round one of its own
    for a position whose plan would run too long."""
    from plans.kinematics.scales import fitted

    mv, ma = default_scales(kin)
    return [fitted(kin, k, mv, ma, build) for k in range(kin.n)]


__all__ = ["Reading", "PositionPlans", "build", "build_all", "default_scales", "nice_scale"]
