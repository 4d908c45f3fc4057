"""The draftsman's tolerance model: a drawn figure's error propagated through its construction.

The velocity and acceleration plans are drawn again, by the same construction as the plans
(:mod:`plans.kinematics.dyads`), with a linearised pencil (:class:`Linearised`); a force
polygon's protocol is replayed step by step (:class:`Propagation`)."""

from __future__ import annotations

import cmath
from typing import Any

import numpy as np

from plans.kinematics.accelerations import acceleration_plan
from plans.kinematics.dyads import PerfectPencil, Scheme, unit
from plans.kinematics.exact import Kinematics
from plans.kinematics.plan import Plan
from plans.kinematics.velocities import velocity_plan
from plans.tolerances import LOCK_SIN


class Propagation:
    """A force polygon's tolerance: its protocol replayed with one draftsman's error at a time.

    Errors: each laid-off vector's length (±seg) and direction (±dir), each construction
    line's direction (±dir).  Sensitivities are first order (small steps) and add up in the
    worst case (a stack-up of limits: a figure fails only if no combination of step errors
    within the limits explains it), plus ±seg for reading the segment.  (The velocity and
    acceleration plans are drawn again with the :class:`LinearisedPencil` instead.)"""

    def __init__(self, plan: Plan, seg_mm: float, dir_rad: float) -> None:
        self.seg = seg_mm
        self.base = {p.name: complex(*p.xy) for p in plan.points}
        self.coincide = {p.name: p.coincides_with for p in plan.points if p.coincides_with}
        self.ops: list[tuple] = []
        self.sizes: list[float] = []
        degenerate = {d.split(":")[0] for d in plan.degenerate}
        lines = list(plan.lines)
        li = 0
        for st in plan.steps:
            if st.op == "lay off" and st.inputs and st.inputs[0] in self.base and st.output in self.base:
                vec = self.base[st.output] - self.base[st.inputs[0]]
                self.ops.append(("lay", st.output, st.inputs[0], vec, self._param(seg_mm), self._param(dir_rad)))
            elif st.op == "intersect" and li + 1 < len(lines) and len(st.inputs) == 2:
                l1, l2 = lines[li], lines[li + 1]
                li += 2
                p1, p2 = complex(*l1.point), complex(*l2.point)
                i1, i2 = st.inputs
                ok = (i1 in self.base and i2 in self.base and abs(self.base[i1] - p1) < 1e-6 * (1 + abs(p1))
                      and abs(self.base[i2] - p2) < 1e-6 * (1 + abs(p2)))
                if not ok or st.output in degenerate:
                    self.ops.append(("keep", st.output))
                else:
                    self.ops.append(("cut", st.output, i1, complex(*l1.direction), i2, complex(*l2.direction),
                                     self._param(dir_rad), self._param(dir_rad)))
        self._base_state = self._run(np.zeros(len(self.sizes)))
        self._cache: dict[tuple[str, str], float] = {}

    def _param(self, size: float) -> int:
        self.sizes.append(size)
        return len(self.sizes) - 1

    def _run(self, d: np.ndarray) -> dict[str, complex]:
        st = dict(self.base)
        for op in self.ops:
            kind = op[0]
            if kind == "lay":
                _, out, inp, vec, pl, pd = op
                n = abs(vec)
                u = vec / n if n > 0 else 1.0 + 0j
                st[out] = st[inp] + (vec + d[pl] * u) * cmath.exp(1j * d[pd])
            elif kind == "cut":
                _, out, i1, d1, i2, d2, p1, p2 = op
                e1, e2 = d1 * cmath.exp(1j * d[p1]), d2 * cmath.exp(1j * d[p2])
                s = (e1.conjugate() * e2).imag
                if abs(s) < LOCK_SIN:
                    continue
                t = ((st[i2] - st[i1]).conjugate() * e2).imag / s
                st[out] = st[i1] + t * e1
            elif kind == "keep":
                partner = self.coincide.get(op[1])
                if partner is not None and partner in st:
                    st[op[1]] = st[partner]
        return st

    def tolerance(self, a: str, b: str) -> float:
        key = (a, b)
        if key in self._cache:
            return self._cache[key]
        base = self._base_state
        if a not in base or b not in base:
            return self.seg
        L0 = abs(base[b] - base[a])
        total = self.seg
        h = 1e-3
        for i, size in enumerate(self.sizes):
            d = np.zeros(len(self.sizes))
            d[i] = h * size
            st = self._run(d)
            dL = (abs(st[b] - st[a]) - L0) / h
            if L0 < 1e-9:  # a vanishing vector: how far its end moves
                dL = abs((st[b] - st[a]) - (base[b] - base[a])) / h
            total += abs(dL)
        out = total
        self._cache[key] = out
        return out


# --------------------------------------------------------------------------- report objects


class LinearisedPencil:
    """The checker's pencil for :mod:`plans.kinematics.dyads`: the construction drawn once
    without error (case 0) and once per drawing error, each error alone and small (cases
    1…P, first order).  Errors: each laid-off vector's length (±seg, plus ``carried`` for a
    component computed from velocity-plan figures) and direction (±dir), each construction
    line's direction (±dir), each point found by similarity (±seg along its link's image).
    A first pass with one case counts the errors (:attr:`sizes`)."""

    exact = True

    def __init__(self, seg_mm: float, dir_rad: float, carried: dict[str, float], cases: int = 1,
                 h: float = 1e-3) -> None:
        self.seg, self.dir, self.carried, self.cases, self.h = seg_mm, dir_rad, carried, cases, h
        self.sizes: list[float] = []

    def _d(self, size: float) -> np.ndarray:
        d = np.zeros(self.cases)
        if len(self.sizes) + 1 < self.cases:
            d[len(self.sizes) + 1] = self.h * size
        self.sizes.append(size)
        return d

    def vector(self, length: Any, direction: Any, span: Any, out: str) -> np.ndarray:
        dl = self._d(self.seg + self.carried.get(out, 0.0))
        return (length + dl) * unit(direction) * np.exp(1j * self._d(self.dir))

    def line(self, direction: Any, span: Any) -> np.ndarray:
        return unit(direction) * np.exp(1j * self._d(self.dir))

    def mark(self, z: Any, along: Any = None, joint: bool = False) -> np.ndarray:
        return z + self._d(self.seg) * (1.0 if along is None else unit(along()))

    def read(self, length: Any) -> Any:
        return length

    cut = PerfectPencil.cut


class Linearised:
    """A plan's draftsman tolerances from the same construction drawn with the
    :class:`LinearisedPencil`: a segment's worst case is the sum of its first-order changes
    under each error at its limit (a stack-up), plus ±seg for reading it."""

    def __init__(self, kin: Kinematics, k: int, kind: str, mv: float, ma: float | None, seg_mm: float, dir_rad: float,
                 carried: dict[str, float] | None = None, h: float = 1e-3) -> None:
        self.seg = seg_mm
        carried = carried or {}

        def draw(pencil: LinearisedPencil) -> dict[str, np.ndarray]:
            snap = Scheme(kin, [k])
            if kind == "velocity":
                return velocity_plan(snap, mv, pencil).pts
            assert ma is not None
            vb = velocity_plan(snap, mv, PerfectPencil())
            return acceleration_plan(snap, ma, vb, pencil).pts

        count = LinearisedPencil(seg_mm, dir_rad, carried)
        draw(count)
        pencil = LinearisedPencil(seg_mm, dir_rad, carried, cases=len(count.sizes) + 1, h=h)
        self.pts = draw(pencil)
        self.h = pencil.h
        self._cache: dict[tuple[str, str], float] = {}

    def tolerance(self, a: str, b: str) -> float:
        if (a, b) not in self._cache:
            if a not in self.pts or b not in self.pts:
                return self.seg
            vec = np.ravel(self.pts[b] - self.pts[a])
            if vec.size < 2:
                self._cache[(a, b)] = self.seg
                return self.seg
            L = np.abs(vec)
            if L[0] < 1e-9:  # a vanishing vector: how far its end moves
                d = np.abs(vec[1:] - vec[0]) / self.h
            else:
                d = np.abs(L[1:] - L[0]) / self.h
            self._cache[(a, b)] = self.seg + float(np.sum(d))
        return self._cache[(a, b)]
