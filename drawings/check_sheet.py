"""Sheets for checking a hand-drawn sheet (see :mod:`plans.check`).

* The **marked sheet**: the exact velocity and acceleration plans drawn at the
  student's own scales (plan mm = sheet mm), each measured figure marked where the
  student's reading puts it (a ring on the exact direction at the student's length:
  green when it passes, red when it fails), the tolerance drawn as a circle around
  the exact point, the error written next to it; then a panel listing the failed
  figures and the findings of the consistency checks.
* The **overlay sheet**: the same exact plans at 1:1 on the student's sheet size
  (``sheet = "A1"`` in the check file), thin lines, poles marked with a cross, and the
  tolerance circles: printed on tracing paper and laid over the drawing with the
  pole on the student's pole and the known vector (p a) along the student's, every
  point of the student's plan should fall inside its circle.

Use :func:`marked_sheets` / :func:`overlay_sheets` for :class:`~drawings.paper.sheet.Sheet`
objects, or :func:`save_check_sheets` to write ``<stem>-marked.svg`` and
``<stem>-overlay.svg`` (and PDF/PNG).  :func:`add_sheet_options` adds ``--sheet DIR``
to the ``plans check`` parser (the command-line wrapper in :mod:`drawings.cli` calls it).
"""

from __future__ import annotations

import argparse
import math
import re
import sys
from collections.abc import Sequence
from pathlib import Path

from drawings.linkage.panels import PAD, SMALL_SIZE, TITLE_SIZE, Panel, plan_panel
from drawings.paper.backend import Prim, Pt, Recording, Style
from drawings.paper.common import Placer, fmt, ident, label_boxes, phi_tag
from drawings.paper.export import FORMATS as FORMATS_OUT
from drawings.paper.export import render, write
from drawings.paper.sheet import FORMATS, Sheet, SheetSpec, compose
from drawings.paper.text import layout, wrap
from plans.check.report import Finding, Item, Report, check_file
from plans.check.wording import CAUSES, KINDS_RU, UNITS_RU
from plans.errors import PlansError
from plans.kinematics.plan import Plan

PASS = "#1d7a34"
FAIL = "#c0261d"
MARK_R = 1.2  # mm, the ring marking the student's point
TEXT_SIZE = 2.8
LIST_WIDTH = 260.0  # mm, the findings panel


def _pole_paper(panel: Panel, plan: Plan) -> Pt:
    """Where the plan's pole ended up on the panel (its dot is drawn there)."""
    eid = f"{panel.pid}-pt-{ident(plan.pole)}"
    for p in panel.prims:
        if p.op == "circle" and p.eid == eid:
            return p.pts[0]
    raise KeyError(eid)  # pragma: no cover - plan_panel always draws the pole


def _repack(pid: str, kind: str, phi: float | None, prims: Sequence[Prim], title: str,
            quantity: str | None = None, scale: float | None = None) -> Panel:
    rec = Recording(list(prims))
    x0, y0, x1, y1 = rec.bbox()
    moved = rec.moved(PAD - x0, PAD - y0)
    return Panel(pid, kind, phi, tuple(moved.prims), x1 - x0 + 2 * PAD, y1 - y0 + 2 * PAD, title, quantity, scale)


def _items_on(report: Report, plan: Plan) -> list[Item]:
    return [i for i in report.items if i.phi_deg == plan.phi_deg and i.plan == plan.kind and i.segment
            and i.figure != "value" and i.student_mm is not None]


def _marks(report: Report, plan: Plan, pole: Pt, lang: str, *, annotate: bool,
           taken: Sequence[Prim] = ()) -> Recording:
    """Rings at the student's points, tolerance circles at the exact ones, errors written
    (placed clear of the plan's own labels and vectors)."""
    rec = Recording()
    placer = Placer()
    for box in label_boxes(taken):
        placer.add_box(box)
    for p in taken:
        if p.op == "line" and len(p.pts) == 2:
            placer.add_line(list(p.pts))

    def paper(xy: tuple[float, float]) -> Pt:
        return (pole[0] + xy[0], pole[1] - xy[1])

    seen: set[tuple[str, str]] = set()
    for it in _items_on(report, plan):
        assert it.segment is not None and it.student_mm is not None
        a, b = it.segment
        if not (plan.has(a) and plan.has(b)) or it.segment in seen:
            continue
        seen.add(it.segment)
        pa, pb = paper(plan.xy(a)), paper(plan.xy(b))
        L = math.dist(pa, pb)
        color = PASS if it.verdict == "pass" else FAIL
        key = f"check-{plan.kind}-{phi_tag(plan.phi_deg)}-{ident(it.quantity)}"
        rec.begin(key, f"check-mark {it.verdict}")
        if it.tolerance_mm:
            rec.circle(pb, it.tolerance_mm, Style(width=0.18, stroke=color, dash=(1.0, 0.8)), f"{key}-tol")
        if L > 1e-9:
            ux, uy = (pb[0] - pa[0]) / L, (pb[1] - pa[1]) / L
            sp = (pa[0] + ux * it.student_mm, pa[1] + uy * it.student_mm)
        else:  # a vector that vanishes exactly: the student's end drawn off along x
            ux, uy = 1.0, 0.0
            sp = (pa[0] + it.student_mm, pa[1])
        if not annotate:  # tracing paper: only the tolerance circles, the student's points are below
            rec.end()
            continue
        rec.circle(sp, MARK_R, Style(width=0.3, stroke=color), f"{key}-student")
        if annotate:
            mm_ = "мм" if lang == "ru" else "mm"
            err = "" if it.error_mm is None else f"{it.error_mm:+.1f} {mm_}".replace(".", "," if lang == "ru" else ".")
            pct = "" if it.error_pct is None else f" ({fmt(it.error_pct, 2, lang)} %)"
            text = f"{typeset(it.quantity, lang)}: {fmt(it.student_mm, 3, lang)} {mm_}, {err}{pct}"
            # beside the ring, preferably across the vector
            lab = placer.place(text, sp, SMALL_SIZE, prefer=(-uy, ux), gap=MARK_R + 0.6)
            rec.text(lab, f"check-note {it.verdict}", f"{key}-note", fill=color)
        rec.end()
    return rec


def plan_with_marks(report: Report, plan: Plan, lang: str = "ru", *, overlay: bool = False) -> Panel:
    """One exact plan at the student's scale with the student's figures marked."""
    base = plan_panel(plan, lang, "mu", pid=f"{'overlay' if overlay else 'check'}-{plan.kind}-"
                                             f"{phi_tag(plan.phi_deg)}")
    pole = _pole_paper(base, plan)
    prims = list(base.prims)
    if overlay:  # a cross on the pole to align the tracing paper
        c = Style(width=0.18, stroke="#000")
        rec = Recording()
        rec.line((pole[0] - 8, pole[1]), (pole[0] + 8, pole[1]), c, f"{base.pid}-cross-h")
        rec.line((pole[0], pole[1] - 8), (pole[0], pole[1] + 8), c, f"{base.pid}-cross-v")
        prims += rec.prims
    prims += _marks(report, plan, pole, lang, annotate=not overlay, taken=base.prims).prims
    return _repack(base.pid, plan.kind, plan.phi_deg, prims, base.title, base.quantity, base.scale)


_NAME = re.compile(r"\b([A-Za-z]+)_([A-Za-z0-9_]+)(?:\^[nτk])?")



_SPECIAL = {
    "F_bal": ("F_{ур}", "F_{bal}"), "F_bal_lever": ("F_{ур} (рычаг)", "F_{bal} (lever)"),
    "F_bal_diff_pct": ("δF_{ур}, %", "δF_{bal}, %"),
}
_GREEK = {"Phi": "Φ", "omega": "ω", "eps": "ε", "tau": "τ"}


def typeset(name: str, lang: str = "ru") -> str:
    """A quantity key of the report as the sheet writes it: ``M_Phi_2`` -> ``M_{Φ2}``,
    ``F_bal_lever`` -> ``F_{ур} (рычаг)``, ``omega_3`` -> ``ω_{3}``, ``a_BA^n`` -> ``a_{BA}^n``."""
    if name in _SPECIAL:
        return _SPECIAL[name][0 if lang == "ru" else 1]
    head, sep, rest = name.partition("_")
    head = _GREEK.get(head, head)
    if not sep:
        return head
    parts = rest.split("_")
    if parts and parts[0] in _GREEK:  # M_Phi_2 -> M_{Φ2}
        return f"{head}_{{{_GREEK[parts[0]]}{''.join(parts[1:])}}}"
    if parts and parts[0].startswith("Phi"):  # an arm: h_Phi2_B -> h_{Φ2,B}
        return f"{head}_{{{','.join([_GREEK['Phi'] + parts[0][3:]] + parts[1:])}}}"
    sub, caret, sup = "_".join(parts).partition("^")
    return f"{head}_{{{sub}}}" + (f"^{sup}" if caret else "")


def _markup(text: str, lang: str = "ru") -> str:
    """Quantity names of the report as sheet markup, typeset (:func:`typeset`)."""
    return _NAME.sub(lambda m: typeset(m.group(0), lang), text)


def finding_text(f: Finding, lang: str = "ru") -> str:
    """A finding as the sheet writes it: in the sheet's language, quantities typeset."""
    kind = KINDS_RU.get(f.kind, f.kind) if lang == "ru" else f.kind
    if f.words is None:  # pragma: no cover - every finding of the check has its words
        return f"[{kind}] {_markup(f.message, lang)}"
    return f"[{kind}] {f.words.render(lang, lambda q: typeset(q, lang))}"


def _fail_line(it: Item, lang: str) -> str:
    pct = "" if it.error_pct is None else f", {fmt(it.error_pct, 3, lang)} %"
    mm = "" if it.error_mm is None else f", {fmt(it.error_mm, 3, lang)} {'мм' if lang == 'ru' else 'mm'}"
    where = f" ({it.where})" if it.where else ""
    exact = "точно" if lang == "ru" else "exact"
    unit = UNITS_RU.get(it.unit, it.unit) if lang == "ru" else it.unit.replace("^2", "²")
    return (f"φ = {fmt(it.phi_deg, 6, lang)}°  {it.quantity} = {fmt(it.student, 4, lang)}, "
            f"{exact} {fmt(it.exact, 4, lang)} {unit}{pct}{mm}{where}")


def findings_panel(report: Report, lang: str = "ru") -> Panel:
    """The failed figures and the consistency findings, as text."""
    rec = Recording()
    y = 0.0
    title = "Замечания" if lang == "ru" else "Findings"
    rec.text(layout(f"{title}: {report.check.student}", 0, y, TITLE_SIZE, "start", "top"), "title", "check-list-title")
    y += TITLE_SIZE + 3
    fails: list[Item] = report.unexplained if report.diagnosis is not None else \
        [i for i in report.items if i.verdict == "fail"]
    mark = fmt(report.mark or 0.0, 4, lang) if report.mark is not None else "—"
    if lang == "ru":
        head = (f"Проверено величин: {len(report.items)}; в допуске {report.passed}, вне допуска "
                f"{report.failed}; ошибок {len(report.causes)}; замечаний {len(report.findings_left)}; оценка {mark}")
    else:
        head = (f"{len(report.items)} figures: {report.passed} pass, {report.failed} fail; "
                f"{len(report.causes)} mistakes; {len(report.findings_left)} findings; mark {mark}")
    rec.text(layout(head, 0, y, TEXT_SIZE, "start", "top"), "note", "check-list-summary")
    y += TEXT_SIZE + 3
    lines: list[tuple[str, str]] = []
    for n, c in enumerate(report.causes, 1):  # the mistakes first, each with what it explains
        at = ", ".join(f"{fmt(p, 6, lang)}°" for p in c.positions)
        names = ", ".join(typeset(q, lang) for q in c.explains)
        if lang == "ru":
            text = (f"Ошибка {n}: {CAUSES[c.kind][1] if c.kind in CAUSES else c.kind}"
                    + (f" (φ = {at})" if at else "") + (f"; объясняет: {names}" if names else "")
                    + f"; −{fmt(c.deduction, 3, lang)}")
        else:
            text = (f"Mistake {n}: {c.detail}" + (f" (φ = {at})" if at else "")
                    + (f"; explains {names}" if names else "") + f"; −{fmt(c.deduction, 3, lang)}")
        lines.append((text, FAIL))
        for i in c.items:  # the figures it explains, under it
            lines.append(("    " + _markup(_fail_line(report.items[i], lang), lang), FAIL))
        for fi in c.findings:
            lines.append(("    " + finding_text(report.findings[fi], lang), "#000"))
    for it in fails:  # the failures no mistake explains
        lines.append((_fail_line(it, lang), FAIL))
    lines = [(text if text.startswith(("Ошибка", "Mistake", "    ")) else _markup(text, lang), color)
             for text, color in lines]
    f: Finding
    for f in report.findings_left:
        lines.append((finding_text(f, lang), "#000"))
    for k, (text, color) in enumerate(lines):
        for part in wrap(text, LIST_WIDTH, TEXT_SIZE):
            rec.text(layout(part, 0, y, TEXT_SIZE, "start", "top"), "check-line", f"check-list-{k}", fill=color)
            y += TEXT_SIZE * 1.45
    return _repack("check-findings", "table", None, rec.prims, title)


def _spec(report: Report, lang: str, title: str, fmt_name: str | None) -> SheetSpec:
    sheet = fmt_name or report.check.sheet or "A1"
    if sheet not in FORMATS:
        sheet = "A1"
    return SheetSpec(format=sheet, language=lang, title=title, author=report.check.student,
                     subtitle=report.check.scene.title_in(lang))


def _plans(report: Report) -> list[Plan]:
    out = []
    for pos in report.check.positions:
        pp = report.context.plans[pos.index]
        for plan in (pp.velocity, pp.acceleration):
            if plan is not None:
                out.append(plan)
    return out


def marked_sheets(report: Report, *, language: str = "ru", format: str | None = None) -> list[Sheet]:
    """Exact plans at the student's scales with the student's figures marked, then the findings."""
    panels = [plan_with_marks(report, p, language) for p in _plans(report)]
    panels.append(findings_panel(report, language))
    title = "Проверка листа" if language == "ru" else "Sheet check"
    return compose(panels, _spec(report, language, title, format), "", report.check.path)


def overlay_sheets(report: Report, *, language: str = "ru") -> list[Sheet]:
    """The exact plans at 1:1 on the student's sheet size, with tolerance circles, for tracing paper."""
    panels = [plan_with_marks(report, p, language, overlay=True) for p in _plans(report)]
    title = "Калька для проверки" if language == "ru" else "Overlay"
    # the plans stay 1:1; the paper is the smallest format that holds them on one sheet
    for fmt_name in ("A4", "A3", "A2"):
        try:
            sheets = compose(panels, _spec(report, language, title, fmt_name), "1:1", report.check.path)
        except PlansError:
            continue
        if len(sheets) == 1:
            return sheets
    return compose(panels, _spec(report, language, title, report.check.sheet or "A1"), "1:1", report.check.path)


def save_check_sheets(report: Report | str | Path, outdir: str | Path, stem: str | None = None,
                      formats: Sequence[str] = ("svg",), *, language: str = "ru", dpi: float = 150.0) -> list[Path]:
    """Write ``<stem>-marked.*`` and ``<stem>-overlay.*``; returns the files written."""
    rep = report if isinstance(report, Report) else check_file(report)
    return write(render_check_sheets(rep, outdir, stem, formats, language=language, dpi=dpi), outdir,
                 source=rep.check.path)


def render_check_sheets(rep: Report, outdir: str | Path, stem: str | None = None,
                        formats: Sequence[str] = ("svg",), *, language: str = "ru",
                        dpi: float = 150.0) -> dict[Path, bytes]:
    """The marked and overlay sheets as bytes by target path; nothing is written."""
    name = stem or Path(rep.check.path).stem
    files = render(marked_sheets(rep, language=language), outdir, f"{name}-marked", formats, dpi)
    files.update(render(overlay_sheets(rep, language=language), outdir, f"{name}-overlay", formats, dpi))
    return files


# --------------------------------------------------------------------------- command line


def add_sheet_options(check_parser: argparse.ArgumentParser) -> argparse.ArgumentParser:
    """Give ``plans check`` (the parser from :func:`plans.check.register`) the options
    ``--sheet DIR`` and ``--sheet-format svg,pdf,png``: after the report, the marked and
    overlay sheets of every file checked are written to DIR (a bad file has none)."""
    check_parser.add_argument("--sheet", metavar="DIR",
                              help="also write the marked sheet and the 1:1 overlay of each file here")
    check_parser.add_argument("--sheet-format", default="svg", metavar="svg,pdf,png,dxf",
                              help="formats of the sheets (default svg)")
    check_parser.add_argument("--sheet-language", choices=("ru", "en"),
                              help="of the marked sheets (default: the report's, --language else the scene's "
                                   "[sheet] language else the locale's)")
    inner = check_parser.get_default("func")

    def run_with_sheets(args: argparse.Namespace) -> int:
        if getattr(args, "sheet", None):
            formats = [f.strip().lower() for f in str(args.sheet_format).split(",") if f.strip()]
            bad = [f for f in formats if f not in FORMATS_OUT] or ([] if formats else [args.sheet_format])
            if bad:
                from plans.errors import Said, error_prefix, run_language

                print(f"{error_prefix()}--sheet-format: "
                      + Said("dc_formats", formats=",".join(FORMATS_OUT), got=repr(args.sheet_format)).text(run_language()),
                      file=sys.stderr)
                return 2

            from drawings.paper.manifest import forget, plan_sheets, remove

            folder = Path(args.sheet)
            stale: list[Path] = []  # the old sheets of the file being checked

            def extra(report: Report, target: Path) -> dict[Path, bytes]:
                from plans.check.report import report_language

                lang = args.sheet_language or report_language(args, report)
                files = render_check_sheets(report, folder, target.stem, formats, language=lang)
                staged, old = plan_sheets(folder, files, target)
                stale[:] = old
                return staged

            def after(target: Path, written: bool) -> None:
                if written:
                    remove(stale)
                elif folder.is_dir():
                    forget(folder, target)
                stale.clear()

            args.extra_files = extra
            args.after_write = after
        return int(inner(args))

    check_parser.set_defaults(func=run_with_sheets)
    return check_parser
