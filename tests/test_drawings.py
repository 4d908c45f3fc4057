"""Drawings: the sheet is the measurement.

The SVG of the V-engine is parsed back, every plan vector is measured in mm,
divided by the scale written on the sheet, and compared with the exact
kinematics (not with the plan objects it was drawn from).
"""

from __future__ import annotations

import itertools
import math
import re
import xml.etree.ElementTree as ET
from pathlib import Path

import numpy as np
import pytest
import shapely

from drawings.linkage import draw
from drawings.linkage.panels import plan_panel, scheme_panel, strokes_over_cycle
from drawings.paper.backend import Recording, Style, Transform, hatch_segments, replay
from drawings.paper.common import arrow, fmt, ident
from drawings.paper.sheet import FORMATS, compose, sheet_spec
from drawings.paper.svg import SvgBackend, num
from drawings.paper.text import layout, parse, point_label
from plans.errors import InputError
from plans.kinematics.exact import solve
from plans.kinematics.placing import load_scene
from plans.kinematics.plan import ConstructionLine, Plan, PlanPoint, Segment
from plans.solution import Solution
from tests.locales import in_russian

#: The sheets these tests measure were drawn in Russian, the default before it followed the locale.
draw = in_russian(draw)

ROOT = Path(__file__).resolve().parents[1]
V_ENGINE = ROOT / "samples" / "v_engine.toml"
SVG = "{http://www.w3.org/2000/svg}"


@pytest.fixture(scope="module")
def v_engine():
    return draw(V_ENGINE)


@pytest.fixture(scope="module")
def v_svgs(v_engine):
    return [ET.fromstring(sh.svg()) for sh in v_engine.sheets]


# --------------------------------------------------------------------------- helpers


def _text(el) -> str:
    return "".join(el.itertext())


def _stated_scale(root, pid: str) -> float:
    """μ (mm per unit) as written on the sheet: ``μ_v = 6,667 мм/(м/с)``, ``μ_v = 0,15 (м/с)/мм``
    or ``K_v = 0,15 (m/s)/mm``: the direction read off the unit, whatever the letter."""
    el = root.find(f".//{SVG}text[@id='{pid}-scale']")
    assert el is not None, pid
    t = _text(el)
    m = re.match(r"\s*([μK])\w*\s*=\s*([-\d.,]+)\s*(\S+)", t)
    assert m, t
    value = float(m.group(2).replace(",", "."))
    return 1.0 / value if m.group(3).endswith(("/мм", "/mm")) else value


def _vectors(root, pid: str) -> dict[str, float]:
    """Length (mm) of every vector group of a panel: shaft start to head tip."""
    out = {}
    for g in root.iter(f"{SVG}g"):
        cls = g.get("class", "")
        gid = g.get("id", "")
        if cls.split()[:1] != ["vector"] or not gid.startswith(pid + "-"):
            continue
        line = g.find(f"{SVG}line")
        head = g.find(f"{SVG}path")
        x0, y0 = float(line.get("x1")), float(line.get("y1"))
        if head is None:
            x1, y1 = float(line.get("x2")), float(line.get("y2"))
        else:
            m = re.match(r"M([-\d.]+),([-\d.]+)", head.get("d"))
            x1, y1 = float(m.group(1)), float(m.group(2))
        out[gid[len(pid) + 1:]] = math.hypot(x1 - x0, y1 - y0)
    return out


def _exact(kin, k: int, ident_label: str) -> float:
    """The exact magnitude a plan vector stands for, straight from the kinematics."""
    m = re.match(r"^([va])_([A-Z]\d?)([A-Z]\d?)?(?:-(n|tau))?$", ident_label)
    assert m, ident_label
    kind, X, Y, comp = m.groups()
    idx = 1 if kind == "v" else 2
    qx = complex(kin.point(X)[idx][k])
    if Y is None:
        return abs(qx)
    qy = complex(kin.point(Y)[idx][k])
    if comp is None:
        return abs(qx - qy)
    link = next(lid for lid, ln in kin.scene.links.items() if X in ln.points and Y in ln.points)
    rx, ry = complex(kin.point(X)[0][k]), complex(kin.point(Y)[0][k])
    L = abs(rx - ry)
    if comp == "n":
        return float(kin.omega(link)[k]) ** 2 * L
    return abs(float(kin.eps(link)[k])) * L


# --------------------------------------------------------------------------- the measurement


@pytest.mark.parametrize("kind", ["velocity", "acceleration"])
@pytest.mark.parametrize("phi", ["45", "0"])
def test_vectors_measured_on_the_sheet_match_exact_values(v_engine, v_svgs, kind, phi):
    scene = v_engine.scene
    kin = solve(scene)
    k = [f"{x:g}" for x in kin.phi_deg].index(phi)
    pid = f"{kind}-{phi}"
    root = next(r for r in v_svgs if r.find(f".//{SVG}g[@id='{pid}']") is not None)
    mu = _stated_scale(root, pid)
    vectors = _vectors(root, pid)
    assert len(vectors) >= 7
    ref = max(vectors.values())
    for name, mm in vectors.items():
        exact = _exact(kin, k, name)
        # 3-decimal coordinates and a 4-digit written scale: well under a pencil line
        assert mm / mu == pytest.approx(exact, rel=3e-4, abs=2e-3 * ref / mu), name


def test_dead_position_vector_is_zero_length_and_present(v_svgs):
    root = next(r for r in v_svgs if r.find(f".//{SVG}g[@id='velocity-0']") is not None)
    vectors = _vectors(root, "velocity-0")
    assert vectors["v_B"] == pytest.approx(0.0, abs=1e-3)
    label = root.find(f".//{SVG}text[@id='velocity-0-label-p_v']")
    assert label is not None and _text(label).replace(" ", "") == "pv,b"


def _sheet_with(roots, pid: str):
    return next(r for r in roots if r.find(f".//{SVG}g[@id='{pid}']") is not None)


def test_component_vectors_are_distinguishable(v_svgs):
    root = _sheet_with(v_svgs, "acceleration-45")
    g_n = root.find(f".//{SVG}g[@id='acceleration-45-a_BA-n']")
    g_t = root.find(f".//{SVG}g[@id='acceleration-45-a_BA-tau']")
    g_a = root.find(f".//{SVG}g[@id='acceleration-45-a_B']")
    assert g_n.get("class") == "vector normal" and g_t.get("class") == "vector tangential"
    styles = {g.find(f"{SVG}line").get("stroke-dasharray") for g in (g_n, g_t, g_a)}
    assert len(styles) == 3  # dashed, dash-dot, solid
    lab = root.find(f".//{SVG}text[@id='acceleration-45-a_BA-n-label']")
    assert _text(lab) == "aBAn"


def test_scales_written_as_the_course_writes_them(v_svgs):
    root = _sheet_with(v_svgs, "velocity-45")
    # a Russian sheet: μ in units per millimetre, as the course writes it (plans.scene.notation)
    assert _text(root.find(f".//{SVG}text[@id='velocity-45-scale']")).startswith("μv = 0,1 (м/с)/мм")  # its plan drawn long: the sheet has room
    assert "M 1:1" in _text(root.find(f".//{SVG}text[@id='scheme-45-scale']"))


def test_k_style_scales(tmp_path):
    text = V_ENGINE.read_text(encoding="utf-8").replace('fij = ', '[scales]\nstyle = "K"\n\nfij = ', 1)
    # [scales] must precede other top-level keys only as a table: put it at the end instead
    text = V_ENGINE.read_text(encoding="utf-8") + '\n[scales]\nstyle = "K"\n\n[sheet]\nlanguage = "en"\n'
    p = tmp_path / "k.toml"
    p.write_text(text, encoding="utf-8")
    d = draw(p)
    root = _sheet_with([ET.fromstring(sh.svg()) for sh in d.sheets], "velocity-45")
    t = _text(root.find(f".//{SVG}text[@id='velocity-45-scale']"))
    assert t.startswith("Kv = 0.1 (m/s)/mm")
    assert _stated_scale(root, "velocity-45") == pytest.approx(1 / 0.1)


# --------------------------------------------------------------------------- the sheet


def test_no_overlaps_and_everything_inside_the_frame(v_engine):
    for sh in v_engine.sheets:
        x0, y0, x1, y1 = sh.frame_box
        frame = shapely.box(x0, y0, x1, y1)
        tb = shapely.box(*sh.title_box)
        boxes = {pid: shapely.box(*b) for pid, b in sh.panel_boxes().items()}
        for (a, ga), (b, gb) in itertools.combinations(boxes.items(), 2):
            assert not ga.intersects(gb), (a, b)
        for pid, g in boxes.items():
            assert frame.contains(g), pid
            assert not g.intersects(tb), pid
        for p in sh.prims:
            b = p.box()
            if b is not None:  # half the frame's 0.7 mm line lies outside its centre line
                assert x0 - 0.36 <= b[0] and b[2] <= x1 + 0.36 and y0 - 0.36 <= b[1] and b[3] <= y1 + 0.36, p
        # every primitive of a panel lies in that panel's box (labels included)
        for panel, px, py in sh.placed:
            box = shapely.box(px - 1e-6, py - 1e-6, px + panel.width + 1e-6, py + panel.height + 1e-6)
            for p in panel.at(px, py):
                b = p.box()
                if b is not None:
                    assert box.contains(shapely.box(*b)), (panel.pid, p.eid)


def test_labels_do_not_overlap(v_engine):
    for panel in v_engine.panels:
        boxes = [shapely.box(*b) for b in panel.text_boxes()]
        for a, b in itertools.combinations(boxes, 2):
            assert a.intersection(b).area < 0.01, panel.pid


def test_title_block_filled(v_svgs, v_engine):
    root = v_svgs[0]
    got = {el.get("id"): _text(el) for el in root.iter(f"{SVG}text") if el.get("id", "").startswith("tb-")}
    assert got["tb-title-0"].startswith("Механизм V-образного")  # the Russian title on a Russian sheet
    assert got["tb-sheet"] == "Лист 1"
    assert got["tb-sheets"] == f"Листов {len(v_engine.sheets)}"
    assert got["tb-scale"] == "1:1"
    assert got["tb-author"] == "Разраб."


def test_title_block_from_sheet_table(tmp_path):
    text = V_ENGINE.read_text(encoding="utf-8") + (
        '\n[sheet]\nformat = "A1"\nlanguage = "en"\ntitle = "V-engine: kinematics and forces"\n'
        'designation = "TMM.CP.07.00.00"\nauthor = "I. Ivanov"\nchecked_by = "P. Petrov"\n'
        'group = "MT-31"\nfirst_sheet = 2\ntotal_sheets = 5\n')
    p = tmp_path / "s.toml"
    p.write_text(text, encoding="utf-8")
    d = draw(p)
    root = ET.fromstring(d.sheets[0].svg())
    got = {el.get("id"): _text(el) for el in root.iter(f"{SVG}text") if el.get("id", "").startswith("tb-")}
    assert got["tb-designation"] == "TMM.CP.07.00.00"
    assert got["tb-author-name"] == "I. Ivanov" and got["tb-checked-name"] == "P. Petrov"
    assert got["tb-org-0"] == "MT-31"
    assert got["tb-sheet"] == "Sheet 2" and got["tb-sheets"] == "Sheets 5"
    assert "kinematics and forces" in " ".join(v for k, v in got.items() if k.startswith("tb-title"))


def test_svg_is_true_millimetres_and_passes_svgwrite_validation(v_engine):
    sh = v_engine.sheets[0]
    text = sh.svg(debug=True)  # svgwrite validates every element and attribute
    root = ET.fromstring(text)
    assert root.get("width") == "841mm" and root.get("height") == "594mm"
    assert root.get("viewBox").replace(",", " ").split() == ["0", "0", "841.0", "594.0"]


def test_same_scene_same_bytes():
    a = [s.svg() for s in draw(V_ENGINE).sheets]
    b = [s.svg() for s in draw(V_ENGINE).sheets]
    assert a == b


@pytest.mark.parametrize("fmt_,orientation", [("A1", "landscape"), ("A2", "portrait"), ("A3", "landscape"),
                                              ("A4", "portrait")])
def test_sheet_sizes(fmt_, orientation):
    spec = sheet_spec({"sheet": {"format": fmt_, "orientation": orientation}}, "x.toml")
    sheets = compose([], spec)
    w, h = FORMATS[fmt_]
    if orientation == "portrait":
        w, h = h, w
    assert (sheets[0].width, sheets[0].height) == (w, h)
    root = ET.fromstring(sheets[0].svg())
    assert root.get("width") == f"{w:g}mm"


def test_spills_onto_further_sheets_on_a_small_format():
    d = draw(V_ENGINE, format="A3")
    assert len(d.sheets) > len(draw(V_ENGINE).sheets)
    for sh in d.sheets:
        assert sh.placed
        assert sh.count == len(d.sheets)


def test_pinned_panel_stays_where_pinned(tmp_path):
    text = V_ENGINE.read_text(encoding="utf-8") + (
        '\n[sheet]\n[[sheet.pins]]\npanel = "velocity-45"\nx = 600\ny = 300\n')
    p = tmp_path / "pin.toml"
    p.write_text(text, encoding="utf-8")
    d = draw(p)
    box = d.sheets[0].panel_boxes()["velocity-45"]
    assert box[:2] == (600.0, 300.0)


def test_panels_only_when_asked(tmp_path):
    text = V_ENGINE.read_text(encoding="utf-8").replace(
        'outputs = ["positions", "velocity_plan", "acceleration_plan", "force_polygons", "lever"]',
        'outputs = ["positions", "velocity_plan"]').replace(
        'outputs = ["positions", "velocity_plan", "acceleration_plan"]', 'outputs = ["positions", "velocity_plan"]')
    p = tmp_path / "v.toml"
    p.write_text(text, encoding="utf-8")
    d = draw(p)
    kinds = {panel.kind for panel in d.panels}
    assert kinds == {"positions", "scheme", "velocity", "table", "legend"}
    legend = next(p for p in d.panels if p.kind == "legend")
    shown = {p.eid[len("legend-"):-len("-text")] for p in legend.prims if p.op == "text" and p.eid.endswith("-text")}
    assert shown == {"absolute", "relative", "construction", "trace"}  # only the styles drawn


# --------------------------------------------------------------------------- bad input


def test_unknown_sheet_format():
    with pytest.raises(InputError, match=r"sheet.format: unknown sheet format 'B5'; expected one of A1"):
        draw(V_ENGINE, format="B5")


def test_unknown_sheet_key(tmp_path):
    p = tmp_path / "bad.toml"
    p.write_text(V_ENGINE.read_text(encoding="utf-8") + '\n[sheet]\nfromat = "A1"\n', encoding="utf-8")
    with pytest.raises(InputError, match=r"sheet.fromat: unknown key"):
        draw(p)


def test_panel_too_big_even_for_a1_suggests_a_scale(tmp_path):
    p = tmp_path / "big.toml"
    p.write_text(V_ENGINE.read_text(encoding="utf-8") + "\n[scales]\nlength = { mu = 8000 }\n", encoding="utf-8")
    with pytest.raises(InputError, match=r"does not fit even on an empty A1 .*\[scales\] length = \{ mu = \d"):
        draw(p)


def test_panel_too_big_for_a4_at_the_files_own_scale_suggests_a_larger_sheet(tmp_path):
    """A scale the file fixes is kept: a plan too big for A4 at it is refused, naming a sheet
    it fits (at the engine's own scales the same scene is drawn smaller: see test_sheet_fit)."""
    p = tmp_path / "fixed.toml"
    p.write_text(V_ENGINE.read_text(encoding="utf-8") + "\n[scales]\nvelocity = { mu = 10 }\n", encoding="utf-8")
    with pytest.raises(InputError, match=r"does not fit on an empty A4 .*--sheet A\d"):
        draw(p, format="A4")


def test_missing_font_names_font_and_package():
    from drawings.paper.fonts import FontMissing, find_font

    with pytest.raises(FontMissing, match=r"'DejaVu Sans' \(DejaVuSans.ttf\) not found.*fonts-dejavu-core"):
        find_font(("/nonexistent/fonts",))


# --------------------------------------------------------------------------- pieces


def test_transform_flips_y_once():
    T = Transform(1000.0, 10.0, 20.0)
    assert T(0.001, 0.002) == (11.0, 18.0)
    assert T.direction(0.0, 1.0) == (0.0, -1.0)
    assert T.angle(math.pi / 2) == -math.pi / 2


def test_number_formatting():
    assert num(1.23456) == "1.235" and num(-0.0001) == "0" and num(2.0) == "2" and num(-1.5) == "-1.5"
    assert fmt(6.666666, 4, "ru") == "6,667" and fmt(0.02) == "0.02" and fmt(1e-15) == "0"
    assert ident("a_BA^τ") == "a_BA-tau" and ident("F21^n") == "F21-n"


def test_label_markup():
    assert parse("a^k_B3B2") == [("a", "base"), ("k", "sup"), ("B3B2", "sub")]
    assert parse("μ_v = 6 mm") == [("μ", "base"), ("v", "sub"), (" = 6 mm", "base")]
    assert point_label("S2") == "S_2" and point_label("p_v") == "p_v"
    lab = layout("a_BA^n", 10.0, 20.0, 3.5)
    sub, sup = lab.runs[1], lab.runs[2]
    assert sub.x == sup.x  # stacked as the textbook writes a^n_BA
    assert sub.y > 20.0 > sup.y and sub.size < 3.5
    assert lab.box[0] == 10.0 and lab.box[2] > 10.0


def test_glyph_fallback_for_perpendicular():
    assert layout("⟂ AB", 0, 0, 3).plain == "⊥ AB"


def test_hatch_strokes_lean_to_the_chosen_side():
    segs = hatch_segments((0.0, 0.0), (10.0, 0.0), +1, 2.0, 2.0)
    assert len(segs) == 6
    assert all(b[1] < a[1] for a, b in segs)  # left of +x on a y-down sheet is up
    segs = hatch_segments((0.0, 0.0), (10.0, 0.0), -1, 2.0, 2.0)
    assert all(b[1] > a[1] for a, b in segs)


def test_arrow_records_shaft_from_start_and_head_tip_at_end():
    rec = Recording()
    arrow(rec, (0.0, 0.0), (30.0, 40.0), Style(width=0.5), "v", "vector absolute")
    ops = [p.op for p in rec.prims]
    assert ops == ["begin", "line", "polygon", "end"]
    line, head = rec.prims[1], rec.prims[2]
    assert line.pts[0] == (0.0, 0.0) and head.pts[0] == (30.0, 40.0)
    assert head.style.fill == "#000" and head.style.stroke is None


def _hand_plan() -> Plan:
    pts = (PlanPoint("p_v", (0.0, 0.0)), PlanPoint("a", (-60.0, 0.0)), PlanPoint("b", (-40.0, -40.0)),
           PlanPoint("s2", (-53.4, -13.2)))
    segs = (Segment("p_v", "a", "absolute", "v_A", 60.0, 12.0),
            Segment("p_v", "b", "absolute", "v_B", math.hypot(40, 40), math.hypot(40, 40) / 5),
            Segment("a", "b", "relative", "v_BA", math.hypot(20, 40), math.hypot(20, 40) / 5),
            Segment("p_v", "s2", "absolute", "v_S2", math.hypot(53.4, 13.2), math.hypot(53.4, 13.2) / 5))
    lines = (ConstructionLine((-60.0, 0.0), (0.447, -0.894), "⟂ AB"),
             ConstructionLine((0.0, 0.0), (0.7071, 0.7071), "∥ guide of B"))
    return Plan("velocity", 30.0, 5.0, "p_v", pts, segs, lines, ())


def test_plan_panel_on_a_recording_backend():
    panel = plan_panel(_hand_plan(), "en", "mu")
    rec = Recording(list(panel.prims))
    groups = [p for p in rec.prims if p.op == "begin" and p.cls.split()[:1] == ["vector"]]
    assert [g.eid for g in groups] == ["velocity-30-v_A", "velocity-30-v_B", "velocity-30-v_BA", "velocity-30-v_S2"]
    heads = [p for p in rec.prims if p.op == "polygon" and p.style and p.style.cls == "head"]
    assert len(heads) == 4
    thin = [p for p in rec.prims if p.op == "line" and p.style and p.style.cls == "construction"]
    assert len(thin) == 2 and all(p.style.width < 0.25 for p in thin)
    texts = {p.eid: p.label.plain for p in rec.texts()}
    assert texts["velocity-30-scale"] == "μv = 5 mm/(m/s)"
    assert texts["velocity-30-label-s2"] == "s2"
    assert "⊥ AB" in texts.values()
    # measured on the recording: |p_v a| = 60 mm at 5 mm/(m/s) is 12 m/s
    g = rec.prims.index(groups[0])
    shaft, head = rec.prims[g + 1], rec.prims[g + 2]
    assert math.dist(shaft.pts[0], head.pts[0]) / 5.0 == pytest.approx(12.0, abs=1e-9)
    # replayed onto SVG it is valid and keeps the ids
    be = SvgBackend(panel.width, panel.height, debug=True)
    replay(panel.prims, be)
    root = ET.fromstring(be.tostring())
    assert root.find(f".//{SVG}g[@id='velocity-30-v_BA']") is not None


def test_scheme_panel_draws_what_the_textbook_draws():
    scene = load_scene(V_ENGINE)
    kin = solve(scene)
    panel = scheme_panel(scene, kin, 0, 1000.0, "ru", strokes_over_cycle(Solution(scene)))
    ids = [p.eid for p in panel.prims if p.eid]
    assert {"scheme-45-slider-B", "scheme-45-slider-C", "scheme-45-support-O", "scheme-45-omega-arc",
            "scheme-45-omega-head", "scheme-45-hatch-B", "scheme-45-hatch-C", "scheme-45-centre-S2",
            "scheme-45-centre-S4", "scheme-45-link-1", "scheme-45-link-2", "scheme-45-link-4"} <= set(ids)
    joints = [i for i in ids if "-joint-" in i]
    assert sorted(joints) == ["scheme-45-joint-A", "scheme-45-joint-B", "scheme-45-joint-C", "scheme-45-joint-O"]
    # OA drawn at μl = 1000 mm/m is 35 mm long
    link1 = next(p for p in panel.prims if p.eid == "scheme-45-link-1")
    assert math.dist(*link1.pts) == pytest.approx(35.0, abs=1e-9)
    labels = {p.label.plain for p in panel.prims if p.op == "text" and "-label-" in p.eid}
    assert labels == {"O", "A", "B", "C", "S2", "S4"}


def test_no_import_of_the_renderer_in_the_core():
    for path in (ROOT / "plans").glob("*.py"):
        src = path.read_text(encoding="utf-8")
        assert not re.search(r"^\s*(from|import)\s+(drawings|svgwrite|cairosvg)\b", src, re.M), path


def test_stroke_range_of_the_pistons():
    scene = load_scene(V_ENGINE)
    st = strokes_over_cycle(Solution(scene))
    for lo, hi in st.values():
        assert hi - lo == pytest.approx(0.070, rel=1e-3)  # H = 2·OA
    assert np.isfinite(list(st.values())).all()


def test_jupyter_views(v_engine):
    from drawings import show_plan

    assert v_engine._repr_svg_().startswith("<svg")
    assert v_engine.sheets[0]._repr_svg_().startswith("<svg")
    view = show_plan(_hand_plan())
    root = ET.fromstring(view._repr_svg_())
    assert root.get("width").endswith("mm")
    assert root.find(f".//{SVG}g[@id='velocity-30-v_A']") is not None


def test_force_polygon_vectors_measured_on_the_sheet(v_engine, v_svgs):
    """Polygon vectors / written μF against the exact kinetostatics (loads and reactions)."""
    from plans.forces.analysis import kinetostatics

    scene = v_engine.scene
    kin = solve(scene)
    fa, _ = kinetostatics(scene, kin)
    k = [f"{x:g}" for x in kin.phi_deg].index("45")
    exact: dict[str, float] = {}
    for gf in fa.groups:
        for f in list(gf.loads_i) + list(gf.loads_j):
            exact[ident(f.label)] = abs(complex(f.F[k]))
        for rc in gf.reactions:
            name = rc.name(scene.fij)
            exact[ident(name)] = abs(complex(rc.F[k]))
            if rc.tau is not None:
                exact[ident(name + "^τ")] = abs(float(rc.tau[k]))
                exact[ident(name + "^n")] = abs(float(rc.n[k]))
    checked = 0
    for gf in fa.groups:
        pid = f"polygon-{gf.group.name}-45"
        root = next(r for r in v_svgs if r.find(f".//{SVG}g[@id='{pid}']") is not None)
        mu = _stated_scale(root, pid)
        for name, mm in _vectors(root, pid).items():
            assert mm / mu == pytest.approx(exact[name], rel=3e-4, abs=0.01 / mu), (pid, name)
            checked += 1
    assert checked >= 12
