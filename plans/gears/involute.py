"""The involute: inv α = tan α − α, its inverse, and the curve drawn by rolling a line.

The draftsman's construction: from a point on the base circle, the generating line is
rolled on the circle; at each tangent point T_k the arc already unrolled, r_b·θ_k, is laid
off along the tangent.  :func:`rolled_points` builds the profile exactly that way.
"""

from __future__ import annotations

import math

import numpy as np

from plans.errors import InputError, Said

_SERIES = (1 / 3, 2 / 15, 17 / 315, 62 / 2835, 1382 / 155925, 21844 / 6081075)


def inv(alpha: float) -> float:
    """inv α = tan α − α (α in radians); below 0.1 rad by its series (no cancellation)."""
    if abs(alpha) < 0.1:
        a2 = alpha * alpha
        acc = 0.0
        for c in reversed(_SERIES):
            acc = acc * a2 + c
        return acc * a2 * alpha
    return math.tan(alpha) - alpha


def inv_inverse(value: float, *, field: str = "inv", file: str | None = None) -> float:
    """The α in (0, π/2) with inv α = value, to 1e-12 relative or better.

    inv is increasing and convex on (0, π/2) with derivative tan²α, so Newton started above
    the root descends onto it monotonically; a start above the root: α₀ = (3v)^(1/3) is
    above it (inv α > α³/3), capped below π/2 by atan of the value plus the value's own
    atan (tan α₀ ≥ v + α₀ there).
    """
    if not (value > 0.0 and math.isfinite(value)):
        raise InputError(Said("gi_pressure_angle_has", value=value), file=file,
                         field=field)
    a = min((3.0 * value) ** (1.0 / 3.0), math.atan(value + math.pi / 2))
    for _ in range(200):
        t = math.tan(a)
        a_new = a - (inv(a) - value) / (t * t)
        if not a_new < a:  # monotone descent has stopped: converged to the last bit
            break
        a = a_new
    return a


def rolled_points(rb: float, theta: np.ndarray, start: float = 0.0, sign: float = 1.0
                  ) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Points of the involute of a base circle of radius ``rb`` (centre at the origin).

    The generating line touches the base circle at T_k (polar angle start + sign·θ_k); the
    point lies on the tangent at T_k, at the unrolled arc r_b·θ_k from T_k, on the side the
    line rolled from.  Returns (points as complex, tangent points T_k, laid-off lengths).
    """
    th = np.asarray(theta, dtype=float)
    phi = start + sign * th
    T = rb * np.exp(1j * phi)
    back = -1j * sign * np.exp(1j * phi)  # unit tangent, pointing back along the rolled arc
    lengths = rb * th
    return T + lengths * back, T, lengths


def thickness_at(r_y: float, s: float, r: float, alpha: float, rb: float) -> float:
    """Arc thickness of an external tooth at radius r_y: s_y = 2 r_y (s/2r + inv α − inv α_y)."""
    alpha_y = math.acos(min(1.0, rb / r_y))
    return 2.0 * r_y * (s / (2.0 * r) + inv(alpha) - inv(alpha_y))


def half_angle(r_y: float, s: float, r: float, alpha: float, rb: float) -> float:
    """Half the angular thickness of an external tooth at radius r_y (radians)."""
    return thickness_at(r_y, s, r, alpha, rb) / (2.0 * r_y)
