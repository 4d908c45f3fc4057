"""The exact solvers of the five class-II Assur groups (RRR, RRP, RPR, PRP, RPP), each
written once for numpy arrays over positions and for plain Python numbers alike: positions
in closed form per group, velocities and accelerations from the group's vector loop as a
2×2 linear system (Cramer's rule).  :mod:`plans.kinematics.exact` runs them in the order
of the structure analysis and holds the result.
"""

from __future__ import annotations

import cmath
import math
from typing import Any

import numpy as np

from plans.errors import Indeterminate, Locked, NotAssemblable, Said
from plans.kinematics.context import Context, Motion, place_link, point_at
from plans.kinematics.structure import Group, Structure, TriadGroup
from plans.lines import cross
from plans.records import derived
from plans.scene.model import Guide, Joint, Scene
from plans.tolerances import ASSEMBLY_REL, LOCK_SIN

# numpy arrays over positions (or numbers at one position); typed loosely because numpy's
# operator stubs do not follow Optional fields that the order of analysis fills in.
C = Any  # complex128 array, shape (N,)
R = Any  # float64 array, shape (N,)


# --------------------------------------------------------------------------- helpers


def program(scene: Scene, st: Structure) -> list:
    """(solver, group, constants) per group, derived once per scene and structure."""
    kept = derived(scene)
    done = kept.get("exact")
    if done is None or done[0] is not st:
        done = kept["exact"] = (st, [_step(scene, g) for g in st.groups])
    return done[1]


def _step(scene: Scene, g: Any) -> tuple:
    if isinstance(g, TriadGroup):
        from plans.kinematics import triad_exact  # only mechanisms with a class-III group

        return triad_exact.solve_group, g, triad_exact.constants(scene, g)
    return _SOLVERS[g.kind], g, _CONSTANTS[g.kind](scene, g)


def _fail(cls, ctx: Context, g: Group, mask, point: str, why: str | Said):
    k = int(np.flatnonzero(np.atleast_1d(mask))[0])
    return cls(why, group=f"{g.kind} {g.name}", point=point, phi_deg=float(ctx.phis[k]))


def _carried(ctx: Context, link: int, X: C) -> tuple[C, C]:
    """v and a of the point fixed to ``link`` that coincides with X now (zero on the frame)."""
    m = ctx.motion[link]
    if link == ctx.frame:
        return m.v0, m.a0
    rel = X - m.r0
    v = m.v0 + 1j * m.omega * rel
    a = None if m.eps is None else m.a0 + (1j * m.eps - m.omega * m.omega) * rel
    return v, a


def _guide_line(ctx: Context, jt: Joint, constants: bool = False) -> tuple[C, C]:
    """Global origin and unit direction of a joint's guide (with ``constants``: plain numbers
    for a guide on the frame)."""
    assert jt.guide is not None
    if constants and jt.guide.link == ctx.frame:
        return jt.guide.origin, jt.guide.direction
    m = ctx.motion[jt.guide.link]
    return m.r0 + m.rot * jt.guide.origin, m.rot * jt.guide.direction


def _rates(ctx: Context, m: Motion, anchor: C, v: C, a: C, omega: R, eps: R) -> None:
    """Rates of a placed link from one point's v, a and the link's ω, ε."""
    rel = m.r0 - anchor if m.r0 is not anchor else None
    m.omega = omega
    m.v0 = v if rel is None else v + 1j * omega * rel
    if ctx.order >= 2:
        m.eps = eps
        m.a0 = a if rel is None else a + (1j * eps - omega * omega) * rel


class _System:
    """x1·c1 + x2·c2 = rhs for several right-hand sides with the same c1, c2 (Cramer);
    ``det`` = c1 × c2 is read before solving (to check for a lock)."""

    __slots__ = ("cc1", "c2", "det", "k1", "k2")

    def __init__(self, c1: C, c2: C) -> None:
        self.cc1 = c1.conjugate()
        self.c2 = c2
        self.det = (self.cc1 * c2).imag
        self.k1 = None

    def __call__(self, rhs: C) -> tuple[R, R]:
        if self.k1 is None:
            inv = 1.0 / self.det
            self.k1 = (-self.c2).conjugate() * inv  # x1 = cross(rhs, c2)/det = −Im(rhs·conj(c2))/det
            self.k2 = self.cc1 * inv  # x2 = cross(c1, rhs)/det = Im(conj(c1)·rhs)/det
        return (rhs * self.k1).imag, (rhs * self.k2).imag


def _lock(ctx: Context, g: Group, det: R, size: Any, point: str, system: _System | None = None,
          rhs: Any = None) -> None:
    """Condition number |c1||c2| / |c1 × c2|; parallel construction lines lock the group, or,
    where they coincide (the known velocity lies along them: a change point, such as a
    parallelogram's crank along its frame), leave the plan indeterminate."""
    adet = abs(det)
    if (ctx.xp.low(adet) <= LOCK_SIN * size) if isinstance(size, float) else (ctx.xp.low(adet / size) <= LOCK_SIN):
        bad = adet <= LOCK_SIN * size
        if system is not None and rhs is not None:
            k = int(np.flatnonzero(np.atleast_1d(bad))[0])
            c1 = complex(np.atleast_1d(system.cc1)[k if np.size(system.cc1) > 1 else 0]).conjugate()
            w = complex(np.atleast_1d(rhs)[k if np.size(rhs) > 1 else 0])
            if abs((c1.conjugate() * w).imag) <= LOCK_SIN * abs(c1) * abs(w) or abs(w) == 0:
                raise _fail(Indeterminate, ctx, g, bad, point,
                            Said("ka_construction_lines_coincide"))
        raise _fail(Locked, ctx, g, bad, point,
                    Said("ka_construction_lines_are"))
    ctx.conditions[g.name] = size / adet


def _root(ctx: Context, g: Group, x: R, y: R, scale: Any, point: str, why: Any) -> R:
    """sqrt(x·y) with x·y >= 0 up to rounding (relative to scale()²); below that not
    assemblable (``why(k)`` says why at the position k the error names)."""
    xp = ctx.xp
    x = x * y
    if xp.low(x) < 0:
        size = scale()
        bad = x < -ASSEMBLY_REL * size * size
        if (bad.any() if hasattr(bad, "any") else bad):
            k = int(np.flatnonzero(np.atleast_1d(bad))[0])
            raise _fail(NotAssemblable, ctx, g, bad, point, why(k))
        x = xp.maximum(x, 0.0)
    return xp.sqrt(x)


def _nth(x: Any, k: int) -> float:
    """The value at the position k an error names (a number alone is every position's)."""
    a = np.atleast_1d(np.asarray(x, dtype=float))
    return float(a[k] if a.size > 1 else a[0])


def _branch_hint(g: Group) -> Said:
    """Which ``[branches]`` entry picks the group's other assembly (where there are two)."""
    return Said("ka_branch_hint", name=g.name, branch=f"{-g.branch:+d}")


_NAMES: dict[Joint, str] = {}


def slide_name(jt: Joint) -> str:
    """A P joint's name (formatted once)."""
    nm = _NAMES.get(jt)
    if nm is None:
        nm = _NAMES[jt] = jt.name
    return nm


def _slot(jt: Joint) -> Guide:
    """The guide (a slot, a guide of a moving link) a P pair's block slides on."""
    guide = jt.guide
    assert guide is not None
    return guide


def slider_turn(jt: Joint) -> complex:
    """e^{i(α − α_s)}: a slider's rotation relative to the link carrying its guide."""
    return cmath.exp(1j * (_slot(jt).angle - jt.slider_angle))


def _rotation_of(ctx: Context, q: int, turn: complex) -> C:
    """Rotation of a link that keeps its angle to link q."""
    if q == ctx.frame:
        return ctx.xp.full(ctx.n, turn)
    return ctx.motion[q].rot * turn


# --------------------------------------------------------------------------- the five dyads


def _k_rrr(scene: Scene, g: Group) -> tuple:
    i, j = g.links
    j1, j2, j3 = g.joints
    p, q = g.known
    Li, Lj = scene.links[i], scene.links[j]
    zi = Li.points[j2.point] - Li.points[j1.point]
    zj = Lj.points[j2.point] - Lj.points[j3.point]
    l1, l3 = abs(zi), abs(zj)
    return (_local(scene, p, j1.point), _local(scene, q, j3.point), l1, l3,
            zi.conjugate() / l1, zj.conjugate() / l3,
            Li.points[j1.point], Lj.points[j3.point], 0.5 * (l1 * l1 - l3 * l3))


def _local(scene: Scene, link: int, name: str) -> complex:
    return scene.frame_points[name] if link == scene.frame else scene.links[link].points[name]


def _rrr(ctx: Context, g: Group, k: tuple) -> None:
    zp, zq, l1, l3, ci, cj, z1i, z3j, half_diff = k
    i, j = g.links
    j1, j2, j3 = g.joints
    p, q = g.known
    P1, vP1, aP1 = point_at(ctx, p, zp)
    P3, vP3, aP3 = point_at(ctx, q, zq)
    d = P3 - P1
    D = abs(d)
    if ctx.xp.low(D) <= ASSEMBLY_REL * (l1 + l3):
        raise _fail(NotAssemblable, ctx, g, D <= ASSEMBLY_REL * (l1 + l3), j2.point,
                    Said("ka_point_point_coincide", point=j1.point, point2=j3.point, point3=j2.point))
    # a along d, h across it; h² as (l1 − a)(l1 + a): no cancellation near a tangent assembly
    a = (half_diff + 0.5 * D * D) / D
    h = _root(ctx, g, l1 - a, l1 + a, lambda: l1 + l3 + D, j2.point,
              lambda k: Said("ka_cannot_span", ab=f"{j1.point}{j2.point}", l1=l1 * 1e3, cb=f"{j3.point}{j2.point}",
                             l3=l3 * 1e3, ac=f"{j1.point}{j3.point}", d=_nth(D, k) * 1e3, lo=abs(l1 - l3) * 1e3,
                             hi=(l1 + l3) * 1e3, hint=_branch_hint(g)))
    r1 = (a + 1j * h if g.branch > 0 else a - 1j * h) * (d / D)  # B − P1
    B = P1 + r1
    r3 = B - P3
    # rotations from the unit vectors along the links (|r1| = l1 only to rounding, which
    # a near-tangent assembly makes large)
    mi = place_link(ctx, i, r1 * (ci / abs(r1)), P1, z1i)
    mj = place_link(ctx, j, r3 * (cj / abs(r3)), P3, z3j)
    if ctx.order < 1:
        return
    # iωi r1 − iωj r3 = vP3 − vP1
    c1, c2 = 1j * r1, -1j * r3
    sys2 = _System(c1, c2)
    _lock(ctx, g, sys2.det, l1 * l3, j2.point, sys2, vP3 - vP1)
    wi, wj = sys2(vP3 - vP1)
    ei = ej = None
    if ctx.order >= 2:
        ei, ej = sys2(aP3 - aP1 + wi * wi * r1 - wj * wj * r3)
    _rates(ctx, mi, P1, vP1, aP1, wi, ei)
    _rates(ctx, mj, P3, vP3, aP3, wj, ej)


def _k_rrp(scene: Scene, g: Group) -> tuple:
    i, j = g.links
    j1, j2, j3 = g.joints
    Li, Lj = scene.links[i], scene.links[j]
    zi = Li.points[j2.point] - Li.points[j1.point]
    l1 = abs(zi)
    return (_local(scene, g.known[0], j1.point), l1, zi.conjugate() / l1, Li.points[j1.point],
            slider_turn(j3), Lj.points[j2.point])


def _rrp(ctx: Context, g: Group, k: tuple) -> None:
    zp, l1, ci, z1i, turn, zBj = k
    i, j = g.links
    j1, j2, j3 = g.joints
    p, q = g.known
    P1, vP1, aP1 = point_at(ctx, p, zp)
    G0, u = _guide_line(ctx, j3, constants=True)
    wu = (P1 - G0) * u.conjugate()  # t0 + i·e: along and across the guide
    t0, e = wu.real, wu.imag
    root = _root(ctx, g, l1 - e, l1 + e, lambda: l1, j2.point,
                 lambda k: Said("ka_shorter", ab=f"{j1.point}{j2.point}", l1=l1 * 1e3, d=abs(_nth(e, k)) * 1e3,
                                a=j1.point, b=j2.point, hint=_branch_hint(g)))
    B = G0 + (t0 + root if g.branch > 0 else t0 - root) * u
    r1 = B - P1
    mi = place_link(ctx, i, r1 * (ci / abs(r1)), P1, z1i)
    mj = place_link(ctx, j, _rotation_of(ctx, q, turn), B, zBj)
    if ctx.order < 1:
        return
    vBq, aBq = _carried(ctx, q, B)
    c1, c2 = 1j * r1, -u
    sys2 = _System(c1, c2)
    _lock(ctx, g, sys2.det, l1, j2.point, sys2, vBq - vP1)
    wi, sd = sys2(vBq - vP1)
    vB = sd * u if q == ctx.frame else vBq + sd * u
    mq = ctx.motion[q]
    ei = sdd = aB = None
    if ctx.order >= 2:
        if q == ctx.frame:
            ei, sdd = sys2(wi * wi * r1 - aP1)
            aB = sdd * u
        else:
            cor = 2j * mq.omega * sd * u
            ei, sdd = sys2(aBq + cor - aP1 + wi * wi * r1)
            aB = aBq + cor + sdd * u
    _rates(ctx, mi, P1, vP1, aP1, wi, ei)
    _rates(ctx, mj, B, vB, aB, mq.omega, mq.eps)
    ctx.slides[slide_name(j3)] = (sd, sdd)


def _k_rpr(scene: Scene, g: Group) -> tuple:
    i, j = g.links
    j1, j2, j3 = g.joints
    Lj = scene.links[j]
    guide = _slot(j2)
    c0 = guide.origin - Lj.points[j3.point]
    return (_local(scene, g.known[0], j1.point), _local(scene, g.known[1], j3.point),
            cross(guide.direction, c0), Lj.points[j3.point], slider_turn(j2),
            scene.links[i].points[j1.point])


def _rpr(ctx: Context, g: Group, k: tuple) -> None:
    zp, zq, ecc, z3j, turn, z1i = k
    i, j = g.links
    j1, j2, j3 = g.joints
    p, q = g.known
    xp = ctx.xp
    A, vA, aA = point_at(ctx, p, zp)
    Cq, vC, aC = point_at(ctx, q, zq)
    guide = _slot(j2)
    d = A - Cq
    D = abs(d)
    if xp.low(D) == 0 or xp.high(abs(ecc / xp.maximum(D, 1e-300))) > 1 + ASSEMBLY_REL:
        sin_ = ecc / np.where(D > 0, D, 1.0)
        bad = (D == 0) | (np.abs(sin_) > 1 + ASSEMBLY_REL)
        raise _fail(NotAssemblable, ctx, g, bad, j2.point,
                    Said("ka_slot_link_offset", j=j, v=abs(ecc), point=j3.point, point2=j1.point))
    s = xp.arcsin(xp.clip(ecc / D, -1.0, 1.0))
    psi = xp.angle(d)
    # θ_j: the slot through C + e^{iθ}c0 along e^{i(θ+α)} holds A iff D sin(ψ − θ − α) = ecc;
    # branch +1 puts A ahead along the slot
    tj = psi - guide.angle - s if g.branch > 0 else psi - guide.angle - math.pi + s
    mj = place_link(ctx, j, xp.exp(1j * tj), Cq, z3j)
    mi = place_link(ctx, i, mj.rot * turn, A, z1i)
    if ctx.order < 1:
        return
    u = mj.rot * guide.direction
    c1, c2 = 1j * d, u
    sys2 = _System(c1, c2)
    _lock(ctx, g, sys2.det, D, j2.point, sys2, vA - vC)
    wj, sd = sys2(vA - vC)
    ej = sdd = None
    if ctx.order >= 2:
        cor = 2j * wj * sd * u
        ej, sdd = sys2(aA - aC + wj * wj * d - cor)
    _rates(ctx, mj, Cq, vC, aC, wj, ej)
    _rates(ctx, mi, A, vA, aA, wj, ej)
    ctx.slides[slide_name(j2)] = (sd, sdd)


def _k_prp(scene: Scene, g: Group) -> tuple:
    return (slider_turn(g.joints[0]), slider_turn(g.joints[2]), scene.links[g.links[0]].points[g.joints[1].point],
            scene.links[g.links[1]].points[g.joints[1].point])


def _prp(ctx: Context, g: Group, k: tuple) -> None:
    turn1, turn3, zBi, zBj = k
    i, j = g.links
    j1, j2, j3 = g.joints
    p, q = g.known
    G1, u1 = _guide_line(ctx, j1)
    G3, u3 = _guide_line(ctx, j3)
    sys2 = _System(u1, -u3)
    det = sys2.det
    if ctx.xp.low(abs(det)) <= LOCK_SIN:
        raise _fail(NotAssemblable, ctx, g, abs(det) <= LOCK_SIN, j2.point,
                    Said("ka_two_guides_are"))
    ctx.conditions[g.name] = 1.0 / abs(det)
    s1, _ = sys2(G3 - G1)
    B = G1 + s1 * u1
    mp, mq = ctx.motion[p], ctx.motion[q]
    mi = place_link(ctx, i, _rotation_of(ctx, p, turn1), B, zBi)
    mj = place_link(ctx, j, _rotation_of(ctx, q, turn3), B, zBj)
    if ctx.order < 1:
        return
    vBp, aBp = _carried(ctx, p, B)
    vBq, aBq = _carried(ctx, q, B)
    sd1, sd3 = sys2(vBq - vBp)
    vB = vBp + sd1 * u1
    sdd1 = sdd3 = aB = None
    if ctx.order >= 2:
        k1 = 2j * mp.omega * sd1 * u1
        k3 = 2j * mq.omega * sd3 * u3
        sdd1, sdd3 = sys2(aBq + k3 - aBp - k1)
        aB = aBp + k1 + sdd1 * u1
    _rates(ctx, mi, B, vB, aB, mp.omega, mp.eps)
    _rates(ctx, mj, B, vB, aB, mq.omega, mq.eps)
    ctx.slides[slide_name(j1)] = (sd1, sdd1)
    ctx.slides[slide_name(j3)] = (sd3, sdd3)


def _k_rpp(scene: Scene, g: Group) -> tuple:
    i, j = g.links
    j1, j2, j3 = g.joints
    zK = scene.links[j].points[j3.point]
    return (_local(scene, g.known[0], j1.point), slider_turn(j3), zK, zK - _slot(j2).origin, slider_turn(j2),
            scene.links[i].points[j1.point])


def _rpp(ctx: Context, g: Group, k: tuple) -> None:
    zp, turn3, zK, zKg, turn2, z1i = k
    i, j = g.links
    j1, j2, j3 = g.joints
    p, q = g.known
    A, vA, aA = point_at(ctx, p, zp)
    G3, u3 = _guide_line(ctx, j3)
    mq = ctx.motion[q]
    rot = _rotation_of(ctx, q, turn3)
    u2 = rot * _slot(j2).direction
    sys2 = _System(u2, u3)
    det = sys2.det
    if ctx.xp.low(abs(det)) <= LOCK_SIN:
        raise _fail(NotAssemblable, ctx, g, abs(det) <= LOCK_SIN, j2.point,
                    Said("ka_slot_link_parallel", j=j, point=j2.point))
    ctx.conditions[g.name] = 1.0 / abs(det)
    # r0_j = G3 + t u3 − rot zK ; A on slot: cross(u2, A − G3 − t u3 + rot (zK − g2)) = 0
    t = cross(u2, A - G3 + rot * zKg) / det
    ctx.motion[j] = Motion(rot, G3 + t * u3 - rot * zK)
    mi = place_link(ctx, i, rot * turn2, A, z1i)
    if ctx.order < 1:
        return
    vAq, aAq = _carried(ctx, q, A)
    sd2, sd3 = sys2(vA - vAq)
    vAj = vAq + sd3 * u3
    sdd2 = sdd3 = aAj = None
    if ctx.order >= 2:
        if q == ctx.frame:
            sdd2, sdd3 = sys2(aA)
            aAj = sdd3 * u3
        else:
            k3 = 2j * mq.omega * sd3 * u3
            k2 = 2j * mq.omega * sd2 * u2
            sdd2, sdd3 = sys2(aA - aAq - k3 - k2)
            aAj = aAq + k3 + sdd3 * u3
    _rates(ctx, ctx.motion[j], A, vAj, aAj, mq.omega, mq.eps)
    _rates(ctx, mi, A, vA, aA, mq.omega, mq.eps)
    ctx.slides[slide_name(j2)] = (sd2, sdd2)
    ctx.slides[slide_name(j3)] = (sd3, sdd3)


_SOLVERS = {"RRR": _rrr, "RRP": _rrp, "RPR": _rpr, "PRP": _prp, "RPP": _rpp}
_CONSTANTS = {"RRR": _k_rrr, "RRP": _k_rrp, "RPR": _k_rpr, "PRP": _k_prp, "RPP": _k_rpp}
