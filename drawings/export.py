"""Writing sheets: SVG (svgwrite), PDF and PNG (cairosvg), each file atomically."""

from __future__ import annotations

import os
from collections.abc import Callable, Sequence
from pathlib import Path
from typing import TYPE_CHECKING

from plans.errors import OutputError
from plans.io import atomic_write

if TYPE_CHECKING:  # the sheet's modules (svgwrite, numpy) load only when a sheet is drawn
    from .sheet import Sheet

FORMATS = ("svg", "pdf", "png")


def svg_bytes(sheet: Sheet) -> bytes:
    return sheet.svg().encode("utf-8")


#: A fixed creation date: the same sheet gives the same PDF bytes.
PDF_DATE = "2000-01-01T00:00:00Z"


def pdf_bytes(svg: bytes, title: str = "") -> bytes:
    """SVG -> PDF at 1:1 (the page is the sheet in points), with fixed metadata."""
    import io

    import cairocffi
    from cairosvg.surface import PDFSurface

    class _Pdf(PDFSurface):
        def _create_surface(self, width, height):
            surface, w, h = super()._create_surface(width, height)
            surface.set_metadata(cairocffi.PDF_METADATA_CREATE_DATE, PDF_DATE)
            surface.set_metadata(cairocffi.PDF_METADATA_CREATOR, "plans (drawings)")
            if title:
                surface.set_metadata(cairocffi.PDF_METADATA_TITLE, title)
            return surface, w, h

    out = io.BytesIO()
    _Pdf.convert(bytestring=svg, write_to=out)
    return out.getvalue()


def png_bytes(svg: bytes, dpi: float) -> bytes:
    import cairosvg

    return cairosvg.svg2png(bytestring=svg, dpi=dpi)


def save(sheets: Sequence[Sheet], outdir: str | Path, stem: str, formats: Sequence[str] = ("svg",),
         dpi: float = 150.0, progress: Callable[[str], None] | None = None) -> list[Path]:
    """Write every sheet in every format: ``stem.svg`` (one sheet) or ``stem-2.svg`` ..."""
    out = Path(outdir)
    for f in formats:
        if f not in FORMATS:
            raise OutputError(f"unknown output format {f!r}; expected some of {', '.join(FORMATS)}")
    if not (dpi > 0 and dpi <= 1200):
        raise OutputError(f"dpi {dpi:g} is out of range; expected 1..1200")
    try:
        out.mkdir(parents=True, exist_ok=True)
    except OSError as exc:
        raise OutputError(f"cannot create the output folder {out}: {exc.strerror}") from None
    if not os.access(out, os.W_OK):
        raise OutputError(f"cannot write to {out}: permission denied")
    written = []
    for sh in sheets:
        name = stem if len(sheets) == 1 else f"{stem}-{sh.number}"
        svg = svg_bytes(sh)
        for f in formats:
            p = out / f"{name}.{f}"
            data = svg if f == "svg" else pdf_bytes(svg) if f == "pdf" else png_bytes(svg, dpi)
            atomic_write(p, data)
            written.append(p)
        if progress is not None:
            progress(f"sheet {sh.number} of {len(sheets)} written ({', '.join(formats)})")
    return written
