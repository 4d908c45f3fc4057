"""A position's block whose border runs round the plan of positions (its top-left corner) and
the title block (its bottom-right corner): the border drawn, the room the block takes on the
sheet and the panels packed inside it agree, checked as polygons with shapely."""

from __future__ import annotations

import itertools
from pathlib import Path

import pytest
import shapely

from drawings.paper.blocks import HEAD, INSET, Block, frame_of, pack_block
from drawings.paper.packing import MIN_STEP, free_spots
from drawings.paper.panel_frame import Panel
from drawings.paper.sheet import GAP
from tests.locales import in_russian

ROOT = Path(__file__).resolve().parents[1]


def _panel(n: int, w: float, h: float) -> Panel:
    return Panel(f"p{n}-0", "scheme", 0.0, (), w, h)


@pytest.mark.parametrize("notch, lead", [(None, None), ((320.0, 300.0, 500.0, 400.0), None),
                                         (None, (0.0, 0.0, 150.0, 120.0)),
                                         ((320.0, 300.0, 500.0, 400.0), (0.0, 0.0, 150.0, 120.0))])
def test_the_room_a_block_takes_is_the_inside_of_its_border(notch, lead):
    """The rectangles a block takes on the sheet cover exactly what its border encloses."""
    b = Block([], 500.0, 400.0, 0.0, "Положение 1, φ = 0°", notch, lead)
    border = shapely.Polygon(frame_of(b, 30.0, 20.0).outline())
    boxes = b.boxes(30.0, 20.0)
    taken = shapely.union_all([shapely.box(*t) for t in boxes])
    assert border.is_valid
    assert taken.symmetric_difference(border).area < 1e-6
    assert sum(shapely.box(*t).area for t in boxes) == pytest.approx(border.area)  # no overlap


def test_panels_packed_round_both_corners_stay_inside_the_border():
    """Packed into a room with both corners kept clear, every panel lies INSET inside the
    border, GAP from the others, and out of the heading band that starts right of the lead."""
    panels = [_panel(n, w, h) for n, (w, h) in enumerate(
        [(240, 140), (150, 190), (150, 160), (140, 120), (180, 250), (160, 130), (110, 140), (80, 110),
         (100, 160), (170, 160), (120, 110), (150, 140)])]
    width, height = 800.0, 620.0
    lead = (0.0, 0.0, 245.0, 250.0)
    notch = (610.0, 560.0, width, height)
    blk, left = pack_block(panels, width, height, GAP, free_spots(GAP), "Положение 1, φ = 45°", notch, lead)
    assert not left
    assert blk.lead == lead  # the panels run under the plan of positions
    assert blk.notch is not None and blk.notch[:2] == notch[:2]  # and left of the title block
    f = frame_of(blk, 26.0, 11.0)
    inner = shapely.Polygon(f.outline()).buffer(-INSET + 1e-6, join_style="mitre")
    boxes = [shapely.box(26.0 + x, 11.0 + y, 26.0 + x + p.width, 11.0 + y + p.height) for p, x, y in blk.panels]
    assert all(inner.contains(b) for b in boxes)
    assert all(a.distance(b) >= GAP - 1e-6 for a, b in itertools.combinations(boxes, 2))
    assert f.head_x == pytest.approx(26.0 + lead[2])
    band = shapely.box(f.head_x, f.box[1], f.box[2], f.box[1] + HEAD)
    assert all(b.intersection(band).area < 1e-6 for b in boxes)


@pytest.fixture(scope="module")
def v_engine():
    from drawings.linkage import draw

    return in_russian(draw)(ROOT / "samples" / "v_engine.toml")


def test_v_engine_blocks_run_round_the_plan_of_positions_and_the_title_block(v_engine):
    """v_engine on A1: a position's border goes round the plan of positions (the block runs on
    under it) and round the title block, stepping down beside it by a visible step; what is not
    the position's (the plan, the legend, the title block) lies outside every border, at least
    half a GAP from it, and the legend shares the plan of positions' sheet."""
    rounds = {"plan": 0, "title": 0}
    for n, sh in enumerate(v_engine.sheets):
        outside = [shapely.box(*sh.title_box)] + [
            shapely.box(x, y, x + p.width, y + p.height) for p, x, y in sh.placed if p.phi is None]
        for f in sh.frames:
            border = shapely.Polygon(f.outline())
            hull = shapely.box(*f.box)
            for o in outside:
                assert border.intersection(o).area < 1e-6
                assert border.exterior.distance(o) >= GAP / 2 - 1e-6
            plan = [shapely.box(x, y, x + p.width, y + p.height) for p, x, y in sh.placed if p.kind == "positions"]
            rounds["plan"] += any(hull.contains(b) for b in plan)
            rounds["title"] += hull.intersection(shapely.box(*sh.title_box)).area > 1.0
            if f.notch is not None:  # a step down beside the title block, not a slip of the pen
                assert f.box[3] - f.notch[1] >= MIN_STEP
            for p, x, y in sh.placed:
                if p.phi == f.phi:
                    assert border.buffer(1e-6).contains(shapely.box(x, y, x + p.width, y + p.height)), (n, p.pid)
    assert rounds["plan"] >= 1 and rounds["title"] >= 1, rounds
    kinds = [{p.kind for p, _, _ in sh.placed} for sh in v_engine.sheets]
    assert "legend" in next(k for k in kinds if "positions" in k)
