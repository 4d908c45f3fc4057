"""The flywheel sample's kinematics sheet: the plans of velocity analogues beside the plan of
positions (none left for the dynamics sheet), each read back at the analogue scale written on
it against the crank's own analogue: v_A/ω1 = l_OA, perpendicular to the crank, turned with
its rotation."""

from __future__ import annotations

import math
import re
from pathlib import Path

import pytest

import drawings
from plans.io import read_toml

ROOT = Path(__file__).resolve().parents[1]
SAMPLE = ROOT / "samples" / "flywheel" / "turning_moment.toml"


def _plain(panel, eid: str) -> str:
    return next(p.label.plain for p in panel.prims if p.eid == eid and p.label is not None)


@pytest.mark.parametrize("language", ["en", "ru"])
def test_analogue_plans_beside_the_positions_read_back_at_their_written_scale(language):
    data = read_toml(SAMPLE)
    l_oa = data["links"]["1"]["length"] * 1e-3  # m
    d = drawings.draw(SAMPLE, language=language)
    first, second = d.sheets[0], d.sheets[1]
    assert not any(p.pid.startswith("analogue-") for p, _, _ in second.placed)
    plans = [p for p, _, _ in first.placed if p.pid.startswith("analogue-")]
    assert [p.pid for p, _, _ in first.placed if not p.pid.startswith("analogue-")] == ["positions"]
    assert len(plans) == data["driver"]["positions"]
    for panel in plans:
        mu = float(re.search(r"μ = ([0-9]+(?:[.,][0-9]+)?)", _plain(panel, f"{panel.pid}-note")).group(1)
                   .replace(",", "."))
        mant = mu / 10 ** math.floor(math.log10(mu))
        assert any(math.isclose(mant, r) for r in (1.0, 2.0, 2.5, 4.0, 5.0))
        phi = math.radians(float(re.search(r"φ = (-?[0-9]+(?:[.,][0-9]+)?)°", _plain(panel, f"{panel.pid}-title"))
                                 .group(1).replace(",", ".")))
        i = next(k for k, p in enumerate(panel.prims) if p.op == "begin" and p.eid == f"{panel.pid}-v_A")
        (x0, y0), _ = panel.prims[i + 1].pts  # the shaft leaves the pole
        tip = panel.prims[i + 2].pts[0]  # the head's first point is the vector's end
        dx, dy = tip[0] - x0, -(tip[1] - y0)  # paper y down
        assert math.hypot(dx, dy) / mu == pytest.approx(l_oa, abs=0.01 / mu)  # to 0.01 mm
        sense = 1.0 if data["driver"]["sense"] == "ccw" else -1.0
        assert dx == pytest.approx(-sense * math.sin(phi) * l_oa * mu, abs=0.01)
        assert dy == pytest.approx(sense * math.cos(phi) * l_oa * mu, abs=0.01)
