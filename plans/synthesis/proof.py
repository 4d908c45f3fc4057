"""The proof of a design: the designed mechanism's motion, measured, not assumed.

Each mechanism here knows only its link lengths, pivots and assembly branch, and places its
links at a crank angle by the loop equations (closed form per group, written apart from the
construction that sized it).  From that alone:

* the extreme positions are the roots of the output's velocity analogue (ds/dφ or dψ/dφ,
  in closed form) found by Brent's method, not read off a grid;
* the stroke (or the swing) is the output's travel between them, and K the ratio of the
  crank's turns in the working and the return strokes;
* the minimum transmission angle γ_min is a minimum over the whole turn (golden section
  from every local minimum of a grid), the maximum pressure angle 90° − γ_min where the
  output is a slider;
* a group that cannot be assembled at some angle has its links in line there (γ = 0): so
  γ_min > 0 over the whole turn means the crank turns fully and the groups keep one
  assembly branch; the assembly margin (how far the groups stay from their limiting
  positions) is read where γ is least.

Crank angles φ are absolute (from +x, counter-clockwise), lengths in metres.
"""

from __future__ import annotations

import cmath
import math
from dataclasses import dataclass

from .numeric import TAU, grid, minimum, roots, wrap


@dataclass(frozen=True, slots=True)
class Slider:
    """Crank O–A (length l1) and rod A–B (l2); B slides on the line through G0 along the unit
    vector u, ahead of A's foot along u (branch +1)."""

    O: complex
    l1: float
    l2: float
    G0: complex
    u: complex

    def place(self, phi: float) -> tuple[complex, complex]:
        A = self.O + self.l1 * cmath.exp(1j * phi)
        w = (A - self.G0) * self.u.conjugate()
        root = math.sqrt(max(self.l2 * self.l2 - w.imag * w.imag, 0.0))
        return A, self.G0 + (w.real + root) * self.u

    def s(self, phi: float) -> float:
        w = (self.O + self.l1 * cmath.exp(1j * phi) - self.G0) * self.u.conjugate()
        return w.real + math.sqrt(max(self.l2 * self.l2 - w.imag * w.imag, 0.0))

    def ds(self, phi: float) -> float:
        e = cmath.exp(1j * phi)
        w = (self.O + self.l1 * e - self.G0) * self.u.conjugate()
        dw = 1j * self.l1 * e * self.u.conjugate()
        root = math.sqrt(max(self.l2 * self.l2 - w.imag * w.imag, 1e-300))
        return dw.real - w.imag * dw.imag / root

    def gamma(self, phi: float) -> float:
        """The transmission angle, 90° minus the pressure angle (the rod against the guide)."""
        h = ((self.O + self.l1 * cmath.exp(1j * phi) - self.G0) * self.u.conjugate()).imag
        return math.atan2(math.sqrt(max(self.l2 * self.l2 - h * h, 0.0)), abs(h))

    def margin(self, phi: float) -> float:
        """How far the rod stays from being unable to reach the guide (l2 − |h|)."""
        h = ((self.O + self.l1 * cmath.exp(1j * phi) - self.G0) * self.u.conjugate()).imag
        return self.l2 - abs(h)

    def near(self, phi: float) -> float:
        """The slider's distance from the crank's pivot (the near dead centre has the least)."""
        return abs(self.place(phi)[1] - self.O)


@dataclass(frozen=True, slots=True)
class FourBar:
    """Crank O–A (l1), coupler A–B (l2), rocker D–B (l3); ``branch`` +1 puts B on the left of
    the line from A to D."""

    O: complex
    D: complex
    l1: float
    l2: float
    l3: float
    branch: int

    def place(self, phi: float) -> tuple[complex, complex]:
        A = self.O + self.l1 * cmath.exp(1j * phi)
        d = self.D - A
        delta = abs(d)
        c = (self.l2 * self.l2 + delta * delta - self.l3 * self.l3) / (2.0 * self.l2 * delta)
        alpha = math.acos(max(-1.0, min(1.0, c)))
        return A, A + self.l2 * (d / delta) * cmath.exp(1j * self.branch * alpha)

    def psi(self, phi: float) -> float:
        """The rocker's angle (from +x)."""
        return cmath.phase(self.place(phi)[1] - self.D)

    def dpsi(self, phi: float) -> float:
        """dψ/dφ = l1 sin(φ − φ2) / (l3 sin(φ3 − φ2)) from the loop's velocities."""
        A, B = self.place(phi)
        p2, p3 = cmath.phase(B - A), cmath.phase(B - self.D)
        a = math.sin(p3 - p2)
        return self.l1 * math.sin(phi - p2) / (self.l3 * (a if a != 0.0 else 1e-300))

    def gamma(self, phi: float) -> float:
        """The transmission angle between coupler and rocker, folded to [0°, 90°]."""
        A, B = self.place(phi)
        t = (B - A) * (B - self.D).conjugate()
        return math.atan2(abs(t.imag), abs(t.real))

    def rate_and_gamma(self, phi: float) -> tuple[float, float]:
        """dψ/dφ and γ from one placing (the grid's values)."""
        A, B = self.place(phi)
        p2, p3 = cmath.phase(B - A), cmath.phase(B - self.D)
        a = math.sin(p3 - p2)
        t = (B - A) * (B - self.D).conjugate()
        return (self.l1 * math.sin(phi - p2) / (self.l3 * (a if a != 0.0 else 1e-300)),
                math.atan2(abs(t.imag), abs(t.real)))

    def margin(self, phi: float) -> float:
        delta = abs(self.D - self.O - self.l1 * cmath.exp(1j * phi))
        return min(delta - abs(self.l2 - self.l3), self.l2 + self.l3 - delta)

    def near(self, phi: float) -> float:
        return abs(self.place(phi)[1] - self.O)


@dataclass(frozen=True, slots=True)
class Coulisse:
    """Crank O–A (l1), block A in the slot of the coulisse C–D (l3), rod D–E (l4), ram E on
    the line through G0 along u, ahead of D's foot along u.  ``l4 = 0``: the RPP ram, a block
    at D sliding in the ram's slot ⟂ u (E is D's foot on the guide)."""

    O: complex
    C: complex
    l1: float
    l3: float
    l4: float
    G0: complex
    u: complex

    def place(self, phi: float) -> tuple[complex, complex, complex]:
        A = self.O + self.l1 * cmath.exp(1j * phi)
        r = A - self.C
        D = self.C + self.l3 * r / abs(r)
        w = (D - self.G0) * self.u.conjugate()
        if self.l4 == 0.0:
            return A, D, self.G0 + w.real * self.u
        root = math.sqrt(max(self.l4 * self.l4 - w.imag * w.imag, 0.0))
        return A, D, self.G0 + (w.real + root) * self.u

    def s(self, phi: float) -> float:
        return ((self.place(phi)[2] - self.G0) * self.u.conjugate()).real

    def ds(self, phi: float) -> float:
        e = cmath.exp(1j * phi)
        A = self.O + self.l1 * e
        r = A - self.C
        dbeta = (r.conjugate() * 1j * self.l1 * e).imag / (abs(r) ** 2)
        D = self.C + self.l3 * r / abs(r)
        w = (D - self.G0) * self.u.conjugate()
        dw = 1j * dbeta * (D - self.C) * self.u.conjugate()
        if self.l4 == 0.0:
            return dw.real
        root = math.sqrt(max(self.l4 * self.l4 - w.imag * w.imag, 1e-300))
        return dw.real - w.imag * dw.imag / root

    def psi(self, phi: float) -> float:
        return cmath.phase(self.O + self.l1 * cmath.exp(1j * phi) - self.C)

    def gamma(self, phi: float) -> float:
        """The ram group's transmission angle: 90° − the rod's pressure angle on the ram; of
        an RPP ram, 90° − the angle between D's velocity (⟂ CD) and the guide."""
        _, D, _ = self.place(phi)
        if self.l4 == 0.0:
            t = (D - self.C) * (1j * self.u).conjugate()  # CD against the slot
            return math.atan2(abs(t.real), abs(t.imag))
        h = ((D - self.G0) * self.u.conjugate()).imag
        return math.atan2(math.sqrt(max(self.l4 * self.l4 - h * h, 0.0)), abs(h))

    def margin(self, phi: float) -> float:
        A = self.O + self.l1 * cmath.exp(1j * phi)
        r = A - self.C
        D = self.C + self.l3 * r / abs(r)
        h = ((D - self.G0) * self.u.conjugate()).imag
        return min(abs(r), self.l4 - abs(h)) if self.l4 > 0 else abs(r)


@dataclass(frozen=True, slots=True)
class Measured:
    """What the designed mechanism does, found from its motion alone."""

    phi_start: float  # crank angle at the start of the working stroke (rad)
    phi_end: float  # … and at its end (the other extreme position)
    K: float  # crank's turn in the working stroke / in the return
    stroke: float | None  # the slider's or ram's travel between the extremes (m)
    swing: float | None  # the rocker's or coulisse's swing (rad)
    gamma_min: float  # the least transmission angle over the turn (rad)
    phi_gamma: float  # where it is (crank angle, rad)
    margin: float  # the assembly margin where γ is least (m): > 0 turns fully on one branch
    extremes: int  # how many extreme positions the output has over one turn (2)

    @property
    def full_rotation(self) -> bool:
        return self.margin > 0 and self.extremes == 2


def _extremes(d, n: int = 48) -> list[float]:
    return roots(d, n)


def _k(start: float, end: float, sense: int) -> float:
    travel = ((end - start) * sense) % TAU
    return travel / (TAU - travel) if 0 < travel < TAU else math.inf


def measure(mech: Slider | FourBar | Coulisse, sense: int, working: str = "away") -> Measured:
    """The mechanism's extremes, K, stroke or swing, γ_min and assembly margin.

    ``working``: which stroke is the working one: ``"away"`` (the slider or the rocker from
    its position nearest the crank's pivot to the farthest), ``"+"``/``"-"`` (the ram toward
    +u or −u)."""
    if isinstance(mech, FourBar):  # one placing per node gives both grids
        both = [mech.rate_and_gamma(x) for x in grid()]
        ex = roots(mech.dpsi, values=[r for r, _ in both])
        phi_g, g = minimum(mech.gamma, values=[y for _, y in both])
    else:
        ex = _extremes(mech.ds)
        phi_g, g = minimum(mech.gamma)
    # a group that cannot be assembled has γ = 0 there (its links in line), so γ_min > 0 is
    # the crank's full turn on one branch; the margin is read where γ is least
    margin = mech.margin(phi_g) if g > 0 else 0.0
    if isinstance(mech, Coulisse):  # and the block never reaches the coulisse's pivot
        margin = min(margin, abs(mech.O - mech.C) - mech.l1)
    if len(ex) != 2:
        return Measured(math.nan, math.nan, math.nan, None, None, g, phi_g, margin, len(ex))
    a, b = ex
    if working == "away":
        assert not isinstance(mech, Coulisse)
        start, end = (a, b) if mech.near(a) <= mech.near(b) else (b, a)
    else:
        sa, sb = mech.s(a), mech.s(b)  # type: ignore[union-attr]
        lo, hi = (a, b) if sa <= sb else (b, a)
        start, end = (lo, hi) if working == "+" else (hi, lo)
    stroke = swing = None
    if isinstance(mech, FourBar):
        swing = abs(wrap(mech.psi(end) - mech.psi(start)))
    else:
        stroke = abs(mech.s(end) - mech.s(start))
        if isinstance(mech, Coulisse):
            swing = abs(wrap(mech.psi(end) - mech.psi(start)))
    return Measured(start, end, _k(start, end, sense), stroke, swing, g, phi_g, margin, 2)
