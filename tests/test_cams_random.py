"""Random cams (laws, senses, offsets, both followers): the envelope, the pressure angle and
the base radius keep their geometric meaning."""

from __future__ import annotations

import math
from dataclasses import replace

import numpy as np
import shapely
from hypothesis import given, settings
from hypothesis import strategies as st

from plans.cams.analysis import findings, grid, profile
from plans.cams.base_radius import min_base_radius
from plans.cams.laws import LAWS
from plans.cams.model import cam_from_dict

LAW_NAMES = sorted(LAWS)


@st.composite
def cams(draw):
    osc = draw(st.booleans())
    rise = draw(st.integers(60, 150))
    far = draw(st.integers(0, 40))
    ret = draw(st.integers(60, 150))
    near = 360 - rise - far - ret
    phases = [{"kind": "rise", "angle_deg": rise, "law": draw(st.sampled_from(LAW_NAMES))}]
    if osc:
        phases[0]["swing_deg"] = draw(st.floats(8, 25))
    else:
        phases[0]["stroke"] = draw(st.floats(5, 25))
    if far:
        phases.append({"kind": "dwell", "angle_deg": far})
    phases.append({"kind": "return", "angle_deg": ret, "law": draw(st.sampled_from(LAW_NAMES))})
    if near:
        phases.append({"kind": "dwell", "angle_deg": near})
    r0 = draw(st.floats(30, 60))
    d = {"format": 1, "kind": "cam", "unit": "mm", "follower": "oscillating" if osc else "translating",
         "base_radius": r0, "roller": draw(st.floats(2, 8)), "omega_rpm": 100,
         "sense": draw(st.sampled_from(["ccw", "cw"])), "phases": phases}
    if osc:
        d["arm"] = draw(st.floats(1.2 * r0, 2 * r0))
        d["pivot"] = draw(st.floats(1.3 * r0, 2.2 * r0))
    else:
        d["offset"] = draw(st.floats(-0.3 * r0, 0.3 * r0))
    return cam_from_dict(d, "random")


@settings(max_examples=8, derandomize=True, deadline=None)
@given(cams())
def test_random_cam_geometry(cam):
    fi = findings(cam)
    prof = profile(cam, grid(cam, 0.05))
    line = shapely.LineString(np.vstack([prof.theoretical, prof.theoretical[:1]]))
    coarse = profile(cam, grid(cam, 3.0))
    d = shapely.distance(shapely.points(coarse.actual), line)
    if not fi.undercut:
        assert np.allclose(d, cam.roller, atol=1e-5 * cam.base_radius)
    assert np.all(np.isfinite(coarse.pressure_angle)) and np.all(coarse.pressure_angle < math.pi / 2)
    br = min_base_radius(cam)
    if br.min_base_radius is None:  # a rocker whose arm and pivot admit no base radius
        assert cam.follower == "oscillating"
        for r in np.linspace(abs(cam.pivot - cam.arm), cam.pivot + cam.arm, 12)[1:-1]:
            f = findings(replace(cam, base_radius=float(r)))
            assert f.max_pressure_rise > cam.alpha_rise or f.max_pressure_return > cam.alpha_return
        return
    at = findings(replace(cam, base_radius=br.min_base_radius))
    excess = max(at.max_pressure_rise - cam.alpha_rise, at.max_pressure_return - cam.alpha_return)
    assert -math.radians(0.05) <= excess <= 1e-9
