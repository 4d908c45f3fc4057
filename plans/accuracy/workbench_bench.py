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
from plans.phrases import phrase

#: The renderer's timer of the workbench: (scene path) -> figures.
FIGURES: list[Callable[[Path], dict[str, Any]]] = []

SERVER_SHARE_S = 0.020  # the TOML edited and the scene solved again, answered as JSON
ROUND_TRIP_S = 0.100  # a changed length to the new plans drawn in the page
START_S = 1.0  # ``plans serve`` to its first page


def workbench_goals(samples: Path) -> list[Goal]:
    scene = samples / "four_bar.toml"
    if not FIGURES:
        return [Goal(phrase("bq_workbench_short"), phrase("bq_no_renderer"), math.nan, None)]
    try:
        fig = FIGURES[0](scene.resolve())
    except Exception as exc:  # noqa: BLE001 - report, never break the benchmark
        return [Goal(phrase("bq_workbench_short"), phrase("bq_failed", error=f"{type(exc).__name__}: {exc}"),
                     math.nan, None)]
    n = fig["positions"]
    out = [Goal(phrase("bq_server", n=n, bound=SERVER_SHARE_S * 1000),
                phrase("bq_server_got", t=fig["server_s"] * 1000, cpu=fig["server_cpu_s"] * 1000,
                       http=fig["loopback_s"] * 1000, kb=fig["answer_bytes"] / 1e3),
                fig["server_s"] / SERVER_SHARE_S, fig["server_s"] <= SERVER_SHARE_S)]
    page = fig.get("page_s")
    what = phrase("bq_round_trip", n=n, bound=ROUND_TRIP_S * 1000)
    if page is None:
        out.append(Goal(what, phrase("bq_no_browser"), math.nan, None))
    else:
        out.append(Goal(what, phrase("bq_ms", t=page * 1000), page / ROUND_TRIP_S, page <= ROUND_TRIP_S))
    out.append(Goal(phrase("bq_serve", bound=START_S), phrase("bq_seconds3", t=fig["start_s"]),
                    fig["start_s"] / START_S, fig["start_s"] <= START_S))
    return out
