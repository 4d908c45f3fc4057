"""The force drawings over the cycle: each group's polygon, the crank's, and the lever, at
every frame of the page's cycle, from the engine's own constructions.

A drawing keeps one scale over the whole turn (a polygon's μF is chosen per position on a
sheet; here it is the round μF that keeps the largest polygon of the turn within the panel),
so the page can move it smoothly from frame to frame.  A vector is a track of its two ends,
one entry per frame (None where it is not drawn at that position: a zero force, a crank
standing still); the page interpolates between frames and solves nothing.
"""

from __future__ import annotations

from collections.abc import Callable, Sequence
from typing import Any

import numpy as np

from plans.demo.mistakes import page_mm
from plans.forces.lever import LeverAnalysis
from plans.forces.polygons import ForceAnalysis, ForcePolygon, force_polygons
from plans.kinematics.plan import Plan
from plans.kinematics.scales import round_scale

#: Largest extent of a drawing in the cycle's panels, mm.
PANEL_MM = 80.0


def _ends(plan: Plan) -> dict[str, tuple[complex, complex]]:
    """Each vector of a polygon in newtons (ends relative to the pole), named by its label
    (a label met again is numbered: the page matches vectors by name across frames)."""
    out: dict[str, tuple[complex, complex]] = {}
    for s in plan.segments:
        a, b = complex(*plan.xy(s.start)) / plan.scale, complex(*plan.xy(s.end)) / plan.scale
        key, n = s.label, 1
        while key in out:
            n += 1
            key = f"{s.label}#{n}"
        out[key] = (a, b)
    return out


def _track(values: list[tuple[complex, complex] | None], mu: float) -> list[list[float] | None]:
    return [None if v is None else [page_mm(v[0].real * mu), page_mm(v[0].imag * mu),
                                    page_mm(v[1].real * mu), page_mm(v[1].imag * mu)] for v in values]


def _polygons(fa: ForceAnalysis, drawn: Callable[[int], Sequence[ForcePolygon]] | None) -> list[dict[str, Any]]:
    n = fa.kin.n
    frames = [force_polygons(fa, k) if drawn is None else drawn(k) for k in range(n)]
    out = []
    for g, poly in enumerate(frames[0]):
        name = "crank" if poly.kind == "crank" else f"group {poly.group}"
        ends = [_ends(fr[g].plan) for fr in frames]
        kinds: dict[str, str] = {}
        for fr, e in zip(frames, ends, strict=True):
            for key, s in zip(e, fr[g].plan.segments, strict=True):
                kinds.setdefault(key, s.kind)
        extent = max([abs(z) for e in ends for v in e.values() for z in v] + [0.0])
        mu = round_scale(extent, PANEL_MM)
        segs = [{"label": key.split("#")[0], "kind": kind, "track": _track([e.get(key) for e in ends], mu)}
                for key, kind in kinds.items()]
        out.append({"id": name.replace(" ", "-"), "name": name, "kind": "force", "scale": mu, "unit": "mm/N",
                    "segments": segs})
    return out


def _lever(lv: LeverAnalysis) -> dict[str, Any]:
    """The lever over the turn: the turned plan's images at the lever's μv (as the engine
    draws them) and each force at one round μF for the whole turn."""
    valid = np.asarray(lv.valid, bool)
    fmax = max([float(np.max(np.abs(it.F[valid]))) for it in lv.forces if valid.any()] + [0.0])
    mu_f = round_scale(fmax, 30.0)
    points: dict[str, list[list[float] | None]] = {}
    segs = []
    for it in lv.forces:
        w = np.asarray(it.w, complex)
        if it.point not in points:
            points[it.point] = [[page_mm(z.real), page_mm(z.imag)] if ok else None
                                for z, ok in zip(w, valid, strict=True)]
        F = np.asarray(it.F, complex)
        ends = [(z, z + f * mu_f) if ok and f != 0 else None for z, f, ok in zip(w, F, valid, strict=True)]
        segs.append({"label": it.label, "kind": "force", "track": _track(ends, 1.0)})
    wb = np.asarray(lv.w_bal, complex)
    points.setdefault(lv.bal_point, [[page_mm(z.real), page_mm(z.imag)] if ok else None
                                     for z, ok in zip(wb, valid, strict=True)])
    return {"id": "lever", "name": "lever", "kind": "lever", "scale": lv.scale, "unit": "mm/(m/s)",
            "force_scale": mu_f, "points": points, "segments": segs}


def cycle_forces(fa: ForceAnalysis, lv: LeverAnalysis,
                 drawn: Callable[[int], Sequence[ForcePolygon]] | None = None) -> list[dict[str, Any]]:
    """The polygons (groups farthest first, then the crank) and the lever over the frames;
    ``drawn(k)``: the polygons of position k as a solution keeps them (``Solution.force_polygons``,
    which the workbench reads), else they are drawn here from ``fa``."""
    return _polygons(fa, drawn) + [_lever(lv)]


__all__ = ["PANEL_MM", "cycle_forces"]
