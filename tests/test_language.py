"""One language per run: every terminal output of every sample, in Russian, has no Latin word
outside symbols, and in English no Cyrillic; English output is unchanged by the option."""

from __future__ import annotations

import re
import tomllib
from pathlib import Path

import pytest

from plans.cli import main

SAMPLES = Path(__file__).resolve().parent.parent / "samples"

#: Scenes whose output is still printed in English in part (none: every sample is scanned).
_ENGLISH_PARTS: set[str] = set()

_SCENES = sorted([*SAMPLES.glob("*.toml"), *SAMPLES.glob("projects/*.toml"), *SAMPLES.glob("class3/*.toml"),
                  *SAMPLES.glob("centres/*.toml"), *SAMPLES.glob("flywheel/*.toml")])
_RUNS = ([("solve", p, ["--protocol"]) for p in _SCENES]
         + [("gears", p, []) for p in sorted(SAMPLES.glob("gears/*.toml"))]
         + [("cam", p, []) for p in sorted(SAMPLES.glob("cams/*.toml"))]
         + [("balance", p, []) for p in sorted(SAMPLES.glob("engines/*.toml"))]
         + [("design", p, []) for p in sorted(SAMPLES.glob("synthesis/*.toml"))])

#: Latin words a Russian text may hold: the textbook's functions.  Besides these, a Latin run
#: of letters is a symbol only when it is one letter (v, a, h, l, x, i in F_ij...), capitals
#: (point names A, BA, S2, structure RRR) or two small letters naming a segment of a plan or
#: polygon (ab, oa); the English words of two letters are refused by name.
_FUNCTIONS = {"max", "min", "cos", "sin"}
_TWO_LETTER_WORDS = {"mm", "in", "at", "to", "by", "is", "of", "on", "or", "ok", "no", "an", "as", "if"}


#: A Russian letter: none may stand in an English output.
CYRILLIC = re.compile(r"[А-Яа-яЁё]")


def _latin_words(text: str) -> set[str]:
    bad = set()
    for w in re.findall(r"[A-Za-z]+", text):
        if len(w) == 1 or w.isupper() or w in _FUNCTIONS:
            continue
        if len(w) == 2 and w.islower() and w not in _TWO_LETTER_WORDS:
            continue
        bad.add(w)
    return bad


def _titles(path: Path) -> list[str]:
    """The file's own titles: the user's words, in whatever language the user wrote them."""
    with open(path, "rb") as fh:
        data = tomllib.load(fh)
    out: list[str] = []
    for t in (data.get("title"), (data.get("sheet") or {}).get("title")):
        if isinstance(t, str):
            out.append(t)
        elif isinstance(t, dict):
            out += [v for v in t.values() if isinstance(v, str)]
    return sorted(out, key=len, reverse=True)


def _run(capsys, command: str, path: Path, extra: list[str], lang: str) -> str:
    assert main([command, str(path), *extra, "--language", lang]) == 0
    text = capsys.readouterr().out
    for t in _titles(path):
        text = text.replace(t, "")
    return text


@pytest.mark.parametrize(("command", "path", "extra"),
                         [r for r in _RUNS if r[1].stem not in _ENGLISH_PARTS],
                         ids=lambda x: x.stem if isinstance(x, Path) else None)
def test_russian_output_has_no_latin_word(capsys, command, path, extra):
    text = _run(capsys, command, path, extra, "ru")
    assert text.strip()
    text = re.sub(r"(?<== )[a-z]{2}(?=[.,;]?\s)", " ", text)  # a polygon's segment found: "F21^n = no."
    assert not _latin_words(text), (command, path.name, sorted(_latin_words(text))[:20])
    assert not re.search(r"\d\.\d", text), "a decimal point in Russian"


@pytest.mark.parametrize(("command", "path", "extra"), _RUNS,
                         ids=lambda x: x.stem if isinstance(x, Path) else None)
def test_english_output_has_no_cyrillic_and_is_the_default(capsys, command, path, extra):
    text = _run(capsys, command, path, extra, "en")
    assert not re.search(r"[А-Яа-яЁё]", text), (command, path.name, re.findall(r"\S*[А-Яа-яЁё]\S*", text)[:10])
    with open(path, "rb") as fh:
        declared = (tomllib.load(fh).get("sheet") or {}).get("language")
    if declared != "ru" and command != "solve":  # no option, no Russian sheet: English, the same bytes
        assert main([command, str(path), *extra]) == 0
        same = capsys.readouterr().out
        for t in _titles(path):
            same = same.replace(t, "")
        assert same == text


def test_the_scene_language_is_the_default(capsys):
    """A scene whose sheet is Russian prints Russian without the option; the option overrides;
    a scene without one prints English."""
    path = SAMPLES / "projects" / "v_engine_project.toml"
    assert main(["solve", str(path)]) == 0
    assert "план скоростей" in capsys.readouterr().out
    assert main(["solve", str(path), "--language", "en"]) == 0
    assert "velocity plan" in capsys.readouterr().out
    assert main(["solve", str(SAMPLES / "slider_crank.toml")]) == 0
    assert "velocity plan" in capsys.readouterr().out


def test_same_numbers_in_both_languages(capsys, tmp_path):
    """Russian changes the words and the decimal sign, never a number (the scales written one
    way in both: a Russian protocol writes μ in units per mm by default)."""
    path = tmp_path / "four_bar.toml"
    path.write_text((SAMPLES / "four_bar.toml").read_text(encoding="utf-8") + '\n[scales]\nstyle = "mu"\n',
                    encoding="utf-8")
    en = _run(capsys, "solve", path, ["--protocol"], "en")
    ru = _run(capsys, "solve", path, ["--protocol"], "ru")
    nums = re.compile(r"(?<![\w^])-?\d+(?:[.,]\d+)?(?:e[-+]\d+)?")
    got = sorted(float(x.replace(",", ".")) for x in nums.findall(ru))
    want = sorted(float(x) for x in nums.findall(en))
    assert got == want


def test_the_scan_finds_english_words():
    """The scan refuses the words a half-translated line would leave."""
    assert _latin_words("v_BA = 1,2 mm/(m/s) at the pole") == {"mm", "at", "the", "pole"}
    assert _latin_words("h_Phi2 на рычаге, F_bal") == {"Phi", "bal"}
    assert not _latin_words("v_BA ⟂ AB, πa = 12,5 мм, n_BA, F21^τ, cos(2α), RRR")


def test_demonstration_heading_in_the_page_language():
    """A Russian page is headed by the scene's Russian title, an English page by the English one."""
    from plans.demo.lesson import lesson
    from plans.kinematics.placing import load_scene

    scene = load_scene(SAMPLES / "whitworth.toml")
    with open(SAMPLES / "whitworth.toml", "rb") as fh:
        titles = tomllib.load(fh)["title"]
    assert lesson(scene, frames=2, language="ru")["title"] == titles["ru"]
    assert lesson(scene, frames=2, language="en")["title"] == titles["en"]
