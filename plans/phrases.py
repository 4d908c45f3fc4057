"""The sentences of the construction protocol, in English and in Russian.

A step of a plan, a polygon or the lever keeps its sentence as a :class:`Phrase`: a key into
:data:`PHRASES` and the values to put in.  ``Phrase.say(lang)`` writes it in either language
with the same numbers (the same format, a decimal comma in Russian as on the sheets; the
textbook's Russian terms and units; F_bal and M_bal become F_ур and M_ур).  A value may
itself be a phrase, or a list of phrases written one after another.

Format specifications are Python's, plus ``num``: zero up to round-off is 0, else six
significant digits (how the force protocol prints a value).  A field is a plain name with
an optional specification (no conversions, no nested fields): each sentence is parsed once
and then written by joining its pieces, which a table of hundreds of steps feels.
"""

from __future__ import annotations

import re
from _string import formatter_parser  # the parser of str.format and string.Formatter
from collections.abc import Mapping
from typing import Any

import numpy as np

from plans.language import TERMS, UNITS_RU

#: The languages a protocol can be written in.
LANGUAGES = ("en", "ru")

#: key -> (English, Russian).  Fields in braces are the step's values.
PHRASES: dict[str, tuple[str, str]] = {
    # ---- velocity plan
    "v_crank": (
        "v_{A} = ω1·l_{O}{A} = {w:.6g}·{l:.6g} = {v:.6g} m/s; lay off {pole}{a} = {mm:.3f} mm ⟂ {O}{A} "
        "in the sense of ω1 (μv = {mu:.6g} mm/(m/s))",
        "v_{A} = ω1·l_{O}{A} = {w:.6g}·{l:.6g} = {v:.6g} м/с; от полюса {pole} откладываем {pole}{a} = "
        "{mm:.3f} мм ⟂ {O}{A} в сторону вращения ω1 (μv = {mu:.6g} мм/(м/с))"),
    "v_rrr": (
        "v_{B} = v_{A} + v_{B}{A} = v_{C} + v_{B}{C}: line through {n1} ⟂ {A}{B}, line through {n3} ⟂ {C}{B}; "
        "they meet at {out}",
        "v_{B} = v_{A} + v_{B}{A} = v_{C} + v_{B}{C}: через {n1} проводим прямую ⟂ {A}{B}, через {n3} — "
        "прямую ⟂ {C}{B}; точка {out} — их пересечение"),
    "v_rrp": (
        "v_{B} = v_{A} + v_{B}{A}, v_{B}{A} ⟂ {A}{B}, v_{B} ∥ guide: line through {n1} ⟂ {A}{B}, "
        "line through {nq} ∥ guide; they meet at {out}",
        "v_{B} = v_{A} + v_{B}{A}, v_{B}{A} ⟂ {A}{B}, v_{B} ∥ направляющей: через {n1} проводим прямую "
        "⟂ {A}{B}, через {nq} — прямую ∥ направляющей; точка {out} — их пересечение"),
    "v_rpr": (
        "v_{A}{j} = v_{C} + v_{A}{j}{C} (⟂ {C}{A}) = v_{A}{i} + v_{A}{j}{A}{i} (∥ slot): they meet at {out}",
        "v_{A}{j} = v_{C} + v_{A}{j}{C} (⟂ {C}{A}) = v_{A}{i} + v_{A}{j}{A}{i} (∥ кулисе): "
        "точка {out} — пересечение этих прямых"),
    "v_prp": (
        "v_{B} = v_{B}{p} + v_rel ∥ guide of {i} = v_{B}{q} + v_rel ∥ guide of {j}: they meet at {out}",
        "v_{B} = v_{B}{p} + v_r ∥ направляющей {i} = v_{B}{q} + v_r ∥ направляющей {j}: "
        "точка {out} — пересечение этих прямых"),
    "v_rpp": (
        "v_{A}{j} = v_{A}{q} + v_rel ∥ guide = v_{A}{i} + v_rel ∥ slot: they meet at {out}",
        "v_{A}{j} = v_{A}{q} + v_r ∥ направляющей = v_{A}{i} + v_r ∥ кулисе: точка {out} — пересечение этих прямых"),
    "v_triad_s": (
        "Assur's point S (axes {A}{D} and {B}{E} meet), a point of the base link: line through {n1} ⟂ {A}{D}, "
        "line through {n2} ⟂ {B}{E}; they meet at {out}",
        "особая точка Ассура S (пересечение осей {A}{D} и {B}{E}), точка базисного звена: через {n1} проводим "
        "прямую ⟂ {A}{D}, через {n2} — прямую ⟂ {B}{E}; точка {out} — их пересечение"),
    "v_triad_f": (
        "v_{F} = v_S + v_{F}S = v_{C} + v_{F}{C}: line through {s} ⟂ S{F}, line through {n3} ⟂ {C}{F}; they meet at {out}",
        "v_{F} = v_S + v_{F}S = v_{C} + v_{F}{C}: через {s} проводим прямую ⟂ S{F}, через {n3} — прямую ⟂ {C}{F}; "
        "точка {out} — их пересечение"),
    "v_triad_sg": (
        "Assur's point S ({ax1} and {ax2} meet), a point of the base link: line through {n1} {l1}, line through "
        "{n2} {l2}; they meet at {out}",
        "особая точка Ассура S (пересечение: {ax1} и {ax2}), точка базисного звена: через {n1} проводим прямую "
        "{l1}, через {n2} — прямую {l2}; точка {out} — их пересечение"),
    "v_triad_fg": (
        "v_{F} = v_S + v_{F}S: line through {s} ⟂ S{F}, line through {n3} {l3}; they meet at {out}",
        "v_{F} = v_S + v_{F}S: через {s} проводим прямую ⟂ S{F}, через {n3} — прямую {l3}; "
        "точка {out} — их пересечение"),
    "t_axis_leash": ("the axis {A}{D}", "ось {A}{D}"),
    "t_axis_guide": ("the normal to the guide at {F}", "нормаль к направляющей в точке {F}"),
    "t_perp": ("⟂ {A}{D}", "⟂ {A}{D}"),
    "t_par_guide": ("∥ guide of {F}", "∥ направляющей {F}"),
    "t_axis_slot": ("the normal to the slot of link {j} at {C}", "нормаль к кулисе звена {j} в точке {C}"),
    "t_par_slot": ("∥ slot of link {j}", "∥ кулисе звена {j}"),
    "similarity": (
        "{lb}: similarity theorem on link {link} ({name} of link {link} from {ref})",
        "{lb}: по теореме подобия на звене {link} (точка {name} звена {link} от {ref})"),
    "coincident": (
        "{lb}: image of the point of link {link} under {name} (similarity theorem)",
        "{lb}: изображение точки звена {link}, совпадающей с {name} (теорема подобия)"),
    "coincide": ("{name} coincides with {same}", "{name} совпадает с {same}"),
    # ---- acceleration plan
    "a_crank_n": (
        "a_{A}^n = ω1²·l_{O}{A} = {an:.6g} m/s²: {mm:.3f} mm from {A} toward {O} (μa = {mu:.6g} mm/(m/s²))",
        "нормальное ускорение a_{A}^n = ω1²·l_{O}{A} = {an:.6g} м/с²: откладываем {mm:.3f} мм ∥ {O}{A}, "
        "в направлении от {A} к {O} (μa = {mu:.6g} мм/(м/с²))"),
    "a_crank_t": (
        "a_{A}^τ = ε1·l_{O}{A} = {at:.6g} m/s²: {mm:.3f} mm ⟂ {O}{A}",
        "касательное ускорение a_{A}^τ = ε1·l_{O}{A} = {at:.6g} м/с²: откладываем {mm:.3f} мм ⟂ {O}{A}"),
    "a_crank": (
        "a_{A} = a_{A}^n = ω1²·l_{O}{A} = {an:.6g} m/s² (ε1 = 0): {mm:.3f} mm from {A} toward {O} "
        "(μa = {mu:.6g} mm/(m/s²))",
        "a_{A} = a_{A}^n = ω1²·l_{O}{A} = {an:.6g} м/с² (ε1 = 0): от полюса откладываем {mm:.3f} мм ∥ {O}{A}, "
        "в направлении от {A} к {O} (μa = {mu:.6g} мм/(м/с²))"),
    "a_normal": (
        "a_{X}{P}^n = v_{X}{P}²/l_{P}{X} = {v:.5g}²/{l:.5g} = {an:.6g} m/s²: {mm:.3f} mm from {frm} "
        "parallel to {X}{P}, from {X} toward {P}",
        "нормальное ускорение a_{X}{P}^n = v_{X}{P}²/l_{P}{X} = {v:.5g}²/{l:.5g} = {an:.6g} м/с²: от {frm} "
        "откладываем {mm:.3f} мм ∥ {X}{P}, в направлении от {X} к {P}"),
    "a_coriolis": (
        "a^k_{label} = 2·ω{g}·v_r = 2·{w:.5g}·{v:.5g} = {ak:.6g} m/s²: {mm:.3f} mm, "
        "v_r turned 90° in the sense of ω{g}",
        "кориолисово ускорение a^k_{label} = 2·ω{g}·v_r = 2·{w:.5g}·{v:.5g} = {ak:.6g} м/с²: {mm:.3f} мм, "
        "вектор v_r повёрнут на 90° в сторону ω{g}"),
    "a_triad_s": (
        "a_S: line ⟂ {A}{D} through {m1} and line ⟂ {B}{E} through {m2} (after the normal terms) meet at {out}",
        "a_S: через {m1} проводим прямую ⟂ {A}{D}, через {m2} — прямую ⟂ {B}{E} (после нормальных ускорений); "
        "точка {out} — их пересечение"),
    "a_triad_sg": (
        "a_S: line {l1} through {m1} and line {l2} through {m2} (after the normal terms) meet at {out}",
        "a_S: через {m1} проводим прямую {l1}, через {m2} — прямую {l2} (после нормальных ускорений); "
        "точка {out} — их пересечение"),
    "a_triad_fg": (
        "a_{F}S^τ ⟂ S{F} through {ms} and the line {l3} through {m3} meet at {out}",
        "через {ms} проводим прямую a_{F}S^τ ⟂ S{F}, через {m3} — прямую {l3}; точка {out} — их пересечение"),
    "a_triad_f": (
        "a_{F}S^τ ⟂ S{F} through {ms} and a_{F}{C}^τ ⟂ {C}{F} through {m3} meet at {out}",
        "через {ms} проводим прямую a_{F}S^τ ⟂ S{F}, через {m3} — прямую a_{F}{C}^τ ⟂ {C}{F}; "
        "точка {out} — их пересечение"),
    "a_rrr": (
        "a_{B}{A}^τ ⟂ {A}{B} through {m1} and a_{B}{C}^τ ⟂ {C}{B} through {m3} meet at {out}",
        "через {m1} проводим прямую a_{B}{A}^τ ⟂ {A}{B}, через {m3} — прямую a_{B}{C}^τ ⟂ {C}{B}; "
        "точка {out} — их пересечение"),
    "a_rrp": (
        "line through {m1} ⟂ {A}{B} (a_{B}{A}^τ) and line through {start} ∥ guide meet at {out}",
        "через {m1} проводим прямую ⟂ {A}{B} (a_{B}{A}^τ), через {start} — прямую ∥ направляющей; "
        "точка {out} — их пересечение"),
    "a_rpr": (
        "a_{An}{C}^τ ⟂ {C}{A} through {mc} and a^r ∥ slot through {mk} meet at {out}",
        "через {mc} проводим прямую a_{An}{C}^τ ⟂ {C}{A}, через {mk} — прямую a^r ∥ кулисе; "
        "точка {out} — их пересечение"),
    "a_prp": (
        "line through {e0} ∥ guide of link {i} and line through {e1} ∥ guide of link {j} meet at {out}",
        "через {e0} проводим прямую ∥ направляющей звена {i}, через {e1} — прямую ∥ направляющей звена {j}; "
        "точка {out} — их пересечение"),
    "a_rpp": (
        "line through {s3} ∥ guide of link {j} and line through {s2} ∥ slot meet at {out}",
        "через {s3} проводим прямую ∥ направляющей звена {j}, через {s2} — прямую ∥ кулисе; "
        "точка {out} — их пересечение"),
    # ---- force polygons
    "f_lay": ("From {start} lay off {label} = {F:.6g} N as {start}{end} = {mm:.1f} mm.",
              "От {start} откладываем {label} = {F:.6g} Н отрезком {start}{end} = {mm:.1f} мм."),
    "f_meet": (
        "Through {end} draw the line of {le}, through {start} the line of {ls}; they meet at {xn}: "
        "{le} = {end}{xn}, {ls} = {xn}{start}.",
        "Через {end} проводим линию действия {le}, через {start} — линию действия {ls}; точка {xn} — "
        "их пересечение: {le} = {end}{xn}, {ls} = {xn}{start}."),
    "f_close": ("{label} = {a}{to} closes the polygon.", "{label} = {a}{to} замыкает силовой многоугольник."),
    "f_join": ("{label} = {a}{b} ({why}).", "{label} = {a}{b} ({why})."),
    "f_sum": ("{x}", "{x}"),
    "f_closes_link": ("closes the polygon of link {i}", "замыкает многоугольник сил звена {i}"),
    # ---- moment equations (the force protocol)
    "m_term_force": ("{sign}{label}·h (h = {mm:.2f} mm: {F:num} N × {h:num} m = {M:num} N·m)",
                     "{sign}{label}·h (h = {mm:.2f} мм: {F:num} Н × {h:num} м = {M:num} Н·м)"),
    "m_term_couple": ("{sign}{label} ({M:num} N·m)", "{sign}{label} ({M:num} Н·м)"),
    "m_equation": (
        "{name} = 0: {known}; known moments sum to {total:num} N·m (ccw +), so {unknown}.",
        "уравнение моментов {name} = 0: {known}; сумма моментов известных сил {total:num} Н·м "
        "(против часовой стрелки +), отсюда {unknown}."),
    "m_zero": ("0", "0"),
    "m_tau": ("{n}^τ · l_{A}{B} ({l:.5g} m) balances them: {n}^τ = {tau:num} N",
              "{n}^τ · l_{A}{B} ({l:.5g} м) их уравновешивает: {n}^τ = {tau:num} Н"),
    "m_guide": ("the guide's couple is {M:num} N·m: {n} acts {mm:.2f} mm from {B} along the guide",
                "момент пары в направляющей {M:num} Н·м: {n} приложена в {mm:.2f} мм от {B} вдоль направляющей"),
    "m_slot_couple": ("the slot's couple on the block is {M:num} N·m", "момент пары кулисы на камне {M:num} Н·м"),
    "m_slot": ("{n} ⟂ the slot, its arm {mm:.2f} mm: |{n}| = {F:num} N",
               "{n} ⟂ кулисе, её плечо {mm:.2f} мм: |{n}| = {F:num} Н"),
    "m_name": ("{n}", "{n}"),
    "m_couple_of": ("the couple of {n} is {M:num} N·m", "момент пары {n} равен {M:num} Н·м"),
    "m_triad_n": (
        "S is where the axes {A}{D} and {B}{E} meet ({n1}^n and {n2}^n pass through it); {n}^n along {C}{F}, its arm "
        "h = {mm:.2f} mm ({h:.5g} m), balances them: {n}^n = {N:num} N",
        "S — точка пересечения осей {A}{D} и {B}{E} (через неё проходят {n1}^n и {n2}^n); {n}^n вдоль {C}{F} "
        "с плечом h = {mm:.2f} мм ({h:.5g} м) их уравновешивает: {n}^n = {N:num} Н"),
    "f_block_tau": (
        "ΣF = 0 along the slot of link {j} for block {k}: {n}^τ (∥ the slot) = {tau:num} N",
        "ΣF = 0 вдоль кулисы звена {j} для камня {k}: {n}^τ (∥ кулисе) = {tau:num} Н"),
    "m_triad_ng": (
        "S is where {ax1} and {ax2} meet ({n1} and {n2} pass through it); {n} along {ax3}, its arm "
        "h = {mm:.2f} mm ({h:.5g} m), balances them: {n} = {N:num} N",
        "S — точка пересечения: {ax1} и {ax2} (через неё проходят {n1} и {n2}); {n} вдоль: {ax3}, "
        "с плечом h = {mm:.2f} мм ({h:.5g} м) их уравновешивает: {n} = {N:num} Н"),
    "m_crank_force": (
        "F_bal ⟂ O{pt} with the arm l = {mm:.2f} mm ({l:.5g} m) balances them: F_bal = {F:num} N "
        "along the motion of {pt}",
        "уравновешивающая сила F_bal ⟂ O{pt} с плечом l = {mm:.2f} мм ({l:.5g} м) их уравновешивает: "
        "F_bal = {F:num} Н по направлению движения точки {pt}"),
    "m_crank_moment": ("the balancing moment is M_bal = {M:num} N·m along ω1",
                       "уравновешивающий момент M_bal = {M:num} Н·м по направлению ω1"),
    # ---- the Zhukovsky lever
    "l_turn": ("Turn the velocity plan 90° {sense} about the pole p (μv = {mu:g} mm/(m/s)).",
               "Рычаг Жуковского: поворачиваем план скоростей на 90° {sense} вокруг полюса p "
               "(μv = {mu:g} мм/(м/с))."),
    "ccw": ("ccw", "против часовой стрелки"),
    "cw": ("cw", "по часовой стрелке"),
    "l_apply": ("Apply {label} = {F:.4g} N at {pt} parallel to itself; arm h = {h:.2f} mm from p.",
                "Переносим {label} = {F:.4g} Н в точку {pt} параллельно самой себе; плечо h = {h:.2f} мм "
                "относительно полюса p."),
    "l_result": ("ΣM_p = 0 gives F_bal = {F:.6g} {unit} at {pt}.",
                 "Из ΣM_p = 0 уравновешивающая сила F_bal = {F:.6g} {unit} в точке {pt}."),
    "l_term": ("{sign}{label}·h_{pt} ({F:num} N × {h:.2f} mm)", "{sign}{label}·h_{pt} ({F:num} Н × {h:.2f} мм)"),
    "l_arm": (" × {a:.2f} mm", " × {a:.2f} мм"),
    "l_equation": (
        "ΣM_p = 0 on the lever: {terms} + F_bal·h_{pt}{arm} = 0, so F_bal = {F:num} {unit} "
        "(by power balance {P:num} {unit}).",
        "ΣM_p = 0 на рычаге Жуковского: {terms} + F_bal·h_{pt}{arm} = 0, отсюда F_bal = {F:num} {unit} "
        "(по балансу мощностей {P:num} {unit})."),
    "nothing": ("", ""),
    # ---- classic mistakes (the demonstration)
    "x_moved": (
        "{why} Point {name} moves by {d:.1f} mm on the drawing: |p{name}| = {w:.5g} {unit} instead of "
        "{r:.5g} {unit} ({pct}).",
        "{why} Точка {name} смещается на чертеже на {d:.1f} мм: |p{name}| = {w:.5g} {unit} вместо "
        "{r:.5g} {unit} ({pct})."),
    "x_pct": ("{p:+.2f} %", "{p:+.2f} %"),
    "x_diff": ("{d:+.4g}", "{d:+.4g}"),
    "x_coriolis": (
        "The Coriolis acceleration {label} laid off the wrong way round (ω of the guide not turned 90° in its "
        "own sense).",
        "Кориолисово ускорение {label} отложено в обратную сторону (вектор v_r повёрнут на 90° против "
        "направления ω кулисы)."),
    "x_normal": ("The normal component {label} laid off from the pole {pole} instead of from {frm}.",
                 "Нормальная составляющая {label} отложена от полюса {pole}, а не от точки {frm}."),
    "x_couple": (
        "The inertia couple {label} put on the lever in the sense of the angular acceleration instead of "
        "against it: F_bal = {w:.5g} {unit} instead of {r:.5g} {unit} ({pct}).",
        "Момент сил инерции {label} приложен к рычагу по направлению углового ускорения, а не против него: "
        "F_bal = {w:.5g} {unit} вместо {r:.5g} {unit} ({pct})."),
    "x_pi": (
        "ω1 = πn/30 computed with π = 3.14: ω1 = {w:.5g} rad/s instead of {r:.5g} rad/s, so v_{A} = {vw:.5g} m/s "
        "instead of {vr:.5g} m/s ({pct}), every acceleration {pct2}.",
        "ω1 = πn/30 вычислена при π = 3,14: ω1 = {w:.5g} рад/с вместо {r:.5g} рад/с, поэтому v_{A} = {vw:.5g} м/с "
        "вместо {vr:.5g} м/с ({pct}), все ускорения {pct2}."),
    "x_pi_force": (" F_bal = {w:.5g} {unit} instead of {r:.5g} {unit} ({pct}).",
                   " F_bal = {w:.5g} {unit} вместо {r:.5g} {unit} ({pct})."),
}

PHRASES.update(TERMS)  # the terminal's lines: one catalogue, written one way


_BAL = r"\b([FM])_bal\b"  # F_bal, M_bal as words (compiled by ``re`` when Russian is first written)


class Phrase:
    """A sentence not yet written: a key of :data:`PHRASES` and its values."""

    __slots__ = ("args", "key")

    def __init__(self, key: str, args: Mapping[str, Any]) -> None:
        if key not in PHRASES:
            _terminal()
            if key not in PHRASES:
                raise KeyError(key)
        self.key, self.args = key, dict(args)

    def say(self, lang: str = "en") -> str:
        ru = lang == "ru"
        args = self.args
        out = []
        for literal, name, spec in _pieces(self.key, ru):
            out.append(literal)
            if name is not None:
                value = args[name]
                if ru and name.startswith("unit") and isinstance(value, str):
                    value = UNITS_RU.get(value, value)
                out.append(_field(value, spec, lang))
        text = "".join(out)
        return re.sub(_BAL, r"\1_ур", text) if ru else text

    def __str__(self) -> str:
        return self.say("en")

    def __repr__(self) -> str:
        return f"Phrase({self.key!r}, {self.args!r})"


def _terminal() -> None:
    """The renderer's, the group's and the bench's terminal lines (:mod:`plans.messages_terminal`,
    :mod:`plans.messages_bench`), read the first time one is written."""
    from plans.messages_bench import BENCH
    from plans.messages_terminal import TERMINAL

    TERMS.update(TERMINAL)
    PHRASES.update(TERMINAL)
    PHRASES.update(BENCH)


def phrase(key: str, **args: Any) -> Phrase:
    return Phrase(key, args)


def say(key: str, lang: str = "en", **args: Any) -> str:
    """A line of the catalogue written at once in ``lang``."""
    return Phrase(key, args).say(lang)


def number(x: Any, spec: str = "", lang: str = "en") -> str:
    """One value as a protocol writes it (``spec`` as in a phrase; decimal comma in Russian)."""
    if spec == "num":
        s = "0" if abs(float(x)) < 1e-12 else f"{float(x):.6g}"
    else:
        s = format(x, spec)
    return s.replace(".", ",") if lang == "ru" else s


#: (key, Russian?) -> the sentence's pieces: (text before a field, the field's name or None, its spec)
_PIECES: dict[tuple[str, bool], list[tuple[str, str | None, str]]] = {}


def _pieces(key: str, ru: bool) -> list[tuple[str, str | None, str]]:
    got = _PIECES.get((key, ru))
    if got is None:
        got = []
        for literal, name, spec, conversion in formatter_parser(PHRASES[key][1 if ru else 0]):
            if name is not None and (conversion or not name.isidentifier() or "{" in (spec or "")):
                raise ValueError(f"phrase {key!r}: field {{{name}}} is not a plain name with a format spec")
            got.append((literal, name, spec or ""))
        _PIECES[(key, ru)] = got
    return got


def _field(value: Any, spec: str, lang: str) -> str:
    """One field written: a phrase in the same language, a list of them one after another,
    a number as :func:`number` writes it, anything else by ``format``."""
    if isinstance(value, Phrase):
        return value.say(lang)
    if isinstance(value, list | tuple):
        return " ".join(_field(v, spec, lang) for v in value)
    if isinstance(value, float | int | np.floating | np.integer) and not isinstance(value, bool):
        return number(value, spec, lang)
    return format(value, spec)


__all__ = ["LANGUAGES", "PHRASES", "UNITS_RU", "Phrase", "number", "phrase", "say"]
