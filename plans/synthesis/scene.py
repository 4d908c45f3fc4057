"""The linkage scene of a design: the links, joints and frame points the design found, in
the file's unit, with the task's crank speed, positions, masses, loads, outputs,
``[dynamics]`` and ``[sheet]`` carried over unchanged, so that ``plans solve`` and
``plans draw`` take it as it is."""

from __future__ import annotations

import math
from typing import Any

from .design import Design
from .toml_out import dumps

#: [task] keys carried into the scene's top level, and into its [driver].
_TOP = ("outputs", "scales", "fij", "loads", "sheet", "diagrams", "dynamics")
_DRIVER = ("omega_rpm", "omega", "eps", "sense", "phi_ref_deg", "phi0_deg")


def _n(x: float) -> float:
    """A number as written: 12 significant digits (K measured back from the written scene
    stays K to 1e-10), a whole number without its fraction's noise."""
    y = float(f"{x:.12g}")
    return 0.0 if y == 0 else y


def _xy(z: complex, scale: float) -> list[float]:
    """A point in the file's unit; a coordinate within rounding of 0 written as 0."""
    tiny = 1e-12 * abs(z) + 1e-300
    return [_n(z.real / scale) if abs(z.real) > tiny else 0.0, _n(z.imag / scale) if abs(z.imag) > tiny else 0.0]


def scene_dict(d: Design) -> dict[str, Any]:
    t = d.task
    u = t.scale
    task = t.task
    title = task.get("title", t.raw.get("title", t.title))
    out: dict[str, Any] = {"format": 1, "title": title, "unit": t.unit}
    links: dict[str, Any]
    joints: list[dict[str, Any]]
    L = {k: _n(v / u) for k, v in d.lengths.items()}
    m = d.measured[0] if d.measured else None
    if d.model in ("central", "offset", "v_engine"):
        frame = 4 if d.model != "v_engine" else 6
        out["frame"] = frame
        out["points"] = {"O": [0.0, 0.0]}
        links = {
            "1": {"name": "crank OA", "axis": ["O", "A"], "length": L["crank"]},
            "2": {"name": "connecting rod AB", "axis": ["A", "B"], "length": L["rod"]},
            "3": {"name": "piston B" if d.model == "v_engine" else "slider B", "axis": ["B"]},
        }
        joints = [{"kind": "R", "links": [frame, 1], "point": "O"},
                  {"kind": "R", "links": [1, 2], "point": "A"},
                  {"kind": "R", "links": [2, 3], "point": "B"}]
        s0 = d.mechs[0]
        g0: Any = "O" if s0.G0 == 0 else _xy(s0.G0, u)
        ang = _n(math.degrees(math.atan2(s0.u.imag, s0.u.real)) % 360.0)
        joints.append({"kind": "P", "links": [3, frame], "point": "B",
                       "guide": {"link": frame, "through": g0, "angle_deg": ang}})
        phi_ref = ang if d.model != "offset" else math.degrees(m.phi_start) if m else 0.0
        if d.model == "v_engine":
            s1 = d.mechs[1]
            links["4"] = {"name": "connecting rod AC", "axis": ["A", "C"], "length": L["rod"]}
            links["5"] = {"name": "piston C", "axis": ["C"]}
            ang2 = _n(math.degrees(math.atan2(s1.u.imag, s1.u.real)) % 360.0)
            joints[3:3] = [{"kind": "R", "links": [1, 4], "point": "A"}]
            joints += [{"kind": "R", "links": [4, 5], "point": "C"},
                       {"kind": "P", "links": [5, frame], "point": "C",
                        "guide": {"link": frame, "through": "O", "angle_deg": ang2}}]
    elif d.model in ("crank_rocker", "three_positions"):
        frame = 4
        fb = d.mechs[0]
        out["frame"] = frame
        out["points"] = {"O": [0.0, 0.0], "D": _xy(fb.D, u)}
        links = {"1": {"name": "crank OA", "axis": ["O", "A"], "length": L["crank"]},
                 "2": {"name": "coupler AB", "axis": ["A", "B"], "length": L["coupler"]},
                 "3": {"name": "rocker DB", "axis": ["D", "B"], "length": L["rocker"]}}
        joints = [{"kind": "R", "links": [frame, 1], "point": "O"},
                  {"kind": "R", "links": [1, 2], "point": "A"},
                  {"kind": "R", "links": [2, 3], "point": "B"},
                  {"kind": "R", "links": [3, frame], "point": "D"}]
        out["branches"] = {"2-3": fb.branch}
        phi_ref = math.degrees(m.phi_start) if m and d.model == "crank_rocker" else 0.0
    else:  # coulisse: the ram driven by a rod DE, or (l4 = 0) by block D in the ram's slot (RPP)
        frame = 6
        c = d.mechs[0]
        slot = c.l4 == 0.0
        out["frame"] = frame
        out["points"] = {"O": [0.0, 0.0], "C": _xy(c.C, u)}
        links = {"1": {"name": "crank OA", "axis": ["O", "A"], "length": L["crank"]},
                 "2": {"name": "block A", "axis": ["A"]},
                 "3": {"name": "coulisse CD", "axis": ["C", "D"], "length": L["coulisse"]},
                 "4": {"name": "block D", "axis": ["D"]} if slot else
                      {"name": "rod DE", "axis": ["D", "E"], "length": L["rod"]},
                 "5": {"name": "ram E", "axis": ["E"]}}
        joints = [{"kind": "R", "links": [frame, 1], "point": "O"},
                  {"kind": "R", "links": [1, 2], "point": "A"},
                  {"kind": "P", "links": [2, 3], "point": "A", "guide": {"link": 3, "through": "C", "toward": "D"}},
                  {"kind": "R", "links": [3, frame], "point": "C"},
                  {"kind": "R", "links": [3, 4], "point": "D"},
                  {"kind": "P", "links": [4, 5], "point": "D", "guide": {"link": 5, "through": [0.0, 0.0],
                                                                         "angle_deg": 90.0}} if slot else
                  {"kind": "R", "links": [4, 5], "point": "E"},
                  {"kind": "P", "links": [5, frame], "point": "E",
                   "guide": {"link": frame, "through": _xy(c.G0, u), "angle_deg": 0.0}}]
        if not slot:
            out["branches"] = {"4-5": 1}
        phi_ref = math.degrees(m.phi_start) if m else 0.0
    for key, body in task.get("masses", {}).items():
        link = links.get(str(int(key)))
        if link is None:
            continue  # the reader refuses a link the mechanism does not have
        for k in ("mass", "inertia"):
            if k in body:
                link[k] = body[k]
        pts = dict(body.get("points", {}))
        if "centre" in body:
            cen = body["centre"]
            if isinstance(cen, str):
                link["centre"] = cen
            elif len(link["axis"]) == 1:
                link["centre"] = link["axis"][0]
            else:
                pts[f"S{int(key)}"] = {"ratio": cen}
                link["centre"] = f"S{int(key)}"
        if pts:
            link["points"] = pts
    out["links"] = links
    out["joints"] = joints
    driver: dict[str, Any] = {"link": 1}
    for k in _DRIVER:
        if k in task:
            driver[k] = task[k]
    if "omega_rpm" not in driver and "omega" not in driver:
        if t.mean_speed is not None and t.stroke is not None:
            driver["omega_rpm"] = _n(t.mean_speed * 30.0 / t.stroke)
        else:
            driver["omega"] = 1.0  # no speed in the task: velocities read as analogues
    driver.setdefault("phi_ref_deg", _n(phi_ref % 360.0))
    pos = task.get("positions", task.get("phi_deg", 12))
    if isinstance(pos, list) or "phi_deg" in task:
        driver["phi_deg"] = pos
    else:
        driver["positions"] = pos
    out["driver"] = driver
    for k in _TOP:
        if k in task:
            out[k] = task[k]
    return out


def scene_text(d: Design, lang: str = "en") -> str:
    """The designed scene as TOML, its heading comment in ``lang``."""
    t = d.task
    import os

    from plans.phrases import say

    name = " ".join(os.path.basename(t.path).split())
    # the task's key as written in English; in Russian the mechanism's name (as plans design says it)
    mechanism = say(f"dm_{t.mechanism}", lang) if lang == "ru" else t.mechanism
    return say("d_scene_head", lang, name=name, mechanism=mechanism) + dumps(scene_dict(d))
