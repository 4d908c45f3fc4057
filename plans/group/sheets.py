"""The gears and cam sheets: their answer keys and their check files judged.

A check file of a gears or cam sheet is the linkage check file's shape with the file it
checks named instead of a scene::

    format = 1
    student = "Ivanov I. I."
    group = "MT-31"
    variant = "07"
    gears = "gears.toml"            # or cam = "cam.toml" (relative to this file)
    [scales]
    length = { mu = 2 }             # mm on the student's drawing per mm of the gear (2:1)
    [[positions]]
    phi_deg = 0                     # quantities of no position stand at 0
    [positions.values]
    x_1 = 0.294
    a_w_12 = 106.3

Gears (per mesh ``12`` of gears ``1`` and ``2``): ``x_1``, ``alpha_w_12`` (degrees),
``a_w_12``, ``eps_12``; per gear ``r_1`` (pitch), ``r_b1``, ``r_a1``, ``r_f1``, ``r_w1``
(file units).  Cam: ``r0``, ``e`` (offset), ``theta_rise``, ``theta_return`` (the largest
pressure angles, degrees), ``r0_min`` at φ = 0; ``R`` (theoretical profile radius),
``R_a`` (actual profile) and ``s`` (displacement) at the cam angles of the key.

What a drawing is behind (radii, a_w, ε measured off the meshing; the profile radii, the
displacements, r0 and e off the cam drawing) is judged with the draftsman's tolerance:
±``segment_mm`` on the student's drawing (ε: both ends of the active line over the base
pitch; a pressure angle: ±2·``direction_deg``); what is computed (x, α_w) by the course
rule, ±``rule_pct`` % with a floor.  The causes: a wrong shift coefficient
(``shift_coefficient``: the pair re-solved with the student's x explains the rest), a
wrong base radius (``base_radius``: the cam re-solved with the student's r0), a drawing
read at the wrong scale (``scale``: one factor over the drawn figures).
"""

from __future__ import annotations

import math
import re
from dataclasses import dataclass, field, replace
from pathlib import Path
from statistics import median
from typing import Any

from plans.check import wording as wd
from plans.errors import InputError, Said
from plans.tolerances import VERDICT_REL
from plans.units import DUST

#: Angles of the cam at which the key gives the profile (degrees).
CAM_ANGLES = tuple(float(a) for a in range(0, 360, 30))
#: Deductions of the sheet causes (points out of ``full``), beside the examiner's RUBRIC.
SHEET_RUBRIC = {"full": 100.0, "shift_coefficient": 10.0, "base_radius": 10.0, "scale": 10.0,
                "arithmetic": 3.0, "unexplained": 2.0}
#: Floors of the course rule where the exact value may be near zero.
_FLOOR = {"x": 0.01, "alpha_w": 0.1, "theta": 0.5, "e": 0.5, "K": 0.01}


def _pair(a: str, b: str) -> str:
    return f"{a}{b}" if len(a) == 1 and len(b) == 1 else f"{a}_{b}"


# --------------------------------------------------------------------------- keys


def gears_values(data: dict[str, Any], path: str) -> tuple[dict[str, float], dict[str, str]]:
    """Every figure of a gears sheet at position 0, and how each is judged
    (``drawn`` | ``ratio`` | ``rule``)."""
    from plans.gears.model import parse_gears
    from plans.gears.solution import solve_file

    gf = parse_gears(data, path)
    sol = solve_file(gf).solution
    k = gf.to_unit
    vals: dict[str, float] = {}
    how: dict[str, str] = {}
    for n in gf.gears:
        vals[f"x_{n}"] = float(sol.x[n])
        how[f"x_{n}"] = "rule"
    for p in sol.pairs:
        tag = _pair(*p.gears)
        vals[f"alpha_w_{tag}"] = math.degrees(p.alpha_w)
        how[f"alpha_w_{tag}"] = "rule"
        vals[f"a_w_{tag}"] = p.a_w * k
        how[f"a_w_{tag}"] = "drawn"
        vals[f"eps_{tag}"] = float(p.contact_ratio)
        how[f"eps_{tag}"] = f"ratio:{p.p_b * k}"
        for w in p.wheels:
            for q, v in ((f"r_{w.name}", w.pitch), (f"r_b{w.name}", w.base), (f"r_a{w.name}", w.tip),
                         (f"r_f{w.name}", w.root), (f"r_w{w.name}", w.working)):
                if q not in vals:
                    vals[q] = v * k
                    how[q] = "drawn"
    return vals, how


def cam_values(data: dict[str, Any], path: str, r0: float | None = None, e: float | None = None
               ) -> dict[tuple[str, float], float]:
    """Every figure of a cam sheet: (quantity, φ) -> value in the file's unit, degrees.
    ``r0``, ``e``: the cam re-made with this base radius, offset (file units)."""
    import numpy as np

    from plans.cams.model import cam_from_dict
    from plans.cams.solution import solve_cam

    cam = cam_from_dict(data, path)
    L = cam.scale
    if r0 is not None:
        cam = replace(cam, base_radius=r0 * L)
    if e is not None and cam.follower == "translating":
        cam = replace(cam, offset=e * L)
    out: dict[tuple[str, float], float] = {(("r0"), 0.0): cam.base_radius / L}
    if cam.follower == "translating":
        out[("e", 0.0)] = cam.offset / L
    sol = solve_cam(cam)
    fi = sol.findings
    out[("theta_rise", 0.0)] = math.degrees(fi.max_pressure_rise)
    out[("theta_return", 0.0)] = math.degrees(fi.max_pressure_return)
    got = sol.base_radius.min_base_radius
    if got is not None and r0 is None:
        out[("r0_min", 0.0)] = got / L
    pr = sol.profile_at(np.radians(np.array(CAM_ANGLES)))
    lift = (180 / math.pi) if cam.follower == "oscillating" else 1 / L
    for i, phi in enumerate(CAM_ANGLES):
        out[("R", phi)] = float(np.hypot(*pr.theoretical[i])) / L
        if cam.roller > 0:
            out[("R_a", phi)] = float(np.hypot(*pr.actual[i])) / L
        out[("s", phi)] = float(pr.motion.s[i]) * lift
    return out


#: The orders of a balancing sheet, as the quantities name them.
_ORDERS = {"rotating": "rot", "first_order": "I", "second_order": "II"}


def engine_values(data: dict[str, Any], path: str) -> dict[str, float]:
    """An engine's balancing figures: the force and moment polygons' resultants
    (``F_I``, ``M_II``, ``F_rot``: dimensionless, the closing side of the polygon of unit
    vectors, and ``F_I_amp`` in N, ``M_I_amp`` in N·m), and each counterweight's
    mass-radius product ``mr_cw1`` (kg·m) and angle ``angle_cw1`` (degrees)."""
    from plans.balancing.engine import engine_from_dict
    from plans.balancing.solution import solve_engine

    got = solve_engine(engine_from_dict(data, path)).balance.to_json()
    out: dict[str, float] = {}
    for what, letter in (("forces", "F"), ("moments", "M")):
        for order, tag in _ORDERS.items():
            r = got.get(what, {}).get(order)
            if r is not None:
                out[f"{letter}_{tag}"] = float(r["dimensionless"])
                out[f"{letter}_{tag}_amp"] = float(r["amplitude"])
    for i, cw in enumerate(got.get("counterweights") or [], 1):
        out[f"mr_cw{i}"] = float(cw["mass_radius"])
        out[f"angle_cw{i}"] = float(cw["angle_deg"]) % 360.0
    return out


def _engine_how(q: str) -> str:
    if q.startswith("angle_"):
        return "angle"
    if q.endswith("_amp") or q.startswith("mr_"):
        return "rule"
    return "drawn"


def synthesis_values(data: dict[str, Any], path: str, lang: str = "en") -> tuple[str, dict[str, float]]:
    """A synthesis task designed: the scene's text (its heading in ``lang``) and the design's figures (lengths
    ``l_<name>`` in the file's unit, ``theta`` in degrees, ``K``, the stroke ``H`` or the
    swing ``psi`` in degrees, ``gamma_min`` in degrees, as measured back on the design)."""
    from plans.synthesis.cli import check_scene, results
    from plans.synthesis.model import task_from_dict
    from plans.synthesis.scene import scene_text
    from plans.synthesis.solution import solve_task

    d = solve_task(task_from_dict(data, path)).design
    text = scene_text(d, lang)
    check_scene(text, path)
    res = results(d, "scene.toml")
    out = {f"l_{k}": float(v) for k, v in res["lengths"].items() if v}
    out["K"] = float(res["K_measured"])
    out["theta"] = 180.0 * (out["K"] - 1) / (out["K"] + 1)
    if "stroke_measured" in res:
        out["H"] = float(res["stroke_measured"])
    if "swing_measured_deg" in res:
        out["psi"] = float(res["swing_measured_deg"])
    out["gamma_min"] = float(res["gamma_min_deg"])
    return text, out


def _synthesis_how(q: str) -> str:
    if q in ("theta", "psi", "gamma_min"):
        return "angle"
    if q == "K":
        return "rule"
    return "drawn"


def _cam_how(q: str, osc: bool) -> str:
    if q in ("theta_rise", "theta_return"):
        return "angle"
    if q == "s" and osc:
        return "angle"
    return "drawn"


def sheet_key(kind: str, data: dict[str, Any], path: str) -> dict[str, dict[str, float]]:
    """The key's values of a gears or cam file: {quantity: {φ: value}}."""
    out: dict[str, dict[str, float]] = {}
    if kind in ("gears", "engine"):
        vals = gears_values(data, path)[0] if kind == "gears" else engine_values(data, path)
        for q, v in vals.items():
            out[q] = {"0": _round(v)}
    else:
        for (q, phi), v in cam_values(data, path).items():
            out.setdefault(q, {})[f"{phi:g}"] = _round(v)
    return out


def _round(v: float) -> float:
    return float(f"{v:.9g}")


def blank(kind: str, file_ref: str, key: dict[str, dict[str, float]], variant: str, lang: str = "en") -> str:
    """The blank check file of a gears or cam sheet (the form ``plans check --template`` writes),
    its comments in ``lang``."""
    import json

    from plans.phrases import say

    def q(x: str) -> str:
        return json.dumps(x, ensure_ascii=False)

    lines = [say("cf_head_sheet", lang),
             "format = 1", 'student = ""', 'group = ""', f"variant = {q(variant)}", f"{kind} = {q(file_ref)}", ""]
    if kind == "engine":
        lines += ["[scales]  " + say("cf_scales_polygons", lang), "length = { mu = 50 }"]
    else:
        lines += ["[scales]  " + say("cf_scales_drawing", lang), "length = { mu = 1 }"]
    phis = sorted({float(p) for vals in key.values() for p in vals})
    for phi in phis:
        lines += ["", "[[positions]]", f"phi_deg = {phi:g}", "", "[positions.values]"]
        lines += [f"{q(name)} = \"\"" for name, vals in key.items() if f"{phi:g}" in vals]
    return "\n".join(lines) + "\n"


# --------------------------------------------------------------------------- checking


@dataclass(frozen=True)
class SheetItem:
    quantity: str
    phi_deg: float
    student: float
    exact: float
    tolerance: float
    how: str

    @property
    def verdict(self) -> str:
        return "pass" if abs(self.student - self.exact) <= self.tolerance * (1 + VERDICT_REL) else "fail"


@dataclass(frozen=True)
class SheetCause:
    kind: str
    positions: tuple[float, ...]
    explains: tuple[str, ...]
    detail: str  # in English; ``words`` writes it in either language
    deduction: float
    words: Any = field(default=None, repr=False, compare=False)

    def text(self, lang: str = "en") -> str:
        return self.words.render(lang) if self.words is not None and lang == "ru" else self.detail

    def to_json(self, lang: str = "en") -> dict[str, Any]:
        return {"kind": self.kind, "positions": list(self.positions), "explains": list(self.explains),
                "detail": self.text(lang), "deduction": self.deduction}


@dataclass(frozen=True)
class SheetReport:
    """A gears or cam sheet checked: the shape :mod:`plans.group.gradebook` reads."""

    path: str
    sheet: str  # "gears" | "cam"
    student: str
    group: str
    variant: str
    items: tuple[SheetItem, ...]
    causes: tuple[SheetCause, ...]
    unexplained: tuple[SheetItem, ...]
    mark: float
    full: float
    extra: dict[str, Any] = field(default_factory=dict)

    def to_json(self, lang: str = "en") -> dict[str, Any]:
        return {"format": 1, "student": self.student, "group": self.group, "variant": self.variant,
                "sheet": self.sheet, "check_file": self.path,
                "causes": [c.to_json(lang) for c in self.causes],
                "unexplained": list(dict.fromkeys(i.quantity for i in self.unexplained)),
                "mark": self.mark, "full": self.full,
                "items": [{"quantity": i.quantity, "phi_deg": i.phi_deg, "student": i.student, "exact": i.exact,
                           "tolerance": i.tolerance, "verdict": i.verdict} for i in self.items]}


def is_sheet_check(data: dict[str, Any]) -> str | None:
    """``gears``, ``cam`` or ``synthesis`` when the table is a check file of such a sheet."""
    if "positions" in data and "student" in data:
        for kind in ("gears", "cam", "synthesis", "engine"):
            if isinstance(data.get(kind), str):
                return kind
    return None


_TOP = {"format", "student", "group", "variant", "gears", "cam", "synthesis", "engine", "scales", "tolerance", "positions", "title",
        "rubric"}


def _number(v: Any, path: str, where: str) -> float | None:
    if v == "":
        return None
    if isinstance(v, bool) or not isinstance(v, int | float) or not math.isfinite(v):
        raise InputError(Said("gs_number_written", v=v), file=path, field=where)
    return float(v)


def check_sheet(data: dict[str, Any], path: str) -> SheetReport:
    """Judge a gears or cam check file against the exact figures of the file it names."""
    from plans.io import read_toml
    from plans.reader import check_keys

    kind = is_sheet_check(data)
    if kind is None:
        raise InputError(Said("gs_check_file_naming"), file=path)
    check_keys(data, _TOP, file=path, where="")
    src = Path(path).parent / data[kind]
    part = read_toml(src)
    mu = 50.0 if kind == "engine" else 1.0  # a polygon's unit vector drawn 50 mm long
    scales = data.get("scales", {})
    if isinstance(scales, dict) and isinstance(scales.get("length"), dict):
        got = _number(scales["length"].get("mu", 1), path, "scales.length.mu")
        mu = got if got and got > 0 else 1.0
    tol = data.get("tolerance", {}) if isinstance(data.get("tolerance", {}), dict) else {}
    seg_mm = float(tol.get("segment_mm", 0.5))
    dir_deg = float(tol.get("direction_deg", 0.5))
    rule = float(tol.get("rule_pct", 5.0)) / 100
    rubric = {**SHEET_RUBRIC, **{k: float(v) for k, v in (data.get("rubric") or {}).items()}}
    written: dict[tuple[str, float], float] = {}
    for i, pos in enumerate(data.get("positions") or []):
        phi = _number(pos.get("phi_deg"), path, f"positions[{i}].phi_deg")
        for q, v in (pos.get("values") or {}).items():
            got = _number(v, path, f"positions[{i}].values.{q}")
            if got is not None and phi is not None:
                written[(q, phi)] = got
    if kind == "gears":
        vals, how = gears_values(part, str(src))
        exact = {(q, 0.0): v for q, v in vals.items()}
        hows = {(q, 0.0): h for q, h in how.items()}
    elif kind == "engine":
        exact = {(q, 0.0): v for q, v in engine_values(part, str(src)).items()}
        hows = {key: _engine_how(key[0]) for key in exact}
    elif kind == "synthesis":
        exact = {(q, 0.0): v for q, v in synthesis_values(part, str(src))[1].items()}
        hows = {key: _synthesis_how(key[0]) for key in exact}
    else:
        exact = cam_values(part, str(src))
        osc = part.get("follower") == "oscillating"
        hows = {key: _cam_how(key[0], osc) for key in exact}

    def tolerance(key: tuple[str, float], value: float) -> float:
        h = hows[key]
        base = re.sub(r"_?\d.*$", "", key[0])
        floor = _FLOOR.get(base, 0.0)
        if h == "drawn":
            return max(seg_mm / mu, floor)
        if h == "angle":
            return max(2 * dir_deg, rule * abs(value), floor)
        if h.startswith("ratio:"):
            return 2 * seg_mm / mu / float(h.split(":", 1)[1])
        return max(rule * abs(value), floor, DUST * big)

    big = max((abs(v) for v in exact.values()), default=0.0)  # a balanced order's 0 is 0 to rounding
    items = []
    for key, s in written.items():
        if key not in exact:
            raise InputError(Said("gs_figure_this_kind", v=key[0], v2=key[1], kind=kind, v3=', '.join(sorted({q for q, _ in exact}))), file=path,
                             field="positions")
        if key[0].startswith("angle_"):  # a direction: 359.9° is 0.1° from 0°
            s = exact[key] + ((s - exact[key] + 180.0) % 360.0 - 180.0)
        items.append(SheetItem(key[0], key[1], s, exact[key], tolerance(key, exact[key]), hows[key]))
    items.sort(key=lambda it: (it.phi_deg, it.quantity))
    causes, left = _diagnose(kind, part, str(src), items, written, tolerance, rubric)
    full = rubric["full"]
    mark = max(0.0, full - sum(c.deduction for c in causes) - rubric["unexplained"] * len(left))
    return SheetReport(path, kind, str(data.get("student", "")), str(data.get("group", "")),
                       str(data.get("variant", "")), tuple(items), tuple(causes), tuple(left), mark, full)


def _diagnose(kind: str, part: dict[str, Any], src: str, items: list[SheetItem],
              written: dict[tuple[str, float], float], tolerance: Any, rubric: dict[str, float]
              ) -> tuple[list[SheetCause], list[SheetItem]]:
    """The smallest set of causes that explains the failures, greedily (the examiner's way):
    each model a sheet of predicted figures; it explains a failing figure it predicts within
    the figure's tolerance and must not move a passing one out of it."""
    failing = [it for it in items if it.verdict == "fail"]
    models: list[tuple[str, wd.Words, dict[tuple[str, float], float]]] = []
    if failing and kind == "gears":
        xs = {q[0][2:]: v for q, v in written.items() if q[0].startswith("x_")}
        if any(it.quantity.startswith("x_") for it in failing):
            data = {**part, "gears": [{**g, "x": xs.get(str(g.get("name")), g.get("x", 0))}
                                      for g in part.get("gears", [])]}
            try:
                vals, _ = gears_values(data, src)
                models.append(("shift_coefficient", wd.say("sc_shift", xs=(", ", [
                    wd.say("use", q=f"x_{n}", w=wd.n(v, "g")) for n, v in sorted(xs.items())])),
                               {(q, 0.0): v for q, v in vals.items()}))
            except Exception:  # noqa: BLE001 - a shift the pair cannot take: no model
                pass
    if failing and kind == "cam":
        r0 = written.get(("r0", 0.0))
        e = written.get(("e", 0.0))
        if any(it.quantity in ("r0", "e") for it in failing):
            try:
                models.append(("base_radius", wd.say("sc_base", r0=wd.n(r0 or 0.0, "g"),
                                                     e=wd.say("sc_offset", e=wd.n(e, "g")) if e is not None else ""),
                               cam_values(part, src, r0, e)))
            except Exception:  # noqa: BLE001 - no cam on such a base circle: no model
                pass
    drawn = [it for it in failing if it.how == "drawn" and it.exact != 0]
    if len(drawn) >= 2:
        f = median(it.student / it.exact for it in drawn)
        models.append(("scale", wd.say("sc_scale", f=wd.n(f, ".4g")),
                       {(it.quantity, it.phi_deg): it.exact * f for it in items if it.how == "drawn"}))
    causes: list[SheetCause] = []
    left = list(failing)
    while left and models:
        best = None
        for kind_, detail, pred in models:
            expl = [it for it in left if (it.quantity, it.phi_deg) in pred
                    and abs(it.student - pred[(it.quantity, it.phi_deg)]) <= it.tolerance]
            moved = [it for it in items if it.verdict == "pass" and (it.quantity, it.phi_deg) in pred
                     and abs(it.student - pred[(it.quantity, it.phi_deg)]) > it.tolerance]
            need = 2 if kind_ == "scale" else 1
            if len(expl) >= need and len(expl) > len(moved) and (best is None or len(expl) > len(best[3])):
                best = (kind_, detail, pred, expl)
        if best is None:
            break
        kind_, detail, _, expl = best
        causes.append(SheetCause(kind_, tuple(sorted({it.phi_deg for it in expl})),
                                 tuple(dict.fromkeys(it.quantity for it in expl)), detail.render("en"),
                                 rubric.get(kind_, 10.0), detail))
        left = [it for it in left if it not in expl]
        models = [m for m in models if m[0] != kind_]
    if kind == "gears" and left:  # a figure that does not follow from the student's own figures
        own = _gears_own(part, written, items)
        for it in list(left):
            if it.quantity in own:
                said = wd.say("sc_own", q=it.quantity, s=wd.n(it.student, "g"), v=wd.n(own[it.quantity], ".5g"))
                causes.append(SheetCause("arithmetic", (it.phi_deg,), (it.quantity,), said.render("en"),
                                         rubric.get("arithmetic", 3.0), said))
                left.remove(it)
    return causes, left


def _gears_own(part: dict[str, Any], written: dict[tuple[str, float], float], items: list[SheetItem]
               ) -> dict[str, float]:
    """What the student's own passing figures give (external pairs of one module): r = m z/2,
    r_b = r cos α, and from the student's α_w: a_w = a cos α / cos α_w, r_w = r cos α / cos α_w."""
    ok = {it.quantity for it in items if it.verdict == "pass"}
    try:
        m = float(part["module"])
        alpha = math.radians(float(part.get("pressure_angle_deg", 20)))
        z = {str(g["name"]): int(g["z"]) for g in part["gears"] if not g.get("internal")}
    except (KeyError, TypeError, ValueError):
        return {}
    out: dict[str, float] = {}
    for n, zn in z.items():
        out[f"r_{n}"] = m * zn / 2
        out[f"r_b{n}"] = m * zn / 2 * math.cos(alpha)
    for a_ in z:
        for b_ in z:
            tag = _pair(a_, b_)
            aw = written.get((f"alpha_w_{tag}", 0.0))
            if a_ == b_ or aw is None or f"alpha_w_{tag}" not in ok or not 0 < aw < 89:
                continue
            k = math.cos(alpha) / math.cos(math.radians(aw))
            out[f"a_w_{tag}"] = m * (z[a_] + z[b_]) / 2 * k
            out.setdefault(f"r_w{a_}", m * z[a_] / 2 * k)
            out.setdefault(f"r_w{b_}", m * z[b_] / 2 * k)
    return out


def sheet_check_of(path: str | Path) -> SheetReport | None:
    """The report of a gears or cam check file; None: the file is another kind."""
    from plans.io import read_toml

    try:
        text = Path(path).read_text(encoding="utf-8", errors="replace")
        if not any(k in text for k in ("gears", "cam", "synthesis", "engine")):
            return None
    except OSError:
        return None
    data = read_toml(path)
    return check_sheet(data, str(path)) if is_sheet_check(data) else None


def table(rep: SheetReport, lang: str = "en") -> str:
    """The report on the terminal: the mark, the causes, what no cause explains, every figure."""
    from plans.check.report import decimal, kind_word, say_line
    from plans.language import CHECK_TERMS

    def g(x: float, spec: str = "g") -> str:
        return decimal(format(x, spec), lang)

    sheet = say_line(f"sc_{rep.sheet}", lang) if f"sc_{rep.sheet}" in CHECK_TERMS else rep.sheet
    lines = [say_line("sc_head", lang, student=rep.student or Path(rep.path).stem, sheet=sheet)
             + (say_line("sc_variant", lang, v=rep.variant) if rep.variant else ""),
             say_line("ch_mark", lang, mark=say_line("ch_of", lang, mark=g(rep.mark), full=g(rep.full)))]
    if rep.causes:
        lines.append(say_line("sc_mistakes", lang))
        for n, c in enumerate(rep.causes, 1):
            lines.append(say_line("sc_mistake", lang, n=n, kind=kind_word(c.kind, lang), detail=c.text(lang),
                              names=", ".join(c.explains), d=g(c.deduction)))
    else:
        lines.append(say_line("sc_none", lang) if not rep.unexplained else say_line("sc_none_explains", lang))
    if rep.unexplained:
        lines.append(say_line("sc_unexplained", lang, names=", ".join(i.quantity for i in rep.unexplained)))
    w = {k: say_line(k, lang) for k in ("ch_quantity", "ch_phi", "ch_student", "ch_exact", "ch_verdict")}
    lines.append(f"{w['ch_quantity']:<14}{w['ch_phi']:>6}{w['ch_student']:>13}{w['ch_exact']:>13}{'±':>10}  "
                 f"{w['ch_verdict']}")
    for it in rep.items:
        verdict = say_line("ch_pass" if it.verdict == "pass" else "ch_fail", lang) if lang == "ru" else it.verdict
        lines.append(f"{it.quantity:<14}{g(it.phi_deg):>6}{g(it.student, '.6g'):>13}{g(it.exact, '.6g'):>13}"
                     f"{g(it.tolerance, '.3g'):>10}  {verdict}")
    return "\n".join(lines)


def summary_row(path: str, rep: SheetReport, lang: str = "en") -> dict[str, Any]:
    """The row of ``summary.csv`` (the examiner's columns)."""
    from plans.check.report import decimal, kind_word, say_line

    def at(q: str, phi: float) -> str:
        return say_line("ch_at", lang, what=q, phi=decimal(f"{phi:g}", lang))

    failed = [i for i in rep.items if i.verdict == "fail"]
    worst = max(rep.items, key=lambda i: abs(i.student - i.exact) / i.tolerance if i.tolerance else 0.0,
                default=None)
    return {"file": path, "student": rep.student, "status": "ok" if lang != "ru" else "проверен",
            "mark": decimal(f"{rep.mark:g}", lang),
            "causes": "; ".join(kind_word(c.kind, lang) for c in rep.causes),
            "unexplained": "; ".join(at(i.quantity, i.phi_deg) for i in rep.unexplained),
            "items": len(rep.items), "passed": len(rep.items) - len(failed), "failed": len(failed), "findings": 0,
            "worst": "" if worst is None else at(worst.quantity, worst.phi_deg),
            "worst_error_pct": "" if worst is None or not worst.exact else
            decimal(f"{100 * (worst.student - worst.exact) / abs(worst.exact):.2f}", lang),
            "worst_tol": "" if worst is None or not worst.tolerance else
            decimal(f"{abs(worst.student - worst.exact) / worst.tolerance:.2f}", lang), "message": ""}


def sheet_outputs(rep: SheetReport, path: Path, out: Path,
                  lang: str = "en") -> tuple[dict[Path, Any], dict[str, Any]]:
    """The report files of a folder's gears or cam sheet, and its summary row."""
    from plans.io import dumps

    return ({out / f"{path.stem}.json": dumps(rep.to_json(lang)), out / f"{path.stem}.txt": table(rep, lang) + "\n"},
            summary_row(str(path), rep, lang))
