"""Loads of the force analysis: what acts on the links besides the reactions.

Masses, moments of inertia and centres of mass live in ``[links.N]``
(``mass`` kg, ``inertia`` kg·m² about the centre, ``centre = "S2"``); one-point
links (sliders) default to their axis point as centre.  Everything else is in
``[loads]``.  Forces are in N, moments in N·m (counter-clockwise positive),
lengths in the file's ``unit`` (or strings such as ``"82 mm"``).

.. code-block:: toml

    [loads]
    gravity = false            # default true: G = m g, g = 9.81 m/s² along -y;
                               # or gravity = { g = 9.81, direction_deg = -90 }
    inertia = "force_and_moment"  # or "offset_force": (Φ, M_Φ) replaced by one force Φ
                               # offset from S by h = M_Φ/Φ (moment kept where Φ = 0)
    lever_turn = "ccw"         # the Zhukovsky lever is the velocity plan turned 90° ccw (or "cw")

    [loads.balancing]          # default: a force at the crank pin ⟂ the crank
    kind = "force"             # or "moment" (a couple on the driving link)
    point = "A"                # a point of the driving link (not its pivot)

    [loads.mass_rule]          # optional, the coursework's rule m = k·F_p·1e-3 kg (F_p in cm²)
    diameter = 82              # piston diameter (file unit) giving F_p = π d²/4
    g_per_cm2 = { 3 = 13, 5 = 13, 2 = 16, 4 = 16 }   # k per link; such links must not set mass
    rod_inertia = [2, 4]       # I_S = m l² (1/3 − (l_AS/l)²) for these links (coursework formula)

    [[loads.gas]]              # gas force on a piston, along its guide
    link = 3                   # the piston: a link sliding on a guide
    diameter = 82              # or area = 52.8 (in area_unit, default "cm2")
    pressure = 50              # constant pressure, in pressure_unit
    pressure_unit = "N/cm2"    # Pa, kPa, MPa, bar, N/cm2, N/mm2 (default MPa)
    strokes = ["down"]         # act only while the piston moves toward the crank pivot
                               # ("down") or away from it ("up"); default both
    direction = "toward_pivot" # default; or "away_from_pivot"
    # indicator diagram instead of `pressure`: pressure over piston travel s measured
    # from the outer dead centre (file unit), one table per stroke; must cover 0..H
    # diagram = { down = [[0, 50], [35, 20], [70, 2]], up = [[0, 8], [70, 0]] }
    # a four-stroke cylinder: one table per stroke of the 720° cycle, and the crank angle
    # of its ignition (the outer dead centre nearest to it; default 360, intake from 0)
    # diagram = { intake = [...], compression = [...], expansion = [...], exhaust = [...] }
    # fires_deg = 360
    # the course's standard diagram: travel = "fraction" (s/H from 0 to 1) and p_max = 5
    # (in pressure_unit): the tables' pressures are then fractions of p_max

    [[loads.force]]            # an external force at a named point of a link
    link = 3
    point = "B"
    vector = [-1000, 0]        # N, global axes; or magnitude = 1000 with angle_deg = 180;
                               # or resisting = 1000: opposite the point's velocity
                               #   (along = deg: only the velocity's sign along that axis counts;
                               #    stroke = "positive" | "negative": act only on that stroke)
                               # stroke = "working" | "idle": act only on that stroke of the output
                               #   (the slow one / the fast return; plans.forces.strokes), any force
    name = "F_c"               # label on the polygons and the lever (default F_ext<k>)
    # or a gas force by its pressure over the cycle's crank angle, on a piston along its
    # guide toward the crank: area = 0.00528 (m²) or bore = 82 (file unit), and
    # pressure_table = [[0, 0], [360, 5e6], ..., [720, 0]]  (φ deg over 0..360 or 0..720, Pa)

    [[loads.moment]]           # an external moment on a link
    link = 4
    value = -20                # N·m ccw+; or resisting = 20 (opposite ω of the link);
                               # or a turning-moment diagram over the cycle (φ the crank's):
                               # table = [[0, 0], [90, 600], ..., [360, 0]]  (φ deg, N·m)
                               # expression = "600*sin(2*phi) - 500*sin(phi)"  (φ in rad)
    stroke = "working"         # or "idle": act only on that stroke of the output (default both)
    name = "M_c"

Sign of the balancing force in the results: positive along the velocity of
its point (it drives the crank); the balancing moment is counter-clockwise
positive.
"""

from __future__ import annotations

import math
from collections.abc import Iterator
from dataclasses import replace
from typing import Any

import numpy as np

from plans.errors import InputError, Said

# the records and the gas cycle, importable from here as before
from plans.forces.gas_cycle import (  # noqa: F401
    FOUR_STROKES,
    cycle_of,
    cycle_phase,
    cycle_table,
    extreme_indices,
    four_stroke,
    gas_force,
    ignition,
    piston_stroke,
    pressure_force,
    stroke_index,
)
from plans.forces.load_records import (  # noqa: F401
    AREA_UNITS,
    G_STANDARD,
    PRESSURE_UNITS,
    AppliedForce,
    AppliedLoads,
    AppliedMoment,
    Balancing,
    C,
    ForceLoad,
    GasLoad,
    Loads,
    MomentLoad,
    R,
    local_at,
    mechanism_extent,
)
from plans.forces.shared import unit_vector
from plans.reader import Reader, check_keys, did_you_mean, show
from plans.scene.model import Scene
from plans.units import DUST, LENGTH_UNITS

_LOAD_KEYS = {"gravity", "inertia", "lever_turn", "balancing", "mass_rule", "gas", "force", "moment"}


def parse_loads(scene: Scene) -> Loads:
    """The scene's ``[loads]`` (and the links' masses) as a :class:`Loads`: the record the
    scene holds once solved (``plans.solve`` reads it once, :mod:`plans.tables`), else
    read now; InputError on anything wrong."""
    return scene.loads if scene.loads is not None else _parse_loads(scene)


def _parse_loads(scene: Scene) -> Loads:
    path = scene.path
    raw = scene.raw.get("loads", {})
    unit = scene.raw.get("unit", "mm")

    def fail(field: str, msg: str | Said) -> InputError:
        return InputError(msg, file=path, field=field)

    if not isinstance(raw, dict):
        raise fail("loads", Said("ld_table_loads"))
    r = Reader(path)
    check_keys(raw, _LOAD_KEYS, file=path, where="loads.")

    def number(body: dict[str, Any], key: str, where: str, *, nonneg: bool = False,
               positive: bool = False) -> float:
        return r.number(body, key, where, nonneg=nonneg, positive=positive)

    def angle(body: dict[str, Any], key: str, where: str, default: float) -> float:
        return r.angle(body, key, where, default=default)

    def length(v: Any, field: str, positive: bool = True) -> float:
        return r.length(v, field, unit if unit in LENGTH_UNITS else "mm", positive=positive)

    def label(body: dict[str, Any], where: str, default: str) -> str:
        return r.name(body.get("name", default), f"{where}name")

    def moving_link(body: dict[str, Any], where: str) -> int:
        lid = body.get("link")
        if lid == scene.frame and not isinstance(lid, bool):
            raise fail(f"{where}link", Said("l_frame", link=lid))
        if isinstance(lid, bool) or not isinstance(lid, int) or lid not in scene.links:
            raise fail(f"{where}link", Said("l_link", link=show(lid), links=sorted(scene.links)))
        return int(lid)

    def tables(key: str, said: str, keys: tuple[str, ...]) -> Iterator[tuple[int, dict[str, Any], str]]:
        """Each table of the array ``[[loads.KEY]]``, its index and its fields' prefix; its keys checked."""
        got = raw.get(key, [])
        if not isinstance(got, list):
            raise fail(f"loads.{key}", Said(said))
        for k, body in enumerate(got):
            where = f"loads.{key}[{k}]."
            if not isinstance(body, dict):
                raise fail(f"loads.{key}[{k}]", Said("sm_table"))
            check_keys(body, keys, file=path, where=where)
            yield k, body, where

    # ---- masses, inertias, centres
    masses = {lid: link.mass for lid, link in scene.links.items()}
    inertias = {lid: link.inertia for lid, link in scene.links.items()}
    links_raw = scene.raw.get("links", {})
    rule = raw.get("mass_rule")
    if rule is not None:
        if not isinstance(rule, dict):
            raise fail("loads.mass_rule", Said("ld_table_diameter_per"))
        check_keys(rule, ("diameter", "g_per_cm2", "rod_inertia"), file=path, where="loads.mass_rule.")
        if "diameter" not in rule:
            raise fail("loads.mass_rule.diameter", Said("ld_missing_piston_diameter"))
        d = length(rule["diameter"], "loads.mass_rule.diameter")
        area_cm2 = math.pi * d**2 / 4 / 1e-4
        ks = rule.get("g_per_cm2", {})
        if not isinstance(ks, dict):
            raise fail("loads.mass_rule.g_per_cm2", Said("ld_table_link"))
        for key in ks:
            where = f"loads.mass_rule.g_per_cm2.{key}"
            if not (key.isascii() and key.isdigit() and key == str(int(key))):
                raise fail(where, Said("ld_link_number"))
            lid = int(key)
            if lid not in scene.links:
                raise fail(where, Said("ld_unknown_link_lid", lid=lid))
            if "mass" in links_raw.get(str(lid), {}):
                raise fail(where, Said("ld_link_lid_sets", lid=lid))
            masses[lid] = number(ks, key, "loads.mass_rule.g_per_cm2.", nonneg=True) * area_cm2 * 1e-3
        rods = rule.get("rod_inertia", [])
        if not isinstance(rods, list):
            raise fail("loads.mass_rule.rod_inertia", Said("ld_list_link_numbers"))
        for lid in rods:
            where = "loads.mass_rule.rod_inertia"
            if isinstance(lid, bool) or not isinstance(lid, int) or lid not in scene.links:
                raise fail(where, Said("ld_unknown_link_lid2", lid=lid))
            link = scene.links[lid]
            if link.length is None or link.centre is None:
                raise fail(where, Said("ld_link_lid_needs", lid=lid))
            if "inertia" in links_raw.get(str(lid), {}):
                raise fail(where, Said("ld_link_lid_sets2", lid=lid))
            ratio = abs(link.points[link.centre]) / link.length
            inertias[lid] = masses[lid] * link.length**2 * (1 / 3 - ratio**2)
    centres: dict[int, str] = {}
    for lid, link in scene.links.items():
        if link.centre is not None:
            centres[lid] = link.centre
        elif masses[lid] > 0 or inertias[lid] > 0:
            if len(link.axis) == 1:
                centres[lid] = link.axis[0]
            else:
                raise fail(f"links.{lid}.centre", Said("ld_link_lid_has", lid=lid))

    # ---- gravity
    grav = raw.get("gravity", True)
    if isinstance(grav, bool):
        g = complex(0, -G_STANDARD) if grav else 0j
    elif isinstance(grav, dict):
        check_keys(grav, ("g", "direction_deg"), file=path, where="loads.gravity.")
        gval = number(grav, "g", "loads.gravity.", nonneg=True) if "g" in grav else G_STANDARD
        ang = angle(grav, "direction_deg", "loads.gravity.", -90.0)
        g = gval * complex(math.cos(math.radians(ang)), math.sin(math.radians(ang)))
    else:
        raise fail("loads.gravity", Said("l_gravity"))

    inertia_mode = r.choice(raw, "inertia", "loads.", ("force_and_moment", "offset_force"), "force_and_moment")
    turn = r.choice(raw, "lever_turn", "loads.", ("ccw", "cw"), "ccw")

    # ---- balancing load
    crank = scene.links[scene.driver.link]
    bal = raw.get("balancing", {})
    if not isinstance(bal, dict):
        raise fail("loads.balancing", Said("l_balancing"))
    check_keys(bal, ("kind", "point"), file=path, where="loads.balancing.")
    kind = r.choice(bal, "kind", "loads.balancing.", ("force", "moment"), "force")
    bpoint = bal.get("point", crank.axis[1])
    if not isinstance(bpoint, str):
        raise fail("loads.balancing.point", Said("e_point_name"))
    if bpoint not in crank.points:
        if bpoint in scene.frame_points:
            raise fail("loads.balancing.point", Said("l_bal_frame", point=bpoint, link=crank.id))
        raise fail("loads.balancing.point", Said("l_bal_not_on", point=bpoint, link=crank.id,
                                                 hint=did_you_mean(bpoint, crank.points)))
    if abs(crank.points[bpoint] - crank.points[scene.driver.pivot]) == 0:
        raise fail("loads.balancing.point", Said("l_bal_pivot", point=bpoint))

    # ---- gas forces
    gas = []
    for k, body, where in tables("gas", "ld_array_tables_loads", (
            "link", "diameter", "area", "area_unit", "pressure", "pressure_unit", "strokes", "direction", "diagram",
            "name", "fires_deg", "p_max", "travel")):
        for key in ("p_max", "travel"):
            if key in body and "diagram" not in body:
                raise fail(f"{where}{key}", Said("ld_goes_indicator_diagram"))
        fraction = r.choice(body, "travel", where, ("length", "fraction"), "length") == "fraction"
        if "diameter" in body and "area" in body:
            raise fail(f"{where}area", Said("ld_give_diameter_area"))
        lid = moving_link(body, where)
        pj = [j for j in scene.joints if j.kind == "P" and j.guide is not None and j.slider == lid]
        if len(pj) != 1:
            raise fail(f"{where}link", Said("l_piston", link=lid))
        if "diameter" in body:
            area = math.pi * length(body["diameter"], f"{where}diameter") ** 2 / 4
        elif "area" in body:
            au = r.choice(body, "area_unit", where, AREA_UNITS, "cm2")
            area = number(body, "area", where, positive=True) * AREA_UNITS[au]
        else:
            raise fail(f"{where}diameter", Said("ld_missing_piston_diameter2"))
        pu = r.choice(body, "pressure_unit", where, PRESSURE_UNITS, "MPa")
        scale = PRESSURE_UNITS[pu]
        strokes = body.get("strokes", ["down", "up"])
        if not (isinstance(strokes, list) and strokes and all(s in ("down", "up") for s in strokes)):
            raise fail(f"{where}strokes", Said("ld_list_down_toward"))
        direction = body.get("direction", "toward_pivot")
        if direction not in ("toward_pivot", "away_from_pivot"):
            raise fail(f"{where}direction", Said("ld_toward_pivot_away", direction=direction))
        pressure = None
        outer = stroke_len = 0.0
        diagram: dict[str, tuple[R, R]] = {}
        if "pressure" in body and "diagram" in body:
            raise fail(f"{where}diagram", Said("ld_give_pressure_diagram"))
        if "pressure" in body:
            pressure = number(body, "pressure", where) * scale
        elif "diagram" in body:
            diag = body["diagram"]
            four = isinstance(diag, dict) and bool(diag) and set(diag) <= set(FOUR_STROKES)
            if four:
                lost = [k for k in FOUR_STROKES if k not in diag]
                if lost:
                    raise fail(f"{where}diagram", Said("ld_four_stroke_diagram", v=lost[0]))
                if "strokes" in body:
                    raise fail(f"{where}strokes", Said("ld_four_stroke_diagram2"))
            elif not isinstance(diag, dict) or not diag or not set(diag) <= {"down", "up"}:
                raise fail(f"{where}diagram", Said("ld_down_up_four"))
            outer, stroke_len = piston_stroke(scene, pj[0].name, lid)
            # the pressures as given, or fractions of p_max (in pressure_unit)
            unit_p = number(body, "p_max", where, positive=True) * scale if "p_max" in body else scale
            for side, table in diag.items():
                f = f"{where}diagram.{side}"
                if not (isinstance(table, list) and len(table) >= 2
                        and all(isinstance(row, list) and len(row) == 2 for row in table)):
                    raise fail(f, Said("ld_least_two_rows"))
                if fraction:  # the course's standard diagram: travel in fractions of H, p of p_max
                    s = np.array([r.value(row[0], f, nonneg=True) for row in table]) * stroke_len
                else:
                    s = np.array([length(row[0], f, positive=False) for row in table])
                p = np.array([number({"p": row[1]}, "p", f + ".") for row in table]) * unit_p
                if np.any(np.diff(s) <= 0):
                    raise fail(f, Said("ld_travel_increasing_from"))
                tol = 1e-6 * stroke_len
                if s[0] > tol or s[-1] < stroke_len - tol:
                    raise fail(f, Said("ld_table_covers_travel", v=s[0] * 1e3, v2=s[-1] * 1e3, v3=stroke_len * 1e3))
                diagram[side] = (s, p)
            missing = [] if four else [s for s in strokes if s not in diagram]
            if missing:
                raise fail(f"{where}diagram", Said("ld_table_stroke_listed", v=missing[0]))
        else:
            raise fail(f"{where}pressure", Said("ld_missing_pressure_indicator"))
        fires = None
        if "fires_deg" in body:
            if not (diagram and set(diagram) == set(FOUR_STROKES)):
                raise fail(f"{where}fires_deg", Said("ld_ignition_angle_belongs"))
            fires = r.value(body["fires_deg"], f"{where}fires_deg", limit=1e6)
        elif diagram and set(diagram) == set(FOUR_STROKES):
            fires = 360.0  # the course's cycle: intake from 0°, ignition at 360°
        gl = GasLoad(link=lid, joint=pj[0].name, area=area, pressure=pressure, diagram=diagram,
                     strokes=tuple(strokes), toward_pivot=direction == "toward_pivot",
                     name=label(body, where, f"P{lid}"), outer=outer, stroke=stroke_len, fires=fires)
        gas.append(gl if fires is None else replace(gl, ignition=ignition(scene, gl)))

    # ---- external forces and moments
    forces = []
    for k, body, where in tables("force", "ld_array_tables_loads2", (
            "link", "point", "vector", "magnitude", "angle_deg", "resisting", "along", "stroke", "name", "area",
            "bore", "pressure_table")):
        if "pressure_table" in body or "area" in body or "bore" in body:
            gas.append(pressure_force(scene, r, body, where, k, moving_link, length))
            continue
        given: list[str] = [key for key in ("vector", "magnitude", "resisting") if key in body]
        if len(given) > 1:
            raise fail(f"{where}{given[1]}", Said("l_force_ways", given=Said("l_and", a=given[0], b=given[1])))
        lid = moving_link(body, where)
        pt = body.get("point")
        if not isinstance(pt, str) or pt not in scene.links[lid].points:
            hint = did_you_mean(pt, scene.links[lid].points) if isinstance(pt, str) else ""
            raise fail(f"{where}point", Said("l_point", point=show(pt), link=lid, hint=hint,
                                             points=sorted(scene.links[lid].points)))
        vec = res = along = None
        stroke = body.get("stroke", "both")
        if stroke not in ("both", "positive", "negative", "working", "idle"):
            raise fail(f"{where}stroke", Said("l_stroke", got=show(stroke)))
        if "vector" in body:
            v = body["vector"]
            if not (isinstance(v, list) and len(v) == 2):
                raise fail(f"{where}vector", Said("l_vector"))
            vv = {"x": v[0], "y": v[1]}
            vec = complex(number(vv, "x", f"{where}vector."), number(vv, "y", f"{where}vector."))
        elif "magnitude" in body:
            mag = number(body, "magnitude", where)
            ang = angle(body, "angle_deg", where, 0.0)
            vec = mag * complex(math.cos(math.radians(ang)), math.sin(math.radians(ang)))
        elif "resisting" in body:
            res = number(body, "resisting", where, nonneg=True)
            if "along" in body:
                along = math.radians(angle(body, "along", where, 0.0))
        else:
            raise fail(f"{where}vector", Said("l_force_none"))
        if stroke in ("positive", "negative") and along is None:
            raise fail(f"{where}stroke", Said("l_stroke_axis"))
        forces.append(ForceLoad(link=lid, point=pt, vector=vec, resisting=res, along=along, stroke=stroke,
                                name=label(body, where, f"F_ext{k + 1}")))
    moments = []
    for _, body, where in tables("moment", "ld_array_tables_loads3",
                                 ("link", "value", "resisting", "name", "table", "expression", "stroke")):
        m_stroke = r.choice(body, "stroke", where, ("both", "working", "idle"), "both")
        given = [key for key in ("value", "resisting", "table", "expression") if key in body]
        if len(given) > 1:
            raise fail(f"{where}{given[1]}", Said("l_moment_ways", a=given[0], b=given[1]))
        lid = moving_link(body, where)
        if "table" in body:
            tab = cycle_table(r, body["table"], f"{where}table", "M")
            moments.append(MomentLoad(lid, None, None, label(body, where, f"M{lid}"), table=tab,
                                      period=float(tab[0][-1]), stroke=m_stroke))
            continue
        if "expression" in body:
            from plans.expression import check_finite, parse

            expr = parse(body["expression"], file=path, field=f"{where}expression")
            period = cycle_of(scene)
            check_finite(expr, np.radians(np.linspace(0.0, period, 7201)), file=path, field=f"{where}expression")
            moments.append(MomentLoad(lid, None, None, label(body, where, f"M{lid}"), expression=expr,
                                      period=period, stroke=m_stroke))
            continue
        if "value" in body:
            moments.append(MomentLoad(lid, number(body, "value", where), None, label(body, where, f"M{lid}"),
                                      stroke=m_stroke))
        elif "resisting" in body:
            moments.append(MomentLoad(lid, None, number(body, "resisting", where, nonneg=True),
                                      label(body, where, f"M_c{lid}"), stroke=m_stroke))
        else:
            raise fail(f"{where}value", Said("ld_value_ccw_resisting"))

    limited = [f"loads.{key}[{k}].stroke" for key, got in (("force", raw.get("force", [])), ("moment", raw.get("moment", [])))
               for k, body in enumerate(got) if body.get("stroke") in ("working", "idle")]
    if limited:  # the strokes exist (an output with two extremes), or the first such load fails here
        from plans.forces.strokes import on_stroke

        on_stroke(scene, "working", [], limited[0])
    if any("resisting" in body and body.get("stroke", "positive") in ("positive", "negative")
           for body in (*raw.get("force", []), *raw.get("moment", []))):  # no stroke given, or one by the sign of the velocity
        from plans.forces.strokes import warn_idle

        warn_idle(scene, raw, forces)
    return Loads(masses=masses, inertias=inertias, centres=centres, g=g,
                 offset_inertia=inertia_mode == "offset_force", lever_turn=1 if turn == "ccw" else -1,
                 balancing=Balancing(kind, bpoint), gas=tuple(gas), forces=tuple(forces),
                 moments=tuple(moments))


# --------------------------------------------------------------------------- loads at positions


def apply_loads(scene: Scene, loads: Loads, kin: Any) -> AppliedLoads:
    """Gravity, inertia (Φ = −m a_S at S, M_Φ = −I_S ε), gas, external loads at every position."""
    n = kin.n
    forces: list[AppliedForce] = []
    moments: list[AppliedMoment] = []
    for lid in sorted(scene.links):
        m, inert = loads.masses[lid], loads.inertias[lid]
        if lid not in loads.centres:
            continue
        s_name = loads.centres[lid]
        z = scene.links[lid].points[s_name]
        r, _, a = kin.point_on(lid, z)
        if m > 0 and loads.g != 0:
            forces.append(AppliedForce(f"G{lid}", lid, s_name, r, np.full(n, z), np.full(n, m * loads.g),
                                       "gravity"))
        phi = -m * a if m > 0 else np.zeros(n, complex)
        m_phi = -inert * kin.eps(lid) if inert > 0 else np.zeros(n)
        if loads.offset_inertia and m > 0:
            # one force Φ offset from S so that its moment about S is M_Φ: d = −iΦ M_Φ/|Φ|²;
            # where Φ vanishes (or is dust beside M_Φ: an offset a billion times the mechanism)
            # the couple stays a couple
            mag = np.abs(phi)
            ok = np.abs(m_phi) < 1e9 * mechanism_extent(kin) * mag
            safe = np.where(ok, mag, 1.0)
            d = np.where(ok, -1j * (m_phi / safe) * unit_vector(phi), 0)
            local = z + d * np.conj(kin.motion[lid].rot)
            forces.append(AppliedForce(f"Phi{lid}", lid, f"{s_name}*", r + d, local, phi, "inertia"))
            rest = np.where(ok, 0.0, m_phi)
            if inert > 0:
                moments.append(AppliedMoment(f"M_Phi{lid}", lid, rest, "inertia"))
        else:
            if m > 0:
                forces.append(AppliedForce(f"Phi{lid}", lid, s_name, r, local_at(n, z), phi, "inertia"))
            if inert > 0:
                moments.append(AppliedMoment(f"M_Phi{lid}", lid, m_phi, "inertia"))
    for gl in loads.gas:
        forces.append(gas_force(scene, kin, gl))
    for fl in loads.forces:
        z = scene.links[fl.link].points[fl.point]
        r, v, _ = kin.point_on(fl.link, z)
        if fl.vector is not None:
            F = np.full(n, fl.vector, dtype=complex)
        else:
            assert fl.resisting is not None and v is not None
            # at rest up to round-off (an extreme position): no motion to resist, no force
            still = DUST * abs(scene.driver.omega) * mechanism_extent(kin)
            if fl.along is None:
                speed = np.abs(v)
                F = np.where(speed > still, -fl.resisting * unit_vector(v), 0)
            else:
                e = complex(math.cos(fl.along), math.sin(fl.along))
                ve = (v * np.conj(e)).real
                sv = np.where(np.abs(ve) > still, np.sign(ve), 0.0)
                if fl.stroke == "positive":
                    sv = np.where(sv > 0, sv, 0.0)
                elif fl.stroke == "negative":
                    sv = np.where(sv < 0, sv, 0.0)
                F = -fl.resisting * sv * e
        if fl.stroke in ("working", "idle"):
            from plans.forces.strokes import mask

            F = mask(scene, kin, fl.stroke, F)
        forces.append(AppliedForce(fl.name, fl.link, fl.point, r, np.full(n, z), F.astype(complex), "external"))
    for ml in loads.moments:
        if ml.table is not None:
            M = np.interp(cycle_phase(scene, kin, ml.period), ml.table[0], ml.table[1])
        elif ml.expression is not None:
            M = ml.expression(np.radians(cycle_phase(scene, kin, ml.period)))
        elif ml.value is not None:
            M = np.full(n, ml.value)
        else:
            assert ml.resisting is not None
            w = kin.omega(ml.link)
            M = -ml.resisting * np.where(np.abs(w) > DUST * abs(scene.driver.omega), np.sign(w), 0.0)
        if ml.stroke != "both":
            from plans.forces.strokes import mask

            M = mask(scene, kin, ml.stroke, M)
        moments.append(AppliedMoment(ml.name, ml.link, M, "external"))
    return AppliedLoads(tuple(forces), tuple(moments))
