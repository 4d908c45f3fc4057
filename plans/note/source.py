"""The project's files solved, for the note: the one module that knows the engine's API.

Each file is read by the room of its kind and solved as its own command solves it; the
note takes its numbers from the same JSON those commands write (``plans solve --json``,
``plans gears --json``, ``plans cam --json``, ``plans balance --json``), so the document
and the commands agree to the digit.  What JSON does not carry (a step's sentence in
Russian) comes from the solved objects kept beside it.
"""

from __future__ import annotations

import importlib
from dataclasses import dataclass
from typing import Any

from plans.errors import InputError, Said
from plans.io import read_toml
from plans.kinds import kind_of


@dataclass
class Item:
    """One file of the project: its kind, its table, what was solved and its JSON."""

    index: int
    path: str
    kind: str  # linkage | gears | cam | engine | synthesis
    raw: dict[str, Any]
    solved: Any  # plans.results.Solution, GearSolution, Cam, Balance, ...
    data: dict[str, Any]  # the command's JSON

    # ---- the linkage's protocol (sentences in either language)
    def plan_steps(self, k: int, kind: str) -> tuple:
        """The steps of the velocity or acceleration plan of position k (``Step.say(lang)``)."""
        sol = self.solved
        if not sol.plans:
            return ()
        plan = getattr(sol.plans[k], kind)
        return tuple(plan.steps) if plan is not None else ()

    def force_steps(self, k: int) -> tuple:
        """The force analysis of position k step by step (``ForceStep``: drawing, step)."""
        sol = self.solved
        if sol.forces is None:
            return ()
        from plans.forces.protocol import force_steps

        return force_steps(sol.forces[0], sol.forces[1], k)


    def gas(self) -> dict[str, tuple[float, float]]:
        """The pistons' gas forces of constant pressure: name -> (piston area m², pressure Pa)."""
        sol = self.solved
        if getattr(sol, "forces", None) is None:
            return {}
        return {g.name: (float(g.area), float(g.pressure)) for g in sol.forces[0].loads.gas
                if g.pressure is not None}

    def wittenbauer(self) -> tuple[float, float] | None:
        """The energy–mass diagram's tangents cut the ΔT axis at k and l (J)."""
        cyc = getattr(self.solved, "cycle", None)
        if cyc is None or cyc.dynamics is None:
            return None
        w = cyc.dynamics.wittenbauer
        return float(w.k), float(w.l)


#: A file kind the note knows a section for, read by a module of its own when installed
#: (``read(path, raw) -> (solved, json)`` and ``section(item, lang) -> list[Section]``).
HOOKS: dict[str, str] = {"synthesis": "plans.design.note"}


def read(paths: list[str]) -> list[Item]:
    """Every file solved in the order given; a file no room reads is one InputError line."""
    out: list[Item] = []
    for i, path in enumerate(paths):
        raw = read_toml(path)
        kind = raw.get("kind")
        if isinstance(kind, str) and kind in HOOKS:
            try:
                hook = importlib.import_module(HOOKS[kind])
            except ModuleNotFoundError:
                raise InputError(Said("ns_kind_files_have", kind=kind),
                                 file=path, field="kind") from None
            solved, data = hook.read(path, raw)
            out.append(Item(i, path, kind, raw, solved, data))
            continue
        kind = kind_of(raw, path)
        solved, data = _READERS[kind](path)
        out.append(Item(i, path, kind, raw, solved, data))
    return out


def _linkage(path: str) -> tuple[Any, dict]:
    from plans.results import load_and_solve, to_json

    sol = load_and_solve(path)
    return sol, to_json(sol)


def _gears(path: str) -> tuple[Any, dict]:
    from plans.gears.meshing import drawn_contact_ratios
    from plans.gears.model import load_gears
    from plans.gears.solve import solve_gears, to_json

    sol = solve_gears(load_gears(path))
    return sol, to_json(sol, drawn_contact_ratios(sol))


def _cam(path: str) -> tuple[Any, dict]:
    from plans.cams.cli import results
    from plans.cams.model import load_cam

    cam = load_cam(path)
    return cam, results(cam)


def _engine(path: str) -> tuple[Any, dict]:
    from plans.balancing.analysis import balance
    from plans.balancing.engine import load_engine

    b = balance(load_engine(path))
    return b, b.to_json()


_READERS = {"linkage": _linkage, "gears": _gears, "cam": _cam, "engine": _engine}
