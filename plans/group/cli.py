"""The group's parts of ``plans check``: the gradebook (``--xlsx``) and the blank forms of
gears and cam sheets (``--template gears.toml``)."""

from __future__ import annotations

import argparse
import sys
from pathlib import Path

from plans.errors import InputError, PlansError, Said, error_prefix, one_line


def run_group(args: argparse.Namespace) -> int | None:
    """Run the group's part of ``plans check``; None: not ours (a linkage template)."""
    try:
        if getattr(args, "xlsx", None):
            from plans.group.gradebook import run_gradebook

            return run_gradebook(args)
        return _template(args)
    except PlansError as exc:
        print(f"{error_prefix()}{one_line(exc)}", file=sys.stderr)
        return 2


def _template(args: argparse.Namespace) -> int | None:
    from plans.check.forms import scene_reference
    from plans.io import read_toml

    src = Path(args.template)
    if not src.is_file():
        return None
    data = read_toml(src)
    kind = data.get("kind")
    if kind not in ("gears", "cam"):
        return None
    if args.form != "toml":
        raise InputError(Said("gl_csv_form_linkage", kind=kind), file=str(src), field="--form")
    from plans.group.sheets import blank, sheet_key

    target = Path(args.output) if args.output else None
    ref = str(src.resolve()) if target is None else scene_reference(src, target)
    from plans.errors import run_language

    text = blank(kind, ref, sheet_key(kind, data, str(src)), "", run_language())
    from plans.check.forms import put_form

    return put_form(text, target, src, args.quiet)


def run_sheet_file(target: Path, args: argparse.Namespace) -> int | None:
    """``plans check SHEET.toml`` of a gears or cam sheet; None: another kind of file."""
    from plans.check.report import csv_text
    from plans.group.sheets import sheet_check_of, summary_row, table
    from plans.io import dumps, write_all

    rep = sheet_check_of(target)
    if rep is None:
        return None
    from plans.check.report import report_language

    lang = report_language(args)
    files: dict[Path, str] = {}
    if args.json and args.json != "-":
        files[Path(args.json)] = dumps(rep.to_json(lang))
    if args.csv and args.csv != "-":
        files[Path(args.csv)] = csv_text([summary_row(str(target), rep, lang)], lang)
    if args.out:
        Path(args.out).mkdir(parents=True, exist_ok=True)
        files[Path(args.out) / f"{target.stem}.json"] = dumps(rep.to_json(lang))
        files[Path(args.out) / f"{target.stem}.txt"] = table(rep, lang) + "\n"
    write_all(files)
    if args.json == "-":
        sys.stdout.write(dumps(rep.to_json(lang)))
    elif args.csv == "-":
        sys.stdout.write(csv_text([summary_row(str(target), rep, lang)], lang))
    elif not args.quiet:
        print(table(rep, lang))
    return 0
