"""A scene with a class-III group (triad): recognised by the structure analysis, solved
exactly over a full turn (against a one-parameter solver written here and finite
differences of its positions), its plans built by Assur's special point (readings against
the exact rates), and what is not done yet refused in one line."""

from __future__ import annotations

import cmath
import json
import math
from pathlib import Path

import numpy as np
import pytest

from plans.cli import main
from plans.kinematics.construction import build_many
from plans.kinematics.exact import solve
from plans.kinematics.placing import load_scene
from plans.kinematics.structure import TriadGroup, analyse

from .newton2 import newton2

SAMPLE = Path(__file__).resolve().parent.parent / "samples" / "class3" / "triad_crusher.toml"


def _geometry(scene):
    """What the hand-written solver needs, read from the scene's links (not from the engine)."""
    L = scene.links
    crank = abs(L[1].points["A"] - L[1].points["O"])
    l1 = abs(L[2].points["D"] - L[2].points["A"])
    l2 = abs(L[4].points["E"] - L[4].points["B"])
    l3 = abs(L[5].points["F"] - L[5].points["C"])
    zD, zE, zF = L[3].points["D"], L[3].points["E"], L[3].points["F"]
    O, B, C = scene.frame_points["O"], scene.frame_points["B"], scene.frame_points["C"]
    return crank, l1, l2, l3, zD, zE, zF, O, B, C


class _TwoAngles:
    """Unknowns: the angles α of leash AD and β of leash BE (D = A + l1·e^{iα},
    E = B + l2·e^{iβ}, F = D + shape·(E − D)); equations |E − D| = |DE| and |F − C| = l3;
    Newton with a difference Jacobian from the previous angles."""

    def __init__(self, scene) -> None:
        (self.r, self.l1, self.l2, self.l3, zD, zE, zF, self.O, self.B, self.C) = _geometry(scene)
        self.de = abs(zE - zD)
        self.shape = (zF - zD) / (zE - zD)

    def A(self, phi: float) -> complex:
        return self.O + self.r * cmath.exp(1j * phi)

    def points(self, phi: float, ab: tuple[float, float]) -> tuple[complex, complex, complex]:
        D = self.A(phi) + self.l1 * cmath.exp(1j * ab[0])
        E = self.B + self.l2 * cmath.exp(1j * ab[1])
        return D, E, D + self.shape * (E - D)

    def _f(self, phi: float, ab: tuple[float, float]) -> tuple[float, float]:
        D, E, F = self.points(phi, ab)
        return abs(E - D) - self.de, abs(F - self.C) - self.l3

    def root(self, phi: float, ab: tuple[float, float]) -> tuple[float, float]:
        return newton2(lambda x: self._f(phi, x), ab, 50)


@pytest.fixture(scope="module")
def scene():
    return load_scene(str(SAMPLE))


def test_structure_names_the_triad(scene):
    st = analyse(scene)
    assert st.mobility == 1
    (g,) = st.groups
    assert isinstance(g, TriadGroup)
    assert g.links[0] == 3 and sorted(g.links) == [2, 3, 4, 5]
    js = st.to_json()["groups"][0]
    assert js["class"] == 3 and js["order"] == 3 and js["base"] == 3
    assert js["leashes"] == [["A", "D"], ["B", "E"], ["C", "F"]]


def test_full_turn_against_a_separate_solver_and_finite_differences(scene):
    phis = np.arange(0.0, 360.0, 1.0)
    kin = solve(scene, phis, order=2)
    one = _TwoAngles(scene)
    rD, rE, rF = (kin.point(n)[0] for n in "DEF")
    # the same assembly at the start: the leashes' angles read off the engine, rounded to 0.01 rad
    alpha = (round(cmath.phase(rD[0] - one.A(0.0)), 2), round(cmath.phase(rE[0] - one.B), 2))
    # branch +1: D to the left of the line A -> B at φ = 0
    assert ((one.B - one.A(0.0)).conjugate() * (rD[0] - one.A(0.0))).imag > 0
    w = scene.driver.omega
    size = 0.5
    h = 3e-3  # crank angle step of the seven-point stencils (rad): truncation and rounding both < 1e-9
    vmax = max(float(np.max(np.abs(kin.point(n)[1]))) for n in "DEF")
    amax = max(float(np.max(np.abs(kin.point(n)[2]))) for n in "DEF")
    for k, phi_deg in enumerate(phis):
        phi = math.radians(phi_deg)
        alpha = one.root(phi, alpha)
        pts = one.points(phi, alpha)
        for P, exact in zip(pts, (rD[k], rE[k], rF[k]), strict=True):
            assert abs(P - exact) <= 1e-9 * size
        if k % 5:
            continue
        around = [one.points(phi + m * h, one.root(phi + m * h, alpha)) for m in (-3, -2, -1, 1, 2, 3)]
        for idx, name in enumerate("DEF"):
            f = [p[idx] for p in around]
            d1 = (-f[0] + 9 * f[1] - 45 * f[2] + 45 * f[3] - 9 * f[4] + f[5]) / (60 * h)
            d2 = (2 * f[0] - 27 * f[1] + 270 * f[2] - 490 * pts[idx] + 270 * f[3] - 27 * f[4] + 2 * f[5]) / (180 * h * h)
            _, v, a = kin.point(name)
            assert abs(d1 * w - v[k]) <= 1e-9 * vmax, (name, phi_deg)
            assert abs(d2 * w * w - a[k]) <= 1e-9 * amax, (name, phi_deg)


def test_special_point_readings_agree_with_the_exact_rates(scene):
    kin = solve(scene, [0.0, 37.0, 90.0, 211.0, 300.0], order=2)
    plans = build_many(kin, range(kin.n))
    for pp in plans:
        got = {r.quantity: r for r in pp.readings}
        for q in ("v_D", "v_E", "v_F", "a_D", "a_E", "a_F", "omega_3", "eps_3", "omega_2", "eps_5"):
            assert q in got, q
        for r in pp.readings:
            assert abs(abs(r.value) - abs(r.exact)) <= 1e-9 * max(1.0, abs(r.exact)), r.quantity
        steps = [s.output for s in pp.velocity.steps] if pp.velocity.steps else []
        assert steps == [] or "s" in steps


def test_json_reports_class_3_and_the_rates(tmp_path, capsys):
    out = tmp_path / "out.json"
    assert main(["solve", str(SAMPLE), "--json", str(out), "--quiet"]) == 0
    data = json.loads(out.read_text(encoding="utf-8"))
    (g,) = data["structure"]["groups"]
    assert g["class"] == 3 and g["order"] == 3 and g["kind"] == "RRR"
    p = data["positions"][1]
    assert set(p["points"]["F"]) == {"r", "v", "a"}
    assert "eps" in p["links"]["3"]
    assert any(r["quantity"] == "v_F" for r in p["readings"])


def _variant(tmp_path: Path, old: str, new: str) -> Path:
    text = SAMPLE.read_text(encoding="utf-8")
    assert old in text
    f = tmp_path / "scene.toml"
    f.write_text(text.replace(old, new), encoding="utf-8")
    return f


@pytest.mark.parametrize("old,new,words", [
    ('axis = ["C", "F"]\nlength = 272', 'axis = ["C", "F"]\nlength = 20', "group RRR 2-3-4-5"),
    ('kind = "R"\nlinks = [3, 5]\npoint = "F"',
     'kind = "P"\nlinks = [3, 5]\npoint = "F"\nguide = { link = 5, through = "C", toward = "F" }',
     "revolute pairs only"),
])
def test_refusals_are_one_line(tmp_path, capsys, old, new, words):
    f = _variant(tmp_path, old, new)
    out = tmp_path / "out.json"
    code = main(["solve", str(f), "--json", str(out), "--quiet"])
    err = capsys.readouterr().err
    assert code == 2
    assert err.count("\n") == 1 and words in err and str(f) in err
    assert not out.exists()


def test_one_position_equals_the_turn(scene):
    """A few positions are solved in Python numbers, a turn on arrays: the same numbers."""
    many = solve(scene, np.arange(0.0, 360.0, 30.0), order=2)
    for phi in (30.0, 211.0):
        few = solve(scene, [phi, 90.0], order=2)
        ref = solve(scene, np.array([phi, 90.0, 0.0, 0.0, 0.0]), order=2)
        for n in "DEFK":
            for x, y in zip(few.point(n), ref.point(n), strict=True):
                assert np.max(np.abs(x - y[:2])) <= 1e-12
        assert abs(few.omega(3)[0] - ref.omega(3)[0]) <= 1e-12
    assert abs(many.eps(3)[1] - solve(scene, [30.0], order=2).eps(3)[0]) <= 1e-9


def test_pencils_and_positions_built_together():
    """The noisy pencil without noise reads what the perfect one reads; positions built
    together read what each built alone reads (the same checks as for the class-II samples)."""
    from .test_pencils import (
        test_noisy_pencil_without_noise_draws_the_plans,
        test_positions_built_together_are_the_positions_built_one_by_one,
    )

    test_noisy_pencil_without_noise_draws_the_plans(SAMPLE)
    test_positions_built_together_are_the_positions_built_one_by_one(SAMPLE)


def test_parallel_axes_take_the_other_pair(tmp_path):
    """The leash CF numbered second: at the angle where AD ∥ CF Assur's point is where the
    axes of CF and BE meet, and the plans still read the exact rates."""
    text = SAMPLE.read_text(encoding="utf-8")
    for old, new in (("[links.4]", "[links.X]"), ("[links.5]", "[links.4]"), ("[links.X]", "[links.5]"),
                     ("links = [3, 4]", "links = [3, Y]"), ("links = [4, 6]", "links = [Y, 6]"),
                     ("links = [3, 5]", "links = [3, 4]"), ("links = [5, 6]", "links = [4, 6]"),
                     ("Y", "5"), ('"2-3-4-5" = 1', '"2-3-4-5" = 1')):
        assert old in text
        text = text.replace(old, new)
    f = tmp_path / "renumbered.toml"
    f.write_text(text, encoding="utf-8")
    sc = load_scene(str(f))
    assert [o.point for o, _ in analyse(sc).groups[0].joints] == ["A", "C", "B"]

    def sin(phi: float) -> float:
        k = solve(sc, [phi], order=0)
        A, D, C, F = (complex(k.point(n)[0][0]) for n in "ADCF")
        return ((D - A).conjugate() * (F - C)).imag / abs(D - A) / abs(F - C)
    lo, hi = 340.0, 355.0
    assert sin(lo) * sin(hi) < 0
    for _ in range(50):
        mid = 0.5 * (lo + hi)
        lo, hi = (mid, hi) if sin(lo) * sin(mid) > 0 else (lo, mid)
    kin = solve(sc, [lo], order=2)
    (pp,) = build_many(kin, [0])
    for r in pp.readings:
        assert abs(abs(r.value) - abs(r.exact)) <= 1e-9 * max(1.0, abs(r.exact)), r.quantity
    labels = [ln.label for ln in pp.velocity.lines]
    assert labels[:4] == ["⟂ CF", "⟂ BE", "⟂ AD", "⟂ SD"]  # s from CF and BE, then d from a and s
    far = build_many(solve(sc, [300.0], order=2), [0])[0]
    assert [ln.label for ln in far.velocity.lines][:4] == ["⟂ AD", "⟂ CF", "⟂ BE", "⟂ SE"]
