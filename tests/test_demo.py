"""The demonstration: the lesson's data, the force protocol, the mistakes, and the page
driven in real headless Chromium (Debian's ``chromium`` through Playwright)."""

from __future__ import annotations

import json
import math
import re
from pathlib import Path

import numpy as np
import pytest

from drawings.cli import main
from drawings.demo import Demo, page
from plans.demo import lesson
from plans.forces.lever import zhukovsky_lever
from plans.forces.polygons import analyse_forces
from plans.kinematics.exact import solve
from plans.kinematics.placing import load_scene
from plans.results import solve_scene, to_json

SAMPLES = Path(__file__).resolve().parent.parent / "samples"
SCENES = sorted(SAMPLES.glob("*.toml"))


@pytest.fixture(scope="module")
def lessons():
    return {p.stem: lesson(load_scene(p), frames=24) for p in SCENES}


# --------------------------------------------------------------------------- the lesson as data


def test_every_step_of_every_drawing_is_in_the_lesson(lessons):
    for p in SCENES:
        scene = load_scene(p)
        sol = solve_scene(scene)
        L = lessons[p.stem]
        want = sum(len(plan.steps) for plan in (sol.plans[0].velocity, sol.plans[0].acceleration)
                   if plan is not None) if sol.plans else 0
        if sol.forces is not None:
            from plans.forces.protocol import force_steps

            want += len(force_steps(*sol.forces, 0))
        assert len(L["steps"]) == want, p.stem


def test_each_segment_and_line_is_drawn_by_exactly_one_step(lessons):
    for name, L in lessons.items():
        for panel in L["panels"]:
            steps = [s for s in L["steps"] if s["panel"] == panel["id"]]
            segs = [k for s in steps for k in s["segments"]]
            lines = [k for s in steps for k in s["lines"]]
            assert sorted(segs) == list(range(len(panel["segments"]))), (name, panel["id"])
            assert sorted(lines) == list(range(len(panel["lines"]))), (name, panel["id"])
            # a segment is drawn only once both its ends are on the drawing
            shown = {panel["pole"]}
            for s in steps:
                shown.update(s["points"])
                for k in s["segments"]:
                    sg = panel["segments"][k]
                    assert sg["from"] in shown and sg["to"] in shown, (name, panel["id"], sg["label"])


def test_cycle_frames_are_the_exact_positions(lessons):
    scene = load_scene(SAMPLES / "v_engine.toml")
    L = lessons["v_engine"]
    cyc = L["cycle"]
    kin = solve(scene, cyc["phi_deg"], order=2)
    mu_l = cyc["scheme"]["mu_l"]
    for nm, track in cyc["scheme"]["points"].items():
        want = kin.point(nm)[0] * mu_l
        got = np.array([complex(x, y) for x, y in track])
        assert np.max(np.abs(got - want)) <= 1e-3, nm  # page coordinates to 1 µm
    mu_v = cyc["mu_v"]
    got = np.array([complex(x, y) for x, y in cyc["velocity"]["b"]])
    assert np.max(np.abs(got - kin.point("B")[1] * mu_v)) <= 1e-3


def test_lesson_is_deterministic_json():
    a = json.dumps(lesson(load_scene(SAMPLES / "shaper.toml"), frames=12), allow_nan=False)
    b = json.dumps(lesson(load_scene(SAMPLES / "shaper.toml"), frames=12), allow_nan=False)
    assert a == b


# --------------------------------------------------------------------------- the force protocol


_TERM = re.compile(r"([+−])[^\s(]+ \(h = ([\d.]+) mm: ([-\d.e+]+) N × ([-\d.e+]+) m = ([-\d.e+]+) N·m\)")


def test_printed_moment_equations_balance():
    """Each printed ΣM equation, re-added from its printed forces and arms, gives the printed
    tangential component: the protocol is an equation a student can check by hand."""
    for name in ("slider_crank", "v_engine", "four_bar"):
        scene = load_scene(SAMPLES / f"{name}.toml")
        sol = solve_scene(scene)
        from plans.forces.protocol import force_steps

        for k in range(sol.kinematics.n):
            for fs in force_steps(*sol.forces, k):
                text = fs.step.text
                m = re.search(r"· l_\w+ \(([\d.e+-]+) m\) balances them: (\S+) = ([-\d.e+]+) N", text)
                if not m or "ΣM_" not in text:
                    continue
                moment = 0.0
                for sign, _mm, F, h, M in _TERM.findall(text.split(";")[0]):
                    moment += (1 if sign == "+" else -1) * float(F) * float(h)
                    # force × arm is printed as a moment (N·m), not as a length
                    assert float(M) == pytest.approx(float(F) * float(h), rel=2e-5, abs=1e-9), text
                for sign, M in re.findall(r"([+−])M_\w+ \(([\d.e+-]+) N·m\)", text.split(";")[0]):
                    moment += (1 if sign == "+" else -1) * float(M)
                l, tau = float(m.group(1)), float(m.group(3))
                # ΣM_B(i) = −l·F^τ + Σ moments = 0 (F^τ along i·(B − A))
                assert tau * l == pytest.approx(moment, rel=2e-4, abs=1e-6 * max(1.0, abs(moment))), text


def test_solve_protocol_prints_force_steps_and_json_has_steps(capsys):
    assert main(["solve", str(SAMPLES / "v_engine.toml"), "--protocol"]) == 0
    out = capsys.readouterr().out
    for words in ("force analysis, group 2-3:", "ΣM_B(2) = 0", "force analysis, crank:", "ΣM_O(1) = 0",
                  "force analysis, lever:", "ΣM_p = 0 on the lever"):
        assert words in out
    data = to_json(solve_scene(load_scene(SAMPLES / "v_engine.toml")))
    plans = {s["plan"] for s in data["positions"][0]["steps"]}
    assert {"velocity", "acceleration", "group 2-3", "group 4-5", "crank", "lever"} <= plans
    assert all(s["text"] for s in data["positions"][0]["steps"])


# --------------------------------------------------------------------------- the mistakes


def _mistake(L, mid):
    return next(m for m in L["mistakes"] if m["id"] == mid)


def test_reversed_coriolis_moves_the_point_along_its_partner_line():
    L = lesson(load_scene(SAMPLES / "six_bar.toml"), frames=12, phi_deg=60)
    m = _mistake(L, "coriolis")
    acc = next(p for p in L["panels"] if p["id"] == "acceleration")
    cor = next(s for s in acc["segments"] if s["kind"] == "coriolis")
    c = complex(*acc["points"][cor["to"]]) - complex(*acc["points"][cor["from"]])
    (name, wrong), = m["moved"].items()
    right = complex(*acc["points"][name])
    wrong = complex(*wrong)
    k_line = next(ln for ln in acc["lines"] if abs(complex(*ln["point"]) - complex(*acc["points"][cor["to"]])) < 1e-2)
    d = complex(*k_line["dir"])
    # the wrong point lies on the line laid off from k − 2·a^k, parallel to the right one
    dist_wrong = ((wrong - (complex(*k_line["point"]) - 2 * c)).conjugate() * d).imag
    assert abs(dist_wrong) < 5e-3
    # and it moved along the partner line through the right point
    partner = [ln for ln in acc["lines"] if ln is not k_line
               and abs(((right - complex(*ln["point"])).conjugate() * complex(*ln["dir"])).imag) < 5e-3]
    assert any(abs(((wrong - right).conjugate() * complex(*ln["dir"])).imag) < 5e-3 for ln in partner)


def test_pi_mistake_scales_every_velocity_by_314_over_pi():
    L = lesson(load_scene(SAMPLES / "slider_crank.toml"), frames=12, phi_deg=30)
    m = _mistake(L, "pi")
    for nm, wrong in m["moved"].items():
        right = complex(*m["right"][nm])
        assert abs(complex(*wrong) - right * 3.14 / math.pi) < 2e-3, nm


def test_wrong_couple_sign_changes_the_balancing_force_by_twice_its_power():
    scene = load_scene(SAMPLES / "v_engine.toml")
    L = lesson(scene, frames=12)
    m = _mistake(L, "couple")
    label = m["highlight"][0].rstrip("'")
    wrong, right = m["values"]["wrong"], m["values"]["right"]
    assert f"{wrong:.5g}" in m["text"] and f"{right:.5g}" in m["text"]
    kin = solve(scene, [L["phi_deg"]], order=2)
    fa = analyse_forces(scene, kin)
    mom = next(x for x in fa.applied.moments if x.label == label)
    # power balance: flipping M changes Σ M·ω by 2 M ω_link, so F_bal·v_A changes by as much
    crank = scene.links[scene.driver.link]
    v_a = abs(scene.driver.omega) * abs(crank.points[crank.axis[1]])
    expected = abs(2 * float(mom.M[0]) * float(kin.omega(mom.link)[0])) / v_a
    assert abs(wrong - right) == pytest.approx(expected, rel=2e-4)
    assert zhukovsky_lever(fa).valid[0]


# --------------------------------------------------------------------------- the page


def test_page_builds_for_every_sample_and_is_self_contained(tmp_path):
    for p in SCENES:
        out = tmp_path / f"{p.stem}.html"
        assert main(["demo", str(p), "-o", str(out), "--frames", "24"]) == 0
        text = out.read_text(encoding="utf-8")
        assert "<script" in text and "http://" not in text.replace("http://www.w3.org/2000/svg", "")
        assert "https://" not in text
    assert page(SAMPLES / "v_engine.toml", frames=24) == page(SAMPLES / "v_engine.toml", frames=24)


def test_markup_in_a_title_cannot_break_out_of_the_page(tmp_path):
    src = (SAMPLES / "slider_crank.toml").read_text(encoding="utf-8")
    src = re.sub(r'^title = .*$', 'title = "</script><script>alert(1)</script><b>"', src, count=1, flags=re.M)
    f = tmp_path / "evil.toml"
    f.write_text(src, encoding="utf-8")
    text = page(f, frames=12)
    assert "<script>alert(1)" not in text
    assert text.count("</script>") == 3


def test_bad_demo_arguments_are_one_line(tmp_path, capsys):
    out = tmp_path / "p.html"
    assert main(["demo", str(SAMPLES / "slider_crank.toml"), "-o", str(out), "--frames", "1"]) == 2
    assert main(["demo", str(SAMPLES / "slider_crank.toml"), "-o", str(out), "--phi", "7"]) == 2
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) == 2 and all(line.startswith("plans: error:") for line in err)
    assert not out.exists()


def test_jupyter_demo_displays_inline():
    d = Demo(SAMPLES / "slider_crank.toml", frames=12)
    html_text = d._repr_html_()
    assert html_text.startswith("<iframe srcdoc=") and "plansDemo" in html_text


# --------------------------------------------------------------------------- in a real browser


def _open(browser, path: Path, size=(1024, 768)):
    pg = browser.new_page(viewport={"width": size[0], "height": size[1]})
    errors: list[str] = []
    requests: list[str] = []
    pg.on("console", lambda m: errors.append(m.text) if m.type == "error" else None)
    pg.on("pageerror", lambda e: errors.append(str(e)))
    pg.on("request", lambda r: requests.append(r.url))
    pg.goto(path.as_uri())
    pg.wait_for_selector("body[data-ready='1']")
    return pg, errors, requests


def test_page_steps_through_to_the_end_with_buttons_and_keys(browser, tmp_path):
    f = tmp_path / "v.html"
    f.write_text(page(SAMPLES / "v_engine.toml", frames=24, language="en"), encoding="utf-8")
    pg, errors, requests = _open(browser, f)
    n = pg.evaluate("plansDemo.steps")
    texts = [pg.inner_text("#step-text")]
    assert pg.inner_text("#counter") == f"1 / {n}"
    assert pg.is_disabled("#back")
    for _ in range(n - 1):
        pg.click("#next")
        texts.append(pg.inner_text("#step-text"))
    assert pg.inner_text("#counter") == f"{n} / {n}"
    assert pg.is_disabled("#next")
    assert len(set(texts)) >= n - 2  # every step says something of its own
    # the last step has drawn every segment of the lever
    assert pg.locator("#panel [data-seg]").count() > 0
    pg.keyboard.press("Home")
    assert pg.inner_text("#counter") == f"1 / {n}"
    pg.keyboard.press("ArrowRight")
    pg.keyboard.press("ArrowRight")
    assert pg.inner_text("#counter") == f"3 / {n}"
    pg.keyboard.press("ArrowLeft")
    assert pg.inner_text("#counter") == f"2 / {n}"
    # the scheme highlights what the step is about (the crank pin A at the first step)
    pg.keyboard.press("Home")
    assert "hi" in pg.get_attribute("#scheme-joint-A", "class")
    assert errors == []
    assert requests == [f.as_uri()]


def test_slider_moves_the_mechanism_as_the_exact_positions_say(browser, tmp_path):
    scene = load_scene(SAMPLES / "slider_crank.toml")
    f = tmp_path / "s.html"
    L = lesson(scene, frames=36)
    f.write_text(page(scene, frames=36, language="ru"), encoding="utf-8")
    pg, errors, _ = _open(browser, f)
    pg.click("#mode-cycle")
    mu_l = float(pg.get_attribute("#cyc-scheme", "data-mu-l"))
    assert mu_l == L["cycle"]["scheme"]["mu_l"]
    kin = solve(scene, L["cycle"]["phi_deg"], order=0)
    seen = set()
    for k in (0, 5, 9, 17, 30):
        pg.fill("#phi", str(k))
        pg.dispatch_event("#phi", "input")
        cx = float(pg.get_attribute("#cyc-scheme-joint-B", "cx"))
        cy = float(pg.get_attribute("#cyc-scheme-joint-B", "cy"))
        z = complex(kin.point("B")[0][k]) * mu_l
        assert abs(cx - z.real) <= 0.1 and abs(-cy - z.imag) <= 0.1, k
        seen.add((round(cx, 1), round(cy, 1)))
    assert len(seen) >= 4  # it really moved
    pg.click("#cyc-scheme")  # away from the slider, whose own keys move it by its step
    pg.keyboard.press("ArrowRight")  # the keyboard turns the crank one frame on
    cx = float(pg.get_attribute("#cyc-scheme-joint-B", "cx"))
    assert abs(cx - complex(kin.point("B")[0][31]).real * mu_l) <= 0.1
    # the cursor on the balancing force reads the exact value at this crank angle
    fa = analyse_forces(scene, solve(scene, [L["cycle"]["phi_deg"][31]], order=2))
    shown = float(pg.get_attribute("#chart-0 text[data-value]", "data-value"))
    assert shown == pytest.approx(float(fa.balancing[0]), rel=1e-5, abs=1e-6)
    pg.click("#play")
    pg.wait_for_timeout(300)
    pg.click("#play")
    assert errors == []


def test_mistake_toggle_draws_the_wrong_point(browser, tmp_path):
    f = tmp_path / "m.html"
    f.write_text(page(SAMPLES / "six_bar.toml", frames=12, phi_deg=60, language="en"), encoding="utf-8")
    pg, errors, _ = _open(browser, f)
    pg.check("#mistake-coriolis")
    assert pg.locator("#panel [data-wrong]").count() == 1
    assert "Coriolis" in pg.inner_text("#mistake-text")
    pg.uncheck("#mistake-coriolis")
    assert pg.locator("#panel [data-wrong]").count() == 0
    assert errors == []


def test_every_sample_page_opens_without_errors(browser, tmp_path):
    for p in SCENES:
        f = tmp_path / f"{p.stem}.html"
        f.write_text(page(p, frames=12), encoding="utf-8")
        pg, errors, requests = _open(browser, f)
        pg.keyboard.press("End")
        pg.click("#mode-cycle")
        pg.close()
        assert errors == [], p.stem
        assert requests == [f.as_uri()], p.stem


#: The class-III scenes (a triad: Assur's special point S gives its plans).
TRIADS = sorted((SAMPLES / "class3").glob("*.toml"))


def _joint(pg, name: str) -> complex:
    """A joint's centre on the step-by-step scheme as drawn (y up, as the lesson's)."""
    return complex(float(pg.get_attribute(f"#scheme-joint-{name}", "cx")),
                   -float(pg.get_attribute(f"#scheme-joint-{name}", "cy")))


@pytest.mark.parametrize("lang", ["en", "ru"])
@pytest.mark.parametrize("path", TRIADS, ids=[p.stem for p in TRIADS])
def test_class3_page_steps_through_every_step_mistake_and_the_cycle(browser, tmp_path, path, lang):
    f = tmp_path / f"{path.stem}.{lang}.html"
    f.write_text(page(path, frames=12, language=lang), encoding="utf-8")
    pg, errors, requests = _open(browser, f)
    n = pg.evaluate("plansDemo.steps")
    assert n > 20  # the plans by Assur's point, the group's polygon, the crank, the lever
    # Assur's point S, the first point of the velocity plan after a: on the scheme, highlighted,
    # where the axes AD and BE of the leashes drawn there meet (the drawn joints' own geometry)
    pg.click("#next")
    assert "Assur" in pg.inner_text("#step-text") or "Ассура" in pg.inner_text("#step-text")
    assert "hi" in pg.get_attribute("#scheme-joint-S", "class")
    a, d, b, e = (_joint(pg, nm) for nm in "ADBE")
    u, w = d - a, e - b
    s = a + u * ((b - a).real * w.imag - (b - a).imag * w.real) / (u.real * w.imag - u.imag * w.real)
    assert abs(_joint(pg, "S") - s) <= 0.05 * abs(d - a)
    pg.keyboard.press("Home")
    texts, drawn = [], 0
    for k in range(n):
        texts.append(pg.inner_text("#step-text"))
        assert pg.inner_text("#counter") == f"{k + 1} / {n}"
        drawn = max(drawn, pg.locator("#panel [data-seg]").count())
        if k < n - 1:
            pg.click("#next")
    assert pg.is_disabled("#next") and all(x.strip() for x in texts) and drawn > 0
    boxes = pg.locator("#mistakes input")
    assert boxes.count() >= 2
    for k in range(boxes.count()):
        boxes.nth(k).check()
        assert pg.inner_text("#mistake-text").strip()
        boxes.nth(k).uncheck()
    pg.click("#mode-cycle")
    pg.fill("#phi", "5")
    pg.dispatch_event("#phi", "input")
    assert pg.locator("#cyc-scheme [id^='cyc-scheme-joint-']").count() >= 6
    assert pg.locator("#cyc-vel line").count() > 0 and pg.locator("#cyc-acc line").count() > 0
    pg.close()
    assert errors == []
    assert requests == [f.as_uri()]


def test_cycle_page_carries_the_diagrams_and_dynamics_with_the_graphical_nodes():
    from plans.cycle.diagrams import diagrams
    from plans.cycle.dynamics import dynamics

    scene = load_scene(SAMPLES / "v_engine_cycle.toml")
    charts = {c["label"]: c for c in lesson(scene, frames=12)["cycle"]["charts"]}
    names = [d.name for d in diagrams(scene).diagrams]
    assert set(names) | {"M_pr", "I_pr", "ΔT", "ω1"} <= set(charts)
    dyn = dynamics(scene)
    # the graphical nodes are the table's values; the exact curve passes within the graphical error
    mpr = charts["M_pr"]
    assert mpr["nodes"] == pytest.approx([float(x) for x in dyn.table.M_pr], rel=1e-5)
    exact_at_nodes = np.interp(mpr["nodes_deg"], mpr["phi_deg"], mpr["values"])
    assert np.max(np.abs(exact_at_nodes - np.array(mpr["nodes"]))) <= 1e-3 * np.max(np.abs(mpr["values"]))


# --------------------------------------------------------------------------- one language per page

_ENGLISH = {"intersection", "guide", "from", "polygon", "lever", "line", "through", "meet", "lay", "off", "the",
            "and", "of", "link", "slot", "balances", "sum", "sense", "toward", "parallel", "apply", "turn",
            "couple", "closes", "arm", "instead", "moves", "gives", "so", "known", "point", "similarity", "image",
            "acceleration", "normal", "inertia", "power", "balance", "draw", "coincides", "computed", "every"}
_WORD = re.compile(r"[^\W\d_]+")
_NUMBER_EN = re.compile(r"\d+(?:\.\d+)?")
_NUMBER_RU = re.compile(r"\d+(?:,\d+)?")


def _sentences(L):
    return [s["text"] for s in L["steps"]] + [m["text"] for m in L["mistakes"]]


@pytest.mark.parametrize("name, phi", [("v_engine", None), ("six_bar", 60), ("scotch_yoke", None),
                                       ("shaper", None), ("slider_crank", 30)])
def test_russian_lesson_speaks_russian_with_the_same_numbers(name, phi):
    from collections import Counter

    scene = load_scene(SAMPLES / f"{name}.toml")
    ru = _sentences(lesson(scene, frames=12, phi_deg=phi, language="ru"))
    en = _sentences(lesson(scene, frames=12, phi_deg=phi, language="en"))
    assert len(ru) == len(en) and ru
    for r, e in zip(ru, en, strict=True):
        words = {w.lower() for w in _WORD.findall(r)}
        assert not words & _ENGLISH, r
        assert re.search("[а-яё]", r.lower()) or not re.search("[a-z]{3}", e.lower()), r  # a sentence, not symbols
        assert not re.search("[А-яЁё]", e), e
        # the same values, decimal comma in Russian
        got = Counter(float(x.replace(",", ".")) for x in _NUMBER_RU.findall(r))
        assert got == Counter(float(x) for x in _NUMBER_EN.findall(e)), (r, e)
    # the textbook's words are there
    text = " ".join(ru)
    assert "пересечение" in text
    if name == "v_engine":
        assert "F_ур" in text and "рычаге Жуковского" in text and "многоугольник" in text and "плечом" in text
    if name == "six_bar":
        assert "кориолисово ускорение" in text.lower()


def test_unknown_lesson_language_is_an_input_error():
    from plans.errors import InputError

    with pytest.raises(InputError):
        lesson(load_scene(SAMPLES / "four_bar.toml"), frames=6, language="de")


def test_v_engine_page_with_72_positions_stays_small():
    size = len(page(SAMPLES / "v_engine.toml").encode("utf-8"))
    assert size < 1_500_000


# --------------------------------------------------------------------------- forces over the cycle


def test_cycle_forces_are_the_engines_polygons_and_lever_at_every_frame():
    from plans.forces.lever import lever_plan
    from plans.forces.polygons import force_polygons

    scene = load_scene(SAMPLES / "v_engine.toml")
    L = lesson(scene, frames=12)
    panels = {p["id"]: p for p in L["cycle"]["forces"]}
    assert set(panels) == {"group-2-3", "group-4-5", "crank", "lever"}
    # over the turn, as the page does: at a dead centre the stroke (and so the gas force) is
    # told by the piston's velocity against the turn's largest
    fa = analyse_forces(scene, solve(scene, L["cycle"]["phi_deg"], order=2))
    lv = zhukovsky_lever(fa, scale=panels["lever"]["scale"])
    for k in (0, 5, 11):
        for poly in force_polygons(fa, k):
            pid = "crank" if poly.kind == "crank" else f"group-{poly.group}"
            mu = panels[pid]["scale"]
            segs = {s["label"]: s["track"][k] for s in panels[pid]["segments"]}
            for s in poly.plan.segments:
                a = complex(*poly.plan.xy(s.start)) / poly.plan.scale * mu
                b = complex(*poly.plan.xy(s.end)) / poly.plan.scale * mu
                x1, y1, x2, y2 = segs[s.label]
                assert abs(complex(x1, y1) - a) <= 2e-3 and abs(complex(x2, y2) - b) <= 2e-3, (k, pid, s.label)
        plan = lever_plan(lv, k)
        for nm, track in panels["lever"]["points"].items():
            assert abs(complex(*track[k]) - complex(*plan.xy(nm))) <= 2e-3, (k, nm)


def test_slider_moves_the_force_polygons_and_the_lever(browser, tmp_path):
    from plans.forces.lever import lever_plan
    from plans.forces.polygons import force_polygons

    scene = load_scene(SAMPLES / "slider_crank.toml")
    f = tmp_path / "f.html"
    L = lesson(scene, frames=36)
    f.write_text(page(scene, frames=36, language="ru"), encoding="utf-8")
    pg, errors, requests = _open(browser, f)
    pg.keyboard.press("End")  # the lever's equation, as the Russian page writes it
    last = pg.inner_text("#step-text")
    assert "ΣM_p = 0 на рычаге Жуковского" in last and "F_ур" in last and "Φ2" in last, last
    assert not re.search(r"\b(lever|so|by|power)\b", last), last
    pg.click("#mode-cycle")
    mu = float(pg.get_attribute("#cyc-f-group-2-3", "data-mu"))
    mu_v = float(pg.get_attribute("#cyc-f-lever", "data-mu"))

    fa = analyse_forces(scene, solve(scene, L["cycle"]["phi_deg"], order=2))
    lv = zhukovsky_lever(fa, scale=mu_v)

    def engine(k):
        poly = force_polygons(fa, k)[0].plan
        ends = {s.label: complex(*poly.xy(s.end)) / poly.scale * mu for s in poly.segments}
        return ends, complex(*lever_plan(lv, k).xy("b"))

    def shown():
        ends = {}
        for ln in pg.locator("#cyc-f-group-2-3 line[data-seg]").all():
            ends[ln.get_attribute("data-seg")] = complex(float(ln.get_attribute("x2")), -float(ln.get_attribute("y2")))
        b = pg.locator("#cyc-f-lever-pt-b")
        return ends, complex(float(b.get_attribute("cx")), -float(b.get_attribute("cy")))

    seen = []
    for k in (0, 7, 20, 31):
        pg.fill("#phi", str(k))
        pg.dispatch_event("#phi", "input")
        ends, b = shown()
        want, want_b = engine(k)
        assert set(ends) == set(want), k
        for label, z in want.items():
            assert abs(ends[label] - z) <= 0.1, (k, label)
        assert abs(b - want_b) <= 0.1, k
        seen.append(ends)
    assert len({tuple(round(abs(z), 1) for z in e.values()) for e in seen}) == len(seen)  # it really moved
    # between two frames the drawing is interpolated, as the plans are
    pg.fill("#phi", "7.5")
    pg.dispatch_event("#phi", "input")
    ends, _ = shown()
    (w7, _), (w8, _) = engine(7), engine(8)
    for label in w7.keys() & w8.keys():
        assert abs(ends[label] - (w7[label] + w8[label]) / 2) <= 0.1, label
    # the page's figures speak Russian
    assert "Н" in pg.inner_text("#cyc-forces") and "mm/N" not in pg.inner_text("#cyc-forces")
    assert errors == []
    assert requests == [f.as_uri()]


def test_cycle_plans_fill_their_panels_and_read_the_exact_velocities(browser, tmp_path):
    # six_bar's quick return: one view for the whole turn would leave most frames a dot
    scene = load_scene(SAMPLES / "six_bar.toml")
    f = tmp_path / "p.html"
    L = lesson(scene, frames=36)
    f.write_text(page(scene, frames=36, language="en"), encoding="utf-8")
    pg, errors, _ = _open(browser, f)
    pg.click("#mode-cycle")
    mu_v, mu_a = L["cycle"]["mu_v"], L["cycle"]["mu_a"]
    kin = solve(scene, L["cycle"]["phi_deg"], order=2)
    widths = set()
    for k in (0, 9, 20, 27):
        pg.fill("#phi", str(k))
        pg.dispatch_event("#phi", "input")
        for svg, mu, order in (("#cyc-vel", mu_v, 1), ("#cyc-acc", mu_a, 2)):
            ln = pg.locator(f"{svg}-a")
            drawn = complex(float(ln.get_attribute("x2")), -float(ln.get_attribute("y2"))) / mu
            exact = complex(kin.point("A")[order][k])
            assert abs(drawn - exact) <= 1e-3 * max(abs(exact), 1e-9) + 0.01 / mu, (k, svg)
            # the scale bar is a round value at the same μ
            bar = pg.locator(f"{svg} line[data-bar]")
            length = float(bar.get_attribute("x2")) - float(bar.get_attribute("x1"))
            assert length == pytest.approx(float(bar.get_attribute("data-bar")) * mu, rel=1e-3)
            view = [float(v) for v in pg.get_attribute(svg, "viewBox").split()]
            reach = max(abs(complex(float(x.get_attribute("x2")), float(x.get_attribute("y2"))))
                        for x in pg.locator(f"{svg} line[id]").all())
            assert reach >= 0.3 * view[2], (k, svg)  # the frame's plan fills its panel
            widths.add(round(view[2], 3))
    assert len(widths) > 2 and errors == []


def test_cycle_charts_read_zero_where_the_value_is_round_off():
    # at φ = 0 the V-engine's bank B is at its dead centre: v_B is zero, not 1e-15
    charts = {c["label"]: c for c in lesson(load_scene(SAMPLES / "v_engine_cycle.toml"), frames=12)["cycle"]["charts"]}
    assert charts["v_B"]["phi_deg"][0] == 0 and charts["v_B"]["values"][0] == 0.0
    for c in charts.values():
        size = max(abs(v) for v in c["values"])
        assert all(v == 0.0 or abs(v) > 1e-9 * size for v in c["values"] + c.get("nodes", [])), c["label"]


def test_russian_cycle_view_labels_and_coincident_plan_points(browser, tmp_path):
    f = tmp_path / "c.html"
    f.write_text(page(SAMPLES / "v_engine_cycle.toml", frames=12, language="ru"), encoding="utf-8")
    pg, errors, _ = _open(browser, f)
    pg.click("#mode-cycle")
    captions = pg.inner_text("#cyc-charts")
    assert "M_пр, Н·м" in captions and "I_пр" in captions and "м/с²" in captions
    assert "m/s" not in captions and "M_pr" not in captions
    # φ = 0: the rod AC only translates, so a, c and s4 are one point of the velocity plan, one label
    labels = pg.evaluate("[...document.querySelectorAll('#cyc-vel text.label')].map((t) => t.textContent)")
    assert "a, c, s4" in labels and "a" not in labels
    # only the panels the scene asks for share the row
    assert pg.evaluate("document.getElementById('cyc-vel').closest('.stage').classList.contains('two')")
    assert errors == []


@pytest.mark.parametrize("name", ["v_engine", "six_bar", "shaper"])
def test_moment_steps_draw_each_printed_arm_on_the_scheme(name):
    """A moment equation's step carries each known force's arm on the page's scheme: the
    foot is on the force's line, the arm ⟂ it, and its length is the h the step prints."""
    scene = load_scene(SAMPLES / f"{name}.toml")
    L = lesson(scene, frames=6, language="en")
    mu_l = L["scheme"]["mu_l"]
    drawn = 0
    for s in L["steps"]:
        if s["op"] != "moment":
            continue
        printed = {label: float(h) for _sign, label, h in
                   re.findall(r"([+−])(\w+)·h \(h = [\d.]+ mm: [\d.e+-]+ N × ([\d.e+-]+) m = [\d.e+-]+ N·m\)",
                              s["text"].split(";")[0])}
        for a in s.get("arms", []):
            P, foot, at = (complex(*a[key]) for key in ("about", "foot", "at"))
            arm, along = foot - P, foot - at
            assert abs(arm) / mu_l == pytest.approx(printed[a["label"]], rel=2e-3, abs=2e-6), (s["text"], a)
            if abs(along) > 1e-3:  # the arm ⟂ the force's line through its point
                assert abs((arm.conjugate() * along).real) <= 2e-3 * abs(arm) * abs(along), a
            drawn += 1
        # every printed arm that a pencil can show is drawn
        assert {a["label"] for a in s.get("arms", [])} == {k for k, h in printed.items() if h * mu_l >= 0.5}
    assert drawn > 0


def test_scheme_shows_the_arms_of_a_moment_step(browser, tmp_path):
    f = tmp_path / "v.html"
    L = lesson(load_scene(SAMPLES / "v_engine.toml"), frames=12, language="ru")
    f.write_text(page(SAMPLES / "v_engine.toml", frames=12, language="ru"), encoding="utf-8")
    pg, errors, _ = _open(browser, f)
    k = next(n for n, s in enumerate(L["steps"]) if s.get("arms"))
    assert pg.locator("#scheme [data-arm]").count() == 0  # the first step is the velocity plan's
    for _ in range(k):
        pg.click("#next")
    arms = L["steps"][k]["arms"]
    assert pg.locator("#scheme [data-arm]").count() == len(arms)
    for a in arms:
        ln = pg.locator(f"#scheme line[data-arm='{a['label']}']")
        got = [float(ln.get_attribute(x)) for x in ("x1", "y1", "x2", "y2")]
        want = [a["about"][0], -a["about"][1], a["foot"][0], -a["foot"][1]]
        assert got == pytest.approx(want, abs=2e-3)
    pg.click("#next")
    assert pg.locator("#scheme [data-arm]").count() == len(L["steps"][k + 1].get("arms", []))
    assert errors == []
