"""``plans note FILE... -o NOTE.docx [--language ru|en] [--format docx|pdf]``: the
explanatory note of a project's files as an editable Word document (or a PDF of it made
by LibreOffice, where it is installed)."""

from __future__ import annotations

import argparse
import os
import shutil
import subprocess
import tempfile
from pathlib import Path

from plans.errors import InputError, OutputError, Said


def register(sub: argparse._SubParsersAction) -> None:
    p = sub.add_parser("note", help="the explanatory note of the project's files (DOCX, or PDF via LibreOffice)")
    p.add_argument("files", nargs="+", metavar="FILE", help="scene, gears, cam, engine files (TOML)")
    p.add_argument("-o", "--output", required=True, metavar="NOTE.docx", help="the document to write")
    p.add_argument("--language", choices=("ru", "en"), default=None,
                   help="the note's language (default: the first file's [sheet] language, else the locale's)")
    p.add_argument("--format", choices=("docx", "pdf"), default=None,
                   help="docx (default) or pdf (through LibreOffice: soffice --headless)")
    p.add_argument("--dpi", type=float, default=200.0, help="the figures' resolution (default 200)")
    p.add_argument("--font", choices=("dejavu", "gost"),
                   help="overrides [sheet] font: gost is osifont, a GOST 2.304 type B font (apt-get install fonts-osifont)")
    p.set_defaults(func=run)


def _language(files: list[str]) -> str:
    from plans.io import read_toml
    from plans.language import choose

    return choose(None, read_toml(files[0]))


def run(args: argparse.Namespace) -> int:
    from plans.io import atomic_write, refuse_input

    fmt = args.format or ("pdf" if args.output.lower().endswith(".pdf") else "docx")
    refuse_input(args.output, *args.files)
    if not (0 < args.dpi <= 1200):
        raise InputError(Said("dc_dpi_out_range", dpi=args.dpi), file=args.files[0], field="--dpi")
    if Path(args.output).is_dir():
        raise InputError(Said("nc_output_folder_file", output=args.output), file=args.files[0],
                         field="--output")
    lang = args.language or _language(args.files)
    data = note_bytes(args.files, lang, args.dpi, getattr(args, "font", None))
    if fmt == "pdf":
        data = to_pdf(data)
    atomic_write(args.output, data)
    print(args.output)
    return 0


def note_bytes(files: list[str], lang: str | None = None, dpi: float = 200.0, font: str | None = None) -> bytes:
    """The note's DOCX bytes in ``lang`` (None: the first file's ``[sheet] language``, else
    the locale's): the files read and solved, the content built, the figures drawn (their
    words in ``font``; None: each file's ``[sheet] font``)."""
    from plans.note.build import build
    from plans.note.source import read

    from .docx_writer import write_docx
    from .figures import Figures

    items = read(list(files))
    lang = lang or _language(list(files))
    return write_docx(build(items, lang), Figures(items, lang, dpi, font))


def soffice() -> str | None:
    """LibreOffice's command where it is installed."""
    return shutil.which("soffice") or shutil.which("libreoffice")


def to_pdf(docx: bytes, timeout: float = 300.0) -> bytes:
    """A DOCX converted to PDF by LibreOffice (headless, its own profile in a temporary folder)."""
    exe = soffice()
    if exe is None:
        raise OutputError(Said("nc_format_pdf_needs"))
    with tempfile.TemporaryDirectory(prefix="plans-note-") as tmp:
        src = os.path.join(tmp, "note.docx")
        with open(src, "wb") as fh:
            fh.write(docx)
        cmd = [exe, f"-env:UserInstallation=file://{tmp}/profile", "--headless", "--convert-to", "pdf",
               "--outdir", tmp, src]
        try:
            subprocess.run(cmd, check=True, capture_output=True, timeout=timeout)
        except (subprocess.CalledProcessError, subprocess.TimeoutExpired) as exc:
            raise OutputError(Said("nc_libreoffice_could_convert", name=type(exc).__name__)) from None
        out = os.path.join(tmp, "note.pdf")
        if not os.path.exists(out):
            raise OutputError(Said("nc_libreoffice_wrote_pdf"))
        with open(out, "rb") as fh:
            return fh.read()



def note_figures(path: str, repeat: int = 3) -> dict[str, float]:
    """The best of ``repeat`` builds of a scene's note (read, solve, content, figures, DOCX),
    after one that loads the libraries as a command does once: wall and processor seconds."""
    import time

    note_bytes([path], "ru")
    wall = cpu = float("inf")
    size = 0
    for _ in range(max(1, repeat)):
        t, c = time.perf_counter(), time.process_time()
        size = len(note_bytes([path], "ru"))
        wall, cpu = min(wall, time.perf_counter() - t), min(cpu, time.process_time() - c)
    return {"seconds": wall, "cpu_seconds": cpu, "bytes": float(size)}


if __name__ == "__main__":  # ``python -m drawings.note.cli SCENE [REPEAT]``: the note's build time as JSON (bench)
    import json
    import sys

    print(json.dumps(note_figures(sys.argv[1], int(sys.argv[2]) if len(sys.argv) > 2 else 3)))
