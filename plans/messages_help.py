"""The command line's help in Russian: each command's and option's help as written in English
(the key) and in Russian, read by ``--help`` in a Russian run (:class:`plans.cli.Parser`)."""

from __future__ import annotations

#: English help -> Russian help.
HELP_RU: dict[str, str] = {
    "Velocity and acceleration plans, force polygons and the Zhukovsky lever of planar linkages, built as a draftsman builds them and checked exactly.":
        "Планы скоростей и ускорений, планы сил и рычаг Жуковского плоских механизмов, построенные так, как их строит чертёжник, и проверенные точным расчётом.",
    "solve a scene: table per position, JSON":
        "рассчитать сцену: таблица по положениям, JSON",
    "check a hand-drawn sheet (or a folder of them) against the exact analysis":
        "проверить лист, выполненный от руки (или папку листов), по точному расчёту",
    "error against run time of every method; stability; hand-drawing error":
        "погрешность и время счёта каждого метода; устойчивость; погрешность ручного построения",
    "engine balancing: force and moment polygons, counterweights":
        "уравновешивание двигателя: многоугольники сил и моментов, противовесы",
    "involute gears and trains: geometry, checks, speeds (JSON)":
        "эвольвентные зубчатые колёса и механизмы: геометрия, проверки, скорости (JSON)",
    "a cam: motion laws, base radius, profile by inversion (JSON)":
        "кулачок: законы движения, радиус начальной шайбы, профиль методом обращения (JSON)",
    "design a mechanism from K, stroke, swing; prove it; write its scene":
        "спроектировать механизм по K, ходу, углу размаха; проверить; записать его сцену",
    "draw the scene's sheets (A1..A4) as SVG, PDF, PNG, DXF":
        "построить листы сцены (A1..A4) в SVG, PDF, PNG, DXF",
    "a self-contained HTML page: the plans step by step, the cycle, mistakes":
        "самодостаточная страница HTML: планы шаг за шагом, цикл, ошибки",
    "the explanatory note of the project's files (DOCX, or PDF via LibreOffice)":
        "пояснительная записка по файлам проекта (DOCX или PDF через LibreOffice)",
    "a group's variants from a variant table: files, keys, forms, handouts":
        "варианты группы по таблице вариантов: файлы, ключи, формы, задания",
    "the workbench: edit, solve, check and export a mechanism in the browser":
        "верстак: правка, расчёт, проверка и выгрузка механизма в браузере",
    "scene file (TOML)":
        "файл сцены (TOML)",
    "write results as JSON ('-' for stdout)":
        "записать результаты в JSON ('-' — на стандартный вывод)",
    "write the tables over the positions as CSV ('-' for stdout)":
        "записать таблицы по положениям в CSV ('-' — на стандартный вывод)",
    "print the construction protocol":
        "напечатать протокол построения",
    "no table on stdout":
        "без таблицы на стандартном выводе",
    "language of the output (default: the file's [sheet] language, else the locale's: Russian when LANG starts with ru, else English)":
        "язык вывода (по умолчанию — [sheet] language файла, иначе язык локали: русский, если LANG начинается с ru, иначе английский)",
    "Compare what a student measured and computed on a hand-drawn sheet with the exact values at the student's scales; find inconsistencies in the student's own work.":
        "Сравнить то, что студент измерил и вычислил на листе, выполненном от руки, с точными значениями в масштабах студента; найти несогласованности в работе самого студента.",
    "a check file (TOML), a CSV form (one student per column) or a folder of check files (a scene file beside them is the scene of those that name none)":
        "файл проверки (TOML), форма CSV (по студенту в столбце) или папка файлов проверки (файл сцены рядом с ними — сцена тех, что её не называют)",
    "write the report as JSON ('-' for stdout; single file only)":
        "записать отчёт в JSON ('-' — на стандартный вывод; только для одного файла)",
    "write the summary table as CSV ('-' for stdout)":
        "записать сводную таблицу в CSV ('-' — на стандартный вывод)",
    "write a blank check file of this scene to fill in":
        "записать пустой файл проверки этой сцены для заполнения",
    "with --template: the positions (default: the scene's)":
        "с --template: положения (по умолчанию — положения сцены)",
    "with --template: write it here (default: stdout)":
        "с --template: записать сюда (по умолчанию — на стандартный вывод)",
    "with --template: a check file (toml) or a CSV form, one column per student":
        "с --template: файл проверки (toml) или форма CSV, по столбцу на студента",
    "with --form csv: columns (default 3)":
        "с --form csv: число столбцов (по умолчанию 3)",
    "write <name>.json and <name>.txt per check file here (batch default: DIR/reports)":
        "записать сюда <имя>.json и <имя>.txt по каждому файлу проверки (для папки по умолчанию DIR/reports)",
    "with a folder: every sheet under it checked, one row per student, one worksheet per group (the gradebook)":
        "с папкой: проверить каждый лист в ней, по строке на студента, по листу книги на группу (ведомость)",
    "with --xlsx: weights per sheet, pass threshold, marks":
        "с --xlsx: веса листов, проходной порог, оценки",
    "with --xlsx: check in N processes":
        "с --xlsx: проверять в N процессах",
    "also write the marked sheet and the 1:1 overlay of each file here":
        "записать сюда же размеченный лист и наложение 1:1 для каждого файла",
    "formats of the sheets (default svg)":
        "форматы листов (по умолчанию svg)",
    "``plans bench``: error against run time of every method, and how a hand drawing compares.":
        "plans bench: погрешность и время счёта каждого метода и сравнение с ручным построением.",
    "fewer sizes and samples (well under 30 s)":
        "меньше размеров и выборок (заметно меньше 30 с)",
    "write the JSON here ('-' for stdout) instead of OUT/bench.json":
        "записать JSON сюда ('-' — на стандартный вывод) вместо OUT/bench.json",
    "directory for bench.md, bench.svg (default bench-out)":
        "папка для bench.md, bench.svg (по умолчанию bench-out)",
    "directory of sample scenes (default: the project's samples/)":
        "папка примеров сцен (по умолчанию samples/ проекта)",
    "Monte Carlo drawings per sheet":
        "построений методом Монте-Карло на лист",
    "numbers of positions (default 1,12,360,3600)":
        "числа положений (по умолчанию 1,12,360,3600)",
    "chain lengths in dyads (default 1,2,5,10,20,50)":
        "длины цепочек из диад (по умолчанию 1,2,5,10,20,50)",
    "pencil error, ± mm (default 0.25)":
        "погрешность карандаша, ± мм (по умолчанию 0,25)",
    "protractor error, ± degrees (default 0.25)":
        "погрешность транспортира, ± градусов (по умолчанию 0,25)",
    "no progress lines and no summary on the terminal":
        "без строк хода работы и без сводки на терминале",
    "instead of the bench: fuzz the sample files with N hostile cases and report every broken promise":
        "вместо замеров: проверить файлы примеров N враждебными случаями и сообщить о каждом нарушенном обещании",
    "seed of --fuzz (default 0)":
        "начальное значение для --fuzz (по умолчанию 0)",
    "keep the files of distinct failures here":
        "сохранять сюда файлы различных отказов",
    "engine file (TOML, kind = \"engine\")":
        "файл двигателя (TOML, kind = \"engine\")",
    "write the results as JSON ('-' for stdout)":
        "записать результаты в JSON ('-' — на стандартный вывод)",
    "no tables on stdout":
        "без таблиц на стандартном выводе",
    "gear file (TOML, kind = \"gears\")":
        "файл зубчатой передачи (TOML, kind = \"gears\")",
    "cam file (TOML, kind = \"cam\")":
        "файл кулачка (TOML, kind = \"cam\")",
    "synthesis file (TOML, kind = \"synthesis\")":
        "файл проектирования (TOML, kind = \"synthesis\")",
    "write the designed linkage scene (TOML) here":
        "записать сюда сцену спроектированного механизма (TOML)",
    "write the design as JSON ('-' for stdout)":
        "записать проект в JSON ('-' — на стандартный вывод)",
    "output folder":
        "папка результатов",
    "comma-separated output formats (default svg)":
        "форматы результатов через запятую (по умолчанию svg)",
    "sheet format A1..A4 (overrides [sheet] format)":
        "формат листа A1..A4 (вместо [sheet] format)",
    "overrides [sheet] orientation":
        "вместо [sheet] orientation",
    "overrides [sheet] language":
        "вместо [sheet] language",
    "overrides [sheet] font: gost is osifont, a GOST 2.304 type B font (apt-get install fonts-osifont)":
        "вместо [sheet] font: gost — osifont, шрифт типа Б по ГОСТ 2.304 (apt-get install fonts-osifont)",
    "PNG resolution (default 150)":
        "разрешение PNG (по умолчанию 150)",
    "no progress lines on a terminal":
        "без строк хода работы на терминале",
    "the page to write":
        "записываемая страница",
    "positions per turn in the cycle (default 72)":
        "положений за оборот в цикле (по умолчанию 72)",
    "the position built step by step (default the first)":
        "положение, построенное шаг за шагом (по умолчанию первое)",
    "scene, gears, cam, engine files (TOML)":
        "файлы сцен, зубчатых передач, кулачков, двигателей (TOML)",
    "the document to write":
        "записываемый документ",
    "the note's language (default: the first file's [sheet] language, else the locale's)":
        "язык записки (по умолчанию — [sheet] language первого файла, иначе язык локали)",
    "docx (default) or pdf (through LibreOffice: soffice --headless)":
        "docx (по умолчанию) или pdf (через LibreOffice: soffice --headless)",
    "the figures' resolution (default 200)":
        "разрешение рисунков (по умолчанию 200)",
    "Make one folder per row of a variant table (CSV or TOML): the variant's file, key.json, check.toml and reference sheets; with a roster, the handouts.":
        "Сделать по папке на строку таблицы вариантов (CSV или TOML): файл варианта, key.json, check.toml и эталонные листы; со списком группы — задания.",
    "variant table: CSV or TOML, one row per variant":
        "таблица вариантов: CSV или TOML, по строке на вариант",
    "the group's folder":
        "папка группы",
    "roster: name, group, variant; writes DIR/handouts/":
        "список группы: name, group, variant; пишет DIR/handouts/",
    "variants made in N processes (default 1)":
        "делать варианты в N процессах (по умолчанию 1)",
    "of the handouts, the files' comments and the reference sheets (default: the locale's)":
        "заданий, комментариев в файлах и эталонных листов (по умолчанию — язык локали)",
    "of the marked sheets (default: the report's, --language else the scene's [sheet] language else the locale's)":
        "размеченных листов (по умолчанию — язык отчёта: --language, иначе [sheet] language сцены, иначе язык локали)",
    "no reference sheets (files, keys, forms only)":
        "без эталонных листов (только файлы, ключи, формы)",
    "no progress lines":
        "без строк хода работы",
    "the project folder (default: the current one)":
        "папка проекта (по умолчанию текущая)",
    "the port (default 8765; 0 picks a free one)":
        "порт (по умолчанию 8765; 0 — любой свободный)",
    "the address to listen on (default 127.0.0.1: this computer only)":
        "адрес для приёма запросов (по умолчанию 127.0.0.1: только этот компьютер)",
    "open the page in the web browser":
        "открыть страницу в браузере",
}
