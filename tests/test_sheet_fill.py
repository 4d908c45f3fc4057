"""Sheets filled as a draftsman fills them: the plans drawn at a larger round scale where an A1
sheet has room (the scales written on them the ones they are drawn at), two short sets on
one sheet."""

from __future__ import annotations

import itertools
import xml.etree.ElementTree as ET
from pathlib import Path

import pytest
import shapely

import plans
from drawings import draw
from plans.kinematics.scales import is_round
from tests.locales import in_russian
from tests.test_drawings import _stated_scale, _vectors
from tests.test_sheet_fit import assert_clear

#: The sheets these tests measure were drawn in Russian, the default before it followed the locale.
draw = in_russian(draw)

ROOT = Path(__file__).resolve().parents[1]
SAMPLES = ROOT / "samples"


@pytest.fixture(scope="module")
def four_bar():
    return draw(SAMPLES / "four_bar.toml")


@pytest.fixture(scope="module")
def four_bar_plans_alone():
    """The four-bar's sheets without the output's kinematic diagrams (``panels = { diagrams =
    false }``): a kinematics sheet of the plan of positions and the plans alone."""
    from plans.io import read_toml
    from plans.kinematics.placing import scene_from_dict

    data = read_toml(SAMPLES / "four_bar.toml")
    data["sheet"] = {"panels": {"diagrams": False}}
    return draw(scene_from_dict(data, str(SAMPLES / "four_bar.toml")))


def test_plans_drawn_larger_where_the_sheet_has_room(four_bar_plans_alone):
    """The four-bar's kinematics sheet of the plans alone (no diagrams: they take this room by
    default, tests/test_output_diagrams.py) at the A1 lengths is left 0.47 empty: its velocity plans
    are drawn at a larger round scale than the engine's A1 one, every one written on its panel
    and the one its known vector p_v a is drawn at (v_A = ω1·l_OA from the scene, not the plan)."""
    sol = plans.solve(SAMPLES / "four_bar.toml")  # the A1 lengths
    a1 = {float(pp.velocity.phi_deg): pp.velocity.scale for pp in sol.plans if pp.velocity is not None}
    scene = sol.scene
    crank = scene.links[scene.driver.link]
    v_a = abs(scene.driver.omega) * abs(crank.points[crank.axis[1]] - crank.points[crank.axis[0]])
    grown = 0
    for sh in four_bar_plans_alone.sheets:
        root = ET.fromstring(sh.svg())
        for p, _, _ in sh.placed:
            if p.kind != "velocity":
                continue
            mu = _stated_scale(root, p.pid)
            assert is_round(mu) and mu >= a1[p.phi] * (1 - 1e-12), p.pid
            assert _vectors(root, p.pid)["v_A"] == pytest.approx(mu * v_a, abs=0.02), p.pid
            grown += mu > a1[p.phi] * (1 + 1e-9)
    assert grown >= 6


def test_the_sheets_stay_clear_and_as_few(four_bar):
    """Larger plans never cost a sheet (the course's two) nor overlap: every panel inside the
    frame, clear of the title block and of the others."""
    assert len(four_bar.sheets) == 2
    for sh in four_bar.sheets:
        assert_clear(sh)


def test_a_solution_solved_at_another_fit_is_drawn_as_solved():
    """Only the drawing's own choice grows: a Solution solved at a fit of its own keeps its
    scales on the sheet."""
    from drawings.linkage import fit_for
    from plans.kinematics.placing import load_scene

    scene = load_scene(SAMPLES / "v_engine.toml")
    fit = fit_for(scene.sheet_for()) * 0.8
    sol = plans.solve(scene, fit=fit)
    want = {float(pp.velocity.phi_deg): pp.velocity.scale for pp in sol.plans}
    got = {p.phi: p.scale for sh in draw(sol).sheets for p, _, _ in sh.placed if p.kind == "velocity"}
    assert got == {phi: want[phi] for phi in got} and got


def test_two_short_sets_on_one_sheet():
    """A gear file's meshing and its train share one sheet: the train's figures keep an
    arrangement they have laid out alone (the plan of velocities beside the scheme at its
    heights), moved as one piece, clear of the meshing; the Scale cell names both scales."""
    import dataclasses

    from drawings.gears import draw as draw_gears
    from drawings.paper.sheet import compose

    d = draw_gears(SAMPLES / "gears" / "seed_train.toml")
    assert len(d.sheets) == 1
    sh = d.sheets[0]
    at = {p.pid: (x, y) for p, x, y in sh.placed}
    train = [p for p in d.panels if p.pid in ("train-scheme", "velocity-plan", "ray-diagram")]
    assert len(train) == 3
    shifts = []
    for fmt, orientation in (("A1", "landscape"), ("A2", "landscape"), ("A2", "portrait")):
        on = dataclasses.replace(d.spec, format=fmt, orientation=orientation)
        alone = {p.pid: (x, y) for p, x, y in compose(train, on, "", "<x>")[0].placed}
        shifts.append({(round(at[k][0] - alone[k][0], 6), round(at[k][1] - alone[k][1], 6)) for k in alone})
    assert min(len(s) for s in shifts) == 1  # moved as one piece, as laid out alone on some sheet
    assert at["velocity-plan"][1] == at["train-scheme"][1]  # beside the scheme, tops level
    assert at["velocity-plan"][0] > at["train-scheme"][0]
    boxes = [shapely.box(x, y, x + p.width, y + p.height) for p, x, y in sh.placed]
    for b, c in itertools.combinations(boxes, 2):
        assert b.intersection(c).area < 1e-6
    cell = [p.label.plain for p in sh.prims if p.op == "text" and p.eid == "tb-scale"]
    assert cell and ";" in cell[0]
