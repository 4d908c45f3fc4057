"""The force analysis as the draftsman writes it, step by step.

For each Assur group (farthest first): the moment equations that give the tangential
components or the couples of the prismatic pairs, each force with its arm on the drawing
(mm at μl) and in metres; then the polygon, force by force head to tail, and the closing
reactions.  Then the crank (ΣM_O and its polygon) and the Zhukovsky lever's moment
equation with the arms on the turned plan.  The same steps feed ``plans solve
--protocol``, the JSON (``positions[i].steps``) and the demonstration page.
"""

from __future__ import annotations

from dataclasses import dataclass

from plans.forces.lever import LeverAnalysis, lever_plan
from plans.forces.polygons import ForceAnalysis, GroupForces, force_polygons
from plans.kinematics.exact import cross
from plans.kinematics.plan import Plan, Step


@dataclass(frozen=True, slots=True)
class ForceStep:
    """One step of the force analysis: on which drawing (``plan``: "group 2-3", "crank",
    "lever") and the step itself (operation, inputs, output, sentence)."""

    plan: str
    step: Step


def _num(x: float) -> str:
    """A value as printed: zero up to round-off is 0."""
    return "0" if abs(x) < 1e-12 else f"{x:.6g}"


def _moment_terms(forces, moments, P: complex, k: int, mu_l: float) -> tuple[list[str], float]:
    """Signed moments of known forces (arms in mm on the scheme and in m) and couples about P."""
    terms, total = [], 0.0
    for f in forces:
        F = complex(f.F[k])
        if abs(F) == 0:
            continue
        m = cross(complex(f.r[k]) - P, F)
        h = abs(m) / abs(F)
        if h <= 1e-12 * max(abs(complex(f.r[k]) - P), 1e-300):  # passes through P up to round-off
            m, h = 0.0, 0.0
        terms.append(f"{'+' if m >= 0 else '−'}{f.label}·h ({_num(abs(F))} N × {h * mu_l:.2f} mm = {_num(h)} m)")
        total += m
    for mo in moments:
        M = float(mo.M[k])
        if M == 0:
            continue
        terms.append(f"{'+' if M >= 0 else '−'}{mo.label} ({_num(abs(M))} N·m)")
        total += M
    return terms, total


def _equation(name: str, terms: list[str], total: float, unknown: str) -> str:
    known = " ".join(terms) if terms else "0"
    return f"{name} = 0: {known}; known moments sum to {_num(total)} N·m (ccw +), so {unknown}."


def _group_steps(fa: ForceAnalysis, gf: GroupForces, k: int, mu_l: float) -> list[Step]:
    scene, kin = fa.scene, fa.kin
    g = gf.group
    i, j = g.links
    r1, r2, r3 = gf.reactions
    n1, n2, n3 = (rc.name(scene.fij) for rc in gf.reactions)
    out: list[Step] = []

    def about(point: str, link: int) -> complex:
        return complex(kin.point(point, link)[0][k])

    if g.kind in ("RRR", "RRP"):
        B = about(g.joints[1].point, i)
        A = about(g.joints[0].point, i)
        terms, total = _moment_terms(gf.loads_i, gf.moments_i, B, k, mu_l)
        assert r1.tau is not None
        out.append(Step("moment", (g.joints[1].point,), f"{n1}^τ", _equation(
            f"ΣM_{g.joints[1].point}({i})", terms, total,
            f"{n1}^τ · l_{g.joints[0].point}{g.joints[1].point} ({abs(B - A):.5g} m) balances them: "
            f"{n1}^τ = {_num(float(r1.tau[k]))} N")))
        terms, total = _moment_terms(gf.loads_j, gf.moments_j, B, k, mu_l)
        if g.kind == "RRR":
            assert r3.tau is not None
            Cc = about(g.joints[2].point, j)
            out.append(Step("moment", (g.joints[1].point,), f"{n3}^τ", _equation(
                f"ΣM_{g.joints[1].point}({j})", terms, total,
                f"{n3}^τ · l_{g.joints[2].point}{g.joints[1].point} ({abs(B - Cc):.5g} m) balances them: "
                f"{n3}^τ = {_num(float(r3.tau[k]))} N")))
        else:
            out.append(Step("moment", (g.joints[1].point,), n3, _equation(
                f"ΣM_{g.joints[1].point}({j})", terms, total,
                f"the guide's couple is {_num(float(r3.M[k]))} N·m: {n3} acts "
                f"{abs(float(r3.offset[k])) * mu_l:.2f} mm from {g.joints[1].point} along the guide")))
    elif g.kind == "RPR":
        A = about(g.joints[0].point, i)
        Cc = about(g.joints[2].point, j)
        terms, total = _moment_terms(gf.loads_i, gf.moments_i, A, k, mu_l)
        out.append(Step("moment", (g.joints[0].point,), n2, _equation(
            f"ΣM_{g.joints[0].point}({i})", terms, total, f"the slot's couple on the block is "
                                                         f"{_num(float(r2.M[k]))} N·m")))
        terms, total = _moment_terms(gf.loads_j, gf.moments_j, Cc, k, mu_l)
        out.append(Step("moment", (g.joints[2].point,), n2, _equation(
            f"ΣM_{g.joints[2].point}({j})", terms, total,
            f"{n2} ⟂ the slot, its arm {abs(cross(A - Cc, complex(1j * r2.guide[k]))) * mu_l:.2f} mm: "
            f"|{n2}| = {_num(abs(complex(r2.F[k])))} N" if r2.guide is not None else n2)))
    else:  # PRP, RPP: the couples of the prismatic pairs
        P = about(g.joints[1].point if g.kind == "PRP" else g.joints[0].point, i)
        terms, total = _moment_terms(gf.loads_i, gf.moments_i, P, k, mu_l)
        first = r1 if g.kind == "PRP" else r2
        out.append(Step("moment", (), first.name(scene.fij), _equation(
            f"ΣM({i})", terms, total, f"the couple of {first.name(scene.fij)} is {_num(float(first.M[k]))} N·m")))
        terms, total = _moment_terms(gf.loads_j, gf.moments_j, P, k, mu_l)
        out.append(Step("moment", (), n3, _equation(
            f"ΣM({j})", terms, total, f"the couple of {n3} is {_num(float(r3.M[k]))} N·m")))
    return out


def _crank_steps(fa: ForceAnalysis, k: int, mu_l: float) -> list[Step]:
    scene, kin = fa.scene, fa.kin
    c = fa.crank
    O = complex(kin.point(scene.driver.pivot, c.link)[0][k])
    terms, total = _moment_terms(c.loads, c.moments, O, k, mu_l)
    if c.kind == "force":
        l = abs(complex(c.r_point[k]) - O)
        what = (f"F_bal ⟂ O{c.point} with the arm l = {l * mu_l:.2f} mm ({l:.5g} m) balances them: "
                f"F_bal = {_num(float(fa.balancing[k]))} N along the motion of {c.point}")
    else:
        what = f"the balancing moment is M_bal = {_num(float(fa.balancing[k]))} N·m along ω1"
    return [Step("moment", (scene.driver.pivot,), "F_bal" if c.kind == "force" else "M_bal",
                 _equation(f"ΣM_{scene.driver.pivot}({c.link})", terms, total, what))]


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
        terms.append(f"{'+' if m >= 0 else '−'}{it.label}·h_{it.point} ({_num(F)} N × {float(it.arm[k]):.2f} mm)")
    unit = "N" if lv.fa.crank.kind == "force" else "N·m"
    bal = float(lv.signed(lv.by_lever)[k])
    arm = (f" × {float(lv.arm_bal[k]):.2f} mm" if lv.fa.crank.kind == "force" else "")
    eq = Step("moment", ("p",), "F_bal",
              f"ΣM_p = 0 on the lever: {' '.join(terms) or '0'} + F_bal·h_{lv.bal_point}{arm} = 0, "
              f"so F_bal = {_num(bal)} {unit} (by power balance {_num(float(lv.signed(lv.by_power)[k]))} {unit}).")
    return list(plan.steps[:-1]) + [eq]


def force_steps(fa: ForceAnalysis, lv: LeverAnalysis, k: int) -> tuple[ForceStep, ...]:
    """The whole force analysis of position k in the textbook's order."""
    mu_l = fa.scene.scales.get("length") or 1000.0
    polys = force_polygons(fa, k)
    out: list[ForceStep] = []
    for gf, poly in zip(fa.groups, polys, strict=False):
        name = f"group {gf.group.name}"
        out += [ForceStep(name, s) for s in _group_steps(fa, gf, k, mu_l)]
        out += [ForceStep(name, s) for s in poly.plan.steps]
    crank_poly = polys[-1]
    out += [ForceStep("crank", s) for s in _crank_steps(fa, k, mu_l)]
    out += [ForceStep("crank", s) for s in crank_poly.plan.steps]
    out += [ForceStep("lever", s) for s in _lever_steps(lv, k)]
    return tuple(out)


def steps_json(plans: tuple[Plan | None, ...], forces: tuple[ForceStep, ...]) -> list[dict]:
    """``positions[i].steps``: every step of the plans, the polygons and the lever, in order."""
    out = []
    for plan in plans:
        if plan is None:
            continue
        out += [{"plan": plan.kind, "op": s.op, "inputs": list(s.inputs), "output": s.output, "text": s.text}
                for s in plan.steps]
    out += [{"plan": f.plan, "op": f.step.op, "inputs": list(f.step.inputs), "output": f.step.output,
             "text": f.step.text} for f in forces]
    return out


def protocol_lines(forces: tuple[ForceStep, ...]) -> list[str]:
    """The force analysis for ``plans solve --protocol``, numbered per drawing."""
    lines: list[str] = []
    current, n = None, 0
    for f in forces:
        if f.plan != current:
            current, n = f.plan, 0
            lines.append(f"  force analysis, {f.plan}:")
        n += 1
        lines.append(f"   {n:2d}. {f.step.text}")
    return lines


__all__ = ["ForceStep", "force_steps", "protocol_lines", "steps_json"]
