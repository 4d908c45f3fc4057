"""One language per run, over every command's files for every sample: the sheets (SVG, and DXF
for one sample of each kind), ``plans solve --json``/``--csv``, ``plans check`` of the check
samples with its marked sheets, the note (DOCX), the demonstration page (as a browser shows
it), ``plans variants`` (the key, the blank forms, a synthesis variant's scene, the handouts)
and the gradebook.  A Russian output holds no Latin word outside symbols, units, identifiers
and the user's own words (:func:`russian_leaks`); an English one no Cyrillic letter
(:func:`english_leaks`).  What is excluded is named by a rule of its own below.

The terminal lines of every command are scanned in tests/test_language.py; the check's
report, CSV and JSON sentences in tests/test_language_more.py.
"""

from __future__ import annotations

import csv
import html
import io
import json
import re
import shutil
import tomllib
from pathlib import Path
from typing import Any

import pytest

from drawings.cli import main
from tests.test_language import _latin_words
from tests.test_language_more import _own_words

ROOT = Path(__file__).resolve().parent.parent
SAMPLES = ROOT / "samples"
LANGS = ("ru", "en")


def _kind(path: Path) -> str:
    with open(path, "rb") as fh:
        return str(tomllib.load(fh).get("kind", "linkage"))


#: Every sample a command draws: samples/*.toml and its subfolders, the check files apart
#: (samples/checks: ``plans check`` reads them, :func:`test_check_samples_and_their_marked_sheets`).
DRAWABLE = sorted(p for p in SAMPLES.rglob("*.toml") if p.parent.name != "checks")
SCENES = [p for p in DRAWABLE if _kind(p) == "linkage"]
#: One sample of each kind of sheet for the DXF: the text a CAD program reads back.
DXF_SAMPLES = {"slider_crank", "v_engine_cycle", "inline4", "planetary_2kh", "seed001_valve_cam", "crank_rocker",
               "turning_moment", "triad_press"}

pytestmark = pytest.mark.usefixtures("english_locale")

#: The ``[sheet]`` strings that are the user's own words, in the title block as written.
_SHEET_OWN = ("title", "designation", "subtitle", "author", "checked_by", "approved_by", "group", "organization",
              "date")
#: A file's name as a command writes it beside a sentence ("samples/x.toml", "key.json").
_FILE_NAME = re.compile(r"\S*[\w-]+\.(?:toml|csv|json|docx|pdf|svg|xlsx|template)\b")


def own_words(*paths: Path) -> list[str]:
    """The user's own words in ``paths``: the titles and the ``[sheet]`` strings, longest first."""
    out: list[str] = []
    for path in paths:
        with open(path, "rb") as fh:
            out += own_of(tomllib.load(fh))
    return sorted({w for w in out if w}, key=len, reverse=True)


def own_of(data: dict) -> list[str]:
    """The user's own words of a file's table: its title and its ``[sheet]`` strings."""
    out: list[str] = []
    sheet = data.get("sheet") or {}
    for v in (data.get("title"), *(sheet.get(key) for key in _SHEET_OWN)):
        out += [v] if isinstance(v, str) else [x for x in (v or {}).values() if isinstance(x, str)]
    return out


def _without(text: str, own: list[str]) -> str:
    """``text`` without the user's strings, whole, then word by word (a title block wraps a
    long title or organisation over lines), and without file names."""
    for w in sorted(own, key=len, reverse=True):
        text = text.replace(w, " ")
    text = _FILE_NAME.sub(" ", text)
    words = {x for w in own for x in re.findall(r"[^\W\d_]+", w)}
    if words:
        text = re.sub(r"[^\W\d_]+", lambda m: " " if m.group(0) in words else m.group(0), text)
    return text


def russian_leaks(text: str, own: list[str] = ()) -> list[str]:  # type: ignore[assignment]
    """The English words and decimal points of a Russian text (the user's words and the
    file names apart); symbols, units and identifiers pass (:func:`tests.test_language._latin_words`)."""
    text = _without(text, list(own))
    bad = sorted(_latin_words(text))
    return bad + re.findall(r".{0,20}\d\.\d.{0,10}", text)


def english_leaks(text: str, own: list[str] = ()) -> list[str]:  # type: ignore[assignment]
    """The Cyrillic words of an English text (the user's words and the file names apart)."""
    return sorted(set(re.findall(r"\S*[А-Яа-яЁё]\S*", _without(text, list(own)))))


#: A polygon's segment found, named by its two letters ("F21^n = no."): a symbol, not a word.
_SEGMENT_FOUND = re.compile(r"(?<== )[a-z]{2}(?=[.,;]?\s)")


def leaks(text: str, lang: str, own: list[str] = ()) -> list[str]:  # type: ignore[assignment]
    return russian_leaks(text, own) if lang == "ru" else english_leaks(text, own)


def test_the_scan_finds_a_word_of_the_other_language():
    """The scan refuses a half-translated line in either language and passes the user's own words."""
    assert russian_leaks("План скоростей, scale 1:2,5") == ["scale"]
    assert russian_leaks("μv = 2.5 мм/(м/с)") == ["μv = 2.5 мм/(м/с)"]
    assert russian_leaks("Кинематическая схема, Shaper", ["Shaper"]) == []
    assert russian_leaks("V6 engine,\n90° V, three crank pins", ["V6 engine, 90° V, three crank pins"]) == []
    assert russian_leaks("см. samples/slider_crank.toml") == []
    assert english_leaks("Velocity plan, масштаб") == ["масштаб"]
    assert english_leaks("Механизм: Velocity plan", ["Механизм"]) == []


# --------------------------------------------------------------------------- sheets


def _svg_text(svg: str) -> str:
    """The words of an SVG as drawn: each text element's runs (a subscript a run of its own)."""
    out = []
    for m in re.finditer(r"<text[^>]*>(.*?)</text>", svg, re.S):
        out.append(html.unescape(re.sub(r"<[^>]+>", " ", m.group(1))))
    return "\n".join(out)


def _dxf_text(data: bytes) -> str:
    """The TEXT and MTEXT of a DXF read back by ezdxf, in the blocks too."""
    import ezdxf

    doc = ezdxf.read(io.StringIO(data.decode("utf-8")))
    out = []
    for layout in [doc.modelspace(), *doc.blocks]:
        for e in layout.query("TEXT MTEXT"):
            out.append(e.plain_text() if e.dxftype() == "MTEXT" else e.dxf.text)
    return "\n".join(out)


def _sheet_words(path: Path) -> dict[str, tuple[set[str], str, str]]:
    """Both languages' sheets of a sample, solved once: per language the sheets' languages,
    their SVG words and (:data:`DXF_SAMPLES`) their DXF words.  Drawn without the search for
    longer plans (:func:`drawings.linkage.larger.may_grow`): it changes the scales and the
    room, not a word (the same sets of words either way: slider_crank, six_link,
    v_engine_cycle, both languages)."""
    import drawings
    import plans
    from drawings.linkage import larger

    keep = larger.may_grow
    larger.may_grow = lambda sol, spec: False
    try:
        sol = plans.solve(path)
        out = {}
        for lang in LANGS:
            d = drawings.draw(sol, language=lang)
            svg = "\n".join(_svg_text(sh.svg()) for sh in d.sheets)
            dxf = "\n".join(_dxf_text(sh.dxf()) for sh in d.sheets) if path.stem in DXF_SAMPLES else ""
            out[lang] = ({sh.spec.language for sh in d.sheets}, svg, dxf)
        return out
    finally:
        larger.may_grow = keep


#: The samples' sheets being drawn (:func:`_drawn_meanwhile`), by path.
_DRAWING: dict[Path, Any] = {}


@pytest.fixture(scope="module", autouse=True)
def _drawn_meanwhile(request):
    """The sheets of every sample a selected test reads, both languages, drawn in two other
    processes while this module's other tests run (the samples are independent; CI's machine
    has two cores), the longest first; the sheets' tests, last in the module, read them."""
    import multiprocessing
    import os
    from concurrent.futures import ProcessPoolExecutor

    wanted = {item.callspec.params["path"] for item in request.session.items
              if getattr(item, "originalname", "") == "test_every_sheet_of_every_sample_in_one_language"}
    if (os.cpu_count() or 1) < 2 or not wanted:
        yield  # drawn here, when read
        return
    pool = ProcessPoolExecutor(2, mp_context=multiprocessing.get_context("fork"))
    try:
        _DRAWING.update({p: pool.submit(_sheet_words, p) for p in sorted(wanted, key=lambda p: -p.stat().st_size)})
        yield
    finally:
        pool.shutdown(wait=True, cancel_futures=True)
        _DRAWING.clear()


def sheet_words(path: Path) -> dict[str, tuple[set[str], str, str]]:
    return _DRAWING[path].result() if path in _DRAWING else _sheet_words(path)


def test_sheets_and_terminal_follow_the_locale_when_nothing_is_asked(tmp_path, monkeypatch, capsys):
    """No option, no ``[sheet] language``: the sheets speak the locale's language, as the
    terminal does (one run, one language); a file's ``[sheet] language`` wins over the locale."""
    scene = SAMPLES / "synthesis" / "crank_rocker.toml"
    for locale, lang in (("ru_RU.UTF-8", "ru"), ("C.UTF-8", "en")):
        monkeypatch.setenv("LANG", locale)
        out = tmp_path / lang
        assert main(["draw", str(scene), "-o", str(out), "--format", "svg"]) == 0
        assert main(["design", str(scene)]) == 0
        said = capsys.readouterr().out
        text = "\n".join(_svg_text(p.read_text(encoding="utf-8")) for p in sorted(out.glob("*.svg")))
        assert text.strip() and not leaks(text, lang, own_words(scene)), leaks(text, lang)
        assert said.strip() and not leaks(said, lang, own_words(scene)), said
    from plans.scene.sheet import sheet_spec

    monkeypatch.setenv("LANG", "C.UTF-8")
    assert sheet_spec({"sheet": {"language": "ru"}}, "x.toml").language == "ru"
    assert sheet_spec({}, "x.toml").language == "en"
    monkeypatch.setenv("LANG", "ru_RU.UTF-8")
    assert sheet_spec({}, "x.toml").language == "ru"
    assert sheet_spec({"sheet": {"language": "en"}}, "x.toml").language == "en"


# --------------------------------------------------------------------------- plans solve --json --csv

#: A JSON document's sentences: the values under these keys (the others are identifiers, the
#: keys and units a program reads, the same in both languages).
_SENTENCES = ("text", "title", "angles", "sign_rule", "note", "notes", "detail", "choice", "warning", "message")


def _keys(data) -> set[str]:
    """Every key of a JSON document: a sentence that names one ("phi_deg в градусах") names an
    identifier, the same in both languages."""
    if isinstance(data, dict):
        return set(data) | {k for v in data.values() for k in _keys(v)}
    return {k for v in data for k in _keys(v)} if isinstance(data, list) else set()


def _without_keys(text: str, data) -> str:
    keys = _keys(data)
    return re.sub(r"\w+", lambda m: " " if m.group(0) in keys else m.group(0), text)


def _strings(data, keys: tuple[str, ...] | None = None) -> list[str]:
    """The strings of a JSON document: under ``keys`` (None: every one), never the keys themselves."""
    out: list[str] = []
    if isinstance(data, dict):
        for k, v in data.items():
            if isinstance(v, str):
                out += [v] if keys is None or k in keys else []
            elif isinstance(v, list) and keys is not None and k in keys:  # a list of sentences
                out += [x for x in v if isinstance(x, str)] + _strings([x for x in v if not isinstance(x, str)], keys)
            else:
                out += _strings(v, keys)
    elif isinstance(data, list):
        for v in data:
            out += [v] if isinstance(v, str) and keys is None else _strings(v, keys)
    return out


@pytest.mark.parametrize("path", SCENES, ids=[f"{p.parent.name}-{p.stem}" for p in SCENES])
def test_solve_json_and_csv_of_every_scene(tmp_path, capsys, path):
    """``plans solve --json --csv`` in both languages: the CSV (headings, labels, a decimal
    comma) and the JSON's sentences in Russian; nothing Cyrillic in English."""
    own = own_words(path)
    for lang in LANGS:
        j, c = tmp_path / f"{lang}.json", tmp_path / f"{lang}.csv"
        assert main(["solve", str(path), "--json", str(j), "--csv", str(c), "--quiet", "--language", lang]) == 0
        capsys.readouterr()
        data = json.loads(j.read_text(encoding="utf-8"))
        said = "\n".join(_strings(data, _SENTENCES if lang == "ru" else None))
        said = _SEGMENT_FOUND.sub(" ", _without_keys(said, data))
        assert not leaks(said, lang, own), (path.name, lang, "json", leaks(said, lang, own)[:20])
        if c.exists():  # a scene with tables over the positions
            table = c.read_text(encoding="utf-8")
            rows = list(csv.reader(io.StringIO(table)))
            # a row: the quantity's key (an identifier, the JSON's, the same in both languages), its
            # label and unit, the values; a table's title and its head row are words throughout
            heads = {"table", "quantity", "таблица", "величина"}
            words = "\n".join(" ".join(r[:3] if r and r[0] in heads else r[1:3]) for r in rows)
            if lang == "en":
                words = table
            assert not leaks(words, lang, own), (path.name, lang, "csv", leaks(words, lang, own)[:20])
            if lang == "ru":
                assert not re.search(r"\d\.\d", table), "a decimal point in a Russian CSV"


# --------------------------------------------------------------------------- plans check

CHECKS = sorted((SAMPLES / "checks").glob("*.toml"))


def _check_own(path: Path) -> list[str]:
    """A check file's own words: the student, the title, its keys (quantity names), its scene's."""
    with open(path, "rb") as fh:
        data = tomllib.load(fh)
    own = [str(data.get(k, "")) for k in ("student", "group", "title")]
    own += [k for k in re.findall(r"^\s*\"?([\w^']+)\"?\s*=", path.read_text(encoding="utf-8"), re.M) if "_" in k]
    if isinstance(data.get("scene"), str):
        own += own_words(path.parent / data["scene"])
    return sorted({w for w in own if w}, key=len, reverse=True)


#: The check's CSV column that names the field of the check file a row reads (its own path).
_FIELD_COLUMN = ("field", "поле")


@pytest.mark.parametrize("path", CHECKS, ids=lambda p: p.stem)
def test_check_samples_and_their_marked_sheets(tmp_path, capsys, path):
    """``plans check`` of every check sample, both languages: the report, the CSV (its header,
    the form read back, apart), the JSON's sentences and the marked sheets."""
    own = _check_own(path)
    for lang in LANGS:
        out = tmp_path / lang
        out.mkdir()
        code = main(["check", str(path), "--csv", str(out / "r.csv"), "--json", str(out / "r.json"),
                     "--sheet", str(out / "sheets"), "--language", lang])
        # the student's own section numbers where a figure was written, "(3.2.1)": tests/test_language_more.py
        report = _own_words(capsys.readouterr().out)
        assert code in (0, 1), report
        assert report.strip() and not leaks(report, lang, own), (lang, leaks(report, lang, own)[:20])
        rows = list(csv.reader(io.StringIO((out / "r.csv").read_text(encoding="utf-8"))))
        cols = [k for k, h in enumerate(rows[0]) if h not in _FIELD_COLUMN]
        body = "\n".join(" ".join(r[k] for k in cols if k < len(r)) for r in rows)
        assert not leaks(body, lang, own), (lang, "csv", leaks(body, lang, own)[:20])
        data = json.loads((out / "r.json").read_text(encoding="utf-8"))
        said = _own_words("\n".join(_strings(data, _SENTENCES if lang == "ru" else None)))
        assert not leaks(said, lang, own), (lang, "json", leaks(said, lang, own)[:20])
        sheets = sorted((out / "sheets").glob("*.svg"))  # none for a dynamics sheet: no plan to mark
        text = _own_words("\n".join(_svg_text(p.read_text(encoding="utf-8")) for p in sheets))
        assert not leaks(text, lang, own), (lang, "sheet", leaks(text, lang, own)[:20])
        with open(path, "rb") as fh:
            assert bool(sheets) == ("positions" in tomllib.load(fh))  # a linkage's plans, marked


# --------------------------------------------------------------------------- plans note

#: One note of every kind of file the note reads: a linkage with its cycle and its forces, gears,
#: a cam, an engine.
NOTE_FILES = [SAMPLES / "v_engine_cycle.toml", SAMPLES / "gears" / "seed_train.toml",
              SAMPLES / "cams" / "seed001_valve_cam.toml", SAMPLES / "engines" / "inline4.toml"]


#: A section's or a figure's number, "3.1 Планы скоростей", "рисунок 2.4": not a decimal point.
_SECTION = re.compile(r"(?m)^\d+(?:\.\d+)+(?= )|(?<=[Рр]исун(?:ок|ке) )\d+\.\d+|(?<=[Тт]аблиц[аеы] )\d+\.\d+")


def _docx_text(path: Path) -> str:
    """A DOCX's paragraphs and table cells as python-docx reads them back, the header too."""
    import docx

    doc = docx.Document(str(path))
    out = [p.text for p in doc.paragraphs]
    for t in doc.tables:
        out += [c.text for row in t.rows for c in row.cells]
    for s in doc.sections:
        out += [p.text for p in s.header.paragraphs] + [p.text for p in s.footer.paragraphs]
    return "\n".join(out)


@pytest.mark.parametrize("lang", LANGS)
def test_note_in_one_language(tmp_path, capsys, lang):
    own = own_words(*NOTE_FILES)
    out = tmp_path / "note.docx"
    assert main(["note", *map(str, NOTE_FILES), "-o", str(out), "--language", lang, "--dpi", "30"]) == 0
    capsys.readouterr()
    text = _SECTION.sub(" ", _docx_text(out))
    assert len(text) > 2000 and not leaks(text, lang, own), leaks(text, lang, own)[:30]


# --------------------------------------------------------------------------- plans demo

#: What a reader sees on the page: the body's text as shown, at every step, with every
#: mistake shown in turn, then the cycle; the drawings' labels with it.
_SEEN = """() => {
  const out = [];
  const grab = () => out.push(document.body.innerText,
      [...document.querySelectorAll('svg text')].map((t) => t.textContent).join('\\n'));
  grab();
  const next = document.querySelector('#next');
  for (let k = 0; k < 1000 && !next.disabled; k++) { next.click(); grab(); }
  for (const box of document.querySelectorAll('#mistakes input')) { box.click(); grab(); box.click(); }
  document.querySelector('#mode-cycle').click();
  grab();
  return out.join('\\n');
}"""


#: What the page names in the reader's own terms: the keys of the keyboard ("Home / End").
_KEYS_NAMED = re.compile(r"\b(?:Home|End)\b")


@pytest.mark.parametrize("path", SCENES, ids=[f"{p.parent.name}-{p.stem}" for p in SCENES])
def test_demo_page_of_every_scene_as_a_browser_shows_it(browser, tmp_path, path):
    from drawings.demo import page

    own = own_words(path)
    for lang in LANGS:
        f = tmp_path / f"{lang}.html"
        f.write_text(page(path, language=lang, frames=4), encoding="utf-8")
        pg = browser.new_page(viewport={"width": 1024, "height": 768})
        try:
            pg.goto(f.as_uri())
            pg.wait_for_selector("body[data-ready='1']")
            seen = pg.evaluate(_SEEN)
        finally:
            pg.close()
        seen = _SEGMENT_FOUND.sub(" ", _KEYS_NAMED.sub(" ", seen))
        assert seen.strip() and not leaks(seen, lang, own), (lang, leaks(seen, lang, own)[:20])


# --------------------------------------------------------------------------- plans variants, the gradebook

#: A table of one variant of each template and the students' slips the gradebook explains.
_VARIANTS = ("L03", "G03", "C02", "E01", "S01")
_SLIPS = {"L03": "coriolis_reversed", "G03": "shift_coefficient", "C02": "base_radius"}


#: What a file's comment names in the file's own terms: the command to run ("plans check"), a
#: check file's tables (measured, values) and a value as it is typed there ("65 mm").
_COMMAND = re.compile(r"\bplans (?:solve|check|bench|balance|gears|cam|design|draw|demo|note|variants|serve)\b")
_FORM_TABLES = re.compile(r"\b(?:measured|values)\b")
_TYPED = re.compile(r'"[^"]*"')


def _comments(text: str) -> str:
    """A TOML file's comments (what follows a # outside a string), without what they name in
    the file's own terms."""
    out = []
    for line in text.splitlines():
        m = re.match(r'(?:[^"#]|"(?:[^"\\]|\\.)*")*#(.*)', line)
        if m:
            out.append(m.group(1))
    said = "\n".join(out)
    for rule in (_COMMAND, _FORM_TABLES, _TYPED):
        said = rule.sub(" ", said)
    return said


@pytest.fixture(scope="module")
def table(tmp_path_factory) -> Path:
    folder = tmp_path_factory.mktemp("table")
    for t in SAMPLES.joinpath("group").glob("*.template"):
        shutil.copy(t, folder / t.name)
    lines = (SAMPLES / "group" / "group.csv").read_text(encoding="utf-8").splitlines()
    rows = [ln for ln in lines[1:] if ln.split(",")[0] in _VARIANTS]
    (folder / "t.csv").write_text("\n".join([lines[0], *rows]) + "\n", encoding="utf-8")
    made = [r.split(",")[0] for r in rows]
    roster = ["name,group,variant"] + [f"Иванов {v},ТМ-21,{v}" for v in made]
    (folder / "roster.csv").write_text("\n".join(roster) + "\n", encoding="utf-8")
    return folder


@pytest.mark.parametrize("lang", LANGS)
def test_variants_files_handouts_and_gradebook_in_one_language(table, tmp_path, capsys, lang):
    """``plans variants`` in one language: its lines, every file's comments (the blank forms,
    a synthesis variant's scene), the key's strings, the handouts; then ``plans check`` of the
    students' work made from the keys (three with a slip) and its gradebook (XLSX, CSV)."""
    import openpyxl
    import tomlkit

    from drawings.variants import handout_svg
    from plans.group.build import build, read_table
    from plans.group.samples import key_submission

    out = tmp_path / "course"  # its paths and the folder it names, handouts, are the user's and the file's names
    assert main(["variants", str(table / "t.csv"), "-o", str(out), "--students", str(table / "roster.csv"),
                 "--no-sheets", "--language", lang]) == 0
    said = capsys.readouterr().out
    own = [str(out / "handouts"), str(out), str(table)] + [f"Иванов {v}" for v in _VARIANTS] + ["ТМ-21"]
    assert said.strip() and not leaks(said, lang, own), leaks(said, lang, own)
    folders = sorted(p for p in out.iterdir() if p.name != "handouts")
    assert len(folders) == len(_VARIANTS)
    for folder in folders:
        # the files the command writes (a variant's own file is its template filled in: the
        # teacher's words; a synthesis variant's scene.toml is designed, its heading the command's)
        ours = ["check.toml", "synthesis.check.toml", "scene.toml" if (folder / "synthesis.toml").exists() else ""]
        for f in [folder / n for n in ours if n and (folder / n).exists()]:
            text = _comments(f.read_text(encoding="utf-8"))
            assert text.strip() and not leaks(text, lang), (f, leaks(text, lang))
        assert (folder / "check.toml").read_text(encoding="utf-8").startswith(
            "# Пустой файл проверки" if lang == "ru" else "# A blank check file")
        key = json.loads((folder / "key.json").read_text(encoding="utf-8"))
        assert not english_leaks("\n".join(_strings(key)))  # the key: names and numbers, no sentence
    scene = (out / "S01" / "scene.toml").read_text(encoding="utf-8")
    assert scene.startswith("# Синтезировано" if lang == "ru" else "# Designed")
    assert len(list((out / "handouts").glob("*.pdf"))) == len(_VARIANTS)
    for row in read_table(table / "t.csv"):
        got = build(row, lang)
        page = _svg_text(handout_svg({"name": f"Иванов {row.variant}", "group": "ТМ-21", "variant": row.variant},
                                     got, lang))
        # the data row is the variant table's as the teacher wrote it: its columns' names and values
        mine = own + own_of(tomllib.loads(got.files[got.key["file"]])) + [*row.data, *row.data.values()]
        assert not leaks(page, lang, mine), (row.variant, leaks(page, lang, mine))
    subs = tmp_path / "subs"
    for folder in folders:
        target = subs / f"{folder.name}.toml"
        target.parent.mkdir(parents=True, exist_ok=True)
        target.write_text(tomlkit.dumps(key_submission(folder, target, f"Иванов {folder.name}", "ТМ-21",
                                                       _SLIPS.get(folder.name))), encoding="utf-8")
    book, marks = tmp_path / "marks.xlsx", tmp_path / "marks.csv"
    main(["check", str(subs), "--xlsx", str(book), "--csv", str(marks), "--language", lang])
    said = capsys.readouterr().out
    assert not leaks(said, lang, own), leaks(said, lang, own)[:20]
    wb = openpyxl.load_workbook(book)
    cells = "\n".join(str(c) for ws in wb.worksheets for row in ws.iter_rows(values_only=True) for c in row
                      if isinstance(c, str))
    assert "Иванов L03" in cells and not leaks(cells, lang, own), leaks(cells, lang, own)[:20]
    rows = marks.read_text(encoding="utf-8")
    assert not leaks(rows, lang, own), leaks(rows, lang, own)[:20]


# --------------------------------------------------------------------------- the sheets, drawn meanwhile


@pytest.mark.parametrize(("path", "lang"), [(p, lang) for p in DRAWABLE for lang in LANGS],
                         ids=[f"{p.parent.name}-{p.stem}-{lang}" for p in DRAWABLE for lang in LANGS])
def test_every_sheet_of_every_sample_in_one_language(path, lang):
    """Every word of every sheet in the run's language (the DXF's too, one sample of each kind)."""
    langs, svg, dxf = sheet_words(path)[lang]
    own = own_words(path)
    assert langs == {lang}
    assert svg.strip() and not leaks(svg, lang, own), (path.name, leaks(svg, lang, own)[:20])
    if path.stem in DXF_SAMPLES:
        assert dxf.strip() and not leaks(dxf, lang, own), (path.name, "dxf", leaks(dxf, lang, own)[:20])
