"""Instant centres by Kennedy's theorem against the centre's own definition.

The oracle is written here, apart from the construction: the point where two links have
the same velocity, P_ij = Q + i·(v_i(Q) − v_j(Q)) / (ω_i − ω_j), from the exact analysis'
velocities of each link's origin; where ω_i = ω_j the centre lies at infinity,
perpendicular to the common relative velocity.
"""

from __future__ import annotations

import json
import math
from itertools import combinations
from pathlib import Path

import numpy as np
import pytest

from plans.kinematics.centres import Centre, all_links, centres_at, kennedy, velocities_at
from plans.kinematics.exact import solve
from plans.kinematics.placing import load_scene
from plans.results import solve_scene, to_json

SAMPLES = Path(__file__).resolve().parent.parent / "samples" / "centres"
MECHANISMS = ["four_bar", "slider_crank", "six_bar"]


def _motion(kin, link: int, k: int) -> tuple[complex, complex, float]:
    """(r, v) of the link's local origin and ω at position k; the frame is at rest."""
    if link == kin.scene.frame:
        return 0j, 0j, 0.0
    r, v, _ = kin.point_on(link, 0j)
    return complex(r[k]), complex(v[k]), float(kin.omega(link)[k])


def _oracle(kin, i: int, j: int, k: int) -> tuple[str, complex]:
    ri, vi, wi = _motion(kin, i, k)
    rj, vj, wj = _motion(kin, j, k)
    q = 0j  # any point of the plane, taken as a point of both links
    vi_q = vi + 1j * wi * (q - ri)
    vj_q = vj + 1j * wj * (q - rj)
    if abs(wi - wj) <= 1e-12 * max(abs(wi), abs(wj), abs(kin.scene.driver.omega)):
        return "direction", 1j * (vi_q - vj_q)
    return "point", q + 1j * (vi_q - vj_q) / (wi - wj)


def _check(kin, k: int, size: float) -> float:
    """Every centre at position k against the oracle; the largest error over the size."""
    got = centres_at(kin, k)
    links = all_links(kin)
    assert sorted(got) == list(combinations(links, 2))
    n = len(links)
    assert len(got) == n * (n - 1) // 2
    worst = 0.0
    for (i, j), c in got.items():
        kind, z = _oracle(kin, i, j, k)
        if kind == "direction" and abs(z) <= 1e-12 * abs(kin.scene.driver.omega) * size:
            assert c.point is not None or c.direction is not None
            continue  # the two links are at rest relative to each other: any centre will do
        if kind == "point" and abs(z) > 1e6 * size:  # beyond any drawing: a direction to the draftsman
            kind, z = "direction", z
        if kind == "point":
            assert c.point is not None, (i, j, k, c)
            far = max(1.0, abs(z) / size)
            err = abs(c.point - z) / size / far**2  # a far intersection is as sharp as its angle
            assert err <= 1e-9, (i, j, k, c.point, z)
            worst = max(worst, err)
        else:
            assert c.direction is not None, (i, j, k, c)
            assert abs(abs(c.direction) - 1) < 1e-12
            sin = abs((c.direction.conjugate() * z).imag) / abs(z)
            assert sin <= 1e-9, (i, j, k, c.direction, z)
    return worst


@pytest.mark.parametrize("name", MECHANISMS)
def test_every_centre_agrees_with_its_definition_at_random_positions(name: str) -> None:
    scene = load_scene(SAMPLES / f"{name}.toml")
    phis = np.random.default_rng(hash(name) % 2**32).uniform(0.0, 360.0, 40)
    kin = solve(scene, phi_deg=phis, order=1)
    size = kin.reach()
    worst = max(_check(kin, k, size) for k in range(kin.n))
    assert worst < 1e-9


@pytest.mark.parametrize("name", MECHANISMS)
def test_velocities_by_centres_agree_with_the_exact_ones(name: str) -> None:
    scene = load_scene(SAMPLES / f"{name}.toml")
    kin = solve(scene, phi_deg=np.random.default_rng(7).uniform(0.0, 360.0, 20), order=1)
    v_ref = abs(scene.driver.omega) * kin.reach()
    for k in range(kin.n):
        for cv in velocities_at(kin, k, centres_at(kin, k)):
            assert cv.v is not None, (name, k, cv.point)
            assert abs(cv.v - cv.exact) <= 1e-9 * v_ref, (name, k, cv.point, cv.v, cv.exact)


def test_dead_centres_give_the_draftsmans_centres() -> None:
    """Slider-crank at both dead centres: the piston stands (P34 at infinity, v_B = 0), the
    rod's centre relative to the frame is the piston pin B, P13 is the crank's pivot O."""
    scene = load_scene(SAMPLES / "slider_crank.toml")
    kin = solve(scene, phi_deg=[0.0, 180.0], order=1)
    size = kin.reach()
    for k in range(2):
        c = centres_at(kin, k)
        B = complex(kin.point("B")[0][k])
        assert abs(c[(2, 4)].point - B) < 1e-9 * size
        assert abs(c[(1, 3)].point - 0j) < 1e-9 * size
        assert c[(3, 4)].direction is not None
        _check(kin, k, size)
        vb = [cv for cv in velocities_at(kin, k, c) if cv.point == "B"][0]
        assert vb.v is not None and abs(vb.v) < 1e-9


def test_four_bar_rocker_at_its_extreme_turns_about_the_crank_pivot() -> None:
    """Where crank and coupler line up, ω3 = 0: P13 is the crank's pivot O and P34 = D."""
    scene = load_scene(SAMPLES / "four_bar.toml")
    grid = solve(scene, phi_deg=np.linspace(0.0, 360.0, 73), order=1).omega(3)
    k = int(np.nonzero(np.sign(grid[:-1]) != np.sign(grid[1:]))[0][0])
    lo, hi = 5.0 * k, 5.0 * (k + 1)
    w_lo = float(solve(scene, phi_deg=[lo], order=1).omega(3)[0])
    for _ in range(60):  # bisection on the sign of ω3
        mid = 0.5 * (lo + hi)
        w = float(solve(scene, phi_deg=[mid], order=1).omega(3)[0])
        lo, hi, w_lo = (mid, hi, w) if (w > 0) == (w_lo > 0) else (lo, mid, w_lo)
    kin = solve(scene, phi_deg=[lo], order=1)
    size = kin.reach()
    c = centres_at(kin, 0)
    assert abs(c[(1, 3)].point) < 1e-9 * size
    _check(kin, 0, size)


def test_six_bar_with_the_crank_along_the_rocker_fixes_what_kennedy_lines_cannot() -> None:
    """At φ = 90° the crank lies along the rocker: every Kennedy line of P15 is the line OC,
    and blocks 2 and 4 slide in one slot.  The draftsman fixes P15 on that line by the
    angular velocities (through a third link k: (ω1 − ωk)(P − P1k) = (ω5 − ωk)(P − Pk5)) and
    puts P24 at infinity ⟂ the slot (ω2 = ω4); both agree with the definition, as does every
    other centre, and the velocities by the centres with the exact ones."""
    kin = solve(load_scene(SAMPLES / "six_bar.toml"), phi_deg=[90.0], order=1)
    got = centres_at(kin, 0)
    size = kin.reach()
    assert all(c.point is not None or c.direction is not None for c in got.values())
    assert {key for key, c in got.items() if c.by} == {(1, 5), (2, 4)}
    assert got[(1, 5)].to_json()["by"] == "omega_ratio"
    _check(kin, 0, size)
    kind, z = _oracle(kin, 1, 5, 0)
    assert kind == "point" and abs(got[(1, 5)].point - z) < 1e-9 * size
    v_ref = abs(kin.scene.driver.omega) * size
    for cv in velocities_at(kin, 0, got):
        assert cv.v is not None and abs(cv.v - cv.exact) <= 1e-9 * v_ref, cv.point
    json.dumps([c.to_json() for c in got.values()], allow_nan=False)


def test_six_bar_at_the_stroke_end_takes_p16_for_p15() -> None:
    """At the ram's stroke end (ω3 = 0, the crank ⟂ the rocker) the ram stands still: P15 is
    the crank's point at rest, its pivot P16, as the draftsman takes it."""
    scene = load_scene(SAMPLES / "six_bar.toml")
    phis = np.arange(0.0, 360.0, 5.0)
    w = solve(scene, phi_deg=phis, order=1).omega(3)
    k0 = int(np.flatnonzero(np.sign(w[:-1]) != np.sign(w[1:]))[0])
    lo, hi = float(phis[k0]), float(phis[k0 + 1])
    w_lo = float(w[k0])
    for _ in range(60):  # bisection on the sign of ω3
        mid = 0.5 * (lo + hi)
        wm = float(solve(scene, phi_deg=[mid], order=1).omega(3)[0])
        lo, hi, w_lo = (mid, hi, wm) if (wm > 0) == (w_lo > 0) else (lo, mid, w_lo)
    kin = solve(scene, phi_deg=[lo], order=1)
    size = kin.reach()
    got = centres_at(kin, 0)
    assert abs(got[(1, 5)].point - got[(1, 6)].point) < 1e-9 * size
    assert all(c.point is not None or c.direction is not None for c in got.values())
    _check(kin, 0, size)


def test_coincident_kennedy_lines_leave_the_centre_undetermined_not_nan() -> None:
    """All four pivots of a four-bar on one line (the change point): both Kennedy lines of
    P13 and of P24 are that line; the centres are reported undetermined."""
    pts = {(1, 2): -1 + 0j, (2, 3): 1 + 0j, (3, 4): 3 + 0j, (1, 4): 0j}
    got = kennedy([1, 2, 3, 4], {k: Centre(k, z, None, "pair") for k, z in pts.items()}, 3.0)
    for key in ((1, 3), (2, 4)):
        c = got[key]
        assert c.point is None and c.direction is None
        assert "coincide" in c.why
        text = json.dumps(c.to_json(), allow_nan=False)
        assert '"point": null' in text and '"direction": null' in text


def test_parallel_kennedy_lines_put_the_centre_at_infinity() -> None:
    """A parallelogram four-bar: the coupler translates (P24 at infinity, along the cranks'
    perpendicular... the cranks' direction) and P13 lies at infinity along the coupler."""
    pts = {(1, 2): 1j, (2, 3): 2 + 1j, (3, 4): 2 + 0j, (1, 4): 0j}
    got = kennedy([1, 2, 3, 4], {k: Centre(k, z, None, "pair") for k, z in pts.items()}, 2.0)
    assert got[(1, 3)].point is None and abs(got[(1, 3)].direction - 1) < 1e-15
    assert got[(2, 4)].point is None and abs(got[(2, 4)].direction - 1j) < 1e-15


@pytest.mark.parametrize("name", MECHANISMS)
def test_json_names_and_plan_readings(name: str) -> None:
    sol = solve_scene(load_scene(SAMPLES / f"{name}.toml"))
    data = json.loads(json.dumps(to_json(sol), allow_nan=False))
    assert "instant_centres" in data["outputs"]
    n = len(sol.scene.links) + 1
    for pos in data["positions"]:
        cs = pos["instant_centres"]
        assert len(cs) == n * (n - 1) // 2
        for c in cs:
            assert set(c) >= {"links", "point", "direction", "from"}
            assert (c["point"] is None) != (c["direction"] is None) or c["undetermined"]
            if isinstance(c["from"], list):  # [[i, k], [k, j]]: the triangle i-k-j of the circle diagram
                (a, k1), (k2, b) = c["from"]
                assert [a, b] == c["links"] and k1 == k2 and k1 not in c["links"]
            else:
                assert c["from"] == "pair" or (c["from"] is None and c["undetermined"])
        open_ = any(c["point"] is None and c["direction"] is None for c in cs)
        for v in pos["velocities_by_centres"]:
            assert v["v"] is not None or open_
            if v["v_plan"] is not None and v["v"] is not None:
                assert math.isclose(v["v"], v["v_plan"], rel_tol=1e-9, abs_tol=1e-9 * (1 + v["v_exact"]))


def test_random_crank_rockers_and_offset_slider_cranks() -> None:
    """Beyond the samples: random proportions (crank-rockers by Grashof, slider-cranks with
    an offset and an inclined guide), random positions, every centre by its definition."""
    import tomllib

    from plans.kinematics.placing import scene_from_dict

    rng = np.random.default_rng(2024)
    four = tomllib.loads((SAMPLES / "four_bar.toml").read_text(encoding="utf-8"))
    slider = tomllib.loads((SAMPLES / "slider_crank.toml").read_text(encoding="utf-8"))
    checked = 0
    for _ in range(6):
        d = dict(four)
        crank = float(rng.uniform(30, 90))
        frame_len, coupler, rocker = (float(x) for x in rng.uniform(200, 320, 3))
        longest = max(frame_len, coupler, rocker)
        if crank + longest > frame_len + coupler + rocker - longest:  # Grashof, the crank shortest
            continue
        d["points"] = {"O": [0, 0], "D": [frame_len, float(rng.uniform(-60, 60))]}
        d["links"] = {**four["links"], "1": {**four["links"]["1"], "length": crank},
                      "2": {**four["links"]["2"], "length": coupler}, "3": {**four["links"]["3"], "length": rocker}}
        d.pop("loads", None)
        scene = scene_from_dict(d, "random-four-bar")
        kin = solve(scene, phi_deg=rng.uniform(0, 360, 10), order=1)
        for k in range(kin.n):
            _check(kin, k, kin.reach())
            checked += 1
    for _ in range(4):
        d = dict(slider)
        r = float(rng.uniform(50, 120))
        joints = [dict(j) for j in slider["joints"]]
        joints[3] = {**joints[3], "guide": {"link": 4, "through": [0, float(rng.uniform(-40, 40))],
                                            "angle_deg": float(rng.uniform(-30, 30))}}
        d["joints"] = joints
        d["links"] = {**slider["links"], "1": {**slider["links"]["1"], "length": r},
                      "2": {**slider["links"]["2"], "length": float(rng.uniform(3.2, 4.5)) * r}}
        d.pop("loads", None)
        scene = scene_from_dict(d, "random-slider-crank")
        kin = solve(scene, phi_deg=rng.uniform(0, 360, 10), order=1)
        for k in range(kin.n):
            _check(kin, k, kin.reach())
            checked += 1
    assert checked >= 80
