"""The synthesis file (TOML, ``format = 1``, ``kind = "synthesis"``) and the frozen
:class:`Task` it describes.

.. code-block:: toml

    format = 1
    kind = "synthesis"
    unit = "mm"
    mechanism = "slider_crank"   # slider_crank, crank_rocker, coulisse, v_engine
    stroke = 245                 # H, the slider's (or the ram's) stroke
    K = 1.0                      # coefficient of speed change
    lambda = 0.5                 # or offset, or pressure_angle_max_deg; or mean_speed
    [task]                       # passed into the written scene: omega_rpm, sense, masses, ...

Inside everything is SI (m, rad).  Every problem is one InputError line naming the key.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

from plans.io import read_toml
from plans.reader import Reader
from plans.units import LENGTH_UNITS

MECHANISMS = ("slider_crank", "crank_rocker", "coulisse", "v_engine")
#: The keys each mechanism reads (besides the common ones).
MODEL_KEYS = {
    "slider_crank": {"stroke", "K", "lambda", "offset", "pressure_angle_max_deg", "mean_speed"},
    "crank_rocker": {"K", "rocker", "swing_deg", "frame", "frame_angle_deg", "gamma_min_deg", "positions"},
    "coulisse": {"K", "stroke", "centre_distance", "guide_height", "rod", "pressure_angle_max_deg", "ram_group"},
    "v_engine": {"stroke", "lambda", "bank_deg", "mean_speed"},
}
COMMON_KEYS = {"format", "kind", "title", "unit", "mechanism", "task", "sheet"}
#: What [task] may carry into the written scene.
TASK_KEYS = {"omega_rpm", "omega", "eps", "sense", "phi_ref_deg", "phi0_deg", "positions", "phi_deg",
             "masses", "loads", "outputs", "dynamics", "sheet", "scales", "fij", "diagrams", "title"}
MASS_KEYS = {"mass", "inertia", "centre", "points"}


@dataclass(frozen=True)
class Task:
    """A synthesis task, SI units (the angles in radians)."""

    path: str
    title: str
    unit: str
    mechanism: str
    stroke: float | None = None  # H (m)
    K: float = 1.0
    lam: float | None = None  # l1/l2
    offset: float | None = None  # e (m)
    pressure_angle_max: float | None = None  # [ϑ] (rad)
    mean_speed: float | None = None  # m/s
    rocker: float | None = None  # m
    swing: float | None = None  # ψ (rad)
    frame: float | None = None  # m
    frame_angle: float | None = None  # rad
    gamma_min: float | None = None  # [γ] (rad)
    positions: tuple[tuple[float, float], ...] | None = None  # (φ, ψ) rad, three
    centre_distance: float | None = None  # m
    guide_height: float | None = None  # m
    rod: float | None = None  # m
    bank: float | None = None  # rad
    ram_group: str = "RRP"  # the coulisse's ram: RRP (rod DE) or RPP (block D in the ram's slot)
    omega_rpm: float | None = None  # from [task]
    sense: int = 1
    task: dict[str, Any] = field(default_factory=dict)
    raw: dict[str, Any] = field(default_factory=dict)

    @property
    def scale(self) -> float:
        """Metres per file unit."""
        return LENGTH_UNITS[self.unit]

    @property
    def theta(self) -> float:
        """The overlap angle θ = 180°·(K − 1)/(K + 1), rad."""
        return math.pi * (self.K - 1.0) / (self.K + 1.0)


def load_task(path: str | Path) -> Task:
    return task_from_dict(read_toml(path), str(path))


def task_from_dict(data: dict[str, Any], path: str) -> Task:
    r = Reader(path)
    fmt = data.get("format")
    if isinstance(fmt, bool) or fmt != 1:
        raise r.fail("format", f"expected format = 1, got {'nothing' if fmt is None else repr(fmt)}")
    if data.get("kind") != "synthesis":
        raise r.fail("kind", f"expected \"synthesis\", got {data.get('kind')!r}")
    mech = r.choice(data, "mechanism", "", MECHANISMS)
    for key in data:
        if key not in COMMON_KEYS and key not in MODEL_KEYS[mech]:
            others = [m for m in MECHANISMS if key in MODEL_KEYS[m]]
            if others:
                raise r.fail(key, f"not read for mechanism = {mech!r} (it is read for "
                                  f"{', '.join(repr(m) for m in others)}); expected some of "
                                  f"{', '.join(sorted(MODEL_KEYS[mech]))}")
            r.keys({key: None}, COMMON_KEYS | MODEL_KEYS[mech], "")
    unit = r.choice(data, "unit", "", sorted(LENGTH_UNITS), "mm")
    title = data.get("title", Path(path).stem)
    if isinstance(title, dict) and title and all(k in ("ru", "en") and isinstance(v, str) for k, v in title.items()):
        title = title.get("en") or title.get("ru")
    title = r.string(title, "title", limit=2000)
    task = r.table(data, "task", "", required=False)
    r.keys(task, TASK_KEYS, "task.")
    for key in ("masses", "loads", "dynamics", "sheet", "scales", "diagrams"):
        if key in task and not isinstance(task[key], dict):
            raise r.fail(f"task.{key}", "expected a table")
    _finite(r, task, "task")
    _masses(r, task, mech)
    if "sheet" in data and not isinstance(data["sheet"], dict):
        raise r.fail("sheet", "expected a table")

    def length(key: str) -> float | None:
        return r.length(data[key], key, unit, positive=True) if key in data else None

    def deg(key: str, lo: float, hi: float, what: str) -> float | None:
        if key not in data:
            return None
        v = r.value(data[key], key)
        if not lo < v < hi:
            raise r.fail(key, f"expected {what} between {lo:g}° and {hi:g}° (exclusive), got {v:g}")
        return math.radians(v)

    K = r.number(data, "K", "", default=1.0)
    if not 1.0 <= K <= 1e6:
        raise r.fail("K", f"expected the coefficient of speed change K >= 1, got {K:g}")
    lam = None
    if "lambda" in data:
        lam = r.value(data["lambda"], "lambda")
        if not 0 < lam < 1:
            raise r.fail("lambda", f"expected λ = l1/l2 between 0 and 1 (exclusive), got {lam:g}")
    offset = None
    if "offset" in data:
        offset = r.length(data["offset"], "offset", unit)
        if offset < 0:
            raise r.fail("offset", f"expected the offset e >= 0 (its side follows the sense), got {data['offset']!r}")
    mean_speed = r.number(data, "mean_speed", "", positive=True) if "mean_speed" in data else None
    omega_rpm = None
    if "omega_rpm" in task:
        omega_rpm = r.number(task, "omega_rpm", "task.", positive=True, limit=1e7)
    sense = 1 if r.choice(task, "sense", "task.", ("ccw", "cw"), "ccw") == "ccw" else -1
    positions = None
    if "positions" in data:
        positions = _positions(r, data["positions"])
    t = Task(path=path, title=title, unit=unit, mechanism=mech, stroke=length("stroke"), K=K, lam=lam,
             offset=offset,
             pressure_angle_max=deg("pressure_angle_max_deg", 0, 90, "the permissible pressure angle"),
             mean_speed=mean_speed, rocker=length("rocker"),
             swing=deg("swing_deg", 0, 180, "the rocker's swing ψ"), frame=length("frame"),
             frame_angle=deg("frame_angle_deg", 0, 180, "the frame's angle to the rocker's mean position"),
             gamma_min=deg("gamma_min_deg", 0, 90, "the permissible transmission angle [γ]"),
             positions=positions, centre_distance=length("centre_distance"),
             guide_height=length("guide_height"), rod=length("rod"),
             bank=deg("bank_deg", 0, 180, "the bank angle between the cylinders"),
             ram_group=r.choice(data, "ram_group", "", ("RRP", "RPP"), "RRP") if mech == "coulisse" else "RRP",
             omega_rpm=omega_rpm, sense=sense, task=task, raw=data)
    _required(r, t)
    return t


#: The moving links of each mechanism's scene (the frame is the next number).
LINKS = {"slider_crank": 3, "crank_rocker": 3, "coulisse": 5, "v_engine": 5}


def _masses(r: Reader, task: dict[str, Any], mech: str) -> None:
    n = LINKS[mech]
    for key, body in task.get("masses", {}).items():
        where = f"task.masses.{key}."
        if not (key.isdigit() and 1 <= int(key) <= n):
            raise r.fail(f"task.masses.{key}", f"expected a moving link's number 1..{n} as the key "
                                               "([task.masses.2])")
        if not isinstance(body, dict):
            raise r.fail(f"task.masses.{key}", "expected a table: mass, inertia, centre, points")
        r.keys(body, MASS_KEYS, where)
        if "centre" in body:
            c = body["centre"]
            if isinstance(c, bool) or not isinstance(c, int | float | str):
                raise r.fail(f"{where}centre", "expected a ratio along the link (0..1) or a point name")
            if not isinstance(c, str) and not 0 <= c <= 1:
                raise r.fail(f"{where}centre", f"expected a ratio along the link between 0 and 1, got {c!r}")
        if "points" in body and not isinstance(body["points"], dict):
            raise r.fail(f"{where}points", "expected a table of points, as in a scene")


def _finite(r: Reader, value: Any, where: str) -> None:
    """No NaN or infinity anywhere in what [task] carries into the scene."""
    if isinstance(value, float) and not math.isfinite(value):
        raise r.fail(where, f"expected a finite number, got {value!r}")
    if isinstance(value, dict):
        for k, v in value.items():
            _finite(r, v, f"{where}.{k}")
    elif isinstance(value, list):
        for i, v in enumerate(value):
            _finite(r, v, f"{where}[{i}]")


def _positions(r: Reader, raw: Any) -> tuple[tuple[float, float], ...]:
    ok = isinstance(raw, list) and len(raw) == 3 and all(
        isinstance(p, list) and len(p) == 2 for p in raw)
    if not ok:
        raise r.fail("positions", "expected three pairs [crank_deg, rocker_deg]")
    out = []
    for i, p in enumerate(raw):
        phi = r.value(p[0], f"positions[{i}][0]")
        psi = r.value(p[1], f"positions[{i}][1]")
        out.append((math.radians(phi), math.radians(psi)))
    return tuple(out)


def _required(r: Reader, t: Task) -> None:
    """The keys a model cannot do without, and the third conditions given one at a time."""
    def need(key: str, value: Any, what: str) -> None:
        if value is None:
            raise r.fail(key, f"missing; {t.mechanism} needs {what}")

    if t.mechanism in ("slider_crank", "v_engine"):
        if t.stroke is None and t.mean_speed is None:
            raise r.fail("stroke", "missing; expected the stroke H (or mean_speed with task.omega_rpm)")
        if t.mean_speed is not None and t.stroke is None and t.omega_rpm is None:
            raise r.fail("task.omega_rpm", "missing; mean_speed gives the stroke only with the crank's speed")
        if t.mean_speed is not None and t.stroke is not None and t.omega_rpm is not None:
            raise r.fail("mean_speed", "give two of stroke, mean_speed and task.omega_rpm, not all three")
        third = [k for k in ("lambda", "offset", "pressure_angle_max_deg") if k in t.raw]
        if len(third) > 1:
            raise r.fail(third[1], f"give one third condition ({' or '.join(third)}), not {len(third)}")
    if t.mechanism == "v_engine":
        need("lambda", t.lam, "λ = l1/l2")
        need("bank_deg", t.bank, "the bank angle between the cylinders")
    if t.mechanism == "crank_rocker":
        if t.positions is not None:
            for key in ("K", "swing_deg", "frame_angle_deg", "gamma_min_deg"):
                if key in t.raw:
                    raise r.fail(key, "three positions fix the mechanism; give rocker or frame (its size) only")
            if (t.rocker is None) == (t.frame is None):
                raise r.fail("rocker", "with three positions give one size: rocker or frame")
        else:
            need("rocker", t.rocker, "the rocker's length")
            need("swing_deg", t.swing, "the rocker's swing ψ")
            given = [k for k in ("frame", "frame_angle_deg", "gamma_min_deg") if k in t.raw]
            if len(given) > 1:
                raise r.fail(given[1], f"give one third condition ({' or '.join(given)}), not {len(given)}")
    if t.mechanism == "coulisse":
        need("stroke", t.stroke, "the ram's stroke H")
        need("centre_distance", t.centre_distance, "the centre distance of the crank's and coulisse's pivots")
        if t.K <= 1.0:
            raise r.fail("K", "a coulisse has K > 1 (the overlap angle θ is its swing); expected K > 1")
        if t.ram_group == "RPP" and t.rod is not None:
            raise r.fail("rod", "an RPP ram has no rod DE (a block at D slides in the ram's slot)")
        if t.ram_group == "RRP" and t.rod is None and t.pressure_angle_max is None:
            raise r.fail("pressure_angle_max_deg", "missing; the ram's group is sized by its permissible "
                                                   "pressure angle (or give rod)")
