"""The dynamics sheet's diagrams over φ in one column at a round μ_φ written in mm/°: their
φ axes start on one vertical and are equally long, that length the cycle at the written μ_φ,
and an ordinate drawn, read back at the scales written on the sheet, is the solved value."""

from __future__ import annotations

import math
import re
from pathlib import Path

import pytest

import drawings
from drawings.cycle.column import PHI_PANELS
from drawings.cycle.cycle_plot import phi_axis
from plans.kinematics.placing import load_scene
from plans.solution import solve

ROOT = Path(__file__).resolve().parents[1]
SAMPLES = ["dynamics_slider_crank.toml", "flywheel/turning_moment.toml", "v_engine_cycle.toml"]
#: The mantissas of a round scale (mm per unit): 1, 2, 2.5, 4, 5 times a power of ten.
ROUND = (1.0, 2.0, 2.5, 4.0, 5.0)


def _column(path: Path):
    """The placed column of the dynamics sheet: (its primitives on the paper, the scene)."""
    for sh in drawings.draw(path, language="en").sheets:
        for panel, x, y in sh.placed:
            if panel.pid == "dyn-column":
                return [p.moved(x, y) for p in panel.prims]
    raise AssertionError(f"{path.name}: no column of the diagrams over φ")


def _text(prims, eid: str) -> str:
    return next(p.label.plain for p in prims if p.op == "text" and p.eid == eid)


def _scale(text: str, symbol: str, unit: str) -> float:
    m = re.search(rf"{re.escape(symbol)} = (?:[^=;]*= )?([0-9.]+) {re.escape(unit)}", text)
    assert m, (symbol, unit, text)
    return float(m.group(1))


def _axis(prims, pid: str) -> tuple[tuple[float, float], float]:
    """A diagram's φ axis on the paper: the origin (the arrow's shaft starts there) and the
    x of the arrow's tip."""
    k = next(i for i, p in enumerate(prims) if p.op == "begin" and p.eid == f"{pid}-xaxis")
    shaft = prims[k + 1]
    head = next(p for p in prims[k + 1:] if p.op == "polygon")
    return shaft.pts[0], head.pts[0][0]


def _round(x: float) -> bool:
    e = math.floor(math.log10(x))
    return any(math.isclose(x, m * 10.0**e, rel_tol=1e-12) for m in ROUND)


@pytest.fixture(scope="module", params=SAMPLES)
def drawn(request):
    """The sample's drawn column (primitives on the paper) and its solved dynamics."""
    path = ROOT / "samples" / request.param
    d = solve(load_scene(path)).dynamics
    assert d is not None
    return _column(path), d


def test_the_phi_diagrams_share_one_axis_at_a_round_written_scale(drawn):
    prims, d = drawn
    axes = {pid: _axis(prims, pid) for pid in PHI_PANELS}
    (x0, _), tip = axes["dyn-M"]
    for pid, ((x, _), t) in axes.items():
        assert abs(x - x0) < 1e-9 and abs((t - x) - (tip - x0)) < 1e-9, (pid, x, x0, t - x, tip - x0)
    per_deg = _scale(_text(prims, "dyn-M-scale"), "μφ", "mm/°")
    assert _round(per_deg), per_deg
    # the curve of M_пр runs over the whole cycle: from the origin to the cycle at μ_φ
    curve = next(p for p in prims if p.eid == "dyn-M-graphical").pts
    assert curve[0][0] == pytest.approx(x0, abs=1e-9)
    assert curve[-1][0] - x0 == pytest.approx(d.spec.cycle_deg * per_deg, rel=1e-12)


def test_an_ordinate_read_back_at_the_written_scales_is_the_solved_value(drawn):
    prims, d = drawn
    per_deg = _scale(_text(prims, "dyn-M-scale"), "μφ", "mm/°")
    mu_M = _scale(_text(prims, "dyn-M-scale"), "μM", "mm/(N·m)")
    mu_A = _scale(_text(prims, "dyn-A-scale"), "μA", "mm/J")
    phis = d.table.phi_deg
    k = len(phis) // 3  # a position inside the cycle, not at its ends
    for pid, mu, solved in (("dyn-M", mu_M, d.table.M_pr[k]), ("dyn-A", mu_A, d.A_c[k])):
        own = _group(prims, pid)
        (x0, y0), _ = _axis(own, pid)
        x = x0 + (phis[k] - phis[0]) * per_deg  # the vertical through position k
        ys = [p.pts[0][1] for p in own if p.op == "circle" and p.r == 0.5 and abs(p.pts[0][0] - x) < 1e-6]
        assert len(ys) == 1, (pid, x, ys)
        read = (y0 - ys[0]) / mu
        # the scale written to 4 significant digits: the reading as exact as that
        assert read == pytest.approx(solved, rel=1e-3, abs=1e-9), (pid, read, solved)


def _group(prims, pid: str) -> list:
    """The primitives of the panel ``pid``'s own group."""
    start = next(i for i, p in enumerate(prims) if p.op == "begin" and p.eid == pid)
    depth = 0
    for i, p in enumerate(prims[start:], start):
        depth += (p.op == "begin") - (p.op == "end")
        if depth == 0:
            return prims[start:i + 1]
    raise AssertionError(f"{pid}: its group is not closed")


def test_the_round_scale_in_degrees_is_found_and_others_left_in_radians():
    assert phi_axis(360.0 / (2 * math.pi), 360.0) == (360.0, 1.0)
    assert phi_axis(360.0 / (4 * math.pi), 720.0) == (360.0, 0.5)
    length, per_deg = phi_axis(240.0 / (2 * math.pi), 360.0)
    assert per_deg is None and length == pytest.approx(240.0, rel=1e-12)
