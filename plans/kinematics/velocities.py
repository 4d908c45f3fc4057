"""The velocity plan: the crank's known vector, then each dyad's two lines intersected.

One function per dyad kind, each written once over arrays of cases and drawn with a
:class:`plans.kinematics.dyads.Pencil` (see :mod:`plans.kinematics.dyads`).
"""

from __future__ import annotations

import numpy as np

from plans.kinematics.cases import sign
from plans.kinematics.dyads import (
    Builder,
    Pencil,
    Scheme,
    coincident,
    ensure,
    lab,
    link_points,
    meet,
    read_rates,
    rel_seg,
)
from plans.kinematics.structure import Group, TriadGroup
from plans.phrases import phrase


def velocity_plan(snap: Scheme, mu: float, pencil: Pencil, protocol: bool = False) -> Builder:
    b = Builder(snap, "velocity", mu, pencil, protocol)
    d = snap.scene.driver
    crank = snap.scene.links[d.link]
    O, A_name = d.pivot, crank.axis[1]
    Opos, Apos = snap.pos(d.link, O), snap.pos(d.link, A_name)
    w1 = d.omega
    l1 = abs(Apos - Opos)
    a_xy = pencil.vector(mu * abs(w1) * l1, 1j * sign(w1) * (Apos - Opos), l1, lab(A_name))
    b.add(lab(A_name), a_xy)
    b.ref = abs(a_xy) / mu
    b.labels[(d.link, A_name)] = lab(A_name)
    b.labels[(d.link, O)] = b.pole
    b.step("lay off", (b.pole,), lab(A_name), lambda: phrase(
        "v_crank", A=A_name, O=O, w=abs(w1), l=b.s(l1), v=abs(w1) * b.s(l1), pole=b.pole, a=lab(A_name),
        mm=abs(b.s(a_xy)), mu=mu))
    b.set_link(d.link, lab(A_name), Apos, mu * 1j * w1 + 0 * Apos)
    b.seg(b.pole, lab(A_name), "absolute", f"v_{A_name}", abs(snap.v(d.link, Apos)))
    link_points(b, d.link)
    for g in snap.kin.structure.groups:
        if isinstance(g, TriadGroup):  # class III: by Assur's special point
            from plans.kinematics.triad_plans import v_triad

            v_triad(b, g)
        else:
            _VEL[g.kind](b, g)
        for lid in g.links:
            link_points(b, lid)
    read_rates(b)
    return b


def _exact_v(b: Builder, link: int, X: np.ndarray) -> np.ndarray:
    return b.mu * b.snap.v(link, X)


def _v_rrr(b: Builder, g: Group) -> None:
    snap = b.snap
    i, j = g.links
    j1, j2, j3 = g.joints
    p, q = g.known
    P1, B, P3 = snap.pos(p, j1.point), snap.pos(i, j2.point), snap.pos(q, j3.point)
    x1, x3 = b.image(p, j1.point), b.image(q, j3.point)
    n1 = ensure(b, p, j1.point, x1)
    n3 = ensure(b, q, j3.point, x3)
    L1 = b.line(x1, 1j * (B - P1), abs(B - P1), f"⟂ {j1.point}{j2.point}")
    L3 = b.line(x3, 1j * (B - P3), abs(B - P3), f"⟂ {j3.point}{j2.point}")
    out = lab(j2.point)
    xb = meet(b, g, L1, L3, out, _exact_v(b, i, B), j2.point, (i, j))
    b.step("intersect", (n1, n3), out, lambda: phrase(
        "v_rrr", A=j1.point, B=j2.point, C=j3.point, n1=n1, n3=n3, out=out))
    b.set_link(i, out, B, (xb - x1) / (B - P1))
    b.set_link(j, out, B, (xb - x3) / (B - P3))
    b.rate[i], b.rate[j] = (n1, out, abs(B - P1)), (n3, out, abs(B - P3))
    b.seg(b.pole, out, "absolute", f"v_{j2.point}", abs(snap.v(i, B)))
    rel_seg(b, n1, out, j1.point, j2.point, abs(snap.v(i, B) - snap.v(p, P1)))
    rel_seg(b, n3, out, j3.point, j2.point, abs(snap.v(j, B) - snap.v(q, P3)))


def _v_rrp(b: Builder, g: Group) -> None:
    snap = b.snap
    i, j = g.links
    j1, j2, j3 = g.joints
    p, q = g.known
    P1, B = snap.pos(p, j1.point), snap.pos(i, j2.point)
    u, span = snap.guide(j3)
    x1 = b.image(p, j1.point)
    n1 = ensure(b, p, j1.point, x1)
    nq, xq = coincident(b, q, j2.point, B)
    L1 = b.line(x1, 1j * (B - P1), abs(B - P1), f"⟂ {j1.point}{j2.point}")
    L3 = b.line(xq, u, span, f"∥ guide of {j2.point}")
    out = lab(j2.point)
    xb = meet(b, g, L1, L3, out, _exact_v(b, i, B), j2.point, (i, j))
    b.step("intersect", (n1, nq), out, lambda: phrase(
        "v_rrp", A=j1.point, B=j2.point, n1=n1, nq=nq, out=out))
    b.set_link(i, out, B, (xb - x1) / (B - P1))
    b.set_link(j, out, B, b.factor[q])
    b.rate[i], b.rate[j] = (n1, out, abs(B - P1)), q
    b.seg(b.pole, out, "absolute", f"v_{j2.point}", abs(snap.v(i, B)))
    rel_seg(b, n1, out, j1.point, j2.point, abs(snap.v(i, B) - snap.v(p, P1)))
    if q != snap.scene.frame:
        sd, _ = snap.slide(j3)
        b.seg(nq, out, "sliding", f"v_{j2.point}{j}{j2.point}{q}", abs(sd))


def _v_rpr(b: Builder, g: Group) -> None:
    snap = b.snap
    i, j = g.links
    j1, j2, j3 = g.joints
    p, q = g.known
    A, Cq = snap.pos(p, j1.point), snap.pos(q, j3.point)
    u, span = snap.guide(j2)  # the slot carried by j, from j's placed pose
    xa, xc = b.image(p, j1.point), b.image(q, j3.point)
    na = ensure(b, p, j1.point, xa)
    nc = ensure(b, q, j3.point, xc)
    L1 = b.line(xc, 1j * (A - Cq), abs(A - Cq), f"⟂ {j3.point}{j1.point}")
    L2 = b.line(xa, u, span, f"∥ slot of link {j}")
    out = f"{lab(j1.point)}{j}"
    x3 = meet(b, g, L1, L2, out, _exact_v(b, j, A), j1.point, ())
    b.step("intersect", (nc, na), out, lambda: phrase(
        "v_rpr", A=j1.point, C=j3.point, i=i, j=j, out=out))
    f = (x3 - xc) / (A - Cq)
    b.set_link(j, out, A, f)
    b.set_link(i, na, A, f)
    b.rate[j], b.rate[i] = (nc, out, abs(A - Cq)), j
    b.labels[(i, j1.point)] = na
    b.seg(b.pole, out, "absolute", f"v_{j1.point}{j}", abs(snap.v(j, A)))
    rel_seg(b, nc, out, j3.point, f"{j1.point}{j}", abs(snap.v(j, A) - snap.v(q, Cq)))
    sd, _ = snap.slide(j2)
    b.seg(out, na, "sliding", f"v_{j1.point}{i}{j1.point}{j}", abs(sd))


def _v_prp(b: Builder, g: Group) -> None:
    snap = b.snap
    i, j = g.links
    j1, j2, j3 = g.joints
    p, q = g.known
    B = snap.pos(i, j2.point)
    u1, s1 = snap.guide(j1)
    u3, s3 = snap.guide(j3)
    n1, x1 = coincident(b, p, j2.point, B)
    n3, x3 = coincident(b, q, j2.point, B)
    L1 = b.line(x1, u1, s1, f"∥ guide of link {i}")
    L3 = b.line(x3, u3, s3, f"∥ guide of link {j}")
    out = lab(j2.point)
    meet(b, g, L1, L3, out, _exact_v(b, i, B), j2.point, (i, j))
    b.step("intersect", (n1, n3), out, lambda: phrase(
        "v_prp", B=j2.point, p=p, q=q, i=i, j=j, out=out))
    b.set_link(i, out, B, b.factor[p])
    b.set_link(j, out, B, b.factor[q])
    b.rate[i], b.rate[j] = p, q
    b.seg(b.pole, out, "absolute", f"v_{j2.point}", abs(snap.v(i, B)))
    sd1, _ = snap.slide(j1)
    sd3, _ = snap.slide(j3)
    if n1 != b.pole:
        b.seg(n1, out, "sliding", f"v_{j2.point}{i}{j2.point}{p}", abs(sd1))
    if n3 != b.pole:
        b.seg(n3, out, "sliding", f"v_{j2.point}{j}{j2.point}{q}", abs(sd3))


def _v_rpp(b: Builder, g: Group) -> None:
    snap = b.snap
    i, j = g.links
    j1, j2, j3 = g.joints
    p, q = g.known
    A = snap.pos(p, j1.point)
    u2, s2 = snap.guide(j2)
    u3, s3 = snap.guide(j3)
    xa = b.image(p, j1.point)
    na = ensure(b, p, j1.point, xa)
    nq, xq = coincident(b, q, j1.point, A)
    L3 = b.line(xq, u3, s3, f"∥ guide of link {j}")
    L2 = b.line(xa, u2, s2, f"∥ slot of link {j}")
    out = f"{lab(j1.point)}{j}"
    meet(b, g, L3, L2, out, _exact_v(b, j, A), j1.point, ())
    b.step("intersect", (nq, na), out, lambda: phrase(
        "v_rpp", A=j1.point, q=q, i=i, j=j, out=out))
    b.set_link(j, out, A, b.factor[q])
    b.set_link(i, na, A, b.factor[q])
    b.rate[j], b.rate[i] = q, q
    b.labels[(i, j1.point)] = na
    b.seg(b.pole, out, "absolute", f"v_{j1.point}{j}", abs(snap.v(j, A)))
    sd2, _ = snap.slide(j2)
    sd3, _ = snap.slide(j3)
    b.seg(out, na, "sliding", f"v_{j1.point}{i}{j1.point}{j}", abs(sd2))
    if nq != b.pole:
        b.seg(nq, out, "sliding", f"v_{j1.point}{j}{j1.point}{q}", abs(sd3))


_VEL = {"RRR": _v_rrr, "RRP": _v_rrp, "RPR": _v_rpr, "PRP": _v_prp, "RPP": _v_rpp}
