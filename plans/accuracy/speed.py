"""The performance goals of ``plans bench``, each measured in the run that reports it.

The speed goals (bench.json "performance"), each measured as a ratio in one run: exact
kinematics against the numpy floor and the peers, one position, a long chain, forces,
start-up, the demonstration page.  The V-engine's goals with fixed limits (bench.json
"goals", :data:`GOALS`), with a profile of each one not met.

Times are medians of several repetitions in this process (the machine is shared: what is
compared is measured side by side, so the ratios hold when absolute times drift).  Peers
(pylinkage, ``mechanism``) run when installed (``pip install -e '.[peers]'``); a goal that
needs a missing peer says "skipped" and why.
"""

from __future__ import annotations

import functools
import math
import sys
import time
from collections.abc import Callable
from dataclasses import asdict
from pathlib import Path
from typing import Any

import numpy as np

from plans.accuracy import floor, peers
from plans.accuracy.timing import (
    Goal,
    commands_seconds,
    interpreter_env,
    least_paired,
    least_time,
    median_time,
    took,
    us,
)
from plans.kinematics import exact
from plans.kinematics.placing import load_scene
from plans.kinematics.structure import analyse
from plans.phrases import Phrase, number, phrase, say
from plans.scene.model import Scene

#: Exact kinematics at 360 positions: at most this many times the numpy floor ...
FLOOR_RATIO = 1.5
#: ... and at least this many times faster than pylinkage + numba, agreeing to POSITIONS_AGREE.
PEER_SPEEDUP = 2.0
POSITIONS_AGREE = 1e-12
#: One position (seconds), by mechanism.
ONE_POSITION = {"slider-crank (offset)": 20e-6, "four-bar": 20e-6, "v_engine": 40e-6}
#: Turns of the 360 positions' short batches with the numpy floor and with pylinkage + numba.
KINEMATICS_TURNS = 41
#: Turns of the one position's batches with pylinkage's step (the least of each is compared).
ONE_POSITION_TURNS = 61
CHAIN_DYADS = 200
CHAIN_ONE_POSITION = 40e-3
FORCES_360 = 2e-3
#: Turns of the forces' single runs with the kinematics alone (the least of each is compared).
FORCES_TURNS = 41
START_UP = 0.15
#: ``plans --help``, which imports no numpy: well under the interpreter importing numpy alone.
HELP_UP = 0.08
#: The start-up bounds hold where the interpreter imports numpy alone in this long (where
#: they were set); where it takes longer (a slower machine, or one loaded by other work:
#: the load stretches every start alike) each bound is stretched by as much.
START_FLOOR = 0.125
#: ``plans solve`` of the slider-crank whole (seconds of our own work over the interpreter importing numpy).
SOLVE_BUDGET = 0.09
#: Fresh interpreters per command for the start-up goals (quick, full): the least of them.
START_REPS = (7, 15)

def mechanisms(samples: Path) -> list[tuple[str, Scene]]:
    """The slider-crank and the four-bar of the reference, and the V-engine sample."""
    from plans.accuracy import reference

    out = [("slider-crank (offset)", reference.slider_crank_scene(r=0.05, l=0.2, e=0.015, omega=2 * math.pi * 25)),
           ("four-bar", reference.four_bar_scene(a=0.05, b=0.2, c=0.15, d=0.18, omega=2 * math.pi * 25))]
    v = samples / "v_engine.toml"
    if v.exists():
        out.append(("v_engine", load_scene(v)))
    return out


def kinematics_goals(cases: list[tuple[str, Scene]], peer_runs: list[peers.PeerRun]) -> list[Goal]:
    out: list[Goal] = []
    phis = np.linspace(0.0, 360.0, 360, endpoint=False) + 7.5
    by = {(r.peer, r.mechanism): r for r in peer_runs}
    skipped = [r.note for r in peer_runs if r.peer == "pylinkage" and r.mechanism == "-"]
    for name, sc in cases:
        fl = floor.floor_for(sc)

        def ours(sc: Scene = sc) -> Any:
            return exact.solve(sc, phis, order=2)
        t_ours = least_time(ours, KINEMATICS_TURNS)
        if fl is not None:  # the least of short batches turn about: the load only ever adds
            t_ours, t_floor = least_paired(ours, functools.partial(fl, phis), KINEMATICS_TURNS)
            r = t_ours / t_floor
            out.append(Goal(phrase("bq_floor", name=name, ratio=FLOOR_RATIO),
                            phrase("bq_floor_got", ours=took(t_ours / 360), floor=took(t_floor / 360), r=r),
                            r / FLOOR_RATIO, r <= FLOOR_RATIO))
        pr = by.get(("pylinkage + numba", name))
        if pr is not None and math.isfinite(pr.time_per_position):
            if pr.runner is not None:
                t_peer, t_ours = least_paired(pr.runner, ours, KINEMATICS_TURNS)
                pr.time_per_position = t_peer / 360
            speed = pr.time_per_position / (t_ours / 360)
            out.append(Goal(phrase("bq_peer", name=name, speedup=PEER_SPEEDUP),
                            phrase("bq_peer_got", peer=took(pr.time_per_position), ours=took(t_ours / 360), speed=speed),
                            PEER_SPEEDUP / speed, speed >= PEER_SPEEDUP))
            e = pr.errors.get("r", math.nan)
            out.append(Goal(phrase("bq_agree", name=name, tol=POSITIONS_AGREE),
                            phrase("bq_agree_got", e=e, v=pr.errors.get("v", math.nan), a=pr.errors.get("a", math.nan)),
                            e / POSITIONS_AGREE, e <= POSITIONS_AGREE))
        else:
            why = pr.note if pr is not None else (skipped[0] if skipped else phrase("bq_no_run"))
            out.append(Goal(phrase("bq_peer", name=name, speedup=PEER_SPEEDUP), why, math.nan, None))
        bound = ONE_POSITION.get(name)
        one = functools.partial(exact.solve, sc, [45.0], order=2)
        step = by.get(("pylinkage step", name))
        extra: Phrase | str = ""
        ahead = True
        if step is not None and step.runner is not None:  # ours and pylinkage's step turn about
            step.time_per_position, t1 = least_paired(step.runner, one, ONE_POSITION_TURNS)
        else:
            t1 = least_time(one, ONE_POSITION_TURNS)
        if step is not None and math.isfinite(step.time_per_position):
            extra = phrase("bq_one_step", t=took(step.time_per_position), turns=ONE_POSITION_TURNS)
            ahead = t1 <= step.time_per_position
        if bound is not None:
            out.append(Goal(phrase("bq_one", name=name, bound=took(bound)), phrase("bq_one_got", t=took(t1), extra=extra),
                            t1 / bound, t1 <= bound and ahead))
    return out


def structure_goal() -> list[Goal]:
    """A chain of 200 dyads at one position, structure analysis included (a fresh scene each
    time), and the cost per dyad at 100 and 200 (linear: the same)."""
    from plans.accuracy.oracles import chain_scene

    def once(n: int) -> float:
        scenes = [chain_scene(n) for _ in range(5)]
        ts = []
        for sc in scenes:
            t0 = time.perf_counter()
            analyse(sc)
            exact.solve(sc, [45.0], order=2)
            ts.append(time.perf_counter() - t0)
        return sorted(ts)[len(ts) // 2]

    t100, t200 = once(CHAIN_DYADS // 2), once(CHAIN_DYADS)
    growth = t200 / t100
    return [Goal(phrase("bq_chain", n=CHAIN_DYADS, bound=took(CHAIN_ONE_POSITION)),
                 phrase("bq_chain_got", t=took(t200), per=took(t200 / CHAIN_DYADS), growth=growth, half=CHAIN_DYADS // 2,
                        n=CHAIN_DYADS), t200 / CHAIN_ONE_POSITION, t200 <= CHAIN_ONE_POSITION)]


def forces_goal(cases: list[tuple[str, Scene]]) -> list[Goal]:
    from plans.forces import analysis as polygons
    from plans.forces.loads import parse_loads

    out = []
    phis = np.linspace(0.0, 360.0, 360, endpoint=False) + 7.5
    for name, sc in cases:
        if not (sc.wants("force_polygons") or sc.wants("lever")):
            continue
        # a fresh analysis each time (points read once are kept by it): forces = both − solve,
        # each the least of many single runs taken turn about (a millisecond's run is seldom
        # cut by the scheduler, a batch of them nearly always is on a loaded machine)
        def both_fn(sc: Scene = sc) -> Any:
            return polygons.kinetostatics(sc, exact.solve(sc, phis, order=2))
        both, alone = least_paired(both_fn, functools.partial(exact.solve, sc, phis, order=2), FORCES_TURNS)
        t = max(both - alone, 0.0)
        tl = median_time(functools.partial(parse_loads, sc))
        out.append(Goal(phrase("bq_forces", name=name, bound=took(FORCES_360)),
                        phrase("bq_forces_got", t=took(t), tl=took(tl), turns=FORCES_TURNS), t / FORCES_360,
                        t <= FORCES_360))
    return out


#: The ``plans`` console command as the installed script runs it (``{entry}``: its module).
_CONSOLE = "import sys\nfrom {entry} import main\nsys.argv[0] = 'plans'\nsys.exit(main())\n"
#: The same command stopped the moment it begins to solve the scene: the scene is read and
#: handed to :func:`plans.results.solve_scene`, which leaves the interpreter at once
#: (``os._exit``: no output, no clean-up), so what is timed is the start alone.
_UNTIL_SOLVING = ("import os\nimport plans.results\n"
                  "plans.results.solve_scene = lambda scene: os._exit(0)\n" + _CONSOLE)


def start_up_goals(samples: Path, reps: int = START_REPS[1]) -> list[Goal]:
    """``plans --help``; ``plans solve`` of a small scene until it begins solving (the
    interpreter, the imports the command needs and the scene read); the same solve whole,
    to its table on stdout.  Each runs in a fresh interpreter as the installed console
    command runs it (bytecode compiled), the least of ``reps`` (a start's own cost: a
    loaded machine only ever adds to it), taking turns with the floor measured in the
    same run: the interpreter importing numpy and nothing else.  Each is judged on its
    processor time where that is less than its wall time (what it waited for the processor
    is not its cost), and where the floor takes longer than :data:`START_FLOOR`, the bounds
    are stretched by as much."""
    import importlib.util

    root = Path(__file__).resolve().parents[2]
    env = interpreter_env()
    entry = "drawings.console" if importlib.util.find_spec("drawings") is not None else "plans.cli"
    scene = str(samples / "slider_crank.toml")
    t = commands_seconds({
        "floor": ["-c", "import numpy"],
        # the floor of the start, stopped as the start is (no clean-up at exit, which costs numpy
        # 8–17 ms here): like is compared with like
        "floor_start": ["-c", "import os\nimport numpy\nos._exit(0)\n"],
        "help": ["-c", _CONSOLE.format(entry=entry), "--help"],
        "start": ["-c", _UNTIL_SOLVING.format(entry=entry), "solve", scene],
        "solve": ["-c", _CONSOLE.format(entry=entry), "solve", scene],
    }, root, env, reps, least=True)
    def judged(key: str) -> float:  # the processor time where it is less than the wall time
        wall, cpu, _ = t[key]
        return min(wall, cpu) if math.isfinite(cpu) else wall

    floor_s, floor_cpu, _ = t["floor"]
    stretch = max(1.0, judged("floor") / START_FLOOR)
    scaled = (phrase("bq_scaled", stretch=stretch, floor=START_FLOOR) if stretch > 1 else phrase("bq_unscaled"))
    out = []
    for key, what in (("help", phrase("bq_help", bound=HELP_UP, floor=START_FLOOR)),
                      ("start", phrase("bq_start", bound=START_UP, floor=START_FLOOR)),
                      ("solve", phrase("bq_solve", budget=SOLVE_BUDGET))):
        wall, cpu, status = t[key]
        if status != 0:
            out.append(Goal(what, phrase("bq_exit", status=status), math.nan, None))
        elif key == "solve":
            ours, bound = judged("solve") - judged("floor"), SOLVE_BUDGET * stretch
            out.append(Goal(what, phrase("bq_solve_got", took=wall, floor=floor_s, own=wall - floor_s,
                                         own_cpu=cpu - floor_cpu, reps=reps, scaled=scaled), ours / bound, ours <= bound))
        elif key == "start":
            base, base_cpu, _ = t["floor_start"]
            bound = START_UP * stretch
            out.append(Goal(what, phrase("bq_start_got", took=wall, cpu=cpu, reps=reps, base=base, base_cpu=base_cpu,
                                         over=wall - base, scaled=scaled), judged(key) / bound, judged(key) <= bound))
        else:
            bound = HELP_UP * stretch
            out.append(Goal(what, phrase("bq_help_got", took=wall, cpu=cpu, reps=reps, floor=floor_s,
                                         floor_cpu=floor_cpu, scaled=scaled), judged(key) / bound,
                            judged(key) <= bound))
    return out


#: Each A1 sheet of the V-engine (seconds, per sheet) and the cycle's diagrams sheet.
SHEET_SVG, SHEET_PDF, SHEET_PNG, DIAGRAMS_SVG = 0.1, 0.4, 0.6, 0.2
#: The same sheets as DXF: seconds per sheet, and at most this many times the SVG's time.
SHEET_DXF, SHEET_DXF_PER_SVG = 0.1, 5.0


#: The renderer's timer of a scene's sheets, registered by the drawing package when it builds
#: ``plans bench`` (``plans`` never imports ``drawings``): (scene paths, repeats) -> figures
#: (:func:`drawings.bench.figures`: the sheets drawn through ``drawings.draw``).
SHEET_FIGURES: list[Callable[[list[str], int], dict[str, Any]]] = []


def sheet_goals(samples: Path, reps: int = 3) -> list[Goal]:
    """The V-engine's sheets written as SVG, PDF and PNG at 150 dpi, per sheet, and the
    cycle's diagrams sheet as SVG, timed by the renderer's public API in this process
    (:data:`SHEET_FIGURES`); skipped where the renderer is not installed.  Each goal judges
    the sheet's processor time where it is less than its wall time (one core draws a sheet:
    on a loaded machine the wall time counts the others' work too); both are reported."""
    scenes = [str(samples / "v_engine.toml"), str(samples / "v_engine_cycle.toml")]
    scenes = [s for s in scenes if Path(s).is_file()]
    if not scenes or not scenes[0].endswith("v_engine.toml"):
        return [Goal(phrase("bq_sheets"), phrase("bq_missing", path="samples/v_engine.toml"), math.nan, None)]
    if not SHEET_FIGURES:
        return [Goal(phrase("bq_sheets"), phrase("bq_no_renderer"), math.nan, None)]
    fig = SHEET_FIGURES[0](scenes, reps)
    sh = fig["sheets"]
    n = sh["sheets"]
    load = "/".join(f"{x:.1f}" for x in fig["load"])
    out = []
    def judged(key: str) -> tuple[float, float, float]:
        """Per sheet: the wall time, the processor time, and what the goal judges: one core
        draws a sheet, so on an idle machine the two agree, and on a loaded one the wall
        time is stretched by the others' work, the processor time hardly."""
        wall = sum(sh[key]) / n
        cpu = sum(sh.get(key.replace("_s", "_cpu_s"), [math.nan])) / n
        return wall, cpu, min(wall, cpu) if math.isfinite(cpu) else wall

    for key, name, bound in (("svg_s", "SVG", SHEET_SVG), ("pdf_s", "PDF", SHEET_PDF),
                             ("png_s", phrase("bq_png"), SHEET_PNG)):
        ts = sh[key]
        wall, cpu, per = judged(key)
        extra = phrase("bq_sheet_built", t=sh["build_s"] / n) if key == "svg_s" else ""
        out.append(Goal(phrase("bq_sheet", n=n, size=sh["format"], name=name, bound=bound),
                        phrase("bq_sheet_got", wall=wall, cpu=cpu, slowest=max(ts), reps=reps, extra=extra, load=load),
                        per / bound, per <= bound))
    if sh.get("dxf_s"):  # the DXF of the same sheets: a bound of its own and the SVG's time × 5
        wall, cpu, per = judged("dxf_s")
        svg_per = judged("svg_s")[2]
        bound = min(SHEET_DXF, SHEET_DXF_PER_SVG * svg_per) if svg_per > 0 else SHEET_DXF
        out.append(Goal(phrase("bq_dxf", n=n, size=sh["format"], bound=SHEET_DXF, per_svg=SHEET_DXF_PER_SVG),
                        phrase("bq_dxf_got", wall=wall, cpu=cpu, slowest=max(sh["dxf_s"]),
                               svg=per / svg_per if svg_per > 0 else math.nan, reps=reps, load=load),
                        per / bound, per <= bound))
    d = fig.get("diagrams")
    if d is not None:
        wall, cpu = d["svg_s"], d.get("svg_cpu_s", math.nan)
        t = min(wall, cpu) if math.isfinite(cpu) else wall
        out.append(Goal(phrase("bq_diagrams", bound=DIAGRAMS_SVG),
                        phrase("bq_diagrams_got", wall=wall, cpu=cpu, reps=reps, load=load), t / DIAGRAMS_SVG,
                        t <= DIAGRAMS_SVG))
    return out


#: The explanatory note of the V-engine project (12 positions, 32 figures), seconds.
NOTE_BUILD = 3.0

#: The renderer's timers of the note and of the demonstration page, registered with
#: :data:`SHEET_FIGURES` when the drawing package builds ``plans bench``: (scene path, repeats)
#: -> the note's figures (:func:`drawings.note.cli.note_figures`: the note built through
#: :func:`drawings.note.cli.note_bytes`, as ``plans note`` builds it); (scene path) -> the
#: page's figures (:func:`drawings.demo.page_figures`: the page built by
#: :func:`drawings.demo.page`, as ``plans demo`` builds it, and opened in headless Chromium).
NOTE_FIGURES: list[Callable[[str, int], dict[str, float]]] = []
PAGE_FIGURES: list[Callable[[str], dict[str, Any]]] = []


def note_goals(samples: Path, reps: int = 3) -> list[Goal]:
    """The explanatory note of the V-engine project built as a DOCX with its figures, timed
    in this process by the renderer's public API (:data:`NOTE_FIGURES`)."""
    scene = samples / "projects" / "v_engine_project.toml"
    if not scene.is_file():
        return [Goal(phrase("bq_note_short"), phrase("bq_missing", path="samples/projects/v_engine_project.toml"),
                     math.nan, None)]
    if not NOTE_FIGURES:
        return [Goal(phrase("bq_note_short"), phrase("bq_no_renderer"), math.nan, None)]
    try:
        fig = NOTE_FIGURES[0](str(scene), reps)
    except Exception as exc:  # noqa: BLE001 - report, never break the benchmark
        return [Goal(phrase("bq_note_short"), phrase("bq_failed", error=f"{type(exc).__name__}: {exc}"), math.nan, None)]
    # one core builds the note: on an idle machine its wall and processor times agree, and on a
    # loaded one the wall time is stretched by the others' work, the processor time hardly
    wall, cpu = fig["seconds"], fig["cpu_seconds"]
    t = min(wall, cpu) if math.isfinite(cpu) else wall
    return [Goal(phrase("bq_note", bound=NOTE_BUILD),
                 phrase("bq_note_got", t=t, wall=wall, reps=reps, mb=fig["bytes"] / 1e6), t / NOTE_BUILD, t <= NOTE_BUILD)]


#: The demonstration page of the V-engine, 72 positions a turn.
PAGE_BYTES, PAGE_BUILD, PAGE_FIRST_STEP = 1.5e6, 2.0, 1.0


def page_goals(samples: Path) -> list[Goal]:
    """The demonstration page's size, build time and first step in headless Chromium, timed
    in this process by the renderer's public API (:data:`PAGE_FIGURES`; the engine never
    imports it)."""
    if not PAGE_FIGURES:
        return [Goal(phrase("bq_page_short"), phrase("bq_no_renderer"), math.nan, None)]
    try:
        fig = PAGE_FIGURES[0](str(samples / "v_engine.toml"))
    except Exception as exc:  # noqa: BLE001 - report, never break the benchmark
        return [Goal(phrase("bq_page_short"), phrase("bq_failed", error=f"{type(exc).__name__}: {exc}"), math.nan, None)]
    out = [Goal(phrase("bq_page_size", bound=PAGE_BYTES / 1e6), phrase("bq_mb", mb=fig["bytes"] / 1e6),
                fig["bytes"] / PAGE_BYTES, fig["bytes"] <= PAGE_BYTES),
           Goal(phrase("bq_page_build", bound=PAGE_BUILD), phrase("bq_seconds3", t=fig["build_s"]),
                fig["build_s"] / PAGE_BUILD, fig["build_s"] <= PAGE_BUILD)]
    first = fig.get("first_step_s")
    if first is None:
        out.append(Goal(phrase("bq_page_first", bound=PAGE_FIRST_STEP), phrase("bq_no_browser"), math.nan, None))
    else:
        out.append(Goal(phrase("bq_page_first", bound=PAGE_FIRST_STEP), phrase("bq_seconds3", t=first),
                        first / PAGE_FIRST_STEP, first <= PAGE_FIRST_STEP))
    return out


def measure(samples: Path, log: Callable[[Phrase | str], None] | None = None, with_peers: bool = True,
            quick: bool = False) -> dict[str, Any]:
    """Every goal, and the peers' runs behind them (JSON-ready)."""
    log = log or (lambda s: None)
    cases = mechanisms(samples)
    runs = peers.run_peers(cases, log=log) if with_peers else []
    log(phrase("bp_g_kinematics"))
    goals = kinematics_goals(cases, runs)
    log(phrase("bp_g_structure"))
    goals += structure_goal()
    goals += forces_goal(cases)
    goals += start_up_goals(samples, START_REPS[0] if quick else START_REPS[1])
    log(phrase("bp_g_sheets"))
    goals += sheet_goals(samples, 3 if quick else 5)
    log(phrase("bp_g_page"))
    goals += page_goals(samples)
    log(phrase("bp_g_examiner"))
    from plans.accuracy.examiner_bench import examiner_goals

    goals += examiner_goals(samples, quick)
    log(phrase("bp_g_note"))
    goals += note_goals(samples, 1 if quick else 3)
    log(phrase("bp_g_group"))
    from plans.accuracy.group_bench import group_goals

    log(phrase("bp_g_workbench"))
    from plans.accuracy.workbench_bench import workbench_goals

    if quick:  # a minute of a whole group and a browser: the full bench measures them
        goals += [Goal(phrase("bq_group_short"), phrase("bq_full_bench"), math.nan, None),
                  Goal(phrase("bq_workbench_short"), phrase("bq_full_bench"), math.nan, None)]
    else:
        goals += group_goals(samples) + workbench_goals(samples)
    return {"goals": [asdict(g) for g in goals],
            "peers": [{k: v for k, v in asdict(r).items() if k != "runner"} for r in runs]}


def lines(result: dict[str, Any], lang: str = "en") -> list[str]:
    return [Goal(**g).line(lang) for g in result.get("goals", [])]


def markdown(result: dict[str, Any], lang: str = "en") -> str:
    """The goals and the peers' runs as Markdown tables (in ``lang``: the goals' phrases and
    the bench's words; a result read back from bench.json has the English alone)."""
    from plans.messages_bench import words

    def head(key: str, align: tuple[str, ...]) -> list[str]:
        return ["| " + say(key, lang) + " |", "|" + "|".join(align) + "|"]

    out = head("bh_speed", ("---", "---", "---:", "---"))
    for g in result.get("goals", []):
        state = say("bs_yes" if g["met"] else "bs_skipped" if g["met"] is None else "bs_no", lang)
        r = "" if g["ratio"] is None or math.isnan(g["ratio"]) else number(g["ratio"], ".2f", lang)
        out.append(f"| {words(g['goal'], lang)} | {words(g['measured'], lang)} | {r} | {state} |")
    runs = result.get("peers", [])
    if runs:
        out += ["", *head("bh_peers", ("---", "---", "---:", "---:", "---:", "---:", "---:", "---"))]
        for r in runs:
            e = r.get("errors") or {}
            tp = r["time_per_position"]
            out.append(f"| {r['peer']} | {words(r['mechanism'], lang)} | {r['positions']} | "
                       f"{'' if tp is None or math.isnan(tp) else took(tp).say(lang)} | "
                       + " | ".join(number(e[k], ".2g", lang) if k in e else "" for k in ("r", "v", "a"))
                       + f" | {words(r['note'], lang)} |")
    return "\n".join(out)


# --------------------------------------------------------------------------- docs/accuracy.md

_BEGIN, _END = "<!-- from plans bench: begin -->", "<!-- from plans bench: end -->"


def results_table(result: dict[str, Any]) -> str:
    """The accuracy table of docs/accuracy.md from a run's records (1 and 360 positions)."""
    recs = result["records"]

    def get(method: str, scene: str, n: int, param: str = "") -> dict | None:
        return next((r for r in recs if r["method"] == method and r["scene"] == scene and r["positions"] == n
                     and (not param or r.get("param") == param)), None)

    def fmt(x: float | None, unit: bool = False) -> str:
        if x is None or not math.isfinite(x):
            return "–"
        return us(x) if unit else f"{x:.2g}"

    rows = ["| method | mechanism | positions | error | time per position |", "|---|---|---:|---:|---:|"]
    for scene, label in (("slider-crank (offset)", "slider-crank"), ("four-bar", "four-bar")):
        for method, name, param in (("exact", "exact (closed form)", ""), ("construction", "construction", ""),
                                    ("newton", "Newton–Raphson, tol 1e-12", "")):
            a, b = get(method, scene, 1, param), get(method, scene, 360, param)
            if a and b:
                rows.append(f"| {name} | {label} | 1 / 360 | {fmt(a['error'])} / {fmt(b['error'])} | "
                            f"{fmt(a['time_per_position'], True)} / {fmt(b['time_per_position'], True)} |")
        fd = get("finite differences", scene, 360, "h=1e-02 deg")
        if fd:
            rows.append(f"| finite differences, h = 0.01° | {label} | 360 | {fmt(fd['error'])} | "
                        f"{fmt(fd['time_per_position'], True)} |")
    for sheet in ("A1", "A4"):
        d = get(f"draftsman {sheet}", "slider-crank (offset)", 1)
        if d:
            rows.append(f"| hand drawing, {sheet} (95 % of drawings) | slider-crank | – | {fmt(d['error'])} | – |")
    return "\n".join(rows)


def update_doc(result: dict[str, Any], path: Path) -> None:
    """Rewrite the part of ``path`` between the bench markers from ``result``."""
    from plans.io import atomic_write

    text = path.read_text(encoding="utf-8")
    m = result.get("meta", {})
    body = "\n".join([
        _BEGIN, "",
        f"`plans bench{' --quick' if m.get('quick') else ''}`, Python {m.get('python')}, numpy {m.get('numpy')}, "
        f"{m.get('machine')}, OPENBLAS_NUM_THREADS={m.get('OPENBLAS_NUM_THREADS') or 'unset'} "
        "(a shared machine: times drift, the ratios are measured side by side).", "",
        results_table(result), "",
        "### Performance goals", "",
        "Each goal measured in the same run as what it is compared to; ratio: measured over the "
        "goal's bound (met when at most 1).", "",
        markdown(result.get("performance", {})), "", _END])
    if _BEGIN in text and _END in text:
        head, rest = text.split(_BEGIN, 1)
        text = head + body + rest.split(_END, 1)[1]
    else:
        text = text.rstrip("\n") + "\n\n" + body + "\n"
    atomic_write(path, text)


if __name__ == "__main__":  # pragma: no cover - python -m plans.accuracy.speed bench.json docs/accuracy.md
    import json

    update_doc(json.loads(Path(sys.argv[1]).read_text(encoding="utf-8")), Path(sys.argv[2]))
