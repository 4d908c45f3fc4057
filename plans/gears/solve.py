"""A gear file solved: shifts chosen, every pair's geometry, the train's speeds two ways,
the planetary synthesis; and the JSON (lengths in the file's unit)."""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Any

from plans.errors import InputError, Said
from plans.tolerances import EXACT_ZERO_REL

from . import shifts
from .geometry import Pair, pair
from .model import GearFile
from .synthesis import TeethSet, synthesise
from .train import TrainMesh, VelocityPlan, velocity_plan, willis


@dataclass(frozen=True)
class GearSolution:
    file: GearFile
    x: dict[str, float]  # shift of every gear, chosen ones included
    pairs: tuple[Pair, ...]  # one per mesh, in the file's order (ring second when internal)
    omega: dict[str, float] | None  # rad/s per shaft by Willis (None: no speeds given)
    plan: VelocityPlan | None
    synthesis: TeethSet | None

    def drawn_pairs(self) -> list[Pair]:
        """The pairs the meshing sheets draw: those marked ``draw``, else the first external
        one (else the first)."""
        marked = [p for me, p in zip(self.file.meshes, self.pairs, strict=True) if me.draw]
        if marked:
            return marked
        first = next((p for p in self.pairs if not p.internal), self.pairs[0] if self.pairs else None)
        return [first] if first is not None else []


def _ordered(gf: GearFile, names: tuple[str, str]) -> tuple[str, str]:
    a, b = names
    return (b, a) if gf.gears[a].internal else (a, b)


def choose_shifts(gf: GearFile) -> dict[str, float]:
    x: dict[str, float] = {n: g.x for n, g in gf.gears.items() if g.x is not None}
    auto = [n for n, g in gf.gears.items() if g.x is None]
    if gf.shift_rule == "equal_sliding":
        for me in gf.meshes:
            a, b = _ordered(gf, me.gears)
            ga, gb = gf.gears[a], gf.gears[b]
            if a in auto and b in auto and a not in x and b not in x and not gb.internal:
                x[a], x[b] = shifts.equal_sliding((a, b), (ga.z, gb.z), ga.module, gf.alpha, gf.ha, gf.c)
    for n in auto:
        if n not in x:
            g = gf.gears[n]
            x[n] = shifts.single(gf.shift_rule, g.z, g.internal, gf.alpha, gf.ha)
    # a mesh assembled at a given centre distance takes the shift sum that centre needs
    for i, me in enumerate(gf.meshes):
        a, b = _ordered(gf, me.gears)
        if me.centre_distance is None or not (a in auto or b in auto):
            continue
        ga, gb = gf.gears[a], gf.gears[b]
        from .geometry import sum_for_centre

        S = sum_for_centre(ga.z, gb.z, ga.module, gf.alpha, gb.internal, me.centre_distance)
        if not math.isfinite(S):
            raise InputError(Said("gv_impossible_centre_distance", a=a, b=b), file=gf.path,
                             field=f"meshes[{i}].centre_distance")
        if b in auto:
            x[b] = S - x[a] if not gb.internal else S + x[a]
        else:
            x[a] = S - x[b] if not gb.internal else x[b] - S
    return x


def solve_gears(gf: GearFile) -> GearSolution:
    x = choose_shifts(gf)
    # first pass: Δy of every external mesh; a gear's tip is shortened by the largest Δy of
    # its external meshes (the course's rule for the wheel between two others)
    first = []
    for i, me in enumerate(gf.meshes):
        a, b = _ordered(gf, me.gears)
        ga, gb = gf.gears[a], gf.gears[b]
        first.append(pair((a, b), (ga.z, gb.z), (x[a], x[b]), gb.internal, ga.module, gf.alpha, gf.ha,
                          gf.c, (0.0, 0.0), me.centre_distance, f"meshes[{i}]", gf.path, gb.ring_tip))
    dy = {n: 0.0 for n in gf.gears}
    for p in first:
        if not p.internal:
            for n in p.gears:
                dy[n] = max(dy[n], p.delta_y)
    pairs = []
    for i, (me, p0) in enumerate(zip(gf.meshes, first, strict=True)):
        a, b = p0.gears
        ga, gb = gf.gears[a], gf.gears[b]
        pairs.append(pair((a, b), (ga.z, gb.z), (x[a], x[b]), gb.internal, ga.module, gf.alpha, gf.ha,
                          gf.c, (dy[a], 0.0 if gb.internal else dy[b]), me.centre_distance,
                          f"meshes[{i}]", gf.path, gb.ring_tip))
    omega, plan = None, None
    if gf.meshes and any(s.speed_rpm is not None for s in gf.shafts.values()):
        tm = train_meshes(gf, pairs)
        omega = willis(gf.shafts, tm, gf.path)
        size = max([abs(p.a_w) + max(w.working for w in p.wheels) for p in pairs] + [1e-9])
        mu_l = _plan_scale(size * len(pairs))
        plan = velocity_plan(gf.shafts, tm, gf.path, mu_l=mu_l)
    synth = synthesise(gf.synthesis, gf.ha, gf.path) if gf.synthesis else None
    return GearSolution(gf, x, tuple(pairs), omega, plan, synth)


def _plan_scale(size_m: float, target_mm: float = 320.0) -> float:
    """A standard scale (mm per m, 5:1 … 1:100) drawing the unfolded train within
    ``target_mm``; 1:100 where none does."""
    from plans.kinematics.scales import RATIOS, ratio_scale

    return ratio_scale(size_m, target_mm, RATIOS[1:]) or 10.0


def train_meshes(gf: GearFile, pairs: list[Pair] | tuple[Pair, ...]) -> list[TrainMesh]:
    out = []
    for p in pairs:
        a, b = p.gears
        ring = b if p.internal else None
        out.append(TrainMesh((a, b), (gf.gears[a].shaft, gf.gears[b].shaft), (gf.gears[a].z, gf.gears[b].z),
                             (p.wheels[0].working, p.wheels[1].working), ring))
    return out


def _r(v: float) -> float:
    """Numbers in the JSON: 13 significant digits (the metre/mm round trip's last bits
    dropped, 52.00000000000001 is 52.0), and no -0.0."""
    return 0.0 if v == 0 else float(f"{v:.13g}")


def to_json(sol: GearSolution, contact_ratio_drawn: dict[tuple[str, str], float] | None = None
            ) -> dict[str, Any]:
    gf = sol.file
    k = gf.to_unit
    meshes = []
    for p in sol.pairs:
        radii = {w.name: {"pitch": _r(w.pitch * k), "base": _r(w.base * k), "tip": _r(w.tip * k),
                          "root": _r(w.root * k), "working": _r(w.working * k)} for w in p.wheels}
        drawn = (contact_ratio_drawn or {}).get(p.gears)
        meshes.append({
            "gears": list(p.gears),
            "internal": p.internal,
            "x": {w.name: _r(w.x) for w in p.wheels},
            "working_pressure_angle_deg": math.degrees(p.alpha_w),
            "reference_centre_distance": _r(p.a * k),
            "centre_distance": _r(p.a_w * k),
            "y": _r(p.y),
            "delta_y": _r(p.delta_y),
            "backlash": _r(p.backlash * k),
            "contact_ratio": p.contact_ratio,
            "contact_ratio_drawn": drawn,
            "radii": radii,
            "tip_pressure_angle_deg": {w.name: math.degrees(w.tip_angle) for w in p.wheels},
            "thickness": {w.name: _r(w.thickness * k) for w in p.wheels},
            "tip_thickness": {w.name: _r(w.tip_thickness * k) for w in p.wheels},
            "base_pitch": _r(p.p_b * k),
            "line_of_action": {"N1N2": _r(p.g * k), "N1B1": _r(p.rho_start * k), "N1B2": _r(p.rho_end * k),
                               "N1P": _r(p.rho_p * k)},
            "specific_sliding": {w.name: (s if math.isfinite(s) else None)
                                 for w, s in zip(p.wheels, p.sliding, strict=True)},
            "checks": p.checks(),
        })
        if p.internal:
            from .geometry import RING_TIPS, ring_tip_radius

            ring = p.wheels[1]
            g = gf.gears[ring.name]
            meshes[-1]["ring_tip"] = {"rule": g.ring_tip} | {
                rule: _r(ring_tip_radius(ring.pitch, ring.z, ring.x, p.m, p.alpha, gf.ha, rule) * k)
                for rule in RING_TIPS}
    out: dict[str, Any] = {"unit": gf.unit, "x": {n: _r(sol.x[n]) for n in gf.gears}, "meshes": meshes}
    out["ratios"] = ratios(sol)
    if sol.omega is not None and sol.plan is not None:
        out["speeds_rpm"] = {n: _r(w * 30.0 / math.pi) for n, w in sol.omega.items()}
        out["speeds_rpm_plan"] = {n: _r(ln.omega * 30.0 / math.pi) for n, ln in sol.plan.lines.items()}
    if sol.synthesis is not None:
        t = sol.synthesis
        out["synthesis"] = {"z1": t.z1, "z2": t.z2, "z3": t.z3, "planets": t.planets, "ratio": t.ratio,
                            "conditions": t.conditions(gf.ha)}
    return out


def ratios(sol: GearSolution) -> dict[str, float]:
    """Per mesh i_ab = ω_a/ω_b = ∓z_b/z_a (fixed axes), and, with speeds, from the driving
    shaft (the first with a non-zero given speed) to every other moving shaft."""
    gf = sol.file
    out: dict[str, float] = {}
    for p in sol.pairs:
        a, b = p.gears
        za, zb = gf.gears[a].z, gf.gears[b].z
        out[f"{a}-{b}"] = (zb / za) if p.internal else -(zb / za)
    if sol.omega:
        drive = next((n for n, s in gf.shafts.items() if s.speed_rpm), None)
        if drive is not None:
            for n, w in sol.omega.items():
                if n != drive and abs(w) > EXACT_ZERO_REL * abs(sol.omega[drive]):
                    out[f"{drive}-{n}"] = sol.omega[drive] / w
    return out


def _check_name(name: str, lang: str) -> str:
    """A check's name as the table prints it (its JSON name in English)."""
    if lang == "en":
        return name
    from plans.phrases import say

    for key in ("no_undercut", "tip_thickness"):
        if name.startswith(key + "_"):
            return say("g_" + key, lang, n=name[len(key) + 1:])
    return say("g_" + name, lang)


def table(sol: GearSolution, lang: str = "en") -> str:
    """The course's table of results as text, in ``lang`` (decimal comma in Russian)."""
    from plans.phrases import UNITS_RU, say

    gf = sol.file
    k = gf.to_unit
    u = gf.unit if lang == "en" else UNITS_RU.get(gf.unit, gf.unit)
    lines = []
    for p in sol.pairs:
        a, b = p.gears
        lines.append(say("g_pair", lang, a=a, b=b, kind=say("g_internal" if p.internal else "g_external", lang),
                         x1=p.wheels[0].x, x2=p.wheels[1].x))
        lines.append(say("g_centre", lang, aw=math.degrees(p.alpha_w), a=p.a * k, a_w=p.a_w * k, u=u, y=p.y,
                         dy=p.delta_y))
        for w in p.wheels:
            lines.append(say("g_wheel", lang, n=w.name, r=w.pitch * k, rb=w.base * k, ra=w.tip * k, rf=w.root * k,
                             al=math.degrees(w.tip_angle), s=w.thickness * k, sa=w.tip_thickness * k, u=u))
        if p.internal:
            rule = gf.gears[b].ring_tip
            lines.append(say("g_ring", lang, b=b, rule=repr(rule) if lang == "en" else say("g_rule_" + rule, lang)))
        lines.append(say("g_checks", lang, e=p.contact_ratio, checks=", ".join(
            say("g_check", lang, n=_check_name(n, lang), v=say("g_ok" if v else "g_fails", lang))
            for n, v in p.checks().items())))
    for n, v in ratios(sol).items():
        lines.append(say("g_ratio", lang, n=n, v=v))
    if sol.omega is not None and sol.plan is not None:
        for n, om in sol.omega.items():
            lines.append(say("g_speed", lang, n=n, w=om * 30 / math.pi, p=sol.plan.lines[n].omega * 30 / math.pi))
    if sol.synthesis is not None:
        t = sol.synthesis
        lines.append(say("g_synthesis", lang, z1=t.z1, z2=t.z2, z3=t.z3, k=t.planets, i=t.ratio))
    return "\n".join(lines)
