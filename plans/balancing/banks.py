"""A V engine bank by bank, as the course draws it: each bank's forces act along its own
axis; combine the banks.

A bank is the set of cylinders whose axes lie along one line γ_b.  Its reciprocating
inertia forces of order k are an inline engine's: on the bank's own phase diagram
cylinder i sits at k(β_i − γ_b) (its crank measured from the bank's axis), the polygon of
the vectors p_i (or p_i·l_i for the turned moments) closes with S_b, and the bank sends
along its axis

    F_b(α) = P_0 |S_b| cos(kα + φ_b) · e^{iγ_b},   φ_b = arg S_b.

Two (or more) such forces along axes at the V angle add to a vector whose tip, over a
turn, runs on an ellipse: writing cos x = (e^{ix} + e^{−ix})/2,

    F(α) = F⁺ e^{ikα} + F⁻ e^{−ikα},  F⁺ = Σ_b P_0 S_b e^{iγ_b}/2,  F⁻ = Σ_b P_0 S̄_b e^{iγ_b}/2,

a vector turning with the crank and one turning against it (the decomposition
:mod:`plans.balancing.analysis` uses for the counterweights).  The largest magnitude is
|F⁺| + |F⁻|, the smallest ||F⁺| − |F⁻||, reached along the direction
(arg F⁺ + arg F⁻)/2 (and 90° from it); F⁻ = 0 is a circle turning with the crank
(a counterweight takes it), |F⁺| = |F⁻| a line.
"""

from __future__ import annotations

import cmath
import math
from dataclasses import dataclass
from typing import Any

from plans.balancing.engine import Cylinder, Engine
from plans.tolerances import CLOSED_REL

#: Below this fraction of the reference a magnitude counts as round-off.
CLOSED = CLOSED_REL
ORDERS = {"first_order": 1, "second_order": 2}


@dataclass(frozen=True, slots=True)
class BankPolygon:
    """One bank's polygon of one order: rows (cylinder, angle on the bank's phase diagram,
    p_i, l_i) and the closing vector S_b (dimensionless)."""

    quantity: str  # "force" | "moment"
    kind: str  # first_order | second_order
    order: int
    unit: float  # N (or N·m) per dimensionless unit
    rows: tuple[tuple[int, float, float, float], ...]

    @property
    def closing(self) -> complex:
        return complex(sum((p * l * cmath.exp(1j * a) for _, a, p, l in self.rows), 0j))

    @property
    def scale_ref(self) -> float:
        return max((abs(p * l) for _, _, p, l in self.rows), default=0.0)

    @property
    def closed(self) -> bool:
        return abs(self.closing) <= CLOSED * max(self.scale_ref, 1e-300)

    @property
    def amplitude(self) -> float:
        """The bank's resultant along its axis, N (N·m): P_0 |S_b|."""
        return 0.0 if self.closed else abs(self.closing) * self.unit

    @property
    def phase(self) -> float:
        """rad: arg S_b, the crank angle (of crank 1, times k) before the resultant peaks."""
        if self.closed:
            return 0.0
        return cmath.phase(self.closing)

    def to_json(self) -> dict[str, Any]:
        s = self.closing
        return {"amplitude": self.amplitude, "phase_deg": _deg(self.phase),
                "dimensionless": 0.0 if self.closed else abs(s),
                "dimensionless_cos": _clean(s.real, self.scale_ref),
                "dimensionless_sin": _clean(s.imag, self.scale_ref),
                "polygon": [{"cylinder": c, "angle_deg": _deg(a), "p": p, "l": l} for c, a, p, l in self.rows]}


@dataclass(frozen=True, slots=True)
class Bank:
    """The cylinders along one axis γ_b and their polygons."""

    number: int  # 1-based, in the order the banks first appear along the shaft
    axis: float  # γ_b, rad from the vertical in the direction of rotation
    cylinders: tuple[Cylinder, ...]
    forces: dict[str, BankPolygon]
    moments: dict[str, BankPolygon]

    @property
    def direction(self) -> complex:
        return cmath.exp(1j * self.axis)

    def to_json(self) -> dict[str, Any]:
        return {"bank": self.number, "axis_deg": _deg(self.axis),
                "cylinders": [c.number for c in self.cylinders], "names": [c.name for c in self.cylinders],
                "forces": {k: p.to_json() for k, p in self.forces.items()},
                "moments": {k: p.to_json() for k, p in self.moments.items()}}


@dataclass(frozen=True, slots=True)
class Locus:
    """The banks combined: F(α) = F⁺e^{ikα} + F⁻e^{−ikα}; its tip's path over a turn."""

    quantity: str
    kind: str
    order: int
    forward: complex  # F⁺, N (N·m)
    backward: complex  # F⁻
    ref: float  # the largest single vector (N, N·m): the round-off scale

    @property
    def maximum(self) -> float:
        return _clean(abs(self.forward) + abs(self.backward), self.ref)

    @property
    def minimum(self) -> float:
        f, b = _clean(abs(self.forward), self.ref), _clean(abs(self.backward), self.ref)
        return _clean(abs(f - b), self.ref)

    @property
    def shape(self) -> str:
        """zero | circle | line | ellipse."""
        if self.maximum == 0.0:
            return "zero"
        if _clean(abs(self.forward), self.ref) == 0.0 or _clean(abs(self.backward), self.ref) == 0.0:
            return "circle"
        return "line" if self.minimum == 0.0 else "ellipse"

    @property
    def sense(self) -> str:
        """with | against (the crank) | none (a line: it does not turn)."""
        if self.shape in ("zero", "line"):
            return "none"
        return "with" if abs(self.forward) > abs(self.backward) else "against"

    @property
    def direction(self) -> float:
        """rad: the direction of the largest magnitude (the major axis, modulo π); for a
        circle, the vector's direction at α = 0."""
        f, b = self.forward, self.backward
        if self.shape == "zero":
            return 0.0
        if self.shape == "circle":
            return cmath.phase(f + b)
        return _half_turn((cmath.phase(f) + cmath.phase(b)) / 2)

    def at(self, alpha: Any) -> Any:
        import numpy as np

        a = np.asarray(alpha, dtype=float)
        return self.forward * np.exp(1j * self.order * a) + self.backward * np.exp(-1j * self.order * a)

    def to_json(self) -> dict[str, Any]:
        return {"locus": self.shape, "max": self.maximum, "min": self.minimum,
                "direction_deg": _deg(self.direction), "sense": self.sense,
                "forward": {"amplitude": _clean(abs(self.forward), self.ref),
                            "phase_deg": _deg(cmath.phase(self.forward))
                            if _clean(abs(self.forward), self.ref) else 0.0},
                "backward": {"amplitude": _clean(abs(self.backward), self.ref),
                             "phase_deg": _deg(cmath.phase(self.backward))
                             if _clean(abs(self.backward), self.ref) else 0.0}}


@dataclass(frozen=True, slots=True)
class BankAnalysis:
    banks: tuple[Bank, ...]
    forces: dict[str, Locus]
    moments: dict[str, Locus]

    def to_json(self) -> tuple[list[dict[str, Any]], dict[str, Any]]:
        return ([b.to_json() for b in self.banks],
                {"forces": {k: v.to_json() for k, v in self.forces.items()},
                 "moments": {k: v.to_json() for k, v in self.moments.items()}})


def _deg(a: float) -> float:
    d = round(math.degrees(a) % 360.0, 9)
    return 0.0 if d >= 360.0 else d + 0.0


def _half_turn(a: float) -> float:
    """An axis direction in [0, π)."""
    return a % math.pi


def _clean(x: float, ref: float) -> float:
    return 0.0 if abs(x) <= CLOSED * max(abs(ref), 1e-300) else float(x)


def _wrap(a: float) -> float:
    return math.atan2(math.sin(a), math.cos(a))


def bank_groups(engine: Engine) -> list[tuple[float, tuple[Cylinder, ...]]]:
    """The banks: cylinders grouped by axis, in the order they first appear."""
    out: list[tuple[float, list[Cylinder]]] = []
    for c in engine.cylinders:
        for g, cs in out:
            if abs(_wrap(c.bank - g)) < 1e-12:
                cs.append(c)
                break
        else:
            out.append((c.bank, [c]))
    return [(g, tuple(cs)) for g, cs in out]


def analyse_banks(engine: Engine) -> BankAnalysis:
    """Every bank's first- and second-order polygons (forces and turned moments) and the
    banks combined."""
    m1 = engine.cylinders[0].m_rec
    banks = []
    for number, (g, cyls) in enumerate(bank_groups(engine), start=1):
        polys: dict[str, dict[str, BankPolygon]] = {"force": {}, "moment": {}}
        for kind, k in ORDERS.items():
            P0 = m1 * engine.r * engine.omega**2 * (engine.lam if k == 2 else 1.0)
            for quantity in ("force", "moment"):
                unit = P0 * (engine.arm_unit if quantity == "moment" else 1.0)
                rows = tuple((c.number, _wrap(k * (c.crank - g)), c.m_rec / m1 if m1 > 0 else 0.0,
                              (c.z - engine.reference_z) / engine.arm_unit if quantity == "moment" else 1.0)
                             for c in cyls)
                polys[quantity][kind] = BankPolygon(quantity, kind, k, unit, rows)
        banks.append(Bank(number, g, cyls, polys["force"], polys["moment"]))
    combined: dict[str, dict[str, Locus]] = {"force": {}, "moment": {}}
    for quantity in ("force", "moment"):
        for kind, k in ORDERS.items():
            fwd = bwd = 0j
            ref = 0.0
            for b in banks:
                poly = (b.forces if quantity == "force" else b.moments)[kind]
                S = poly.closing * poly.unit
                fwd += S * b.direction / 2
                bwd += S.conjugate() * b.direction / 2
                ref = max(ref, poly.scale_ref * poly.unit)
            combined[quantity][kind] = Locus(quantity, kind, k, fwd, bwd, ref)
    return BankAnalysis(tuple(banks), combined["force"], combined["moment"])


_SHAPES = {"zero": "balanced", "circle": "a circle", "line": "a line", "ellipse": "an ellipse"}


def report_lines(a: BankAnalysis, lang: str = "en") -> list[str]:
    """What ``plans balance`` prints for the banks, in ``lang``."""
    from plans.phrases import say

    ru = lang == "ru"
    out: list[str] = []
    for b in a.banks:
        names = ", ".join(c.name for c in b.cylinders)
        out.append(say("k_bank", lang, n=b.number, axis=_deg(b.axis), names=names))
        for quantity, polys in (("force", b.forces), ("moment", b.moments)):
            unit = ("N*m" if quantity == "moment" else "N") if not ru else ("Н·м" if quantity == "moment" else "Н")
            for kind, p in polys.items():
                angles = ", ".join(f"{_deg(r[1]):.4g}".replace(".", "," if ru else ".") for r in p.rows)
                what = f"{quantity} {kind.replace('_', ' ')}" if not ru else \
                    f"{say('b_' + quantity, lang)} {say('k_' + kind, lang)}"
                head = say("k_polygon", lang, what=what, angles=angles)
                if p.closed:
                    out.append(head + say("k_closes", lang))
                    continue
                k = "" if p.order == 1 else "2"
                out.append(head + say("k_closing", lang, c=abs(p.closing), a=p.amplitude, u=unit, k=k,
                                      ph=_deg(p.phase)))
    out.append(say("k_combined", lang))
    for quantity, loci in (("force", a.forces), ("moment", a.moments)):
        unit = ("N*m" if quantity == "moment" else "N") if not ru else ("Н·м" if quantity == "moment" else "Н")
        for kind, L in loci.items():
            what = f"{quantity} {kind.replace('_', ' ')}" if not ru else \
                f"{say('b_' + quantity, lang)} {say('k_' + kind, lang)}"
            text = f"  {what}: {_SHAPES[L.shape] if not ru else say('k_' + L.shape, lang)}"
            if L.shape != "zero":
                text += say("k_locus_circle" if L.shape == "circle" else "k_locus", lang, mx=L.maximum, u=unit,
                            d=_deg(L.direction), mn=L.minimum)
                text += "" if L.sense == "none" else say("k_turning", lang, s=say("k_" + L.sense, lang) if ru
                                                         else L.sense)
            out.append(text)
    return out
