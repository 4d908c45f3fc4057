"""One solved object that every reader takes: ``plans.solve`` once, values by their textbook
names with one sign convention, tables validated when the scene is read, sheets that only
draw what was solved."""

from __future__ import annotations

import copy
import math
import subprocess
import sys
from pathlib import Path
from types import SimpleNamespace

import pytest

import plans
from plans import quantities
from plans.io import read_toml
from plans.kinds import read_kind
from plans.kinematics.placing import load_scene, scene_from_dict
from plans.results import to_json

ROOT = Path(__file__).resolve().parent.parent
SAMPLES = ROOT / "samples"
V_ENGINE = SAMPLES / "v_engine.toml"
#: every linkage sample, those of the folders (instant centres, class III, a project, a flywheel) too
LINKAGES = [p for p in sorted(SAMPLES.rglob("*.toml")) if "checks" not in p.parts and read_kind(p)[0] == "linkage"]


@pytest.fixture(scope="module")
def v_engine():
    return plans.solve(V_ENGINE)


def _xy(z: complex) -> list[float]:
    return [z.real, z.imag]


# --------------------------------------------------------------------------- values by name


def test_reaction_components_rebuild_the_jsons_vector_in_both_orders(v_engine):
    """F_ij^τ e_τ + F_ij^n e_n is the reaction the JSON writes under F_ij (written by its own
    code from the polygons' vectors), for both orders: F_12^τ = −F_21^τ, and on the V-engine
    at 45° F_12 along e_τ is +2111.3 N (F_21's is −2111.3 N)."""
    data = to_json(v_engine)
    fa = v_engine.forces.analysis
    checked = 0
    for k, phi in enumerate(v_engine.scene.driver.phis_deg):
        written = data["positions"][k]["reactions"]
        for rc in fa.reactions():
            if rc.tau is None:
                continue
            for i, j in ((rc.on, rc.frm), (rc.frm, rc.on)):
                name = quantities.reaction_label(i, j)
                tau, n = v_engine.value(name + "^τ", phi), v_engine.value(name + "^n", phi)
                F = tau * complex(rc.e_tau[k]) + n * complex(rc.e_n[k])
                want = complex(*written[f"F{i}{j}"])
                assert abs(F - want) <= 1e-9 * abs(want)
                assert v_engine.value(name, phi) == pytest.approx(abs(want), rel=1e-12)
                checked += 1
    assert checked >= 8
    assert v_engine.value("F_12^τ", 45) == pytest.approx(2111.2957824667, rel=1e-9)
    assert v_engine.value("F_21^τ", 45) == -v_engine.value("F_12^τ", 45)


def test_the_reaction_read_in_the_other_order_is_that_links_reaction(v_engine):
    """fa.reaction("F12") gives −F21 and the reaction of link 1 on 2 with its own τ and n."""
    fa = v_engine.forces.analysis
    F21, rc21 = fa.reaction("F21")
    F12, rc12 = fa.reaction("F12")
    assert (F12 == -F21).all() and (rc12.F == F12).all()
    assert (rc12.tau == -rc21.tau).all() and (rc12.n == -rc21.n).all()
    assert (rc12.on, rc12.frm) == (rc21.frm, rc21.on)


def test_rates_and_vectors_by_name_are_the_exact_motions(v_engine):
    """omega and eps signed counter-clockwise as the JSON writes them; v_B read off the
    velocity plan is |v_B| of the exact motion; a_BA^τ off the acceleration plan is |ε2|·l_AB."""
    data = to_json(v_engine)
    for k, phi in enumerate(v_engine.scene.driver.phis_deg):
        pos = data["positions"][k]
        assert v_engine.value("omega_2", phi) == pos["links"]["2"]["omega"]
        assert v_engine.value("eps_2", phi) == pos["links"]["2"]["eps"]
        assert v_engine.value("v_B", phi) == pytest.approx(math.hypot(*pos["points"]["B"]["v"]), rel=1e-9)
        l_ab = abs(complex(*pos["points"]["B"]["r"]) - complex(*pos["points"]["A"]["r"]))
        a_a = math.hypot(*pos["points"]["A"]["a"])  # the plan's size: a zero reads as its round-off
        assert v_engine.value("a_BA^τ", phi) == pytest.approx(abs(pos["links"]["2"]["eps"]) * l_ab, rel=1e-9,
                                                               abs=1e-12 * a_a)
        assert v_engine.value("a_AB^τ", phi) == v_engine.value("a_BA^τ", phi)
        assert v_engine.value("l_AB", phi) == pytest.approx(l_ab, rel=1e-12)
    assert v_engine.values("omega_1") == [p["links"]["1"]["omega"] for p in data["positions"]]


def test_every_listed_name_reads_and_an_unknown_one_names_the_known(v_engine):
    names = v_engine.names()
    assert {"v_B", "a_BA^n", "omega_2", "eps_2", "F_21^τ", "F_bal", "M_Phi_2", "Phi_2"} <= set(names)
    for name in names:
        assert math.isfinite(v_engine.value(name, 45))
    with pytest.raises(KeyError, match="F_bal"):
        v_engine.value("F_99", 45)
    with pytest.raises(ValueError, match="not among"):
        v_engine.value("F_12", 44)


def _renumbered(data: dict, old_to_new: dict[int, int]) -> dict:
    d = copy.deepcopy(data)
    new = old_to_new.get
    d["frame"] = new(d["frame"])
    d["links"] = {str(new(int(k))): v for k, v in d["links"].items()}
    for jt in d["joints"]:
        jt["links"] = [new(x) for x in jt["links"]]
        if "guide" in jt:
            jt["guide"]["link"] = new(jt["guide"]["link"])
    d["driver"]["link"] = new(d["driver"]["link"])
    for key in ("gas", "force", "moment"):
        for body in d.get("loads", {}).get(key, []):
            body["link"] = new(body["link"])
    return d


def test_link_numbers_of_two_digits_read_as_one_digit_ones():
    """The slider-crank with its links numbered 1, 12, 13 and the frame 14: every reaction
    reads as the same mechanism numbered 1..4 (F_12_13^τ is F_23^τ), and so does the checker."""
    data = read_toml(SAMPLES / "slider_crank.toml")
    one = plans.solve(scene_from_dict(data, "one.toml"))
    two = plans.solve(scene_from_dict(_renumbered(data, {1: 1, 2: 12, 3: 13, 4: 14}), "two.toml"))
    pairs = {"F_21": "F_12_1", "F_23": "F_12_13", "F_32": "F_13_12", "F_34": "F_13_14", "F_41": "F_14_1",
             "F_21^τ": "F_12_1^τ", "F_12^τ": "F_1_12^τ", "F_21^n": "F_12_1^n", "omega_2": "omega_12",
             "eps_3": "eps_13", "M_Phi_2": "M_Phi_12", "P_3": "P_13", "F_bal": "F_bal"}
    for phi in one.scene.driver.phis_deg[:4]:
        for a, b in pairs.items():
            assert two.value(b, phi) == pytest.approx(one.value(a, phi), rel=1e-12, abs=1e-9), (a, b)
    assert "F_12_13" in two.names() and quantities.reaction_name("F_12_13^τ") == (12, 13, "^τ")
    assert [quantities.reaction_name(n) for n in ("F_1_2", "F_12")] == [(1, 2, None)] * 2
    from plans.check.providers import PROVIDERS

    assert next(kind for kind, pattern, _ in PROVIDERS if pattern.match("F_12_13^τ")) == "forces"
    from plans.check.checkfile import check_from_dict
    from plans.check.report import check

    def checked(scene: dict, name: str) -> float:  # the checker's exact value of one figure at 30°
        cf = check_from_dict({"format": 1, "scene": scene, "scales": {"length": {"mu": 1000}},
                              "positions": [{"phi_deg": 30, "values": {name: {"value": 100.0}}}]}, "c.toml")
        return next(it.exact for it in check(cf).items if it.quantity == name)

    renumbered = _renumbered(data, {1: 1, 2: 12, 3: 13, 4: 14})
    assert checked(renumbered, "F_12_1^τ") == pytest.approx(abs(one.value("F_21^τ", 30)), rel=1e-12)
    assert checked(renumbered, "F_13_14") == pytest.approx(checked(data, "F_34"), rel=1e-12)
    with pytest.raises(plans.InputError, match="F_12_13"):  # the checker lists the names it knows
        checked(renumbered, "F_21^τ")


# --------------------------------------------------------------------------- solve once


def test_parts_are_computed_once_and_only_when_read(monkeypatch):
    from plans.kinematics import construction

    calls = []
    real = construction.build_all
    monkeypatch.setattr(construction, "build_all", lambda kin: calls.append(1) or real(kin))
    sol = plans.solve(SAMPLES / "four_bar.toml")
    assert sol._parts == {} and sol._common == {}  # nothing yet
    assert sol.kinematics.n == len(sol.scene.driver.phis_deg)
    assert calls == [] and "forces" not in sol._parts and "reactions" not in sol._common
    assert sol.plans is sol.plans and calls == [1]
    assert sol.forces is sol.forces and sol.lever is sol.forces.lever


@pytest.mark.parametrize("path", LINKAGES, ids=[str(p.relative_to(SAMPLES).with_suffix("")) for p in LINKAGES])
def test_plans_draw_solves_each_scene_once(path, monkeypatch):
    """``plans draw``: one Solution, whose exact analysis runs at the scene's positions once
    and over one revolution once (what the sheets read of the plan of positions, the strokes
    and the mechanism's size: before, three revolutions and the positions again), the longer
    plans a roomy sheet tries included: each is the same Solution at another fit, whose plans
    alone are built again (before, each longer fit solved the whole scene again)."""
    from plans import solution
    from plans.kinematics import exact

    # the panels of one position in detail (the plan of positions, every plan, the polygons,
    # the lever and the cycle are solved all the same): the label placement of twelve is slow
    data = read_toml(path)
    data.setdefault("sheet", {})["positions"] = [load_scene(path).driver.phis_deg[0]]
    scene = scene_from_dict(data, str(path))
    solutions, solves = [], []
    init, solve = solution.Solution.__init__, exact.solve

    def counted_init(self, *a, **kw):
        solutions.append(self)
        init(self, *a, **kw)

    monkeypatch.setattr(solution.Solution, "__init__", counted_init)

    def counted_solve(scene, phi_deg=None, *a, **kw):
        solves.append(0 if phi_deg is None else len(phi_deg))  # 0: the scene's own positions
        return solve(scene, phi_deg, *a, **kw)

    monkeypatch.setattr(exact, "solve", counted_solve)
    from plans.kinematics import construction

    built = []  # the plans' construction: every position's plans together, at most once
    build_all = construction.build_all
    monkeypatch.setattr(construction, "build_all", lambda kin, *a, **kw: built.append(kin.n) or build_all(kin, *a, **kw))
    from drawings import cycle, linkage
    from drawings.linkage import larger

    for module in (linkage, cycle):  # the layout of the panels on the sheets solves nothing: not timed here
        monkeypatch.setattr(module, "compose", lambda panels, *a, **kw: [SimpleNamespace(
            panels=panels, placed=[(p, 0.0, 0.0) for p in panels], number=1, count=1, prims=[],
            render=lambda: None)])  # (all in one corner: a sheet with room, so the longer fit is tried)
    grows = []
    may_grow = larger.may_grow
    # one longer fit tried (each costs the panels drawn again), and the course's sheets' last one
    monkeypatch.setattr(larger, "STEPS", (2.0,))
    monkeypatch.setattr(larger, "BLOCK_STEPS", (2.0,))
    monkeypatch.setattr(larger, "may_grow", lambda sol, spec: grows.append(may_grow(sol, spec)) or grows[-1])
    d = linkage.draw(scene)
    assert d.sheets and d.panels
    fits = [sol.fit for sol in solutions]
    if any(grows):  # the longer plans tried (tests/test_sheet_fill.py): the same Solution at each longer fit
        longer = [min(fits[0] * s, solution.MAX_FIT) for s in (*larger.STEPS, larger.KINEMATIC_STEP)]
        assert fits[1:] == longer[:len(fits) - 1], fits  # in order, until one stops the search
        assert all(sol._common is solutions[0]._common for sol in solutions)
    else:
        assert len(solutions) == 1
    # the scene's own positions once, one revolution at most (the sheets' 73- and 37-angle
    # revolutions read off it, no longer solved again), whatever the fits drawn; the rooms'
    # own grids (a gas load's stroke, the dynamics' integration) are the engine's, not the sheets'
    assert solves.count(0) == 1 and solves.count(solution.REVOLUTION) <= 1, solves
    assert 73 not in solves and 37 not in solves, solves
    # the plans built once at each fit: their scales are what a fit changes
    assert built == ([len(scene.driver.phis_deg)] * len(fits) if scene.wants("velocity_plan") else []), built
    solutions.clear()
    solves.clear()  # drawn again from a Solution whose parts are made: nothing is solved
    sol = solution.Solution(scene)
    for part in ("plans", "forces", "cycle"):
        getattr(sol, part)
    sol.revolution()
    sol.strokes()  # the output's extreme positions on the plan of positions
    sol.output_diagrams()  # the output's kinematic diagrams at one φ axis: every other axis reads its exact grid
    if not scene.wants("velocity_plan"):
        sol.analogue_plans()
    solves.clear()
    built.clear()
    assert linkage.draw(sol).panels and solves == []
    # only the longer fits' plans are built (each once), by the same Solution at those fits
    assert [s.fit for s in solutions] == fits and all(s._common is sol._common for s in solutions)
    assert built == ([len(scene.driver.phis_deg)] * (len(fits) - 1) if scene.wants("velocity_plan") else []), built


@pytest.mark.parametrize("name", ["shaper_friction", "v_engine_cycle", "class3/triad_press"])
def test_a_solution_at_another_fit_solves_nothing_again_and_gives_what_a_solve_there_gives(name, monkeypatch):
    """``sol.at_fit(f)`` shares every part no fit changes (the exact analysis, the reactions
    with friction and the efficiency, the cycle's dynamics and diagrams, a revolution, the
    strokes: ``sol``'s own objects, nothing solved again), and what it makes again is what the
    scene solved at f from scratch gives: the same JSON (plans, polygons, lever, tables) to
    the character, the same scales of every polygon and lever."""
    import json

    from plans.kinematics import exact

    sol = plans.solve(SAMPLES / f"{name}.toml")
    fit = 2.0 * sol.fit
    fresh = plans.solve(sol.scene, fit=fit)
    want, before = json.dumps(to_json(fresh)), json.dumps(to_json(sol))
    sol.revolution(), sol.strokes()
    solves: list = []
    real = exact.solve
    monkeypatch.setattr(exact, "solve", lambda *a, **kw: solves.append(a[1:2]) or real(*a, **kw))
    longer = sol.at_fit(fit)
    assert longer.fit == fit and longer.scene.fit == fit and sol.at_fit(sol.fit) is sol
    got = json.dumps(to_json(longer))
    assert got == want and got != before  # the scales are the longer fit's, every value the same
    assert longer.revolution().kinematics is sol.revolution().kinematics and longer.strokes() is sol.strokes()
    for part in ("efficiency", "dynamics", "diagrams", "structure"):
        assert getattr(longer, part) is getattr(sol, part), part
    kin = longer.kinematics
    assert kin.scene is longer.scene and kin.motion is sol.kinematics.motion  # read at f, not solved again
    if sol.forces is not None:
        fa = longer.forces.analysis
        assert fa.scene is longer.scene and fa.crank is sol.forces.analysis.crank
        for k in range(kin.n):
            assert [p.scale for p in longer.force_polygons(k)] == [p.scale for p in fresh.force_polygons(k)]
            assert longer.lever_plan(k).scale == fresh.lever_plan(k).scale
    assert solves == []


# --------------------------------------------------------------------------- validate once


def _run(*args: str) -> subprocess.CompletedProcess:
    return subprocess.run([sys.executable, "-c", "from drawings.console import main; raise SystemExit(main())",
                           *args], cwd=ROOT, capture_output=True, text=True, timeout=120)


def test_a_bad_sheet_fails_solve_as_it_fails_draw(tmp_path):
    text = (SAMPLES / "slider_crank.toml").read_text(encoding="utf-8") + '\n[sheet]\nformat = "A7"\n'
    bad = tmp_path / "bad_sheet.toml"
    bad.write_text(text, encoding="utf-8")
    solve = _run("solve", str(bad))
    draw = _run("draw", str(bad), "-o", str(tmp_path / "out"))
    assert solve.returncode == draw.returncode == 2
    assert solve.stdout == "" and not (tmp_path / "out").exists()
    assert solve.stderr == draw.stderr and len(solve.stderr.splitlines()) == 1
    assert "sheet.format" in solve.stderr and "A7" in solve.stderr


def test_every_table_is_held_typed_by_the_scene():
    """[sheet] read with the file; [loads], [dynamics], [diagrams] when the scene is solved,
    before anything is computed, whether or not its outputs use them."""
    scene = load_scene(SAMPLES / "v_engine_cycle.toml")
    assert scene.sheet.format in ("A1", "A2", "A3", "A4") and scene.sheet.size[0] > 0
    assert not scene.tables and scene.loads is None
    solved = plans.solve(scene).scene
    assert solved.tables and solved.loads is not None and solved.loads.masses
    assert solved.dynamics_spec is not None and solved.dynamics_spec.delta > 0
    assert solved.diagrams_spec is not None and solved.diagrams_spec.quantities
    sol = plans.solve(SAMPLES / "four_bar.toml")
    assert sol.scene.dynamics_spec is None and sol.scene.diagrams_spec is None and sol._parts == sol._common == {}
    data = read_toml(SAMPLES / "four_bar.toml")
    data["outputs"] = ["positions"]  # [loads] unused: a misspelt key in it fails all the same
    data["loads"]["gravty"] = True
    with pytest.raises(plans.InputError, match="loads.gravty"):
        plans.solve(scene_from_dict(data, "typo.toml"))


def test_a_bad_dynamics_table_fails_solve_as_it_fails_draw(tmp_path):
    text = (SAMPLES / "four_bar.toml").read_text(encoding="utf-8").replace(
        'outputs = ["positions", "velocity_plan", "acceleration_plan", "force_polygons", "lever"]',
        'outputs = ["positions", "velocity_plan"]') + "\n[dynamics]\ndelt = 0.05\n"
    bad = tmp_path / "bad_dynamics.toml"
    bad.write_text(text, encoding="utf-8")
    solve = _run("solve", str(bad))
    draw = _run("draw", str(bad), "-o", str(tmp_path / "out"))
    assert solve.returncode == draw.returncode == 2 and solve.stdout == ""
    assert solve.stderr == draw.stderr and len(solve.stderr.splitlines()) == 1 and "dynamics.delt" in solve.stderr


# --------------------------------------------------------------------------- draw only


def test_a_notebook_solves_reads_and_draws_in_three_lines(monkeypatch):
    """The README's lines, run as written: F_12^τ at 45° read, and the sheet drawn from the
    Solution is the sheet ``plans draw`` draws of the file."""
    import re

    import drawings

    readme = (ROOT / "README.md").read_text(encoding="utf-8")
    code = re.search(r"### In Python \(a notebook\).*?```python\n(.*?)```", readme, re.S).group(1)
    lines = [line for line in code.splitlines() if line.strip()]
    assert len(lines) == 4 and lines[0].startswith("import")  # the import, then three lines
    monkeypatch.chdir(ROOT)
    ns: dict = {}
    for line in lines[:-1]:
        exec(line, ns)
    assert eval(lines[2].split("#")[0], ns) == pytest.approx(2111.2957824667, rel=1e-9)
    d = eval(lines[3].split("#")[0], ns)
    assert d._repr_svg_() == d.sheets[0].svg()
    assert [s.svg() for s in d.sheets] == [s.svg() for s in drawings.draw(V_ENGINE).sheets]


def test_a_smaller_sheet_is_drawn_from_a_solution_at_its_fit():
    """fit is an explicit parameter: a Solution solved at A3's fit draws what ``--sheet A3``
    draws, its plans shorter than at A1 and their scales round."""
    from drawings.linkage import draw, fit_for
    from plans.kinematics.scales import LONGEST_MM, is_round

    scene = load_scene(V_ENGINE)
    fit = fit_for(scene.sheet_for(format="A3"))
    assert fit == pytest.approx(math.sqrt(420 / 841))
    small = plans.solve(scene, fit=fit)
    assert small.scene.fit == fit and scene.fit == 1.0
    for pp in small.plans:
        for plan in (pp.velocity, pp.acceleration):
            assert plan.extent <= LONGEST_MM * fit + 1e-9 and is_round(plan.scale)
    a = [s.svg() for s in draw(small, format="A3").sheets]
    assert a == [s.svg() for s in draw(V_ENGINE, format="A3").sheets]
    with pytest.raises(ValueError, match="fit"):
        plans.solve(scene, fit=0.0)


def test_a_mechanism_that_does_not_turn_a_revolution_is_drawn_at_its_own_positions():
    """A four-bar whose crank cannot go round (180 + 300 > 260 + 200): no revolution to read,
    tried once; the sheets are drawn from the positions it has (no paths, no strokes)."""
    from drawings.linkage import draw
    from drawings.linkage.panels import cycle_size, strokes_over_cycle

    data = read_toml(SAMPLES / "four_bar.toml")
    data["links"]["1"]["length"] = 180
    data["driver"].pop("positions")
    data["driver"]["phi_deg"] = [0, 20]
    sol = plans.solve(scene_from_dict(data, "locking.toml"))
    with pytest.raises(plans.ConstructionError):
        sol.revolution()
    assert sol._common["no revolution"] and strokes_over_cycle(sol) == {}  # (for the scene at every fit)
    xs = [complex(sol.kinematics.point(p)[0][k]).real for p in ("O", "A", "B", "D", "E") for k in (0, 1)]
    assert cycle_size(sol) >= max(xs) - min(xs) > 0
    d = draw(sol)
    assert d.sheets and "positions" in {p.kind for p in d.panels}
