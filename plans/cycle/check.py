"""Checking the cycle tables of a hand-drawn dynamics sheet (seed 004's tables 1.1–1.4).

A cycle check file is a check file with a ``[cycle]`` table instead of ``[[positions]]``;
rows are arrays over the student's positions, as the tables are laid out on the sheet::

    format = 1
    student = "..."
    scene = "../dynamics_slider_crank.toml"

    [cycle]
    phi_deg = [0, 30, 60]            # the student's positions
    sign = "driving"                 # M_pr > 0 when the loads drive the crank; or "resisting"
    velocity_scale = { mu = 125 }    # μ of the student's velocity plans, mm per m/s ...
    # analogue_scale = { mu = 850 }  # ... or of plans of analogues (ω1 = 1), mm per m
    segment_mm = 1.0                 # a segment drawn and read: ±1 mm
    rule_pct = 5                     # values: ±5 % (of the row's largest where they vanish)

    [cycle.measured]                 # segments on the plans, mm: p + point, or two points
    pc = [0, 36, 59]
    bs2 = [21.6, 18.6, 11]

    [cycle.values]                   # SI: v_C, v_CB, omega_2, I_pr, M_pr, I_A, m2_vS2, I2_w2,
    I_pr = [2.2317, 2.535, 3.059]    # m3_vC (the rows of I_pr), G2, F_c (loads, N), M_G2 ...
    M_pr = [0, 83.084, 138.319]

    [cycle.flywheel]
    inertia = 380.0                  # kg·m², the flywheel the student read off
"""

from __future__ import annotations

import argparse
import re
from dataclasses import dataclass
from pathlib import Path
from typing import Any

import numpy as np

from plans.errors import InputError, OutputError, Said
from plans.forces.loads import apply_loads, parse_loads
from plans.io import dumps, read_toml, refuse_input, write_all
from plans.kinematics.exact import solve
from plans.reader import Reader, show
from plans.scene.model import Scene, load_scene
from plans.verdicts import Tally

from .dynamics import dynamics, reduce
from .spec import ANGLE_LIMIT_DEG, rotor_inertia

_KEYS = {"phi_deg", "sign", "velocity_scale", "analogue_scale", "segment_mm", "rule_pct", "measured", "values",
         "flywheel"}
#: The error of a figure is judged against at least this (where every exact value of its row
#: vanishes): a student's 1e12 against 0 is a finite, huge percentage, never infinite.
PCT_FLOOR = 1e-12
_TOP = {"format", "student", "scene", "cycle", "title"}
VANISH = 0.05  # a value is judged against 5 % of its row's largest where it vanishes


@dataclass(frozen=True, slots=True)
class CycleItem:
    quantity: str
    phi_deg: float | None
    student: float
    exact: float
    unit: str
    error_pct: float
    error_mm: float | None
    tolerance: str
    verdict: str
    field: str

    def to_json(self) -> dict[str, Any]:
        return {"quantity": self.quantity, "phi_deg": self.phi_deg, "student": self.student, "exact": self.exact,
                "unit": self.unit, "error_pct": self.error_pct, "error_mm": self.error_mm,
                "tolerance": self.tolerance, "verdict": self.verdict, "field": self.field}


@dataclass(frozen=True)
class CycleReport(Tally):
    path: str
    student: str
    scene: Scene
    items: tuple[CycleItem, ...]

    def to_json(self) -> dict[str, Any]:
        return {"format": 1, "kind": "cycle", "student": self.student, "check_file": self.path,
                "scene": self.scene.path, "items": [i.to_json() for i in self.items],
                "summary": self.counts()}


def is_cycle_check(path: str | Path) -> bool:
    """A check file whose figures are cycle tables."""
    try:
        data = read_toml(path)
    except InputError:
        return False
    return isinstance(data.get("cycle"), dict) and "positions" not in data


def _fail(path: str, field: str, msg: str | Said) -> InputError:
    return InputError(msg, file=path, field=field)


def _scale(path: str, raw: Any, field: str) -> float:
    if not (isinstance(raw, dict) and len(raw) == 1 and set(raw) <= {"mu", "K"}):
        raise _fail(path, field, Said("cc_mu_mm_per"))
    (k, v), = raw.items()
    f = Reader(path).value(v, f"{field}.{k}", positive=True)
    return f if k == "mu" else 1.0 / f


def _rows(path: str, raw: Any, where: str, n: int) -> dict[str, list[float | None]]:
    if not isinstance(raw, dict):
        raise _fail(path, where, Said("cc_table_name_one"))
    out = {}
    for name, vals in raw.items():
        f = f"{where}.{name}"
        if not (isinstance(vals, list) and len(vals) == n):
            raise _fail(path, f, Said("cc_figures_one_per", n=n))
        row: list[float | None] = []
        for k, v in enumerate(vals):
            if v == "" or v == "-":
                row.append(None)
            elif isinstance(v, bool) or not isinstance(v, int | float):
                raise _fail(path, f"{f}[{k}]", Said("cc_numbers_none", got=show(v)))
            else:
                row.append(Reader(path).value(v, f"{f}[{k}]"))
        out[name] = row
    return out


def _segment(scene: Scene, name: str) -> tuple[str | None, str] | None:
    """``pc`` -> (None, "C"); ``bs2`` -> ("B", "S2"): the pole or a point, then a point."""
    points = sorted({n for link in scene.links.values() for n in link.points} | set(scene.frame_points),
                    key=len, reverse=True)
    low = {p.lower(): p for p in points}

    def split(s: str) -> list[str] | None:
        if not s:
            return []
        for p in sorted(low, key=len, reverse=True):
            if s.startswith(p):
                rest = split(s[len(p):])
                if rest is not None:
                    return [low[p]] + rest
        return None

    if name.startswith("p") and len(name) > 1:
        tail = split(name[1:])
        if tail is not None and len(tail) == 1:
            return None, tail[0]
    parts = split(name)
    if parts is not None and len(parts) == 2:
        return parts[0], parts[1]
    return None


def check_cycle(path: str | Path) -> CycleReport:
    path = str(path)
    data = read_toml(path)
    from plans.kinds import check_top

    check_top(data, path, "check", _TOP)
    rd = Reader(path)
    cyc = rd.table(data, "cycle", "")
    rd.keys(cyc, _KEYS, "cycle.")
    scene_ref = data.get("scene")
    if not isinstance(scene_ref, str):
        raise _fail(path, "scene", Said("cc_path_scene_file"))
    target = Path(scene_ref) if Path(scene_ref).is_absolute() else Path(path).parent / scene_ref
    if not target.is_file():
        raise _fail(path, "scene", Said("cc_scene_file_scene", scene_ref=scene_ref, target=target))
    scene = load_scene(target)
    phis = cyc.get("phi_deg")
    if not (isinstance(phis, list) and phis and all(isinstance(p, int | float) and not isinstance(p, bool)
                                                    for p in phis)):
        raise _fail(path, "cycle.phi_deg", Said("cc_student_crank_angles"))
    phis_a = np.asarray([rd.value(p, "cycle.phi_deg", limit=ANGLE_LIMIT_DEG, floor=0.0) for p in phis], float)
    n = len(phis)
    sign = cyc.get("sign", "driving")
    if sign not in ("driving", "resisting"):
        raise _fail(path, "cycle.sign", Said("cc_driving_resisting", got=show(sign)))
    mu_v = _scale(path, cyc["velocity_scale"], "cycle.velocity_scale") if "velocity_scale" in cyc else None
    mu_an = _scale(path, cyc["analogue_scale"], "cycle.analogue_scale") if "analogue_scale" in cyc else None
    seg_tol = rd.number(cyc, "segment_mm", "cycle.", default=1.0, positive=True)
    rule = rd.number(cyc, "rule_pct", "cycle.", default=5.0, positive=True)
    loads = parse_loads(scene)
    kin = solve(scene, phis_a, order=2)
    red = reduce(scene, loads, kin, rotor_inertia(scene))
    w = abs(scene.driver.omega)
    exact_rows: dict[str, tuple[np.ndarray, str]] = {"I_pr": (red.I_pr, "kg*m^2"),
                                                      "M_pr": (red.M_pr * (1 if sign == "driving" else -1), "N*m")}
    for r in red.inertia_rows:
        exact_rows[r.key] = (r.values, "kg*m^2")
    for r in red.load_rows:
        exact_rows[f"M_{r.key}"] = (r.values * (1 if sign == "driving" else -1), "N*m")
    for f in apply_loads(scene, loads, kin).forces:
        if f.kind != "inertia":
            exact_rows[f.label] = (np.abs(f.F), "N")
    for lid in scene.links:
        exact_rows[f"omega_{lid}"] = (np.abs(kin.omega(lid)), "rad/s")
    items: list[CycleItem] = []
    measured = _rows(path, cyc.get("measured", {}), "cycle.measured", n)
    for name, row in measured.items():
        seg = _segment(scene, name)
        if seg is None:
            raise _fail(path, f"cycle.measured.{name}", Said("cc_segment_plan_point"))
        if mu_v is None and mu_an is None:
            raise _fail(path, "cycle.velocity_scale", Said("cc_segments_need_student"))
        vb = kin.point(seg[1])[1]
        va = 0 if seg[0] is None else kin.point(seg[0])[1]
        mm = np.abs(vb - va) * (mu_v if mu_v is not None else (mu_an or 0.0) / w)
        for k, s in enumerate(row):
            if s is None:
                continue
            err = abs(s - mm[k])
            items.append(CycleItem(name, float(phis_a[k]), s, float(mm[k]), "mm",
                                   100 * err / max(abs(mm[k]), VANISH * float(np.max(mm)), PCT_FLOOR), err,
                                   f"±{seg_tol:g} mm", "pass" if err <= seg_tol + 1e-9 else "fail",
                                   f"cycle.measured.{name}[{k}]"))
    values = _rows(path, cyc.get("values", {}), "cycle.values", n)
    for name, row in values.items():
        ex = _exact_value(scene, kin, name, exact_rows)
        if ex is None:
            raise _fail(path, f"cycle.values.{name}", Said("cc_scene_has_such", v=sorted(exact_rows)))
        vals, unit = ex
        ref = VANISH * float(np.max(np.abs(vals)))
        for k, s in enumerate(row):
            if s is None:
                continue
            e = float(vals[k])
            pct = 100 * abs(s - e) / max(abs(e), ref, PCT_FLOOR)
            items.append(CycleItem(name, float(phis_a[k]), s, e, unit, pct, None, f"±{rule:g} %",
                                   "pass" if pct <= rule else "fail", f"cycle.values.{name}[{k}]"))
    fly = cyc.get("flywheel", {})
    if fly:
        if not isinstance(fly, dict) or set(fly) - {"inertia"} or "inertia" not in fly:
            raise _fail(path, "cycle.flywheel", Said("cc_inertia_kg"))
        s = rd.value(fly["inertia"], "cycle.flywheel.inertia", positive=True)
        d = dynamics(scene)
        e = d.flywheel.inertia_exact
        pct = 100 * abs(s - e) / max(abs(e), PCT_FLOOR)
        items.append(CycleItem("I_fw", None, s, e, "kg*m^2", pct, None, f"±{rule:g} %",
                               "pass" if pct <= rule else "fail", "cycle.flywheel.inertia"))
    student = rd.string(data.get("student", Path(path).stem), "student")
    if "title" in data:
        rd.string(data["title"], "title", limit=2000)
    return CycleReport(path, student, scene, tuple(items))


def _exact_value(scene: Scene, kin: Any, name: str, rows: dict[str, tuple[np.ndarray, str]]):
    if name in rows:
        return rows[name]
    m = re.fullmatch(r"v_([A-Z][A-Za-z0-9]*)", name)
    points = {nm for link in scene.links.values() for nm in link.points}
    if m:
        if m.group(1) in points:
            return np.abs(kin.point(m.group(1))[1]), "m/s"
        for a in sorted(points, key=len, reverse=True):  # v_CB: relative velocity of C about B
            if m.group(1).startswith(a) and m.group(1)[len(a):] in points:
                return np.abs(kin.point(a)[1] - kin.point(m.group(1)[len(a):])[1]), "m/s"
    return None


def text(rep: CycleReport, lang: str = "en") -> str:
    from plans.check.report import decimal, say_line, unit_word
    from plans.language import quantity_name

    w = {k: say_line(k, lang) for k in ("ch_quantity", "ch_student", "ch_exact", "ch_error_pct", "ch_tolerance_col",
                                    "ch_verdict")}
    lines = [say_line("ch_cycle_title", lang, student=rep.student, title=rep.scene.title), say_line("ch_file", lang, path=rep.path),
             f"  {w['ch_quantity']:<10}{'φ':>9}{w['ch_student']:>12}{w['ch_exact']:>12}{w['ch_error_pct']:>10}  "
             f"{w['ch_tolerance_col']}  {w['ch_verdict']}"]
    for i in rep.items:
        phi = "" if i.phi_deg is None else decimal(f"{i.phi_deg:g}", lang)
        verdict = say_line("ch_pass" if i.verdict == "pass" else "ch_fail", lang) if lang == "ru" else i.verdict
        tol = decimal(i.tolerance, lang).replace(" mm", " " + unit_word("mm", lang))
        lines.append(f"  {quantity_name(i.quantity, lang):<10}{phi:>9}{decimal(f'{i.student:.6g}', lang):>12}"
                     f"{decimal(f'{i.exact:.6g}', lang):>12}{decimal(f'{i.error_pct:.2f}', lang):>10}  {tol:<9}  {verdict}")
    lines.append(say_line("ch_cycle_sum", lang, n=len(rep.items), passed=rep.passed, failed=rep.failed))
    return "\n".join(lines)


#: The columns of a cycle check's CSV, and as a Russian table heads them.
CSV_COLUMNS = ("quantity", "phi_deg", "student", "exact", "unit", "error_pct", "error_mm", "tolerance", "verdict",
               "field")
CSV_COLUMNS_RU = ("величина", "φ_град", "студент", "точно", "ед.", "ошибка_%", "ошибка_мм", "допуск", "оценка",
                  "поле")


def csv_text(rep: CycleReport, lang: str = "en") -> str:
    """One line per figure checked."""
    import csv
    import io

    from plans.check.report import decimal, say_line, unit_word

    ru = lang == "ru"
    buf = io.StringIO()
    w = csv.writer(buf, lineterminator="\n")
    w.writerow(CSV_COLUMNS_RU if ru else CSV_COLUMNS)
    for i in rep.items:
        num = (lambda x: decimal(repr(x), lang)) if ru else repr  # noqa: E731
        w.writerow([i.quantity, "" if i.phi_deg is None else num(i.phi_deg), num(i.student), num(i.exact),
                    unit_word(i.unit, lang), decimal(f"{i.error_pct:.4f}", lang),
                    "" if i.error_mm is None else decimal(f"{i.error_mm:.4f}", lang),
                    decimal(i.tolerance, lang).replace(" mm", " " + unit_word("mm", lang)),
                    say_line("ch_pass" if i.verdict == "pass" else "ch_fail", lang) if ru else i.verdict, i.field])
    return buf.getvalue()


def summary_row(path: str, rep: CycleReport, lang: str = "en") -> dict[str, Any]:
    """The line of ``summary.csv`` (``plans check DIR``) for a cycle check file."""
    from plans.check.report import decimal, say_line
    from plans.language import quantity_name

    worst = max(rep.items, key=lambda i: abs(i.error_pct), default=None)
    where = "" if worst is None else (quantity_name(worst.quantity, lang) if worst.phi_deg is None else say_line(
        "ch_at", lang, what=quantity_name(worst.quantity, lang), phi=decimal(f"{worst.phi_deg:g}", lang)))
    return {"file": path, "student": rep.student, "status": "ok" if lang != "ru" else "проверен",
            **rep.counts(), "findings": 0, "worst": where,
            "worst_error_pct": "" if worst is None else decimal(f"{worst.error_pct:.2f}", lang), "message": ""}


def outputs(rep: CycleReport, target: Path, out: Path, lang: str = "en") -> dict[Path, str]:
    """The report files of one cycle check file in the folder ``out``."""
    return {out / f"{target.stem}.json": dumps(rep.to_json()), out / f"{target.stem}.txt": text(rep, lang) + "\n"}


def run_file(target: Path, args: argparse.Namespace) -> int:
    """``plans check`` on a cycle check file (same options as for a sheet's check file; a
    cycle has no marked sheet).  Its outputs are written all or none."""
    import sys

    from plans.check.report import report_language

    rep = check_cycle(target)
    lang = report_language(args)
    for out_path in (args.json, getattr(args, "csv", None)):
        refuse_input(out_path, target, rep.scene.path)
    files: dict[Path, str] = {}
    if args.json and args.json != "-":
        files[Path(args.json)] = dumps(rep.to_json())
    if getattr(args, "csv", None) and args.csv != "-":
        files[Path(args.csv)] = csv_text(rep, lang)
    if getattr(args, "out", None):
        out = Path(args.out)
        try:
            out.mkdir(parents=True, exist_ok=True)
        except OSError as exc:
            raise OutputError(Said("cc_cannot_create_output", out=out, strerror=exc.strerror)) from None
        files.update(outputs(rep, target, out, lang))
    write_all(files)
    if args.json == "-":
        sys.stdout.write(dumps(rep.to_json()))
    elif getattr(args, "csv", None) == "-":
        sys.stdout.write(csv_text(rep, lang))
    if not args.quiet and args.json != "-" and getattr(args, "csv", None) != "-":
        print(text(rep, lang))
    return 0
