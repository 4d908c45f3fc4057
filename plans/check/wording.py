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

from plans.language import CAUSES, CHECK_TERMS, KINDS_RU, PLANS_RU, UNITS_RU
from plans.language import CHECK_SENTENCES as SENTENCES

_NAME = re.compile(r"(?<![\w])([A-Za-zΑ-Ωα-ω]+)_([A-Za-z0-9_]+)(?:\^[nτk])?")
_DECIMAL = re.compile(r"(\d)\.(\d)")
_NOTE = re.compile(r"(\([^)]*\))")


@dataclass(frozen=True, slots=True)
class Part:
    """One part of a sentence: ``tag`` says how each language writes ``value``:
    q quantity key, n computed number (``spec`` a format, "" four digits), w figure as
    written, x how the student got a figure, u unit, p plan kind, f formula, t literal text,
    s a sentence, z a sentence without its position, j a list joined by "and"."""

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


def tail(words: Words) -> Part:
    """A finding's sentence without its position ("φ = 45°: "), as a cause quotes it."""
    return Part("z", words)


def plan(kind: str) -> Part:
    return Part("p", kind)


def formula(text: str) -> Part:
    return Part("f", text)


@dataclass(frozen=True, slots=True)
class Words:
    """A sentence: its key in :data:`SENTENCES` (or the report's :data:`plans.language.CHECK_TERMS`)
    and its parts by field name."""

    key: str
    parts: tuple[tuple[str, Part], ...]

    def render(self, lang: str = "en", name: Callable[[str], str] | None = None) -> str:
        """The sentence in ``lang``; ``name`` writes a quantity key (default: the key itself)."""
        en, ru = SENTENCES[self.key] if self.key in SENTENCES else CHECK_TERMS[self.key]
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
    if p.tag == "z":  # a finding's sentence without its "φ = …°: " head
        return p.value.render(lang, name).split(": ", 1)[-1]
    if p.tag == "j":
        items = [_part(x, lang, name) for x in p.value]
        sep = p.spec or (" и " if ru else " and ")
        return sep.join(items)
    return str(p.value)


__all__ = ["CAUSES", "KINDS_RU", "PLANS_RU", "UNITS_RU", "Part", "SENTENCES", "Words", "formula", "n", "plan", "q", "say",
           "t", "tail", "u", "w", "x"]
