"""``plans bench`` in one language: its terminal lines and its report (bench.md) in Russian
hold no English word outside the programs, files and symbols they name; bench.json keeps the
English; ``--fuzz``'s lines and report follow the run's language; a run inside the bench
(``plans check`` timed) leaves the bench its language."""

from __future__ import annotations

import argparse
import io
import json
import re
import string
from dataclasses import asdict
from pathlib import Path

import pytest

from tests.test_language import CYRILLIC, _latin_words

pytestmark = pytest.mark.usefixtures("english_locale")

SAMPLES = Path(__file__).resolve().parents[1] / "samples"

#: What a Russian report names in Latin letters: programs and their versions, commands and
#: options, files and folders, the machine's architecture, the profile's function names.
_NAMED = re.compile(r"`[^`]*`|\bpylinkage( \+ numba| step)?\b|\bstep_fast_with_kinematics\b|\bmechanism\b|"
                    r"\bChromium\b|\bPlaywright\b|\b[Pp]ython\b|\bnumpy\b|\bnumba\b|\bshapely\b|\bmpmath\b|\bfsolve\b|"
                    r"\bplans( (bench|solve|serve|check|draw))?\b|--\w[\w-]*|\bOPENBLAS_NUM_THREADS\b|\bx86_64\b|\baarch64\b|"
                    r"\S*/\S*|\S+\.(toml|md|svg|json)\b|\b(v_engine|shaper|six_bar|scotch_yoke|whitworth|"
                    r"v_twin_four_stroke|dynamics_slider_crank)\b|\bx_ref\b|\bdpi\b|\bdrawings\b")


def _russian_words(text: str) -> set[str]:
    return _latin_words(_NAMED.sub(" ", text))


@pytest.fixture(scope="module")
def russian_run(tmp_path_factory):
    """The bench at its smallest in Russian, its speed goals (minutes of fresh interpreters and
    sheets) those measured in process in a few seconds: the chain and the forces."""
    from drawings.bench_plot import add_plot
    from plans.accuracy import bench, speed
    from plans.cli import main

    out = tmp_path_factory.mktemp("bench-ru")
    saved = speed.measure

    def measure(samples, log=None, with_peers=True, quick=False):
        cases = speed.mechanisms(samples)[-1:]
        goals = speed.structure_goal() + speed.forces_goal(cases) + speed.kinematics_goals(cases, [])
        log(speed.phrase("bp_g_kinematics"))
        return {"goals": [asdict(g) for g in goals], "peers": []}

    speed.measure = measure
    try:
        parser = argparse.ArgumentParser(prog="plans")
        sub = parser.add_subparsers(dest="command", required=True)
        bench.register(sub)
        add_plot(sub.choices["bench"])
        args = parser.parse_args(["bench", "--quick", "--out", str(out), "--sizes", "1,12", "--chain", "1,3",
                                  "--mc", "30", "--language", "ru"])
        import contextlib

        stdout, stderr = io.StringIO(), io.StringIO()
        from plans.errors import set_run

        outer = set_run("ru", None)
        try:
            with contextlib.redirect_stdout(stdout), contextlib.redirect_stderr(stderr):
                assert args.func(args) == 0
                # a command run inside (the bench times plans check so): the bench keeps its language
                assert main(["solve", str(SAMPLES / "slider_crank.toml"), "--quiet", "--language", "en"]) == 0
                from plans.errors import run_language

                assert run_language() == "ru"
        finally:
            set_run(*outer)
    finally:
        speed.measure = saved
    return out, stdout.getvalue(), stderr.getvalue()


def test_bench_terminal_and_report_in_russian(russian_run):
    out, stdout, _ = russian_run
    md = (out / "bench.md").read_text(encoding="utf-8")
    for text in (stdout, md):
        assert not _russian_words(text), sorted(_russian_words(text))
        body = re.sub(r"(Python|numpy|shapely) \d+(\.\d+)+", " ", text)  # versions
        assert not re.search(r"\d\.\d", body), re.findall(r".{20}\d\.\d.{10}", body)[:5]
    assert "## Сводка" in md and "## Устойчивость" in md and "## Ручной чертёж (метод Монте-Карло)" in md
    assert "цепь из 200 диад" in md and "кривошипно-ползунный (со смещением)" in md and "мкс" in md
    assert "цель: точная кинематика V-образного двигателя в 360 положениях (v и a)" in stdout
    assert "записано: " in stdout


def test_bench_json_of_a_russian_run_is_english(russian_run):
    out, _, _ = russian_run
    text = (out / "bench.json").read_text(encoding="utf-8")
    assert not CYRILLIC.search(text)
    data = json.loads(text)
    goals = data["performance"]["goals"]
    assert goals and all(isinstance(g["goal"], str) and isinstance(g["measured"], str) for g in goals)
    assert any(g["goal"].startswith("chain of 200 dyads") for g in goals)
    from plans.accuracy.markdown import markdown

    md = markdown(data)  # the English report again from the JSON alone
    assert "## Summary" in md and not CYRILLIC.search(md)


def _fields(template: str) -> set[str]:
    return {name for _, name, _, _ in string.Formatter().parse(template) if name}


def test_every_bench_phrase_in_both_languages():
    """Each phrase of the bench's catalogue: the same fields in both; no Russian letter in the
    English one; no English word in the Russian one outside what the bench names."""
    from plans.messages_bench import BENCH

    assert len(BENCH) >= 100
    for key, (en, ru) in BENCH.items():
        assert _fields(en) == _fields(ru) or key == "bq_either", key  # either: a text made in both
        assert not CYRILLIC.search(en), key
        literal = re.sub(r"\{[^{}]*\}", " ", ru)
        assert not _russian_words(literal) - {"DOCX", "SVG", "PDF", "PNG", "DXF", "HTTP", "JSON"}, (key, ru)
        assert CYRILLIC.search(ru) or not _latin_words(literal) or key.startswith(("br_title", "br_hand_scene")), key


def test_the_records_words_in_russian():
    from plans.messages_bench import words

    for en, ru in (("chain of 5 dyads", "цепь из 5 диад"), ("slider-crank (offset)", "кривошипно-ползунный (со смещением)"),
                   ("h=1e-02 deg", "h = 1e-02°"), ("newton tol sweep", "Ньютон, ряд допусков"),
                   ("Scotch yoke, slot 0.001° to its guide", "синусный механизм, кулиса под углом 0,001° к направляющей"),
                   ("draftsman A1", "чертёжник A1"), ("exact", "точно")):
        assert words(en, "ru") == ru and words(en, "en") == en


def test_fuzz_lines_in_russian(capsys):
    from plans.accuracy import fuzz
    from plans.errors import set_run

    samples = [s for s in fuzz.load_samples() if s.kind in ("gears", "cam")][:2]
    outer = set_run("ru", None)
    try:
        summary = fuzz.fuzz(4, seed=1, samples=samples, draw_every=0)
        text = fuzz.report(summary, 1, "ru")
    finally:
        set_run(*outer)
    assert text.startswith("--fuzz: случаев 4 (начальное число 1): ")
    assert not _russian_words(text), text
    assert fuzz.report(summary, 1).startswith("fuzz: 4 cases (seed 1): ")


def test_fuzz_progress_in_the_runs_language(monkeypatch):
    from plans.accuracy import fuzz
    from plans.errors import set_run

    samples = [s for s in fuzz.load_samples() if s.kind == "gears"][:1]
    lines: list[str] = []
    outer = set_run("ru", None)
    try:
        monkeypatch.setattr(fuzz, "run_case", lambda *a, **k: fuzz.Result(False, None, "ValueError: x"))
        fuzz.fuzz(1000, samples=samples, draw_every=0, progress=lines.append)
    finally:
        set_run(*outer)
    assert lines[0].startswith("случай 0: ") and lines[-1].startswith("случаев: 1000, принято: 0, отклонено: 0, ")
