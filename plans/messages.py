"""The one-line errors on bad input and the warnings of an implausible scene, in both
languages (read through :mod:`plans.language`)."""

from __future__ import annotations

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
    # ---- the sheets' font (drawings/paper/fonts.py)
    "e_font_missing": ("font {font!r} needs {family!r}, which is not installed; install it ({install}) "
                       "or choose \"dejavu\"",
                       "для шрифта {font!r} нужен {family!r}, а он не установлен; установите его ({install}) "
                       "или выберите \"dejavu\""),
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

def sentence(key: str) -> tuple[str, str]:
    """(English, Russian) of a key of :data:`ERRORS` or :data:`WARNINGS`; the sentences of the
    other file kinds' readers, the drawing options and the constructions are read the first
    time one is asked for (:func:`complete`): a run that says nothing never loads them."""
    got = ERRORS.get(key) or WARNINGS.get(key)
    if got is None:
        complete()
        got = ERRORS.get(key) or WARNINGS[key]
    return got


def complete() -> dict[str, tuple[str, str]]:
    """:data:`ERRORS` with every sentence of the catalogue in it."""
    if "x_at_group" not in ERRORS:
        from plans.messages_commands import COMMAND_ERRORS
        from plans.messages_construction import CONSTRUCTION_ERRORS
        from plans.messages_files import FILE_ERRORS
        from plans.messages_kinds import KIND_ERRORS

        ERRORS.update(FILE_ERRORS)
        ERRORS.update(KIND_ERRORS)
        ERRORS.update(COMMAND_ERRORS)
        ERRORS.update(CONSTRUCTION_ERRORS)
    return ERRORS

#: argparse's own sentences (its msgids, as Python's argparse writes them) -> Russian: a usage
#: error and ``--help`` in the run's language (:func:`plans.language.argparse_text`).
ARGPARSE: dict[str, str] = {
    "usage: ": "использование: ",
    "positional arguments": "позиционные аргументы",
    "options": "параметры",
    "show this help message and exit": "показать эту справку и выйти",
    "the following arguments are required: %s": "не заданы обязательные аргументы: %s",
    "unrecognized arguments: %s": "неизвестные аргументы: %s",
    "argument %(argument_name)s: %(message)s": "аргумент %(argument_name)s: %(message)s",
    "invalid choice: %(value)r (choose from %(choices)s)": "недопустимое значение %(value)r (допустимы: %(choices)s)",
    "invalid %(type)s value: %(value)r": "недопустимое значение %(value)r (ожидалось %(type)s)",
    "expected one argument": "ожидалось одно значение",
    "expected at most one argument": "ожидалось не больше одного значения",
    "expected at least one argument": "ожидалось хотя бы одно значение",
    "expected %s argument": "ожидалось значений: %s",
    "expected %s arguments": "ожидалось значений: %s",
    "ambiguous option: %(option)s could match %(matches)s": "неоднозначный параметр %(option)s: подходят %(matches)s",
    "ignored explicit argument %r": "лишнее значение %r",
    "not allowed with argument %s": "нельзя задавать вместе с %s",
    "one of the arguments %s is required": "нужен один из аргументов %s",
    "unexpected option string: %s": "неожиданный параметр: %s",
    "can't open '%(filename)s': %(error)s": "не удаётся открыть '%(filename)s': %(error)s",
}

ERRORS.update({
    "a_see_help": (" (see plans -h)", " (см. plans -h)"),
    "a_float": ("float", "число"),
    "a_int": ("int", "целое число"),
    "a_command": ("command", "команда"),
})

WARNINGS.update({
    # a resisting load on the idle (fast) stroke (plans.forces.strokes)
    "w_idle": ("{file}: {field}: the resisting force {name} acts on the idle (fast) stroke too; give stroke = \"working\" if it resists the working stroke only (or stroke = \"both\" to say so)",
                "{file}: {field}: сила сопротивления {name} действует и на холостом (быстром) ходу; укажите stroke = \"working\", если она действует только на рабочем ходу (или stroke = \"both\", если так и задумано)"),
    "w_idle_moment": ("{file}: {field}: the resisting moment {name} acts on the idle (fast) stroke too; give stroke = \"working\" if it resists the working stroke only (or stroke = \"both\" to say so)",
                "{file}: {field}: момент сопротивления {name} действует и на холостом (быстром) ходу; укажите stroke = \"working\", если он действует только на рабочем ходу (или stroke = \"both\", если так и задумано)"),
    "w_idle_only": ("{file}: {field}: the resisting force {name} acts on the idle (fast) stroke only (stroke = \"{stroke}\"); give stroke = \"working\" for the working (slow) stroke",
                "{file}: {field}: сила сопротивления {name} действует только на холостом (быстром) ходу (stroke = \"{stroke}\"); для рабочего (медленного) хода укажите stroke = \"working\""),
    "w_serving": ("serving on {host}: other computers on the network can read and write the files of {root}",
                  "сервер открыт на {host}: другие компьютеры сети могут читать и записывать файлы в {root}"),
})
