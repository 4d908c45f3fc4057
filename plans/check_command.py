"""``plans check``: a check file, a CSV form, a folder of them (a report per file and the
summary), or a blank template; the group's gradebook (``--xlsx``) and the gear and cam
sheets go to :mod:`plans.group`, the cycle's tables to :mod:`plans.check.cycle`.  The checking
itself is :mod:`plans.check.report`'s.  The command sits above the check room and the group
room, which reads the check room (a variant's key, the gradebook): neither imports it."""

from __future__ import annotations

import argparse
import sys
from pathlib import Path
from typing import Any

from plans.check.report import (
    Report,
    check,
    check_file,
    csv_text,
    error_line,
    make_folder,
    report_language,
    summary_row,
    table,
    write_summary,
)
from plans.errors import OutputError, PlansError, Said, one_line, run_language
from plans.guard import abandon
from plans.io import dumps, refuse_input, write_all
from plans.io import remove as remove_files


def register(subparsers: Any) -> argparse.ArgumentParser:
    p = subparsers.add_parser(
        "check", help="check a hand-drawn sheet (or a folder of them) against the exact analysis",
        description="Compare what a student measured and computed on a hand-drawn sheet with the exact "
                    "values at the student's scales; find inconsistencies in the student's own work.")
    p.add_argument("path", metavar="FILE|DIR", nargs="?",
                   help="a check file (TOML), a CSV form (one student per column) or a folder of check files "
                        "(a scene file beside them is the scene of those that name none)")
    p.add_argument("--json", metavar="PATH", help="write the report as JSON ('-' for stdout; single file only)")
    p.add_argument("--csv", metavar="PATH", help="write the summary table as CSV ('-' for stdout)")
    p.add_argument("--template", metavar="SCENE", help="write a blank check file of this scene to fill in")
    p.add_argument("--phi", metavar="DEG,DEG", help="with --template: the positions (default: the scene's)")
    p.add_argument("-o", "--output", metavar="FILE", help="with --template: write it here (default: stdout)")
    p.add_argument("--form", choices=("toml", "csv"), default="toml",
                   help="with --template: a check file (toml) or a CSV form, one column per student")
    p.add_argument("--students", type=int, default=3, metavar="N", help="with --form csv: columns (default 3)")
    p.add_argument("--out", metavar="DIR", help="write <name>.json and <name>.txt per check file here "
                                                 "(batch default: DIR/reports)")
    p.add_argument("--quiet", action="store_true", help="no table on stdout")
    p.add_argument("--xlsx", metavar="MARKS.xlsx", help="with a folder: every sheet under it checked, one row per "
                                                         "student, one worksheet per group (the gradebook)")
    p.add_argument("--rubric", metavar="RUBRIC.toml", help="with --xlsx: weights per sheet, pass threshold, marks")
    p.add_argument("--jobs", type=int, default=1, metavar="N", help="with --xlsx: check in N processes")
    from plans.language import add_option

    add_option(p)
    p.set_defaults(func=run)
    return p


def _extra(args: argparse.Namespace, report: Report, target: Path) -> dict[Path, Any]:
    """Files another module adds for each checked file (``plans check --sheet``: the marked
    and overlay sheets), rendered before anything is written."""
    hook = getattr(args, "extra_files", None)
    return dict(hook(report, target)) if hook is not None else {}


def _after(args: argparse.Namespace, target: Path, written: bool) -> None:
    """Tell that module whether ``target``'s files were written (its old sheets the new set
    lacks go) or, in a folder, the file failed (its sheets of an earlier run go)."""
    hook = getattr(args, "after_write", None)
    if hook is not None:
        hook(target, written)


def run(args: argparse.Namespace) -> int:
    """``plans check``: 0 when every file was checked, 2 on a user error (one line on stderr).
    A single file's outputs (JSON, CSV, reports, sheets) are written all or none."""
    if getattr(args, "xlsx", None) or getattr(args, "template", None):
        from plans.group.cli import run_group

        got = run_group(args)
        if got is not None:
            return got
    if getattr(args, "template", None):
        from plans.check.forms import run_template

        return run_template(args)
    if not args.path:
        error_line(Said("k_nothing").text(run_language()))
        return 2
    target = Path(args.path)
    try:
        if target.is_dir():
            return _batch(target, args)
        if target.suffix.lower() == ".csv" and target.is_file():
            from plans.check.forms import run_form

            return run_form(target, args)
        if not target.exists():
            why = Said("k_link") if target.is_symlink() else Said("k_no_file")
            error_line(f"{target}: {why.text(run_language())}")
            return 2
        for out_path in (args.json, args.csv):
            refuse_input(out_path, target)
        from plans.check import cycle as cycle_check  # cycle tables (a dynamics sheet)

        if cycle_check.is_cycle_check(target):
            return cycle_check.run_file(target, args)
        from plans.group.cli import run_sheet_file  # a gears or cam sheet

        done = run_sheet_file(target, args)
        if done is not None:
            return done
        report = check_file(target)
        lang = report_language(args, report)
        for out_path in (args.json, args.csv):
            refuse_input(out_path, report.check.scene.path)
        files: dict[Path, Any] = {}
        if args.json and args.json != "-":
            files[Path(args.json)] = dumps(report.to_json(lang))
        if args.csv and args.csv != "-":
            files[Path(args.csv)] = csv_text([summary_row(str(target), report, lang=lang)], lang)
        if args.out:
            out = Path(args.out)
            files[out / f"{target.stem}.json"] = dumps(report.to_json(lang))
            files[out / f"{target.stem}.txt"] = table(report, lang) + "\n"
        for out_path in (args.json, args.csv):
            if out_path and out_path != "-" and not Path(out_path).parent.is_dir():
                raise OutputError(Said("k_no_folder", path=out_path, folder=str(Path(out_path).parent)))
        files.update(_extra(args, report, target))
        for folder in sorted({p.parent for p in files}):
            make_folder(folder)
        written = write_all(files)
        _after(args, target, True)
        if args.json == "-":
            sys.stdout.write(dumps(report.to_json(lang)))
        elif args.csv == "-":
            sys.stdout.write(csv_text([summary_row(str(target), report, lang=lang)], lang))
        if not args.quiet and args.json != "-" and args.csv != "-":
            print(table(report, lang))
            for p in written:
                if p.suffix in (".svg", ".pdf", ".png"):
                    print(p)
        return 0
    except PlansError as exc:
        abandon()  # nothing of the command is written (it answers 2 itself)
        error_line(one_line(exc))
        return 2
    except BrokenPipeError:
        raise  # the runner ends quietly: the reader of the table has gone
    except OSError as exc:
        abandon()
        error_line(f"{exc.filename or ''}: {exc.strerror}")
        return 2


def _batch(folder: Path, args: argparse.Namespace) -> int:
    if args.json:
        error_line(f"{folder}: {Said('k_json_folder').text(run_language())}")
        return 2
    files = sorted(p for p in folder.glob("*.toml") if p.is_file())
    from plans.check.forms import is_scene
    from plans.io import read_toml

    scenes = []
    for f in files:
        try:
            # a scene has a [driver]; a check file is read once, below, not twice
            if "[driver]" in f.read_text(encoding="utf-8", errors="replace") and is_scene(read_toml(f)):
                scenes.append(f)
        except (PlansError, OSError):
            continue  # reported as that file's error below
    files = [f for f in files if f not in scenes]
    beside = scenes[0] if len(scenes) == 1 else None
    if not files:
        error_line(f"{folder}: {Said('k_no_checks').text(run_language())}")
        return 2
    out = Path(args.out) if args.out else folder / "reports"
    make_folder(out)
    rows = []
    bad = 0
    from plans.check import cycle as cycle_check
    from plans.progress import Progress

    progress = Progress(args.quiet)
    for k, f in enumerate(files, 1):
        progress(f"{k}/{len(files)} {f.name}")
        reports = {out / f"{f.stem}.json", out / f"{f.stem}.txt"}
        try:
            outputs: dict[Path, Any]
            from plans.group.sheets import sheet_check_of, sheet_outputs

            srep = None if cycle_check.is_cycle_check(f) else sheet_check_of(f)
            if cycle_check.is_cycle_check(f):  # cycle tables: a report, no marked sheet
                crep = cycle_check.check_cycle(f)
                lang = report_language(args)
                outputs, row = cycle_check.outputs(crep, f, out, lang), cycle_check.summary_row(str(f), crep, lang)
            elif srep is not None:  # a gears or cam sheet
                outputs, row = sheet_outputs(srep, f, out, report_language(args))
            else:
                report = _check_beside(f, beside)
                lang = report_language(args, report)
                outputs = {out / f"{f.stem}.json": dumps(report.to_json(lang)),
                           out / f"{f.stem}.txt": table(report, lang) + "\n"}
                outputs.update(_extra(args, report, f))
                row = summary_row(str(f), report, lang=lang)
            for sub in sorted({p.parent for p in outputs}):
                make_folder(sub)
            write_all(outputs)
        except PlansError as exc:
            bad += 1
            error_line(one_line(exc))
            rows.append(summary_row(str(f), None, str(exc), lang=report_language(args)))
            remove_files(reports)  # a report of an earlier run would look current
            _after(args, f, False)
            continue
        _after(args, f, True)
        rows.append(row)
    write_summary(rows, args, out)
    return 2 if bad else 0


def _check_beside(path: Path, scene: Path | None) -> Report:
    """A check file of a folder; one that names no scene uses the scene file beside it."""
    from plans.check.checkfile import check_from_dict
    from plans.io import read_toml

    data = read_toml(path)
    if scene is not None and "scene" not in data:
        data = {**data, "scene": scene.name}
    try:
        return check(check_from_dict(data, str(path)))
    except PlansError as exc:
        exc.source = exc.source or str(path)
        raise
