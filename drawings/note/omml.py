"""A formula tree (:mod:`plans.note.model`) as Office Math Markup (``m:oMath``): native
Word equations, editable in Word and LibreOffice."""

from __future__ import annotations

import re
from xml.sax.saxutils import escape

from plans.note.model import Formula, Frac, Num, Op, Root, Row, Sym, Text, Vec

M = "http://schemas.openxmlformats.org/officeDocument/2006/math"
W = "http://schemas.openxmlformats.org/wordprocessingml/2006/main"

_FONT = ('<w:rPr><w:rFonts w:ascii="Cambria Math" w:hAnsi="Cambria Math" w:cs="Cambria Math"/>'
         '<w:sz w:val="28"/><w:szCs w:val="28"/></w:rPr>')  # 14 pt, as the text
_UPRIGHT = re.compile(r"[А-Яа-яЁё]|[a-z]{2,}|^(inv|tg|cos|sin)\b|\s")


def _run(text: str, upright: bool) -> str:
    # m:nor: ordinary upright text (a unit, a word, a Cyrillic index), as Word and
    # LibreOffice's import both read it; numbers and operators are upright by themselves
    sty = "<m:rPr><m:nor/></m:rPr>" if upright and (text.isspace() or any(ch.isalpha() for ch in text)) else ""
    return f'<m:r>{sty}{_FONT}<m:t xml:space="preserve">{escape(text)}</m:t></m:r>'


def _text(s: str) -> str:
    """A symbol's letters: words and Cyrillic upright, single letters italic (the default)."""
    return _run(s, bool(_UPRIGHT.search(s)))


def _part(x: str | Formula) -> str:
    return _text(x) if isinstance(x, str) else xml(x)


def xml(f: Formula) -> str:
    """The formula's OMML, without the enclosing ``m:oMath``."""
    if isinstance(f, Row):
        if f.items and isinstance(f.items[0], Op) and f.items[0].text == "=":
            # a line that goes on from the one above: an empty left side first (LibreOffice's
            # formulas need something left of "=")
            return _run("\u2002", True) + "".join(xml(x) for x in f.items)
        return "".join(xml(x) for x in f.items)
    if isinstance(f, Num):
        return _run(f.text, True)
    if isinstance(f, Op):
        t = f.text
        return _run(f" {t} " if t in ("=", "+", "−", "-", "≈", "×") else (t + " " if t == "," else t), True)
    if isinstance(f, Text):
        t = f.text
        return _run((" " + t) if t[:1].isalnum() or t[:1] == "(" else t, True)
    if isinstance(f, Sym):
        base = _text(f.base) if f.base else _run("", True)
        if f.sub is not None and f.sup is not None:
            return (f"<m:sSubSup><m:e>{base}</m:e><m:sub>{_part(f.sub)}</m:sub>"
                    f"<m:sup>{_part(f.sup)}</m:sup></m:sSubSup>")
        if f.sub is not None:
            return f"<m:sSub><m:e>{base}</m:e><m:sub>{_part(f.sub)}</m:sub></m:sSub>"
        if f.sup is not None:
            return f"<m:sSup><m:e>{base}</m:e><m:sup>{_part(f.sup)}</m:sup></m:sSup>"
        return base
    if isinstance(f, Frac):
        return f"<m:f><m:num>{xml(f.num)}</m:num><m:den>{xml(f.den)}</m:den></m:f>"
    if isinstance(f, Root):
        return f'<m:rad><m:radPr><m:degHide m:val="1"/></m:radPr><m:deg/><m:e>{xml(f.body)}</m:e></m:rad>'
    if isinstance(f, Vec):
        return f'<m:acc><m:accPr><m:chr m:val="\u20d7"/></m:accPr><m:e>{xml(f.body)}</m:e></m:acc>'
    raise TypeError(f"not a formula: {f!r}")


def omath(f: Formula) -> str:
    """One ``m:oMath`` element (with its namespaces declared, to be parsed on its own)."""
    return f'<m:oMath xmlns:m="{M}" xmlns:w="{W}">{xml(f)}</m:oMath>'


def omath_para(f: Formula) -> str:
    """A displayed equation: ``m:oMathPara`` holding one ``m:oMath``, centred."""
    return (f'<m:oMathPara xmlns:m="{M}" xmlns:w="{W}"><m:oMathParaPr><m:jc m:val="center"/></m:oMathParaPr>'
            f'<m:oMath>{xml(f)}</m:oMath></m:oMathPara>')


def plain(f: Formula) -> str:
    """The formula as plain text (a cell, a caption): v_B = 12,46 м/с."""
    if isinstance(f, Row):
        return "".join(plain(x) for x in f.items)
    if isinstance(f, Num | Text):
        return f.text
    if isinstance(f, Op):
        return f" {f.text} " if f.text in ("=", "+", "−") else f.text
    if isinstance(f, Sym):
        s = f.base
        if f.sub is not None:
            s += "_" + (f.sub if isinstance(f.sub, str) else plain(f.sub))
        if f.sup is not None:
            s += "^" + (f.sup if isinstance(f.sup, str) else plain(f.sup))
        return s
    if isinstance(f, Frac):
        return f"({plain(f.num)})/({plain(f.den)})"
    if isinstance(f, Root):
        return f"√({plain(f.body)})"
    if isinstance(f, Vec):
        return plain(f.body)
    raise TypeError(f"not a formula: {f!r}")
