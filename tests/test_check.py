"""Checking hand-drawn sheets (plans.check): the coursework's verdicts, synthetic students,
batch mode and bad input.

Oracles are independent of the code under test: the coursework's own figures (seed 000),
closed-form slider-crank formulas, and velocities/accelerations of the V-engine by
finite differences of its closed-form positions."""

from __future__ import annotations

import cmath
import csv
import dataclasses
import json
import math
import random
from pathlib import Path

import pytest

from plans.check.checkfile import check_from_dict, parse_check
from plans.check.report import check, check_file, table
from plans.cli import main
from plans.errors import InputError

ROOT = Path(__file__).resolve().parent.parent
SCENE = ROOT / "samples" / "v_engine.toml"
COURSEWORK = ROOT / "samples" / "checks" / "v_engine_coursework.toml"

R, L, RATIO = 0.035, 0.1207, 0.33
OMEGA = 3400 * math.pi / 30
MU_V, MU_A = 6.58, 0.0185


# --------------------------------------------------------------------------- oracles


def slider_accel(theta: float) -> float:
    """|a| of a slider-crank's slider, θ from the cylinder axis (closed form, ω const)."""
    lam = R / L
    s2 = math.sin(theta) ** 2
    return abs(R * OMEGA**2 * (math.cos(theta)
                               + (lam * math.cos(2 * theta) + lam**3 * s2 * s2) / (1 - lam**2 * s2) ** 1.5))


def slider_speed(theta: float) -> float:
    lam = R / L
    return abs(R * OMEGA * (math.sin(theta) + lam * math.sin(2 * theta)
                            / (2 * math.sqrt(1 - lam**2 * math.sin(theta) ** 2))))


def positions(theta1: float) -> dict[str, complex]:
    """The V-engine from closed forms: cylinder B on the 45° axis, C on 135°."""
    A = R * cmath.exp(1j * theta1)
    out = {"O": 0j, "A": A}
    for name, axis in (("B", math.pi / 4), ("C", 3 * math.pi / 4)):
        t = theta1 - axis
        s = R * math.cos(t) + math.sqrt(L**2 - (R * math.sin(t)) ** 2)
        out[name] = s * cmath.exp(1j * axis)
    out["S2"] = A + RATIO * (out["B"] - A)
    out["S4"] = A + RATIO * (out["C"] - A)
    return out


def oracle(phi_deg: float) -> dict[str, float]:
    """Magnitudes by finite differences of positions (θ1 = 45° + φ, ω1 constant)."""
    th = math.radians(45 + phi_deg)
    h = 1e-4
    p0, pp, pm = positions(th), positions(th + h), positions(th - h)
    v = {k: (pp[k] - pm[k]) / (2 * h) * OMEGA for k in p0}
    a = {k: (pp[k] - 2 * p0[k] + pm[k]) / h**2 * OMEGA**2 for k in p0}

    def ang(p: dict[str, complex], x: str, y: str) -> float:
        return cmath.phase(p[y] - p[x])

    out: dict[str, float] = {}
    for k in ("A", "B", "C", "S2", "S4"):
        out[f"v_{k}"] = abs(v[k])
        out[f"a_{k}"] = abs(a[k])
    for link, (P, Q) in ((2, ("A", "B")), (4, ("A", "C"))):
        w = (ang(pp, P, Q) - ang(pm, P, Q)) / (2 * h) * OMEGA
        e = (ang(pp, P, Q) - 2 * ang(p0, P, Q) + ang(pm, P, Q)) / h**2 * OMEGA**2
        out[f"omega_{link}"] = abs(w)
        out[f"eps_{link}"] = abs(e)
        out[f"v_{Q}{P}"] = abs(v[Q] - v[P])
        out[f"a_{Q}{P}^n"] = w * w * L
        out[f"a_{Q}{P}^τ"] = abs(e) * L
    return out


def test_oracle_agrees_with_closed_forms():
    o45, o0 = oracle(45), oracle(0)
    assert o45["v_B"] == pytest.approx(slider_speed(math.radians(45)), rel=1e-6)
    assert o45["a_B"] == pytest.approx(slider_accel(math.radians(45)), rel=1e-5)
    assert o0["a_C"] == pytest.approx(slider_accel(math.radians(90)), rel=1e-5)
    assert o0["v_B"] == pytest.approx(0.0, abs=1e-6)


# --------------------------------------------------------------------------- the coursework


@pytest.fixture(scope="module")
def coursework():
    return check_file(COURSEWORK)


def _items(report, quantity, phi):
    return [i for i in report.items if i.quantity == quantity and i.phi_deg == phi]


def test_coursework_velocities_pass(coursework):
    vel = [i for i in coursework.items if i.quantity.startswith(("v_", "omega_"))]
    assert len(vel) >= 20
    assert all(i.verdict == "pass" for i in vel), [(i.quantity, i.phi_deg) for i in vel if i.verdict == "fail"]
    # the student's 70 mm for p_v b against the closed form at μv = 6.58
    vb = _items(coursework, "v_B", 45)[0]
    assert vb.exact == pytest.approx(slider_speed(math.radians(45)), rel=1e-6)
    assert vb.error_mm == pytest.approx(70 - MU_V * slider_speed(math.radians(45)), abs=1e-6)


def test_coursework_dead_position_acceleration_fails(coursework):
    ac = _items(coursework, "a_C", 0)[0]
    exact = slider_accel(math.radians(90))  # C's crank is ⟂ to its cylinder at φ = 0
    assert ac.exact == pytest.approx(exact, rel=1e-6)
    assert ac.verdict == "fail"
    assert ac.error_pct == pytest.approx(100 * (17.5 / MU_A - exact) / exact, rel=1e-6)
    assert ac.error_pct < -25  # "off by ~30 %"
    assert ac.error_mm == pytest.approx(17.5 - MU_A * exact, abs=1e-6)
    assert _items(coursework, "a_S4", 0)[0].verdict == "fail"
    assert _items(coursework, "a_B", 0)[0].verdict == "pass"  # 105.8 mm is good


def test_coursework_reactions_and_balancing_fail(coursework):
    for q in ("F_12", "F_63", "F_32", "F_14", "F_54", "F_bal", "F_bal_lever"):
        it = _items(coursework, q, 45)[0]
        assert it.verdict == "fail", q
        assert it.tolerance_model == "rule"
    assert abs(_items(coursework, "F_63", 45)[0].error_pct) > 200
    bal = _items(coursework, "F_bal", 45)[0]
    lever = _items(coursework, "F_bal_lever", 45)[0]
    assert bal.exact == lever.exact  # exactly the two methods agree


def test_coursework_findings(coursework):
    kinds = {f.kind for f in coursework.findings}
    assert {"duplicate", "relation", "percent", "symmetry", "pi"} <= kinds
    msgs = "\n".join(f.message for f in coursework.findings)
    # ω1² l_OA written as 4433.27 and later 3868.7
    assert any(f.kind == "duplicate" and "a_A" in f.quantities and "4433.27" in f.message and "3868.7" in f.message
               for f in coursework.findings)
    # the inertia moment 68 N·m and later 27.6 N·m
    assert any(f.kind == "duplicate" and "M_Phi_2" in f.quantities and "68" in f.message and "27.6" in f.message
               for f in coursework.findings)
    # 6.18 % recomputed with the lever's force as the base: 100·(2112 − 1989)/2112
    pct = coursework.findings_of("percent")
    assert len(pct) == 1
    assert f"{100 * (2112 - 1989) / 2112:.4g}" in pct[0].message
    assert "denominator" in pct[0].message
    # a_B and a_C at the symmetric 45° position: 57 mm and 59 mm
    assert any(set(f.quantities) == {"a_B", "a_C"} and f.phi_deg == 45 for f in coursework.findings_of("symmetry"))
    # ω1 = 3.14·3400/30
    assert any("omega_1" in f.quantities for f in coursework.findings_of("pi"))
    # each finding says where
    for f in coursework.findings:
        assert f.where and all(isinstance(w, str) for w in f.where), f
    assert "3.2.2" in msgs and "4.6" in msgs


def test_coursework_report_json_and_table(coursework, tmp_path):
    out = tmp_path / "r.json"
    assert main(["check", str(COURSEWORK), "--json", str(out), "--quiet"]) == 0
    data = json.loads(out.read_text(encoding="utf-8"))
    assert {"items", "findings", "summary"} <= set(data)
    for it in data["items"]:
        assert {"quantity", "phi_deg", "student", "exact", "error_pct", "verdict"} <= set(it)
        assert it["verdict"] in ("pass", "fail")
    for f in data["findings"]:
        assert f["kind"] and f["message"]
    text = table(coursework)
    assert "FAIL" in text and "Findings" in text


# --------------------------------------------------------------------------- synthetic students


def student_data(seed: int, *, noise: float = 0.3, mu_v_used: float = MU_V, mu_v_drawn: float = MU_V,
                 swap: tuple[str, str] | None = None, pi: float | None = None) -> dict:
    """A student who measures an exact drawing to ±noise mm and computes like the course."""
    rng = random.Random(seed)
    positions_ = []
    for phi in (45.0, 0.0):
        o = oracle(phi)

        def measure(x: float, mu: float) -> float:
            return max(0.0, round(x * mu + rng.uniform(-noise, noise), 1))

        meas: dict[str, float] = {}
        vals: dict[str, float] = {}
        for q in ("v_A", "v_B", "v_C", "v_S2", "v_S4", "v_BA", "v_CA"):
            meas[q] = measure(o[q] * mu_v_drawn / MU_V, MU_V)
        for q in ("a_A", "a_B", "a_C", "a_S2", "a_S4", "a_BA^τ", "a_CA^τ"):
            meas[q] = measure(o[q], MU_A)
        if swap:
            meas[swap[0]], meas[swap[1]] = meas[swap[1]], meas[swap[0]]
        for q, mm in meas.items():
            mu = mu_v_used if q.startswith("v_") else MU_A
            vals[q] = float(f"{mm / mu:.4g}")
        for link, (P, Q) in ((2, ("A", "B")), (4, ("A", "C"))):
            v_rel = meas[f"v_{Q}{P}"] / mu_v_used
            vals[f"omega_{link}"] = float(f"{v_rel / L:.4g}")
            an = v_rel**2 / L  # computed from the student's own v_BA, then laid off
            vals[f"a_{Q}{P}^n"] = float(f"{an:.4g}")
            meas[f"a_{Q}{P}^n"] = round(an * MU_A, 1)
            vals[f"eps_{link}"] = float(f"{meas[f'a_{Q}{P}^τ'] / MU_A / L:.4g}")
        w1 = (pi or math.pi) * 3400 / 30
        vals["omega_1"] = round(w1, 2)
        # the crank's vectors are computed, then laid off (to 0.1 mm)
        vals["v_A"] = float(f"{w1 * R:.4g}")
        vals["a_A"] = float(f"{w1 * w1 * R:.4g}")
        meas["v_A"] = round(vals["v_A"] * mu_v_drawn, 1)
        meas["a_A"] = round(vals["a_A"] * MU_A, 1)
        positions_.append({"phi_deg": phi, "measured": meas, "values": vals})
    return {"format": 1, "student": f"synthetic {seed}", "scene": str(SCENE),
            "scales": {"velocity": {"mu": MU_V}, "acceleration": {"K": 1 / MU_A}},
            "positions": positions_}


@pytest.mark.parametrize("seed", range(6))
def test_synthetic_student_passes_everything(seed):
    rep = check(check_from_dict(student_data(seed), "synthetic.toml"))
    assert len(rep.items) > 40
    assert [(i.quantity, i.phi_deg) for i in rep.items if i.verdict == "fail"] == []
    assert [f.message for f in rep.findings] == []


def test_swapped_segments_are_caught():
    rep = check(check_from_dict(student_data(1, swap=("v_B", "v_BA")), "swapped.toml"))
    fails = {(i.quantity, i.phi_deg) for i in rep.items if i.verdict == "fail"}
    assert ("v_B", 45.0) in fails and ("v_BA", 45.0) in fails
    sw = [f for f in rep.findings_of("swapped") if f.phi_deg == 45.0]
    assert sw and set(sw[0].quantities) == {"v_B", "v_BA"}
    assert "swapped" in sw[0].message


def test_values_divided_by_a_wrong_scale_are_caught():
    rep = check(check_from_dict(student_data(2, mu_v_used=6.0), "scale.toml"))
    sc = rep.findings_of("scale")
    assert len(sc) == 1 and "6.58" in sc[0].message and "wrong scale" in sc[0].message
    assert any(i.verdict == "fail" and i.quantity == "v_B" and i.figure == "value" for i in rep.items)
    # the drawing itself is right: the measured segments pass
    assert all(i.verdict == "pass" for i in rep.items if i.figure == "measured")


def test_plans_drawn_at_another_scale_are_caught():
    rep = check(check_from_dict(student_data(3, mu_v_drawn=7.0, mu_v_used=7.0), "drawn.toml"))
    sc = [f for f in rep.findings_of("scale") if "drawn at" in f.message]
    assert len(sc) == 1 and "μv = 7" in sc[0].message


def test_pi_314_is_caught():
    rep = check(check_from_dict(student_data(4, pi=3.14), "pi.toml"))
    found = rep.findings_of("pi")
    assert {f.phi_deg for f in found} == {45.0, 0.0}
    assert all("π = 3.14" in f.message and f.quantities == ("omega_1",) for f in found)
    # within the drawing tolerance: only the finding tells
    assert all(i.verdict == "pass" for i in rep.items if i.quantity == "omega_1")


def test_rule_model_uses_the_course_percentage():
    data = student_data(5)
    data["tolerance"] = {"model": "rule", "rule_pct": 5}
    rep = check(check_from_dict(data, "rule.toml"))
    assert {i.tolerance_model for i in rep.items} == {"rule"}
    it = next(i for i in rep.items if i.quantity == "a_B" and i.phi_deg == 45)
    assert it.tolerance == pytest.approx(0.05 * slider_accel(math.radians(45)), rel=1e-6)


def test_short_vector_gets_a_wider_percentage_than_a_long_one():
    rep = check(check_from_dict(student_data(0), "s.toml"))
    short = next(i for i in rep.items if i.quantity == "a_BA^n" and i.phi_deg == 45)  # ~12 mm
    long_ = next(i for i in rep.items if i.quantity == "a_A" and i.phi_deg == 45)  # ~82 mm
    assert short.tolerance_pct > 3 * long_.tolerance_pct


# --------------------------------------------------------------------------- batch


def _write(path: Path, text: str) -> Path:
    path.write_text(text, encoding="utf-8")
    return path


def test_batch_folder(tmp_path, capsys):
    group = tmp_path / "group"
    group.mkdir()
    cw = COURSEWORK.read_text(encoding="utf-8").replace('scene = "../v_engine.toml"', f'scene = "{SCENE}"')
    _write(group / "rozenenkov.toml", cw)
    good = student_data(0)

    lines = [f'format = 1\nstudent = "Good"\nscene = "{SCENE}"\n[scales]\nvelocity = {MU_V}\nacceleration = {MU_A}\n']
    for pos in good["positions"]:
        lines.append(f"[[positions]]\nphi_deg = {pos['phi_deg']}\n[positions.measured]\n")
        lines += [f'"{k}" = {v}\n' for k, v in pos["measured"].items()]
        lines.append("[positions.values]\n")
        lines += [f'"{k}" = {v}\n' for k, v in pos["values"].items()]
    _write(group / "good.toml", "".join(lines))
    _write(group / "bad.toml", cw.replace("velocity = { mu = 6.58 }", "velocity = { mu = 0 }"))
    out = tmp_path / "reports"
    rc = main(["check", str(group), "--out", str(out)])
    assert rc == 2  # one file could not be checked
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) == 1 and "bad.toml" in err[0] and "scales.velocity" in err[0]
    rows = list(csv.DictReader((out / "summary.csv").open(encoding="utf-8")))
    assert [r["status"] for r in rows] == ["error", "ok", "ok"]
    assert rows[2]["student"].startswith("Розененков") and int(rows[2]["failed"]) > 0
    assert rows[1]["failed"] == "0"
    assert sorted(p.name for p in out.iterdir()) == ["good.json", "good.txt", "rozenenkov.json", "rozenenkov.txt",
                                                     "summary.csv"]


# --------------------------------------------------------------------------- bad input


def _cw(**replace: str) -> str:
    text = COURSEWORK.read_text(encoding="utf-8").replace('scene = "../v_engine.toml"', f'scene = "{SCENE}"')
    for old, new in replace.items():
        assert old in text
        text = text.replace(old, new)
    return text


@pytest.mark.parametrize("old,new,match", [
    ('v_B = { mm = 70, where = "3.1.2" }', 'v_Z = { mm = 70, where = "3.1.2" }', r"no quantity 'v_Z'"),
    ("velocity = { mu = 6.58 }", "velocity = { mu = 0 }", r"scales\.velocity\.mu: .*scale of zero"),
    ("phi_deg = 45", "phi_deg = 30", r"\[\[positions\]\] entry 1, phi_deg: position 30° is not in the scene"),
    ('h_Phi2_B = { value = "65 mm"', "h_Phi2_B = { value = 65", r"h_Phi2_B: a length needs its unit"),
    ("format = 1", "format = 2", r"format: expected format = 1"),
    ('scene = "', 'scene = "missing/', r"scene: scene file"),
])
def test_bad_input_one_line(old, new, match, tmp_path):
    path = _write(tmp_path / "bad.toml", _cw(**{old: new}) if old != 'scene = "' else
                  COURSEWORK.read_text(encoding="utf-8").replace('scene = "../', 'scene = "missing/'))
    with pytest.raises(InputError, match=match):
        check_file(path)


def test_bad_input_cli_exit_2_and_nothing_written(tmp_path, capsys):
    path = _write(tmp_path / "bad.toml", _cw(**{"velocity = { mu = 6.58 }": "velocity = { mu = 0 }"}))
    out = tmp_path / "r.json"
    assert main(["check", str(path), "--json", str(out)]) == 2
    err = capsys.readouterr().err
    assert err.count("\n") == 1 and "bad.toml" in err and "Traceback" not in err
    assert not out.exists()
    assert list(tmp_path.iterdir()) == [path]


def test_measured_segment_of_a_computed_quantity_is_refused(tmp_path):
    text = _cw(**{'v_B = { mm = 70, where = "3.1.2" }': 'v_B = { mm = 70, where = "3.1.2" }\nm_2 = 12'})
    with pytest.raises(InputError, match=r"measured\.m_2: m_2 is not read off a plan"):
        check(parse_check(text, str(tmp_path / "x.toml")))


# --------------------------------------------------------------------------- force polygons at μF


def test_force_polygon_readings_get_the_draftsman_tolerance():
    from plans.forces.polygons import analyse_forces, force_polygons
    from plans.kinematics.exact import solve
    from plans.kinematics.placing import load_scene

    mu_f = 0.02  # mm/N, the student's
    scene = load_scene(SCENE)
    scene = dataclasses.replace(scene, scales={**scene.scales, "force": mu_f})
    fa = analyse_forces(scene, solve(scene, order=2))
    polys = force_polygons(fa, 0)  # φ = 45°, the scene's first position
    seg = {s.label: s.length_mm for fp in polys for s in fp.plan.segments}
    data = student_data(0)
    data["scales"]["force"] = {"mu": mu_f}
    rng = random.Random(7)
    measured = {"F_12": seg["F21"], "F_63": seg["F36"], "F_14": seg["F41"], "F_bal": seg["F_bal"]}
    data["positions"][0]["measured"].update({q: round(mm + rng.uniform(-0.3, 0.3), 1) for q, mm in measured.items()})
    rep = check(check_from_dict(data, "forces.toml"))
    for q in measured:
        it = next(i for i in rep.items if i.quantity == q)
        assert it.tolerance_model == "draftsman" and it.verdict == "pass", q
        assert it.tolerance_mm >= 0.5
    # the coursework's F63 = 362 N (4.4) is 7.2 mm at this μF; exactly it is under 2 mm: caught
    data["positions"][0]["values"]["F_63"] = 362
    del data["positions"][0]["measured"]["F_63"]
    rep = check(check_from_dict(data, "forces.toml"))
    f63 = next(i for i in rep.items if i.quantity == "F_63")
    assert f63.verdict == "fail" and f63.error_mm == pytest.approx(362 * mu_f - seg["F36"], abs=1e-9)


def test_inline_scene_slider_crank_against_closed_form():
    from .conftest import slider_crank_scene

    r, l, w, phi = 0.05, 0.18, 100.0, 30.0
    lam = r / l
    th = math.radians(phi)
    v_b = r * w * (math.sin(th) + lam * math.sin(2 * th) / (2 * math.sqrt(1 - (lam * math.sin(th)) ** 2)))
    s2 = math.sin(th) ** 2
    a_b = r * w * w * (math.cos(th) + (lam * math.cos(2 * th) + lam**3 * s2 * s2) / (1 - lam**2 * s2) ** 1.5)
    mu_v, mu_a = 15.0, 0.15  # mm per m/s, mm per m/s²
    data = {"format": 1, "student": "inline", "scene": slider_crank_scene(phi_deg=(phi,), omega=w),
            "scales": {"style": "K", "velocity": 1 / mu_v, "acceleration": 1 / mu_a},
            "positions": [{"phi_deg": phi, "measured": {"v_B": round(abs(v_b) * mu_v + 0.3, 1),
                                                        "a_B": round(abs(a_b) * mu_a - 0.3, 1)}}]}
    rep = check(check_from_dict(data, "inline.toml"))
    assert [i.verdict for i in rep.items] == ["pass", "pass"]
    assert rep.item("v_B", phi).exact == pytest.approx(abs(v_b), rel=1e-9)
    assert rep.item("a_B", phi).exact == pytest.approx(abs(a_b), rel=1e-9)
    data["positions"][0]["measured"]["a_B"] = round(abs(a_b) * mu_a * 1.1, 1)  # 10 % long
    rep = check(check_from_dict(data, "inline.toml"))
    assert rep.item("a_B", phi).verdict == "fail"
    assert rep.item("a_B", phi).error_pct == pytest.approx(10.0, abs=0.2)


def test_draftsman_tolerance_of_an_intersection_by_hand(coursework):
    """p_v b at 45°: b = line through a ⟂ AB ∩ line through p_v ∥ guide B.  By hand:
    b = t·u with t = cross(a, n)/cross(u, n); the four drawing errors (length and direction
    of p_v a, direction of each line) move |p_v b| by their partial derivatives; the worst
    case adds them, plus the reading of p_v b."""
    p = positions(math.radians(90))
    A, B = p["A"], p["B"]
    a0 = 6.58 * OMEGA * R * (1j * A / abs(A))
    n0, u0 = 1j * (B - A) / abs(B - A), cmath.exp(1j * math.pi / 4)

    def cross(x: complex, y: complex) -> float:
        return (x.conjugate() * y).imag

    def pb(dl: float = 0, da: float = 0, dn: float = 0, du: float = 0) -> float:
        a = (a0 + dl * a0 / abs(a0)) * cmath.exp(1j * da)
        n, u = n0 * cmath.exp(1j * dn), u0 * cmath.exp(1j * du)
        return abs(cross(a, n) / cross(u, n))

    h, deg = 1e-6, math.radians(0.5)
    base = pb()
    worst = sum(abs(pb(**{k: h * size}) - base) / h
                for k, size in (("dl", 0.5), ("da", deg), ("dn", deg), ("du", deg)))
    item = coursework.item("v_B", 45.0)
    assert item.exact_mm == pytest.approx(base, rel=1e-9)
    assert item.tolerance_mm == pytest.approx(worst + 0.5, rel=1e-4)
