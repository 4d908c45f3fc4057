"""The cycle in ``plans bench``: the dynamics of 360 positions with the exact integration
(goal: under 0.15 s), the dynamics of the course's 14 positions, the four-stroke V-twin's
720 positions over its 720° cycle (goal: under 0.5 s), and the diagrams sheet to SVG
(goal: under 0.2 s) when the renderer has registered its timer.

The renderer is not imported here (``plans`` never imports ``drawings``): the drawing
package puts ``name -> function`` into :data:`SHEET_TIMERS` when it builds the command
line; the function takes a scene path and the repeats and returns seconds.
"""

from __future__ import annotations

import dataclasses
import time
from collections.abc import Callable
from pathlib import Path
from typing import Any

#: Timers of the cycle's sheets, registered by the renderer: name -> (scene path, repeats) -> seconds.
SHEET_TIMERS: dict[str, Callable[[Path, int], float]] = {}
# the dynamics integrates the loads' work by Gauss–Legendre between the points where they are
# not smooth (five evaluations per step of the exact grid) and refines the flywheel's extremes
# between the grid angles: exact to 1e-9, at about three times the trapezoid's cost
GOALS_S = {"cycle dynamics": 0.150, "cycle diagrams sheet": 0.2, "cycle dynamics 720": 0.5}


def _best(f: Callable[[], Any], n: int) -> float:
    best = float("inf")
    for _ in range(n):
        t = time.perf_counter()
        f()
        best = min(best, time.perf_counter() - t)
    return best


def records(samples: Path, quick: bool = False) -> list[Any]:
    """Bench records (:class:`plans.accuracy.bench.Record`) of the cycle."""
    from plans.accuracy.oracles import Record
    from plans.cycle.dynamics import dynamics
    from plans.cycle.spec import dynamics_spec
    from plans.kinematics.placing import load_scene

    out = []
    seed = samples / "dynamics_slider_crank.toml"
    if seed.is_file():
        scene = load_scene(seed)
        base = dynamics_spec(scene)
        reps = 3 if quick else 10
        for n in (len(base.phi_deg), 360):
            spec = base if n == len(base.phi_deg) else dataclasses.replace(
                base, phi_deg=tuple(base.phi_deg[0] + 360.0 * k / n for k in range(n)))
            dynamics(scene, spec)
            t = _best(lambda spec=spec: dynamics(scene, spec), reps)  # type: ignore[misc]
            d = dynamics(scene, spec)
            goal = GOALS_S["cycle dynamics"]
            out.append(Record("cycle dynamics", seed.stem, n, abs(d.flywheel.graphical_error), t, t / n,
                              param=f"exact {spec.exact_steps} steps", oracle="exact flywheel",
                              note=f"graphical flywheel error; goal {goal * 1e3:g} ms at 360 positions "
                                   f"({'met' if n != 360 or t < goal else 'missed'})"))
    four = samples / "v_twin_four_stroke.toml"
    if four.is_file():  # the four-stroke engine's cycle: 720 positions over 720°, exact to 1e-9
        scene = load_scene(four)
        base = dynamics_spec(scene)
        spec = dataclasses.replace(base, phi_deg=tuple(base.phi_deg[0] + k for k in range(720)))
        dynamics(scene, spec)
        t = _best(lambda: dynamics(scene, spec), 2 if quick else 5)
        d = dynamics(scene, spec)
        goal = GOALS_S["cycle dynamics 720"]
        out.append(Record("cycle dynamics 720", four.stem, 720, abs(d.flywheel.graphical_error), t, t / 720,
                          param=f"exact {spec.exact_steps} steps over 720°", oracle="exact flywheel",
                          note=f"graphical flywheel error; work integrated to {d.flywheel.work_bound:.1e} J; "
                               f"goal {goal:g} s ({'met' if t < goal else 'missed'})"))
    veng = samples / "v_engine_cycle.toml"
    for name, timer in sorted(SHEET_TIMERS.items()):
        if not veng.is_file():
            break
        t = float(timer(veng, 2 if quick else 5))
        goal = GOALS_S.get(name, 0.0)
        out.append(Record(name, veng.stem, 1, 0.0, t, t, param="svg",
                          note=f"goal {goal:g} s ({'met' if t < goal else 'missed'})"))
    return out
