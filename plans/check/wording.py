"""The words of the check's findings, in English (the report) and Russian (the marked sheet).

A finding keeps what it says as a :class:`Words`: a sentence key and its parts, each part
tagged by what it is (a quantity, a computed number, a figure as the student wrote it, a
unit, a plan, a formula, literal text), so each language writes numbers, units and
quantity names its own way (``M_Phi_2`` typeset as M_Φ2 on a sheet, a decimal comma in
Russian) from one source.
"""

from __future__ import annotations

import re
from collections.abc import Callable
from dataclasses import dataclass
from typing import Any

SENTENCES: dict[str, tuple[str, str]] = {  # key: (English, Russian)
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
    "pi_rounded": ("π = 3.14", "π = 3,14"),
    "g_rounded": ("g = 10", "g = 10"),
    "arithmetic": ("an arithmetic slip", "ошибка в вычислении"),
}
PLANS_RU = {"velocity": "скоростей", "acceleration": "ускорений"}  # "план скоростей": genitive
UNITS_RU = {"m/s": "м/с", "m/s^2": "м/с²", "rad/s": "рад/с", "rad/s^2": "рад/с²", "N": "Н", "N m": "Н·м",
            "N·m": "Н·м", "N*m": "Н·м", "mm": "мм", "m": "м", "kg": "кг", "kg m^2": "кг·м²", "kg·m^2": "кг·м²",
            "kg*m^2": "кг·м²", "%": "%", "unit": "ед."}
_NAME = re.compile(r"(?<![\w])([A-Za-zΑ-Ωα-ω]+)_([A-Za-z0-9_]+)(?:\^[nτk])?")
_DECIMAL = re.compile(r"(\d)\.(\d)")
_NOTE = re.compile(r"(\([^)]*\))")


@dataclass(frozen=True, slots=True)
class Part:
    """One part of a sentence: ``tag`` says how each language writes ``value``:
    q quantity key, n computed number (``spec`` a format, "" four digits), w figure as
    written, x how the student got a figure, u unit, p plan kind, f formula, t literal text,
    s a sentence, j a list joined by "and"."""

    tag: str
    value: Any
    spec: str = ""


def q(name: str) -> Part:
    return Part("q", name)


def n(x: float, spec: str = "") -> Part:
    return Part("n", float(x), spec)


def w(text: str) -> Part:
    return Part("w", text)


def u(unit: str) -> Part:
    return Part("u", unit)


def t(text: str) -> Part:
    return Part("t", text)


def x(text: str) -> Part:
    return Part("x", text)


def plan(kind: str) -> Part:
    return Part("p", kind)


def formula(text: str) -> Part:
    return Part("f", text)


@dataclass(frozen=True, slots=True)
class Words:
    """A sentence: its key in :data:`SENTENCES` and its parts by field name."""

    key: str
    parts: tuple[tuple[str, Part], ...]

    def render(self, lang: str = "en", name: Callable[[str], str] | None = None) -> str:
        """The sentence in ``lang``; ``name`` writes a quantity key (default: the key itself)."""
        en, ru = SENTENCES[self.key]
        return (ru if lang == "ru" else en).format(**{k: _part(p, lang, name) for k, p in self.parts})


def say(key: str, **parts: Part | Words | str | list | tuple[str, list]) -> Words:
    """``say("pi", phi=n(45, "g"), q=q("omega_1"), ...)``; a plain string is literal text,
    a Words a nested sentence, a list a list joined by "and" (a list of one tuple
    ``(", ", [...])`` is joined by that separator)."""
    out = []
    for k, v in parts.items():
        if isinstance(v, Words):
            v = Part("s", v)
        elif isinstance(v, str):
            v = Part("t", v)
        elif isinstance(v, list):
            v = Part("j", tuple(x if isinstance(x, Part | Words) else Part("t", x) for x in v))
        elif isinstance(v, tuple):
            sep, items = v
            v = Part("j", tuple(items), sep)
        out.append((k, v))
    return Words(key, tuple(out))


def plain_number(x: float, spec: str = "") -> str:
    """A computed number, four significant digits (whole numbers above 10 000)."""
    if spec:
        return format(x, spec)
    if x == 0:
        return "0"
    if abs(x) >= 1e4:
        return f"{x:.0f}"
    return f"{x:.4g}"


def _part(p: Part | Words, lang: str, name: Callable[[str], str] | None) -> str:
    ru = lang == "ru"
    if isinstance(p, Words):
        return p.render(lang, name)
    if p.tag == "q":
        return name(p.value) if name else p.value
    if p.tag == "n":
        s = plain_number(p.value, p.spec)
        return s.replace(".", ",") if ru else s
    if p.tag == "w":
        return _DECIMAL.sub(r"\1,\2", p.value, count=1) if ru else p.value
    if p.tag == "x":  # how the student got a figure: "60 mm (3.2) / 6.58", "68.32 (exact)"
        if not ru:
            return p.value
        bits = _NOTE.split(p.value)  # the notes in brackets are section numbers: kept as written
        text = "".join(b if b.startswith("(") else _DECIMAL.sub(r"\1,\2", b) for b in bits)
        return text.replace(" mm", " мм").replace("(exact)", "(точно)")
    if p.tag == "u":
        return UNITS_RU.get(p.value, p.value) if ru else p.value
    if p.tag == "p":
        return PLANS_RU.get(p.value, p.value) if ru else p.value
    if p.tag == "f":
        text = p.value.replace("(Coriolis)", "(кориолисово)") if ru else p.value
        return _NAME.sub(lambda m: name(m.group(0)), text) if name else text
    if p.tag == "s":
        return p.value.render(lang, name)
    if p.tag == "j":
        items = [_part(x, lang, name) for x in p.value]
        sep = p.spec or (" и " if ru else " and ")
        return sep.join(items)
    return str(p.value)


__all__ = ["KINDS_RU", "UNITS_RU", "Part", "SENTENCES", "Words", "formula", "n", "plan", "q", "say", "t", "u", "w", "x"]
