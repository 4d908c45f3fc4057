"""A linkage scene's sections: the task's data, the structure, the kinematics of each
position studied (the plans' steps, scales, segments), the tables over the positions, the
force analysis (inertia, each group's moment equations and polygon, the crank, the
Zhukovsky lever, the balancing force three ways)."""

from __future__ import annotations

import math
from typing import Any

from plans.kinematics.structure import TriadGroup
from plans.tolerances import SAME_ANGLE_DEG

from .model import Figure, Frac, Num, Section, Sym, Table, Text, Vec, fmt, num, row
from .words import quantity, say, symbols, unit, w

# --------------------------------------------------------------------------- positions


def studied(item: Any) -> list[int]:
    """The positions studied in detail: the sheet's ``positions`` when given, else the
    first two (the others are in the tables over the positions)."""
    phis = [p["phi_deg"] for p in item.data["positions"]]
    sheet = item.raw.get("sheet")
    want = sheet.get("positions") if isinstance(sheet, dict) else None
    if isinstance(want, list | int | float) and not isinstance(want, bool):
        want = want if isinstance(want, list) else [want]
        ks = [next(k for k, p in enumerate(phis) if abs(p - float(x)) < SAME_ANGLE_DEG) for x in want
              if any(abs(p - float(x)) < SAME_ANGLE_DEG for p in phis)]
        if ks:
            return ks
    return list(range(min(2, len(phis))))


def deg(x: float) -> str:
    return f"{x:g}"


# --------------------------------------------------------------------------- the task


def task(item: Any, lang: str, sec: Section) -> None:
    sol = item.solved
    scene = sol.scene
    sec.para(say(lang, f"Объект расчёта: {scene.title_in('ru')}.", f"The object of the analysis: {scene.title_in('en')}."))
    rows = []
    for lid in sorted(scene.links):
        lk = scene.links[lid]
        rows.append((str(lid), "".join(lk.axis), fmt(lk.length, lang) if lk.length else "—",
                     fmt(lk.mass, lang) if lk.mass else "—", fmt(lk.inertia, lang) if lk.inertia else "—"))
    key = f"links-{item.index}"
    sec.para(say(lang, f"Размеры и массы звеньев приведены в таблице {{tab:{key}}}.",
                 f"The links' dimensions and masses are in table {{tab:{key}}}."))
    sec.add(Table(key, say(lang, "Размеры и массы звеньев", "Dimensions and masses of the links"),
                  (w("link", lang), w("points", lang), w("length", lang), w("mass", lang), w("inertia", lang)),
                  tuple(rows)))
    d = scene.driver
    n_rpm = abs(d.omega) * 30 / math.pi
    sec.para(say(lang, "Частота вращения начального звена ", "The initial link turns at "),
             row(Sym("n", "1"), "=", num(n_rpm, lang), unit("rpm", lang)),
             say(lang, ", его угловая скорость", "; its angular velocity"))
    sec.eq(Sym("ω", "1"), "=", Frac(row("π", "·", Sym("n", "1")), Num("30")), "=",
           Frac(row(Num("3,1416" if lang == "ru" else "3.1416"), "·", num(n_rpm, lang)), Num("30")), "=",
           num(abs(d.omega), lang), unit("rad/s", lang))
    phis = ", ".join(deg(p["phi_deg"]) for p in item.data["positions"])
    sec.para(say(lang, f"Положения начального звена: φ = {phis}°.", f"Positions of the initial link: φ = {phis}°."))


# --------------------------------------------------------------------------- structure

#: A group's kind in Russian letters: В for a turning pair, П for a sliding one (ВВП for RRP).
_RU_PAIRS = str.maketrans({"R": "В", "P": "П"})


def structure(item: Any, lang: str, sec: Section) -> None:
    st = item.data["structure"]
    n, p5, p4, W = st["n"], st["p5"], st["p4"], st["W"]
    sec.para(say(lang, f"Число подвижных звеньев n = {n}, кинематических пар пятого класса p₅ = {p5}, "
                       f"четвёртого класса p₄ = {p4}. Подвижность механизма по формуле Чебышева:",
                 f"Moving links n = {n}, lower pairs (class five) p₅ = {p5}, higher pairs (class four) "
                 f"p₄ = {p4}. The mobility by Chebyshev's formula:"))
    sec.eq(Sym("W"), "=", Num("3"), Sym("n"), "−", Num("2"), Sym("p", "5"), "−", Sym("p", "4"), "=",
           Num("3"), "·", Num(str(n)), "−", Num("2"), "·", Num(str(p5)), "−", Num(str(p4)), "=", Num(str(W)))
    il = st["initial_link"]
    sec.para(say(lang, f"Механизм состоит из начального звена {il[0]} со стойкой {il[1]} (механизм первого класса) "
                       "и присоединённых к нему структурных групп Ассура:",
                 f"The mechanism is the initial link {il[0]} with the frame {il[1]} (a class I mechanism) "
                 "and the Assur groups attached to it:"))
    rows = []
    for g in st["groups"]:
        rows.append((g["name"], g["kind"] if lang == "en" else g["kind"].translate(_RU_PAIRS), ", ".join(str(x) for x in g["links"]),
                     ", ".join(str(x) for x in g["attached_to"]), say(lang, "II класс, 2 порядок", "class II, order 2")))
    key = f"groups-{item.index}"
    sec.add(Table(key, say(lang, "Структурные группы Ассура", "Assur groups"),
                  (say(lang, "Группа", "Group"), say(lang, "Вид", "Kind"), say(lang, "Звенья", "Links"),
                   say(lang, "Присоединена к", "Attached to"), say(lang, "Класс, порядок", "Class, order")),
                  tuple(rows)))
    cls = "II" if st["groups"] else "I"
    sec.para(say(lang, f"Формула строения: I({il[0]}, {il[1]}) → " + " → ".join(f"II({g['name']})" for g in st["groups"])
                 + f". Механизм {cls} класса (таблица {{tab:{key}}}).",
                 f"Structure: I({il[0]}, {il[1]}) → " + " → ".join(f"II({g['name']})" for g in st["groups"])
                 + f"; a class {cls} mechanism (table {{tab:{key}}})."))
    if item.solved.scene.wants("positions"):
        sec.para(say(lang, f"План положений механизма показан на рисунке {{fig:positions-{item.index}}}.",
                     f"The plan of positions is in figure {{fig:positions-{item.index}}}."))
        sec.add(Figure(f"positions-{item.index}", item.index, "positions",
                       say(lang, "План положений механизма", "Plan of positions of the mechanism")))


# --------------------------------------------------------------------------- kinematics


def _readings(pos: dict, prefix: tuple[str, ...]) -> list[dict]:
    return [r for r in pos.get("readings", []) if r["quantity"].split("_", 1)[0] in prefix]


def _crank_scale(item: Any, pos: dict, kind: str, lang: str, sec: Section) -> None:
    """The scale chosen: the crank's vector over its segment on the plan."""
    plan = pos["plans"][kind]
    first = _readings(pos, ("v",) if kind == "velocity" else ("a",))
    if not first:
        return
    r0 = first[0]
    q, sub = ("v", "v") if kind == "velocity" else ("a", "a")
    sec.para(say(lang, "Масштаб плана выбираем по отрезку, изображающему ", "The plan's scale is chosen from the segment of "),
             quantity(r0["quantity"], lang), say(lang, f" (отрезок {r0['segment']}):", f" (segment {r0['segment']}):"))
    sec.eq(Sym("μ", sub), "=", Frac(Text(r0["segment"]), quantity(r0["quantity"], lang)), "=",
           Frac(num(r0["length_mm"], lang), num(r0["exact"], lang)), "=", num(plan["scale"], lang),
           unit("mm/(m/s)" if q == "v" else "mm/(m/s^2)", lang))


def _reading_table(item: Any, k: int, pos: dict, kind: str, lang: str) -> Table:
    rows = []
    for r in _readings(pos, ("v", "omega") if kind == "velocity" else ("a", "eps")):
        name = r["quantity"]
        rows.append((_plain(name, lang), r["segment"] or "—",
                     fmt(r["length_mm"], lang) if r["length_mm"] is not None else "—",
                     fmt(r["exact"], lang), unit(r["unit"], lang)))
    phi = deg(pos["phi_deg"])
    cap = say(lang, f"Скорости точек и угловые скорости звеньев, φ = {phi}°",
              f"Velocities of the points and angular velocities of the links, φ = {phi}°") if kind == "velocity" else \
        say(lang, f"Ускорения точек и угловые ускорения звеньев, φ = {phi}°",
            f"Accelerations of the points and angular accelerations of the links, φ = {phi}°")
    return Table(f"{kind}-{item.index}-{k}", cap, (w("quantity", lang), w("segment", lang), w("mm", lang),
                                                   w("value", lang), w("unit", lang)), tuple(rows))


def _plain(name: str, lang: str) -> str:
    """A reading's name in a table cell: ω₂, ε₂, v_BA, a^n_BA."""
    base, _, rest = name.partition("_")
    base = {"omega": "ω", "eps": "ε"}.get(base, base)
    return f"{base}_{rest}" if rest else base


def kinematics(item: Any, lang: str, sec: Section) -> list[Section]:
    """Per studied position: the velocity and acceleration plans; then the tables over the
    positions."""
    out: list[Section] = []
    data = item.data
    for k in studied(item):
        pos = data["positions"][k]
        if "plans" not in pos:
            continue
        phi = deg(pos["phi_deg"])
        sub = Section(say(lang, f"Планы скоростей и ускорений, φ = {phi}°",
                          f"Velocity and acceleration plans, φ = {phi}°"), 2, key=f"kinematics-{phi}")
        if item.solved.scene.wants("positions"):
            sub.para(say(lang, f"Кинематическая схема механизма в этом положении — на рисунке {{fig:scheme-{item.index}-{phi}}}.",
                         f"The kinematic scheme in this position is in figure {{fig:scheme-{item.index}-{phi}}}."))
            sub.add(Figure(f"scheme-{item.index}-{phi}", item.index, f"scheme-{phi}",
                           say(lang, f"Кинематическая схема, φ = {phi}°", f"Kinematic scheme, φ = {phi}°")))
        for kind in ("velocity", "acceleration"):
            if kind not in pos["plans"]:
                continue
            _crank_scale(item, pos, kind, lang, sub)
            sub.para(say(lang, "Построение плана " + ("скоростей" if kind == "velocity" else "ускорений")
                         + " по векторным уравнениям групп:",
                         f"The {kind} plan is built from the groups' vector equations:"))
            _vector_equations(item, pos, kind, lang, sub)
            for s in item.plan_steps(k, kind):
                sub.para(symbols(s.say(lang), lang))
            _rates(item, pos, kind, lang, sub)
            fig = f"{kind}-{item.index}-{phi}"
            sub.add(Figure(fig, item.index, f"{kind}-{phi}",
                           say(lang, ("План скоростей" if kind == "velocity" else "План ускорений") + f", φ = {phi}°",
                               f"{kind.capitalize()} plan, φ = {phi}°")))
            tab = _reading_table(item, k, pos, kind, lang)
            sub.para(say(lang, f"План показан на рисунке {{fig:{fig}}}, отрезки и величины — в таблице {{tab:{tab.key}}}.",
                         f"The plan is in figure {{fig:{fig}}}, its segments and values in table {{tab:{tab.key}}}."))
            sub.add(tab)
        out.append(sub)
    tables = over_positions(item, lang)
    if tables:
        sub = Section(say(lang, "Результаты по положениям", "Results over the positions"), 2, key="kinematics-table")
        for t in tables:
            sub.para(say(lang, f"Величины по положениям механизма — в таблице {{tab:{t.key}}}.",
                         f"The quantities over the positions are in table {{tab:{t.key}}}."))
            sub.add(t)
        out.append(sub)
    return out


def _vector_equations(item: Any, pos: dict, kind: str, lang: str, sec: Section) -> None:
    """Each group's vector equation as a formula: v̄_B = v̄_A + v̄_BA (the joint pins)."""
    q = "v" if kind == "velocity" else "a"
    for g in item.solved.structure.groups:
        if isinstance(g, TriadGroup):  # class III: its equations are in the steps' sentences
            continue
        if g.kind in ("RRR", "RRP"):
            A, B = g.joints[0].point, g.joints[1].point
            if kind == "velocity":
                rhs: list = [Vec(Sym(q, A)), "+", Vec(Sym(q, B + A))]
            else:
                rhs = [Vec(Sym(q, A)), "+", Vec(Sym(q, B + A, "n")), "+", Vec(Sym(q, B + A, "τ"))]
            sec.eq(Vec(Sym(q, B)), "=", *rhs)
        elif g.kind == "RPR":  # the slotted link j turns about C, the block i slides in it at A
            A, C = g.joints[0].point, g.joints[2].point
            i, j = g.links
            Aj, Ai = f"{A}{j}", f"{A}{i}"
            if kind == "velocity":
                sec.eq(Vec(Sym(q, Aj)), "=", Vec(Sym(q, Ai)), "+", Vec(Sym(q, Aj + Ai)), "=",
                       Vec(Sym(q, C)), "+", Vec(Sym(q, Aj + C)))
            else:
                sec.eq(Vec(Sym(q, Aj)), "=", Vec(Sym(q, Ai)), "+", Vec(Sym(q, Aj + Ai, "k")), "+",
                       Vec(Sym(q, Aj + Ai, "r")), "=", Vec(Sym(q, C)), "+", Vec(Sym(q, Aj + C, "n")), "+",
                       Vec(Sym(q, Aj + C, "τ")))
                _coriolis(pos, lang, sec, Aj, Ai, j)
        # PRP and RPP: their equations are in the steps' sentences


def _rates(item: Any, pos: dict, kind: str, lang: str, sec: Section) -> None:
    """The links' angular velocities ω = v_XY/l_XY (or accelerations ε = a^τ_XY/l_XY) from the
    relative velocities read off the plan, where the plan has the link's two points."""
    scene = item.solved.scene
    r = {x["quantity"]: x["exact"] for x in pos.get("readings", [])}
    first = True
    for lid in sorted(scene.links):
        lk = scene.links[lid]
        if lid == scene.driver.link or len(lk.axis) != 2 or not lk.length:
            continue
        A, B = lk.axis
        rate = r.get(f"omega_{lid}" if kind == "velocity" else f"eps_{lid}")
        for X, Y in ((B, A), (A, B)):
            key = f"v_{X}{Y}" if kind == "velocity" else f"a_{X}{Y}^τ"
            if key in r and rate is not None:
                break
        else:
            continue
        rel = abs(r[key])
        if abs(rel / lk.length - abs(rate)) > 1e-6 * max(abs(rate), 1.0):
            continue  # the relative motion read is not the link's own turning
        if first:
            sec.para(say(lang, "Угловые " + ("скорости" if kind == "velocity" else "ускорения") + " звеньев:",
                         "The links' angular " + ("velocities:" if kind == "velocity" else "accelerations:")))
            first = False
        if kind == "velocity":
            sec.eq(Sym("ω", str(lid)), "=", Frac(Sym("v", X + Y), Sym("l", A + B)), "=",
                   Frac(num(rel, lang), num(lk.length, lang)), "=", num(abs(rate), lang), unit("rad/s", lang))
        else:
            sec.eq(Sym("ε", str(lid)), "=", Frac(Sym("a", X + Y, "τ"), Sym("l", A + B)), "=",
                   Frac(num(rel, lang), num(lk.length, lang)), "=", num(abs(rate), lang), unit("rad/s^2", lang))


def _coriolis(pos: dict, lang: str, sec: Section, Aj: str, Ai: str, j: int) -> None:
    """a^k = 2·ω_j·v_rel with the numbers read off the plans (the exact values)."""
    r = {x["quantity"]: x["exact"] for x in pos.get("readings", [])}
    ak = r.get(f"a^k_{Aj}{Ai}")
    w = r.get(f"omega_{j}")
    v = r.get(f"v_{Aj}{Ai}", r.get(f"v_{Ai}{Aj}"))
    if ak is None or w is None or v is None:
        return
    sec.eq(Sym("a", Aj + Ai, "k"), "=", Num("2"), "·", Sym("ω", str(j)), "·", Sym("v", Aj + Ai), "=", Num("2"), "·",
           num(abs(w), lang), "·", num(abs(v), lang), "=", num(abs(ak), lang), unit("m/s^2", lang))


def over_positions(item: Any, lang: str) -> list[Table]:
    """The plans' values over all the positions: rows of quantities, a column per position
    (the segments in mm stay in the per-position tables)."""
    data = item.data
    tabs = data.get("cycle", {}).get("tables", [])
    if not tabs or len(data["positions"]) < 2:
        return []
    t = tabs[0]
    phis = t["phi_deg"]
    out = []
    for part, heads in (("velocity", ("v", "omega")), ("acceleration", ("a", "eps"))):
        rows = []
        for r in t["rows"]:
            key = r["key"]
            if key.endswith(":mm") or key.split("_", 1)[0] not in heads:
                continue
            rows.append((f"{_plain(key, lang)}, {unit(r['unit'], lang)}",
                         *(fmt(v, lang, 3) if v is not None else "—" for v in r["values"])))
        if rows:
            cap = say(lang, "Скорости по положениям механизма", "Velocities over the positions") if part == "velocity" \
                else say(lang, "Ускорения по положениям механизма", "Accelerations over the positions")
            out.append(Table(f"{part}-all-{item.index}", cap, (w("phi", lang), *(deg(p) for p in phis)), tuple(rows)))
    return out
