"""A triad whose third leash is a block pinned at C and sliding in a slot of the base link:
Newton placement, the rates against finite differences of the positions, and Assur's
special-point construction (the slot's normal through the pin as the axis, the Coriolis term
on the acceleration plan) against the exact rates."""

from __future__ import annotations

import cmath
import math

from plans.kinematics.triad import (
    Triad,
    pair_points,
    place,
    rates,
    special_point_accelerations,
    special_point_velocities,
)

A0, B0 = complex(-0.08, -0.06), complex(0.18, -0.06)
F0, SLOT = complex(0.05, 0.08), cmath.exp(1.0j)
C0 = F0 + 0.07 * SLOT
T = Triad(zE=0.1 + 0j, zF=F0, l1=abs(A0), l2=abs(0.1 - B0), l3=0.0, name="slot", slots=(None, None, SLOT))


def outer(t: float) -> tuple[complex, complex, complex]:
    return (A0 + 0.01 * (cmath.exp(1j * t) - 1), B0 + 0.005j * (cmath.exp(2j * t) - 1),
            C0 + 0.004 * (cmath.exp(3j * t) - 1))


def v_outer(t: float) -> tuple[complex, complex, complex]:
    return (0.01j * cmath.exp(1j * t), 0.005j * 2j * cmath.exp(2j * t), 0.004 * 3j * cmath.exp(3j * t))


def a_outer(t: float) -> tuple[complex, complex, complex]:
    return (-0.01 * cmath.exp(1j * t), 0.005j * (2j) ** 2 * cmath.exp(2j * t), 0.004 * (3j) ** 2 * cmath.exp(3j * t))


def _path(n: int = 72):
    guess = (0j, 0.0)
    out = []
    for k in range(n + 1):
        t = 2 * math.pi * k / n
        guess = place(T, outer(t), guess)
        out.append((t, *guess))
    return out


def test_the_pin_stays_on_the_slot_and_the_leashes_at_their_lengths():
    for t, rD, th in _path():
        P = T.inner(rD, th)
        A, B, C = outer(t)
        assert abs(abs(P[0] - A) - T.l1) < 1e-13 and abs(abs(P[1] - B) - T.l2) < 1e-13
        s = cmath.exp(1j * th) * SLOT
        assert abs(((C - P[2]) * s.conjugate()).imag) < 1e-13


def test_rates_against_finite_differences():
    h = 1e-4
    for t, rD, th in _path(24):
        vD, w, aD, e = rates(T, outer(t), rD, th, v_outer(t), a_outer(t))
        states = [place(T, outer(t + m * h), (rD, th)) for m in (-2, -1, 1, 2)]
        r = [s[0] for s in states]
        a = [s[1] for s in states]
        d1 = (r[0] - 8 * r[1] + 8 * r[2] - r[3]) / (12 * h)
        w1 = (a[0] - 8 * a[1] + 8 * a[2] - a[3]) / (12 * h)
        d2 = (-r[0] + 16 * r[1] - 30 * rD + 16 * r[2] - r[3]) / (12 * h * h)
        e2 = (-a[0] + 16 * a[1] - 30 * th + 16 * a[2] - a[3]) / (12 * h * h)
        assert abs(d1 - vD) < 1e-9 and abs(w1 - w) < 1e-8
        assert abs(d2 - aD) < 1e-6 and abs(e2 - e) < 1e-5


def test_special_point_construction_reads_the_exact_rates():
    for t, rD, th in _path(36):
        vD, w, aD, e = rates(T, outer(t), rD, th, v_outer(t), a_outer(t))
        sp = special_point_velocities(T, outer(t), rD, th, v_outer(t))
        assert abs(sp.omega - w) < 1e-12
        P = pair_points(T, outer(t), rD, th)
        for k in range(3):
            assert abs(sp.v_inner[k] - (vD + 1j * w * (P[k] - rD))) < 1e-12
        acc = special_point_accelerations(T, outer(t), rD, th, v_outer(t), a_outer(t))
        assert abs(acc.eps - e) < 1e-10
        for k in range(3):
            assert abs(acc.a_inner[k] - (aD + (1j * e - w * w) * (P[k] - rD))) < 1e-10


def test_the_slot_giving_assurs_point():
    """The same group with the block numbered first: S where the slot's normal through C meets
    the axis of AD; the construction still reads the exact rates."""
    tri = Triad(zE=-F0, zF=0.1 - F0, l1=0.0, l2=abs(A0), l3=abs(0.1 - B0), name="slot", slots=(SLOT, None, None))

    def out3(t: float, f) -> tuple[complex, complex, complex]:
        a, b, c = f(t)
        return c, a, b
    guess = (F0, 0.0)
    for k in range(37):
        t = 2 * math.pi * k / 36
        guess = place(tri, out3(t, outer), guess)
        rD, th = guess
        vD, w, aD, e = rates(tri, out3(t, outer), rD, th, out3(t, v_outer), out3(t, a_outer))
        sp = special_point_velocities(tri, out3(t, outer), rD, th, out3(t, v_outer))
        assert sp.leashes == (0, 1)
        assert abs(sp.omega - w) < 1e-12
        acc = special_point_accelerations(tri, out3(t, outer), rD, th, out3(t, v_outer), out3(t, a_outer))
        assert abs(acc.eps - e) < 1e-10
        assert abs(acc.aS - (aD + (1j * e - w * w) * (acc.S - rD))) < 1e-10
