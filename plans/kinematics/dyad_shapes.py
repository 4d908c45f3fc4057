"""What the velocity and the acceleration plan of a dyad share, written once: the dyad's
links and pairs, its points on the scheme, the images of its known points on the plan,
and how its links take the point the construction finds.

The construction itself (which lines, through which points, what is laid off first) stays
in :mod:`plans.kinematics.velocities` and :mod:`plans.kinematics.accelerations`, one
function per dyad, as the textbook draws it.  A shape's names are the constructions':
``i``, ``j`` the dyad's links, ``p``, ``q`` the known links they join, ``j1``, ``j2``,
``j3`` its pairs (outer, inner, outer), ``out`` the label of the point found.
"""

from __future__ import annotations

from collections.abc import Callable
from typing import TYPE_CHECKING, Any

from plans.kinematics.dyads import Builder, Scheme, coincident, ensure, lab, link_points, read_rates
from plans.kinematics.structure import Group, TriadGroup

if TYPE_CHECKING:
    from plans.kinematics.dyads import C


class Crank:
    """The initial link O–A: its pivot O and pin A by name, their positions, its length."""

    __slots__ = ("A", "O", "PA", "PO", "driver", "l1")

    def __init__(self, snap: Scheme) -> None:
        d = self.driver = snap.scene.driver
        self.O, self.A = d.pivot, snap.scene.links[d.link].axis[1]
        self.PO, self.PA = snap.pos(d.link, self.O), snap.pos(d.link, self.A)
        self.l1 = abs(self.PA - self.PO)

    def known(self, b: Builder, a: str, factor: C) -> None:
        """The crank's image: O at the pole, A at ``a``, the link's similarity factor."""
        link = self.driver.link
        b.labels[(link, self.A)] = a
        b.labels[(link, self.O)] = b.pole
        b.set_link(link, a, self.PA, factor)


def each_group(b: Builder, dyad: Callable[[Group], None], triad: Callable[[TriadGroup], None]) -> None:
    """The crank's points, then each Assur group in the order of formation and the points of
    its links by similarity; last the links' ω (ε) read off the plan."""
    link_points(b, b.snap.scene.driver.link)
    for g in b.snap.kin.structure.groups:
        if isinstance(g, TriadGroup):  # class III: by Assur's special point
            triad(g)
        else:
            dyad(g)
        for lid in g.links:
            link_points(b, lid)
    read_rates(b)


class _Shape:
    __slots__ = ("i", "j", "j1", "j2", "j3", "out", "p", "q")

    def __init__(self, g: Group) -> None:
        self.i, self.j = g.links
        self.j1, self.j2, self.j3 = g.joints
        self.p, self.q = g.known


class RRR(_Shape):
    """A–B–C: A on link p, C on link q known; B where link i (AB) and link j (CB) meet."""

    __slots__ = ("B", "P1", "P3", "n1", "n3", "x1", "x3")

    def __init__(self, b: Builder, g: Group) -> None:
        super().__init__(g)
        snap, (j1, j2, j3), (p, q) = b.snap, g.joints, g.known
        self.P1, self.B, self.P3 = snap.pos(p, j1.point), snap.pos(self.i, j2.point), snap.pos(q, j3.point)
        self.x1, self.x3 = b.image(p, j1.point), b.image(q, j3.point)
        self.n1 = ensure(b, p, j1.point, self.x1)
        self.n3 = ensure(b, q, j3.point, self.x3)
        self.out = lab(j2.point)

    def take(self, b: Builder, xb: C, r1: str, r3: str) -> None:
        """Links i and j through b; their ω (ε) read off r1–b and r3–b."""
        B, out = self.B, self.out
        b.set_link(self.i, out, B, (xb - self.x1) / (B - self.P1))
        b.set_link(self.j, out, B, (xb - self.x3) / (B - self.P3))
        b.rate[self.i], b.rate[self.j] = (r1, out, abs(B - self.P1)), (r3, out, abs(B - self.P3))


class RRP(_Shape):
    """A–B on link i, A on link p known; B a slider of link j on a guide of link q."""

    __slots__ = ("B", "P1", "n1", "span", "u", "x1")

    def __init__(self, b: Builder, g: Group) -> None:
        super().__init__(g)
        snap, (j1, j2, j3), p = b.snap, g.joints, g.known[0]
        self.P1, self.B = snap.pos(p, j1.point), snap.pos(self.i, j2.point)
        self.u, self.span = snap.guide(j3)
        self.x1 = b.image(p, j1.point)
        self.n1 = ensure(b, p, j1.point, self.x1)
        self.out = lab(j2.point)

    def take(self, b: Builder, xb: C, r1: str) -> None:
        """Link i through b, its ω (ε) read off r1–b; the slider j turns with its guide q."""
        B, out = self.B, self.out
        b.set_link(self.i, out, B, (xb - self.x1) / (B - self.P1))
        b.set_link(self.j, out, B, b.factor[self.q])
        b.rate[self.i], b.rate[self.j] = (r1, out, abs(B - self.P1)), self.q


class RPR(_Shape):
    """A block i pinned at A to link p slides in the slot of link j, which turns about C on q."""

    __slots__ = ("A", "Cq", "na", "nc", "span", "u", "xa", "xc")

    def __init__(self, b: Builder, g: Group) -> None:
        super().__init__(g)
        snap, (j1, j2, j3), (p, q) = b.snap, g.joints, g.known
        self.A, self.Cq = snap.pos(p, j1.point), snap.pos(q, j3.point)
        self.u, self.span = snap.guide(j2)  # the slot carried by j, from j's placed pose
        self.xa, self.xc = b.image(p, j1.point), b.image(q, j3.point)
        self.na = ensure(b, p, j1.point, self.xa)
        self.nc = ensure(b, q, j3.point, self.xc)
        self.out = f"{lab(j1.point)}{self.j}"

    def take(self, b: Builder, x3: C, rc: str) -> None:
        """Link j through the point of it under A, its ω (ε) read off rc–out; the block turns with j."""
        A, out = self.A, self.out
        f = (x3 - self.xc) / (A - self.Cq)
        b.set_link(self.j, out, A, f)
        b.set_link(self.i, self.na, A, f)
        b.rate[self.j], b.rate[self.i] = (rc, out, abs(A - self.Cq)), self.j
        b.labels[(self.i, self.j1.point)] = self.na


class PRP(_Shape):
    """Two sliders i and j pinned at B, on guides of the known links p and q."""

    __slots__ = ("B", "span1", "span3", "u1", "u3")

    def __init__(self, b: Builder, g: Group) -> None:
        super().__init__(g)
        snap = b.snap
        self.B = snap.pos(self.i, self.j2.point)
        self.u1, self.span1 = snap.guide(self.j1)
        self.u3, self.span3 = snap.guide(self.j3)
        self.out = lab(self.j2.point)

    def take(self, b: Builder) -> None:
        """Each slider turns with its guide."""
        b.set_link(self.i, self.out, self.B, b.factor[self.p])
        b.set_link(self.j, self.out, self.B, b.factor[self.q])
        b.rate[self.i], b.rate[self.j] = self.p, self.q


class RPP(_Shape):
    """A block i pinned at A to link p slides in the slot of link j, a slider on a guide of q."""

    __slots__ = ("A", "na", "nq", "span2", "span3", "u2", "u3", "xa", "xq")

    def __init__(self, b: Builder, g: Group) -> None:
        super().__init__(g)
        snap, j1, p = b.snap, self.j1, self.p
        self.A = snap.pos(p, j1.point)
        self.u2, self.span2 = snap.guide(self.j2)
        self.u3, self.span3 = snap.guide(self.j3)
        self.xa = b.image(p, j1.point)
        self.na = ensure(b, p, j1.point, self.xa)
        self.out = f"{lab(j1.point)}{self.j}"
        self.nq, self.xq = coincident(b, self.q, j1.point, self.A)

    def take(self, b: Builder) -> None:
        """Link j turns with its guide q, the block with j."""
        b.set_link(self.j, self.out, self.A, b.factor[self.q])
        b.set_link(self.i, self.na, self.A, b.factor[self.q])
        b.rate[self.j], b.rate[self.i] = self.q, self.q
        b.labels[(self.i, self.j1.point)] = self.na


#: The shape of each dyad kind.
SHAPES: dict[str, type[Any]] = {"RRR": RRR, "RRP": RRP, "RPR": RPR, "PRP": PRP, "RPP": RPP}
