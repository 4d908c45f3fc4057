"""``plans cam FILE [--json PATH]``: the cam's motion, profile, pressure angle, curvature,
undercut and the minimum base radius, as a summary and as JSON."""

from __future__ import annotations

import argparse
import math
from typing import TYPE_CHECKING, Any

from plans.language import file_command

if TYPE_CHECKING:  # the analysis is imported when the command runs: ``plans`` starts fast
    import numpy as np

    from .model import Cam
    from .solution import CamSolution


def register(sub: argparse._SubParsersAction) -> None:
    p = file_command(sub, "cam", "a cam: motion laws, base radius, profile by inversion (JSON)", "cam",
                     "cam file (TOML, kind = \"cam\")", "write the results as JSON ('-' for stdout)")
    p.set_defaults(func=_run)


def _r(v: float, nd: int = 9) -> float:
    x = round(float(v), nd)
    return 0.0 if x == 0 else x


def _opt(v: float | None, L: float) -> float | None:
    return None if v is None else _r(v / L)


def _arr(a: np.ndarray, nd: int = 9) -> list[float]:
    return [_r(x, nd) for x in a]


def results(source: Cam | CamSolution) -> dict[str, Any]:
    """The JSON document of a cam (or of its solution, :func:`plans.solve`): arrays aligned
    with phi_deg (lengths in the file's unit; an oscillating follower's s in degrees of swing)."""
    import numpy as np

    from .analysis import grid
    from .solution import CamSolution, solve_cam

    sol = source if isinstance(source, CamSolution) else solve_cam(source)
    cam = sol.cam
    phi = grid(cam)
    pr = sol.table_profile
    mo = pr.motion
    L = cam.scale
    osc = cam.follower == "oscillating"
    lift = (180 / math.pi) if osc else 1 / L  # s in degrees or in the file's unit
    rate = 1.0 if osc else 1 / L  # the arm's ω and ε in rad/s, rad/s²
    fi = sol.findings
    exact = sol.base_radius
    drawn = sol.drawn_base_radius
    fit = sol.roller_base_radius
    best_fit = sol.best_roller_base_radius
    out: dict[str, Any] = {
        "phi_deg": _arr(np.degrees(phi), 6),
        "s": _arr(mo.s * lift),
        "ds_dphi": _arr(mo.s1 * lift),
        "d2s_dphi2": _arr(mo.s2 * lift),
        "v": _arr(mo.s1 * rate * cam.omega),
        "a": _arr(mo.s2 * rate * cam.omega**2),
        "pressure_angle_deg": _arr(np.degrees(pr.pressure_angle)),
        "curvature": _arr(pr.curvature * L),
        "profile": {"theoretical": [[_r(x / L), _r(y / L)] for x, y in pr.theoretical],
                    "actual": [[_r(x / L), _r(y / L)] for x, y in pr.actual]},
        "min_base_radius": _opt(exact.min_base_radius, L),
        "min_base_radius_graphical": None if drawn is None else _opt(drawn.min_base_radius, L),
        "min_base_radius_roller": None if fit is None else _r(fit / L),
        "best_base_radius": _r(exact.best_base_radius / L),
        "best_offset": None if exact.best_offset is None else _r(exact.best_offset / L),
        "best_base_radius_roller": None if best_fit is None else _r(best_fit / L),
        "best_pivot": None if exact.best_pivot is None else _r(exact.best_pivot / L),
        "min_curvature_radius": _r(fi.min_curvature_radius / L),
        "max_pressure_angle_rise_deg": _r(math.degrees(fi.max_pressure_rise)),
        "max_pressure_angle_return_deg": _r(math.degrees(fi.max_pressure_return)),
        "undercut": [{"from_deg": _r(u.start_deg, 6), "to_deg": _r(u.end_deg, 6),
                      "min_curvature_radius": _r(u.min_radius / L)} for u in fi.undercut],
        "unit": cam.unit,
        "follower": cam.follower,
    }
    return out


def summary(cam: Cam, res: dict[str, Any], lang: str = "en") -> str:
    """What ``plans cam`` prints, in ``lang`` (decimal comma in Russian)."""
    from plans.phrases import UNITS_RU, say

    ru = lang == "ru"
    u = UNITS_RU.get(cam.unit, cam.unit) if ru else cam.unit
    osc = cam.follower == "oscillating"
    lines = [say("c_head", lang, title=cam.title, follower=say("c_" + cam.follower, lang),
                 face=say("c_flat", lang) if cam.flat else say("c_roller", lang, r=cam.roller / cam.scale, u=u),
                 r0=cam.base_radius / cam.scale, u=u, sense=say("c_ccw" if cam.sense > 0 else "c_cw", lang))]
    h = max(res["s"])
    lines.append(say("c_lift", lang, h=h, hu=say("c_deg", lang) if osc else u, v=max(map(abs, res["v"])),
                     vu=say("c_rad_s", lang) if osc else say("c_per_s", lang, u=u), a=max(map(abs, res["a"])),
                     au=say("c_rad_s2", lang) if osc else say("c_per_s2", lang, u=u)))
    lines.append(say("c_pressure", lang, rise=res["max_pressure_angle_rise_deg"], prise=math.degrees(cam.alpha_rise),
                     ret=res["max_pressure_angle_return_deg"], pret=math.degrees(cam.alpha_return)))
    if cam.flat:
        lines.append(say("c_min_flat", lang, r=res["min_base_radius"], u=u))
    else:
        where = "" if osc else say("c_at_offset", lang, e=cam.offset / cam.scale, u=u)
        if res["min_base_radius"] is None:
            line = say("c_no_radius", lang)
        else:
            line = say("c_min", lang, where=where, r=res["min_base_radius"], u=u)
        if res["min_base_radius_graphical"] is not None:
            line += say("c_graphical", lang, r=res["min_base_radius_graphical"], u=u)
        lines.append(line)
        if res["min_base_radius_roller"] is not None:
            lines.append(say("c_roller_fit", lang, rr=cam.roller / cam.scale, r=res["min_base_radius_roller"], u=u))
        if res["best_offset"] is not None:
            line = say("c_best_offset", lang, r=res["best_base_radius"], e=res["best_offset"], u=u)
            fit = res["best_base_radius_roller"]
            if fit is not None and fit > res["best_base_radius"] * (1 + 1e-9):
                line += say("c_best_fit", lang, r=fit, u=u)
            lines.append(line)
        if res["best_pivot"] is not None:
            lines.append(say("c_best_pivot", lang, r=res["best_base_radius"], d=res["best_pivot"], u=u))
    lines.append(say("c_curvature", lang, r=res["min_curvature_radius"], u=u))
    if res["undercut"]:
        for c in res["undercut"]:
            what = (say("c_flat_fails", lang) if cam.flat else
                    say("c_roller_big", lang, rr=cam.roller / cam.scale, r=c["min_curvature_radius"], u=u))
            lines.append(say("c_undercut", lang, a=c["from_deg"], b=c["to_deg"], what=what))
    else:
        lines.append(say("c_no_undercut", lang))
    if res["min_base_radius"] is not None and (
            res["max_pressure_angle_rise_deg"] > math.degrees(cam.alpha_rise) + 1e-9
            or res["max_pressure_angle_return_deg"] > math.degrees(cam.alpha_return) + 1e-9):
        lines.append(say("c_raise", lang, r=res["min_base_radius"], u=u))
    return "\n".join(lines)


def _run(args: argparse.Namespace) -> int:
    from plans.io import dumps, json_out

    from .solution import solve_cam

    sol = solve_cam(args.cam)  # what plans.solve gives of a cam file
    cam = sol.cam
    res = results(sol)
    if json_out(args.json, dumps(res)):
        return 0
    from plans.language import file_language

    print(summary(cam, res, file_language(getattr(args, "language", None), args.cam)))
    return 0
