"""Newton–Raphson on the loop (constraint) equations: the engine's second,
independent solver.

Written without :mod:`plans.kinematics`: every moving link k has a pose
q_k = (x_k, y_k, θ_k) (origin of its local frame and its angle, so a point of
local coordinates z is at r_k + e^{iθ_k} z), and the scene's joints give the
constraint equations Φ(q, t) = 0 (Haug's formulation of multibody kinematics):

* R joint of links a, b at P:   r_a + e^{iθ_a} z_a(P) − r_b − e^{iθ_b} z_b(P) = 0      (2 equations);
* P joint, slider s on the guide (G, α) of carrier c:
      cross(u, r_s + e^{iθ_s} z_s(P) − r_c − e^{iθ_c} G) = 0,   u = e^{i(θ_c + α)},
      θ_s − θ_c − α + β = 0  (β: the sliding direction in the slider's own frame)       (2 equations);
* the driver:  θ_1 − (φ_ref + sense·φ) = 0                                              (1 equation).

The frame's pose is zero.  With W = 3n − 2p5 = 1 the system is square
(3n unknowns, 2p5 + 1 equations).  Positions: Newton–Raphson J Δq = −Φ until
‖Δq‖∞ ≤ ``tol`` (lengths made dimensionless by the mechanism's largest length L,
so ``tol`` is relative).  Velocities: J q̇ = ν (ν = ω1 on the driver's row).
Accelerations: J q̈ = γ with
    γ_R = θ̇_a² e^{iθ_a} z_a − θ̇_b² e^{iθ_b} z_b,
    γ_P = −[Im(−θ̇_c² ū d) + 2 Im(conj(iθ̇_c u) ḋ) + Im(ū (−θ̇_s² E_s + θ̇_c² E_c))],
    γ_driver = ε1.
Over several crank angles the solver continues from the previous position
(predictor q + (dq/dθ1) Δθ1, the tangent from the same Jacobian), halving the
step when the corrector does not converge or jumps, so the assembly branch
follows by continuity.  The 2-norm condition number of J (dimensionless) is
reported for every position.

**As a fallback for groups with no closed form** (class III and up): the lead can
add a ``"GENERIC"`` entry to ``kinematics._SOLVERS`` whose solver calls
:func:`solve` on the scene (or on the sub-scene of the group with the known
links' motion as given) with ``seed`` from the previous solution or from the
sheet, and copies ``r0, θ, ω, ε, v0, a0`` of the group's links from the
:class:`NewtonResult` (``pose``, ``rates``), which follow the same pose
convention as :class:`plans.kinematics.Kinematics`.
"""

from __future__ import annotations

import math
from collections.abc import Callable, Mapping, Sequence
from dataclasses import dataclass, field

import numpy as np
from numpy.typing import NDArray

from plans.errors import Locked, NotAssemblable, Said
from plans.scene.model import Scene

C = NDArray[np.complex128]
R = NDArray[np.float64]

#: Condition number above which the Jacobian is taken as singular: the mechanism locks.
COND_LOCKED = 1e15
#: Condition number above which results are flagged (the benchmark warns).
COND_WARN = 1e8


@dataclass(frozen=True)
class _System:
    """The constraint equations of a scene, compiled to index arrays."""

    scene: Scene
    links: tuple[int, ...]  # moving link ids; index n stands for the frame
    L: float  # length unit (largest length in the scene)
    driver: int  # index of the driver
    # R joints: link indices and local points (dimensionless)
    ra: NDArray[np.intp]
    rb: NDArray[np.intp]
    za: C
    zb: C
    r_names: tuple[str, ...]
    # P joints: slider, carrier, slider point, guide origin, guide angle, slider angle
    ps: NDArray[np.intp]
    pc: NDArray[np.intp]
    zs: C
    g0: C
    alpha: R
    beta: R
    p_names: tuple[str, ...]

    @property
    def n(self) -> int:
        return len(self.links)

    @property
    def m(self) -> int:
        return 2 * len(self.ra) + 2 * len(self.ps) + 1


def compile_scene(scene: Scene) -> _System:
    """Index arrays of the constraint equations (the driver's joint with the frame included)."""
    links = tuple(sorted(scene.links))
    index = {lid: k for k, lid in enumerate(links)}
    frame_index = len(links)
    index[scene.frame] = frame_index
    sizes = [abs(z) for z in scene.frame_points.values()]
    for link in scene.links.values():
        sizes += [abs(z) for z in link.points.values()]
    for jt in scene.joints:
        if jt.guide is not None:
            sizes.append(abs(jt.guide.origin))
    L = max([s for s in sizes if math.isfinite(s)] + [0.0])
    if L <= 0:
        L = 1.0

    def local(lid: int, name: str) -> complex:
        pts = scene.frame_points if lid == scene.frame else scene.links[lid].points
        return pts[name] / L

    ra, rb, za, zb, rn = [], [], [], [], []
    ps, pc, zs, g0, al, be, pn = [], [], [], [], [], [], []
    for jt in scene.joints:
        a, b = jt.links
        if jt.kind == "R":
            ra.append(index[a])
            rb.append(index[b])
            za.append(local(a, jt.point))
            zb.append(local(b, jt.point))
            rn.append(jt.name)
        else:
            g = jt.guide
            assert g is not None
            s = jt.slider
            ps.append(index[s])
            pc.append(index[g.link])
            zs.append(local(s, jt.point))
            g0.append(g.origin / L)
            al.append(g.angle)
            be.append(jt.slider_angle)
            pn.append(jt.name)
    n = len(links)
    if 3 * n != 2 * (len(ra) + len(ps)) + 1:
        raise ValueError(f"the loop equations are not square: {3 * n} unknowns, "
                         f"{2 * (len(ra) + len(ps)) + 1} equations (W must be 1)")
    ii = np.intp
    return _System(scene, links, L, index[scene.driver.link],
                   np.array(ra, ii), np.array(rb, ii), np.array(za, complex), np.array(zb, complex),
                   tuple(rn), np.array(ps, ii), np.array(pc, ii), np.array(zs, complex),
                   np.array(g0, complex), np.array(al, float), np.array(be, float), tuple(pn))


def _wrap(x: R) -> R:
    return (x + np.pi) % (2 * np.pi) - np.pi


class _Eval:
    """Φ, J, ν, γ at one pose (vectors of length n + 1, the frame last and fixed at 0)."""

    def __init__(self, sys: _System) -> None:
        self.sys = sys
        n, m = sys.n, sys.m
        self.J = np.zeros((m, 3 * (n + 1)))
        nr = len(sys.ra)
        self.rows_r = 2 * np.arange(nr)
        self.rows_p = 2 * nr + 2 * np.arange(len(sys.ps))
        self.row_d = m - 1

    def residual(self, X: R, Y: R, T: R, theta1: float) -> R:
        s = self.sys
        r = X + 1j * Y
        Ea = np.exp(1j * T[s.ra]) * s.za
        Eb = np.exp(1j * T[s.rb]) * s.zb
        res_r = r[s.ra] + Ea - r[s.rb] - Eb
        u = np.exp(1j * (T[s.pc] + s.alpha))
        d = r[s.ps] + np.exp(1j * T[s.ps]) * s.zs - r[s.pc] - np.exp(1j * T[s.pc]) * s.g0
        out = np.empty(s.m)
        out[self.rows_r] = res_r.real
        out[self.rows_r + 1] = res_r.imag
        out[self.rows_p] = (u.conjugate() * d).imag
        out[self.rows_p + 1] = _wrap(T[s.ps] - T[s.pc] - s.alpha + s.beta)
        out[self.row_d] = _wrap(np.array([T[s.driver] - theta1]))[0]
        return out

    def jacobian(self, X: R, Y: R, T: R) -> R:
        s = self.sys
        J = self.J
        J[:] = 0.0  # every (row, column) below is set once: plain assignment suffices
        r = X + 1j * Y
        # R joints
        iEa = 1j * np.exp(1j * T[s.ra]) * s.za
        iEb = 1j * np.exp(1j * T[s.rb]) * s.zb
        rr = self.rows_r
        J[rr, 3 * s.ra] = 1.0
        J[rr + 1, 3 * s.ra + 1] = 1.0
        J[rr, 3 * s.ra + 2] = iEa.real
        J[rr + 1, 3 * s.ra + 2] = iEa.imag
        J[rr, 3 * s.rb] = -1.0
        J[rr + 1, 3 * s.rb + 1] = -1.0
        J[rr, 3 * s.rb + 2] = -iEb.real
        J[rr + 1, 3 * s.rb + 2] = -iEb.imag
        # P joints
        if len(s.ps):
            u = np.exp(1j * (T[s.pc] + s.alpha))
            Es = np.exp(1j * T[s.ps]) * s.zs
            Ec = np.exp(1j * T[s.pc]) * s.g0
            d = r[s.ps] + Es - r[s.pc] - Ec
            uc = u.conjugate()
            rp = self.rows_p
            J[rp, 3 * s.ps] = -u.imag
            J[rp, 3 * s.ps + 1] = u.real
            J[rp, 3 * s.ps + 2] = (uc * 1j * Es).imag
            J[rp, 3 * s.pc] = u.imag
            J[rp, 3 * s.pc + 1] = -u.real
            J[rp, 3 * s.pc + 2] = -(uc * (d + Ec)).real
            J[rp + 1, 3 * s.ps + 2] = 1.0
            J[rp + 1, 3 * s.pc + 2] = -1.0
        J[self.row_d, 3 * s.driver + 2] = 1.0
        return J[:, : 3 * s.n]

    def gamma(self, X: R, Y: R, T: R, Xd: R, Yd: R, Td: R, eps1: float) -> R:
        s = self.sys
        r = X + 1j * Y
        rd = Xd + 1j * Yd
        Ea = np.exp(1j * T[s.ra]) * s.za
        Eb = np.exp(1j * T[s.rb]) * s.zb
        g_r = Td[s.ra] ** 2 * Ea - Td[s.rb] ** 2 * Eb
        out = np.zeros(s.m)
        out[self.rows_r] = g_r.real
        out[self.rows_r + 1] = g_r.imag
        if len(s.ps):
            u = np.exp(1j * (T[s.pc] + s.alpha))
            Es = np.exp(1j * T[s.ps]) * s.zs
            Ec = np.exp(1j * T[s.pc]) * s.g0
            d = r[s.ps] + Es - r[s.pc] - Ec
            wc, ws = Td[s.pc], Td[s.ps]
            dd = rd[s.ps] + 1j * ws * Es - rd[s.pc] - 1j * wc * Ec
            uc = u.conjugate()
            rest = ((-wc**2) * uc * d).imag + 2 * ((1j * wc * u).conjugate() * dd).imag \
                + (uc * (-ws**2 * Es + wc**2 * Ec)).imag
            out[self.rows_p] = -rest
        out[self.row_d] = eps1
        return out


@dataclass(frozen=True)
class NewtonResult:
    """Poses and rates of every moving link at each crank angle, SI units.

    ``pose[link] = (r0, θ)``, ``rates[link] = (v0, ω, a0, ε)`` (arrays over positions),
    the same convention as :class:`plans.kinematics.Kinematics`; ``iterations``,
    ``residual`` (‖Φ‖∞, dimensionless) and ``cond`` (2-norm condition number of the
    dimensionless Jacobian) per position."""

    scene: Scene
    phi_deg: R
    tol: float
    pose: dict[int, tuple[C, R]]
    rates: dict[int, tuple[C, R, C, R]]
    iterations: NDArray[np.int_]
    residual: R
    cond: R
    steps: NDArray[np.int_] = field(repr=False)  # continuation sub-steps taken to reach each angle

    def _local(self, link: int, name: str) -> complex:
        if link == self.scene.frame:
            return self.scene.frame_points[name]
        return self.scene.links[link].points[name]

    def point(self, name: str, link: int | None = None) -> tuple[C, C, C]:
        """r, v, a of a named point (read from the lowest-numbered moving link carrying it)."""
        if link is None:
            links = [k for k in self.scene.point_links(name) if k != self.scene.frame]
            if not links:
                z = self.scene.frame_points[name]
                zero = np.zeros(len(self.phi_deg), complex)
                return zero + z, zero, zero
            link = min(links)
        z = self._local(link, name)
        r0, th = self.pose[link]
        v0, w, a0, e = self.rates[link]
        rel = np.exp(1j * th) * z
        return r0 + rel, v0 + 1j * w * rel, a0 + (1j * e - w**2) * rel

    def theta(self, link: int) -> R:
        return self.pose[link][1]

    def omega(self, link: int) -> R:
        return self.rates[link][1]

    def eps(self, link: int) -> R:
        return self.rates[link][3]


Seed = Mapping[int, tuple[complex, float]]


def solve(scene: Scene, phi_deg: Sequence[float] | R | None = None, *, tol: float = 1e-12,
          seed: Seed | Callable[[float], Seed] | None = None, max_iter: int = 50,
          order: int = 2, condition: bool = True, system: _System | None = None) -> NewtonResult:
    """Solve the loop equations at each crank angle by Newton–Raphson with continuation.

    ``seed``: initial poses ``{link: (r0, θ)}`` (SI) for the first angle, e.g. read
    off the drawn scheme; without it every link starts at its drawn (local = global)
    pose, which only suits small mechanisms: give a seed to pick the branch.
    ``tol``: stop when the Newton step ‖Δq‖∞ ≤ tol·max(1, ‖q‖∞) (dimensionless: lengths / L).
    Raises :class:`NotAssemblable` when the corrector fails even at tiny steps and
    :class:`Locked` when the converged Jacobian is singular (cond > 1e15).
    """
    sys = system or compile_scene(scene)
    ev = _Eval(sys)
    d = scene.driver
    phis = np.atleast_1d(np.asarray(d.phis_deg if phi_deg is None else phi_deg, dtype=float))
    npos, n = len(phis), sys.n
    L = sys.L
    X, Y, T = np.zeros(n + 1), np.zeros(n + 1), np.zeros(n + 1)
    first = seed(float(phis[0])) if callable(seed) else seed
    if first:
        for lid, (r0, th) in first.items():
            if lid in scene.links:
                k = sys.links.index(lid)
                X[k], Y[k], T[k] = r0.real / L, r0.imag / L, th
    thetas = d.phi_ref + d.sense * np.radians(phis)
    T[sys.driver] = thetas[0]
    w1 = d.omega
    out_q = np.zeros((npos, 3 * n))
    out_qd = np.zeros((npos, 3 * n))
    out_qdd = np.zeros((npos, 3 * n))
    iters = np.zeros(npos, int)
    resid = np.zeros(npos)
    conds = np.full(npos, np.nan)
    steps = np.zeros(npos, int)
    q = np.concatenate([np.stack([X[:n], Y[:n], T[:n]], axis=1).ravel()])
    tangent: R | None = None
    prev = thetas[0]
    for k in range(npos):
        target = thetas[k]
        if k == 0:
            q, it, res, J = _correct(ev, q, target, tol, max_iter)
            if J is None:
                raise _not_assemblable(ev, q, target, phis[k])
            nsteps = 1
        else:
            q, it, res, J, nsteps = _continue(ev, q, tangent, prev, target, tol, max_iter, phis[k])
        prev = target
        iters[k], resid[k], steps[k] = it, res, nsteps
        Jq = J
        if condition:
            conds[k] = np.linalg.cond(Jq)
            if not math.isfinite(conds[k]) or conds[k] > COND_LOCKED:
                raise Locked(Said("nw_jacobian_loop_equations", v=conds[k]), group="loop equations",
                             point=_worst_point(ev, Jq), phi_deg=float(phis[k]))
        # tangent dq/dθ1 for the next predictor, rates from the same Jacobian
        try:
            tan_k = np.asarray(np.linalg.solve(Jq, _unit(ev)), dtype=float)
        except np.linalg.LinAlgError:
            raise Locked(Said("nw_jacobian_loop_equations2"),
                         group="loop equations", point=_worst_point(ev, Jq), phi_deg=float(phis[k])) from None
        tangent = tan_k
        out_q[k] = q
        if order >= 1:
            qd = tan_k * w1
            out_qd[k] = qd
            if order >= 2:
                Xs, Ys, Ts = _unpack(q, n)
                Xd, Yd, Td = _unpack(qd, n)
                gam = ev.gamma(Xs, Ys, Ts, Xd, Yd, Td, d.eps)
                out_qdd[k] = np.linalg.solve(Jq, gam)
    pose: dict[int, tuple[C, R]] = {}
    rates: dict[int, tuple[C, R, C, R]] = {}
    for idx, lid in enumerate(sys.links):
        x, y, t = out_q[:, 3 * idx], out_q[:, 3 * idx + 1], out_q[:, 3 * idx + 2]
        pose[lid] = (np.asarray((x + 1j * y) * L, dtype=complex), t.copy())
        xd, yd, td = out_qd[:, 3 * idx], out_qd[:, 3 * idx + 1], out_qd[:, 3 * idx + 2]
        xdd, ydd, tdd = out_qdd[:, 3 * idx], out_qdd[:, 3 * idx + 1], out_qdd[:, 3 * idx + 2]
        rates[lid] = (np.asarray((xd + 1j * yd) * L, dtype=complex), td.copy(),
                      np.asarray((xdd + 1j * ydd) * L, dtype=complex), tdd.copy())
    return NewtonResult(scene, phis, tol, pose, rates, iters, resid, conds, steps)


def _unpack(q: R, n: int) -> tuple[R, R, R]:
    z = np.zeros(n + 1)
    X, Y, T = z.copy(), z.copy(), z.copy()
    X[:n], Y[:n], T[:n] = q[0::3], q[1::3], q[2::3]
    return X, Y, T


def _correct(ev: _Eval, q: R, theta1: float, tol: float, max_iter: int,
             jump: float = math.inf) -> tuple[R, int, float, R | None]:
    """Newton–Raphson from q; J is None when it did not converge (or jumped)."""
    n = ev.sys.n
    q = q.copy()
    start = q.copy()
    J = None
    for it in range(1, max_iter + 1):
        X, Y, T = _unpack(q, n)
        F = ev.residual(X, Y, T, theta1)
        J = ev.jacobian(X, Y, T).copy()
        try:
            dq = np.linalg.solve(J, -F)
        except np.linalg.LinAlgError:
            return q, it, float(np.max(np.abs(F))), None
        if not np.all(np.isfinite(dq)):
            return q, it, float(np.max(np.abs(F))), None
        q += dq
        step = float(np.max(np.abs(dq)))
        if float(np.max(np.abs(q - start))) > jump:
            return q, it, float(np.max(np.abs(F))), None
        if step <= tol * max(1.0, float(np.max(np.abs(q)))):  # relative once the pose is far out
            X, Y, T = _unpack(q, n)
            J = ev.jacobian(X, Y, T).copy()
            res = float(np.max(np.abs(ev.residual(X, Y, T, theta1))))
            if res > max(1e3 * tol, 1e-6):  # converged steps but the equations do not hold
                return q, it, res, None
            return q, it, res, J
    X, Y, T = _unpack(q, n)
    return q, max_iter, float(np.max(np.abs(ev.residual(X, Y, T, theta1)))), None


def _continue(ev: _Eval, q: R, tangent: R | None, th0: float, th1: float, tol: float,
              max_iter: int, phi: float) -> tuple[R, int, float, R, int]:
    """From the converged q at θ1 = th0 to th1, halving the step on trouble."""
    total_it = 0
    nsteps = 0
    at, goal = th0, th1
    h = goal - at
    res = 0.0
    J: R | None = None
    while True:
        nxt = goal if abs(goal - at) <= abs(h) else at + h
        pred = q + (tangent * (nxt - at) if tangent is not None else 0.0)
        # a step that moves the pose by more than 0.25 L (or rad) past the predictor is a branch jump
        qn, it, res, J = _correct(ev, pred, nxt, tol, max_iter, jump=0.25)
        total_it += it
        if J is not None:
            q, at = qn, nxt
            nsteps += 1
            if at == goal:
                return q, total_it, res, J, nsteps
            try:
                tangent = np.asarray(np.linalg.solve(J, _unit(ev)), dtype=float)
            except np.linalg.LinAlgError:
                tangent = None
            h = h * 2 if abs(h) < abs(goal - at) else goal - at
            continue
        h /= 2
        if abs(h) < 1e-10:
            raise _not_assemblable(ev, qn, nxt, phi)


def _unit(ev: _Eval) -> R:
    nu = np.zeros(ev.sys.m)
    nu[ev.row_d] = 1.0
    return nu


def _joint_names(ev: _Eval) -> list[tuple[str, str]]:
    """(joint name, point) for each equation row."""
    s = ev.sys
    rows: list[tuple[str, str]] = [("", "")] * s.m
    for k, nm in enumerate(s.r_names):
        rows[2 * k] = rows[2 * k + 1] = (nm, nm.split(":")[1])
    base = 2 * len(s.ra)
    for k, nm in enumerate(s.p_names):
        rows[base + 2 * k] = rows[base + 2 * k + 1] = (nm, nm.split(":")[1])
    rows[-1] = ("driver", s.scene.driver.pivot)
    return rows


def _not_assemblable(ev: _Eval, q: R, theta1: float, phi: float) -> NotAssemblable:
    X, Y, T = _unpack(q, ev.sys.n)
    F = np.abs(ev.residual(X, Y, T, theta1))
    row = int(np.argmax(F))
    jn, pt = _joint_names(ev)[row]
    return NotAssemblable(Said("nw_loop_equations_have", v=F[row], jn=jn),
                          group="loop equations", point=pt, phi_deg=float(phi))


def _worst_point(ev: _Eval, J: R) -> str:
    """The joint whose equation weighs most in the Jacobian's null direction."""
    try:
        U, _, _ = np.linalg.svd(J)
    except np.linalg.LinAlgError:  # pragma: no cover
        return "?"
    row = int(np.argmax(np.abs(U[:, -1])))
    return _joint_names(ev)[row][1]


def seed_from(kin_like, k: int = 0, perturb: float = 0.0, rng: np.random.Generator | None = None) -> dict:
    """Seed poses ``{link: (r0, θ)}`` from any object with ``motion[link].r0/.theta``
    (e.g. a :class:`plans.kinematics.Kinematics` or a drawn scheme), optionally
    perturbed by ``perturb`` (relative to the mechanism's size, and in radians) so
    the corrector has work to do."""
    scene = kin_like.scene
    sys = compile_scene(scene)
    rng = rng or np.random.default_rng(0)
    out = {}
    for lid in scene.links:
        m = kin_like.motion[lid]
        r0 = complex(m.r0[k])
        th = float(m.theta[k])
        if perturb:
            r0 += sys.L * perturb * complex(*rng.uniform(-1, 1, 2))
            th += perturb * float(rng.uniform(-1, 1))
        out[lid] = (r0, th)
    return out


__all__ = ["COND_LOCKED", "COND_WARN", "NewtonResult", "compile_scene", "seed_from", "solve"]
