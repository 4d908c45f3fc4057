"""Every kind of file solved once by its room into one object, which its sheets only draw:
``plans.solve`` dispatches on the file's kind, ``drawings.draw`` takes what it gives, and
``plans draw`` solves each file once (the room's solvers counted)."""

from __future__ import annotations

import importlib
from pathlib import Path
from types import SimpleNamespace

import numpy as np
import pytest

import drawings
import plans
from plans.kinds import KINDS, read_kind
from plans.solution import ROOMS

ROOT = Path(__file__).resolve().parent.parent
SAMPLES = ROOT / "samples"
FILES = [p for p in sorted(SAMPLES.rglob("*.toml")) if read_kind(p)[0] in ROOMS]

#: kind -> the room's solved object's module and what it calls to solve (each call counted)
COUNTED = {
    "engine": ("plans.balancing.solution", ("balance", "exact_check")),
    "gears": ("plans.gears.solution", ("solve_gears", "meshing")),
    "cam": ("plans.cams.solution", ("motion", "profile", "integrate_cam", "min_base_radius", "findings",
                                    "division_points", "diagram", "region", "allowed_region")),
    "synthesis": ("plans.synthesis.solution", ("design", "_joints")),
}


def _key(args: tuple) -> str:
    """A call's arguments as a comparable text (arrays by their bytes)."""
    return repr([a.tobytes() if isinstance(a, np.ndarray) else a for a in args])


def test_every_room_is_a_sample_kind_and_a_kind_of_the_family():
    assert set(ROOMS) == set(KINDS) - {"linkage"} == set(COUNTED)
    assert {read_kind(p)[0] for p in FILES} == set(ROOMS)


@pytest.mark.parametrize("path", FILES, ids=[f"{p.parent.name}-{p.stem}" for p in FILES])
def test_plans_draw_solves_each_file_once(path, monkeypatch):
    """One solved object per drawing, each of the room's solvers called at most once with the
    same arguments; drawn again from that object, nothing is solved."""
    kind = read_kind(path)[0]
    module_name, names = COUNTED[kind]
    module = importlib.import_module(module_name)
    calls: list[tuple[str, str]] = []
    for name in names:
        if not hasattr(module, name):
            continue
        real = getattr(module, name)

        def counted(*args, _real=real, _name=name, **kw):
            calls.append((_name, _key(args)))
            return _real(*args, **kw)

        monkeypatch.setattr(module, name, counted)
    made: list = []
    cls = type(plans.solve(path))
    init = cls.__init__

    def counted_init(self, *a, **kw):
        made.append(self)
        init(self, *a, **kw)

    monkeypatch.setattr(cls, "__init__", counted_init)
    sheets = importlib.import_module(KINDS[kind][1])
    # the layout on the sheets solves nothing: not timed here
    monkeypatch.setattr(sheets, "compose", lambda panels, *a, **kw: [SimpleNamespace(
        panels=panels, number=1, count=1, prims=[], render=lambda: None, width=841.0, height=594.0,
        title_box=(656.0, 534.0, 836.0, 589.0), placed=[])])
    monkeypatch.setattr("drawings.paper.merge.merged", lambda laid, *a, **kw: list(laid))
    d = drawings.draw(str(path))
    assert d.panels and len(made) == 1
    assert calls and len(calls) == len(set(calls)), sorted(calls)
    calls.clear()  # drawn again from that solved object, whose parts are made: nothing is solved
    again = drawings.draw(made[0])
    assert calls == [] and len(made) == 1
    assert [p.svg() for p in again.panels] == [p.svg() for p in d.panels]


def test_a_solved_file_draws_the_sheets_of_its_path():
    """``drawings.draw`` of what ``plans.solve`` gave is ``plans draw`` of the file, byte for
    byte, for one file of each kind."""
    for kind in ROOMS:
        path = next(p for p in FILES if read_kind(p)[0] == kind)
        solved = plans.solve(path)
        assert type(solved).__module__.startswith(ROOMS[kind][1].rpartition(".")[0])
        assert [s.svg() for s in drawings.draw(solved).sheets] == [
            s.svg() for s in importlib.import_module(KINDS[kind][1]).draw(str(path)).sheets]


def test_plans_solve_takes_a_record_of_each_kind_and_refuses_anything_else():
    from plans.balancing.engine import load_engine
    from plans.balancing.solution import EngineSolution

    engine = load_engine(next(p for p in FILES if read_kind(p)[0] == "engine"))
    solved = plans.solve(engine)
    assert isinstance(solved, EngineSolution) and solved.engine is engine
    assert solved.balance is solved.balance
    with pytest.raises(TypeError, match="plans.solve takes"):
        plans.solve(3.0)
