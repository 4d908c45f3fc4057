"""Hostile files in bulk: every sample under samples/ (whatever its kind: new kinds are
fuzzed as soon as their samples land) mutated by :mod:`plans.accuracy.fuzz` and run through
its command.  A fixed, derandomized budget here; ``plans bench --fuzz N`` runs the long one."""

from __future__ import annotations

import random
import tempfile
from pathlib import Path

import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

import drawings.cli  # noqa: F401  (loaded: the fuzzer also draws)
from plans.accuracy import fuzz

POOL = fuzz.load_samples()
SCENES = [s for s in POOL if s.argv("f", None)[0] != "check"]
CHECKS = [s for s in POOL if s.argv("f", None)[0] == "check"]


def test_every_sample_is_fuzzed():
    found = sorted(p for p in fuzz.SAMPLES.rglob("*.toml"))
    assert len(POOL) == len(found), "every sample file is accepted as it is and so fuzzed"


def _keeps_promise(sample: fuzz.Sample, rng: random.Random, draw: bool) -> None:
    raw = fuzz.case_bytes(sample, rng)
    with tempfile.TemporaryDirectory() as tmp:
        res = fuzz.run_case(sample, raw, Path(tmp), draw=draw)
    assert res.ok, f"{sample.rel}: {res.why}\n--- the file ---\n{raw.decode('utf-8', 'replace')[:3000]}"


@settings(max_examples=300, derandomize=True, deadline=None, database=None,
          suppress_health_check=[HealthCheck.too_slow])
@given(st.sampled_from(SCENES), st.randoms(use_true_random=False), st.integers(0, 19))
def test_fuzzed_files_keep_the_promise(sample, rng, k):
    _keeps_promise(sample, rng, draw=k == 0)


@pytest.mark.skipif(not CHECKS, reason="no check files among the samples")
@settings(max_examples=40, derandomize=True, deadline=None, database=None,
          suppress_health_check=[HealthCheck.too_slow])
@given(st.sampled_from(CHECKS or [None]), st.randoms(use_true_random=False))
def test_fuzzed_check_files_keep_the_promise(sample, rng):
    _keeps_promise(sample, rng, draw=False)


def test_the_long_run_reports_and_keeps_failures(tmp_path):
    summary = fuzz.fuzz(16, seed=3, draw_every=0, keep=tmp_path, samples=SCENES[:2])
    assert summary.cases == 16 and not summary.failures
    assert summary.accepted + summary.refused == 16
    assert "16 cases" in fuzz.report(summary, 3)


def test_toml_writer_round_trips_hostile_values():
    import tomllib

    data = {"a b": "x\u0001\"\\", "n": [1, 2.5, -0.0, 10**30], "t": {"k": True, "s": "ω"}}
    assert tomllib.loads(fuzz.to_toml(data)) == data
