"""Stiff and extreme cases: each result within a stated relative error of the mpmath
reference (or the Newton solver), or a clear error naming group, point and angle.

Errors are relative to the size of the known vector of each kind (l1, ω1·l1, ω1²·l1,
ω1, ω1²), as :func:`plans.bench.solver_errors` defines them.
"""

from __future__ import annotations

import math
import warnings
from pathlib import Path

import numpy as np
import pytest
from hypothesis import HealthCheck, assume, given, settings
from hypothesis import strategies as st

from plans.accuracy import newton, reference
from plans.accuracy.oracles import (
    construction_errors,
    oracle_from_reference,
    solver_errors,
    total_error,
)
from plans.errors import Locked, NotAssemblable
from plans.kinematics import construction
from plans.kinematics import exact as kinematics


def _all_methods(sc, ref, phis):
    """Worst error of v, a, ω, ε (positions: see _position_error) of exact, construction, Newton."""
    kin = kinematics.solve(sc, phis, order=2)
    oracle = oracle_from_reference(ref)
    exact = solver_errors(sc, oracle, kin.point, kin.omega, kin.eps)
    plans = [construction.build(kin, k) for k in range(len(phis))]
    cons = construction_errors(sc, oracle, plans)
    nr = newton.solve(sc, phis, seed=newton.seed_from(kin, 0, perturb=1e-4))
    newt = solver_errors(sc, oracle, nr.point, nr.omega, nr.eps)
    return total_error(exact), total_error(cons), total_error(newt), plans


def _position_error(sc, ref, phis, size):
    """Largest position error of the exact analysis against ``size`` (a point ~size from
    the origin is only known to one ulp of size)."""
    kin = kinematics.solve(sc, phis, order=0)
    return max(float(np.max(np.abs(kin.point(p)[0] - ref.point(p)[0]))) for p in ("A", "B")) / size


# --------------------------------------------------------------------------- dead centres


@pytest.mark.parametrize("offset", [0.0, 1e-12, 1e-9, 1e-6, 1e-3])
def test_dead_centres_near_zero(offset):
    """Inner dead centre (φ = 0) and just past it: floor-level errors, no NaN."""
    phis = np.array([math.degrees(offset), -math.degrees(offset)])
    sc = reference.slider_crank_scene(0.05, 0.2, 0.0, 100.0, phis)
    ref = reference.slider_crank(0.05, 0.2, 0.0, 100.0, phis)
    e, c, n, plans = _all_methods(sc, ref, phis)
    assert e < 1e-14 and n < 1e-14
    assert c < 1e-11  # shapely puts b on the pole when |v_B| is below ~1e-10 of the plan
    for pp in plans:
        for rd in pp.readings:
            assert math.isfinite(rd.value)


@pytest.mark.parametrize("offset", [0.0, 1e-6, 1e-3])
def test_dead_centres_near_180(offset):
    phis = np.array([180.0 + math.degrees(offset), 180.0 - math.degrees(offset)])
    sc = reference.slider_crank_scene(0.05, 0.2, 0.0, 100.0, phis)
    ref = reference.slider_crank(0.05, 0.2, 0.0, 100.0, phis)
    e, c, n, _ = _all_methods(sc, ref, phis)
    assert max(e, c, n) < 1e-14


def test_outer_dead_centre_relative_accuracy_of_small_quantities():
    """1e-9 rad past the outer dead centre, v_B itself (not just against v_A) to 1e-12."""
    phis = np.array([180.0 + math.degrees(1e-9)])
    sc = reference.slider_crank_scene(0.05, 0.2, 0.0, 100.0, phis)
    ref = reference.slider_crank(0.05, 0.2, 0.0, 100.0, phis)
    kin = kinematics.solve(sc, phis, order=2)
    vB, vB_ref = kin.point("B")[1][0], ref.point("B")[1][0]
    assert abs(vB - vB_ref) / abs(vB_ref) < 1e-12


def test_dead_centre_offset_slider_crank():
    """The dead centres of an offset slider-crank: crank and rod collinear,
    θ = asin(e/(l + r)) and π + asin(e/(l − r)); v_B = 0 there to the floor."""
    r, l, e = 0.05, 0.2, 0.02
    th = np.array([math.asin(e / (l + r)), math.pi + math.asin(e / (l - r))])
    phis = np.degrees(th)
    sc = reference.slider_crank_scene(r, l, e, 100.0, phis)
    ref = reference.slider_crank(r, l, e, 100.0, phis)
    ex, c, n, _ = _all_methods(sc, ref, phis)
    assert max(ex, c, n) < 1e-14
    assert np.all(np.abs(ref.point("B")[1]) < 1e-14 * 100 * r)


# --------------------------------------------------------------------------- λ, lengths, ω


@pytest.mark.parametrize("lam, tol", [(1e-4, 1e-14), (1e-2, 1e-14), (0.5, 1e-14), (0.99, 1e-12),
                                      (0.999999, 1e-9)])
def test_connecting_rod_ratio(lam, tol):
    """λ up to 0.999999 (rod nearly square to the guide at φ = 90°: a_B ~ 1/√(1−λ²)³)."""
    phis = np.array([0.0, 45.0, 89.0, 90.0, 135.0, 270.0])
    sc = reference.slider_crank_scene(0.1 * lam, 0.1, 0.0, 100.0, phis)
    ref = reference.slider_crank(0.1 * lam, 0.1, 0.0, 100.0, phis)
    kin = kinematics.solve(sc, phis, order=2)
    oracle = oracle_from_reference(ref)
    # relative to the quantity itself where it is large (a_B grows without bound as λ → 1)
    big = max(float(np.max(np.abs(ref.point("B")[2]))), (100.0**2) * 0.1 * lam)
    err = float(np.max(np.abs(kin.point("B")[2] - ref.point("B")[2]))) / big
    assert err < tol
    errs = solver_errors(sc, oracle, kin.point, kin.omega, kin.eps)
    # positions against the rod (B sits ~l from O: its ulp is ~1e-16 l, i.e. 1e-12 r at λ = 1e-4)
    assert errs["r"] * lam < 1e-15
    assert errs["v"] < tol and errs["omega"] < tol


def test_lengths_from_micrometres_to_kilometres_in_one_mechanism():
    phis = np.array([10.0, 100.0, 250.0])
    sc = reference.slider_crank_scene(1e-6, 1e3, 0.0, 100.0, phis)
    ref = reference.slider_crank(1e-6, 1e3, 0.0, 100.0, phis)
    e, c, n, _ = _all_methods(sc, ref, phis)
    assert max(e, c, n) < 1e-14
    assert _position_error(sc, ref, phis, 1e3) < 1e-15
    sc = reference.four_bar_scene(1e-6, 1e3, 1e3, 1e3, 100.0, phis)
    ref = reference.four_bar(1e-6, 1e3, 1e3, 1e3, 100.0, phis)
    e, c, n, _ = _all_methods(sc, ref, phis)
    assert max(e, c, n) < 1e-14
    assert _position_error(sc, ref, phis, 1e3) < 1e-15


@pytest.mark.parametrize("omega", [1e-6, 1.0, 1e5])
def test_crank_speed_range(omega):
    phis = np.array([10.0, 100.0, 250.0])
    sc = reference.four_bar_scene(0.05, 0.2, 0.15, 0.18, omega, phis, eps=0.3 * omega**2)
    ref = reference.four_bar(0.05, 0.2, 0.15, 0.18, omega, phis, eps=0.3 * omega**2)
    e, c, n, _ = _all_methods(sc, ref, phis)
    assert max(e, c, n) < 1e-14


# --------------------------------------------------------------------------- parallel guides


@pytest.mark.parametrize("alpha, tol_exact, tol_newton", [(90.0, 1e-14, 1e-14), (1.0, 1e-13, 1e-11),
                                                          (1e-3, 1e-10, 1e-6)])
def test_nearly_parallel_slot_and_guide(alpha, tol_exact, tol_newton):
    """A Scotch yoke whose slot is α to its guide: x = r sin(α − θ)/sin α, values grow as 1/α.
    Errors relative to the known vectors; the quantities themselves are ~1/α larger."""
    phis = np.array([10.0, 100.0, 250.0])
    sc = reference.scotch_yoke_scene(0.05, alpha, 100.0, phis)
    ref = oracle_from_reference(reference.scotch_yoke(0.05, alpha, 100.0, phis))
    kin = kinematics.solve(sc, phis, order=2)
    assert max(solver_errors(sc, ref, kin.point, kin.omega, kin.eps).values()) < tol_exact
    nr = newton.solve(sc, phis, seed=newton.seed_from(kin, 0, perturb=1e-6))
    assert max(solver_errors(sc, ref, nr.point, nr.omega, nr.eps).values()) < tol_newton
    plans = [construction.build(kin, k) for k in range(len(phis))]
    assert max(construction_errors(sc, ref, plans).values()) < tol_exact


def test_parallel_slot_and_guide_is_a_clear_error():
    sc = reference.scotch_yoke_scene(0.05, 0.0, 100.0, [30.0])
    with pytest.raises(NotAssemblable, match=r"group RPP 2-3, point A, phi = 30 deg"):
        kinematics.solve(sc, [30.0], order=2)


# --------------------------------------------------------------------------- coincident points


def test_coincident_point_on_the_plan():
    """S2 at A (ratio 0): its image coincides with a, its reading equals v_A, a_A."""
    phis = [30.0]
    sc = reference.slider_crank_scene(0.05, 0.2, 0.01, 100.0, phis, ratio=0.0)
    kin = kinematics.solve(sc, phis, order=2)
    pp = construction.build(kin, 0)
    assert pp.velocity is not None and pp.acceleration is not None
    read = {r.quantity: r for r in pp.readings}
    assert read["v_S2"].value == pytest.approx(read["v_A"].value, rel=1e-14)
    assert read["a_S2"].value == pytest.approx(read["a_A"].value, rel=1e-14)
    s2 = next(p for p in pp.velocity.points if p.name == "s2")
    assert s2.coincides_with == "a"


def test_coincident_joints_of_a_dyad_are_a_clear_error():
    """A four-bar whose moving pivot A comes onto the fixed pivot C: B is undefined."""
    sc = reference.four_bar_scene(0.1, 0.1, 0.1, 0.1, 10.0, [0.0])
    with pytest.raises(NotAssemblable, match=r"group RRR 2-3, point B, phi = 0 deg: A and C coincide"):
        kinematics.solve(sc, [0.0], order=2)


# --------------------------------------------------------------------------- locking


def test_lock_is_a_clear_error():
    """λ = 1 at φ = 90°: the rod is square to the guide, v_B unbounded."""
    sc = reference.slider_crank_scene(0.1, 0.1, 0.0, 10.0, [90.0])
    with pytest.raises(Locked, match=r"group RRP 2-3, point B, phi = 90 deg"):
        kinematics.solve(sc, [90.0], order=2)


def test_not_assemblable_is_a_clear_error():
    sc = reference.slider_crank_scene(0.2, 0.1, 0.0, 10.0, [0.0, 90.0])
    with pytest.raises(NotAssemblable, match=r"group RRP 2-3, point B, phi = 90 deg"):
        kinematics.solve(sc, [0.0, 90.0], order=2)


def test_four_bar_toggle_limit_never_gives_nan():
    """A non-Grashof four-bar swept past its limit angle: either finite values or a clear error."""
    phis = np.linspace(0, 180, 181)
    sc = reference.four_bar_scene(0.1, 0.1, 0.1, 0.25, 10.0, phis)
    with pytest.raises(NotAssemblable) as info:
        kinematics.solve(sc, phis, order=2)
    phi = info.value.phi_deg
    assert phi is not None
    good = phis[phis < phi]
    kin = kinematics.solve(sc, good, order=2)
    for name in ("A", "B"):
        for arr in kin.point(name):
            assert np.all(np.isfinite(arr))


# --------------------------------------------------------------------------- random mechanisms


@st.composite
def slider_cranks(draw):
    r = draw(st.floats(0.01, 1.0))
    lam = draw(st.floats(0.05, 0.8))
    e_rel = draw(st.floats(-0.3, 0.3))
    l = r / lam
    e = e_rel * (l - r)
    w = draw(st.floats(0.5, 500.0)) * draw(st.sampled_from([1, -1]))
    eps = draw(st.floats(-1.0, 1.0)) * w * w
    return r, l, e, w, eps


@st.composite
def four_bars(draw):
    """Crank-rockers with transmission angles kept well away from 0 and 180°."""
    a = draw(st.floats(0.02, 0.1))
    b = draw(st.floats(0.25, 0.5))
    c = draw(st.floats(0.25, 0.5))
    d = draw(st.floats(0.3, 0.5))
    w = draw(st.floats(0.5, 500.0)) * draw(st.sampled_from([1, -1]))
    branch = draw(st.sampled_from([1, -1]))
    return a, b, c, d, w, branch


PHIS = np.linspace(0.0, 360.0, 24, endpoint=False) + 1.0


def _four_bar_ok(a, b, c, d):
    """Grashof crank-rocker with |cos μ| ≤ 0.9 over the cycle."""
    if not (a + max(b, c, d) < sum(sorted((b, c, d))[:2]) + a and a < min(b, c, d)):
        return False
    if a + max(b, c, d) > b + c + d - max(b, c, d):
        return False
    for D in (d - a, d + a):
        cos_mu = (b * b + c * c - D * D) / (2 * b * c)
        if abs(cos_mu) > 0.9:
            return False
    return True


@settings(max_examples=25, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(slider_cranks())
def test_random_slider_cranks_three_methods_agree(p):
    r, l, e, w, eps = p
    sc = reference.slider_crank_scene(r, l, e, w, PHIS, eps=eps)
    ref = reference.slider_crank(r, l, e, w, PHIS, eps=eps)
    ex, c, n, _ = _all_methods(sc, ref, PHIS)
    assert max(ex, c, n) < 1e-12


@settings(max_examples=25, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(four_bars())
def test_random_four_bars_three_methods_agree(p):
    a, b, c, d, w, branch = p
    assume(_four_bar_ok(a, b, c, d))
    sc = reference.four_bar_scene(a, b, c, d, w, PHIS, branch=branch)
    ref = reference.four_bar(a, b, c, d, w, PHIS, branch=branch)
    ex, cc, n, _ = _all_methods(sc, ref, PHIS)
    assert max(ex, cc, n) < 1e-12


# --------------------------------------------------------------------------- toggle of a four-bar


def test_four_bar_toggle_is_locked_and_near_it_error_follows_the_conditioning():
    """Crank 3, coupler 2, rocker 3, frame 4: at φ = 90° |AC| = 5 = coupler + rocker, the
    coupler and rocker are collinear (toggle).  Exactly there: Locked, naming group, point and
    angle.  δ rad before it ω3 ~ 1/√δ and its relative error is bounded by the problem's
    conditioning, ~1e-16/δ; the exact analysis and Newton both stay within 1e-15/δ."""
    sc = reference.four_bar_scene(3.0, 2.0, 3.0, 4.0, 1.0, [90.0])
    with pytest.raises(Locked, match=r"group RRR 2-3, point B, phi = 90 deg"):
        kinematics.solve(sc, [90.0], order=2)
    for d_deg in (1e-3, 1e-5, 1e-7):
        phis = [90.0 - d_deg]
        sc = reference.four_bar_scene(3.0, 2.0, 3.0, 4.0, 1.0, phis)
        ref = reference.four_bar(3.0, 2.0, 3.0, 4.0, 1.0, phis)
        kin = kinematics.solve(sc, phis, order=2)
        nr = newton.solve(sc, phis, seed=newton.seed_from(kin, 0, perturb=1e-6))
        bound = 1e-15 / math.radians(d_deg)
        w3, e3 = ref.link(3)[1][0], ref.link(3)[2][0]
        for got in (kin, nr):
            assert abs(got.omega(3)[0] - w3) / abs(w3) < bound
            assert abs(got.eps(3)[0] - e3) / abs(e3) < 10 * bound


# --------------------------------------------------------------------------- stiff loads


def test_stiff_loads_three_balancing_loads_agree():
    """V-engine with a rod 1e6 times heavier than the other, and with the gas force 1e-8 of the
    inertia loads: kinetostatics, Zhukovsky lever and power balance agree to 1e-13 of the
    largest balancing load."""
    from pathlib import Path

    from plans.accuracy.stability import stiff_load_records

    samples = Path(__file__).resolve().parent.parent / "samples"
    if not (samples / "v_engine.toml").exists():
        pytest.skip("no V-engine sample")
    rows = stiff_load_records(samples)
    assert len(rows) == 4
    for row in rows:
        assert "error" not in row, row
        assert row["lever"] < 1e-13 and row["power"] < 1e-13, row


@pytest.mark.parametrize("y_mm", ["0", "1e-154", "1e-30"])
def test_ram_guide_through_the_rocker_pivot_keeps_the_inertia_couple(tmp_path, y_mm):
    # The ram's guide through C (to the last subnormal): D stays at C, the ram's inertia force
    # is zero or dust, and its offset force would lie farther than any sheet: it stays a couple.
    from plans.kinematics.placing import load_scene
    from plans.results import solve_scene, write_json

    text = (Path(__file__).resolve().parent.parent / "samples" / "six_bar.toml").read_text(encoding="utf-8")
    assert "through = [0, 520]" in text and 'inertia = "offset_force"' in text
    path = tmp_path / "six_bar.toml"
    path.write_text(text.replace("through = [0, 520]", f"through = [0, {y_mm}]"), encoding="utf-8")
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        sol = solve_scene(load_scene(path))
        pieces: list[str] = []
        write_json(sol, pieces.append)
    assert "NaN" not in "".join(pieces) and "Infinity" not in "".join(pieces)
    for f in sol.forces[0].applied.forces:
        assert np.all(np.isfinite(f.r)) and np.all(np.isfinite(f.F))


def test_gas_force_at_a_dead_centre_solved_alone_is_the_one_of_the_whole_turn():
    # At the dead centre the piston's velocity is round-off; the stroke that begins there is
    # the acceleration's, whatever other positions are solved with it.
    from plans.io import read_toml
    from plans.kinematics.placing import scene_from_dict
    from plans.results import solve_scene

    path = Path(__file__).resolve().parent.parent / "samples" / "v_engine.toml"
    raw = read_toml(path)
    gas = {}
    for phis in ([0.0], [180.0], [float(p) for p in range(0, 360, 5)]):
        raw["driver"]["phi_deg"] = phis
        sol = solve_scene(scene_from_dict(raw, str(path)))
        for phi in (0.0, 180.0):
            if phi in phis:
                gas.setdefault(phi, []).append({f.label: complex(f.F[phis.index(phi)])
                                                for f in sol.forces[0].applied.forces if f.kind == "gas"})
    for phi, seen in gas.items():
        assert len(seen) == 2 and seen[0] == seen[1], phi
    assert any(abs(F) > 0 for seen in gas.values() for F in seen[0].values())  # a gas force acts there


def test_a_ram_of_subnormal_mass_keeps_the_promise(tmp_path):
    # A subnormal mass is refused by the number rule (0 or at least 1e-12); at the smallest
    # mass accepted its inertia force is dust of newtons: the offset force divides by it.
    from plans.errors import InputError
    from plans.kinematics.placing import load_scene
    from plans.results import solve_scene, table

    text = (Path(__file__).resolve().parent.parent / "samples" / "six_bar.toml").read_text(encoding="utf-8")
    assert text.count("mass = 20.0") == 1
    path = tmp_path / "six_bar.toml"
    path.write_text(text.replace("mass = 20.0", "mass = 5e-324"), encoding="utf-8")
    with pytest.raises(InputError, match="links.5.mass"):
        load_scene(path)
    path.write_text(text.replace("mass = 20.0", "mass = 1e-12"), encoding="utf-8")
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        sol = solve_scene(load_scene(path))
        text = table(sol, protocol=True)
    assert "nan" not in text.lower() and "inf" not in text.lower()
