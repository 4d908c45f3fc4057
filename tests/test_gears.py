"""Gears: seed 001's table 2.4 proven (and its slips shown), with independent oracles:
the involute by its defining property, the contact ratio by turning two real profiles,
Willis against the velocity plan against plane rigid-body kinematics."""

from __future__ import annotations

import math

import mpmath
import numpy as np
import pytest
import shapely
from hypothesis import given, settings
from hypothesis import strategies as st

from plans.errors import InputError
from plans.gears import shifts
from plans.gears.geometry import pair, wheel
from plans.gears.involute import inv, inv_inverse, rolled_points
from plans.gears.meshing import meshing
from plans.gears.model import load_gears, parse_gears
from plans.gears.solve import ratios, solve_gears, to_json
from plans.gears.synthesis import synthesise

SEED = "samples/gears/seed_train.toml"
PLANETARY = "samples/gears/planetary_2kh.toml"
A20 = math.radians(20.0)
M = 4e-3


def seed_solution():
    return solve_gears(load_gears(SEED))


# --------------------------------------------------------------------------- involute


@settings(max_examples=60, derandomize=True, deadline=None)
@given(st.floats(min_value=1e-7, max_value=50.0))
def test_inv_inverse_to_1e12_against_mpmath(v):
    a = inv_inverse(v)
    mpmath.mp.dps = 40
    exact = mpmath.findroot(lambda t: mpmath.tan(t) - t - v, mpmath.mpf(a))
    assert abs(a - float(exact)) <= 1e-12 * float(exact)


def test_involute_points_by_their_defining_property():
    rb = 0.0488
    th = np.linspace(0.0, 0.8, 41)
    pts, T, L = rolled_points(rb, th, start=0.3, sign=-1.0)
    # each point lies on the tangent at T (PT ⟂ OT) at the unrolled arc r_b θ from T
    assert np.allclose(((pts - T) * np.conj(T)).real, 0.0, atol=1e-15)
    assert np.allclose(np.abs(pts - T), rb * th, rtol=1e-14, atol=1e-16)
    # polar form of the involute: r = r_b / cos α_y, angle = start − inv α_y
    ay = np.arctan(th)
    assert np.allclose(np.abs(pts), rb / np.cos(ay), rtol=1e-14)
    assert np.allclose(np.angle(pts), 0.3 - (np.tan(ay) - ay), atol=1e-14)
    # the generating line is the curve's normal: the chord direction ⟂ PT
    d = np.diff(pts)
    mid = (pts[1:] + pts[:-1]) / 2
    Tm = rb * np.exp(1j * (0.3 - (th[1:] + th[:-1]) / 2))
    cosang = np.abs((d * np.conj(mid - Tm)).real) / (np.abs(d) * np.abs(mid - Tm) + 1e-300)
    assert np.max(cosang[1:]) < 1e-3


# --------------------------------------------------------------------------- seed 001, table 2.4


def test_seed_shift_and_the_exact_undercut_limit():
    assert round(shifts.minimum(14, A20, 1.0), 5) == 0.17647  # the seed's x2 = (17 − 14)/17
    assert shifts.minimum(26, A20, 1.0) == 0.0 and shifts.minimum(46, A20, 1.0) == 0.0
    # the exact limit 1 − 14 sin²20°/2 is larger: the seed's gear 2 is cut a hair undercut
    assert round(shifts.no_undercut(14, A20, 1.0), 5) == 0.18116
    sol = seed_solution()
    assert sol.x["2"] == pytest.approx(3 / 17, abs=1e-15)
    assert sol.pairs[0].checks()["no_undercut_2"] is False


def test_seed_radii_thickness_and_ratios_as_printed():
    sol = seed_solution()
    p12, p23 = sol.pairs
    w1, w2 = p12.wheels
    w3 = p23.wheels[1]
    assert [round(w.pitch * 1e3, 3) for w in (w1, w2, w3)] == [52.0, 28.0, 92.0]
    assert [round(w.base * 1e3, 3) for w in (w1, w2, w3)] == [48.864, 26.311, 86.452]
    assert [round(p.a * 1e3, 3) for p in (p12, p23)] == [80.0, 120.0]
    assert round(w1.root * 1e3, 3) == 47.0 and round(w3.root * 1e3, 3) == 87.0
    # the seed prints 47.412 for gear 2's root "radius": that is its diameter
    assert round(2 * w2.root * 1e3, 3) == 47.412
    # s2 = 6.79703 mm: the seed's 6.79 is cut off, not rounded (6.80)
    assert round(w1.thickness * 1e3, 2) == 6.28 and math.floor(w2.thickness * 1e5) / 100 == 6.79
    r = ratios(sol)
    assert round(r["1-2"], 2) == -0.54 and round(r["2-3"], 2) == -3.29
    # i13 = z3/z1 = 1.769; the seed's 1.78 is the product of the rounded −0.54 × −3.29
    assert r["1-3"] == pytest.approx(46 / 26, rel=1e-12)
    assert round(0.54 * 3.29, 2) == 1.78


def test_seed_working_angles_do_not_follow_from_its_shifts():
    sol = seed_solution()
    p12, p23 = sol.pairs
    for p, z_sum in ((p12, 40), (p23, 60)):
        # the exact α_w satisfies the course's equation to the last bits
        lhs = inv(p.alpha_w)
        rhs = inv(A20) + 2 * math.tan(A20) * (3 / 17) / z_sum
        assert abs(lhs - rhs) <= 1e-15
    assert round(math.degrees(p12.alpha_w), 2) == 21.30 and round(math.degrees(p23.alpha_w), 2) == 20.88
    assert round(p12.a_w * 1e3, 3) == 80.684 and round(p23.a_w * 1e3, 3) == 120.691
    # the seed's 20.33° and 20.73° do not: they would need Σx/Σz 0.00107 and 0.00241, not
    # 0.17647/40 = 0.00441 and 0.17647/60 = 0.00294 (and the bigger wheel sum the bigger angle)
    for deg in (20.33, 20.73):
        assert abs(inv(math.radians(deg)) - inv(A20)) / (2 * math.tan(A20)) < 0.0025


def test_seed_chain_from_its_angles_reproduces_its_digits():
    """From the seed's (wrong) α_w on, its arithmetic is right: a_w, y, Δy, r_a, α_a."""
    a_w12 = 80 * math.cos(A20) / math.cos(math.radians(20.33))
    a_w23 = 120 * math.cos(A20) / math.cos(math.radians(20.73))
    assert round(a_w12, 3) == 80.169 and round(a_w23, 3) == 120.569
    # the seed's y come from the rounded a_w: 0.169/4, 0.569/4 (unrounded: 0.04235, 0.14222)
    y12, y23 = (round(a_w12, 3) - 80) / 4, (round(a_w23, 3) - 120) / 4
    assert round(y12, 5) == 0.04225 and round(y23, 5) == 0.14225
    assert round((a_w12 - 80) / 4, 5) == 0.04235
    dy = 0.17647 - 0.04225
    assert round(dy, 5) == 0.13422
    tips = [wheel(n, z, x, False, M, A20, 1.0, 0.25, A20, dy, "t", None)
            for n, z, x in (("1", 26, 0.0), ("2", 14, 0.17647), ("3", 46, 0.0))]
    assert [round(w.tip * 1e3, 2) for w in tips] == [55.46, 32.17, 95.46]
    # the seed's α_a are taken from the rounded r_a (from the unrounded: 35.12°, 25.10°)
    rounded = [math.degrees(math.acos(w.base / (round(w.tip * 1e3, 2) * 1e-3))) for w in tips]
    assert [round(a, 2) for a in rounded] == [28.23, 35.13, 25.09]


def test_seed_contact_ratios_and_tip_thickness_are_slips():
    t = lambda d: math.tan(math.radians(d))  # noqa: E731
    # the course's formula on the seed's own inputs gives 1.43 and 1.38, not 1.46 and 1.35
    e12 = (26 * (t(28.23) - t(20.33)) + 14 * (t(35.13) - t(20.33))) / (2 * math.pi)
    e23 = (14 * (t(35.13) - t(20.73)) + 46 * (t(25.09) - t(20.73))) / (2 * math.pi)
    assert round(e12, 2) == 1.43 and round(e23, 2) == 1.38
    # 1.35 is what comes out with the teeth written as 40 and 15
    assert round((40 * (t(25.09) - t(20.73)) + 15 * (t(35.13) - t(20.73))) / (2 * math.pi), 2) == 1.35
    # s_a2 from the seed's r_a2 = 32.17, α_a2 = 35.13°, s2 = 6.79 is 2.94, not 3.01
    sa = 2 * 32.17 * (6.79 / 56 + inv(A20) - inv(math.radians(35.13)))
    assert round(sa, 2) == 2.94
    # exact: both pairs and the tip of gear 2 satisfy the course's checks all the same
    p12, p23 = seed_solution().pairs
    assert round(p12.contact_ratio, 4) == 1.4734 and round(p23.contact_ratio, 4) == 1.5305
    assert round(p12.wheels[1].tip_thickness * 1e3, 3) == 2.250
    assert p12.wheels[1].tip_thickness > 0.4 * M
    for p in (p12, p23):
        c = p.checks()
        assert c["contact_ratio"] and c["no_interference"] and c["tip_thickness_2"]


def test_the_seed_centre_distance_cannot_hold_its_shifts():
    text = open(SEED, encoding="utf-8").read().replace(
        'gears = ["1", "2"]\ndraw = true', 'gears = ["1", "2"]\ndraw = true\ncentre_distance = 80.169')
    text = text.replace('x = "auto"', 'x = 0.17647')
    import tomllib

    with pytest.raises(InputError, match="teeth would jam.*80.6844"):
        solve_gears(parse_gears(tomllib.loads(text), "seed.toml"))


# --------------------------------------------------------------------------- oracles


def _course_eps(p):
    (w1, w2), tw = p.wheels, math.tan(p.alpha_w)
    s = -1.0 if p.internal else 1.0
    return (w1.z * (math.tan(w1.tip_angle) - tw) + s * w2.z * (math.tan(w2.tip_angle) - tw)) / (2 * math.pi)


@pytest.mark.parametrize("path", [SEED, PLANETARY])
def test_contact_ratio_line_of_action_equals_the_course_formula(path):
    for p in solve_gears(load_gears(path)).pairs:
        assert p.contact_ratio == pytest.approx(_course_eps(p), rel=1e-13)


def _flank(w, alpha, n=600):
    th = np.linspace(0.0, math.sqrt((w.tip / w.base) ** 2 - 1.0), n)
    pts, _, _ = rolled_points(w.base, th, start=w.thickness / (2 * w.pitch) + inv(alpha), sign=-1.0)
    return pts


def test_contact_ratio_by_turning_two_profiles():
    """Mean number of flank pairs touching while gear 1 turns one pitch = ε."""
    p = seed_solution().pairs[0]
    w1, w2 = p.wheels
    O1, O2 = complex(0, -w1.working), complex(0, w2.working)
    f1, f2 = _flank(w1, p.alpha), _flank(w2, p.alpha)
    psi1 = w1.thickness / (2 * w1.pitch) + inv(p.alpha) - inv(p.alpha_w)
    psi2 = w2.thickness / (2 * w2.pitch) + inv(p.alpha) - inv(p.alpha_w)
    tol = 2e-4 * p.m
    counts = []
    steps = 240
    for k in range(steps):
        phi = -2 * math.pi / w1.z * (k + 0.5) / steps  # gear 1 turns clockwise, driving
        A = [O1 + f1 * np.exp(1j * (math.pi / 2 - psi1 + j * 2 * math.pi / w1.z + phi)) for j in range(-3, 4)]
        B = [O2 + f2 * np.exp(1j * (-math.pi / 2 - psi2 + j * 2 * math.pi / w2.z - phi * w1.z / w2.z))
             for j in range(-3, 4)]
        n = 0
        for a in A:
            for b in B:  # only flanks whose boxes meet can touch
                if (a.real.min() > b.real.max() + tol or b.real.min() > a.real.max() + tol
                        or a.imag.min() > b.imag.max() + tol or b.imag.min() > a.imag.max() + tol):
                    continue
                la = shapely.LineString(np.column_stack([a.real, a.imag]))
                if la.distance(shapely.LineString(np.column_stack([b.real, b.imag]))) < tol:
                    n += 1
        counts.append(n)
    assert np.mean(counts) == pytest.approx(p.contact_ratio, abs=2.5 / steps + 0.01)
    assert set(counts) <= {1, 2}


def test_meshing_drawing_profiles_touch_and_read_the_contact_ratio():
    pairs = solve_gears(load_gears(SEED)).drawn_pairs() + solve_gears(load_gears(PLANETARY)).drawn_pairs()
    assert [p.internal for p in pairs] == [False, False, True]
    for p in pairs:
        mg = meshing(p)
        tooth = max(w.tip - w.root for w in p.wheels) * 1e3 * mg.k
        assert 40.0 <= tooth <= 60.0
        polys = []
        for dw in mg.wheels:
            wedge = shapely.Polygon([(z.real, z.imag) for z in dw.outline] + [(dw.centre.real, dw.centre.imag)])
            if p.internal and dw is mg.wheels[1]:  # the ring's body: a wider wedge less its hole
                a0, a1 = (np.angle(z - dw.centre) for z in (dw.outline[0], dw.outline[-1]))
                far = [dw.centre + 2 * dw.radii["root"] * np.exp(1j * a) for a in np.linspace(a0, a1, 50)]
                big = shapely.Polygon([(dw.centre.real, dw.centre.imag)] + [(z.real, z.imag) for z in far])
                wedge = big.buffer(0).difference(wedge.buffer(0))
            polys.append(wedge.buffer(0))
        assert polys[0].intersection(polys[1]).area < 1e-3  # mm²: the profiles never cut into each other
        assert polys[0].distance(polys[1]) < 0.01  # and they touch (at P)
        # line of action: tangent to both base circles, through P
        for dw, N in zip(mg.wheels, (mg.N1, mg.N2), strict=True):
            assert abs(N - dw.centre) == pytest.approx(dw.radii["base"], rel=1e-12)
            assert abs(((N - dw.centre) * np.conj(mg.N2 - mg.N1)).real) < 1e-9 * abs(N - dw.centre) ** 2
        assert abs(((mg.N1) * np.conj(mg.N2 - mg.N1)).imag) < 1e-9 * abs(mg.N2 - mg.N1) ** 2
        assert mg.contact_ratio_drawn == pytest.approx(p.contact_ratio, abs=2e-3)


def test_planetary_willis_plan_and_rigid_body_kinematics_agree():
    sol = solve_gears(load_gears(PLANETARY))
    w1 = 1450 * math.pi / 30
    # Willis, closed form: i_1H = 1 + z3/z1 with the ring held
    assert sol.omega["H"] == pytest.approx(w1 / (1 + 70 / 20), rel=1e-14)
    for n, w in sol.omega.items():
        assert sol.plan.lines[n].omega == pytest.approx(w, rel=1e-12, abs=1e-12 * w1)
    # plane rigid-body kinematics with the planet at an arbitrary angle β: no slip at the sun's
    # and the ring's pitch points
    p12, p23 = sol.pairs
    beta = 0.7
    e = complex(math.cos(beta), math.sin(beta))
    C = p12.a_w * e
    S = p12.wheels[0].working * e
    R = (p12.a_w + p12.wheels[1].working) * e
    # unknowns (ωH, ω2): v(p) = i ωH C + i ω2 (p − C)
    A = np.array([[(1j * C).real, (1j * (S - C)).real], [(1j * C).imag, (1j * (S - C)).imag],
                  [(1j * C).real, (1j * (R - C)).real], [(1j * C).imag, (1j * (R - C)).imag]])
    b = np.array([(1j * w1 * S).real, (1j * w1 * S).imag, 0.0, 0.0])
    (wH, w2), *_ = np.linalg.lstsq(A, b, rcond=None)
    assert sol.omega["H"] == pytest.approx(wH, rel=1e-12)
    assert sol.omega["2"] == pytest.approx(w2, rel=1e-12)


def test_seed_train_plan_agrees_with_willis_to_1e12():
    sol = seed_solution()
    for n, w in sol.omega.items():
        assert abs(sol.plan.lines[n].omega - w) <= 1e-12 * abs(w)
    assert sol.omega["3"] == pytest.approx(650 * math.pi / 30 * 26 / 46, rel=1e-14)


def test_differential_needs_two_speeds_and_then_agrees():
    base = open(PLANETARY, encoding="utf-8").read().split("\n[synthesis]")[0]
    import tomllib

    free = base.replace('name = "3"\nspeed_rpm = 0', 'name = "3"')
    with pytest.raises(InputError, match="degree"):
        solve_gears(parse_gears(tomllib.loads(free), "d.toml"))
    two = base.replace('name = "3"\nspeed_rpm = 0', 'name = "3"\nspeed_rpm = -200')
    sol = solve_gears(parse_gears(tomllib.loads(two), "d.toml"))
    w1, w3 = 1450 * math.pi / 30, -200 * math.pi / 30
    wH = (w1 * 20 + w3 * 70) / 90  # Willis: (ω1 − ωH)/(ω3 − ωH) = −z3/z1
    assert sol.omega["H"] == pytest.approx(wH, rel=1e-13)
    assert sol.plan.lines["H"].omega == pytest.approx(wH, rel=1e-12)


def test_equal_sliding_rule():
    x1, x2 = shifts.equal_sliding(("1", "2"), (18, 40), M, A20, 1.0, 0.25)
    assert x1 == pytest.approx(-x2, abs=1e-15) and x1 > 0
    p = pair(("1", "2"), (18, 40), (x1, x2), False, M, A20, 1.0, 0.25, (0.0, 0.0))
    assert p.sliding[0] == pytest.approx(p.sliding[1], rel=1e-9)
    assert p.a_w == pytest.approx(p.a, rel=1e-14)


def test_internal_pair_and_given_centre_distance():
    p = pair(("2", "3"), (25, 70), (0.0, 0.0), True, 2e-3, A20, 1.0, 0.25, (0.0, 0.0))
    assert p.a == pytest.approx(45e-3) and p.alpha_w == pytest.approx(A20, rel=1e-14)
    # x chosen for a given centre distance: the pair meshes without backlash exactly there
    import tomllib

    text = open(SEED, encoding="utf-8").read().replace('draw = true', 'draw = true\ncentre_distance = 81')
    sol = solve_gears(parse_gears(tomllib.loads(text), "s.toml"))
    assert sol.pairs[0].a_w == pytest.approx(81e-3, rel=1e-12)
    assert sol.pairs[0].backlash == 0.0


def test_synthesis_meets_its_conditions_and_is_the_smallest():
    gf = load_gears(PLANETARY)
    t = synthesise(gf.synthesis, 1.0)
    assert t.z1 + 2 * t.z2 == t.z3 and (t.z1 + t.z3) % t.planets == 0
    assert math.sin(math.pi / t.planets) > (t.z2 + 2) / (t.z1 + t.z2)
    assert abs(t.ratio - 4.5) <= 0.01 * 4.5
    # brute force over rings, written the other way round: nothing smaller qualifies
    for z3 in range(3 * 17, t.z3):
        for z2 in range(17, z3):
            z1 = z3 - 2 * z2
            if z1 < 17:
                continue
            for k in (3, 4):
                ok = ((z1 + z3) % k == 0 and math.sin(math.pi / k) > (z2 + 2) / (z1 + z2)
                      and abs(1 + z3 / z1 - 4.5) <= 0.01 * 4.5)
                assert not ok, (z1, z2, z3, k)


def test_json_names():
    sol = seed_solution()
    data = to_json(sol, {("1", "2"): 1.47})
    m = data["meshes"][0]
    for key in ("gears", "working_pressure_angle_deg", "centre_distance", "y", "delta_y", "contact_ratio",
                "contact_ratio_drawn", "radii", "tip_thickness"):
        assert key in m
    assert set(m["radii"]["1"]) >= {"pitch", "base", "tip", "root"}
    assert m["radii"]["2"]["tip"] == pytest.approx(28 + (1 + 3 / 17 - m["delta_y"]) * 4, rel=1e-12)
    assert "ratios" in data and data["meshes"][1]["contact_ratio_drawn"] is None


@settings(max_examples=80, derandomize=True, deadline=None)
@given(st.integers(5, 120), st.integers(5, 200), st.floats(-0.6, 1.2), st.floats(-0.6, 1.2),
       st.booleans())
def test_any_pair_is_exact_or_one_input_error(z1, z2, x1, x2, internal):
    """Random pairs: either an InputError, or finite figures meeting the course's identities."""
    if internal:
        z2 = z1 + 8 + z2 % 100
    try:
        p = pair(("1", "2"), (z1, z2), (x1, x2), internal, M, A20, 1.0, 0.25, (0.0, 0.0))
    except InputError as exc:
        assert "\n" not in str(exc)
        return
    S, Z = (x2 - x1, z2 - z1) if internal else (x1 + x2, z1 + z2)
    assert inv(p.alpha_w) == pytest.approx(inv(A20) + 2 * math.tan(A20) * S / Z, rel=1e-12, abs=1e-15)
    assert p.a_w * math.cos(p.alpha_w) == pytest.approx(p.a * math.cos(A20), rel=1e-13)
    if not internal:
        assert p.delta_y >= -1e-12  # Σx ≥ y always: the pair needs its tips shortened, never grown
    assert p.contact_ratio == pytest.approx(_course_eps(p), rel=1e-12)
    for v in (p.alpha_w, p.a_w, p.y, p.delta_y, p.contact_ratio, *(w.tip_thickness for w in p.wheels)):
        assert math.isfinite(v)


def test_drawn_involute_is_laid_off_as_unrolled_arcs():
    mg = meshing(seed_solution().pairs[0])
    O1, rb = mg.wheels[0].centre, mg.wheels[0].radii["base"]
    for T, q in mg.construction:
        assert abs(T - O1) == pytest.approx(rb, rel=1e-12)  # T on the base circle
        assert abs(((q - T) * np.conj(T - O1)).real) < 1e-9 * rb * rb  # on its tangent
    # consecutive laid-off lengths grow by the arcs between consecutive tangent points
    for (T1, q1), (T2, q2) in zip(mg.construction, mg.construction[1:], strict=False):
        arc = rb * abs(np.angle((T2 - O1) / (T1 - O1)))
        assert abs(q2 - T2) - abs(q1 - T1) == pytest.approx(arc, rel=1e-9)


@settings(max_examples=8, derandomize=True, deadline=None)
@given(st.integers(12, 70), st.integers(12, 90), st.floats(0.0, 0.6), st.floats(-0.3, 0.6))
def test_meshing_drawing_of_any_pair(z1, z2, x1, x2):
    """Any sound pair: the drawn profiles never cut into each other and ε reads right (with
    interference B1 lies beyond N1, off the drawn line of action, and there is no reading)."""
    try:
        p = pair(("1", "2"), (z1, z2), (x1, x2), False, M, A20, 1.0, 0.25, (0.0, 0.0))
        p = pair(("1", "2"), (z1, z2), (x1, x2), False, M, A20, 1.0, 0.25, (p.delta_y, p.delta_y))
    except InputError:
        return
    if not p.checks()["no_interference"]:
        return
    mg = meshing(p)
    polys = [shapely.Polygon([(z.real, z.imag) for z in dw.outline] + [(dw.centre.real, dw.centre.imag)]).buffer(0)
             for dw in mg.wheels]
    assert polys[0].intersection(polys[1]).area < 1e-2
    assert mg.contact_ratio_drawn == pytest.approx(p.contact_ratio, abs=3e-3)


# --------------------------------------------------------------------------- the ring's tip


def _planetary(ring_tip: str | None = None):
    import tomllib

    text = open(PLANETARY, encoding="utf-8").read()
    if ring_tip is not None:
        text = text.replace("internal = true", f'internal = true\nring_tip = "{ring_tip}"')
    return solve_gears(parse_gears(tomllib.loads(text), PLANETARY))


def test_ring_tip_rules_and_the_planets_limit_point():
    """The trimmed ring tip passes through the point where the planet's rack-cut involute
    begins (the rack's tip line on the line of action, found here by coordinates), GOST's
    first-order rule falls a hair short, the plain one 0.85 mm short; only the trimmed rule
    passes the interference check."""
    radii = {}
    for rule in ("trimmed", "gost", "plain"):
        p = _planetary(rule).pairs[1]
        planet, ring = p.wheels
        radii[rule] = ring.tip
        ok = p.checks()["no_interference"]
        assert ok == (rule == "trimmed"), rule
        # the pair at its pitch position: P at the origin, the planet's centre below, the ring's
        # centre below it; the rack tip line (h_a* − x) m inside the planet's pitch circle meets
        # the line of action, which runs through P at α_w to the common tangent
        O_ring = complex(0.0, -ring.working)
        u = -np.exp(1j * p.alpha_w)  # from P towards N1 (down the tangent of both base circles)
        L = (1.0 - planet.x) * p.m / math.sin(p.alpha) * u
        assert abs(L - complex(0.0, -planet.working)) == pytest.approx(
            math.hypot(planet.base, planet.limit), rel=1e-12)  # L is the limit circle's point
        gap = (abs(L - O_ring) - ring.tip) * 1e3  # mm: > 0 the ring's tip reaches past L
        if rule == "trimmed":
            assert abs(gap) < 1e-9
        elif rule == "gost":
            assert 0.0 < gap < 0.01
            # the printed rule: d_a2 = d2 − 2(h_a* − x2 − 7.55/z2) m, with 7.55 rounded
            assert ring.tip == pytest.approx(ring.pitch - (1.0 - ring.x - 7.55 / ring.z) * p.m, rel=1e-6)
        else:
            assert ring.tip == pytest.approx(ring.pitch - p.m, rel=1e-14)
            assert (planet.limit - p.rho_start) * 1e3 == pytest.approx(0.8546, abs=1e-4)
    assert radii["plain"] < radii["gost"] < radii["trimmed"]
    assert radii["trimmed"] * 1e3 == pytest.approx(68.22166, abs=1e-5)


def test_trimmed_ring_contact_ratio_read_off_the_drawing():
    p = _planetary().pairs[1]
    assert p.contact_ratio == pytest.approx(_course_eps(p), rel=1e-13)
    mg = meshing(p)
    assert mg.contact_ratio_drawn == pytest.approx(p.contact_ratio, abs=1e-3)
    assert p.contact_ratio == pytest.approx(1.79623, abs=1e-5)
    # the drawn B1 is on the ring's tip circle and at the planet's limit circle
    planet = mg.wheels[0]
    r_l = math.hypot(p.wheels[0].base, p.wheels[0].limit) * 1e3 * mg.k
    assert abs(mg.B1 - planet.centre) == pytest.approx(r_l, rel=2e-4)


def _tip_contacts(p):
    """Turn the drawn pair: each tip corner of the drawn ring, carried into the planet's frame,
    and where it comes nearest the drawn planet's outline. Returns (radii from O1 of the
    touching corners, paper mm; deepest penetration into the planet, mm; the scale)."""
    mg = meshing(p)
    planet, ring = mg.wheels
    z1, z2 = p.wheels[0].z, p.wheels[1].z
    outline = np.array(planet.outline)
    line = shapely.LineString(np.column_stack([outline.real, outline.imag]))
    body = shapely.Polygon(np.column_stack([outline.real, outline.imag]).tolist()
                           + [(planet.centre.real, planet.centre.imag)]).buffer(0)
    ro = np.array(ring.outline)
    on_tip = np.abs(np.abs(ro - ring.centre) - ring.radii["tip"]) < 1e-6
    # the ends of each tip land (the points on the tip circle next to a flank point)
    ends = on_tip & ~(np.roll(on_tip, 1) & np.roll(on_tip, -1))
    corners = ro[ends & (np.abs(ro - mg.B1) < 4 * math.pi * p.m * 1e3 * mg.k)]
    phis = np.linspace(-2.5, 2.5, 1501) * 2 * math.pi / z1
    O1, O2 = planet.centre, ring.centre
    # same sense for an internal pair: the ring turns by φ z1/z2 while the planet turns by φ
    q = O1 + ((corners[None, :] - O2) * np.exp(1j * phis[:, None] * z1 / z2) + O2 - O1) * np.exp(-1j * phis[:, None])
    pts = shapely.points(q.real, q.imag)
    d = shapely.distance(pts, line)
    inside = shapely.contains(body, pts)
    depth = float(np.max(np.where(inside, d, 0.0)))
    low = (d[1:-1] <= d[:-2]) & (d[1:-1] <= d[2:]) & (d[1:-1] < 0.05)  # nearest approaches that touch
    return [float(v) for v in np.abs(q[1:-1][low] - O1)], depth, mg.k


def test_ring_tip_meets_the_planet_only_on_its_involute():
    """A direct test by turning the drawn wheels: the ring's tip corners touch the planet's
    drawn flank only outside the planet's limit circle (where its rack-cut flank is an
    involute), and never enter it; with the plain tip they touch inside the limit circle."""
    for rule in ("trimmed", "plain"):
        p = _planetary(rule).pairs[1]
        touch, depth, k = _tip_contacts(p)
        planet = p.wheels[0]
        r_l = math.hypot(planet.base, planet.limit) * 1e3 * k
        assert touch, rule
        assert depth < 0.05
        if rule == "trimmed":
            assert min(touch) >= r_l - 0.05  # paper mm at 10:1: 5 µm on the gear
        else:
            # ρ = 1.85 mm instead of 2.70 mm from N1: 0.082 mm lower on the flank, 0.82 mm drawn
            assert min(touch) < r_l - 0.5


def test_ring_root_has_fillets():
    """The drawn ring meets its root circle through fillet arcs: along its outline the only
    sharp corners left are at the tips (on the tip circle); at the root the direction turns
    smoothly, and the spaces' outermost points lie on the root circle."""
    p = _planetary().pairs[1]
    ring = meshing(p).wheels[1]
    ro = np.array(ring.outline)
    seg = np.diff(ro)
    turn = np.abs(np.angle(seg[1:] / seg[:-1]))  # at the points ro[1:-1]
    r = np.abs(ro[1:-1] - ring.centre)
    sharp = turn > math.radians(20)
    assert np.all(np.abs(r[sharp] - ring.radii["tip"]) < 1e-6)
    assert np.max(np.abs(ro - ring.centre)) == pytest.approx(ring.radii["root"], rel=1e-9)
    # without the fillet the flank would meet the root circle at a corner of some 60°-90°
    near_root = r > ring.radii["root"] - 0.38 * p.m * 1e3 * meshing(p).k
    assert near_root.sum() >= 10 and np.max(turn[near_root]) < math.radians(20)


@pytest.mark.parametrize("edit, field", [
    (("internal = true", 'internal = true\nring_tip = "cut"'), "gears[2].ring_tip"),
    (("addendum = 1.0", "addendum = 1.0\nring_tip = 3"), "ring_tip"),
    (('z = 20\n', 'z = 20\nring_tip = "plain"\n'), "gears[0].ring_tip"),
])
def test_ring_tip_bad_input_names_the_key(edit, field):
    import tomllib

    text = open(PLANETARY, encoding="utf-8").read().replace(*edit, 1)
    with pytest.raises(InputError) as exc:
        parse_gears(tomllib.loads(text), "p.toml")
    from plans.errors import field_name

    assert f"p.toml: {field_name(field)}:" in str(exc.value) and "\n" not in str(exc.value)


@pytest.mark.parametrize("language", ["ru", "en"])
def test_meshing_panels_draw_nothing_outside_their_field(language):
    # An internal pair's N2 lies far beyond the field: an arrow at the edge names it instead.
    # At the least field and at one as large as an A1 sheet holds, every line, circle and
    # polygon but the field's own frame lies inside that frame.
    from drawings.gears_meshing import meshing_panel

    pairs = solve_gears(load_gears(SEED)).drawn_pairs() + solve_gears(load_gears(PLANETARY)).drawn_pairs()
    for p in pairs:
        for field in (None, (380.0, 250.0)):
            panel = meshing_panel(meshing(p, 3, field), language)
            frame = next(q for q in panel.prims if q.eid == "field")
            fx, fy = zip(*frame.pts, strict=True)
            for prim in panel.prims:
                if prim.pts and prim.label is None and prim.eid != "field":
                    xs, ys = zip(*prim.pts, strict=True)
                    assert min(fx) - 1e-6 <= min(xs) and max(xs) <= max(fx) + 1e-6, prim.eid
                    assert min(fy) - 1e-6 <= min(ys) and max(ys) <= max(fy) + 1e-6, prim.eid
            if field is not None:  # the field asked for, as wide and as high as asked
                assert max(fx) - min(fx) == pytest.approx(2 * field[0]) and max(fy) - min(fy) == pytest.approx(2 * field[1])
            else:
                least = panel
    labels = [pr.label.plain for pr in least.prims if pr.label is not None]
    assert any(t.startswith("N2:") or t.startswith("N_2:") for t in labels), labels
