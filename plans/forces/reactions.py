"""What the kinetostatics finds, over the positions: each joint's reaction (the force on one
link from the other, a slide's couple and where its resultant acts), each Assur group in
equilibrium with its known loads, the driving link with its balancing load, and the whole
analysis that every table, polygon, lever and check reads."""

from __future__ import annotations

from collections.abc import Callable, Mapping
from dataclasses import field, replace
from typing import Any

import numpy as np
from numpy.typing import NDArray

from plans.forces.loads import (
    AppliedForce,
    AppliedLoads,
    AppliedMoment,
    Loads,
)
from plans.forces.shared import safe_div
from plans.kinematics.exact import Kinematics
from plans.kinematics.structure import Group
from plans.lines import cross
from plans.records import derived, frozen
from plans.scene.model import Joint, Scene

C = NDArray[np.complex128]
R = NDArray[np.float64]


@frozen
class Reaction:
    """The reaction of one joint: force on link ``on`` from link ``frm``, over positions.

    R joint: F at the pin ``r``.  P joint: F ⟂ ``guide`` at the slider's pin ``r`` plus the
    couple ``M``; the resultant acts on the guide at ``offset`` = M/N from ``r``."""

    joint: Joint
    on: int
    frm: int
    r: C
    F: C
    M: R
    guide: C | None = None  # unit direction of the guide (P joints)
    tau: R | None = None  # F^τ along e_tau (outer revolute of a dyad)
    n: R | None = None  # F^n along e_n
    e_tau: C | None = None
    e_n: C | None = None

    @property
    def point(self) -> str:
        return self.joint.point

    def name(self, fij: str) -> str:
        """F_ij in the scene's convention: on_i_from_j → F{on}{frm}, of_i_on_j → F{frm}{on}."""
        return f"F{self.on}{self.frm}" if fij == "on_i_from_j" else f"F{self.frm}{self.on}"

    def reversed(self) -> Reaction:
        """The same joint's reaction on the other link (F_ji = −F_ij): F, the couple, F^τ and F^n
        change sign, e_τ and e_n stay (so F_12^τ = −F_21^τ along the same e_τ)."""
        return replace(self, on=self.frm, frm=self.on, F=-self.F, M=-self.M,
                       tau=None if self.tau is None else -self.tau, n=None if self.n is None else -self.n)

    @property
    def N(self) -> R:
        """Signed normal force ⟂ guide (along i·guide), P joints."""
        assert self.guide is not None
        return cross(self.guide, self.F)

    @property
    def offset(self) -> R:
        """x along the guide from the pin to the resultant (m); 0 where N = 0 (pure couple)."""
        if self.guide is None:
            return np.zeros(len(self.M))
        return safe_div(self.M, self.N)


@frozen
class GroupForces:
    """One Assur group in equilibrium: its known loads and its three reactions over positions."""

    group: Group
    loads_i: tuple[AppliedForce, ...]  # known forces on i (reactions from farther groups included)
    loads_j: tuple[AppliedForce, ...]
    moments_i: tuple[AppliedMoment, ...]
    moments_j: tuple[AppliedMoment, ...]
    reactions: tuple[Reaction, Reaction, Reaction]  # J1 (on i from p), J2 (on i from j), J3 (on j from q)
    #: lever arms h (m) of the moment equations: (equation, label) -> |arm| over positions
    arms: Mapping[tuple[str, str], R] = field(default_factory=dict)


@frozen
class CrankForces:
    """The driving link in equilibrium: its loads, the balancing load and the frame's reaction."""

    link: int
    loads: tuple[AppliedForce, ...]  # everything on the crank except the balancing load and the frame
    moments: tuple[AppliedMoment, ...]
    kind: str  # "force" | "moment"
    point: str
    r_point: C
    e_bal: C  # unit ⟂ crank, counter-clockwise
    F_bal: R  # along e_bal (force mode), N; 0 in moment mode
    M_bal: R  # balancing moment about the pivot, N·m ccw+ (F_bal·l in force mode)
    frame: Reaction  # on the crank from the frame
    arms: Mapping[str, R] = field(default_factory=dict)


@frozen(weakref_slot=True)
class ForceAnalysis:
    """The kinetostatics of a scene: every group and the crank, over the positions."""

    scene: Scene
    kin: Kinematics
    loads: Loads
    applied: AppliedLoads
    groups: tuple[GroupForces, ...]  # in solving order: farthest first
    crank: CrankForces
    #: the successive approximation with friction (plans.forces.friction.FrictionResult), or None
    friction: Any = None

    @property
    def n(self) -> int:
        return self.kin.n

    def on_paper(self, scene: Scene) -> ForceAnalysis:
        """This analysis read with ``scene``, the same mechanism at another fit (the polygons'
        and the lever's target lengths): the same reactions, nothing solved again; what is
        derived from it (no fit enters that) is kept for the other too."""
        if scene is self.scene:
            return self
        other = replace(self, scene=scene, kin=self.kin.on_paper(scene))
        derived(other).update(derived(self))
        return other

    def _once(self, key: str, make: Callable[[], Any]) -> Any:
        """What every position's table and polygons read again, worked out once and kept
        beside the record (:func:`plans.records.derived`; arrays made read-only)."""
        kept = derived(self)
        got = kept.get(key)
        if got is None:
            got = kept[key] = make()
            if isinstance(got, np.ndarray):
                got.flags.writeable = False
        return got

    @property
    def largest_reaction(self) -> float:
        """The largest reaction over the positions (N): what sets the scale of a polygon
        whose forces all vanish."""
        return self._once("largest", lambda: max((float(np.max(np.abs(rc.F))) for rc in self.reactions()),
                                                 default=0.0))

    def reactions(self) -> list[Reaction]:
        """Every joint's reaction once, crank–frame first, then groups in attachment order."""
        out = [self.crank.frame]
        for gf in reversed(self.groups):
            out.extend(gf.reactions)
        return out

    def reaction(self, name: str) -> tuple[C, Reaction]:
        """A reaction by its F_ij name in the scene's convention, either order (F_ij = −F_ji):
        the force and the reaction so named (the other order :meth:`Reaction.reversed`)."""
        for rc in self.reactions():
            if rc.name(self.scene.fij) == name:
                return rc.F, rc
            rev = rc.name("of_i_on_j" if self.scene.fij == "on_i_from_j" else "on_i_from_j")
            if rev == name:
                return -rc.F, rc.reversed()
        raise KeyError(name)

    @property
    def sense(self) -> R:
        """+1 where the balancing point moves counter-clockwise about the pivot."""
        return self._once("sense", lambda: np.where(self.kin.omega(self.scene.driver.link) < 0, -1.0, 1.0))

    @property
    def balancing(self) -> R:
        """The balancing load, positive along the motion of its point (N, or N·m for a moment)."""
        c = self.crank
        return self._once("balancing", lambda: self.sense * (c.F_bal if c.kind == "force" else c.M_bal))
