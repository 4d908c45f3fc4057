"""The guard of every command's inputs and outputs (plans.guard): no command writes over a
file it read, by any spelling of the path; a run's outputs appear all together or not at
all; and the angles of any finite size reduced exactly."""

from __future__ import annotations

import math
import os
import random
import shutil
from fractions import Fraction
from pathlib import Path

import numpy as np
import pytest

from drawings.cli import main
from plans import guard, io
from plans.errors import OutputError

SAMPLES = Path(__file__).resolve().parent.parent / "samples"

#: (sample, command, output option) for every command that reads a file of the family
COMMANDS = [
    ("slider_crank.toml", "solve", "--json"),
    ("slider_crank.toml", "solve", "--csv"),
    ("gears/seed_train.toml", "gears", "--json"),
    ("cams/seed001_valve_cam.toml", "cam", "--json"),
    ("engines/v_twin.toml", "balance", "--json"),
    ("slider_crank.toml", "demo", "-o"),
    ("checks/dynamics_seed004.toml", "check", "--json"),
    ("checks/dynamics_seed004.toml", "check", "--csv"),
]
SPELLINGS = ("same", "dot", "absolute", "relative-up", "symlink", "hardlink", "folder-link", "chain-link")


def _copy(sample: str, folder: Path) -> Path:
    import tomllib

    from plans.accuracy.fuzz import to_toml

    src = SAMPLES / sample
    data = tomllib.loads(src.read_text(encoding="utf-8"))
    if isinstance(data.get("scene"), str):
        data["scene"] = str((src.parent / data["scene"]).resolve())
    dst = folder / Path(sample).name
    dst.write_text(to_toml(data), encoding="utf-8")
    return dst


def _spell(path: Path, how: str) -> str:
    folder = path.parent
    if how == "dot":
        return f"{folder}/./{path.name}"
    if how == "absolute":
        return str(path.resolve())
    if how == "relative-up":
        return os.path.relpath(path, Path.cwd())
    if how == "symlink":
        (folder / "link.out").symlink_to(path.name)
        return str(folder / "link.out")
    if how == "hardlink":
        os.link(path, folder / "hard.out")
        return str(folder / "hard.out")
    if how == "folder-link":
        (folder / "here").symlink_to(".", target_is_directory=True)
        return str(folder / "here" / path.name)
    if how == "chain-link":
        (folder / "a.out").symlink_to(path)
        (folder / "b.out").symlink_to(folder / "a.out")
        return str(folder / "b.out")
    return str(path)


def _state(folder: Path) -> dict[str, bytes | str]:
    return {p.name: (os.readlink(p) if p.is_symlink() else "<folder>" if p.is_dir() else p.read_bytes())
            for p in sorted(folder.iterdir())}


@pytest.mark.parametrize("how", SPELLINGS)
@pytest.mark.parametrize("sample,command,option", COMMANDS, ids=[f"{c}{o}" for _, c, o in COMMANDS])
def test_no_command_overwrites_its_input_by_any_spelling(sample, command, option, how, tmp_path, capsys):
    src = _copy(sample, tmp_path)
    target = _spell(src, how)
    before = _state(tmp_path)
    status = main([command, str(src), option, target])
    err = capsys.readouterr().err.splitlines()
    assert status == 2 and len(err) == 1, err
    assert "input file" in err[0] and "refusing to overwrite" in err[0], err[0]
    assert _state(tmp_path) == before


def test_check_never_writes_over_the_scene_it_reads(tmp_path, capsys):
    check = _copy("checks/dynamics_seed004.toml", tmp_path)
    scene = check.parent / "dynamics_seed004.toml"
    import tomllib

    from plans.accuracy.fuzz import to_toml

    data = tomllib.loads(check.read_text(encoding="utf-8"))
    shutil.copy(data["scene"], tmp_path / "scene.toml")
    data["scene"] = str(tmp_path / "scene.toml")
    scene.write_text(to_toml(data), encoding="utf-8")
    before = _state(tmp_path)
    assert main(["check", str(scene), "--json", f"{tmp_path}/./scene.toml"]) == 2
    assert "refusing to overwrite" in capsys.readouterr().err
    assert _state(tmp_path) == before


def test_a_report_or_sheet_named_like_the_input_is_refused(tmp_path, capsys):
    """Outputs named after the input (``--out`` of check, the sheets of draw) never land on
    an input that happens to bear that name."""
    check = _copy("checks/dynamics_seed004.toml", tmp_path)
    named = tmp_path / "c.json"  # a check file named like its own report
    check.rename(named)
    before = _state(tmp_path)
    assert main(["check", str(named), "--out", str(tmp_path)]) == 2
    assert "refusing to overwrite" in capsys.readouterr().err
    assert _state(tmp_path) == before
    scene = tmp_path / "s.svg"  # a cam file named like its own (one) sheet
    shutil.copy(SAMPLES / "cams" / "seed001_valve_cam.toml", scene)
    before = _state(tmp_path)
    assert main(["draw", str(scene), "-o", str(tmp_path)]) == 2
    assert "refusing to overwrite" in capsys.readouterr().err
    assert _state(tmp_path) == before


def test_a_later_output_that_fails_leaves_nothing_of_the_run(tmp_path, capsys):
    src = _copy("slider_crank.toml", tmp_path)
    (tmp_path / "r.json").mkdir()  # the second output is a folder
    before = _state(tmp_path)
    assert main(["solve", str(src), "--csv", str(tmp_path / "t.csv"), "--json", str(tmp_path / "r.json")]) == 2
    err = capsys.readouterr().err.splitlines()
    assert len(err) == 1 and "folder" in err[0]
    assert _state(tmp_path) == before  # the CSV written first is not there either
    train = _copy("gears/planetary_2kh.toml", tmp_path)  # two sheets
    out = tmp_path / "sheets"
    (out / "planetary_2kh-2.svg").mkdir(parents=True)  # the later sheet's target is a folder
    assert main(["draw", str(train), "-o", str(out)]) == 2
    assert "planetary_2kh-2.svg" in capsys.readouterr().err
    assert sorted(p.name for p in out.iterdir()) == ["planetary_2kh-2.svg"]
    cam = _copy("cams/seed001_valve_cam.toml", tmp_path)  # one sheet, its PNG target a folder
    (out / "seed001_valve_cam.png").mkdir()
    assert main(["draw", str(cam), "-o", str(out), "--format", "svg,png", "--dpi", "10"]) == 2
    assert "seed001_valve_cam.png" in capsys.readouterr().err
    assert sorted(p.name for p in out.iterdir()) == ["planetary_2kh-2.svg", "seed001_valve_cam.png"]


def test_a_run_renames_its_files_only_when_it_returns(tmp_path):
    a, b = tmp_path / "a.txt", tmp_path / "b.txt"
    a.write_text("old a")
    with guard.Run():
        io.atomic_write(a, "new a")
        with io.atomic_file(b) as fh:
            fh.write(b"new b")
        assert a.read_text() == "old a" and not b.exists()  # staged, not yet in place
        assert io.staged_bytes(a) == b"new a"
    assert a.read_text() == "new a" and b.read_text() == "new b"
    with pytest.raises(KeyError), guard.Run():
        io.write_all({a: "newer a", b: "newer b"})
        io.remove([b])
        raise KeyError("a later failure")
    assert a.read_text() == "new a" and b.read_text() == "new b"  # nothing of the failed run
    assert sorted(p.name for p in tmp_path.iterdir()) == ["a.txt", "b.txt"]  # no temporary left


def test_a_run_refuses_its_inputs_and_folders(tmp_path):
    src = tmp_path / "in.toml"
    src.write_text("format = 1\n")
    with pytest.raises(OutputError, match="refusing to overwrite"), guard.Run():
        io.read_toml(src)
        io.atomic_write(tmp_path / "." / "in.toml", "x")
    assert src.read_text() == "format = 1\n"
    (tmp_path / "d").mkdir()
    with pytest.raises(OutputError, match="is a folder"), guard.Run():
        io.write_all({tmp_path / "ok.txt": "x", tmp_path / "d": "y"})
    assert not (tmp_path / "ok.txt").exists()
    with guard.Run():  # an old output of the run is removed, an input never
        io.read_toml(src)
        io.remove([src])
    assert src.exists()


def test_a_symbolic_link_loop_and_deep_tables_are_one_line(tmp_path, capsys):
    loop = tmp_path / "loop.toml"
    loop.symlink_to(loop)
    for command in ("solve", "gears", "cam", "balance", "check", "draw", "demo"):
        extra = {"draw": ["-o", str(tmp_path / "s")], "demo": ["-o", str(tmp_path / "p.html")]}.get(command, [])
        assert main([command, str(loop), *extra]) == 2, command
        err = capsys.readouterr().err.splitlines()
        assert len(err) == 1 and "loop.toml" in err[0], (command, err)
    deep = tmp_path / "deep.toml"
    deep.write_text("format = 1\n[" + ".".join(["a"] * 20000) + "]\n", encoding="utf-8")
    assert main(["solve", str(deep)]) == 2
    err = capsys.readouterr().err.splitlines()
    assert len(err) == 1 and "nested" in err[0] and len(err[0]) < 300


# --------------------------------------------------------------------------- angles


def test_fmod_of_a_float_by_360_is_the_exact_remainder():
    """The reduction's proof: for every float x, fmod(x, 360) equals x − 360·⌊x/360⌋ (with
    the sign of x) computed in rational arithmetic; checked over every binade of floats."""
    rng = random.Random(5)
    xs = [1.234567e21, 1e300, -1e300, 5e-324, 359.99999999999994, 360.0, -360.0, 720.5, 2.0**1023]
    for e in range(-1074, 1024, 7):
        xs += [math.ldexp(rng.random() + 1, e) * rng.choice((1, -1)) for _ in range(3)]
    for x in xs:
        exact = Fraction(x) - 360 * int(Fraction(x) / 360)  # truncated toward zero, like fmod
        assert Fraction(math.fmod(x, 360.0)) == exact, x
        assert np.fmod(np.array([x]), 360.0)[0] == math.fmod(x, 360.0)


def test_the_crank_at_a_huge_angle_is_where_exact_arithmetic_puts_it():
    from plans.kinematics import fast
    from plans.kinematics.exact import solve
    from plans.kinematics.placing import load_scene

    big = 1.234567e21
    exact = float(Fraction(big) % 360)  # 256°, exactly
    assert 255 < exact < 257
    sc = load_scene(SAMPLES / "slider_crank.toml")
    import warnings

    with warnings.catch_warnings():
        warnings.simplefilter("error")
        kin = solve(sc, [big, exact, 1e300, float(Fraction(1e300) % 360)], order=2)
        one = fast.rotation1(0.0, 1, big)
        many = fast.rotation(0.0, -1, np.array([big, -big, 1e300]))
    for name in sc.links[sc.driver.link].points:
        p = kin.point(name)
        assert abs(p[0][0] - p[0][1]) < 1e-15 and abs(p[1][0] - p[1][1]) < 1e-15
        assert abs(p[0][2] - p[0][3]) < 1e-15
    assert abs(one - np.exp(1j * np.radians(exact))) < 1e-15
    assert abs(many[0] - np.exp(-1j * np.radians(exact))) < 1e-15
    assert abs(many[1] - np.exp(1j * np.radians(exact))) < 1e-15


def test_an_engine_takes_the_same_angle_reduced_exactly():
    from plans.balancing.engine import engine_from_dict

    base = {"format": 1, "kind": "engine", "r": 50, "lambda": 0.25, "omega_rpm": 3000, "strokes": 2,
            "m_rot": 1, "m_rec": 1, "cylinders": [{"z": 0}, {"z": 100}]}
    huge = engine_from_dict(dict(base, crank_deg=[0, 1.234567e21]))
    plain = engine_from_dict(dict(base, crank_deg=[0, float(Fraction(1.234567e21) % 360)]))
    assert huge.cylinders[1].crank == plain.cylinders[1].crank


# --------------------------------------------------------------------------- messages of the construction


def test_a_span_message_names_the_distance_at_its_own_angle(tmp_path, capsys):
    text = (SAMPLES / "four_bar.toml").read_text(encoding="utf-8").replace("length = 80\n", "length = 250\n", 1)
    for phis, angle, distance in (("positions = 12", "phi = 0 deg", "AD = 50 mm"),
                                  ("phi_deg = [180, 0]", "phi = 180 deg", "AD = 550 mm")):
        f = tmp_path / "f.toml"
        f.write_text(text.replace("positions = 12", phis), encoding="utf-8")
        assert main(["solve", str(f)]) == 2
        err = capsys.readouterr().err
        assert angle in err and distance in err, err


def test_a_parallelogram_at_its_change_point_is_indeterminate(tmp_path, capsys):
    text = (SAMPLES / "four_bar.toml").read_text(encoding="utf-8")
    text = text.replace("D = [300, 0]", "D = [260, 0]").replace("length = 200\n", "length = 80\n")
    f = tmp_path / "p.toml"
    f.write_text(text.replace("positions = 12", "phi_deg = [30, 0]"), encoding="utf-8")
    assert main(["solve", str(f)]) == 2
    err = capsys.readouterr().err
    assert "group RRR 2-3" in err and "phi = 0 deg" in err and "indeterminate" in err, err
    f.write_text(text.replace("positions = 12", "phi_deg = [30, 60]"), encoding="utf-8")
    assert main(["solve", str(f), "--quiet"]) == 0  # beside the change point it is a parallelogram
    capsys.readouterr()


def test_the_dynamics_sample_is_drawn_on_a4_at_smaller_scales(tmp_path, capsys):
    """Where a smaller scale exists a sheet is scaled (the plan of positions, the diagrams'
    φ axis and heights) and split, not refused."""
    out = tmp_path / "a4"
    assert main(["draw", str(SAMPLES / "dynamics_slider_crank.toml"), "-o", str(out), "--sheet", "A4"]) == 0
    ids = " ".join(p.read_text(encoding="utf-8") for p in out.glob("*.svg"))
    for pid in ('id="positions', 'id="dyn-M', 'id="dyn-A', 'id="dyn-I', 'id="dyn-W'):
        assert pid in ids, pid
    capsys.readouterr()


def test_every_file_is_written_through_the_guard():
    """By construction: outside plans.io and plans.guard no module of plans/ or drawings/
    writes, renames or removes a file itself (a new command that writes through plans.io is
    guarded without further care).  The few exceptions write only into temporary folders
    of their own, whole modules or lines marked "# guard: a temporary folder"."""
    import re

    root = Path(__file__).resolve().parent.parent
    pattern = re.compile(r"\.write_text\(|\.write_bytes\(|\bos\.(replace|rename|remove|unlink)\(|\.unlink\(|"
                         r"shutil\.(copy|copyfile|copy2|move|rmtree)\(|\bopen\([^)]*[\"'][wax]b?[\"']")
    allowed = {"plans/io.py", "plans/guard.py",
               "plans/accuracy/fuzz.py",  # its cases live in a temporary folder; failures kept on request
               "plans/accuracy/examiner_bench.py",  # the submissions it times, in a temporary folder
               "drawings/demo.py",  # the page timed in a browser, from a temporary folder
               "drawings/note/cli.py",  # the DOCX handed to LibreOffice in a temporary folder
               "plans/accuracy/group_bench.py",  # the group it times, in a temporary folder
               "drawings/workbench/bench.py"}  # the scene it edits while timing, in a temporary folder
    found = []
    for folder in ("plans", "drawings"):
        for p in sorted((root / folder).rglob("*.py")):
            rel = p.relative_to(root).as_posix()
            if rel in allowed:
                continue
            for n, line in enumerate(p.read_text(encoding="utf-8").splitlines(), 1):
                if pattern.search(line.split("#")[0]) and "# guard: a temporary folder" not in line:
                    found.append(f"{rel}:{n}: {line.strip()}")
    assert not found, "write through plans.io (atomic_write, atomic_file, write_all, remove):\n" + "\n".join(found)


def test_a_command_that_answers_2_itself_leaves_nothing(tmp_path, monkeypatch, capsys):
    """``plans check`` prints its own error and returns 2: what it staged before is dropped."""
    import plans.check_command as report
    from plans.errors import InputError

    check = _copy("checks/v_engine_coursework.toml", tmp_path)

    def late(args, target, written):
        raise InputError("a failure after the reports were staged", file=str(target))

    monkeypatch.setattr(report, "_after", late)
    before = _state(tmp_path)
    status = main(["check", str(check), "--json", str(tmp_path / "c.json")])
    err = capsys.readouterr().err
    assert status == 2 and "after the reports were staged" in err
    assert _state(tmp_path) == before


def test_a_guide_longer_than_any_sheet_is_refused_without_billions_of_strokes(tmp_path, capsys):
    """Found by the long fuzz: a fuzzed six-bar whose guide runs 1e8 mm hatched a stroke
    every 2 mm (gigabytes) before the sheet refused it; now at most MAX_HATCH strokes."""
    from drawings.paper.backend import MAX_HATCH, hatch_segments

    assert len(hatch_segments((0.0, 0.0), (1e12, 0.0), 1, 2.0, 3.0)) <= MAX_HATCH + 1
    assert len(hatch_segments((0.0, 0.0), (10.0, 0.0), 1, 2.0, 3.0)) == 6  # a sheet's own hatch unchanged
    data = Path(__file__).resolve().parent / "data" / "hostile" / "huge_guide.toml"
    assert main(["draw", str(data), "-o", str(tmp_path / "s")]) == 2
    err = capsys.readouterr().err.splitlines()
    assert len(err) == 1 and "does not fit" in err[0]
