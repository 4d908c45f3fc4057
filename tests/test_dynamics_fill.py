"""The A1 sheets of the flywheel, engine-balancing and whole-project samples (the folders
beside the top-level samples) drawn over at least two thirds of their field: inside the
frame, less the title block, the union of the placed panels' boxes."""

from __future__ import annotations

from pathlib import Path

import pytest

import drawings
from drawings.paper.fill import drawn_part
from tests.locales import in_russian

ROOT = Path(__file__).resolve().parents[1]
SAMPLES = sorted(p for folder in ("flywheel", "engines", "projects") for p in (ROOT / "samples" / folder).glob("*.toml"))


@pytest.mark.parametrize("path", SAMPLES, ids=[p.stem for p in SAMPLES])
def test_no_a1_sheet_of_a_subfolder_sample_is_more_than_a_third_empty(path):
    d = in_russian(drawings.draw)(path)  # the figures measured on Russian sheets
    sheets = d.sheets
    assert all(sh.spec.format == "A1" for sh in sheets)
    fills = [drawn_part(sh) for sh in sheets]
    assert min(fills) >= 2 / 3, [round(f, 2) for f in fills]


def test_the_folders_hold_samples():
    assert {p.parent.name for p in SAMPLES} == {"flywheel", "engines", "projects"}
