"""Kinematic diagrams s(φ), v(φ), a(φ) over the cycle, by graphical differentiation and
integration, beside the exact curves.

s(φ) of a slider on a guide of the frame is its distance from its extreme position where
its working stroke begins (the slower stroke; the outer dead centre where both take equal
time), s ≥ 0, v and a along the same direction, as the course measures it
(``[diagrams] s_from = "first"``: the signed displacement along the guide from the first
position instead); of any other point, the length of its path travelled since the first
position; of a link, its angle turned.  The diagram is drawn at μ_s (mm per m) against μ_φ = L/2π (mm
per rad of crank angle).

Differentiation by chords: on each interval the chord of s(φ) is carried parallel through
a pole at H mm from the origin; its ordinate H·Δy/Δx is ds/dφ at the middle of the
interval, so v(φ) = ω1 ds/dφ is drawn at μ_v = μ_s·H/(μ_φ·ω1); a(φ) follows from v(φ)
the same way, μ_a = μ_v·H/(μ_φ·ω1).  The tangent method carries the tangent at a node
instead (drawn as the chord of the two neighbours, parallel to it).  Each differentiation
errs by O(Δφ²); the error is reported in % of the exact diagram's range.

Integration by chords is the reverse: the mean ordinate of each interval of a(φ) gives
the slope of the chord of v(φ), chained from the known value at the first position.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np
from numpy.typing import NDArray

from plans.kinematics.construction import nice_scale
from plans.kinematics.exact import Kinematics, solve
from plans.scene.model import Scene

from . import spline
from .spec import DiagramsSpec, diagrams_spec

R = NDArray[np.float64]

_POLES = (5.0, 8.0, 10.0, 12.0, 15.0, 20.0, 25.0, 30.0, 40.0, 50.0, 60.0, 80.0, 100.0)
EXACT_PER_STEP = 30  # exact samples per interval of the diagram (thin exact curves)


@dataclass(frozen=True, slots=True)
class Diagram:
    """One diagram as drawn, and the exact curve beside it (arrays over crank angle)."""

    subject: str  # point name ("B") or link ("2")
    quantity: str  # "s" | "v" | "a"
    name: str  # "s_B", "v_B", "a_B"; "φ_2", "ω_2", "ε_2" for a link
    unit: str
    phi_deg: R  # abscissae of the graphical values
    values: R  # graphical (SI)
    exact_phi_deg: R
    exact: R
    scale: float  # μ, mm per unit
    scale_formula: str  # how the course writes it
    pole_mm: float | None  # H of the differentiation that produced it
    error_max_pct: float  # of the exact diagram's range
    error_rms_pct: float
    integral: R | None = None  # this quantity by graphical integration of the next (at the nodes)
    integral_error_max_pct: float | None = None


@dataclass(frozen=True, slots=True)
class Diagrams:
    spec: DiagramsSpec
    omega: float  # |ω1|, rad/s
    mu_phi: float  # mm per rad
    pole_mm: float  # H_1, of the differentiation of s into v
    pole2_mm: float  # H_2, of v into a
    nodes_deg: R  # the positions, closing one included
    diagrams: tuple[Diagram, ...]

    def get(self, name: str) -> Diagram:
        for d in self.diagrams:
            if d.name == name:
                return d
        raise KeyError(name)


def _errors(phi_deg: R, values: R, ex_phi: R, ex: R) -> tuple[float, float]:
    ref = np.interp(phi_deg, ex_phi, ex)
    rng = float(np.ptp(ex)) or max(float(np.max(np.abs(ex))), 1e-300)
    err = np.abs(values - ref)
    return 100 * float(np.max(err)) / rng, 100 * float(np.sqrt(np.mean(err**2))) / rng


def _along(scene: Scene, name: str) -> complex | None:
    """The direction of the frame's guide a point slides on (None: not a slider on the frame)."""
    for jt in scene.joints:
        if jt.kind == "P" and jt.guide is not None and jt.guide.link == scene.frame and jt.point == name:
            return jt.guide.direction
    return None


def _motion(scene: Scene, kin: Kinematics, subject: str, is_link: bool, w: float,
            s_from: str = "first") -> tuple[R, R, R, str]:
    """s, v, a (SI) of a subject at the positions of ``kin`` (dense, closing node last)."""
    if is_link:
        lid = int(subject)
        th = np.unwrap(kin.theta(lid))
        return th - th[0], kin.omega(lid), kin.eps(lid), "rad"
    r, v, a = kin.point(subject)
    u = _along(scene, subject)
    if u is not None and s_from == "extreme":
        from plans.kinematics.extreme import slider, strokes

        out = slider(scene, subject)
        assert out is not None
        st = strokes(scene, "diagrams.s_from", output=out)
        u = u if st.working_up else -u  # s grows into the working stroke
        r0 = solve(scene, [st.working_deg], order=0).point(out.point, out.link)[0][0]
        return (np.maximum(((r - r0) * np.conj(u)).real, 0.0), (v * np.conj(u)).real, (a * np.conj(u)).real, "m")
    if u is not None:
        return (((r - r[0]) * np.conj(u)).real, (v * np.conj(u)).real, (a * np.conj(u)).real, "m")
    speed = np.abs(v)
    s = np.zeros(len(r))
    s[1:] = np.cumsum(0.5 * (speed[1:] + speed[:-1]) * np.diff(np.radians(kin.phi_deg))) / w
    tang = np.where(speed > 0, (a * np.conj(v)).real / np.where(speed > 0, speed, 1.0), 0.0)
    return s, speed, tang, "m"


def _pole(mu_y: float, mu_phi: float, w: float, top: float, target: float = 45.0) -> float:
    """The H that draws the derivative's largest ordinate near ``target`` mm."""
    if top <= 0:
        return 40.0
    want = target * mu_phi * w / (mu_y * top)
    best = _POLES[0]
    for H in _POLES:
        if H <= want:
            best = H
    return best


def _differentiate(phi: R, y: R, method: str, periodic_slope: float) -> tuple[R, R]:
    """dy/dφ by chords (at the middles) or tangents (at the nodes); closed cycle (last = first + Δ)."""
    h = np.diff(phi)
    if method == "chords":
        return 0.5 * (phi[1:] + phi[:-1]), np.diff(y) / h
    ext = np.concatenate([[y[-2] - periodic_slope], y, [y[1] + periodic_slope]])
    d = (ext[2:] - ext[:-2]) / (2 * h[0])
    return phi, d


@dataclass(frozen=True, slots=True)
class Motions:
    """The exact motion (s, v, a and the unit of s) of every subject of a diagrams' spec over
    its dense grid of crank angles: what no φ axis, pole or scale changes."""

    dense_deg: R  # EXACT_PER_STEP samples per interval, the closing node last
    motions: tuple[tuple[R, R, R, str], ...]  # in the order of the subjects (points, then links)


def motion_key(spec: DiagramsSpec) -> tuple[object, ...]:
    """What :func:`exact_motions` reads of ``spec``: diagrams of equal keys share one."""
    return spec.points, spec.links, spec.phi_deg, spec.s_from


def _subjects(spec: DiagramsSpec) -> list[tuple[str, bool]]:
    return [(p, False) for p in spec.points] + [(str(k), True) for k in spec.links]


def exact_motions(scene: Scene, spec: DiagramsSpec) -> Motions:
    """The exact analysis (to accelerations) over the dense grid of ``spec``'s revolution, and
    every subject's s, v, a read off it."""
    n = len(spec.phi_deg)
    phi0 = spec.phi_deg[0]
    dense = phi0 + 360.0 * np.arange(n * EXACT_PER_STEP + 1) / (n * EXACT_PER_STEP)
    kin = solve(scene, dense, order=2)
    w = abs(scene.driver.omega)
    return Motions(dense, tuple(_motion(scene, kin, s, is_link, w, spec.s_from) for s, is_link in _subjects(spec)))


def diagrams(scene: Scene, spec: DiagramsSpec | None = None, exact: Motions | None = None) -> Diagrams:
    """s, v, a diagrams of every subject of ``[diagrams]`` (or of ``spec``), drawn off
    ``exact`` (:func:`exact_motions` of a spec of the same :func:`motion_key`; default: solved
    here)."""
    spec = spec or diagrams_spec(scene)
    w = abs(scene.driver.omega)
    n = len(spec.phi_deg)
    phi0 = spec.phi_deg[0]
    nodes = phi0 + 360.0 * np.arange(n + 1) / n
    exact = exact or exact_motions(scene, spec)
    dense, motions = exact.dense_deg, list(exact.motions)
    mu_phi = spec.length_mm / (2 * math.pi)
    subjects = _subjects(spec)
    # one pole per differentiation for the sheet (H1 for v, H2 for a): what the fastest subject needs
    H1, H2 = spec.pole_mm, spec.pole_mm
    if H1 is None or H2 is None:
        h1s, h2s = [], []
        for (s_e, v_e, a_e, _) in motions:
            mu_s = nice_scale(float(np.ptp(s_e)) or 1.0, 50.0)
            h1 = _pole(mu_s, mu_phi, w, float(np.max(np.abs(v_e))))
            mu_v = mu_s * h1 / (mu_phi * w)
            h1s.append(h1)
            h2s.append(_pole(mu_v, mu_phi, w, float(np.max(np.abs(a_e)))))
        H1, H2 = min(h1s), min(h2s)
    out: list[Diagram] = []
    step = EXACT_PER_STEP
    for (subject, is_link), (s_e, v_e, a_e, unit) in zip(subjects, motions, strict=True):
        s_nodes = s_e[::step]
        rad = np.radians(nodes - phi0)
        mu_s = nice_scale(float(np.ptp(s_e)) or 1.0, 50.0)
        total = float(s_nodes[-1] - s_nodes[0])  # s gained per revolution (a path's length)
        names = ("φ", "ω", "ε") if is_link else ("s", "v", "a")
        units = (unit, "rad/s", "rad/s^2") if is_link else ("m", "m/s", "m/s^2")
        phi_v, dv = _differentiate(rad, s_nodes, spec.method, total)
        v_g = w * dv
        mu_v = mu_s * H1 / (mu_phi * w)
        if spec.method == "chords":
            # chords of v(φ), whose values sit at the middles: the middles of the middles are the
            # nodes 1..n, the first node is the last again
            v_closed = np.append(v_g, v_g[0])
            mid = np.append(phi_v, phi_v[0] + 2 * math.pi)
            phi_a, da = 0.5 * (mid[1:] + mid[:-1]), np.diff(v_closed) / np.diff(mid)
        else:
            phi_a, da = _differentiate(rad, v_g, "tangents", 0.0)
        a_g = w * da
        mu_a = mu_v * H2 / (mu_phi * w)
        deg = np.degrees
        v_int = v_e[0] + np.append(0.0, np.cumsum(0.5 * (a_e[::step][1:] + a_e[::step][:-1]) * np.diff(rad))) / w
        s_int = s_nodes[0] + np.append(0.0, np.cumsum(0.5 * (v_int[1:] + v_int[:-1]) * np.diff(rad))) / w
        ex_phi = dense
        for q, nm, un, ph, val, ex, mu, formula, pole, integ in (
                ("s", names[0], units[0], nodes, s_nodes, s_e, mu_s, f"μ_{names[0]} = {mu_s:.4g} mm/{units[0]}",
                 None, s_int),
                ("v", names[1], units[1], phi0 + deg(phi_v), v_g, v_e, mu_v,
                 f"μ_{names[1]} = μ_{names[0]}·H_1/(μ_φ·ω_1) = {mu_v:.4g} mm/({units[1]})", H1, v_int),
                ("a", names[2], units[2], phi0 + deg(phi_a), a_g, a_e, mu_a,
                 f"μ_{names[2]} = μ_{names[1]}·H_2/(μ_φ·ω_1) = {mu_a:.4g} mm/({units[2]})", H2, None)):
            if q not in spec.quantities:
                continue
            e_max, e_rms = _errors(ph, val, ex_phi, ex)
            ie = None
            if integ is not None:
                ie = _errors(nodes, integ, ex_phi, ex)[0]
            out.append(Diagram(subject, q, f"{nm}_{subject}", un, np.asarray(ph, float), np.asarray(val, float),
                               ex_phi, np.asarray(ex, float), mu, formula, pole, e_max, e_rms, integ, ie))
    result = Diagrams(spec, w, mu_phi, float(H1), float(H2), nodes, tuple(out))
    spline.freeze(result)
    return result
