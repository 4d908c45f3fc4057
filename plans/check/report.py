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
from plans.errors import InputError, OutputError, PlansError
from plans.io import atomic_write
from plans.units import DUST, percent

_SCALE_UNIT = {"length": "mm/m", "velocity": "mm/(m/s)", "acceleration": "mm/(m/s²)", "force": "mm/N"}


@dataclass(frozen=True)
class Report:
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

    @property
    def passed(self) -> int:
        return sum(1 for i in self.items if i.verdict == "pass")

    @property
    def failed(self) -> int:
        return sum(1 for i in self.items if i.verdict == "fail")

    def item(self, quantity: str, phi_deg: float, where: str | None = None) -> Item:
        for it in self.items:
            if it.quantity == quantity and it.phi_deg == phi_deg and (where is None or it.where == where):
                return it
        raise KeyError((quantity, phi_deg, where))

    def findings_of(self, kind: str) -> list[Finding]:
        return [f for f in self.findings if f.kind == kind]

    def to_json(self) -> dict:
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
            "causes": [c.to_json() for c in self.causes],
            "unexplained": list(dict.fromkeys(i.quantity for i in self.unexplained)),
            "unexplained_items": [{"quantity": i.quantity, "phi_deg": i.phi_deg, "field": i.field}
                                  for i in self.unexplained],
            "mark": self.mark,
            "rubric": dict(self.diagnosis.rubric) if self.diagnosis is not None else {},
            "items": [i.to_json() for i in self.items],
            "findings": [{**f.to_json(), "cause": self._cause_of(n)} for n, f in enumerate(self.findings)],
            "unchecked": [u.to_json() for u in self.unchecked],
            "summary": {"items": len(self.items), "passed": self.passed, "failed": self.failed,
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
                            reason = "the student's own figure (checked for consistency)"
                        elif m:
                            reason = (f"the exact analysis has no arm of {m.group(1)} about {m.group(2)} "
                                      f"(a load it does not apply, or another moment equation)")
                        else:
                            reason = "a lever arm named by the student: name it h_<load>_<point> (e.g. h_Phi2_B)"
                        unchecked.append(Unchecked(q, pos.phi_deg, w.value, reason, w.where))
                    continue
                w0 = pos.written(q)[0]
                known = ", ".join(known_quantities(ctx, k))
                extra = f" ({ctx._forces_error})" if ctx._forces_error else ""
                raise InputError(f"the scene has no quantity {q!r} at {pos.phi_deg:g}°{extra}; "
                                 f"expected one of {known}", file=cf.path, field=w0.field)
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
        raise InputError(f"{q} is not read off a plan at a scale the check file gives: write it under values",
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
        verdict = "pass" if abs(diff) <= tol * (1 + 1e-9) else "fail"
        out.append(Item(q, pos.phi_deg, student, student_mm, ex.value, exact_mm, ex.unit, err_pct, err_mm,
                        tol, None if not mu else tol * mu, model, verdict, where, w.field, ex.source,
                        figure, ex.plan, ex.segment))
    return out





def _num(x: float | None, unit: str = "") -> str:
    if x is None:
        return "—"
    return fmt(x) + (f" {unit}" if unit else "")


def table(report: Report) -> str:
    """The readable terminal report."""
    cf = report.check
    t = cf.tolerance
    model = (f"draftsman: ±{t.segment_mm:g} mm per segment, ±{t.direction_deg:g}° per direction, "
             f"propagated; else course rule ±{t.rule_pct:g} %" if t.model == "draftsman"
             else f"course rule ±{t.rule_pct:g} %")
    lines = [f"Check of {cf.student} — {cf.scene.title}",
             f"  file {cf.path}; scales " + ", ".join(f"{k} {v:.4g} {_SCALE_UNIT.get(k, 'mm/unit')}" for k, v in cf.scales.items()),
             f"  tolerance: {model}"]
    lines += _causes_text(report)
    cause_no = {i: n for n, c in enumerate(report.causes, 1) for i in c.items}
    head = f"  {'quantity':<16}{'student':>14}{'exact':>14}{'error':>10}{'err mm':>9}{'tol mm':>8}{'tol %':>8}  verdict  where"
    for pos in cf.positions:
        lines.append("")
        lines.append(f"φ = {pos.phi_deg:g}°")
        lines.append(head)
        for n, it in enumerate(report.items):
            if it.phi_deg != pos.phi_deg:
                continue
            err = "—" if it.error_pct is None else f"{it.error_pct:+.1f} %"
            emm = "—" if it.error_mm is None else f"{it.error_mm:+.2f}"
            tmm = "—" if it.tolerance_mm is None else f"±{it.tolerance_mm:.2f}"
            tp = "—" if it.tolerance_pct is None else f"±{it.tolerance_pct:.1f}"
            mark = "pass" if it.verdict == "pass" else (f"FAIL #{cause_no[n]}" if n in cause_no else "FAIL")
            # only what the student wrote: a segment alone is shown in mm, its value is derived
            shown = f"{fmt(it.student_mm)} mm" if it.figure == "measured" and it.student_mm is not None \
                else _num(it.student)
            lines.append(f"  {it.quantity:<16}{shown:>14}{_num(it.exact):>14}{err:>10}{emm:>9}{tmm:>8}"
                         f"{tp:>8}  {mark:<7}  {it.where}  [{it.unit}{', rule' if it.tolerance_model == 'rule' else ''}]")
    if report.unchecked:
        lines.append("")
        lines.append("Not compared:")
        for u in report.unchecked:
            lines.append(f"  φ = {u.phi_deg:g}°: {u.quantity} = {fmt(u.student)}{(' (' + u.where + ')') if u.where else ''}"
                         f": {u.reason}")
    left = report.findings_left
    if left:
        lines.append("")
        lines.append(f"Findings no mistake accounts for ({len(left)}):")
        for f in left:
            lines.append(f"  [{f.kind}] {f.message}")
    lines.append("")
    lines.append(f"Summary: {len(report.items)} figures, {report.passed} pass, {report.failed} fail; "
                 f"{len(report.causes)} mistakes, {len(report.unexplained)} failures unexplained, "
                 f"{len(left)} other findings; mark {_mark(report)}")
    return "\n".join(lines)


def _mark(report: Report) -> str:
    full = report.diagnosis.rubric.get("full", 100.0) if report.diagnosis is not None else 100.0
    return f"{fmt(report.mark or 0.0)} of {fmt(full)}"


def _causes_text(report: Report) -> list[str]:
    """The mistakes found, each with the figures it explains; then the failures no
    mistake explains."""
    lines = ["", f"Mark: {_mark(report)}"]
    if not report.causes and not report.unexplained:
        lines.append("No mistakes found: every figure agrees with the exact analysis within the tolerance.")
        return lines
    lines.append(f"Mistakes ({len(report.causes)}):")
    for n, c in enumerate(report.causes, 1):
        at = ", ".join(f"{p:g}°" for p in c.positions)
        lines.append(f"  #{n} [{c.kind}] {c.detail}" + (f" (φ = {at})" if at else "") + f"; −{fmt(c.deduction)}")
        if c.explains:
            n_fig = len(c.items) or len(c.explains)
            lines.append(f"     explains {n_fig} figure{'s' if n_fig != 1 else ''}: {', '.join(c.explains)}")
        for fi in c.findings:
            lines.append(f"     [{report.findings[fi].kind}] {report.findings[fi].message}")
    if report.unexplained:
        lines.append(f"Failures no mistake explains ({len(report.unexplained)}):")
        for it in report.unexplained:
            shown = f"{fmt(it.student_mm)} mm" if it.figure == "measured" and it.student_mm is not None \
                else fmt(it.student)
            lines.append(f"  φ = {it.phi_deg:g}°: {it.quantity} = {shown}{(' (' + it.where + ')') if it.where else ''}, "
                         f"exact {fmt(it.exact)} {it.unit}")
    return lines


CSV_FIELDS = ("file", "student", "status", "mark", "causes", "unexplained", "items", "passed", "failed",
              "findings", "worst", "worst_error_pct", "worst_tol", "message")


def summary_row(path: str, report: Report | None, error: str | None = None) -> dict[str, Any]:
    if report is None:
        return {"file": path, "student": "", "status": "error", "mark": "", "causes": "", "unexplained": "",
                "items": "", "passed": "", "failed": "", "findings": "", "worst": "", "worst_error_pct": "",
                "worst_tol": "", "message": error or ""}
    # the worst figure in units of its own tolerance: 0 mm against a short exact segment is
    # a fraction of a millimetre, not −100 %
    worst = max((i for i in report.items if i.tolerance > 0), key=_in_tolerances, default=None)
    causes = "; ".join(c.kind + (f" at {','.join(f'{p:g}' for p in c.positions)}°" if c.positions else "")
                       for c in report.causes)
    unexplained = "; ".join(f"{i.quantity} at {i.phi_deg:g}°" for i in report.unexplained)
    return {"file": path, "student": report.check.student, "status": "ok",
            "mark": "" if report.mark is None else fmt(report.mark), "causes": causes, "unexplained": unexplained,
            "items": len(report.items), "passed": report.passed, "failed": report.failed,
            "findings": len(report.findings_left),
            "worst": "" if worst is None else f"{worst.quantity} at {worst.phi_deg:g}°",
            "worst_error_pct": "" if worst is None or worst.error_pct is None else f"{worst.error_pct:.2f}",
            "worst_tol": "" if worst is None else f"{_in_tolerances(worst):.2f}", "message": ""}


def _in_tolerances(it: Item) -> float:
    return abs(it.student - it.exact) / it.tolerance if it.tolerance > 0 else 0.0


def csv_text(rows: list[dict[str, Any]]) -> str:
    buf = io.StringIO()
    w = csv.DictWriter(buf, fieldnames=list(CSV_FIELDS), lineterminator="\n")
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
    """A user error of ``plans check`` as one line on stderr."""
    print(f"plans: error: {' '.join(msg.split())}", file=sys.stderr)


def make_folder(folder: Path) -> None:
    """An output folder made (OutputError naming it when it cannot be)."""
    try:
        folder.mkdir(parents=True, exist_ok=True)
    except OSError as exc:
        raise OutputError(f"cannot create the output folder {folder}: {exc.strerror}") from None


def write_summary(rows: list[dict[str, Any]], args: argparse.Namespace, out: Path) -> None:
    """summary.csv (or --csv, '-': stdout) and a line per file on the terminal."""
    if args.csv == "-":
        sys.stdout.write(csv_text(rows))
        return
    atomic_write(Path(args.csv) if args.csv else out / "summary.csv", csv_text(rows))
    if not args.quiet:
        for r in rows:
            if r["status"] == "ok":
                print(f"{r['file']}: {r['student']}: {r['passed']} pass, {r['failed']} fail, "
                      f"{r['findings']} findings" + (f"; mark {r['mark']}" if r.get("mark") else "")
                      + (f"; {r['causes']}" if r.get("causes") else ""))
            else:
                print(f"{r['file']}: not checked: {r['message']}")
