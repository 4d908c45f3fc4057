"""One pair of involute spur gears, external or internal, with profile shifts (course §4).

External pair (1, 2)::

    inv α_w = inv α + 2 tan α (x1 + x2)/(z1 + z2),   a = m (z1 + z2)/2,
    a_w = a cos α / cos α_w,   y = (a_w − a)/m,   Δy = x1 + x2 − y,
    r = m z/2,  r_b = r cos α,  r_a = r + (h_a* + x − Δy) m,  r_f = r − (h_a* + c* − x) m.

Internal pair (pinion 1, ring 2): the sums become differences (x2 − x1, z2 − z1), the ring's
tip circle is inside, r_f2 = r2 + (h_a* + c* + x2) m, and no tip is shortened by Δy (the
clearances of an internal pair grow by Δy m instead of shrinking).

The ring's tip circle (``ring_tip``).  By the plain rule r_a2 = r2 − (h_a* − x2) m its tip
reaches, on the line of action, below where a rack-cut pinion's involute begins (the
pinion's limit point, (h_a* − x1) m / sin α from P), and the pair interferes.  Rings cut by
a shaper cutter have the tip circle enlarged (the tip trimmed).  ``"trimmed"`` (default)
puts it through that limit point for a pinion with the ring's shift (x1 = x2, so α_w = α):

    r_a2² = r_b2² + (r2 sin α − H/sin α)² = (r2 − H)² + (H cot α)²,   H = (h_a* − x2) m;

``"gost"`` is its expansion to first order in 1/z2, the ring-gear rule of GOST 19274,
d_a2 = d2 − 2(h_a* − x2 − Δh_a*) m with Δh_a* = h_a*²/(z2 tan² α) (7.55/z2 at α = 20°,
h_a* = 1), a hair smaller; ``"plain"`` keeps r_a2 = r2 − (h_a* − x2) m.

The line of action is measured from N1, where it touches the base circle of gear 1: the
active part B1B2 runs from B1, where gear 2's tip circle cuts it, to B2, where gear 1's does;
ε = B1B2 / p_b with p_b = π m cos α (the course's ε = Σ ±z (tan α_a − tan α_w)/2π is the
same number, used as an oracle in the tests).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

from plans.errors import InputError, Said
from plans.tolerances import ROUND_OFF_REL

from .involute import inv, inv_inverse, thickness_at

#: the checks a course makes on a pair
MIN_CONTACT_RATIO = 1.2
MIN_TIP_THICKNESS = 0.25  # × m, the least accepted
GOOD_TIP_THICKNESS = 0.4  # × m, the usual requirement
#: how a ring gear's tip circle is found (see the module's docstring)
RING_TIPS = ("trimmed", "gost", "plain")


@dataclass(frozen=True)
class Wheel:
    """One gear as it is cut and assembled in a pair (metres, radians)."""

    name: str
    z: int
    x: float
    internal: bool
    pitch: float  # r
    base: float  # r_b
    tip: float  # r_a
    root: float  # r_f
    working: float  # r_w
    tip_angle: float  # α_a
    thickness: float  # s, on the reference circle
    tip_thickness: float  # s_a
    limit: float  # ρ_l: radius of curvature where the generated involute starts (< 0: undercut)


@dataclass(frozen=True)
class Pair:
    """Everything a course computes for one meshing pair (metres, radians)."""

    gears: tuple[str, str]
    internal: bool
    m: float
    alpha: float
    alpha_w: float
    a: float
    a_w: float
    y: float
    delta_y: float
    backlash: float  # circumferential, on the working circles (0 unless a_w is given larger)
    wheels: tuple[Wheel, Wheel]
    g: float  # N1N2
    rho_start: float  # distance N1 -> B1, where gear 2's tip circle cuts N1N2
    rho_end: float  # distance N1 -> B2, where gear 1's tip circle cuts N1N2
    p_b: float
    contact_ratio: float
    sliding: tuple[float, float]  # greatest specific sliding on gear 1 and on gear 2

    @property
    def rho_p(self) -> float:
        """Distance N1 -> P."""
        return self.wheels[0].base * math.tan(self.alpha_w)

    def checks(self) -> dict[str, bool]:
        m = self.m
        out = {"contact_ratio": self.contact_ratio >= MIN_CONTACT_RATIO}
        for w in self.wheels:
            out[f"no_undercut_{w.name}"] = w.internal or w.limit >= -ROUND_OFF_REL * m
            out[f"tip_thickness_{w.name}"] = w.tip_thickness >= GOOD_TIP_THICKNESS * m - ROUND_OFF_REL * m
        w1, w2 = self.wheels
        rho2_start = self.rho_start + self.g if self.internal else self.g - self.rho_end
        # no interference: each flank is met only where it is an involute
        ok1 = self.rho_start >= max(0.0, w1.limit) - ROUND_OFF_REL * m
        ok2 = True if w2.internal else rho2_start >= max(0.0, w2.limit) - ROUND_OFF_REL * m
        out["no_interference"] = ok1 and ok2
        return out


def centre(z1: int, z2: int, x1: float, x2: float, m: float, alpha: float, internal: bool,
           a_w_given: float | None, where: str, file: str | None) -> tuple[float, float, float, float]:
    """(α_w, a, a_w, backlash) of a pair; with a_w given, the pair is assembled there."""
    S, Z = (x2 - x1, z2 - z1) if internal else (x1 + x2, z1 + z2)
    if Z <= 0:
        raise InputError(Said("gg2_ring_gear_needs", z2=z2, z1=z1),
                         file=file, field=where)
    a = m * Z / 2.0
    if a_w_given is None:
        v = inv(alpha) + 2.0 * math.tan(alpha) * S / Z
        if v <= 0.0:
            raise InputError(Said("gg2_shifts_sum_leave", S=S, v=v), file=file, field=where)
        alpha_w = inv_inverse(v, field=where, file=file)
        return alpha_w, a, a * math.cos(alpha) / math.cos(alpha_w), 0.0
    c = a * math.cos(alpha) / a_w_given
    if not 0.0 < c < 1.0:
        raise InputError(Said("gg2_impossible_centre_distance", v=a_w_given * 1e3, v2=a * math.cos(alpha) * 1e3), file=file, field=where)
    alpha_w = math.acos(c)
    S0 = (inv(alpha_w) - inv(alpha)) * Z / (2.0 * math.tan(alpha))
    if S > S0 + 1e-9:
        need = centre(z1, z2, x1, x2, m, alpha, internal, None, where, file)[2]
        raise InputError(Said("gg2_impossible_centre_distance2", v=a_w_given * 1e3, v2=need * 1e3),
                         file=file, field=where)
    backlash = 2.0 * m * math.tan(alpha) * (S0 - S) * math.cos(alpha) / math.cos(alpha_w)
    return alpha_w, a, a_w_given, max(0.0, backlash)


def sum_for_centre(z1: int, z2: int, m: float, alpha: float, internal: bool, a_w: float) -> float:
    """Σx (x1 + x2, or x2 − x1 for an internal pair) that meshes without backlash at a_w."""
    Z = z2 - z1 if internal else z1 + z2
    c = m * Z / 2.0 * math.cos(alpha) / a_w
    if not 0.0 < c < 1.0:
        return math.nan
    return (inv(math.acos(c)) - inv(alpha)) * Z / (2.0 * math.tan(alpha))


def wheel(name: str, z: int, x: float, internal: bool, m: float, alpha: float, ha: float, c: float,
          alpha_w: float, dy_tip: float, where: str, file: str | None, ring_tip: str = "trimmed") -> Wheel:
    r = m * z / 2.0
    rb = r * math.cos(alpha)
    if internal:
        ra, rf = ring_tip_radius(r, z, x, m, alpha, ha, ring_tip), r + (ha + c + x) * m
        s = m * (math.pi / 2.0 - 2.0 * x * math.tan(alpha))
    else:
        ra, rf = r + (ha + x - dy_tip) * m, r - (ha + c - x) * m
        s = m * (math.pi / 2.0 + 2.0 * x * math.tan(alpha))
    if rf <= 0.0:
        raise InputError(Said("gg2_gear_name_leave", name=name, z=z, x=x, v=rf * 1e3),
                         file=file, field=where)
    if ra <= rb * (1.0 + ROUND_OFF_REL):
        raise InputError(Said("gg2_gear_name_tip", name=name, v=ra * 1e3, v2=rb * 1e3), file=file, field=where)
    aa = math.acos(rb / ra)
    if internal:
        sa = 2.0 * ra * (s / (2.0 * r) - inv(alpha) + inv(aa))
        limit = math.inf
    else:
        sa = thickness_at(ra, s, r, alpha, rb)
        limit = r * math.sin(alpha) - (ha - x) * m / math.sin(alpha)
    if sa <= 0.0:
        raise InputError(Said("gg2_gear_name_gives", name=name, x=x, v=sa * 1e3), file=file, field=where)
    rw = rb / math.cos(alpha_w)
    return Wheel(name, z, x, internal, r, rb, ra, rf, rw, aa, s, sa, limit)


def ring_tip_radius(r: float, z: int, x: float, m: float, alpha: float, ha: float, rule: str) -> float:
    """r_a of a ring gear by ``rule`` (one of RING_TIPS)."""
    H = (ha - x) * m
    if rule == "plain":
        return r - H
    if rule == "gost":
        return r - H + ha * ha / (z * math.tan(alpha) ** 2) * m
    return math.hypot(r - H, H / math.tan(alpha))


def pair(names: tuple[str, str], z: tuple[int, int], x: tuple[float, float], internal: bool, m: float,
         alpha: float, ha: float, c: float, dy_tips: tuple[float, float], a_w_given: float | None = None,
         where: str = "meshes", file: str | None = None, ring_tip: str = "trimmed") -> Pair:
    """The pair (gear 2 is the ring when ``internal``); ``dy_tips``: the Δy each tip is
    shortened by (the course takes the largest Δy of a gear's meshes)."""
    alpha_w, a, a_w, backlash = centre(z[0], z[1], x[0], x[1], m, alpha, internal, a_w_given, where, file)
    y = (a_w - a) / m
    S = x[1] - x[0] if internal else x[0] + x[1]
    dy = S - y
    if abs(dy) < 1e-12:
        dy = 0.0
    w1 = wheel(names[0], z[0], x[0], False, m, alpha, ha, c, alpha_w, dy_tips[0], where, file)
    w2 = wheel(names[1], z[1], x[1], internal, m, alpha, ha, c, alpha_w, dy_tips[1], where, file, ring_tip)
    g = a_w * math.sin(alpha_w)
    rho_a1 = math.sqrt(w1.tip**2 - w1.base**2)
    rho_a2 = math.sqrt(w2.tip**2 - w2.base**2)
    start = rho_a2 - g if internal else g - rho_a2
    end = rho_a1
    p_b = math.pi * m * math.cos(alpha)
    if end - start <= 0.0:
        raise InputError(Said("gg2_gears_tip_circles", v=names[0], v2=names[1]), file=file, field=where)
    eps = (end - start) / p_b
    u = z[1] / z[0]

    def rho2(r1: float) -> float:
        return r1 + g if internal else g - r1

    s1 = abs(1.0 - rho2(start) / (u * start)) if start > 0 else math.inf
    s2 = abs(1.0 - u * end / rho2(end)) if rho2(end) > 0 else math.inf
    return Pair(names, internal, m, alpha, alpha_w, a, a_w, y, dy, backlash, (w1, w2), g, start, end,
                p_b, eps, (s1, s2))
