"""One language per run, beyond the solve: the check's reports (text, CSV, JSON's sentences)
of the samples and of the examiner's planted mistakes, every bad-input error of the hostile
table, the warnings of implausible scenes, the locale as the last default."""

from __future__ import annotations

import csv
import io
import json
import re
import shutil
from pathlib import Path

import numpy as np
import pytest

from plans.cli import main
from plans.errors import InputError, Said, field_name
from plans.language import CHECK_TERMS, WARNINGS, choose
from plans.messages import complete
from tests.test_language import CYRILLIC, _latin_words

ERRORS = complete()  # every sentence, the other file kinds' and the constructions' too

ROOT = Path(__file__).resolve().parent.parent
SAMPLES = ROOT / "samples"


pytestmark = pytest.mark.usefixtures("english_locale")  # the default is the locale's: these tests choose it


def _own_words(text: str, *own: str) -> str:
    """The text without the user's words: paths, titles, names, the student's section numbers."""
    for w in sorted(own, key=len, reverse=True):
        text = text.replace(w, "")
    text = re.sub(r"\S*(samples|/tmp|pytest)\S*|\S+\.toml\b", "", text)
    # where the student wrote a figure, the coursework's section: "(3.2.1)", a column "3.1.1, 3.2.1"
    text = re.sub(r"\(\d+(\.\d+)*(, \d+(\.\d+)*)*\)", "", text)
    return re.sub(r"(?<=  )\d+(\.\d+)+(, \d+(\.\d+)+)*(?=  \[)", "", text)


def _russian_ok(text: str) -> None:
    assert not _latin_words(text), sorted(_latin_words(text))[:20]
    assert not re.search(r"\d\.\d", text), re.findall(r".{20}\d\.\d.{20}", text)[:3]


# --------------------------------------------------------------------------- check reports


CHECKS = [SAMPLES / "checks" / "v_engine_coursework.toml", SAMPLES / "checks" / "dynamics_seed004.toml"]


def _check_own(path: Path) -> list[str]:
    import tomllib

    with open(path, "rb") as fh:
        data = tomllib.load(fh)
    scene = (path.parent / data["scene"]) if isinstance(data.get("scene"), str) else None
    own = [str(data.get("student", "")), str(data.get("title", ""))]
    own += [k for k in re.findall(r"^\s*(\w+)\s*=", path.read_text(encoding="utf-8"), re.M) if "_" in k]
    if scene is not None:
        with open(scene, "rb") as fh:
            t = tomllib.load(fh).get("title")
        own += list(t.values()) if isinstance(t, dict) else [str(t)]
    return [w for w in own if w]


@pytest.mark.parametrize("path", CHECKS, ids=lambda p: p.stem)
def test_check_report_text_csv_and_json_in_russian(capsys, path):
    own = _check_own(path)
    assert main(["check", str(path), "--language", "ru"]) == 0
    _russian_ok(_own_words(capsys.readouterr().out, *own))
    assert main(["check", str(path), "--language", "ru", "--csv", "-"]) == 0
    rows = list(csv.reader(io.StringIO(capsys.readouterr().out)))
    assert rows[0][0] in ("файл", "величина")
    _russian_ok(re.sub(r"\S+\[\d+\]", "", _own_words("\n".join(" ".join(r) for r in rows), *own)))  # fields


@pytest.mark.parametrize("path", CHECKS, ids=lambda p: p.stem)
def test_check_report_in_english_is_unchanged_by_the_option(capsys, path):
    own = _check_own(path)
    assert main(["check", str(path)]) == 0
    plain = capsys.readouterr().out
    assert main(["check", str(path), "--language", "en"]) == 0
    assert capsys.readouterr().out == plain
    assert not CYRILLIC.search(_own_words(plain, *own))


def test_check_json_keeps_its_keys_and_says_its_sentences_in_russian(capsys):
    path = CHECKS[0]
    assert main(["check", str(path), "--json", "-"]) == 0
    en = json.loads(capsys.readouterr().out)
    assert main(["check", str(path), "--json", "-", "--language", "ru"]) == 0
    ru = json.loads(capsys.readouterr().out)

    def keys(x):
        if isinstance(x, dict):
            return {k: keys(v) for k, v in x.items()}
        return [keys(v) for v in x] if isinstance(x, list) else None

    assert keys(en) == keys(ru)
    assert [c["kind"] for c in en["causes"]] == [c["kind"] for c in ru["causes"]]
    assert [c["deduction"] for c in en["causes"]] == [c["deduction"] for c in ru["causes"]]
    for c, f in zip(ru["causes"], en["causes"], strict=True):
        assert CYRILLIC.search(c["detail"]) and not CYRILLIC.search(f["detail"])
    for f in ru["findings"]:
        _russian_ok(_own_words(f["message"]))


@pytest.fixture(scope="module")
def planted_reports():
    from plans.check.checkfile import check_from_dict
    from plans.check.planted import PLANTED, Scenario, submission
    from plans.check.report import check

    out = []
    for name, phis in (("shaper", (30.0, 120.0)), ("six_bar", (30.0, 90.0))):
        sc = Scenario.of(SAMPLES / f"{name}.toml")
        for n, kind in enumerate(PLANTED):
            try:
                data, _ = submission(sc, phis, kind, np.random.default_rng(7 + n))
            except LookupError:
                continue
            out.append((kind, check(check_from_dict(data, f"{name}.toml"))))
    return out


def test_planted_mistakes_are_reported_in_russian(planted_reports):
    """Every mistake the examiner plants, named and explained in Russian, in English without
    a Russian letter; the same mark and the same causes in both."""
    from plans.check.report import csv_text, summary_row, table

    named = set()
    for _kind, rep in planted_reports:
        ru, en = table(rep, "ru"), table(rep, "en")
        _russian_ok(_own_words(ru, rep.check.student, rep.check.scene.title))
        assert not CYRILLIC.search(_own_words(en, rep.check.student, rep.check.scene.title))
        assert ru.count("\n") == en.count("\n")
        named |= {c.kind for c in rep.causes}
        row = csv_text([summary_row("x.toml", rep, lang="ru")], "ru")
        _russian_ok(_own_words(row, rep.check.student))
    assert len(named) >= 5, named


# --------------------------------------------------------------------------- the catalogue


def _all_keys() -> set[str]:
    """Every key the scene and check readers know (a message may list or name them)."""
    from plans.check import checkfile
    from plans.check.diagnosis import RUBRIC
    from plans.forces import loads
    from plans.scene import model

    out = set(RUBRIC) | {"ratio", "along", "across", "toward", "through", "mu", "K", "known_mm", "scene", "student",
                         "kind", "omega", "true", "false", "direction_deg", "vector", "magnitude", "resisting", "value",
                         "table", "expression", "stroke", "Fx", "Fy"}
    for mod in (model, loads, checkfile):
        for name, value in vars(mod).items():
            if name.endswith("KEYS") and isinstance(value, set | frozenset):
                out |= {k for k in value if isinstance(k, str)}
    # the other readers' keys (gears, cams, engines, synthesis tasks, the cycle, the sheet)
    import importlib

    for name in ("plans.gears.model", "plans.cams.model", "plans.balancing.engine", "plans.synthesis.model",
                 "plans.cycle.spec", "plans.check.cycle", "plans.scene.sheet", "plans.scene.friction",
                 "plans.kinematics.extreme", "plans.scene.positions", "plans.group.build"):
        for const, value in vars(importlib.import_module(name)).items():
            if const.isupper() and isinstance(value, set | frozenset | tuple | dict):
                out |= {k for k in value if isinstance(k, str) and re.fullmatch(r"[a-z]\w*", k)}
    # keys named in sentences of several readers; programs named by their names; inv α
    out |= {"lift", "rod", "rocker", "diameter", "area", "pressure", "diagram", "bore", "symbol", "style",
            "direction", "dpi", "phi", "inv", "pdf", "LibreOffice", "soffice"}
    return out


_KEYS = _all_keys()
_KEY_WORDS = re.compile(r"(?<![\w])(" + "|".join(sorted(map(re.escape, _KEYS), key=len, reverse=True)) + r")(?![\w])")


def _without_keys(text: str) -> str:
    """The text without the file's keys (``angle_deg``, ``phi0_deg``: the file's words)."""
    return _KEY_WORDS.sub(" ", text)




def _literal(template: str) -> str:
    """A template without its fields (the values are the file's own words)."""
    return re.sub(r"\[+[\w. ]+\]+|\"[^\"]*\"|'[^']*'|--[\w-]+|\*\.\w+", " ", re.sub(r"\{[^{}]*\}", " ", template))  # a field; a [table] or [[array]] of the file


@pytest.mark.parametrize("table", [ERRORS, WARNINGS, CHECK_TERMS], ids=["errors", "warnings", "check"])
def test_every_sentence_of_the_catalogue_in_both_languages(table):
    """Russian templates hold no English word outside symbols and the keys the file writes
    (unit, "mm"); English ones no Russian letter; both have the same fields."""
    keys_of_files = {"unit", "mm", "format", "plans"}
    for key, (en, ru) in table.items():
        fields = lambda t: set(re.findall(r"\{(\w+)", t))  # noqa: E731
        assert fields(ru) <= fields(en) and fields(en) - fields(ru) <= {"s"}, key  # s: an English plural
        assert not CYRILLIC.search(en), key
        literal = re.sub(r"[A-Za-z]\w*_\w+", " ", _without_keys(_literal(ru)))  # snake_case: a key or a quantity
        bad = _latin_words(literal.replace('"mm"', "")) - keys_of_files - {"TOML", "UTF"}
        assert not bad, (key, bad)


# --------------------------------------------------------------------------- bad input


HOSTILE = ROOT / "tests" / "data" / "hostile"


def _run_case(case, tmp: Path, lang: str, capsys) -> str:
    from drawings.cli import main as draw_main
    from tests import test_hostile_inputs as H  # noqa: N812 - the table of bad inputs

    argv = H.lay_out(case, tmp)
    assert draw_main([*argv, "--language", lang]) == 2
    err = capsys.readouterr().err.strip()
    assert len(err.splitlines()) == 1
    return err


def _said_cases():
    """The hostile cases whose error is the catalogue's (found once, in English)."""
    from tests import test_hostile_inputs as H  # noqa: N812

    return [c for c in H.CASES if c.argv[:1] in (("solve",), ("check",)) and "--language" not in c.argv]


def test_bad_input_in_both_languages(tmp_path, capsys):
    """Every error of the hostile table in Russian: the catalogue's are Russian through and
    through (outside the file's own words: file, field, keys and values quoted from it); in
    English none has a Russian letter.  Most of the table is the catalogue's already."""
    said = total = 0
    for k, case in enumerate(_said_cases()):
        tmp = tmp_path / str(k)
        tmp.mkdir()
        try:
            en = _run_case(case, tmp, "en", capsys)
            ru = _run_case(case, tmp, "ru", capsys)
        except SystemExit:
            capsys.readouterr()
            continue  # an argument error of argparse (its own English), not a file's
        if ".toml" not in en:
            continue  # an option's error (--sheet-format), as argparse words it
        total += 1
        assert en.startswith("plans: error: ") and not CYRILLIC.search(en.replace(str(tmp), "")), en
        assert ru.startswith("plans: ошибка: "), ru
        body = ru.split(": ", 2)[-1].replace(str(tmp), "")
        if not CYRILLIC.search(body):
            continue  # a message not yet in the catalogue: English in both
        said += 1
        body = re.sub(r"/\S*|\[+[\w. ]+\]+|«[^»]*»|'[^']*'|\"[^\"]*\"|\[\[[\w.]+\]\] № \d+|\S+\.toml\S*|0x[0-9a-f]+", " ", body)
        body = re.sub(r"(из|из:) [\w, ]+", " ", body)  # a list of the keys a table takes: the file's words
        head, _, message = body.partition(": ")
        text = message if re.fullmatch(r"[\w.\[\], №\\-]+", head) else body
        words = _latin_words(_without_keys(text))
        # what is left of the file's words: the keys listed as expected, a TOML parser's own
        allowed = set(re.findall(r"[A-Za-z_][\w]*", (tmp / "scene.toml").read_text(encoding="utf-8", errors="replace")))
        allowed |= set(re.findall(r"[A-Za-z_][\w]*", (tmp / "check.toml").read_text(encoding="utf-8", errors="replace")))
        allowed |= {"TOML", "UTF", "mm", "unit"} | _KEYS
        assert not {w for w in words if w not in allowed and not set(re.split("_", w)) <= allowed}, (case.id, ru)
    print(f"catalogue errors: {said} of {total}")
    assert total >= 150 and said >= 0.85 * total, (said, total)


def test_an_entry_of_joints_is_named_one_based():
    assert field_name("joints[3].guide.link") == "[[joints]] entry 4, guide.link"
    assert field_name("joints[3].guide.link", "ru") == "[[joints]] № 4, guide.link"
    assert field_name("loads.force[0]") == "[[loads.force]] entry 1"
    assert field_name("points.O[0]") == "points.O[0]"  # a coordinate of an array of numbers
    e = InputError(Said("e_table"), file="s.toml", field="joints[0]")
    assert str(e) == "s.toml: [[joints]] entry 1: expected a table"
    assert e.text("ru") == "s.toml: [[joints]] № 1: ожидалась таблица" and e.field == "joints[0]"


def test_a_decimal_comma_is_named_as_such(tmp_path, capsys):
    text = (SAMPLES / "slider_crank.toml").read_text(encoding="utf-8")
    bad = tmp_path / "comma.toml"
    bad.write_text(text.replace("[driver]", "[driver]\neps = 12,5  # rad/s²", 1), encoding="utf-8")
    assert main(["solve", str(bad)]) == 2
    err = capsys.readouterr().err
    line = text[:text.index("[driver]")].count("\n") + 2
    assert err == (f"plans: error: {bad}:{line}: driver.eps: '12,5' is written with a decimal comma; TOML numbers "
                   f"take a decimal point: write 12.5\n")
    assert main(["solve", str(bad), "--language", "ru"]) == 2
    assert "дробная часть отделена запятой" in capsys.readouterr().err


# --------------------------------------------------------------------------- warnings


def _mm_written_as_metres(tmp_path: Path) -> Path:
    text = (SAMPLES / "slider_crank.toml").read_text(encoding="utf-8")
    assert '\nunit = "mm"' in text
    out = tmp_path / "metres.toml"
    out.write_text(text.replace('\nunit = "mm"', '\nunit = "m"', 1), encoding="utf-8")
    return out


def test_a_unit_slip_is_warned_about_and_the_run_goes_on(tmp_path, capsys):
    """Millimetres with unit = "m": each link and the crank pin's speed beyond any machine,
    in the run's language, on stderr; the exit status and the output are the run's."""
    from plans.kinematics.placing import load_scene

    path = _mm_written_as_metres(tmp_path)
    scene = load_scene(SAMPLES / "slider_crank.toml")
    capsys.readouterr()
    r = scene.links[scene.driver.link]
    v_mm = abs(scene.driver.omega) * abs(r.points[r.axis[1]] - r.points[r.axis[0]])  # m/s, the file in mm
    assert main(["solve", str(path), "--quiet"]) == 0
    err = capsys.readouterr().err.splitlines()
    assert err and all(e.startswith("plans: warning: ") for e in err)
    assert any("links.1: link 1 is" in e and "unit = 'm'" in e for e in err)
    speed = next(e for e in err if "m/s is beyond" in e)
    assert float(re.search(r"= ([\d.e+]+) m/s", speed).group(1)) == pytest.approx(1000 * v_mm, rel=1e-3)
    assert main(["solve", str(path), "--quiet", "--language", "ru"]) == 0
    err = capsys.readouterr().err.splitlines()
    assert err and all(e.startswith("plans: внимание: ") for e in err)
    said = " ".join(e.split(": ", 3)[-1] for e in err)
    _russian_ok(re.sub(r"unit = \S+|links\.\d+:|\bunit\b", "", said))  # the file's keys
    assert main(["solve", str(SAMPLES / "slider_crank.toml"), "--quiet"]) == 0
    assert capsys.readouterr().err == ""  # a plausible scene: not a word


def test_a_cyrillic_letter_where_a_latin_one_is_meant(tmp_path, capsys):
    text = (SAMPLES / "slider_crank.toml").read_text(encoding="utf-8")
    i = text.index('point = "A"')
    bad = tmp_path / "cyr.toml"
    bad.write_text(text[:i] + 'point = "А"' + text[i + len('point = "A"'):], encoding="utf-8")
    assert main(["solve", str(bad)]) == 2
    err = capsys.readouterr().err
    assert "'А' is written with Cyrillic letters and link" in err and "has 'A' in Latin letters" in err
    assert "[[joints]] entry " in err
    assert main(["solve", str(bad), "--language", "ru"]) == 2
    err = capsys.readouterr().err
    assert "кириллические буквы" in err and "[[joints]] № " in err
    # the whole scene in Cyrillic А: consistent, solved, no word
    both = tmp_path / "both.toml"
    both.write_text(text.replace('"A"', '"А"'), encoding="utf-8")
    assert main(["solve", str(both), "--quiet"]) == 0 and capsys.readouterr().err == ""


def test_twin_and_mixed_names_are_warned_about(tmp_path, capsys):
    from plans.plausible import looks, script, twin

    assert script("А2") == "cyrillic" and script("A2") == "latin" and script("Аb") == "mixed"
    assert looks("СВ") == "CB" and twin("В", ["B", "C"]) == "B" and twin("D", ["B"]) is None
    text = (SAMPLES / "slider_crank.toml").read_text(encoding="utf-8")
    assert "\n[points]\n" in text
    path = tmp_path / "twins.toml"
    twins = '\n[points]\n"Oх" = [0, -50]\n"О" = [0, -90]\n'  # TOML quotes a name in Cyrillic
    path.write_text(text.replace("\n[points]\n", twins, 1), encoding="utf-8")
    assert main(["solve", str(path), "--quiet"]) == 0
    err = capsys.readouterr().err
    assert "the name 'Oх' mixes Cyrillic and Latin letters that look alike ('х')" in err, err
    assert re.search("the names '[OО]' and '[OО]' look the same but one is written in Cyrillic", err), err


def test_the_locale_is_the_last_default(monkeypatch, capsys):
    assert choose(None, {}) == "en"
    monkeypatch.setenv("LANG", "ru_RU.UTF-8")
    assert choose(None, {}) == "ru" and choose("en", {}) == "en"
    assert choose(None, {"sheet": {"language": "en"}}) == "en"
    assert main(["solve", str(SAMPLES / "slider_crank.toml")]) == 0
    assert "план скоростей" in capsys.readouterr().out
    monkeypatch.setenv("LC_ALL", "en_GB.UTF-8")
    assert choose(None, {}) == "en"


def test_a_figure_without_its_key_is_named_in_both_languages(tmp_path, capsys):
    """A measured figure written as a table without ``mm``: the missing key named in the
    run's language (the key itself as the file writes it)."""
    shutil.copy(HOSTILE / "scene.toml", tmp_path / "scene.toml")
    text = (HOSTILE / "check.toml").read_text(encoding="utf-8")
    assert text.count("\nv_B = 60\n") == 1
    (tmp_path / "check.toml").write_text(text.replace("\nv_B = 60\n", '\nv_B = { where = "3.1" }\n'), encoding="utf-8")
    assert main(["check", str(tmp_path / "check.toml")]) == 2
    assert capsys.readouterr().err.rstrip().endswith("measured.v_B: missing mm")
    assert main(["check", str(tmp_path / "check.toml"), "--language", "ru"]) == 2
    assert capsys.readouterr().err.rstrip().endswith("measured.v_B: не задано mm")
