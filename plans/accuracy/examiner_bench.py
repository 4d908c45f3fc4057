"""The examiner's goals for ``plans bench``: how often it names a planted mistake, how often
a clean student gets no finding, and how long a submission and a folder take.

Submissions come from :mod:`plans.check.planted` (the construction drawn with the slip,
every segment read to a seeded random ±0.5 mm) on the V-engine, the shaper, the six-bar
and the Whitworth mechanism.  A planted mistake counts when it shows: when the same
submission read without noise gives the checker something (a failure, a finding, a
cause); a slip that moves nothing beyond the tolerance cannot be named.

Run alone: ``python -m plans.accuracy.examiner_bench [--quick]``.
"""

from __future__ import annotations

import copy
import tempfile
import time
from collections import Counter
from pathlib import Path
from typing import Any

import numpy as np

from plans.accuracy.timing import Goal
from plans.phrases import phrase

NAMED_RATE = 0.95  # the planted cause named alone or first
CLEAN_RATE = 0.99  # a clean submission gets no finding at all
ONE_SUBMISSION_S = 0.5  # one submission with two positions diagnosed
FOLDER_S = 10.0  # a folder of 30 submissions
SCENES = {"v_engine": (0.0, 45.0), "shaper": (30.0, 120.0, 210.0, 300.0),
          "six_bar": (30.0, 90.0, 150.0, 240.0), "whitworth": (30.0, 120.0, 210.0, 300.0)}


def rates(samples: Path, per_kind: int, clean_per_scene: int, seed: int = 2024,
          scenes: tuple[str, ...] = tuple(SCENES)) -> dict[str, Any]:
    """Planted and clean submissions on the scenes of :data:`SCENES`; the counts."""
    from plans.check.checkfile import check_from_dict
    from plans.check.planted import PLANTED, Scenario, submission
    from plans.check.report import check

    count: Counter[str] = Counter()
    by_kind: dict[str, list[int]] = {k: [0, 0] for k in PLANTED}
    misses: list[str] = []
    for s_ix, (name, phis) in enumerate(SCENES.items()):
        if name not in scenes:
            continue
        sc = Scenario.of(samples / f"{name}.toml")
        plan = [None] * clean_per_scene + [k for k in PLANTED for _ in range(per_kind)]
        for n, kind in enumerate(plan):
            rng = np.random.default_rng([seed, s_ix, n])
            i, j = rng.choice(len(phis), 2, replace=False)
            pair = (float(phis[i]), float(phis[j]))
            twin = copy.deepcopy(rng)
            try:
                data, told = submission(sc, pair, kind, rng)
            except LookupError:
                count["not applicable"] += 1
                continue
            rep = check(check_from_dict(data, f"{name}.toml"))
            kinds = [c.kind for c in rep.causes]
            if kind is None:
                count["clean"] += 1
                if not kinds and not rep.unexplained and not rep.findings:
                    count["clean ok"] += 1
                else:
                    misses.append(f"{name} clean: {kinds or [f.kind for f in rep.findings]}")
                continue
            quiet, _ = submission(sc, pair, kind, twin, noise_mm=0.0)
            q = check(check_from_dict(quiet, f"{name}.toml"))
            if not q.failed and not q.findings and not q.causes:
                count["invisible"] += 1
                continue
            count["shown"] += 1
            by_kind[kind][1] += 1
            if kinds and kinds[0] == kind:
                count["named"] += 1
                by_kind[kind][0] += 1
            else:
                misses.append(f"{name} {told}: {kinds[:3]}")
    return {"counts": dict(count), "by_kind": by_kind, "misses": misses[:20]}


def _one_submission(samples: Path) -> tuple[float, Path]:
    """Seconds to check (and diagnose) one two-position submission from its file."""
    import tomlkit

    from plans.check.planted import Scenario, submission
    from plans.check.report import check_file

    sc = Scenario.of(samples / "whitworth.toml")
    data, _ = submission(sc, (30.0, 210.0), "coriolis_reversed", np.random.default_rng(7))
    folder = Path(tempfile.mkdtemp(prefix="plans-examiner-"))
    path = folder / "one.toml"
    path.write_text(tomlkit.dumps(data), encoding="utf-8")
    times = []
    for _ in range(3):
        t0 = time.perf_counter()
        check_file(path)
        times.append(time.perf_counter() - t0)
    return float(np.median(times)), folder


def _folder(samples: Path, folder: Path) -> float:
    """Seconds for ``plans check DIR`` on 30 submissions (reports and summary written)."""
    import tomlkit

    from plans.check.planted import PLANTED, Scenario, submission
    from plans.cli import main

    group = folder / "group"
    group.mkdir()
    scs = [Scenario.of(samples / f"{name}.toml") for name in ("shaper", "whitworth", "six_bar")]
    for n in range(30):
        sc = scs[n % 3]
        kind = None if n % 4 == 0 else PLANTED[n % len(PLANTED)]
        try:
            data, _ = submission(sc, (30.0, 120.0), kind, np.random.default_rng(n))
        except LookupError:
            data, _ = submission(sc, (30.0, 120.0), None, np.random.default_rng(n))
        (group / f"student{n:02d}.toml").write_text(tomlkit.dumps(data), encoding="utf-8")
    t0 = time.perf_counter()
    main(["check", str(group), "--out", str(folder / "out"), "--quiet"])
    return time.perf_counter() - t0


def examiner_goals(samples: Path, quick: bool = False) -> list[Goal]:
    """The examiner's four goals, measured in this run."""
    import shutil

    if not all((samples / f"{n}.toml").exists() for n in SCENES):
        return [Goal(phrase("bq_examiner_short"), phrase("bq_examiner_needed"), float("nan"), None)]
    # quick: two scenes, one submission per mistake (the rates are then indicative only)
    got = rates(samples, 1, 2, scenes=("shaper", "whitworth")) if quick else rates(samples, 6, 25)
    c = got["counts"]
    shown, named = c.get("shown", 0), c.get("named", 0)
    clean, ok = c.get("clean", 0), c.get("clean ok", 0)
    named_rate = named / shown if shown else 0.0
    clean_rate = ok / clean if clean else 0.0
    from plans.language import CAUSES

    rows = [(k, a, b) for k, (a, b) in got["by_kind"].items() if b]
    kinds = phrase("bq_either", en=", ".join(f"{k} {a}/{b}" for k, a, b in rows),
                   ru=", ".join(f"{CAUSES[k][1] if k in CAUSES else k} {a}/{b}" for k, a, b in rows))
    where = phrase("bq_where_quick" if quick else "bq_where_full")
    out = [Goal(phrase("bq_named", rate=NAMED_RATE, where=where),
                phrase("bq_named_got", named=named, shown=shown, rate=named_rate, invisible=c.get("invisible", 0),
                       kinds=kinds), NAMED_RATE / max(named_rate, 1e-9), named_rate >= NAMED_RATE),
           Goal(phrase("bq_clean", rate=CLEAN_RATE), phrase("bq_clean_got", ok=ok, clean=clean, rate=clean_rate),
                CLEAN_RATE / max(clean_rate, 1e-9), clean_rate >= CLEAN_RATE)]
    one, folder = _one_submission(samples)
    try:
        out.append(Goal(phrase("bq_one_submission", bound=ONE_SUBMISSION_S), phrase("bq_seconds3", t=one),
                        one / ONE_SUBMISSION_S, one <= ONE_SUBMISSION_S))
        many = _folder(samples, folder)
        out.append(Goal(phrase("bq_folder", bound=FOLDER_S), phrase("bq_seconds2", t=many), many / FOLDER_S,
                        many <= FOLDER_S))
    finally:
        shutil.rmtree(folder, ignore_errors=True)
    return out


def main() -> int:
    import sys

    samples = Path(__file__).resolve().parents[2] / "samples"
    for g in examiner_goals(samples, quick="--quick" in sys.argv):
        print(g.line())
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
