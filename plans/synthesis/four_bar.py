"""The crank-rocker four-bar: from the rocker's swing ψ and K by the circle on which the chord
C′C″ subtends θ (the pivot chosen by the frame's length, its direction or the best γ_min),
and from three given positions by Freudenstein's equation."""

from __future__ import annotations

import cmath
import math
from typing import Any, NamedTuple

from plans.errors import Said

from .model import Task
from .numeric import golden
from .proof import FourBar
from .record import Design, fail
from .record import deg_text as _deg
from .record import mirror as _mirror


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
    # Grashof with the crank shortest: l1 + the longest < the other two
    longest = l0 if l0 > l2 else l2
    longest = longest if longest > l3 else l3
    if not (l1 < l0 and l1 < l2 and l1 < l3 and 2.0 * longest + l1 < l0 + l2 + l3):
        return None
    P1 = A - l1 * (C1 - A) / a
    P2 = A + l1 * (C2 - A) / b
    x1 = ((0 - P1).conjugate() * (C1 - P1)).imag
    x2 = ((0 - P2).conjugate() * (C2 - P2)).imag
    if x1 * x2 <= 0:
        return None
    travel = (cmath.phase((P2 - A) / (P1 - A))) % (2 * math.pi)
    flip = travel < math.pi - 1e-12 if theta > 1e-12 else False
    # γ at the crank along the frame line (the diagonal AD least and greatest), acute
    k = 2.0 * l2 * l3
    c_lo = (l2 * l2 + l3 * l3 - (l0 - l1) ** 2) / k
    c_hi = (l2 * l2 + l3 * l3 - (l0 + l1) ** 2) / k
    worst = max(abs(c_lo), abs(c_hi))  # the largest |cos γ| is the least acute γ
    return _Candidate(A, l1, l2, l0, math.acos(min(1.0, worst)), flip)


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
            raise fail(t, key, Said("s4_crank_rocker_what", what=what, v=_deg(psi), K=t.K))
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
            raise fail(t, "swing_deg", Said("s4_crank_rocker_gives", v=_deg(psi), K=t.K, v2=_deg(theta)))
        if t.gamma_min is not None and best[0].gamma < t.gamma_min:
            raise fail(t, "gamma_min_deg", Said("s4_min_cannot_met3", v=_deg(t.gamma_min), v2=_deg(psi), K=t.K, v3=_deg(best[0].gamma)))
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
        raise fail(t, "gamma_min_deg", Said("s4_missing_min_grows"))
    limit = math.pi / 2 - t.swing / 2
    if t.gamma_min >= limit:
        raise fail(t, "gamma_min_deg", Said("s4_min_cannot_met2", v=_deg(t.gamma_min), v2=_deg(t.swing), v3=_deg(limit)))
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
    raise fail(t, "gamma_min_deg", Said("s4_min_cannot_met", v=_deg(t.gamma_min)))


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
        raise fail(t, "positions", Said("s4_three_positions_do"))
    ks = []
    for j in range(3):
        m = [list(r[:3]) for r in rows]
        for i in range(3):
            m[i][j] = rows[i][3]
        ks.append(_det3(m) / det)
    K1, K2, K3 = ks
    if K1 <= 0 or K2 <= 0:
        raise fail(t, "positions", Said("s4_three_positions_give", K1=K1, K2=K2))
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
        raise fail(t, "positions", Said("s4_three_positions_give2"))
    b = math.sqrt(b2)
    ls = sorted((a, b, c, d))
    if not (a == ls[0] and a < ls[1] and ls[0] + ls[3] < ls[1] + ls[2]):
        raise fail(t, "positions", Said("s4_three_positions_give3", v=a / t.scale, v2=b / t.scale, v3=c / t.scale, v4=d / t.scale, unit=t.unit))
    D = complex(d, 0.0)
    sides = []
    for phi, psi in t.positions:
        A = a * cmath.exp(1j * phi)
        B = D + c * cmath.exp(1j * psi)
        sides.append(((D - A).conjugate() * (B - A)).imag)
    if not (all(x > 0 for x in sides) or all(x < 0 for x in sides)):
        raise fail(t, "positions", Said("s4_three_positions_lie"))
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
