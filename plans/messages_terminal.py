"""The terminal's lines of the renderer and the group's commands (``plans draw``, ``plans
variants``, ``plans serve``, ``plans check --xlsx``, ``plans bench``) and the gradebook's
headings, in both languages; merged into :data:`plans.language.TERMS` (written by
:func:`plans.phrases.say`)."""

from __future__ import annotations

#: key -> (English, Russian), as :data:`plans.language.TERMS`.
TERMINAL: dict[str, tuple[str, str]] = {
    # ---- plans draw (its progress lines on a terminal)
    "dr_drawing": ("drawing {scene} ...", "построение {scene} ..."),
    "dr_sheet": ("sheet {n} of {total} drawn ({formats})", "лист {n} из {total} построен ({formats})"),
    # ---- plans variants
    "vr_made": ("{folder}: {kind}, {n} figures in the key", "{folder}: {kind}, чисел в ключе: {n}"),
    "vr_handouts": ("{folder}: {n} handouts", "{folder}: листов заданий: {n}"),
    # ---- plans serve
    "sv_serving": ("plans serve: {root} at {url} (Ctrl-C stops)", "plans serve: {root} по адресу {url} (Ctrl-C — остановить)"),
    # ---- plans check --xlsx: the gradebook's columns and its line on the terminal
    "gb_summary": ("{target}: {students} students, {sheets} sheets, {groups} groups",
                   "{target}: студентов {students}, листов {sheets}, групп {groups}"),
    "gb_student": ("student", "студент"),
    "gb_group": ("group", "группа"),
    "gb_variant": ("variant", "вариант"),
    "gb_mark": ("mark", "оценка"),
    "gb_causes": ("causes", "причины"),
    "gb_unexplained": ("unexplained", "не объяснено"),
    "gb_findings": ("findings", "замечания"),
    "gb_linkage": ("linkage", "механизм"),
    "gb_gears": ("gears", "зубчатые передачи"),
    "gb_cam": ("cam", "кулачок"),
    "gb_cycle": ("cycle", "динамика"),
    "gb_engine": ("engine", "уравновешивание"),
    "gb_synthesis": ("synthesis", "синтез"),
    "gb_check": ("check", "проверка"),
    "gb_at": ("{what} at {phis}°", "{what} при {phis}°"),
    # ---- the workbench page: the balancing load's rows
    "wb_bal_moment": ("{sym}, its moment about the pivot", "{sym}, её момент относительно опоры"),
    "wb_bal_exact": ("{sym}: lever against the exact value, %", "{sym}: рычаг относительно точного значения, %"),
    "wb_bal_drawn": ("{sym}: lever against kinetostatics on the drawing, %",
                     "{sym}: рычаг относительно кинетостатики по чертежу, %"),
    # ---- plans check --template: the blank check file's comments
    "cf_head": ("# A blank check file: type in what the student wrote; leave \"\" where nothing is written.\n"
                "# measured: segments measured on the student's plans, mm; values: SI units\n"
                "# (lengths with their unit: \"65 mm\").  Check it with: plans check THIS_FILE",
                "# Пустой файл проверки: впишите то, что записал студент; оставьте \"\", где ничего не записано.\n"
                "# measured — отрезки, измеренные на планах студента, мм; values — величины в СИ\n"
                "# (длины с единицей: \"65 mm\").  Проверка: plans check ЭТОТ_ФАЙЛ"),
    "cf_scales": ("# the student's scales: {{ mu = mm per unit }} or {{ K = unit per mm }}",
                  "# масштабы студента: {{ mu = мм на единицу }} или {{ K = единиц на мм }}"),
    # ---- the blank check file of a gears, cam, engine or synthesis sheet (plans variants, plans check --template)
    "cf_head_sheet": ("# A blank check file: type in what the student wrote; leave \"\" where nothing is written.\n"
                      "# Lengths in the file's unit (mm), angles in degrees.  Check it with: plans check THIS_FILE",
                      "# Пустой файл проверки: впишите то, что записал студент; оставьте \"\", где ничего не записано.\n"
                      "# Длины — в единицах файла (мм), углы — в градусах.  Проверка: plans check ЭТОТ_ФАЙЛ"),
    "cf_scales_polygons": ("# the student's polygons: mm per unit vector",
                           "# масштаб многоугольников студента: мм на единичный вектор"),
    "cf_scales_drawing": ("# the student's drawing: mm on the sheet per mm of the part",
                          "# масштаб чертежа студента: мм на листе на мм детали"),
    # ---- plans design: the heading of the scene it writes
    "d_scene_head": ("# Designed by plans design from {name} ({mechanism}): the lengths are the design's,\n"
                     "# the crank speed, positions, masses and loads the task's.\n",
                     "# Синтезировано командой plans design по {name} ({mechanism}): длины — найденные синтезом,\n"
                     "# частота вращения кривошипа, положения, массы и нагрузки — из задания.\n"),
    # ---- plans bench (its lines on the terminal; the goals' names are the bench's own)
    "bn_goal": ("goal: {goal} {want}: {got}, {state}", "цель: {goal} {want}: {got}, {state}"),
    "bn_met": ("met", "достигнута"),
    "bn_not_met": ("not met", "не достигнута"),
    "bn_speed": ("\nSpeed goals, measured side by side in this run ([measured / bound]):",
                 "\nЦели по скорости, измеренные рядом в этом прогоне ([измерено / граница]):"),
    "bn_warning": ("warning: {w}", "внимание: {w}"),
    "bn_wrote": ("wrote {paths}", "записано: {paths}"),
    "bn_mpmath": ("plans bench: error: the 50-digit reference needs mpmath: pip install -e '.[bench]'",
                  "plans bench: ошибка: для эталона с 50 знаками нужен mpmath: pip install -e '.[bench]'"),
}
