"""``plans gears FILE [--json PATH]``: a gear pair or train solved, the course's table."""

from __future__ import annotations

import argparse

from plans.language import file_command


def register(sub: argparse._SubParsersAction) -> None:
    p = file_command(sub, "gears", "involute gears and trains: geometry, checks, speeds (JSON)", "file",
                     "gear file (TOML, kind = \"gears\")", "write results as JSON ('-' for stdout)",
                     "no table on stdout")
    p.set_defaults(func=_run)


def _run(args: argparse.Namespace) -> int:
    from plans.io import dumps, json_out

    from .meshing import drawn_contact_ratios
    from .solution import solve_file
    from .solve import table, to_json

    sol = solve_file(args.file).solution
    data = dumps(to_json(sol, drawn_contact_ratios(sol)))
    if json_out(args.json, data):
        return 0
    if not args.quiet:
        from plans.language import file_language

        print(table(sol, file_language(getattr(args, "language", None), args.file)))
    return 0
