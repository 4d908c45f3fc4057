"""The gear sheets read back as a draftsman reads them, against values worked out here from the
teeth and the speeds (not from the drawing's construction): the contact ratio measured on the
drawn line of action of every meshing (its field grown to fill the sheet) against the closed
form, every tooth the grown field shows drawn, and the train's speeds read off its plans at
the scales they are written with against Willis worked by hand."""

from __future__ import annotations

import math
import re
from pathlib import Path

import pytest
import shapely

from drawings.gears import draw
from plans.gears.model import load_gears
from plans.gears.solve import solve_gears
from plans.kinematics.scales import is_round

ROOT = Path(__file__).resolve().parents[1]
SAMPLES = [ROOT / "samples" / "gears" / f"{n}.toml" for n in ("planetary_2kh", "seed_train")]


def _number(text: str) -> float:
    """The first number of a written scale (a decimal comma on a Russian sheet)."""
    found = re.search(r"\d+(?:[.,]\d+)?", text)
    assert found is not None, text
    return float(found.group().replace(",", "."))


def _scale(panel) -> str:
    return next(q.label.plain for q in panel.prims if q.op == "text" and q.eid == f"{panel.pid}-scale")


def _enlargement(panel) -> float:
    """M 10:1 -> 10, M 1:2 -> 0.5."""
    a, b = _scale(panel).split()[-1].split(":")
    return float(a) / float(b)


def _prim(panel, eid: str):
    return next(q for q in panel.prims if q.eid == eid)


def _arrow(panel, eid: str) -> float:
    """A vector's drawn length: its shaft starts at the tail, its head's first point is the tip."""
    i = next(k for k, q in enumerate(panel.prims) if q.op == "begin" and q.eid == eid)
    line = next(q for q in panel.prims[i + 1:] if q.op == "line")
    head = next(q for q in panel.prims[i + 1:i + 4] if q.op == "polygon")
    return math.dist(line.pts[0], head.pts[0])


@pytest.fixture(scope="module", params=[(p, lang) for p in SAMPLES for lang in ("ru", "en")],
                ids=lambda t: f"{t[0].stem}-{t[1]}")
def drawn(request):
    path, lang = request.param
    return path, solve_gears(load_gears(path)), draw(path, format="A1", language=lang)


def test_contact_ratio_measured_on_each_drawn_meshing_is_the_closed_form(drawn):
    """B1B2 as drawn on the sheet over the base pitch π m cos α at the written enlargement is
    ε = (√(r_a1² − r_b1²) ± √(r_a2² − r_b2²) ∓ a_w sin α_w) / (π m cos α), to a thousandth."""
    _, sol, d = drawn
    panels = [p for p in d.panels if p.pid.startswith("meshing-")]
    assert len(panels) == len(sol.drawn_pairs())
    for panel, pair in zip(panels, sol.drawn_pairs(), strict=True):
        k = _enlargement(panel)
        line = _prim(panel, "B1B2")
        p_b = math.pi * pair.m * 1e3 * math.cos(pair.alpha) * k
        w1, w2 = pair.wheels
        t1 = math.sqrt(w1.tip**2 - w1.base**2)
        t2 = math.sqrt(w2.tip**2 - w2.base**2)
        s = pair.a_w * math.sin(pair.alpha_w)
        exact = (t1 - t2 + s if pair.internal else t1 + t2 - s) / (math.pi * pair.m * math.cos(pair.alpha))
        assert math.dist(*line.pts) / p_b == pytest.approx(exact, abs=1e-3)
        assert exact == pytest.approx(pair.contact_ratio, rel=1e-12)


def test_every_tooth_the_grown_field_shows_is_drawn(drawn):
    """Each wheel's tip circle, wherever it crosses the meshing's field, runs within 0.6 of a
    pitch of the drawn teeth (over a space it is half a space from a flank; a tooth left out
    leaves a pitch and more), the wheels' centres placed from P by the working radii."""
    _, sol, d = drawn
    for panel, pair in zip([p for p in d.panels if p.pid.startswith("meshing-")], sol.drawn_pairs(), strict=True):
        k = _enlargement(panel)
        xs, ys = zip(*_prim(panel, "field").pts, strict=True)
        field = shapely.box(min(xs) + 1.0, min(ys) + 1.0, max(xs) - 1.0, max(ys) - 1.0)
        px, py = _prim(panel, "point-P").pts[0]
        w1, w2 = pair.wheels
        centres = {w1.name: (px, py + w1.working * 1e3 * k),  # paper y grows downward
                   w2.name: (px, py + (1.0 if pair.internal else -1.0) * w2.working * 1e3 * k)}
        for w in pair.wheels:
            teeth = shapely.MultiLineString([q.pts for q in panel.prims
                                             if q.op == "polyline" and q.eid.startswith(f"wheel-{w.name}-teeth")])
            cx, cy = centres[w.name]
            r = w.tip * 1e3 * k
            ring = [shapely.Point(cx + r * math.cos(t), cy + r * math.sin(t))
                    for t in (2 * math.pi * j / 3600 for j in range(3600))]
            seen = [q for q in ring if field.contains(q)]
            assert seen
            assert max(teeth.distance(q) for q in seen) <= 0.6 * math.pi * pair.m * 1e3 * k, (panel.pid, w.name)


def _willis_by_hand(path: Path) -> dict[str, float]:
    """The shafts' ω (rad/s) worked out from the numbers of teeth alone."""
    if path.stem == "planetary_2kh":  # sun 1 (1450 rpm), planets 2 on carrier H, ring 3 held
        z1, z2, z3 = 20, 25, 70
        w1 = 1450 * math.pi / 30
        wh = w1 * z1 / (z1 + z3)
        return {"1": w1, "2": wh - (w1 - wh) * z1 / z2, "3": 0.0, "H": wh}
    z1, z2, z3 = 26, 14, 46  # seed_train: 1 (650 rpm) drives the idler 2, which drives 3
    w1 = 650 * math.pi / 30
    return {"1": w1, "2": -w1 * z1 / z2, "3": w1 * z1 / z3}


def test_speeds_read_off_the_plans_at_their_written_scales(drawn):
    """The plan of linear velocities' vectors over its written μ_v are ω r of the pitch points
    (and the planets' axis); its points' heights over the scheme's written μ_l are the radii;
    the plan of angular velocities' intercepts over its written μ_ω are Willis's ω, its rays
    parallel to the plan's lines; every one of the three scales round."""
    path, sol, d = drawn
    scheme, plan, rays = (next(p for p in d.panels if p.pid == pid)
                          for pid in ("train-scheme", "velocity-plan", "ray-diagram"))
    mu_l, mu_v, mu_w = (_number(_scale(p)) for p in (scheme, plan, rays))
    assert all(is_round(m) for m in (mu_l, mu_v, mu_w))
    omega = _willis_by_hand(path)
    a_w = {p.gears: p.a_w for p in sol.pairs}
    if path.stem == "planetary_2kh":
        r1, a = 0.020, 0.045  # m z1 / 2 and the carrier's arm, unshifted
        want = {"P_{12}": omega["1"] * r1, "O_2": omega["H"] * a}
        heights = {"P_{12}": r1, "O_2": a}
    else:
        z1, z2, z3 = 26, 14, 46
        r12, r23 = a_w[("1", "2")] * z1 / (z1 + z2), a_w[("2", "3")] * z2 / (z2 + z3)
        want = {"P_{12}": omega["1"] * r12, "P_{23}": abs(omega["2"]) * r23}
        heights = {"P_{12}": r12, "P_{23}": a_w[("1", "2")] + r23}
    for name, v in want.items():
        assert _arrow(plan, f"v-{name}") / mu_v == pytest.approx(abs(v), rel=1e-6), name
    base = _prim(plan, "pt-O_1").pts[0][1]
    for name, r in heights.items():
        assert abs(_prim(plan, f"pt-{name}").pts[0][1] - base) / mu_l == pytest.approx(r, rel=1e-6), name
    pole = _prim(rays, "pole").pts[0]
    for n, w in omega.items():
        at = _prim(rays, f"omega-{n}").pts[0]
        assert (at[0] - pole[0]) / mu_w == pytest.approx(w, rel=1e-6, abs=1e-9), n
        ray = (at[0] - pole[0], at[1] - pole[1])
        (x0, y0), (x1, y1) = _prim(plan, f"line-{n}").pts
        line = (x1 - x0, y1 - y0)
        assert abs(ray[0] * line[1] - ray[1] * line[0]) <= 1e-9 * math.hypot(*ray) * math.hypot(*line), n
