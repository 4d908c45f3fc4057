"""The exact work of the loads over the cycle and the extremes the flywheel is made of.

The work A_c(φ) = ∫ M_pr dφ is integrated by Gauss–Legendre on the intervals of the exact
grid, each interval first cut where M_pr is not smooth: where a piston turns at a dead
centre (a stroke's diagram ends, a stroke's pressure starts), where its travel crosses a
row of an indicator diagram (the interpolant's kink), at the rows of a diagram over the
crank angle, and where a resisting load turns with the velocity.  These points are found
where their functions change sign on the grid, then by subdivision and a last chord to
round-off.  Between
them M_pr is analytic: the three-point rule (exact for quintics) on intervals of a tenth of
a degree errs by about h⁶ f⁽⁶⁾/2016000 ≈ 1e-20 of the integrand's scale, and the stated
bound is Σ |Q₃ − Q₂| over the intervals (the two-point rule's error, far above the
three-point rule's).

The flywheel and the motion need maxima and minima of smooth functions of φ
(ω²I_pr − 2ΔT, 2(E₀ + ΔT)/(I_fw + I_pr)); each is found near the grid's extreme on a
window of two grid steps sampled 32 times finer (the cuts included), with a parabola
through the three best samples: the error is of order g‴ (h/32)³, below 1e-12 relative.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Any, cast

import numpy as np
from numpy.typing import NDArray

from plans.forces.loads import Loads, apply_loads
from plans.kinematics.exact import solve
from plans.kinematics.structure import Structure
from plans.kinematics.travel import piston_travel, toward_pivot
from plans.scene.model import Scene
from plans.tolerances import AGREE_REL

R = NDArray[np.float64]

_X3, _W3 = np.polynomial.legendre.leggauss(3)
_X2, _W2 = np.polynomial.legendre.leggauss(2)
FINE = 32  # samples per grid step of a window around an extreme
SUBDIVIDE, ROUNDS = 32, 4  # a bracket of a cut is divided 32 times, four times over


@dataclass
class Machine:
    """The machine reduced to the crank, evaluated at any crank angle."""

    scene: Scene
    loads: Loads
    structure: Structure
    rotor: float
    phi0: float  # deg, start of the cycle
    cycle: float  # deg

    def at(self, phis_deg: R, inertia: bool = True) -> tuple[R, R]:
        """I_pr (zeros unless ``inertia``) and M_pr at the crank angles (deg), as
        :func:`.dynamics.reduce` sums them, without its rows and analogues."""
        phis = np.asarray(phis_deg, float)
        if len(phis) == 0:
            return np.zeros(0), np.zeros(0)
        sc, loads = self.scene, self.loads
        kin = solve(sc, phis, order=2, structure=self.structure)
        w = np.abs(kin.omega(sc.driver.link))
        I = np.full(kin.n, self.rotor)
        if inertia:
            for lid in loads.centres:
                m, inert = loads.masses[lid], loads.inertias[lid]
                if m > 0:
                    I = I + m * (np.abs(kin.point_on(lid, sc.links[lid].points[loads.centres[lid]])[1]) / w) ** 2
                if inert > 0:
                    I = I + inert * (kin.omega(lid) / w) ** 2
        applied = apply_loads(sc, loads, kin)
        M = np.zeros(kin.n)
        for f in applied.forces:
            if f.kind != "inertia":
                M = M + (f.F * np.conj(kin.point_on(f.link, cast(Any, f.local))[1])).real / w
        for mo in applied.moments:
            if mo.kind != "inertia":
                M = M + mo.M * kin.omega(mo.link) / w
        return I, M

    # ------------------------------------------------------------------ where M_pr is not smooth

    def _event_values(self, kin: Any) -> R:
        """Continuous functions whose sign changes mark where M_pr is not smooth (columns)."""
        sc, cols = self.scene, []
        for gl in self.loads.gas:
            if gl.phi_table is None and gl.pressure is not None and set(gl.strokes) == {"down", "up"}:
                continue  # a constant pressure on both strokes: smooth
            joint = next(j for j in sc.joints if j.name == gl.joint)
            assert joint.guide is not None
            z = sc.links[gl.link].points[joint.point]
            r, v, _ = kin.point_on(gl.link, z)
            u: Any = joint.guide.direction if joint.guide.link == sc.frame else \
                kin.motion[joint.guide.link].rot * joint.guide.direction
            if gl.phi_table is None:
                cols.append((v * np.conj(toward_pivot(sc, r, u))).real)  # the dead centres
            if gl.diagram:
                s = piston_travel(sc, kin, gl.joint, gl.link) - gl.outer
                rows = np.unique(np.concatenate([ts for ts, _ in gl.diagram.values()]))
                for sk in rows[(rows > AGREE_REL * gl.stroke) & (rows < gl.stroke * (1 - AGREE_REL))]:
                    cols.append(s - sk)
        for fl in self.loads.forces:
            if fl.resisting is not None and fl.along is not None:
                z = sc.links[fl.link].points[fl.point]
                v = kin.point_on(fl.link, z)[1]
                cols.append((v * complex(math.cos(fl.along), -math.sin(fl.along))).real)
        for ml in self.loads.moments:
            if ml.resisting is not None:
                cols.append(kin.omega(ml.link))
        return np.array(cols).reshape(len(cols), kin.n)

    def _roots(self, which: NDArray[np.intp], x0: R, x1: R) -> R:
        """Where event ``which[j]`` changes sign in [x0[j], x1[j]]: the bracket cut 32 times
        at a time (all brackets in one solve) to a millionth of the grid step, then the
        chord through its ends (the function is smooth there: the chord errs by the square
        of the bracket)."""
        m = len(x0)
        t = np.linspace(0.0, 1.0, SUBDIVIDE + 1)
        f0 = f1 = np.zeros(m)
        for _ in range(ROUNDS):
            xs = x0[:, None] + (x1 - x0)[:, None] * t
            vals = self._event_values(solve(self.scene, xs.ravel(), order=1, structure=self.structure))
            f = vals[np.repeat(which, SUBDIVIDE + 1), np.arange(xs.size)].reshape(m, SUBDIVIDE + 1)
            change = np.signbit(f[:, :-1]) != np.signbit(f[:, 1:])
            k = np.argmax(change, axis=1)  # the first interval where the sign changes
            rows = np.arange(m)
            x0, x1 = xs[rows, k], xs[rows, k + 1]
            f0, f1 = f[rows, k], f[rows, k + 1]
        den = np.where(f1 != f0, f1 - f0, 1.0)
        return np.where(f1 != f0, x0 - f0 * (x1 - x0) / den, 0.5 * (x0 + x1))

    def cuts(self, grid: R) -> R:
        """The crank angles (deg) inside the cycle where M_pr is not smooth."""
        out: list[float] = []
        lo, hi = grid[0], grid[-1]
        for tab, period in ([(ml.table, ml.period) for ml in self.loads.moments if ml.table is not None]
                            + [(gl.phi_table, gl.period) for gl in self.loads.gas if gl.phi_table is not None]):
            assert tab is not None
            for m in range(math.floor(lo / period) - 1, math.ceil(hi / period) + 1):
                out += [float(x) for x in tab[0] + m * period if lo < x < hi]
        kin = solve(self.scene, grid, order=1, structure=self.structure)
        ev = self._event_values(kin)
        if ev.shape[0]:
            a, b = ev[:, :-1], ev[:, 1:]
            which, cell = np.nonzero(a * b < 0)
            if len(cell):
                out += [float(x) for x in self._roots(which, grid[cell], grid[cell + 1])]
        return np.unique(np.asarray(out, float))


@dataclass(frozen=True)
class Work:
    """A_c on the grid, exactly, with the breakpoints it was integrated between."""

    grid: R  # deg, closed
    A_c: R  # J, on the grid
    breaks: R  # deg: the grid and the cuts, sorted
    A_breaks: R  # J, A_c at the breaks
    bound: float  # J, the stated bound of the quadrature over the whole cycle


def integrate(machine: Machine, grid: R) -> Work:
    """A_c(φ) = ∫ M_pr dφ from the first grid angle, by Gauss–Legendre between the cuts."""
    cuts = machine.cuts(grid)
    breaks = np.unique(np.concatenate([grid, cuts]))
    tiny = 1e-11 * (grid[-1] - grid[0])
    keep = np.append(True, np.diff(breaks) > tiny)  # a cut on a grid angle to round-off is that angle
    keep |= np.isin(breaks, grid)
    breaks = breaks[keep]
    h = np.radians(np.diff(breaks))
    mid = 0.5 * (breaks[1:] + breaks[:-1])
    half = 0.5 * np.diff(breaks)
    pts = np.concatenate([(mid[:, None] + half[:, None] * _X3).ravel(), (mid[:, None] + half[:, None] * _X2).ravel()])
    M = machine.at(pts, inertia=False)[1]
    m = len(mid)
    q3 = 0.5 * h * (M[:3 * m].reshape(m, 3) @ _W3)
    q2 = 0.5 * h * (M[3 * m:].reshape(m, 2) @ _W2)
    A_b = np.append(0.0, np.cumsum(q3))
    idx = np.searchsorted(breaks, grid)
    return Work(grid, A_b[idx], breaks, A_b, float(np.sum(np.abs(q3 - q2))))


def work_at(machine: Machine, work: Work, phis_deg: R) -> tuple[R, R]:
    """I_pr and A_c at any crank angles of the cycle (deg, wrapped into it)."""
    lo, span = work.grid[0], work.grid[-1] - work.grid[0]
    phis = lo + np.mod(np.asarray(phis_deg, float) - lo, span)
    k = np.clip(np.searchsorted(work.breaks, phis, side="right") - 1, 0, len(work.breaks) - 2)
    a = work.breaks[k]
    mid, half = 0.5 * (a + phis), 0.5 * (phis - a)
    pts = (mid[:, None] + half[:, None] * _X3).ravel()
    I, M = machine.at(np.concatenate([phis, pts]))
    n = len(phis)
    part = np.radians(half) * (M[n:].reshape(n, 3) @ _W3)
    return I[:n], work.A_breaks[k] + part


class Extremes:
    """Windows of fine samples of I_pr and ΔT around grid angles, made once and reused
    while the flywheel and the motion look for their extremes."""

    def __init__(self, machine: Machine, work: Work, M_d: float) -> None:
        self.machine, self.work, self.M_d = machine, work, M_d
        self.grid = work.grid
        self._win: dict[int, tuple[R, R, R]] = {}

    def window(self, k: int) -> tuple[R, R, R]:
        """(φ deg, I_pr, ΔT) sampled finely over the two grid steps around grid index k."""
        if k in self._win:
            return self._win[k]
        g = self.grid
        step = g[1] - g[0]
        lo, hi = g[k] - step, g[k] + step
        phis = np.linspace(lo, hi, 2 * FINE + 1)
        span = g[-1] - g[0]
        cuts = np.concatenate([self.work.breaks + shift for shift in (-span, 0.0, span)])
        phis = np.unique(np.concatenate([phis, cuts[(cuts > lo) & (cuts < hi)]]))
        I, A = work_at(self.machine, self.work, phis)
        wrapped = self.grid[0] + np.mod(phis - self.grid[0], g[-1] - g[0])
        T = A + self.M_d * np.radians(wrapped - g[0])
        out = self._win[k] = (phis, I, T)
        return out

    def extreme(self, values: R, fn: Any, biggest: bool) -> float:
        """The max (or min) over the cycle of fn(I_pr, ΔT), ``values`` its grid samples."""
        v = values[:-1]
        k = int(np.argmax(v) if biggest else np.argmin(v))
        phis, I, T = self.window(k)
        f = fn(I, T)
        j = int(np.argmax(f) if biggest else np.argmin(f))
        best = float(f[j])
        if 0 < j < len(f) - 1:
            h1, h2 = phis[j] - phis[j - 1], phis[j + 1] - phis[j]
            if abs(h1 - h2) < AGREE_REL * h1:  # three equal steps: no cut between them
                a, b, c = f[j - 1], f[j], f[j + 1]
                den = a - 2 * b + c
                if den != 0:
                    t = 0.5 * (a - c) / den
                    if abs(t) <= 1:
                        cand = float(b - 0.25 * (a - c) * t)
                        best = max(best, cand) if biggest else min(best, cand)
        return best


def flywheel(ext: Extremes, I_pr: R, dT: R, omega_m: float, delta: float) -> tuple[float, float, float]:
    """The exact flywheel I_fw (kg·m²) and the continuous extremes it is made of:
    max(ω_min² I − 2ΔT), min(ω_max² I − 2ΔT)."""
    wmax2 = (omega_m * (1 + delta / 2)) ** 2
    wmin2 = (omega_m * (1 - delta / 2)) ** 2
    hi = ext.extreme(wmin2 * I_pr - 2 * dT, lambda i, t: wmin2 * i - 2 * t, True)
    lo = ext.extreme(wmax2 * I_pr - 2 * dT, lambda i, t: wmax2 * i - 2 * t, False)
    return (hi - lo) / (wmax2 - wmin2), hi, lo


def motion(ext: Extremes, I_pr: R, dT: R, I_fw: float, omega_m: float) -> tuple[R, float]:
    """ω(φ) on the grid of the steady cycle with flywheel I_fw ((ω_max + ω_min)/2 = ω_m) and
    its δ, the extremes of ω found between the grid angles."""
    J = np.maximum(I_fw + I_pr, 1e-300)
    T = dT
    E0 = 0.5 * omega_m**2 * float(np.mean(J[:-1])) - float(np.mean(T[:-1]))
    floor = -float(np.min(T)) + 1e-300

    def ends(e0: float) -> tuple[float, float, float, float]:
        x = 2 * (e0 + T) / J

        def fx(i: R, t: R) -> R:
            return 2 * (e0 + t) / np.maximum(I_fw + i, 1e-300)

        xmax, xmin = ext.extreme(x, fx, True), ext.extreme(x, fx, False)
        return xmax, xmin, float(J[int(np.argmax(x[:-1]))]), float(J[int(np.argmin(x[:-1]))])

    for _ in range(60):
        xmax, xmin, jmax, jmin = ends(E0)
        f = 0.5 * (math.sqrt(max(xmax, 0.0)) + math.sqrt(max(xmin, 0.0))) - omega_m
        df = 0.5 * (1 / (jmax * math.sqrt(max(xmax, 1e-300))) + 1 / (jmin * math.sqrt(max(xmin, 1e-300))))
        new = E0 - f / df
        E0 = new if new > floor else 0.5 * (E0 + floor)  # keep the kinetic energy positive
        if abs(f) <= 1e-14 * omega_m:
            break
    xmax, xmin, _, _ = ends(E0)
    om = np.sqrt(np.maximum(2 * (E0 + T) / J, 0.0))
    return om, (math.sqrt(max(xmax, 0.0)) - math.sqrt(max(xmin, 0.0))) / omega_m


def wittenbauer_bound(ext: Extremes, phi_curve_deg: R, I_curve: R, T_curve: R, omega_m: float, delta: float,
                      hi: float, lo: float) -> float:
    """A bound on |I_W − I_exact| (kg·m²) for the Wittenbauer flywheel drawn on the curve
    (I_curve, T_curve) at the crank angles ``phi_curve_deg``.

    The construction's slopes ω_m²(1 ± δ)/2 are the exact ω²/2 less ε/2, ε = ω_m²δ²/4,
    which moves the numerator by at most ε (I_max − I_min); the drawn curve lies within D
    (of I) and E (of ΔT) of the exact one at the same angles, which moves each of the two
    extremes by at most ω² D + 2E; and the exact extremes between those angles exceed
    the sampled ones by what the refined extremes say (hi − max, min − lo)."""
    I_e, A_e = work_at(ext.machine, ext.work, phi_curve_deg)
    g = ext.grid
    wrapped = g[0] + np.mod(phi_curve_deg - g[0], g[-1] - g[0])
    T_e = A_e + ext.M_d * np.radians(wrapped - g[0])
    wmax2 = (omega_m * (1 + delta / 2)) ** 2
    wmin2 = (omega_m * (1 - delta / 2)) ** 2
    eps = omega_m**2 * delta**2 / 4
    D = float(np.max(np.abs(I_curve - I_e)))
    E = float(np.max(np.abs(T_curve - T_e)))
    c1 = max(hi - float(np.max(wmin2 * I_e - 2 * T_e)), 0.0)
    c2 = max(float(np.min(wmax2 * I_e - 2 * T_e)) - lo, 0.0)
    num = eps * float(np.ptp(I_curve)) + (wmin2 + wmax2) * D + 4 * E + c1 + c2
    return num / (2 * omega_m**2 * delta)
