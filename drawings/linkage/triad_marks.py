"""Assur's special point S of a class-III group on the scheme and on the group cut free: the
axes of the two leashes that give it, extended to S, and S marked and labelled."""

from __future__ import annotations

from typing import Any

import numpy as np

from drawings.paper.backend import Recording, Style, Transform
from drawings.paper.common import Placer, dot, ident
from plans.kinematics.triad_plans import PAIRS, special_point_of

AXIS = Style(width=0.18, stroke="#333", dash=(6.0, 1.0, 1.0, 1.0), cls="axis")
#: S farther than this many times the group's size from its pairs is not drawn (the axes
#: nearly parallel would carry the drawing off the sheet)
REACH = 2.5


def _mark(rec: Recording, placer: Placer, T: Transform, S: complex, Q: list[complex], P: list[complex],
          pair: tuple[int, int], pid: str, size: float, label: str = "S") -> bool:
    """The two axes from the outer pairs through the inner ones to S, S itself; False where S
    lies too far to draw."""
    pts = Q + P
    centre = sum(pts) / len(pts)
    extent = max(abs(z - centre) for z in pts)
    if not np.isfinite(S.real + S.imag) or abs(S - centre) > REACH * extent:
        return False
    for x in pair:
        a, b = (Q[x], S) if abs(S - Q[x]) >= abs(P[x] - Q[x]) else (Q[x], P[x])
        rec.line(T.z(a), T.z(b), AXIS, f"{pid}-assur-axis-{x}")
        placer.add_line([T.z(a), T.z(b)])
    c = T.z(S)
    rec.circle(c, 1.1, Style(width=0.3, fill="#fff", cls="assur"), f"{pid}-assur-point")
    dot(rec, c, 0.45)
    placer.add_disc(c, 1.3)
    away = S - centre
    L = abs(away) or 1.0
    lab = placer.place(label, c, size, prefer=(away.real / L, -away.imag / L), gap=1.6)
    rec.text(lab, "label", f"{pid}-label-assur-{ident(label)}")
    return True


def scheme_points(rec: Recording, placer: Placer, T: Transform, scene: Any, kin: Any, k: int, pid: str,
                  size: float) -> None:
    """S of every class-III group at position k on the scheme (labels of ``size``): S, the
    leashes and their pairs as the solved kinematics keeps them (the JSON's own), drawn."""
    triads = kin.structure.triads()
    for n, g in enumerate(triads):
        S, choice, Qs, Ps = special_point_of(kin, g)  # as the solved kinematics keeps it
        Q = [complex(x[k]) for x in Qs]
        P = [complex(x[k]) for x in Ps]
        _mark(rec, placer, T, complex(S[k]), Q, P, PAIRS[int(choice[k])], f"{pid}-{ident(g.name)}", size,
              "S" if len(triads) == 1 else f"S{'′' * n}")


def special_point(rec: Recording, placer: Placer, T: Transform, gf: Any, k: int, pts: dict[str, complex],
                  pid: str, size: float, kin: Any = None) -> None:
    """S on the group cut free (the force analysis' moment point); the slot of the base a block
    leash slides in is drawn with every moving guide's slot (:func:`drawings.linkage.free_body.draw_slot`)."""
    outer = gf.reactions[:3]
    inner = gf.reactions[3:]
    Q = [complex(rc.r[k]) for rc in outer]
    P = [complex(rc.r[k]) for rc in inner]
    i, j, _ = gf.leashes(k)
    _mark(rec, placer, T, complex(gf.S[k]), Q, P, (i, j), pid, size)
