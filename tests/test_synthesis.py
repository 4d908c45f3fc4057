"""Synthesis: every model against oracles written apart from it.

* closed forms of each construction (the law of cosines in the triangle O C′ C″, the
  triangles of a four-bar's dead centres, l1 = l0·sin(θ/2) of the coulisse);
* the written scene solved by the engine's exact kinematics (a separate solver), its extreme
  positions found from the slider's velocity or the rocker's ω;
* dense sweeps of the transmission angle;
* mechanisms known beforehand (the sample four-bar) designed back from their own K and ψ.
"""

from __future__ import annotations

import math
import random
import subprocess
import sys
import tomllib
from pathlib import Path

import pytest

from plans.errors import InputError
from plans.kinematics import exact
from plans.scene.model import load_scene, scene_from_dict
from plans.synthesis.design import design
from plans.synthesis.model import task_from_dict
from plans.synthesis.numeric import brent
from plans.synthesis.scene import scene_dict, scene_text
from plans.synthesis.toml_out import dumps

ROOT = Path(__file__).resolve().parent.parent
SAMPLES = sorted((ROOT / "samples" / "synthesis").glob("*.toml"))


def task(**kw):
    return task_from_dict({"format": 1, "kind": "synthesis", **kw}, "t.toml")


def theta_of(K):
    return math.pi * (K - 1) / (K + 1)


# --------------------------------------------------------------------------- closed forms


def four_bar_dead_centres(l0, l1, l2, l3):
    """ψ at the folded and stretched dead centres (angle at D from D→O), θ between the
    crank lines there (angle at O), γ_min: triangles O-D-B with OB = l2 ∓ l1."""
    def at_D(ob):
        return math.acos((l0 * l0 + l3 * l3 - ob * ob) / (2 * l0 * l3))

    def at_O(ob):
        return math.acos((l0 * l0 + ob * ob - l3 * l3) / (2 * l0 * ob))

    swing = abs(at_D(l2 + l1) - at_D(l2 - l1))
    theta = abs(at_O(l2 - l1) - at_O(l2 + l1))
    gs = []
    for dd in (abs(l0 - l1), l0 + l1):
        g = math.acos((l2 * l2 + l3 * l3 - dd * dd) / (2 * l2 * l3))
        gs.append(min(g, math.pi - g))
    return swing, theta, min(gs)


def offset_closed(H, K, lam):
    """The triangle O C′ C″: H² = a² + b² − 2ab·cos θ with a = l2 − l1, b = l2 + l1."""
    th = theta_of(K)
    l2 = H / math.sqrt(2 * (1 + lam * lam) - 2 * (1 - lam * lam) * math.cos(th))
    l1 = lam * l2
    e = (l2 - l1) * (l2 + l1) * math.sin(th) / H
    return l1, l2, e


def slider_closed(l1, l2, e):
    """Stroke and θ of an offset slider-crank from its lengths."""
    H = math.sqrt((l1 + l2) ** 2 - e * e) - math.sqrt((l2 - l1) ** 2 - e * e)
    th = math.asin(e / (l2 - l1)) - math.asin(e / (l2 + l1))
    return H, th


# --------------------------------------------------------------------------- each model


def test_central_slider_crank_seed001():
    d = design(task(mechanism="slider_crank", stroke=245, **{"lambda": 0.5}))
    assert d.lengths["crank"] == pytest.approx(0.1225, rel=1e-12)
    assert d.lengths["rod"] == pytest.approx(0.245, rel=1e-12)
    m = d.measured[0]
    assert abs(m.K - 1) < 1e-9 and abs(m.stroke - 0.245) < 1e-9 * 0.245
    assert abs(m.gamma_min - (math.pi / 2 - math.asin(0.5))) < 1e-9


def test_central_from_mean_speed():
    # v_m = 2·H·n/60: 4 m/s at 1200 rpm is H = 0.1 m
    d = design(task(mechanism="slider_crank", mean_speed=4.0, task={"omega_rpm": 1200}, **{"lambda": 0.25}))
    assert abs(d.measured[0].stroke - 0.1) < 1e-12


@pytest.mark.parametrize("K,lam,sense", [(1.4, 0.3, "ccw"), (1.2, 0.3, "cw"), (1.8, 0.5, "ccw")])
def test_offset_from_lambda_matches_the_triangle(K, lam, sense):
    d = design(task(mechanism="slider_crank", stroke=120, K=K, task={"sense": sense}, **{"lambda": lam}))
    l1, l2, e = offset_closed(0.12, K, lam)
    assert abs(d.lengths["crank"] - l1) < 1e-9 * l2
    assert abs(d.lengths["rod"] - l2) < 1e-9 * l2
    assert abs(d.lengths["offset"] - e) < 1e-9 * l2
    m = d.measured[0]
    assert abs(m.K - K) < 1e-9 and abs(m.stroke - 0.12) < 1e-9 * 0.12
    # the pressure angle at its worst: crank ⟂ guide on the far side, sin ϑ = (l1 + e)/l2
    assert abs(m.gamma_min - (math.pi / 2 - math.asin((l1 + e) / l2))) < 1e-9


def test_offset_from_offset_and_the_construction_circle():
    d = design(task(mechanism="slider_crank", stroke=100, K=1.4, offset=20))
    l1, l2, e = d.lengths["crank"], d.lengths["rod"], d.lengths["offset"]
    assert abs(e - 0.02) < 1e-15
    H, th = slider_closed(l1, l2, e)
    assert abs(H - 0.1) < 1e-9 * 0.1 and abs(th - theta_of(1.4)) < 1e-9
    # the construction's readings: O, C′, C″ on its circle; C′C″ = H; the chord seen at θ from O
    c, R = d.circle
    for name in ("O", "C1", "C2"):
        assert abs(abs(d.points[name] - c) - R) < 1e-9 * R
    C1, C2 = d.points["C1"], d.points["C2"]
    assert abs(abs(C2 - C1) - 0.1) < 1e-12
    import cmath
    assert abs(abs(cmath.phase(C2 / C1)) - theta_of(1.4)) < 1e-9
    assert abs(l1 - (abs(C2) - abs(C1)) / 2) < 1e-12 and abs(l2 - (abs(C2) + abs(C1)) / 2) < 1e-12


def test_offset_best_pressure_angle_beats_every_pivot_on_the_arc():
    best = design(task(mechanism="slider_crank", stroke=100, K=1.4))
    g = best.measured[0].gamma_min
    assert best.choice is not None and best.choice[0] == "least_pressure"
    for lam in [0.1 + 0.05 * k for k in range(17)]:
        other = design(task(mechanism="slider_crank", stroke=100, K=1.4, **{"lambda": lam}))
        assert other.measured[0].gamma_min <= g + 1e-9


def test_crank_rocker_designed_back_from_the_sample_four_bar():
    # the sample four-bar (80, 260, 200, 300): its own ψ and K, and its frame, give it back
    swing, th, gmin = four_bar_dead_centres(0.3, 0.08, 0.26, 0.2)
    K = (math.pi + th) / (math.pi - th)
    d = design(task(mechanism="crank_rocker", rocker=200, swing_deg=math.degrees(swing), K=K, frame=300))
    assert abs(d.lengths["crank"] - 0.08) < 1e-9 * 0.3
    assert abs(d.lengths["coupler"] - 0.26) < 1e-9 * 0.3
    m = d.measured[0]
    assert abs(m.K - K) < 1e-9 and abs(m.swing - swing) < 1e-9 and abs(m.gamma_min - gmin) < 1e-9
    # the best pivot on the arc is at least as good
    best = design(task(mechanism="crank_rocker", rocker=200, swing_deg=math.degrees(swing), K=K))
    assert best.measured[0].gamma_min >= gmin - 1e-9


def test_crank_rocker_frame_angle_and_k1():
    d = design(task(mechanism="crank_rocker", rocker=200, swing_deg=40, K=1.2, frame_angle_deg=100))
    m = d.measured[0]
    assert abs(m.K - 1.2) < 1e-9 and abs(m.swing - math.radians(40)) < 1e-9
    # the frame's line at 100° from the rocker's mean position, at D
    import cmath
    C1, C2, D = d.points["C1"], d.points["C2"], d.points["D"]
    mean = (C1 - D) / abs(C1 - D) + (C2 - D) / abs(C2 - D)
    assert abs(abs(cmath.phase((0 - D) / mean)) - math.radians(100)) < 1e-9
    k1 = design(task(mechanism="crank_rocker", rocker=200, swing_deg=40, K=1, gamma_min_deg=50))
    assert abs(k1.measured[0].K - 1) < 1e-9 and abs(k1.measured[0].gamma_min - math.radians(50)) < 1e-7


def test_three_positions_recover_the_four_bar():
    from plans.synthesis.proof import FourBar

    fb = FourBar(0j, 0.3 + 0j, 0.08, 0.26, 0.2, 1)
    pos = [[p, math.degrees(fb.psi(math.radians(p)))] for p in (0, 40, 90)]
    d = design(task(mechanism="crank_rocker", rocker=200, positions=pos))
    for k, v in {"crank": 0.08, "coupler": 0.26, "rocker": 0.2, "frame": 0.3}.items():
        assert abs(d.lengths[k] - v) < 1e-9 * 0.3
    swing, th, gmin = four_bar_dead_centres(0.3, 0.08, 0.26, 0.2)
    assert abs(d.measured[0].swing - swing) < 1e-9
    assert abs(d.measured[0].gamma_min - gmin) < 1e-9


def test_coulisse_closed_forms():
    d = design(task(mechanism="coulisse", stroke=400, K=1.6, centre_distance=300, pressure_angle_max_deg=10))
    th = theta_of(1.6)
    assert abs(d.lengths["crank"] - 0.3 * math.sin(th / 2)) < 1e-12
    assert abs(d.lengths["coulisse"] - 0.4 / (2 * math.sin(th / 2))) < 1e-12
    m = d.measured[0]
    assert abs(m.K - 1.6) < 1e-9 and abs(m.stroke - 0.4) < 1e-9 * 0.4 and abs(m.swing - th) < 1e-9
    assert abs(m.gamma_min - math.radians(80)) < 1e-9  # [ϑ] = 10° met exactly at the mid and extremes


def test_v_engine_seed000():
    d = design(task(mechanism="v_engine", stroke=70, bank_deg=90, **{"lambda": 0.29}))
    assert abs(d.lengths["crank"] - 0.035) < 1e-15 and abs(d.lengths["rod"] - 0.035 / 0.29) < 1e-15
    for m in d.measured:
        assert abs(m.K - 1) < 1e-9 and abs(m.stroke - 0.07) < 1e-9 * 0.07
        assert abs(m.gamma_min - (math.pi / 2 - math.asin(0.29))) < 1e-9


# --------------------------------------------------------------------------- γ_min by a dense sweep


def test_gamma_min_against_a_dense_sweep():
    for t in (task(mechanism="crank_rocker", rocker=200, swing_deg=40, K=1.2),
              task(mechanism="slider_crank", stroke=100, K=1.4, offset=20),
              task(mechanism="coulisse", stroke=400, K=1.6, centre_distance=300, pressure_angle_max_deg=10)):
        d = design(t)
        mech, m = d.mechs[0], d.measured[0]
        sweep = min(mech.gamma(2 * math.pi * k / 20000) for k in range(20000))
        assert m.gamma_min <= sweep + 1e-12
        assert sweep - m.gamma_min < 1e-6  # the sweep's step (0.018°) squared, on the curvature


# --------------------------------------------------------------------------- randomised


def _check(d, K=None, H=None, swing=None):
    for m in d.measured:
        assert m.full_rotation
        if K is not None:
            assert abs(m.K - K) < 1e-9 * K, (d.lengths, m)
        if H is not None:
            assert abs(m.stroke - H) < 1e-9 * H
        if swing is not None:
            assert abs(m.swing - swing) < 1e-9


def test_random_tasks_every_model():
    rng = random.Random(20261125)
    for _ in range(200):  # central
        H, lam = rng.uniform(10, 500), rng.uniform(0.05, 0.95)
        _check(design(task(mechanism="slider_crank", stroke=H, **{"lambda": lam})), 1.0, H / 1000)
    for _ in range(200):  # offset, λ, e or the best pressure angle
        K, H = rng.uniform(1.02, 2.8), rng.uniform(10, 500)
        th = theta_of(K)
        sense = rng.choice(("ccw", "cw"))
        pick = rng.randrange(3)
        if pick == 0:
            extra = {"lambda": math.tan(th / 2) ** 2 + rng.uniform(0.02, 0.9) * (1 - math.tan(th / 2) ** 2)}
        elif pick == 1:
            extra = {"offset": H / math.tan(th) * rng.uniform(0.02, 0.98)}
        else:
            extra = {}
        d = design(task(mechanism="slider_crank", stroke=H, K=K, task={"sense": sense}, **extra))
        _check(d, K, H / 1000)
        if pick == 0:
            l1, l2, e = offset_closed(H / 1000, K, extra["lambda"])
            assert abs(d.lengths["rod"] - l2) < 1e-9 * l2 and abs(d.lengths["offset"] - e) < 1e-9 * l2
    for _ in range(200):  # crank-rocker: a random Grashof crank-rocker designed back from its ψ and K
        while True:
            l1, l2, l3, l0 = 1.0, rng.uniform(1.5, 6), rng.uniform(1.5, 6), rng.uniform(1.5, 6)
            ls = sorted((l0, l1, l2, l3))
            if ls[0] == l1 and ls[0] + ls[3] < ls[1] + ls[2] - 0.05:
                break
        swing, th, gmin = four_bar_dead_centres(l0, l1, l2, l3)
        K = (math.pi + th) / (math.pi - th)
        s = 100.0
        d = design(task(mechanism="crank_rocker", rocker=l3 * s, swing_deg=math.degrees(swing), K=K, frame=l0 * s))
        _check(d, K, None, swing)
        best = design(task(mechanism="crank_rocker", rocker=l3 * s, swing_deg=math.degrees(swing), K=K,
                           task={"sense": rng.choice(("ccw", "cw"))}))
        _check(best, K, None, swing)
        assert best.measured[0].gamma_min >= gmin - 1e-9
    for _ in range(200):  # coulisse
        K, l0 = rng.uniform(1.1, 3.0), rng.uniform(100, 500)
        h = theta_of(K) / 2
        H = 2 * math.sin(h) * l0 * (1 + math.sin(h)) * rng.uniform(1.001, 3.0)
        d = design(task(mechanism="coulisse", stroke=H, K=K, centre_distance=l0,
                        pressure_angle_max_deg=rng.uniform(3, 30), task={"sense": rng.choice(("ccw", "cw"))}))
        _check(d, K, H / 1000, 2 * h)
    for _ in range(200):  # V-engine
        H, lam, bank = rng.uniform(20, 300), rng.uniform(0.1, 0.45), rng.uniform(20, 160)
        _check(design(task(mechanism="v_engine", stroke=H, bank_deg=bank, **{"lambda": lam})), 1.0, H / 1000)


# --------------------------------------------------------------------------- impossible tasks


@pytest.mark.parametrize("kw,field,words", [
    ({"mechanism": "slider_crank", "stroke": 100, "K": 3.5, "lambda": 0.3}, "K", "θ < 90°"),
    ({"mechanism": "slider_crank", "stroke": 100, "K": 1.8, "lambda": 0.05}, "lambda", "tan²(θ/2)"),
    ({"mechanism": "slider_crank", "stroke": 100, "K": 1.4, "offset": 500}, "offset", "H/tan θ"),
    ({"mechanism": "slider_crank", "stroke": 100, "K": 1.4, "pressure_angle_max_deg": 20},
     "pressure_angle_max_deg", "the best is"),
    ({"mechanism": "slider_crank", "stroke": 100, "offset": 10}, "offset", "K = 1 has no offset"),
    ({"mechanism": "crank_rocker", "rocker": 200, "swing_deg": 40, "K": 1.2, "gamma_min_deg": 60},
     "gamma_min_deg", "cannot be met"),
    ({"mechanism": "crank_rocker", "rocker": 200, "swing_deg": 20, "K": 5}, "swing_deg", "no crank-rocker"),
    ({"mechanism": "crank_rocker", "rocker": 200, "swing_deg": 40, "K": 1.2, "frame": 5},
     "frame", "no crank-rocker"),
    ({"mechanism": "coulisse", "stroke": 50, "K": 1.6, "centre_distance": 300, "pressure_angle_max_deg": 10},
     "stroke", "shorter than the block's reach"),
    ({"mechanism": "crank_rocker", "rocker": 200, "positions": [[0, 60], [40, 75], [90, 95]]},
     "positions", "negative link"),
    ({"mechanism": "crank_rocker", "rocker": 200, "swing_deg": 40, "K": 1 + 1e-10}, "K", "so close to 1"),
    ({"mechanism": "slider_crank", "stroke": 100, "lambda": 1e-9}, "mechanism", "between 1 µm and 10 km"),
    ({"mechanism": "coulisse", "stroke": 400, "K": 1.6, "centre_distance": 300, "rod": 1e-3}, "rod",
     "cannot reach the ram's guide"),
])
def test_impossible_tasks_name_the_condition(kw, field, words):
    with pytest.raises(InputError) as e:
        design(task(**kw))
    assert e.value.field == field and words in str(e.value)
    assert "\n" not in str(e.value)


def test_the_reader_names_the_key():
    with pytest.raises(InputError, match="lambda: not read for mechanism = 'crank_rocker'"):
        task(mechanism="crank_rocker", rocker=200, swing_deg=40, **{"lambda": 0.3})
    with pytest.raises(InputError, match="give one third condition"):
        task(mechanism="slider_crank", stroke=100, K=1.4, offset=10, **{"lambda": 0.3})
    with pytest.raises(InputError, match="K: expected the coefficient"):
        task(mechanism="slider_crank", stroke=100, K=0.5, **{"lambda": 0.3})
    with pytest.raises(InputError, match=r"\[\[task.loads.gas\]\] entry 1, diameter: expected a finite number"):
        task(mechanism="slider_crank", stroke=100, task={"loads": {"gas": [{"diameter": math.nan}]}},
             **{"lambda": 0.3})
    with pytest.raises(InputError, match="task.masses.7"):
        task(mechanism="slider_crank", stroke=100, task={"masses": {"7": {"mass": 1}}}, **{"lambda": 0.3})


def test_cli_error_is_one_line_and_exit_2(tmp_path):
    f = tmp_path / "bad.toml"
    f.write_text('format = 1\nkind = "synthesis"\nmechanism = "slider_crank"\nstroke = 100\nK = 1.8\n'
                 'lambda = 0.05\n', encoding="utf-8")
    out = tmp_path / "scene.toml"
    r = subprocess.run([sys.executable, "-m", "plans", "design", str(f), "-o", str(out)], capture_output=True,
                       text=True, cwd=ROOT)
    assert r.returncode == 2 and r.stdout == ""
    assert r.stderr.count("\n") == 1 and r.stderr.startswith(f"plans: error: {f}: lambda: ")
    assert not out.exists()


# --------------------------------------------------------------------------- the written scenes


def _scene_extremes(sc, point, sense_u=None, rocker=None):
    """The output's extreme crank angles (degrees of the scene's φ) found with the engine's exact
    kinematics alone: roots of the slider's velocity along its guide, or of the rocker's ω."""
    def rate(phi):
        kin = exact.solve(sc, [phi], order=1)
        if rocker is not None:
            return float(kin.omega(rocker)[0])
        return float((kin.point(point)[1][0] * sense_u.conjugate()).real)

    grid = [0.37 + 360 * k / 72 for k in range(73)]
    ys = [rate(p) for p in grid]
    out = []
    for k in range(72):
        if (ys[k] > 0) != (ys[k + 1] > 0):
            out.append(brent(rate, grid[k], grid[k + 1], ys[k], ys[k + 1], xtol=1e-12) % 360)
    return out


RPP = ROOT / "tests" / "data" / "synthesis_shaper_rpp.toml"


@pytest.mark.parametrize("path", [*SAMPLES, RPP], ids=lambda p: p.stem)
def test_each_sample_written_scene_solves_with_k_and_stroke(path, tmp_path):
    from plans.io import read_toml
    from plans.synthesis.model import load_task

    t = load_task(path)
    d = design(t)
    text = scene_text(d)
    out = tmp_path / "scene.toml"
    out.write_text(text, encoding="utf-8")
    sc = load_scene(out)
    # the task's table passed through unchanged
    written = read_toml(out)
    for key in ("loads", "outputs", "dynamics"):
        if key in t.task:
            assert written[key] == t.task[key]
    assert written["driver"]["omega_rpm"] == t.task["omega_rpm"]
    assert written["driver"]["sense"] == t.task["sense"]
    for lid, body in t.task.get("masses", {}).items():
        assert written["links"][lid]["mass"] == body["mass"]
    import cmath

    if d.model == "crank_rocker":
        ex = _scene_extremes(sc, "B", rocker=3)
        assert len(ex) == 2
        kin = exact.solve(sc, ex, order=0)
        B = kin.point("B")[0]
        D = sc.frame_points["D"]
        swing = abs(cmath.phase((B[1] - D) / (B[0] - D)))
        assert abs(swing - t.swing) < 1e-9
        near = 0 if abs(B[0]) < abs(B[1]) else 1
        travel = (ex[1 - near] - ex[near]) % 360
        assert abs(travel / (360 - travel) - t.K) < 1e-9
        return
    cyl = [("B", 3)] + ([("C", 5)] if d.model == "v_engine" else [])
    if d.model == "coulisse":
        cyl = [("E", 5)]
    for pt, link in cyl:
        j = next(j for j in sc.joints if j.kind == "P" and link in j.links and sc.frame in j.links)
        u = j.guide.direction
        ex = _scene_extremes(sc, pt, sense_u=u)
        assert len(ex) == 2
        kin = exact.solve(sc, ex, order=0)
        P = kin.point(pt)[0]
        H = abs(((P[1] - P[0]) * u.conjugate()).real)
        assert abs(H - d.measured[0].stroke) < 1e-9 * H
        if d.model == "coulisse":
            # working stroke (slow) toward +x for a clockwise crank
            lo = 0 if P[0].real < P[1].real else 1
            travel = (ex[1 - lo] - ex[lo]) % 360
        else:
            near = 0 if abs(P[0]) < abs(P[1]) else 1
            travel = (ex[1 - near] - ex[near]) % 360
        assert abs(travel / (360 - travel) - t.K) < 1e-9


@pytest.mark.parametrize("path", [*SAMPLES, RPP], ids=lambda p: p.stem)
def test_each_sample_written_scene_draws(path):
    """The written scene drawn as it is (at one crank angle here, to keep the test fast)."""
    from drawings.linkage import draw
    from plans.synthesis.model import load_task

    data = tomllib.loads(scene_text(design(load_task(path))))
    data["driver"].pop("positions", None)
    data["driver"]["phi_deg"] = [30.0]
    dr = draw(scene_from_dict(data, "x.toml"), format="A1")
    assert dr.sheets


def test_design_solve_draw_by_cli(tmp_path):
    src = SAMPLES[1].read_text(encoding="utf-8").replace("positions = 12", "phi_deg = [30]")
    f = tmp_path / "offset.toml"
    f.write_text(src, encoding="utf-8")
    scene = tmp_path / "offset.scene.toml"
    js = tmp_path / "d.json"
    r = subprocess.run([sys.executable, "-m", "plans", "design", str(f), "-o", str(scene), "--json", str(js)],
                       capture_output=True, text=True, cwd=ROOT)
    assert r.returncode == 0, r.stderr
    import json

    res = json.loads(js.read_text(encoding="utf-8"))
    for key in ("mechanism", "lengths", "theta_deg", "K", "K_measured", "stroke", "stroke_measured",
                "gamma_min_deg", "pressure_angle_max_deg", "scene"):
        assert key in res
    assert "swing_deg" not in res and res["scene"] == str(scene)
    assert abs(res["K_measured"] - res["K"]) < 1e-9
    r = subprocess.run([sys.executable, "-m", "plans", "solve", str(scene), "--quiet"], capture_output=True,
                       text=True, cwd=ROOT)
    assert r.returncode == 0, r.stderr
    from drawings.cli import main

    assert main(["draw", str(scene), "-o", str(tmp_path / "sheets"), "--quiet"]) == 0
    assert main(["draw", str(f), "-o", str(tmp_path / "design"), "--quiet", "--language", "en"]) == 0
    assert list((tmp_path / "sheets").glob("*.svg")) and list((tmp_path / "design").glob("*.svg"))


def test_toml_writer_reads_back():
    data = {"format": 1, "title": {"ru": "Механизм \"A\"", "en": "x"}, "points": {"O": [0.0, 0.0]},
            "links": {"1": {"name": "crank", "points": {"S1": {"ratio": 0.5}}}},
            "joints": [{"kind": "P", "guide": {"link": 4, "through": [0.0, -1e-7]}}],
            "loads": {"gravity": True, "gas": [{"diagram": {"down": [[0, 1.5]]}}]},
            "branches": {"2-3": -1}, "odd key": 1}
    assert tomllib.loads(dumps(data)) == data


def test_json_names_for_a_crank_rocker():
    from plans.synthesis.cli import results

    d = design(task(mechanism="crank_rocker", rocker=200, swing_deg=40, K=1.2))
    res = results(d, "scene")
    assert {"mechanism", "lengths", "theta_deg", "K", "K_measured", "swing_deg", "gamma_min_deg", "scene"} <= set(res)
    assert "stroke" not in res and "pressure_angle_max_deg" not in res
    assert set(res["lengths"]) == {"crank", "coupler", "rocker", "frame"}
    assert res["grashof"] is True and "best γmin" in res["choice"]


def test_scene_dict_is_a_valid_scene_for_every_model():
    for t in (task(mechanism="crank_rocker", rocker=200, swing_deg=40, K=1.2, task={"sense": "cw"}),
              task(mechanism="slider_crank", stroke=100, K=1.4, task={"positions": [0, 90]})):
        scene_from_dict(tomllib.loads(dumps(scene_dict(design(t)))), "x.toml")


# --------------------------------------------------------------------------- the sheet


@pytest.mark.parametrize("path", [*SAMPLES, RPP], ids=lambda p: p.stem)
def test_synthesis_sheet(path):
    from drawings.synthesis import draw

    dr = draw(path, format="A3", language="en")
    # the diagrams over the turn where the one sheet holds them beside the construction
    assert [p.pid for p in dr.panels] in (["construction", "design-table"],
                                          ["construction", "design-table", "output-motion", "transmission"])
    assert len(dr.sheets) == 1
    ids = {p.eid for p in dr.panels[0].prims}
    assert "gamma-min" in ids
    if dr.design.circle is not None:
        assert "construction-circle" in ids


def test_bench_goals_listed_for_every_model():
    from plans.accuracy.synthesis_bench import GOALS, synthesis_goals

    goals = synthesis_goals(ROOT / "samples", 0.003)
    assert [g["key"] for g in goals] == [k for k, _, _ in GOALS]
    assert all(g["unit"] == "s" and g["limit"] == 5e-3 and g["value"] > 0 for g in goals)


def test_construction_readings_crank_rocker_and_coulisse():
    import cmath

    for sense in ("ccw", "cw"):
        d = design(task(mechanism="crank_rocker", rocker=200, swing_deg=40, K=1.2, task={"sense": sense}))
        (c, R), p = d.circle, d.points
        for name in ("O", "C1", "C2"):
            assert abs(abs(p[name] - c) - R) < 1e-9 * R
        O, C1, C2, D = p["O"], p["C1"], p["C2"], p["D"]
        assert abs(abs(C1 - D) - 0.2) < 1e-12 and abs(abs(C2 - D) - 0.2) < 1e-12
        assert abs(abs(cmath.phase((C2 - D) / (C1 - D))) - math.radians(40)) < 1e-9
        assert abs(abs(cmath.phase((C2 - O) / (C1 - O))) - theta_of(1.2)) < 1e-9
        assert abs(d.lengths["crank"] - (abs(C2 - O) - abs(C1 - O)) / 2) < 1e-12
        assert abs(d.lengths["coupler"] - (abs(C2 - O) + abs(C1 - O)) / 2) < 1e-12
        assert abs(d.lengths["frame"] - abs(D - O)) < 1e-12
    d = design(task(mechanism="coulisse", stroke=400, K=1.6, centre_distance=300, pressure_angle_max_deg=10))
    p, L = d.points, d.lengths
    for a in ("A1", "A2"):  # the crank at the extremes: on its circle, ⟂ the coulisse
        A = p[a]
        assert abs(abs(A) - L["crank"]) < 1e-12
        assert abs((A.conjugate() * (A - p["C"])).real) < 1e-12
    assert abs(abs(cmath.phase((p["D2"] - p["C"]) / (p["D1"] - p["C"]))) - theta_of(1.6)) < 1e-12
    assert abs(abs(p["D2"] - p["D1"]) - 0.4) < 1e-12  # the chord of D's arc is the ram's stroke


def test_random_three_positions_recover_their_four_bar():
    """A random Grashof crank-rocker placed by the circle intersection written here, three of its
    positions, designed back by Freudenstein's equation."""
    import cmath

    rng = random.Random(7)
    done = 0
    while done < 150:
        l1, l2, l3, l0 = 1.0, rng.uniform(1.5, 6), rng.uniform(1.5, 6), rng.uniform(1.5, 6)
        ls = sorted((l0, l1, l2, l3))
        if not (ls[0] == l1 and ls[0] + ls[3] < ls[1] + ls[2] - 0.05):
            continue
        pos = []
        phi = rng.uniform(0, 60)
        for _ in range(3):
            A = l1 * cmath.exp(1j * math.radians(phi))
            d = l0 - A
            c = (l2 * l2 + abs(d) ** 2 - l3 * l3) / (2 * l2 * abs(d))
            B = A + l2 * d / abs(d) * cmath.exp(1j * math.acos(c))
            pos.append([phi, math.degrees(cmath.phase(B - l0))])
            phi += rng.uniform(40, 100)
        d = design(task(mechanism="crank_rocker", rocker=l3 * 100, positions=pos))
        for k, v in {"crank": l1, "coupler": l2, "rocker": l3, "frame": l0}.items():
            assert abs(d.lengths[k] - v / 10) < 1e-9 * l0 / 10, (k, d.lengths, (l0, l1, l2, l3), pos)
        swing, _th, gmin = four_bar_dead_centres(l0, l1, l2, l3)
        assert abs(d.measured[0].swing - swing) < 1e-9 and abs(d.measured[0].gamma_min - gmin) < 1e-9
        done += 1


def test_task_dynamics_pass_into_a_scene_that_solves():
    from plans.results import solve_scene

    dyn = {"rotor_inertia": 2.0, "delta": 0.05, "driving": "constant"}
    loads = {"gravity": True, "gas": [{"name": "P3", "link": 3, "diameter": 150, "pressure_unit": "MPa",
                                       "diagram": {"down": [[0, 4.0], [245, 0.2]], "up": [[0, 1.2], [245, 0.1]]}}]}
    t = task(mechanism="slider_crank", stroke=245, task={
        "omega_rpm": 650, "positions": 12, "outputs": ["positions", "velocity_plan", "dynamics"],
        "dynamics": dyn, "loads": loads, "masses": {"2": {"mass": 6.0, "inertia": 0.035, "centre": 0.35},
                                                     "3": {"mass": 4.5}}}, **{"lambda": 0.5})
    data = tomllib.loads(scene_text(design(t)))
    assert data["dynamics"] == dyn and data["loads"] == loads
    sol = solve_scene(scene_from_dict(data, "x.toml"))
    assert sol.cycle is not None


def test_coulisse_rpp_ram():
    d = design(task(mechanism="coulisse", stroke=400, K=1.6, centre_distance=300, ram_group="RPP"))
    m = d.measured[0]
    th = theta_of(1.6)
    assert abs(m.K - 1.6) < 1e-9 and abs(m.stroke - 0.4) < 1e-9 * 0.4
    assert abs(m.gamma_min - (math.pi / 2 - th / 2)) < 1e-9  # the pressure angle is the coulisse's tilt
    with pytest.raises(InputError, match="θ/2"):
        design(task(mechanism="coulisse", stroke=400, K=1.6, centre_distance=300, ram_group="RPP",
                    pressure_angle_max_deg=15))


def test_json_construction_is_the_circle_through_the_pivot_and_the_extremes():
    from plans.synthesis.cli import results

    res = results(design(task(mechanism="slider_crank", stroke=120, K=1.2, **{"lambda": 0.3})), "s")
    c = complex(*res["construction"]["circle"]["centre"])
    R = res["construction"]["circle"]["radius"]
    for name in ("O", "C1", "C2"):
        assert abs(abs(complex(*res["construction"]["points"][name]) - c) - R) < 1e-6


def test_mean_speed_and_stroke_give_the_crank_speed():
    # v_m = 2·H·n/60: H = 0.1 m at 4 m/s is n = 1200 rpm, written into the scene's driver
    t = task(mechanism="slider_crank", stroke=100, mean_speed=4.0, **{"lambda": 0.25})
    data = tomllib.loads(scene_text(design(t)))
    assert abs(data["driver"]["omega_rpm"] - 1200) < 1e-9
