"""The force analysis as the draftsman writes it, step by step.

For each Assur group (farthest first): the moment equations that give the tangential
components or the couples of the prismatic pairs, each force with its arm on the drawing
(mm at μl) and in metres; then the polygon, force by force head to tail, and the closing
reactions.  Then the crank (ΣM_O and its polygon) and the Zhukovsky lever's moment
equation with the arms on the turned plan.  The same steps feed ``plans solve
--protocol``, the JSON (``positions[i].steps``) and the demonstration page.
"""

from __future__ import annotations

from plans.forces.lever import LeverAnalysis, lever_plan
from plans.forces.polygons import ForceAnalysis, GroupForces, force_polygons
from plans.kinematics.plan import Plan, Step
from plans.lines import cross
from plans.phrases import Phrase, phrase
from plans.records import frozen
from plans.tolerances import EXACT_ZERO_REL


@frozen
class Arm:
    """A known force's arm in a moment equation, on the scheme (m): the perpendicular from the
    point the moments are taken about (``about``) to the force's line, met at ``foot``; the
    force acts at ``at``."""

    label: str
    about: complex
    foot: complex
    at: complex


@frozen
class ForceStep:
    """One step of the force analysis: on which drawing (``plan``: "group 2-3", "crank",
    "lever"), the step itself (operation, inputs, output, sentence) and, for a moment
    equation, the arms of its known forces on the scheme."""

    plan: str
    step: Step
    arms: tuple[Arm, ...] = ()


def _moment_terms(forces, moments, P: complex, k: int, mu_l: float) -> tuple[list[Phrase], float, list[Arm]]:
    """Signed moments of known forces (arms in mm on the scheme and in m) and couples about
    P, and each force's arm where it has one."""
    terms, total, arms = [], 0.0, []
    for f in forces:
        F = complex(f.F[k])
        if abs(F) == 0:
            continue
        r = complex(f.r[k])
        m = cross(r - P, F)
        h = abs(m) / abs(F)
        if h <= EXACT_ZERO_REL * max(abs(r - P), 1e-300):  # passes through P up to round-off
            m, h = 0.0, 0.0
        else:
            d = F / abs(F)
            arms.append(Arm(f.label, P, r + d * ((P - r) * d.conjugate()).real, r))
        terms.append(phrase("m_term_force", sign="+" if m >= 0 else "−", label=f.label, F=abs(F), mm=h * mu_l, h=h,
                            M=abs(F) * h))
        total += m
    for mo in moments:
        M = float(mo.M[k])
        if M == 0:
            continue
        terms.append(phrase("m_term_couple", sign="+" if M >= 0 else "−", label=mo.label, M=abs(M)))
        total += M
    return terms, total, arms


def _equation(op: str, inputs: tuple[str, ...], output: str, name: str,
              known: tuple[list[Phrase], float, list[Arm]], unknown: Phrase) -> tuple[Step, tuple[Arm, ...]]:
    """The step of one moment equation (the known moments and what they give), with the
    known forces' arms."""
    terms, total, arms = known
    return Step.of(op, inputs, output, phrase("m_equation", name=name, known=terms or phrase("m_zero"),
                                              total=total, unknown=unknown)), tuple(arms)


def _group_steps(fa: ForceAnalysis, gf: GroupForces, k: int, mu_l: float) -> list[tuple[Step, tuple[Arm, ...]]]:
    scene, kin = fa.scene, fa.kin
    g = gf.group
    i, j = g.links
    r1, r2, r3 = gf.reactions
    n1, n2, n3 = (rc.name(scene.fij) for rc in gf.reactions)
    p1, p2, p3 = (jt.point for jt in g.joints)
    out: list[tuple[Step, tuple[Arm, ...]]] = []

    def about(point: str, link: int) -> complex:
        return complex(kin.point(point, link)[0][k])

    if g.kind in ("RRR", "RRP"):
        B = about(p2, i)
        A = about(p1, i)
        known = _moment_terms(gf.loads_i, gf.moments_i, B, k, mu_l)
        assert r1.tau is not None
        out.append(_equation("moment", (p2,), f"{n1}^τ", f"ΣM_{p2}({i})", known, phrase(
            "m_tau", n=n1, A=p1, B=p2, l=abs(B - A), tau=float(r1.tau[k]))))
        known = _moment_terms(gf.loads_j, gf.moments_j, B, k, mu_l)
        if g.kind == "RRR":
            assert r3.tau is not None
            Cc = about(p3, j)
            out.append(_equation("moment", (p2,), f"{n3}^τ", f"ΣM_{p2}({j})", known, phrase(
                "m_tau", n=n3, A=p3, B=p2, l=abs(B - Cc), tau=float(r3.tau[k]))))
        else:
            out.append(_equation("moment", (p2,), n3, f"ΣM_{p2}({j})", known, phrase(
                "m_guide", M=float(r3.M[k]), n=n3, mm=abs(float(r3.offset[k])) * mu_l, B=p2)))
    elif g.kind == "RPR":
        A = about(p1, i)
        Cc = about(p3, j)
        known = _moment_terms(gf.loads_i, gf.moments_i, A, k, mu_l)
        out.append(_equation("moment", (p1,), n2, f"ΣM_{p1}({i})", known,
                             phrase("m_slot_couple", M=float(r2.M[k]))))
        known = _moment_terms(gf.loads_j, gf.moments_j, Cc, k, mu_l)
        slot = (phrase("m_slot", n=n2, mm=abs(cross(A - Cc, complex(1j * r2.guide[k]))) * mu_l,
                       F=abs(complex(r2.F[k]))) if r2.guide is not None else phrase("m_name", n=n2))
        out.append(_equation("moment", (p3,), n2, f"ΣM_{p3}({j})", known, slot))
    else:  # PRP, RPP: the couples of the prismatic pairs
        P = about(p2 if g.kind == "PRP" else p1, i)
        known = _moment_terms(gf.loads_i, gf.moments_i, P, k, mu_l)
        first = r1 if g.kind == "PRP" else r2
        out.append(_equation("moment", (), first.name(scene.fij), f"ΣM({i})", known,
                             phrase("m_couple_of", n=first.name(scene.fij), M=float(first.M[k]))))
        known = _moment_terms(gf.loads_j, gf.moments_j, P, k, mu_l)
        out.append(_equation("moment", (), n3, f"ΣM({j})", known,
                             phrase("m_couple_of", n=n3, M=float(r3.M[k]))))
    return out


def _crank_steps(fa: ForceAnalysis, k: int, mu_l: float) -> list[tuple[Step, tuple[Arm, ...]]]:
    scene, kin = fa.scene, fa.kin
    c = fa.crank
    O = complex(kin.point(scene.driver.pivot, c.link)[0][k])
    known = _moment_terms(c.loads, c.moments, O, k, mu_l)
    if c.kind == "force":
        l = abs(complex(c.r_point[k]) - O)
        what = phrase("m_crank_force", pt=c.point, mm=l * mu_l, l=l, F=float(fa.balancing[k]))
    else:
        what = phrase("m_crank_moment", M=float(fa.balancing[k]))
    return [_equation("moment", (scene.driver.pivot,), "F_bal" if c.kind == "force" else "M_bal",
                      f"ΣM_{scene.driver.pivot}({c.link})", known, what)]


def _lever_steps(lv: LeverAnalysis, k: int) -> list[Step]:
    plan = lever_plan(lv, k)
    if not bool(lv.valid[k]):
        return list(plan.steps)
    terms = []
    for it in lv.forces:
        F = abs(complex(it.F[k]))
        if F == 0:
            continue
        m = float(it.moment[k]) / 1000.0  # N·mm on the plan → N·m
        terms.append(phrase("l_term", sign="+" if m >= 0 else "−", label=it.label, pt=it.point, F=F,
                            h=float(it.arm[k])))
    unit = "N" if lv.fa.crank.kind == "force" else "N·m"
    bal = float(lv.signed(lv.by_lever)[k])
    arm = phrase("l_arm", a=float(lv.arm_bal[k])) if lv.fa.crank.kind == "force" else phrase("nothing")
    eq = Step.of("moment", ("p",), "F_bal", phrase(
        "l_equation", terms=terms or phrase("m_zero"), pt=lv.bal_point, arm=arm, F=bal, unit=unit,
        P=float(lv.signed(lv.by_power)[k])))
    return list(plan.steps[:-1]) + [eq]


def force_steps(fa: ForceAnalysis, lv: LeverAnalysis, k: int) -> tuple[ForceStep, ...]:
    """The whole force analysis of position k in the textbook's order."""
    mu_l = fa.scene.scales.get("length") or 1000.0
    polys = force_polygons(fa, k)
    out: list[ForceStep] = []
    for gf, poly in zip(fa.groups, polys, strict=False):
        name = f"group {gf.group.name}"
        if hasattr(gf, "S"):  # class III: the leashes' and the group's moments about Assur's point
            from plans.forces.triad_polygon import triad_steps

            out += [ForceStep(name, s, arms) for s, arms in triad_steps(fa, gf, k, mu_l, _equation, _moment_terms)]  # type: ignore[arg-type]
        else:
            out += [ForceStep(name, s, arms) for s, arms in _group_steps(fa, gf, k, mu_l)]
        out += [ForceStep(name, s) for s in poly.plan.steps]
    crank_poly = polys[-1]
    out += [ForceStep("crank", s, arms) for s, arms in _crank_steps(fa, k, mu_l)]
    out += [ForceStep("crank", s) for s in crank_poly.plan.steps]
    out += [ForceStep("lever", s) for s in _lever_steps(lv, k)]
    return tuple(out)


def steps_json(plans: tuple[Plan | None, ...], forces: tuple[ForceStep, ...], lang: str = "en") -> list[dict]:
    """``positions[i].steps``: every step of the plans, the polygons and the lever, in order;
    the operations as the program names them, the sentences in ``lang`` (in Russian with the
    textbook's symbols, as ``plans solve --protocol`` writes them)."""
    from plans.language import symbols

    def text(step: Step) -> str:
        return symbols(step.say(lang), lang) if lang == "ru" else step.text

    out = []
    for plan in plans:
        if plan is None:
            continue
        out += [{"plan": plan.kind, "op": s.op, "inputs": list(s.inputs), "output": s.output, "text": text(s)}
                for s in plan.steps]
    out += [{"plan": f.plan, "op": f.step.op, "inputs": list(f.step.inputs), "output": f.step.output,
             "text": text(f.step)} for f in forces]
    return out


def protocol_lines(forces: tuple[ForceStep, ...], lang: str = "en") -> list[str]:
    """The force analysis for ``plans solve --protocol``, numbered per drawing, in ``lang``."""
    from plans.phrases import say

    lines: list[str] = []
    current, n = None, 0
    for f in forces:
        if f.plan != current:
            current, n = f.plan, 0
            plan = f.plan
            if lang == "ru":
                plan = say("t_" + plan, lang) if plan in ("crank", "lever") else plan.replace("group", "группа")
            lines.append(say("t_force_protocol", lang, plan=plan))
        n += 1
        lines.append(f"   {n:2d}. {f.step.say(lang)}")
    return lines


__all__ = ["Arm", "ForceStep", "force_steps", "protocol_lines", "steps_json"]
