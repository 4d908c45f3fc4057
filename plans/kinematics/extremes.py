"""The extreme positions of the output link and the strokes between them.

The output link (the last slider on a guide of the frame, else the last rocker hinged to
the frame) stops and turns back where its velocity changes sign; the crank angles of these
two extreme positions split the revolution into the working stroke and the idle stroke.
The working stroke is the slower one (the larger crank angle, 180° + θ); the overlap angle
θ = φ_working − 180° is the angle between the crank's two extreme positions and one
extended through the pivot, and K = (180° + θ)/(180° − θ).  Where the strokes are equal
(θ = 0) the working stroke is the one toward the crank's pivot (an engine's expansion).

Found on the exact analysis: the sign changes of the output's velocity over a revolution,
each refined by bisection to round-off.  None where the crank does not turn a whole
revolution or the output turns back more than twice a revolution.
"""

from __future__ import annotations

from typing import Any

import numpy as np

from plans.errors import PlansError
from plans.records import frozen


@frozen
class Strokes:
    """The output's two extreme positions and the strokes between them (degrees)."""

    output: str  # the slider's pin or the rocker's link, as it is named: "B", "3"
    slider: bool
    phi_start_deg: float  # φ (the driver's angle, as positions are given) where the working stroke begins
    phi_end_deg: float  # ... and ends (the idle stroke runs on from here to the start)
    working_deg: float  # the crank's angle over the working stroke
    idle_deg: float
    at: Any = None  # the exact positions (order 0) at [phi_start_deg, phi_end_deg], to draw them

    @property
    def theta_deg(self) -> float:
        """The overlap angle θ = φ_working − 180° (≥ 0)."""
        return self.working_deg - 180.0

    @property
    def K(self) -> float:
        """The coefficient of the output's speed change, t_working / t_idle."""
        return self.working_deg / self.idle_deg


def _output(scene: Any) -> tuple[str, bool, int, Any] | None:
    """(name, is slider, link, guide or None) of the output link."""
    sliders = [jt for jt in scene.joints if jt.kind == "P" and jt.guide is not None and jt.guide.link == scene.frame]
    if sliders:
        jt = max(sliders, key=lambda j: j.slider)
        return jt.point, True, jt.slider, jt.guide
    rockers = sorted(lid for jt in scene.joints if jt.kind == "R" and scene.frame in jt.links
                     for lid in jt.links if lid not in (scene.frame, scene.driver.link))
    if rockers:
        return str(rockers[-1]), False, rockers[-1], None
    return None


def strokes(scene: Any, n: int = 361) -> Strokes | None:
    """The extreme positions of the scene's output link (None where there are not two)."""
    from plans.kinematics.exact import solve

    out = _output(scene)
    if out is None:
        return None
    name, slider, link, guide = out

    def speed(phis: Any) -> Any:
        kin = solve(scene, np.asarray(phis, float), order=1)
        if slider:
            v = kin.point(name, link)[1]
            return (v * np.conj(guide.direction)).real
        return kin.omega(link)

    def travel(phis: Any) -> Any:
        kin = solve(scene, np.asarray(phis, float), order=0)
        if slider:
            return (kin.point(name, link)[0] * np.conj(guide.direction)).real
        return np.unwrap(kin.theta(link))

    grid = np.linspace(0.0, 360.0, n)
    try:
        v = speed(grid)
    except PlansError:
        return None
    sg = np.sign(v)
    # a change of sign between two nodes, or at a node where the velocity is exactly zero
    cuts = [k for k in range(n - 1) if sg[k] * sg[k + 1] < 0 or
            (sg[k] == 0 and sg[k - 1 if k else n - 2] * sg[k + 1] < 0)]
    if len(cuts) != 2:
        return None
    ends = []
    for k in cuts:
        lo, hi = float(grid[k]), float(grid[k + 1])
        f_lo = float(v[k])
        if f_lo == 0:
            ends.append(lo)
            continue
        for _ in range(60):
            mid = 0.5 * (lo + hi)
            f = float(speed([mid])[0])
            if f == 0:
                lo = hi = mid
                break
            if (f > 0) == (f_lo > 0):
                lo, f_lo = mid, f
            else:
                hi = mid
        ends.append(0.5 * (lo + hi) % 360.0)
    a, b = ends
    # φ grows with time whichever way the crank turns (θ1 = φ_ref + sense·φ)
    ab = (b - a) % 360.0
    ba = 360.0 - ab
    if abs(ab - ba) > 1e-9:
        start, end = (a, b) if ab > ba else (b, a)
    else:  # equal strokes: the working one toward the crank's pivot
        O = scene.frame_points.get(scene.driver.pivot, 0j)
        kin = solve(scene, np.array([a, b]), order=0)
        far = (np.abs(kin.point(name, link)[0] - O) if slider else travel([a, b]))
        start, end = (a, b) if far[0] >= far[1] else (b, a)
    work = (end - start) % 360.0
    at = solve(scene, np.array([start, end]), order=0)
    return Strokes(name, slider, float(start), float(end), float(work), float(360.0 - work), at)


__all__ = ["Strokes", "strokes"]
