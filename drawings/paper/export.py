"""Writing sheets: SVG text, PDF and PNG (cairosvg, through :mod:`drawings.paper.convert`), DXF
(ezdxf, through :mod:`drawings.paper.dxf`), each file atomically."""

from __future__ import annotations

import os
from collections.abc import Callable, Sequence
from pathlib import Path
from typing import TYPE_CHECKING, Any

from plans.errors import OutputError, Said
from plans.io import atomic_write  # noqa: F401  (re-exported by drawings)

if TYPE_CHECKING:  # the sheet's modules (svgwrite, numpy) load only when a sheet is drawn
    from drawings.paper.sheet import Sheet

FORMATS = ("svg", "pdf", "png", "dxf")


def svg_bytes(sheet: Sheet) -> bytes:
    return sheet.svg().encode("utf-8")


def dxf_bytes(sheet: Sheet) -> bytes:
    """The sheet as DXF (R2010, mm, 1:1; ezdxf is loaded here, when DXF is asked for)."""
    return sheet.dxf()


#: A fixed creation date: the same sheet gives the same PDF bytes.
PDF_DATE = "2000-01-01T00:00:00Z"


def pdf_bytes(svg: bytes | Any, title: str = "") -> bytes:
    """SVG -> PDF at 1:1 (the page is the sheet in points), with fixed metadata; ``svg`` is
    the document's bytes or its tree parsed once (:func:`drawings.paper.convert.tree`)."""
    import cairocffi
    from cairosvg.surface import PDFSurface

    from drawings.paper import convert

    class _Pdf(PDFSurface):
        def _create_surface(self, width, height):
            surface, w, h = super()._create_surface(width, height)
            surface.set_metadata(cairocffi.PDF_METADATA_CREATE_DATE, PDF_DATE)
            surface.set_metadata(cairocffi.PDF_METADATA_CREATOR, "plans (drawings)")
            if title:
                surface.set_metadata(cairocffi.PDF_METADATA_TITLE, title)
            return surface, w, h

    return convert.draw(_Pdf, convert.tree(svg) if isinstance(svg, bytes) else svg)


def png_bytes(svg: bytes | Any, dpi: float) -> bytes:
    """SVG -> PNG (bytes or a parsed tree, as :func:`pdf_bytes`): cairosvg draws the page,
    the pixels are written here (cairo's own PNG writer, with libpng's adaptive filters,
    took as long as drawing an A1 sheet)."""
    from cairosvg.surface import PNGSurface, Surface

    from drawings.paper import convert

    class _Png(PNGSurface):
        def finish(self):
            self.cairo.flush()
            if self.output is not None:
                self.output.write(encode_png(self.cairo))
            return Surface.finish(self)

    return convert.draw(_Png, convert.tree(svg) if isinstance(svg, bytes) else svg, dpi)


def encode_png(surface) -> bytes:
    """An ARGB32 cairo image surface as an RGBA PNG: the pixels cairo's writer stores
    (un-premultiplied as cairo does it), rows unfiltered, deflated by ISA-L (isal, eight
    times zlib's speed on a sheet, and a smaller file; zlib where isal is not installed)."""
    import struct
    import zlib

    import numpy as np

    compress: Callable[[Any, int], bytes] = zlib.compress
    level = 3
    try:
        from isal.isal_zlib import compress

        level = 1
    except ImportError:  # pragma: no cover - isal is a dependency; the same pixels without it
        pass
    w, h, stride = surface.get_width(), surface.get_height(), surface.get_stride()
    argb = np.frombuffer(surface.get_data(), np.uint32).reshape(h, stride // 4)[:, :w]
    idat = compress(_rgba_rows(argb).data, level)

    def chunk(kind: bytes, data: bytes) -> bytes:
        return struct.pack(">I", len(data)) + kind + data + struct.pack(">I", zlib.crc32(kind + data))

    return (b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", struct.pack(">IIBBBBB", w, h, 8, 6, 0, 0, 0))
            + chunk(b"IDAT", idat) + chunk(b"IEND", b""))


def _rgba_rows(argb: Any) -> Any:
    """Rows of premultiplied native ARGB words as PNG rows: a 0 (no filter), then R G B A
    un-premultiplied as cairo's writer does it."""
    import numpy as np

    h, w = argb.shape
    # cairo keeps A R G B in a native (little-endian) word, bytes B G R A; byte-swapped
    # the word reads B G R A from the top, turned right by 8 bits A B G R: bytes R G B A
    bs = argb.byteswap()
    rgba = np.right_shift(bs, 8)
    np.left_shift(bs, 24, out=bs)
    rgba |= bs
    odd = np.flatnonzero(argb < 0xFF000000)  # alpha below 255
    if odd.size:  # cairo's unpremultiply: (c·255 + a/2) / a, integer; 0 where a = 0
        flat = rgba.reshape(-1)
        px = flat[odd]
        a = px >> 24
        seen = np.maximum(a, 1)
        out = a << 24
        for shift in (0, 8, 16):
            c = (px >> shift) & 0xFF
            out |= np.where(a > 0, (c * 255 + seen // 2) // seen, 0) << shift
        flat[odd] = out
    raw = np.empty((h, 1 + 4 * w), np.uint8)
    raw[:, 0] = 0
    raw[:, 1:] = rgba.view(np.uint8).reshape(h, 4 * w)
    return raw


def render(sheets: Sequence[Sheet], outdir: str | Path, stem: str, formats: Sequence[str] = ("svg",),
           dpi: float = 150.0, progress: Callable[[str], None] | None = None) -> dict[Path, bytes]:
    """Every sheet in every format as bytes, by target path: ``stem.svg`` (one sheet) or
    ``stem-2.svg`` ...; nothing is written."""
    out = Path(outdir)
    for f in formats:
        if f not in FORMATS:
            raise OutputError(Said("pe_unknown_output_format", f=f, v=', '.join(FORMATS)))
    if not (dpi > 0 and dpi <= 1200):
        raise OutputError(Said("pe_dpi_dpi_out", dpi=dpi))
    files: dict[Path, bytes] = {}
    for sh in sheets:
        name = stem if len(sheets) == 1 else f"{stem}-{sh.number}"
        svg = svg_bytes(sh)
        doc = None  # parsed once for both PDF and PNG
        for f in formats:
            p = out / f"{name}.{f}"
            if f in ("svg", "dxf"):
                files[p] = svg if f == "svg" else dxf_bytes(sh)
                continue
            if doc is None:
                from drawings.paper.convert import tree

                doc = tree(svg)
            files[p] = pdf_bytes(doc) if f == "pdf" else png_bytes(doc, dpi)
        if progress is not None:
            from plans.errors import run_language
            from plans.phrases import say

            progress(say("dr_sheet", run_language(), n=sh.number, total=len(sheets), formats=", ".join(formats)))
    return files


def write(files: dict[Path, bytes], outdir: str | Path, *, source: str | Path | None = None) -> list[Path]:
    """Write rendered files as one (an error leaves none of them); with ``source`` the
    folder's manifest removes that input's old sheets the new set lacks and refuses to
    overwrite another input's sheets (:mod:`drawings.paper.manifest`)."""
    from drawings.paper.manifest import write_sheets

    out = Path(outdir)
    try:
        out.mkdir(parents=True, exist_ok=True)
    except OSError as exc:
        raise OutputError(Said("cc_cannot_create_output", out=out, strerror=exc.strerror)) from None
    if not os.access(out, os.W_OK):
        raise OutputError(Said("pe_cannot_write_out", out=out))
    return write_sheets(out, files, source)


def save(sheets: Sequence[Sheet], outdir: str | Path, stem: str, formats: Sequence[str] = ("svg",),
         dpi: float = 150.0, progress: Callable[[str], None] | None = None, *,
         source: str | Path | None = None) -> list[Path]:
    """Render every sheet in every format, then write them all as one (see :func:`write`)."""
    return write(render(sheets, outdir, stem, formats, dpi, progress), outdir, source=source)
