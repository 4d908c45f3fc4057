"""The note's words in Russian and English, and the course's symbols in each."""

from __future__ import annotations

import re

from .model import Formula, Sym

#: key -> (Russian, English)
WORDS: dict[str, tuple[str, str]] = {
    "note": ("ПОЯСНИТЕЛЬНАЯ ЗАПИСКА", "EXPLANATORY NOTE"),
    "to_project": ("к курсовому проекту по теории механизмов и машин",
                   "to the course project in the theory of machines and mechanisms"),
    "contents": ("СОДЕРЖАНИЕ", "CONTENTS"),
    "author": ("Выполнил", "Done by"),
    "group": ("Группа", "Group"),
    "checked": ("Проверил", "Checked by"),
    "designation": ("Обозначение", "Designation"),
    "task": ("Задание и исходные данные", "The task and its data"),
    "structure": ("Структурный анализ механизма", "Structural analysis of the mechanism"),
    "design": ("Проектирование механизма", "Design of the mechanism"),
    "kinematics": ("Кинематический анализ механизма", "Kinematic analysis of the mechanism"),
    "forces": ("Силовой анализ механизма", "Force analysis of the mechanism"),
    "dynamics": ("Динамика машины и маховик", "Machine dynamics and the flywheel"),
    "diagrams": ("Кинематические диаграммы", "Kinematic diagrams"),
    "gears": ("Зубчатые передачи", "Gears"),
    "cams": ("Кулачковый механизм", "Cam mechanism"),
    "balancing": ("Уравновешивание двигателя", "Balancing of the engine"),
    "conclusions": ("Заключение", "Conclusions"),
    "link": ("Звено", "Link"),
    "points": ("Точки", "Points"),
    "length": ("Длина, м", "Length, m"),
    "mass": ("Масса, кг", "Mass, kg"),
    "inertia": ("I_S, кг·м²", "I_S, kg·m²"),
    "quantity": ("Величина", "Quantity"),
    "segment": ("Отрезок", "Segment"),
    "mm": ("Длина, мм", "Length, mm"),
    "value": ("Значение", "Value"),
    "unit": ("Ед.", "Unit"),
    "position": ("Положение", "Position"),
    "phi": ("φ, °", "φ, °"),
    "reaction": ("Реакция", "Reaction"),
    "force_N": ("Модуль, Н", "Magnitude, N"),
    "by_kin": ("по планам сил", "by the force polygons"),
    "by_lever": ("по рычагу Жуковского", "by the Zhukovsky lever"),
    "by_power": ("по балансу мощностей", "by the power balance"),
    "diff": ("Расхождение, %", "Difference, %"),
    "gear": ("Колесо", "Gear"),
    "mesh": ("Передача", "Pair"),
}

UNITS: dict[str, tuple[str, str]] = {
    "m": ("м", "m"), "m^2": ("м²", "m²"), "mm": ("мм", "mm"), "m/s": ("м/с", "m/s"), "m/s^2": ("м/с²", "m/s²"),
    "rad/s": ("рад/с", "rad/s"), "rad/s^2": ("рад/с²", "rad/s²"), "N": ("Н", "N"), "N*m": ("Н·м", "N·m"),
    "N·m": ("Н·м", "N·m"), "N*mm": ("Н·мм", "N·mm"), "kg*m^2": ("кг·м²", "kg·m²"), "kg": ("кг", "kg"), "J": ("Дж", "J"),
    "mm/(m/s)": ("мм/(м/с)", "mm/(m/s)"), "mm/(m/s^2)": ("мм/(м/с²)", "mm/(m/s²)"), "mm/N": ("мм/Н", "mm/N"),
    "mm/m": ("мм/м", "mm/m"), "deg": ("°", "°"), "rpm": ("об/мин", "rpm"), "mm/rad": ("мм/рад", "mm/rad"),
    "mm/(N*m)": ("мм/(Н·м)", "mm/(N·m)"), "mm/J": ("мм/Дж", "mm/J"), "mm/(kg*m^2)": ("мм/(кг·м²)", "mm/(kg·m²)"),
    "%": ("%", "%"), "": ("", ""),
}


def w(key: str, lang: str) -> str:
    ru, en = WORDS[key]
    return ru if lang == "ru" else en


def unit(u: str, lang: str) -> str:
    ru, en = UNITS.get(u, (u, u))
    return ru if lang == "ru" else en


def say(lang: str, ru: str, en: str) -> str:
    return ru if lang == "ru" else en


_PHI = re.compile(r"(?<![A-Za-z])Phi(?=\d)")
_BAL = re.compile(r"\b([FM])_bal\b")


def symbols(text: str, lang: str) -> str:
    """A protocol's sentence with the course's symbols: Φ for an inertia force, F_ур and
    M_ур for the balancing force and moment in Russian."""
    text = _PHI.sub("Φ", text)
    return _BAL.sub(r"\1_ур", text) if lang == "ru" else text


_GREEK = {"omega": "ω", "eps": "ε", "Phi": "Φ", "phi": "φ", "alpha": "α", "delta": "δ"}


def quantity(name: str, lang: str = "en") -> Formula:
    """A reading's name as a symbol: ``v_BA`` → v with BA, ``omega_2`` → ω₂, ``a_BA^n`` → a^n_BA,
    ``F_bal`` → F_ур in Russian."""
    base, _, rest = name.partition("_")
    sub, _, sup = rest.partition("^")
    base = _GREEK.get(base, base)
    if sub == "bal":
        sub = "ур" if lang == "ru" else "bal"
    return Sym(base, sub or None, sup or None)
