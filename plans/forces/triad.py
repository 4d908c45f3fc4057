"""Kinetostatics of a class-III group (triad) by Assur's special point.

The base link b carries the inner pairs D, E, F; the leashes AD, BE, CF join them to the
known links at A, B, C.  The reaction of a known link on leash k at its outer pair is split
as for a dyad's outer revolute: R_k = R_k^τ (⟂ the leash) + R_k^n (along it).

* Each leash's moments about its inner pair give its R_k^τ = M_k(P_k)/l_k (the inner pair's
  reaction passes through P_k, R_k^n along the leash too).
* The axes of two leashes i, j meet at Assur's point S: R_i^n and R_j^n pass through S, so the
  moments of the whole group about S give the third leash's R_m^n (its arm: S to the axis m,
  zero only at the group's special position).
* The group's polygon closes with R_i^n ∥ axis i and R_j^n ∥ axis j (two directions intersected).
* Each leash's polygon gives the reaction of the leash on the base link at its inner pair.

S is chosen per position as the velocity plan chooses it: AD and BE unless nearly parallel,
then BE and CF, then AD and CF.
"""

from __future__ import annotations

from collections.abc import Mapping
from dataclasses import field
from typing import Any

import numpy as np
from numpy.typing import NDArray

from plans.errors import Locked, Said
from plans.forces.loads import AppliedForce, AppliedMoment
from plans.forces.shared import force_sum, moment_about, safe_div, unit_vector
from plans.kinematics.exact import Kinematics
from plans.kinematics.structure import TriadGroup
from plans.kinematics.triad_plans import PAIRS, pair_choice
from plans.lines import cross
from plans.records import frozen
from plans.tolerances import COINCIDE_REL, LOCK_SIN

C = NDArray[np.complex128]
R = NDArray[np.float64]


@frozen
class TriadForces:
    """One class-III group in equilibrium over positions.

    ``loads[k]``/``moments[k]`` are the known loads on ``group.links[k]`` (base first, then the
    leashes, reactions from farther groups included).  ``reactions``: the three outer ones
    (on leash k from its known link, with τ and n components), then the three inner ones (on
    the base link from leash k).  ``S``: Assur's point per position; ``pair``: the index in
    :data:`PAIRS` of the two leashes whose axes give it."""

    group: TriadGroup
    loads: tuple[tuple[AppliedForce, ...], ...]
    moments: tuple[tuple[AppliedMoment, ...], ...]
    reactions: tuple[Any, ...]  # six polygons.Reaction
    S: C
    pair: NDArray[np.int_]
    #: ΣM_S of the whole group's known loads and the τ components (N·m): what R_m^n balances
    moment_S: R
    #: per leash: the unit direction of its axis (outer → inner pair, or the guide's normal for
    #: a slider), R^τ along i·axis and R^n along the axis (a slider's τ is 0: its guide's
    #: reaction is N along the normal through the pin and the guide's couple)
    axes: tuple[C, C, C]
    tau: tuple[R, R, R]
    normal: tuple[R, R, R]
    arms: Mapping[tuple[str, str], R] = field(default_factory=dict)

    def slider(self, k: int) -> bool:
        return self.group.joints[k][0].kind == "P"

    def leashes(self, k: int) -> tuple[int, int, int]:
        """(i, j, m) at position k: the leashes giving S, then the third."""
        i, j = PAIRS[int(self.pair[k])]
        return i, j, 3 - i - j


def solve_triad(kin: Kinematics, g: TriadGroup, forces: dict, moments: dict, Reaction: Any) -> TriadForces:
    """The six reactions of the group, exact, vectorised over the positions of ``kin``
    (``Reaction``: the polygons' record of a joint's reaction, passed by its caller)."""
    from plans.kinematics.triad_plans import axes_of

    n = kin.n
    base = g.links[0]
    leashes = g.links[1:]
    Q, axis, P = axes_of(kin, g)
    Q = [np.broadcast_to(x, (n,)) for x in Q]
    u = [unit_vector(np.broadcast_to(a, (n,))) for a in axis]  # along the leash, outer → inner
    length = [np.abs(a) for a in axis]
    e = [1j * x for x in u]
    links = g.links
    fl = [tuple(forces[x]) for x in links]
    ml = [tuple(moments[x]) for x in links]
    slider = [o.kind == "P" for o, _ in g.joints]
    block = [d.kind == "P" for _, d in g.joints]

    def tau_of(k: int) -> R:
        if slider[k]:  # the guide's reaction is all along the normal (and a couple)
            return np.zeros(n)
        if block[k]:  # the block along the slot: R^τ (∥ slot) balances its loads there
            return -(np.conj(e[k]) * force_sum(fl[1 + k], n)).real
        return moment_about(fl[1 + k], ml[1 + k], P[k], n) / length[k]  # ΣM_P(leash) = 0: −l·R^τ + M(P) = 0
    # a slider: the guide's couple −M_k(P), no τ
    tau = [tau_of(k) for k in range(3)]
    couple = [-moment_about(fl[1 + k], ml[1 + k], P[k], n) if slider[k] else np.zeros(n) for k in range(3)]
    pair = pair_choice(axis)
    ii = np.array([PAIRS[c][0] for c in range(3)])[pair]
    jj = np.array([PAIRS[c][1] for c in range(3)])[pair]
    mm = 3 - ii - jj
    Qs, us = np.stack(Q), np.stack(u)
    cols = np.arange(n)
    Qi, Qj, Qm = Qs[ii, cols], Qs[jj, cols], Qs[mm, cols]
    ui, uj, um = us[ii, cols], us[jj, cols], us[mm, cols]
    sin = cross(ui, uj)
    bad = np.abs(sin) <= LOCK_SIN
    if bad.any():
        _locked(kin, g, bad, Said("tp_three_leashes_axes"))
    S = Qi + cross(Qj - Qi, uj) / np.where(bad, 1.0, sin) * ui
    everything_f = [f for fs in fl for f in fs]
    everything_m = [m for ms in ml for m in ms]
    known_S = moment_about(everything_f, everything_m, S, n)
    for k in range(3):
        known_S = known_S + cross(Q[k] - S, tau[k] * e[k]) + couple[k]
    arm_m = cross(Qm - S, um)  # R_m^n·arm_m + known_S = 0
    size = max(float(np.max(np.abs(a))) for a in axis)
    bad = np.abs(arm_m) <= COINCIDE_REL * size
    if bad.any():
        _locked(kin, g, bad, Said("tr_forces_one_point"))
    nrm = np.zeros((3, n))
    nrm[mm, cols] = -known_S / np.where(bad, 1.0, arm_m)
    rest = force_sum(everything_f, n) + sum(tau[k] * e[k] for k in range(3)) + nrm[mm, cols] * um
    # rest + n_i·u_i + n_j·u_j = 0
    n_i = cross(-rest, uj) / sin
    n_j = cross(ui, -rest) / sin
    nrm[ii, cols] = n_i
    nrm[jj, cols] = n_j
    zero = np.zeros(n)
    outer, inner = [], []
    for k, (o, d) in enumerate(g.joints):
        Rk = tau[k] * e[k] + nrm[k] * u[k]
        if slider[k]:  # N ⟂ the guide at the pin and the guide's couple
            outer.append(Reaction(o, leashes[k], g.known[k], P[k], Rk, couple[k], guide=-1j * u[k]))
        else:
            outer.append(Reaction(o, leashes[k], g.known[k], Q[k], Rk, zero, tau=tau[k], n=nrm[k], e_tau=e[k],
                                  e_n=u[k]))
        # leash k in equilibrium: the base's reaction on it is −(R_k + its loads); a block's
        # slot takes its loads' moment about the pin as the slot's couple
        if block[k]:
            inner.append(Reaction(d, base, leashes[k], P[k], Rk + force_sum(fl[1 + k], n),
                                  moment_about(fl[1 + k], ml[1 + k], P[k], n), guide=-1j * u[k]))
        else:
            inner.append(Reaction(d, base, leashes[k], P[k], Rk + force_sum(fl[1 + k], n), zero))
    arms = _Arms(g, fl, P, S, Qm, um)
    return TriadForces(g, tuple(fl), tuple(ml), tuple(outer) + tuple(inner), S, pair, known_S,
                       (u[0], u[1], u[2]), (tau[0], tau[1], tau[2]), (nrm[0], nrm[1], nrm[2]), arms)


class _Arms(Mapping):
    """Lever arms of the moment equations, worked out when first read: each leash's loads about
    its inner pair, the whole group's loads about S."""

    def __init__(self, g: TriadGroup, fl, P, S, Qm, um) -> None:
        self._args = (g, fl, P, S, Qm, um)
        self._done: dict | None = None

    def _arms(self) -> dict:
        if self._done is None:
            g, fl, P, S, Qm, um = self._args
            out: dict[tuple[str, str], R] = {}
            for k, (_, d) in enumerate(g.joints):
                for f in fl[1 + k]:
                    out[(f"M_{d.point}({g.links[1 + k]})", f.label)] = safe_div(np.abs(cross(f.r - P[k], f.F)),
                                                                                np.abs(f.F))
            for fs in fl:
                for f in fs:
                    out[(f"M_S({g.name})", f.label)] = safe_div(np.abs(cross(f.r - S, f.F)), np.abs(f.F))
            self._done = out
        return self._done

    def __getitem__(self, key: Any) -> R:
        return self._arms()[key]

    def __iter__(self):
        return iter(self._arms())

    def __len__(self) -> int:
        return len(self._arms())


def _locked(kin: Kinematics, g: TriadGroup, bad: NDArray[np.bool_], why: Said) -> None:
    k = int(np.flatnonzero(bad)[0])
    raise Locked(why, group=f"class III {g.kind} {g.name}", point=g.point, phi_deg=float(kin.phi_deg[k]))
