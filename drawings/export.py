"""Writing sheets: SVG (svgwrite), PDF and PNG (cairosvg), each file atomically."""

from __future__ import annotations

import os
from collections.abc import Sequence
from pathlib import Path

from plans.errors import OutputError
from plans.io import atomic_write  # noqa: F401  (re-exported by drawings)

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


def render(sheets: Sequence[Sheet], outdir: str | Path, stem: str, formats: Sequence[str] = ("svg",),
           dpi: float = 150.0) -> dict[Path, bytes]:
    """Every sheet in every format as bytes, by target path: ``stem.svg`` (one sheet) or
    ``stem-2.svg`` ...; nothing is written."""
    out = Path(outdir)
    for f in formats:
        if f not in FORMATS:
            raise OutputError(f"unknown output format {f!r}; expected some of {', '.join(FORMATS)}")
    if not (dpi > 0 and dpi <= 1200):
        raise OutputError(f"dpi {dpi:g} is out of range; expected 1..1200")
    files: dict[Path, bytes] = {}
    for sh in sheets:
        name = stem if len(sheets) == 1 else f"{stem}-{sh.number}"
        svg = svg_bytes(sh)
        for f in formats:
            p = out / f"{name}.{f}"
            files[p] = svg if f == "svg" else pdf_bytes(svg) if f == "pdf" else png_bytes(svg, dpi)
    return files


def write(files: dict[Path, bytes], outdir: str | Path, *, source: str | Path | None = None) -> list[Path]:
    """Write rendered files as one (an error leaves none of them); with ``source`` the
    folder's manifest removes that input's old sheets the new set lacks and refuses to
    overwrite another input's sheets (:mod:`drawings.manifest`)."""
    from .manifest import write_sheets

    out = Path(outdir)
    try:
        out.mkdir(parents=True, exist_ok=True)
    except OSError as exc:
        raise OutputError(f"cannot create the output folder {out}: {exc.strerror}") from None
    if not os.access(out, os.W_OK):
        raise OutputError(f"cannot write to {out}: permission denied")
    return write_sheets(out, files, source)


def save(sheets: Sequence[Sheet], outdir: str | Path, stem: str, formats: Sequence[str] = ("svg",),
         dpi: float = 150.0, *, source: str | Path | None = None) -> list[Path]:
    """Render every sheet in every format, then write them all as one (see :func:`write`)."""
    return write(render(sheets, outdir, stem, formats, dpi), outdir, source=source)
