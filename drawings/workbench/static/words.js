// The page's words in Russian and English, the language chosen, and the units as each writes them.
export const WORDS = {
  en: {gallery: "the gallery", workbench: "workbench", save: "Save", page: "Page", check: "Check…",
    page_tip: "the demonstration page (plans demo)", check_tip: "a blank check file for this scene: type in a student's figures",
    start: "Start from a course mechanism", files_of: "Files of", scheme: "Scheme", velocity_plan: "Velocity plan",
    acceleration_plan: "Acceleration plan", forces: "Forces ▸", forces_tip: "the force polygons and the Zhukovsky lever",
    cycle: "Cycle ▸", cycle_tip: "the tables over the cycle as diagrams", cycle_title: "Over the cycle",
    open_designed: "Open the designed scene", designed: "Designed:",
    plans: "◂ Plans", forces_title: "Force polygons and the Zhukovsky lever", quantity: "quantity", segment: "segment",
    mm: "mm", read: "read", exact: "exact", difference: "difference", unit: "unit", where: "where", student: "student",
    error_pct: "error, %", tolerance_pct: "tolerance, %", verdict: "verdict", create: "Create",
    no_files: "No TOML files yet: create one above and save it.", not_saved: "(not saved)", solving: "solving…",
    solved: "solved in", error: "error", not_changed: "not changed", saved: "saved", checking: "checking…",
    checked: "checked", within: "✓ within", off: "✗ off", of: "of", figures_within: "figures within tolerance",
    figures_off: "off", mark: "mark", link: "link", guide: "guide at", at_scale: "(at scale, lengths in mm)",
    not_asked: "(not asked for)", balancing: "balancing", expected_number: "expected a number, got",
    no_answer: "the server does not answer", drawing: "drawing", ready: "ready", building: "building the page…",
    save_first: "save the scene first: a check file names its scene's file", name_needed: "a file name is needed",
    no_forces: "The scene asks for no force analysis (outputs: force_polygons, lever).",
    kinds: {linkage: "linkages", engine: "engines", gears: "gears", cam: "cams", check: "check files", synthesis: "synthesis"},
    sections: {task: "task"},
    note: "Note", note_tip: "the explanatory note (plans note), DOCX", writing_note: "writing the note…",
    structure: "Structure", frame_link: "frame: link", pivots: "fixed pivots", s_links: "links", s_points: "points on links",
    s_joints: "joints", s_driver: "driver", s_branches: "branches of the groups", s_loads: "loads",
    add: "add", remove: "remove", name: "name", axis: "axis", length: "length", along: "along", across: "across",
    s_link: "link", s_links2: "links", s_point: "point", through: "through", angle: "angle", rpm: "n, rpm",
    positions: "positions", group: "group", force: "force", moment: "moment", resisting: "resisting",
    set_driver: "set", guide_of: "guide", at: "at", empty_first: "fill in every field",
    new_scene: "New mechanism (empty)", new_tip: "an empty scene: build it link by link",
    id: "number", kind: "kind", links: "links", point: "point", sign: "±1", undo_tip: "take back the last change",
    file_name: "file name", ratio: "ratio", lengths: {},
    taken: "the number is taken (remove that link first)", ms: "ms"},
  ru: {gallery: "галерея", workbench: "верстак", save: "Сохранить", page: "Страница", check: "Проверка…",
    page_tip: "демонстрационная страница (plans demo)", check_tip: "пустой файл проверки для этой схемы: введите цифры студента",
    start: "Начать с механизма курса", files_of: "Файлы папки", scheme: "Схема", velocity_plan: "План скоростей",
    acceleration_plan: "План ускорений", forces: "Силы ▸", forces_tip: "планы сил и рычаг Жуковского",
    cycle: "Цикл ▸", cycle_tip: "таблицы за цикл в виде диаграмм", cycle_title: "За цикл",
    open_designed: "Открыть спроектированную схему", designed: "Спроектировано:",
    plans: "◂ Планы", forces_title: "Планы сил и рычаг Жуковского", quantity: "величина", segment: "отрезок",
    mm: "мм", read: "по плану", exact: "точно", difference: "разность", unit: "ед.", where: "где", student: "студент",
    error_pct: "ошибка, %", tolerance_pct: "допуск, %", verdict: "итог", create: "Создать",
    no_files: "Файлов TOML пока нет: создайте схему выше и сохраните её.", not_saved: "(не сохранён)",
    solving: "расчёт…", solved: "рассчитано за", error: "ошибка", not_changed: "не изменено", saved: "сохранён",
    checking: "проверка…", checked: "проверено", within: "✓ в допуске", off: "✗ вне допуска", of: "из",
    figures_within: "величин в допуске", figures_off: "вне допуска", mark: "оценка", link: "звено", guide: "направляющая",
    at_scale: "(в масштабе, длины в мм)", not_asked: "(не запрошен)", balancing: "уравновешивающая",
    expected_number: "ожидалось число, введено", no_answer: "сервер не отвечает", drawing: "чертёж", ready: "готов",
    building: "строится страница…", save_first: "сначала сохраните схему: файл проверки ссылается на её файл",
    name_needed: "нужно имя файла", no_forces: "Силовой расчёт в схеме не запрошен (outputs: force_polygons, lever).",
    kinds: {linkage: "механизмы", engine: "двигатели", gears: "зубчатые передачи", cam: "кулачки", check: "файлы проверки", synthesis: "проектирование"},
    sections: {points: "точки стойки", driver: "начальное звено", loads: "нагрузки", branches: "сборки",
      positions: "положения", scales: "масштабы", tolerance: "допуски", cycle: "цикл", dynamics: "динамика",
      task: "задание"},
    note: "Записка", note_tip: "пояснительная записка (plans note), DOCX", writing_note: "пишется записка…",
    structure: "Структура", frame_link: "стойка: звено", pivots: "неподвижные шарниры", s_links: "звенья",
    s_points: "точки звеньев", s_joints: "кинематические пары", s_driver: "начальное звено", s_branches: "сборки групп",
    s_loads: "нагрузки", add: "добавить", remove: "удалить", name: "имя", axis: "ось", length: "длина",
    along: "вдоль", across: "поперёк", s_link: "звено", s_links2: "звенья", s_point: "точка", through: "через",
    angle: "угол", rpm: "n, об/мин", positions: "положений", group: "группа", force: "сила", moment: "момент",
    resisting: "сопротивления", set_driver: "задать", guide_of: "направляющая", at: "в",
    empty_first: "заполните все поля", new_scene: "Новый механизм (пустой)", new_tip: "пустая схема: соберите её звено за звеном",
    id: "номер", kind: "вид", links: "звенья", point: "точка", sign: "±1", undo_tip: "отменить последнее изменение",
    file_name: "имя файла", ratio: "доля длины",
    lengths: {crank: "кривошип", coupler: "шатун", rocker: "коромысло", frame: "стойка", rod: "шатун",
      offset: "эксцентриситет", centre_distance: "межосевое расстояние", guide_height: "высота направляющей",
      coulisse: "кулиса"},
    taken: "номер занят (сначала удалите то звено)", ms: "мс"},
};

export const L = {lang: localStorage.getItem("plans-lang") || ((navigator.language || "").startsWith("ru") ? "ru" : "en")};
export const t = (k) => (WORDS[L.lang][k] !== undefined ? WORDS[L.lang][k] : WORDS.en[k]);

export function setLanguage(lang) {
  L.lang = lang;
  localStorage.setItem("plans-lang", lang);
  translate();
}

export function translate() {
  document.documentElement.lang = L.lang;
  for (const e of document.querySelectorAll("[data-t]")) e.textContent = t(e.dataset.t);
  for (const e of document.querySelectorAll("[data-t-title]")) e.title = t(e.dataset.tTitle);
  for (const e of document.querySelectorAll("[data-t-aria]")) e.setAttribute("aria-label", t(e.dataset.tAria));
  document.getElementById("lang").textContent = L.lang === "ru" ? "EN" : "RU";
}

const RU_UNITS = {"mm": "мм", "m": "м", "kg": "кг", "kg·m²": "кг·м²", "rpm": "об/мин", "rad/s": "рад/с",
  "N or N·m": "Н или Н·м", "N": "Н", "N·m": "Н·м", "Pa": "Па", "SI": "СИ", "m/s": "м/с", "m/s^2": "м/с²",
  "m/s²": "м/с²", "rad/s²": "рад/с²", "mm/N": "мм/Н", "mm/(m/s)": "мм/(м/с)", "mm/(m/s²)": "мм/(м/с²)",
  "rad/s, rad/s²": "рад/с, рад/с²", "rad/s^2": "рад/с²", "(m/s)/mm": "(м/с)/мм", "(m/s²)/mm": "(м/с²)/мм", "N/mm": "Н/мм", "m/mm": "м/мм", "kg*m^2": "кг·м²", "N*m": "Н·м", "J": "Дж", "W": "Вт", "s": "с"};
export const un = (u) => (L.lang === "ru" && RU_UNITS[u] ? RU_UNITS[u] : u);
export const panelName = (nm) => (L.lang !== "ru" ? nm : nm === "crank" ? "начальное звено"
  : nm === "lever" ? "рычаг Жуковского" : nm.replace(/^group /, "группа "));
export const titleOf = (tt, fallback) => (typeof tt === "string" ? tt : (tt && (tt[L.lang] || tt.ru || tt.en)) || fallback);
