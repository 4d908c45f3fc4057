"""Every case of both bad-input tables (tests/test_hostile_inputs.py, tests/test_hostile_kinds.py)
run in Russian: its one error line holds no Latin word outside the file's and the command
line's own words (file names, fields, keys, values quoted from the file or the options,
the commands' names) and the symbols; the same cases run in English by those tables are
checked there for a Russian letter."""

from __future__ import annotations

import contextlib
import io
import re
from collections.abc import Callable
from pathlib import Path

import pytest

from drawings.cli import main
from tests import test_hostile_inputs as H  # noqa: N812 - the tables of bad inputs
from tests import test_hostile_kinds as K  # noqa: N812
from tests.test_language import _latin_words
from tests.test_language_more import _KEYS, _without_keys

pytestmark = pytest.mark.usefixtures("english_locale")  # the default is the locale's: these tests choose it


def _kinds(case: K.Case, tmp: Path) -> list[str]:
    (tmp / "out").mkdir(exist_ok=True)
    f = K._file(case.base, tmp, case.edit)
    return [a.format(f=f, dir=tmp, dotf=f"{tmp}/./out/../{f.name}") for a in (case.argv or K.BASES[case.base][1])]


def _error_line(argv: list[str]) -> str:
    err = io.StringIO()
    with contextlib.redirect_stderr(err), contextlib.redirect_stdout(io.StringIO()):
        try:
            status = main(argv)
        except SystemExit as exc:
            status = exc.code
    assert status == 2, (argv, err.getvalue())
    return err.getvalue().strip()


def english_words(line: str, tmp: Path, argv: list[str]) -> set[str]:
    """The Latin words of a Russian error line that are neither the file's nor the command
    line's own words nor symbols."""
    text = line.replace(str(tmp), "")
    own = " ".join(p.read_text(encoding="utf-8", errors="replace") for p in tmp.glob("*.toml")) + " ".join(argv)
    allowed = set(re.findall(r"[A-Za-z_]\w*", own)) | {"TOML", "UTF", "mm", "unit", "plans"} | _KEYS
    text = re.sub(r"/\S*|\[+[\w. ]+\]+|«[^»]*»|'[^']*'|\"[^\"]*\"|\S+\.toml\S*|0x[0-9a-f]+|--[\w-]+", " ", text)
    text = re.sub(r"(из|из:) [\w, ]+", " ", text)  # the keys a table takes, listed
    text = re.sub(r"\b[A-Za-z]\w*_\w*", " ", text)  # snake_case: a key, a field or a quantity
    return {w for w in _latin_words(_without_keys(text)) if w not in allowed}


def _russian_run(cases: list, prepare: Callable[[object, Path], list[str]], tmp_path: Path,
                 monkeypatch: pytest.MonkeyPatch) -> list[str]:
    bad = []
    for k, case in enumerate(cases):
        tmp = tmp_path / str(k)
        tmp.mkdir()
        argv = prepare(case, tmp)
        if argv:
            line = _error_line([argv[0], "--language", "ru", *argv[1:]])
        else:  # no command to take the option: the locale's language
            with monkeypatch.context() as m:
                m.setenv("LANG", "ru_RU.UTF-8")
                line = _error_line([])
        assert line.startswith("plans: ошибка: ") and len(line.splitlines()) == 1, (case.id, line)
        words = english_words(line, tmp, argv)
        if words:
            bad.append(f"{case.id}: {sorted(words)}: {line}")
    return bad


def test_every_bad_input_of_the_scene_and_check_table_in_russian(tmp_path, monkeypatch):
    bad = _russian_run(H.CASES, H.lay_out, tmp_path, monkeypatch)
    assert not bad, "\n".join(bad[:20])


def test_every_bad_input_of_every_kind_in_russian(tmp_path, monkeypatch):
    bad = _russian_run(K.CASES, _kinds, tmp_path, monkeypatch)
    assert not bad, "\n".join(bad[:20])


def test_the_scan_finds_an_english_sentence(tmp_path):
    """The scan above refuses an English sentence and passes the file's words."""
    (tmp_path / "s.toml").write_text('format = 1\nmodule = "abc"\n', encoding="utf-8")
    line = "plans: ошибка: s.toml: module: expected a module m > 0, got 'abc'"
    assert english_words(line, tmp_path, []) == {"expected", "got"}
    line = "plans: ошибка: s.toml: module: ожидалось: модуль m > 0, а записано 'abc'"
    assert english_words(line, tmp_path, []) == set()
