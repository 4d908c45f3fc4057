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

#: A few scenes per tab (the one shown, the one before an edit); a solved four-bar is a few
#: hundred kilobytes.
KEEP = 12

_LOCK = threading.Lock()
_SOLVED: OrderedDict[tuple[str, str], Any] = OrderedDict()
_JSON: OrderedDict[tuple[str, str, bool], bytes] = OrderedDict()
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
        while len(cache) > KEEP:
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
        from plans.results import solve_scene
        from plans.scene.model import parse_scene, scene_from_dict

        scene = parse_scene(text, name) if data is None else scene_from_dict(data, name)
        got = solve_scene(scene)
        _keep(_SOLVED, key, got)
        return got


def solve_json(text: str, name: str, steps: bool = True, data: dict[str, Any] | None = None) -> bytes:
    """The JSON of ``plans solve --json`` (``steps=False``: without the construction
    protocol's sentences), as compact bytes."""
    key = (text, name, steps)
    got = _recall(_JSON, key)
    if got is not None:
        return got
    from plans.results import to_json

    sol = solved(text, name, data)
    with _lock_for((text, name)):  # the lazy parts of one Solution are read by one thread at a time
        got = _recall(_JSON, key)
        if got is None:
            got = json.dumps(to_json(sol, steps), ensure_ascii=False, allow_nan=False,
                             separators=(",", ":")).encode("utf-8")
            _keep(_JSON, key, got)
    return got


def forces_json(text: str, name: str) -> bytes:
    """The force polygons and the lever over the turn (``[]`` when the scene asks for none)."""
    from plans.demo.cycle_forces import cycle_forces

    sol = solved(text, name)
    with _lock_for((text, name)):
        panels = [] if sol.forces is None else cycle_forces(*sol.forces)
    return json.dumps(panels, ensure_ascii=False, allow_nan=False, separators=(",", ":")).encode("utf-8")


def clear() -> None:
    """Forget every solve (the bench measures an edit's solve cold)."""
    with _LOCK:
        _SOLVED.clear()
        _JSON.clear()
