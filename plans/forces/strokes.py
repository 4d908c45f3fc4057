"""Loads limited to a stroke of the output: ``stroke = "working"`` or ``"idle"``.

The working stroke is the slow one, where the output (the slider or rocker of
:mod:`plans.kinematics.extreme`, ``[driver] extreme_of``) moves against the useful
resistance; the idle stroke is the fast return.  A force or a moment given with one of them
acts at the positions whose crank angle lies on that stroke (the extreme position that
begins it included) and is zero on the other.  A resisting force (or moment) is still
opposite the motion of its point (link), so it vanishes where that motion stops.

A resisting load given without ``stroke`` acts on both strokes; where the strokes differ
(K > 1) that is usually a slip (a cutting force on the return stroke), so it is said on
stderr, not refused.
"""

from __future__ import annotations

from typing import Any

import numpy as np

from plans.errors import Field, InputError
from plans.scene.model import Scene

#: The strokes a ``[[loads.force]]`` or ``[[loads.moment]]`` may be limited to.
OUTPUT_STROKES = ("working", "idle")
#: K above this: the idle stroke is measurably the faster one (the warning's threshold).
K_DISTINCT = 1.0 + 1e-9


def on_stroke(scene: Scene, stroke: str, phi_deg: Any, field: str = "loads") -> Any:
    """True at the crank angles on ``stroke`` ("working" or "idle") of the scene's output."""
    from plans.kinematics.extreme import strokes

    st = strokes(scene, field)
    working = st.working(phi_deg)
    return working if stroke == "working" else ~working


def warn_idle(scene: Scene, raw: dict[str, Any], forces: Any = ()) -> None:
    """On stderr: each resisting load given without ``stroke`` that also acts on the idle
    stroke, and each one limited by the sign of its velocity (``stroke = "positive"`` or
    ``"negative"``) that acts on the idle stroke only."""
    suspects = []
    for key, what in (("force", "w_idle"), ("moment", "w_idle_moment")):
        bodies = raw.get(key, [])
        for k, body in enumerate(bodies if isinstance(bodies, list) else []):
            if isinstance(body, dict) and "resisting" in body and "stroke" not in body:
                suspects.append((key, k, what, body.get("name", "")))
    signed = [(k, fl) for k, fl in enumerate(forces) if fl.resisting is not None and fl.stroke in ("positive", "negative")]
    if not suspects and not signed:
        return
    from plans.kinematics.extreme import strokes

    try:
        st = strokes(scene, "loads")
    except InputError:
        return  # no output with two extremes: no strokes to tell apart
    if st.K <= K_DISTINCT:
        return
    from plans.errors import Said, warn

    # in the run's language: --language, the scene's [sheet] language, the locale
    for k, fl in signed:
        if _idle_only(scene, st, fl):
            warn(Said("w_idle_only", file=scene.path, field=Field(f"loads.force[{k}].stroke"), name=fl.name,
                      stroke=fl.stroke), scene.raw)
    for key, k, what, name in suspects:
        warn(Said(what, file=scene.path, field=Field(f"loads.{key}[{k}].resisting"), name=name or f"#{k + 1}"),
             scene.raw)


def mask(scene: Scene, kin: Any, stroke: str, values: Any) -> Any:
    """``values`` where the positions of ``kin`` lie on ``stroke``, zero elsewhere."""
    if stroke not in OUTPUT_STROKES:
        return values
    keep = on_stroke(scene, stroke, kin.phi_deg)
    return np.where(keep, values, 0)


def _idle_only(scene: Scene, st: Any, fl: Any) -> bool:
    """The force acts somewhere on the revolution, and only on the idle stroke (sampled every 0.5°)."""
    import math

    from plans.kinematics.exact import solve
    from plans.kinematics.extreme import GRID, probe_scene

    grid = np.arange(GRID) * (360.0 / GRID)
    v = solve(probe_scene(scene), grid, order=1).point_on(fl.link, scene.links[fl.link].points[fl.point])[1]
    along = (v * complex(math.cos(fl.along), -math.sin(fl.along))).real
    acts = along > 0 if fl.stroke == "positive" else along < 0
    return bool(acts.any()) and not bool((acts & st.working(grid)).any())
