"""``[driver] phi_start = "extreme"``: the positions from the output's exact extreme position.

Oracles: the extremes written here again in mpmath at 50 digits (the slider-crank's
x_B(θ) = r cos θ + √(l² − (e − r sin θ)²) made stationary by findroot; the crank-rocker's
crank and coupler in line; the shaper's crank ⟂ its slotted lever), the closed form and
the bisection of the output's velocity against each other, and the positions alone (the
output's coordinate a hair either side is on one side of its value at the extreme).  The
hidden-dust test: at the extreme start every plan's reading that vanishes there is below
1e-9 of its plan, and none lies between dust and a drawn length.
"""

from __future__ import annotations

import json
import math
import re

import mpmath
import numpy as np
import pytest

import plans
from plans.accuracy.reference import slider_crank_scene
from plans.errors import InputError
from plans.io import read_toml
from plans.kinematics import extreme
from plans.kinematics.exact import solve
from plans.kinematics.placing import scene_from_dict

from .conftest import ROOT


def _sample(stem: str, **driver) -> dict:
    data = read_toml(ROOT / "samples" / f"{stem}.toml")
    d = data["driver"]
    for key in ("phi_deg", "phi0_deg"):
        d.pop(key, None)
    d.setdefault("positions", 12)
    d.update(driver)
    return data


def _scene(stem: str, **driver):
    return scene_from_dict(_sample(stem, **driver), f"{stem}.toml")


def _gap(a: float, b: float) -> float:
    d = abs(a - b) % 360.0
    return min(d, 360.0 - d)


# --------------------------------------------------------------------------- exact extremes


def _slider_crank_extremes(r: float, l: float, e: float) -> list[float]:
    """θ (deg) where dx_B/dθ = 0, by mpmath's findroot at 50 digits (θ = φ here: φ_ref 0, ccw)."""
    with mpmath.workdps(50):
        R, L, E = mpmath.mpf(r), mpmath.mpf(l), mpmath.mpf(e)

        def dx(t):
            s = E - R * mpmath.sin(t)
            return -R * mpmath.sin(t) + s * R * mpmath.cos(t) / mpmath.sqrt(L * L - s * s)

        # starts: crank along ± the rod's direction at the dead centres (within a few degrees)
        guesses = [mpmath.asin(E / (L + R)), mpmath.pi + mpmath.asin(E / (L - R))]
        return [float(mpmath.degrees(mpmath.findroot(dx, g)) % 360) for g in guesses]


@pytest.mark.parametrize("r, l, e", [(0.05, 0.18, 0.0), (0.06, 0.2, 0.025), (0.04, 0.15, -0.03)])
def test_slider_crank_extremes_match_mpmath(r, l, e):
    scene = slider_crank_scene(r, l, e)
    want = sorted(_slider_crank_extremes(r, l, e))
    for closed in (True, False):
        st = extreme.strokes(scene, closed=closed)
        got = sorted([st.working_deg, st.idle_deg])
        assert max(_gap(a, b) for a, b in zip(got, want, strict=True)) < 1e-11, (closed, got, want)
    assert extreme.strokes(scene).closed_form  # a slider-crank has its closed form
    # K from the same extremes: the slower stroke is the working one
    st = extreme.strokes(scene)
    assert st.K >= 1.0 and st.working_span >= 180.0 - 1e-9


def test_crank_rocker_extremes_crank_and_coupler_in_line():
    """four_bar: the rocker turns back where A lies on OB (|OB| = l_AB ± r), found in mpmath."""
    scene = _scene("four_bar")
    crank, coupler = scene.links[1], scene.links[2]
    O = scene.frame_points[crank.axis[0]]
    r = abs(crank.points[crank.axis[1]] - crank.points[crank.axis[0]])
    lab = abs(coupler.points["B"] - coupler.points["A"])
    out = extreme.output_of(scene)
    assert out.kind == "rocker"
    rocker = scene.links[out.link]
    D = scene.frame_points[out.joint.point]
    c = abs(rocker.points["B"] - rocker.points[out.joint.point])
    st = extreme.strokes(scene)
    got = [st.working_deg, st.idle_deg]
    local = math.degrees(math.atan2((crank.points[crank.axis[1]] - crank.points[crank.axis[0]]).imag,
                                    (crank.points[crank.axis[1]] - crank.points[crank.axis[0]]).real))
    hits = []
    with mpmath.workdps(50):
        for L, s in ((lab + r, 0.0), (lab - r, 180.0)):
            # B at |OB| = L on the rocker's circle: the angle ψ of OB with |O + L e^{iψ} − D| = c
            def f(psi, L=L):
                return (O.real + L * mpmath.cos(psi) - D.real) ** 2 + (O.imag + L * mpmath.sin(psi) - D.imag) ** 2 \
                    - c * c
            for g in np.radians(np.arange(0, 360, 5)):
                try:
                    psi = mpmath.findroot(f, g)
                except (ValueError, ZeroDivisionError):
                    continue
                theta = float(mpmath.degrees(psi)) + s  # the crank along OB, or against it (folded)
                hits.append((scene.driver.sense * (theta - local - math.degrees(scene.driver.phi_ref))) % 360)
    for x in got:
        assert min(_gap(h, x) for h in hits) < 1e-10, (x, sorted(set(round(h, 6) for h in hits)))
    # both extremes are among the mpmath roots
    bisected = extreme.strokes(scene, closed=False)
    assert _gap(bisected.working_deg, st.working_deg) < 1e-11 and _gap(bisected.idle_deg, st.idle_deg) < 1e-11


def test_shaper_extremes_crank_perpendicular_to_the_slotted_lever():
    """The ram turns back with the lever: OA ⟂ CA, cos ∠(OC, OA) = r/|OC| (mpmath)."""
    scene = _scene("shaper")
    st = extreme.strokes(scene)
    O, C = scene.frame_points["O"], scene.frame_points["C"]
    r = abs(scene.links[1].points["A"] - scene.links[1].points["O"])
    with mpmath.workdps(50):
        base = mpmath.atan2(C.imag - O.imag, C.real - O.real)
        half = mpmath.acos(r / mpmath.mpf(abs(C - O)))
        want = sorted(float((scene.driver.sense * (mpmath.degrees(base + s * half) - 90)) % 360) for s in (1, -1))
    got = sorted([st.working_deg, st.idle_deg])
    assert max(_gap(a, b) for a, b in zip(got, want, strict=True)) < 1e-11
    # the working stroke is the slower one: K = (180 + θ)/(180 − θ) with θ from the same angles
    theta = st.working_span - 180.0
    assert st.K == pytest.approx((180 + theta) / (180 - theta), rel=1e-12) and st.K > 1


@pytest.mark.parametrize("stem", ["offset_slider_crank", "four_bar", "shaper", "whitworth", "six_bar", "six_link"])
def test_the_extreme_is_one_of_positions_alone(stem):
    """Positions only: a hair either side, the output's coordinate is on the same side of its value."""
    scene = _scene(stem)
    st = extreme.strokes(scene)
    out = st.output
    for phi in (st.working_deg, st.idle_deg):
        kin = solve(scene, [phi - 1e-4, phi, phi + 1e-4], order=0)
        c = extreme._coordinate(out, kin)[0]
        assert (c[0] - c[1]) * (c[2] - c[1]) > 0, (stem, phi, c)
    # the coordinate grows on the working stroke exactly when working_up says so
    mid = (st.working_deg + st.working_span / 2) % 360
    kin = solve(scene, [st.working_deg, mid], order=0)
    c = extreme._coordinate(out, kin)[0]
    assert (c[1] > c[0]) == st.working_up


def test_central_slider_crank_ties_to_the_outer_dead_centre():
    """K = 1: the working stroke begins where the slider is farthest from the crank's pivot."""
    scene = slider_crank_scene(0.05, 0.18, 0.0)
    st = extreme.strokes(scene)
    assert st.K == pytest.approx(1.0, abs=1e-12)
    kin = solve(scene, [st.working_deg, st.idle_deg], order=0)
    B = kin.point("B")[0]
    assert abs(B[0]) > abs(B[1])


# --------------------------------------------------------------------------- phi_start


@pytest.mark.parametrize("stem", ["offset_slider_crank", "four_bar", "shaper", "whitworth"])
def test_no_hidden_dust_at_the_extreme_start(stem):
    """Every reading that vanishes at the extreme is below 1e-9 of its plan, and no reading
    lies between that and 1e-6 of its plan (dust that prints as a length)."""
    sol = plans.solve(_scene(stem, phi_start="extreme"))
    pp = sol.plans[0]
    out = sol.scene.driver.strokes.output
    vanishing = {f"v_{out.point}"} if out.kind == "slider" else {f"omega_{out.link}", f"v_{out.point}"}
    seen = set()
    for r in pp.readings:
        rel = abs(r.value) / (r.ref or abs(r.exact) or 1.0)
        assert not 1e-9 <= rel < 1e-6, (stem, r.quantity, r.value, r.ref)
        if r.quantity in vanishing:
            seen.add(r.quantity)
            assert rel < 1e-9 and abs(r.exact) < 1e-9 * r.ref, (stem, r.quantity, r.value)
    assert seen == vanishing
    for plan in (pp.velocity, pp.acceleration):
        size = max(s.length_mm for s in plan.segments)
        assert all(s.length_mm == 0 or s.length_mm > 1e-6 * size for s in plan.segments), stem
    # nor in the protocol's numbers (ω3 = 3.8e-16 in the Coriolis step, say)
    from plans.results import table

    text = table(sol, protocol=True).split("\nphi = ")[1]  # the first position
    assert not re.findall(r"\d(?:\.\d+)?e-(?:1[0-9]|[2-9]\d)", text), stem


def test_a_start_by_hand_leaves_dust():
    """The same check fails for the angle a user would compute by hand (to 0.001°): the test can fail."""
    st = extreme.strokes(_scene("offset_slider_crank"))
    sol = plans.solve(_scene("offset_slider_crank", phi0_deg=round(st.working_deg, 3)))
    vB = next(r for r in sol.plans[0].readings if r.quantity == "v_B")
    assert 1e-9 <= abs(vB.value) / vB.ref < 1e-3


def test_phi_start_positions_json_and_protocol():
    scene = _scene("shaper", phi_start="extreme")
    st = scene.driver.strokes
    assert scene.driver.phis_deg[0] == st.working_deg
    assert all(_gap(p, st.working_deg + 30 * k) < 1e-9 for k, p in enumerate(scene.driver.phis_deg))
    idle = _scene("shaper", phi_start="extreme_idle")
    assert idle.driver.phis_deg[0] == st.idle_deg
    sol = plans.solve(scene)
    from plans.results import table, to_json

    js = json.loads(json.dumps(to_json(sol, steps=False)))
    assert js["phi_start"]["start"] == "extreme"
    assert js["phi_start"]["phi_deg"] == js["positions"][0]["phi_deg"] == st.working_deg
    assert js["phi_start"]["output"] == {"kind": "slider", "link": 5, "point": "E"}
    assert js["phi_start"]["K"] == pytest.approx(st.K)
    en, ru = table(sol, lang="en"), table(sol, lang="ru")
    assert f"phi = {st.working_deg:.6f} deg" in en and "working stroke begins" in en
    assert f"φ = {st.working_deg:.6f}°".replace(".", ",") in ru and "рабочий ход" in ru
    assert "phi_start" not in json.dumps(to_json(plans.solve(_scene("shaper")), steps=False))


def test_extreme_of_names_the_output():
    scene = _scene("shaper", phi_start="extreme", extreme_of=3)
    assert scene.driver.strokes.output.kind == "rocker" and scene.driver.strokes.output.link == 3
    # the rocker and the ram turn back together in a shaper
    ram = _scene("shaper", phi_start="extreme").driver.strokes
    assert _gap(scene.driver.strokes.working_deg, ram.working_deg) < 1e-9 or \
        _gap(scene.driver.strokes.working_deg, ram.idle_deg) < 1e-9
    assert _scene("shaper", extreme_of="E", phi_start="extreme").driver.strokes.output.link == 5


@pytest.mark.parametrize("driver, field, words", [
    ({"phi_start": "extreme", "phi0_deg": 10}, "driver.phi0_deg", "drop phi0_deg"),
    ({"phi_start": "extremes"}, "driver.phi_start", "extreme"),
    ({"phi_start": "extreme", "extreme_of": 1}, "driver.extreme_of", "not the crank"),
    ({"phi_start": "extreme", "extreme_of": 3}, "driver.phi_start", "turns all the way round"),
])
def test_phi_start_bad_input(driver, field, words):
    with pytest.raises(InputError) as exc:
        _scene("whitworth", **driver)
    assert exc.value.field == field and words in str(exc.value)


def test_the_scene_room_reads_the_request_and_the_kinematics_places_it():
    """plans.scene reads phi_start as a request (no angle yet, and the exact analysis will not
    read the positions of such a scene); placed by plans.kinematics.placing, or by plans.solve
    given the unplaced scene, the positions are the extreme's, the same either way."""
    from plans.kinematics.exact import solve
    from plans.scene import model
    from plans.scene.positions import FromExtreme

    raw = _sample("shaper", phi_start="extreme_idle")
    unplaced = model.scene_from_dict(raw, "shaper.toml")
    assert unplaced.driver.placing == FromExtreme("extreme_idle", 12) and unplaced.driver.phis_deg == ()
    with pytest.raises(ValueError, match="not placed"):
        solve(unplaced)
    placed = scene_from_dict(raw, "shaper.toml")
    st = extreme.strokes(placed)
    assert placed.driver.placing is None and placed.driver.phis_deg[0] == st.idle_deg != st.working_deg
    assert plans.solve(unplaced).scene.driver.phis_deg == placed.driver.phis_deg
