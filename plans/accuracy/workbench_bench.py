"""The workbench's goals for ``plans bench``: an edit's round trip on a 12-position scene
(the server's share and the whole, to the new plans drawn in headless Chromium) and the
start of ``plans serve`` to its first page, measured by the renderer's side
(:func:`drawings.workbench.bench.figures`, registered in :data:`FIGURES` when the drawing
package builds ``plans bench``: the engine never imports the server).  The round trip is
timed in this process; the start of ``plans serve`` is a command's start, timed as one.

Run alone: ``plans bench`` of the drawing package (the goals of a full run).
"""

from __future__ import annotations

import math
from collections.abc import Callable
from pathlib import Path
from typing import Any

from plans.accuracy.timing import Goal

#: The renderer's timer of the workbench: (scene path) -> figures.
FIGURES: list[Callable[[Path], dict[str, Any]]] = []

SERVER_SHARE_S = 0.020  # the TOML edited and the scene solved again, answered as JSON
ROUND_TRIP_S = 0.100  # a changed length to the new plans drawn in the page
START_S = 1.0  # ``plans serve`` to its first page


def workbench_goals(samples: Path) -> list[Goal]:
    scene = samples / "four_bar.toml"
    if not FIGURES:
        return [Goal("workbench", "skipped: the renderer is not installed (plans bench of the drawings package)",
                     math.nan, None)]
    try:
        fig = FIGURES[0](scene.resolve())
    except Exception as exc:  # noqa: BLE001 - report, never break the benchmark
        return [Goal("workbench", f"skipped: {type(exc).__name__}: {exc}", math.nan, None)]
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
