"""The draftsman's smooth curve through the points of a closed (periodic) diagram.

A periodic cubic spline: what the French curve does when a course joins the plotted
points of a diagram over the cycle before integrating it or drawing tangents to it.
"""

from __future__ import annotations

import numpy as np
from numpy.typing import NDArray

R = NDArray[np.float64]


def moments(x: R, y: R) -> R:
    """Second derivatives at the nodes of the periodic cubic spline through (x, y); ``x``
    increasing with the closing node last (``y[-1]`` equal to ``y[0]``)."""
    h = np.diff(x)
    n = len(h)
    if n < 3:
        return np.zeros(n + 1)
    A = np.zeros((n, n))
    rhs = np.zeros(n)
    for i in range(n):  # equation at node i (periodic: node 0 joins intervals n-1 and 0)
        hp, hn = h[i - 1], h[i]
        A[i, (i - 1) % n] += hp / 6
        A[i, i] += (hp + hn) / 3
        A[i, (i + 1) % n] += hn / 6
        yp, y0, yn = y[i - 1] if i else y[n - 1], y[i], y[i + 1]
        rhs[i] = (yn - y0) / hn - (y0 - yp) / hp
    m = np.linalg.solve(A, rhs)
    return np.append(m, m[0])


def interval_integrals(x: R, y: R, m: R) -> R:
    """∫ of the spline over each interval."""
    h = np.diff(x)
    return h * (y[1:] + y[:-1]) / 2 - h**3 * (m[1:] + m[:-1]) / 24


def sample(x: R, y: R, m: R, per: int) -> tuple[R, R]:
    """The spline at ``per`` points per interval (the closing node included)."""
    h = np.diff(x)
    t = np.arange(per) / per
    a = 1 - t
    xs = (x[:-1, None] + h[:, None] * t).ravel()
    ys = (a * y[:-1, None] + t * y[1:, None]
          + ((a**3 - a) * m[:-1, None] + (t**3 - t) * m[1:, None]) * h[:, None] ** 2 / 6).ravel()
    return np.append(xs, x[-1]), np.append(ys, y[-1])
