"""Unbalanced inertia forces and moments of an engine, by phase diagrams and polygons (seed 002).

One cylinder, crank at θ = α + β_i from the vertical, axis at γ_i (both in the direction
of rotation), sends to the frame

* the rotating inertia force m_r r ω² along its crank;
* the reciprocating inertia force along its axis, m_j r ω² (cos θ' + λ cos 2θ') + O(λ³),
  θ' = θ − γ_i: first order P_I cos θ', second order P_II cos 2θ'.

Vectors in the plane ⟂ the shaft are complex numbers: real part along the vertical, the
imaginary part along the direction of rotation.  Over the cylinders of one bank (an
inline engine) a harmonic of order k adds as the phase diagram says: the polygon of the
vectors p_i at k·β_i closes with S, and the force along the bank is |S|·P_0·cos(kα + φ),
φ = arg S, the closing vector turning with the crank (k times as fast).  Cylinders on
different banks (V engines) are split into the two vectors that make up a force along a
fixed line, P cos(kα + ψ)·e^{iγ} = (P/2)e^{iγ}(e^{i(kα+ψ)} + e^{−i(kα+ψ)}): one polygon
turning with the crank (forward) and one against it (backward); the resultant traces an
ellipse, its largest magnitude |F_f| + |F_b|.

Moments about the reference plane: the force of cylinder i times its arm l_i = z_i − z_ref.
Seed 002 turns every moment vector by 90° so that it lies along its force (its crank on
the phase diagram), adds them as forces, and turns the closing vector back; the polygons
here are those of the turned vectors p_i·l_i, and a moment's phase is the phase of its
turned closing vector.

Dimensionless values as the seed tabulates them: p_i = m_i / m_1 (the forces in units
of cylinder 1's, P_0 = m_1 r ω², times λ for the second order) and l_i in units of
l_ц, the spacing of the cylinders.
"""

from __future__ import annotations

import cmath
import math
from dataclasses import dataclass
from typing import Any

import numpy as np

from plans.balancing.banks import BankAnalysis, analyse_banks
from plans.balancing.engine import Engine, wrap
from plans.tolerances import CLOSED_REL, SAME_LAYOUT
from plans.units import DUST

KINDS = ("rotating", "first_order", "second_order")
#: Below this fraction of the largest vector a resultant counts as closed (round-off).
CLOSED = CLOSED_REL


@dataclass(frozen=True, slots=True)
class Row:
    """One line of an analytic table: cylinder, angle on the phase diagram, p_i, l_i."""

    cylinder: int
    angle: float  # rad, on the phase diagram of the polygon's order
    p: float  # dimensionless force (halved in the forward/backward polygons of a V engine)
    l: float  # dimensionless arm (1 for forces)

    @property
    def vector(self) -> complex:
        """p_i·l_i at its angle (the vector laid off on the polygon)."""
        return self.p * self.l * cmath.exp(1j * self.angle)


@dataclass(frozen=True, slots=True)
class Polygon:
    """The vectors of one order laid head to tail, and the closing vector."""

    quantity: str  # "force" | "moment"
    kind: str  # rotating | first_order | second_order
    order: int  # 1 or 2 (the phase diagram the angles are on)
    branch: str  # "" (one polygon), "forward" or "backward" (V engines)
    unit: float  # N (or N·m) per dimensionless unit: P_0 (× l_ц)
    rows: tuple[Row, ...]

    @property
    def closing(self) -> complex:
        """The dimensionless closing vector Σ p_i l_i e^{i angle_i}."""
        return complex(sum((r.vector for r in self.rows), 0j))

    @property
    def scale_ref(self) -> float:
        return max((abs(r.vector) for r in self.rows), default=0.0)

    @property
    def closed(self) -> bool:
        return abs(self.closing) <= CLOSED * max(self.scale_ref, 1e-300)


@dataclass(frozen=True, slots=True)
class Resultant:
    """An unbalanced force (N) or turned moment (N·m): F(α) = F_f e^{ikα} + F_b e^{−ikα}."""

    quantity: str
    kind: str
    order: int
    forward: complex
    backward: complex
    polygons: tuple[Polygon, ...]
    line: complex | None  # unit direction it acts along (inline engines), else None

    @property
    def amplitude(self) -> float:
        """The largest magnitude over a turn."""
        return _clean(abs(self.forward) + abs(self.backward), self._ref)

    @property
    def _ref(self) -> float:
        return max((p.scale_ref * p.unit for p in self.polygons), default=0.0)

    @property
    def phase(self) -> float:
        """rad: the angle of the closing vector on the phase diagram (of the forward
        polygon for a V engine), from the vertical in the direction of rotation."""
        poly = self.polygons[0]  # the forward polygon of a V engine comes first
        if poly.closed:
            return 0.0
        z = poly.closing
        return math.atan2(z.imag, z.real)

    @property
    def dimensionless(self) -> float:
        """The closing vector's length in the polygon's units (r_r, m_r of the seed)."""
        unit = self.polygons[0].unit if self.polygons else 1.0
        return self.amplitude / unit if unit > 0 else 0.0

    def at(self, alpha: Any) -> Any:
        """The vector at crank angle α (rad; array or scalar)."""
        a = np.asarray(alpha, dtype=float)
        k = self.order
        return self.forward * np.exp(1j * k * a) + self.backward * np.exp(-1j * k * a)

    def to_json(self) -> dict[str, Any]:
        out: dict[str, Any] = {"amplitude": self.amplitude, "phase_deg": _deg(self.phase),
                               "dimensionless": _clean(self.dimensionless, 1.0)}
        if len(self.polygons) == 1:
            s = self.polygons[0].closing
            out["dimensionless_cos"] = _clean(s.real, 1.0)
            out["dimensionless_sin"] = _clean(s.imag, 1.0)
        else:
            out["forward"] = {"amplitude": _clean(abs(self.forward), self._ref),
                              "phase_deg": _deg(cmath.phase(self.forward)) if abs(self.forward) > 0 else 0.0}
            out["backward"] = {"amplitude": _clean(abs(self.backward), self._ref),
                               "phase_deg": _deg(cmath.phase(self.backward)) if abs(self.backward) > 0 else 0.0}
        return out


@dataclass(frozen=True, slots=True)
class Counterweight:
    """A mass on the crankshaft: mass × radius at an angle from crank 1, in a plane z."""

    of: str  # what it balances: "rotating" or "first_order"
    plane_z: float  # m
    mass_radius: float  # kg·m
    radius: float  # m
    angle: float  # rad, from crank 1 in the direction of rotation

    @property
    def mass(self) -> float:
        return self.mass_radius / self.radius

    def to_json(self) -> dict[str, Any]:
        return {"for": self.of, "plane_z": self.plane_z, "mass_radius": self.mass_radius,
                "mass": self.mass, "radius": self.radius, "angle_deg": _deg(self.angle)}


@dataclass(frozen=True, slots=True)
class Balance:
    engine: Engine
    forces: dict[str, Resultant]
    moments: dict[str, Resultant]
    counterweights: tuple[Counterweight, ...]
    notes: tuple[str, ...]
    banks: BankAnalysis  # the reciprocating forces bank by bank, and the banks combined

    @property
    def P0(self) -> dict[str, float]:
        """The unit forces of cylinder 1 (N): P_r0, P_I0, P_II0."""
        return {k: self.forces[k].polygons[0].unit for k in KINDS}

    def shaking_force(self, alpha: Any) -> Any:
        """Rotating + first + second order force at crank angle α (engine plane, N)."""
        return sum(self.forces[k].at(alpha) for k in KINDS)

    def turned_moment(self, alpha: Any) -> Any:
        """Rotating + first + second order turned moment at crank angle α (N·m)."""
        return sum(self.moments[k].at(alpha) for k in KINDS)

    def to_json(self, lang: str = "en") -> dict[str, Any]:
        """The balance as JSON: the program's keys, its sentences (the angles' rule, the
        notes) in ``lang``."""
        from plans.language import TERMS

        e = self.engine
        banks, combined = self.banks.to_json()
        return {
            "engine": {"title": e.title, "file": e.path, "cylinders": e.n, "r": e.r, "lambda": e.lam,
                       "omega": e.omega, "strokes": e.strokes, "reference_z": e.reference_z,
                       "arm_unit": e.arm_unit,
                       "crank_deg": [_deg(c.crank) for c in e.cylinders],
                       "bank_deg": [c.bank_deg for c in e.cylinders],
                       "z": [c.z for c in e.cylinders]},
            "units": {"force": "N", "moment": "N*m", "length": "m", "mass": "kg",
                      "angles": TERMS["b_json_angles"][lang == "ru"]},
            "unit_forces": self.P0,
            "phase_diagrams": {"first_order": [_deg(c.crank) for c in e.cylinders],
                               "second_order": [_deg(2 * c.crank) for c in e.cylinders]},
            "forces": {k: self.forces[k].to_json() for k in KINDS},
            "moments": {k: self.moments[k].to_json() for k in KINDS},
            "counterweights": [c.to_json() for c in self.counterweights],
            "notes": [_note(n, lang) for n in self.notes],
            "banks": banks,
            "banks_combined": combined,
        }


def _deg(a: float) -> float:
    d = math.degrees(a) % 360.0
    d = round(d, 9)
    return 0.0 if d >= 360.0 else d + 0.0


def _clean(x: float, ref: float) -> float:
    return 0.0 if abs(x) <= CLOSED * max(abs(ref), 1e-300) else float(x)


# --------------------------------------------------------------------------- the analysis


def balance(engine: Engine) -> Balance:
    """Every polygon, resultant and counterweight of the engine."""
    forces = {k: _resultant(engine, k, "force") for k in KINDS}
    moments = {k: _resultant(engine, k, "moment") for k in KINDS}
    cws, notes = _counterweights(engine, forces, moments)
    return Balance(engine, forces, moments, cws, notes, analyse_banks(engine))


def _masses(engine: Engine, kind: str) -> list[float]:
    return [c.m_rot if kind == "rotating" else c.m_rec for c in engine.cylinders]


def _resultant(engine: Engine, kind: str, quantity: str) -> Resultant:
    """The polygon(s) of one kind and their resultant in N (or N·m)."""
    ms = _masses(engine, kind)
    k = 2 if kind == "second_order" else 1
    # the polygon's unit is the first cylinder's force (the first with a mass: an engine may
    # have no rotating masses at all, whose polygon is then of zero sides at 1 kg's unit)
    m0 = next((m for m in ms if m > 0), 1.0)
    P0 = m0 * engine.r * engine.omega**2 * (engine.lam if k == 2 else 1.0)
    unit = P0 * (engine.arm_unit if quantity == "moment" else 1.0)
    ps = [m / m0 for m in ms]
    ls = [(c.z - engine.reference_z) / engine.arm_unit if quantity == "moment" else 1.0
          for c in engine.cylinders]
    cyl = engine.cylinders
    if kind == "rotating":
        rows = tuple(Row(c.number, c.crank, p, l) for c, p, l in zip(cyl, ps, ls, strict=True))
        poly = Polygon(quantity, kind, 1, "", unit, rows)
        return Resultant(quantity, kind, 1, unit * poly.closing, 0j, (poly,), None)
    if engine.is_inline:
        g0 = cyl[0].bank
        rows = tuple(Row(c.number, wrap(k * (c.crank - g0)), p, l) for c, p, l in zip(cyl, ps, ls, strict=True))
        poly = Polygon(quantity, kind, k, "", unit, rows)
        S = unit * poly.closing
        # along the bank: Re(S e^{ikα}) e^{iγ0} = (S e^{ikα} + conj(S) e^{−ikα}) e^{iγ0} / 2
        u = cmath.exp(1j * g0)
        return Resultant(quantity, kind, k, S * u / 2, S.conjugate() * u / 2, (poly,), u)
    fwd = tuple(Row(c.number, wrap(k * (c.crank - c.bank) + c.bank), p / 2, l)
                for c, p, l in zip(cyl, ps, ls, strict=True))
    bwd = tuple(Row(c.number, wrap(-k * (c.crank - c.bank) + c.bank), p / 2, l)
                for c, p, l in zip(cyl, ps, ls, strict=True))
    pf = Polygon(quantity, kind, k, "forward", unit, fwd)
    pb = Polygon(quantity, kind, k, "backward", unit, bwd)
    return Resultant(quantity, kind, k, unit * pf.closing, unit * pb.closing, (pf, pb), None)


def _planes(engine: Engine) -> tuple[float, ...]:
    if engine.cw_planes is not None:
        return engine.cw_planes
    zs = [c.z for c in engine.cylinders]
    lo, hi = min(zs), max(zs)
    return (lo, hi) if hi - lo > SAME_LAYOUT else (lo,)


def _counterweights(engine: Engine, forces: dict[str, Resultant], moments: dict[str, Resultant]
                    ) -> tuple[tuple[Counterweight, ...], tuple[str, ...]]:
    """Counterweights for the rotating force and moment, and for the first-order
    reciprocating ones where they turn with the crank only (no backward part, e.g. the
    90° V-twin); what a counterweight cannot take is said in a note."""
    w2 = engine.omega**2
    out: list[Counterweight] = []
    notes: list[str] = []
    for kind in ("rotating", "first_order"):
        F, M = forces[kind], moments[kind]
        if kind == "first_order":
            if F.amplitude == 0 and M.amplitude == 0:
                continue
            ref = max(F._ref, M._ref / max(engine.arm_unit, 1e-300), 1e-300)
            if abs(F.backward) > CLOSED_REL * ref or abs(M.backward) > CLOSED_REL * ref * engine.arm_unit:
                notes.append("first-order reciprocating force or moment has a part turning against "
                             "the crank: a counterweight on the crankshaft cannot take it (it only moves "
                             "it to the other plane); balancing shafts can")
                continue
        S = F.forward / w2  # kg·m, in the engine plane (turns with the crank)
        T = M.forward / w2  # kg·m·m about the reference plane (turned moment)
        ws, note = _solve_planes(engine, S, T, max(F._ref, M._ref / max(engine.arm_unit, 1e-300)) / w2)
        if note:
            notes.append(f"{kind.replace('_', '-')}: {note}")  # written in a language by _note
        out += [Counterweight(kind, z, abs(U), engine.cw_radius, math.atan2(U.imag, U.real)) for z, U in ws]
    if forces["second_order"].amplitude > 0 or moments["second_order"].amplitude > 0:
        notes.append("second-order reciprocating force or moment turns at twice the crank speed: no "
                     "counterweight on the crankshaft takes it (balancing shafts at 2 omega can)")
    return tuple(out), tuple(notes)


def _solve_planes(engine: Engine, S: complex, T: complex, ref: float
                  ) -> tuple[list[tuple[float, complex]], str]:
    """Mass-radius vectors U_A, U_B in the planes z_A, z_B with U_A + U_B = −S and
    U_A a + U_B b = −T (a, b the planes' arms); one plane takes −S alone."""
    tiny = DUST * max(ref, 1e-300)
    if abs(S) <= tiny and abs(T) <= tiny * max(engine.arm_unit, 1e-300):
        return [], ""
    planes = _planes(engine)
    zr = engine.reference_z
    if len(planes) == 1:
        z = planes[0]
        rest = T - S * (z - zr)
        note = ""
        if abs(rest) > tiny * max(engine.arm_unit, 1e-300):
            note = (f"one counterweight leaves a moment of {abs(rest) * engine.omega**2:.6g} N*m; "
                    f"give two planes")
        return ([(z, -S)] if abs(S) > tiny else []), note
    a, b = planes[0] - zr, planes[1] - zr
    UB = (-T + a * S) / (b - a)
    UA = -S - UB
    return [(z, U) for z, U in ((planes[0], UA), (planes[1], UB)) if abs(U) > tiny], ""


# --------------------------------------------------------------------------- text


def _n(x: float, width: int = 9, digits: int = 4) -> str:
    x = 0.0 if abs(x) < 5e-13 else x
    return f"{x:{width}.{digits}g}"


def table_lines(poly: Polygon, lang: str = "en") -> list[str]:
    """The seed's analytic table: β_i, cos, sin, p_i, (l_i,) p_i l_i cos, p_i l_i sin, Σ."""
    ru = lang == "ru"
    moment = poly.quantity == "moment"
    angle = ("beta_i" if poly.order == 1 else "2beta_i") if not ru else ("β_i" if poly.order == 1 else "2β_i")
    head = f"  {'No' if not ru else '№':>3} {angle:>9} {'cos':>9} {'sin':>9} {'p_i':>9}"
    head += f" {'l_i':>9} {'p l cos':>9} {'p l sin':>9}" if moment else f" {'p cos':>9} {'p sin':>9}"
    head += f" {('N*m' if moment else 'N') if not ru else ('Н·м' if moment else 'Н'):>11}"
    lines = [head]
    for r in poly.rows:
        c, s = math.cos(r.angle), math.sin(r.angle)
        line = f"  {r.cylinder:>3} {_n(_deg(r.angle))} {_n(c)} {_n(s)} {_n(r.p)}"
        line += f" {_n(r.l)}" if moment else ""
        line += f" {_n(r.p * r.l * c)} {_n(r.p * r.l * s)} {_n(r.p * r.l * poly.unit, 11, 7)}"
        lines.append(line.replace(".", ",") if ru else line)
    z = poly.closing
    pad = 10 * (5 if moment else 4)
    total = 0.0 if poly.closed else abs(z) * poly.unit
    line = f"  {'sum' if not ru else 'Σ':>3}{' ' * (pad - 3)} {_n(z.real)} {_n(z.imag)} {_n(total, 11, 7)}"
    lines.append(line.replace(".", ",") if ru else line)
    return lines


_NAMES = {"rotating": "rotating masses", "first_order": "reciprocating, first order",
          "second_order": "reciprocating, second order"}


def _note(text: str, lang: str) -> str:
    """A note of the analysis in ``lang`` (a fixed sentence of the catalogue where it is one)."""
    if lang == "en":
        return text
    from plans.language import TERMS

    for key in ("b_note_against", "b_note_second"):
        if text == TERMS[key][0]:
            return TERMS[key][1]
    import re

    got = re.fullmatch(r"(rotating|first-order|second-order): one counterweight leaves a moment of (\S+) N\*m; "
                       r"give two planes", text)
    if got:  # a number of the analysis in the sentence of _solve_planes
        from plans.phrases import say

        return say("b_note_one_plane", lang, order=say("b_" + got[1].replace("-", "_"), lang), m=float(got[2]))
    return text


def report(b: Balance, lang: str = "en") -> str:
    """What ``plans balance`` prints: tables, resultants, counterweights, in ``lang``."""
    from plans.phrases import say

    ru = lang == "ru"
    e = b.engine
    out = [e.title,
           say("b_head", lang, n=e.n, strokes=e.strokes, r=e.r, lam=e.lam, w=e.omega, z=e.reference_z, l=e.arm_unit),
           ""]
    for quantity, res in (("force", b.forces), ("moment", b.moments)):
        unit = ("N*m" if quantity == "moment" else "N") if not ru else ("Н·м" if quantity == "moment" else "Н")
        for kind in KINDS:
            R = res[kind]
            for poly in R.polygons:
                branch = say("b_branch_" + poly.branch, lang) if poly.branch else ""
                out.append(say("b_polygon", lang, q=say("b_" + quantity, lang), kind=say("b_" + kind, lang) if ru
                               else _NAMES[kind], order=poly.order, branch=branch, unit=poly.unit, u=unit))
                out += table_lines(poly, lang)
            out.append(say("b_amplitude", lang, a=R.amplitude, u=unit, d=R.dimensionless, ph=_deg(R.phase)))
            out.append("")
    if not e.is_inline:
        from plans.balancing.banks import report_lines

        out += report_lines(b.banks, lang) + [""]
    out.append(say("b_counterweights" if b.counterweights else "b_no_counterweights", lang))
    for c in b.counterweights:
        out.append(say("b_counterweight", lang, of=f"{c.of if not ru else say('b_cw_' + c.of, lang):12s}",
                       z=c.plane_z, mr=c.mass_radius, m=c.mass, r=c.radius, a=_deg(c.angle)))
    out += [say("b_note", lang, t=_note(t, lang)) for t in b.notes]
    return "\n".join(out)
