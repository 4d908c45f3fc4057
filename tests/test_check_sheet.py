"""The marked and overlay sheets of a checked drawing (drawings.check_sheet), asserted on
what was drawn (recorded primitives), not on SVG bytes."""

from __future__ import annotations

import math
from pathlib import Path

import pytest

from drawings.check_sheet import marked_sheets, overlay_sheets, plan_with_marks, save_check_sheets
from plans.check.report import check_file

ROOT = Path(__file__).resolve().parent.parent
COURSEWORK = ROOT / "samples" / "checks" / "v_engine_coursework.toml"
MU_A = 0.0185


@pytest.fixture(scope="module")
def report():
    return check_file(COURSEWORK)


def _plan(report, phi, kind):
    pos = next(p for p in report.check.positions if p.phi_deg == phi)
    pp = report.context.plans[pos.index]
    return pp.velocity if kind == "velocity" else pp.acceleration


def _one(prims, eid):
    found = [p for p in prims if p.eid == eid]
    assert len(found) == 1, eid
    return found[0]


def test_student_point_marked_on_the_exact_direction_at_the_students_length(report):
    plan = _plan(report, 0.0, "acceleration")
    panel = plan_with_marks(report, plan, "ru")
    pole = _one(panel.prims, f"{panel.pid}-pt-p_a").pts[0]
    ring = _one(panel.prims, "check-acceleration-0-a_C-student")
    # the student measured p_a c = 17.5 mm (3.2.4); a_C lies along cylinder C's axis (135°)
    dx, dy = ring.pts[0][0] - pole[0], ring.pts[0][1] - pole[1]
    assert math.hypot(dx, dy) == pytest.approx(17.5, abs=1e-6)
    along = abs(dx * math.cos(math.radians(135)) - dy * math.sin(math.radians(135)))  # paper y is down
    assert along == pytest.approx(17.5, abs=1e-6)
    assert ring.style.stroke == "#c0261d"  # failed: red
    tol = _one(panel.prims, "check-acceleration-0-a_C-tol")
    item = next(i for i in report.items if i.quantity == "a_C" and i.phi_deg == 0.0)
    assert tol.r == pytest.approx(item.tolerance_mm)
    # the exact point is the centre of the tolerance circle, at the exact length from the pole
    exact_len = math.dist(tol.pts[0], pole)
    assert exact_len == pytest.approx(item.exact * MU_A, rel=1e-9)
    note = _one(panel.prims, "check-acceleration-0-a_C-note")
    assert "17,5" in note.label.plain


def test_passing_figure_is_green(report):
    panel = plan_with_marks(report, _plan(report, 45.0, "velocity"), "ru")
    ring = _one(panel.prims, "check-velocity-45-v_B-student")
    assert ring.style.stroke == "#1d7a34"


def test_marked_sheet_lists_failures_and_findings(report):
    sheets = marked_sheets(report, language="ru")
    assert sheets and (sheets[0].width, sheets[0].height) == (841.0, 594.0)
    texts = " ".join(p.label.plain for sh in sheets for p in sh.prims if p.op == "text" and p.label)
    assert "[проценты]" in texts and "[повтор]" in texts and "[симметрия]" in texts  # the sheet's language
    assert "δFур, % = 6,18" in texts  # quantities typeset, not raw keys; a decimal comma
    assert "F_bal" not in texts and "M_Phi" not in texts
    rings = [p for sh in sheets for p in sh.prims if p.op == "circle" and p.eid.endswith("-student")]
    assert len(rings) >= 30


def test_overlay_is_one_to_one_on_the_students_sheet(report):
    sheets = overlay_sheets(report, language="ru")
    # the plans at 1:1 on the smallest sheet that holds them (not a mostly empty A1)
    assert len(sheets) == 1 and (sheets[0].width, sheets[0].height) in ((297.0, 210.0), (420.0, 297.0),
                                                                         (594.0, 420.0))
    used = sum(p.width * p.height for p, _, _ in sheets[0].placed)
    assert used > 0.2 * sheets[0].width * sheets[0].height
    prims = [p for sh in sheets for p in sh.prims]
    # 1:1: p_v a is 82 mm on the overlay as on the student's sheet
    panel = plan_with_marks(report, _plan(report, 45.0, "velocity"), "ru", overlay=True)
    pole = _one(panel.prims, f"{panel.pid}-pt-p_v").pts[0]
    a = _one(panel.prims, f"{panel.pid}-pt-a").pts[0]
    assert math.dist(pole, a) == pytest.approx(12.4616 * 6.58, rel=1e-3)
    assert any(p.eid.endswith("-cross-h") for p in prims)
    assert not any(p.eid.endswith("-note") for p in prims)  # no annotations on tracing paper
    assert any(p.eid.endswith("-tol") for p in prims)


def test_save_writes_both_sheets(report, tmp_path):
    written = save_check_sheets(report, tmp_path, "cw", ("svg",))
    assert [p.name for p in written] == ["cw-marked.svg", "cw-overlay.svg"]
    assert all(p.stat().st_size > 1000 for p in written)


def test_sheet_option_on_the_check_command(tmp_path, capsys):
    from drawings.check_sheet import add_sheet_options
    from plans.cli import build_parser, run

    parser = build_parser()
    sub = next(a for a in parser._actions if a.__class__.__name__ == "_SubParsersAction")
    add_sheet_options(sub.choices["check"])
    args = parser.parse_args(["check", str(COURSEWORK), "--quiet", "--sheet", str(tmp_path), "--sheet-format", "svg"])
    assert run(args) == 0
    assert sorted(p.name for p in tmp_path.iterdir() if not p.name.startswith(".")) == [
        "v_engine_coursework-marked.svg",
        "v_engine_coursework-overlay.svg"]


def test_overlay_has_no_student_rings(report):
    prims = [p for sh in overlay_sheets(report) for p in sh.prims]
    assert not any(p.eid.endswith("-student") for p in prims)


def _texts(sheets) -> list[str]:
    return [p.label.plain for sh in sheets for p in (sh.prims or sh.render()) if p.op == "text" and p.label is not None]


def test_russian_marked_sheet_has_no_english_finding_words(report):
    """One language per sheet: every finding, failed figure and title of the Russian marked
    sheet in Russian, quantities typeset (M_Φ2, F_ур), never the report's keys."""
    import re

    from plans.check.wording import SENTENCES

    english = {w.lower() for en, _ru in SENTENCES.values() for w in re.findall(r"[A-Za-z]{3,}", en)}
    english |= {"exact", "findings", "figures", "pass", "fail", "duplicate", "relation", "symmetry", "swapped",
                "arithmetic", "percent", "scale", "mechanism", "engine", "twin"}
    assert report.findings and {"duplicate", "relation", "percent", "symmetry", "swapped", "pi"} <= \
        {f.kind for f in report.findings}
    texts = _texts(marked_sheets(report, language="ru"))
    words = {w.lower() for t in texts for w in re.findall(r"[A-Za-z]{3,}", t)}
    assert not words & english, sorted(words & english)
    joined = "\n".join(texts)
    for raw in ("M_Phi", "Phi", "F_bal", "bal", "omega", "eps_", "diff_pct"):
        assert raw not in joined, raw
    assert "MΦ2" in joined and "Fур" in joined  # typeset: M_{Φ2}, F_{ур}
    assert "Н·м" in joined and not re.search(r"\d (N|N m|m/s|kg|rad/s)\b", joined)  # units in Russian
    assert "записана по-разному" in joined and "вычислено с π = 3,14" in joined


def test_english_report_keeps_its_words(report):
    """The report's own text is the English rendering of the same words."""
    for f in report.findings:
        assert f.words is not None and f.words.render("en") == f.message
    texts = "\n".join(_texts(marked_sheets(report, language="en")))
    assert "is written as" in texts and "[duplicate]" in texts


def test_a_folder_checked_again_keeps_no_stale_sheet_or_report(tmp_path, capsys):
    from drawings.cli import main

    group, out, sheets = tmp_path / "group", tmp_path / "reports", tmp_path / "sheets"
    group.mkdir()
    text = COURSEWORK.read_text(encoding="utf-8").replace('scene = "../v_engine.toml"',
                                                         f'scene = "{ROOT / "samples" / "v_engine.toml"}"')
    (group / "a.toml").write_text(text, encoding="utf-8")
    (group / "b.toml").write_text(text, encoding="utf-8")
    args = ["check", str(group), "--out", str(out), "--quiet", "--sheet", str(sheets)]
    assert main([*args, "--sheet-format", "svg,png"]) == 0
    assert len([p for p in sheets.iterdir() if not p.name.startswith(".")]) == 8
    # b.toml now fails, and a.toml is drawn in one format only
    (group / "b.toml").write_text(text.replace("velocity = { mu = 6.58 }", "velocity = { mu = 0 }"), encoding="utf-8")
    assert main([*args, "--sheet-format", "svg"]) == 2
    assert "b.toml" in capsys.readouterr().err
    assert sorted(p.name for p in sheets.iterdir() if not p.name.startswith(".")) == ["a-marked.svg",
                                                                                      "a-overlay.svg"]
    assert sorted(p.name for p in out.iterdir()) == ["a.json", "a.txt", "summary.csv"]
