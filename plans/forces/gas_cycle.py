"""The gas force's cycle: the working cycle's length, a diagram over the cycle read from its
table, the crank angle within the cycle, a four-stroke cylinder's ignition, the piston's
outer dead centre and stroke over a revolution, and a gas force given by its pressure table."""

from __future__ import annotations

import math
from typing import Any

import numpy as np

from plans.errors import ConstructionError, InputError, Said
from plans.forces.load_records import AppliedForce, GasLoad, R, local_at, mechanism_extent
from plans.kinematics.travel import piston_travel, toward_pivot
from plans.reader import Reader
from plans.scene.model import Scene
from plans.units import DUST

FOUR_STROKES = ("intake", "compression", "expansion", "exhaust")


def cycle_of(scene: Scene) -> float:
    """The working cycle in crank degrees: 720 when ``[dynamics] cycle_deg = 720``, else 360
    (the dynamics' reader checks the value itself)."""
    dyn = scene.raw.get("dynamics")
    return 720.0 if isinstance(dyn, dict) and dyn.get("cycle_deg") == 720 else 360.0


def cycle_table(r: Reader, rows: Any, field: str, what: str, scale: float = 1.0) -> tuple[R, R]:
    """A diagram over the cycle's crank angle: rows [φ deg, value] from 0 to 360 or 720."""
    if not (isinstance(rows, list) and len(rows) >= 2 and all(isinstance(x, list) and len(x) == 2 for x in rows)):
        raise r.fail(field, Said("gc_least_two_rows", what=what))
    phi = np.array([r.value(x[0], field) for x in rows])
    val = np.array([r.value(x[1], field) for x in rows]) * scale
    if np.any(np.diff(phi) <= 0):
        raise r.fail(field, Said("gc_crank_angles_increasing"))
    if phi[0] != 0 or phi[-1] not in (360.0, 720.0):
        raise r.fail(field, Said("gc_table_covers_whole", v=phi[0], v2=phi[-1]))
    return phi, val


def pressure_force(scene: Scene, r: Reader, body: dict[str, Any], where: str, k: int, moving_link: Any,
                    length: Any) -> GasLoad:
    """``[[loads.force]]`` given by its pressure over the cycle's crank angle: a gas force on a
    piston, along its guide toward the crank, F = p(φ)·A."""
    for key in ("vector", "magnitude", "angle_deg", "resisting", "along", "stroke"):
        if key in body:
            raise r.fail(f"{where}{key}", Said("gc_force_pressure_table"))
    if "pressure_table" not in body:
        raise r.fail(f"{where}pressure_table", Said("gc_pressure_table_phi"))
    if ("area" in body) == ("bore" in body):
        raise r.fail(f"{where}area", Said("gc_piston_area_its"))
    lid = moving_link(body, where)
    pj = [j for j in scene.joints if j.kind == "P" and j.guide is not None and j.slider == lid]
    if len(pj) != 1:
        raise r.fail(f"{where}link", Said("gc_link_lid_piston", lid=lid))
    if "point" in body and body["point"] != pj[0].point:
        raise r.fail(f"{where}point", Said("gc_pressure_acts_piston", point=pj[0].point))
    if "area" in body:
        area = r.number(body, "area", where, positive=True)
    else:
        area = math.pi * length(body["bore"], f"{where}bore") ** 2 / 4
    tab = cycle_table(r, body["pressure_table"], f"{where}pressure_table", "p_Pa")
    return GasLoad(link=lid, joint=pj[0].name, area=area, pressure=None, diagram={}, strokes=("down", "up"),
                   toward_pivot=True, name=r.name(body.get("name", f"P{lid}"), f"{where}name"),
                   phi_table=tab, period=float(tab[0][-1]))


def cycle_phase(scene: Scene, kin: Any, period: float) -> R:
    """The crank angle within the cycle, 0 <= φ < period (deg)."""
    return np.mod(np.asarray(kin.phi_deg, float), period)


def ignition(scene: Scene, gl: GasLoad) -> float:
    """The crank angle (deg) of a four-stroke cylinder's ignition: the piston's outer dead
    centre nearest to ``fires_deg``, found where its velocity along the guide turns toward
    the crank (to round-off)."""
    from plans.kinematics.exact import solve  # late import: only four-stroke diagrams need it

    assert gl.fires is not None
    joint = next(j for j in scene.joints if j.name == gl.joint)
    guide = joint.guide
    assert guide is not None
    z = scene.links[gl.link].points[joint.point]

    def speed(at: Any) -> R:  # the piston's velocity toward the crank's pivot (its travel's rate)
        kin = solve(scene, np.asarray(at, float), order=1)
        r, v, _ = kin.point_on(gl.link, z)
        u: Any = guide.direction if guide.link == scene.frame else kin.motion[guide.link].rot * guide.direction
        return (v * np.conj(toward_pivot(scene, r, u))).real * np.sign(scene.driver.omega)

    phis = gl.fires + np.linspace(-180.0, 180.0, 361)
    try:
        t = piston_travel(scene, solve(scene, phis, order=0), gl.joint, gl.link)
        k = int(np.argmin(t))
        lo, hi = float(phis[max(k - 1, 0)]), float(phis[min(k + 1, 360)])
        for _ in range(8):  # 64 samples a step: the bracket where the travel turns shrinks 64 times
            grid = np.linspace(lo, hi, 65)
            up = speed(grid) > 0
            j = int(np.argmax(up)) if np.any(up) and not up[0] else 0
            if j == 0:
                break
            lo, hi = float(grid[j - 1]), float(grid[j])
            if hi - lo < 1e-13:
                break
    except ConstructionError as exc:
        raise InputError(Said("gc_four_stroke_diagram", exc=exc),
                         file=scene.path, field="loads.gas") from None
    return 0.5 * (lo + hi)


def piston_stroke(scene: Scene, joint_name: str, link: int) -> tuple[float, float]:
    """The piston's outer dead centre (travel coordinate) and stroke H over one crank
    revolution, by dense sampling of the exact positions (relative error ~1e-7)."""
    from plans.kinematics.exact import solve  # late import: only indicator diagrams need it

    grid = np.linspace(0.0, 360.0, 3601)  # the extremes are those of this 0.1° grid
    try:
        # every tenth grid angle first, then the grid around the coarse extremes only
        coarse = np.arange(0, 3601, 10)
        t = piston_travel(scene, solve(scene, grid[coarse], order=0), joint_name, link)
        keep = np.zeros(3601, dtype=bool)  # the grid around the extremes, each index once, in order
        keep[[0, 3600]] = True
        for k in extreme_indices(t):
            keep[(coarse[k] + np.arange(-10, 11)) % 3600] = True
        near = np.flatnonzero(keep)
        kin = solve(scene, grid[near], order=0)
    except ConstructionError as exc:
        raise InputError(Said("gc_indicator_diagram_needs", exc=exc),
                         file=scene.path, field="loads.gas") from None
    travel = piston_travel(scene, kin, joint_name, link)
    return float(travel.min()), float(travel.max() - travel.min())


def extreme_indices(t: R) -> list[int]:
    """The coarse samples near which a finer sample may beat the coarse extremes: between
    two samples a smooth travel rises at most (largest second difference)/8 above them;
    every sample within the whole second difference of an extreme is kept (a flat dwell
    keeps many)."""
    slack = float(np.max(np.abs(t[2:] - 2 * t[1:-1] + t[:-2])))
    return [int(k) for k in np.flatnonzero((t <= t.min() + slack) | (t >= t.max() - slack))]


# --------------------------------------------------------------------------- the gas force at the positions


def gas_force(scene: Scene, kin: Any, gl: GasLoad) -> AppliedForce:
    joint = next(j for j in scene.joints if j.name == gl.joint)
    assert joint.guide is not None
    z = scene.links[gl.link].points[joint.point]
    r, v, a = kin.point_on(gl.link, z)
    u: Any
    if joint.guide.link == scene.frame:  # the same direction at every position
        u = joint.guide.direction
    else:
        u = kin.motion[joint.guide.link].rot * joint.guide.direction
    e_down = toward_pivot(scene, r, u)
    # stroke: the sign of the piston's velocity toward the pivot; at a dead centre (v = 0)
    # the acceleration says which stroke begins
    ce = np.conj(e_down)
    vd = (v * ce).real
    ad = (a * ce).real if a is not None else np.zeros_like(vd)
    # zero up to round-off against the mechanism's own speed (ω × its reach), not against the
    # positions asked for: a dead centre solved alone gives the same stroke as in the whole turn
    moving = np.abs(vd) > DUST * abs(scene.driver.omega) * mechanism_extent(kin)
    down = np.where(moving, vd > 0, ad >= 0)
    p: Any
    if gl.phi_table is not None:
        p = np.interp(cycle_phase(scene, kin, gl.period), gl.phi_table[0], gl.phi_table[1])
    elif gl.fires is not None:
        p = four_stroke(scene, kin, gl, down)
    elif gl.pressure is not None:
        p = gl.pressure  # the same at every position
    else:
        # travel from the outer dead centre (the extreme position away from the pivot)
        s = np.clip(piston_travel(scene, kin, gl.joint, gl.link) - gl.outer, 0.0, gl.stroke)
        p = np.zeros(kin.n)
        for side, mask in (("down", down), ("up", ~down)):
            if side in gl.diagram:
                ts, ps = gl.diagram[side]
                p = np.where(mask, np.interp(s, ts, ps), p)
    if gl.fires is not None or gl.phi_table is not None:
        active = np.ones(kin.n, dtype=bool)  # the diagram says the pressure on every stroke
    elif "down" in gl.strokes:
        active = np.ones(kin.n, dtype=bool) if "up" in gl.strokes else down
    else:
        active = ~down if "up" in gl.strokes else np.zeros(kin.n, dtype=bool)
    direction = e_down if gl.toward_pivot else -e_down
    F = np.where(active, p * gl.area, 0.0) * direction
    return AppliedForce(gl.name, gl.link, joint.point, r, local_at(kin.n, z), F, "gas")



def stroke_index(scene: Scene, kin: Any, gl: GasLoad, down: Any) -> Any:
    """Which of the four strokes each position is in (0 intake, 1 compression, 2 expansion,
    3 exhaust): the revolution after the ignition's outer dead centre is expansion (toward
    the crank) then exhaust, the next intake then compression."""
    assert gl.ignition is not None, "a four-stroke load's ignition is found when the loads are read"
    psi = np.mod(np.asarray(kin.phi_deg, float) - gl.ignition, 720.0)
    # a dead centre met to round-off is the one the angle names: 360 begins the intake, 720 the expansion
    psi = np.where(np.abs(psi - 360.0) < 1e-7, 360.0, np.where(psi > 720.0 - 1e-7, 0.0, psi))
    first = psi < 360.0
    return np.where(first, np.where(down, 2, 3), np.where(down, 0, 1))


def four_stroke(scene: Scene, kin: Any, gl: GasLoad, down: Any) -> R:
    s = np.clip(piston_travel(scene, kin, gl.joint, gl.link) - gl.outer, 0.0, gl.stroke)
    k = stroke_index(scene, kin, gl, down)
    p = np.zeros(kin.n)
    for j, name in enumerate(FOUR_STROKES):
        ts, ps = gl.diagram[name]
        p = np.where(k == j, np.interp(s, ts, ps), p)
    return p
