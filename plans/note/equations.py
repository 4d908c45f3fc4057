"""The force protocol's moment equations as formulas: in letters, then with the numbers.

A step of :mod:`plans.forces.protocol` keeps its sentence as a phrase with its values
(the known forces with their arms, the couples, the sum, the unknown); here they become
Office-Math-ready formula trees.  A step of another kind, or an unknown with no formula of
its own, gives nothing (its sentence stands alone)."""

from __future__ import annotations

import re
from typing import Any

from .model import Formula, Frac, Sym, num, row
from .words import unit

_NAME = re.compile(r"ΣM(?:_(\w+))?\((\d+)\)")
_LABEL = re.compile(r"^(M_)?(Phi|[A-Za-z])(\w*?)('*)$")


def label(lb: str, lang: str) -> Formula:
    """A force's label as a symbol: Phi2 → Φ₂, M_Phi2 → M_Φ2, F21 → F₂₁, F_bal → F_ур."""
    if lb in ("F_bal", "M_bal"):
        return Sym(lb[0], "ур" if lang == "ru" else "bal")
    m = _LABEL.match(lb)
    if m is None:
        return Sym(lb)
    couple, base, sub, primes = m.groups()
    base = "Φ" if base == "Phi" else base
    if couple:
        return Sym("M", base + sub + primes)
    return Sym(base + primes, sub or None)


def _name(name: str) -> Formula:
    m = _NAME.fullmatch(name)
    if m is None:
        return Sym(name)
    pt, link = m.groups()
    return row(Sym("ΣM", pt), "(", link, ")") if pt else row(Sym("ΣM"), "(", link, ")")


def _sign(s: str, first: bool) -> list:
    if s == "+":
        return [] if first else ["+"]
    return ["−"]


def moment(step: Any, lang: str) -> list[Formula]:
    """A moment equation of a group or of the crank: the known moments' sum in letters and
    numbers, and the unknown it gives."""
    ph = getattr(step, "phrase", None)
    if ph is None:
        return []
    if ph.key == "l_equation":
        return lever(ph, lang)
    if ph.key != "m_equation":
        return []
    a = ph.args
    known = a["known"] if isinstance(a["known"], list) else []
    letters: list = []
    numbers: list = []
    for t in known:
        first = not letters
        if t.key == "m_term_force":
            lb = label(t.args["label"], lang)
            letters += [*_sign(t.args["sign"], first), lb, "·", Sym("h", _plain(lb))]
            numbers += [*_sign(t.args["sign"], first), num(t.args["F"], lang), "·", num(t.args["h"], lang)]
        elif t.key == "m_term_couple":
            letters += [*_sign(t.args["sign"], first), label(t.args["label"], lang)]
            numbers += [*_sign(t.args["sign"], first), num(t.args["M"], lang)]
    total = float(a["total"])
    Mk = Sym("M", "изв" if lang == "ru" else "known")
    out: list[Formula] = []
    if letters:
        out += _split(row(_name(a["name"]), ":", " ", Mk), letters, numbers, num(total, lang), unit("N·m", lang))
    u = a["unknown"]
    args = u.args

    def sign_of(value: float, scale: float) -> str:
        """'' when value = total/scale, '−' when value = −total/scale (the protocol's sense)."""
        return "" if abs(value - total / scale) <= abs(value + total / scale) else "−"

    if u.key == "m_tau":
        n, lab = args["n"], Sym("l", args["A"] + args["B"])
        tau = float(args["tau"])
        s = sign_of(tau, float(args["l"]))
        out.append(row(Sym(n[0], n[1:], "τ"), "=", *([s] if s else []), Frac(Mk, lab), "=",
                       *([s] if s else []), Frac(num(total, lang), num(args["l"], lang)), "=", num(tau, lang),
                       unit("N", lang)))
    elif u.key == "m_crank_force":
        F = float(args["F"])
        s = sign_of(F, float(args["l"]))
        Fb = label("F_bal", lang)
        out.append(row(Fb, "=", *([s] if s else []), Frac(Mk, Sym("l", "O" + args["pt"])), "=", *([s] if s else []),
                       Frac(num(total, lang), num(args["l"], lang)), "=", num(F, lang), unit("N", lang)))
    elif u.key in ("m_crank_moment", "m_guide", "m_couple_of"):
        M = float(args["M"])
        s = sign_of(M, 1.0)
        lhs = label("M_bal", lang) if u.key == "m_crank_moment" else Sym("M", args["n"])
        out.append(row(lhs, "=", *([s] if s else []), Mk, "=", num(M, lang), unit("N·m", lang)))
    return out


def lever(ph: Any, lang: str) -> list[Formula]:
    """The Zhukovsky lever: the moments about the pole p of the forces moved to the turned
    plan (their arms in mm on it), and the balancing force they give with its own arm."""
    a = ph.args
    terms = a["terms"] if isinstance(a["terms"], list) else []
    arm = a["arm"]
    if getattr(arm, "key", None) != "l_arm" or not terms or float(arm.args["a"]) == 0:
        return []
    letters: list = []
    numbers: list = []
    total = 0.0
    for t in terms:
        first = not letters
        lb = label(t.args["label"], lang)
        letters += [*_sign(t.args["sign"], first), lb, "·", Sym("h", t.args["pt"])]
        numbers += [*_sign(t.args["sign"], first), num(t.args["F"], lang), "·", num(t.args["h"], lang)]
        total += (1 if t.args["sign"] == "+" else -1) * float(t.args["F"]) * float(t.args["h"])
    F, h = float(a["F"]), float(arm.args["a"])
    s = "" if abs(F - total / h) <= abs(F + total / h) else "−"
    Mk = Sym("M", "p")
    Fb = label("F_bal", lang)
    return [*_split(row(Mk), letters, numbers, num(total, lang), unit("N*mm", lang)),
            row(Fb, "=", *([s] if s else []), Frac(Mk, Sym("h", a["pt"])), "=", *([s] if s else []),
                Frac(num(total, lang), num(h, lang)), "=", num(F, lang), unit("N", lang))]


#: More known terms than this: the letters and the numbers each on a line of their own.
_ONE_LINE = 3


def _split(lhs: Formula, letters: list, numbers: list, total: Formula, u: str) -> list[Formula]:
    """``lhs = letters = numbers = total`` on one line, or on two when it would not fit."""
    if sum(1 for x in letters if x == "·") <= _ONE_LINE:
        return [row(lhs, "=", *letters, "=", *numbers, "=", total, u)]
    lines: list[Formula] = [row(lhs, "=", *part) if i == 0 else row(*part) for i, part in enumerate(_chunks(letters))]
    parts = _chunks(numbers)
    lines += [row("=", *part) if i == 0 else row(*part) for i, part in enumerate(parts[:-1])]
    last = parts[-1]
    lines.append(row(*(["="] if len(parts) == 1 else []), *last, "=", total, u))
    return lines


def _chunks(items: list, per_line: int = 4) -> list[list]:
    """A sum's terms, ``per_line`` to a line, each line after the first opening with its sign."""
    terms: list[list] = [[]]
    for x in items:
        if x in ("+", "−") and terms[-1]:
            terms.append([])
        terms[-1].append(x)
    return [sum(terms[i:i + per_line], []) for i in range(0, len(terms), per_line)]


def _plain(f: Formula) -> str:
    if isinstance(f, Sym):
        return f.base + (f.sub if isinstance(f.sub, str) else "")
    return ""


__all__ = ["label", "lever", "moment"]
