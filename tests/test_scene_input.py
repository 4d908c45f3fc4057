"""Bad input: one line naming file and field, exit status 2, nothing written."""

from __future__ import annotations

import copy
import json
import subprocess
import sys
from pathlib import Path

import pytest

from plans.cli import main
from plans.errors import InputError
from plans.kinematics.placing import scene_from_dict
from plans.kinematics.structure import analyse

from .conftest import slider_crank_scene


def _toml(d: dict) -> str:
    """A tiny TOML writer for the scene dicts used here."""
    def val(v):
        if isinstance(v, bool):
            return "true" if v else "false"
        if isinstance(v, str):
            return json.dumps(v)
        if isinstance(v, list):
            return "[" + ", ".join(val(x) for x in v) + "]"
        if isinstance(v, dict):
            return "{ " + ", ".join(f"{json.dumps(k)} = {val(x)}" for k, x in v.items()) + " }"
        return repr(v)

    lines = [f"{k} = {val(v)}" for k, v in d.items() if not isinstance(v, dict | list) or
             (isinstance(v, list) and not (v and isinstance(v[0], dict)))]
    for k, v in d.items():
        if isinstance(v, dict):
            if k == "links":
                for lid, body in v.items():
                    lines.append(f"[links.{lid}]")
                    lines += [f"{kk} = {val(vv)}" for kk, vv in body.items()]
            else:
                lines.append(f"[{k}]")
                lines += [f"{json.dumps(kk)} = {val(vv)}" for kk, vv in v.items()]
        elif isinstance(v, list) and v and isinstance(v[0], dict):
            for item in v:
                lines.append(f"[[{k}]]")
                lines += [f"{kk} = {val(vv)}" for kk, vv in item.items()]
    return "\n".join(lines) + "\n"


def _run(tmp_path: Path, text: str, capsys, *extra, good: bool = False) -> tuple[int, str]:
    f = tmp_path / "scene.toml"
    f.write_text(text, encoding="utf-8")
    out = tmp_path / "out.json"
    code = main(["solve", str(f), "--json", str(out), "--quiet", *extra])
    err = capsys.readouterr().err
    assert out.exists() == good, "output only for good input"
    assert not list(tmp_path.glob(".out.json*")), "no temporary file may be left"
    return code, err


def test_round_trip_of_the_test_writer(tmp_path, capsys):
    code, err = _run(tmp_path, _toml(slider_crank_scene()), capsys, good=True)
    assert code == 0 and err == ""


BAD = [
    ("malformed", lambda d: None, "format = 1\n[links\n", r"scene\.toml.*malformed TOML.*line 2"),
    ("unknown point", lambda d: d["joints"][1].update(point="Q"), None, r"\[\[joints\]\] entry 2, point: point 'Q' is not on link 1"),
    ("zero length", lambda d: d["links"]["2"].update(length=0), None, r"links\.2\.length: expected a positive length"),
    ("negative length", lambda d: d["links"]["1"].update(length=-5), None, r"links\.1\.length: expected a positive length"),
    ("mobility", lambda d: d["joints"].append({"kind": "R", "links": [2, 4], "point": "O"}) or d["links"]["2"].update(points={"O": {"along": 10}}), None, r"joints: mobility W = .* expected W = 1"),
    ("unknown output", lambda d: d.update(outputs=["velocity_plan", "vibes"]), None, r"outputs: unknown output 'vibes'"),
    ("angle not a number", lambda d: d["driver"].update(phi_deg=["forty"]), None, r"driver\.phi_deg: expected a number of degrees"),
    ("unknown link", lambda d: d["joints"][0].update(links=[9, 1]), None, r"\[\[joints\]\] entry 1, links: unknown link 9"),
    ("format", lambda d: d.update(format=2), None, r"format: expected format = 1"),
    ("bad unit", lambda d: d.update(unit="inch"), None, r"unit: expected one of"),
    ("length unit", lambda d: d["links"]["2"].update(length="180 furlong"), None, r"links\.2\.length: expected a length"),
]


@pytest.mark.parametrize("name,edit,raw,pattern", BAD, ids=[b[0] for b in BAD])
def test_bad_input_is_one_line_exit_2(tmp_path, capsys, name, edit, raw, pattern):
    d = copy.deepcopy(slider_crank_scene())
    edit(d)
    code, err = _run(tmp_path, raw if raw is not None else _toml(d), capsys)
    assert code == 2
    assert err.count("\n") == 1 and "Traceback" not in err
    assert "scene.toml" in err
    import re
    assert re.search(pattern, err), err


def test_missing_file(tmp_path, capsys):
    code = main(["solve", str(tmp_path / "nope.toml")])
    err = capsys.readouterr().err
    assert code == 2 and "nope.toml" in err and "cannot read" in err


def test_not_assemblable_is_exit_2(tmp_path, capsys):
    code, err = _run(tmp_path, _toml(slider_crank_scene(50, 100, 140, phi_deg=[270])), capsys)
    assert code == 2 and "group RRP 2-3, point B, phi = 270 deg" in err


def test_structure_of_samples():
    from plans.kinematics.placing import load_scene

    kinds = {p: [g.kind for g in analyse(load_scene(f"samples/{p}.toml")).groups]
             for p in ("v_engine", "slider_crank", "four_bar", "shaper", "six_bar", "scotch_yoke")}
    assert kinds == {"v_engine": ["RRP", "RRP"], "slider_crank": ["RRP"], "four_bar": ["RRR"],
                     "shaper": ["RPR", "RRP"], "six_bar": ["RPR", "PRP"], "scotch_yoke": ["RPP"]}


def test_mirror_group_is_turned_round():
    """A slider-crank written with the slider first (PRR) is recognised as RRP."""
    d = slider_crank_scene()
    d["links"] = {"1": d["links"]["1"], "2": {"axis": ["B"]},
                  "3": {"axis": ["A", "B"], "length": 180}}
    d["joints"] = [
        {"kind": "R", "links": [4, 1], "point": "O"},
        {"kind": "R", "links": [1, 3], "point": "A"},
        {"kind": "R", "links": [3, 2], "point": "B"},
        {"kind": "P", "links": [2, 4], "point": "B", "guide": {"link": 4, "through": [0, 0], "angle_deg": 0}},
    ]
    g = analyse(scene_from_dict(d)).groups[0]
    assert g.kind == "RRP" and g.links == (3, 2)


def test_input_error_carries_field():
    d = slider_crank_scene()
    d["links"]["2"]["length"] = -1
    with pytest.raises(InputError) as exc:
        scene_from_dict(d, "x.toml")
    assert exc.value.field == "links.2.length" and exc.value.file == "x.toml"


def test_console_command_runs_as_a_new_user_would(tmp_path):
    out = tmp_path / "v.json"
    r = subprocess.run([sys.executable, "-m", "plans", "solve", "samples/v_engine.toml", "--json", str(out)],
                       capture_output=True, text=True, cwd=Path(__file__).parent.parent)
    assert r.returncode == 0, r.stderr
    assert "v_B" in r.stdout and "phi = 0 deg" in r.stdout
    assert json.loads(out.read_text())["positions"][1]["phi_deg"] == 0.0
