"""The solved scene as data (JSON) and as readable tables.

JSON contract (docs/guide/json.md documents it): ``positions[i].phi_deg``;
``positions[i].points[NAME]`` with ``r``, ``v``, ``a`` as ``[x, y]`` in SI;
``positions[i].links["N"]`` with ``theta``, ``omega``, ``eps`` (rad, rad/s,
rad/s², counter-clockwise positive); ``positions[i].plans.velocity`` /
``.acceleration`` with ``scale`` (mm per SI unit) and labelled ``points`` in
plan mm; ``positions[i].readings`` (value read off the plan next to the exact
value).  Keys appear only for what the scene asked for.
"""

from __future__ import annotations

from collections.abc import Callable, Iterator
from typing import TYPE_CHECKING, Any

import plans.kinematics.construction  # noqa: F401  (the solve's own modules, loaded with the command:
import plans.kinematics.exact  # noqa: F401  what ``plans bench`` times as the start of ``plans solve``)
from plans.scene.model import Scene

if TYPE_CHECKING:
    from plans.solution import Solution
from plans.tolerances import ILL_CONDITIONED


def __getattr__(name: str) -> Any:
    """``from plans.results import Solution`` as before (loaded when asked for: the start of
    ``plans solve`` does not pay for it)."""
    if name == "Solution":
        from plans.solution import Solution

        return Solution
    raise AttributeError(f"module {__name__!r} has no attribute {name!r}")


def solve_scene(scene: Scene) -> Solution:
    """Everything the scene asks for, computed now (``plans solve``); a construction that has
    no answer names the file.  :func:`plans.solve` computes each part when it is first read."""
    from plans.solution import Solution

    return Solution(scene).solve_all()


def _xy(z: complex) -> list[float]:
    return [float(z.real), float(z.imag)]


def to_json(sol: Solution, steps: bool = True, lang: str = "en") -> dict[str, Any]:
    """The whole result as one dict (``plans solve --json``); :func:`write_json` writes the
    same text position by position.  ``steps=False`` leaves out the construction protocol's
    text (most of the time taken), for a page that draws the plans and reads no protocol.
    Its keys are the program's; its sentences (the steps, the tables' titles) in ``lang``."""
    out = head_json(sol, lang)
    out["positions"] = list(_positions(sol, steps, lang))
    return out


#: Stands for the positions in the head of the JSON while it is written in pieces.
_POSITIONS = "\x00positions"


def head_json(sol: Solution, lang: str = "en") -> dict[str, Any]:
    scene = sol.scene
    from plans.language import TERMS

    out: dict[str, Any] = {
        "title": scene.title if lang == "en" else scene.title_in(lang),
        "scene": scene.path,
        "units": {"length": "m", "velocity": "m/s", "acceleration": "m/s^2", "force": "N",
                  "plan": "mm", "angles": TERMS["t_json_angles"][lang == "ru"]},
        "fij": scene.fij,
        "outputs": sorted(scene.outputs),
        "structure": sol.structure.to_json(),
        "positions": _POSITIONS,
    }
    if scene.driver.start:  # the positions from the output's extreme: where, and the strokes
        out["phi_start"] = scene.driver.strokes.to_json(scene.driver.start)
    if sol.cycle is not None:
        from plans.cycle.results import cycle_json

        out.update(cycle_json(sol.cycle, lang))
    if sol.efficiency is not None:
        out["efficiency"] = sol.efficiency
    return out


def _positions(sol: Solution, steps: bool = True, lang: str = "en") -> Iterator[dict[str, Any]]:
    forces: list[dict] | None = None
    if sol.forces is not None:
        from plans.forces.lever import force_json

        forces = force_json(sol.forces[1])
    for k in range(sol.kinematics.n):
        yield position_json(sol, k, None if forces is None else forces[k], steps, lang)


def position_json(sol: Solution, k: int, forces: dict | None, steps: bool = True, lang: str = "en") -> dict[str, Any]:
    kin, scene = sol.kinematics, sol.scene
    pos: dict[str, Any] = {"phi_deg": float(kin.phi_deg[k]), "points": {}, "links": {}}
    for nm in kin.point_names():
        r, v, a = kin.point(nm)
        entry = {"r": _xy(r[k])}
        if v is not None:
            entry["v"] = _xy(v[k])
        if a is not None:
            entry["a"] = _xy(a[k])
        pos["points"][nm] = entry
    for lid in sorted(scene.links):
        m = kin.motion[lid]
        le: dict[str, float] = {"theta": float(m.theta[k])}
        if m.omega is not None:
            le["omega"] = float(m.omega[k])
        if m.eps is not None:
            le["eps"] = float(m.eps[k])
        pos["links"][str(lid)] = le
    if kin.conditions:
        pos["conditioning"] = {g: float(c[k]) for g, c in kin.conditions.items()}
    if kin.structure.triads():  # class III: Assur's special point of each group
        from plans.kinematics.triad_plans import assur_points_json

        pos["assur_points"] = assur_points_json(kin, k)
    if sol.plans:
        pp = sol.plans[k]
        pos["plans"] = {}
        if pp.velocity is not None:
            pos["plans"]["velocity"] = pp.velocity.to_json()
        if pp.acceleration is not None:
            pos["plans"]["acceleration"] = pp.acceleration.to_json()
        pos["readings"] = [r.to_json() for r in pp.readings]
    if scene.wants("instant_centres"):
        from plans.kinematics.centres import centres_json

        pos.update(centres_json(kin, k, sol.plans[k].readings if sol.plans else ()))
    if forces is not None:
        pos.update(forces)
    if steps and (sol.plans or sol.forces is not None):
        from plans.forces.protocol import force_steps, steps_json

        plans = (sol.plans[k].velocity, sol.plans[k].acceleration) if sol.plans else ()
        drawn = force_steps(sol.forces[0], sol.forces[1], k) if sol.forces is not None else ()
        pos["steps"] = steps_json(plans, drawn, lang)
    return pos


def write_json(sol: Solution, write: Callable[[str], object], lang: str = "en") -> None:
    """Write ``dumps(to_json(sol))`` in pieces, one position at a time: the text is the same
    to the byte, and memory holds one position's JSON, not the whole run's (3600 positions
    of a V-engine are over 100 MB of text)."""
    import json

    from plans.io import dumps

    before, after = dumps(head_json(sol, lang)).split(json.dumps(_POSITIONS))
    write(before)
    opening = "[\n    "
    for pos in _positions(sol, lang=lang):
        write(opening + dumps(pos)[:-1].replace("\n", "\n    "))  # nested two levels deep
        opening = ",\n    "
    write("[]" if opening == "[\n    " else "\n  ]")
    write(after)


def _fmt(x: float | None, width: int = 12) -> str:
    if x is None:
        return " " * (width - 1) + "-"
    return f"{x:{width}.6g}"


def table(sol: Solution, protocol: bool = False, lang: str = "en") -> str:
    """Per position: quantity, segment on the plan (mm), value read, exact value, difference;
    in ``lang`` (a decimal comma and the textbook's symbols in Russian)."""
    from plans.language import symbols
    from plans.phrases import number, say

    ru = lang == "ru"

    def num(x: float, spec: str) -> str:
        return number(x, spec, lang) if ru else format(x, spec)

    kin, scene = sol.kinematics, sol.scene
    title = scene.titles.get(lang, scene.title) if ru else scene.title
    lines = [title, symbols(sol.structure.formula(), lang), ""]
    if scene.driver.start:
        from plans.kinematics.extreme import start_line

        lines[-1:-1] = [start_line(scene, lang)]
    for k in range(kin.n):
        lines.append(say("t_position", lang, phi=float(kin.phi_deg[k])))
        if not sol.plans:
            for nm in kin.point_names():
                r = kin.point(nm)[0][k]
                lines.append(say("t_point", lang, nm=f"{nm:6s}", x=r.real, y=r.imag))
            lines.append("")
            continue
        pp = sol.plans[k]
        for g, c in kin.conditions.items():
            if c[k] > ILL_CONDITIONED:
                lines.append(say("t_ill", lang, g=g, c=float(c[k]), a=float(1 / c[k])))
        for plan in (pp.velocity, pp.acceleration):
            if plan is None:
                continue
            unit = "mm/(m/s)" if plan.kind == "velocity" else "mm/(m/s^2)"
            sc = _scale_phrase(scene.scale_style, plan.scale, unit, lang)
            lines.append(symbols(say("t_plan", lang, kind=say("t_" + plan.kind, lang) if ru else plan.kind,
                                     sc=sc), lang))
            if plan.degenerate:
                lines += [symbols(say("t_note", lang, d=d), lang) for d in plan.degenerate]
        w = {key: say("w_" + key, lang) for key in ("quantity", "segment", "mm", "read", "exact", "difference",
                                                     "unit")}
        lines.append(f"  {w['quantity']:14s} {w['segment']:>10s} {w['mm']:>10s} "
                     f"{w['read']:>12s} {w['exact']:>12s} {w['difference']:>12s}  {w['unit']}")
        for r in pp.readings:
            seg = r.segment or ""
            mm = f"{num(r.length_mm, '10.3f')}" if r.length_mm is not None else " " * 9 + "-"
            if ru:
                q, seg, u = symbols(r.quantity, lang), symbols(seg, lang), symbols(r.unit, lang)
                lines.append(f"  {q:14s} {seg:>10s} {mm} {_fmt(r.value)} {_fmt(r.exact)} "
                             f"{r.difference:12.2e}  {u}".replace(".", ","))
            else:
                lines.append(f"  {r.quantity:14s} {seg:>10s} {mm} {_fmt(r.value)} {_fmt(r.exact)} "
                             f"{r.difference:12.2e}  {r.unit}")
        if sol.forces is not None:
            from plans.forces import lever as _lever

            if hasattr(_lever, "table_lines"):
                lines += _lever.table_lines(sol.forces[0], sol.forces[1], k, lang)
        if protocol:
            for plan in (pp.velocity, pp.acceleration):
                if plan is not None:
                    lines.append(say("t_construction", lang, kind=say("t_" + plan.kind, lang) if ru else plan.kind))
                    lines += ["   " + symbols(s, lang) for s in plan.protocol(lang).splitlines()]
            if sol.forces is not None:
                from plans.forces import protocol as _protocol

                fa, lv = sol.forces
                lines += [symbols(s, lang) for s in
                          _protocol.protocol_lines(_protocol.force_steps(fa, lv, k), lang)]
        lines.append("")
    if sol.cycle is not None:
        from plans.cycle.results import cycle_text

        lines.append(cycle_text(sol.cycle, lang))
    if sol.forces is not None and sol.forces[0].friction is not None:
        from plans.forces.friction import cycle_line

        line = cycle_line(sol.forces[0], lang)
        if line:
            lines.append(line)
    text = "\n".join(lines)
    if not scene.scale_style.endswith(("|", "mu", "K")):  # the acceleration pole as the scene names it
        text = _pole_named(text, scene.scale_style, lang)
    return text


def _pole_named(text: str, style: str, lang: str) -> str:
    """The protocol with the acceleration pole written as ``[sheet] acceleration_pole`` says (the
    solve's protocol writes no other π)."""
    import re

    from plans.scene.notation import resolve

    pole = resolve(style, lang)[2]
    if lang == "ru":
        return text.replace("π", pole) if pole != "π" else text
    return re.sub(r"\bp_a(?![A-Z_])", pole, text) if pole != "p_a" else text


def _scale_phrase(style: str, mu: float, unit: str, lang: str) -> str:
    """A plan's scale in the protocol: the scene's letter and direction (plans.scene.notation)."""
    from plans.phrases import say  # the old "mu" and "K" as they always were

    per = unit.split('/', 1)[1].strip('()')
    if style == "mu":
        return say("t_mu", lang, mu=mu, unit=unit)
    if style == "K":
        return say("t_k", lang, k=1 / mu, unit=per)
    from plans.scene.notation import resolve

    letter, per_mm, _ = resolve(style, lang)
    if not per_mm:
        return say("t_mu", lang, mu=mu, unit=unit)
    return say("t_k" if letter == "K" else "x_mu_per_mm", lang, k=1 / mu, unit=f"({per})")


def load_and_solve(path: str) -> Solution:
    from plans.kinematics.placing import load_scene

    return solve_scene(load_scene(path))
