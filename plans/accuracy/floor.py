"""The numpy floor: the fewest complex-numpy operations that give a mechanism's exact
kinematics at many positions, written by hand for one shape of mechanism.

A crank OA and dyads hung on the crank pin A and the frame: RRR (A, rod to B, rocker about a
fixed C) and RRP (A, rod to a slider B on a fixed straight guide).  That covers the
slider-crank, the four-bar and the V-engine.  For every position it returns what the
exact analysis returns for these mechanisms: A and each B with their velocities and
accelerations, and ω, ε of every moving link.  There is no checking, no general
bookkeeping: it is the yardstick for the general solver's overhead, not a solver.
"""

from __future__ import annotations

import math
from collections.abc import Callable
from typing import Any

import numpy as np

from plans.kinematics.structure import analyse
from plans.scene.model import Scene


def floor_for(scene: Scene) -> Callable[[np.ndarray], dict[str, Any]] | None:
    """The hand-written closed form for ``scene``, or None when it is not a crank with
    RRR/RRP dyads on the crank pin and the frame."""
    st = analyse(scene)
    d = scene.driver
    frame = scene.frame
    crank = scene.links[d.link]
    if len(crank.axis) != 2:
        return None
    O = scene.frame_points[d.pivot]
    pin = crank.axis[1]
    r = crank.points[pin] - crank.points[d.pivot]  # local, on the crank's x axis
    dyads: list[tuple] = []
    for g in st.groups:
        j1, j2, j3 = g.joints
        if g.known != (d.link, frame) or j1.point != pin:
            return None
        rod = scene.links[g.links[0]]
        l1 = abs(rod.points[j2.point] - rod.points[j1.point])
        if g.kind == "RRR":
            rocker = scene.links[g.links[1]]
            C = scene.frame_points[j3.point]
            l3 = abs(rocker.points[j2.point] - rocker.points[j3.point])
            dyads.append(("RRR", j2.point, l1, l3, C, g.branch))
        elif g.kind == "RRP":
            assert j3.guide is not None
            dyads.append(("RRP", j2.point, l1, j3.guide.origin, j3.guide.direction, g.branch))
        else:
            return None
    w, e = d.omega, d.eps
    theta0 = math.degrees(d.phi_ref)
    rad = math.pi / 180.0 * d.sense
    Wr, Er = 1j * w * r, complex(-w * w, e) * r

    def solve(phi_deg: np.ndarray) -> dict[str, Any]:
        rot = np.exp(1j * rad * (phi_deg + theta0 * d.sense))
        rel = r * rot
        A = O + rel
        vA = Wr * rot
        aA = Er * rot
        out: dict[str, Any] = {"A": (A, vA, aA)}
        for kind, name, l1, x, y, b in dyads:
            if kind == "RRR":
                C, l3 = y, x
                dd = C - A
                D = np.abs(dd)
                a = (l1 * l1 - l3 * l3 + D * D) / (2 * D)
                h = np.sqrt((l1 - a) * (l1 + a))
                AB = (a + 1j * b * h) * (dd / D)
                CB = A + AB - C
                # iω2·AB − iω3·CB = −vA; the same for the accelerations
                det = (AB * CB.conjugate()).imag
                w2 = (vA * CB.conjugate()).real / det
                w3 = (vA * AB.conjugate()).real / det
                rhs = aA - w2 * w2 * AB + w3 * w3 * CB
                e2 = (rhs * CB.conjugate()).real / det
                e3 = (rhs * AB.conjugate()).real / det
                vB = 1j * w3 * CB
                aB = (1j * e3 - w3 * w3) * CB
                out[name] = (C + CB, vB, aB, w2, e2, w3, e3)
            else:
                G0, u = x, y
                cu = u.conjugate()
                p = (A - G0) * cu
                root = np.sqrt((l1 - p.imag) * (l1 + p.imag))
                B = G0 + (p.real + b * root) * u
                AB = B - A
                q = AB * cu
                w2 = -(vA * cu).imag / q.real
                e2 = (w2 * w2 * q.imag - (aA * cu).imag) / q.real
                vB = vA + 1j * w2 * AB
                aB = aA + (1j * e2 - w2 * w2) * AB
                out[name] = (B, vB, aB, w2, e2)
        return out

    return solve


def floor_point(res: dict[str, Any], name: str) -> tuple[Any, Any, Any]:
    return res[name][:3]


def check_against(scene: Scene, phis: np.ndarray, kin: Any) -> float:
    """Largest disagreement of the floor with ``kin`` over its points, relative to the crank."""
    f = floor_for(scene)
    if f is None:
        return math.nan
    res = f(phis)
    d = scene.driver
    crank = scene.links[d.link]
    size = abs(crank.points[crank.axis[1]] - crank.points[d.pivot])
    w = max(abs(d.omega), 1e-300)
    worst = 0.0
    for name, vals in res.items():
        r, v, a = kin.point(name)
        worst = max(worst, float(np.max(np.abs(vals[0] - r))) / size,
                    float(np.max(np.abs(vals[1] - v))) / (w * size),
                    float(np.max(np.abs(vals[2] - a))) / (w * w * size))
    return worst
