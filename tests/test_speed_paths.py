"""The fast paths change no reading: one position in Python numbers equals the same position
solved with numpy among many; the linear structure analysis finds the groups the plain
search finds; the hand-written floor and the peers agree with the exact analysis."""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np
import pytest

from plans.accuracy import floor, peers, reference
from plans.accuracy.oracles import chain_scene
from plans.errors import ConstructionError
from plans.kinematics import exact
from plans.kinematics.placing import load_scene
from plans.kinematics.structure import _orient, analyse

SAMPLES = sorted((Path(__file__).resolve().parent.parent / "samples").glob("*.toml"))
FIELDS = ("rot", "r0", "omega", "v0", "eps", "a0")


def _scenes():
    out = [(p.stem, load_scene(p)) for p in SAMPLES]
    out.append(("chain of 7", chain_scene(7)))
    out.append(("slider-crank, pivot off the crank's origin",
                reference.slider_crank_scene(0.05, 0.2, 0.015, -80.0, eps=30.0)))
    return out


def _scale(sc, f):
    w = abs(sc.driver.omega) or 1.0
    return {"rot": 1.0, "r0": 1.0, "omega": w, "v0": w, "eps": w * w, "a0": w * w}[f]


@pytest.mark.parametrize("name, sc", _scenes(), ids=[n for n, _ in _scenes()])
@pytest.mark.parametrize("order", [0, 1, 2])
def test_scalar_path_equals_vectorised_path(name, sc, order):
    picked = [3.0, 45.0, 181.0]
    assert len(picked) <= exact.SCALAR_MAX
    many = np.concatenate([np.linspace(0.0, 360.0, 24, endpoint=False) + 0.5, picked])
    one = exact.solve(sc, picked, order=order)
    vec = exact.solve(sc, many, order=order)
    assert set(one.motion) == set(vec.motion)
    assert set(one.slides) == set(vec.slides) and set(one.conditions) == set(vec.conditions)
    for lid in vec.motion:
        for f in FIELDS:
            x, y = getattr(one.motion[lid], f), getattr(vec.motion[lid], f)
            assert (x is None) == (y is None), (lid, f)
            if y is None:
                continue
            assert x.shape == (3,)
            assert np.max(np.abs(x - y[-3:])) <= 1e-12 * _scale(sc, f), (lid, f)
    for nm, (sd, sdd) in vec.slides.items():
        w = abs(sc.driver.omega)
        assert np.max(np.abs(one.slides[nm][0] - sd[-3:])) <= 1e-12 * w
        if sdd is not None:
            assert np.max(np.abs(one.slides[nm][1] - sdd[-3:])) <= 1e-12 * w * w
    for g, c in vec.conditions.items():
        assert np.allclose(one.conditions[g], c[-3:], rtol=1e-9, atol=0)
    # the readings every consumer takes: points by name
    for nm in vec.point_names():
        for k in range(order + 1):
            a, b = one.point(nm)[k], vec.point(nm)[k]
            assert np.max(np.abs(a - b[-3:])) <= 1e-12 * (abs(sc.driver.omega) ** k or 1.0)


def test_both_paths_name_the_same_position_that_does_not_assemble():
    # crank 0.1, rod 0.15, rocker 0.05, frame 0.2: the rod cannot reach at φ = 180°
    sc = reference.four_bar_scene(0.1, 0.15, 0.05, 0.2)
    errs = []
    for phis in ([180.0], np.array([10.0, 20.0, 180.0, 30.0, 40.0, 50.0])):
        with pytest.raises(ConstructionError) as ei:
            exact.solve(sc, phis, order=2)
        errs.append(ei.value)
    assert type(errs[0]) is type(errs[1])
    assert str(errs[0]) == str(errs[1])


def _plain_groups(sc):
    """The search the linear analysis replaced: every pair in order, every joint scanned."""
    known = {sc.driver.link, sc.frame}
    remaining = sorted(set(sc.links) - known)
    out = []
    while remaining:
        found = None
        for i in remaining:
            for j in remaining:
                if j <= i:
                    continue
                inner = [x for x in sc.joints if set(x.links) == {i, j}]
                oi = [x for x in sc.joints if i in x.links and x.other(i) in known]
                oj = [x for x in sc.joints if j in x.links and x.other(j) in known]
                if len(inner) == 1 and len(oi) == 1 and len(oj) == 1:
                    found = _orient(sc, i, j, oi[0], inner[0], oj[0])
                    break
            if found:
                break
        assert found is not None
        out.append(found)
        known |= set(found.links)
        remaining = [x for x in remaining if x not in found.links]
    return tuple(out)


@pytest.mark.parametrize("name, sc", _scenes(), ids=[n for n, _ in _scenes()])
def test_linear_structure_analysis_finds_the_same_groups(name, sc):
    st = analyse(sc)
    assert st.groups == _plain_groups(sc)
    assert analyse(sc) is st  # once per scene


def test_structure_of_a_long_chain_is_linear_in_work():
    sc = chain_scene(120)
    st = analyse(sc)
    assert len(st.groups) == 120
    assert [g.name for g in st.groups] == [f"{2 * k}-{2 * k + 1}" for k in range(1, 121)]


@pytest.mark.parametrize("case", ["slider", "four-bar", "v_engine"])
def test_the_numpy_floor_agrees_with_the_exact_analysis(case):
    if case == "slider":
        sc = reference.slider_crank_scene(0.05, 0.2, 0.015, 2 * math.pi * 25)
    elif case == "four-bar":
        sc = reference.four_bar_scene(0.05, 0.2, 0.15, 0.18, 2 * math.pi * 25)
    else:
        sc = load_scene(Path(__file__).resolve().parent.parent / "samples" / "v_engine.toml")
    phis = np.linspace(0.0, 360.0, 72, endpoint=False) + 7.5
    assert floor.check_against(sc, phis, exact.solve(sc, phis, order=2)) < 1e-13


def test_the_floor_declines_what_it_does_not_model():
    sc = load_scene(Path(__file__).resolve().parent.parent / "samples" / "shaper.toml")
    assert floor.floor_for(sc) is None


def test_a_missing_peer_is_skipped_with_its_reason():
    runs = peers.run_peers([("four-bar", reference.four_bar_scene(0.05, 0.2, 0.15, 0.18, 10.0))],
                           positions=36, mechanism_positions=4)
    for r in runs:
        why = peers.available(r.peer.split()[0])
        if why:
            assert r.note.startswith("skipped: ") and math.isnan(r.time_per_position)
        elif r.peer in ("pylinkage + numba", "mechanism"):
            tol = 1e-12 if r.peer.startswith("pylinkage") else 1e-6
            assert r.errors["r"] < tol, r


@pytest.mark.parametrize("name, sc", _scenes(), ids=[n for n, _ in _scenes()])
@pytest.mark.parametrize("order", [0, 1, 2])
@pytest.mark.parametrize("phis", [[45.0], [3.0, 181.0], list(np.linspace(0.0, 360.0, 24, endpoint=False) + 0.5)],
                         ids=["one", "few", "many"])
def test_fast_path_equals_the_general_solvers(name, sc, order, phis, monkeypatch):
    """The fast path for cranks with RRR/RRP dyads gives what the general solvers give."""
    fast_kin = exact.solve(sc, phis, order=order)
    monkeypatch.setattr(exact.fast, "plan_for", lambda *a: None)
    slow = exact.solve(sc, phis, order=order)
    w = abs(sc.driver.omega) or 1.0
    assert set(fast_kin.motion) == set(slow.motion)
    for lid in slow.motion:
        for f in FIELDS:
            x, y = getattr(fast_kin.motion[lid], f), getattr(slow.motion[lid], f)
            assert (x is None) == (y is None), (lid, f)
            if y is not None:
                assert x.shape == y.shape == (len(phis),)
                assert np.max(np.abs(x - y)) <= 1e-12 * _scale(sc, f), (lid, f)
    assert set(fast_kin.slides) == set(slow.slides) and set(fast_kin.conditions) == set(slow.conditions)
    for nm, (sd, sdd) in slow.slides.items():
        assert np.max(np.abs(fast_kin.slides[nm][0] - sd)) <= 1e-12 * w
        assert (sdd is None) == (fast_kin.slides[nm][1] is None)
        if sdd is not None:
            assert np.max(np.abs(fast_kin.slides[nm][1] - sdd)) <= 1e-12 * w * w
    for g, c in slow.conditions.items():
        assert np.allclose(fast_kin.conditions[g], c, rtol=1e-9, atol=0)
    assert np.array_equal(fast_kin.phi_deg, slow.phi_deg)


def test_the_fast_path_covers_the_usual_mechanisms():
    for sc in (reference.slider_crank_scene(0.05, 0.2, 0.015, 10.0), reference.four_bar_scene(0.05, 0.2, 0.15, 0.18),
               load_scene(Path(__file__).resolve().parent.parent / "samples" / "v_engine.toml"), chain_scene(5)):
        assert exact.fast.plan_for(sc, analyse(sc)) is not None


@pytest.mark.parametrize("order", [0, 1, 2])
@pytest.mark.parametrize("case", ["slider-crank", "four-bar", "V-engine"])
def test_what_does_not_assemble_is_named_alike_on_every_path(case, order, monkeypatch):
    """A position that does not assemble gives the general solvers' error whether the fast
    path runs (one position, a few, many) or not."""
    if case == "slider-crank":  # at 270° A is 70 mm from the guide, the rod 60 mm long
        sc = reference.slider_crank_scene(0.05, 0.06, 0.02, 10.0)
        bad = 270.0
    elif case == "four-bar":
        sc = reference.four_bar_scene(0.1, 0.15, 0.05, 0.2)
        bad = 180.0
    else:
        import dataclasses

        v = load_scene(Path(__file__).resolve().parent.parent / "samples" / "v_engine.toml")
        links = dict(v.links)
        rod = links[4]
        links[4] = dataclasses.replace(rod, points={k: z * 0.2 for k, z in rod.points.items()})
        sc = dataclasses.replace(v, links=links)
        bad = 45.0
    msgs = []
    for phis in ([bad], [10.0, bad], np.array([10.0, 20.0, bad, 30.0, 40.0, 50.0])):
        for off in (False, True):
            if off:
                monkeypatch.setattr(exact.fast, "plan_for", lambda *a: None)
            with pytest.raises(ConstructionError) as ei:
                exact.solve(sc, phis, order=order)
            msgs.append(str(ei.value))
            monkeypatch.undo()
    assert msgs[0::2] == msgs[1::2]  # fast path or not, the same error
    assert f"phi = {bad:g} deg" in msgs[0]


def test_one_position_reads_like_any_other():
    """One position solved in Python numbers reads as arrays of one element, copies and
    compares like any Kinematics, and has no attribute it should not have."""
    import copy

    sc = reference.four_bar_scene(0.05, 0.2, 0.15, 0.18, 10.0)
    one = exact.solve(sc, [30.0], order=2)
    assert not hasattr(one, "not_a_field")
    twin = copy.deepcopy(one)
    assert isinstance(one.phi_deg, np.ndarray) and one.phi_deg.tolist() == [30.0] and one.n == 1
    assert "1 positions, order 2" in repr(one)  # how many positions and the order solved, as any Kinematics
    for k in (one, twin):
        assert all(isinstance(x, np.ndarray) and x.shape == (1,) for x in k.point("B"))
        assert all(c.shape == (1,) for c in k.conditions.values())
    assert np.array_equal(one.point("B")[2], twin.point("B")[2])


def test_what_waits_until_read_reads_as_the_general_solvers_give_it(monkeypatch):
    """Over arrays the fast path leaves a link's rotation, a slider's v and a and a group's
    condition until they are read: read after a copy, and after the points, they are
    arrays over the positions equal to the general solvers', and the reach (the largest
    |r| of the points) is theirs too."""
    import copy

    sc = load_scene(Path(__file__).resolve().parent.parent / "samples" / "v_engine.toml")
    phis = np.linspace(0.0, 360.0, 360, endpoint=False) + 7.5
    kin = exact.solve(sc, phis, order=2)
    twin = copy.deepcopy(kin)
    monkeypatch.setattr(exact.fast, "plan_for", lambda *a: None)
    slow = exact.solve(sc, phis, order=2)
    w = abs(sc.driver.omega)
    for k in (kin, twin):
        for nm in k.point_names():
            k.point(nm)
        for lid, m in slow.motion.items():
            for f in FIELDS:
                x, y = getattr(k.motion[lid], f), getattr(m, f)
                assert isinstance(x, np.ndarray) and x.shape == (360,), (lid, f)
                assert np.max(np.abs(x - y)) <= 1e-12 * _scale(sc, f), (lid, f)
        for g, c in slow.conditions.items():
            assert isinstance(k.conditions[g], np.ndarray) and np.allclose(k.conditions[g], c, rtol=1e-9, atol=0)
        assert abs(k.reach() - slow.reach()) <= 1e-15 * slow.reach()
        for nm in ("B", "C"):
            assert np.max(np.abs(k.point(nm)[1] - slow.point(nm)[1])) <= 1e-12 * w
    # the pistons are farthest from the crank's pivot (the origin) at their outer dead
    # centres, OA + AB away; the positions pass within half a degree of them
    r, l = 0.035, 0.1207
    assert (r + l) * (1 - 1e-4) <= kin.reach() <= (r + l) * (1 + 1e-15)


def test_the_lever_arm_read_when_asked_is_the_distance_from_the_pole():
    """A lever force's arm (worked out where it is read) is the distance from the pole to
    the force's line: |w × F| / |F| from the plane vectors' components."""
    from plans.forces.analysis import kinetostatics

    sc = load_scene(Path(__file__).resolve().parent.parent / "samples" / "v_engine.toml")
    _, lv = kinetostatics(sc, exact.solve(sc, np.linspace(0.0, 360.0, 36, endpoint=False) + 2.5, order=2))
    for it in lv.forces:
        w = np.stack([it.w.real, it.w.imag], axis=-1)
        F = np.stack([it.F.real, it.F.imag], axis=-1)
        mag = np.hypot(F[:, 0], F[:, 1])
        h = np.abs(w[:, 0] * F[:, 1] - w[:, 1] * F[:, 0]) / np.where(mag > 0, mag, 1.0)
        assert np.allclose(it.arm, np.where(mag > 0, h, 0.0), rtol=1e-12, atol=1e-12 * np.max(np.abs(it.w)))
        assert it.arm is it.arm  # worked out once
