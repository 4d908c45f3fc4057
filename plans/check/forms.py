"""Blank forms for a teacher to type a student's figures into, and the form read back.

``plans check --template SCENE [--phi 90,210] [-o FILE]`` writes a check file with every
quantity the scene's sheets show at each position, under the names the checker reads,
each empty (``""``: not written), with the student and the scales to fill.
``--form csv`` writes the same as one row per quantity and one column per student;
``plans check FORM.csv`` reads every filled column back as one submission.

The CSV form::

    quantity,phi_deg,figure,1,2,3
    scene,,,../shaper.toml,../shaper.toml,../shaper.toml
    student,,,Ivanov,Petrov,
    scales.velocity.mu,,,100,100,
    v_B,30,mm,56.5,57,
    v_B,30,value,0.565,0.57,

``figure`` is ``mm`` (a segment measured on the student's plan) or ``value`` (SI units).
An empty cell is a figure not written; a column with no figure is no submission.
"""

from __future__ import annotations

import argparse
import csv
import io
import json
import math
import sys
from pathlib import Path
from typing import Any

from plans.check.checkfile import SCALE_KINDS, CheckFile, check_from_dict
from plans.errors import InputError, OutputError, PlansError, Said, one_line
from plans.io import dumps, refuse_input, write_all
from plans.scene.model import Scene
from plans.tolerances import SAME_ANGLE_DEG

_FIXED = ("quantity", "phi_deg", "figure")


def question_names(scene: Scene, scene_ref: str, phis: tuple[float, ...]) -> dict[float, tuple[list[str], list[str]]]:
    """Per position: (segments to measure, values to write), in the order of the sheets."""
    from plans.check.providers import Context, exact_value
    from plans.kinematics.construction import default_scales
    from plans.kinematics.exact import solve

    kin = solve(scene, order=2)
    mv, ma = default_scales(kin)
    # read as a form beside the scene names it (the written form, beside its target, names it by
    # scene_ref); an inline scene (a variant not yet on disk) as it is
    beside = Path(scene.path).name if scene.path and isinstance(scene_ref, str) else scene_ref
    data = {"format": 1, "scene": beside, "scales": {"velocity": {"mu": mv}, "acceleration": {"mu": ma}},
            "positions": [{"phi_deg": p, "values": {f"omega_{scene.driver.link}": 1.0}} for p in phis]}
    cf = check_from_dict(data, str(Path(scene.path or "scene.toml").with_suffix(".form.toml")))
    ctx = Context(cf)
    out: dict[float, tuple[list[str], list[str]]] = {}
    for pos in cf.positions:
        k = pos.index
        segs: list[str] = []
        for kind in ("velocity", "acceleration"):
            plan = ctx.plan(k, kind)
            if plan is not None:
                segs += [s.label for s in plan.segments if s.label not in segs]
        values = list(segs)
        for lid, link in sorted(scene.links.items()):
            if len(link.axis) == 2:
                values += [f"omega_{lid}", f"eps_{lid}"]
        got = ctx.forces()
        if got is not None:
            loads, fa = got
            for lid in sorted(scene.links):
                for q in (f"m_{lid}", f"I_{lid}", f"G_{lid}", f"Phi_{lid}", f"M_Phi_{lid}"):
                    if exact_value(ctx, k, q) is not None:
                        values.append(q)
            for rc in fa.reactions():
                name = f"F_{rc.name(scene.fij)[1:]}"
                values += [q for q in (name, f"{name}^τ", f"{name}^n") if exact_value(ctx, k, q) is not None]
            values += ["F_bal", "F_bal_lever", "F_bal_diff_pct"]
        out[pos.phi_deg] = (segs, list(dict.fromkeys(values)))
    return out


def _phis(scene: Scene, phis: tuple[float, ...] | None) -> tuple[float, ...]:
    return tuple(phis) if phis else tuple(scene.driver.phis_deg)


def template_toml(scene: Scene, scene_ref: str, phis: tuple[float, ...] | None = None, lang: str = "en") -> str:
    """The blank check file of a scene (see the module docstring), its comments in ``lang``."""
    phis = _phis(scene, phis)
    names = question_names(scene, scene_ref, phis)
    def q(x: str) -> str:
        return json.dumps(x, ensure_ascii=False)

    from plans.phrases import say

    lines = [say("cf_head", lang), "format = 1", 'student = ""', f"scene = {q(scene_ref)}", "",
             "[scales]  " + say("cf_scales", lang),
             "length = { mu = 1000 }", 'velocity = { mu = "" }', 'acceleration = { mu = "" }']
    if any("F_bal" in v for _, v in names.values()):
        lines.append('force = { mu = "" }')
    for phi in phis:
        segs, values = names[phi]
        lines += ["", "[[positions]]", f"phi_deg = {phi:g}", "", "[positions.measured]"]
        lines += [f"{q(s)} = \"\"" for s in segs]
        lines += ["", "[positions.values]"]
        lines += [f"{q(v)} = \"\"" for v in values]
    return "\n".join(lines) + "\n"


def template_csv(scene: Scene, scene_ref: str, phis: tuple[float, ...] | None = None, students: int = 3) -> str:
    """The blank CSV form: one row per quantity, one column per student."""
    phis = _phis(scene, phis)
    names = question_names(scene, scene_ref, phis)
    buf = io.StringIO()
    w = csv.writer(buf, lineterminator="\n")
    cols = [str(i + 1) for i in range(students)]
    w.writerow([*_FIXED, *cols])
    w.writerow(["scene", "", "", *[scene_ref] * students])
    w.writerow(["student", "", "", *[""] * students])
    w.writerow(["scales.length.mu", "", "", *["1000"] * students])
    for kind in ("velocity", "acceleration", "force"):
        w.writerow([f"scales.{kind}.mu", "", "", *[""] * students])
    for phi in phis:
        segs, values = names[phi]
        for s in segs:
            w.writerow([s, f"{phi:g}", "mm", *[""] * students])
        for v in values:
            w.writerow([v, f"{phi:g}", "value", *[""] * students])
    return buf.getvalue()


def _number(text: str, path: str, where: str) -> float | int | str:
    t = text.strip().replace(",", ".") if text.count(",") == 1 and "." not in text else text.strip()
    try:
        x = float(t)
    except ValueError:
        if any(c.isalpha() for c in t):
            return t  # a length with its unit: "65 mm"
        raise InputError(Said("cf_number_text", text=text), file=path, field=where) from None
    if not math.isfinite(x):
        raise InputError(Said("cf_finite_number_text", text=text), file=path, field=where)
    return int(x) if t.lstrip("+-").isdigit() else x


def read_form(path: str | Path) -> list[tuple[str, CheckFile]]:
    """Every filled column of a CSV form as (column, check file)."""
    path = str(path)
    try:
        text = Path(path).read_text(encoding="utf-8-sig")
    except UnicodeDecodeError:
        raise InputError(Said("cf_csv_form_utf"), file=path) from None
    rows = list(csv.reader(io.StringIO(text)))
    if not rows or [c.strip() for c in rows[0][:3]] != list(_FIXED) or len(rows[0]) < 4:
        raise InputError(Said("cf_csv_form_whose", v=','.join(_FIXED)), file=path, field="row 1")
    cols = rows[0][3:]
    subs: list[dict[str, Any]] = [{"format": 1, "scales": {}, "positions": {}} for _ in cols]
    for r, row in enumerate(rows[1:], 2):
        if not row or not any(c.strip() for c in row):
            continue
        row = row + [""] * (3 + len(cols) - len(row))
        quantity, phi, figure = (c.strip() for c in row[:3])
        for j, cell in enumerate(row[3:3 + len(cols)]):
            cell = cell.strip()
            if not cell:
                continue
            where = f"row {r} ({quantity}), column {cols[j]!r}"
            sub = subs[j]
            if quantity == "scene":
                sub["scene"] = cell
            elif quantity == "student":
                sub["student"] = cell
            elif quantity.startswith("scales."):
                parts = quantity.split(".")
                if len(parts) != 3 or parts[1] not in SCALE_KINDS or parts[2] not in ("mu", "K"):
                    raise InputError(Said("cf_scales_mu_quantity", v='|'.join(SCALE_KINDS), quantity=quantity),
                                     file=path, field=where)
                sub["scales"][parts[1]] = {parts[2]: _number(cell, path, where)}
            else:
                try:
                    p = float(phi)
                except ValueError:
                    raise InputError(Said("cf_crank_angle_degrees", phi=phi), file=path,
                                     field=f"row {r}, phi_deg") from None
                if figure not in ("mm", "value"):
                    raise InputError(Said("cf_mm_value_figure", figure=figure), file=path, field=f"row {r}, figure")
                pos = sub["positions"].setdefault(p, {"phi_deg": p, "measured": {}, "values": {}})
                pos["measured" if figure == "mm" else "values"][quantity] = _number(cell, path, where)
    out = []
    for col, sub in zip(cols, subs, strict=True):
        positions = [p for p in sub["positions"].values() if p["measured"] or p["values"]]
        if not positions:
            continue
        sub["positions"] = positions
        if not sub["scales"]:
            sub.pop("scales")
        sub.setdefault("student", f"column {col}")
        out.append((col, check_from_dict(sub, f"{path}[{col}]")))
    if not out:
        raise InputError(Said("cf_student_figures_any"), file=path)
    return out


def is_scene(data: dict[str, Any]) -> bool:
    """A linkage scene (not a check file) lying in a folder of check files."""
    return data.get("kind", "linkage") == "linkage" and "links" in data and "positions" not in data


# --------------------------------------------------------------------------- command line


def run_template(args: argparse.Namespace) -> int:
    """``plans check --template SCENE``: a blank check file (or CSV form) to fill in."""
    from plans.check.report import error_line
    from plans.kinematics.placing import load_scene

    try:
        scene_path = Path(args.template)
        if args.path:
            raise InputError(Said("cf_template_writes_blank"), file=args.path)
        scene = load_scene(scene_path)
        phis = None
        if args.phi:
            try:
                phis = tuple(float(x) for x in args.phi.split(","))
            except ValueError:
                raise InputError(Said("cf_angles_degrees_separated", phi=args.phi),
                                 field="--phi") from None
            known = scene.driver.phis_deg
            for p in phis:
                if not any(abs(p - q) < SAME_ANGLE_DEG for q in known):
                    raise InputError(Said("cf_position_scene_it", p=p, v=', '.join(f'{q:g}°' for q in known)), file=str(scene_path), field="--phi")
        target = Path(args.output) if args.output else None
        ref = str(scene_path.resolve()) if target is None else scene_reference(scene_path, target)
        if args.form == "csv":
            if not 1 <= args.students <= 500:
                raise InputError(Said("cf_student_columns_students", students=args.students), field="--students")
            text = template_csv(scene, ref, phis, args.students)
        else:
            from plans.errors import run_language

            text = template_toml(scene, ref, phis, run_language())
        return put_form(text, target, scene_path, args.quiet)
    except PlansError as exc:
        from plans.guard import abandon

        abandon()  # nothing of the command is written (it answers 2 itself)
        error_line(one_line(exc))
        return 2


def put_form(text: str, target: Path | None, source: str | Path, quiet: bool) -> int:
    """A blank form to standard output (no target) or to its file, never over the file it
    was made from, into a folder that exists."""
    if target is None:
        sys.stdout.write(text)
        return 0
    refuse_input(str(target), source)
    if not target.parent.is_dir():
        raise OutputError(Said("cf_target_such_folder", target=target, parent=target.parent))
    write_all({target: text})
    if not quiet:
        print(target)
    return 0


def scene_reference(scene: Path, target: Path) -> str:
    """The scene's path as the form beside ``target`` names it."""
    import os

    try:
        return Path(os.path.relpath(scene.resolve(), target.resolve().parent)).as_posix()
    except ValueError:  # another drive
        return str(scene.resolve())


def run_form(target: Path, args: argparse.Namespace) -> int:
    """``plans check FORM.csv``: each filled column one submission, as a folder is checked."""
    from plans.check.report import check, error_line, make_folder, summary_row, table, write_summary

    if args.json:
        error_line(f"{target}: --json is for one check file; a form writes one report per student into --out")
        return 2
    subs = read_form(target)
    out = Path(args.out) if args.out else target.parent / f"{target.stem}-reports"
    files: dict[Path, Any] = {}
    rows = []
    for col, cf in subs:
        report = check(cf)
        stem = f"{target.stem}-{col}"
        files[out / f"{stem}.json"] = dumps(report.to_json())
        files[out / f"{stem}.txt"] = table(report) + "\n"
        rows.append(summary_row(f"{target}[{col}]", report))
        if not args.quiet and args.csv != "-":
            print(table(report))
            print()
    make_folder(out)
    write_all(files)
    write_summary(rows, args, out)
    return 0
