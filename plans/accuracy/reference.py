"""High-precision reference solutions (mpmath, 50 significant digits).

The oracles the benchmark and the stability tests measure every other method
against.  Each mechanism is solved in closed form, independently of
:mod:`plans.kinematics` and :mod:`plans.construction`:

* offset slider-crank (crank OA = r about O at the origin, rod AB = l, slider B on
  the line y = e along +x):
      s = e − r sin θ,  c = √(l² − s²),  x_B = r cos θ + c,
      ω2 = (ṡ c − s ċ)/l²,  ċ = −s ṡ / c,  c̈ = −(ṡ² + s s̈ + ċ²)/c;
* four-bar (crank OA = a about O, coupler AB = b, rocker CB = c about C = (d, 0)):
      B = A + (p + i·branch·h)(C − A)/|C − A|,  p = (b² − c² + |C − A|²)/(2|C − A|),  h = √(b² − p²),
      then v and a from v_B = v_A + iω2(B − A) = iω3(B − C) by Cramer's rule;
* Scotch yoke with a skewed slot (crank OA = r; yoke sliding along x, its slot at
  angle α to the x axis):  x = r sin(α − θ)/sin α,  ẋ = −r ω cos(α − θ)/sin α, ...

``*_scene`` builds the matching :class:`~plans.scene.Scene` (SI lengths, ω in
rad/s, θ = φ measured counter-clockwise from +x), so that a test can solve the
same mechanism with every method.  Results come back as float64 numpy arrays
(``as_float``) or as mpmath numbers.
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass

import mpmath
import numpy as np

from plans.scene.model import Scene, scene_from_dict

#: Crank angles in degrees: one number, a sequence or an array.
Angles = Sequence[float] | float | np.ndarray

DPS = 50


@dataclass(frozen=True)
class Reference:
    """Reference values at each crank angle: ``points[name] = (r, v, a)`` and
    ``links[id] = (θ, ω, ε)``, each a list of mpmath numbers (mpc for plane vectors)."""

    phi_deg: tuple[float, ...]
    points: dict[str, tuple[list, list, list]]
    links: dict[int, tuple[list, list, list]]

    def point(self, name: str) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
        """r, v, a of a point as complex128 arrays."""
        return tuple(np.array([complex(z) for z in seq]) for seq in self.points[name])  # type: ignore[return-value]

    def link(self, link: int) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
        """θ, ω, ε of a link as float64 arrays."""
        return tuple(np.array([float(x) for x in seq]) for seq in self.links[link])  # type: ignore[return-value]


def _angles(phi_deg: Angles, omega: float) -> tuple[tuple[float, ...], list]:
    """Crank angles θ = sense·φ (the scene's convention with φ_ref = 0, sense = sign ω)."""
    phis = tuple(float(p) for p in np.atleast_1d(np.asarray(phi_deg, dtype=float)))
    sense = -1 if omega < 0 else 1
    with mpmath.workdps(DPS):
        return phis, [sense * mpmath.mpf(p) * mpmath.pi / 180 for p in phis]


# --------------------------------------------------------------------------- slider-crank


def slider_crank(r: float, l: float, e: float, omega: float, phi_deg: Angles,
                 eps: float = 0.0, ratio: float = 0.33) -> Reference:
    """Offset slider-crank in closed form at 50 digits.  Points O, A, B, S2 (on AB at
    ``ratio``); links 1 (crank), 2 (rod), 3 (slider)."""
    phis, thetas = _angles(phi_deg, omega)
    out_p: dict[str, tuple[list, list, list]] = {k: ([], [], []) for k in ("O", "A", "B", "S2")}
    out_l: dict[int, tuple[list, list, list]] = {k: ([], [], []) for k in (1, 2, 3)}
    with mpmath.workdps(DPS):
        R, L, E, W, Ep, rho = (mpmath.mpf(x) for x in (r, l, e, omega, eps, ratio))
        for th in thetas:
            ct, st = mpmath.cos(th), mpmath.sin(th)
            A = mpmath.mpc(R * ct, R * st)
            vA = mpmath.mpc(0, W) * A
            aA = (mpmath.mpc(0, Ep) - W**2) * A
            s = E - R * st
            s_d = -R * ct * W
            s_dd = R * st * W**2 - R * ct * Ep
            c2 = (L - s) * (L + s)
            if c2 < 0:
                raise ValueError(f"slider-crank not assemblable at {float(th * 180 / mpmath.pi)} deg")
            c = mpmath.sqrt(c2)
            c_d = -s * s_d / c
            c_dd = -(s_d**2 + s * s_dd + c_d**2) / c
            B = mpmath.mpc(R * ct + c, E)
            vB = mpmath.mpc(-R * st * W + c_d, 0)
            aB = mpmath.mpc(-R * ct * W**2 - R * st * Ep + c_dd, 0)
            th2 = mpmath.atan2(s, c)
            w2 = (s_d * c - s * c_d) / L**2
            e2 = (s_dd * c - s * c_dd) / L**2
            S = A + rho * (B - A)
            vS = vA + rho * (vB - vA)
            aS = aA + rho * (aB - aA)
            for name, triple in (("O", (mpmath.mpc(0), mpmath.mpc(0), mpmath.mpc(0))),
                                 ("A", (A, vA, aA)), ("B", (B, vB, aB)), ("S2", (S, vS, aS))):
                for k in range(3):
                    out_p[name][k].append(triple[k])
            for lid, triple in ((1, (th, W, Ep)), (2, (th2, w2, e2)), (3, (mpmath.mpf(0),) * 3)):
                for k in range(3):
                    out_l[lid][k].append(triple[k])
    return Reference(phis, out_p, out_l)


def slider_crank_scene(r: float, l: float, e: float = 0.0, omega: float = 100.0,
                       phi_deg: Angles = (45.0,), eps: float = 0.0,
                       ratio: float = 0.33, outputs: Sequence[str] | None = None) -> Scene:
    """The scene of :func:`slider_crank` (SI units, frame 4)."""
    phis = [float(p) for p in np.atleast_1d(phi_deg)]
    data = {
        "format": 1, "title": f"slider-crank r={r:g} l={l:g} e={e:g}", "unit": "m", "frame": 4,
        "points": {"O": [0.0, 0.0]},
        "links": {
            "1": {"axis": ["O", "A"], "length": r},
            "2": {"axis": ["A", "B"], "length": l, "points": {"S2": {"ratio": ratio}}},
            "3": {"axis": ["B"]},
        },
        "joints": [
            {"kind": "R", "links": [4, 1], "point": "O"},
            {"kind": "R", "links": [1, 2], "point": "A"},
            {"kind": "R", "links": [2, 3], "point": "B"},
            {"kind": "P", "links": [3, 4], "point": "B",
             "guide": {"link": 4, "through": [0.0, e], "angle_deg": 0.0}},
        ],
        "driver": _driver(omega, eps, phis),
        "outputs": list(outputs or ["positions", "velocity_plan", "acceleration_plan"]),
    }
    return scene_from_dict(data, "<slider-crank>")


def _driver(omega: float, eps: float, phis: list[float]) -> dict:
    return {"link": 1, "omega": abs(omega), "sense": "ccw" if omega >= 0 else "cw",
            "eps": eps if omega >= 0 else -eps, "phi_deg": phis}


# --------------------------------------------------------------------------- four-bar


def four_bar(a: float, b: float, c: float, d: float, omega: float, phi_deg: Angles,
             eps: float = 0.0, branch: int = 1, ratio: float = 0.5) -> Reference:
    """Four-bar O-A-B-C (O at the origin, C at (d, 0)) at 50 digits.  Points O, A, B,
    C, S2 (on AB at ``ratio``); links 1 (crank), 2 (coupler), 3 (rocker)."""
    phis, thetas = _angles(phi_deg, omega)
    out_p: dict[str, tuple[list, list, list]] = {k: ([], [], []) for k in ("O", "A", "B", "C", "S2")}
    out_l: dict[int, tuple[list, list, list]] = {k: ([], [], []) for k in (1, 2, 3)}

    def cross(u, v):
        return (mpmath.conj(u) * v).imag

    with mpmath.workdps(DPS):
        a_, b_, c_, d_, W, Ep, rho = (mpmath.mpf(x) for x in (a, b, c, d, omega, eps, ratio))
        C = mpmath.mpc(d_, 0)
        I = mpmath.mpc(0, 1)
        for th in thetas:
            A = a_ * mpmath.expj(th)
            vA = I * W * A
            aA = (I * Ep - W**2) * A
            dv = C - A
            D = abs(dv)
            p = (b_**2 - c_**2 + D**2) / (2 * D)
            h2 = (b_ - p) * (b_ + p)
            if h2 < 0:
                raise ValueError(f"four-bar not assemblable at {float(th * 180 / mpmath.pi)} deg")
            h = mpmath.sqrt(h2)
            B = A + (p + I * branch * h) * dv / D
            r1, r3 = B - A, B - C
            # vA + iω2 r1 = iω3 r3  ->  ω2 (i r1) + ω3 (−i r3) = −vA
            c1, c2 = I * r1, -I * r3
            det = cross(c1, c2)
            rhs = -vA
            w2, w3 = cross(rhs, c2) / det, cross(c1, rhs) / det
            rhs = -aA + w2**2 * r1 - w3**2 * r3
            e2, e3 = cross(rhs, c2) / det, cross(c1, rhs) / det
            vB = vA + I * w2 * r1
            aB = aA + (I * e2 - w2**2) * r1
            S = A + rho * r1
            vS = vA + I * w2 * rho * r1
            aS = aA + (I * e2 - w2**2) * rho * r1
            zero = mpmath.mpc(0)
            for name, triple in (("O", (zero, zero, zero)), ("C", (C, zero, zero)), ("A", (A, vA, aA)),
                                 ("B", (B, vB, aB)), ("S2", (S, vS, aS))):
                for k in range(3):
                    out_p[name][k].append(triple[k])
            for lid, triple in ((1, (th, W, Ep)), (2, (mpmath.arg(r1), w2, e2)),
                                (3, (mpmath.arg(r3), w3, e3))):
                for k in range(3):
                    out_l[lid][k].append(triple[k])
    return Reference(phis, out_p, out_l)


def four_bar_scene(a: float, b: float, c: float, d: float, omega: float = 100.0,
                   phi_deg: Angles = (45.0,), eps: float = 0.0, branch: int = 1,
                   ratio: float = 0.5, outputs: Sequence[str] | None = None) -> Scene:
    """The scene of :func:`four_bar` (SI units, frame 4)."""
    phis = [float(p) for p in np.atleast_1d(phi_deg)]
    data = {
        "format": 1, "title": f"four-bar {a:g}/{b:g}/{c:g}/{d:g}", "unit": "m", "frame": 4,
        "points": {"O": [0.0, 0.0], "C": [d, 0.0]},
        "links": {
            "1": {"axis": ["O", "A"], "length": a},
            "2": {"axis": ["A", "B"], "length": b, "points": {"S2": {"ratio": ratio}}},
            "3": {"axis": ["C", "B"], "length": c},
        },
        "joints": [
            {"kind": "R", "links": [4, 1], "point": "O"},
            {"kind": "R", "links": [1, 2], "point": "A"},
            {"kind": "R", "links": [2, 3], "point": "B"},
            {"kind": "R", "links": [3, 4], "point": "C"},
        ],
        "driver": _driver(omega, eps, phis),
        "branches": {"2-3": branch},
        "outputs": list(outputs or ["positions", "velocity_plan", "acceleration_plan"]),
    }
    return scene_from_dict(data, "<four-bar>")


# --------------------------------------------------------------------------- Scotch yoke


def scotch_yoke(r: float, alpha_deg: float, omega: float, phi_deg: Angles,
                eps: float = 0.0) -> Reference:
    """Yoke (link 3) sliding along the x axis, its slot through its origin at angle α;
    block 2 pinned to the crank at A slides in the slot.  Point A and the yoke's point
    K (its origin, on the x axis): x_K = r sin(α − θ)/sin α."""
    phis, thetas = _angles(phi_deg, omega)
    out_p: dict[str, tuple[list, list, list]] = {k: ([], [], []) for k in ("A", "K")}
    out_l: dict[int, tuple[list, list, list]] = {k: ([], [], []) for k in (1, 2, 3)}
    with mpmath.workdps(DPS):
        R, W, Ep = mpmath.mpf(r), mpmath.mpf(omega), mpmath.mpf(eps)
        al = mpmath.mpf(alpha_deg) * mpmath.pi / 180
        sa = mpmath.sin(al)
        I = mpmath.mpc(0, 1)
        for th in thetas:
            A = R * mpmath.expj(th)
            x = R * mpmath.sin(al - th) / sa
            xd = -R * W * mpmath.cos(al - th) / sa
            xdd = (-R * W**2 * mpmath.sin(al - th) - R * Ep * mpmath.cos(al - th)) / sa
            for name, triple in (("A", (A, I * W * A, (I * Ep - W**2) * A)),
                                 ("K", (mpmath.mpc(x), mpmath.mpc(xd), mpmath.mpc(xdd)))):
                for k in range(3):
                    out_p[name][k].append(triple[k])
            zero = mpmath.mpf(0)
            for lid, triple in ((1, (th, W, Ep)), (2, (zero, zero, zero)), (3, (zero, zero, zero))):
                for k in range(3):
                    out_l[lid][k].append(triple[k])
    return Reference(phis, out_p, out_l)


def scotch_yoke_scene(r: float, alpha_deg: float, omega: float = 100.0,
                      phi_deg: Angles = (45.0,), eps: float = 0.0,
                      outputs: Sequence[str] | None = None) -> Scene:
    """The scene of :func:`scotch_yoke`: crank + RPP group (block 2, yoke 3), frame 4."""
    phis = [float(p) for p in np.atleast_1d(phi_deg)]
    data = {
        "format": 1, "title": f"Scotch yoke r={r:g} alpha={alpha_deg:g}", "unit": "m", "frame": 4,
        "points": {"O": [0.0, 0.0]},
        "links": {
            "1": {"axis": ["O", "A"], "length": r},
            "2": {"axis": ["A"]},
            "3": {"axis": ["K"]},
        },
        "joints": [
            {"kind": "R", "links": [4, 1], "point": "O"},
            {"kind": "R", "links": [1, 2], "point": "A"},
            {"kind": "P", "links": [2, 3], "point": "A",
             "guide": {"link": 3, "through": "K", "angle_deg": alpha_deg}},
            {"kind": "P", "links": [3, 4], "point": "K",
             "guide": {"link": 4, "through": "O", "angle_deg": 0.0}},
        ],
        "driver": _driver(omega, eps, phis),
        "outputs": list(outputs or ["positions", "velocity_plan", "acceleration_plan"]),
    }
    return scene_from_dict(data, "<scotch-yoke>")


__all__ = ["DPS", "Reference", "slider_crank", "slider_crank_scene", "four_bar", "four_bar_scene",
           "scotch_yoke", "scotch_yoke_scene"]
