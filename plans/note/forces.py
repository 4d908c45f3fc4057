"""The force analysis of each studied position: the loads (gravity, inertia forces and
couples, the working forces), each Assur group's moment equations and polygon, the
crank, the Zhukovsky lever and the balancing force found three ways."""

from __future__ import annotations

import math
from typing import Any

from .equations import label, moment
from .linkage import deg, studied
from .model import (
    Equation,
    Figure,
    Formula,
    Frac,
    Num,
    Row,
    Section,
    Sym,
    Table,
    Text,
    fmt,
    num,
    of_tables,
    row,
)
from .words import quantity, say, symbols, unit, w


def _abs(v: list[float]) -> float:
    return math.hypot(v[0], v[1])


def _label(lb: str, lang: str) -> str:
    return symbols(lb, lang)


def forces(item: Any, lang: str) -> list[Section]:
    sol = item.solved
    if sol.forces is None:
        return []
    scene = sol.scene
    out: list[Section] = []
    for k in studied(item):
        pos = item.data["positions"][k]
        if "balancing" not in pos:
            continue
        phi = deg(pos["phi_deg"])
        sec = Section(say(lang, f"Силовой расчёт, φ = {phi}°", f"Force analysis, φ = {phi}°"), 2, key=f"forces-{phi}")
        # ---- gravity
        weights = [(lb[1:], _abs(v)) for lb, v in pos.get("loads", {}).items()
                   if lb.startswith("G") and lb[1:].isdigit() and int(lb[1:]) in scene.links]
        if weights:
            sec.para(say(lang, "Силы тяжести звеньев:", "The links' weights:"))
        for lid_s, G in weights:
            m = scene.links[int(lid_s)].mass
            if m:
                sec.eq(Sym("G", lid_s), "=", Sym("m", lid_s), "·", Sym("g"), "=", num(m, lang), "·",
                       num(G / m, lang, 3), "=", num(G, lang), unit("N", lang))
        # ---- inertia
        sec.para(say(lang, "Силы инерции и моменты пар сил инерции звеньев:",
                     "The links' inertia forces and the moments of their inertia couples:"))
        for lid_s, inert in sorted(pos.get("inertia", {}).items(), key=lambda t: int(t[0])):
            lk = scene.links[int(lid_s)]
            F = _abs(inert["force"])
            if lk.mass and F > 0:
                centre = lk.centre or (lk.axis[0] if len(lk.axis) == 1 else None)
                a_s = _abs(pos["points"][centre]["a"]) if centre and centre in pos["points"] else None
                if a_s is not None:
                    sec.eq(Sym("Φ", lid_s), "=", Sym("m", lid_s), "·", Sym("a", centre), "=",
                           num(lk.mass, lang), "·", num(a_s, lang), "=", num(F, lang), unit("N", lang))
            M = inert.get("moment", 0.0)
            if lk.inertia and abs(M) > 1e-9:
                eps = abs(pos["links"][lid_s]["eps"])
                sec.eq(Sym("M", f"Φ{lid_s}"), "=", Sym("I", f"S{lid_s}"), "·", Sym("ε", lid_s), "=",
                       num(lk.inertia, lang), "·", num(eps, lang), "=", num(abs(M), lang), unit("N·m", lang))
        gas = item.gas()
        for lb, v in pos.get("loads", {}).items():
            if lb in gas and _abs(v) > 0:
                area, p = gas[lb]
                sec.para(say(lang, f"Сила давления газов на поршень {lb} (площадь поршня ",
                             f"The gas force on piston {lb} (the piston's area "),
                         row(Sym("F", "п" if lang == "ru" else "p"), "=", Frac(row("π", Sym("d", None, "2")), Num("4")),
                             "=", num(area, lang), unit("m^2", lang)),
                         say(lang, f", давление p = {fmt(p, lang)} Па):", f", pressure p = {fmt(p, lang)} Pa):"))
                sec.eq(label(lb, lang), "=", Sym("p"), "·", Sym("F", "п" if lang == "ru" else "p"), "=", num(p, lang),
                       "·", num(area, lang), "=", num(_abs(v), lang), unit("N", lang))
        loads = [(lb, _abs(v)) for lb, v in pos.get("loads", {}).items()
                 if not lb.startswith("Phi") and not (lb.startswith("G") and lb[1:] in dict(weights))
                 and not (lb in gas and _abs(v) > 0)]
        if loads:
            sec.para(say(lang, "Внешние силы: ", "The applied forces: ")
                     + "; ".join(f"{_label(lb, lang)} = {fmt(F, lang)} {unit('N', lang)}" for lb, F in loads) + ".")
        # ---- groups, crank, lever
        current = None
        for fs in item.force_steps(k):
            if fs.plan != current:
                current = fs.plan
                _heading(item, fs.plan, phi, lang, sec)
            sec.para(symbols(fs.step.say(lang), lang))
            for f in moment(fs.step, lang):
                sec.add(Equation(f))
        _reactions(item, k, pos, phi, lang, sec)
        _three_ways(item, pos, phi, lang, sec)
        out.append(sec)
    table = _balancing_over(item, lang)
    return out + of_tables(
        say(lang, "Уравновешивающая сила по положениям", "The balancing force over the positions"), "forces-table",
        [] if table is None else [table],
        lambda key: say(lang, f"Уравновешивающая сила во всех положениях — в таблице {{tab:{key}}}.",
                        f"The balancing force at every position is in table {{tab:{key}}}."))


def _heading(item: Any, plan: str, phi: str, lang: str, sec: Section) -> None:
    i = item.index
    if plan.startswith("group "):
        g = plan[len("group "):]
        sec.para(say(lang, f"Группа Ассура {g}. Её звенья с приложенными силами — на рисунке "
                           f"{{fig:group-{i}-{g}-{phi}}}, план сил — на рисунке {{fig:polygon-{i}-{g}-{phi}}}.",
                     f"Assur group {g}. Its links with their forces are in figure {{fig:group-{i}-{g}-{phi}}}, "
                     f"its force polygon in figure {{fig:polygon-{i}-{g}-{phi}}}."))
        sec.add(Figure(f"group-{i}-{g}-{phi}", i, f"group-{g}-{phi}",
                       say(lang, f"Группа {g} с приложенными силами, φ = {phi}°", f"Group {g} with its forces, φ = {phi}°")),
                Figure(f"polygon-{i}-{g}-{phi}", i, f"polygon-{g}-{phi}",
                       say(lang, f"План сил группы {g}, φ = {phi}°", f"Force polygon of group {g}, φ = {phi}°")))
    elif plan == "crank":
        sec.para(say(lang, f"Начальное звено (рисунки {{fig:crank-{i}-{phi}}} и {{fig:polygon-crank-{i}-{phi}}}).",
                     f"The initial link (figures {{fig:crank-{i}-{phi}}} and {{fig:polygon-crank-{i}-{phi}}})."))
        sec.add(Figure(f"crank-{i}-{phi}", i, f"crank-{phi}",
                       say(lang, f"Начальное звено с приложенными силами, φ = {phi}°",
                           f"The initial link with its forces, φ = {phi}°")),
                Figure(f"polygon-crank-{i}-{phi}", i, f"polygon-crank-{phi}",
                       say(lang, f"План сил начального звена, φ = {phi}°", f"Force polygon of the initial link, φ = {phi}°")))
    elif plan == "lever":
        sec.para(say(lang, f"Рычаг Жуковского (рисунок {{fig:lever-{i}-{phi}}}).",
                     f"The Zhukovsky lever (figure {{fig:lever-{i}-{phi}}})."))
        sec.add(Figure(f"lever-{i}-{phi}", i, f"lever-{phi}",
                       say(lang, f"Рычаг Жуковского, φ = {phi}°", f"Zhukovsky lever, φ = {phi}°")))


def _reactions(item: Any, k: int, pos: dict, phi: str, lang: str, sec: Section) -> None:
    reac = pos.get("reactions", {})
    seen: set[frozenset[str]] = set()
    rows = []
    for name, v in reac.items():
        pair = frozenset((name[1:2], name[2:3]))
        if pair in seen:
            continue
        seen.add(pair)
        rows.append((name, fmt(_abs(v), lang)))
    if rows:
        key = f"reactions-{item.index}-{phi}"
        sec.para(say(lang, f"Реакции в кинематических парах — в таблице {{tab:{key}}} (F_ij — сила на звено i со стороны звена j).",
                     f"The reactions in the pairs are in table {{tab:{key}}} (F_ij: the force on link i from link j)."))
        sec.add(Table(key, say(lang, f"Реакции в кинематических парах, φ = {phi}°", f"Reactions in the pairs, φ = {phi}°"),
                      (w("reaction", lang), w("force_N", lang)), tuple(rows)))


def _three_ways(item: Any, pos: dict, phi: str, lang: str, sec: Section) -> None:
    b = pos["balancing"]
    force = b["kind"] == "force"
    u = unit("N" if force else "N·m", lang)
    sym = quantity("F_bal" if force else "M_bal", lang)
    sec.para(say(lang, "Уравновешивающая сила, найденная тремя способами:" if force else
                 "Уравновешивающий момент, найденный тремя способами:",
                 "The balancing force found three ways:" if force else "The balancing moment found three ways:"))
    for key, word in (("by_kinetostatics", "by_kin"), ("by_lever", "by_lever"), ("by_power", "by_power")):
        if b.get(key) is None:
            continue
        sec.para(w(word, lang) + ": ", row(sym, "=", num(b[key], lang), u))
    if b.get("difference_percent") is not None:
        sec.para(say(lang, "Расхождение значений по планам сил и по рычагу Жуковского (по отрезкам чертежей):",
                     "The difference between the force polygons and the lever (as read on the drawings):"))
        sec.eq(Sym("Δ"), "=", _frac_diff(sym, lang), "·", num(100, lang), "%", "=",
               num(b["difference_percent"], lang, 3), "%")
    if b.get("exact_difference_percent") is not None:
        sec.para(say(lang, f"По точным значениям расхождение {fmt(b['exact_difference_percent'], lang, 3)} %.",
                     f"By the exact values the difference is {fmt(b['exact_difference_percent'], lang, 3)} %."))


def _frac_diff(sym: Formula, lang: str) -> Formula:
    """(F_ур(пс) − F_ур(Ж)) / F_ур(пс): the polygons' value against the lever's."""

    def s(tag: str) -> Formula:
        return Row((sym, Text(f" ({tag})")))

    kin, lev = say(lang, "пс", "fp"), say(lang, "Ж", "Zh")
    return Frac(row(s(kin), "−", s(lev)), s(kin))


def _balancing_over(item: Any, lang: str) -> Table | None:
    positions = item.data["positions"]
    if len(positions) < 2 or "balancing" not in positions[0]:
        return None
    rows = []
    for p in positions:
        b = p["balancing"]
        rows.append((deg(p["phi_deg"]), fmt(b["by_kinetostatics"], lang),
                     fmt(b["by_lever"], lang) if b["by_lever"] is not None else "—",
                     fmt(b["by_power"], lang) if b["by_power"] is not None else "—"))
    force = positions[0]["balancing"]["kind"] == "force"
    sym = ("F_ур" if lang == "ru" else "F_bal") if force else ("M_ур" if lang == "ru" else "M_bal")
    u = unit("N" if force else "N·m", lang)
    return Table(f"balancing-all-{item.index}", say(lang, "Уравновешивающая сила по положениям механизма",
                                                     "The balancing force over the positions"),
                 (w("phi", lang), f"{sym} {w('by_kin', lang)}, {u}", f"{sym} {w('by_lever', lang)}, {u}",
                  f"{sym} {w('by_power', lang)}, {u}"),
                 tuple(rows))
