"""``plans variants TABLE -o DIR``: a group's variants made from a variant table.

One folder per variant (``DIR/<variant>/``): the variant's file, ``key.json`` (every figure a
student reports, exact), ``check.toml`` (the blank form) and ``reference/`` (the variant's
sheets as PDF, the answer drawn); with a roster, ``DIR/handouts/``: one A4 page per student
(the scheme, the data row, what to hand in) as PDF.  A variant that cannot be made is named
with its row and why; the others are made.  ``--jobs N`` makes them in N processes.
"""

from __future__ import annotations

import argparse
import html
import json
import math
import sys
from pathlib import Path
from typing import Any

from plans.errors import (
    InputError,
    PlansError,
    Said,
    error_prefix,
    field_name,
    one_line,
    run_language,
)
from plans.phrases import say

_TEXT: dict[str, dict[str, Any]] = {
    "ru": {"task": "Задание на курсовой проект по ТММ", "student": "Студент", "group": "Группа",
           "variant": "Вариант", "data": "Исходные данные", "hand": "Сдать",
           "scheme": "Схема механизма (положение φ = {phi}°)",
           "linkage": ["Лист 1: планы положений, скоростей и ускорений в положениях {phis}",
                       "Лист 2: силовой анализ (планы сил, рычаг Жуковского)",
                       "Заполненный бланк check.toml: отрезки планов (мм) и величины (СИ)"],
           "gears": ["Лист: картина зацепления, x, αw, aw, радиусы, εα",
                     "Заполненный бланк check.toml"],
           "cam": ["Лист: закон движения, r0 и e по углу давления, профиль кулачка",
                   "Заполненный бланк check.toml: R, s через 30°, θmax"],
           "engine": ["Лист: уравновешивание, многоугольники сил и моментов, противовесы"],
           "synthesis": ["Лист 1: синтез механизма по K (θ) и заданным условиям; длины звеньев, γmin",
                         "Лист 2: планы положений, скоростей и ускорений в положениях {phis}",
                         "Лист 3: силовой анализ (планы сил, рычаг Жуковского)",
                         "Заполненные бланки synthesis.check.toml и check.toml"]},
    "en": {"task": "TMM course project: the task", "student": "Student", "group": "Group",
           "variant": "Variant", "data": "Data", "hand": "Hand in",
           "scheme": "The mechanism (position φ = {phi}°)",
           "linkage": ["Sheet 1: position, velocity and acceleration plans at {phis}",
                       "Sheet 2: force analysis (force polygons, Zhukovsky lever)",
                       "The check.toml form filled in: plan segments (mm) and values (SI)"],
           "gears": ["Sheet: the meshing, x, α_w, a_w, radii, ε_α", "The check.toml form filled in"],
           "cam": ["Sheet: the motion law, r0 and e from the pressure angle, the cam profile",
                   "The check.toml form filled in: R, s every 30°, θ_max"],
           "engine": ["Sheet: balancing, force and moment polygons, counterweights"],
           "synthesis": ["Sheet 1: the mechanism designed from K (θ) and the given conditions; lengths, γ_min",
                         "Sheet 2: position, velocity and acceleration plans at {phis}",
                         "Sheet 3: force analysis (force polygons, Zhukovsky lever)",
                         "The synthesis.check.toml and check.toml forms filled in"]},
}


def register(sub: argparse._SubParsersAction) -> argparse.ArgumentParser:
    p = sub.add_parser("variants", help="a group's variants from a variant table: files, keys, forms, handouts",
                       description="Make one folder per row of a variant table (CSV or TOML): the variant's "
                                   "file, key.json, check.toml and reference sheets; with a roster, the handouts.")
    p.add_argument("table", help="variant table: CSV or TOML, one row per variant")
    p.add_argument("-o", "--output", required=True, metavar="DIR", help="the group's folder")
    p.add_argument("--students", metavar="ROSTER.csv", help="roster: name, group, variant; writes DIR/handouts/")
    p.add_argument("--jobs", type=int, default=1, metavar="N", help="variants made in N processes (default 1)")
    p.add_argument("--language", choices=("ru", "en"),
                   help="of the handouts, the files' comments and the reference sheets (default: the locale's)")
    p.add_argument("--font", choices=("dejavu", "gost"),
                   help="overrides [sheet] font: gost is osifont, a GOST 2.304 type B font (apt-get install fonts-osifont)")
    p.add_argument("--no-sheets", action="store_true", help="no reference sheets (files, keys, forms only)")
    p.add_argument("--quiet", action="store_true", help="no progress lines")
    p.set_defaults(func=run)
    return p


def make(row: Any, sheets: bool, language: str | None = None, font: str | None = None) -> tuple[Any, dict[str, bytes]]:
    """One variant: built (:func:`plans.group.build.build`) and its reference sheets drawn,
    nothing written: (built, {path in its folder: bytes})."""
    from plans.group.build import build

    got = build(row, language)
    files: dict[str, bytes] = {n: t.encode("utf-8") for n, t in got.files.items()}
    if got.error:
        return got, {}
    files["key.json"] = (json.dumps(got.key, ensure_ascii=False, indent=1, sort_keys=False) + "\n").encode("utf-8")
    if sheets and got.kind:
        try:
            files.update(reference(got, language, font))
        except PlansError as exc:
            got.error = Said("dv_reference_sheets", error=one_line(exc)).text(run_language())
            return got, {}
    return got, files


def reference(got: Any, language: str | None = None, font: str | None = None) -> dict[str, bytes]:
    """The variant's sheets as PDF, drawn from its file read in memory under the path it
    will have in the variant's folder (a warning names that file, the same in every run;
    in ``language``, None: the file's own; in ``font``, None: the file's own)."""
    import importlib

    from drawings.paper.export import render
    from plans.io import loads_toml
    from plans.kinds import KINDS, READERS

    names = [(got.key["file"], got.kind)]
    if "scene" in got.key:  # a synthesis: its construction and its scene's sheets
        names.append((got.key["scene"], "linkage"))
    out: dict[str, bytes] = {}
    for name, kind in names:
        path = str(got.row.template.parent / got.row.variant / name)
        module, function = READERS[kind].split(":")
        source = getattr(importlib.import_module(module), function)(loads_toml(got.files[name], path), path)
        drawing = importlib.import_module(KINDS[kind][1]).draw(source, language=language, font=font)
        rendered = render(drawing.sheets, Path("reference"), Path(name).stem, ["pdf"])
        out.update({str(p): data for p, data in rendered.items()})
    return out


def _make_star(args: tuple[Any, bool, str | None, str | None]) -> tuple[Any, dict[str, bytes]]:
    return make(*args)


def run(args: argparse.Namespace) -> int:
    from plans.group.build import read_roster, read_table
    from plans.io import remove, write_all

    out = Path(args.output)
    table = Path(args.table)
    if out.exists() and not out.is_dir():
        raise InputError(Said("dv_out_file_folder", out=out), file=str(table),
                         field="--output")
    if out.resolve() == table.resolve().parent:
        raise InputError(Said("dv_output_folder_table"),
                         file=str(table), field="--output")
    if not 1 <= args.jobs <= 64:
        raise InputError(Said("gg_jobs_jobs", jobs=args.jobs), file=str(table), field="--jobs")
    rows = read_table(table)
    roster = read_roster(args.students, {r.variant for r in rows}) if args.students else []
    font = getattr(args, "font", None)
    if font:
        from drawings.paper.fonts import require

        require(font, str(table), "--font")  # before any variant is made
    lang = args.language or run_language()  # one language for every variant, its files and sheets
    work = [(r, not args.no_sheets, lang, font) for r in rows]
    if args.jobs > 1 and len(rows) > 1:
        from concurrent.futures import ProcessPoolExecutor

        with ProcessPoolExecutor(max_workers=args.jobs) as pool:
            results = list(pool.map(_make_star, work, chunksize=1))
    else:
        results = [make(*w) for w in work]
    bad = 0
    made = {}
    for got, files in results:
        if got.error:
            bad += 1
            print(error_prefix(lang) + Said("dv_variant_error", variant=got.row.variant, where=field_name(got.row.where, lang),
                                            error=got.error).text(lang), file=sys.stderr)
            continue
        folder = out / got.row.variant
        (folder / "reference").mkdir(parents=True, exist_ok=True)
        written = set(write_all({folder / n: data for n, data in sorted(files.items())}))
        # a sheet of an earlier run that the new set lacks
        remove(old for old in (folder / "reference").glob("*.pdf") if old not in written)
        made[got.row.variant] = got
        if not args.quiet:
            from plans.group.gradebook import heading

            print(say("vr_made", lang, folder=folder, kind=heading(got.kind, lang),
                      n=sum(len(v) for v in got.key["values"].values())))
    if roster:
        hand = out / "handouts"
        hand.mkdir(parents=True, exist_ok=True)
        pages = {}
        for st in roster:
            got = made.get(st["variant"])
            if got is None:
                continue
            stem = _stem(st)
            pages[hand / f"{stem}.pdf"] = handout_pdf(st, got, lang, font or "dejavu")
        write_all(pages)
        if not args.quiet:
            print(say("vr_handouts", lang, folder=hand, n=len(pages)))
    return 2 if bad else 0


def _stem(st: dict[str, str]) -> str:
    import re

    raw = f"{st['group']}_{st['name']}_{st['variant']}"
    return re.sub(r"[^\w.-]+", "_", raw, flags=re.UNICODE).strip("_") or "student"


# --------------------------------------------------------------------------- the handout


def handout_svg(st: dict[str, str], got: Any, lang: str, font: str = "dejavu") -> str:
    """One A4 page: who, which variant, the scheme (a linkage), the data row, what to hand in;
    its words in ``font`` ("gost": osifont, DejaVu Sans where osifont lacks a letter)."""
    from drawings.paper.fonts import FONT_FAMILY, pieces

    t = _TEXT[lang]
    w, h = 210.0, 297.0
    out = [f'<svg xmlns="http://www.w3.org/2000/svg" width="{w}mm" height="{h}mm" viewBox="0 0 {w:g} {h:g}" '
           'font-family="DejaVu Sans, sans-serif">',
           f'<rect x="0" y="0" width="{w:g}" height="{h:g}" fill="white"/>',
           f'<rect x="10" y="10" width="{w - 20:g}" height="{h - 20:g}" fill="none" stroke="black" stroke-width="0.5"/>']

    def text(x: float, y: float, s: str, size: float = 4.0, bold: bool = False) -> None:
        weight = ' font-weight="bold"' if bold else ""
        runs = "".join(f'<tspan font-family="{fam or FONT_FAMILY}">{html.escape(p)}</tspan>' if font != "dejavu"
                       else html.escape(p) for p, fam in pieces(s, font))
        out.append(f'<text x="{x:.2f}" y="{y:.2f}" font-size="{size:g}"{weight}>{runs}</text>')

    text(18, 24, t["task"], 6.0, True)
    text(18, 34, f"{t['student']}: {st['name']}", 4.5)
    text(18, 41, f"{t['group']}: {st['group']}    {t['variant']}: {got.row.variant}", 4.5)
    y = 52.0
    phis = ""
    if got.kind == "synthesis":  # the design is the student's to find: no scheme, the positions only
        phis = ", ".join(f"{float(q):g}°" for q in _scene_phis(got))
    if got.kind == "linkage":
        scheme, phi, phis = _scheme(got)
        text(18, y, t["scheme"].format(phi=f"{phi:g}"), 4.0, True)
        out.append(f'<g transform="translate(20,{y + 8:g})">{scheme}</g>')
        y += 100
    elif got.kind in ("gears", "cam"):
        out.append(f'<g transform="translate(20,{y + 2:g})">{_sketch(got)}</g>')
        y += 80
    text(18, y, t["data"], 4.5, True)
    y += 7
    rows = [(k, v) for k, v in got.row.data.items() if v]
    for i, (k, v) in enumerate(rows):
        x = 18 + (i % 2) * 90
        if i % 2 == 0 and i:
            y += 6
        text(x, y, f"{k} = {v}", 4.0)
    y += 12
    text(18, y, t["hand"], 4.5, True)
    for line in t.get(got.kind, []):
        y += 7
        text(22, y, "— " + line.format(phis=phis), 3.8)
    out.append("</svg>")
    return "\n".join(out)


def _scene_phis(got: Any) -> tuple[float, ...]:
    from plans.io import loads_toml
    from plans.kinematics.placing import scene_from_dict

    name = got.key.get("scene", got.key["file"])
    return tuple(scene_from_dict(loads_toml(got.files[name], name), name).driver.phis_deg)


def _scheme(got: Any) -> tuple[str, float, str]:
    """The mechanism at its first position as a stick drawing fitted in 170 × 90 mm."""
    from plans.group.build import scheme

    name = got.key.get("scene", got.key["file"])
    pts, segs, frame_joints, phis_deg = scheme(got.files[name], name)
    xs = [z.real for z in pts.values()]
    ys = [z.imag for z in pts.values()]
    span = max(max(xs) - min(xs), max(ys) - min(ys) * 1.0, 1e-9)
    k = min(170 / max(max(xs) - min(xs), 1e-9), 78 / max(max(ys) - min(ys), 1e-9), 170 / span)  # supports below

    def p(z: complex) -> tuple[float, float]:
        return (z.real - min(xs)) * k, (max(ys) - z.imag) * k

    body = []
    for a, b in segs:
        (x1, y1), (x2, y2) = p(pts[a]), p(pts[b])
        body.append(f'<line x1="{x1:.2f}" y1="{y1:.2f}" x2="{x2:.2f}" y2="{y2:.2f}" stroke="black" stroke-width="0.7"/>')
    for kind, point in frame_joints:  # the frame: a hatched support under a pivot, a block on a guide
        x, y = p(pts[point])
        if kind == "R":
            body.append(f'<path d="M{x:.2f},{y:.2f} l-3,5 h6 z" fill="none" stroke="black" stroke-width="0.4"/>'
                        f'<line x1="{x - 5:.2f}" y1="{y + 5:.2f}" x2="{x + 5:.2f}" y2="{y + 5:.2f}" '
                        'stroke="black" stroke-width="0.5"/>'
                        + "".join(f'<line x1="{x - 4 + 2 * i:.2f}" y1="{y + 5:.2f}" x2="{x - 5 + 2 * i:.2f}" '
                                  f'y2="{y + 6.5:.2f}" stroke="black" stroke-width="0.3"/>' for i in range(5)))
        else:
            body.append(f'<rect x="{x - 4:.2f}" y="{y - 2.5:.2f}" width="8" height="5" fill="white" '
                        'stroke="black" stroke-width="0.5"/>'
                        f'<line x1="{x - 12:.2f}" y1="{y + 2.5:.2f}" x2="{x + 12:.2f}" y2="{y + 2.5:.2f}" '
                        'stroke="black" stroke-width="0.5"/>')
    for n, z in sorted(pts.items()):
        x, y = p(z)
        body.append(f'<circle cx="{x:.2f}" cy="{y:.2f}" r="1.2" fill="white" stroke="black" stroke-width="0.4"/>')
        body.append(f'<text x="{x + 1.8:.2f}" y="{y - 1.5:.2f}" font-size="3.5">{html.escape(n)}</text>')
    phi = float(phis_deg[0])
    phis = ", ".join(f"{float(q):g}°" for q in phis_deg)
    return "".join(body), phi if math.isfinite(phi) else 0.0, phis


def _sketch(got: Any) -> str:
    """A gear pair as its pitch circles, a cam as its base circle and a roller follower:
    what the task is about, not its answer (nothing measured off it)."""
    line = 'stroke="black" stroke-width="0.5" fill="none"'
    if got.kind == "gears":
        z1, z2 = (float(got.row.data.get(k) or n) for k, n in (("z1", 12), ("z2", 30)))
        k = min(160.0 / (z1 + z2), 60.0 / max(z1, z2)) / 2  # both circles within 160 × 60 mm
        r1, r2 = z1 * k, z2 * k
        cx = 85 - (r1 + r2)
        return (f'<circle cx="{cx + r1:.2f}" cy="35" r="{r1:.2f}" {line}/>'
                f'<circle cx="{cx + 2 * r1 + r2:.2f}" cy="35" r="{r2:.2f}" {line}/>'
                f'<circle cx="{cx + r1:.2f}" cy="35" r="0.8"/><circle cx="{cx + 2 * r1 + r2:.2f}" cy="35" r="0.8"/>'
                f'<text x="{cx + r1 - 2:.2f}" y="{31 - r1:.2f}" font-size="3.5">z1</text>'
                f'<text x="{cx + 2 * r1 + r2 - 2:.2f}" y="{31 - r2:.2f}" font-size="3.5">z2</text>')
    return (f'<circle cx="85" cy="45" r="25" {line}/><circle cx="85" cy="45" r="0.8"/>'
            f'<circle cx="85" cy="16" r="4" {line}/><line x1="85" y1="12" x2="85" y2="-2" {line}/>'
            '<text x="90" y="47" font-size="3.5">r0</text><line x1="85" y1="45" x2="85" y2="20" '
            'stroke="black" stroke-width="0.3" stroke-dasharray="1,1"/>')


def handout_pdf(st: dict[str, str], got: Any, lang: str, font: str = "dejavu") -> bytes:
    from drawings.paper.export import pdf_bytes

    return pdf_bytes(handout_svg(st, got, lang, font).encode("utf-8"), title=f"{st['name']}, {got.row.variant}")
