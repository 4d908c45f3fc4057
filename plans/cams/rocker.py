"""The oscillating follower's diagram of centres: the rocker's counterpart of ds/dφ–s.

For the arm at angle θ about its pivot A (roller centre B), the relative pole P of cam and
arm lies on AO with P − A = (O − A)/(1 − r), r = k·σ·dψ/dφ (the arm's angular velocity over
the cam's).  The homothety about A that takes P back to O takes B to D = A + (1 − r)(B − A),
so OD is parallel to the normal BP: the pressure angle is the angle between OD and the
perpendicular to the arm.  Every position thus allows O in a wedge of half-angle [α] about
that perpendicular, through D on the arm's line; the region of centres is the intersection of
these half-planes.  With the pivot distance given, O lies on the circle of that radius about A
and the smallest base radius is the distance from B0 to the nearest allowed point of it.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np
import shapely
from shapely.ops import nearest_points

from .analysis import clip_half_plane, motion, oscillating_rest
from .model import Cam


@dataclass(frozen=True, slots=True)
class RockerDiagram:
    """Fixed frame (cam centre at the origin): pivot A, the arm positions B and the points D,
    the region of allowed centres (a polygon within ``box``), the minimum base radius for the
    file's pivot distance with its centre, and the best centre of any pivot distance."""

    A: tuple[float, float]
    B: np.ndarray
    D: np.ndarray
    region: list[tuple[float, float]]
    min_base_radius: float | None  # None: the pivot circle misses the region
    centre: tuple[float, float] | None
    best_base_radius: float
    best_pivot: float
    best_centre: tuple[float, float]


def points(cam: Cam, phi: np.ndarray) -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray]:
    """B, D, the unit perpendicular n to the arm (towards the cam centre) and tan [α] per angle."""
    mo = motion(cam, phi)
    th0, sig = oscillating_rest(cam)
    th = th0 + sig * mo.s
    u = np.stack([np.cos(th), np.sin(th)], axis=-1)
    A = np.array([cam.pivot, 0.0])
    B = A + cam.arm * u
    r = cam.sense * sig * mo.s1
    D = A + (1 - r)[:, None] * (B - A)
    n = np.stack([-u[:, 1], u[:, 0]], axis=-1)
    side = np.sign(np.sum((B - 0.0) * n, axis=-1))  # the cam centre O (origin) lies at −side
    n = -side[:, None] * n
    kinds = np.array([cam.phases[i].kind for i in mo.phase])
    t = np.where(kinds == "return", math.tan(cam.alpha_return), math.tan(cam.alpha_rise))
    return B, D, n, t


def region(cam: Cam, phi: np.ndarray, box: tuple[float, float, float, float]) -> list[tuple[float, float]]:
    """The allowed centres within ``box``: O with (O − D)·n·tan[α] ≥ |(O − D)·u| for every φ,
    clipping the box by each half-plane."""
    B, D, n, t = points(cam, phi)
    u = np.stack([n[:, 1], -n[:, 0]], axis=-1)
    x0, y0, x1, y1 = box
    poly = [(x0, y0), (x1, y0), (x1, y1), (x0, y1)]
    for i in range(len(phi)):
        for sgn in (1.0, -1.0):
            g = sgn * u[i] - t[i] * n[i]  # g·(O − D) ≤ 0
            c = float(g @ D[i])
            poly = clip_half_plane(poly, float(g[0]), float(g[1]), c)
            if not poly:
                return []
    return poly


def diagram(cam: Cam, phi: np.ndarray) -> RockerDiagram:
    """The construction on the angles ``phi`` (the division points as drawn, or a fine grid)."""
    B, D, _, _ = points(cam, phi)
    A = (cam.pivot, 0.0)
    reach = cam.pivot + cam.arm
    box = (-reach, -reach, cam.pivot + reach, reach)
    poly = region(cam, phi, box)
    B0 = shapely.Point(*B[0])
    if len(poly) < 3:
        return RockerDiagram(A, B, D, [], None, None, 0.0, 0.0, (0.0, 0.0))
    shape = shapely.Polygon(poly)
    circle = shapely.Point(*A).buffer(cam.pivot, quad_segs=2048).exterior
    on = shape.intersection(circle)
    centre: tuple[float, float] | None = None
    r_min: float | None = None
    if not on.is_empty:
        near = nearest_points(on, B0)[0]
        centre = (near.x, near.y)
        r_min = math.hypot(near.x - B[0, 0], near.y - B[0, 1])
    best = nearest_points(shape, B0)[0]
    best_c = (best.x, best.y)
    return RockerDiagram(A, B, D, poly, r_min, centre, math.hypot(best.x - B[0, 0], best.y - B[0, 1]),
                         math.hypot(best.x - A[0], best.y - A[1]), best_c)
