"""s(φ) of a slider measured from its extreme position, s ≥ 0, as the course measures it
(``[diagrams] s_from``, default "extreme"; "first" keeps the signed guide coordinate).

Oracles: the stroke in closed form (H = √((l + r)² − e²) − √((l − r)² − e²) for an offset
slider-crank), the exact positions alone (s is the distance along the guide from the
position where s vanishes, which is a turning point of the slider), and the derivative:
v(φ) = ω ds/dφ by central differences of s.
"""

from __future__ import annotations

import math

import numpy as np
import pytest

from plans.cycle.diagrams import diagrams
from plans.errors import InputError
from plans.io import read_toml
from plans.kinematics.placing import scene_from_dict

from .conftest import ROOT


def _scene(**dia):
    data = read_toml(ROOT / "samples" / "offset_slider_crank.toml")
    data["outputs"] = ["positions", "velocity_plan", "acceleration_plan", "diagrams"]
    data["diagrams"] = {"points": ["B"], "positions": 12, **dia}
    return scene_from_dict(data, "offset_slider_crank.toml")


def test_s_from_the_extreme_is_nonnegative_up_to_the_stroke():
    scene = _scene()
    d = diagrams(scene)
    s = d.get("s_B")
    r, l, e = 0.05, 0.18, 0.02
    H = math.sqrt((l + r) ** 2 - e**2) - math.sqrt((l - r) ** 2 - e**2)
    assert float(np.min(s.exact)) >= 0.0
    # sampled every degree: the top within (0.5°)² of the curvature, never above the stroke
    assert H * (1 - 1e-5) < float(np.max(s.exact)) <= H * (1 + 1e-12)
    # s vanishes where the slider turns back, at the start of its slow (working) stroke
    k0 = int(np.argmin(s.exact))
    assert s.exact[k0] < 1e-5 * H  # sampled every degree
    from plans.kinematics.extreme import slider, strokes

    st = strokes(scene, output=slider(scene, "B"))
    assert st.K > 1
    phi = np.asarray(s.exact_phi_deg, float)
    gap = abs((phi[k0] - st.working_deg + 180) % 360 - 180)
    assert gap <= 360 / len(phi) + 1e-9


def test_v_is_the_derivative_of_s_from_the_extreme():
    scene = _scene()
    d = diagrams(scene)
    s, v = d.get("s_B"), d.get("v_B")
    phi = np.radians(np.asarray(s.exact_phi_deg, float))
    h = phi[1] - phi[0]
    ds = (s.exact[2:] - s.exact[:-2]) / (2 * h) * d.omega
    inner = (s.exact[1:-1] > 1e-4)  # away from the extreme, where the clip at 0 could bite
    np.testing.assert_allclose(ds[inner], v.exact[1:-1][inner], rtol=0, atol=2e-3 * float(np.max(np.abs(v.exact))))


def test_s_from_the_first_position_keeps_the_signed_coordinate():
    new, old = diagrams(_scene()).get("s_B"), diagrams(_scene(s_from="first")).get("s_B")
    assert old.exact[0] == 0.0 and float(np.min(old.exact)) < 0  # signed, from the first position
    # the same motion: the two differ by a constant and, perhaps, the direction
    diff_same = np.ptp(new.exact - old.exact)
    diff_flip = np.ptp(new.exact + old.exact)
    assert min(diff_same, diff_flip) < 1e-12
    with pytest.raises(InputError) as exc:
        diagrams(_scene(s_from="zero"))
    assert exc.value.field == "diagrams.s_from"
