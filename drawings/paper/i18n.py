"""Words on the sheet, in Russian and English (kept with every other phrase in
:mod:`plans.language`)."""

from __future__ import annotations

from collections.abc import Callable

from plans.language import SHEET_WORDS

WORDS = SHEET_WORDS


def lookup(table: dict[str, tuple[str, str]]) -> Callable[[str, str], str]:
    """``tr(key, lang)`` over a table of (Russian, English) words: each sheet module keeps its
    own words and reads them the same way."""

    def tr(key: str, lang: str) -> str:
        ru, en = table[key]
        return ru if lang == "ru" else en

    return tr


tr = lookup(WORDS)
