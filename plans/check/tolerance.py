"""The draftsman's tolerance model: a drawn figure's error propagated through its construction."""

from __future__ import annotations

import cmath
import itertools
import re
from typing import Any

import numpy as np

from plans.kinematics.exact import Kinematics
from plans.kinematics.plan import Plan


class Propagation:
    """Replays a plan's protocol with one draftsman's error at a time.

    Parameters: each laid-off vector's length (±seg, plus for a normal or Coriolis
    component the tolerance of the velocity-plan figures it is computed from) and direction (±dir), each
    construction line's direction (±dir), each point found by similarity (±seg along
    the link's image).  Sensitivities are first order (small steps) and add up in the
    worst case (a stack-up of limits: a figure fails only if no combination of
    step errors within the limits explains it), plus ±seg for reading the segment."""

    def __init__(self, plan: Plan, kin: Kinematics, k: int, seg_mm: float, dir_rad: float,
                 carried: dict[str, float] | None = None) -> None:
        self.plan = plan
        self.seg = seg_mm
        self.carried = carried or {}  # laid-off point -> extra length tolerance (mm) from the velocity plan
        self.base = {p.name: complex(*p.xy) for p in plan.points}
        self.coincide = {p.name: p.coincides_with for p in plan.points if p.coincides_with}
        self.ops: list[tuple] = []
        self.sizes: list[float] = []
        scene = kin.scene
        degenerate = {d.split(":")[0] for d in plan.degenerate}
        lines = list(plan.lines)
        li = 0
        self._done: set[str] = {plan.pole}  # points drawn so far, in the protocol's order
        for st in plan.steps:
            self._step(st, lines, li, degenerate, seg_mm, dir_rad, scene, kin, k)
            li = self._li
            self._done.add(st.output)
        self._base_state = self._run(np.zeros(len(self.sizes)))
        self._cache: dict[tuple[str, str], float] = {}

    def _step(self, st: Any, lines: list, li: int, degenerate: set[str], seg_mm: float, dir_rad: float,
              scene: Any, kin: Kinematics, k: int) -> None:
        """One protocol step as an operation to replay (``self._li``: the next construction line)."""
        self._li = li
        if st.op == "lay off" and st.inputs and st.inputs[0] in self.base and st.output in self.base:
            vec = self.base[st.output] - self.base[st.inputs[0]]
            self.ops.append(("lay", st.output, st.inputs[0], vec, self._param(seg_mm + self.carried.get(st.output, 0.0)),
                             self._param(dir_rad)))
        elif st.op == "intersect" and li + 1 < len(lines) and len(st.inputs) == 2:
            l1, l2 = lines[li], lines[li + 1]
            li += 2
            self._li = li
            p1, p2 = complex(*l1.point), complex(*l2.point)
            i1, i2 = st.inputs
            ok = (i1 in self.base and i2 in self.base and abs(self.base[i1] - p1) < 1e-6 * (1 + abs(p1))
                  and abs(self.base[i2] - p2) < 1e-6 * (1 + abs(p2)))
            if not ok or st.output in degenerate:
                self.ops.append(("keep", st.output))
                return
            self.ops.append(("cut", st.output, i1, complex(*l1.direction), i2, complex(*l2.direction),
                             self._param(dir_rad), self._param(dir_rad)))
        elif st.op == "similarity":
            op = self._similarity(st.text, st.output, scene, kin, k)
            if op is not None:
                self.ops.append(op)

    def _param(self, size: float) -> int:
        self.sizes.append(size)
        return len(self.sizes) - 1

    def _similarity(self, text: str, out: str, scene: Any, kin: Kinematics, k: int) -> tuple | None:
        m = re.search(r"on link (\d+) \((\S+) of link", text) or re.search(r"point of link (\d+) under (\S+) ", text)
        if not m:
            return None
        lid, name = int(m.group(1)), m.group(2)
        if lid == scene.frame or lid not in scene.links:
            return ("keep", out)
        X = complex(kin.point(name)[0][k]) if scene.point_links(name) else None
        if X is None:
            return None
        link = scene.links[lid]
        known = []
        for pname in link.points:
            lab = self.plan.pole if pname in scene.frame_points else pname.lower()
            if lab == out or lab not in self.base or lab not in self._done:
                continue
            known.append((lab, complex(kin.point_on(lid, link.points[pname])[0][k])))
        # images of other links' points under this link, already drawn (a3: A of the rocker 3
        # under the block, found by intersection; it anchors the rocker's image)
        for lab in self._done:
            m = re.fullmatch(r"([a-z][a-z0-9]*?)(\d+)", lab)
            if not m or int(m.group(2)) != lid or lab == out or lab not in self.base:
                continue
            pname = m.group(1).upper()
            if pname in link.points or not scene.point_links(pname):
                continue
            known.append((lab, complex(kin.point(pname)[0][k])))
        if len(known) < 2:
            return ("keep", out)
        (la, Pa), (lb, Pb) = max(itertools.combinations(known, 2), key=lambda c: abs(c[0][1] - c[1][1]))
        if abs(Pb - Pa) == 0:
            return ("keep", out)
        ratio = (X - Pa) / (Pb - Pa)
        return ("sim", out, la, lb, ratio, self._param(self.seg))

    def _run(self, d: np.ndarray) -> dict[str, complex]:
        st = dict(self.base)
        moved: dict[str, complex] = {}
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
                if abs(s) < 1e-12:
                    continue
                t = ((st[i2] - st[i1]).conjugate() * e2).imag / s
                st[out] = st[i1] + t * e1
            elif kind == "sim":
                _, out, la, lb, ratio, pa = op
                span = st[lb] - st[la]
                u = span / abs(span) if abs(span) > 0 else 1.0 + 0j
                st[out] = st[la] + span * ratio + d[pa] * u
            elif kind == "keep":
                partner = self.coincide.get(op[1])
                if partner is not None and partner in st:
                    st[op[1]] = st[partner]
            moved[op[1]] = st[op[1]]
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

