"""The extreme positions of the output link and its two strokes, as the course takes them.

The output is a slider on a guide of the frame (its coordinate along the guide) or a
rocker turning about a pivot of the frame (its angle): ``[driver] extreme_of`` names it
(a link number, or a point the slider or the rocker carries); by default it is the output
of the last Assur group that reaches the frame.  Its two extreme positions split the
revolution into two strokes; the **working stroke** is the slow one (the longer crank
angle, K = φ_working/φ_idle ≥ 1, θ = φ_working − 180°), the idle stroke the fast one.
Where both take 180° (K = 1) the working stroke is the one that begins at the extreme
farther from the crank's pivot (the outer dead centre of a slider-crank).

The extremes are found exactly: in closed form where the output's group hangs on the
crank (slider-crank: crank and rod in line; crank-rocker: crank and coupler in line;
slotted rocker: crank ⟂ slot), checked against the bracket where the output's velocity
changes sign; otherwise as that root itself, bisected to the last bit of the crank angle.

``[driver] phi_start = "extreme"`` starts the positions at the extreme where the working
stroke begins (the course's position 0), ``"extreme_idle"`` at the other one.
"""

from __future__ import annotations

import cmath
import dataclasses
import math
from typing import Any

import numpy as np

from plans.errors import ConstructionError, InputError, Said
from plans.records import derived, frozen
from plans.scene.model import Joint, Scene
from plans.scene.positions import FromExtreme
from plans.tolerances import COINCIDE_REL, SAME_ANGLE_DEG

#: The strokes' crank angles differ by less than this (degrees): K = 1, the tie rule decides.
TIE_DEG = 1e-7
GRID = 720  # samples of a revolution that bracket the extremes (0.5° apart)


@frozen
class Output:
    """The link whose extremes are taken: a slider on a guide of the frame, or a rocker."""

    kind: str  # "slider" | "rocker"
    link: int
    point: str  # the slider's pin; the rocker's pin farthest along the chain (its group's point)
    joint: Joint  # the slider's prismatic pair with the frame, or the rocker's pivot


@frozen
class Strokes:
    """The output's extreme positions (crank angles φ in the driver's own measure, degrees)
    and its strokes: the working stroke runs from ``working_deg`` for ``working_span`` degrees."""

    output: Output
    working_deg: float  # where the working stroke begins (the course's position 0)
    idle_deg: float  # where the idle stroke begins
    working_span: float  # crank degrees of the working stroke
    working_up: bool  # the output's coordinate grows on the working stroke
    closed_form: bool  # the extremes were found in closed form (else bisected)

    @property
    def K(self) -> float:
        """Coefficient of speed change K = t_working / t_idle."""
        return self.working_span / (360.0 - self.working_span)

    @property
    def theta_deg(self) -> float:
        """The overlap angle θ = 180°(K − 1)/(K + 1)."""
        return self.working_span - 180.0

    def working(self, phi_deg: Any) -> Any:
        """True where a crank angle lies on the working stroke (its first extreme included)."""
        d = np.mod(np.asarray(phi_deg, float) - self.working_deg, 360.0)
        d = np.where(d > 360.0 - SAME_ANGLE_DEG, 0.0, d)  # the working extreme met to round-off
        return d < self.working_span - SAME_ANGLE_DEG

    def to_json(self, start: str) -> dict[str, Any]:
        """``phi_start`` of the JSON: the start asked for, its φ, the output and its strokes."""
        return {"start": start, "phi_deg": self.working_deg if start == "extreme" else self.idle_deg,
                "output": {"kind": self.output.kind, "link": self.output.link, "point": self.output.point},
                "working_from_deg": self.working_deg, "idle_from_deg": self.idle_deg,
                "working_stroke_deg": self.working_span, "idle_stroke_deg": 360.0 - self.working_span,
                "K": self.K, "theta_deg": self.theta_deg,
                "found": "closed form" if self.closed_form else "bisection"}


def start_line(scene: Scene, lang: str) -> str:
    """The protocol's line saying where the positions start."""
    from plans.phrases import say

    st = scene.driver.strokes
    o = st.output
    kind = say("x_slider" if o.kind == "slider" else "x_rocker", lang)
    key = "x_start_working" if scene.driver.start == "extreme" else "x_start_idle"
    phi = st.working_deg if scene.driver.start == "extreme" else st.idle_deg
    return say(key, lang, link=o.link, kind=kind, point=o.point, phi=phi, work=st.working_span,
               idle=360.0 - st.working_span, K=st.K, theta=st.theta_deg)


# --------------------------------------------------------------------------- the output


def _fail(scene: Scene, field: str, msg: str | Said) -> InputError:
    return InputError(msg, file=scene.path, field=field)


def _on_frame(scene: Scene, lid: int) -> Output | None:
    """The link as a slider on a guide of the frame, or as a rocker pivoted on it."""
    for j in scene.joints:
        if j.kind == "P" and j.guide is not None and j.guide.link == scene.frame and j.slider == lid:
            return Output("slider", lid, j.point, j)
    for j in scene.joints:
        if j.kind == "R" and scene.frame in j.links and lid in j.links:
            far = [k.point for k in scene.joints if lid in k.links and k is not j]
            return Output("rocker", lid, far[-1] if far else j.point, j)
    return None


def output_of(scene: Scene, field: str = "driver.extreme_of") -> Output:
    """The output the scene names (``[driver] extreme_of``) or the last group's: of a dyad its
    second link or its first, of a triad its third leash, second, first or its base link (a
    press's ram, a crusher's swing link), the first on the frame."""
    from plans.kinematics.structure import Group, TriadGroup, analyse

    d = scene.raw.get("driver", {})
    want = d.get("extreme_of") if isinstance(d, dict) else None
    if want is not None:
        if isinstance(want, int) and not isinstance(want, bool):
            cands = [want] if want in scene.links and want != scene.driver.link else []
        elif isinstance(want, str):
            cands = [lid for lid in scene.point_links(want) if lid not in (scene.frame, scene.driver.link)]
        else:
            cands = []
        if not cands:
            raise _fail(scene, field, Said("kx_moving_link_crank", want=want))
        outs = [o for o in (_on_frame(scene, lid) for lid in cands) if o is not None]
        sliders = [o for o in outs if o.kind == "slider"]
        if not outs:
            raise _fail(scene, field, Said("kx_want_neither_slider", want=want))
        return (sliders or outs)[0]
    st = analyse(scene)
    for g in reversed(st.groups):
        if isinstance(g, Group):
            lids: tuple[int, ...] = (g.links[1], g.links[0])
        elif isinstance(g, TriadGroup):
            lids = tuple(reversed(g.links))
        else:
            continue
        for lid in lids:
            o = _on_frame(scene, lid)
            if o is not None:
                return o
    raise _fail(scene, field, Said("kx_slider_rocker_frame"))


# --------------------------------------------------------------------------- its motion


def probe_scene(scene: Scene) -> Scene:
    """The scene turning at |ω| = 1 (the velocities are the analogues: any ω, even 0)."""
    d = scene.driver
    return dataclasses.replace(scene, driver=dataclasses.replace(d, omega=float(d.sense), eps=0.0,
                                                                 phis_deg=(0.0,), placing=None))


def _coordinate(out: Output, kin: Any) -> tuple[Any, Any]:
    """The output's coordinate (along the guide, m; or its angle, rad) and its rate."""
    if out.kind == "slider":
        g = out.joint.guide
        assert g is not None
        r, v, _ = kin.point(out.point, out.link)
        u = g.direction
        return ((r - g.origin) * np.conj(u)).real, None if v is None else (v * np.conj(u)).real
    return np.unwrap(np.atleast_1d(kin.theta(out.link))), kin.omega(out.link) if kin.order >= 1 else None


def _rate(probe: Scene, out: Output, phi: float) -> float:
    from plans.kinematics.exact import solve

    return float(np.atleast_1d(_coordinate(out, solve(probe, [float(phi)], order=1))[1])[0])


def _bisect(probe: Scene, out: Output, lo: float, hi: float) -> float:
    """The crank angle in [lo, hi] where the output's rate changes sign, to the last bit."""
    f_lo = _rate(probe, out, lo)
    if f_lo == 0.0:
        return lo
    for _ in range(200):
        mid = 0.5 * (lo + hi)
        if mid in (lo, hi):
            break
        f = _rate(probe, out, mid)
        if f == 0.0:
            return mid
        if (f > 0) == (f_lo > 0):
            lo, f_lo = mid, f
        else:
            hi = mid
    # the end whose rate is the smaller: the root to the last bit of φ
    return lo if abs(f_lo) <= abs(_rate(probe, out, hi)) else hi


def strokes(scene: Scene, field: str = "driver.phi_start", *, closed: bool = True,
            output: Output | None = None) -> Strokes:
    """The extremes and strokes of the scene's output, or of ``output`` (computed once per scene)."""
    if closed and output is None and scene.driver.strokes is not None:
        return scene.driver.strokes
    key = ("strokes", closed, None if output is None else (output.link, output.point))
    kept = derived(scene)
    done = kept.get(key)
    if done is None:
        done = kept[key] = _strokes(scene, field, closed, output)
    return done


def slider(scene: Scene, point: str) -> Output | None:
    """The slider on a guide of the frame whose pin is ``point`` (None: no such slider)."""
    for j in scene.joints:
        if j.kind == "P" and j.guide is not None and j.guide.link == scene.frame and j.point == point:
            return Output("slider", j.slider, point, j)
    return None


def _strokes(scene: Scene, field: str, closed: bool, output: Output | None) -> Strokes:
    from plans.kinematics.exact import solve

    out = output or output_of(scene)
    probe = probe_scene(scene)
    grid = np.arange(GRID + 1) * (360.0 / GRID)
    try:
        kin = solve(probe, grid, order=1)
    except ConstructionError as exc:
        raise _fail(scene, field, Said("kx_extreme_positions_need", exc=exc)) from None
    c, v = _coordinate(out, kin)
    top, bottom = int(np.argmax(c[:-1])), int(np.argmin(c[:-1]))
    crank = scene.links[scene.driver.link]
    reach = abs(crank.points[crank.axis[1]] - crank.points[scene.driver.pivot]) if out.kind == "slider" else 1.0
    if c[top] - c[bottom] <= COINCIDE_REL * reach:  # a ram whose guide passes through its rocker's pivot
        raise _fail(scene, field, Said("kx_output_link_link", link=out.link))
    if out.kind == "rocker" and abs(c[-1] - c[0]) > math.pi:
        raise _fail(scene, field, Said("kx_link_link_turns", link=out.link))
    found = []
    used_closed = closed
    for k, sign in ((top, 1.0), (bottom, -1.0)):
        # the bracket: the rate changes sign from +sign to -sign between two grid samples near k
        lo, hi = grid[k] - 360.0 / GRID, grid[k] + 360.0 / GRID
        phi = _closed_form(scene, out, 0.5 * (lo + hi), lo, hi) if closed else None
        if phi is None:
            used_closed = False
            if _rate(probe, out, lo) * sign < 0 or _rate(probe, out, hi) * sign > 0:
                raise _fail(scene, field, Said("kx_output_link_link3", link=out.link, v=grid[k]))
            phi = _bisect(probe, out, lo, hi)
        found.append(_turn(phi))
    at_top, at_bottom = found
    up = float(np.mod(at_top - at_bottom, 360.0))  # crank degrees while the coordinate grows
    if abs(up - 180.0) > TIE_DEG:
        working_up = up > 180.0
    else:  # K = 1: the stroke from the extreme farther from the crank's pivot
        pivot = scene.frame_points[scene.driver.pivot]
        kin2 = solve(probe, [at_top, at_bottom], order=0)
        r = np.atleast_1d(kin2.point(out.point, out.link)[0])
        working_up = bool(abs(r[1] - pivot) >= abs(r[0] - pivot))
    start, other = (at_bottom, at_top) if working_up else (at_top, at_bottom)
    span = up if working_up else 360.0 - up
    if not 0.0 < span < 360.0:
        raise _fail(scene, field, Said("kx_output_link_link2", link=out.link))
    return Strokes(out, start, other, span, working_up, used_closed)


# --------------------------------------------------------------------------- closed forms


def _crank_angle(scene: Scene, A: complex) -> float:
    """φ (the driver's measure, degrees) that puts the crank pin at A."""
    d = scene.driver
    crank = scene.links[d.link]
    O = scene.frame_points[d.pivot]
    pin = crank.axis[1]
    local = crank.points[pin] - crank.points[d.pivot]
    theta = math.degrees(cmath.phase(A - O) - cmath.phase(local))
    return _turn(d.sense * (theta - math.degrees(d.phi_ref)))


def _closed_form(scene: Scene, out: Output, near: float, lo: float, hi: float) -> float | None:
    """The extreme in closed form when the output's group, a dyad, hangs on the crank; None
    otherwise (a triad's output is bisected; or when no candidate falls in the bracket the
    samples give)."""
    from plans.kinematics.structure import Group, analyse

    d = scene.driver
    O = scene.frame_points[d.pivot]
    crank = scene.links[d.link]
    pin = crank.axis[1]
    r = abs(crank.points[pin] - crank.points[d.pivot])
    group = next((g for g in analyse(scene).groups if out.link in getattr(g, "links", ())), None)
    if not isinstance(group, Group) or set(group.known) != {d.link, scene.frame} or len(group.joints) != 3:
        return None
    j1, j2, j3 = group.joints
    if j1.point != pin or j1.kind != "R":
        return None
    i, j = group.links
    cands: list[complex] = []  # crank pin positions
    if group.kind in ("RRP", "RRR") and out.link == j:
        lAB = abs(scene.links[i].points[j2.point] - scene.links[i].points[j1.point])
        for L, s in ((lAB + r, 1.0), (lAB - r, -1.0)):
            if L <= 0:
                continue
            for B in _on_slide_or_circle(scene, group.kind, j3, j, j2.point, O, L):
                if abs(B - O) > 0:
                    cands.append(O + s * r * (B - O) / abs(B - O))
    elif group.kind == "RPR" and out.link == j and j2.guide is not None and j3.kind == "R":
        C = scene.frame_points.get(j3.point)
        if C is None:
            return None
        zC = scene.links[j].points[j3.point]
        g = j2.guide
        e = ((zC - g.origin) * np.conj(g.direction)).imag  # the slot's offset from the pivot
        dist = abs(C - O)
        for s_e in (1.0, -1.0):
            c = (r + s_e * e) / dist if dist > 0 else 2.0
            if abs(c) > 1:
                continue
            for s in (1.0, -1.0):
                n = cmath.exp(1j * (cmath.phase(C - O) + s * math.acos(c)))
                cands.append(O + r * n)
    else:
        return None
    phis = [_crank_angle(scene, A) for A in cands]
    inside = [p for p in phis if _within(p, lo, hi)]
    # the two assembly branches meet their extremes at one crank angle: one root, however found
    if not inside or max(_gap(p, inside[0]) for p in inside) > SAME_ANGLE_DEG:
        return None
    return inside[0]


def _gap(a: float, b: float) -> float:
    d = abs(a - b) % 360.0
    return min(d, 360.0 - d)


def _turn(phi: float) -> float:
    """φ reduced to 0 <= φ < 360 (a root a hair below 0 is 0, not 360 rounded)."""
    x = float(np.mod(phi, 360.0))
    return 0.0 if x >= 360.0 else x


def _within(p: float, lo: float, hi: float) -> bool:
    d = float(np.mod(p - lo, 360.0))
    return d <= hi - lo


def _on_slide_or_circle(scene: Scene, kind: str, j3: Joint, j: int, point: str, O: complex, L: float) -> list[complex]:
    """Points B at distance L from O: on the slider's guide (RRP) or on the rocker's circle (RRR)."""
    if kind == "RRP":
        g = j3.guide
        if g is None or g.link != scene.frame:
            return []
        u, p0 = g.direction, g.origin
        b = ((p0 - O) * np.conj(u)).real
        c = abs(p0 - O) ** 2 - L * L
        disc = b * b - c
        if disc < 0:
            return []
        q = math.sqrt(disc)
        return [p0 + t * u for t in (-b + q, -b - q)]
    D = scene.frame_points.get(j3.point)
    if D is None or scene.frame not in j3.links:
        return []
    R = abs(scene.links[j].points[point] - scene.links[j].points[j3.point])
    dd = abs(D - O)
    if dd == 0:
        return []
    a = (L * L - R * R + dd * dd) / (2 * dd)
    h2 = L * L - a * a
    if h2 < 0:
        return []
    h = math.sqrt(h2)
    e = (D - O) / dd
    return [O + e * (a + 1j * s * h) for s in (1.0, -1.0)]


def start_scene(scene: Scene, request: FromExtreme) -> Scene:
    """``[driver] phi_start``: the scene's positions from the extreme asked for (read and
    validated with the file, :mod:`plans.scene.positions`)."""
    st = strokes(scene)
    phi0 = st.working_deg if request.start == "extreme" else st.idle_deg
    n = request.n
    phis = tuple(float(np.mod(phi0 + 360.0 * k / n, 360.0)) if k else phi0 for k in range(n))
    return dataclasses.replace(scene, driver=dataclasses.replace(scene.driver, phis_deg=phis, start=request.start,
                                                                 strokes=st, placing=None))
