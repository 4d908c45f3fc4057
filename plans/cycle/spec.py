"""``[dynamics]`` and ``[diagrams]``: what a scene asks of the cycle.

.. code-block:: toml

    outputs = ["dynamics", "diagrams"]

    [dynamics]
    rotor_inertia = 2.06     # kg·m², the rotor's own inertia at the crank (I_A)
    delta = 0.05             # coefficient of fluctuation δ = (ω_max − ω_min)/ω_m
    driving = "constant"     # the driving moment: constant, from the cycle's work balance,
                             # or a number (N·m, in the crank's sense) that must balance it
    positions = 12           # or phi_deg = [...] (extra positions such as the dead centres)
    pole_mm = 40             # pole distance H of the graphical integration (default: chosen)
    exact_steps = 3600       # steps of the exact integration per revolution
    cycle_deg = 720          # the working cycle: 360 (default) or 720 (a four-stroke engine)

    [diagrams]
    points = ["B"]           # s along the guide (a slider) or the path (any other point)
    s_from = "extreme"       # a slider's s from its extreme position, s >= 0 (default); or
                             # "first": signed along the guide from the first position
    links = [2]              # and/or angles of links
    quantities = ["s", "v", "a"]
    positions = 12           # equal steps over the revolution
    method = "chords"        # or "tangents"
    pole_mm = 30             # H of the differentiation (default: chosen for ~50 mm ordinates)
    length_mm = 240          # the φ axis of one revolution
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Any

from plans.errors import InputError, Said
from plans.reader import Reader, show
from plans.scene.model import Scene
from plans.tolerances import SAME_ANGLE_DEG

#: The widest step between the positions of a cycle (the graphical integration needs the
#: whole revolution, drawn by chords no longer than this).
MAX_STEP_DEG = 90.0
#: The most positions of a cycle (one every 0.1°).
MAX_POSITIONS = 3600
#: Positions closer than this are one position; angles beyond ANGLE_LIMIT_DEG are not a crank's.
MIN_STEP_DEG = 1e-3
DELTA_FLOOR = 1e-6
ANGLE_LIMIT_DEG = 1e6


@dataclass(frozen=True, slots=True)
class DynamicsSpec:
    rotor_inertia: float
    delta: float
    driving: float | None  # None: constant, from the work balance
    phi_deg: tuple[float, ...]  # the table's positions (closing 360° added by the method)
    pole_mm: float | None
    exact_steps: int  # over the whole cycle
    cycle_deg: float = 360.0


@dataclass(frozen=True, slots=True)
class DiagramsSpec:
    points: tuple[str, ...]
    links: tuple[int, ...]
    quantities: tuple[str, ...]
    phi_deg: tuple[float, ...]  # equal steps, first = phi0, without the closing 360°
    method: str
    pole_mm: float | None
    length_mm: float
    s_from: str = "extreme"  # a slider's s: from its extreme ("extreme") or the first position ("first")


_DYN_KEYS = {"rotor_inertia", "delta", "driving", "positions", "phi_deg", "pole_mm", "exact_steps", "cycle_deg"}
CYCLES = (360, 720)
_DIA_KEYS = {"points", "links", "quantities", "positions", "phi_deg", "method", "pole_mm", "length_mm", "s_from"}
QUANTITIES = ("s", "v", "a")
METHODS = ("chords", "tangents")


def _fail(scene: Scene, field: str, msg: str | Said) -> InputError:
    return InputError(msg, file=scene.path, field=field)


def _table(scene: Scene, key: str, known: set[str]) -> dict[str, Any]:
    raw = scene.raw.get(key, {})
    if not isinstance(raw, dict):
        raise _fail(scene, key, Said("cs_table", k=key))
    for k in raw:
        if k not in known:
            raise _fail(scene, f"{key}.{k}", Said("cs_unknown_key_some", v=sorted(known)))
    return raw


def _number(scene: Scene, raw: dict[str, Any], key: str, where: str, floor: float | None = None) -> float:
    """A number by the reader's rule (``floor=0`` where the caller checks a range of its own)."""
    return Reader(scene.path).value(raw[key], f"{where}.{key}", floor=floor)


def _positions(scene: Scene, raw: dict[str, Any], where: str, *, equal: bool,
               cycle: float = 360.0) -> tuple[float, ...]:
    """The positions of a cycle: ``positions = N`` equal steps from the driver's first angle, or
    ``phi_deg = [...]`` increasing within one cycle (one revolution or two) with no step over
    MAX_STEP_DEG."""
    phi0 = scene.driver.phis_deg[0] if scene.driver.phis_deg else 0.0
    if "positions" in raw and "phi_deg" in raw:
        raise _fail(scene, f"{where}.phi_deg", Said("cs_give_positions_phi"))
    if "phi_deg" in raw:
        vals = raw["phi_deg"]
        if not (isinstance(vals, list) and 4 <= len(vals) <= MAX_POSITIONS):
            raise _fail(scene, f"{where}.phi_deg", Said("cs_max_positions_crank", MAX_POSITIONS=MAX_POSITIONS))
        rd = Reader(scene.path)
        phis = [rd.value(v, f"{where}.phi_deg", limit=ANGLE_LIMIT_DEG, floor=0.0) for v in vals]
        # Closer positions than MIN_STEP_DEG make the curve's chord slopes 0/0.
        if any(b - a < MIN_STEP_DEG for a, b in zip(phis, phis[1:], strict=False)):
            raise _fail(scene, f"{where}.phi_deg", Said("cs_crank_angles_increasing", MIN_STEP_DEG=MIN_STEP_DEG))
        if abs(phis[-1] - phis[0] - cycle) < SAME_ANGLE_DEG:
            phis = phis[:-1]  # the closing position is the first one again
        span = phis[-1] - phis[0]
        gap = max([b - a for a, b in zip(phis, phis[1:], strict=False)] + [cycle - span])
        if span >= cycle or gap > MAX_STEP_DEG + SAME_ANGLE_DEG:
            within = "one revolution" if cycle == 360 else f"one cycle of {cycle:g}°"
            raise _fail(scene, f"{where}.phi_deg",
                        Said("cs_positions_do_close", within=within, v=phis[0], v2=phis[0] + cycle, MAX_STEP_DEG=MAX_STEP_DEG, gap=gap))
        if equal:
            closed = phis + [phis[0] + cycle]
            steps = [b - a for a, b in zip(closed, closed[1:], strict=False)]
            if max(steps) - min(steps) > 1e-6:
                raise _fail(scene, f"{where}.phi_deg",
                            Said("cs_diagram_does_cover"))
        return tuple(phis)
    n = raw.get("positions", round(12 * cycle / 360))
    least = max(4, math.ceil(cycle / MAX_STEP_DEG))
    if isinstance(n, bool) or not isinstance(n, int) or n < least or n > MAX_POSITIONS:
        raise _fail(scene, f"{where}.positions", Said("cs_whole_number_positions", least=least, MAX_POSITIONS=MAX_POSITIONS, got=show(n)))
    return tuple(phi0 + cycle * k / n for k in range(n))


def rotor_inertia(scene: Scene) -> float:
    """The rotor's own inertia at the crank (``[dynamics] rotor_inertia``, 0 when absent),
    read on its own for a check file that needs no flywheel."""
    raw = _table(scene, "dynamics", _DYN_KEYS)
    rotor = _number(scene, raw, "rotor_inertia", "dynamics") if "rotor_inertia" in raw else 0.0
    if rotor < 0:
        raise _fail(scene, "dynamics.rotor_inertia", Said("cs_moment_inertia_kg", rotor=rotor))
    return rotor


def dynamics_spec(scene: Scene) -> DynamicsSpec:
    raw = _table(scene, "dynamics", _DYN_KEYS)
    where = "dynamics"
    if "delta" not in raw:
        raise _fail(scene, "dynamics.delta", Said("cs_missing_coefficient_fluctuation"))
    delta = _number(scene, raw, "delta", where, floor=0.0)
    # Below DELTA_FLOOR ω_max² − ω_min² is lost to round-off (and no flywheel is that uniform).
    if not DELTA_FLOOR <= delta < 1.0:
        raise _fail(scene, "dynamics.delta", Said("cs_delta_floor_delta", DELTA_FLOOR=DELTA_FLOOR, delta=delta))
    rotor = rotor_inertia(scene)
    driving: float | None = None
    d = raw.get("driving", "constant")
    if isinstance(d, str):
        if d != "constant":
            raise _fail(scene, "dynamics.driving", Said("cs_constant_moment", got=show(d)))
    else:
        driving = _number(scene, raw, "driving", where)
    pole = None
    if "pole_mm" in raw:
        pole = _number(scene, raw, "pole_mm", where)
        if pole <= 0:
            raise _fail(scene, "dynamics.pole_mm", Said("cs_positive_pole_distance", pole=pole))
    steps = raw.get("exact_steps", 3600)
    if isinstance(steps, bool) or not isinstance(steps, int) or not 360 <= steps <= 200000:
        raise _fail(scene, "dynamics.exact_steps", Said("cs_whole_number_from", got=show(steps)))
    cycle = raw.get("cycle_deg", 360)
    if isinstance(cycle, bool) or cycle not in CYCLES:
        raise _fail(scene, "dynamics.cycle_deg", Said("cs_one_revolution_four", got=show(cycle)))
    if scene.driver.omega == 0:
        raise _fail(scene, "driver.omega", Said("cs_dynamics_needs_mean"))
    phis = _positions(scene, raw, where, equal=False, cycle=float(cycle))
    return DynamicsSpec(rotor, delta, driving, phis, pole, steps * int(cycle) // 360, float(cycle))


def diagrams_spec(scene: Scene) -> DiagramsSpec:
    raw = _table(scene, "diagrams", _DIA_KEYS)
    pts = raw.get("points", [])
    if not (isinstance(pts, list) and all(isinstance(p, str) for p in pts)):
        raise _fail(scene, "diagrams.points", Said("cs_list_point_names"))
    known = {n for link in scene.links.values() for n in link.points}
    for p in pts:
        if p not in known:
            raise _fail(scene, "diagrams.points", Said("cs_unknown_point_one", p=p, v=sorted(known)))
    links = raw.get("links", [])
    if not (isinstance(links, list) and all(isinstance(x, int) and not isinstance(x, bool) for x in links)):
        raise _fail(scene, "diagrams.links", Said("cs_list_link_numbers"))
    for lid in links:
        if lid not in scene.links:
            raise _fail(scene, "diagrams.links", Said("cs_unknown_link_lid", lid=lid, v=sorted(scene.links)))
    if not pts and not links:
        raise _fail(scene, "diagrams.points", Said("cs_least_one_point"))
    qs = raw.get("quantities", list(QUANTITIES))
    if not (isinstance(qs, list) and qs and all(q in QUANTITIES for q in qs)):
        raise _fail(scene, "diagrams.quantities", Said("cs_some", v=list(QUANTITIES), got=show(qs)))
    method = raw.get("method", "chords")
    if method not in METHODS:
        raise _fail(scene, "diagrams.method", Said("gm_one", v=list(METHODS), got=show(method)))
    pole = None
    if "pole_mm" in raw:
        pole = _number(scene, raw, "pole_mm", "diagrams")
        if pole <= 0:
            raise _fail(scene, "diagrams.pole_mm", Said("cs_positive_pole_distance", pole=pole))
    length = _number(scene, raw, "length_mm", "diagrams", floor=0.0) if "length_mm" in raw else 240.0
    if not 60.0 <= length <= 700.0:
        raise _fail(scene, "diagrams.length_mm", Said("cs_axis_from_mm", length=length))
    if scene.driver.omega == 0:
        raise _fail(scene, "driver.omega", Said("cs_need_crank_angular"))
    phis = _positions(scene, raw, "diagrams", equal=True)
    s_from = raw.get("s_from", "extreme")
    if s_from not in ("extreme", "first"):
        raise _fail(scene, "diagrams.s_from", Said("cs_extreme_first", got=show(s_from)))
    return DiagramsSpec(tuple(pts), tuple(links), tuple(q for q in QUANTITIES if q in qs), phis, method,
                        pole, length, s_from)


def check_table(scene: Scene, key: str) -> None:
    """``[dynamics]`` or ``[diagrams]`` given where the scene does not ask for it: its keys
    checked all the same (a misspelt key fails as it would where it is used)."""
    _table(scene, key, _DYN_KEYS if key == "dynamics" else _DIA_KEYS)


def output_diagrams_spec(scene: Scene, length_mm: float = 240.0) -> DiagramsSpec | None:
    """The kinematic diagrams a course's kinematics sheet draws when the scene has no
    ``[diagrams]`` of its own: s, v, a of the output (:func:`plans.kinematics.extreme.output_of`,
    a slider's pin, or a rocker's angle φ, ω, ε), by chords, over the 12 positions of a
    revolution from the driver's first angle; None where the scene has no such output or its
    crank stands still."""
    from plans.kinematics.extreme import output_of

    if scene.driver.omega == 0:
        return None
    try:
        out = output_of(scene)
    except InputError:
        return None  # no slider or rocker on the frame: no output to draw
    pts, links = ((out.point,), ()) if out.kind == "slider" else ((), (out.link,))
    return DiagramsSpec(pts, links, QUANTITIES, _positions(scene, {}, "diagrams", equal=True), "chords", None,
                        length_mm)
