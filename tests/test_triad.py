"""The class-III triad: Newton placement against a one-dimensional solver written apart,
velocities and accelerations against finite differences, Assur's special-point construction
against the exact rates, and the special position named."""

from __future__ import annotations

import cmath
import math

import pytest

from plans.kinematics.triad import SpecialPosition, Triad, place, rates, special_point_velocities

# base D(0,0) E(100,0) F(50,80) mm; outer A, B, C where the leashes have these lengths at t = 0
A0, B0, C0 = complex(-0.08, -0.06), complex(0.18, -0.06), complex(0.2, 0.08)
T = Triad(zE=0.1 + 0j, zF=complex(0.05, 0.08), l1=abs(A0), l2=abs(0.1 - B0), l3=abs(complex(0.05, 0.08) - C0),
          name="3-4-5-6")


def outer(t: float) -> tuple[complex, complex, complex]:
    """A on a crank, B on a faster small circle, C fixed."""
    return (A0 + 0.01 * (cmath.exp(1j * t) - 1), B0 + 0.005j * (cmath.exp(2j * t) - 1), C0)


def v_outer(t: float) -> tuple[complex, complex, complex]:
    return (0.01j * cmath.exp(1j * t), 0.005j * 2j * cmath.exp(2j * t), 0j)


def a_outer(t: float) -> tuple[complex, complex, complex]:
    return (-0.01 * cmath.exp(1j * t), 0.005j * (2j) ** 2 * cmath.exp(2j * t), 0j)


def _path(n: int = 120):
    """(t, r_D, θ) over a full turn, each position from the previous one."""
    guess = (0j, 0.0)
    out = []
    for k in range(n + 1):
        t = 2 * math.pi * k / n
        guess = place(T, outer(t), guess)
        out.append((t, *guess))
    return out


def _independent(t: float, alpha0: float) -> tuple[complex, float]:
    """Leash 1's angle α as the one unknown: D on the circle about A, E where the circle about
    D (radius |DE|) meets the circle about B (the branch of the start), F then fixed; the root
    of |CF| − l3 = 0 by bisection next to α0."""
    A, B, C = outer(t)
    dE = abs(T.zE)

    def pose(alpha: float):
        D = A + T.l1 * cmath.exp(1j * alpha)
        d = abs(B - D)
        x = (d * d + dE * dE - T.l2 ** 2) / (2 * d)
        h = math.sqrt(max(dE * dE - x * x, 0.0))
        u = (B - D) / d
        E = D + u * (x + 1j * h)  # E to the left of D -> B, as assembled
        th = cmath.phase((E - D) / T.zE)
        return D, th, abs(D + cmath.exp(1j * th) * T.zF - C) - T.l3

    lo, hi = alpha0 - 1e-3, alpha0 + 1e-3
    glo = pose(lo)[2]
    assert glo * pose(hi)[2] < 0
    for _ in range(80):
        mid = 0.5 * (lo + hi)
        g = pose(mid)[2]
        lo, hi, glo = (mid, hi, g) if (g > 0) == (glo > 0) else (lo, mid, glo)
    D, th, _ = pose(0.5 * (lo + hi))
    return D, th


def test_place_agrees_with_a_separate_solver_over_a_full_turn() -> None:
    for t, rD, th in _path():
        alpha = cmath.phase(rD - outer(t)[0])
        D2, th2 = _independent(t, alpha)
        assert abs(rD - D2) < 1e-9 * T.size
        assert abs(cmath.exp(1j * th) - cmath.exp(1j * th2)) < 1e-9


def test_rates_agree_with_finite_differences() -> None:
    h = 1e-6
    for t, rD, th in _path(36):
        vD, w, aD, eps = rates(T, outer(t), rD, th, v_outer(t), a_outer(t))
        p = place(T, outer(t + h), (rD, th))
        m = place(T, outer(t - h), (rD, th))
        assert abs(vD - (p[0] - m[0]) / (2 * h)) < 1e-9 * T.size
        assert abs(w - (p[1] - m[1]) / (2 * h)) < 1e-8
        vp = rates(T, outer(t + h), *p, v_outer(t + h))
        vm = rates(T, outer(t - h), *m, v_outer(t - h))
        assert aD is not None and eps is not None
        assert abs(aD - (vp[0] - vm[0]) / (2 * h)) < 1e-8 * T.size
        assert abs(eps - (vp[1] - vm[1]) / (2 * h)) < 1e-7


def test_special_point_construction_reads_the_exact_velocities() -> None:
    for t, rD, th in _path(72):
        vD, w, _, _ = rates(T, outer(t), rD, th, v_outer(t))
        sp = special_point_velocities(T, outer(t), rD, th, v_outer(t))
        P = T.inner(rD, th)
        ref = 0.04 * 1.0  # the outer pairs' speeds are at most 0.02 m/s
        assert abs(sp.omega - w) < 1e-9 * ref / T.size
        for k in range(3):
            assert abs(sp.v_inner[k] - (vD + 1j * w * (P[k] - rD))) < 1e-9 * ref
        # S lies on both leashes' axes
        i, j = sp.leashes
        for q in (i, j):
            assert abs(((sp.S - outer(t)[q]) * (P[q] - outer(t)[q]).conjugate()).imag) < 1e-9 * T.size ** 2 * 10


def test_all_axes_through_one_point_is_named_a_special_position() -> None:
    F = cmath.exp(1j * math.radians(225))
    tri = Triad(zE=-1 + 1j, zF=F - 1, l1=1.0, l2=1.0, l3=1.0, name="2-3-4-5")
    out = (2 + 0j, 2j, 2 * F)  # the axes AD, BE, CF all pass through the origin
    with pytest.raises(SpecialPosition, match="one point"):
        special_point_velocities(tri, out, 1 + 0j, 0.0, (0.1j, 0j, 0j))
    with pytest.raises(SpecialPosition, match="2-3-4-5"):
        rates(tri, out, 1 + 0j, 0.0, (0.1j, 0j, 0j))


def test_parallel_axes_take_the_other_pairs_point() -> None:
    """AD ∥ BE: their point is at infinity; S is taken where BE meets CF."""
    tri = Triad(zE=1 + 0j, zF=0.5 + 1j, l1=1.0, l2=1.0, l3=1.0, name="2-3-4-5")
    out = (-1j, 1 - 1j, 1.5 + 1j)
    v_out = (0.3 + 0.1j, -0.2j, 0.05 + 0j)
    sp = special_point_velocities(tri, out, 0j, 0.0, v_out)
    assert sp.leashes == (1, 2)
    vD, w, _, _ = rates(tri, out, 0j, 0.0, v_out)
    assert abs(sp.omega - w) < 1e-12 and abs(sp.v_inner[0] - vD) < 1e-12


def test_special_point_acceleration_plan_reads_the_exact_accelerations() -> None:
    from plans.kinematics.triad import special_point_accelerations

    for t, rD, th in _path(72):
        vD, w, aD, eps = rates(T, outer(t), rD, th, v_outer(t), a_outer(t))
        acc = special_point_accelerations(T, outer(t), rD, th, v_outer(t), a_outer(t))
        assert aD is not None and eps is not None
        ref = 0.05  # m/s²: the outer pairs' accelerations are at most 0.02
        assert abs(acc.eps - eps) < 1e-9 * ref / T.size
        P = T.inner(rD, th)
        for k in range(3):
            assert abs(acc.a_inner[k] - (aD + (1j * eps - w * w) * (P[k] - rD))) < 1e-9 * ref
