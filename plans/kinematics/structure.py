"""Structural analysis: Chebyshev mobility and the decomposition into the
initial link and class-II Assur groups (dyads), in attachment order.

A dyad is two links i, j with three pairs: J1 joins i to an already known link
p, J2 joins i to j, J3 joins j to a known link q.  Its kind is the letters of
(J1, J2, J3): RRR, RRP, RPR, PRP, RPP (mirror images PRR, PPR are turned round).
"""

from __future__ import annotations

from dataclasses import field
from typing import Any, cast

from plans.errors import InputError, Said
from plans.records import derived, frozen
from plans.scene.model import Joint, Scene

KINDS = ("RRR", "RRP", "RPR", "PRP", "RPP")


@frozen
class Group:
    """One Assur group of class II, ready to solve: ``links = (i, j)``,
    ``joints = (J1, J2, J3)``, ``known = (p, q)``."""

    kind: str
    links: tuple[int, int]
    joints: tuple[Joint, Joint, Joint]
    known: tuple[int, int]
    branch: int
    name: str = field(init=False, compare=False)  # "i-j", smaller link first

    def __post_init__(self) -> None:
        a, b = sorted(self.links)
        object.__setattr__(self, "name", f"{a}-{b}")

    @property
    def point(self) -> str:
        """The point the group's construction finds (the inner joint, or A on the slotted link)."""
        return self.joints[1].point


@frozen
class TriadGroup:
    """A class-III group of the third order: a base link with three inner pairs D, E, F and
    three leashes joining them to pairs A, B, C of known links (pairs R; a leash may be a
    slider carrying its inner pin along a guide of the frame: its outer pair P at that pin; or
    a block pinned at its outer pair, sliding in a slot of the base: its inner pair P there).
    ``links = (base, l1, l2, l3)``, ``joints = ((A, D), (B, E), (C, F))`` as (outer, inner)
    pairs of each leash, ``known = (p1, p2, p3)`` the links carrying A, B, C."""

    kind: str  # "RRR" (revolute leashes), else each leash's (outer, inner) pairs: "RR-RR-PR", "RR-RR-RP"
    links: tuple[int, int, int, int]
    joints: tuple[tuple[Joint, Joint], tuple[Joint, Joint], tuple[Joint, Joint]]
    known: tuple[int, int, int]
    branch: int
    name: str = field(init=False, compare=False)

    def __post_init__(self) -> None:
        object.__setattr__(self, "name", "-".join(str(k) for k in sorted(self.links)))

    @property
    def point(self) -> str:
        """The base link's first inner pair (the point its place is found from)."""
        return self.joints[0][1].point

    def to_json(self) -> dict:
        return {"name": self.name, "kind": self.kind, "class": 3, "order": 3, "links": list(self.links),
                "attached_to": list(self.known), "point": self.point, "branch": self.branch,
                "base": self.links[0], "leashes": [[o.point, i.point] for o, i in self.joints]}


@frozen
class Structure:
    """The mechanism's structure: the initial link and its Assur groups in the order they are solved."""

    n: int  # moving links
    p5: int  # lower pairs
    p4: int  # higher pairs
    initial: tuple[int, int]  # (driving link, frame)
    groups: tuple[Group, ...]

    @property
    def mobility(self) -> int:
        """W = 3n − 2p5 − p4 (Chebyshev)."""
        return 3 * self.n - 2 * self.p5 - self.p4

    def formula(self) -> str:
        return (f"W = 3n - 2p5 - p4 = 3*{self.n} - 2*{self.p5} - {self.p4} = {self.mobility}; "
                f"initial link {self.initial[0]}-{self.initial[1]}"
                + "".join(f" + {'class-III ' if isinstance(g, TriadGroup) else ''}{g.kind} group {g.name}"
                          for g in self.groups))

    def to_json(self) -> dict:
        return {
            "n": self.n, "p5": self.p5, "p4": self.p4, "W": self.mobility,
            "initial_link": list(self.initial),
            "groups": [g.to_json() if isinstance(g, TriadGroup) else
                       {"name": g.name, "kind": g.kind, "links": list(g.links),
                        "attached_to": list(g.known), "point": g.point, "branch": g.branch}
                       for g in self.groups],
        }

    def triads(self) -> list[TriadGroup]:
        # the groups are typed as dyads for the many readers that handle only those
        return [g for g in cast(tuple[Any, ...], self.groups) if isinstance(g, TriadGroup)]

    def no_triad(self, path: str, what: str | Said) -> None:
        """Refuse, in one line, what is not yet done for a class-III group."""
        for g in self.triads():
            raise InputError(Said("ks_what_class_iii", what=what, kind=g.kind, name=g.name),
                             file=path, field="outputs")


def analyse(scene: Scene) -> Structure:
    """Mobility and Assur groups derived from links and joints alone (once per scene)."""
    kept = derived(scene)
    done = kept.get("structure")
    if done is None:
        done = kept["structure"] = _analyse(scene)
    return done


def _analyse(scene: Scene) -> Structure:
    fail = _failer(scene.path)
    n = len(scene.links)
    p5 = len(scene.joints)
    w = 3 * n - 2 * p5
    if w != 1:
        raise fail("joints", Said("ks_mobility_one_driving", n=n, p5=p5, w=w))
    drv = scene.driver.link
    frame = scene.frame
    base = [j for j in scene.joints if set(j.links) == {drv, frame}]
    if len(base) != 1 or base[0].kind != "R" or base[0].point != scene.driver.pivot:
        raise fail("driver.link", Said("ks_link_drv_must", drv=drv, frame=frame, pivot=scene.driver.pivot))
    groups = _groups(scene, {drv, frame})
    return Structure(n=n, p5=p5, p4=0, initial=(drv, frame), groups=tuple(groups))


def _groups(scene: Scene, known: set[int]) -> list[Group]:
    """Assur groups in attachment order: at each step the first pair (i < j) of unknown links
    joined to each other by one pair and each to the known links by one pair.

    Linear in the number of groups: every link keeps the count of its pairs with known links,
    updated only around the links that a group makes known; the pairs to try are those of the
    links with exactly one such pair (a handful at any step)."""
    by_link: dict[int, list[Joint]] = {}
    between: dict[tuple[int, int], list[Joint]] = {}
    for jt in scene.joints:
        a, b = jt.links
        by_link.setdefault(a, []).append(jt)
        by_link.setdefault(b, []).append(jt)
        between.setdefault((min(a, b), max(a, b)), []).append(jt)
    remaining = set(scene.links) - known
    to_known = {k: sum(1 for jt in by_link.get(k, ()) if jt.other(k) in known) for k in remaining}
    ready = {k for k in remaining if to_known[k] == 1}
    groups: list[Group] = []
    while remaining:
        found = None
        for i in sorted(ready):
            for j in sorted({jt.other(i) for jt in by_link[i]} & ready):
                if j > i and len(between[(i, j)]) == 1:
                    outer_i = next(jt for jt in by_link[i] if jt.other(i) in known)
                    outer_j = next(jt for jt in by_link[j] if jt.other(j) in known)
                    found = _orient(scene, i, j, outer_i, between[(i, j)][0], outer_j)
                    break
            if found is not None:
                break
        if found is None:
            found = cast(Group, _triad(scene, known, remaining, by_link, between))
        if found is None:
            raise _failer(scene.path)("joints", f"links {sorted(remaining)} do not form class-II Assur "
                                                f"groups attached to links {sorted(known)}")
        groups.append(found)
        for k in found.links:
            known.add(k)
            remaining.discard(k)
            ready.discard(k)
        for k in found.links:
            for jt in by_link.get(k, ()):
                m = jt.other(k)
                if m in remaining:
                    to_known[m] += 1
                    if to_known[m] == 1:
                        ready.add(m)
                    else:
                        ready.discard(m)
    return groups


def _triad(scene: Scene, known: set[int], remaining: set[int], by_link: dict, between: dict) -> TriadGroup | None:
    """The first triad among the unknown links: a base link b (no pair with a known link)
    joined by one pair each to three leashes, each leash joined by one pair to a known
    link and having no other pair yet."""
    for b in sorted(remaining):
        if any(jt.other(b) in known for jt in by_link.get(b, ())):
            continue
        leashes = []
        for k in sorted({jt.other(b) for jt in by_link.get(b, ())} & remaining):
            outer = [jt for jt in by_link[k] if jt.other(k) in known]
            if len(outer) == 1 and len(between[(min(b, k), max(b, k))]) == 1:
                leashes.append((k, outer[0], between[(min(b, k), max(b, k))][0]))
        if len(leashes) < 3:
            continue
        leashes = leashes[:3]
        name = "-".join(str(x) for x in sorted([b] + [k for k, _, _ in leashes]))
        for k, o, i in leashes:
            slider = (o.kind == "P" and i.kind == "R" and o.guide is not None and o.guide.link == scene.frame
                      and o.point == i.point)
            block = (o.kind == "R" and i.kind == "P" and i.guide is not None and i.guide.link == b
                     and o.point == i.point)
            if not (o.kind == "R" and i.kind == "R" or slider or block):
                raise _failer(scene.path)(f"joints (triad {name})", "a class-III group is solved with revolute "
                                          f"pairs only, a leash that is a slider carrying its inner pin along a "
                                          f"guide of the frame, or a block pinned at its outer pair sliding in a "
                                          f"slot of the base link; link {k} has another prismatic pair")
        branch = scene.branches.get(name, scene.branches.get(leashes[0][2].point, 1))
        codes = [o.kind + i.kind for _, o, i in leashes]
        return TriadGroup(kind="RRR" if codes == ["RR"] * 3 else "-".join(codes),
                          links=(b, leashes[0][0], leashes[1][0], leashes[2][0]),
                          joints=tuple((o, i) for _, o, i in leashes),  # type: ignore[arg-type]
                          known=tuple(o.other(k) for k, o, _ in leashes),  # type: ignore[arg-type]
                          branch=branch)
    return None


def _failer(path: str):
    def fail(field: str, msg: str | Said) -> InputError:
        return InputError(msg, file=path, field=field)
    return fail


def _orient(scene: Scene, i: int, j: int, j1: Joint, j2: Joint, j3: Joint) -> Group:
    """Turn the group so its kind is one of KINDS and check the variant is one we solve."""
    fail = _failer(scene.path)
    kind = j1.kind + j2.kind + j3.kind
    if kind in ("PRR", "PPR") or (kind == "RPR" and j2.guide is not None and j2.guide.link == i):
        i, j, j1, j3 = j, i, j3, j1
        kind = kind[::-1]
    name = f"{min(i, j)}-{max(i, j)}"
    where = f"joints ({kind} group {name})"
    if kind == "PPP":
        raise fail(where, Said("ks_three_prismatic_pairs"))
    p, q = j1.other(i), j3.other(j)
    if kind == "RRP":
        if j3.guide is None or j3.guide.link != q or j3.point != j2.point:
            raise fail(where, Said("ks_slider_must_carry", j=j, point=j2.point, q=q))
    elif kind == "RPR":
        if j2.guide is None or j2.guide.link != j or j2.point != j1.point:
            raise fail(where, Said("ks_block_pinned_point", i=i, point=j1.point, j=j))
    elif kind == "PRP":
        for jt, carrier in ((j1, p), (j3, q)):
            if jt.guide is None or jt.guide.link != carrier or jt.point != j2.point:
                raise fail(where, Said("ks_both_sliders_must", point=j2.point))
    elif kind == "RPP":
        if j2.guide is None or j2.guide.link != j or j2.point != j1.point:
            raise fail(where, Said("ks_block_pinned_point", i=i, point=j1.point, j=j))
        if j3.guide is None or j3.guide.link != q:
            raise fail(where, Said("ks_link_must_slide", j=j, q=q))
    branch = scene.branches.get(name, scene.branches.get(j2.point, 1))
    return Group(kind=kind, links=(i, j), joints=(j1, j2, j3), known=(p, q), branch=branch)
