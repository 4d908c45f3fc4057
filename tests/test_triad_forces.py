"""The force analysis of a class-III group by Assur's special point, against oracles written
here: every link's equations solved as one linear system (twelve unknown reaction components),
the power balance, and the Zhukovsky lever."""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest

from plans.forces.analysis import kinetostatics
from plans.forces.triad import TriadForces
from plans.kinematics.exact import solve
from plans.kinematics.placing import load_scene

SAMPLE = Path(__file__).resolve().parent.parent / "samples" / "class3" / "triad_crusher.toml"


def _cross(a: complex, b: complex) -> float:
    return (a.conjugate() * b).imag


@pytest.fixture(scope="module")
def analysed():
    scene = load_scene(str(SAMPLE))
    rng = np.random.default_rng(7)
    phis = np.concatenate([np.arange(0.0, 360.0, 15.0), rng.uniform(0.0, 360.0, 16)])
    kin = solve(scene, phis, order=2)
    fa, lv = kinetostatics(scene, kin)
    return scene, kin, fa, lv


def _all_link_equations(fa, gf: TriadForces, k: int) -> np.ndarray:
    """Unknowns (x, y) of X_1..X_3 (on the base from leash m, at D, E, F) and Y_1..Y_3 (on leash
    m from its known link, at A, B, C); three equations per link (ΣFx, ΣFy, ΣM about the
    origin), solved together by least squares (12 × 12)."""
    g = gf.group
    kin = fa.kin
    leashes = g.links[1:]
    Q = [complex(kin.point(o.point, leashes[m])[0][k]) for m, (o, _) in enumerate(g.joints)]
    P = [complex(kin.point(d.point, leashes[m])[0][k]) for m, (_, d) in enumerate(g.joints)]
    loads: dict[int, tuple[complex, float]] = {}
    for link in g.links:  # every load on the link, reactions of farther groups included
        F = sum((complex(f.F[k]) for f in fa.applied.forces if f.link == link), 0j)
        M = sum((_cross(complex(f.r[k]), complex(f.F[k])) for f in fa.applied.forces if f.link == link), 0.0)
        M += sum(float(m.M[k]) for m in fa.applied.moments if m.link == link)
        loads[link] = (F, M)
    A = np.zeros((12, 12))
    b = np.zeros(12)

    def put(row: int, col: int, r: complex, sign: float) -> None:  # force (x, y) at r into rows
        A[row, col] += sign
        A[row + 1, col + 1] += sign
        A[row + 2, col] += -sign * r.imag
        A[row + 2, col + 1] += sign * r.real
    for m in range(3):
        put(0, 2 * m, P[m], 1.0)  # base: X_m at P_m
        row = 3 + 3 * m  # leash m: Y_m at Q_m, −X_m at P_m
        put(row, 6 + 2 * m, Q[m], 1.0)
        put(row, 2 * m, P[m], -1.0)
    for r, link in zip((0, 3, 6, 9), g.links, strict=True):
        F, M = loads[link]
        b[r:r + 3] = [-F.real, -F.imag, -M]
    return np.linalg.solve(A, b)


def test_reactions_satisfy_every_link_equation(analysed):
    scene, kin, fa, _ = analysed
    (gf,) = [g for g in fa.groups if isinstance(g, TriadForces)]
    for k in range(kin.n):
        x = _all_link_equations(fa, gf, k)
        ref = max(np.max(np.abs(x)), 1.0)
        got = []
        for rc in gf.reactions[3:]:
            got.append(complex(rc.F[k]))
        for rc in gf.reactions[:3]:
            got.append(complex(rc.F[k]))
        mine = np.array([c for z in got for c in (z.real, z.imag)])
        assert np.max(np.abs(mine - x)) <= 1e-9 * ref, float(kin.phi_deg[k])


def test_components_are_the_textbooks(analysed):
    """R^τ ⟂ the leash from the leash's moments about its inner pair, R^n along it; the whole
    group's moments about S vanish with them."""
    _, kin, fa, _ = analysed
    (gf,) = [g for g in fa.groups if isinstance(g, TriadForces)]
    for rc in gf.reactions[:3]:
        assert np.max(np.abs(rc.tau * rc.e_tau + rc.n * rc.e_n - rc.F)) <= 1e-9 * fa.largest_reaction
        assert np.max(np.abs((rc.e_n.conjugate() * rc.e_tau).real)) <= 1e-15
    for k in range(kin.n):  # the two of S pass through S
        i, j, m = gf.leashes(k)
        for x in (i, j):
            rc = gf.reactions[x]
            assert abs(_cross(complex(rc.r[k] - gf.S[k]), complex(rc.e_n[k]))) <= 1e-9


def test_balancing_force_three_ways(analysed):
    """Kinetostatics (the crank's ΣM_O), the Zhukovsky lever and the power balance agree."""
    _, kin, fa, lv = analysed
    bal = lv.signed(lv.by_power)
    ref = max(float(np.max(np.abs(bal))), 1.0)
    assert np.all(lv.valid)
    assert np.max(np.abs(fa.balancing - bal)) <= 1e-9 * ref
    assert np.max(np.abs(lv.signed(lv.by_lever) - bal)) <= 1e-9 * ref
    assert np.max(np.abs(bal)) > 10.0  # the crushing load is felt


def test_power_balance_written_here(analysed):
    """Σ F·v + Σ M·ω + F_bal·v_A = 0 from the applied loads and the exact velocities alone."""
    scene, kin, fa, _ = analysed
    power = np.zeros(kin.n)
    for f in fa.applied.forces:
        if f.kind == "reaction":
            continue
        v = kin.point_on(f.link, scene.links[f.link].points.get(f.point, f.local))[1]
        power += (np.conj(f.F) * v).real
    for m in fa.applied.moments:
        if m.kind != "reaction":
            power += m.M * kin.omega(m.link)
    vA = kin.point("A", 1)[1]
    F_bal = fa.crank.F_bal * fa.crank.e_bal
    power += (np.conj(F_bal) * vA).real
    assert np.max(np.abs(power)) <= 1e-9 * max(float(np.max(np.abs(F_bal * vA))), 1.0)


def test_polygon_closes_on_the_reactions(analysed):
    """The group's polygon, built by intersecting the lines of R_i^n and R_j^n, reads every
    reaction (and the components) as the analysis found them; the steps say S's moment
    equation."""
    from plans.forces.polygons import force_polygons
    from plans.forces.protocol import force_steps

    scene, kin, fa, lv = analysed
    (gf,) = [g for g in fa.groups if isinstance(g, TriadForces)]
    for k in (0, 5, 17, kin.n - 1):
        poly = force_polygons(fa, k)[0]
        assert poly.group == "2-3-4-5"
        plan = poly.plan
        for rc in gf.reactions:
            name = rc.name(scene.fij)
            seg = plan.segment(name)
            assert abs(seg.value - abs(complex(rc.F[k]))) <= 1e-9 * fa.largest_reaction, name
        for rc in gf.reactions[:3]:
            name = rc.name(scene.fij)
            if abs(float(rc.n[k])) > 1e-6:
                assert abs(plan.segment(f"{name}^n").value - abs(float(rc.n[k]))) <= 1e-9 * fa.largest_reaction
        # the closing vertex is where the two closing lines meet: both reactions of S meet there
        i, j, m = gf.leashes(k)
        steps = [f for f in force_steps(fa, lv, k) if f.plan == "group 2-3-4-5"]
        texts = [f.step.say("en") for f in steps]
        assert sum(t.startswith("ΣM_") for t in texts) == 4
        assert any(t.startswith("ΣM_S(2-3-4-5)") for t in texts)
        assert any("S —" in f.step.say("ru") for f in steps)


def test_json_and_sheet_carry_the_group(tmp_path):
    """`plans solve --json` gives the triad's reactions as for dyads and the balancing load
    three ways; the sheet draws the group cut free with Assur's point and its polygon."""
    import json

    from plans.cli import main

    out = tmp_path / "out.json"
    assert main(["solve", str(SAMPLE), "--json", str(out), "--quiet"]) == 0
    data = json.loads(out.read_text(encoding="utf-8"))
    pos = data["positions"][3]
    for name in ("F21", "F46", "F56", "F32", "F34", "F35", "F23"):
        assert name in pos["reactions"]
    (sp,) = pos["assur_points"]  # S on the axes of the two leashes it names
    assert sp["group"] == "2-3-4-5"
    S = complex(*sp["point"])
    for a, b in sp["leashes"]:
        A_, B_ = complex(*pos["points"][a]["r"]), complex(*pos["points"][b]["r"])
        assert abs(_cross(B_ - A_, S - A_)) <= 1e-12 * abs(B_ - A_) * max(abs(S - A_), 1.0)
    bal = pos["balancing"]
    assert abs(bal["by_kinetostatics"] - bal["by_power"]) <= 1e-9 * abs(bal["by_power"])
    assert abs(bal["by_lever"] - bal["by_power"]) <= 1e-9 * abs(bal["by_power"])


def test_assur_point_drawn_on_the_scheme_and_the_group():
    """S at its place at μl on the scheme and on the group cut free, labelled."""
    import math

    import plans
    from drawings.linkage import build_panels
    from drawings.paper.sheet import sheet_spec
    from plans.kinematics.triad_plans import assur_point

    spec = sheet_spec({"sheet": {"positions": [30.0], "panels": ["scheme", "group"]}}, str(SAMPLE))
    sol = plans.solve(SAMPLE, fit=spec.fit)
    panels, mu_l = build_panels(sol, spec)
    kin = solve(load_scene(str(SAMPLE)), [30.0, 0.0], order=2)
    S = complex(assur_point(kin, kin.structure.triads()[0])[0][0])
    D = complex(kin.point("D")[0][0])
    for a, b in ("AD", "BE"):  # S where the axes of AD and BE meet (the plans' pair at 30°)
        A_, B_ = complex(kin.point(a)[0][0]), complex(kin.point(b)[0][0])
        assert abs(_cross(B_ - A_, S - A_)) <= 1e-12 * abs(B_ - A_) * max(abs(S - A_), 1.0)
    for kind in ("scheme", "group"):
        (panel,) = [p for p in panels if p.kind == kind]
        marks = {p.eid: p.pts[0] for p in panel.prims if p.op == "circle"}
        (s_xy,) = [xy for eid, xy in marks.items() if eid.endswith("assur-point")]
        (d_xy,) = [xy for eid, xy in marks.items() if eid.endswith("joint-D")]
        assert abs(math.dist(s_xy, d_xy) - mu_l * abs(S - D)) < 1e-6
        assert any(p.op == "text" and p.eid.endswith("label-assur-S") for p in panel.prims)


def test_parallel_leashes_take_the_other_pairs_point(tmp_path):
    """The leash CF numbered second: where AD ∥ CF the force analysis takes S where CF and BE
    meet (as the plans do); the reactions still satisfy every link's equations and the
    balancing force still agrees with the power balance."""
    text = SAMPLE.read_text(encoding="utf-8")
    for old, new in (("[links.4]", "[links.X]"), ("[links.5]", "[links.4]"), ("[links.X]", "[links.5]"),
                     ("links = [3, 4]", "links = [3, Y]"), ("links = [4, 6]", "links = [Y, 6]"),
                     ("links = [3, 5]", "links = [3, 4]"), ("links = [5, 6]", "links = [4, 6]"), ("Y", "5")):
        assert old in text
        text = text.replace(old, new)
    f = tmp_path / "renumbered.toml"
    f.write_text(text, encoding="utf-8")
    sc = load_scene(str(f))

    def sin(phi: float) -> float:
        k = solve(sc, [phi], order=0)
        A, D, C, F = (complex(k.point(n)[0][0]) for n in "ADCF")
        return _cross(D - A, F - C) / abs(D - A) / abs(F - C)
    lo, hi = 340.0, 355.0
    for _ in range(50):
        mid = 0.5 * (lo + hi)
        lo, hi = (mid, hi) if sin(lo) * sin(mid) > 0 else (lo, mid)
    kin = solve(sc, [lo, 300.0], order=2)
    fa, lv = kinetostatics(sc, kin)
    (gf,) = [g for g in fa.groups if isinstance(g, TriadForces)]
    assert gf.leashes(0) == (1, 2, 0) and gf.leashes(1) == (0, 1, 2)
    for k in range(2):
        x = _all_link_equations(fa, gf, k)
        got = [complex(rc.F[k]) for rc in gf.reactions[3:]] + [complex(rc.F[k]) for rc in gf.reactions[:3]]
        mine = np.array([c for z in got for c in (z.real, z.imag)])
        assert np.max(np.abs(mine - x)) <= 1e-9 * max(np.max(np.abs(x)), 1.0)
        assert np.all(np.isfinite(mine))
    bal = lv.signed(lv.by_power)
    assert np.max(np.abs(fa.balancing - bal)) <= 1e-9 * max(float(np.max(np.abs(bal))), 1.0)
