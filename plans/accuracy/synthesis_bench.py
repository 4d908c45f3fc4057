"""``plans bench``'s synthesis goals: one design, proven (the extreme positions by root
finding, γ_min and the assembly margin by minimisation), per model, in 5 ms at most."""

from __future__ import annotations

from pathlib import Path
from typing import Any

#: (key, sample under samples/synthesis, what is measured); every limit 5 ms.
GOALS = (
    ("design_central", "seed001_slider_crank.toml", "design of a central slider-crank, proven"),
    ("design_offset", "offset_slider_crank.toml", "design of an offset slider-crank from K, proven"),
    ("design_crank_rocker", "crank_rocker.toml", "design of a crank-rocker from ψ and K (best γmin), proven"),
    ("design_coulisse", "shaper.toml", "design of a shaper's coulisse mechanism, proven"),
    ("design_v_engine", "seed000_v_engine.toml", "design of a V-engine, proven"),
)
LIMIT = 5e-3


def synthesis_goals(samples: Path, budget: float) -> list[dict[str, Any]]:
    """Each model's design time (best of three batches) against :data:`LIMIT`; a profile
    where a goal is not met."""
    from plans.accuracy.oracles import timeit
    from plans.accuracy.timing import goal_record, profile
    from plans.synthesis.design import design
    from plans.synthesis.model import load_task

    out = []
    for key, name, what in GOALS:
        f = samples / "synthesis" / name
        if not f.exists():
            continue
        task = load_task(f)

        def run(task: Any = task) -> Any:
            return design(task)

        g = goal_record(key, what, LIMIT, "s", timeit(run, budget))
        if not g["met"]:
            g["profile"] = profile(run, 50)
        out.append(g)
    return out
