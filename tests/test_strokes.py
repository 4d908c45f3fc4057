"""``stroke = "working"`` / ``"idle"`` on forces and moments, and the warning for a resisting
load on the fast stroke.

Oracles: which positions are on the working stroke is found here again from the exact
velocities alone (the output's velocity sampled over a turn: the sign it keeps for the
longer crank angle is the working direction); the power balance (the balancing load's
power changes by minus the load's own power, read off the exact velocities) and the
Zhukovsky lever (the same balancing load) at positions on both strokes.
"""

from __future__ import annotations

import numpy as np
import pytest

import plans
from plans.errors import InputError
from plans.io import read_toml
from plans.kinematics.exact import solve
from plans.kinematics.placing import scene_from_dict

from .conftest import ROOT

PHIS = tuple(float(x) for x in np.arange(24) * 15.0 + 3.0)  # both strokes, off the extremes


def _scene(stem: str, force: dict | None = None, moment: dict | None = None, drop_forces: bool = False):
    data = read_toml(ROOT / "samples" / f"{stem}.toml")
    d = data["driver"]
    d.pop("positions", None)
    d.pop("phi0_deg", None)
    d["phi_deg"] = list(PHIS)
    loads = data.setdefault("loads", {})
    if drop_forces:
        loads.pop("force", None)
        loads.pop("moment", None)
    if force is not None:
        loads["force"] = [force]
    if moment is not None:
        loads["moment"] = [moment]
    return scene_from_dict(data, f"{stem}.toml")


def _forces(scene):
    """The force analysis of a scene (what reads ``[loads]``)."""
    return plans.solve(scene).forces


def _working_direction(scene, link: int, point: str) -> tuple[complex, np.ndarray]:
    """The guide's unit vector signed toward the working motion, and where each position's
    velocity points that way: from a dense sample of exact velocities, nothing else."""
    grid = np.arange(3600) * 0.1
    v = solve(scene, grid, order=1).point(point, link)[1].real
    sign = 1.0 if np.count_nonzero(v > 0) > np.count_nonzero(v < 0) else -1.0
    at = solve(scene, PHIS, order=1).point(point, link)[1].real
    return sign, at * sign > 0


def _balancing_power(sol) -> np.ndarray:
    fa, lv = sol.forces
    c = fa.crank
    np.testing.assert_allclose(lv.signed(lv.by_lever), fa.balancing, rtol=0,
                               atol=1e-9 * float(np.max(np.abs(fa.balancing))))  # the lever agrees
    if fa.loads.balancing.kind == "moment":
        return c.M_bal * sol.kinematics.omega(c.link)
    return fa.balancing * np.abs(sol.kinematics.point(c.point, c.link)[1])


@pytest.mark.parametrize("stem", ["shaper", "whitworth"])
@pytest.mark.parametrize("stroke", ["working", "idle"])
def test_a_cutting_force_on_one_stroke_balances_its_power(stem, stroke):
    F = 1500.0
    base = _scene(stem, drop_forces=True)
    scene = _scene(stem, force={"name": "F_c", "link": 5, "point": "E", "resisting": F, "along": 0,
                                "stroke": stroke})
    sign, working = _working_direction(scene, 5, "E")
    on = working if stroke == "working" else ~working
    assert 0 < np.count_nonzero(on) < len(PHIS)
    sol, sol0 = plans.solve(scene), plans.solve(base)
    vE = sol.kinematics.point("E", 5)[1].real
    # the force's own power: −F|v| where it acts, nothing elsewhere
    p_force = np.where(on, -F * np.abs(vE), 0.0)
    dP = _balancing_power(sol) - _balancing_power(sol0)
    np.testing.assert_allclose(dP, -p_force, rtol=0, atol=1e-9 * F * float(np.max(np.abs(vE))))
    # the working stroke is the slow one: more of the equally spaced positions lie on it
    if stroke == "working":
        assert np.count_nonzero(on) > len(PHIS) / 2


def test_a_moment_limited_to_the_working_stroke():
    M = 40.0
    scene = _scene("four_bar", moment={"name": "M_c", "link": 3, "resisting": M, "stroke": "working"})
    base = _scene("four_bar", moment={"name": "M_c", "link": 3, "value": 0.0})
    # the rocker is link 3: its working swing from the exact ω3 alone
    grid = np.arange(3600) * 0.1
    w = solve(scene, grid, order=1).omega(3)
    sign = 1.0 if np.count_nonzero(w > 0) > np.count_nonzero(w < 0) else -1.0
    w3 = solve(scene, PHIS, order=1).omega(3)
    on = w3 * sign > 0
    sol, sol0 = plans.solve(scene), plans.solve(base)
    p_moment = np.where(on, -M * np.abs(w3), 0.0)
    dP = _balancing_power(sol) - _balancing_power(sol0)
    np.testing.assert_allclose(dP, -p_moment, rtol=0, atol=1e-9 * M * float(np.max(np.abs(w3))))
    assert 0 < np.count_nonzero(on) < len(PHIS)


def test_a_fixed_moment_limited_to_the_idle_stroke():
    scene = _scene("four_bar", moment={"name": "M_x", "link": 3, "value": 25.0, "stroke": "idle"})
    fa = _forces(scene)[0]
    m = next(x for x in fa.applied.moments if x.label == "M_x").M
    grid = np.arange(3600) * 0.1
    w = solve(scene, grid, order=1).omega(3)
    sign = 1.0 if np.count_nonzero(w > 0) > np.count_nonzero(w < 0) else -1.0
    idle = solve(scene, PHIS, order=1).omega(3) * sign < 0
    np.testing.assert_array_equal(m, np.where(idle, 25.0, 0.0))


def test_a_resisting_force_on_both_strokes_warns(capsys):
    _scene("shaper", force={"name": "F_c", "link": 5, "point": "E", "resisting": 1000, "along": 0})
    _forces(_scene("shaper", force={"name": "F_c", "link": 5, "point": "E", "resisting": 1000,
                                        "along": 0}))
    err = capsys.readouterr().err
    assert "warning" in err and "[[loads.force]] entry 1, resisting" in err and "F_c" in err and "idle" in err
    assert err.count("\n") == 1  # once per scene
    for stroke in ("working", "both", "positive"):
        _forces(_scene("shaper", force={"name": "F_c", "link": 5, "point": "E", "resisting": 1000,
                                            "along": 0, "stroke": stroke}))
        assert capsys.readouterr().err == ""


def test_a_resisting_moment_warns_in_the_scenes_language(capsys):
    data = read_toml(ROOT / "samples" / "four_bar.toml")
    del data["loads"]["moment"][0]["stroke"]
    data["sheet"] = dict(data.get("sheet", {}), language="ru")
    _forces(scene_from_dict(data, "four_bar.toml"))
    err = capsys.readouterr().err
    assert "внимание" in err and "холостом" in err and "[[loads.moment]] № 1, resisting" in err


def test_no_warning_when_the_strokes_take_equal_time(capsys):
    """A central slider-crank (K = 1) has no fast stroke to warn of."""
    data = read_toml(ROOT / "samples" / "offset_slider_crank.toml")
    del data["loads"]["force"][0]["stroke"]
    data["joints"][-1]["guide"].pop("offset", None)
    data["joints"][-1]["guide"]["through"] = "O" if "O" in data["points"] else [0, 0]
    scene = scene_from_dict(data, "central.toml")
    _forces(scene)
    assert capsys.readouterr().err == ""
    del data["joints"][-1]["guide"]["through"]
    data["joints"][-1]["guide"]["through"] = [0, 20]
    _forces(scene_from_dict(data, "offset.toml"))
    assert "warning" in capsys.readouterr().err


def test_stroke_bad_input():
    with pytest.raises(InputError) as exc:
        _forces(_scene("shaper", force={"link": 5, "point": "E", "resisting": 10, "stroke": "work"}))
    assert exc.value.field == "loads.force[0].stroke" and "working" in str(exc.value)
    with pytest.raises(InputError) as exc:
        _forces(_scene("shaper", moment={"link": 3, "value": 1, "stroke": "fast"}))
    assert exc.value.field == "loads.moment[0].stroke"
    # a coulisse that turns round has no strokes of its own: the ram's are taken by default,
    # naming the coulisse says why it cannot be
    data = read_toml(ROOT / "samples" / "whitworth.toml")
    data["driver"]["extreme_of"] = 3
    data["loads"]["force"][0]["stroke"] = "working"
    del data["loads"]["force"][0]["along"]
    with pytest.raises(InputError) as exc:
        _forces(scene_from_dict(data, "whitworth.toml"))
    assert "turns all the way round" in str(exc.value)


def test_a_force_by_the_sign_of_its_velocity_on_the_fast_stroke_only_warns(capsys):
    """The Whitworth ram cuts while moving to −x (its slow stroke): stroke = "positive" would
    put the cutting force on the quick return."""
    for stroke, warned in (("positive", True), ("negative", False), ("working", False)):
        _forces(_scene("whitworth", force={"name": "F_c", "link": 5, "point": "E", "resisting": 1500, "along": 0,
                                           "stroke": stroke}))
        err = capsys.readouterr().err
        assert ("idle (fast) stroke only" in err and "[[loads.force]] entry 1, stroke" in err) == warned, (stroke, err)


@pytest.mark.parametrize("load", [
    {"force": {"name": "F_c", "link": 5, "point": "E", "resisting": 2000, "stroke": "working"}},
    {"force": {"name": "F_c", "link": 5, "point": "E", "resisting": 2000, "along": 0, "stroke": "both"}},
])
def test_no_resisting_force_at_the_extreme_where_the_ram_stops(load):
    """At the exact extreme the ram's velocity is round-off (1e-17 m/s): it resists nothing there,
    not the full force in the direction of the dust."""
    data = read_toml(ROOT / "samples" / "shaper.toml")
    data["driver"]["phi_start"] = "extreme"
    data["loads"]["force"] = [load["force"]]
    fa = _forces(scene_from_dict(data, "shaper.toml"))[0]
    F = next(f for f in fa.applied.forces if f.label == "F_c").F
    assert F[0] == 0 and np.all(np.abs(F[1:4]) == 2000)


def test_no_resisting_moment_at_the_rockers_extreme():
    data = read_toml(ROOT / "samples" / "four_bar.toml")
    data["driver"].pop("phi_deg", None)
    data["driver"].update(positions=12, phi_start="extreme")
    fa = _forces(scene_from_dict(data, "four_bar.toml"))[0]
    M = next(m for m in fa.applied.moments if m.label == "M_c").M
    assert M[0] == 0 and np.all(np.abs(M[1:5]) == 40)


def test_the_warning_is_advice_to_the_fuzzer_not_a_broken_promise(tmp_path):
    """A scene accepted with a warning keeps the bad-input promise (status 0, advice on stderr)."""
    from plans.accuracy import fuzz

    data = read_toml(ROOT / "samples" / "four_bar.toml")
    del data["loads"]["moment"][0]["stroke"]
    sample = fuzz.Sample(ROOT / "samples" / "four_bar.toml", data, fuzz._kind_argv("linkage", False), "four_bar.toml",
                         kind="linkage")
    res = fuzz.run_case(sample, fuzz.to_toml(data).encode("utf-8"), tmp_path)
    assert res.ok and res.status == 0, res.why
    assert fuzz._without_advice("plans: warning: x\nplans: error: y\n") == "plans: error: y\n"
