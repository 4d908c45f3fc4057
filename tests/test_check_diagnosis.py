"""The examiner names the mistake: students with one planted mistake, a clean student, the
seed 000 coursework, the slips replayed against closed forms, and the report's new keys.

Planted submissions (:mod:`plans.check.planted`) are drawn by the construction with the
slip in it and every segment read to a seeded random ±0.5 mm.  The larger rate
measurement (hundreds of submissions, a slip counted only when it shows without the
reading noise) is a goal of ``plans bench``; here a smaller share of it must already
meet the rates."""

from __future__ import annotations

import csv
import io
import json
import math
from pathlib import Path

import numpy as np
import pytest

from plans.check.checkfile import check_from_dict, load_check
from plans.check.diagnosis import RUBRIC
from plans.check.mistakes import KINDS, Slip, inventory, replay
from plans.check.planted import PLANTED, Scenario, submission
from plans.check.report import check, csv_text, summary_row
from plans.cli import main
from plans.kinematics import construction
from plans.kinematics.exact import solve
from plans.kinematics.placing import load_scene

ROOT = Path(__file__).resolve().parent.parent
SAMPLES = ROOT / "samples"
SCENES = {"v_engine": (0.0, 45.0), "shaper": (30.0, 120.0, 210.0, 300.0),
          "six_bar": (30.0, 90.0, 150.0, 240.0), "whitworth": (30.0, 120.0, 210.0, 300.0)}


@pytest.fixture(scope="module")
def scenarios():
    return {name: Scenario.of(SAMPLES / f"{name}.toml") for name in SCENES}


def _pair(name: str, rng: np.random.Generator) -> tuple[float, float]:
    phis = SCENES[name]
    i, j = rng.choice(len(phis), 2, replace=False)
    return float(phis[i]), float(phis[j])


def test_planted_mistakes_are_named_and_clean_sheets_stay_clean(scenarios):
    """Per scene: clean students get no finding at all; a planted mistake that shows is
    named first.  The rates over this share: ≥ 95 % named, 100 % of the clean ones clean."""
    named = shown = clean = clean_ok = 0
    misses = []
    for name, sc in scenarios.items():
        for n, kind in enumerate([None] * 3 + list(PLANTED) * 2):
            rng = np.random.default_rng(1000 * len(name) + n)
            try:
                data, told = submission(sc, _pair(name, rng), kind, rng)
            except LookupError:  # no such slip in this scene (no Coriolis in a V-engine)
                continue
            rep = check(check_from_dict(data, f"{name}.toml"))
            kinds = [c.kind for c in rep.causes]
            if kind is None:
                clean += 1
                ok = not kinds and not rep.unexplained and not rep.findings
                clean_ok += ok
                if not ok:
                    misses.append((name, told, kinds, [f.message for f in rep.findings][:2]))
                continue
            if not rep.failed and not rep.findings and not kinds:
                continue  # the slip moves nothing beyond the tolerance here: nothing to name
            shown += 1
            named += bool(kinds) and kinds[0] == kind
            if not kinds or kinds[0] != kind:
                misses.append((name, told, kinds[:3]))
    assert clean >= 12 and clean_ok == clean, misses
    assert shown >= 60
    assert named >= 0.95 * shown, (named, shown, misses)


def test_every_planted_kind_is_a_json_kind():
    assert set(PLANTED) <= set(KINDS)
    assert KINDS[:11] == ("coriolis_reversed", "normal_from_pole", "tangential_wrong_line", "scale",
                          "similarity", "wrong_segment", "inertia_sign", "reaction_swapped", "fij_reversed",
                          "pi_rounded", "g_rounded")


# --------------------------------------------------------------------------- the slips against closed forms


def test_reversed_coriolis_lands_where_the_lines_of_the_textbook_meet():
    """a3 with a^k reversed: the line ⟂ CA through the end of a_A3C^n (toward C) meets the
    line ∥ slot through a_A2 − a^k: solved here as a 2×2 system from the rigid-body rates."""
    scene = load_scene(SAMPLES / "shaper.toml")
    kin = solve(scene, order=2)
    k = 1
    mv, ma = 100.0, 10.0
    slips = [s for s in inventory(kin, k, mv, ma) if s.kind == "coriolis_reversed"]
    assert len(slips) == 1
    _, ap = replay(kin, k, mv, ma, slips)
    rA = complex(kin.point("A")[0][k])
    rC = complex(kin.point("C")[0][k])
    u = (rA - rC) / abs(rA - rC)
    w3 = float(kin.omega(3)[k])
    v_rel = complex(kin.point("A")[1][k]) - (1j * w3 * (rA - rC))  # v_A2 − v_A3: along the slot
    coriolis = 2 * w3 * 1j * (-v_rel)  # a^k of A3 relative to A2: 2 ω3 × v_A3A2
    a_a2 = complex(kin.point("A")[2][k])
    an = -(w3**2) * (rA - rC)
    base = a_a2 - coriolis - an  # a3 = an + t·iu = a_A2 − a^k + s·u
    m = np.array([[(1j * u).real, -u.real], [(1j * u).imag, -u.imag]])
    t, _ = np.linalg.solve(m, [base.real, base.imag])
    want = (an + t * 1j * u) * ma
    assert abs(ap["a3"][0] - want) < 1e-9 * abs(want)
    right = construction.build(kin, k, velocity_scale=mv, acceleration_scale=ma).acceleration
    assert abs(ap["a3"][0] - complex(*right.xy("a3"))) > 1.0  # and it moved


def test_similarity_from_the_wrong_end_mirrors_the_point_on_its_link():
    """S2 on AB at ratio λ from A, found from the wrong end: at λ from B (s2' = a + b − s2)."""
    scene = load_scene(SAMPLES / "v_engine.toml")
    kin = solve(scene, order=2)
    slips = [s for s in inventory(kin, 1, 10.0, 0.02) if s.kind == "similarity" and s.target == "s2"
             and s.variant == "wrong_end" and s.phase == "velocity"]
    vp, _ = replay(kin, 1, 10.0, 0.02, slips)
    assert abs(vp["s2"][0] - (vp["a"][0] + vp["b"][0] - complex(*construction.build(
        kin, 1, velocity_scale=10.0, acceleration_scale=0.02).velocity.xy("s2")))) < 1e-9


def test_a_plan_drawn_at_another_scale_is_that_plan_scaled():
    scene = load_scene(SAMPLES / "six_bar.toml")
    kin = solve(scene, order=2)
    vp, _ = replay(kin, 2, 50.0, 5.0, [Slip("scale", "velocity", "drawn", "velocity", factor=1.1)])
    right = construction.build(kin, 2, velocity_scale=50.0, acceleration_scale=5.0).velocity
    for p in right.points:
        assert abs(vp[p.name][0] - 1.1 * complex(*p.xy)) < 1e-9


# --------------------------------------------------------------------------- no noise


def _student(sc: Scenario, seed: int, kind: str | None = None) -> dict:
    rng = np.random.default_rng(seed)
    return submission(sc, (30.0, 210.0), kind, rng)[0]


def test_a_value_from_its_segment_is_judged_at_the_reading_not_at_its_digits(scenarios):
    """42.5 mm at μ = 5 is 8.5; a student who wrote 8.422 (ω²l, computed) is within the ±0.5 mm
    of the reading: no arithmetic finding, whatever the digits typed."""
    data = _student(scenarios["whitworth"], 3)
    pos = data["positions"][0]
    mu = data["scales"]["acceleration"]["mu"]
    q = next(q for q in pos["measured"] if q.startswith("a_") and pos["measured"][q] > 20)
    pos["values"][q] = float(f"{(pos['measured'][q] + 0.4) / mu:.5g}")
    rep = check(check_from_dict(data, "w.toml"))
    assert rep.findings == () and rep.causes == () and rep.unexplained == []


def test_clean_sheet_json_and_csv(scenarios, tmp_path):
    data = _student(scenarios["shaper"], 5)
    rep = check(check_from_dict(data, "s.toml"))
    js = rep.to_json()
    assert js["causes"] == [] and js["unexplained"] == []
    assert js["mark"] == RUBRIC["full"]
    row = summary_row("s.toml", rep)
    assert row["causes"] == "" and row["unexplained"] == "" and float(row["mark"]) == 100
    assert float(row["worst_tol"]) <= 1.0  # the worst figure is within its tolerance
    text = csv_text([row])
    assert next(csv.DictReader(io.StringIO(text)))["mark"] == "100"
    table = __import__("plans.check.report", fromlist=["table"]).table(rep)
    assert "No mistakes found" in table


def test_measured_only_figure_is_printed_in_mm_not_as_a_derived_value(scenarios):
    data = _student(scenarios["shaper"], 6)
    pos = data["positions"][0]
    del pos["values"]["v_D"]
    rep = check(check_from_dict(data, "s.toml"))
    table = __import__("plans.check.report", fromlist=["table"]).table(rep)
    line = next(ln for ln in table.splitlines() if ln.strip().startswith("v_D "))
    assert f"{pos['measured']['v_D']:g} mm" in line


# --------------------------------------------------------------------------- causes in the report


def test_reversed_coriolis_is_one_cause_with_its_consequences(scenarios):
    sc = scenarios["whitworth"]
    for seed in range(20):
        rng = np.random.default_rng(seed)
        data, told = submission(sc, (30.0, 120.0), "coriolis_reversed", rng)
        rep = check(check_from_dict(data, "w.toml"))
        if rep.failed >= 3:
            break
    js = rep.to_json()
    first = js["causes"][0]
    assert set(first) >= {"kind", "positions", "explains", "detail"}
    assert first["kind"] == "coriolis_reversed", told
    assert len(first["positions"]) == 1 and first["positions"][0] in (30.0, 120.0)
    assert len(first["explains"]) >= 3  # a3, ε3 and what is found from them
    assert js["unexplained"] == []
    # every failure is under the cause: none listed twice
    assert sum(len(c.items) for c in rep.causes) == rep.failed


def test_json_of_the_check_command_and_of_a_folder_carry_causes(scenarios, tmp_path, capsys):
    folder = tmp_path / "group"
    folder.mkdir()
    import tomlkit

    for n, kind in enumerate((None, "coriolis_reversed", "scale")):
        data = _student(scenarios["shaper"], 40 + n, kind)
        (folder / f"s{n}.toml").write_text(tomlkit.dumps(data), encoding="utf-8")
    assert main(["check", str(folder / "s1.toml"), "--json", "-"]) == 0
    one = json.loads(capsys.readouterr().out)
    assert "causes" in one and "unexplained" in one
    out = tmp_path / "out"
    assert main(["check", str(folder), "--out", str(out), "--quiet"]) == 0
    for n in range(3):
        js = json.loads((out / f"s{n}.json").read_text(encoding="utf-8"))
        assert "causes" in js and "unexplained" in js
    rows = list(csv.DictReader((out / "summary.csv").open(encoding="utf-8")))
    assert {"mark", "causes", "unexplained", "worst_tol"} <= set(rows[0])
    assert rows[0]["causes"] == ""
    assert rows[2]["causes"].startswith("scale")


def test_seed_000_coursework_grouped_by_cause():
    rep = check(load_check(ROOT / "samples" / "checks" / "v_engine_coursework.toml"))
    kinds = [c.kind for c in rep.causes]
    # the slips the checker found before, now as causes: ω1 with π = 3.14, a_A miscalculated,
    # a_CA at 0° measured on another segment (it is a_B's length)
    assert "pi_rounded" in kinds and "arithmetic" in kinds and "wrong_segment" in kinds
    a_a = next(c for c in rep.causes if c.kind == "arithmetic" and "a_A" in c.explains)
    assert set(a_a.positions) == {0.0, 45.0}
    # its arithmetic and relation findings are grouped under it, not counted again
    grouped = {rep.findings[i].kind for i in a_a.findings}
    assert {"arithmetic", "relation"} <= grouped
    ws = next(c for c in rep.causes if c.kind == "wrong_segment" and "a_CA" in c.explains)
    assert any(rep.findings[i].kind == "swapped" for i in ws.findings)
    assert all(i not in rep.diagnosis.findings_left for c in rep.causes for i in c.findings)
    # every failure is either under one cause or unexplained
    under = [i for c in rep.causes for i in c.items]
    assert len(under) == len(set(under))
    assert len(under) + len(rep.unexplained) == rep.failed
    assert 0 <= rep.mark < RUBRIC["full"]


def test_rubric_from_the_check_file(scenarios):
    data = _student(scenarios["shaper"], 7, "pi_rounded")
    data["rubric"] = {"full": 20, "pi_rounded": 0.5}
    rep = check(check_from_dict(data, "s.toml"))
    assert [c.kind for c in rep.causes] == ["pi_rounded"]
    assert rep.mark == pytest.approx(19.5)
    data["rubric"] = {"coriolis": 3}
    with pytest.raises(Exception, match="coriolis"):
        check_from_dict(data, "s.toml")



# --------------------------------------------------------------------------- forms


def test_template_lists_what_the_sheets_show_and_a_blank_reads_as_not_written(tmp_path, capsys):
    scene = tmp_path / "shaper.toml"
    scene.write_text((SAMPLES / "shaper.toml").read_text(encoding="utf-8"), encoding="utf-8")
    form = tmp_path / "blank.toml"
    assert main(["check", "--template", str(scene), "--phi", "30,210", "-o", str(form), "--quiet"]) == 0
    import tomllib

    data = tomllib.loads(form.read_text(encoding="utf-8"))
    assert data["scene"] == "shaper.toml"
    assert [p["phi_deg"] for p in data["positions"]] == [30, 210]
    plan = construction.build(solve(load_scene(scene), order=2), 1, velocity_scale=100.0, acceleration_scale=10.0)
    labels = {s.label for s in plan.velocity.segments} | {s.label for s in plan.acceleration.segments}
    assert labels <= set(data["positions"][0]["measured"])
    assert {"omega_3", "eps_3", "F_bal", "Phi_3"} <= set(data["positions"][0]["values"])
    # the blank form names every quantity the checker reads: filled with one figure it checks
    data["positions"][0]["values"]["omega_1"] = 6.2832
    data["scales"]["velocity"] = {"mu": 100}
    rep = check(check_from_dict(data, str(form)))
    assert [i.quantity for i in rep.items] == ["omega_1"] and rep.causes == ()
    assert main(["check", "--template", str(scene), "--phi", "31"]) == 2
    assert "31" in capsys.readouterr().err


def test_csv_form_one_submission_per_column(scenarios, tmp_path, capsys):
    scene = tmp_path / "whitworth.toml"
    scene.write_text((SAMPLES / "whitworth.toml").read_text(encoding="utf-8"), encoding="utf-8")
    form = tmp_path / "group.csv"
    assert main(["check", "--template", str(scene), "--phi", "30,120", "--form", "csv", "--students", "3",
                 "-o", str(form), "--quiet"]) == 0
    rows = list(csv.reader(form.open(encoding="utf-8")))
    sc = scenarios["whitworth"]
    planted = [submission(sc, (30.0, 120.0), kind, np.random.default_rng(seed))[0]
               for kind, seed in ((None, 11), ("coriolis_reversed", 12))]
    for col, data in enumerate(planted):  # the third column stays empty: no submission
        for r in rows[1:]:
            q, phi, fig = r[:3]
            if q == "student":
                r[3 + col] = f"student {col + 1}"
            elif q.startswith("scales.") and q.split(".")[1] in ("velocity", "acceleration"):
                r[3 + col] = str(data["scales"][q.split(".")[1]]["mu"])
            elif phi:
                pos = next(p for p in data["positions"] if p["phi_deg"] == float(phi))
                figures = pos["measured" if fig == "mm" else "values"]
                if q in figures:
                    r[3 + col] = str(figures[q])
    with form.open("w", encoding="utf-8", newline="") as fh:
        csv.writer(fh, lineterminator="\n").writerows(rows)
    capsys.readouterr()
    assert main(["check", str(form), "--csv", "-", "--quiet"]) == 0
    got = list(csv.DictReader(io.StringIO(capsys.readouterr().out)))
    assert [r["student"] for r in got] == ["student 1", "student 2"]
    assert got[0]["causes"] == "" and got[0]["mark"] == "100"
    assert got[1]["causes"].startswith("coriolis_reversed")
    assert sorted(p.name for p in (tmp_path / "group-reports").iterdir()) == \
        ["group-1.json", "group-1.txt", "group-2.json", "group-2.txt"]


def test_folder_with_its_scene_beside_the_check_files(scenarios, tmp_path, capsys):
    import tomlkit

    (tmp_path / "v_engine.toml").write_text((SAMPLES / "v_engine.toml").read_text(encoding="utf-8"),
                                            encoding="utf-8")
    data = submission(scenarios["v_engine"], (0.0, 45.0), None, np.random.default_rng(3))[0]
    del data["scene"]
    (tmp_path / "ivanov.toml").write_text(tomlkit.dumps(data), encoding="utf-8")
    capsys.readouterr()
    assert main(["check", str(tmp_path), "--csv", "-", "--quiet"]) == 0
    got = list(csv.DictReader(io.StringIO(capsys.readouterr().out)))
    assert len(got) == 1 and got[0]["status"] == "ok" and got[0]["mark"] == "100"


def test_velocity_scale_written_45_drawn_at_49_75_is_one_scale_mistake():
    """The Whitworth student whose sheet says μv = 45 while the plan is drawn at 49.75: one
    short segment read to ±0.5 mm does not hide it, and the failures that follow from it
    (ω read off the plan, the normal and Coriolis components computed from it) are its
    consequences, not separate mistakes."""
    sc = Scenario.of(SAMPLES / "whitworth.toml", mv=45.0)
    slip = Slip("scale", "velocity", "drawn", "velocity", factor=49.75 / 45.0)
    data, _ = submission(sc, (30.0, 210.0), "scale", np.random.default_rng(9), drawn=slip)
    rep = check(check_from_dict(data, "w.toml"))
    assert rep.failed >= 10
    first = rep.causes[0]
    import re

    assert first.kind == "scale" and "μv = 45 is written" in first.detail
    drawn_at = float(re.search(r"drawn at μv = ([\d.]+)", first.detail).group(1))
    assert drawn_at == pytest.approx(49.75, rel=0.01)
    assert len(first.items) >= 10
    assert len(rep.unexplained) <= 2
    assert not [f for f in rep.findings_left if f.kind == "swapped"]


def test_two_mistakes_are_two_causes(scenarios):
    """A reversed Coriolis vector and ω1 computed with π = 3.14 and one velocity miscalculated:
    three causes, the Coriolis one first, nothing unexplained."""
    sc = scenarios["whitworth"]
    for seed in range(20):
        data, told = submission(sc, (30.0, 120.0), "coriolis_reversed", np.random.default_rng(seed))
        if check(check_from_dict(data, "w.toml")).failed >= 3:
            break
    d = sc.scene.driver
    w1 = abs(d.omega) * 3.14 / math.pi
    for pos in data["positions"]:
        pos["values"]["omega_1"] = float(f"{w1:.5g}")
        pos["values"]["a_A"] = float(f"{w1 * w1 * 0.12:.5g}")
    other = data["positions"][1] if "30" in told else data["positions"][0]
    other["values"]["v_D"] = float(f"{other['values']['v_D'] * 1.3:.4g}")
    rep = check(check_from_dict(data, "w.toml"))
    kinds = [c.kind for c in rep.causes]
    assert kinds[0] == "coriolis_reversed", (told, kinds)
    assert {"pi_rounded", "arithmetic"} <= set(kinds), kinds
    assert len(kinds) == 3 and rep.unexplained == []


def test_a_segment_read_wrong_and_used_on_is_one_cause(scenarios):
    """v_ED of the shaper read between the wrong points, ω4 taken from it and a_ED^n = ω4²·l
    laid off: the acceleration plan's figures that follow are that one mistake's."""
    sc = scenarios["shaper"]
    for seed in range(60):
        data, told = submission(sc, (30.0, 120.0), "wrong_segment", np.random.default_rng(seed))
        if "used on" in told and "v_ED" in told:
            break
    rep = check(check_from_dict(data, "s.toml"))
    assert [c.kind for c in rep.causes] == ["wrong_segment"], told
    assert {"v_ED", "omega_4", "a_ED^n"} <= set(rep.causes[0].explains)
    assert rep.unexplained == []
