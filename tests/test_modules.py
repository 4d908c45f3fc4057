"""How the modules of ``plans`` and ``drawings`` depend on each other, read from their source:
no import cycle among the modules (inside a room or across rooms) nor among the rooms, lazy
imports (inside a function) and ``TYPE_CHECKING`` imports counted; no private name (``_x``)
taken from another module; no module longer than a reader takes in."""

from __future__ import annotations

import ast
import functools
import re
from collections.abc import Iterator
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parent.parent
PACKAGES = ("plans", "drawings")
LONGEST = 600  # lines


def _modules() -> dict[str, Path]:
    out = {}
    for pkg in PACKAGES:
        for p in sorted((ROOT / pkg).rglob("*.py")):
            parts = list(p.relative_to(ROOT).with_suffix("").parts)
            if parts[-1] == "__init__":
                parts = parts[:-1]
            out[".".join(parts)] = p
    return out


MODULES = _modules()


def _statements(body: list[ast.stmt]) -> Iterator[ast.stmt]:
    """Every statement, nested ones included (an import is a statement: no expression is read)."""
    for node in body:
        yield node
        for key in ("body", "orelse", "finalbody"):
            yield from _statements(getattr(node, key, []))
        for h in getattr(node, "handlers", []):
            yield from _statements(h.body)
        for case in getattr(node, "cases", []):
            yield from _statements(case.body)


@functools.cache
def _imports(name: str, path: Path) -> list[tuple[str, str, int]]:
    """(module imported, name taken from it or "", line) for every import anywhere in the file,
    relative imports resolved; a module imported by name (``from plans.kinematics import
    exact``) is the module itself."""
    tree = ast.parse(path.read_text(encoding="utf-8"))
    package = name.split(".") if path.name == "__init__.py" else name.split(".")[:-1]
    out = []
    for node in _statements(tree.body):
        if isinstance(node, ast.Import):
            out += [(a.name, "", node.lineno) for a in node.names]
        elif isinstance(node, ast.ImportFrom):
            if node.level:
                base = package[:len(package) - node.level + 1]
                mod = ".".join(base + ([node.module] if node.module else []))
            else:
                mod = node.module or ""
            for a in node.names:
                sub = f"{mod}.{a.name}"
                out.append((sub, "", node.lineno) if sub in MODULES else (mod, a.name, node.lineno))
    return out


def _ours(mod: str) -> str | None:
    """The module of ours that an import loads (a name inside a package: the package)."""
    while mod and mod not in MODULES:
        mod = mod.rpartition(".")[0]
    return mod or None


def _room(mod: str) -> str:
    """plans.kinematics.exact -> plans.kinematics; plans.cli -> plans; drawings.note.x -> drawings.note."""
    parts = mod.split(".")
    is_package = MODULES[mod].name == "__init__.py"
    return ".".join(parts[:2]) if len(parts) > 2 or (len(parts) == 2 and is_package) else parts[0]


def _graph(across: bool = False) -> dict[str, set[str]]:
    """Module -> the modules of its room it imports (``across``: of any room)."""
    graph: dict[str, set[str]] = {m: set() for m in MODULES}
    for m, p in MODULES.items():
        for mod, _, _ in _imports(m, p):
            dep = _ours(mod)
            if dep is not None and dep != m and (across or _room(dep) == _room(m)):
                graph[m].add(dep)
    return graph


def _cycles(graph: dict[str, set[str]]) -> list[list[str]]:
    """The strongly connected components of more than one module (Tarjan, iterative)."""
    index: dict[str, int] = {}
    low: dict[str, int] = {}
    stack: list[str] = []
    on: set[str] = set()
    out: list[list[str]] = []
    for start in graph:
        if start in index:
            continue
        work = [(start, iter(sorted(graph[start])))]
        index[start] = low[start] = len(index)
        stack.append(start)
        on.add(start)
        while work:
            v, it = work[-1]
            w = next(it, None)
            if w is not None:
                if w not in index:
                    index[w] = low[w] = len(index)
                    stack.append(w)
                    on.add(w)
                    work.append((w, iter(sorted(graph[w]))))
                elif w in on:
                    low[v] = min(low[v], index[w])
                continue
            work.pop()
            if work:
                low[work[-1][0]] = min(low[work[-1][0]], low[v])
            if low[v] == index[v]:
                comp = []
                while True:
                    w = stack.pop()
                    on.discard(w)
                    comp.append(w)
                    if w == v:
                        break
                if len(comp) > 1:
                    out.append(sorted(comp))
    return out


def test_the_cycle_finder_finds_a_cycle_and_a_loop_of_three():
    g = {"a": {"b"}, "b": {"c"}, "c": {"a"}, "d": {"a"}, "e": {"f"}, "f": {"e"}, "g": set()}
    assert sorted(_cycles(g)) == [["a", "b", "c"], ["e", "f"]]
    assert _cycles({"a": {"b"}, "b": set()}) == []


def test_rooms_are_read_as_the_packages_are_laid_out():
    assert _room("plans.kinematics.exact") == "plans.kinematics"
    assert _room("plans.kinematics") == "plans.kinematics"
    assert _room("plans.cli") == "plans"
    assert _room("drawings.linkage.panels") == "drawings.linkage"
    assert _room("drawings.cli") == "drawings"
    assert _room("drawings.note.figures") == "drawings.note"
    # lazy and TYPE_CHECKING imports are edges too
    assert "plans.kinematics.accelerations" in _graph()["plans.kinematics.construction"]


def test_no_import_cycle_inside_a_room():
    assert _cycles(_graph()) == []


def test_no_import_cycle_among_all_the_modules():
    """Across rooms too: no module reaches itself through the modules it imports (the scene's
    reader, say, never through the kinematics that places its positions)."""
    assert _cycles(_graph(across=True)) == []


def test_no_private_name_crosses_modules():
    found = []
    for m, p in MODULES.items():
        whole = set()  # local names of our modules imported whole
        for mod, name, line in _imports(m, p):
            if _ours(mod) is None:
                continue
            if name.startswith("_") and not name.startswith("__"):
                found.append(f"{p.relative_to(ROOT)}:{line}: {name} from {mod}")
            if mod in MODULES and not name:
                whole.add(mod.rpartition(".")[2])
        text = p.read_text(encoding="utf-8")
        for alias in sorted(whole):
            found += [f"{p.relative_to(ROOT)}: {alias}.{hit}" for hit in re.findall(rf"\b{alias}\.(_[A-Za-z]\w*)", text)
                      if not hit.startswith("__")]
    assert found == []


@pytest.mark.parametrize("name", ["private", "cycle", "cycle across rooms"])
def test_the_checks_see_what_they_forbid(name, tmp_path, monkeypatch):
    """A private name taken across modules, a lazy import closing a loop inside a room, and a
    TYPE_CHECKING import closing one through another room, are found."""
    pkg = tmp_path / "plans" / "room"
    other = tmp_path / "plans" / "other"
    for folder in (pkg, other):
        folder.mkdir(parents=True)
        (folder / "__init__.py").write_text("")
    (tmp_path / "plans" / "__init__.py").write_text("")
    (pkg / "a.py").write_text({"private": "from plans.room.b import _hidden\n",
                               "cycle": "def f():\n    from plans.room import b\n",
                               "cycle across rooms": "from plans.other.c import g\n"}[name])
    (pkg / "b.py").write_text("_hidden = 1\n" if name == "private" else "from plans.room.a import f\n")
    (other / "c.py").write_text("from typing import TYPE_CHECKING\nif TYPE_CHECKING:\n    from plans.room.b import x\n")
    mods = {"plans": tmp_path / "plans" / "__init__.py", "plans.room": pkg / "__init__.py",
            "plans.room.a": pkg / "a.py", "plans.room.b": pkg / "b.py",
            "plans.other": other / "__init__.py", "plans.other.c": other / "c.py"}
    monkeypatch.setitem(globals(), "MODULES", mods)
    if name == "cycle":
        assert _cycles(_graph()) == [["plans.room.a", "plans.room.b"]]
    elif name == "cycle across rooms":
        assert _cycles(_graph()) == []  # inside each room no loop
        assert _cycles(_graph(across=True)) == [["plans.other.c", "plans.room.a", "plans.room.b"]]
        assert _cycles(_rooms_graph()) == [["plans.other", "plans.room"]]
    else:
        assert _imports("plans.room.a", pkg / "a.py") == [("plans.room.b", "_hidden", 1)]


#: The exact solver's ways to run (closed forms over arrays, the same in Python numbers, the
#: usual crank's fast paths, the triads), behind one entry: :func:`plans.kinematics.exact.solve`.
EXACT_SOLVERS = {"plans.kinematics.assur", "plans.kinematics.context", "plans.kinematics.fast",
                 "plans.kinematics.fast_arrays", "plans.kinematics.triad_exact"}


def test_the_exact_solvers_have_one_entry():
    """Nothing but :mod:`plans.kinematics.exact` (and the solvers among themselves) imports
    the exact solvers: every reader solves through ``exact.solve``."""
    outside = sorted(f"{m} imports {dep}" for m, p in MODULES.items()
                     if m not in EXACT_SOLVERS | {"plans.kinematics.exact"}
                     for dep in {_ours(mod) for mod, _, _ in _imports(m, p)} & EXACT_SOLVERS)
    assert outside == []
    assert EXACT_SOLVERS <= set(MODULES)


def test_no_module_is_longer_than_a_reader_takes_in():
    long = sorted(f"{p.relative_to(ROOT)}: {n} lines" for p in MODULES.values()
                  if (n := len(p.read_text(encoding="utf-8").splitlines())) > LONGEST)
    assert long == []


def _room_of(mod: str) -> str:
    """A room for the graph between rooms: a sub-package, or a top-level module of its own
    (plans.solution, plans.errors: the shared modules and the composers above the rooms)."""
    room = _room(mod)
    return mod if room in PACKAGES else room


def _rooms_graph() -> dict[str, set[str]]:
    """Room -> the rooms its modules import (lazy and TYPE_CHECKING imports counted)."""
    graph: dict[str, set[str]] = {}
    for m, p in MODULES.items():
        graph.setdefault(_room_of(m), set())
        for mod, _, _ in _imports(m, p):
            dep = _ours(mod)
            if dep is not None and _room_of(dep) != _room_of(m):
                graph[_room_of(m)].add(_room_of(dep))
    return graph


#: The rooms at the bottom of the pipeline and the other kinds' rooms: each imports only rooms
#: below it.
BASE_ROOMS = ("plans.scene", "plans.kinematics", "plans.forces", "plans.balancing", "plans.gears",
              "plans.cams", "drawings.paper")


def test_no_import_cycle_between_rooms():
    """The rooms (sub-packages, and the top-level modules each a room of its own: the shared
    modules and the composers above the rooms) form a DAG: each imports only rooms below it."""
    assert _cycles(_rooms_graph()) == []


#: The modules above the rooms that compose them (a solve, its outputs, the tables read for
#: it, the commands).
COMPOSERS = {"plans.solution", "plans.results", "plans.tables", "plans.cli", "plans.check_command"}


def test_the_base_rooms_import_only_what_lies_below_them():
    graph = _rooms_graph()
    for room in BASE_ROOMS:
        packages = {r for r in graph[room] if MODULES[r].name == "__init__.py"}
        assert packages <= set(BASE_ROOMS) and not graph[room] & COMPOSERS, (room, sorted(graph[room]))
    assert {"plans.forces", "plans.cycle"} & graph["plans.scene"] == set()  # the tables: plans.tables
    # the scene reads, and validates, what the kinematics places (plans.kinematics.placing)
    assert graph["plans.scene"] <= {m for m in MODULES if _room(m) == "plans"}
    assert "plans.scene" in graph["plans.kinematics"]


def test_the_upper_rooms_lie_in_order():
    """What closed loops among the upper rooms stays open: the cycle's check is the check
    room's, the check command is above the group's gradebook and sheets, the drawings of the
    cycle take their panels from the paper toolkit, not from the linkage's sheets."""
    graph = _rooms_graph()
    assert "plans.check" not in graph["plans.cycle"]
    assert {"plans.group", "plans.accuracy", "plans.check_command"} & graph["plans.check"] == set()
    assert "drawings.linkage" not in graph["drawings.cycle"]


def test_the_rooms_graph_sees_a_lazy_import_between_rooms(tmp_path, monkeypatch):
    """A lazy import from one room back into another that imports it is a cycle of rooms."""
    for room in ("low", "high"):
        (tmp_path / "plans" / room).mkdir(parents=True)
        (tmp_path / "plans" / room / "__init__.py").write_text("")
    (tmp_path / "plans" / "__init__.py").write_text("")
    (tmp_path / "plans" / "low" / "a.py").write_text("def f():\n    from plans.high import b\n")
    (tmp_path / "plans" / "high" / "b.py").write_text("from plans.low.a import f\n")
    mods = {"plans": tmp_path / "plans" / "__init__.py",
            "plans.low": tmp_path / "plans" / "low" / "__init__.py",
            "plans.high": tmp_path / "plans" / "high" / "__init__.py",
            "plans.low.a": tmp_path / "plans" / "low" / "a.py", "plans.high.b": tmp_path / "plans" / "high" / "b.py"}
    monkeypatch.setitem(globals(), "MODULES", mods)
    assert _cycles(_rooms_graph()) == [["plans.high", "plans.low"]]
