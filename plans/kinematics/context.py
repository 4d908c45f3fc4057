"""What the exact solvers of the groups read and fill, one position or all at once.

A :class:`Context` holds the motions of the links placed so far (:class:`Motion`: e^{iθ},
the origin and their rates), the slides and the conditions; ``xp`` is how it computes:
numpy over all positions (:data:`VEC`) or plain Python numbers at one (:data:`SCA`).
The dyads' solvers (:mod:`plans.kinematics.assur`) and the triads'
(:mod:`plans.kinematics.triad_exact`) share it; :func:`plans.kinematics.exact.solve` makes it.
"""

from __future__ import annotations

import cmath
import math
from collections.abc import Callable
from dataclasses import dataclass
from typing import Any

import numpy as np

from plans.scene.model import Scene

# numpy arrays over positions (or numbers at one position); typed loosely because numpy's
# operator stubs do not follow Optional fields that the order of analysis fills in.
C = Any  # complex128 array, shape (N,)
R = Any  # float64 array, shape (N,)


@dataclass(slots=True)
class Motion:
    rot: C  # e^{iθ}: kept as a unit complex, so no angle is ever taken in the solvers
    r0: C
    omega: R = None
    v0: C = None
    eps: R = None
    a0: C = None

    @property
    def theta(self) -> R:
        return np.angle(self.rot)



class Vec:
    """numpy over all positions."""

    sqrt = staticmethod(np.sqrt)
    maximum = staticmethod(np.maximum)
    exp = staticmethod(np.exp)
    angle = staticmethod(np.angle)
    arcsin = staticmethod(np.arcsin)

    @staticmethod
    def low(x):
        return x.min()

    @staticmethod
    def high(x):
        return x.max()

    @staticmethod
    def clip(x, lo, hi):
        return np.clip(x, lo, hi)

    @staticmethod
    def full(n, v):
        return np.full(n, v)


class Sca:
    """Plain Python numbers, one position."""

    sqrt = staticmethod(math.sqrt)
    maximum = staticmethod(max)
    exp = staticmethod(cmath.exp)
    angle = staticmethod(cmath.phase)
    arcsin = staticmethod(math.asin)

    @staticmethod
    def low(x):
        return x

    @staticmethod
    def high(x):
        return x

    @staticmethod
    def clip(x, lo, hi):
        return min(max(x, lo), hi)

    @staticmethod
    def full(n, v):
        return v


VEC = Vec()
SCA = Sca()


class Context:
    """What the group solvers read and fill: motions, slides, conditions."""

    __slots__ = ("scene", "xp", "phis", "n", "order", "motion", "slides", "conditions", "frame",
                 "crank", "pivot", "zpivot", "W", "E", "pins", "solve")

    def __init__(self, scene: Scene, xp: Any, phis: Any, order: int, solve: Callable[..., Any]) -> None:
        self.scene = scene
        self.solve = solve  # the exact solver (a triad solves the groups before it over a turn)
        self.n = len(phis)
        self.xp = xp
        self.phis = phis
        self.order = order
        self.motion: dict[int, Motion] = {}
        self.slides: dict[str, tuple[Any, Any]] = {}
        self.conditions: dict[str, Any] = {}
        self.frame = scene.frame
        d = scene.driver
        # the crank turns at constant ω1, ε1 about its pivot: its points in four operations
        self.crank = d.link
        self.pivot = scene.frame_points[d.pivot]
        self.zpivot = scene.links[d.link].points[d.pivot]
        self.W = 1j * d.omega
        self.E = complex(-d.omega * d.omega, d.eps)
        self.pins: dict[complex, tuple] = {}


def point_at(ctx: Context, link: int, z: complex) -> tuple[Any, Any, Any]:
    """r, v, a of the point with local coordinates z on a known link (v, a only as ordered)."""
    m = ctx.motion[link]
    if link == ctx.frame:
        return m.r0 + z, m.v0, m.a0
    if link == ctx.crank and z != ctx.zpivot:
        done = ctx.pins.get(z)  # the crank pin carries several groups (V-engine)
        if done is None:
            rel = m.rot * (z - ctx.zpivot)
            done = ctx.pins[z] = (ctx.pivot + rel, ctx.W * rel, ctx.E * rel)
        return done
    if not z:
        return m.r0, m.v0, m.a0
    rel = m.rot * z
    v = a = None
    if ctx.order >= 1:
        w = 1j * m.omega
        v = m.v0 + w * rel
        if ctx.order >= 2:
            a = m.a0 + (1j * m.eps - m.omega * m.omega) * rel
    return m.r0 + rel, v, a


def place_link(ctx: Context, link: int, rot: C, anchor: C, z: complex) -> Motion:
    """A link placed by its rotation e^{iθ} and one of its points (local z)."""
    m = Motion(rot, anchor - rot * z if z else anchor)
    ctx.motion[link] = m
    return m
