"""A position given by the piston's travel from its dead centre, as textbooks state it.

``[driver] s_mm = 20`` (or a list), or ``s_fraction = 0.25`` of the stroke H: the crank
angle at which the piston has travelled that far from its outer dead centre (the one
away from the crank), on the stroke toward the crank (``s_stroke = "down"``, the
default) or on the way back (``"up"``).  ``piston = 3`` names the piston when the
mechanism has several.  The angle is found where the exact travel crosses the value, by
bisection to round-off; the outer dead centre likewise, where the travel is least.
"""

from __future__ import annotations

import dataclasses
from typing import Any

import numpy as np
from numpy.typing import NDArray

from plans.errors import ConstructionError, InputError, Said
from plans.reader import Reader
from plans.scene.model import Scene
from plans.tolerances import ROUND_OFF_REL

C = NDArray[np.complex128]
R = NDArray[np.float64]

KEYS = ("s_mm", "s_fraction", "s_stroke", "piston")


def wanted(data: dict[str, Any]) -> bool:
    d = data.get("driver")
    return isinstance(d, dict) and ("s_mm" in d or "s_fraction" in d)


def toward_pivot(scene: Scene, B: C, u: C) -> C:
    """The guide's unit direction that points from the piston toward the crank pivot."""
    pivot = scene.frame_points[scene.driver.pivot]
    sgn = np.sign(((pivot - B) * np.conj(u)).real)
    return np.where(sgn < 0, -1.0, 1.0) * u


def piston_travel(scene: Scene, kin: Any, joint_name: str, link: int) -> R:
    """Signed position of the piston along its guide, increasing toward the crank pivot."""
    joint = next(j for j in scene.joints if j.name == joint_name)
    assert joint.guide is not None
    carrier = kin.motion[joint.guide.link]
    rot = carrier.rot
    origin = carrier.r0 + rot * joint.guide.origin
    u = rot * joint.guide.direction
    B = kin.point(joint.point, link)[0]
    return ((B - origin) * np.conj(toward_pivot(scene, B, u))).real


def by_travel(scene: Scene, r: Reader) -> Scene:
    """The scene with its driver's positions at the travels asked for."""
    from plans.kinematics.exact import solve

    d = scene.raw["driver"]
    if "s_mm" in d and "s_fraction" in d:
        raise r.fail("driver.s_fraction", Said("kt_give_mm_fraction"))
    for other in ("phi_deg", "positions"):
        if other in d:
            raise r.fail(f"driver.{other}", Said("kt_positions_are_given", other=other))
    key = "s_mm" if "s_mm" in d else "s_fraction"
    raw = d[key] if isinstance(d[key], list) else [d[key]]
    if not raw or len(raw) > 360:
        raise r.fail(f"driver.{key}", Said("kt_travels"))
    values = [r.value(v, f"driver.{key}", nonneg=True) for v in raw]
    stroke = r.choice(d, "s_stroke", "driver.", ("down", "up"), "down")
    pistons = [j for j in scene.joints if j.kind == "P" and j.guide is not None and j.guide.link == scene.frame]
    if "piston" in d:
        pistons = [j for j in pistons if j.slider == d["piston"] and not isinstance(d["piston"], bool)]
        if not pistons:
            raise r.fail("driver.piston", Said("kt_link_piston_sliding", v=d['piston']))
    elif len({j.slider for j in pistons}) != 1:
        raise r.fail("driver.piston" if pistons else f"driver.{key}",
                     "name the piston: piston = link number" if pistons else
                     "a position by travel needs a piston sliding on a guide of the frame")
    joint = pistons[0]
    guide = joint.guide
    assert guide is not None
    probe = dataclasses.replace(scene, driver=dataclasses.replace(scene.driver, phis_deg=(0.0,)))
    grid = np.linspace(0.0, 360.0, 721)
    try:
        t = piston_travel(probe, solve(probe, grid, order=0), joint.name, joint.slider)
        lo_k, hi_k = int(np.argmin(t[:-1])), int(np.argmax(t[:-1]))

        def travel(phis: Any) -> Any:
            return piston_travel(probe, solve(probe, np.asarray(phis, float), order=0), joint.name, joint.slider)

        def speed(phis: Any) -> Any:  # along the guide, toward the crank's pivot
            kin = solve(probe, np.asarray(phis, float), order=1)
            B, v = kin.point(joint.point, joint.slider)[:2]
            u: Any = guide.direction
            return (v * np.conj(toward_pivot(probe, B, u))).real * np.sign(probe.driver.omega)

        odc = _dead_centre(speed, grid[lo_k])
        idc = _dead_centre(speed, grid[hi_k])
        t0, H = float(travel([odc])[0]), float(travel([idc])[0]) - float(travel([odc])[0])
        a, b = (odc, idc if idc > odc else idc + 360.0) if stroke == "down" else \
            (idc, odc if odc > idc else odc + 360.0)
        want = np.array([v / 1000.0 if key == "s_mm" else v * H for v in values])
        if np.any(want > H * (1 + ROUND_OFF_REL)):
            top = H * 1000 if key == "s_mm" else 1.0
            raise r.fail(f"driver.{key}", Said("kt_travel_within_stroke", top=top, v=' mm' if key == 's_mm' else ''))
        lo, hi = np.full(len(want), a), np.full(len(want), b)
        sign = 1.0 if stroke == "down" else -1.0
        for _ in range(60):
            mid = 0.5 * (lo + hi)
            below = sign * (travel(mid) - t0 - want) < 0
            lo, hi = np.where(below, mid, lo), np.where(below, hi, mid)
    except ConstructionError as exc:
        raise InputError(Said("kt_position_piston_travel", exc=exc),
                         file=scene.path, field=f"driver.{key}") from None
    # the ends of the stroke are the dead centres themselves (the travel is flat there)
    inner, outer = (b, a) if stroke == "down" else (a, b)
    at = np.where(want >= H * (1 - ROUND_OFF_REL), inner, np.where(want <= ROUND_OFF_REL * H, outer, 0.5 * (lo + hi)))
    phis = tuple(float(x) for x in np.mod(at, 360.0))
    return dataclasses.replace(scene, driver=dataclasses.replace(scene.driver, phis_deg=phis))


def _dead_centre(speed: Any, near: float) -> float:
    """The crank angle near ``near`` (within 0.5°) where the piston's speed changes sign."""
    lo, hi = near - 0.5, near + 0.5
    f_lo = float(speed([lo])[0])
    for _ in range(60):
        mid = 0.5 * (lo + hi)
        f = float(speed([mid])[0])
        if f == 0:
            return mid % 360.0
        if (f > 0) == (f_lo > 0):
            lo, f_lo = mid, f
        else:
            hi = mid
    return float(0.5 * (lo + hi)) % 360.0
