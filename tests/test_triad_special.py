"""Special positions of a class-III group: where the three leashes' axes pass through one point
(or are parallel) the group is not carried further: the engine says so, with the group and
the angle, never a NaN.  Parallel axes of two leashes only take the other pair's point."""

from __future__ import annotations

import cmath
import math
import re

import numpy as np

from plans.cli import main
from plans.kinematics.triad import SpecialPosition, Triad, place, special_kind

JOINTS = "".join(f'[[joints]]\nkind = "R"\nlinks = [{a}, {b}]\npoint = "{p}"\n' for a, b, p in (
    (6, 1, "O"), (1, 2, "A"), (2, 3, "D"), (3, 4, "E"), (4, 6, "B"), (3, 5, "F"), (5, 6, "C")))


def _design() -> tuple[complex, complex, complex, complex, complex, complex]:
    """A crank OA = 100 mm and a triad whose axes meet in S = (100, 300) at φ = 10.5° (a
    configuration the crank does not reach from φ = 0: its own fold lies elsewhere)."""
    A = 100 * cmath.exp(1j * math.radians(10.5))
    S = 100 + 300j
    D = S + 100 * (A - S) / abs(A - S)
    E, F = D + 120 - 40j, D + 70 + 90j
    return A, D, E, F, E + 1.2 * (E - S), F + 1.5 * (F - S)


def _scene() -> str:
    A, D, E, F, B, C = _design()
    loc = (F - D) / (E - D) * abs(E - D)
    return (f'format = 1\ntitle = "triad with a dead position"\nunit = "mm"\nframe = 6\n'
            f'outputs = ["positions", "velocity_plan", "acceleration_plan", "force_polygons"]\n'
            f'[points]\nO = [0, 0]\nB = [{B.real!r}, {B.imag!r}]\nC = [{C.real!r}, {C.imag!r}]\n'
            f'[links.1]\naxis = ["O", "A"]\nlength = 100\n'
            f'[links.2]\naxis = ["A", "D"]\nlength = {abs(D - A)!r}\n'
            f'[links.3]\naxis = ["D", "E"]\nlength = {abs(E - D)!r}\n'
            f'points = {{ F = {{ along = {loc.real!r}, across = {loc.imag!r} }} }}\n'
            f'[links.4]\naxis = ["B", "E"]\nlength = {abs(E - B)!r}\n'
            f'[links.5]\naxis = ["C", "F"]\nlength = {abs(F - C)!r}\n'
            + JOINTS + '[driver]\nlink = 1\nomega_rpm = 60\nsense = "ccw"\nphi_ref_deg = 0\npositions = 12\n')


def _concurrency(outer, inner) -> float:
    """Distance from the meeting point of axes 1 and 2 to axis 3, over the group's size."""
    (A, B, C), (D, E, F) = outer, inner
    u1, u2, u3 = D - A, E - B, F - C
    s = (u1.conjugate() * u2).imag
    S = A + ((B - A).conjugate() * u2).imag / s * u1
    return abs((u3.conjugate() * (S - C)).imag) / abs(u3) / max(abs(u1), abs(u2), abs(u3))


def test_dead_position_named_with_group_and_angle(tmp_path, capsys):
    f = tmp_path / "dead.toml"
    f.write_text(_scene(), encoding="utf-8")
    out = tmp_path / "out.json"
    assert main(["solve", str(f), "--json", str(out), "--quiet"]) == 2
    err = capsys.readouterr().err
    assert err.count("\n") == 1 and "nan" not in err.lower() and not out.exists()
    m = re.search(r"group RRR 2-3-4-5, point D, phi = ([0-9.]+) deg: the three leashes' axes pass through one "
                  r"point \(special position of the group\)", err)
    assert m, err
    stop = float(m.group(1))
    # walked to it apart (small steps of the leash equations from the assembly at φ = 0): the
    # axes do meet in one point there, and the group goes no further
    A0, D0, E0, F0, B, C = _design()
    t = Triad(E0 - D0, F0 - D0, abs(D0 - A0), abs(E0 - B), abs(F0 - C))
    from plans.kinematics.placing import load_scene
    from plans.kinematics.structure import analyse
    from plans.kinematics.triad_exact import _assemble

    g = analyse(load_scene(str(f))).triads()[0]

    def outer(phi: float) -> tuple[complex, complex, complex]:
        return 100 * cmath.exp(1j * math.radians(phi)), B, C
    state = _assemble(t, outer(0.0), g)
    for phi in np.arange(0.0, stop - 0.5, 0.25):
        state = place(t, outer(phi), state)
    lo, hi = stop - 0.5, stop + 0.5  # the last angle the group reaches, by bisection
    for _ in range(45):
        mid = 0.5 * (lo + hi)
        try:
            state, lo = place(t, outer(mid), state), mid
        except SpecialPosition:
            hi = mid
    assert abs(lo - stop) <= 1e-3
    assert _concurrency(outer(lo), t.inner(*state)) < 1e-3
    assert _concurrency(outer(10.0), t.inner(*place(t, outer(10.0), _assemble(t, outer(10.0), g)))) > 1e-2


def test_special_kind_names_parallel_and_concurrent_axes():
    """The three kinds: parallel axes, axes through one point, and an ordinary position."""
    u = cmath.exp(0.3j)
    D, E, F = 0j, 0.1 + 0j, 0.05 + 0.08j
    t = Triad(E - D, F - D, 0.2, 0.15, 0.25)
    parallel = (D - 0.2 * u, E - 0.15 * u, F - 0.25 * u)
    assert "parallel" in str(special_kind(t, parallel, D, 0.0))
    S = 0.05 - 0.3j  # the axes through S
    through = tuple(P + L * (S - P) / abs(S - P) for P, L in ((D, 0.2), (E, 0.15), (F, 0.25)))
    assert "one point" in str(special_kind(t, through, D, 0.0))
    ordinary = (D - 0.2j, E + 0.15, F + 0.25j)
    assert special_kind(t, ordinary, D, 0.0) is None


def test_instant_centres_of_the_class_3_samples():
    """Kennedy's theorem on the crusher and the press (a triad, a slider leash): every centre
    against its definition at random positions."""
    from pathlib import Path

    from plans.kinematics.exact import solve
    from plans.kinematics.placing import load_scene

    from .test_instant_centres import _check

    root = Path(__file__).resolve().parent.parent / "samples" / "class3"
    for name in ("triad_crusher", "triad_press"):
        kin = solve(load_scene(root / f"{name}.toml"), np.random.default_rng(5).uniform(0.0, 360.0, 12), order=1)
        size = kin.reach()
        assert max(_check(kin, k, size) for k in range(kin.n)) < 1e-9
