"""Instant centres of velocity by Kennedy's theorem (Aronhold–Kennedy, three centres).

For n links (the frame included) there are n(n−1)/2 centres P_ij.  Primary centres are
read off the pairs: a revolute pair is its own centre; a sliding pair (the slider keeps its
angle to the link that carries the guide) puts the centre at infinity, perpendicular to the
guide.  Every other centre is found as the draftsman finds it on the circle diagram: P_ij
lies on the line through P_ik and P_kj for every third link k, so two such lines (two
triangles of the circle diagram closed by the edge ij) meet at P_ij.  Of all the lines
available the two at the largest angle are taken (the sharpest intersection).

A centre at infinity is a direction (the relative motion of the two links is a
translation, ω_i = ω_j); two parallel Kennedy lines give it.  Where every pair of lines
coincides (or no two are known yet), the centre is left undetermined and said so: no
number is made up for it.

Plane vectors are complex numbers, as in :mod:`plans.kinematics.exact`; everything is in
metres in the scene's frame.
"""

from __future__ import annotations

import cmath
from collections.abc import Iterator
from itertools import combinations
from typing import TYPE_CHECKING, Any

from plans.records import frozen
from plans.tolerances import COINCIDE_REL, LOCK_SIN, ROUND_OFF_REL

if TYPE_CHECKING:
    from plans.kinematics.exact import Kinematics

#: |sin| of the angle between two Kennedy lines below which they are taken as parallel
#: (links related by sliding pairs give lines parallel to rounding, ~1e-16).
PARALLEL = LOCK_SIN
#: Distance between two parallel lines, as a fraction of the mechanism's size, below which
#: they are one line (the centre is then not fixed by them).
COINCIDENT = COINCIDE_REL


@frozen
class Centre:
    """P_ij: a point (m), or a direction at infinity (unit vector), or neither (undetermined).

    ``source`` is "pair" for a primary centre, else the two centres ((i, k), (k, j)) of the
    first Kennedy line (in that order, i < j; look a centre up by its sorted pair) and
    ``other`` the two of the second."""

    links: tuple[int, int]
    point: complex | None
    direction: complex | None
    source: Any  # "pair" | ((i, k), (k, j)) | None
    other: Any = None
    why: str = ""  # for an undetermined centre: what the construction met
    #: "omega_ratio" where Kennedy's lines coincide and the centre is fixed on that line by
    #: the angular velocities (``source`` then names the two centres it divides)
    by: str = ""

    @property
    def label(self) -> str:
        return f"P{self.links[0]}{self.links[1]}" if max(self.links) < 10 else f"P{self.links[0]},{self.links[1]}"

    def to_json(self) -> dict[str, Any]:
        src = self.source if self.source in ("pair", None) else [list(self.source[0]), list(self.source[1])]
        out: dict[str, Any] = {"links": list(self.links),
                               "point": None if self.point is None else _xy(self.point),
                               "direction": None if self.direction is None else _xy(self.direction),
                               "from": src}
        if self.other is not None:
            out["with"] = [list(self.other[0]), list(self.other[1])]
        if self.why:
            out["undetermined"] = self.why
        if self.by:
            out["by"] = self.by
        return out


def _xy(z: complex) -> list[float]:
    return [float(z.real), float(z.imag)]


def _key(i: int, j: int) -> tuple[int, int]:
    return (i, j) if i < j else (j, i)


def _canonical(d: complex) -> complex:
    """A unit direction with a fixed sense (x > 0, or x = 0 and y > 0): a centre at infinity
    lies both ways along its line."""
    d = d / abs(d)
    if d.real < -1e-15 or (abs(d.real) <= 1e-15 and d.imag < 0):
        d = -d
    return complex(d.real + 0.0, d.imag + 0.0)


def all_links(kin: Kinematics) -> list[int]:
    """The links of the circle diagram: the moving ones in order, the frame among them."""
    return sorted(set(kin.scene.links) | {kin.scene.frame})


def primary(kin: Kinematics, k: int) -> dict[tuple[int, int], Centre]:
    """The centres at the pairs at position k."""
    scene = kin.scene
    out: dict[tuple[int, int], Centre] = {}
    for jt in scene.joints:
        key = _key(*jt.links)
        if jt.kind == "R":
            r = complex(kin.point(jt.point, jt.links[0])[0][k])
            out[key] = Centre(key, r, None, "pair")
        else:
            assert jt.guide is not None
            g = jt.guide.link
            rot = cmath.exp(1j * float(kin.theta(g)[k])) if g != scene.frame else 1.0
            out[key] = Centre(key, None, _canonical(1j * rot * jt.guide.direction), "pair")
    return out


def _line(a: Centre, b: Centre, size: float) -> tuple[complex, complex] | None | str:
    """The line through two centres as (point, unit direction); "infinity" for the line at
    infinity (both centres there); None where it is not fixed (one point twice, or unknown)."""
    if a.point is None and a.direction is None or b.point is None and b.direction is None:
        return None
    if a.point is None and b.point is None:
        return "infinity"
    if a.point is None:
        a, b = b, a
    assert a.point is not None
    if b.point is None:
        assert b.direction is not None
        return a.point, b.direction
    d = b.point - a.point
    if abs(d) <= COINCIDENT * size:
        return None
    return a.point, d / abs(d)


def _meet(l1: Any, l2: Any, size: float) -> tuple[str, complex | None, float]:
    """Where two Kennedy lines meet: ("point", z, |sin|), ("direction", d, 0),
    or ("same", None, 0) when the lines coincide."""
    if l1 == "infinity" and l2 == "infinity":
        return "same", None, 0.0
    if l1 == "infinity" or l2 == "infinity":
        line = l2 if l1 == "infinity" else l1
        return "direction", _canonical(line[1]), 2.0  # the centre lies at infinity for certain
    (p1, d1), (p2, d2) = l1, l2
    s = (d1.conjugate() * d2).imag
    if abs(s) <= PARALLEL:
        gap = abs(((p2 - p1) * d1.conjugate()).imag)
        if gap <= COINCIDENT * size:
            return "same", None, 0.0
        return "direction", _canonical(d1), 0.0
    t = ((p2 - p1).conjugate() * d2).imag / s  # p1 + t·d1 on line 2: cross(p1 + t d1 − p2, d2) = 0
    return "point", p1 + t * d1, abs(s)


def kennedy(links: list[int], known: dict[tuple[int, int], Centre], size: float,
            omega: dict[int, float] | None = None) -> dict[tuple[int, int], Centre]:
    """All centres from the primary ones: sweep the unknown edges of the circle diagram,
    closing each by the two best triangles available, until no edge can be added.  With the
    links' angular velocities ``omega``, a centre whose Kennedy lines all coincide is fixed
    on that line as the draftsman fixes it, by the ratio of the angular velocities."""
    found = dict(known)
    pending = [p for p in combinations(links, 2) if p not in found]
    why: dict[tuple[int, int], str] = {}
    progress = True
    while pending and progress:
        progress = _sweep(links, found, pending, why, size)
        if not progress and omega is not None:
            progress = _by_ratio(links, found, pending, why, omega, size)
    for p in pending:
        found[p] = Centre(p, None, None, None, None, why.get(p, "no two Kennedy lines reach it"))
    return {p: found[p] for p in combinations(links, 2)}


def _thirds(links: list[int], found: dict, i: int, j: int) -> Iterator[tuple[int, Centre, Centre]]:
    """Every third link k whose centres with i and with j are both found: (k, P_ik, P_kj)."""
    for k in links:
        if k in (i, j):
            continue
        a, b = found.get(_key(i, k)), found.get(_key(k, j))
        if a is not None and b is not None:
            yield k, a, b


def _by_ratio(links: list[int], found: dict, pending: list, why: dict, omega: dict[int, float], size: float) -> bool:
    """The first centre left open, fixed by a third link k with both P_ik and P_jk known: the
    common point of i and j moves alike as a point of either, relative to k:
    (ω_i − ω_k)(P − P_ik) = (ω_j − ω_k)(P − P_jk), so P divides P_ik P_jk in the ratio of the
    relative angular velocities (on their Kennedy line).  Where ω_i = ω_j the relative motion
    is a translation: P_ij lies at infinity, along two centres at infinity of one direction."""
    scale = max((abs(w) for w in omega.values()), default=0.0)
    if scale == 0.0:
        return False
    for i, j in list(pending):
        wi, wj = omega.get(i, 0.0), omega.get(j, 0.0)
        best: tuple | None = None
        for k, a, b in _thirds(links, found, i, j):
            wk = omega.get(k, 0.0)
            if abs(wi - wj) <= ROUND_OFF_REL * scale:
                if a.direction is not None and b.direction is not None \
                        and abs((a.direction.conjugate() * b.direction).imag) <= PARALLEL:
                    best = (2.0 * size, None, a.direction, k)
                continue
            if a.point is None or b.point is None:
                continue
            z = ((wi - wk) * a.point - (wj - wk) * b.point) / (wi - wj)
            spread = abs(a.point - b.point) + min(abs(wi - wk), abs(wj - wk)) / scale * size
            if best is None or spread > best[0]:
                best = (spread, z, None, k)
        if best is None:
            continue
        _, z, d, k = best
        found[(i, j)] = Centre((i, j), z, d, ((i, k), (k, j)), None, by="omega_ratio")
        pending.remove((i, j))
        why.pop((i, j), None)
        return True
    return False


def _sweep(links: list[int], found: dict, pending: list, why: dict, size: float) -> bool:
    """One sweep of the open edges by Kennedy's lines; True if any centre was added."""
    progress = False
    for i, j in list(pending):
        lines = []
        for k, a, b in _thirds(links, found, i, j):
            ln = _line(a, b, size)
            if ln is not None:
                lines.append((ln, ((i, k), (k, j))))
        best: tuple | None = None
        same = False
        for (l1, s1), (l2, s2) in combinations(lines, 2):
            kind, z, sin = _meet(l1, l2, size)
            if kind == "same":
                same = True
                continue
            rank = (sin >= 2.0, kind == "point", sin)
            if best is None or rank > best[0]:
                best = (rank, kind, z, s1, s2)
        if best is None:
            if same:
                why[(i, j)] = "Kennedy's lines coincide"
            continue
        _, kind, z, s1, s2 = best
        found[(i, j)] = Centre((i, j), z if kind == "point" else None, z if kind == "direction" else None,
                               s1, s2)  # as the circle diagram reads them: (i, k), (k, j)
        pending.remove((i, j))
        why.pop((i, j), None)
        progress = True
    return progress


def size_of(kin: Kinematics) -> float:
    return kin.reach()


def centres_at(kin: Kinematics, k: int) -> dict[tuple[int, int], Centre]:
    """All n(n−1)/2 instant centres at position k, keyed (i, j) with i < j."""
    scene = kin.scene
    omega = {j: (0.0 if j == scene.frame else float(kin.omega(j)[k])) for j in all_links(kin)}
    return kennedy(all_links(kin), primary(kin, k), size_of(kin), omega)


@frozen
class CentreVelocity:
    """The velocity of a point found by the centres from the driver's ω alone, next to the
    exact one: v_P = ω1·|P_1f P_1j| at the centre P_1j, ω_j = v_P / |P_jf P_1j|, v = ω_j·|P_jf Q|."""

    point: str
    link: int
    centre: tuple[int, int] | None  # P_jf about which the link turns (None: it translates)
    distance: float | None  # |P_jf Q| (m)
    omega: float | None  # ω_j by the centres (rad/s, counter-clockwise positive)
    v: complex | None
    exact: complex

    def to_json(self) -> dict[str, Any]:
        return {"point": self.point, "link": self.link,
                "centre": None if self.centre is None else list(self.centre),
                "distance": self.distance, "omega": self.omega,
                "v": None if self.v is None else abs(self.v),
                "v_vector": None if self.v is None else _xy(self.v),
                "v_exact": abs(self.exact)}


def velocities_at(kin: Kinematics, k: int, centres: dict[tuple[int, int], Centre]) -> list[CentreVelocity]:
    """Velocities of the named points of the moving links by the instant centres."""
    scene = kin.scene
    f, d = scene.frame, scene.driver.link
    w1 = float(kin.omega(d)[k])
    p1f = centres[_key(d, f)].point
    out = []
    for nm in kin.point_names():
        j = kin.home(nm)
        if j == f:
            continue
        q = complex(kin.point(nm, j)[0][k])
        exact = complex(kin.point(nm, j)[1][k])
        v, wj, dist, about = _by_centres(centres, d, f, j, w1, p1f, q)
        out.append(CentreVelocity(nm, j, about, dist, wj, v, exact))
    return out


def _by_centres(centres: dict, d: int, f: int, j: int, w1: float, p1f: complex | None,
                q: complex) -> tuple[complex | None, float | None, float | None, tuple[int, int] | None]:
    if p1f is None:
        return None, None, None, None
    pjf = centres[_key(j, f)]
    if j == d:
        return 1j * w1 * (q - p1f), w1, abs(q - p1f), _key(j, f)
    p1j = centres[_key(d, j)]
    if p1j.point is not None:
        vp = 1j * w1 * (p1j.point - p1f)  # the common point of links 1 and j, as a point of 1
        if pjf.direction is not None:  # link j translates: every point moves as P_1j
            return vp, 0.0, None, None
        if pjf.point is None:
            return None, None, None, None
        arm = p1j.point - pjf.point
        if abs(arm) == 0.0:
            return None, None, None, _key(j, f)
        wj = (vp / (1j * arm)).real
    elif p1j.direction is not None:  # j translates relative to 1: the same ω
        wj = w1
        if pjf.point is None:
            return None, None, None, None
    else:
        return None, None, None, None
    assert pjf.point is not None
    return 1j * wj * (q - pjf.point), wj, abs(q - pjf.point), _key(j, f)


def centres_json(kin: Kinematics, k: int, readings: Any = ()) -> dict[str, Any]:
    """``instant_centres`` and ``velocities_by_centres`` of position k; each velocity is
    given next to the exact one and, where the velocity plan read it, the plan's value."""
    centres = centres_at(kin, k)
    plan = {r.quantity: r.value for r in readings}
    vel = []
    for cv in velocities_at(kin, k, centres):
        e = cv.to_json()
        e["v_plan"] = plan.get(f"v_{cv.point}")
        vel.append(e)
    return {"instant_centres": [c.to_json() for c in centres.values()], "velocities_by_centres": vel}
