"""Cams: seed 001's profile tables, the laws' derivatives, the roller envelope, pressure angle
and curvature against geometry measured on the profile itself, the base radius, bad input."""

from __future__ import annotations

import copy
import json
import math
from dataclasses import replace
from pathlib import Path

import numpy as np
import pytest
import shapely

from plans.cams.analysis import findings, grid, motion, profile
from plans.cams.base_radius import min_base_radius
from plans.cams.graphical import integrate_cam
from plans.cams.laws import LAWS, table_law
from plans.cams.model import cam_from_dict, load_cam
from plans.io import read_toml

from .cams_seed001 import ACTUAL_X, ACTUAL_Y, THEORETICAL_X, THEORETICAL_Y

ROOT = Path(__file__).resolve().parent.parent
CAM_SAMPLES = sorted((ROOT / "samples" / "cams").glob("*.toml"))
SEED = ROOT / "samples" / "cams" / "seed001_valve_cam.toml"
OSC = ROOT / "samples" / "cams" / "oscillating_cycloidal.toml"


def _seed_dict() -> dict:
    return read_toml(SEED)


def _printed(v: float) -> str:
    s = f"{v:.4f}"
    return "0.0000" if s == "-0.0000" else s


def _as_printed(s: str) -> str:
    return _printed(float(s))


def _table_mismatches(cam) -> list[tuple[int, str]]:
    pr = profile(cam, np.radians(np.arange(73) * 5.0))
    bad = []
    for i in range(73):
        for name, got, printed in (("x", pr.theoretical[i, 0], THEORETICAL_X[i]),
                                   ("y", pr.theoretical[i, 1], THEORETICAL_Y[i]),
                                   ("xa", pr.actual[i, 0], ACTUAL_X[i]),
                                   ("ya", pr.actual[i, 1], ACTUAL_Y[i])):
            if _printed(got * 1000) != _as_printed(printed):
                bad.append((5 * i, name))
    return bad


def test_seed_tables_describe_rise_55_dwell_5_return_55():
    """All 292 printed numbers (73 points × theoretical and actual x, y) to their 4 decimals
    are those of a cam with rise 55°, far dwell 5°, return 55°, near dwell 245°, turning
    clockwise: not the cam the seed states (rise 65°, dwell 20°, return 55°, dwell 220°)."""
    d = _seed_dict()
    for ph, ang in zip(d["phases"], (55, 5, 55, 245), strict=True):
        ph["angle_deg"] = ang
    assert _table_mismatches(cam_from_dict(d, "seed-as-tabulated")) == []


def test_seed_stated_cam_differs_from_its_tables():
    """The seed is wrong here: its stated phases (the sample) give other coordinates from 5°
    to 110° of the cam; on the base circle (115°..360°) both agree."""
    bad = _table_mismatches(load_cam(SEED))
    angles = sorted({a for a, _ in bad})
    assert angles[0] == 5 and angles[-1] <= 140
    cam = load_cam(SEED)
    pr = profile(cam, np.radians([5.0]))
    assert _printed(pr.theoretical[0, 0] * 1000) == "-3.0631"  # the seed prints -3.0681
    assert all(a not in angles for a in range(145, 361, 5))


def test_seed_sense_ccw_mirrors_the_table():
    d = _seed_dict()
    d["sense"] = "ccw"
    ccw = profile(cam_from_dict(d, "ccw"), grid(load_cam(SEED), 5.0))
    cw = profile(load_cam(SEED), grid(load_cam(SEED), 5.0))
    assert np.allclose(ccw.theoretical[:, 0], -cw.theoretical[:, 0], atol=1e-15)
    assert np.allclose(ccw.actual[:, 1], cw.actual[:, 1], atol=1e-15)


def test_seed_return_law_and_acceleration():
    """The seed's MATLAB return s = 5(1 + cos(π(φ−85)/65)) uses the rise angle 65° for a 55°
    return: at 140° it leaves 5(1 + cos(55π/65)) = 0.573 mm, a jump onto the base circle.
    Its v amplitude 476.7 mm/s (ω = 34.43 rad/s) is right; its a amplitude 51538.7 mm/s² is
    not: (h/2)(π/Φ)²ω² = 45453 mm/s²."""
    seed_return_end = 5 * (1 + math.cos(math.pi * 55 / 65))
    assert seed_return_end == pytest.approx(0.5727, abs=1e-4)
    cam = load_cam(SEED)
    mo = motion(cam, np.radians([139.999999, 140.0]))
    assert abs(mo.s[1]) < 1e-12 and abs(mo.s[0]) < 1e-12
    omega = 34.43
    rise = np.radians(np.linspace(0, 65, 6501))
    mo = motion(cam, rise)
    v_max = float(np.max(mo.s1)) * 1000 * omega
    a_max = float(np.max(mo.s2)) * 1000 * omega**2
    assert round(v_max, 1) == 476.7
    assert a_max == pytest.approx(45453, abs=1)
    assert abs(a_max - 51538.7) > 6000


@pytest.mark.parametrize("name", sorted(LAWS))
def test_laws_derivatives_by_finite_differences(name):
    law = LAWS[name]
    t = np.linspace(0.013, 0.987, 40)
    t = t[np.abs(t - 0.5) > 1e-3]
    h = 1e-5
    f0, d1, d2 = law(t)
    fp, fm = law(t + h)[0], law(t - h)[0]
    assert np.allclose((fp - fm) / (2 * h), d1, atol=1e-8)
    assert np.allclose((fp - 2 * f0 + fm) / h**2, d2, atol=5e-4)
    e = law(np.array([0.0, 1.0]))
    assert e[0][0] == pytest.approx(0, abs=1e-15) and e[0][1] == pytest.approx(1, abs=1e-15)
    assert e[1][0] == pytest.approx(0, abs=1e-12) and e[1][1] == pytest.approx(0, abs=1e-12)


def test_laws_closed_forms():
    """The formulas of the course, written out again."""
    t = np.linspace(0, 1, 101)
    assert np.allclose(LAWS["harmonic"](t)[0], (1 - np.cos(np.pi * t)) / 2)
    assert np.allclose(LAWS["cycloidal"](t)[0], t - np.sin(2 * np.pi * t) / (2 * np.pi))
    assert np.allclose(LAWS["poly345"](t)[0], 10 * t**3 - 15 * t**4 + 6 * t**5)
    ca = np.where(t <= 0.5, 2 * t**2, 1 - 2 * (1 - t) ** 2)
    assert np.allclose(LAWS["constant_acceleration"](t)[0], ca)


def test_table_law_passes_through_its_points_and_is_smooth():
    tt = [0, 0.2, 0.5, 0.8, 1.0]
    ff = [0, 0.1, 0.5, 0.9, 1.0]
    law = table_law(tt, ff)
    assert np.allclose(law(np.array(tt))[0], ff, atol=1e-14)
    x = np.linspace(0.01, 0.99, 50)
    h = 1e-6
    assert np.allclose((law(x + h)[0] - law(x - h)[0]) / (2 * h), law(x)[1], atol=1e-6)
    assert np.allclose(law(np.array([0.0, 1.0]))[1], 0, atol=1e-12)


@pytest.mark.parametrize("path", [SEED, OSC], ids=lambda p: p.stem)
def test_motion_derivatives_by_the_cam_angle(path):
    cam = load_cam(path)
    phi = grid(cam, 0.7) + 1.3e-3
    h = 1e-6
    mo, mp, mm = motion(cam, phi), motion(cam, phi + h), motion(cam, phi - h)
    same = (mp.phase == mo.phase) & (mm.phase == mo.phase)
    assert np.allclose(((mp.s - mm.s) / (2 * h))[same], mo.s1[same], atol=1e-8)
    assert np.allclose(((mp.s1 - mm.s1) / (2 * h))[same], mo.s2[same], atol=1e-6)


@pytest.mark.parametrize("path", [SEED, OSC], ids=lambda p: p.stem)
def test_actual_profile_at_roller_distance(path):
    """Every point of the envelope lies exactly r_roller from the theoretical profile (the
    nearest point on a dense polyline of it)."""
    cam = load_cam(path)
    dense = profile(cam, grid(cam, 0.01)).theoretical
    line = shapely.LineString(np.vstack([dense, dense[:1]]))
    act = profile(cam, grid(cam, 1.0)).actual
    d = shapely.distance(shapely.points(act), line)
    assert np.allclose(d, cam.roller, rtol=0, atol=1e-7 * cam.base_radius)


@pytest.mark.parametrize("path", [SEED, OSC], ids=lambda p: p.stem)
def test_pressure_angle_from_profile_geometry(path):
    """The angle between the profile's normal (from neighbouring profile points, turned back
    into the fixed frame) and the follower's velocity (from neighbouring follower positions)."""
    cam = load_cam(path)
    phi = grid(cam, 3.0) + 1e-3
    h = 1e-6
    pr = profile(cam, phi)
    tp, tm = profile(cam, phi + h).theoretical, profile(cam, phi - h).theoretical
    tan_cam = tp - tm
    k = cam.sense
    c, s = np.cos(k * phi), np.sin(k * phi)
    tan_fixed = np.stack([c * tan_cam[:, 0] - s * tan_cam[:, 1], s * tan_cam[:, 0] + c * tan_cam[:, 1]], 1)
    normal = np.stack([-tan_fixed[:, 1], tan_fixed[:, 0]], 1)
    Bp, Bm = profile(cam, phi + h).B, profile(cam, phi - h).B
    vel = Bp - Bm
    moving = np.hypot(*vel.T) > 1e-12
    cosang = np.abs(np.sum(normal * vel, 1)) / np.hypot(*normal.T) / np.maximum(np.hypot(*vel.T), 1e-300)
    geo = np.degrees(np.arccos(np.clip(cosang, -1, 1)))
    assert np.allclose(geo[moving], np.degrees(pr.pressure_angle[moving]), atol=1e-4)
    if cam.follower == "translating":  # the course's formula tan α = (k·ds/dφ − e)/(s0 + s)
        s0 = math.sqrt(cam.base_radius**2 - cam.offset**2)
        ref = np.degrees(np.abs(np.arctan((k * pr.motion.s1 - cam.offset) / (s0 + pr.motion.s))))
        assert np.allclose(ref, np.degrees(pr.pressure_angle), atol=1e-12)


@pytest.mark.parametrize("path", [SEED, OSC], ids=lambda p: p.stem)
def test_curvature_against_three_point_circle(path):
    cam = load_cam(path)
    phi = grid(cam, 4.0) + 0.3e-2
    h = 1e-4
    a, b, c = (profile(cam, phi + d).theoretical for d in (-h, 0.0, h))
    # circumscribed circle of three points: curvature = 4·area / (|ab|·|bc|·|ca|)
    cross = (b[:, 0] - a[:, 0]) * (c[:, 1] - a[:, 1]) - (b[:, 1] - a[:, 1]) * (c[:, 0] - a[:, 0])
    kappa = 2 * cross / (np.hypot(*(b - a).T) * np.hypot(*(c - b).T) * np.hypot(*(c - a).T))
    convex_positive = -cam.sense * kappa
    assert np.allclose(convex_positive, profile(cam, phi).curvature, rtol=1e-4, atol=1e-6)


def test_undercut_found_when_roller_is_too_big():
    cam = load_cam(SEED)
    fi = findings(cam)
    assert fi.undercut == ()
    big = replace(cam, roller=fi.min_curvature_radius * 1.3)
    cut = findings(big).undercut
    assert cut and all(u.min_radius < big.roller for u in cut)
    small = replace(cam, roller=fi.min_curvature_radius * 0.95)
    assert findings(small).undercut == ()


def test_min_base_radius_gives_the_permissible_angle():
    """At the exact minimum the largest rise pressure angle is [α]; a little less and it is
    exceeded; the best offset's pair is no bigger and also just reaches [α]."""
    cam = load_cam(SEED)
    br = min_base_radius(cam)
    at = findings(replace(cam, base_radius=br.min_base_radius))
    assert math.degrees(at.max_pressure_rise) == pytest.approx(30.0, abs=1e-5)
    below = findings(replace(cam, base_radius=br.min_base_radius * 0.995))
    assert math.degrees(below.max_pressure_rise) > 30.0
    best = replace(cam, base_radius=br.best_base_radius, offset=br.best_offset)
    fb = findings(best)
    assert br.best_base_radius <= br.min_base_radius
    assert max(math.degrees(fb.max_pressure_rise) - 30, math.degrees(fb.max_pressure_return) - 70) \
        == pytest.approx(0.0, abs=1e-5)
    drawn = min_base_radius(cam, exact=False)
    assert drawn.min_base_radius <= br.min_base_radius
    assert drawn.min_base_radius == pytest.approx(br.min_base_radius, rel=0.05)


def test_oscillating_min_base_radius():
    cam = load_cam(OSC)
    r = min_base_radius(cam).min_base_radius
    f = findings(replace(cam, base_radius=r))
    assert math.degrees(f.max_pressure_rise) == pytest.approx(45.0, abs=1e-3)


def test_graphical_integration_meets_the_exact_curves():
    cam = load_cam(SEED)
    ig = integrate_cam(cam)
    exact = motion(cam, ig.nodes % (2 * np.pi))
    h = np.max(np.diff(ig.nodes))
    assert np.max(np.abs(ig.v_nodes - exact.s1)) < 0.2 * cam.h * h**2 * 10
    assert np.max(np.abs(ig.s_nodes - exact.s)) < 0.02 * cam.h
    assert abs(ig.s_nodes[-1]) < 0.02 * cam.h  # the chain closes on itself after a turn


def _cli(argv, capsys):
    from drawings.cli import main

    code = main(argv)
    return code, capsys.readouterr()


def test_cli_json_names(tmp_path, capsys):
    out = tmp_path / "cam.json"
    code, _ = _cli(["cam", str(SEED), "--json", str(out)], capsys)
    assert code == 0
    d = json.loads(out.read_text())
    for key in ("phi_deg", "s", "ds_dphi", "d2s_dphi2", "pressure_angle_deg", "profile", "min_base_radius",
                "min_curvature_radius"):
        assert key in d
    assert len(d["phi_deg"]) == 360 and len(d["profile"]["actual"]) == 360
    assert all(len(d[k]) == 360 for k in ("s", "ds_dphi", "d2s_dphi2", "v", "a", "pressure_angle_deg"))
    assert set(d["profile"]) == {"theoretical", "actual"}
    assert d["s"][65] == pytest.approx(10.0) and d["s"][150] == 0.0
    code, _ = _cli(["cam", str(SEED), "--json", str(tmp_path / "b.json")], capsys)
    assert (tmp_path / "b.json").read_bytes() == out.read_bytes()


@pytest.mark.parametrize("path", CAM_SAMPLES, ids=lambda p: p.stem)
def test_every_cam_sample_solves_and_draws(path, tmp_path, capsys):
    code, cap = _cli(["cam", str(path)], capsys)
    assert code == 0 and "minimum base radius" in cap.out
    from drawings.cams import draw

    drawing = draw(path)
    assert drawing.sheets
    svg = drawing.sheets[0].svg()
    for eid in ("actual-profile", "graphical-s", "exact-s", "graphical-ds", "exact-d2s", "mid-ordinates"):
        assert f'id="{eid}"' in "".join(sh.svg() for sh in drawing.sheets)
    cam = load_cam(path)
    if not cam.flat:
        assert 'id="theoretical-profile"' in svg
    small = draw(path, format="A4", language="ru")  # every panel fits the smallest sheet
    assert all(sh.width == 297 for sh in small.sheets)
    assert "nan" not in svg.lower().replace("nanosecond", "")


def _bad(tmp_path, capsys, change) -> str:
    d = copy.deepcopy(_seed_dict())
    change(d)
    p = tmp_path / "bad.toml"
    p.write_text(_to_toml(d))
    code, cap = _cli(["cam", str(p)], capsys)
    assert code == 2
    assert cap.out == "" and len(cap.err.strip().splitlines()) == 1 and "Traceback" not in cap.err
    return cap.err


def _to_toml(d: dict) -> str:
    def value(v) -> str:  # JSON's numbers, strings and arrays are TOML's; a table is written inline
        return "{ " + ", ".join(f"{k} = {value(x)}" for k, x in v.items()) + " }" if isinstance(v, dict) else json.dumps(v)

    lines = []
    for k, v in d.items():
        if k in ("phases", "sheet"):
            continue
        lines.append(f"{k} = {value(v)}")
    for ph in d.get("phases", []):
        lines.append("[[phases]]")
        lines += [f"{k} = {value(v)}" for k, v in ph.items()]
    return "\n".join(lines) + "\n"


def test_bad_phases_sum(tmp_path, capsys):
    err = _bad(tmp_path, capsys, lambda d: d["phases"][3].update(angle_deg=200))
    assert "phases" in err and "340" in err and "360" in err


def test_bad_table_does_not_reach_stroke(tmp_path, capsys):
    def change(d):
        d["phases"][0].update(law="table", table=[[0, 0], [30, 4], [65, 9.5]])

    err = _bad(tmp_path, capsys, change)
    assert "phases[0].table" in err and "does not reach the stroke" in err


@pytest.mark.parametrize("r0", [0, -5])
def test_bad_base_radius(tmp_path, capsys, r0):
    err = _bad(tmp_path, capsys, lambda d: d.update(base_radius=r0))
    assert "base_radius" in err and "positive" in err


@pytest.mark.parametrize("key", ["pressure_angle_rise_deg", "pressure_angle_return_deg"])
def test_bad_permissible_pressure_angle(tmp_path, capsys, key):
    err = _bad(tmp_path, capsys, lambda d: d.update({key: 5e-324}))
    assert f"{key}: expected at least 1" in err


def test_title_that_is_not_text(tmp_path, capsys):
    err = _bad(tmp_path, capsys, lambda d: d.update(title=5))
    assert "title: expected a string" in err


def test_roller_bigger_than_base_circle(tmp_path, capsys):
    err = _bad(tmp_path, capsys, lambda d: d.update(roller=40))
    assert "roller" in err and "smaller than the base radius" in err


def test_unknown_key_named(tmp_path, capsys):
    err = _bad(tmp_path, capsys, lambda d: d.update(rollr=5))
    assert "rollr" in err and "roller" in err
    err = _bad(tmp_path, capsys, lambda d: d["phases"][0].update(strok=3))
    assert "phases[0].strok" in err


def test_table_law_in_a_file_reaches_the_stroke():
    d = _seed_dict()
    d["phases"][0].update(law="table", table=[[0, 0], [20, 1.5], [32.5, 5], [45, 8.5], [65, 10]])
    cam = cam_from_dict(d, "t")
    mo = motion(cam, np.radians([0.0, 32.5, 65.0]))
    assert np.allclose(mo.s * 1000, [0, 5, 10], atol=1e-12)


def test_flat_face_translating():
    d = _seed_dict()
    d.pop("roller")
    d["face"] = "flat"
    # r0 = 35 mm is too small for a flat face: ρ = r0 + s + s″ < 0 after the far dwell
    thin = cam_from_dict(d, "flat")
    cut = findings(thin).undercut
    assert cut and 85 <= cut[0].start_deg < 100
    assert min_base_radius(thin).min_base_radius > thin.base_radius
    d["base_radius"] = 80
    cam = cam_from_dict(d, "flat")
    assert findings(cam).undercut == ()
    pr = profile(cam, grid(cam, 2.0))
    assert np.all(pr.pressure_angle == 0)
    # the flat face's contact lies on the face: the support line at distance r0 + s from O
    phi = pr.motion.phi
    n = np.stack([np.sin(cam.sense * phi), np.cos(cam.sense * phi)], 1)  # R(−kφ)·(0, 1)
    assert np.allclose(np.sum(pr.theoretical * n, 1), cam.base_radius + pr.motion.s, atol=1e-15)
    # and it is the envelope: every face line supports the whole profile (no line cuts it)
    support = pr.theoretical @ n.T  # support[i, j]: point i projected on face j's normal
    assert np.all(support <= (cam.base_radius + pr.motion.s)[None, :] + 1e-12)


def test_rocker_diagram_reads_the_pressure_angle_and_the_base_radius():
    """D = A + (1 − r)(B − A): the angle of OD with the arm's normal is the pressure angle found
    from the profile's tangent; the centres' region on the pivot circle gives the base radius
    the bisection on the largest pressure angle finds."""
    from plans.cams.rocker import diagram, points

    cam = load_cam(OSC)
    phi = grid(cam, 1.0)
    _, D, n, _ = points(cam, phi)
    u = np.stack([n[:, 1], -n[:, 0]], 1)
    od = -D  # O at the origin
    ang = np.arctan2(np.abs(np.sum(od * u, 1)), np.sum(od * n, 1))
    assert np.allclose(ang, profile(cam, phi).pressure_angle, atol=1e-12)
    d = diagram(cam, grid(cam, 0.25))
    assert d.min_base_radius == pytest.approx(min_base_radius(cam).min_base_radius, rel=1e-5)
    best = replace(cam, base_radius=d.best_base_radius, pivot=d.best_pivot)
    fb = findings(best)
    worst = max(math.degrees(fb.max_pressure_rise) - 45, math.degrees(fb.max_pressure_return) - 70)
    assert worst == pytest.approx(0.0, abs=0.05)


def test_step_deg_sets_the_arrays(capsys):
    flat = ROOT / "samples" / "cams" / "flat_face_poly345.toml"
    code, cap = _cli(["cam", str(flat), "--json", "-"], capsys)
    d = json.loads(cap.out)
    assert code == 0 and len(d["phi_deg"]) == 180 and d["phi_deg"][1] == 2.0
    assert max(d["pressure_angle_deg"]) == 0.0
    assert d["profile"]["theoretical"] == d["profile"]["actual"]


def test_cli_json_to_stdout(capsys):
    code, cap = _cli(["cam", str(OSC), "--json", "-"], capsys)
    assert code == 0
    d = json.loads(cap.out)
    assert d["follower"] == "oscillating" and max(d["s"]) == pytest.approx(20.0)
    assert max(d["v"]) == pytest.approx(4.18879, abs=1e-4)  # 2·ψ/Φ·ω of the cycloid, rad/s


def _smallest_convex_radius_drawn(cam, step_deg: float = 0.05) -> float:
    """The theoretical profile as a fine polyline, each three neighbours' circle: the
    smallest convex radius found without the analytic curvature."""
    pts = np.asarray(profile(cam, np.radians(np.arange(0.0, 360.0, step_deg))).theoretical)
    a, b, c = pts, np.roll(pts, -1, axis=0), np.roll(pts, -2, axis=0)
    cross = (b[:, 0] - a[:, 0]) * (c[:, 1] - a[:, 1]) - (b[:, 1] - a[:, 1]) * (c[:, 0] - a[:, 0])
    ab, bc, ca = (np.hypot(*(q - p).T) for p, q in ((a, b), (b, c), (c, a)))
    radius = ab * bc * ca / (2 * np.abs(cross))
    turning = np.sign(np.median(cross))  # the profile's own sense: convex parts turn with it
    return float(np.min(radius[np.sign(cross) == turning]))


@pytest.mark.parametrize("roller_mm", [15.0, 22.0])
def test_base_radius_raised_until_a_big_roller_fits(roller_mm):
    from plans.cams.base_radius import roller_base_radius

    cam = replace(load_cam(SEED), roller=roller_mm / 1000)
    start = min_base_radius(cam).min_base_radius
    fit = roller_base_radius(cam, start)
    assert fit is not None and fit > start  # the pressure angle alone would undercut this roller
    assert findings(replace(cam, base_radius=start)).undercut
    # at the radius found the profile's smallest convex radius is the roller's, measured on the drawn curve
    assert _smallest_convex_radius_drawn(replace(cam, base_radius=fit)) == pytest.approx(cam.roller, rel=2e-3)
    assert findings(replace(cam, base_radius=fit * 1.001)).undercut == ()


def test_cam_command_reports_the_roller_base_radius(tmp_path):
    from plans.cli import main

    text = SEED.read_text(encoding="utf-8")
    assert "\nroller = 5\n" in text
    path = tmp_path / "big_roller.toml"
    path.write_text(text.replace("\nroller = 5\n", "\nroller = 15\n"), encoding="utf-8")
    out = tmp_path / "r.json"
    assert main(["cam", str(path), "--json", str(out)]) == 0
    res = json.loads(out.read_text(encoding="utf-8"))
    assert res["min_base_radius_roller"] > res["min_base_radius"]
    assert res["best_base_radius_roller"] >= res["best_base_radius"]


@pytest.mark.parametrize("fmt", ["A1", None], ids=["A1", "own"])
@pytest.mark.parametrize("path", CAM_SAMPLES, ids=lambda p: p.stem)
def test_motion_diagrams_stacked_and_their_scales_off_the_curves(path, fmt):
    """s, ds/dφ and d²s/dφ² stand one under the other with a label's room between them (no
    empty band the size of a diagram), and each diagram's scales are written where no curve
    of the panel passes."""
    from drawings.cams import draw

    motion = next(p for p in draw(path, format=fmt, language="ru").panels if p.pid == "motion")
    curves = {q.eid: q.pts for q in motion.prims if q.op == "polyline" and q.eid}
    rows = [[y for eid, pts in curves.items() if eid.endswith(f"-{tag}") or (tag == "d2s" and eid == "mid-ordinates")
             for _, y in pts] for tag in ("s", "ds", "d2s")]
    for upper, lower in zip(rows, rows[1:], strict=False):
        assert 0.0 < min(lower) - max(upper) < 25.0  # paper y grows downward
    lines = [shapely.LineString(pts) for pts in curves.values()]
    scales = [q for q in motion.prims if q.op == "text" and q.label.plain.startswith("μ") and ";" not in q.label.plain]
    assert len(scales) == 5
    for q in scales:
        assert not any(ln.intersects(shapely.box(*q.label.box)) for ln in lines), q.label.plain
