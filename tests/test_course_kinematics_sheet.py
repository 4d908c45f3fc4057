"""The course's kinematics sheets with kinematic diagrams: each point's diagrams one under
another with their φ axes from one vertical, as a course draws them, and the sheets at least
two thirds drawn where the diagrams' φ axis and the acceleration plans could grow."""

from __future__ import annotations

from pathlib import Path

import pytest

import drawings
from drawings.cycle.column import axis_origin
from drawings.paper.fill import drawn_part
from tests.locales import in_russian

ROOT = Path(__file__).resolve().parents[1]
PROJECT = ROOT / "samples" / "projects" / "v_engine_project.toml"
#: The kinds of panel a kinematics sheet holds.
KINEMATIC = {"positions", "velocity", "acceleration", "diagram", "cycle-table", "legend"}


@pytest.fixture(scope="module")
def kinematics_sheets(tmp_path_factory):
    text = PROJECT.read_text(encoding="utf-8")
    assert ', "dynamics"]' in text
    path = tmp_path_factory.mktemp("project") / PROJECT.name  # its linkage's sheets only: no dynamics
    path.write_text(text.replace(', "dynamics"]', "]"), encoding="utf-8")
    d = in_russian(drawings.draw)(path)
    sheets = [sh for sh in d.sheets if not any(p.pid.startswith("dyn-") for p, _, _ in sh.placed)
              and {p.kind for p, _, _ in sh.placed} <= KINEMATIC]
    assert len(sheets) == 2  # the plan of positions with the velocity plans; the acceleration plans
    return sheets


def test_kinematics_sheets_at_least_two_thirds_drawn(kinematics_sheets):
    fills = [drawn_part(sh) for sh in kinematics_sheets]
    assert min(fills) >= 2 / 3, [round(f, 3) for f in fills]


def test_a_points_diagrams_stand_one_under_another_on_one_vertical(kinematics_sheets):
    columns = 0
    for sh in kinematics_sheets:
        by_point: dict[str, list[tuple[float, float, float, float, float]]] = {}
        for p, x, y in sh.placed:
            if p.kind == "diagram":
                ox, _ = axis_origin(p)  # read off the drawn φ axis
                by_point.setdefault(p.pid.split("_", 1)[1], []).append((x + ox, x, y, x + p.width, y + p.height))
        for point, ds in by_point.items():
            if len(ds) < 2:
                continue
            columns += 1
            assert max(d[0] for d in ds) - min(d[0] for d in ds) < 0.01, (point, ds)  # one vertical
            ds.sort(key=lambda d: d[2])
            for upper, lower in zip(ds, ds[1:], strict=False):
                assert upper[4] <= lower[2] < upper[4] + 10.0, (point, ds)  # the next just below
            box = (min(d[1] for d in ds), ds[0][2], max(d[3] for d in ds), ds[-1][4])
            for p, x, y in sh.placed:  # nothing else inside the column
                if not p.pid.endswith(f"_{point}"):
                    assert not (x < box[2] and box[0] < x + p.width and y < box[3] and box[1] < y + p.height), p.pid
    assert columns >= 2  # B's and C's diagrams
