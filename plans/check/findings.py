"""What a report is made of (items, findings) and the findings about the student's own work:
the same figure written twice, figures symmetry makes equal, π = 3.14, a wrong scale,
swapped segments."""

from __future__ import annotations

import itertools
import math
import re
from dataclasses import dataclass
from typing import Any

import numpy as np

from plans.check import wording as wd
from plans.check.checkfile import CheckFile, StudentPosition, Written
from plans.check.providers import Context, points_of
from plans.tolerances import AGREE_REL, VERDICT_REL

PI_314 = 3.14

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
        if self.error_pct is None and self.student is not None:  # no % against a zero exact value
            return None
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
    message: str  # in English (the report); ``words`` writes it in any language
    phi_deg: float | None = None
    quantities: tuple[str, ...] = ()
    where: tuple[str, ...] = ()
    fields: tuple[str, ...] = ()
    words: wd.Words | None = None

    @classmethod
    def of(cls, kind: str, words: wd.Words, phi_deg: float | None = None, quantities: tuple[str, ...] = (),
           where: tuple[str, ...] = (), fields: tuple[str, ...] = ()) -> Finding:
        return cls(kind, words.render("en"), phi_deg, quantities, where, fields, words)

    def text(self, lang: str = "en") -> str:
        """The finding in ``lang``, quantities as that language writes them."""
        if self.words is None or lang != "ru":
            return self.message
        from plans.language import quantity_name

        return self.words.render(lang, lambda q: quantity_name(q, lang))

    def to_json(self, lang: str = "en") -> dict:
        return {"kind": self.kind, "message": self.text(lang), "phi_deg": self.phi_deg,
                "quantities": list(self.quantities), "where": list(self.where), "fields": list(self.fields)}


@dataclass(frozen=True, slots=True)
class Unchecked:
    quantity: str
    phi_deg: float
    student: float
    reason: str  # in English; ``words`` writes it in either language
    where: str
    words: wd.Words | None = None

    def text(self, lang: str = "en") -> str:
        return self.words.render(lang) if self.words is not None and lang == "ru" else self.reason

    def to_json(self, lang: str = "en") -> dict:
        return {"quantity": self.quantity, "phi_deg": self.phi_deg, "student": self.student,
                "reason": self.text(lang), "where": self.where}


def consistent(w: Written, m: Written, mm_per_unit: float, rel: float, read_mm: float = 0.0) -> bool:
    """A value that is its measured segment over the scale, to the student's rounding and
    to the reading of the segment (±``read_mm``: the digits typed do not narrow it)."""
    want = m.value / mm_per_unit
    slack = max(w.half_ulp + m.half_ulp / mm_per_unit, read_mm / mm_per_unit)
    return abs(w.value - want) <= slack + rel * abs(want) + 1e-12


# --------------------------------------------------------------------------- consistency


def fmt(x: float, lang: str = "en") -> str:
    """A computed number, four significant digits (whole numbers above 10 000); a decimal
    comma in Russian."""
    if x == 0:
        return "0"
    s = f"{x:.0f}" if abs(x) >= 1e4 else f"{x:.4g}"
    return s.replace(".", ",") if lang == "ru" else s


def as_written(w: Written) -> str:
    """A figure as the student wrote it."""
    x = w.value
    if w.half_ulp >= 0.5 and float(x).is_integer():
        return str(int(x))
    s = repr(float(x))
    return s[:-2] if s.endswith(".0") else s


def where_note(w: Written) -> str:
    return f" ({w.where})" if w.where else ""


def _same(a: Written, b: Written, rel: float) -> bool:
    slack = a.half_ulp + b.half_ulp + rel * max(abs(a.value), abs(b.value))
    return abs(a.value - b.value) <= slack


def duplicate_findings(cf: CheckFile, pos: StudentPosition) -> list[Finding]:
    out = []
    rel = cf.tolerance.arithmetic_pct / 100.0
    for kind in ("value", "measured"):
        groups: dict[str, list[Written]] = {}
        for x in (pos.values if kind == "value" else pos.measured):
            groups.setdefault(x.quantity, []).append(x)
        for qn, ws in groups.items():
            if len(ws) < 2:
                continue
            if all(_same(ws[0], x, rel) for x in ws[1:]):
                continue
            fig = "fig_mm" if kind == "measured" else "fig"
            shown = [wd.say(fig, w=wd.w(as_written(x)), where=where_note(x)) for x in ws]
            words = wd.say("duplicate_segment" if kind == "measured" else "duplicate", phi=wd.n(pos.phi_deg, "g"),
                        q=wd.q(qn), shown=shown)
            out.append(Finding.of("duplicate", words, pos.phi_deg, (qn,), tuple(x.where for x in ws),
                                  tuple(x.field for x in ws)))
    return out


_POSITION_FREE = re.compile(r"^(m|I|G)_\d+$|^l_\w+$")


def position_free(scene: Any, q: str) -> bool:
    """A mass, an inertia, or the length between two points of one rigid link; not the
    distance of a block from its rocker's pivot (l_CA of a shaper changes with the angle)."""
    if not _POSITION_FREE.match(q):
        return False
    if not q.startswith("l_"):
        return True
    pts = points_of(q[2:])
    if len(pts) != 2:
        return True
    return any(set(pts) <= set(link.points) for link in scene.links.values()) \
        or set(pts) <= set(scene.frame_points)


def across_positions_findings(cf: CheckFile) -> list[Finding]:
    """Masses, inertias, lengths do not depend on the crank angle."""
    out = []
    rel = cf.tolerance.arithmetic_pct / 100.0
    seen: dict[str, list[tuple[float, Written]]] = {}
    for pos in cf.positions:
        for w in pos.values:
            if position_free(cf.scene, w.quantity):
                seen.setdefault(w.quantity, []).append((pos.phi_deg, w))
    for qn, ws in seen.items():
        phis = {p for p, _ in ws}
        if len(phis) < 2:
            continue
        first = ws[0][1]
        bad = [(p, x) for p, x in ws if not _same(first, x, rel) and p != ws[0][0]]
        if bad:
            shown = [wd.say("fig_at", w=wd.w(as_written(x)), phi=wd.n(p, "g"), where=where_note(x)) for p, x in ws]
            out.append(Finding.of("duplicate", wd.say("across", q=wd.q(qn), shown=shown),
                                  None, (qn,), tuple(x.where for _, x in ws), tuple(x.field for _, x in ws)))
    return out




def symmetry_findings(cf: CheckFile, pos: StudentPosition, items: list[Item]) -> list[Finding]:
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
        if abs(ia.exact - ib.exact) > AGREE_REL * abs(ia.exact):
            continue
        gap = abs(ia.student - ib.student)
        # the student should write the same figure twice: allow the reading of two segments
        # (±seg each) or the rounding of two values
        allow = _half_ulp_of(ia.student) + _half_ulp_of(ib.student) + rel * abs(ia.exact)
        if ia.exact_mm and ib.exact_mm:  # read off the drawing (directly or through a segment)
            allow += 2 * seg_mm / (ia.exact_mm / ia.exact)
        if gap > allow * (1 + VERDICT_REL):
            mm: wd.Words | str = ""
            if ia.figure != "value" and ib.figure != "value" and ia.student_mm is not None \
                    and ib.student_mm is not None:
                mm = wd.say("mm_pair", x=wd.n(ia.student_mm), y=wd.n(ib.student_mm))
            words = wd.say("symmetry", phi=wd.n(pos.phi_deg, "g"), a=wd.q(a), b=wd.q(b), exact=wd.n(ia.exact), unit=wd.u(ia.unit),
                        sa=wd.n(ia.student), wa=_at_item(ia), sb=wd.n(ib.student), wb=_at_item(ib), mm=mm)
            out.append(Finding.of("symmetry", words, pos.phi_deg, (a, b), (ia.where, ib.where), (ia.field, ib.field)))
    return out


def _at_item(it: Item) -> str:
    return f" ({it.where})" if it.where else ""


def swapped_findings(ctx: Context, pos: StudentPosition, items: list[Item]) -> list[Finding]:
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
                words = wd.say("swapped", phi=wd.n(pos.phi_deg, "g"), q=wd.q(it.quantity), smm=wd.n(it.student_mm),
                            s=wd.q(s.label), pmm=wd.n(partner.student_mm), plan=wd.plan(it.plan), emm=wd.n(it.exact_mm),
                            slen=wd.n(s.length_mm))
                out.append(Finding.of("swapped", words, pos.phi_deg, (it.quantity, s.label),
                                      (it.where, partner.where), (it.field, partner.field)))
            elif abs(it.student_mm - it.exact_mm) > 3 * own_tol:
                words = wd.say("wrong_segment", phi=wd.n(pos.phi_deg, "g"), q=wd.q(it.quantity), smm=wd.n(it.student_mm),
                            where=_at_item(it), s=wd.q(s.label), slen=wd.n(s.length_mm), emm=wd.n(it.exact_mm))
                out.append(Finding.of("swapped", words, pos.phi_deg, (it.quantity, s.label), (it.where,),
                                      (it.field,)))
            break
    return out


def pi_findings(cf: CheckFile, items: list[Item]) -> list[Finding]:
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
                words = wd.say("pi", phi=wd.n(it.phi_deg, "g"), q=wd.q(it.quantity), s=wd.n(it.student), where=_at_item(it),
                            exact=wd.n(it.exact), unit=wd.u(it.unit), pct=wd.n(100 * (it.student / it.exact - 1), "+.3f"))
                out.append(Finding.of("pi", words, it.phi_deg, (it.quantity,), (it.where,), (it.field,)))
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


def scale_findings(cf: CheckFile, items: list[Item]) -> list[Finding]:
    """A plan whose figures are all off by one factor: values divided by another μ than the
    sheet's, or segments drawn at another μ."""
    out = []
    for kind in ("velocity", "acceleration"):
        mu = cf.scales.get(kind)
        if mu is None:
            continue
        sym = "μv" if kind == "velocity" else "μa"
        prefix = "v_" if kind == "velocity" else "a_"
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
                words = wd.say("scale_values", plan=wd.plan(kind), mu2=wd.n(mu / r, ".3g"), sym=sym, mu=wd.n(mu),
                            pct=wd.n(100 * (r - 1), "+.1f"))
                out.append(Finding.of("scale", words, None, tuple(dict.fromkeys(members))))
        rows = [i for i in items if i.plan == kind and i.source == "plan" and i.figure != "value"
                and i.exact_mm and i.exact_mm > 5 and i.student_mm]
        ratios = [(i.student_mm or 0.0) / (i.exact_mm or 1.0) for i in rows]
        if len(ratios) >= 3:
            r = float(np.median(ratios))
            if abs(r - 1) > 0.02 and max(abs(x / r - 1) for x in ratios) < 0.02:
                words = wd.say("scale_drawn", plan=wd.plan(kind), r=wd.n(r, ".3f"), sym=sym, mu=wd.n(mu), mu2=wd.n(mu * r, ".3g"))
                out.append(Finding.of("scale", words, None, tuple(dict.fromkeys(i.quantity for i in rows))))
    return out


# --------------------------------------------------------------------------- text and CSV
