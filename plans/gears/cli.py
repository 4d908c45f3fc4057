"""``plans gears FILE [--json PATH]``: a gear pair or train solved, the course's table."""

from __future__ import annotations

import argparse
import sys


def register(sub: argparse._SubParsersAction) -> None:
    p = sub.add_parser("gears", help="involute gears and trains: geometry, checks, speeds (JSON)")
    p.add_argument("file", help="gear file (TOML, kind = \"gears\")")
    p.add_argument("--json", metavar="PATH", help="write results as JSON ('-' for stdout)")
    p.add_argument("--quiet", action="store_true", help="no table on stdout")
    from plans.language import add_option

    add_option(p)
    p.set_defaults(func=_run)


def _run(args: argparse.Namespace) -> int:
    from plans.io import atomic_write, dumps

    from .meshing import drawn_contact_ratios
    from .solution import solve_file
    from .solve import table, to_json

    sol = solve_file(args.file).solution
    data = dumps(to_json(sol, drawn_contact_ratios(sol)))
    if args.json == "-":
        sys.stdout.write(data)
        return 0
    if args.json:
        atomic_write(args.json, data)
    if not args.quiet:
        from plans.language import file_language

        print(table(sol, file_language(getattr(args, "language", None), args.file)))
    return 0
