"""One construction, drawn by different pencils: the plans (a perfect pencil, every position
at once) and the hand-drawing Monte Carlo (a noisy pencil) run the same dyad functions."""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest

from plans.accuracy.draftsman import DraftsmanModel, NoisyPencil
from plans.kinematics import construction
from plans.kinematics.construction import plans_of
from plans.kinematics.dyads import PerfectPencil, Scheme
from plans.kinematics.exact import solve
from plans.kinematics.placing import load_scene

SAMPLES = sorted((Path(__file__).resolve().parent.parent / "samples").glob("*.toml"))


def _scales(kin):
    mv, ma = construction.default_scales(kin)
    return kin.scene.scales.get("velocity", mv), kin.scene.scales.get("acceleration", ma)


@pytest.mark.parametrize("path", SAMPLES, ids=lambda p: p.stem)
def test_noisy_pencil_without_noise_draws_the_plans(path):
    """A pencil and a protractor without error, over all positions at once, read what the
    perfect pencil reads, to 1e-12 of the plan (positions whose lines are nearly parallel,
    where the draftsman takes the exact point, excepted)."""
    kin = solve(load_scene(path), np.linspace(0.0, 360.0, 24, endpoint=False) + 7.0, order=2)
    mv, ma = _scales(kin)
    pencil = NoisyPencil(DraftsmanModel(0.0, 0.0), kin.n, np.random.default_rng(0), 1000.0)
    perfect = plans_of(Scheme(kin), mv, ma, PerfectPencil())
    noisy = plans_of(Scheme(kin), mv, ma, pencil)
    for pb, nb in zip(perfect, noisy, strict=True):
        assert pb is not None and nb is not None
        skip = np.zeros(kin.n, bool)
        for _, near, _ in pb.degenerate:
            skip |= np.broadcast_to(near, (kin.n,))
        assert [r[0] for r in pb.readings] == [r[0] for r in nb.readings]
        for rp, rn in zip(pb.readings, nb.readings, strict=True):
            ref = np.broadcast_to(np.maximum(np.abs(rp[5]), rp[7]), (kin.n,))
            diff = np.abs(np.broadcast_to(rp[4], (kin.n,)) - np.broadcast_to(rn[4], (kin.n,)))
            assert np.all((diff <= 1e-12 * ref + 1e-300) | skip), (path.stem, rp[0], diff.max())


@pytest.mark.parametrize("path", SAMPLES, ids=lambda p: p.stem)
def test_positions_built_together_are_the_positions_built_one_by_one(path):
    kin = solve(load_scene(path), order=2)
    mv, ma = _scales(kin)
    together = construction.build_all(kin)
    for k, pp in enumerate(together):
        one = construction.build(kin, k, velocity_scale=mv, acceleration_scale=ma)
        assert [r.quantity for r in pp.readings] == [r.quantity for r in one.readings]
        for a, b in zip(pp.readings, one.readings, strict=True):
            assert a.value == pytest.approx(b.value, rel=1e-12, abs=1e-12 * max(a.ref, 1e-300))
            assert a.exact == pytest.approx(b.exact, rel=1e-12, abs=1e-12 * max(a.ref, 1e-300))
        for p, q in ((pp.velocity, one.velocity), (pp.acceleration, one.acceleration)):
            if p is None:
                assert q is None
                continue
            assert [(x.name, x.coincides_with) for x in p.points] == [(x.name, x.coincides_with) for x in q.points]
            assert [s.label for s in p.segments] == [s.label for s in q.segments]
            assert p.degenerate == q.degenerate


def test_protocol_is_written_only_when_read():
    kin = solve(load_scene(SAMPLES[0].parent / "shaper.toml"), order=2)
    plans = construction.build_all(kin)
    written = plans[3].velocity.steps._source._protocols  # kept by the construction that built the plans
    assert written == {}  # built together: no sentence written yet
    text = plans[3].velocity.protocol()
    mv, ma = _scales(kin)
    assert text == construction.build(kin, 3, velocity_scale=mv, acceleration_scale=ma).velocity.protocol()
    assert "meet at" in text and "similarity" in text
    assert list(written) == [("velocity", 3)]  # other positions still unwritten
    assert plans[3].velocity.steps[0] is written[("velocity", 3)][0]  # and written once


def test_monte_carlo_runs_the_construction_with_a_noisy_pencil():
    """Many drawings at once through the same dyad functions: every reading spreads, the
    spread grows with the pencil, and the mean stays on the exact value."""
    kin = solve(load_scene(SAMPLES[0].parent / "six_bar.toml"), [40.0], order=2)
    mv, ma = _scales(kin)
    spread = {}
    for pencil_mm in (0.1, 0.4):
        pencil = NoisyPencil(DraftsmanModel(pencil_mm, 0.0), 3000, np.random.default_rng(1), 1000.0)
        vb, ab = plans_of(Scheme(kin, [0]), mv, ma, pencil)
        for b in (vb, ab):
            for q, _, _, _, value, exact, _, ref, drawn in b.readings:
                if drawn:
                    err = np.asarray(value) - np.ravel(exact)[0]
                    assert abs(err.mean()) < 4 * err.std() / np.sqrt(err.size) + 1e-9 * float(np.ravel(ref)[0]), q
                    spread[(pencil_mm, q)] = err.std()
    qs = {q for _, q in spread}
    assert all(spread[(0.4, q)] > 2 * spread[(0.1, q)] for q in qs)


def test_linearised_pencil_is_first_order():
    """The checker's pencil: the same construction drawn once per error; the stack-up above
    the reading's ±seg scales with the limits and does not depend on the step."""
    from plans.check.tolerance import Linearised

    kin = solve(load_scene(SAMPLES[0].parent / "shaper.toml"), order=2)
    mv, ma = _scales(kin)
    k = 2
    pp = construction.build(kin, k, velocity_scale=mv, acceleration_scale=ma)
    pairs = [(s.start, s.end) for s in pp.acceleration.segments if s.length_mm > 1.0]
    one = Linearised(kin, k, "acceleration", mv, ma, 0.5, np.radians(0.5))
    two = Linearised(kin, k, "acceleration", mv, ma, 1.0, np.radians(1.0))
    assert len(pairs) >= 8
    for a, b in pairs:
        t1, t2 = one.tolerance(a, b), two.tolerance(a, b)
        assert t1 > 0.5 and (t2 - 1.0) == pytest.approx(2 * (t1 - 0.5), rel=1e-3), (a, b)
    coarse = Linearised(kin, k, "velocity", mv, ma, 0.5, np.radians(0.5))
    fine = Linearised(kin, k, "velocity", mv, ma, 0.5, np.radians(0.5), h=1e-6)
    for s in pp.velocity.segments:
        assert fine.tolerance(s.start, s.end) == pytest.approx(coarse.tolerance(s.start, s.end), rel=1e-3)
