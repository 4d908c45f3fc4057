"""The project's performance goals, each measured in the run that reports it."""

from __future__ import annotations

import cProfile
import io
import pstats
from collections.abc import Callable
from pathlib import Path
from typing import Any

import numpy as np

from plans.accuracy.oracles import timeit
from plans.kinematics import construction
from plans.kinematics import exact as kinematics
from plans.scene.model import Scene, load_scene

#: The performance goals on this class of machine: (key, what is measured, limit, unit).
#: A time ("s") is met at or below its limit, a speed-up ("×") at or above it.
GOALS = (
    ("exact_360", "exact kinematics of 360 V-engine positions (v and a)", 300e-6, "s"),
    ("construction_1", "construction of both plans of the V-engine at one position", 500e-6, "s"),
    ("construction_360", "both plans of 360 V-engine positions built together, against one position "
                         "at a time", 20.0, "×"),
)


def _goal(key: str, what: str, limit: float, unit: str, value: float) -> dict[str, Any]:
    met = value <= limit if unit == "s" else value >= limit
    return {"key": key, "goal": what, "value": value, "limit": limit, "unit": unit, "met": bool(met)}


def performance_goals(samples: Path, budget: float) -> list[dict[str, Any]]:
    """Each goal of :data:`GOALS` measured on the V-engine, with a profile when it is not met."""
    f = samples / "v_engine.toml"
    if not f.exists():
        return []
    sc = load_scene(f)
    phis = np.linspace(0.0, 360.0, 360, endpoint=False)
    k1 = kinematics.solve(sc, [45.0], order=2)
    work: dict[str, Callable[[], Any]] = {
        "exact_360": lambda: kinematics.solve(sc, phis, order=2),
        "construction_1": lambda: construction.build(k1, 0),
    }
    out = []
    for key, what, limit, unit in GOALS:
        if key == "construction_360":
            g = _together(sc, phis, what, limit, budget)
        else:
            g = _goal(key, what, limit, unit, timeit(work[key], budget))
            if not g["met"]:
                g["profile"] = profile(work[key], 200)
        out.append(g)
    return out


def _together(sc: Scene, phis: np.ndarray, what: str, limit: float, budget: float) -> dict[str, Any]:
    """The plans of 360 positions as one construction over arrays (readings included, as
    arrays) against the same construction run position by position; the readings of the
    two agree (the largest difference over all readings is reported)."""
    kin = kinematics.solve(sc, phis, order=2)
    mv, ma = construction.default_scales(kin)
    together = timeit(lambda: construction.build_all(kin), budget)
    one_by_one = timeit(lambda: [construction.build(kin, k, velocity_scale=mv, acceleration_scale=ma)
                                 for k in range(kin.n)], budget)
    apart = 0.0
    for a, b in zip(construction.build_all(kin), (construction.build(kin, k, velocity_scale=mv, acceleration_scale=ma)
                                                   for k in range(kin.n)), strict=True):
        for ra, rb in zip(a.readings, b.readings, strict=True):
            apart = max(apart, abs(ra.value - rb.value) / max(abs(ra.exact), ra.ref, 1e-300))
    g = _goal("construction_360", what, limit, "×", one_by_one / together)
    g.update({"together_s": together, "one_by_one_s": one_by_one, "readings_apart": apart})
    return g


def profile(fn: Callable[[], Any], reps: int, top: int = 12) -> list[dict]:
    """The functions where ``fn`` spends its time (own time, cProfile), as records."""
    pr = cProfile.Profile()
    pr.enable()
    for _ in range(reps):
        fn()
    pr.disable()
    st = pstats.Stats(pr, stream=io.StringIO())
    rows = []
    for (file, line, func), (_cc, nc, tt, ct, _callers) in st.stats.items():  # type: ignore[attr-defined]
        rows.append({"function": f"{Path(file).name}:{line}({func})", "calls_per_run": nc / reps,
                     "own_us_per_run": tt / reps * 1e6, "cum_us_per_run": ct / reps * 1e6})
    rows.sort(key=lambda r: -r["own_us_per_run"])
    return rows[:top]


