"""Speeds of a gear train, ordinary, planetary or differential, two independent ways.

Willis: relative to the carrier C that holds both axes of a mesh (the frame for fixed axes),
each mesh turns as an ordinary pair, z_a (ω_a − ω_C) = ∓ z_b (ω_b − ω_C) (− external,
+ internal); with the given speeds this is a linear system for every shaft's ω.

The velocity plan (Smirnov's method, as Russian courses draw it): the train is unfolded
along one radial line (axes and pitch points at their heights y); the linear velocities of
the points of one shaft lie on a straight line through the plan (v = 0 at a fixed axis);
meshing wheels share the velocity of their pitch point, a planet's axis moves with its
carrier.  Line by line the plan is built from points already known; the ray diagram then
draws from a pole, at distance h from a reference line, rays parallel to each shaft's line:
the intercepts on the reference line are the angular velocities, ω = x μ_l / (h μ_v).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from plans.errors import InputError, Said
from plans.tolerances import AGREE_REL

Pt = tuple[float, float]  # (v drawn, y drawn), plan millimetres


@dataclass(frozen=True)
class TrainMesh:
    """A mesh as the train sees it: gears, their shafts, working radii (m), internal flag."""

    gears: tuple[str, str]
    shafts: tuple[str, str]
    z: tuple[int, int]
    r_w: tuple[float, float]
    internal_gear: str | None  # the ring, if the pair is internal


@dataclass(frozen=True)
class ShaftLine:
    """One shaft on the plan: its line through two constructed points, the points it was
    built from (names for the sheet), and the ray-diagram intercept."""

    name: str
    p0: Pt
    p1: Pt
    points: tuple[tuple[str, Pt], ...]
    intercept: float  # on the reference line, mm
    omega: float  # rad/s read from the intercept


@dataclass(frozen=True)
class VelocityPlan:
    mu_l: float  # mm per m of radius
    mu_v: float  # mm per m/s
    h: float  # pole distance of the ray diagram, mm
    axes: dict[str, float]  # shaft -> y of its axis (m)
    pitch: dict[tuple[str, str], float]  # mesh gears -> y of the pitch point (m)
    lines: dict[str, ShaftLine]
    order: tuple[str, ...]  # the order the lines were constructed in

    @property
    def mu_omega(self) -> float:
        """Ray diagram scale, mm per rad/s."""
        return self.h * self.mu_v / self.mu_l


def carrier_of(shafts: dict, s: str) -> str | None:
    return shafts[s].carrier


def mesh_carrier(shafts: dict, me: TrainMesh, file: str | None) -> str | None:
    ca, cb = carrier_of(shafts, me.shafts[0]), carrier_of(shafts, me.shafts[1])
    if ca is not None and cb is not None and ca != cb:
        raise InputError(Said("gt_gears_ride_different", v=me.gears[0], v2=me.gears[1], ca=ca, cb=cb), file=file, field="shafts")
    return ca or cb


def willis(shafts: dict, meshes: list[TrainMesh], file: str | None) -> dict[str, float]:
    """ω of every shaft (rad/s) from Willis' formula per mesh and the given speeds."""
    names = list(shafts)
    idx = {n: i for i, n in enumerate(names)}
    rows, rhs = [], []
    for me in meshes:
        row = np.zeros(len(names))
        C = mesh_carrier(shafts, me, file)
        sign = -1.0 if me.internal_gear else 1.0
        za, zb = me.z
        row[idx[me.shafts[0]]] += za
        row[idx[me.shafts[1]]] += sign * zb
        if C is not None:
            row[idx[C]] -= za + sign * zb
        rows.append(row)
        rhs.append(0.0)
    for n, s in shafts.items():
        if s.speed_rpm is not None:
            row = np.zeros(len(names))
            row[idx[n]] = 1.0
            rows.append(row)
            rhs.append(math.pi * s.speed_rpm / 30.0)
    A = np.array(rows, dtype=float).reshape(-1, len(names))
    b = np.array(rhs, dtype=float)
    rank = np.linalg.matrix_rank(A) if len(A) else 0
    if rank < len(names):
        free = len(names) - rank
        raise InputError(Said("gt_train_has_free", free=free),
                         file=file, field="shafts")
    w, *_ = np.linalg.lstsq(A, b, rcond=None)
    scale = max(1.0, float(np.max(np.abs(b))))
    if float(np.max(np.abs(A @ w - b))) > AGREE_REL * scale * max(1.0, float(np.max(np.abs(A)))):
        raise InputError(Said("gt_given_speeds_contradict"), file=file, field="shafts")
    return {n: float(w[idx[n]]) for n in names}


def layout(shafts: dict, meshes: list[TrainMesh], file: str | None) -> tuple[dict[str, float],
                                                                               dict[tuple[str, str], float]]:
    """Heights of the axes and pitch points on the unfolded train (metres, first shaft at 0)."""
    axes: dict[str, float] = {}
    pitch: dict[tuple[str, str], float] = {}
    gear_shafts = [s for me in meshes for s in me.shafts]
    if not gear_shafts:
        return {n: 0.0 for n in shafts}, pitch
    axes[gear_shafts[0]] = 0.0
    todo = list(meshes)
    while todo:
        progress = False
        for me in list(todo):
            sa, sb = me.shafts
            if sa not in axes and sb not in axes:
                continue
            k = 0 if sa in axes else 1
            known, other = me.shafts[k], me.shafts[1 - k]
            rk, ro = me.r_w[k], me.r_w[1 - k]
            y_p = axes[known] + rk  # the pitch point above the known axis
            y_o = y_p - ro if me.internal_gear is not None else y_p + ro
            pitch[me.gears] = y_p
            if other in axes:
                if abs(axes[other] - y_o) > 1e-9 * max(1.0, abs(y_o)) + 1e-9:
                    raise InputError(Said("gt_gears_train_does", v=me.gears[0], v2=me.gears[1], v3=abs(axes[other] - y_o) * 1e3),
                                     file=file, field="meshes")
            else:
                axes[other] = y_o
            todo.remove(me)
            progress = True
        if not progress:
            raise InputError(Said("gt_meshes_do_join"), file=file, field="meshes")
    for n in shafts:  # carriers sit on the axis of the central wheels they turn about
        if n in axes:
            continue
        centrals = set()
        for me in meshes:
            for k in (0, 1):
                if carrier_of(shafts, me.shafts[k]) == n and carrier_of(shafts, me.shafts[1 - k]) is None:
                    centrals.add(round(axes[me.shafts[1 - k]], 12))
        if len(centrals) > 1:
            raise InputError(Said("gt_carrier_its_central", n=n), file=file, field="shafts")
        axes[n] = centrals.pop() if centrals else 0.0
    return axes, pitch


def _at(p0: Pt, p1: Pt, y: float) -> float:
    """x of the line p0p1 at height y (the lines of a plan are never horizontal)."""
    return p0[0] + (y - p0[1]) * (p1[0] - p0[0]) / (p1[1] - p0[1])


def velocity_plan(shafts: dict, meshes: list[TrainMesh], file: str | None, *, mu_l: float,
                  v_len: float = 100.0, h: float = 0.0) -> VelocityPlan:
    """Build the plan line by line from the given speeds, then read ω off the ray diagram.

    One construction read top to bottom as it is drawn (scales, lines, rays, the closing
    check), hence its length."""
    axes, pitch = layout(shafts, meshes, file)
    Y = {n: y * mu_l for n, y in axes.items()}
    lines: dict[str, tuple[Pt, Pt, list[tuple[str, Pt]]]] = {}
    order: list[str] = []
    # the scale of velocities: the fastest given speed draws its farthest pitch point v_len long
    vmax = 0.0
    for me in meshes:
        for k in (0, 1):
            sp = shafts[me.shafts[k]].speed_rpm
            if sp:
                vmax = max(vmax, abs(sp) * math.pi / 30.0 * abs(pitch[me.gears] - axes[me.shafts[k]]))
    for n, s in shafts.items():
        if s.speed_rpm and s.carrier is None:
            for q, t in shafts.items():
                if t.carrier == n:
                    vmax = max(vmax, abs(s.speed_rpm) * math.pi / 30.0 * abs(axes[q] - axes[n]))
    # round, as every scale of the sheets (the fastest at most v_len long)
    from plans.kinematics.scales import round_scale

    mu_v = round_scale(vmax, v_len) if vmax > 0 else 1.0
    slope = mu_v / mu_l  # drawn dv per drawn dy, per rad/s

    def known_points(n: str) -> list[tuple[str, Pt]]:
        pts: list[tuple[str, Pt]] = []
        s = shafts[n]
        if s.carrier is None:
            pts.append((f"O_{n}", (0.0, Y[n])))
        elif s.carrier in lines:
            a0, a1, _ = lines[s.carrier]
            pts.append((f"O_{n}", (_at(a0, a1, Y[n]), Y[n])))
        for me in meshes:
            if n in me.shafts:
                other = me.shafts[1 - me.shafts.index(n)]
                if other in lines:
                    a0, a1, _ = lines[other]
                    yp = pitch[me.gears] * mu_l
                    pts.append((f"P_{{{me.gears[0]}{me.gears[1]}}}", (_at(a0, a1, yp), yp)))
        for q, t in shafts.items():
            if t.carrier == n and q in lines:
                a0, a1, _ = lines[q]
                pts.append((f"O_{q}", (_at(a0, a1, Y[q]), Y[q])))
        return pts

    while len(lines) < len(shafts):
        progress = False
        for n, s in shafts.items():
            if n in lines:
                continue
            pts = known_points(n)
            distinct: list[tuple[str, Pt]] = []
            for name, p in pts:
                if all(abs(p[1] - q[1]) > 1e-9 for _, q in distinct):
                    distinct.append((name, p))
            if s.speed_rpm is not None and distinct:
                name, p = distinct[0]
                w = s.speed_rpm * math.pi / 30.0
                d = 10.0  # the given speed laid off 10 mm of radius away
                q = (p[0] + w * slope * d, p[1] + d)
                lines[n] = (p, q, [(name, p)])
            elif len(distinct) >= 2:
                lines[n] = (distinct[0][1], distinct[1][1], distinct)
            else:
                continue
            order.append(n)
            progress = True
        if not progress:
            missing = [n for n in shafts if n not in lines]
            raise InputError(Said("gt_velocity_plan_cannot", v=', '.join(missing)), file=file, field="shafts")
    if h <= 0.0:  # the pole distance: 50 mm, or a multiple of 5 mm keeping rays within 150 mm
        steep = max(abs((q[0] - p[0]) / (q[1] - p[1])) for p, q, _ in lines.values())
        h = 50.0 if steep * 50.0 <= 150.0 else max(5.0, 5.0 * math.floor(150.0 / steep / 5.0))
    out: dict[str, ShaftLine] = {}
    for n, (p0, p1, _) in lines.items():
        dx, dy = p1[0] - p0[0], p1[1] - p0[1]
        x = h * dx / dy  # the ray from the pole parallel to the line meets the reference line
        full = known_points(n)
        out[n] = ShaftLine(n, p0, p1, tuple(full), x, x * mu_l / (h * mu_v))
    for me in meshes:
        yp = pitch[me.gears] * mu_l
        la, lb = out[me.shafts[0]], out[me.shafts[1]]
        va, vb = _at(la.p0, la.p1, yp), _at(lb.p0, lb.p1, yp)
        if abs(va - vb) > AGREE_REL * max(1.0, abs(va)):
            raise InputError(Said("gt_given_speeds_contradict"), file=file, field="shafts")
    return VelocityPlan(mu_l, mu_v, h, axes, pitch, out, tuple(order))
