"""The hand-drawing Monte Carlo: the construction drawn at sheet scale with a pencil and a
protractor that err, repeated over many drawings; the spread of each reading."""

from __future__ import annotations

from dataclasses import dataclass
from typing import TYPE_CHECKING, Any

import numpy as np

from plans.kinematics import exact as kinematics
from plans.kinematics.construction import nice_scale, plans_of
from plans.kinematics.dyads import Builder, Scheme, unit
from plans.kinematics.scales import norms
from plans.lines import meet
from plans.scene.model import Scene

if TYPE_CHECKING:  # mpmath is an optional dependency (the ``bench`` extra): imported where used
    pass

#: Linear size of a sheet relative to A1 (A4 is A1 halved three times in area).
SHEETS = {"A1": 1.0, "A2": 2**-0.5, "A3": 0.5, "A4": 2**-1.5}

# --------------------------------------------------------------------------- the draftsman


@dataclass(frozen=True)
class DraftsmanModel:
    """What a careful hand drawing gets wrong, per primitive (uniform in ±value):

    * ``pencil_mm``: a marked point (each coordinate), a length laid off or read with the rule;
    * ``protractor_deg``: a direction drawn with set square or protractor;
    the directions ⟂ link / ∥ guide are also transferred from the scheme drawn at its
    own scale, whose two end points carry the pencil error."""

    pencil_mm: float = 0.25
    protractor_deg: float = 0.25


@dataclass(frozen=True)
class ExpectedError:
    """The spread of one quantity read off hand-drawn plans (Monte Carlo)."""

    quantity: str
    unit: str
    exact: float
    mean: float  # mean signed error (SI)
    std: float
    p95_abs: float  # 95 % of drawings are within this absolute error (SI)
    p95_rel: float  # ... and within this relative error (|error| / max(|exact|, known vector))
    p95_mm: float  # ... which is this many millimetres on the plan (0 for ω, ε)
    max_abs: float


class NoisyPencil:
    """A hand that draws, for :mod:`plans.kinematics.dyads`: every marked point, laid-off or
    read length carries the pencil's error (uniform, ±``pencil_mm``), every drawn direction
    the protractor's (±``protractor_deg``) plus the pencil error of the two end points it is
    transferred from on the scheme (drawn at μl); arrays over ``samples`` drawings."""

    exact = False

    def __init__(self, model: DraftsmanModel, samples: int, rng: np.random.Generator, mul: float) -> None:
        self.model, self.M, self.rng, self.mul = model, samples, rng, mul

    def u(self, half: float) -> np.ndarray:
        return self.rng.uniform(-half, half, self.M)

    def mark(self, z: Any, along: Any = None, joint: bool = False) -> np.ndarray:
        if joint:  # a joint found by similarity is where its link's image puts it
            return z
        p = self.model.pencil_mm
        return z + self.u(p) + 1j * self.u(p)

    def read(self, length: Any) -> np.ndarray:
        return np.abs(length + self.u(self.model.pencil_mm))

    def line(self, direction: Any, span: Any) -> np.ndarray:
        p = self.model.pencil_mm
        ang = np.radians(self.u(self.model.protractor_deg))
        span = np.asarray(span, float)
        if np.any(span > 0):  # a direction taken off the scheme: its two end points marked there
            ang = ang + np.where(span > 0, (self.u(p) - self.u(p)) / (np.where(span > 0, span, 1.0) * self.mul), 0.0)
        return unit(direction) * np.exp(1j * ang)

    def vector(self, length: Any, direction: Any, span: Any, out: str) -> np.ndarray:
        return self.read(length) * self.line(direction, span)

    def cut(self, b: Builder, l1: Any, l2: Any, out: str, exact_xy: Any, group: Any, point: str) -> np.ndarray:
        """Two drawn lines intersected, the point marked."""
        (p1, d1), (p2, d2) = l1, l2
        return self.mark(meet(p1, d1, p2, d2))


def draftsman_errors(scene: Scene, phi_deg: float, sheet: str | float = "A1",
                     model: DraftsmanModel | None = None, samples: int = 2000,
                     seed: int = 0, scales: tuple[float, float, float] | None = None) -> dict[str, ExpectedError]:
    """Monte Carlo of hand-drawn velocity and acceleration plans at one crank angle.

    The scheme is drawn at μl (the scene's length scale on A1, or the mechanism's
    extent at about 200 mm) times the sheet factor; the plans at the draftsman's nice
    scales for a 100 mm known vector times the same factor.  Every marked point, laid-off
    or read length and drawn direction carries the model's error; each drawing is
    built as the construction builds it (lines ⟂ link and ∥ guide, intersections,
    similarity; normal and Coriolis components from ω and v_r read off the drawn velocity
    plan), its readings compared with the exact values.  ``scales`` = (μl, μv, μa) draws
    at a given sheet's scales instead (the checker's: a student's).  All five class-II dyads, on fixed
    and moving guides.  Quantities are named as the plans name them (``v_A3``,
    ``v_A2A3``, ``a^k_A3A2``, ``a^r_A3A2``, ``omega_3``, ``eps_3``).
    """
    model = model or DraftsmanModel()
    factor = SHEETS[sheet] if isinstance(sheet, str) else float(sheet)
    kin = kinematics.solve(scene, [phi_deg], order=2)
    nm = norms(scene)
    extent = max(abs(complex(z)) for name in kin.point_names() for z in kin.point(name)[0]) or nm["r"]
    mul = scene.scales.get("length") or nice_scale(extent, 200.0)
    mul *= factor
    muv = nice_scale(nm["v"], 100.0 * factor)
    mua = nice_scale(nm["a"], 100.0 * factor)
    if scales is not None:  # a given sheet (a student's μl, μv, μa in mm per unit): no sheet factor
        mul, muv, mua = scales
    pencil = NoisyPencil(model, samples, np.random.default_rng(seed), mul)
    vb, ab = plans_of(Scheme(kin, [0]), muv, mua, pencil)
    readings: dict[str, tuple[np.ndarray, float, str, float]] = {}  # q -> (values, exact, unit, mm per unit)
    for b in (vb, ab):
        assert b is not None
        for q, _, mm, mu, value, exact, unit_, _, drawn in b.readings:
            if drawn:  # read off the drawing (not a datum, nor a rate a block shares with its guide)
                readings[q] = (np.broadcast_to(value, (samples,)), float(np.ravel(exact)[0]), unit_,
                               0.0 if mm is None or mu is None else mu)
    out = {}
    for q, (vals, ex, un, mm_per) in readings.items():
        err = vals - ex
        if q.startswith(("omega_", "eps_")):  # the plan's size in this unit: v_A / l_k, a_A / l_k
            link = scene.links[int(q.split("_")[1])]
            lk = link.length or nm["r"]
            ref = (nm["v"] if q.startswith("omega") else nm["a"]) / lk
        else:
            ref = nm[q[0]]
        a = np.abs(err)
        p95 = float(np.quantile(a, 0.95))
        out[q] = ExpectedError(q, un, ex, float(np.mean(err)), float(np.std(err)), p95,
                               p95 / max(abs(ex), ref), p95 * mm_per, float(np.max(a)))
    return out


def expected_errors(scene: Scene, phi_deg: float, sheet: str | float = "A1",
                    model: DraftsmanModel | None = None, samples: int = 2000,
                    seed: int = 0, scales: tuple[float, float, float] | None = None
                    ) -> dict[str, tuple[float, float]]:
    """For the checker: ``{quantity: (relative, absolute)}`` that 95 % of careful hand
    drawings of this scene at ``phi_deg`` on ``sheet`` (or at ``scales``) stay within."""
    res = draftsman_errors(scene, phi_deg, sheet, model, samples, seed, scales)
    return {q: (e.p95_rel, e.p95_abs) for q, e in res.items()}
