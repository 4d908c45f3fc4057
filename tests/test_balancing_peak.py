"""The exact shaking moment's maximum is found by maximising, not read off 1° samples."""

from __future__ import annotations

import math
from dataclasses import replace
from pathlib import Path

import numpy as np
import pytest

from plans.balancing.engine import load_engine
from plans.balancing.exact import exact_check, frame_force

ROOT = Path(__file__).resolve().parent.parent


def test_shaking_moment_peak_against_a_brute_force_scan():
    """seed 002's four-cylinder engine: the largest |M| between the 1° samples, against a
    scan every 0.00067° around the largest sample, each cylinder's frame force times its arm."""
    e = load_engine(ROOT / "samples" / "engines" / "seed002_four_cylinder_two_stroke.toml")
    chk = exact_check(e)
    sampled = float(np.max(np.abs(chk.moment_exact)))
    k = int(np.argmax(np.abs(chk.moment_exact)))
    phis = [float(x) for x in np.linspace(k - 1.0, k + 1.0, 3001)]
    moment = np.zeros(len(phis), complex)
    for c in e.cylinders:
        alone = replace(e, cylinders=(replace(c, crank=0.0),))
        moment += (c.z - e.reference_z) * frame_force(alone, crank_deg=math.degrees(c.crank), phi_deg=phis)
    brute = float(np.max(np.abs(moment)))
    assert chk.max_moment == pytest.approx(brute, rel=1e-9)
    assert chk.max_moment - sampled > 1e-6 * sampled  # the 1° samples miss the peak
    assert chk.max_moment >= brute * (1 - 1e-12)


def test_peak_of_a_force_whose_largest_sample_is_the_peak():
    """The inline four: its peak falls on a sample (the dead centres); maximising keeps it."""
    e = load_engine(ROOT / "samples" / "engines" / "inline4.toml")
    chk = exact_check(e)
    assert chk.max_exact == pytest.approx(float(np.max(np.abs(chk.exact))), rel=1e-12)


def test_an_engine_with_no_rotating_masses(tmp_path):
    """The 90° V-twin with m_rot = 0: no rotating force; its first-order reciprocating force
    is m_rec r ω² turning with the crank, taken by a counterweight of m·r = m_rec·r."""
    from plans.balancing.analysis import balance

    text = (ROOT / "samples" / "engines" / "v_twin.toml").read_text().replace("m_rot = 0.56615", "m_rot = 0")
    f = tmp_path / "v0.toml"
    f.write_text(text)
    e = load_engine(f)
    b = balance(e)
    assert abs(b.forces["rotating"].forward) == 0
    cw = [c for c in b.counterweights if c.of == "first_order"]
    assert len(cw) == 1 and cw[0].mass_radius == pytest.approx(0.96485 * 0.035, rel=1e-12)
    assert not [c for c in b.counterweights if c.of == "rotating"]
    assert exact_check(e).max_exact > 0
