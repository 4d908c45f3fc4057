"""The course's notation of the plans, chosen by the scene and resolved per sheet language.

* A scale's letter and direction, chosen apart: ``[scales] symbol = "mu" | "K"`` and
  ``[scales] direction = "m/mm" | "mm/m"`` (m/mm: units per millimetre, μ_l = 0,002 м/мм as
  Russian courses write it; mm/m: millimetres per unit).  ``[scales] style = "mu"`` (μ in
  mm/m) and ``"K"`` (K in m/mm) keep their meaning and set both at once.  Nothing given: μ
  in m/mm on a Russian sheet, μ in mm/m in English; a K alone runs m/mm.
* The acceleration pole: ``[sheet] acceleration_pole = "π" | "p_a"``; by default π in
  Russian (the textbooks' letter), p_a in English.

The scene keeps what it was given as one short token (:attr:`plans.scene.Scene.scale_style`,
``symbol|direction|pole`` with empty parts left to the language, or the old "mu"/"K");
:func:`resolve` turns it into what a sheet or a protocol in one language writes.
"""

from __future__ import annotations

from typing import Any

from plans.errors import Said

SYMBOLS = ("mu", "K")
DIRECTIONS = ("m/mm", "mm/m")
POLES = {"π": "π", "pi": "π", "p_a": "p_a"}


def read(r: Any, scales: dict[str, Any], sheet: Any) -> str:
    """The token of ``[scales]`` (style, symbol, direction) and ``[sheet] acceleration_pole``."""
    style = scales.get("style")
    given = [k for k in ("symbol", "direction") if k in scales]
    if style is not None and given:
        raise r.fail(f"scales.{given[0]}", Said("sn_give_style_mu"))
    if style is not None:
        sym = r.choice(scales, "style", "scales.", SYMBOLS, "mu")
        direction = "mm/m" if sym == "mu" else "m/mm"
    else:
        sym = r.choice(scales, "symbol", "scales.", SYMBOLS, "mu") if "symbol" in scales else ""
        direction = r.choice(scales, "direction", "scales.", DIRECTIONS, "m/mm") if "direction" in scales else ""
    pole = ""
    if isinstance(sheet, dict) and "acceleration_pole" in sheet:
        got = sheet["acceleration_pole"]
        if not isinstance(got, str) or got not in POLES:
            raise r.fail("sheet.acceleration_pole", Said("sn_pi", got=got))
        pole = POLES[got]
    return f"{sym}|{direction}|{pole}"


def resolve(style: str, lang: str) -> tuple[str, bool, str]:
    """(the scale's letter "μ" or "K", True where it runs units per mm, the acceleration
    pole's label) for a sheet or a protocol in ``lang``."""
    if style in SYMBOLS:  # the old two-way style: μ in mm/m, K in m/mm
        sym, direction, pole = style, "mm/m" if style == "mu" else "m/mm", ""
    else:
        sym, direction, pole = (style.split("|") + ["", "", ""])[:3]
    ru = lang == "ru"
    sym = sym or "mu"
    direction = direction or ("m/mm" if sym == "K" or ru else "mm/m")
    return ("μ" if sym == "mu" else "K"), direction == "m/mm", pole or ("π" if ru else "p_a")


def pole_label(name: str, style: str, lang: str) -> str:
    """A plan point's name as the sheet writes it: the acceleration pole per the notation."""
    return resolve(style, lang)[2] if name == "p_a" else name


_UNITS_RU = {"N/mm": "Н/мм", "m/mm": "м/мм", "(m/s)/mm": "(м/с)/мм", "(m/s^2)/mm": "(м/с²)/мм",
             "mm/N": "мм/Н", "mm/m": "мм/м", "mm/(m/s)": "мм/(м/с)", "mm/(m/s^2)": "мм/(м/с²)"}
_PER_MM = {"mm/N": "N/mm", "mm/m": "m/mm", "mm/(m/s)": "(m/s)/mm", "mm/(m/s^2)": "(m/s^2)/mm"}


def scale_words(style: str, lang: str, sub: str, mu: float, mm_per: str) -> str | None:
    """``μF = 25 Н/мм`` as the notation writes a scale of ``mu`` mm per unit in a protocol's
    line; None where it is the old μ in mm per unit (the caller's own phrase then)."""
    letter, per_mm, _ = resolve(style, lang)
    if not per_mm and letter == "μ":
        return None
    from plans.phrases import number

    value, unit = (1.0 / mu, _PER_MM[mm_per]) if per_mm else (mu, mm_per)
    return f"{letter}{sub} = {number(value, 'g', lang)} {_UNITS_RU[unit] if lang == 'ru' else unit}"
