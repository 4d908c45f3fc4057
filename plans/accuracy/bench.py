"""``plans bench``: error against run time of every method, and how a hand drawing compares.

Methods, each timed per position and over 1, 12, 360 and 3600 positions:

* ``exact``        closed-form positions and 2×2 linear systems (:mod:`plans.kinematics`), vectorised;
* ``construction`` the draftsman's construction in floating point (:mod:`plans.kinematics.construction`,
                   closed-form intersections), the positions built together;
* ``newton``       Newton–Raphson on the loop equations (:mod:`plans.accuracy.newton`), tolerance 1e-2 … 1e-14;
* ``fd``           central finite differences of exact positions (step sweep) for v and a;
* ``draftsman``    Monte Carlo of the construction drawn at sheet scale with pencil and protractor
                   error (:func:`draftsman_errors`, :func:`expected_errors`), A4 against A1;
* ``pylinkage`` / ``mechanism``: open peers, when importable (skipped cleanly otherwise).

Errors are against the mpmath reference (:mod:`plans.accuracy.reference`, 50 digits) for the
slider-crank and the four-bar, against the exact analysis elsewhere.  An error is
the largest over positions and quantities of |x − x_ref| / N, with N the size of
the known vector of the quantity's kind: l1 for positions, |ω1| l1 for velocities,
ω1² l1 for accelerations, |ω1| for ω, ω1² for ε (a vanishing quantity, such as v_B
at a dead centre, is judged against the plan's size, as a draftsman's reading is).

Writes ``bench.md``, ``bench.json`` (``records``: one per method, scene and size,
with ``method``, ``error``, ``time``, ``time_per_position``, ``cond``) and, when the renderer
is installed (``plans bench`` from :mod:`drawings.cli`), ``bench.svg`` (log-log error against
run time per position, :mod:`drawings.bench_plot`) to ``--out``.
"""

from __future__ import annotations

import argparse
import functools
import importlib.util
import json
import math
import os
import platform
import sys
import time
from collections.abc import Callable, Mapping, Sequence
from dataclasses import asdict
from pathlib import Path
from typing import TYPE_CHECKING, Any

import numpy as np

from plans.accuracy import fuzz, newton, speed, vengine_goals
from plans.accuracy.draftsman import DraftsmanModel, draftsman_errors
from plans.accuracy.markdown import goal_line, goal_said, markdown, summary_table
from plans.accuracy.oracles import (
    Case,
    Oracle,
    Record,
    chain_scene,
    construction_errors,
    force_errors,
    oracle_from_kinematics,
    reference_cases,
    sample_cases,
    solver_errors,
    timeit,
    total_error,
)
from plans.accuracy.stability import stability_records, stiff_load_records
from plans.errors import Said, run_language
from plans.io import write_all
from plans.kinematics import construction
from plans.kinematics import exact as kinematics
from plans.messages_bench import words
from plans.phrases import Phrase, phrase
from plans.scene.model import Scene

if TYPE_CHECKING:  # mpmath is an optional dependency (the ``bench`` extra): imported where used
    pass

SIZES = (1, 12, 360, 3600)
QUICK_SIZES = (1, 12, 360)
TOLERANCES = (1e-2, 1e-4, 1e-6, 1e-8, 1e-10, 1e-12, 1e-14)
FD_STEPS_DEG = (1.0, 1e-1, 1e-2, 1e-3, 1e-4, 1e-5, 1e-6, 1e-7)
CHAIN_SIZES = (1, 2, 5, 10, 20, 50)
QUICK_CHAIN_SIZES = (1, 5, 20)  # the full run goes to 50; dense Newton solves dominate there
#: Samples whose hand-drawing Monte Carlo the report always shows (Coriolis, moving guides).
CORIOLIS_SAMPLES = ("shaper", "six_bar", "scotch_yoke")

# --------------------------------------------------------------------------- methods


def _phis(n: int) -> np.ndarray:
    """n positions spread over the cycle, avoiding exact dead centres only by accident."""
    if n == 1:
        return np.array([45.0])
    return np.linspace(0.0, 360.0, n, endpoint=False) + 7.5


def bench_case(case: Case, sizes: Sequence[int], budget: float, quick: bool,
               log: Callable[[str], None]) -> list[Record]:
    recs: list[Record] = []
    sc = case.scene
    for n in sizes:
        phis = _phis(n)
        oracle_kin = kinematics.solve(sc, phis, order=2)
        oracle = case.reference(phis) if case.reference else oracle_from_kinematics(oracle_kin)
        # exact analysis
        t = timeit(functools.partial(kinematics.solve, sc, phis, order=2), budget)
        errs = solver_errors(sc, oracle, oracle_kin.point, oracle_kin.omega, oracle_kin.eps)
        recs.append(Record("exact", case.name, n, total_error(errs), t, t / n, dyads=case.dyads,
                           oracle=oracle.name, errors=errs,
                           note="" if case.reference else "is the oracle"))
        # construction (plans of both kinds, the positions built together)
        if n <= (360 if quick else 3600):
            kin = oracle_kin
            mv, ma = construction.default_scales(kin)

            def build_all(kin=kin, n=n, mv=mv, ma=ma) -> list:
                return construction.build_many(kin, range(n), velocity_scale=mv, acceleration_scale=ma)
            t = timeit(build_all, budget if n < 360 else 0.0)
            plans = build_all()
            errs = construction_errors(sc, oracle, plans)
            deg = sum(len(p.velocity.degenerate) + len(p.acceleration.degenerate)
                      for p in plans if p.velocity and p.acceleration)
            recs.append(Record("construction", case.name, n, total_error(errs), t, t / n, dyads=case.dyads,
                               oracle=oracle.name, errors=errs,
                               note=f"{deg} degenerate intersections" if deg else ""))
        # Newton–Raphson (default tolerance 1e-12), seeded 1 % off at the first angle
        if n <= (360 if quick else 3600):
            seed = newton.seed_from(oracle_kin, 0, perturb=1e-2)
            system = newton.compile_scene(sc)
            t = timeit(functools.partial(newton.solve, sc, phis, tol=1e-12, seed=seed, system=system),
                       budget if n < 360 else 0.0)
            nr = newton.solve(sc, phis, tol=1e-12, seed=seed, system=system)
            errs = solver_errors(sc, oracle, nr.point, nr.omega, nr.eps)
            recs.append(Record("newton", case.name, n, total_error(errs), t, t / n, param="tol=1e-12",
                               dyads=case.dyads, oracle=oracle.name, errors=errs,
                               cond=float(np.nanmax(nr.cond)), iterations=float(np.mean(nr.iterations))))
        log(f"  {case.name}: {n} positions done")
    # Newton tolerance sweep at 12 positions (30° continuation steps) and at 1 position
    for n in (1, 12):
        phis = _phis(n)
        kin = kinematics.solve(sc, phis, order=2)
        oracle = case.reference(phis) if case.reference else oracle_from_kinematics(kin)
        seed = newton.seed_from(kin, 0, perturb=1e-2)
        system = newton.compile_scene(sc)
        for tol in TOLERANCES:
            t = timeit(functools.partial(newton.solve, sc, phis, tol=tol, seed=seed, system=system),
                       budget / 4)
            nr = newton.solve(sc, phis, tol=tol, seed=seed, system=system)
            errs = solver_errors(sc, oracle, nr.point, nr.omega, nr.eps)
            recs.append(Record("newton tol sweep", case.name, n, total_error(errs), t, t / n, param=f"tol={tol:.0e}",
                               dyads=case.dyads, oracle=oracle.name, errors=errs,
                               cond=float(np.nanmax(nr.cond)), iterations=float(np.mean(nr.iterations))))
    # finite differences of exact positions (central, step sweep), 360 positions
    n = 360
    phis = _phis(n)
    kin = kinematics.solve(sc, phis, order=2)
    oracle = case.reference(phis) if case.reference else oracle_from_kinematics(kin)
    for h in FD_STEPS_DEG:
        t = timeit(functools.partial(_finite_differences, sc, phis, h, oracle), budget / 4)
        point, omega, eps = _finite_differences(sc, phis, h, oracle)
        errs = solver_errors(sc, oracle, point, omega, eps)
        recs.append(Record("finite differences", case.name, n, total_error(errs), t, t / n, param=f"h={h:.0e} deg",
                           dyads=case.dyads, oracle=oracle.name, errors=errs))
    return recs


def _finite_differences(sc: Scene, phis: np.ndarray, h_deg: float, oracle: Oracle):
    """v = ω1 dr/dθ1 and a = ω1² d²r/dθ1² by central differences of exact positions (ε1 = 0:
    θ1 = ω1 t; with ε1 ≠ 0 the ε1 dr/dθ1 term is added)."""
    n = len(phis)
    kin = kinematics.solve(sc, np.concatenate([phis - h_deg, phis, phis + h_deg]), order=0)
    h = math.radians(h_deg) * sc.driver.sense
    w, e = sc.driver.omega, sc.driver.eps

    def point(name: str):
        r = kin.point(name)[0]
        rm, r0, rp = r[:n], r[n:2 * n], r[2 * n:]
        d1 = (rp - rm) / (2 * h)
        d2 = (rp - 2 * r0 + rm) / (h * h)
        return r0, w * d1, w * w * d2 + e * d1

    def angles(link: int):
        th = kin.theta(link)
        tm, t0, tp = th[:n], th[n:2 * n], th[2 * n:]
        dp = np.angle(np.exp(1j * (tp - t0)))
        dm = np.angle(np.exp(1j * (t0 - tm)))
        return (dp + dm) / (2 * h), (dp - dm) / (h * h)

    def omega(link: int):
        return w * angles(link)[0]

    def eps(link: int):
        d1, d2 = angles(link)
        return w * w * d2 + e * d1

    return point, omega, eps



def bench_chain(sizes: Sequence[int], budget: float, log: Callable[[str], None]) -> list[Record]:
    """Cost against mechanism size: exact (360 positions), construction (1 position),
    Newton (12 positions), errors against the exact analysis."""
    recs = []
    for n in sizes:
        sc = chain_scene(n)
        name = f"chain of {n} dyads"
        phis = _phis(360)
        t = timeit(functools.partial(kinematics.solve, sc, phis, order=2), budget)
        recs.append(Record("exact", name, 360, 0.0, t, t / 360, dyads=n, oracle="exact analysis",
                           note="is the oracle"))
        k1 = kinematics.solve(sc, [45.0], order=2)
        t = timeit(functools.partial(construction.build, k1, 0), budget)
        pp = [construction.build(k1, 0)]
        errs = construction_errors(sc, oracle_from_kinematics(k1), pp)
        recs.append(Record("construction", name, 1, total_error(errs), t, t, dyads=n, oracle="exact analysis",
                           errors=errs))
        ph12 = _phis(12)
        k12 = kinematics.solve(sc, ph12, order=2)
        seed = newton.seed_from(k12, 0, perturb=1e-3)
        system = newton.compile_scene(sc)
        t0 = time.perf_counter()
        nr = newton.solve(sc, ph12, seed=seed, system=system)
        t = time.perf_counter() - t0  # seconds on a long chain (dense solves): timed once, as it ran
        if t < budget / 2:
            t = timeit(functools.partial(newton.solve, sc, ph12, seed=seed, system=system), budget / 2)
        errs = solver_errors(sc, oracle_from_kinematics(k12), nr.point, nr.omega, nr.eps)
        recs.append(Record("newton", name, 12, total_error(errs), t, t / 12, param="tol=1e-12", dyads=n,
                           oracle="exact analysis", errors=errs, cond=float(np.nanmax(nr.cond)),
                           iterations=float(np.mean(nr.iterations))))
        log(f"  chain N={n} done")
    return recs


def bench_peers(perf: dict[str, Any]) -> list[Record]:
    """The peers' runs (:mod:`plans.accuracy.peers`, measured with the speed goals) as
    records; error: their largest disagreement with the exact analysis over r, v, a."""
    out = []
    for r in perf.get("peers", []):
        errs = r.get("errors") or {}
        t = r["time_per_position"]
        out.append(Record(r["peer"], r["mechanism"], r["positions"], max(errs.values(), default=math.nan),
                          t * r["positions"], t, oracle="exact analysis", errors=errs, note=r["note"]))
    return out


def _wants_forces(sc: Scene) -> bool:
    return sc.wants("force_polygons") or sc.wants("lever")



def bench_forces(cases: list[Case], sizes: Sequence[int], budget: float) -> list[Record]:
    """Force analysis (plans.forces, plans.lever) where a scene asks for it: the exact
    kinetostatics with the lever vectorised over positions, and the force polygons drawn
    per position; error = disagreement of the three balancing loads."""
    try:
        from plans.forces import analysis as forces
        from plans.forces import polygons
    except ImportError:  # pragma: no cover - the module is another engineer's
        return [Record("forces", "-", 0, math.nan, math.nan, math.nan, note="skipped: plans.forces absent")]
    recs = []
    for case in cases:
        sc = case.scene
        if not _wants_forces(sc):
            continue
        for n in sizes:
            phis = _phis(n)
            try:
                kin = kinematics.solve(sc, phis, order=2)
                t = timeit(functools.partial(forces.kinetostatics, sc, kin), budget if n < 3600 else 0.0)
                res = forces.kinetostatics(sc, kin)
                assert res is not None
                fa, lv = res
                e_lever, e_power = force_errors(fa, lv)
                recs.append(Record("forces exact", case.name, n, max(e_lever, e_power), t, t / n,
                                   dyads=case.dyads, oracle="kinetostatics vs lever vs power",
                                   errors={"lever": e_lever, "power": e_power}))
                if n <= 360:
                    def polys(fa: Any = fa, n: int = n) -> list:
                        return [polygons.force_polygons(fa, k) for k in range(n)]
                    t = timeit(polys, budget if n < 360 else 0.0)
                    recs.append(Record("force polygons", case.name, n, math.nan, t, t / n, dyads=case.dyads,
                                       note="construction of the polygons (readings: see plans solve)"))
            except Exception as exc:  # noqa: BLE001 - report, never break the benchmark
                recs.append(Record("forces exact", case.name, n, math.nan, math.nan, math.nan,
                                   note=f"skipped: {type(exc).__name__}: {exc}"))
                break
    return recs



# --------------------------------------------------------------------------- command


def run_bench(quick: bool = False, samples: Path | None = None, progress: Callable[[str], None] | None = None,
              sizes: Sequence[int] | None = None, chain_sizes: Sequence[int] | None = None,
              mc_samples: int | None = None, budget: float | None = None,
              model: DraftsmanModel | None = None) -> dict[str, Any]:
    """Run every method and return the JSON-ready result (see the module docstring)."""
    import shapely

    t_start = time.perf_counter()
    _log = progress or (lambda s: None)

    lang = run_language()

    def log(msg: Phrase | str) -> None:  # a line in the run's language (the bench's own words too)
        _log(f"[{time.perf_counter() - t_start:6.1f} s] {words(msg, lang)}")

    samples = samples or Path(__file__).resolve().parents[2] / "samples"
    budget = budget if budget is not None else (0.02 if quick else 0.2)
    sizes = tuple(sizes or (QUICK_SIZES if quick else SIZES))
    records: list[Record] = []
    cases = reference_cases()
    vcases = [c for c in sample_cases(samples) if c.name == "v_engine"] if quick else sample_cases(samples)
    for case in cases + vcases:
        log(phrase("bp_case", name=case.name))
        records += bench_case(case, sizes, budget, quick, log)
    log(phrase("bp_chain"))
    records += bench_chain(tuple(chain_sizes or (QUICK_CHAIN_SIZES if quick else CHAIN_SIZES)), budget, log)
    log(phrase("bp_speed"))
    perf = speed.measure(samples, log, quick=quick)
    records += bench_peers(perf)
    log(phrase("bp_forces"))
    records += bench_forces(cases + vcases, sizes, budget)
    log(phrase("bp_cycle"))
    from plans.accuracy import cycle_bench  # the cycle's dynamics and sheets

    records += cycle_bench.records(samples, quick)
    log(phrase("bp_draftsman"))
    mc = mc_samples or (400 if quick else 4000)
    model = model or DraftsmanModel()
    dm: dict[str, Any] = {"model": asdict(model), "samples": mc, "phi_deg": 45.0, "scenes": {}}
    draft_lines: dict[str, float] = {}
    # the samples with Coriolis terms and moving guides (RPR, PRP, RPP): cheap, always drawn
    mc_cases = cases + vcases[:1]
    have = {c.name for c in mc_cases}
    mc_cases += [c for c in (vcases if not quick else sample_cases(samples))
                 if c.name in CORIOLIS_SAMPLES and c.name not in have]
    for case in mc_cases:
        sheets = {}
        for sheet in ("A4", "A1"):
            try:
                t0 = time.perf_counter()
                res = draftsman_errors(case.scene, 45.0, sheet, model, mc, seed=1)
                t = time.perf_counter() - t0
            except NotImplementedError:
                break
            sheets[sheet] = {q: asdict(e) for q, e in res.items()}
            worst = max(e.p95_rel for e in res.values())
            records.append(Record(f"draftsman {sheet}", case.name, 1, worst, t / mc, t / mc,
                                  param=f"p95 of {mc} drawings", oracle="exact analysis",
                                  note="time: simulation cost per drawing"))
            if case.name == "slider-crank (offset)":
                draft_lines[f"hand drawing {sheet} (p95, slider-crank)"] = worst
            if case.name == "shaper" and sheet == "A1":
                draft_lines["hand drawing A1 (p95, shaper)"] = worst
        if sheets:
            dm["scenes"][case.name] = sheets
    log(phrase("bp_stability"))
    stability = stability_records()
    stiff = stiff_load_records(samples)
    log(phrase("bp_goals"))
    goals = vengine_goals.performance_goals(samples, budget)
    from plans.accuracy.synthesis_bench import synthesis_goals  # one design per model, proven

    goals += synthesis_goals(samples, budget)
    # phrases: bench.json writes their English, the report and the terminal the run's language
    warnings = [phrase("bw_cond", method=r.method, scene=r.scene, n=r.positions, param=r.param, cond=r.cond,
                       limit=newton.COND_WARN) for r in records
                if r.cond is not None and math.isfinite(r.cond) and r.cond > newton.COND_WARN]
    warnings += [phrase("bw_stability", case=row["case"], cond=row["cond"])
                 for row in stability if row.get("cond", 0) > newton.COND_WARN]
    warnings += [phrase("bw_goal", goal=goal_said(g)) for g in goals if not g["met"]]
    meta = {"quick": quick, "python": platform.python_version(), "numpy": np.__version__,
            "shapely": shapely.__version__, "machine": f"{platform.machine()}, {_cpus()} CPUs",
            "wall_s": time.perf_counter() - t_start, "sizes": list(sizes),
            "OPENBLAS_NUM_THREADS": os.environ.get("OPENBLAS_NUM_THREADS")}
    return {"meta": meta, "records": [r.to_json() for r in records], "goals": goals,
            "draftsman": dm, "draftsman_lines": draft_lines, "stability": stability, "stiff_loads": stiff,
            "warnings": warnings, "performance": perf}


def _cpus() -> int:
    return len(os.sched_getaffinity(0)) if hasattr(os, "sched_getaffinity") else (os.cpu_count() or 1)


def write_outputs(result: dict[str, Any], out_dir: Path, json_path: str | None = None,
                  plots: Mapping[str, Callable[[dict[str, Any]], str]] | None = None) -> list[Path]:
    """Write bench.md, bench.json and each of ``plots`` (file name -> the result drawn; the
    renderer supplies bench.svg): all of them or none."""
    files: dict[Path, str] = {out_dir / "bench.md": markdown(result, run_language())}
    for name, draw in (plots or {}).items():
        files[out_dir / name] = draw(result)
    text = json.dumps(result, indent=1, sort_keys=True, default=_jsonable)
    if json_path != "-":
        files[Path(json_path) if json_path else out_dir / "bench.json"] = text + "\n"
    out_dir.mkdir(parents=True, exist_ok=True)
    written = write_all(files)
    if json_path == "-":
        sys.stdout.write(text + "\n")
    return written


def check_outputs(out_dir: Path, json_path: str | None) -> None:
    """Refuse output paths that cannot be written before the bench runs for minutes."""
    from plans.errors import OutputError

    targets = [out_dir] + ([Path(json_path).parent] if json_path and json_path != "-" else [])
    for folder in targets:
        probe = folder
        while not probe.exists() and probe != probe.parent:
            probe = probe.parent
        if not probe.is_dir() or not os.access(probe, os.W_OK):
            raise OutputError(Said("bn2_folder_cannot_write", folder=folder))
        if folder != out_dir and not folder.is_dir():
            raise OutputError(Said("bn2_folder_such_folder", folder=folder, json_path=json_path))


def _jsonable(x: Any) -> Any:
    if isinstance(x, np.generic):
        return x.item()
    return str(x)


def register(subparsers: Any) -> argparse.ArgumentParser:
    """Add ``bench`` to the ``plans`` command line (``func=run``)."""
    p = subparsers.add_parser("bench", help="error against run time of every method; stability; hand-drawing error",
                              description=__doc__.split("\n\n")[0] if __doc__ else None)
    p.add_argument("--quick", action="store_true", help="fewer sizes and samples (well under 30 s)")
    from plans.language import add_option

    add_option(p)
    p.add_argument("--json", metavar="PATH", help="write the JSON here ('-' for stdout) instead of OUT/bench.json")
    p.add_argument("--out", metavar="DIR", default="bench-out", help="directory for bench.md, bench.svg (default bench-out)")
    p.add_argument("--samples", metavar="DIR", help="directory of sample scenes (default: the project's samples/)")
    p.add_argument("--mc", type=int, metavar="N", help="Monte Carlo drawings per sheet")
    p.add_argument("--sizes", type=_ints, metavar="N,N,...", help="numbers of positions (default 1,12,360,3600)")
    p.add_argument("--chain", type=_ints, metavar="N,N,...", help="chain lengths in dyads (default 1,2,5,10,20,50)")
    p.add_argument("--pencil-mm", type=float, default=0.25, help="pencil error, ± mm (default 0.25)")
    p.add_argument("--protractor-deg", type=float, default=0.25, help="protractor error, ± degrees (default 0.25)")
    p.add_argument("--quiet", action="store_true", help="no progress lines and no summary on the terminal")
    fuzz.add_arguments(p)
    p.set_defaults(func=run)
    return p


def _ints(text: str) -> tuple[int, ...]:
    try:
        out = tuple(int(x) for x in text.split(","))
    except ValueError:
        raise argparse.ArgumentTypeError(Said("bn_sizes", got=repr(text)).text(run_language())) from None
    if not out or min(out) < 1:
        raise argparse.ArgumentTypeError(Said("bn_sizes_positive", got=repr(text)).text(run_language()))
    return out


def run(args: argparse.Namespace) -> int:
    if getattr(args, "fuzz", None) is not None:
        return fuzz.run(args)
    from plans.phrases import say
    from plans.progress import Progress

    quiet = getattr(args, "json", None) == "-" or getattr(args, "quiet", False)
    progress = Progress(quiet)
    err = sys.stderr
    if importlib.util.find_spec("mpmath") is None:
        print(say("bn_mpmath", run_language()), file=err)
        return 2

    def log(s: str) -> None:
        progress(s.split("] ", 1)[-1])

    check_outputs(Path(args.out), getattr(args, "json", None))
    model = DraftsmanModel(getattr(args, "pencil_mm", 0.25), getattr(args, "protractor_deg", 0.25))
    result = run_bench(quick=bool(args.quick), samples=Path(args.samples) if getattr(args, "samples", None) else None,
                       progress=log, mc_samples=getattr(args, "mc", None), sizes=getattr(args, "sizes", None),
                       chain_sizes=getattr(args, "chain", None), model=model)
    written = write_outputs(result, Path(args.out), getattr(args, "json", None), getattr(args, "plots", None))
    if not quiet:
        recs = [Record.from_json(r) for r in result["records"]]
        lang = run_language()
        print(summary_table(recs, lang))
        for g in result["goals"]:
            print(goal_line(g, lang))
        print(say("bn_speed", lang))
        print("\n".join(words(line, lang) for line in speed.lines(result.get("performance", {}), lang)))
        for w in result["warnings"]:
            print(say("bn_warning", lang, w=words(w, lang)), file=err)
        print(say("bn_wrote", lang, paths=", ".join(str(p) for p in written)))
    return 0


def main(argv: Sequence[str] | None = None) -> int:
    parser = argparse.ArgumentParser(prog="plans")
    sub = parser.add_subparsers(dest="command", required=True)
    register(sub)
    args = parser.parse_args(["bench", *(argv if argv is not None else sys.argv[1:])])
    return int(args.func(args))


if __name__ == "__main__":  # pragma: no cover
    raise SystemExit(main())
