"""The force polygon of a class-III group and its moment equations, as the draftsman writes them.

With i, j the leashes whose axes give Assur's point S and m the third: from the pole lay off
R_i^τ and leash i's loads, the base link's loads, leash m's loads, R_m^τ and R_m^n (both
known), leash j's loads and R_j^τ; then the line of R_j^n (∥ axis j) through the end and the
line of R_i^n (∥ axis i) through the pole meet and close the polygon.  Each leash's own
loads and its outer reaction then close onto the base link's reaction from that leash.
"""

from __future__ import annotations

from typing import Any

from plans.forces.loads import AppliedForce, AppliedMoment
from plans.forces.shared import mu_force
from plans.forces.triad import TriadForces
from plans.kinematics.plan import Step
from plans.phrases import phrase


def triad_polygon(fa: Any, gf: TriadForces, k: int, Poly: Any, ForcePolygon: Any) -> Any:
    """The group's polygon at position k (``Poly``: the polygons' head-to-tail builder, and
    ``ForcePolygon`` their record, passed by the caller)."""
    scene = fa.scene
    g = gf.group
    phi = float(fa.kin.phi_deg[k])
    i, j, m = gf.leashes(k)
    outer, inner = gf.reactions[:3], gf.reactions[3:]
    names = [rc.name(scene.fij) for rc in outer]
    inner_names = [rc.name(scene.fij) for rc in inner]
    loads = [[(f.label, complex(f.F[k])) for f in fs] for fs in gf.loads]  # base, then leashes
    everything = [v for ls in loads for _, v in ls] + [complex(rc.F[k]) for rc in gf.reactions]
    poly = Poly(mu_force(fa, everything))

    def tau(x: int) -> complex:
        return complex(gf.tau[x][k] * 1j * gf.axes[x][k])

    def n_of(x: int) -> str:  # a slider's reaction is all along its axis: named whole
        return names[x] if gf.slider(x) else f"{names[x]}^n"

    def lay_all(items: list[tuple[str, complex]]) -> None:
        for lab, v in items:
            poly.lay(lab, v)

    poly.lay(f"{names[i]}^τ", tau(i))
    lay_all(loads[1 + i])
    end_i = poly.cur
    lay_all(loads[0])
    start_m = poly.cur
    lay_all(loads[1 + m])
    start_rm = poly.cur
    poly.lay(f"{names[m]}^τ", tau(m))
    poly.lay(n_of(m), complex(gf.normal[m][k] * gf.axes[m][k]))
    if not gf.slider(m) and poly.cur != start_rm:
        poly.join(names[m], start_rm, poly.cur, f"{names[m]}^τ + {names[m]}^n")
    end_m = poly.cur
    start_j = poly.cur
    lay_all(loads[1 + j])
    start_rj = poly.cur
    poly.lay(f"{names[j]}^τ", tau(j))
    x = poly.intersect(n_of(j), complex(gf.axes[j][k]), n_of(i), complex(gf.axes[i][k]))
    if not gf.slider(j):
        poly.join(names[j], start_rj, x, f"{names[j]}^τ + {names[j]}^n")
    if not gf.slider(i):
        poly.join(names[i], x, poly.end_of([f"{names[i]}^τ"], "o"), f"{names[i]}^n + {names[i]}^τ")
    # the base link's reactions from the leashes: each closes its leash's polygon
    for leash, a, b in ((i, x, end_i), (m, start_m, end_m), (j, start_j, x)):
        poly.join(inner_names[leash], a, b, phrase("f_closes_link", i=g.links[1 + leash]))
    return ForcePolygon(g.name, g.kind, poly.plan(phi))


def triad_steps(fa: Any, gf: TriadForces, k: int, mu_l: float, _equation: Any,
                _moment_terms: Any) -> list[tuple[Step, tuple[Any, ...]]]:
    """The moment equations: each leash's about its inner pair (its R^τ), then the whole
    group's about Assur's point S (the third leash's R^n); the protocol's writers of a moment
    equation and of its terms are passed by the caller."""
    scene, g = fa.scene, gf.group
    i, j, m = gf.leashes(k)
    outer = gf.reactions[:3]
    names = [rc.name(scene.fij) for rc in outer]
    out: list[tuple[Step, tuple[Any, ...]]] = []
    taus = []
    couples = []
    for x, (o, d) in enumerate(g.joints):
        rc = outer[x]
        P = complex(fa.kin.point(d.point, g.links[1 + x])[0][k])
        known = _moment_terms(gf.loads[1 + x], gf.moments[1 + x], P, k, mu_l)
        if d.kind == "P":  # a block in the base's slot: its loads along the slot give R^τ
            out.append((Step.of("sum", (), f"{names[x]}^τ", phrase(
                "f_block_tau", n=names[x], k=g.links[1 + x], j=g.links[0], tau=float(rc.tau[k]))), ()))
            taus.append(AppliedForce(f"{names[x]}^τ", rc.on, o.point, rc.r, rc.r * 0, rc.tau * rc.e_tau, "reaction"))
            continue
        if gf.slider(x):  # the guide's couple on the slider
            out.append(_equation("moment", (d.point,), names[x], f"ΣM_{d.point}({g.links[1 + x]})", known,
                                 phrase("m_couple_of", n=names[x], M=float(rc.M[k]))))
            couples.append(AppliedMoment(f"M{names[x][1:]}", rc.on, rc.M, "reaction"))
            continue
        Q = complex(rc.r[k])
        out.append(_equation("moment", (d.point,), f"{names[x]}^τ", f"ΣM_{d.point}({g.links[1 + x]})", known,
                             phrase("m_tau", n=names[x], A=o.point, B=d.point, l=abs(P - Q), tau=float(rc.tau[k]))))
        taus.append(AppliedForce(f"{names[x]}^τ", rc.on, o.point, rc.r, rc.r * 0, rc.tau * rc.e_tau, "reaction"))
    S = complex(gf.S[k])
    loads = [f for fs in gf.loads for f in fs] + taus
    moments = [mo for ms in gf.moments for mo in ms] + couples
    known = _moment_terms(loads, moments, S, k, mu_l)
    rm = outer[m]
    um = complex(gf.axes[m][k])
    h = abs(((complex(rm.r[k]) - S).conjugate() * um).imag)
    ax = [(o.point, d.point) for o, d in g.joints]
    if all(o.kind == "R" and d.kind == "R" for o, d in g.joints):
        what = phrase("m_triad_n", n=names[m], n1=names[i], n2=names[j], A=ax[i][0], D=ax[i][1], B=ax[j][0],
                      E=ax[j][1], C=ax[m][0], F=ax[m][1], mm=h * mu_l, h=h, N=float(gf.normal[m][k]))
    else:
        def axis(x: int) -> Any:
            if g.joints[x][1].kind == "P":
                return phrase("t_axis_slot", C=ax[x][0], j=g.links[0])
            return (phrase("t_axis_guide", F=ax[x][1]) if gf.slider(x)
                    else phrase("t_axis_leash", A=ax[x][0], D=ax[x][1]))

        def name(x: int) -> str:
            return names[x] if gf.slider(x) else f"{names[x]}^n"
        what = phrase("m_triad_ng", ax1=axis(i), ax2=axis(j), ax3=axis(m), n1=name(i), n2=name(j), n=name(m),
                      mm=h * mu_l, h=h, N=float(gf.normal[m][k]))
    out.append(_equation("moment", ("S",), names[m] if gf.slider(m) else f"{names[m]}^n", f"ΣM_S({g.name})",
                         known, what))
    return out
