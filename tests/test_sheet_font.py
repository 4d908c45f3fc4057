"""``[sheet] font = "gost"`` and ``plans draw --font``: the sheets in osifont (a GOST 2.304 type B
font), each character it does not draw in DejaVu Sans.

The oracle of what osifont draws is the font file itself read with fontTools (its character map
and its outlines: a glyph that is one filled rectangle is a placeholder, not a letter), not the
cairo probe the code uses; the rendered check goes through cairosvg as the PNG export does.
"""

from __future__ import annotations

import io
import re
import xml.etree.ElementTree as ET
from pathlib import Path

import pytest

from drawings.cli import main
from drawings.paper import fonts
from plans.errors import InputError
from plans.scene.sheet import read_sheet, sheet_spec

ROOT = Path(__file__).resolve().parents[1]
FOUR_BAR = ROOT / "samples" / "four_bar.toml"
OSIFONT = Path("/usr/share/fonts/truetype/osifont/osifont.ttf")


def _osifont() -> bool:
    try:
        return fonts.installed(fonts.GOST_FAMILY)
    except Exception:  # pragma: no cover - no cairo at all
        return False


needs_osifont = pytest.mark.skipif(not _osifont(), reason="osifont is not installed (apt-get install fonts-osifont)")


# --------------------------------------------------------------------------- the option


def test_the_option_is_read_and_defaults_to_dejavu():
    assert sheet_spec({}, "s.toml").font == "dejavu"
    assert sheet_spec({"sheet": {"font": "gost"}}, "s.toml").font == "gost"
    assert sheet_spec({"sheet": {"font": "gost"}}, "s.toml", font="dejavu").font == "dejavu"  # --font wins
    assert "font" not in read_sheet({}, "s.toml")  # absent: the record's default


@pytest.mark.parametrize("value", ["GOST", "times", 3, True, ["gost"]])
def test_a_wrong_font_is_one_error_naming_the_field(value):
    with pytest.raises(InputError) as e:
        sheet_spec({"sheet": {"font": value}}, "s.toml")
    assert e.value.field == "sheet.font" and "'dejavu', 'gost'" in str(e.value)
    assert str(e.value).count("\n") == 0


def test_every_command_refuses_a_wrong_font_in_the_file(tmp_path, capsys):
    from plans.cli import main as plans_main

    scene = tmp_path / "bad.toml"
    scene.write_text(FOUR_BAR.read_text(encoding="utf-8") + '\n[sheet]\nfont = "gots"\n', encoding="utf-8")
    rc = plans_main(["solve", str(scene), "--language", "en"])
    err = capsys.readouterr().err
    assert rc == 2 and err.count("\n") == 1 and "sheet.font" in err and "'gost'?" in err, err


def test_the_cli_option_and_its_refusal(tmp_path, capsys):
    with pytest.raises(SystemExit) as e:
        main(["draw", str(FOUR_BAR), "-o", str(tmp_path), "--font", "times"])
    assert e.value.code == 2 and "--font" in capsys.readouterr().err


@pytest.mark.parametrize("where", ["file", "cli"])
def test_gost_without_osifont_is_one_line_naming_field_and_package(tmp_path, capsys, monkeypatch, where):
    monkeypatch.setattr(fonts, "installed", lambda family: family == fonts.FONT_FAMILY)
    scene = tmp_path / "gost.toml"
    text = FOUR_BAR.read_text(encoding="utf-8")
    if where == "file":
        text = text.replace("[sheet]", '[sheet]\nfont = "gost"', 1) if "[sheet]" in text else \
            text + '\n[sheet]\nfont = "gost"\n'
    scene.write_text(text, encoding="utf-8")
    out = tmp_path / "out"
    rc = main(["draw", str(scene), "-o", str(out), "--quiet", "--language", "en"]
              + (["--font", "gost"] if where == "cli" else []))
    err = capsys.readouterr().err
    assert rc == 2 and err.count("\n") == 1 and "Traceback" not in err, err
    field = "sheet.font" if where == "file" else "--font"
    assert f"{field}: " in err and "osifont" in err and "apt-get install fonts-osifont" in err
    assert not out.exists()  # nothing half-written


def test_the_error_in_russian():
    from plans.errors import Said

    e = InputError(Said("e_font_missing", font="gost", family="osifont", install="apt-get install fonts-osifont"),
                   file="s.toml", field="sheet.font")
    ru = e.text("ru")
    assert "не установлен" in ru and "apt-get install fonts-osifont" in ru


# --------------------------------------------------------------------------- what osifont draws


@pytest.fixture(scope="module")
def truth():
    """What osifont draws by its file: mapped characters whose glyph is not one filled rectangle."""
    ttlib = pytest.importorskip("fontTools.ttLib")
    from fontTools.pens.recordingPen import RecordingPen

    if not OSIFONT.is_file():
        pytest.skip(f"{OSIFONT} not present")
    font = ttlib.TTFont(str(OSIFONT))
    glyphs = font.getGlyphSet()
    drawn = set()
    for code, name in font.getBestCmap().items():
        pen = RecordingPen()
        glyphs[name].draw(pen)
        ops = [op for op, _ in pen.value]
        rectangle = ops.count("moveTo") == 1 and ops.count("lineTo") in (3, 4) and len(ops) <= 6
        if not rectangle or chr(code) in "-_|.":
            drawn.add(chr(code))
    return drawn


@pytest.fixture(scope="module")
def gost_sheets():
    """A Russian four-bar's sheets in the GOST font: their SVG text."""
    if not _osifont():
        pytest.skip("osifont is not installed")
    from drawings.linkage import draw

    sheets = draw(FOUR_BAR, language="ru", font="gost").sheets
    return [sh.svg() for sh in sheets] + [sheets[0].dxf()]


def _runs(svg: str) -> list[tuple[str, str]]:
    """(text, family) of every text node of the SVG, the family inherited as SVG inherits it."""
    out: list[tuple[str, str]] = []

    def walk(el: ET.Element, family: str) -> None:
        family = el.get("font-family", family)
        tag = el.tag.rpartition("}")[2]
        if tag in ("text", "tspan") and el.text:
            out.append((el.text, family))
        for kid in el:
            walk(kid, family)

    walk(ET.fromstring(svg), "")
    return out


@needs_osifont
def test_every_character_osifont_lacks_is_in_dejavu_and_no_other(truth, gost_sheets):
    seen_osi, seen_dejavu = set(), set()
    for svg in gost_sheets[:-1]:
        for text, family in _runs(svg):
            chars = {c for c in text if not c.isspace()}
            assert family in (fonts.GOST_FAMILY, fonts.FONT_FAMILY), family
            (seen_osi if family == fonts.GOST_FAMILY else seen_dejavu).update(chars)
    assert seen_osi and seen_dejavu
    assert seen_osi <= truth, sorted(seen_osi - truth)  # nothing osifont lacks is written in it
    assert not seen_dejavu & truth, sorted(seen_dejavu & truth)  # nor in DejaVu what it has
    assert {"⊥", "∥", "†"} <= seen_dejavu  # the plans' and the lever's symbols are on these sheets


@needs_osifont
def test_the_symbols_of_every_sheet_fall_back(truth):
    """The characters the samples' sheets write (letters of both alphabets, Greek, the course's
    symbols): each laid out in osifont when it draws it, else in DejaVu Sans."""
    from drawings.paper.text import _layout0

    sample = ("АБВГДЕЁЖЗИЙКЛМНОПРСТУФХЦЧШЩЪЫЬЭЮЯабвгдеёжзийклмнопрстуфхцчшщъыьэюя"
              "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789"
              "ΔΣΦΩαβγδεηθλμπρτφψωϑ°±²³·×–—†′″₁₂−∠∥∫≤≥≈⊥№%()+,-./:;=[]|")
    lab = _layout0(sample, 5.0, "start", "baseline", "gost")
    assert "".join(r.text for r in lab.runs) == sample
    for run in lab.runs:
        inside = {c for c in run.text if not c.isspace()}
        assert inside <= truth if run.font == fonts.GOST_FAMILY else not inside & truth, (run.font, run.text)
    assert {c for c in sample if c not in truth} >= set("⊥∥†′″−")  # the font's gaps this test knows of


@needs_osifont
def test_each_run_is_measured_in_its_own_font():
    """The runs of a mixed label abut: each starts where the one before ends, measured by cairo
    in that run's family (a fresh context, not the layout's cache)."""
    import cairocffi as cairo

    from drawings.paper.text import layout

    def advance(text: str, family: str, size: float) -> float:
        ctx = cairo.Context(cairo.ImageSurface(cairo.FORMAT_A8, 1, 1))
        ctx.select_font_face(family)
        opts = cairo.FontOptions()
        opts.set_hint_metrics(cairo.HINT_METRICS_OFF)
        opts.set_hint_style(cairo.HINT_STYLE_NONE)
        ctx.set_font_options(opts)
        ctx.set_font_size(1000.0)
        return ctx.text_extents(text)[4] * size / 1000.0

    with fonts.use("gost"):
        lab = layout("Эпюра ⊥ AB − 2″, μ_F", 10.0, 20.0, 5.0)
    runs = lab.runs
    assert [r.font or fonts.FONT_FAMILY for r in runs] == ["DejaVu Sans", "osifont", "DejaVu Sans", "osifont",
                                                          "DejaVu Sans", "osifont", "DejaVu Sans", "osifont",
                                                          "osifont"]
    assert "".join(r.text for r in runs) == "Эпюра ⊥ AB − 2″, μF"
    for a, b in zip(runs, runs[1:], strict=False):  # the last is μ's subscript, from μ's end
        assert b.x == pytest.approx(a.x + advance(a.text, a.font or fonts.FONT_FAMILY, a.size), abs=1e-6)
    last = runs[-1]
    assert last.size < 5.0 and last.y > runs[0].y
    assert lab.box[2] == pytest.approx(last.x + advance(last.text, last.font, last.size), abs=1e-6)


def test_the_default_font_writes_no_family_but_the_sheets():
    from drawings.paper.backend import Recording
    from drawings.paper.svg import document
    from drawings.paper.text import layout

    rec = Recording()
    rec.text(layout("v_B ⊥ AB, μ_v", 0, 0, 3.5))
    svg = document(50, 20, rec.prims)
    assert svg.count("font-family") == 1  # the root group's
    assert fonts.current() == "dejavu"


# --------------------------------------------------------------------------- rendered


def _ink(png: bytes):
    import cairocffi as cairo
    import numpy as np

    surface = cairo.ImageSurface.create_from_png(io.BytesIO(png))
    a = np.frombuffer(bytes(surface.get_data()), np.uint8).reshape(surface.get_height(), surface.get_stride())
    return 255 - a[:, : surface.get_width() * 4].reshape(surface.get_height(), surface.get_width(), 4)[:, :, 1]


@needs_osifont
def test_the_rendered_sheet_characters_show_no_missing_glyph_box(gost_sheets):
    """Every (character, family) of the sheets' text drawn through cairosvg (the PNG export's
    path) in a cell of its own, written as the sheets write it (the family on the group, the
    text and a fallback's tspan, inherited by the others): none is blank, its family's .notdef
    glyph or a filled box, and each looks like its character in its family, not in the other."""
    import cairocffi as cairo
    import numpy as np
    from cairosvg.surface import PNGSurface

    from drawings.paper.convert import draw, tree

    pairs = sorted({(c, f) for svg in gost_sheets[:-1] for t, f in _runs(svg) for c in t if not c.isspace()})
    size, cell = 40, 60
    spans = "".join(f'<tspan{"" if f == fonts.GOST_FAMILY else f" font-family={chr(34)}{f}{chr(34)}"} '
                    f'x="{10 + cell * i}" y="{cell - 15}">{c}</tspan>' for i, (c, f) in enumerate(pairs))
    svg = (f'<svg xmlns="http://www.w3.org/2000/svg" width="{cell * len(pairs)}" height="{cell}">'
           f'<rect width="100%" height="100%" fill="#fff"/><g font-family="{fonts.FONT_FAMILY}">'
           f'<text font-family="{fonts.GOST_FAMILY}" font-size="{size}">{spans}</text></g></svg>')
    ink = _ink(draw(PNGSurface, tree(svg.replace("&", "&amp;").encode())))

    def alone(family: str, glyph: int | None = None, text: str = ""):
        """A cell drawn by cairo itself: ``text`` in ``family``, or its glyph number ``glyph``."""
        surface = cairo.ImageSurface(cairo.FORMAT_RGB24, cell, cell)
        ctx = cairo.Context(surface)
        ctx.set_source_rgb(1, 1, 1)
        ctx.paint()
        ctx.set_source_rgb(0, 0, 0)
        ctx.select_font_face(family)
        ctx.set_font_size(size)
        if glyph is not None:
            ctx.show_glyphs([(glyph, 10, cell - 15)])
        else:
            ctx.move_to(10, cell - 15)
            ctx.show_text(text)
        buf = io.BytesIO()
        surface.write_to_png(buf)
        return _ink(buf.getvalue()).astype(float)

    families = (fonts.GOST_FAMILY, fonts.FONT_FAMILY)
    boxes = {f: alone(f, glyph=0) for f in families}
    bad = []
    for i, (c, f) in enumerate(pairs):
        got = ink[:, cell * i: cell * (i + 1)].astype(float)
        if not got.any():
            bad.append((c, f, "blank"))
            continue
        if np.abs(got - boxes[f]).mean() < 2.0:
            bad.append((c, f, ".notdef"))
        ys, xs = np.nonzero(got > 128)
        h, w = (np.ptp(ys) + 1, np.ptp(xs) + 1) if ys.size else (0, 0)
        if h > 0.4 * size and w > 0.15 * size and (got[ys.min():ys.max() + 1, xs.min():xs.max() + 1] > 128).mean() > 0.9:
            bad.append((c, f, "filled box"))
        own, other = (np.abs(got - alone(g, text=c)).mean() for g in (f, families[f == fonts.GOST_FAMILY]))
        if not own < other:
            bad.append((c, f, "drawn in the other family"))
    assert not bad, bad
    assert len(pairs) > 100


# --------------------------------------------------------------------------- deterministic


@needs_osifont
def test_same_bytes_on_two_runs(gost_sheets):
    from drawings.linkage import draw
    from drawings.paper.text import _layout0

    _layout0.cache_clear()
    fonts.metrics.cache_clear()
    again = draw(FOUR_BAR, language="ru", font="gost").sheets
    assert [sh.svg() for sh in again] + [again[0].dxf()] == gost_sheets
    assert re.search(r'font-family="osifont"', gost_sheets[0])
    assert fonts.current() == "dejavu"  # the drawing's font did not leak out of it
