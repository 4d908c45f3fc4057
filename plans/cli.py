"""The ``plans`` command: solve, check, bench (``draw`` is added by drawings.cli,
since this package never imports the renderer)."""

from __future__ import annotations

import argparse
import importlib
import os
import sys
from collections.abc import Callable, Sequence
from typing import Any, NoReturn

from plans.errors import InputError, PlansError, error_prefix, one_line, set_run

#: Pure commands living in their own modules, each with ``register(subparsers)``; a module
#: that is absent is simply not offered.
_COMMAND_MODULES = ("plans.check_command", "plans.accuracy.bench", "plans.balancing.cli",
                    "plans.gears.cli", "plans.cams.cli", "plans.synthesis.cli")
#: The command each module adds and its one-line help, to list it (``plans --help``) or to
#: run another command without importing it: start-up stays a fraction of a second.
_COMMAND_NAMES = {
    "plans.check_command": ("check", "check a hand-drawn sheet (or a folder of them) against the exact analysis"),
    "plans.accuracy.bench": ("bench", "error against run time of every method; stability; hand-drawing error"),
    "plans.balancing.cli": ("balance", "engine balancing: force and moment polygons, counterweights"),
    "plans.gears.cli": ("gears", "involute gears and trains: geometry, checks, speeds (JSON)"),
    "plans.cams.cli": ("cam", "a cam: motion laws, base radius, profile by inversion (JSON)"),
    "plans.synthesis.cli": ("design", "design a mechanism from K, stroke, swing; prove it; write its scene"),
}


def command_of(argv: Sequence[str] | None) -> str | None:
    """The command named in ``argv`` (None: none named, e.g. ``plans --help``)."""
    return next((a for a in argv if not a.startswith("-")), None) if argv is not None else None


def _columns() -> int:
    """The terminal's width as ``shutil.get_terminal_size().columns`` gives it: $COLUMNS,
    else the terminal's own, else 80."""
    try:
        columns = int(os.environ["COLUMNS"])
    except (KeyError, ValueError):
        columns = 0
    if columns <= 0:
        try:
            columns = os.get_terminal_size(sys.__stdout__.fileno()).columns  # type: ignore[union-attr]
        except (AttributeError, ValueError, OSError):
            columns = 0
        columns = columns or 80
    return columns


class Formatter(argparse.HelpFormatter):
    """argparse's help formatter at the width it would pick itself, found without importing
    shutil (and the compression modules it loads): argparse makes a formatter for every
    option it adds, so every command would pay for them."""

    def __init__(self, prog: str, *args: Any, **kwargs: Any) -> None:
        if len(args) < 3 and kwargs.get("width") is None:
            kwargs["width"] = _columns() - 2
        super().__init__(prog, *args, **kwargs)


class Parser(argparse.ArgumentParser):
    """argparse with every usage error as one line, like every other error of ``plans``;
    its subcommands' parsers are of this class too (argparse makes them so)."""

    def __init__(self, *args: Any, **kwargs: Any) -> None:
        kwargs.setdefault("formatter_class", Formatter)
        super().__init__(*args, **kwargs)

    def error(self, message: str) -> NoReturn:
        from plans.errors import Said, run_language
        from plans.language import argparse_text

        lang = run_language()
        self.exit(2, f"{error_prefix(lang)}{self.prog.split(' ', 1)[-1] + ': ' if ' ' in self.prog else ''}"
                     f"{argparse_text(' '.join(message.split()), lang)}{Said('a_see_help').text(lang)}\n")

    def format_help(self) -> str:
        """The help in the run's language: argparse's own words (usage, the headings, -h's
        line) and the commands' and options' help (:data:`plans.messages_help.HELP_RU`)."""
        from plans.errors import run_language

        lang = run_language()
        if lang != "ru":
            return super().format_help()
        from plans.language import argparse_text
        from plans.messages_help import HELP_RU

        def ru(text: str | None) -> str | None:
            return text and (HELP_RU.get(text) or argparse_text(text, lang))

        saved: list[tuple[Any, str, Any]] = [(self, "description", self.description)]
        saved += [(g, "title", g.title) for g in self._action_groups]
        for a in self._actions:
            saved.append((a, "help", a.help))
            if isinstance(a, argparse._SubParsersAction):
                saved += [(c, "help", c.help) for c in a._choices_actions]
        try:
            for obj, name, text in saved:
                setattr(obj, name, ru(text))
            return super().format_help().replace("usage: ", argparse_text("usage: ", lang), 1)
        finally:
            for obj, name, text in saved:
                setattr(obj, name, text)

    def format_usage(self) -> str:
        from plans.errors import run_language
        from plans.language import argparse_text

        return super().format_usage().replace("usage: ", argparse_text("usage: ", run_language()), 1)


def only_command(argv: Sequence[str] | None) -> str | None:
    """The command asked for when it is the first word of ``argv`` and one of the engine's
    (``plans solve FILE``): argparse then hands everything after it to that command's
    parser and never consults the others (an error is one line without the list of
    commands), so they are not built: each costs its gettext look-ups and options."""
    if argv and argv[0] in {"solve", *(name for name, _ in _COMMAND_NAMES.values())}:
        return argv[0]
    return None


def build_parser(argv: Sequence[str] | None = None) -> argparse.ArgumentParser:
    """The parser; with ``argv``, only the module of the command asked for is imported (the
    others are listed by name, or left out when the command comes first: :func:`only_command`),
    without it every command is complete."""
    parser = Parser(
        prog="plans",
        description="Velocity and acceleration plans, force polygons and the Zhukovsky lever "
                    "of planar linkages, built as a draftsman builds them and checked exactly.")
    sub = parser.add_subparsers(dest="command", required=True)
    only = only_command(argv)
    if only in (None, "solve"):
        s = sub.add_parser("solve", help="solve a scene: table per position, JSON")
        s.add_argument("scene", help="scene file (TOML)")
        s.add_argument("--json", metavar="PATH", help="write results as JSON ('-' for stdout)")
        s.add_argument("--csv", metavar="PATH", help="write the tables over the positions as CSV ('-' for stdout)")
        s.add_argument("--protocol", action="store_true", help="print the construction protocol")
        s.add_argument("--quiet", action="store_true", help="no table on stdout")
        from plans.language import add_option

        add_option(s)
        s.set_defaults(func=_solve)
    register_commands(sub, _COMMAND_MODULES, argv)
    return parser


def register_commands(sub: argparse._SubParsersAction, modules: Sequence[str],
                      argv: Sequence[str] | None = None, names: dict[str, tuple[str, str]] | None = None) -> None:
    """Let each module add its subcommand (``register(sub)``); an absent module is skipped.
    With ``argv``, a module whose command is known (``names``) and not the one asked for is
    only listed, not imported; when the engine's command comes first (:func:`only_command`),
    the others are left out."""
    names = _COMMAND_NAMES if names is None else names
    wanted = command_of(argv)
    only = only_command(argv)
    for mod in modules:
        if only is not None and (mod not in names or names[mod][0] != only):
            continue
        if argv is not None and mod in names and names[mod][0] != wanted:
            # only to list the others: ``plans solve FILE`` lists none
            from importlib.util import find_spec

            if find_spec(mod) is not None:
                sub.add_parser(names[mod][0], help=names[mod][1])
            continue
        try:
            module = importlib.import_module(mod)
        except ModuleNotFoundError as exc:
            if exc.name is None or not (mod == exc.name or mod.startswith(exc.name + ".")):
                raise
            continue
        module.register(sub)


def _solve(args: argparse.Namespace) -> int:
    from plans.io import atomic_file, atomic_write, refuse_input
    from plans.kinematics.placing import load_scene
    from plans.results import solve_scene, table, write_json

    refuse_input(args.json, args.scene)
    scene = load_scene(args.scene)
    sol = solve_scene(scene)
    from plans.language import choose

    lang = choose(getattr(args, "language", None), scene.raw)
    if getattr(args, "csv", None):
        from plans.cycle.results import cycle_csv

        text = cycle_csv(sol.cycle, lang) if sol.cycle is not None else ""
        if args.csv == "-":
            sys.stdout.write(text)
            return 0
        atomic_write(args.csv, text)
    if args.json == "-":
        write_json(sol, sys.stdout.write, lang)
        return 0
    if args.json:
        with atomic_file(args.json) as fh:
            write_json(sol, lambda text: fh.write(text.encode("utf-8")), lang)
    if not args.quiet:
        print(table(sol, protocol=args.protocol, lang=lang))
    return 0


def run(args: argparse.Namespace) -> int:
    """Run a parsed command; user errors become one line on stderr and status 2; Ctrl-C
    stops quietly with 130; a closed pipe (``plans solve ... | head``) ends with 0.  Every
    command runs inside one guard of its inputs and outputs (:mod:`plans.guard`): its files
    are renamed into place only when it has returned, none over an input."""
    from plans.guard import Run

    outer = set_run(getattr(args, "language", None), _input_of(args))
    try:
        with Run():
            return int(args.func(args))
    except PlansError as exc:
        if exc.source is None and not isinstance(exc, InputError):
            exc.source = getattr(args, "scene", None) or getattr(args, "path", None)
        print(f"{error_prefix()}{one_line(exc)}", file=sys.stderr)
        return 2
    except BrokenPipeError:
        return _closed_pipe()
    except OSError as exc:
        print(f"{error_prefix()}{exc.filename or ''}: {' '.join((exc.strerror or str(exc)).split())}",
              file=sys.stderr)
        return 2
    except KeyboardInterrupt:
        return 130
    finally:
        set_run(*outer)  # the caller's run again (none: a library call follows its own scene's language)


def _input_of(args: argparse.Namespace) -> str | None:
    """The command's input file (its ``[sheet] language`` is the run's default language)."""
    for name in ("scene", "path", "file", "engine", "cam", "task", "template"):
        value = getattr(args, name, None)
        if isinstance(value, str) and value.endswith(".toml"):
            return value
    return None


def _asked_language(argv: Sequence[str]) -> str | None:
    """``--language`` as written on the command line (for argparse's own messages, before
    the arguments are parsed)."""
    for k, a in enumerate(argv):
        if a == "--language" and k + 1 < len(argv):
            return argv[k + 1]
        if a.startswith("--language="):
            return a.split("=", 1)[1]
    return None


def _closed_pipe() -> int:
    """The reader of our output has gone (``| head``): that is not an error.  Point stdout
    at /dev/null so the interpreter's final flush does not complain either."""
    try:
        devnull = os.open(os.devnull, os.O_WRONLY)
        os.dup2(devnull, sys.stdout.fileno())
    except (OSError, ValueError):
        pass
    return 0


def main(argv: Sequence[str] | None = None,
         parser: Callable[[Sequence[str]], argparse.ArgumentParser] | None = None) -> int:
    """Parse and run one command; ``parser`` builds the parser (the renderer's CLI passes its
    own, with ``draw`` added)."""
    argv = sys.argv[1:] if argv is None else list(argv)
    outer = set_run(_asked_language(argv), next((a for a in argv if a.endswith(".toml")), None))
    try:
        args = (parser or build_parser)(argv).parse_args(argv)
    except KeyboardInterrupt:
        set_run(*outer)
        return 130
    except SystemExit:  # --help, or a usage error said: a library call after it follows its own scene
        set_run(*outer)
        raise
    set_run(*outer)
    return run(args)


if __name__ == "__main__":  # pragma: no cover
    raise SystemExit(main())
