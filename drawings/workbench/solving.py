"""The workbench's solves, each made once per text: the page asks for the same scene's
solution, its force polygons and its sheets one after another, and an edit taken back (a
value typed again, a pivot dragged back) is a text solved before.

``solved(text, name)`` is the :class:`plans.solution.Solution` (its parts computed when first
read, as every reader takes them); ``solve_json`` the bytes of ``plans solve --json`` for it.
A scene that cannot be solved raises the engine's error every time it is asked (not cached).
"""

from __future__ import annotations

import json
import threading
from collections import OrderedDict
from typing import Any

#: A few scenes per tab (the one shown, the one before an edit): the solutions (a solved
#: four-bar is a few hundred kilobytes, a scene of hundreds of positions far more) and
#: their JSON.
KEEP_SOLVED = 4
KEEP = 12
#: Larger answers and solutions are made each time they are asked for, never kept.
KEEP_BYTES = 4 << 20
KEEP_POSITIONS = 720

_LOCK = threading.Lock()
_SOLVED: OrderedDict[tuple[str, str], Any] = OrderedDict()
_JSON: OrderedDict[tuple[str, str, bool, str, int | None], bytes] = OrderedDict()
#: One lock per scene being solved: two requests for the same text solve it once.
_BUSY: dict[tuple[str, str], threading.Lock] = {}


def _recall(cache: OrderedDict, key: Any) -> Any:
    with _LOCK:
        got = cache.get(key)
        if got is not None:
            cache.move_to_end(key)
        return got


def _keep(cache: OrderedDict, key: Any, value: Any) -> None:
    with _LOCK:
        cache[key] = value
        cache.move_to_end(key)
        while len(cache) > (KEEP_SOLVED if cache is _SOLVED else KEEP):
            cache.popitem(last=False)


def _lock_for(key: tuple[str, str]) -> threading.Lock:
    with _LOCK:
        lock = _BUSY.get(key)
        if lock is None:
            lock = _BUSY[key] = threading.Lock()
            if len(_BUSY) > 4 * KEEP:  # the locks of scenes long solved
                for k in list(_BUSY)[: len(_BUSY) - KEEP]:
                    if k != key and not _BUSY[k].locked():
                        del _BUSY[k]
        return lock


def solved(text: str, name: str, data: dict[str, Any] | None = None) -> Any:
    """The scene's Solution with every part it asks for computed (``data``: the text already
    parsed, when the caller has it)."""
    key = (text, name)
    got = _recall(_SOLVED, key)
    if got is not None:
        return got
    with _lock_for(key):
        got = _recall(_SOLVED, key)
        if got is not None:
            return got
        from plans.kinematics.placing import parse_scene, scene_from_dict
        from plans.results import solve_scene

        scene = parse_scene(text, name) if data is None else scene_from_dict(data, name)
        got = solve_scene(scene)
        if got.kinematics.n <= KEEP_POSITIONS:
            _keep(_SOLVED, key, got)
        return got


#: What the page draws of a position (``view="page"``): the points' positions, the links' ω
#: and ε, the plans' points and segments, the readings and the balancing load.
PAGE_POSITION = ("phi_deg", "points", "links", "plans", "readings", "balancing")
PAGE_READING = ("quantity", "segment", "length_mm", "value", "exact", "unit", "difference")
PAGE_SEGMENT = ("label", "from", "to", "kind")


def page_view(out: dict[str, Any]) -> dict[str, Any]:
    """``plans solve --json`` cut to what the page draws: the same keys and values, fewer of
    them (half the text to write and to read: the velocities and accelerations of the
    points, the reactions and the construction's details stay in the full JSON)."""
    positions = []
    for pos in out["positions"]:
        p = {k: pos[k] for k in PAGE_POSITION if k in pos}
        p["points"] = {nm: {"r": e["r"]} for nm, e in pos["points"].items()}
        if "plans" in p:
            p["plans"] = {kind: {"scale": pl["scale"], "pole": pl["pole"], "points": pl["points"],
                                 "segments": [{k: s[k] for k in PAGE_SEGMENT} for s in pl["segments"]]}
                          for kind, pl in pos["plans"].items()}
        if "readings" in p:
            p["readings"] = [{k: r[k] for k in PAGE_READING} for r in pos["readings"]]
        positions.append(p)
    return {**out, "positions": positions}


def page_symbols(out: dict[str, Any], scene: Any) -> dict[str, dict[str, str]]:
    """What the page writes for each key it shows, per language: the readings' quantities,
    the plans' points and segments in the textbook's symbols (ω1, π or p_a as the scene's
    notation says), the balancing load's rows in words."""
    from plans.language import symbols
    from plans.page_words import again, textbook_symbol
    from plans.phrases import say
    from plans.scene.notation import resolve

    names: set[str] = set()
    bal: set[str] = set()
    for pos in out["positions"]:
        for r in pos.get("readings", []):
            names.add(r["quantity"])
            names.update(str(r.get("segment") or "").split())
        for pl in (pos.get("plans") or {}).values():
            names.update(pl["points"])
        if isinstance(pos.get("balancing"), dict):
            bal.update(k for k, v in pos["balancing"].items() if isinstance(v, int | float))
            names.add("M_bal" if pos["balancing"].get("kind") == "moment" else "F_bal")
    rows = {"moment": "wb_bal_moment", "by_kinetostatics": "r_kin", "by_lever": "r_lever", "by_power": "r_power",
            "exact_difference_percent": "wb_bal_exact", "difference_percent": "wb_bal_drawn"}
    got: dict[str, dict[str, str]] = {}
    for lang in ("ru", "en"):
        letter, per_mm, pole = resolve(getattr(scene, "scale_style", "") or "", lang)
        words = {nm: textbook_symbol(nm, lang, pole) for nm in sorted(names)}
        words["scale.symbol"], words["scale.per_mm"] = letter, "1" if per_mm else "0"  # the notation's scales
        sym = words.get("M_bal") or words.get("F_bal") or ""
        for k in sorted(bal):
            words["balancing." + k] = say(rows[k], lang, sym=sym) if k in rows else k
        for table in (out.get("cycle") or {}).get("tables", []):  # the tables over the cycle
            words["cycle." + table["title"]] = again(table["title"], _CYCLE_TITLES, lang)
            for r in table["rows"]:
                words["cycle." + r["label"]] = symbols(r["label"], lang) if lang == "ru" else " ".join(
                    textbook_symbol(w, lang, pole) for w in r["label"].split(" "))
        got[lang] = words
    return got


#: The catalogue's titles of the tables over the cycle (written in English in the JSON).
_CYCLE_TITLES = ("y_plans", "y_positions", "y_analogues", "y_inertia", "y_forces", "y_energy")


def solve_json(text: str, name: str, steps: bool = True, data: dict[str, Any] | None = None,
               view: str = "full", at: int | None = None) -> bytes:
    """The JSON of ``plans solve --json`` (``steps=False``: without the construction
    protocol's sentences; ``view="page"``: only what the page draws), as compact bytes.
    ``at``: the page's position (with ``view="page"``): that one whole, the others only
    their angle, points and links (the page draws the position on its slider first and
    asks for the rest after, ``"partial": at`` says so)."""
    key = (text, name, steps, view, at)
    got = _recall(_JSON, key)
    if got is not None:
        return got
    from plans.results import to_json

    sol = solved(text, name, data)
    with _lock_for((text, name)):  # the lazy parts of one Solution are read by one thread at a time
        got = _recall(_JSON, key)
        if got is None:
            if at is not None and view == "page" and 0 <= at < sol.kinematics.n:
                out = page_view(_partial(sol, at, steps))
            else:
                out = to_json(sol, steps)
                out = page_view(out) if view == "page" else out
            if view == "page":
                out["symbols"] = page_symbols(out, sol.scene)
            got = json.dumps(out, ensure_ascii=False, allow_nan=False, separators=(",", ":")).encode("utf-8")
            if len(got) <= KEEP_BYTES:
                _keep(_JSON, key, got)
    return got


def _partial(sol: Any, at: int, steps: bool) -> dict[str, Any]:
    """``plans solve --json`` with position ``at`` whole (as ``plans.results`` writes each
    position) and every other one its angle, points' positions and links' motion."""
    import numpy as np

    from plans.forces.lever import force_json
    from plans.results import head_json, position_json

    out = head_json(sol)
    kin = sol.kinematics
    forces = None if sol.forces is None else force_json(sol.forces[1])
    n = kin.n

    def column(x: Any) -> list:  # an array over the positions as Python numbers, read once
        return np.broadcast_to(np.asarray(x), (n,)).tolist()

    r = {nm: column(kin.point(nm)[0]) for nm in kin.point_names()}
    motion = {}
    for lid in sorted(sol.scene.links):
        m = kin.motion[lid]
        motion[str(lid)] = [(key, column(x)) for key, x in (("theta", m.theta), ("omega", m.omega), ("eps", m.eps))
                            if x is not None]
    phi = kin.phi_deg.tolist()
    positions = []
    for k in range(n):
        if k == at:
            positions.append(position_json(sol, k, None if forces is None else forces[k], steps))
            continue
        links = {lid: {key: float(col[k]) for key, col in cols} for lid, cols in motion.items()}
        positions.append({"phi_deg": phi[k], "points": {nm: {"r": [z[k].real, z[k].imag]} for nm, z in r.items()},
                          "links": links})
    out["positions"] = positions
    out["partial"] = at
    return out


def forces_json(text: str, name: str) -> bytes:
    """The force polygons and the lever over the turn (``[]`` when the scene asks for none)."""
    from plans.demo.cycle_forces import cycle_forces
    from plans.page_words import page_label
    from plans.scene.notation import resolve

    sol = solved(text, name)
    with _lock_for((text, name)):
        panels = [] if sol.forces is None else cycle_forces(sol.forces.analysis, sol.forces.lever,
                                                             sol.force_polygons)  # read, not drawn again
    for pn in panels:  # each label as the page writes it in either language
        labels = {*(pn.get("points") or {}), *(g["label"] for g in pn.get("segments", []) if g.get("label"))}
        pn["said"] = {lang: {lb: page_label(lb, lang, resolve(sol.scene.scale_style or "", lang)[2]) for lb in sorted(labels)}
                      for lang in ("ru", "en")}
    return json.dumps(panels, ensure_ascii=False, allow_nan=False, separators=(",", ":")).encode("utf-8")


def clear() -> None:
    """Forget every solve (the bench measures an edit's solve cold)."""
    with _LOCK:
        _SOLVED.clear()
        _JSON.clear()
