"""Numerical dust: a value that is zero up to round-off against its scale is printed 0 in
``plans solve`` (tables and protocol), in the JSON readings, and every % difference is defined
once (plans.units.percent), with none against a zero exact value."""

from __future__ import annotations

import re

import pytest

from plans.kinematics.placing import load_scene
from plans.results import solve_scene, table, to_json
from plans.units import DUST, clean, percent

from .conftest import SAMPLES

# a printed number whose size is below 1e-9 of any scale in these samples (all ≥ 1e-3)
_DUST = re.compile(r"(?<![\w.])[-+]?\d+(?:[.,]\d+)?e-(?:1[2-9]|[2-9]\d|\d{3})\b", re.I)


@pytest.fixture(scope="module", params=SAMPLES, ids=[p.stem for p in SAMPLES])
def solved(request):
    return solve_scene(load_scene(request.param))


def test_no_dust_in_the_table_and_protocol(solved):
    text = table(solved, protocol=True)
    assert not _DUST.findall(text), _DUST.findall(text)[:5]


def test_json_readings_zero_or_above_their_scale(solved):
    for pos in to_json(solved)["positions"]:
        readings = pos.get("readings", [])
        scale: dict[str, float] = {}
        for r in readings:  # the size of each plan: its largest exact value
            scale[r["unit"]] = max(scale.get(r["unit"], 0.0), abs(r["exact"]), abs(r["value"]))
        for r in readings:
            for key in ("value", "exact", "difference"):
                x = r[key]
                assert x == 0 or abs(x) > DUST * scale[r["unit"]], (r["quantity"], key, x)
        bal = pos.get("balancing")
        if bal:
            for key in ("difference_percent", "exact_difference_percent"):
                x = bal[key]
                assert x is None or x == 0 or abs(x) > DUST * 100, (key, x)


def test_one_percent_definition():
    assert percent(101.0, 100.0) == pytest.approx(1.0)
    assert percent(1.0, 0.0) is None  # never a % against zero
    assert percent(1.0, 3e-17, ref=5.0) is None  # zero up to round-off against its plan
    assert percent(1.05, 1.0, ref=10.0) == pytest.approx(0.5)  # floored by the plan's size
    assert percent(1.0 + 1e-15, 1.0) == 0.0
    assert clean(3.57e-32, 100.0) == 0.0 and clean(-1e-20, 1.0) == 0.0
    assert str(clean(-0.0, 1.0)) == "0.0"


def test_scale_of_a_subnormal_vector_is_finite():
    """A vector of 5e-324 (found by the fuzzer) gives a plain scale, not a math domain error."""
    from plans.kinematics.construction import nice_scale

    assert nice_scale(5e-324) == 1.0
    assert nice_scale(5e-324, 1e-300) > 0
