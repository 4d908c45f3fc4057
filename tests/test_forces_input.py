"""Bad loads: one clear line naming the file and the field."""

from __future__ import annotations

import pytest

from plans.errors import InputError
from plans.forces.loads import parse_loads
from plans.kinematics.placing import scene_from_dict

from .conftest import four_bar_scene, slider_crank_scene


def _scene(loads=None, **link_keys):
    raw = slider_crank_scene(outputs=("force_polygons", "lever"))
    raw["links"]["2"].update(centre="S2")
    for lid, keys in link_keys.items():
        raw["links"][lid.lstrip("l")].update(keys)
    if loads is not None:
        raw["loads"] = loads
    return scene_from_dict(raw, "bad.toml")


GAS = {"link": 3, "diameter": 80, "pressure_unit": "MPa"}


@pytest.mark.parametrize("loads, link_keys, match", [
    (None, {"l2": {"mass": -1.0}}, r"bad.toml: links.2.mass: expected a number >= 0"),
    (None, {"l2": {"inertia": -0.1}}, r"links.2.inertia: expected a number >= 0"),
    ({"force": [{"link": 9, "point": "B", "vector": [1, 0]}]}, {}, r"\[\[loads.force\]\] entry 1, link: unknown link 9"),
    ({"force": [{"link": 2, "point": "Q", "vector": [1, 0]}]}, {}, r"\[\[loads.force\]\] entry 1, point: unknown point 'Q' on link 2"),
    ({"force": [{"link": 4, "point": "O", "vector": [1, 0]}]}, {}, r"\[\[loads.force\]\] entry 1, link: link 4 is the frame"),
    ({"moment": [{"link": 7, "value": 1}]}, {}, r"\[\[loads.moment\]\] entry 1, link: unknown link 7"),
    ({"moment": [{"link": 2}]}, {}, r"\[\[loads.moment\]\] entry 1, value"),
    ({"balancing": {"point": "O"}}, {}, r"loads.balancing.point: point 'O' is the pivot"),
    ({"balancing": {"point": "B"}}, {}, r"loads.balancing.point: point 'B' is not on the driving link 1"),
    ({"balancing": {"kind": "torque"}}, {}, r"loads.balancing.kind"),
    ({"gas": [dict(GAS, link=2, pressure=1)]}, {}, r"\[\[loads.gas\]\] entry 1, link: link 2 is not a piston"),
    ({"gas": [dict(GAS)]}, {}, r"\[\[loads.gas\]\] entry 1, pressure: missing pressure"),
    ({"gas": [dict(GAS, pressure=1, pressure_unit="psi")]}, {}, r"\[\[loads.gas\]\] entry 1, pressure_unit"),
    ({"gas": [dict(GAS, diagram={"down": [[0, 1], [50, 0.5]]})]}, {},
     r"\[\[loads.gas\]\] entry 1, diagram.down: the table covers travel 0..50 mm but the stroke is 0..100 mm"),
    ({"gas": [dict(GAS, diagram={"down": [[10, 1], [100, 0.5]]})]}, {}, r"diagram.down: the table covers"),
    ({"gas": [dict(GAS, diagram={"down": [[0, 1], [100, 0.5]]})]}, {},
     r"\[\[loads.gas\]\] entry 1, diagram: no table for the 'up' stroke"),
    ({"gas": [dict(GAS, diagram={"down": [[0, 1], [0, 0.5], [100, 0]]}, strokes=["down"])]}, {},
     r"expected travel increasing"),
    ({"gravity": "yes"}, {}, r"loads.gravity: expected true, false"),
    ({"inertia": "both"}, {}, r"loads.inertia"),
    ({"lever_turn": "left"}, {}, r"loads.lever_turn"),
    ({"wind": 3}, {}, r"loads.wind: unknown key"),
    ({"mass_rule": {"diameter": 82, "g_per_cm2": {"2": 16}}}, {"l2": {"mass": 1.0}},
     r"loads.mass_rule.g_per_cm2.2: link 2 sets mass"),
    ({"force": [{"link": 3, "point": "B", "resisting": 10, "stroke": "positive"}]}, {},
     r"\[\[loads.force\]\] entry 1, stroke: a stroke needs an axis"),
])
def test_bad_loads(loads, link_keys, match):
    with pytest.raises(InputError, match=match):
        parse_loads(_scene(loads, **link_keys))


def test_message_is_one_line_with_file_and_field():
    with pytest.raises(InputError) as info:
        parse_loads(_scene({"balancing": {"point": "B"}}))
    msg = str(info.value)
    assert "\n" not in msg and msg.startswith("bad.toml: loads.balancing.point:")


def test_balancing_point_on_the_frame():
    raw = four_bar_scene(outputs=("lever",))
    raw["loads"] = {"balancing": {"point": "D"}}
    with pytest.raises(InputError, match=r"loads.balancing.point: point 'D' is on the frame"):
        parse_loads(scene_from_dict(raw, "fb.toml"))


def test_mass_without_a_centre():
    raw = four_bar_scene(outputs=("lever",))
    raw["links"]["2"]["mass"] = 1.0
    with pytest.raises(InputError, match=r"links.2.centre: link 2 has mass"):
        parse_loads(scene_from_dict(raw, "fb.toml"))


def test_a_diagram_that_covers_the_stroke_is_accepted():
    loads = parse_loads(_scene({"gas": [dict(GAS, diagram={"down": [[0, 1], [100, 0.5]]}, strokes=["down"])]}))
    assert loads.gas[0].stroke == pytest.approx(0.1, rel=1e-6)  # H = 2 r


def test_the_documented_example_parses():
    """The TOML block of plans.loads' docstring (copied into the README) is valid input."""
    import tomllib

    import plans.forces.loads as loads_mod
    from plans.kinematics.placing import load_scene

    from .conftest import SAMPLES

    doc = loads_mod.__doc__ or ""
    block = doc.split(".. code-block:: toml", 1)[1].split("\nSign of", 1)[0]
    example = tomllib.loads("\n".join(line[4:] for line in block.splitlines()))
    path = next(p for p in SAMPLES if p.stem == "v_engine")
    raw = dict(load_scene(path).raw)
    raw["links"] = {k: {kk: vv for kk, vv in v.items() if kk not in ("mass", "inertia")}
                    for k, v in raw["links"].items()}
    raw["loads"] = example["loads"]
    loads = parse_loads(scene_from_dict(raw, "doc.toml"))
    assert loads.masses[3] > 0 and loads.gas[0].pressure == pytest.approx(50e4)
    assert loads.forces[0].name == "F_c" and loads.moments[0].value == -20
