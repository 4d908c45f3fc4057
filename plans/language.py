"""One catalogue of the words and sentences ``plans`` writes, in English and in Russian.

:data:`SHEET_WORDS` are the sheets' words, (Russian, English) as the sheets read them;
:data:`TERMS` are the terminal's lines (``plans solve`` and its protocol, ``plans gears``,
``plans cam``, ``plans balance``, ``plans check``), (English, Russian) as the protocol's
sentences in :mod:`plans.phrases`, which merges them and writes them (:func:`plans.phrases.say`):
a decimal comma in Russian, the textbook's Russian terms and symbols (F_ур, μ, π).

One language per run: ``--language ru|en``, else the file's ``[sheet] language``, else the
locale's (``LC_ALL``/``LC_MESSAGES``/``LANG`` starting with ``ru``: Russian), else English.
"""

from __future__ import annotations

from collections.abc import Mapping
from typing import Any

SHEET_WORDS: dict[str, tuple[str, str]] = {
    "scheme": ("Кинематическая схема", "Kinematic scheme"),
    "positions": ("План положений механизма", "Plan of positions"),
    "velocity": ("План скоростей", "Velocity plan"),
    "acceleration": ("План ускорений", "Acceleration plan"),
    "table": ("Результаты", "Results"),
    "centre_table": ("Скорости по мгновенным центрам", "Velocities by the instant centres"),
    "forces_table": ("Силы по планам сил", "Forces read off the polygons"),
    "group": ("Группа", "Group"),
    "group_polygon": ("План сил группы", "Force polygon of group"),
    "crank": ("Начальное звено", "Initial link"),
    "crank_polygon": ("План сил начального звена", "Force polygon of the initial link"),
    "lever": ("Рычаг Жуковского", "Zhukovsky lever"),
    "quantity": ("Величина", "Quantity"),
    "segment": ("Отрезок", "Segment"),
    "mm": ("мм", "mm"),
    "scale": ("Масштаб", "Scale"),
    "read": ("По чертежу", "Read"),
    "exact": ("Точно", "Exact"),
    "diff": ("Δ, %", "Δ, %"),
    "unit": ("Ед.", "Unit"),
    "m/s": ("м/с", "m/s"),
    "m/s^2": ("м/с²", "m/s²"),
    "rad/s": ("рад/с", "rad/s"),
    "rad/s^2": ("рад/с²", "rad/s²"),
    "N": ("Н", "N"),
    "N*m": ("Н·м", "N·m"),
    "mm/m": ("мм/м", "mm/m"),
    "m/mm": ("м/мм", "m/mm"),
    "mm/(m/s)": ("мм/(м/с)", "mm/(m/s)"),
    "(m/s)/mm": ("(м/с)/мм", "(m/s)/mm"),
    "mm/(m/s^2)": ("мм/(м/с²)", "mm/(m/s²)"),
    "(m/s^2)/mm": ("(м/с²)/мм", "(m/s²)/mm"),
    "mm/N": ("мм/Н", "mm/N"),
    "N/mm": ("Н/мм", "N/mm"),
    "dead": ("мёртвое положение", "dead position"),
    "ccw": ("против часовой", "counter-clockwise"),
    # title block (GOST 2.104, form 1)
    "izm": ("Изм.", "Rev."),
    "list": ("Лист", "Sheet"),
    "ndoc": ("№ докум.", "Doc. No."),
    "sign": ("Подп.", "Sign."),
    "date": ("Дата", "Date"),
    "author": ("Разраб.", "Drawn"),
    "checked": ("Пров.", "Checked"),
    "tcontr": ("Т.контр.", "Tech."),
    "ncontr": ("Н.контр.", "Std."),
    "approved": ("Утв.", "Approved"),
    "lit": ("Лит.", "Lit."),
    "mass": ("Масса", "Mass"),
    "mscale": ("Масштаб", "Scale"),
    "sheet": ("Лист", "Sheet"),
    "sheets": ("Листов", "Sheets"),
    "balancing": ("Уравновешивающая сила", "Balancing force"),
    "by_groups": ("кинетостатика", "kinetostatics"),
    "by_lever": ("рычаг Жуковского", "Zhukovsky lever"),
    "by_power": ("баланс мощностей", "power balance"),
}


#: Units written in Russian, every spelling the engine uses (a value named ``unit...`` in a
#: protocol's sentence, a check's unit, a table's column).
UNITS_RU: dict[str, str] = {
    "m/s": "м/с", "m/s^2": "м/с²", "m/s²": "м/с²", "rad/s": "рад/с", "rad/s^2": "рад/с²", "rad/s²": "рад/с²",
    "N": "Н", "N m": "Н·м", "N·m": "Н·м", "N*m": "Н·м", "mm": "мм", "cm": "см", "m": "м", "J": "Дж", "W": "Вт",
    "kg": "кг", "kg m^2": "кг·м²", "kg·m^2": "кг·м²", "kg*m^2": "кг·м²", "kg·m²": "кг·м²", "%": "%",
    "unit": "ед.", "s": "с", "rpm": "об/мин", "mm/m": "мм/м", "mm/(m/s)": "мм/(м/с)", "mm/(m/s²)": "мм/(м/с²)",
    "mm/(m/s^2)": "мм/(м/с²)", "mm/N": "мм/Н", "mm/unit": "мм/ед.",
}


#: key -> (English, Russian): the terminal's lines.  Fields as in :mod:`plans.phrases`.
TERMS: dict[str, tuple[str, str]] = {
    # ---- plans solve
    "t_position": ("phi = {phi:g} deg", "φ = {phi:g}°"),
    "t_point": ("  {nm} x = {x:.6g} m  y = {y:.6g} m", "  {nm} x = {x:.6g} м  y = {y:.6g} м"),
    "t_ill": ("  warning: group {g} is ill-conditioned here (condition number {c:.1e}: its construction lines "
              "meet at {a:.1e} rad)",
              "  внимание: группа {g} здесь плохо обусловлена (число обусловленности {c:.1e}: её линии построения "
              "пересекаются под углом {a:.1e} рад)"),
    "t_velocity": ("velocity", "скоростей"),
    "t_acceleration": ("acceleration", "ускорений"),
    "t_plan": ("  {kind} plan, {sc}", "  план {kind}, {sc}"),
    "t_mu": ("mu = {mu:.6g} {unit}", "μ = {mu:.6g} {unit}"),
    "t_k": ("K = {k:.6g} {unit}/mm", "K = {k:.6g} {unit}/мм"),
    "t_note": ("    note: {d}", "    примечание: {d}"),
    "w_quantity": ("quantity", "величина"),
    "w_segment": ("segment", "отрезок"),
    "w_read": ("read", "по чертежу"),
    "w_drawing": ("drawing", "по чертежу"),
    "w_exact": ("exact", "точно"),
    "w_difference": ("difference", "разность"),
    "w_unit": ("unit", "ед."),
    "w_mm": ("mm", "мм"),
    "t_construction": ("  construction of the {kind} plan:", "  построение плана {kind}:"),
    "t_force_head": ("  force analysis (F_ij = force {fij}), lever turned 90° {sense}, μv = {mu:g} mm/(m/s)",
                     "  силовой расчёт (F_ij — {fij}), рычаг повёрнут на 90° {sense}, μv = {mu:g} мм/(м/с)"),
    "t_on_i": ("on link i from link j", "сила, действующая на звено i со стороны звена j"),
    "t_of_i": ("of link i on link j", "сила, действующая со стороны звена i на звено j"),
    "t_polygon_note": ("    note (polygon {g}): {d}", "    примечание (план сил {g}): {d}"),
    "t_balancing": (
        "  balancing {kind}: by kinetostatics {kin:.6g} {unit}, by lever {lev} {unit} (positive along the motion "
        "of {pt})",
        "  уравновешивающ{kind}: по кинетостатике {kin:.6g} {unit}, по рычагу Жуковского {lev} {unit} "
        "({end} по направлению движения точки {pt})"),
    "t_force_protocol": ("  force analysis, {plan}:", "  силовой расчёт, {plan}:"),
    "t_crank": ("crank", "начальное звено"),
    "t_lever": ("lever", "рычаг Жуковского"),
    # ---- plans gears
    "g_pair": ("pair {a}-{b} ({kind}): x = {x1:.5f}, {x2:.5f}", "пара {a}-{b} ({kind}): x = {x1:.5f}, {x2:.5f}"),
    "g_internal": ("internal", "внутреннее зацепление"),
    "g_external": ("external", "внешнее зацепление"),
    "g_centre": ("  α_w = {aw:.6f}°   a = {a:.6g} {u}   a_w = {a_w:.6f} {u}   y = {y:.5f}   Δy = {dy:.5f}",
                 "  α_w = {aw:.6f}°   a = {a:.6g} {u}   a_w = {a_w:.6f} {u}   y = {y:.5f}   Δy = {dy:.5f}"),
    "g_wheel": ("  gear {n}: r = {r:.4f}  r_b = {rb:.4f}  r_a = {ra:.4f}  r_f = {rf:.4f}  α_a = {al:.4f}°"
                "  s = {s:.4f}  s_a = {sa:.4f} {u}",
                "  колесо {n}: r = {r:.4f}  r_b = {rb:.4f}  r_a = {ra:.4f}  r_f = {rf:.4f}  α_a = {al:.4f}°"
                "  s = {s:.4f}  s_a = {sa:.4f} {u}"),
    "g_ring": ("  ring {b}: tip circle by the rule {rule}", "  колесо {b} с внутренними зубьями: окружность вершин — {rule}"),
    "g_rule_plain": ("plain", "по простому правилу"),
    "g_rule_gost": ("gost", "по ГОСТ"),
    "g_rule_trimmed": ("trimmed", "увеличенная (нарезание долбяком)"),
    "g_checks": ("  ε = {e:.6f}   checks: {checks}", "  ε = {e:.6f}   проверки: {checks}"),
    "g_check": ("{n} {v}", "{n} — {v}"),
    "g_ok": ("ok", "да"),
    "g_fails": ("FAILS", "НЕТ"),
    "g_contact_ratio": ("contact_ratio", "коэффициент перекрытия"),
    "g_no_undercut": ("no_undercut_{n}", "нет подрезания {n}"),
    "g_tip_thickness": ("tip_thickness_{n}", "толщина на вершине {n}"),
    "g_no_interference": ("no_interference", "нет интерференции"),
    "g_ratio": ("i_{n} = {v:.6f}", "i_{n} = {v:.6f}"),
    "g_speed": ("n_{n} = {w:.6f} rpm (Willis), {p:.6f} rpm (velocity plan)",
                "n_{n} = {w:.6f} об/мин (по Виллису), {p:.6f} об/мин (по плану скоростей)"),
    "g_synthesis": ("synthesis: z1 = {z1}, z2 = {z2}, z3 = {z3}, k = {k}, i_1H = {i:.6f}",
                    "подбор чисел зубьев: z1 = {z1}, z2 = {z2}, z3 = {z3}, k = {k}, i_1H = {i:.6f}"),
    # ---- plans cam
    "c_head": ("{title}: {follower} follower, {face}, base radius {r0:g} {u}, {sense}",
               "{title}: толкатель {follower}, {face}, радиус начальной шайбы {r0:g} {u}, {sense}"),
    "c_translating": ("translating", "поступательный"),
    "c_oscillating": ("oscillating", "коромысловый"),
    "c_flat": ("flat face", "плоский"),
    "c_roller": ("roller {r:g} {u}", "ролик {r:g} {u}"),
    "c_ccw": ("ccw", "против часовой стрелки"),
    "c_cw": ("cw", "по часовой стрелке"),
    "c_deg": ("deg", "°"),
    "c_rad_s": ("rad/s", "рад/с"),
    "c_rad_s2": ("rad/s^2", "рад/с²"),
    "c_per_s": ("{u}/s", "{u}/с"),
    "c_per_s2": ("{u}/s^2", "{u}/с²"),
    "c_lift": ("  lift {h:.4g} {hu}; max |v| {v:.4g} {vu}; max |a| {a:.4g} {au}",
               "  ход {h:.4g} {hu}; max |v| {v:.4g} {vu}; max |a| {a:.4g} {au}"),
    "c_pressure": ("  pressure angle: rise max {rise:.3f} deg (permissible {prise:g}), return max {ret:.3f} deg "
                   "(permissible {pret:g})",
                   "  угол давления: на подъёме max {rise:.3f}° (допускаемый {prise:g}°), на опускании max "
                   "{ret:.3f}° (допускаемый {pret:g}°)"),
    "c_min_flat": ("  minimum base radius (convex profile): {r:.4f} {u}",
                   "  наименьший радиус начальной шайбы (выпуклый профиль): {r:.4f} {u}"),
    "c_at_offset": (" at offset {e:g} {u}", " при эксцентриситете {e:g} {u}"),
    "c_no_radius": ("  NO BASE RADIUS keeps the pressure angle within the permissible with this arm and pivot",
                    "  НИ ПРИ КАКОМ радиусе начальной шайбы угол давления не укладывается в допускаемый при "
                    "этих коромысле и положении его оси"),
    "c_min": ("  minimum base radius{where}: {r:.4f} {u} exactly", "  наименьший радиус начальной шайбы{where}: "
              "{r:.4f} {u} точно"),
    "c_graphical": (", {r:.4f} {u} from the diagram's division points", ", {r:.4f} {u} по точкам разметки диаграммы"),
    "c_roller_fit": ("  with the roller ({rr:g} {u}) fitting every convex part: base radius {r:.4f} {u} at least",
                     "  чтобы ролик ({rr:g} {u}) вписался в каждый выпуклый участок: радиус начальной шайбы не "
                     "меньше {r:.4f} {u}"),
    "c_best_offset": ("  with the offset chosen: base radius {r:.4f} {u} at offset {e:.4f} {u}",
                      "  с подобранным эксцентриситетом: радиус начальной шайбы {r:.4f} {u} при эксцентриситете "
                      "{e:.4f} {u}"),
    "c_best_fit": (" ({r:.4f} {u} for the roller to fit)", " ({r:.4f} {u}, чтобы вписался ролик)"),
    "c_best_pivot": ("  with the pivot moved: base radius {r:.4f} {u} at pivot distance {d:.4f} {u}",
                     "  с перенесённой осью коромысла: радиус начальной шайбы {r:.4f} {u} при межосевом "
                     "расстоянии {d:.4f} {u}"),
    "c_curvature": ("  smallest convex radius of curvature: {r:.4f} {u}",
                    "  наименьший радиус кривизны выпуклого участка: {r:.4f} {u}"),
    "c_flat_fails": ("the flat face cannot follow: r0 + s + s'' <= 0",
                     "плоский толкатель не может следовать профилю: r0 + s + s'' ≤ 0"),
    "c_roller_big": ("the roller ({rr:g} {u}) is bigger than the profile's radius {r:.4f} {u}: the actual profile "
                     "undercuts",
                     "ролик ({rr:g} {u}) больше радиуса кривизны профиля {r:.4f} {u}: действительный профиль "
                     "подрезается"),
    "c_undercut": ("  UNDERCUT at phi {a:g}..{b:g} deg: {what}", "  ПОДРЕЗАНИЕ при φ = {a:g}…{b:g}°: {what}"),
    "c_no_undercut": ("  no undercut", "  подрезания нет"),
    "c_raise": ("  PRESSURE ANGLE above the permissible: raise the base radius to at least {r:.4f} {u}",
                "  УГОЛ ДАВЛЕНИЯ больше допускаемого: увеличьте радиус начальной шайбы хотя бы до {r:.4f} {u}"),
    # ---- plans balance
    "b_head": ("{n} cylinders, {strokes}-stroke, r = {r:.6g} m, lambda = {lam:.6g}, omega = {w:.6g} rad/s; "
               "moments about z = {z:.6g} m, l_c = {l:.6g} m",
               "цилиндров {n}, тактность {strokes}, r = {r:.6g} м, λ = {lam:.6g}, ω = {w:.6g} рад/с; "
               "моменты относительно плоскости z = {z:.6g} м, l_c = {l:.6g} м"),
    "b_force": ("force", "сила"),
    "b_moment": ("moment", "момент"),
    "b_rotating": ("rotating masses", "вращающихся масс"),
    "b_first_order": ("reciprocating, first order", "возвратно-движущихся масс первого порядка"),
    "b_second_order": ("reciprocating, second order", "возвратно-движущихся масс второго порядка"),
    "b_branch_forward": (", forward polygon", ", прямой многоугольник"),
    "b_branch_backward": (", backward polygon", ", обратный многоугольник"),
    "b_polygon": ("{q} of the {kind} (phase diagram of order {order}{branch}), unit {unit:.6g} {u}",
                  "{q} {kind} (фазовая диаграмма порядка {order}{branch}), единица {unit:.6g} {u}"),
    "b_amplitude": ("  amplitude {a:.6g} {u} ({d:.4g} units), phase {ph:.4g} deg",
                    "  амплитуда {a:.6g} {u} ({d:.4g} ед.), фаза {ph:.4g}°"),
    "b_counterweights": ("counterweights:", "противовесы:"),
    "b_no_counterweights": ("counterweights: none needed", "противовесы: не нужны"),
    "b_cw_rotating": ("rotating", "вращ."),
    "b_cw_first_order": ("first_order", "1-й порядок"),
    "b_counterweight": ("  {of} plane z = {z:.6g} m: m*r = {mr:.6g} kg*m ({m:.6g} kg at {r:.6g} m), "
                        "at {a:.4g} deg from crank 1",
                        "  {of} плоскость z = {z:.6g} м: m·r = {mr:.6g} кг·м ({m:.6g} кг на {r:.6g} м), "
                        "под углом {a:.4g}° к кривошипу 1"),
    "b_note": ("note: {t}", "примечание: {t}"),
    "b_note_against": (
        "first-order reciprocating force or moment has a part turning against the crank: a counterweight on "
        "the crankshaft cannot take it (it only moves it to the other plane); balancing shafts can",
        "у силы или момента первого порядка есть часть, вращающаяся против кривошипа: противовес на "
        "коленчатом валу её не уравновесит (лишь перенесёт в другую плоскость); это могут уравновешивающие валы"),
    "b_note_second": (
        "second-order reciprocating force or moment turns at twice the crank speed: no counterweight on the "
        "crankshaft takes it (balancing shafts at 2 omega can)",
        "сила или момент второго порядка вращается с удвоенной угловой скоростью: противовес на коленчатом "
        "валу её не уравновесит (это могут уравновешивающие валы, вращающиеся с 2ω)"),
    "b_exact": ("\nexact check (kinetostatics of {how}, {n} positions): largest shaking force {f:.6g} N, harmonic "
                "truncation error {fe:.6g} N; largest shaking moment {m:.6g} N*m, truncation error {me:.6g} N*m",
                "\nточная проверка (кинетостатика {how}, положений {n}): наибольшая неуравновешенная сила {f:.6g} Н, "
                "погрешность отбрасывания гармоник {fe:.6g} Н; наибольший неуравновешенный момент {m:.6g} Н·м, "
                "погрешность {me:.6g} Н·м"),
    "b_one_linkage": ("the engine as one linkage", "двигателя как одного механизма"),
    "b_linkages": ("{n} linkages, one per cylinder", "{n} механизмов, по одному на цилиндр"),
    "k_bank": ("bank {n} (axis {axis:.4g} deg; cylinders {names}): resultants along its axis",
               "ряд {n} (ось {axis:.4g}°; цилиндры {names}): равнодействующие вдоль его оси"),
    "k_first_order": ("first order", "первого порядка"),
    "k_second_order": ("second order", "второго порядка"),
    "k_polygon": ("  {what}: polygon at [{angles}] deg, ", "  {what}: многоугольник при [{angles}]°, "),
    "k_closes": ("closes: 0", "замыкается: 0"),
    "k_closing": ("closing {c:.6g} units -> {a:.6g} {u} * cos({k}alpha + {ph:.4g} deg)",
                  "замыкающая {c:.6g} ед. → {a:.6g} {u} · cos({k}α + {ph:.4g}°)"),
    "k_combined": ("banks combined (the tip of the resultant over a turn):",
                   "ряды вместе (конец равнодействующей за оборот):"),
    "k_zero": ("balanced", "уравновешено"),
    "k_circle": ("a circle", "окружность"),
    "k_line": ("a line", "отрезок прямой"),
    "k_ellipse": ("an ellipse", "эллипс"),
    "k_locus_circle": (", max {mx:.6g} {u} at alpha = 0 along {d:.4g} deg, min {mn:.6g} {u}",
                       ", max {mx:.6g} {u} при α = 0 в направлении {d:.4g}°, min {mn:.6g} {u}"),
    "k_locus": (", max {mx:.6g} {u} along {d:.4g} deg, min {mn:.6g} {u}",
                ", max {mx:.6g} {u} в направлении {d:.4g}°, min {mn:.6g} {u}"),
    "k_turning": (", turning {s} the crank", ", вращается {s}"),
    "k_with": ("with", "вместе с кривошипом"),
    "k_against": ("against", "против вращения кривошипа"),
    "y_plans": ("Plans over the cycle", "Планы за цикл"),
    "y_positions": ("Positions over the cycle", "Положения за цикл"),
    # ---- the cycle: kinematic diagrams, machine dynamics, the flywheel (plans solve)
    "y_analogues": ("Velocity analogues (plans for ω1 = 1, μ = {mu:.4g} mm/m)",
                    "Аналоги скоростей (планы при ω1 = 1, μ = {mu:.4g} мм/м)"),
    "y_inertia": ("Reduced moment of inertia", "Приведённый момент инерции"),
    "y_forces": ("Reduced moment of forces (positive when the loads drive the crank)",
                 "Приведённый момент сил (положителен, когда нагрузки движут кривошип)"),
    "y_energy": ("Work and kinetic energy (graphical integration)",
                 "Работа и кинетическая энергия (графическое интегрирование)"),
    "y_position": ("position", "положение"),
    "y_phi": ("phi, deg", "φ, °"),
    "y_chords": ("chords", "метод хорд"),
    "y_tangents": ("tangents", "метод касательных"),
    "y_diagrams": ("Kinematic diagrams ({method}, H1 = {h1:g} mm, H2 = {h2:g} mm, μφ = {mu:.4g} mm/rad); "
                   "error of the graphical method in % of each diagram's range",
                   "Кинематические диаграммы ({method}, H1 = {h1:g} мм, H2 = {h2:g} мм, μφ = {mu:.4g} мм/рад); "
                   "погрешность графического метода в % от размаха каждой диаграммы"),
    "y_diagram": ("  {name:<8} {formula:<44} max {mx:.3g} %, rms {rms:.3g} %{integ}",
                  "  {name:<8} {formula:<44} max {mx:.3g} %, ср. кв. {rms:.3g} %{integ}"),
    "y_integ": ("; integrated back from the next: max {mx:.3g} %",
                "; при обратном интегрировании следующей: max {mx:.3g} %"),
    "y_dynamics": ("Machine dynamics over the steady cycle{cycle}", "Динамика машины за цикл установившегося движения{cycle}"),
    "y_720": (" of 720° (two revolutions)", " 720° (два оборота)"),
    "y_sign_rule": ("  M_pr is the power of the loads over |ω1|: positive where they drive the crank, negative where "
                    "they resist it (the driving moment is not among them)",
                    "  M_пр — мощность нагрузок, делённая на |ω1|: положителен, где они движут кривошип, "
                    "отрицателен, где сопротивляются (движущий момент в них не входит)"),
    "y_driving": ("  driving moment M_d = {g:.6g} N·m (graphical), {e:.6g} N·m (exact)",
                  "  движущий момент M_д = {g:.6g} Н·м (графически), {e:.6g} Н·м (точно)"),
    "y_scales": ("  scales: μφ = {phi:.4g} mm/rad, μM = {M:.4g} mm/(N·m), H = {H:.4g} mm, μA = μM·μφ/H = {A:.4g} mm/J, "
                 "μI = {I:.4g} mm/(kg·m²)",
                 "  масштабы: μφ = {phi:.4g} мм/рад, μM = {M:.4g} мм/(Н·м), H = {H:.4g} мм, μA = μM·μφ/H = {A:.4g} "
                 "мм/Дж, μI = {I:.4g} мм/(кг·м²)"),
    "y_flywheel": ("  flywheel for δ = {d:g} at ω_m = {w:.6g} rad/s (added at the crank on top of I_pr):",
                   "  маховик для δ = {d:g} при ω_ср = {w:.6g} рад/с (добавляется на кривошипе сверх I_пр):"),
    "y_wittenbauer": ("    Wittenbauer (graphical)  I = {I:.6g} kg·m²  -> achieved δ = {d:.6g}  (error {e:+.2f} % against "
                      "the exact flywheel)",
                      "    по Виттенбауэру (графически)  I = {I:.6g} кг·м²  → достигнутый δ = {d:.6g}  (погрешность "
                      "{e:+.2f} % относительно точного маховика)"),
    "y_merkalov": ("    Merkalov                 I = {I:.6g} kg·m²  -> achieved δ = {d:.6g}",
                   "    по Мерцалову                  I = {I:.6g} кг·м²  → достигнутый δ = {d:.6g}"),
    "y_exact": ("    exact                    I = {I:.6g} kg·m²  -> achieved δ = {d:.6g}",
                "    точно                         I = {I:.6g} кг·м²  → достигнутый δ = {d:.6g}"),
    "y_bound": ("  Wittenbauer's flywheel is within {b:.3g} kg·m² of the exact one (its own bound); the work of the "
                "loads is integrated to {w}",
                "  маховик по Виттенбауэру отличается от точного не более чем на {b:.3g} кг·м² (его собственная "
                "оценка); работа нагрузок проинтегрирована с точностью {w}"),
    "y_work": ("{w:.2g} J", "{w:.2g} Дж"),
    "y_work_fine": ("better than 1e-9 J", "лучше 1e-9 Дж"),
    "y_note": ("  note: {t}", "  примечание: {t}"),
    "y_no_flywheel": ("the machine's own inertia already keeps δ below {d:g}: no flywheel is needed",
                      "собственная инерция машины уже держит δ ниже {d:g}: маховик не нужен"),
    # ---- plans design
    "dm_slider_crank": ("slider crank", "кривошипно-ползунный механизм"),
    "dm_crank_rocker": ("crank rocker", "кривошипно-коромысловый механизм"),
    "dm_coulisse": ("coulisse", "кулисный механизм"),
    "dm_v_engine": ("v engine", "механизм V-образного двигателя"),
    "d_coulisse": ("coulisse", "кулиса"),
    "d_central": (" (central)", " (центральный)"),
    "d_offset_model": (" (offset)", " (дезаксиальный)"),
    "d_three_positions": (" (three positions)", " (по трём положениям)"),
    "d_crank": ("crank", "кривошип"),
    "d_coupler": ("coupler", "шатун"),
    "d_rocker": ("rocker", "коромысло"),
    "d_frame": ("frame", "стойка"),
    "d_rod": ("rod", "шатун"),
    "d_offset": ("offset", "эксцентриситет"),
    "d_centre_distance": ("centre_distance", "межосевое расстояние"),
    "d_guide_height": ("guide_height", "высота направляющей"),
    "d_length": ("{k} {v:.6g} {u}", "{k} {v:.6g} {u}"),
    "d_K": ("  K {K:.6g} (θ {theta:.6g} deg), measured {m:.12g}", "  K = {K:.6g} (θ = {theta:.6g}°), по построению {m:.12g}"),
    "d_K_measured": ("  K measured {m:.12g}", "  K по построению {m:.12g}"),
    "d_stroke": ("  stroke {given}measured {m:.12g} {u}", "  ход {given}по построению {m:.12g} {u}"),
    "d_given": ("{v:.6g} {u}, ", "{v:.6g} {u}, "),
    "d_swing": ("  swing {given}measured {m:.12g} deg", "  угол размаха {given}по построению {m:.12g}°"),
    "d_given_deg": ("{v:.6g} deg, ", "{v:.6g}°, "),
    "d_gamma": ("  gamma_min {g:.6g} deg at phi {at:.6g} deg", "  γ_min = {g:.6g}° при φ = {at:.6g}°"),
    "d_pressure": ("; pressure angle max {p:.6g} deg", "; наибольший угол давления {p:.6g}°"),
    "d_cylinder": ("  cylinder {c}: stroke measured {s:.12g} {u}, K measured {k:.12g}",
                   "  цилиндр {c}: ход по построению {s:.12g} {u}, K по построению {k:.12g}"),
    "d_three": ("  the three positions met to {e:.3g} deg", "  три положения выдержаны с точностью {e:.3g}°"),
    "d_turns": ("  the crank turns fully, one assembly branch", "  кривошип проворачивается полностью, одна ветвь сборки"),
    "d_grashof": ("; Grashof holds", "; условие Грасгофа выполнено"),
    "d_chosen": ("  chosen: {c}", "  выбрано: {c}"),
    # ---- friction (plans solve)
    "fr_settled": ("settled to {tol:g}", "сошлись с точностью {tol:g}"),
    "fr_locked": ("did not settle: self-locking", "не сошлись: самоторможение"),
    "fr_head": ("  friction: {n} approximations ({settled}); balancing load {free:.6g} {unit} without friction, "
                "{withit}{eta}",
                "  трение: приближений {n} ({settled}); уравновешивающая нагрузка {free:.6g} {unit} без трения, "
                "{withit}{eta}"),
    "fr_with": ("{b:.6g} {unit} with it", "{b:.6g} {unit} с трением"),
    "fr_none": ("none with it", "с трением не существует"),
    "fr_eta": ("; η = {e:.4f}", "; η = {e:.4f}"),
    "fr_no_eta": ("; η undefined", "; η не определён"),
    "fr_couple": ("couple", "момент"),
    "fr_force": ("force", "сила"),
    "fr_stops": ("    {name} {label} sense undetermined (relative motion stops): |{kind}| ≤ {lim:.6g} {unit}",
                 "    {name} {label} направление не определено (относительное движение останавливается): "
                 "|{kind}| ≤ {lim:.6g} {unit}"),
    "fr_pair": ("    {name} {label} {kind} {load:.6g} {unit}, loss {loss:.6g} W",
                "    {name} {label} {kind} {load:.6g} {unit}, потери {loss:.6g} Вт"),
    "fr_self_locking": ("    self-locking here: {name}", "    здесь самоторможение: {name}"),
    "fr_cycle": ("efficiency over the cycle: η = A_useful / A_driving = {u:.6g} / {d:.6g} J = {e:.4f} "
                 "(friction {f:.6g} J)",
                 "КПД за цикл: η = A_пс / A_дв = {u:.6g} / {d:.6g} Дж = {e:.4f} (трение {f:.6g} Дж)"),
    "r_polygon": ("{label} (polygon {g}, μF = {mu:g} mm/N)", "{label} (план сил {g}, μF = {mu:g} мм/Н)"),
    "r_arm": ("h_{lab} in {eq} = 0 (μl = {mu:g} mm/m)", "h_{lab} в {eq} = 0 (μl = {mu:g} мм/м)"),
    "r_lever_arm": ("h_{lab} on the lever (μv = {mu:g})", "h_{lab} на рычаге (μv = {mu:g})"),
    "r_kin": ("{sym} by kinetostatics", "{sym} по кинетостатике"),
    "r_lever": ("{sym} by Zhukovsky's lever", "{sym} по рычагу Жуковского"),
    "r_power": ("{sym} by power balance", "{sym} по балансу мощностей"),
    "r_delta": ("δ = ({l}_lever − {l}_kin)/{l}_kin (coursework, from the drawings)",
                "δ = ({l}_рыч − {l}_кин)/{l}_кин (по чертежам)"),
}

# ============================================================================ plans check
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
#: key -> (English, Russian): the one-line errors on bad input (:class:`plans.errors.Said`).
#: Field names, TOML keys and the values quoted from the file stay as the file writes them.
ERRORS: dict[str, tuple[str, str]] = {
    # ---- the readers (plans/reader.py)
    "e_missing_table": ("missing table", "нет таблицы"),
    "e_table": ("expected a table", "ожидалась таблица"),
    "e_number": ("expected a number, got {got}", "ожидалось число, а записано {got}"),
    "e_finite": ("expected a finite number, got {got}", "ожидалось конечное число, а записано {got}"),
    "e_magnitude": ("expected a number of magnitude at most {limit:g}, got {got}",
                    "ожидалось число, по модулю не больше {limit:g}, а записано {got}"),
    "e_positive": ("expected a positive number, got {got}", "ожидалось положительное число, а записано {got}"),
    "e_nonneg": ("expected a number >= 0, got {got}", "ожидалось число ≥ 0, а записано {got}"),
    "e_between": ("expected a number from {floor:g} to {limit:g}, got {got}",
                  "ожидалось число от {floor:g} до {limit:g}, а записано {got}"),
    "e_floor": ("expected 0 or a magnitude of at least {floor:g}, got {got}",
                "ожидался 0 или число, по модулю не меньше {floor:g}, а записано {got}"),
    "e_missing_number": ("missing number", "нет числа"),
    "e_angle": ("expected an angle in degrees, got {got}", "ожидался угол в градусах, а записано {got}"),
    "e_finite_angle": ("expected a finite angle in degrees, got {got}",
                       "ожидался конечный угол в градусах, а записано {got}"),
    "e_missing_whole": ("missing whole number", "нет целого числа"),
    "e_whole": ("expected a whole number, got {got}", "ожидалось целое число, а записано {got}"),
    "e_whole_min": ("expected a whole number >= {n}, got {got}", "ожидалось целое число ≥ {n}, а записано {got}"),
    "e_whole_max": ("expected a whole number <= {n}, got {got}", "ожидалось целое число ≤ {n}, а записано {got}"),
    "e_missing_text": ("missing text", "нет текста"),
    "e_string": ("expected a string, got {got}", "ожидалась строка, а записано {got}"),
    "e_char": ("the text holds a {bad}; expected printable text", "в тексте {bad}; ожидался печатный текст"),
    "e_key_char": ("the key holds a {bad}; expected printable text", "в ключе {bad}; ожидался печатный текст"),
    "e_control": ("control character U+{code}", "управляющий символ U+{code}"),
    "e_nonchar": ("Unicode noncharacter U+{code}", "несимвол Юникода U+{code}"),
    "e_surrogate": ("surrogate U+{code}", "суррогат U+{code}"),
    "e_text_long": ("text of {n} characters; expected at most {limit}", "текст из {n} символов; ожидалось не больше {limit}"),
    "e_chars": ("expected at most {limit} characters, got {n}", "ожидалось не больше {limit} символов, а их {n}"),
    "e_name_empty": ("expected a non-empty name", "ожидалось непустое имя"),
    "e_choice": ("expected one of {options}, got {got}{hint}", "ожидалось одно из: {options}, а записано {got}{hint}"),
    "e_length_max": ("expected a length of at most {limit:g} m, got {got}",
                     "ожидалась длина не больше {limit:g} м, а записано {got}"),
    "e_length_finite": ("expected a finite length, got {got}", "ожидалась конечная длина, а записано {got}"),
    "e_length_positive": ("expected a positive length, got {got}", "ожидалась положительная длина, а записано {got}"),
    "e_length_min": ("expected a length of at least 1 µm, got {got}", "ожидалась длина не меньше 1 мкм, а записано {got}"),
    "e_unknown_key": ("unknown key{hint} (expected one of {known})", "неизвестный ключ{hint} (ожидался один из: {known})"),
    "e_did_you_mean": ("; did you mean {word!r}?", "; может быть, {word!r}?"),
    "e_digits": ("an integer of {n} digits", "целое число из {n} цифр"),
    "e_nothing": ("nothing", "ничего"),
    # ---- reading a file (plans/io.py)
    "e_read": ("cannot read file ({why})", "файл не читается ({why})"),
    "e_ENOENT": ("No such file or directory", "нет такого файла или папки"),
    "e_EISDIR": ("Is a directory", "это папка"),
    "e_EACCES": ("Permission denied", "нет доступа"),
    "e_ENOTDIR": ("Not a directory", "часть пути — не папка"),
    "e_ENAMETOOLONG": ("File name too long", "слишком длинное имя файла"),
    "e_ELOOP": ("Too many levels of symbolic links", "символические ссылки ведут по кругу"),
    "e_utf8": ("not UTF-8 text (byte 0x{byte:02x}); expected a TOML file saved as UTF-8",
               "не текст UTF-8 (байт 0x{byte:02x}); ожидался файл TOML в кодировке UTF-8"),
    "e_toml": ("malformed TOML: {why}", "ошибка синтаксиса TOML: «{why}» (слова разборщика TOML)"),
    "e_toml_at": ("malformed TOML: {why} (at line {line}, column {col})",
                  "ошибка синтаксиса TOML в строке {line}, столбце {col}: «{why}» (слова разборщика TOML)"),
    "e_toml_end": ("malformed TOML: {why} (at end of document)",
                   "ошибка синтаксиса TOML в конце файла: «{why}» (слова разборщика TOML)"),
    "e_decimal_comma": ("{text!r} is written with a decimal comma; TOML numbers take a decimal point: write {fixed}",
                        "в {text!r} дробная часть отделена запятой; в числах TOML пишется точка: {fixed}"),
    "e_depth": ("tables or arrays nested more than {n} deep; expected a file of the family",
                "таблицы или массивы вложены глубже {n}; ожидался файл семейства plans"),
    # ---- the loads (plans/forces/loads.py)
    "l_frame": ("link {link} is the frame: loads on the frame do not enter the analysis",
                "звено {link} — стойка: нагрузки на стойку в расчёт не входят"),
    "l_link": ("unknown link {link}; expected one of {links}", "нет звена {link}; ожидалось одно из {links}"),
    "l_gravity": ("expected true, false or {{ g = 9.81, direction_deg = -90 }}",
                  "ожидалось true, false или {{ g = 9.81, direction_deg = -90 }}"),
    "l_balancing": ("expected a table {{ kind = \"force\", point = \"A\" }}",
                    "ожидалась таблица {{ kind = \"force\", point = \"A\" }}"),
    "l_bal_frame": ("point {point!r} is on the frame; the balancing force acts on the driving link {link}",
                    "точка {point!r} на стойке; уравновешивающая сила приложена к начальному звену {link}"),
    "l_bal_not_on": ("point {point!r} is not on the driving link {link}{hint}",
                     "точки {point!r} нет на начальном звене {link}{hint}"),
    "l_bal_pivot": ("point {point!r} is the pivot: a force there has no moment",
                    "точка {point!r} — опора: у силы в ней нет момента"),
    "l_piston": ("link {link} is not a piston: it must slide on exactly one guide",
                 "звено {link} — не поршень: он должен скользить ровно по одной направляющей"),
    "l_and": ("{a} and {b}", "{a} и {b}"),
    "l_force_ways": ("give one of vector, magnitude or resisting, not {given}",
                     "задайте одно из: vector, magnitude или resisting, а не {given}"),
    "l_point": ("unknown point {point} on link {link}{hint}; expected one of {points}",
                "на звене {link} нет точки {point}{hint}; ожидалась одна из {points}"),
    "l_stroke": ("expected \"working\", \"idle\", \"both\", \"positive\" or \"negative\", got {got}",
                 "ожидалось \"working\", \"idle\", \"both\", \"positive\" или \"negative\", а записано {got}"),
    "l_vector": ("expected [Fx, Fy] in N", "ожидалось [Fx, Fy] в Н"),
    "l_force_none": ("expected vector = [Fx, Fy], magnitude (+ angle_deg) or resisting",
                     "ожидалось vector = [Fx, Fy], magnitude (+ angle_deg) или resisting"),
    "l_stroke_axis": ("a stroke needs an axis: along = angle in degrees", "для хода нужна ось: along = угол в градусах"),
    "l_moment_ways": ("give one of value, resisting, table or expression, not both {a} and {b}",
                      "задайте одно из: value, resisting, table или expression, а не {a} и {b} вместе"),
    # ---- a length (plans/units.py, read by plans/reader.py)
    "e_length_bool": ("expected a length (number or string like '35 mm')", "ожидалась длина (число или строка вида '35 mm')"),
    "e_length_digits": ("expected a length of a sensible size, got an integer of {n} digits",
                        "ожидалась длина разумной величины, а записано целое число из {n} цифр"),
    "e_length_inf": ("expected a finite length", "ожидалась конечная длина"),
    "e_length_of": ("expected a length: a number in the file's unit or a string like '35 mm'",
                    "ожидалась длина: число в единицах файла или строка вида '35 mm'"),
    # ---- plans check's command (plans/check/command.py)
    "k_nothing": ("expected a check file, a CSV form or a folder (or --template SCENE)",
                  "ожидался файл проверки, форма CSV или папка (или --template SCENE)"),
    "k_link": ("a symbolic link to no readable file (a loop, or its target gone)",
               "символическая ссылка не ведёт к читаемому файлу (петля или цель удалена)"),
    "k_no_file": ("no such file or folder", "нет такого файла или папки"),
    "k_no_folder": ("{path}: no such folder {folder}", "{path}: нет папки {folder}"),
    "k_json_folder": ("--json is for one file; a folder writes one report per file into --out",
                      "--json — для одного файла; для папки отчёты по файлам пишутся в --out"),
    "k_no_checks": ("no check files (*.toml)", "нет файлов проверки (*.toml)"),
    "k_make_folder": ("cannot create the output folder {folder}: {why}", "не удаётся создать папку {folder}: {why}"),
    # ---- writing the outputs (plans/io.py, plans/guard.py)
    "o_input": ("{target}: is the input file {src}; refusing to overwrite it (expected another path for the output)",
                "{target}: это входной файл {src}; он не будет перезаписан (ожидался другой путь для результата)"),
    "o_folder": ("{target}: is a folder; expected a path for a file", "{target}: это папка; ожидался путь к файлу"),
    "o_write": ("cannot write {target}: {why}", "не удаётся записать {target}: {why}"),
    "o_write_to": ("cannot write to {folder}: {why}", "не удаётся записать в {folder}: {why}"),
    # ---- the file's kind and format (plans/kinds.py)
    "e_format": ("expected format = 1, got {got}", "ожидалось format = 1, а записано {got}"),
    # ---- the scene (plans/scene/model.py)
    "e_frame": ("expected the frame's link number (a positive integer)", "ожидался номер стойки (целое положительное)"),
    "e_link_is_frame": ("link {link} is the frame; put frame points in [points]",
                        "звено {link} — стойка; точки стойки записывают в [points]"),
    "e_link_twice": ("link {link} is given twice ([links.{a}] and [links.{b}])",
                     "звено {link} задано дважды ([links.{a}] и [links.{b}])"),
    "e_no_links": ("expected at least the driving link", "ожидалось хотя бы начальное звено"),
    "e_link_number": ("expected links numbered as the textbook does: [links.1], [links.2], ...",
                      "звенья нумеруют, как в учебнике: [links.1], [links.2], ..."),
    "e_link_positive": ("expected a positive link number", "ожидался положительный номер звена"),
    "e_point_xy": ("expected a point [x, y]", "ожидалась точка [x, y]"),
    "e_axis": ("expected one or two point names, e.g. axis = [\"A\", \"B\"]",
               "ожидались имена одной или двух точек, например axis = [\"A\", \"B\"]"),
    "e_axis_same": ("expected two different points", "ожидались две разные точки"),
    "e_missing_length": ("missing length {ab}", "не задана длина {ab}"),
    "e_slider_length": ("a one-point link (slider) has no length", "у звена с одной точкой (ползуна) нет длины"),
    "e_points_table": ("expected a table of named points", "ожидалась таблица именованных точек"),
    "e_point_on_axis": ("point already defined by the axis", "точка уже задана осью звена"),
    "e_point_spec": ("expected {{ ratio = r }} or {{ along = a, across = c }}",
                     "ожидалось {{ ratio = r }} или {{ along = a, across = c }}"),
    "e_point_both": ("give ratio, or along and across, not both", "задайте ratio или along и across, но не то и другое"),
    "e_ratio_axis": ("ratio needs a two-point axis", "для ratio нужна ось из двух точек"),
    "e_unknown_point": ("unknown point {point} on link {link}{hint}", "на звене {link} нет точки {point}{hint}"),
    "e_joints": ("expected an array of tables [[joints]]", "ожидался массив таблиц [[joints]]"),
    "e_joint_kind": ("expected \"R\" or \"P\", got {got}", "ожидалось \"R\" или \"P\", а записано {got}"),
    "e_joint_links": ("expected two link numbers, e.g. links = [1, 2]", "ожидались номера двух звеньев, например links = [1, 2]"),
    "e_unknown_link": ("unknown link {link}", "нет звена {link}"),
    "e_joint_same": ("a joint needs two different links", "кинематическая пара соединяет два разных звена"),
    "e_point_name": ("expected a point name", "ожидалось имя точки"),
    "e_r_guide": ("a turning pair (kind = \"R\") has no guide", "у вращательной пары (kind = \"R\") нет направляющей"),
    "e_p_guide": ("a P joint needs guide = {{ link = N, through = ..., angle_deg = ... }}",
                  "поступательной паре нужна направляющая: guide = {{ link = N, through = ..., angle_deg = ... }}"),
    "e_toward_angle": ("give toward or angle_deg, not both", "задайте toward или angle_deg, но не то и другое"),
    "e_guide_link": ("expected one of the joint's links {pair}", "ожидалось одно из звеньев пары {pair}"),
    "e_not_on_slider": ("point {point!r} is not on the sliding link {link}", "точки {point!r} нет на ползуне {link}"),
    "e_through": ("expected a point name or [x, y]", "ожидалось имя точки или [x, y]"),
    "e_toward": ("expected a point on link {link}", "ожидалась точка звена {link}"),
    "e_toward_through": ("coincides with 'through'", "совпадает с 'through'"),
    "e_one_point": ("a one-point link must slide on a guide or carry one",
                    "звено с одной точкой должно скользить по направляющей или нести её"),
    "e_slider_axis": ("a slider's axis point must be its pin on the guide ({point})",
                      "точкой оси ползуна должен быть его шарнир на направляющей ({point})"),
    "e_driver_link": ("expected a moving link number (one of {links}), got {got}",
                      "ожидался номер подвижного звена (одно из {links}), а записано {got}"),
    "e_driver_axis": ("the driving link needs axis = [pivot on the frame, crank pin]",
                      "начальному звену нужна ось axis = [опора на стойке, шарнир кривошипа]"),
    "e_omega_both": ("give omega (rad/s) or omega_rpm, not both", "задайте omega (рад/с) или omega_rpm, но не то и другое"),
    "e_omega_missing": ("missing crank speed: omega = rad/s or omega_rpm = rev/min",
                        "не задана скорость кривошипа: omega = рад/с или omega_rpm = об/мин"),
    "e_phi_both": ("give phi_deg or positions, not both", "задайте phi_deg или positions, но не то и другое"),
    "e_phi0": ("phi0_deg goes with positions = N (with phi_deg give the angles)",
               "phi0_deg задают вместе с positions = N (с phi_deg перечисляют сами углы)"),
    "e_positions_many": ("{n} positions; expected at most {limit} (a position every 0.1°)",
                         "положений {n}; ожидалось не больше {limit} (положение через 0,1°)"),
    "e_phi_missing": ("missing crank angle(s): phi_deg = 45, a list, or positions = N",
                      "не заданы углы кривошипа: phi_deg = 45, список или positions = N"),
    "e_phi_none": ("expected at least one angle", "ожидался хотя бы один угол"),
    "e_angles_many": ("{n} angles; expected at most {limit}", "углов {n}; ожидалось не больше {limit}"),
    "e_degrees": ("expected a number of degrees, got {got}", "ожидалось число градусов, а записано {got}"),
    "e_shared_point": ("point {point!r} is on links {links} but no joint at {point!r} joins them; rename one of them "
                       "(S2, S3, ...) or add the joint",
                       "точка {point!r} есть на звеньях {links}, но ни одна пара в {point!r} их не соединяет; "
                       "переименуйте одну из них (S2, S3, ...) или добавьте пару"),
    "e_branch": ("expected +1 or -1, got {got}", "ожидалось +1 или -1, а записано {got}"),
    "e_outputs": ("expected a list of names", "ожидался список имён"),
    "e_output": ("unknown output {name!r}{hint} (expected some of {known})",
                 "нет такого результата {name!r}{hint} (ожидались некоторые из: {known})"),
    "e_title": ("expected a string or {{ ru = \"...\", en = \"...\" }}",
                "ожидалась строка или {{ ru = \"...\", en = \"...\" }}"),
    "e_scale": ("expected {{ mu = mm per unit }}, {{ K = unit per mm }}",
                "ожидалось {{ mu = мм на единицу }} или {{ K = единиц на мм }}"),
    "e_scale_known": ("expected {{ mu = mm per unit }}, {{ K = unit per mm }} or {{ known_mm = length of the known vector }}",
                      "ожидалось {{ mu = мм на единицу }}, {{ K = единиц на мм }} или {{ known_mm = длина известного "
                      "вектора }}"),
    # ---- a check file (plans/check/checkfile.py)
    "c_student": ("expected a string (the student's name)", "ожидалась строка (фамилия студента)"),
    "c_positions": ("expected at least one [[positions]] with phi_deg", "ожидалась хотя бы одна запись [[positions]] с phi_deg"),
    "c_nothing_anywhere": ("nothing written at any position: fill in the student's figures",
                           "ни в одном положении ничего не записано: внесите величины студента"),
    "c_twice": ("position phi_deg = {phi:g} given twice", "положение phi_deg = {phi:g} задано дважды"),
    "c_rubric": ("expected a table of deductions, e.g. coriolis_reversed = 15",
                 "ожидалась таблица снижений оценки, например coriolis_reversed = 15"),
    "c_points": ("expected a number of points from 0 to 1e6, got {got}", "ожидалось число баллов от 0 до 1e6, а записано {got}"),
    "c_scene_missing": ("missing: a scene file path or an inline [scene] table",
                        "не задано: путь к файлу сцены или таблица [scene] в самом файле"),
    "c_scene_not_found": ("scene file {name!r} not found (looked at {target})",
                          "файл сцены {name!r} не найден (искали {target})"),
    "c_scene_self": ("names the check file itself; expected the scene file", "указывает на сам файл проверки; ожидался файл сцены"),
    "c_scene_type": ("expected a path (string) or an inline [scene] table", "ожидался путь (строка) или таблица [scene]"),
    "c_scale_positive": ("expected a positive scale, got {got} (a scale of zero draws nothing)",
                         "ожидался положительный масштаб, а записано {got} (в нулевом масштабе ничего не построить)"),
    "c_scales": ("missing table [scales] with the student's μv, μa (and μl, μF)",
                 "нет таблицы [scales] с масштабами студента μv, μa (и μl, μF)"),
    "c_phi": ("expected the crank angle in degrees, got {got}", "ожидался угол поворота кривошипа в градусах, а записано {got}"),
    "c_phi_not_in_scene": ("position {phi:g}° is not in the scene (it has {has})", "положения {phi:g}° в сцене нет (в ней {has})"),
    "c_string": ("expected a string", "ожидалась строка"),
    "c_nothing": ("nothing written: expected [positions.measured] and/or [positions.values]",
                  "ничего не записано: ожидались [positions.measured] и/или [positions.values]"),
    "c_figures": ("expected a table of quantity = figure", "ожидалась таблица «величина = число»"),
    "c_not_a_name": ("not a quantity name (e.g. v_B, omega_2, a_BA^τ, F_12)",
                     "это не имя величины (например, v_B, omega_2, a_BA^τ, F_12)"),
    "c_one_figure": ("expected at least one figure", "ожидалось хотя бы одно число"),
    "c_where": ("expected a string (the section of the student's work)", "ожидалась строка (раздел работы студента)"),
    "c_missing": ("missing {key}", "не задано {key}"),
    "c_negative": ("a measured segment cannot be negative, got {got}", "измеренный отрезок не бывает отрицательным, а записано {got}"),
    "c_si": ("expected a number in SI units (magnitude at most {limit:g}), got {got}",
             "ожидалось число в единицах СИ (по модулю не больше {limit:g}), а записано {got}"),
    "c_length": ("expected a length, got {got}", "ожидалась длина, а записано {got}"),
    "c_unit": ("a length needs its unit: write '{item} mm' or '{item} m'", "у длины должна быть единица: '{item} mm' или '{item} m'"),
    "c_finite_length": ("expected a finite length of at most 10 km", "ожидалась конечная длина не больше 10 км"),
    "c_finite_length_got": ("expected a finite length of at most 10 km, got {got}",
                            "ожидалась конечная длина не больше 10 км, а записано {got}"),
    "c_length_such": ("expected a length such as '65 mm' or '0.065 m', got {got}",
                      "ожидалась длина вида '65 mm' или '0.065 m', а записано {got}"),
    # ---- the kind of a file (plans/kinds.py)
    "e_kind": ("expected one of {kinds}, got {got}{hint}", "ожидалось одно из: {kinds}, а записано {got}{hint}"),
    "e_kind_here": ("expected one of {kinds} (here {want}), got {got}{hint}",
                    "ожидалось одно из: {kinds} (здесь {want}), а записано {got}{hint}"),
    "e_no_kind": ("no kind", "без kind"),
    "e_use": ("use '{command}' for it; ", "для него есть команда '{command}'; "),
    "e_a_linkage": ("a linkage scene", "сцена механизма"),
    "e_a_engine": ("an engine file", "файл двигателя"),
    "e_a_gears": ("a gears file", "файл зубчатых передач"),
    "e_a_cam": ("a cam file", "файл кулачка"),
    "e_a_check": ("a check file", "файл проверки"),
    "e_a_kind": ("a {kind} file", "файл вида {kind!r}"),
    "e_want_check": ("a check file (scene = ..., no kind)", "файл проверки (scene = ..., без kind)"),
    "e_want_linkage": ("kind = \"linkage\" or no kind", "kind = \"linkage\" или без kind"),
    "e_kind_other": ("this is {other}, not {kind}; {command}expected {want}", "это {other}, а не {kind}; {command}ожидалось {want}"),
    "e_not_on_link": ("point {point!r} is not on link {link}", "точки {point!r} нет на звене {link}"),
    "e_lookalike": ("point {point!r} is not on link {link}: {point!r} is written with {script} letters "
                    "and link {link} has {other!r} in {other_script} letters (they look alike)",
                    "точки {point!r} нет на звене {link}: в {point!r} {script} буквы, а на звене {link} есть "
                    "{other!r} из букв {other_script} (они выглядят одинаково)"),
    "e_cyrillic": ("Cyrillic", "кириллицы"),
    "e_latin": ("Latin", "латиницы"),
    "e_cyrillic_is": ("Cyrillic", "кириллические"),
    "e_latin_is": ("Latin", "латинские"),
}

#: key -> (English, Russian): the warnings of an implausible scene, on stderr (the run goes on).
WARNINGS: dict[str, tuple[str, str]] = {
    "w_prefix": ("plans: warning: ", "plans: внимание: "),
    "w_length": ("{file}: {field}: {what} {value:.4g} m long, beyond any machine's (unit = {unit!r}: are the lengths "
                 "in millimetres? then write unit = \"mm\")",
                 "{file}: {field}: {what} {value:.4g} м — таких машин не бывает (unit = {unit!r}: длины в "
                 "миллиметрах? тогда запишите unit = \"mm\")"),
    "w_link": ("link {link} is", "звено {link} длиной"),
    "w_length_figure": ("{file}: {field}: {what} {value:.4g} m long, beyond any machine's: is a figure mistyped?",
                        "{file}: {field}: {what} {value:.4g} м — таких машин не бывает: нет ли опечатки в числе?"),
    "w_speed": ("{file}: v_{point} = ω1·l = {v:.4g} m/s is beyond any machine's (more than {limit:g} m/s): "
                "check unit and the driver's speed",
                "{file}: v_{point} = ω1·l = {v:.4g} м/с — таких скоростей у машин не бывает (больше {limit:g} м/с): "
                "проверьте unit и скорость начального звена"),
    "w_lookalike": ("{file}: {where}: the name {name!r} mixes Cyrillic and Latin letters that look alike ({letters})",
                    "{file}: {where}: в имени {name!r} смешаны похожие буквы кириллицы и латиницы ({letters})"),
    "w_twins": ("{file}: the names {a!r} and {b!r} look the same but one is written in Cyrillic letters and the "
                "other in Latin: they are two different points",
                "{file}: имена {a!r} и {b!r} выглядят одинаково, но одно написано кириллицей, а другое латиницей: "
                "это две разные точки"),
}


#: Russian symbols of the terminal's English spellings (the textbook's letters; π is the
#: acceleration pole, p the velocity pole).
_SYMBOLS = ((r"\bp_a(?![A-Z_])", "π"), (r"\bp_v(?![A-Z_])", "p"), (r"\bomega_?(?=\w)", "ω"), (r"\beps_?(?=\w)", "ε"),
            (r"(?<![A-Za-z])Phi(?=\w)", "Φ"), (r"\bmu\b", "μ"), (r"\^2\b", "²"), (r"(?<![A-Za-z])([FM])_bal\b", r"\1_ур"),
            (r"(?<![A-Za-z])([FM])f(?=\d)", r"\1_тр"),
            (r"\brad/s", "рад/с"), (r"(?<![\w/])m/s", "м/с"), (r"\bmm\b", "мм"), (r"\bN·m\b", "Н·м"),
            (r"(?<=\d )N\b", "Н"), (r"\bN\b(?= )", "Н"), (r"\binitial link\b", "начальное звено"),
            (r"\b(RRR|RRP|RPR|PRP|RPP|PRR|PPR) group\b", r"группа \1"), (r"\bgroup\b", "группа"))


_GREEK = {"Phi": "Φ", "omega": "ω", "eps": "ε", "tau": "τ"}
_QUANTITY_RU = {"F_bal": "F_ур", "M_bal": "M_ур", "F_bal_lever": "F_ур (рычаг)", "F_bal_diff_pct": "δF_ур, %",
                "p_a": "π", "p_v": "p"}


def quantity_name(name: str, lang: str) -> str:
    """A quantity key of the check (``M_Phi_2``, ``omega_1``, ``h_Phi2_B``) as a Russian text
    writes it (M_Φ2, ω1, h_Φ2,B, F_ур); in English the key itself."""
    if lang != "ru":
        return name
    if name in _QUANTITY_RU:
        return _QUANTITY_RU[name]
    head, sep, rest = name.partition("_")
    head = _GREEK.get(head, head)
    if not sep:
        return head
    parts = rest.split("_")
    if head in ("ω", "ε"):
        return head + "".join(parts)
    if parts[0] in _GREEK:  # M_Phi_2 -> M_Φ2
        return f"{head}_{_GREEK[parts[0]]}{''.join(parts[1:])}"
    if parts[0].startswith("Phi"):  # an arm: h_Phi2_B -> h_Φ2,B
        return f"{head}_{','.join([_GREEK['Phi'] + parts[0][3:]] + parts[1:])}"
    return f"{head}_{'_'.join(parts)}"


def symbols(text: str, lang: str) -> str:
    """``text`` with the textbook's Russian symbols and units in Russian (unchanged in English)."""
    if lang != "ru":
        return text
    import re

    for pattern, repl in _SYMBOLS:
        text = re.sub(pattern, repl, text)
    return text


def locale_language() -> str:
    """The environment's language: Russian when the locale (``LC_ALL``, else ``LC_MESSAGES``,
    else ``LANG``, as POSIX orders them) starts with ``ru``, else English."""
    import os

    for name in ("LC_ALL", "LC_MESSAGES", "LANG"):
        value = os.environ.get(name)
        if value:
            return "ru" if value.lower().startswith("ru") else "en"
    return "en"


def choose(asked: str | None, data: Mapping[str, Any] | None = None) -> str:
    """The run's language: the one asked for, else the file's ``[sheet] language``, else the
    locale's (:func:`locale_language`)."""
    if asked in ("ru", "en"):
        return asked
    sheet = data.get("sheet") if isinstance(data, Mapping) else None
    lang = sheet.get("language") if isinstance(sheet, Mapping) else None
    return lang if lang in ("ru", "en") else locale_language()


def file_language(asked: str | None, path: str) -> str:
    """:func:`choose` for a file read by its own reader: its ``[sheet]`` table read again
    (already validated by then, so a failure here just means the locale's language)."""
    if asked in ("ru", "en"):
        return asked
    import tomllib

    try:
        with open(path, "rb") as fh:
            return choose(None, tomllib.load(fh))
    except (OSError, ValueError, RecursionError):
        return locale_language()


def add_option(parser: Any) -> None:
    """``--language ru|en`` on a command."""
    parser.add_argument("--language", choices=("ru", "en"),
                        help="language of the output (default: the file's [sheet] language, else the locale's: "
                             "Russian when LANG starts with ru, else English)")


# ---- sheet sets: the course's two sheets, tables split over parts (drawings.sheet_sets)
SHEET_WORDS.update({
    "continued": ("(продолжение)", "(continued)"),
    "kinematics_sheet": ("Кинематический анализ", "Kinematic analysis"),
    "kinetostatics_sheet": ("Силовой анализ", "Force analysis"),
})


# ---- task semantics: the positions from the extreme, the strokes of the loads, the course's notation
TERMS.update({
    "x_slider": ("slider", "ползун"),
    "x_mu_per_mm": ("mu = {k:.6g} {unit}/mm", "μ = {k:.6g} {unit}/мм"),
    "x_r_polygon": ("{label} (polygon {g}, {sc})", "{label} (план сил {g}, {sc})"),
    "x_r_arm": ("h_{lab} in {eq} = 0 ({sc})", "h_{lab} в {eq} = 0 ({sc})"),
    "x_force_head": ("  force analysis (F_ij = force {fij}), lever turned 90° {sense}, {sc}",
                     "  силовой расчёт (F_ij — {fij}), рычаг повёрнут на 90° {sense}, {sc}"),
    "x_rocker": ("rocker", "коромысло"),
    "x_start_working": (
        "positions from the extreme position of link {link} ({kind} {point}) where the working stroke begins: "
        "phi = {phi:.6f} deg (working stroke {work:.4f} deg, idle {idle:.4f} deg, K = {K:.4f}, theta = {theta:.4f} deg)",
        "положения от крайнего положения звена {link} ({kind} {point}), с которого начинается рабочий ход: "
        "φ = {phi:.6f}° (рабочий ход {work:.4f}°, холостой {idle:.4f}°, K = {K:.4f}, θ = {theta:.4f}°)"),
    "x_start_idle": (
        "positions from the extreme position of link {link} ({kind} {point}) where the idle stroke begins: "
        "phi = {phi:.6f} deg (working stroke {work:.4f} deg, idle {idle:.4f} deg, K = {K:.4f}, theta = {theta:.4f} deg)",
        "положения от крайнего положения звена {link} ({kind} {point}), с которого начинается холостой ход: "
        "φ = {phi:.6f}° (рабочий ход {work:.4f}°, холостой {idle:.4f}°, K = {K:.4f}, θ = {theta:.4f}°)"),
    "x_warn_idle": (
        "warning: {file}: {field}: the resisting force {name} acts on the idle (fast) stroke too; give "
        "stroke = \"working\" if it resists the working stroke only (or stroke = \"both\" to say so)",
        "внимание: {file}: {field}: сила сопротивления {name} действует и на холостом (быстром) ходу; "
        "укажите stroke = \"working\", если она действует только на рабочем ходу (или stroke = \"both\", "
        "если так и задумано)"),
    "x_warn_idle_only": (
        "warning: {file}: {field}: the resisting force {name} acts on the idle (fast) stroke only (stroke = "
        "\"{stroke}\"); give stroke = \"working\" for the working (slow) stroke",
        "внимание: {file}: {field}: сила сопротивления {name} действует только на холостом (быстром) ходу "
        "(stroke = \"{stroke}\"); для рабочего (медленного) хода укажите stroke = \"working\""),
    "x_warn_idle_moment": (
        "warning: {file}: {field}: the resisting moment {name} acts on the idle (fast) stroke too; give "
        "stroke = \"working\" if it resists the working stroke only (or stroke = \"both\" to say so)",
        "внимание: {file}: {field}: момент сопротивления {name} действует и на холостом (быстром) ходу; "
        "укажите stroke = \"working\", если он действует только на рабочем ходу (или stroke = \"both\", "
        "если так и задумано)"),
})


# --------------------------------------------------------------------------- the gear and cam sheets' words
SHEET_WORDS.update({
    "coaxiality": ("соосность", "coaxiality"),  # the 2K-H train's conditions
    "assembly": ("сборка", "assembly"),
    "neighbourhood": ("соседство", "neighbourhood"),
    "centre_min": ("O_{мин}", "O_{min}"),  # the cam's centre: the least base radius, the chosen one
    "centre_best": ("O_{опт}", "O_{best}"),
    "unit_mm": ("мм", "mm"),
    "unit_m": ("м", "m"),
    "working_stroke": ("рабочий ход", "working stroke"),  # the plan of positions
    "idle_stroke": ("холостой ход", "idle stroke"),
})
