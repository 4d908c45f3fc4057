"""``plans draw``: the console command, its errors, and atomic writing."""

from __future__ import annotations

import os
from pathlib import Path

import pytest

from drawings.cli import build_parser, main
from drawings.paper.export import OutputError, atomic_write

ROOT = Path(__file__).resolve().parents[1]
V_ENGINE = ROOT / "samples" / "v_engine.toml"


def test_draw_writes_every_requested_format(tmp_path, capsys):
    rc = main(["draw", str(V_ENGINE), "-o", str(tmp_path), "--format", "svg,pdf,png", "--dpi", "10"])
    assert rc == 0
    out = capsys.readouterr().out.split()
    assert out and all(Path(p).exists() for p in out)
    assert {Path(p).suffix for p in out} == {".svg", ".pdf", ".png"}


def test_parser_keeps_the_engine_commands():
    parser = build_parser()
    args = parser.parse_args(["draw", "x.toml", "-o", "out", "--sheet", "A3"])
    assert args.sheet == "A3" and args.format == ["svg"]
    sub = parser.parse_args(["solve", str(V_ENGINE), "--quiet"])
    assert sub.command == "solve"


@pytest.mark.parametrize("argv, message", [
    (["--sheet", "B5"], "unknown sheet format 'B5'"),
    (["--sheet", "A4"], "does not fit on an empty A4"),
])
def test_user_errors_are_one_line_exit_2(tmp_path, capsys, argv, message):
    scene = tmp_path.parent / f"{tmp_path.name}-fixed.toml"  # a velocity scale of the file's own: kept
    scene.write_text(V_ENGINE.read_text(encoding="utf-8") + "\n[scales]\nvelocity = { mu = 10 }\n",
                     encoding="utf-8")
    rc = main(["draw", str(scene), "-o", str(tmp_path)] + argv)
    err = capsys.readouterr().err
    assert rc == 2
    assert err.count("\n") == 1 and message in err and "Traceback" not in err
    assert not list(tmp_path.iterdir())  # nothing half-written


def test_missing_scene_is_one_line(tmp_path, capsys):
    rc = main(["draw", str(tmp_path / "nope.toml"), "-o", str(tmp_path)])
    err = capsys.readouterr().err
    assert rc == 2 and err.startswith("plans: error:") and err.count("\n") == 1


@pytest.mark.skipif(os.geteuid() == 0, reason="root writes everywhere")
def test_unwritable_output_folder(tmp_path, capsys):  # pragma: no cover - CI runs as a user
    ro = tmp_path / "ro"
    ro.mkdir()
    ro.chmod(0o500)
    rc = main(["draw", str(V_ENGINE), "-o", str(ro)])
    assert rc == 2 and "cannot write" in capsys.readouterr().err


def test_output_folder_that_is_a_file(tmp_path, capsys):
    f = tmp_path / "file"
    f.write_text("x")
    rc = main(["draw", str(V_ENGINE), "-o", str(f / "sub")])
    err = capsys.readouterr().err
    assert rc == 2 and "cannot create the output folder" in err and err.count("\n") == 1


def test_bad_format_list_is_an_argparse_error(tmp_path, capsys):
    with pytest.raises(SystemExit) as exc:
        main(["draw", str(V_ENGINE), "-o", str(tmp_path), "--format", "svg,gif"])
    assert exc.value.code == 2


def test_atomic_write_leaves_nothing_on_failure(tmp_path):
    target = tmp_path / "a.svg"
    target.write_bytes(b"old")
    with pytest.raises(TypeError):
        atomic_write(target, 12345)  # type: ignore[arg-type]  # fails mid-write
    assert target.read_bytes() == b"old"
    assert [p.name for p in tmp_path.iterdir()] == ["a.svg"]
    with pytest.raises(OutputError, match="cannot write to"):
        atomic_write(tmp_path / "missing" / "a.svg", b"x")


def test_check_gets_the_sheet_options():
    parser = build_parser()
    sub = next(a for a in parser._actions if a.__class__.__name__ == "_SubParsersAction")
    if "check" not in sub.choices:  # pragma: no cover - engine without checking
        pytest.skip("plans check not present")
    args = parser.parse_args(["check", "x.toml", "--sheet", "out"])
    assert args.sheet == "out" and args.sheet_format == "svg"
