"""Profile-shift coefficients chosen by a rule, for gears whose file says ``x = "auto"``.

- ``minimum``: the course's formula x = h_a* (z_min − z)/z_min with z_min = 2h_a*/sin²α
  rounded to the whole number the course tabulates (17 at 20°); no shift when z ≥ z_min.
- ``no_undercut``: the exact limit x = h_a* − z sin²α / 2 (the rack's tip line through N);
  at 20° and z = 14 it is 0.18116, a little more than the course's 3/17 = 0.17647.
- ``equal_sliding``: for a pair of "auto" gears, a height-modified pair x1 = −x2 (the centre
  distance stays a) with the greatest specific sliding the same on both wheels, each wheel at
  or above its undercut limit (when z1 + z2 < 2 z_min no such pair exists and each wheel gets
  its undercut limit, and both tips at least 0.4 m thick); other "auto" gears get their no-undercut shift.

An internal (ring) gear chosen "auto" is not shifted.
"""

from __future__ import annotations

import math

from plans.errors import InputError

from .geometry import GOOD_TIP_THICKNESS, pair


def z_min(alpha: float, ha: float) -> float:
    """The exact fewest teeth without undercut, 2 h_a* / sin²α."""
    return 2.0 * ha / math.sin(alpha) ** 2


def minimum(z: int, alpha: float, ha: float) -> float:
    zm = round(z_min(alpha, ha))
    return max(0.0, ha * (zm - z) / zm)


def no_undercut(z: int, alpha: float, ha: float) -> float:
    return max(0.0, ha - z * math.sin(alpha) ** 2 / 2.0)


def single(rule: str, z: int, internal: bool, alpha: float, ha: float) -> float:
    if internal:
        return 0.0
    return minimum(z, alpha, ha) if rule == "minimum" else no_undercut(z, alpha, ha)


def equal_sliding(names: tuple[str, str], z: tuple[int, int], m: float, alpha: float, ha: float,
                  c: float) -> tuple[float, float]:
    """(x1, −x1) with equal greatest specific sliding on both wheels.

    |ϑ1| falls and |ϑ2| rises as x1 grows (gear 1's root moves away from N1); bisection on
    x1 between the two undercut limits finds where they are equal, or the limit nearer it.
    """
    lo1 = ha - z[0] * math.sin(alpha) ** 2 / 2.0  # undercut limits, negative for many teeth
    lo2 = ha - z[1] * math.sin(alpha) ** 2 / 2.0
    if lo1 + lo2 > 0.0:
        return lo1, lo2
    total = 0.0

    def diff(x1: float) -> float:
        # a tooth thinner at the tip than the course accepts counts as too much shift there
        try:
            p = pair(names, z, (x1, total - x1), False, m, alpha, ha, c, (0.0, 0.0))
        except InputError:
            return -1.0 if x1 > 0 else 1.0
        w1, w2 = p.wheels
        if w1.tip_thickness < GOOD_TIP_THICKNESS * m:
            return -1.0
        if w2.tip_thickness < GOOD_TIP_THICKNESS * m:
            return 1.0
        return p.sliding[0] - p.sliding[1]

    a, b = lo1, total - lo2
    fa, fb = diff(a), diff(b)
    if fa <= 0.0:
        return a, total - a
    if fb >= 0.0:
        return b, total - b
    for _ in range(200):
        mid = 0.5 * (a + b)
        fm = diff(mid)
        if fm > 0.0:
            a = mid
        else:
            b = mid
        if b - a < 1e-14:
            break
    x1 = 0.5 * (a + b)
    return x1, total - x1
