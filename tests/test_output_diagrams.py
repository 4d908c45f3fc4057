"""The output's kinematic diagrams on the course's kinematics sheet, against an oracle apart
from the engine: each mechanism's closed form written here from its scene file, in mpmath at
30 digits, differentiated by mpmath (s', s'' in φ); the engine's exact analysis is not read.

- the exact curves drawn thin are the oracle's s, v = ω1·s', a = ω1²·s'' + ε1·s';
- the graphical ordinates are the chords of the oracle's s at the 12 positions, as the course
  builds them (v at the middle of each interval, a at the nodes, from the chords of v);
- the chords err from the oracle's derivatives by no more than the chord's own bound
  (h²/24·max|y'''| for a chord of y over h), which a diagram placed at the nodes instead
  of the middles, or at the wrong scale, would break;
- the sheet: the four-bar's kinematics sheet carries φ, ω, ε of its rocker with their
  ordinates, the dots where the diagram says at the scale it writes.
"""

from __future__ import annotations

import math
from pathlib import Path

import mpmath as mp
import numpy as np
import pytest

import plans
from plans.io import read_toml

SAMPLES = Path(__file__).resolve().parents[1] / "samples"
mp.mp.dps = 30
RPM = 2 * mp.pi / 60


def _driver(data):
    d = data["driver"]
    w = mp.mpf(d["omega"]) if "omega" in d else mp.mpf(d["omega_rpm"]) * RPM
    sense = 1 if d.get("sense", "ccw") == "ccw" else -1
    return w, mp.mpf(d.get("eps", 0)), sense, mp.radians(d.get("phi_ref_deg", 0))


def _metre(data):
    return mp.mpf(1) / 1000 if data.get("unit") == "mm" else mp.mpf(1)


def _slider(data):
    """s(φ) of the slider's pin from the extreme where its working stroke (the slower, or the
    outer one where they take equal time) begins: crank r about O, rod l, the guide along x
    through (0, y_g), the pin on the +x side."""
    m = _metre(data)
    r, l = m * mp.mpf(data["links"]["1"]["length"]), m * mp.mpf(data["links"]["2"]["length"])
    guide = next(j["guide"] for j in data["joints"] if j["kind"] == "P")
    y_g = mp.mpf(0) if guide["through"] == "O" else m * mp.mpf(guide["through"][1])
    w, eps, sense, ref = _driver(data)

    def x(phi):
        th = ref + sense * phi
        return r * mp.cos(th) + mp.sqrt(l**2 - (y_g - r * mp.sin(th))**2)

    x_out, x_in = mp.sqrt((l + r)**2 - y_g**2), mp.sqrt((l - r)**2 - y_g**2)
    th_out, th_in = mp.atan2(y_g, x_out), mp.atan2(-y_g, -x_in)  # the crank along the rod, against it
    out_to_in = mp.fmod(sense * (th_in - th_out) + 4 * mp.pi, 2 * mp.pi)  # crank angle of that stroke
    if out_to_in >= mp.pi - mp.mpf(10)**-20:  # the slower one, or equal: it begins at the outer extreme
        return (lambda phi: x_out - x(phi)), w, eps
    return (lambda phi: x(phi) - x_in), w, eps


def _rocker(data):
    """φ_3(φ) of the four-bar's rocker DB, turned since the first position: B where the
    circles about A (the coupler) and D (the rocker) meet left of A → D (``[branches]``)."""
    o, dd = (complex(*data["points"][k]) for k in ("O", "D"))
    r1, r2, r3 = (mp.mpf(data["links"][k]["length"]) for k in ("1", "2", "3"))
    w, eps, sense, ref = _driver(data)
    D = mp.mpc(dd.real, dd.imag)

    def theta3(phi):
        a = mp.mpc(o.real, o.imag) + r1 * mp.expjpi((ref + sense * phi) / mp.pi)
        d = abs(D - a)
        u = (D - a) / d
        along = (r2**2 - r3**2 + d**2) / (2 * d)
        b = a + u * (along + 1j * mp.sqrt(r2**2 - along**2))
        return mp.arg(b - D)

    th0 = theta3(mp.mpf(0))
    return (lambda phi: mp.fmod(theta3(phi) - th0 + 3 * mp.pi, 2 * mp.pi) - mp.pi), w, eps


CASES = {  # sample -> (the oracle, the diagram's subject)
    "slider_crank": (_slider, "B"),
    "offset_slider_crank": (_slider, "B"),
    "four_bar": (_rocker, "3"),
}


@pytest.fixture(scope="module", params=sorted(CASES))
def case(request):
    name = request.param
    make, subject = CASES[name]
    data = read_toml(SAMPLES / f"{name}.toml")
    s, w, eps = make(data)
    sol = plans.solve(SAMPLES / f"{name}.toml")
    dg = sol.output_diagrams()
    assert dg is not None
    names = ("φ", "ω", "ε") if subject.isdigit() else ("s", "v", "a")
    return name, s, w, eps, dg, [dg.get(f"{n}_{subject}") for n in names]


def _at(f, phis_deg, n=0):
    return np.array([float(mp.diff(f, mp.radians(p), n)) for p in phis_deg])


def test_the_exact_curves_are_the_oracles(case):
    """The thin curves: s, v = ω1·s', a = ω1²·s'' + ε1·s' of the oracle at every 10th of
    their samples, to 1e-9 of each curve's range."""
    _, s, w, eps, _, (gs, gv, ga) = case
    phis = gs.exact_phi_deg[::10] - gs.exact_phi_deg[0]  # φ from the first position
    s0, s1, s2 = (_at(s, phis, n) for n in (0, 1, 2))
    want = (s0, float(w) * s1, float(w)**2 * s2 + float(eps) * s1)
    for g, y in zip((gs, gv, ga), want, strict=True):
        assert np.ptp(y) > 0
        assert np.max(np.abs(g.exact[::10] - y)) < 1e-9 * np.ptp(y), g.name


def test_the_ordinates_are_the_chords_of_the_oracle(case):
    """The graphical diagrams as drawn by chords over the 12 positions: s at the positions,
    v = ω1·Δs/Δφ at the middle of each interval, a = ω1·Δv/Δφ at the positions (the middles
    of the middles, the last one the first again a revolution on)."""
    _, s, w, _, dg, (gs, gv, ga) = case
    h = 30.0
    nodes = np.arange(13) * h
    s_k = _at(s, nodes)
    v_k = float(w) * np.diff(s_k) / math.radians(h)
    a_k = float(w) * np.diff(np.append(v_k, v_k[0])) / math.radians(h)
    phi0 = float(dg.nodes_deg[0])
    for g, phi, y in ((gs, nodes, s_k), (gv, nodes[:-1] + h / 2, v_k), (ga, nodes[1:], a_k)):
        assert np.allclose(g.phi_deg - phi0, phi, atol=1e-9), g.name
        assert np.max(np.abs(g.values - y)) < 1e-9 * np.ptp(y), g.name


def test_the_chords_err_within_their_bound(case):
    """Each chord ordinate of v against the oracle's v at its middle: within ω1·h²/24·max|s'''|
    (the chord's Taylor bound, 1.2 for the terms of h⁴); each of a against ω1²·s'' at its node
    within ω1²·h²/12·max|s''''|.  Placed at the nodes, either errs by O(h)."""
    name, s, w, eps, _, (_, gv, ga) = case
    h = math.radians(30.0)
    fine = np.arange(0.0, 360.0, 1.0)
    s3, s4 = (np.max(np.abs(_at(s, fine, n))) for n in (3, 4))
    w = float(w)
    mids = np.arange(12) * 30.0 + 15.0
    assert np.max(np.abs(gv.values - w * _at(s, mids, 1))) <= 1.2 * w * h**2 / 24 * s3, name
    # a by the chords of v's chords: ω1²·(s(φ+h) − 2s(φ) + s(φ−h))/h², off s'' by h²/12·s''''
    nodes = np.arange(1, 13) * 30.0
    assert np.max(np.abs(ga.values - w**2 * _at(s, nodes, 2))) <= 1.2 * w**2 * h**2 / 12 * s4, name


def test_the_four_bars_kinematics_sheet_carries_its_rockers_diagrams():
    """The course's kinematics sheet of the four-bar (no ``[diagrams]`` of its own): φ, ω, ε of
    its rocker and the table of their ordinates, beside the plans on the first of its two
    sheets, at least two thirds of it drawn; each diagram's dots where its values at its
    scale put them (μφ = L/2π across, the written μ up)."""
    import drawings
    from drawings.paper.fill import drawn_part

    sol = plans.solve(SAMPLES / "four_bar.toml")
    d = drawings.draw(sol)
    assert len(d.sheets) == 2
    first = {p.pid: p for p, _, _ in d.sheets[0].placed}
    assert {"diagram-φ_3", "diagram-ω_3", "diagram-ε_3"} <= set(first)
    assert any(pid.startswith("diagram-table") for pid in first)
    assert any(p.kind == "velocity" for p in first.values())
    assert not any(p.pid.startswith("diagram") for p, _, _ in d.sheets[1].placed)
    assert drawn_part(d.sheets[0]) >= 2 / 3
    from drawings.linkage import OUTPUT_AXES_MM

    phi_dots = sorted(q.pts[0][0] for q in first["diagram-φ_3"].prims if q.op == "circle" and q.r == 0.5)
    axis = 12 * (phi_dots[1] - phi_dots[0])  # the φ axis drawn: 12 intervals
    assert min(abs(axis - a) for a in OUTPUT_AXES_MM) < 1e-6, axis
    dg = sol.output_diagrams(min(OUTPUT_AXES_MM, key=lambda a: abs(axis - a)))
    for name in ("φ_3", "ω_3", "ε_3"):
        g = dg.get(name)
        dots = sorted(q.pts[0] for q in first[f"diagram-{name}"].prims if q.op == "circle" and q.r == 0.5)
        xs, ys = np.array([x for x, _ in dots]), np.array([y for _, y in dots])
        assert len(dots) == len(g.values) >= 12 and np.allclose(np.diff(xs), dg.spec.length_mm / 12, atol=1e-6)
        up = ys + g.values * g.scale  # the paper's y grows down: each dot this far under one line
        assert np.ptp(up) < 1e-6, name


def test_left_out_where_the_sheet_says_so():
    """``panels = { diagrams = false }`` and a ``panels`` list without "diagrams" draw none."""
    import drawings
    from plans.kinematics.placing import scene_from_dict

    for sheet in ({"panels": {"diagrams": False}}, {"panels": ["positions", "velocity", "acceleration", "group",
                                                               "crank", "lever", "legend"]}):
        data = read_toml(SAMPLES / "four_bar.toml")
        data["sheet"] = sheet
        d = drawings.draw(scene_from_dict(data, str(SAMPLES / "four_bar.toml")))
        assert not any(p.pid.startswith("diagram") for sh in d.sheets for p, _, _ in sh.placed), sheet


@pytest.mark.parametrize("name, kind", [("triad_press", "slider"), ("triad_crusher", "rocker"),
                                        ("triad_rocking_block", "rocker")])
def test_a_triads_output_is_its_leash_on_the_frame_stopped_at_its_extremes(name, kind):
    """A class III scene's output is its triad's leash on the frame (a press's ram, a crusher's
    swing link, the rocking block): its diagrams are drawn, and its extremes, found by
    bisection, are where the second solver (Newton on the loop equations, apart from the
    engine's) finds it stopped, at the largest and least of its coordinate over a revolution
    every half degree; the working stroke the slower."""
    from plans.accuracy.newton import seed_from
    from plans.accuracy.newton import solve as newton
    from plans.kinematics.extreme import output_of

    sol = plans.solve(SAMPLES / "class3" / f"{name}.toml")
    out = output_of(sol.scene)
    assert (out.kind, out.link) == (kind, 5)
    assert sol.output_diagrams() is not None
    st = sol.strokes()[0]
    assert st.working_span > 180.0  # K > 1
    seed = seed_from(sol.kinematics, 0)
    assert float(sol.kinematics.phi_deg[0]) == 0.0

    def coordinate(phis):
        got = newton(sol.scene, phis, seed=seed, order=1)
        r0, theta = got.pose[5]
        v0, omega = got.rates[5][:2]
        if kind == "rocker":
            return np.unwrap(theta), omega
        u = np.conj(out.joint.guide.direction)
        return (r0 * u).real, (v0 * u).real

    c, rate = coordinate(np.arange(0.0, 360.0, 0.5))
    c_ext, rate_ext = coordinate(np.array([0.0, st.working_deg, st.idle_deg]))
    assert np.max(np.abs(rate_ext[1:])) < 1e-6 * np.max(np.abs(rate))
    lo, hi = sorted(c_ext[1:])
    assert lo <= np.min(c) + 1e-9 * np.ptp(c) and hi >= np.max(c) - 1e-9 * np.ptp(c)
