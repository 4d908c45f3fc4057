"""``plans check DIR --xlsx MARKS.xlsx``: every sheet of a group checked, marks in a gradebook.

Every check file under DIR (linkage, gears, cam; blank forms and the variants' own files
are passed over) is checked; the sheets of one student (the same ``student`` and
``group``) make one row: the mark by the teacher's rubric, each sheet's score (its mark out
of 100), the causes found (``kind at φ°``, by sheet), the failing figures no cause
explains and the findings left, counted by kind.  One worksheet per group, header frozen,
the marks and scores coloured against the pass threshold.  Beside it, each sheet's report
and ``summary.csv`` in ``--out`` (default ``DIR/reports``), as ``plans check DIR`` writes.

The rubric (``--rubric RUBRIC.toml``)::

    format = 1
    kind = "rubric"
    pass = 60                        # a score or mark below it is coloured red
    [weights]                        # the weight of each sheet kind in the mark
    linkage = 2
    gears = 1
    cam = 1
    [marks]                          # the mark given from the weighted score (%)
    5 = 85
    4 = 70
    3 = 55
    2 = 0

Without ``[marks]`` the mark is the weighted score itself; a sheet with a weight and not
handed in scores 0.
"""

from __future__ import annotations

import io
import math
import re
import sys
import zipfile
from collections import Counter
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

from plans.errors import InputError, PlansError, Said, error_prefix, one_line, run_language

HEADER = ("student", "group", "variant", "mark")
TAIL = ("causes", "unexplained", "findings")


def heading(column: str, lang: str) -> str:
    """A column's heading (a sheet kind's too) in ``lang``: the catalogue's ``gb_<column>``."""
    from plans.messages_terminal import TERMINAL
    from plans.phrases import say

    return say(f"gb_{column}", lang) if f"gb_{column}" in TERMINAL else column


def _at(what: str, phis: list[float], lang: str) -> str:
    """``coriolis_reversed at 30,60°``; in Russian the teacher's words for the cause."""
    from plans.errors import Figures
    from plans.phrases import say

    if lang == "ru":
        return say("gb_at", lang, what=_cause(what, lang), phis=Figures(phis).written(lang))
    return say("gb_at", lang, what=what, phis=",".join(f"{p:g}" for p in phis))


def _cause(kind: str, lang: str) -> str:
    """A cause's kind as the gradebook names it: the rubric's key in English, the teacher's
    words in Russian."""
    from plans.language import CAUSES

    return CAUSES[kind][1] if lang == "ru" and kind in CAUSES else kind


@dataclass
class Sheet:
    """One check file checked: what the gradebook needs of it."""

    path: str
    kind: str  # "linkage" | "gears" | "cam"
    student: str
    group: str
    variant: str
    score: float | None = None  # out of 100
    causes: list[str] = field(default_factory=list)
    unexplained: list[str] = field(default_factory=list)
    findings: dict[str, int] = field(default_factory=dict)
    error: str = ""
    report: str = ""  # the report as JSON text
    text: str = ""  # the report as the terminal shows it
    row: dict[str, Any] = field(default_factory=dict)  # its summary.csv row


@dataclass(frozen=True)
class Rubric:
    weights: dict[str, float]
    marks: tuple[tuple[str, float], ...]  # (label, lowest weighted score), highest first
    passing: float


def read_rubric(path: str | Path | None) -> Rubric:
    if path is None:
        return Rubric({}, (), 60.0)
    from plans.io import read_toml
    from plans.reader import check_keys

    data = read_toml(path)
    check_keys(data, ("format", "kind", "pass", "weights", "marks", "title"), file=str(path), where="")
    if data.get("kind", "rubric") != "rubric":
        raise InputError(Said("gg_kind_rubric", v=data.get('kind')), file=str(path), field="kind")

    def num(v: Any, where: str) -> float:
        if isinstance(v, bool) or not isinstance(v, int | float) or not math.isfinite(v) or not 0 <= v <= 1e6:
            raise InputError(Said("gg_number_from", v=v), file=str(path), field=where)
        return float(v)

    weights = {str(k): num(v, f"weights.{k}") for k, v in (data.get("weights") or {}).items()}
    marks = sorted(((str(k), num(v, f"marks.{k}")) for k, v in (data.get("marks") or {}).items()),
                   key=lambda m: -m[1])
    return Rubric(weights, tuple(marks), num(data.get("pass", 60), "pass"))


def _sheet_of(path: Path) -> Sheet | None:
    """Check one file; None: not a check file with a figure written (a blank, a scene)."""
    from plans.group.sheets import check_sheet, is_sheet_check
    from plans.io import read_toml

    try:
        data = read_toml(path)
    except PlansError:
        return None
    kind = is_sheet_check(data) or ("linkage" if {"student", "scene", "positions"} <= set(data) else None)
    if kind is None or not _written(data):
        return None
    sh = Sheet(str(path), kind, str(data.get("student", "")) or path.stem, str(data.get("group", "")),
               str(data.get("variant", "")))
    lang = run_language()
    try:
        if kind == "linkage":
            from plans.check.checkfile import check_from_dict
            from plans.check.report import check, summary_row, table
            from plans.io import dumps

            rep = check(check_from_dict(data, str(path)))
            sh.report, sh.text, sh.row = dumps(rep.to_json()), table(rep, lang) + "\n", summary_row(str(path), rep, lang=lang)
            full = (rep.diagnosis.rubric.get("full", 100.0) if rep.diagnosis is not None else 100.0) or 100.0
            sh.score = 100.0 * (rep.mark if rep.mark is not None else full) / full
            sh.causes = [_at(c.kind, c.positions, lang) if c.positions else _cause(c.kind, lang) for c in rep.causes]
            sh.unexplained = list(dict.fromkeys(_at(i.quantity, [i.phi_deg], lang) for i in rep.unexplained))
            sh.findings = dict(Counter(f.kind for f in rep.findings_left))
        else:
            from plans.group.sheets import summary_row as sheet_row
            from plans.group.sheets import table as sheet_table
            from plans.io import dumps

            srep = check_sheet(data, str(path))
            sh.report, sh.text, sh.row = (dumps(srep.to_json()), sheet_table(srep, lang) + "\n",
                                          sheet_row(str(path), srep, lang))
            sh.score = 100.0 * srep.mark / (srep.full or 100.0)
            sh.causes = [_cause(c.kind, lang) for c in srep.causes]
            sh.unexplained = list(dict.fromkeys(i.quantity for i in srep.unexplained))
    except PlansError as exc:
        sh.error = one_line(exc)
        from plans.check.report import summary_row

        sh.row = summary_row(str(path), None, sh.error, lang=lang)
    return sh


def _written(data: dict[str, Any]) -> bool:
    for pos in data.get("positions") or []:
        if isinstance(pos, dict):
            for part in ("measured", "values"):
                if any(v != "" for v in (pos.get(part) or {}).values()):
                    return True
    return False


def check_all(folder: Path, jobs: int = 1) -> list[Sheet]:
    files = sorted(p for p in folder.rglob("*.toml") if p.is_file())
    if jobs > 1 and len(files) > 1:
        from concurrent.futures import ProcessPoolExecutor

        with ProcessPoolExecutor(max_workers=jobs) as pool:
            got = list(pool.map(_sheet_of, files, chunksize=max(1, len(files) // (4 * jobs))))
    else:
        got = [_sheet_of(f) for f in files]
    return [s for s in got if s is not None]


def rows(sheets: list[Sheet], rubric: Rubric, lang: str | None = None) -> tuple[list[str], dict[str, list[dict[str, Any]]]]:
    """The sheet kinds (score columns) and, per group, one row per student."""
    lang = lang or run_language()
    kinds = sorted({s.kind for s in sheets} | set(rubric.weights))
    students: dict[tuple[str, str], list[Sheet]] = {}
    for s in sheets:
        students.setdefault((s.group, s.student), []).append(s)
    out: dict[str, list[dict[str, Any]]] = {}
    for (group, student), mine in sorted(students.items()):
        scores: dict[str, float | None] = {}
        for s in mine:
            if s.score is not None:
                scores[s.kind] = min(scores.get(s.kind) or 100.0, s.score) if s.kind in scores else s.score
        if rubric.weights:
            total = sum(rubric.weights.values()) or 1.0
            weighted = sum(w * (scores.get(k) or 0.0) for k, w in rubric.weights.items()) / total
        else:
            got = [v for v in scores.values() if v is not None]
            weighted = sum(got) / len(got) if got else 0.0
        mark: Any = round(weighted, 1)
        if rubric.marks:
            mark = next((label for label, low in rubric.marks if weighted >= low - 1e-9), rubric.marks[-1][0])
            mark = int(mark) if mark.isdigit() else mark
        findings = Counter[str]()
        for s in mine:
            findings.update(s.findings)
        row: dict[str, Any] = {
            "student": student, "group": group,
            "variant": ", ".join(sorted({s.variant for s in mine if s.variant})), "mark": mark,
            "_score": weighted,
            **{k: (None if scores.get(k) is None else round(float(scores[k] or 0.0), 1)) for k in kinds},
            "causes": "; ".join(f"{heading(s.kind, lang)}: {c}" for s in mine for c in s.causes),
            "unexplained": "; ".join(f"{heading(s.kind, lang)}: {u}" for s in mine for u in s.unexplained),
            "findings": "; ".join(f"{k}: {n}" for k, n in sorted(findings.items())),
            "_errors": [f"{s.path}: {s.error}" for s in mine if s.error],
        }
        out.setdefault(group or "-", []).append(row)
    return kinds, out


def xlsx_bytes(kinds: list[str], groups: dict[str, list[dict[str, Any]]], rubric: Rubric,
               lang: str | None = None) -> bytes:
    """The workbook: one worksheet per group, its headings in ``lang`` (default: the run's);
    the same rows give the same bytes."""
    lang = lang or run_language()
    import datetime

    from openpyxl import Workbook
    from openpyxl.formatting.rule import CellIsRule, FormulaRule
    from openpyxl.styles import Font, PatternFill
    from openpyxl.utils import get_column_letter

    wb = Workbook()
    wb.remove(wb.active)
    header = [*HEADER, *kinds, *TAIL]
    red = PatternFill(start_color="FFC7CE", end_color="FFC7CE", fill_type="solid")
    green = PatternFill(start_color="C6EFCE", end_color="C6EFCE", fill_type="solid")
    yellow = PatternFill(start_color="FFEB9C", end_color="FFEB9C", fill_type="solid")
    for group, rs in sorted(groups.items()):
        ws = wb.create_sheet(_title(group))
        ws.append([heading(h, lang) for h in header])
        for c in ws[1]:
            c.font = Font(bold=True)
        for r in rs:
            ws.append([r[h] for h in header])
        ws.freeze_panes = "A2"
        n = len(rs) + 1
        for j, h in enumerate(header, 1):
            col = get_column_letter(j)
            ws.column_dimensions[col].width = 40 if h in TAIL else max(10, len(heading(h, lang)) + 2)
            if h in kinds or (h == "mark" and not rubric.marks):
                rng = f"{col}2:{col}{n}"
                ws.conditional_formatting.add(rng, CellIsRule(operator="lessThan", formula=[str(rubric.passing)],
                                                              fill=red))
                ws.conditional_formatting.add(rng, CellIsRule(operator="greaterThanOrEqual",
                                                              formula=[str(rubric.passing)], fill=green))
            if h in ("causes", "unexplained"):
                ws.conditional_formatting.add(f"{col}2:{col}{n}", FormulaRule(formula=[f'LEN({col}2)>0'],
                                                                              fill=yellow))
        if rubric.marks:
            col = get_column_letter(header.index("mark") + 1)
            for i, r in enumerate(rs, 2):
                ws[f"{col}{i}"].fill = green if r["_score"] >= rubric.passing else red
    fixed = datetime.datetime(2000, 1, 1)
    wb.properties.created = fixed
    wb.properties.modified = fixed
    buf = io.BytesIO()
    wb.save(buf)
    return _fixed_zip(buf.getvalue())


def _title(group: str) -> str:
    bad = '[]:*?/\\'
    t = "".join("_" if ch in bad else ch for ch in group)[:31]
    return t or "-"


def _fixed_zip(raw: bytes) -> bytes:
    """The same archive with every entry dated 1980-01-01: the bytes depend on the rows only."""
    src = zipfile.ZipFile(io.BytesIO(raw))
    out = io.BytesIO()
    with zipfile.ZipFile(out, "w", zipfile.ZIP_DEFLATED) as dst:
        for info in src.infolist():
            zi = zipfile.ZipInfo(info.filename, date_time=(1980, 1, 1, 0, 0, 0))
            zi.compress_type = zipfile.ZIP_DEFLATED
            zi.external_attr = 0o600 << 16
            body = src.read(info.filename)
            if info.filename == "docProps/core.xml":  # openpyxl dates the save itself
                body = re.sub(rb"(<dcterms:modified[^>]*>)[^<]*", rb"\g<1>2000-01-01T00:00:00Z", body)
            dst.writestr(zi, body)
    return out.getvalue()


def run_gradebook(args: Any) -> int:
    """``plans check DIR --xlsx MARKS.xlsx [--rubric R.toml] [--jobs N] [--csv PATH]``."""
    from plans.io import refuse_input, write_all

    folder = Path(args.path or "")
    if not args.path or not folder.is_dir():
        raise InputError(Said("gg_folder_check_files"), file=args.path, field="--xlsx")
    target = Path(args.xlsx)
    if target.suffix.lower() != ".xlsx":
        raise InputError(Said("gg_xlsx_file_name", name=target.name), file=str(folder), field="--xlsx")
    refuse_input(str(target), *(str(p) for p in folder.rglob("*.toml")))
    if not target.parent.is_dir():
        raise InputError(Said("gg_such_folder_parent", parent=target.parent), file=str(folder), field="--xlsx")
    jobs = getattr(args, "jobs", 1) or 1
    if not 1 <= jobs <= 64:
        raise InputError(Said("gg_jobs_jobs", jobs=jobs), file=str(folder), field="--jobs")
    rubric = read_rubric(getattr(args, "rubric", None))
    sheets = check_all(folder, jobs)
    if not sheets:
        raise InputError(Said("gg_check_file_figure"), file=str(folder))
    kinds, groups = rows(sheets, rubric)
    data = xlsx_bytes(kinds, groups, rubric)
    files: dict[Path, bytes | str] = {target: data}
    if args.csv and args.csv != "-":
        files[Path(args.csv)] = csv_text(kinds, groups)
    # beside the gradebook, the examiner's outputs: a report per sheet and summary.csv
    out = Path(args.out) if args.out else folder / "reports"
    from plans.check.report import csv_text as summary_csv

    for s in sheets:
        stem = "_".join(Path(s.path).resolve().relative_to(folder.resolve()).with_suffix("").parts)
        if s.report:
            files[out / f"{stem}.json"] = s.report
            files[out / f"{stem}.txt"] = s.text
    files[out / "summary.csv"] = summary_csv([s.row for s in sheets], run_language())
    out.mkdir(parents=True, exist_ok=True)
    write_all(files)
    if args.csv == "-":
        sys.stdout.write(csv_text(kinds, groups))
    bad = [e for rs in groups.values() for r in rs for e in r["_errors"]]
    for e in bad:
        print(f"{error_prefix()}{e}", file=sys.stderr)
    if not args.quiet and args.csv != "-":
        n = sum(len(rs) for rs in groups.values())
        from plans.phrases import say

        print(say("gb_summary", run_language(), target=target, students=n, sheets=len(sheets), groups=len(groups)))
    return 2 if bad else 0


def csv_text(kinds: list[str], groups: dict[str, list[dict[str, Any]]], lang: str | None = None) -> str:
    import csv

    lang = lang or run_language()
    buf = io.StringIO()
    w = csv.writer(buf, lineterminator="\n")
    header = [*HEADER, *kinds, *TAIL]
    w.writerow([heading(h, lang) for h in header])
    for _, rs in sorted(groups.items()):
        for r in rs:
            w.writerow([_cell(r[h], lang) for h in header])
    return buf.getvalue()


def _cell(v: Any, lang: str) -> Any:
    """A gradebook CSV's cell: a score with a decimal comma in Russian (as the check's CSV)."""
    if v is None:
        return ""
    return str(v).replace(".", ",") if lang == "ru" and isinstance(v, float) else v
