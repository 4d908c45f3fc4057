"""Laws of the follower's motion over one phase, in the phase's own fraction t = φ/Φ ∈ [0, 1].

Each law gives the unit lift f(t) with f(0) = 0, f(1) = 1 and its first two derivatives
with respect to t; the phase scales them: s = h·f, ds/dφ = h·f′/Φ, d²s/dφ² = h·f″/Φ².
"""

from __future__ import annotations

from collections.abc import Callable, Sequence

import numpy as np

Law = Callable[[np.ndarray], tuple[np.ndarray, np.ndarray, np.ndarray]]


def harmonic(t: np.ndarray) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Cosine (simple harmonic) law: f = (1 − cos πt)/2."""
    p = np.pi
    return (1 - np.cos(p * t)) / 2, p / 2 * np.sin(p * t), p * p / 2 * np.cos(p * t)


def cycloidal(t: np.ndarray) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Cycloidal (sine acceleration) law: f = t − sin 2πt / 2π."""
    q = 2 * np.pi
    return t - np.sin(q * t) / q, 1 - np.cos(q * t), q * np.sin(q * t)


def constant_acceleration(t: np.ndarray) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Constant acceleration then deceleration (parabolic): f = 2t² up to t = ½, then
    1 − 2(1 − t)²."""
    first = t <= 0.5
    u = 1 - t
    f = np.where(first, 2 * t * t, 1 - 2 * u * u)
    d1 = np.where(first, 4 * t, 4 * u)
    d2 = np.where(first, 4.0, -4.0)
    return f, d1, d2 * np.ones_like(t)


def poly345(t: np.ndarray) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """3-4-5 polynomial: f = 10t³ − 15t⁴ + 6t⁵."""
    return (10 * t**3 - 15 * t**4 + 6 * t**5, 30 * t**2 - 60 * t**3 + 30 * t**4,
            60 * t - 180 * t**2 + 120 * t**3)


LAWS: dict[str, Law] = {
    "harmonic": harmonic,
    "cycloidal": cycloidal,
    "constant_acceleration": constant_acceleration,
    "poly345": poly345,
}


def table_law(t_nodes: Sequence[float], f_nodes: Sequence[float]) -> Law:
    """A law given as a table: the cubic spline through the points (t, f), clamped with zero
    slope at both ends (the follower starts and ends the phase at rest), C² inside."""
    x = np.asarray(t_nodes, float)
    y = np.asarray(f_nodes, float)
    n = len(x)
    h = np.diff(x)
    # Second derivatives M at the nodes from the clamped-spline equations.
    A = np.zeros((n, n))
    r = np.zeros(n)
    A[0, 0], A[0, 1] = 2 * h[0], h[0]
    r[0] = 6 * ((y[1] - y[0]) / h[0])
    A[-1, -2], A[-1, -1] = h[-1], 2 * h[-1]
    r[-1] = -6 * ((y[-1] - y[-2]) / h[-1])
    for i in range(1, n - 1):
        A[i, i - 1], A[i, i], A[i, i + 1] = h[i - 1], 2 * (h[i - 1] + h[i]), h[i]
        r[i] = 6 * ((y[i + 1] - y[i]) / h[i] - (y[i] - y[i - 1]) / h[i - 1])
    M = np.linalg.solve(A, r)

    def law(t: np.ndarray) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
        t = np.asarray(t, float)
        i = np.clip(np.searchsorted(x, t, side="right") - 1, 0, n - 2)
        hi = h[i]
        a = (x[i + 1] - t) / hi
        b = (t - x[i]) / hi
        f = a * y[i] + b * y[i + 1] + ((a**3 - a) * M[i] + (b**3 - b) * M[i + 1]) * hi * hi / 6
        d1 = ((y[i + 1] - y[i]) / hi - (3 * a * a - 1) / 6 * hi * M[i] + (3 * b * b - 1) / 6 * hi * M[i + 1])
        d2 = a * M[i] + b * M[i + 1]
        return f, d1, d2

    return law
