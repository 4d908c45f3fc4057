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

from plans.errors import Locked, Said
from plans.kinematics.dyads import (
    Builder,
    Mixed,
    coincident,
    ensure,
    lab,
    lay_coriolis,
    lay_normal,
    link_points,
    meet,
    rel_seg,
)
from plans.kinematics.structure import TriadGroup
from plans.lines import cross
from plans.phrases import phrase
from plans.tolerances import LOCK_SIN

#: sin of the angle between two leashes' axes above which their meeting point is taken as S
FAR_FROM_PARALLEL = 0.05


def _slider(o: Any) -> bool:
    """A leash that is a slider on a guide of the frame (its outer pair P at its inner pin)."""
    return o.kind == "P"


def _block(d: Any) -> bool:
    """A leash that is a block pinned at its outer pair, sliding in a slot of the base."""
    return d.kind == "P"


def _geometry(b: Builder, g: TriadGroup) -> tuple[list, list, list, tuple[int, int, int], Any]:
    """Per leash a point of its axis (the outer pair, or a slider's pin) and the axis' direction
    (along the leash, or the guide's or slot's normal); where it meets the base (its inner
    pair, or a block's pin); the leashes (i, j) whose axes give S, the third; S."""
    snap = b.snap
    base = g.links[0]
    P, Q, axis = [], [], []
    for p, (o, d) in zip(g.known, g.joints, strict=True):
        if _slider(o):
            P.append(snap.pos(base, d.point))
            Q.append(P[-1])
            axis.append(1j * snap.guide(o)[0])
        elif _block(d):
            Q.append(snap.pos(p, o.point))
            P.append(Q[-1])
            axis.append(1j * snap.guide(d)[0])
        else:
            P.append(snap.pos(base, d.point))
            Q.append(snap.pos(p, o.point))
            axis.append(P[-1] - Q[-1])
    sins = _sins(axis)
    choice = pair_choice(axis)
    if np.any(choice != choice[0]):
        raise Mixed("s")
    i, j = PAIRS[int(choice[0])]
    if np.any(sins[int(choice[0])] <= LOCK_SIN):
        raise Locked(Said("tp_three_leashes_axes"), group=f"{g.kind} {g.name}",
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
    o, d = g.joints[k]
    A, D = names[k]
    if _slider(o):
        return phrase("t_axis_guide", F=D), phrase("t_par_guide", F=D)
    if _block(d):
        return phrase("t_axis_slot", C=A, j=g.links[0]), phrase("t_par_slot", j=g.links[0])
    return phrase("t_axis_leash", A=A, D=D), phrase("t_perp", A=A, D=D)


def _label_of(g: TriadGroup, names: list, k: int) -> str:
    o, d = g.joints[k]
    if _block(d):
        return f"∥ slot of link {g.links[0]}"
    return f"∥ guide of {names[k][1]}" if _slider(o) else f"⟂ {names[k][0]}{names[k][1]}"


def _span(Q: Any, P: Any, o: Any) -> Any:
    return 0.0 if _slider(o) or Q is P else abs(P - Q)


def _plain(g: TriadGroup) -> bool:
    return all(o.kind == "R" and d.kind == "R" for o, d in g.joints)


def _under_pin(b: Builder, g: TriadGroup, k: int) -> str:
    """The label of the base's point under a block's pin (c3): where the plan has it."""
    return f"{lab(g.joints[k][0].point)}{g.links[0]}"


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
    plain = _plain(g)
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
    block_m = _block(g.joints[m][1])
    out = _under_pin(b, g, m) if block_m else lab(Fn)
    xF = meet(b, cast(Any, g), Lc, Ls, out, b.mu * snap.v(base, Pm), Fn, () if block_m else (base, g.links[1 + m]))
    if plain:
        b.step("intersect", (ns[m], s_lab), out, lambda: phrase(
            "v_triad_f", C=Cn, F=Fn, n3=ns[m], s=s_lab, out=out))
    else:
        b.step("intersect", (ns[m], s_lab), out, lambda: phrase(
            "v_triad_fg", F=Fn, n3=ns[m], s=s_lab, out=out, l3=_words(g, names, m)[1]))
    b.set_link(base, s_lab, S, (xF - xS) / (Pm - S))
    b.rate[base] = (s_lab, out, abs(Pm - S))
    b.seg(b.pole, out, "absolute", f"v_{Fn}{base}" if block_m else f"v_{Fn}", abs(snap.v(base, Pm)))
    link_points(b, base)
    _leashes(b, g, Q, P, xs, ns)


def _leashes(b: Builder, g: TriadGroup, Q: list, P: list, xs: list, ns: list) -> None:
    snap = b.snap
    base = g.links[0]
    for k, (o, d) in enumerate(g.joints):
        leash = g.links[1 + k]
        if _block(d):  # it turns with the base; its pin is the known link's point
            under = _under_pin(b, g, k)
            if under not in b.pts:
                coincident(b, base, o.point, P[k])
            b.labels[(leash, o.point)] = ns[k]
            b.set_link(leash, ns[k], P[k], b.factor[base])
            b.rate[leash] = base
            if b.sym == "v":
                sd, _ = snap.slide(d)
                b.seg(under, ns[k], "sliding", f"v_{o.point}{leash}{o.point}{base}", abs(sd))
            continue
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
        elif _block(g.joints[k][1]):  # the base under the pin: a_C + a^k (+ a^r ∥ slot)
            m1, y1 = _coriolis_at(b, vr, g, k, ns[k], xs[k])
        else:
            m1, y1 = lay_normal(b, vr, leash, ns[k], xs[k], Q[k], P[k], names[k][0], names[k][1])
        ends[k] = (m1, y1)
        m2, y2 = lay_normal(b, vr, base, m1, y1, P[k], S, names[k][1], "S")
        ends[(k, "S")] = (m2, y2)
    (mi, yi), (mj, yj) = ends[(i, "S")], ends[(j, "S")]
    oi, om, oj = g.joints[i][0], g.joints[m][0], g.joints[j][0]
    Li = b.line(yi, 1j * axis[i], _span(Q[i], P[i], oi), _label_of(g, names, i))
    Lj = b.line(yj, 1j * axis[j], _span(Q[j], P[j], oj), _label_of(g, names, j))
    s_lab = _label(b, "s")
    xS = meet(b, cast(Any, g), Li, Lj, s_lab, b.mu * snap.a(base, S), "S", ())
    plain = _plain(g)
    if plain:
        b.step("intersect", (mi, mj), s_lab, lambda: phrase(
            "a_triad_s", A=names[i][0], D=names[i][1], B=names[j][0], E=names[j][1], m1=mi, m2=mj, out=s_lab))
    else:
        b.step("intersect", (mi, mj), s_lab, lambda: phrase(
            "a_triad_sg", l1=_words(g, names, i)[1], l2=_words(g, names, j)[1], m1=mi, m2=mj, out=s_lab))
    Pm, Cn, Fn = P[m], names[m][0], names[m][1]
    leash_m = g.links[1 + m]
    block_m = _block(g.joints[m][1])
    if _slider(om):
        mc, yc = b.pole, b.zero
    elif block_m:
        mc, yc = _coriolis_at(b, vr, g, m, ns[m], xs[m])
    else:
        mc, yc = lay_normal(b, vr, leash_m, ns[m], xs[m], Q[m], Pm, Cn, Fn)
    ms, ys = lay_normal(b, vr, base, s_lab, xS, S, Pm, "S", Fn)
    Lc = b.line(yc, 1j * axis[m], _span(Q[m], Pm, om), _label_of(g, names, m))
    Ls = b.line(ys, 1j * (Pm - S), abs(Pm - S), f"⟂ S{Fn}")
    out = _under_pin(b, g, m) if block_m else lab(Fn)
    xF = meet(b, cast(Any, g), Lc, Ls, out, b.mu * snap.a(base, Pm), Fn, () if block_m else (base, leash_m))
    if plain:
        b.step("intersect", (mc, ms), out, lambda: phrase(
            "a_triad_f", C=Cn, F=Fn, m3=mc, ms=ms, out=out))
    else:
        b.step("intersect", (mc, ms), out, lambda: phrase(
            "a_triad_fg", F=Fn, m3=mc, ms=ms, out=out, l3=_words(g, names, m)[1]))
    b.set_link(base, s_lab, S, (xF - xS) / (Pm - S))
    b.rate[base] = (ms, out, abs(Pm - S))
    b.seg(ms, out, "tangential", f"a_{Fn}S^τ", abs(snap.e[base]) * abs(Pm - S))
    b.seg(b.pole, out, "absolute", f"a_{Fn}{base}" if block_m else f"a_{Fn}", abs(snap.a(base, Pm)))
    link_points(b, base)
    _leashes(b, g, Q, P, xs, ns)
    for k in range(3):
        leash = g.links[1 + k]
        if _slider(g.joints[k][0]) or _block(g.joints[k][1]):
            continue
        start = ends[k][0] if k in ends else mc
        inner = b.labels[(base, names[k][1])]
        if k != m:  # the leash's own tangential term: from its normal term to its inner pair's image
            b.rate[leash] = (start, inner, abs(P[k] - Q[k]))
        else:
            b.rate[leash] = (mc, out, abs(P[k] - Q[k]))
        b.seg(start, inner, "tangential", f"a_{names[k][1]}{names[k][0]}^τ", abs(snap.e[leash]) * abs(P[k] - Q[k]))


def _coriolis_at(b: Builder, vr: Any, g: TriadGroup, k: int, frm: str, frm_xy: Any) -> tuple[str, Any]:
    """From the image of a block's pin (c), the Coriolis term of the base's point under it:
    a_C3 = a_C + a^k_C3C + a^r (∥ slot), v_C3C read off the velocity plan."""
    base = g.links[0]
    pin = g.joints[k][0].point
    vb = vr.vb
    known = g.known[k]
    at_pin = vb.pole if known == vb.snap.scene.frame else vb.labels.get((known, pin), lab(pin))
    v_rel = vr.rel(at_pin, f"{lab(pin)}{base}")
    sd, _ = b.snap.slide(g.joints[k][1])
    return lay_coriolis(b, vr, base, v_rel, frm, frm_xy, f"{pin}{base}{pin}{g.links[1 + k]}",
                     abs(2 * b.snap.w[base] * sd))


def axes_of(kin: Any, g: TriadGroup) -> tuple[list, list, list]:
    """Over the positions of ``kin``: per leash a point of its axis (the outer pair, or a
    slider's pin), the axis' direction (along the leash, or the guide's normal), the inner pair."""
    base = g.links[0]
    P, Q, axis = [], [], []
    for p, (o, d) in zip(g.known, g.joints, strict=True):
        if _slider(o):
            P.append(kin.point(d.point, base)[0])
            Q.append(P[-1])
            assert o.guide is not None
            axis.append(np.broadcast_to(1j * o.guide.direction, np.shape(P[-1])))
        elif _block(d):
            assert d.guide is not None
            Q.append(kin.point(o.point, p)[0])
            P.append(Q[-1])
            axis.append(1j * kin.motion[base].rot * d.guide.direction * np.ones(np.shape(Q[-1])))
        else:
            P.append(kin.point(d.point, base)[0])
            Q.append(kin.point(o.point, p)[0])
            axis.append(P[-1] - Q[-1])
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


def special_point_of(kin: Any, g: TriadGroup) -> tuple[Any, Any, list, list]:
    """Assur's point S of the group over the positions of ``kin``, the choice of the two
    leashes (:func:`assur_point`), and per leash its outer and inner pair (:func:`axes_of`,
    the outer ones over the positions): found once and kept by ``kin``, read by the JSON and
    by the sheets that mark S."""
    memo = kin.special_points
    got = memo.get(g.name)
    if got is None:
        S, choice = assur_point(kin, g)
        Q, _, P = axes_of(kin, g)
        got = memo[g.name] = (S, choice, [np.broadcast_to(x, np.shape(P[0])) for x in Q], P)
    return got


def assur_points_json(kin: Any, k: int) -> list[dict]:
    """``positions[i].assur_points``: per class-III group its special point S (m, the scene's
    frame) and the two leashes whose axes give it ([outer, inner] point names)."""
    out = []
    for g in kin.structure.triads():
        S, choice, _, _ = special_point_of(kin, g)
        i, j = PAIRS[int(choice[k])]
        z = complex(S[k])
        out.append({"group": g.name, "point": [z.real, z.imag],
                    "leashes": [[g.joints[x][0].point, g.joints[x][1].point] for x in (i, j)]})
    return out
