"""``plans bench`` in both languages: its report (``bench.md``), its goals and what each
measured, its lines on the terminal and ``--fuzz``'s; merged into :data:`plans.phrases.PHRASES`
the first time one is written (:func:`plans.phrases.say`), so no other command reads it.
The report's English is docs/accuracy.md's and docs/bench/bench.md's."""

from __future__ import annotations

from typing import Any

#: key -> (English, Russian), as :data:`plans.phrases.PHRASES`.
BENCH: dict[str, tuple[str, str]] = {
    # ---- a time, as the goals write it (plans.accuracy.timing.took)
    "bu_us": ("{v:.1f} µs", "{v:.1f} мкс"),
    "bu_ms": ("{v:.2f} ms", "{v:.2f} мс"),
    "bu_s": ("{v:.2f} s", "{v:.2f} с"),
    "bu_3g": ("{v:.3g} {unit}", "{v:.3g} {unit}"),
    # ---- the progress lines
    "bp_case": ("{name} ...", "{name} ..."),
    "bp_chain": ("chain ...", "цепь групп ..."),
    "bp_chain_n": ("chain {n} ...", "цепь из {n} групп ..."),
    "bp_speed": ("speed goals and peers ...", "цели по скорости и сравнение с другими программами ..."),
    "bp_forces": ("forces ...", "силовой расчёт ..."),
    "bp_cycle": ("cycle ...", "цикл ..."),
    "bp_draftsman": ("draftsman Monte Carlo ...", "ручной чертёж, метод Монте-Карло ..."),
    "bp_stability": ("stability ...", "устойчивость ..."),
    "bp_goals": ("performance goals ...", "цели по быстродействию ..."),
    "bp_g_kinematics": ("goals: kinematics ...", "цели: кинематика ..."),
    "bp_g_structure": ("goals: structure, forces, start-up ...", "цели: строение, силы, запуск ..."),
    "bp_g_sheets": ("goals: sheets ...", "цели: листы ..."),
    "bp_g_page": ("goals: demonstration page ...", "цели: демонстрационная страница ..."),
    "bp_g_examiner": ("goals: the examiner ...", "цели: проверка листов ..."),
    "bp_g_note": ("goals: explanatory note ...", "цели: пояснительная записка ..."),
    "bp_g_group": ("goals: a group's course ...", "цели: курсовые проекты группы ..."),
    "bp_g_workbench": ("goals: the workbench ...", "цели: рабочее место ..."),
    "bp_peer": ("peer {peer} ...", "программа {peer} ..."),
    # ---- the state of a goal (a line on the terminal, a cell of the report)
    "bs_met": ("met", "достигнута"),
    "bs_not_met": ("NOT met", "НЕ достигнута"),
    "bs_skipped": ("skipped", "пропущена"),
    "bs_yes": ("yes", "да"),
    "bs_no": ("no", "нет"),
    # ---- the goals (what is measured) and what each measured
    "bq_exact_360": ("exact kinematics of 360 V-engine positions (v and a)",
                     "точная кинематика V-образного двигателя в 360 положениях (v и a)"),
    "bq_construction_1": ("construction of both plans of the V-engine at one position",
                          "построение обоих планов V-образного двигателя в одном положении"),
    "bq_construction_360": ("both plans of 360 V-engine positions built together, against one position at a time",
                            "оба плана V-образного двигателя в 360 положениях, построенные вместе, против "
                            "построения по одному положению"),
    "bq_friction_360": ("force analysis with friction in every pair of 360 V-engine positions (successive "
                        "approximation, lever included), against the frictionless one",
                        "силовой расчёт V-образного двигателя с трением во всех парах в 360 положениях "
                        "(последовательные приближения, с рычагом) против расчёта без трения"),
    "bq_design_central": ("design of a central slider-crank, proven",
                          "синтез центрального кривошипно-ползунного механизма с проверкой"),
    "bq_design_offset": ("design of an offset slider-crank from K, proven",
                         "синтез дезаксиального кривошипно-ползунного механизма по K с проверкой"),
    "bq_design_crank_rocker": ("design of a crank-rocker from ψ and K (best γmin), proven",
                               "синтез кривошипно-коромыслового механизма по ψ и K (наибольший γmin) с проверкой"),
    "bq_design_coulisse": ("design of a shaper's coulisse mechanism, proven",
                           "синтез кулисного механизма строгального станка с проверкой"),
    "bq_design_v_engine": ("design of a V-engine, proven", "синтез V-образного двигателя с проверкой"),
    "bq_floor": ("exact kinematics, 360 positions, {name}: within {ratio}× of the numpy floor",
                 "точная кинематика, 360 положений, {name}: не дольше {ratio}× нижней границы numpy"),
    "bq_floor_got": ("{ours} per position, floor {floor}, {r:.2f}×",
                     "{ours} на положение, граница {floor}, {r:.2f}×"),
    "bq_peer": ("exact kinematics, 360 positions, {name}: ≥ {speedup:g}× ahead of pylinkage + numba",
                "точная кинематика, 360 положений, {name}: быстрее pylinkage + numba не меньше чем в {speedup:g}×"),
    "bq_peer_got": ("pylinkage + numba {peer} per position, ours {ours}: {speed:.2f}× ahead",
                    "pylinkage + numba {peer} на положение, наша {ours}: быстрее в {speed:.2f}×"),
    "bq_agree": ("positions, {name}: agree with pylinkage to {tol:g}",
                 "положения, {name}: совпадают с pylinkage до {tol:g}"),
    "bq_agree_got": ("largest difference {e:.2g} of the crank (v {v:.2g}, a {a:.2g})",
                     "наибольшая разность {e:.2g} длины кривошипа (v {v:.2g}, a {a:.2g})"),
    "bq_no_run": ("skipped: no run", "пропущена: не запускалась"),
    "bq_one": ("one position, {name}: ≤ {bound} and ahead of pylinkage's step",
               "одно положение, {name}: ≤ {bound} и быстрее шага pylinkage"),
    "bq_one_got": ("{t} (positions, v, a){extra}", "{t} (положения, v, a){extra}"),
    "bq_one_step": ("; pylinkage's step {t} (positions only), least of {turns} turns each",
                    "; шаг pylinkage {t} (только положения), наименьшее из {turns} запусков каждого"),
    "bq_chain": ("chain of {n} dyads, one position, structure analysis included: ≤ {bound}",
                 "цепь из {n} диад, одно положение, со структурным анализом: ≤ {bound}"),
    "bq_chain_got": ("{t}; {per} per dyad (×{growth:.2f} from {half} to {n} dyads: linear is ×2)",
                     "{t}; {per} на диаду (×{growth:.2f} от {half} до {n} диад: линейный рост — ×2)"),
    "bq_forces": ("forces and lever, 360 positions, {name}: ≤ {bound}",
                  "силы и рычаг, 360 положений, {name}: ≤ {bound}"),
    "bq_forces_got": ("{t} (loads read in {tl}), least of {turns} turns with the solve alone",
                      "{t} (нагрузки прочитаны за {tl}), наименьшее из {turns} запусков поочерёдно с одним расчётом"),
    "bq_help": ("plans --help starts in ≤ {bound:g} s (where numpy imports in ≤ {floor:g} s; else stretched alike)",
                "plans --help запускается за ≤ {bound:g} с (где numpy загружается за ≤ {floor:g} с; иначе граница "
                "растягивается так же)"),
    "bq_start": ("plans solve starts in ≤ {bound:g} s (where numpy imports in ≤ {floor:g} s; else stretched alike; "
                 "launch to solving begun: interpreter, imports, scene read)",
                 "plans solve запускается за ≤ {bound:g} с (где numpy загружается за ≤ {floor:g} с; иначе граница "
                 "растягивается так же; от запуска до начала расчёта: интерпретатор, загрузка модулей, чтение сцены)"),
    "bq_solve": ("plans solve whole, slider_crank.toml with its table: ≤ numpy floor + {budget:g} s (stretched alike)",
                 "plans solve целиком, slider_crank.toml с таблицей: ≤ граница numpy + {budget:g} с (растягивается "
                 "так же)"),
    "bq_exit": ("skipped: exit status {status}", "пропущена: код завершения {status}"),
    "bq_scaled": ("judged on processor time where less than wall; bound ×{stretch:.2f}: numpy's floor over {floor:g} s",
                  "по процессорному времени, где оно меньше полного; граница ×{stretch:.2f}: нижняя граница numpy "
                  "больше {floor:g} с"),
    "bq_unscaled": ("judged on processor time where less than wall", "по процессорному времени, где оно меньше полного"),
    "bq_solve_got": ("{took:.3f} s = {floor:.3f} s (python importing numpy alone) + {own:.3f} s of our own (processor "
                     "{own_cpu:.3f} s of our own), least of {reps}; {scaled}",
                     "{took:.3f} с = {floor:.3f} с (python загружает только numpy) + {own:.3f} с собственных "
                     "(процессорных {own_cpu:.3f} с собственных), наименьшее из {reps}; {scaled}"),
    "bq_start_got": ("{took:.3f} s (processor {cpu:.3f} s), least of {reps} (python importing numpy alone, stopped the "
                     "same way: {base:.3f} s, processor {base_cpu:.3f} s; {over:+.3f} s over it); {scaled}",
                     "{took:.3f} с (процессорных {cpu:.3f} с), наименьшее из {reps} (python загружает только numpy "
                     "и останавливается так же: {base:.3f} с, процессорных {base_cpu:.3f} с; на {over:+.3f} с "
                     "дольше); {scaled}"),
    "bq_help_got": ("{took:.3f} s (processor {cpu:.3f} s), least of {reps} (python importing numpy alone: "
                    "{floor:.3f} s, processor {floor_cpu:.3f} s); {scaled}",
                    "{took:.3f} с (процессорных {cpu:.3f} с), наименьшее из {reps} (python загружает только numpy: "
                    "{floor:.3f} с, процессорных {floor_cpu:.3f} с); {scaled}"),
    "bq_sheets": ("sheets", "листы"),
    "bq_missing": ("skipped: {path} missing", "пропущена: нет {path}"),
    "bq_no_renderer": ("skipped: the renderer is not installed (plans bench of the drawings package)",
                       "пропущена: чертёжная часть не установлена (plans bench пакета drawings)"),
    "bq_failed": ("skipped: {error}", "пропущена: {error}"),
    "bq_no_browser": ("skipped: Chromium or Playwright not installed", "пропущена: не установлены Chromium или Playwright"),
    "bq_sheet": ("V-engine, {n} {size} sheets: {name} ≤ {bound:g} s per sheet",
                 "V-образный двигатель, листов {size}: {n}; {name} ≤ {bound:g} с на лист"),
    "bq_png": ("PNG at 150 dpi", "PNG при 150 dpi"),
    "bq_sheet_got": ("{wall:.3f} s per sheet (processor {cpu:.3f} s, the least; slowest {slowest:.3f} s), medians of "
                     "{reps}{extra}; load {load}",
                     "{wall:.3f} с на лист (процессорных {cpu:.3f} с, наименьшее; самый долгий {slowest:.3f} с), "
                     "медианы из {reps}{extra}; загрузка {load}"),
    "bq_sheet_built": ("; the sheets built (engine, panels, layout) in {t:.3f} s per sheet",
                       "; листы построены (расчёт, поля, раскладка) за {t:.3f} с на лист"),
    "bq_dxf": ("V-engine, {n} {size} sheets: DXF ≤ {bound:g} s per sheet and ≤ SVG × {per_svg:g}",
               "V-образный двигатель, листов {size}: {n}; DXF ≤ {bound:g} с на лист и ≤ SVG × {per_svg:g}"),
    "bq_dxf_got": ("{wall:.3f} s per sheet (processor {cpu:.3f} s, the least; slowest {slowest:.3f} s; SVG × "
                   "{svg:.2f}), medians of {reps}; load {load}",
                   "{wall:.3f} с на лист (процессорных {cpu:.3f} с, наименьшее; самый долгий {slowest:.3f} с; SVG × "
                   "{svg:.2f}), медианы из {reps}; загрузка {load}"),
    "bq_diagrams": ("cycle diagrams sheet (V-engine): SVG ≤ {bound:g} s",
                    "лист диаграмм цикла (V-образный двигатель): SVG ≤ {bound:g} с"),
    "bq_diagrams_got": ("{wall:.3f} s (processor {cpu:.3f} s, the least), median of {reps} (engine, panels, layout "
                        "and SVG); load {load}",
                        "{wall:.3f} с (процессорных {cpu:.3f} с, наименьшее), медиана из {reps} (расчёт, поля, "
                        "раскладка и SVG); загрузка {load}"),
    "bq_note_short": ("explanatory note", "пояснительная записка"),
    "bq_note": ("V-engine project's explanatory note, 12 positions and its figures: DOCX ≤ {bound:g} s",
                "пояснительная записка проекта V-образного двигателя, 12 положений с рисунками: DOCX ≤ {bound:g} с"),
    "bq_note_got": ("{t:.3f} s of processor time (wall {wall:.3f} s), best of {reps}; {mb:.2f} MB",
                    "{t:.3f} с процессорного времени (полного {wall:.3f} с), лучшее из {reps}; {mb:.2f} МБ"),
    "bq_page_short": ("demonstration page", "демонстрационная страница"),
    "bq_page_size": ("V-engine demonstration page, 72 positions: ≤ {bound:g} MB",
                     "демонстрационная страница V-образного двигателя, 72 положения: ≤ {bound:g} МБ"),
    "bq_mb": ("{mb:.3f} MB", "{mb:.3f} МБ"),
    "bq_page_build": ("the page built in ≤ {bound:g} s", "страница построена за ≤ {bound:g} с"),
    "bq_seconds3": ("{t:.3f} s", "{t:.3f} с"),
    "bq_seconds2": ("{t:.2f} s", "{t:.2f} с"),
    "bq_seconds1": ("{t:.1f} s", "{t:.1f} с"),
    "bq_page_first": ("first step visible in headless Chromium in ≤ {bound:g} s",
                      "первый шаг виден в Chromium без окна за ≤ {bound:g} с"),
    "bq_group_short": ("a group's course", "курсовые проекты группы"),
    "bq_workbench_short": ("workbench", "рабочее место"),
    "bq_full_bench": ("skipped: measured by the full bench", "пропущена: измеряется полным прогоном"),
    "bq_group_needed": ("samples/group is needed", "нужна папка samples/group"),
    "bq_variants": ("a group of 30 variants (files, keys, forms, reference sheets), --jobs 2 (≤ {bound:g} s)",
                    "группа из 30 вариантов (файлы, ключи, бланки, эталонные листы), --jobs 2 (≤ {bound:g} с)"),
    "bq_variants_got": ("{t:.1f} s{complaint}", "{t:.1f} с{complaint}"),
    "bq_gradebook": ("30 submissions checked into the gradebook (≤ {bound:g} s)",
                     "30 работ проверены в ведомость (≤ {bound:g} с)"),
    "bq_server": ("workbench edit round trip, {n} positions: the server's share ≤ {bound:g} ms",
                  "правка на рабочем месте, {n} положений: доля сервера ≤ {bound:g} мс"),
    "bq_server_got": ("{t:.1f} ms (processor time {cpu:.1f} ms; with loopback HTTP {http:.1f} ms; {kb:.0f} kB of JSON)",
                      "{t:.1f} мс (процессорное время {cpu:.1f} мс; с HTTP на этом же компьютере {http:.1f} мс; "
                      "{kb:.0f} кБ JSON)"),
    "bq_round_trip": ("workbench edit round trip, {n} positions: new plans drawn in the page in ≤ {bound:g} ms",
                      "правка на рабочем месте, {n} положений: новые планы на странице за ≤ {bound:g} мс"),
    "bq_ms": ("{t:.1f} ms", "{t:.1f} мс"),
    "bq_serve": ("plans serve to its first page in ≤ {bound:g} s", "plans serve до первой страницы за ≤ {bound:g} с"),
    "bq_either": ("{en}", "{ru}"),  # a text made in both languages where it is measured
    "bq_examiner_short": ("examiner", "проверка листов"),
    "bq_examiner_needed": ("the V-engine, shaper, six-bar and Whitworth samples are needed",
                           "нужны примеры V-образного двигателя, строгального станка, шестизвенника и механизма Витворта"),
    "bq_named": ("planted mistake named first (≥ {rate:.0%}), {where}",
                 "внесённая ошибка названа первой (≥ {rate:.0%}), {where}"),
    "bq_where_quick": ("shaper and Whitworth", "строгальный станок и механизм Витворта"),
    "bq_where_full": ("4 scenes", "4 сцены"),
    "bq_named_got": ("{named} of {shown} ({rate:.1%}; {invisible} slips moved nothing beyond the tolerance); {kinds}",
                     "{named} из {shown} ({rate:.1%}; описок, не вышедших за допуск: {invisible}); {kinds}"),
    "bq_clean": ("clean submission with no finding (≥ {rate:.0%})", "работа без ошибок без замечаний (≥ {rate:.0%})"),
    "bq_clean_got": ("{ok} of {clean} ({rate:.1%})", "{ok} из {clean} ({rate:.1%})"),
    "bq_one_submission": ("one submission, two positions, diagnosed (≤ {bound} s)",
                          "одна работа, два положения, с разбором ошибок (≤ {bound} с)"),
    "bq_folder": ("a folder of 30 submissions checked (≤ {bound:g} s)", "папка из 30 работ проверена (≤ {bound:g} с)"),
    # ---- the terminal's and the report's frame
    "br_goal_line": ("{state} {goal}: {measured}{ratio}", "{state} {goal}: {measured}{ratio}"),  # state padded
    "br_title": ("# plans bench{quick}", "# plans bench{quick}"),
    "br_meta": ("Python {python}, numpy {numpy}, shapely {shapely}, {machine}, OPENBLAS_NUM_THREADS={threads}; total "
                "{wall:.1f} s.",
                "Python {python}, numpy {numpy}, shapely {shapely}, {machine}, OPENBLAS_NUM_THREADS={threads}; всего "
                "{wall:.1f} с."),
    "br_unset": ("unset", "не задано"),
    "br_cpus": ("{machine}, {n} CPUs", "{machine}, процессоров: {n}"),
    "br_error": ("Error: largest over positions and quantities of |x − x_ref| / (size of the known vector of that "
                 "kind: l1, ω1·l1, ω1²·l1, ω1, ω1²); reference: mpmath at 50 digits for the slider-crank and the "
                 "four-bar, the exact analysis elsewhere.",
                 "Погрешность: наибольшее по положениям и величинам |x − x_ref| / (размер известного вектора того же "
                 "рода: l1, ω1·l1, ω1²·l1, ω1, ω1²); эталон: mpmath с 50 знаками для кривошипно-ползунного механизма "
                 "и четырёхзвенника, в остальных — точный расчёт."),
    "br_summary": ("## Summary", "## Сводка"),
    "br_cost": ("## Cost relative to the exact analysis (same run)", "## Время относительно точного расчёта (тот же прогон)"),
    "br_cost_text": ("Time per position over the exact analysis's time per position at the same number of positions "
                     "(the exact analysis is vectorised over positions, the construction and the polygons are built "
                     "position by position, Newton continues from position to position).",
                     "Время на положение, делённое на время точного расчёта на положение при том же числе положений "
                     "(точный расчёт идёт по массивам положений, построение и планы сил — положение за положением, "
                     "метод Ньютона продолжает решение от положения к положению)."),
    "br_all": ("## All methods by number of positions", "## Все методы по числу положений"),
    "br_others": ("## Other samples (against the exact analysis)", "## Другие примеры (против точного расчёта)"),
    "br_speed": ("## Speed goals and open peers", "## Цели по скорости и открытые программы для сравнения"),
    "br_speed_text": ("Each goal measured in this run, side by side with what it is compared to; ratio: measured over "
                      "the goal's bound (at most 1 when met).",
                      "Каждая цель измерена в этом прогоне рядом с тем, с чем сравнивается; отношение — измеренное, "
                      "делённое на границу цели (не больше 1, если цель достигнута)."),
    "br_chain": ("## Cost against mechanism size (chain of N RRR dyads)",
                 "## Время в зависимости от размера механизма (цепь из N диад RRR)"),
    "br_stability": ("## Stability", "## Устойчивость"),
    "br_stiff": ("## Stiff loads (V-engine, 72 positions)", "## Жёсткие нагрузки (V-образный двигатель, 72 положения)"),
    "br_stiff_text": ("Balancing load by the Zhukovsky lever and by the power balance against kinetostatics, relative "
                      "to the largest |F_bal| of the cycle.",
                      "Уравновешивающая нагрузка по рычагу Жуковского и по балансу мощностей против кинетостатики, "
                      "относительно наибольшей |F_ур| за цикл."),
    "br_warnings": ("## Warnings", "## Предупреждения"),
    "br_plot": ("![error against run time](bench.svg)", "![погрешность и время расчёта](bench.svg)"),
    "br_goals": ("## Performance goals", "## Цели по быстродействию"),
    "br_together": ("Built together: {together} for 360 positions; one position at a time: {one}; the readings of "
                    "the two differ by at most {apart:.1e} of the plan.",
                    "Построены вместе: {together} на 360 положений; по одному положению: {one}; отсчёты двух "
                    "построений расходятся не больше чем на {apart:.1e} плана."),
    "br_profile": ("Where the time goes ({goal}, own time per run):", "На что уходит время ({goal}, собственное время за запуск):"),
    "br_hand": ("## Hand drawing (Monte Carlo)", "## Ручной чертёж (метод Монте-Карло)"),
    "br_hand_text": ("Pencil ±{pencil} mm, protractor ±{protractor}°, {n} drawings per sheet; the 95th percentile of "
                     "each reading's error.",
                     "Карандаш ±{pencil} мм, транспортир ±{protractor}°, чертежей на лист: {n}; 95-й процентиль "
                     "погрешности каждого отсчёта."),
    "br_hand_scene": ("### {scene}, φ = {phi}°", "### {scene}, φ = {phi}°"),
    # ---- the tables' heads (cells joined by " | ")
    "bh_summary": ("method | mechanism | positions | param | error (max rel.) | time | per position",
                   "метод | механизм | положений | параметр | погрешность (наиб. отн.) | время | на положение"),
    "bh_ratio": ("mechanism | positions | exact per position", "механизм | положений | точно, на положение"),
    "bh_over_exact": ("{method} / exact", "{method} / точно"),
    "bh_all": ("method | mechanism | positions | param | error | time | per position | cond | note",
               "метод | механизм | положений | параметр | погрешность | время | на положение | обусл. | примечание"),
    "bh_others": ("method | sample | positions | error | per position | cond",
                  "метод | пример | положений | погрешность | на положение | обусл."),
    "bh_chain": ("N | exact, per position (360) | construction, 1 position | Newton, per position (12) | Newton error "
                 "| construction error | Newton cond",
                 "N | точно, на положение (360) | построение, 1 положение | Ньютон, на положение (12) | погрешность "
                 "Ньютона | погрешность построения | обусл. Ньютона"),
    "bh_stability": ("case | exact | construction | newton | Newton cond | error raised",
                     "случай | точно | построение | Ньютон | обусл. Ньютона | ошибка"),
    "bh_stiff": ("case | lever | power | error raised", "случай | рычаг | мощности | ошибка"),
    "bh_goals": ("goal | limit | measured | met", "цель | граница | измерено | достигнута"),
    "bh_profile": ("function | calls | own µs | cum µs", "функция | вызовов | своё, мкс | всего, мкс"),
    "bh_hand": ("quantity | exact", "величина | точно"),
    "bh_hand_sheet": ("{h}: p95 rel. | {h}: p95 abs. | {h}: p95 mm", "{h}: p95 отн. | {h}: p95 абс. | {h}: p95 мм"),
    "bh_speed": ("goal | measured | ratio | met", "цель | измерено | отношение | достигнута"),
    "bh_peers": ("peer | mechanism | positions | per position | r | v | a | note",
                 "программа | механизм | положений | на положение | r | v | a | примечание"),
    "bc_oracle": ("(oracle)", "(эталон)"),
    # ---- the warnings
    "bw_cond": ("{method} on {scene} ({n} positions, {param}): condition number {cond:.3g} > {limit:.0e}",
                "{method}, {scene} ({n} положений, {param}): число обусловленности {cond:.3g} > {limit:.0e}"),
    "bw_stability": ("stability case '{case}': Newton condition number {cond:.3g}",
                     "случай устойчивости «{case}»: число обусловленности Ньютона {cond:.3g}"),
    "bw_goal": ("performance goal not met: {goal} (see the profile in bench.md)",
                "цель по быстродействию не достигнута: {goal} (см. профиль в bench.md)"),
    # ---- plans bench --fuzz
    "bf_case": ("case {i}: {sample}: {why}", "случай {i}: {sample}: {why}"),
    "bf_progress": ("{n} cases, {accepted} accepted, {refused} refused, {failures} distinct failures, {t:.0f} s",
                    "случаев: {n}, принято: {accepted}, отклонено: {refused}, разных сбоев: {failures}, {t:.0f} с"),
    "bf_report": ("fuzz: {n} cases (seed {seed}): {accepted} accepted, {refused} refused in one line, {broke} broke "
                  "the promise ({foreign} foreign exceptions, {nonfinite} non-finite outputs, {distinct} distinct)",
                  "--fuzz: случаев {n} (начальное число {seed}): принято {accepted}, отклонено одной строкой {refused}, "
                  "обещание нарушено в {broke} (чужих исключений {foreign}, нечисловых результатов {nonfinite}, "
                  "разных {distinct})"),
    "bf_by_kind": ("  by kind: {kinds}", "  по видам файлов: {kinds}"),
    "bf_no_samples": ("plans bench --fuzz: no samples to fuzz", "plans bench --fuzz: нет примеров для проверки"),
}

#: The bench's words inside its records (methods, mechanisms, parameters, notes, stability
#: cases) and the goals' mechanism names, English -> Russian: bench.json keeps the English and
#: the Russian report writes these (:func:`words`).  A pattern's groups are numbers.
WORDS_RU: tuple[tuple[str, str], ...] = (
    (r"chain of (\d+) dyads", r"цепь из \1 диад"),
    (r"chain N=(\d+) done", r"цепь из \1 диад готова"),
    (r"(\S+): (\d+) positions done", r"\1: \2 положений готово"),
    (r"(\S[^:]*): (\S+) done", r"\1: \2 готово"),
    (r"h=(\S+) deg", r"h = \1°"),
    (r"tol=(\S+)", r"допуск \1"),
    (r"p95 of (\d+) drawings", r"p95 из \1 чертежей"),
    (r"exact (\d+) steps over 720°", r"точно, \1 шагов за 720°"),
    (r"exact (\d+) steps", r"точно, \1 шагов"),
    (r"(\d+) degenerate intersections", r"вырожденных пересечений: \1"),
    (r"graphical flywheel error; goal (\S+) ms at 360 positions \(met\)",
     r"погрешность маховика графически; цель \1 мс при 360 положениях (достигнута)"),
    (r"graphical flywheel error; goal (\S+) ms at 360 positions \(missed\)",
     r"погрешность маховика графически; цель \1 мс при 360 положениях (не достигнута)"),
    (r"graphical flywheel error; work integrated to (\S+) J; goal (\S+) s \(met\)",
     r"погрешность маховика графически; работа проинтегрирована до \1 Дж; цель \2 с (достигнута)"),
    (r"graphical flywheel error; work integrated to (\S+) J; goal (\S+) s \(missed\)",
     r"погрешность маховика графически; работа проинтегрирована до \1 Дж; цель \2 с (не достигнута)"),
    (r"goal (\S+) s \(met\)", r"цель \1 с (достигнута)"),
    (r"goal (\S+) s \(missed\)", r"цель \1 с (не достигнута)"),
    (r"(\S+) rad from dead centres", r"\1 рад от мёртвого положения"),
    (r"r = (\S+) m, l = (\S+) m", r"r = \1 м, l = \2 м"),
    (r"crank (\S+) m, others (\S+) m", r"кривошип \1 м, остальные звенья \2 м"),
    (r"ω1 = (\S+) rad/s", r"ω1 = \1 рад/с"),
    (r"slot (\S+)° to its guide", r"кулиса под углом \1° к направляющей"),
    (r"rod 2 (\S+) times heavier than rod 4", r"шатун 2 в \1 раз тяжелее шатуна 4"),
    (r"gas force (\S+) of the inertia loads", r"сила давления газов — \1 от сил инерции"),
    (r"V-engine as given", "V-образный двигатель как задан"),
    (r"no masses \(inertia-free, gas only\)", "без масс (без сил инерции, только газы)"),
    (r"Scotch yoke", "синусный механизм"),
    (r"slider-crank \(offset\)", "кривошипно-ползунный (со смещением)"),
    (r"slider-crank", "кривошипно-ползунный"),
    (r"four-bar", "четырёхзвенник"),
    (r"newton tol sweep", "Ньютон, ряд допусков"),
    (r"newton", "Ньютон"),
    (r"finite differences", "конечные разности"),
    (r"forces exact", "силы точно"),
    (r"force polygons", "планы сил"),
    (r"construction of the polygons \(readings: see plans solve\)", "построение планов сил (отсчёты: см. plans solve)"),
    (r"construction", "построение"),
    (r"draftsman (A\d)", r"чертёжник \1"),
    (r"cycle dynamics 720", "динамика цикла 720"),
    (r"cycle dynamics", "динамика цикла"),
    (r"cycle diagrams sheet", "лист диаграмм цикла"),
    (r"is the oracle", "это эталон"),
    (r"time: simulation cost per drawing", "время: расчёт одного чертежа"),
    (r"exact analysis", "точный расчёт"),
    (r"exact flywheel", "точный маховик"),
    (r"mpmath 50 digits", "mpmath, 50 знаков"),
    (r"kinetostatics vs lever vs power", "кинетостатика, рычаг и мощности"),
    (r"step_fast_with_kinematics: positions, v and a of the joints",
     "step_fast_with_kinematics: положения, v и a шарниров"),
    (r"one pure-Python step: positions only", "один шаг на чистом Python: только положения"),
    (r"skipped: only single-dyad mechanisms are modelled for this peer",
     "пропущено: для этой программы смоделированы только механизмы из одной диады"),
    (r"skipped: not a crank with RRR/RRP dyads", "пропущено: не кривошип с диадами RRR/RRP"),
    (r"fsolve on the vector loop at each position: positions, v and a",
     "fsolve по векторному контуру в каждом положении: положения, v и a"),
    (r"skipped: ", "пропущено: "),
    (r"exact", "точно"),
    (r"phi = (\S+) deg", r"φ = \1°"),
)


def words(text: Any, lang: str) -> str:
    """A phrase, or a word or line of the bench's records, in ``lang``: in Russian the bench's
    own English words (:data:`WORDS_RU`) replaced where they stand whole."""
    # a phrase (plans.phrases, which reads this catalogue: not imported here) or an error of the catalogue
    out = text.say(lang) if hasattr(text, "say") else text.text(lang) if hasattr(text, "text") else str(text)
    if lang != "ru":
        return out
    import re

    for pattern, russian in WORDS_RU:
        out = re.sub(r"(?<![\w-])" + pattern + r"(?![\w-])", russian, out)
    return re.sub(r"(?<=\d)\.(?=\d)", ",", out)  # the records' numbers with a decimal comma
