"""Arithmetic consistency of the student's own work: value = segment/μ, ω = v/l, ε = a^τ/l,
a^n = v²/l, Φ = m a, M_Φ = I ε, similarity ratios, the % difference of the balancing forces."""

from __future__ import annotations

import itertools
import re
from collections.abc import Callable
from dataclasses import dataclass

from plans.check import wording as wd
from plans.check.checkfile import CheckFile, StudentPosition, Written
from plans.check.findings import (
    Finding,
    as_written,
    consistent,
    fmt,
    position_free,
    where_note,
    within,
)
from plans.check.providers import G_STANDARD, Context, exact_value, points_of


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
        pts = points_of(m.group(2))
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
    # a figure read off a drawing is as good as the reading (±segment_mm), whatever digits it has
    read = 0.0
    if ex is not None and ex.mm_per_unit and ex.tol_mm is not None and ex.plan in ("velocity", "acceleration"):
        read = ctx.cf.tolerance.segment_mm / ex.mm_per_unit
    for w in _written_any(pos, q, "measured"):
        if ex is not None and ex.mm_per_unit:
            out.append(_Input(w.value / ex.mm_per_unit, f"{as_written(w)} mm{where_note(w)} / {ex.mm_per_unit:g}", True,
                              max(w.half_ulp / ex.mm_per_unit, read)))
    for w in _written_any(pos, q, "value"):
        out.append(_Input(w.value, f"{as_written(w)}{where_note(w)}", True, max(w.half_ulp, read)))
    if not out and position_free(ctx.scene, q):  # a length or a mass written at another position
        for other in ctx.cf.positions:
            for w in other.written(q, "value"):
                out.append(_Input(w.value, f"{as_written(w)}{where_note(w)}", True, w.half_ulp))
    if not out and ex is not None:
        out.append(_Input(ex.value, f"{fmt(ex.value)} (exact)", False))
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
                                    f"({fmt(ratio)})·{sym}_{Q}{P} (similarity: l_{P}{name}/l_{P}{Q})"))
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


def relation_findings(ctx: Context, pos: StudentPosition) -> list[Finding]:
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
        read = cf.tolerance.segment_mm if cf.tolerance.model == "draftsman" else 0.0
        if any(consistent(w, m, ex.mm_per_unit, rel_tol, read) for m in measured):
            continue
        m = measured[0]
        want = m.value / ex.mm_per_unit
        words = wd.say("arithmetic", phi=wd.n(pos.phi_deg, "g"), q=wd.q(w.quantity), w=wd.w(as_written(w)),
                       where=where_note(w), m=wd.w(as_written(m)), mwhere=where_note(m),
                       mu=wd.n(ex.mm_per_unit, ".4g"), unit=wd.u(ex.unit), want=wd.n(want))
        out.append(Finding.of("arithmetic", words, pos.phi_deg, (w.quantity,), (w.where, m.where), (w.field, m.field)))
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
            ex = exact_value(ctx, pos.index, r.target)
            if w.kind == "measured":
                slack_abs = w.half_ulp / (ex.mm_per_unit if ex is not None and ex.mm_per_unit else 1.0)
            if ex is not None and ex.mm_per_unit and ex.tol_mm is not None and ex.plan in ("velocity", "acceleration") \
                    and _written_any(pos, r.target, "measured"):  # the target read off its own segment
                slack_abs = max(slack_abs, cf.tolerance.segment_mm / ex.mm_per_unit)
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
                if within(value, want, slack_abs + carried, rel_tol):
                    ok = True
                    break
            if ok or not results:
                continue
            want, combo = results[0]
            used = (", ", [wd.say("use", q=wd.q(q), w=wd.x(c.text)) for q, c in zip(r.inputs, combo, strict=True)])
            kind = "percent" if r.target == "F_bal_diff_pct" else "relation"
            shown = wd.say("fig_mm" if w.kind == "measured" else "fig", w=wd.w(as_written(w)), where="")
            hint = _percent_hint(cf, combo, value) if kind == "percent" else ""
            words = wd.say("relation", phi=wd.n(pos.phi_deg, "g"), target=wd.q(r.target), shown=shown,
                           where=where_note(w), formula=wd.formula(r.formula), want=wd.n(want), used=used,
                           hint=hint)
            out.append(Finding.of(kind, words, pos.phi_deg, (r.target,) + r.inputs, (w.where,), (w.field,)))
    return out


def _percent_hint(cf: CheckFile, combo: tuple[_Input, ...], value: float) -> wd.Words | str:
    lever, kin = combo[0].value, combo[1].value
    denominator = kin if cf.tolerance.balance_base == "lever" else lever
    if denominator == 0:  # a student's zero: no other denominator to suspect
        return ""
    other = 100 * abs(lever - kin) / denominator
    if abs(other - value) <= 0.01 * max(abs(value), 1e-9) + 0.005:
        key = "hint_lever" if cf.tolerance.balance_base == "lever" else "hint_kin"
        return wd.say(key, value=wd.n(value), other=wd.n(other), kin=wd.q("F_bal"), lever=wd.q("F_bal_lever"))
    return ""
