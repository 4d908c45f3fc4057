"""The gear, cam and synthesis sheets of every sample drawn over at least two thirds of an A1
sheet's field (inside the frame, less the title block): their figures at the largest round
scales one sheet holds, not left at lengths that leave the sheet two thirds empty."""

from __future__ import annotations

from pathlib import Path

import pytest

from drawings import draw
from drawings.paper.fill import drawn_part
from tests.locales import in_russian

#: The sheets these tests measure were drawn in Russian, the default before it followed the locale.
draw = in_russian(draw)

ROOT = Path(__file__).resolve().parents[1]
KINDS = ("gears", "cams", "synthesis")
SAMPLES = sorted(p for k in KINDS for p in (ROOT / "samples" / k).glob("*.toml"))


@pytest.mark.parametrize("path", SAMPLES, ids=lambda p: f"{p.parent.name}-{p.stem}")
def test_a1_sheet_at_least_two_thirds_drawn(path):
    d = draw(path, format="A1")
    fills = [drawn_part(sh) for sh in d.sheets]
    assert all(sh.width == 841 and sh.height == 594 for sh in d.sheets)
    assert min(fills) >= 2 / 3, [round(f, 3) for f in fills]


@pytest.mark.parametrize("path", sorted((ROOT / "samples" / "synthesis").glob("*.toml")), ids=lambda p: p.stem)
def test_synthesis_strokes_read_off_the_turn_are_180_plus_and_minus_theta(path):
    """The working and the return strokes' angles written on the travel diagram are
    180° ± θ, θ = 180°·(K − 1)/(K + 1) from the task's K (not from the design)."""
    import tomllib

    K = float(tomllib.loads(path.read_text(encoding="utf-8")).get("K", 1.0))
    theta = 180.0 * (K - 1.0) / (K + 1.0)
    d = draw(path, format="A1", language="en")
    motion = next(p for p in d.panels if p.pid == "output-motion")
    said = {q.eid: q.label.plain for q in motion.prims if q.op == "text" and q.eid.startswith("stroke-")}
    assert float(said["stroke-working"].split()[-1].rstrip("°")) == pytest.approx(180.0 + theta, abs=6e-3)
    assert float(said["stroke-return"].split()[-1].rstrip("°")) == pytest.approx(180.0 - theta, abs=6e-3)


def test_specific_sliding_drawn_reaches_the_pairs_greatest_at_b1_and_b2():
    """λ1 at B1 and λ2 at B2 of the diagram's formula are the pair's greatest specific sliding
    (plans.gears.geometry's own), and the drawn curves pass through them."""
    import numpy as np

    from drawings.gears_sliding import sliding
    from plans.gears.solution import solve_file

    for name in ("planetary_2kh", "seed_train"):
        gs = solve_file(ROOT / "samples" / "gears" / f"{name}.toml")
        for mg in gs.meshings:
            p = mg.pair
            u = p.wheels[1].z / p.wheels[0].z
            l1, _ = sliding(np.array([p.rho_start]), p.g, u, p.internal)
            _, l2 = sliding(np.array([p.rho_end]), p.g, u, p.internal)
            assert abs(l1[0]) == pytest.approx(p.sliding[0], rel=1e-12)
            assert abs(l2[0]) == pytest.approx(p.sliding[1], rel=1e-12)


def test_flat_face_convexity_curve_touches_minus_r0_min():
    """A flat face's s + s″ drawn over the turn reaches down to the line −r0 min (the base
    radius the solver found on its own finer grid) and no lower."""
    d = draw(ROOT / "samples" / "cams" / "flat_face_poly345.toml", format="A1")
    panel = next(p for p in d.panels if p.pid == "convexity")
    curve = [q for q in panel.prims if q.op == "polyline" and q.eid == "s-plus-s2"][0]
    line = [q for q in panel.prims if q.op == "line" and q.eid == "r0-min"][0]
    lowest = max(y for _, y in curve.pts)  # paper y grows downward
    assert lowest == pytest.approx(line.pts[0][1], abs=0.05)


def test_bisected_chains_find_what_laying_out_every_candidate_finds():
    """fullest_of_chains, bisecting each chain of ever larger drawings, ends on the same sheet
    as laying out every candidate (fullest_on_one_sheet): figures that outgrow the sheet
    part-way along each chain."""
    from drawings.linkage.panels import finish
    from drawings.paper.backend import THIN, Recording
    from drawings.paper.fill import fullest_of_chains, fullest_on_one_sheet
    from drawings.paper.sheet import sheet_spec

    def box(pid: str, w: float, h: float):
        rec = Recording()
        rec.polyline([(0, 0), (w, 0), (w, h), (0, h), (0, 0)], THIN, pid)
        return finish(pid, "cam-diagram", None, rec, pid)

    spec = sheet_spec({}, "<test>", "test", format="A1", language="en")
    left = box("left", 300, 250)
    chains = [[[left, box("right", w, h), box("low", 380, low)] for h in range(100, 700, 40)]
              for w in (420, 480) for low in (120, 200)]
    flat = [c for chain in chains for c in chain]
    cut = fullest_of_chains([chains], spec, "<test>", lambda ps: None)
    every = fullest_on_one_sheet([flat], spec, "<test>", lambda ps: None)
    assert cut is not None and every is not None
    assert [(p.pid, p.width, p.height) for p in cut[0]] == [(p.pid, p.width, p.height) for p in every[0]]
    assert drawn_part(cut[1][0]) == pytest.approx(drawn_part(every[1][0]), abs=1e-12)
