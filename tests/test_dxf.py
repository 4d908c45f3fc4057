"""DXF sheets (drawings.paper.dxf): each kind's sheets read back by ezdxf hold the SVG's shapes,
the plans' vectors are ``plans solve``'s segments, mm units and A-format extents, layers by
content and GOST line type, Cyrillic intact, the same bytes every time, ezdxf loaded only
for DXF."""

from __future__ import annotations

import io
import json
import math
import subprocess
import sys
from pathlib import Path

import pytest

from tests.dxf_sheets import differences, dxf_shapes, dxf_tags_shapes, svg_shapes
from tests.locales import in_russian

ezdxf = pytest.importorskip("ezdxf")

ROOT = Path(__file__).resolve().parent.parent
SAMPLES = ROOT / "samples"
KIND_SAMPLES = {  # one sample of every kind of file (the smallest that shows it)
    "linkage": SAMPLES / "v_engine.toml",
    "gears": SAMPLES / "gears" / "seed_train.toml",
    "cam": SAMPLES / "cams" / "seed001_valve_cam.toml",
    "engine": SAMPLES / "engines" / "v_twin.toml",
    "synthesis": SAMPLES / "synthesis" / "crank_rocker.toml",
}


def _draw(path: Path):
    import importlib

    from plans.kinds import KINDS, read_kind

    kind, _ = read_kind(path)
    return in_russian(importlib.import_module(KINDS[kind][1]).draw)(path).sheets  # Russian, as measured


@pytest.fixture(scope="module")
def drawn() -> dict[str, list]:
    out = {kind: _draw(path) for kind, path in KIND_SAMPLES.items()}
    from drawings.cycle import extend  # the cycle's diagrams and dynamics sheets alone
    from drawings.paper.sheet import sheet_spec
    from plans.kinematics.placing import load_scene

    scene = load_scene(SAMPLES / "v_engine_cycle.toml")
    out["cycle"] = extend(scene, sheet_spec(scene.raw, scene.path, scene.title), [])
    from drawings.check_sheet import marked_sheets, overlay_sheets
    from plans.check.report import check_file

    rep = check_file(SAMPLES / "checks" / "v_engine_coursework.toml")
    out["check"] = marked_sheets(rep) + overlay_sheets(rep)
    return out


def _read(data: bytes):
    return ezdxf.read(io.StringIO(data.decode("utf-8")))


@pytest.fixture(scope="module")
def first(drawn):
    """The linkage sample's first sheet and its DXF read back by ezdxf (read once)."""
    sh = drawn["linkage"][0]
    return sh, _read(sh.dxf())


@pytest.mark.parametrize("kind", [*KIND_SAMPLES, "cycle", "check"])
def test_every_kinds_dxf_holds_the_svgs_shapes(drawn, kind):
    """Every line, circle, arc, outline, fill and text run of the SVG, and nothing else, in
    the same order, within 0.01 mm: read back by a plain tag reader, and by ezdxf (the first
    sheet of each kind)."""
    for k, sh in enumerate(drawn[kind]):
        svg, data = svg_shapes(sh.svg()), sh.dxf()
        assert len(svg) > 50
        assert differences(svg, dxf_tags_shapes(data)[0]) == [], (kind, sh.number)
        if k == 0:
            assert differences(svg, dxf_shapes(_read(data))) == [], (kind, sh.number)


def test_a_shape_moved_by_two_hundredths_of_a_millimetre_is_seen():
    shapes = [("LINE", ((10.0, 20.0), (30.0, 40.0)), None), ("TEXT", ((1.0, 2.0),), ("ω_1", 2.5))]
    moved = [("LINE", ((10.0, 20.0), (30.02, 40.0)), None), shapes[1]]
    assert differences(shapes, shapes) == []
    assert differences(shapes, moved)
    assert differences(shapes, shapes[:1])
    assert differences(shapes, [shapes[0], ("TEXT", ((1.0, 2.0),), ("ω_2", 2.5))])


def _vectors(doc, block: str) -> list[tuple[float, float]]:
    """Each vector of a plan's block: from its shaft's start to its head's tip (DXF mm, y up)."""
    ents = list(doc.blocks.get(block))
    out = []
    for a, b in zip(ents, ents[1:], strict=False):
        if a.dxftype() == "LINE" and b.dxftype() == "SOLID":
            out.append((b.dxf.vtx0.x - a.dxf.start.x, b.dxf.vtx0.y - a.dxf.start.y))
    return out


def test_plan_vectors_read_off_the_dxf_are_the_segments_plans_solve_reports(drawn, first, tmp_path):
    """Every segment of every velocity and acceleration plan in ``plans solve --json`` (plan
    mm, y up, at the A1 scales) is a vector of its plan's block in the DXF (1 unit = 1 mm, y up)
    to 0.01 mm, times the ratio of the scale the sheet draws that plan at (a larger round one
    where the sheet has room) to the JSON's."""
    from plans.cli import main

    out = tmp_path / "solve.json"
    assert main(["solve", str(KIND_SAMPLES["linkage"]), "--json", str(out), "--quiet"]) == 0
    solved = json.loads(out.read_text(encoding="utf-8"))
    checked = 0
    from drawings.paper.common import phi_tag
    from plans.kinematics.scales import is_round

    for sh in drawn["linkage"]:
        doc = first[1] if sh is first[0] else _read(sh.dxf())
        names = {b.name for b in doc.blocks}
        drawn_at = {p.pid: p.scale for p, _, _ in sh.placed}
        for pos in solved["positions"]:
            for kind in ("velocity", "acceleration"):
                block = f"{kind}-{phi_tag(pos['phi_deg'])}"
                if block not in names:
                    continue
                plan = pos["plans"][kind]
                vectors = _vectors(doc, block)
                k = drawn_at[block] / plan["scale"]
                assert k >= 1.0 and is_round(drawn_at[block])
                for s in plan["segments"]:
                    if s["length_mm"] < 0.5:
                        continue
                    (x0, y0), (x1, y1) = plan["points"][s["from"]], plan["points"][s["to"]]
                    assert math.hypot(x1 - x0, y1 - y0) == pytest.approx(s["length_mm"], abs=1e-9)
                    want = (k * (x1 - x0), k * (y1 - y0))
                    near = [v for v in vectors if math.dist(v, want) <= 0.01]
                    assert near, (block, s["label"], want)
                    assert math.hypot(*near[0]) == pytest.approx(k * s["length_mm"], abs=0.01)
                    checked += 1
    assert checked >= 20


def test_units_extents_and_the_frame_in_millimetres(drawn, first):
    for sh in [drawn["linkage"][0], drawn["check"][-1]]:
        doc = first[1] if sh is first[0] else _read(sh.dxf())
        assert doc.dxfversion >= "AC1024"  # R2010 or later
        assert doc.header["$INSUNITS"] == 4 and doc.header["$MEASUREMENT"] == 1
        assert tuple(doc.header["$EXTMIN"])[:2] == (0.0, 0.0)
        assert tuple(doc.header["$EXTMAX"])[:2] == (sh.width, sh.height)
        border = next(e for e in doc.blocks.get("frame") if e.dxftype() == "LWPOLYLINE")
        ins = next(e for e in doc.modelspace() if e.dxftype() == "INSERT" and e.dxf.name == "frame").dxf.insert
        pts = sorted((x + ins.x, y + ins.y) for x, y in border.get_points("xy"))
        assert border.closed
        assert pts == sorted([(20.0, 5.0), (sh.width - 5.0, 5.0), (sh.width - 5.0, sh.height - 5.0),
                              (20.0, sh.height - 5.0)])  # GOST 2.104: 20 mm binding margin, 5 elsewhere
    assert (drawn["linkage"][0].width, drawn["linkage"][0].height) == (841.0, 594.0)


def test_layers_by_content_and_gost_line_type_with_true_lineweights(first):
    from drawings.paper.dxf import LAYER_WORDS, LINEWEIGHTS

    sh, doc = first  # a Russian sheet: scheme, plans, forces, lever, tables
    ru = LAYER_WORDS["ru"]
    layers = {layer.dxf.name: layer for layer in doc.layers}
    for content in ("frame", "scheme", "velocity", "acceleration", "forces", "lever", "tables"):
        assert f"{ru[content]}-{ru['main']}" in layers, content
    assert ru["text"] in layers
    assert layers["Рамка-основная"].dxf.lineweight == 50 and layers["Схема-тонкая"].dxf.lineweight == 25
    assert layers["План ускорений-штрихпунктирная"].dxf.linetype == "ESKD_CENTRE"
    svg_widths = {}
    import xml.etree.ElementTree as ET

    for el in ET.fromstring(sh.svg()).iter():
        if el.get("stroke-width"):
            svg_widths[round(float(el.get("stroke-width")) * 100)] = True
    used = set()
    for block in doc.blocks:
        for e in block:
            assert e.dxf.layer in layers, e.dxf.layer
            if e.dxftype() == "TEXT":
                assert e.dxf.layer == ru["text"] and e.dxf.style == "GOST"
            if e.dxftype() in ("LINE", "CIRCLE", "ARC", "LWPOLYLINE"):
                assert e.dxf.lineweight in LINEWEIGHTS
                used.add(e.dxf.lineweight)
    assert used <= {w for w in LINEWEIGHTS if any(abs(w - s) <= 5 for s in svg_widths)}
    assert {70, 25} <= used  # the frame's and the links' main lines, the thin ones


def test_dashed_lines_carry_the_svgs_dash_pattern(first):
    import xml.etree.ElementTree as ET

    sh, doc = first
    svg_dashes = {tuple(float(v) for v in el.get("stroke-dasharray").split())
                  for el in ET.fromstring(sh.svg()).iter() if el.get("stroke-dasharray")}
    dxf_dashes = set()
    for lt in doc.linetypes:
        if lt.dxf.name.startswith("ESKD_") and lt.dxf.name not in ("ESKD_CENTRE", "ESKD_DASHED"):
            tags = [t.value for t in lt.pattern_tags.tags if t.code == 49]
            dxf_dashes.add(tuple(abs(v) for v in tags))
    assert svg_dashes and dxf_dashes == svg_dashes


def test_each_panel_is_a_block_inserted_where_it_stands(first):
    sh, doc = first
    inserts = {e.dxf.name: e.dxf.insert for e in doc.modelspace() if e.dxftype() == "INSERT"}
    assert [e.dxftype() for e in doc.modelspace()] == ["INSERT"] * len(inserts)
    for panel, x, y in sh.placed:
        ins = inserts[panel.pid]
        assert (ins.x, ins.y) == pytest.approx((x, sh.height - y - panel.height), abs=1e-4)
    assert {"frame", "title-block"} <= set(inserts)


def test_cyrillic_text_round_trips(first):
    sh, doc = first
    data = sh.dxf()
    texts = [e.dxf.text for b in doc.blocks for e in b if e.dxftype() == "TEXT"]
    assert sh.spec.title and any(sh.spec.title.split()[0] in t for t in texts)
    assert any("План скоростей" in t for t in texts) and any(t == "ур" for t in texts)  # F_ур's subscript
    assert "\\U+" not in data.decode("utf-8")  # UTF-8 as is, no escapes
    assert doc.styles.get("GOST").dxf.font == "isocpeur.ttf"


def test_same_bytes_every_time_and_the_same_as_ezdxfs_own_entities(drawn):
    from drawings.paper.dxf import document_ezdxf

    sh = drawn["gears"][-1]
    first, again = sh.dxf(), sh.dxf()
    assert first == again
    prims, bases = sh._dxf_blocks()
    assert document_ezdxf(sh.width, sh.height, prims, sh.spec.language, sh.spec.title, bases) == first
    assert b"$TDCREATE\n 40\n2451545.0\n" in first  # ezdxf's fixed date (2000-01-01), not today's
    auditor = _read(first).audit()  # handles, owners, tables, references: all as CAD expects
    assert not auditor.has_errors and not auditor.has_fixes, [str(e) for e in auditor.errors + auditor.fixes]


def test_draw_writes_one_dxf_per_sheet_beside_the_other_formats(tmp_path, capsys):
    from drawings.cli import main

    src = SAMPLES / "gears" / "planetary_2kh.toml"  # two sheets
    assert main(["draw", str(src), "-o", str(tmp_path), "--format", "svg,dxf", "--quiet"]) == 0
    names = sorted(p.name for p in tmp_path.iterdir() if not p.name.startswith("."))
    assert names == ["planetary_2kh-1.dxf", "planetary_2kh-1.svg", "planetary_2kh-2.dxf", "planetary_2kh-2.svg"]
    alone = tmp_path / "alone"
    assert main(["draw", str(src), "-o", str(alone), "--format", "dxf", "--quiet"]) == 0
    assert sorted(p.name for p in alone.iterdir() if not p.name.startswith(".")) == \
        ["planetary_2kh-1.dxf", "planetary_2kh-2.dxf"]
    assert (alone / "planetary_2kh-1.dxf").read_bytes() == (tmp_path / "planetary_2kh-1.dxf").read_bytes()
    with pytest.raises(SystemExit):
        main(["draw", str(src), "-o", str(alone), "--format", "dwg"])
    assert "svg,pdf,png,dxf" in capsys.readouterr().err


def _run(code: str) -> str:
    import os

    # another process, other hashes: the same bytes; Russian, as the sheets it is compared with
    env = {**os.environ, "PYTHONHASHSEED": "7", "LC_ALL": "ru_RU.UTF-8"}
    got = subprocess.run([sys.executable, "-c", code], cwd=ROOT, capture_output=True, text=True, timeout=300,
                         env=env)
    assert got.returncode == 0, got.stderr
    return got.stdout.strip()


def test_ezdxf_is_loaded_only_when_dxf_is_asked_for(drawn, tmp_path):
    """Solving (``plans gears``; ``plans solve`` loads nothing of the renderer at all, see
    test_layering) and drawing SVG leave ezdxf unloaded; drawing DXF loads it."""
    code = ("import contextlib, io, sys\n"
            "from drawings.cli import main\n"
            "with contextlib.redirect_stdout(io.StringIO()):\n"
            f"    assert main(['gears', {str(KIND_SAMPLES['gears'])!r}]) == 0\n"
            "print('ezdxf' in sys.modules)\n"
            "with contextlib.redirect_stdout(io.StringIO()):\n"
            f"    assert main(['draw', {str(KIND_SAMPLES['gears'])!r}, '-o', {str(tmp_path)!r}, '--quiet']) == 0\n"
            "print('ezdxf' in sys.modules)\n"
            "with contextlib.redirect_stdout(io.StringIO()):\n"
            f"    assert main(['draw', {str(KIND_SAMPLES['gears'])!r}, '-o', {str(tmp_path)!r}, '--quiet',"
            " '--format', 'dxf']) == 0\n"
            "print('ezdxf' in sys.modules)\n")
    assert _run(code).split() == ["False", "False", "True"]
    for sh in drawn["gears"]:  # written by another process with other string hashes
        name = "seed_train.dxf" if len(drawn["gears"]) == 1 else f"seed_train-{sh.number}.dxf"
        assert (tmp_path / name).read_bytes() == sh.dxf()


def test_a4_portrait_sheet_is_210_by_297(tmp_path):
    from drawings.cams import draw

    sh = draw(SAMPLES / "cams" / "flat_face_poly345.toml", format="A4", orientation="portrait").sheets[0]
    doc = _read(sh.dxf())
    assert tuple(doc.header["$EXTMAX"])[:2] == (210.0, 297.0)
    border = next(e for e in doc.blocks.get("frame") if e.dxftype() == "LWPOLYLINE")
    ins = next(e for e in doc.modelspace() if e.dxf.name == "frame").dxf.insert
    xs = sorted({x + ins.x for x, _ in border.get_points("xy")})
    ys = sorted({y + ins.y for _, y in border.get_points("xy")})
    assert (xs, ys) == ([20.0, 205.0], [5.0, 292.0])
    assert differences(svg_shapes(sh.svg()), dxf_tags_shapes(sh.dxf())[0]) == []


OTHER_SAMPLES = sorted(p for d in ("gears", "cams", "engines") for p in (SAMPLES / d).glob("*.toml")
                       if p not in KIND_SAMPLES.values())


@pytest.mark.parametrize("path", OTHER_SAMPLES, ids=[p.stem for p in OTHER_SAMPLES])
def test_every_other_gears_cam_and_engine_sample_as_dxf(path):
    for sh in _draw(path):
        assert differences(svg_shapes(sh.svg()), dxf_tags_shapes(sh.dxf())[0]) == [], (path.name, sh.number)


def test_a_labels_runs_are_fitted_end_to_end_so_scripts_sit_where_the_svg_has_them(first):
    """Each run is a "fit" TEXT from its start to its end measured in the SVG's font: a
    script (a^n_BA, F_ур) starts where its base ends, in any CAD font."""
    from ezdxf.enums import TextEntityAlignment

    sh, doc = first
    joined = 0
    for block in doc.blocks:
        texts = [e for e in block if e.dxftype() == "TEXT"]
        for a, b in zip(texts, texts[1:], strict=False):
            assert a.get_placement()[0] == TextEntityAlignment.FIT
            assert a.dxf.align_point.x > a.dxf.insert.x and a.dxf.align_point.y == a.dxf.insert.y
            script = b.dxf.height < a.dxf.height and b.dxf.insert.y != a.dxf.insert.y
            if script and abs(b.dxf.insert.x - a.dxf.align_point.x) < 1.0:
                assert b.dxf.insert.x == pytest.approx(a.dxf.align_point.x, abs=0.01)
                joined += 1
    assert joined >= 20


def test_ezdxfs_own_renderer_draws_the_sheet_on_its_paper(drawn):
    """A third program's reading: ezdxf's drawing add-on renders the DXF (model space, mm)
    onto the sheet's page, every block's lines and text included, without complaint."""
    from ezdxf.addons.drawing import Frontend, RenderContext, layout
    from ezdxf.addons.drawing.svg import SVGBackend

    sh = drawn["gears"][-1]
    doc = _read(sh.dxf())
    backend = SVGBackend()
    Frontend(RenderContext(doc), backend).draw_layout(doc.modelspace(), finalize=True)
    page = layout.Page(sh.width, sh.height, layout.Units.mm, margins=layout.Margins.all(0))
    svg = backend.get_string(page, settings=layout.Settings(fit_page=False, scale=1.0))
    assert f'width="{sh.width:g}mm"' in svg and f'height="{sh.height:g}mm"' in svg
    lines = sum(1 for s in svg_shapes(sh.svg()) if s[0] in ("LINE", "LWPOLYLINE"))
    assert svg.count("<path") >= 1 and len(svg) > 20 * lines
