"""Quantities by their textbook names, read off a :class:`plans.solution.Solution`.

One table of names (:data:`PATTERNS`) serves every reader: ``Solution.value``, the checker
(:mod:`plans.check.providers` reads its patterns from here) and whoever writes a note or a
sheet.  The sign convention is one, written out in docs/quantities.md:

* a vector read off a plan or a polygon (``v_B``, ``v_BA``, ``a_BA^n``, ``a^k_A3A2``, ``F_12``)
  is its magnitude, ≥ 0, in SI;
* a rate of a link (``omega_3``, ``eps_3``) and a moment (``M_Phi_2``) are signed,
  counter-clockwise positive, as in the JSON;
* a component of a reaction (``F_12^τ``, ``F_12^n``) is signed: its projection on the unit
  vectors e_τ and e_n of the joint's Assur group (the JSON's and the polygons' own), and
  ``F_ij^τ = −F_ji^τ``;
* the balancing load (``F_bal`` by kinetostatics, ``F_bal_lever`` by the lever) is signed,
  positive along the motion of its point (N, or N·m for a balancing moment), as in the JSON;
* masses, inertias, weights and lengths are ≥ 0.

``F_ij`` is the force on link i from link j in the scene's ``fij = "on_i_from_j"`` (of link i
on link j in ``"of_i_on_j"``); links numbered 10 and above are written with an underscore
between them: ``F_10_2``, ``F_10_2^τ`` (``F_1_2`` is ``F_12``).
"""

from __future__ import annotations

import re
from typing import TYPE_CHECKING, Any, Protocol

from plans.tolerances import SAME_ANGLE_DEG

if TYPE_CHECKING:
    from plans.forces.lever import LeverAnalysis
    from plans.forces.polygons import ForceAnalysis, Reaction
    from plans.kinematics.construction import PositionPlans
    from plans.kinematics.exact import Kinematics
    from plans.kinematics.plan import Plan
    from plans.scene.model import Scene


class Forces(Protocol):
    """A solution's force analysis and lever (:class:`plans.solution.Forces`)."""

    @property
    def analysis(self) -> ForceAnalysis: ...

    @property
    def lever(self) -> LeverAnalysis: ...


class Solution(Protocol):
    """What the names are read off: a :class:`plans.solution.Solution`."""

    @property
    def scene(self) -> Scene: ...

    @property
    def kinematics(self) -> Kinematics: ...

    @property
    def plans(self) -> tuple[PositionPlans, ...]: ...

    @property
    def forces(self) -> Forces | None: ...


#: Every kind of quantity by the pattern of its name, first match first.
PATTERNS: dict[str, re.Pattern[str]] = {
    "plan": re.compile(r"^[va]_[A-Za-z0-9]+(\^[nτ])?$|^a\^[kr]_\w+$"),
    "angular": re.compile(r"^(omega|eps)_\d+$"),
    "length": re.compile(r"^l_[A-Z][A-Za-z0-9]*$"),
    "loads": re.compile(r"^(m|I|G|Phi|M_Phi|P)_\d+$"),
    "forces": re.compile(r"^F_(\d\d|\d+_\d+)(\^[nτ])?$|^F_bal(_lever)?$"),
    "arms": re.compile(r"^h_\w+$"),
}
#: Quantities that are the student's own and have no exact counterpart.
STUDENT_ONLY = re.compile(r"^(F_bal_diff_pct|h_\w+)$")
#: g where the scene turns gravity off (the weight G = m·g is still a figure of the course).
G_STANDARD = 9.81

_REACTION = re.compile(r"F_(?:(\d)(\d)|(\d+)_(\d+))(\^[nτ])?")
_POINT = re.compile(r"[A-Z][a-z0-9]*")


def kind_of(name: str) -> str | None:
    """The kind of a quantity name (a key of :data:`PATTERNS`), None for an unknown one."""
    return next((kind for kind, pattern in PATTERNS.items() if pattern.match(name)), None)


def reaction_name(name: str) -> tuple[int, int, str | None] | None:
    """``F_12^τ`` -> (1, 2, "^τ"); ``F_10_2`` -> (10, 2, None); None for another name."""
    m = _REACTION.fullmatch(name)
    if m is None:
        return None
    i, j = (m.group(1), m.group(2)) if m.group(1) else (m.group(3), m.group(4))
    return int(i), int(j), m.group(5)


def reaction_label(i: int, j: int) -> str:
    """The name of the reaction F_ij: ``F_12``, or ``F_10_2`` where a link number has two digits."""
    return f"F_{i}{j}" if i < 10 and j < 10 else f"F_{i}_{j}"


def name_of(rc: Reaction, fij: str) -> str:
    """The name of a reaction in the scene's F_ij convention: ``F_21``, ``F_12_1``."""
    return reaction_label(*((rc.on, rc.frm) if fij == "on_i_from_j" else (rc.frm, rc.on)))


def reaction(fa: ForceAnalysis, i: int, j: int) -> tuple[Any, Reaction]:
    """F_ij over the positions and its reaction, in the scene's F_ij convention, either order
    (the other order reversed: F, the couple, F^τ and F^n of the other link).  KeyError where
    links i and j share no joint."""
    on, frm = (i, j) if fa.scene.fij == "on_i_from_j" else (j, i)
    for rc in fa.reactions():
        if (rc.on, rc.frm) == (on, frm):
            return rc.F, rc
        if (rc.on, rc.frm) == (frm, on):
            return -rc.F, rc.reversed()
    raise KeyError(reaction_label(i, j))


def points_of(token: str) -> list[str]:
    """``A3A2`` -> ["A3", "A2"]; [] where the token is not a run of point names."""
    pts = _POINT.findall(token)
    return pts if "".join(pts) == token else []


# --------------------------------------------------------------------------- reading


def position(sol: Solution, phi: float | None) -> int:
    """The index of the scene's position at crank angle ``phi`` (degrees; None: the first)."""
    phis = sol.scene.driver.phis_deg
    if phi is None:
        return 0
    for k, p in enumerate(phis):
        if abs(p - phi) < SAME_ANGLE_DEG:
            return k
    raise ValueError(f"crank angle {phi:g}° is not among the scene's positions {list(phis)}")


def value(sol: Solution, name: str, phi: float | None = None) -> float:
    """The quantity ``name`` at crank angle ``phi`` (see the module's sign convention)."""
    got = _read(sol, name, position(sol, phi))
    if got is None:
        known = names(sol)
        raise KeyError(f"{name!r} is not a quantity of {sol.scene.path}; known: {', '.join(known)}")
    return got


def values(sol: Solution, name: str) -> list[float]:
    """The quantity ``name`` at every position of the scene."""
    return [value(sol, name, phi) for phi in sol.scene.driver.phis_deg]


def names(sol: Solution, k: int = 0) -> list[str]:
    """Every name :func:`value` reads for this solution (at position ``k``)."""
    scene = sol.scene
    out: list[str] = []
    if sol.plans:
        for plan in (sol.plans[k].velocity, sol.plans[k].acceleration):
            if plan is not None:
                out += [s.label for s in plan.segments if PATTERNS["plan"].match(s.label)]
    else:
        out += [f"{q}_{p}" for q in ("v", "a")[:sol.kinematics.order] for p in sol.kinematics.point_names()]
    if sol.kinematics.order >= 1:
        out += [f"omega_{i}" for i in sorted(scene.links)]
    if sol.kinematics.order >= 2:
        out += [f"eps_{i}" for i in sorted(scene.links)]
    if scene.loads is not None:
        loads = scene.loads
        out += [f"m_{i}" for i in sorted(loads.masses) if loads.masses[i] > 0]
        out += [f"G_{i}" for i in sorted(loads.masses) if loads.masses[i] > 0]
        out += [f"I_{i}" for i in sorted(loads.inertias) if loads.inertias[i] > 0]
    if sol.forces is not None:
        fa = sol.forces.analysis
        out += [f"Phi_{f.link}" for f in fa.applied.forces if f.label == f"Phi{f.link}"]
        out += [f"M_Phi_{m.link}" for m in fa.applied.moments if m.kind == "inertia"]
        out += [f"P_{f.link}" for f in fa.applied.forces if f.kind == "gas"]
        for rc in fa.reactions():
            base = name_of(rc, scene.fij)
            out += [base] + ([base + "^τ", base + "^n"] if rc.tau is not None else [])
        out += ["F_bal", "F_bal_lever"]
    return list(dict.fromkeys(out))


def _read(sol: Solution, name: str, k: int) -> float | None:
    kind = kind_of(name)
    if kind == "plan":
        return _plan_value(sol, name, k)
    if kind == "angular":
        what, lid = name.split("_")
        kin = sol.kinematics
        if int(lid) not in sol.scene.links or kin.order < (1 if what == "omega" else 2):
            return None
        return float((kin.omega(int(lid)) if what == "omega" else kin.eps(int(lid)))[k])
    if kind == "length":
        pts = points_of(name[2:])
        if len(pts) != 2:
            return None
        try:
            r = [complex(sol.kinematics.point(p)[0][k]) for p in pts]
        except KeyError:
            return None
        return abs(r[1] - r[0])
    if kind == "loads":
        return _load_value(sol, name, k)
    if kind == "forces":
        return _force_value(sol, name, k)
    return None


def _plan_value(sol: Solution, name: str, k: int) -> float | None:
    """A vector of the velocity or acceleration plan: read off the plan where the scene has
    plans (the exact construction), else from the exact motion of the points."""
    kind = "velocity" if name.startswith("v") else "acceleration"
    if sol.plans:
        pp = sol.plans[k]
        plan = pp.velocity if kind == "velocity" else pp.acceleration
        return None if plan is None else _on_plan(sol, plan, name)
    kin = sol.kinematics
    m = re.fullmatch(r"([va])_([A-Za-z0-9]+)", name)
    if m is None or kin.order < (1 if kind == "velocity" else 2):
        return None
    pts = points_of(m.group(2))
    if len(pts) not in (1, 2):
        return None
    i = 1 if kind == "velocity" else 2
    try:
        z = [complex(kin.point(p)[i][k]) for p in pts]
    except KeyError:
        return None
    return abs(z[0]) if len(z) == 1 else abs(z[0] - z[1])


def _on_plan(sol: Solution, plan: Plan, name: str) -> float | None:
    """The length of the named vector on ``plan`` over its scale: a segment so labelled (its
    points in either order), or from the pole (one point) or between two points' images."""
    def between(a: str, b: str) -> float:
        (xa, ya), (xb, yb) = plan.xy(a), plan.xy(b)
        return abs(complex(xb - xa, yb - ya)) / plan.scale

    for label in _spellings(name):
        try:
            s = plan.segment(label)
        except KeyError:
            continue
        return between(s.start, s.end)
    m = re.fullmatch(r"[va]_([A-Za-z0-9]+)", name)
    pts = points_of(m.group(1)) if m else []
    labels = [plan.pole if p in sol.scene.frame_points else p.lower() for p in pts]
    if len(labels) == 1 and plan.has(labels[0]):
        return between(plan.pole, labels[0])
    if len(labels) == 2 and all(plan.has(x) for x in labels):
        return between(labels[0], labels[1])
    return None


def _spellings(name: str) -> list[str]:
    """A plan's label and the same vector with its two points written the other way round."""
    out = [name]
    m = re.fullmatch(r"(a\^[kr]_|[va]_)([A-Za-z0-9]+)(\^[nτ])?", name)
    if m:
        pts = points_of(m.group(2))
        if len(pts) == 2:
            out.append(f"{m.group(1)}{pts[1]}{pts[0]}{m.group(3) or ''}")
    return out


def _load_value(sol: Solution, name: str, k: int) -> float | None:
    loads = sol.scene.loads
    what, _, lid_text = name.rpartition("_")
    lid = int(lid_text)
    if loads is None or lid not in sol.scene.links:
        return None
    mass, inertia = float(loads.masses.get(lid, 0.0)), float(loads.inertias.get(lid, 0.0))
    if what == "m":
        return mass if mass > 0 else None
    if what == "I":
        return inertia if inertia > 0 else None
    if what == "G":
        return mass * (abs(loads.g) or G_STANDARD) if mass > 0 else None
    f = sol.forces
    if f is None:
        return None
    fa = f.analysis
    if what == "Phi":
        return next((abs(complex(x.F[k])) for x in fa.applied.forces if x.label == f"Phi{lid}"), None)
    if what == "M_Phi":
        return next((float(x.M[k]) for x in fa.applied.moments if x.link == lid and x.kind == "inertia"), None)
    return next((abs(complex(x.F[k])) for x in fa.applied.forces if x.link == lid and x.kind == "gas"), None)


def _force_value(sol: Solution, name: str, k: int) -> float | None:
    f = sol.forces
    if f is None:
        return None
    fa, lv = f.analysis, f.lever
    if name == "F_bal":
        return float(fa.balancing[k])
    if name == "F_bal_lever":
        return float(lv.signed(lv.by_lever)[k]) if bool(lv.valid[k]) else None
    got = reaction_name(name)
    if got is None:
        return None
    i, j, comp = got
    try:
        F, rc = reaction(fa, i, j)
    except KeyError:
        return None
    if comp is None:
        return abs(complex(F[k]))
    part = rc.tau if comp == "^τ" else rc.n
    return None if part is None else float(part[k])


__all__ = ["G_STANDARD", "PATTERNS", "STUDENT_ONLY", "kind_of", "name_of", "names", "points_of", "position", "reaction",
           "reaction_label", "reaction_name", "value", "values"]
