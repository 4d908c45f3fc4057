"""Kinetostatics by Assur groups (Bruevich's method, seed 003), exact and at drawing scale.

d'Alembert: each link carries its inertia force Φ = −m a_S at S and inertia
moment M_Φ = −I_S ε besides gravity, gas and external loads; then every group
is in equilibrium and is solved by statics, the group farthest from the crank
first, so that the reactions it sends to earlier links are known loads there.

For each dyad (links i, j; J1 = i–p, J2 = i–j, J3 = j–q):

* RRR: F_ip = F_ip^τ + F_ip^n at A, F_jq = F_jq^τ + F_jq^n at C.  ΣM_B(i) = 0 gives
  F_ip^τ = M_i(B)/l_AB, ΣM_B(j) = 0 gives F_jq^τ; the group's polygon closes with the
  two n components (directions ∥ AB and ∥ CB intersected); F_ij closes link i's polygon.
* RRP: F_ip^τ from ΣM_B(i); the polygon closes with F_ip^n ∥ AB and the guide's
  reaction N ⟂ guide; F_ij closes link i; ΣM_B(j) places N along the guide.
* RPR: block i at A slides in j's slot.  ΣM_A(i) gives the slot's couple (zero for a
  block without moments); ΣM_C(j) gives the slot reaction ⟂ slot; F_jq closes j's polygon,
  F_ip the block's.
* PRP: both guide reactions ⟂ their guides from the group's polygon (two directions
  intersected); F_ij closes link i; each link's ΣM_B places its guide reaction.
* RPP: block i at A in j's slot, j on q's guide.  ΣM_A(i) gives the slot's couple; j's
  polygon closes with the slot reaction ⟂ slot and the guide reaction ⟂ guide (two
  directions); ΣM(j) places the guide reaction; F_ip closes the block's polygon.

Initial link: ΣM_O gives the balancing force ⟂ the crank at its point (or the balancing
moment); the frame reaction closes the crank's polygon.

Reactions are stored as "force on link ``on`` from link ``frm``" (seed 003); the
scene's ``fij`` only decides how they are named.  A prismatic pair's reaction is
a force N ⟂ guide at the slider's pin plus a couple M; its point of application
lies on the guide at offset x = M/N from the pin (undefined where N = 0).

Plane vectors are complex numbers, ``cross(a, b) = Im(conj(a)·b)``.
"""

from __future__ import annotations

from collections.abc import Callable, Iterator, Mapping
from typing import Any

import numpy as np
from numpy.typing import NDArray

from plans.errors import Locked, Said
from plans.forces.drawn_polygon import ForcePolygon, Poly, closing_point  # noqa: F401  (importable from here)
from plans.forces.loads import (
    AppliedForce,
    AppliedLoads,
    AppliedMoment,
    Loads,
    apply_loads,
    parse_loads,
)
from plans.forces.reactions import CrankForces, ForceAnalysis, GroupForces, Reaction  # noqa: F401  (importable from here)
from plans.forces.shared import force_sum, moment_about, mu_force, safe_div, unit_vector
from plans.kinematics.exact import Kinematics
from plans.kinematics.structure import Group, TriadGroup
from plans.lines import cross
from plans.phrases import phrase
from plans.scene.model import Joint, Scene
from plans.tolerances import LOCK_SIN

C = NDArray[np.complex128]
R = NDArray[np.float64]

# --------------------------------------------------------------------------- analysis


def analyse_forces(scene: Scene, kin: Kinematics, loads: Loads | None = None) -> ForceAnalysis:
    """All reactions and the balancing load, exact, vectorised over the positions of ``kin``."""
    if kin.order < 2:
        raise ValueError("force analysis needs accelerations: solve(scene, order=2)")
    loads = parse_loads(scene) if loads is None else loads
    return solve_applied(scene, kin, loads, apply_loads(scene, loads, kin))


def solve_applied(scene: Scene, kin: Kinematics, loads: Loads, applied: AppliedLoads,
                  geometry: dict | None = None) -> ForceAnalysis:
    """The groups and the crank in equilibrium under ``applied``.  Linear in the loads: a
    load's arrays may carry a leading axis (several load cases at once, by superposition).
    ``geometry``: what no load changes (each group's points, unit vectors and determinant,
    the crank's arm), kept in this dict by the first solve of these positions and read by
    the next ones (the same numbers, not worked out again)."""
    forces: dict[int, list[AppliedForce]] = {k: [] for k in scene.links}
    moments: dict[int, list[AppliedMoment]] = {k: [] for k in scene.links}
    for f in applied.forces:
        forces[f.link].append(f)
    for m in applied.moments:
        moments[m.link].append(m)
    solved: list[Any] = []  # GroupForces, or TriadForces for a class-III group
    for g in reversed(kin.structure.groups):
        if isinstance(g, TriadGroup):  # class III: by Assur's special point
            from plans.forces.triad import solve_triad

            gf = solve_triad(kin, g, forces, moments, Reaction)
        else:
            gf = _SOLVERS[g.kind](kin, g, forces, moments, geometry)
        solved.append(gf)
        # what the group sends back to the known links (F_pi = −F_ip)
        for rc in gf.reactions:
            if rc.frm == scene.frame or rc.frm in g.links:
                continue
            forces[rc.frm].append(_bound(kin, rc.frm, rc.r, -rc.F, _fname(scene, rc.frm, rc.on), rc.point,
                                         geometry, rc.joint))
            if rc.guide is not None:
                moments[rc.frm].append(AppliedMoment(f"M{_fname(scene, rc.frm, rc.on)[1:]}", rc.frm,
                                                     -rc.M, "reaction"))
    crank = _crank(scene, kin, loads, forces, moments, geometry)
    return ForceAnalysis(scene, kin, loads, applied, tuple(solved), crank)


def _fname(scene: Scene, on: int, frm: int) -> str:
    return f"F{on}{frm}" if scene.fij == "on_i_from_j" else f"F{frm}{on}"


def _bound(kin: Kinematics, link: int, r: C, F: C, label: str, point: str, geo: dict | None = None,
           joint: Joint | None = None) -> AppliedForce:
    local = _local(kin, link, r) if geo is None or joint is None else \
        _kept(geo, ("local", link, joint.name), _local, kin, link, r)
    return AppliedForce(label, link, point, r, local, F, "reaction")


def _local(kin: Kinematics, link: int, r: C) -> C:
    m = kin.motion[link]
    return (r - m.r0) * np.conj(m.rot)


def _kept(geo: dict | None, key: Any, make: Callable[..., Any], *args: Any) -> Any:
    """``make(*args)``, or what an earlier solve of the same positions kept under ``key``."""
    if geo is None:
        return make(*args)
    got = geo.get(key)
    if got is None:
        got = geo[key] = make(*args)
    return got


class _ArmsWhenRead(Mapping):
    """Lever arms worked out when first read: a drawn, printed or checked position reads
    them, the analysis never does."""

    __slots__ = ("_make", "_done")

    def __init__(self, make: Callable[[], dict]) -> None:
        self._make = make
        self._done: dict | None = None

    def _arms(self) -> dict:
        if self._done is None:
            self._done = self._make()
        return self._done

    def __getitem__(self, key: Any) -> R:
        return self._arms()[key]

    def __iter__(self) -> Iterator:
        return iter(self._arms())

    def __len__(self) -> int:
        return len(self._arms())


def _arms(eq: str, fs, P: C) -> dict[tuple[str, str], R]:
    """Lever arms h = |cross(r − P, F)|/|F| of each force about P (0 for a zero force)."""
    out = {}
    for f in fs:
        mag = np.abs(f.F)
        out[(eq, f.label)] = safe_div(np.abs(cross(f.r - P, f.F)), mag)
    return out


def _guide(kin: Kinematics, jt: Joint) -> C:
    assert jt.guide is not None
    return kin.motion[jt.guide.link].rot * jt.guide.direction


def _check(kin: Kinematics, g: Group, det: R, scale: R | float, point: str) -> None:
    bad = np.abs(det) <= LOCK_SIN * scale
    if bad.any():
        k = int(np.flatnonzero(bad)[0])
        raise Locked(Said("fp_two_unknown_reaction"),
                     group=f"{g.kind} {g.name}", point=point, phi_deg=float(kin.phi_deg[k]))


def _solve2(c1: C, c2: C, rhs: C, det: R | None = None) -> tuple[R, R]:
    if det is None:
        det = cross(c1, c2)
    return cross(rhs, c2) / det, cross(c1, rhs) / det


def _rrr_geometry(kin: Kinematics, g: Group) -> tuple:
    i, j = g.links
    j1, j2, j3 = g.joints
    A = kin.point(j1.point, i)[0]
    B = kin.point(j2.point, i)[0]
    Cc = kin.point(j3.point, j)[0]
    BA, BC = B - A, B - Cc
    ui, uj = unit_vector(BA), unit_vector(BC)
    det = cross(ui, uj)
    _check(kin, g, det, 1.0, j2.point)
    return A, B, Cc, ui, uj, np.abs(BA), np.abs(BC), 1j * ui, 1j * uj, det


def _rrr(kin: Kinematics, g: Group, forces, moments, geo: dict | None = None) -> GroupForces:
    i, j = g.links
    j1, j2, j3 = g.joints
    p, q = g.known
    n = kin.n
    A, B, Cc, ui, uj, li, lj, ei, ej, det = _kept(geo, g.name, _rrr_geometry, kin, g)
    fi, fj, mi, mj = forces[i], forces[j], moments[i], moments[j]
    t_i = moment_about(fi, mi, B, n) / li  # ΣM_B(i): −l·F^τ + M_i(B) = 0
    t_j = moment_about(fj, mj, B, n) / lj
    sum_i = force_sum(fi, n)
    rest = sum_i + force_sum(fj, n) + t_i * ei + t_j * ej
    n_i, n_j = _solve2(ui, uj, -rest, det)
    F_ip = t_i * ei + n_i * ui
    F_jq = t_j * ej + n_j * uj
    F_ij = -sum_i - F_ip
    zero = np.zeros(n)
    ti, tj = tuple(fi), tuple(fj)
    arms = _ArmsWhenRead(lambda: _arms(f"M_{j2.point}({i})", ti, B) | _arms(f"M_{j2.point}({j})", tj, B))
    return GroupForces(g, tuple(fi), tuple(fj), tuple(mi), tuple(mj), (
        Reaction(j1, i, p, A, F_ip, zero, tau=t_i, n=n_i, e_tau=ei, e_n=ui),
        Reaction(j2, i, j, B, F_ij, zero),
        Reaction(j3, j, q, Cc, F_jq, zero, tau=t_j, n=n_j, e_tau=ej, e_n=uj),
    ), arms)


def _rrp_geometry(kin: Kinematics, g: Group) -> tuple:
    i, _ = g.links
    j1, j2, j3 = g.joints
    A = kin.point(j1.point, i)[0]
    B = kin.point(j2.point, i)[0]
    BA = B - A
    ui = unit_vector(BA)
    u3 = _guide(kin, j3)
    n3 = 1j * u3
    det = cross(ui, n3)
    _check(kin, g, det, 1.0, j2.point)
    return A, B, ui, np.abs(BA), 1j * ui, u3, n3, det


def _rrp(kin: Kinematics, g: Group, forces, moments, geo: dict | None = None) -> GroupForces:
    i, j = g.links
    j1, j2, j3 = g.joints
    p, q = g.known
    n = kin.n
    A, B, ui, li, ei, u3, n3, det = _kept(geo, g.name, _rrp_geometry, kin, g)
    fi, fj, mi, mj = forces[i], forces[j], moments[i], moments[j]
    t_i = moment_about(fi, mi, B, n) / li
    sum_i = force_sum(fi, n)
    rest = sum_i + force_sum(fj, n) + t_i * ei
    n_i, N = _solve2(ui, n3, -rest, det)
    F_ip = t_i * ei + n_i * ui
    F_ij = -sum_i - F_ip
    M_jq = -moment_about(fj, mj, B, n)  # ΣM_B(j): the guide's couple; F_ji and N pass through B
    zero = np.zeros(n)
    ti = tuple(fi)
    arms = _ArmsWhenRead(lambda: _arms(f"M_{j2.point}({i})", ti, B))
    return GroupForces(g, ti, tuple(fj), tuple(mi), tuple(mj), (
        Reaction(j1, i, p, A, F_ip, zero, tau=t_i, n=n_i, e_tau=ei, e_n=ui),
        Reaction(j2, i, j, B, F_ij, zero),
        Reaction(j3, j, q, B, N * n3, M_jq, guide=u3),
    ), arms)


def _rpr_geometry(kin: Kinematics, g: Group) -> tuple:
    i, j = g.links
    j1, j2, j3 = g.joints
    A = kin.point(j1.point, i)[0]
    Cc = kin.point(j3.point, j)[0]
    us = _guide(kin, j2)
    ns = 1j * us
    arm = cross(A - Cc, ns)  # ΣM_C(j): M_j(C) − N·arm − M_ij = 0 (F_ji = −N n_s at A)
    _check(kin, g, arm, np.abs(A - Cc), j2.point)
    return A, Cc, us, ns, arm


def _rpr(kin: Kinematics, g: Group, forces, moments, geo: dict | None = None) -> GroupForces:
    i, j = g.links
    j1, j2, j3 = g.joints
    p, q = g.known
    n = kin.n
    A, Cc, us, ns, arm = _kept(geo, g.name, _rpr_geometry, kin, g)
    fi, fj, mi, mj = forces[i], forces[j], moments[i], moments[j]
    M_ij = -moment_about(fi, mi, A, n)  # ΣM_A(block): the slot's couple on the block
    N = (moment_about(fj, mj, Cc, n) - M_ij) / arm
    F_ij = N * ns
    F_jq = -force_sum(fj, n) + F_ij
    F_ip = -force_sum(fi, n) - F_ij
    zero = np.zeros(n)
    arms = _arms(f"M_{j3.point}({j})", fj, Cc)
    arms[(f"M_{j3.point}({j})", _fname(kin.scene, j, i))] = np.abs(arm)
    return GroupForces(g, tuple(fi), tuple(fj), tuple(mi), tuple(mj), (
        Reaction(j1, i, p, A, F_ip, zero),
        Reaction(j2, i, j, A, F_ij, M_ij, guide=us),
        Reaction(j3, j, q, Cc, F_jq, zero),
    ), arms)


def _prp_geometry(kin: Kinematics, g: Group) -> tuple:
    i, _ = g.links
    j1, j2, j3 = g.joints
    B = kin.point(j2.point, i)[0]
    u1, u3 = _guide(kin, j1), _guide(kin, j3)
    n1, n3 = 1j * u1, 1j * u3
    det = cross(n1, n3)
    _check(kin, g, det, 1.0, j2.point)
    return B, u1, u3, n1, n3, det


def _prp(kin: Kinematics, g: Group, forces, moments, geo: dict | None = None) -> GroupForces:
    i, j = g.links
    j1, j2, j3 = g.joints
    p, q = g.known
    n = kin.n
    B, u1, u3, n1, n3, det = _kept(geo, g.name, _prp_geometry, kin, g)
    fi, fj, mi, mj = forces[i], forces[j], moments[i], moments[j]
    N1, N3 = _solve2(n1, n3, -(force_sum(fi, n) + force_sum(fj, n)), det)
    F_ij = -force_sum(fi, n) - N1 * n1
    M1 = -moment_about(fi, mi, B, n)
    M3 = -moment_about(fj, mj, B, n)
    zero = np.zeros(n)
    return GroupForces(g, tuple(fi), tuple(fj), tuple(mi), tuple(mj), (
        Reaction(j1, i, p, B, N1 * n1, M1, guide=u1),
        Reaction(j2, i, j, B, F_ij, zero),
        Reaction(j3, j, q, B, N3 * n3, M3, guide=u3),
    ), {})


def _rpp_geometry(kin: Kinematics, g: Group) -> tuple:
    i, j = g.links
    j1, j2, j3 = g.joints
    A = kin.point(j1.point, i)[0]
    K = kin.point(j3.point, j)[0]
    u2, u3 = _guide(kin, j2), _guide(kin, j3)
    n2, n3 = 1j * u2, 1j * u3
    _check(kin, g, cross(n2, n3), 1.0, j2.point)
    return A, K, u2, u3, n2, n3, cross(-n2, n3)


def _rpp(kin: Kinematics, g: Group, forces, moments, geo: dict | None = None) -> GroupForces:
    i, j = g.links
    j1, j2, j3 = g.joints
    p, q = g.known
    n = kin.n
    A, K, u2, u3, n2, n3, det = _kept(geo, g.name, _rpp_geometry, kin, g)
    fi, fj, mi, mj = forces[i], forces[j], moments[i], moments[j]
    M_ij = -moment_about(fi, mi, A, n)  # ΣM_A(block)
    # j's polygon: F_j − N2 n2 + N3 n3 = 0 (the slot's reaction on j is −F_ij)
    N2m, N3 = _solve2(-n2, n3, -force_sum(fj, n), det)
    F_ij = N2m * n2
    # ΣM_K(j): M_j(K) + cross(A − K, −F_ij) − M_ij + M_jq = 0
    M_jq = -(moment_about(fj, mj, K, n) + cross(A - K, -F_ij) - M_ij)
    F_ip = -force_sum(fi, n) - F_ij
    zero = np.zeros(n)
    return GroupForces(g, tuple(fi), tuple(fj), tuple(mi), tuple(mj), (
        Reaction(j1, i, p, A, F_ip, zero),
        Reaction(j2, i, j, A, F_ij, M_ij, guide=u2),
        Reaction(j3, j, q, K, N3 * n3, M_jq, guide=u3),
    ), {})


_SOLVERS = {"RRR": _rrr, "RRP": _rrp, "RPR": _rpr, "PRP": _prp, "RPP": _rpp}


def _crank_geometry(scene: Scene, kin: Kinematics, loads: Loads) -> tuple:
    d = scene.driver
    O = kin.point(d.pivot, d.link)[0]
    P = kin.point(loads.balancing.point, d.link)[0]
    joint = next(jt for jt in scene.joints if set(jt.links) == {d.link, scene.frame})
    return O, P, np.abs(P - O), 1j * unit_vector(P - O), joint


def _crank(scene: Scene, kin: Kinematics, loads: Loads, forces, moments, geo: dict | None = None) -> CrankForces:
    link = scene.driver.link
    n = kin.n
    O, P, l, e, joint = _kept(geo, ("crank", loads.balancing.point), _crank_geometry, scene, kin, loads)
    f1, m1 = forces[link], moments[link]
    M_O = moment_about(f1, m1, O, n)
    if loads.balancing.kind == "force":
        F_bal = -M_O / l  # ΣM_O: F_bal·l + M_1(O) = 0
        M_bal = F_bal * l
        F_frame = -(force_sum(f1, n) + F_bal * e)
    else:
        F_bal = np.zeros(n)
        M_bal = -M_O
        F_frame = -force_sum(f1, n)
    frame = Reaction(joint, link, scene.frame, O, F_frame, np.zeros(n))
    t1 = tuple(f1)

    def arms() -> dict[str, Any]:
        out = {f.label: safe_div(np.abs(cross(f.r - O, f.F)), np.abs(f.F)) for f in t1}
        out["F_bal"] = l
        return out

    return CrankForces(link, t1, tuple(m1), loads.balancing.kind, loads.balancing.point, P, e,
                       F_bal, M_bal, frame, _ArmsWhenRead(arms))


def force_polygons(fa: ForceAnalysis, k: int) -> tuple[ForcePolygon, ...]:
    """The force polygons of position k: groups farthest first, then the crank."""
    scene = fa.scene
    phi = float(fa.kin.phi_deg[k])
    out = []
    for gf in fa.groups:
        g = gf.group
        if isinstance(g, TriadGroup):  # class III: by Assur's special point
            from plans.forces.triad_polygon import triad_polygon

            out.append(triad_polygon(fa, gf, k, Poly, ForcePolygon))
            continue
        i, j = g.links
        r1, r2, r3 = gf.reactions
        n1, n2, n3 = (rc.name(scene.fij) for rc in gf.reactions)
        li = [(f.label, complex(f.F[k])) for f in gf.loads_i]
        lj = [(f.label, complex(f.F[k])) for f in gf.loads_j]
        # a slide's friction on j laid last: then it and the guide's normal reaction make the
        # total reaction, leaning by the friction angle (F_ijΣ, drawn as their sum)
        slide_f = f"Ff{n3[1:]}" if r3.guide is not None else ""
        lj = [x for x in lj if x[0] != slide_f] + [x for x in lj if x[0] == slide_f]
        everything = [v for _, v in li + lj] + [complex(rc.F[k]) for rc in gf.reactions]
        poly = Poly(mu_force(fa, everything))
        if g.kind in ("RRR", "RRP"):
            assert r1.tau is not None and r1.e_tau is not None and r1.e_n is not None
            tau1 = f"{n1}^τ"
            poly.lay(tau1, complex(r1.tau[k] * r1.e_tau[k]))
            for lab, v in li:
                poly.lay(lab, v)
            end_i = poly.end_of([tau1] + [lab for lab, _ in li], "o")
            for lab, v in lj:
                poly.lay(lab, v)
            if g.kind == "RRR":
                assert r3.tau is not None and r3.e_tau is not None and r3.e_n is not None
                tau3 = f"{n3}^τ"
                poly.lay(tau3, complex(r3.tau[k] * r3.e_tau[k]))
                start3 = poly.ends[tau3][0] if tau3 in poly.ends else poly.cur
                x = poly.intersect(f"{n3}^n", complex(r3.e_n[k]), f"{n1}^n", complex(r1.e_n[k]))
                poly.join(n3, start3, x, f"{n3}^τ + {n3}^n")
            else:
                assert r3.guide is not None
                x = poly.intersect(n3, complex(1j * r3.guide[k]), f"{n1}^n", complex(r1.e_n[k]))
                poly.total(slide_f, n3, x)
            poly.join(n1, x, poly.end_of([tau1], "o"), f"{n1}^n + {n1}^τ")
            poly.join(n2, end_i, x, phrase("f_closes_link", i=i))
        elif g.kind == "PRP":
            assert r1.guide is not None and r3.guide is not None
            for lab, v in li:
                poly.lay(lab, v)
            end_i = poly.cur
            for lab, v in lj:
                poly.lay(lab, v)
            x = poly.intersect(n3, complex(1j * r3.guide[k]), n1, complex(1j * r1.guide[k]))
            poly.total(slide_f, n3, x)
            poly.join(n2, end_i, x, phrase("f_closes_link", i=i))
        elif g.kind == "RPP":
            assert r2.guide is not None and r3.guide is not None
            n_ji = _fname(scene, j, i)
            for lab, v in lj:
                poly.lay(lab, v)
            x = poly.intersect(n3, complex(1j * r3.guide[k]), n_ji, complex(1j * r2.guide[k]))
            poly.join(n2, "o", x, f"= −{n_ji}")
            poly.cur = x
            for lab, v in li:
                poly.lay(lab, v)
            poly.close(n1, "o")
        else:  # RPR
            n_ji = _fname(scene, j, i)
            for lab, v in lj:
                poly.lay(lab, v)
            b = poly.cur
            poly.lay(n_ji, complex(-r2.F[k]))
            e = poly.cur
            poly.close(n3, "o")
            poly.join(n2, e, b, f"= −{n_ji}")
            poly.cur = b
            for lab, v in li:
                poly.lay(lab, v)
            poly.close(n1, e)
        out.append(ForcePolygon(g.name, g.kind, poly.plan(phi)))
    c = fa.crank
    loads = [(f.label, complex(f.F[k])) for f in c.loads]
    bal = complex(c.F_bal[k] * c.e_bal[k])
    poly = Poly(mu_force(fa, [v for _, v in loads] + [bal, complex(c.frame.F[k])]))
    for lab, v in loads:
        poly.lay(lab, v)
    if c.kind == "force":
        poly.lay("F_bal", bal)
    poly.close(c.frame.name(scene.fij), "o")
    out.append(ForcePolygon(str(c.link), "crank", poly.plan(phi)))
    return tuple(out)
