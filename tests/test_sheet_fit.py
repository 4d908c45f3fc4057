"""Small sheets: a drawing that does not fit A4 or A3 at the A1 scales is drawn at smaller round
scales (the scales written on it changed with them) or split over sheets, never refused."""

from __future__ import annotations

import itertools
from pathlib import Path

import pytest
import shapely

from drawings.linkage import draw
from drawings.paper.sheet import usable
from plans.kinematics.placing import load_scene
from plans.kinematics.scales import is_round
from plans.solution import solve
from tests.locales import in_russian

#: The sheets these tests measure were drawn in Russian, the default before it followed the locale.
draw = in_russian(draw)

ROOT = Path(__file__).resolve().parents[1]
SAMPLES = sorted((ROOT / "samples").glob("*.toml"))


@pytest.mark.parametrize("fmt", ["A4", "A3"])
@pytest.mark.parametrize("path", SAMPLES, ids=[p.stem for p in SAMPLES])
def test_every_sample_draws_on_a_small_sheet(path, fmt):
    """Every sample on A4 and A3 (A1: tests/test_drawings_samples.py): every panel inside the
    frame, clear of the title block and of every other panel."""
    d = draw(path, format=fmt)
    assert d.sheets
    for sh in d.sheets:
        assert_clear(sh)


def assert_clear(sh) -> None:
    """Every panel of a sheet inside the frame, clear of the title block and of the others."""
    a = usable(sh.width, sh.height)
    boxes = [(p.pid, (x, y, x + p.width, y + p.height)) for p, x, y in sh.placed]
    for pid, b in boxes:
        assert a[0] - 1e-6 <= b[0] and a[1] - 1e-6 <= b[1] and b[2] <= a[2] + 1e-6 and b[3] <= a[3] + 1e-6, pid
        assert not shapely.box(*b).intersects(shapely.box(*sh.title_box)), pid
    for (p, b), (q, c) in itertools.combinations(boxes, 2):
        assert shapely.box(*b).intersection(shapely.box(*c)).area < 1e-6, (p, q)


def _plans(d) -> dict[str, object]:
    return {p.pid: p for sh in d.sheets for p, _, _ in sh.placed}


def test_plans_too_big_for_a4_are_drawn_at_smaller_round_scales(tmp_path):
    """The shaper's acceleration plan at φ = 180° does not fit A4 at A4's own fit: the scene is
    solved again at a smaller fit, and every plan is drawn at a round scale smaller than the
    A4 fit's, the one written on the panel."""
    path = tmp_path / "shaper.toml"
    path.write_text((ROOT / "samples" / "shaper.toml").read_text(encoding="utf-8")
                    + '\n[sheet]\npanels = { acceleration = [1, 7], forces = "none", lever = "none" }\n',
                    encoding="utf-8")
    scene = load_scene(path)
    at_fit = solve(scene, fit=scene.sheet_for(format="A4").fit)
    before = {float(pp.acceleration.phi_deg): pp.acceleration.scale for pp in at_fit.plans}
    d = draw(path, format="A4")
    panels = _plans(d)
    acc = {p.phi: p.scale for p in panels.values() if p.kind == "acceleration"}
    assert acc and all(is_round(mu) for mu in acc.values())
    assert acc[180.0] < before[180.0]  # smaller than it was: it fits now
    for pid, p in panels.items():
        if p.quantity in ("velocity", "acceleration") and p.kind in ("velocity", "acceleration"):
            text = " ".join(t.label.plain for t in p.prims if t.op == "text" and t.label is not None)
            assert any(f"= {x:g} ".replace(".", ",") in text for x in (p.scale, 1.0 / p.scale)), pid


def test_a_table_too_tall_for_a4_is_split_into_parts(tmp_path):
    """The V-engine's table of readings at 45° (146 × 144 mm) is too tall for A4: it is drawn
    in two parts, the second "(продолжение)", holding the whole table's rows between them."""
    d = draw(ROOT / "samples" / "v_engine.toml", format="A4")
    panels = _plans(d)
    parts = sorted(pid for pid in panels if pid.startswith("table-45"))
    assert parts == ["table-45", "table-45-2"]
    assert panels["table-45-2"].title.endswith("(продолжение)")

    def rows(p) -> list[str]:
        return [t.eid for t in p.prims if t.op == "begin" and t.cls == "row"]

    whole = draw(ROOT / "samples" / "v_engine.toml")
    full = next(p for p in whole.panels if p.pid == "table-45")
    got = rows(panels["table-45"]) + rows(panels["table-45-2"])
    assert [r.replace("table-45-2-", "table-45-") for r in got] == rows(full)


def test_the_energy_mass_diagram_is_drawn_smaller_on_a4():
    """The Wittenbauer diagram of a 48-position engine (149 × 130 mm at its readable A1 size)
    does not fit A4 beside the title block: on A4 it is drawn at smaller round scales (the
    ones written on it, read back off the curve drawn), its position numbers still 2.5 mm and
    every position numbered."""
    import re

    from drawings.cycle import fitting_dynamics
    from drawings.cycle.dynamics_diagrams import w_panel
    from drawings.paper.sheet import fits_empty

    scene = load_scene(ROOT / "samples" / "single_four_stroke.toml")
    from tests.locales import locale

    with locale("ru_RU.UTF-8"):  # the scales read back in the Russian words they were written in
        spec = scene.sheet_for(format="A4")
    sol = solve(scene, fit=spec.fit)
    d = sol.cycle.dynamics
    assert not fits_empty(w_panel(d, "ru"), "A4", spec.orientation)
    w = next(p for p in fitting_dynamics(sol, d, sol.cycle.tables[-4:], spec) if p.pid == "dyn-W")
    assert fits_empty(w, "A4", spec.orientation)
    text = " ".join(t.label.plain for t in w.prims if t.op == "text" and t.label is not None)
    mu_T, mu_I = (float(re.search(rf"μ{q} = ([\d,]+) ", text).group(1).replace(",", ".")) for q in ("T", "I"))
    full = " ".join(t.label.plain for t in w_panel(d, "ru").prims if t.op == "text" and t.label is not None)
    mu_T1 = float(re.search(r"μT = ([\d,]+) ", full).group(1).replace(",", "."))
    assert is_round(mu_T) and is_round(mu_I) and mu_T < mu_T1
    curve = next(p for p in w.prims if p.eid == "dyn-W-curve")
    xs = [x for x, _ in curve.pts]
    ys = [y for _, y in curve.pts]
    wb = d.wittenbauer
    assert max(xs) - min(xs) == pytest.approx(mu_I * (max(wb.I) - min(wb.I)), rel=1e-9)
    assert max(ys) - min(ys) == pytest.approx(mu_T * (max(wb.dT) - min(wb.dT)), rel=1e-9)
    ticks = [t.label for t in w.prims if t.op == "text" and t.eid.startswith("dyn-W-n-")]
    assert min(r.size for lab in ticks for r in lab.runs) >= 2.5
    numbered = {int(n) for lab in ticks for n in lab.plain.split(", ")}
    assert numbered == set(range(1, len(d.table.phi_deg)))
