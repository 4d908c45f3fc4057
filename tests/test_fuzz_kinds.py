"""A seeded fuzz of every file kind in the suite: a few thousand mutated files per kind run
through the kind's reader (the fast half: accepted, or refused in one line naming the file),
and a smaller share run through the whole command (status, one line, nothing written, every
number finite), some with --json naming the input by another spelling, some through another
kind's command.  ``plans bench --fuzz N`` runs the long one over the same mutations."""

from __future__ import annotations

import random
import tempfile
from collections import Counter
from pathlib import Path

import pytest

import drawings.cli  # noqa: F401  (loaded: the fuzzer also draws)
from plans.accuracy import fuzz

POOL = fuzz.load_samples()
KINDS = sorted({s.kind for s in POOL})
#: cases per kind through the reader, and through the whole command
READS = {"linkage": 2000, "engine": 2000, "gears": 2000, "cam": 2000, "synthesis": 1000, "check": 150}
RUNS = 40


def test_every_kind_has_samples_to_fuzz():
    """Every kind the family registers (plans.kinds.KINDS), and check files, has a sample
    under samples/ that its command accepts: a new kind is fuzzed as soon as it is added."""
    from plans.kinds import KINDS as REGISTERED
    from plans.kinds import READERS

    assert set(KINDS) == set(REGISTERED) | {"check"}
    assert set(READERS) == set(REGISTERED), "every kind registers the reader the fuzzer drives"
    assert set(READS) >= set(KINDS)


@pytest.mark.parametrize("kind", KINDS)
def test_the_reader_of_every_kind_keeps_the_promise(kind):
    rng = random.Random(f"read-{kind}")
    pool = [s for s in POOL if s.kind == kind]
    seen: Counter[int] = Counter()
    with tempfile.TemporaryDirectory() as tmp:
        for _ in range(READS[kind]):
            sample = rng.choice(pool)
            raw = fuzz.case_bytes(sample, rng)
            res = fuzz.read_case(sample, raw, Path(tmp))
            assert res.ok, f"{sample.rel}: {res.why}\n--- the file ---\n{raw.decode('utf-8', 'replace')[:3000]}"
            seen[res.status or 0] += 1
    assert seen[0] and seen[2], f"both accepted and refused cases: {seen}"


@pytest.mark.parametrize("kind", KINDS)
def test_the_command_of_every_kind_keeps_the_promise(kind):
    rng = random.Random(f"run-{kind}")
    pool = [s for s in POOL if s.kind == kind]
    for i in range(RUNS):
        sample = rng.choice(pool)
        raw = fuzz.case_bytes(sample, rng)
        over = fuzz.SPELLINGS[i % len(fuzz.SPELLINGS)] if i % 4 == 1 else None
        other = rng.choice(fuzz.COMMANDS) if i % 4 == 3 else None
        with tempfile.TemporaryDirectory() as tmp:
            res = fuzz.run_case(sample, raw, Path(tmp), draw=i % 20 == 0, json_out=True, command=other,
                                over_input=over)
        assert res.ok, f"{sample.rel} ({over or other or ''}): {res.why}\n--- the file ---\n" \
                       f"{raw.decode('utf-8', 'replace')[:3000]}"


def test_the_long_run_covers_every_kind():
    """``plans bench --fuzz N`` fuzzes every kind of file (and says how many of each)."""
    summary = fuzz.fuzz(40, seed=1, draw_every=0)
    assert set(summary.kinds) == set(KINDS) and not summary.failures, fuzz.report(summary, 1)
    assert "by kind: cam" in fuzz.report(summary, 1)
