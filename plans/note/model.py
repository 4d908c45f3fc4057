"""The note's building blocks: a document of sections, each a list of blocks.

A formula is a small tree that any writer can turn into its own mathematics (Office Math
in the DOCX): symbols with subscripts and superscripts, numbers already written in the
note's rounding, operators, upright text, fractions, roots and vectors.  Text that refers
to a figure or a table carries ``{fig:KEY}`` / ``{tab:KEY}``: the writer numbers them.
"""

from __future__ import annotations

import math
from collections.abc import Callable, Sequence
from dataclasses import dataclass, field
from typing import Union

# --------------------------------------------------------------------------- formulas


@dataclass(frozen=True)
class Sym:
    """A letter with an optional subscript and superscript (``v`` with ``B``: v_B)."""

    base: str
    sub: str | Formula | None = None
    sup: str | Formula | None = None


@dataclass(frozen=True)
class Num:
    """A number written in the note's rounding (its text, a decimal comma in Russian)."""

    text: str


@dataclass(frozen=True)
class Op:
    """An operator or a bracket: =, +, −, ·, ×, (, )."""

    text: str


@dataclass(frozen=True)
class Text:
    """Upright text inside a formula: a unit, a word."""

    text: str


@dataclass(frozen=True)
class Frac:
    num: Formula
    den: Formula


@dataclass(frozen=True)
class Root:
    body: Formula


@dataclass(frozen=True)
class Vec:
    """A vector: the quantity with an arrow over it."""

    body: Formula


@dataclass(frozen=True)
class Row:
    items: tuple[Formula, ...]


Formula = Union[Sym, Num, Op, Text, Frac, Root, Vec, Row]  # noqa: UP007 (a runtime alias)


def row(*items: Formula | str) -> Row:
    """A row of items; a bare string is an operator when it is one, else upright text."""
    out: list[Formula] = []
    for it in items:
        if isinstance(it, str):
            out.append(Op(it) if it in _OPS else Text(it))
        else:
            out.append(it)
    return Row(tuple(out))


_OPS = {"=", "+", "−", "-", "·", "×", "(", ")", "/", "≈", ",", "⟂", "∥", "Σ", "; "}

# --------------------------------------------------------------------------- blocks


@dataclass(frozen=True)
class Para:
    """A paragraph: text and inline formulas one after another."""

    parts: tuple[str | Formula, ...]


@dataclass(frozen=True)
class Equation:
    """A displayed formula, on a line of its own."""

    formula: Formula


@dataclass(frozen=True)
class Table:
    """A Word table: ``key`` for references, the caption's text, a header row and rows."""

    key: str
    caption: str
    header: tuple[str, ...]
    rows: tuple[tuple[str, ...], ...]


@dataclass(frozen=True)
class Figure:
    """A figure drawn from a sheet's panel: which file (``file``: its index among the
    note's files), which panel (``panel``: the sheets' panel id, or ``kind:NAME`` for a
    panel of a kind) and its caption."""

    key: str
    file: int
    panel: str
    caption: str


Block = Union[Para, Equation, Table, Figure]  # noqa: UP007


@dataclass
class Section:
    """A numbered section (level 1) or subsection (level 2, 3)."""

    title: str
    level: int = 1
    blocks: list[Block] = field(default_factory=list)
    key: str = ""  # what the section is about: "task", "structure", "kinematics", ...
    children: list[Section] = field(default_factory=list)  # its subsections, in order

    def add(self, *blocks: Block) -> Section:
        self.blocks.extend(blocks)
        return self

    def para(self, *parts: str | Formula) -> Section:
        self.blocks.append(Para(tuple(parts)))
        return self

    def eq(self, *items: Formula | str) -> Section:
        self.blocks.append(Equation(row(*items)))
        return self


def of_tables(title: str, key: str, tables: Sequence[Table], pointer: Callable[[str], str]) -> list[Section]:
    """A subsection of ``tables``, each after the sentence ``pointer(its key)`` that refers
    to it; none where there are no tables."""
    if not tables:
        return []
    sec = Section(title, 2, key=key)
    for t in tables:
        sec.para(pointer(t.key))
        sec.add(t)
    return [sec]


@dataclass(frozen=True)
class TitlePage:
    organization: str = ""
    department: str = ""
    kind: str = ""  # "ПОЯСНИТЕЛЬНАЯ ЗАПИСКА ..."
    title: str = ""
    subtitle: str = ""
    designation: str = ""
    author: str = ""
    group: str = ""
    checked_by: str = ""
    date: str = ""
    labels: tuple[tuple[str, str], ...] = ()  # (label, value) lines under the title


@dataclass
class Note:
    lang: str
    title: TitlePage
    sections: list[Section]
    files: tuple[str, ...]  # the paths read, by index (figures refer to them)
    kinds: tuple[str, ...]  # each file's kind
    contents: str = ""  # the heading of the table of contents


# --------------------------------------------------------------------------- numbers


def fmt(x: float, lang: str = "en", digits: int = 4) -> str:
    """A value in the note's rounding: ``digits`` significant figures (trailing zeros
    dropped), never an exponent (a value of a thousand or more as a whole number), a
    decimal comma in Russian, a zero up to round-off written 0, a minus as the
    typographic minus."""
    x = float(x)
    if not math.isfinite(x):
        return "—"
    if abs(x) < 5e-10:
        return "0"
    e = math.floor(math.log10(abs(x)))
    places = min(9, max(0, digits - 1 - e))
    s = f"{round(x, places):.{places}f}"
    if "." in s:  # 6 kg, not 6,000: the figures a value has, not those it might have
        s = s.rstrip("0").rstrip(".")
    if s.lstrip("-").strip("0.") == "":
        return "0"
    s = s.replace("-", "−")
    return s.replace(".", ",") if lang == "ru" else s


def num(x: float, lang: str, digits: int = 4) -> Num:
    return Num(fmt(x, lang, digits))
