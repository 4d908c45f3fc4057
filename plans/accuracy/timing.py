"""How ``plans bench`` times what it measures: medians of batches, two things measured turn
about (a shared machine drifts less within a turn), fresh interpreters run as the installed
command runs, profiles of what is slow, and the record of one goal."""

from __future__ import annotations

import cProfile
import io
import math
import pstats
import subprocess
import sys
import time
from collections.abc import Callable
from dataclasses import dataclass
from pathlib import Path
from typing import Any

from plans.phrases import Phrase, number, phrase, say


@dataclass
class Goal:
    goal: Phrase | str  # a phrase of plans.messages_bench (bench.json keeps its English)
    measured: Phrase | str
    ratio: float  # measured over the goal's bound (≤ 1 met), or the speed-up for "ahead" goals
    met: bool | None  # None: not measured (the reason in ``measured``)

    def line(self, lang: str = "en") -> str:
        state = say("bs_met" if self.met else "bs_skipped" if self.met is None else "bs_not_met", lang)
        r = "" if math.isnan(self.ratio) else f" [{number(self.ratio, '.2f', lang)}]"
        width = 8 if lang == "en" else 11  # the states' column: "NOT met", "не достигнута"
        return say("br_goal_line", lang, state=state.ljust(width), goal=self.goal, measured=self.measured, ratio=r)


def median_time(fn: Callable[[], Any], reps: int = 7, least: float = 2e-3) -> float:
    """Median over ``reps`` of the mean time of a batch long enough to time (≥ ``least`` s)."""
    t0 = time.perf_counter()
    fn()
    one = time.perf_counter() - t0
    inner = max(1, int(least / max(one, 1e-9)))
    ts = []
    for _ in range(reps):
        t0 = time.perf_counter()
        for _ in range(inner):
            fn()
        ts.append((time.perf_counter() - t0) / inner)
    return sorted(ts)[len(ts) // 2]


def paired(fa: Callable[[], Any], fb: Callable[[], Any], reps: int = 7) -> tuple[float, float, float]:
    """Times of ``fa`` and ``fb`` measured turn about (median of each) and the median of the
    per-turn ratio fa/fb: on a shared machine the load drifts less within one turn."""
    ta, tb, ratios = [], [], []
    fa()
    fb()
    for _ in range(reps):
        a = median_time(fa, reps=3, least=1e-3)
        b = median_time(fb, reps=3, least=1e-3)
        ta.append(a)
        tb.append(b)
        ratios.append(a / b)
    mid = reps // 2
    return sorted(ta)[mid], sorted(tb)[mid], sorted(ratios)[mid]


def least_paired(fa: Callable[[], Any], fb: Callable[[], Any], reps: int = 41, batch: float = 3e-4,
                 clock: Callable[[], float] = time.perf_counter) -> tuple[float, float]:
    """The least time per call of ``fa`` and of ``fb``, measured turn about in short batches
    (about ``batch`` seconds each, one call at least), ``reps`` turns.  On a loaded machine
    the scheduler takes the processor away for longer than it gives it (tens of
    milliseconds out of every few): a batch that long is nearly always cut, one this short
    mostly is not, and the least of many is what the call itself costs (the load only ever
    adds to it).  Taking turns, the two see the same machine.  A call longer than the
    scheduler's share is timed by ``clock=time.process_time``: the processor time it took,
    without the time it waited for the processor."""
    def inner(fn: Callable[[], Any]) -> int:
        fn()
        t0 = time.perf_counter()
        fn()
        return max(1, int(batch / max(time.perf_counter() - t0, 1e-9)))

    na, nb = inner(fa), inner(fb)
    ta = tb = math.inf
    for _ in range(reps):
        t0 = clock()
        for _ in range(na):
            fa()
        ta = min(ta, (clock() - t0) / na)
        t0 = clock()
        for _ in range(nb):
            fb()
        tb = min(tb, (clock() - t0) / nb)
    return ta, tb


def least_time(fn: Callable[[], Any], reps: int = 41, batch: float = 3e-4) -> float:
    """The least time per call of ``fn`` over ``reps`` short batches (see :func:`least_paired`)."""
    fn()
    t0 = time.perf_counter()
    fn()
    n = max(1, int(batch / max(time.perf_counter() - t0, 1e-9)))
    best = math.inf
    for _ in range(reps):
        t0 = time.perf_counter()
        for _ in range(n):
            fn()
        best = min(best, (time.perf_counter() - t0) / n)
    return best


def us(t: float) -> str:
    return f"{t * 1e6:.1f} µs" if t < 1e-3 else f"{t * 1e3:.2f} ms" if t < 1 else f"{t:.2f} s"


def took(t: float) -> Phrase:
    """A time as :func:`us` writes it, in either language (a goal's field)."""
    return phrase("bu_us", v=t * 1e6) if t < 1e-3 else phrase("bu_ms", v=t * 1e3) if t < 1 else phrase("bu_s", v=t)


def goal_record(key: str, what: str, limit: float, unit: str, value: float) -> dict[str, Any]:
    met = value <= limit if unit in ("s", "× cost") else value >= limit
    return {"key": key, "goal": what, "value": value, "limit": limit, "unit": unit, "met": bool(met)}


def interpreter_env() -> dict[str, str]:
    """The environment of the fresh interpreters timed here: bytecode compiled and kept (in
    a cache folder of its own, the source tree untouched), as an installed ``plans`` has it;
    one BLAS thread, as the rest of the bench."""
    import os
    import tempfile

    env = dict(os.environ)
    env.pop("PYTHONDONTWRITEBYTECODE", None)
    env["PYTHONPYCACHEPREFIX"] = str(Path(tempfile.gettempdir()) / "plans-bench-pycache")
    env.setdefault("OPENBLAS_NUM_THREADS", "1")
    return env


def commands_seconds(runs: dict[str, list[str]], root: Path, env: dict[str, str],
                      reps: int, least: bool = False) -> dict[str, tuple[float, float, int]]:
    """Median wall time of each ``python args`` in a fresh interpreter, the median processor
    time it took (user and system; NaN where the platform does not tell) and its exit status,
    after one run of each that compiles its bytecode; with ``least``, the least of each
    (what a start costs when nothing else is in its way: the load only ever adds to it).
    The commands take turns, one run of each per turn: on a shared machine the load drifts
    less within a turn, so the floor and the commands measured beside it see the same machine."""
    try:
        import resource
    except ImportError:  # pragma: no cover - not POSIX
        resource = None  # type: ignore[assignment]

    def processor() -> float:
        if resource is None:  # pragma: no cover
            return math.nan
        r = resource.getrusage(resource.RUSAGE_CHILDREN)
        return r.ru_utime + r.ru_stime

    wall: dict[str, list[float]] = {name: [] for name in runs}
    cpu: dict[str, list[float]] = {name: [] for name in runs}
    status = {name: subprocess.run([sys.executable, *args], cwd=root, capture_output=True, env=env).returncode
              for name, args in runs.items()}
    for _ in range(reps):
        for name, args in runs.items():
            c0, t0 = processor(), time.perf_counter()
            p = subprocess.run([sys.executable, *args], cwd=root, capture_output=True, env=env)
            wall[name].append(time.perf_counter() - t0)
            cpu[name].append(processor() - c0)
            status[name] = status[name] or p.returncode
    mid = 0 if least else reps // 2
    return {name: (sorted(wall[name])[mid], sorted(cpu[name])[mid], status[name]) for name in runs}


def profile(fn: Callable[[], Any], reps: int, top: int = 12) -> list[dict]:
    """The functions where ``fn`` spends its time (own time, cProfile), as records."""
    pr = cProfile.Profile()
    pr.enable()
    for _ in range(reps):
        fn()
    pr.disable()
    st = pstats.Stats(pr, stream=io.StringIO())
    rows = []
    for (file, line, func), (_cc, nc, tt, ct, _callers) in st.stats.items():  # type: ignore[attr-defined]
        rows.append({"function": f"{Path(file).name}:{line}({func})", "calls_per_run": nc / reps,
                     "own_us_per_run": tt / reps * 1e6, "cum_us_per_run": ct / reps * 1e6})
    rows.sort(key=lambda r: -r["own_us_per_run"])
    return rows[:top]
