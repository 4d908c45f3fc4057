"""Newton's method on two equations in two unknowns with a forward-difference Jacobian: the
step the class III tests' separately written solvers share (each writes its own equations)."""

from __future__ import annotations

from collections.abc import Callable

Pair = tuple[float, float]


def newton2(f: Callable[[Pair], Pair], ab: Pair, iterations: int) -> Pair:
    """A root of ``f`` near ``ab``: at most ``iterations`` steps, until a step is below 1e-15."""
    a, b = ab
    for _ in range(iterations):
        f1, f2 = f((a, b))
        d = 1e-7
        g1, g2 = f((a + d, b))
        h1, h2 = f((a, b + d))
        j11, j21, j12, j22 = (g1 - f1) / d, (g2 - f2) / d, (h1 - f1) / d, (h2 - f2) / d
        det = j11 * j22 - j12 * j21
        da, db = (-f1 * j22 + f2 * j12) / det, (-j11 * f2 + j21 * f1) / det
        a, b = a + da, b + db
        if abs(da) + abs(db) < 1e-15:
            break
    return a, b
