"""The group's goals: a group of 30 variants made (files, keys, forms, reference sheets)
with ``plans variants --jobs 2``, and their 30 submissions checked into the gradebook.

Measured by ``plans bench`` of the drawing package (``plans variants`` is the renderer's).
"""

from __future__ import annotations

import contextlib
import csv
import io
import math
import shutil
import tempfile
import time
from collections.abc import Callable
from pathlib import Path

from plans.accuracy.timing import Goal
from plans.phrases import phrase

VARIANTS_S = 60.0  # 30 variants, sheets included, on 2 cores with --jobs 2
CHECK_S = 5.0  # 30 submissions checked, the gradebook written
SLIPS = {1: "scale", 2: "coriolis_reversed", 3: "arithmetic"}


def _table(samples: Path, folder: Path, n: int = 30) -> Path:
    """The sample group's table grown to ``n`` rows (its rows again, under new names)."""
    src = samples / "group"
    for t in src.glob("*.template"):
        shutil.copy(t, folder / t.name)
    with (src / "group.csv").open(encoding="utf-8") as fh:
        rows = list(csv.DictReader(fh))
    out = folder / "group.csv"
    with out.open("w", encoding="utf-8", newline="") as fh:
        w = csv.DictWriter(fh, fieldnames=list(rows[0]), lineterminator="\n")
        w.writeheader()
        for i in range(n):
            w.writerow({**rows[i % len(rows)], "variant": f"V{i + 1:02d}"})
    return out


#: The renderer's ``plans`` command line (:func:`drawings.cli.main`), registered when the drawing
#: package builds ``plans bench``: ``plans variants`` is the renderer's command.
COMMAND: list[Callable[[list[str]], int]] = []


def _variants(table: Path, out: Path) -> tuple[float, str]:
    """Seconds for the whole command run through the command line's own entry in this process,
    and its complaint ("" if none)."""
    err = io.StringIO()
    t0 = time.perf_counter()
    with contextlib.redirect_stderr(err), contextlib.redirect_stdout(io.StringIO()):
        status = COMMAND[0](["variants", str(table), "-o", str(out), "--jobs", "2", "--quiet"])
    took = time.perf_counter() - t0
    return took, "" if status == 0 else f"exit {status}: {err.getvalue()[:300]}"


def _check(course: Path, subs: Path) -> float:
    import tomlkit

    from plans.cli import main
    from plans.group.samples import key_submission

    for n, d in enumerate(sorted(p for p in course.iterdir() if p.name != "handouts")):
        target = subs / f"{d.name}.toml"
        slip = SLIPS.get(n) if (d / "scene.toml").exists() else None
        target.write_text(tomlkit.dumps(key_submission(d, target, f"student {n:02d}", "G-1", slip)),
                          encoding="utf-8")
    t0 = time.perf_counter()
    main(["check", str(subs), "--xlsx", str(subs.parent / "marks.xlsx"), "--quiet"])
    return time.perf_counter() - t0


def group_goals(samples: Path) -> list[Goal]:
    if not (samples / "group" / "group.csv").exists():
        return [Goal(phrase("bq_group_short"), phrase("bq_group_needed"), float("nan"), None)]
    if not COMMAND:
        return [Goal(phrase("bq_group_short"), phrase("bq_no_renderer"), math.nan, None)]
    with tempfile.TemporaryDirectory(prefix="plans-group-bench-") as tmp:
        root = Path(tmp)
        table = _table(samples, root)
        made, complaint = _variants(table, root / "course")
        out = [Goal(phrase("bq_variants", bound=VARIANTS_S),
                    phrase("bq_variants_got", t=made, complaint=f" ({complaint})" if complaint else ""),
                    made / VARIANTS_S, made <= VARIANTS_S and not complaint)]
        if complaint:
            return out
        subs = root / "subs"
        subs.mkdir()
        took = _check(root / "course", subs)
        out.append(Goal(phrase("bq_gradebook", bound=CHECK_S), phrase("bq_seconds2", t=took),
                        took / CHECK_S, took <= CHECK_S))
    return out

