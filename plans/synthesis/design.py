"""The models: each sizes a mechanism from a :class:`~plans.synthesis.model.Task` by the
graphical construction a course draws (kept as data: the extreme positions C′, C″, the
circle on whose arc the chord C′C″ subtends θ, the chosen pivot), then hands the designed
mechanism to :mod:`plans.synthesis.proof` to be measured.  The slider-cranks, the coulisse
and the V-engine are here, the crank-rocker in :mod:`plans.synthesis.four_bar`.

Frames: the scene's.  The crank's pivot O is the origin; a slider-crank's guide runs along
+x (an offset one at distance e on the side that makes the stroke away from O the slow
one); a four-bar's frame O→D lies along +x; a coulisse's pivot C is below O at the centre
distance, the ram's guide horizontal above.  A task with ``sense = "cw"`` is the mirror
image of the counter-clockwise design.

Impossible tasks raise :class:`~plans.errors.InputError` naming the condition not met.
"""

from __future__ import annotations

import cmath
import math

from plans.errors import InputError, Said
from plans.reader import LENGTH_FLOOR, LENGTH_LIMIT

from .four_bar import crank_rocker, three_positions
from .model import Task
from .numeric import golden
from .proof import Coulisse, Measured, Slider, measure
from .record import CHOICES, Design, choice_text, fail, stroke_of
from .record import deg_text as _deg
from .record import mirror as _mirror

__all__ = ["CHOICES", "Design", "choice_text", "design", "fail", "stroke_of", "three_positions"]


# --------------------------------------------------------------------------- slider-crank


def slider_crank(t: Task) -> Design:
    H = stroke_of(t)
    theta = t.theta
    if theta <= 0.0:
        return _central(t, H)
    if theta >= math.pi / 2:
        raise fail(t, "K", Said("sd_gives_offset_slider", K=t.K, v=_deg(theta)))
    # the chord C′C″ = H on the guide, C′ at 0; the circle on which it subtends θ
    hc = H / (2.0 * math.tan(theta))
    R = H / (2.0 * math.sin(theta))
    Oc = complex(H / 2.0, hc)
    t_top = math.atan2(hc, -H / 2.0)  # the pivot right above C′ (AC′ ⟂ guide: a locked limit)
    t_low = math.atan2(-hc, -H / 2.0) + 2.0 * math.pi  # the pivot at C′ itself
    choice = None
    if t.offset is not None:
        e = t.offset
        if not 0.0 < e < 2.0 * hc:
            raise fail(t, "offset", Said("sd_offset_unit_cannot", v=e / t.scale, unit=t.unit, K=t.K, v2=2 * hc / t.scale))
        A = complex(Oc.real - math.sqrt(max(R * R - (e - hc) ** 2, 0.0)), e)
    elif t.lam is not None:
        lam = t.lam
        low = math.tan(theta / 2.0) ** 2
        if lam <= low:
            raise fail(t, "lambda", Said("sd_lam_too_small", lam=lam, K=t.K, low=low))
        # Apollonius' circle of the points with AC″/AC′ = (1 + λ)/(1 − λ), met with the arc
        k = (1.0 + lam) / (1.0 - lam)
        c2 = complex(H, 0.0)
        ac = c2 / (1.0 - k * k)  # (C″ − k²·C′)/(1 − k²), C′ at 0
        ar = k * H / abs(1.0 - k * k)
        met = _meet(Oc, R, ac, ar, upper=True)
        if met is None:
            raise fail(t, "lambda", Said("sd_lam_finds_crank", lam=lam, K=t.K))
        A = met
    else:
        def worst(tp: float) -> float:
            A = Oc + R * cmath.exp(1j * tp)
            a, b = abs(A), abs(A - H)
            return ((b - a) / 2.0 + A.imag) / ((b + a) / 2.0)

        tp, s = golden(worst, t_top, t_low)
        A = Oc + R * cmath.exp(1j * tp)
        best = math.asin(min(s, 1.0))
        if t.pressure_angle_max is not None and best > t.pressure_angle_max:
            raise fail(t, "pressure_angle_max_deg",
                       Said("sd_crank_pivot_arc", v=_deg(t.pressure_angle_max), K=t.K, v2=_deg(best)))
        choice = ("least_pressure", best)
    a, b = abs(A), abs(A - H)
    l1, l2, e = (b - a) / 2.0, (b + a) / 2.0, A.imag
    # to the scene's frame: O at the origin, the guide at y = −e (mirrored for cw)
    s = t.sense
    pts = {"O": 0j, "C1": _mirror(-A, s), "C2": _mirror(H - A, s), "Oc": _mirror(Oc - A, s)}
    mech = Slider(0j, l1, l2, _mirror(complex(0.0, -e), s), 1 + 0j)
    return Design(t, "offset", {"crank": l1, "rod": l2, "offset": e}, (mech,), "away", pts,
                  (pts["Oc"], R), choice)


def _meet(c1: complex, r1: float, c2: complex, r2: float, upper: bool) -> complex | None:
    """The meeting point of two circles left of the chord's start (x < 0), above it."""
    d = c2 - c1
    D = abs(d)
    a = (r1 * r1 - r2 * r2 + D * D) / (2.0 * D)
    h = math.sqrt(max(r1 * r1 - a * a, 0.0))
    base = c1 + a * d / D
    cands = [base + h * 1j * d / D, base - h * 1j * d / D]
    cands = [z for z in cands if (z.imag > 0) == upper]
    return min(cands, key=lambda z: z.real) if cands else None


def _central(t: Task, H: float) -> Design:
    if t.offset:
        raise fail(t, "offset", Said("sd_has_offset_offset"))
    r = H / 2.0
    if t.lam is not None:
        lam = t.lam
        choice = None
    elif t.pressure_angle_max is not None:
        lam = math.sin(t.pressure_angle_max)
        choice = ("lambda_from_pressure", lam)
    else:
        raise fail(t, "lambda", Said("sd_missing_central_slider"))
    l = r / lam
    s = t.sense
    pts = {"O": 0j, "C1": complex(l - r, 0.0), "C2": complex(l + r, 0.0)}
    mech = Slider(0j, r, l, 0j, 1 + 0j)
    del s
    return Design(t, "central", {"crank": r, "rod": l, "offset": 0.0}, (mech,), "away", pts, None, choice)


def v_engine(t: Task) -> Design:
    H = stroke_of(t)
    assert t.lam is not None and t.bank is not None
    r = H / 2.0
    l = r / t.lam
    half = t.bank / 2.0
    uB = cmath.exp(1j * (math.pi / 2 - half))
    uC = cmath.exp(1j * (math.pi / 2 + half))
    mechs = (Slider(0j, r, l, 0j, uB), Slider(0j, r, l, 0j, uC))
    pts = {"O": 0j, "B1": (l - r) * uB, "B2": (l + r) * uB, "C1": (l - r) * uC, "C2": (l + r) * uC}
    return Design(t, "v_engine", {"crank": r, "rod": l}, mechs, "away", pts, None, None)


# --------------------------------------------------------------------------- coulisse


def coulisse(t: Task) -> Design:
    """l1 = l0·sin(θ/2) (the coulisse swings by ψ = θ, tangent to the crank circle at its
    extremes), CD = H/(2 sin(θ/2)), the ram's guide through the middle of the sagitta of D's
    arc, the rod DE from [ϑ]: sin ϑ_max = (f/2)/DE."""
    assert t.stroke is not None and t.centre_distance is not None
    H, l0, theta = t.stroke, t.centre_distance, t.theta
    half = theta / 2.0
    if math.sin(half) > 1.0 - 1e-9:
        raise fail(t, "K", Said("sd_puts_crank_circle", K=t.K, v=_deg(theta)))
    l1 = l0 * math.sin(half)
    l3 = H / (2.0 * math.sin(half))
    if l3 < l0 + l1:
        raise fail(t, "stroke", Said("sd_coulisse_cd_sin", v=l3 / t.scale, unit=t.unit, v2=(l0 + l1) / t.scale))
    low = l3 * math.cos(half)  # D's height at the extremes
    sag = l3 - low
    choice = None
    if t.ram_group == "RPP":
        return _coulisse_rpp(t, l0, l1, l3, half, low)
    if t.guide_height is not None:
        h = t.guide_height
        dev = max(l3 - h, h - low)
    else:
        h = (l3 + low) / 2.0
        dev = sag / 2.0
        choice = ("mid_sagitta", 0.0)  # its pressure angle filled in once the rod is known
    if t.rod is not None:
        l4 = t.rod
        if l4 <= dev:
            raise fail(t, "rod", Said("sd_rod_de_unit", v=l4 / t.scale, unit=t.unit, v2=dev / t.scale))
        if t.pressure_angle_max is not None and math.asin(dev / l4) > t.pressure_angle_max:
            raise fail(t, "pressure_angle_max_deg", Said("sd_rod_de_unit2", v=l4 / t.scale, unit=t.unit, v2=_deg(math.asin(dev / l4))))
    else:
        assert t.pressure_angle_max is not None
        l4 = dev / math.sin(t.pressure_angle_max) if dev > 0 else l3 / 4.0
    if choice is not None:
        choice = ("mid_sagitta", math.asin(min(dev / l4, 1.0)))
    C = complex(0.0, -l0)  # the scene's frame has O at the origin
    pts = {"O": 0j, "C": C, "D1": C + l3 * cmath.exp(1j * (math.pi / 2 + half)),
           "D2": C + l3 * cmath.exp(1j * (math.pi / 2 - half)),
           "A1": l1 * cmath.exp(1j * (math.pi + half)), "A2": l1 * cmath.exp(-1j * half)}
    mech = Coulisse(0j, C, l1, l3, l4, complex(0.0, h - l0), 1 + 0j)
    return Design(t, "coulisse", {"crank": l1, "centre_distance": l0, "coulisse": l3, "rod": l4,
                                  "guide_height": h}, (mech,), "+" if t.sense < 0 else "-", pts, None, choice)


def _coulisse_rpp(t: Task, l0: float, l1: float, l3: float, half: float, low: float) -> Design:
    """The RPP ram: a block at D slides in the ram's slot ⟂ its guide, so the ram follows D's
    x; the force on the coulisse is along the guide, D's velocity ⟂ CD: the pressure angle is
    the coulisse's tilt, θ/2 at the extremes, whatever the guide's height."""
    if t.pressure_angle_max is not None and half > t.pressure_angle_max:
        raise fail(t, "pressure_angle_max_deg", Said("sd_rpp_ram_pressure", v=_deg(half), v2=_deg(t.pressure_angle_max)))
    h = t.guide_height if t.guide_height is not None else (l3 + low) / 2.0
    C = complex(0.0, -l0)
    pts = {"O": 0j, "C": C, "D1": C + l3 * cmath.exp(1j * (math.pi / 2 + half)),
           "D2": C + l3 * cmath.exp(1j * (math.pi / 2 - half)),
           "A1": l1 * cmath.exp(1j * (math.pi + half)), "A2": l1 * cmath.exp(-1j * half)}
    mech = Coulisse(0j, C, l1, l3, 0.0, complex(0.0, h - l0), 1 + 0j)
    return Design(t, "coulisse", {"crank": l1, "centre_distance": l0, "coulisse": l3, "guide_height": h},
                  (mech,), "+" if t.sense < 0 else "-", pts, None, None)


# --------------------------------------------------------------------------- all


MODELS = {"slider_crank": slider_crank, "crank_rocker": crank_rocker, "coulisse": coulisse, "v_engine": v_engine}


def _met(t: Task, d: Design, measured: tuple[Measured, ...]) -> None:
    """The task's K, stroke and swing as the designed mechanism measures them (to 1e-7: the
    proof finds them to 1e-12 and better; a miss is a task the model cannot meet)."""
    for m in measured:
        if not m.full_rotation:
            continue
        if d.model != "three_positions" and abs(m.K - t.K) > 1e-7 * t.K:
            raise fail(t, "K", Said("sd_designed_mechanism_gives", K=m.K, K2=t.K, v=t.mechanism.replace('_', '-')))
        if t.mechanism == "crank_rocker" and d.model != "three_positions" and t.swing is not None \
                and m.swing is not None and abs(m.swing - t.swing) > 1e-7:
            raise fail(t, "swing_deg", Said("sd_designed_mechanism_swings", v=_deg(m.swing), v2=_deg(t.swing)))
        if m.stroke is not None and t.mechanism != "crank_rocker":
            H = stroke_of(t)
            if abs(m.stroke - H) > 1e-7 * H:
                raise fail(t, "stroke", Said("sd_designed_mechanism_stroke", v=m.stroke / t.scale, unit=t.unit, v2=H / t.scale))


def design(t: Task) -> Design:
    """Size the mechanism and prove it: the measured K, stroke or swing, γ_min; a design that
    does not turn fully on one branch is refused (it never is, when the model is right)."""
    if 0.0 < t.theta < 1e-6:  # the construction's circle would be a million strokes across
        raise fail(t, "K", Said("sd_so_close_rad", K=t.K))
    d = MODELS[t.mechanism](t)
    for name, v in d.lengths.items():
        if v and not LENGTH_FLOOR <= v <= LENGTH_LIMIT:
            raise fail(t, "mechanism", Said("sd_design_name_would", name=name, v=v))
    sense = t.sense
    measured = tuple(measure(m, sense, d.working) for m in d.mechs)
    _met(t, d, measured)
    for m in measured:
        if not m.full_rotation:
            raise InputError(Said("sd_designed_mechanism_does", margin=m.margin, extremes=m.extremes), file=t.path, field="mechanism")
    return Design(d.task, d.model, d.lengths, d.mechs, d.working, d.points, d.circle, d.choice, measured,
                  d.notes)
