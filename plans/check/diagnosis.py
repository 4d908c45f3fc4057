"""Diagnosis by cause: the smallest set of mistakes that explains what the student wrote.

Each mistake a student makes is a model of the whole sheet (:mod:`plans.check.mistakes`
replays the construction slips; the rest are read off the figures: a segment measured
between the wrong pair of points, a plan's values divided by the wrong scale, a
reaction's components swapped, g = 10, π = 3.14, an arithmetic slip in one figure).  A
model *explains* a failing figure when the figure agrees with the model's sheet within
the figure's own tolerance, and *contradicts* a passing one it moves out of tolerance.
Causes are chosen greedily, the one explaining most new failures first (ties go to the
model the figures lie closest to, in their tolerances, then to the kind listed first in
:data:`plans.check.mistakes.KINDS`), as long as each contradicts under a third of what it
explains and moves no more failing figures elsewhere than the student has them than it
explains; a factor fitted to the figures (a scale) must explain two and contradict none.
Every consequence is grouped under its cause and counted once; the findings about the
student's own work are grouped under the cause that explains their figures.  Failing
figures no cause explains stay ``unexplained``.  Causes are listed most important first
(the largest deduction, then the most figures explained).

The mark: ``full`` less a deduction per cause (by kind), per unexplained figure and per
remaining finding (:data:`RUBRIC`; a check file's ``[rubric]`` table overrides it).
"""

from __future__ import annotations

import math
from collections.abc import Callable
from dataclasses import dataclass, field, replace
from statistics import median
from typing import TYPE_CHECKING, Any

import numpy as np

from plans import quantities
from plans.check import wording as wd
from plans.check.checkfile import RUBRIC, RUBRIC_KEYS  # noqa: F401  (read here and from here)
from plans.check.mistakes import KINDS, Slip, describe, inventory, replay
from plans.check.providers import Context, exact_value
from plans.errors import PlansError
from plans.tolerances import ROUND_OFF_REL, VERDICT_REL

if TYPE_CHECKING:
    from plans.check.findings import Finding, Item


G_ROUNDED = 10.0
PI_ROUNDED = 3.14
_RANK = {k: i for i, k in enumerate(KINDS)}


@dataclass(frozen=True)
class Cause:
    """One mistake and everything it explains."""

    kind: str
    positions: tuple[float, ...]
    explains: tuple[str, ...]  # quantity names of the figures it explains
    detail: str  # in English (the report's JSON); ``words`` writes it in either language
    deduction: float
    items: tuple[int, ...] = ()  # indices of the report's items it explains
    findings: tuple[int, ...] = ()  # indices of the report's findings it accounts for
    superseded: tuple[int, ...] = ()  # findings it makes moot ("was the wrong segment measured?")
    words: wd.Words | None = field(default=None, repr=False, compare=False)

    def text(self, lang: str = "en") -> str:
        """The mistake in ``lang``, quantities as that language writes them."""
        if self.words is None or lang != "ru":
            return self.detail
        from plans.language import quantity_name

        return self.words.render(lang, lambda q: quantity_name(q, lang))

    def to_json(self) -> dict:
        return {"kind": self.kind, "positions": list(self.positions), "explains": list(self.explains),
                "detail": self.detail, "deduction": self.deduction}


@dataclass(frozen=True)
class Diagnosis:
    causes: tuple[Cause, ...]
    unexplained: tuple[int, ...]  # indices of failing items no cause explains
    findings_left: tuple[int, ...]  # indices of findings no cause accounts for
    mark: float
    rubric: dict[str, float] = field(default_factory=dict)


# --------------------------------------------------------------------------- models


@dataclass
class _Model:
    """A candidate: for some items a predicted (value, mm); the rest as exact."""

    kind: str
    key: tuple  # causes with the same key at several positions merge
    detail: wd.Words
    positions: set[float]
    pred: dict[int, tuple[float | None, float | None]] = field(default_factory=dict)
    base: int = 0  # tie-break: larger is less likely
    free: bool = False  # a factor fitted to the student's figures


def _ok(it: Item, value: float | None, mm: float | None) -> bool:
    """The student's figure against a predicted one, at the figure's own tolerance."""
    if it.figure != "value" and it.student_mm is not None and mm is not None and it.tolerance_mm:
        return abs(it.student_mm - mm) <= it.tolerance_mm * (1 + VERDICT_REL)
    if value is None:
        return it.verdict == "pass"
    return abs(it.student - value) <= it.tolerance * (1 + VERDICT_REL)


class _Sheet:
    """The report's items with what the diagnosis needs of each."""

    def __init__(self, ctx: Context, items: tuple[Item, ...]) -> None:
        self.ctx, self.items = ctx, items
        d = ctx.scene.driver
        pin = ctx.scene.links[d.link].axis[1]
        #: computed from the data (ω1, v_A = ω1·l, a_A = ω1²·l), not read off a drawing
        self.data = {f"omega_{d.link}", f"v_{pin}", f"a_{pin}"}
        self.k_of = {pos.phi_deg: pos.index for pos in ctx.cf.positions}
        self.mu: list[float | None] = []
        for it in items:
            mu = None
            if it.exact_mm is not None and it.exact:
                mu = it.exact_mm / it.exact
            elif it.plan in ("velocity", "acceleration", "scheme") or it.exact_mm is not None:
                ex = exact_value(ctx, self.k_of[it.phi_deg], it.quantity)
                mu = ex.mm_per_unit if ex is not None else None
            self.mu.append(mu)
        self.fails = {i for i, it in enumerate(items) if it.verdict == "fail"}


def _plan_models(sh: _Sheet) -> list[_Model]:
    """The construction slips at every position, and the plans drawn at another scale."""
    ctx, items = sh.ctx, sh.items
    cf = ctx.cf
    mv, ma = cf.scales.get("velocity"), cf.scales.get("acceleration")
    if mv is None:
        return []
    drawn: list[Slip] = []
    for kind, mu in (("velocity", mv), ("acceleration", ma)):
        r = _fit([(it.student_mm, it.exact_mm) for it in items if it.plan == kind and it.figure != "value"
                  and it.source == "plan" and it.student_mm and it.exact_mm and it.exact_mm > 5.0])
        if mu is not None and r is not None and abs(r - 1) > 0.01:
            drawn.append(Slip("scale", kind, "drawn", kind, factor=r))
    out: list[_Model] = []
    scale_models = {s.target: _Model("scale", ("scale", "drawn", s.target), _scale_drawn(s, cf.scales), set(),
                                      free=True)
                    for s in drawn}
    wrong = _wrong_pairs(sh)
    for pos in cf.positions:
        k = pos.index
        # a segment read wrong and used on: ω of its link, the components computed from it
        reads = [w for w in wrong if items[w[0]].phi_deg == pos.phi_deg]
        mine = [i for i, it in enumerate(items) if it.phi_deg == pos.phi_deg and it.segment is not None
                and it.plan in ("velocity", "acceleration") and sh.mu[i]
                and not (it.figure == "value" and it.quantity in sh.data)]
        if not mine:
            continue
        try:
            with np.errstate(all="ignore"):
                slips = inventory(ctx.kin, k, mv, ma) + drawn
                for i, _, _, d in reads:
                    seg = items[i].segment
                    plan = ctx.plan(k, items[i].plan or "")
                    assert seg is not None and plan is not None
                    clean = abs(complex(*plan.xy(seg[1])) - complex(*plan.xy(seg[0])))
                    slips.append(Slip("wrong_segment", items[i].quantity, "read", items[i].plan or "",
                                      read_mm=(clean, d)))
                vp, ap = replay(ctx.kin, k, mv, ma, slips)
        except (PlansError, ArithmeticError, ValueError, KeyError):
            continue  # a construction that cannot be replayed here offers no model: the rest still do
        pts = {"velocity": vp, "acceleration": ap}
        for j, s in enumerate(slips):
            if s.kind == "scale":
                model = scale_models[s.target]
                model.positions.add(pos.phi_deg)
            elif s.kind == "wrong_segment":
                w = next(w for w in reads if items[w[0]].quantity == s.target)
                model = _Model("wrong_segment", ("wrong_segment", s.target, pos.phi_deg), wd.say("ca_kind", kind=""),
                               {pos.phi_deg})
                model.pred, model.detail = {}, _wrong_model(sh, *w).detail
                out.append(model)
            else:
                model = _Model(s.kind, (s.kind, s.target, s.variant, s.phase), describe(s), {pos.phi_deg},
                               base=2 if s.kind == "similarity" and s.variant == "inverted" else 1)
                out.append(model)
            own = f"a_{s.target[2:]}^n" if s.kind == "normal_from_pole" and s.variant == "from_pole" else None
            for i in mine:
                it = items[i]
                if it.quantity == own:  # laid off from the pole: its length is still ω²l at μa
                    continue
                seg = it.segment
                assert seg is not None and it.plan is not None
                got = pts[it.plan]
                if seg[0] not in got or seg[1] not in got:
                    continue
                mm = float(abs(got[seg[1]][j] - got[seg[0]][j]))
                mu = sh.mu[i]
                assert mu
                model.pred[i] = (mm / mu, mm)
            if s.kind == "wrong_segment":  # and the figures on the segment itself, as read
                w = next(w for w in reads if items[w[0]].quantity == s.target)
                model.pred.update(_wrong_model(sh, *w).pred)
    return out + list(scale_models.values())


def _fit(pairs: list[tuple[Any, Any]]) -> float | None:
    """The factor a plan is drawn at: least squares over its segments (the long ones, read
    to the same ±0.5 mm, weigh most), once more without those far off it (other slips)."""
    if len(pairs) < 3:
        return None
    r = float(median(s / e for s, e in pairs))
    for _ in range(2):
        near = [(s, e) for s, e in pairs if abs(s - r * e) <= 0.05 * r * e + 1.0] or pairs
        r = sum(s * e for s, e in near) / sum(e * e for _, e in near)
    return r


def _scale_drawn(s: Slip, scales: dict[str, float]) -> wd.Words:
    sym = "μv" if s.target == "velocity" else "μa"
    mu = scales[s.target]
    return wd.say("ca_scale_drawn", plan=wd.say("ca_plan_nom", kind=wd.plan(s.target)), sym=sym,
                  drawn=wd.n(mu * s.factor, ".4g"), mu=wd.n(mu, ".4g"), f=wd.n(s.factor, ".3f"))


def _value_scale_models(sh: _Sheet) -> list[_Model]:
    """A plan's values divided by another scale than the one its segments are drawn at
    (μ written one way and used another, μ and K confused, the scale inverted)."""
    out = []
    cf = sh.ctx.cf
    for kind, prefix in (("velocity", ("v_", "omega_")), ("acceleration", ("a_", "a^", "eps_"))):
        mu = cf.scales.get(kind)
        if mu is None:
            continue
        idx = [i for i, it in enumerate(sh.items) if it.figure == "value" and it.quantity.startswith(prefix)
               and it.exact and it.quantity not in sh.data]
        if len(idx) < 2:
            continue
        c = float(median(sh.items[i].student / sh.items[i].exact for i in idx))
        if abs(c - 1) <= 0.01:
            continue
        used = mu / c
        sym = "μv" if kind == "velocity" else "μa"
        how = wd.say("ca_divided", used=wd.n(used, ".4g"), sym=sym, mu=wd.n(mu, ".4g"))
        if abs(used * mu - 1) < 0.02:
            how = wd.say("ca_multiplied", sym=sym, mu=wd.n(mu, ".4g"))
        m = _Model("scale", ("scale", "values", kind), wd.say("ca_values_scale", kind=wd.plan(kind), how=how),
                   {sh.items[i].phi_deg for i in idx}, free=True)
        for i in idx:
            m.pred[i] = (c * sh.items[i].exact, None)
        out.append(m)
    return out


def _wrong_pairs(sh: _Sheet) -> list[tuple[int, str, str, float]]:
    """Failing segments whose length is that of another pair of points of their plan:
    (item, the pair, its length in mm)."""
    out = []
    ctx = sh.ctx
    for i in sorted(sh.fails):
        it = sh.items[i]
        if it.figure == "value" or it.student_mm is None or it.segment is None or it.exact_mm is None or \
                it.plan not in ("velocity", "acceleration") or not it.tolerance_mm or \
                abs(it.student_mm - it.exact_mm) <= 3 * it.tolerance_mm:
            continue  # a gross error only: a near miss is a drawing's, not another pair of points
        plan = ctx.plan(sh.k_of[it.phi_deg], it.plan)
        if plan is None:
            continue
        labels = [p.name for p in plan.points if not p.name.startswith(("n_", "k_"))]
        best = None
        for a_ix, a in enumerate(labels):
            za = complex(*plan.xy(a))
            for b in labels[a_ix + 1:]:
                if {a, b} == set(it.segment):
                    continue
                d = abs(complex(*plan.xy(b)) - za)
                gap = abs(d - it.student_mm)
                if d > 0 and gap <= it.tolerance_mm and (best is None or gap < best[0]):
                    best = (gap, a, b, d)
        if best is not None:
            out.append((i, best[1], best[2], best[3]))
    return out


def _wrong_model(sh: _Sheet, i: int, a: str, b: str, d: float) -> _Model:
    """The figures on the segment of item ``i`` read as the length ``d`` of the pair a–b
    (ω of its link too, where the student took it from there)."""
    it = sh.items[i]
    assert it.segment is not None
    m = _Model("wrong_segment", ("wrong_segment", it.quantity, it.phi_deg),
               wd.say("ca_wrong_segment", q=wd.q(it.quantity), a=wd.q(a), b=wd.q(b), d=wd.n(d, ".1f"), c=it.segment[0],
                      e=it.segment[1], kind=wd.plan(it.plan or "")), {it.phi_deg}, base=0)
    for j, other in enumerate(sh.items):
        if other.phi_deg == it.phi_deg and other.segment == it.segment and other.plan == it.plan and sh.mu[j] \
                and (other.quantity == it.quantity or j in sh.fails):  # ω from it: if the student used it
            mu = sh.mu[j]
            assert mu
            m.pred[j] = (d / mu, d)
    return m


def _wrong_segment_models(sh: _Sheet) -> list[_Model]:
    """A segment measured between the wrong points, its consequences on its own figures."""
    return [_wrong_model(sh, *w) for w in _wrong_pairs(sh)]


def _force_models(sh: _Sheet) -> list[_Model]:
    """A reaction's τ and n components swapped."""
    out = []
    by = {(it.phi_deg, it.quantity): i for i, it in enumerate(sh.items)}
    for (phi, q), i in by.items():
        got = quantities.reaction_name(q)
        if got is None or got[2] != "^τ" or (phi, q[:-2] + "^n") not in by:
            continue
        base = q[:-2]  # F_12, F_10_2: as the sheet spells it
        j = by[(phi, base + "^n")]
        ti, tj = sh.items[i], sh.items[j]
        if abs(ti.exact - tj.exact) <= max(ti.tolerance, tj.tolerance):
            continue
        model = _Model("reaction_swapped", ("reaction_swapped", base[2:], phi),
                       wd.say("ca_reaction", n=base[2:]),
                       {phi})
        model.pred[i] = (tj.exact, None)
        model.pred[j] = (ti.exact, None)
        out.append(model)
    return out


def reversed_couple(ctx: Context, lid: int) -> Any:
    """The force analysis with the inertia couple of link ``lid`` on the wrong side: the
    analysis is linear in its loads, so with M_Φ reversed it is 2·(without M_Φ) − (with)."""
    from plans.forces.polygons import analyse_forces

    got = ctx.forces()
    assert got is not None
    loads, _ = got
    return analyse_forces(ctx.scene, ctx.kin, replace(loads, inertias={**loads.inertias, lid: 0.0}))


def couple_value(fa: Any, fa0: Any, q: str, k: int) -> float | None:
    """|q| at position k with the couple reversed (``fa`` with it, ``fa0`` without)."""
    if q in ("F_bal", "F_bal_lever"):
        return abs(2 * float(fa0.balancing[k]) - float(fa.balancing[k]))
    got = quantities.reaction_name(q)
    if got is None:
        return None
    i, j, comp = got
    try:
        F, rc = quantities.reaction(fa, i, j)
        F0, rc0 = quantities.reaction(fa0, i, j)
    except KeyError:
        return None
    if comp is None:
        return abs(2 * complex(F0[k]) - complex(F[k]))
    arr, arr0 = (rc.tau, rc0.tau) if comp == "^τ" else (rc.n, rc0.n)
    if arr is None or arr0 is None:
        return None
    return abs(2 * float(arr0[k]) - float(arr[k]))


def _inertia_models(sh: _Sheet) -> list[_Model]:
    """An inertia couple applied with the wrong sign: every reaction and the balancing force."""
    ctx = sh.ctx
    if not any(sh.items[i].source == "forces" for i in sh.fails):
        return []
    got = ctx.forces()
    if got is None:
        return []
    loads, fa = got
    out = []
    for lid, inert in sorted(loads.inertias.items()):
        if inert <= 0 or lid not in loads.centres:
            continue
        fa0 = reversed_couple(ctx, lid)
        model = _Model("inertia_sign", ("inertia_sign", lid),
                       wd.say("ca_couple", i=str(lid)), {p.phi_deg for p in ctx.cf.positions})
        for i, it in enumerate(sh.items):
            if it.source == "forces":
                v = couple_value(fa, fa0, it.quantity, sh.k_of[it.phi_deg])
                if v is not None:
                    model.pred[i] = (v, None)
        out.append(model)
    return out


# --------------------------------------------------------------------------- choosing


def _score(model: _Model, sh: _Sheet, open_: set[int]) -> tuple[set[int], set[int], float, int]:
    """The failures a model explains, the passing figures it contradicts, how far the
    explained figures lie from the model's (in their tolerances: the closer the likelier),
    and how many failing figures it moves elsewhere than the student has them."""
    explains, contra = set(), set()
    miss = 0.0
    astray = 0
    for i, (value, mm) in model.pred.items():
        it = sh.items[i]
        ok = _ok(it, value, mm)
        if i in sh.fails:
            if ok and i in open_:
                explains.add(i)
                miss += _miss(it, value, mm)
            elif not ok and i in open_ and _miss(it, value, mm) > 0 and _moves(it, value, mm):
                astray += 1
        elif not ok:
            contra.add(i)
    return explains, contra, miss, astray


def _moves(it: Item, value: float | None, mm: float | None) -> bool:
    """The model puts the figure out of its tolerance of the exact one."""
    if it.figure != "value" and mm is not None and it.exact_mm is not None and it.tolerance_mm:
        return abs(mm - it.exact_mm) > it.tolerance_mm
    return value is not None and abs(value - it.exact) > it.tolerance


def _miss(it: Item, value: float | None, mm: float | None) -> float:
    if it.figure != "value" and it.student_mm is not None and mm is not None and it.tolerance_mm:
        return abs(it.student_mm - mm) / it.tolerance_mm
    if value is None or not it.tolerance:
        return 1.0
    return abs(it.student - value) / it.tolerance


def diagnose(ctx: Context, items: tuple[Item, ...], findings: tuple[Finding, ...],
             rubric: dict[str, float] | None = None) -> Diagnosis:
    """The causes behind a sheet's failures and findings (see the module docstring)."""
    rub = {**RUBRIC, **(rubric or {})}
    sh = _Sheet(ctx, items)
    chosen: list[tuple[_Model, set[int]]] = []
    open_ = set(sh.fails)
    if open_:
        builders: list[Callable[[_Sheet], list[_Model]]] = [_plan_models, _value_scale_models,
                                                              _wrong_segment_models, _force_models,
                                                              _inertia_models]
        models = [m for build in builders for m in build(sh)]
        while open_:
            best = None
            for m in models:
                ex, co, miss, astray = _score(m, sh, open_)
                if not ex or len(co) > len(ex) // 3 or (m.free and (len(ex) < 2 or co)) or astray > len(ex):
                    continue  # a fitted factor must explain several figures; a mistake, most of what it moves
                rank = (len(ex) - 2 * len(co), -round(miss / len(ex), 1), -_RANK.get(m.kind, 99), -m.base)
                if best is None or rank > best[0]:
                    best = (rank, m, ex)
            if best is None:
                break
            _, m, ex = best
            chosen.append((m, ex))
            open_ -= ex
            models.remove(m)
    # findings: grouped under a cause that explains one of their figures at their position
    quantity_at = {(items[i].phi_deg, items[i].quantity): n for n, (_, ex) in enumerate(chosen) for i in ex}
    by_cause: dict[int, list[int]] = {}
    hidden: dict[int, list[int]] = {}
    extra = _constants(ctx, items, open_)
    left: list[int] = []

    def owner_of(f: Finding) -> int | None:
        return next((quantity_at[(p, q)] for q in f.quantities
                     for p in ([f.phi_deg] if f.phi_deg is not None else [it.phi_deg for it in items])
                     if (p, q) in quantity_at), None)

    # a plan's values all off by one factor (the student's own figures show it): one cause,
    # under which each value's disagreement with its segment is grouped
    scaled: dict[str, _Row] = {}
    for fi, f in enumerate(findings):
        if f.kind != "scale" or owner_of(f) is not None:
            continue
        hits = {i for i in open_ if items[i].quantity in f.quantities}
        assert f.words is not None  # every finding of the check has its words
        row: _Row = ("scale", ("scale", "findings", f.message), f.words,
                     {items[i].phi_deg for i in hits} or {p.phi_deg for p in ctx.cf.positions}, hits, [fi],
                     f.quantities)
        extra.append(row)
        open_ -= hits
        for q in f.quantities:
            scaled.setdefault(q, row)
    for fi, f in enumerate(findings):
        if f.kind == "scale":
            continue
        owner = owner_of(f)
        if owner is not None:
            if f.kind == "swapped" and chosen[owner][0].kind != "wrong_segment":
                hidden.setdefault(owner, []).append(fi)  # "the wrong segment measured?": no, the mistake moved it
                continue
            by_cause.setdefault(owner, []).append(fi)
            continue
        if f.kind in ("arithmetic", "relation") and f.quantities and f.quantities[0] in scaled:
            scaled[f.quantities[0]][5].append(fi)
            continue
        kind = {"pi": "pi_rounded", "arithmetic": "arithmetic", "relation": "arithmetic"}.get(f.kind)
        if kind is None:
            left.append(fi)
            continue
        target = f.quantities[0] if f.quantities else ""
        phi = f.phi_deg
        hits = {i for i in open_ if items[i].quantity == target and (phi is None or items[i].phi_deg == phi)}
        key: tuple = (kind,) if kind == "pi_rounded" else (kind, target, phi)
        assert f.words is not None  # every finding of the check has its words
        detail = wd.say("ca_pi") if kind == "pi_rounded" else \
            wd.say("ca_not_follow", q=wd.q(target), what=wd.tail(f.words))
        extra.append((kind, key, detail, {phi} if phi is not None else set(), hits, [fi], ()))
        open_ -= hits
    causes = _merge(chosen, by_cause, extra, items, rub)
    causes = [replace(c, superseded=tuple(sorted(fi for n, fis in hidden.items() for fi in fis
                                                 if set(chosen[n][1]) & set(c.items))))
              for c in causes]
    unexplained = tuple(sorted(open_))
    mark = rub["full"] - sum(c.deduction for c in causes) - rub["unexplained"] * len(unexplained) \
        - rub["finding"] * len(left)
    return Diagnosis(tuple(causes), unexplained, tuple(left), max(0.0, round(mark, 1)), rub)


_Row = tuple[str, tuple, wd.Words, set[float], set[int], list[int], tuple[str, ...]]


def _constants(ctx: Context, items: tuple[Item, ...], open_: set[int]) -> list[_Row]:
    """Figures computed from the data with π = 3.14 (ω1, v_A, a_A) or g = 10 (the
    weights): the student's value is the rounded constant's to the digits written, and not
    the exact one; whatever else they pass or fail."""
    scene = ctx.scene
    d = scene.driver
    crank = scene.links[d.link]
    pin = crank.axis[1]
    out: list[_Row] = []
    for kind, powers, ratio, detail in (
            ("pi_rounded", {f"omega_{d.link}": 1, f"v_{pin}": 1, f"a_{pin}": 2}, PI_ROUNDED / math.pi,
             wd.say("ca_pi")),
            ("g_rounded", {f"G_{lid}": 1 for lid in scene.links}, G_ROUNDED / 9.81,
             wd.say("ca_g"))):
        if kind == "pi_rounded" and "omega_rpm" not in scene.raw.get("driver", {}):
            continue
        phis: set[float] = set()
        names: list[str] = []
        for pos in ctx.cf.positions:
            for w in pos.values:
                n = powers.get(w.quantity)
                ex = exact_value(ctx, pos.index, w.quantity) if n else None
                if ex is None or not ex.value or n is None:
                    continue
                hu = w.half_ulp + ROUND_OFF_REL * abs(ex.value)
                if abs(w.value - ex.value) > hu and abs(w.value - ex.value * ratio**n) <= hu:
                    phis.add(pos.phi_deg)
                    names.append(w.quantity)
        if names:
            hits = {i for i in open_ if items[i].quantity in names and items[i].phi_deg in phis}
            open_ -= hits
            out.append((kind, (kind,), detail, phis, hits, [], tuple(dict.fromkeys(names))))
    return out


def _merge(chosen: list[tuple[_Model, set[int]]], by_cause: dict[int, list[int]], extra: list[_Row],
           items: tuple[Item, ...], rub: dict[str, float]) -> list[Cause]:
    """One cause per mistake: the same slip at several positions is one mistake."""
    groups: dict[tuple, dict[str, Any]] = {}
    rows: list[_Row] = [(m.kind, m.key, m.detail, {items[i].phi_deg for i in ex} or m.positions, ex,
                         by_cause.get(n, []), ()) for n, (m, ex) in enumerate(chosen)] + extra
    for kind, key, detail, phis, ex, fis, named in rows:
        merge_key = key[:-1] if kind in ("wrong_segment", "arithmetic", "reaction_swapped") else \
            tuple(x for x in key if not isinstance(x, float))
        g = groups.setdefault((kind, merge_key), {"phis": set(), "items": set(), "findings": [], "detail": detail,
                                                  "names": []})
        g["names"] += named
        g["phis"] |= phis
        g["items"] |= ex
        g["findings"] += fis
    out = []
    for (kind, _), g in groups.items():
        detail = g["detail"]
        its = sorted(g["items"])
        names = tuple(dict.fromkeys([items[i].quantity for i in its] + g["names"]))
        out.append(Cause(kind, tuple(sorted(g["phis"])), names, detail.render("en"), rub.get(kind, 0.0), tuple(its),
                         tuple(sorted(g["findings"])), words=detail))
    out.sort(key=lambda c: (-c.deduction, -len(c.items), _RANK.get(c.kind, 99)))
    return out

