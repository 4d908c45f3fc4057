"""A force polygon as it is drawn: the known forces laid off head to tail at μF, closed by the
unknown reactions' directions (the closing point where their lines meet), each vector with its
label and what it reads."""

from __future__ import annotations

import numpy as np
from numpy.typing import NDArray

from plans.forces.reactions import CrankForces, ForceAnalysis, GroupForces, Reaction  # noqa: F401  (importable from here)
from plans.forces.shared import RULER_MM
from plans.kinematics.plan import ConstructionLine, Plan, PlanPoint, Segment, Step, Written
from plans.lines import along, cross, meet
from plans.phrases import Phrase, phrase
from plans.records import frozen
from plans.units import clean

C = NDArray[np.complex128]
R = NDArray[np.float64]


@frozen
class ForcePolygon:
    """The closed force polygon of one group (or of the crank) at one position.

    ``plan`` holds the vertices (plan mm, start "o"), the vectors head to tail in
    drawing order (kind "force" for known ones, "closing" for the ones found), the two
    construction lines whose intersection closes it, and the protocol."""

    group: str  # "2-3", or "1" for the initial link
    kind: str  # "RRR", ..., or "crank"
    plan: Plan

    @property
    def scale(self) -> float:
        return self.plan.scale

    def reading(self, label: str) -> float:
        """What a draftsman reads: the vector's length to the ruler's precision, over μF (N)."""
        return round(self.plan.segment(label).length_mm / RULER_MM) * RULER_MM / self.plan.scale


def closing_point(e: complex, d_end: complex, s: complex, d_start: complex, reach: float) -> complex | None:
    """Where the construction line through ``e`` along ``d_end`` meets the one through ``s``
    along ``d_start``, each drawn ``reach`` (in units of its direction) either side of its
    point; None where the drawn lines do not cross in one point (parallel, or so nearly
    that they would meet beyond them): then the polygon's two closing reactions lie on
    one line."""
    if cross(d_end, d_start) == 0:
        return None
    t_e, t_s = along(e, d_end, s, d_start)
    if not (abs(t_e) <= reach and abs(t_s) <= reach):
        return None
    return complex(meet(e, d_end, s, d_start))


class Poly:
    """Head-to-tail construction at one position, in plan mm."""

    def __init__(self, mu: float) -> None:
        self.mu = mu
        self.pts: dict[str, complex] = {"o": 0j}
        self.order = ["o"]
        self.cur = "o"
        self.segs: list[Segment] = []
        self.lines: list[ConstructionLine] = []
        self.steps: list[tuple[str, tuple[str, ...], str, Phrase]] = []  # written when read (Written)
        self._written: tuple[Step, ...] | None = None
        self.ends: dict[str, tuple[str, str]] = {}
        self.notes: list[str] = []

    def _new(self, z: complex) -> str:
        k = len(self.order)
        name = "abcdefghijklmnqrstuvwxyz"[k - 1] if k <= 24 else f"v{k}"
        self.pts[name] = z
        self.order.append(name)
        return name

    def _seg(self, a: str, b: str, kind: str, label: str) -> None:
        length = abs(self.pts[b] - self.pts[a])
        self.segs.append(Segment(a, b, kind, label, length, length / self.mu))
        self.ends[label] = (a, b)

    def lay(self, label: str, F: complex) -> None:
        if F == 0:
            return
        start = self.cur
        end = self._new(self.pts[start] + F * self.mu)
        self._seg(start, end, "force", label)
        shown = clean(abs(F), 100.0 / self.mu)  # against the polygon's size (its longest ≈ 100 mm)
        self.steps.append(("lay off", (start,), end, phrase(
            "f_lay", start=start, end=end, label=label, F=shown, mm=abs(F) * self.mu)))
        self.cur = end

    def intersect(self, label_end: str, d_end: complex, label_start: str, d_start: complex,
                  start: str = "o") -> str:
        """Close with two known directions: through the current end along d_end, through
        ``start`` along d_start; the two construction lines intersected."""
        e, s = self.pts[self.cur], self.pts[start]
        reach = 10.0 * (max(abs(z) for z in self.pts.values()) + 100.0)
        hit = closing_point(e, d_end, s, d_start, reach)
        if hit is not None:
            x = hit
        else:  # coincident lines: the exact analysis already refused locked groups, so the
            x = s  # closing vectors vanish here (the known ones sum to zero along the line)
            self.notes.append(f"{label_end} and {label_start} lie on one line")
        self.lines.append(ConstructionLine((e.real, e.imag), (d_end.real, d_end.imag), f"line of {label_end}"))
        self.lines.append(ConstructionLine((s.real, s.imag), (d_start.real, d_start.imag),
                                           f"line of {label_start}"))
        end = self.cur
        xn = self._new(x)
        self._seg(end, xn, "closing", label_end)
        self._seg(xn, start, "closing", label_start)
        self.steps.append(("intersect", (end, start), xn, phrase(
            "f_meet", end=end, start=start, le=label_end, ls=label_start, xn=xn)))
        self.cur = xn
        return xn

    def close(self, label: str, to: str = "o") -> None:
        a = self.cur
        if abs(self.pts[a] - self.pts[to]) == 0:
            self.notes.append(f"{label} = 0")
        self._seg(a, to, "closing", label)
        self.steps.append(("closing", (a, to), label, phrase("f_close", label=label, a=a, to=to)))
        self.cur = to

    def join(self, label: str, a: str, b: str, why: str | Phrase) -> None:
        self._seg(a, b, "closing", label)
        words = why if isinstance(why, Phrase) else phrase("f_sum", x=why)
        self.steps.append(("closing", (a, b), label, phrase("f_join", label=label, a=a, b=b, why=words)))

    def total(self, friction: str, normal: str, x: str) -> None:
        """A slide's total reaction N + F_f where its friction was laid just before N."""
        if friction in self.ends and self.ends[friction][1] == self.ends[normal][0]:
            self.join(f"{normal}Σ", self.ends[friction][0], x, f"{normal} + {friction}")

    def end_of(self, labels: list[str], default: str) -> str:
        for lab in reversed(labels):
            if lab in self.ends:
                return self.ends[lab][1]
        return default

    def recorded(self) -> int:
        return len(self.steps)

    def written(self) -> tuple[Step, ...]:
        """The steps' sentences, written once (the plan's :class:`Written` reads them)."""
        if self._written is None:
            self._written = tuple(Step.of(*r) for r in self.steps)
        return self._written

    def plan(self, phi: float) -> Plan:
        pts = []
        seen: dict[tuple[float, float], str] = {}
        for nm in self.order:
            z = self.pts[nm]
            key = (round(z.real, 9), round(z.imag, 9))
            pts.append(PlanPoint(nm, (z.real, z.imag), seen.get(key)))
            seen.setdefault(key, nm)
        return Plan("force", phi, self.mu, "o", tuple(pts), tuple(self.segs), tuple(self.lines),
                    Written(self), tuple(self.notes))
