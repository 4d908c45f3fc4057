"""The models: each sizes a mechanism from a :class:`~plans.synthesis.model.Task` by the
graphical construction a course draws (kept as data: the extreme positions C′, C″, the
circle on whose arc the chord C′C″ subtends θ, the chosen pivot), then hands the designed
mechanism to :mod:`plans.synthesis.proof` to be measured.

Frames: the scene's.  The crank's pivot O is the origin; a slider-crank's guide runs along
+x (an offset one at distance e on the side that makes the stroke away from O the slow
one); a four-bar's frame O→D lies along +x; a coulisse's pivot C is the origin with O
above it at the centre distance, the ram's guide horizontal.  A task with ``sense = "cw"``
is the mirror image of the counter-clockwise design.

Impossible tasks raise :class:`~plans.errors.InputError` naming the condition not met.
"""

from __future__ import annotations

import cmath
import math
from dataclasses import dataclass, field
from typing import Any, NamedTuple

from plans.errors import InputError

from .model import Task
from .numeric import golden
from .proof import Coulisse, FourBar, Measured, Slider, measure


@dataclass(frozen=True)
class Design:
    """A designed mechanism, its construction and its proof (SI, the scene's frame)."""

    task: Task
    model: str  # central, offset, crank_rocker, three_positions, coulisse, v_engine
    lengths: dict[str, float]  # name -> metres (the JSON's names)
    mechs: tuple[Any, ...]  # the proof's mechanisms (two sliders for a V-engine)
    working: str  # which stroke is the working one (see proof.measure)
    points: dict[str, complex]  # the construction's points: O, C1, C2, D, Oc, C, ...
    circle: tuple[complex, float] | None  # the construction's circle (centre, radius)
    choice: tuple[str, float] | None  # how a free choice was made (see CHOICES), None when none was left
    measured: tuple[Measured, ...] = ()
    notes: tuple[str, ...] = field(default=())

    @property
    def theta(self) -> float:
        return self.task.theta


#: The free choices a model makes, as said in English and in Russian ({} is an angle or λ).
CHOICES = {
    "least_pressure": ("the crank's pivot on the arc with the least maximum pressure angle ({})",
                       "ось кривошипа на дуге — при наименьшем наибольшем угле давления ({})"),
    "lambda_from_pressure": ("λ = sin[ϑ] = {}: the shortest rod within the permissible pressure angle",
                             "λ = sin[ϑ] = {}: самый короткий шатун при допускаемом угле давления"),
    "two_pivots": ("of the pivots the condition leaves, the one with the best γmin ({})",
                   "из допустимых положений оси — с наибольшим γmin ({})"),
    "shortest_frame": ("the shortest frame with γmin >= [γ] (γmin grows toward {} as the frame lengthens)",
                       "самая короткая стойка с γmin >= [γ] (γmin растёт к {} с длиной стойки)"),
    "best_gamma": ("the crank's pivot on the arc with the best γmin ({})",
                   "ось кривошипа на дуге — при наибольшем γmin ({})"),
    "mid_sagitta": ("the ram's guide through the middle of the sagitta of D's arc (pressure angle {})",
                    "направляющая ползуна — через середину стрелки дуги точки D (угол давления {})"),
}


def choice_text(choice: tuple[str, float] | None, lang: str = "en") -> str:
    """The sentence saying how the free choice was made ("" when there was none)."""
    if choice is None:
        return ""
    key, v = choice
    shown = f"{v:.6g}" if key == "lambda_from_pressure" else f"{math.degrees(v):.6g}°"
    if lang == "ru":
        shown = shown.replace(".", ",")
    return CHOICES[key][1 if lang == "ru" else 0].format(shown)


def fail(t: Task, key: str, message: str) -> InputError:
    return InputError(message, file=t.path, field=key)


def _mirror(z: complex, sense: int) -> complex:
    return z if sense > 0 else z.conjugate()


def _deg(x: float) -> str:
    return f"{math.degrees(x):.6g}°"


# --------------------------------------------------------------------------- slider-crank


def stroke_of(t: Task) -> float:
    """H, given or from the mean speed: v_m = 2H·n/60."""
    if t.stroke is not None:
        return t.stroke
    assert t.mean_speed is not None and t.omega_rpm is not None
    return t.mean_speed * 30.0 / t.omega_rpm


def slider_crank(t: Task) -> Design:
    H = stroke_of(t)
    theta = t.theta
    if theta <= 0.0:
        return _central(t, H)
    if theta >= math.pi / 2:
        raise fail(t, "K", f"K = {t.K:g} gives θ = {_deg(theta)}; an offset slider-crank has θ < 90° "
                           "(expected K < 3)")
    # the chord C′C″ = H on the guide, C′ at 0; the circle on which it subtends θ
    hc = H / (2.0 * math.tan(theta))
    R = H / (2.0 * math.sin(theta))
    Oc = complex(H / 2.0, hc)
    t_top = math.atan2(hc, -H / 2.0)  # the pivot right above C′ (AC′ ⟂ guide: a locked limit)
    t_low = math.atan2(-hc, -H / 2.0) + 2.0 * math.pi  # the pivot at C′ itself
    choice = None
    if t.offset is not None:
        e = t.offset
        if not 0.0 < e < 2.0 * hc:
            raise fail(t, "offset", f"the offset e = {e / t.scale:.6g} {t.unit} cannot give K = {t.K:g}: "
                                    f"expected 0 < e < H/tan θ = {2 * hc / t.scale:.6g} {t.unit}")
        A = complex(Oc.real - math.sqrt(max(R * R - (e - hc) ** 2, 0.0)), e)
    elif t.lam is not None:
        lam = t.lam
        low = math.tan(theta / 2.0) ** 2
        if lam <= low:
            raise fail(t, "lambda", f"λ = {lam:g} is too small for K = {t.K:g}: the crank's pivot would leave "
                                    f"the arc; expected λ > tan²(θ/2) = {low:.6g}")
        # Apollonius' circle of the points with AC″/AC′ = (1 + λ)/(1 − λ), met with the arc
        k = (1.0 + lam) / (1.0 - lam)
        c2 = complex(H, 0.0)
        ac = (c2 - k * k * 0.0) / (1.0 - k * k)
        ar = k * H / abs(1.0 - k * k)
        A = _meet(Oc, R, ac, ar, upper=True)
    else:
        def worst(tp: float) -> float:
            A = Oc + R * cmath.exp(1j * tp)
            a, b = abs(A), abs(A - H)
            return ((b - a) / 2.0 + A.imag) / ((b + a) / 2.0)

        tp, s = golden(worst, t_top, t_low)
        A = Oc + R * cmath.exp(1j * tp)
        best = math.asin(min(s, 1.0))
        if t.pressure_angle_max is not None and best > t.pressure_angle_max:
            raise fail(t, "pressure_angle_max_deg",
                       f"no crank pivot on the arc keeps the pressure angle within [ϑ] = "
                       f"{_deg(t.pressure_angle_max)} for K = {t.K:g}: the best is {_deg(best)}")
        choice = ("least_pressure", best)
    a, b = abs(A), abs(A - H)
    l1, l2, e = (b - a) / 2.0, (b + a) / 2.0, A.imag
    # to the scene's frame: O at the origin, the guide at y = −e (mirrored for cw)
    s = t.sense
    pts = {"O": 0j, "C1": _mirror(-A, s), "C2": _mirror(H - A, s), "Oc": _mirror(Oc - A, s)}
    mech = Slider(0j, l1, l2, _mirror(complex(0.0, -e), s), 1 + 0j)
    return Design(t, "offset", {"crank": l1, "rod": l2, "offset": e}, (mech,), "away", pts,
                  (pts["Oc"], R), choice)


def _meet(c1: complex, r1: float, c2: complex, r2: float, upper: bool) -> complex:
    """The meeting point of two circles left of the chord's start (x < 0), above it."""
    d = c2 - c1
    D = abs(d)
    a = (r1 * r1 - r2 * r2 + D * D) / (2.0 * D)
    h = math.sqrt(max(r1 * r1 - a * a, 0.0))
    base = c1 + a * d / D
    cands = [base + h * 1j * d / D, base - h * 1j * d / D]
    cands = [z for z in cands if (z.imag > 0) == upper]
    return min(cands, key=lambda z: z.real)


def _central(t: Task, H: float) -> Design:
    if t.offset:
        raise fail(t, "offset", "K = 1 has no offset: an offset slider-crank has θ > 0 (give K > 1, "
                                "or offset = 0)")
    r = H / 2.0
    if t.lam is not None:
        lam = t.lam
        choice = None
    elif t.pressure_angle_max is not None:
        lam = math.sin(t.pressure_angle_max)
        choice = ("lambda_from_pressure", lam)
    else:
        raise fail(t, "lambda", "missing; a central slider-crank needs λ = l1/l2 (or "
                                "pressure_angle_max_deg)")
    l = r / lam
    s = t.sense
    pts = {"O": 0j, "C1": complex(l - r, 0.0), "C2": complex(l + r, 0.0)}
    mech = Slider(0j, r, l, 0j, 1 + 0j)
    del s
    return Design(t, "central", {"crank": r, "rod": l, "offset": 0.0}, (mech,), "away", pts, None, choice)


def v_engine(t: Task) -> Design:
    H = stroke_of(t)
    assert t.lam is not None and t.bank is not None
    r = H / 2.0
    l = r / t.lam
    half = t.bank / 2.0
    uB = cmath.exp(1j * (math.pi / 2 - half))
    uC = cmath.exp(1j * (math.pi / 2 + half))
    mechs = (Slider(0j, r, l, 0j, uB), Slider(0j, r, l, 0j, uC))
    pts = {"O": 0j, "B1": (l - r) * uB, "B2": (l + r) * uB, "C1": (l - r) * uC, "C2": (l + r) * uC}
    return Design(t, "v_engine", {"crank": r, "rod": l}, mechs, "away", pts, None, None)


# --------------------------------------------------------------------------- crank-rocker


class _Candidate(NamedTuple):
    A: complex  # the crank's pivot in the construction's frame (D at 0)
    l1: float
    l2: float
    l0: float
    gamma: float  # γ_min, closed form (for choosing; the proof measures it again)
    flip: bool  # the counter-clockwise crank needs the mirror image for K >= 1


def _candidate(A: complex, C1: complex, C2: complex, l3: float, theta: float) -> _Candidate | None:
    """The four-bar whose crank pivot is A, with the rocker's extremes C1 (crank and coupler
    folded) and C2 (stretched); None when it is not a crank-rocker on one branch."""
    a, b = abs(A - C1), abs(A - C2)
    if not a < b or a <= 0:
        return None
    if abs(abs(cmath.phase((C2 - A) / (C1 - A))) - theta) > 1e-7:
        return None  # the circle's other arc: there the chord subtends 180° − θ
    l1, l2, l0 = (b - a) / 2.0, (b + a) / 2.0, abs(A)
    ls = sorted((l0, l1, l2, l3))
    if not (l1 == ls[0] and l1 < ls[1] and ls[0] + ls[3] < ls[1] + ls[2]):
        return None
    P1 = A - l1 * (C1 - A) / a
    P2 = A + l1 * (C2 - A) / b
    x1 = ((0 - P1).conjugate() * (C1 - P1)).imag
    x2 = ((0 - P2).conjugate() * (C2 - P2)).imag
    if x1 * x2 <= 0:
        return None
    travel = (cmath.phase((P2 - A) / (P1 - A))) % (2 * math.pi)
    flip = travel < math.pi - 1e-12 if theta > 1e-12 else False
    lo, hi = abs(l0 - l1), l0 + l1
    g = []
    for d in (lo, hi):
        c = (l2 * l2 + l3 * l3 - d * d) / (2 * l2 * l3)
        x = math.acos(max(-1.0, min(1.0, c)))
        g.append(min(x, math.pi - x))
    return _Candidate(A, l1, l2, l0, min(g), flip)


def crank_rocker(t: Task) -> Design:
    if t.positions is not None:
        return three_positions(t)
    assert t.rocker is not None and t.swing is not None
    l3, psi, theta = t.rocker, t.swing, t.theta
    C1 = l3 * cmath.exp(1j * (math.pi / 2 + psi / 2))
    C2 = l3 * cmath.exp(1j * (math.pi / 2 - psi / 2))
    c = l3 * math.sin(psi / 2)
    y0 = l3 * math.cos(psi / 2)
    families: list[tuple[Any, float, float, Any]] = []  # (point at parameter p, lo, hi, circle)
    if theta > 1e-12:
        R = c / math.sin(theta)
        for sgn in (-1.0, 1.0):
            Oc = complex(0.0, y0 + sgn * c / math.tan(theta))
            families.append((lambda p, Oc=Oc, R=R: Oc + R * cmath.exp(1j * p), 0.0, 2 * math.pi, (Oc, R)))
    else:  # K = 1: the "circle" is the line C′C″ itself, the pivot beyond C′
        u = (C1 - C2) / abs(C1 - C2)
        families.append((lambda p, u=u: C1 + u * l3 * math.exp(p), math.log(1e-3), math.log(1e3), None))

    def cand(A: complex) -> _Candidate | None:
        return _candidate(A, C1, C2, l3, theta)

    picked: list[tuple[_Candidate, Any]] = []
    choice: tuple[str, float] | None = None
    if t.frame is not None or t.frame_angle is not None:
        for f, lo, hi, circ in families:
            for A in _family_meets(f, lo, hi, circ, t):
                k = cand(A)
                if k is not None:
                    picked.append((k, circ))
        key = "frame" if t.frame is not None else "frame_angle_deg"
        if not picked:
            what = (f"frame = {t.frame / t.scale:.6g} {t.unit}" if t.frame is not None  # type: ignore[operator]
                    else f"frame_angle_deg = {math.degrees(t.frame_angle):.6g}")  # type: ignore[arg-type]
            raise fail(t, key, f"no crank-rocker with {what} gives the swing {_deg(psi)} at K = {t.K:g}: "
                               "the pivot's line misses the arc where the crank turns fully on one branch")
        if len(picked) > 1:
            choice = ("two_pivots", max(k.gamma for k, _ in picked))
    elif theta <= 1e-12:
        picked = [_k1_pick(t, families[0][0], cand)]
        choice = ("shortest_frame", math.pi / 2 - psi / 2)
    else:
        best: tuple[_Candidate, Any] | None = None
        peaks = []  # (γ, family, grid index): the grid's local maxima of γ_min
        grids = []
        for j, (f, lo, hi, _circ) in enumerate(families):
            n = 48
            ps = [lo + (hi - lo) * (i + 0.5) / n for i in range(n)]
            ks = [cand(f(p)) for p in ps]
            grids.append((ps, ks))
            for i, k in enumerate(ks):
                if k is None:
                    continue
                left = ks[i - 1] if i > 0 else None
                right = ks[i + 1] if i + 1 < n else None
                if (left is None or left.gamma <= k.gamma) and (right is None or right.gamma <= k.gamma):
                    peaks.append((k.gamma, j, i))
        for _g, j, i in sorted(peaks, reverse=True)[:2]:  # the two best refined
            f, circ = families[j][0], families[j][3]
            ps, ks = grids[j]
            k = ks[i]
            assert k is not None
            a = ps[i - 1] if i > 0 and ks[i - 1] is not None else ps[i]
            b = ps[i + 1] if i + 1 < len(ps) and ks[i + 1] is not None else ps[i]

            def neg(p: float, f=f) -> float:
                kk = cand(f(p))
                return -kk.gamma if kk is not None else 1.0

            p, _ = golden(neg, a, b, xtol=1e-7) if b > a else (ps[i], 0.0)
            kk = cand(f(p))
            if kk is None or kk.gamma < k.gamma:
                kk = k
            if best is None or kk.gamma > best[0].gamma:
                best = (kk, circ)
        if best is None:
            raise fail(t, "swing_deg", f"no crank-rocker gives the swing {_deg(psi)} at K = {t.K:g} "
                                       f"(θ = {_deg(theta)}): the arc has no pivot where the crank turns "
                                       "fully on one branch")
        if t.gamma_min is not None and best[0].gamma < t.gamma_min:
            raise fail(t, "gamma_min_deg", f"γ_min >= [γ] = {_deg(t.gamma_min)} cannot be met for the swing "
                                           f"{_deg(psi)} at K = {t.K:g}: the best pivot gives {_deg(best[0].gamma)}")
        picked = [best]
        choice = ("best_gamma", best[0].gamma)
    k, circ = max(picked, key=lambda kc: kc[0].gamma)
    return _four_bar_design(t, "crank_rocker", k.A, k.l1, k.l2, l3, k.flip,
                            {"C1": C1, "C2": C2, **({"Oc": circ[0]} if circ else {})},
                            None if circ is None else circ[1], choice)


def _k1_pick(t: Task, f, cand) -> tuple[_Candidate, Any]:
    """K = 1: the pivot on the line C″C′ beyond C′; γ_min rises toward 90° − ψ/2 as it goes
    away, so [γ] picks the nearest pivot that meets it."""
    from .numeric import brent

    assert t.swing is not None
    if t.gamma_min is None:
        raise fail(t, "gamma_min_deg", "missing; at K = 1 γ_min grows as the frame lengthens without bound: give "
                                       "frame, frame_angle_deg or gamma_min_deg")
    limit = math.pi / 2 - t.swing / 2
    if t.gamma_min >= limit:
        raise fail(t, "gamma_min_deg", f"γ_min >= [γ] = {_deg(t.gamma_min)} cannot be met at K = 1 for the "
                                       f"swing {_deg(t.swing)}: γ_min stays below 90° − ψ/2 = {_deg(limit)}")
    lo, hi = math.log(1e-3), math.log(1e6)
    n = 200
    prev = None
    for i in range(n + 1):
        p = lo + (hi - lo) * i / n
        k = cand(f(p))
        if k is not None and k.gamma >= t.gamma_min:
            if prev is None:
                return k, None

            def g(q: float) -> float:
                kk = cand(f(q))
                return (kk.gamma if kk is not None else 0.0) - t.gamma_min  # type: ignore[operator]

            q = brent(g, prev, p, g(prev), g(p))
            kk = cand(f(q))
            return (kk if kk is not None and kk.gamma >= t.gamma_min - 1e-12 else k), None
        prev = p
    raise fail(t, "gamma_min_deg", f"γ_min >= [γ] = {_deg(t.gamma_min)} cannot be met at K = 1")


def _family_meets(f, lo: float, hi: float, circ: Any, t: Task) -> list[complex]:
    """Where the frame's condition meets a family of pivots (D at 0)."""
    if t.frame is not None:
        target = t.frame

        def g(p: float) -> float:
            return abs(f(p)) - target
    else:
        assert t.frame_angle is not None
        direction = cmath.exp(1j * (math.pi / 2 + t.frame_angle))

        def g(p: float) -> float:
            z = f(p) * direction.conjugate()
            return z.imag if z.real > 0 else (1.0 if z.imag >= 0 else -1.0) * (abs(z) + 1.0)
    from .numeric import brent

    n = 720
    ps = [lo + (hi - lo) * i / n for i in range(n + 1)]
    ys = [g(p) for p in ps]
    out = []
    for i in range(n):
        if ys[i] == 0.0:
            out.append(f(ps[i]))
        elif (ys[i] > 0) != (ys[i + 1] > 0) and ys[i + 1] != 0.0:
            p = brent(g, ps[i], ps[i + 1], ys[i], ys[i + 1])
            z = f(p)
            if t.frame is None and (z * cmath.exp(-1j * (math.pi / 2 + t.frame_angle))).real <= 0:  # type: ignore[operator]
                continue  # the jump across the ray's back, not a crossing
            out.append(z)
    return out


def _four_bar_design(t: Task, model: str, A: complex, l1: float, l2: float, l3: float, flip: bool,
                     extra: dict[str, complex], R: float | None, choice: tuple[str, float] | None) -> Design:
    """To the scene's frame: O at the origin, D on +x; mirrored for K's sense."""
    d = -A
    rot = abs(d) / d  # turns O→D onto +x

    def to(z: complex) -> complex:
        w = (z - A) * rot
        w = w.conjugate() if flip else w
        return _mirror(w, t.sense)

    D = complex(abs(A), 0.0)  # on +x exactly
    pts = {"O": 0j, "D": D, **{k: to(v) for k, v in extra.items()}}
    C1 = pts["C1"]
    P1 = -l1 * C1 / abs(C1)
    branch = 1 if ((D - P1).conjugate() * (C1 - P1)).imag > 0 else -1
    mech = FourBar(0j, D, l1, l2, l3, branch)
    circle = (pts["Oc"], R) if "Oc" in pts and R is not None else None
    return Design(t, model, {"crank": l1, "coupler": l2, "rocker": l3, "frame": D.real}, (mech,), "away",
                  pts, circle, choice)


def three_positions(t: Task) -> Design:
    """Freudenstein: K1·cos ψ − K2·cos φ + K3 = cos(φ − ψ), K1 = d/a, K2 = d/c,
    K3 = (a² − b² + c² + d²)/(2ac); φ and ψ from the frame line O→D."""
    assert t.positions is not None
    rows = [(math.cos(psi), -math.cos(phi), 1.0, math.cos(phi - psi)) for phi, psi in t.positions]
    det = _det3([r[:3] for r in rows])
    scale = max(1.0, *(abs(x) for r in rows for x in r[:3]))
    if abs(det) < 1e-9 * scale ** 3:
        raise fail(t, "positions", "the three positions do not fix a four-bar (Freudenstein's equations "
                                   "are dependent); expected three different crank and rocker angles")
    ks = []
    for j in range(3):
        m = [list(r[:3]) for r in rows]
        for i in range(3):
            m[i][j] = rows[i][3]
        ks.append(_det3(m) / det)
    K1, K2, K3 = ks
    if K1 <= 0 or K2 <= 0:
        raise fail(t, "positions", f"the three positions give a negative link (K1 = {K1:.6g}, K2 = {K2:.6g}); "
                                   "expected angles of a crank-rocker measured from the frame line O→D")
    if t.rocker is not None:
        c = t.rocker
        d = K2 * c
    else:
        assert t.frame is not None
        d = t.frame
        c = d / K2
    a = d / K1
    b2 = a * a + c * c + d * d - 2 * a * c * K3
    if b2 <= 0:
        raise fail(t, "positions", "the three positions give no coupler (b² <= 0)")
    b = math.sqrt(b2)
    ls = sorted((a, b, c, d))
    if not (a == ls[0] and a < ls[1] and ls[0] + ls[3] < ls[1] + ls[2]):
        raise fail(t, "positions", f"the three positions give a four-bar that is not a crank-rocker "
                                   f"(crank {a / t.scale:.6g}, coupler {b / t.scale:.6g}, rocker "
                                   f"{c / t.scale:.6g}, frame {d / t.scale:.6g} {t.unit}: Grashof's "
                                   "shortest + longest < the other two, with the crank shortest)")
    D = complex(d, 0.0)
    sides = []
    for phi, psi in t.positions:
        A = a * cmath.exp(1j * phi)
        B = D + c * cmath.exp(1j * psi)
        sides.append(((D - A).conjugate() * (B - A)).imag)
    if not (all(x > 0 for x in sides) or all(x < 0 for x in sides)):
        raise fail(t, "positions", "the three positions lie on both assembly branches of the coupler and "
                                   "rocker; expected positions of one assembly")
    branch = 1 if sides[0] > 0 else -1
    pts = {"O": 0j, "D": D}
    for i, (phi, psi) in enumerate(t.positions):
        pts[f"A{i + 1}"] = a * cmath.exp(1j * phi)
        pts[f"B{i + 1}"] = D + c * cmath.exp(1j * psi)
    mech = FourBar(0j, D, a, b, c, branch)
    return Design(t, "three_positions", {"crank": a, "coupler": b, "rocker": c, "frame": d}, (mech,), "away",
                  pts, None, None)


def _det3(m: list) -> float:
    return (m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1]) - m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0])
            + m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0]))


# --------------------------------------------------------------------------- coulisse


def coulisse(t: Task) -> Design:
    """l1 = l0·sin(θ/2) (the coulisse swings by ψ = θ, tangent to the crank circle at its
    extremes), CD = H/(2 sin(θ/2)), the ram's guide through the middle of the sagitta of D's
    arc, the rod DE from [ϑ]: sin ϑ_max = (f/2)/DE."""
    assert t.stroke is not None and t.centre_distance is not None
    H, l0, theta = t.stroke, t.centre_distance, t.theta
    half = theta / 2.0
    if math.sin(half) > 1.0 - 1e-9:
        raise fail(t, "K", f"K = {t.K:g} puts the crank's circle through the coulisse's pivot (θ = {_deg(theta)}); "
                           "expected a smaller K")
    l1 = l0 * math.sin(half)
    l3 = H / (2.0 * math.sin(half))
    if l3 < l0 + l1:
        raise fail(t, "stroke", f"the coulisse CD = H/(2 sin(θ/2)) = {l3 / t.scale:.6g} {t.unit} is shorter than "
                                f"the block's reach l0 + l1 = {(l0 + l1) / t.scale:.6g} {t.unit}; expected a "
                                "larger stroke or a smaller centre distance")
    low = l3 * math.cos(half)  # D's height at the extremes
    sag = l3 - low
    choice = None
    if t.ram_group == "RPP":
        return _coulisse_rpp(t, l0, l1, l3, half, low)
    if t.guide_height is not None:
        h = t.guide_height
        dev = max(l3 - h, h - low)
    else:
        h = (l3 + low) / 2.0
        dev = sag / 2.0
        choice = ("mid_sagitta", math.asin(dev / t.rod) if t.rod is not None else t.pressure_angle_max or 0.0)
    if t.rod is not None:
        l4 = t.rod
        if l4 <= dev:
            raise fail(t, "rod", f"the rod DE = {l4 / t.scale:.6g} {t.unit} cannot reach the ram's guide from every "
                                 f"position of D (it strays {dev / t.scale:.6g} {t.unit} from the guide)")
        if t.pressure_angle_max is not None and math.asin(dev / l4) > t.pressure_angle_max:
            raise fail(t, "pressure_angle_max_deg", f"the rod DE = {l4 / t.scale:.6g} {t.unit} gives the ram a "
                                                    f"pressure angle {_deg(math.asin(dev / l4))} > [ϑ]")
    else:
        assert t.pressure_angle_max is not None
        l4 = dev / math.sin(t.pressure_angle_max) if dev > 0 else l3 / 4.0
    C = complex(0.0, -l0)  # the scene's frame has O at the origin
    pts = {"O": 0j, "C": C, "D1": C + l3 * cmath.exp(1j * (math.pi / 2 + half)),
           "D2": C + l3 * cmath.exp(1j * (math.pi / 2 - half)),
           "A1": l1 * cmath.exp(1j * (math.pi + half)), "A2": l1 * cmath.exp(-1j * half)}
    mech = Coulisse(0j, C, l1, l3, l4, complex(0.0, h - l0), 1 + 0j)
    return Design(t, "coulisse", {"crank": l1, "centre_distance": l0, "coulisse": l3, "rod": l4,
                                  "guide_height": h}, (mech,), "+" if t.sense < 0 else "-", pts, None, choice)


def _coulisse_rpp(t: Task, l0: float, l1: float, l3: float, half: float, low: float) -> Design:
    """The RPP ram: a block at D slides in the ram's slot ⟂ its guide, so the ram follows D's
    x; the force on the coulisse is along the guide, D's velocity ⟂ CD: the pressure angle is
    the coulisse's tilt, θ/2 at the extremes, whatever the guide's height."""
    if t.pressure_angle_max is not None and half > t.pressure_angle_max:
        raise fail(t, "pressure_angle_max_deg", f"an RPP ram's pressure angle reaches θ/2 = {_deg(half)} > [ϑ] = "
                                                f"{_deg(t.pressure_angle_max)}; expected a smaller K or the RRP ram")
    h = t.guide_height if t.guide_height is not None else (l3 + low) / 2.0
    C = complex(0.0, -l0)
    pts = {"O": 0j, "C": C, "D1": C + l3 * cmath.exp(1j * (math.pi / 2 + half)),
           "D2": C + l3 * cmath.exp(1j * (math.pi / 2 - half)),
           "A1": l1 * cmath.exp(1j * (math.pi + half)), "A2": l1 * cmath.exp(-1j * half)}
    mech = Coulisse(0j, C, l1, l3, 0.0, complex(0.0, h - l0), 1 + 0j)
    return Design(t, "coulisse", {"crank": l1, "centre_distance": l0, "coulisse": l3, "guide_height": h},
                  (mech,), "+" if t.sense < 0 else "-", pts, None, None)


# --------------------------------------------------------------------------- all


MODELS = {"slider_crank": slider_crank, "crank_rocker": crank_rocker, "coulisse": coulisse, "v_engine": v_engine}


def _met(t: Task, d: Design, measured: tuple[Measured, ...]) -> None:
    """The task's K, stroke and swing as the designed mechanism measures them (to 1e-7: the
    proof finds them to 1e-12 and better; a miss is a task the model cannot meet)."""
    for m in measured:
        if not m.full_rotation:
            continue
        if d.model != "three_positions" and abs(m.K - t.K) > 1e-7 * t.K:
            raise fail(t, "K", f"the designed mechanism gives K = {m.K:.9g}, not {t.K:g}; the task has no "
                               f"{t.mechanism.replace('_', '-')} with this K")
        if t.mechanism == "crank_rocker" and d.model != "three_positions" and t.swing is not None \
                and m.swing is not None and abs(m.swing - t.swing) > 1e-7:
            raise fail(t, "swing_deg", f"the designed mechanism swings {_deg(m.swing)}, not {_deg(t.swing)}")
        if m.stroke is not None and t.mechanism != "crank_rocker":
            H = stroke_of(t)
            if abs(m.stroke - H) > 1e-7 * H:
                raise fail(t, "stroke", f"the designed mechanism's stroke is {m.stroke / t.scale:.9g} {t.unit}, "
                                        f"not {H / t.scale:g}")


def design(t: Task) -> Design:
    """Size the mechanism and prove it: the measured K, stroke or swing, γ_min; a design that
    does not turn fully on one branch is refused (it never is, when the model is right)."""
    d = MODELS[t.mechanism](t)
    sense = t.sense
    measured = tuple(measure(m, sense, d.working) for m in d.mechs)
    _met(t, d, measured)
    for m in measured:
        if not m.full_rotation:
            raise InputError(f"the designed mechanism does not turn fully on one assembly branch (assembly "
                             f"margin {m.margin:.3g} m, {m.extremes} extreme positions); the task has no "
                             "crank mechanism", file=t.path, field="mechanism")
    return Design(d.task, d.model, d.lengths, d.mechs, d.working, d.points, d.circle, d.choice, measured,
                  d.notes)
