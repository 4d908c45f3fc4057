"""Zhukovsky's lever: geometry of the turned plan and its moment equation."""

from __future__ import annotations

import numpy as np
import pytest

from plans.forces.lever import force_rows, lever_plan, table_lines, zhukovsky_lever
from plans.forces.loads import parse_loads
from plans.forces.polygons import analyse_forces
from plans.kinematics.exact import solve
from plans.kinematics.placing import load_scene, scene_from_dict

from .conftest import SAMPLES

PHIS = np.arange(12) * 30.0 + 11.0


def _sample(stem, **loads_over):
    path = next(p for p in SAMPLES if p.stem == stem)
    raw = dict(load_scene(path).raw)
    raw["loads"] = dict(raw.get("loads", {}), **loads_over)
    scene = scene_from_dict(raw, str(path))
    kin = solve(scene, PHIS, order=2)
    fa = analyse_forces(scene, kin, parse_loads(scene))
    return scene, kin, fa, zhukovsky_lever(fa)


@pytest.mark.parametrize("turn", ["ccw", "cw"])
def test_images_are_the_velocities_turned_90_degrees(turn):
    scene, kin, fa, lv = _sample("shaper", lever_turn=turn)
    sign = 1 if turn == "ccw" else -1
    for it in lv.forces:
        if it.point.endswith("*") or it.label.endswith("'"):
            continue
        f = next(f for f in fa.applied.forces if f.label == it.label)
        v = kin.point_on(f.link, f.local)[1]
        np.testing.assert_allclose(it.w, sign * 1j * lv.scale * v, atol=1e-12 * lv.scale * np.max(np.abs(v)))
        # |image| / μv is the speed; turned by +-90°: perpendicular to the velocity
        assert np.all(np.abs((np.conj(it.w) * v).real) <= 1e-9 * np.abs(it.w) * np.abs(v) + 1e-300)


def test_lever_sense_does_not_change_the_balancing_force():
    a = _sample("six_bar", lever_turn="ccw")[3]
    b = _sample("six_bar", lever_turn="cw")[3]
    np.testing.assert_allclose(a.signed(a.by_lever), b.signed(b.by_lever),
                               atol=1e-9 * np.max(np.abs(a.by_lever)))
    # turning the other way mirrors every moment
    for fa_, fb_ in zip(a.forces, b.forces, strict=True):
        np.testing.assert_allclose(fa_.moment, -fb_.moment, atol=1e-9 * np.max(np.abs(fa_.moment)) + 1e-12)


def test_moment_of_each_force_about_the_pole_is_minus_mu_times_its_power():
    scene, kin, fa, lv = _sample("v_engine")
    for it in lv.forces:
        if it.label.endswith("'"):
            continue
        f = next(f for f in fa.applied.forces if f.label == it.label)
        v = kin.point_on(f.link, f.local)[1]
        power = (np.conj(f.F) * v).real
        np.testing.assert_allclose(it.moment, -lv.turn * lv.scale * power,
                                   atol=1e-9 * lv.scale * (np.max(np.abs(power)) + 1))


def test_an_inertia_moment_becomes_a_couple_at_the_joint_images():
    scene, kin, fa, lv = _sample("four_bar")
    for m in fa.applied.moments:
        pair = [it for it in lv.forces if it.label in (m.label + "'", m.label + "''")]
        assert len(pair) == 2
        np.testing.assert_allclose(pair[0].F, -pair[1].F)
        link = scene.links[m.link]
        l = link.length
        np.testing.assert_allclose(np.abs(pair[0].F), np.abs(m.M) / l, rtol=1e-12, atol=1e-12)
        # the pair's lever moment is the couple's power, M·ω, times −μv
        np.testing.assert_allclose(pair[0].moment + pair[1].moment, -lv.turn * lv.scale * m.M * kin.omega(m.link),
                                   atol=1e-9 * lv.scale * np.max(np.abs(m.M * kin.omega(m.link))) + 1e-12)
        assert {pair[0].point, pair[1].point} == {p.lower() for p in link.axis}


def test_balancing_moment_on_the_lever():
    scene, kin, fa, lv = _sample("four_bar")
    assert fa.crank.kind == "moment"
    np.testing.assert_allclose(lv.by_lever, fa.crank.M_bal, atol=1e-9 * np.max(np.abs(fa.crank.M_bal)))
    np.testing.assert_allclose(lv.by_power, fa.crank.M_bal, atol=1e-9 * np.max(np.abs(fa.crank.M_bal)))


def test_lever_plan_and_readings():
    scene, kin, fa, lv = _sample("v_engine")
    plan = lever_plan(lv, 0)
    assert plan.kind == "lever" and plan.has("p") and plan.has("a") and plan.protocol()
    rows = force_rows(lv, 0)
    names = [r.quantity for r in rows]
    assert "F_bal by kinetostatics" in names and "F_bal by Zhukovsky's lever" in names
    delta = rows[-1]
    assert delta.unit == "%" and abs(delta.exact) < 1e-9 and delta.drawing is not None
    assert abs(delta.drawing) < 5  # ruler readings differ by a few tenths of a percent, not 6 %
    text = "\n".join(table_lines(fa, lv, 0))
    assert "F_bal" in text and "nan" not in text.lower()
