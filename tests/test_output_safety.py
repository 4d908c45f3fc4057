"""Outputs that are complete or absent: sheets of one input never clobber another's, old
sheets of a redrawn scene go, an error or Ctrl-C mid-way leaves nothing, markup in names
stays text, the renderer never reads local files, a closed pipe is not an error."""

from __future__ import annotations

import math
import os
import signal
import subprocess
import sys
import time
import warnings
import xml.etree.ElementTree as ET
from pathlib import Path

import numpy as np
import pytest

from drawings.cli import main
from drawings.paper import export
from plans.kinematics.placing import parse_scene
from plans.reader import Reader, check_keys, did_you_mean, reduce_deg

ROOT = Path(__file__).resolve().parent.parent
DATA = Path(__file__).resolve().parent / "data" / "hostile"
SCENE = (DATA / "scene.toml").read_text(encoding="utf-8")


def _files(folder: Path) -> dict[str, bytes]:
    return {p.name: p.read_bytes() for p in sorted(folder.iterdir()) if p.is_file()} if folder.exists() else {}


def _write(path: Path, text: str) -> Path:
    path.parent.mkdir(parents=True, exist_ok=True)
    path.write_text(text, encoding="utf-8")
    return path


# --------------------------------------------------------------------------- folders of sheets


def test_redraw_with_fewer_sheets_removes_the_old_ones_only(tmp_path, capsys):
    scene = _write(tmp_path / "x.toml", SCENE)
    out = tmp_path / "out"
    foreign = _write(out / "x-9.svg", "not ours")
    assert main(["draw", str(scene), "-o", str(out)]) == 0
    many = {n for n in _files(out) if n.endswith(".svg")} - {"x-9.svg"}
    assert len(many) >= 2
    _write(scene, SCENE.replace("outputs = [", 'outputs = ["positions"]\nx_outputs = [')
           .replace('x_outputs = ["positions", "velocity_plan", "acceleration_plan", "force_polygons", "lever"]\n', ""))
    capsys.readouterr()
    assert main(["draw", str(scene), "-o", str(out)]) == 0
    printed = {Path(line).name for line in capsys.readouterr().out.split()}
    now = {n for n in _files(out) if n.endswith(".svg")}
    assert len(printed) < len(many)
    assert now == printed | {"x-9.svg"}, now
    assert foreign.read_text() == "not ours"  # never written by plans: never removed
    capsys.readouterr()


def test_two_scenes_of_one_stem_do_not_overwrite_each_other(tmp_path, capsys):
    a = _write(tmp_path / "a" / "x.toml", SCENE)
    b = _write(tmp_path / "b" / "x.toml", SCENE.replace("Base slider-crank", "Other"))
    out = tmp_path / "out"
    assert main(["draw", str(a), "-o", str(out)]) == 0
    before = _files(out)
    capsys.readouterr()
    assert main(["draw", str(b), "-o", str(out)]) == 2
    err = capsys.readouterr().err.splitlines()
    assert len(err) == 1 and "refusing to overwrite" in err[0] and str(a.resolve()) in err[0]
    assert _files(out) == before
    assert main(["draw", str(a), "-o", str(out)]) == 0  # the owner may redraw


def test_an_error_while_rendering_leaves_no_sheet(tmp_path, monkeypatch, capsys):
    scene = _write(tmp_path / "x.toml", SCENE)
    out = tmp_path / "out"
    calls = []
    real = export.svg_bytes

    def failing(sheet):
        calls.append(sheet)
        if len(calls) == 2:
            from plans.errors import OutputError
            raise OutputError("the second sheet failed")
        return real(sheet)

    monkeypatch.setattr(export, "svg_bytes", failing)
    assert main(["draw", str(scene), "-o", str(out)]) == 2
    assert not out.exists() or not any(out.iterdir())
    assert len(capsys.readouterr().err.splitlines()) == 1


def test_ctrl_c_while_rendering_is_quiet_and_leaves_no_file(tmp_path, monkeypatch, capsys):
    scene = _write(tmp_path / "x.toml", SCENE)
    out = tmp_path / "out"
    out.mkdir()
    calls = []
    real = export.svg_bytes

    def interrupted(sheet):
        calls.append(sheet)
        if len(calls) == 2:
            raise KeyboardInterrupt
        return real(sheet)

    monkeypatch.setattr(export, "svg_bytes", interrupted)
    assert main(["draw", str(scene), "-o", str(out)]) == 130
    assert list(out.iterdir()) == []
    cap = capsys.readouterr()
    assert cap.err == ""


def test_ctrl_c_while_writing_leaves_no_temporary(tmp_path, monkeypatch):
    from plans import io

    real = os.replace
    calls = []

    def interrupted(src, dst):
        calls.append(dst)
        raise KeyboardInterrupt

    monkeypatch.setattr(io.os, "replace", interrupted)
    with pytest.raises(KeyboardInterrupt):
        io.write_all({tmp_path / "a.txt": "a", tmp_path / "b.txt": "b"})
    monkeypatch.setattr(io.os, "replace", real)
    assert list(tmp_path.iterdir()) == []


def test_check_writes_nothing_when_its_sheets_fail(tmp_path, monkeypatch, capsys):
    import drawings.check_sheet as cs
    from plans.errors import OutputError

    _write(tmp_path / "scene.toml", SCENE)
    check = _write(tmp_path / "check.toml", (DATA / "check.toml").read_text(encoding="utf-8"))

    def broken(*args, **kwargs):
        raise OutputError("the sheet cannot be drawn")

    monkeypatch.setattr(cs, "render_check_sheets", broken)
    before = sorted(p.name for p in tmp_path.rglob("*"))
    status = main(["check", str(check), "--json", str(tmp_path / "c.json"), "--csv", str(tmp_path / "c.csv"),
                   "--sheet", str(tmp_path / "sheets")])
    assert status == 2
    assert sorted(p.name for p in tmp_path.rglob("*")) == before
    assert len(capsys.readouterr().err.splitlines()) == 1


def test_check_with_sheets_writes_everything(tmp_path, capsys):
    _write(tmp_path / "scene.toml", SCENE)
    check = _write(tmp_path / "check.toml", (DATA / "check.toml").read_text(encoding="utf-8"))
    assert main(["check", str(check), "--json", str(tmp_path / "c.json"), "--sheet", str(tmp_path / "s"),
                 "--quiet"]) == 0
    assert (tmp_path / "c.json").exists()
    assert {p.suffix for p in (tmp_path / "s").iterdir()} >= {".svg"}


# --------------------------------------------------------------------------- markup and local files

HOSTILE_NAME = '<script>alert(1)</script><image href="file:///etc/passwd"/>&amp;'


def test_markup_in_names_stays_text_on_the_sheet(tmp_path, capsys):
    text = (SCENE.replace('title = "Base slider-crank"', f"title = '{HOSTILE_NAME}'")
            .replace('name = "rod AB"', f"name = '{HOSTILE_NAME}'")
            .replace('name = "F_c"', "name = '<F&c>'"))
    scene = _write(tmp_path / "x.toml", text)
    out = tmp_path / "out"
    assert main(["draw", str(scene), "-o", str(out)]) == 0
    svgs = sorted(out.glob("*.svg"))
    assert svgs
    found = False
    for p in svgs:
        raw = p.read_text(encoding="utf-8")
        root = ET.fromstring(raw)  # well-formed
        for el in root.iter():
            assert not el.tag.endswith("script") and not el.tag.endswith("image")
            for value in el.attrib.values():
                assert "file:" not in value and "passwd" not in value
        found = found or "&lt;script&gt;" in raw
    assert found, "the title is drawn as text"


def test_the_renderer_never_reads_local_files(tmp_path):
    secret = tmp_path / "secret.png"
    secret.write_bytes(export.png_bytes(b'<svg xmlns="http://www.w3.org/2000/svg" width="10" height="10">'
                                        b'<rect width="10" height="10" fill="red"/></svg>', 96))
    blank = b'<svg xmlns="http://www.w3.org/2000/svg" width="10" height="10"></svg>'
    evil = (b'<svg xmlns="http://www.w3.org/2000/svg" xmlns:xlink="http://www.w3.org/1999/xlink" width="10" '
            b'height="10"><image xlink:href="' + secret.as_uri().encode() + b'" width="10" height="10"/></svg>')
    assert export.png_bytes(evil, 96) == export.png_bytes(blank, 96)


# --------------------------------------------------------------------------- angles, keys


def test_a_huge_crank_angle_is_reduced_exactly():
    big = 1.234567e21
    reduced = math.fmod(big, 360.0)
    assert 255 < reduced < 257  # the crank is at 256°, not at 0°
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        sc = parse_scene(SCENE.replace("phi_deg = [30, 120]", f"phi_deg = [{big!r}, {reduced!r}]"))
        rot = sc.driver.rotation(np.array(sc.driver.phis_deg))
    assert abs(rot[0] - rot[1]) < 1e-15
    assert abs(rot[1] - np.exp(1j * np.radians(reduced))) < 1e-12
    assert reduce_deg(-30.0) == 330.0 and reduce_deg(big) == reduced


def test_did_you_mean_and_the_shared_key_check():
    assert str(did_you_mean("omega_rmp", ["omega", "omega_rpm", "eps"])) == "; did you mean 'omega_rpm'?"
    assert str(did_you_mean("output", ["outputs", "title"])) == "; did you mean 'outputs'?"
    assert did_you_mean("zzz", ["outputs"]) == ""
    from plans.errors import InputError

    with pytest.raises(InputError, match=r"f.toml: pair.z_1: unknown key; did you mean 'z1'"):
        check_keys({"z_1": 20}, ("z1", "z2", "module"), file="f.toml", where="pair.")
    r = Reader("f.toml")
    with pytest.raises(InputError, match="at most"):
        r.value(10**400, "x")
    with pytest.raises(InputError, match="finite"):
        r.length("1e400 mm", "x", "mm")


# --------------------------------------------------------------------------- end to end: pipe and Ctrl-C


def _plans(*args: str, **kw) -> subprocess.Popen:
    env = dict(os.environ, PYTHONPATH=str(ROOT))
    return subprocess.Popen([sys.executable, "-m", "drawings.cli", *args], cwd=ROOT, env=env,
                            stdout=subprocess.PIPE, stderr=subprocess.PIPE, **kw)


def test_solve_into_head_ends_quietly():
    proc = _plans("solve", "samples/six_bar.toml", "--protocol")
    assert proc.stdout is not None and proc.stderr is not None
    proc.stdout.readline()
    proc.stdout.close()
    err = proc.stderr.read().decode()
    assert proc.wait(timeout=60) == 0
    assert err == ""


def test_ctrl_c_stops_quietly_with_130(tmp_path):
    scene = _write(tmp_path / "x.toml", SCENE.replace("phi_deg = [30, 120]", "positions = 3600"))
    env = dict(os.environ, PYTHONPATH=str(ROOT))
    code = ("import sys, drawings.cli\nprint('ready', flush=True)\n"
            f"sys.exit(drawings.cli.main(['solve', {str(scene)!r}, '--json', {str(tmp_path / 'r.json')!r}]))")
    proc = subprocess.Popen([sys.executable, "-c", code], cwd=ROOT, env=env, stdout=subprocess.PIPE,
                            stderr=subprocess.PIPE)
    assert proc.stdout is not None
    assert proc.stdout.readline() == b"ready\n"  # imports done: Ctrl-C while solving
    time.sleep(0.5)
    proc.send_signal(signal.SIGINT)
    out, err = proc.communicate(timeout=120)
    if proc.returncode == 0:  # finished before the signal: nothing to assert about Ctrl-C
        pytest.skip("the solve finished before Ctrl-C")
    assert proc.returncode == 130
    assert b"Traceback" not in err and err.strip() == b""
    assert sorted(p.name for p in tmp_path.iterdir()) == ["x.toml"]


def test_ctrl_c_while_the_command_loads_stops_quietly_with_130():
    # A real SIGINT, sent while the command's modules are being imported.
    code = ("import os, signal, sys\n"
            # as in a terminal: a shell that starts a job in the background leaves SIGINT ignored
            "signal.signal(signal.SIGINT, signal.default_int_handler)\n"
            "class Interrupt:\n"
            "    def find_spec(self, name, path=None, target=None):\n"
            "        if name == 'plans.cli':\n"
            "            os.kill(os.getpid(), signal.SIGINT)\n"
            "        return None\n"
            "sys.meta_path.insert(0, Interrupt())\n"
            "from drawings.console import main\n"
            "sys.exit(main())\n")
    env = dict(os.environ, PYTHONPATH=str(ROOT))
    proc = subprocess.run([sys.executable, "-c", code, "solve", "samples/slider_crank.toml"], cwd=ROOT, env=env,
                          capture_output=True, timeout=60)
    assert proc.returncode == 130
    assert proc.stderr == b"" and proc.stdout == b""


def test_console_script_runs_the_command():
    env = dict(os.environ, PYTHONPATH=str(ROOT))
    proc = subprocess.run([sys.executable, "-c", "import sys; from drawings.console import main; sys.exit(main())",
                           "solve", "samples/slider_crank.toml", "--quiet"], cwd=ROOT, env=env,
                          capture_output=True, timeout=60)
    assert proc.returncode == 0 and proc.stderr == b""


@pytest.mark.parametrize("name", ["slider_crank", "six_bar", "v_engine_cycle", "dynamics_slider_crank"])
def test_json_written_in_pieces_is_the_whole_json_to_the_byte(name):
    from plans.io import dumps
    from plans.kinematics.placing import load_scene
    from plans.results import solve_scene, to_json, write_json

    sol = solve_scene(load_scene(ROOT / "samples" / f"{name}.toml"))
    pieces: list[str] = []
    write_json(sol, pieces.append)
    assert len(pieces) > sol.kinematics.n  # one piece per position, not one string
    assert "".join(pieces) == dumps(to_json(sol))
