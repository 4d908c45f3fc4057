"""One language per run beyond the errors: the renderer's terminal lines (``plans draw``'s
progress, ``plans variants``, ``plans serve``), the gradebook's headings, argparse's help,
the warnings of a scene read by a library call, and the workbench page's symbols and labels
in real headless Chromium."""

from __future__ import annotations

import io
import re
import shutil
import subprocess
import sys
from pathlib import Path

import pytest

from drawings.cli import main
from tests.test_language import CYRILLIC, _latin_words

ROOT = Path(__file__).resolve().parents[1]
SAMPLES = ROOT / "samples"


pytestmark = pytest.mark.usefixtures("english_locale")  # the default is the locale's: these tests choose it


def _russian(text: str, *own: str) -> set[str]:
    """The Latin words of a Russian text outside paths, file names and the given own words."""
    for w in sorted(own, key=len, reverse=True):
        text = text.replace(w, " ")
    text = re.sub(r"\S*/\S*|\S+\.(toml|svg|csv|pdf|xlsx)\b", " ", text)
    return _latin_words(text)


class _Terminal(io.StringIO):
    """stderr as a terminal: the progress lines are written."""

    def isatty(self) -> bool:
        return True


def test_draw_progress_lines_in_both_languages(tmp_path, monkeypatch, capsys):
    lines = {}
    for lang in ("ru", "en"):
        err = _Terminal()
        monkeypatch.setattr(sys, "stderr", err)
        assert main(["draw", str(SAMPLES / "gears" / "seed_train.toml"), "-o", str(tmp_path / lang), "--format", "svg",
                     "--language", lang]) == 0
        monkeypatch.undo()
        capsys.readouterr()
        lines[lang] = [ln.split("] ", 1)[-1] for ln in err.getvalue().splitlines()]
    assert len(lines["ru"]) == len(lines["en"]) >= 2
    assert lines["ru"][0].startswith("построение ") and lines["ru"][1].startswith("лист 1 из ")
    assert lines["en"][0].startswith("drawing ") and lines["en"][1].startswith("sheet 1 of ")
    assert not _russian("\n".join(lines["ru"]), "svg"), lines["ru"]
    assert not CYRILLIC.search("\n".join(lines["en"])), lines["en"]


def test_variants_lines_in_both_languages(tmp_path, capsys):
    shutil.copy(SAMPLES / "group" / "gears.template", tmp_path / "gears.template")
    (tmp_path / "t.csv").write_text("variant,template,m,z1,z2\nG1,gears.template,4,13,30\n", encoding="utf-8")
    (tmp_path / "r.csv").write_text("name,group,variant\nИванов И. И.,ТМ-21,G1\n", encoding="utf-8")
    got = {}
    for lang in ("ru", "en"):
        out = tmp_path / f"out-{lang}"
        assert main(["variants", str(tmp_path / "t.csv"), "--students", str(tmp_path / "r.csv"), "-o", str(out),
                     "--no-sheets", "--language", lang]) == 0, capsys.readouterr().err
        got[lang] = capsys.readouterr().out
    assert "чисел в ключе" in got["ru"] and "листов заданий: 1" in got["ru"]
    assert "зубчатые передачи" in got["ru"] and not _russian(got["ru"]), got["ru"]
    assert "figures in the key" in got["en"] and not CYRILLIC.search(got["en"])


def _serve_line(folder: Path, lang: str) -> str:
    proc = subprocess.Popen([sys.executable, "-c", "from drawings.cli import main; raise SystemExit(main())", "serve",
                             str(folder), "--port", "0", "--language", lang],
                            stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True, cwd=ROOT)
    try:
        line = proc.stdout.readline()
    finally:
        proc.terminate()
        proc.wait(10)
    return line.strip()


def test_serve_says_where_it_serves_in_both_languages(tmp_path):
    ru, en = _serve_line(tmp_path, "ru"), _serve_line(tmp_path, "en")
    assert ru.startswith("plans serve: ") and " по адресу http://127.0.0.1:" in ru and "остановить" in ru, ru
    assert not _russian(ru, "plans serve", "Ctrl-C"), ru
    assert en.startswith("plans serve: ") and " at http://127.0.0.1:" in en and not CYRILLIC.search(en), en


def test_gradebook_headings_in_both_languages():
    import openpyxl

    from plans.group.gradebook import Rubric, csv_text, xlsx_bytes

    kinds = ["cam", "gears", "linkage"]
    row = {"student": "Иванов", "group": "ТМ-21", "variant": "7", "mark": 4, "_score": 80.0, "cam": 90.0,
           "gears": 70.0, "linkage": 80.0, "causes": "", "unexplained": "", "findings": "", "_errors": []}
    rubric = Rubric({}, (), 60.0)
    heads = {}
    for lang in ("ru", "en"):
        wb = openpyxl.load_workbook(io.BytesIO(xlsx_bytes(kinds, {"ТМ-21": [row]}, rubric, lang)))
        heads[lang] = [c.value for c in next(wb["ТМ-21"].iter_rows(max_row=1))]
        assert csv_text(kinds, {"ТМ-21": [row]}, lang).splitlines()[0] == ",".join(heads[lang])
    assert heads["en"] == ["student", "group", "variant", "mark", "cam", "gears", "linkage", "causes", "unexplained",
                           "findings"]
    assert heads["ru"][:4] == ["студент", "группа", "вариант", "оценка"]
    assert not _russian(" ".join(heads["ru"])), heads["ru"]
    assert not CYRILLIC.search(" ".join(heads["en"]))


def test_help_in_russian_keeps_the_options_and_translates_argparse(capsys):
    with pytest.raises(SystemExit):
        main(["solve", "--help", "--language", "ru"])
    text = capsys.readouterr().out
    assert text.startswith("использование: plans solve") and "позиционные аргументы:" in text
    assert "параметры:" in text and "показать эту справку и выйти" in text and "--protocol" in text
    with pytest.raises(SystemExit):
        main(["solve", "--help"])
    assert capsys.readouterr().out.startswith("usage: plans solve")
    from plans.errors import run_language

    with pytest.raises(SystemExit):
        main(["solve", "--help", "--language", "ru"])
    capsys.readouterr()
    assert run_language() == "en"  # the run over: its language does not outlive it


def test_a_warning_of_a_library_call_speaks_the_scenes_language(tmp_path, capsys):
    """No command line: the scene's [sheet] language says the warning's language."""
    from plans.kinematics.placing import load_scene

    text = (SAMPLES / "slider_crank.toml").read_text(encoding="utf-8").replace('\nunit = "mm"', '\nunit = "m"', 1)
    for lang, prefix in (("ru", "plans: внимание: "), ("en", "plans: warning: ")):
        path = tmp_path / f"{lang}.toml"
        path.write_text(text + f'\n[sheet]\nlanguage = "{lang}"\n', encoding="utf-8")
        load_scene(path)
        err = capsys.readouterr().err.splitlines()
        assert err and all(e.startswith(prefix) for e in err), err


# --------------------------------------------------------------------------- the workbench page
from tests.test_workbench import server  # noqa: E402, F401 - the page's fixture (the browser is conftest's)


def _page_text(browser, url: str, lang: str) -> tuple[str, list[str]]:  # noqa: F811
    pg = browser.new_page(viewport={"width": 1366, "height": 900})
    pg.add_init_script(f"localStorage.setItem('plans-lang', '{lang}')")
    pg.goto(url + "/#file=slider_crank.toml")
    pg.wait_for_function("() => document.body.dataset.solved")
    pg.wait_for_function("() => document.querySelectorAll('#table tbody tr').length > 0")
    table = pg.inner_text("#table") + "\n" + pg.inner_text("#vel-scale") + "\n" + pg.inner_text("#acc-scale")
    labels = pg.eval_on_selector_all("#vel text, #acc text", "ts => ts.map(t => t.textContent)")
    pg.click("#show-cycle")  # the tables over the cycle: their titles and rows
    pg.wait_for_function("() => document.querySelectorAll('option').length > 0")
    labels += pg.eval_on_selector_all("option", "os => os.map(o => o.textContent)")
    pg.close()
    return table, labels


def test_workbench_shows_the_textbooks_symbols_in_the_pages_language(browser, server):  # noqa: F811
    _, url = server
    ru, ru_labels = _page_text(browser, url, "ru")
    en, en_labels = _page_text(browser, url, "en")
    for raw in ("omega_", "eps_", "p_a", "p_v", "by_", "rad/s^2"):
        assert raw not in ru, (raw, ru)
    assert "ω1" in ru and "ε1" in ru and "π a" in ru and "p a" in ru and "8,3383" in ru
    assert "μ = 0,1 (м/с)/мм" in ru and "μ = 10 мм/(м/с)" not in ru  # a Russian course's scale: units per mm
    assert any(lb.startswith("π") for lb in ru_labels) and not any("p_a" in lb for lb in ru_labels), ru_labels
    assert "по кинетостатике" in ru and "по рычагу Жуковского" in ru
    cycle = [lb for lb in ru_labels if " — " in lb]
    assert cycle and all(lb.endswith("Планы за цикл") for lb in cycle), cycle
    assert not _russian(" ".join(cycle)), sorted(_russian(" ".join(cycle)))
    assert not _russian(ru, "n_BA", "a_BA", "v_BA"), sorted(_russian(ru, "n_BA", "a_BA", "v_BA"))
    assert "μ = 10 mm/(m/s)" in en
    assert "ω1" in en and "p_a a" in en and "p_v a" in en and "by kinetostatics" in en and "8.3383" in en
    assert any(lb.startswith("p_a") for lb in en_labels), en_labels
    assert any(lb == "p_v a, mm — Plans over the cycle" for lb in en_labels), en_labels
    assert not CYRILLIC.search(en)


def _helps() -> list[str]:
    """Every command's and option's help and every description of the command line."""
    import argparse

    from drawings.cli import build_parser

    out: list[str] = []

    def walk(parser: argparse.ArgumentParser) -> None:
        out.append(parser.description or "")
        for a in parser._actions:
            out.append(a.help or "")
            if isinstance(a, argparse._SubParsersAction):
                out.extend(c.help or "" for c in a._choices_actions)
                for sub in a.choices.values():
                    walk(sub)

    walk(build_parser(None))
    return sorted({h for h in out if h and h != argparse.SUPPRESS and h != "show this help message and exit"})


def test_every_help_of_the_command_line_has_its_russian():
    """Each help in the catalogue; a Russian one holds no Latin word its English one lacks
    (the options, keys, formats and programs both name)."""
    from plans.messages_help import HELP_RU

    helps = _helps()
    assert len(helps) >= 80
    missing = [h for h in helps if h not in HELP_RU]
    assert not missing, missing
    for en in helps:
        ru = HELP_RU[en]
        assert CYRILLIC.search(ru), ru
        extra = {w for w in _latin_words(ru) if w not in set(re.findall(r"[A-Za-z]+", en))}
        assert not extra, (ru, extra)


def test_every_commands_help_in_russian(capsys):
    for command in ("solve", "check", "bench", "balance", "gears", "cam", "design", "draw", "demo", "note",
                    "variants", "serve"):
        with pytest.raises(SystemExit):
            main([command, "--help", "--language", "ru"])
        text = capsys.readouterr().out
        assert text.startswith(f"использование: plans {command}") and "показать эту справку и выйти" in text, text


def test_workbench_force_polygons_in_the_pages_language(browser, server):  # noqa: F811
    _, url = server
    got = {}
    for lang in ("ru", "en"):
        pg = browser.new_page(viewport={"width": 1366, "height": 900})
        pg.add_init_script(f"localStorage.setItem('plans-lang', '{lang}')")
        pg.goto(url + "/#file=slider_crank.toml")
        pg.wait_for_function("() => document.body.dataset.solved")
        pg.click("#show-forces")
        pg.wait_for_function("() => document.querySelectorAll('#force-panels figure').length > 0")
        got[lang] = pg.inner_text("#force-panels")
        pg.close()
    assert "Φ2" in got["ru"] and "F_ур" in got["ru"] and "группа 2-3" in got["ru"] and "Phi" not in got["ru"]
    assert not _russian(got["ru"]), sorted(_russian(got["ru"]))
    assert "Φ2" in got["en"] and "F_bal" in got["en"] and "group 2-3" in got["en"] and not CYRILLIC.search(got["en"])
