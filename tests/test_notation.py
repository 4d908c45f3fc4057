"""The course's notation: the scales' letter and direction chosen apart, π for the
acceleration pole, each the default of a Russian sheet and an option everywhere.

The plan's scale as written is read back and checked against the plan's own drawn
lengths (a vector's millimetres over its exact value), so a letter or a direction written
the wrong way round fails.
"""

from __future__ import annotations

import re

import pytest

import plans
from plans.errors import InputError
from plans.io import read_toml
from plans.kinematics.placing import scene_from_dict
from plans.scene.notation import resolve

from .conftest import ROOT


def _scene(scales: dict | None = None, sheet: dict | None = None):
    data = read_toml(ROOT / "samples" / "slider_crank.toml")
    if scales is not None:
        data["scales"] = scales
    if sheet is not None:
        data["sheet"] = dict(data.get("sheet", {}), **sheet)
    return scene_from_dict(data, "slider_crank.toml")


@pytest.mark.parametrize("scales, lang, letter, per_mm", [
    (None, "ru", "μ", True), (None, "en", "μ", False),
    ({"style": "mu"}, "ru", "μ", False), ({"style": "K"}, "en", "K", True),
    ({"symbol": "K"}, "ru", "K", True), ({"symbol": "K", "direction": "mm/m"}, "ru", "K", False),
    ({"symbol": "mu", "direction": "m/mm"}, "en", "μ", True), ({"direction": "mm/m"}, "ru", "μ", False),
])
def test_scale_letter_and_direction_apart(scales, lang, letter, per_mm):
    from drawings.linkage.panels import scale_text

    scene = _scene(scales)
    assert resolve(scene.scale_style, lang)[:2] == (letter, per_mm)
    sol = plans.solve(scene)
    plan = sol.plans[0].velocity
    text = scale_text("velocity", plan.scale, scene.scale_style, lang)
    m = re.match(r"([μK])_v = ([\d.,]+) (\S+)", text)
    assert m and m.group(1) == letter, text
    written = float(m.group(2).replace(",", "."))
    # the oracle: a drawn vector's mm over its exact m/s is mm per (m/s)
    seg = max(plan.segments, key=lambda s: s.length_mm)
    mm_per_unit = seg.length_mm / seg.value
    stated = 1.0 / written if m.group(3).endswith(("/mm", "/мм")) else written
    assert m.group(3).endswith(("/mm", "/мм")) == per_mm
    assert stated == pytest.approx(mm_per_unit, rel=1e-3)


def test_the_protocol_writes_the_direction_too():
    from plans.results import table

    sol = plans.solve(_scene())
    assert re.search(r"план скоростей, μ = [\d,]+ \(м/с\)/мм", table(sol, lang="ru"))
    assert re.search(r"velocity plan, mu = [\d.]+ mm/\(m/s\)", table(sol, lang="en"))


def test_style_and_symbol_together_is_an_error():
    with pytest.raises(InputError) as exc:
        _scene({"style": "K", "symbol": "mu"})
    assert exc.value.field == "scales.symbol"
    with pytest.raises(InputError) as exc:
        _scene({"direction": "mm per m"})
    assert exc.value.field == "scales.direction"
    with pytest.raises(InputError) as exc:
        _scene(sheet={"acceleration_pole": "P"})
    assert exc.value.field == "sheet.acceleration_pole"


def _labels(scene, lang: str, pid_prefix: str = "acceleration-") -> set[str]:
    from drawings.linkage.panels import plan_panel

    plan = plans.solve(scene).plans[0].acceleration
    panel = plan_panel(plan, lang, scene.scale_style)
    return {p.label.plain for p in panel.prims if p.op == "text" and p.label is not None
            and "-label-" in (p.eid or "")}


@pytest.mark.parametrize("sheet, lang, pole", [
    (None, "ru", "π"), (None, "en", "pa"), ({"acceleration_pole": "p_a"}, "ru", "pa"),
    ({"acceleration_pole": "π"}, "en", "π"), ({"acceleration_pole": "pi"}, "en", "π")])
def test_the_acceleration_pole(sheet, lang, pole):
    labels = _labels(_scene(sheet=sheet), lang)
    assert any(lab == pole or lab.startswith(pole + ",") for lab in labels), labels
    other = {"π", "pa"} - {pole}
    assert not any(lab.split(",")[0] in other for lab in labels), labels


def test_the_results_table_names_the_pole_too():
    from drawings.linkage.panels import table_panel

    scene = _scene()
    pp = plans.solve(scene).plans[0]
    panel = table_panel(pp.readings, "ru", scene.scale_style, pp.phi_deg)
    cells = {p.label.plain for p in panel.prims if p.op == "text" and p.label is not None}
    assert any(c.startswith("π ") for c in cells) and not any(c.startswith("pa ") for c in cells)


def test_english_sheets_keep_their_notation():
    """The English defaults are what the sheets always wrote: μ in mm per unit, p_a."""
    scene = _scene()
    assert resolve(scene.scale_style, "en") == resolve("mu", "en") == ("μ", False, "p_a")


@pytest.mark.parametrize("sheet, lang, want, not_want", [
    (None, "ru", "π a", "p_a a"), (None, "en", "p_a a", "π a"),
    ({"acceleration_pole": "p_a"}, "ru", "p_a a", "π"), ({"acceleration_pole": "π"}, "en", "π a", "p_a")])
def test_the_protocol_names_the_pole_as_asked(sheet, lang, want, not_want):
    from plans.results import table

    text = table(plans.solve(_scene(sheet=sheet)), protocol=True, lang=lang)
    assert want in text and not_want not in text


def test_the_force_protocol_writes_its_scales_in_the_notation():
    """μF, μl and the lever's μv in the force analysis follow the plans' notation: read back, each
    is the polygon's own scale (its mm per newton) the other way round."""
    from plans.results import table

    data = read_toml(ROOT / "samples" / "shaper.toml")
    sol = plans.solve(scene_from_dict(data, "shaper.toml"))
    ru, en = table(sol, lang="ru"), table(sol, lang="en")
    from plans.forces.polygons import force_polygons

    fa = sol.forces[0]
    scales = {fp.group: fp.scale for fp in force_polygons(fa, 0)}
    for group, mu in scales.items():
        m = re.search(rf"план сил {group}, μF = ([\d,]+) Н/мм", ru)
        assert m and float(m.group(1).replace(",", ".")) == pytest.approx(1 / mu), group
        assert re.search(rf"polygon {group}, μF = [\d.]+ mm/N", en), group
    assert "мм/Н" not in ru and "N/mm" not in en
    assert re.search(r"рычаг повёрнут на 90° [^,]+, μv = [\d,]+ \(м/с\)/мм", ru)
