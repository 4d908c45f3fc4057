"""Machine dynamics over the steady cycle, as seed 004 draws it, checked exactly.

The machine is reduced to the crank (the link of reduction, angle φ):

* velocity analogues v_X/ω1, ω_i/ω1 (lengths on a plan drawn for ω1 = 1);
* I_pr(φ) = I_A + Σ [m_i (v_Si/ω1)² + I_Si (ω_i/ω1)²], one row per term;
* M_pr(φ) = Σ [F·v + M ω] / |ω1| over every load the scene applies except inertia and
  the driving moment (gravity, gas and indicator diagrams, external forces and moments):
  the loads' power over |ω1|, **positive when the loads drive the crank** (seed 004's
  sheet prints the opposite sign for resisting loads; :data:`SIGN_RULE`);
* the constant driving moment M_d = −(1/Φ) ∮ M_pr dφ over the working cycle Φ (2π, or 4π
  for a four-stroke engine: ``[dynamics] cycle_deg = 720``; the cycle's work balances);
  A_c(φ) = ∫ M_pr dφ, A_d(φ) = M_d (φ − φ0), ΔT = A_c + A_d;
* the flywheel: the Wittenbauer energy–mass diagram (ΔT against I_pr) with tangents at
  tan ψ = ω_m²(1 ± δ)/2, I_fw = kl/(ω_m² δ) (graphical: over the table's positions,
  the curves joined through the points as a French curve joins them, :mod:`.spline`);
  Merkalov's method; and the exact one.

Exact flywheel.  With ω_max,min = ω_m (1 ± δ/2), ω(φ) ≤ ω_max everywhere and = somewhere
means 2E0 = ω_max² I_fw + min_φ (ω_max² I_pr − 2ΔT), and likewise for ω_min with the max:
subtracting, I_fw = [max_φ(ω_min² I_pr − 2ΔT) − min_φ(ω_max² I_pr − 2ΔT)] / (ω_max² − ω_min²),
the Wittenbauer construction with the exact slopes ω²/2 on the exact curve.  The motion
½ (I_fw + I_pr) ω² = E0 + ΔT is then integrated for any flywheel (E0 such that
(ω_max + ω_min)/2 = ω_m) to give the achieved δ.  The work is integrated and the extremes
found by :mod:`.quadrature` (to 1e-9 and better, with the quadrature's stated bound).
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field, replace
from typing import Any, cast

import numpy as np
from numpy.typing import NDArray

from plans.errors import InputError, Said
from plans.forces.loads import Loads, apply_loads, parse_loads
from plans.kinematics.construction import nice_scale
from plans.kinematics.exact import Kinematics, solve
from plans.kinematics.structure import Structure, analyse
from plans.language import TERMS
from plans.scene.model import Scene
from plans.tolerances import EXACT_ZERO_REL

from . import quadrature, spline
from .spec import DynamicsSpec, dynamics_spec

R = NDArray[np.float64]

SIGN_RULE = TERMS["y_sign_rule"][0].strip()  # in both languages in the catalogue (the table's line)

_POLES = (10.0, 12.0, 15.0, 20.0, 25.0, 30.0, 40.0, 50.0, 60.0, 80.0, 100.0, 120.0, 150.0, 200.0)


@dataclass(frozen=True, slots=True)
class Row:
    """One row of a table over positions: a label, its unit and a value per position."""

    key: str  # machine name: "m2_vS2", "I2_w2", "G3", ...
    label: str  # textbook notation: "m_2 (v_S2/ω_1)^2"
    unit: str
    values: R
    link: int | None = None


@dataclass(frozen=True, slots=True)
class Reduced:
    """Reduced quantities at a set of crank angles."""

    phi_deg: R
    I_pr: R  # kg·m², rotor included
    M_pr: R  # N·m, positive when the loads drive the crank
    inertia_rows: tuple[Row, ...]  # the rotor, then per link
    load_rows: tuple[Row, ...]  # M_pr of each load
    analogue_rows: tuple[Row, ...]  # v_X/ω1 (m), ω_i/ω1
    constant_inertia: float  # the part of I_pr that does not vary (rotor, crank)


@dataclass(frozen=True, slots=True)
class Flywheel:
    delta: float
    omega_mean: float
    inertia_exact: float  # kg·m² added at the crank on top of I_pr
    inertia_graphical: float  # Wittenbauer over the table's positions (chords, textbook slopes)
    inertia_merkalov: float
    delta_achieved: float  # by the graphical flywheel, exact integration of the motion
    delta_achieved_exact: float  # by the exact flywheel (= delta, to the integration's accuracy)
    delta_achieved_merkalov: float
    graphical_bound: float = 0.0  # kg·m², |I_graphical − I_exact| stays within it (Wittenbauer's own)
    work_bound: float = 0.0  # J, of the exact integration of the loads' work over the cycle

    @property
    def graphical_error(self) -> float:
        """(I_graphical − I_exact)/I_exact."""
        return (self.inertia_graphical - self.inertia_exact) / self.inertia_exact if self.inertia_exact else 0.0


@dataclass(frozen=True, slots=True)
class Wittenbauer:
    """The energy–mass diagram as drawn: the smooth closed curve through the table's points,
    the tangent slopes (SI, J per kg·m²) and their intercepts k, l on the ΔT axis (I_pr = 0)."""

    I: R  # I_pr along the curve (closed: first repeated last)
    dT: R
    slope_max: float  # tan ψ_max in SI: ω_m²(1 + δ)/2
    slope_min: float
    k: float  # J, intercept of the ψ_max tangent
    l: float  # J, intercept of the ψ_min tangent
    touch_max: int  # index of the tangency point
    touch_min: int


@dataclass(frozen=True, slots=True)
class Scales:
    """The scales of the dynamics sheet, as the course writes them (mm per unit)."""

    phi: float  # μ_φ, mm per rad
    M: float  # μ_M, mm per N·m
    H: float  # pole distance, mm
    A: float  # μ_A = μ_M μ_φ / H, mm per J
    I: float  # μ_I, mm per kg·m²
    analogue: float  # μ of the plans of analogues, mm per m (of v/ω1)


@dataclass(frozen=True)
class Dynamics:
    """The whole dynamics of a scene; arrays over positions (frozen: a page can read them)."""

    scene: Scene
    spec: DynamicsSpec
    table: Reduced  # at the table's positions (the graphical method's nodes, closing 360° added)
    exact: Reduced  # on the dense grid of the exact integration
    M_driving: float  # constant driving moment, N·m (graphical: from the table's chords)
    M_driving_exact: float
    A_c: R  # graphical work of the loads at the table's nodes, J
    A_d: R
    dT: R
    A_c_exact: R
    dT_exact: R
    wittenbauer: Wittenbauer
    flywheel: Flywheel
    omega: R  # ω(φ) on the exact grid with the graphical flywheel
    omega_exact: R  # with the exact flywheel
    scales: Scales
    notes: tuple[str, ...] = field(default=())

    def at(self, axis_mm: float, height: float) -> Dynamics:
        """The same dynamics drawn at another φ axis (mm for 360°) and diagram height (times the
        A1 one): only the sheet's round scales change (:func:`drawn_scales`)."""
        return replace(self, scales=drawn_scales(self.scene, self.spec, self.table, self.A_c, self.A_d, self.dT,
                                                 axis_mm, height))


# --------------------------------------------------------------------------- reduction


def reduce(scene: Scene, loads: Loads, kin: Kinematics, rotor: float) -> Reduced:
    """I_pr, M_pr, their rows and the velocity analogues at the positions of ``kin`` (order 2)."""
    d = scene.driver
    w = np.abs(kin.omega(d.link))
    n = kin.n
    rows: list[Row] = [Row("I_A", "I_A", "kg*m^2", np.full(n, rotor))]
    const = rotor
    for lid in sorted(scene.links):
        m, inert = loads.masses[lid], loads.inertias[lid]
        if lid not in loads.centres:
            continue
        s = loads.centres[lid]
        v = kin.point_on(lid, scene.links[lid].points[s])[1]
        if m > 0:
            val = m * (np.abs(v) / w) ** 2
            rows.append(Row(f"m{lid}_v{s}", f"m_{lid} (v_{s}/ω_1)^2", "kg*m^2", val, lid))
            if lid == d.link:
                const += float(val[0])
        if inert > 0:
            val = inert * (kin.omega(lid) / w) ** 2
            rows.append(Row(f"I{lid}_w{lid}", f"I_S{lid} (ω_{lid}/ω_1)^2", "kg*m^2", val, lid))
            if lid == d.link:
                const += float(val[0])
    I_pr = np.sum([r.values for r in rows], axis=0)
    applied = apply_loads(scene, loads, kin)
    load_rows: list[Row] = []
    for f in applied.forces:
        if f.kind == "inertia":
            continue
        v = kin.point_on(f.link, cast(Any, f.local))[1]  # local coordinates per position
        load_rows.append(Row(f.label, f.label, "N*m", (f.F * np.conj(v)).real / w, f.link))
    for mo in applied.moments:
        if mo.kind == "inertia":
            continue
        load_rows.append(Row(mo.label, mo.label, "N*m", mo.M * kin.omega(mo.link) / w, mo.link))
    M_pr = np.sum([r.values for r in load_rows], axis=0) if load_rows else np.zeros(n)
    return Reduced(np.asarray(kin.phi_deg, float), I_pr, M_pr, tuple(rows), tuple(load_rows),
                   tuple(analogues(scene, kin)), const)


def analogues(scene: Scene, kin: Kinematics) -> list[Row]:
    """v_X/ω1 of every moving point and centre (m), ω_i/ω1 of every link that turns."""
    w = np.abs(kin.omega(scene.driver.link))
    out: list[Row] = []
    seen: set[str] = set()
    for lid in sorted(scene.links):
        link = scene.links[lid]
        for name, z in link.points.items():
            if name in seen or name in scene.frame_points:
                continue
            seen.add(name)
            v = kin.point_on(lid, z)[1]
            out.append(Row(f"v_{name}", f"v_{name}/ω_1", "m", np.abs(v) / w, lid))
    for lid in sorted(scene.links):
        om = kin.omega(lid) / w
        if lid != scene.driver.link and np.max(np.abs(om)) > EXACT_ZERO_REL:
            out.append(Row(f"omega_{lid}", f"ω_{lid}/ω_1", "1", np.abs(om), lid))
    return out


# --------------------------------------------------------------------------- work and energy


def cumulative(phi_rad: R, y: R) -> R:
    """∫ y dφ from the first node, by chords (the mean ordinate of each interval)."""
    out = np.zeros_like(y)
    out[1:] = np.cumsum(0.5 * (y[1:] + y[:-1]) * np.diff(phi_rad))
    return out


def _driving(scene: Scene, spec: DynamicsSpec, A_end: float, scale: float, cycle: float = 360.0) -> float:
    need = -A_end / math.radians(cycle)
    if spec.driving is None:
        return need
    given = spec.driving * (1 if scene.driver.omega > 0 else -1)
    if abs(given - need) > 1e-3 * max(scale, 1e-300):
        raise InputError(Said("cd_driving_moment_driving", driving=spec.driving, need=need), file=scene.path,
                         field="dynamics.driving")
    return given


def _extreme(y: R, k: int) -> float:
    """The extreme of a smooth sampled function near node k (parabola through k−1, k, k+1)."""
    n = len(y)
    if n < 3:
        return float(y[k])
    a, b, c = y[(k - 1) % n], y[k], y[(k + 1) % n]
    den = a - 2 * b + c
    if den == 0:
        return float(b)
    t = 0.5 * (a - c) / den
    if abs(t) > 1:
        return float(b)
    return float(b - 0.25 * (a - c) * t)


def exact_flywheel(I_pr: R, dT: R, omega_m: float, delta: float) -> float:
    """I_fw from the closed form (module docstring) on a closed periodic grid (last = first)."""
    wmax2 = (omega_m * (1 + delta / 2)) ** 2
    wmin2 = (omega_m * (1 - delta / 2)) ** 2
    g_hi = (wmin2 * I_pr - 2 * dT)[:-1]
    g_lo = (wmax2 * I_pr - 2 * dT)[:-1]
    hi = _extreme(g_hi, int(np.argmax(g_hi)))
    lo = _extreme(g_lo, int(np.argmin(g_lo)))
    return (hi - lo) / (wmax2 - wmin2)


def wittenbauer(I_pr: R, dT: R, omega_m: float, delta: float) -> tuple[Wittenbauer, float]:
    """Tangents at tan ψ = ω_m²(1 ± δ)/2 to the points (I_pr, ΔT); I_fw = kl/(ω_m² δ)."""
    s_max = omega_m**2 * (1 + delta) / 2
    s_min = omega_m**2 * (1 - delta) / 2
    up = dT - s_max * I_pr
    lo = dT - s_min * I_pr
    i, j = int(np.argmax(up)), int(np.argmin(lo))
    k, l = float(up[i]), float(lo[j])
    return Wittenbauer(I_pr, dT, s_max, s_min, k, l, i, j), (k - l) / (omega_m**2 * delta)


def merkalov(I_pr: R, I_const: float, dT: R, omega_m: float, delta: float) -> float:
    """Merkalov: ΔT less the variable part's energy I_II ω_m²/2; I_fw = (max − min)/(ω_m² δ) − I_I."""
    rest = dT - (I_pr - I_const) * omega_m**2 / 2
    return float(np.max(rest) - np.min(rest)) / (omega_m**2 * delta) - I_const


# --------------------------------------------------------------------------- the whole


def _pole(mu_M: float, mu_phi: float, A_range: float, target_mm: float = 60.0) -> float:
    if A_range <= 0:
        return 40.0
    want = mu_M * mu_phi * A_range / target_mm
    for H in _POLES:
        if H >= want:
            return H
    return _POLES[-1]


def dynamics(scene: Scene, spec: DynamicsSpec | None = None, structure: Structure | None = None,
             loads: Loads | None = None, axis_mm: float = 240.0, height: float = 1.0) -> Dynamics:
    """Everything of the dynamics sheet for a scene with ``[dynamics]``."""
    spec = spec or dynamics_spec(scene)
    loads = loads if loads is not None else parse_loads(scene)
    st = structure or analyse(scene)
    phi0, cycle = spec.phi_deg[0], spec.cycle_deg
    _check_cycle(scene, loads, cycle)
    nodes = np.append(np.asarray(spec.phi_deg, float), phi0 + cycle)
    grid = phi0 + np.linspace(0.0, cycle, spec.exact_steps + 1)
    kin = solve(scene, np.concatenate([nodes, grid]), order=2, structure=st)
    both = reduce(scene, loads, kin, spec.rotor_inertia)
    m = len(nodes)
    tab, ex = _split(both, slice(0, m)), _split(both, slice(m, None))
    if not np.any(ex.M_pr != 0):
        raise InputError(Said("cd_scene_applies_load"), file=scene.path, field="loads")
    omega_m = abs(scene.driver.omega)
    delta = spec.delta
    rad = np.radians(nodes - phi0)
    # the draftsman's smooth curve through the points: the mean ordinate of each interval is
    # the curve's, and the tangents of the energy–mass diagram touch the curve
    A_c = np.append(0.0, np.cumsum(spline.interval_integrals(rad, tab.M_pr, spline.slopes(rad, tab.M_pr))))
    rad_e = np.radians(grid - phi0)
    machine = quadrature.Machine(scene, loads, st, spec.rotor_inertia, phi0, cycle)
    work = quadrature.integrate(machine, grid)
    A_c_e = work.A_c
    M_d_e = _driving(scene, spec, float(A_c_e[-1]), float(np.max(np.abs(ex.M_pr))), cycle)
    dT_e = A_c_e + M_d_e * rad_e
    if np.ptp(dT_e) <= EXACT_ZERO_REL * float(np.max(np.abs(ex.M_pr))) * math.radians(cycle):
        raise InputError(Said("cd_loads_moment_does"), file=scene.path, field="loads")
    # a given driving moment balances the exact work; the graphical one is read off A_c's end
    M_d = -float(A_c[-1]) / math.radians(cycle) if spec.driving is None else M_d_e
    A_d = M_d * rad
    dT = A_c + A_d
    per = max(1, 240 // len(rad))
    _, I_curve = spline.sample(rad, tab.I_pr, spline.slopes(rad, tab.I_pr), per)
    _, T_curve = spline.sample(rad, dT, spline.slopes(rad, dT), per)
    wit, I_graph = wittenbauer(I_curve, T_curve, omega_m, delta)
    ext = quadrature.Extremes(machine, work, M_d_e)
    I_ex, hi, lo = quadrature.flywheel(ext, ex.I_pr, dT_e, omega_m, delta)
    I_mer = merkalov(I_curve, tab.constant_inertia, T_curve, omega_m, delta)
    phi_curve = phi0 + np.degrees(spline.sample(rad, dT, spline.slopes(rad, dT), per)[0])
    bound = quadrature.wittenbauer_bound(ext, phi_curve, I_curve, T_curve, omega_m, delta, hi, lo)
    notes: list[Any] = []  # the protocol's sentences (plans.phrases.Phrase)
    if I_ex < 0:
        from plans.phrases import phrase

        notes.append(phrase("y_no_flywheel", d=delta))
    om_g, d_g = quadrature.motion(ext, ex.I_pr, dT_e, _usable(I_graph, ex.I_pr), omega_m)
    om_e, d_e = quadrature.motion(ext, ex.I_pr, dT_e, _usable(I_ex, ex.I_pr), omega_m)
    _, d_m = quadrature.motion(ext, ex.I_pr, dT_e, _usable(I_mer, ex.I_pr), omega_m)
    fw = Flywheel(delta, omega_m, I_ex, I_graph, I_mer, d_g, d_e, d_m, bound, work.bound)
    out = Dynamics(scene, spec, tab, ex, M_d, M_d_e, A_c, A_d, dT, A_c_e, dT_e, wit, fw, om_g, om_e,
                   drawn_scales(scene, spec, tab, A_c, A_d, dT, axis_mm, height), tuple(notes))
    spline.freeze(out)
    return out


def drawn_scales(scene: Scene, spec: DynamicsSpec, tab: Reduced, A_c: R, A_d: R, dT: R, axis_mm: float = 240.0,
                 height: float = 1.0) -> Scales:
    """The sheet's scales: μ_φ from the φ axis (``axis_mm`` for 360°), round μ_M and μ_I and a
    pole from the course's list for diagrams ``height`` times the A1 ones (< 1 on small sheets,
    > 1 where an A1 sheet has room), μ_A = μ_M μ_φ / H."""
    cycle = spec.cycle_deg
    # the φ axis of a four-stroke cycle is half as long again: 1 mm for every 2° of 720°
    mu_phi = axis_mm * (1.5 if cycle == 720 else 1.0) / math.radians(cycle)
    mu_M = nice_scale(float(np.max(np.abs(tab.M_pr))) or 1.0, 50.0 * height)
    A_range = float(max(np.max(np.abs(A_c)), np.max(np.abs(A_d)), np.ptp(dT)))
    H = spec.pole_mm or _pole(mu_M, mu_phi, A_range, 60.0 * height)
    mu_A = mu_M * mu_phi / H
    mu_I = nice_scale(float(np.max(tab.I_pr)), 120.0 * height)
    crank = scene.links[scene.driver.link]
    mu_an = nice_scale(crank.length or 1.0, 70.0)
    return Scales(mu_phi, mu_M, H, mu_A, mu_I, mu_an)


def _usable(I_fw: float, I_pr: R) -> float:
    """A flywheel the motion can be integrated with: none when it comes out negative, and
    never a machine with no inertia at all somewhere in the cycle."""
    I_fw = max(I_fw, 0.0)
    if I_fw + float(np.min(I_pr)) <= 0:
        I_fw = 1e-12 * max(float(np.max(I_pr)), 1e-300)
    return I_fw


def _check_cycle(scene: Scene, loads: Loads, cycle: float) -> None:
    """Loads given over a four-stroke cycle need the 720° dynamics, and a diagram over 720°
    cannot close a cycle of one revolution."""
    if cycle == 720:
        return
    for gl in loads.gas:
        if gl.fires is not None or gl.period == 720:
            raise InputError(Said("cd_name_given_over", name=gl.name),
                             file=scene.path, field="dynamics.cycle_deg")
    for ml in loads.moments:
        if ml.period == 720 and (ml.table is not None or ml.expression is not None):
            raise InputError(Said("cd_name_given_over2", name=ml.name), file=scene.path,
                             field="dynamics.cycle_deg")


def _split(red: Reduced, sl: slice) -> Reduced:
    def cut(rows: tuple[Row, ...]) -> tuple[Row, ...]:
        return tuple(Row(r.key, r.label, r.unit, r.values[sl], r.link) for r in rows)

    return Reduced(red.phi_deg[sl], red.I_pr[sl], red.M_pr[sl], cut(red.inertia_rows), cut(red.load_rows),
                   cut(red.analogue_rows), red.constant_inertia)
