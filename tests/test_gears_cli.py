"""``plans gears`` and ``plans draw`` on gear files: every sample solved and drawn, the JSON,
bad input as one line and exit status 2."""

from __future__ import annotations

import json
import subprocess
import sys
from pathlib import Path

import pytest

from drawings.cli import main
from drawings.gears import draw

ROOT = Path(__file__).resolve().parent.parent
GEAR_SAMPLES = sorted((ROOT / "samples" / "gears").glob("*.toml"))
SEED = ROOT / "samples" / "gears" / "seed_train.toml"


def test_there_are_gear_samples():
    names = {p.name for p in GEAR_SAMPLES}
    assert {"seed_train.toml", "planetary_2kh.toml"} <= names


@pytest.mark.parametrize("path", GEAR_SAMPLES, ids=lambda p: p.name)
def test_every_gear_sample_solves_and_draws(path, tmp_path, capsys):
    out = tmp_path / "r.json"
    assert main(["gears", str(path), "--json", str(out), "--quiet"]) == 0
    data = json.loads(out.read_text(encoding="utf-8"))
    assert data["meshes"] and "ratios" in data
    d = draw(path)
    assert d.sheets
    svg = [sh.svg() for sh in d.sheets]
    assert all("<svg" in s for s in svg)
    assert [sh.svg() for sh in draw(path).sheets] == svg  # same input, same bytes
    panels = {p.kind for p in d.panels}
    if d.solution.plan is not None:
        assert {"velocity-plan", "ray-diagram"} <= panels
    if d.meshing is not None:
        assert "meshing" in panels
        drawn = [m["contact_ratio_drawn"] for m in data["meshes"] if m["contact_ratio_drawn"] is not None]
        assert len(drawn) == len(d.solution.drawn_pairs())


def test_plans_draw_dispatches_gear_files(tmp_path, capsys):
    assert main(["draw", str(SEED), "-o", str(tmp_path), "--format", "svg"]) == 0
    written = capsys.readouterr().out.split()  # the meshing and the train share one A1 sheet
    assert len(written) == 1 and all(Path(p).exists() for p in written)


def test_json_to_stdout(capsys):
    assert main(["gears", str(SEED), "--json", "-"]) == 0
    data = json.loads(capsys.readouterr().out)
    m = data["meshes"][0]
    assert m["gears"] == ["1", "2"]
    assert abs(m["contact_ratio_drawn"] - m["contact_ratio"]) < 2e-3
    assert m["radii"]["1"]["pitch"] == pytest.approx(52.0)


BAD = [
    ('[[gears]]\nname = "1"\nz = 26\nx = 0', '[[gears]]\nname = "1"\nz = 0\nx = 0', "gears[0].z"),
    ('name = "2"\nz = 14\nx = "auto"', 'name = "2"\nz = 14\nx = 1.2', "pointed tooth"),
    ('gears = ["1", "2"]\ndraw = true', 'gears = ["1", "2"]\ndraw = true\ncentre_distance = 70',
     "impossible centre distance"),
    ("module = 4", "modul = 4", "did you mean 'module'"),
    ('gears = ["1", "2"]\ndraw = true', 'gears = ["1", "2"]\ndraw = true\ncentre = 81', "meshes[0].centre"),
    ('speed_rpm = 650', 'speed_rpm = 650\ncarier = "H"', "did you mean 'carrier'"),
    ("module = 4", "module = -" + "1" * 400, "module: expected a number of magnitude"),
    ('[[gears]]\nname = "1"\nz = 26\nx = 0', '[[gears]]\nname = "1"\nz = 1' + "0" * 400 + '\nx = 0',
     "gears[0].z: expected a whole number of teeth"),
    ('[[gears]]\nname = "1"\nz = 26\nx = 0', '[[gears]]\nname = "1"\nz = 26\nx = -1' + "0" * 400,
     "an integer of 401 digits"),
    ('unit = "mm"', 'unit = ["A"]', "unit: expected one of"),
    ("addendum = 1.0", "addendum = 9.99e-07", "addendum: expected h_a*"),
]


def _bad(tmp_path, old, new):
    text = SEED.read_text(encoding="utf-8")
    assert old in text
    bad = tmp_path / "bad.toml"
    bad.write_text(text.replace(old, new, 1), encoding="utf-8")
    return bad


@pytest.mark.parametrize("old,new,expect", BAD, ids=[b[2] for b in BAD])
def test_bad_input_is_one_line_and_exit_2(tmp_path, capsys, old, new, expect):
    bad = _bad(tmp_path, old, new)
    out = tmp_path / "out.json"
    assert main(["gears", str(bad), "--json", str(out)]) == 2
    err = capsys.readouterr().err
    lines = err.strip().splitlines()
    assert len(lines) == 1 and _named(expect) in lines[0] and "bad.toml" in lines[0], err
    assert not out.exists()
    assert main(["draw", str(bad), "-o", str(tmp_path / "sheets")]) == 2
    assert len(capsys.readouterr().err.strip().splitlines()) == 1
    assert not (tmp_path / "sheets").exists()


def test_bad_input_from_the_console_has_no_traceback(tmp_path):
    bad = _bad(tmp_path, *BAD[0][:2])
    r = subprocess.run([sys.executable, "-m", "drawings.cli", "gears", str(bad)],
                       capture_output=True, text=True, cwd=ROOT)
    assert r.returncode == 2 and "Traceback" not in r.stderr
    assert len(r.stderr.strip().splitlines()) == 1


def test_a_file_with_nothing_to_solve_is_refused(tmp_path, capsys):
    f = tmp_path / "one.toml"
    f.write_text('format = 1\nkind = "gears"\nmodule = 2\n[[gears]]\nname = "1"\nz = 20\n', encoding="utf-8")
    assert main(["gears", str(f)]) == 2
    assert "meshes" in capsys.readouterr().err


def test_synthesis_alone_is_solved_and_drawn(tmp_path, capsys):
    f = tmp_path / "s.toml"
    f.write_text('format = 1\nkind = "gears"\nmodule = 2\n[[gears]]\nname = "1"\nz = 20\n'
                 '[synthesis]\nratio = 6\nplanets = 3\n', encoding="utf-8")
    assert main(["gears", str(f), "--json", "-"]) == 0
    data = json.loads(capsys.readouterr().out)
    s = data["synthesis"]
    assert s["z1"] + 2 * s["z2"] == s["z3"] and all(s["conditions"].values())
    assert [p.kind for p in draw(f).panels] == ["table"]


def _named(text: str) -> str:
    """An expected field as the message names it: an entry of an array of tables 1-based
    (``gears[0].z`` is ``[[gears]] entry 1, z``)."""
    from plans.errors import field_name

    head, sep, rest = text.partition(": ")
    return field_name(head) + sep + rest
