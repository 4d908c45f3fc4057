"""One position is built in Python numbers, many positions over arrays: the same dyad code.

The construction of the plans at many positions together (numpy arrays over the positions)
is the reference; each position built alone (Python ``complex`` and ``float``, no numpy
call per step) must draw every plan point, line and segment and read every value the same
to 1e-12 of the plan, at ordinary positions, at dead centres and where two construction
lines are nearly parallel (the draftsman's exact point), and stop with the same error
where they are parallel and apart.
"""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np
import pytest

from plans.accuracy import reference
from plans.accuracy.draftsman import DraftsmanModel, NoisyPencil
from plans.errors import Locked
from plans.kinematics import construction
from plans.kinematics.cases import Arrays, Numbers
from plans.kinematics.construction import plans_of
from plans.kinematics.dyads import Builder, PerfectPencil, Scheme
from plans.kinematics.exact import solve
from plans.kinematics.placing import load_scene

SAMPLES = sorted((Path(__file__).resolve().parent.parent / "samples").glob("*.toml"))
TOL = 1e-12


def _scales(kin):
    mv, ma = construction.default_scales(kin)
    return kin.scene.scales.get("velocity", mv), kin.scene.scales.get("acceleration", ma)


def _col(x, k):
    """Case k of an array over the cases (a number: the same for every case)."""
    return np.ravel(x)[k] if np.size(x) > 1 else np.ravel(x)[0]


def _same_builders(arr: Builder, one: Builder, k: int) -> None:
    """Case k of the plan built over arrays against the plan built alone in numbers."""
    assert arr.xp is Arrays and one.xp is Numbers  # the two paths really differ
    assert one.order == arr.order
    pts = {name: complex(_col(arr.pts[name], k)) for name in arr.order}
    extent = max(max(abs(z) for z in pts.values()), 1e-300)
    for name in arr.order:
        got = one.pts[name]
        assert type(got) in (complex, float), (name, type(got))  # Python numbers, not numpy's
        assert abs(got - pts[name]) <= TOL * extent, (arr.kind, name, got, pts[name])
    assert [s[:4] for s in one.segments] == [s[:4] for s in arr.segments]
    for sa, so in zip(arr.segments, one.segments, strict=True):
        assert abs(so[4] - _col(sa[4], k)) <= TOL * extent, (arr.kind, sa[3])
    assert [ln[2] for ln in one.lines] == [ln[2] for ln in arr.lines]
    for la, lo in zip(arr.lines, one.lines, strict=True):
        assert abs(lo[0] - _col(la[0], k)) <= TOL * extent and abs(lo[1] - _col(la[1], k)) <= TOL, la[2]
    assert [(r[0], r[1], r[3], r[6], r[8]) for r in one.readings] == [(r[0], r[1], r[3], r[6], r[8])
                                                                       for r in arr.readings]
    for ra, ro in zip(arr.readings, one.readings, strict=True):
        ref = float(_col(ra[7], k))
        assert ro[7] == pytest.approx(ref, rel=TOL)
        exact = float(_col(ra[5], k))
        scale = max(abs(exact), ref, 1e-300)
        assert abs(ro[4] - float(_col(ra[4], k))) <= TOL * scale, (arr.kind, ra[0], ro[4], _col(ra[4], k))
        assert abs(ro[5] - exact) <= TOL * scale, (arr.kind, ra[0])
    degenerate = [(out, float(_col(s, k))) for out, near, s in arr.degenerate if _col(near, k)]
    assert [out for out, _, _ in one.degenerate] == [out for out, _ in degenerate]
    for (_, so), (_, sa) in zip(((o, s) for o, _, s in one.degenerate), degenerate, strict=True):
        assert so == pytest.approx(sa, rel=1e-6, abs=1e-18)


def _compare(kin, mv=None, ma=None) -> list[str]:
    """Every position of ``kin`` built alone against all of them built together; the
    degenerate intersections met (to show the case was exercised)."""
    if mv is None:
        mv, ma = _scales(kin)
    together = plans_of(Scheme(kin, list(range(kin.n))), mv, ma, PerfectPencil())
    met = []
    for k in range(kin.n):
        alone = plans_of(Scheme(kin, k), mv, ma, PerfectPencil())
        for arr, one in zip(together, alone, strict=True):
            if arr is None:
                assert one is None
                continue
            _same_builders(arr, one, k)
            met += [out for out, _, _ in one.degenerate]
    return met


@pytest.mark.parametrize("path", SAMPLES, ids=lambda p: p.stem)
def test_each_sample_alone_as_all_together(path):
    kin = solve(load_scene(path), order=2)
    assert kin.n >= 2
    _compare(kin)


@pytest.mark.parametrize("path", SAMPLES, ids=lambda p: p.stem)
def test_position_objects_alone_as_all_together(path):
    """What the engine hands out (readings, plan points, segments) at one position, built
    alone, is what the positions built together give."""
    kin = solve(load_scene(path), order=2)
    mv, ma = construction._scales(kin, *_scales(kin))
    assert mv is not None
    together = construction._Together(kin, list(range(kin.n)), mv, ma)
    for k in (0, kin.n // 2):
        a, b = together.position(k), construction.build(kin, k, velocity_scale=mv, acceleration_scale=ma)
        assert [r.quantity for r in a.readings] == [r.quantity for r in b.readings]
        for ra, rb in zip(a.readings, b.readings, strict=True):
            scale = max(abs(ra.exact), ra.ref, 1e-300)
            assert type(rb.value) is float and abs(ra.value - rb.value) <= TOL * scale, ra.quantity
            assert abs(ra.exact - rb.exact) <= TOL * scale, ra.quantity
        for p, q in ((a.velocity, b.velocity), (a.acceleration, b.acceleration)):
            if p is None:
                assert q is None and ma is None
                continue
            assert q is not None
            assert [(x.name, x.coincides_with) for x in p.points] == [(x.name, x.coincides_with) for x in q.points]
            for x, y in zip(p.points, q.points, strict=True):
                assert math.dist(x.xy, y.xy) <= TOL * max(p.extent, 1e-300)
            assert [(s.label, s.start, s.end) for s in p.segments] == [(s.label, s.start, s.end) for s in q.segments]
            assert p.degenerate == q.degenerate


@pytest.mark.parametrize("offset", [0.0, 1e-12, 1e-9])
def test_dead_centres_alone_as_together(offset):
    """The slider-crank at both dead centres and just past them (stability suite)."""
    phis = [math.degrees(offset), 180.0 + math.degrees(offset), 90.0]
    sc = reference.slider_crank_scene(0.05, 0.2, 0.0, 100.0, phis)
    _compare(solve(sc, phis, order=2))


@pytest.mark.parametrize("alpha", [1e-3, 1e-5])
def test_nearly_parallel_slot_and_guide_alone_as_together(alpha):
    """The Scotch yoke whose slot is α to its guide (stability suite): at 1e-5° the two
    lines meet at less than the draftsman's resolution and the exact point is taken."""
    phis = [10.0, 100.0, 250.0]
    sc = reference.scotch_yoke_scene(0.05, alpha, 100.0, phis)
    met = _compare(solve(sc, phis, order=2))
    assert bool(met) == (math.sin(math.radians(alpha)) <= 1e-6)


def test_rod_as_long_as_the_crank_near_its_lock_alone_as_together():
    """λ = 1 at 1e-7 rad before φ = 90°: ⟂ AB and ∥ guide meet at 1e-7 rad (exact point)."""
    phis = [90.0 - math.degrees(1e-7), 45.0]
    sc = reference.slider_crank_scene(0.1, 0.1, 0.0, 100.0, phis)
    assert _compare(solve(sc, phis, order=2))


def _cut(snap: Scheme, l1, l2):
    """Two construction lines drawn and intersected on a fresh velocity plan."""
    b = Builder(snap, "velocity", 1000.0, PerfectPencil())
    g = snap.kin.structure.groups[0]
    L1 = b.line(l1[0], l1[1], 0.0, "⟂ AB")
    L2 = b.line(l2[0], l2[1], 0.0, "∥ guide of B")
    return b.pencil.cut(b, L1, L2, "b", 7 + 3j, g, "B"), b


@pytest.mark.parametrize("lines, expect", [
    (((0j, 1 + 0j), (2j, 1j)), 0j),  # crossing: where they cross
    (((0j, 1 + 0j), (2j, 1 + 1e-7j)), 7 + 3j),  # nearly parallel: the exact point
    (((0j, 1 + 0j), (2j, 1 + 0j)), Locked),  # parallel and apart
    (((5 + 0j, 1 + 0j), (6 + 1e-12j, 1 + 0j)), 7 + 3j),  # parallel through one point: the exact point
])
def test_the_draftsman_cuts_alike_alone_and_together(lines, expect):
    kin = solve(load_scene(SAMPLES[0].parent / "slider_crank.toml"), order=2)
    (p1, d1), (p2, d2) = lines
    arrays = Scheme(kin, [1, 2])
    one = Scheme(kin, 1)
    lines_arr = ((np.full(2, p1), np.full(2, d1)), (np.full(2, p2), np.full(2, d2)))
    if expect is Locked:
        with pytest.raises(Locked) as want:
            _cut(arrays, *lines_arr)
        with pytest.raises(Locked) as got:
            _cut(one, (p1, d1), (p2, d2))
        assert str(got.value) == str(want.value)
        assert "parallel and apart" in str(got.value) and f"phi = {kin.phi_deg[1]:g} deg" in str(got.value)
        return
    za, ba = _cut(arrays, *lines_arr)
    zo, bo = _cut(one, (p1, d1), (p2, d2))
    assert type(zo) is complex and abs(zo - za[0]) <= 1e-12 and abs(zo - expect) <= 1e-12
    assert [out for out, _, _ in bo.degenerate] == [out for out, near, _ in ba.degenerate if near[0]]


def test_a_noisy_pencil_at_one_position_draws_over_arrays():
    """The hand-drawing Monte Carlo at one position: a scheme of one position in numbers
    drawn by the noisy pencil is drawn over arrays of drawings, as from a scheme of arrays."""
    kin = solve(load_scene(SAMPLES[0].parent / "shaper.toml"), order=2)
    mv, ma = _scales(kin)

    def draw(ks):
        pencil = NoisyPencil(DraftsmanModel(), 50, np.random.default_rng(3), 1000.0)
        return plans_of(Scheme(kin, ks), mv, ma, pencil)

    for a, b in zip(draw([4]), draw(4), strict=True):
        assert a is not None and b is not None and b.xp is Arrays
        assert [r[0] for r in a.readings] == [r[0] for r in b.readings]
        for ra, rb in zip(a.readings, b.readings, strict=True):
            assert np.allclose(np.broadcast_to(ra[4], (50,)), np.broadcast_to(rb[4], (50,)), rtol=1e-12,
                               atol=1e-12 * float(np.max(ra[7])))


@pytest.mark.parametrize("name, ks", [("v_engine", None), ("shaper", [3, 7]), ("six_link", [0, 5, 11])])
def test_a_few_positions_are_built_one_by_one_as_together(name, ks):
    """Up to ``ALONE_MAX`` positions are built each alone in numbers (numpy's cost per call
    over arrays would outweigh them): what is read is what the positions built together read."""
    kin = solve(load_scene(SAMPLES[0].parent / f"{name}.toml"), order=2)
    mv, ma = construction._scales(kin, *construction.default_scales(kin))
    assert mv is not None
    if ks is None:  # every position of the scene
        ks, few = list(range(kin.n)), construction.build_all(kin)
    else:
        few = construction.build_many(kin, ks, velocity_scale=mv, acceleration_scale=ma)
    assert len(ks) <= construction.ALONE_MAX
    together = construction._Together(kin, ks, mv, ma)
    for i, pp in enumerate(few):
        assert pp._source is not None and type(pp._source.ks) is int  # built alone
        ref = together.position(i)
        assert [r.quantity for r in pp.readings] == [r.quantity for r in ref.readings]
        for ra, rb in zip(ref.readings, pp.readings, strict=True):
            scale = max(abs(ra.exact), ra.ref, 1e-300)
            assert abs(ra.value - rb.value) <= TOL * scale and abs(ra.exact - rb.exact) <= TOL * scale, ra.quantity
