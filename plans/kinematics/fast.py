"""The exact analysis's fast path for the usual mechanism: a crank and RRR/RRP dyads (each
RRP's guide on the frame), in any chain.

The same formulas as the general solvers of :mod:`plans.kinematics.exact`, in the same
order, with everything that depends only on the scene worked out once (:func:`plan_for`) and
no bookkeeping per group beyond local variables: one function per dyad kind on plain Python
numbers for one position, and the same over numpy arrays of positions in
:mod:`.fast_arrays`.  What is constant over the positions (the frame, the crank's ω and ε, a
slider's angle) stays one number, and what the analysis never reads itself waits
(:class:`Later`): :mod:`.exact` makes arrays of them only when they are read.

Whatever is out of the ordinary (a group that does not assemble somewhere, an assembly at
the tangent, a lock) is not handled here: the solve returns None and the general solvers
run instead, and they give the draftsman's answer or the error that names the group.
"""

from __future__ import annotations

import cmath
import math
from typing import Any

import numpy as np

from plans.kinematics.structure import Structure
from plans.records import derived
from plans.scene.model import Scene
from plans.tolerances import ASSEMBLY_REL, LOCK_SIN

#: A link's motion while solving: [rot, r0, ω, v0, ε, a0] (numbers, arrays or None).
Motion = list

_QUARTER = np.array([1, 1j, -1, -1j])
#: i^k for k in [-4096, 4096) by k itself (numpy's negative indices): no k mod 4 to work out
_QUARTERS = np.tile(_QUARTER, 1024)
_NINETY, _MINUS_NINETY, _DEGREE = np.array(90.0), np.array(-90.0), np.array(1j * math.pi / 180.0)


class Later:
    """A quantity over the positions worked out when first read, from arrays that stay as
    they are (a link's rotation, a group's condition number: the analysis does not read
    them itself)."""

    __slots__ = ("fn", "args")

    def __init__(self, fn: Any, *args: Any) -> None:
        self.fn = fn
        self.args = args

    def __call__(self) -> Any:
        return self.fn(*self.args)


def rotation(ref_deg: float, sense: int, phis: Any) -> Any:
    """e^{iθ1} over positions, θ1 = ref + sense·φ reduced by whole quarter turns in degrees
    first (as :meth:`plans.scene.model.Driver.rotation`), so that a dead centre's small
    offset is kept exactly."""
    phis = np.fmod(phis, 360.0)  # exact for every float (the remainder is representable)
    t = phis if sense == 1 and ref_deg == 0 else ref_deg + sense * phis
    q = t / _NINETY
    np.rint(q, out=q)
    k = q.astype(np.intp)
    try:
        quarter = _QUARTERS[k]
    except IndexError:  # beyond ±368640°
        k &= 3
        quarter = _QUARTER[k]
    q *= _MINUS_NINETY
    q += t  # the remainder in degrees, in place (the same numbers as t − 90·q)
    z = q * _DEGREE
    np.exp(z, out=z)
    z *= quarter
    return z


def rotation1(ref_deg: float, sense: int, phi: float) -> complex:
    """e^{iθ1} of one position, reduced by quarter turns like :func:`rotation`."""
    t = ref_deg + sense * math.fmod(phi, 360.0)  # exact for every float
    q = round(t / 90.0)
    r = t - 90.0 * q
    return (1, 1j, -1, -1j)[int(q) % 4] * cmath.exp(1j * math.radians(r))


class Plan:
    """What the fast path needs of a scene, worked out once."""

    __slots__ = ("frame", "crank", "pivot", "zpivot", "W", "E", "W0", "E0", "omega", "eps", "ref_deg", "sense",
                 "steps", "vsteps")

    def __init__(self, scene: Scene, steps: list) -> None:
        d = scene.driver
        self.frame = scene.frame
        self.crank = d.link
        self.pivot = scene.frame_points[d.pivot]
        self.zpivot = scene.links[d.link].points[d.pivot]
        self.omega, self.eps = d.omega, d.eps
        self.W = 1j * d.omega
        self.E = complex(-d.omega * d.omega, d.eps)
        self.W0, self.E0 = np.array(self.W), np.array(self.E)  # numpy's own, for products with arrays
        self.ref_deg = math.degrees(d.phi_ref)
        self.sense = d.sense
        self.steps = steps
        self.vsteps: list | None = None  # the steps over arrays (plans.kinematics.fast_arrays)


def plan_for(scene: Scene, st: Structure) -> Plan | None:
    """The fast path's plan of ``scene``, or None where the general solvers are needed."""
    kept = derived(scene)
    done = kept.get("fast")
    if done is None or done[0] is not st:
        done = kept["fast"] = (st, _make_plan(scene, st))
    return done[1]


def _local(scene: Scene, link: int, name: str) -> complex:
    return scene.frame_points[name] if link == scene.frame else scene.links[link].points[name]


def _real(z: complex) -> complex | float:
    """z as a real number where it is one (real by complex arrays is the cheaper product)."""
    return z.real if z.imag == 0 else z


def _make_plan(scene: Scene, st: Structure) -> Plan | None:
    if st.triads():  # a class-III group is placed by Newton: general path
        return None
    steps: list[tuple] = []
    frame = scene.frame
    for g in st.groups:
        i, j = g.links
        j1, j2, j3 = g.joints
        p, q = g.known
        if p == frame and q == frame:  # a group on the frame alone does not move: general path
            return None
        Li, Lj = scene.links[i], scene.links[j]
        zi = Li.points[j2.point] - Li.points[j1.point]
        l1 = abs(zi)
        if g.kind == "RRR":
            zj = Lj.points[j2.point] - Lj.points[j3.point]
            l3 = abs(zj)
            steps.append((rrr_step, i, j, p, _local(scene, p, j1.point), q, _local(scene, q, j3.point), l1, l3,
                          zi.conjugate() / (l1 * l1), _real(zj.conjugate() / l3), Li.points[j1.point],
                          Lj.points[j3.point],
                          0.5 * (l1 * l1 - l3 * l3), g.branch, g.name, ASSEMBLY_REL * (l1 + l3), l1 * l3))
        elif g.kind == "RRP" and j3.guide is not None and j3.guide.link == frame:
            guide = j3.guide
            u = guide.direction
            steps.append((rrp_step, i, j, p, _local(scene, p, j1.point), l1, zi.conjugate() / l1, Li.points[j1.point],
                          cmath.exp(1j * (guide.angle - j3.slider_angle)), Lj.points[j2.point], guide.origin, u,
                          u.conjugate(), g.branch, g.name, j3.name, u * zi.conjugate() / (l1 * l1),
                          (2 * LOCK_SIN * l1) ** 2))
        else:
            return None
    return Plan(scene, steps)


# --------------------------------------------------------------------------- the solve


def solve_one(plan: Plan, phi: float, order: int) -> tuple[dict, dict, dict] | None:
    """The same at one position, in Python numbers, or None."""
    return run_steps(plan, rotation1(plan.ref_deg, plan.sense, phi), order, plan.steps)


def crank_motion(plan: Plan, rot1: Any, order: int) -> Motion:
    """The crank's motion from e^{iθ1} (a number or an array): its origin and rates where its
    pivot is not at the origin; ω and ε stay the driver's numbers."""
    z = plan.zpivot
    if z:
        rel = -rot1 * z  # the crank's origin from its pivot
        m1 = [rot1, plan.pivot + rel, None, None, None, None]
        if order >= 1:
            m1[2], m1[3] = plan.omega, plan.W * rel
            if order >= 2:
                m1[4], m1[5] = plan.eps, plan.E * rel
    else:
        m1 = [rot1, plan.pivot, None, None, None, None]
        if order >= 1:
            m1[2], m1[3] = plan.omega, 0j
            if order >= 2:
                m1[4], m1[5] = plan.eps, 0j
    return m1


def run_steps(plan: Plan, rot1: Any, order: int, steps: list) -> tuple[dict, dict, dict] | None:
    """The crank's motion, then each group's step (numbers or arrays alike), or None where a
    step leaves it to the general solvers."""
    motion: dict[int, Motion] = {plan.frame: [1 + 0j, 0j, 0.0, 0j, 0.0, 0j]}
    motion[plan.crank] = crank_motion(plan, rot1, order)
    pins: dict[tuple[int, complex], tuple] = {}
    slides: dict[str, tuple] = {}
    conditions: dict[str, Any] = {}
    for step in steps:
        if not step[0](plan, motion, pins, slides, conditions, step, order):
            return None
    return motion, slides, conditions


def _at(plan: Plan, motion: dict, pins: dict, link: int, z: complex, order: int) -> tuple:
    """r, v, a of the point with local coordinates z on a known link (v, a None on the frame
    and where not ordered)."""
    if link == plan.frame:
        return z, None, None
    key = (link, z)
    done = pins.get(key)  # a pin carries several groups (the V-engine's crank pin)
    if done is not None:
        return done
    if link == plan.crank:
        rel = motion[link][0] * (z - plan.zpivot)
        done = (plan.pivot + rel if plan.pivot else rel, plan.W * rel if order >= 1 else None,
                plan.E * rel if order >= 2 else None)
    else:
        rot, r0, w, v0, e, a0 = motion[link]
        if not z:
            done = (r0, v0, a0)
        else:
            rel = rot * z
            v = a = None
            if order >= 1:
                v = v0 + 1j * w * rel
                if order >= 2:
                    a = a0 + (1j * e - w * w) * rel
            done = (r0 + rel, v, a)
    pins[key] = done
    return done


def placed(rot: Any, anchor: Any, z: complex, v: Any, a: Any, omega: Any, eps: Any, order: int) -> Motion:
    """A link placed by its rotation and one of its points (local z, velocity v, acceleration
    a), with its ω and ε (as far as ordered); a rotation left until read (:class:`Later`,
    over arrays) is worked out here when the origin needs it."""
    if not z:  # the point is the link's origin
        if order >= 2:
            return [rot, anchor, omega, v, eps, a]
        return [rot, anchor, omega, v, None, None] if order else [rot, anchor, None, None, None, None]
    if type(rot) is Later:
        rot = rot()
    rel = -rot * z  # the origin from the point
    m = [rot, anchor + rel, None, None, None, None]
    if order >= 1:
        m[2], m[3] = omega, v + 1j * omega * rel
        if order >= 2:
            m[4], m[5] = eps, a + (1j * eps - omega * omega) * rel
    return m


def rrr_step(plan: Plan, motion: dict, pins: dict, slides: dict, conditions: dict, k: tuple, order: int) -> bool:
    """An RRR group at one position (over arrays: :mod:`plans.kinematics.fast_arrays`)."""
    _, i, j, p, zp, q, zq, l1, l3, ci, cj, z1i, z3j, half_diff, branch, name, near, size = k
    P1: Any
    vP1: Any
    aP1: Any
    if p == plan.frame:
        P1, vP1, aP1 = zp, None, None
    else:
        P1, vP1, aP1 = _at(plan, motion, pins, p, zp, order)
    if q == plan.frame:
        P3, vP3, aP3 = zq, None, None
    else:
        P3, vP3, aP3 = _at(plan, motion, pins, q, zq, order)
    d = P3 - P1
    D = abs(d)
    if D <= near:
        return False
    invD = 1.0 / D
    a = half_diff * invD + 0.5 * D
    x = (l1 - a) * (l1 + a)
    if x < 0:
        return False
    h = math.sqrt(x)
    r1 = (a + 1j * h if branch > 0 else a - 1j * h) * (d * invD)  # B − P1
    r3 = P1 + r1 - P3
    # |r1| = l1 to rounding (from a and h, no cancellation); r3 is normalised as drawn
    roti = r1 * ci
    rotj = r3 * (cj / abs(r3))
    if order < 1:
        motion[i] = placed(roti, P1, z1i, None, None, None, None, 0)
        motion[j] = placed(rotj, P3, z3j, None, None, None, None, 0)
        return True
    # iωi r1 − iωj r3 = vP3 − vP1, by Cramer's rule as assur._System
    c2 = -1j * r3
    cc1 = (1j * r1).conjugate()
    det = (cc1 * c2).imag
    if abs(det) <= LOCK_SIN * size:
        return False
    inv = 1.0 / det
    cond = abs(inv)
    cond *= size  # |c1||c2| / |det|
    conditions[name] = cond
    k1 = c2.conjugate() * -inv
    k2 = cc1 * inv
    rhs = -vP1 if vP3 is None else vP3 if vP1 is None else vP3 - vP1
    wi, wj = (rhs * k1).imag, (rhs * k2).imag
    ei = ej = None
    if order >= 2:
        rhs = -aP1 if aP3 is None else aP3 if aP1 is None else aP3 - aP1
        rhs = rhs + wi * wi * r1 - wj * wj * r3
        ei, ej = (rhs * k1).imag, (rhs * k2).imag
    if vP1 is None:
        vP1 = aP1 = 0j
    if vP3 is None:
        vP3 = aP3 = 0j
    motion[i] = placed(roti, P1, z1i, vP1, aP1, wi, ei, order)
    motion[j] = placed(rotj, P3, z3j, vP3, aP3, wj, ej, order)
    return True


def rrp_step(plan: Plan, motion: dict, pins: dict, slides: dict, conditions: dict, k: tuple, order: int) -> bool:
    """An RRP group (its guide on the frame) at one position (over arrays:
    :mod:`plans.kinematics.fast_arrays`)."""
    _, i, j, p, zp, l1, ci, z1i, turn, zBj, G0, u, cu, branch, name, slide, K, lock = k
    P1, vP1, aP1 = _at(plan, motion, pins, p, zp, order)
    wu = (P1 - G0) * cu if G0 else P1 * cu  # t0 + i·e: P1 along and across the guide
    t0, e = wu.real, wu.imag
    x = (l1 - e) * (l1 + e)
    # the system's determinant below is ±√x to rounding: a lock is √x ≤ LOCK_SIN·l1 (looked
    # for here, with a margin: the general solvers decide at the limit)
    if x < 0 or (order and x <= lock):
        return False
    rt = math.sqrt(x)
    root = rt if branch > 0 else -rt
    # the rod B − P1 along and across the guide: q = ±√x − i·e (|q| = l1 to rounding,
    # with no cancellation near a tangent assembly, unlike B − P1)
    q = complex(root, -e)
    B = (t0 + root) * u
    if G0:
        B = G0 + B
    mi_rot = q * K  # K = u·conj(z_B − z_P1)/l1²: the rod's rotation
    if order < 1:
        motion[i] = placed(mi_rot, P1, z1i, None, None, None, None, 0)
        motion[j] = placed(turn, B, zBj, None, None, None, None, 0)
        return True
    # iωi r1 − ṡ u = −vP1 (the guide on the frame), by Cramer's rule with assur._System's
    # numbers (a dead centre's exact zeros kept)
    r1 = B - P1
    cc1 = (1j * r1).conjugate()
    det = (cc1 * -u).imag
    conditions[name] = l1 / abs(det)
    inv = 1.0 / det
    k1 = cu * inv
    k2 = cc1 * inv
    nv = -vP1
    wi, sd = (nv * k1).imag, (nv * k2).imag
    ei = sdd = aB = None
    if order >= 2:
        rhs = wi * wi * r1 - aP1
        ei, sdd = (rhs * k1).imag, (rhs * k2).imag
        aB = sdd * u
    motion[i] = placed(mi_rot, P1, z1i, vP1, aP1, wi, ei, order)
    motion[j] = placed(turn, B, zBj, sd * u, aB, 0.0, 0.0, order)
    slides[slide] = (sd, sdd)
    return True
