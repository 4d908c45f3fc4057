"""The promise on bad input, case by case: status 2, exactly one line
``plans: error: FILE: FIELD: ...`` on stderr naming what was wrong, no traceback, and no
file created or changed anywhere in the working folder.

Each case edits a small valid scene or check file (tests/data/hostile) in one place, runs
the command in-process, and asserts the promise plus the words that show the right field
was blamed (so a case cannot pass on some other, unrelated error).
"""

from __future__ import annotations

import re
import shutil
from collections.abc import Callable
from dataclasses import dataclass
from pathlib import Path

import pytest

from drawings.cli import main

DATA = Path(__file__).resolve().parent / "data" / "hostile"
SCENE = (DATA / "scene.toml").read_text(encoding="utf-8")
CHECK = (DATA / "check.toml").read_text(encoding="utf-8")


@dataclass(frozen=True)
class Case:
    id: str
    argv: tuple[str, ...]  # {scene} {check} {dir} are filled in
    expect: tuple[str, ...]  # words the error line must hold
    scene: Callable[[str], str | bytes] | None = None
    check: Callable[[str], str | bytes] | None = None


def sub(old: str, new: str) -> Callable[[str], str]:
    def edit(text: str) -> str:
        assert text.count(old) == 1, f"the base file must hold {old!r} once"
        return text.replace(old, new)
    return edit


def add(extra: str) -> Callable[[str], str]:
    """Tables at the end of the file."""
    return lambda text: text + "\n" + extra + "\n"


def top(extra: str) -> Callable[[str], str]:
    """Keys at the top level (before the first table)."""
    return lambda text: text.replace("format = 1\n", "format = 1\n" + extra + "\n", 1)


def raw(data: bytes) -> Callable[[str], bytes]:
    return lambda text: data


SOLVE = ("solve", "{scene}", "--json", "{dir}/out/r.json")
DRAW = ("draw", "{scene}", "-o", "{dir}/sheets")
CHECK_CMD = ("check", "{check}", "--json", "{dir}/out/c.json")

CASES: list[Case] = []


def scene(id: str, edit: Callable[[str], str | bytes], *expect: str, argv: tuple[str, ...] = SOLVE) -> None:
    CASES.append(Case(id, argv, expect, scene=edit))


def check(id: str, edit: Callable[[str], str | bytes], *expect: str, argv: tuple[str, ...] = CHECK_CMD) -> None:
    CASES.append(Case(id, argv, expect, check=edit))


def cli(id: str, argv: tuple[str, ...], *expect: str) -> None:
    CASES.append(Case(id, argv, expect))


# --------------------------------------------------------------------------- the file itself
scene("not-utf8", raw(b'format = 1\ntitle = "\xff\xfe"\n'), "not UTF-8")
scene("latin1-title", raw('format = 1\ntitle = "Шатун"\n'.encode("cp1251")), "not UTF-8")
scene("malformed", add("[links.1"), "malformed TOML")
scene("empty", raw(b""), "format")
scene("binary", raw(bytes(range(256))), "UTF-8")
scene("truncated", lambda t: t[: len(t) // 2].rsplit("\n", 3)[0] + '\nx = "', "malformed TOML")
scene("nul-byte", raw(b"format = 1\x00\n"), "malformed TOML")
scene("deep-nesting", raw(b"x = " + b"[" * 3000 + b"]" * 3000 + b"\n"), "")

# --------------------------------------------------------------------------- top level
scene("unknown-top", top("foo = 1"), "foo", "unknown key")
scene("output-for-outputs", sub("outputs =", "output ="), "output", "did you mean 'outputs'")
scene("titel", sub("title =", "titel ="), "titel", "did you mean 'title'")
scene("format-true", sub("format = 1", "format = true"), "format", "format = 1")
scene("format-2", sub("format = 1", "format = 2"), "format")
scene("format-float", sub("format = 1", "format = 1.0"), "format")
scene("format-string", sub("format = 1", 'format = "1"'), "format")
scene("format-missing", sub("format = 1\n", ""), "format")
scene("kind-typo", top('kind = "linkges"'), "kind", "linkage")
scene("kind-number", top("kind = 1"), "kind")
scene("kind-list", top("kind = [\"linkage\"]"), "kind", "expected one of")
scene("kind-table", top("kind = { a = 1 }"), "kind", "expected one of")
scene("kind-gears", top('kind = "gears"'), "kind", "gears")
scene("unit-inch", sub('unit = "mm"', 'unit = "inch"'), "unit", "expected one of")
scene("unit-list", sub('unit = "mm"', 'unit = ["mm"]'), "unit")
scene("title-list", sub('title = "Base slider-crank"', "title = [1]"), "title", "string")
scene("title-control", sub('title = "Base slider-crank"', 'title = "Base\\u0001"'), "title", "control character")
scene("title-del", sub('title = "Base slider-crank"', 'title = "Base\\u007f"'), "title", "control character")
scene("title-nonchar", sub('title = "Base slider-crank"', 'title = "Base\\uFFFE"'), "title", "noncharacter")
scene("title-nonchar-fdd0", sub('title = "Base slider-crank"', 'title = "\\uFDD0"'), "title", "noncharacter")
scene("title-huge", sub('title = "Base slider-crank"', 'title = "' + "x" * 5000 + '"'), "title")
scene("frame-zero", sub("frame = 4", "frame = 0"), "frame")
scene("frame-negative", sub("frame = 4", "frame = -4"), "frame")
scene("frame-bool", sub("frame = 4", "frame = true"), "frame")
scene("frame-string", sub("frame = 4", 'frame = "4"'), "frame")
scene("frame-huge", sub("frame = 4", "frame = 1" + "0" * 400), "frame")
scene("fij-typo", top('fij = "on_i_from"'), "fij", "did you mean")
scene("outputs-string", sub('outputs = ["positions", "velocity_plan", "acceleration_plan", "force_polygons", "lever"]',
                            'outputs = "positions"'), "outputs")
scene("outputs-typo", sub('"lever"]', '"levers"]'), "outputs", "did you mean 'lever'")
scene("outputs-number", sub('"lever"]', '1]'), "outputs")

# --------------------------------------------------------------------------- points
scene("point-list3", sub("O = [0, 0]", "O = [0, 0, 0]"), "points.O", "[x, y]")
scene("point-strings", sub("O = [0, 0]", 'O = ["a", "b"]'), "points.O[0]", "length")
scene("point-1e400mm", sub("O = [0, 0]", 'O = ["1e400 mm", 0]'), "points.O[0]", "finite")
scene("point-huge-int", sub("O = [0, 0]", "O = [1" + "0" * 400 + ", 0]"), "points.O[0]")
scene("point-1e300", sub("O = [0, 0]", "O = [1e300, 0]"), "points.O[0]", "at most")
scene("point-inf", sub("O = [0, 0]", "O = [inf, 0]"), "points.O[0]", "finite")
scene("point-nan", sub("O = [0, 0]", "O = [nan, 0]"), "points.O[0]", "finite")
scene("point-unit-furlong", sub("O = [0, 0]", 'O = ["3 furlongs", 0]'), "points.O[0]")
scene("point-name-control", sub("O = [0, 0]", '"O\\u0002" = [0, 0]'), "control character")
scene("points-not-table", sub("[points]\nO = [0, 0]", "points = [1, 2]"), "points", "table")

# --------------------------------------------------------------------------- links
scene("link-01", sub("[links.1]", "[links.01]"), "links.01", "[links.1]")
scene("link-01-and-1", add('[links.01]\naxis = ["O", "Q"]\nlength = 5'), "links.01")
scene("link-zero", sub("[links.3]", "[links.0]"), "links.0")
scene("link-name", sub("[links.3]", "[links.slider]"), "links.slider")
scene("link-plus", sub("[links.3]", '[links."+3"]'), "links.+3")
scene("link-is-frame", add('[links.4]\naxis = ["O"]'), "links.4", "frame")
scene("link-unknown-key", sub('length = 300', 'lenght = 300'), "links.2.lenght", "did you mean 'length'")
scene("link-name-list", sub('name = "rod AB"', "name = [1]"), "links.2.name", "string")
scene("link-name-markup-control", sub('name = "rod AB"', 'name = "<b>\\u0007</b>"'), "links.2.name", "control")
scene("axis-numbers", sub('axis = ["A", "B"]', "axis = [1, 2]"), "links.2.axis")
scene("axis-same", sub('axis = ["A", "B"]', 'axis = ["A", "A"]'), "links.2.axis", "different")
scene("axis-three", sub('axis = ["A", "B"]', 'axis = ["A", "B", "C"]'), "links.2.axis")
scene("axis-empty-name", sub('axis = ["A", "B"]', 'axis = ["A", " "]'), "links.2.axis[1]", "non-empty")
scene("length-zero", sub("length = 300", "length = 0"), "links.2.length", "positive")
scene("length-negative", sub("length = 300", "length = -300"), "links.2.length", "positive")
scene("length-1e400mm", sub("length = 300", 'length = "1e400 mm"'), "links.2.length", "finite")
scene("length-huge-int", sub("length = 300", "length = 1" + "0" * 400), "links.2.length", "401 digits")
scene("length-1e300", sub("length = 300", "length = 1e300"), "links.2.length", "at most")
scene("length-tiny", sub("length = 300", "length = 1e-300"), "links.2.length", "at least")
scene("length-bool", sub("length = 300", "length = true"), "links.2.length")
scene("length-list", sub("length = 300", "length = [300]"), "links.2.length")
scene("length-words", sub("length = 300", 'length = "long"'), "links.2.length")
scene("length-missing", sub("length = 300\n", ""), "links.2.length", "missing")
scene("slider-with-length", sub('axis = ["B"]', 'axis = ["B"]\nlength = 5'), "links.3.length")
scene("ratio-string", sub("ratio = 0.3", 'ratio = "x"'), "links.2.points.S2.ratio", "number")
scene("ratio-and-along", sub("ratio = 0.3", "ratio = 0.3, along = 5"), "links.2.points.S2", "not both")
scene("point-spec-unknown", sub("ratio = 0.3", "ratio = 0.3, foo = 1"), "links.2.points.S2.foo", "unknown key")
scene("point-spec-number", sub("S2 = { ratio = 0.3 }", "S2 = 0.3"), "links.2.points.S2")
scene("point-redefines-axis", sub("S2 = { ratio = 0.3 }", "A = { ratio = 0.3 }"), "links.2.points.A", "axis")
scene("mass-negative", sub("mass = 5.0", "mass = -5.0"), "links.2.mass", ">= 0")
scene("mass-1e300", sub("mass = 5.0", "mass = 1e300"), "links.2.mass", "at most")
scene("mass-string", sub("mass = 5.0", 'mass = "5 kg"'), "links.2.mass", "number")
scene("mass-huge-int", sub("mass = 5.0", "mass = 1" + "0" * 400), "links.2.mass", "digits")
scene("inertia-negative", sub("inertia = 0.04", "inertia = -0.04"), "links.2.inertia")
scene("inertia-nan", sub("inertia = 0.04", "inertia = nan"), "links.2.inertia", "finite")
scene("centre-unknown", sub('centre = "S2"', 'centre = "S3"'), "links.2.centre", "did you mean 'S2'")
scene("centre-list", sub('centre = "S2"', 'centre = ["S2"]'), "links.2.centre")
scene("centre-typo-key", sub('centre = "S2"', 'center = "S2"'), "links.2.center", "did you mean 'centre'")
scene("same-point-two-links", sub("S2 = { ratio = 0.3 }", "S2 = { ratio = 0.3 }, O = { ratio = 0.5 }"),
      "'O'", "no joint")
scene("same-point-unjoined", add('[links.5]\naxis = ["Q", "S2"]\nlength = 10'), "S2")

# --------------------------------------------------------------------------- joints
J_P = 'guide = { link = 4, through = "O", angle_deg = 0 }'
scene("joint-kind", sub('kind = "P"', 'kind = "Q"'), "[[joints]] entry 4, kind")
scene("joint-links-one", sub("links = [1, 2]", "links = [1]"), "[[joints]] entry 2, links")
scene("joint-links-same", sub("links = [1, 2]", "links = [1, 1]"), "[[joints]] entry 2, links", "different")
scene("joint-links-unknown", sub("links = [1, 2]", "links = [1, 9]"), "[[joints]] entry 2, links", "unknown link 9")
scene("joint-links-bool", sub("links = [1, 2]", "links = [true, 2]"), "[[joints]] entry 2, links")
scene("joint-links-nested", sub("links = [1, 2]", "links = [[1], 2]"), "[[joints]] entry 2, links")
scene("joint-point-list", sub('point = "A"', 'point = ["A"]'), "[[joints]] entry 2, point")
scene("joint-point-missing", sub('point = "A"', 'point = "Z"'), "[[joints]] entry 2, point", "not on link")
scene("joint-unknown-key", sub('point = "A"', 'point = "A"\nfoo = 1'), "[[joints]] entry 2, foo", "unknown key")
scene("joint-R-with-guide", sub('point = "A"', 'point = "A"\nguide = { link = 1 }'), "[[joints]] entry 2, guide")
scene("guide-missing", sub(J_P, ""), "[[joints]] entry 4, guide")
scene("guide-link-other", sub(J_P, 'guide = { link = 2, through = "O" }'), "[[joints]] entry 4, guide.link")
scene("guide-link-list", sub(J_P, 'guide = { link = [4], through = "O" }'), "[[joints]] entry 4, guide.link")
scene("guide-through-number", sub(J_P, "guide = { link = 4, through = 5 }"), "[[joints]] entry 4, guide.through")
scene("guide-through-unknown", sub(J_P, 'guide = { link = 4, through = "Q" }'), "[[joints]] entry 4, guide.through")
scene("guide-angle-string", sub(J_P, 'guide = { link = 4, through = "O", angle_deg = "flat" }'),
      "[[joints]] entry 4, guide.angle_deg")
scene("guide-angle-inf", sub(J_P, 'guide = { link = 4, through = "O", angle_deg = inf }'),
      "[[joints]] entry 4, guide.angle_deg", "finite")
scene("guide-unknown-key", sub(J_P, 'guide = { link = 4, through = "O", angel_deg = 0 }'),
      "[[joints]] entry 4, guide.angel_deg", "did you mean 'angle_deg'")
scene("guide-offset-1e400", sub(J_P, 'guide = { link = 4, through = "O", offset = "1e400 mm" }'),
      "[[joints]] entry 4, guide.offset")
scene("guide-toward-and-angle", sub(J_P, 'guide = { link = 4, through = "O", toward = "O", angle_deg = 0 }'),
      "[[joints]] entry 4, guide.angle_deg", "not both")
scene("joints-table", lambda t: t.replace("[[joints]]", "[joints.x]", 1).replace("[[joints]]", "[joints.y]"),
      "joints")

# --------------------------------------------------------------------------- driver
scene("driver-link-list", sub("link = 1\nomega_rpm", "link = [1]\nomega_rpm"), "driver.link")
scene("driver-link-string", sub("link = 1\nomega_rpm", 'link = "1"\nomega_rpm'), "driver.link")
scene("driver-link-frame", sub("link = 1\nomega_rpm", "link = 4\nomega_rpm"), "driver.link")
scene("driver-link-rod", sub("link = 1\nomega_rpm", "link = 2\nomega_rpm"), "driver.link", "pivot")
scene("omega-and-rpm", sub("omega_rpm = 300", "omega_rpm = 300\nomega = 31.4"), "driver.omega_rpm", "not both")
scene("omega-rmp", sub("omega_rpm = 300", "omega_rmp = 300"), "driver.omega_rmp", "did you mean 'omega_rpm'")
scene("omega-missing", sub("omega_rpm = 300\n", ""), "driver.omega", "missing")
scene("omega-negative", sub("omega_rpm = 300", "omega = -3"), "driver.omega", ">= 0")
scene("omega-1e300", sub("omega_rpm = 300", "omega = 1e300"), "driver.omega", "at most")
scene("omega-1e-154", sub("omega_rpm = 300", "omega = 1e-154"), "driver.omega", "at least")
scene("omega-huge-int", sub("omega_rpm = 300", "omega_rpm = 1" + "0" * 400), "driver.omega_rpm")
scene("omega-string", sub("omega_rpm = 300", 'omega_rpm = "300 rpm"'), "driver.omega_rpm", "number")
scene("sense-left", sub('sense = "ccw"', 'sense = "left"'), "driver.sense")
scene("sense-typo", sub('sense = "ccw"', 'sense = "cww"'), "driver.sense", "did you mean")
scene("phi-empty", sub("phi_deg = [30, 120]", "phi_deg = []"), "driver.phi_deg")
scene("phi-string", sub("phi_deg = [30, 120]", 'phi_deg = ["30"]'), "driver.phi_deg")
scene("phi-nan", sub("phi_deg = [30, 120]", "phi_deg = [nan]"), "driver.phi_deg", "finite")
scene("phi-inf", sub("phi_deg = [30, 120]", "phi_deg = inf"), "driver.phi_deg", "finite")
scene("phi-and-positions", sub("phi_deg = [30, 120]", "phi_deg = 30\npositions = 12"), "driver.phi_deg", "not both")
scene("phi0-without-positions", sub("phi_deg = [30, 120]", "phi_deg = 30\nphi0_deg = 5"), "driver.phi0_deg")
scene("positions-zero", sub("phi_deg = [30, 120]", "positions = 0"), "driver.positions")
scene("positions-float", sub("phi_deg = [30, 120]", "positions = 12.0"), "driver.positions", "whole number")
scene("positions-bool", sub("phi_deg = [30, 120]", "positions = true"), "driver.positions")
scene("positions-ten-million", sub("phi_deg = [30, 120]", "positions = 10_000_000"), "driver.positions",
      "at most 3600")
scene("positions-3601", sub("phi_deg = [30, 120]", "positions = 3601"), "driver.positions", "at most 3600")
scene("phi-list-too-long", sub("phi_deg = [30, 120]", "phi_deg = [" + ", ".join(["1"] * 3601) + "]"),
      "driver.phi_deg", "at most 3600")
scene("eps-string", sub('sense = "ccw"', 'sense = "ccw"\neps = "fast"'), "driver.eps")
scene("eps-1e300", sub('sense = "ccw"', 'sense = "ccw"\neps = 1e300'), "driver.eps", "at most")
scene("driver-unknown", sub('sense = "ccw"', 'sense = "ccw"\nspeed = 3'), "driver.speed", "unknown key")
scene("driver-not-table", sub("[driver]\nlink = 1", "driver = 1\n[driverx]\nlink = 1"), "driver")
scene("phi-ref-string", sub('sense = "ccw"', 'sense = "ccw"\nphi_ref_deg = "up"'), "driver.phi_ref_deg")

# --------------------------------------------------------------------------- branches, scales
scene("branch-two", sub('"2-3" = 1', '"2-3" = 2'), "branches.2-3", "+1 or -1")
scene("branch-bool", sub('"2-3" = 1', '"2-3" = true'), "branches.2-3")
scene("branch-string", sub('"2-3" = 1', '"2-3" = "up"'), "branches.2-3")
scene("scale-zero", sub("velocity = { mu = 20 }", "velocity = { mu = 0 }"), "scales.velocity.mu", "positive")
scene("scale-tiny", sub("velocity = { mu = 20 }", "velocity = { mu = 1e-300 }"), "scales.velocity.mu")
scene("scale-K-tiny", sub("velocity = { mu = 20 }", "velocity = { K = 1e-300 }"), "scales.velocity.K")
scene("scale-huge", sub("velocity = { mu = 20 }", "velocity = { mu = 1e300 }"), "scales.velocity.mu")
scene("scale-both", sub("velocity = { mu = 20 }", "velocity = { mu = 20, K = 0.05 }"), "scales.velocity")
scene("scale-unknown", sub("velocity = { mu = 20 }", "speed = { mu = 20 }"), "scales.speed", "unknown key")
scene("scale-style", sub("velocity = { mu = 20 }", 'style = "M"\nvelocity = { mu = 20 }'), "scales.style")
scene("scale-number", sub("velocity = { mu = 20 }", "velocity = 20"), "scales.velocity")

# --------------------------------------------------------------------------- loads
scene("loads-unknown", sub("gravity = true", "gravity = true\nfoo = 1"), "loads.foo", "unknown key")
scene("loads-typo", sub("gravity = true", "gravty = true"), "loads.gravty", "did you mean 'gravity'")
scene("loads-not-table", lambda t: t.split("[loads]")[0] + "loads = 5\n", "loads")
scene("gravity-string", sub("gravity = true", 'gravity = "yes"'), "loads.gravity")
scene("gravity-negative", sub("gravity = true", "gravity = { g = -9.81 }"), "loads.gravity.g")
scene("gravity-unknown", sub("gravity = true", "gravity = { gg = 9.81 }"), "loads.gravity.gg", "did you mean")
scene("gravity-direction-nan", sub("gravity = true", "gravity = { direction_deg = nan }"),
      "loads.gravity.direction_deg")
scene("inertia-mode", sub("gravity = true", 'gravity = true\ninertia = "both"'), "loads.inertia")
scene("lever-turn", sub("gravity = true", 'gravity = true\nlever_turn = "left"'), "loads.lever_turn")
scene("force-unknown-key", sub("resisting = 1000", "resisting = 1000\nfoo = 1"), "[[loads.force]] entry 1, foo",
      "unknown key")
scene("force-link-list", sub("link = 3\npoint", "link = [3]\npoint"), "[[loads.force]] entry 1, link")
scene("force-link-frame", sub("link = 3\npoint", "link = 4\npoint"), "[[loads.force]] entry 1, link", "frame")
scene("force-link-unknown", sub("link = 3\npoint", "link = 9\npoint"), "[[loads.force]] entry 1, link")
scene("force-point-unknown", sub('point = "B"\nresisting', 'point = "Bb"\nresisting'), "[[loads.force]] entry 1, point",
      "did you mean 'B'")
scene("force-point-list", sub('point = "B"\nresisting', 'point = ["B"]\nresisting'), "[[loads.force]] entry 1, point")
scene("force-vector-short", sub("resisting = 1000", "vector = [1]"), "[[loads.force]] entry 1, vector")
scene("force-vector-strings", sub("resisting = 1000", 'vector = ["a", "b"]'), "[[loads.force]] entry 1, vector")
scene("force-vector-1e308", sub("resisting = 1000", "vector = [1e308, 0]"), "[[loads.force]] entry 1, vector", "at most")
scene("force-two-ways", sub("resisting = 1000", "resisting = 1000\nvector = [1, 0]"), "[[loads.force]] entry 1",
      "not vector and resisting")
scene("force-resisting-negative", sub("resisting = 1000", "resisting = -1000"), "[[loads.force]] entry 1, resisting")
scene("force-stroke", sub("resisting = 1000", 'resisting = 1000\nstroke = "up"'), "[[loads.force]] entry 1, stroke")
scene("force-stroke-no-axis", sub("resisting = 1000", 'resisting = 1000\nstroke = "positive"'),
      "[[loads.force]] entry 1, stroke", "axis")
scene("force-name-list", sub('name = "F_c"', "name = [1]"), "[[loads.force]] entry 1, name", "string")
scene("force-name-control", sub('name = "F_c"', 'name = "F\\u001b[31m"'), "[[loads.force]] entry 1, name", "control")
scene("force-nothing", sub("resisting = 1000", ""), "[[loads.force]] entry 1, vector")
scene("moment-link-list", sub("link = 2\nvalue", "link = [2]\nvalue"), "[[loads.moment]] entry 1, link")
scene("moment-value-string", sub("value = -5", 'value = "-5"'), "[[loads.moment]] entry 1, value")
scene("moment-value-huge", sub("value = -5", "value = -1" + "0" * 400), "[[loads.moment]] entry 1, value")
scene("moment-both", sub("value = -5", "value = -5\nresisting = 5"), "[[loads.moment]] entry 1, resisting", "not both")
scene("moment-unknown", sub("value = -5", "valeu = -5"), "[[loads.moment]] entry 1, valeu", "did you mean 'value'")
scene("balancing-pivot", add('[loads.balancing]\npoint = "O"'), "loads.balancing.point")
scene("balancing-unknown-point", add('[loads.balancing]\npoint = "Z"'), "loads.balancing.point")
scene("balancing-kind", add('[loads.balancing]\nkind = "couple"'), "loads.balancing.kind")
scene("balancing-unknown-key", add('[loads.balancing]\npoints = "A"'), "loads.balancing.points",
      "did you mean 'point'")
scene("gas-not-piston", add("[[loads.gas]]\nlink = 2\npressure = 1"), "[[loads.gas]] entry 1, link", "piston")
scene("gas-pressure-unit", add('[[loads.gas]]\nlink = 3\ndiameter = 80\npressure = 1\npressure_unit = "psi"'),
      "[[loads.gas]] entry 1, pressure_unit")
scene("gas-unknown-key", add("[[loads.gas]]\nlink = 3\ndiameter = 80\npresure = 1"), "[[loads.gas]] entry 1, presure",
      "did you mean 'pressure'")
scene("gas-diameter-1e400", add('[[loads.gas]]\nlink = 3\ndiameter = "1e400 mm"\npressure = 1'),
      "[[loads.gas]] entry 1, diameter")
scene("mass-rule-diameter", add('[loads.mass_rule]\ndiameter = "x"'), "loads.mass_rule.diameter")

# --------------------------------------------------------------------------- [sheet] (draw)
scene("sheet-format", sub('format = "A3"', 'format = "A7"'), "sheet.format", argv=DRAW)
scene("sheet-unknown", sub('format = "A3"', 'format = "A3"\nfoo = 1'), "sheet.foo", argv=DRAW)
scene("sheet-orientation", sub('format = "A3"', 'format = "A3"\norientation = "up"'), "sheet.orientation",
      argv=DRAW)
scene("sheet-author-list", sub('format = "A3"', 'format = "A3"\nauthor = [1]'), "sheet.author", argv=DRAW)
scene("sheet-author-control", sub('format = "A3"', 'format = "A3"\nauthor = "A\\u0000"'), "sheet.author",
      argv=DRAW)
scene("sheet-typo", sub('format = "A3"', 'format = "A3"\norientaton = "portrait"'), "sheet.orientaton",
      "did you mean 'orientation'", argv=DRAW)
scene("sheet-positions-huge", sub('format = "A3"', 'format = "A3"\npositions = [1' + "0" * 400 + "]"),
      "sheet.positions", argv=DRAW)
scene("sheet-pin-unknown", add('[[sheet.pins]]\npanel = "velocity-30"\nx = 10\ny = 10\nsheets = 1'),
      "sheet.pins[0].sheets", "did you mean 'sheet'", argv=DRAW)
scene("sheet-pin-far", add('[[sheet.pins]]\npanel = "velocity-30"\nx = 1e300\ny = 10'), "sheet.pins[0].x",
      argv=DRAW)
scene("sheet-total-huge", sub('format = "A3"', 'format = "A3"\ntotal_sheets = 1' + "0" * 30), "sheet.total_sheets",
      argv=DRAW)
scene("draw-bad-scene", sub("length = 300", "length = -1"), "links.2.length", argv=DRAW)
scene("draw-not-assemblable", sub("length = 300", "length = 10"), "scene.toml", "is shorter than", "mm", argv=DRAW)

# --------------------------------------------------------------------------- geometry that has no answer
scene("rod-too-short", sub("length = 300", "length = 50"), "group RRP 2-3", "is shorter than the distance",
      "[branches]")

# --------------------------------------------------------------------------- check files
check("check-unknown-top", top("foo = 1"), "foo", "unknown key")
check("check-format-true", sub("format = 1", "format = true"), "format")
check("check-student-list", sub('student = "Student S."', "student = [1]"), "student")
check("check-student-control", sub('student = "Student S."', 'student = "S\\u0003"'), "student")
check("check-scene-missing", sub('scene = "scene.toml"\n', ""), "scene", "missing")
check("check-scene-nofile", sub('scene = "scene.toml"', 'scene = "nope.toml"'), "scene", "not found")
check("check-scene-self", sub('scene = "scene.toml"', 'scene = "check.toml"'), "scene", "itself")
check("check-scene-number", sub('scene = "scene.toml"', "scene = 5"), "scene")
check("check-scene-bad-inline", sub('scene = "scene.toml"', "scene = { format = 1 }"), "[scene]")
check("check-sheet", sub('sheet = "A1"', 'sheet = "A9"'), "sheet")
check("check-scales-missing", lambda t: t.replace("velocity = { mu = 20 }\nacceleration = { mu = 0.5 }\n", "")
      .replace("[scales]\n", ""), "scales")
check("check-scale-zero", sub("velocity = { mu = 20 }", "velocity = { mu = 0 }"), "scales.velocity.mu")
check("check-scale-tiny", sub("velocity = { mu = 20 }", "velocity = { mu = 1e-300 }"), "scales.velocity.mu")
check("check-scale-K-zero", sub("velocity = { mu = 20 }", "velocity = { K = 0 }"), "scales.velocity.K")
check("check-scale-string", sub("velocity = { mu = 20 }", 'velocity = { mu = "20" }'), "scales.velocity.mu")
check("check-scale-unknown", sub("velocity = { mu = 20 }", "velocty = { mu = 20 }"), "scales.velocty",
      "did you mean 'velocity'")
check("check-scale-huge-int", sub("velocity = { mu = 20 }", "velocity = 1" + "0" * 400), "scales.velocity")
check("check-tolerance-unknown", sub("segment_mm = 0.5", "segment = 0.5"), "tolerance.segment",
      "did you mean 'segment_mm'")
check("check-tolerance-model", sub('model = "draftsman"', 'model = "draftsmen"'), "tolerance.model",
      "did you mean 'draftsman'")
check("check-tolerance-negative", sub("segment_mm = 0.5", "segment_mm = -0.5"), "tolerance.segment_mm")
check("check-positions-missing", lambda t: t.split("[[positions]]")[0], "positions")
check("check-phi-not-in-scene", sub("phi_deg = 30", "phi_deg = 45"), "[[positions]] entry 1, phi_deg", "not in the scene")
check("check-phi-string", sub("phi_deg = 30", 'phi_deg = "30"'), "[[positions]] entry 1, phi_deg")
check("check-phi-twice", add("[[positions]]\nphi_deg = 30\n[positions.values]\nomega_2 = 1"),
      "[[positions]] entry 2, phi_deg", "twice")
check("check-position-unknown", sub("phi_deg = 30", "phi_deg = 30\nphi = 30"), "[[positions]] entry 1, phi",
      "did you mean 'phi_deg'")
check("check-measured-string", sub("v_B = 60", 'v_B = "sixty"'), "[[positions]] entry 1, measured.v_B")
check("check-measured-negative", sub("v_B = 60", "v_B = -60"), "[[positions]] entry 1, measured.v_B", "negative")
check("check-measured-1e400", sub("v_B = 60", 'v_B = "1e400 mm"'), "[[positions]] entry 1, measured.v_B")
check("check-measured-unknown-key", sub("v_B = 60", "v_B = { mm = 60, foo = 1 }"),
      "[[positions]] entry 1, measured.v_B.foo", "unknown key")
check("check-measured-empty-list", sub("v_B = 60", "v_B = []"), "[[positions]] entry 1, measured.v_B")
check("check-value-string", sub("omega_2 = 5.0", 'omega_2 = "5"'), "[[positions]] entry 1, values.omega_2")
check("check-value-huge-int", sub("omega_2 = 5.0", "omega_2 = 1" + "0" * 400), "[[positions]] entry 1, values.omega_2")
check("check-value-subnormal", sub("omega_2 = 5.0", "omega_2 = 5e-324"), "[[positions]] entry 1, values.omega_2", "at least")
check("check-value-nan", sub("omega_2 = 5.0", "omega_2 = nan"), "[[positions]] entry 1, values.omega_2")
check("check-length-no-unit", sub("omega_2 = 5.0", "h_1 = 65"), "[[positions]] entry 1, values.h_1", "unit")
check("check-name-control", sub("omega_2 = 5.0", '"v\\u0001" = 5.0'), "control character")
check("check-not-a-name", sub("omega_2 = 5.0", '"5 + 5" = 5.0'), "not a quantity name")
check("check-nothing-written", lambda t: t.split("[positions.measured]")[0], "[[positions]] entry 1", "nothing written")
check("check-not-utf8", raw(b"format = 1\nstudent = \"\xe9\"\n"), "not UTF-8")
check("check-scene-broken", lambda t: t.replace('scene = "scene.toml"', 'scene = "scene.toml"'), "links.2.length",
      argv=CHECK_CMD)

# --------------------------------------------------------------------------- the command line
cli("no-command", (), "command")
cli("unknown-command", ("solv", "{scene}"), "solv")
cli("solve-no-file", ("solve",), "scene")
cli("solve-unknown-option", ("solve", "{scene}", "--bogus"), "--bogus")
cli("solve-missing-file", ("solve", "{dir}/nope.toml"), "nope.toml", "cannot read")
cli("solve-folder", ("solve", "{dir}"), "cannot read")
cli("solve-json-is-input", ("solve", "{scene}", "--json", "{scene}"), "input file", "refusing")
cli("solve-json-no-folder", ("solve", "{scene}", "--json", "{dir}/nodir/r.json"), "nodir")
cli("solve-json-is-folder", ("solve", "{scene}", "--json", "{dir}"), "")
cli("draw-no-output", ("draw", "{scene}"), "-o")
cli("draw-format-gif", ("draw", "{scene}", "-o", "{dir}/s", "--format", "gif"), "gif")
cli("draw-format-empty", ("draw", "{scene}", "-o", "{dir}/s", "--format", ","), "--format")
cli("draw-dpi-zero", ("draw", "{scene}", "-o", "{dir}/s", "--format", "png", "--dpi", "0"), "--dpi")
cli("draw-dpi-huge", ("draw", "{scene}", "-o", "{dir}/s", "--dpi", "1e9"), "--dpi")
cli("draw-dpi-nan", ("draw", "{scene}", "-o", "{dir}/s", "--dpi", "nan"), "--dpi")
cli("draw-dpi-word", ("draw", "{scene}", "-o", "{dir}/s", "--dpi", "high"), "--dpi")
cli("draw-sheet-A9", ("draw", "{scene}", "-o", "{dir}/s", "--sheet", "A9"), "sheet.format")
cli("draw-orientation", ("draw", "{scene}", "-o", "{dir}/s", "--orientation", "up"), "--orientation")
cli("draw-language", ("draw", "{scene}", "-o", "{dir}/s", "--language", "de"), "--language")
cli("draw-output-is-file", ("draw", "{scene}", "-o", "{scene}"), "--output", "folder")
cli("check-missing", ("check", "{dir}/nope.toml"), "nope.toml")
cli("check-json-is-input", ("check", "{check}", "--json", "{check}"), "input file")
cli("check-json-is-scene", ("check", "{check}", "--json", "{scene}"), "input file")
cli("check-csv-is-input", ("check", "{check}", "--csv", "{check}"), "input file")
cli("check-sheet-format", ("check", "{check}", "--sheet", "{dir}/s", "--sheet-format", "gif"), "--sheet-format")
cli("check-json-no-folder-with-sheets", ("check", "{check}", "--json", "{dir}/nodir/c.json", "--sheet", "{dir}/s"),
    "nodir")
cli("check-sheet-language", ("check", "{check}", "--sheet-language", "de"), "--sheet-language")
cli("bench-json-no-folder", ("bench", "--quick", "--json", "{dir}/nodir/b.json", "--out", "{dir}/bench"), "nodir")
cli("bench-sizes", ("bench", "--sizes", "x"), "--sizes")
cli("bench-fuzz-zero", ("bench", "--fuzz", "0"), "--fuzz")


def _snapshot(folder: Path) -> dict[str, bytes]:
    return {str(p.relative_to(folder)): p.read_bytes() for p in sorted(folder.rglob("*")) if p.is_file()} | {
        str(p.relative_to(folder)) + "/": b"" for p in folder.rglob("*") if p.is_dir()}


def run(argv: list[str]) -> int:
    try:
        return main(argv)
    except SystemExit as exc:
        return exc.code if isinstance(exc.code, int) else 1


def test_the_table_is_large():
    assert len(CASES) >= 150
    assert len({c.id for c in CASES}) == len(CASES)


def lay_out(case: Case, tmp: Path) -> list[str]:
    """A case's files in ``tmp`` (the scene and the check file as the case edits them, and an
    output folder) and its command line."""
    (tmp / "out").mkdir(exist_ok=True)
    shutil.copy(DATA / "scene.toml", tmp / "scene.toml")
    shutil.copy(DATA / "check.toml", tmp / "check.toml")
    for name, edit in (("scene.toml", case.scene), ("check.toml", case.check)):
        if edit is not None:
            text = edit((tmp / name).read_text(encoding="utf-8"))
            data = text.encode("utf-8") if isinstance(text, str) else text
            (tmp / name).write_bytes(data)
    if case.id == "check-scene-broken":
        (tmp / "scene.toml").write_text(SCENE.replace("length = 300", "length = -1"), encoding="utf-8")
    return [a.format(scene=tmp / "scene.toml", check=tmp / "check.toml", dir=tmp) for a in case.argv]


@pytest.mark.parametrize("case", CASES, ids=[c.id for c in CASES])
def test_bad_input_keeps_the_promise(case: Case, tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    argv = lay_out(case, tmp_path)
    before = _snapshot(tmp_path)
    status = run(argv)
    out, err = capsys.readouterr()
    lines = err.splitlines()
    assert status == 2, f"status {status}; stderr: {err!r}"
    assert len(lines) == 1, f"expected one line on stderr, got {err!r}"
    assert lines[0].startswith("plans: error: "), lines[0]
    assert not re.search("[А-Яа-яЁё]", re.sub(r"'[^']*'", "", lines[0])), "a Russian word in English"
    assert "Traceback" not in err and "Traceback" not in out
    for word in case.expect:
        assert word in lines[0], f"{word!r} not in {lines[0]!r}"
    assert _snapshot(tmp_path) == before, "files were created or changed"
