"""The cam sheet: motion diagrams by graphical integration, the ds/dφ–s diagram with the
pressure-angle rays and the region of allowed centres, the profile by inversion."""

from __future__ import annotations

import math
from collections.abc import Callable
from dataclasses import dataclass
from pathlib import Path
from typing import Any

import numpy as np

from drawings.linkage.panels import Panel, auto_length_scale, finish, ratio_text
from drawings.paper.backend import (
    CENTRE_LINE,
    HAIR,
    MAIN,
    THICK,
    THIN,
    Pt,
    Recording,
    Style,
    Transform,
)
from drawings.paper.common import arrow, dot, fmt
from drawings.paper.fonts import choose, drawing
from drawings.paper.i18n import lookup
from drawings.paper.sheet import GAP, TB_H, Sheet, SheetSpec, compose, sheet_spec, usable
from drawings.paper.text import layout
from plans.cams.analysis import Profile
from plans.cams.graphical import Integration, integral_scale
from plans.cams.model import Cam
from plans.cams.solution import CamSolution, solve_cam
from plans.kinematics.scales import DIVISIONS, ROUND, round_down, round_up

EXACT = Style(width=0.25, stroke="#1f5fbf", dash=(2.0, 1.0))
AXIS = CENTRE_LINE
REGION = Style(stroke=None, width=0.0, fill="#cfe3cf")
WARN = Style(width=0.7, stroke="#c00000")
SMALL = 2.5
LABEL = 3.5
PHI_LENGTH = 360.0  # mm for the whole turn on the motion diagrams of an A1 sheet (1 mm per degree)
ROW_GAP = 10.0  # mm between one motion diagram's lowest point and the next one's ordinate label

WORDS = {
    "motion": ("Диаграммы движения толкателя (графическое интегрирование)",
               "Follower motion diagrams (graphical integration)"),
    "diagram": ("Диаграмма ds/dφ – s: углы давления, область центров",
                "The ds/dφ – s diagram: pressure angles, region of centres"),
    "profile": ("Профиль кулачка (метод обращения)", "Cam profile by inversion"),
    "rocker": ("Область центров кулачка по углам давления (коромысло)",
               "Region of cam centres from the pressure angles (rocker)"),
    "results": ("Результаты", "Results"),
    "convexity": ("Выпуклость профиля: ρ = r0 + s + s″ > 0", "Convexity of the profile: ρ = r0 + s + s″ > 0"),
}


_w = lookup(WORDS)


@dataclass(frozen=True)
class Drawing:
    cam: Cam
    spec: SheetSpec
    panels: tuple[Panel, ...]
    sheets: tuple[Sheet, ...]


def drawing_scale(size_m: float, target_mm: float) -> float:
    """The largest standard drawing scale (GOST 2.302), paper mm per m, drawing ``size_m``
    within ``target_mm``."""
    return auto_length_scale(size_m, target_mm)


def nice_up(x: float) -> float:
    """The smallest 1, 2, 2.5, 5 × 10ⁿ not below x (x > 0)."""
    return round_up(x, DIVISIONS)


def pole_distance(x: float) -> float:
    """The shortest pole distance of the usual ones, not below x."""
    for h in (10.0, 12.0, 15.0, 20.0, 25.0, 30.0, 40.0, 50.0, 60.0, 80.0, 100.0):
        if h >= x:
            return h
    return nice_up(x)


def _centre_name(name: str, lang: str) -> str:
    """O_min, O_best as the sheet writes them (O_мин, O_опт on a Russian sheet)."""
    from drawings.paper.i18n import tr

    return {"O_min": tr("centre_min", lang), "O_best": tr("centre_best", lang)}.get(name, name)


def _unit(unit: str, lang: str) -> str:
    return {"mm": "мм", "cm": "см", "m": "м"}.get(unit, unit) if lang == "ru" else unit


def _lift(cam: Cam) -> tuple[float, str]:
    """Factor from SI lift to the drawn unit, and its name."""
    if cam.follower == "oscillating":
        return 180 / math.pi, "°"
    return 1 / cam.scale, cam.unit


def _text(rec: Recording, s: str, x: float, y: float, size: float = SMALL, anchor: str = "start",
          valign: str = "middle", eid: str = "") -> None:
    rec.text(layout(s, x, y, size, anchor, valign), "label", eid)


def motion_scales(cs: CamSolution, g: float = 1.0, tall: float = 1.0, lift: float = 1.0) -> tuple[float, float, float]:
    """The motion diagrams' scales: μ_a′ (mm per unit/rad², round) and the pole distances H1,
    H2 (mm, usual ones) integrating it to ds/dφ and s.  ``tall`` lengthens the ordinates,
    ``lift`` the s diagram's further (a shorter H2)."""
    f, _ = _lift(cs.cam)
    mo = cs.motion
    h = g * tall  # the ordinates' size
    x_of = PHI_LENGTH * g / (2 * math.pi)  # k_φ, mm per rad
    a_max = float(np.max(np.abs(mo.s2))) * f or 1.0
    v_max = float(np.max(np.abs(mo.s1))) * f or 1.0
    s_max = float(np.max(mo.s)) * f or 1.0
    k_a = round_down(32.0 * h / a_max, ROUND)  # a round scale: 1, 2, 2.5, 4, 5 × 10ⁿ
    # poles: the shortest usual H (10 mm at least) that keeps ds/dφ within 30h mm, s within 50h mm
    H1 = pole_distance(k_a * x_of * v_max / (30.0 * h))
    k_v = integral_scale(k_a, x_of, H1)
    H2 = pole_distance(k_v * x_of * s_max / (50.0 * h * lift))
    return k_a, H1, H2


def motion_panel(cs: CamSolution, lang: str, g: float = 1.0, tall: float = 1.0, over: bool = False,
                 lift: float = 1.0) -> Panel:
    """s, ds/dφ and d²s/dφ² against φ: a(φ) exact, integrated twice by mid-ordinates and a
    pole (the chains, thick), the exact curves beside them (dashed), one diagram under the
    other as tall as its curves.  ``g`` sizes the φ axis to the sheet (1 mm per degree on A1);
    ``tall`` and ``lift`` lengthen the ordinates where there is room (:func:`motion_scales`);
    each diagram's scales are written beyond its axis's end, or with ``over`` above the
    axis's end where the curve lies on the axis there (a dwell), leaving the room beyond it
    to the rest of the sheet."""
    cam = cs.cam
    f, unit = _lift(cam)
    ig: Integration = cs.integration
    mo = cs.motion
    length = PHI_LENGTH * g
    x_of = length / (2 * math.pi)  # k_φ, mm per rad
    k_a, H1, H2 = motion_scales(cs, g, tall, lift)
    k_v = integral_scale(k_a, x_of, H1)
    k_s = integral_scale(k_v, x_of, H2)
    rec = Recording()
    # each diagram as tall as its curves at its scale: the axes one under the other, ROW_GAP
    # between one diagram's lowest point and the next one's ordinate label
    reach = [(k * max(float(np.max(e)), 0.0 if c is None else float(np.max(c)), 0.0 if m is None else float(np.max(m))),
              k * max(-float(np.min(e)), 0.0 if c is None else -float(np.min(c)), 0.0 if m is None else -float(np.min(m)), 0.0))
             for k, e, c, m in ((k_s, mo.s * f, ig.s_nodes * f, None), (k_v, mo.s1 * f, ig.v_nodes * f, None),
                                (k_a, mo.s2 * f, None, ig.a_mid * f))]
    y_v = reach[0][1] + ROW_GAP + reach[1][0] + 6.0
    y_a = y_v + reach[1][1] + ROW_GAP + reach[2][0] + 6.0
    bottom = y_a + reach[2][1] + 2.0
    rows = [("s", k_s, mo.s * f, ig.s_nodes * f, None, 0.0, reach[0]),
            ("ds/dφ", k_v, mo.s1 * f, ig.v_nodes * f, None, y_v, reach[1]),
            ("d²s/dφ²", k_a, mo.s2 * f, None, ig.a_mid * f, y_a, reach[2])]
    X = cs.turn * x_of
    nodes_x = ig.nodes * x_of
    for name, k, exact, chain, mid, y0, (up, down) in rows:
        tag = {"s": "s", "ds/dφ": "ds", "d²s/dφ²": "d2s"}[name]  # ids: plain ASCII
        rec.line((-4, y0), (length + 6, y0), THIN, f"axis-{tag}")
        top = y0 - up - 6.0
        rec.line((0, y0 + down + 2.0 if down > 0 else y0), (0, top), THIN)
        _text(rec, name, 1.5, top, LABEL, "start", "top")
        _text(rec, "φ", length + 7, y0, LABEL)
        for xn in nodes_x:
            rec.line((xn, y0 - 0.8), (xn, y0 + 0.8), HAIR)
        pts = [(float(x), y0 - k * float(v)) for x, v in zip(X, exact, strict=True)]
        if chain is not None:
            rec.polyline(pts, EXACT, f"exact-{tag}")
            rec.polyline([(float(x), y0 - k * float(v)) for x, v in zip(nodes_x, chain, strict=True)], MAIN,
                         f"graphical-{tag}")
        else:
            rec.polyline(pts, MAIN, f"exact-{tag}")
            steps: list[Pt] = []
            assert mid is not None
            for i, m in enumerate(mid):
                steps += [(float(nodes_x[i]), y0 - k * float(m)), (float(nodes_x[i + 1]), y0 - k * float(m))]
            rec.polyline(steps, HAIR, "mid-ordinates")
        U, mm = _unit(unit, lang), _unit("mm", lang)
        rad, sec = ("рад", "с") if lang == "ru" else ("rad", "s")
        sub, per, phys = {"s": ("s", U, None), "ds/dφ": ("v", f"{U}/{rad}", ("v", f"{U}/{sec}", 1)),
                          "d²s/dφ²": ("a", f"{U}/{rad}²", ("a", f"{U}/{sec}²", 2))}[name]
        said = [f"μ_{sub}′ = {fmt(k, 4, lang)} {mm}/({per})" if name != "s" else f"μ_s = {fmt(k, 4, lang)} {mm}/{per}"]
        if phys is not None:
            # v = ω·ds/dφ, a = ω²·d²s/dφ²: the same curve read at μ′/ω and μ″/ω²
            said.append(f"μ_{phys[0]} = {fmt(k / cam.omega ** phys[2], 4, lang)} {mm}/({phys[1]})")
        wide = max(layout(t, 0, 0, SMALL).box[2] for t in said) + 2.0
        flat = over and all(bool(np.all(k * v[x >= length - wide] < 1.5)) for x, v in
                            ((X, exact), (nodes_x, chain), (nodes_x[1:], mid)) if v is not None)
        for t, dy in zip(said, (7.0, 3.5), strict=False):
            _text(rec, t, *((length, y0 - dy - 1.0) if flat else (length + 7, y0 - dy)), SMALL, "end" if flat else "start")
    # the poles and their rays: integrand's mid-ordinate projected on the axis, ray from P
    for (k, mids, y0, H, tag) in ((k_a, ig.a_mid * f, y_a, H1, "1"), (k_v, ig.v_mid * f, y_v, H2, "2")):
        P = (-H, y0)
        dot(rec, P, 0.6, f"pole-{tag}")
        _text(rec, f"P{tag}", P[0] - 1, P[1], SMALL, "end")
        _text(rec, f"H{tag} = {fmt(H, 3, lang)} {_unit('mm', lang)}", P[0] - 1, P[1] + 3.5, SMALL, "end")
        for m in mids:
            rec.line(P, (0.0, y0 - k * float(m)), Style(width=0.13, stroke="#888"))
    # the phase boundaries and their angles
    for ph in cam.phases:
        xb = ph.start * x_of
        rec.line((xb, -2), (xb, bottom), Style(width=0.13, stroke="#888", dash=(1.0, 1.0)))
        _text(rec, f"{math.degrees(ph.angle):g}°", xb + ph.angle * x_of / 2, bottom + 3, SMALL, "middle")
    err = cs.integration_error * f
    mm = _unit("mm", lang)
    note = (f"μ_φ = {fmt(x_of * math.pi / 180, 4, lang)} {mm}/°; μ′ = μ·μ_φ/H; "
            f"|Δs| ≤ {fmt(err, 3, lang)} {_unit(unit, lang)}; " + ("штрих — точно" if lang == "ru" else "dashed: exact"))
    return finish("motion", "cam-motion", None, rec, _w("motion", lang), note=note)


def diagram_panel(cs: CamSolution, lang: str, g: float = 1.0) -> Panel:
    """D = (−k·ds/dφ, s) from B0 at one length scale, the rays at [α] tangent to the curve,
    the allowed region below them, the centres: minimum at the file's offset, the best, the
    file's own."""
    cam, br = cs.cam, cs.base_radius
    assert br.bounds is not None
    mo = cs.motion
    Xd, Yd = -cam.sense * mo.s1, mo.s
    s0 = math.sqrt(cam.base_radius**2 - cam.offset**2)
    O_file = (-cam.offset, -s0)
    assert br.centre is not None  # a translating follower always has one
    pts = np.vstack([np.c_[Xd, Yd], [O_file, br.centre, br.best_centre]])
    span = float(np.max(np.ptp(pts, axis=0)))
    mu = drawing_scale(span, 200.0 * g)  # paper mm per m
    rec = Recording()

    def P(x: float, y: float) -> Pt:
        return (mu * x, -mu * y)

    xmin, xmax = float(pts[:, 0].min()) - 0.1 * span, float(pts[:, 0].max()) + 0.1 * span
    ymin = float(pts[:, 1].min()) - 0.15 * span
    # allowed region: clip the half-planes to the box
    assert br.bounds is not None
    region = cs.allowed_region((xmin, ymin, xmax, float(np.max(Yd))))
    if len(region) >= 3:
        rec.polygon([P(*q) for q in region], REGION, "allowed-region")
    rec.line(P(0, ymin), P(0, float(np.max(Yd)) * 1.1), AXIS, "follower-line")
    rec.line(P(xmin, 0), P(xmax, 0), THIN, "ds-axis")
    rec.polyline([P(float(x), float(y)) for x, y in zip(Xd, Yd, strict=True)], MAIN, "ds-s-curve")
    for x, y in cs.division_diagram:
        dot(rec, P(x, y), 0.4)
    for i, (t, _c1, _c2) in enumerate(br.bounds.lines):
        for j, sgn in enumerate((1, -1)):
            D = br.bounds.tangent[2 * i + j]
            # ray through D leaning by α: direction down-left (c1) or down-right (c2)
            d = (-sgn * t, -1.0)
            L = min(D[1] - ymin, ((D[0] - xmin) if d[0] < 0 else (xmax - D[0])) / max(abs(d[0]), 1e-12))
            E = (D[0] + d[0] * L, D[1] + d[1] * L)
            rec.line(P(*D), P(*E), Style(width=0.35, stroke="#1f5fbf"), f"ray-{i}-{j}")
            dot(rec, P(*D), 0.5)
            if j == 0:
                _text(rec, f"{fmt(math.degrees(math.atan(t)), 3, lang)}°", *P(*E), SMALL, "start", "top")
    for name, c, st in (("O_min", br.centre, "#c00000"), ("O_best", br.best_centre, "#1f7f1f"),
                        ("O", O_file, "#000")):
        q = P(*c)
        rec.circle(q, 0.8, Style(stroke=None, width=0, fill=st), f"centre-{name}")
        _text(rec, _centre_name(name, lang), q[0] + 1.5, q[1] + 1.5, LABEL, "start", "top")
    _text(rec, "B0", *P(0, 0), LABEL, "end", "bottom")
    _text(rec, "s", *P(0, float(np.max(Yd)) * 1.1), LABEL, "start", "bottom")
    _text(rec, "ds/dφ", *P(xmax, 0), SMALL, "end", "bottom")
    note = f"μ_l = {fmt(mu * cam.scale, 4, lang)} {_unit('mm', lang)}/{_unit(cam.unit, lang)} ({ratio_text(mu, lang)})"
    return finish("ds-s", "cam-diagram", None, rec, _w("diagram", lang), note=note)


def rocker_panel(cs: CamSolution, lang: str, g: float = 1.0) -> Panel:
    """The oscillating follower's diagram: pivot A, the arm positions A–B at the division
    points, D on each arm at (1 − r)·AB, the wedges' region of allowed centres, the circle of
    the file's pivot distance and the centres on it."""
    cam, br = cs.cam, cs.base_radius
    q = cs.division
    d = cs.rocker
    fine = cs.rocker_fine
    centres = [(0.0, 0.0), br.best_centre] + ([br.centre] if br.centre is not None else [])
    pts = np.vstack([d.B, fine.D, [d.A, *centres]])
    x0, y0 = pts.min(axis=0)
    x1, y1 = pts.max(axis=0)
    span = max(x1 - x0, y1 - y0)
    box = (x0 - 0.3 * span, y0 - 0.3 * span, x1 + 0.1 * span, y1 + 0.1 * span)
    mu = drawing_scale(span * 1.4, 200.0 * g)
    rec = Recording()

    def P(v) -> Pt:
        return (mu * float(v[0]), -mu * float(v[1]))

    poly = cs.rocker_region(box)
    if len(poly) >= 3:
        rec.polygon([P(v) for v in poly], REGION, "allowed-region")
    # the arc of the file's pivot distance about A, where O may sit
    a_o = math.atan2(-d.A[1], -d.A[0])
    arc = [P((d.A[0] + cam.pivot * math.cos(a_o + t), d.A[1] + cam.pivot * math.sin(a_o + t)))
           for t in np.linspace(-0.6, 0.6, 121)]
    rec.polyline(arc, Style(width=0.18, stroke="#333", dash=(3.0, 1.5)), "pivot-arc")
    for i in range(len(q)):
        rec.line(P(d.A), P(d.B[i]), Style(width=0.18, stroke="#555"), f"arm-{i}")
        rec.line(P(d.B[i]), P(d.D[i]), Style(width=0.35, stroke="#1f5fbf"), f"BD-{i}")
        dot(rec, P(d.B[i]), 0.35)
    rec.polyline([P(v) for v in fine.D], MAIN, "D-curve")
    dot(rec, P(d.A), 0.7, "pivot")
    _text(rec, "A", *P(d.A), LABEL, "start", "top")
    _text(rec, "B0", *P(d.B[0]), LABEL, "end", "bottom")
    for name, c, st in (("O_min", br.centre, "#c00000"), ("O_best", br.best_centre, "#1f7f1f"),
                        ("O", (0.0, 0.0), "#000")):
        if c is None:
            continue
        rec.circle(P(c), 0.8, Style(stroke=None, width=0, fill=st), f"centre-{name}")
        _text(rec, _centre_name(name, lang), P(c)[0] + 1.5, P(c)[1] + 1.5, LABEL, "start", "top")
    note = f"{ratio_text(mu, lang)}; AD = (1 − r)·AB, r = ω_2/ω_1; ∠(OD, ⟂AB) = α"  # 1 the cam, 2 the rocker
    return finish("rocker", "cam-diagram", None, rec, _w("rocker", lang), note=note)


def convexity_panel(cs: CamSolution, lang: str, g: float = 1.0, tall: float = 1.0) -> Panel:
    """A flat face's base radius: s + d²s/dφ² over the turn (its φ axis the motion diagrams'),
    the least base radius at the depth of its lowest point (ρ = r0 + s + s″ > 0 everywhere
    above it) and the file's r0; the profile's radius of curvature is read between them."""
    from drawings.cycle.cycle_plot import Axes
    from plans.kinematics.scales import round_scale

    cam, mo = cs.cam, cs.motion
    f = 1.0 / cam.scale  # to the file's unit
    y = (mo.s + mo.s2) * f
    r0, r_min = cam.base_radius * f, (cs.base_radius.min_base_radius or 0.0) * f
    length = PHI_LENGTH * g
    deep = max(float(np.max(np.abs(y))), r0)
    mu = round_scale(deep, 60.0 * g * tall)  # mm per the file's unit
    rec = Recording()
    ax = Axes(rec, "convexity", length / (2 * math.pi), 0.0, lang)
    ax.frame(length, -deep * mu, float(np.max(y)) * mu, "s + s″")
    xs = np.asarray(cs.turn) * length / (2 * math.pi)
    ax.curve(xs, y * mu, MAIN, "s-plus-s2")
    U = _unit(cam.unit, lang)
    ax.hline(-r_min * mu, 0.0, length, WARN, f"−r0 min = −{fmt(r_min, 4, lang)} {U}", "r0-min")
    ax.hline(-r0 * mu, 0.0, length, EXACT, f"−r0 = −{fmt(r0, 4, lang)} {U}", "r0")
    for ph in cam.phases:
        xb = ph.start * length / (2 * math.pi)
        rec.line((xb, -float(np.max(y)) * mu - 2.0), (xb, r0 * mu + 2.0), Style(width=0.13, stroke="#888", dash=(1.0, 1.0)))
    mm = _unit("mm", lang)
    scale = f"μ_φ = {fmt(length / 360.0, 4, lang)} {mm}/°; μ = {fmt(mu, 4, lang)} {mm}/{U}"
    return finish("convexity", "cam-diagram", None, rec, _w("convexity", lang), scale)


def profile_panel(cs: CamSolution, lang: str, target: float = 180.0, mu: float | None = None) -> Panel:
    """Inversion: the follower's positions at the division points turned by −φ, the
    theoretical profile through the roller centres, the roller circles and their envelope; at
    the largest standard scale drawing the cam's reach within ``target`` mm (or at ``mu``)."""
    cam = cs.cam
    pr: Profile = cs.profile
    q = cs.division
    pq = cs.division_profile
    reach = float(np.max(np.hypot(*pr.theoretical.T))) + cam.roller + 0.15 * cam.base_radius
    if cam.follower == "oscillating":
        reach = max(reach, cam.pivot + 0.15 * cam.arm)
    if mu is None:
        mu = drawing_scale(reach, target)  # paper mm per m
    rec = Recording()

    def P(v: np.ndarray | tuple[float, float]) -> Pt:
        return (mu * float(v[0]), -mu * float(v[1]))

    r0 = cam.base_radius
    rec.circle((0, 0), mu * r0, Style(width=0.18, stroke="#333", dash=(6.0, 1.0, 1.0, 1.0)), "base-circle")
    if cam.roller > 0:
        rec.circle((0, 0), mu * (r0 - cam.roller), HAIR, "actual-base-circle")
    _follower_positions(rec, cam, pr, pq, q, mu)
    if cam.follower == "translating" and abs(cam.offset) > 0:
        rec.circle((0, 0), mu * abs(cam.offset), HAIR, "offset-circle")
    if cam.follower == "oscillating":
        rec.circle((0, 0), mu * cam.pivot, Style(width=0.13, stroke="#777", dash=(3.0, 1.5)), "pivot-circle")
    if not cam.flat:  # a flat face touches the cam itself: one profile
        rec.polyline([P(p) for p in pr.theoretical], Style(width=0.35, stroke="#1f5fbf",
                                                           dash=(6.0, 1.0, 1.0, 1.0)), "theoretical-profile")
    if cam.roller > 0 or cam.flat:
        rec.polyline([P(p) for p in pr.actual], THICK, "actual-profile")
    bad = (pr.curvature <= 0) if cam.flat else (pr.curvature * cam.roller >= 1.0) if cam.roller > 0 else \
        np.zeros_like(pr.curvature, bool)
    if np.any(bad):
        for j in np.flatnonzero(bad):
            rec.circle(P(pr.actual[j]), 0.5, Style(stroke=None, width=0, fill="#c00000"), f"undercut-{j}")
    _phases_and_omega(rec, cam, pr, mu)
    note = (f"{ratio_text(mu, lang)}; {len(q)} положений, повёрнутых на −φ" if lang == "ru" else
            f"{ratio_text(mu, lang)}; {len(q)} positions turned by −φ")
    return finish("profile", "cam-profile", None, rec, _w("profile", lang), note=note, quantity="length",
                  scale=mu)


def _P(mu: float) -> Callable[[Any], Pt]:
    """World metres (y up) to the panel's paper mm at μ mm per m."""
    T = Transform(mu)

    def P(v: Any) -> Pt:
        return T(float(v[0]), float(v[1]))

    return P


def _follower_positions(rec: Recording, cam: Cam, pr: Profile, pq: Profile, q: np.ndarray, mu: float) -> None:
    """At each division point: the follower (its line and flat face, or its arm) turned by
    −φ, the roller circle about the roller centre, the number of the position."""
    P = _P(mu)
    k = cam.sense
    r0 = cam.base_radius
    for i, ph_ in enumerate(q):
        c, s = math.cos(-k * ph_), math.sin(-k * ph_)

        def R(v: np.ndarray, c: float = c, s: float = s) -> np.ndarray:
            return np.array([c * v[0] - s * v[1], s * v[0] + c * v[1]])

        B = pq.theoretical[i]
        if cam.follower == "translating":
            s0 = math.sqrt(r0**2 - cam.offset**2)
            foot = R(np.array([cam.offset, s0 - 0.1 * r0]))
            top = R(np.array([cam.offset, s0 + cam.h + cam.roller + 0.12 * r0]))
            rec.line(P(foot), P(top), Style(width=0.13, stroke="#777"), f"follower-{i}")
            if cam.flat:  # the face at r0 + s, perpendicular to the follower, touching at B
                lift = cam.base_radius + float(pq.motion.s[i])
                w = float(np.max(np.abs(pr.motion.s1))) + 0.15 * r0
                rec.line(P(R(np.array([-w, lift]))), P(R(np.array([w, lift]))),
                         Style(width=0.25, stroke="#555"), f"face-{i}")
        else:
            A = R(np.array([cam.pivot, 0.0]))
            rec.line(P(A), P(B), Style(width=0.25, stroke="#555"), f"arm-{i}")
            dot(rec, P(A), 0.35)
        if cam.roller > 0:
            rec.circle(P(B), mu * cam.roller, Style(width=0.18, stroke="#555"), f"roller-{i}")
        dot(rec, P(B), 0.35)
        rb = math.hypot(*B)
        lab = np.asarray(B) * (rb + cam.roller + 2.5 / mu) / rb  # just outside the roller circle
        _text(rec, str(i), *P(lab), SMALL, "middle")


def _phases_and_omega(rec: Recording, cam: Cam, pr: Profile, mu: float) -> None:
    P = _P(mu)
    k = cam.sense
    r0 = cam.base_radius
    # the phase angles, laid off from the start of the rise against ω as the follower turns
    outer = float(np.max(np.hypot(*pr.theoretical.T))) + cam.roller + 6.0 / mu
    a0 = math.atan2(float(pr.theoretical[0, 1]), float(pr.theoretical[0, 0]))
    for i, ph in enumerate(cam.phases):
        a = a0 - k * ph.start
        rec.line((0, 0), P((outer * math.cos(a), outer * math.sin(a))),
                 Style(width=0.13, stroke="#888", dash=(1.0, 1.0)), f"phase-{i}")
        m = a0 - k * (ph.start + ph.angle / 2)
        _text(rec, f"{math.degrees(ph.angle):g}°", *P((outer * math.cos(m), outer * math.sin(m))), SMALL,
              "middle")
    dot(rec, (0, 0), 0.7, "cam-centre")
    _text(rec, "O", 1.5, 2.0, LABEL, "start", "top")
    # the sense of rotation
    rr = mu * r0 * 0.35
    a0, a1 = (0.3, 1.3) if k > 0 else (1.3, 0.3)
    p0 = (rr * math.cos(a0), -rr * math.sin(a0))
    p1 = (rr * math.cos(a1), -rr * math.sin(a1))
    rec.arc((0, 0), rr, -max(a0, a1), -min(a0, a1), THIN)
    arrow(rec, (p1[0] + (p1[1]) * 0.15 * k, p1[1] - p1[0] * 0.15 * k), p1, THIN, "omega", "omega")
    _text(rec, "ω", p0[0] + 1.5, p0[1], LABEL)


def results_panel(cs: CamSolution, lang: str) -> Panel:
    cam, br, drawn = cs.cam, cs.base_radius, cs.drawn_base_radius
    ru = lang == "ru"

    def T(en: str, rus: str) -> str:
        return rus if ru else en

    fi = cs.findings
    L = cam.scale
    u = _unit(cam.unit, lang)

    def n(v: float, sig: int = 4) -> str:
        return fmt(v, sig, lang)

    where = (T(f"arm = {n(cam.arm / L)} {u}, pivot at {n(cam.pivot / L)} {u}",
               f"коромысло {n(cam.arm / L)} {u}, ось на {n(cam.pivot / L)} {u}")
             if cam.follower == "oscillating" else f"e = {n(cam.offset / L)} {u}")
    tip = T("flat face", "плоский толкатель") if cam.flat else f"r_ролика = {n(cam.roller / L)} {u}" if ru \
        else f"r_roller = {n(cam.roller / L)} {u}"
    a_r, a_b = math.degrees(fi.max_pressure_rise), math.degrees(fi.max_pressure_return)
    lines = [
        f"r0 = {n(cam.base_radius / L)} {u}, {where}, {tip}",
        T(f"α max: rise {n(a_r)}° ([α] = {n(math.degrees(cam.alpha_rise), 3)}°), return {n(a_b)}° "
          f"([α] = {n(math.degrees(cam.alpha_return), 3)}°)",
          f"α max: подъём {n(a_r)}° ([α] = {n(math.degrees(cam.alpha_rise), 3)}°), опускание {n(a_b)}° "
          f"([α] = {n(math.degrees(cam.alpha_return), 3)}°)"),
    ]
    if br.min_base_radius is None:
        lines.append(T("r0 min: none with this arm and pivot", "r0 min: нет при этих коромысле и оси"))
    else:
        line = f"r0 min = {n(br.min_base_radius / L, 5)} {u} ({T('exact', 'точно')})"
        if drawn is not None and drawn.min_base_radius is not None:
            line += f", {n(drawn.min_base_radius / L, 5)} {u} ({T('diagram', 'по диаграмме')})"
        lines.append(line)
    if br.best_offset is not None and cam.follower == "translating" and not cam.flat:
        lines.append(T("best", "наименьший") + f": r0 = {n(br.best_base_radius / L, 5)} {u}, "
                     f"e = {n(br.best_offset / L)} {u}")
    if br.best_pivot is not None:
        lines.append(T("best", "наименьший") + f": r0 = {n(br.best_base_radius / L, 5)} {u}, "
                     + T("pivot at", "ось на") + f" {n(br.best_pivot / L)} {u}")
    lines.append(T("ρ min (convex, theoretical)", "ρ min (выпуклый, теоретический)")
                 + f" = {n(fi.min_curvature_radius / L)} {u}")
    for c in fi.undercut:
        lines.append(T("UNDERCUT", "ПОДРЕЗ") + f" φ = {n(c.start_deg)}…{n(c.end_deg)}°: "
                     f"ρ = {n(c.min_radius / L)} {u} < r")
    if not fi.undercut:
        lines.append(T("no undercut", "подреза нет"))
    rec = Recording()
    for i, t in enumerate(lines):
        rec.text(layout(t, 0, i * 5.5, LABEL, "start", "top"), "label", f"result-{i}",
                 fill="#c00000" if t.startswith(("UNDERCUT", "ПОДРЕЗ")) else "#000")
    return finish("results", "cam-results", None, rec, _w("results", lang))


def build_panels(cs: CamSolution, spec: SheetSpec) -> list[Panel]:
    """The profile, the motion diagrams, the base radius's diagram and the results: at the A1
    lengths, or larger where one sheet holds them all: the profile at the largest standard
    scale it does, then, of the motion diagrams' round scales and usual poles (the φ axis
    keeps its length, their scales written beyond the axes or over a dwell at their ends) and
    the third diagram's scales, those covering most of the sheet."""
    from drawings.linkage.panels import STANDARD_RATIOS
    from drawings.paper.fill import fullest_of_chains

    lang = spec.language
    W, H = spec.size
    g = min(W / 841.0, H / 594.0)
    # the profile: as big as A1 allows beside the rest, and never taller than the sheet beside
    # its title block (about 2.3 × the reach with the follower's lines and labels)
    x0, y0, x1, y1 = usable(W, H)
    target = min(180.0 * g, (y1 - y0 - TB_H - GAP - 20.0) / 2.3)
    cam = cs.cam
    results = results_panel(cs, lang)

    def third(size: float) -> list[Panel]:
        if cs.base_radius.bounds is not None:
            return [diagram_panel(cs, lang, size)]
        if cam.follower == "oscillating":
            return [rocker_panel(cs, lang, size)]
        return [convexity_panel(cs, lang, g, size / g)] if cam.flat else []

    first = profile_panel(cs, lang, target)
    at_a1 = [first, motion_panel(cs, lang, g), *third(g), results]
    base = first.scale or 1000.0
    mus = [r * 1000.0 for r in STANDARD_RATIOS if base / 2.0 - 1e-9 <= r * 1000.0 <= 4.0 * base + 1e-9]
    # the motion diagrams: their scales beyond the axes, then over their ends where they may
    # be; the ordinates from the longest, s's pole shorter still; round scales and usual poles
    # make many the same size: each size once
    sizes: dict[tuple[float, float, float], tuple[float, float]] = {}
    for tenths in range(40, 9, -1):
        for lift in (1.5, 1.25, 1.0):
            sizes.setdefault(motion_scales(cs, g, tenths / 10.0, lift), (tenths / 10.0, lift))
    motions: dict[tuple[int, int], Panel] = {}
    chains: list[list[Panel]] = []  # of each placing of the scales, from the shortest diagrams
    for over in (False, True):
        chain = []
        for tall, lift in sizes.values():
            m = motion_panel(cs, lang, g, tall, over, lift)
            if (round(m.width), round(m.height)) not in motions:
                motions[(round(m.width), round(m.height))] = m
                chain.append(m)
        chains.append(sorted(chain, key=lambda m: (m.height, m.width)))
    thirds = [third(g * size) for size in (1.0, 1.5, 2.0)]

    def candidates(mu: float) -> list[list[list[Panel]]]:
        profile = profile_panel(cs, lang, target, mu)
        return [[[profile, m, *t, results] for m in chain] for t in thirds for chain in chains]

    found = fullest_of_chains((candidates(mu) for mu in sorted(mus, reverse=True)), spec, cam.path,
                              lambda ps: ratio_text(ps[0].scale or 1000.0, spec.language))
    return found[0] if found is not None else at_a1


@drawing
def draw(source: CamSolution | Cam | str | Path, *, format: str | None = None, orientation: str | None = None,
         language: str | None = None, font: str | None = None) -> Drawing:
    """The cam's sheets: of a solved cam (``plans.solve``), or of a cam or the path of its
    file, solved here."""
    cs = source if isinstance(source, CamSolution) else solve_cam(source)
    cam = cs.cam
    spec = sheet_spec(cam.raw, cam.path, cam.title, format=format, orientation=orientation, language=language,
                      font=font)
    choose(spec.font, cam.path, font)
    panels = build_panels(cs, spec)
    sheets = compose(panels, spec, ratio_text(panels[0].scale or 1000.0, spec.language), cam.path)
    return Drawing(cam, spec, tuple(panels), tuple(sheets))
