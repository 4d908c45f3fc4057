"""A variant table made into one folder per variant: its file, the answer key, the blank form.

The table (CSV or TOML) has one row per variant; its columns are the ``{placeholders}`` of
a template file (a scene, gears, cam or engine file) standing beside it.  CSV::

    variant,template,l_AB,l_BC,n_1
    01,shaper.template,0.10,0.40,60
    02,gears.template,,,          # a column a template does not name is left empty

``template`` may be left out when one ``*.template`` stands beside the table.
TOML: ``format = 1``, ``kind = "variants"``, ``template = "…"`` and ``[[variants]]``
tables with the same keys.

The answer key ``key.json``: ``{"variant", "kind", "file", "values": {quantity: {φ: value}},
"scales"}`` with the quantities named as the check files name them (SI for a linkage,
the file's unit and degrees for gears and cams; position-free figures at φ = 0) and, for
a linkage, the scales the key's figures are read at.
"""

from __future__ import annotations

import csv
import io
import re
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

from plans.errors import InputError, PlansError, Said, one_line

#: ``{name}``: a placeholder (a TOML inline table has spaces or ``=`` inside its braces).
PLACEHOLDER = re.compile(r"\{([A-Za-z_][A-Za-z0-9_]*)\}")
#: The file a variant's folder holds, by kind.
FILE_NAMES = {"linkage": "scene.toml", "gears": "gears.toml", "cam": "cam.toml", "engine": "engine.toml",
              "synthesis": "synthesis.toml"}
_VARIANT = re.compile(r"^[A-Za-z0-9][A-Za-z0-9_.-]{0,63}$")


@dataclass(frozen=True)
class Row:
    """One variant: its name, the template it fills, its data, where it stands in the table."""

    variant: str
    template: Path
    data: dict[str, str]
    where: str  # "group.csv, row 3"


@dataclass
class Built:
    """A variant made (``error`` empty) or not (``error``: why)."""

    row: Row
    kind: str = ""
    files: dict[str, str] = field(default_factory=dict)  # name in the folder -> text
    key: dict[str, Any] = field(default_factory=dict)
    error: str = ""


def _text(v: Any) -> str:
    if isinstance(v, bool):
        return "true" if v else "false"
    return v if isinstance(v, str) else f"{v!r}" if isinstance(v, float) else str(v)


def read_table(path: str | Path) -> list[Row]:
    """The rows of a variant table (CSV or TOML); a bad table is one InputError line."""
    path = Path(path)
    if not path.is_file():
        raise InputError(Said("gb_such_file"), file=str(path))
    raws: list[tuple[dict[str, str], str]] = []
    default: str | None = None
    if path.suffix.lower() == ".toml":
        from plans.io import read_toml

        data = read_toml(path)
        if data.get("kind") != "variants":
            raise InputError(Said("gb_kind_variants", v=data.get('kind')), file=str(path), field="kind")
        default = data.get("template") if isinstance(data.get("template"), str) else None
        rows = data.get("variants")
        if not isinstance(rows, list) or not rows:
            raise InputError(Said("gb_variants_tables_one"), file=str(path), field="variants")
        for i, r in enumerate(rows):
            if not isinstance(r, dict):
                raise InputError(Said("sm_table"), file=str(path), field=f"variants[{i}]")
            raws.append(({str(k): _text(v) for k, v in r.items()}, f"variants[{i}]"))
    else:
        try:
            text = path.read_text(encoding="utf-8-sig")
        except UnicodeDecodeError:
            raise InputError(Said("gb_utf_csv_file"), file=str(path)) from None
        reader = csv.DictReader(io.StringIO(text))
        if not reader.fieldnames or "variant" not in reader.fieldnames:
            raise InputError(Said("gb_header_row_variant"), file=str(path), field="variant")
        for n, r in enumerate(reader, 2):
            raws.append(({k.strip(): (v or "").strip() for k, v in r.items() if k}, f"row {n}"))
    if default is None:
        beside = sorted(path.parent.glob("*.template"))
        default = beside[0].name if len(beside) == 1 else None
    out: list[Row] = []
    seen: set[str] = set()
    for data, where in raws:
        v = data.pop("variant", "")
        if not _VARIANT.match(v):
            raise InputError(Said("gb_variant_name_letters", v=v),
                             file=str(path), field=f"{where}.variant")
        if v == "handouts":
            raise InputError(Said("gb_handouts_folder_handouts"),
                             file=str(path), field=f"{where}.variant")
        if v in seen:
            raise InputError(Said("gb_variant_given_twice", v=v), file=str(path), field=f"{where}.variant")
        seen.add(v)
        tmpl = data.pop("template", "") or default
        if not tmpl:
            raise InputError(Said("gb_template_column_one"),
                             file=str(path), field=f"{where}.template")
        out.append(Row(v, path.parent / tmpl, data, f"{path.name}, {where}"))
    return out


def read_roster(path: str | Path, variants: set[str]) -> list[dict[str, str]]:
    """The roster: CSV with columns name, group, variant (every variant one of the table's)."""
    path = Path(path)
    if not path.is_file():
        raise InputError(Said("gb_such_file"), file=str(path))
    reader = csv.DictReader(io.StringIO(path.read_text(encoding="utf-8-sig")))
    need = ("name", "group", "variant")
    if not reader.fieldnames or any(c not in reader.fieldnames for c in need):
        raise InputError(Said("gb_columns_name_group"), file=str(path))
    out = []
    for n, r in enumerate(reader, 2):
        st = {c: (r.get(c) or "").strip() for c in need}
        if not st["name"]:
            raise InputError(Said("gb_student_name"), file=str(path), field=f"row {n}.name")
        if st["variant"] not in variants:
            raise InputError(Said("gb_variant_variant_table", v=st['variant']), file=str(path),
                             field=f"row {n}.variant")
        out.append(st)
    return out


def fill(template: str, row: Row) -> str:
    """The template with every ``{placeholder}`` replaced by the row's value as written."""
    missing = sorted({m for m in PLACEHOLDER.findall(template) if m != "variant" and not row.data.get(m)})
    if missing:
        raise InputError(Said("gb_value_template_name", v=', '.join(missing), name=row.template.name),
                         file=row.where)
    return PLACEHOLDER.sub(lambda m: row.variant if m.group(1) == "variant" else row.data[m.group(1)], template)


def build(row: Row, lang: str | None = None) -> Built:
    """Make one variant in memory: its file, key and blank form (their comments in ``lang``,
    None: the run's); a variant that cannot be made (cannot be assembled, a mesh that jams,
    ...) comes back with ``error``."""
    if lang is None:
        from plans.errors import run_language

        lang = run_language()
    out = Built(row)
    try:
        from plans.io import loads_toml
        from plans.kinds import kind_of

        try:
            template = row.template.read_text(encoding="utf-8")
        except OSError as exc:
            raise InputError(Said("gb_cannot_read_template", strerror=exc.strerror), file=str(row.template)) from None
        text = fill(template, row)
        syn: dict[str, float] = {}
        data = loads_toml(text, str(row.template))
        out.kind = kind_of(data, str(row.template))
        name = FILE_NAMES[out.kind]
        # the file is judged where it will stand: its relative paths are the variant folder's
        path = str(row.template.parent / row.variant / name)
        out.files[name] = text
        if out.kind == "synthesis":  # designed into its scene: the scene's figures and the design's
            from plans.group.sheets import synthesis_values

            scene_text, syn = synthesis_values(data, path, lang)
            out.files["scene.toml"] = scene_text
            values, scales = linkage_key(loads_toml(scene_text, path), str(Path(path).with_name("scene.toml")))
            out.files["synthesis.check.toml"] = _synthesis_form(name, syn, row.variant, lang)
            values = {**{q: {"0": v} for q, v in syn.items()}, **values}
        else:
            values, scales = key_values(out.kind, data, path)
        out.key = {"variant": row.variant, "kind": out.kind, "file": name, "values": values}
        if out.kind == "synthesis":
            out.key["scene"] = "scene.toml"
        if scales:
            out.key["scales"] = scales
        if out.kind in ("linkage", "synthesis"):
            scene_values = {q: v for q, v in values.items() if q not in syn}
            out.files["check.toml"] = linkage_form("scene.toml", scene_values, row.variant, "F_bal" in values, lang)
        elif out.kind in ("gears", "cam", "engine"):
            from plans.group.sheets import blank

            out.files["check.toml"] = blank(out.kind, name, values, row.variant, lang)
    except PlansError as exc:
        out.error = one_line(exc)
    except (ValueError, ArithmeticError) as exc:  # a geometry the solvers refuse
        out.error = f"{type(exc).__name__}: {exc}"
    return out


def key_values(kind: str, data: dict[str, Any], path: str
               ) -> tuple[dict[str, dict[str, float]], dict[str, Any]]:
    """The key's values and (a linkage) the scales they are read at."""
    if kind in ("gears", "cam", "engine"):
        from plans.group.sheets import sheet_key

        return sheet_key(kind, data, path), {}
    return linkage_key(data, path)


def _synthesis_form(name: str, values: dict[str, float], variant: str, lang: str) -> str:
    from plans.group.sheets import blank

    return blank("synthesis", name, {q: {"0": v} for q, v in values.items()}, variant, lang)


def linkage_form(scene_ref: str, values: dict[str, dict[str, float]], variant: str, force: bool,
                 lang: str = "en") -> str:
    """The blank check file of a linkage variant: the form ``plans check --template`` writes
    (every figure of the key a value to write, its comments in ``lang``), with the group and the variant."""
    import json

    from plans.phrases import say

    def q(x: str) -> str:
        return json.dumps(x, ensure_ascii=False)

    lines = [say("cf_head", lang),
             "format = 1", 'student = ""', 'group = ""', f"variant = {q(variant)}", f"scene = {q(scene_ref)}", "",
             "[scales]  " + say("cf_scales", lang),
             "length = { mu = 1000 }", 'velocity = { mu = "" }', 'acceleration = { mu = "" }']
    if force:
        lines.append('force = { mu = "" }')
    phis = sorted({float(p) for v in values.values() for p in v})
    for phi in phis:
        lines += ["", "[[positions]]", f"phi_deg = {phi:g}", "", "[positions.values]"]
        lines += [f"{q(n)} = \"\"" for n, v in values.items() if f"{phi:g}" in v]
    return "\n".join(lines) + "\n"


def linkage_key(data: dict[str, Any], path: str) -> tuple[dict[str, dict[str, float]], dict[str, Any]]:
    """Every figure of the scene's sheets at every position, exact, at the nice scales a
    draftsman picks (the ones ``plans check --template`` lists)."""
    from plans.check.checkfile import check_from_dict
    from plans.check.forms import question_names
    from plans.check.providers import Context, exact_value
    from plans.kinematics.construction import default_scales
    from plans.kinematics.exact import solve
    from plans.kinematics.placing import scene_from_dict

    scene = scene_from_dict(data, path)
    kin = solve(scene, order=2)
    mv, ma = default_scales(kin)
    phis = tuple(scene.driver.phis_deg)
    names = question_names(scene, data, phis)  # type: ignore[arg-type]  # an inline scene: not on disk yet
    scales: dict[str, Any] = {"length": {"mu": 1000}, "velocity": {"mu": mv}, "acceleration": {"mu": ma}}
    skeleton = {"format": 1, "scene": data, "scales": scales,
                "positions": [{"phi_deg": p, "values": {f"omega_{scene.driver.link}": 1.0}} for p in phis]}
    ctx = Context(check_from_dict(skeleton, path))
    values: dict[str, dict[str, float]] = {}
    for k, phi in enumerate(phis):
        _, qs = names[phi]
        for q in qs:
            if q == "F_bal_diff_pct":
                continue
            ex = exact_value(ctx, k, q)
            if ex is not None:
                values.setdefault(q, {})[f"{phi:g}"] = float(f"{ex.value:.9g}")
    return values, scales


def scheme(text: str, name: str) -> tuple[dict[str, complex], list[tuple[str, str]], list[tuple[str, str]],
                                          tuple[float, ...]]:
    """A scene at its first position, for the handout's stick drawing: every point (m), the
    links' axes as pairs of points, the joints with the frame (``R`` or ``P``, the point) and
    the positions the student draws (degrees)."""
    from plans.io import loads_toml
    from plans.kinematics.exact import solve
    from plans.kinematics.placing import scene_from_dict

    scene = scene_from_dict(loads_toml(text, name), name)
    kin = solve(scene, order=0)
    pts: dict[str, complex] = {}
    segs: list[tuple[str, str]] = []
    for lid, link in sorted(scene.links.items()):
        for n in dict.fromkeys([*link.axis, *link.points]):
            pts.setdefault(n, complex(kin.point_on(lid, link.points[n])[0][0]))
        if len(link.axis) == 2:
            segs.append((link.axis[0], link.axis[1]))
    for n, z in scene.frame_points.items():
        pts.setdefault(n, complex(z))
    frame = [(j.kind, j.point) for j in scene.joints if scene.frame in j.links and j.point in pts]
    return pts, segs, frame, tuple(float(q) for q in kin.phi_deg)
