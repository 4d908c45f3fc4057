"""The drawing's legibility: the extreme positions and θ against closed forms, one numbering of
the positions on every panel, the energy–mass diagram readable and every point of it numbered."""

from __future__ import annotations

import math
import re
from pathlib import Path

import pytest

from plans.errors import InputError
from plans.kinematics.placing import load_scene
from plans.solution import solve
from tests.locales import in_russian

ROOT = Path(__file__).resolve().parents[1]
SAMPLES = ROOT / "samples"


def _strokes(name: str):
    made = solve(SAMPLES / f"{name}.toml").strokes()
    assert made is not None
    return made


def test_offset_slider_crank_extremes_drawn_where_theta_is_the_closed_form():
    """What the plan of positions draws: θ = asin(e/(l2 − l1)) − asin(e/(l2 + l1)) (l1 = 50,
    l2 = 180, e = 20 mm); at both extremes the crank pin, the rod and the slider in one line
    and the slider at rest (the exact analysis at the drawn angles)."""
    from plans.kinematics.exact import solve as exact

    st, at = _strokes("offset_slider_crank")
    assert st.output.kind == "slider" and st.output.point == "B"
    l1, l2, e = 50.0, 180.0, 20.0
    theta = math.degrees(math.asin(e / (l2 - l1)) - math.asin(e / (l2 + l1)))
    assert st.theta_deg == pytest.approx(theta, abs=1e-9)
    assert st.K == pytest.approx((180 + theta) / (180 - theta), rel=1e-12)
    scene = load_scene(SAMPLES / "offset_slider_crank.toml")
    v = exact(scene, [st.working_deg, st.idle_deg], order=1).point("B")[1]
    for j in range(2):
        A = complex(at.point("A")[0][j])
        B = complex(at.point("B")[0][j])
        assert abs((A.conjugate() * B).imag) <= 1e-9 * abs(A) * abs(B)  # O at the origin
        assert abs(complex(v[j])) <= 1e-9 * abs(scene.driver.omega) * 0.05


def test_four_bar_extremes_drawn_by_the_law_of_cosines():
    """Crank-rocker a = 80, b = 260, c = 200, d = 300 mm: at the extremes OB = b ± a, and the
    crank's angle is the angle at O of the triangle O-D-B (B above OD)."""
    st, at = _strokes("four_bar")
    assert st.output.kind == "rocker"
    a, b, c, d = 80.0, 260.0, 200.0, 300.0

    def at_O(ob: float) -> float:
        return math.degrees(math.acos((d * d + ob * ob - c * c) / (2 * d * ob)))

    out, back = at_O(b + a), at_O(b - a)  # crank along OB, and opposite to it
    assert sorted([st.working_deg, st.idle_deg]) == pytest.approx(sorted([out, back + 180.0]), abs=1e-9)
    assert st.theta_deg == pytest.approx(back - out, abs=1e-9)
    OB = sorted(abs(complex(at.point("B")[0][j])) for j in range(2))  # the mechanism drawn there, m
    assert OB == pytest.approx([(b - a) / 1000, (b + a) / 1000], abs=1e-12)


def test_central_slider_crank_has_equal_strokes_and_no_theta():
    st, _ = _strokes("slider_crank")
    assert st.theta_deg == pytest.approx(0.0, abs=1e-9) and st.K == pytest.approx(1.0, abs=1e-12)


def test_first_position_key_is_checked(tmp_path):
    text = (SAMPLES / "slider_crank.toml").read_text(encoding="utf-8")
    bad = tmp_path / "bad.toml"
    bad.write_text(text + '\n[sheet]\nfirst_position = 2\n', encoding="utf-8")
    with pytest.raises(InputError, match="first_position"):
        load_scene(bad).sheet_for()


def _all_panels(d):
    seen = {p.pid: p for p in d.panels}
    for sh in d.sheets:
        for p, _x, _y in sh.placed:
            seen.setdefault(p.pid, p)
    return list(seen.values())


def _texts(panel, prefix: str = "") -> list[str]:
    return [q.label.plain for q in panel.prims if q.op == "text" and q.label is not None and q.eid.startswith(prefix)]


@pytest.mark.parametrize("first", [1, 0])
def test_one_numbering_on_the_plans_the_plan_of_positions_and_the_cycle(tmp_path, first):
    """Position k (0-based in JSON) is labelled k + first_position on every panel: the block
    headings, the plan of positions, the cycle's axes and tables, the energy–mass diagram."""
    from drawings.linkage import draw

    scene = tmp_path / "dyn.toml"
    text = (SAMPLES / "dynamics_slider_crank.toml").read_text(encoding="utf-8")
    text += '\n[sheet]\nset = "positions"\n' + ("first_position = 0\n" if first == 0 else "")  # headed blocks
    scene.write_text(text, encoding="utf-8")
    d = in_russian(draw)(scene)
    panels = {p.pid: p for p in _all_panels(d)}
    n = len(d.scene.driver.phis_deg)
    want = [str(k + first) for k in range(n)]
    headings = [q.label.plain for sh in d.sheets for q in sh.prims if q.op == "text" and q.label is not None
                and q.label.plain.startswith("Положение ")]
    got = sorted({int(re.match(r"Положение (\d+),", h).group(1)) for h in headings})
    assert got[0] == first and set(got) <= {k + first for k in range(n)}
    # the plan of positions: the crank pin's numbers, its letter at the first position
    pos = _texts(panels["positions"], "positions-n-B-")  # the crank AB's pin
    nums = {x.strip() for t in pos for x in t.split(",")}
    assert f"B{first}" in nums and {str(k + first) for k in range(1, n)} <= nums
    # the cycle: the table's head and the energy–mass diagram's labels
    table = next(p for pid, p in panels.items() if pid.startswith("dyn-table-"))
    cells = _texts(table)
    head = cells.index("№ положения")
    assert cells[head + 1:head + 1 + min(n, 12)] == want[:min(n, 12)]
    w = {x.strip() for t in _texts(panels["dyn-W"], "dyn-W-n-") for x in t.split(",")}
    assert w == set(want)


def test_energy_mass_diagram_readable_every_point_numbered():
    """The Wittenbauer diagram at least 120 × 90 mm, every position numbered once, labels
    at GOST's 2.5 mm."""
    from drawings.linkage import draw

    d = in_russian(draw)(SAMPLES / "dynamics_slider_crank.toml")
    w = next(p for p in _all_panels(d) if p.pid == "dyn-W")
    curve = next(q for q in w.prims if q.eid == "dyn-W-curve")
    xs = [x for x, _ in curve.pts]
    ys = [y for _, y in curve.pts]
    assert w.width >= 120 and w.height >= 90
    assert max(ys) - min(ys) >= 60  # the closed curve itself, not only the panel, is tall enough
    assert max(xs) >= 100
    labels = [q for q in w.prims if q.op == "text" and q.eid.startswith("dyn-W-n-")]
    numbers = sorted(int(x) for q in labels for x in q.label.plain.split(", "))
    assert numbers == list(range(1, len(d.scene.driver.phis_deg) + 1))
    assert all(r.size >= 2.5 for q in labels for r in q.label.runs)


OTHER_KINDS = ("gears", "cams", "engines", "synthesis", "flywheel")


@pytest.mark.parametrize("path", sorted(str(p.relative_to(SAMPLES)) for sub in OTHER_KINDS
                                        for p in (SAMPLES / sub).glob("*.toml")))
def test_letters_at_least_gost_2_5_mm_on_the_other_kinds(path):
    """Gear, cam, engine, synthesis, flywheel sheets: every letter at least 2.5 mm, indices 1.8."""
    import importlib

    from plans.kinds import KINDS, read_kind
    from tests.test_drawings_samples import gost_letters

    kind, _ = read_kind(str(SAMPLES / path))
    d = in_russian(importlib.import_module(KINDS[kind][1]).draw)(str(SAMPLES / path))
    for sh in d.sheets:
        assert gost_letters(sh.svg()) == [], (path, sh.number)


def test_gear_train_in_gost_symbols_at_round_scales():
    """The unfolded train: shafts thick, bearings on the frame, gears fixed by a cross, the
    planets free on the carrier's pin; μ_l and μ_v round; the scheme drawn larger than the
    engine's plan where the sheet has room."""
    from drawings.gears import draw
    from plans.kinematics.scales import is_round

    d = draw(SAMPLES / "gears" / "planetary_2kh.toml", language="ru")
    scheme = next(p for p in d.panels if p.pid == "train-scheme")
    ids = {q.eid for q in scheme.prims if q.eid}
    assert {"shaft-1", "shaft-H", "fix-1-a", "pin-bearing-2-top", "bearing-1-0-top", "bearing-H-top"} <= ids
    plan = d.solution.plan
    assert is_round(plan.mu_v) and is_round(plan.mu_l)
    scales = [q.label.plain for p in d.panels if p.pid in ("train-scheme", "velocity-plan") for q in p.prims
              if q.op == "text" and q.eid.endswith("-scale")]
    assert scales and all(is_round(float(s.split("=")[1].split()[0].replace(",", "."))) for s in scales)
    assert scheme.height > 200  # twice the engine's 1:1 on A1
    words = " ".join(q.label.plain for p in d.panels for q in p.prims if q.op == "text" and q.label)
    for leak in ("coaxiality", "assembly", "neighbourhood", ", mm"):
        assert leak not in words


@pytest.mark.parametrize(("name", "crowded"), [("whitworth", {"D"}), ("shaper", {"D", "E"})])
def test_overlapping_trajectories_never_share_bare_numbers(name, crowded):
    """Two pins' marks within 6 mm of each other (the coulisse's D on the crank circle's
    side, the rocker's end over the ram's guide): every such mark but the crank pin's is
    numbered with its letter, so no two bare numbers of different pins sit together."""
    from drawings.linkage.overview import positions_panel
    from drawings.linkage.panels import strokes_over_cycle
    from plans.solution import Solution

    sol = Solution(load_scene(SAMPLES / f"{name}.toml"))
    panel = positions_panel(sol, 500.0, "ru", [0], strokes_over_cycle(sol))
    marks = [(q.eid.split("-")[2], q.label) for q in panel.prims if q.op == "text" and q.eid.startswith("positions-n-")]
    bare = {pt for pt, lab in marks if re.fullmatch(r"[\d, ]+", lab.plain)}
    assert "A" in bare and not bare & crowded  # the crank pin's numbers stand bare
    lettered = [lab.plain for pt, lab in marks if pt in crowded]
    assert lettered and all(re.fullmatch(r"([A-Z]\d+)(, [A-Z]\d+)*", t) for t in lettered), lettered


@pytest.mark.parametrize("path", sorted(str(p.relative_to(SAMPLES)) for sub in ("gears", "cams", "engines")
                                        for p in (SAMPLES / sub).glob("*.toml")))
def test_title_block_in_the_sheets_language(path):
    """A Russian sheet's title block has no English word in it: the title is the file's
    Russian one of its title per language."""
    import importlib

    from plans.kinds import KINDS, read_kind

    kind, _ = read_kind(str(SAMPLES / path))
    draw = importlib.import_module(KINDS[kind][1]).draw

    def title_block(lang: str) -> str:
        d = draw(str(SAMPLES / path), language=lang)
        return " ".join(q.label.plain for sh in d.sheets for q in sh.prims
                        if q.op == "text" and q.label is not None and q.eid.startswith("tb-"))

    ru = title_block("ru")
    assert not re.findall(r"[A-Za-z]{3,}", ru), ru  # "2K-H", "V6" are a train's and an engine's symbols
    assert re.search(r"[А-Яа-я]{3,}", ru)
