"""PNG pixels are written by drawings.paper.export itself: the same page as cairo's own writer."""

from __future__ import annotations

import io
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent


def _pixels(png: bytes) -> tuple[int, int, bytes]:
    import cairocffi as cairo

    s = cairo.ImageSurface.create_from_png(io.BytesIO(png))
    return s.get_width(), s.get_height(), bytes(s.get_data())


def test_png_has_the_pixels_of_cairos_writer_and_is_deterministic():
    import cairosvg

    from drawings import draw
    from drawings.paper.export import png_bytes

    sheet = draw(str(ROOT / "samples" / "four_bar.toml")).sheets[0]
    svg = sheet.svg().encode()
    ours = png_bytes(svg, 40)
    theirs = cairosvg.svg2png(bytestring=svg, dpi=40)
    assert ours.startswith(b"\x89PNG\r\n\x1a\n")
    assert _pixels(ours) == _pixels(theirs)
    assert png_bytes(svg, 40) == ours


def test_translucent_ink_is_unpremultiplied_as_cairo_does():
    import cairosvg

    from drawings.paper.export import png_bytes

    svg = (b'<svg xmlns="http://www.w3.org/2000/svg" width="40" height="20">'
           b'<rect x="2" y="2" width="30" height="10" fill="#3a7fd0" fill-opacity="0.37"/>'
           b'<circle cx="20" cy="10" r="7.3" fill="none" stroke="#c02020" stroke-width="1.3"/></svg>')
    assert _pixels(png_bytes(svg, 96)) == _pixels(cairosvg.svg2png(bytestring=svg, dpi=96))


def test_svg_is_written_as_svgwrite_writes_it():
    import svgwrite

    from drawings import draw
    from drawings.paper.svg import SvgBackend, serialize

    sheet = draw(str(ROOT / "samples" / "shaper.toml")).sheets[0]
    be = SvgBackend(100, 50, title='a "quoted" <title> & more')
    be.dwg.defs.add(be.dwg.style(".link{stroke-width:0.7}"))
    t = be.dwg.text("", insert=(1, 2))
    t.add(be.dwg.tspan("v_B < 1 & a > 2", dy=["1"]))
    be.dwg.add(t)
    be.dwg.add(be.dwg.line((0, 0), (1, 1), stroke="#000", id="x\ny\t\"z\""))
    be.dwg.add(be.dwg.use("#x", insert=(0, 0)))
    be.dwg.add(be.dwg.g())
    for dwg in (be.dwg, svgwrite.Drawing(size=("10mm", "10mm"))):
        assert serialize(dwg) == dwg.tostring()
    assert sheet.svg().startswith("<svg ")


def test_pdf_is_cairosvgs_own_page_byte_for_byte():
    """Labels drawn by drawings.paper.convert leave the PDF cairosvg itself writes."""
    import cairocffi
    import cairosvg
    from cairosvg.surface import PDFSurface

    from drawings import draw
    from drawings.paper.export import PDF_DATE, pdf_bytes

    class Plain(PDFSurface):  # cairosvg as it is, with our fixed metadata
        def _create_surface(self, width, height):
            surface, w, h = super()._create_surface(width, height)
            surface.set_metadata(cairocffi.PDF_METADATA_CREATE_DATE, PDF_DATE)
            surface.set_metadata(cairocffi.PDF_METADATA_CREATOR, "plans (drawings)")
            return surface, w, h

    svg = draw(str(ROOT / "samples" / "four_bar.toml")).sheets[0].svg().encode()
    out = io.BytesIO()
    Plain.convert(bytestring=svg, write_to=out)
    assert pdf_bytes(svg) == out.getvalue()
    # a label outside what the fast drawer takes (anchor, letter offsets, stroke) goes to cairosvg
    odd = (b'<svg xmlns="http://www.w3.org/2000/svg" width="60" height="30">'
           b'<text x="30" y="10" text-anchor="middle" font-size="6">mid</text>'
           b'<text x="2 8 14" y="20" font-size="6" stroke="#c00">abc</text>'
           b'<text font-size="5"><tspan x="3" y="27">v</tspan><tspan x="6" y="28" font-size="3">B</tspan></text>'
           b'<g stroke-dasharray="2 1" stroke-linejoin="bevel"><path d="M30,20 L50,25 L40,5" stroke="#00f" fill="none"'
           b' stroke-width="1.5"/></g><line x1="5" y1="5" x2="25" y2="8" stroke="#000" transform="rotate(10)"/>'
           b'<circle cx="50" cy="8" r="4" fill="#0a0" opacity="0.5" stroke="#000"/></svg>')
    assert _pixels(png_bytes_of(odd)) == _pixels(cairosvg.svg2png(bytestring=odd, dpi=96))


def png_bytes_of(svg: bytes) -> bytes:
    from drawings.paper.export import png_bytes

    return png_bytes(svg, 96)


def test_sheet_text_is_the_svgwrite_backends():
    """Sheets are written as text directly (drawings.paper.svg.document): the same characters as
    the svgwrite backend writes, for a linkage, a cycle and a gear sheet."""
    from drawings import draw
    from drawings.gears import draw as draw_gears
    from drawings.paper.backend import replay
    from drawings.paper.svg import SvgBackend

    sheets = draw(str(ROOT / "samples" / "dynamics_slider_crank.toml")).sheets
    sheets += draw_gears(str(ROOT / "samples" / "gears" / "seed_train.toml")).sheets
    assert len(sheets) >= 3
    for sh in sheets:
        be = SvgBackend(sh.width, sh.height)
        replay(sh.prims or sh.render(), be)
        assert sh.svg() == be.tostring()
    panel = draw(str(ROOT / "samples" / "four_bar.toml")).panels[0]
    be = SvgBackend(panel.width, panel.height)
    replay(panel.prims, be)
    assert panel.svg() == be.tostring()
