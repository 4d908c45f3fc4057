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

from plans.errors import Said
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
        raise r.fail("format", Said("sm_format", v='nothing' if fmt is None else repr(fmt)))
    if data.get("kind") != "synthesis":
        raise r.fail("kind", Said("sm_synthesis", v=data.get('kind')))
    mech = r.choice(data, "mechanism", "", MECHANISMS)
    for key in data:
        if key not in COMMON_KEYS and key not in MODEL_KEYS[mech]:
            others = [m for m in MECHANISMS if key in MODEL_KEYS[m]]
            if others:
                raise r.fail(key, Said("sm_read_mechanism_mech", mech=mech, v=', '.join(repr(m) for m in others), v2=', '.join(sorted(MODEL_KEYS[mech]))))
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
            raise r.fail(f"task.{key}", Said("sm_table"))
    _finite(r, task, "task")
    _masses(r, task, mech)
    if "sheet" in data and not isinstance(data["sheet"], dict):
        raise r.fail("sheet", Said("sm_table"))

    def length(key: str) -> float | None:
        return r.length(data[key], key, unit, positive=True) if key in data else None

    def deg(key: str, lo: float, hi: float, what: str | Said) -> float | None:
        if key not in data:
            return None
        v = r.value(data[key], key)
        if not lo < v < hi:
            raise r.fail(key, Said("sm_what_between_lo", what=what, lo=lo, hi=hi, v=v))
        return math.radians(v)

    K = r.number(data, "K", "", default=1.0)
    if not 1.0 <= K <= 1e6:
        raise r.fail("K", Said("sm_coefficient_speed_change", K=K))
    lam = None
    if "lambda" in data:
        lam = r.value(data["lambda"], "lambda")
        if not 0 < lam < 1:
            raise r.fail("lambda", Said("sm_between_exclusive_lam", lam=lam))
    offset = None
    if "offset" in data:
        offset = r.length(data["offset"], "offset", unit)
        if offset < 0:
            raise r.fail("offset", Said("sm_offset_its_side", v=data['offset']))
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
             pressure_angle_max=deg("pressure_angle_max_deg", 0, 90, Said("sm_w_pressure")),
             mean_speed=mean_speed, rocker=length("rocker"),
             swing=deg("swing_deg", 0, 180, Said("sm_w_swing")), frame=length("frame"),
             frame_angle=deg("frame_angle_deg", 0, 180, Said("sm_w_frame_angle")),
             gamma_min=deg("gamma_min_deg", 0, 90, Said("sm_w_gamma")),
             positions=positions, centre_distance=length("centre_distance"),
             guide_height=length("guide_height"), rod=length("rod"),
             bank=deg("bank_deg", 0, 180, Said("sm_w_bank")),
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
            raise r.fail(f"task.masses.{key}", Said("sm_moving_link_number", n=n))
        if not isinstance(body, dict):
            raise r.fail(f"task.masses.{key}", Said("sm_table_mass_inertia"))
        r.keys(body, MASS_KEYS, where)
        if "centre" in body:
            c = body["centre"]
            if isinstance(c, bool) or not isinstance(c, int | float | str):
                raise r.fail(f"{where}centre", Said("sm_ratio_along_link"))
            if not isinstance(c, str) and not 0 <= c <= 1:
                raise r.fail(f"{where}centre", Said("sm_ratio_along_link2", c=c))
        if "points" in body and not isinstance(body["points"], dict):
            raise r.fail(f"{where}points", Said("sm_table_points_scene"))


def _finite(r: Reader, value: Any, where: str) -> None:
    """No NaN or infinity anywhere in what [task] carries into the scene."""
    if isinstance(value, float) and not math.isfinite(value):
        raise r.fail(where, Said("sm_finite_number_value", value=value))
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
        raise r.fail("positions", Said("sm_three_pairs_crank"))
    out = []
    for i, p in enumerate(raw):
        phi = r.value(p[0], f"positions[{i}][0]")
        psi = r.value(p[1], f"positions[{i}][1]")
        out.append((math.radians(phi), math.radians(psi)))
    return tuple(out)


def _required(r: Reader, t: Task) -> None:
    """The keys a model cannot do without, and the third conditions given one at a time."""
    def need(key: str, value: Any, what: str | Said) -> None:
        if value is None:
            raise r.fail(key, Said("sm_missing_mechanism_needs", mechanism=t.mechanism, what=what))

    def one_of(keys: tuple[str, ...]) -> None:
        given = [k for k in keys if k in t.raw]
        if len(given) > 1:
            raise r.fail(given[1], Said("sm_give_one_third", v=' or '.join(given), v2=len(given)))

    if t.mechanism in ("slider_crank", "v_engine"):
        if t.stroke is None and t.mean_speed is None:
            raise r.fail("stroke", Said("sm_missing_stroke_mean"))
        if t.mean_speed is not None and t.stroke is None and t.omega_rpm is None:
            raise r.fail("task.omega_rpm", Said("sm_missing_mean_speed"))
        if t.mean_speed is not None and t.stroke is not None and t.omega_rpm is not None:
            raise r.fail("mean_speed", Said("sm_give_two_stroke"))
        one_of(("lambda", "offset", "pressure_angle_max_deg"))
    if t.mechanism == "v_engine":
        need("lambda", t.lam, Said("sm_w_lambda"))
        need("bank_deg", t.bank, Said("sm_w_bank"))
    if t.mechanism == "crank_rocker":
        if t.positions is not None:
            for key in ("K", "swing_deg", "frame_angle_deg", "gamma_min_deg"):
                if key in t.raw:
                    raise r.fail(key, Said("sm_three_positions_fix"))
            if (t.rocker is None) == (t.frame is None):
                raise r.fail("rocker", Said("sm_three_positions_give"))
        else:
            need("rocker", t.rocker, Said("sm_w_rocker"))
            need("swing_deg", t.swing, Said("sm_w_swing"))
            one_of(("frame", "frame_angle_deg", "gamma_min_deg"))
    if t.mechanism == "coulisse":
        need("stroke", t.stroke, Said("sm_w_stroke"))
        need("centre_distance", t.centre_distance, Said("sm_w_centre"))
        if t.K <= 1.0:
            raise r.fail("K", Said("sm_coulisse_has_overlap"))
        if t.ram_group == "RPP" and t.rod is not None:
            raise r.fail("rod", Said("sm_rpp_ram_has"))
        if t.ram_group == "RRP" and t.rod is None and t.pressure_angle_max is None:
            raise r.fail("pressure_angle_max_deg", Said("sm_missing_ram_group"))
