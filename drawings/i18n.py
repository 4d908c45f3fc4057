"""Words on the sheet, in Russian and English."""

from __future__ import annotations

from collections.abc import Callable

WORDS: dict[str, tuple[str, str]] = {
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


def lookup(table: dict[str, tuple[str, str]]) -> Callable[[str, str], str]:
    """``tr(key, lang)`` over a table of (Russian, English) words: each sheet module keeps its
    own words and reads them the same way."""

    def tr(key: str, lang: str) -> str:
        ru, en = table[key]
        return ru if lang == "ru" else en

    return tr


tr = lookup(WORDS)
