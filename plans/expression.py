"""A small, safe language for a quantity given as a formula of the crank angle.

A turning-moment diagram is often stated as a formula, ``600*sin(2*phi) - 500*sin(phi)``.
The formula is read here by a recursive-descent parser (no Python ``eval``): numbers,
the variable ``phi`` (radians), the constant ``pi``, ``+ - * / ^`` with the usual
precedence (``^`` binds tighter than a sign and groups to the right: ``-2^2 = -4``,
``2^3^2 = 2^9``), parentheses and the functions ``sin cos tan sqrt exp``.  Anything else
is refused with one line naming the field and the place in the formula.

The parsed formula is a tree of closures evaluated over a numpy array of angles.
"""

from __future__ import annotations

import math
import re
from collections.abc import Callable

import numpy as np
from numpy.typing import NDArray

from plans.errors import InputError, Said

R = NDArray[np.float64]
Node = Callable[[R], R]

FUNCTIONS: dict[str, Callable[[R], R]] = {"sin": np.sin, "cos": np.cos, "tan": np.tan, "sqrt": np.sqrt,
                                          "exp": np.exp}
VARIABLE = "phi"
MAX_LENGTH = 500
MAX_DEPTH = 40

_TOKEN = re.compile(r"\s*(?:(\d+\.?\d*(?:[eE][+-]?\d+)?|\.\d+(?:[eE][+-]?\d+)?)|([A-Za-z_][A-Za-z_0-9]*)|(.))")


class _Fail(Exception):
    pass


def _tokens(text: str) -> list[tuple[str, str, int]]:
    out: list[tuple[str, str, int]] = []
    pos = 0
    while pos < len(text):
        m = _TOKEN.match(text, pos)
        if m is None or m.end() == pos:  # trailing blanks
            break
        num, name, op = m.groups()
        at = m.start(m.lastindex or 0)
        if num is not None:
            out.append(("num", num, at))
        elif name is not None:
            out.append(("name", name, at))
        elif op is not None:
            if op not in "+-*/^()":
                raise _Fail(f"unexpected character {op!r} at position {at + 1}")
            out.append(("op", op, at))
        pos = m.end()
    return out


class _Parser:
    def __init__(self, text: str) -> None:
        self.toks = _tokens(text)
        self.k = 0
        self.depth = 0

    def peek(self) -> tuple[str, str, int] | None:
        return self.toks[self.k] if self.k < len(self.toks) else None

    def take(self, op: str) -> bool:
        t = self.peek()
        if t is not None and t[0] == "op" and t[1] == op:
            self.k += 1
            return True
        return False

    def parse(self) -> Node:
        if not self.toks:
            raise _Fail("the formula is empty")
        node = self.sum()
        t = self.peek()
        if t is not None:
            raise _Fail(f"unexpected {t[1]!r} at position {t[2] + 1}")
        return node

    def sum(self) -> Node:
        node = self.product()
        while True:
            if self.take("+"):
                a, b = node, self.product()
                node = _add(a, b)
            elif self.take("-"):
                a, b = node, self.product()
                node = _sub(a, b)
            else:
                return node

    def product(self) -> Node:
        node = self.unary()
        while True:
            if self.take("*"):
                a, b = node, self.unary()
                node = _mul(a, b)
            elif self.take("/"):
                a, b = node, self.unary()
                node = _div(a, b)
            else:
                return node

    def unary(self) -> Node:
        self.depth += 1
        if self.depth > MAX_DEPTH:
            raise _Fail(f"the formula nests deeper than {MAX_DEPTH} levels")
        try:
            if self.take("-"):
                a = self.unary()
                return lambda x: -a(x)
            if self.take("+"):
                return self.unary()
            return self.power()
        finally:
            self.depth -= 1

    def power(self) -> Node:
        base = self.atom()
        if self.take("^"):
            expo = self.unary()  # right-associative, a sign allowed in the exponent
            return _pow(base, expo)
        return base

    def atom(self) -> Node:
        t = self.peek()
        if t is None:
            raise _Fail("the formula ends where a number, phi, pi, a function or '(' was expected")
        kind, text, at = t
        self.k += 1
        if kind == "num":
            v = float(text)
            if not math.isfinite(v):
                raise _Fail(f"the number {text} at position {at + 1} is too large")
            return lambda x: np.full(np.shape(x), v)
        if kind == "name":
            if text == VARIABLE:
                return lambda x: np.asarray(x, float)
            if text == "pi":
                return lambda x: np.full(np.shape(x), math.pi)
            if text in FUNCTIONS:
                if not self.take("("):
                    raise _Fail(f"{text} at position {at + 1} needs its argument in parentheses")
                arg = self.sum()
                if not self.take(")"):
                    raise _Fail(f"missing ')' after the argument of {text} (position {at + 1})")
                fn = FUNCTIONS[text]
                return lambda x: fn(arg(x))
            raise _Fail(f"unknown name {text!r} at position {at + 1}; expected phi, pi or one of "
                        f"{', '.join(FUNCTIONS)}")
        if text == "(":
            self.depth += 1
            if self.depth > MAX_DEPTH:
                raise _Fail(f"the formula nests deeper than {MAX_DEPTH} levels")
            node = self.sum()
            self.depth -= 1
            if not self.take(")"):
                raise _Fail(f"missing ')' for the '(' at position {at + 1}")
            return node
        raise _Fail(f"unexpected {text!r} at position {at + 1}")


def _add(a: Node, b: Node) -> Node:
    return lambda x: a(x) + b(x)


def _sub(a: Node, b: Node) -> Node:
    return lambda x: a(x) - b(x)


def _mul(a: Node, b: Node) -> Node:
    return lambda x: a(x) * b(x)


def _div(a: Node, b: Node) -> Node:
    return lambda x: a(x) / b(x)


def _pow(a: Node, b: Node) -> Node:
    return lambda x: np.power(a(x), b(x))


class Expression:
    """A parsed formula of ``phi``; call it with angles in radians."""

    __slots__ = ("text", "_node")

    def __init__(self, text: str, node: Node) -> None:
        self.text = text
        self._node = node

    def __call__(self, phi: R) -> R:
        with np.errstate(all="ignore"):
            return np.asarray(self._node(np.asarray(phi, float)), float)

    def __repr__(self) -> str:
        return f"Expression({self.text!r})"


def parse(text: object, *, file: str | None = None, field: str = "expression") -> Expression:
    """The formula as an :class:`Expression`; InputError (one line, naming ``field``) if it is
    not one."""
    if not isinstance(text, str):
        raise InputError(Said("ex_formula_phi_string", text=text), file=file, field=field)
    if len(text) > MAX_LENGTH:
        raise InputError(Said("ex_formula_longer_than", MAX_LENGTH=MAX_LENGTH), file=file, field=field)
    try:
        node = _Parser(text).parse()
    except _Fail as exc:
        hint = "" if "expected" in str(exc) else (f"; expected numbers, phi, pi, + - * / ^, parentheses and "
                                                  f"{', '.join(FUNCTIONS)}")
        raise InputError(Said("ex_exc_text_hint", exc=exc, text=text, hint=hint), file=file, field=field) from None
    return Expression(text, node)


def check_finite(expr: Expression, phi: R, *, file: str | None, field: str, limit: float = 1e12) -> R:
    """The formula's values at ``phi`` (rad, increasing), refused where one is not a finite
    number, exceeds ``limit`` in magnitude, or where the formula passes through a pole
    between two angles: at every change of sign the bracket is halved 60 times keeping the
    change, and a root ends near zero where a pole ends beyond both ends' values."""
    vals = expr(phi)
    bad = ~np.isfinite(vals) | (np.abs(np.where(np.isfinite(vals), vals, 0.0)) > limit)
    if np.any(bad):
        k = int(np.argmax(bad))
        what = Said("ex_w_not_finite") if not np.isfinite(vals[k]) else Said("ex_w_beyond", limit=limit)
        raise InputError(Said("ex_text_what_pole", text=expr.text, what=what, v=float(np.degrees(phi[k]))), file=file, field=field)
    cells = np.flatnonzero(np.signbit(vals[:-1]) != np.signbit(vals[1:]))
    if len(cells):
        lo, hi = phi[cells].copy(), phi[cells + 1].copy()
        f_lo = vals[cells]
        ends = np.maximum(np.abs(vals[cells]), np.abs(vals[cells + 1]))
        for _ in range(60):
            mid = 0.5 * (lo + hi)
            fm = expr(mid)
            left = np.signbit(fm) == np.signbit(f_lo)
            lo, hi = np.where(left, mid, lo), np.where(left, hi, mid)
            f_lo = np.where(left, fm, f_lo)
        fm = expr(0.5 * (lo + hi))
        pole = ~np.isfinite(fm) | (np.abs(np.where(np.isfinite(fm), fm, 0.0)) > ends)
        if np.any(pole):
            at = float(np.degrees(0.5 * (lo + hi))[int(np.argmax(pole))])
            raise InputError(Said("ex_text_has_pole", text=expr.text, at=at), file=file, field=field)
    # an even pole (1/x²) keeps its sign: climb every local peak of |f| to its top
    mag = np.abs(vals)
    peaks = np.flatnonzero((mag[1:-1] >= mag[:-2]) & (mag[1:-1] >= mag[2:])) + 1
    if len(peaks):
        lo, hi = phi[peaks - 1].copy(), phi[peaks + 1].copy()
        for _ in range(80):
            a, b = lo + (hi - lo) / 3, hi - (hi - lo) / 3
            fa, fb = np.abs(expr(a)), np.abs(expr(b))
            up = ~(fa > fb) | ~np.isfinite(fb)  # toward the larger (or the infinite) side
            lo, hi = np.where(up, a, lo), np.where(up, hi, b)
        top = np.abs(expr(0.5 * (lo + hi)))
        pole = ~np.isfinite(top) | (top > limit)
        if np.any(pole):
            at = float(np.degrees(0.5 * (lo + hi))[int(np.argmax(pole))])
            raise InputError(Said("ex_text_has_pole2", text=expr.text, at=at), file=file, field=field)
    return vals
