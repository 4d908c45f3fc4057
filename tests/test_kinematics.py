"""Exact kinematics against independent oracles: derivatives of positions
(finite differences over the crank angle) and closed-form formulas."""

from __future__ import annotations

import math

import numpy as np
import pytest
from hypothesis import assume, given, settings
from hypothesis import strategies as st

from plans.kinematics.exact import solve
from plans.kinematics.placing import load_scene, scene_from_dict

from .conftest import four_bar_scene, slider_crank_scene

H_DEG = 1e-3


def _fd_check(scene, phis, rtol_v=1e-6, rtol_a=1e-4):
    """v = dr/dφ·φ', a = d²r/dφ²·φ'² + dr/dφ·φ'' (5-point stencils), for every point."""
    kin = solve(scene, phis, order=2)
    around = {d: solve(scene, phis + d * H_DEG, order=0) for d in (-2, -1, 1, 2)}
    h = math.radians(H_DEG)
    w = abs(scene.driver.omega)  # φ is counted in the sense of rotation
    e = scene.driver.eps * scene.driver.sense
    vs = max(float(np.max(np.abs(kin.point(n)[1]))) for n in kin.point_names())
    as_ = max(float(np.max(np.abs(kin.point(n)[2]))) for n in kin.point_names())
    for name in kin.point_names():
        r0, v, a = kin.point(name)

        def P(d, name=name):
            return around[d].point(name)[0]

        d1 = (-P(2) + 8 * P(1) - 8 * P(-1) + P(-2)) / (12 * h)
        d2 = (-P(2) + 16 * P(1) - 30 * r0 + 16 * P(-1) - P(-2)) / (12 * h * h)
        np.testing.assert_allclose(d1 * w, v, rtol=0, atol=rtol_v * vs, err_msg=f"v of {name}")
        np.testing.assert_allclose(d2 * w**2 + d1 * e, a, rtol=0, atol=rtol_a * as_, err_msg=f"a of {name}")


def test_samples_velocity_and_acceleration_are_derivatives_of_positions(sample_path):
    scene = load_scene(sample_path)
    phis = np.array(scene.driver.phis_deg) + 7.3  # off the special angles
    _fd_check(scene, phis)


def test_angular_rates_are_derivatives_of_link_angles(sample_path):
    scene = load_scene(sample_path)
    phis = np.array(scene.driver.phis_deg) + 3.1
    kin = solve(scene, phis, order=2)
    kp, km = solve(scene, phis + H_DEG, order=0), solve(scene, phis - H_DEG, order=0)
    h = math.radians(H_DEG)
    w = abs(scene.driver.omega)
    for lid in scene.links:
        dth = np.angle(np.exp(1j * (kp.theta(lid) - km.theta(lid)))) / (2 * h)
        np.testing.assert_allclose(dth * w, kin.omega(lid), atol=1e-6 * w + 1e-9)


def test_seed_001_closed_form_slider_crank():
    """x_B = r cos φ + sqrt(l² − r² sin² φ) and its derivatives (seed 001, with r = 122.5 mm,
    l = 245 mm, n = 650 rpm; its MATLAB listing has slips: 107.5 for r and 68.03 for ω)."""
    scene = load_scene("samples/slider_crank.toml")
    kin = solve(scene)
    r, l = 0.1225, 0.245
    w = 650 * math.pi / 30
    phi = np.radians(kin.phi_deg)
    root = np.sqrt(l**2 - (r * np.sin(phi)) ** 2)
    x = r * np.cos(phi) + root
    v = -r * w * (np.sin(phi) + r * np.sin(2 * phi) / (2 * root))
    a = -r * w**2 * (np.cos(phi) + (r * l**2 * np.cos(2 * phi) + r**3 * np.sin(phi) ** 4) / root**3)
    rB, vB, aB = kin.point("B")
    np.testing.assert_allclose(rB.real, x, rtol=1e-12)
    np.testing.assert_allclose(vB.real, v, atol=1e-12 * r * w)
    np.testing.assert_allclose(aB.real, a, atol=1e-11 * r * w**2)
    np.testing.assert_allclose(rB.imag, 0, atol=1e-15)


def test_coursework_v_engine_numbers():
    """Seed 000 at φ = 45° (hand-measured, so within a few %) and the dead position φ = 0
    as the coursework reasons it: V_B = 0, ω4 = 0, v_BA = v_A."""
    kin = solve(load_scene("samples/v_engine.toml"))
    v = lambda n: np.abs(kin.point(n)[1])  # noqa: E731
    a = lambda n: np.abs(kin.point(n)[2])  # noqa: E731
    assert v("A")[0] == pytest.approx(12.46, rel=2e-3)  # ω1 = 355.9 with π = 3.14 in the seed
    assert v("B")[0] == pytest.approx(10.6, rel=0.02)
    assert v("S2")[0] == pytest.approx(11.2, rel=0.02)
    assert abs(kin.omega(2)[0]) == pytest.approx(75.5, rel=0.02)
    assert a("B")[0] == pytest.approx(3081, rel=0.05)
    assert abs(kin.eps(2)[0]) == pytest.approx(25302, rel=0.02)
    # symmetric position: B and C mirror each other
    assert v("B")[0] == pytest.approx(v("C")[0], rel=1e-12)
    assert a("S2")[0] == pytest.approx(a("S4")[0], rel=1e-12)
    # dead position φ = 0
    assert v("B")[1] <= 1e-12 * v("A")[1]
    assert abs(kin.omega(4)[1]) <= 1e-12 * abs(kin.omega(1)[1])
    vBA = kin.point("B")[1][1] - kin.point("A")[1][1]
    assert abs(vBA - (-kin.point("A")[1][1])) <= 1e-12 * v("A")[1]
    assert abs(kin.omega(2)[1]) == pytest.approx(103.2, rel=2e-3)
    assert v("S2")[1] == pytest.approx(8.35, rel=2e-3)
    assert a("B")[1] == pytest.approx(5719, rel=2e-3)


def test_scotch_yoke_is_harmonic():
    kin = solve(load_scene("samples/scotch_yoke.toml"))
    r, w = 0.06, 300 * math.pi / 30
    phi = np.radians(kin.phi_deg)
    rK, vK, aK = kin.point("K")
    np.testing.assert_allclose(rK.real, r * np.cos(phi), atol=1e-15)
    np.testing.assert_allclose(vK.real, -r * w * np.sin(phi), atol=1e-13)
    np.testing.assert_allclose(aK.real, -r * w**2 * np.cos(phi), atol=1e-11)


def test_branch_follows_by_continuity_over_a_cycle():
    """No flip mid-cycle: over 720 positions B moves by small steps only."""
    for branch in (1, -1):
        scene = scene_from_dict(four_bar_scene(branch=branch, phi_deg=list(np.arange(0, 360, 0.5))))
        rB = solve(scene, order=0).point("B")[0]
        steps = np.abs(np.diff(np.concatenate([rB, rB[:1]])))
        assert steps.max() < 0.01  # m; a flip would jump by a chord of ~0.2 m
        assert np.all(np.sign(rB.imag) == branch)


@settings(max_examples=60, deadline=None)
@given(r=st.floats(10, 100), ratio=st.floats(1.3, 5), e=st.floats(-0.5, 0.5),
       phi=st.floats(0, 360), w=st.floats(0.5, 500), eps=st.floats(-100, 100))
def test_random_slider_cranks_match_derivatives(r, ratio, e, phi, w, eps):
    l = r * ratio
    scene = scene_from_dict(slider_crank_scene(r, l, e * (l - r), phi_deg=[phi], omega=w, eps=eps))
    _fd_check(scene, np.array([phi]), rtol_v=2e-6, rtol_a=5e-4)


@settings(max_examples=60, deadline=None)
@given(a=st.floats(20, 60), b=st.floats(150, 250), c=st.floats(150, 250), d=st.floats(180, 260),
       phi=st.floats(0, 360), branch=st.sampled_from([1, -1]))
def test_random_four_bars_match_derivatives(a, b, c, d, phi, branch):
    # Grashof crank-rocker with margin: well-conditioned by construction
    s, lmax = a, max(b, c, d)
    others = b + c + d - lmax
    assume(s + lmax <= others - 20)
    scene = scene_from_dict(four_bar_scene(a, b, c, d, phi_deg=[phi], branch=branch, omega=5.0, eps=2.0))
    _fd_check(scene, np.array([phi]), rtol_v=2e-6, rtol_a=5e-4)


def _shaper_dict(oc, r, rocker, rod, ram_y, phi, ram_kind):
    """Crank OA on a slotted rocker CD (RPR), then the ram: by a rod (RRP) or a block
    on the rocker (PRP)."""
    d = {
        "format": 1, "unit": "mm", "frame": 6,
        "outputs": ["positions", "velocity_plan", "acceleration_plan"],
        "points": {"C": [0, 0], "O": [0, oc]},
        "links": {
            "1": {"axis": ["O", "A"], "length": r},
            "2": {"axis": ["A"]},
            "3": {"axis": ["C", "D"], "length": rocker, "points": {"S3": {"ratio": 0.5}}},
        },
        "joints": [
            {"kind": "R", "links": [6, 1], "point": "O"},
            {"kind": "R", "links": [1, 2], "point": "A"},
            {"kind": "P", "links": [2, 3], "point": "A", "guide": {"link": 3, "through": "C", "toward": "D"}},
            {"kind": "R", "links": [3, 6], "point": "C"},
        ],
        "driver": {"link": 1, "omega": 7.0, "eps": 3.0, "sense": "cw", "phi_ref_deg": 0, "phi_deg": [phi]},
    }
    if ram_kind == "RRP":
        d["links"]["4"] = {"axis": ["D", "E"], "length": rod}
        d["links"]["5"] = {"axis": ["E"]}
        d["joints"] += [
            {"kind": "R", "links": [3, 4], "point": "D"},
            {"kind": "R", "links": [4, 5], "point": "E"},
            {"kind": "P", "links": [5, 6], "point": "E", "guide": {"link": 6, "through": [0, ram_y], "angle_deg": 0}},
        ]
    else:
        d["links"]["4"] = {"axis": ["E"]}
        d["links"]["5"] = {"axis": ["E"]}
        d["joints"] += [
            {"kind": "P", "links": [4, 3], "point": "E", "guide": {"link": 3, "through": "C", "toward": "D"}},
            {"kind": "R", "links": [4, 5], "point": "E"},
            {"kind": "P", "links": [5, 6], "point": "E", "guide": {"link": 6, "through": [0, ram_y], "angle_deg": 0}},
        ]
    return d


@settings(max_examples=40, deadline=None)
@given(oc=st.floats(200, 400), ratio=st.floats(0.2, 0.7), phi=st.floats(0, 360),
       ram=st.sampled_from(["RRP", "PRP"]))
def test_random_chained_groups_match_derivatives_and_construction(oc, ratio, phi, ram):
    """RPR followed by RRP or PRP: exact analysis vs derivatives, construction vs exact."""
    from plans.kinematics.construction import build

    r = oc * ratio
    rocker = 1.8 * (oc + r)
    # D's height swings between these; the ram's guide runs midway and the rod reaches it
    # at every angle with margin, so every generated mechanism turns fully
    y_low, y_high = rocker * math.sqrt(1 - ratio**2), rocker
    ram_y = 0.5 * (y_low + y_high)
    rod = 0.5 * (y_high - y_low) + 0.3 * oc
    scene = scene_from_dict(_shaper_dict(oc, r, rocker, rod, ram_y, phi, ram))
    _fd_check(scene, np.array([phi]), rtol_v=2e-6, rtol_a=5e-4)
    pp = build(solve(scene), 0)
    assert max(rd.relative for rd in pp.readings) < 1e-9


def test_two_point_slider_and_offset_guide():
    """A piston with its own axis B→Q (sliding along it), a guide given by `toward` and
    `offset`: the piston's points translate with B; derivatives still match."""
    d = slider_crank_scene(50, 180, 0, phi_deg=[10, 100, 250])
    d["points"]["G"] = [100, 0]
    d["links"]["3"] = {"axis": ["B", "Q"], "length": 30, "points": {"S3": {"along": 15, "across": 5}}}
    d["joints"][3] = {"kind": "P", "links": [3, 4], "point": "B",
                      "guide": {"link": 4, "through": "O", "toward": "G", "offset": 12}}
    scene = scene_from_dict(d)
    kin = solve(scene)
    rB, vB, _ = kin.point("B")
    np.testing.assert_allclose(rB.imag, 0.012, atol=1e-15)  # offset to the left of O→G
    rQ, vQ, _ = kin.point("Q")
    np.testing.assert_allclose(rQ - rB, 0.03, atol=1e-15)  # the piston keeps its direction
    np.testing.assert_allclose(vQ, vB, atol=1e-15)
    _fd_check(scene, np.array([10.0, 100.0, 250.0]))
