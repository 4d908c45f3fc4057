"""Sheets of many positions: packing panels of different crank angles together, the plan of
positions (all positions overlaid), and the legend of line styles."""

from __future__ import annotations

import itertools
import math
import random
from pathlib import Path

import pytest
import shapely

from drawings.linkage import draw as draw_set
from drawings.linkage.overview import positions_panel
from drawings.linkage.panels import Panel, finish, strokes_over_cycle
from drawings.paper.backend import THIN, Recording
from drawings.paper.sheet import GAP, compose, sheet_spec, usable
from plans.errors import InputError
from plans.kinematics.exact import solve
from plans.kinematics.placing import load_scene
from plans.solution import Solution
from tests.locales import in_russian


def draw(source, **kw):
    """The block layout these tests are about: ``[sheet] set = "positions"``, on Russian sheets
    unless the file or the test says otherwise (the default follows the locale: pinned)."""
    return in_russian(draw_set)(source, sheet_set="positions", **kw)


ROOT = Path(__file__).resolve().parents[1]
SAMPLES = ROOT / "samples"
TWELVE = ["slider_crank", "offset_slider_crank", "four_bar", "scotch_yoke", "shaper", "six_bar"]
# sheet counts of the one-band-per-position layout this packing replaced (A1 and A3)
BAND_A1 = {"slider_crank": 6, "offset_slider_crank": 6, "four_bar": 7, "scotch_yoke": 6, "shaper": 12, "six_bar": 12}


@pytest.fixture(scope="module")
def drawings():
    return {name: draw(SAMPLES / f"{name}.toml") for name in TWELVE}


def _scene_with(tmp_path: Path, name: str, extra: str) -> Path:
    p = tmp_path / f"{name}.toml"
    p.write_text((SAMPLES / f"{name}.toml").read_text(encoding="utf-8") + extra, encoding="utf-8")
    return p


# --------------------------------------------------------------------------- packing


@pytest.mark.parametrize("name", TWELVE)
def test_positions_share_sheets(drawings, name):
    d = drawings[name]
    n = len({p.phi for p in d.panels if p.phi is not None})
    assert n == 12
    assert len(d.sheets) <= BAND_A1[name] <= n  # no more sheets than one band per position
    phis_per_sheet = [{p.phi for p, _, _ in sh.placed if p.phi is not None} for sh in d.sheets]
    if BAND_A1[name] < n:  # where a position's band never filled a sheet, blocks share one
        assert any(len(s) >= 2 for s in phis_per_sheet)


def _fill(sh) -> float:
    """The part of a sheet's free paper its panels cover."""
    a = usable(sh.width, sh.height)
    return sum(p.width * p.height for p, _, _ in sh.placed) / ((a[2] - a[0]) * (a[3] - a[1]))


@pytest.mark.parametrize("name", TWELVE)
def test_a1_sheets_are_used_but_the_last(drawings, name):
    """Blocks share sheets: every A1 sheet but the last has at least 0.38 of its paper under
    panels (the plan of positions shares sheet 1 with the first blocks)."""
    fills = [_fill(sh) for sh in drawings[name].sheets]
    assert min(fills[:-1]) >= 0.38, [round(f, 2) for f in fills]
    assert any(p.phi is not None for p, _, _ in drawings[name].sheets[0].placed)


@pytest.mark.parametrize("name", ["v_engine", "six_link"])
def test_plan_of_positions_shares_the_first_sheet(name):
    d = draw(SAMPLES / f"{name}.toml")
    first = d.sheets[0]
    assert first.placed[0][0].kind == "positions"
    assert any(p.phi is not None for p, _, _ in first.placed)  # a position's block beside it
    assert min(_fill(sh) for sh in d.sheets[:-1]) >= 0.38


def _where(d) -> dict[float, set[int]]:
    out: dict[float, set[int]] = {}
    for i, sh in enumerate(d.sheets):
        for p, _x, _y in sh.placed:
            if p.phi is not None:
                out.setdefault(p.phi, set()).add(i)
    return out


@pytest.mark.parametrize("name", TWELVE)
def test_each_position_one_bordered_block_on_one_sheet_in_angle_order(drawings, name):
    """A1: a position's panels all on one sheet inside its own border, under a heading that
    names the position and its angle; the sheets run in angle order, and the plan of
    positions comes first."""
    d = drawings[name]
    where = _where(d)
    phis = sorted(where)
    assert all(len(where[phi]) == 1 for phi in phis), {phi: s for phi, s in where.items() if len(s) > 1}
    firsts = [min(where[phi]) for phi in phis]
    assert firsts == sorted(firsts)
    assert d.sheets[0].placed[0][0].kind == "positions"
    for sh in d.sheets:
        borders = {f.phi: shapely.Polygon(f.outline()) for f in sh.frames}  # round corners, as drawn
        for p, x, y in sh.placed:
            box = shapely.box(x, y, x + p.width, y + p.height)
            if p.phi is None:
                assert all(b.intersection(box).area < 1e-6 for b in borders.values()), p.pid
                continue
            assert borders[p.phi].buffer(1e-6).contains(box), p.pid
            assert all(b.intersection(box).area < 1e-6 for phi, b in borders.items() if phi != p.phi)
        for f in sh.frames:
            k = sorted(where).index(f.phi) + 1  # numbered from 1 ([sheet] first_position)
            assert f.heading.startswith(f"Положение {k}, φ = "), f.heading
        for a, b in itertools.combinations(sh.frames, 2):
            assert borders[a.phi].distance(borders[b.phi]) >= GAP - 1e-6
        tops = [f.box[1] for f in sorted(sh.frames, key=lambda f: f.phi)]
        assert tops == sorted(tops)  # a later position never starts above an earlier one


@pytest.mark.parametrize("name", ["four_bar", "six_bar"])
def test_a3_blocks_split_only_into_consecutive_parts_in_angle_order(name):
    d = draw(SAMPLES / f"{name}.toml", format="A3")
    where = _where(d)
    phis = sorted(where)
    for a, b in zip(phis, phis[1:], strict=False):
        assert max(where[a]) <= min(where[b]), (a, b)
    for phi in phis:
        s = sorted(where[phi])
        assert s == list(range(s[0], s[-1] + 1))
        heads = [f.heading for i in s for f in d.sheets[i].frames if f.phi == phi]
        assert len(heads) >= len(s) and all(h.endswith("(продолжение)") for h in heads[1:])


@pytest.mark.parametrize("name", ["slider_crank", "scotch_yoke"])
def test_a3_first_sheet_is_not_left_to_the_plan_of_positions(name):
    """On A3 the first position's block does not fit whole beside the plan of positions: it
    starts there and continues on the next sheet, instead of leaving sheet 1 nearly empty."""
    d = draw(SAMPLES / f"{name}.toml", format="A3")
    first = d.sheets[0]
    assert first.placed[0][0].kind == "positions"
    assert any(p.phi is not None for p, _, _ in first.placed)
    assert _fill(first) >= 0.38
    for sh in d.sheets:
        _check_sheet(sh)


def _check_sheet(sh) -> None:
    area = shapely.box(*usable(sh.width, sh.height))
    tb = shapely.box(*sh.title_box)
    boxes = {pid: shapely.box(*b) for pid, b in sh.panel_boxes().items()}
    for (a, ga), (b, gb) in itertools.combinations(boxes.items(), 2):
        assert ga.distance(gb) >= GAP - 1e-6, (a, b)
    for pid, g in boxes.items():
        assert area.buffer(1e-6).contains(g), pid
        assert g.distance(tb) >= GAP - 1e-6, pid
    for panel, px, py in sh.placed:  # labels included: every primitive inside its panel's box
        box = shapely.box(px - 1e-6, py - 1e-6, px + panel.width + 1e-6, py + panel.height + 1e-6)
        for p in panel.at(px, py):
            b = p.box()
            if b is not None:
                assert box.contains(shapely.box(*b)), (panel.pid, p.eid)


@pytest.mark.parametrize("name", TWELVE)
def test_packed_sheets_have_no_overlaps_and_stay_in_the_frame(drawings, name):
    for sh in drawings[name].sheets:
        _check_sheet(sh)


@pytest.mark.parametrize("name", TWELVE)
def test_positions_read_top_to_bottom_on_each_sheet(drawings, name):
    """A later crank angle never starts above an earlier one on the same sheet; the panels
    of one angle run over at most two consecutive sheets."""
    d = drawings[name]
    order = sorted({p.phi for p in d.panels if p.phi is not None})
    where: dict[float, list[int]] = {}
    for i, sh in enumerate(d.sheets):
        tops: dict[float, float] = {}
        for p, _x, y in sh.placed:
            if p.phi is not None:
                tops[p.phi] = min(tops.get(p.phi, math.inf), y)
                where.setdefault(p.phi, []).append(i)
        seq = [tops[phi] for phi in order if phi in tops]
        assert all(b >= a - 1e-9 for a, b in zip(seq, seq[1:], strict=False)), (i, seq)
    for phi, sheets in where.items():
        assert max(sheets) - min(sheets) <= 1, phi


def test_packing_is_deterministic():
    a = [s.svg() for s in draw(SAMPLES / "slider_crank.toml").sheets]
    b = [s.svg() for s in draw(SAMPLES / "slider_crank.toml").sheets]
    assert a == b


def _fake(pid: str, phi: float, w: float, h: float) -> Panel:
    rec = Recording()
    rec.polygon([(0, 0), (w, 0), (w, h), (0, h)], THIN)
    return finish(pid, "velocity", phi, rec, pid)


@pytest.mark.parametrize("seed", range(6))
@pytest.mark.parametrize("fmt", ["A1", "A3"])
def test_random_panels_pack_without_overlap(seed, fmt):
    """Random panel sizes (up to a third of the sheet): no overlap, inside the frame, off the
    title block, same input → same layout, and the sheets are not mostly empty."""
    rnd = random.Random(seed)
    spec = sheet_spec({"sheet": {"format": fmt}}, "x.toml")
    W, H = spec.size
    a = usable(W, H)
    panels = [_fake(f"p{i}", float(i // 5), rnd.uniform(15, (a[2] - a[0]) / 3), rnd.uniform(12, (a[3] - a[1]) / 3))
              for i in range(40)]
    sheets = compose(panels, spec)
    for sh in sheets:
        _check_sheet(sh)
    assert sorted(p.pid for sh in sheets for p, _, _ in sh.placed) == sorted(p.pid for p in panels)
    again = compose(panels, spec)
    assert [sh.panel_boxes() for sh in sheets] == [sh.panel_boxes() for sh in again]
    used = sum(p.width * p.height for p in panels)
    free = (a[2] - a[0]) * (a[3] - a[1])
    # whole bordered blocks in angle order: on A3 a block of five panels of up to a third of
    # the sheet each way often needs most of a sheet, so less paper can be used there
    assert used / (len(sheets) * free) > (0.4 if fmt == "A1" else 0.3)


def test_a_block_runs_round_the_title_blocks_corner_rather_than_take_another_sheet():
    """A position too tall for the room above the title block and too wide for the column
    beside it: with ``corner`` it takes all the room below the previous one, its border an L
    round the title block (its panels inside the border, clear of the title block), where
    without it goes on a second sheet."""
    spec = sheet_spec({"sheet": {"format": "A1"}}, "x.toml")
    W, H = spec.size
    a = usable(W, H)
    aw = a[2] - a[0]
    panels = [_fake("top", 0.0, aw - 20, 130), _fake("wide", 30.0, aw - 20, 200), _fake("under", 30.0, 500, 150)]
    assert len(compose(panels, spec)) == 2
    sheets = compose(panels, spec, corners=True)
    assert len(sheets) == 1
    sh = sheets[0]
    _check_sheet(sh)
    framed = {f.phi: f for f in sh.frames}
    tb = shapely.box(*sh.title_box)
    border = shapely.Polygon(framed[30.0].outline())
    assert framed[30.0].notch is not None and framed[0.0].notch is None
    assert border.buffer(-1e-6).disjoint(tb)  # the border goes round the title block
    assert border.area < shapely.box(*framed[30.0].box).area  # an L, not the whole box
    for pid in ("wide", "under"):
        assert border.contains(shapely.box(*sh.panel_boxes()[pid])), pid
    assert sh.panel_boxes()["under"][3] > sh.title_box[1]  # beside the title block, below its top


def test_legend_sits_above_the_title_block(drawings):
    sh = drawings["slider_crank"].sheets[0]
    box = sh.panel_boxes()["legend"]
    tb = sh.title_box
    assert box[3] <= tb[1] and box[2] >= tb[0]  # over the title block, right-aligned to the frame


# --------------------------------------------------------------------------- the plan of positions


@pytest.fixture(scope="module")
def slider_positions():
    scene = load_scene(SAMPLES / "slider_crank.toml")
    kin = solve(scene)
    mu_l = 400.0
    sol = Solution(scene)
    return scene, kin, mu_l, positions_panel(sol, mu_l, "ru", [0, 1], strokes_over_cycle(sol))


def test_positions_panel_one_polyline_per_position(slider_positions):
    _scene, kin, _mu, panel = slider_positions
    lines = [p for p in panel.prims if p.op == "polyline" and p.eid.startswith("positions-pos-")]
    assert sorted(p.eid for p in lines) == sorted(f"positions-pos-{k}" for k in range(kin.n))
    widths = {int(p.eid.rsplit("-", 1)[1]): p.style.width for p in lines}
    assert widths[0] == widths[1] > widths[2]  # the positions with plans are bold
    assert len({widths[k] for k in range(2, kin.n)}) == 1


def test_positions_panel_points_are_where_the_closed_form_puts_them(slider_positions):
    """The polyline of position k passes through A_k and B_k of x_B = r cos φ + √(l² − r² sin² φ)."""
    scene, kin, mu_l, panel = slider_positions
    r = abs(scene.links[1].points["A"] - scene.links[1].points["O"])
    l_ = abs(scene.links[2].points["B"] - scene.links[2].points["A"])
    pivot = next(p for p in panel.prims if p.eid == "positions-joint-O").pts[0]
    for k in range(kin.n):
        phi = math.radians(float(kin.phi_deg[k]))  # phi_ref = 0, the line of stroke along x
        A = (pivot[0] + mu_l * r * math.cos(phi), pivot[1] - mu_l * r * math.sin(phi))
        B = (pivot[0] + mu_l * (r * math.cos(phi) + math.sqrt(l_**2 - (r * math.sin(phi)) ** 2)), pivot[1])
        line = next(p for p in panel.prims if p.op == "polyline" and p.eid == f"positions-pos-{k}")
        for q in (pivot, A, B) if k in (0, 1) else (pivot, A):  # links only where bold
            assert min(math.dist(q, v) for v in line.pts) < 1e-6, (k, q)
        if k not in (0, 1):
            assert len(line.pts) == 2  # the crank alone
        marks = [
            p.pts[0] for p in panel.prims if p.op == "circle" and p.style is not None and p.style.cls == "mark"]
        assert min(math.dist(B, m) for m in marks) < 1e-6, k  # B_k still marked on its axis


def test_plan_of_positions_links_only_at_bold_positions():
    """four_bar: the coupler triangle at the bold positions only; B and E on trajectories."""
    scene = load_scene(SAMPLES / "four_bar.toml")
    kin = solve(scene)
    sol = Solution(scene)
    panel = positions_panel(sol, 500.0, "ru", [0], strokes_over_cycle(sol))
    lines = {p.eid: p for p in panel.prims if p.op == "polyline" and p.eid.startswith("positions-pos-")}
    assert len(lines["positions-pos-0"].pts) > 2
    assert all(len(lines[f"positions-pos-{k}"].pts) == 2 for k in range(1, kin.n))
    assert "positions-path-B" in {p.eid for p in panel.prims}


def test_positions_panel_numbers_every_position(slider_positions):
    _scene, kin, _mu, panel = slider_positions
    texts = [p for p in panel.prims if p.op == "text" and p.eid.startswith("positions-n-")]

    def numbers(point: str) -> list[list[str]]:
        return [p.label.plain.replace(point, "").split(", ") for p in texts if p.eid.startswith(f"positions-n-{point}-")]

    a, b = numbers("A"), numbers("B")  # numbered from 1 by default ([sheet] first_position)
    assert sorted(int(x) for g in a for x in g) == list(range(1, kin.n + 1))
    assert len(a) == kin.n  # the crank pin never repeats a place
    assert sorted(int(x) for g in b for x in g) == list(range(1, kin.n + 1))
    assert len(b) == kin.n // 2 + 1  # a centred slider-crank: B_k = B_{14-k}
    assert ["2", "12"] in b and ["1"] in b
    plain = {p.label.plain for p in texts}
    assert "A1" in plain and "B1" in plain  # the letter once, at the first position
    boxes = [shapely.box(*p.label.box) for p in panel.prims if p.op == "text"]
    assert not [(i, j) for (i, x), (j, y) in itertools.combinations(enumerate(boxes), 2)
                if x.intersection(y).area > 0.01]


def test_positions_panel_traces_the_centre_of_mass(slider_positions):
    scene, kin, mu_l, panel = slider_positions
    curve = next(p for p in panel.prims if p.op == "polyline" and p.eid == "positions-trace-S2")
    pivot = next(p for p in panel.prims if p.eid == "positions-joint-O").pts[0]
    seg = shapely.LineString(curve.pts)
    for k in range(kin.n):
        s = complex(kin.point("S2")[0][k])
        q = shapely.Point(pivot[0] + mu_l * s.real, pivot[1] - mu_l * s.imag)
        assert seg.distance(q) < 0.05, k  # S2 at every position lies on its traced path (mm)


def test_schemes_only_for_the_first_two_positions_by_default(drawings):
    d = drawings["slider_crank"]
    kinds = [p.kind for p in d.panels]
    assert kinds.count("positions") == 1 and kinds.count("legend") == 1
    assert [p.phi for p in d.panels if p.kind == "scheme"] == [0.0, 30.0]
    assert len({p.phi for p in d.panels if p.kind == "velocity"}) == 12  # plans still at every position


def test_listed_positions_get_schemes_plans_and_bold_lines(tmp_path):
    p = _scene_with(tmp_path, "slider_crank", '\n[sheet]\nformat = "A1"\npositions = [90, 210]\ntrace = ["S2", "B"]\n')
    d = draw(p)
    assert [q.phi for q in d.panels if q.kind == "scheme"] == [90.0, 210.0]
    assert {q.phi for q in d.panels if q.kind not in ("positions", "legend")} == {90.0, 210.0}
    pos = next(q for q in d.panels if q.kind == "positions")
    bold = sorted(int(q.eid.rsplit("-", 1)[1]) for q in pos.prims if q.op == "polyline"
                  and q.eid.startswith("positions-pos-") and q.style.width > 0.5)
    assert bold == [3, 7]
    assert {q.eid for q in pos.prims if q.eid.startswith("positions-trace-")} == {"positions-trace-S2",
                                                                                 "positions-trace-B"}
    assert len(d.sheets) == 1


def test_no_plan_of_positions_for_a_single_position(tmp_path):
    p = tmp_path / "one.toml"
    p.write_text((SAMPLES / "v_engine.toml").read_text(encoding="utf-8").replace("phi_deg = [45, 0]", "phi_deg = [45]"),
                 encoding="utf-8")
    kinds = {q.kind for q in draw(p).panels}
    assert "positions" not in kinds and "scheme" in kinds


def test_plan_of_positions_can_be_left_out(tmp_path):
    p = _scene_with(tmp_path, "slider_crank", '\n[sheet]\npanels = ["scheme", "velocity"]\n')
    d = draw(p)
    assert {q.kind for q in d.panels} == {"scheme", "velocity"}
    assert len([q for q in d.panels if q.kind == "scheme"]) == 12  # no overlay: a scheme at every position


def test_unknown_trace_point(tmp_path):
    p = _scene_with(tmp_path, "slider_crank", '\n[sheet]\ntrace = ["S9"]\n')
    with pytest.raises(InputError, match=r"sheet.trace: no point 'S9'"):
        draw(p)


def test_legend_in_the_sheets_language(tmp_path):
    ru = next(q for q in draw(SAMPLES / "shaper.toml").panels if q.kind == "legend")
    en = next(q for q in draw(SAMPLES / "shaper.toml", language="en").panels if q.kind == "legend")
    t_ru = {q.label.plain for q in ru.prims if q.op == "text"}
    t_en = {q.label.plain for q in en.prims if q.op == "text"}
    assert "Условные обозначения" in t_ru and "Legend" in t_en
    assert any("Кориолиса" in t for t in t_ru) and any("Coriolis" in t for t in t_en)  # the shaper's RPR
    assert any("замыкающая" in t for t in t_ru) and any("closing" in t for t in t_en)
    assert not any("Coriolis" in q.label.plain for q in next(
        x for x in draw(SAMPLES / "slider_crank.toml", language="en").panels if x.kind == "legend").prims
        if q.op == "text")


def test_plans_are_smaller_on_smaller_sheets(tmp_path):
    """A3 draws every plan, polygon and lever at a round scale no larger than A1's, each
    plan's longest vector within the A1 target times √(420/841) (about 106 mm)."""
    from plans.kinematics.scales import LONGEST_MM, is_round

    path = _scene_with(tmp_path, "six_bar", "")
    text = path.read_text(encoding="utf-8")
    path.write_text(text.replace("[sheet]", "[sheet]\npositions = [30, 240]") if "[sheet]" in text
                    else text + "\n[sheet]\npositions = [30, 240]\n", encoding="utf-8")
    by = {}
    for fmt in ("A1", "A3"):
        d = draw(path, format=fmt)
        by[fmt] = {p.pid: p for p in d.panels if p.kind in ("velocity", "acceleration", "polygon", "lever")}
    assert set(by["A1"]) == set(by["A3"]) and by["A1"]
    smaller = 0
    for pid, p1 in by["A1"].items():
        p3 = by["A3"][pid]
        assert p1.scale is not None and p3.scale is not None and is_round(p1.scale) and is_round(p3.scale)
        assert p3.scale <= p1.scale * (1 + 1e-12), pid
        smaller += p3.scale < p1.scale
    assert smaller >= len(by["A1"]) // 2  # most of them get smaller, not just the same
    from drawings.linkage import fit_for

    fit = fit_for(sheet_spec({"sheet": {"format": "A3"}}, str(path)))
    for pp in Solution(load_scene(path), fit).plans:
        for plan in (pp.velocity, pp.acceleration):
            assert plan.extent <= LONGEST_MM * math.sqrt(420 / 841) + 1e-9


def _cell(sh, eid: str) -> str:
    return next(p.label.plain for p in sh.prims if p.eid == eid and p.label is not None)


def test_scale_cell_is_the_scale_of_the_sheets_main_image(drawings):
    """GOST 2.104: the "Scale" cell holds the scale of the sheet's main image, written as
    GOST 2.302 writes it: the shaper's plan of positions is drawn at μl = 500 mm/m (1:2),
    its schemes and groups at 400 mm/m (1:2,5, a decimal comma on a Russian sheet)."""
    d = drawings["shaper"]
    assert next(p for p in d.panels if p.kind == "positions").scale == 500.0
    assert {p.scale for p in d.panels if p.kind in ("scheme", "group", "crank")} == {400.0}
    assert _cell(d.sheets[0], "tb-scale") == "1:2"
    assert {_cell(sh, "tb-scale") for sh in d.sheets[1:]} == {"1:2,5"}


def test_scale_cell_is_a_dash_without_a_length_scale():
    d = draw(SAMPLES / "v_engine_cycle.toml")
    last = d.sheets[-1]
    assert not any(p.quantity == "length" for p, _, _ in last.placed)
    assert _cell(last, "tb-scale") == "—"
