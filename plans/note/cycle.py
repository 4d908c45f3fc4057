"""The cycle's sections: the kinematic diagrams (graphical differentiation, the scales)
and the machine's dynamics (I_pr, M_pr, works, the flywheel)."""

from __future__ import annotations

from typing import Any

from .linkage import deg
from .model import Figure, Frac, Section, Sym, Table, fmt, num, row
from .words import say, unit


def diagrams(item: Any, lang: str) -> Section | None:
    d = item.data.get("diagrams")
    if d is None:
        return None
    i = item.index
    sec = Section(say(lang, "Кинематические диаграммы", "Kinematic diagrams"), 2, key="diagrams")
    sec.para(say(lang, "Диаграммы перемещений строим по планам положений, диаграммы скоростей и ускорений — "
                       "графическим дифференцированием методом хорд. Масштаб угла поворота",
                 "The displacement diagrams come from the plans of positions, those of velocities and accelerations "
                 "from graphical differentiation by chords. The scale of the crank angle"))
    sec.eq(Sym("μ", "φ"), "=", num(d["mu_phi"], lang), unit("mm/rad", lang), ",", Sym("H", "1"), "=",
           num(d["pole_mm"], lang), unit("mm", lang), ",", Sym("H", "2"), "=", num(d["pole2_mm"], lang), unit("mm", lang))
    for g in d["diagrams"]:
        q, _, pt = g["name"].partition("_")
        u = {"s": "mm/m", "v": "mm/(m/s)", "a": "mm/(m/s^2)"}[q]
        if q == "s":
            sec.eq(Sym("μ", "s"), "=", num(g["scale"], lang), unit(u, lang), f" ({pt})")
        else:
            prev = "s" if q == "v" else "v"
            H = d["pole_mm"] if q == "v" else d["pole2_mm"]
            prev_scale = next(x["scale"] for x in d["diagrams"] if x["name"] == f"{prev}_{pt}")
            sec.eq(Sym("μ", q), "=", Frac(row(Sym("μ", prev), "·", Sym("H", "1" if q == "v" else "2")),
                                          row(Sym("μ", "φ"), "·", Sym("ω", "1"))), "=",
                   Frac(row(num(prev_scale, lang), "·", num(H, lang)), row(num(d["mu_phi"], lang), "·", num(d["omega"], lang))),
                   "=", num(g["scale"], lang), unit(u, lang), f" ({pt})")
        key = f"diagram-{i}-{g['name']}"
        sec.para(say(lang, f"{_diagram_caption(q, pt, lang)} — на рисунке {{fig:{key}}}.",
                     f"{_diagram_caption(q, pt, lang)}: figure {{fig:{key}}}."))
        sec.add(Figure(key, i, f"diagram-{g['name']}", _diagram_caption(q, pt, lang)))
    sec.para(say(lang, "Наибольшая погрешность графического метода, % размаха диаграммы: "
                 + "; ".join(f"{g['name']} — {fmt(g['error_max_pct'], lang, 2)}" for g in d["diagrams"]) + ".",
                 "The largest error of the graphical method, % of the diagram's range: "
                 + "; ".join(f"{g['name']}: {fmt(g['error_max_pct'], lang, 2)}" for g in d["diagrams"]) + "."))
    return sec


def _diagram_caption(q: str, pt: str, lang: str) -> str:
    ru = {"s": "перемещений", "v": "скоростей", "a": "ускорений"}[q]
    en = {"s": "Displacement", "v": "Velocity", "a": "Acceleration"}[q]
    return say(lang, f"Диаграмма {ru} точки {pt}", f"{en} diagram of point {pt}")


def dynamics(item: Any, lang: str) -> list[Section]:
    dy = item.data.get("dynamics")
    if dy is None:
        return []
    i = item.index
    out = []
    sec = Section(say(lang, "Приведённый момент инерции и приведённый момент сил",
                      "The reduced moment of inertia and the reduced moment of forces"), 2, key="dynamics-reduced")
    sec.para(say(lang, "Приведённый к начальному звену момент инерции по равенству кинетических энергий:",
                 "The moment of inertia reduced to the initial link, from the equality of kinetic energies:"))
    sec.eq(Sym("I", "пр" if lang == "ru" else "r"), "=", Sym("I", "A"), "+", Sym("Σ"),
           row("(", Sym("m", "i"), "·", row("(", Frac(Sym("v", "Si"), Sym("ω", "1")), ")"), Sym("", None, "2"), "+",
               Sym("I", "Si"), "·", row("(", Frac(Sym("ω", "i"), Sym("ω", "1")), ")"), Sym("", None, "2"), ")"))
    sec.para(say(lang, "Приведённый момент сил по равенству мощностей:", "The reduced moment of forces, from the equality of powers:"))
    sec.eq(Sym("M", "пр" if lang == "ru" else "r"), "=", Sym("Σ"), row(Frac(row(Sym("F", "k"), "·", Sym("v", "k"), "·",
                                                                                 Sym("cos α", "k")), Sym("ω", "1"))))
    rows = []
    for j, phi in enumerate(dy["phi_deg"]):
        rows.append((deg(phi), fmt(dy["I_pr"][j], lang), fmt(dy["M_pr"][j], lang), fmt(dy["A_d"][j], lang),
                     fmt(dy["A_c"][j], lang), fmt(dy["dT"][j], lang)))
    key = f"dynamics-{i}"
    ipr = "I_пр" if lang == "ru" else "I_r"
    mpr = "M_пр" if lang == "ru" else "M_r"
    ad, ac, dt = ("A_д", "A_с", "ΔT") if lang == "ru" else ("A_d", "A_c", "ΔT")
    sec.para(say(lang, f"Значения по положениям — в таблице {{tab:{key}}}; движущий момент постоянен, "
                       f"M_д = {fmt(dy['M_driving'], lang)} Н·м.",
                 f"The values over the positions are in table {{tab:{key}}}; the driving moment is constant, "
                 f"M_d = {fmt(dy['M_driving'], lang)} N·m."))
    sec.add(Table(key, say(lang, "Приведённые моменты, работы и приращение кинетической энергии",
                           "Reduced moments, works and the change of kinetic energy"),
                  ("φ, °", f"{ipr}, {unit('kg*m^2', lang)}", f"{mpr}, {unit('N*m', lang)}", f"{ad}, {unit('J', lang)}",
                   f"{ac}, {unit('J', lang)}", f"{dt}, {unit('J', lang)}"), tuple(rows)))
    for pid, ru, en in (("dyn-I", "Диаграмма приведённого момента инерции", "The reduced moment of inertia"),
                        ("dyn-M", "Диаграмма приведённого момента сил", "The reduced moment of forces"),
                        ("dyn-A", "Диаграммы работ", "The works"),
                        ("dyn-W", "Диаграмма энергомасс (Виттенбауэра)", "The energy–mass (Wittenbauer) diagram")):
        sec.para(say(lang, f"{ru} — на рисунке {{fig:{pid}-{i}}}.", f"{en}: figure {{fig:{pid}-{i}}}."))
        sec.add(Figure(f"{pid}-{i}", i, pid, say(lang, ru, en)))
    out.append(sec)
    fw = dy["flywheel"]
    sec = Section(say(lang, "Маховик", "The flywheel"), 2, key="flywheel")
    sec.para(say(lang, f"Коэффициент неравномерности хода δ = {fmt(fw['delta'], lang)}, средняя угловая скорость:",
                 f"The coefficient of fluctuation δ = {fmt(fw['delta'], lang)}, the mean angular velocity:"))
    sec.eq(Sym("ω", "m"), "=", num(fw["omega_mean"], lang), unit("rad/s", lang))
    sec.para(say(lang, "Момент инерции маховика по диаграмме энергомасс (касательные под углами ψ_max, ψ_min):",
                 "The flywheel's moment of inertia from the energy–mass diagram (tangents at ψ_max, ψ_min):"))
    kl = item.wittenbauer()
    with_numbers: list = []
    if kl is not None:
        k, l = kl
        with_numbers = [Frac(row(num(k, lang), "−", "(", num(l, lang), ")"),
                             row(num(fw["omega_mean"], lang), Sym("", None, "2"), "·", num(fw["delta"], lang))), "="]
        sec.para(say(lang, "Касательные отсекают на оси ΔT отрезки k и l (в джоулях): ",
                     "The tangents cut the ΔT axis at k and l (in joules): "),
                 row(Sym("k"), "=", num(k, lang), unit("J", lang), ",", Sym("l"), "=", num(l, lang), unit("J", lang)))
    sec.eq(Sym("I", "M"), "=", Frac(row(Sym("k"), "−", Sym("l")), row(Sym("ω", "m", "2"), "·", Sym("δ"))), "=",
           *with_numbers, num(fw["inertia_graphical"], lang), unit("kg*m^2", lang))
    sec.para(say(lang, "Точным интегрированием уравнения движения:", "By exact integration of the equation of motion:"))
    sec.eq(Sym("I", "M"), "=", num(fw["inertia_exact"], lang), unit("kg*m^2", lang))
    sec.para(say(lang, "По методу Мерцалова (ΔT_I — изменение кинетической энергии звеньев постоянного "
                       "приведённого момента инерции):",
                 "By Merkalov's method (ΔT_I: the change of kinetic energy of the links of constant reduced "
                 "moment of inertia):"))
    sec.eq(Sym("I", "M"), "=", Frac(Sym("ΔT", "I max"), row(Sym("ω", "m", "2"), "·", Sym("δ"))), "=",
           num(fw["inertia_merkalov"], lang), unit("kg*m^2", lang))
    sec.para(say(lang, f"С маховиком по диаграмме энергомасс достигнутый коэффициент неравномерности "
                       f"δ = {fmt(fw['delta_achieved'], lang)}.",
                 f"With the flywheel from the energy–mass diagram the achieved coefficient of fluctuation is "
                 f"δ = {fmt(fw['delta_achieved'], lang)}."))
    sec.para(say(lang, f"Угловая скорость за цикл — на рисунке {{fig:dyn-omega-{i}}}.",
                 f"The angular velocity over the cycle is in figure {{fig:dyn-omega-{i}}}."))
    sec.add(Figure(f"dyn-omega-{i}", i, "dyn-w", say(lang, "Угловая скорость начального звена за цикл",
                                                      "The initial link's angular velocity over the cycle")))
    out.append(sec)
    return out
