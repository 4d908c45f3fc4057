"""The exact analysis of a class-III group (triad) inside the mechanism: its place by
:func:`plans.kinematics.triad.place`, its rates by :func:`plans.kinematics.triad.rates`.

The place has no closed form, so the branch is kept by continuation: the group is assembled
once at φ = 0 (of all its assemblies there, the first with the base's pair D on the side
``branch`` of the line AB: +1 left, −1 right, the base's angle breaking ties) and carried
round the crank's turn in 1° steps; each asked-for angle starts its Newton solve from the
nearest step.  The steps are worked out once per scene.
"""

from __future__ import annotations

import cmath
import math
from collections.abc import Callable
from dataclasses import replace
from typing import Any

import numpy as np

from plans.errors import Locked, NotAssemblable, Said
from plans.kinematics.context import Context, Motion, place_link, point_at
from plans.kinematics.structure import Structure, TriadGroup, analyse
from plans.kinematics.triad import SpecialPosition, Triad, determinant, place, rates, special_kind
from plans.records import derived
from plans.scene.model import Scene

STEP_DEG = 1.0


def constants(scene: Scene, g: TriadGroup) -> tuple:
    """The group's triad (base frame: the base link's own, origin moved to D), the local
    coordinates of A, B, C on their links and of the leashes' ends."""
    base = scene.links[g.links[0]]

    def on_base(i: Any) -> complex:  # an inner pair on the base, or the origin of its slot
        return i.guide.origin if i.kind == "P" else base.points[i.point]
    (oA, iD), (oB, iE), (oC, iF) = g.joints
    zD = on_base(iD)
    lengths: list[float] = []
    guides: list[complex | None] = []
    slots: list[complex | None] = []
    outer = []
    for k, p, (o, i) in zip(g.links[1:], g.known, g.joints, strict=True):
        leash = scene.links[k]
        if o.kind == "P":  # a slider on a guide of the frame: the guide's origin, its direction
            assert o.guide is not None
            lengths.append(0.0)
            guides.append(o.guide.direction)
            slots.append(None)
            outer.append((p, o.guide.origin))
            continue
        guides.append(None)
        outer.append((p, _local(scene, p, o.point)))
        if i.kind == "P":  # a block in a slot of the base: the slot's direction on the base
            assert i.guide is not None
            lengths.append(0.0)
            slots.append(i.guide.direction)
            continue
        lengths.append(abs(leash.points[i.point] - leash.points[o.point]))
        slots.append(None)
    t = Triad(on_base(iE) - zD, on_base(iF) - zD, lengths[0], lengths[1], lengths[2],
              name=f"{g.kind} {g.name}", guides=(guides[0], guides[1], guides[2]), slots=(slots[0], slots[1], slots[2]))
    return t, zD, tuple(outer)


def _local(scene: Scene, link: int, name: str) -> complex:
    return scene.frame_points[name] if link == scene.frame else scene.links[link].points[name]


def _phase(phi: float) -> float:
    return phi % 360.0


def _track(solve: Callable[..., Any], scene: Scene, st: Structure, g: TriadGroup, t: Triad, outer_of) -> tuple[np.ndarray, list]:
    """(step angles, (r_D, θ) at each) over one turn from φ = 0, computed once per scene."""
    key = ("triad", g.name)
    kept = derived(scene)
    done = kept.get(key)
    if done is not None:
        return done
    before = replace(st, groups=st.groups[:st.groups.index(g)])
    grid = np.arange(0.0, 360.0 + STEP_DEG / 2, STEP_DEG)
    kin = solve(scene, grid, order=0, structure=before)
    outs = [kin.point_on(p, z)[0] for p, z in outer_of]
    state = _assemble(t, (complex(outs[0][0]), complex(outs[1][0]), complex(outs[2][0])), g)
    states = []
    sense = 0.0  # the sign of the leash equations' determinant along the branch
    for k, phi in enumerate(grid.tolist()):
        outer = (complex(outs[0][k]), complex(outs[1][k]), complex(outs[2][k]))
        try:
            new = place(t, outer, state)
        except SpecialPosition as exc:
            if k:  # the group may have run into its special position between two steps
                _special_between(solve, scene, before, g, t, outer_of, float(grid[k - 1]), phi, state, sense)
            raise NotAssemblable(exc.said, group=t.name, point=g.point, phi_deg=phi) from None
        d = determinant(t, outer, *new)
        if k and d * sense < 0:  # Newton landed on the other branch: a special position was passed
            _special_between(solve, scene, before, g, t, outer_of, float(grid[k - 1]), phi, state, sense)
            raise NotAssemblable(Said("te_group_leaves_its"),
                                 group=t.name, point=g.point, phi_deg=phi)
        state, sense = new, d
        states.append(state)
    done = kept[key] = (grid, states)
    return done


def _special_between(solve: Callable[..., Any], scene: Scene, before: Structure, g: TriadGroup, t: Triad, outer_of,
                     lo: float, hi: float, state: tuple[complex, float], sense: float = 0.0) -> None:
    """Where the group cannot be carried from ``lo`` to ``hi``: bisect to the last angle it
    reaches; if its leashes' axes pass through one point there (or are parallel), that is
    the group's special position (a dead position of the triad): say so, with the angle."""
    def outer_at(phi: float) -> tuple[complex, complex, complex]:
        kin = solve(scene, [phi], order=0, structure=before)
        got = [complex(np.atleast_1d(kin.point_on(p, z)[0])[0]) for p, z in outer_of]
        return got[0], got[1], got[2]

    for _ in range(40):  # the last angle reached on the same branch (its determinant's sign kept)
        mid = 0.5 * (lo + hi)
        try:
            new = place(t, outer_at(mid), state)
        except SpecialPosition:
            hi = mid
            continue
        if determinant(t, outer_at(mid), *new) * sense < 0:
            hi = mid
        else:
            state, lo = new, mid
    kind = special_kind(t, outer_at(lo), *state)
    if kind is not None:
        raise Locked(kind, group=t.name, point=g.point, phi_deg=round(lo, 3))


def _assemble(t: Triad, outer: tuple[complex, complex, complex], g: TriadGroup) -> tuple[complex, float]:
    """The group's assembly at φ = 0 chosen by its branch, from Newton solves started all round."""
    A, B = outer[0], outer[1]
    found: list[tuple[complex, float]] = []
    for a in range(12):
        for b in range(12):
            guess = (A + t.l1 * cmath.exp(1j * math.pi * a / 6), math.pi * b / 6)
            try:
                rD, th = place(t, outer, guess)
            except SpecialPosition:
                continue
            th = math.remainder(th, 2 * math.pi)
            if all(abs(rD - r) > 1e-7 * t.size or abs(math.remainder(th - h, 2 * math.pi)) > 1e-7 for r, h in found):
                found.append((rD, th))
    if not found:
        raise NotAssemblable(Said("te_leashes_cannot_reach"), group=t.name, point=g.point, phi_deg=0.0)
    side = [s for s in found if ((B - A).conjugate() * (s[0] - A)).imag * g.branch > 0] or found
    return min(side, key=lambda s: (round(s[1], 9), s[0].real, s[0].imag))


def solve_group(ctx: Context, g: TriadGroup, k: tuple) -> None:
    t, zD, outer_of = k
    st = analyse(ctx.scene)
    grid, states = _track(ctx.solve, ctx.scene, st, g, t, outer_of)
    got = [point_at(ctx, p, z) for p, z in outer_of]
    scalar = type(got[0][0]) is not np.ndarray
    phis = [float(x) for x in np.atleast_1d(np.asarray(ctx.phis, dtype=float))]
    n = len(phis)

    def col(x: Any) -> Any:
        return np.broadcast_to(np.asarray(x, dtype=complex), (n,)) if x is not None else None

    R = [col(r) for r, _, _ in got]
    V: Any = [col(v) for _, v, _ in got] if ctx.order >= 1 else None
    A: Any = [col(a) for _, _, a in got] if ctx.order >= 2 else None
    rD = np.empty(n, complex)
    th = np.empty(n)
    vD = np.empty(n, complex)
    w = np.empty(n)
    aD = np.empty(n, complex)
    e = np.empty(n)
    for m, phi in enumerate(phis):
        outer = (complex(R[0][m]), complex(R[1][m]), complex(R[2][m]))
        start = states[int(round(_phase(phi) / STEP_DEG))]
        try:
            rD[m], th[m] = place(t, outer, start)
            if V is not None:
                vo = (complex(V[0][m]), complex(V[1][m]), complex(V[2][m]))
                ao = None if A is None else (complex(A[0][m]), complex(A[1][m]), complex(A[2][m]))
                x = rates(t, outer, complex(rD[m]), float(th[m]), vo, ao)
                vD[m], w[m] = x[0], x[1]
                if ao is not None:
                    aD[m], e[m] = x[2], x[3]
        except SpecialPosition as exc:
            raise Locked(exc.said, group=t.name, point=g.point, phi_deg=phi) from None

    def out(x: np.ndarray) -> Any:
        return complex(x[0]) if scalar and x.dtype == complex else float(x[0]) if scalar else x

    base = g.links[0]
    rot = np.exp(1j * th)
    mb = place_link(ctx, base, out(rot), out(rD), zD)
    if ctx.order >= 1:
        _set_rates(ctx, mb, out(rD), out(vD), out(aD), out(w), out(e))
    inner = (rD, rD + rot * t.zE, rD + rot * t.zF)
    for leash, (o, i), Q in zip(g.links[1:], g.joints, range(3), strict=True):
        L = ctx.scene.links[leash]
        if o.kind == "P":
            _slider(ctx, leash, o, L.points[i.point], inner[Q], rD, vD, aD, w, e, out)
            continue
        if i.kind == "P":
            _block(ctx, leash, i, L.points[o.point], rot, R[Q], None if V is None else V[Q],
                   None if A is None else A[Q], rD, vD, aD, w, e, out)
            continue
        zq, zp = L.points[o.point], L.points[i.point]
        P = inner[Q]
        d = P - R[Q]
        rot_l = d / abs(d) / ((zp - zq) / abs(zp - zq))
        ml = place_link(ctx, leash, out(rot_l), out(R[Q]), zq)
        if ctx.order >= 1:
            arm = P - rD
            vP = vD + 1j * w * arm
            wl = (d.conjugate() * (vP - V[Q])).imag / abs(d) ** 2
            el = aPl = None
            if ctx.order >= 2:
                aPl = aD + (1j * e - w * w) * arm
                el = (d.conjugate() * (aPl - A[Q])).imag / abs(d) ** 2
            _set_rates(ctx, ml, out(R[Q]), out(V[Q]), None if A is None else out(A[Q]), out(wl),
                       None if el is None else out(el))


def _slider(ctx: Context, leash: int, o: Any, zp: complex, P: Any, rD: Any, vD: Any, aD: Any, w: Any, e: Any,
            out: Any) -> None:
    """A leash that slides on a guide of the frame: it keeps its angle, its pin is the base's
    inner pair; its slide ṡ, s̈ along the guide."""
    n = len(P)
    turn = _turn(o)
    m = place_link(ctx, leash, out(np.full(n, turn)), out(P), zp)
    if ctx.order < 1:
        return
    arm = P - rD
    vP = vD + 1j * w * arm
    g = o.guide.direction
    aP = aD + (1j * e - w * w) * arm if ctx.order >= 2 else None
    _set_rates(ctx, m, out(P), out(vP), None if aP is None else out(aP), out(np.zeros(n)),
               None if aP is None else out(np.zeros(n)))
    sd = (vP * np.conj(g)).real
    sdd = None if aP is None else (aP * np.conj(g)).real
    ctx.slides[o.name] = (out(sd), None if sdd is None else out(sdd))


def _block(ctx: Context, leash: int, i: Any, zq: complex, rot: Any, Q: Any, vQ: Any, aQ: Any, rD: Any, vD: Any,
           aD: Any, w: Any, e: Any, out: Any) -> None:
    """A block pinned at Q, sliding in a slot of the base: it turns with the base; its slide
    along the slot (ṡ, s̈) relative to the base's point under the pin."""
    m = place_link(ctx, leash, out(rot * _turn(i)), out(Q), zq)
    if ctx.order < 1:
        return
    _set_rates(ctx, m, out(Q), out(vQ), None if aQ is None else out(aQ), out(w), None if aQ is None else out(e))
    s = rot * i.guide.direction
    arm = Q - rD
    v_rel = vQ - (vD + 1j * w * arm)
    sd = (v_rel * np.conj(s)).real
    sdd = None
    if aQ is not None:
        a_rel = aQ - (aD + (1j * e - w * w) * arm) - 2j * w * v_rel
        sdd = (a_rel * np.conj(s)).real
    ctx.slides[i.name] = (out(sd), None if sdd is None else out(sdd))


def _turn(jt: Any) -> complex:
    """e^{i(α − α_s)}: a slider's rotation relative to the link carrying its guide."""
    return cmath.exp(1j * (jt.guide.angle - jt.slider_angle))


def _set_rates(ctx: Context, m: Motion, anchor: Any, v: Any, a: Any, omega: Any, eps: Any) -> None:
    """Rates of a placed link from one point's v, a and its ω, ε."""
    rel = m.r0 - anchor
    m.omega = omega
    m.v0 = v + 1j * omega * rel
    if ctx.order >= 2:
        m.eps = eps
        m.a0 = a + (1j * eps - omega * omega) * rel
