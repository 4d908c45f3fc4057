"""Exact values of the quantities a student writes on a sheet, keyed by name.

:class:`Context` holds everything exact for one check file (kinematics, the plans at the
student's scales, loads and forces when the scene has them, the draftsman's error
propagation); :func:`exact_value` asks the table of providers (:data:`PROVIDERS`): plan
segments, angular rates, lengths of the scheme, masses and inertia loads
(:mod:`plans.forces.loads`), reactions and the balancing force
(:mod:`plans.forces.polygons`), lever arms.
"""

from __future__ import annotations

import math
import re
from collections.abc import Callable
from dataclasses import dataclass, replace
from typing import Any

from plans import quantities
from plans.check.checkfile import CheckFile
from plans.check.tolerance import Linearised, Propagation
from plans.errors import ConstructionError, PlansError
from plans.kinematics.construction import PositionPlans
from plans.kinematics.exact import Kinematics
from plans.kinematics.plan import Plan

G_STANDARD = quantities.G_STANDARD
#: An exact value below this fraction of its plan's size is zero (a point on the pole).
ZERO_REL = 1e-9



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
        from plans.solution import solve

        self.cf = cf
        self.scene = cf.scene
        #: the scene solved once (plans.solve): what the JSON, the sheets and this check read
        self.solution = solve(cf.scene)
        mv = cf.scales.get("velocity")
        ma = cf.scales.get("acceleration")
        ks = tuple(pos.index for pos in cf.positions)
        try:
            self.kin: Kinematics = self.solution.kinematics_to(2)
            self.plans: dict[int, PositionPlans] = dict(zip(ks, self.solution.plans_at(ks, mv, ma), strict=True))
        except ConstructionError as exc:
            exc.source = None  # a check names the check file it was asked about
            raise
        self._prop: dict[tuple[int, str], Propagation] = {}  # force polygons: their protocol replayed
        self._lin: dict[tuple[int, str], Linearised] = {}
        self._polygons: dict[int, tuple[Plan, ...]] = {}
        self._forces: Any = None
        self._forces_error: str | None = None
        self._loaded = False
        self._memo: dict[tuple[int, str], Exact | None] = {}  # exact_value, asked again and again

    # -- plans
    def plan(self, k: int, kind: str) -> Plan | None:
        pp = self.plans[k]
        return pp.velocity if kind == "velocity" else pp.acceleration

    def propagation(self, k: int, kind: str) -> Linearised | None:
        """The plan's construction drawn with the checker's linearised pencil."""
        key = (k, kind)
        if key not in self._lin:
            plan = self.plan(k, kind)
            if plan is None:
                return None
            tol = self.cf.tolerance
            extra = self._carried(k, plan) if kind == "acceleration" else {}
            pp = self.plans[k]
            assert pp.velocity is not None
            ma = pp.acceleration.scale if pp.acceleration is not None else None
            self._lin[key] = Linearised(self.kin, k, kind, pp.velocity.scale, ma, tol.segment_mm,
                                        math.radians(tol.direction_deg), extra)
        return self._lin[key]

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
            if body is None or set(points_of(body.group(1))) <= set(crank.points):
                continue  # the crank's components come from the data (ω1, ε1, l_OA), not the plan
            if sg.kind == "normal":
                m = re.fullmatch(r"a_([A-Za-z0-9]+)\^n", sg.label)
                v = _plan_segment(self, k, f"v_{m.group(1)}") if m else None
                if v is None or not v.tol_mm or not v.mm_per_unit or v.value <= 0:
                    continue
                out[sg.end] = sg.length_mm * 2 * v.tol_mm / (v.value * v.mm_per_unit)
            else:
                m = re.fullmatch(r"a\^k_([A-Za-z0-9]+)", sg.label)
                pts = points_of(m.group(1)) if m else []
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
                self._forces = self.solution.frictionless()
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
            self._prop[key] = Propagation(self.polygons(k)[i], tol.segment_mm, math.radians(tol.direction_deg))
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


points_of = quantities.points_of


def _ends(plan: Any, name: str) -> tuple[str, str] | None:
    """The ends of the plan's segment ``name``, or None where the plan has none of that name."""
    try:
        s = plan.segment(name)
    except KeyError:
        return None
    return s.start, s.end


def _plan_segment(ctx: Context, k: int, q: str) -> Exact | None:
    kind = "velocity" if q.startswith("v_") else "acceleration"
    plan = ctx.plan(k, kind)
    if plan is None:
        return None
    unit = "m/s" if kind == "velocity" else "m/s^2"
    ref = (abs(complex(*plan.xy("a"))) / plan.scale) if plan.has("a") else 0.0
    seg = _ends(plan, q)
    if seg is None:
        mk = re.fullmatch(r"a\^([kr])_([A-Za-z0-9]+)", q)
        if mk:  # a^k_A2A3 written for a^k_A3A2: the same segment
            pts = points_of(mk.group(2))
            if len(pts) == 2:
                seg = _ends(plan, f"a^{mk.group(1)}_{pts[1]}{pts[0]}")
        m = re.fullmatch(r"([va])_([A-Za-z0-9]+)(\^[nτ])?", q)
        if m and not m.group(3):
            pts = points_of(m.group(2))
            if len(pts) in (1, 2):
                labs = [plan.pole] if len(pts) == 1 else []
                labs += [_label(ctx, plan, p) or "" for p in pts]
                if all(labs):
                    seg = (labs[0], labs[1])
        if m and m.group(3) and seg is None:  # a_AB^τ written for a_BA^τ
            pts = points_of(m.group(2))
            if len(pts) == 2:
                seg = _ends(plan, f"{m.group(1)}_{pts[1]}{pts[0]}{m.group(3)}")
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
    pts = points_of(q[2:])
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
    got = quantities.reaction_name(q)
    assert got
    i, j, comp = got
    try:
        F, rc = quantities.reaction(fa, i, j)
    except KeyError:
        return None
    if comp is None:
        value = abs(complex(F[k]))
    else:
        arr = rc.tau if comp == "^τ" else rc.n
        if arr is None:
            return None
        value = abs(float(arr[k]))
    sfx = comp or ""
    return drawn(value, "N", (f"F{i}{j}{sfx}", f"F{j}{i}{sfx}"))


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


#: Exact value providers keyed by quantity name (first match wins; the names are
#: :data:`plans.quantities.PATTERNS`, the engine's one table of them).
PROVIDERS: tuple[tuple[str, re.Pattern[str], Callable[[Context, int, str], Exact | None]], ...] = tuple(
    (kind, quantities.PATTERNS[kind], fn) for kind, fn in (
        ("plan", _plan_segment), ("angular", _angular), ("length", _length), ("loads", _loads),
        ("forces", _force), ("arms", _arm)))

#: Quantities that are the student's own and have no exact counterpart.
STUDENT_ONLY = quantities.STUDENT_ONLY


def exact_value(ctx: Context, k: int, q: str) -> Exact | None:
    """The first provider whose pattern matches q and that knows it; a value that vanishes
    against the size of its plan (b on the pole) is exactly zero."""
    key = (k, q)
    if key in ctx._memo:
        return ctx._memo[key]
    got = _exact_value(ctx, k, q)
    ctx._memo[key] = got
    return got


def _exact_value(ctx: Context, k: int, q: str) -> Exact | None:
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
        out += [quantities.name_of(rc, ctx.scene.fij) for rc in fa.reactions()]
    return out


# --------------------------------------------------------------------------- draftsman propagation

