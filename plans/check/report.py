"""Checking a hand-drawn sheet: the student's figures against the exact analysis.

For every figure the student wrote (:mod:`plans.checkfile`) the report gives the exact
value, the error in % and in mm on the student's drawing at the student's scales, and
a verdict against a tolerance:

* ``draftsman`` model: a laid-off or measured segment is good to ±``segment_mm`` and a
  drawn direction to ±``direction_deg``; these errors are propagated through the
  construction of the plan drawn at the student's scale (the plan's protocol replayed
  with each error in turn, first order, worst-case sum) and the reading adds one more
  ±``segment_mm``.  A normal or Coriolis component, computed from figures read off the
  velocity plan and then laid off, carries their tolerance into its length; a point found
  by similarity from a coincident image (the shaper's d from a3) moves with that image.
  A short vector found by intersecting nearly parallel lines gets a
  wide tolerance, a long vector laid off from the pole a narrow one.  Figures that
  are computed rather than drawn (masses, reactions without the student's μF, ...)
  fall back to the course rule.
* ``rule`` model: every figure within ±``rule_pct`` % of the exact value.

Independently of the exact values, the student's own work is checked for
consistency (:data:`RELATIONS`: value = segment/μ, ω = v/l, ε = a^τ/l, a^n = v²/l,
Φ = m a, M_Φ = I ε, similarity ratios, the % difference of the balancing forces),
for the same quantity written twice with different values, for figures that
symmetry makes equal, for π = 3.14, for a wrong scale and for swapped segments.

Exact values come from a table of providers keyed by quantity name
(:data:`PROVIDERS`): plan segments, angular rates, lengths of the scheme, masses
and inertia loads (:mod:`plans.loads`), reactions and the balancing force
(:mod:`plans.forces`), lever arms.

JSON (``plans check FILE --json PATH``)::

    {"format": 1, "student": ..., "check_file": ..., "scene": ..., "tolerance": {...},
     "scales": {"velocity": μv, ...},
     "items": [{"quantity", "phi_deg", "student", "student_mm", "exact", "exact_mm", "unit",
                "error_pct", "error_mm", "tolerance", "tolerance_mm", "tolerance_pct",
                "tolerance_model", "verdict": "pass" | "fail", "where", "field", "source"}],
     "findings": [{"kind", "message", "phi_deg", "quantities", "where", "fields"}],
     "unchecked": [{"quantity", "phi_deg", "student", "reason", "where"}],
     "summary": {"items", "passed", "failed", "findings"}}
"""

from __future__ import annotations

import argparse
import csv
import io
import re
import sys
from dataclasses import dataclass, field, replace
from pathlib import Path
from typing import Any

from plans.check import wording as wd
from plans.check.checkfile import CheckFile, StudentPosition, Written, load_check
from plans.check.diagnosis import Diagnosis, diagnose
from plans.check.findings import (
    Finding,
    Item,
    Unchecked,
    across_positions_findings,
    consistent,
    duplicate_findings,
    fmt,
    pi_findings,
    scale_findings,
    swapped_findings,
    symmetry_findings,
)
from plans.check.providers import STUDENT_ONLY, Context, Exact, exact_value, known_quantities
from plans.check.relations import relation_findings
from plans.errors import InputError, OutputError, PlansError, Said, os_reason
from plans.io import atomic_write
from plans.tolerances import VERDICT_REL
from plans.units import DUST, percent
from plans.verdicts import Tally

_SCALE_UNIT = {"length": "mm/m", "velocity": "mm/(m/s)", "acceleration": "mm/(m/s²)", "force": "mm/N"}


@dataclass(frozen=True)
class Report(Tally):
    check: CheckFile
    items: tuple[Item, ...]
    findings: tuple[Finding, ...]
    unchecked: tuple[Unchecked, ...]
    context: Context = field(repr=False)
    diagnosis: Diagnosis | None = field(default=None, repr=False)

    @property
    def causes(self) -> tuple:
        return self.diagnosis.causes if self.diagnosis is not None else ()

    @property
    def unexplained(self) -> list[Item]:
        return [self.items[i] for i in self.diagnosis.unexplained] if self.diagnosis is not None else []

    @property
    def mark(self) -> float | None:
        return self.diagnosis.mark if self.diagnosis is not None else None

    @property
    def findings_left(self) -> list[Finding]:
        """Findings no cause accounts for."""
        if self.diagnosis is None:
            return list(self.findings)
        return [self.findings[i] for i in self.diagnosis.findings_left]

    def item(self, quantity: str, phi_deg: float, where: str | None = None) -> Item:
        for it in self.items:
            if it.quantity == quantity and it.phi_deg == phi_deg and (where is None or it.where == where):
                return it
        raise KeyError((quantity, phi_deg, where))

    def findings_of(self, kind: str) -> list[Finding]:
        return [f for f in self.findings if f.kind == kind]

    def to_json(self, lang: str = "en") -> dict:
        """The report as JSON: its keys always as written, its sentences (a finding's
        message, a mistake's detail, a reason) in ``lang``."""
        cf = self.check
        t = cf.tolerance
        return {
            "format": 1,
            "student": cf.student,
            "check_file": cf.path,
            "scene": cf.scene.path,
            "scales": dict(cf.scales),
            "tolerance": {"model": t.model, "segment_mm": t.segment_mm, "direction_deg": t.direction_deg,
                          "rule_pct": t.rule_pct, "arithmetic_pct": t.arithmetic_pct,
                          "balance_base": t.balance_base},
            "causes": [{**c.to_json(), "detail": c.text(lang)} for c in self.causes],
            "unexplained": list(dict.fromkeys(i.quantity for i in self.unexplained)),
            "unexplained_items": [{"quantity": i.quantity, "phi_deg": i.phi_deg, "field": i.field}
                                  for i in self.unexplained],
            "mark": self.mark,
            "rubric": dict(self.diagnosis.rubric) if self.diagnosis is not None else {},
            "items": [i.to_json() for i in self.items],
            "findings": [{**f.to_json(lang), "cause": self._cause_of(n)} for n, f in enumerate(self.findings)],
            "unchecked": [u.to_json(lang) for u in self.unchecked],
            "summary": {**self.counts(),
                        "findings": len(self.findings), "unchecked": len(self.unchecked),
                        "causes": len(self.causes), "unexplained": len(self.unexplained),
                        "findings_left": len(self.findings_left)},
        }

    def _cause_of(self, n: int) -> str | None:
        return next((c.kind for c in self.causes if n in c.findings or n in c.superseded), None)


# --------------------------------------------------------------------------- comparison


def check(cf: CheckFile) -> Report:
    """Compare every figure of a check file with the exact analysis; find inconsistencies."""
    ctx = Context(cf)
    items: list[Item] = []
    unchecked: list[Unchecked] = []
    for pos in cf.positions:
        k = pos.index
        names = []
        for w in pos.measured + pos.values:
            if w.quantity not in names:
                names.append(w.quantity)
        for q in names:
            ex = exact_value(ctx, k, q)
            if ex is None:
                if STUDENT_ONLY.match(q):
                    for w in pos.written(q):
                        m = re.fullmatch(r"h_([A-Za-z_0-9]+?)_([A-Z][a-z0-9]*)", q)
                        if q == "F_bal_diff_pct":
                            why = wd.say("ch_own_figure")
                        elif m:
                            why = wd.say("ch_no_arm", load=m.group(1), point=m.group(2))
                        else:
                            why = wd.say("ch_arm_name")
                        unchecked.append(Unchecked(q, pos.phi_deg, w.value, why.render("en"), w.where, why))
                    continue
                w0 = pos.written(q)[0]
                known = ", ".join(known_quantities(ctx, k))
                extra = f" ({ctx._forces_error})" if ctx._forces_error else ""
                raise InputError(Said("cr_scene_has_quantity", q=q, phi_deg=pos.phi_deg, extra=extra, known=known), file=cf.path, field=w0.field)
            items += _items(cf, pos, q, ex)
    findings: list[Finding] = []
    for pos in cf.positions:
        findings += duplicate_findings(cf, pos)
        findings += relation_findings(ctx, pos)
        findings += symmetry_findings(cf, pos, [i for i in items if i.phi_deg == pos.phi_deg])
        findings += swapped_findings(ctx, pos, [i for i in items if i.phi_deg == pos.phi_deg])
    findings += across_positions_findings(cf)
    findings += pi_findings(cf, items)
    findings += scale_findings(cf, items)
    its, fis = tuple(items), tuple(findings)
    return Report(cf, its, fis, tuple(unchecked), ctx, diagnose(ctx, its, fis, dict(cf.rubric)))




def _items(cf: CheckFile, pos: StudentPosition, q: str, ex: Exact) -> list[Item]:
    """One item per figure written; a value that is its measured segment over μ joins it."""
    if ex.value != 0 and abs(ex.value) <= DUST * ex.ref:  # zero up to round-off: exactly 0
        ex = replace(ex, value=0.0)
    values = pos.written(q, "value")
    measured = pos.written(q, "measured")
    mu = ex.mm_per_unit
    if measured and not mu:
        raise InputError(Said("cr_read_off_plan", q=q),
                         file=cf.path, field=measured[0].field)
    rel = cf.tolerance.arithmetic_pct / 100.0
    # a value derived from a measured segment is as good as the reading (±segment_mm),
    # however many digits were typed
    read = cf.tolerance.segment_mm if cf.tolerance.model == "draftsman" else 0.0
    rows: list[tuple[Written | None, Written | None]] = []  # (measured, value)
    free = list(values)
    for meas in measured:
        assert mu
        pair = next((w for w in free if consistent(w, meas, mu, rel, read)), None)
        if pair is not None:
            free.remove(pair)
        rows.append((meas, pair))
    rows += [(None, w) for w in free]
    out = []
    t = cf.tolerance
    exact_mm = ex.value * mu if mu else None
    for m, v in rows:
        if m is not None:  # judged on the drawing
            assert mu
            judged = m.value / mu
            student = v.value if v is not None else judged
            student_mm: float | None = m.value
            figure = "both" if v is not None else "measured"
            slack = 0.0
        else:
            assert v is not None
            judged = student = v.value
            student_mm = v.value * mu if mu else None
            figure = "value"
            slack = v.half_ulp
        w = v if v is not None else m
        assert w is not None
        where = ", ".join(dict.fromkeys(x.where for x in (m, v) if x is not None and x.where))
        diff = judged - ex.value
        # one definition with solve and the sheet; none against an exact value that vanishes
        err_pct = percent(judged, ex.value) if abs(ex.value) > DUST * ex.ref else None
        err_mm = None if not mu or student_mm is None or exact_mm is None else student_mm - exact_mm
        if t.model == "draftsman" and ex.tol_mm is not None and mu:
            tol = ex.tol_mm / mu
            model = "draftsman"
        else:
            tol = t.rule_pct / 100.0 * max(abs(ex.value), 0.05 * ex.ref)
            model = "rule"
        tol = max(tol, slack)
        verdict = "pass" if abs(diff) <= tol * (1 + VERDICT_REL) else "fail"
        out.append(Item(q, pos.phi_deg, student, student_mm, ex.value, exact_mm, ex.unit, err_pct, err_mm,
                        tol, None if not mu else tol * mu, model, verdict, where, w.field, ex.source,
                        figure, ex.plan, ex.segment))
    return out





def _num(x: float | None, unit: str = "", lang: str = "en") -> str:
    if x is None:
        return "—"
    return fmt(x, lang) + (f" {unit}" if unit else "")


def say_line(key: str, lang: str, **values: Any) -> str:
    """A line of the report (:data:`plans.language.CHECK_TERMS`) in ``lang``."""
    from plans.language import CHECK_TERMS

    return CHECK_TERMS[key][1 if lang == "ru" else 0].format(**values)


def unit_word(unit: str, lang: str) -> str:
    from plans.language import UNITS_RU

    return UNITS_RU.get(unit, unit) if lang == "ru" else unit


def decimal(text: str, lang: str) -> str:
    """A number already written, with a decimal comma in Russian."""
    return text.replace(".", ",") if lang == "ru" else text


def _scale_text(kind: str, mu: float, lang: str) -> str:
    sym = {"length": "μl", "velocity": "μv", "acceleration": "μa", "force": "μF"}.get(kind, kind) \
        if lang == "ru" else kind
    return say_line("ch_scale", lang, kind=sym, mu=decimal(f"{mu:.4g}", lang),
                unit=unit_word(_SCALE_UNIT.get(kind, "mm/unit"), lang))


def table(report: Report, lang: str = "en") -> str:
    """The readable terminal report, in ``lang``."""
    from plans.language import quantity_name

    def qn(q: str) -> str:
        return quantity_name(q, lang)

    cf = report.check
    t = cf.tolerance
    d = lambda x: decimal(f"{x:g}", lang)  # noqa: E731 - a number of the tolerance as written
    model = (say_line("ch_draftsman", lang, seg=d(t.segment_mm), dir=d(t.direction_deg), rule=d(t.rule_pct))
             if t.model == "draftsman" else say_line("ch_rule", lang, rule=d(t.rule_pct)))
    head_line = say_line("ch_file", lang, path=cf.path)
    if cf.scales:
        head_line += say_line("ch_scales", lang, scales=", ".join(_scale_text(k, v, lang) for k, v in cf.scales.items()))
    lines = [say_line("ch_title", lang, student=cf.student, title=cf.scene.title), head_line,
             say_line("ch_tolerance", lang, model=model)]
    lines += _causes_text(report, lang)
    cause_no = {i: n for n, c in enumerate(report.causes, 1) for i in c.items}
    w = {k: say_line(k, lang) for k in ("ch_quantity", "ch_student", "ch_exact", "ch_error", "ch_err_mm", "ch_tol_mm",
                                    "ch_tol_pct", "ch_verdict", "ch_where")}
    tw = 9 if lang == "ru" else 8  # "доп., мм"
    head = (f"  {w['ch_quantity']:<16}{w['ch_student']:>14}{w['ch_exact']:>14}{w['ch_error']:>10}{w['ch_err_mm']:>9}"
            f"{w['ch_tol_mm']:>{tw}}{w['ch_tol_pct']:>8}  {w['ch_verdict']}  {w['ch_where']}")
    mm = unit_word("mm", lang)
    for pos in cf.positions:
        lines.append("")
        lines.append(f"φ = {d(pos.phi_deg)}°")
        lines.append(head)
        for n, it in enumerate(report.items):
            if it.phi_deg != pos.phi_deg:
                continue
            err = "—" if it.error_pct is None else decimal(f"{it.error_pct:+.1f} %", lang)
            emm = "—" if it.error_mm is None else decimal(f"{it.error_mm:+.2f}", lang)
            tmm = "—" if it.tolerance_mm is None else decimal(f"±{it.tolerance_mm:.2f}", lang)
            tp = "—" if it.tolerance_pct is None else decimal(f"±{it.tolerance_pct:.1f}", lang)
            mark = say_line("ch_pass", lang) if it.verdict == "pass" else (
                say_line("ch_fail_no", lang, n=cause_no[n]) if n in cause_no else say_line("ch_fail", lang))
            # only what the student wrote: a segment alone is shown in mm, its value is derived
            shown = f"{fmt(it.student_mm, lang)} {mm}" if it.figure == "measured" and it.student_mm is not None \
                else _num(it.student, lang=lang)
            rule = say_line("ch_rule_tag", lang) if it.tolerance_model == "rule" else ""
            lines.append(f"  {qn(it.quantity):<16}{shown:>14}{_num(it.exact, lang=lang):>14}{err:>10}{emm:>9}"
                         f"{tmm:>{tw}}{tp:>8}  {mark:<7}  {it.where}  [{unit_word(it.unit, lang)}{rule}]")
    if report.unchecked:
        lines.append("")
        lines.append(say_line("ch_not_compared", lang))
        for u in report.unchecked:
            lines.append(f"  φ = {d(u.phi_deg)}°: {qn(u.quantity)} = {fmt(u.student, lang)}"
                         f"{(' (' + u.where + ')') if u.where else ''}: {u.text(lang)}")
    left = report.findings_left
    if left:
        lines.append("")
        lines.append(say_line("ch_left", lang, n=len(left)))
        for f in left:
            lines.append(f"  [{kind_word(f.kind, lang)}] {f.text(lang)}")
    lines.append("")
    lines.append(say_line("ch_summary", lang, items=len(report.items), passed=report.passed, failed=report.failed,
                      causes=len(report.causes), unexplained=len(report.unexplained), left=len(left),
                      mark=_mark(report, lang)))
    return "\n".join(lines)


def kind_word(kind: str, lang: str) -> str:
    """A finding's or a mistake's kind as the report tags it (the teacher's word in Russian)."""
    if lang != "ru":
        return kind
    from plans.language import CAUSES, KINDS_RU

    return KINDS_RU.get(kind) or (CAUSES[kind][1] if kind in CAUSES else kind)


def _mark(report: Report, lang: str = "en") -> str:
    full = report.diagnosis.rubric.get("full", 100.0) if report.diagnosis is not None else 100.0
    return say_line("ch_of", lang, mark=fmt(report.mark or 0.0, lang), full=fmt(full, lang))


def _causes_text(report: Report, lang: str = "en") -> list[str]:
    """The mistakes found, each with the figures it explains; then the failures no
    mistake explains."""
    from plans.language import quantity_name

    lines = ["", say_line("ch_mark", lang, mark=_mark(report, lang))]
    if not report.causes and not report.unexplained:
        lines.append(say_line("ch_no_mistakes", lang))
        return lines
    lines.append(say_line("ch_mistakes", lang, n=len(report.causes)))
    for n, c in enumerate(report.causes, 1):
        at = ", ".join(f"{decimal(f'{p:g}', lang)}°" for p in c.positions)
        lines.append(f"  #{n} [{kind_word(c.kind, lang)}] {c.text(lang)}" + (f" (φ = {at})" if at else "")
                     + f"; −{fmt(c.deduction, lang)}")
        if c.explains:
            n_fig = len(c.items) or len(c.explains)
            lines.append(say_line("ch_explains", lang, n=n_fig, s="s" if n_fig != 1 else "",
                              names=", ".join(quantity_name(q, lang) for q in c.explains)))
        for fi in c.findings:
            lines.append(f"     [{kind_word(report.findings[fi].kind, lang)}] {report.findings[fi].text(lang)}")
    if report.unexplained:
        lines.append(say_line("ch_unexplained", lang, n=len(report.unexplained)))
        for it in report.unexplained:
            shown = f"{fmt(it.student_mm, lang)} {unit_word('mm', lang)}" \
                if it.figure == "measured" and it.student_mm is not None else fmt(it.student, lang)
            lines.append(say_line("ch_unexplained_item", lang, phi=decimal(f"{it.phi_deg:g}", lang),
                              q=quantity_name(it.quantity, lang), shown=shown,
                              where=f" ({it.where})" if it.where else "", exact=fmt(it.exact, lang),
                              unit=unit_word(it.unit, lang)))
    return lines


CSV_FIELDS = ("file", "student", "status", "mark", "causes", "unexplained", "items", "passed", "failed",
              "findings", "worst", "worst_error_pct", "worst_tol", "message")
#: The CSV's columns as a Russian table heads them.
CSV_FIELDS_RU = ("файл", "студент", "статус", "оценка", "ошибки", "необъяснённые", "величин", "верно", "неверно",
                 "замечаний", "худшая", "худшая_ошибка_%", "худшая_в_допусках", "сообщение")


def summary_row(path: str, report: Report | None, error: str | None = None, lang: str = "en") -> dict[str, Any]:
    if report is None:
        return {"file": path, "student": "", "status": "error" if lang != "ru" else "ошибка", "mark": "",
                "causes": "", "unexplained": "", "items": "", "passed": "", "failed": "", "findings": "", "worst": "",
                "worst_error_pct": "", "worst_tol": "", "message": error or ""}
    from plans.language import quantity_name

    def at(q: str, phi: float) -> str:
        return say_line("ch_at", lang, what=quantity_name(q, lang), phi=decimal(f"{phi:g}", lang))

    # the worst figure in units of its own tolerance: 0 mm against a short exact segment is
    # a fraction of a millimetre, not −100 %
    worst = max((i for i in report.items if i.tolerance > 0), key=_in_tolerances, default=None)
    causes = "; ".join(kind_word(c.kind, lang) + (
        f" {'при' if lang == 'ru' else 'at'} {','.join(decimal(f'{p:g}', lang) for p in c.positions)}°"
        if c.positions else "") for c in report.causes)
    unexplained = "; ".join(at(i.quantity, i.phi_deg) for i in report.unexplained)
    return {"file": path, "student": report.check.student, "status": "ok" if lang != "ru" else "проверен",
            "mark": "" if report.mark is None else fmt(report.mark, lang), "causes": causes,
            "unexplained": unexplained,
            **report.counts(),
            "findings": len(report.findings_left),
            "worst": "" if worst is None else at(worst.quantity, worst.phi_deg),
            "worst_error_pct": "" if worst is None or worst.error_pct is None else decimal(f"{worst.error_pct:.2f}", lang),
            "worst_tol": "" if worst is None else decimal(f"{_in_tolerances(worst):.2f}", lang), "message": ""}


def _in_tolerances(it: Item) -> float:
    return abs(it.student - it.exact) / it.tolerance if it.tolerance > 0 else 0.0


def csv_text(rows: list[dict[str, Any]], lang: str = "en") -> str:
    """The summary table; in Russian its heads are Russian (the rows' keys stay)."""
    buf = io.StringIO()
    w = csv.DictWriter(buf, fieldnames=list(CSV_FIELDS), lineterminator="\n")
    if lang == "ru":
        w.writerow(dict(zip(CSV_FIELDS, CSV_FIELDS_RU, strict=True)))
    else:
        w.writeheader()
    for r in rows:
        w.writerow(r)
    return buf.getvalue()


def check_file(path: str | Path) -> Report:
    cf = load_check(path)
    try:
        return check(cf)
    except PlansError as exc:
        exc.source = exc.source or str(path)
        raise


# --------------------------------------------------------------------------- what the command writes


def error_line(msg: str) -> None:
    """A user error of ``plans check`` as one line on stderr (in the run's language)."""
    from plans.errors import error_prefix

    print(f"{error_prefix()}{' '.join(msg.split())}", file=sys.stderr)


def report_language(args: argparse.Namespace, report: Report | None = None) -> str:
    """The report's language: ``--language``, else the scene's ``[sheet] language``, else
    the locale's."""
    from plans.language import choose

    return choose(getattr(args, "language", None), report.check.scene.raw if report is not None else None)


def make_folder(folder: Path) -> None:
    """An output folder made (OutputError naming it when it cannot be)."""
    try:
        folder.mkdir(parents=True, exist_ok=True)
    except OSError as exc:
        raise OutputError(Said("k_make_folder", folder=str(folder), why=os_reason(exc))) from None


def write_summary(rows: list[dict[str, Any]], args: argparse.Namespace, out: Path) -> None:
    """summary.csv (or --csv, '-': stdout) and a line per file on the terminal."""
    lang = report_language(args)
    if args.csv == "-":
        sys.stdout.write(csv_text(rows, lang))
        return
    atomic_write(Path(args.csv) if args.csv else out / "summary.csv", csv_text(rows, lang))
    if not args.quiet:
        for r in rows:
            if r["status"] in ("ok", "проверен"):
                print(say_line("ch_row_ok", lang, file=r["file"], student=r["student"], passed=r["passed"],
                           failed=r["failed"], findings=r["findings"])
                      + (say_line("ch_row_mark", lang, mark=r["mark"]) if r.get("mark") else "")
                      + (f"; {r['causes']}" if r.get("causes") else ""))
            else:
                print(say_line("ch_row_error", lang, file=r["file"], message=r["message"]))
