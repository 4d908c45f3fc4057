"""Check files: what a student wrote on a hand-drawn sheet, typed in by a teacher.

A check file is TOML, ``format = 1``::

    format = 1
    student = "Ivanov I. I., group 06Ad-31"
    scene = "../v_engine.toml"       # path relative to this file, or an inline [scene] table
    sheet = "A1"                     # the student's sheet (for the 1:1 overlay); optional

    [scales]                         # the student's scales: mu = mm per SI unit, K = unit per mm
    length = { mu = 1000 }           # 1:1
    velocity = { mu = 6.58 }         # mm per m/s
    acceleration = { K = 54.05 }     # m/s² per mm (mu = 0.0185)
    force = { mu = 0.02 }            # mm per N

    [tolerance]
    model = "draftsman"              # or "rule": every item within rule_pct
    segment_mm = 0.5                 # a measured or laid-off segment is good to ±0.5 mm
    direction_deg = 0.5              # a drawn direction is good to ±0.5°
    rule_pct = 5                     # course rule; also for items with no drawing model
    arithmetic_pct = 0.2             # slack of the student's own arithmetic beyond rounding
    balance_base = "lever"           # % difference of the balancing forces relative to the
                                     # Zhukovsky lever's value ("lever") or "kinetostatics"

    [[positions]]
    phi_deg = 45

    [positions.measured]             # segments measured on the student's plans, mm
    v_B = 70                         # the segment that stands for v_B (p_v b)
    a_BA^τ = { mm = 56.5, where = "3.2.2" }

    [positions.values]               # what the student derived, SI units
    v_B = 10.6
    omega_2 = 75.5
    a_A = [ { value = 4433.27, where = "3.2.1" }, { value = 3868.7, where = "3.2.2" } ]
    h_1 = "65 mm"                    # lengths need their unit
    F_bal_diff_pct = 6.18            # the student's own % difference

A value may be a number, ``{ value = x, where = "section" }`` or an array of those
(the same quantity written more than once).  Quantity names follow the plans:
``v_B``, ``v_BA``, ``omega_2``, ``a_BA^n``, ``a_BA^τ`` (``^t`` accepted), ``eps_2``;
a point of a link that slides on another is the point's name and the link's number
(``v_A3``: A of the rocker 3 under the block 2; ``v_A2A3``: the block's sliding velocity
along the slot); Coriolis and sliding components are ``a^k_A3A2`` and ``a^r_A3A2`` (also
``a_A3A2^k``; either order of the two points);
``Phi_2``, ``M_Phi_2``, ``m_2``, ``I_2``, ``G_2``, ``P_3``, ``F_12`` (``F12``),
``F_12^τ``, ``F_bal``, ``F_bal_lever``, ``F_bal_diff_pct``, ``l_AB``, ``h_<name>``.
Greek letters (ω2, ε2, Φ2, MΦ2) are accepted.  Whether the scene has a quantity
is checked against the exact analysis (:func:`plans.check.check`).
"""

from __future__ import annotations

import math
import re
from dataclasses import dataclass
from pathlib import Path
from typing import Any

from plans.errors import InputError, Said
from plans.io import loads_toml, read_toml
from plans.kinematics.placing import load_scene, scene_from_dict
from plans.reader import (
    NUMBER_FLOOR,
    NUMBER_LIMIT,
    Reader,
    bad_character,
    check_keys,
    did_you_mean,
    show,
)
from plans.scene.model import Scene
from plans.tolerances import SAME_ANGLE_DEG
from plans.units import LENGTH_UNITS

SCALE_KINDS = ("length", "velocity", "acceleration", "force")
TOLERANCE_MODELS = ("draftsman", "rule")
BALANCE_BASES = ("lever", "kinetostatics")

#: Deductions by kind of mistake (points off ``full``); a check file's [rubric] overrides.
RUBRIC: dict[str, float] = {
    "full": 100.0,
    "coriolis_reversed": 15.0, "normal_from_pole": 10.0, "tangential_wrong_line": 10.0, "scale": 10.0,
    "similarity": 8.0, "wrong_segment": 5.0, "inertia_sign": 10.0, "reaction_swapped": 8.0,
    "fij_reversed": 5.0, "pi_rounded": 2.0, "g_rounded": 2.0, "arithmetic": 3.0,
    "unexplained": 2.0,  # each failing figure no cause explains
    "finding": 1.0,  # each inconsistency of the student's own work left after the causes
}
RUBRIC_KEYS = tuple(RUBRIC)


@dataclass(frozen=True, slots=True)
class Written:
    """One figure the student wrote."""

    quantity: str  # canonical name
    value: float  # mm for measured segments, SI for values
    kind: str  # "measured" | "value"
    where: str  # section of the student's work ("3.2.2"), "" when not given
    field: str  # where in the check file: positions[0].values.a_A[1]
    half_ulp: float  # half a unit of the last digit typed (the student's rounding)


@dataclass(frozen=True, slots=True)
class StudentPosition:
    phi_deg: float
    index: int  # index of the position in the scene
    measured: tuple[Written, ...]
    values: tuple[Written, ...]
    field: str

    def written(self, quantity: str, kind: str | None = None) -> list[Written]:
        return [w for w in self.measured + self.values
                if w.quantity == quantity and (kind is None or w.kind == kind)]


@dataclass(frozen=True, slots=True)
class Tolerance:
    model: str = "draftsman"
    segment_mm: float = 0.5
    direction_deg: float = 0.5
    rule_pct: float = 5.0
    arithmetic_pct: float = 0.2
    balance_base: str = "lever"


@dataclass(frozen=True, slots=True)
class CheckFile:
    path: str
    student: str
    scene: Scene
    scales: dict[str, float]  # mm per SI unit
    tolerance: Tolerance
    positions: tuple[StudentPosition, ...]
    sheet: str | None = None
    rubric: tuple[tuple[str, float], ...] = ()  # deductions by kind of mistake (the teacher's)


# --------------------------------------------------------------------------- names

_GREEK = (("ω", "omega_"), ("ε", "eps_"), ("МΦ", "M_Phi_"), ("MΦ", "M_Phi_"), ("Φ", "Phi_"),
          ("φ", "Phi_"))
_NAME = re.compile(r"^[A-Za-z][A-Za-z0-9_]*(\^(n|τ|k|r))?$|^a\^(k|r)_[A-Z][A-Za-z0-9]*$")


def canonical(name: str) -> str:
    """The canonical spelling of a quantity name (see the module docstring)."""
    q = name.strip().replace(" ", "")
    for g, latin in _GREEK:
        if q.startswith(g):
            q = latin + q[len(g):]
    q = q.replace("__", "_")
    q = re.sub(r"\^t$", "^τ", q)
    # Coriolis and sliding components: a^k_A3A2 (also written a_A3A2^k, a_k_A3A2)
    q = re.sub(r"^a_([A-Z][A-Za-z0-9]*)\^(k|r)$", r"a^\2_\1", q)
    q = re.sub(r"^a_(k|r)_([A-Z][A-Za-z0-9]*)$", r"a^\1_\2", q)
    q = re.sub(r"^(a_[A-Z]\w*?)_(n|t|τ)$", lambda m: m.group(1) + "^" + ("τ" if m.group(2) != "n" else "n"), q)
    m = re.fullmatch(r"(omega|eps|Phi|M_Phi|m|I|G|P)_?S?(\d+)", q)
    if m:
        return f"{m.group(1)}_{m.group(2)}"
    m = re.fullmatch(r"F_?(\d)(\d)(\^?(n|t|τ))?", q)
    if m:
        tail = "" if not m.group(4) else ("^n" if m.group(4) == "n" else "^τ")
        return f"F_{m.group(1)}{m.group(2)}{tail}"
    return q


LENGTH_QUANTITY = re.compile(r"^(h_\w+|l_[A-Z]\w*)$")


# --------------------------------------------------------------------------- parsing


def load_check(path: str | Path) -> CheckFile:
    """Read and validate a check file (and the scene it names)."""
    return check_from_dict(read_toml(path), str(path))


def parse_check(text: str, path: str = "<check>") -> CheckFile:
    return check_from_dict(loads_toml(text, path), path)


def _fail(path: str, field: str, msg: str | Said) -> InputError:
    return InputError(msg, file=path, field=field)


_TOP = {"format", "student", "group", "variant", "scene", "sheet", "scales", "tolerance", "positions", "title",
        "rubric"}


def check_from_dict(data: dict[str, Any], path: str = "<check>") -> CheckFile:
    from plans.kinds import check_top

    check_top(data, path, "check", _TOP)
    student = data.get("student", Path(path).stem)
    if not isinstance(student, str):
        raise _fail(path, "student", Said("c_student"))
    Reader(path).string(student, "student")
    if "title" in data:
        Reader(path).string(data["title"], "title", limit=2000)
    scene = _scene(path, data.get("scene"))
    sheet = data.get("sheet")
    if sheet is not None and not (isinstance(sheet, str) and sheet in SHEETS):
        hint = did_you_mean(sheet, SHEETS) if isinstance(sheet, str) else ""
        raise _fail(path, "sheet", Said("e_choice", options=", ".join(repr(s) for s in sorted(SHEETS)), got=show(sheet),
                                          hint=hint))
    scales = _scales(path, data.get("scales"))
    tol = _tolerance(path, data.get("tolerance", {}))
    raw = data.get("positions")
    if not isinstance(raw, list) or not raw:
        raise _fail(path, "positions", Said("c_positions"))
    blank = [isinstance(b, dict) and _blank(b) for b in raw]
    if all(blank):
        raise _fail(path, "positions", Said("c_nothing_anywhere"))
    positions = tuple(_position(path, k, body, scene) for k, body in enumerate(raw) if not blank[k])
    seen: set[float] = set()
    for pos in positions:
        if pos.phi_deg in seen:
            raise _fail(path, f"{pos.field}.phi_deg", Said("c_twice", phi=pos.phi_deg))
        seen.add(pos.phi_deg)
    rubric = read_rubric(path, data.get("rubric", {}), "rubric")
    return CheckFile(path=path, student=student, scene=scene, scales=scales, tolerance=tol,
                     positions=positions, sheet=sheet, rubric=rubric)


def _blank(body: dict[str, Any]) -> bool:
    """A position of a blank form: every figure "" (not written)."""
    figures = [v for key in ("measured", "values") if isinstance(body.get(key), dict) for v in body[key].values()]
    return ("measured" in body or "values" in body) and all(v == "" or v == [] for v in figures)


def read_rubric(path: str, raw: Any, where: str) -> tuple[tuple[str, float], ...]:
    """A [rubric] table: ``full`` and the points each kind of mistake costs."""
    if not isinstance(raw, dict):
        raise _fail(path, where, Said("c_rubric"))
    check_keys(raw, RUBRIC_KEYS, file=path, where=f"{where}.")
    out = []
    for key, value in raw.items():
        if isinstance(value, bool) or not isinstance(value, int | float) or \
                not (isinstance(value, int) or math.isfinite(value)) or not 0 <= value <= 1e6:
            raise _fail(path, f"{where}.{key}", Said("c_points", got=show(value)))
        out.append((key, float(value)))
    return tuple(out)


#: Sheet sizes (landscape, mm) for the overlay.
SHEETS = {"A1": (841.0, 594.0), "A2": (594.0, 420.0), "A3": (420.0, 297.0), "A4": (297.0, 210.0)}


def _scene(path: str, raw: Any) -> Scene:
    if raw is None:
        raise _fail(path, "scene", Said("c_scene_missing"))
    if isinstance(raw, str):
        target = Path(raw)
        if not target.is_absolute():
            target = Path(path).parent / target
        if not target.is_file():
            raise _fail(path, "scene", Said("c_scene_not_found", name=raw, target=str(target)))
        if target.resolve() == Path(path).resolve():
            raise _fail(path, "scene", Said("c_scene_self"))
        return load_scene(target)
    if isinstance(raw, dict):
        return scene_from_dict(raw, f"{path} [scene]")
    raise _fail(path, "scene", Said("c_scene_type"))


def _positive(path: str, field: str, value: Any, limit: float = 1e9, floor: float = 1e-9) -> float:
    if isinstance(value, bool) or not isinstance(value, int | float) or \
            (isinstance(value, float) and not math.isfinite(value)):
        raise _fail(path, field, Said("e_positive", got=show(value)))
    if value <= 0:
        raise _fail(path, field, Said("c_scale_positive", got=show(value)))
    return Reader(path).value(value, field, positive=True, limit=limit, floor=floor)


def _scales(path: str, raw: Any) -> dict[str, float]:
    if not isinstance(raw, dict):
        raise _fail(path, "scales", Said("c_scales"))
    style = Reader(path).choice(raw, "style", "scales.", ("mu", "K"), "mu")
    check_keys(raw, ("style", *SCALE_KINDS), file=path, where="scales.")
    out: dict[str, float] = {}
    for key, value in raw.items():
        if key == "style" or value == "" or (isinstance(value, dict) and list(value.values()) == [""]):
            continue  # a blank of the form: not given
        if isinstance(value, dict):
            if len(value) != 1 or not ({"mu", "K"} & set(value)):
                raise _fail(path, f"scales.{key}", Said("e_scale"))
            kind = "mu" if "mu" in value else "K"
            x = _positive(path, f"scales.{key}.{kind}", value[kind])
        else:
            kind = style
            x = _positive(path, f"scales.{key}", value)
        out[key] = x if kind == "mu" else 1.0 / x
    if "length" not in out:
        out["length"] = 1000.0  # 1:1, as an A1 sheet of an engine is usually drawn
    return out


def _tolerance(path: str, raw: Any) -> Tolerance:
    if not isinstance(raw, dict):
        raise _fail(path, "tolerance", Said("e_table"))
    known = {"model", "segment_mm", "direction_deg", "rule_pct", "arithmetic_pct", "balance_base"}
    check_keys(raw, known, file=path, where="tolerance.")
    model = Reader(path).choice(raw, "model", "tolerance.", TOLERANCE_MODELS, "draftsman")
    base = Reader(path).choice(raw, "balance_base", "tolerance.", BALANCE_BASES, "lever")
    nums = {}
    for key, default in (("segment_mm", 0.5), ("direction_deg", 0.5), ("rule_pct", 5.0),
                         ("arithmetic_pct", 0.2)):
        v = raw.get(key, default)
        nums[key] = _positive(path, f"tolerance.{key}", v, limit=1e6, floor=1e-6)
    return Tolerance(model=model, balance_base=base, **nums)


def half_ulp(x: float | int) -> float:
    """Half a unit of the last digit of a number as typed (TOML keeps ints apart)."""
    if isinstance(x, int):
        return 0.5
    s = repr(float(x))
    if "e" in s or "E" in s:
        mant, exp = s.lower().split("e")
        dec = len(mant.split(".")[1]) if "." in mant else 0
        return 0.5 * 10.0 ** (int(exp) - dec)
    dec = len(s.split(".")[1]) if "." in s else 0
    if s.endswith(".0"):
        dec = 0
    return 0.5 * 10.0 ** (-dec)


def _position(path: str, k: int, body: Any, scene: Scene) -> StudentPosition:
    where = f"positions[{k}]"
    if not isinstance(body, dict):
        raise _fail(path, where, Said("e_table"))
    check_keys(body, ("phi_deg", "measured", "values", "where"), file=path, where=f"{where}.")
    phi = body.get("phi_deg")
    if isinstance(phi, bool) or not isinstance(phi, int | float) or \
            (isinstance(phi, float) and not math.isfinite(phi)) or abs(phi) > 1e300:
        raise _fail(path, f"{where}.phi_deg", Said("c_phi", got=show(phi)))
    phis = scene.driver.phis_deg
    idx = next((i for i, p in enumerate(phis) if abs(p - phi) < SAME_ANGLE_DEG), None)
    if idx is None:
        raise _fail(path, f"{where}.phi_deg", Said("c_phi_not_in_scene", phi=float(phi),
                                                    has=", ".join(f"{p:g}°" for p in phis)))
    default_where = body.get("where", "")
    if not isinstance(default_where, str):
        raise _fail(path, f"{where}.where", Said("c_string"))
    measured = _entries(path, f"{where}.measured", body.get("measured", {}), "measured", default_where)
    values = _entries(path, f"{where}.values", body.get("values", {}), "value", default_where)
    if not measured and not values:
        raise _fail(path, where, Said("c_nothing"))
    return StudentPosition(float(phi), idx, tuple(measured), tuple(values), where)


def _entries(path: str, where: str, raw: Any, kind: str, default_where: str) -> list[Written]:
    if not isinstance(raw, dict):
        raise _fail(path, where, Said("c_figures"))
    out = []
    for name, spec in raw.items():
        if spec == "":
            continue  # a blank of the form: not written
        if bad_character(name) or len(name) > 200:
            raise _fail(path, f"{where}.{name!r}", Said("c_not_a_name"))
        q = canonical(name)
        if not _NAME.match(q.replace("^τ", "^τ")):
            raise _fail(path, f"{where}.{name}", Said("c_not_a_name"))
        items = [x for x in spec if x != ""] if isinstance(spec, list) else [spec]
        if not items:
            raise _fail(path, f"{where}.{name}", Said("c_one_figure"))
        for j, item in enumerate(items):
            f = f"{where}.{name}" + (f"[{j}]" if isinstance(spec, list) else "")
            out.append(_one(path, f, q, item, kind, default_where))
    return out


def _one(path: str, field: str, q: str, item: Any, kind: str, default_where: str) -> Written:
    loc = default_where
    key = "mm" if kind == "measured" else "value"
    if isinstance(item, dict):
        check_keys(item, (key, "where") + (("length",) if kind == "value" else ()), file=path,
                   where=f"{field}.")
        loc = item.get("where", default_where)
        if not isinstance(loc, str):
            raise _fail(path, f"{field}.where", Said("c_where"))
        if "length" in item and kind == "value":
            item = item["length"]
        elif key not in item:
            raise _fail(path, field, Said("c_missing", key=key))
        else:
            item = item[key]
    if kind == "measured":
        mm, hu = _length_mm(path, field, item, need_unit=False)
        if mm < 0:
            raise _fail(path, field, Said("c_negative", got=show(item)))
        return Written(q, mm, kind, loc, field, hu)
    if LENGTH_QUANTITY.match(q):
        mm, hu = _length_mm(path, field, item, need_unit=True)
        return Written(q, mm * 1e-3, kind, loc, field, hu * 1e-3)
    if isinstance(item, bool) or not isinstance(item, int | float) or \
            (isinstance(item, float) and not math.isfinite(item)) or abs(item) > NUMBER_LIMIT:
        raise _fail(path, field, Said("c_si", limit=NUMBER_LIMIT,
                                      got=show(item)))
    if item != 0 and abs(item) < NUMBER_FLOOR:
        raise _fail(path, field, Said("e_floor", floor=NUMBER_FLOOR, got=show(item)))
    return Written(q, float(item), kind, loc, field, half_ulp(item))


_LEN = re.compile(r"^\s*([-+]?(?:\d+\.?\d*|\.\d+)(?:[eE][-+]?\d+)?)\s*([a-zA-Z]*)\s*$")


def _length_mm(path: str, field: str, item: Any, *, need_unit: bool) -> tuple[float, float]:
    """A length in mm and half its last typed digit (mm)."""
    if isinstance(item, bool):
        raise _fail(path, field, Said("c_length", got=show(item)))
    if isinstance(item, int | float):
        if need_unit:
            raise _fail(path, field, Said("c_unit", item=item))
        if (isinstance(item, float) and not math.isfinite(item)) or abs(item) > 1e7:
            raise _fail(path, field, Said("c_finite_length"))
        return float(item), half_ulp(item)
    if isinstance(item, str):
        m = _LEN.match(item)
        if m:
            unit = m.group(2) or ("" if need_unit else "mm")
            if unit in LENGTH_UNITS:
                number = m.group(1)
                if not (abs(float(number)) * LENGTH_UNITS[unit] <= 1e4):
                    raise _fail(path, field, Said("c_finite_length_got", got=show(item)))
                hu = half_ulp(float(number)) if "." in number else 0.5
                factor = LENGTH_UNITS[unit] / 1e-3
                return float(number) * factor, hu * factor
            if need_unit and not unit:
                raise _fail(path, field, Said("c_unit", item=item))
    raise _fail(path, field, Said("c_length_such", got=show(item)))
