"""The arithmetic of a construction over its cases: numpy arrays or plain Python numbers.

The dyad constructions (:mod:`plans.kinematics.dyads`) are written once, over the cases
drawn together: the positions of a cycle, the drawings of a Monte Carlo (arrays), or one
position (Python ``complex`` and ``float``: at one position numpy's cost per call is all
the cost).  Most of the construction is arithmetic on complex numbers, the same for both;
what is not (a choice per case, a maximum, a sign, "any case") goes through one of these
two namespaces, picked once per plan (:attr:`plans.kinematics.dyads.Builder.xp`).
"""

from __future__ import annotations

from typing import Any

import numpy as np

from plans.lines import cross


class Arrays:
    """Cases as numpy arrays (each value an array over the cases, or a number the same for all)."""

    scalar = False

    @staticmethod
    def where(c: Any, a: Any, b: Any) -> Any:
        return np.where(c, a, b)

    @staticmethod
    def any(x: Any) -> bool:
        return bool(x.any()) if type(x) is np.ndarray else bool(np.any(x))

    @staticmethod
    def all(x: Any) -> bool:
        return bool(x.all()) if type(x) is np.ndarray else bool(np.all(x))

    @staticmethod
    def maximum(a: Any, b: Any) -> Any:
        return np.maximum(a, b)

    @staticmethod
    def sign(x: Any) -> Any:
        return np.sign(x)

    @staticmethod
    def zeros(n: int, dtype: type = float) -> Any:
        return np.zeros(n, dtype)

    @staticmethod
    def full(n: int, value: float) -> Any:
        return np.full(n, value)

    @staticmethod
    def first(x: Any) -> Any:
        """The first case's value, a Python number (for the protocol's sentences)."""
        a = np.ravel(x)
        return complex(a[0]) if np.iscomplexobj(a) else float(a[0])

    @staticmethod
    def argmax(x: Any) -> int:
        return int(np.argmax(x))


class Numbers:
    """One case, as Python numbers (``complex`` for plane vectors, ``float`` otherwise)."""

    scalar = True

    @staticmethod
    def where(c: Any, a: Any, b: Any) -> Any:
        return a if c else b

    @staticmethod
    def any(x: Any) -> bool:
        return bool(x)

    all = any

    @staticmethod
    def maximum(a: Any, b: Any) -> Any:
        return a if a >= b else b

    @staticmethod
    def sign(x: Any) -> float:
        return 1.0 if x > 0 else -1.0 if x < 0 else 0.0 if x == 0 else x  # ±0 -> 0, NaN -> NaN, as numpy

    @staticmethod
    def zeros(n: int, dtype: type = float) -> Any:
        return dtype(0)

    @staticmethod
    def full(n: int, value: float) -> float:
        return float(value)

    @staticmethod
    def first(x: Any) -> Any:
        return x

    @staticmethod
    def argmax(x: Any) -> int:
        return 0


def sign(x: float) -> float:
    """The sign of one number (a datum: ω1, ε1), as a Python float."""
    return 1.0 if x > 0 else -1.0 if x < 0 else 0.0


def unit(z: Any) -> Any:
    """z / |z|, and 1 where z = 0 (arrays or numbers)."""
    mag = abs(z)
    if type(mag) is float:
        return z / mag if mag > 0 else 1.0 + 0j
    if np.all(mag > 0):
        return z / mag
    return np.where(mag > 0, z / np.where(mag > 0, mag, 1.0), 1.0 + 0j)


__all__ = ["Arrays", "Numbers", "cross", "sign", "unit"]
