"""The V-engine's performance goals with fixed limits (bench.json "goals", :data:`GOALS`): exact
kinematics and the construction at 360 positions and at one, the plans built together, the
force analysis with friction against the frictionless one; a profile of each goal not met."""

from __future__ import annotations

import math
import time
from collections.abc import Callable
from pathlib import Path
from typing import Any

import numpy as np

from plans.accuracy.oracles import timeit
from plans.accuracy.timing import goal_record, least_paired, least_time, profile
from plans.kinematics import construction, exact
from plans.kinematics.placing import load_scene
from plans.scene.model import Scene

#: The performance goals on this class of machine: (key, what is measured, limit, unit).
#: A time ("s") is met at or below its limit, a speed-up ("×") at or above it.
GOALS = (
    ("exact_360", "exact kinematics of 360 V-engine positions (v and a)", 300e-6, "s"),
    ("construction_1", "construction of both plans of the V-engine at one position", 500e-6, "s"),
    ("construction_360", "both plans of 360 V-engine positions built together, against one position "
                         "at a time", 20.0, "×"),
    ("friction_360", "force analysis with friction in every pair of 360 V-engine positions (successive "
                     "approximation, lever included), against the frictionless one", 5.0, "× cost"),
)


#: Short batches of exact_360 and construction_1, and turns of the friction's single runs with
#: the frictionless ones (the least of each is taken).
SHORT_BATCHES, FRICTION_TURNS = 41, 41


def performance_goals(samples: Path, budget: float) -> list[dict[str, Any]]:
    """Each goal of :data:`GOALS` measured on the V-engine, with a profile when it is not met."""
    f = samples / "v_engine.toml"
    if not f.exists():
        return []
    sc = load_scene(f)
    phis = np.linspace(0.0, 360.0, 360, endpoint=False)
    k1 = exact.solve(sc, [45.0], order=2)
    work: dict[str, Callable[[], Any]] = {
        "exact_360": lambda: exact.solve(sc, phis, order=2),
        "construction_1": lambda: construction.build(k1, 0),
    }
    out = []
    for key, what, limit, unit in GOALS:
        if key == "construction_360":
            g = _together(sc, phis, what, limit, budget)
        elif key == "friction_360":
            g = friction_cost(samples, phis, what, limit)
        else:  # the least of many short batches: the load only ever adds to a call's time
            g = goal_record(key, what, limit, unit, least_time(work[key], SHORT_BATCHES))
            if not g["met"]:
                g["profile"] = profile(work[key], 200)
        out.append(g)
    return out


def _together(sc: Scene, phis: np.ndarray, what: str, limit: float, budget: float) -> dict[str, Any]:
    """The plans of 360 positions as one construction over arrays (readings included, as
    arrays) against the same construction run position by position; the readings of the
    two agree (the largest difference over all readings is reported)."""
    kin = exact.solve(sc, phis, order=2)
    mv, ma = construction.default_scales(kin)
    together = timeit(lambda: construction.build_all(kin), budget)
    one_by_one = timeit(lambda: [construction.build(kin, k, velocity_scale=mv, acceleration_scale=ma)
                                 for k in range(kin.n)], budget)
    apart = 0.0
    for a, b in zip(construction.build_all(kin), (construction.build(kin, k, velocity_scale=mv, acceleration_scale=ma)
                                                   for k in range(kin.n)), strict=True):
        for ra, rb in zip(a.readings, b.readings, strict=True):
            apart = max(apart, abs(ra.value - rb.value) / max(abs(ra.exact), ra.ref, 1e-300))
    g = goal_record("construction_360", what, limit, "×", one_by_one / together)
    g.update({"together_s": together, "one_by_one_s": one_by_one, "readings_apart": apart})
    return g


def friction_cost(samples: Path, phis: np.ndarray, what: str, limit: float) -> dict[str, Any]:
    """The kinetostatics and the lever of the V-engine with friction in every pair
    (``v_engine_friction.toml``) against the same scene without its friction, at 360
    positions, measured turn about."""
    from plans.forces.analysis import kinetostatics
    from plans.kinematics.placing import scene_from_dict

    f = samples / "v_engine_friction.toml"
    if not f.exists():
        return {"key": "friction_360", "goal": what, "value": math.nan, "limit": limit, "unit": "× cost",
                "met": None}
    raw = dict(load_scene(f).raw)
    raw["driver"] = {k: v for k, v in raw["driver"].items() if k not in ("positions", "phi0_deg")}
    raw["driver"]["phi_deg"] = [float(x) for x in phis]
    with_f = scene_from_dict(raw, str(f))
    raw = {k: v for k, v in raw.items() if k != "friction"}
    raw["joints"] = [{k: v for k, v in j.items() if k not in ("f", "pin_radius", "friction_circle")}
                     for j in raw["joints"]]
    without = scene_from_dict(raw, str(f))
    kin_f, kin_0 = exact.solve(with_f, order=2), exact.solve(without, order=2)
    # single runs turn about, each the processor time it took: a run of several milliseconds
    # outlasts the scheduler's share on a loaded machine, and what it waited is not its cost
    t_f, t_0 = least_paired(lambda: kinetostatics(with_f, kin_f), lambda: kinetostatics(without, kin_0),
                            FRICTION_TURNS, clock=time.process_time)
    g = goal_record("friction_360", what, limit, "× cost", t_f / t_0)
    fa = kinetostatics(with_f, kin_f)
    assert fa is not None
    g.update({"friction_s": t_f, "frictionless_s": t_0,
              "iterations_max": int(fa[0].friction.iterations.max())})
    if not g["met"]:
        g["profile"] = profile(lambda: kinetostatics(with_f, kin_f), 50)
    return g
