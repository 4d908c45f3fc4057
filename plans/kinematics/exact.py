"""Exact kinematic analysis, vectorised over crank positions.

Written independently of the graphical construction (:mod:`plans.construction`):
positions in closed form per group, velocities and accelerations from the
vector loop of each group as a 2×2 linear system (Cramer's rule).  Plane
vectors are complex numbers: ``1j * z`` is z turned 90° counter-clockwise
(``k × z``), ``cross(a, b) = Im(conj(a)·b)``.

For a point X of link k (origin r0, angle θ, rates ω, ε):
    r_X = r0 + e^{iθ} z_X,   v_X = v0 + iω (r_X − r0),   a_X = a0 + (iε − ω²)(r_X − r0).
"""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import Any

import numpy as np

from plans.errors import Locked, NotAssemblable
from plans.kinematics.structure import Group, Structure, analyse
from plans.scene.model import Joint, Scene
from plans.tolerances import ASSEMBLY_REL, LOCK_SIN

# numpy arrays over positions; typed loosely because numpy's operator stubs do not
# follow Optional fields that the order of analysis fills in.
C = Any  # complex128 array, shape (N,)
R = Any  # float64 array, shape (N,)


def cross(a, b):
    """a × b (z component) for complex-coded plane vectors."""
    return (a.conjugate() * b).imag


@dataclass(slots=True)
class _Motion:
    rot: C  # e^{iθ}: kept as a unit complex, so no angle is ever taken in the solvers
    r0: C
    omega: R = None
    v0: C = None
    eps: R = None
    a0: C = None

    @property
    def theta(self) -> R:
        return np.angle(self.rot)


@dataclass(frozen=True)
class Kinematics:
    """Positions (and, if asked, velocities and accelerations) of every link and point."""

    scene: Scene
    structure: Structure
    phi_deg: R
    order: int  # 0 positions, 1 + velocities, 2 + accelerations
    motion: dict[int, _Motion] = field(repr=False)
    slides: dict[str, tuple[R, R]] = field(repr=False)  # P joint name -> (ṡ, s̈)
    #: group name -> condition number of its velocity/acceleration system per position:
    #: |c1||c2| / |c1 × c2| = 1 / sin(angle between the two construction lines)
    conditions: dict[str, R] = field(repr=False, default_factory=dict)

    @property
    def n(self) -> int:
        return len(self.phi_deg)

    def home(self, name: str) -> int:
        """The link a named point is read from (lowest number, frame last)."""
        links = self.scene.point_links(name)
        if not links:
            raise KeyError(name)
        moving = [k for k in links if k != self.scene.frame]
        return min(moving) if moving else self.scene.frame

    def local(self, link: int, name: str) -> complex:
        if link == self.scene.frame:
            return self.scene.frame_points[name]
        return self.scene.links[link].points[name]

    def point_on(self, link: int, z: complex) -> tuple[C, C, C]:
        """r, v, a of the point with local coordinates z on ``link``."""
        m = self.motion[link]
        rel = m.rot * z
        r = m.r0 + rel
        v = None if m.omega is None else m.v0 + 1j * m.omega * rel
        a = None if m.eps is None else m.a0 + (1j * m.eps - m.omega**2) * rel
        return r, v, a

    def point(self, name: str, link: int | None = None) -> tuple[C, C, C]:
        k = self.home(name) if link is None else link
        return self.point_on(k, self.local(k, name))

    def omega(self, link: int) -> R:
        m = self.motion[link]
        assert m.omega is not None
        return m.omega

    def eps(self, link: int) -> R:
        m = self.motion[link]
        assert m.eps is not None
        return m.eps

    def theta(self, link: int) -> R:
        return self.motion[link].theta

    def point_names(self) -> list[str]:
        names: list[str] = []
        for link in [self.scene.links[k] for k in sorted(self.scene.links)]:
            for nm in link.points:
                if nm not in names:
                    names.append(nm)
        return names


def solve(scene: Scene, phi_deg=None, order: int | None = None,
          structure: Structure | None = None) -> Kinematics:
    """Exact analysis at the scene's crank angles (or ``phi_deg``).

    ``order`` is what to compute: 0 positions, 1 velocities, 2 accelerations;
    by default what the scene's outputs need.
    """
    st = structure or analyse(scene)
    if order is None:
        order = 0
        if scene.wants("velocity_plan"):
            order = 1
        if scene.wants("acceleration_plan"):
            order = 2
    phis = np.atleast_1d(np.asarray(scene.driver.phis_deg if phi_deg is None else phi_deg, dtype=float))
    n = len(phis)
    motion: dict[int, _Motion] = {}
    zeros = np.zeros(n)
    czeros = np.zeros(n, dtype=complex)
    motion[scene.frame] = _Motion(np.ones(n, dtype=complex), czeros, zeros, czeros, zeros, czeros)
    d = scene.driver
    crank = scene.links[d.link]
    rot1 = d.rotation(phis)
    pivot = scene.frame_points[d.pivot]
    m1 = _Motion(rot1, pivot - rot1 * crank.points[d.pivot])
    if order >= 1:
        m1.omega = np.full(n, d.omega)
        m1.v0 = 1j * m1.omega * (m1.r0 - pivot)
    if order >= 2:
        m1.eps = np.full(n, d.eps)
        m1.a0 = (1j * m1.eps - m1.omega**2) * (m1.r0 - pivot)
    motion[d.link] = m1
    kin = Kinematics(scene, st, phis, order, motion, {})
    for g in st.groups:
        _SOLVERS[g.kind](kin, g, order)
    return kin


# --------------------------------------------------------------------------- helpers


def _fail(cls, kin: Kinematics, g: Group, mask, point: str, why: str):
    k = int(np.flatnonzero(mask)[0])
    return cls(why, group=f"{g.kind} {g.name}", point=point, phi_deg=float(kin.phi_deg[k]))


def _guide_line(kin: Kinematics, jt: Joint) -> tuple[C, C]:
    """Global origin and unit direction of a joint's guide."""
    assert jt.guide is not None
    m = kin.motion[jt.guide.link]
    return m.r0 + m.rot * jt.guide.origin, m.rot * jt.guide.direction


def _unit(z: C) -> C:
    return z / np.abs(z)


def _place(kin: Kinematics, link: int, rot: C, anchor: C, anchor_name: str) -> _Motion:
    """A link placed by its rotation e^{iθ} and one of its points."""
    z = kin.scene.links[link].points[anchor_name]
    m = _Motion(rot, anchor - rot * z)
    kin.motion[link] = m
    return m


def _set_rates(kin: Kinematics, link: int, anchor: C, v: C, a: C, omega: R, eps: R) -> None:
    """Rates of a placed link from one point's v, a and the link's ω, ε."""
    m = kin.motion[link]
    rel = m.r0 - anchor
    m.omega = omega
    m.v0 = v + 1j * omega * rel
    if a is not None and eps is not None:
        m.eps = eps
        m.a0 = a + (1j * eps - omega**2) * rel


def _solve2(c1: C, c2: C, rhs: C) -> tuple[R, R]:
    """x1, x2 with x1·c1 + x2·c2 = rhs."""
    det = cross(c1, c2)
    return cross(rhs, c2) / det, cross(c1, rhs) / det


def _check_lock(kin: Kinematics, g: Group, c1: C, c2: C, point: str) -> None:
    det = np.abs(cross(c1, c2))
    size = np.abs(c1) * np.abs(c2)
    bad = det <= LOCK_SIN * size
    kin.conditions[g.name] = size / np.where(bad, 1.0, det)
    if bad.any():
        raise _fail(Locked, kin, g, bad, point,
                    "the construction lines are parallel and do not coincide: the group locks here "
                    "(velocities are unbounded)")


def _sqrt_nonneg(kin: Kinematics, g: Group, x: R, y: R, scale: R, point: str, why) -> R:
    """sqrt(x·y) with x·y >= 0 up to rounding; negative beyond that is not assemblable
    (``why(k)`` says why at the first such position ``k``)."""
    prod = x * y
    bad = prod < -ASSEMBLY_REL * scale**2
    if bad.any():
        raise _fail(NotAssemblable, kin, g, bad, point, why(int(np.flatnonzero(bad)[0])))
    return np.sqrt(np.maximum(prod, 0.0))


def _branch_hint(g: Group) -> str:
    """Which ``[branches]`` entry picks the group's other assembly (where there are two)."""
    return (f"; the group has no assembly here on either branch ([branches] \"{g.name}\" = "
            f"{-g.branch:+d} selects the other of two assemblies only where two exist)")


# --------------------------------------------------------------------------- the five dyads


def _rrr(kin: Kinematics, g: Group, order: int) -> None:
    i, j = g.links
    j1, j2, j3 = g.joints
    p, q = g.known
    P1, vP1, aP1 = kin.point(j1.point, p)
    P3, vP3, aP3 = kin.point(j3.point, q)
    Li, Lj = kin.scene.links[i], kin.scene.links[j]
    zi = Li.points[j2.point] - Li.points[j1.point]
    zj = Lj.points[j2.point] - Lj.points[j3.point]
    l1, l3 = abs(zi), abs(zj)
    d = P3 - P1
    D = np.abs(d)
    if (D <= ASSEMBLY_REL * (l1 + l3)).any():
        raise _fail(NotAssemblable, kin, g, D <= ASSEMBLY_REL * (l1 + l3), j2.point,
                    f"{j1.point} and {j3.point} coincide: the position of {j2.point} is undefined")
    a = (l1**2 - l3**2 + D**2) / (2 * D)
    h = _sqrt_nonneg(kin, g, l1 - a, l1 + a, l1 + l3 + D, j2.point,
                     lambda k: f"{j1.point}{j2.point} = {l1 * 1e3:.6g} mm and {j3.point}{j2.point} = "
                               f"{l3 * 1e3:.6g} mm cannot span {j1.point}{j3.point} = {D[k] * 1e3:.6g} mm "
                               f"(they span {abs(l1 - l3) * 1e3:.6g} to {(l1 + l3) * 1e3:.6g} mm)"
                               + _branch_hint(g))
    B = P1 + (a + 1j * g.branch * h) * d / D
    _place(kin, i, _unit(B - P1) * (zi.conjugate() / l1), P1, j1.point)
    _place(kin, j, _unit(B - P3) * (zj.conjugate() / l3), P3, j3.point)
    if order < 1:
        return
    r1, r3 = B - P1, B - P3
    c1, c2 = 1j * r1, -1j * r3
    _check_lock(kin, g, c1, c2, j2.point)
    wi, wj = _solve2(c1, c2, vP3 - vP1)
    ei = ej = None
    if order >= 2:
        ei, ej = _solve2(c1, c2, aP3 - aP1 + wi**2 * r1 - wj**2 * r3)
    _set_rates(kin, i, P1, vP1, aP1, wi, ei)
    _set_rates(kin, j, P3, vP3, aP3, wj, ej)


def _rrp(kin: Kinematics, g: Group, order: int) -> None:
    i, j = g.links
    j1, j2, j3 = g.joints
    p, q = g.known
    P1, vP1, aP1 = kin.point(j1.point, p)
    G0, u = _guide_line(kin, j3)
    Li = kin.scene.links[i]
    l1 = abs(Li.points[j2.point] - Li.points[j1.point])
    w = P1 - G0
    t0 = (w * u.conjugate()).real
    e = cross(u, w)
    root = _sqrt_nonneg(kin, g, l1 - e, l1 + e, np.full_like(e, l1), j2.point,
                        lambda k: f"{j1.point}{j2.point} = {l1 * 1e3:.6g} mm is shorter than the distance "
                                  f"{abs(e[k]) * 1e3:.6g} mm from {j1.point} to the guide of {j2.point}"
                                  + _branch_hint(g))
    B = G0 + (t0 + g.branch * root) * u
    zi = Li.points[j2.point] - Li.points[j1.point]
    _place(kin, i, _unit(B - P1) * (zi.conjugate() / l1), P1, j1.point)
    mq = kin.motion[q]
    _place(kin, j, mq.rot * _turn(j3), B, j2.point)
    if order < 1:
        return
    r1 = B - P1
    vBq, aBq = _carried(kin, q, B)
    c1, c2 = 1j * r1, -u
    _check_lock(kin, g, c1, c2, j2.point)
    wi, sd = _solve2(c1, c2, vBq - vP1)
    vB = vBq + sd * u
    ei = sdd = aB = None
    if order >= 2:
        cor = 2 * mq.omega * sd * 1j * u
        ei, sdd = _solve2(c1, c2, aBq + cor - aP1 + wi**2 * r1)
        aB = aBq + cor + sdd * u
    _set_rates(kin, i, P1, vP1, aP1, wi, ei)
    _set_rates(kin, j, B, vB, aB, mq.omega, mq.eps)
    kin.slides[j3.name] = (sd, sdd)


def _rpr(kin: Kinematics, g: Group, order: int) -> None:
    i, j = g.links
    j1, j2, j3 = g.joints
    p, q = g.known
    A, vA, aA = kin.point(j1.point, p)
    Cq, vC, aC = kin.point(j3.point, q)
    Lj = kin.scene.links[j]
    guide = j2.guide
    assert guide is not None
    c0 = guide.origin - Lj.points[j3.point]
    ecc = cross(guide.direction, c0)  # signed offset of the slot from C, in j's frame
    d = A - Cq
    D = np.abs(d)
    sin_ = ecc / np.where(D > 0, D, 1.0)
    bad = (D == 0) | (np.abs(sin_) > 1 + ASSEMBLY_REL)
    if bad.any():
        k = int(np.flatnonzero(bad)[0])
        raise _fail(NotAssemblable, kin, g, bad, j2.point,
                    f"the slot of link {j} (offset {abs(ecc) * 1e3:.6g} mm from {j3.point}) cannot pass through "
                    f"{j1.point}, {D[k] * 1e3:.6g} mm from {j3.point}" + _branch_hint(g))
    tj = _rpr_angle(np.angle(d), guide.angle, ecc, D, g.branch)
    mj = _place(kin, j, np.exp(1j * tj), Cq, j3.point)
    _place(kin, i, mj.rot * _turn(j2), A, j1.point)
    if order < 1:
        return
    u = mj.rot * guide.direction
    r = A - Cq
    c1, c2 = 1j * r, u
    _check_lock(kin, g, c1, c2, j2.point)
    wj, sd = _solve2(c1, c2, vA - vC)
    ej = sdd = None
    if order >= 2:
        cor = 2 * wj * sd * 1j * u
        ej, sdd = _solve2(c1, c2, aA - aC + wj**2 * r - cor)
    _set_rates(kin, j, Cq, vC, aC, wj, ej)
    _set_rates(kin, i, A, vA, aA, wj, ej)
    kin.slides[j2.name] = (sd, sdd)


def _rpr_angle(psi, alpha, ecc, D, branch):
    """θ_j of a slotted link: the slot through C + e^{iθ}c0 along e^{i(θ+α)} holds A iff
    cross(u, A − C) = ecc ⇔ D sin(ψ − θ − α) = ecc; branch +1 puts A ahead along the slot."""
    s = np.arcsin(np.clip(ecc / D, -1.0, 1.0))
    if branch > 0:
        return psi - alpha - s  # A ahead along the slot direction
    return psi - alpha - np.pi + s


def _prp(kin: Kinematics, g: Group, order: int) -> None:
    i, j = g.links
    j1, j2, j3 = g.joints
    p, q = g.known
    G1, u1 = _guide_line(kin, j1)
    G3, u3 = _guide_line(kin, j3)
    c1, c2 = u1, -u3
    det = cross(c1, c2)
    bad = np.abs(det) <= LOCK_SIN
    if bad.any():
        raise _fail(NotAssemblable, kin, g, bad, j2.point, "the two guides are parallel: they have no common point")
    kin.conditions[g.name] = 1.0 / np.abs(det)
    s1, _ = _solve2(c1, c2, G3 - G1)
    B = G1 + s1 * u1
    mp, mq = kin.motion[p], kin.motion[q]
    _place(kin, i, mp.rot * _turn(j1), B, j2.point)
    _place(kin, j, mq.rot * _turn(j3), B, j2.point)
    if order < 1:
        return
    vBp, aBp = _carried(kin, p, B)
    vBq, aBq = _carried(kin, q, B)
    sd1, sd3 = _solve2(c1, c2, vBq - vBp)
    vB = vBp + sd1 * u1
    sdd1 = sdd3 = aB = None
    if order >= 2:
        k1 = 2 * mp.omega * sd1 * 1j * u1
        k3 = 2 * mq.omega * sd3 * 1j * u3
        sdd1, sdd3 = _solve2(c1, c2, aBq + k3 - aBp - k1)
        aB = aBp + k1 + sdd1 * u1
    _set_rates(kin, i, B, vB, aB, mp.omega, mp.eps)
    _set_rates(kin, j, B, vB, aB, mq.omega, mq.eps)
    kin.slides[j1.name] = (sd1, sdd1)
    kin.slides[j3.name] = (sd3, sdd3)


def _rpp(kin: Kinematics, g: Group, order: int) -> None:
    i, j = g.links
    j1, j2, j3 = g.joints
    p, q = g.known
    A, vA, aA = kin.point(j1.point, p)
    G3, u3 = _guide_line(kin, j3)
    mq = kin.motion[q]
    Lj = kin.scene.links[j]
    rot = mq.rot * _turn(j3)
    guide = j2.guide
    assert guide is not None
    u2 = rot * guide.direction
    zK = Lj.points[j3.point]
    c1, c2 = u2, u3
    det = cross(c1, c2)
    bad = np.abs(det) <= LOCK_SIN
    if bad.any():
        raise _fail(NotAssemblable, kin, g, bad, j2.point,
                    f"the slot of link {j} is parallel to its guide: {j2.point} cannot be reached")
    kin.conditions[g.name] = 1.0 / np.abs(det)
    # r0_j = G3 + t u3 − rot zK ; A on slot: cross(u2, A − G3 − t u3 + rot (zK − g2)) = 0
    t = cross(u2, A - G3 + rot * (zK - guide.origin)) / cross(u2, u3)
    r0 = G3 + t * u3 - rot * zK
    kin.motion[j] = _Motion(rot, r0)
    _place(kin, i, rot * _turn(j2), A, j1.point)
    if order < 1:
        return
    vAq, aAq = _carried(kin, q, A)
    sd2, sd3 = _solve2(c1, c2, vA - vAq)
    vAj = vAq + sd3 * u3
    sdd2 = sdd3 = aAj = None
    if order >= 2:
        k3 = 2 * mq.omega * sd3 * 1j * u3
        k2 = 2 * mq.omega * sd2 * 1j * u2
        sdd2, sdd3 = _solve2(c1, c2, aA - aAq - k3 - k2)
        aAj = aAq + k3 + sdd3 * u3
    _set_rates(kin, j, A, vAj, aAj, mq.omega, mq.eps)
    _set_rates(kin, i, A, vA, aA, mq.omega, mq.eps)
    kin.slides[j2.name] = (sd2, sdd2)
    kin.slides[j3.name] = (sd3, sdd3)


def _turn(jt: Joint) -> complex:
    """e^{i(α − α_s)}: a slider's rotation relative to the link carrying its guide."""
    assert jt.guide is not None
    return complex(np.exp(1j * (jt.guide.angle - jt.slider_angle)))


def _carried(kin: Kinematics, link: int, X: C) -> tuple[C, C]:
    """v and a of the point fixed to ``link`` that coincides with X now (zero on the frame)."""
    m = kin.motion[link]
    if link == kin.scene.frame:
        return m.v0, m.a0
    rel = X - m.r0
    v = m.v0 + 1j * m.omega * rel
    a = None if m.eps is None else m.a0 + (1j * m.eps - m.omega**2) * rel
    return v, a


_SOLVERS = {"RRR": _rrr, "RRP": _rrp, "RPR": _rpr, "PRP": _prp, "RPP": _rpp}
