"""The draftsman's construction against the exact analysis, degenerate geometry,
and 'compute only what the scene asks for'."""

from __future__ import annotations

import math

import numpy as np
import pytest

from plans.errors import ConstructionError, Locked, NotAssemblable
from plans.io import dumps
from plans.kinematics.construction import build, build_all, nice_scale
from plans.kinematics.exact import solve
from plans.kinematics.placing import load_scene, scene_from_dict
from plans.kinematics.scales import LONGEST_MM, is_round, round_scale
from plans.results import solve_scene, to_json

from .conftest import ROOT, four_bar_scene, slider_crank_scene


def _worst(kin):
    worst = 0.0
    for pp in build_all(kin):
        for r in pp.readings:
            assert math.isfinite(r.value) and math.isfinite(r.exact), r
            worst = max(worst, r.relative)
    return worst


def test_every_plan_reading_equals_the_exact_value(sample_path):
    kin = solve(load_scene(sample_path))
    assert _worst(kin) < 1e-9


def test_plan_points_are_exact_velocities_at_scale(sample_path):
    """Every labelled image of a named point is μ·v (μ·a) of that point."""
    scene = load_scene(sample_path)
    kin = solve(scene)
    for k, pp in enumerate(build_all(kin)):
        for plan, idx in ((pp.velocity, 1), (pp.acceleration, 2)):
            if plan is None:  # a scene that asks for velocity plans only
                continue
            for name in kin.point_names():
                lab = name.lower()
                if not plan.has(lab) or name in scene.frame_points:
                    continue
                exact = kin.point(name)[idx][k] * plan.scale
                x, y = plan.xy(lab)
                assert abs(complex(x, y) - exact) <= 1e-9 * max(plan.extent, 1e-12), (name, plan.kind)


def test_dead_position_of_the_coursework():
    kin = solve(load_scene("samples/v_engine.toml"))
    pp = build(kin, 1)  # φ = 0
    v = {p.name: p for p in pp.velocity.points}
    assert v["b"].coincides_with == "p_v"  # V_B = 0: b on the pole
    assert v["c"].coincides_with == "a"  # ω4 = 0: c on a
    assert pp.velocity.segment("v_BA").length_mm == pytest.approx(pp.velocity.segment("v_A").length_mm)
    assert any("coincides" in s.text for s in pp.velocity.steps)


def test_near_dead_centre_is_smooth():
    """1e-9 rad from the dead centre the plan is as good as anywhere."""
    d = slider_crank_scene(50, 180, 0, phi_deg=[0.0, math.degrees(1e-9), -math.degrees(1e-9), 180.0])
    kin = solve(scene_from_dict(d))
    assert _worst(kin) < 1e-9
    rB, vB, _ = kin.point("B")
    assert np.all(np.abs(vB) < 1e-6)


def test_lambda_close_to_one():
    d = slider_crank_scene(99, 100, 0, phi_deg=list(np.arange(0, 360, 15) + 0.5))
    assert _worst(solve(scene_from_dict(d))) < 1e-9


def test_not_assemblable_names_group_point_angle():
    d = slider_crank_scene(50, 100, 140, phi_deg=[90, 270])  # the rod cannot reach the guide at 270°
    with pytest.raises(NotAssemblable, match=r"group RRP 2-3, point B, phi = 270 deg"):
        solve(scene_from_dict(d))


def test_four_bar_beyond_its_limit_angle():
    # non-Grashof: |AD| may not exceed b + c = 250; the limit is at cos φ = -0.3125
    d = four_bar_scene(100, 150, 100, 200, phi_deg=[0, 120])
    with pytest.raises(NotAssemblable, match=r"RRR 2-3.*phi = 120"):
        solve(scene_from_dict(d))


def test_locking_position_is_a_clear_error():
    """λ = 1 at φ = 90°: the rod stands ⟂ to the guide over O; the two velocity lines
    (⟂ AB and ∥ guide) are parallel and apart: velocities are unbounded."""
    d = slider_crank_scene(100, 100, 0, phi_deg=[90.0])
    with pytest.raises(ConstructionError, match=r"point B, phi = 90 deg"):
        solve(scene_from_dict(d))


def test_nearly_parallel_lines_take_the_exact_point():
    # 1e-7 rad before the lock the two lines meet at 1e-7 rad: no pencil resolves that
    d = slider_crank_scene(100, 100.0, 0, phi_deg=[90.0 - math.degrees(1e-7)])
    kin = solve(scene_from_dict(d))
    pp = build(kin, 0)
    assert pp.velocity.degenerate and "exact point" in pp.velocity.degenerate[0]
    for r in pp.readings:
        assert math.isfinite(r.value)


def test_locked_error_type():
    d = slider_crank_scene(100, 100, 0, phi_deg=[90.0])
    with pytest.raises((Locked, NotAssemblable)):
        solve(scene_from_dict(d))


def test_velocity_only_scene_computes_no_acceleration():
    d = slider_crank_scene(outputs=["velocity_plan"])
    sol = solve_scene(scene_from_dict(d))
    assert sol.kinematics.order == 1
    assert all(m.eps is None and m.a0 is None for m in sol.kinematics.motion.values()
               if m is not sol.kinematics.motion[4])
    assert sol.plans[0].acceleration is None
    data = to_json(sol)
    assert "a" not in data["positions"][0]["points"]["B"]
    assert "acceleration" not in data["positions"][0]["plans"]


def test_positions_only_scene_builds_no_plan(monkeypatch):
    import plans.kinematics.construction as construction

    def boom(*a, **k):
        raise AssertionError("a plan was built for a positions-only scene")

    monkeypatch.setattr(construction, "build", boom)
    monkeypatch.setattr(construction, "build_all", boom)  # what plans.solve builds the plans with
    sol = solve_scene(scene_from_dict(slider_crank_scene(outputs=["positions"])))
    assert sol.kinematics.order == 0 and sol.plans == ()
    assert "v" not in to_json(sol)["positions"][0]["points"]["B"]


def test_coriolis_only_where_a_slider_moves_on_a_rotating_guide():
    def coriolis(path):
        kin = solve(load_scene(path))
        return [s for pp in build_all(kin) for s in pp.acceleration.segments if s.kind == "coriolis"]

    assert coriolis("samples/v_engine.toml") == []
    assert coriolis("samples/four_bar.toml") == []
    cor = coriolis("samples/shaper.toml")
    assert cor and all(s.label.startswith("a^k_") for s in cor)
    assert len(coriolis("samples/six_bar.toml")) >= 24  # both groups, 12 positions


def test_coriolis_magnitude_is_two_omega_v_rel():
    """Independent of both codes: 2·ω3·|v_A2 − v_A3| from the exact velocities."""
    scene = load_scene("samples/shaper.toml")
    kin = solve(scene)
    for k, pp in enumerate(build_all(kin)):
        seg = next(s for s in pp.acceleration.segments if s.kind == "coriolis")
        A = kin.point("A")[0][k]
        vA2 = kin.point("A")[1][k]
        m3 = kin.motion[3]
        vA3 = m3.v0[k] + 1j * m3.omega[k] * (A - m3.r0[k])
        assert seg.value == pytest.approx(2 * abs(m3.omega[k]) * abs(vA2 - vA3), rel=1e-9, abs=1e-12)


def test_nice_scale():
    assert 1 / nice_scale(12.46) == pytest.approx(0.2)
    for x in (1e-7, 0.37, 12.46, 4436.9, 3.3e6):
        mm = x * nice_scale(x)
        assert 50 <= mm <= 100 + 1e-9
        assert is_round(nice_scale(x)) and is_round(1 / nice_scale(x))


def test_round_scales_both_ways():
    ok = [1, 2, 2.5, 4, 5, 0.4, 0.25, 0.5, 0.2, 25, 400, 0.0025]
    bad = [1.2, 1.5, 3, 6, 8, 83.33, 0.01429, 6.667]
    assert all(is_round(x) and is_round(1 / x) for x in ok)
    assert not any(is_round(x) for x in bad)
    assert round_scale(0.0) == 1.0 and round_scale(float("nan")) == 1.0


@pytest.mark.parametrize("name", ["six_bar", "shaper", "four_bar", "slider_crank"])
def test_every_default_plan_scale_round_and_every_plan_within_its_length(name):
    kin = solve(load_scene(ROOT / "samples" / f"{name}.toml"))
    for pp in build_all(kin):
        for plan in (pp.velocity, pp.acceleration):
            if plan is not None:
                assert is_round(plan.scale), (plan.kind, pp.phi_deg, plan.scale)
                assert plan.extent <= LONGEST_MM + 1e-6, (plan.kind, pp.phi_deg, plan.extent)


def test_json_is_deterministic_and_finite(sample_path):
    a = dumps(to_json(solve_scene(load_scene(sample_path))))
    b = dumps(to_json(solve_scene(load_scene(sample_path))))
    assert a == b
    assert "NaN" not in a and "Infinity" not in a


def test_json_contract():
    data = to_json(solve_scene(load_scene("samples/v_engine.toml")))
    p0 = data["positions"][0]
    assert p0["phi_deg"] == 45.0
    assert set(p0["points"]["B"]) == {"r", "v", "a"} and len(p0["points"]["B"]["r"]) == 2
    assert set(p0["links"]["2"]) >= {"omega", "eps"}
    vel = p0["plans"]["velocity"]
    assert vel["scale"] > 0 and "b" in vel["points"] and vel["points"]["p_v"] == [0.0, 0.0]
    assert "acceleration" in p0["plans"]
    assert data["structure"]["W"] == 1
    assert [g["kind"] for g in data["structure"]["groups"]] == ["RRP", "RRP"]


def test_known_vector_given_length_keeps_the_course_habit(tmp_path):
    """[scales] velocity = { known_mm = 100 }: p_v a is drawn 100 mm (pa = 100 mm), and πa 80 mm."""
    src = (ROOT / "samples" / "slider_crank.toml").read_text(encoding="utf-8")
    p = tmp_path / "k.toml"
    p.write_text(src + "\n[scales]\nvelocity = { known_mm = 100 }\nacceleration = { known_mm = 80 }\n",
                 encoding="utf-8")
    kin = solve(load_scene(p))
    for pp in build_all(kin):
        assert pp.velocity.segment("v_A").length_mm == pytest.approx(100.0, rel=1e-9)
        assert pp.acceleration.segment("a_A").length_mm == pytest.approx(80.0, rel=1e-9)


@pytest.mark.parametrize("name", ["six_bar", "shaper", "v_engine"])
def test_plans_refitted_from_the_arrays_are_those_refitted_from_the_plan_objects(name):
    """build_all looks at the plan objects only where the arrays say a plan may run long:
    the same plans as refitting every position from its plan objects."""
    from plans.kinematics import construction
    from plans.kinematics.scales import refit

    kin = solve(load_scene(ROOT / "samples" / f"{name}.toml"), np.linspace(0.0, 360.0, 72, endpoint=False))
    mv, ma = construction.default_scales(kin)
    together = construction._Together(kin, slice(None), mv, ma)
    every = [together.position(k) for k in range(kin.n)]
    flagged = set(together.may_run_past(LONGEST_MM))
    for k, pp in enumerate(every):
        if any(p is not None and p.extent > LONGEST_MM for p in (pp.velocity, pp.acceleration)):
            assert k in flagged
    a, b = build_all(kin), refit(kin, every, build)
    for pa, pb in zip(a, b, strict=True):
        for x, y in ((pa.velocity, pb.velocity), (pa.acceleration, pb.acceleration)):
            assert (x is None) == (y is None)
            if x is not None:
                assert x.scale == y.scale and x.points == y.points
