"""Sheet sets: the course's kinematics and kinetostatics sheets, and ``[sheet] panels`` choosing
the positions of each kind of panel."""

from __future__ import annotations

from pathlib import Path

import pytest
import shapely

from drawings.linkage import draw
from drawings.paper.sheet import usable
from plans.errors import InputError
from plans.scene.sheet import read_sheet
from tests.locales import in_russian

#: The sheets these tests measure were drawn in Russian, the default before it followed the locale.
draw = in_russian(draw)

ROOT = Path(__file__).resolve().parents[1]
SAMPLES = ROOT / "samples"
FORCES = ("group", "polygon", "crank", "lever")


@pytest.fixture(scope="module")
def course():
    return draw(SAMPLES / "slider_crank.toml")


def _scene_with(tmp_path: Path, name: str, sheet: str) -> Path:
    """A sample with ``sheet`` as its ``[sheet]`` table (the sample's own has none)."""
    text = (SAMPLES / f"{name}.toml").read_text(encoding="utf-8")
    assert "[sheet]" not in text
    p = tmp_path / f"{name}.toml"
    p.write_text(text + "\n[sheet]\n" + sheet + "\n", encoding="utf-8")
    return p


def _kinds(sheet) -> list[str]:
    return [p.kind for p, _, _ in sheet.placed]


def test_twelve_positions_give_a_kinematics_sheet_and_a_kinetostatics_sheet(course):
    """The course's set is the default for 12 positions: the plan of positions, the 12 velocity
    plans and the acceleration plans of the two positions studied (the first two) on the
    kinematics sheet; the mechanism, the groups, polygons, crank and lever of those two
    positions on the kinetostatics sheet, nothing else."""
    d = course
    assert len(d.sheets) == 2
    kin, dyn = d.sheets
    kinds = _kinds(kin)
    assert kinds[0] == "positions"
    assert not set(kinds) & set(FORCES)
    vel = {p.phi for p, _, _ in kin.placed if p.kind == "velocity"}
    acc = {p.phi for p, _, _ in kin.placed if p.kind == "acceleration"}
    assert vel == {30.0 * k for k in range(12)}
    assert acc == {0.0, 30.0}
    assert {p.phi for p, _, _ in dyn.placed} == {0.0, 30.0}
    assert {"scheme", "group", "polygon", "crank", "lever"} <= set(_kinds(dyn))
    assert not {"velocity", "acceleration", "positions"} & set(_kinds(dyn))
    assert [f.heading.split(",")[0] for f in dyn.frames] == ["Положение 1", "Положение 2"]


def test_the_velocity_plans_come_before_the_acceleration_plans(course):
    """The method's order: the plan of positions, every velocity plan, then the acceleration
    plans, in that order on the sheet as read (top to bottom, left to right) at each position."""
    kin = course.sheets[0]
    kinds = _kinds(kin)
    last_velocity = max(i for i, k in enumerate(kinds) if k == "velocity")
    assert all(i > last_velocity for i, k in enumerate(kinds) if k == "acceleration")
    boxes = kin.panel_boxes()
    for pid, box in boxes.items():
        if pid.startswith("acceleration-"):
            v = boxes["velocity-" + pid.split("-", 1)[1]]
            assert (v[1], v[0]) < (box[1], box[0]) or v[3] <= box[1], pid


def test_panels_choose_the_positions_of_each_kind(tmp_path):
    p = _scene_with(tmp_path, "four_bar",
                    'panels = { velocity = [1, 4, 7], acceleration = [4], forces = [7], lever = "none" }')
    d = draw(p)
    placed = [pl for sh in d.sheets for pl, _, _ in sh.placed]
    at = {kind: sorted({pl.phi for pl in placed if pl.kind == kind}) for kind in
          ("velocity", "acceleration", "group", "lever", "scheme")}
    assert at == {"velocity": [0.0, 90.0, 180.0], "acceleration": [90.0], "group": [180.0], "lever": [],
                  "scheme": [180.0]}  # the mechanism where the forces are
    assert sum(pl.kind == "positions" for pl in placed) == 1
    assert len(d.sheets) == 2 and "group" not in _kinds(d.sheets[0])


def test_the_positions_set_keeps_a_block_per_position(tmp_path):
    p = _scene_with(tmp_path, "four_bar", 'set = "positions"\npositions = [0, 90]')
    d = draw(p)
    heads = [f.heading for sh in d.sheets for f in sh.frames]
    assert [h.split(",")[0] for h in heads] == ["Положение 1", "Положение 4"]
    assert draw(SAMPLES / "v_engine.toml").sheets[0].frames  # fewer than 12 positions: blocks


@pytest.mark.parametrize("sheet, field, words", [
    ('set = "kinematics"', "sheet.set", "expected one of 'course', 'positions'"),
    ('panels = { velocty = "all" }', "sheet.panels.velocty", "did you mean 'velocity'"),
    ('panels = { acceleration = "some" }', "sheet.panels.acceleration", 'expected "all", "none" or position'),
    ('panels = { forces = [1.5] }', "sheet.panels.forces", "position numbers"),
    ('panels = { forces = [true] }', "sheet.panels.forces", "position numbers"),
    ('panels = { positions = 1 }', "sheet.panels.positions", "expected true or false"),
    ('panels = 3', "sheet.panels", "or a table such as"),
])
def test_bad_sheet_set_or_panels_one_line_naming_the_field(sheet, field, words):
    import tomllib

    with pytest.raises(InputError) as e:
        read_sheet(tomllib.loads("[sheet]\n" + sheet), "s.toml")
    msg = str(e.value)
    assert "\n" not in msg and msg.startswith(f"s.toml: {field}: ") and words in msg, msg


def test_a_position_number_the_scene_has_not(tmp_path):
    p = _scene_with(tmp_path, "slider_crank", "panels = { forces = [13] }")
    with pytest.raises(InputError, match=r"sheet\.panels\.forces: no position 13; the positions are numbered 1 to 12"):
        draw(p)


def test_pins_with_the_course_set_are_refused(tmp_path):
    p = _scene_with(tmp_path, "slider_crank",
                    'set = "course"\n[[sheet.pins]]\npanel = "velocity-30"\nx = 300\ny = 20')
    with pytest.raises(InputError, match=r"sheet\.pins: pinned panels need set = \"positions\""):
        draw(p)


def fill(sheet) -> float:
    """The drawn part of a sheet's field (inside the frame, less the title block): the union
    of its panels' boxes over the field's area."""
    field = shapely.box(*usable(sheet.width, sheet.height)).difference(shapely.box(*sheet.title_box))
    boxes = [shapely.box(x, y, x + p.width, y + p.height) for p, x, y in sheet.placed]
    return shapely.union_all(boxes).intersection(field).area / field.area


def test_fill_measures_the_union_of_the_panels():
    """The measure itself, on two made-up sheets: overlapping boxes count once."""
    from types import SimpleNamespace

    P = SimpleNamespace
    a = usable(841.0, 594.0)
    sh = SimpleNamespace(width=841.0, height=594.0, title_box=(651.0, 534.0, 836.0, 589.0),
                         placed=[(P(width=a[2] - a[0], height=100.0), a[0], a[1]),
                                 (P(width=a[2] - a[0], height=100.0), a[0], a[1] + 50.0)])
    corner = (a[2] - 651.0) * (a[3] - 534.0)  # the title block's part inside the field
    want = (a[2] - a[0]) * 150.0 / ((a[2] - a[0]) * (a[3] - a[1]) - corner)
    assert fill(sh) == pytest.approx(want)
