"""The instant-centre panels: the scheme carries every centre at its place at μl, and the
circle diagram has one edge per centre found, solid at a pair, dashed by Kennedy."""

from __future__ import annotations

import math
from pathlib import Path

import pytest

import plans
from drawings.linkage import build_panels
from drawings.paper.sheet import sheet_spec
from plans.kinematics.centres import centres_at
from plans.kinematics.exact import solve
from plans.kinematics.placing import load_scene

SAMPLES = Path(__file__).resolve().parent.parent / "samples" / "centres"


def _panels(name: str, phi: float):
    path = SAMPLES / f"{name}.toml"
    spec = sheet_spec({"sheet": {"positions": [phi], "panels": ["scheme", "centres"]}}, str(path))
    panels, mu_l = build_panels(plans.solve(path, fit=spec.fit), spec)
    return {p.kind: p for p in panels}, mu_l


@pytest.mark.parametrize("name", ["four_bar", "six_bar"])
def test_centres_drawn_at_their_places_and_the_circle_diagram(name: str) -> None:
    panels, mu_l = _panels(name, 30.0)
    scene = load_scene(SAMPLES / f"{name}.toml")
    kin = solve(scene, phi_deg=[30.0], order=1)
    centres = centres_at(kin, 0)
    marks = {p.eid: p.pts[0] for p in panels["centres"].prims if p.op == "circle" and "-ic-" in p.eid}
    drawn = {eid.rsplit("-ic-", 1)[1]: xy for eid, xy in marks.items()}
    finite = [c for c in centres.values() if c.point is not None and c.label in drawn]
    assert len(finite) >= 4
    a, b = finite[0], finite[-1]  # paper distance = μl · world distance
    d_paper = math.dist(drawn[a.label], drawn[b.label])
    assert abs(d_paper - mu_l * abs(a.point - b.point)) < 1e-6
    edges = [p for p in panels["circle-diagram"].prims if p.op == "line" and "-edge-" in p.eid]
    found = [c for c in centres.values() if c.point is not None or c.direction is not None]
    assert len(edges) == len(found)
    dashed = [e for e in edges if e.style.dash]
    assert len(dashed) == sum(1 for c in found if c.source != "pair")
    arrows = [p for p in panels["centres"].prims if p.op == "begin" and p.cls == "instant-centre-direction"]
    assert len(arrows) == 2 * sum(1 for c in centres.values() if c.direction is not None)


def test_same_scene_same_panels() -> None:
    p1, _ = _panels("slider_crank", 30.0)
    p2, _ = _panels("slider_crank", 30.0)
    assert p1["centres"].svg() == p2["centres"].svg()


def test_velocity_table_reads_the_arm_on_the_scheme() -> None:
    """The row of v_B: the arm |P_jf B| in mm at μl, the velocity ω_j·|P_jf B| next to the exact one."""
    panels, mu_l = _panels("four_bar", 30.0)
    table = panels["table"]
    assert table.pid.startswith("centre-table-")
    assert table.title.startswith("Скорости по мгновенным центрам") or table.title.startswith("Velocities by")
    rows = [p.eid for p in table.prims if p.op == "begin" and p.eid.startswith(f"{table.pid}-row-")]
    scene = load_scene(SAMPLES / "four_bar.toml")
    kin = solve(scene, phi_deg=[30.0], order=1)
    moving = [nm for nm in kin.point_names() if kin.home(nm) != scene.frame]
    assert len(rows) == len(moving)
