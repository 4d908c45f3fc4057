"""A lesson: everything a demonstration shows of one scene, as plain data.

- the construction of one position, step by step in the textbook's order (velocity plan,
  acceleration plan, each group's force polygon with its moment equations, the crank,
  the lever), each step naming what it draws and what it highlights on the scheme;
- the cycle: the scheme and the plans at ``frames`` equally spaced crank angles, from the
  exact analysis (the page only interpolates, it solves nothing);
- the classic mistakes and how far each one moves the result (:mod:`plans.demo.mistakes`).

Coordinates are millimetres on the page (scheme at μl, plans at their μ), y up.
"""

from __future__ import annotations

import math
from typing import TYPE_CHECKING, Any

import numpy as np

from plans.demo.mistakes import mistakes, page_mm, page_tol, page_xy
from plans.errors import Figures, InputError, PlansError, Said
from plans.kinematics.exact import Kinematics, solve
from plans.kinematics.plan import Plan, Step
from plans.kinematics.scales import ratio_scale
from plans.language import symbols
from plans.phrases import LANGUAGES
from plans.results import Solution, solve_scene
from plans.scene.model import Scene
from plans.tolerances import SAME_ANGLE_DEG
from plans.units import clean

if TYPE_CHECKING:  # the force rooms are loaded only for a scene with forces
    from plans.forces.lever import LeverAnalysis
    from plans.forces.polygons import ForceAnalysis
    from plans.forces.protocol import Arm

#: How many crank positions the cycle of a page holds by default (every 5°).
FRAMES = 72
#: Largest number of frames a page may hold (the page stays small and quick to open).
MAX_FRAMES = 720


def _nice_length_scale(extent_m: float, target_mm: float = 120.0) -> float:
    """μl (mm per m) from the standard ratios, the largest that keeps the scheme within target."""
    if extent_m <= 0:
        return 1000.0
    got = ratio_scale(extent_m, target_mm)
    if got is not None:
        return got
    k = math.floor(math.log10(target_mm / (extent_m * 1000.0)))
    return 1000.0 * 10.0**k


# --------------------------------------------------------------------------- the scheme


def _scheme(scene: Scene, kin: Kinematics, mu_l: float) -> dict[str, Any]:
    """The mechanism's drawing over the frames: joints, links as bars, sliders, guides."""
    names = kin.point_names()
    points = {nm: [page_xy(z * mu_l) for z in kin.point(nm)[0]] for nm in names}
    links = []
    for lid in sorted(scene.links):
        link = scene.links[lid]
        pts = [p for p in link.points if p in points]
        links.append({"id": lid, "name": link.name, "points": pts, "axis": [p for p in link.axis if p in points]})
    sliders = []
    guides = []
    for jt in scene.joints:
        if jt.kind != "P" or jt.guide is None:
            continue
        g = jt.guide
        if g.link == scene.frame:
            ang = np.full(kin.n, g.angle)
        else:
            ang = kin.theta(g.link) + g.angle
        sliders.append({"point": jt.point, "link": jt.slider,
                        "angle_deg": [page_mm(math.degrees(a)) for a in ang]})
        if g.link == scene.frame:
            pin = kin.point(jt.point)[0]
            d = complex(math.cos(g.angle), math.sin(g.angle))
            s = ((pin - g.origin) * d.conjugate()).real
            lo, hi = float(np.min(s)), float(np.max(s))
            pad = 0.15 * (hi - lo) + 0.02 * (abs(lo) + abs(hi)) + 1e-9
            a, b = g.origin + (lo - pad) * d, g.origin + (hi + pad) * d
            guides.append({"from": page_xy(a * mu_l), "to": page_xy(b * mu_l), "point": jt.point})
    # The frame's pivots: a frame point on no link (a guide's "through" point, G of a press's
    # ram) is no pivot and has no track; its guide is drawn, it gets no ground mark.
    pivots = sorted(nm for nm in scene.frame_points if nm in points)
    return {"mu_l": mu_l, "points": points, "frame_points": pivots,
            "links": links, "sliders": sliders, "guides": guides, "frame": scene.frame}


def _plan_images(kin: Kinematics, names: list[str], order: int, mu: float) -> dict[str, list[list[float]]]:
    """Images of the moving points on a plan (the frame's points sit on the pole)."""
    out = {}
    for nm in names:
        if nm in kin.scene.frame_points:
            continue
        z = kin.point(nm)[order]
        if z is None:
            continue
        out[nm.lower()] = [page_xy(w * mu) for w in z]
    return out


#: S farther than this many times its group's size from the group's pairs is not drawn on the
#: scheme (the axes nearly parallel would shrink the mechanism to a dot); the sheets' rule.
ASSUR_REACH = 2.5


def _assur_points(kin: Kinematics, k: int, mu_l: float) -> list[dict[str, Any]]:
    """Assur's special point S of each class-III group at position k, as the sheets mark it:
    its name, where it is on the page, and the two leashes' axes from the outer pairs extended
    to S (or the leash itself where S lies on it); a point too far to draw is left out."""
    from plans.kinematics.triad_plans import PAIRS, special_point_of

    triads = kin.structure.triads()
    out = []
    for n, g in enumerate(triads):
        S_all, choice, Qs, Ps = special_point_of(kin, g)
        S = complex(S_all[k])
        Q = [complex(x[k]) for x in Qs]
        P = [complex(x[k]) for x in Ps]
        centre = sum(Q + P) / 6
        extent = max(abs(z - centre) for z in Q + P)
        if not math.isfinite(S.real + S.imag) or abs(S - centre) > ASSUR_REACH * extent:
            continue
        axes = [(Q[x], S if abs(S - Q[x]) >= abs(P[x] - Q[x]) else P[x]) for x in PAIRS[int(choice[k])]]
        out.append({"name": "S" if len(triads) == 1 else "S" + "′" * n, "xy": page_xy(S * mu_l),
                    "axes": [{"from": page_xy(a * mu_l), "to": page_xy(b * mu_l)} for a, b in axes]})
    return out


# --------------------------------------------------------------------------- steps


def _panel(pid: str, title: str, plan: Plan, unit: str) -> dict[str, Any]:
    return {
        "id": pid, "title": title, "kind": plan.kind, "scale": plan.scale, "unit": unit, "pole": plan.pole,
        "points": {p.name: page_xy(complex(*p.xy)) for p in plan.points},
        "segments": [{"from": s.start, "to": s.end, "kind": s.kind, "label": s.label} for s in plan.segments],
        "lines": [{"point": page_xy(complex(*ln.point)), "dir": [round(ln.direction[0], 9) + 0.0, round(ln.direction[1], 9) + 0.0],
                   "label": ln.label} for ln in plan.lines],
    }


def _on_line(xy: tuple[float, float], ln: dict[str, Any], tol: float) -> bool:
    px, py = ln["point"]
    dx, dy = ln["dir"]
    return abs((xy[0] - px) * dy - (xy[1] - py) * dx) <= tol


def _reveal(panel: dict[str, Any], steps: list[Step]) -> list[dict[str, Any]]:
    """Which points, segments and construction lines each step of a plan draws.

    A point appears with the step that makes it; a segment when both its ends are there
    (a closing vector only with the step that names it); a construction line with the
    first step whose new point lies on it."""
    pts = panel["points"]
    closing = {s.output for s in steps if s.op == "closing"}
    shown: set[str] = {panel["pole"]}
    seg_done: set[int] = set()
    line_done: set[int] = set()
    tol = page_tol(max([1.0] + [math.hypot(*xy) for xy in pts.values()]))
    out: list[dict[str, list]] = []
    for s in steps:
        new_pts: list[str] = []
        for nm in (*s.inputs, s.output):  # the lever's forces start at images no step made
            if nm in pts and nm not in shown and nm not in new_pts:
                new_pts.append(nm)
        shown.update(new_pts)
        named = s.output if s.op == "closing" else None
        segs = []
        for k, sg in enumerate(panel["segments"]):
            if k in seg_done or sg["from"] not in shown or sg["to"] not in shown:
                continue
            if sg["label"] in closing and sg["label"] != named and s.op != "intersect":
                continue
            segs.append(k)
        seg_done.update(segs)
        lines = []
        if s.output in pts:
            for k, ln in enumerate(panel["lines"]):
                at_anchor = math.hypot(pts[s.output][0] - ln["point"][0], pts[s.output][1] - ln["point"][1]) <= tol
                if k not in line_done and not at_anchor and _on_line(tuple(pts[s.output]), ln, tol):
                    lines.append(k)
        line_done.update(lines)
        out.append({"points": new_pts, "segments": segs, "lines": lines})
    if out:  # anything a step did not claim is drawn with the last one
        out[-1]["segments"] += [k for k in range(len(panel["segments"])) if k not in seg_done]
        out[-1]["lines"] += [k for k in range(len(panel["lines"])) if k not in line_done]
    return out


def _scheme_marks(scene: Scene, step: Step, plan: str, assur: tuple[str, ...] = ()) -> list[str]:
    """Scheme points a step is about: the plan's lower-case images name them (Assur's point S
    of a class-III group by its image s on the velocity and acceleration plans)."""
    names = {nm.lower(): nm for lid in scene.links for nm in scene.links[lid].points}
    names.update({nm.lower(): nm for nm in scene.frame_points})
    if plan in ("velocity", "acceleration"):
        names.update({nm.lower(): nm for nm in assur if nm.lower() not in names})
    out = []
    for word in (step.output, *step.inputs):
        if word in names and names[word] not in out:
            out.append(names[word])
    return out


def _group_links(label: str) -> list[int]:
    """Links of a drawing named "group 2-3" or "crank" (the scheme highlights them)."""
    if label.startswith("group "):
        return [int(x) for x in label[6:].split("-") if x.isdigit()]
    return []


#: An arm shorter than this on the page's scheme (mm) is not drawn: the force passes through
#: the point, up to what a pencil can show.
ARM_MM = 0.5


def _arms(arms: tuple[Arm, ...], mu_l: float) -> list[dict[str, Any]]:
    """A moment equation's arms on the page's scheme (mm): the perpendicular from the point
    the moments are taken about to each known force's line."""
    return [{"label": a.label, "about": page_xy(a.about * mu_l), "foot": page_xy(a.foot * mu_l),
             "at": page_xy(a.at * mu_l)} for a in arms if abs(a.foot - a.about) * mu_l >= ARM_MM]


def _steps(sol: Solution, k: int, lang: str, mu_l: float, assur: tuple[str, ...] = ()) -> tuple[list[dict], list[dict]]:
    scene = sol.scene
    panels: list[dict] = []
    steps: list[dict] = []
    pp = sol.plans[k] if sol.plans else None

    def add(panel: dict, plan_steps: list[Step], links: list[int] | None = None,
            arms: list[tuple[Arm, ...]] | None = None):
        panel["found"] = [s.output for s in plan_steps if s.op == "intersect" and s.output in panel["points"]]
        panels.append(panel)
        reveal = _reveal(panel, plan_steps) if panel is not None else []
        for n, s in enumerate(plan_steps):
            steps.append({"panel": panel["id"], "text": symbols(s.say(lang), lang) if lang == "ru" else s.say(lang),
                          "op": s.op, **reveal[n],
                          "scheme": _scheme_marks(scene, s, panel["kind"], assur), "links": links or []})
            if arms and arms[n]:
                steps[-1]["arms"] = _arms(arms[n], mu_l)

    if pp is not None and pp.velocity is not None:
        add(_panel("velocity", "velocity plan", pp.velocity, "mm/(m/s)"), list(pp.velocity.steps))
    if pp is not None and pp.acceleration is not None:
        add(_panel("acceleration", "acceleration plan", pp.acceleration, "mm/(m/s²)"), list(pp.acceleration.steps))
    if sol.forces is not None:
        from plans.forces.lever import lever_plan
        from plans.forces.polygons import force_polygons
        from plans.forces.protocol import force_steps

        fa, lv = sol.forces
        polys = {("crank" if p.kind == "crank" else f"group {p.group}"): p for p in force_polygons(fa, k)}
        fsteps = force_steps(fa, lv, k)
        by_plan: dict[str, list[Step]] = {}
        arms: dict[str, list[tuple[Arm, ...]]] = {}
        for f in fsteps:
            by_plan.setdefault(f.plan, []).append(f.step)
            arms.setdefault(f.plan, []).append(f.arms)
        for name, st in by_plan.items():
            if name == "lever":
                plan = lever_plan(lv, k)
                panel = _panel("lever", "Zhukovsky lever", plan, "mm/(m/s)")
            else:
                plan = polys[name].plan
                panel = _panel(name.replace(" ", "-"), f"force polygon, {name}", plan, "mm/N")
            links = _group_links(name) or ([scene.driver.link] if name == "crank" else [])
            add(panel, st, links, arms[name])
    return panels, steps


# --------------------------------------------------------------------------- the lesson


def _position_index(sol: Solution, phi_deg: float | None) -> int:
    phis = [float(x) for x in sol.kinematics.phi_deg]
    if phi_deg is None:
        return 0
    for k, p in enumerate(phis):
        if abs(p - phi_deg) < SAME_ANGLE_DEG:
            return k
    raise InputError(Said("dl_crank_angle_phi", phi_deg=phi_deg, shown=Said("dl_shown", phis=Figures(phis[:8]), n=len(phis))
                          if len(phis) > 8 else Said("dl_shown_all", phis=Figures(phis))), file=sol.scene.path,
                     field="--phi")


def lesson(scene: Scene, *, phi_deg: float | None = None, frames: int = FRAMES,
           language: str = "en") -> dict[str, Any]:
    """The lesson of a scene (a JSON-able dict): steps at one position, the cycle, mistakes;
    every sentence in ``language`` ("en" or "ru")."""
    if not (isinstance(frames, int) and 2 <= frames <= MAX_FRAMES):
        raise InputError(Said("dl_whole_number_frames", MAX_FRAMES=MAX_FRAMES, frames=frames),
                         field="--frames")
    if language not in LANGUAGES:
        raise InputError(Said("dl_one_language", v=', '.join(LANGUAGES), language=language), field="--language")
    sol = solve_scene(scene)
    k = _position_index(sol, phi_deg)
    phis = np.arange(frames) * (360.0 / frames)
    order = 2 if scene.wants("acceleration_plan") else 1 if scene.wants("velocity_plan") else 0
    cyc = solve(scene, phis, order=order, structure=sol.structure)
    extent = max(abs(z) for nm in cyc.point_names() for z in cyc.point(nm)[0])
    mu_l = scene.scales.get("length") or _nice_length_scale(2.0 * float(extent))
    names = cyc.point_names()
    cycle: dict[str, Any] = {"phi_deg": [page_mm(p) for p in phis], "scheme": _scheme(scene, cyc, mu_l)}
    if order >= 1:
        vmax = max(float(np.max(np.abs(cyc.point(nm)[1]))) for nm in names)
        cycle["mu_v"] = _nice_length_scale(vmax / 1000.0, 60.0) / 1000.0 if vmax > 0 else 1.0
        cycle["velocity"] = _plan_images(cyc, names, 1, cycle["mu_v"])
    if order >= 2:
        amax = max(float(np.max(np.abs(cyc.point(nm)[2]))) for nm in names)
        cycle["mu_a"] = _nice_length_scale(amax / 1000.0, 60.0) / 1000.0 if amax > 0 else 1.0
        cycle["acceleration"] = _plan_images(cyc, names, 2, cycle["mu_a"])
    forces = _cycle_force_analysis(scene, phis, cycle.get("mu_v")) if sol.forces is not None else None
    charts = [] if forces is None else [_balancing_chart(phis, forces[0])]
    cycle["charts"] = charts + _cycle_charts(scene)
    if forces is not None:
        from plans.demo.cycle_forces import cycle_forces

        cycle["forces"] = cycle_forces(*forces)
    at = solve(scene, [float(sol.kinematics.phi_deg[k])], order=order, structure=sol.structure)
    scheme = _scheme(scene, at, mu_l)
    scheme["guides"] = cycle["scheme"]["guides"]  # a guide is drawn over the whole stroke
    # a class-III group's Assur point S on the step-by-step scheme, its leashes' axes extended
    # to it thin and dashed as a guide is (the plans' first point s is its image)
    assur = [s for s in _assur_points(at, 0, mu_l) if s["name"] not in scheme["points"]]
    for s in assur:
        scheme["points"][s["name"]] = [s["xy"]]
        scheme["guides"] = scheme["guides"] + [{**ax, "point": s["name"]} for ax in s["axes"]]
    panels, steps = _steps(sol, k, language, mu_l, tuple(s["name"] for s in assur))
    return {
        "title": scene.title_in(language) if language == "ru" else scene.title,
        "phi_deg": float(sol.kinematics.phi_deg[k]),
        "scheme": scheme,
        "panels": panels,
        "steps": steps,
        "cycle": cycle,
        "mistakes": mistakes(sol, k, panels, language),
        "links": {str(lid): scene.links[lid].name for lid in scene.links},
    }


#: Most samples of one curve on the page (a smooth curve at the page's size).
CHART_SAMPLES = 361


def _chart(label: str, unit: str, phi_deg: Any, values: Any, nodes: tuple[Any, Any] | None = None) -> dict:
    """A curve over the crank angle for the page's cursor: exact values, and where a
    graphical method drew it, its values at the nodes."""
    phi = np.asarray(phi_deg, float)
    y = np.asarray(values, float)
    step = max(1, int(np.ceil(len(phi) / CHART_SAMPLES)))
    keep = np.unique(np.append(np.arange(0, len(phi), step), len(phi) - 1))
    size = float(np.max(np.abs(y))) if y.size else 0.0  # round-off against the curve's size reads 0

    def value(v: float) -> float:
        return float(f"{clean(float(v), size):.6g}") + 0.0

    out: dict[str, Any] = {"label": label, "unit": unit, "phi_deg": [page_mm(x) for x in phi[keep]],
                           "values": [value(v) for v in y[keep]]}
    if nodes is not None:
        out["nodes_deg"] = [page_mm(x) for x in np.asarray(nodes[0], float)]
        out["nodes"] = [value(v) for v in np.asarray(nodes[1], float)]
    return out


def _cycle_force_analysis(scene: Scene, phis: np.ndarray, mu_v: float | None
                          ) -> tuple[ForceAnalysis, LeverAnalysis] | None:
    """The force analysis and the lever (at the cycle's μv) over the frames; None where the
    turn passes a position the force analysis cannot take (a locked group)."""
    from plans.forces.lever import zhukovsky_lever
    from plans.forces.polygons import analyse_forces

    try:
        fa = analyse_forces(scene, solve(scene, phis, order=2))
        return fa, zhukovsky_lever(fa, scale=mu_v)
    except PlansError:
        return None


def _balancing_chart(phis: np.ndarray, fa: ForceAnalysis) -> dict[str, Any]:
    """F_bal(φ) over the cycle, exact."""
    kind = fa.crank.kind
    closed = np.append(phis, phis[0] + 360.0), np.append(fa.balancing, fa.balancing[0])  # the turn closes
    return _chart("F_bal" if kind == "force" else "M_bal", "N" if kind == "force" else "N·m", *closed)


def _cycle_charts(scene: Scene) -> list[dict[str, Any]]:
    """The kinematic diagrams (exact curve, graphical values at the nodes) and the dynamics
    (M_pr, I_pr, ΔT, ω) of a scene that asks for them."""
    out: list[dict[str, Any]] = []
    if scene.wants("diagrams"):
        from plans.cycle.diagrams import diagrams

        for d in diagrams(scene).diagrams:
            out.append(_chart(d.name, d.unit, d.exact_phi_deg, d.exact, (d.phi_deg, d.values)))
    if scene.wants("dynamics"):
        from plans.cycle.dynamics import dynamics

        dyn = dynamics(scene)
        ex, tab = dyn.exact, dyn.table
        out.append(_chart("M_pr", "N·m", ex.phi_deg, ex.M_pr, (tab.phi_deg, tab.M_pr)))
        out.append(_chart("I_pr", "kg·m²", ex.phi_deg, ex.I_pr, (tab.phi_deg, tab.I_pr)))
        out.append(_chart("ΔT", "J", ex.phi_deg, dyn.dT_exact, (tab.phi_deg, dyn.dT)))
        out.append(_chart("ω1", "rad/s", ex.phi_deg, dyn.omega))
    return out


__all__ = ["FRAMES", "MAX_FRAMES", "lesson"]
