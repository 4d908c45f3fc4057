"""The meshing drawing's construction, in paper millimetres (x right, y up, P at the origin).

The pair is drawn at a standard enlargement where a tooth is 40–60 mm high; gear 1's centre
O1 straight below the pitch point P, gear 2's O2 above.  Each flank is the involute built
the draftsman's way (:func:`plans.gears.involute.rolled_points`: tangents to the base
circle, the unrolled arc laid off on each), continued radially below the base circle and
joined to the root circle by a fillet arc (radius 0.38 m, smaller where the space is
narrow); a ring's flanks meet its root circle (outside) through the same fillet, drawn as
the rounded corner of each space.  The line of action N1N2 touches both base circles; B1 and B2 are found on the
drawing as the crossings of N1N2 with the tip circles drawn as polygons, so the contact
ratio B1B2/p_b is *read off the drawing*, next to the exact one.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np
import shapely

from .geometry import Pair, Wheel
from .involute import half_angle, inv, rolled_points

ENLARGEMENTS = (1.0, 2.0, 2.5, 4.0, 5.0, 10.0, 20.0, 25.0, 40.0, 50.0, 100.0)
CIRCLE_SEGMENTS = 720  # the tip circles as the drawing has them


@dataclass(frozen=True)
class DrawnWheel:
    name: str
    centre: complex  # paper mm
    radii: dict[str, float]  # pitch, base, tip, root, working (paper mm)
    outline: tuple[complex, ...]  # the teeth near P, one polyline
    teeth: int


@dataclass(frozen=True)
class Meshing:
    pair: Pair
    k: float  # drawing scale (paper mm per mm of the gear)
    wheels: tuple[DrawnWheel, DrawnWheel]
    N1: complex
    N2: complex
    B1: complex  # gear 2's tip circle on N1N2 (start of contact when 1 drives)
    B2: complex  # gear 1's tip circle on N1N2
    p_b: float  # drawn base pitch
    construction: tuple[tuple[complex, complex], ...]  # (T_k on the base circle, laid-off point)
    window: float  # half-width of the drawn field around P
    rows: tuple[float, float] | None = None  # its bottom and top (y up) where a field was asked for

    @property
    def b1b2(self) -> float:
        return abs(self.B2 - self.B1)

    @property
    def contact_ratio_drawn(self) -> float:
        return self.b1b2 / self.p_b

    def zones(self) -> tuple[tuple[complex, complex], tuple[complex, complex], tuple[complex, complex]]:
        """(double, single, double) contact along B1B2: p_b from each end is double contact."""
        u = (self.B2 - self.B1) / self.b1b2
        a = self.B1 + u * min(self.p_b, self.b1b2)
        b = self.B2 - u * min(self.p_b, self.b1b2)
        if abs(a - self.B1) > abs(b - self.B1):  # ε ≥ 1: single contact between b and a
            return (self.B1, b), (b, a), (a, self.B2)
        return (self.B1, a), (a, a), (a, self.B2)


def enlargement(tooth_mm: float) -> float:
    """The standard scale drawing a tooth nearest 50 mm high, preferring 40–60 mm."""
    inside = [s for s in ENLARGEMENTS if 40.0 <= tooth_mm * s <= 60.0]
    pool = inside or list(ENLARGEMENTS)
    return min(pool, key=lambda s: abs(tooth_mm * s - 50.0))


def _flank(w: Wheel, m: float, alpha: float, k: float, n: int = 48) -> tuple[np.ndarray, float]:
    """One flank (the tooth's counter-clockwise side) of a tooth centred on angle 0, in the
    wheel's frame at scale k, from the root circle to the tip; and the half-angle of the
    space at the root.  Complex points, root first."""
    rb, ra, rf = w.base * 1e3 * k, w.tip * 1e3 * k, w.root * 1e3 * k
    r, s = w.pitch * 1e3 * k, w.thickness * 1e3 * k
    theta_b = s / (2.0 * r) + inv(alpha)  # where the involute leaves the base circle
    r0 = max(rb, rf)
    th0 = math.sqrt(max(0.0, (r0 / rb) ** 2 - 1.0))
    tha = math.sqrt((ra / rb) ** 2 - 1.0)
    pts, _, _ = rolled_points(rb, np.linspace(th0, tha, n), start=theta_b, sign=-1.0)
    if rf < rb:  # radial below the base circle
        radial = np.linspace(rf, rb, 6, endpoint=False) * np.exp(1j * theta_b)
        pts = np.concatenate([radial, pts])
    space_half = math.pi / w.z - (half_angle(rf, s, r, alpha, rb) if rf > rb else theta_b)
    return pts, space_half


def _filleted(flank: np.ndarray, rf: float, space_half: float, rho: float) -> np.ndarray:
    """The flank from the root circle with a fillet arc: centre at radius r_f + ρ in the space,
    tangent to the root circle and to the flank (the largest ρ ≤ the given that fits)."""
    line = shapely.LineString(np.column_stack([flank.real, flank.imag]))
    base_ang = float(np.angle(flank[0]))
    for _ in range(30):
        R = rf + rho
        lo, hi = 0.0, space_half  # the centre's angle beyond the flank, bisected to distance ρ
        for _ in range(60):
            mid = 0.5 * (lo + hi)
            c = R * complex(math.cos(base_ang + mid), math.sin(base_ang + mid))
            if line.distance(shapely.Point(c.real, c.imag)) < rho:
                lo = mid
            else:
                hi = mid
        if hi < space_half * 0.999:
            break
        rho *= 0.8
    ang = base_ang + hi
    c = R * complex(math.cos(ang), math.sin(ang))
    touch = line.interpolate(line.project(shapely.Point(c.real, c.imag)))
    t = complex(touch.x, touch.y)
    foot = rf * complex(math.cos(ang), math.sin(ang))
    a0, a1 = np.angle(foot - c), np.angle(t - c)
    if a1 < a0:
        a1 += 2 * math.pi
    if a1 - a0 > math.pi:
        a0, a1 = a1 - 2 * math.pi, a0
        arc = c + rho * np.exp(1j * np.linspace(a1, a0, 12))
    else:
        arc = c + rho * np.exp(1j * np.linspace(a0, a1, 12))
    along = line.project(touch)
    dist = np.array([line.project(shapely.Point(p.real, p.imag)) for p in flank])
    rest = flank[dist > along + 1e-9]
    return np.concatenate([arc, rest])


def _rounded_tip(flank: np.ndarray, ra: float, rho: float) -> np.ndarray:
    """The flank ending in a fillet arc to the tip circle ``ra`` (a ring's root seen from its
    space): centre at radius r_a − ρ inside the tooth, tangent to the circle and to the
    flank (the largest ρ ≤ the given that fits the tooth's half-width there)."""
    line = shapely.LineString(np.column_stack([flank.real, flank.imag]))
    radius = np.abs(flank)
    angle = np.unwrap(np.angle(flank))
    for _ in range(30):
        R = ra - rho
        edge = float(np.interp(R, radius, angle))  # the flank's angle at the centre's radius
        far = line.distance(shapely.Point(R, 0.0))  # from the tooth's middle (angle 0)
        if far > rho and R > radius[0]:
            break
        rho *= 0.8
    lo, hi = 0.0, edge  # the centre's angle, bisected to distance ρ from the flank
    for _ in range(60):
        mid = 0.5 * (lo + hi)
        c = R * complex(math.cos(mid), math.sin(mid))
        if line.distance(shapely.Point(c.real, c.imag)) > rho:
            lo = mid
        else:
            hi = mid
    ang = lo
    c = R * complex(math.cos(ang), math.sin(ang))
    touch = line.interpolate(line.project(shapely.Point(c.real, c.imag)))
    t = complex(touch.x, touch.y)
    top = ra * complex(math.cos(ang), math.sin(ang))
    a0, a1 = float(np.angle(t - c)), float(np.angle(top - c))
    if a1 > a0:  # the short way round, from the flank to the tip circle
        a1 -= 2 * math.pi
    if a0 - a1 > math.pi:
        a1 += 2 * math.pi
    arc = c + rho * np.exp(1j * np.linspace(a0, a1, 12))
    along = line.project(touch)
    dist = np.array([line.project(shapely.Point(p.real, p.imag)) for p in flank])
    return np.concatenate([flank[dist < along - 1e-9], arc])


def _as_spaces(w: Wheel, m: float) -> Wheel:
    """A ring gear seen from its spaces: each space is bounded like an external tooth of
    thickness e = πm − s, from the ring's tip circle (inside) to its root circle (outside)."""
    return Wheel(w.name, w.z, w.x, False, w.pitch, w.base, w.root, w.tip, w.working, w.tip_angle,
                 math.pi * m - w.thickness, 0.0, 0.0)


def _outline(w: Wheel, m: float, alpha: float, k: float, centre: complex, axis: float,
             teeth: int) -> tuple[complex, ...]:
    """The teeth j = −teeth..teeth about the tooth centred on ``axis`` (paper angle, y up), the
    whole wheel, closed, where that is all of its teeth; for a ring, its spaces about the space
    centred on ``axis``, the fillets at the ring's root drawn as the rounded corners of the
    spaces."""
    ring = w.internal
    if ring:
        w = _as_spaces(w, m)
    flank, space_half = _flank(w, m, alpha, k)
    rf = w.root * 1e3 * k
    if ring:
        flank = _rounded_tip(flank, w.tip * 1e3 * k, 0.38 * m * 1e3 * k)
    else:
        flank = _filleted(flank, rf, space_half, 0.38 * m * 1e3 * k)
    ra = w.tip * 1e3 * k
    a_tip = float(np.angle(flank[-1]))
    tip = ra * np.exp(1j * np.linspace(-a_tip, a_tip, 9)[1:-1])  # the tip land, an arc
    tooth = np.concatenate([np.conj(flank), tip, flank[::-1]])  # cw flank up, tip, ccw flank down
    step = 2 * math.pi / w.z
    a_foot = float(np.angle(flank[0]))
    root = rf * np.exp(1j * np.linspace(a_foot, step - a_foot, 9)[1:-1])  # the root arc to the next tooth
    whole = 2 * teeth + 1 >= w.z
    js = range(-(w.z // 2), w.z - w.z // 2) if whole else range(-teeth, teeth + 1)
    pts: list[complex] = []
    for j in js:
        rot = np.exp(1j * (axis + j * step))
        pts.extend((centre + tooth * rot).tolist())
        if whole or j < teeth:
            pts.extend((centre + root * rot).tolist())
    if whole:  # back to the first tooth's first point
        pts.append(pts[0])
    return tuple(pts)


def field_rows(centres: tuple[complex, complex], reach: tuple[float, float], half_h: float) -> tuple[float, float]:
    """The bottom and top (y up, paper mm) of a field 2·``half_h`` high about P, moved up or
    down as far as it takes to show no empty band beyond the wheels (centres on x = 0 and the
    largest radii ``reach``, plus 12 mm), where they are that high."""
    lo = min(c.imag - r for c, r in zip(centres, reach, strict=True)) - 12.0
    hi = max(c.imag + r for c, r in zip(centres, reach, strict=True)) + 12.0
    top = min(half_h, hi)
    bottom = max(top - 2.0 * half_h, lo)
    return bottom, bottom + 2.0 * half_h


def teeth_to_fill(centre: complex, radius: float, axis: float, z: int, half_w: float, rows: tuple[float, float]) -> int:
    """How many teeth either side of the one on ``axis`` reach every point of the circle of
    ``radius`` (the tip circle, paper mm) inside the field |x| ≤ half_w, ``rows`` in y: the
    greatest turn from the axis to such a point, in pitches, one more for the tooth that
    crosses the field's edge (the whole wheel where that is all of it)."""
    t = np.linspace(-math.pi, math.pi, 1441)
    pts = centre + radius * np.exp(1j * (axis + t))
    inside = (np.abs(pts.real) <= half_w) & (pts.imag >= rows[0]) & (pts.imag <= rows[1])
    turn = float(np.max(np.abs(t[inside]))) if inside.any() else 0.0
    return min(math.ceil(turn * z / (2 * math.pi)) + 1, z // 2 + 1)


def meshing(p: Pair, teeth: int = 3, field: tuple[float, float] | None = None) -> Meshing:
    """The construction of a pair: external (O2 above P) or internal (the ring's centre O2
    below P, beyond O1; the flank through P is then a flank of a ring space).  ``field``, the
    drawn field's half-width and half-height about P (paper mm), draws as many teeth of each
    wheel as it shows (at least ``teeth`` either side); else the field is the least that shows
    ``teeth`` teeth and the line of action."""
    w1, w2 = p.wheels
    tooth = max(abs(w.tip - w.root) for w in p.wheels) * 1e3
    k = enlargement(tooth)
    m, alpha = p.m, p.alpha
    O1 = complex(0.0, -w1.working * 1e3 * k)
    O2 = complex(0.0, (-1.0 if p.internal else 1.0) * w2.working * 1e3 * k)
    psi1 = half_angle(w1.working, w1.thickness, w1.pitch, alpha, w1.base)
    ax1 = math.pi / 2 - psi1  # gear 1's tooth whose ccw flank passes through P
    if p.internal:  # the ring's space holding that tooth: its ccw side through P
        e2 = math.pi * m - w2.thickness
        ax2 = math.pi / 2 - half_angle(w2.working, e2, w2.pitch, alpha, w2.base)
        s2 = e2 / (2 * w2.pitch) + inv(alpha)
    else:
        ax2 = -math.pi / 2 - half_angle(w2.working, w2.thickness, w2.pitch, alpha, w2.base)
        s2 = w2.thickness / (2 * w2.pitch) + inv(alpha)
    far = tuple(max(w.tip, w.root) * 1e3 * k for w in (w1, w2))
    rows = None if field is None else field_rows((O1, O2), (far[0], far[1]), field[1])
    drawn = []
    for w, O, ax, R in ((w1, O1, ax1, far[0]), (w2, O2, ax2, far[1])):
        radii = {key: getattr(w, key) * 1e3 * k for key in ("pitch", "base", "tip", "root", "working")}
        n = teeth if field is None or rows is None else max(teeth, teeth_to_fill(O, R, ax, w.z, field[0], rows))
        drawn.append(DrawnWheel(w.name, O, radii, _outline(w, m, alpha, k, O, ax, n), n))
    # N1, N2: where the flanks through P were unrolled from (their tangent points)
    tw = math.tan(p.alpha_w)
    s1 = w1.thickness / (2 * w1.pitch) + inv(alpha)
    N1 = O1 + w1.base * 1e3 * k * np.exp(1j * (ax1 + s1 - tw))
    N2 = O2 + w2.base * 1e3 * k * np.exp(1j * (ax2 + s2 - tw))
    # B1, B2 read on the drawing: the line of action against the tip circles as drawn
    # (polygons); an internal pair's line runs on past P, beyond N1 from N2
    u = (N2 - N1) / abs(N2 - N1)
    end = N2 if not p.internal else N1 - u * (p.rho_end * 1e3 * k + 20.0)
    line = shapely.LineString([(N1.real, N1.imag), (end.real, end.imag)] if not p.internal
                              else [(N2.real, N2.imag), (end.real, end.imag)])

    def cut(O: complex, r: float, near: complex) -> complex:
        ang = np.linspace(0, 2 * math.pi, CIRCLE_SEGMENTS + 1)
        ring = shapely.LineString(np.column_stack([O.real + r * np.cos(ang), O.imag + r * np.sin(ang)]))
        hit = line.intersection(ring)
        pts = [complex(g.x, g.y) for g in getattr(hit, "geoms", [hit]) if not g.is_empty]
        return min(pts, key=lambda z: abs(z - near)) if pts else near

    ahead = -u if p.internal else u  # from N1 towards P
    B1 = cut(O2, drawn[1].radii["tip"], N1 + ahead * p.rho_start * 1e3 * k)
    B2 = cut(O1, drawn[0].radii["tip"], N1 + ahead * p.rho_end * 1e3 * k)
    pb = p.p_b * 1e3 * k
    # the draftsman's construction of gear 1's flank through P: tangents and laid-off arcs
    rb1 = w1.base * 1e3 * k
    tha = math.sqrt((w1.tip / w1.base) ** 2 - 1.0)
    th = np.linspace(0.0, tha, 7)[1:]
    pts, T, _ = rolled_points(rb1, th, start=ax1 + s1, sign=-1.0)
    cons = tuple((complex(O1 + t), complex(O1 + q)) for t, q in zip(T, pts, strict=True))
    least = max(2.6 * math.pi * m * 1e3 * k, abs(N2 - N1) / 2 + 25.0)
    window = least if field is None else max(field[0], least)
    return Meshing(p, k, (drawn[0], drawn[1]), complex(N1), complex(N2), B1, B2, pb, cons, window, rows)


def drawn_contact_ratios(sol) -> dict[tuple[str, str], float]:
    """ε read off the meshing drawings, for the pairs the sheets draw."""
    return {p.gears: meshing(p).contact_ratio_drawn for p in sol.drawn_pairs()}
