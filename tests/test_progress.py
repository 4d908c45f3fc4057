"""Long runs show progress on a terminal and stay quiet when piped or asked to."""

from __future__ import annotations

import io
import subprocess
import sys
from pathlib import Path

from plans.progress import Progress

ROOT = Path(__file__).resolve().parent.parent


class _Tty(io.StringIO):
    def isatty(self) -> bool:
        return True


def test_progress_on_a_terminal_only_and_not_when_quiet():
    tty, pipe, quiet = _Tty(), io.StringIO(), _Tty()
    for stream, q in ((tty, False), (pipe, False), (quiet, True)):
        p = Progress(q, stream)
        p("sheet 1 of 2 written")
        p("sheet 2 of 2 written")
    lines = tty.getvalue().splitlines()
    assert len(lines) == 2 and lines[1].endswith("sheet 2 of 2 written") and lines[0].startswith("[")
    assert pipe.getvalue() == "" and quiet.getvalue() == ""


def test_draw_reports_each_sheet_through_its_progress(tmp_path):
    from drawings import draw, save

    d = draw(str(ROOT / "samples" / "slider_crank.toml"))
    seen: list[str] = []
    save(d.sheets, tmp_path, "s", ("svg",), progress=seen.append)
    assert len(seen) == len(d.sheets) and seen[-1].startswith(f"sheet {len(d.sheets)} of {len(d.sheets)}")


def test_piped_draw_prints_only_the_written_files(tmp_path):
    r = subprocess.run([sys.executable, "-m", "drawings.cli", "draw", str(ROOT / "samples" / "slider_crank.toml"),
                        "-o", str(tmp_path)], cwd=ROOT, capture_output=True, text=True)
    assert r.returncode == 0
    assert r.stderr == ""
    assert all(line.endswith(".svg") for line in r.stdout.splitlines())
