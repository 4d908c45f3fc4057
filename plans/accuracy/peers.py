"""Open peers, run for real beside plans: pylinkage (numba-compiled and pure-Python steps)
and ``mechanism`` (vector loops solved by scipy's fsolve).

Each peer builds the same mechanism from the scene (a crank with RRR/RRP dyads on the crank
pin and the frame: the slider-crank, the four-bar, the V-engine), its positions are checked
against the exact analysis, and its time is measured in the same run as ours.  A peer that is
not installed, or whose interface has moved, gives a record saying "skipped: reason".
"""

from __future__ import annotations

import importlib.util
import math
import time
from collections.abc import Callable
from dataclasses import dataclass, field
from typing import Any

import numpy as np

from plans.kinematics import exact
from plans.kinematics.structure import analyse
from plans.scene.model import Scene


@dataclass
class PeerRun:
    """One peer on one mechanism: seconds per position, and its disagreement with plans
    (largest |Δ| over the solved points, relative to the crank (positions), ω1·crank (v),
    ω1²·crank (a))."""

    peer: str
    mechanism: str
    positions: int
    time_per_position: float
    errors: dict[str, float] = field(default_factory=dict)
    note: str = ""
    #: runs the peer again over the same positions (for timing side by side with plans)
    runner: Callable[[], Any] | None = field(default=None, repr=False, compare=False)


def _median(fn: Callable[[], Any], reps: int = 7) -> float:
    ts = []
    for _ in range(reps):
        t0 = time.perf_counter()
        fn()
        ts.append(time.perf_counter() - t0)
    return sorted(ts)[len(ts) // 2]


@dataclass
class _Shape:
    """The scene as a crank and dyads on its pin: what a peer is built from."""

    O: complex
    r: float
    theta0: float  # crank angle at phi = 0 (rad)
    sense: int
    omega: float
    eps: float
    pin: str
    dyads: list[tuple]  # ("RRR", B, l1, l3, C) / ("RRP", B, l1, G0, u)


def shape_of(scene: Scene) -> _Shape | None:
    st = analyse(scene)
    d = scene.driver
    crank = scene.links[d.link]
    if len(crank.axis) != 2:
        return None
    pin = crank.axis[1]
    z = crank.points[pin] - crank.points[d.pivot]
    dyads: list[tuple] = []
    for g in st.groups:
        j1, j2, j3 = g.joints
        if g.known != (d.link, scene.frame) or j1.point != pin:
            return None
        rod = scene.links[g.links[0]]
        l1 = abs(rod.points[j2.point] - rod.points[j1.point])
        if g.kind == "RRR":
            rocker = scene.links[g.links[1]]
            dyads.append(("RRR", j2.point, l1, abs(rocker.points[j2.point] - rocker.points[j3.point]),
                          scene.frame_points[j3.point]))
        elif g.kind == "RRP" and j3.guide is not None:
            dyads.append(("RRP", j2.point, l1, j3.guide.origin, j3.guide.direction))
        else:
            return None
    import cmath

    return _Shape(scene.frame_points[d.pivot], abs(z), d.phi_ref + cmath.phase(z), d.sense, d.omega, d.eps,
                  pin, dyads)


def _errors(scene: Scene, phis: np.ndarray, got: dict[str, tuple], size: float) -> dict[str, float]:
    kin = exact.solve(scene, phis, order=2)
    w = abs(scene.driver.omega)
    out = {"r": 0.0, "v": 0.0, "a": 0.0}
    for name, vals in got.items():
        ours = kin.point(name)
        for key, k, norm in (("r", 0, size), ("v", 1, w * size), ("a", 2, w * w * size)):
            if k < len(vals) and vals[k] is not None:
                out[key] = max(out[key], float(np.max(np.abs(vals[k] - ours[k]))) / norm)
    return out


# --------------------------------------------------------------------------- pylinkage


def _pylinkage(scene: Scene, sh: _Shape, phis: np.ndarray) -> tuple[Any, Any, list[str]]:
    """The linkage positioned one step before phis[0] (pylinkage steps, then yields)."""
    import pylinkage as pl

    step = math.radians(float(phis[1] - phis[0])) * sh.sense
    th = sh.theta0 + math.radians(float(phis[0])) * sh.sense
    before = exact.solve(scene, [float(phis[0] - (phis[1] - phis[0]))], order=0)
    O = pl.Ground(sh.O.real, sh.O.imag, name="O")
    crank = pl.Crank(anchor=O, radius=sh.r, angular_velocity=step, initial_angle=th - step, name=sh.pin)
    parts: list[Any] = [O, crank]
    names = ["O", sh.pin]
    for kind, name, l1, x, y in sh.dyads:
        B0 = complex(before.point(name)[0][0])
        dy: Any
        if kind == "RRR":
            C = pl.Ground(y.real, y.imag, name=f"{name}_C")
            dy = pl.RRRDyad(crank.output, C, distance1=l1, distance2=x, x=B0.real, y=B0.imag, name=name)
            parts += [C, dy]
            names += [f"{name}_C", name]
        else:
            G1 = pl.Ground(x.real, x.imag, name=f"{name}_G1")
            G2 = pl.Ground((x + y).real, (x + y).imag, name=f"{name}_G2")
            dy = pl.RRPDyad(revolute_anchor=crank.output, line_anchor1=G1, line_anchor2=G2, distance=l1,
                            x=B0.real, y=B0.imag, name=name)
            parts += [G1, G2, dy]
            names += [f"{name}_G1", f"{name}_G2", name]
    lk = pl.Linkage(parts)
    lk.set_input_velocity(crank, omega=sh.omega, alpha=sh.eps)
    return lk, crank, names


def run_pylinkage(name: str, scene: Scene, phis: np.ndarray, reps: int = 7) -> list[PeerRun]:
    """numba (``step_fast_with_kinematics``: positions, velocities, accelerations over all
    positions) and one pure-Python ``step`` (positions of one position)."""
    sh = shape_of(scene)
    if sh is None:
        return [PeerRun("pylinkage", name, len(phis), math.nan, note="skipped: not a crank with RRR/RRP dyads")]
    n = len(phis)
    lk, _, names = _pylinkage(scene, sh, phis)
    pos, vel, acc = lk.step_fast_with_kinematics(iterations=n)  # compiles once
    lk, _, names = _pylinkage(scene, sh, phis)
    pos, vel, acc = lk.step_fast_with_kinematics(iterations=n)
    cx = pos[..., 0] + 1j * pos[..., 1]
    cv = vel[..., 0] + 1j * vel[..., 1]
    ca = acc[..., 0] + 1j * acc[..., 1]
    got = {nm: (cx[:, k], cv[:, k], ca[:, k]) for k, nm in enumerate(names) if nm in
           [sh.pin] + [d[1] for d in sh.dyads]}
    errs = _errors(scene, phis, got, sh.r)
    t = _median(lambda: lk.step_fast_with_kinematics(iterations=n), reps)
    runs = [PeerRun("pylinkage + numba", name, n, t / n, errs,
                    note="step_fast_with_kinematics: positions, v and a of the joints",
                    runner=lambda: lk.step_fast_with_kinematics(iterations=n))]
    k = 36
    lk2, _, _ = _pylinkage(scene, sh, phis)

    def steps() -> None:
        for _ in lk2.step(iterations=k):
            pass
    steps()
    t = _median(steps, reps)
    turning = lk2.step(iterations=2**62)  # one step a call, the crank turning on (what the goal times)
    runs.append(PeerRun("pylinkage step", name, 1, t / k, note="one pure-Python step: positions only",
                        runner=lambda: next(turning)))
    return runs


# --------------------------------------------------------------------------- mechanism


def run_mechanism(name: str, scene: Scene, phis: np.ndarray) -> list[PeerRun]:
    """Vector-loop model solved by fsolve at each position (positions, v, a)."""
    sh = shape_of(scene)
    if sh is None or len(sh.dyads) != 1:
        return [PeerRun("mechanism", name, len(phis), math.nan,
                        note="skipped: only single-dyad mechanisms are modelled for this peer")]
    import mechanism as me

    kind, bname, l1, x, y = sh.dyads[0]
    theta = sh.theta0 + np.radians(phis) * sh.sense
    omega = np.full(len(phis), sh.omega)
    alpha = np.full(len(phis), sh.eps)
    pre = exact.solve(scene, phis[:1], order=2)
    O, A, B, G = me.get_joints(f"O {sh.pin} {bname} G")
    a = me.Vector((O, A), r=sh.r)
    if kind == "RRR":
        C = complex(y)
        ground = me.Vector((O, G), r=abs(C - sh.O), theta=math.atan2((C - sh.O).imag, (C - sh.O).real),
                           style="ground")
        b = me.Vector((A, B), r=l1)
        c = me.Vector((G, B), r=x)

        def loop(v: Any, i: Any) -> Any:
            return a(i) + b(v[0]) - ground() - c(v[1])
        th2 = float(np.angle(pre.point(bname)[0][0] - pre.point(sh.pin)[0][0]))
        th3 = float(np.angle(pre.point(bname)[0][0] - C))
        guess = (np.array([th2, th3]), np.array([1.0, 1.0]), np.array([1.0, 1.0]))
    else:
        G0, u = complex(x), complex(y)
        # O → foot of the guide (fixed) → B along the guide (variable length)
        t0 = ((sh.O - G0) * u.conjugate()).real
        foot = G0 + t0 * u
        off = me.Vector((O, G), r=abs(foot - sh.O), theta=float(np.angle(foot - sh.O)) if foot != sh.O else 0.0,
                        style="ground")
        b = me.Vector((A, B), r=l1)
        c = me.Vector((G, B), theta=float(np.angle(u)), style="ground")

        def loop(v: Any, i: Any) -> Any:
            return a(i) + b(v[0]) - off() - c(v[1])
        B0 = complex(pre.point(bname)[0][0])
        guess = (np.array([float(np.angle(B0 - pre.point(sh.pin)[0][0])), float(((B0 - foot) * u.conjugate()).real)]),
                 np.array([1.0, 1.0]), np.array([1.0, 1.0]))
    m = me.Mechanism(vectors=(a, b, off if kind != "RRR" else ground, c), origin=O, loops=loop, pos=theta,
                     vel=omega, acc=alpha, guess=guess)
    t0 = time.perf_counter()
    m.iterate()
    t = time.perf_counter() - t0
    got = {bname: (B.x_positions + 1j * B.y_positions, B.x_velocities + 1j * B.y_velocities,
                   B.x_accelerations + 1j * B.y_accelerations)}
    shift = sh.O  # mechanism puts its origin joint at (0, 0)
    got = {k: (v[0] + shift, v[1], v[2]) for k, v in got.items()}
    return [PeerRun("mechanism", name, len(phis), t / len(phis), _errors(scene, phis, got, sh.r),
                    note="fsolve on the vector loop at each position: positions, v and a")]


# --------------------------------------------------------------------------- all


def available(peer: str) -> str | None:
    """None when the peer can run, else why not."""
    need = {"pylinkage": ("pylinkage", "numba"), "mechanism": ("mechanism", "scipy")}[peer]
    missing = [m for m in need if importlib.util.find_spec(m) is None]
    return f"skipped: {', '.join(missing)} not installed (pip install -e '.[peers]')" if missing else None


def run_peers(cases: list[tuple[str, Scene]], positions: int = 360, mechanism_positions: int = 36,
              log: Callable[[str], None] | None = None) -> list[PeerRun]:
    """Every peer on every case; a 'skipped' run for what cannot run."""
    out: list[PeerRun] = []
    for peer, fn in (("pylinkage", run_pylinkage), ("mechanism", run_mechanism)):
        why = available(peer)
        if why:
            out.append(PeerRun(peer, "-", 0, math.nan, note=why))
            continue
        for name, scene in cases:
            n = positions if peer == "pylinkage" else mechanism_positions
            phis = np.linspace(0.0, 360.0, n, endpoint=False) + 7.5
            try:
                out += fn(name, scene, phis)
            except Exception as exc:  # a peer's interface drift must not break the benchmark
                out.append(PeerRun(peer, name, n, math.nan, note=f"skipped: {type(exc).__name__}: {exc}"))
            if log:
                log(f"  {peer}: {name} done")
    return out
