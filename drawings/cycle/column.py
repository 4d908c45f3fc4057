"""The dynamics sheet's diagrams over φ in one column, as a course draws them: M_пр, A, ΔT,
I_пр and ω one under another, their φ axes from one vertical (the same origin, length and
μ_φ), so that a vertical through a position crosses every diagram at that position."""

from __future__ import annotations

from collections.abc import Callable, Sequence

from drawings.paper.backend import Prim
from drawings.paper.panel_frame import Panel

#: The diagrams over φ, top to bottom, by their panels' ids.
PHI_PANELS = ("dyn-M", "dyn-A", "dyn-T", "dyn-I", "dyn-w")
#: mm between one diagram's panel and the next in the column.
GAP = 4.0


def axis_origin(panel: Panel) -> tuple[float, float]:
    """Where a diagram's φ axis starts (the origin of its axes), in the panel's mm: the
    shaft of its ``<pid>-xaxis`` arrow starts exactly there."""
    prims = panel.prims
    k = next(i for i, p in enumerate(prims) if p.op == "begin" and p.eid == f"{panel.pid}-xaxis")
    return prims[k + 1].pts[0]


def stacked(panels: Sequence[Panel]) -> Panel:
    """The panels one under another, moved sideways so that their φ axes' origins are on one
    vertical."""
    left = max(axis_origin(p)[0] for p in panels)
    prims: list[Prim] = [Prim("begin", eid="dyn-column", cls="panel dynamics")]
    y = 0.0
    width = 0.0
    for p in panels:
        dx = left - axis_origin(p)[0]
        prims += p.at(dx, y)
        width = max(width, dx + p.width)
        y += p.height + GAP
    prims.append(Prim("end"))
    return Panel("dyn-column", "dynamics", None, tuple(prims), width, y - GAP, panels[0].title)


def column_fits(panels: Sequence[Panel], fits: Callable[[Panel], bool]) -> bool:
    """Whether all of the diagrams over φ among ``panels`` stacked fit an empty sheet."""
    phi = [p for pid in PHI_PANELS for p in panels if p.pid == pid]
    return len(phi) < 2 or fits(stacked(phi))


def phi_column(panels: Sequence[Panel], fits: Callable[[Panel], bool]) -> list[Panel]:
    """``panels`` with their diagrams over φ in one column in the first one's place, as many
    of them from the top (M_пр first) as an empty sheet holds (``fits``); unchanged where
    fewer than two do."""
    by_id = {p.pid: p for p in panels}
    phi = [by_id[pid] for pid in PHI_PANELS if pid in by_id]
    while len(phi) > 1 and not fits(stacked(phi)):
        phi = phi[:-1]
    if len(phi) < 2:
        return list(panels)
    inside = {p.pid for p in phi}
    out: list[Panel] = []
    for p in panels:
        if p.pid == phi[0].pid:
            out.append(stacked(phi))
        elif p.pid not in inside:
            out.append(p)
    return out
