"""Roots and minima of a function of the crank angle over the whole turn, exactly.

The grid only brackets: every root is then found by Brent's method to the last bits of
φ, every minimum by golden-section search to the last bits of its value (a minimum is
flat: its value is exact long before its place is).  Plain Python floats: one design is
proven in about a millisecond.
"""

from __future__ import annotations

import math
from collections.abc import Callable

TAU = 2.0 * math.pi
#: The grid's start: not a round angle, so a root at 0°, 90°, 180° never falls on a node.
_START = 0.0123456789
_GOLD = (math.sqrt(5.0) - 1.0) / 2.0


def brent(f: Callable[[float], float], a: float, b: float, fa: float, fb: float,
          xtol: float = 1e-15) -> float:
    """The root of ``f`` in [a, b] where ``fa``, ``fb`` differ in sign (Brent 1973)."""
    if fa == 0.0:
        return a
    if fb == 0.0:
        return b
    c, fc = a, fa
    d = e = b - a
    for _ in range(200):
        if (fb > 0) == (fc > 0):
            c, fc = a, fa
            d = e = b - a
        if abs(fc) < abs(fb):
            a, b, c = b, c, b
            fa, fb, fc = fb, fc, fb
        tol = 2.0 * 2.2e-16 * abs(b) + 0.5 * xtol
        m = 0.5 * (c - b)
        if abs(m) <= tol or fb == 0.0:
            return b
        if abs(e) >= tol and abs(fa) > abs(fb):
            s = fb / fa
            if a == c:
                p, q = 2.0 * m * s, 1.0 - s
            else:
                qq, r = fa / fc, fb / fc
                p = s * (2.0 * m * qq * (qq - r) - (b - a) * (r - 1.0))
                q = (qq - 1.0) * (r - 1.0) * (s - 1.0)
            if p > 0:
                q = -q
            else:
                p = -p
            if 2.0 * p < min(3.0 * m * q - abs(tol * q), abs(e * q)):
                e, d = d, p / q
            else:
                d = e = m
        else:
            d = e = m
        a, fa = b, fb
        b += d if abs(d) > tol else math.copysign(tol, m)
        fb = f(b)
    return b


def grid(n: int = 48) -> list[float]:
    """The turn's grid that :func:`roots` and :func:`minimum` bracket on."""
    return [_START + TAU * k / n for k in range(n)]


def roots(f: Callable[[float], float], n: int = 48, values: list[float] | None = None) -> list[float]:
    """Every root of the 2π-periodic ``f`` over one turn, in [0, 2π): a sign change between
    neighbours of an ``n``-point grid (``values``: f on :func:`grid` already), then Brent."""
    xs = [_START + TAU * k / n for k in range(n + 1)]
    ys = list(values) if values is not None else [f(x) for x in xs[:-1]]
    ys.append(ys[0])
    out = []
    for k in range(n):
        if ys[k] == 0.0:
            out.append(xs[k] % TAU)
        elif (ys[k] > 0) != (ys[k + 1] > 0) and ys[k + 1] != 0.0:
            out.append(brent(f, xs[k], xs[k + 1], ys[k], ys[k + 1]) % TAU)
    return sorted(out)


def golden(f: Callable[[float], float], a: float, b: float, iters: int = 90,
           xtol: float = 1e-9) -> tuple[float, float]:
    """The minimum of a unimodal ``f`` on [a, b]: (where, value).  The place to ``xtol``
    (relative) is the value to its square: a smooth minimum is flat."""
    c = b - _GOLD * (b - a)
    d = a + _GOLD * (b - a)
    fc, fd = f(c), f(d)
    for _ in range(iters):
        if b - a <= xtol * max(1.0, abs(a)):
            break
        if fc <= fd:
            b, d, fd = d, c, fc
            c = b - _GOLD * (b - a)
            fc = f(c)
        else:
            a, c, fc = c, d, fd
            d = a + _GOLD * (b - a)
            fd = f(d)
    return (c, fc) if fc <= fd else (d, fd)


def fmin(f: Callable[[float], float], a: float, b: float, xtol: float = 1e-10) -> tuple[float, float]:
    """The minimum of ``f`` on [a, b] by Brent's method (golden sections and parabolas):
    a smooth minimum in a dozen evaluations; (where, value)."""
    c = 0.5 * (3.0 - math.sqrt(5.0))
    x = w = v = a + c * (b - a)
    fx = fw = fv = f(x)
    d = e = 0.0
    for _ in range(100):
        m = 0.5 * (a + b)
        tol = xtol * max(1.0, abs(x))
        if abs(x - m) <= 2.0 * tol - 0.5 * (b - a):
            break
        parabola = False
        if abs(e) > tol:
            r = (x - w) * (fx - fv)
            q = (x - v) * (fx - fw)
            p = (x - v) * q - (x - w) * r
            q = 2.0 * (q - r)
            if q > 0:
                p = -p
            q = abs(q)
            if abs(p) < abs(0.5 * q * e) and q * (a - x) < p < q * (b - x):
                e, d = d, p / q
                u = x + d
                if u - a < 2 * tol or b - u < 2 * tol:
                    d = tol if x < m else -tol
                parabola = True
        if not parabola:
            e = (b - x) if x < m else (a - x)
            d = c * e
        u = x + (d if abs(d) >= tol else (tol if d > 0 else -tol))
        fu = f(u)
        if fu <= fx:
            if u < x:
                b = x
            else:
                a = x
            v, fv, w, fw, x, fx = w, fw, x, fx, u, fu
        else:
            if u < x:
                a = u
            else:
                b = u
            if fu <= fw or w == x:
                v, fv, w, fw = w, fw, u, fu
            elif fu <= fv or v == x or v == w:
                v, fv = u, fu
    return x, fx


def minimum(f: Callable[[float], float], n: int = 48, lo: float = 0.0, hi: float = TAU,
            periodic: bool = True, values: list[float] | None = None) -> tuple[float, float]:
    """The smallest value of ``f`` over [lo, hi] (over the whole turn when ``periodic``):
    every local minimum of the grid refined between its neighbours; (where, value).
    ``values``: f on :func:`grid` already (periodic only)."""
    start = _START if periodic else lo
    step = (hi - lo) / n
    xs = [start + step * k for k in range(n + (0 if periodic else 1))]
    ys = list(values) if values is not None and periodic else [f(x) for x in xs]
    m = len(xs)
    best = (xs[0], ys[0])
    for k in range(m):
        if periodic:
            left, right = ys[k - 1], ys[(k + 1) % m]
        else:
            left = ys[k - 1] if k > 0 else math.inf
            right = ys[k + 1] if k + 1 < m else math.inf
        if ys[k] <= left and ys[k] <= right:
            a = xs[k] - step if (periodic or k > 0) else xs[k]
            b = xs[k] + step if (periodic or k + 1 < m) else xs[k]
            x, y = fmin(f, a, b) if b > a else (xs[k], ys[k])
            if y > ys[k]:
                x, y = xs[k], ys[k]
            if y < best[1]:
                best = (x, y)
    return (best[0] % TAU if periodic else best[0], best[1])


def wrap(a: float) -> float:
    """An angle reduced to (−π, π]."""
    r = math.remainder(a, TAU)
    return math.pi if r == -math.pi else r
