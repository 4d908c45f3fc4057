"""The balancing sheet's diagrams over a turn read back at the scales written on them, against
the inertia forces and moments in closed form from the engine file's own numbers; every scale
written on a balancing sheet a round one."""

from __future__ import annotations

import math
import re
from pathlib import Path

import numpy as np
import pytest

from drawings.balancing import draw
from plans.io import read_toml

ROOT = Path(__file__).resolve().parents[1]
ENGINES = sorted((ROOT / "samples" / "engines").glob("*.toml"))
ROUND = (1.0, 2.0, 2.5, 4.0, 5.0)


def _omega(data: dict) -> float:
    return data["omega_rpm"] * math.pi / 30.0


def _text(panel, eid: str) -> str:
    return next(p.label.plain for p in panel.prims if p.eid == eid and p.label is not None)


def _number(text: str, after: str) -> float:
    m = re.search(re.escape(after) + r" = ([0-9]+(?:[.,][0-9]+)?)", text)
    assert m, (after, text)
    return float(m.group(1).replace(",", "."))


def _origin(panel, eid: str) -> tuple[float, float]:
    """The start of an arrow (its group's first line): the diagram's origin on its x axis."""
    i = next(k for k, p in enumerate(panel.prims) if p.op == "begin" and p.eid == eid)
    return panel.prims[i + 1].pts[0]


def _read(panel, row: str, side: str = "vertical") -> tuple[np.ndarray, np.ndarray, float]:
    """A row's curve read off the paper: crank angle (°) at the panel's μ_α and value at the
    row's μ, both as written; and the row's μ."""
    pid = panel.pid
    mu_alpha = _number(_text(panel, f"{pid}-scale"), "μα")  # subscripts drop their marks in plain text
    k = _number(_text(panel, f"{pid}-{row}-scale"), "μR" if pid.endswith("force") else "μM")
    x0, y0 = _origin(panel, f"{pid}-{row}-xaxis")
    curve = next(p for p in panel.prims if p.eid == f"{pid}-{row}-{side}")
    pts = np.array(curve.pts)
    return (pts[:, 0] - x0) * mu_alpha, -(pts[:, 1] - y0) * k, k


def test_inline4_second_order_force_read_back_against_four_cylinders_in_phase():
    """Inline four, cranks 0-180-180-0: the second-order forces of all four cylinders add,
    4 m_j r ω² λ cos 2α along the cylinders; the first order and every moment balance."""
    path = ROOT / "samples" / "engines" / "inline4.toml"
    data = read_toml(path)
    d = draw(path, language="en")
    panel = next(p for p in d.panels if p.pid == "turn-force")
    assert not any(p.pid == "turn-moment" for p in d.panels)
    a, F, k = _read(panel, "second_order")
    P2 = data["m_rec"] * data["r"] * 1e-3 * _omega(data) ** 2 * data["lambda"]
    assert len(a) > 100 and a.min() == pytest.approx(0.0, abs=1e-9) and a.max() == pytest.approx(360.0)
    expected = 4 * P2 * np.cos(2 * np.radians(a))
    assert np.max(np.abs(F - expected)) <= 1e-6 * 4 * P2
    assert 4 * P2 / k <= 100.0  # drawn within its row, at its round scale
    assert not any(p.eid == "turn-force-second_order-horizontal" for p in panel.prims)  # along the cylinders


def test_v6_rotating_moment_read_back_against_the_throws():
    """The 90° V6 on three pins: the rotating masses of both cylinders on a throw, at arms
    −l_c, 0, l_c; the moment of their vertical forces Σ 2 m_r r ω² l_i cos(α + β_i) and of
    their horizontal ones Σ 2 m_r r ω² l_i sin(α + β_i)."""
    path = ROOT / "samples" / "engines" / "v6_90.toml"
    data = read_toml(path)
    d = draw(path, language="en")
    panel = next(p for p in d.panels if p.pid == "turn-moment")
    P = 2 * data["m_rot"] * data["r"] * 1e-3 * _omega(data) ** 2
    throws = [(math.radians(c["crank_deg"]), (c["z"] - data["reference_z"]) * 1e-3) for c in data["cylinders"][:3]]
    for side, f in (("vertical", np.cos), ("horizontal", np.sin)):
        a, M, _ = _read(panel, "rotating", side)
        expected = sum(P * arm * f(np.radians(a) + beta) for beta, arm in throws)
        assert np.max(np.abs(M - expected)) <= 1e-6 * P * 0.1 * math.sqrt(3)


def test_the_turn_diagrams_share_one_alpha_axis():
    """The rows of a diagram over a turn stand in one column: one x origin, one axis length."""
    d = draw(ROOT / "samples" / "engines" / "v6_90.toml", language="en")
    panel = next(p for p in d.panels if p.pid == "turn-moment")
    rows = [p.eid[len("turn-moment-"):-len("-xaxis")] for p in panel.prims
            if p.op == "begin" and p.eid.startswith("turn-moment-") and p.eid.endswith("-xaxis")]
    assert rows == ["rotating", "first_order", "second_order", "sum"]
    xs = {round(_origin(panel, f"turn-moment-{r}-xaxis")[0], 9) for r in rows}
    assert len(xs) == 1
    ends = {round(_read(panel, r)[0].max(), 9) for r in rows}
    assert ends == {360.0}


@pytest.mark.parametrize("path", ENGINES, ids=[p.stem for p in ENGINES])
def test_every_scale_on_a_balancing_sheet_is_round(path):
    """μ of the polygons (mm per unit), of the diagrams over a turn (N or N·m per mm), μ_α and
    the counterweights' μ_mr are 1, 2, 2.5, 4 or 5 × 10^k; the crankshaft at a GOST 2.302
    scale, written."""
    d = draw(path, language="en")
    texts = [p.label.plain for sh in d.sheets for pan, _, _ in sh.placed for p in pan.prims
             if p.op == "text" and p.label is not None]
    found = 0
    for t in texts:
        for m in re.finditer(r"μ[A-Za-zα]* = ([0-9]+(?:\.[0-9]+)?)", t):
            v = float(m.group(1))
            mant = v / 10 ** math.floor(math.log10(v))
            assert any(math.isclose(mant, r, rel_tol=1e-9) for r in ROUND), t
            found += 1
    assert found >= 6
    assert any(re.fullmatch(r"Scale (1:(1|2|2\.5|4|5|10|15|20|25|40|50)|(2|2\.5|4|5|10):1)", t) for t in texts)


def test_v6_first_order_counterweights_read_back_at_their_written_scale():
    """Two counterweights take the V6's first-order moment (a circle turning with the crank):
    each √3 m_j r l_c over the planes' spacing, drawn as m·r at the end view's written μ_mr."""
    path = ROOT / "samples" / "engines" / "v6_90.toml"
    data = read_toml(path)
    d = draw(path, language="en")
    panel = next(p for p in d.panels if p.pid == "counterweights")
    k = _number(_text(panel, "counterweights-scale"), "μmr")
    first = [i for i, c in enumerate(d.balance.counterweights) if c.of == "first_order"]
    assert len(first) == 2
    expected = math.sqrt(3) * data["m_rec"] * data["r"] * 1e-3 * 0.1 / 0.2
    for i in first:
        j = next(n for n, p in enumerate(panel.prims) if p.op == "begin" and p.eid == f"cw-{i}")
        start = panel.prims[j + 1].pts[0]
        tip = panel.prims[j + 2].pts[0]
        assert math.dist(start, tip) * k == pytest.approx(expected, abs=0.01 * k)  # to 0.01 mm
