"""The sections of the other files: gears (geometry of each pair, the train's speeds),
a cam (motion law, base radius, pressure angles), an engine's balancing."""

from __future__ import annotations

import math
import re
from typing import Any

from .model import Figure, Frac, Num, Section, Sym, Table, fmt, num, row
from .words import say, unit, w

_LATIN = re.compile(r"[A-Za-z]{3,}")
_CYRILLIC = re.compile(r"[А-Яа-яЁё]")


def in_language(text: str, lang: str) -> bool:
    """Whether a file's own text (a title) may stand in a note of ``lang``."""
    return not (_LATIN.search(text) if lang == "ru" else _CYRILLIC.search(text))


def _title(item: Any, lang: str, default_ru: str, default_en: str) -> str:
    t = item.raw.get("title")
    if isinstance(t, dict):
        t = t.get(lang)
    return t if isinstance(t, str) and t and in_language(t, lang) else say(lang, default_ru, default_en)


def gears(item: Any, lang: str) -> Section:
    sol, data = item.solved, item.data
    gf = sol.file
    sec = Section(w("gears", lang), 1, key="gears")
    sec.para(_title(item, lang, "Зубчатый механизм", "Gear mechanism") + say(
        lang, f": модуль m = {fmt(next(iter(gf.gears.values())).module * 1000, lang)} мм, угол профиля α = "
              f"{fmt(math.degrees(gf.alpha), lang)}°, h_a* = {fmt(gf.ha, lang)}, c* = {fmt(gf.c, lang)}.",
        f": module m = {fmt(next(iter(gf.gears.values())).module * 1000, lang)} mm, pressure angle α = "
        f"{fmt(math.degrees(gf.alpha), lang)}°, h_a* = {fmt(gf.ha, lang)}, c* = {fmt(gf.c, lang)}."))
    i = item.index
    for n, me in enumerate(data["meshes"]):
        a, b = me["gears"]
        za, zb = gf.gears[a].z, gf.gears[b].z
        xa, xb = me["x"][a], me["x"][b]
        sub = Section(say(lang, f"Передача {a}–{b}", f"Pair {a}–{b}"), 2, key=f"mesh-{a}-{b}")
        sub.para(say(lang, f"Числа зубьев z_{a} = {za}, z_{b} = {zb}; коэффициенты смещения x_{a} = {fmt(xa, lang)}, "
                           f"x_{b} = {fmt(xb, lang)}. Угол зацепления:",
                     f"Teeth z_{a} = {za}, z_{b} = {zb}; shifts x_{a} = {fmt(xa, lang)}, x_{b} = {fmt(xb, lang)}. "
                     "The working pressure angle:"))
        sign = "−" if me["internal"] else "+"
        sub.eq(Sym("inv α", "w"), "=", Sym("inv α"), "+", Frac(row(Num("2"), "(", Sym("x", a), sign, Sym("x", b), ")"),
                                                              row(Sym("z", a), sign, Sym("z", b))), "·", Sym("tg α"))
        sub.eq(Sym("α", "w"), "=", num(me["working_pressure_angle_deg"], lang, 6), "°")
        sub.eq(Sym("a", "w"), "=", Sym("a"), "·", Frac(Sym("cos α"), Sym("cos α", "w")), "=",
               num(me["reference_centre_distance"], lang), "·", Frac(Sym("cos α"), Sym("cos α", "w")), "=",
               num(me["centre_distance"], lang), unit(data["unit"], lang))
        sub.eq(Sym("ε", "α"), "=", num(me["contact_ratio"], lang))
        rows = []
        for g in (a, b):
            r = me["radii"][g]
            rows.append((g, str(gf.gears[g].z), fmt(me["x"][g], lang), fmt(r["pitch"], lang), fmt(r["base"], lang),
                         fmt(r["tip"], lang), fmt(r["root"], lang), fmt(r["working"], lang), fmt(me["tip_thickness"][g], lang)))
        key = f"mesh-{i}-{n}"
        sub.para(say(lang, f"Размеры колёс — в таблице {{tab:{key}}}, мм.", f"The gears' dimensions are in table {{tab:{key}}}, mm."))
        sub.add(Table(key, say(lang, f"Размеры колёс передачи {a}–{b}", f"Dimensions of the gears of pair {a}–{b}"),
                      (w("gear", lang), "z", "x", "r", "r_b", "r_a", "r_f", "r_w", "s_a"), tuple(rows)))
        fails = [k for k, ok in me["checks"].items() if not ok]
        sub.para(say(lang, "Все проверки выполнены." if not fails else
                     "Не выполнены проверки: " + ", ".join(_check(f, lang) for f in fails) + ".",
                     "Every check passes." if not fails else "Checks failed: " + ", ".join(_check(f, lang) for f in fails) + "."))
        if n == 0:
            sub.para(say(lang, f"Картина зацепления — на рисунке {{fig:meshing-{i}}}.", f"The meshing is in figure {{fig:meshing-{i}}}."))
            sub.add(Figure(f"meshing-{i}", i, "kind:meshing", say(lang, f"Картина зацепления {a}–{b}", f"Meshing of {a}–{b}")))
        sec.children.append(sub)
    if "speeds_rpm" in data:
        sub = Section(say(lang, "Частоты вращения", "Speeds"), 2, key="gear-speeds")
        speeds = [(g, fmt(v, lang), fmt(data["speeds_rpm_plan"].get(g, float("nan")), lang))
                  for g, v in data["speeds_rpm"].items()]
        key = f"speeds-{i}"
        sub.para(say(lang, f"Частоты вращения по формуле Виллиса и по плану скоростей — в таблице {{tab:{key}}}.",
                     f"Speeds by Willis's formula and by the velocity plan are in table {{tab:{key}}}."))
        sub.add(Table(key, say(lang, "Частоты вращения, об/мин", "Speeds, rpm"),
                      (say(lang, "Вал", "Shaft"), say(lang, "по Виллису", "by Willis"), say(lang, "по плану скоростей", "by the plan")),
                      tuple(speeds)))
        sub.para(say(lang, f"План линейных скоростей — на рисунке {{fig:gear-plan-{i}}}.",
                     f"The plan of linear velocities is in figure {{fig:gear-plan-{i}}}."))
        sub.add(Figure(f"gear-plan-{i}", i, "kind:velocity-plan", say(lang, "План линейных скоростей", "Plan of linear velocities")))
        sec.children.append(sub)
    return sec


def _check(key: str, lang: str) -> str:
    name, _, g = key.rpartition("_") if key[-1].isdigit() else (key, "", "")
    ru = {"contact_ratio": "коэффициент перекрытия", "no_undercut": "отсутствие подрезания",
          "tip_thickness": "толщина зуба на вершине", "no_interference": "отсутствие интерференции"}
    en = {"contact_ratio": "contact ratio", "no_undercut": "no undercut", "tip_thickness": "tip thickness",
          "no_interference": "no interference"}
    t = (ru if lang == "ru" else en).get(name, name.replace("_", " "))
    return f"{t} ({g})" if g else t


def cam(item: Any, lang: str) -> Section:
    cm, d = item.solved, item.data
    u = unit(d["unit"], lang)
    L = 1.0 / cm.scale
    sec = Section(w("cams", lang), 1, key="cams")
    fol = say(lang, "поступательно движущимся" if cm.follower == "translating" else "коромысловым",
              "translating" if cm.follower == "translating" else "oscillating")
    sec.para(_title(item, lang, "Кулачковый механизм", "Cam mechanism") + say(
        lang, f" с {fol} толкателем; ход h = {fmt(cm.h * L, lang)} {u}, частота вращения кулачка "
              f"ω = {fmt(cm.omega, lang)} рад/с.",
        f" with a {fol} follower; lift h = {fmt(cm.h * L, lang)} {u}, the cam turns at ω = {fmt(cm.omega, lang)} rad/s."))
    rows = []
    for ph in cm.phases:
        rows.append((say(lang, {"rise": "подъём", "dwell": "выстой", "return": "опускание"}.get(ph.kind, ph.kind),
                         ph.kind), fmt(math.degrees(ph.angle), lang), ph.law_name if ph.kind != "dwell" else "—"))
    key = f"phases-{item.index}"
    sec.para(say(lang, f"Фазы движения толкателя — в таблице {{tab:{key}}}.", f"The follower's phases are in table {{tab:{key}}}."))
    sec.add(Table(key, say(lang, "Фазы движения толкателя", "Phases of the follower"),
                  (say(lang, "Фаза", "Phase"), say(lang, "Угол, °", "Angle, °"), say(lang, "Закон", "Law")),
                  tuple((a, b, _law(c, lang)) for a, b, c in rows)))
    sec.para(say(lang, "Минимальный радиус начальной шайбы из условия допустимого угла давления (диаграмма ds/dφ – s):",
                 "The smallest base radius from the permissible pressure angle (the ds/dφ – s diagram):"))
    sec.eq(Sym("r", "0 min"), "=", num(d["min_base_radius"], lang), u)
    if d.get("min_base_radius_graphical") is not None:
        sec.para(say(lang, "по точкам деления диаграммы: ", "from the diagram's division points: "),
                 row(Sym("r", "0 min"), "=", num(d["min_base_radius_graphical"], lang), u))
    sec.para(say(lang, "Принятый радиус: ", "The base radius taken: "), row(Sym("r", "0"), "=", num(cm.base_radius * L, lang), u))
    sec.para(say(lang, f"Наибольший угол давления на подъёме {fmt(d['max_pressure_angle_rise_deg'], lang)}°, "
                       f"на опускании {fmt(d['max_pressure_angle_return_deg'], lang)}°; наименьший радиус кривизны "
                       f"профиля {fmt(d['min_curvature_radius'], lang)} {u}" + ("; подрезания нет." if not d["undercut"] else "; профиль подрезан."),
                 f"The largest pressure angle on the rise is {fmt(d['max_pressure_angle_rise_deg'], lang)}°, on the return "
                 f"{fmt(d['max_pressure_angle_return_deg'], lang)}°; the smallest radius of curvature "
                 f"{fmt(d['min_curvature_radius'], lang)} {u}" + ("; no undercut." if not d["undercut"] else "; the profile is undercut.")))
    i = item.index
    sec.para(say(lang, f"Диаграммы движения — на рисунке {{fig:cam-motion-{i}}}, профиль кулачка — на рисунке {{fig:cam-profile-{i}}}.",
                 f"The motion diagrams are in figure {{fig:cam-motion-{i}}}, the profile in figure {{fig:cam-profile-{i}}}."))
    sec.add(Figure(f"cam-motion-{i}", i, "kind:cam-motion", say(lang, "Диаграммы движения толкателя", "The follower's motion diagrams")),
            Figure(f"cam-profile-{i}", i, "kind:cam-profile", say(lang, "Профиль кулачка", "The cam's profile")))
    return sec


def _law(law: Any, lang: str) -> str:
    if not isinstance(law, str) or law in ("", "—"):
        return "—"
    ru = {"harmonic": "косинусоидальный", "cycloidal": "синусоидальный",
          "constant_acceleration": "равноускоренный (параболический)", "poly345": "полином 3-4-5",
          "table": "по таблице"}
    en = {"harmonic": "harmonic (cosine)", "cycloidal": "cycloidal (sine)",
          "constant_acceleration": "constant acceleration (parabolic)", "poly345": "3-4-5 polynomial",
          "table": "a table"}
    return (ru if lang == "ru" else en).get(law, "—")


def balancing(item: Any, lang: str) -> Section:
    d = item.data
    e = d["engine"]
    sec = Section(w("balancing", lang), 1, key="balancing")
    sec.para(say(lang, f"Двигатель: число цилиндров {e['cylinders']}, радиус кривошипа r = {fmt(e['r'], lang)} м, λ = {fmt(e['lambda'], lang)}, "
                       f"ω = {fmt(e['omega'], lang)} рад/с.",
                 f"The engine: {e['cylinders']} cylinders, crank radius r = {fmt(e['r'], lang)} m, λ = {fmt(e['lambda'], lang)}, "
                 f"ω = {fmt(e['omega'], lang)} rad/s."))
    rows = []
    names = {"rotating": say(lang, "вращающихся масс", "rotating masses"),
             "first_order": say(lang, "первого порядка", "first order"),
             "second_order": say(lang, "второго порядка", "second order")}
    for k, f in d["forces"].items():
        mo = d["moments"].get(k, {})
        rows.append((names.get(k, k), fmt(f.get("amplitude", 0.0), lang), fmt(mo.get("amplitude", 0.0), lang)))
    key = f"balance-{item.index}"
    sec.para(say(lang, f"Неуравновешенные силы и моменты — в таблице {{tab:{key}}}.",
                 f"The unbalanced forces and moments are in table {{tab:{key}}}."))
    sec.add(Table(key, say(lang, "Неуравновешенные силы и моменты", "Unbalanced forces and moments"),
                  (say(lang, "Силы", "Forces"), say(lang, "Сила, Н", "Force, N"), say(lang, "Момент, Н·м", "Moment, N·m")),
                  tuple(rows)))
    for cw in d["counterweights"]:
        what = names.get(cw["for"], cw["for"])
        sec.para(say(lang, f"Противовес для сил {what}: ", f"Counterweight ({what}): "),
                 row(Sym("m", "пв" if lang == "ru" else "cw"), "·", Sym("r", "пв" if lang == "ru" else "cw"), "=",
                     num(cw["mass_radius"], lang), unit("kg", lang) + "·" + unit("m", lang)),
                 say(lang, f" (масса {fmt(cw['mass'], lang)} кг на радиусе {fmt(cw['radius'], lang)} м, "
                           f"угол {fmt(cw['angle_deg'], lang)}°).",
                     f" (mass {fmt(cw['mass'], lang)} kg at radius {fmt(cw['radius'], lang)} m, "
                     f"angle {fmt(cw['angle_deg'], lang)}°)."))
    return sec
