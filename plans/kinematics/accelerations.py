"""The acceleration plan: the crank's known vector, normal and Coriolis components computed
from what the velocity plan shows, then each dyad's two lines intersected.

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
    lay_coriolis,
    lay_normal,
    link_points,
    meet,
    read_rates,
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
    d = snap.scene.driver
    crank = snap.scene.links[d.link]
    O, A_name = d.pivot, crank.axis[1]
    Opos, Apos = snap.pos(d.link, O), snap.pos(d.link, A_name)
    w1, e1 = d.omega, d.eps
    l1 = abs(Apos - Opos)
    a_lab = lab(A_name)
    an = pencil.vector(mu * w1**2 * l1, Opos - Apos, l1, f"n_{A_name}{O}" if e1 != 0.0 else a_lab)
    at = pencil.vector(mu * abs(e1) * l1, 1j * sign(e1) * (Apos - Opos), l1, a_lab) if e1 != 0.0 else 0 * an
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
    b.labels[(d.link, A_name)] = a_lab
    b.labels[(d.link, O)] = b.pole
    b.ref = abs(an + at) / mu
    b.set_link(d.link, a_lab, Apos, mu * (1j * e1 - w1**2) + 0 * Apos)
    b.seg(b.pole, a_lab, "absolute", f"a_{A_name}", abs(snap.a(d.link, Apos)))
    link_points(b, d.link)
    for g in snap.kin.structure.groups:
        if isinstance(g, TriadGroup):  # class III: by Assur's special point
            from plans.kinematics.triad_plans import a_triad

            a_triad(b, g, vr)
        else:
            _ACC[g.kind](b, g, vr)
        for lid in g.links:
            link_points(b, lid)
    read_rates(b)
    return b


def _a_rrr(b: Builder, g: Group, vr: _VelReader) -> None:
    snap = b.snap
    i, j = g.links
    j1, j2, j3 = g.joints
    p, q = g.known
    P1, B, P3 = snap.pos(p, j1.point), snap.pos(i, j2.point), snap.pos(q, j3.point)
    x1, x3 = b.image(p, j1.point), b.image(q, j3.point)
    n1 = ensure(b, p, j1.point, x1)
    n3 = ensure(b, q, j3.point, x3)
    m1, y1 = lay_normal(b, vr, i, n1, x1, P1, B, j1.point, j2.point)
    m3, y3 = lay_normal(b, vr, j, n3, x3, P3, B, j3.point, j2.point)
    L1 = b.line(y1, 1j * (B - P1), abs(B - P1), f"⟂ {j1.point}{j2.point}")
    L3 = b.line(y3, 1j * (B - P3), abs(B - P3), f"⟂ {j3.point}{j2.point}")
    out = lab(j2.point)
    xb = meet(b, g, L1, L3, out, b.mu * snap.a(i, B), j2.point, (i, j))
    b.step("intersect", (m1, m3), out, lambda: phrase(
        "a_rrr", A=j1.point, B=j2.point, C=j3.point, m1=m1, m3=m3, out=out))
    b.set_link(i, out, B, (xb - x1) / (B - P1))
    b.set_link(j, out, B, (xb - x3) / (B - P3))
    b.rate[i], b.rate[j] = (m1, out, abs(B - P1)), (m3, out, abs(B - P3))
    b.seg(m1, out, "tangential", f"a_{j2.point}{j1.point}^τ", abs(snap.e[i]) * abs(B - P1))
    b.seg(m3, out, "tangential", f"a_{j2.point}{j3.point}^τ", abs(snap.e[j]) * abs(B - P3))
    b.seg(b.pole, out, "absolute", f"a_{j2.point}", abs(snap.a(i, B)))


def _a_rrp(b: Builder, g: Group, vr: _VelReader) -> None:
    snap = b.snap
    i, j = g.links
    j1, j2, j3 = g.joints
    p, q = g.known
    P1, B = snap.pos(p, j1.point), snap.pos(i, j2.point)
    u, span = snap.guide(j3)
    x1 = b.image(p, j1.point)
    n1 = ensure(b, p, j1.point, x1)
    m1, y1 = lay_normal(b, vr, i, n1, x1, P1, B, j1.point, j2.point)
    nq, xq = coincident(b, q, j2.point, B)
    start, start_xy = nq, xq
    if q != snap.scene.frame:
        v_rel = vr.rel(f"{lab(j2.point)}{q}", lab(j2.point))
        sd, _ = snap.slide(j3)
        start, start_xy = lay_coriolis(b, vr, q, v_rel, nq, xq, f"{j2.point}{j}{j2.point}{q}",
                                    abs(2 * snap.w[q] * sd))
    L1 = b.line(y1, 1j * (B - P1), abs(B - P1), f"⟂ {j1.point}{j2.point}")
    L3 = b.line(start_xy, u, span, f"∥ guide of {j2.point}")
    out = lab(j2.point)
    xb = meet(b, g, L1, L3, out, b.mu * snap.a(i, B), j2.point, (i, j))
    b.step("intersect", (m1, start), out, lambda: phrase(
        "a_rrp", A=j1.point, B=j2.point, m1=m1, start=start, out=out))
    b.set_link(i, out, B, (xb - x1) / (B - P1))
    b.set_link(j, out, B, b.factor[q])
    b.rate[i], b.rate[j] = (m1, out, abs(B - P1)), q
    b.seg(m1, out, "tangential", f"a_{j2.point}{j1.point}^τ", abs(snap.e[i]) * abs(B - P1))
    b.seg(b.pole, out, "absolute", f"a_{j2.point}", abs(snap.a(i, B)))
    if q != snap.scene.frame:
        _, sdd = snap.slide(j3)
        b.seg(start, out, "sliding", f"a^r_{j2.point}{j}{j2.point}{q}", abs(sdd))


def _a_rpr(b: Builder, g: Group, vr: _VelReader) -> None:
    snap = b.snap
    i, j = g.links
    j1, j2, j3 = g.joints
    p, q = g.known
    A, Cq = snap.pos(p, j1.point), snap.pos(q, j3.point)
    u, span = snap.guide(j2)
    xa, xc = b.image(p, j1.point), b.image(q, j3.point)
    na = ensure(b, p, j1.point, xa)
    nc = ensure(b, q, j3.point, xc)
    An = f"{j1.point}{j}"
    mc, yc = lay_normal(b, vr, j, nc, xc, Cq, A, j3.point, An)
    # a_A3 = a_A2 + a^k_A3A2 + a^r_A3A2, v_A3A2 read from the velocity plan (a2 -> a3)
    v_rel = vr.rel(lab(j1.point), f"{lab(j1.point)}{j}")
    sd, sdd = snap.slide(j2)
    mk, yk = lay_coriolis(b, vr, j, v_rel, na, xa, f"{j1.point}{j}{j1.point}{i}", abs(2 * snap.w[j] * sd))
    L1 = b.line(yc, 1j * (A - Cq), abs(A - Cq), f"⟂ {j3.point}{j1.point}")
    L2 = b.line(yk, u, span, f"∥ slot of link {j}")
    out = f"{lab(j1.point)}{j}"
    x3 = meet(b, g, L1, L2, out, b.mu * snap.a(j, A), j1.point, ())
    b.step("intersect", (mc, mk), out, lambda: phrase(
        "a_rpr", An=An, A=j1.point, C=j3.point, mc=mc, mk=mk, out=out))
    f = (x3 - xc) / (A - Cq)
    b.set_link(j, out, A, f)
    b.set_link(i, na, A, f)
    b.rate[j], b.rate[i] = (mc, out, abs(A - Cq)), j
    b.labels[(i, j1.point)] = na
    b.seg(mc, out, "tangential", f"a_{An}{j3.point}^τ", abs(snap.e[j]) * abs(A - Cq))
    b.seg(mk, out, "sliding", f"a^r_{j1.point}{j}{j1.point}{i}", abs(sdd))
    b.seg(b.pole, out, "absolute", f"a_{An}", abs(snap.a(j, A)))


def _a_prp(b: Builder, g: Group, vr: _VelReader) -> None:
    snap = b.snap
    i, j = g.links
    j1, j2, j3 = g.joints
    p, q = g.known
    B = snap.pos(i, j2.point)
    u1, s1 = snap.guide(j1)
    u3, s3 = snap.guide(j3)
    out = lab(j2.point)
    ends = []
    for jt, carrier, link in ((j1, p, i), (j3, q, j)):
        nm, xy = coincident(b, carrier, j2.point, B)
        if carrier != snap.scene.frame:
            v_rel = vr.rel(f"{lab(j2.point)}{carrier}", out)
            sd, _ = snap.slide(jt)
            nm, xy = lay_coriolis(b, vr, carrier, v_rel, nm, xy, f"{j2.point}{link}{j2.point}{carrier}",
                               abs(2 * snap.w[carrier] * sd))
        ends.append((nm, xy))
    L1 = b.line(ends[0][1], u1, s1, f"∥ guide of link {i}")
    L3 = b.line(ends[1][1], u3, s3, f"∥ guide of link {j}")
    meet(b, g, L1, L3, out, b.mu * snap.a(i, B), j2.point, (i, j))
    b.step("intersect", (ends[0][0], ends[1][0]), out, lambda: phrase(
        "a_prp", e0=ends[0][0], e1=ends[1][0], i=i, j=j, out=out))
    b.set_link(i, out, B, b.factor[p])
    b.set_link(j, out, B, b.factor[q])
    b.rate[i], b.rate[j] = p, q
    b.seg(b.pole, out, "absolute", f"a_{j2.point}", abs(snap.a(i, B)))
    for (nm, _), jt, carrier, link in ((ends[0], j1, p, i), (ends[1], j3, q, j)):
        if nm != b.pole:
            _, sdd = snap.slide(jt)
            b.seg(nm, out, "sliding", f"a^r_{j2.point}{link}{j2.point}{carrier}", abs(sdd))


def _a_rpp(b: Builder, g: Group, vr: _VelReader) -> None:
    snap = b.snap
    i, j = g.links
    j1, j2, j3 = g.joints
    p, q = g.known
    A = snap.pos(p, j1.point)
    u2, sp2 = snap.guide(j2)
    u3, sp3 = snap.guide(j3)
    xa = b.image(p, j1.point)
    na = ensure(b, p, j1.point, xa)
    out = f"{lab(j1.point)}{j}"
    nq, xq = coincident(b, q, j1.point, A)
    s3, y3 = nq, xq
    if q != snap.scene.frame:
        v_rel = vr.rel(f"{lab(j1.point)}{q}", out)
        sd3, _ = snap.slide(j3)
        s3, y3 = lay_coriolis(b, vr, q, v_rel, nq, xq, f"{j1.point}{j}{j1.point}{q}", abs(2 * snap.w[q] * sd3))
    # a_Aj = a_Ai + a^k_AjAi + a^r_AjAi, v_AjAi from the velocity plan (a -> aj)
    v_rel2 = vr.rel(lab(j1.point), out)
    sd2, sdd2 = snap.slide(j2)
    s2, y2 = na, xa
    if q != snap.scene.frame or b.xp.any(snap.w.get(j, 0.0) != 0.0):
        s2, y2 = lay_coriolis(b, vr, j, v_rel2, na, xa, f"{j1.point}{j}{j1.point}{i}", abs(2 * snap.w[j] * sd2))
    L3 = b.line(y3, u3, sp3, f"∥ guide of link {j}")
    L2 = b.line(y2, u2, sp2, f"∥ slot of link {j}")
    meet(b, g, L3, L2, out, b.mu * snap.a(j, A), j1.point, ())
    b.step("intersect", (s3, s2), out, lambda: phrase("a_rpp", s3=s3, s2=s2, j=j, out=out))
    b.set_link(j, out, A, b.factor[q])
    b.set_link(i, na, A, b.factor[q])
    b.rate[j], b.rate[i] = q, q
    b.labels[(i, j1.point)] = na
    b.seg(b.pole, out, "absolute", f"a_{j1.point}{j}", abs(snap.a(j, A)))
    b.seg(s2, out, "sliding", f"a^r_{j1.point}{j}{j1.point}{i}", abs(sdd2))


_ACC = {"RRR": _a_rrr, "RRP": _a_rrp, "RPR": _a_rpr, "PRP": _a_prp, "RPP": _a_rpp}
