"""The force analysis with friction, by successive approximation as the course does it.

Solve without friction; put on every pair its friction as loads: a turning pair's
friction couple ρ·|R| against the relative rotation ω_ij, a slide's friction force f·|N|
along the guide against the relative velocity v_ij (both senses read off the velocity
plan); solve again with them; repeat until no reaction changes by more than the tolerance
(times the position's largest reaction).  The reaction of a pin is then tangent to its
friction circle, the total reaction of a slide leans from the normal by φ = arctan f.

The kinetostatics is linear in its loads, so each approximation is the frictionless
reactions plus each pair's friction load times that load's own reactions (a unit load
solved once, every pair at once along a leading axis): the same approximations, without
solving the groups again at each one.  The last approximation's friction loads are solved
in full, so its reactions satisfy every link's equilibrium to rounding.

Where a pair's relative motion stops (ω_ij = 0, v_ij = 0 at a dead centre) the sense of its
friction is undetermined: its load is left out, the pair is named and the range given
(|M_f| ≤ ρ|R|, |F_f| ≤ f|N|).  Where the approximations grow without end the mechanism
self-locks there: those positions keep the frictionless reactions, marked unconverged.
"""

from __future__ import annotations

from typing import Any

import numpy as np
from numpy.typing import NDArray

from plans.forces.loads import AppliedForce, AppliedLoads, AppliedMoment, Loads, apply_loads
from plans.forces.polygons import ForceAnalysis, Reaction, solve_applied
from plans.kinematics.exact import Kinematics
from plans.records import frozen
from plans.scene.friction import FrictionSpec, PairFriction
from plans.scene.model import Scene
from plans.units import DUST

C = NDArray[np.complex128]
R = NDArray[np.float64]

#: Approximations whose reactions grow past this many times the frictionless ones diverge.
DIVERGED = 1e6


@frozen
class PairLoss:
    """One pair's friction over the positions."""

    friction: PairFriction
    reaction: Reaction  # the frictionless analysis's reaction of this pair (its geometry)
    label: str  # "Mf12" (turning pair) or "Ff36" (slide), in the scene's F_ij convention
    sense: R  # sign of the relative motion (ω_ij, or v_ij along the guide); 0: undetermined
    relative: R  # ω_ij (rad/s) or v_ij along the guide (m/s) of link ``on`` against ``frm``
    load: R  # the friction couple (N·m) or force (N) applied, ≥ 0
    limit: R  # ρ|R| or f|N| at the converged reactions (the range where undetermined)
    loss: R  # power lost, W, ≥ 0

    @property
    def name(self) -> str:
        return self.friction.joint.name

    def labels(self, scene: Scene) -> tuple[str, str]:
        """The load's labels on link ``on`` and on link ``frm``."""
        return self.label, _label(scene, self.reaction, back=True)


@frozen
class FrictionResult:
    """The successive approximation over the positions, and the efficiency it gives."""

    spec: FrictionSpec
    frictionless: ForceAnalysis
    pairs: tuple[PairLoss, ...]  # the pairs with friction (ρ or f > 0)
    iterations: NDArray[np.int64]  # approximations solved until the reactions settled
    converged: NDArray[np.bool_]
    efficiency: R  # instantaneous η; NaN where undefined (no balancing load, or unconverged)
    power_bal: R  # the balancing load's power with friction, W
    losses: R  # Σ of the pairs' losses, W
    locking: NDArray[np.int64]  # per position, the index of the pair that self-locks there, or −1

    def self_locking(self, k: int) -> list[str]:
        """The pairs that self-lock at position k."""
        q = int(self.locking[k])
        return [] if q < 0 else [self.pairs[q].name]

    def undetermined(self, k: int) -> list[PairLoss]:
        return [p for p in self.pairs if p.sense[k] == 0 and p.friction.coefficient > 0]


def friction_analysis(scene: Scene, kin: Kinematics, loads: Loads, spec: FrictionSpec) -> ForceAnalysis:
    """The reactions and the balancing load with friction in every pair (``fa.friction``)."""
    applied = apply_loads(scene, loads, kin)
    geometry: dict = {}  # the groups' geometry, worked out by the first solve, read by the next two
    fa0 = solve_applied(scene, kin, loads, applied, geometry)
    n = kin.n
    reactions = fa0.reactions()
    rows = {rc.joint.name: q for q, rc in enumerate(reactions)}
    pairs = [p for p in spec.pairs if p.coefficient > 0 and p.joint.name in rows]
    idx = [rows[p.joint.name] for p in pairs]
    omega1 = np.abs(kin.omega(scene.driver.link))
    reach = kin.reach() if hasattr(kin, "reach") else 1.0
    senses, relatives, labels, places = [], [], [], []
    for q in idx:
        rc = reactions[q]
        rel, still = _relative(kin, rc, omega1, reach)
        senses.append(np.where(still, 0.0, np.sign(rel)))
        relatives.append(rel)
        labels.append(_label(scene, rc))
        places.append(_places(scene, kin, rc, labels[-1]))
    P = len(pairs)
    sense = np.array(senses).reshape(P, n)
    coef = np.array([p.coefficient for p in pairs]).reshape(P, 1)
    R0 = np.array([rc.F for rc in reactions])  # (Q, n)
    scale = np.max(np.abs(R0), axis=0)
    scale = np.where(scale > 0, scale, max(float(np.max(scale)) if n else 0.0, 1e-300))
    # each pair's unit friction load solved once, all pairs along a leading axis: (Q, P, n),
    # every reaction (rows) under each pair's unit load (columns), per position
    if P:
        unit = solve_applied(scene, kin, loads, _unit_loads(places, sense), geometry)
        rs = unit.reactions()
        U = np.empty((len(rs), P, n), complex)
        for q, rc in enumerate(rs):
            U[q] = rc.F
        gain = np.maximum.reduce(np.add.reduce(np.abs(U), axis=1), axis=0)
        G = U[idx]  # the pairs' own reactions
    else:
        gain, G = np.zeros(n), np.zeros((0, 0, n), complex)
    # the superposition Σ_p G_qp·m_p in real numbers, position by position: G's x and y
    # apart, (P, P, 2, n), summed over p straight into the x and y of a complex array
    Gxy = np.stack((G.real, G.imag), axis=2)
    S = np.empty((P, n), complex)
    Sxy = S.view(np.float64).reshape(P, n, 2).transpose(0, 2, 1)
    # every reaction's change is at most Σ_p |G_qp|·|Δm_p| ≤ gain·max|Δm| (the stop is never early)
    Rf0 = R0[idx]
    live = coef * (sense != 0)  # (P, n): what multiplies |R| (0 where the sense is undetermined)
    m = np.zeros((P, n))
    Rf = Rf0
    iters = np.zeros(n, np.int64)
    done = np.zeros(n, bool)
    bad = np.zeros(n, bool)
    growth = np.zeros((P, n))
    grew = np.zeros(n, np.int64)  # the pair whose friction grew most where it grows without end
    limit = spec.tolerance * scale
    largest = np.maximum.reduce
    for it in range(1, spec.max_iterations + 1):
        m_new = live * np.abs(Rf)
        growth = np.abs(m_new - m)
        m = m_new
        fresh = (gain * largest(growth, axis=0, initial=0.0) <= limit) > done  # settled now, not before
        if fresh.any():
            iters[fresh] = it
            done |= fresh
            if done.all():
                break
        if it % 8 == 0:  # growing without end: those positions stop here
            grown = ~done & (largest(m, axis=0, initial=0.0) > DIVERGED * scale)
            if grown.any():
                bad |= grown
                grew[grown] = np.argmax(growth[:, grown], axis=0)
                iters[grown] = it
                done |= grown
                live = np.where(grown, 0.0, live)
                if done.all():
                    break
        np.einsum("qpcn,pn->qcn", Gxy, m, out=Sxy)
        Rf = Rf0 + S  # superposition
    iters = np.where(done, iters, spec.max_iterations)
    if P:
        grew = np.where(done, grew, np.argmax(growth, axis=0))
    bad |= ~done
    m = np.where(bad, 0.0, m)
    fa = solve_applied(scene, kin, loads, _merge(applied, _friction_loads(places, m * sense)), geometry)
    final = fa.reactions()  # the same joints in the same order as the frictionless ones
    # every pair's limit ρ|R| or f|N| and loss at once, a row each
    limits = coef * np.abs(np.array([final[q].F for q in idx]).reshape(P, n))
    lost = m * np.abs(np.array(relatives).reshape(P, n))
    out = [PairLoss(p, reactions[q], lab, s, rel, mp, lim, loss)
           for p, s, rel, lab, mp, q, lim, loss in zip(pairs, sense, relatives, labels, m, idx, limits, lost, strict=True)]
    losses = np.sum(lost, axis=0) if out else np.zeros(n)
    power = _balancing_power(fa)
    eta = _efficiency(fa0.balancing, fa.balancing, bad)
    locking = _self_locking(out, grew, bad, eta)
    result = FrictionResult(spec, fa0, tuple(out), iters, ~bad, eta, power, losses, locking)
    return ForceAnalysis(fa.scene, fa.kin, fa.loads, fa.applied, fa.groups, fa.crank, result)


def _relative(kin: Kinematics, rc: Reaction, omega1: R, reach: float) -> tuple[R, NDArray[np.bool_]]:
    """ω_ij (turning pair) or v_ij along the guide (slide) of ``rc.on`` against ``rc.frm``,
    and where it stops (zero up to round-off against the crank's own motion)."""
    if rc.guide is None:
        rel = kin.omega(rc.on) - kin.omega(rc.frm)
        return rel, np.abs(rel) <= DUST * omega1
    v = []
    at = contact(kin, rc)
    for link in (rc.on, rc.frm):
        m = kin.motion[link]
        vl = kin.point_on(link, (at - m.r0) * np.conj(m.rot))[1]
        v.append(np.zeros(kin.n, complex) if vl is None else vl)
    rel = ((v[0] - v[1]) * np.conj(rc.guide)).real
    return rel, np.abs(rel) <= DUST * omega1 * reach


def contact(kin: Kinematics, rc: Reaction) -> C:
    """Where a slide's friction acts: its slider's pin on the guide (the joint's point)."""
    jt = rc.joint
    return kin.point(jt.point, jt.slider)[0]


def _label(scene: Scene, rc: Reaction, back: bool = False) -> str:
    """The friction load's label on link ``on`` (``back``: on ``frm``), named as F_ij is."""
    on, frm = (rc.frm, rc.on) if back else (rc.on, rc.frm)
    ij = f"{on}{frm}" if scene.fij == "on_i_from_j" else f"{frm}{on}"
    return ("Mf" if rc.guide is None else "Ff") + ij


def _places(scene: Scene, kin: Kinematics, rc: Reaction, label: str) -> list[tuple]:
    """Where a pair's friction acts on each of its links (none on the frame), worked out once:
    (link, sign, label) of a turning pair's couple, −on ``on``, + on ``frm``; a slide's force
    adds its point, the pin on the guide, the pin in the link's own coordinates and the
    guide's direction."""
    out: list[tuple] = []
    for link, sign, name in ((rc.on, -1.0, label), (rc.frm, 1.0, _label(scene, rc, back=True))):
        if link == scene.frame:
            continue
        if rc.guide is None:
            out.append((link, sign, name))
        else:
            mo = kin.motion[link]
            at = contact(kin, rc)
            out.append((link, sign, name, rc.point, at, (at - mo.r0) * np.conj(mo.rot), rc.guide))
    return out


def _friction_loads(places: list[list[tuple]], value: Any) -> AppliedLoads:
    """Each pair's friction on both its links (:func:`_places`): the couple −value on ``on``
    (+value on ``frm``) of a turning pair, the force −value·u along the guide at the pin of
    a slide; ``value`` carries the sense (its last axis the positions)."""
    forces: list[AppliedForce] = []
    moments: list[AppliedMoment] = []
    for place, val in zip(places, value, strict=True):
        for at in place:
            if len(at) == 3:
                link, sign, name = at
                moments.append(AppliedMoment(name, link, sign * val, "friction"))
            else:
                link, sign, name, point, r, local, guide = at
                forces.append(AppliedForce(name, link, point, r, local, sign * val * guide, "friction"))
    return AppliedLoads(tuple(forces), tuple(moments))


def _unit_loads(places: list[list[tuple]], sense: R) -> AppliedLoads:
    """Each pair's friction at unit size, one load case a pair (a row each, the positions
    along the last axis): a link's couples from all its pairs in one array (no two pairs
    share a row, so the sum is each pair's own), a slide's force on its own."""
    P, n = sense.shape
    couples: dict[int, tuple[str, R]] = {}
    forces: list[AppliedForce] = []
    for p, place in enumerate(places):
        for at in place:
            if len(at) == 3:
                link, sign, name = at
                if link not in couples:
                    couples[link] = (name, np.zeros((P, n)))
                couples[link][1][p] = sign * sense[p]
            else:
                link, sign, name, point, r, local, guide = at
                val = np.zeros((P, n))
                val[p] = sense[p]
                forces.append(AppliedForce(name, link, point, r, local, sign * val * guide, "friction"))
    moments = tuple(AppliedMoment(name, link, M, "friction") for link, (name, M) in couples.items())
    return AppliedLoads(tuple(forces), moments)


def _merge(a: AppliedLoads, b: AppliedLoads) -> AppliedLoads:
    return AppliedLoads(a.forces + b.forces, a.moments + b.moments)


def _balancing_power(fa: ForceAnalysis) -> R:
    """F_bal·v of its point (or M_bal·ω1), W."""
    c, kin = fa.crank, fa.kin
    if c.kind == "force":
        z = fa.scene.links[c.link].points[c.point]
        v = kin.point_on(c.link, z)[1]
        return (c.F_bal * c.e_bal * np.conj(v)).real
    return c.M_bal * kin.omega(c.link)


def _efficiency(b0: R, bf: R, bad: NDArray[np.bool_]) -> R:
    """η = F_bal,0 / F_bal where the crank drives (F_bal,0 > 0), F_bal / F_bal,0 where the
    loads drive it (F_bal,0 < 0); NaN where the balancing load vanishes or the
    approximation did not settle."""
    big = float(np.max(np.abs(b0))) if len(b0) else 0.0
    some = np.abs(b0) > DUST * big
    driving = b0 > 0
    num = np.where(driving, b0, bf)
    den = np.where(driving, bf, b0)
    ok = some & ~bad & (den != 0)
    return np.where(ok, num / np.where(ok, den, 1.0), np.nan)


def _self_locking(pairs: list[PairLoss], grew: NDArray[np.int64], bad: NDArray[np.bool_], eta: R) -> NDArray[np.int64]:
    """Per position the pair that self-locks (−1: none): where the approximations grow
    without end, the pair whose friction grew most at the last one; where the loads drive
    and η ≤ 0, the pair that loses most power there."""
    n = len(bad)
    if not pairs:
        return np.full(n, -1, np.int64)
    lost = np.argmax(np.array([p.loss for p in pairs]), axis=0)
    return np.where(bad, grew, np.where(eta <= 0, lost, -1)).astype(np.int64)


def cycle_efficiency(fa: ForceAnalysis) -> dict[str, Any] | None:
    """η over the cycle = A_useful / A_driving from the powers at the positions (a whole
    turn at equal steps; the inertia and gravity works cancel over it).  The crank drives
    (A_bal > 0): A_driving = A_bal, A_useful = A_bal − A_f; the loads drive it (A_bal < 0):
    A_useful = −A_bal, A_driving = −A_bal + A_f.  Works per second of the turn, J."""
    fr: FrictionResult | None = fa.friction
    if fr is None or fa.n == 0:
        return None
    w = np.abs(fa.kin.omega(fa.scene.driver.link))
    if not np.all(w > 0) or not np.all(fr.converged):
        return None
    dt = (2 * np.pi / fa.n) / w  # the time of each step of the turn
    a_bal = float(np.sum(fr.power_bal * dt))
    a_f = float(np.sum(fr.losses * dt))
    if a_bal > 0:
        driving, useful = a_bal, a_bal - a_f
    else:
        driving, useful = a_f - a_bal, -a_bal
    eta = useful / driving if driving > 0 else None
    return {"cycle": eta, "A_driving": driving, "A_useful": useful, "A_friction": a_f}



def _num(x: float) -> float | None:
    x = float(x)
    return x + 0.0 if np.isfinite(x) else None


def friction_json(fr: FrictionResult, fa: ForceAnalysis, k: int) -> dict[str, Any]:
    """``positions[i].friction``: η, the approximations solved, each pair's loss (W, ≥ 0), the
    balancing load with friction (signed as ``balancing``), the pairs whose sense is
    undetermined with their ranges, and whether the approximation settled."""
    ok = bool(fr.converged[k])
    und = fr.undetermined(k)
    return {
        "efficiency": _num(fr.efficiency[k]),
        "iterations": int(fr.iterations[k]),
        "converged": ok,
        "tolerance": fr.spec.tolerance,
        "losses": {p.name: float(p.loss[k]) + 0.0 for p in fr.pairs},
        "F_bal": _num(fa.balancing[k]) if ok else None,
        "F_bal_frictionless": float(fr.frictionless.balancing[k]) + 0.0,
        "undetermined": [p.name for p in und],
        "ranges": {p.name: {"load": p.label, "at_most": float(p.limit[k]) + 0.0,
                            "unit": "N*m" if p.reaction.guide is None else "N"} for p in und},
        "self_locking": fr.self_locking(k),
    }


def efficiency_json(fa: ForceAnalysis) -> dict[str, Any] | None:
    """The top-level ``efficiency``: η over the cycle and η(φ), where the scene's positions
    are a whole turn at equal steps (``[driver] positions = N``)."""
    fr: FrictionResult | None = fa.friction
    if fr is None or "positions" not in fa.scene.raw.get("driver", {}):
        return None
    cyc = cycle_efficiency(fa) or {"cycle": None}
    return {**cyc, "phi_deg": [float(x) for x in fa.kin.phi_deg], "eta": [_num(x) for x in fr.efficiency]}


def friction_lines(fa: ForceAnalysis, k: int, lang: str = "en") -> list[str]:
    """The friction of position k as text lines for ``plans solve`` (indented two spaces), in ``lang``."""
    from plans.language import symbols
    from plans.phrases import say

    fr: FrictionResult | None = fa.friction
    if fr is None:
        return []
    unit = "N" if fa.crank.kind == "force" else "N·m"
    eta = float(fr.efficiency[k])
    settled = say("fr_settled", lang, tol=fr.spec.tolerance) if fr.converged[k] else say("fr_locked", lang)
    out = [symbols(say("fr_head", lang, n=int(fr.iterations[k]), settled=settled,
                       free=float(fr.frictionless.balancing[k]), unit=unit,
                       withit=say("fr_with", lang, b=float(fa.balancing[k]), unit=unit) if fr.converged[k]
                       else say("fr_none", lang),
                       eta=say("fr_eta", lang, e=eta) if np.isfinite(eta) else say("fr_no_eta", lang)), lang)]
    for p in fr.pairs:
        kind = say("fr_couple" if p.reaction.guide is None else "fr_force", lang)
        u = "N·m" if p.reaction.guide is None else "N"
        name, label = f"{p.name:10s}", f"{symbols(p.label, lang):6s}"
        if p.sense[k] == 0:
            out.append(symbols(say("fr_stops", lang, name=name, label=label, kind=kind, lim=float(p.limit[k]),
                                   unit=u), lang))
        else:
            out.append(symbols(say("fr_pair", lang, name=name, label=label, kind=kind, load=float(p.load[k]), unit=u,
                                   loss=float(p.loss[k])), lang))
    for name in fr.self_locking(k):
        out.append(say("fr_self_locking", lang, name=name))
    return out


def cycle_line(fa: ForceAnalysis, lang: str = "en") -> str | None:
    """η over the cycle as one line, where the positions are a whole turn."""
    from plans.phrases import say

    eff = efficiency_json(fa)
    if eff is None or eff.get("cycle") is None:
        return None
    return say("fr_cycle", lang, u=eff["A_useful"], d=eff["A_driving"], e=eff["cycle"], f=eff["A_friction"])
