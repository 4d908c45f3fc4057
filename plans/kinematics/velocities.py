"""The velocity plan: the crank's known vector, then each dyad's two lines intersected.

A function per dyad kind, over arrays of cases, drawn by a pencil (:mod:`plans.kinematics.dyads`);
the dyad's points and how its links take the point found are its shape's
(:mod:`plans.kinematics.dyad_shapes`), shared with the acceleration plan.
"""

from __future__ import annotations

import numpy as np

from plans.kinematics.cases import sign
from plans.kinematics.dyad_shapes import PRP, RPP, RPR, RRP, RRR, Crank, each_group
from plans.kinematics.dyads import Builder, Pencil, Scheme, coincident, lab, meet, rel_seg
from plans.kinematics.structure import Group, TriadGroup
from plans.phrases import phrase


def velocity_plan(snap: Scheme, mu: float, pencil: Pencil, protocol: bool = False) -> Builder:
    b = Builder(snap, "velocity", mu, pencil, protocol)
    c = Crank(snap)
    A_name, w1, l1 = c.A, c.driver.omega, c.l1
    a_xy = pencil.vector(mu * abs(w1) * l1, 1j * sign(w1) * (c.PA - c.PO), l1, lab(A_name))
    b.add(lab(A_name), a_xy)
    b.ref = abs(a_xy) / mu
    b.step("lay off", (b.pole,), lab(A_name), lambda: phrase(
        "v_crank", A=A_name, O=c.O, w=abs(w1), l=b.s(l1), v=abs(w1) * b.s(l1), pole=b.pole, a=lab(A_name),
        mm=abs(b.s(a_xy)), mu=mu))
    c.known(b, lab(A_name), mu * 1j * w1 + 0 * c.PA)
    b.seg(b.pole, lab(A_name), "absolute", f"v_{A_name}", abs(snap.v(c.driver.link, c.PA)))

    def triad(g: TriadGroup) -> None:
        from plans.kinematics.triad_plans import v_triad

        v_triad(b, g)

    each_group(b, lambda g: _VEL[g.kind](b, g), triad)
    return b


def _exact_v(b: Builder, link: int, X: np.ndarray) -> np.ndarray:
    return b.mu * b.snap.v(link, X)


def _v_rrr(b: Builder, g: Group) -> None:
    snap, d = b.snap, RRR(b, g)
    j1, j2, j3, B = d.j1, d.j2, d.j3, d.B
    L1 = b.line(d.x1, 1j * (B - d.P1), abs(B - d.P1), f"⟂ {j1.point}{j2.point}")
    L3 = b.line(d.x3, 1j * (B - d.P3), abs(B - d.P3), f"⟂ {j3.point}{j2.point}")
    xb = meet(b, g, L1, L3, d.out, _exact_v(b, d.i, B), j2.point, (d.i, d.j))
    b.step("intersect", (d.n1, d.n3), d.out, lambda: phrase(
        "v_rrr", A=j1.point, B=j2.point, C=j3.point, n1=d.n1, n3=d.n3, out=d.out))
    d.take(b, xb, d.n1, d.n3)
    b.seg(b.pole, d.out, "absolute", f"v_{j2.point}", abs(snap.v(d.i, B)))
    rel_seg(b, d.n1, d.out, j1.point, j2.point, abs(snap.v(d.i, B) - snap.v(d.p, d.P1)))
    rel_seg(b, d.n3, d.out, j3.point, j2.point, abs(snap.v(d.j, B) - snap.v(d.q, d.P3)))


def _v_rrp(b: Builder, g: Group) -> None:
    snap, d = b.snap, RRP(b, g)
    j1, j2, B, q = d.j1, d.j2, d.B, d.q
    nq, xq = coincident(b, q, j2.point, B)
    L1 = b.line(d.x1, 1j * (B - d.P1), abs(B - d.P1), f"⟂ {j1.point}{j2.point}")
    L3 = b.line(xq, d.u, d.span, f"∥ guide of {j2.point}")
    xb = meet(b, g, L1, L3, d.out, _exact_v(b, d.i, B), j2.point, (d.i, d.j))
    b.step("intersect", (d.n1, nq), d.out, lambda: phrase(
        "v_rrp", A=j1.point, B=j2.point, n1=d.n1, nq=nq, out=d.out))
    d.take(b, xb, d.n1)
    b.seg(b.pole, d.out, "absolute", f"v_{j2.point}", abs(snap.v(d.i, B)))
    rel_seg(b, d.n1, d.out, j1.point, j2.point, abs(snap.v(d.i, B) - snap.v(d.p, d.P1)))
    if q != snap.scene.frame:
        sd, _ = snap.slide(d.j3)
        b.seg(nq, d.out, "sliding", f"v_{j2.point}{d.j}{j2.point}{q}", abs(sd))


def _v_rpr(b: Builder, g: Group) -> None:
    snap, d = b.snap, RPR(b, g)
    i, j, j1, j3, A, Cq = d.i, d.j, d.j1, d.j3, d.A, d.Cq
    L1 = b.line(d.xc, 1j * (A - Cq), abs(A - Cq), f"⟂ {j3.point}{j1.point}")
    L2 = b.line(d.xa, d.u, d.span, f"∥ slot of link {j}")
    x3 = meet(b, g, L1, L2, d.out, _exact_v(b, j, A), j1.point, ())
    b.step("intersect", (d.nc, d.na), d.out, lambda: phrase(
        "v_rpr", A=j1.point, C=j3.point, i=i, j=j, out=d.out))
    d.take(b, x3, d.nc)
    b.seg(b.pole, d.out, "absolute", f"v_{j1.point}{j}", abs(snap.v(j, A)))
    rel_seg(b, d.nc, d.out, j3.point, f"{j1.point}{j}", abs(snap.v(j, A) - snap.v(d.q, Cq)))
    sd, _ = snap.slide(d.j2)
    b.seg(d.out, d.na, "sliding", f"v_{j1.point}{i}{j1.point}{j}", abs(sd))


def _v_prp(b: Builder, g: Group) -> None:
    snap, d = b.snap, PRP(b, g)
    i, j, p, q, j2, B = d.i, d.j, d.p, d.q, d.j2, d.B
    n1, x1 = coincident(b, p, j2.point, B)
    n3, x3 = coincident(b, q, j2.point, B)
    L1 = b.line(x1, d.u1, d.span1, f"∥ guide of link {i}")
    L3 = b.line(x3, d.u3, d.span3, f"∥ guide of link {j}")
    meet(b, g, L1, L3, d.out, _exact_v(b, i, B), j2.point, (i, j))
    b.step("intersect", (n1, n3), d.out, lambda: phrase(
        "v_prp", B=j2.point, p=p, q=q, i=i, j=j, out=d.out))
    d.take(b)
    b.seg(b.pole, d.out, "absolute", f"v_{j2.point}", abs(snap.v(i, B)))
    sd1, _ = snap.slide(d.j1)
    sd3, _ = snap.slide(d.j3)
    if n1 != b.pole:
        b.seg(n1, d.out, "sliding", f"v_{j2.point}{i}{j2.point}{p}", abs(sd1))
    if n3 != b.pole:
        b.seg(n3, d.out, "sliding", f"v_{j2.point}{j}{j2.point}{q}", abs(sd3))


def _v_rpp(b: Builder, g: Group) -> None:
    snap, d = b.snap, RPP(b, g)
    i, j, q, j1, A = d.i, d.j, d.q, d.j1, d.A
    L3 = b.line(d.xq, d.u3, d.span3, f"∥ guide of link {j}")
    L2 = b.line(d.xa, d.u2, d.span2, f"∥ slot of link {j}")
    meet(b, g, L3, L2, d.out, _exact_v(b, j, A), j1.point, ())
    b.step("intersect", (d.nq, d.na), d.out, lambda: phrase(
        "v_rpp", A=j1.point, q=q, i=i, j=j, out=d.out))
    d.take(b)
    b.seg(b.pole, d.out, "absolute", f"v_{j1.point}{j}", abs(snap.v(j, A)))
    sd2, _ = snap.slide(d.j2)
    sd3, _ = snap.slide(d.j3)
    b.seg(d.out, d.na, "sliding", f"v_{j1.point}{i}{j1.point}{j}", abs(sd2))
    if d.nq != b.pole:
        b.seg(d.nq, d.out, "sliding", f"v_{j1.point}{j}{j1.point}{q}", abs(sd3))


_VEL = {"RRR": _v_rrr, "RRP": _v_rrp, "RPR": _v_rpr, "PRP": _v_prp, "RPP": _v_rpp}
