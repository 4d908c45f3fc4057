"""The fast path over arrays of positions: the formulas of :mod:`plans.kinematics.fast`
with numpy arrays over positions, arranged for the fewest numpy calls.

At a few hundred positions a numpy call costs about as much as the arithmetic it does, so
what counts is how many there are: the constants are numpy's own (a Python number costs a
conversion at every call), temporaries are worked on in place, and what the analysis does
not read itself waits until it is read (:class:`plans.kinematics.fast.Later`): the
rotation of a link placed at its origin, a slider's velocity and acceleration, a group's
condition number.

The numbers are those of the one-position formulas operation for operation, with numpy's
fused products: a sign moved from the right-hand side into a factor, Im(conj(i·r1)·(−u))
read as Im(ũ·r1) with ũ = u_y + i·u_x, a product's real part instead of the imaginary part
of the same product turned by i; the same roundings (exact zeros may change sign).
"""

from __future__ import annotations

from typing import Any

import numpy as np

from plans.kinematics.fast import Later, Plan, placed, rotation, rrp_step, rrr_step, run_steps
from plans.tolerances import LOCK_SIN

_low = np.minimum.reduce  # the least element, without ndarray.min's Python wrapper
_ONE = np.array(1.0)
_I = np.array(1j)


def _c(x: Any) -> Any:
    """A constant as numpy's own (0-d array): no conversion at each array operation."""
    return np.array(x)


def solve(plan: Plan, phis: Any, order: int) -> tuple[dict, dict, dict] | None:
    """Motions, slides and conditions over the positions ``phis`` (an array), or None
    where the general solvers are needed."""
    steps = plan.vsteps
    if steps is None:
        steps = plan.vsteps = _array_steps(plan)
    return run_steps(plan, rotation(plan.ref_deg, plan.sense, phis), order, steps)


def _array_steps(plan: Plan) -> list:
    """The steps with their constants as numpy's; RRP groups one after another on the same
    pin (the cylinders of a V or radial engine on the crank pin) solved together, one row
    of (groups × positions) arrays each."""
    out: list = []
    run: list = []
    for st in plan.steps + [None]:
        if run and (st is None or st[0] is not rrp_step or st[3:5] != run[0][3:5]):
            out.append(_rrp_step(plan, run[0]) if len(run) == 1 else _rrp_batch(plan, run))
            run = []
        if st is None:
            continue
        if st[0] is rrp_step:
            run.append(st)
        else:
            assert st[0] is rrr_step
            _, i, j, p, zp, q, zq, l1, l3, ci, cj, z1i, z3j, half_diff, branch, name, near, size = st
            out.append((_rrr_arrays, i, j, p, zp, _local(plan, p, zp), q, zq, _local(plan, q, zq), _c(l1), ci, cj,
                        z1i, z3j, _c(half_diff), branch, name, near, size))
    return out


def _local(plan: Plan, link: int, z: complex) -> Any:
    """A point's local coordinates as numpy's, from the crank's pivot on the crank."""
    return _c(z - plan.zpivot if link == plan.crank else z)


def _rrp_step(plan: Plan, st: tuple) -> tuple:
    _, i, j, p, zp, l1, ci, z1i, turn, zBj, G0, u, cu, branch, name, slide, K, lock = st
    return (_rrp_arrays, i, j, p, zp, _local(plan, p, zp), _c(l1), z1i, turn, zBj, G0, _c(G0), _c(u),
            _c(complex(u.imag, u.real)), _c(cu), _c(-cu), u == 1, branch, name, slide, K, lock)


def _rrp_batch(plan: Plan, run: list) -> tuple:
    col = np.array
    return (_rrp_many, run[0][3], run[0][4], _local(plan, run[0][3], run[0][4]), tuple(run),
            col([[m[5]] for m in run]), col([[m[10]] for m in run]), any(m[10] for m in run),
            col([[m[11]] for m in run]), col([[complex(m[11].imag, m[11].real)] for m in run]),
            col([[m[12]] for m in run]), col([[-m[12]] for m in run]),
            col([[1.0 if m[13] > 0 else -1.0] for m in run]), all(m[13] > 0 for m in run),
            max(m[17] for m in run))


def _at(plan: Plan, motion: dict, pins: dict, link: int, z: complex, z0: Any, order: int) -> tuple:
    """r, v, a of the point with local coordinates z on a known moving link (z0: the same
    as numpy's, from the crank's pivot on the crank), as :func:`plans.kinematics.fast._at`."""
    key = (link, z)
    done = pins.get(key)  # a pin carries several groups (the V-engine's crank pin)
    if done is not None:
        return done
    if link == plan.crank:
        rel = motion[link][0] * z0
        done = (plan.pivot + rel if plan.pivot else rel, plan.W0 * rel if order >= 1 else None,
                plan.E0 * rel if order >= 2 else None)
    else:
        m = motion[link]
        rot, r0, w, v0, e, a0 = m
        if not z:
            done = (r0, v0, a0)
        else:
            if type(rot) is Later:
                rot = m[0] = rot()
            rel = rot * z0
            v = a = None
            if order >= 1:
                v = v0 + _I * w * rel
                if order >= 2:
                    a = a0 + (_I * e - w * w) * rel
            done = (r0 + rel, v, a)
    pins[key] = done
    return done


# --------------------------------------------------------------------------- read when asked


def _unit_turned(r: Any, c: Any) -> Any:
    """A rocker's rotation from its vector r, normalised as drawn."""
    return r * (c / abs(r))


def _rod(wu: Any, root: Any, K: complex) -> Any:
    """An RRP rod's rotation: q = ±√x − i·e (its vector along and across the guide) by K."""
    q = wu.conjugate()
    q.real = root
    return q * K


def _condition_rrr(inv: Any, size: float) -> Any:
    cond = abs(inv)
    cond *= size  # |c1||c2| / |det|
    return cond


def _condition_rrp(l1: float, det: Any) -> Any:
    return l1 / abs(det)


# --------------------------------------------------------------------------- the dyads


def _rrr_arrays(plan: Plan, motion: dict, pins: dict, slides: dict, conditions: dict, k: tuple,
                order: int) -> bool:
    """:func:`plans.kinematics.fast.rrr_step` over arrays."""
    _, i, j, p, zp, zp0, q, zq, zq0, l1, ci, cj, z1i, z3j, half_diff, branch, name, near, size = k
    P1: Any
    vP1: Any
    aP1: Any
    if p == plan.frame:
        P1, vP1, aP1 = zp0, None, None
    else:
        P1, vP1, aP1 = _at(plan, motion, pins, p, zp, zp0, order)
    if q == plan.frame:
        P3, vP3, aP3 = zq0, None, None
    else:
        P3, vP3, aP3 = _at(plan, motion, pins, q, zq, zq0, order)
    d = P3 - P1
    D = np.abs(d)
    Dm = _low(D)
    if Dm <= near:
        return False
    invD = _ONE / D
    D *= 0.5
    a = half_diff * invD
    a += D  # a = half_diff/D + D/2
    x = l1 - a
    x *= l1 + a
    xm = _low(x)
    # the lock (|r1 × r3| = h·D ≤ LOCK_SIN·l1·l3) looked for here, with a margin (the general
    # solvers decide at the limit)
    if xm < 0 or (order and xm <= (2 * LOCK_SIN * size / Dm) ** 2):
        return False
    r1 = np.empty(len(x), dtype=complex)  # a ± i·h, then turned along d: B − P1
    r1.real = a
    h = r1.imag
    np.sqrt(x, out=h)
    if branch < 0:
        np.subtract(0.0, h, out=h)
    d *= invD
    r1 *= d
    r3 = P1 + r1
    r3 -= P3
    # the rotations from the unit vectors along the links (|r1| = l1 to rounding)
    roti = r1 * ci if z1i else Later(np.multiply, r1, ci)
    rotj = _unit_turned(r3, cj) if z3j else Later(_unit_turned, r3, cj)
    if order < 1:
        motion[i] = placed(roti, zp if p == plan.frame else P1, z1i, None, None, None, None, 0)
        motion[j] = placed(rotj, zq if q == plan.frame else P3, z3j, None, None, None, None, 0)
        return True
    # iωi r1 − iωj r3 = vP3 − vP1 by Cramer's rule, as the one-position formulas: with
    # numpy's fused products det = Im(conj(i r1)·(−i r3)) is Im(conj(r3)·r1), and ωi, ωj the
    # real parts of the negated right-hand side by conj(r3)/det, conj(r1)/det
    k1 = r3.conjugate()
    det = (k1 * r1).imag
    inv = _ONE / det
    conditions[name] = Later(_condition_rrr, inv, size)
    k1 *= inv
    k2 = r1.conjugate()
    k2 *= inv
    rhs = vP1 if vP3 is None else -vP3 if vP1 is None else vP1 - vP3
    wi, wj = (rhs * k1).real, (rhs * k2).real
    ei = ej = None
    if order >= 2:
        base = aP1 if aP3 is None else -aP3 if aP1 is None else aP1 - aP3
        t = wi * wi
        rhs = t * r1
        np.subtract(base, rhs, out=rhs)
        t = wj * wj
        rhs += t * r3
        ei, ej = (rhs * k1).real, (rhs * k2).real
    if vP1 is None:  # on the frame: the point as a number (the same at every position)
        P1, vP1, aP1 = zp, 0j, 0j
    if vP3 is None:
        P3, vP3, aP3 = zq, 0j, 0j
    if z1i or z3j or order < 2:
        motion[i] = placed(roti, P1, z1i, vP1, aP1, wi, ei, order)
        motion[j] = placed(rotj, P3, z3j, vP3, aP3, wj, ej, order)
    else:
        motion[i] = [roti, P1, wi, vP1, ei, aP1]
        motion[j] = [rotj, P3, wj, vP3, ej, aP3]
    return True


def _rrp_rates(r1: Any, su: Any, ncu: Any, vP1: Any, aP1: Any, order: int) -> tuple:
    """An RRP group's rates: iωi r1 − ṡ u = −vP1 by Cramer's rule, as the one-position
    formulas (numpy's fused products): det = Im(conj(i r1)·(−u)) is Im(ũ·r1), ũ = u_y + i·u_x;
    the right-hand side's sign moved into k1, k2 = conj(r1)/det (ṡ a real part where it was
    an imaginary one).  Returns det, ωi, ṡ and, at order 2, εi and s̈ (else None)."""
    det = (su * r1).imag
    inv = _ONE / det
    k1 = ncu * inv
    k2 = r1.conjugate()
    k2 *= inv
    wi, sd = (vP1 * k1).imag, (vP1 * k2).real
    ei = sdd = None
    if order >= 2:
        t = wi * wi
        rhs = t * r1
        np.subtract(aP1, rhs, out=rhs)
        ei, sdd = (rhs * k1).imag, (rhs * k2).real
    return det, wi, sd, ei, sdd


def _rrp_arrays(plan: Plan, motion: dict, pins: dict, slides: dict, conditions: dict, k: tuple,
                order: int) -> bool:
    """:func:`plans.kinematics.fast.rrp_step` over arrays."""
    _, i, j, p, zp, zp0, l1, z1i, turn, zBj, g0, G0, u, su, cu, ncu, along_x, branch, name, slide, K, lock = k
    P1, vP1, aP1 = _at(plan, motion, pins, p, zp, zp0, order)
    if g0:
        wu = P1 - G0
        wu *= cu  # t0 + i·e: P1 along and across the guide
    else:
        wu = P1 * cu
    t0, e = wu.real, wu.imag
    x = l1 - e
    x *= l1 + e
    # the system's determinant below is ±√x to rounding: a lock is √x ≤ LOCK_SIN·l1 (looked
    # for here, with a margin: the general solvers decide at the limit)
    xm = _low(x)
    if xm < 0 or (order and xm <= lock):
        return False
    root = np.sqrt(x, out=x)
    if branch < 0:
        np.negative(root, out=root)
    B = t0 + root
    if along_x and g0:  # (s + 0i)·1 + G0 is s + G0, the same numbers
        B = B + G0
    else:
        B = B * u
        if g0:
            B += G0
    rot = _rod(wu, root, K) if z1i else Later(_rod, wu, root, K)
    if order < 1:
        motion[i] = placed(rot, P1, z1i, None, None, None, None, 0)
        motion[j] = placed(turn, B, zBj, None, None, None, None, 0)
        return True
    r1 = B - P1
    det, wi, sd, ei, sdd = _rrp_rates(r1, su, ncu, vP1, aP1, order)
    conditions[name] = Later(_condition_rrp, l1, det)
    if z1i or zBj:
        motion[i] = placed(rot, P1, z1i, vP1, aP1, wi, ei, order)
        motion[j] = placed(turn, B, zBj, sd * u, None if sdd is None else sdd * u, 0.0, 0.0, order)
    else:
        motion[i] = [rot, P1, wi, vP1, ei, aP1]
        motion[j] = [turn, B, 0.0, Later(np.multiply, sd, u), 0.0 if order >= 2 else None,
                     Later(np.multiply, sdd, u) if order >= 2 else None]
    slides[slide] = (sd, sdd)
    return True


def _rrp_many(plan: Plan, motion: dict, pins: dict, slides: dict, conditions: dict, k: tuple,
              order: int) -> bool:
    """RRP groups on the same pin, each a row of (groups × positions) arrays: the formulas
    of :func:`_rrp_arrays` with the constants as columns."""
    _, p, zp, zp0, groups, l1, G0, g0, u, su, cu, ncu, sgn, ahead, lock = k
    P1, vP1, aP1 = _at(plan, motion, pins, p, zp, zp0, order)
    if g0:
        wu = P1 - G0
        wu *= cu
    else:
        wu = P1 * cu
    t0, e = wu.real, wu.imag
    x = l1 - e
    x *= l1 + e
    xm = _low(x, axis=None)
    if xm < 0 or (order and xm <= lock):  # not assembled, or at or near a lock somewhere
        return False
    root = np.sqrt(x, out=x)
    if not ahead:
        root *= sgn
    B = t0 + root
    B = B * u
    if g0:
        B += G0
    if order < 1:
        for r, g in enumerate(groups):
            rot = _rod(wu[r], root[r], g[16]) if g[7] else Later(_rod, wu[r], root[r], g[16])
            motion[g[1]] = placed(rot, P1, g[7], None, None, None, None, 0)
            motion[g[2]] = placed(g[8], B[r], g[9], None, None, None, None, 0)
        return True
    r1 = B - P1
    det, wi, sd, ei, sdd = _rrp_rates(r1, su, ncu, vP1, aP1, order)
    for r, g in enumerate(groups):
        rot = _rod(wu[r], root[r], g[16]) if g[7] else Later(_rod, wu[r], root[r], g[16])
        sdr, sddr = sd[r], None if sdd is None else sdd[r]
        ur = g[11]
        motion[g[1]] = placed(rot, P1, g[7], vP1, aP1, wi[r], None if ei is None else ei[r], order)
        if g[9]:
            motion[g[2]] = placed(g[8], B[r], g[9], sdr * ur, None if sddr is None else sddr * ur, 0.0, 0.0,
                                   order)
        else:
            motion[g[2]] = [g[8], B[r], 0.0, Later(np.multiply, sdr, ur), 0.0 if order >= 2 else None,
                            None if sddr is None else Later(np.multiply, sddr, ur)]
        conditions[g[14]] = Later(_condition_rrp, g[5], det[r])
        slides[g[15]] = (sdr, sddr)
    return True
