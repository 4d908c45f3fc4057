"""Classic mistakes of a hand-drawn sheet, made on purpose, and how far they move the result.

Each mistake is redone the way the student would make it: the wrong construction line is
laid off and intersected again (Coriolis vector reversed, the normal component laid off
from the pole instead of from its point), the inertia couple is put on the lever with the
wrong sign, or the whole analysis is rerun with π = 3.14 in ω1 = πn/30.  The result is the
wrong point on the plan and the numbers a checked sheet would show.
"""

from __future__ import annotations

import math
from dataclasses import replace
from typing import Any

from plans.kinematics.exact import solve
from plans.lines import cross, meet
from plans.phrases import Phrase, phrase
from plans.results import Solution
from plans.tolerances import AGREE_REL, LOCK_SIN


def page_mm(x: float) -> float:
    """Page coordinates to 1 µm: small pages, and no −0.0 or round-off dust."""
    return round(float(x), 3) + 0.0


def page_xy(z: complex) -> list[float]:
    return [page_mm(z.real), page_mm(z.imag)]


def _meet(p1: complex, d1: complex, p2: complex, d2: complex) -> complex | None:
    """Intersection of two lines (point, direction); None when they are parallel."""
    den = cross(d1, d2)
    if abs(den) < LOCK_SIN * abs(d1) * abs(d2):
        return None
    return meet(p1, d1, p2, d2, den)


def _pct(wrong: float, right: float) -> Phrase:
    if right == 0:
        return phrase("x_diff", d=wrong - right)
    return phrase("x_pct", p=100.0 * (wrong - right) / abs(right))


def _panel(panels: list[dict], pid: str) -> dict | None:
    return next((p for p in panels if p["id"] == pid), None)


def _relay(panel: dict, anchor: str, shift: complex) -> tuple[str, complex, complex] | None:
    """Lay off again the construction line drawn from ``anchor`` shifted by ``shift``;
    the point it found (the one it meets its partner line at) moves: (name, right, wrong)."""
    pts = {nm: complex(*xy) for nm, xy in panel["points"].items()}
    a = pts[anchor]
    size = max([1.0] + [abs(z) for z in pts.values()])
    tol = max(2e-3, 1e-6 * size)  # page coordinates are kept to 1 µm
    lines = [(complex(*ln["point"]), complex(*ln["dir"])) for ln in panel["lines"]]

    def on(z: complex, ln: tuple[complex, complex]) -> bool:
        p, d = ln
        return abs(((z - p).conjugate() * d).imag) <= tol

    mine = [ln for ln in lines if abs(ln[0] - a) <= tol]
    for ln in mine:
        for name in panel.get("found", ()):
            z = pts[name]
            if name == anchor or abs(z - a) <= tol or not on(z, ln):
                continue
            partners = [o for o in lines if o is not ln and on(z, o) and not on(a, o)]
            for p2, d2 in partners:
                hit = _meet(ln[0] + shift, ln[1], p2, d2)
                if hit is not None:
                    return name, z, hit
    return None


def _moved(pid: str, name: str, right: complex, wrong: complex, mu: float, unit: str, why: Phrase,
           lang: str) -> dict:
    words = phrase("x_moved", why=why, name=name, d=abs(wrong - right), w=abs(wrong) / mu, r=abs(right) / mu,
                   unit=unit, pct=_pct(abs(wrong), abs(right)))
    return {"panel": pid, "moved": {name: page_xy(wrong)}, "right": {name: page_xy(right)}, "text": words.say(lang)}


def _coriolis(panels: list[dict], lang: str) -> dict | None:
    acc = _panel(panels, "acceleration")
    if acc is None:
        return None
    for sg in acc["segments"]:
        if sg["kind"] != "coriolis":
            continue
        c = complex(*acc["points"][sg["to"]]) - complex(*acc["points"][sg["from"]])
        if abs(c) < 0.5:  # shorter than a pencil line here: reversing it shows nothing
            continue
        hit = _relay(acc, sg["to"], -2.0 * c)
        if hit is not None:
            out = _moved("acceleration", *hit, acc["scale"], "m/s²", phrase("x_coriolis", label=sg["label"]), lang)
            return {"id": "coriolis", "title": "Coriolis vector reversed", **out}
    return None


def _normal(panels: list[dict], lang: str) -> dict | None:
    acc = _panel(panels, "acceleration")
    if acc is None:
        return None
    pole = acc["pole"]
    for sg in acc["segments"]:
        if sg["kind"] != "normal" or sg["from"] == pole:
            continue
        shift = -complex(*acc["points"][sg["from"]])  # laid off from the pole instead of from its point
        hit = _relay(acc, sg["to"], shift)
        if hit is not None:
            out = _moved("acceleration", *hit, acc["scale"], "m/s²",
                         phrase("x_normal", label=sg["label"], pole=pole, frm=sg["from"]), lang)
            return {"id": "normal", "title": "normal component from the wrong point", **out}
    return None


def _couple(sol: Solution, k: int, lang: str) -> dict | None:
    if sol.forces is None:
        return None
    _, lv = sol.forces
    inertia = {m.label for m in lv.fa.applied.moments if m.kind == "inertia"}
    couples: dict[str, float] = {}
    for it in lv.forces:
        if it.label.rstrip("'") in inertia:
            base = it.label.rstrip("'")
            couples[base] = couples.get(base, 0.0) + float(it.moment[k])
    if not couples:
        return None
    label, m = max(couples.items(), key=lambda kv: abs(kv[1]))
    if not bool(lv.valid[k]) or float(lv.unit_moment[k]) == 0:
        return None
    right = float(lv.signed(lv.by_lever)[k])
    wrong = right + float(lv.fa.sense[k]) * 2.0 * m / float(lv.unit_moment[k])
    if abs(wrong - right) <= AGREE_REL * max(abs(right), 1.0):  # the couple vanishes here (ε = 0)
        return None
    unit = "N" if lv.fa.crank.kind == "force" else "N·m"
    return {"id": "couple", "title": "inertia couple with the wrong sign", "panel": "lever", "moved": {},
            "right": {}, "highlight": [label + "'", label + "''"],
            "values": {"quantity": "F_bal" if unit == "N" else "M_bal", "unit": unit, "right": right, "wrong": wrong},
            "text": phrase("x_couple", label=label, w=wrong, r=right, unit=unit, pct=_pct(wrong, right)).say(lang)}


def _pi(sol: Solution, k: int, panels: list[dict], lang: str) -> dict | None:
    scene = sol.scene
    if "omega_rpm" not in scene.raw.get("driver", {}):
        return None
    vel = _panel(panels, "velocity")
    if vel is None:
        return None
    ratio = 3.14 / math.pi
    d = scene.driver
    wrong_scene = replace(scene, driver=replace(d, omega=d.omega * ratio))
    phi = float(sol.kinematics.phi_deg[k])
    order = 2 if scene.wants("acceleration_plan") else 1
    kin = solve(wrong_scene, [phi], order=order, structure=sol.structure)
    moved = {}
    for nm in kin.point_names():
        img = nm.lower()
        if img in vel["points"]:
            v = complex(kin.point(nm)[1][0]) * vel["scale"]
            moved[img] = page_xy(v)
    crank_pin = scene.links[d.link].axis[1]
    vA = abs(d.omega) * abs(scene.links[d.link].points[crank_pin])
    text = phrase("x_pi", w=abs(d.omega) * ratio, r=abs(d.omega), A=crank_pin, vw=vA * ratio, vr=vA,
                  pct=_pct(ratio, 1.0), pct2=_pct(ratio**2, 1.0)).say(lang)
    if sol.forces is not None and order == 2:
        from plans.errors import PlansError
        from plans.forces.polygons import analyse_forces

        try:
            fa = analyse_forces(wrong_scene, kin)
        except PlansError:
            fa = None
        if fa is not None:
            f_right = float(sol.forces[0].balancing[k])
            f_wrong = float(fa.balancing[0])
            unit = "N" if fa.crank.kind == "force" else "N·m"
            text += phrase("x_pi_force", w=f_wrong, r=f_right, unit=unit, pct=_pct(f_wrong, f_right)).say(lang)
    right = {nm: vel["points"][nm] for nm in moved}
    return {"id": "pi", "title": "π = 3.14", "panel": "velocity", "moved": moved, "right": right, "text": text}


def mistakes(sol: Solution, k: int, panels: list[dict], lang: str = "en") -> list[dict[str, Any]]:
    """The classic mistakes that apply to this scene at position k, told in ``lang``."""
    out = [m for m in (_coriolis(panels, lang), _normal(panels, lang), _couple(sol, k, lang),
                       _pi(sol, k, panels, lang)) if m]
    return out


__all__ = ["mistakes"]
