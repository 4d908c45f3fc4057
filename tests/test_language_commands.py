"""One language per run in every command's files, not only its terminal: ``plans solve``'s
JSON sentences and CSV headings, ``plans balance``'s and ``plans design``'s JSON sentences,
the scene ``plans design`` writes and the blank check file of ``plans check --template``, the
sheets' words, the workbench's check; English unchanged by the option; ``--font`` wherever
sheets are drawn; ``plans variants``'s warnings the same in every run."""

from __future__ import annotations

import csv
import io
import json
import re
import shutil
from pathlib import Path

import pytest

from drawings.cli import main
from tests.test_language import CYRILLIC, _latin_words, _titles

ROOT = Path(__file__).resolve().parents[1]
SAMPLES = ROOT / "samples"

pytestmark = pytest.mark.usefixtures("english_locale")


def _run(capsys, *argv: str) -> str:
    assert main(list(argv)) == 0, capsys.readouterr().err
    return capsys.readouterr().out


def _sentences(data, keys: tuple[str, ...]) -> list[str]:
    """The strings under ``keys`` anywhere in a JSON document (its sentences, not its keys)."""
    out: list[str] = []
    if isinstance(data, dict):
        for k, v in data.items():
            if k in keys and isinstance(v, str):
                out.append(v)
            else:
                out += _sentences(v, keys)
    elif isinstance(data, list):
        for v in data:
            out += _sentences(v, keys)
    return out


def _russian_ok(text: str) -> None:
    text = re.sub(r"[A-Za-z]\w*_\w+", " ", text)  # snake_case: a key the file or the JSON names
    assert not _latin_words(text), sorted(_latin_words(text))[:20]
    assert not re.search(r"\d\.\d", text), re.findall(r".{20}\d\.\d.{10}", text)[:3]


@pytest.mark.parametrize("name", ["four_bar.toml", "v_engine.toml", "v_engine_cycle.toml", "class3/triad_press.toml"])
def test_solve_json_sentences_in_the_runs_language(capsys, name):
    path = str(SAMPLES / name)
    en = _run(capsys, "solve", path, "--json", "-")
    assert _run(capsys, "solve", path, "--json", "-", "--language", "en") == en  # English: the same bytes
    ru = json.loads(_run(capsys, "solve", path, "--json", "-", "--language", "ru"))
    keys = ("text", "title", "angles", "sign_rule")
    said = _sentences(ru, keys)
    assert said and sum(bool(CYRILLIC.search(s)) for s in said) > 0.8 * len(said)  # the others: formulas alone
    own = _titles(SAMPLES / name)
    _russian_ok("\n".join(s for s in said if s not in own))
    assert not CYRILLIC.search("\n".join(s for s in _sentences(json.loads(en), keys) if s not in own))

    def shape(x):
        if isinstance(x, dict):
            return {k: shape(v) for k, v in x.items()}
        return [shape(v) for v in x] if isinstance(x, list) else type(x).__name__

    assert shape(ru) == shape(json.loads(en))  # the same keys and numbers, only the sentences


def test_solve_csv_headings_in_the_runs_language(capsys):
    path = str(SAMPLES / "v_engine_cycle.toml")
    en = _run(capsys, "solve", path, "--csv", "-")
    assert en.startswith("table,Plans over the cycle\nquantity,label,unit,")
    ru = list(csv.reader(io.StringIO(_run(capsys, "solve", path, "--csv", "-", "--language", "ru"))))
    assert ru[0] == ["таблица", "Планы за цикл"] and ru[1][:3] == ["величина", "обозначение", "ед."]
    heads = [r for r in ru if r and r[0] == "таблица"] + [r[:3] for r in ru if r and r[0] == "величина"]
    labels = [r[1] + " " + r[2] for r in ru if r and r[0] not in ("таблица", "величина")]
    _russian_ok(" ".join(" ".join(r) for r in heads) + " " + " ".join(labels))
    values = [float(v.replace(",", ".")) for r in ru[2:] for v in r[3:] if v and r[0] not in ("таблица", "величина")]
    want = [float(v) for r in csv.reader(io.StringIO(en)) for v in r[3:] if v and r[0] not in ("table", "quantity")]
    assert values == want  # the same numbers, with a decimal comma


def test_balance_json_notes_in_russian(capsys):
    path = str(SAMPLES / "engines" / "inline4.toml")
    en = json.loads(_run(capsys, "balance", path, "--json", "-"))
    ru = json.loads(_run(capsys, "balance", path, "--json", "-", "--language", "ru"))
    assert en["notes"] and len(en["notes"]) == len(ru["notes"])
    _russian_ok("\n".join(ru["notes"]) + "\n" + ru["units"]["angles"])
    assert not CYRILLIC.search("\n".join(en["notes"]) + en["units"]["angles"])


def test_design_json_and_scene_in_russian(capsys, tmp_path):
    path = str(SAMPLES / "synthesis" / "crank_rocker.toml")
    en = json.loads(_run(capsys, "design", path, "--json", "-"))
    ru = json.loads(_run(capsys, "design", path, "--json", "-", "--language", "ru"))
    assert en["choice"] and CYRILLIC.search(ru["choice"]) and not CYRILLIC.search(en["choice"])
    _russian_ok(ru["choice"])
    _run(capsys, "design", path, "-o", str(tmp_path / "ru.toml"), "--language", "ru")
    text = (tmp_path / "ru.toml").read_text(encoding="utf-8")
    comments = "\n".join(re.findall(r"^#(.*)", text, re.M))
    assert comments.startswith(" Синтезировано командой plans design")
    _russian_ok(comments.replace("plans design", "").replace("crank_rocker.toml", ""))
    assert main(["solve", str(tmp_path / "ru.toml"), "--quiet"]) == 0  # the scene it wrote is read back


def test_blank_check_file_in_russian_and_beside_another_folder(capsys, tmp_path):
    """The blank form's comments in the run's language; written into another folder it names
    its scene from there and is read back."""
    scene = str(SAMPLES / "slider_crank.toml")
    en = _run(capsys, "check", "--template", scene)
    target = tmp_path / "forms" / "slider.toml"
    target.parent.mkdir()
    _run(capsys, "check", "--template", scene, "-o", str(target), "--language", "ru")
    ru = target.read_text(encoding="utf-8")
    comments = "\n".join(re.findall(r"#(.*)", ru))
    assert comments.startswith(" Пустой файл проверки")
    _russian_ok(re.sub(r"plans check|\{[^}]*\}|\"[^\"]*\"|\bmeasured\b|\bvalues\b", " ", comments))
    assert not CYRILLIC.search(en)
    assert [ln for ln in ru.splitlines() if not ln.lstrip().startswith("#") and "#" not in ln and "scene =" not in ln] == \
        [ln for ln in en.splitlines() if not ln.lstrip().startswith("#") and "#" not in ln and "scene =" not in ln]


#: The sheets whose words differ most: a synthesis's table, an engine's indicator diagram
#: (its pressure scale), a linkage's plans and polygons.
_SHEETS = ["synthesis/crank_rocker.toml", "single_four_stroke.toml", "slider_crank.toml"]


@pytest.mark.parametrize("name", _SHEETS)
def test_sheet_words_in_russian(tmp_path, capsys, name):
    """Every word written on a Russian sheet is Russian, the symbols' letters apart (a
    subscript is a run of its own)."""
    import html

    path = SAMPLES / name
    assert main(["draw", str(path), "-o", str(tmp_path), "--format", "svg", "--language", "ru", "--quiet"]) == 0
    capsys.readouterr()
    words = []
    for svg in sorted(tmp_path.glob("*.svg")):
        for m in re.finditer(r"<text[^>]*>(.*?)</text>", svg.read_text(encoding="utf-8"), re.S):
            words.append(html.unescape(re.sub(r"<[^>]+>", " ", m.group(1))))
    text = "\n".join(words)
    for own in _titles(path):
        text = text.replace(own, " ")
    assert words and not _latin_words(re.sub(r"\S+\.toml\b", " ", text)), sorted(_latin_words(text))


def test_demo_page_type_follows_the_font(tmp_path, capsys):
    scene = str(SAMPLES / "four_bar.toml")
    _run(capsys, "demo", scene, "-o", str(tmp_path / "d.html"), "--frames", "4")
    _run(capsys, "demo", scene, "-o", str(tmp_path / "g.html"), "--frames", "4", "--font", "gost")
    plain, gost = (tmp_path / "d.html").read_text(encoding="utf-8"), (tmp_path / "g.html").read_text(encoding="utf-8")
    assert 'font: clamp(14px, 1.6vw, 22px)/1.35 "DejaVu Sans", Arial, sans-serif' in plain and "osifont" not in plain
    assert 'font: clamp(14px, 1.6vw, 22px)/1.35 osifont, "DejaVu Sans", Arial, sans-serif' in gost
    assert gost.count("osifont, \"DejaVu Sans\"") == 2  # the page's text and the drawings' labels
    assert plain.replace('"DejaVu Sans", Arial', 'osifont, "DejaVu Sans", Arial') == gost


def _osifont() -> bool:
    from drawings.paper.fonts import GOST_FAMILY, installed

    return installed(GOST_FAMILY)


@pytest.mark.skipif(not _osifont(), reason="osifont is not installed")
def test_note_figures_and_handouts_in_the_gost_font():
    from drawings.note.figures import _build
    from drawings.variants import handout_svg
    from plans.group.build import build, read_table
    from plans.note.source import read

    items = read([str(SAMPLES / "cams" / "flat_face_poly345.toml")])
    gost = "".join(p.svg() for p in _build(items[0], "all", "ru", "gost"))
    plain = "".join(p.svg() for p in _build(items[0], "all", "ru", None))
    assert "osifont" in gost and "osifont" not in plain
    got = build(read_table(SAMPLES / "group" / "group.csv")[0])
    assert not got.error, got.error
    st = {"name": "Иванов И. И.", "group": "ТМ-21", "variant": got.row.variant}
    page = handout_svg(st, got, "ru", "gost")
    assert 'font-family="osifont"' in page and "Иванов" in page
    assert 'font-family="osifont"' not in handout_svg(st, got, "ru")


@pytest.mark.parametrize("command", ["note", "variants", "demo"])
def test_font_option_where_sheets_are_drawn(capsys, command):
    with pytest.raises(SystemExit):
        main([command, "--help"])
    assert "--font {dejavu,gost}" in capsys.readouterr().out


def test_variants_warnings_name_the_variant_the_same_in_every_run(tmp_path, capsys):
    """A synthesis variant whose scene warns: the warning names the variant's file (its
    folder under the table), not a scratch folder, so two runs say the same."""
    for name in ("crank_rocker.template",):
        shutil.copy(SAMPLES / "group" / name, tmp_path / name)
    with open(SAMPLES / "group" / "group.csv", encoding="utf-8") as fh:
        lines = fh.read().splitlines()
    (tmp_path / "t.csv").write_text("\n".join([lines[0], next(ln for ln in lines if ln.startswith("S01,"))]) + "\n",
                                    encoding="utf-8")
    err = []
    for k in range(2):
        assert main(["variants", str(tmp_path / "t.csv"), "-o", str(tmp_path / f"out{k}"), "--quiet",
                     "--language", "ru"]) == 0
        err.append(capsys.readouterr().err)
    assert err[0] and err[0] == err[1] and "plans-variant-" not in err[0]
    assert all(line.startswith(f"plans: внимание: {tmp_path / 'S01'}/") for line in err[0].splitlines()), err[0]


from tests.test_workbench import _req, server  # noqa: E402, F401 - the workbench on a loopback port


def test_workbench_check_in_the_pages_language(server):  # noqa: F811
    """The workbench's check answers ``plans check --json`` in the page's language, and with
    ``names=1`` the textbook's names of its quantities."""
    root, url = server
    shutil.copy(SAMPLES / "v_engine.toml", root / "v_engine.toml")
    (root / "checks").mkdir(exist_ok=True)
    text = (SAMPLES / "checks" / "v_engine_coursework.toml").read_text(encoding="utf-8")
    (root / "checks" / "c.toml").write_text(text, encoding="utf-8")
    got = {}
    for lang in ("ru", "en"):
        status, _, body = _req(f"{url}/api/check?names=1&language={lang}&path=checks/c.toml", "POST", text.encode())
        assert status == 200, body
        got[lang] = json.loads(body)
    assert got["ru"]["causes"] and all(CYRILLIC.search(c["detail"]) for c in got["ru"]["causes"])
    assert not any(CYRILLIC.search(c["detail"]) for c in got["en"]["causes"])
    assert got["ru"]["names"]["omega_1"] == "ω1" and got["en"]["names"]["omega_1"] == "omega_1"
    status, _, _ = _req(f"{url}/api/check?language=de&path=checks/c.toml", "POST", text.encode())
    assert status == 400
