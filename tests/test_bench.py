"""The benchmark command runs at small size, writes its report, and its parts make sense."""

from __future__ import annotations

import argparse
import json
import math
import re
from pathlib import Path

import numpy as np
import pytest

from drawings.bench_plot import add_plot, svg_plot
from plans.accuracy import bench, draftsman, oracles, reference
from plans.kinematics import exact as kinematics


@pytest.fixture(scope="module")
def small_run(tmp_path_factory):
    out = tmp_path_factory.mktemp("bench")
    parser = argparse.ArgumentParser(prog="plans")
    sub = parser.add_subparsers(dest="command", required=True)
    bench.register(sub)
    add_plot(sub.choices["bench"])  # the renderer hands the command its plot (bench.svg)
    args = parser.parse_args(["bench", "--quick", "--out", str(out), "--sizes", "1,12",
                              "--chain", "1,3", "--mc", "60"])
    assert args.func is bench.run
    assert args.func(args) == 0
    return out


def test_bench_writes_markdown_json_and_svg(small_run):
    for name in ("bench.md", "bench.json", "bench.svg"):
        assert (small_run / name).stat().st_size > 0
    md = (small_run / "bench.md").read_text(encoding="utf-8")
    assert "## Summary" in md and "## Stability" in md and "## Hand drawing" in md
    assert "## Performance goals" in md and "360 V-engine positions" in md
    svg = (small_run / "bench.svg").read_text(encoding="utf-8")
    assert svg.startswith("<svg") and svg.rstrip().endswith("</svg>")


def test_bench_json_records(small_run):
    data = json.loads((small_run / "bench.json").read_text(encoding="utf-8"))
    recs = data["records"]
    methods = {r["method"] for r in recs}
    assert {"exact", "construction", "newton", "newton tol sweep", "finite differences",
            "draftsman A1", "draftsman A4", "mechanism"} <= methods
    assert {"pylinkage", "pylinkage + numba"} & methods
    for r in recs:
        assert {"method", "error", "time"} <= set(r)
    newton_recs = [r for r in recs if r["method"].startswith("newton")]
    assert newton_recs and all(r["cond"] is not None and r["cond"] >= 1 for r in newton_recs)
    for peer in ("pylinkage", "mechanism"):
        rec = next(r for r in recs if r["method"].split()[0] == peer)
        assert rec["note"].startswith("skipped") or rec["error"] is not None
    # errors against the 50-digit reference: the exact analysis at the floating-point floor
    exact = [r for r in recs if r["method"] == "exact" and r["oracle"] == "mpmath 50 digits"]
    assert exact and max(r["error"] for r in exact) < 1e-13
    chains = {r["dyads"] for r in recs if r["scene"].startswith("chain")}
    assert chains == {1, 3}
    assert data["stability"] and all("case" in row for row in data["stability"])


def test_exact_is_fastest_per_position_in_the_same_run(small_run):
    """Ratios within one run, not absolute times: exact (vectorised) beats every other solver."""
    recs = json.loads((small_run / "bench.json").read_text(encoding="utf-8"))["records"]
    for scene in ("slider-crank (offset)", "four-bar"):
        exact = min(r["time_per_position"] for r in recs if r["scene"] == scene and r["method"] == "exact")
        for r in recs:
            if r["scene"] == scene and r["method"] in ("construction", "newton") and r["positions"] == 12:
                assert r["time_per_position"] > exact


def test_svg_is_deterministic():
    recs = [oracles.Record("exact", "x", 360, 1e-15, 1e-4, 3e-7), oracles.Record("newton", "x", 12, 1e-9, 1e-2, 1e-3)]
    assert svg_plot(recs, {"hand A1": 1e-2}) == svg_plot(list(recs), {"hand A1": 1e-2})


def test_draftsman_error_shrinks_from_a4_to_a1():
    sc = reference.slider_crank_scene(0.05, 0.2, 0.015, 157.0)
    a4 = draftsman.draftsman_errors(sc, 45.0, "A4", samples=800, seed=3)
    a1 = draftsman.draftsman_errors(sc, 45.0, "A1", samples=800, seed=3)
    assert set(a4) == set(a1) >= {"v_B", "omega_2", "a_B", "eps_2", "v_S2", "a_S2"}
    for q in a1:
        assert a1[q].p95_rel < a4[q].p95_rel, q
        assert 1e-4 < a1[q].p95_rel < 0.05, q  # a careful drawing is good to a few per cent
    # no bias larger than the spread
    for q in a1:
        assert abs(a1[q].mean) < 3 * a1[q].std + 1e-12


def test_expected_errors_for_the_checker():
    sc = reference.four_bar_scene(0.05, 0.2, 0.15, 0.18, 100.0)
    tol = draftsman.expected_errors(sc, 30.0, "A1", samples=300)
    rel, absolute = tol["v_B"]
    v_B = abs(kinematics.solve(sc, [30.0], order=1).point("B")[1][0])
    assert 0 < rel < 0.1 and 0 < absolute < v_B
    assert tol == draftsman.expected_errors(sc, 30.0, "A1", samples=300)  # seeded: reproducible


def test_draftsman_model_scales_with_pencil():
    sc = reference.slider_crank_scene(0.05, 0.2, 0.0, 100.0)
    fine = draftsman.draftsman_errors(sc, 60.0, "A1", draftsman.DraftsmanModel(0.05, 0.05), samples=500)
    coarse = draftsman.draftsman_errors(sc, 60.0, "A1", draftsman.DraftsmanModel(0.5, 0.5), samples=500)
    assert fine["v_B"].p95_abs < coarse["v_B"].p95_abs / 3


def test_finite_differences_converge_then_cancel():
    """Central differences: error falls as h² and then grows as ε/h (the step sweep's V)."""
    sc = reference.slider_crank_scene(0.05, 0.2, 0.015, 100.0)
    phis = np.linspace(0, 360, 36, endpoint=False) + 2.0
    oracle = oracles.oracle_from_reference(reference.slider_crank(0.05, 0.2, 0.015, 100.0, phis))
    errs = {}
    for h in (1.0, 1e-2, 1e-7):
        point, omega, eps = bench._finite_differences(sc, phis, h, oracle)
        errs[h] = oracles.solver_errors(sc, oracle, point, omega, eps)["v"]
    assert errs[1e-2] < errs[1.0] / 100
    assert errs[1e-7] > errs[1e-2]


def test_chain_scene_is_well_conditioned():
    sc = oracles.chain_scene(10)
    kin = kinematics.solve(sc, np.linspace(0, 360, 36), order=2)
    w = np.concatenate([kin.omega(k) for k in sc.links])
    assert np.all(np.isfinite(w)) and np.max(np.abs(w)) < 50 * abs(sc.driver.omega)


def test_peers_skip_cleanly():
    from dataclasses import asdict

    from plans.accuracy import peers

    runs = peers.run_peers([(c.name, c.scene) for c in oracles.reference_cases()], positions=36,
                           mechanism_positions=4)
    recs = bench.bench_peers({"peers": [{k: v for k, v in asdict(r).items() if k != "runner"} for r in runs]})
    assert {r.method.split()[0] for r in recs} == {"pylinkage", "mechanism"}
    for r in recs:  # a pure-Python step is timed only (its positions are those of the numba run)
        assert r.note.startswith("skipped") or r.method == "pylinkage step" or math.isfinite(r.error)


def test_plans_does_not_import_renderers():
    src = Path(bench.__file__).read_text(encoding="utf-8")
    for name in ("svgwrite", "cairosvg", "drawings"):
        assert f"import {name}" not in src and f"from {name}" not in src


SAMPLE_FILES = sorted((Path(__file__).resolve().parent.parent / "samples").glob("*.toml"))


@pytest.mark.parametrize("path", SAMPLE_FILES, ids=lambda p: p.stem)
def test_draftsman_without_error_draws_the_exact_plans(path):
    """With a perfect pencil and protractor the Monte Carlo's construction (every dyad kind,
    Coriolis terms laid off from ω and v_r read off the drawn velocity plan) reads the exact
    analysis at every position: a wrong sense of a^k or a wrong line would show here."""
    from plans.kinematics.placing import load_scene

    sc = load_scene(path)
    kin = kinematics.solve(sc, order=2)
    perfect = draftsman.DraftsmanModel(0.0, 0.0)
    for k, phi in enumerate(sc.driver.phis_deg):
        res = draftsman.draftsman_errors(sc, phi, "A1", perfect, samples=2, seed=0)
        for q, e in res.items():
            ref = abs(sc.driver.omega) * 0.01 if q[0] == "v" else sc.driver.omega**2 * 0.01
            if q.startswith(("omega_", "eps_")):
                lid = int(q.split("_")[1])
                want = float((kin.omega(lid) if q[0] == "o" else kin.eps(lid))[k])
                assert e.exact == pytest.approx(want, rel=1e-12, abs=1e-12 * abs(sc.driver.omega) ** 2)
                ref = abs(want) + 1e-6 * sc.driver.omega**2
            elif re.fullmatch(r"[va]_[A-Z][a-z]?\d?", q) and q[2:] in kin.point_names():
                r, v, a = kin.point(q[2:])
                assert e.exact == pytest.approx(abs(complex((v if q[0] == "v" else a)[k])), rel=1e-12, abs=1e-12)
            assert abs(e.mean) <= 1e-9 * max(abs(e.exact), ref), (path.stem, phi, q, e.exact, e.mean)
            assert e.max_abs <= 1e-9 * max(abs(e.exact), ref)


@pytest.mark.parametrize("name", ["shaper", "six_bar", "scotch_yoke"])
def test_draftsman_covers_coriolis_samples(name):
    from plans.kinematics.placing import load_scene

    sc = load_scene(Path(__file__).resolve().parent.parent / "samples" / f"{name}.toml")
    a1 = draftsman.draftsman_errors(sc, 45.0, "A1", samples=1500, seed=5)
    a4 = draftsman.draftsman_errors(sc, 45.0, "A4", samples=1500, seed=5)
    assert set(a1) == set(a4)
    assert any(q.startswith("a^r_") for q in a1) and any(re.fullmatch(r"v_[A-Z]\d[A-Z]\d", q) for q in a1)
    if name != "scotch_yoke":  # the yoke translates: no Coriolis term
        assert any(q.startswith("a^k_") for q in a1)
    for q in a1:
        assert 1e-4 < a1[q].p95_rel < 0.05, (q, a1[q].p95_rel)
        assert a1[q].p95_rel < a4[q].p95_rel, q
        assert abs(a1[q].mean) < 3 * a1[q].std + 1e-12, q
    tol = draftsman.expected_errors(sc, 45.0, "A1", samples=300)
    assert set(tol) == set(a1)


def test_coriolis_error_carries_the_velocity_plan_error():
    """a^k = 2 ω v_r is laid off from figures read off the drawn velocity plan: a pencil error
    alone (no protractor) still spreads it, and more than the pencil's width on the plan."""
    from plans.kinematics.placing import load_scene

    sc = load_scene(Path(__file__).resolve().parent.parent / "samples" / "shaper.toml")
    pencil = draftsman.draftsman_errors(sc, 45.0, "A1", draftsman.DraftsmanModel(0.25, 0.0), samples=1500, seed=2)
    protractor = draftsman.draftsman_errors(sc, 45.0, "A1", draftsman.DraftsmanModel(0.0, 0.25), samples=1500, seed=2)
    ak = "a^k_A3A2"
    assert pencil[ak].p95_mm > 0.25  # laid off ±0.25 plus ω and v_r read with error
    assert protractor[ak].p95_abs > 0  # the velocity plan's lines are drawn with the protractor
    # the sense of a^k decides where a3 lands: the direction error moves a_A3
    assert protractor["a_A3"].p95_mm > 0.05


def test_the_renderer_registers_its_sheet_timers_and_the_goals_read_them(monkeypatch):
    """``plans bench`` of the drawing package times the sheets in process through the
    renderer's registered functions (no subprocess, no module named by a string); the sheet
    goals are the per-sheet means of what the timer returns."""
    from drawings.cli import build_parser
    from plans.accuracy import cycle_bench, speed

    build_parser(["bench", "--quick"])
    assert speed.SHEET_FIGURES and all(callable(f) for f in speed.SHEET_FIGURES)
    assert callable(cycle_bench.SHEET_TIMERS["cycle diagrams sheet"])
    fake = {"sheets": {"sheets": 2, "format": "A1", "build_s": 0.2, "svg_s": [0.05, 0.07],
                       "pdf_s": [0.3, 0.5], "png_s": [0.5, 0.9]}, "load": [1.0, 2.0]}
    asked = []
    monkeypatch.setattr(speed, "SHEET_FIGURES", [lambda paths, reps: asked.append((paths, reps)) or fake])
    goals = speed.sheet_goals(Path(__file__).resolve().parents[1] / "samples", reps=2)
    assert [Path(p).name for p in asked[0][0]] == ["v_engine.toml", "v_engine_cycle.toml"] and asked[0][1] == 2
    svg, pdf, png = goals
    assert svg.met and abs(svg.ratio - 0.06 / speed.SHEET_SVG) < 1e-12
    assert not png.met and abs(png.ratio - 0.7 / speed.SHEET_PNG) < 1e-12
    monkeypatch.setattr(speed, "SHEET_FIGURES", [])
    assert speed.sheet_goals(Path(__file__).resolve().parents[1] / "samples")[0].met is None


def test_the_note_page_workbench_and_group_goals_time_the_renderers_public_functions(monkeypatch):
    """The note, the demonstration page, the workbench and a group's variants are timed in
    this process through what the renderer registers (its public functions and its command
    line), never a subprocess of a module named by a string; unregistered, each is skipped."""
    import subprocess

    from drawings.cli import build_parser, main
    from plans.accuracy import group_bench, speed, workbench_bench

    build_parser(["bench", "--quick"])
    assert group_bench.COMMAND == [main]
    assert speed.NOTE_FIGURES and speed.PAGE_FIGURES and workbench_bench.FIGURES
    samples = Path(__file__).resolve().parents[1] / "samples"
    asked: list = []
    monkeypatch.setattr("drawings.note.cli.note_figures",
                        lambda path, reps: asked.append(("note", path, reps)) or
                        {"seconds": 4.0, "cpu_seconds": 2.5, "bytes": 2e6})
    monkeypatch.setattr("drawings.demo.page_figures",
                        lambda path: asked.append(("page", path)) or
                        {"bytes": 1e5, "build_s": 0.1, "first_step_s": None})

    def no_subprocess(*args, **kwargs):
        raise AssertionError(f"a subprocess: {args}")
    monkeypatch.setattr(subprocess, "run", no_subprocess)
    note, = speed.note_goals(samples, reps=2)
    assert note.met and abs(note.ratio - 2.5 / speed.NOTE_BUILD) < 1e-12  # the processor time of one core's build
    size, build, first = speed.page_goals(samples)
    assert size.met and build.met and first.met is None
    assert asked == [("note", str(samples / "projects" / "v_engine_project.toml"), 2),
                     ("page", str(samples / "v_engine.toml"))]
    for name in ("NOTE_FIGURES", "PAGE_FIGURES"):
        monkeypatch.setattr(speed, name, [])
    monkeypatch.setattr(workbench_bench, "FIGURES", [])
    monkeypatch.setattr(group_bench, "COMMAND", [])
    assert [g.met for g in speed.note_goals(samples) + speed.page_goals(samples)
            + workbench_bench.workbench_goals(samples) + group_bench.group_goals(samples)] == [None] * 4


def test_least_paired_takes_turns_and_keeps_the_least_of_each():
    """The noisy goals' timer: the two calls take turns, and each keeps its least batch
    (a loaded machine only ever adds to a call's time); a fake clock makes it exact."""
    from plans.accuracy.timing import least_paired

    calls: list[str] = []
    durations = iter([5.0, 3.0, 2.0, 1.0, 4.0, 6.0])  # a, b, a, b, a, b
    now = [0.0]
    started = [True]

    def clock() -> float:
        if not started[0]:
            now[0] += next(durations)
        started[0] = not started[0]
        return now[0]

    ta, tb = least_paired(lambda: calls.append("a"), lambda: calls.append("b"), reps=3, batch=0.0, clock=clock)
    assert (ta, tb) == (2.0, 1.0)
    assert calls == ["a", "a", "b", "b"] + ["a", "b"] * 3  # two calls each to size the batches, then turn about
