"""The minimum base radius from the permissible pressure angle.

Translating follower, the ds/dφ–s diagram: from the follower's lowest roller centre B0
(origin, follower up) plot for every φ the point D = (−k·ds/dφ, s) (ds/dφ laid off at the
same scale as s, turned a quarter turn with the rotation).  The line from the cam centre O
to D is parallel to the normal at the contact, so the pressure angle is the angle between OD
and the follower's line.  O is allowed where every OD leans by no more than the permissible
angle: below two rays at [α] tangent to the curve on each side (rise angles with [α]rise,
return angles with [α]return).  The region is the intersection of half-planes
x − y·tan α ≥ c₁, x + y·tan α ≤ c₂; the minimum base radius for a given offset is the
highest allowed point on the line x = −e, the least of all the nearest allowed point to B0.

Oscillating follower: the base radius for the given pivot and arm, found by bisection on
the largest pressure angle over the cycle.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, replace

import numpy as np

from .analysis import FINE_STEP_DEG, clip_half_plane, grid, motion, profile
from .model import Cam

#: Equal parts of a phase in the drawn diagrams (the graphical constructions): 8, or 12 for a
#: phase longer than 90°.
DIVISIONS = 8
DIVISIONS_LONG = 12


@dataclass(frozen=True, slots=True)
class Bounds:
    """The allowed region for O (B0 at the origin): x − y·tan α ≥ c1, x + y·tan α ≤ c2,
    one pair per permissible angle (rise, return); ``tangent`` are the points D where the
    rays touch the curve."""

    lines: tuple[tuple[float, float, float], ...]  # (tan α, c1, c2)
    tangent: tuple[tuple[float, float], ...]  # D points of c1 and c2 per pair


@dataclass(frozen=True, slots=True)
class BaseRadius:
    """Minimum base radius (m) at the file's offset; the best pair (r0, e) of any offset;
    the cam centre O for each in the diagram's frame (B0 at origin; an oscillating follower:
    the fixed frame).  ``min_base_radius`` is None when no base radius keeps the pressure
    angle within the permissible (an oscillating follower with this arm and pivot)."""

    min_base_radius: float | None
    centre: tuple[float, float] | None
    best_base_radius: float
    best_offset: float | None
    best_centre: tuple[float, float]
    bounds: Bounds | None
    best_pivot: float | None = None  # oscillating: the pivot distance of the best centre


def diagram_points(cam: Cam, phi: np.ndarray) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """D = (−k·ds/dφ, s) and each angle's permissible tan α (return phases: [α]return)."""
    mo = motion(cam, phi)
    kinds = np.array([cam.phases[i].kind for i in mo.phase])
    t = np.where(kinds == "return", math.tan(cam.alpha_return), math.tan(cam.alpha_rise))
    return -cam.sense * mo.s1, mo.s, t


def _refine(cam: Cam, f, phi0: float, h: float) -> tuple[float, float]:
    """Golden-section maximum of f(φ) on [φ0 − h, φ0 + h] (f smooth within a phase)."""
    a, b = phi0 - h, phi0 + h
    g = (math.sqrt(5) - 1) / 2
    for _ in range(80):
        c, d = b - g * (b - a), a + g * (b - a)
        if f(c) >= f(d):
            b = d
        else:
            a = c
    x = (a + b) / 2
    return x, f(x)


def bounds(cam: Cam, phi: np.ndarray | None = None, exact: bool = True) -> Bounds:
    """The supporting rays; ``exact``: each extreme refined on the law itself, else taken at
    the given points only (the draftsman's division points)."""
    if phi is None:
        phi = grid(cam, FINE_STEP_DEG)
    X, Y, t = diagram_points(cam, phi)
    lines = []
    touch = []
    for tan_a in sorted(set(t.tolist())):
        m = t == tan_a
        out = [tan_a]
        for sgn in (1, -1):  # c1 = max(X − Y·t), c2 = min(X + Y·t) = −max(−X − Y·t)
            vals = np.where(m, sgn * X - Y * tan_a, -np.inf)
            i = int(np.argmax(vals))
            best, where = float(vals[i]), float(phi[i])
            if exact and len(phi) > 2:
                h = float(np.max(np.diff(phi)))
                ph = cam.phases[int(motion(cam, np.array([phi[i]])).phase[0])]
                lo, hi = ph.start, ph.start + ph.angle

                def f(p: float, sgn: int = sgn, lo: float = lo, hi: float = hi, tan_a: float = tan_a) -> float:
                    p = min(max(p, lo), hi - 1e-12)
                    x, y, _ = diagram_points(cam, np.array([p]))
                    return float(sgn * x[0] - y[0] * tan_a)

                p, v = _refine(cam, f, where, h)
                if v > best:
                    best, where = v, min(max(p, lo), hi - 1e-12)
            x, y, _ = diagram_points(cam, np.array([where]))
            touch.append((float(x[0]), float(y[0])))
            out.append(best if sgn == 1 else -best)
        lines.append((out[0], out[1], out[2]))
    return Bounds(tuple(lines), tuple(touch))


def allowed_region(b: Bounds, box: tuple[float, float, float, float]) -> list[tuple[float, float]]:
    """The allowed centres within ``box`` (x0, y0, x1, y1): the box clipped by each half-plane
    of the bounds, x − y·tan α ≥ c1 and x + y·tan α ≤ c2."""
    x0, y0, x1, y1 = box
    poly = [(x0, y0), (x1, y0), (x1, y1), (x0, y1)]
    for t, c1, c2 in b.lines:
        for a, bb, c in ((-1.0, t, -c1), (1.0, t, c2)):  # a·x + b·y ≤ c
            poly = clip_half_plane(poly, a, bb, c)
            if not poly:
                return []
    return poly


def _allowed(b: Bounds, x: float, y: float, tol: float = 1e-12) -> bool:
    return all(x - y * t >= c1 - tol and x + y * t <= c2 + tol for t, c1, c2 in b.lines)


def centre_for_offset(b: Bounds, e: float) -> tuple[float, float]:
    """The highest allowed cam centre on the line x = −e (B0 at origin)."""
    x = -e
    y = min(min((x - c1) / t, (c2 - x) / t) for t, c1, c2 in b.lines)
    return x, y


def nearest_centre(b: Bounds) -> tuple[float, float]:
    """The allowed point nearest B0: a foot of a perpendicular onto a bounding line, or a
    corner where two lines meet."""
    rows = []  # a·x + b·y ≤ c
    for t, c1, c2 in b.lines:
        rows.append((-1.0, t, -c1))
        rows.append((1.0, t, c2))
    cand = []
    for a, bb, c in rows:
        n2 = a * a + bb * bb
        cand.append((a * c / n2, bb * c / n2))
    for i in range(len(rows)):
        for j in range(i + 1, len(rows)):
            a1, b1, c1 = rows[i]
            a2, b2, c2 = rows[j]
            det = a1 * b2 - a2 * b1
            if abs(det) > 1e-14:
                cand.append(((c1 * b2 - c2 * b1) / det, (a1 * c2 - a2 * c1) / det))
    tol = 1e-12 * max([1.0] + [abs(c) for _, _, c in rows])  # relative: a huge lift's bounds round too
    ok = [p for p in cand if _allowed(b, *p, tol=tol) and p[1] < 0]
    if not ok:  # rounding still shut every corner out: the one that breaks the bounds least

        def excess(p: tuple[float, float]) -> float:
            return max(max(c1 - (p[0] - p[1] * t), p[0] + p[1] * t - c2) for t, c1, c2 in b.lines)

        ok = [min((p for p in cand if p[1] < 0), key=excess, default=min(cand, key=excess))]
    return min(ok, key=lambda p: math.hypot(*p))


def min_base_radius(cam: Cam, exact: bool = True) -> BaseRadius:
    """Exact (each ray's tangent point refined on the law) or graphical (the curve only at
    the division points, as drawn)."""
    if cam.follower == "oscillating":
        from .rocker import diagram

        if exact:
            d = diagram(cam, grid(cam, 0.5))
            r = _oscillating(cam)
        else:
            d = diagram(cam, division_points(cam))
            r = d.min_base_radius
        return BaseRadius(r, d.centre, d.best_base_radius, None, d.best_centre, None, d.best_pivot)
    if cam.flat:
        # A flat face keeps the pressure angle at 0; the base radius is bound by convexity:
        # ρ = r0 + s + s″ > 0.
        mo = motion(cam, grid(cam, FINE_STEP_DEG))
        r = max(float(np.max(-(mo.s + mo.s2))), 0.0)
        return BaseRadius(r, (0.0, -r), r, 0.0, (0.0, -r), None)
    phi = grid(cam, FINE_STEP_DEG) if exact else division_points(cam)
    b = bounds(cam, phi, exact)
    c = centre_for_offset(b, cam.offset)
    best = nearest_centre(b)
    return BaseRadius(math.hypot(*c), c, math.hypot(*best), -best[0], best, b)


def division_points(cam: Cam) -> np.ndarray:
    """The draftsman's points: every phase that moves the follower divided into
    ``DIVISIONS`` equal parts (``DIVISIONS_LONG`` beyond 90°), ends included."""
    pts: list[float] = []
    for ph in cam.phases:
        n = 1 if ph.kind == "dwell" else DIVISIONS if ph.angle <= math.pi / 2 + 1e-12 else DIVISIONS_LONG
        pts.extend(ph.start + ph.angle * np.arange(n + 1) / n)
    arr = np.unique(np.round(np.array(pts), 12))
    return arr[arr < 2 * math.pi - 1e-12]


def _max_alpha_excess(cam: Cam, r0: float, phi: np.ndarray) -> float:
    c = replace(cam, base_radius=r0)
    pr = profile(c, phi)
    kinds = np.array([cam.phases[i].kind for i in pr.motion.phase])
    lim = np.where(kinds == "return", cam.alpha_return, cam.alpha_rise)
    return float(np.max(pr.pressure_angle - lim))


def _oscillating(cam: Cam) -> float | None:
    """Smallest r0 (pivot and arm kept) with every pressure angle within the permissible:
    scan r0 across the range where the roller reaches the base circle (on a 1° grid of φ),
    then bisect on the fine grid; None when no r0 of the range will do."""
    a, l = cam.pivot, cam.arm
    lo_lim, hi_lim = abs(a - l) * (1 + 1e-9) + 1e-12, (a + l) * (1 - 1e-9)
    coarse, fine = grid(cam, 1.0), grid(cam, FINE_STEP_DEG)
    rs = np.linspace(lo_lim, hi_lim, 201)
    prev = lo_lim
    for r in rs[1:-1]:
        if _max_alpha_excess(cam, float(r), coarse) <= 0 and _max_alpha_excess(cam, float(r), fine) <= 0:
            lo, hi = prev, float(r)
            for _ in range(50):
                mid = (lo + hi) / 2
                if _max_alpha_excess(cam, mid, fine) <= 0:
                    hi = mid
                else:
                    lo = mid
            return hi
        prev = float(r)
    return None


def roller_base_radius(cam: Cam, start: float) -> float | None:
    """The smallest base radius, from ``start`` (the pressure angle's minimum) up, at which
    the roller fits every convex part of the theoretical profile (no undercut), the file's
    offset (or arm and pivot) kept; ``None`` for a flat face or when no base radius the
    mechanism allows will do.  The profile's radius grows with r0, so the first radius that
    fits is found by doubling the step and then halving the bracket."""
    from .analysis import findings

    if cam.flat or cam.roller <= 0:
        return None
    top = math.inf
    if cam.follower == "oscillating":  # the base circle must still reach the arm: |arm − r0| < pivot
        top = cam.arm + cam.pivot
    low = max(start, cam.roller, abs(cam.offset)) * (1 + 1e-12)

    def fits(r0: float) -> bool:
        return not findings(replace(cam, base_radius=r0)).undercut

    if fits(low):
        return low
    step = max(low, cam.h)
    high = low + step
    while not fits(high):
        low, step = high, 2 * step
        high = low + step
        if high >= top or step > 1e6 * max(cam.h, cam.roller):
            return None
    while high - low > 1e-9 * high:
        mid = 0.5 * (low + high)
        low, high = (low, mid) if fits(mid) else (mid, high)
    return high
