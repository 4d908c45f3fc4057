"""The gear file: TOML, ``format = 1``, ``kind = "gears"``.

::

    format = 1
    kind = "gears"
    unit = "mm"              # lengths in the file (module, centre distances) and in the JSON
    module = 4               # m, every gear unless it says otherwise
    pressure_angle_deg = 20  # α of the generating rack
    addendum = 1.0           # h_a*
    clearance = 0.25         # c*
    ring_tip = "trimmed"     # a ring gear's tip circle: "trimmed" (through the rack-cut pinion's
                             # limit point, the exact form of GOST 19274's rule), "gost"
                             # (d_a2 = d2 − 2(h_a* − x2 − h_a*²/(z2 tan²α)) m) or "plain"
                             # (r_a2 = r2 − (h_a* − x2) m)
    shift_rule = "minimum"   # how x = "auto" is chosen: "minimum" (x = h_a*(z_min − z)/z_min,
                             # z_min rounded as the course tabulates it), "no_undercut" (the exact
                             # x = h_a* − z sin²α/2), "equal_sliding" (a pair of "auto" gears:
                             # equal greatest specific sliding, each above its undercut limit)
    [[gears]]
    name = "1"
    z = 26
    x = 0                    # or "auto"
    internal = false         # true: a ring gear (internal teeth)
    ring_tip = "plain"       # a ring's own tip rule (default: the file's ring_tip)
    shaft = "1"              # gears on one shaft turn as one (default: the gear's own name)
    [[meshes]]
    gears = ["1", "2"]
    centre_distance = 80.7   # optional: the pair assembled at this a_w (else a_w follows the shifts)
    draw = true              # the pair drawn on the meshing sheet (default: the first external)
    [[shafts]]               # only shafts that need saying: speeds, carriers
    name = "1"
    speed_rpm = 650          # given speed (0: held); a differential needs two
    carrier = "H"            # this shaft's axis rides on the carrier H (a planet)
    [synthesis]              # numbers of teeth of a 2K-H train (sun 1, planets 2, ring 3, carrier H)
    ratio = 4.5              # i_1H with the ring held
    planets = 3              # k (or a list to try, e.g. [3, 4])
    tolerance = 0.02         # accepted relative error of the ratio
    z_min = 17               # fewest teeth on any wheel
    [sheet]                  # the drawing's title block and format, as for every sheet

Every length inside the engine is in metres; the file's ``unit`` comes back at the JSON.
"""

from __future__ import annotations

import math
from collections.abc import Iterator
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

from plans.errors import InputError, Said
from plans.io import read_toml
from plans.reader import LENGTH_FLOOR, LENGTH_LIMIT, Reader, check_keys, show
from plans.scene.sheet import own_title
from plans.tolerances import ROUND_OFF_REL
from plans.units import LENGTH_UNITS

SHIFT_RULES = ("minimum", "no_undercut", "equal_sliding")
#: The most teeth a wheel may have (more is no gear a course draws, and keeps numbers finite).
MAX_TEETH = 10_000

_TOP_KEYS = ("format", "kind", "unit", "title", "module", "pressure_angle_deg", "addendum",
             "clearance", "shift_rule", "ring_tip", "gears", "meshes", "shafts", "synthesis", "sheet")
_GEAR_KEYS = ("name", "z", "x", "internal", "shaft", "module", "ring_tip")
_MESH_KEYS = ("gears", "centre_distance", "draw")
_SHAFT_KEYS = ("name", "speed_rpm", "carrier")
_SYNTH_KEYS = ("ratio", "planets", "tolerance", "z_min")


@dataclass(frozen=True)
class Gear:
    name: str
    z: int
    x: float | None  # None: chosen by the file's shift rule
    internal: bool
    shaft: str
    module: float  # m, metres
    ring_tip: str = "trimmed"  # a ring gear's tip rule (RING_TIPS)


@dataclass(frozen=True)
class Mesh:
    gears: tuple[str, str]
    centre_distance: float | None  # a_w given, metres
    draw: bool


@dataclass(frozen=True)
class Shaft:
    name: str
    speed_rpm: float | None
    carrier: str | None


@dataclass(frozen=True)
class SynthesisSpec:
    ratio: float
    planets: tuple[int, ...]
    tolerance: float
    z_min: int


@dataclass(frozen=True)
class GearFile:
    path: str
    title: str
    unit: str
    alpha: float  # radians
    ha: float
    c: float
    shift_rule: str
    gears: dict[str, Gear]
    meshes: tuple[Mesh, ...]
    shafts: dict[str, Shaft]
    synthesis: SynthesisSpec | None
    ring_tip: str = "trimmed"  # the file's default tip rule for ring gears
    raw: dict[str, Any] = field(repr=False, default_factory=dict)

    @property
    def to_unit(self) -> float:
        """Metres -> the file's unit."""
        return 1.0 / LENGTH_UNITS[self.unit]


def _num(v: Any, path: str, field_: str, what: str | Said, lo: float | None = None,
         hi: float | None = None, strict: bool = True) -> float:
    if isinstance(v, bool) or not isinstance(v, int | float):
        raise InputError(Said("gm_what", what=what, got=show(v)), file=path, field=field_)
    ranged = lo is not None and lo > 0  # its own range says more than the floor
    f = Reader(path).value(v, field_, positive=lo == 0.0 and strict, floor=0.0 if ranged else None)
    if lo is not None and (f <= lo if strict else f < lo):
        raise InputError(Said("gm_what", what=what, got=show(v)), file=path, field=field_)
    if hi is not None and f >= hi:
        raise InputError(Said("gm_what", what=what, got=show(v)), file=path, field=field_)
    return f


def _name(v: Any, path: str, field_: str) -> str:
    if isinstance(v, bool) or not isinstance(v, str | int) or str(v) == "":
        raise InputError(Said("gm_name_string_such", got=show(v)), file=path, field=field_)
    return Reader(path).name(str(v), field_)


def _tables(data: dict[str, Any], key: str, path: str) -> list[dict[str, Any]]:
    v = data.get(key, [])
    if not isinstance(v, list) or not all(isinstance(t, dict) for t in v):
        raise InputError(Said("gm_array_tables", k=key), file=path, field=key)
    return v


def _named(data: dict[str, Any], key: str, path: str, keys: Any, missing: str,
           twice: str) -> Iterator[tuple[str, dict[str, Any], str]]:
    """Each table of the array ``key`` with its keys checked, its name read and not given
    before: (name, table, the field's prefix ``key[i].``).  ``missing`` and ``twice`` name
    the messages for a table without a name and for a name given twice."""
    seen: set[str] = set()
    for i, t in enumerate(_tables(data, key, path)):
        f = f"{key}[{i}]."
        check_keys(t, keys, file=path, where=f)
        if "name" not in t:
            raise InputError(Said(missing), file=path, field=f + "name")
        name = _name(t["name"], path, f + "name")
        if name in seen:
            raise InputError(Said(twice, name=name), file=path, field=f + "name")
        seen.add(name)
        yield name, t, f


def load_gears(path: str | Path) -> GearFile:
    """Read and validate a gear file (one-line InputError naming the field on any problem)."""
    return parse_gears(read_toml(path), str(path))


def parse_gears(data: dict[str, Any], path: str) -> GearFile:
    from plans.kinds import check_top

    check_top(data, path, "gears", _TOP_KEYS)
    unit = Reader(path).choice(data, "unit", "", LENGTH_UNITS, default="mm")
    k = LENGTH_UNITS[unit]
    if "module" not in data:
        raise InputError(Said("gm_missing_module_file"),
                         file=path, field="module")
    m = _num(data["module"], path, "module", Said("gm_w_module"), lo=0.0) * k
    if not LENGTH_FLOOR <= m <= LENGTH_LIMIT:
        raise InputError(Said("gm_module_from_length", LENGTH_LIMIT=LENGTH_LIMIT, got=show(data['module']), unit=unit),
                         file=path, field="module")
    alpha_deg = _num(data.get("pressure_angle_deg", 20), path, "pressure_angle_deg",
                     Said("gm_w_alpha"), lo=5.0, hi=45.0, strict=False)
    # h_a* below 0.5 leaves no tooth to cut and z_min rounds to nothing.
    ha = _num(data.get("addendum", 1.0), path, "addendum", Said("gm_w_addendum"), lo=0.5, hi=2.0,
              strict=False)
    c = _num(data.get("clearance", 0.25), path, "clearance", Said("gm_w_clearance"), lo=0.0, strict=False)
    rule = data.get("shift_rule", "minimum")
    if rule not in SHIFT_RULES:
        raise InputError(Said("gm_one", v=', '.join(repr(r) for r in SHIFT_RULES), got=show(rule)),
                         file=path, field="shift_rule")
    ring_tip = _ring_tip(data, path, "ring_tip", "trimmed")
    title = own_title(data.get("title", ""))
    if not isinstance(title, str):
        raise InputError(Said("gm_string"), file=path, field="title")
    gears = _gears(data, path, m, k, ring_tip)
    if not gears:
        raise InputError(Said("gm_least_one_gears"), file=path, field="gears")
    meshes = _meshes(data, path, gears, k)
    shafts = {g.shaft: Shaft(g.shaft, None, None) for g in gears.values()}
    for name, t, f in _named(data, "shafts", path, _SHAFT_KEYS, "gm_missing_shaft_name", "gm_shaft_name_described"):
        sp = t.get("speed_rpm")
        spv = None if sp is None else _num(sp, path, f + "speed_rpm", Said("gm_w_speed"))
        car = None if t.get("carrier") is None else _name(t["carrier"], path, f + "carrier")
        shafts[name] = Shaft(name, spv, car)
    for s in list(shafts.values()):
        if s.carrier is not None:
            if s.carrier == s.name:
                raise InputError(Said("gm_shaft_name_cannot", name=s.name), file=path, field="shafts")
            if s.carrier not in shafts:
                shafts[s.carrier] = Shaft(s.carrier, None, None)
            if shafts[s.carrier].carrier is not None:
                raise InputError(Said("gm_carrier_carrier_rides", carrier=s.carrier), file=path, field="shafts")
    carriers = {s.carrier for s in shafts.values() if s.carrier is not None}
    riding = {g.shaft for g in gears.values()}
    for i, t in enumerate(_tables(data, "shafts", path)):
        name = str(t["name"])
        if name not in riding and name not in carriers:
            raise InputError(Said("gm_gear_rides_shaft", name=name, v=', '.join(repr(s) for s in sorted(riding | carriers))), file=path,
                             field=f"shafts[{i}].name")
    synth = _synthesis(data.get("synthesis"), path)
    if not meshes and synth is None:
        raise InputError(Said("gm_least_one_meshes"), file=path,
                         field="meshes")
    return GearFile(path, title, unit, math.radians(alpha_deg), ha, c, rule, gears, tuple(meshes),
                    shafts, synth, ring_tip, data)


def _ring_tip(t: dict[str, Any], path: str, field_: str, default: str) -> str:
    from .geometry import RING_TIPS

    v = t.get(field_.rsplit(".", 1)[-1], default)
    if v not in RING_TIPS:
        raise InputError(Said("gm_one", v=', '.join(repr(r) for r in RING_TIPS), got=show(v)),
                         file=path, field=field_)
    return str(v)


def _synthesis(t: Any, path: str) -> SynthesisSpec | None:
    if t is None:
        return None
    if not isinstance(t, dict):
        raise InputError(Said("gm_table_synthesis"), file=path, field="synthesis")
    check_keys(t, _SYNTH_KEYS, file=path, where="synthesis.")
    if "ratio" not in t:
        raise InputError(Said("gm_missing_ratio_ratio"), file=path,
                         field="synthesis.ratio")
    ratio = _num(t["ratio"], path, "synthesis.ratio", Said("gm_w_ratio"),
                 lo=2.0)
    k = t.get("planets", [3, 4, 5, 6])
    ks = k if isinstance(k, list) else [k]
    if not ks or not all(isinstance(v, int) and not isinstance(v, bool) and 2 <= v <= 12 for v in ks):
        raise InputError(Said("gm_number_planets_list"), file=path,
                         field="synthesis.planets")
    tol = _num(t.get("tolerance", 0.02), path, "synthesis.tolerance", Said("gm_w_tolerance"),
               lo=0.0, hi=0.5)
    zmin = t.get("z_min", 17)
    if isinstance(zmin, bool) or not isinstance(zmin, int) or zmin < 4:
        raise InputError(Said("gm_whole_number"), file=path, field="synthesis.z_min")
    return SynthesisSpec(ratio, tuple(ks), tol, zmin)


def _gears(data: dict[str, Any], path: str, m: float, k: float, ring_tip: str) -> dict[str, Gear]:
    gears: dict[str, Gear] = {}
    for name, g, f in _named(data, "gears", path, _GEAR_KEYS, "gm_missing_name_such", "gm_gear_name_named"):
        z = g.get("z")
        if isinstance(z, bool) or not isinstance(z, int) or not 1 <= z <= MAX_TEETH:
            raise InputError(Said("gm_whole_number_teeth", MAX_TEETH=MAX_TEETH, got=show(z)), file=path,
                             field=f + "z")
        xv = g.get("x", 0)
        x: float | None
        if xv == "auto":
            x = None
        else:
            if isinstance(xv, bool) or not isinstance(xv, int | float) or not abs(xv) <= 5:  # NaN fails too
                raise InputError(Said("gm_shift_coefficient_number", got=show(xv)),
                                 file=path, field=f + "x")
            x = Reader(path).value(xv, f + "x")  # 0 or at least 1e-12, as every number
        internal = g.get("internal", False)
        if not isinstance(internal, bool):
            raise InputError(Said("gm_true_false"), file=path, field=f + "internal")
        shaft = _name(g.get("shaft", name), path, f + "shaft")
        gm = _num(g["module"], path, f + "module", Said("gm_w_module"), lo=0.0) * k if "module" in g else m
        tip = _ring_tip(g, path, f + "ring_tip", ring_tip)
        if "ring_tip" in g and not internal:
            raise InputError(Said("gm_ring_tip_ring"), file=path, field=f + "ring_tip")
        gears[name] = Gear(name, z, x, internal, shaft, gm, tip)
    return gears


def _meshes(data: dict[str, Any], path: str, gears: dict[str, Gear], k: float) -> list[Mesh]:
    meshes = []
    seen: set[frozenset[str]] = set()
    for i, t in enumerate(_tables(data, "meshes", path)):
        f = f"meshes[{i}]."
        check_keys(t, _MESH_KEYS, file=path, where=f)
        pair = t.get("gears")
        if not isinstance(pair, list) or len(pair) != 2:
            raise InputError(Said("gm_two_gear_names"), file=path, field=f + "gears")
        a, b = (_name(v, path, f + "gears") for v in pair)
        for n in (a, b):
            if n not in gears:
                raise InputError(Said("gm_gear_named_one", n=n, v=', '.join(gears)), file=path,
                                 field=f + "gears")
        if a == b or frozenset((a, b)) in seen:
            raise InputError(Said("gm_pair_new_pair", a=a, b=b), file=path, field=f + "gears")
        seen.add(frozenset((a, b)))
        ga, gb = gears[a], gears[b]
        if ga.internal and gb.internal:
            raise InputError(Said("gm_two_internal_gears", a=a, b=b), file=path, field=f + "gears")
        if abs(ga.module - gb.module) > ROUND_OFF_REL * ga.module:
            raise InputError(Said("gm_gears_have_different", a=a, b=b), file=path, field=f + "gears")
        if ga.shaft == gb.shaft:
            raise InputError(Said("gm_gears_are_one", a=a, b=b), file=path, field=f + "gears")
        aw = t.get("centre_distance")
        awv = None if aw is None else _num(aw, path, f + "centre_distance", Said("gm_w_centre"), lo=0.0) * k
        draw = t.get("draw", False)
        if not isinstance(draw, bool):
            raise InputError(Said("gm_true_false"), file=path, field=f + "draw")
        meshes.append(Mesh((a, b), awv, draw))
    return meshes
