"""Zhukovsky's lever and the power balance: the balancing load without any reaction.

Turn the velocity plan 90° about its pole (sense from ``[loads] lever_turn``):
the image of point X is w_X = ±i·μv·v_X.  A force F applied at X, moved parallel
to itself to w_X, has the moment cross(w_X, F) = ∓μv (F·v_X) about the pole, so
the lever's moment equation Σ cross(w, F) = 0 *is* the power balance
Σ F·v + Σ M·ω + F_bal·v_A = 0 (d'Alembert + virtual work).  Inertia moments
become couples M/l ⟂ the link at the images of its two joints.  The balancing
force ⟂ crank at its point follows from the moment sum about the pole.
"""

from __future__ import annotations

from dataclasses import field
from typing import Any

import numpy as np
from numpy.typing import NDArray

from plans.forces.loads import AppliedMoment
from plans.forces.polygons import ForceAnalysis, ForcePolygon, force_polygons
from plans.forces.shared import RULER_MM, mu_force, nice_scale, safe_div, unit_vector
from plans.kinematics.plan import ConstructionLine, Plan, PlanPoint, Segment, Step
from plans.kinematics.scales import round_scale
from plans.lines import cross
from plans.phrases import phrase, say
from plans.records import frozen
from plans.tolerances import EXACT_ZERO_REL
from plans.units import clean, percent

C = NDArray[np.complex128]
R = NDArray[np.float64]


@frozen
class LeverForce:
    """A force on the lever: ``F`` (N) at the image ``w`` (plan mm) of its point."""

    label: str  # "Phi2", "P3", "M_Phi2'" (one force of a couple)
    link: int
    point: str  # image name on the plan ("s2", "b", ...)
    w: C  # plan mm
    F: C  # N
    moment: R  # cross(w, F), N·mm about the pole
    #: the arm once worked out (it is read only where a position is drawn or printed)
    _arm: list = field(default_factory=list, repr=False, compare=False)

    @property
    def arm(self) -> R:
        """|moment| / |F|, mm (0 for a zero force)."""
        if not self._arm:
            self._arm.append(safe_div(np.abs(self.moment), np.abs(self.F)))
        return self._arm[0]


@frozen
class LeverAnalysis:
    """Zhukovsky's lever: the velocity plan turned 90° with every load on it, over positions."""

    fa: ForceAnalysis
    scale: float  # μv of the plan, mm per m/s
    turn: int  # +1: velocity plan turned 90° ccw, −1: cw
    forces: tuple[LeverForce, ...]
    bal_point: str  # image of the balancing point ("a")
    w_bal: C  # plan mm
    unit_moment: R  # lever moment of a unit balancing load (F_bal = 1 N along e_bal, or M = 1 N·m)
    arm_bal: R  # mm (force mode)
    by_lever: R  # balancing load, along e_bal (N) or ccw (N·m), from the lever
    by_power: R  # same, from Σ F·v + Σ M·ω + F_bal·v_A = 0
    valid: NDArray[np.bool_]  # False where the crank stands still (ω1 = 0): no lever, no power

    def signed(self, x: R) -> R:
        """Along the motion of the balancing point (the convention of the JSON)."""
        return self.fa.sense * x


#: Local coordinates the same at every position (a point's velocity image kept by them).
_NUMBERS = (complex, float, int)


def _image_name(point: str) -> str:
    return point.lower()


def zhukovsky_lever(fa: ForceAnalysis, scale: float | None = None) -> LeverAnalysis:
    """The lever of every position of ``fa`` (vectorised), balancing load two more ways."""
    scene, kin, loads = fa.scene, fa.kin, fa.loads
    n = kin.n
    turn = loads.lever_turn
    if scale is None:
        scale = scene.scales.get("velocity") or _auto_scale(fa)
    rot = turn * 1j * scale

    items: list[LeverForce] = []
    power = np.zeros(n)

    images: dict[tuple, tuple[C, C]] = {}  # a point's v and image, once for all the forces there

    def add(label: str, link: int, point: str, local: Any, F: C) -> C:  # local: complex or per position
        key = (link, local) if type(local) in _NUMBERS else None
        got = None if key is None else images.get(key)
        if got is None:
            _, v, _ = kin.point_on(link, local)
            assert v is not None
            got = (v, rot * v)
            if key is not None:
                images[key] = got
        v, w = got
        mom = cross(w, F)
        items.append(LeverForce(label, link, point, w, F, mom))
        return v

    for f in fa.applied.forces:
        # at a named point the same local coordinates at every position: its v read once
        local = scene.links[f.link].points.get(f.point, f.local)
        v = add(f.label, f.link, _image_name(f.point), local, f.F)
        power += (f.F.conjugate() * v).real  # F·v
    arms: dict[int, tuple] = {}  # a link's two joints and its length, once for all its couples
    for m in _on_the_lever(fa.applied.moments, kin):
        for label, link, pt, local, F in _couple(fa, m, arms):
            add(label, link, pt, local, F)
        power += m.M * kin.omega(m.link)  # M·ω, not through the couple's forces

    crank = fa.crank
    link1 = scene.driver.link
    z_bal = scene.links[link1].points[crank.point]
    _, v_bal, _ = kin.point_on(link1, z_bal)
    assert v_bal is not None
    w_bal = rot * v_bal
    total = np.zeros(n)
    for it in items:
        total += it.moment
    omega1 = kin.omega(link1)
    valid = omega1 != 0
    arm_bal = np.abs(cross(w_bal, crank.e_bal))  # a moment is drawn as ±M/l at o and at this point
    if crank.kind == "force":
        unit = cross(w_bal, crank.e_bal)
        unit_power = (crank.e_bal.conjugate() * v_bal).real
    else:
        # a unit couple on the crank: its lever moment is ∓μv ω1, its power ω1
        unit = -turn * scale * omega1
        unit_power = omega1
    by_lever = safe_div(-total, unit)
    by_power = safe_div(-power, unit_power)
    return LeverAnalysis(fa, float(scale), turn, tuple(items), _image_name(crank.point), w_bal,
                         unit, arm_bal, by_lever, by_power, valid)


def _auto_scale(fa: ForceAnalysis) -> float:
    """μv of the velocity plan (the lever is that plan turned), or, without the construction
    module, the fastest point's image 80–100 mm long."""
    kin = fa.kin
    try:
        from plans.kinematics.construction import default_scales
    except ImportError:  # pragma: no cover - the construction module is optional here
        pass
    else:
        return float(default_scales(kin)[0])
    fastest = 0.0
    for lid, link in fa.scene.links.items():
        for z in link.points.values():
            _, v, _ = kin.point_on(lid, z)
            assert v is not None
            fastest = max(fastest, float(np.max(np.abs(v))))
    return nice_scale(fastest)


def _on_the_lever(moments: tuple[AppliedMoment, ...], kin: Any) -> list[AppliedMoment]:
    """The couples as the lever takes them: a link's friction couples (one per pin) summed
    into one, M_f of that link (the lever moment and the power are the sum's); none on a
    link that only translates (ω = 0: no lever moment, no power)."""
    out: list[AppliedMoment] = []
    friction: dict[int, AppliedMoment] = {}
    turns: dict[int, bool] = {}
    for m in moments:
        if m.kind != "friction":
            out.append(m)
            continue
        if m.link not in turns:
            turns[m.link] = bool(np.any(kin.omega(m.link)))
        if not turns[m.link]:
            continue
        if m.link in friction:
            was = friction[m.link]
            friction[m.link] = AppliedMoment(was.label, m.link, was.M + m.M, "friction")
        else:
            friction[m.link] = AppliedMoment(f"M_f{m.link}", m.link, m.M, "friction")
    return out + list(friction.values())


def _couple(fa: ForceAnalysis, m: AppliedMoment, arms: dict[int, tuple] | None = None):
    """M on a link as two forces ±M/l ⟂ the link at its two joints (textbook form).  ``arms``:
    each link's joints, images and length kept for its next couple (the same numbers)."""
    got = None if arms is None else arms.get(m.link)
    if got is None:
        got = _arm(fa, m.link)
        if arms is not None:
            arms[m.link] = got
    zX, zY, iX, iY, l, u = got
    f = m.M / l * 1j * u  # cross(Y − X, f) = M
    return ((f"{m.label}'", m.link, iY, zY, f),
            (f"{m.label}''", m.link, iX, zX, -f))


def _arm(fa: ForceAnalysis, lid: int) -> tuple:
    """A link's two joints (local coordinates and images), their distance and direction."""
    scene, kin = fa.scene, fa.kin
    link = scene.links[lid]
    if len(link.axis) == 2:
        zX, zY = link.points[link.axis[0]], link.points[link.axis[1]]
        nX, nY = link.axis
    else:  # a slider: a unit arm along its local x axis, from its pin
        zX, zY = link.points[link.axis[0]], link.points[link.axis[0]] + 1.0
        nX, nY = link.axis[0], link.axis[0] + "'"
    X = kin.point_on(lid, zX)[0]
    Y = kin.point_on(lid, zY)[0]
    XY = Y - X
    return zX, zY, _image_name(nX), _image_name(nY), np.abs(XY), unit_vector(XY)


# --------------------------------------------------------------------------- drawing


def lever_plan(lv: LeverAnalysis, k: int) -> Plan:
    """The lever of position k as a plan: rotated images, forces at them, arms, protocol."""
    fa = lv.fa
    kin = fa.kin
    pts: dict[str, tuple[float, float]] = {"p": (0.0, 0.0)}
    segs: list[Segment] = []
    lines: list[ConstructionLine] = []
    steps: list[Step] = [Step.of("lay off", (), "p", phrase(
        "l_turn", sense=phrase("ccw" if lv.turn > 0 else "cw"), mu=lv.scale))]
    # force vectors drawn at a common force scale, only for the picture
    fmax = max([float(np.abs(it.F[k])) for it in lv.forces] + [abs(float(lv.by_lever[k]))], default=0.0)
    mu_f = round_scale(fmax, 30.0) if fmax > 0 else 1.0  # a round μF, the largest ≤ 30 mm
    for it in lv.forces:
        w = complex(it.w[k])
        pts.setdefault(it.point, (w.real, w.imag))
        F = complex(it.F[k])
        if F == 0:
            continue
        tip = f"{it.label}>"
        end = w + F * mu_f
        pts[tip] = (end.real, end.imag)
        segs.append(Segment(it.point, tip, "force", it.label, abs(F) * mu_f, abs(F)))
        u = F / abs(F)
        lines.append(ConstructionLine((w.real, w.imag), (u.real, u.imag), f"line of {it.label}"))
        steps.append(Step.of("parallel", (it.point,), tip, phrase(
            "l_apply", label=it.label, F=clean(abs(F), fmax), pt=it.point, h=float(it.arm[k]))))
    wb = complex(lv.w_bal[k])
    pts.setdefault(lv.bal_point, (wb.real, wb.imag))
    steps.append(Step.of("intersect", (), "F_bal", phrase(
        "l_result", F=float(lv.signed(lv.by_lever)[k]), unit="N" if fa.crank.kind == "force" else "N·m",
        pt=lv.bal_point)))
    points = tuple(PlanPoint(nm, xy, "p" if nm != "p" and xy == (0.0, 0.0) else None) for nm, xy in pts.items())
    return Plan("lever", float(kin.phi_deg[k]), lv.scale, "p", points, tuple(segs), tuple(lines), tuple(steps),
                () if bool(lv.valid[k]) else ("the crank stands still: no lever",))




# --------------------------------------------------------------------------- JSON and readings


def _xy(z: complex) -> list[float]:
    return [float(z.real) + 0.0, float(z.imag) + 0.0]  # + 0.0 turns −0.0 into 0.0


def _num(x: float | None, ok: bool = True) -> float | None:
    if x is None:
        return None
    x = float(x)
    return x if ok and np.isfinite(x) else None


def force_json(lv: LeverAnalysis) -> list[dict]:
    """Per position, the pieces to merge into ``positions[i]`` of ``plans solve --json``.

    ``reactions``: {"F21": [x, y], "F12": [−x, −y], ...} N, both orders (F_ij = −F_ji) named in
    the scene's convention; ``reaction_points``: for prismatic pairs, where the resultant acts
    ({"at": [x, y] m, "offset": m along the guide from the pin or null, "couple": N·m about the pin});
    ``balancing``: {"kind", "force": {"point", "vector"} (null for a moment), "moment" N·m ccw+,
    "by_kinetostatics", "by_lever", "by_power" (N, or N·m for a moment; positive along the motion
    of the balancing point), "difference_percent" (drawing readings, coursework formula),
    "exact_difference_percent"}; ``inertia``: {"2": {"force": [x, y], "moment": M}}; ``loads``:
    every applied force by label."""
    fa = lv.fa
    scene = fa.scene
    fij = scene.fij
    other = "of_i_on_j" if fij == "on_i_from_j" else "on_i_from_j"
    kin_bal = fa.balancing
    lev, powr = lv.signed(lv.by_lever), lv.signed(lv.by_power)
    out = []
    for k in range(fa.n):
        reactions: dict[str, list[float]] = {}
        points: dict[str, dict] = {}
        for rc in fa.reactions():
            F = complex(rc.F[k])
            reactions[rc.name(fij)] = _xy(F)
            reactions.setdefault(rc.name(other), _xy(-F))
            if rc.guide is not None:
                off = float(rc.offset[k])
                has = abs(float(rc.N[k])) > EXACT_ZERO_REL * max(abs(F), 1.0) or float(rc.M[k]) == 0.0
                at = complex(rc.r[k] + off * rc.guide[k])
                points[rc.name(fij)] = {"pin": rc.point, "at": _xy(at) if has else None,
                                        "offset": off if has else None, "couple": float(rc.M[k])}
        c = fa.crank
        ok = bool(lv.valid[k])
        cycle = float(np.max(np.abs(kin_bal)))
        bal = {
            "kind": c.kind,
            "force": ({"point": c.point, "vector": _xy(complex(c.F_bal[k] * c.e_bal[k]))}
                      if c.kind == "force" else None),
            "moment": float(c.M_bal[k]),
            "by_kinetostatics": float(kin_bal[k]),
            "by_lever": _num(lev[k], ok),
            "by_power": _num(powr[k], ok),
            "exact_difference_percent": _num(_pct(float(lev[k]), clean(float(kin_bal[k]), cycle)), ok),
            "difference_percent": _num(_pct(*_drawn_balancing(lv, k)), ok),
        }
        inertia: dict[str, dict] = {}
        for f in fa.applied.forces:
            if f.kind == "inertia":
                inertia.setdefault(str(f.link), {"force": [0.0, 0.0], "moment": 0.0})["force"] = _xy(complex(f.F[k]))
        for m in fa.applied.moments:
            if m.kind == "inertia":
                inertia.setdefault(str(m.link), {"force": [0.0, 0.0], "moment": 0.0})["moment"] = float(m.M[k])
        loads = {f.label: _xy(complex(f.F[k])) for f in fa.applied.forces}
        entry = {"reactions": reactions, "reaction_points": points, "balancing": bal,
                 "inertia": inertia, "loads": loads}
        if fa.friction is not None:
            from plans.forces.friction import friction_json

            entry["friction"] = friction_json(fa.friction, fa, k)
        out.append(entry)
    return out


#: Arms shorter than this (mm on the sheet) are rounding noise of a zero arm: not listed.
NOISE_MM = 1e-6


def _pct(x: float, ref: float) -> float | None:
    """The coursework's δ = 100 (F_lever − F_kin)/F_kin, % (:func:`plans.units.percent`);
    None against a balancing load that vanishes."""
    return percent(x, ref)


def _ruler(mm: float) -> float:
    return round(mm / RULER_MM) * RULER_MM


def _drawn_balancing(lv: LeverAnalysis, k: int) -> tuple[float, float]:
    """(lever, kinetostatics) balancing loads as read off the drawings: the crank polygon's
    F_bal vector to the ruler, and the lever's arms h to the ruler (forces are computed)."""
    fa = lv.fa
    s = float(fa.sense[k])
    if fa.crank.kind == "force":
        c = fa.crank
        mu = mu_force(fa, [complex(f.F[k]) for f in c.loads]
                       + [complex(c.F_bal[k] * c.e_bal[k]), complex(c.frame.F[k])])
        kin_read = _ruler(abs(float(c.F_bal[k])) * mu) / mu * float(np.sign(c.F_bal[k])) * s
        arm_m = 1.0  # the lever gives the force itself
    else:
        kin_read = float(fa.balancing[k])  # the moment equation of the crank, no polygon
        arm_m = float(np.abs(fa.crank.r_point[k] - fa.kin.point(fa.scene.driver.pivot, fa.crank.link)[0][k]))
    # the lever: F' ⟂ crank at the image of the balancing point, arms read to the ruler
    h_bal = _ruler(float(lv.arm_bal[k]))
    unit_sign = float(np.sign(lv.unit_moment[k]))
    total = 0.0
    for it in lv.forces:
        F = abs(complex(it.F[k]))
        total += float(np.sign(it.moment[k])) * F * _ruler(float(it.arm[k]))
    lev = -total / (unit_sign * h_bal) * s * arm_m if h_bal and unit_sign else 0.0
    return lev, kin_read


@frozen
class Reading:
    """One row of the report: a quantity as read on the drawing next to its exact value."""

    quantity: str
    drawing: float | None
    exact: float
    unit: str
    compare: bool = True  # False for a row that is itself a difference
    ref: float = 0.0  # size of the polygon read from: the floor of the % (plans.units.percent)

    @property
    def difference(self) -> float | None:
        """(drawing − exact)/max(|exact|, ref), %; None against a zero exact value."""
        if not self.compare or self.drawing is None:
            return None
        return percent(self.drawing, self.exact, self.ref)

    def cells(self) -> tuple[str, str, str, str]:
        d = self.difference
        scale = max(abs(self.exact), self.ref, abs(self.drawing or 0.0))
        if d is not None:
            diff = f"{d:+.2f} %"
        elif self.compare and self.drawing is not None:  # against zero: the absolute difference
            diff = f"{clean(self.drawing - self.exact, scale):+.4g} {self.unit}"
        else:
            diff = ""
        return (self.quantity, "" if self.drawing is None else f"{clean(self.drawing, scale):.4g} {self.unit}",
                f"{clean(self.exact, scale):.6g} {self.unit}", diff)


def force_rows(lv: LeverAnalysis, k: int, polygons: tuple[ForcePolygon, ...] | None = None,
               lang: str = "en") -> list[Reading]:
    """Readable rows of position k: every polygon vector (read at μF to the ruler), the lever's
    arms, and the balancing load three ways with the coursework's % difference.  ``polygons``:
    the position's force polygons when the caller has built them already."""
    fa = lv.fa
    rows: list[Reading] = []
    big = max([abs(complex(f.F[k])) for f in fa.applied.forces]
              + [abs(complex(rc.F[k])) for rc in fa.reactions()] + [1e-300])
    words = _scale_words(fa.scene.scale_style, lang)  # the scene's notation, where not μ in mm per unit
    for fp in force_polygons(fa, k) if polygons is None else polygons:
        ref = max((sg.value for sg in fp.plan.segments), default=0.0)
        sc = words("F", fp.scale, "mm/N")
        for sg in fp.plan.segments:
            exact = clean(sg.value, big)  # rounding noise of a vanishing force
            rows.append(Reading(say("r_polygon", lang, label=sg.label, g=fp.group, mu=fp.scale) if sc is None
                                else say("x_r_polygon", lang, label=sg.label, g=fp.group, sc=sc),
                                fp.reading(sg.label), exact, "N", ref=ref))
    mu_l = fa.scene.scales.get("length", 1000.0)  # the mechanism's drawing, 1:1 unless the scene says
    arms = [(eq, lab, h) for gf in fa.groups for (eq, lab), h in gf.arms.items()]
    arms += [(f"M_{fa.scene.driver.pivot}({fa.crank.link})", lab, h) for lab, h in fa.crank.arms.items()]
    for eq, lab, h in arms:
        mm = float(h[k]) * mu_l
        if mm > NOISE_MM:
            sc = words("l", mu_l, "mm/m")
            rows.append(Reading(say("r_arm", lang, lab=lab, eq=eq, mu=mu_l) if sc is None
                                else say("x_r_arm", lang, lab=lab, eq=eq, sc=sc), _ruler(mm), mm, "mm"))
    for it in lv.forces:
        a = float(it.arm[k])
        if a > NOISE_MM:
            rows.append(Reading(say("r_lever_arm", lang, lab=it.label, mu=lv.scale), _ruler(a), a, "mm"))
    unit = "N" if fa.crank.kind == "force" else "N·m"
    exact = float(fa.balancing[k])
    lev_read, kin_read = _drawn_balancing(lv, k)
    cycle = float(np.max(np.abs(fa.balancing))) if fa.n else 0.0
    exact = clean(exact, cycle)
    sym = "F_bal" if fa.crank.kind == "force" else "M_bal"
    rows.append(Reading(say("r_kin", lang, sym=sym), clean(kin_read, cycle), exact, unit))
    ok = bool(lv.valid[k])
    rows.append(Reading(say("r_lever", lang, sym=sym), clean(lev_read, cycle) if ok else None,
                        clean(float(lv.signed(lv.by_lever)[k]), cycle), unit))
    rows.append(Reading(say("r_power", lang, sym=sym), None, clean(float(lv.signed(lv.by_power)[k]), cycle), unit))
    # δ against a balancing load that vanishes here is not a percentage: left out
    pct = percent(lev_read, kin_read) if ok and exact else None
    ex_pct = percent(float(lv.signed(lv.by_lever)[k]), exact) if exact else None
    letter = sym[0]
    rows.append(Reading(say("r_delta", lang, l=letter),
                        pct, 0.0 if ex_pct is None else ex_pct, "%", False))
    return rows


def _scale_words(style: str, lang: str) -> Any:
    """``(sub, mu, mm_per) -> "μF = 25 Н/мм"`` in the scene's notation, or None for the old μ in
    mm per unit (English, by default: the notation module not even loaded)."""
    sym, d = (style, "mm/m" if style == "mu" else "m/mm") if style in ("mu", "K") else (style.split("|") + [""])[:2]
    if sym in ("", "mu") and (d == "mm/m" or (d == "" and lang != "ru")):
        return lambda sub, mu, mm_per: None
    from plans.scene.notation import scale_words

    return lambda sub, mu, mm_per: scale_words(style, lang, sub, mu, mm_per)


def table_lines(fa: ForceAnalysis, lv: LeverAnalysis, k: int, lang: str = "en") -> list[str]:
    """The force analysis of position k as text lines for ``plans solve`` (indented two spaces),
    in ``lang``."""
    from plans.language import symbols
    from plans.phrases import number, say

    ru = lang == "ru"
    unit = "N" if fa.crank.kind == "force" else "N·m"
    sc = _scale_words(fa.scene.scale_style, lang)("v", lv.scale, "mm/(m/s)")
    lines = [say("t_force_head" if sc is None else "x_force_head", lang,
                 fij=say("t_on_i" if fa.scene.fij == "on_i_from_j" else "t_of_i", lang),
                 sense=say("ccw" if lv.turn > 0 else "cw", lang), mu=lv.scale, sc=sc)]
    polygons = force_polygons(fa, k)
    for fp in polygons:
        for note in fp.plan.degenerate:
            lines.append(symbols(say("t_polygon_note", lang, g=fp.group, d=note), lang))
    w = {key: say("w_" + key, lang) for key in ("quantity", "drawing", "exact", "difference")}
    lines.append(f"  {w['quantity']:58s} {w['drawing']:>14s} {w['exact']:>16s} {w['difference']:>11s}")
    for r in force_rows(lv, k, polygons, lang):
        q, d, e, diff = r.cells()
        if ru:
            d, e, diff = (symbols(c.replace(".", ","), lang) for c in (d, e, diff))
            q = symbols(q, lang)
        lines.append(f"  {q:58s} {d:>14s} {e:>16s} {diff:>11s}")
    b = lv.signed(lv.by_lever)[k] if lv.valid[k] else None
    cyc = float(np.max(np.abs(fa.balancing)))
    force = fa.crank.kind == "force"
    lines.append(symbols(say(
        "t_balancing", lang, kind=("ая сила" if force else "ий момент") if ru else fa.crank.kind,
        end="положительна" if force else "положителен", kin=clean(float(fa.balancing[k]), cyc), unit=unit,
        lev="-" if b is None else number(clean(float(b), cyc), ".6g", lang), pt=fa.crank.point), lang))
    if fa.friction is not None:
        from plans.forces.friction import friction_lines

        lines += friction_lines(fa, k, lang)
    return lines
