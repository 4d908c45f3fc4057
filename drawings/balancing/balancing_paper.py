"""How the balancing sheets put the engine on paper: the engine plane's mapping (the real
part up, the imaginary part along the rotation) and the figures' round scales."""

from __future__ import annotations

from drawings.paper.backend import Pt, Transform
from plans.kinematics.scales import ROUND, round_scale

POLY_MM = 130.0  # the largest polygon extent on the sheet, mm
#: K = 1/μ of the polygons: μ is 1, 2, 2.5, 4 or 5 × 10^k mm per unit
POLYGON_ROUND = ROUND
#: The diagrams over a turn: μ_α, degrees of crank angle per mm (the turn 180 mm long).
TURN_DEG_PER_MM = 2.0


def engine_paper(z: complex, s: float, o: Pt = (0.0, 0.0)) -> Pt:
    """Engine plane -> paper at ``s`` mm per unit from ``o``: the real part is up, the
    imaginary part along the rotation (counter-clockwise on the sheet, as the seed draws it)."""
    return Transform(s, o[0], o[1])(-z.imag, z.real)


def polygon_scale(extent: float, size: float = 1.0) -> float:
    """mm per dimensionless unit: the largest round value (1, 2, 2.5, 4, 5 × 10^k) that
    draws ``extent`` units within POLY_MM (``size`` times that where the sheet has room); 20
    where there is nothing to draw."""
    if extent <= 0:
        return 20.0
    return round_scale(extent, POLY_MM * size, POLYGON_ROUND)


def diagram_scale(largest: float, target_mm: float) -> float:
    """Units (N, N·m) per mm of a diagram's ordinate: the smallest round value (1, 2, 2.5, 4,
    5 × 10^k) that draws ``largest`` within ``target_mm``."""
    return 1.0 / round_scale(largest, target_mm, ROUND)
