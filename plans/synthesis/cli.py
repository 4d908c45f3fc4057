"""``plans design FILE [-o scene.toml] [--json PATH|-]``: size the mechanism of a synthesis
file, prove it, write the linkage scene."""

from __future__ import annotations

import argparse
import math
import sys
from typing import TYPE_CHECKING, Any

from plans.errors import Said

if TYPE_CHECKING:
    from .design import Design


def register(sub: argparse._SubParsersAction) -> None:
    p = sub.add_parser("design", help="design a mechanism from K, stroke, swing; prove it; write its scene")
    p.add_argument("task", help="synthesis file (TOML, kind = \"synthesis\")")
    p.add_argument("-o", "--output", metavar="SCENE", help="write the designed linkage scene (TOML) here")
    p.add_argument("--json", metavar="PATH", help="write the design as JSON ('-' for stdout)")
    from plans.language import add_option

    add_option(p)
    p.set_defaults(func=_run)


def _r(x: float, nd: int = 9) -> float:
    y = round(float(x), nd)
    return 0.0 if y == 0 else y


def _deg360(x: float, nd: int) -> float:
    """An angle in degrees, rounded, in [0, 360)."""
    y = _r(math.degrees(x) % 360.0, nd)
    return 0.0 if y >= 360.0 - 1e-5 else y  # a hair short of a full turn is 0°


def results(d: Design, scene: str, lang: str = "en") -> dict[str, Any]:
    """The JSON document (lengths in the file's unit, angles in degrees; keys that do not
    apply to the model are absent; its sentence, the choice made, in ``lang``)."""
    t = d.task
    u = t.scale
    m = d.measured[0]
    out: dict[str, Any] = {"mechanism": t.mechanism, "model": d.model, "unit": t.unit,
                           "lengths": {k: _r(v / u) for k, v in d.lengths.items()}}
    if d.model != "three_positions":
        out["theta_deg"] = _r(math.degrees(t.theta))
        out["K"] = _r(t.K, 12)
    out["K_measured"] = _r(m.K, 12)
    if m.stroke is not None:
        if d.model != "three_positions":
            from .design import stroke_of

            out["stroke"] = _r(stroke_of(t) / u)
        out["stroke_measured"] = _r(m.stroke / u)
    if m.swing is not None:
        given = t.swing if t.mechanism == "crank_rocker" else t.theta if t.mechanism == "coulisse" else None
        if given is not None and d.model != "three_positions":
            out["swing_deg"] = _r(math.degrees(given))
        out["swing_measured_deg"] = _r(math.degrees(m.swing))
    out["gamma_min_deg"] = _r(math.degrees(min(x.gamma_min for x in d.measured)))
    if t.mechanism != "crank_rocker":
        out["pressure_angle_max_deg"] = _r(90.0 - out["gamma_min_deg"])
    out["gamma_min_at_deg"] = _deg360(m.phi_gamma, 6)
    out["extremes_deg"] = [_deg360(x, 9) for x in (m.phi_start, m.phi_end)]
    out["full_rotation"] = all(x.full_rotation for x in d.measured)
    if t.mechanism == "crank_rocker":
        ls = sorted(d.lengths[k] for k in ("crank", "coupler", "rocker", "frame"))
        out["grashof"] = ls[0] + ls[3] < ls[1] + ls[2]
    if t.mechanism == "v_engine":
        out["cylinders"] = [{"stroke_measured": _r(x.stroke / u), "K_measured": _r(x.K, 12)}  # type: ignore[operator]
                            for x in d.measured]
    if d.model == "three_positions":
        from .numeric import wrap

        fb = d.mechs[0]
        assert t.positions is not None
        out["positions_error_deg"] = _r(max(abs(math.degrees(wrap(fb.psi(phi) - psi))) for phi, psi in t.positions),
                                        12)
    # the construction as drawn: its points and circle, in the scene's frame and the file's unit
    cons: dict[str, Any] = {"points": {k: [_r(z.real / u), _r(z.imag / u)] for k, z in d.points.items()}}
    if d.circle is not None:
        c, R = d.circle
        cons["circle"] = {"centre": [_r(c.real / u), _r(c.imag / u)], "radius": _r(R / u)}
    out["construction"] = cons
    if d.choice:
        from .design import choice_text

        out["choice"] = choice_text(d.choice, lang)
    out["scene"] = scene
    return out


def summary(d: Design, res: dict[str, Any], lang: str = "en") -> str:
    """The design on the terminal, in ``lang``."""
    from plans.phrases import PHRASES, UNITS_RU, say

    from .record import choice_text

    def word(key: str, default: str) -> str:
        return say(key, lang) if key in PHRASES else default

    t = d.task
    u = UNITS_RU.get(t.unit, t.unit) if lang == "ru" else t.unit
    kind = word(f"dm_{t.mechanism}", t.mechanism.replace("_", " "))
    if d.model in ("central", "offset", "three_positions"):
        kind += word("d_offset_model" if d.model == "offset" else f"d_{d.model}", f" ({d.model.replace('_', ' ')})")
    lines = [f"{t.title}: {kind}"]
    lines.append("  " + ", ".join(say("d_length", lang, k=word(f"d_{k}", k), v=v, u=u)
                                  for k, v in res["lengths"].items()))
    if "K" in res:
        lines.append(say("d_K", lang, K=res["K"], theta=res["theta_deg"], m=res["K_measured"]))
    else:
        lines.append(say("d_K_measured", lang, m=res["K_measured"]))
    if "stroke_measured" in res:
        given = say("d_given", lang, v=res["stroke"], u=u) if "stroke" in res else ""
        lines.append(say("d_stroke", lang, given=given, m=res["stroke_measured"], u=u))
    if "swing_measured_deg" in res:
        given = say("d_given_deg", lang, v=res["swing_deg"]) if "swing_deg" in res else ""
        lines.append(say("d_swing", lang, given=given, m=res["swing_measured_deg"]))
    line = say("d_gamma", lang, g=res["gamma_min_deg"], at=res["gamma_min_at_deg"])
    if "pressure_angle_max_deg" in res:
        line += say("d_pressure", lang, p=res["pressure_angle_max_deg"])
    lines.append(line)
    for i, c in enumerate(res.get("cylinders", [])):
        lines.append(say("d_cylinder", lang, c="BC"[i], s=c["stroke_measured"], u=u, k=c["K_measured"]))
    if "positions_error_deg" in res:
        lines.append(say("d_three", lang, e=res["positions_error_deg"]))
    lines.append(say("d_turns", lang) + (say("d_grashof", lang) if res.get("grashof") else ""))
    if d.choice:
        lines.append(say("d_chosen", lang, c=choice_text(d.choice, lang)))
    return "\n".join(lines)


def check_scene(text: str, task_path: str) -> None:
    """The written scene read back and solved as ``plans solve`` does: what [task] carried
    that a scene refuses is one line naming the task's key (nothing is written)."""
    from plans.errors import InputError
    from plans.io import loads_toml
    from plans.kinematics.placing import scene_from_dict
    from plans.results import solve_scene

    try:
        solve_scene(scene_from_dict(loads_toml(text, task_path), task_path))  # loads, dynamics too
    except InputError as exc:
        field = exc.field or ""
        if field.startswith("driver."):
            field = field.split(".", 1)[1]
        raise InputError(exc.said if exc.said is not None else exc.detail, file=task_path,
                         field=f"task.{field}" if field else "task") from None


def _run(args: argparse.Namespace) -> int:
    from pathlib import Path

    from plans.io import dumps, refuse_input, write_all

    from .scene import scene_text
    from .solution import solve_task

    refuse_input(args.output, args.task)
    refuse_input(args.json, args.task)
    if args.output and args.json and args.json != "-" and args.output == args.json:
        from plans.errors import OutputError

        raise OutputError(Said("sc_output_scene_json", output=args.output))
    from plans.language import file_language

    lang = file_language(getattr(args, "language", None), args.task)
    d = solve_task(args.task).design
    text = scene_text(d, lang)
    check_scene(text, args.task)
    res = results(d, args.output if args.output else text, lang)
    files: dict[Path, str] = {}
    if args.output:
        files[Path(args.output)] = text
    if args.json and args.json != "-":
        files[Path(args.json)] = dumps(res)
    write_all(files)  # the scene and the JSON together, or neither
    if args.json == "-":
        sys.stdout.write(dumps(res))
        return 0
    print(summary(d, res, lang))
    return 0
