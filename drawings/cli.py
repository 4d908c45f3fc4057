"""The ``plans`` console command with ``draw``: the parser of :mod:`plans.cli` plus one
subcommand that needs the renderer (``plans`` itself never imports ``drawings``)."""

from __future__ import annotations

import argparse
import importlib
from collections.abc import Sequence
from typing import Any

from plans.cli import command_of, only_command, register_commands
from plans.cli import main as plans_main
from plans.errors import InputError, Said

#: Commands that need the renderer, listed without importing them (see plans.cli).
_DRAWING_NAMES = {"drawings.demo": ("demo", "a step-by-step demonstration page of a scene's analysis"),
                  "drawings.note.cli": ("note", "the explanatory note of the project's files (DOCX, or PDF via LibreOffice)"),
                  "drawings.variants": ("variants", "a group's variants from a variant table: files, keys, "
                                                    "forms, handouts"),
                  "drawings.workbench": ("serve", "the workbench: edit, solve, check and export a mechanism in the browser")}


def _formats(text: str) -> list[str]:
    from drawings.paper.export import FORMATS  # the renderer is loaded by ``draw`` alone

    out = [f.strip().lower() for f in text.split(",") if f.strip()]
    bad = [f for f in out if f not in FORMATS]
    if bad or not out:
        from plans.errors import Said, run_language

        raise argparse.ArgumentTypeError(Said("dc_formats", formats=",".join(FORMATS), got=repr(text)).text(run_language()))
    return out


def add_draw(sub: argparse._SubParsersAction) -> argparse.ArgumentParser:
    p = sub.add_parser("draw", help="draw the scene's sheets (A1..A4) as SVG, PDF, PNG, DXF")
    p.add_argument("scene", help="scene file (TOML)")
    p.add_argument("-o", "--output", required=True, metavar="DIR", help="output folder")
    p.add_argument("--format", type=_formats, default=["svg"], metavar="svg,pdf,png,dxf",
                   help="comma-separated output formats (default svg)")
    p.add_argument("--sheet", metavar="A1", help="sheet format A1..A4 (overrides [sheet] format)")
    p.add_argument("--orientation", choices=("landscape", "portrait"), help="overrides [sheet] orientation")
    p.add_argument("--language", choices=("ru", "en"), help="overrides [sheet] language")
    p.add_argument("--font", choices=("dejavu", "gost"),
                   help="overrides [sheet] font: gost is osifont, a GOST 2.304 type B font (apt-get install fonts-osifont)")
    p.add_argument("--dpi", type=float, default=150.0, help="PNG resolution (default 150)")
    p.add_argument("--quiet", action="store_true", help="no progress lines on a terminal")
    p.set_defaults(func=draw_command)
    return p


def draw_command(args: argparse.Namespace) -> int:
    """``plans draw``: build the sheets of any file of the family (linkage scene, engine,
    gears, cam: dispatched on its ``kind``), write them atomically, list what was written."""

    from pathlib import Path

    from drawings.paper.export import save
    from plans.kinds import KINDS, read_kind
    from plans.progress import Progress

    progress = Progress(getattr(args, "quiet", False))

    if not (0 < args.dpi <= 1200):
        raise InputError(Said("dc_dpi_out_range", dpi=args.dpi), file=args.scene, field="--dpi")
    if Path(args.output).exists() and not Path(args.output).is_dir():
        raise InputError(Said("dc_output_file_folder", output=args.output), file=args.scene,
                         field="--output")
    kind, _ = read_kind(args.scene)
    try:
        module = importlib.import_module(KINDS[kind][1])
    except ModuleNotFoundError as exc:
        if exc.name is None or not KINDS[kind][1].startswith(exc.name):
            raise
        raise InputError(Said("dc_drawing_kind_files", kind=kind),
                         file=args.scene, field="kind") from None
    from plans.errors import run_language
    from plans.phrases import say

    progress(say("dr_drawing", run_language(), scene=args.scene))
    options = {"font": args.font} if getattr(args, "font", None) else {}
    drawing = module.draw(args.scene, format=args.sheet, orientation=args.orientation,
                          language=args.language, **options)
    written = save(drawing.sheets, args.output, Path(args.scene).stem, args.format, args.dpi,
                   progress=progress, source=args.scene)
    for p in written:
        print(p)
    return 0


#: Commands that need the renderer, each module with ``register(subparsers)``; a module
#: that is absent is simply not offered.
_DRAWING_COMMANDS = ("drawings.demo", "drawings.note.cli", "drawings.variants", "drawings.workbench")


def _sheet_figures(paths: list[str], repeat: int) -> dict[str, Any]:
    """The sheets' times for ``plans bench`` (:func:`drawings.bench.figures`), loaded when run."""
    from drawings.bench import figures

    return figures(paths, repeat)


def _diagrams_seconds(path: Any, repeat: int) -> float:
    """The cycle's diagrams sheet to SVG for ``plans bench``, loaded when run."""
    from drawings.cycle import diagrams_sheet_seconds

    return diagrams_sheet_seconds(path, repeat)


def _note_figures(path: str, repeat: int) -> dict[str, float]:
    """The note's build for ``plans bench`` (:func:`drawings.note.cli.note_figures`), loaded when run."""
    from drawings.note.cli import note_figures

    return note_figures(path, repeat)


def _page_figures(path: str) -> dict[str, Any]:
    """The demonstration page for ``plans bench`` (:func:`drawings.demo.page_figures`), loaded when run."""
    from drawings.demo import page_figures

    return page_figures(path)


def _workbench_figures(path: Any) -> dict[str, Any]:
    """The workbench's round trip and start for ``plans bench``, loaded when run."""
    from drawings.workbench.bench import figures

    return figures(path)


def _register_bench_timers() -> None:
    """``plans bench`` times the renderer's work through its public functions, in process."""
    from plans.accuracy import cycle_bench, group_bench, speed, workbench_bench

    cycle_bench.SHEET_TIMERS.setdefault("cycle diagrams sheet", _diagrams_seconds)
    _once(speed.SHEET_FIGURES, _sheet_figures)
    _once(speed.NOTE_FIGURES, _note_figures)
    _once(speed.PAGE_FIGURES, _page_figures)
    _once(workbench_bench.FIGURES, _workbench_figures)
    _once(group_bench.COMMAND, main)


def _once(timers: list[Any], timer: Any) -> None:
    if timer not in timers:
        timers.append(timer)


def build_parser(argv: Sequence[str] | None = None) -> argparse.ArgumentParser:
    """The engine's parser (solve, check, bench, ...) with ``draw`` and the other
    commands that need the renderer added (with ``argv``: only the command asked for
    imported, see :func:`plans.cli.build_parser`)."""
    try:
        from plans.cli import build_parser as base
    except ImportError:  # pragma: no cover - the engine's CLI not written yet
        parser = argparse.ArgumentParser(prog="plans")
        sub = parser.add_subparsers(dest="command", required=True)
        add_draw(sub)
        return parser
    parser = base(argv)
    sub = next(a for a in parser._actions if isinstance(a, argparse._SubParsersAction))
    if only_command(argv) is None:  # else one of the engine's commands comes first: it alone is built
        add_draw(sub)
        register_commands(sub, _DRAWING_COMMANDS, argv, _DRAWING_NAMES)
    if "bench" in sub.choices and (argv is None or command_of(argv) == "bench"):
        from drawings.bench_plot import (
            add_plot,  # ``plans bench`` draws bench.svg with the sheets' backend
        )

        add_plot(sub.choices["bench"])
        _register_bench_timers()  # and times the sheets (through drawings.draw), the note, the page, ...
    if "check" in sub.choices and (argv is None or command_of(argv) == "check"):  # ``plans check --sheet DIR``: the marked and overlay sheets
        try:
            from drawings.check_sheet import add_sheet_options
        except ImportError:  # pragma: no cover - checking sheets not installed
            pass
        else:
            add_sheet_options(sub.choices["check"])
    return parser


def main(argv: Sequence[str] | None = None) -> int:
    """Every command, draw included, runs through the engine's main and runner (one-line
    errors, exit 2)."""
    return plans_main(argv, build_parser)


if __name__ == "__main__":  # pragma: no cover
    raise SystemExit(main())
