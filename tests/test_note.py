"""The explanatory note read back from its DOCX (python-docx and the XML): sections as
the files ask, numbers equal to the commands' JSON in the note's rounding, Office Math
equations, numbered and referenced figures and tables, one language, the same bytes."""

from __future__ import annotations

import io
import json
import math
import re
import zipfile
from pathlib import Path

import pytest

docx = pytest.importorskip("docx")

from plans.cli import main as plans_main  # noqa: E402

SAMPLES = Path(__file__).resolve().parent.parent / "samples"
V_ENGINE = str(SAMPLES / "v_engine.toml")  # seed 000: φ = 45° and 0°, forces and lever
PROJECT = str(SAMPLES / "projects" / "v_engine_project.toml")  # 12 positions, forces, diagrams, dynamics
SLIDER = str(SAMPLES / "slider_crank.toml")  # seed 001's slider-crank
GEARS = str(SAMPLES / "gears" / "seed_train.toml")  # seed 001's gear train
CAM = str(SAMPLES / "cams" / "seed001_valve_cam.toml")  # seed 001's valve cam
DPI = 30.0  # the figures' resolution does not matter here: small and quick

W = "{http://schemas.openxmlformats.org/wordprocessingml/2006/main}"
M = "{http://schemas.openxmlformats.org/officeDocument/2006/math}"


def _note(files: list[str], lang: str) -> bytes:
    from drawings.note.cli import note_bytes

    return note_bytes(files, lang, DPI)


def _json(tmp: Path, *argv: str) -> dict:
    out = tmp / f"{len(list(tmp.iterdir()))}.json"
    assert plans_main([*argv, "--json", str(out)] + (["--quiet"] if argv[0] == "solve" else [])) == 0
    return json.loads(out.read_text(encoding="utf-8"))


@pytest.fixture(scope="module")
def notes() -> dict[str, bytes]:
    return {"engine_ru": _note([V_ENGINE], "ru"), "project_ru": _note([PROJECT], "ru"), "cam_ru": _note([CAM], "ru"),
            "seed001_ru": _note([SLIDER, GEARS, CAM], "ru"), "seed001_en": _note([SLIDER, GEARS, CAM], "en")}


# --------------------------------------------------------------------------- reading back


class Read:
    """A note's body in order: (section heading, kind, text) with kind "p" (a paragraph's
    own text), "math" (one m:oMath's text, its spaces dropped), "table" (rows of cells)."""

    def __init__(self, data: bytes) -> None:
        self.doc = docx.Document(io.BytesIO(data))
        self.items: list[tuple[str, str, object]] = []
        self.headings: list[tuple[int, str]] = []
        heading = ""
        for el in self.doc.element.body:
            if el.tag == W + "p":
                style = el.find(f"{W}pPr/{W}pStyle")
                sid = style.get(W + "val") if style is not None else ""
                text = "".join(t.text or "" for t in el.iter(W + "t"))
                if sid.startswith("Heading"):
                    heading = text
                    self.headings.append((int(sid[-1]), text))
                    continue
                self.items.append((heading, "p", text))
                for m in el.iter(M + "oMath"):
                    self.items.append((heading, "math", _math_text(m).replace(" ", "")))
            elif el.tag == W + "tbl":
                rows = [["".join(t.text or "" for t in tc.iter(W + "t")) for tc in tr.iter(W + "tc")]
                        for tr in el.iter(W + "tr")]
                self.items.append((heading, "table", rows))

    def top(self) -> list[str]:
        """The numbered level-1 headings without their numbers."""
        return [re.sub(r"^\d+ ", "", t) for lvl, t in self.headings if lvl == 1]

    def text(self) -> str:
        return "\n".join(str(x) for _, k, x in self.items if k == "p") + "\n" + "\n".join(
            c for _, k, rows in self.items if k == "table" for r in rows for c in r)  # type: ignore[union-attr]

    def math(self, under: str = "") -> list[str]:
        return [str(x) for h, k, x in self.items if k == "math" and under in h]

    def table_after(self, caption: str) -> list[list[str]]:
        seen = False
        for _, k, x in self.items:
            if k == "p" and caption in str(x):
                seen = True
            elif k == "table" and seen:
                return x  # type: ignore[return-value]
        raise AssertionError(f"no table captioned {caption!r}")


def _math_text(el) -> str:
    """An equation's text, a fraction written (num)/(den)."""
    if el.tag == M + "t":
        return el.text or ""
    if el.tag == M + "f":
        num, den = el.find(M + "num"), el.find(M + "den")
        return f"({_math_text(num)})/({_math_text(den)})"
    return "".join(_math_text(c) for c in el)


def value(text: str) -> float:
    """A number as the note writes it: a decimal comma in Russian, a typographic minus."""
    return float(text.replace("−", "-").replace(",", ".").replace("\u2009", ""))


def rounded_equal(note_text: str, exact: float) -> bool:
    """The note's number is the engine's to its four significant figures (or more)."""
    x = value(note_text)
    if exact == 0:
        return x == 0
    e = math.floor(math.log10(abs(exact)))
    return abs(x - exact) <= 0.5 * 10 ** (e - 3) * (1 + 1e-9) + 1e-12


_NUM = r"−?\d+(?:[.,]\d+)?"


def after_eq(math_text: str) -> str:
    """The last number after the last '=' of an equation (its result)."""
    tail = math_text.rsplit("=", 1)[1]
    return re.findall(_NUM, tail)[0]


# --------------------------------------------------------------------------- sections


RU = {"task": "Задание и исходные данные", "structure": "Структурный анализ механизма",
      "kinematics": "Кинематический анализ механизма", "forces": "Силовой анализ механизма",
      "dynamics": "Динамика машины и маховик", "gears": "Зубчатые передачи", "cams": "Кулачковый механизм",
      "balancing": "Уравновешивание двигателя", "conclusions": "Заключение"}


def test_sections_as_the_files_ask(notes):
    assert Read(notes["engine_ru"]).top() == [RU[k] for k in ("task", "structure", "kinematics", "forces",
                                                                "conclusions")]
    assert Read(notes["project_ru"]).top() == [RU[k] for k in ("task", "structure", "kinematics", "forces",
                                                                 "dynamics", "conclusions")]
    assert Read(notes["seed001_ru"]).top() == [RU[k] for k in ("task", "structure", "kinematics", "forces",
                                                                 "gears", "cams", "conclusions")]
    en = Read(notes["seed001_en"]).top()
    assert en[0] == "The task and its data" and "Machine dynamics and the flywheel" not in en
    assert Read(notes["cam_ru"]).top() == [RU["task"], RU["cams"], RU["conclusions"]]


# --------------------------------------------------------------------------- numbers


def test_velocity_at_45_equals_plans_solve(notes, tmp_path):
    data = _json(tmp_path, "solve", V_ENGINE)
    k = next(i for i, p in enumerate(data["positions"]) if p["phi_deg"] == 45.0)
    want = {r["quantity"]: r["exact"] for r in data["positions"][k]["readings"]}
    rows = Read(notes["engine_ru"]).table_after("Скорости точек и угловые скорости звеньев, φ = 45°")
    got = {r[0]: r[3] for r in rows[1:]}
    assert rounded_equal(got["v_B"], want["v_B"]), (got["v_B"], want["v_B"])
    assert rounded_equal(got["v_BA"], want["v_BA"]) and rounded_equal(got["ω_2"], want["omega_2"])
    omega = next(m for m in Read(notes["engine_ru"]).math("φ = 45°") if m.startswith("ω2=(vBA)/(lAB)="))
    v, length = re.findall(_NUM, omega.split("=")[2])
    assert rounded_equal(v, abs(want["v_BA"])) and rounded_equal(after_eq(omega), abs(want["omega_2"]))
    assert abs(value(v) / value(length) - value(after_eq(omega))) <= 2e-3 * value(after_eq(omega))


def test_balancing_force_three_ways_equals_plans_solve(notes, tmp_path):
    data = _json(tmp_path, "solve", V_ENGINE)
    k = next(i for i, p in enumerate(data["positions"]) if p["phi_deg"] == 45.0)
    b = data["positions"][k]["balancing"]
    rd = Read(notes["engine_ru"])
    items = [(h, kd, x) for h, kd, x in rd.items if "φ = 45°" in h]
    found = {}
    for i, (_, kd, x) in enumerate(items):
        for key, words in (("by_kinetostatics", "по планам сил: "), ("by_lever", "по рычагу Жуковского: "),
                           ("by_power", "по балансу мощностей: ")):
            if kd == "p" and str(x).startswith(words):
                found[key] = str(items[i + 1][2])  # the paragraph's formula: F_ур = N Н
    assert set(found) == {"by_kinetostatics", "by_lever", "by_power"}
    for key, text in found.items():
        assert text.startswith("Fур=") and rounded_equal(after_eq(text), b[key]), (key, text, b[key])
    diff = [m for m in rd.math("φ = 45°") if m.startswith("Δ=")]
    assert diff and abs(value(after_eq(diff[0])) - b["difference_percent"]) <= 0.005 * abs(b["difference_percent"]) + 1e-3


def test_flywheel_equals_plans_solve(notes, tmp_path):
    fw = _json(tmp_path, "solve", PROJECT)["dynamics"]["flywheel"]
    eqs = [m for m in Read(notes["project_ru"]).math("Маховик") if m.startswith("IM=")]
    assert len(eqs) == 3
    graphical, exact, merkalov = (after_eq(m) for m in eqs)
    assert rounded_equal(graphical, fw["inertia_graphical"])
    assert rounded_equal(exact, fw["inertia_exact"])
    assert rounded_equal(merkalov, fw["inertia_merkalov"])


def test_working_pressure_angle_and_base_radius_equal_gears_and_cam(notes, tmp_path):
    g = _json(tmp_path, "gears", GEARS)
    c = _json(tmp_path, "cam", CAM)
    rd = Read(notes["seed001_ru"])
    alphas = [m for m in rd.math("Передача") if m.startswith("αw=")]
    assert len(alphas) == len(g["meshes"])
    for m, me in zip(alphas, g["meshes"], strict=True):
        assert rounded_equal(after_eq(m), me["working_pressure_angle_deg"]), (m, me["working_pressure_angle_deg"])
    r0 = [m for m in rd.math(RU["cams"]) if m.startswith("r0min=")]
    assert r0 and rounded_equal(after_eq(r0[0]), c["min_base_radius"])


def test_gear_speeds_table_equals_plans_gears(notes, tmp_path):
    g = _json(tmp_path, "gears", GEARS)
    rows = Read(notes["seed001_ru"]).table_after("Частоты вращения, об/мин")
    assert [r[0] for r in rows[1:]] == list(g["speeds_rpm"])
    for r in rows[1:]:
        assert len(r) == 3
        assert rounded_equal(r[1], g["speeds_rpm"][r[0]]) and rounded_equal(r[2], g["speeds_rpm_plan"][r[0]])


def test_chebyshev_formula_with_the_numbers(notes, tmp_path):
    st = _json(tmp_path, "solve", V_ENGINE)["structure"]
    eq = next(m for m in Read(notes["engine_ru"]).math(RU["structure"]) if m.startswith("W="))
    assert eq.endswith(f"3·{st['n']}−2·{st['p5']}−{st['p4']}={st['W']}")


# --------------------------------------------------------------------------- form


def test_equations_are_office_math(notes):
    body = docx.Document(io.BytesIO(notes["engine_ru"])).element.body
    maths = list(body.iter(M + "oMath"))
    assert len(maths) > 20
    assert len(list(body.iter(M + "f"))) > 3 and len(list(body.iter(M + "sSub"))) > 20
    for m in maths:  # equations are never pictures
        assert not list(m.iter(W + "drawing"))


@pytest.mark.parametrize("name, fig, tab", [("engine_ru", "Рисунок", "Таблица"), ("seed001_en", "Figure", "Table")])
def test_figures_and_tables_numbered_and_referenced(notes, name, fig, tab):
    rd = Read(notes[name])
    paras = [str(x) for _, k, x in rd.items if k == "p"]
    figs = [int(m.group(1)) for p in paras if (m := re.match(rf"{fig} (\d+) – ", p))]
    tabs = [int(m.group(1)) for p in paras if (m := re.match(rf"{tab} (\d+) – ", p))]
    assert figs == list(range(1, len(figs) + 1)) and len(figs) >= 5
    assert tabs == list(range(1, len(tabs) + 1)) and len(tabs) >= 3
    body = rd.doc.element.body
    assert len(list(body.iter(W + "drawing"))) == len(figs)
    assert len(list(body.iter(W + "tbl"))) == len(tabs)
    text = "\n".join(p for p in paras if not re.match(rf"({fig}|{tab}) \d+ – ", p))
    refs_f = {int(n) for n in re.findall(r"(?:рисун\w*|figures?)\s+(\d+)", text, re.I)}
    refs_f |= {int(n) for m in re.finditer(r"(?:рисунках|рисунки|figures)\s+([\d, и and]+)", text) for n in re.findall(r"\d+", m.group(1))}
    refs_t = {int(n) for n in re.findall(r"(?:таблиц\w*|tables?)\s+(\d+)", text, re.I)}
    assert set(figs) <= refs_f, sorted(set(figs) - refs_f)
    assert set(tabs) <= refs_t, sorted(set(tabs) - refs_t)


def test_one_language_per_note(notes):
    for name in ("engine_ru", "project_ru", "seed001_ru"):
        text = Read(notes[name]).text()
        # a Latin word: three letters or more standing alone (v_BA, p_v, ab, S2 are symbols)
        words = {m.group(0) for m in re.finditer(r"(?<![A-Za-z_^\d])[A-Za-z]{3,}(?![A-Za-z_\d])", text)}
        assert not words, (name, sorted(words))
        assert "Phi" not in text and "_bal" not in text, name  # the course's Φ and F_ур
    for name in ("seed001_en",):
        text = Read(notes[name]).text()
        assert not re.search(r"[А-Яа-яЁё]", text), name
        assert "Phi" not in text, name
    rows = Read(notes["engine_ru"]).table_after("Скорости точек и угловые скорости звеньев, φ = 45°")
    assert re.fullmatch(r"\d+,\d+", rows[1][3]), rows[1]  # v_A with a decimal comma


def test_a4_gost_margins_title_and_fields(notes):
    d = docx.Document(io.BytesIO(notes["project_ru"]))
    s = d.sections[0]
    assert (round(s.page_width.mm), round(s.page_height.mm)) == (210, 297)
    assert (round(s.left_margin.mm), round(s.right_margin.mm), round(s.top_margin.mm), round(s.bottom_margin.mm)) \
        == (30, 15, 20, 20)
    xml = d.element.xml
    assert " TOC " in xml and "ПОЯСНИТЕЛЬНАЯ ЗАПИСКА" in xml and "ТММ.КП.07.00.00" in xml
    assert " PAGE " in s.footer._element.xml and s.different_first_page_header_footer


def test_same_bytes_twice(notes, tmp_path):
    again = _note([CAM], "ru")
    assert again == notes["cam_ru"]
    import os
    import subprocess
    import sys

    out = tmp_path / "other.docx"  # another interpreter, another hash seed: the same bytes
    env = {**os.environ, "PYTHONHASHSEED": "12345"}
    subprocess.run([sys.executable, "-m", "drawings.cli", "note", CAM, "-o", str(out), "--language", "ru",
                    "--dpi", str(DPI)], check=True, env=env, capture_output=True)
    assert out.read_bytes() == again
    z = zipfile.ZipFile(io.BytesIO(again))
    assert {i.date_time for i in z.infolist()} == {(1980, 1, 1, 0, 0, 0)}
    assert b"2000-01-01T00:00:00Z" in z.read("docProps/core.xml")


# --------------------------------------------------------------------------- the command


def test_command_writes_the_note_and_refuses_its_input(tmp_path, capsys):
    from drawings.cli import main

    out = tmp_path / "note.docx"
    assert main(["note", CAM, "-o", str(out), "--language", "en", "--dpi", "30"]) == 0
    assert zipfile.is_zipfile(out)
    cam_copy = tmp_path / "cam.toml"
    cam_copy.write_bytes(Path(CAM).read_bytes())
    before = cam_copy.read_bytes()
    assert main(["note", str(cam_copy), "-o", str(cam_copy)]) == 2
    assert cam_copy.read_bytes() == before
    bad = tmp_path / "bad.toml"
    bad.write_text('format = 1\nkind = "gearbox"\n', encoding="utf-8")
    assert main(["note", str(bad), "-o", str(tmp_path / "x.docx")]) == 2
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) == 2 and all(e.startswith("plans: error:") for e in err) and "kind" in err[-1]
    assert not (tmp_path / "x.docx").exists()


def test_content_needs_no_renderer():
    import subprocess
    import sys

    code = (f"import sys; from plans.note.build import note; n = note([{CAM!r}], 'en'); "
            "assert not [m for m in sys.modules if m == 'docx' or m.startswith('drawings') or m == 'svgwrite'], "
            "sorted(m for m in sys.modules if m.startswith(('docx', 'drawings')))")
    subprocess.run([sys.executable, "-c", code], check=True)


def test_a_synthesis_file_gets_its_modules_section(tmp_path, monkeypatch):
    """The design section comes from the synthesis room's own module (a hook), after the
    structure and before the kinematics; without that module the file is one clear error."""
    import sys
    import types

    from plans.errors import InputError
    from plans.note.build import note
    from plans.note.model import Section

    syn = tmp_path / "syn.toml"
    syn.write_text('format = 1\nkind = "synthesis"\n', encoding="utf-8")
    monkeypatch.setitem(sys.modules, "plans.design.note", None)  # the room absent
    with pytest.raises(InputError, match="kind"):
        note([str(syn)], "en")
    hook = types.ModuleType("plans.design.note")
    hook.read = lambda path, raw: ("solved", {"k": 1})  # type: ignore[attr-defined]
    hook.section = lambda item, lang: [Section("Design of the mechanism", key="design").para(  # type: ignore[attr-defined]
        f"from {item.data['k']}")]
    monkeypatch.setitem(sys.modules, "plans.design.note", hook)
    keys = [s.key for s in note([V_ENGINE, str(syn)], "en").sections]
    assert keys == ["task", "structure", "design", "kinematics", "forces", "conclusions"]


def test_the_notes_arithmetic_holds(notes):
    """Every product written out (Φ = m·a_S, M_Φ = I_S·ε, G = m·g, ω1 = π·n/30's numbers) and
    every moment sum in numbers equals its result to the note's rounding."""
    checked = 0
    for name in ("engine_ru", "project_ru", "seed001_ru"):
        for m in Read(notes[name]).math():
            for a, b, c in re.findall(rf"=({_NUM})·({_NUM})=({_NUM})(?![\d·])", m):
                x, y, z = value(a), value(b), value(c)
                assert abs(x * y - z) <= 2e-3 * abs(z) + 1e-9, m
                checked += 1
            sums = re.fullmatch(rf".*?M\w*=((?:[−+]?{_NUM}·{_NUM})+)=({_NUM})Н·м", m)
            if sums:
                terms = re.findall(rf"([−+]?)({_NUM})·({_NUM})", sums.group(1))
                total = sum((-1 if s == "−" else 1) * value(f) * value(h) for s, f, h in terms)
                want = value(sums.group(2))
                assert abs(total - want) <= 2e-3 * max(abs(want), max(value(f) * value(h) for _, f, h in terms)) + 1e-9, m
                checked += 1
    assert checked > 30


def test_pdf_without_libreoffice_is_one_clear_line(tmp_path, capsys, monkeypatch):
    from drawings.cli import main
    from drawings.note import cli as note_cli

    monkeypatch.setattr(note_cli, "soffice", lambda: None)
    out = tmp_path / "note.pdf"
    assert main(["note", CAM, "-o", str(out), "--dpi", "30"]) == 2  # .pdf: the PDF asked for
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) == 1 and "LibreOffice" in err[0] and not out.exists()


def test_an_engine_gets_its_balancing(tmp_path):
    engine = str(SAMPLES / "engines" / "v_twin.toml")
    data = _json(tmp_path, "balance", engine)
    rd = Read(_note([engine], "ru"))
    assert rd.top() == [RU["task"], RU["balancing"], RU["conclusions"]]
    rows = rd.table_after("Неуравновешенные силы и моменты")
    got = [value(r[1]) for r in rows[1:]]
    want = [data["forces"][k]["amplitude"] for k in ("rotating", "first_order", "second_order")]
    assert all(rounded_equal(r[1], w) for r, w in zip(rows[1:], want, strict=True)), (got, want)
    cw = [m for m in rd.math(RU["balancing"]) if m.startswith("mпв·rпв=")]
    assert len(cw) == len(data["counterweights"])
    for m, c in zip(cw, data["counterweights"], strict=True):
        assert rounded_equal(re.findall(_NUM, m.split("=")[1])[0], c["mass_radius"])


def test_coriolis_acceleration_of_the_shaper(tmp_path):
    """A slotted link (RPR group): its vector equations with the Coriolis term, and
    a^k = 2·ω·v_rel with the plans' numbers, equal to plans solve's."""
    from drawings.note.omml import plain
    from plans.note.build import note
    from plans.note.model import Equation

    shaper = str(SAMPLES / "shaper.toml")
    data = _json(tmp_path, "solve", shaper)
    n = note([shaper], "ru")
    kin = next(s for s in n.sections if s.key == "kinematics")
    for k, sub in enumerate(kin.children[:2]):
        eqs = [plain(b.formula).replace(" ", "") for b in sub.blocks if isinstance(b, Equation)]
        assert "a_A3=a_A2+a_A3A2^k+a_A3A2^r=a_C+a_A3C^n+a_A3C^τ" in eqs
        cor = next(e for e in eqs if e.startswith("a_A3A2^k=2·ω_3·"))
        r = {x["quantity"]: x["exact"] for x in data["positions"][k]["readings"]}
        two, w, v, ak = re.findall(_NUM, cor.split("=", 2)[2])[:4]
        assert rounded_equal(w, abs(r["omega_3"])) and rounded_equal(ak, abs(r["a^k_A3A2"]))
        assert abs(2 * value(w) * value(v) - value(ak)) <= 2e-3 * abs(value(ak)) + 1e-9
