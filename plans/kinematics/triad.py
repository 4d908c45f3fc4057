"""The class-III Assur group of the third order (a triad), exactly and by Assur's special point.

A base link carries three inner pairs D, E, F; three leashes join them to outer pairs A, B,
C of links already known: |AD| = l1, |BE| = l2, |CF| = l3.  The base link's place (D and
its angle θ) has no closed form: a Newton solve on the three leash equations, started from
the previous position (the branch is the one the group is assembled in, kept by
continuation).  Velocities and accelerations are then linear: three equations
(P − Q)·(v_P − v_Q) = 0, and their derivative.

The graphical route (the textbook's): the axes of leashes AD and BE meet at Assur's special
point S, taken as a point of the base link.  v_S − v_A ⟂ AD and v_S − v_B ⟂ BE (each the sum
of the leash's turn and the base's turn about a point of that leash's axis): two lines of the
velocity plan meet at s.  Then f: v_F = v_S + ω·(F − S)⊥ with v_F − v_C ⟂ CF fixes ω, and d,
e follow by similarity.  The acceleration plan is built the same way, with the normal terms
along the leashes (−ω_leash²·QP) and along the axis through S (−ω²·PS).  Parallel axes AD ∥ BE take the other pair's point; all three axes
through one point (or all parallel) is the group's special position: ω is then not fixed.

Plane vectors are complex numbers; the base link's local frame has its origin at D.
"""

from __future__ import annotations

import cmath
import math

from plans.errors import Said
from plans.records import frozen
from plans.tolerances import LOCK_SIN


def _dot(a: complex, b: complex) -> float:
    return (a.conjugate() * b).real


def _cross(a: complex, b: complex) -> float:
    return (a.conjugate() * b).imag


@frozen
class Triad:
    """E and F in the base link's frame (origin D, x axis at angle θ), the leash lengths.

    A leash may be a slider instead (``guides[k]`` its guide's unit direction, fixed to the
    frame): its inner pair then moves along the guide through its outer point (the guide's
    origin, passed as the outer point), and its "axis" (the line the special point is taken
    on) is the normal to the guide through the inner pair."""

    zE: complex
    zF: complex
    l1: float
    l2: float
    l3: float
    name: str = "triad"
    guides: tuple[complex | None, complex | None, complex | None] = (None, None, None)
    #: a leash that is a block pinned at its outer pair and sliding in a slot of the base link:
    #: the slot's unit direction in the base's frame (its origin is the leash's inner point:
    #: D, E or F above); the "inner pair" is then the pin itself, where the slot passes
    slots: tuple[complex | None, complex | None, complex | None] = (None, None, None)

    def inner(self, rD: complex, theta: float) -> tuple[complex, complex, complex]:
        rot = cmath.exp(1j * theta)
        return rD, rD + rot * self.zE, rD + rot * self.zF

    @property
    def size(self) -> float:
        return max(abs(self.zE), abs(self.zF), self.l1, self.l2, self.l3)


class SpecialPosition(ValueError):
    """The group has no unique velocity state (or no place) at this position: ``said`` is
    why, a sentence of the catalogue (the message names the group too)."""

    def __init__(self, group: str, said: Said) -> None:
        self.said = said
        super().__init__(f"group {group}: {said.text('en')}")


def place(t: Triad, outer: tuple[complex, complex, complex], guess: tuple[complex, float],
          tol: float = 1e-13, iterations: int = 60) -> tuple[complex, float]:
    """(r_D, θ) with every leash at its length, by Newton from ``guess``."""
    rD, th = guess
    for _ in range(iterations):
        P = t.inner(rD, th)
        rot = cmath.exp(1j * th)
        arms = (0j, rot * t.zE, rot * t.zF)
        f, J = [], []
        for k in range(3):
            n = _normal(t, k, P[k], outer[k], rot)  # the row is n·(δr_D + δθ·i·arm)
            turn = _dot(n, 1j * arms[k])
            if t.slots[k] is not None:  # the slot's normal turns with the base too
                turn += _dot(1j * n, P[k] - outer[k])
            J.append([n.real, n.imag, turn])
            f.append(_residual(t, k, P[k], outer[k], rot))
        step = _solve3(J, [-x for x in f])
        if step is None:
            raise SpecialPosition(t.name, Said("sp_singular"))
        rD += complex(step[0], step[1])
        th += step[2]
        if max(abs(step[0]), abs(step[1]), abs(step[2]) * t.size) <= tol * t.size:
            return rD, th
    raise SpecialPosition(t.name, Said("sp_no_place"))


def _lengths(t: Triad) -> tuple[float, float, float]:
    return t.l1, t.l2, t.l3


def _normal(t: Triad, k: int, P: complex, Q: complex, rot: complex = 1) -> complex:
    """The gradient of leash k's equation in the inner pair's position: P − Q for a revolute
    leash (|P − Q|² = l², halved), i·g for a slider on the guide g through Q, the slot's
    normal (turned with the base) for a block in a slot of the base."""
    g, sl = t.guides[k], t.slots[k]
    if sl is not None:
        return 1j * rot * sl
    return P - Q if g is None else 1j * g


def _residual(t: Triad, k: int, P: complex, Q: complex, rot: complex = 1) -> float:
    g = t.guides[k]
    if t.slots[k] is not None:  # the pin's distance from the slot's line (P: the slot's origin)
        return _dot(_normal(t, k, P, Q, rot), P - Q)
    if g is None:
        return (abs(P - Q) ** 2 - _lengths(t)[k] ** 2) / 2
    return _dot(1j * g, P - Q)  # the pin's distance from the guide's line


def pair_points(t: Triad, outer: tuple[complex, complex, complex], rD: complex, theta: float) -> list[complex]:
    """Where each leash meets the base link: its inner pair, or the pin of a block in a slot."""
    P = t.inner(rD, theta)
    return [outer[k] if t.slots[k] is not None else P[k] for k in range(3)]


def determinant(t: Triad, outer: tuple[complex, complex, complex], rD: complex, theta: float) -> float:
    """The determinant of the leash equations' matrix (the velocity equations), each row scaled
    to unit length: its sign marks the branch, zero the group's special position."""
    P = pair_points(t, outer, rD, theta)
    rot = cmath.exp(1j * theta)
    rows = []
    for k in range(3):
        n = _normal(t, k, P[k], outer[k], rot)
        row = [n.real, n.imag, _dot(n, 1j * (P[k] - rD)) / t.size]
        size = math.sqrt(sum(x * x for x in row)) or 1.0
        rows.append([x / size for x in row])
    m = rows
    return (m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1]) - m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0])
            + m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0]))


def _solve3(J: list[list[float]], b: list[float]) -> list[float] | None:
    """Cramer's rule; None where the system is singular to rounding."""
    def det(m: list[list[float]]) -> float:
        return (m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1]) - m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0])
                + m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0]))
    D = det(J)
    scale = max(abs(x) for row in J for x in row) ** 3
    if abs(D) <= 1e-14 * scale:
        return None
    out = []
    for c in range(3):
        m = [[b[r] if cc == c else J[r][cc] for cc in range(3)] for r in range(3)]
        out.append(det(m) / D)
    return out


def rates(t: Triad, outer: tuple[complex, complex, complex], rD: complex, theta: float,
          v_outer: tuple[complex, complex, complex],
          a_outer: tuple[complex, complex, complex] | None = None) -> tuple[complex, float, complex | None, float | None]:
    """(v_D, ω, a_D, ε) of the base link from the leash equations (exact, not graphical)."""
    P = pair_points(t, outer, rD, theta)
    rot = cmath.exp(1j * theta)
    arms = [P[k] - rD for k in range(3)]
    d = [_normal(t, k, P[k], outer[k], rot) for k in range(3)]
    J = [[d[k].real, d[k].imag, _dot(d[k], 1j * arms[k])] for k in range(3)]
    x = _solve3(J, [_dot(d[k], v_outer[k]) for k in range(3)])
    if x is None:
        raise SpecialPosition(t.name, Said("sp_velocity"))
    vD, w = complex(x[0], x[1]), x[2]
    if a_outer is None:
        return vD, w, None, None
    vP = [vD + 1j * w * arms[k] for k in range(3)]
    # a slider on a fixed guide: n·a_P = 0 (n constant); a revolute leash: the derivative
    # of (P − Q)·(v_P − v_Q) = 0 brings |v_P − v_Q|²; a block in a slot: the Coriolis term
    # 2ω × v_rel of the pin relative to the base
    rhs = []
    for k in range(3):
        r = _dot(d[k], a_outer[k] + w * w * arms[k])
        if t.slots[k] is not None:
            r -= 2 * w * _dot(d[k], 1j * (v_outer[k] - vP[k]))
        elif t.guides[k] is None:
            r -= abs(vP[k] - v_outer[k]) ** 2
        rhs.append(r)
    y = _solve3(J, rhs)
    assert y is not None  # the same matrix
    return vD, w, complex(y[0], y[1]), y[2]


def _meet(p1: complex, d1: complex, p2: complex, d2: complex) -> complex | None:
    s = _cross(d1, d2)
    if abs(s) <= LOCK_SIN * abs(d1) * abs(d2):
        return None
    return p1 + d1 * _cross(p2 - p1, d2) / s


@frozen
class SpecialPoint:
    """The velocity plan of the group by Assur's point: which leashes' axes gave S, S itself,
    v_S, the base's ω and the inner pairs' velocities."""

    leashes: tuple[int, int]  # 0-based: the two leashes whose axes meet at S
    S: complex
    vS: complex
    omega: float
    v_inner: tuple[complex, complex, complex]


def _axis(t: Triad, k: int, P: complex, Q: complex, rot: complex = 1) -> complex:
    """The direction of leash k's axis: along the leash, or the guide's (slot's) normal."""
    return _normal(t, k, P, Q, rot)


def _on_axis(t: Triad, k: int, P: complex, Q: complex) -> complex:
    """A point of leash k's axis: its outer pair, or the slider's pin."""
    return P if t.guides[k] is not None else Q


def special_point_velocities(t: Triad, outer: tuple[complex, complex, complex], rD: complex, theta: float,
                             v_outer: tuple[complex, complex, complex]) -> SpecialPoint:
    """The textbook's construction: s where the lines through a ⟂ AD and through b ⟂ BE meet,
    then f from v_F − v_C ⟂ CF, then d and e."""
    P = pair_points(t, outer, rD, theta)
    rot = cmath.exp(1j * theta)
    axis = [_axis(t, k, P[k], outer[k], rot) for k in range(3)]
    on = [_on_axis(t, k, P[k], outer[k]) for k in range(3)]
    for i, j in ((0, 1), (1, 2), (0, 2)):  # parallel axes: the other pair's point
        S = _meet(on[i], axis[i], on[j], axis[j])
        if S is None:
            continue
        # s: v_S − v_Qi ⟂ axis i and v_S − v_Qj ⟂ axis j, two lines of the velocity plan
        vS = _meet(v_outer[i], 1j * axis[i], v_outer[j], 1j * axis[j])
        if vS is None:
            raise SpecialPosition(t.name, Said("sp_lines_s"))
        m = 3 - i - j  # the third leash fixes ω: v_S + ω (P_m − S)⊥ − v_Qm ⟂ axis m
        den = _dot(axis[m], 1j * (P[m] - S))
        if abs(den) <= LOCK_SIN * abs(axis[m]) * max(abs(P[m] - S), t.size):
            raise SpecialPosition(t.name, Said("sp_one_point"))
        w = _dot(axis[m], v_outer[m] - vS) / den
        v_inner = tuple(vS + 1j * w * (P[k] - S) for k in range(3))
        return SpecialPoint((i, j), S, vS, w, (v_inner[0], v_inner[1], v_inner[2]))
    raise SpecialPosition(t.name, Said("sp_parallel"))


def special_kind(t: Triad, outer: tuple[complex, complex, complex], rD: complex, theta: float,
                 tol: float = 1e-3) -> Said | None:
    """What makes this position special, or None: the three leashes' axes parallel, or
    passing through one point (the leash equations' matrix singular to ``tol``)."""
    P = pair_points(t, outer, rD, theta)
    rot = cmath.exp(1j * theta)
    axis = [_axis(t, k, P[k], outer[k], rot) for k in range(3)]
    on = [_on_axis(t, k, P[k], outer[k]) for k in range(3)]
    u = [a / abs(a) for a in axis]
    if max(abs(_cross(u[i], u[j])) for i, j in ((0, 1), (1, 2), (0, 2))) <= tol:
        return Said("tr_parallel")
    for i, j in ((0, 1), (1, 2), (0, 2)):
        S = _meet(on[i], axis[i], on[j], axis[j])
        if S is None:
            continue
        m = 3 - i - j
        if abs(_cross(u[m], S - on[m])) <= tol * max(t.size, abs(S - on[m])):
            return Said("tr_one_point")
        return None
    return None


def leash_angles(t: Triad, outer: tuple[complex, complex, complex], rD: complex, theta: float) -> tuple[float, ...]:
    P = t.inner(rD, theta)
    return tuple(math.atan2((P[k] - outer[k]).imag, (P[k] - outer[k]).real) for k in range(3))


@frozen
class SpecialPointAcc:
    """The acceleration plan by the same point: a_S, the base's ε, the inner pairs' a."""

    S: complex
    aS: complex
    eps: float
    a_inner: tuple[complex, complex, complex]


def special_point_accelerations(t: Triad, outer: tuple[complex, complex, complex], rD: complex, theta: float,
                                v_outer: tuple[complex, complex, complex],
                                a_outer: tuple[complex, complex, complex]) -> SpecialPointAcc:
    """a_S = a_Q + (normal terms along the leash: −ω_leash²·QP − ω²·PS) + a term ⟂ QP, for two
    leashes: two lines of the acceleration plan meet at s; the third leash's normal
    acceleration −ω_leash²·|QP| along its axis fixes ε; then d, e, f."""
    sp = special_point_velocities(t, outer, rD, theta, v_outer)
    i, j = sp.leashes
    P = pair_points(t, outer, rD, theta)
    rot = cmath.exp(1j * theta)
    axis = [_axis(t, k, P[k], outer[k], rot) for k in range(3)]
    w = sp.omega
    # a slider on a fixed guide does not turn, a block turns with the base: no normal term
    # along its axis; the block's pin has the Coriolis term relative to the base instead
    w_leash = [0.0 if t.guides[k] is not None or t.slots[k] is not None
               else _cross(axis[k], sp.v_inner[k] - v_outer[k]) / abs(axis[k]) ** 2 for k in range(3)]
    a_outer = tuple(a_outer[k] - (2j * w * (v_outer[k] - sp.v_inner[k]) if t.slots[k] is not None else 0)
                    for k in range(3))  # type: ignore[assignment]
    known = [a_outer[k] - w_leash[k] ** 2 * axis[k] - w * w * (sp.S - P[k]) for k in range(3)]
    aS = _meet(known[i], 1j * axis[i], known[j], 1j * axis[j])
    if aS is None:
        raise SpecialPosition(t.name, Said("sp_lines_s"))
    m = 3 - i - j
    arm = P[m] - sp.S
    den = _dot(axis[m], 1j * arm)  # not zero: special_point_velocities has checked it
    eps = (-w_leash[m] ** 2 * abs(axis[m]) ** 2 - _dot(axis[m], aS - w * w * arm - a_outer[m])) / den
    a_inner = tuple(aS + (1j * eps - w * w) * (P[k] - sp.S) for k in range(3))
    return SpecialPointAcc(sp.S, aS, eps, (a_inner[0], a_inner[1], a_inner[2]))
