"""The checker's words in both languages: a finding's sentence, the kinds of finding and of
mistake as a teacher names them, and the check's report on the terminal, its text and CSV
(read through :mod:`plans.language`)."""

from __future__ import annotations

#: key -> (English, Russian): a finding's sentence (:class:`plans.check.wording.Words`).
CHECK_SENTENCES: dict[str, tuple[str, str]] = {
    "duplicate": ("φ = {phi}°: {q} is written as {shown}",
                  "φ = {phi}°: {q} записана по-разному: {shown}"),
    "duplicate_segment": ("φ = {phi}°: the segment for {q} is written as {shown}",
                          "φ = {phi}°: отрезок для {q} записан по-разному: {shown}"),
    "across": ("{q} does not depend on the crank angle but is written as {shown}",
               "{q} не зависит от угла поворота кривошипа, но записана по-разному: {shown}"),
    "fig": ("{w}{where}", "{w}{where}"),
    "fig_mm": ("{w} mm{where}", "{w} мм{where}"),
    "fig_at": ("{w} at {phi}°{where}", "{w} при φ = {phi}°{where}"),
    "symmetry": ("φ = {phi}°: {a} and {b} are exactly equal at this position (both {exact} {unit}: symmetry), "
                 "but the student has {sa}{wa} and {sb}{wb} {unit}{mm}",
                 "φ = {phi}°: {a} и {b} в этом положении равны точно (обе {exact} {unit}: симметрия), "
                 "а у студента {sa}{wa} и {sb}{wb} {unit}{mm}"),
    "mm_pair": (" ({x} mm and {y} mm)", " ({x} мм и {y} мм)"),
    "swapped": ("φ = {phi}°: {q} = {smm} mm and {s} = {pmm} mm are swapped: on the {plan} plan at the "
                "student's scale {q} is {emm} mm and {s} {slen} mm",
                "φ = {phi}°: {q} = {smm} мм и {s} = {pmm} мм перепутаны: на плане {plan} в масштабе "
                "студента {q} = {emm} мм, а {s} = {slen} мм"),
    "wrong_segment": ("φ = {phi}°: {q} = {smm} mm{where} is close to the length of {s} ({slen} mm), not of {q} "
                      "({emm} mm): was the wrong segment measured?",
                      "φ = {phi}°: {q} = {smm} мм{where} близко к длине {s} ({slen} мм), а не {q} ({emm} мм): "
                      "измерен не тот отрезок?"),
    "pi": ("φ = {phi}°: {q} = {s}{where} is computed with π = 3.14: with π it is {exact} {unit} ({pct} %), "
           "and everything computed from it inherits the error",
           "φ = {phi}°: {q} = {s}{where} вычислено с π = 3,14: с точным π это {exact} {unit} ({pct} %), "
           "и всё, что вычислено из неё, наследует ошибку"),
    "scale_values": ("the {plan} values are their measured segments divided by {mu2} mm per unit, but the "
                     "sheet's {sym} is {mu}: the student divided by the wrong scale, the values are {pct} % off",
                     "значения {plan} — измеренные отрезки, делённые на {mu2} мм на единицу, а на листе "
                     "{sym} = {mu}: студент разделил не на тот масштаб, значения отличаются на {pct} %"),
    "scale_drawn": ("every measured segment of the {plan} plans is {r}× its exact length at {sym} = {mu}: the "
                    "plans look drawn at {sym} = {mu2}, not at the scale written on the sheet",
                    "каждый измеренный отрезок планов {plan} равен {r}× его точной длины при {sym} = {mu}: "
                    "планы будто построены при {sym} = {mu2}, а не в масштабе, записанном на листе"),
    "arithmetic": ("φ = {phi}°: {q} = {w}{where}, but the segment measured for it, {m} mm{mwhere}, at the scale "
                   "{mu} mm per {unit} gives {want} {unit}",
                   "φ = {phi}°: {q} = {w}{where}, но измеренный для неё отрезок {m} мм{mwhere} в масштабе "
                   "{mu} мм на {unit} даёт {want} {unit}"),
    "relation": ("φ = {phi}°: {target} = {shown}{where}, but {formula} = {want} with {used}{hint}",
                 "φ = {phi}°: {target} = {shown}{where}, но {formula} = {want} при {used}{hint}"),
    "use": ("{q} = {w}", "{q} = {w}"),
    "hint_lever": ("; the student's {value} % divides by the kinetostatic force {kin} ({other} %): the wrong "
                   "denominator, the course compares with the Zhukovsky lever's {lever}",
                   "; студент делит {value} % на {kin} из кинетостатики ({other} %): не тот знаменатель, "
                   "в курсе сравнивают с {lever}"),
    "hint_kin": ("; the student's {value} % divides by the lever's {lever} ({other} %): the wrong denominator, "
                 "the course compares with {kin}",
                 "; студент делит {value} % на {lever} ({other} %): не тот знаменатель, в курсе "
                 "сравнивают с {kin}"),
}

#: The kinds of finding as a teacher names them in Russian.
KINDS_RU = {"duplicate": "повтор", "arithmetic": "арифметика", "relation": "формула", "percent": "проценты",
            "symmetry": "симметрия", "swapped": "перепутаны", "pi": "π", "scale": "масштаб"}
#: The kinds of mistake (:data:`plans.check.mistakes.KINDS`) as a teacher names them.
CAUSES = {
    "coriolis_reversed": ("the Coriolis vector laid off the wrong way", "ускорение Кориолиса отложено в обратную сторону"),
    "normal_from_pole": ("a normal component laid off from the pole or in the wrong sense",
                         "нормальное ускорение отложено от полюса или не в ту сторону"),
    "tangential_wrong_line": ("a tangential component on the wrong line", "касательное ускорение — не по той линии"),
    "scale": ("a wrong scale", "ошибка масштаба"),
    "similarity": ("a point found by similarity wrongly", "точка по подобию найдена неверно"),
    "wrong_segment": ("the wrong segment measured", "измерен не тот отрезок"),
    "inertia_sign": ("an inertia force or couple with the wrong sign", "знак силы или момента сил инерции"),
    "reaction_swapped": ("a reaction's τ and n components swapped", "перепутаны составляющие реакции τ и n"),
    "fij_reversed": ("F_ij read for F_ji", "F_ij вместо F_ji"),
    "shift_coefficient": ("a wrong shift coefficient", "неверный коэффициент смещения"),
    "base_radius": ("a wrong base circle", "неверная начальная шайба"),
    "pi_rounded": ("π = 3.14", "π = 3,14"),
    "g_rounded": ("g = 10", "g = 10"),
    "arithmetic": ("an arithmetic slip", "ошибка в вычислении"),
}
#: "план скоростей": the plans' kinds in the genitive.
PLANS_RU = {"velocity": "скоростей", "acceleration": "ускорений"}


#: key -> (English, Russian): the check's report on the terminal, its text file and CSV.
CHECK_TERMS: dict[str, tuple[str, str]] = {
    "ch_title": ("Check of {student} — {title}", "Проверка: {student} — {title}"),
    "ch_file": ("  file {path}", "  файл {path}"),
    "ch_cycle_title": ("Check of {student} — cycle tables of {title}", "Проверка: {student} — таблицы цикла: {title}"),
    "ch_cycle_sum": ("  {n} figures: {passed} pass, {failed} fail", "  величин {n}: верно {passed}, неверно {failed}"),
    "ch_error_pct": ("error %", "ошибка, %"),
    "ch_tolerance_col": ("tolerance", "допуск"),
    "ch_scales": ("; scales {scales}", "; масштабы {scales}"),
    "ch_scale": ("{kind} {mu} {unit}", "{kind} = {mu} {unit}"),
    "ch_tolerance": ("  tolerance: {model}", "  допуск: {model}"),
    "ch_draftsman": ("draftsman: ±{seg} mm per segment, ±{dir}° per direction, propagated; else course rule ±{rule} %",
                     "чертёжный: ±{seg} мм на отрезок, ±{dir}° на направление, по всему построению; иначе "
                     "правило курса ±{rule} %"),
    "ch_rule": ("course rule ±{rule} %", "правило курса ±{rule} %"),
    "ch_quantity": ("quantity", "величина"),
    "ch_student": ("student", "студент"),
    "ch_exact": ("exact", "точно"),
    "ch_error": ("error", "ошибка"),
    "ch_err_mm": ("err mm", "ош., мм"),
    "ch_tol_mm": ("tol mm", "доп., мм"),
    "ch_tol_pct": ("tol %", "доп., %"),
    "ch_verdict": ("verdict", "оценка"),
    "ch_phi": ("φ°", "φ°"),
    "ch_where": ("where", "где"),
    "ch_pass": ("pass", "верно"),
    "ch_fail": ("FAIL", "НЕВЕРНО"),
    "ch_fail_no": ("FAIL #{n}", "НЕВЕРНО №{n}"),
    "ch_rule_tag": (", rule", ", правило курса"),
    "ch_not_compared": ("Not compared:", "Не сравнивались:"),
    "ch_left": ("Findings no mistake accounts for ({n}):", "Замечания, которых не объясняет ни одна ошибка ({n}):"),
    "ch_summary": ("Summary: {items} figures, {passed} pass, {failed} fail; {causes} mistakes, {unexplained} failures "
                   "unexplained, {left} other findings; mark {mark}",
                   "Итог: величин {items}, верно {passed}, неверно {failed}; ошибок {causes}, необъяснённых "
                   "расхождений {unexplained}, прочих замечаний {left}; оценка {mark}"),
    "ch_of": ("{mark} of {full}", "{mark} из {full}"),
    "ch_mark": ("Mark: {mark}", "Оценка: {mark}"),
    "ch_no_mistakes": ("No mistakes found: every figure agrees with the exact analysis within the tolerance.",
                       "Ошибок не найдено: каждая величина совпадает с точным расчётом в пределах допуска."),
    "ch_mistakes": ("Mistakes ({n}):", "Ошибки ({n}):"),
    "ch_explains": ("     explains {n} figure{s}: {names}", "     объясняет величин: {n} — {names}"),
    "ch_unexplained": ("Failures no mistake explains ({n}):", "Расхождения, которых не объясняет ни одна ошибка ({n}):"),
    "ch_unexplained_item": ("  φ = {phi}°: {q} = {shown}{where}, exact {exact} {unit}",
                            "  φ = {phi}°: {q} = {shown}{where}, точно {exact} {unit}"),
    "ch_at": ("{what} at {phi}°", "{what} при φ = {phi}°"),
    "ch_row_ok": ("{file}: {student}: {passed} pass, {failed} fail, {findings} findings",
                  "{file}: {student}: верно {passed}, неверно {failed}, замечаний {findings}"),
    "ch_row_mark": ("; mark {mark}", "; оценка {mark}"),
    "ch_row_error": ("{file}: not checked: {message}", "{file}: не проверен: {message}"),
    # the reasons a figure is not compared
    "ch_own_figure": ("the student's own figure (checked for consistency)",
                      "собственная величина студента (проверена на согласованность)"),
    "ch_no_arm": ("the exact analysis has no arm of {load} about {point} (a load it does not apply, or another "
                  "moment equation)",
                  "в точном расчёте нет плеча {load} относительно {point} (такая нагрузка не приложена или "
                  "уравнение моментов другое)"),
    "ch_arm_name": ("a lever arm named by the student: name it h_<load>_<point> (e.g. h_Phi2_B)",
                    "плечо, названное студентом по-своему: назовите его h_<нагрузка>_<точка> (например, h_Φ2_B)"),
    # the mistakes found (a cause's detail)
    "ca_coriolis": ("the Coriolis vector a^k_{t} laid off the wrong way on {plan}",
                    "кориолисово ускорение a^k_{t} отложено в обратную сторону на {plan}"),
    "ca_normal_sense": ("the normal component {name} laid off away from {end} (the wrong sense)",
                        "нормальное ускорение {name} отложено в направлении от {end} (не в ту сторону)"),
    "ca_the_centre": ("the centre", "центра"),
    "ca_normal_pole": ("the normal component {name} laid off from the pole instead of from the image of {end}",
                       "нормальное ускорение {name} отложено от полюса, а не от изображения точки {end}"),
    "ca_tangential": ("the line {t} on {plan} drawn along the link instead of across it",
                      "линия {t} на {plan} проведена вдоль звена, а не перпендикулярно ему"),
    "ca_similarity": ("the image {t} of {point} (link {link}) on {plan} found by similarity {how}",
                      "изображение {t} точки {point} (звено {link}) на {plan} найдено по подобию {how}"),
    "ca_wrong_end": ("from the wrong end of the link", "не от того конца звена"),
    "ca_inverted": ("with the ratio of lengths inverted", "с перевёрнутым отношением длин"),
    "ca_scale_drawn": ("{plan} drawn at {sym} = {drawn} mm per unit while {sym} = {mu} is written and used ({f}×)",
                       "{plan} построен при {sym} = {drawn} мм на единицу, а записан и использован {sym} = {mu} "
                       "({f}×)"),
    "ca_scale_drawn_at": ("{plan} drawn at {f} × the scale written on the sheet",
                          "{plan} построен в масштабе {f} × записанного на листе"),
    "ca_kind": ("{kind}", "{kind}"),
    "ca_plan": ("the {kind} plan", "плане {kind}"),
    "ca_plan_nom": ("the {kind} plan", "план {kind}"),
    "ca_wrong_segment": ("{q} measured between {a} and {b} ({d} mm) instead of {c} and {e} on the {kind} plan",
                         "{q} измерена между {a} и {b} ({d} мм), а не между {c} и {e} на плане {kind}"),
    "ca_pi": ("ω1 = πn/30 computed with π = 3.14", "ω1 = πn/30 вычислена при π = 3,14"),
    "ca_g": ("the weights computed with g = 10 m/s² instead of 9.81",
             "силы тяжести вычислены при g = 10 м/с², а не 9,81"),
    "ca_not_follow": ("{q} does not follow from the student's own figures: {what}",
                      "{q} не следует из собственных величин студента: {what}"),
    "ca_values_scale": ("the {kind} values: segments {how}", "значения {kind}: отрезки {how}"),
    # a gears, cam or synthesis sheet's check
    "sc_head": ("{student}: {sheet} sheet", "{student}: лист «{sheet}»"),
    "sc_variant": (", variant {v}", ", вариант {v}"),
    "sc_gears": ("gears", "зубчатое зацепление"),
    "sc_cam": ("cam", "кулачковый механизм"),
    "sc_engine": ("engine", "уравновешивание двигателя"),
    "sc_synthesis": ("synthesis", "синтез механизма"),
    "sc_mistake": ("  {n}. {kind}: {detail} (explains {names}; −{d})", "  {n}. {kind}: {detail} (объясняет {names}; −{d})"),
    "sc_mistakes": ("Mistakes:", "Ошибки:"),
    "sc_none": ("No mistakes found", "Ошибок не найдено"),
    "sc_none_explains": ("No mistake explains the failures", "Ни одна ошибка не объясняет расхождений"),
    "sc_unexplained": ("Failures no mistake explains: {names}", "Расхождения, которых не объясняет ни одна ошибка: {names}"),
    "sc_shift": ("the pair drawn with a wrong shift coefficient {xs}", "пара построена с неверным коэффициентом смещения {xs}"),
    "sc_base": ("the cam drawn on a base circle r0 = {r0}{e}", "кулачок построен на начальной шайбе r0 = {r0}{e}"),
    "sc_offset": (", offset e = {e}", ", эксцентриситет e = {e}"),
    "sc_scale": ("the drawing read at {f}× its scale", "чертёж прочитан в {f}× его масштаба"),
    "sc_own": ("{q} = {s} does not follow from the student's own figures ({v})",
               "{q} = {s} не следует из собственных величин студента ({v})"),
    "ca_divided": ("divided by {used} instead of {sym} = {mu}", "разделены на {used}, а не на {sym} = {mu}"),
    "ca_multiplied": ("multiplied by {sym} = {mu} instead of divided (μ and K confused)",
                      "умножены на {sym} = {mu}, а не разделены (перепутаны μ и K)"),
    "ca_reaction": ("F_{n}^τ and F_{n}^n swapped (the components along and across the link)",
                    "F_{n}^τ и F_{n}^n перепутаны (составляющие вдоль звена и перпендикулярно ему)"),
    "ca_couple": ("the inertia couple M_Φ{i} = I{i}·ε{i} applied with the wrong sense (along ε{i}, not against it)",
                  "момент сил инерции M_Φ{i} = I{i}·ε{i} приложен не в ту сторону (по ε{i}, а не против)"),
}


# ============================================================================ errors and warnings
