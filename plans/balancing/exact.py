"""The harmonic analysis checked against exact physics.

An engine whose cylinders all sit on one crank throw (a single cylinder, a V-twin) is a
planar linkage: the crank carries the rotating masses at its pin, each cylinder is an
RRP dyad (a massless rod, a piston carrying the reciprocating mass on a guide along the
bank's axis).  The kinetostatics of :mod:`plans.forces` solves it group by group, with no
gravity and the driving load a couple (which sends no force to the frame); the shaking
force is then the sum of the forces the links put on the frame,
−Σ F(on link from frame), an independent route to Σ Φ.  Against it, the rotating +
first + second order force of the balancing analysis: their difference is the
truncation of the harmonic series, m_j r ω² (λ³/4)(cos 2θ − cos 4θ) + O(λ⁵) for each
cylinder, so it shrinks as λ³.

An engine with several throws is checked the same way cylinder by cylinder: each
crank-slider unit is its own planar linkage (its crank at β_i), and the frame forces of
all of them add up to the shaking force and, times their arms z_i − z_ref, to the
(turned) shaking moment.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, replace
from typing import Any

import numpy as np

from plans.balancing.analysis import balance
from plans.balancing.engine import Cylinder, Engine
from plans.errors import InputError, Said
from plans.tolerances import CLOSED_REL
from plans.units import DUST


@dataclass(frozen=True, slots=True)
class ExactCheck:
    """The shaking force and turned moment over a turn, exact and harmonic (engine plane:
    real along the vertical, imaginary along the rotation; N and N·m)."""

    alpha: np.ndarray  # crank angle of crank 1 from the vertical, rad
    exact: np.ndarray
    harmonic: np.ndarray
    moment_exact: np.ndarray
    moment_harmonic: np.ndarray
    linkages: int  # planar linkages solved (1: the engine is one; else one per cylinder)
    force_ref: float = 0.0  # Σ m r ω² (N): below 1e-9 of it a force is round-off
    moment_ref: float = 0.0  # the same times the longest arm (N·m)
    peak_force: float | None = None  # max |R| over the turn, maximised between the samples
    peak_moment: float | None = None  # max |M| likewise

    @property
    def max_error(self) -> float:
        return _clean(float(np.max(np.abs(self.exact - self.harmonic))), self.force_ref)

    @property
    def max_exact(self) -> float:
        peak = float(np.max(np.abs(self.exact))) if self.peak_force is None else self.peak_force
        return _clean(peak, self.force_ref)

    @property
    def max_moment_error(self) -> float:
        return _clean(float(np.max(np.abs(self.moment_exact - self.moment_harmonic))), self.moment_ref)

    @property
    def max_moment(self) -> float:
        peak = float(np.max(np.abs(self.moment_exact))) if self.peak_moment is None else self.peak_moment
        return _clean(peak, self.moment_ref)

    def to_json(self) -> dict[str, Any]:
        return {"positions": len(self.alpha), "linkages": self.linkages,
                "max_shaking_force": self.max_exact, "max_truncation_error": self.max_error,
                "relative_truncation_error": self.max_error / self.max_exact if self.max_exact > 0 else 0.0,
                "max_shaking_moment": self.max_moment, "max_moment_truncation_error": self.max_moment_error}


def _clean(x: float, ref: float) -> float:
    """Round-off of a vanishing quantity shown as 0."""
    return 0.0 if x <= DUST * ref else x


def scene_dict(engine: Engine, positions: int = 360, crank_deg: float = 0.0,
               phi_deg: list[float] | None = None) -> dict[str, Any]:
    """The engine (one crank throw, at ``crank_deg`` ahead of crank 1) as a linkage scene in
    SI units, crank 1 at top dead centre at φ = 0."""
    if not engine.is_planar:
        raise InputError(Said("bx_engine_has_more"),
                         file=engine.path, field="cylinders")
    if engine.lam <= 0:
        raise InputError(Said("bx_lambda_infinitely_long"),
                         file=engine.path, field="lambda")
    n = engine.n
    frame = 2 * n + 2
    links: dict[str, Any] = {"1": {"name": "crank", "axis": ["O", "A"], "length": engine.r,
                                   "mass": sum(c.m_rot for c in engine.cylinders), "centre": "A"}}
    joints: list[dict[str, Any]] = [{"kind": "R", "links": [frame, 1], "point": "O"}]
    for k, c in enumerate(engine.cylinders):
        rod, piston, B = 2 * k + 2, 2 * k + 3, f"B{k + 1}"
        links[str(rod)] = {"name": f"rod {c.name}", "axis": ["A", B], "length": engine.rod_length}
        links[str(piston)] = {"name": f"piston {c.name}", "axis": [B], "mass": c.m_rec}
        joints += [{"kind": "R", "links": [1, rod], "point": "A"},
                   {"kind": "R", "links": [rod, piston], "point": B},
                   {"kind": "P", "links": [piston, frame], "point": B,
                    # the bank's axis, measured from the vertical in the direction of rotation (ccw)
                    "guide": {"link": frame, "through": "O", "angle_deg": 90.0 + c.bank_deg}}]
    driver: dict[str, Any] = {"link": 1, "omega": engine.omega, "sense": "ccw", "phi_ref_deg": 90.0 + crank_deg}
    if phi_deg is None:
        driver["positions"] = positions
    else:
        driver["phi_deg"] = phi_deg
    return {"format": 1, "title": engine.title, "unit": "m", "frame": frame,
            "points": {"O": [0.0, 0.0]}, "links": links, "joints": joints,
            "driver": driver,
            "outputs": ["positions", "velocity_plan", "acceleration_plan", "force_polygons"],
            "loads": {"gravity": False, "balancing": {"kind": "moment"}}}


def frame_force(engine: Engine, positions: int = 360, crank_deg: float = 0.0,
                phi_deg: list[float] | None = None) -> np.ndarray:
    """The force a one-throw engine puts on its frame over a turn (or at the crank angles
    ``phi_deg`` of crank 1), by the kinetostatics (engine plane, N)."""
    from plans.forces.polygons import analyse_forces
    from plans.kinematics.exact import solve
    from plans.scene.model import scene_from_dict

    scene = scene_from_dict(scene_dict(engine, positions, crank_deg, phi_deg), engine.path)
    kin = solve(scene, order=2)
    fa = analyse_forces(scene, kin)
    world = np.zeros(kin.n, complex)
    for rc in fa.reactions():
        if rc.frm == scene.frame:
            world = world - rc.F  # the link pushes the frame with −F(on link from frame)
    return world / 1j  # world (x right, y up) -> engine plane (vertical real, ccw imaginary)


def exact_check(engine: Engine, positions: int = 360) -> ExactCheck:
    """Shaking force and moment from the kinetostatics against the harmonic approximation."""
    if engine.lam <= 0:
        raise InputError(Said("bx_lambda_infinitely_long"),
                         file=engine.path, field="lambda")
    alpha = 2 * np.pi * np.arange(positions) / positions
    b = balance(engine)
    if engine.is_planar:
        force = frame_force(engine, positions)
        # one throw, but each cylinder's force acts in its own plane: the moment cylinder by cylinder
        moment = _moment_by_cylinders(engine, positions)
        count = 1
    else:
        force = np.zeros(positions, complex)
        moment = np.zeros(positions, complex)
        for c in engine.cylinders:
            f = frame_force(_single(engine, c), positions, math.degrees(c.crank))
            force += f
            moment += (c.z - engine.reference_z) * f
        count = engine.n
    fref = sum(c.m_rot + c.m_rec for c in engine.cylinders) * engine.r * engine.omega**2
    arm = max([abs(c.z - engine.reference_z) for c in engine.cylinders] + [engine.r])
    step = 360.0 / positions
    peak_f = _peak(lambda a: _shaking(engine, a)[0], np.degrees(alpha), np.abs(force), step)
    peak_m = _peak(lambda a: _shaking(engine, a)[1], np.degrees(alpha), np.abs(moment), step) \
        if np.max(np.abs(moment)) > CLOSED_REL * fref * arm else None
    return ExactCheck(alpha, force, np.asarray(b.shaking_force(alpha)), moment,
                      np.asarray(b.turned_moment(alpha)), count, fref, fref * arm, peak_f, peak_m)


def _shaking(engine: Engine, phi_deg: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """The exact shaking force and turned moment at crank angles of crank 1 (deg)."""
    phis = [float(x) for x in phi_deg]
    if engine.is_planar:
        force = frame_force(engine, phi_deg=phis)
        moment = np.zeros(len(phis), complex)
        for c in engine.cylinders:
            if c.z != engine.reference_z:
                moment += (c.z - engine.reference_z) * frame_force(_single(engine, c), crank_deg=math.degrees(c.crank),
                                                                   phi_deg=phis)
        return force, moment
    force = np.zeros(len(phis), complex)
    moment = np.zeros(len(phis), complex)
    for c in engine.cylinders:
        f = frame_force(_single(engine, c), crank_deg=math.degrees(c.crank), phi_deg=phis)
        force += f
        moment += (c.z - engine.reference_z) * f
    return force, moment


def _peak(fn: Any, phi_deg: np.ndarray, mags: np.ndarray, step: float) -> float:
    """max |fn| over the turn: around each sample within reach of the largest, the window of
    two steps zoomed in 16 times at a time until the step is 1e-7°, then a parabola
    through the best three (|fn| is smooth there: its error is of order (1e-7°)³)."""
    top = float(np.max(mags))
    # the local maxima near which a larger value may hide: within a second difference of the top
    slack = float(np.max(np.abs(np.roll(mags, 1) - 2 * mags + np.roll(mags, -1))))
    local = (mags >= np.roll(mags, 1)) & (mags >= np.roll(mags, -1)) & (mags >= top - slack)
    best = top
    for k in np.flatnonzero(local)[:4]:
        lo, hi = phi_deg[k] - step, phi_deg[k] + step
        for _ in range(8):
            xs = np.linspace(lo, hi, 33)
            ys = np.abs(fn(xs))
            j = int(np.argmax(ys))
            best = max(best, float(ys[j]))
            h = xs[1] - xs[0]
            if 0 < j < 32:
                a, b, c = ys[j - 1], ys[j], ys[j + 1]
                den = a - 2 * b + c
                if den < 0:
                    best = max(best, float(b - 0.125 * (a - c) ** 2 / den))
            lo, hi = xs[j] - h, xs[j] + h
            if h < 1e-7:
                break
    return best


def _single(engine: Engine, c: Cylinder) -> Engine:
    """Cylinder c alone, its crank taken as crank 1 (the scene turns it by β_i)."""
    return replace(engine, cylinders=(replace(c, crank=0.0),))


def _moment_by_cylinders(engine: Engine, positions: int) -> np.ndarray:
    moment = np.zeros(positions, complex)
    for c in engine.cylinders:
        if c.z != engine.reference_z:
            moment += (c.z - engine.reference_z) * frame_force(_single(engine, c), positions, math.degrees(c.crank))
    return moment


def truncation_table(engine: Engine, lambdas: tuple[float, ...] = (0.05, 0.1, 0.2, 0.3),
                     positions: int = 360) -> list[tuple[float, float, float]]:
    """(λ, max error N, error / (Σ m_j r ω² λ³)) for the same engine at other λ."""
    unit = sum(c.m_rec for c in engine.cylinders) * engine.r * engine.omega**2
    out = []
    for lam in lambdas:
        err = exact_check(replace(engine, lam=lam), positions).max_error
        out.append((lam, err, err / (unit * lam**3) if unit > 0 else math.nan))
    return out
