"""Students with one planted mistake: the submissions the examiner's rates are measured on.

A submission is what a student writes at two positions: every segment of both plans
measured on a drawing made by the construction with the mistake in it (the perfect pencil
with the slip, :mod:`plans.check.mistakes`) and read to a random ±``noise_mm`` (seeded),
each value derived from its segment (4 significant digits), ω and ε from their segments,
ω1, v_A and a_A computed from the data (5 digits), the weights and the reactions' components
from the analysis.  The mistakes a construction does not make (a plan's values divided by
another scale, a segment measured between the wrong points, a figure miscalculated, τ and
n swapped, g = 10, π = 3.14) are made on the figures as a student makes them.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from pathlib import Path
from typing import Any

import numpy as np

from plans.check.checkfile import check_from_dict
from plans.check.diagnosis import couple_value, reversed_couple
from plans.check.mistakes import Slip, effective, inventory, replay
from plans.check.providers import Context, exact_value
from plans.kinematics.construction import nice_scale
from plans.kinematics.placing import load_scene
from plans.scene.model import Scene
from plans.tolerances import SAME_ANGLE_DEG

#: The mistakes the planted suite plants (kinds of :data:`plans.check.mistakes.KINDS`).
PLANTED = ("coriolis_reversed", "normal_from_pole", "tangential_wrong_line", "scale", "similarity",
           "wrong_segment", "inertia_sign", "reaction_swapped", "pi_rounded", "g_rounded", "arithmetic")


def sig(x: float, n: int = 4) -> float:
    return 0.0 if abs(x) < 1e-9 else float(f"{x:.{n}g}")


@dataclass
class Scenario:
    """One scene prepared once: its exact analysis and a student's scales."""

    path: Path
    scene: Scene
    mv: float
    ma: float
    mf: float | None
    ctx: Context

    @classmethod
    def of(cls, path: str | Path, phis: tuple[float, ...] | None = None, mv: float | None = None,
           ma: float | None = None) -> Scenario:
        """The scene at the student's scales (μv, μa; by default nice ones for 80 mm)."""
        path = Path(path)
        scene = load_scene(path)
        from plans.kinematics.scales import norms

        nm = norms(scene)
        mv, ma = mv or nice_scale(nm["v"], 80.0), ma or nice_scale(nm["a"], 80.0)
        phis = phis or tuple(scene.driver.phis_deg)
        cf = check_from_dict(_skeleton(path, phis, mv, ma, None, {}), str(path.with_suffix(".check.toml")))
        return cls(path, scene, mv, ma, None, Context(cf))


def _skeleton(path: Path, phis: tuple[float, ...], mv: float, ma: float, mf: float | None,
              body: dict[float, tuple[dict, dict]]) -> dict[str, Any]:
    scales: dict[str, Any] = {"length": {"mu": 1000}, "velocity": {"mu": mv}, "acceleration": {"mu": ma}}
    if mf:
        scales["force"] = {"mu": mf}
    positions = []
    for phi in phis:
        meas, vals = body.get(phi, ({}, {}))
        if not meas and not vals:
            vals = {"omega_1": 1.0}
        positions.append({"phi_deg": phi, "measured": meas, "values": vals})
    return {"format": 1, "student": "planted", "scene": str(path.resolve()), "scales": scales,
            "positions": positions}


def submission(sc: Scenario, phis: tuple[float, float], kind: str | None, rng: np.random.Generator,
               noise_mm: float = 0.5, drawn: Slip | None = None) -> tuple[dict[str, Any], str]:
    """A check file (as a dict) of a student who made the mistake ``kind`` (None: none),
    and what was planted (in words, for a failing test's message).  ``drawn``: a given
    plan drawn at another scale than the one written (``kind`` "scale")."""
    ctx, scene = sc.ctx, sc.scene
    d = scene.driver
    crank = scene.links[d.link]
    A = crank.axis[1]
    mv, ma = sc.mv, sc.ma
    where = int(rng.integers(2))  # the position a local slip is made at
    slip: Slip | None = None
    told = kind or "clean"
    factor = 1.0
    if kind == "scale" and drawn is not None:
        slip, told = drawn, f"scale: {drawn.target} plan drawn at {drawn.factor:.4g}×"
    elif kind == "scale":
        factor = float(rng.choice([-1, 1]) * rng.uniform(0.06, 0.2) + 1)
        plan = "velocity" if rng.random() < 0.5 else "acceleration"
        if rng.random() < 0.5:
            slip = Slip("scale", plan, "drawn", plan, factor=factor)
            told = f"scale: {plan} plan drawn at {factor:.3f}×"
            factor = 1.0
        else:
            told = f"scale: {plan} values × {factor:.3f}"
    couple = None
    if kind == "inertia_sign":
        got = ctx.forces()
        links = [lid for lid, i in sorted(got[0].inertias.items()) if i > 0 and lid in got[0].centres] if got else []
        if not links:
            raise LookupError(f"no inertia couple in {sc.path.name}")
        lid = links[int(rng.integers(len(links)))]
        couple = (got[1], reversed_couple(ctx, lid))
        told = f"inertia_sign: M_Phi{lid}"
    misread = None  # a segment read between the wrong points and used on (ω, a^n, a^k)
    if kind == "wrong_segment" and rng.random() < 0.5:
        misread = _misread(ctx, phis[where], rng)
        if misread is not None:
            told = f"wrong_segment: {misread[0].target} read as {misread[1]}, used on, at {phis[where]:g}°"
    body: dict[float, tuple[dict, dict]] = {}
    for n, phi in enumerate(phis):
        k = next(i for i, p in enumerate(d.phis_deg) if abs(p - phi) < SAME_ANGLE_DEG)
        slips: list[Slip] = []
        if kind in ("coriolis_reversed", "normal_from_pole", "tangential_wrong_line", "similarity") and n == where:
            options = effective(ctx.kin, k, mv, ma, [s for s in inventory(ctx.kin, k, mv, ma) if s.kind == kind])
            if not options:
                raise LookupError(f"no {kind} at {phi:g}° in {sc.path.name}")
            slip = options[int(rng.integers(len(options)))]
            told = f"{kind}: {slip.target} {slip.variant} at {phi:g}°"
            slips = [slip]
        elif slip is not None and slip.kind == "scale":
            slips = [slip]
        elif misread is not None and n == where:
            slips = [misread[0]]
        vp, ap = replay(ctx.kin, k, mv, ma, slips)
        pts = {"velocity": vp, "acceleration": ap}
        meas: dict[str, float] = {}
        vals: dict[str, Any] = {}
        own = f"a_{slip.target[2:]}^n" if slip is not None and slip.variant == "from_pole" else None
        read: dict[str, float] = {}
        for kind_ in ("velocity", "acceleration"):
            right = ctx.plan(k, kind_)
            assert right is not None
            for sg in right.segments:
                got = pts[kind_]
                mm = float(abs(got[sg.end][0] - got[sg.start][0])) if sg.label != own else sg.length_mm
                r = max(0.0, round(mm + rng.uniform(-noise_mm, noise_mm), 1))
                if misread is not None and n == where and sg.label == misread[0].target:
                    r = max(0.0, round(misread[0].read_mm[1] + rng.uniform(-noise_mm, noise_mm), 1))
                read[f"{kind_}:{sg.start}:{sg.end}"] = r
                read[f"{kind_}:{sg.end}:{sg.start}"] = r
                meas[sg.label] = r
                scale_values = kind == "scale" and factor != 1.0 and told.startswith(f"scale: {kind_}")
                vals[sg.label] = sig(r / right.scale * (factor if scale_values else 1.0))
        for lid in sorted(scene.links):
            for q in (f"omega_{lid}", f"eps_{lid}"):
                if lid == d.link:
                    continue
                ex = exact_value(ctx, k, q)
                if ex is None or ex.segment is None or not ex.mm_per_unit or ex.plan is None:
                    continue
                seen = read.get(f"{ex.plan}:{ex.segment[0]}:{ex.segment[1]}")
                if seen is None:
                    continue
                scale_values = kind == "scale" and factor != 1.0 and told.startswith(f"scale: {ex.plan}")
                vals[q] = sig(seen / ex.mm_per_unit * (factor if scale_values else 1.0))
        w1 = abs(d.omega) * (3.14 / math.pi if kind == "pi_rounded" else 1.0)
        l1 = abs(crank.points[A] - crank.points[crank.axis[0]])
        vals[f"omega_{d.link}"] = sig(w1, 5)
        vals[f"v_{A}"] = sig(w1 * l1, 5)
        if d.eps == 0:
            vals[f"a_{A}"] = sig(w1 * w1 * l1, 5)
        _forces(ctx, k, vals, kind == "g_rounded", couple)
        body[phi] = (meas, vals)
    if kind == "wrong_segment" and misread is None:
        told = _wrong_segment(ctx, phis[where], body[phis[where]], rng)
    elif kind == "arithmetic":
        told = _arithmetic(phis[where], body[phis[where]], rng)
    elif kind == "reaction_swapped":
        told = _swap(phis[where], body[phis[where]], rng)
    return _skeleton(sc.path, phis, mv, ma, sc.mf, body), told


def _forces(ctx: Context, k: int, vals: dict[str, Any], g10: bool, couple: tuple[Any, Any] | None) -> None:
    got = ctx.forces()
    if got is None:
        return
    loads, fa = got
    for lid, m in sorted(loads.masses.items()):
        if m > 0:
            vals[f"G_{lid}"] = sig(m * (10.0 if g10 else 9.81))
    names = [f"F_{rc.name(ctx.scene.fij)[1:]}{comp}" for rc in fa.reactions() for comp in ("", "^τ", "^n")]
    for q in names + ["F_bal"]:
        ex = exact_value(ctx, k, q)
        if ex is None:
            continue
        value = ex.value
        if couple is not None:
            wrong = couple_value(couple[0], couple[1], q, k)
            value = ex.value if wrong is None else wrong
        vals[q] = sig(value)


def _wrong_segment(ctx: Context, phi: float, body: tuple[dict, dict], rng: np.random.Generator) -> str:
    meas, vals = body
    k = next(pos.index for pos in ctx.cf.positions if pos.phi_deg == phi)
    crank = ctx.scene.links[ctx.scene.driver.link]
    crank_pin = crank.axis[1].lower()  # v_A, a_A: laid off from the data, not measured
    options = []
    for kind in ("velocity", "acceleration"):
        plan = ctx.plan(k, kind)
        assert plan is not None
        names = [p.name for p in plan.points if not p.name.startswith(("n_", "k_"))]
        for sg in plan.segments:
            if sg.kind != "absolute" or sg.label not in meas or sg.start == plan.pole and sg.end == crank_pin:
                continue
            for i, a in enumerate(names):
                for b in names[i + 1:]:
                    d = abs(complex(*plan.xy(b)) - complex(*plan.xy(a)))
                    if {a, b} != {sg.start, sg.end} and d > 5 and abs(d - sg.length_mm) > 8:
                        options.append((sg.label, a, b, d, plan.scale))
    label, a, b, d, mu = options[int(rng.integers(len(options)))]
    r = round(d + rng.uniform(-0.5, 0.5), 1)
    meas[label] = r
    vals[label] = sig(r / mu)
    return f"wrong_segment: {label} measured {a}–{b} at {phi:g}°"


def _misread(ctx: Context, phi: float, rng: np.random.Generator) -> tuple[Slip, str] | None:
    """A velocity segment ω of a link is read from, read between another pair of points."""
    k = next(pos.index for pos in ctx.cf.positions if pos.phi_deg == phi)
    plan = ctx.plan(k, "velocity")
    assert plan is not None
    names = [p.name for p in plan.points]
    options = []
    for lid in sorted(ctx.scene.links):
        if lid == ctx.scene.driver.link:
            continue
        ex = exact_value(ctx, k, f"omega_{lid}")
        if ex is None or ex.segment is None or ex.plan != "velocity":
            continue
        sg = next((s for s in plan.segments if {s.start, s.end} == set(ex.segment)), None)
        if sg is None or sg.length_mm < 5:
            continue
        for i, a in enumerate(names):
            for b in names[i + 1:]:
                d = abs(complex(*plan.xy(b)) - complex(*plan.xy(a)))
                if {a, b} != {sg.start, sg.end} and d > 5 and abs(d - sg.length_mm) > 8:
                    options.append((Slip("wrong_segment", sg.label, "read", "velocity", read_mm=(sg.length_mm, d)),
                                    f"{a}–{b}"))
    return options[int(rng.integers(len(options)))] if options else None


def _arithmetic(phi: float, body: tuple[dict, dict], rng: np.random.Generator) -> str:
    meas, vals = body
    options = [q for q in vals if q in meas and meas[q] > 10]
    q = options[int(rng.integers(len(options)))]
    f = float(rng.choice([-1, 1]) * rng.uniform(0.08, 0.4) + 1)
    vals[q] = sig(vals[q] * f)
    return f"arithmetic: {q} × {f:.3f} at {phi:g}°"


def _swap(phi: float, body: tuple[dict, dict], rng: np.random.Generator) -> str:
    _, vals = body
    pairs = [q[:-2] for q in vals if q.startswith("F_") and q.endswith("^τ") and f"{q[:-2]}^n" in vals
             and abs(vals[q] - vals[f"{q[:-2]}^n"]) > 0.2 * max(vals[q], vals[f"{q[:-2]}^n"])]
    if not pairs:
        raise LookupError("no reaction whose components differ")
    q = pairs[int(rng.integers(len(pairs)))]
    vals[f"{q}^τ"], vals[f"{q}^n"] = vals[f"{q}^n"], vals[f"{q}^τ"]
    return f"reaction_swapped: {q} at {phi:g}°"

