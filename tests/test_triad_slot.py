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

from .newton2 import newton2

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


# --------------------------------------------------------------------------- the sample

import re  # noqa: E402
from pathlib import Path  # noqa: E402

import numpy as np  # noqa: E402
import pytest  # noqa: E402

SAMPLE = Path(__file__).resolve().parent.parent / "samples" / "class3" / "triad_rocking_block.toml"


def _cross(a: complex, b: complex) -> float:
    return (a.conjugate() * b).imag


class _TwoAngles:
    """Unknowns: the angles α of AD and β of BE; equations |E − D| = |DE| and the pin C on the
    jaw's slot through F (at 165° to DE); Newton with a difference Jacobian."""

    def __init__(self, scene) -> None:
        L = scene.links
        self.r = abs(L[1].points["A"] - L[1].points["O"])
        self.l1 = abs(L[2].points["D"] - L[2].points["A"])
        self.l2 = abs(L[4].points["E"] - L[4].points["B"])
        zD, zE, zF = L[3].points["D"], L[3].points["E"], L[3].points["F"]
        self.de = abs(zE - zD)
        self.shape = (zF - zD) / (zE - zD)
        self.turn = cmath.exp(1j * math.radians(165.0)) * abs(zE - zD) / (zE - zD)  # the slot from DE
        self.O, self.B, self.C = (scene.frame_points[n] for n in "OBC")

    def A(self, phi: float) -> complex:
        return self.O + self.r * cmath.exp(1j * phi)

    def points(self, phi: float, ab: tuple[float, float]) -> tuple[complex, complex, complex]:
        D = self.A(phi) + self.l1 * cmath.exp(1j * ab[0])
        E = self.B + self.l2 * cmath.exp(1j * ab[1])
        return D, E, D + self.shape * (E - D)

    def _f(self, phi: float, ab: tuple[float, float]) -> tuple[float, float]:
        D, E, F = self.points(phi, ab)
        s = (E - D) / abs(E - D) * self.turn
        return abs(E - D) - self.de, _cross(s, self.C - F)

    def root(self, phi: float, ab: tuple[float, float]) -> tuple[float, float]:
        return newton2(lambda x: self._f(phi, x), ab, 60)


@pytest.fixture(scope="module")
def scene():
    from plans.kinematics.placing import load_scene

    return load_scene(str(SAMPLE))


def test_structure_names_the_block(scene):
    from plans.kinematics.structure import analyse

    (g,) = analyse(scene).triads()
    assert g.kind == "RR-RR-RP" and [d.kind for _, d in g.joints] == ["R", "R", "P"]


def test_full_turn_against_a_separate_solver_and_finite_differences(scene):
    from plans.kinematics.exact import solve

    phis = np.arange(0.0, 360.0, 2.0)
    kin = solve(scene, phis, order=2)
    one = _TwoAngles(scene)
    rD, rE, rF = (kin.point(n)[0] for n in "DEF")
    ab = (round(cmath.phase(rD[0] - one.A(0.0)), 2), round(cmath.phase(rE[0] - one.B), 2))
    w = scene.driver.omega
    h = 3e-3  # crank angle step of the seven-point stencils (rad): truncation and rounding both < 1e-9
    vmax = max(float(np.max(np.abs(kin.point(n)[1]))) for n in "DEF")
    amax = max(float(np.max(np.abs(kin.point(n)[2]))) for n in "DEF")
    for k, phi_deg in enumerate(phis):
        phi = math.radians(phi_deg)
        ab = one.root(phi, ab)
        pts = one.points(phi, ab)
        for P, exact in zip(pts, (rD[k], rE[k], rF[k]), strict=True):
            assert abs(P - exact) <= 1e-9 * 0.5, phi_deg
        if k % 6:
            continue
        around = [one.points(phi + m * h, one.root(phi + m * h, ab)) for m in (-3, -2, -1, 1, 2, 3)]
        for idx, name in enumerate("DEF"):
            f = [p[idx] for p in around]
            d1 = (-f[0] + 9 * f[1] - 45 * f[2] + 45 * f[3] - 9 * f[4] + f[5]) / (60 * h)
            d2 = (2 * f[0] - 27 * f[1] + 270 * f[2] - 490 * pts[idx] + 270 * f[3] - 27 * f[4] + 2 * f[5]) / (180 * h * h)
            _, v, a = kin.point(name)
            assert abs(d1 * w - v[k]) <= 1e-9 * vmax, (name, phi_deg)
            assert abs(d2 * w * w - a[k]) <= 1e-9 * amax, (name, phi_deg)
    assert np.max(np.abs(kin.omega(5) - kin.omega(3))) == 0.0  # the block turns with the jaw


def test_special_point_plans_read_the_exact_rates(scene):
    from plans.kinematics.construction import build_many
    from plans.kinematics.exact import solve

    kin = solve(scene, [0.0, 47.0, 133.0, 250.0, 321.0], order=2)
    for pp in build_many(kin, range(kin.n)):
        got = {r.quantity for r in pp.readings}
        assert {"v_D", "v_E", "v_C3", "a_C3", "a^k_C3C5", "omega_3", "eps_3"} <= got
        for r in pp.readings:
            assert abs(abs(r.value) - abs(r.exact)) <= 1e-9 * max(1.0, abs(r.exact)), r.quantity
        assert "∥ slot of link 3" in [ln.label for ln in pp.velocity.lines]


def test_reactions_satisfy_every_link_equation_and_the_power_balance(scene):
    """Unknowns: X_D, X_E (on the jaw from the rod and the swing link), the slot's N (⟂ the slot,
    on the jaw at C) and couple M, Y_A, Y_B, and R_C (on the block from the frame): twelve."""
    from plans.forces.analysis import kinetostatics
    from plans.forces.triad import TriadForces
    from plans.kinematics.exact import solve

    kin = solve(scene, np.concatenate([np.arange(0.0, 360.0, 30.0), [17.0, 222.0]]), order=2)
    fa, lv = kinetostatics(scene, kin)
    (gf,) = [x for x in fa.groups if isinstance(x, TriadForces)]
    for k in range(kin.n):
        D, E, C, A, B = (complex(kin.point(nm)[0][k]) for nm in "DECAB")
        n = complex(gf.reactions[5].guide[k]) * 1j  # the slot's normal
        M = np.zeros((12, 12))
        rhs = np.zeros(12)

        def put(row: int, col: int, r: complex, sign: float, M=M) -> None:
            M[row, col] += sign
            M[row + 1, col + 1] += sign
            M[row + 2, col] += -sign * r.imag
            M[row + 2, col + 1] += sign * r.real
        put(0, 0, D, 1.0)  # jaw: X_D, X_E, N·n at C, M
        put(0, 2, E, 1.0)
        M[0, 4], M[1, 4], M[2, 4] = n.real, n.imag, _cross(C, n)
        M[2, 5] = 1.0
        put(3, 0, D, -1.0)  # rod 2: −X_D, Y_A
        put(3, 6, A, 1.0)
        put(6, 2, E, -1.0)  # swing link 4: −X_E, Y_B
        put(6, 8, B, 1.0)
        M[9, 4], M[10, 4], M[11, 4] = -n.real, -n.imag, -_cross(C, n)  # block 5: −N·n, −M, R_C
        M[11, 5] = -1.0
        put(9, 10, C, 1.0)
        for r, link in zip((0, 3, 6, 9), (3, 2, 4, 5), strict=True):
            F = sum((complex(f.F[k]) for f in fa.applied.forces if f.link == link), 0j)
            Mo = sum((_cross(complex(f.r[k]), complex(f.F[k])) for f in fa.applied.forces if f.link == link), 0.0)
            Mo += sum(float(mo.M[k]) for mo in fa.applied.moments if mo.link == link)
            rhs[r:r + 3] = [-F.real, -F.imag, -Mo]
        x = np.linalg.solve(M, rhs)
        ref = max(float(np.max(np.abs(x))), 1.0)
        r2, r4, r5, i2, i4, i5 = gf.reactions
        slot_F = complex(i5.F[k])
        mine = [complex(i2.F[k]).real, complex(i2.F[k]).imag, complex(i4.F[k]).real, complex(i4.F[k]).imag,
                (slot_F * n.conjugate()).real, float(i5.M[k]), complex(r2.F[k]).real, complex(r2.F[k]).imag,
                complex(r4.F[k]).real, complex(r4.F[k]).imag, complex(r5.F[k]).real, complex(r5.F[k]).imag]
        assert abs(_cross(n, slot_F)) <= 1e-9 * ref  # the slot's reaction ⟂ the slot
        assert np.max(np.abs(np.array(mine) - x)) <= 1e-9 * ref, float(kin.phi_deg[k])
    bal = lv.signed(lv.by_power)
    ref = max(float(np.max(np.abs(bal))), 1.0)
    assert np.max(np.abs(fa.balancing - bal)) <= 1e-9 * ref
    assert np.max(np.abs(lv.signed(lv.by_lever) - bal)) <= 1e-9 * ref


def test_a_fold_is_named_not_jumped_over(tmp_path, capsys):
    """The slot at 75° to DE: near φ = 87° the jaw's axes come to one point and the crank
    cannot carry the group further; the engine says so with the angle, where Newton from the
    last step would land on the other branch.  The two-angle solver written apart meets its
    own fold (its determinant changes sign) at the same angle."""
    from plans.cli import main
    from plans.kinematics.placing import load_scene

    text = SAMPLE.read_text(encoding="utf-8").replace("angle_deg = 165 }", "angle_deg = 75 }")
    text = text.replace("C = [250, 450]", "C = [150, 450]")
    f = tmp_path / "fold.toml"
    f.write_text(text, encoding="utf-8")
    assert main(["solve", str(f), "--quiet"]) == 2
    err = capsys.readouterr().err
    m = re.search(r"phi = ([0-9.]+) deg: the three leashes' axes pass through one point", err)
    assert m and err.count("\n") == 1, err
    stop = float(m.group(1))
    assert 86.0 < stop < 88.0
    one = _TwoAngles(load_scene(str(f)))
    one.turn *= cmath.exp(1j * math.radians(75.0 - 165.0))
    ab = _start(one)
    sign = math.copysign(1.0, _jacobian(one, 0.0, ab))
    flipped = None
    for phi_deg in np.arange(0.0, stop + 0.5, 0.05):  # the separate solver's own fold
        ab = one.root(math.radians(phi_deg), ab)
        if _jacobian(one, math.radians(phi_deg), ab) * sign < 0 or max(map(abs, one._f(math.radians(phi_deg), ab))) > 1e-9:
            flipped = phi_deg
            break
    assert flipped is not None and abs(flipped - stop) < 0.2, (flipped, stop)


def _start(one: _TwoAngles) -> tuple[float, float]:
    """Of the two-angle solver's roots at φ = 0 from a grid of guesses, with D left of A→B, the
    one with the jaw's axis DE at the smallest angle (the file's branch rule)."""
    best, key = None, None
    for a in np.linspace(-math.pi, math.pi, 13):
        for b in np.linspace(-math.pi, math.pi, 13):
            try:
                r = one.root(0.0, (a, b))
            except ZeroDivisionError:
                continue
            r = (math.remainder(r[0], 2 * math.pi), math.remainder(r[1], 2 * math.pi))
            f1, f2 = one._f(0.0, r)
            D = one.points(0.0, r)[0]
            if abs(f1) + abs(f2) < 1e-12 and _cross(one.B - one.A(0.0), D - one.A(0.0)) > 0:
                E = one.points(0.0, r)[1]
                if best is None or cmath.phase(E - D) < key - 1e-9:
                    best, key = r, cmath.phase(E - D)
    assert best is not None
    return best


def _jacobian(one: _TwoAngles, phi: float, ab: tuple[float, float]) -> float:
    d = 1e-7
    f1, f2 = one._f(phi, ab)
    g1, g2 = one._f(phi, (ab[0] + d, ab[1]))
    h1, h2 = one._f(phi, (ab[0], ab[1] + d))
    return ((g1 - f1) * (h2 - f2) - (h1 - f1) * (g2 - f2)) / d / d


def test_the_group_cut_free_shows_the_slot_from_its_origin_past_the_pin():
    import math as m

    import plans
    from drawings.linkage import build_panels
    from drawings.paper.sheet import sheet_spec
    from plans.kinematics.exact import solve
    from plans.kinematics.placing import load_scene

    spec = sheet_spec({"sheet": {"positions": [30.0], "panels": ["group"]}}, str(SAMPLE))
    panels, mu_l = build_panels(plans.solve(SAMPLE, fit=spec.fit), spec)
    (panel,) = [p for p in panels if p.kind == "group"]
    (slot,) = [p for p in panel.prims if p.op == "line" and p.eid.endswith("-slot-C")]
    kin = solve(load_scene(str(SAMPLE)), [30.0], order=1)
    F, C = (complex(kin.point(n)[0][0]) for n in "FC")
    assert m.dist(*slot.pts[:2]) >= abs(C - F) * mu_l + 8.0  # one slot, from F past the block at C
