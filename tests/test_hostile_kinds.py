"""The promise on bad input over every file kind and command: gears, cams, engines, the
dynamics of a scene and the cycle check files, as well as linkage scenes.

Each case takes a sample file of one kind, sets one field to a hostile value (text, a
boolean, nan, inf, 1e300, 1e-300, a list, a table) or breaks its top level (format, kind,
an unknown key), runs the command in-process and asserts the promise: status 2, exactly one
line ``plans: error: FILE: FIELD: ...`` naming the field, no traceback, and no file created
or changed anywhere in the working folder.
"""

from __future__ import annotations

import math
import re
import tomllib
from collections.abc import Callable
from dataclasses import dataclass
from pathlib import Path
from typing import Any

import pytest

from drawings.cli import main
from plans.accuracy.fuzz import to_toml

SAMPLES = Path(__file__).resolve().parent.parent / "samples"
OUT = ("--json", "{dir}/out/r.json")

#: base name -> (sample, command)
BASES: dict[str, tuple[str, tuple[str, ...]]] = {
    "gears": ("gears/seed_train.toml", ("gears", "{f}", *OUT)),
    "planetary": ("gears/planetary_2kh.toml", ("gears", "{f}", *OUT)),
    "cam": ("cams/seed001_valve_cam.toml", ("cam", "{f}", *OUT)),
    "osc": ("cams/oscillating_cycloidal.toml", ("cam", "{f}", *OUT)),
    "flat": ("cams/flat_face_poly345.toml", ("cam", "{f}", *OUT)),
    "engine": ("engines/v_twin.toml", ("balance", "{f}", *OUT)),
    "inline4": ("engines/inline4.toml", ("balance", "{f}", *OUT)),
    "dynamics": ("dynamics_slider_crank.toml", ("solve", "{f}", *OUT)),
    "fourbar": ("four_bar.toml", ("solve", "{f}", *OUT)),
    "cycle": ("checks/dynamics_seed004.toml", ("check", "{f}", *OUT)),
}

HOSTILE: dict[str, Any] = {"text": "abc", "bool": True, "nan": math.nan, "inf": -math.inf, "huge": 1e300,
                           "tiny": 1e-300, "list": [1.0], "table": {"a": 1}}


@dataclass(frozen=True)
class Case:
    id: str
    base: str
    edit: Callable[[dict[str, Any]], Any]
    expect: tuple[str, ...]
    argv: tuple[str, ...] | None = None  # instead of the base's command


CASES: list[Case] = []


def _set(path: tuple[Any, ...], value: Any) -> Callable[[dict[str, Any]], None]:
    def edit(data: dict[str, Any]) -> None:
        node = data
        for k in path[:-1]:
            node = node[k]
        node[path[-1]] = value
    return edit


def _field(path: tuple[Any, ...]) -> str:
    out = ""
    for k in path:
        out += f"[{k}]" if isinstance(k, int) else (f".{k}" if out else k)
    return out


def numbers(base: str, *paths: tuple[Any, ...], skip: tuple[str, ...] = ()) -> None:
    """Every hostile value in every one of these number fields."""
    for path in paths:
        field = _field(path)
        for name, value in HOSTILE.items():
            if name not in skip:
                CASES.append(Case(f"{base}-{field}-{name}", base, _set(path, value), (field,)))


def case(id: str, base: str, edit: Callable[[dict[str, Any]], Any], *expect: str,
         argv: tuple[str, ...] | None = None) -> None:
    CASES.append(Case(id, base, edit, expect, argv))


def _del(*path: Any) -> Callable[[dict[str, Any]], None]:
    def edit(data: dict[str, Any]) -> None:
        node = data
        for k in path[:-1]:
            node = node[k]
        del node[path[-1]]
    return edit


# --------------------------------------------------------------------------- numbers of every kind
numbers("gears", ("module",), ("pressure_angle_deg",), ("addendum",), ("clearance",), ("gears", 0, "z"),
        ("gears", 0, "x"), ("shafts", 0, "speed_rpm"))
numbers("planetary", ("module",), ("gears", 2, "z"), ("synthesis", "ratio"), ("synthesis", "tolerance"),
        ("shafts", 0, "speed_rpm"))
numbers("cam", ("offset",), ("roller",), skip=("tiny",))  # an offset or roller of dust is 0
numbers("cam", ("base_radius",), ("omega_rpm",), ("pressure_angle_rise_deg",),
        ("pressure_angle_return_deg",), ("step_deg",), ("phases", 0, "angle_deg"), ("phases", 0, "stroke"))
numbers("osc", ("arm",), ("pivot",), ("phases", 0, "swing_deg"))
numbers("engine", ("r",), ("lambda",), ("omega_rpm",), ("m_rot",), ("m_rec",))
numbers("engine", ("cylinders", 1, "z"), ("cylinders", 1, "bank_deg"), skip=("tiny",))  # dust is 0
numbers("dynamics", ("dynamics", "rotor_inertia"), ("dynamics", "delta"), ("links", "2", "mass"),
        ("links", "2", "inertia"), ("driver", "omega"), ("loads", "gas", 0, "area"))
numbers("cycle", ("cycle", "rule_pct"), ("cycle", "segment_mm"), ("cycle", "velocity_scale", "mu"),
        ("cycle", "values", "I_pr", 3), ("cycle", "measured", "pc", 2))
for _name, _value in HOSTILE.items():
    CASES.append(Case(f"cycle-cycle.flywheel.inertia-{_name}", "cycle",
                      _set(("cycle", "flywheel"), {"inertia": _value}), ("cycle.flywheel.inertia",)))

# --------------------------------------------------------------------------- the top level of every kind
for base in BASES:
    case(f"{base}-format-2", base, _set(("format",), 2), "format")
    case(f"{base}-format-true", base, _set(("format",), True), "format")
    case(f"{base}-format-text", base, _set(("format",), "1"), "format")
    case(f"{base}-format-missing", base, _del("format"), "format")
    case(f"{base}-unknown-key", base, _set(("titel",), "x"), "titel", "unknown key", "title")
    case(f"{base}-kind-unknown", base, _set(("kind",), "gear"), "kind")
    case(f"{base}-kind-number", base, _set(("kind",), 3), "kind")

#: each kind's file run through every other kind's command: named as the kind it is
_COMMANDS = {"gears": "gears", "cam": "cam", "engine": "balance", "fourbar": "solve", "cycle": "check"}
_NAMES = {"gears": "a gears file", "cam": "a cam file", "engine": "an engine file", "fourbar": "a linkage scene",
          "cycle": "a check file"}
for base, name in _NAMES.items():
    for other, command in _COMMANDS.items():
        if other != base:
            case(f"{base}-through-{command}", base, lambda d: None, "kind", f"this is {name}",
                 argv=(command, "{f}", *OUT))

# --------------------------------------------------------------------------- unknown keys in nested tables
case("gears-gear-unknown", "gears", _set(("gears", 0, "zz"), 3), "gears[0].zz", "did you mean 'z'")
case("gears-mesh-unknown", "gears", _set(("meshes", 0, "gear"), ["1", "2"]), "meshes[0].gear", "gears")
case("gears-modul", "gears", lambda d: d.update(modul=d.pop("module")), "modul", "did you mean 'module'")
case("cam-phase-unknown", "cam", _set(("phases", 0, "strok"), 3), "phases[0].strok", "did you mean 'stroke'")
case("cam-omega-rmp", "cam", lambda d: d.update(omega_rmp=d.pop("omega_rpm")), "omega_rmp", "omega_rpm")
case("engine-cyl-unknown", "engine", _set(("cylinders", 0, "crank"), 3), "cylinders[0].crank", "crank_deg")
case("dynamics-unknown", "dynamics", _set(("dynamics", "rotor"), 3), "dynamics.rotor", "rotor_inertia")
case("cycle-unknown", "cycle", _set(("cycle", "rule"), 3), "cycle.rule", "rule_pct")
case("cycle-top-unknown", "cycle", _set(("scenes",), "x"), "scenes", "scene")
case("cycle-not-a-table", "cycle", _set(("cycle",), 3), "cycle")
case("cycle-flywheel-list", "cycle", _set(("cycle", "flywheel"), [1]), "cycle.flywheel")
case("cycle-flywheel-extra", "cycle", _set(("cycle", "flywheel"), {"inertia": 2, "mass": 1}), "cycle.flywheel")
case("cycle-student-number", "cycle", _set(("student",), 3), "student")

# --------------------------------------------------------------------------- the crash paths once found
case("cam-table-rows-too-close", "cam", lambda d: d["phases"][0].update(
    law="table", table=[[0, 0], [5e-324, 0], [30, 5], [65, 10]]), "phases[0].table", "apart")
case("cam-base-radius-tiny-mm", "cam", _set(("base_radius",), 1e-300), "base_radius")
case("cam-omega-5e-324", "cam", _set(("omega_rpm",), 5e-324), "omega_rpm")
case("cam-omega-tiny-draw", "cam", _set(("omega_rpm",), 1e-9), "omega_rpm", argv=("draw", "{f}", "-o", "{dir}/s"))
case("gears-module-4e-9", "gears", _set(("module",), 4e-9), "module")
case("gears-speed-on-no-shaft", "gears", lambda d: d["shafts"].append({"name": "9", "speed_rpm": 100}),
     "shafts")
case("engine-crank-deg-text", "inline4", lambda d: d.update(crank_deg=[0, "x", 0, 0]) or d.pop("firing_order", None),
     "crank_deg")
case("engine-lambda-dust", "engine", _set(("lambda",), 1e-11), "lambda", "rod")  # not links.2.length
case("dynamics-delta-huge", "dynamics", _set(("dynamics", "delta"), 5.0), "dynamics.delta")
case("fourbar-phi-1.5e300", "fourbar", lambda d: d["driver"].update(phi_deg=[1.5e300]) or d["driver"].pop("positions"),
     "driver.phi_deg", "1e+300")

# --------------------------------------------------------------------------- drawing and the demonstration
_DRAW = ("draw", "{f}", "-o", "{dir}/sheets")
_FIRST = {"gears": ("module",), "planetary": ("module",), "cam": ("base_radius",), "osc": ("arm",),
          "flat": ("base_radius",), "engine": ("r",), "inline4": ("m_rot",), "dynamics": ("dynamics", "delta"),
          "fourbar": ("links", "1", "length")}
for base, path in _FIRST.items():
    for name in ("text", "nan", "huge", "tiny"):
        case(f"{base}-draw-{_field(path)}-{name}", base, _set(path, HOSTILE[name]), _field(path), argv=_DRAW)
    case(f"{base}-draw-format-2", base, _set(("format",), 2), "format", argv=_DRAW)
    case(f"{base}-draw-unknown-key", base, _set(("titel",), "x"), "titel", argv=_DRAW)
    case(f"{base}-draw-sheet-A9", base, lambda d: None, "sheet", argv=(*_DRAW, "--sheet", "A9"))
    case(f"{base}-draw-output-is-input", base, lambda d: None, "--output", argv=("draw", "{f}", "-o", "{f}"))
for base in ("dynamics", "fourbar"):
    _DEMO = ("demo", "{f}", "-o", "{dir}/page.html")
    case(f"{base}-demo-format-2", base, _set(("format",), 2), "format", argv=_DEMO)
    case(f"{base}-demo-driver-omega-nan", base, _set(("driver", "omega_rpm" if base == "fourbar" else "omega"),
                                                     math.nan), "driver.omega", argv=_DEMO)
    case(f"{base}-demo-is-input", base, lambda d: None, "input file", argv=("demo", "{f}", "-o", "{dotf}"))
    case(f"{base}-demo-phi-nan", base, lambda d: None, "--phi", argv=(*_DEMO, "--phi", "nan"))
    case(f"{base}-demo-phi-huge", base, lambda d: None, "--phi", argv=(*_DEMO, "--phi", "1e400"))
for kind in ("gears", "cam", "engine"):
    case(f"{kind}-demo-wrong-kind", kind, lambda d: None, "kind", argv=("demo", "{f}", "-o", "{dir}/page.html"))
case("cycle-csv-is-input", "cycle", lambda d: None, "input file", argv=("check", "{f}", "--csv", "{dotf}"))

# --------------------------------------------------------------------------- outputs
for base, (_, argv) in BASES.items():
    case(f"{base}-json-is-input", base, lambda d: None, "input file", "refusing",
         argv=(argv[0], "{f}", "--json", "{f}"))
    case(f"{base}-json-is-input-dot", base, lambda d: None, "input file", "refusing",
         argv=(argv[0], "{f}", "--json", "{dotf}"))
    case(f"{base}-json-is-folder", base, lambda d: None, "folder", argv=(argv[0], "{f}", "--json", "{dir}/out"))
    case(f"{base}-json-no-folder", base, lambda d: None, "nodir", argv=(argv[0], "{f}", "--json", "{dir}/nodir/r.json"))


def _snapshot(folder: Path) -> dict[str, bytes]:
    return {str(p.relative_to(folder)): p.read_bytes() for p in sorted(folder.rglob("*")) if p.is_file()} | {
        str(p.relative_to(folder)) + "/": b"" for p in folder.rglob("*") if p.is_dir()}


def _run(argv: list[str]) -> int:
    try:
        return main(argv)
    except SystemExit as exc:
        return exc.code if isinstance(exc.code, int) else 1


def test_the_table_is_large_and_covers_every_kind():
    assert len(CASES) >= 300
    assert len({c.id for c in CASES}) == len(CASES)
    assert {c.base for c in CASES} == set(BASES)


def _file(base: str, tmp: Path, edit: Callable[[dict[str, Any]], Any]) -> Path:
    sample = SAMPLES / BASES[base][0]
    data = tomllib.loads(sample.read_text(encoding="utf-8"))
    if isinstance(data.get("scene"), str):  # a check file names its scene beside it
        data["scene"] = str((sample.parent / data["scene"]).resolve())
    edit(data)
    path = tmp / f"{base}.toml"
    path.write_text(to_toml(data), encoding="utf-8")
    return path


@pytest.mark.parametrize("case", CASES, ids=[c.id for c in CASES])
def test_bad_input_of_every_kind_keeps_the_promise(case: Case, tmp_path: Path,
                                                    capsys: pytest.CaptureFixture[str]) -> None:
    (tmp_path / "out").mkdir()
    f = _file(case.base, tmp_path, case.edit)
    before = _snapshot(tmp_path)
    argv = [a.format(f=f, dir=tmp_path, dotf=f"{tmp_path}/./out/../{f.name}")
            for a in (case.argv or BASES[case.base][1])]
    status = _run(argv)
    out, err = capsys.readouterr()
    lines = err.splitlines()
    assert status == 2, f"status {status}; stderr: {err!r}"
    assert len(lines) == 1, f"expected one line on stderr, got {err!r}"
    assert lines[0].startswith("plans: error: "), lines[0]
    assert not re.search("[А-Яа-яЁё]", re.sub(r"'[^']*'", "", lines[0])), "a Russian word in English"
    assert "Traceback" not in err and "Traceback" not in out
    for word in case.expect:
        assert _named(word) in lines[0], f"{_named(word)!r} not in {lines[0]!r}"
    assert len(lines[0]) < 400, "a short line"
    assert _snapshot(tmp_path) == before, "files were created or changed"


@pytest.mark.parametrize("base", sorted(BASES))
def test_every_sample_is_accepted_as_written_back(base: str, tmp_path: Path, capsys) -> None:
    """The table's base files are good: each case fails for its one edit only."""
    (tmp_path / "out").mkdir()
    f = _file(base, tmp_path, lambda d: None)
    argv = [a.format(f=f, dir=tmp_path) for a in BASES[base][1]]
    assert _run(argv) == 0, capsys.readouterr().err
    assert (tmp_path / "out" / "r.json").is_file()


#: Extreme files that are good: accepted, every number written finite.
ACCEPTED: dict[str, tuple[str, Callable[[dict[str, Any]], Any]]] = {
    "cam-table-overshoot": ("cam", lambda d: d["phases"][0].update(
        law="table", table=[[0, 0], [20, 60], [45, 40], [65, 10]])),
    "cam-table-overshoot-huge": ("cam", lambda d: d["phases"][0].update(
        law="table", table=[[0, 0], [20, 6e5], [45, -4e5], [65, 10]])),
    "cycle-student-1e12-against-zero": ("cycle", lambda d: d["cycle"]["values"]["M_pr"].__setitem__(0, 1e12)),
    "cycle-flywheel-given": ("cycle", _set(("cycle", "flywheel"), {"inertia": 12.5})),
    "engine-crank-deg-huge": ("inline4", lambda d: d.update(crank_deg=[0, 1.234567e21, 180, 0])
                              or d.pop("firing_order", None)),
    "fourbar-phi-1e300": ("fourbar", lambda d: d["driver"].update(phi_deg=[1e300, 1.234567e21])
                          or d["driver"].pop("positions")),
    "fourbar-phi-ref-1e300": ("fourbar", _set(("driver", "phi_ref_deg"), 1e300)),
}


@pytest.mark.parametrize("name", sorted(ACCEPTED))
def test_extreme_good_files_give_finite_numbers(name: str, tmp_path: Path, capsys) -> None:
    import json

    base, edit = ACCEPTED[name]
    (tmp_path / "out").mkdir()
    f = _file(base, tmp_path, edit)
    argv = [a.format(f=f, dir=tmp_path) for a in BASES[base][1]]
    assert _run(argv) == 0, capsys.readouterr().err
    text = (tmp_path / "out" / "r.json").read_text(encoding="utf-8")

    def refuse(word: str) -> float:
        raise AssertionError(f"{word} in the JSON of {name}")

    json.loads(text, parse_constant=refuse)


def _named(text: str) -> str:
    """An expected field as the message names it: an entry of an array of tables 1-based
    (``gears[0].z`` is ``[[gears]] entry 1, z``)."""
    from plans.errors import field_name

    head, sep, rest = text.partition(": ")
    return field_name(head) + sep + rest
