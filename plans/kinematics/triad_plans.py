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


def _slider(o: Any) -> bool:
    """A leash that is a slider on a guide of the frame (its outer pair P at its inner pin)."""
    return o.kind == "P"


def _geometry(b: Builder, g: TriadGroup) -> tuple[list, list, list, tuple[int, int, int], Any]:
    """Per leash a point of its axis (the outer pair, or a slider's pin) and the axis' direction
    (along the leash, or the guide's normal); the inner pairs; the leashes (i, j) whose axes
    give S, the third; S."""
    snap = b.snap
    base = g.links[0]
    P = [snap.pos(base, i.point) for _, i in g.joints]
    Q, axis = [], []
    for k, (p, (o, _)) in enumerate(zip(g.known, g.joints, strict=True)):
        if _slider(o):
            Q.append(P[k])
            axis.append(1j * snap.guide(o)[0])
        else:
            Q.append(snap.pos(p, o.point))
            axis.append(P[k] - Q[k])
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
    return Q, P, axis, (i, j, 3 - i - j), S


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
    the known link gives it (laid off where the plan has no such point yet; a slider's: the
    frame's point under its pin, the pole)."""
    names = [(o.point, d.point) for o, d in g.joints]
    xs, ns = [], []
    for k, (o, _) in enumerate(g.joints):
        if _slider(o):
            xs.append(b.zero)
            ns.append(b.pole)
            continue
        x = b.image(g.known[k], names[k][0])
        xs.append(x)
        ns.append(ensure(b, g.known[k], names[k][0], x))
    return names, xs, ns


def _words(g: TriadGroup, names: list, k: int) -> tuple[Any, Any]:
    """(the axis, the line through the leash's outer image) of leash k, as the protocol says them."""
    o, _ = g.joints[k]
    A, D = names[k]
    if _slider(o):
        return phrase("t_axis_guide", F=D), phrase("t_par_guide", F=D)
    return phrase("t_axis_leash", A=A, D=D), phrase("t_perp", A=A, D=D)


def _label_of(g: TriadGroup, names: list, k: int) -> str:
    o, _ = g.joints[k]
    return f"∥ guide of {names[k][1]}" if _slider(o) else f"⟂ {names[k][0]}{names[k][1]}"


def _span(Q: Any, P: Any, o: Any) -> Any:
    return 0.0 if _slider(o) else abs(P - Q)


def v_triad(b: Builder, g: TriadGroup) -> None:
    snap = b.snap
    base = g.links[0]
    Q, P, axis, (i, j, m), S = _geometry(b, g)
    names, xs, ns = _leash_ends(b, g)
    oi, om, oj = g.joints[i][0], g.joints[m][0], g.joints[j][0]
    Li = b.line(xs[i], 1j * axis[i], _span(Q[i], P[i], oi), _label_of(g, names, i))
    Lj = b.line(xs[j], 1j * axis[j], _span(Q[j], P[j], oj), _label_of(g, names, j))
    s_lab = _label(b, "s")
    xS = meet(b, cast(Any, g), Li, Lj, s_lab, b.mu * snap.v(base, S), "S", ())
    plain = not any(_slider(o) for o, _ in g.joints)
    if plain:
        b.step("intersect", (ns[i], ns[j]), s_lab, lambda: phrase(
            "v_triad_s", A=names[i][0], D=names[i][1], B=names[j][0], E=names[j][1], n1=ns[i], n2=ns[j], out=s_lab))
    else:
        b.step("intersect", (ns[i], ns[j]), s_lab, lambda: phrase(
            "v_triad_sg", ax1=_words(g, names, i)[0], ax2=_words(g, names, j)[0], l1=_words(g, names, i)[1],
            l2=_words(g, names, j)[1], n1=ns[i], n2=ns[j], out=s_lab))
    Pm, Cn, Fn = P[m], names[m][0], names[m][1]
    Lc = b.line(xs[m], 1j * axis[m], _span(Q[m], Pm, om), _label_of(g, names, m))
    Ls = b.line(xS, 1j * (Pm - S), abs(Pm - S), f"⟂ S{Fn}")
    out = lab(Fn)
    xF = meet(b, cast(Any, g), Lc, Ls, out, b.mu * snap.v(base, Pm), Fn, (base, g.links[1 + m]))
    if plain:
        b.step("intersect", (ns[m], s_lab), out, lambda: phrase(
            "v_triad_f", C=Cn, F=Fn, n3=ns[m], s=s_lab, out=out))
    else:
        b.step("intersect", (ns[m], s_lab), out, lambda: phrase(
            "v_triad_fg", F=Fn, n3=ns[m], s=s_lab, out=out, l3=_words(g, names, m)[1]))
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
        if _slider(o):  # it slides on the frame: it does not turn
            b.set_link(leash, inner, P[k], b.factor[g.known[k]])
            b.rate[leash] = g.known[k]
            continue
        b.set_link(leash, inner, P[k], (b.pts[inner] - xs[k]) / (P[k] - Q[k]))
        if b.sym == "v":
            b.rate[leash] = (ns[k], inner, abs(P[k] - Q[k]))
            rel_seg(b, ns[k], inner, o.point, d.point, abs(snap.v(leash, P[k]) - snap.v(g.known[k], Q[k])))


def a_triad(b: Builder, g: TriadGroup, vr: Any) -> None:
    from plans.kinematics.accelerations import _normal

    snap = b.snap
    base = g.links[0]
    Q, P, axis, (i, j, m), S = _geometry(b, g)
    names, xs, ns = _leash_ends(b, g)
    ends: dict[Any, tuple[str, Any]] = {}
    for k in (i, j):  # a_S = a_Q + a_PQ^n + a_SP^n + (a_PQ^τ + a_SP^τ) ⟂ QP
        leash = g.links[1 + k]
        o = g.joints[k][0]
        if _slider(o):  # a_P ∥ guide: from the pole, only the base's normal term a_SP^n
            m1, y1 = b.pole, b.zero
        else:
            m1, y1 = _normal(b, vr, leash, ns[k], xs[k], Q[k], P[k], names[k][0], names[k][1])
        ends[k] = (m1, y1)
        m2, y2 = _normal(b, vr, base, m1, y1, P[k], S, names[k][1], "S")
        ends[(k, "S")] = (m2, y2)
    (mi, yi), (mj, yj) = ends[(i, "S")], ends[(j, "S")]
    oi, om, oj = g.joints[i][0], g.joints[m][0], g.joints[j][0]
    Li = b.line(yi, 1j * axis[i], _span(Q[i], P[i], oi), _label_of(g, names, i))
    Lj = b.line(yj, 1j * axis[j], _span(Q[j], P[j], oj), _label_of(g, names, j))
    s_lab = _label(b, "s")
    xS = meet(b, cast(Any, g), Li, Lj, s_lab, b.mu * snap.a(base, S), "S", ())
    plain = not any(_slider(o) for o, _ in g.joints)
    if plain:
        b.step("intersect", (mi, mj), s_lab, lambda: phrase(
            "a_triad_s", A=names[i][0], D=names[i][1], B=names[j][0], E=names[j][1], m1=mi, m2=mj, out=s_lab))
    else:
        b.step("intersect", (mi, mj), s_lab, lambda: phrase(
            "a_triad_sg", l1=_words(g, names, i)[1], l2=_words(g, names, j)[1], m1=mi, m2=mj, out=s_lab))
    Pm, Cn, Fn = P[m], names[m][0], names[m][1]
    leash_m = g.links[1 + m]
    if _slider(om):
        mc, yc = b.pole, b.zero
    else:
        mc, yc = _normal(b, vr, leash_m, ns[m], xs[m], Q[m], Pm, Cn, Fn)
    ms, ys = _normal(b, vr, base, s_lab, xS, S, Pm, "S", Fn)
    Lc = b.line(yc, 1j * axis[m], _span(Q[m], Pm, om), _label_of(g, names, m))
    Ls = b.line(ys, 1j * (Pm - S), abs(Pm - S), f"⟂ S{Fn}")
    out = lab(Fn)
    xF = meet(b, cast(Any, g), Lc, Ls, out, b.mu * snap.a(base, Pm), Fn, (base, leash_m))
    if plain:
        b.step("intersect", (mc, ms), out, lambda: phrase(
            "a_triad_f", C=Cn, F=Fn, m3=mc, ms=ms, out=out))
    else:
        b.step("intersect", (mc, ms), out, lambda: phrase(
            "a_triad_fg", F=Fn, m3=mc, ms=ms, out=out, l3=_words(g, names, m)[1]))
    b.set_link(base, s_lab, S, (xF - xS) / (Pm - S))
    b.rate[base] = (ms, out, abs(Pm - S))
    b.seg(ms, out, "tangential", f"a_{Fn}S^τ", abs(snap.e[base]) * abs(Pm - S))
    b.seg(b.pole, out, "absolute", f"a_{Fn}", abs(snap.a(base, Pm)))
    link_points(b, base)
    _leashes(b, g, Q, P, xs, ns)
    for k in range(3):
        leash = g.links[1 + k]
        if _slider(g.joints[k][0]):
            continue
        start = ends[k][0] if k in ends else mc
        inner = b.labels[(base, names[k][1])]
        if k != m:  # the leash's own tangential term: from its normal term to its inner pair's image
            b.rate[leash] = (start, inner, abs(P[k] - Q[k]))
        else:
            b.rate[leash] = (mc, out, abs(P[k] - Q[k]))
        b.seg(start, inner, "tangential", f"a_{names[k][1]}{names[k][0]}^τ", abs(snap.e[leash]) * abs(P[k] - Q[k]))


def axes_of(kin: Any, g: TriadGroup) -> tuple[list, list, list]:
    """Over the positions of ``kin``: per leash a point of its axis (the outer pair, or a
    slider's pin), the axis' direction (along the leash, or the guide's normal), the inner pair."""
    base = g.links[0]
    P = [kin.point(d.point, base)[0] for _, d in g.joints]
    Q, axis = [], []
    for k, (p, (o, _)) in enumerate(zip(g.known, g.joints, strict=True)):
        if _slider(o):
            Q.append(P[k])
            assert o.guide is not None
            axis.append(np.broadcast_to(1j * o.guide.direction, np.shape(P[k])))
        else:
            Q.append(kin.point(o.point, p)[0])
            axis.append(P[k] - Q[k])
    return Q, axis, P


def assur_point(kin: Any, g: TriadGroup) -> tuple[Any, Any]:
    """Assur's point S of the group over the positions of ``kin`` (the plans' choice of the two
    leashes), and that choice (index in :data:`PAIRS`); S is NaN-free: where all three axes
    are parallel the caller has been stopped already, a pair never parallel is taken."""
    Q, axis, _ = axes_of(kin, g)
    choice = pair_choice(axis)
    ii = np.array([p[0] for p in PAIRS])[choice]
    jj = np.array([p[1] for p in PAIRS])[choice]
    cols = np.arange(len(choice))
    Qs, ax = np.stack(Q), np.stack(axis)
    Qi, Qj, ui, uj = Qs[ii, cols], Qs[jj, cols], ax[ii, cols], ax[jj, cols]
    s = cross(ui, uj)
    safe = np.where(s == 0, 1.0, s)
    return Qi + cross(Qj - Qi, uj) / safe * ui, choice


def assur_points_json(kin: Any, k: int) -> list[dict]:
    """``positions[i].assur_points``: per class-III group its special point S (m, the scene's
    frame) and the two leashes whose axes give it ([outer, inner] point names)."""
    memo = kin.__dict__.setdefault("_assur", {})
    out = []
    for g in kin.structure.triads():
        got = memo.get(g.name)
        if got is None:
            got = memo[g.name] = assur_point(kin, g)
        S, choice = got
        i, j = PAIRS[int(choice[k])]
        z = complex(S[k])
        out.append({"group": g.name, "point": [z.real, z.imag],
                    "leashes": [[g.joints[x][0].point, g.joints[x][1].point] for x in (i, j)]})
    return out
