"""What makes ``plans solve`` start and finish fast changes no reading: the closed-form
intersection that closes a force polygon is shapely's (the independent oracle here) to the
rounding of the drawn lines, with the same answer where the lines are (nearly) parallel;
the polygons of every sample at every position are the ones shapely closes; the protocol's
sentences are the ones Python's own ``string.Formatter`` writes, in both languages."""

from __future__ import annotations

import cmath
import math
import re
import string
from pathlib import Path

import numpy as np
import pytest
import shapely

from plans.forces import polygons
from plans.forces.analysis import kinetostatics
from plans.kinematics.exact import solve
from plans.kinematics.placing import load_scene
from plans.lines import along, cross, meet
from plans.phrases import PHRASES, UNITS_RU, Phrase, number, phrase

SAMPLES = sorted((Path(__file__).resolve().parent.parent / "samples").glob("*.toml"))


def _segment(p: complex, d: complex, reach: float) -> shapely.LineString:
    a, b = p - reach * d, p + reach * d
    return shapely.LineString([(a.real, a.imag), (b.real, b.imag)])


def shapely_closing(e: complex, d_end: complex, s: complex, d_start: complex, reach: float) -> complex | None:
    """The two construction lines drawn as segments ``reach`` either side of their points and
    intersected by shapely; None where they do not cross in one point."""
    hit = _segment(e, d_end, reach).intersection(_segment(s, d_start, reach))
    if isinstance(hit, shapely.Point) and not hit.is_empty:
        return complex(hit.x, hit.y)
    return None


def _lines(rng: np.random.Generator, n: int, near: bool) -> list[tuple[complex, complex, complex, complex, float]]:
    """Random construction lines in plan mm: any two, or two nearly parallel (1e-12..1e-2 rad)
    with the second point close to the first line, so that they still meet on the sheet."""
    out = []
    for _ in range(n):
        e = complex(*rng.uniform(-150.0, 150.0, 2))
        a = rng.uniform(0.0, 2 * math.pi)
        d_end = cmath.exp(1j * a)
        if near:
            s = e + rng.uniform(-100.0, 100.0) * d_end + 1j * d_end * 10 ** rng.uniform(-10.0, 1.0)
            d_start = cmath.exp(1j * (a + rng.choice([0.0, math.pi]) + rng.choice([-1.0, 1.0])
                                      * 10 ** rng.uniform(-12.0, -2.0)))
        else:
            s = complex(*rng.uniform(-150.0, 150.0, 2))
            d_start = cmath.exp(1j * rng.uniform(0.0, 2 * math.pi))
        out.append((e, d_end, s, d_start, 10.0 * (max(abs(e), abs(s)) + 100.0)))
    return out


@pytest.mark.parametrize("near", [False, True], ids=["random", "nearly parallel"])
def test_closing_point_is_shapelys_intersection(near):
    met = 0
    for e, d_end, s, d_start, reach in _lines(np.random.default_rng(7 + near), 3000, near):
        ours, theirs = polygons.closing_point(e, d_end, s, d_start, reach), shapely_closing(e, d_end, s, d_start, reach)
        assert (ours is None) == (theirs is None), (e, d_end, s, d_start)
        if ours is None or theirs is None:
            continue
        met += 1
        # shapely intersects the segments' rounded ends (|end| ~ reach): that rounding moves
        # the point by ~1e-16·reach/sin(angle between the lines), no more
        sin = abs(cross(d_end, d_start))
        assert abs(ours - theirs) <= 1e-12 * reach * (1.0 if not near else 1e-3 / sin), (e, d_end, s, d_start)
    assert met > 1000  # most pairs do meet on the sheet


def test_parallel_and_coincident_lines_do_not_meet_in_a_point():
    d = cmath.exp(0.3j)
    for e, s, d2 in ((0j, 5j * d, d), (0j, 40 * d, d), (0j, 40 * d, -d), (1 + 1j, 1 + 1j + 1e-3j * d, d),
                     (0j, 10 * d + 1j * d, d * cmath.exp(1e-9j))):  # the last meets far beyond the drawn lines
        assert polygons.closing_point(e, d, s, d2, 1000.0) is None
        assert shapely_closing(e, d, s, d2, 1000.0) is None


def test_meet_over_arrays_is_shapelys_intersection():
    rng = np.random.default_rng(3)
    n = 200
    p1, p2 = (rng.uniform(-1, 1, n) + 1j * rng.uniform(-1, 1, n) for _ in range(2))
    d1, d2 = (np.exp(1j * rng.uniform(0, 2 * math.pi, n)) for _ in range(2))
    t1, t2 = along(p1, d1, p2, d2)
    x = meet(p1, d1, p2, d2)
    assert np.allclose(p1 + t1 * d1, p2 + t2 * d2, rtol=0, atol=1e-9 * np.max(np.abs(x)))
    for k in range(n):
        if abs(cross(d1[k], d2[k])) < 1e-3:
            continue
        reach = 2.0 * (abs(x[k]) + 2.0)
        hit = shapely_closing(complex(p1[k]), complex(d1[k]), complex(p2[k]), complex(d2[k]), reach)
        assert hit is not None and abs(hit - x[k]) <= 1e-12 * reach


@pytest.mark.parametrize("path", SAMPLES, ids=[p.stem for p in SAMPLES])
def test_every_force_polygon_closes_where_shapely_closes_it(path, monkeypatch):
    """Every polygon of every position: the same vertices (to the rounding of the drawn lines),
    the same notes, the same vectors read off to the ruler."""
    scene = load_scene(path)
    if not scene.wants("force_polygons"):
        pytest.skip("no force polygons asked for")
    fa, _ = kinetostatics(scene, solve(scene))
    ours = [polygons.force_polygons(fa, k) for k in range(fa.n)]
    monkeypatch.setattr(polygons, "closing_point", shapely_closing)
    theirs = [polygons.force_polygons(fa, k) for k in range(fa.n)]
    for a_k, b_k in zip(ours, theirs, strict=True):
        for a, b in zip(a_k, b_k, strict=True):
            assert a.plan.degenerate == b.plan.degenerate
            assert [p.name for p in a.plan.points] == [p.name for p in b.plan.points]
            size = max(a.plan.extent, 1.0)
            for p, q in zip(a.plan.points, b.plan.points, strict=True):
                assert abs(complex(*p.xy) - complex(*q.xy)) <= 1e-12 * size
            assert [a.reading(s.label) for s in a.plan.segments] == [b.reading(s.label) for s in b.plan.segments]
            assert [s.text for s in a.plan.steps] == [s.text for s in b.plan.steps]


class _Formatter(string.Formatter):
    """A phrase written by Python's own formatter: units and decimal comma in Russian, a
    phrase inside a phrase in the same language, a list of values one after another."""

    def __init__(self, lang: str) -> None:
        self.lang = lang

    def get_value(self, key, args, kwargs):
        value = kwargs[str(key)]
        if self.lang == "ru" and str(key).startswith("unit") and isinstance(value, str):
            return UNITS_RU.get(value, value)
        return value

    def format_field(self, value, format_spec):
        if isinstance(value, Phrase):
            return value.say(self.lang)
        if isinstance(value, list | tuple):
            return " ".join(self.format_field(v, format_spec) for v in value)
        if isinstance(value, float | int | np.floating | np.integer) and not isinstance(value, bool):
            return number(value, format_spec, self.lang)
        return format(value, format_spec)


def _written(p: Phrase, lang: str) -> str:
    text = _Formatter(lang).vformat(PHRASES[p.key][1 if lang == "ru" else 0], (), p.args)
    return re.sub(r"\b([FM])_bal\b", r"\1_ур", text) if lang == "ru" else text


@pytest.mark.parametrize("lang", ["en", "ru"])
def test_every_phrase_is_written_as_pythons_formatter_writes_it(lang):
    rng = np.random.default_rng(11)
    values = [0.0, -0.0, 1e-13, 12.5, -3.25e-7, 123456.789, np.float64(2.5e5), np.int64(7), 3, "m/s", "N·m",
              "F_bal", phrase("ccw"), [phrase("m_zero"), phrase("l_arm", a=1.5)]]
    for key, (en, ru) in PHRASES.items():
        names = {name for _, name, _, _ in string.Formatter().parse(en + ru) if name}
        for trial in range(6):
            args = {}
            for name in names:
                spec_numeric = any(name == nm and spec for _, nm, spec, _ in string.Formatter().parse(en + ru))
                pool = [v for v in values if not isinstance(v, str | Phrase | list)] if spec_numeric else values
                args[name] = pool[int(rng.integers(len(pool)))] if trial else float(rng.normal() * 100)
            p = phrase(key, **args)
            assert p.say(lang) == _written(p, lang), (key, args)


def _records():
    import plans.cycle.results  # noqa: F401  (every module whose classes are records)
    import plans.forces.protocol  # noqa: F401
    import plans.results  # noqa: F401
    from plans.records import MADE

    return list(MADE)


def _twin(cls):
    """The same class made by dataclass itself, the reference."""
    import dataclasses

    spec = [(f.name, f.type, dataclasses.field(default=f.default, default_factory=f.default_factory, init=f.init,
                                              repr=f.repr, hash=f.hash, compare=f.compare))
            for f in dataclasses.fields(cls)]
    ns = {"__post_init__": cls.__post_init__} if hasattr(cls, "__post_init__") else {}
    twin = dataclasses.make_dataclass(cls.__name__, spec, namespace=ns, frozen=True, slots=hasattr(cls, "__slots__"))
    twin.__qualname__ = cls.__qualname__
    return twin


def _hash(x):
    try:
        return hash(x)
    except TypeError as exc:  # a field that is a dict or a list: unhashable, as with dataclass
        return str(exc)


@pytest.mark.parametrize("cls", _records(), ids=lambda c: f"{c.__module__}.{c.__name__}")
def test_every_record_behaves_as_dataclass_makes_it(cls):
    import copy
    import dataclasses
    import inspect
    import pickle

    twin = _twin(cls)
    assert len(_records()) >= 30
    assert str(inspect.signature(cls)) == str(inspect.signature(twin))
    assert hasattr(cls, "__slots__") == hasattr(twin, "__slots__")
    assert cls.__match_args__ == twin.__match_args__
    fs = [f for f in dataclasses.fields(cls) if f.init]
    required = [f for f in fs if f.default is dataclasses.MISSING and f.default_factory is dataclasses.MISSING]
    args = {f.name: (k, k + 1) for k, f in enumerate(required)}
    a, b = cls(**args), twin(**args)
    assert repr(a) == repr(b) and a == cls(**args) and _hash(a) == _hash(cls(**args)) == _hash(b)
    for f in dataclasses.fields(cls):
        assert getattr(a, f.name) == getattr(b, f.name)
        with pytest.raises(dataclasses.FrozenInstanceError):
            setattr(a, f.name, 1)
        with pytest.raises(dataclasses.FrozenInstanceError):
            delattr(a, f.name)
    for f in fs:  # one field changed: equal, hashed and shown as the twin has it
        changed = {**args, f.name: (-2, -1)}
        x, y = cls(**changed), twin(**changed)
        assert (x == a) == (y == b) and (_hash(x) == _hash(a)) == (_hash(y) == _hash(b)) and repr(x) == repr(y)
        assert dataclasses.replace(a, **{f.name: (-2, -1)}) == x
    assert a != b and a.__eq__(b) is NotImplemented  # another class, as between two dataclasses
    assert pickle.loads(pickle.dumps(a)) == a and copy.deepcopy(a) == a and copy.copy(a) == a
    assert dataclasses.asdict(a) == dataclasses.asdict(b)


def test_the_start_measure_stops_the_command_when_solving_begins():
    """What ``plans bench`` times as the start of ``plans solve``: the installed console
    command, stopped the moment the scene, read, is handed to the solver (nothing printed);
    a scene that cannot be read is refused before that point, so its reading is counted."""
    import subprocess
    import sys

    from plans.accuracy import speed

    root = Path(__file__).resolve().parent.parent
    code = speed._UNTIL_SOLVING.format(entry="drawings.console")
    got = subprocess.run([sys.executable, "-c", code, "solve", "samples/slider_crank.toml"], cwd=root,
                         capture_output=True, text=True, timeout=120)
    assert got.returncode == 0 and got.stdout == "" and got.stderr == "", got
    bad = subprocess.run([sys.executable, "-c", code, "solve", "samples/no_such_scene.toml"], cwd=root,
                         capture_output=True, text=True, timeout=120)
    assert bad.returncode == 2 and "no_such_scene.toml" in bad.stderr
    whole = subprocess.run([sys.executable, "-c", speed._CONSOLE.format(entry="drawings.console"), "solve",
                            "samples/slider_crank.toml"], cwd=root, capture_output=True, text=True, timeout=120)
    assert whole.returncode == 0 and "phi = " in whole.stdout


def test_every_command_listed_by_name_is_the_one_its_module_registers():
    """``plans`` lists (or leaves out) a command without importing its module: the name and
    the help it lists are the module's own."""
    import argparse
    import importlib

    from plans import cli

    for mod, (name, text) in cli._COMMAND_NAMES.items():
        sub = argparse.ArgumentParser().add_subparsers()
        importlib.import_module(mod).register(sub)
        assert [(a.dest, a.help) for a in sub._choices_actions] == [(name, text)], mod


@pytest.mark.parametrize("argv", [["solve", "x.toml"], ["balance", "-h"], ["check", "DIR"], ["bench", "--quick"]])
def test_a_command_that_comes_first_is_parsed_as_by_the_whole_parser(argv):
    from drawings.cli import build_parser

    alone, whole = build_parser(argv), build_parser()
    assert set(alone._subparsers._group_actions[0].choices) == {argv[0]}
    if "-h" not in argv:
        def parsed(parser):
            return {k: getattr(v, "__qualname__", v) for k, v in vars(parser.parse_args(argv)).items()}

        assert parsed(alone) == parsed(whole)
