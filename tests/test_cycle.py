"""The cycle: reduced inertia and moment against independent oracles, graphical methods
against their own error bounds, the flywheel against an independent integration of the
motion, bad input, and the seed's tables."""

from __future__ import annotations

import csv
import dataclasses
import json
import math
from pathlib import Path

import numpy as np
import pytest

from plans.check.cycle import check_cycle
from plans.cli import main
from plans.cycle.diagrams import diagrams
from plans.cycle.dynamics import dynamics, reduce
from plans.cycle.spec import diagrams_spec, dynamics_spec
from plans.errors import InputError
from plans.forces.loads import apply_loads, parse_loads
from plans.forces.polygons import analyse_forces
from plans.kinematics.exact import solve
from plans.kinematics.placing import load_scene, scene_from_dict

ROOT = Path(__file__).resolve().parents[1]
SEED = ROOT / "samples" / "dynamics_slider_crank.toml"
VENG = ROOT / "samples" / "v_engine_cycle.toml"
RNG = np.random.default_rng(4)


@pytest.fixture(scope="module")
def seed():
    sc = load_scene(SEED)
    return sc, dynamics(sc)


@pytest.fixture(scope="module")
def veng():
    sc = load_scene(VENG)
    return sc, dynamics(sc)


def _fd_velocity(scene, phis, h=1e-4):
    """Velocities by central differences of exact *positions* (an oracle apart from the
    velocity analysis): dr/dφ per point and dθ/dφ per link, φ in radians."""
    kp, km = solve(scene, phis + h, order=0), solve(scene, phis - h, order=0)
    hr = math.radians(h)

    def dr(link, z):
        return (kp.point_on(link, z)[0] - km.point_on(link, z)[0]) / (2 * hr)

    def dth(link):
        return np.angle(kp.motion[link].rot / km.motion[link].rot) / (2 * hr)

    return dr, dth


@pytest.mark.parametrize("path", [SEED, VENG], ids=["seed004", "v_engine"])
def test_I_pr_is_twice_the_kinetic_energy_over_omega1_squared(path):
    scene = load_scene(path)
    loads = parse_loads(scene)
    phis = RNG.uniform(0, 360, 9)
    red = reduce(scene, loads, solve(scene, phis, order=2), 0.37)
    dr, dth = _fd_velocity(scene, phis)
    T = np.zeros(len(phis))  # per unit ω1: T/ω1² with velocities as dr/dφ
    for lid, link in scene.links.items():
        m, inert = loads.masses[lid], loads.inertias[lid]
        if lid in loads.centres:
            T += 0.5 * m * np.abs(dr(lid, link.points[loads.centres[lid]])) ** 2
        T += 0.5 * inert * dth(lid) ** 2
    assert np.allclose(red.I_pr, 0.37 + 2 * T, rtol=1e-7, atol=0)


@pytest.mark.parametrize("path", [SEED, VENG], ids=["seed004", "v_engine"])
def test_M_pr_is_the_virtual_work_of_every_load(path):
    scene = load_scene(path)
    loads = parse_loads(scene)
    phis = RNG.uniform(0, 360, 9)
    kin = solve(scene, phis, order=2)
    red = reduce(scene, loads, kin, 0.0)
    dr, dth = _fd_velocity(scene, phis)
    work = np.zeros(len(phis))
    applied = apply_loads(scene, loads, kin)
    for f in applied.forces:
        if f.kind != "inertia":
            work += (f.F * np.conj(dr(f.link, f.local[0]))).real
    for mo in applied.moments:
        if mo.kind != "inertia":
            work += mo.M * dth(mo.link)
    scale = np.max(np.abs(red.M_pr))  # φ grows along the crank's motion: dφ/dt = |ω1|
    assert np.allclose(red.M_pr, work, rtol=0, atol=1e-7 * scale)


@pytest.mark.parametrize("path", [SEED, VENG], ids=["seed004", "v_engine"])
def test_M_pr_is_minus_the_balancing_moment_without_inertia(path):
    """Kinetostatics at a crawl (inertia ∝ ω² vanishes): the balancing moment the force
    polygons find is −M_pr."""
    scene = load_scene(path)
    slow = dataclasses.replace(scene, driver=dataclasses.replace(scene.driver, omega=scene.driver.sense * 1e-5))
    phis = RNG.uniform(0, 360, 7)
    kin = solve(slow, phis, order=2)
    fa = analyse_forces(slow, kin)
    M_bal = fa.sense * fa.crank.M_bal  # along the crank's motion
    red = reduce(slow, parse_loads(slow), kin, 0.0)
    scale = np.max(np.abs(red.M_pr))
    assert np.allclose(M_bal, -red.M_pr, rtol=0, atol=1e-6 * scale)


def test_graphical_integration_within_the_trapezoid_bound():
    """v(φ) integrated back from a(φ) by chords errs by at most (φ − φ0)·h²/12·max|f''|,
    f = dv/dφ = a/ω1, and by the Euler–Maclaurin term h²/12·(f'(φ) − f'(φ0)) to first order."""
    scene = load_scene(VENG)
    spec = diagrams_spec(scene)
    d = diagrams(scene, spec)
    g = d.get("v_B")
    w = d.omega
    h = math.radians(360.0 / len(spec.phi_deg))
    ex_phi = np.radians(d.get("a_B").exact_phi_deg)
    f = d.get("a_B").exact / w
    f2 = np.gradient(np.gradient(f, ex_phi), ex_phi)
    nodes = np.radians(d.nodes_deg - d.nodes_deg[0])
    exact_v = np.interp(d.nodes_deg, g.exact_phi_deg, g.exact)
    err = g.integral - exact_v  # m/s: v = v0 + ∫ f dφ
    bound = nodes * h**2 / 12 * np.max(np.abs(f2))
    assert np.all(np.abs(err) <= 1.02 * bound + 1e-12)
    f1 = np.interp(nodes, ex_phi - ex_phi[0], np.gradient(f, ex_phi))
    lead = h**2 / 12 * (f1 - f1[0])
    assert np.allclose(err, lead, rtol=0, atol=0.1 * np.max(np.abs(lead)))


def test_differentiation_errors_shrink_as_the_square_of_the_step():
    scene = load_scene(VENG)
    errs = {}
    for n in (12, 24, 48):
        spec = dataclasses.replace(diagrams_spec(scene), phi_deg=tuple(360.0 * k / n for k in range(n)))
        errs[n] = diagrams(scene, spec).get("v_B").error_max_pct
    assert 3.0 < errs[12] / errs[24] < 5.0 and 3.0 < errs[24] / errs[48] < 5.0


def _independent_delta(scene, I_fw, omega_m, steps=20000):
    """δ of the steady cycle by Simpson quadrature on a finer grid and bisection on E0."""
    spec = dynamics_spec(scene)
    phis = spec.phi_deg[0] + np.linspace(0, 360, steps + 1)
    red = reduce(scene, parse_loads(scene), solve(scene, phis, order=2), spec.rotor_inertia)
    x = np.radians(phis - phis[0])
    M = red.M_pr
    A = np.zeros(steps + 1)
    A[2::2] = np.cumsum((x[2::2] - x[:-2:2]) / 6 * (M[:-2:2] + 4 * M[1:-1:2] + M[2::2]))
    A[1::2] = A[:-1:2] + (x[1::2] - x[:-1:2]) / 2 * (M[:-1:2] + M[1::2])  # odd nodes: only for the extremes
    dT = A - A[-1] * x / x[-1]
    J = I_fw + red.I_pr
    lo, hi = -np.min(dT) + 1e-12, 1e3 * (omega_m**2 * np.max(J) + np.ptp(dT))
    for _ in range(200):
        E0 = 0.5 * (lo + hi)
        om = np.sqrt(2 * (E0 + dT) / J)
        if 0.5 * (om.max() + om.min()) > omega_m:
            hi = E0
        else:
            lo = E0
    return (om.max() - om.min()) / omega_m


@pytest.mark.parametrize("which", ["seed", "veng"])
def test_flywheel_achieves_delta(which, seed, veng):
    scene, d = seed if which == "seed" else veng
    fw = d.flywheel
    assert fw.inertia_exact > 0
    assert abs(fw.delta_achieved - fw.delta) <= 0.05 * fw.delta  # graphical: within 5 %
    assert abs(fw.delta_achieved_exact - fw.delta) <= 1e-6 * fw.delta
    ind = _independent_delta(scene, fw.inertia_exact, fw.omega_mean)
    assert abs(ind - fw.delta) <= 1e-6 * fw.delta
    ind_g = _independent_delta(scene, fw.inertia_graphical, fw.omega_mean)
    assert ind_g == pytest.approx(fw.delta_achieved, rel=1e-5)


def test_seed_004_tables_recovered(seed):
    """The recovered dimensions give the seed's tables 1.2 and 1.4 back (the seed's own
    rounding: I_pr to 1 %, M_pr to 2.5 % where it is not small)."""
    _, d = seed
    phis = list(d.table.phi_deg)
    seed_I = {0: 2.2317, 30: 2.535, 60: 3.059, 90: 3.154, 120: 2.79, 150: 2.391, 180: 2.232, 210: 2.358,
              240: 2.723, 270: 3.154, 300: 3.123, 330: 2.589}
    seed_M = {30: 83.084, 60: 138.319, 90: 147.935, 120: 117.444, 150: 64.968, 210: -78.605, 240: -215.915,
              270: -437.935, 300: -781.215, 330: -934.024}
    for phi, v in seed_I.items():
        assert d.table.I_pr[phis.index(phi)] == pytest.approx(v, rel=0.01)
    for phi, v in seed_M.items():
        assert d.table.M_pr[phis.index(phi)] == pytest.approx(v, rel=0.025)


def test_json_dynamics_block(tmp_path, seed):
    out = tmp_path / "s.json"
    assert main(["solve", str(SEED), "--json", str(out), "--quiet"]) == 0
    data = json.loads(out.read_text())
    dyn = data["dynamics"]
    assert len(dyn["phi_deg"]) == len(dyn["I_pr"]) == len(dyn["M_pr"]) == 14
    assert set(dyn["flywheel"]) >= {"delta", "omega_mean", "inertia_exact", "inertia_graphical", "delta_achieved"}
    assert dyn["flywheel"]["inertia_exact"] == pytest.approx(seed[1].flywheel.inertia_exact)
    assert "cycle" in data and data["cycle"]["tables"][0]["phi_deg"] == dyn["phi_deg"]
    again = tmp_path / "t.json"
    main(["solve", str(SEED), "--json", str(again), "--quiet"])
    assert again.read_bytes() == out.read_bytes()


def test_csv_has_a_column_per_position(tmp_path):
    out = tmp_path / "t.csv"
    assert main(["solve", str(SEED), "--csv", str(out), "--quiet"]) == 0
    lines = out.read_text().splitlines()
    head = next(x for x in lines if x.startswith("quantity,"))
    assert len(head.split(",")) == 3 + 14
    assert any(x.startswith("I_pr,") for x in lines) and any(x.startswith("M_pr,") for x in lines)


def _seed_dict():
    import tomllib

    return tomllib.loads(SEED.read_text())


@pytest.mark.parametrize("change, field", [
    ({"dynamics": {"delta": 0.0}}, "dynamics.delta"),
    ({"dynamics": {"delta": 1.0}}, "dynamics.delta"),
    ({"dynamics": {"delta": 0.05, "phi_deg": [0, 30, 60, 90]}}, "dynamics.phi_deg"),
    ({"dynamics": {"delta": 0.05, "phi_deg": [0, 90, 180, 170]}}, "dynamics.phi_deg"),
    ({"dynamics": {"delta": 0.05, "driving": "variable"}}, "dynamics.driving"),
    ({"dynamics": {"delta": 0.05, "driving": 100.0}}, "dynamics.driving"),
    ({"dynamics": {"delta": 0.05, "rotor": 1}}, "dynamics.rotor"),
    ({"diagrams": {"points": ["C"], "phi_deg": [0, 30, 60, 90, 120]}}, "diagrams.phi_deg"),
    ({"diagrams": {"points": ["C"], "phi_deg": [0, 10, 30, 90, 180, 270]}}, "diagrams.phi_deg"),
    ({"diagrams": {"points": ["Q"]}}, "diagrams.points"),
    ({"diagrams": {"points": ["C"], "quantities": ["j"]}}, "diagrams.quantities"),
])
def test_bad_input_names_the_key(change, field):
    data = _seed_dict()
    data.update(change)
    data["outputs"] = ["positions", "dynamics", "diagrams"]
    data.setdefault("diagrams", {"points": ["C"]})
    scene = scene_from_dict(data, "bad.toml")
    with pytest.raises(InputError) as exc:
        if field.startswith("dynamics"):
            dynamics(scene)
        else:
            diagrams(scene)
    assert exc.value.field == field and "\n" not in str(exc.value)


def test_a_flywheel_of_a_scene_with_no_loads(tmp_path, capsys):
    data = _seed_dict()
    data["loads"] = {"gravity": False}
    bad = tmp_path / "free.toml"
    import tomllib  # noqa: F401  (the dict goes back out as TOML through a tiny writer)

    text = SEED.read_text().split("[loads]")[0] + "[loads]\ngravity = false\n"
    bad.write_text(text)
    assert main(["solve", str(bad)]) == 2
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) == 1 and "loads" in err[0]


def test_cycle_check_of_the_seed_tables(tmp_path):
    from plans.check.cycle import check_cycle

    rep = check_cycle(ROOT / "samples" / "checks" / "dynamics_seed004.toml")
    assert len(rep.items) == 14 * 20 - 56  # every figure of tables 1.1–1.4
    assert rep.passed > 0.85 * len(rep.items)
    by = {(i.quantity, i.phi_deg): i for i in rep.items}
    assert by[("pc", 181.851)].verdict == "fail"  # position 7 drawn off the dead centre
    assert by[("M_pr", 270.0)].verdict == "pass" and by[("I_pr", 90.0)].verdict == "pass"
    out = tmp_path / "r.json"
    assert main(["check", str(ROOT / "samples" / "checks" / "dynamics_seed004.toml"), "--json", str(out),
                 "--quiet"]) == 0
    assert json.loads(out.read_text())["summary"]["items"] == len(rep.items)


def test_cycle_check_passes_a_student_who_wrote_exact_figures(tmp_path):
    """Figures from finite differences of exact positions (not from the code under test)."""
    from plans.check.cycle import check_cycle

    scene = load_scene(SEED)
    phis = np.array([15.0, 100.0, 250.0])
    dr, _ = _fd_velocity(scene, phis)
    w = abs(scene.driver.omega)
    vC = np.abs(dr(3, 0j)) * w
    vB = np.abs(dr(1, scene.links[1].points["B"])) * w
    mu = 125.0
    def arr(a):
        return json.dumps([float(x) for x in a])

    text = (f'format = 1\nstudent = "synthetic"\nscene = "{SEED}"\n[cycle]\nphi_deg = {arr(phis)}\n'
            f'velocity_scale = {{ mu = {mu} }}\n[cycle.measured]\npc = {arr(vC * mu)}\npb = {arr(vB * mu)}\n'
            f'[cycle.values]\nv_C = {arr(vC)}\n')
    f = tmp_path / "c.toml"
    f.write_text(text)
    rep = check_cycle(f)
    assert len(rep.items) == 9 and rep.failed == 0
    assert max(i.error_pct for i in rep.items) < 1e-4


def test_cycle_check_bad_row_names_the_key(tmp_path):
    from plans.check.cycle import check_cycle

    f = tmp_path / "c.toml"
    f.write_text(f'format = 1\nscene = "{SEED}"\n[cycle]\nphi_deg = [0, 30]\n[cycle.values]\nI_pr = [1]\n')
    with pytest.raises(InputError) as exc:
        check_cycle(f)
    assert exc.value.field == "cycle.values.I_pr"


def test_diagram_objects_are_frozen_data(veng):
    d = diagrams(load_scene(VENG))
    g = d.get("v_B")
    assert g.phi_deg.shape == g.values.shape and g.scale > 0 and g.pole_mm == d.pole_mm
    with pytest.raises(ValueError):
        g.values[0] = 1.0
    with pytest.raises(dataclasses.FrozenInstanceError):
        g.scale = 2.0  # type: ignore[misc]
    with pytest.raises(ValueError):
        veng[1].table.I_pr[0] = 0.0


def test_drawing_adds_the_cycle_sheets_numbered_on():
    from drawings.linkage import draw

    d = draw(VENG)
    kinds = [{p.kind for p, _, _ in sh.placed} for sh in d.sheets]
    assert any("diagram" in k for k in kinds) and any("dynamics" in k for k in kinds)
    assert [sh.number for sh in d.sheets] == list(range(1, len(d.sheets) + 1))
    assert all(sh.count == len(d.sheets) for sh in d.sheets)
    again = draw(VENG)
    assert [s.svg() for s in again.sheets] == [s.svg() for s in d.sheets]  # same input, same bytes


def test_cycle_table_columns_are_the_positions_readings(tmp_path):
    """The table over the positions carries, column by column, what each position's plans read."""
    out = tmp_path / "s.json"
    assert main(["solve", str(ROOT / "samples" / "six_bar.toml"), "--json", str(out), "--quiet"]) == 0
    data = json.loads(out.read_text())
    table = data["cycle"]["tables"][0]
    assert table["phi_deg"] == [p["phi_deg"] for p in data["positions"]]
    rows = {r["key"]: r["values"] for r in table["rows"]}
    for k, pos in enumerate(data["positions"]):
        for r in pos["readings"]:
            assert rows[r["quantity"]][k] == pytest.approx(r["value"], abs=1e-12)
            if r["length_mm"] is not None:
                assert rows[r["quantity"] + ":mm"][k] == pytest.approx(r["length_mm"], abs=1e-12)


def test_a_machine_without_inertia_gets_the_flywheel_that_is_all_its_inertia():
    """No masses, no rotor: I_fw = (ΔT_max − ΔT_min)/(ω_m² δ); the force at S2 is constant,
    so ΔT = F·(r_S2 − r_S2(φ0)) (a potential, M_d = 0) and its range is F·(y_max − y_min)."""
    data = _seed_dict()
    for lid in ("2", "3"):
        data["links"][lid].pop("mass", None)
        data["links"][lid].pop("inertia", None)
    data["links"]["2"].pop("centre", None)
    data["dynamics"]["rotor_inertia"] = 0.0
    data["loads"] = {"gravity": False, "moment": [{"link": 1, "value": 0.0}],
                     "force": [{"link": 2, "point": "S2", "vector": [0, -100]}]}
    scene = scene_from_dict(data, "bare.toml")
    d = dynamics(scene)
    assert np.all(d.exact.I_pr == 0)
    assert abs(d.M_driving_exact) < 1e-9
    phis = np.linspace(0.0, 360.0, 36001)
    y = solve(scene, phis, order=0).point("S2")[0].imag
    ext = []
    for k in (int(np.argmax(y)), int(np.argmin(y))):  # refine each extreme on a 1e-5° grid
        fine = np.linspace(phis[k] - 0.01, phis[k] + 0.01, 2001)
        yf = solve(scene, fine, order=0).point("S2")[0].imag
        ext.append(float(yf.max() if k == int(np.argmax(y)) else yf.min()))
    w = abs(scene.driver.omega)
    assert d.flywheel.inertia_exact == pytest.approx(100 * (ext[0] - ext[1]) / (w**2 * 0.05), rel=1e-9)


CHECK = ROOT / "samples" / "checks" / "dynamics_seed004.toml"


@pytest.mark.parametrize("which, old, new, field", [
    ("scene", "phi_deg = [0, 1.096", "phi_deg = [0, 5e-324", "dynamics.phi_deg: expected crank angles increasing"),
    ("scene", "delta = 0.05", "delta = 5e-324", "dynamics.delta: expected 1e-06 <= δ < 1"),
    ("check", "rule_pct = 5", "rule_pct = {K = 1e-300}", "cycle.rule_pct: expected a number"),
    ("check", "phi_deg = [0, 30", "phi_deg = [" + "9" * 400 + ", 30", "cycle.phi_deg: expected a number of magnitude"),
    ("check", "velocity_scale = { mu = 125 }", "velocity_scale = { K = 1e-300 }", "cycle.velocity_scale.K"),
])
def test_bad_input_from_the_console_is_one_line(tmp_path, capsys, which, old, new, field):
    if which == "scene":
        head, tail = SEED.read_text(encoding="utf-8").split("[dynamics]", 1)
        assert old in tail
        text = head + "[dynamics]" + tail.replace(old, new, 1)
        command = ["solve", "--quiet"]
    else:
        text = CHECK.read_text(encoding="utf-8")
        assert old in text
        text = text.replace(old, new, 1).replace('scene = "', f'scene = "{CHECK.parent.as_posix()}/', 1)
        command = ["check", "--quiet"]
    bad = tmp_path / "bad.toml"
    bad.write_text(text, encoding="utf-8")
    out = tmp_path / "out.json"
    assert main([command[0], str(bad), "--json", str(out), *command[1:]]) == 2
    err = capsys.readouterr().err
    lines = err.strip().splitlines()
    assert len(lines) == 1 and field in lines[0] and "bad.toml" in lines[0] and "Traceback" not in err, err
    assert not out.exists()


def test_a_folder_of_sheet_and_cycle_check_files(tmp_path, capsys):
    group, out = tmp_path / "group", tmp_path / "reports"
    group.mkdir()
    for name, scene in (("dynamics_seed004", "dynamics_slider_crank"), ("v_engine_coursework", "v_engine")):
        text = (ROOT / "samples" / "checks" / f"{name}.toml").read_text(encoding="utf-8")
        (group / f"{name}.toml").write_text(text.replace(f'"../{scene}.toml"', f'"{ROOT / "samples" / scene}.toml"'),
                                            encoding="utf-8")
    assert main(["check", str(group), "--out", str(out), "--quiet"]) == 0
    rows = {r["file"]: r for r in csv.DictReader((out / "summary.csv").open(encoding="utf-8"))}
    cyc = rows[str(group / "dynamics_seed004.toml")]
    single = check_cycle(ROOT / "samples" / "checks" / "dynamics_seed004.toml")
    assert cyc["status"] == "ok" and (int(cyc["passed"]), int(cyc["failed"])) == (single.passed, single.failed)
    assert json.loads((out / "dynamics_seed004.json").read_text(encoding="utf-8"))["kind"] == "cycle"
    assert rows[str(group / "v_engine_coursework.toml")]["status"] == "ok"
