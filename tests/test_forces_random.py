"""Random well-conditioned mechanisms and loads: groups vs one global solve, three ways."""

from __future__ import annotations

import numpy as np
from hypothesis import assume, given, settings
from hypothesis import strategies as st

from plans.forces.lever import zhukovsky_lever
from plans.forces.loads import parse_loads
from plans.forces.polygons import analyse_forces
from plans.kinematics.exact import solve
from plans.kinematics.placing import scene_from_dict

from .conftest import four_bar_scene, slider_crank_scene
from .test_forces import _global_reactions, _largest

masses = st.floats(0.1, 5.0)
inertias = st.one_of(st.just(0.0), st.floats(1e-12, 0.05))  # 0 or at least 1e-12: the number rule


def _file_number(x: float) -> float:
    """x as a file may give it: 0 or a magnitude of at least 1e-12 (the number rule)."""
    return 0.0 if abs(x) < 1e-12 else x


forces = st.floats(-500.0, 500.0).map(_file_number)


def _check(scene):
    kin = solve(scene, order=2)
    fa = analyse_forces(scene, kin, parse_loads(scene))
    lv = zhukovsky_lever(fa)
    big = _largest(fa)
    x = _global_reactions(fa, 0)
    by_joint = {rc.joint.name: rc for rc in fa.reactions()}
    for c, jt in enumerate(scene.joints):
        rc = by_joint[jt.name]
        if jt.kind == "R":
            sign = 1.0 if rc.on == jt.links[0] else -1.0
            assert abs(sign * complex(rc.F[0]) - complex(x[2 * c], x[2 * c + 1])) < 1e-8 * big
        else:
            sign = 1.0 if rc.on == jt.slider else -1.0
            assert abs(sign * float(rc.N[0]) - x[2 * c]) < 1e-8 * big
    bal = fa.balancing
    assert abs(float(lv.signed(lv.by_lever)[0] - bal[0])) < 1e-8 * big
    assert abs(float(lv.signed(lv.by_power)[0] - bal[0])) < 1e-8 * big


@settings(max_examples=40, deadline=None)
@given(r=st.floats(20, 80), ratio=st.floats(2.5, 5.0), e=st.floats(-0.3, 0.3), phi=st.floats(0, 360),
       omega=st.floats(1, 300), eps=st.floats(-100, 100), sense=st.sampled_from(["ccw", "cw"]),
       m2=masses, i2=inertias, m3=masses, fx=forces, fy=forces, grav=st.booleans())
def test_random_slider_crank(r, ratio, e, phi, omega, eps, sense, m2, i2, m3, fx, fy, grav):
    raw = slider_crank_scene(r, ratio * r, e * r, phi_deg=(phi,), omega=omega, eps=eps, sense=sense,
                             outputs=("lever",))
    raw["links"]["2"].update(mass=m2, inertia=i2, centre="S2")
    raw["links"]["3"].update(mass=m3)
    raw["loads"] = {"gravity": grav, "force": [{"link": 3, "point": "B", "vector": [fx, fy]}],
                    "moment": [{"link": 2, "value": _file_number(fy / 100)}]}
    _check(scene_from_dict(raw))


@settings(max_examples=40, deadline=None)
@given(phi=st.floats(0, 360), omega=st.floats(1, 100), m2=masses, i2=inertias, m3=masses, i3=inertias,
       fx=forces, fy=forces, kind=st.sampled_from(["force", "moment"]))
def test_random_four_bar(phi, omega, m2, i2, m3, i3, fx, fy, kind):
    raw = four_bar_scene(phi_deg=(phi,), omega=omega, outputs=("lever",))
    kin = solve(scene_from_dict(raw), order=0)
    A, B, D = (complex(kin.point(nm)[0][0]) for nm in "ABD")
    assume(abs(np.sin(np.angle((B - A) / (B - D)))) > 0.1)  # away from the locking positions
    raw["links"]["2"].update(mass=m2, inertia=i2, centre="E")
    raw["links"]["3"]["points"] = {"S3": {"ratio": 0.5}}
    raw["links"]["3"].update(mass=m3, inertia=i3, centre="S3")
    raw["loads"] = {"balancing": {"kind": kind}, "force": [{"link": 2, "point": "E", "vector": [fx, fy]}],
                    "moment": [{"link": 3, "resisting": _file_number(abs(fx) / 50)}]}
    _check(scene_from_dict(raw))
