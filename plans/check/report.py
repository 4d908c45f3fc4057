"""Checking a hand-drawn sheet: the student's figures against the exact analysis.

For every figure the student wrote (:mod:`plans.checkfile`) the report gives the exact
value, the error in % and in mm on the student's drawing at the student's scales, and
a verdict against a tolerance:

* ``draftsman`` model: a laid-off or measured segment is good to ±``segment_mm`` and a
  drawn direction to ±``direction_deg``; these errors are propagated through the
  construction of the plan drawn at the student's scale (the plan's protocol replayed
  with each error in turn, first order, worst-case sum) and the reading adds one more
  ±``segment_mm``.  A normal or Coriolis component, computed from figures read off the
  velocity plan and then laid off, carries their tolerance into its length; a point found
  by similarity from a coincident image (the shaper's d from a3) moves with that image.
  A short vector found by intersecting nearly parallel lines gets a
  wide tolerance, a long vector laid off from the pole a narrow one.  Figures that
  are computed rather than drawn (masses, reactions without the student's μF, ...)
  fall back to the course rule.
* ``rule`` model: every figure within ±``rule_pct`` % of the exact value.

Independently of the exact values, the student's own work is checked for
consistency (:data:`RELATIONS`: value = segment/μ, ω = v/l, ε = a^τ/l, a^n = v²/l,
Φ = m a, M_Φ = I ε, similarity ratios, the % difference of the balancing forces),
for the same quantity written twice with different values, for figures that
symmetry makes equal, for π = 3.14, for a wrong scale and for swapped segments.

Exact values come from a table of providers keyed by quantity name
(:data:`PROVIDERS`): plan segments, angular rates, lengths of the scheme, masses
and inertia loads (:mod:`plans.loads`), reactions and the balancing force
(:mod:`plans.forces`), lever arms.

JSON (``plans check FILE --json PATH``)::

    {"format": 1, "student": ..., "check_file": ..., "scene": ..., "tolerance": {...},
     "scales": {"velocity": μv, ...},
     "items": [{"quantity", "phi_deg", "student", "student_mm", "exact", "exact_mm", "unit",
                "error_pct", "error_mm", "tolerance", "tolerance_mm", "tolerance_pct",
                "tolerance_model", "verdict": "pass" | "fail", "where", "field", "source"}],
     "findings": [{"kind", "message", "phi_deg", "quantities", "where", "fields"}],
     "unchecked": [{"quantity", "phi_deg", "student", "reason", "where"}],
     "summary": {"items", "passed", "failed", "findings"}}
"""

from __future__ import annotations

import argparse
import cmath
import csv
import io
import itertools
import math
import re
import sys
from collections.abc import Callable
from dataclasses import dataclass, field, replace
from pathlib import Path
from typing import Any

import numpy as np

from plans.check.checkfile import CheckFile, StudentPosition, Written, load_check
from plans.errors import InputError, OutputError, PlansError, one_line
from plans.io import atomic_write, dumps, refuse_input, write_all
from plans.kinematics.construction import PositionPlans, build
from plans.kinematics.exact import Kinematics, solve
from plans.kinematics.plan import Plan

G_STANDARD = 9.81
#: An exact value below this fraction of its plan's size is zero (a point on the pole).
ZERO_REL = 1e-9
PI_314 = 3.14


# --------------------------------------------------------------------------- exact values


@dataclass(frozen=True, slots=True)
class Exact:
    """The exact value of one quantity at one position, and how it sits on the drawing."""

    quantity: str
    value: float  # magnitude, SI
    unit: str
    mm_per_unit: float | None  # mm on the student's drawing per unit of value
    tol_mm: float | None  # draftsman tolerance on the drawing (mm); None: course rule
    source: str  # provider
    plan: str | None = None  # "velocity" | "acceleration" | "scheme" (for the sheet)
    segment: tuple[str, str] | None = None  # plan points the value is read between
    ref: float = 0.0  # size of the plan in this unit (floor for % near zero)


class Context:
    """Everything exact for one check file: kinematics, plans at the student's scales,
    loads and forces when the scene has them, and the draftsman's error propagation."""

    def __init__(self, cf: CheckFile) -> None:
        self.cf = cf
        self.scene = cf.scene
        self.kin: Kinematics = solve(cf.scene, order=2)
        mv = cf.scales.get("velocity")
        ma = cf.scales.get("acceleration")
        self.plans: dict[int, PositionPlans] = {}
        for pos in cf.positions:
            self.plans[pos.index] = build(self.kin, pos.index, velocity_scale=mv, acceleration_scale=ma)
        self._prop: dict[tuple[int, str], _Propagation] = {}
        self._polygons: dict[int, tuple[Plan, ...]] = {}
        self._forces: Any = None
        self._forces_error: str | None = None
        self._loaded = False

    # -- plans
    def plan(self, k: int, kind: str) -> Plan | None:
        pp = self.plans[k]
        return pp.velocity if kind == "velocity" else pp.acceleration

    def propagation(self, k: int, kind: str) -> _Propagation | None:
        key = (k, kind)
        if key not in self._prop:
            plan = self.plan(k, kind)
            if plan is None:
                return None
            tol = self.cf.tolerance
            extra = self._carried(k, plan) if kind == "acceleration" else {}
            self._prop[key] = _Propagation(plan, self.kin, k, tol.segment_mm, math.radians(tol.direction_deg),
                                           extra)
        return self._prop[key]

    def _carried(self, k: int, plan: Plan) -> dict[str, float]:
        """Normal and Coriolis components are computed from figures read off the velocity plan
        (a^n = v²/l, a^k = 2ωv_r) and then laid off: the tolerance of those readings carries
        into their length (mm on the acceleration plan), keyed by the point laid off."""
        out: dict[str, float] = {}
        crank = self.scene.links[self.scene.driver.link]
        for sg in plan.segments:
            if sg.kind not in ("normal", "coriolis") or sg.length_mm <= 0:
                continue
            body = re.fullmatch(r"a(?:\^k)?_([A-Za-z0-9]+)(?:\^n)?", sg.label)
            if body is None or set(_points(body.group(1))) <= set(crank.points):
                continue  # the crank's components come from the data (ω1, ε1, l_OA), not the plan
            if sg.kind == "normal":
                m = re.fullmatch(r"a_([A-Za-z0-9]+)\^n", sg.label)
                v = _plan_segment(self, k, f"v_{m.group(1)}") if m else None
                if v is None or not v.tol_mm or not v.mm_per_unit or v.value <= 0:
                    continue
                out[sg.end] = sg.length_mm * 2 * v.tol_mm / (v.value * v.mm_per_unit)
            else:
                m = re.fullmatch(r"a\^k_([A-Za-z0-9]+)", sg.label)
                pts = _points(m.group(1)) if m else []
                if len(pts) != 2:
                    continue
                v = _plan_segment(self, k, f"v_{pts[0]}{pts[1]}")
                links = [int(x.group(1)) for x in (re.fullmatch(r"[A-Z][a-z]*(\d+)", t) for t in pts) if x]
                links = sorted((lk for lk in links if lk in self.scene.links),
                               key=lambda lk: (len(self.scene.links[lk].axis) != 2, lk))
                w = _angular(self, k, f"omega_{links[0]}") if links else None
                rels = [x.tol_mm / (x.value * x.mm_per_unit) for x in (v, w)
                        if x is not None and x.tol_mm and x.mm_per_unit and x.value > 0]
                # two separate readings (each already a worst case over the velocity plan's
                # steps, sharing most of them): combined in quadrature, not added once more
                out[sg.end] = sg.length_mm * math.hypot(*rels) if rels else 0.0
        return out

    def tol_mm(self, k: int, kind: str, a: str, b: str) -> float | None:
        if self.cf.tolerance.model != "draftsman":
            return None
        pr = self.propagation(k, kind)
        if pr is None:
            return None
        return pr.tolerance(a, b)

    # -- forces (optional modules)
    def forces(self) -> Any:
        if not self._loaded:
            self._loaded = True
            try:
                from plans.forces import loads as _loads
                from plans.forces import polygons as _forces

                loads = _loads.parse_loads(self.scene)
                self._forces = (loads, _forces.analyse_forces(self.scene, self.kin, loads))
            except ImportError as exc:  # pragma: no cover - modules are part of the package
                self._forces_error = f"force analysis unavailable ({exc})"
            except PlansError as exc:
                self._forces_error = f"force analysis failed: {exc}"
        return self._forces

    def polygons(self, k: int) -> tuple[Plan, ...]:
        """The force polygons of position k drawn at the student's μF (none without μF)."""
        if k not in self._polygons:
            mu_f = self.cf.scales.get("force")
            got = self.forces()
            out: tuple[Plan, ...] = ()
            if mu_f and got is not None:
                from plans.forces import polygons as _forces

                loads, _ = got
                scene = replace(self.scene, scales={**self.scene.scales, "force": mu_f})
                fa = _forces.analyse_forces(scene, self.kin, loads)
                out = tuple(fp.plan for fp in _forces.force_polygons(fa, k))
            self._polygons[k] = out
        return self._polygons[k]

    def polygon_segment(self, k: int, labels: tuple[str, ...]) -> tuple[int, str, str] | None:
        """(polygon index, start, end) of the first segment labelled one of ``labels``."""
        for i, plan in enumerate(self.polygons(k)):
            for lab in labels:
                for sg in plan.segments:
                    if sg.label == lab:
                        return i, sg.start, sg.end
        return None

    def polygon_tol(self, k: int, i: int, a: str, b: str) -> float | None:
        if self.cf.tolerance.model != "draftsman":
            return None
        key = (k, f"force-{i}")
        if key not in self._prop:
            tol = self.cf.tolerance
            self._prop[key] = _Propagation(self.polygons(k)[i], self.kin, k, tol.segment_mm,
                                           math.radians(tol.direction_deg))
        return self._prop[key].tolerance(a, b)

    def pos(self, k: int, name: str) -> complex:
        return complex(self.kin.point(name)[0][k])


# -- providers: (name, pattern, function(ctx, k, quantity) -> Exact | None) -------------


def _label(ctx: Context, plan: Plan, point: str) -> str | None:
    if point in ctx.scene.frame_points:
        return plan.pole
    lab = point.lower()
    if plan.has(lab):
        return lab
    # A2 written for the block's own point A: its image is labelled a (a2 only when it differs)
    m = re.fullmatch(r"([A-Z][a-z]*)(\d+)", point)
    if m:
        link = ctx.scene.links.get(int(m.group(2)))
        base = m.group(1)
        if link is not None and base in link.points and plan.has(base.lower()):
            return base.lower()
    return None


_POINT = re.compile(r"[A-Z][a-z0-9]*")


def _points(token: str) -> list[str]:
    pts = _POINT.findall(token)
    return pts if "".join(pts) == token else []


def _plan_segment(ctx: Context, k: int, q: str) -> Exact | None:
    kind = "velocity" if q.startswith("v_") else "acceleration"
    plan = ctx.plan(k, kind)
    if plan is None:
        return None
    unit = "m/s" if kind == "velocity" else "m/s^2"
    ref = (abs(complex(*plan.xy("a"))) / plan.scale) if plan.has("a") else 0.0
    seg = None
    try:
        s = plan.segment(q)
        seg = (s.start, s.end)
    except KeyError:
        mk = re.fullmatch(r"a\^([kr])_([A-Za-z0-9]+)", q)
        if mk:  # a^k_A2A3 written for a^k_A3A2: the same segment
            pts = _points(mk.group(2))
            if len(pts) == 2:
                try:
                    s = plan.segment(f"a^{mk.group(1)}_{pts[1]}{pts[0]}")
                    seg = (s.start, s.end)
                except KeyError:
                    pass
        m = re.fullmatch(r"([va])_([A-Za-z0-9]+)(\^[nτ])?", q)
        if m and not m.group(3):
            pts = _points(m.group(2))
            if len(pts) in (1, 2):
                labs = [plan.pole] if len(pts) == 1 else []
                labs += [_label(ctx, plan, p) or "" for p in pts]
                if all(labs):
                    seg = (labs[0], labs[1])
        if m and m.group(3) and seg is None:  # a_AB^τ written for a_BA^τ
            pts = _points(m.group(2))
            if len(pts) == 2:
                try:
                    s = plan.segment(f"{m.group(1)}_{pts[1]}{pts[0]}{m.group(3)}")
                    seg = (s.start, s.end)
                except KeyError:
                    pass
    if seg is None:
        return None
    a, b = seg
    mm = abs(complex(*plan.xy(b)) - complex(*plan.xy(a)))
    return Exact(q, mm / plan.scale, unit, plan.scale, ctx.tol_mm(k, kind, a, b), "plan", kind, seg, ref)


def _link_axis(ctx: Context, lid: int) -> tuple[str, str] | None:
    link = ctx.scene.links.get(lid)
    if link is None or len(link.axis) != 2:
        return None
    return link.axis[0], link.axis[1]


def _angular(ctx: Context, k: int, q: str) -> Exact | None:
    m = re.fullmatch(r"(omega|eps)_(\d+)", q)
    assert m
    lid = int(m.group(2))
    if lid not in ctx.scene.links:
        return None
    kind = "velocity" if m.group(1) == "omega" else "acceleration"
    value = abs(float((ctx.kin.omega(lid) if kind == "velocity" else ctx.kin.eps(lid))[k]))
    unit = "rad/s" if kind == "velocity" else "rad/s^2"
    plan = ctx.plan(k, kind)
    axis = _link_axis(ctx, lid)
    if plan is None or axis is None:  # a slider: moves with its guide
        return Exact(q, value, unit, None, None, "kinematics")
    P, Q = axis
    length = abs(ctx.scene.links[lid].points[Q] - ctx.scene.links[lid].points[P])
    mu = plan.scale * length
    seg = None
    if kind == "velocity":
        a, b = _label(ctx, plan, P), _label(ctx, plan, Q)
        if a and b:
            seg = (a, b)
    else:
        for label in (f"a_{Q}{P}^τ", f"a_{P}{Q}^τ"):
            try:
                s = plan.segment(label)
                seg = (s.start, s.end)
                break
            except KeyError:
                continue
        if seg is None:  # a^τ of another pair of the link's points: a_A3C^τ on a slotted lever
            found = _tangential_on(ctx, k, plan, lid)
            if found is not None:
                seg, length = found
                mu = plan.scale * length
    tol = ctx.tol_mm(k, kind, *seg) if seg else (ctx.cf.tolerance.segment_mm
                                                   if ctx.cf.tolerance.model == "draftsman" else None)
    ref = (abs(complex(*plan.xy("a"))) / plan.scale / length) if plan.has("a") else 0.0
    return Exact(q, value, unit, mu, tol, "kinematics", kind, seg, ref)


def _tangential_on(ctx: Context, k: int, plan: Plan, lid: int) -> tuple[tuple[str, str], float] | None:
    """A tangential segment a_XY^τ of the acceleration plan whose points X, Y both belong to
    link ``lid`` (a point written with the link's number, A3, or one of its own points), and
    the distance XY at position k: ε = a^τ / l_XY."""
    link = ctx.scene.links[lid]
    for sg in plan.segments:
        m = re.fullmatch(r"a_(\w+)\^τ", sg.label)
        if sg.kind != "tangential" or not m:
            continue
        toks = re.findall(r"[A-Z][a-z]*\d*", m.group(1))
        if len(toks) != 2 or "".join(toks) != m.group(1):
            continue
        names = []
        for t in toks:
            if t in link.points:
                names.append(t)
                continue
            mm = re.fullmatch(r"([A-Z][a-z]*)(\d+)", t)
            if mm and int(mm.group(2)) == lid and ctx.scene.point_links(mm.group(1)):
                names.append(mm.group(1))
            else:
                break
        if len(names) != 2:
            continue
        try:
            length = abs(ctx.pos(k, names[0]) - ctx.pos(k, names[1]))
        except KeyError:
            continue
        if length > 0:
            return (sg.start, sg.end), length
    return None


def _length(ctx: Context, k: int, q: str) -> Exact | None:
    pts = _points(q[2:])
    if len(pts) != 2:
        return None
    try:
        d = abs(ctx.pos(k, pts[0]) - ctx.pos(k, pts[1]))
    except KeyError:
        return None
    mu_l = ctx.cf.scales["length"]
    tol = ctx.cf.tolerance.segment_mm if ctx.cf.tolerance.model == "draftsman" else None
    return Exact(q, d, "m", mu_l * 1e-3 * 1e3, tol, "scheme", "scheme", None, d)


def _loads(ctx: Context, k: int, q: str) -> Exact | None:
    got = ctx.forces()
    if got is None:
        return None
    loads, fa = got
    m = re.fullmatch(r"(m|I|G|Phi|M_Phi|P)_(\d+)", q)
    assert m
    what, lid = m.group(1), int(m.group(2))
    if lid not in ctx.scene.links:
        return None
    mass = float(loads.masses.get(lid, 0.0))
    inertia = float(loads.inertias.get(lid, 0.0))
    if what == "m":
        return Exact(q, mass, "kg", None, None, "loads") if mass > 0 else None
    if what == "I":
        return Exact(q, inertia, "kg m^2", None, None, "loads") if inertia > 0 else None
    if what == "G":
        return Exact(q, mass * G_STANDARD, "N", None, None, "loads") if mass > 0 else None
    if what == "P":
        for f in fa.applied.forces:
            if f.link == lid and f.kind == "gas":
                return Exact(q, abs(complex(f.F[k])), "N", None, None, "loads")
        return None
    if what == "Phi":
        if mass <= 0:
            return None
        centre = loads.centres.get(lid)
        if centre is None:
            return None
        base = _plan_segment(ctx, k, f"a_{centre}")
        value = next((abs(complex(f.F[k])) for f in fa.applied.forces if f.label == f"Phi{lid}"), None)
        if value is None:
            return None
        if base is None:
            return Exact(q, value, "N", None, None, "loads")
        return Exact(q, value, "N", (base.mm_per_unit or 0.0) / mass, base.tol_mm, "loads",
                     base.plan, base.segment, base.ref * mass)
    # M_Phi
    if inertia <= 0:
        return None
    value = abs(float(inertia * ctx.kin.eps(lid)[k]))
    base = _angular(ctx, k, f"eps_{lid}")
    if base is None or base.mm_per_unit is None:
        return Exact(q, value, "N m", None, None, "loads")
    return Exact(q, value, "N m", base.mm_per_unit / inertia, base.tol_mm, "loads", base.plan,
                 base.segment, base.ref * inertia)


def _force(ctx: Context, k: int, q: str) -> Exact | None:
    got = ctx.forces()
    if got is None:
        return None
    _, fa = got
    mu_f = ctx.cf.scales.get("force")

    def drawn(value: float, unit: str, labels: tuple[str, ...]) -> Exact:
        """On a force polygon at the student's μF: the draftsman's tolerance of that polygon."""
        seg = ctx.polygon_segment(k, labels) if mu_f else None
        if seg is None:
            return Exact(q, value, unit, mu_f, None, "forces", "force" if mu_f else None)
        i, a, b = seg
        return Exact(q, value, unit, mu_f, ctx.polygon_tol(k, i, a, b), "forces", f"force-{i}", (a, b))

    if q in ("F_bal", "F_bal_lever"):
        value = abs(float(fa.balancing[k]))
        unit = "N" if fa.crank.kind == "force" else "N m"
        if q == "F_bal_lever" or fa.crank.kind != "force":
            return Exact(q, value, unit, mu_f, None, "forces")
        return drawn(value, unit, ("F_bal",))
    m = re.fullmatch(r"F_(\d)(\d)(\^[nτ])?", q)
    assert m
    name = f"F{m.group(1)}{m.group(2)}"
    try:
        F, rc = fa.reaction(name)
    except KeyError:
        return None
    comp = m.group(3)
    if comp is None:
        value = abs(complex(F[k]))
    else:
        arr = rc.tau if comp == "^τ" else rc.n
        if arr is None:
            return None
        value = abs(float(arr[k]))
    sfx = comp or ""
    return drawn(value, "N", (f"F{m.group(1)}{m.group(2)}{sfx}", f"F{m.group(2)}{m.group(1)}{sfx}"))


def _arm(ctx: Context, k: int, q: str) -> Exact | None:
    """h_<force>_<point>: the arm of a load about a point in a moment equation (scheme, m)."""
    got = ctx.forces()
    if got is None:
        return None
    _, fa = got
    m = re.fullmatch(r"h_([A-Za-z_0-9]+?)_([A-Z][a-z0-9]*)", q)
    if not m:
        return None
    label, point = m.group(1).replace("_", ""), m.group(2)
    mu_l = ctx.cf.scales["length"]
    tol = ctx.cf.tolerance.segment_mm if ctx.cf.tolerance.model == "draftsman" else None
    for gf in fa.groups:
        for (eq, lab), arr in gf.arms.items():
            if lab.replace("_", "") == label and eq.startswith(f"M_{point}("):
                return Exact(q, abs(float(arr[k])), "m", mu_l, tol, "forces", "scheme")
    if point == ctx.scene.driver.pivot:
        for lab, arr in fa.crank.arms.items():
            if lab.replace("_", "") == label:
                return Exact(q, abs(float(arr[k])), "m", mu_l, tol, "forces", "scheme")
    return None


#: Exact value providers keyed by quantity name (first match wins).
PROVIDERS: tuple[tuple[str, re.Pattern[str], Callable[[Context, int, str], Exact | None]], ...] = (
    ("plan", re.compile(r"^[va]_[A-Za-z0-9]+(\^[nτ])?$|^a\^[kr]_\w+$"), _plan_segment),
    ("angular", re.compile(r"^(omega|eps)_\d+$"), _angular),
    ("length", re.compile(r"^l_[A-Z][A-Za-z0-9]*$"), _length),
    ("loads", re.compile(r"^(m|I|G|Phi|M_Phi|P)_\d+$"), _loads),
    ("forces", re.compile(r"^F_\d\d(\^[nτ])?$|^F_bal(_lever)?$"), _force),
    ("arms", re.compile(r"^h_\w+$"), _arm),
)

#: Quantities that are the student's own and have no exact counterpart.
STUDENT_ONLY = re.compile(r"^(F_bal_diff_pct|h_\w+)$")


def exact_value(ctx: Context, k: int, q: str) -> Exact | None:
    """The first provider whose pattern matches q and that knows it; a value that vanishes
    against the size of its plan (b on the pole) is exactly zero."""
    for _, pattern, fn in PROVIDERS:
        if pattern.match(q):
            got = fn(ctx, k, q)
            if got is not None:
                if got.value != 0 and abs(got.value) <= ZERO_REL * got.ref:
                    got = replace(got, value=0.0)
                return got
    return None


def known_quantities(ctx: Context, k: int) -> list[str]:
    """Names the scene can answer at position k (for error messages)."""
    out: list[str] = []
    for kind in ("velocity", "acceleration"):
        plan = ctx.plan(k, kind)
        if plan is not None:
            out += [s.label for s in plan.segments]
    out += [f"omega_{i}" for i in sorted(ctx.scene.links)] + [f"eps_{i}" for i in sorted(ctx.scene.links)]
    got = ctx.forces()
    if got is not None:
        _, fa = got
        out += [f"Phi_{f.label[3:]}" for f in fa.applied.forces if f.label.startswith("Phi")]
        out += ["F_bal", "F_bal_lever"]
        out += [f"F_{rc.name(ctx.scene.fij)[1:]}" for rc in fa.reactions()]
    return out


# --------------------------------------------------------------------------- draftsman propagation


class _Propagation:
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


@dataclass(frozen=True, slots=True)
class Item:
    quantity: str
    phi_deg: float
    student: float  # SI
    student_mm: float | None
    exact: float
    exact_mm: float | None
    unit: str
    error_pct: float | None
    error_mm: float | None
    tolerance: float  # SI
    tolerance_mm: float | None
    tolerance_model: str  # "draftsman" | "rule"
    verdict: str  # "pass" | "fail"
    where: str
    field: str
    source: str
    figure: str = "value"  # "measured" (a segment, mm), "value", "both" (a value and its segment)
    plan: str | None = None
    segment: tuple[str, str] | None = None

    @property
    def tolerance_pct(self) -> float | None:
        return 100.0 * self.tolerance / abs(self.exact) if self.exact else None

    def to_json(self) -> dict:
        return {"quantity": self.quantity, "phi_deg": self.phi_deg, "student": self.student,
                "student_mm": self.student_mm, "exact": self.exact, "exact_mm": self.exact_mm,
                "unit": self.unit, "error_pct": self.error_pct, "error_mm": self.error_mm,
                "tolerance": self.tolerance, "tolerance_mm": self.tolerance_mm,
                "tolerance_pct": self.tolerance_pct, "tolerance_model": self.tolerance_model,
                "verdict": self.verdict, "where": self.where, "field": self.field, "source": self.source,
                "figure": self.figure, "plan": self.plan, "segment": list(self.segment) if self.segment else None}


@dataclass(frozen=True, slots=True)
class Finding:
    kind: str  # duplicate arithmetic relation symmetry pi scale swapped percent
    message: str
    phi_deg: float | None = None
    quantities: tuple[str, ...] = ()
    where: tuple[str, ...] = ()
    fields: tuple[str, ...] = ()

    def to_json(self) -> dict:
        return {"kind": self.kind, "message": self.message, "phi_deg": self.phi_deg,
                "quantities": list(self.quantities), "where": list(self.where), "fields": list(self.fields)}


@dataclass(frozen=True, slots=True)
class Unchecked:
    quantity: str
    phi_deg: float
    student: float
    reason: str
    where: str

    def to_json(self) -> dict:
        return {"quantity": self.quantity, "phi_deg": self.phi_deg, "student": self.student,
                "reason": self.reason, "where": self.where}


@dataclass(frozen=True)
class Report:
    check: CheckFile
    items: tuple[Item, ...]
    findings: tuple[Finding, ...]
    unchecked: tuple[Unchecked, ...]
    context: Context = field(repr=False)

    @property
    def passed(self) -> int:
        return sum(1 for i in self.items if i.verdict == "pass")

    @property
    def failed(self) -> int:
        return sum(1 for i in self.items if i.verdict == "fail")

    def item(self, quantity: str, phi_deg: float, where: str | None = None) -> Item:
        for it in self.items:
            if it.quantity == quantity and it.phi_deg == phi_deg and (where is None or it.where == where):
                return it
        raise KeyError((quantity, phi_deg, where))

    def findings_of(self, kind: str) -> list[Finding]:
        return [f for f in self.findings if f.kind == kind]

    def to_json(self) -> dict:
        cf = self.check
        t = cf.tolerance
        return {
            "format": 1,
            "student": cf.student,
            "check_file": cf.path,
            "scene": cf.scene.path,
            "scales": dict(cf.scales),
            "tolerance": {"model": t.model, "segment_mm": t.segment_mm, "direction_deg": t.direction_deg,
                          "rule_pct": t.rule_pct, "arithmetic_pct": t.arithmetic_pct,
                          "balance_base": t.balance_base},
            "items": [i.to_json() for i in self.items],
            "findings": [f.to_json() for f in self.findings],
            "unchecked": [u.to_json() for u in self.unchecked],
            "summary": {"items": len(self.items), "passed": self.passed, "failed": self.failed,
                        "findings": len(self.findings), "unchecked": len(self.unchecked)},
        }


# --------------------------------------------------------------------------- comparison


def check(cf: CheckFile) -> Report:
    """Compare every figure of a check file with the exact analysis; find inconsistencies."""
    ctx = Context(cf)
    items: list[Item] = []
    unchecked: list[Unchecked] = []
    for pos in cf.positions:
        k = pos.index
        names = []
        for w in pos.measured + pos.values:
            if w.quantity not in names:
                names.append(w.quantity)
        for q in names:
            ex = exact_value(ctx, k, q)
            if ex is None:
                if STUDENT_ONLY.match(q):
                    for w in pos.written(q):
                        m = re.fullmatch(r"h_([A-Za-z_0-9]+?)_([A-Z][a-z0-9]*)", q)
                        if q == "F_bal_diff_pct":
                            reason = "the student's own figure (checked for consistency)"
                        elif m:
                            reason = (f"the exact analysis has no arm of {m.group(1)} about {m.group(2)} "
                                      f"(a load it does not apply, or another moment equation)")
                        else:
                            reason = "a lever arm named by the student: name it h_<load>_<point> (e.g. h_Phi2_B)"
                        unchecked.append(Unchecked(q, pos.phi_deg, w.value, reason, w.where))
                    continue
                w0 = pos.written(q)[0]
                known = ", ".join(known_quantities(ctx, k))
                extra = f" ({ctx._forces_error})" if ctx._forces_error else ""
                raise InputError(f"the scene has no quantity {q!r} at {pos.phi_deg:g}°{extra}; "
                                 f"expected one of {known}", file=cf.path, field=w0.field)
            items += _items(cf, pos, q, ex)
    findings: list[Finding] = []
    for pos in cf.positions:
        findings += _duplicates(cf, pos)
        findings += _relations(ctx, pos)
        findings += _symmetry(cf, pos, [i for i in items if i.phi_deg == pos.phi_deg])
        findings += _swapped(ctx, pos, [i for i in items if i.phi_deg == pos.phi_deg])
    findings += _across_positions(cf)
    findings += _pi(cf, items)
    findings += _scale(cf, items)
    return Report(cf, tuple(items), tuple(findings), tuple(unchecked), ctx)


def _consistent(w: Written, m: Written, mm_per_unit: float, rel: float) -> bool:
    """A value that is its measured segment over the scale, to the student's rounding."""
    want = m.value / mm_per_unit
    return abs(w.value - want) <= w.half_ulp + m.half_ulp / mm_per_unit + rel * abs(want) + 1e-12


def _items(cf: CheckFile, pos: StudentPosition, q: str, ex: Exact) -> list[Item]:
    """One item per figure written; a value that is its measured segment over μ joins it."""
    values = pos.written(q, "value")
    measured = pos.written(q, "measured")
    mu = ex.mm_per_unit
    if measured and not mu:
        raise InputError(f"{q} is not read off a plan at a scale the check file gives: write it under values",
                         file=cf.path, field=measured[0].field)
    rel = cf.tolerance.arithmetic_pct / 100.0
    rows: list[tuple[Written | None, Written | None]] = []  # (measured, value)
    free = list(values)
    for meas in measured:
        assert mu
        pair = next((w for w in free if _consistent(w, meas, mu, rel)), None)
        if pair is not None:
            free.remove(pair)
        rows.append((meas, pair))
    rows += [(None, w) for w in free]
    out = []
    t = cf.tolerance
    exact_mm = ex.value * mu if mu else None
    for m, v in rows:
        if m is not None:  # judged on the drawing
            assert mu
            judged = m.value / mu
            student = v.value if v is not None else judged
            student_mm: float | None = m.value
            figure = "both" if v is not None else "measured"
            slack = 0.0
        else:
            assert v is not None
            judged = student = v.value
            student_mm = v.value * mu if mu else None
            figure = "value"
            slack = v.half_ulp
        w = v if v is not None else m
        assert w is not None
        where = ", ".join(dict.fromkeys(x.where for x in (m, v) if x is not None and x.where))
        diff = judged - ex.value
        err_pct = None if ex.value == 0 else 100.0 * diff / abs(ex.value)
        if ex.value == 0 and abs(diff) <= 1e-12:
            err_pct = 0.0
        err_mm = None if not mu or student_mm is None or exact_mm is None else student_mm - exact_mm
        if t.model == "draftsman" and ex.tol_mm is not None and mu:
            tol = ex.tol_mm / mu
            model = "draftsman"
        else:
            tol = t.rule_pct / 100.0 * max(abs(ex.value), 0.05 * ex.ref)
            model = "rule"
        tol = max(tol, slack)
        verdict = "pass" if abs(diff) <= tol * (1 + 1e-9) else "fail"
        out.append(Item(q, pos.phi_deg, student, student_mm, ex.value, exact_mm, ex.unit, err_pct, err_mm,
                        tol, None if not mu else tol * mu, model, verdict, where, w.field, ex.source,
                        figure, ex.plan, ex.segment))
    return out


# --------------------------------------------------------------------------- consistency


def _fmt(x: float) -> str:
    """A computed number, four significant digits (whole numbers above 10 000)."""
    if x == 0:
        return "0"
    if abs(x) >= 1e4:
        return f"{x:.0f}"
    return f"{x:.4g}"


def _typed(w: Written) -> str:
    """A figure as the student wrote it."""
    x = w.value
    if w.half_ulp >= 0.5 and float(x).is_integer():
        return str(int(x))
    s = repr(float(x))
    return s[:-2] if s.endswith(".0") else s


def _at(w: Written) -> str:
    return f" ({w.where})" if w.where else ""


def _same(a: Written, b: Written, rel: float) -> bool:
    slack = a.half_ulp + b.half_ulp + rel * max(abs(a.value), abs(b.value))
    return abs(a.value - b.value) <= slack


def _duplicates(cf: CheckFile, pos: StudentPosition) -> list[Finding]:
    out = []
    rel = cf.tolerance.arithmetic_pct / 100.0
    for kind in ("value", "measured"):
        groups: dict[str, list[Written]] = {}
        for w in (pos.values if kind == "value" else pos.measured):
            groups.setdefault(w.quantity, []).append(w)
        for q, ws in groups.items():
            if len(ws) < 2:
                continue
            if all(_same(ws[0], w, rel) for w in ws[1:]):
                continue
            unit = "mm" if kind == "measured" else ""
            shown = " and ".join(f"{_typed(w)}{(' ' + unit) if unit else ''}{_at(w)}" for w in ws)
            what = f"the segment for {q}" if kind == "measured" else q
            out.append(Finding("duplicate", f"φ = {pos.phi_deg:g}°: {what} is written as {shown}",
                               pos.phi_deg, (q,), tuple(w.where for w in ws), tuple(w.field for w in ws)))
    return out


_POSITION_FREE = re.compile(r"^(m|I|G)_\d+$|^l_\w+$")


def _position_free(scene: Any, q: str) -> bool:
    """A mass, an inertia, or the length between two points of one rigid link; not the
    distance of a block from its rocker's pivot (l_CA of a shaper changes with the angle)."""
    if not _POSITION_FREE.match(q):
        return False
    if not q.startswith("l_"):
        return True
    pts = _points(q[2:])
    if len(pts) != 2:
        return True
    return any(set(pts) <= set(link.points) for link in scene.links.values()) \
        or set(pts) <= set(scene.frame_points)


def _across_positions(cf: CheckFile) -> list[Finding]:
    """Masses, inertias, lengths do not depend on the crank angle."""
    out = []
    rel = cf.tolerance.arithmetic_pct / 100.0
    seen: dict[str, list[tuple[float, Written]]] = {}
    for pos in cf.positions:
        for w in pos.values:
            if _position_free(cf.scene, w.quantity):
                seen.setdefault(w.quantity, []).append((pos.phi_deg, w))
    for q, ws in seen.items():
        phis = {p for p, _ in ws}
        if len(phis) < 2:
            continue
        first = ws[0][1]
        bad = [(p, w) for p, w in ws if not _same(first, w, rel) and p != ws[0][0]]
        if bad:
            shown = " and ".join(f"{_typed(w)} at {p:g}°{_at(w)}" for p, w in ws)
            out.append(Finding("duplicate", f"{q} does not depend on the crank angle but is written as {shown}",
                               None, (q,), tuple(w.where for _, w in ws), tuple(w.field for _, w in ws)))
    return out


@dataclass(frozen=True, slots=True)
class _Input:
    value: float
    text: str  # how the student got it ("ab = 60 mm / μv")
    student: bool
    half: float = 0.0  # the rounding of the figure as written, in the value's unit


def _aliases(q: str) -> list[str]:
    """q and the names of the same magnitude with the two points swapped (v_A2A3 = v_A3A2,
    a^k_A3A2 = a^k_A2A3)."""
    m = re.fullmatch(r"(v_|a\^[kr]_)([A-Za-z0-9]+)", q)
    if m:
        pts = _points(m.group(2))
        if len(pts) == 2:
            return [q, f"{m.group(1)}{pts[1]}{pts[0]}"]
    return [q]


def _written_any(pos: StudentPosition, q: str, kind: str) -> list[Written]:
    return [w for name in _aliases(q) for w in pos.written(name, kind)]


def _candidates(ctx: Context, pos: StudentPosition, q: str) -> list[_Input]:
    """What the student has for q at this position: measured/μ first, then values; the exact
    value (marked) when the student wrote nothing for it."""
    out = []
    k = pos.index
    ex = exact_value(ctx, k, q)
    for w in _written_any(pos, q, "measured"):
        if ex is not None and ex.mm_per_unit:
            out.append(_Input(w.value / ex.mm_per_unit, f"{_typed(w)} mm{_at(w)} / {ex.mm_per_unit:g}", True,
                              w.half_ulp / ex.mm_per_unit))
    for w in _written_any(pos, q, "value"):
        out.append(_Input(w.value, f"{_typed(w)}{_at(w)}", True, w.half_ulp))
    if not out and _position_free(ctx.scene, q):  # a length or a mass written at another position
        for other in ctx.cf.positions:
            for w in other.written(q, "value"):
                out.append(_Input(w.value, f"{_typed(w)}{_at(w)}", True, w.half_ulp))
    if not out and ex is not None:
        out.append(_Input(ex.value, f"{_fmt(ex.value)} (exact)", False))
    return out


@dataclass(frozen=True, slots=True)
class Relation:
    """target = fn(inputs), as the student should have computed it."""

    target: str
    inputs: tuple[str, ...]
    fn: Callable[..., float]
    formula: str


def relations(ctx: Context) -> list[Relation]:
    """The relations of the course that the student's figures must satisfy among themselves."""
    scene = ctx.scene
    rel: list[Relation] = []
    d = scene.driver
    crank = scene.links[d.link]
    O, A = crank.axis[0], crank.axis[1]
    rel.append(Relation(f"v_{A}", (f"omega_{d.link}", f"l_{O}{A}"), lambda w, l: w * l, f"ω{d.link}·l_{O}{A}"))
    if d.eps == 0:
        rel.append(Relation(f"a_{A}", (f"omega_{d.link}", f"l_{O}{A}"), lambda w, l: w * w * l,
                            f"ω{d.link}²·l_{O}{A}"))
    for lid, link in sorted(scene.links.items()):
        if lid == d.link or len(link.axis) != 2:
            continue
        P, Q = link.axis
        rel.append(Relation(f"omega_{lid}", (f"v_{Q}{P}", f"l_{P}{Q}"), lambda v, l: v / l, f"v_{Q}{P}/l_{P}{Q}"))
        rel.append(Relation(f"eps_{lid}", (f"a_{Q}{P}^τ", f"l_{P}{Q}"), lambda a, l: a / l,
                            f"a_{Q}{P}^τ/l_{P}{Q}"))
        rel.append(Relation(f"a_{Q}{P}^n", (f"v_{Q}{P}", f"l_{P}{Q}"), lambda v, l: v * v / l,
                            f"v_{Q}{P}²/l_{P}{Q}"))
        for name, z in link.points.items():
            if name in (P, Q):
                continue
            ratio = abs(z - link.points[P]) / abs(link.points[Q] - link.points[P])
            for sym in ("v", "a"):
                rel.append(Relation(f"{sym}_{name}{P}", (f"{sym}_{Q}{P}",), lambda x, r=ratio: r * x,
                                    f"({_fmt(ratio)})·{sym}_{Q}{P} (similarity: l_{P}{name}/l_{P}{Q})"))
    rel += _coriolis_relations(ctx)
    got = ctx.forces()
    if got is not None:
        loads, _ = got
        for lid, centre in loads.centres.items():
            rel.append(Relation(f"Phi_{lid}", (f"m_{lid}", f"a_{centre}"), lambda m, a: m * a,
                                f"m_{lid}·a_{centre}"))
            rel.append(Relation(f"M_Phi_{lid}", (f"I_{lid}", f"eps_{lid}"), lambda i, e: i * e,
                                f"I_{lid}·ε_{lid}"))
            rel.append(Relation(f"G_{lid}", (f"m_{lid}",), lambda m: m * G_STANDARD, f"m_{lid}·g"))
    base = ctx.cf.tolerance.balance_base
    if base == "lever":
        rel.append(Relation("F_bal_diff_pct", ("F_bal_lever", "F_bal"), lambda lv, kn: 100 * abs(lv - kn) / lv,
                            "100·|F_bal_lever − F_bal|/F_bal_lever"))
    else:
        rel.append(Relation("F_bal_diff_pct", ("F_bal_lever", "F_bal"), lambda lv, kn: 100 * abs(lv - kn) / kn,
                            "100·|F_bal_lever − F_bal|/F_bal"))
    return rel


def _coriolis_relations(ctx: Context) -> list[Relation]:
    """a^k = 2·ω·v_r for every Coriolis segment of the plans: ω of the link carrying the guide
    (the block turns with it), v_r the sliding segment of the velocity plan (either order)."""
    out: list[Relation] = []
    scene = ctx.scene
    seen: set[str] = set()
    for pp in ctx.plans.values():
        if pp.velocity is None or pp.acceleration is None:
            continue
        sliding = {s.label for s in pp.velocity.segments if s.kind == "sliding"}
        for sg in pp.acceleration.segments:
            m = re.fullmatch(r"a\^k_(\w+)", sg.label)
            if sg.kind != "coriolis" or not m or sg.label in seen:
                continue
            toks = re.findall(r"[A-Z][a-z]*\d*", m.group(1))
            if len(toks) != 2:
                continue
            v_lab = next((f"v_{a}{b}" for a, b in (toks, toks[::-1]) if f"v_{a}{b}" in sliding), None)
            nums = [re.fullmatch(r"[A-Z][a-z]*(\d+)", x) for x in toks]
            links = [int(n.group(1)) for n in nums if n and int(n.group(1)) in scene.links]
            if v_lab is None or not links:
                continue
            links.sort(key=lambda lid: (len(scene.links[lid].axis) != 2, lid))  # the rocker first
            seen.add(sg.label)
            out.append(Relation(sg.label, (f"omega_{links[0]}", v_lab), lambda w, v: 2 * abs(w) * abs(v),
                                f"2·ω{links[0]}·{v_lab} (Coriolis)"))
    return out


def _relations(ctx: Context, pos: StudentPosition) -> list[Finding]:
    out: list[Finding] = []
    cf = ctx.cf
    rel_tol = cf.tolerance.arithmetic_pct / 100.0
    # value = segment / scale
    for w in pos.values:
        measured = pos.written(w.quantity, "measured")
        if not measured:
            continue
        ex = exact_value(ctx, pos.index, w.quantity)
        if ex is None or not ex.mm_per_unit:
            continue
        if any(_consistent(w, m, ex.mm_per_unit, rel_tol) for m in measured):
            continue
        m = measured[0]
        want = m.value / ex.mm_per_unit
        out.append(Finding("arithmetic",
                           f"φ = {pos.phi_deg:g}°: {w.quantity} = {_typed(w)}{_at(w)}, but the segment "
                           f"measured for it, {_typed(m)} mm{_at(m)}, at the scale {ex.mm_per_unit:.4g} mm per "
                           f"{ex.unit} gives {_fmt(want)} {ex.unit}",
                           pos.phi_deg, (w.quantity,), (w.where, m.where), (w.field, m.field)))
    for r in relations(ctx):
        targets = _written_any(pos, r.target, "value") or _written_any(pos, r.target, "measured")
        if not targets:
            continue
        cands = [_candidates(ctx, pos, q) for q in r.inputs]
        if any(not c for c in cands) or not any(c.student for cs in cands for c in cs):
            continue
        for w in targets:
            value = w.value
            if w.kind == "measured":
                ex = exact_value(ctx, pos.index, r.target)
                if ex is None or not ex.mm_per_unit:
                    continue
                value = w.value / ex.mm_per_unit
            slack_abs = w.half_ulp
            if w.kind == "measured":
                ex = exact_value(ctx, pos.index, r.target)
                slack_abs = w.half_ulp / (ex.mm_per_unit if ex is not None and ex.mm_per_unit else 1.0)
            results = []
            ok = False
            for combo in itertools.product(*cands):
                try:
                    xs = [c.value for c in combo]
                    want = r.fn(*xs)
                    # the rounding of each input as written, carried through the relation
                    carried = sum(abs(r.fn(*(xs[:i] + [xs[i] + c.half] + xs[i + 1:])) - want)
                                  for i, c in enumerate(combo) if c.half)
                except ZeroDivisionError:
                    continue
                results.append((want, combo))
                if abs(value - want) <= slack_abs + carried + rel_tol * abs(want) + 1e-12:
                    ok = True
                    break
            if ok or not results:
                continue
            want, combo = results[0]
            used = ", ".join(f"{q} = {c.text}" for q, c in zip(r.inputs, combo, strict=True))
            kind = "percent" if r.target == "F_bal_diff_pct" else "relation"
            shown = _typed(w) + (" mm" if w.kind == "measured" else "")
            msg = (f"φ = {pos.phi_deg:g}°: {r.target} = {shown}{_at(w)}, but {r.formula} = "
                   f"{_fmt(want)} with {used}")
            if kind == "percent":
                msg += _percent_hint(cf, combo, value)
            out.append(Finding(kind, msg, pos.phi_deg, (r.target,) + r.inputs, (w.where,), (w.field,)))
    return out


def _percent_hint(cf: CheckFile, combo: tuple[_Input, ...], value: float) -> str:
    lever, kin = combo[0].value, combo[1].value
    denominator = kin if cf.tolerance.balance_base == "lever" else lever
    if denominator == 0:  # a student's zero: no other denominator to suspect
        return ""
    other = 100 * abs(lever - kin) / denominator
    if abs(other - value) <= 0.01 * max(abs(value), 1e-9) + 0.005:
        base = "the kinetostatic force F_bal" if cf.tolerance.balance_base == "lever" else "the lever's F_bal"
        right = "the Zhukovsky lever's F_bal_lever" if cf.tolerance.balance_base == "lever" else "F_bal"
        return (f"; the student's {_fmt(value)} % divides by {base} ({_fmt(other)} %): "
                f"the wrong denominator, the course compares with {right}")
    return ""


def _symmetry(cf: CheckFile, pos: StudentPosition, items: list[Item]) -> list[Finding]:
    """Figures whose exact values are equal (a symmetric position) must be equal on the sheet."""
    out = []
    seg_mm = cf.tolerance.segment_mm
    rel = cf.tolerance.arithmetic_pct / 100.0
    firsts: dict[str, Item] = {}
    for it in items:
        firsts.setdefault(it.quantity, it)
    qs = list(firsts)
    for a, b in itertools.combinations(qs, 2):
        ia, ib = firsts[a], firsts[b]
        if ia.unit != ib.unit or ia.exact == 0 or ia.source != ib.source:
            continue
        if a[:2] != b[:2] or ("^" in a) != ("^" in b) or (a.startswith("F_bal") and b.startswith("F_bal")):
            continue  # (F_bal by two methods is the percent check's business)
        if abs(ia.exact - ib.exact) > 1e-9 * abs(ia.exact):
            continue
        gap = abs(ia.student - ib.student)
        # the student should write the same figure twice: allow the reading of two segments
        # (±seg each) or the rounding of two values
        allow = _half_ulp_of(ia.student) + _half_ulp_of(ib.student) + rel * abs(ia.exact)
        if ia.exact_mm and ib.exact_mm:  # read off the drawing (directly or through a segment)
            allow += 2 * seg_mm / (ia.exact_mm / ia.exact)
        if gap > allow * (1 + 1e-9):
            mm = ""
            if ia.figure != "value" and ib.figure != "value" and ia.student_mm is not None \
                    and ib.student_mm is not None:
                mm = f" ({_fmt(ia.student_mm)} mm and {_fmt(ib.student_mm)} mm)"
            out.append(Finding("symmetry",
                               f"φ = {pos.phi_deg:g}°: {a} and {b} are exactly equal at this position (both "
                               f"{_fmt(ia.exact)} {ia.unit}: symmetry), but the student has {_fmt(ia.student)}{_at_item(ia)} "
                               f"and {_fmt(ib.student)}{_at_item(ib)} {ia.unit}{mm}",
                               pos.phi_deg, (a, b), (ia.where, ib.where), (ia.field, ib.field)))
    return out


def _at_item(it: Item) -> str:
    return f" ({it.where})" if it.where else ""


def _swapped(ctx: Context, pos: StudentPosition, items: list[Item]) -> list[Finding]:
    """A failed plan segment whose length is that of another segment of the same plan:
    two segments swapped (each has the other's length) or the wrong segment measured."""
    out = []
    k = pos.index
    rows = [i for i in items if i.source == "plan" and i.figure != "value" and i.student_mm is not None
            and i.exact_mm is not None and i.plan in ("velocity", "acceleration")]
    done: set[frozenset[str]] = set()
    for it in rows:
        if it.verdict != "fail":
            continue
        assert it.student_mm is not None and it.exact_mm is not None and it.plan is not None
        plan = ctx.plan(k, it.plan)
        if plan is None:
            continue
        own_tol = it.tolerance_mm or ctx.cf.tolerance.segment_mm
        for s in plan.segments:
            if s.label == it.quantity or abs(s.length_mm - it.exact_mm) <= 2 * own_tol:
                continue
            if abs(s.length_mm - it.student_mm) > own_tol:
                continue
            pair = frozenset((it.quantity, s.label))
            if pair in done:
                break
            partner = next((o for o in rows if o.quantity == s.label), None)
            if partner is not None and partner.student_mm is not None and \
                    abs(partner.student_mm - it.exact_mm) <= (partner.tolerance_mm or own_tol):
                done.add(pair)
                out.append(Finding("swapped",
                                   f"φ = {pos.phi_deg:g}°: {it.quantity} = {_fmt(it.student_mm)} mm and {s.label} = "
                                   f"{_fmt(partner.student_mm)} mm are swapped: on the {it.plan} plan at the "
                                   f"student's scale {it.quantity} is {_fmt(it.exact_mm)} mm and {s.label} "
                                   f"{_fmt(s.length_mm)} mm",
                                   pos.phi_deg, (it.quantity, s.label), (it.where, partner.where),
                                   (it.field, partner.field)))
            elif abs(it.student_mm - it.exact_mm) > 3 * own_tol:
                out.append(Finding("swapped",
                                   f"φ = {pos.phi_deg:g}°: {it.quantity} = {_fmt(it.student_mm)} mm{_at_item(it)} is "
                                   f"close to the length of {s.label} ({_fmt(s.length_mm)} mm), not of {it.quantity} "
                                   f"({_fmt(it.exact_mm)} mm): was the wrong segment measured?",
                                   pos.phi_deg, (it.quantity, s.label), (it.where,), (it.field,)))
            break
    return out


def _pi(cf: CheckFile, items: list[Item]) -> list[Finding]:
    """Values computed from the data (ω1 = πn/30, v_A, a_A, masses, gas forces), not read
    off a drawing, that are the exact ones times (3.14/π)^n, where the student's
    rounding is fine enough to tell."""
    out = []
    measured = {(p.phi_deg, w.quantity) for p in cf.positions for w in p.measured}
    d = cf.scene.driver
    crank = cf.scene.links[d.link]
    computed = {f"omega_{d.link}", f"v_{crank.axis[1]}", f"a_{crank.axis[1]}"}
    for it in items:
        if it.figure != "value" or (it.phi_deg, it.quantity) in measured or it.exact == 0:
            continue
        if it.quantity not in computed and not re.match(r"^(m|I|G|P)_\d+$", it.quantity):
            continue  # read off a drawing: the drawing's error hides π
        hu = _half_ulp_of(it.student)
        if abs(it.student - it.exact) <= hu:
            continue
        for n in (1, 2):
            f = (PI_314 / math.pi) ** n
            if hu > 0.5 * abs(1 - f) * abs(it.exact):
                continue  # the rounding hides the effect of π
            if abs(it.student - it.exact * f) <= hu:
                out.append(Finding("pi", f"φ = {it.phi_deg:g}°: {it.quantity} = {_fmt(it.student)}{_at_item(it)} "
                                         f"is computed with π = 3.14: with π it is {_fmt(it.exact)} {it.unit} "
                                         f"({100 * (it.student / it.exact - 1):+.3f} %), and everything computed "
                                         f"from it inherits the error",
                                   it.phi_deg, (it.quantity,), (it.where,), (it.field,)))
                break
    return out


def _half_ulp_of(x: float) -> float:
    s = repr(float(x))
    if "e" in s:
        mant, exp = s.split("e")
        dec = len(mant.split(".")[1]) if "." in mant else 0
        return 0.5 * 10.0 ** (int(exp) - dec)
    dec = len(s.split(".")[1]) if "." in s and not s.endswith(".0") else 0
    return 0.5 * 10.0 ** (-dec)


def _scale(cf: CheckFile, items: list[Item]) -> list[Finding]:
    """A plan whose figures are all off by one factor: values divided by another μ than the
    sheet's, or segments drawn at another μ."""
    out = []
    for plan in ("velocity", "acceleration"):
        mu = cf.scales.get(plan)
        if mu is None:
            continue
        sym = "μv" if plan == "velocity" else "μa"
        prefix = "v_" if plan == "velocity" else "a_"
        ratios: list[float] = []
        names: list[str] = []
        for pos in cf.positions:
            for w in pos.values:
                if not w.quantity.startswith(prefix) or w.value == 0:
                    continue
                ms = pos.written(w.quantity, "measured")
                if ms and ms[0].value > 0:
                    ratios.append(w.value * mu / ms[0].value)
                    names.append(w.quantity)
        if len(ratios) >= 2:
            r = float(np.median(ratios))
            members = [n for n, x in zip(names, ratios, strict=True) if abs(x / r - 1) < 0.005]
            if abs(r - 1) > 0.01 and len(members) >= max(2, 2 * len(ratios) // 3):
                out.append(Finding("scale", f"the {plan} values are their measured segments divided by "
                                            f"{mu / r:.3g} mm per unit, but the sheet's {sym} is {_fmt(mu)}: "
                                            f"the student divided by the wrong scale, the values are "
                                            f"{100 * (r - 1):+.1f} % off",
                                   None, tuple(dict.fromkeys(members))))
        rows = [i for i in items if i.plan == plan and i.source == "plan" and i.figure != "value"
                and i.exact_mm and i.exact_mm > 5 and i.student_mm]
        ratios = [(i.student_mm or 0.0) / (i.exact_mm or 1.0) for i in rows]
        if len(ratios) >= 3:
            r = float(np.median(ratios))
            if abs(r - 1) > 0.02 and max(abs(x / r - 1) for x in ratios) < 0.02:
                out.append(Finding("scale", f"every measured segment of the {plan} plans is {r:.3f}× its exact "
                                            f"length at {sym} = {_fmt(mu)}: the plans look drawn at {sym} = "
                                            f"{mu * r:.3g}, not at the scale written on the sheet",
                                   None, tuple(dict.fromkeys(i.quantity for i in rows))))
    return out


# --------------------------------------------------------------------------- text and CSV


def _num(x: float | None, unit: str = "") -> str:
    if x is None:
        return "—"
    return _fmt(x) + (f" {unit}" if unit else "")


def table(report: Report) -> str:
    """The readable terminal report."""
    cf = report.check
    t = cf.tolerance
    model = (f"draftsman: ±{t.segment_mm:g} mm per segment, ±{t.direction_deg:g}° per direction, "
             f"propagated; else course rule ±{t.rule_pct:g} %" if t.model == "draftsman"
             else f"course rule ±{t.rule_pct:g} %")
    lines = [f"Check of {cf.student} — {cf.scene.title}",
             f"  file {cf.path}; scales " + ", ".join(f"{k} {v:.4g} mm/unit" for k, v in cf.scales.items()),
             f"  tolerance: {model}"]
    head = f"  {'quantity':<16}{'student':>14}{'exact':>14}{'error':>10}{'err mm':>9}{'tol mm':>8}{'tol %':>8}  verdict  where"
    for pos in cf.positions:
        lines.append("")
        lines.append(f"φ = {pos.phi_deg:g}°")
        lines.append(head)
        for it in report.items:
            if it.phi_deg != pos.phi_deg:
                continue
            err = "—" if it.error_pct is None else f"{it.error_pct:+.1f} %"
            emm = "—" if it.error_mm is None else f"{it.error_mm:+.2f}"
            tmm = "—" if it.tolerance_mm is None else f"±{it.tolerance_mm:.2f}"
            tp = "—" if it.tolerance_pct is None else f"±{it.tolerance_pct:.1f}"
            mark = "pass" if it.verdict == "pass" else "FAIL"
            lines.append(f"  {it.quantity:<16}{_num(it.student):>14}{_num(it.exact):>14}{err:>10}{emm:>9}{tmm:>8}"
                         f"{tp:>8}  {mark:<7}  {it.where}  [{it.unit}{', rule' if it.tolerance_model == 'rule' else ''}]")
    if report.unchecked:
        lines.append("")
        lines.append("Not compared:")
        for u in report.unchecked:
            lines.append(f"  φ = {u.phi_deg:g}°: {u.quantity} = {_fmt(u.student)}{(' (' + u.where + ')') if u.where else ''}"
                         f": {u.reason}")
    lines.append("")
    lines.append(f"Findings ({len(report.findings)}):")
    for f in report.findings:
        lines.append(f"  [{f.kind}] {f.message}")
    lines.append("")
    lines.append(f"Summary: {len(report.items)} figures, {report.passed} pass, {report.failed} fail, "
                 f"{len(report.findings)} findings")
    return "\n".join(lines)


CSV_FIELDS = ("file", "student", "status", "items", "passed", "failed", "findings", "worst", "worst_error_pct",
              "message")


def summary_row(path: str, report: Report | None, error: str | None = None) -> dict[str, Any]:
    if report is None:
        return {"file": path, "student": "", "status": "error", "items": "", "passed": "", "failed": "",
                "findings": "", "worst": "", "worst_error_pct": "", "message": error or ""}
    worst = max((i for i in report.items if i.error_pct is not None), key=lambda i: abs(i.error_pct or 0.0),
                default=None)
    return {"file": path, "student": report.check.student, "status": "ok", "items": len(report.items),
            "passed": report.passed, "failed": report.failed, "findings": len(report.findings),
            "worst": "" if worst is None else f"{worst.quantity} at {worst.phi_deg:g}°",
            "worst_error_pct": "" if worst is None or worst.error_pct is None else f"{worst.error_pct:.2f}",
            "message": ""}


def csv_text(rows: list[dict[str, Any]]) -> str:
    buf = io.StringIO()
    w = csv.DictWriter(buf, fieldnames=list(CSV_FIELDS), lineterminator="\n")
    w.writeheader()
    for r in rows:
        w.writerow(r)
    return buf.getvalue()


def check_file(path: str | Path) -> Report:
    cf = load_check(path)
    try:
        return check(cf)
    except PlansError as exc:
        exc.source = exc.source or str(path)
        raise


# --------------------------------------------------------------------------- command line


def register(subparsers: Any) -> argparse.ArgumentParser:
    p = subparsers.add_parser(
        "check", help="check a hand-drawn sheet (or a folder of them) against the exact analysis",
        description="Compare what a student measured and computed on a hand-drawn sheet with the exact "
                    "values at the student's scales; find inconsistencies in the student's own work.")
    p.add_argument("path", metavar="FILE|DIR", help="a check file (TOML) or a folder of check files")
    p.add_argument("--json", metavar="PATH", help="write the report as JSON ('-' for stdout; single file only)")
    p.add_argument("--csv", metavar="PATH", help="write the summary table as CSV")
    p.add_argument("--out", metavar="DIR", help="write <name>.json and <name>.txt per check file here "
                                                 "(batch default: DIR/reports)")
    p.add_argument("--quiet", action="store_true", help="no table on stdout")
    p.set_defaults(func=run)
    return p


def _err(msg: str) -> None:
    print(f"plans: error: {' '.join(msg.split())}", file=sys.stderr)


def _extra(args: argparse.Namespace, report: Report, target: Path) -> dict[Path, Any]:
    """Files another module adds for each checked file (``plans check --sheet``: the marked
    and overlay sheets), rendered before anything is written."""
    hook = getattr(args, "extra_files", None)
    return dict(hook(report, target)) if hook is not None else {}


def run(args: argparse.Namespace) -> int:
    """``plans check``: 0 when every file was checked, 2 on a user error (one line on stderr).
    A single file's outputs (JSON, CSV, reports, sheets) are written all or none."""
    target = Path(args.path)
    try:
        if target.is_dir():
            return _batch(target, args)
        if not target.exists():
            _err(f"{target}: no such file or folder")
            return 2
        for out_path in (args.json, args.csv):
            refuse_input(out_path, target)
        report = check_file(target)
        for out_path in (args.json, args.csv):
            refuse_input(out_path, report.check.scene.path)
        files: dict[Path, Any] = {}
        if args.json and args.json != "-":
            files[Path(args.json)] = dumps(report.to_json())
        if args.csv:
            files[Path(args.csv)] = csv_text([summary_row(str(target), report)])
        if args.out:
            out = Path(args.out)
            files[out / f"{target.stem}.json"] = dumps(report.to_json())
            files[out / f"{target.stem}.txt"] = table(report) + "\n"
        for out_path in (args.json, args.csv):
            if out_path and out_path != "-" and not Path(out_path).parent.is_dir():
                raise OutputError(f"{out_path}: no such folder {Path(out_path).parent}")
        files.update(_extra(args, report, target))
        for folder in sorted({p.parent for p in files}):
            _make_folder(folder)
        written = write_all(files)
        if args.json == "-":
            sys.stdout.write(dumps(report.to_json()))
        if not args.quiet and args.json != "-":
            print(table(report))
            for p in written:
                if p.suffix in (".svg", ".pdf", ".png"):
                    print(p)
        return 0
    except PlansError as exc:
        _err(one_line(exc))
        return 2
    except BrokenPipeError:
        raise  # the runner ends quietly: the reader of the table has gone
    except OSError as exc:
        _err(f"{exc.filename or ''}: {exc.strerror}")
        return 2


def _make_folder(folder: Path) -> None:
    try:
        folder.mkdir(parents=True, exist_ok=True)
    except OSError as exc:
        raise OutputError(f"cannot create the output folder {folder}: {exc.strerror}") from None


def _batch(folder: Path, args: argparse.Namespace) -> int:
    if args.json:
        _err(f"{folder}: --json is for one file; a folder writes one report per file into --out")
        return 2
    files = sorted(p for p in folder.glob("*.toml") if p.is_file())
    if not files:
        _err(f"{folder}: no check files (*.toml)")
        return 2
    out = Path(args.out) if args.out else folder / "reports"
    _make_folder(out)
    rows = []
    bad = 0
    for f in files:
        try:
            report = check_file(f)
        except PlansError as exc:
            bad += 1
            _err(one_line(exc))
            rows.append(summary_row(str(f), None, str(exc)))
            continue
        try:
            outputs: dict[Path, Any] = {out / f"{f.stem}.json": dumps(report.to_json()),
                                        out / f"{f.stem}.txt": table(report) + "\n"}
            outputs.update(_extra(args, report, f))
            write_all(outputs)
        except PlansError as exc:
            bad += 1
            _err(one_line(exc))
            rows.append(summary_row(str(f), None, str(exc)))
            continue
        rows.append(summary_row(str(f), report))
    atomic_write(Path(args.csv) if args.csv else out / "summary.csv", csv_text(rows))
    if not args.quiet:
        for r in rows:
            if r["status"] == "ok":
                print(f"{r['file']}: {r['student']}: {r['passed']} pass, {r['failed']} fail, "
                      f"{r['findings']} findings")
            else:
                print(f"{r['file']}: not checked: {r['message']}")
    return 2 if bad else 0
