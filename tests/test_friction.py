"""Friction in the force analysis: every oracle here is written apart from the code under test
(the friction loads rebuilt from the reported reactions and the kinematics, each link's
equilibrium summed here, the power balance with the losses, a slider-crank in closed form)."""

from __future__ import annotations

import json

import numpy as np
import pytest

from plans.errors import InputError
from plans.forces.analysis import kinetostatics
from plans.kinematics.exact import solve
from plans.kinematics.placing import load_scene, parse_scene, scene_from_dict
from plans.results import solve_scene, to_json

from .conftest import SAMPLES

FRICTION_SAMPLES = ["v_engine_friction", "shaper_friction"]


def _path(stem):
    return next(p for p in SAMPLES if p.stem == stem)


def _solved(stem, phis=None):
    scene = load_scene(_path(stem))
    if phis is not None:
        raw = dict(scene.raw)
        raw["driver"] = {k: v for k, v in raw["driver"].items() if k not in ("positions", "phi0_deg")}
        raw["driver"]["phi_deg"] = list(phis)
        scene = scene_from_dict(raw, scene.path)
    kin = solve(scene, order=2)
    fa, lv = kinetostatics(scene, kin)
    return scene, kin, fa, lv


def _cross(a, b):
    return (np.conj(a) * b).imag


def _coefficients(scene):
    """ρ of each pin and f of each slide, read from the scene file's own tables here."""
    table = scene.raw.get("friction", {})
    out = {}
    for body, jt in zip(scene.raw["joints"], scene.joints, strict=True):
        if jt.kind == "P":
            out[jt.name] = body.get("f", table.get("f", 0.0))
        elif "friction_circle" in body:
            out[jt.name] = body["friction_circle"] * 1e-3
        else:
            out[jt.name] = body.get("f", table.get("f", 0.0)) * body.get("pin_radius", table.get("pin_radius", 0)) * 1e-3
    return out


def _friction_of(scene, kin, rc, coef):
    """The friction load of one pair rebuilt from its reaction: (couple on ``on``, force on
    ``on``, loss W, relative motion)."""
    n = kin.n
    w1 = np.abs(kin.omega(scene.driver.link))
    if rc.guide is None:
        rel = kin.omega(rc.on) - (kin.omega(rc.frm) if rc.frm != scene.frame else 0.0)
        sense = np.where(np.abs(rel) > 1e-9 * w1, np.sign(rel), 0.0)
        M = -coef * np.abs(rc.F) * sense
        return M, np.zeros(n, complex), np.abs(M * rel), rel, rc.r
    # the relative velocity of the two links at the slider's pin, from ω and a point's v
    at = kin.point(rc.joint.point, rc.joint.slider)[0]

    def v_at(link):
        if link == scene.frame:
            return np.zeros(n, complex)
        pin = scene.links[link].axis[0]
        r0, v0, _ = kin.point(pin, link)
        return v0 + 1j * kin.omega(link) * (at - r0)

    rel = ((v_at(rc.on) - v_at(rc.frm)) * np.conj(rc.guide)).real
    sense = np.where(np.abs(rel) > 1e-9 * w1 * kin.reach(), np.sign(rel), 0.0)
    F = -coef * np.abs(_cross(rc.guide, rc.F)) * sense * rc.guide
    return np.zeros(n), F, np.abs(F) * np.abs(rel), rel, at


def _residuals(scene, kin, fa):
    """Largest |ΣF| and |ΣM about the origin| over the links, with the frictionless loads,
    the friction rebuilt from the reactions, the reactions and the balancing load."""
    coefs = _coefficients(scene)
    n = kin.n
    F = {lid: np.zeros(n, complex) for lid in scene.links}
    M = {lid: np.zeros(n) for lid in scene.links}
    for f in fa.applied.forces:
        if f.kind != "friction":
            F[f.link] += f.F
            M[f.link] += _cross(f.r, f.F)
    for m in fa.applied.moments:
        if m.kind != "friction":
            M[m.link] += m.M
    for rc in fa.reactions():
        mf, ff, _, _, at = _friction_of(scene, kin, rc, coefs[rc.joint.name])
        for link, s in ((rc.on, 1.0), (rc.frm, -1.0)):
            if link == scene.frame:
                continue
            F[link] += s * (rc.F + ff)
            M[link] += s * (_cross(rc.r, rc.F) + _cross(at, ff) + rc.M + mf)
    c = fa.crank
    if c.kind == "force":
        F[c.link] += c.F_bal * c.e_bal
        M[c.link] += _cross(c.r_point, c.F_bal * c.e_bal)
    else:
        M[c.link] += c.M_bal
    big = max(float(np.max(np.abs(rc.F))) for rc in fa.reactions())
    worst_f = max(float(np.max(np.abs(v))) for v in F.values()) / big
    worst_m = max(float(np.max(np.abs(v))) for v in M.values()) / (big * kin.reach())
    return worst_f, worst_m


@pytest.mark.parametrize("stem", FRICTION_SAMPLES)
def test_converged_reactions_keep_every_link_in_equilibrium_with_its_friction(stem):
    scene, kin, fa, _ = _solved(stem)
    fr = fa.friction
    assert fr.converged.all()
    wf, wm = _residuals(scene, kin, fa)
    assert wf <= 1e-9 and wm <= 1e-9
    # and the friction did change the answer (the oracle is not the frictionless one)
    assert np.max(np.abs(fa.balancing - fr.frictionless.balancing)) > 1e-3 * np.max(np.abs(fa.balancing))


@pytest.mark.parametrize("stem", FRICTION_SAMPLES)
def test_power_balance_with_the_losses(stem):
    """Σ P_loads + P_bal = Σ losses, every loss ≥ 0, the losses rebuilt here."""
    scene, kin, fa, lv = _solved(stem)
    coefs = _coefficients(scene)
    n = kin.n
    power = np.zeros(n)
    for f in fa.applied.forces:
        if f.kind != "friction":
            v = kin.point_on(f.link, f.local)[1]
            power += (np.conj(f.F) * v).real
    for m in fa.applied.moments:
        if m.kind != "friction":
            power += m.M * kin.omega(m.link)
    c = fa.crank
    v_bal = kin.point(c.point, c.link)[1]
    power += (np.conj(c.F_bal * c.e_bal) * v_bal).real
    losses = np.zeros(n)
    data = json.loads(json.dumps(to_json(solve_scene(scene))))
    for rc in fa.reactions():
        _, _, loss, _, _ = _friction_of(scene, kin, rc, coefs[rc.joint.name])
        assert np.all(loss >= 0)
        losses += loss
        if coefs[rc.joint.name] > 0:
            reported = np.array([p["friction"]["losses"][rc.joint.name] for p in data["positions"]])
            np.testing.assert_allclose(reported, loss, rtol=0, atol=1e-9 * max(np.max(loss), 1.0))
    scale = max(float(np.max(np.abs(power))), float(np.max(losses)))
    assert np.max(np.abs(power - losses)) <= 1e-9 * scale
    assert np.max(losses) > 0


def _without_friction_keys(data):
    for p in data["positions"]:
        p.pop("friction", None)
    data.pop("efficiency", None)
    return data


@pytest.mark.parametrize("path", [p for p in SAMPLES if "friction" not in p.stem], ids=lambda p: p.stem)
def test_zero_friction_gives_the_frictionless_results_exactly(path):
    scene = load_scene(path)
    if not (scene.wants("force_polygons") or scene.wants("lever")):
        pytest.skip("no force analysis")
    raw = dict(scene.raw)
    raw["friction"] = {"f": 0.0, "pin_radius": 10}
    zero = scene_from_dict(raw, scene.path)
    a = to_json(solve_scene(scene))
    b = to_json(solve_scene(zero))
    assert all(p["friction"]["iterations"] == 1 and p["friction"]["converged"] for p in b["positions"])
    assert json.dumps(_without_friction_keys(b)) == json.dumps(a)


SLIDER = """
format = 1
unit = "mm"
frame = 4
outputs = ["positions", "velocity_plan", "acceleration_plan", "force_polygons", "lever"]
[points]
O = [0, 0]
[links.1]
axis = ["O", "A"]
length = {r}
[links.2]
axis = ["A", "B"]
length = {l}
[links.3]
axis = ["B"]
[[joints]]
kind = "R"
links = [4, 1]
point = "O"
[[joints]]
kind = "R"
links = [1, 2]
point = "A"
[[joints]]
kind = "R"
links = [2, 3]
point = "B"
[[joints]]
kind = "P"
links = [3, 4]
point = "B"
guide = {{ link = 4, through = [0, {e}], angle_deg = 0 }}
f = {f}
[driver]
link = 1
omega = 10
phi_deg = {phis}
[loads]
gravity = false
[[loads.force]]
name = "Q"
link = 3
point = "B"
resisting = {q}
along = 0
"""


def _slider(f, phis, r=50, l=180, e=12, q=1000.0):
    scene = parse_scene(SLIDER.format(r=r, l=l, e=e, f=f, q=q, phis=list(phis)), "slider.toml")
    kin = solve(scene, order=2)
    return scene, kin, kinetostatics(scene, kin)[0]


def test_slider_crank_with_friction_in_the_slide_against_its_closed_form():
    """Massless links, a resisting force Q on the slider, friction f only in the slide: the
    rod is a two-force member along AB with force S; the slider's equilibrium along and
    across the guide gives S = Q s_v / (u_x − f s_v sgn(S) |u_y|) (u = (B − A)/l), N = −S u_y;
    the crank's moment about O gives F_bal = S cross(A − O, u) / r."""
    r, l, e, q, f = 0.05, 0.18, 0.012, 1000.0, 0.2
    phis = [17.0, 63.0, 128.0, 211.0, 290.0, 333.0]
    scene, kin, fa = _slider(f, phis)
    A = r * np.exp(1j * np.radians(phis))
    xb = A.real + np.sqrt(l**2 - (e - A.imag) ** 2)
    B = xb + 1j * e
    u = (B - A) / l
    # the slider's velocity along x, by differentiating x_B(φ) (ω = 10 rad/s ccw)
    dx = -r * np.sin(np.radians(phis)) + (e - A.imag) * r * np.cos(np.radians(phis)) / (xb - A.real)
    sv = np.sign(dx)
    s0 = q * sv / u.real  # frictionless, to read the sign of S
    S = q * sv / (u.real - f * sv * np.sign(s0) * np.abs(u.imag))
    F_bal = S * _cross(A, u) / r  # along the crank's ccw normal
    N = -S * u.imag
    assert np.max(np.abs(fa.crank.F_bal - F_bal)) <= 1e-9 * np.max(np.abs(F_bal))
    slide = next(rc for rc in fa.reactions() if rc.guide is not None)
    np.testing.assert_allclose(_cross(slide.guide, slide.F), N, rtol=0, atol=1e-9 * q)
    fr = fa.friction
    assert fr.converged.all() and np.all(fr.iterations >= 3)  # the slide's friction changes N
    (pair,) = fr.pairs
    np.testing.assert_allclose(pair.loss, f * np.abs(N) * np.abs(dx * 10), rtol=1e-9)
    eta = (s0 * _cross(A, u) / r) / F_bal  # the crank drives: η = F_bal,0 / F_bal
    np.testing.assert_allclose(fr.efficiency, eta, rtol=1e-9)
    assert np.all((fr.efficiency > 0) & (fr.efficiency < 1))


def test_dead_centre_leaves_the_slides_sense_undetermined_and_gives_its_range():
    scene, kin, fa = _slider(0.2, [0.0, 40.0], e=0)
    fr = fa.friction
    (pair,) = fr.pairs
    assert pair.sense[0] == 0 and pair.load[0] == 0 and pair.sense[1] != 0
    data = to_json(solve_scene(scene))["positions"]
    got = data[0]["friction"]
    assert got["undetermined"] == [pair.name]
    slide = next(rc for rc in fa.reactions() if rc.guide is not None)
    assert got["ranges"][pair.name]["at_most"] == pytest.approx(0.2 * abs(float(_cross(slide.guide, slide.F)[0])))
    assert data[1]["friction"]["undetermined"] == []


def test_a_slide_beyond_its_friction_angle_self_locks_and_is_named():
    """The rod leans from the guide by β ≤ arcsin(r/l) = 30°: with f = 3 (friction angle
    71.6°) the slider cannot be pushed where tan β > 1/f; elsewhere it moves."""
    phis = [10.0, 90.0]  # β ≈ 4.8° and 30°
    scene, kin, fa = _slider(3.0, phis, r=90, l=180, e=0)
    fr = fa.friction
    assert bool(fr.converged[0]) and not bool(fr.converged[1])
    data = to_json(solve_scene(scene))["positions"]
    assert data[1]["friction"]["self_locking"] == [fr.pairs[0].name]
    assert data[1]["friction"]["F_bal"] is None and data[1]["friction"]["efficiency"] is None
    assert data[0]["friction"]["self_locking"] == []


def test_cycle_efficiency_from_the_works_over_the_turn():
    scene, kin, fa, _ = _solved("shaper_friction")
    data = to_json(solve_scene(scene))
    eff = data["efficiency"]
    fr = fa.friction
    w = np.abs(kin.omega(scene.driver.link))
    dt = 2 * np.pi / kin.n / w
    c = fa.crank
    v_bal = kin.point(c.point, c.link)[1]
    a_bal = float(np.sum((np.conj(c.F_bal * c.e_bal) * v_bal).real * dt))  # the shaper's crank drives
    a_f = float(np.sum(sum(p.loss for p in fr.pairs) * dt))
    assert a_bal > 0 and eff["cycle"] == pytest.approx((a_bal - a_f) / a_bal, rel=1e-12)
    assert 0 < eff["cycle"] < 1
    assert eff["phi_deg"] == [float(x) for x in kin.phi_deg] and len(eff["eta"]) == kin.n


@pytest.mark.parametrize(("extra", "field"), [
    ('[friction]\nf = 0.1\n', "friction.pin_radius"),
    ('[friction]\nf = -0.1\npin_radius = 5\n', "friction.f"),
    ('[friction]\nf = 0.1\nradius = 5\n', "friction.radius"),
])
def test_bad_friction_names_the_field(extra, field):
    text = SLIDER.format(r=50, l=180, e=0, f=0.1, q=10, phis=[30]) + extra
    scene = parse_scene(text, "bad.toml")
    with pytest.raises(InputError) as err:
        kinetostatics(scene, solve(scene, order=2))
    assert field in str(err.value) and "bad.toml" in str(err.value)


def test_a_slide_has_no_pin_radius():
    text = SLIDER.format(r=50, l=180, e=0, f=0.1, q=10, phis=[30]).replace("f = 0.1", "f = 0.1\npin_radius = 3")
    scene = parse_scene(text, "bad.toml")
    with pytest.raises(InputError, match=r"\[\[joints\]\] entry 4, pin_radius"):
        kinetostatics(scene, solve(scene, order=2))


def test_drawn_reaction_line_is_tangent_to_the_friction_circle_on_the_opposing_side():
    """On the free body of each group: a circle about each pin with friction, and the
    reaction's line at the circle's radius from the pin, on the side where the reaction's
    moment about the pin opposes ω_ij (the sense read here from the link rates)."""
    from drawings.linkage.forces_panels import crank_panel, group_panel

    scene, kin, fa, _ = _solved("shaper_friction", phis=[40.0, 130.0])
    fr = fa.friction
    pins = {p.name: p for p in fr.pairs if p.reaction.guide is None}
    seen = 0
    for k in range(kin.n):
        panels = [group_panel(scene, kin, gf, k, 400.0, "en", "mu", fr) for gf in fa.groups]
        panels.append(crank_panel(scene, kin, fa, k, 400.0, "en", "mu"))
        prims = {p.eid: p for pn in panels for p in pn.prims if p.eid}
        for rc in fa.reactions():
            p = pins.get(rc.joint.name)
            if p is None:
                continue
            circle = next(v for e, v in prims.items() if e.endswith(f"friction-{p.label}-circle"))
            line = next(v for e, v in prims.items() if e.endswith(f"friction-{p.label}-line"))
            (c,) = circle.pts
            (a, b) = line.pts
            # distance of the pin from the line, and the side (paper y points down)
            dx, dy = b[0] - a[0], b[1] - a[1]
            side = (dx * (c[1] - a[1]) - dy * (c[0] - a[0])) / np.hypot(dx, dy)
            assert abs(abs(side) - circle.r) <= 1e-9
            w = kin.omega(rc.on)[k] - (kin.omega(rc.frm)[k] if rc.frm != scene.frame else 0.0)
            F = complex(rc.F[k])
            # the line's point nearest the pin, in model axes (y up) relative to the pin
            t = ((c[0] - a[0]) * dx + (c[1] - a[1]) * dy) / (dx * dx + dy * dy)
            foot = complex(a[0] + t * dx - c[0], -(a[1] + t * dy - c[1]))
            moment = (np.conj(foot) * F).imag  # of F about the pin, ccw+
            assert np.sign(moment) == -np.sign(w)
            seen += 1
    assert seen >= 6


def test_sheet_panels_with_friction_have_the_efficiency_diagram():
    from drawings.linkage.friction_marks import efficiency_panels
    from plans.forces.friction import efficiency_json

    scene, kin, fa, _ = _solved("v_engine_friction")
    panels = efficiency_panels(efficiency_json(fa), fa, "ru")
    assert [p.pid for p in panels] == ["friction-eta", "friction-table"]
    curve = [p for p in panels[0].prims if p.eid.startswith("friction-eta-curve")]
    assert curve and len(curve[0].pts) == kin.n + 1  # the turn closed back to its first position


@pytest.mark.parametrize("stem", ["four_bar", "offset_slider_crank", "scotch_yoke", "six_bar", "six_link"])
def test_every_kind_of_group_in_equilibrium_with_friction_and_the_lever_agrees(stem):
    """RRR, RRP, RPR, PRP, RPP: friction in every pair, each link's equilibrium summed here, and
    the lever (with the friction loads on it) giving the kinetostatic balancing load."""
    scene = load_scene(_path(stem))
    raw = dict(scene.raw)
    raw["friction"] = {"f": 0.1, "pin_radius": 5}
    scene = scene_from_dict(raw, scene.path)
    kin = solve(scene, order=2)
    fa, lv = kinetostatics(scene, kin)
    assert fa.friction.converged.all() and fa.friction.pairs
    wf, wm = _residuals(scene, kin, fa)
    assert wf <= 1e-9 and wm <= 1e-9
    big = np.max(np.abs(fa.balancing))
    assert np.max(np.abs(lv.signed(lv.by_lever) - fa.balancing)) <= 1e-9 * big
    assert np.max(np.abs(lv.signed(lv.by_power) - fa.balancing)) <= 1e-9 * big


@pytest.mark.parametrize(("stem", "size"), [("shaper_friction", 1.0), ("v_engine_friction", 1.0),
                                            ("shaper_friction", 0.7)])
def test_efficiency_diagram_drawn_at_a_round_scale(stem, size):
    """μ_η, the paper's millimetres between the axis and the line η = 1, is round (1, 2, 2.5, 4,
    5 × 10^k) as every scale of the sheet, also on a smaller sheet's fit; the curve's dots
    lie at η·μ_η and its label states that μ."""
    from drawings.linkage.friction_marks import efficiency_panels
    from plans.forces.friction import efficiency_json
    from plans.kinematics.scales import is_round

    _, _, fa, _ = _solved(stem)
    eta_panel = efficiency_panels(efficiency_json(fa), fa, "ru", size)[0]
    prims = list(eta_panel.prims)
    start = next(i for i, q in enumerate(prims) if q.op == "begin" and q.eid == "friction-eta-xaxis")
    axis = next(q for q in prims[start:] if q.op == "line")  # the φ axis, η = 0
    labels = [q for q in prims if q.op == "text" and q.label.plain == "η = 1"]
    one = next(q for q in prims if q.op == "line" and q.pts[0][1] == pytest.approx(labels[0].label.runs[0].y, abs=2))
    mu = abs(one.pts[0][1] - axis.pts[0][1])
    assert is_round(mu), mu
    eta = np.asarray(fa.friction.efficiency, float)
    eta = np.append(eta, eta[0])  # the turn closed back to its first position
    dots = [q.pts[0][1] for q in eta_panel.prims if q.op == "circle" and q.r == 0.5]
    ok = eta[np.isfinite(eta)]
    assert np.allclose(sorted(axis.pts[0][1] - np.asarray(dots)), sorted(ok * mu), atol=1e-9)
    scale = next(q.label.plain for q in eta_panel.prims if q.op == "text" and q.label.plain.startswith("μη"))
    assert float(scale.split("=")[1].split()[0].replace(",", ".")) == pytest.approx(mu, rel=1e-3)
