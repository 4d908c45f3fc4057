"""A cam solved once for every reader: what the cam sheet draws, each part computed the
first time it is read and kept by this object (the cam itself stays a frozen record).

``plans.solve("cam.toml")`` (or :func:`solve_cam`) gives a :class:`CamSolution`; the sheet
(``drawings.cams``) reads it and computes nothing of the cam.
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import replace
from functools import cached_property
from pathlib import Path

import numpy as np

from .analysis import Findings, Motion, Profile, findings, grid, motion, profile
from .base_radius import (
    BaseRadius,
    allowed_region,
    division_points,
    min_base_radius,
    roller_base_radius,
)
from .graphical import Integration, integrate_cam
from .model import Cam, load_cam
from .rocker import RockerDiagram, diagram, region

#: The step of the fine grid the sheet draws its curves on (degrees).
FINE_DEG = 0.5


class CamSolution:
    """The cam's motion, graphical integration, base radius (exact and as drawn), profile by
    inversion and findings, each made when first read."""

    def __init__(self, cam: Cam) -> None:
        self.cam = cam
        self._regions: dict[tuple[str, tuple[float, ...]], list[tuple[float, float]]] = {}

    def __repr__(self) -> str:
        return f"CamSolution({self.cam.path!r})"

    @cached_property
    def fine(self) -> np.ndarray:
        """The fine grid of φ (rad) without 360°, the rocker's diagram and region are drawn on."""
        return grid(self.cam, FINE_DEG)

    @cached_property
    def turn(self) -> np.ndarray:
        """The fine grid closed at 360° (rad): the curves over the whole turn."""
        return np.append(self.fine, 2 * np.pi)

    @cached_property
    def motion(self) -> Motion:
        """s, ds/dφ, d²s/dφ² over :attr:`turn`."""
        return motion(self.cam, self.turn)

    @cached_property
    def integration(self) -> Integration:
        """a(φ) integrated twice by mid-ordinates and a pole, as the course does it."""
        return integrate_cam(self.cam)

    @cached_property
    def integration_error(self) -> float:
        """The largest |Δs| of the graphical s at its nodes against the exact law (m or rad)."""
        ig = self.integration
        return float(np.max(np.abs(ig.s_nodes - motion(self.cam, ig.nodes % (2 * np.pi)).s)))

    @cached_property
    def division(self) -> np.ndarray:
        """The draftsman's division points of the phases (rad)."""
        return division_points(self.cam)

    @cached_property
    def division_diagram(self) -> tuple[tuple[float, float], ...]:
        """(−k·ds/dφ, s) at each division point: the points marked on the ds/dφ–s diagram."""
        cam = self.cam
        out = []
        for q in self.division:
            one = motion(cam, np.array([q]))
            out.append((float(-cam.sense * one.s1[0]), float(one.s[0])))
        return tuple(out)

    @cached_property
    def profile(self) -> Profile:
        """The theoretical and actual profile over :attr:`turn`."""
        return profile(self.cam, self.turn)

    @cached_property
    def division_profile(self) -> Profile:
        """The profile at the division points: the follower's positions turned by −φ."""
        return profile(self.cam, self.division)

    def profile_at(self, phi: np.ndarray) -> Profile:
        """The profile at the angles ``phi`` (rad): a key's chosen positions."""
        return profile(self.cam, phi)

    @cached_property
    def table_profile(self) -> Profile:
        """The profile on the table's grid (``plans cam`` JSON's ``phi_deg``)."""
        return profile(self.cam, grid(self.cam))

    @cached_property
    def roller_base_radius(self) -> float | None:
        """The least base radius raised until the roller fits (None: no least radius)."""
        r0 = self.base_radius.min_base_radius
        return None if r0 is None else roller_base_radius(self.cam, r0)

    @cached_property
    def best_roller_base_radius(self) -> float | None:
        """The best offset kept, the base radius raised until the roller fits (None: no best offset)."""
        br = self.base_radius
        if br.best_offset is None:
            return None
        return roller_base_radius(replace(self.cam, offset=br.best_offset), br.best_base_radius)

    @cached_property
    def base_radius(self) -> BaseRadius:
        """The least base radius, exact."""
        return min_base_radius(self.cam, True)

    @cached_property
    def drawn_base_radius(self) -> BaseRadius | None:
        """The least base radius from the diagram at the division points (None: a flat face)."""
        return None if self.cam.flat else min_base_radius(self.cam, False)

    @cached_property
    def findings(self) -> Findings:
        """The largest pressure angles, the least radius of curvature, undercut."""
        return findings(self.cam)

    @cached_property
    def rocker(self) -> RockerDiagram:
        """The oscillating follower's diagram at the division points."""
        return diagram(self.cam, self.division)

    @cached_property
    def rocker_fine(self) -> RockerDiagram:
        """The oscillating follower's diagram on the fine grid (its curve of D)."""
        return diagram(self.cam, self.fine)

    def allowed_region(self, box: tuple[float, float, float, float]) -> list[tuple[float, float]]:
        """The translating follower's region of allowed centres within ``box`` (m)."""
        bounds = self.base_radius.bounds
        assert bounds is not None
        return self._region("translating", box, lambda: allowed_region(bounds, box))

    def rocker_region(self, box: tuple[float, float, float, float]) -> list[tuple[float, float]]:
        """The oscillating follower's region of allowed centres within ``box`` (m)."""
        return self._region("oscillating", box, lambda: region(self.cam, self.fine, box))

    def _region(self, kind: str, box: tuple[float, float, float, float],
                make: Callable[[], list[tuple[float, float]]]) -> list[tuple[float, float]]:
        key = (kind, tuple(float(x) for x in box))
        got = self._regions.get(key)
        if got is None:
            got = self._regions[key] = make()
        return list(got)


def solve_cam(source: Cam | str | Path) -> CamSolution:
    """A cam (or the path of its file) solved: parts computed when first read."""
    return CamSolution(source if isinstance(source, Cam) else load_cam(source))


__all__ = ["CamSolution", "FINE_DEG", "solve_cam"]
