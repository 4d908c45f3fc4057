"""The checker on every sample: a synthetic student who measured exact plans passes with no
findings, and a Coriolis mistake on the shaper is caught on the right quantity.

The student's figures are computed here from the exact analysis (rigid-body rates of the
links, :mod:`plans.kinematics`) with the textbook's formulas — |a^n| = v_rel²/l,
a^τ = the component of the relative acceleration ⟂ the link, a^k = 2 ω v_r, a^r = the rest
of the relative acceleration (a^r ⟂ a^k) — never from the plans or the checker.  Only the
*names* of the segments come from the plans (they are the interface the teacher types)."""

from __future__ import annotations

import math
import random
import re
from pathlib import Path

import numpy as np
import pytest

from plans.check.checkfile import check_from_dict
from plans.check.report import check
from plans.kinematics import construction
from plans.kinematics.exact import solve
from plans.kinematics.placing import load_scene

ROOT = Path(__file__).resolve().parent.parent
SAMPLES = sorted((ROOT / "samples").glob("*.toml"))
SHAPER = ROOT / "samples" / "shaper.toml"


def nice_mu(longest: float, target_mm: float = 90.0) -> float:
    """mm per unit, K = 1/μ one of 1, 2, 2.5, 5 × 10^n, so that ``longest`` is ≤ target_mm."""
    kmin = longest / target_mm
    e = math.floor(math.log10(kmin))
    for m in (1.0, 2.0, 2.5, 5.0, 10.0):
        if m * 10.0**e >= kmin:
            return 1.0 / (m * 10.0**e)
    return 1.0 / 10.0 ** (e + 1)  # pragma: no cover


class Exact:
    """Exact rates of named plan points at one position, from the links' rigid-body motion."""

    def __init__(self, kin, k: int) -> None:
        self.kin, self.k, self.scene = kin, k, kin.scene
        self.names = set(kin.point_names()) | set(self.scene.frame_points)

    def token(self, t: str) -> tuple[str, int | None]:
        """'A3' is point A on link 3, unless the scene has a point named A3 (S3 is a point)."""
        if t in self.names:
            return t, None
        m = re.fullmatch(r"([A-Z][a-z]*)(\d+)", t)
        assert m and m.group(1) in self.names, t
        return m.group(1), int(m.group(2))

    def pos(self, name: str) -> complex:
        return complex(self.kin.point(name)[0][self.k])

    def rates(self, t: str) -> tuple[complex, complex, complex]:
        name, link = self.token(t)
        X = self.pos(name)
        if link is None:
            if name in self.scene.frame_points and not any(
                    name in lk.points for lk in self.scene.links.values()):
                return X, 0j, 0j
            link = self.kin.home(name)
        if link == self.scene.frame:
            return X, 0j, 0j
        m = self.kin.motion[link]
        w, e = float(m.omega[self.k]), float(m.eps[self.k])
        rel = X - complex(m.r0[self.k])
        return X, complex(m.v0[self.k]) + 1j * w * rel, complex(m.a0[self.k]) + (1j * e - w * w) * rel

    def omega(self, t: str) -> float:
        name, link = self.token(t)
        return float(self.kin.omega(link if link is not None else self.kin.home(name))[self.k])


TOKENS = re.compile(r"[A-Z][a-z]*\d*")


def split(body: str) -> list[str]:
    toks = TOKENS.findall(body)
    assert "".join(toks) == body, body
    return toks


def value_of(ex: Exact, label: str) -> float:
    """|segment| of a plan label, by the textbook's formulas."""
    m = re.fullmatch(r"(v|a)_(\w+?)(\^n|\^τ)?", label)
    if m:
        sym, toks, comp = m.group(1), split(m.group(2)), m.group(3)
        idx = 1 if sym == "v" else 2
        if len(toks) == 1:
            return abs(ex.rates(toks[0])[idx])
        r1, v1, a1 = ex.rates(toks[0])
        r2, v2, a2 = ex.rates(toks[1])
        if comp is None:
            return abs((v1 - v2) if sym == "v" else (a1 - a2))
        if comp == "^n":
            return abs(v1 - v2) ** 2 / abs(r1 - r2)
        u = (r1 - r2) / abs(r1 - r2)
        return abs(((a1 - a2) * u.conjugate()).imag)
    m = re.fullmatch(r"a\^(k|r)_(\w+)", label)
    assert m, label
    t1, t2 = split(m.group(2))
    _, v1, a1 = ex.rates(t1)
    _, v2, a2 = ex.rates(t2)
    ak = 2 * abs(ex.omega(t1)) * abs(v1 - v2)
    if m.group(1) == "k":
        return ak
    return math.sqrt(max(abs(a1 - a2) ** 2 - ak * ak, 0.0))


def _links_of(ex: Exact, t: str) -> set[int]:
    name, link = ex.token(t)
    return {link} if link is not None else set(ex.scene.point_links(name))


def student(path: Path, seed: int, *, noise: float = 0.3, coriolis: str = "right") -> dict:
    """A check-file dict: every segment of both plans measured on an exact drawing to ±noise mm,
    the crank's vectors, normal and Coriolis components computed and laid off, ω and ε from the
    measured segments.  ``coriolis``: "right", "doubled" (a^k = 4ωv_r laid off) or "reversed"
    (a^k laid off the wrong way; what the student then finds is solved here by hand)."""
    rng = random.Random(seed)
    scene = load_scene(path)
    kin = solve(scene, order=2)
    d = scene.driver
    crank = scene.links[d.link]
    O, A = crank.axis
    l1 = abs(crank.points[A] - crank.points[O])
    w1 = abs(d.omega)
    mu_v = nice_mu(w1 * l1)
    mu_a = nice_mu(w1 * w1 * l1)
    acc = scene.wants("acceleration_plan")
    phis = list(scene.driver.phis_deg)
    chosen = phis if len(phis) <= 3 else [phis[1], phis[len(phis) // 2 + 1]]
    positions = []
    for phi in chosen:
        k = phis.index(phi)
        ex = Exact(kin, k)
        pp = construction.build(kin, k, velocity_scale=mu_v, acceleration_scale=mu_a)  # names only
        meas: dict[str, float] = {}
        vals: dict[str, float] = {}

        def measure(x: float, mu: float) -> float:
            return max(0.0, round(x * mu + rng.uniform(-noise, noise), 1))

        def sig(x: float) -> float:
            return float(f"{x:.4g}")

        vals[f"omega_{d.link}"] = round(w1, 2)
        vals[f"v_{A}"] = sig(w1 * l1)
        meas[f"v_{A}"] = round(vals[f"v_{A}"] * mu_v, 1)
        vlabels = [s.label for s in pp.velocity.segments]
        for lab in vlabels:
            if lab not in meas:
                meas[lab] = measure(value_of(ex, lab), mu_v)
                vals[lab] = sig(meas[lab] / mu_v)

        def v_student(t1: str, t2: str | None, meas: dict[str, float] = meas) -> float:
            """The student's |v_t1t2| (or |v_t1|) from a measured segment (either order)."""
            for lab in ([f"v_{t1}"] if t2 is None else [f"v_{t1}{t2}", f"v_{t2}{t1}"]):
                if lab in meas:
                    return meas[lab] / mu_v
            raise AssertionError(f"no velocity segment for {t1}{t2 or ''}")

        # ω of every link with two axis points other than the crank: v of its far point / l
        omega: dict[int, float] = {d.link: w1}
        for lid, link in scene.links.items():
            if lid == d.link or len(link.axis) != 2:
                continue
            P, Q = link.axis
            lpq = abs(link.points[Q] - link.points[P])
            if P in scene.frame_points and f"v_{Q}" in meas:
                omega[lid] = v_student(Q, None) / lpq
            else:
                omega[lid] = v_student(Q, P) / lpq
            vals[f"omega_{lid}"] = sig(omega[lid])
        # a block turns with its guide's link
        for j in scene.joints:
            if j.kind == "P":
                a, b = j.links
                if a in omega and b not in omega and b != scene.frame:
                    omega[b] = omega[a]
                elif b in omega and a not in omega and a != scene.frame:
                    omega[a] = omega[b]
        positions.append({"phi_deg": phi, "measured": meas, "values": vals})
        if not acc or pp.acceleration is None:
            continue
        e1 = abs(d.eps)
        vals[f"a_{A}"] = sig(l1 * math.hypot(w1 * w1, e1))
        if e1:  # the crank's tangential component is computed and laid off too
            vals[f"a_{A}{O}^τ"] = sig(e1 * l1)
            meas[f"a_{A}{O}^τ"] = round(vals[f"a_{A}{O}^τ"] * mu_a, 1)
        meas[f"a_{A}"] = round(vals[f"a_{A}"] * mu_a, 1)
        alabels = [s.label for s in pp.acceleration.segments]
        for lab in alabels:
            if lab in meas:
                continue
            mn = re.fullmatch(r"a_(\w+)\^n", lab)
            mk = re.fullmatch(r"a\^k_(\w+)", lab)
            if mn:  # computed from the student's own velocity, then laid off
                t1, t2 = split(mn.group(1))
                fixed = t2 in scene.frame_points
                v = v_student(t1, None) if fixed and f"v_{t1}{t2}" not in meas and f"v_{t2}{t1}" not in meas \
                    else v_student(t1, t2)
                r = abs(ex.rates(t1)[0] - ex.rates(t2)[0])
                vals[lab] = sig(v * v / r)
                meas[lab] = round(vals[lab] * mu_a, 1)
            elif mk:
                t1, t2 = split(mk.group(1))
                w = next(omega[lk] for lk in sorted(_links_of(ex, t1) | _links_of(ex, t2)) if lk in omega)
                ak = 2 * w * v_student(t1, t2)
                if coriolis == "doubled":
                    ak *= 2
                vals[lab] = sig(ak)
                meas[lab] = round(ak * mu_a, 1)
            else:
                meas[lab] = measure(value_of(ex, lab), mu_a)
                vals[lab] = sig(meas[lab] / mu_a)
        for lab in alabels:  # ε from a tangential segment: a^τ / l, l measured on the scheme
            mt = re.fullmatch(r"a_(\w+)\^τ", lab)
            if not mt:
                continue
            t1, t2 = split(mt.group(1))
            common = _links_of(ex, t1) & _links_of(ex, t2)
            lid = min(lk for lk in common if lk != scene.frame)
            link = scene.links[lid]
            n1, n2 = ex.token(t1)[0], ex.token(t2)[0]
            if {n1, n2} <= set(link.points):
                length = abs(link.points[n1] - link.points[n2])
            else:  # a point sliding in a slot: the distance is measured on the 1:1 scheme
                length = round(abs(ex.pos(n1) - ex.pos(n2)) * 1000 + rng.uniform(-noise, noise), 1) / 1000
                vals[f"l_{n2}{n1}"] = f"{length * 1000:.1f} mm"  # type: ignore[assignment]
            vals[f"eps_{lid}"] = sig(meas[lab] / mu_a / length)
        if coriolis == "reversed":
            _reverse_coriolis(ex, pp.acceleration, meas, vals, mu_a)
    return {"format": 1, "student": f"synthetic {path.stem} {seed}", "scene": str(path),
            "scales": {"length": {"mu": 1000}, "velocity": {"mu": mu_v}, "acceleration": {"mu": mu_a}},
            "positions": positions}


def _reverse_coriolis(ex: Exact, plan, meas: dict, vals: dict, mu_a: float) -> None:
    """The shaper's RPR group drawn with a^k the wrong way: a3' = a_A2 − K + s·u (K the true
    Coriolis term, u the slot) = a_A3C^n + t·iu (⟂ CA).  Solved here with the exact directions;
    what lies downstream of a3 is left as drawn right."""
    rA, _, aA2 = ex.rates("A2")
    _, _, aA3 = ex.rates("A3")
    rC = ex.pos("C")
    w3 = ex.omega("A3")
    u = (rA - rC) / abs(rA - rC)  # the slot runs along CA
    rel = aA3 - aA2
    K = rel - (rel * u.conjugate()).real * u  # the part ⟂ slot: the Coriolis term
    an = -(w3**2) * (rA - rC)  # a_A3C^n, toward C
    base = aA2 - K - an
    M = np.array([[(1j * u).real, -u.real], [(1j * u).imag, -u.imag]])
    t, s = np.linalg.solve(M, [base.real, base.imag])
    a3 = an + t * 1j * u
    assert abs(a3 - aA3) > 0.05 * abs(aA3)  # the mistake matters at this position
    for lab, x in (("a_A3", abs(a3)), ("a_A3C^τ", abs(t)), ("a^r_A3A2", abs(s))):
        meas[lab] = round(x * mu_a, 1)
        vals[lab] = float(f"{x:.4g}")
    lac = float(vals["l_CA"].split()[0]) / 1000 if "l_CA" in vals else abs(rA - rC)
    vals["eps_3"] = float(f"{abs(t) / lac:.4g}")


def test_value_formulas_agree_with_closed_forms():
    """The test's own formulas against the Scotch yoke's harmonic motion: x_K = r cos φ."""
    scene = load_scene(ROOT / "samples" / "scotch_yoke.toml")
    kin = solve(scene, order=2)
    w = abs(scene.driver.omega)
    r = 0.060
    for k, phi in enumerate(scene.driver.phis_deg):
        ex = Exact(kin, k)
        th = math.radians(phi)
        assert value_of(ex, "v_K") == pytest.approx(r * w * abs(math.sin(th)), abs=1e-9)
        assert value_of(ex, "a_K") == pytest.approx(r * w * w * abs(math.cos(th)), abs=1e-9)
        assert value_of(ex, "a^r_A3A2") == pytest.approx(r * w * w * abs(math.sin(th)), abs=1e-9)
        assert value_of(ex, "a^k_A3A2") == pytest.approx(0.0, abs=1e-12)


def test_shaper_coriolis_formula_by_finite_differences():
    """a^k + a^r of the block relative to the rocker, from finite differences of the slide."""
    scene = load_scene(SHAPER)
    phis = [30.0 - 0.01, 30.0, 30.0 + 0.01]
    kin = solve(scene, phis, order=2)
    w1 = abs(scene.driver.omega)
    dt = math.radians(0.01) / w1
    ex = Exact(kin, 1)
    # slide s = |A − C| along the rocker, ψ = angle of the rocker
    rs = [complex(kin.point("A")[0][i]) - complex(kin.point("C")[0][i]) for i in range(3)]
    s = [abs(z) for z in rs]
    psi = np.unwrap([math.atan2(z.imag, z.real) for z in rs])
    sd = (s[2] - s[0]) / (2 * dt)
    sdd = (s[2] - 2 * s[1] + s[0]) / dt**2
    wd = (psi[2] - psi[0]) / (2 * dt)
    assert value_of(ex, "v_A2A3") == pytest.approx(abs(sd), rel=1e-5)
    assert value_of(ex, "a^k_A3A2") == pytest.approx(2 * abs(wd * sd), rel=1e-5)
    assert value_of(ex, "a^r_A3A2") == pytest.approx(abs(sdd), rel=1e-4, abs=1e-6 * w1 * w1)


@pytest.mark.parametrize("path", SAMPLES, ids=lambda p: p.stem)
@pytest.mark.parametrize("seed", (0, 1))
def test_synthetic_student_passes_every_sample(path, seed):
    rep = check(check_from_dict(student(path, seed), f"{path.stem}.toml"))
    assert len(rep.items) >= 10
    assert [(i.quantity, i.phi_deg, i.student, i.exact, i.tolerance) for i in rep.items
            if i.verdict == "fail"] == []
    assert [f.message for f in rep.findings] == []
    assert rep.unchecked == ()
    # every segment of the plans (Coriolis and sliding ones included) was checked
    kinds = {i.quantity.split("_")[0] for i in rep.items}
    assert {"v", "omega"} <= kinds


def test_shaper_items_include_coriolis_and_sliding():
    rep = check(check_from_dict(student(SHAPER, 2), "shaper.toml"))
    qs = {i.quantity for i in rep.items}
    assert {"a^k_A3A2", "a^r_A3A2", "v_A2A3", "v_A3", "a_A3", "eps_3", "l_CA"} <= qs
    # the Coriolis vector is laid off at the student's scale: the draftsman's tolerance applies
    ak = [i for i in rep.items if i.quantity == "a^k_A3A2"]
    assert ak and all(i.tolerance_model == "draftsman" for i in ak)


def test_doubled_coriolis_on_the_shaper_is_caught():
    rep = check(check_from_dict(student(SHAPER, 3, coriolis="doubled"), "doubled.toml"))
    fails = {i.quantity for i in rep.items if i.verdict == "fail"}
    assert "a^k_A3A2" in fails
    # the velocities were drawn right
    assert not {q for q in fails if q.startswith(("v_", "omega_"))}
    # the student's a^k is not 2·ω3·v_r of the student's own figures
    rel = [f for f in rep.findings if f.kind == "relation" and "a^k_A3A2" in f.quantities]
    assert rel and "2" in rel[0].message


def test_reversed_coriolis_on_the_shaper_is_caught():
    data = student(SHAPER, 4, coriolis="reversed")
    rep = check(check_from_dict(data, "reversed.toml"))
    fails = {i.quantity for i in rep.items if i.verdict == "fail"}
    assert "a_A3" in fails or "a^r_A3A2" in fails
    # its length was right: only where it points is wrong
    assert all(i.verdict == "pass" for i in rep.items if i.quantity == "a^k_A3A2")
    assert not {q for q in fails if q.startswith(("v_", "omega_"))}


@pytest.mark.parametrize("name", ["shaper", "six_bar", "four_bar", "v_engine"])
def test_checker_tolerance_agrees_with_the_monte_carlo(name):
    """The checker's worst-case stack-up (±0.5 mm, ±0.5°) and the benchmark's Monte Carlo of
    hand drawings with the same limits, at the same student's scales: the 95th percentile and
    the stack-up describe the same drawing, so they stay within a factor of about 3 of each
    other (points found by similarity from a coincident image, d from a3 on the shaper,
    included; Coriolis components carry the velocity plan's reading error in both).  The
    stack-up adds worst cases, so it is the wider one far down a construction (up to ≈3.1×
    at the shaper's ram); it must never be much narrower than what good drawings reach."""
    from plans.accuracy import draftsman

    path = ROOT / "samples" / f"{name}.toml"
    data = student(path, 0)
    rep = check(check_from_dict(data, f"{name}.toml"))
    scene = load_scene(path)
    scales = (1000.0, data["scales"]["velocity"]["mu"], data["scales"]["acceleration"]["mu"])
    compared = 0
    for pos in data["positions"]:
        mc = draftsman.draftsman_errors(scene, pos["phi_deg"], model=draftsman.DraftsmanModel(0.5, 0.5),
                                    samples=3000, seed=7, scales=scales)
        for it in rep.items:
            if it.phi_deg != pos["phi_deg"] or it.quantity not in mc or it.tolerance_model != "draftsman":
                continue
            e = mc[it.quantity]
            ratio = it.tolerance / e.p95_abs
            assert 0.7 < ratio < 3.5, (it.quantity, it.phi_deg, it.tolerance, e.p95_abs)
            compared += 1
    assert compared >= 15


def test_names_of_coincident_points_and_components_in_either_spelling():
    """a^k_A2A3 / a_A3A2^k / v_A3A2 name the same segments as the plan's a^k_A3A2 / v_A2A3."""
    data = student(SHAPER, 5)
    pos = data["positions"][0]
    meas, vals = pos["measured"], pos["values"]
    meas["a^k_A2A3"] = meas.pop("a^k_A3A2")
    vals["a_A3A2^k"] = vals.pop("a^k_A3A2")
    meas["v_A3A2"] = meas.pop("v_A2A3")
    vals["v_A3A2"] = vals.pop("v_A2A3")
    rep = check(check_from_dict(data, "names.toml"))
    phi = pos["phi_deg"]
    ak = [i for i in rep.items if i.phi_deg == phi and i.quantity == "a^k_A2A3"]
    assert ak and ak[0].exact == pytest.approx(value_of(Exact(solve(load_scene(SHAPER), order=2),
                                                               list(load_scene(SHAPER).driver.phis_deg).index(phi)),
                                                         "a^k_A3A2"), rel=1e-9)
    assert {i.quantity for i in rep.items if i.phi_deg == phi} >= {"a^k_A2A3", "a^k_A3A2", "v_A3A2"}
    assert [i.quantity for i in rep.items if i.verdict == "fail"] == []
    assert [f.message for f in rep.findings] == []
