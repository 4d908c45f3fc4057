"""A class-III group whose third leash is a slider on a guide of the frame (the press sample):
positions against a two-angle solver written here, velocities and accelerations against its
finite differences, the plans by Assur's special point (the slider's axis is the guide's
normal through its pin) against the exact rates, and the force analysis against every link's
equations solved together and the power balance."""

from __future__ import annotations

import cmath
import math
from pathlib import Path

import numpy as np
import pytest

from plans.forces.analysis import kinetostatics
from plans.forces.triad import TriadForces
from plans.kinematics.construction import build_many
from plans.kinematics.exact import solve
from plans.kinematics.placing import load_scene
from plans.kinematics.structure import analyse

from .newton2 import newton2

SAMPLE = Path(__file__).resolve().parent.parent / "samples" / "class3" / "triad_press.toml"


def _cross(a: complex, b: complex) -> float:
    return (a.conjugate() * b).imag


class _TwoAngles:
    """Unknowns: the angles α of the rod AD and β of the swing link BE; equations |E − D| = |DE|
    and F (fixed to DE) on the vertical guide through G; Newton with a difference Jacobian."""

    def __init__(self, scene) -> None:
        L = scene.links
        self.r = abs(L[1].points["A"] - L[1].points["O"])
        self.l1 = abs(L[2].points["D"] - L[2].points["A"])
        self.l2 = abs(L[4].points["E"] - L[4].points["B"])
        zD, zE, zF = L[3].points["D"], L[3].points["E"], L[3].points["F"]
        self.de = abs(zE - zD)
        self.shape = (zF - zD) / (zE - zD)
        self.O, self.B, self.G = (scene.frame_points[n] for n in "OBG")
        self.g = 1j  # the guide: vertical, from the file's angle_deg = 90

    def A(self, phi: float) -> complex:
        return self.O + self.r * cmath.exp(1j * phi)

    def points(self, phi: float, ab: tuple[float, float]) -> tuple[complex, complex, complex]:
        D = self.A(phi) + self.l1 * cmath.exp(1j * ab[0])
        E = self.B + self.l2 * cmath.exp(1j * ab[1])
        return D, E, D + self.shape * (E - D)

    def _f(self, phi: float, ab: tuple[float, float]) -> tuple[float, float]:
        D, E, F = self.points(phi, ab)
        return abs(E - D) - self.de, _cross(self.g, F - self.G)

    def root(self, phi: float, ab: tuple[float, float]) -> tuple[float, float]:
        return newton2(lambda x: self._f(phi, x), ab, 60)


@pytest.fixture(scope="module")
def scene():
    return load_scene(str(SAMPLE))


def test_structure_names_the_slider_leash(scene):
    (g,) = analyse(scene).triads()
    assert g.kind == "RR-RR-PR" and g.to_json()["class"] == 3
    assert [o.kind for o, _ in g.joints] == ["R", "R", "P"]


def test_full_turn_against_a_separate_solver_and_finite_differences(scene):
    phis = np.arange(0.0, 360.0, 2.0)
    kin = solve(scene, phis, order=2)
    one = _TwoAngles(scene)
    rD, rE, rF = (kin.point(n)[0] for n in "DEF")
    ab = (round(cmath.phase(rD[0] - one.A(0.0)), 2), round(cmath.phase(rE[0] - one.B), 2))
    w = scene.driver.omega
    size = 0.4
    h = 3e-3
    vmax = max(float(np.max(np.abs(kin.point(n)[1]))) for n in "DEF")
    amax = max(float(np.max(np.abs(kin.point(n)[2]))) for n in "DEF")
    for k, phi_deg in enumerate(phis):
        phi = math.radians(phi_deg)
        ab = one.root(phi, ab)
        pts = one.points(phi, ab)
        for P, exact in zip(pts, (rD[k], rE[k], rF[k]), strict=True):
            assert abs(P - exact) <= 1e-9 * size, phi_deg
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
    # the ram slides on its guide: it keeps its angle, F moves along the guide
    assert np.max(np.abs(kin.omega(5))) == 0.0
    assert np.max(np.abs(np.real(kin.point("F")[1]))) <= 1e-12 * vmax


def test_special_point_plans_read_the_exact_rates(scene):
    kin = solve(scene, [0.0, 47.0, 133.0, 250.0, 321.0], order=2)
    for pp in build_many(kin, range(kin.n)):
        got = {r.quantity for r in pp.readings}
        assert {"v_D", "v_E", "v_F", "a_F", "omega_3", "eps_3", "eps_4"} <= got
        for r in pp.readings:
            assert abs(abs(r.value) - abs(r.exact)) <= 1e-9 * max(1.0, abs(r.exact)), r.quantity
        labels = [ln.label for ln in pp.velocity.lines]
        assert "∥ guide of F" in labels


def test_protocol_names_the_guide(capsys):
    from plans.cli import main

    for lang, words in (("en", ("∥ guide of F", "the normal to the guide at F")),
                        ("ru", ("∥ направляющей F", "нормаль к направляющей в точке F"))):
        assert main(["solve", str(SAMPLE), "--protocol", "--language", lang]) == 0
        out = capsys.readouterr().out
        for w in words:
            assert w in out, (lang, w)


@pytest.fixture(scope="module")
def analysed(scene):
    phis = np.concatenate([np.arange(0.0, 360.0, 20.0), np.random.default_rng(3).uniform(0.0, 360.0, 10)])
    kin = solve(scene, phis, order=2)
    fa, lv = kinetostatics(scene, kin)
    return kin, fa, lv


def test_reactions_satisfy_every_link_equation(analysed):
    """Unknowns: X_m (on the base from leash m, at D, E, F), Y at A and B, and the guide's N
    (⟂ the guide at F) and couple M on the ram: twelve, from the four links' equations."""
    kin, fa, _ = analysed
    (gf,) = [g for g in fa.groups if isinstance(g, TriadForces)]
    g = gf.group
    for k in range(kin.n):
        P = [complex(kin.point(d.point, g.links[0])[0][k]) for _, d in g.joints]
        Q = [complex(kin.point(o.point, p)[0][k]) for p, (o, _) in zip(g.known[:2], g.joints[:2], strict=True)]
        A = np.zeros((12, 12))
        b = np.zeros(12)

        def put(row: int, col: int, r: complex, sign: float, A=A) -> None:
            A[row, col] += sign
            A[row + 1, col + 1] += sign
            A[row + 2, col] += -sign * r.imag
            A[row + 2, col + 1] += sign * r.real
        for m in range(3):
            put(0, 2 * m, P[m], 1.0)
            put(3 + 3 * m, 2 * m, P[m], -1.0)
        put(3, 6, Q[0], 1.0)
        put(6, 8, Q[1], 1.0)
        A[9 + 0, 10] = 0.0  # the guide's N along x (⟂ the vertical guide), at F
        A[9, 10] = 1.0
        A[11, 10] = -P[2].imag * 1.0
        A[11, 11] = 1.0  # the guide's couple
        for r, link in zip((0, 3, 6, 9), g.links, strict=True):
            F = sum((complex(f.F[k]) for f in fa.applied.forces if f.link == link), 0j)
            M = sum((_cross(complex(f.r[k]), complex(f.F[k])) for f in fa.applied.forces if f.link == link), 0.0)
            M += sum(float(mo.M[k]) for mo in fa.applied.moments if mo.link == link)
            b[r:r + 3] = [-F.real, -F.imag, -M]
        x = np.linalg.solve(A, b)
        ref = max(float(np.max(np.abs(x))), 1.0)
        mine = []
        for rc in gf.reactions[3:]:
            mine += [complex(rc.F[k]).real, complex(rc.F[k]).imag]
        for rc in gf.reactions[:2]:
            mine += [complex(rc.F[k]).real, complex(rc.F[k]).imag]
        ram = gf.reactions[2]
        mine += [complex(ram.F[k]).real, float(ram.M[k])]
        assert abs(complex(ram.F[k]).imag) <= 1e-12 * ref  # ⟂ the guide
        assert np.max(np.abs(np.array(mine) - x)) <= 1e-9 * ref, float(kin.phi_deg[k])


def test_balancing_force_three_ways(analysed):
    _, fa, lv = analysed
    bal = lv.signed(lv.by_power)
    ref = max(float(np.max(np.abs(bal))), 1.0)
    assert np.max(np.abs(fa.balancing - bal)) <= 1e-9 * ref
    assert np.max(np.abs(lv.signed(lv.by_lever) - bal)) <= 1e-9 * ref
    assert np.max(np.abs(bal)) > 100.0  # the pressing load is felt


def test_polygon_reads_the_reactions(analysed):
    from plans.forces.polygons import force_polygons
    from plans.forces.protocol import force_steps

    kin, fa, lv = analysed
    (gf,) = [g for g in fa.groups if isinstance(g, TriadForces)]
    for k in (0, 7, 20):
        plan = force_polygons(fa, k)[0].plan
        for rc in gf.reactions:
            assert abs(plan.segment(rc.name(fa.scene.fij)).value - abs(complex(rc.F[k]))) <= 1e-9 * fa.largest_reaction
        texts = [f.step.say("ru") for f in force_steps(fa, lv, k) if f.plan == "group 2-3-4-5"]
        assert any("нормаль к направляющей в точке F" in t for t in texts)


def test_slider_leash_giving_assurs_point(tmp_path):
    """The ram numbered 2 (the first leash): Assur's point is where the guide's normal at F
    meets the axis of AD; the plans still read the exact rates and the balancing force still
    agrees three ways."""
    text = SAMPLE.read_text(encoding="utf-8")
    for old, new in (("[links.2]", "[links.X]"), ("[links.5]", "[links.2]"), ("[links.X]", "[links.5]"),
                     ("links = [1, 2]", "links = [1, Y]"), ("links = [2, 3]", "links = [Y, 3]"),
                     ("links = [3, 5]", "links = [3, 2]"), ("links = [5, 6]", "links = [2, 6]"),
                     ("link = 5\n", "link = 2\n"), ("Y", "5")):
        assert old in text, old
        text = text.replace(old, new)
    f = tmp_path / "renumbered.toml"
    f.write_text(text, encoding="utf-8")
    sc = load_scene(str(f))
    (g,) = analyse(sc).triads()
    assert g.kind == "PR-RR-RR" and [o.point for o, _ in g.joints] == ["F", "B", "A"]
    kin = solve(sc, [0.0, 47.0, 133.0, 250.0], order=2)
    for pp in build_many(kin, range(kin.n)):
        for r in pp.readings:
            assert abs(abs(r.value) - abs(r.exact)) <= 1e-9 * max(1.0, abs(r.exact)), r.quantity
        assert [ln.label for ln in pp.velocity.lines][:2] == ["∥ guide of F", "⟂ BE"]
    fa, lv = kinetostatics(sc, kin)
    bal = lv.signed(lv.by_power)
    ref = max(float(np.max(np.abs(bal))), 1.0)
    assert np.max(np.abs(fa.balancing - bal)) <= 1e-9 * ref
    # the same mechanism: the same balancing force as numbered in the sample
    same = kinetostatics(load_scene(str(SAMPLE)), solve(load_scene(str(SAMPLE)), [0.0, 47.0, 133.0, 250.0], order=2))
    assert np.max(np.abs(same[0].balancing - fa.balancing)) <= 1e-9 * ref


def test_a_slider_on_a_moving_guide_is_refused_in_one_line(tmp_path, capsys):
    from plans.cli import main

    text = SAMPLE.read_text(encoding="utf-8")
    old = 'links = [5, 6]\npoint = "F"\nguide = { link = 6, through = "G", angle_deg = 90 }'
    assert old in text
    f = tmp_path / "moving_guide.toml"
    f.write_text(text.replace(old, 'links = [5, 1]\npoint = "F"\nguide = { link = 1, through = "O", toward = "A" }'),
                 encoding="utf-8")
    out = tmp_path / "out.json"
    assert main(["solve", str(f), "--json", str(out), "--quiet"]) == 2
    err = capsys.readouterr().err
    assert err.count("\n") == 1 and str(f) in err and "guide of the frame" in err
    assert not out.exists()
