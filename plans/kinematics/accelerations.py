"""The acceleration plan: the crank's known vector, normal and Coriolis components computed
from what the velocity plan shows, then each dyad's two lines intersected.

Each dyad's construction is the velocity plan's with the normal and Coriolis terms laid
off first: the same shape (:mod:`plans.kinematics.dyad_shapes`), the same pencil.
"""

from __future__ import annotations

import numpy as np

from plans.kinematics.cases import sign
from plans.kinematics.dyad_shapes import PRP, RPP, RPR, RRP, RRR, Crank, each_group
from plans.kinematics.dyads import (
    Builder,
    Pencil,
    Scheme,
    coincident,
    lab,
    lay_coriolis,
    lay_normal,
    meet,
)
from plans.kinematics.structure import Group, TriadGroup
from plans.phrases import phrase


class _VelReader:
    """What the acceleration plan takes from the velocity plan already drawn."""

    def __init__(self, vb: Builder) -> None:
        self.vb = vb

    def omega(self, link: int) -> np.ndarray:
        return self.vb.rates[link]

    def rel(self, a: str, b: str) -> np.ndarray:
        """Velocity vector from plan point a to plan point b, in m/s."""
        return (self.vb.pts[b] - self.vb.pts[a]) / self.vb.mu


def acceleration_plan(snap: Scheme, mu: float, vb: Builder, pencil: Pencil, protocol: bool = False) -> Builder:
    b = Builder(snap, "acceleration", mu, pencil, protocol)
    vr = _VelReader(vb)
    c = Crank(snap)
    O, A_name, w1, e1, l1 = c.O, c.A, c.driver.omega, c.driver.eps, c.l1
    a_lab = lab(A_name)
    an = pencil.vector(mu * w1**2 * l1, c.PO - c.PA, l1, f"n_{A_name}{O}" if e1 != 0.0 else a_lab)
    at = pencil.vector(mu * abs(e1) * l1, 1j * sign(e1) * (c.PA - c.PO), l1, a_lab) if e1 != 0.0 else 0 * an
    if e1 != 0.0:
        b.add(f"n_{A_name}{O}", an)
        b.step("lay off", (b.pole,), f"n_{A_name}{O}", lambda: phrase(
            "a_crank_n", A=A_name, O=O, an=w1**2 * b.s(l1), mm=abs(b.s(an)), mu=mu))
        b.add(a_lab, an + at)
        b.step("lay off", (f"n_{A_name}{O}",), a_lab, lambda: phrase(
            "a_crank_t", A=A_name, O=O, at=abs(e1) * b.s(l1), mm=abs(b.s(at))))
        b.seg(b.pole, f"n_{A_name}{O}", "normal", f"a_{A_name}{O}^n", w1**2 * l1)
        b.seg(f"n_{A_name}{O}", a_lab, "tangential", f"a_{A_name}{O}^τ", abs(e1) * l1)
    else:
        b.add(a_lab, an)
        b.step("lay off", (b.pole,), a_lab, lambda: phrase(
            "a_crank", A=A_name, O=O, an=w1**2 * b.s(l1), mm=abs(b.s(an)), mu=mu))
    b.ref = abs(an + at) / mu
    c.known(b, a_lab, mu * (1j * e1 - w1**2) + 0 * c.PA)
    b.seg(b.pole, a_lab, "absolute", f"a_{A_name}", abs(snap.a(c.driver.link, c.PA)))

    def triad(g: TriadGroup) -> None:
        from plans.kinematics.triad_plans import a_triad

        a_triad(b, g, vr)

    each_group(b, lambda g: _ACC[g.kind](b, g, vr), triad)
    return b


def _a_rrr(b: Builder, g: Group, vr: _VelReader) -> None:
    snap, d = b.snap, RRR(b, g)
    i, j, j1, j2, j3, B = d.i, d.j, d.j1, d.j2, d.j3, d.B
    m1, y1 = lay_normal(b, vr, i, d.n1, d.x1, d.P1, B, j1.point, j2.point)
    m3, y3 = lay_normal(b, vr, j, d.n3, d.x3, d.P3, B, j3.point, j2.point)
    L1 = b.line(y1, 1j * (B - d.P1), abs(B - d.P1), f"⟂ {j1.point}{j2.point}")
    L3 = b.line(y3, 1j * (B - d.P3), abs(B - d.P3), f"⟂ {j3.point}{j2.point}")
    xb = meet(b, g, L1, L3, d.out, b.mu * snap.a(i, B), j2.point, (i, j))
    b.step("intersect", (m1, m3), d.out, lambda: phrase(
        "a_rrr", A=j1.point, B=j2.point, C=j3.point, m1=m1, m3=m3, out=d.out))
    d.take(b, xb, m1, m3)
    b.seg(m1, d.out, "tangential", f"a_{j2.point}{j1.point}^τ", abs(snap.e[i]) * abs(B - d.P1))
    b.seg(m3, d.out, "tangential", f"a_{j2.point}{j3.point}^τ", abs(snap.e[j]) * abs(B - d.P3))
    b.seg(b.pole, d.out, "absolute", f"a_{j2.point}", abs(snap.a(i, B)))


def _a_rrp(b: Builder, g: Group, vr: _VelReader) -> None:
    snap, d = b.snap, RRP(b, g)
    i, j, q, j1, j2, B = d.i, d.j, d.q, d.j1, d.j2, d.B
    m1, y1 = lay_normal(b, vr, i, d.n1, d.x1, d.P1, B, j1.point, j2.point)
    nq, xq = coincident(b, q, j2.point, B)
    start, start_xy = nq, xq
    if q != snap.scene.frame:
        v_rel = vr.rel(f"{lab(j2.point)}{q}", lab(j2.point))
        sd, _ = snap.slide(d.j3)
        start, start_xy = lay_coriolis(b, vr, q, v_rel, nq, xq, f"{j2.point}{j}{j2.point}{q}",
                                    abs(2 * snap.w[q] * sd))
    L1 = b.line(y1, 1j * (B - d.P1), abs(B - d.P1), f"⟂ {j1.point}{j2.point}")
    L3 = b.line(start_xy, d.u, d.span, f"∥ guide of {j2.point}")
    xb = meet(b, g, L1, L3, d.out, b.mu * snap.a(i, B), j2.point, (i, j))
    b.step("intersect", (m1, start), d.out, lambda: phrase(
        "a_rrp", A=j1.point, B=j2.point, m1=m1, start=start, out=d.out))
    d.take(b, xb, m1)
    b.seg(m1, d.out, "tangential", f"a_{j2.point}{j1.point}^τ", abs(snap.e[i]) * abs(B - d.P1))
    b.seg(b.pole, d.out, "absolute", f"a_{j2.point}", abs(snap.a(i, B)))
    if q != snap.scene.frame:
        _, sdd = snap.slide(d.j3)
        b.seg(start, d.out, "sliding", f"a^r_{j2.point}{j}{j2.point}{q}", abs(sdd))


def _a_rpr(b: Builder, g: Group, vr: _VelReader) -> None:
    snap, d = b.snap, RPR(b, g)
    i, j, j1, j3, A, Cq = d.i, d.j, d.j1, d.j3, d.A, d.Cq
    An = f"{j1.point}{j}"
    mc, yc = lay_normal(b, vr, j, d.nc, d.xc, Cq, A, j3.point, An)
    # a_A3 = a_A2 + a^k_A3A2 + a^r_A3A2, v_A3A2 read from the velocity plan (a2 -> a3)
    v_rel = vr.rel(lab(j1.point), d.out)
    sd, sdd = snap.slide(d.j2)
    mk, yk = lay_coriolis(b, vr, j, v_rel, d.na, d.xa, f"{j1.point}{j}{j1.point}{i}", abs(2 * snap.w[j] * sd))
    L1 = b.line(yc, 1j * (A - Cq), abs(A - Cq), f"⟂ {j3.point}{j1.point}")
    L2 = b.line(yk, d.u, d.span, f"∥ slot of link {j}")
    x3 = meet(b, g, L1, L2, d.out, b.mu * snap.a(j, A), j1.point, ())
    b.step("intersect", (mc, mk), d.out, lambda: phrase(
        "a_rpr", An=An, A=j1.point, C=j3.point, mc=mc, mk=mk, out=d.out))
    d.take(b, x3, mc)
    b.seg(mc, d.out, "tangential", f"a_{An}{j3.point}^τ", abs(snap.e[j]) * abs(A - Cq))
    b.seg(mk, d.out, "sliding", f"a^r_{j1.point}{j}{j1.point}{i}", abs(sdd))
    b.seg(b.pole, d.out, "absolute", f"a_{An}", abs(snap.a(j, A)))


def _a_prp(b: Builder, g: Group, vr: _VelReader) -> None:
    snap, d = b.snap, PRP(b, g)
    i, j, p, q, j2, B, out = d.i, d.j, d.p, d.q, d.j2, d.B, d.out
    ends = []
    for jt, carrier, link in ((d.j1, p, i), (d.j3, q, j)):
        nm, xy = coincident(b, carrier, j2.point, B)
        if carrier != snap.scene.frame:
            v_rel = vr.rel(f"{lab(j2.point)}{carrier}", out)
            sd, _ = snap.slide(jt)
            nm, xy = lay_coriolis(b, vr, carrier, v_rel, nm, xy, f"{j2.point}{link}{j2.point}{carrier}",
                               abs(2 * snap.w[carrier] * sd))
        ends.append((nm, xy))
    L1 = b.line(ends[0][1], d.u1, d.span1, f"∥ guide of link {i}")
    L3 = b.line(ends[1][1], d.u3, d.span3, f"∥ guide of link {j}")
    meet(b, g, L1, L3, out, b.mu * snap.a(i, B), j2.point, (i, j))
    b.step("intersect", (ends[0][0], ends[1][0]), out, lambda: phrase(
        "a_prp", e0=ends[0][0], e1=ends[1][0], i=i, j=j, out=out))
    d.take(b)
    b.seg(b.pole, out, "absolute", f"a_{j2.point}", abs(snap.a(i, B)))
    for (nm, _), jt, carrier, link in ((ends[0], d.j1, p, i), (ends[1], d.j3, q, j)):
        if nm != b.pole:
            _, sdd = snap.slide(jt)
            b.seg(nm, out, "sliding", f"a^r_{j2.point}{link}{j2.point}{carrier}", abs(sdd))


def _a_rpp(b: Builder, g: Group, vr: _VelReader) -> None:
    snap, d = b.snap, RPP(b, g)
    i, j, q, j1, A, out = d.i, d.j, d.q, d.j1, d.A, d.out
    s3, y3 = d.nq, d.xq
    if q != snap.scene.frame:
        v_rel = vr.rel(f"{lab(j1.point)}{q}", out)
        sd3, _ = snap.slide(d.j3)
        s3, y3 = lay_coriolis(b, vr, q, v_rel, d.nq, d.xq, f"{j1.point}{j}{j1.point}{q}", abs(2 * snap.w[q] * sd3))
    # a_Aj = a_Ai + a^k_AjAi + a^r_AjAi, v_AjAi from the velocity plan (a -> aj)
    v_rel2 = vr.rel(lab(j1.point), out)
    sd2, sdd2 = snap.slide(d.j2)
    s2, y2 = d.na, d.xa
    if q != snap.scene.frame or b.xp.any(snap.w.get(j, 0.0) != 0.0):
        s2, y2 = lay_coriolis(b, vr, j, v_rel2, d.na, d.xa, f"{j1.point}{j}{j1.point}{i}", abs(2 * snap.w[j] * sd2))
    L3 = b.line(y3, d.u3, d.span3, f"∥ guide of link {j}")
    L2 = b.line(y2, d.u2, d.span2, f"∥ slot of link {j}")
    meet(b, g, L3, L2, out, b.mu * snap.a(j, A), j1.point, ())
    b.step("intersect", (s3, s2), out, lambda: phrase("a_rpp", s3=s3, s2=s2, j=j, out=out))
    d.take(b)
    b.seg(b.pole, out, "absolute", f"a_{j1.point}{j}", abs(snap.a(j, A)))
    b.seg(s2, out, "sliding", f"a^r_{j1.point}{j}{j1.point}{i}", abs(sdd2))


_ACC = {"RRR": _a_rrr, "RRP": _a_rrp, "RPR": _a_rpr, "PRP": _a_prp, "RPP": _a_rpp}
