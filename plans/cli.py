"""The ``plans`` command: solve, check, bench (``draw`` is added by drawings.cli,
since this package never imports the renderer)."""

from __future__ import annotations

import argparse
import importlib
import sys
from collections.abc import Sequence

from plans.errors import PlansError
from plans.io import atomic_write, dumps
from plans.results import solve_scene, table, to_json
from plans.scene.model import load_scene

#: Pure commands living in their own modules, each with ``register(subparsers)``; a module
#: that is absent is simply not offered.
_COMMAND_MODULES = ("plans.check.report", "plans.accuracy.bench", "plans.balancing.cli",
                    "plans.gears.cli", "plans.cams.cli")


def build_parser() -> argparse.ArgumentParser:
    parser = argparse.ArgumentParser(
        prog="plans",
        description="Velocity and acceleration plans, force polygons and the Zhukovsky lever "
                    "of planar linkages, built as a draftsman builds them and checked exactly.")
    sub = parser.add_subparsers(dest="command", required=True)
    s = sub.add_parser("solve", help="solve a scene: table per position, JSON")
    s.add_argument("scene", help="scene file (TOML)")
    s.add_argument("--json", metavar="PATH", help="write results as JSON ('-' for stdout)")
    s.add_argument("--csv", metavar="PATH", help="write the tables over the positions as CSV ('-' for stdout)")
    s.add_argument("--protocol", action="store_true", help="print the construction protocol")
    s.add_argument("--quiet", action="store_true", help="no table on stdout")
    s.set_defaults(func=_solve)
    register_commands(sub, _COMMAND_MODULES)
    return parser


def register_commands(sub: argparse._SubParsersAction, modules: Sequence[str]) -> None:
    """Let each module add its subcommand (``register(sub)``); an absent module is skipped."""
    for mod in modules:
        try:
            module = importlib.import_module(mod)
        except ModuleNotFoundError as exc:
            if exc.name is None or not (mod == exc.name or mod.startswith(exc.name + ".")):
                raise
            continue
        module.register(sub)


def _solve(args: argparse.Namespace) -> int:
    sol = solve_scene(load_scene(args.scene))
    if getattr(args, "csv", None):
        from plans.cycle.results import cycle_csv

        text = cycle_csv(sol.cycle) if sol.cycle is not None else ""
        if args.csv == "-":
            sys.stdout.write(text)
            return 0
        atomic_write(args.csv, text)
    if args.json == "-":
        sys.stdout.write(dumps(to_json(sol)))
        return 0
    if args.json:
        atomic_write(args.json, dumps(to_json(sol)))
    if not args.quiet:
        print(table(sol, protocol=args.protocol))
    return 0


def run(args: argparse.Namespace) -> int:
    """Run a parsed command; user errors become one line on stderr and status 2."""
    try:
        return int(args.func(args))
    except PlansError as exc:
        print(f"plans: error: {exc}", file=sys.stderr)
        return 2
    except OSError as exc:
        print(f"plans: error: {exc.filename or ''}: {exc.strerror}", file=sys.stderr)
        return 2


def main(argv: Sequence[str] | None = None) -> int:
    args = build_parser().parse_args(argv)
    return run(args)


if __name__ == "__main__":  # pragma: no cover
    raise SystemExit(main())
