"""A group's course: variants from a table, keys proved by closed forms, keys fed back as
full marks, planted slips found in the gradebook read back with openpyxl."""

from __future__ import annotations

import json
import math
import shutil
from pathlib import Path

import pytest
import tomlkit

from drawings.cli import main

SAMPLE = Path(__file__).resolve().parents[1] / "samples" / "group"
#: the students who make a slip, and the one finding each must get
PLANTED = {"L02": ("scale", "linkage: scale"), "L03": ("coriolis_reversed", "linkage: coriolis_reversed"),
           "L04": ("arithmetic", "linkage: arithmetic"), "G03": ("shift_coefficient", "gears: shift_coefficient"),
           "C02": ("base_radius", "cam: base_radius")}


@pytest.fixture(scope="module")
def group(tmp_path_factory: pytest.TempPathFactory) -> Path:
    out = tmp_path_factory.mktemp("group") / "course"
    assert main(["variants", str(SAMPLE / "group.csv"), "-o", str(out), "--no-sheets", "--quiet",
                 "--students", str(SAMPLE / "roster.csv"), "--language", "en"]) == 0
    return out


def _csv_rows(path: Path) -> list[dict[str, str]]:
    import csv

    return list(csv.DictReader(path.open(encoding="utf-8")))


def test_one_folder_per_variant_with_the_layout(group: Path) -> None:
    rows = _csv_rows(SAMPLE / "group.csv")
    assert len(rows) >= 25 and {r["template"] for r in rows} >= {"shaper.template", "gears.template",
                                                                  "cam.template", "crank_rocker.template"}
    for r in rows:
        folder = group / r["variant"]
        key = json.loads((folder / "key.json").read_text(encoding="utf-8"))
        assert key["variant"] == r["variant"] and key["values"]
        assert all(isinstance(v, dict) and v for v in key["values"].values())
        assert (folder / "check.toml").is_file() and (folder / key["file"]).is_file()
        assert f'variant = "{r["variant"]}"' in (folder / "check.toml").read_text(encoding="utf-8")
    roster = _csv_rows(SAMPLE / "roster.csv")
    pdfs = sorted((group / "handouts").glob("*.pdf"))
    assert len(pdfs) == len(roster) and all(p.read_bytes().startswith(b"%PDF") for p in pdfs)


def test_gear_keys_follow_the_involute_closed_forms(group: Path) -> None:
    for r in _csv_rows(SAMPLE / "group.csv"):
        if r["template"] != "gears.template":
            continue
        v = {q: d["0"] for q, d in json.loads((group / r["variant"] / "key.json").read_text())["values"].items()}
        m, z1, z2, a = float(r["m"]), int(r["z1"]), int(r["z2"]), math.radians(20)
        x1 = max(0.0, (17 - z1) / 17)  # the course's minimum-teeth rule, h_a* = 1 (no negative shift)
        assert v["x_1"] == pytest.approx(x1, abs=1e-7) and v["x_2"] == 0
        inv = math.tan(a) - a + 2 * math.tan(a) * x1 / (z1 + z2)
        lo, hi = 0.0, 1.4  # inv α_w = inv α + 2 tan α (x1 + x2)/(z1 + z2), bisected here
        for _ in range(80):
            mid = (lo + hi) / 2
            lo, hi = (mid, hi) if math.tan(mid) - mid < inv else (lo, mid)
        assert v["alpha_w_12"] == pytest.approx(math.degrees(lo), abs=1e-6)
        assert v["r_1"] == pytest.approx(m * z1 / 2) and v["r_b2"] == pytest.approx(m * z2 / 2 * math.cos(a))
        assert v["a_w_12"] == pytest.approx(m * (z1 + z2) / 2 * math.cos(a) / math.cos(lo), rel=1e-8)
        assert v["r_f1"] == pytest.approx(m * z1 / 2 - (1.25 - x1) * m, rel=1e-8)


def test_cam_keys_follow_the_motion_law(group: Path) -> None:
    for r in _csv_rows(SAMPLE / "group.csv"):
        if r["template"] != "cam.template":
            continue
        v = json.loads((group / r["variant"] / "key.json").read_text())["values"]
        r0, e, h, rise = float(r["r0"]), float(r["e"]), float(r["h"]), float(r["phi_rise"])
        s0 = math.sqrt(r0 * r0 - e * e)
        for phi in (0.0, 30.0, 60.0):
            t = min(phi / rise, 1.0)
            s = {"harmonic": h * (1 - math.cos(math.pi * t)) / 2,
                 "cycloidal": h * (t - math.sin(2 * math.pi * t) / (2 * math.pi)),
                 "poly345": h * (10 * t**3 - 15 * t**4 + 6 * t**5)}[r["law"]]
            assert v["s"][f"{phi:g}"] == pytest.approx(s, abs=1e-6)
            assert v["R"][f"{phi:g}"] == pytest.approx(math.hypot(e, s0 + s), abs=1e-6)


def test_linkage_key_gives_the_crank_from_its_data(group: Path) -> None:
    r = next(r for r in _csv_rows(SAMPLE / "group.csv") if r["template"] == "shaper.template")
    v = json.loads((group / r["variant"] / "key.json").read_text())["values"]
    w = math.pi * float(r["n_1"]) / 30
    l1 = float(r["l_OA"]) / 1000
    assert v["v_A"]["30"] == pytest.approx(w * l1, rel=1e-8)
    assert v["a_A"]["120"] == pytest.approx(w * w * l1, rel=1e-8)
    assert v["omega_1"]["30"] == pytest.approx(w, rel=1e-8)


def _submissions(group: Path, folder: Path, planted: dict[str, tuple[str, str]]) -> None:
    from plans.group.samples import key_submission

    for d in sorted(p for p in group.iterdir() if p.name != "handouts"):
        grp = "MT-31" if int(d.name[1:]) % 2 else "MT-32"
        target = folder / grp / f"{d.name}.toml"
        target.parent.mkdir(parents=True, exist_ok=True)
        slip = planted.get(d.name, (None, ""))[0]
        target.write_text(tomlkit.dumps(key_submission(d, target, f"Student {d.name}", grp, slip)), encoding="utf-8")
        if (d / "synthesis.toml").exists():  # a synthesis variant: the design's sheet besides its scene's
            target = target.with_suffix(".synthesis.toml")
            target.write_text(tomlkit.dumps(key_submission(d, target, f"Student {d.name}", grp, sheet="synthesis")),
                              encoding="utf-8")


def _read(xlsx: Path) -> dict[str, list[dict]]:
    from openpyxl import load_workbook

    wb = load_workbook(xlsx)
    out = {}
    for ws in wb.worksheets:
        rows = list(ws.iter_rows(values_only=True))
        assert ws.freeze_panes == "A2"
        assert list(rows[0][:4]) == ["student", "group", "variant", "mark"]
        assert list(rows[0][-3:-1]) == ["causes", "unexplained"]
        assert ws.conditional_formatting, "scores are coloured against the pass threshold"
        out[ws.title] = [dict(zip(rows[0], r, strict=True)) for r in rows[1:]]
    return out


def test_keys_fed_back_get_full_marks(group: Path, tmp_path: Path) -> None:
    _submissions(group, tmp_path / "subs", {})
    xlsx = tmp_path / "marks.xlsx"
    assert main(["check", str(tmp_path / "subs"), "--xlsx", str(xlsx), "--quiet"]) == 0
    book = _read(xlsx)
    assert sorted(book) == ["MT-31", "MT-32"]
    rows = [r for rs in book.values() for r in rs]
    assert len(rows) == len(list(p for p in group.iterdir() if p.name != "handouts"))
    for r in rows:
        assert r["mark"] == 100 and not r["causes"] and not r["unexplained"] and not r["findings"], r
        for kind in {"L": ["linkage"], "G": ["gears"], "C": ["cam"], "S": ["synthesis", "linkage"],
                     "E": ["engine"]}[r["variant"][0]]:
            assert r[kind] == 100, (kind, r)


def test_planted_slips_are_found_exactly(group: Path, tmp_path: Path) -> None:
    _submissions(group, tmp_path / "subs", PLANTED)
    rubric = tmp_path / "rubric.toml"
    rubric.write_text('format = 1\nkind = "rubric"\npass = 95\n[weights]\nlinkage = 1\n'
                      '[marks]\n5 = 99\n4 = 80\n3 = 60\n2 = 0\n', encoding="utf-8")
    xlsx = tmp_path / "marks.xlsx"
    assert main(["check", str(tmp_path / "subs"), "--xlsx", str(xlsx), "--quiet", "--jobs", "2"]) == 0
    rows = {r["variant"]: r for rs in _read(xlsx).values() for r in rs}
    flagged = {v for v, r in rows.items() if r["causes"] or r["unexplained"] or r["mark"] != 100}
    assert flagged == set(PLANTED)
    for v, (_, finding) in PLANTED.items():
        causes = [c.split(" at ")[0] for c in rows[v]["causes"].split("; ")]
        assert causes == [finding], (v, rows[v])
        assert not rows[v]["unexplained"], (v, rows[v])
    # beside the gradebook: a report per sheet and the examiner's summary.csv
    reports = tmp_path / "subs" / "reports"
    summary = _csv_rows(reports / "summary.csv")
    assert len(summary) == len(list((tmp_path / "subs").rglob("*.toml")))
    assert {r["causes"].split(" at ")[0] for r in summary if r["causes"]} == {k for k, _ in PLANTED.values()}
    got = json.loads((reports / "MT-31_L03.json").read_text(encoding="utf-8"))
    assert [c["kind"] for c in got["causes"]] == ["coriolis_reversed"]
    # the rubric: only the linkage sheet weighs; a mark by thresholds
    xlsx2 = tmp_path / "marks2.xlsx"
    assert main(["check", str(tmp_path / "subs"), "--xlsx", str(xlsx2), "--rubric", str(rubric), "--quiet"]) == 0
    rows2 = {r["variant"]: r for rs in _read(xlsx2).values() for r in rs}
    assert rows2["L01"]["mark"] == 5 and rows2["L03"]["mark"] == 4 and rows2["G01"]["mark"] == 2
    # the same rows, the same bytes
    xlsx3 = tmp_path / "marks3.xlsx"
    assert main(["check", str(tmp_path / "subs"), "--xlsx", str(xlsx3), "--quiet"]) == 0
    assert xlsx3.read_bytes() == xlsx.read_bytes()


def test_a_variant_that_cannot_be_built_is_named_and_the_others_made(tmp_path: Path,
                                                                      capsys: pytest.CaptureFixture) -> None:
    for name in ("shaper.template", "gears.template"):
        shutil.copy(SAMPLE / name, tmp_path / name)
    (tmp_path / "t.csv").write_text("variant,template,l_OA,l_CD,l_OC,n_1,m,z1,z2\n"
                                    "A1,shaper.template,90,520,280,50,,,\n"
                                    "A2,shaper.template,90,120,280,50,,,\n"
                                    "A3,gears.template,,,,,4,13,30\n", encoding="utf-8")
    out = tmp_path / "out"
    assert main(["variants", str(tmp_path / "t.csv"), "-o", str(out), "--quiet", "--language", "en"]) == 2
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) == 1 and "variant A2 (t.csv, row 3)" in err[0]
    shutil.rmtree(out)
    assert main(["variants", str(tmp_path / "t.csv"), "-o", str(out), "--quiet", "--language", "ru"]) == 2
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) == 1 and err[0].startswith("plans: ошибка: вариант A2 (t.csv, строка 3): группа RRP"), err
    assert sorted(p.name for p in out.iterdir()) == ["A1", "A3"]
    assert (out / "A3" / "reference" / "gears.pdf").read_bytes().startswith(b"%PDF")
    assert sorted(p.name for p in (out / "A1" / "reference").iterdir()) == ["scene-1.pdf", "scene-2.pdf"]


def test_bad_tables_are_one_line(tmp_path: Path, capsys: pytest.CaptureFixture) -> None:
    shutil.copy(SAMPLE / "gears.template", tmp_path / "gears.template")
    (tmp_path / "t.csv").write_text("variant,m,z1\nB1,4,13\n", encoding="utf-8")
    assert main(["variants", str(tmp_path / "t.csv"), "-o", str(tmp_path / "out"), "--quiet", "--language", "en"]) == 2
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) == 1 and "z2" in err[0] and "row 2" in err[0]
    assert main(["variants", str(tmp_path / "t.csv"), "-o", str(tmp_path / "out"), "--quiet", "--language", "ru"]) == 2
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) == 1 and "z2" in err[0] and "строка 2" in err[0] and err[0].startswith("plans: ошибка: ")
    (tmp_path / "u.csv").write_text("name,m\nB1,4\n", encoding="utf-8")
    assert main(["variants", str(tmp_path / "u.csv"), "-o", str(tmp_path / "out2"), "--quiet", "--language", "en"]) == 2
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) == 1 and "'variant' column" in err[0] and "u.csv" in err[0]
    assert not (tmp_path / "out2").exists()


def test_synthesis_keys_meet_the_task_by_the_extreme_positions(group: Path) -> None:
    """A crank-rocker's extremes: A to B is b − a and b + a, θ apart, the chord B1B2 the
    rocker's swing (cosine law); the key's K is the task's and θ = 180°(K − 1)/(K + 1)."""
    rows = [r for r in _csv_rows(SAMPLE / "group.csv") if r["template"] == "crank_rocker.template"]
    assert rows
    for r in rows:
        key = json.loads((group / r["variant"] / "key.json").read_text())
        v = {q: d["0"] for q, d in key["values"].items() if "0" in d and not q.startswith(("v_", "a_"))}
        K, psi, c = float(r["K"]), float(r["psi"]), float(r["l_DB"])
        assert v["K"] == pytest.approx(K, abs=1e-9) and v["psi"] == pytest.approx(psi, abs=1e-7)
        assert v["theta"] == pytest.approx(180 * (K - 1) / (K + 1), abs=1e-7)
        a, b, th = v["l_crank"], v["l_coupler"], math.radians(v["theta"])
        chord2 = (b - a) ** 2 + (b + a) ** 2 - 2 * (b - a) * (b + a) * math.cos(th)
        assert math.sqrt(chord2) == pytest.approx(2 * c * math.sin(math.radians(psi) / 2), rel=1e-7)
        assert v["l_rocker"] == pytest.approx(c) and v["gamma_min"] >= 40 - 1e-9
        assert (group / r["variant"] / "scene.toml").is_file() and key["scene"] == "scene.toml"


def test_engine_keys_close_the_rotating_masses_polygon(group: Path) -> None:
    """The rotating masses' polygon in units of cylinder 1's: |Σ m_i e^{iθ_i}| / m_1 (cranks at
    0°, 180°, 90°, 270°); the first-order polygon of four equal reciprocating masses closes."""
    rows = [r for r in _csv_rows(SAMPLE / "group.csv") if r["template"] == "engine.template"]
    assert rows
    for r in rows:
        v = json.loads((group / r["variant"] / "key.json").read_text())["values"]
        m = (400.0, float(r["m_rot2"]), 600.0, 400.0)
        z = sum(mi * complex(math.cos(math.radians(t)), math.sin(math.radians(t)))
                for mi, t in zip(m, (0, 180, 90, 270), strict=True))
        assert v["F_rot"]["0"] == pytest.approx(abs(z) / 400.0, abs=1e-8)
        assert v["F_I"]["0"] == pytest.approx(0.0, abs=1e-9)
        assert v["mr_cw1"]["0"] > 0 and 0 <= v["angle_cw2"]["0"] < 360


def test_a_gears_sheet_alone_and_its_blank_form(group: Path, tmp_path: Path, capsys: pytest.CaptureFixture) -> None:
    from plans.group.samples import key_submission

    target = tmp_path / "g.toml"
    target.write_text(tomlkit.dumps(key_submission(group / "G03", target, "Ivanov", "MT-31", "shift_coefficient")),
                      encoding="utf-8")
    assert main(["check", str(target), "--json", str(tmp_path / "g.json"), "--quiet"]) == 0
    got = json.loads((tmp_path / "g.json").read_text(encoding="utf-8"))
    assert [c["kind"] for c in got["causes"]] == ["shift_coefficient"] and got["unexplained"] == []
    assert "x_1" in got["causes"][0]["explains"] and "a_w_12" in got["causes"][0]["explains"]
    assert main(["check", "--template", str(group / "G03" / "gears.toml"), "-o", str(tmp_path / "blank.toml"),
                 "--quiet"]) == 0
    blank = tomlkit.parse((tmp_path / "blank.toml").read_text(encoding="utf-8"))
    key = json.loads((group / "G03" / "key.json").read_text(encoding="utf-8"))
    assert set(blank["positions"][0]["values"]) == set(key["values"])


def test_a_toml_table_and_a_bad_rubric(tmp_path: Path, capsys: pytest.CaptureFixture) -> None:
    shutil.copy(SAMPLE / "cam.template", tmp_path / "cam.template")
    (tmp_path / "t.toml").write_text(
        'format = 1\nkind = "variants"\ntemplate = "cam.template"\n'
        '[[variants]]\nvariant = "K1"\nr0 = 50\ne = 0\nh = 10\nphi_rise = 60\nphi_dwell = 220\nlaw = "harmonic"\n'
        '[[variants]]\nvariant = "K2"\nr0 = 55.5\ne = 5\nh = 12\nphi_rise = 70\nphi_dwell = 200\nlaw = "poly345"\n',
        encoding="utf-8")
    out = tmp_path / "out"
    assert main(["variants", str(tmp_path / "t.toml"), "-o", str(out), "--no-sheets", "--quiet"]) == 0
    key = json.loads((out / "K2" / "key.json").read_text(encoding="utf-8"))
    assert key["values"]["r0"]["0"] == 55.5 and key["values"]["e"]["0"] == 5
    subs = tmp_path / "subs"
    subs.mkdir()
    from plans.group.samples import key_submission

    (subs / "a.toml").write_text(tomlkit.dumps(key_submission(out / "K1", subs / "a.toml", "A", "G")), encoding="utf-8")
    (tmp_path / "r.toml").write_text('format = 1\nkind = "rubric"\n[weights]\ncam = "two"\n', encoding="utf-8")
    capsys.readouterr()
    assert main(["check", str(subs), "--xlsx", str(tmp_path / "m.xlsx"), "--rubric", str(tmp_path / "r.toml")]) == 2
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) == 1 and "weights.cam" in err[0] and "r.toml" in err[0]
    assert not (tmp_path / "m.xlsx").exists()


def test_the_same_table_gives_the_same_bytes_in_parallel(tmp_path: Path) -> None:
    for name in ("gears.template", "cam.template"):
        shutil.copy(SAMPLE / name, tmp_path / name)
    (tmp_path / "t.csv").write_text("variant,template,m,z1,z2,r0,e,h,phi_rise,phi_dwell,law\n"
                                    "A,gears.template,4,13,30,,,,,,\n"
                                    "B,cam.template,,,,50,5,10,60,220,cycloidal\n"
                                    "C,gears.template,5,15,40,,,,,,\n", encoding="utf-8")
    for jobs, out in (("1", "one"), ("2", "two")):
        assert main(["variants", str(tmp_path / "t.csv"), "-o", str(tmp_path / out), "--jobs", jobs,
                     "--no-sheets", "--quiet"]) == 0
    one = {p.relative_to(tmp_path / "one"): p.read_bytes() for p in (tmp_path / "one").rglob("*") if p.is_file()}
    two = {p.relative_to(tmp_path / "two"): p.read_bytes() for p in (tmp_path / "two").rglob("*") if p.is_file()}
    assert one == two and len(one) == 9


def test_sheets_read_as_a_student_reads_them_stay_clean(group: Path) -> None:
    """Lengths read to ±0.4 mm and written to 0.1 mm, angles within ±0.5°, x and K to three
    decimals, ε to two: within the draftsman's tolerance and the course rule, no mistake."""
    import random

    from plans.group.samples import key_submission
    from plans.group.sheets import check_sheet

    rng = random.Random(7)
    names = [p.name for p in sorted(group.iterdir()) if p.name[0] in "GCSE"]
    assert len(names) >= 15
    for v in names:
        target = group / v / "student.toml"
        data = key_submission(group / v, target, "A", "G", sheet="synthesis" if v[0] == "S" else None)
        for pos in data["positions"]:
            for q, val in pos["values"].items():
                if q.startswith(("x_", "K")):
                    pos["values"][q] = round(val, 3)
                elif q.startswith("eps"):
                    pos["values"][q] = round(val, 2)
                elif q.startswith(("alpha", "theta", "psi", "gamma", "angle")):
                    pos["values"][q] = round(val + rng.uniform(-0.5, 0.5), 1)
                elif q.endswith("_amp") or q.startswith("mr_"):
                    pos["values"][q] = float(f"{val:.3g}")
                elif q.startswith(("F_", "M_")):  # a polygon's side at 50 mm per unit vector
                    pos["values"][q] = round(val + rng.uniform(-0.4, 0.4) / 50, 3)
                else:
                    pos["values"][q] = round(val + rng.uniform(-0.4, 0.4), 1)
        rep = check_sheet(data, str(target))
        assert not rep.causes and not rep.unexplained and rep.mark == rep.full, (v, rep.unexplained)


def test_a_drawing_read_at_the_wrong_scale_is_one_cause(group: Path) -> None:
    from plans.group.samples import key_submission
    from plans.group.sheets import check_sheet

    for v in ("G02", "C03", "S02"):
        target = group / v / "student.toml"
        data = key_submission(group / v, target, "A", "G", sheet="synthesis" if v[0] == "S" else None)
        for pos in data["positions"]:  # every length measured off the drawing, read at 1.1×
            for q, val in pos["values"].items():
                if q.startswith(("r_", "a_w", "R", "s", "l_", "H")):
                    pos["values"][q] = val * 1.1
        rep = check_sheet(data, str(target))
        assert [c.kind for c in rep.causes] == ["scale"] and not rep.unexplained, v
        assert "1.1×" in rep.causes[0].detail


def test_a_gears_figure_that_does_not_follow_from_the_students_own_is_arithmetic(group: Path) -> None:
    """a_w written 2 % off while the student's α_w is right: a_w ≠ a cos α / cos α_w."""
    from plans.group.samples import key_submission
    from plans.group.sheets import check_sheet

    target = group / "G04" / "student.toml"
    data = key_submission(group / "G04", target, "A", "G")
    data["positions"][0]["values"]["a_w_12"] *= 1.02
    rep = check_sheet(data, str(target))
    assert [(c.kind, c.explains) for c in rep.causes] == [("arithmetic", ("a_w_12",))] and not rep.unexplained
    assert rep.mark == rep.full - 3


def test_a_handout_speaks_one_language(group: Path) -> None:
    from drawings.variants import handout_svg
    from plans.group.build import build, read_table

    rows = {r.variant: r for r in read_table(SAMPLE / "group.csv")}
    student = {"name": "Иванов И. И.", "group": "МТ-31", "variant": "L01"}
    for v in ("L01", "G01", "C01", "S01"):
        got = build(rows[v])
        ru, en = handout_svg({**student, "variant": v}, got, "ru"), handout_svg({**student, "variant": v}, got, "en")
        assert "Сдать" in ru and "Hand in" not in ru and "Вариант" in ru
        assert "Hand in" in en and "Сдать" not in en and "Исходные" not in en
        assert ("30°, 120°" in ru) == (v[0] in "LS")  # the positions to draw, where there are any
        assert ("<circle" in ru) == (v[0] != "S")  # a synthesis shows no scheme: the design is the task
