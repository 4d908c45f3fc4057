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
from typing import TYPE_CHECKING, Any

# the checker's words and the errors' and warnings' lines, read from here as before (loaded
# when first asked for, :func:`__getattr__`: ``plans solve`` that succeeds reads neither)
if TYPE_CHECKING:
    from plans.check_terms import CAUSES, CHECK_SENTENCES, CHECK_TERMS, KINDS_RU, PLANS_RU  # noqa: F401
    from plans.messages import ERRORS, WARNINGS  # noqa: F401

_LATER = {"CAUSES": "plans.check_terms", "CHECK_SENTENCES": "plans.check_terms", "CHECK_TERMS": "plans.check_terms",
          "KINDS_RU": "plans.check_terms", "PLANS_RU": "plans.check_terms",
          "ERRORS": "plans.messages", "WARNINGS": "plans.messages"}


def __getattr__(name: str) -> Any:
    if name in _LATER:
        import importlib

        value = getattr(importlib.import_module(_LATER[name]), name)
        globals()[name] = value
        return value
    raise AttributeError(f"module {__name__!r} has no attribute {name!r}")

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
    "mm/(m/s^2)": "мм/(м/с²)", "mm/N": "мм/Н", "mm/unit": "мм/ед.", "ms": "мс", "µs": "мкс", "ns": "нс",
    "deg": "°",
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
    "b_note_one_plane": ("{order}: one counterweight leaves a moment of {m:.6g} N*m; give two planes",  # order: b_<kind>
                         "{order}: один противовес оставляет момент {m:.6g} Н·м; задайте две плоскости"),
    "b_json_angles": ("degrees from the vertical (crank 1 at top dead centre) in the direction of rotation",
                      "градусы от вертикали (кривошип 1 в верхней мёртвой точке) по направлению вращения"),
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
    "t_json_angles": ("rad, counter-clockwise positive; phi_deg in degrees",
                      "рад, положительные против часовой стрелки; phi_deg в градусах"),
    "y_csv_table": ("table", "таблица"),  # the headings of plans solve --csv
    "y_csv_quantity": ("quantity", "величина"),
    "y_csv_label": ("label", "обозначение"),
    "y_csv_unit": ("unit", "ед."),
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
#: Russian symbols of the terminal's English spellings (the textbook's letters; π is the
#: acceleration pole, p the velocity pole).
_SYMBOLS = ((r"\bp_a(?![A-Z_])", "π"), (r"\bp_v(?![A-Z_])", "p"), (r"\bomega_?(?=\w)", "ω"), (r"\beps_?(?=\w)", "ε"),
            (r"(?<![A-Za-z])Phi(?=\w)", "Φ"), (r"\bmu\b", "μ"), (r"\^2\b", "²"), (r"(?<![A-Za-z])([FM])_bal\b", r"\1_ур"),
            (r"(?<![A-Za-z])([FM])f(?=\d)", r"\1_тр"),
            (r"\brad/s", "рад/с"), (r"(?<![\w/])m/s", "м/с"), (r"\bmm\b", "мм"), (r"\bMPa\b", "МПа"), (r"\bN·m\b", "Н·м"),
            (r"(?<=\d )N\b", "Н"), (r"\bN\b(?= )", "Н"), (r"\binitial link\b", "начальное звено"),
            (r"\bclass-III ([\w-]+) group\b", r"группа III класса \1"), (r"(?<=, )deg\b", "°"),
            (r"\b(RRR|RRP|RPR|PRP|RPP|PRR|PPR) group\b", r"группа \1"), (r"\bgroup\b", "группа"))


#: The Greek letters of the quantities' keys.
GREEK = {"Phi": "Φ", "omega": "ω", "eps": "ε", "tau": "τ"}
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
    head = GREEK.get(head, head)
    if not sep:
        return head
    parts = rest.split("_")
    if head in ("ω", "ε"):
        return head + "".join(parts)
    if parts[0] in GREEK:  # M_Phi_2 -> M_Φ2
        return f"{head}_{GREEK[parts[0]]}{''.join(parts[1:])}"
    if parts[0].startswith("Phi"):  # an arm: h_Phi2_B -> h_Φ2,B
        return f"{head}_{','.join([GREEK['Phi'] + parts[0][3:]] + parts[1:])}"
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


def file_command(sub: Any, name: str, help: str, file: str, file_help: str, json_help: str,
                 quiet_help: str | None = None) -> Any:
    """A command of one file: the file, ``--json PATH|-``, ``--quiet`` when it prints a
    table (``quiet_help``), ``--language``; the parser, for the command's own options."""
    p = sub.add_parser(name, help=help)
    p.add_argument(file, help=file_help)
    p.add_argument("--json", metavar="PATH", help=json_help)
    if quiet_help is not None:
        p.add_argument("--quiet", action="store_true", help=quiet_help)
    add_option(p)
    return p


# ---- sheet sets: the course's two sheets, tables split over parts (drawings.linkage.sheet_sets)
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


# ---- argparse's own sentences (plans.cli.Parser): its usage errors and --help's headings
def argparse_text(message: str, lang: str) -> str:
    """A message argparse wrote (in English, from its msgids) in ``lang``: a msgid of
    :data:`plans.messages.ARGPARSE` matched whole, its values kept (a nested message, such
    as an option's invalid choice, and a type's name translated too)."""
    if lang != "ru":
        return message
    import re

    from plans.messages import ARGPARSE

    spec = re.compile(r"%(?:\((\w+)\))?[sr]")
    for msgid, ru in ARGPARSE.items():
        parts = spec.split(msgid)  # literal, name, literal, name, ..., literal
        names = [n or str(k) for k, n in enumerate(parts[1::2])]
        pattern = "(.+?)".join(re.escape(p) for p in parts[0::2])
        m = re.fullmatch(pattern, message, re.S)
        if m is None:
            continue
        values = dict(zip(names, m.groups(), strict=True))
        if "message" in values:
            values["message"] = argparse_text(values["message"], lang)
        for name, value in values.items():  # a type's name, the command's argument
            if f"a_{value}" in ERRORS:
                values[name] = ERRORS[f"a_{value}"][1]
        unnamed = iter([v for k, v in values.items() if k.isdigit()])

        def value(x: re.Match[str], values: dict[str, str] = values, unnamed: Any = unnamed) -> str:
            return values[x.group(1)] if x.group(1) else next(unnamed)

        return spec.sub(value, ru)
    return message
