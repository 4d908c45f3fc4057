"""The workbench's goals for ``plans bench``: an edit's round trip on a 12-position scene
(the server's share and the whole, to the new plans drawn in headless Chromium) and the
start of ``plans serve`` to its first page, measured by the renderer's side in a fresh
interpreter (the engine never imports the server).

Run alone: ``python -m plans.accuracy.workbench_bench``.
"""

from __future__ import annotations

import json
import math
import subprocess
import sys
from pathlib import Path

from plans.accuracy.timing import Goal, interpreter_env

SERVER_SHARE_S = 0.020  # the TOML edited and the scene solved again, answered as JSON
ROUND_TRIP_S = 0.100  # a changed length to the new plans drawn in the page
START_S = 1.0  # ``plans serve`` to its first page


def workbench_goals(samples: Path) -> list[Goal]:
    scene = samples / "four_bar.toml"
    root = Path(__file__).resolve().parents[2]
    p = subprocess.run([sys.executable, "-m", "drawings.workbench.bench", str(scene)], cwd=root,
                       capture_output=True, text=True, env=interpreter_env())
    if p.returncode != 0:
        why = (p.stderr.strip().splitlines() or [f"exit status {p.returncode}"])[-1]
        return [Goal("workbench", f"skipped: {why}", math.nan, None)]
    fig = json.loads(p.stdout)
    n = fig["positions"]
    out = [Goal(f"workbench edit round trip, {n} positions: the server's share ≤ {SERVER_SHARE_S * 1000:g} ms",
                f"{fig['server_s'] * 1000:.1f} ms (processor time {fig['server_cpu_s'] * 1000:.1f} ms; "
                f"with loopback HTTP {fig['loopback_s'] * 1000:.1f} ms; "
                f"{fig['answer_bytes'] / 1e3:.0f} kB of JSON)",
                fig["server_s"] / SERVER_SHARE_S, fig["server_s"] <= SERVER_SHARE_S)]
    page = fig.get("page_s")
    what = f"workbench edit round trip, {n} positions: new plans drawn in the page in ≤ {ROUND_TRIP_S * 1000:g} ms"
    if page is None:
        out.append(Goal(what, "skipped: Chromium or Playwright not installed", math.nan, None))
    else:
        out.append(Goal(what, f"{page * 1000:.1f} ms", page / ROUND_TRIP_S, page <= ROUND_TRIP_S))
    out.append(Goal(f"plans serve to its first page in ≤ {START_S:g} s", f"{fig['start_s']:.3f} s",
                    fig["start_s"] / START_S, fig["start_s"] <= START_S))
    return out


if __name__ == "__main__":
    for g in workbench_goals(Path(__file__).resolve().parents[2] / "samples"):
        print(g.line())
