"""The mistakes students make on the plans, replayed by the construction itself.

A *slip* is one mistake made at one place of the construction: the Coriolis vector laid
off the wrong way, a normal component laid off from the pole (or toward the wrong end),
a tangential line drawn along the link instead of across it, a point found by similarity
from the wrong end of its link (or with the ratio inverted), a plan drawn at another
scale than the one written.  :class:`SlipPencil` is the perfect pencil with the slips in
it, one case of the construction's arrays per slip: the whole sheet a student with that
slip would draw, every consequence downstream included (a point moved by a reversed
Coriolis vector moves the points found from it, ω read off a plan drawn at the wrong
scale puts the wrong normal components on the acceleration plan).

:func:`inventory` lists the slips a position admits (from a clean run that records what
the construction lays off, rules and marks); :func:`replay` draws them all in one run.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import Any

import numpy as np

from plans.check import wording as wd
from plans.kinematics.cases import cross, unit
from plans.kinematics.construction import plans_of
from plans.kinematics.dyads import Builder, Scheme
from plans.kinematics.exact import Kinematics
from plans.tolerances import AGREE_REL

#: Kinds of mistake, most important first (the report's and the JSON's names).
KINDS = ("coriolis_reversed", "normal_from_pole", "tangential_wrong_line", "scale", "similarity",
         "wrong_segment", "inertia_sign", "reaction_swapped", "fij_reversed", "pi_rounded",
         "g_rounded", "arithmetic")

_TOKEN = r"[A-Z][a-z]*\d*"


@dataclass(frozen=True, slots=True)
class Slip:
    """One mistake at one place: ``target`` is what the construction calls the vector
    (``k_A3A2``, ``n_BA``), the line (``⟂ AB``) or the point (``s2``) done wrong."""

    kind: str
    target: str
    variant: str = ""  # reversed | from_pole | sense | along | wrong_end | inverted | drawn
    phase: str = ""  # velocity | acceleration
    index: int = -1  # the n-th line or mark of the run (lines, marks)
    factor: float = 1.0  # a plan drawn at factor × its written scale
    link: int = 0  # the link whose point is found by similarity
    point: str = ""
    read_mm: tuple[float, float] = (0.0, 0.0)  # a segment of this length read as that one


@dataclass
class _Record:
    """What a clean run lays off, rules and marks, in order."""

    vectors: list[tuple[str, str]] = field(default_factory=list)  # (phase, out)
    lines: list[tuple[str, int]] = field(default_factory=list)  # (phase, index in the plan's lines)
    marks: list[tuple[str, int]] = field(default_factory=list)  # (phase, len(order) at the mark)


class SlipPencil:
    """The perfect pencil drawing one case per slip (arrays over the slips)."""

    exact = False  # cases differ: a point may coincide with another in one case and not in the next

    def __init__(self, slips: list[Slip], record: _Record | None = None) -> None:
        self.slips = slips
        self.m = len(slips)
        self.record = record
        self.b: Builder | None = None
        self.phase = ""
        self.n_line = 0
        self.n_mark = 0

    def attach(self, b: Builder) -> None:
        self.b, self.phase = b, b.kind

    def _image_of(self, point: str) -> Any:
        """The image of ``point`` on the plan being drawn (the pole for a frame point)."""
        b = self.b
        assert b is not None
        for (_, name), lb in b.labels.items():
            if name == point:
                return b.pts[lb]
        return None

    def vector(self, length: Any, direction: Any, span: Any, out: str) -> Any:
        if self.record is not None:
            self.record.vectors.append((self.phase, out))
        vec = length * unit(direction)
        if not self.m:
            return vec
        factor = np.ones(self.m, complex)
        shift = np.zeros(self.m, complex)
        for i, s in enumerate(self.slips):
            if s.kind == "scale" and s.variant == "drawn" and s.phase == self.phase:
                factor[i] *= s.factor
            elif out != s.target or s.phase != self.phase:
                continue
            elif s.kind == "coriolis_reversed" or (s.kind == "normal_from_pole" and s.variant == "sense"):
                factor[i] = -1.0
            elif s.kind == "normal_from_pole":
                frm = self._image_of(_tokens(out[2:])[-1])
                if frm is not None:
                    shift[i] = -np.broadcast_to(frm, (self.m,))[i]
        return vec * factor + shift

    def line(self, direction: Any, span: Any) -> Any:
        u = unit(direction)
        n, self.n_line = self.n_line, self.n_line + 1
        if self.record is not None and self.b is not None:
            self.record.lines.append((self.phase, len(self.b.lines)))
        if not self.m:
            return u
        turn = np.array([1j if s.kind == "tangential_wrong_line" and s.index == n else 1.0 for s in self.slips])
        return u * turn

    def mark(self, z: Any, along: Any = None, joint: bool = False) -> Any:
        n, self.n_mark = self.n_mark, self.n_mark + 1
        b = self.b
        assert b is not None
        if self.record is not None:
            self.record.marks.append((self.phase, len(b.order)))
        hits = [i for i, s in enumerate(self.slips) if s.kind == "similarity" and s.index == n]
        if not hits:
            return z
        out = np.array(np.broadcast_to(z, (self.m,)), complex)
        for i in hits:
            wrong = _similar_wrong(b, self.slips[i])
            if wrong is not None:
                out[i] = np.broadcast_to(wrong, (self.m,))[i]
        return out

    def read(self, length: Any) -> Any:
        """A length read with the ruler; a segment read between the wrong points gives the
        other pair's length wherever it is read again (ω of its link, a^n = v²/l, a^k)."""
        hits = [i for i, s in enumerate(self.slips) if s.kind == "wrong_segment"]
        if not hits:
            return length
        out = np.array(np.broadcast_to(length, (self.m,)), float)
        for i in hits:
            clean, wrong = self.slips[i].read_mm
            if abs(out[i] - clean) <= AGREE_REL * max(clean, 1.0):
                out[i] = wrong
        return out

    def cut(self, b: Builder, l1: Any, l2: Any, out: str, exact_xy: Any, group: Any, point: str) -> Any:
        """Two lines intersected; where a slip makes them parallel the exact point stands
        (such a slip explains nothing and is not chosen)."""
        (p1, d1), (p2, d2) = l1, l2
        s = cross(d1, d2)
        near = np.abs(s) <= 1e-9
        t = cross(p2 - p1, d2) / np.where(near, 1.0, s)
        return np.where(near, exact_xy, p1 + t * d1)


def _tokens(body: str) -> list[str]:
    import re

    return re.findall(_TOKEN, body)


def _similar_wrong(b: Builder, s: Slip) -> Any:
    """Where the point ``s.point`` of link ``s.link`` lands when its image is found from the
    wrong end of the link's known image, or with the ratio of lengths inverted."""
    snap = b.snap
    link = snap.scene.links[s.link]
    if s.link not in b.ref_pos:
        return None
    ra, ia = b.ref_pos[s.link], b.anchor[s.link][1]
    others = [nm for nm in link.points if nm != s.point and ((s.link, nm) in b.labels or nm in snap.scene.frame_points)]
    if not others:
        return None
    far = max(others, key=lambda nm: float(np.max(np.abs(snap.pos(s.link, nm) - ra))))
    rb = snap.pos(s.link, far)
    if float(np.max(np.abs(rb - ra))) == 0.0:
        return None
    ib = b.image(s.link, far)
    zeta = (snap.pos(s.link, s.point) - ra) / (rb - ra)
    if s.variant == "wrong_end":
        return ib + (ia - ib) * zeta
    mag = np.abs(zeta) ** 2
    return ia + (ib - ia) * zeta / np.where(mag > 0, mag, 1.0)


# --------------------------------------------------------------------------- runs


def _scheme(kin: Kinematics, k: int, m: int) -> Scheme:
    return Scheme(kin, [k] * max(m, 1))


def inventory(kin: Kinematics, k: int, mv: float, ma: float | None) -> list[Slip]:
    """Every slip position ``k`` admits: one per Coriolis vector, per normal component
    (from the pole where its point is not the pole, and in the wrong sense), per line
    drawn across a link, per point found by similarity (two ways)."""
    rec = _Record()
    pencil = SlipPencil([], rec)
    vb, ab = plans_of(_scheme(kin, k, 1), mv, ma, pencil)
    crank = kin.scene.links[kin.scene.driver.link]
    out: list[Slip] = []
    for phase, lab in rec.vectors:
        if lab.startswith("k_"):
            out.append(Slip("coriolis_reversed", lab, "reversed", phase))
        elif lab.startswith("n_") and phase == "acceleration":
            toks = _tokens(lab[2:])
            if toks and set(toks) <= set(crank.points):
                continue  # the crank's normal component is the known vector
            out.append(Slip("normal_from_pole", lab, "sense", phase))
            if toks and toks[-1] not in kin.scene.frame_points:
                out.append(Slip("normal_from_pole", lab, "from_pole", phase))
    plans = {"velocity": vb, "acceleration": ab}
    for n, (phase, at) in enumerate(rec.lines):
        b = plans[phase]
        assert b is not None
        label = b.line_labels[at]
        if label.startswith("⟂"):
            out.append(Slip("tangential_wrong_line", label, "along", phase, index=n))
    for n, (phase, at) in enumerate(rec.marks):
        b = plans[phase]
        assert b is not None
        if at >= len(b.order):
            continue
        lb = b.order[at]
        owner = next(((lid, nm) for (lid, nm), v in b.labels.items() if v == lb and lid != kin.scene.frame), None)
        if owner is None:
            continue
        for variant in ("wrong_end", "inverted"):
            out.append(Slip("similarity", lb, variant, phase, index=n, link=owner[0], point=owner[1]))
    return out


def replay(kin: Kinematics, k: int, mv: float, ma: float | None,
           slips: list[Slip]) -> tuple[dict[str, Any], dict[str, Any]]:
    """Both plans drawn once per slip: {label: plan mm as complex, one per slip}."""
    pencil = SlipPencil(slips)
    vb, ab = plans_of(_scheme(kin, k, len(slips)), mv, ma, pencil)
    m = max(len(slips), 1)
    vp = {lb: np.broadcast_to(z, (m,)) for lb, z in vb.pts.items()}
    ap = {lb: np.broadcast_to(z, (m,)) for lb, z in ab.pts.items()} if ab is not None else {}
    return vp, ap


def effective(kin: Kinematics, k: int, mv: float, ma: float | None, slips: list[Slip],
              floor_mm: float = 0.01) -> list[Slip]:
    """The slips that move some point of a plan (a line turned onto its partner's
    direction leaves the intersection undefined: the construction keeps the right point)."""
    if not slips:
        return []
    vp, ap = replay(kin, k, mv, ma, slips)
    clean_v, clean_a = replay(kin, k, mv, ma, [])
    moved = np.zeros(len(slips), bool)
    for got, ref in ((vp, clean_v), (ap, clean_a)):
        for lb, z in got.items():
            if lb in ref:
                moved |= np.abs(z - ref[lb][0]) > floor_mm
    return [s for s, m in zip(slips, moved, strict=True) if m]


def describe(s: Slip) -> wd.Words:
    """The slip in a teacher's words (its English the report's ``detail``)."""
    on = wd.say("ca_plan", kind=wd.plan(s.phase))
    if s.kind == "coriolis_reversed":
        return wd.say("ca_coriolis", t=s.target[2:], plan=on)
    if s.kind == "normal_from_pole":
        toks = _tokens(s.target[2:])
        name = f"a_{s.target[2:]}^n"
        if s.variant == "sense":
            return wd.say("ca_normal_sense", name=name, end=toks[-1] if toks else wd.say("ca_the_centre"))
        return wd.say("ca_normal_pole", name=name, end=toks[-1])
    if s.kind == "tangential_wrong_line":
        return wd.say("ca_tangential", t=s.target, plan=on)
    if s.kind == "similarity":
        how = wd.say("ca_wrong_end") if s.variant == "wrong_end" else wd.say("ca_inverted")
        return wd.say("ca_similarity", t=s.target, point=s.point, link=str(s.link), plan=on, how=how)
    if s.kind == "scale":
        return wd.say("ca_scale_drawn_at", plan=wd.say("ca_plan_nom", kind=wd.plan(s.phase)), f=wd.n(s.factor, ".4g"))
    return wd.say("ca_kind", kind=s.kind)
