"""The cam over its cycle: the follower's motion, the profile by inversion, pressure angle,
radius of curvature and undercut.

Frames: the cam centre O at the origin, the translating follower's line x = offset pointing
up (+y), the oscillating follower's pivot at (pivot, 0) with the roller above the x axis.  By
inversion the cam stands still and the follower turns by −φ (against the cam's rotation):
a point B of the fixed frame lies on the cam at P = R(−kφ)·B, k = +1 ccw, −1 cw.  With
J the quarter turn, P′ = R(−kφ)(B′ − kJB) and P″ = R(−kφ)(B″ − 2kJB′ − B).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from .model import Cam

#: Scalar minima (curvature, pressure angle) are taken on this finer grid, degrees.
FINE_STEP_DEG = 0.05


@dataclass(frozen=True, slots=True)
class Motion:
    """s(φ), ds/dφ, d²s/dφ² (SI: m or rad of swing), the phase index of each angle."""

    phi: np.ndarray
    s: np.ndarray
    s1: np.ndarray
    s2: np.ndarray
    phase: np.ndarray


def motion(cam: Cam, phi: np.ndarray) -> Motion:
    """The follower's lift and its first two derivatives by the cam angle φ (rad, [0, 2π])."""
    phi = np.asarray(phi, float)
    s = np.zeros_like(phi)
    s1 = np.zeros_like(phi)
    s2 = np.zeros_like(phi)
    idx = np.zeros(phi.shape, int)
    last = len(cam.phases) - 1
    for i, ph in enumerate(cam.phases):
        hi = ph.start + ph.angle
        m = (phi >= ph.start - 1e-12) & ((phi < hi - 1e-12) if i < last else (phi <= hi + 1e-12))
        t = np.clip((phi[m] - ph.start) / ph.angle, 0.0, 1.0)
        f, f1, f2 = ph.law(t)
        s[m] = ph.lift0 + ph.stroke * f
        s1[m] = ph.stroke * f1 / ph.angle
        s2[m] = ph.stroke * f2 / ph.angle**2
        idx[m] = i
    return Motion(phi, s, s1, s2, idx)


def _J(v: np.ndarray) -> np.ndarray:
    return np.stack([-v[..., 1], v[..., 0]], axis=-1)


def _rot(phi: np.ndarray, v: np.ndarray) -> np.ndarray:
    c, s = np.cos(phi), np.sin(phi)
    return np.stack([c * v[..., 0] - s * v[..., 1], s * v[..., 0] + c * v[..., 1]], axis=-1)


def _cross(a: np.ndarray, b: np.ndarray) -> np.ndarray:
    return a[..., 0] * b[..., 1] - a[..., 1] * b[..., 0]


def oscillating_rest(cam: Cam) -> tuple[float, int]:
    """The arm's angle θ0 at rest (roller centre on the base circle, above the axis) and the
    turning sense σ of the arm that lifts the roller away from the cam centre."""
    a, l, r0 = cam.pivot, cam.arm, cam.base_radius
    x0 = (a * a + r0 * r0 - l * l) / (2 * a)
    y0 = math.sqrt(max(r0 * r0 - x0 * x0, 0.0))
    th0 = math.atan2(y0, x0 - a)
    # d|B|²/dθ = 2 B·(l J u) = 2 l A·J u with A = (a, 0): −2 a l sin θ.
    sigma = 1 if -math.sin(th0) > 0 else -1
    return th0, sigma


def follower_point(cam: Cam, mo: Motion) -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray]:
    """In the fixed frame: the roller centre B (flat face: the contact point), B′, B″ and the
    unit direction w of the follower's velocity when it lifts."""
    n = mo.phi.shape
    if cam.follower == "translating":
        if cam.flat:
            k = cam.sense
            B = np.stack([k * mo.s1, cam.base_radius + mo.s], axis=-1)
            B1 = np.stack([k * mo.s2, mo.s1], axis=-1)
            B2 = np.full(n + (2,), np.nan)  # not used: the flat face's curvature is closed-form
        else:
            s0 = math.sqrt(cam.base_radius**2 - cam.offset**2)
            B = np.stack([np.full(n, cam.offset), s0 + mo.s], axis=-1)
            B1 = np.stack([np.zeros(n), mo.s1], axis=-1)
            B2 = np.stack([np.zeros(n), mo.s2], axis=-1)
        w = np.broadcast_to(np.array([0.0, 1.0]), n + (2,))
        return B, B1, B2, w
    th0, sig = oscillating_rest(cam)
    th = th0 + sig * mo.s
    u = np.stack([np.cos(th), np.sin(th)], axis=-1)
    Ju = _J(u)
    l = cam.arm
    B = np.array([cam.pivot, 0.0]) + l * u
    B1 = (sig * l * mo.s1)[..., None] * Ju
    B2 = (sig * l * mo.s2)[..., None] * Ju - (l * mo.s1**2)[..., None] * u
    return B, B1, B2, sig * Ju


@dataclass(frozen=True, slots=True)
class Profile:
    """The cam at angles φ: theoretical profile (roller centre; a flat face's contact),
    actual profile (the roller's envelope), pressure angle (rad, ≥ 0) and curvature of the
    theoretical profile (1/m, positive where convex)."""

    motion: Motion
    theoretical: np.ndarray  # (n, 2), cam frame
    actual: np.ndarray
    pressure_angle: np.ndarray
    curvature: np.ndarray
    B: np.ndarray  # fixed frame: the roller centre
    contact: np.ndarray  # fixed frame: where the roller touches the cam


def profile(cam: Cam, phi: np.ndarray) -> Profile:
    mo = motion(cam, phi)
    k = cam.sense
    B, B1, B2, w = follower_point(cam, mo)
    back = -k * mo.phi
    theo = _rot(back, B)
    if cam.flat:
        alpha = np.zeros_like(mo.phi)
        rho = cam.base_radius + mo.s + mo.s2
        curv = np.divide(1.0, rho, out=np.full_like(rho, 1e12), where=rho != 0)
        return Profile(mo, theo, theo.copy(), alpha, curv, B, B)
    T = B1 - k * _J(B)  # the profile's tangent P′, seen in the fixed frame
    alpha = np.arctan2(np.abs(np.sum(T * w, axis=-1)), np.abs(_cross(T, w)))
    N2 = B2 - 2 * k * _J(B1) - B
    speed = np.hypot(T[..., 0], T[..., 1])
    curv = -k * _cross(T, N2) / speed**3
    inward = -k * _J(T / speed[..., None])
    contact = B + cam.roller * inward
    return Profile(mo, theo, _rot(back, contact), alpha, curv, B, contact)


def grid(cam: Cam, step_deg: float | None = None) -> np.ndarray:
    """φ from 0 by the step to just below 360°, radians."""
    step = cam.step_deg if step_deg is None else step_deg
    n = int(round(360.0 / step))
    return np.radians(np.arange(n) * step)


@dataclass(frozen=True, slots=True)
class Undercut:
    start_deg: float
    end_deg: float
    min_radius: float  # smallest convex radius of the theoretical profile there (m)


def undercuts(cam: Cam, phi_deg: np.ndarray, curv: np.ndarray) -> list[Undercut]:
    """Stretches of φ where the roller is too big: the theoretical profile is convex with a
    radius below the roller's (the envelope loops, the cam cannot be cut); for a flat face,
    where r0 + s + s″ ≤ 0."""
    if cam.flat:
        bad = curv <= 0
    else:
        if cam.roller <= 0:
            return []
        bad = curv * cam.roller >= 1.0
    out: list[Undercut] = []
    i, n = 0, len(bad)
    while i < n:
        if bad[i]:
            j = i
            while j + 1 < n and bad[j + 1]:
                j += 1
            c = curv[i:j + 1]
            rmin = float(np.min(1.0 / c[c > 0])) if np.any(c > 0) else 0.0
            out.append(Undercut(float(phi_deg[i]), float(phi_deg[j]), rmin))
            i = j + 1
        else:
            i += 1
    return out


@dataclass(frozen=True, slots=True)
class Findings:
    max_pressure_rise: float  # rad, over rise (and dwell) angles
    max_pressure_return: float
    min_curvature_radius: float  # m, convex parts of the theoretical profile
    undercut: tuple[Undercut, ...]


def findings(cam: Cam) -> Findings:
    """Extremes on the fine grid: the largest pressure angles, the smallest convex radius,
    the undercut stretches."""
    phi = grid(cam, FINE_STEP_DEG)
    pr = profile(cam, phi)
    kinds = np.array([cam.phases[i].kind for i in pr.motion.phase])
    ret = kinds == "return"
    a_rise = float(np.max(pr.pressure_angle[~ret])) if np.any(~ret) else 0.0
    a_ret = float(np.max(pr.pressure_angle[ret])) if np.any(ret) else 0.0
    conv = pr.curvature[pr.curvature > 0]
    rmin = float(1.0 / np.max(conv)) if conv.size else 0.0
    return Findings(a_rise, a_ret, rmin, tuple(undercuts(cam, np.degrees(phi), pr.curvature)))


def clip_half_plane(poly: list[tuple[float, float]], a: float, b: float, c: float) -> list[tuple[float, float]]:
    """The part of the convex polygon ``poly`` where a·x + b·y ≤ c."""
    out: list[tuple[float, float]] = []
    for i in range(len(poly)):
        p, q = poly[i], poly[(i + 1) % len(poly)]
        fp, fq = a * p[0] + b * p[1] - c, a * q[0] + b * q[1] - c
        if fp <= 0:
            out.append(p)
        if fp * fq < 0:
            s = fp / (fp - fq)
            out.append((p[0] + s * (q[0] - p[0]), p[1] + s * (q[1] - p[1])))
    return out
