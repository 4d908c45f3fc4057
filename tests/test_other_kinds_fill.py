"""The gear, cam and synthesis sheets of every sample drawn over at least two thirds of an A1
sheet's field (inside the frame, less the title block): their figures at the largest round
scales one sheet holds, not left at lengths that leave the sheet two thirds empty."""

from __future__ import annotations

from pathlib import Path

import pytest
import shapely

from drawings import draw
from drawings.paper.sheet import title_box, usable

ROOT = Path(__file__).resolve().parents[1]
KINDS = ("gears", "cams", "synthesis")
SAMPLES = sorted(p for k in KINDS for p in (ROOT / "samples" / k).glob("*.toml"))

#: What an A1 sheet of these kinds still leaves more than a third empty, and why.
NOT_TWO_THIRDS: dict[str, str] = {
    "gears/planetary_2kh": "the train's sheet: its scheme and plans at round scales fill a fifth of it",
    "gears/seed_train": "the meshing at 5:1 and the train below it leave the right half empty",
    "cams/flat_face_poly345": "at A1 (its file asks for A2, drawn over 0.76 of it) the next standard scale of the "
                              "profile, 4:1, leaves no room beside it for the 360 mm φ axis: 0.665 drawn",
}


def covered(sheet) -> float:
    """The union of the placed panels' boxes over the field: the frame's inside less the title
    block (computed here from the sheet's size, not taken from the layout)."""
    field = shapely.box(*usable(sheet.width, sheet.height)).difference(shapely.box(*title_box(sheet.width, sheet.height)))
    boxes = [shapely.box(x, y, x + p.width, y + p.height) for p, x, y in sheet.placed]
    return shapely.union_all(boxes).intersection(field).area / field.area


@pytest.mark.parametrize("path", SAMPLES, ids=lambda p: f"{p.parent.name}-{p.stem}")
def test_a1_sheet_at_least_two_thirds_drawn(path, request):
    key = f"{path.parent.name}/{path.stem}"
    if key in NOT_TWO_THIRDS:
        request.applymarker(pytest.mark.xfail(reason=NOT_TWO_THIRDS[key], strict=True))
    d = draw(path, format="A1")
    fills = [covered(sh) for sh in d.sheets]
    assert all(sh.width == 841 and sh.height == 594 for sh in d.sheets)
    assert min(fills) >= 2 / 3, [round(f, 3) for f in fills]
