"""Velocity and acceleration plans built as a draftsman builds them, at every position at once.

On the scheme drawn at the crank angle, the draftsman lays off the known vectors from
the pole, draws the two construction lines of each Assur group (⟂ a link, ∥ a guide)
through known plan points and intersects them, then finds further points by the
similarity theorem (:mod:`plans.kinematics.velocities`, :mod:`plans.kinematics.accelerations`,
drawn with the perfect pencil of :mod:`plans.kinematics.dyads`).  Angular velocities,
normal and Coriolis components are read off the plan already drawn, never taken from the
exact analysis; the exact analysis is used only to report each reading's error and as the
draftsman's answer where two construction lines are (nearly) parallel.

:func:`build_all` builds the plans of all positions together, as arrays; each position's
:class:`Plan` objects and readings are made when first asked for, and its protocol (the
sentences of each step) only when read.  One position (:func:`build`, a scene of one
position, a protocol) is built by the same construction in Python numbers.
"""

from __future__ import annotations

from collections.abc import Sequence
from typing import Any

import numpy as np

from plans.errors import Locked
from plans.kinematics.dyads import Builder, Mixed, Pencil, PerfectPencil, Scheme
from plans.kinematics.exact import Kinematics
from plans.kinematics.plan import ConstructionLine, Plan, PlanPoint, Segment, Step
from plans.kinematics.scales import LONGEST_MM, ROUND, common_scales, refit, round_scale
from plans.phrases import phrase
from plans.records import frozen
from plans.tolerances import AGREE_REL, COINCIDE_REL
from plans.units import clean, percent

_NICE = ROUND  # round both ways: μ and K = 1/μ


def nice_scale(longest: float, target_mm: float = 100.0, mantissas: tuple[float, ...] = _NICE) -> float:
    """μ (mm per unit) with K = 1/μ a round number, so that ``longest`` is drawn as
    the longest vector not above ``target_mm`` (75–100 mm): how a draftsman picks it
    (:func:`plans.kinematics.scales.round_scale`)."""
    return round_scale(longest, target_mm, mantissas)


@frozen
class Reading:
    """A value read off a plan next to the exact value."""

    quantity: str  # "v_B", "omega_2", "a_BA^n", ...
    segment: str | None  # segment read ("p_v b") or None for derived values
    length_mm: float | None
    scale: float | None
    value: float  # read off the drawing (signed for ω, ε)
    exact: float
    unit: str
    ref: float  # size of the plan in this unit (the known vector), floor for relative errors

    @property
    def difference(self) -> float:
        return clean(self.value - self.exact, max(abs(self.exact), self.ref))

    @property
    def percent(self) -> float | None:
        """Signed difference, % of max(|exact|, ref); None where the exact value is zero."""
        return percent(self.value, self.exact, self.ref)

    @property
    def relative(self) -> float:
        """|difference| / max(|exact|, ref): a vanishing quantity (b on the pole) is
        compared with the size of the plan it is read from, not with zero."""
        den = max(abs(self.exact), self.ref)
        return abs(self.difference) / den if den > 0 else 0.0

    def to_json(self) -> dict:
        return {"quantity": self.quantity, "segment": self.segment, "length_mm": self.length_mm,
                "scale": self.scale, "value": self.value, "exact": self.exact, "unit": self.unit,
                "difference": self.difference, "relative": self.relative}


class PositionPlans:
    """Both plans at one position and the readings off them (made when first asked for)."""

    __slots__ = ("phi_deg", "_velocity", "_acceleration", "_readings", "_source", "_k")

    def __init__(self, phi_deg: float, velocity: Plan | None = None, acceleration: Plan | None = None,
                 readings: tuple[Reading, ...] = (), *, source: _Together | None = None, k: int = 0) -> None:
        self.phi_deg = phi_deg
        self._velocity, self._acceleration, self._readings = velocity, acceleration, readings
        self._source, self._k = source, k

    @property
    def velocity(self) -> Plan | None:
        if self._source is not None and self._velocity is None:
            self._velocity = self._source.plan(self._source.vb, self._k)
        return self._velocity

    @property
    def acceleration(self) -> Plan | None:
        if self._source is not None and self._acceleration is None and self._source.ab is not None:
            self._acceleration = self._source.plan(self._source.ab, self._k)
        return self._acceleration

    @property
    def readings(self) -> tuple[Reading, ...]:
        if self._source is not None and not self._readings:
            self._readings = self._source.readings(self._k)
        return self._readings

    def __repr__(self) -> str:
        return f"PositionPlans(phi_deg={self.phi_deg!r})"


# --------------------------------------------------------------------------- plans


_PERFECT = PerfectPencil()


def plans_of(snap: Scheme, mv: float, ma: float | None, pencil: Pencil,
             protocol: bool = False) -> tuple[Builder, Builder | None]:
    """Both plans over the cases of ``snap`` (the acceleration plan when ``ma`` is given)."""
    from plans.kinematics import (  # loaded with the first plan, not at start
        accelerations,
        velocities,
    )

    vb = velocities.velocity_plan(snap, mv, pencil, protocol)
    ab = accelerations.acceleration_plan(snap, ma, vb, pencil, protocol) if ma is not None else None
    return vb, ab


def _at(x: Any, k: int) -> Any:
    if type(x) is not np.ndarray:  # a number: one position, or the same at every position
        return x
    a = np.ravel(x)
    return a[k] if a.size > 1 else a[0]


class _Together:
    """The plans of the selected positions built together (arrays over positions; one
    position, ``ks`` an ``int``, in Python numbers)."""

    def __init__(self, kin: Kinematics, ks: Any, mv: float, ma: float | None) -> None:
        self.kin, self.ks, self.mv, self.ma = kin, ks, mv, ma
        snap = Scheme(kin, ks)
        self.phi = [snap.phi] if snap.one else snap.phi
        self.vb, self.ab = plans_of(snap, mv, ma, _PERFECT)
        self._columns: list[tuple] | None = None
        self._plan_cols: dict[str, tuple] = {}
        self._protocols: dict[tuple[str, int], tuple[Step, ...]] = {}  # written when first read

    def position(self, k: int) -> PositionPlans:
        return PositionPlans(float(self.phi[k]), source=self, k=k)

    def may_run_past(self, longest_mm: float) -> list[int]:
        """The positions where a plan's largest distance from the pole (:attr:`Plan.extent`)
        may exceed ``longest_mm``, from the arrays (with a margin for rounding)."""
        limit = longest_mm * (1 - AGREE_REL)
        plans = [b for b in (self.vb, self.ab) if b is not None]
        if type(self.ks) is int:  # one position: numbers
            return [0] if any(abs(b.pts[name]) > limit for b in plans for name in b.order) else []
        far = np.zeros(len(self.phi), dtype=bool)
        for b in plans:
            for name in b.order:
                far |= np.abs(b.pts[name]) > limit
        return np.flatnonzero(far).tolist()

    def readings(self, k: int) -> tuple[Reading, ...]:
        if type(self.ks) is int:  # one position: the readings are numbers already
            return tuple(Reading(q, seg, None if mm is None else float(mm), mu, float(value), float(exact), unit,
                                 float(ref))
                         for b in (self.vb, self.ab) if b is not None
                         for q, seg, mm, mu, value, exact, unit, ref, _ in b.readings)
        if self._columns is None:  # each reading's arrays as lists, once for all positions
            n = len(self.phi)

            def col(x: Any) -> list[float]:
                return np.broadcast_to(np.asarray(x, float), (n,)).tolist()

            self._columns = [(q, seg, None if mm is None else col(mm), mu, col(value), col(exact), unit, col(ref))
                             for b in (self.vb, self.ab) if b is not None
                             for q, seg, mm, mu, value, exact, unit, ref, _ in b.readings]
        return tuple(Reading(q, seg, None if mm is None else mm[k], mu, value[k], exact[k], unit, ref[k])
                     for q, seg, mm, mu, value, exact, unit, ref in self._columns)

    def _plan_columns(self, b: Builder) -> tuple:
        """A plan's arrays as Python lists over the positions, once for all of them (reading
        them element by element from numpy is most of the time of every position's plan)."""
        key = "velocity" if b is self.vb else "acceleration"
        got = self._plan_cols.get(key)
        if got is None:
            n = len(self.phi)
            pts = {name: _column(b.pts[name], n, complex) for name in b.order}
            segs = [(s, e, kind, label, _column(mm, n, float), _column(v, n, float))
                    for s, e, kind, label, mm, v in b.segments]
            lines = [(_column(through, n, complex), _column(u, n, complex), label) for through, u, label in b.lines]
            got = self._plan_cols[key] = (pts, segs, lines)
        return got

    def plan(self, b: Builder, k: int) -> Plan:
        pts, segs, cols = self._plan_columns(b)
        points, _ = _points(b, k, {name: col[k] for name, col in pts.items()})
        segments = tuple(Segment(s, e, kind, label, mm[k], v[k]) for s, e, kind, label, mm, v in segs)
        lines = []
        for through, u, label in cols:
            p, d = through[k], u[k]
            lines.append(ConstructionLine((p.real, p.imag), (d.real, d.imag), label))
        degenerate = tuple(f"{out}: construction lines parallel within {float(_at(s, k)):.1e} rad; "
                           f"the exact point is taken" for out, near, s in b.degenerate if _at(near, k))
        return Plan(kind=b.kind, phi_deg=float(self.phi[k]), scale=b.mu, pole=b.pole, points=points,
                    segments=segments, lines=tuple(lines), steps=_Protocol(self, b.kind, k),
                    degenerate=degenerate)

    def protocol(self, kind: str, k: int) -> tuple[Step, ...]:
        """The steps of one plan at one position, sentences written (built again for it alone),
        once: kept here, where the plans were built."""
        got = self._protocols.get((kind, k))
        if got is None:
            got = self._protocols[(kind, k)] = self._protocol(kind, k)
        return got

    def _protocol(self, kind: str, k: int) -> tuple[Step, ...]:
        kk = self.ks if type(self.ks) is int else int(np.arange(self.kin.n)[self.ks][k])
        vb, ab = plans_of(Scheme(self.kin, kk), self.mv, self.ma, _PERFECT, protocol=True)
        b = vb if kind == "velocity" else ab
        assert b is not None
        _, coincide = _points(b, 0)
        return tuple(b.steps) + tuple(coincide)


class _Protocol(Sequence[Step]):
    """A plan's steps, written when first read (a sheet or a printout asks; a table never does):
    an unchanging view of the steps its construction (:class:`_Together`) writes once and keeps."""

    __slots__ = ("_source", "_kind", "_k")

    def __init__(self, source: _Together, kind: str, k: int) -> None:
        self._source, self._kind, self._k = source, kind, k

    def _get(self) -> tuple[Step, ...]:
        return self._source.protocol(self._kind, self._k)

    def __getitem__(self, i: Any) -> Any:
        return self._get()[i]

    def __len__(self) -> int:
        return len(self._get())

    def __eq__(self, other: object) -> bool:
        return isinstance(other, Sequence) and tuple(self) == tuple(other)

    def __hash__(self) -> int:
        return hash(self._get())


def _column(x: Any, n: int, kind: type) -> list:
    """``_at(x, k)`` for every k < n, as Python numbers of ``kind``."""
    if type(x) is not np.ndarray:
        return [kind(x)] * n
    a = np.ravel(x)
    return [kind(v) for v in a.tolist()] if a.size > 1 else [kind(a[0])] * n


def _points(b: Builder, k: int, at: dict[str, complex] | None = None) -> tuple[tuple[PlanPoint, ...], list[Step]]:
    """The plan's points at position k (``at``: their values there, when known), each
    coinciding point noted (with its step)."""
    pts = at if at is not None else {name: complex(_at(b.pts[name], k)) for name in b.order}
    extent = max((abs(z) for z in pts.values()), default=0.0)
    tol = COINCIDE_REL * max(extent, 1e-300)
    points, steps = [], []
    seen: list[str] = []
    for name in b.order:
        xy = pts[name]
        same = next((o for o in seen if abs(pts[o] - xy) <= tol), None)
        points.append(PlanPoint(name, (float(xy.real), float(xy.imag)), same))
        if same is None:
            seen.append(name)
        elif name != b.pole:
            steps.append(Step.of("coincide", (same,), name, phrase("coincide", name=name, same=same)))
    return tuple(points), steps


def _scales(kin: Kinematics, velocity_scale: float | None, acceleration_scale: float | None
            ) -> tuple[float | None, float | None]:
    scene = kin.scene
    if not (scene.wants("velocity_plan") and kin.order >= 1):
        return None, None
    common: tuple[float, float] | None = None

    def default(i: int) -> float:
        nonlocal common
        common = common or default_scales(kin)
        return common[i]

    mv = velocity_scale or scene.scales.get("velocity") or default(0)
    ma = None
    if scene.wants("acceleration_plan") and kin.order >= 2:
        ma = acceleration_scale or scene.scales.get("acceleration") or default(1)
    return mv, ma


def build(kin: Kinematics, k: int, *, velocity_scale: float | None = None,
          acceleration_scale: float | None = None) -> PositionPlans:
    """Both plans at position ``k`` (as far as the scene asks and the kinematics reaches)."""
    return build_many(kin, [k], velocity_scale=velocity_scale, acceleration_scale=acceleration_scale)[0]


#: Up to this many positions are each built alone, in Python numbers: over arrays numpy's
#: cost per call (about 1.5 ms for both plans of the V-engine) outweighs 0.2-0.3 ms a position.
ALONE_MAX = 4


def _alone(kin: Kinematics, ks: Sequence[int], mv: float, ma: float | None) -> list[_Together]:
    """Each position of ``ks`` built alone, in Python numbers (a lock names the first
    position, as drawn)."""
    return [_Together(kin, int(k), mv, ma) for k in ks]


def build_many(kin: Kinematics, ks: Sequence[int], *, velocity_scale: float | None = None,
               acceleration_scale: float | None = None) -> list[PositionPlans]:
    """Both plans at each position of ``ks``: built together (one construction over arrays),
    a few positions, or where a label differs between positions or a group locks, one by one."""
    mv, ma = _scales(kin, velocity_scale, acceleration_scale)
    if mv is None:
        return [PositionPlans(float(kin.phi_deg[k]), None, None, ()) for k in ks]
    if len(ks) > ALONE_MAX:
        try:
            together = _Together(kin, list(ks), mv, ma)
        except (Mixed, Locked):
            pass
        else:
            return [together.position(i) for i in range(len(ks))]
    return [t.position(0) for t in _alone(kin, ks, mv, ma)]


def default_scales(kin: Kinematics) -> tuple[float, float]:
    """μv and μa as the course picks them: the crank pin's vector (the known one)
    drawn 50–100 mm at a round scale (or as ``[scales]`` says), the same at every position."""
    return common_scales(kin)


def build_all(kin: Kinematics) -> list[PositionPlans]:
    """Plans at every position of the scene, with one round scale for all (as on one sheet;
    a position whose plan would run too long gets a round one of its own), built together;
    position by position for a few positions, or where a label differs between positions or
    a group locks (the error then names the first position, as drawn one by one)."""
    mv, ma = default_scales(kin)
    want_mv, want_ma = _scales(kin, mv, ma)
    if want_mv is None:
        return [PositionPlans(float(phi), None, None, ()) for phi in kin.phi_deg]
    if kin.n > ALONE_MAX:
        try:
            together = _Together(kin, slice(None), want_mv, want_ma)
        except (Mixed, Locked):
            pass
        else:
            return refit(kin, [together.position(k) for k in range(kin.n)], build,
                         only=together.may_run_past(LONGEST_MM))
    alone = _alone(kin, range(kin.n), want_mv, want_ma)
    return refit(kin, [t.position(0) for t in alone], build,
                 only=[k for k, t in enumerate(alone) if t.may_run_past(LONGEST_MM)])


__all__ = ["Reading", "PositionPlans", "build", "build_all", "build_many", "default_scales", "nice_scale"]
