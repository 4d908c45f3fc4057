"""Every sample draws in every format; a structural golden file per sample."""

from __future__ import annotations

import json
import os
import re
import xml.etree.ElementTree as ET
from collections import Counter
from io import BytesIO
from pathlib import Path

import pytest

from drawings.linkage import draw
from drawings.paper.export import save
from drawings.paper.fill import drawn_part
from tests.locales import in_russian

#: The sheets these tests measure were drawn in Russian, the default before it followed the locale.
draw = in_russian(draw)

ROOT = Path(__file__).resolve().parents[1]
SAMPLES = sorted((ROOT / "samples").glob("*.toml"))
GOLDEN = Path(__file__).resolve().parent / "golden" / "drawings"
SVG = "{http://www.w3.org/2000/svg}"
PT_PER_MM = 72.0 / 25.4
DPI = 12  # tiny PNGs: the size is what is checked


@pytest.fixture(scope="module", params=SAMPLES, ids=[p.stem for p in SAMPLES])
def drawn(request, tmp_path_factory):
    out = tmp_path_factory.mktemp(request.param.stem)
    d = draw(request.param)
    files = save(d.sheets, out, request.param.stem, ("svg", "pdf", "png"), dpi=DPI)
    return request.param, d, files


def _structure(d) -> dict:
    """What the golden file pins: sheets, panels on each, element counts per panel."""
    sheets = []
    for sh in d.sheets:
        root = ET.fromstring(sh.svg())
        panels = {}
        for g in root.iter(f"{SVG}g"):
            cls = g.get("class", "").split()
            if cls[:1] != ["panel"]:
                continue
            counts = Counter(el.tag.replace(SVG, "") for el in g.iter())
            vectors = sorted(x.get("id") for x in g.iter(f"{SVG}g") if x.get("class", "").split()[:1] == ["vector"])
            panels[g.get("id")] = {"kind": cls[1], "elements": dict(sorted(counts.items())), "vectors": vectors}
        sheets.append({"format": f"{sh.width:g}x{sh.height:g}", "panels": panels})
    return {"sheets": sheets}


def test_every_format_written(drawn):
    path, d, files = drawn
    names = sorted(p.name for p in files)
    n = len(d.sheets)
    stems = [path.stem] if n == 1 else [f"{path.stem}-{i}" for i in range(1, n + 1)]
    assert names == sorted(f"{s}.{e}" for s in stems for e in ("svg", "pdf", "png"))
    assert not [p for p in files[0].parent.iterdir() if p.name.startswith(".")]  # no temporary files left


def test_pdf_page_is_the_sheet_in_points(drawn):
    _, d, files = drawn
    for p in files:
        if p.suffix != ".pdf":
            continue
        data = p.read_bytes()
        assert data.startswith(b"%PDF")
        m = re.search(rb"/MediaBox\s*\[\s*0 0 ([\d.]+) ([\d.]+)\s*\]", data)
        assert m, p
        sh = d.sheets[0]
        assert float(m.group(1)) == pytest.approx(sh.width * PT_PER_MM, abs=0.01)
        assert float(m.group(2)) == pytest.approx(sh.height * PT_PER_MM, abs=0.01)


def test_png_pixel_size(drawn):
    from PIL import Image

    _, d, files = drawn
    sh = d.sheets[0]
    for p in files:
        if p.suffix == ".png":
            w, h = Image.open(BytesIO(p.read_bytes())).size
            assert abs(w - sh.width / 25.4 * DPI) <= 1 and abs(h - sh.height / 25.4 * DPI) <= 1


def test_svg_well_formed_and_valid(drawn):
    _, d, files = drawn
    for p in files:
        if p.suffix == ".svg":
            root = ET.fromstring(p.read_bytes())
            assert root.tag == f"{SVG}svg" and root.get("width").endswith("mm")
    d.sheets[0].svg(debug=True)  # svgwrite's validator


def test_no_overlaps_in_any_sample(drawn):
    import itertools

    import shapely

    _, d, _ = drawn
    for sh in d.sheets:
        boxes = [shapely.box(*b) for b in sh.panel_boxes().values()]
        for a, b in itertools.combinations(boxes, 2):
            assert not a.intersects(b)
        frame = shapely.box(*sh.frame_box)
        assert all(frame.contains(b) for b in boxes)
    for panel in d.panels:
        texts = [shapely.box(*b) for b in panel.text_boxes()]
        bad = [(i, j) for (i, a), (j, b) in itertools.combinations(enumerate(texts), 2)
               if a.intersection(b).area > 0.01]
        assert not bad, panel.pid


def _segments(prims):
    from drawings.paper.backend import arc_points

    for p in prims:
        if p.op in ("line", "polyline"):
            pts = list(p.pts)
        elif p.op == "polygon":
            pts = list(p.pts) + list(p.pts[:1])
        elif p.op == "circle":
            pts = arc_points(p.pts[0], p.r, 0.0, 2 * 3.141592653589793, 48)
        elif p.op == "arc":
            pts = arc_points(p.pts[0], p.r, p.a0, p.a1, 48)
        else:
            continue
        if len(pts) >= 2:
            yield p, pts


def test_no_label_crossed_by_a_line_or_arrow_in_any_sample(drawn):
    """Every label of every panel (every position) clear of every line, arrow head, circle and
    arc of its panel (a line grazing the box by under 0.25 mm aside), checked with shapely."""
    import shapely

    _, d, _ = drawn
    bad = []
    for panel in d.panels:
        lines = [(p, shapely.LineString(pts)) for p, pts in _segments(panel.prims)]
        tree = shapely.STRtree([g for _, g in lines])
        for t in panel.prims:
            if t.op != "text" or t.label is None:
                continue
            b = t.label.box
            if b[2] - b[0] <= 0.5 or b[3] - b[1] <= 0.5:
                continue
            box = shapely.box(b[0] + 0.25, b[1] + 0.25, b[2] - 0.25, b[3] - 0.25)
            for i in tree.query(box, predicate="intersects"):
                bad.append((panel.pid, t.eid, lines[int(i)][0].eid or lines[int(i)][0].op))
    assert not bad, bad[:10]


def test_structure_matches_golden(drawn):
    path, d, _ = drawn
    got = _structure(d)
    golden = GOLDEN / f"{path.stem}.json"
    if os.environ.get("PLANS_UPDATE_GOLDEN") or not golden.exists():
        if not os.environ.get("PLANS_UPDATE_GOLDEN"):
            pytest.fail(f"no golden file {golden}; run with PLANS_UPDATE_GOLDEN=1 to write it")
        golden.parent.mkdir(parents=True, exist_ok=True)
        golden.write_text(json.dumps(got, indent=1, ensure_ascii=False) + "\n", encoding="utf-8")
    want = json.loads(golden.read_text(encoding="utf-8"))
    assert [len(s["panels"]) for s in got["sheets"]] == [len(s["panels"]) for s in want["sheets"]]
    assert got == want


def test_no_numerical_dust_on_the_sheets(drawn):
    """Values zero up to round-off are written 0 on the sheets: no number in e-notation below
    1e-12 (1e-9 of the smallest scale of these samples), and no scale derived from a zero vector."""
    _, d, _ = drawn
    dust = re.compile(r"\d(?:[.,]\d+)?[eE]-(?:1[2-9]|[2-9]\d)")
    for sh in d.sheets:
        for p in sh.prims:
            if p.op == "text" and p.label is not None:
                assert not dust.search(p.label.plain), (p.eid, p.label.plain)
    for panel in d.panels:
        if panel.scale is not None:
            assert 1e-6 < panel.scale < 1e6, (panel.pid, panel.scale)


def test_no_percent_difference_between_two_zeros(drawn):
    """A table row whose reading and exact value are both 0 differs by 0: no "-100 %" from a
    polygon made of round-off only (the crank's force polygon in a dead position)."""
    _, d, _ = drawn
    for panel in d.panels:
        if panel.kind != "table":
            continue
        cells = [q.label.plain for q in panel.prims if q.op == "text" and q.label is not None and not q.eid]
        assert len(cells) % 8 == 0, panel.pid
        for i in range(0, len(cells), 8):
            row = cells[i:i + 8]
            if row[4] == "0" and row[5] == "0":
                assert row[7] in ("0,00", "0.00", "—") or row[7].startswith("0 "), (panel.pid, row)


def test_panel_titles_give_the_angle_of_their_block_heading(drawn):
    """"Положение 8, φ = 181,851°" heads panels titled "…, φ = 181,851°", not "181,9°"."""
    _, d, _ = drawn
    at = re.compile(r"(?<!Δ)φ = (-?[\d.,]+)°")
    for sh in d.sheets:
        texts = [p.label.plain for p in sh.prims if p.op == "text" and p.label is not None]
        heads = {m.group(1) for t in texts if t.startswith(("Положение", "Position")) for m in at.finditer(t)}
        if not heads:
            continue
        titled = {m.group(1) for t in texts if not t.startswith(("Положение", "Position")) for m in at.finditer(t)}
        assert titled <= heads, sorted(titled - heads)


def test_no_english_abbreviations_on_a_russian_sheet(drawn):
    """I_пр, M_пр and "ср. кв." on a Russian sheet: not the English I_pr, M_pr, rms."""
    _, d, _ = drawn
    english = re.compile(r"(?<![A-Za-z])(?:[IM]pr|rms)(?![a-z])")
    for sh in d.sheets:
        if sh.spec.language != "ru":
            continue
        for p in sh.prims:
            if p.op == "text" and p.label is not None:
                assert not english.search(p.label.plain), p.label.plain


def test_dxf_holds_the_svgs_shapes_in_every_sample(drawn):
    """The first and the last sheet of every sample as DXF: every shape of its SVG, in order,
    to 0.01 mm, and nothing else (the other sheets and kinds: tests/test_dxf.py)."""
    from tests.dxf_sheets import differences, dxf_tags_shapes, svg_shapes

    _, d, _ = drawn
    for sh in {id(s): s for s in (d.sheets[0], d.sheets[-1])}.values():
        assert differences(svg_shapes(sh.svg()), dxf_tags_shapes(sh.dxf())[0]) == [], sh.number


def test_a1_sheets_are_not_left_empty(drawn):
    """Every A1 sheet of every sample has panels over at least 0.35 of its field (the plans,
    polygons and levers drawn at longer round scales where a sheet has room; the block layout
    once left half-empty last sheets of 0.11 to 0.25)."""
    _, d, _ = drawn
    fills = [drawn_part(sh) for sh in d.sheets]
    assert min(fills) >= 0.35, [round(f, 2) for f in fills]


def test_no_a1_sheet_is_more_than_a_third_empty(drawn):
    """Every A1 sheet of a sample drawn over at least two thirds of its field (inside the
    frame, less the title block)."""
    _, d, _ = drawn
    fills = [drawn_part(sh) for sh in d.sheets]
    assert min(fills) >= 2 / 3, [round(f, 2) for f in fills]


#: The class III and instant-centre linkages (samples/class3, samples/centres) drawn on A1.
LINKAGES = sorted((ROOT / "samples").glob("class3/*.toml")) + sorted((ROOT / "samples").glob("centres/*.toml"))


@pytest.mark.parametrize("path", LINKAGES, ids=[f"{p.parent.name}/{p.stem}" for p in LINKAGES])
def test_no_a1_sheet_of_a_class3_or_centres_linkage_is_more_than_a_third_empty(path):
    """The same two thirds on every A1 sheet of the linkages in the samples' subfolders, their
    panels clear of each other and inside the frame."""
    import itertools

    import shapely

    d = draw(path, format="A1")
    for sh in d.sheets:
        boxes = [shapely.box(*b) for b in sh.panel_boxes().values()]
        assert not [(a, b) for a, b in itertools.combinations(boxes, 2) if a.intersects(b)]
        assert all(shapely.box(*sh.frame_box).contains(b) for b in boxes)
    fills = [drawn_part(sh) for sh in d.sheets]
    assert min(fills) >= 2 / 3, [round(f, 2) for f in fills]


def _arrows(prims, kind: str = "force"):
    """(id, length mm) of every vector drawn: a group's shaft starts at its tail, its head
    polygon's first point is its tip (drawings.paper.common.arrow)."""
    import math

    out = []
    for i, p in enumerate(prims):
        if p.op == "begin" and kind in p.cls.split():
            line = next(q for q in prims[i + 1:] if q.op == "line")
            head = next((q for q in prims[i + 1:i + 4] if q.op == "polygon"), None)
            tip = head.pts[0] if head is not None else line.pts[1]
            out.append((p.eid, math.dist(line.pts[0], tip)))
    return out


def test_no_force_arrow_on_a_free_body_shorter_than_legible(drawn):
    """Every force of every group diagram and initial link of every position at least
    MIN_ARROW_MM long, and a panel that lengthened one says so (†, not to scale)."""
    from drawings.linkage.forces_panels import MIN_ARROW_MM

    _, d, _ = drawn
    seen = 0
    for panel in d.panels:
        if panel.kind not in ("group", "crank"):
            continue
        arrows = _arrows(panel.prims)
        seen += len(arrows)
        short = [(e, round(L, 3)) for e, L in arrows if L < MIN_ARROW_MM - 1e-9]
        assert not short, (panel.pid, short)
        marked = [q for q in panel.prims if q.op == "text" and q.label and "†" in q.label.plain
                  and not q.eid.endswith("-scale")]
        said = [q for q in panel.prims if q.op == "text" and q.eid.endswith("-scale") and "†" in q.label.plain]
        assert bool(marked) == bool(said), panel.pid
    if any(p.kind == "group" for p in d.panels):
        assert seen > 0


def test_couples_at_one_point_spread_apart(drawn):
    """Two couples on one point of a free body (M_c and M_Φ3 at S3) drawn on different arcs."""
    _, d, _ = drawn
    for panel in d.panels:
        if panel.kind not in ("group", "crank"):
            continue
        arcs = [p for p in panel.prims if p.op == "arc" and p.style is not None and p.style.cls == "moment"]
        keys = [(round(a.pts[0][0], 3), round(a.pts[0][1], 3), round(a.r, 3)) for a in arcs]
        assert len(keys) == len(set(keys)), panel.pid


def test_slotted_link_drawn_through_its_block(drawn):
    """On a group diagram that holds a coulisse (a guide carried by a link of the group), the
    slot runs through the block's pin and past both ends of the block: no floating block."""
    import math

    from drawings.linkage.panels import BLOCK_L
    from drawings.paper.common import ident, phi_tag

    path, d, _ = drawn
    scene = d.scene
    moving = [jt for jt in scene.joints if jt.kind == "P" and jt.guide is not None and jt.guide.link != scene.frame]
    seen = 0
    for panel in d.panels:
        if panel.kind != "group" or not moving:
            continue
        name = panel.pid[len("group-"):-len(phi_tag(panel.phi)) - 1]
        links = {int(x) for x in name.split("-") if x.isdigit()}
        for jt in moving:
            if jt.guide.link not in links or jt.slider not in links:
                continue
            block = [p for p in panel.prims if p.op == "polygon" and p.eid.endswith(f"-slider-{ident(jt.point)}")]
            slot = [p for p in panel.prims if p.op == "line" and p.eid.endswith(f"-slot-{ident(jt.point)}")]
            assert block and slot, (panel.pid, jt.point)
            corners = block[0].pts
            c = (sum(x for x, _ in corners) / 4, sum(y for _, y in corners) / 4)
            (a, b) = slot[0].pts
            L = math.dist(a, b)
            ux, uy = (b[0] - a[0]) / L, (b[1] - a[1]) / L
            off = abs((c[0] - a[0]) * uy - (c[1] - a[1]) * ux)
            t = (c[0] - a[0]) * ux + (c[1] - a[1]) * uy
            assert off < 1e-6, (panel.pid, off)
            assert BLOCK_L / 2 < t < L - BLOCK_L / 2, (panel.pid, t, L)
            seen += 1
    if path.stem in ("whitworth", "shaper", "six_bar"):  # a coulisse with its block in one group
        assert seen > 0


def gost_letters(svg: str | bytes) -> list[tuple[str, float]]:
    """(id, size) of every text under GOST 2.304's 2.5 mm, and of every index (a tspan written
    smaller than its text) under the standard's smallest size, 1.8 mm.  Title-block cells the
    user fills (names, date, title) may shrink to fit their cell and are not counted."""
    root = ET.fromstring(svg)
    bad = []
    for t in root.iter(f"{SVG}text"):
        eid = t.get("id") or ""
        user = eid.startswith("tb-") and not eid.startswith(("tb-h-", "tb-sheet", "tb-scale"))
        base = float(t.get("font-size"))
        if base < 2.5 - 1e-9 and not user:
            bad.append((eid, base))
        for sp in t.iter(f"{SVG}tspan"):
            fs = sp.get("font-size")
            if fs is not None and float(fs) < min(1.8, base) - 1e-9:
                bad.append((eid, float(fs)))
    return bad


def test_letters_at_least_gost_2_5_mm_on_every_sheet(drawn):
    _, d, _ = drawn
    for sh in d.sheets:
        assert gost_letters(sh.svg()) == [], sh.number
