"""The course's kinetostatics sheet as a department signs it: the positions drawn alike (one
standard scale for the mechanism, one for the free bodies), the title block's Scale cell the
mechanism's, the position blocks packed without empty bands, and the force polygons drawn at
round μF true to the reactions the analysis solved."""

from __future__ import annotations

import math
import re
from pathlib import Path

import pytest

from drawings import draw
from drawings.paper.sheet import GAP
from plans import solve

ROOT = Path(__file__).resolve().parents[1]
#: Samples whose kinetostatics sheet shows a dead centre beside another position, and one
#: with friction (its two positions sharing a sheet at a smaller scale).
NAMES = ["slider_crank", "scotch_yoke", "offset_slider_crank", "shaper_friction"]


@pytest.fixture(scope="module", params=NAMES)
def kinetic(request):
    sol = solve(str(ROOT / "samples" / f"{request.param}.toml"))
    d = draw(sol)
    sheets = [sh for sh in d.sheets if any(p.kind in ("group", "polygon") for p, _, _ in sh.placed)]
    assert sheets, request.param
    return request.param, sol, sheets


def _texts(prims, eid_end: str) -> list[str]:
    return [p.label.plain for p in prims if p.op == "text" and p.eid and p.eid.endswith(eid_end)]


RATIO = re.compile(r"[MМ] (\d+(?:[.,]\d+)?:\d+(?:[.,]\d+)?)")


def test_the_scale_cell_reads_the_mechanism_scale(kinetic):
    """The title block's Scale cell says the scale the schemes of the mechanism say under their
    titles ("M 1:1"), not a dead centre's strip's nor a free body's drawn larger."""
    name, _, sheets = kinetic
    for sh in sheets:
        said = {m.group(1) for p, _, _ in sh.placed if p.kind == "scheme"
                for t in _texts(p.prims, "-scale") for m in [RATIO.search(t)] if m}
        assert len(said) == 1, (name, said)
        cell = _texts(sh.prims, "tb-scale")
        assert cell == [said.pop()], (name, cell)


def test_the_positions_are_drawn_at_one_scale_and_their_free_bodies_at_one(kinetic):
    """Every position's scheme at one GOST 2.302 scale, every free body (groups, initial link)
    at one scale no smaller: a dead centre's strip is not drawn larger than the other position."""
    from drawings.linkage.panels import STANDARD_RATIOS

    name, _, sheets = kinetic
    standard = [1000.0 * r for r in STANDARD_RATIOS]
    schemes = {p.scale for sh in sheets for p, _, _ in sh.placed if p.kind == "scheme"}
    bodies = {p.scale for sh in sheets for p, _, _ in sh.placed if p.kind in ("group", "crank")}
    assert len(schemes) == 1 and len(bodies) == 1, (name, schemes, bodies)
    (mu,), (mb,) = schemes, bodies
    assert any(math.isclose(mu, s, rel_tol=1e-12) for s in standard), mu
    assert any(math.isclose(mb, s, rel_tol=1e-12) for s in standard) and mb >= mu, (mu, mb)


def test_no_empty_band_between_position_blocks(kinetic):
    """A block below another (overlapping it across) starts at most two gaps under it: the spare
    height of a sheet is not spread into empty bands between the positions."""
    name, _, sheets = kinetic
    for sh in sheets:
        boxes = [f.box for f in sh.frames]
        for a in boxes:
            for b in boxes:
                if b[1] < a[3] or not (a[0] < b[2] and b[0] < a[2]):
                    continue  # b not below a, or not across from it
                between = [c for c in boxes if c not in (a, b) and c[1] >= a[3] and c[3] <= b[1]
                           and c[0] < b[2] and b[0] < c[2]]
                if not between:
                    assert b[1] - a[3] <= 2 * GAP + 1e-6, (name, a, b)


def _vectors(panel) -> dict[str, float]:
    """Every vector drawn on a panel: its id -> its length on the paper (mm), from its shaft's
    tail to its head's tip (drawings.paper.common.arrow)."""
    prims = panel.prims
    out = {}
    for i, p in enumerate(prims):
        if p.op == "begin" and "vector" in p.cls.split():
            line = next(q for q in prims[i + 1:] if q.op == "line")
            head = next((q for q in prims[i + 1:i + 4] if q.op == "polygon"), None)
            tip = head.pts[0] if head is not None else line.pts[1]
            out[p.eid] = math.dist(line.pts[0], tip)
    return out


def _round(mu: float) -> bool:
    """μ and 1/μ both 1, 2, 2.5, 4 or 5 × 10^k (a scale a draftsman reads with a ruler)."""
    def ok(x: float) -> bool:
        m = x / 10 ** math.floor(math.log10(x) + 1e-12)
        return any(math.isclose(m, r, rel_tol=1e-9) for r in (1.0, 2.0, 2.5, 4.0, 5.0, 10.0))

    return ok(mu) and ok(1.0 / mu)


def test_the_reactions_read_off_the_drawn_polygons_are_the_solved_ones(kinetic):
    """Each reaction's vector on a drawn force polygon, measured on the paper and divided by
    the polygon's round μF, is the reaction the analysis solved (its magnitude, of a revolute's
    τ and n components too) to a hundredth of a millimetre."""
    from drawings.paper.common import ident, phi_tag

    name, sol, sheets = kinetic
    fa = sol.forces.analysis
    fij = sol.scene.fij
    phis = [float(x) for x in sol.kinematics.phi_deg]
    checked = 0
    for sh in sheets:
        for p, _, _ in sh.placed:
            if p.kind != "polygon":
                continue
            assert _round(p.scale), (p.pid, p.scale)
            k = next(i for i, phi in enumerate(phis) if phi_tag(phi) == p.pid.rsplit("-", 1)[1])
            drawn = _vectors(p)
            exact: dict[str, float] = {}
            for rc in [r for gf in fa.groups for r in gf.reactions] + [fa.crank.frame]:
                n = rc.name(fij)
                exact[n] = abs(complex(rc.F[k]))
                if rc.tau is not None and rc.n is not None:
                    exact[f"{n}^τ"], exact[f"{n}^n"] = abs(float(rc.tau[k])), abs(float(rc.n[k]))
            for label, F in exact.items():
                L = drawn.get(f"{p.pid}-{ident(label)}")
                if L is None:
                    continue
                assert abs(L - F * p.scale) <= 0.01, (name, p.pid, label, L / p.scale, F)
                checked += 1
    assert checked >= 4, (name, checked)


def test_the_scale_cell_is_the_mechanism_s_even_under_a_larger_free_body():
    """A free body drawn at 2:1, larger on the sheet than the two schemes at 1:1 beside it, does
    not make the sheet's scale 2:1; nor does a dead centre's strip at 2:1 wider than the other
    position's scheme when the 1:1 schemes cover more; without a scheme the largest panel's."""
    from drawings.paper.panel_frame import Panel
    from drawings.paper.sheet import sheet_scale

    def panel(kind: str, w: float, h: float, mu: float) -> tuple[Panel, float, float]:
        return Panel(f"{kind}-{w}", kind, 0.0, (), w, h, quantity="length", scale=mu), 0.0, 0.0

    body = panel("group", 500.0, 200.0, 2000.0)
    schemes = [panel("scheme", 400.0, 90.0, 1000.0), panel("scheme", 300.0, 100.0, 1000.0)]
    strip = panel("scheme", 760.0, 45.0, 2000.0)
    assert sheet_scale([body, *schemes], "en") == "1:1"
    assert sheet_scale([body, strip, *schemes], "en") == "1:1"  # 34 200 mm² at 2:1 against 66 000
    assert sheet_scale([body, panel("crank", 100.0, 100.0, 1000.0)], "en") == "2:1"


def test_two_positions_share_a_sheet_at_a_scale_at_most_twice_smaller():
    """The mechanism's scale is lowered (standard scales only, to no less than half the one its
    size asks for) when that takes fewer kinetostatics sheets, the largest such scale kept; a
    layout already one sheet is not made smaller, and none below half is tried."""
    from drawings.linkage.kinetic_scales import fewest
    from drawings.linkage.panels import STANDARD_RATIOS

    tried: list[float] = []

    def lay_at(limit: float):
        def sheets(mu: float) -> list[int]:
            tried.append(mu)
            return [1] if mu <= limit else [1, 2]
        return sheets

    assert fewest(lay_at(300.0), 500.0, STANDARD_RATIOS) == 250.0  # 1:2 -> 1:4, not 1:2.5
    assert fewest(lay_at(400.0), 500.0, STANDARD_RATIOS) == 400.0  # 1:2.5 already one sheet
    tried.clear()
    assert fewest(lay_at(200.0), 500.0, STANDARD_RATIOS) == 500.0  # 1:5 is below half of 1:2
    assert min(tried) == 250.0
    tried.clear()
    assert fewest(lay_at(1000.0), 500.0, STANDARD_RATIOS) == 500.0 and tried == [500.0]


def test_the_friction_shaper_s_two_positions_share_one_kinetostatics_sheet():
    """The shaper with friction: its two positions, each leaving an A1 sheet of its own half
    empty at 1:2, share one at 1:4, that sheet at least two thirds drawn."""
    from drawings.paper.fill import drawn_part

    d = draw(solve(str(ROOT / "samples" / "shaper_friction.toml")))
    sheets = [sh for sh in d.sheets if any(p.kind == "group" for p, _, _ in sh.placed)]
    assert len(sheets) == 1
    assert {p.phi for p, _, _ in sheets[0].placed if p.kind == "scheme"} == {30.0, 180.0}
    assert {p.scale for p, _, _ in sheets[0].placed if p.kind == "scheme"} == {250.0}
    assert drawn_part(sheets[0]) >= 2 / 3


def _laid(part: float):
    """A one-sheet A1 layout covering ``part`` of the field (one panel at the field's top left)."""
    from types import SimpleNamespace

    from drawings.paper.sheet import title_box, usable

    x0, y0, x1, y1 = usable(841.0, 594.0)
    t0, t1, _, _ = title_box(841.0, 594.0)
    field = (x1 - x0) * (y1 - y0) - (x1 - t0) * (y1 - t1)  # the title block's corner of the field
    assert t1 > y0 + part * field / (x1 - x0)  # the panel clear of the title block
    return [[(SimpleNamespace(width=x1 - x0, height=part * field / (x1 - x0)), x0, y0)]]


def test_the_longest_polygons_only_where_the_sheet_is_not_full_without_them():
    """The fits past the plans' (``last``) are laid out only when the sheet is not two thirds
    drawn without them, and then taken where they fill it more."""
    from drawings.linkage.kinetic_scales import kinetic_layout
    from drawings.linkage.larger import fill

    asked: list[tuple[int, ...]] = []

    def lay_at(base: float):
        def lay(fits, mu, mb):  # a position's free bodies, then its lever, each longer fills more
            asked.append(fits)
            return _laid(base + 0.04 * (fits[0] + 1) + 0.02 * (fits[1] + 1))
        return lay

    got = kinetic_layout(lay_at(0.4), 1, 3, 1000.0, (1.0,), True, (841.0, 594.0), last=1)
    assert math.isclose(fill(got[0], (841.0, 594.0)), 0.4 + 0.04 * 4 + 0.02 * 4, rel_tol=1e-9)
    asked.clear()
    got = kinetic_layout(lay_at(0.5), 1, 3, 1000.0, (1.0,), True, (841.0, 594.0), last=1)
    assert fill(got[0], (841.0, 594.0)) >= 2 / 3
    assert asked and all(max(f) < 3 for f in asked)  # full without the last fit: never tried


def test_the_fits_rise_where_the_sheet_gains_most_first():
    """Two positions sharing a sheet: the position whose longer polygons fill it more rises
    first, rather than the first position taking the room the second fills better."""
    from drawings.linkage.kinetic_scales import steepest
    from drawings.linkage.larger import better, fill, score

    size = (841.0, 594.0)

    def lay(fits):  # the first position gains 0.01 a step, the second 0.05; both risen: no room
        if min(fits) >= 0:
            return _laid(0.3) + _laid(0.3)
        return _laid(0.5 + 0.01 * (fits[0] + 1) + 0.05 * (fits[1] + 1))

    choice, got = steepest((-1, -1), 3, lay, lambda a, b: better(a, b, size),
                           lambda s: score(s, size)[1] >= 2 / 3, lambda s: score(s, size))
    assert choice == (-1, 2)
    assert math.isclose(fill(got[0], size), 0.65, rel_tol=1e-9)
