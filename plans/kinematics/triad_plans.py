"""The velocity and acceleration plans of a class-III group (triad) by Assur's special point.

The axes of two leashes (AD and BE) meet at S, taken as a point of the base link: its image
s is where the lines through a ⟂ AD and through b ⟂ BE meet (on the acceleration plan,
after the normal terms along the leash and along SD, SE).  Then f, the third inner pair,
where the line through c ⟂ CF meets the line through s ⟂ SF; d and e by similarity on the
base link.  S is where AD and BE meet unless they are nearly parallel; then BE and CF,
then AD and CF (parallel axes: the other pair's point).  All three axes through one
point is the group's special position: the lines of f are then parallel and the plan says so.
"""

from __future__ import annotations

from typing import Any, cast

import numpy as np

from plans.errors import Locked
from plans.kinematics.dyads import Builder, Mixed, ensure, lab, link_points, meet, rel_seg
from plans.kinematics.structure import TriadGroup
from plans.lines import cross
from plans.phrases import phrase

#: sin of the angle between two leashes' axes above which their meeting point is taken as S
FAR_FROM_PARALLEL = 0.05


def _geometry(b: Builder, g: TriadGroup) -> tuple[list, list, tuple[int, int, int], Any]:
    """Outer and inner pairs on the scheme, the leashes (i, j) whose axes give S, the third, S."""
    snap = b.snap
    base = g.links[0]
    Q = [snap.pos(p, o.point) for p, (o, _) in zip(g.known, g.joints, strict=True)]
    P = [snap.pos(base, i.point) for _, i in g.joints]
    axis = [P[k] - Q[k] for k in range(3)]
    sins = _sins(axis)
    choice = pair_choice(axis)
    if np.any(choice != choice[0]):
        raise Mixed("s")
    i, j = PAIRS[int(choice[0])]
    if np.any(sins[int(choice[0])] <= 1e-12):
        raise Locked("the three leashes' axes are parallel (special position)", group=f"{g.kind} {g.name}",
                     point=g.point, phi_deg=b.snap.phi_at(int(np.argmin(sins[int(choice[0])]))))
    s = cross(Q[j] - Q[i], axis[j]) / cross(axis[i], axis[j])
    S = Q[i] + s * axis[i]
    return Q, P, (i, j, 3 - i - j), S


#: the pairs of leashes whose axes may give S, in the order they are tried
PAIRS = ((0, 1), (1, 2), (0, 2))


def _sins(axis: list) -> list:
    return [np.atleast_1d(np.abs(cross(axis[i], axis[j])) / (np.abs(axis[i]) * np.abs(axis[j]))) for i, j in PAIRS]


def pair_choice(axis: list) -> np.ndarray:
    """Per position, the index in :data:`PAIRS` of the leashes whose axes give S: AD and BE
    unless nearly parallel (then the next pair), so a position reads the same whichever
    positions are built with it (and the force analysis takes the plan's S)."""
    sins = _sins(axis)
    return np.where(sins[0] >= FAR_FROM_PARALLEL, 0, np.where(sins[1] >= FAR_FROM_PARALLEL, 1,
                    np.where(sins[2] >= FAR_FROM_PARALLEL, 2, np.argmax(np.stack(sins), axis=0))))


def _label(b: Builder, name: str) -> str:
    while name in b.pts:
        name += "'"
    return name


def _leash_ends(b: Builder, g: TriadGroup) -> tuple[list[tuple[str, str]], list[Any], list[Any]]:
    """Each leash's (outer, inner) point names, and its outer end's image on the plan as
    the known link gives it (laid off where the plan has no such point yet)."""
    names = [(o.point, d.point) for o, d in g.joints]
    xs, ns = [], []
    for k in range(3):
        x = b.image(g.known[k], names[k][0])
        xs.append(x)
        ns.append(ensure(b, g.known[k], names[k][0], x))
    return names, xs, ns


def v_triad(b: Builder, g: TriadGroup) -> None:
    snap = b.snap
    base = g.links[0]
    Q, P, (i, j, m), S = _geometry(b, g)
    names, xs, ns = _leash_ends(b, g)
    Li = b.line(xs[i], 1j * (P[i] - Q[i]), abs(P[i] - Q[i]), f"⟂ {names[i][0]}{names[i][1]}")
    Lj = b.line(xs[j], 1j * (P[j] - Q[j]), abs(P[j] - Q[j]), f"⟂ {names[j][0]}{names[j][1]}")
    s_lab = _label(b, "s")
    xS = meet(b, cast(Any, g), Li, Lj, s_lab, b.mu * snap.v(base, S), "S", ())
    b.step("intersect", (ns[i], ns[j]), s_lab, lambda: phrase(
        "v_triad_s", A=names[i][0], D=names[i][1], B=names[j][0], E=names[j][1], n1=ns[i], n2=ns[j], out=s_lab))
    Pm, Cn, Fn = P[m], names[m][0], names[m][1]
    Lc = b.line(xs[m], 1j * (Pm - Q[m]), abs(Pm - Q[m]), f"⟂ {Cn}{Fn}")
    Ls = b.line(xS, 1j * (Pm - S), abs(Pm - S), f"⟂ S{Fn}")
    out = lab(Fn)
    xF = meet(b, cast(Any, g), Lc, Ls, out, b.mu * snap.v(base, Pm), Fn, (base, g.links[1 + m]))
    b.step("intersect", (ns[m], s_lab), out, lambda: phrase(
        "v_triad_f", C=Cn, F=Fn, n3=ns[m], s=s_lab, out=out))
    b.set_link(base, s_lab, S, (xF - xS) / (Pm - S))
    b.rate[base] = (s_lab, out, abs(Pm - S))
    b.seg(b.pole, out, "absolute", f"v_{Fn}", abs(snap.v(base, Pm)))
    link_points(b, base)
    _leashes(b, g, Q, P, xs, ns)


def _leashes(b: Builder, g: TriadGroup, Q: list, P: list, xs: list, ns: list) -> None:
    snap = b.snap
    base = g.links[0]
    for k, (o, d) in enumerate(g.joints):
        leash = g.links[1 + k]
        inner = b.labels[(base, d.point)]
        b.labels[(leash, d.point)] = inner
        b.set_link(leash, inner, P[k], (b.pts[inner] - xs[k]) / (P[k] - Q[k]))
        if b.sym == "v":
            b.rate[leash] = (ns[k], inner, abs(P[k] - Q[k]))
            rel_seg(b, ns[k], inner, o.point, d.point, abs(snap.v(leash, P[k]) - snap.v(g.known[k], Q[k])))


def a_triad(b: Builder, g: TriadGroup, vr: Any) -> None:
    from plans.kinematics.accelerations import _normal

    snap = b.snap
    base = g.links[0]
    Q, P, (i, j, m), S = _geometry(b, g)
    names, xs, ns = _leash_ends(b, g)
    ends: dict[Any, tuple[str, Any]] = {}
    for k in (i, j):  # a_S = a_Q + a_PQ^n + a_SP^n + (a_PQ^τ + a_SP^τ) ⟂ QP
        leash = g.links[1 + k]
        m1, y1 = _normal(b, vr, leash, ns[k], xs[k], Q[k], P[k], names[k][0], names[k][1])
        ends[k] = (m1, y1)
        m2, y2 = _normal(b, vr, base, m1, y1, P[k], S, names[k][1], "S")
        ends[(k, "S")] = (m2, y2)
    (mi, yi), (mj, yj) = ends[(i, "S")], ends[(j, "S")]
    Li = b.line(yi, 1j * (P[i] - Q[i]), abs(P[i] - Q[i]), f"⟂ {names[i][0]}{names[i][1]}")
    Lj = b.line(yj, 1j * (P[j] - Q[j]), abs(P[j] - Q[j]), f"⟂ {names[j][0]}{names[j][1]}")
    s_lab = _label(b, "s")
    xS = meet(b, cast(Any, g), Li, Lj, s_lab, b.mu * snap.a(base, S), "S", ())
    b.step("intersect", (mi, mj), s_lab, lambda: phrase(
        "a_triad_s", A=names[i][0], D=names[i][1], B=names[j][0], E=names[j][1], m1=mi, m2=mj, out=s_lab))
    Pm, Cn, Fn = P[m], names[m][0], names[m][1]
    leash_m = g.links[1 + m]
    mc, yc = _normal(b, vr, leash_m, ns[m], xs[m], Q[m], Pm, Cn, Fn)
    ms, ys = _normal(b, vr, base, s_lab, xS, S, Pm, "S", Fn)
    Lc = b.line(yc, 1j * (Pm - Q[m]), abs(Pm - Q[m]), f"⟂ {Cn}{Fn}")
    Ls = b.line(ys, 1j * (Pm - S), abs(Pm - S), f"⟂ S{Fn}")
    out = lab(Fn)
    xF = meet(b, cast(Any, g), Lc, Ls, out, b.mu * snap.a(base, Pm), Fn, (base, leash_m))
    b.step("intersect", (mc, ms), out, lambda: phrase(
        "a_triad_f", C=Cn, F=Fn, m3=mc, ms=ms, out=out))
    b.set_link(base, s_lab, S, (xF - xS) / (Pm - S))
    b.rate[base] = (ms, out, abs(Pm - S))
    b.seg(ms, out, "tangential", f"a_{Fn}S^τ", abs(snap.e[base]) * abs(Pm - S))
    b.seg(b.pole, out, "absolute", f"a_{Fn}", abs(snap.a(base, Pm)))
    link_points(b, base)
    _leashes(b, g, Q, P, xs, ns)
    for k in range(3):
        leash = g.links[1 + k]
        start = ends[k][0] if k in ends else mc
        inner = b.labels[(base, names[k][1])]
        if k != m:  # the leash's own tangential term: from its normal term to its inner pair's image
            b.rate[leash] = (start, inner, abs(P[k] - Q[k]))
        else:
            b.rate[leash] = (mc, out, abs(P[k] - Q[k]))
        b.seg(start, inner, "tangential", f"a_{names[k][1]}{names[k][0]}^τ", abs(snap.e[leash]) * abs(P[k] - Q[k]))


def assur_point(kin: Any, g: TriadGroup) -> tuple[Any, Any]:
    """Assur's point S of the group over the positions of ``kin`` (the plans' choice of the two
    leashes), and that choice (index in :data:`PAIRS`); S is NaN-free: where all three axes
    are parallel the caller has been stopped already, a pair never parallel is taken."""
    base = g.links[0]
    Q = [kin.point(o.point, p)[0] for p, (o, _) in zip(g.known, g.joints, strict=True)]
    P = [kin.point(d.point, base)[0] for _, d in g.joints]
    axis = [P[k] - Q[k] for k in range(3)]
    choice = pair_choice(axis)
    ii = np.array([p[0] for p in PAIRS])[choice]
    jj = np.array([p[1] for p in PAIRS])[choice]
    cols = np.arange(len(choice))
    Qs, ax = np.stack(Q), np.stack(axis)
    Qi, Qj, ui, uj = Qs[ii, cols], Qs[jj, cols], ax[ii, cols], ax[jj, cols]
    s = cross(ui, uj)
    safe = np.where(s == 0, 1.0, s)
    return Qi + cross(Qj - Qi, uj) / safe * ui, choice
