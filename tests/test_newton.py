"""The Newton–Raphson loop-equation solver against the mpmath reference and the exact analysis."""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np
import pytest

from plans.accuracy import newton, reference
from plans.accuracy.oracles import oracle_from_kinematics, oracle_from_reference, solver_errors
from plans.errors import ConstructionError, Locked, NotAssemblable
from plans.kinematics import exact as kinematics
from plans.kinematics.placing import load_scene

SAMPLES = Path(__file__).resolve().parent.parent / "samples"
CYCLE = np.linspace(0.0, 360.0, 72, endpoint=False) + 2.5


def _newton(scene, phis, perturb=1e-2, **kw):
    kin = kinematics.solve(scene, phis, order=2)
    return newton.solve(scene, phis, seed=newton.seed_from(kin, 0, perturb=perturb), **kw), kin


@pytest.mark.parametrize("case", ["slider-crank", "offset slider-crank", "four-bar", "four-bar branch -1",
                                  "Scotch yoke 60°", "cw crank with eps"])
def test_newton_matches_mpmath_over_a_cycle(case):
    """Relative to the known vectors, 1e-12 over a whole cycle (continuation, no branch flip)."""
    if case == "slider-crank":
        sc, ref = (reference.slider_crank_scene(0.1225, 0.245, 0.0, 68.07, CYCLE),
                   reference.slider_crank(0.1225, 0.245, 0.0, 68.07, CYCLE))
    elif case == "offset slider-crank":
        sc, ref = (reference.slider_crank_scene(0.05, 0.2, 0.02, 150.0, CYCLE, eps=40.0),
                   reference.slider_crank(0.05, 0.2, 0.02, 150.0, CYCLE, eps=40.0))
    elif case == "four-bar":
        sc, ref = (reference.four_bar_scene(0.05, 0.2, 0.15, 0.18, 100.0, CYCLE),
                   reference.four_bar(0.05, 0.2, 0.15, 0.18, 100.0, CYCLE))
    elif case == "four-bar branch -1":
        sc, ref = (reference.four_bar_scene(0.05, 0.2, 0.15, 0.18, 100.0, CYCLE, branch=-1),
                   reference.four_bar(0.05, 0.2, 0.15, 0.18, 100.0, CYCLE, branch=-1))
    elif case == "Scotch yoke 60°":
        sc, ref = (reference.scotch_yoke_scene(0.05, 60.0, 100.0, CYCLE),
                   reference.scotch_yoke(0.05, 60.0, 100.0, CYCLE))
    else:
        sc, ref = (reference.four_bar_scene(0.05, 0.2, 0.15, 0.18, -30.0, CYCLE, eps=-500.0),
                   reference.four_bar(0.05, 0.2, 0.15, 0.18, -30.0, CYCLE, eps=-500.0))
    nr, _ = _newton(sc, CYCLE)
    errs = solver_errors(sc, oracle_from_reference(ref), nr.point, nr.omega, nr.eps)
    assert max(errs.values()) < 1e-12, errs


def test_condition_numbers_are_reported_per_position():
    sc = reference.four_bar_scene(0.05, 0.2, 0.15, 0.18, 100.0, CYCLE)
    nr, _ = _newton(sc, CYCLE)
    assert nr.cond.shape == CYCLE.shape
    assert np.all(np.isfinite(nr.cond)) and np.all(nr.cond >= 1.0)
    assert nr.cond.max() < newton.COND_WARN
    assert np.all(nr.residual < 1e-12)
    assert nr.iterations[0] >= 2  # the seed was 1 % off: the corrector had work to do


def test_condition_number_grows_toward_a_lock():
    """λ → 1: at φ = 90° the rod comes square to the guide; cond grows like 1/√(1 − λ²)."""
    conds = []
    for lam in (0.5, 0.99, 0.9999):
        sc = reference.slider_crank_scene(0.1 * lam, 0.1, 0.0, 100.0, [90.0])
        nr, _ = _newton(sc, [90.0], perturb=1e-6)
        conds.append(float(nr.cond[0]))
    assert conds[0] < conds[1] < conds[2]


def test_tolerance_sweep_is_monotone_and_reaches_the_floor():
    phis = np.linspace(0, 330, 12) + 7.5
    sc = reference.four_bar_scene(0.05, 0.2, 0.15, 0.18, 100.0, phis)
    ref = oracle_from_reference(reference.four_bar(0.05, 0.2, 0.15, 0.18, 100.0, phis))
    errors, iters = [], []
    for tol in (1e-2, 1e-4, 1e-8, 1e-14):
        nr, _ = _newton(sc, phis, tol=tol)
        errors.append(max(solver_errors(sc, ref, nr.point, nr.omega, nr.eps).values()))
        iters.append(int(nr.iterations.sum()))
    assert errors[-1] < 1e-13
    assert errors[0] > errors[-1]
    assert all(a <= b for a, b in zip(iters, iters[1:], strict=False))


@pytest.mark.parametrize("path", sorted(SAMPLES.glob("*.toml")), ids=lambda p: p.stem)
def test_newton_agrees_with_exact_on_every_sample(path):
    try:
        sc = load_scene(path)
        phis = np.linspace(0, 360, 24, endpoint=False) + 3.0
        kin = kinematics.solve(sc, phis, order=2)
    except (ConstructionError, Exception) as exc:  # a sample still being written
        pytest.skip(f"sample not solvable by the exact analysis: {exc}")
    nr = newton.solve(sc, phis, seed=newton.seed_from(kin, 0, perturb=1e-3))
    errs = solver_errors(sc, oracle_from_kinematics(kin), nr.point, nr.omega, nr.eps)
    assert max(errs.values()) < 1e-9, errs


def test_newton_raises_not_assemblable_naming_the_angle():
    """Crank 0.1, coupler 0.1, rocker 0.1, frame 0.25: the chain cannot close beyond a limit."""
    phis = np.arange(0.0, 181.0, 5.0)
    sc = reference.four_bar_scene(0.1, 0.1, 0.1, 0.25, 10.0, phis)
    with pytest.raises(NotAssemblable):
        kinematics.solve(sc, phis, order=2)
    kin = kinematics.solve(sc, phis[:1], order=2)
    with pytest.raises((NotAssemblable, Locked), match=r"phi = \d+") as info:
        newton.solve(sc, phis, seed=newton.seed_from(kin, 0))
    assert info.value.phi_deg is not None and 0.0 < info.value.phi_deg <= 180.0
    assert info.value.group == "loop equations"


def test_newton_raises_locked_at_an_exact_lock():
    """λ = 1 at φ = 90°: rod square to the guide, the Jacobian is singular."""
    sc = reference.slider_crank_scene(0.1, 0.1, 0.0, 10.0, [90.0])
    seed = {1: (0j, math.pi / 2), 2: (0.1j, -math.pi / 2), 3: (0j, 0.0)}
    with pytest.raises((Locked, NotAssemblable), match="phi = 90"):
        newton.solve(sc, [90.0], seed=seed)


def test_newton_without_seed_still_satisfies_the_equations():
    sc = reference.slider_crank_scene(0.05, 0.2, 0.0, 100.0, [30.0])
    nr = newton.solve(sc, [30.0])
    assert nr.residual[0] < 1e-12
    rA = nr.point("A")[0][0]
    rB = nr.point("B")[0][0]
    assert abs(abs(rB - rA) - 0.2) < 1e-13
    assert abs(rB.imag) < 1e-13
