"""The draftsman's smooth curve through the points of a closed (periodic) diagram.

A periodic shape-preserving cubic (Fritsch–Carlson/Butland slopes, as PCHIP): what the
French curve does when a course joins the plotted points of a diagram over the cycle
before integrating it or drawing tangents to it.  It never overshoots between points,
even where a dead centre puts two positions a degree apart.
"""

from __future__ import annotations

import numpy as np
from numpy.typing import NDArray

R = NDArray[np.float64]


def slopes(x: R, y: R) -> R:
    """Slopes at the nodes of the periodic curve through (x, y); ``x`` increasing with the
    closing node last (``y[-1]`` equal to ``y[0]``)."""
    h = np.diff(x)
    dl = np.diff(y) / h  # chord slopes of the intervals
    prev_d, prev_h = np.roll(dl, 1), np.roll(h, 1)  # the interval before each node (periodic)
    w1, w2 = 2 * h + prev_h, h + 2 * prev_h
    same = prev_d * dl > 0
    den = np.where(same, w1 / np.where(same, prev_d, 1.0) + w2 / np.where(same, dl, 1.0), 1.0)
    d = np.where(same, (w1 + w2) / den, 0.0)
    return np.append(d, d[0])


def interval_integrals(x: R, y: R, d: R) -> R:
    """∫ of the curve over each interval (Hermite cubic: h(y0 + y1)/2 + h²(d0 − d1)/12)."""
    h = np.diff(x)
    return h * (y[1:] + y[:-1]) / 2 + h**2 * (d[:-1] - d[1:]) / 12


def sample(x: R, y: R, d: R, per: int) -> tuple[R, R]:
    """The curve at ``per`` points per interval (the closing node included)."""
    h = np.diff(x)[:, None]
    t = np.arange(per) / per
    h00, h10, h01, h11 = 2 * t**3 - 3 * t**2 + 1, t**3 - 2 * t**2 + t, -2 * t**3 + 3 * t**2, t**3 - t**2
    ys = (h00 * y[:-1, None] + h10 * h * d[:-1, None] + h01 * y[1:, None] + h11 * h * d[1:, None]).ravel()
    xs = (x[:-1, None] + h * t).ravel()
    return np.append(xs, x[-1]), np.append(ys, y[-1])


def freeze(obj: object) -> None:
    """Make every array reachable through an object's dataclass fields read-only, so that a
    page or a test reading a diagram cannot change what the sheet was drawn from."""
    import dataclasses

    seen: set[int] = set()

    def walk(x: object) -> None:
        if id(x) in seen:
            return
        seen.add(id(x))
        if isinstance(x, np.ndarray):
            x.flags.writeable = False
        elif dataclasses.is_dataclass(x) and not isinstance(x, type):
            for f in dataclasses.fields(x):
                if f.name != "scene":
                    walk(getattr(x, f.name))
        elif isinstance(x, tuple | list):
            for y in x:
                walk(y)

    walk(obj)
